//! The committed `examples/*.json` files are exactly what `shenlong examples NAME` writes.

use shenlong::format::json;
use std::path::Path;

#[test]
fn example_files_are_up_to_date() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    for (name, _) in shenlong::examples::list() {
        let scene = shenlong::examples::build(name).unwrap();
        let expected = json::write(&scene, None);
        let path = dir.join(format!("{name}.json"));
        let committed =
            std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(
            committed == expected,
            "{} is stale: run `cargo run -- examples {name} -o examples/{name}.json`",
            path.display()
        );
        // And it reads back as the same scene.
        let reread = json::read(&committed, name).unwrap().scene;
        assert_eq!(reread.objects.len(), scene.objects.len());
        for (a, b) in reread.objects.iter().zip(&scene.objects) {
            assert_eq!(a.support, b.support, "{name}: {}", a.name);
        }
    }
}

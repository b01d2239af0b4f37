//! The committed generated file must be exactly what the generator writes today.

use std::path::Path;

#[test]
fn generated_file_is_up_to_date() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let committed = std::fs::read_to_string(root.join(cga_codegen::OUTPUT_PATH))
        .expect("crates/cga/src/generated.rs exists");
    assert!(
        committed == cga_codegen::generate(),
        "crates/cga/src/generated.rs is stale: run `cargo run -p cga-codegen`"
    );
}

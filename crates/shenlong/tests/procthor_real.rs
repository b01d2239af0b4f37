//! ProcTHOR import on the real houses and asset database in ../shared/data/procthor (see
//! its SOURCES.md); skips with a message when the data is absent.

use shenlong::format::procthor::AssetDatabase;
use shenlong::format::{json, SceneFile};
use std::path::{Path, PathBuf};

mod support;

use support::shared_data::shared_data;

fn data_dir() -> Option<PathBuf> {
    let houses = shared_data("procthor/houses.jsonl")?;
    shared_data("procthor/asset-database.json")?;
    houses.parent().map(Path::to_path_buf)
}

#[test]
fn all_thirty_houses_import() {
    let Some(dir) = data_dir() else { return };
    let assets = AssetDatabase::load(&dir.join("asset-database.json")).unwrap();
    assert!(assets.len() > 1000, "{} assets", assets.len());
    let mut total = 0;
    let mut nested = 0;
    let mut overlapping_pairs = 0;
    for index in 0..30 {
        let file = SceneFile::load_house(&dir.join("houses.jsonl"), index, &assets).unwrap();
        let scene = &file.scene;
        assert!(!scene.objects.is_empty(), "house {index}");
        total += scene.objects.len();
        nested += scene.objects.iter().filter(|o| o.support_from_file).count();
        let bounds = scene.bounds.expect("rooms give bounds");
        let boxes = scene.world_aabbs();
        for (o, b) in scene.objects.iter().zip(&boxes) {
            // Objects stand on or above the floor (a little sinking is in the data).
            assert!(
                b.min.y > -0.05,
                "house {index}: '{}' is below the floor: {b:?}",
                o.name
            );
            let centre = b.center();
            assert!(
                centre.x >= bounds.min.x - 0.5
                    && centre.x <= bounds.max.x + 0.5
                    && centre.z >= bounds.min.z - 0.5
                    && centre.z <= bounds.max.z + 0.5,
                "house {index}: '{}' at {centre} is outside the room {bounds:?}",
                o.name
            );
        }
        for i in 0..boxes.len() {
            for j in i + 1..boxes.len() {
                if boxes[i].intersects(&boxes[j], 1e-3) {
                    overlapping_pairs += 1;
                }
            }
        }
        // Names are unique and human: lower-case words, numbered from the second.
        for o in &scene.objects {
            assert_eq!(o.name, o.name.to_lowercase());
        }
        // Children rest on their parents: their bottom is within the parent's box height,
        // or a few centimetres above its top (SOURCES.md: the bowl in house 0 floats 5.5 cm
        // above the countertop).
        for (i, o) in scene.objects.iter().enumerate() {
            if let Some(p) = o.support {
                let (a, b) = (boxes[i], boxes[p]);
                assert!(
                    a.min.y >= b.min.y - 0.05 && a.min.y <= b.max.y + 0.1,
                    "house {index}: '{}' on '{}'",
                    o.name,
                    scene.objects[p].name
                );
            }
        }
        // The converted document round-trips through scene JSON.
        let text =
            String::from_utf8(file.to_bytes(shenlong::format::Format::SceneJson).unwrap()).unwrap();
        let again = json::read(&text, "x").unwrap().scene;
        assert_eq!(again.objects.len(), scene.objects.len());
        for (a, b) in again.objects.iter().zip(&scene.objects) {
            assert_eq!(a.support, b.support);
            assert!((a.world_aabb().min - b.world_aabb().min).length() < 1e-6);
        }
    }
    eprintln!("{total} objects, {nested} nested as children, {overlapping_pairs} overlapping pairs before any edit");
    assert_eq!(total, 739);
    assert!(nested > 100);
    assert!(
        overlapping_pairs > 0,
        "the real data has pre-existing overlaps (SOURCES.md)"
    );
}

#[test]
fn a_known_house_in_detail() {
    let Some(dir) = data_dir() else { return };
    let assets = AssetDatabase::load(&dir.join("asset-database.json")).unwrap();
    let file = SceneFile::load_house(&dir.join("houses.jsonl"), 0, &assets).unwrap();
    let scene = &file.scene;
    let fridge = scene
        .find("fridge")
        .expect("house 0 is a kitchen with a fridge");
    // Fridge_25 at Unity (3.6255, 0.8957, 5.5668), rotated 270° about Y: mirrored z.
    let b = scene.objects[fridge].world_aabb();
    assert!((b.center().x - 3.6255498919487).abs() < 1e-6);
    assert!((b.center().z + 5.566846596717834).abs() < 1e-6);
    assert!((b.center().y - 0.8956716060638428).abs() < 1e-6);
    let apple = scene.find("apple").unwrap();
    assert_eq!(scene.objects[apple].support, Some(fridge));
    assert!(scene.carried_by(fridge).contains(&apple));
    // Houses are not scene files: a clear hint.
    let e = SceneFile::load(&dir.join("houses.jsonl")).unwrap_err();
    assert!(
        e.to_string().contains("unknown scene format '.jsonl'"),
        "{e}"
    );
    let e = SceneFile::load_house(&dir.join("houses.jsonl"), 30, &assets).unwrap_err();
    assert!(
        e.to_string()
            .contains("holds 30 houses; house 30 is out of range"),
        "{e}"
    );
}

//! glTF reading and writing on real files made by others (../shared/data/gltf, see its
//! SOURCES.md). Each test skips, with a message, when the data is absent. Written files
//! are checked with the Khronos glTF validator when tools/gltf-validator is installed
//! (`npm ci --prefix tools/gltf-validator`; CI does this).

use cga::{Multivector, Similarity};
use glam::{DQuat, DVec3};
use shenlong::format::{Document, SceneFile};
use std::path::{Path, PathBuf};
use std::process::Command;

mod support;

fn data_dir() -> Option<PathBuf> {
    support::shared_data::shared_data("gltf")
}

fn validate(path: &Path) {
    let tool = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tools/gltf-validator");
    if !tool.join("node_modules/gltf-validator").is_dir() {
        eprintln!("skipping the Khronos validator: run `npm ci --prefix tools/gltf-validator`");
        return;
    }
    let output = Command::new("node")
        .arg(tool.join("validate.mjs"))
        .arg(path)
        .output()
        .expect("node runs");
    assert!(
        output.status.success(),
        "{} fails validation: {}",
        path.display(),
        String::from_utf8_lossy(&output.stdout)
    );
}

fn close(a: DVec3, b: DVec3, tol: f64) -> bool {
    (a - b).abs().max_element() <= tol
}

/// The JSON chunk and binary chunk of a GLB.
fn glb_chunks(bytes: &[u8]) -> (serde_json::Value, Vec<u8>) {
    let json_len = u32::from_le_bytes(bytes[12..16].try_into().unwrap()) as usize;
    let json = serde_json::from_slice(&bytes[20..20 + json_len]).unwrap();
    let rest = &bytes[20 + json_len..];
    let bin = if rest.len() >= 8 {
        rest[8..].to_vec()
    } else {
        Vec::new()
    };
    (json, bin)
}

/// Every node of `b` but `edited` is as in `a`.
#[track_caller]
fn assert_other_nodes_untouched(a: &serde_json::Value, b: &serde_json::Value, edited: usize) {
    let (a, b) = (
        a["nodes"].as_array().unwrap(),
        b["nodes"].as_array().unwrap(),
    );
    assert_eq!(a.len(), b.len());
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        if i != edited {
            assert_eq!(x, y, "node {i} untouched");
        }
    }
}

/// Reads a file modelled in millimetres (the Cornell box, the engine), as `--units mm`.
fn load_mm(path: &Path) -> SceneFile {
    let options = shenlong::format::ReadOptions {
        units: Some(shenlong::format::Units::Millimetres),
        ..Default::default()
    };
    SceneFile::load_with(path, &options).unwrap()
}

#[test]
fn millimetre_files_are_refused_without_units() {
    let Some(dir) = data_dir() else { return };
    for name in ["CornellBox.glb", "2CylinderEngine.glb"] {
        let e = SceneFile::load(&dir.join(name)).err().unwrap();
        assert!(
            matches!(
                e.innermost(),
                shenlong::format::FormatError::Units {
                    guess: shenlong::format::Units::Millimetres,
                    ..
                }
            ),
            "{name}: {e}"
        );
        assert!(e.to_string().contains("--units mm"), "{name}: {e}");
    }
}

#[test]
fn cornell_box_edit_changes_only_the_moved_node() {
    let Some(dir) = data_dir() else { return };
    let input = dir.join("CornellBox.glb");
    let mut file = load_mm(&input);
    let names: Vec<&str> = file.scene.objects.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["Light", "large.box", "small.box", "cornell.box"]);
    let small = file.scene.find("small.box").unwrap();
    let before = file.scene.world_aabbs();
    let t = DVec3::new(0.05, 0.0, -0.02);
    file.scene
        .apply(small, &Multivector::translator(t), true)
        .unwrap();

    let out_dir = tempfile::tempdir().unwrap();
    let output = out_dir.path().join("edited.glb");
    file.save(&output).unwrap();
    validate(&output);

    let original = std::fs::read(&input).unwrap();
    let written = std::fs::read(&output).unwrap();
    let (json_a, bin_a) = glb_chunks(&original);
    let (json_b, bin_b) = glb_chunks(&written);
    assert_eq!(bin_a, bin_b, "the binary chunk is copied byte for byte");
    let node_b = &json_b["nodes"][2];
    assert_eq!(node_b["name"], "small.box");
    assert_other_nodes_untouched(&json_a, &json_b, 2);
    for key in [
        "meshes",
        "materials",
        "accessors",
        "bufferViews",
        "buffers",
        "extensionsUsed",
        "scenes",
        "asset",
    ] {
        assert_eq!(json_a[key], json_b[key], "{key} untouched");
    }
    let reread = load_mm(&output);
    let after = reread.scene.world_aabbs();
    for (i, (a, b)) in before.iter().zip(&after).enumerate() {
        let expected = if i == small { t } else { DVec3::ZERO };
        assert!(
            close(b.min, a.min + expected, 1e-6),
            "object {i}: {:?} vs {:?}",
            b.min,
            a.min
        );
        assert!(close(b.max, a.max + expected, 1e-6));
    }
}

#[test]
fn unchanged_scene_is_written_back_byte_for_byte() {
    let Some(dir) = data_dir() else { return };
    for name in ["CornellBox.glb", "Cubes.glb", "2CylinderEngine.glb"] {
        let input = dir.join(name);
        let file = load_mm(&input);
        let out = tempfile::tempdir().unwrap();
        let output = out.path().join(name);
        file.save(&output).unwrap();
        assert_eq!(
            std::fs::read(&input).unwrap(),
            std::fs::read(&output).unwrap(),
            "{name}"
        );
    }
}

#[test]
fn engine_of_unnamed_nested_matrix_nodes_is_one_object() {
    let Some(dir) = data_dir() else { return };
    let input = dir.join("2CylinderEngine.glb");
    let mut file = load_mm(&input);
    // 82 unnamed nodes, 29 meshes instanced under nested matrix nodes, all touching: one
    // engine, as a person sees it, named by its root node.
    let names: Vec<&str> = file.scene.objects.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["node 0"]);
    let before = file.scene.objects[0].world_aabb();
    assert!(before.size().max_element() > 0.2 && before.size().max_element() < 2.0);
    let motion = Similarity {
        translation: DVec3::new(0.01, 0.02, 0.0),
        rotation: DQuat::from_rotation_y(0.5),
        scale: 1.0,
    };
    file.scene
        .apply(0, &motion.to_versor().unwrap(), false)
        .unwrap();
    let expected = file.scene.objects[0].world_aabb();
    let out = tempfile::tempdir().unwrap();
    let output = out.path().join("engine.glb");
    file.save(&output).unwrap();
    validate(&output);
    let (json_a, _) = glb_chunks(&std::fs::read(&input).unwrap());
    let (json_b, _) = glb_chunks(&std::fs::read(&output).unwrap());
    // Only the root node's transform is written; every nested node, matrices included,
    // is as it was.
    assert_other_nodes_untouched(&json_a, &json_b, 0);
    assert!(json_b["nodes"][0].get("rotation").is_some());
    let reread = load_mm(&output);
    let got = reread.scene.objects[0].world_aabb();
    assert!(
        close(got.min, expected.min, 1e-6) && close(got.max, expected.max, 1e-6),
        "{got:?} vs {expected:?}"
    );
}

#[test]
fn cubes_skip_lights_and_probes() {
    let Some(dir) = data_dir() else { return };
    let file = SceneFile::load(&dir.join("Cubes.glb")).unwrap();
    let names: Vec<&str> = file.scene.objects.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["Cube.001", "Cube.002", "Cube.003"]);
}

#[test]
fn objects_resting_on_a_zero_thickness_board() {
    let Some(dir) = data_dir() else { return };
    let mut file = SceneFile::load(&dir.join("DepthOfFieldExample.glb")).unwrap();
    let scene = &file.scene;
    assert_eq!(scene.objects.len(), 16);
    let board = scene.find("CircuitBoard").unwrap();
    let b = scene.objects[board].world_aabb();
    assert!(
        (b.max.y - b.min.y).abs() < 1e-6,
        "the board has no thickness"
    );
    let resting = scene.carried_by(board);
    assert!(resting.len() >= 5, "objects rest on the board: {resting:?}");
    // Lifting the board lifts what rests on it.
    let sphere = resting[0];
    let before = scene.objects[sphere].world_aabb();
    file.scene
        .apply(board, &Multivector::translator(DVec3::Y), true)
        .unwrap();
    assert!(close(
        file.scene.objects[sphere].world_aabb().min,
        before.min + DVec3::Y,
        1e-9
    ));
    let out = tempfile::tempdir().unwrap();
    let output = out.path().join("dof.glb");
    file.save(&output).unwrap();
    validate(&output);
}

#[test]
fn gltf_with_external_buffers_and_textures_written_elsewhere() {
    let Some(dir) = data_dir() else { return };
    for (folder, name) in [
        ("MixedLightingExample", "MixedLightingExample.gltf"),
        ("TonemappingTest", "TonemappingTest.gltf"),
    ] {
        let input = dir.join(folder).join(name);
        let mut file = SceneFile::load(&input).unwrap();
        assert!(!file.scene.objects.is_empty());
        let before = file.scene.world_aabbs();
        let r = Multivector::rotor(
            std::f64::consts::FRAC_PI_2,
            &Multivector::e3(),
            &Multivector::e1(),
        )
        .unwrap();
        file.scene.apply(0, &r, false).unwrap();
        let expected = file.scene.objects[0].world_aabb();
        let out = tempfile::tempdir().unwrap();
        let output = out.path().join(name);
        file.save(&output).unwrap();
        validate(&output);
        let reread = SceneFile::load(&output).unwrap();
        let got = reread.scene.objects[0].world_aabb();
        assert!(
            close(got.min, expected.min, 1e-4),
            "{name}: {got:?} vs {expected:?}"
        );
        for (i, b) in before.iter().enumerate().skip(1) {
            if !file.scene.carried_by(0).contains(&i) {
                assert!(
                    close(reread.scene.objects[i].world_aabb().min, b.min, 1e-4),
                    "{name}: object {i}"
                );
            }
        }
        // The buffers and textures came along, unchanged, flat beside the output under
        // names Shenlong made from its stem.
        let uris = |f: &SceneFile| -> Vec<String> {
            match &f.document {
                Document::Gltf(d) => d.external_uris(),
                _ => unreachable!(),
            }
        };
        let (originals, copies) = (uris(&file), uris(&reread));
        assert!(!originals.is_empty());
        assert_eq!(originals.len(), copies.len());
        let stem = name.trim_end_matches(".gltf");
        for (original, copy) in originals.iter().zip(&copies) {
            assert!(
                copy.starts_with(&format!("{stem}_")) && !copy.contains('/'),
                "{copy}"
            );
            assert_eq!(
                std::fs::read(dir.join(folder).join(original)).unwrap(),
                std::fs::read(out.path().join(copy)).unwrap(),
                "{original} → {copy}"
            );
        }
        let files = std::fs::read_dir(out.path()).unwrap().count();
        let distinct: std::collections::HashSet<&String> = copies.iter().collect();
        assert_eq!(
            files,
            1 + distinct.len(),
            "the glTF and its copies, nothing else"
        );
    }
}

#[test]
fn mixed_lighting_chair_parts_and_extensions_survive() {
    let Some(dir) = data_dir() else { return };
    let input = dir.join("MixedLightingExample/MixedLightingExample.gltf");
    let mut file = SceneFile::load(&input).unwrap();
    let names: Vec<String> = file.scene.objects.iter().map(|o| o.name.clone()).collect();
    eprintln!("objects: {names:?}");
    let original: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&input).unwrap()).unwrap();
    file.scene
        .apply(0, &Multivector::translator(DVec3::X), false)
        .unwrap();
    let out = tempfile::tempdir().unwrap();
    let output = out.path().join("m.gltf");
    file.save(&output).unwrap();
    let written: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&output).unwrap()).unwrap();
    for key in [
        "extensions",
        "extensionsUsed",
        "materials",
        "textures",
        "samplers",
        "meshes",
        "accessors",
    ] {
        assert_eq!(original.get(key), written.get(key), "{key} untouched");
    }
    // Images and buffers keep everything but their URIs, which name the copies.
    let without_uris = |v: &serde_json::Value| {
        let mut v = v.clone();
        for item in v.as_array_mut().unwrap() {
            item.as_object_mut().unwrap().remove("uri");
        }
        v
    };
    for key in ["images", "buffers"] {
        assert_eq!(
            without_uris(&original[key]),
            without_uris(&written[key]),
            "{key}"
        );
    }
}

#[test]
fn gltf_to_scene_json_gives_boxes_at_the_bottom_centre() {
    let Some(dir) = data_dir() else { return };
    let file = load_mm(&dir.join("CornellBox.glb"));
    let bytes = file.to_bytes(shenlong::format::Format::SceneJson).unwrap();
    let json = shenlong::format::json::read(std::str::from_utf8(&bytes).unwrap(), "x").unwrap();
    for (a, b) in file.scene.objects.iter().zip(&json.scene.objects) {
        let (wa, wb) = (a.world_aabb(), b.world_aabb());
        assert!(
            close(wa.min, wb.min, 1e-6) && close(wa.max, wb.max, 1e-6),
            "{}: {wa:?} vs {wb:?}",
            a.name
        );
    }
}

#[test]
fn a_failed_write_leaves_no_copied_resources_behind() {
    let Some(dir) = data_dir() else { return };
    let input = dir.join("MixedLightingExample/MixedLightingExample.gltf");
    let file = SceneFile::load(&input).unwrap();
    let out = tempfile::tempdir().unwrap();
    // The output is a folder: nothing may be written, not even the buffers and textures.
    let output = out.path().join("edited.gltf");
    std::fs::create_dir(&output).unwrap();
    let e = file.save(&output).unwrap_err();
    assert!(
        matches!(e, shenlong::format::FormatError::Write { .. }),
        "{e:?}"
    );
    assert!(e.to_string().contains("it is a folder"), "{e}");
    let left: Vec<_> = std::fs::read_dir(out.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(
        left,
        vec![std::ffi::OsString::from("edited.gltf")],
        "{left:?}"
    );
}

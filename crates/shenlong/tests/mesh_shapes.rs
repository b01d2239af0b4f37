//! Shapes read off meshes (docs/collisions.md, "Shapes from meshes"): a glTF file whose
//! desk is a top on four legs in one mesh, a crate open at the top, a bed raised on legs
//! and a drawer unit that is solid to the floor. Edits are made in-process and the
//! written file is read back with the `gltf` crate; outcomes are where the nodes end up.

use glam::DVec3;
use serde_json::{json, Value};
use shenlong::format::SceneFile;
use shenlong::offline::OfflineTranslator;
use shenlong::pipeline::{edit, EditOptions};
use std::path::Path;

/// A glTF file being made: one buffer, a mesh per node.
#[derive(Default)]
struct Gltf {
    bin: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
    meshes: Vec<Value>,
    nodes: Vec<Value>,
}

impl Gltf {
    /// A node `name` at `at` whose one mesh is the boxes `parts` (local corners).
    fn node(&mut self, name: &str, at: [f64; 3], parts: &[([f64; 3], [f64; 3])]) {
        let (mut points, mut indices): (Vec<[f32; 3]>, Vec<u32>) = (Vec::new(), Vec::new());
        for (lo, hi) in parts {
            let base = points.len() as u32;
            for k in 0..8 {
                let pick = |bit: usize, axis: usize| if k & bit == 0 { lo[axis] } else { hi[axis] };
                points.push([pick(1, 0) as f32, pick(2, 1) as f32, pick(4, 2) as f32]);
            }
            for f in [
                [0, 1, 3, 2],
                [4, 6, 7, 5],
                [0, 4, 5, 1],
                [2, 3, 7, 6],
                [0, 2, 6, 4],
                [1, 5, 7, 3],
            ] {
                indices.extend([f[0], f[1], f[2], f[0], f[2], f[3]].map(|i| base + i));
            }
        }
        let (mut min, mut max) = ([f32::MAX; 3], [f32::MIN; 3]);
        for p in &points {
            for a in 0..3 {
                min[a] = min[a].min(p[a]);
                max[a] = max[a].max(p[a]);
            }
        }
        let position = self.view(points.iter().flatten().flat_map(|v| v.to_le_bytes()), 34962);
        let index = self.view(indices.iter().flat_map(|v| v.to_le_bytes()), 34963);
        let a = self.accessors.len();
        self.accessors
            .push(json!({"bufferView": position, "componentType": 5126,
            "count": points.len(), "type": "VEC3", "min": min, "max": max}));
        self.accessors
            .push(json!({"bufferView": index, "componentType": 5125,
            "count": indices.len(), "type": "SCALAR"}));
        self.meshes.push(json!({"name": name.to_lowercase(),
            "primitives": [{"attributes": {"POSITION": a}, "indices": a + 1}]}));
        self.nodes
            .push(json!({"name": name, "mesh": self.meshes.len() - 1, "translation": at}));
    }

    fn view(&mut self, bytes: impl Iterator<Item = u8>, target: u32) -> usize {
        let offset = self.bin.len();
        self.bin.extend(bytes);
        self.views.push(json!({"buffer": 0, "byteOffset": offset,
            "byteLength": self.bin.len() - offset, "target": target}));
        self.views.len() - 1
    }

    fn write(&self, path: &Path) {
        use base64::Engine;
        let uri = format!(
            "data:application/octet-stream;base64,{}",
            base64::engine::general_purpose::STANDARD.encode(&self.bin)
        );
        let doc = json!({
            "asset": {"version": "2.0"},
            "scene": 0,
            "scenes": [{"nodes": (0..self.nodes.len()).collect::<Vec<_>>()}],
            "nodes": self.nodes, "meshes": self.meshes, "accessors": self.accessors,
            "bufferViews": self.views,
            "buffers": [{"byteLength": self.bin.len(), "uri": uri}],
        });
        std::fs::write(path, serde_json::to_vec_pretty(&doc).unwrap()).unwrap();
    }
}

/// Four square legs `side` wide at the corners of `[0, w] × [0, d]`, `h` tall.
fn legs(w: f64, d: f64, h: f64, side: f64) -> Vec<([f64; 3], [f64; 3])> {
    [
        (0.0, 0.0),
        (w - side, 0.0),
        (0.0, d - side),
        (w - side, d - side),
    ]
    .map(|(x, z)| ([x, 0.0, z], [x + side, h, z + side]))
    .to_vec()
}

/// The room: a desk (a 4 cm top at 0.72 m on legs), a stool, a chair facing the desk, an
/// open crate, a block, a bed whose frame is 0.25 m above the floor, a storage tray, a
/// drawer unit (two blocks stacked to the floor) and a bookcase with boards at its own
/// heights.
fn room(dir: &Path) -> std::path::PathBuf {
    let mut g = Gltf::default();
    let mut desk = legs(1.2, 0.7, 0.72, 0.05);
    desk.push(([0.0, 0.72, 0.0], [1.2, 0.76, 0.7]));
    g.node("Desk", [0.0, 0.0, 0.0], &desk);
    let mut stool = legs(0.35, 0.35, 0.4, 0.04);
    stool.push(([0.0, 0.4, 0.0], [0.35, 0.45, 0.35]));
    g.node("Stool", [2.0, 0.0, 0.0], &stool);
    // Facing +z (glTF's front): its back along its −z side.
    let mut chair = legs(0.45, 0.45, 0.43, 0.04);
    chair.push(([0.0, 0.43, 0.0], [0.45, 0.47, 0.45]));
    chair.push(([0.0, 0.47, 0.0], [0.45, 0.9, 0.04]));
    g.node("Chair", [0.4, 0.0, -1.0], &chair);
    g.node(
        "Crate",
        [-1.5, 0.0, 0.0],
        &[
            ([0.0, 0.0, 0.0], [0.5, 0.02, 0.4]),
            ([0.0, 0.0, 0.0], [0.02, 0.3, 0.4]),
            ([0.48, 0.0, 0.0], [0.5, 0.3, 0.4]),
            ([0.0, 0.0, 0.0], [0.5, 0.3, 0.02]),
            ([0.0, 0.0, 0.38], [0.5, 0.3, 0.4]),
        ],
    );
    g.node(
        "Block",
        [-1.0, 0.0, 1.5],
        &[([0.0, 0.0, 0.0], [0.1, 0.1, 0.1])],
    );
    let mut bed = legs(1.6, 2.0, 0.25, 0.06);
    bed.push(([0.0, 0.25, 0.0], [1.6, 0.55, 2.0]));
    bed.push(([0.0, 0.55, 0.0], [1.6, 1.0, 0.06]));
    g.node("Bed", [3.0, 0.0, 2.0], &bed);
    g.node(
        "Tray",
        [-2.0, 0.0, 3.0],
        &[([0.0, 0.0, 0.0], [0.6, 0.15, 0.4])],
    );
    g.node(
        "Drawers",
        [5.5, 0.0, -1.0],
        &[
            ([0.0, 0.0, 0.0], [0.6, 0.35, 0.5]),
            ([0.0, 0.35, 0.0], [0.6, 0.7, 0.5]),
        ],
    );
    // Sides, a back and boards at 0, 0.5, 1.2 and 1.78 m: shelves of its own heights.
    let mut bookcase = vec![
        ([0.0, 0.0, 0.0], [0.02, 1.8, 0.3]),
        ([0.78, 0.0, 0.0], [0.8, 1.8, 0.3]),
        ([0.0, 0.0, 0.0], [0.8, 1.8, 0.02]),
    ];
    for y in [0.0, 0.5, 1.2, 1.78] {
        bookcase.push(([0.02, y, 0.02], [0.78, y + 0.02, 0.3]));
    }
    g.node("Bookcase", [-4.0, 0.0, -2.0], &bookcase);
    let path = dir.join("room.gltf");
    g.write(&path);
    path
}

/// Each node's world box, by name, read back with the `gltf` crate.
fn boxes(path: &Path) -> Vec<(String, DVec3, DVec3)> {
    let bytes = std::fs::read(path).unwrap();
    let doc = gltf::Gltf::from_slice(&bytes).expect("the written file reads back");
    doc.nodes()
        .map(|node| {
            let bounds = node
                .mesh()
                .unwrap()
                .primitives()
                .next()
                .unwrap()
                .bounding_box();
            let (t, _, s) = node.transform().decomposed();
            let at = |v: [f32; 3]| {
                DVec3::from_array(v.map(f64::from)) * DVec3::from_array(s.map(f64::from))
                    + DVec3::from_array(t.map(f64::from))
            };
            (
                node.name().unwrap().to_string(),
                at(bounds.min),
                at(bounds.max),
            )
        })
        .collect()
}

fn find(boxes: &[(String, DVec3, DVec3)], name: &str) -> (DVec3, DVec3) {
    let b = boxes.iter().find(|b| b.0 == name).unwrap();
    (b.1, b.2)
}

/// Runs `instruction` on the room and writes the result; `Err` with the refusal.
fn run(instruction: &str) -> Result<Vec<(String, DVec3, DVec3)>, String> {
    let dir = tempfile::tempdir().unwrap();
    let mut file = SceneFile::load(&room(dir.path())).unwrap();
    edit(
        &mut file.scene,
        instruction,
        &OfflineTranslator::new(),
        &EditOptions::default(),
    )
    .map_err(|e| e.message)?;
    let out = dir.path().join("out.gltf");
    file.save(&out).unwrap();
    Ok(boxes(&out))
}

/// Whether the footprint centre of `a` lies within the footprint of `b`.
fn centred_over(a: (DVec3, DVec3), b: (DVec3, DVec3)) -> bool {
    let c = (a.0 + a.1) / 2.0;
    c.x > b.0.x && c.x < b.1.x && c.z > b.0.z && c.z < b.1.z
}

#[test]
fn the_stool_goes_under_the_desk_between_its_legs() {
    let after = run("push the stool under the desk").unwrap();
    let (stool, desk) = (find(&after, "Stool"), find(&after, "Desk"));
    assert!(centred_over(stool, desk), "{stool:?} beside {desk:?}");
    assert!(stool.0.y.abs() < 1e-3, "on the floor: {stool:?}");
    assert!(
        stool.1.y <= 0.72 + 1e-3,
        "below the top's underside: {stool:?}"
    );
    assert_eq!(
        find(&after, "Desk"),
        find(&run("move the block 1 cm left").unwrap(), "Desk")
    );
}

#[test]
fn the_chair_is_tucked_in_its_seat_under_the_top() {
    let after = run("tuck the chair under the desk").unwrap();
    let chair = find(&after, "Chair");
    // Its seat reaches under the top (z > 0); its back (at its −z side) stays out.
    assert!(chair.1.z > 0.2, "not tucked: {chair:?}");
    assert!(chair.0.z < 0.0, "its back went under the top: {chair:?}");
    assert!(chair.0.y.abs() < 1e-3);
}

#[test]
fn the_block_goes_in_the_open_crate() {
    let after = run("put the block in the crate").unwrap();
    let (block, crate_box) = (find(&after, "Block"), find(&after, "Crate"));
    assert!(
        centred_over(block, crate_box),
        "{block:?} beside {crate_box:?}"
    );
    assert!(
        block.0.y >= 0.02 - 1e-3 && block.1.y <= 0.3 + 1e-3,
        "{block:?}"
    );
}

#[test]
fn under_the_raised_bed_goes_what_fits_in_its_gap() {
    let after = run("slide the tray under the bed").unwrap();
    let (tray, bed) = (find(&after, "Tray"), find(&after, "Bed"));
    assert!(centred_over(tray, bed), "{tray:?} beside {bed:?}");
    assert!(tray.0.y.abs() < 1e-3 && tray.1.y <= 0.25 + 1e-3, "{tray:?}");
    // The stool is taller than the gap: refused, saying so.
    let refusal = run("put the stool under the bed").unwrap_err();
    assert!(refusal.contains("0.25 m"), "{refusal}");
}

#[test]
fn a_drawer_unit_solid_to_the_floor_has_no_room_under_it_whatever_its_name() {
    let dir = tempfile::tempdir().unwrap();
    let file = SceneFile::load(&room(dir.path())).unwrap();
    let scene = &file.scene;
    let form = |name: &str| shenlong::ground::kind::form_of(scene, scene.find(name).unwrap());
    assert_eq!(form("Drawers"), shenlong::scene::Form::Solid);
    assert_eq!(form("Crate"), shenlong::scene::Form::Open);
    assert!(form("Desk").on_legs() && form("Bed").on_legs());
    // A mesh that is a plain box keeps the form of its kind (a tray is a container).
    assert_eq!(form("Tray"), shenlong::scene::Form::Open);
    assert!(run("push the stool under the drawers").is_err());
    // Converted to scene JSON, the rooms measured are written as forms.
    let bytes = file.to_bytes(shenlong::format::Format::SceneJson).unwrap();
    let json = shenlong::format::json::read(std::str::from_utf8(&bytes).unwrap(), "x").unwrap();
    let back = &json.scene;
    let form_back = |name: &str| back.objects[back.find(name).unwrap()].form;
    // The room measured below is written too (`room_below`), and read back.
    let below = |name: &str| {
        let o = &back.objects[back.find(name).unwrap()];
        shenlong::scene::form::knee_room(&o.world_aabb(), o.form.unwrap())
    };
    assert!((below("Desk") - 0.72).abs() < 2e-3, "{}", below("Desk"));
    assert!((below("Bed") - 0.25).abs() < 2e-3, "{}", below("Bed"));
    assert_eq!(form_back("Crate"), Some(shenlong::scene::Form::Open));
    assert_eq!(form_back("Drawers"), None);
}

#[test]
fn a_bookcase_mesh_gives_its_own_shelf_heights() {
    let top = run("put the block on the top shelf of the bookcase").unwrap();
    let (block, case) = (find(&top, "Block"), find(&top, "Bookcase"));
    assert!(centred_over(block, case), "{block:?}");
    // On the board at 1.2 m (its top at 1.22), under the one at 1.78.
    assert!((block.0.y - 1.22).abs() < 5e-3, "{block:?}");
    let lowest = run("put the block in the bookcase").unwrap();
    let block = find(&lowest, "Block");
    assert!((block.0.y - 0.02).abs() < 5e-3, "{block:?}");
    let second = run("put the block on the second shelf from the bottom of the bookcase").unwrap();
    let block = find(&second, "Block");
    assert!((block.0.y - 0.52).abs() < 5e-3, "{block:?}");
}

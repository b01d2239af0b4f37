//! A new glTF of boxes for a scene read from no glTF file (`shenlong convert room.json
//! room.glb`), so that scenes of boxes reach Blender, three.js and engines.
//!
//! The room's bounds become slabs named `Room_Floor`, `Room_Ceiling` and `Room_Wall_…`
//! around them, which reading recognises as the room. Each object is a node named as the
//! object, with its pose as translation, rotation and
//! uniform scale, and a mesh of its box about the pivot (its bottom centre, as scene JSON
//! has it), named by its category (else its name); all boxes share one index list. Reading the
//! file back gives the same objects, names, boxes and fronts: a front other than +Z is
//! written as the node's `extras: {"shenlong:front": [x, y, z]}`, and the category as
//! the node's `extras: {"shenlong:category": …}`.

use super::FormatError;
use crate::scene::Scene;
use base64::Engine;
use glam::DVec3;
use serde_json::{json, Value};

/// The 12 triangles of a box over its corners numbered as [`corners`] gives them
/// (outward faces).
const TRIANGLES: [u16; 36] = [
    0, 2, 1, 0, 3, 2, // back (−z)
    4, 5, 6, 4, 6, 7, // front (+z)
    0, 1, 5, 0, 5, 4, // bottom (−y)
    3, 7, 6, 3, 6, 2, // top (+y)
    0, 4, 7, 0, 7, 3, // left (−x)
    1, 2, 6, 1, 6, 5, // right (+x)
];

/// A box's corners about its bottom centre: x ∈ [−w/2, w/2], y ∈ [0, h], z ∈ [−d/2, d/2].
fn corners(size: DVec3) -> [[f32; 3]; 8] {
    let (x, y, z) = ((size.x / 2.0) as f32, size.y as f32, (size.z / 2.0) as f32);
    [
        [-x, 0.0, -z],
        [x, 0.0, -z],
        [x, y, -z],
        [-x, y, -z],
        [-x, 0.0, z],
        [x, 0.0, z],
        [x, y, z],
        [-x, y, z],
    ]
}

fn number(x: f64) -> Value {
    json!(super::tidy(x))
}

/// The document being built: its buffer, meshes, accessors, views, nodes and roots.
struct Builder {
    bin: Vec<u8>,
    meshes: Vec<Value>,
    accessors: Vec<Value>,
    views: Vec<Value>,
    nodes: Vec<Value>,
    roots: Vec<Value>,
}

impl Builder {
    /// A document holding the shared index list of a box's triangles.
    fn new(objects: usize) -> Self {
        Self {
            bin: TRIANGLES.iter().flat_map(|i| i.to_le_bytes()).collect(),
            meshes: Vec::with_capacity(objects),
            accessors: vec![json!(
                {"bufferView": 0, "componentType": 5123, "count": 36, "type": "SCALAR"}
            )],
            views: vec![json!(
                {"buffer": 0, "byteOffset": 0, "byteLength": 72, "target": 34963}
            )],
            nodes: Vec::with_capacity(objects),
            roots: Vec::with_capacity(objects),
        }
    }

    /// A mesh of a box of `size` about its bottom centre, named `name`: its index.
    fn box_mesh(&mut self, name: &str, size: DVec3) -> usize {
        let index = self.meshes.len();
        let box_corners = corners(size);
        let offset = self.bin.len();
        self.bin
            .extend(box_corners.iter().flatten().flat_map(|v| v.to_le_bytes()));
        self.views
            .push(json!({"buffer": 0, "byteOffset": offset, "byteLength": 96, "target": 34962}));
        self.accessors
            .push(json!({"bufferView": index + 1, "componentType": 5126,
            "count": 8, "type": "VEC3", "min": box_corners[0], "max": box_corners[6]}));
        self.meshes.push(json!({"name": name,
            "primitives": [{"attributes": {"POSITION": index + 1}, "indices": 0}]}));
        index
    }

    /// A root node.
    fn root(&mut self, node: Value) {
        self.roots.push(json!(self.nodes.len()));
        self.nodes.push(node);
    }

    /// An object: a node at its pose with a mesh of its box, its front and category in
    /// `extras`.
    fn object(&mut self, object: &crate::scene::Object) {
        let (pose, size) = super::transform::box_pose(object);
        let mesh_name = object.labels.category.as_ref().unwrap_or(&object.name);
        let mesh = self.box_mesh(mesh_name, size);
        let mut extras = serde_json::Map::new();
        if (object.front - DVec3::Z).length() > 1e-12 {
            let f = object.front;
            extras.insert(
                "shenlong:front".into(),
                json!([number(f.x), number(f.y), number(f.z)]),
            );
        }
        if let Some(category) = &object.labels.category {
            extras.insert("shenlong:category".into(), json!(category));
        }
        let (q, t, s) = (pose.rotation, pose.translation, pose.scale);
        let mut node = json!({
            "name": object.name,
            "translation": [number(t.x), number(t.y), number(t.z)],
            "rotation": [number(q.x), number(q.y), number(q.z), number(q.w)],
            "scale": [number(s), number(s), number(s)],
            "mesh": mesh,
        });
        if !extras.is_empty() {
            node["extras"] = Value::Object(extras);
        }
        self.root(node);
    }

    /// The document, with its buffer inside it: a `.glb`'s binary chunk, or a data URI.
    fn finish(self, scene_name: &str, binary: bool) -> Result<Vec<u8>, FormatError> {
        let buffer = if binary {
            json!({"byteLength": self.bin.len()})
        } else {
            json!({
                "byteLength": self.bin.len(),
                "uri": format!(
                    "data:application/octet-stream;base64,{}",
                    base64::engine::general_purpose::STANDARD.encode(&self.bin)
                ),
            })
        };
        let document = json!({
            "asset": {"version": "2.0", "generator": "Shenlong"},
            "scene": 0,
            "scenes": [{"name": scene_name, "nodes": self.roots}],
            "nodes": self.nodes,
            "meshes": self.meshes,
            "accessors": self.accessors,
            "bufferViews": self.views,
            "buffers": [buffer],
        });
        if binary {
            super::gltf::glb_bytes(&document, Some(&self.bin))
        } else {
            Ok(super::pretty::to_string(&document).into_bytes())
        }
    }
}

/// The scene as a new glTF: `.glb` bytes when `binary`, else a `.gltf` with its buffer
/// embedded as a data URI.
///
/// # Errors
/// The scene has no object.
pub fn write_new(scene: &Scene, binary: bool) -> Result<Vec<u8>, FormatError> {
    if scene.objects.is_empty() {
        return Err(FormatError::invalid("the scene has no object to write"));
    }
    let mut builder = Builder::new(scene.objects.len());
    for object in &scene.objects {
        builder.object(object);
    }
    // The room, as slabs the reader recognises as floor, walls and ceiling.
    for (name, slab) in scene
        .bounds
        .as_ref()
        .map(super::facts::room_slabs)
        .unwrap_or_default()
    {
        let mesh = builder.box_mesh(name, slab.size());
        let t = slab.bottom_center();
        builder.root(json!({"name": name, "mesh": mesh,
            "translation": [number(t.x), number(t.y), number(t.z)]}));
    }
    builder.finish(&scene.name, binary)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::ReadOptions;

    #[test]
    fn boxes_read_back_as_the_same_objects() {
        let scene = crate::examples::build("living_room").unwrap();
        for binary in [false, true] {
            let bytes = write_new(&scene, binary).unwrap();
            let (back, _) = super::super::gltf::read_bytes_with(
                bytes,
                std::path::Path::new("."),
                "t",
                &ReadOptions::default(),
            )
            .unwrap();
            assert_eq!(back.objects.len(), scene.objects.len());
            for (a, b) in scene.objects.iter().zip(&back.objects) {
                assert_eq!(a.name, b.name);
                let (wa, wb) = (a.world_aabb(), b.world_aabb());
                assert!((wa.min - wb.min).length() < 1e-6, "{}", a.name);
                assert!((wa.max - wb.max).length() < 1e-6, "{}", a.name);
                assert!((a.world_front() - b.world_front()).length() < 1e-6);
                assert_eq!(a.support.is_some(), b.support.is_some(), "{}", a.name);
            }
            let (ra, rb) = (scene.bounds.unwrap(), back.bounds.unwrap());
            assert!((ra.min - rb.min).length() < 1e-5, "{ra:?} {rb:?}");
            assert!((ra.max - rb.max).length() < 1e-5, "{ra:?} {rb:?}");
        }
    }
}

#[cfg(test)]
mod front_tests {
    use crate::format::ReadOptions;
    use glam::DVec3;

    #[test]
    fn a_nodes_extras_front_and_its_turn() {
        // A node turned 90° about +Y (a quaternion) faces +X; one with its own front −X
        // in `extras` faces −X.
        let positions: [f32; 9] = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0];
        let bytes: Vec<u8> = positions.iter().flat_map(|f| f.to_le_bytes()).collect();
        use base64::Engine as _;
        let data = base64::engine::general_purpose::STANDARD.encode(&bytes);
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let text = serde_json::json!({
            "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
            "nodes": [
                {"name": "Chair", "mesh": 0, "rotation": [0, h, 0, h]},
                {"name": "Lamp", "mesh": 0, "translation": [3, 0, 0],
                 "extras": {"shenlong:front": [-1, 0, 0]}}
            ],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                           "min": [0, 0, 0], "max": [1, 1, 1]}],
            "bufferViews": [{"buffer": 0, "byteLength": 36}],
            "buffers": [{"byteLength": 36, "uri": format!("data:application/octet-stream;base64,{data}")}]
        })
        .to_string();
        let (scene, _) = super::super::gltf::read_bytes_with(
            text.into_bytes(),
            std::path::Path::new("."),
            "t",
            &ReadOptions::default(),
        )
        .unwrap();
        assert!((scene.objects[0].world_front() - DVec3::X).length() < 1e-9);
        assert!((scene.objects[1].world_front() - DVec3::NEG_X).length() < 1e-9);
    }
}

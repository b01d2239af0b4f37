//! glTF 2.0 (`.gltf` with external or embedded buffers, and `.glb`).
//!
//! Reading: every node with a mesh in the default scene is an object, named by its node
//! name (unnamed nodes: `node 12`, by index, which is stable). Its shape is its mesh's
//! vertex positions in world space, so world bounds are exact, and its pivot is the bottom
//! centre of its world box (node origins are arbitrary). A mesh node below another mesh
//! node rests on it (it moves with its parent in the file, so it is carried).
//!
//! Writing: the parsed JSON is edited in place — only the moved nodes' transforms change,
//! written as TRS or as a matrix as the node had them — and the GLB binary chunk is copied
//! byte for byte. An unchanged scene is written back as the original bytes.
//!
//! Node hierarchies of any depth are walked by loops, never by recursion (a file may nest
//! 100,000 nodes); they must be forests, as glTF requires, so no walk meets a cycle. The
//! JSON itself may nest [`super::MAX_JSON_DEPTH`] levels. Every index the gltf crate
//! follows, and every accessor it reads (strides, bounds), is checked before it reads, so
//! no file makes it panic.

use super::FormatError;
use crate::scene::{Labels, Scene, MAX_COORDINATE};
use base64::Engine;
use glam::{DMat4, DQuat, DVec3};
use serde_json::Value;
use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};

/// How the file was stored.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Container {
    /// A binary `.glb`.
    Glb,
    /// A `.gltf` JSON file; external resources are relative to `base_dir`.
    Gltf {
        /// The folder the file was in.
        base_dir: PathBuf,
    },
}

/// What glTF writing needs to know about the source file.
#[derive(Clone, Debug)]
pub struct GltfDocument {
    json: Value,
    bin: Option<Vec<u8>>,
    container: Container,
    original: Vec<u8>,
    /// Per node: parent node, original local and world matrices.
    nodes: Vec<NodeInfo>,
    /// Per object (scene order): its node.
    object_nodes: Vec<usize>,
    /// The nodes of the scene, each after its parent (depth first from the roots).
    order: Vec<usize>,
    /// Nodes targeted by animations: these must stay TRS.
    animated: HashSet<usize>,
    /// Metres per unit of the file (1 unless read with other units).
    meters_per_unit: f64,
}

#[derive(Clone, Debug)]
struct NodeInfo {
    parent: Option<usize>,
    local: DMat4,
    world: DMat4,
    in_scene: bool,
}

impl GltfDocument {
    /// How the source was stored.
    pub fn container(&self) -> &Container {
        &self.container
    }

    /// The node index of each object, in scene order.
    pub fn object_nodes(&self) -> &[usize] {
        &self.object_nodes
    }

    /// The relative URIs of external resources (buffers, images) the document uses.
    pub fn external_uris(&self) -> Vec<String> {
        let mut uris = Vec::new();
        for key in ["buffers", "images"] {
            for item in self
                .json
                .get(key)
                .and_then(Value::as_array)
                .into_iter()
                .flatten()
            {
                if let Some(uri) = item.get("uri").and_then(Value::as_str) {
                    if !uri.starts_with("data:") && !uri.contains("://") {
                        uris.push(uri.to_string());
                    }
                }
            }
        }
        uris
    }

    /// Whether every buffer and image the document names is inside it (a `data:` URI, or a
    /// GLB's own buffer): what a browser may load without calling out to anywhere.
    #[must_use]
    pub fn embedded_only(&self) -> bool {
        ["buffers", "images"].iter().all(|key| {
            self.json
                .get(*key)
                .and_then(Value::as_array)
                .into_iter()
                .flatten()
                .all(|item| {
                    item.get("uri")
                        .and_then(Value::as_str)
                        .is_none_or(|uri| uri.starts_with("data:"))
                })
        })
    }
}

/// Reads a `.gltf` or `.glb` file.
pub fn read(
    path: &Path,
    options: &super::facts::ReadOptions,
) -> Result<(Scene, GltfDocument), FormatError> {
    let bytes = crate::io::read_limited(path, crate::io::MAX_READ_BYTES)
        .map_err(|e| FormatError::read(path, e))?;
    let base_dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("scene");
    read_bytes_with(bytes, &base_dir, stem, options)
}

/// Reads glTF from bytes with the default [`ReadOptions`](super::facts::ReadOptions);
/// `base_dir` resolves external resources.
pub fn read_bytes(
    bytes: Vec<u8>,
    base_dir: &Path,
    name: &str,
) -> Result<(Scene, GltfDocument), FormatError> {
    read_bytes_with(bytes, base_dir, name, &super::facts::ReadOptions::default())
}

/// Reads glTF from bytes; `base_dir` resolves external resources.
pub fn read_bytes_with(
    bytes: Vec<u8>,
    base_dir: &Path,
    name: &str,
    options: &super::facts::ReadOptions,
) -> Result<(Scene, GltfDocument), FormatError> {
    let is_glb = bytes.starts_with(b"glTF");
    let (json_bytes, bin) = if is_glb {
        // The gltf crate subtracts the header size from the declared length unchecked.
        if let Some(length) = bytes.get(8..12) {
            let length = u32::from_le_bytes(length.try_into().expect("four bytes"));
            if length < 12 {
                return Err(FormatError::invalid(format!(
                    "invalid GLB container: the header declares {length} bytes, less than the 12-byte header itself"
                )));
            }
        }
        let glb = ::gltf::Glb::from_slice(&bytes)
            .map_err(|e| FormatError::invalid(format!("invalid GLB container: {e}")))?;
        (glb.json.into_owned(), glb.bin.map(|b| b.into_owned()))
    } else {
        (bytes.clone(), None)
    };
    super::check_json_depth(&json_bytes)?;
    let json: Value = serde_json::from_slice(&json_bytes)
        .map_err(|e| FormatError::json_syntax("glTF JSON", &e))?;
    check_indices(&json)?;
    let gltf = ::gltf::Gltf::from_slice_without_validation(&bytes)
        .map_err(|e| FormatError::invalid(format!("invalid glTF: {e}")))?;
    check_accessors(&json)?;
    let document = &gltf.document;
    let buffers = load_buffers(document, bin.as_deref(), base_dir)?;

    let all_nodes: Vec<::gltf::Node<'_>> = document.nodes().collect();
    let json_nodes = json.get("nodes").and_then(Value::as_array);
    let (nodes, order) = hierarchy(document, &all_nodes, json_nodes)?;
    let unit = options.units.map_or(1.0, super::facts::Units::meters);
    let tree = tree_of(&all_nodes, &nodes, &order, json_nodes, &buffers, unit)?;
    let derived = super::facts::derive(&tree, name, DVec3::Z, options)?;
    let scene = derived.scene;
    let object_nodes: Vec<usize> = derived.nodes.iter().map(|&t| order[t]).collect();

    let animated = document
        .animations()
        .flat_map(|a| {
            a.channels()
                .map(|c| c.target().node().index())
                .collect::<Vec<_>>()
        })
        .collect();
    let container = if is_glb {
        Container::Glb
    } else {
        Container::Gltf {
            base_dir: base_dir.to_path_buf(),
        }
    };
    Ok((
        scene,
        GltfDocument {
            json,
            bin,
            container,
            original: bytes,
            nodes,
            object_nodes,
            order,
            animated,
            meters_per_unit: unit,
        },
    ))
}

/// The nodes' parents, local and world transforms, and the order of the scene's nodes
/// (each after its parent, depth first from the roots). The hierarchy must be a forest
/// (glTF 2.0 §3.5.3): one parent at most, and a scene lists roots only. Then no walk from
/// a root meets a cycle, and every walk is a loop over the nodes, never a recursion, so
/// any depth is read, edited and written.
fn hierarchy(
    document: &::gltf::Document,
    all_nodes: &[::gltf::Node<'_>],
    json_nodes: Option<&Vec<Value>>,
) -> Result<(Vec<NodeInfo>, Vec<usize>), FormatError> {
    let count = all_nodes.len();
    let mut nodes: Vec<NodeInfo> = (0..count)
        .map(|i| NodeInfo {
            parent: None,
            local: json_nodes
                .and_then(|n| n.get(i))
                .map_or(DMat4::IDENTITY, local_from_json),
            world: DMat4::IDENTITY,
            in_scene: false,
        })
        .collect();
    for node in all_nodes {
        for child in node.children() {
            let c = child.index();
            match nodes[c].parent {
                Some(p) if p != node.index() => {
                    return Err(FormatError::invalid(format!(
                        "nodes[{c}] is a child of both nodes[{p}] and nodes[{}]; a glTF node has one parent at most",
                        node.index()
                    )))
                }
                _ => nodes[c].parent = Some(node.index()),
            }
        }
    }
    let roots: Vec<usize> = match document
        .default_scene()
        .or_else(|| document.scenes().next())
    {
        Some(scene) => {
            let roots: Vec<usize> = scene.nodes().map(|n| n.index()).collect();
            for (k, &r) in roots.iter().enumerate() {
                if let Some(p) = nodes[r].parent {
                    return Err(FormatError::invalid(format!(
                        "scenes[{}].nodes[{k}] is nodes[{r}], a child of nodes[{p}]; a scene lists root nodes only",
                        scene.index()
                    )));
                }
            }
            roots
        }
        None => (0..count).filter(|&i| nodes[i].parent.is_none()).collect(),
    };
    // Depth-first from the roots, computing world matrices; each node is visited once.
    let mut order = Vec::new();
    let mut stack: Vec<(usize, DMat4)> =
        roots.iter().rev().map(|&r| (r, DMat4::IDENTITY)).collect();
    while let Some((index, parent_world)) = stack.pop() {
        if nodes[index].in_scene {
            continue;
        }
        let world = parent_world * nodes[index].local;
        nodes[index].world = world;
        nodes[index].in_scene = true;
        order.push(index);
        let node = &all_nodes[index];
        for child in node.children().collect::<Vec<_>>().into_iter().rev() {
            stack.push((child.index(), world));
        }
    }

    Ok((nodes, order))
}

/// The scene's nodes as the tree the shared reading step takes ([`super::facts`]): names,
/// parents, world transforms in metres, vertex positions, the words and fronts their
/// JSON gives.
fn tree_of(
    all_nodes: &[::gltf::Node<'_>],
    nodes: &[NodeInfo],
    order: &[usize],
    json_nodes: Option<&Vec<Value>>,
    buffers: &[Vec<u8>],
    unit: f64,
) -> Result<super::facts::Tree, FormatError> {
    let count = all_nodes.len();
    let to_metres = DMat4::from_scale(DVec3::splat(unit));
    let mut tree = super::facts::Tree::default();
    let mut tree_index = vec![usize::MAX; count];
    for &index in order {
        let node = &all_nodes[index];
        let world = to_metres * nodes[index].world;
        let (points, triangles) = match node.mesh() {
            Some(mesh) => mesh_points(node, &mesh, buffers, world)?,
            None => (Vec::new(), Vec::new()),
        };
        tree_index[index] = tree.nodes.len();
        tree.nodes.push(super::facts::Node {
            name: node.name().unwrap_or_default().to_string(),
            parent: nodes[index].parent.map(|p| tree_index[p]),
            world,
            points,
            triangles,
            transformable: true,
            model: false,
            given_name: None,
            labels: {
                let mut labels = node
                    .mesh()
                    .map_or_else(Labels::default, |m| labels_of(node, &m));
                let json_node = json_nodes.and_then(|n| n.get(index));
                if let Some(c) =
                    json_node.and_then(|n| n.get("extras")?.get("shenlong:category")?.as_str())
                {
                    labels.category = Some(c.to_string());
                }
                labels
            },
            front: json_nodes.and_then(|n| n.get(index)).and_then(extras_front),
            fallback: match node.name() {
                Some(n) if !n.trim().is_empty() => format!("{} (node {index})", n.trim()),
                _ => format!("node {index}"),
            },
        });
    }
    Ok(tree)
}

/// A mesh node's vertex positions, each once, placed by `world`, and its triangles as
/// indices into them; refused when the positions cannot be read or lie beyond the limits.
fn mesh_points(
    node: &::gltf::Node<'_>,
    mesh: &::gltf::Mesh<'_>,
    buffers: &[Vec<u8>],
    world: DMat4,
) -> Result<(Vec<DVec3>, Vec<[u32; 3]>), FormatError> {
    let index = node.index();
    let mut points = Vec::new();
    let mut triangles = Vec::new();
    let mut seen = HashMap::new();
    for primitive in mesh.primitives() {
        let reader = primitive.reader(|b| buffers.get(b.index()).map(Vec::as_slice));
        // Where each of the primitive's vertices is in `points`.
        let mut at = Vec::new();
        if let Some(positions) = reader.read_positions() {
            for p in positions {
                let next = u32::try_from(points.len()).unwrap_or(u32::MAX);
                let k = *seen.entry(p.map(f32::to_bits)).or_insert_with(|| {
                    let local = DVec3::new(p[0] as f64, p[1] as f64, p[2] as f64);
                    points.push(world.transform_point3(local));
                    next
                });
                at.push(k);
            }
        }
        primitive_triangles(&primitive, &reader, &at, &mut triangles);
    }
    let has_positions = mesh
        .primitives()
        .any(|p| p.get(&::gltf::Semantic::Positions).is_some());
    let label = node.name().map(|n| format!(" ('{n}')")).unwrap_or_default();
    if points.iter().any(|p| !p.is_finite()) || (points.is_empty() && has_positions) {
        return Err(FormatError::invalid(format!(
            "nodes[{index}]{label}: its mesh's vertex positions cannot be read (a missing or short buffer, or numbers that are not finite)"
        )));
    }
    // A node transform (or vertex) that puts the mesh beyond the scene limits would
    // leave every later edit inexact; refuse it here, with the node named.
    if let Some(far) = points
        .iter()
        .map(|p| p.abs().max_element())
        .find(|&d| d > MAX_COORDINATE)
    {
        return Err(FormatError::invalid(format!(
            "nodes[{index}]{label}: its mesh lies {far:.3e} m from the origin, beyond the ±{MAX_COORDINATE:.0e} m Shenlong keeps exact (check the node's transform and its parents')"
        )));
    }
    Ok((points, triangles))
}

/// Appends the triangles of a primitive drawn as triangles (a list, a strip or a fan) to
/// `out`, as indices into the node's points (`at`: where each of the primitive's vertices
/// is); indices beyond its vertices are left out, and past [`MAX_TRIANGLES`] in all, the
/// rest (the node then keeps the form of its kind).
///
/// [`MAX_TRIANGLES`]: crate::scene::mesh::MAX_TRIANGLES
fn primitive_triangles<'a, 's, F>(
    primitive: &::gltf::Primitive<'a>,
    reader: &::gltf::mesh::Reader<'a, 's, F>,
    at: &[u32],
    out: &mut Vec<[u32; 3]>,
) where
    F: Clone + Fn(::gltf::Buffer<'a>) -> Option<&'s [u8]>,
{
    use ::gltf::mesh::Mode;
    let indices: Vec<u32> = match reader.read_indices() {
        Some(read) => read.into_u32().collect(),
        None => (0..u32::try_from(at.len()).unwrap_or(u32::MAX)).collect(),
    };
    let corner = |k: u32| at.get(k as usize).copied();
    let mut push = |a: u32, b: u32, c: u32| {
        if out.len() <= crate::scene::mesh::MAX_TRIANGLES {
            if let (Some(a), Some(b), Some(c)) = (corner(a), corner(b), corner(c)) {
                out.push([a, b, c]);
            }
        }
    };
    match primitive.mode() {
        Mode::Triangles => indices.chunks_exact(3).for_each(|t| push(t[0], t[1], t[2])),
        Mode::TriangleStrip => indices.windows(3).for_each(|t| push(t[0], t[1], t[2])),
        Mode::TriangleFan => {
            if let Some((&first, rest)) = indices.split_first() {
                rest.windows(2).for_each(|t| push(first, t[0], t[1]));
            }
        }
        _ => {}
    }
}

/// A node's own front (`extras: {"shenlong:front": [x, y, z]}`), in its own axes.
fn extras_front(node: &Value) -> Option<DVec3> {
    let v = node.get("extras")?.get("shenlong:front")?.as_array()?;
    let xyz: Vec<f64> = v.iter().filter_map(Value::as_f64).collect();
    (xyz.len() == 3)
        .then(|| DVec3::from_slice(&xyz))
        .filter(|d| d.is_finite() && d.length() > 0.0)
}

/// What a mesh node is called besides its name: its mesh's name as the category (glTF
/// files often name nodes `Chair.001` and meshes `Chair`), and its materials' names as
/// attributes (`red_plastic`, `Oak`). Grounding splits camelCase and snake_case and drops
/// numeric suffixes.
fn labels_of(node: &::gltf::Node<'_>, mesh: &::gltf::Mesh<'_>) -> Labels {
    let category = mesh
        .name()
        .map(str::trim)
        .filter(|m| !m.is_empty() && node.name().is_none_or(|n| n.trim() != *m))
        .map(str::to_string);
    let mut attributes: Vec<String> = Vec::new();
    for primitive in mesh.primitives() {
        if let Some(name) = primitive.material().name() {
            let name = name.trim();
            if !name.is_empty() && !attributes.iter().any(|a| a == name) {
                attributes.push(name.to_string());
            }
        }
    }
    Labels {
        category,
        aliases: Vec::new(),
        attributes,
    }
}

/// A node's local transform from its JSON, in f64: `matrix` (column-major) or
/// translation · rotation · scale.
fn local_from_json(node: &Value) -> DMat4 {
    let numbers = |key: &str| -> Option<Vec<f64>> {
        node.get(key)?
            .as_array()?
            .iter()
            .map(Value::as_f64)
            .collect()
    };
    if let Some(m) = numbers("matrix").filter(|m| m.len() == 16) {
        return DMat4::from_cols_slice(&m);
    }
    let t = numbers("translation")
        .filter(|v| v.len() == 3)
        .map_or(DVec3::ZERO, |v| DVec3::from_slice(&v));
    let r = numbers("rotation")
        .filter(|v| v.len() == 4)
        .map_or(DQuat::IDENTITY, |v| DQuat::from_slice(&v).normalize());
    let s = numbers("scale")
        .filter(|v| v.len() == 3)
        .map_or(DVec3::ONE, |v| DVec3::from_slice(&v));
    DMat4::from_scale_rotation_translation(s, r, t)
}

fn load_buffers(
    document: &::gltf::Document,
    blob: Option<&[u8]>,
    base_dir: &Path,
) -> Result<Vec<Vec<u8>>, FormatError> {
    let mut buffers = Vec::new();
    for buffer in document.buffers() {
        let mut data = match buffer.source() {
            ::gltf::buffer::Source::Bin => blob
                .ok_or_else(|| {
                    FormatError::invalid(format!(
                        "buffers[{}] refers to a GLB binary chunk that is missing",
                        buffer.index()
                    ))
                })?
                .to_vec(),
            ::gltf::buffer::Source::Uri(uri) => {
                if let Some(rest) = uri.strip_prefix("data:") {
                    let encoded = rest.split_once(";base64,").map(|(_, d)| d).ok_or_else(|| {
                        FormatError::invalid(format!(
                            "buffers[{}]: only base64 data URIs are supported",
                            buffer.index()
                        ))
                    })?;
                    base64::engine::general_purpose::STANDARD
                        .decode(encoded)
                        .map_err(|e| {
                            FormatError::invalid(format!(
                                "buffers[{}]: invalid base64 data: {e}",
                                buffer.index()
                            ))
                        })?
                } else {
                    let file = resolve_uri(base_dir, uri).map_err(|e| {
                        FormatError::invalid(format!("buffers[{}]: {e}", buffer.index()))
                    })?;
                    std::fs::read(&file).map_err(|e| {
                        FormatError::invalid(format!(
                            "buffers[{}]: cannot read {}: {e}",
                            buffer.index(),
                            file.display()
                        ))
                    })?
                }
            }
        };
        if data.len() < buffer.length() {
            return Err(FormatError::invalid(format!(
                "buffers[{}] has {} bytes; the file says {}",
                buffer.index(),
                data.len(),
                buffer.length()
            )));
        }
        // The GLB chunk may be padded past the buffer's length.
        data.truncate(buffer.length());
        buffers.push(data);
    }
    Ok(buffers)
}

/// Checks every index the reader follows (a node's mesh and children, a scene's nodes, a
/// primitive's accessors and material, an accessor's buffer view, a view's buffer), so
/// that a file pointing at what does not exist is refused with where, not a panic.
fn check_indices(json: &Value) -> Result<(), FormatError> {
    let count = |key: &str| json.get(key).and_then(Value::as_array).map_or(0, Vec::len);
    let check = |at: String, value: Option<&Value>, key: &str| -> Result<(), FormatError> {
        let Some(v) = value else { return Ok(()) };
        let n = count(key);
        match v.as_u64() {
            Some(i) if (i as usize) < n => Ok(()),
            _ => Err(FormatError::invalid(format!(
                "{at} is {v}, but the file has {n} {key}"
            ))),
        }
    };
    let list = |key: &str| {
        json.get(key)
            .and_then(Value::as_array)
            .cloned()
            .unwrap_or_default()
    };
    for (i, node) in list("nodes").iter().enumerate() {
        check(format!("nodes[{i}].mesh"), node.get("mesh"), "meshes")?;
        for (k, c) in node
            .get("children")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
            .enumerate()
        {
            check(format!("nodes[{i}].children[{k}]"), Some(c), "nodes")?;
        }
    }
    for (i, scene) in list("scenes").iter().enumerate() {
        for (k, n) in scene
            .get("nodes")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
            .enumerate()
        {
            check(format!("scenes[{i}].nodes[{k}]"), Some(n), "nodes")?;
        }
    }
    check("scene".into(), json.get("scene"), "scenes")?;
    for (i, mesh) in list("meshes").iter().enumerate() {
        for (k, p) in mesh
            .get("primitives")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
            .enumerate()
        {
            for (name, a) in p
                .get("attributes")
                .and_then(Value::as_object)
                .into_iter()
                .flatten()
            {
                check(
                    format!("meshes[{i}].primitives[{k}].attributes.{name}"),
                    Some(a),
                    "accessors",
                )?;
            }
            check(
                format!("meshes[{i}].primitives[{k}].indices"),
                p.get("indices"),
                "accessors",
            )?;
            check(
                format!("meshes[{i}].primitives[{k}].material"),
                p.get("material"),
                "materials",
            )?;
        }
    }
    for (i, a) in list("accessors").iter().enumerate() {
        check(
            format!("accessors[{i}].bufferView"),
            a.get("bufferView"),
            "bufferViews",
        )?;
    }
    for (i, v) in list("bufferViews").iter().enumerate() {
        check(
            format!("bufferViews[{i}].buffer"),
            v.get("buffer"),
            "buffers",
        )?;
    }
    for (i, a) in list("accessors").iter().enumerate() {
        for part in ["indices", "values"] {
            check(
                format!("accessors[{i}].sparse.{part}.bufferView"),
                a.get("sparse")
                    .and_then(|s| s.get(part))
                    .and_then(|p| p.get("bufferView")),
                "bufferViews",
            )?;
        }
    }
    for (i, animation) in list("animations").iter().enumerate() {
        for (k, c) in animation
            .get("channels")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
            .enumerate()
        {
            check(
                format!("animations[{i}].channels[{k}].target.node"),
                c.get("target").and_then(|t| t.get("node")),
                "nodes",
            )?;
        }
    }
    Ok(())
}

/// Checks every accessor the reader reads (the meshes' `POSITION` attributes) before the
/// gltf crate reads it, so that what the crate would assert on, overflow or read past is
/// refused with the accessor named: the type (`VEC3` of `FLOAT`), a count of at least one,
/// each buffer view's `byteStride` (at least the element's size) and bounds (`byteOffset +
/// byteStride × (count − 1) + element size` within the view, the view within its buffer),
/// for the accessor's own view and a sparse accessor's indices and values alike. The
/// arithmetic is checked, so no count or offset can overflow it.
fn check_accessors(json: &Value) -> Result<(), FormatError> {
    let list = |key: &str| json.get(key).and_then(Value::as_array);
    let number = |v: &Value, key: &str| v.get(key).and_then(Value::as_u64);
    let accessors = list("accessors");
    let views = list("bufferViews");
    let buffers = list("buffers");
    let mut positions: Vec<u64> = list("meshes")
        .into_iter()
        .flatten()
        .filter_map(|m| m.get("primitives").and_then(Value::as_array))
        .flatten()
        .filter_map(|p| p.get("attributes")?.get("POSITION")?.as_u64())
        .collect();
    positions.sort_unstable();
    positions.dedup();
    // `count` elements of `size` bytes from `offset` in bufferViews[view], for `what`.
    let check_view = |what: &str, view: u64, offset: u64, count: u64, size: u64| {
        let fail = |why: String| Err(FormatError::invalid(format!("{what}: {why}")));
        let Some(v) = views.and_then(|v| v.get(view as usize)) else {
            return fail(format!("bufferViews[{view}] does not exist"));
        };
        let stride = match v.get("byteStride") {
            None => size,
            Some(s) => match s.as_u64() {
                // 0 is read as tightly packed, as the gltf crate does.
                Some(0) => size,
                Some(s) if s >= size => s,
                _ => {
                    return fail(format!(
                        "bufferViews[{view}].byteStride is {s}, less than its {size}-byte elements"
                    ))
                }
            },
        };
        let length = number(v, "byteLength").unwrap_or(0);
        let end = (count - 1)
            .checked_mul(stride)
            .and_then(|n| n.checked_add(offset))
            .and_then(|n| n.checked_add(size));
        match end {
            Some(end) if end <= length => {}
            _ => {
                return fail(format!(
                    "{count} elements of {size} bytes every {stride} from byte {offset} do not fit in bufferViews[{view}]'s {length} bytes"
                ))
            }
        }
        let buffer = number(v, "buffer").unwrap_or(0);
        let buffer_length = buffers
            .and_then(|b| b.get(buffer as usize))
            .and_then(|b| number(b, "byteLength"))
            .unwrap_or(0);
        let view_offset = number(v, "byteOffset").unwrap_or(0);
        if view_offset
            .checked_add(length)
            .is_none_or(|end| end > buffer_length)
        {
            return fail(format!(
                "bufferViews[{view}] ({length} bytes from byte {view_offset}) does not fit in buffers[{buffer}]'s {buffer_length} bytes"
            ));
        }
        Ok(())
    };
    for index in positions {
        let what = format!("accessors[{index}] (vertex positions)");
        let Some(a) = accessors.and_then(|a| a.get(index as usize)) else {
            continue; // check_indices has refused it
        };
        let fail = |why: &str| Err(FormatError::invalid(format!("{what}: {why}")));
        if a.get("type").and_then(Value::as_str) != Some("VEC3")
            || number(a, "componentType") != Some(5126)
        {
            return fail("positions must be VEC3 of FLOAT (componentType 5126)");
        }
        let count = number(a, "count").unwrap_or(0);
        if count == 0 {
            return fail("its count is 0; an accessor has one element at least");
        }
        if let Some(view) = number(a, "bufferView") {
            check_view(&what, view, number(a, "byteOffset").unwrap_or(0), count, 12)?;
        }
        let Some(sparse) = a.get("sparse") else {
            continue;
        };
        let sparse_count = number(sparse, "count").unwrap_or(0);
        if sparse_count == 0 || sparse_count > count {
            return fail(&format!(
                "its sparse count is {sparse_count}; it must be from 1 to the accessor's {count}"
            ));
        }
        let part = |key: &str| sparse.get(key).cloned().unwrap_or(Value::Null);
        let (indices, values) = (part("indices"), part("values"));
        let index_size = match number(&indices, "componentType") {
            Some(5121) => 1,
            Some(5123) => 2,
            Some(5125) => 4,
            _ => {
                return fail(
                    "its sparse indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT",
                )
            }
        };
        for (key, part, size) in [("indices", &indices, index_size), ("values", &values, 12)] {
            let Some(view) = number(part, "bufferView") else {
                return fail(&format!("its sparse {key} name no bufferView"));
            };
            check_view(
                &format!("{what}, sparse {key}"),
                view,
                number(part, "byteOffset").unwrap_or(0),
                sparse_count,
                size,
            )?;
        }
    }
    Ok(())
}

/// The largest external resource read, in bytes.
pub const MAX_RESOURCE_BYTES: u64 = 1 << 30;

/// Where a relative URI of a glTF file points: inside the file's folder only — no absolute
/// paths, no `..`, no link out of the folder — and at a regular file (not a device or a
/// pipe) of at most [`MAX_RESOURCE_BYTES`]. A hostile file cannot make Shenlong read
/// elsewhere, hang on a FIFO or run out of memory on `/dev/zero`.
pub(crate) fn resolve_uri(base_dir: &Path, uri: &str) -> Result<PathBuf, UriError> {
    let decoded = percent_decode(uri);
    let relative = PathBuf::from(&decoded);
    let escapes = relative.is_absolute()
        || decoded.contains(':')
        || decoded.starts_with('\\')
        || relative.components().any(|c| {
            !matches!(
                c,
                std::path::Component::Normal(_) | std::path::Component::CurDir
            )
        });
    if escapes {
        return Err(UriError::Escapes(uri.chars().take(200).collect()));
    }
    let base = if base_dir.as_os_str().is_empty() {
        Path::new(".")
    } else {
        base_dir
    };
    let path = base.join(&relative);
    let Ok(real_base) = base.canonicalize() else {
        return Err(UriError::Refused(relative, super::NotInside::Missing));
    };
    match super::file_inside(&path, &real_base) {
        Ok(()) => Ok(path),
        Err(why) => Err(UriError::Refused(relative, why)),
    }
}

/// Why a glTF file's URI is not read.
#[derive(Debug, thiserror::Error)]
pub(crate) enum UriError {
    /// An absolute path, a scheme or `..`: somewhere else than the file's folder.
    #[error("the URI '{0}' points outside the glTF file's folder; only relative paths inside it are read")]
    Escapes(String),
    /// The file it names is not one Shenlong reads.
    #[error("{}", refused(.0, .1))]
    Refused(PathBuf, super::NotInside),
}

fn refused(relative: &Path, why: &super::NotInside) -> String {
    let name = relative.display();
    match why {
        super::NotInside::Missing => format!("cannot find '{name}' beside the glTF file"),
        super::NotInside::Outside => {
            format!("'{name}' links outside the glTF file's folder; only files inside it are read")
        }
        super::NotInside::Unreadable(e) => format!("cannot read '{name}': {e}"),
        super::NotInside::NotAFile => format!("'{name}' is not a regular file"),
        super::NotInside::TooLarge => {
            format!("'{name}' is larger than {} MiB", MAX_RESOURCE_BYTES >> 20)
        }
    }
}

/// Decodes `%XX` escapes in a relative URI.
pub(crate) fn percent_decode(uri: &str) -> String {
    let bytes = uri.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    let hex = |b: u8| (b as char).to_digit(16);
    while i < bytes.len() {
        // (On bytes: a `%` before a character of several bytes is no escape, not a panic.)
        if bytes[i] == b'%' && i + 2 < bytes.len() {
            if let (Some(high), Some(low)) = (hex(bytes[i + 1]), hex(bytes[i + 2])) {
                out.push((high * 16 + low) as u8);
                i += 3;
                continue;
            }
        }
        out.push(bytes[i]);
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// The bytes of the edited file, in the source's container. An unchanged scene gives the
/// original bytes.
pub fn write(scene: &Scene, document: &GltfDocument) -> Result<Vec<u8>, FormatError> {
    match edited_json(scene, document)? {
        None => Ok(document.original.clone()),
        Some(json) => match &document.container {
            Container::Glb => glb_bytes(&json, document.bin.as_deref()),
            Container::Gltf { .. } => Ok(super::pretty::to_string(&json).into_bytes()),
        },
    }
}

/// The edited `.gltf` with its external buffers' and images' URIs replaced as `uris` says
/// (from the URI as the file has it to the new one): the file written in another folder,
/// beside copies of its resources under names Shenlong chose.
pub(crate) fn write_relocated(
    scene: &Scene,
    document: &GltfDocument,
    uris: &std::collections::HashMap<String, String>,
) -> Result<Vec<u8>, FormatError> {
    if document.container == Container::Glb {
        return Err(FormatError::invalid(
            "a binary glTF keeps its resources: it is written as it is",
        ));
    }
    let mut json = edited_json(scene, document)?.unwrap_or_else(|| document.json.clone());
    for key in ["buffers", "images"] {
        for item in json
            .get_mut(key)
            .and_then(Value::as_array_mut)
            .into_iter()
            .flatten()
        {
            let Some(uri) = item.get_mut("uri") else {
                continue;
            };
            if let Some(new) = uri.as_str().and_then(|u| uris.get(u)) {
                *uri = Value::String(new.clone());
            }
        }
    }
    Ok(super::pretty::to_string(&json).into_bytes())
}

/// The document's JSON with the moved nodes' new local transforms; `None` when nothing
/// moved.
fn edited_json(scene: &Scene, document: &GltfDocument) -> Result<Option<Value>, FormatError> {
    if scene.objects.len() != document.object_nodes.len() {
        return Err(FormatError::invalid(
            "the scene's objects no longer match the glTF nodes",
        ));
    }
    // New world matrices: each object node moves by its pose; other nodes keep their
    // local transform and so follow their parent.
    let mut deltas = vec![None; document.nodes.len()];
    let c = DMat4::from_scale(DVec3::splat(document.meters_per_unit));
    let c_inv = c.inverse();
    for (object, &node) in scene.objects.iter().zip(&document.object_nodes) {
        deltas[node] = super::transform::world_motion(object).map(|m| c_inv * m * c);
    }
    if deltas.iter().all(Option::is_none) {
        return Ok(None);
    }
    let mut is_object = vec![false; document.nodes.len()];
    for &node in &document.object_nodes {
        is_object[node] = true;
    }
    // Parents before children, in one loop: no recursion, however deep the hierarchy.
    let mut new_world = vec![DMat4::IDENTITY; document.nodes.len()];
    for &index in &document.order {
        let info = &document.nodes[index];
        new_world[index] = if is_object[index] {
            deltas[index].map_or(info.world, |d| d * info.world)
        } else {
            info.parent.map_or(DMat4::IDENTITY, |p| new_world[p]) * info.local
        };
    }
    let mut json = document.json.clone();
    for &node in &document.object_nodes {
        let info = &document.nodes[node];
        let world = new_world[node];
        let parent_world = info.parent.map_or(DMat4::IDENTITY, |p| new_world[p]);
        let local = parent_world.inverse() * world;
        if super::transform::nearly_equal(&local, &info.local, 1e-12) {
            continue;
        }
        let target = json
            .get_mut("nodes")
            .and_then(|n| n.get_mut(node))
            .and_then(Value::as_object_mut)
            .ok_or_else(|| FormatError::invalid(format!("nodes[{node}] is missing")))?;
        write_local(target, node, &local, document.animated.contains(&node))?;
    }
    Ok(Some(json))
}

/// Writes a node's new local transform, as a matrix if it had one, else as TRS (falling
/// back to a matrix when the transform has shear, which TRS cannot express).
fn write_local(
    node: &mut serde_json::Map<String, Value>,
    index: usize,
    local: &DMat4,
    animated: bool,
) -> Result<(), FormatError> {
    let numbers = |values: &[f64]| Value::Array(values.iter().map(|&x| json_number(x)).collect());
    let trs = super::transform::as_trs(local);
    let Some((scale, rotation, translation)) = trs.filter(|_| !node.contains_key("matrix")) else {
        if animated {
            return Err(FormatError::invalid(format!(
                "nodes[{index}] is animated, so its transform must stay TRS, but the edit gives it a shear"
            )));
        }
        for key in ["translation", "rotation", "scale"] {
            node.remove(key);
        }
        node.insert("matrix".into(), numbers(&local.to_cols_array()));
        return Ok(());
    };
    node.insert("translation".into(), numbers(&translation.to_array()));
    node.insert("rotation".into(), numbers(&rotation.normalize().to_array()));
    node.insert("scale".into(), numbers(&scale.to_array()));
    Ok(())
}

fn json_number(x: f64) -> Value {
    let x = if x == 0.0 { 0.0 } else { x };
    serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number)
}

/// A GLB container: header, JSON chunk padded with spaces, binary chunk as it was.
pub(crate) fn glb_bytes(json: &Value, bin: Option<&[u8]>) -> Result<Vec<u8>, FormatError> {
    let mut json_chunk = serde_json::to_vec(json)
        .map_err(|e| FormatError::invalid(format!("the glTF JSON cannot be written: {e}")))?;
    while json_chunk.len() % 4 != 0 {
        json_chunk.push(b' ');
    }
    let bin_len = bin.map_or(0, |b| 8 + b.len().next_multiple_of(4));
    let total = 12 + 8 + json_chunk.len() + bin_len;
    if u32::try_from(total).is_err() {
        return Err(FormatError::too_large(format!(
            "the edited GLB would be {total} bytes, more than the 4 GiB the format can hold"
        )));
    }
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(json_chunk.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&json_chunk);
    if let Some(bin) = bin {
        let padded = bin.len().next_multiple_of(4);
        out.extend_from_slice(&(padded as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        out.extend_from_slice(bin);
        out.resize(out.len() + (padded - bin.len()), 0);
    }
    Ok(out)
}

#[cfg(test)]
mod uri_tests {
    use super::*;

    /// A one-triangle glTF whose buffer is at `uri`.
    fn gltf_with_buffer(uri: &str) -> String {
        format!(
            r#"{{"asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": [0]}}],
            "nodes": [{{"name": "tri", "mesh": 0}}],
            "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}}}]}}],
            "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 0]}}],
            "bufferViews": [{{"buffer": 0, "byteLength": 36}}],
            "buffers": [{{"byteLength": 36, "uri": "{uri}"}}]}}"#
        )
    }

    #[test]
    fn buffer_uris_stay_inside_the_files_folder() {
        let dir = tempfile::tempdir().unwrap();
        let inner = dir.path().join("scene");
        std::fs::create_dir(&inner).unwrap();
        std::fs::write(dir.path().join("secret.bin"), [0u8; 36]).unwrap();
        for uri in [
            "../secret.bin",
            "/etc/passwd",
            "%2E%2E/secret.bin",
            "file:///etc/passwd",
            "C:/x.bin",
        ] {
            let path = inner.join("t.gltf");
            std::fs::write(&path, gltf_with_buffer(uri)).unwrap();
            let e = read(&path, &crate::format::ReadOptions::default()).unwrap_err();
            assert!(
                e.to_string().contains("outside the glTF file's folder"),
                "{uri}: {}",
                e
            );
            assert!(
                !e.to_string().contains("36"),
                "{uri}: the message reveals nothing of the file: {}",
                e
            );
        }
        // A device is not a regular file (and is never read whole).
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink("/dev/zero", inner.join("zero.bin")).unwrap();
            let path = inner.join("t.gltf");
            std::fs::write(&path, gltf_with_buffer("zero.bin")).unwrap();
            let e = read(&path, &crate::format::ReadOptions::default()).unwrap_err();
            assert!(
                e.to_string().contains("outside") || e.to_string().contains("not a regular file"),
                "{}",
                e.to_string()
            );
        }
        // A buffer beside the file is read.
        let mut bytes = Vec::new();
        for v in [0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0] {
            bytes.extend_from_slice(&v.to_le_bytes());
        }
        std::fs::write(inner.join("ok.bin"), &bytes).unwrap();
        let path = inner.join("ok.gltf");
        std::fs::write(&path, gltf_with_buffer("ok.bin")).unwrap();
        assert_eq!(
            read(&path, &crate::format::ReadOptions::default())
                .unwrap()
                .0
                .objects
                .len(),
            1
        );
    }
}

#[cfg(test)]
mod index_tests {
    use super::*;

    #[test]
    fn a_node_pointing_at_a_missing_mesh_is_refused_not_panicked_on() {
        let text = r#"{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
            "nodes": [{"name": "ghost", "mesh": 3}], "meshes": []}"#;
        let e = read_bytes(text.as_bytes().to_vec(), Path::new("."), "t").unwrap_err();
        assert!(
            e.to_string()
                .contains("nodes[0].mesh is 3, but the file has 0 meshes"),
            "{}",
            e.to_string()
        );
        let text = r#"{"asset": {"version": "2.0"}, "scenes": [{"nodes": [5]}], "nodes": []}"#;
        let e = read_bytes(text.as_bytes().to_vec(), Path::new("."), "t").unwrap_err();
        assert!(
            e.to_string().contains("scenes[0].nodes[0] is 5"),
            "{}",
            e.to_string()
        );
    }

    #[test]
    fn a_glb_header_shorter_than_itself_is_refused() {
        // Found by the `gltf` fuzz target: a declared length of 0 overflowed in the gltf crate.
        let mut bytes = b"glTF".to_vec();
        bytes.extend_from_slice(&2u32.to_le_bytes());
        bytes.extend_from_slice(&0u32.to_le_bytes());
        bytes.extend_from_slice(b"\x00\x03E\x00JSON{}");
        let e = read_bytes(bytes, Path::new("."), "t").unwrap_err();
        assert!(
            e.to_string().contains("declares 0 bytes"),
            "{}",
            e.to_string()
        );
    }

    #[test]
    fn a_mesh_whose_positions_cannot_be_read_is_refused_not_dropped() {
        // The accessor says 3 vertices; the buffer has 12 bytes, not 36.
        let text = r#"{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
            "nodes": [{"name": "tri", "mesh": 0}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
            "bufferViews": [{"buffer": 0, "byteLength": 12}],
            "buffers": [{"byteLength": 12, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAA"}]}"#;
        let e = read_bytes(text.as_bytes().to_vec(), Path::new("."), "t").unwrap_err();
        assert!(
            e.to_string().contains(
                "accessors[0] (vertex positions): 3 elements of 12 bytes every 12 from byte 0 do not fit in bufferViews[0]'s 12 bytes"
            ),
            "{}",
            e.to_string()
        );
        // Vertices that are not finite: the node is named.
        let nan =
            base64::engine::general_purpose::STANDARD.encode(f32::NAN.to_le_bytes().repeat(9));
        let text = text
            .replace(r#""byteLength": 12"#, r#""byteLength": 36"#)
            .replace("AAAAAAAAAAAAAAAA", &nan);
        let e = read_bytes(text.into_bytes(), Path::new("."), "t").unwrap_err();
        assert!(
            e.to_string().contains("nodes[0] ('tri')"),
            "{}",
            e.to_string()
        );
    }

    /// A triangle mesh under `nodes`, as glTF text with an embedded buffer.
    fn triangle_under(nodes: &str) -> String {
        let mut bytes = Vec::new();
        for v in [0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0] {
            bytes.extend_from_slice(&v.to_le_bytes());
        }
        let data = base64::engine::general_purpose::STANDARD.encode(&bytes);
        format!(
            r#"{{"asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": [0]}}],
            "nodes": {nodes},
            "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}}}]}}],
            "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 0]}}],
            "bufferViews": [{{"buffer": 0, "byteLength": 36}}],
            "buffers": [{{"byteLength": 36, "uri": "data:application/octet-stream;base64,{data}"}}]}}"#
        )
    }

    #[test]
    fn strides_and_bounds_the_gltf_crate_would_panic_on_are_refused_with_the_accessor_named() {
        // Each edit of the one-triangle file, and what the one-line error must say. Every
        // one of them panicked inside the gltf crate (an assertion, an overflow, an unwrap).
        type Edit<'a> = &'a dyn Fn(&mut Value);
        let cases: [(&str, Edit, &str); 10] = [
            ("stride 4", &|j| j["bufferViews"][0]["byteStride"] = 4.into(),
             "accessors[0] (vertex positions): bufferViews[0].byteStride is 4, less than its 12-byte elements"),
            ("stride 1", &|j| j["bufferViews"][0]["byteStride"] = 1.into(),
             "bufferViews[0].byteStride is 1"),
            ("offset", &|j| j["accessors"][0]["byteOffset"] = 4.into(),
             "accessors[0] (vertex positions): 3 elements of 12 bytes every 12 from byte 4 do not fit in bufferViews[0]'s 36 bytes"),
            ("huge count", &|j| j["accessors"][0]["count"] = (1u64 << 62).into(),
             "accessors[0] (vertex positions): 4611686018427387904 elements"),
            ("no count", &|j| j["accessors"][0]["count"] = 0.into(),
             "accessors[0] (vertex positions): its count is 0"),
            ("bytes", &|j| j["accessors"][0]["componentType"] = 5121.into(),
             "accessors[0] (vertex positions): positions must be VEC3 of FLOAT"),
            ("view past its buffer", &|j| j["bufferViews"][0]["byteOffset"] = 30.into(),
             "bufferViews[0] (36 bytes from byte 30) does not fit in buffers[0]'s 36 bytes"),
            ("sparse stride", &|j| {
                j["bufferViews"].as_array_mut().unwrap().push(
                    serde_json::json!({"buffer": 0, "byteLength": 36, "byteStride": 4}));
                j["accessors"][0]["sparse"] = serde_json::json!({"count": 1,
                    "indices": {"bufferView": 0, "componentType": 5125}, "values": {"bufferView": 1}});
            }, "accessors[0] (vertex positions), sparse values: bufferViews[1].byteStride is 4"),
            ("sparse view", &|j| j["accessors"][0]["sparse"] = serde_json::json!({"count": 1,
                    "indices": {"bufferView": 0, "componentType": 5125}, "values": {"bufferView": 7}}),
             "accessors[0].sparse.values.bufferView is 7, but the file has 1 bufferViews"),
            ("animated ghost", &|j| j["animations"] = serde_json::json!([{"channels":
                    [{"sampler": 0, "target": {"node": 9, "path": "translation"}}],
                    "samplers": [{"input": 0, "output": 0}]}]),
             "animations[0].channels[0].target.node is 9, but the file has 1 nodes"),
        ];
        let base: Value =
            serde_json::from_str(&triangle_under(r#"[{"name": "tri", "mesh": 0}]"#)).unwrap();
        for (case, edit, message) in cases {
            let mut json = base.clone();
            edit(&mut json);
            let bytes = serde_json::to_vec(&json).unwrap();
            let e = read_bytes(bytes, Path::new("."), "t").unwrap_err();
            assert!(e.to_string().contains(message), "{case}: {}", e);
            assert_eq!(e.to_string().lines().count(), 1, "{case}: {}", e);
        }
        // What is valid is still read: a stride of 12 or 0, a sparse accessor in bounds.
        for stride in [0, 12] {
            let mut json = base.clone();
            json["bufferViews"][0]["byteStride"] = stride.into();
            let bytes = serde_json::to_vec(&json).unwrap();
            assert_eq!(
                read_bytes(bytes, Path::new("."), "t")
                    .unwrap()
                    .0
                    .objects
                    .len(),
                1
            );
        }
        let mut json = base.clone();
        // Vertex 0 replaced by vertex 1 (index 0 is the u32 0 at byte 0; the value is bytes 12..24).
        json["bufferViews"]
            .as_array_mut()
            .unwrap()
            .push(serde_json::json!({"buffer": 0, "byteOffset": 12, "byteLength": 12}));
        json["accessors"][0]["sparse"] = serde_json::json!({"count": 1,
            "indices": {"bufferView": 0, "componentType": 5125}, "values": {"bufferView": 1}});
        let bytes = serde_json::to_vec(&json).unwrap();
        let scene = read_bytes(bytes, Path::new("."), "t").unwrap().0;
        assert_eq!(scene.objects.len(), 1);
    }

    #[test]
    fn a_cycle_of_empty_nodes_is_refused_or_never_walked() {
        // Through empty nodes below a root: one of them has two parents.
        let text = triangle_under(
            r#"[{"name": "root", "children": [1, 3]}, {"name": "a", "children": [2]},
                {"name": "b", "children": [1]}, {"name": "tri", "mesh": 0}]"#,
        );
        let e = read_bytes(text.into_bytes(), Path::new("."), "t").unwrap_err();
        assert!(
            e.to_string()
                .contains("nodes[1] is a child of both nodes[0] and nodes[2]"),
            "{}",
            e.to_string()
        );
        // A pure cycle with no root, in a file without scenes: no node is a root, nothing
        // is walked, and the read ends at once.
        let text =
            triangle_under(r#"[{"name": "a", "children": [1]}, {"name": "b", "children": [0]}]"#)
                .replace(r#""scene": 0, "scenes": [{"nodes": [0]}],"#, "");
        let (scene, _) = read_bytes(text.into_bytes(), Path::new("."), "t").unwrap();
        assert!(scene.objects.is_empty());
    }

    #[test]
    fn a_node_transform_beyond_the_limits_is_refused_with_the_node_named() {
        let read_text = |nodes: &str| {
            read_bytes(triangle_under(nodes).into_bytes(), Path::new("."), "t").map(|r| r.0)
        };
        // Within the limits: read.
        let scene =
            read_text(r#"[{"name": "tri", "mesh": 0, "translation": [1000, 0, 0]}]"#).unwrap();
        assert_eq!(scene.objects.len(), 1);
        // Its own translation is too far.
        let e =
            read_text(r#"[{"name": "tri", "mesh": 0, "translation": [2e9, 0, 0]}]"#).unwrap_err();
        assert!(
            e.to_string().contains("nodes[0] ('tri')"),
            "{}",
            e.to_string()
        );
        assert!(e.to_string().contains("beyond"), "{}", e.to_string());
        // A parent's scale takes the child's vertices too far.
        let e = read_text(
            r#"[{"name": "root", "children": [1], "scale": [1e7, 1e7, 1e7]},
                {"name": "tri", "mesh": 0, "translation": [0.5, 0, 0]}]"#,
        )
        .unwrap_err();
        assert!(
            e.to_string().contains("nodes[1] ('tri')"),
            "{}",
            e.to_string()
        );
    }
}

#[cfg(test)]
mod depth_tests {
    use super::*;
    use cga::Multivector;

    /// A chain of `depth` nodes, each the only child of the one before; the last one (or,
    /// with `meshes_everywhere`, every one) has a triangle mesh.
    pub(crate) fn chain(depth: usize, meshes_everywhere: bool) -> String {
        let mut bytes = Vec::new();
        for v in [0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0] {
            bytes.extend_from_slice(&v.to_le_bytes());
        }
        let data = base64::engine::general_purpose::STANDARD.encode(&bytes);
        let mut nodes = String::with_capacity(depth * 64);
        for i in 0..depth {
            if i > 0 {
                nodes.push(',');
            }
            nodes.push_str(&format!(
                r#"{{"name": "n{i}", "translation": [0, 0.001, 0]"#
            ));
            if i + 1 < depth {
                nodes.push_str(&format!(r#", "children": [{}]"#, i + 1));
            }
            if meshes_everywhere || i + 1 == depth {
                nodes.push_str(r#", "mesh": 0"#);
            }
            nodes.push('}');
        }
        format!(
            r#"{{"asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": [0]}}],
            "nodes": [{nodes}],
            "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}}}]}}],
            "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 0, 1]}}],
            "bufferViews": [{{"buffer": 0, "byteLength": 36}}],
            "buffers": [{{"byteLength": 36, "uri": "data:application/octet-stream;base64,{data}"}}]}}"#
        )
    }

    /// Runs `f` on a thread with the stack of the servers' worker threads (2 MiB).
    fn on_a_worker_stack(f: impl FnOnce() + Send + 'static) {
        std::thread::Builder::new()
            .stack_size(2 << 20)
            .spawn(f)
            .unwrap()
            .join()
            .unwrap();
    }

    #[test]
    fn deep_hierarchies_are_read_edited_and_written_without_recursion() {
        on_a_worker_stack(|| {
            for (depth, meshes_everywhere) in [(8_000, false), (8_000, true), (100_000, false)] {
                let text = chain(depth, meshes_everywhere);
                let (mut scene, document) =
                    read_bytes(text.into_bytes(), Path::new("."), "chain").unwrap();
                let objects = if meshes_everywhere { depth } else { 1 };
                assert_eq!(scene.objects.len(), objects);
                let leaf = objects - 1;
                let y = 0.001 * depth as f64;
                assert!((scene.objects[leaf].world_aabb().min.y - y).abs() < 1e-6);
                if meshes_everywhere {
                    assert_eq!(scene.objects[leaf].support, Some(leaf - 1));
                }
                scene
                    .apply(leaf, &Multivector::translator(DVec3::X), true)
                    .unwrap();
                let written = write(&scene, &document).unwrap();
                let (reread, _) = read_bytes(written, Path::new("."), "chain").unwrap();
                assert_eq!(reread.objects.len(), objects);
                let moved = reread.objects[leaf].world_aabb();
                assert!(
                    (moved.min - DVec3::new(1.0, y, 0.0)).length() < 1e-6,
                    "{depth}: {moved:?}"
                );
                if meshes_everywhere {
                    let root = reread.objects[0].world_aabb();
                    assert!((root.min - DVec3::new(0.0, 0.001, 0.0)).length() < 1e-9);
                }
            }
        });
    }

    #[test]
    fn a_node_with_two_parents_or_a_scene_root_with_a_parent_is_refused() {
        let text = index_tests_triangle(
            r#"[{"name": "a", "children": [2]}, {"name": "b", "children": [2]},
                {"name": "tri", "mesh": 0}]"#,
            "[0, 1]",
        );
        let e = read_bytes(text.into_bytes(), Path::new("."), "t").unwrap_err();
        assert!(
            e.to_string()
                .contains("nodes[2] is a child of both nodes[0] and nodes[1]"),
            "{}",
            e.to_string()
        );
        // A cycle: 1 → 2 → 1, below the root 0.
        let text = index_tests_triangle(
            r#"[{"name": "root", "children": [1]}, {"name": "a", "children": [2]},
                {"name": "tri", "mesh": 0, "children": [1]}]"#,
            "[0]",
        );
        let e = read_bytes(text.into_bytes(), Path::new("."), "t").unwrap_err();
        assert!(
            e.to_string().contains("a child of both"),
            "{}",
            e.to_string()
        );
        // A cycle on its own, reached from a scene: the root has a parent.
        let text = index_tests_triangle(
            r#"[{"name": "a", "children": [1]}, {"name": "tri", "mesh": 0, "children": [0]}]"#,
            "[0]",
        );
        let e = read_bytes(text.into_bytes(), Path::new("."), "t").unwrap_err();
        assert!(
            e.to_string()
                .contains("scenes[0].nodes[0] is nodes[0], a child of nodes[1]"),
            "{}",
            e.to_string()
        );
        // A cycle no scene reaches is not drawn and does no harm.
        let text = index_tests_triangle(
            r#"[{"name": "tri", "mesh": 0}, {"name": "a", "children": [2]},
                {"name": "b", "children": [1]}]"#,
            "[0]",
        );
        let (scene, document) = read_bytes(text.into_bytes(), Path::new("."), "t").unwrap();
        let mut scene = scene;
        scene
            .apply(0, &Multivector::translator(DVec3::X), false)
            .unwrap();
        write(&scene, &document).unwrap();
    }

    /// A triangle mesh under `nodes`, with the default scene's root `roots`.
    fn index_tests_triangle(nodes: &str, roots: &str) -> String {
        chain(1, true)
            .replace(
                r#""nodes": [{"name": "n0", "translation": [0, 0.001, 0], "mesh": 0}]"#,
                &format!(r#""nodes": {nodes}"#),
            )
            .replace(
                r#""scenes": [{"nodes": [0]}]"#,
                &format!(r#""scenes": [{{"nodes": {roots}}}]"#),
            )
    }

    #[test]
    fn json_nested_too_deep_is_refused_with_the_limit_and_where() {
        let deep = format!("{}{}", "[".repeat(200), "]".repeat(200));
        let text = chain(1, true).replacen(
            r#""asset": {"version": "2.0"}"#,
            &format!(r#""asset": {{"version": "2.0", "extras": {deep}}}"#),
            1,
        );
        let e = read_bytes(text.into_bytes(), Path::new("."), "t").unwrap_err();
        assert!(
            e.to_string()
                .starts_with("nesting deeper than 100 levels at line 1, column "),
            "{}",
            e.to_string()
        );
    }

    #[test]
    fn a_uri_with_a_percent_before_a_multibyte_character_is_not_a_panic() {
        for uri in ["%aé.bin", "%é", "x%", "%4"] {
            let _ = percent_decode(uri);
            let text =
                chain(1, true).replace("data:application/octet-stream;base64,", &format!("{uri}?"));
            assert!(read_bytes(text.into_bytes(), Path::new("."), "t").is_err());
        }
    }
}

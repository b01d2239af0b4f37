//! What every node-based reader (glTF, USD) shares once it has read what its file says:
//! the objects as a person sees them, their names, fronts, the room (floor, walls,
//! ceiling), the units and what rests on what.
//!
//! A reader supplies a [`Tree`]: each node's name, parent, world transform (already in
//! Shenlong's frame, Y-up metres), its own geometry and what its file says of it (a model
//! of kind `component`, a `shenlong:name`, a `shenlong:front`). [`derive`] makes the
//! scene:
//!
//! 1. **Objects.** A node that holds geometry below it is one object unless it is merely a
//!    group of objects: a node whose name is a group word (`World`, `Furniture`, `Props`,
//!    `Group`, `Collection`, `Scene`, `Root` …) or whose geometric children fall apart into
//!    separate clusters (boxes that neither touch nor overlap). So `/World/Furniture/Chair`
//!    is the chair, and a chair made of four meshes under one node is one chair. A node
//!    with geometry of its own is an object, and the nodes with geometry nested under it
//!    are objects resting on it. Where the file uses model kinds, its components are the
//!    objects.
//! 2. **Names** are the nodes' names; objects that share one are told apart by their group
//!    (`Chair in GroupA`, also `GroupA Chair`; `Chair in GroupB`), so that "the chair" is
//!    refused naming both.
//! 3. **The room.** Floors, walls and ceilings — by name in the common languages of
//!    exports, or by shape (a large thin slab under everything, tall thin slabs at the
//!    boundary) — and a room modelled as one mesh (`Room`, `Interior_Shell`, whose box
//!    holds the others) are not objects: they give the scene its bounds.
//! 4. **Fronts**: the format's front axis (or the node's own `shenlong:front`, or the
//!    run's) through the node's world rotation.
//! 5. **Units**: a scene whose furniture is tens of "metres" across is refused, naming the
//!    units it looks modelled in, unless the run says its units.
//! 6. **Supports**: nested objects rest on the object above them; the others by geometry,
//!    as for every format ([`Scene::detect_supports`]).

use super::FormatError;
use crate::geometry::Aabb;
use crate::scene::{Labels, Object, Pivot, Scene, Shape};
use glam::{DMat4, DVec3};

/// The units a file is modelled in, when its own metadata is missing or wrong.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Units {
    /// Millimetres (CAD exports).
    Millimetres,
    /// Centimetres.
    Centimetres,
    /// Metres.
    Metres,
    /// Inches.
    Inches,
    /// Feet.
    Feet,
}

impl Units {
    /// Metres per unit.
    #[must_use]
    pub fn meters(self) -> f64 {
        match self {
            Units::Millimetres => 0.001,
            Units::Centimetres => 0.01,
            Units::Metres => 1.0,
            Units::Inches => 0.0254,
            Units::Feet => 0.3048,
        }
    }

    /// The name in words (`millimetres`).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Units::Millimetres => "millimetres",
            Units::Centimetres => "centimetres",
            Units::Metres => "metres",
            Units::Inches => "inches",
            Units::Feet => "feet",
        }
    }

    /// The short name (`mm`).
    #[must_use]
    pub fn short(self) -> &'static str {
        match self {
            Units::Millimetres => "mm",
            Units::Centimetres => "cm",
            Units::Metres => "m",
            Units::Inches => "in",
            Units::Feet => "ft",
        }
    }
}

impl std::str::FromStr for Units {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.trim().to_ascii_lowercase().as_str() {
            "mm" | "millimetre" | "millimetres" | "millimeter" | "millimeters" => {
                Ok(Units::Millimetres)
            }
            "cm" | "centimetre" | "centimetres" | "centimeter" | "centimeters" => {
                Ok(Units::Centimetres)
            }
            "m" | "metre" | "metres" | "meter" | "meters" => Ok(Units::Metres),
            "in" | "inch" | "inches" => Ok(Units::Inches),
            "ft" | "foot" | "feet" => Ok(Units::Feet),
            other => Err(format!("unknown units '{other}': use mm, cm, m, in or ft")),
        }
    }
}

/// An axis of a file's own frame: which way its models face.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Axis(pub DVec3);

impl std::str::FromStr for Axis {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let v = match s.trim().to_ascii_lowercase().as_str() {
            "+x" | "x" => DVec3::X,
            "-x" => DVec3::NEG_X,
            "+y" | "y" => DVec3::Y,
            "-y" => DVec3::NEG_Y,
            "+z" | "z" => DVec3::Z,
            "-z" => DVec3::NEG_Z,
            other => {
                return Err(format!(
                    "unknown axis '{other}': use +x, -x, +y, -y, +z or -z"
                ))
            }
        };
        Ok(Axis(v))
    }
}

/// How to read a file whose conventions its metadata does not tell (or tells wrongly).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ReadOptions {
    /// The units the file is modelled in (glTF and USD): overrides USD's `metersPerUnit`
    /// and glTF's metres, and turns off the check for implausible scales.
    pub units: Option<Units>,
    /// The axis, in the file's own frame, that its models face (glTF and USD): overrides
    /// the format's convention (glTF and Y-up USD: +Z; Z-up USD: −Y), not a node's own
    /// `shenlong:front`.
    pub front: Option<Axis>,
}

/// One node of a file's hierarchy as its reader saw it.
#[derive(Clone, Debug, Default)]
pub(crate) struct Node {
    /// Its name in the file (may be empty).
    pub name: String,
    /// Its parent (an index before its own).
    pub parent: Option<usize>,
    /// Its local-to-world transform, into Shenlong's frame (Y-up metres).
    pub world: DMat4,
    /// Its own geometry, in Shenlong's world frame.
    pub points: Vec<DVec3>,
    /// Its mesh's triangles, as indices into `points` (none for geometry without faces).
    pub triangles: Vec<[u32; 3]>,
    /// Whether it can carry a transform (an `Xform`, a gprim, a glTF node).
    pub transformable: bool,
    /// Whether the file calls it a model of kind `component`.
    pub model: bool,
    /// The name Shenlong wrote for it, when the file is one Shenlong made.
    pub given_name: Option<String>,
    /// Words for it from the file.
    pub labels: Labels,
    /// The direction it faces, in its own axes, when the file says so.
    pub front: Option<DVec3>,
    /// The name to use when its name is empty or shared (`node 7`, a USD path).
    pub fallback: String,
}

/// The nodes of a file, each after its parent.
#[derive(Clone, Debug, Default)]
pub(crate) struct Tree {
    /// The nodes.
    pub nodes: Vec<Node>,
}

/// The scene a tree gives, and which node each object is.
pub(crate) struct Derived {
    /// The scene.
    pub scene: Scene,
    /// Per object, its node.
    pub nodes: Vec<usize>,
    /// Per object, the object it is nested under in the file, if any.
    #[cfg_attr(not(feature = "usd"), allow(dead_code))]
    pub ancestors: Vec<Option<usize>>,
}

/// The most children of a node compared pairwise to tell a group from an object made of
/// parts; a node with more geometric children is a group.
const MAX_PARTS: usize = 512;

/// How far apart two parts may be and still belong to one object, in metres.
const PART_GAP: f64 = 0.02;

/// Words in a node's name that make it a group of objects rather than an object.
const GROUP_WORDS: &[&str] = &[
    "world",
    "root",
    "rootnode",
    "scene",
    "group",
    "grp",
    "groups",
    "collection",
    "furniture",
    "furnishings",
    "props",
    "objects",
    "items",
    "decor",
    "decoration",
    "decorations",
    "set",
    "dressing",
    "environment",
    "env",
    "layout",
    "room",
    "geometry",
    "meshes",
    "models",
    "assets",
    "sketchfab",
    "gltf",
    "fbx",
    "interior",
    "level",
    "stage",
    "clutter",
    "misc",
    "architecture",
    "structure",
];

/// Words naming a floor, in the languages exports are commonly named in.
const FLOOR_WORDS: &[&str] = &[
    "floor",
    "floors",
    "ground",
    "groundplane",
    "flooring",
    "boden",
    "fussboden",
    "sol",
    "plancher",
    "suelo",
    "piso",
    "pavimento",
    "chao",
    "vloer",
    "golv",
    "gulv",
    "lattia",
    "podloga",
    "pol",
    "pavement",
];

/// Words naming a wall.
const WALL_WORDS: &[&str] = &[
    "wall", "walls", "wand", "waende", "mur", "murs", "pared", "paredes", "parete", "pareti",
    "parede", "muur", "vagg", "vaegg", "seina", "sciana", "stena",
];

/// Words naming a ceiling.
const CEILING_WORDS: &[&str] = &[
    "ceiling", "ceilings", "roof", "decke", "plafond", "techo", "soffitto", "teto", "tak", "katto",
    "sufit", "potolok",
];

/// Words naming a whole room's shell as one mesh (floor, walls and ceiling together).
const SHELL_WORDS: &[&str] = &[
    "room",
    "shell",
    "interior",
    "architecture",
    "building",
    "apartment",
    "house",
    "walls",
];

/// The most objects named like a room's shell that are tried as one (each costs a pass
/// over the objects).
const MAX_SHELLS: usize = 16;

/// Words that say nothing of what a node is (`Plane`, `Cube.004`, `mesh_3`): a node so
/// named may be recognised as a floor or wall by its shape alone.
const GENERIC_WORDS: &[&str] = &[
    "plane",
    "grid",
    "mesh",
    "object",
    "obj",
    "geo",
    "geom",
    "node",
    "polysurface",
    "poly",
    "shape",
    "solid",
    "body",
    "surface",
    "slab",
    "cube",
    "box",
    "part",
    "primitive",
    "brep",
];

/// The lower-case words of a name: split at case changes, digits and punctuation.
fn words(name: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut current = String::new();
    let mut prev_lower = false;
    for c in name.chars() {
        if c.is_alphabetic() {
            if c.is_uppercase() && prev_lower && !current.is_empty() {
                out.push(std::mem::take(&mut current));
            }
            prev_lower = c.is_lowercase();
            current.extend(c.to_lowercase());
        } else {
            prev_lower = false;
            if !current.is_empty() {
                out.push(std::mem::take(&mut current));
            }
        }
    }
    if !current.is_empty() {
        out.push(current);
    }
    // Letters with accents folded the simple way (`Fußboden`, `chão`).
    out.into_iter()
        .map(|w| {
            w.replace('ß', "ss")
                .replace(['ä', 'å', 'á', 'à', 'ã', 'â'], "a")
                .replace(['ö', 'ó', 'ò', 'ø', 'ô'], "o")
                .replace(['ü', 'ú'], "u")
                .replace(['é', 'è', 'ê'], "e")
                .replace('ł', "l")
                .replace('ś', "s")
        })
        .collect()
}

fn has_word(name: &str, list: &[&str]) -> bool {
    words(name).iter().any(|w| list.contains(&w.as_str()))
}

/// Words for things that hang on, stand on or cover a floor, wall or ceiling: a name with
/// one of them (`WallClock`, `Wall_Shelf`, `FloorRug`, `Ceiling_Lamp`) names the thing,
/// not the room.
const FIXTURE_WORDS: &[&str] = &[
    "clock",
    "lamp",
    "light",
    "lights",
    "sconce",
    "shelf",
    "shelves",
    "cabinet",
    "cupboard",
    "unit",
    "rug",
    "mat",
    "carpet",
    "art",
    "picture",
    "painting",
    "poster",
    "frame",
    "mirror",
    "hook",
    "hooks",
    "rack",
    "fan",
    "vent",
    "heater",
    "radiator",
    "socket",
    "outlet",
    "switch",
    "plant",
    "vase",
    "decal",
    "sticker",
    "tv",
    "screen",
    "desk",
    "table",
    "stand",
    "speaker",
    "cushion",
    "pillow",
    "blanket",
    "box",
    "bin",
    "basket",
    "chair",
    "sofa",
    "bed",
    "magic",
    "fixture",
    "pendant",
    "chandelier",
    "bulb",
    "sign",
    "board",
];

/// Whether a name names a part of the room of this kind (`Floor`, `Wall_North`,
/// `Boden_01`): one of its words is in `list` and none names a thing on it.
fn room_word(name: &str, list: &[&str]) -> bool {
    let words = words(name);
    words.iter().any(|w| list.contains(&w.as_str()))
        && !words.iter().any(|w| FIXTURE_WORDS.contains(&w.as_str()))
}

/// Whether a name says nothing of what the thing is (an empty name says nothing).
fn generic(name: &str) -> bool {
    words(name)
        .iter()
        .all(|w| GENERIC_WORDS.contains(&w.as_str()))
}

/// Derives the scene from a tree (see the module's documentation).
///
/// `default_front` is the format's front axis in the nodes' own frames.
pub(crate) fn derive(
    tree: &Tree,
    scene_name: &str,
    default_front: DVec3,
    options: &ReadOptions,
) -> Result<Derived, FormatError> {
    let chosen = choose(tree);
    let mut scene = Scene::new(scene_name);
    let mut nodes = Vec::new();
    let mut owners = Vec::new();
    let front_axis = options.front.map_or(default_front, |a| a.0);
    for object in chosen {
        if object.points.is_empty() {
            continue;
        }
        let node = &tree.nodes[object.node];
        let front = front_of(node, front_axis, options.front.is_none());
        let measured = crate::scene::mesh::measure(&object.points, &object.triangles);
        let mut o = Object::new(
            String::new(),
            Shape::Points {
                points: object.points,
            },
            cga::Similarity::IDENTITY,
            Pivot::BottomCenter,
        )
        .map_err(|e| FormatError::invalid(format!("{}: {e}", node.fallback)))?;
        o.labels = node.labels.clone();
        o.front = front;
        o.measured = measured;
        scene.objects.push(o);
        nodes.push(object.node);
        owners.push(object.owner);
    }
    let room = Room::find(tree, &scene, &nodes);
    // The room's parts (sorted) are not objects.
    let mut kept_scene = Scene::new(scene_name);
    let mut kept_nodes = Vec::new();
    let mut kept_owners = Vec::new();
    let objects = scene.objects.into_iter().zip(nodes).zip(owners);
    for (i, ((o, node), owner)) in objects.enumerate() {
        if room.parts.binary_search(&i).is_err() {
            kept_scene.objects.push(o);
            kept_nodes.push(node);
            kept_owners.push(owner);
        }
    }
    finish(
        tree,
        kept_scene,
        kept_nodes,
        kept_owners,
        room.bounds,
        options,
    )
}

/// The world direction a node faces: its own front, else the format's (or the run's) axis
/// through its world rotation. Furniture faces sideways: where the format's axis comes
/// out vertical and neither the node nor the run says otherwise, the models were authored
/// Z-up under a node that turns them Y-up (a Sketchfab or FBX wrapper), and face their
/// −Y, as Blender's do.
fn front_of(node: &Node, axis: DVec3, guess: bool) -> DVec3 {
    let world = |local: DVec3| node.world.transform_vector3(local).try_normalize();
    if let Some(own) = node.front {
        return world(own).unwrap_or(DVec3::Z);
    }
    let front = world(axis).unwrap_or(DVec3::Z);
    if guess && front.y.abs() > 0.9 {
        if let Some(z_up) = world(DVec3::NEG_Y).filter(|f| f.y.abs() < 0.5) {
            return z_up;
        }
    }
    front
}

/// Names, units, nesting and supports.
fn finish(
    tree: &Tree,
    mut scene: Scene,
    nodes: Vec<usize>,
    owners: Vec<Option<usize>>,
    bounds: Option<Aabb>,
    options: &ReadOptions,
) -> Result<Derived, FormatError> {
    if options.units.is_none() {
        check_units(&scene)?;
    }
    let names = names(tree, &nodes);
    for (o, (name, alias)) in scene.objects.iter_mut().zip(names) {
        o.name = name;
        o.labels.aliases.extend(alias);
    }
    scene.bounds = bounds;
    // The object each object is nested under: the nearest owner that is still an object.
    let index_of: rustc_hash::FxHashMap<usize, usize> =
        nodes.iter().enumerate().map(|(i, &n)| (n, i)).collect();
    let ancestors: Vec<Option<usize>> = owners
        .iter()
        .map(|owner| owner.and_then(|n| index_of.get(&n).copied()))
        .collect();
    for (i, a) in ancestors.iter().enumerate() {
        if let Some(a) = *a {
            scene.objects[i].support = Some(a);
            scene.objects[i].support_from_file = true;
        }
    }
    scene.detect_supports();
    Ok(Derived {
        scene,
        nodes,
        ancestors,
    })
}

/// An object found in the tree: its root node, its geometry and the object node it is
/// nested under.
struct Chosen {
    node: usize,
    points: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
    owner: Option<usize>,
}

/// The objects of a tree, as a person sees them (the module's rule 1).
fn choose(tree: &Tree) -> Vec<Chosen> {
    let n = tree.nodes.len();
    let mut children: Vec<Vec<usize>> = vec![Vec::new(); n];
    let mut roots = Vec::new();
    for (i, node) in tree.nodes.iter().enumerate() {
        match node.parent {
            Some(p) if p < i => children[p].push(i),
            _ => roots.push(i),
        }
    }
    // Each subtree's box (none where it holds no geometry), children before parents.
    let mut boxes: Vec<Option<Aabb>> = tree
        .nodes
        .iter()
        .map(|node| Aabb::from_points(node.points.iter().copied()))
        .collect();
    for i in (0..n).rev() {
        if let (Some(p), Some(b)) = (tree.nodes[i].parent, boxes[i]) {
            if p < i {
                boxes[p] = Some(boxes[p].map_or(b, |a| a.union(&b)));
            }
        }
    }
    let uses_models = tree.nodes.iter().any(|node| node.model);
    // Each node's object: the object node it belongs to, found parents first.
    let mut owner: Vec<Option<usize>> = vec![None; n];
    let mut starts = vec![false; n];
    // Whether an object's root has geometry of its own (then nodes with geometry below it
    // are objects resting on it); else what is below it is its parts.
    let mut stack: Vec<usize> = roots.into_iter().rev().collect();
    while let Some(i) = stack.pop() {
        let node = &tree.nodes[i];
        let inherited = node
            .parent
            .and_then(|p| if starts[p] { Some(p) } else { owner[p] });
        let start = if uses_models {
            // The file's components; and, outside them, floors, walls and ceilings that
            // hold geometry (the room, taken out of the objects later).
            node.model
                || (inherited.is_none()
                    && boxes[i].is_some()
                    && !ancestors_model(tree, i)
                    && (room_word(&node.name, FLOOR_WORDS)
                        || room_word(&node.name, WALL_WORDS)
                        || room_word(&node.name, CEILING_WORDS)))
        } else if boxes[i].is_none() || !node.transformable {
            false
        } else {
            match inherited {
                None => !node.points.is_empty() || !is_group(tree, &children, &boxes, i),
                // Below an object with geometry of its own: nested objects.
                Some(o) => !tree.nodes[o].points.is_empty() && !node.points.is_empty(),
            }
        };
        starts[i] = start;
        owner[i] = inherited;
        for &c in children[i].iter().rev() {
            stack.push(c);
        }
    }
    let mut index: Vec<Option<usize>> = vec![None; n];
    let mut out: Vec<Chosen> = Vec::new();
    for i in 0..n {
        if starts[i] {
            index[i] = Some(out.len());
            out.push(Chosen {
                node: i,
                points: tree.nodes[i].points.clone(),
                triangles: tree.nodes[i].triangles.clone(),
                owner: owner[i],
            });
        } else if let Some(o) = owner[i].and_then(|o| index[o]) {
            let object = &mut out[o];
            let base = u32::try_from(object.points.len()).unwrap_or(u32::MAX);
            object.triangles.extend(
                tree.nodes[i]
                    .triangles
                    .iter()
                    .map(|t| t.map(|k| k.saturating_add(base))),
            );
            object.points.extend_from_slice(&tree.nodes[i].points);
        }
    }
    out
}

/// Whether a node lies inside a model (a USD component): its parts are the model's.
fn ancestors_model(tree: &Tree, i: usize) -> bool {
    let mut p = tree.nodes[i].parent;
    while let Some(k) = p {
        if tree.nodes[k].model {
            return true;
        }
        p = tree.nodes[k].parent;
    }
    false
}

/// Whether a node without geometry of its own is merely a group of objects: its name says
/// so, or its geometric children fall apart into separate clusters.
fn is_group(tree: &Tree, children: &[Vec<usize>], boxes: &[Option<Aabb>], i: usize) -> bool {
    let node = &tree.nodes[i];
    let geometric: Vec<usize> = children[i]
        .iter()
        .copied()
        .filter(|&c| boxes[c].is_some())
        .collect();
    if has_word(&node.name, GROUP_WORDS) {
        // `Furniture` over one `Chair` is a group; `toy set` over its one `box` mesh is
        // the object.
        return geometric.len() > 1
            || geometric
                .iter()
                .any(|&c| !generic(&tree.nodes[c].name) && !tree.nodes[c].name.is_empty());
    }
    let parts: Vec<Aabb> = geometric.iter().filter_map(|&c| boxes[c]).collect();
    if parts.len() < 2 {
        return false;
    }
    if parts.len() > MAX_PARTS {
        return true;
    }
    // A floor or a wall among the children: the node is a room of objects (everything
    // stands on the floor, so the boxes alone would make one cluster).
    let union = parts.iter().skip(1).fold(parts[0], |a, b| a.union(b));
    let room_like = |c: usize| {
        let name = &tree.nodes[c].name;
        let Some(b) = boxes[c] else { return false };
        let s = b.size();
        room_word(name, FLOOR_WORDS)
            || room_word(name, WALL_WORDS)
            || room_word(name, CEILING_WORDS)
            || (generic(name)
                && s.y <= 0.1
                && s.x * s.z >= 2.0
                && b.max.y <= union.min.y + 0.02 + s.y)
    };
    if geometric.iter().any(|&c| room_like(c)) {
        return true;
    }
    clusters(&parts) > 1
}

/// How many clusters boxes form, two boxes joined when they touch or overlap (within
/// [`PART_GAP`]).
fn clusters(parts: &[Aabb]) -> usize {
    let mut parent: Vec<usize> = (0..parts.len()).collect();
    fn root(parent: &mut [usize], mut k: usize) -> usize {
        while parent[k] != k {
            parent[k] = parent[parent[k]];
            k = parent[k];
        }
        k
    }
    for a in 0..parts.len() {
        for b in a + 1..parts.len() {
            let (p, q) = (&parts[a], &parts[b]);
            let near = p.overlap(q).cmpge(DVec3::splat(-PART_GAP)).all();
            if near {
                let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
                parent[ra] = rb;
            }
        }
    }
    (0..parts.len())
        .filter(|&k| root(&mut parent, k) == k)
        .count()
}

/// Each object's name: its node's (or the name Shenlong gave it); objects that share a
/// name (compared case-insensitively) are told apart by their group's name — `Chair in
/// GroupA`, also called `GroupA Chair` (the alias returned beside it) — else by their
/// node's fallback name (its path).
fn names(tree: &Tree, nodes: &[usize]) -> Vec<(String, Vec<String>)> {
    let base: Vec<String> = nodes
        .iter()
        .map(|&n| {
            let node = &tree.nodes[n];
            match &node.given_name {
                Some(g) => g.clone(),
                None if node.name.trim().is_empty() => node.fallback.clone(),
                None => node.name.trim().to_string(),
            }
        })
        .collect();
    let mut count: rustc_hash::FxHashMap<String, usize> = rustc_hash::FxHashMap::default();
    for b in &base {
        *count.entry(b.to_lowercase()).or_default() += 1;
    }
    let group_of = |n: usize| -> Option<String> {
        let mut p = tree.nodes[n].parent;
        while let Some(k) = p {
            let name = tree.nodes[k].name.trim();
            if !name.is_empty() {
                return Some(name.to_string());
            }
            p = tree.nodes[k].parent;
        }
        None
    };
    let mut named: Vec<(String, Vec<String>)> = base
        .iter()
        .zip(nodes)
        .map(|(b, &n)| {
            if count[&b.to_lowercase()] > 1 {
                match group_of(n) {
                    Some(g) => (format!("{b} in {g}"), vec![format!("{g} {b}")]),
                    None => (tree.nodes[n].fallback.clone(), Vec::new()),
                }
            } else {
                (b.clone(), Vec::new())
            }
        })
        .collect();
    // Still shared (the same group's name): the fallback, which is unique.
    let mut again: rustc_hash::FxHashMap<String, usize> = rustc_hash::FxHashMap::default();
    for (b, _) in &named {
        *again.entry(b.to_lowercase()).or_default() += 1;
    }
    for (k, &n) in nodes.iter().enumerate() {
        if again[&named[k].0.to_lowercase()] > 1 {
            named[k] = (tree.nodes[n].fallback.clone(), Vec::new());
        }
    }
    named
}

/// The parts of a file that are the room, and the bounds they give.
struct Room {
    /// The objects (indices, sorted) that are floor, walls or ceiling.
    parts: Vec<usize>,
    /// The room's bounds: floor at `min.y`, walls at the x and z limits.
    bounds: Option<Aabb>,
}

/// The objects (indices) that are the room, by kind.
#[derive(Default)]
struct RoomParts {
    floors: Vec<usize>,
    walls: Vec<usize>,
    ceilings: Vec<usize>,
    /// Rooms modelled as one mesh.
    shells: Vec<usize>,
}

impl RoomParts {
    /// Floors, walls and ceilings among the objects, by name or by shape; then rooms
    /// modelled as one mesh (`Room`, `Interior_Shell`: a box that holds the others).
    fn classify(tree: &Tree, nodes: &[usize], boxes: &[Aabb]) -> Self {
        let all = boxes.iter().skip(1).fold(boxes[0], |a, b| a.union(b));
        let all_size = all.size();
        let mut parts = RoomParts::default();
        for (i, b) in boxes.iter().enumerate() {
            let name = &tree.nodes[nodes[i]].name;
            let s = b.size();
            let thin_flat = s.y <= 0.1_f64.max(0.05 * s.x.min(s.z));
            let wide = s.x * s.z >= 0.6 * (all_size.x * all_size.z).max(1e-9);
            let tall_thin = {
                let (thin, long) = (s.x.min(s.z), s.x.max(s.z));
                thin <= 0.35 && long >= 2.0 && s.y >= 2.0 && s.y >= 4.0 * thin
            };
            let at_boundary = (b.min.x - all.min.x).abs() < 0.5
                || (all.max.x - b.max.x).abs() < 0.5
                || (b.min.z - all.min.z).abs() < 0.5
                || (all.max.z - b.max.z).abs() < 0.5;
            if room_word(name, FLOOR_WORDS) && thin_flat {
                parts.floors.push(i);
            } else if room_word(name, CEILING_WORDS) && thin_flat {
                parts.ceilings.push(i);
            } else if room_word(name, WALL_WORDS)
                && s.x.min(s.z) <= 0.6
                && s.x.max(s.z) >= 1.0
                && s.y >= 1.5
            {
                parts.walls.push(i);
            } else if generic(name) && thin_flat && wide {
                // A large thin slab: the floor if nothing is below it, else the ceiling.
                if b.max.y <= all.min.y + 0.1 {
                    parts.floors.push(i);
                } else if b.min.y >= all.max.y - 0.1 {
                    parts.ceilings.push(i);
                }
            } else if generic(name) && tall_thin && at_boundary {
                parts.walls.push(i);
            }
        }
        let classified = parts.all();
        let candidates: Vec<usize> = (0..boxes.len())
            .filter(|i| classified.binary_search(i).is_err())
            .filter(|&i| has_word(&tree.nodes[nodes[i]].name, SHELL_WORDS))
            .take(MAX_SHELLS)
            .collect();
        for i in candidates {
            let b = &boxes[i];
            let others = boxes.len() - 1;
            let inside = (0..boxes.len())
                .filter(|&j| j != i)
                .filter(|&j| {
                    let c = boxes[j].center();
                    b.min.cmple(c).all() && c.cmple(b.max).all()
                })
                .count();
            if others >= 2 && inside * 5 >= others * 4 {
                parts.shells.push(i);
            }
        }
        parts
    }

    /// Every part, sorted, each once.
    fn all(&self) -> Vec<usize> {
        let mut all: Vec<usize> = self
            .floors
            .iter()
            .chain(&self.walls)
            .chain(&self.ceilings)
            .chain(&self.shells)
            .copied()
            .collect();
        all.sort_unstable();
        all.dedup();
        all
    }

    /// The room these parts make around the furniture (whose boxes span `inside`): the
    /// floor's top, the walls' inner faces (else the floor's and the furniture's extent),
    /// the ceiling's underside (else the walls' tops, at least 2.5 m up).
    fn bounds(&self, boxes: &[Aabb], inside: Aabb) -> Aabb {
        let mut min = inside.min;
        let mut max = inside.max;
        for &f in &self.floors {
            min = min.min(boxes[f].min);
            max = max.max(boxes[f].max);
        }
        let centre = inside.center();
        let (mut lo_x, mut hi_x, mut lo_z, mut hi_z) = (None, None, None, None);
        for &w in &self.walls {
            let b = &boxes[w];
            let s = b.size();
            if s.x <= s.z {
                if b.center().x >= centre.x {
                    hi_x = Some(hi_x.map_or(b.min.x, |v: f64| v.min(b.min.x)));
                } else {
                    lo_x = Some(lo_x.map_or(b.max.x, |v: f64| v.max(b.max.x)));
                }
            } else if b.center().z >= centre.z {
                hi_z = Some(hi_z.map_or(b.min.z, |v: f64| v.min(b.min.z)));
            } else {
                lo_z = Some(lo_z.map_or(b.max.z, |v: f64| v.max(b.max.z)));
            }
            max.y = max.y.max(b.max.y);
        }
        if let Some(v) = lo_x.filter(|&v| v <= inside.min.x + 1e-6) {
            min.x = v;
        }
        if let Some(v) = hi_x.filter(|&v| v >= inside.max.x - 1e-6) {
            max.x = v;
        }
        if let Some(v) = lo_z.filter(|&v| v <= inside.min.z + 1e-6) {
            min.z = v;
        }
        if let Some(v) = hi_z.filter(|&v| v >= inside.max.z - 1e-6) {
            max.z = v;
        }
        if let Some(lowest) = self
            .ceilings
            .iter()
            .map(|&c| boxes[c].min.y)
            .min_by(f64::total_cmp)
        {
            max.y = lowest.max(inside.max.y);
        }
        for &r in &self.shells {
            let b = &boxes[r];
            min.x = b.min.x.min(inside.min.x);
            min.z = b.min.z.min(inside.min.z);
            max.x = b.max.x.max(inside.max.x);
            max.z = b.max.z.max(inside.max.z);
            max.y = b.max.y.max(inside.max.y);
        }
        min.y = self.floor_level(boxes, inside);
        if max.y - min.y < 2.0 && self.ceilings.is_empty() {
            max.y = min.y + 2.5_f64.max(inside.max.y - min.y);
        }
        Aabb::new(min, max)
    }

    /// The floor's level: the floors' top; a shell's slab top (where the furniture stands,
    /// when that is just above its box's bottom); else the furniture's bottom.
    fn floor_level(&self, boxes: &[Aabb], inside: Aabb) -> f64 {
        let top = self
            .floors
            .iter()
            .map(|&i| boxes[i].max.y)
            .fold(f64::NEG_INFINITY, f64::max);
        if top.is_finite() {
            return top.min(inside.min.y);
        }
        let shell = self
            .shells
            .iter()
            .map(|&r| {
                let bottom = boxes[r].min.y;
                if inside.min.y >= bottom && inside.min.y - bottom <= 0.3 {
                    inside.min.y
                } else {
                    bottom
                }
            })
            .fold(f64::NEG_INFINITY, f64::max);
        if shell.is_finite() {
            shell
        } else {
            inside.min.y.min(0.0)
        }
    }
}

impl Room {
    /// The room among the objects ([`RoomParts::classify`]) and its bounds; none when
    /// nothing is a room part, or everything is.
    fn find(tree: &Tree, scene: &Scene, nodes: &[usize]) -> Room {
        let none = Room {
            parts: Vec::new(),
            bounds: None,
        };
        let boxes = scene.world_aabbs();
        if boxes.len() < 2 {
            return none;
        }
        let kinds = RoomParts::classify(tree, nodes, &boxes);
        let parts = kinds.all();
        if parts.is_empty() || parts.len() == boxes.len() {
            return none;
        }
        let furniture: Vec<Aabb> = (0..boxes.len())
            .filter(|i| parts.binary_search(i).is_err())
            .map(|i| boxes[i])
            .collect();
        let inside = furniture
            .iter()
            .skip(1)
            .fold(furniture[0], |a, b| a.union(b));
        Room {
            bounds: Some(kinds.bounds(&boxes, inside)),
            parts,
        }
    }
}

/// The slabs that stand for a room's bounds in a file that has no field for them (a new
/// glTF or USD file written from scene JSON): a floor under `min.y`, a ceiling over
/// `max.y`, and four walls outside the x and z limits, each 10 cm thick, named so that
/// reading the file again ([`Room::find`]) gives the same bounds.
#[must_use]
pub(crate) fn room_slabs(bounds: &Aabb) -> Vec<(&'static str, Aabb)> {
    const T: f64 = 0.1;
    let (lo, hi) = (bounds.min, bounds.max);
    let out_lo = lo - DVec3::splat(T);
    let out_hi = hi + DVec3::splat(T);
    vec![
        (
            "Room_Floor",
            Aabb::new(
                DVec3::new(out_lo.x, lo.y - T, out_lo.z),
                DVec3::new(out_hi.x, lo.y, out_hi.z),
            ),
        ),
        (
            "Room_Ceiling",
            Aabb::new(
                DVec3::new(out_lo.x, hi.y, out_lo.z),
                DVec3::new(out_hi.x, hi.y + T, out_hi.z),
            ),
        ),
        (
            "Room_Wall_West",
            Aabb::new(
                DVec3::new(out_lo.x, lo.y, out_lo.z),
                DVec3::new(lo.x, hi.y, out_hi.z),
            ),
        ),
        (
            "Room_Wall_East",
            Aabb::new(
                DVec3::new(hi.x, lo.y, out_lo.z),
                DVec3::new(out_hi.x, hi.y, out_hi.z),
            ),
        ),
        (
            "Room_Wall_Back",
            Aabb::new(
                DVec3::new(lo.x, lo.y, out_lo.z),
                DVec3::new(hi.x, hi.y, lo.z),
            ),
        ),
        (
            "Room_Wall_Front",
            Aabb::new(
                DVec3::new(lo.x, lo.y, hi.z),
                DVec3::new(hi.x, hi.y, out_hi.z),
            ),
        ),
    ]
}

/// Refuses a scene whose furniture is implausibly large for metres: the median of the
/// objects' largest extents over 20 m (a room's furniture is 0.1 m to 3 m), naming the
/// units it looks modelled in.
fn check_units(scene: &Scene) -> Result<(), FormatError> {
    let mut extents: Vec<f64> = scene
        .objects
        .iter()
        .map(|o| o.world_aabb().size().max_element())
        .collect();
    if extents.is_empty() {
        return Ok(());
    }
    extents.sort_by(f64::total_cmp);
    let median = extents[extents.len() / 2];
    if median <= 20.0 {
        return Ok(());
    }
    // The units that bring the median nearest a typical piece of furniture (0.8 m), on a
    // log scale: 330 units are 0.33 m in millimetres rather than 3.3 m in centimetres.
    let off = |u: &Units| (median * u.meters() / 0.8).ln().abs();
    let guess = [Units::Centimetres, Units::Inches, Units::Millimetres]
        .into_iter()
        .min_by(|a, b| off(a).total_cmp(&off(b)))
        .unwrap_or(Units::Millimetres);
    Err(FormatError::Units { median, guess })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn slab(min: [f64; 3], max: [f64; 3]) -> Vec<DVec3> {
        Aabb::new(DVec3::from(min), DVec3::from(max))
            .corners()
            .to_vec()
    }

    fn node(name: &str, parent: Option<usize>, points: Vec<DVec3>) -> Node {
        Node {
            name: name.into(),
            parent,
            world: DMat4::IDENTITY,
            points,
            triangles: Vec::new(),
            transformable: true,
            fallback: format!("/{name}"),
            ..Node::default()
        }
    }

    #[test]
    fn groups_parts_floors_and_duplicates() {
        let tree = Tree {
            nodes: vec![
                node("World", None, vec![]),
                node("Furniture", Some(0), vec![]),
                // A chair of two touching parts.
                node("Chair", Some(1), vec![]),
                node("Seat", Some(2), slab([0.0, 0.4, 0.0], [0.5, 0.45, 0.5])),
                node("Legs", Some(2), slab([0.0, 0.0, 0.0], [0.5, 0.4, 0.5])),
                node("Props", Some(0), vec![]),
                node("Mug", Some(5), slab([2.0, 0.0, 2.0], [2.1, 0.1, 2.1])),
                node("Floor", Some(0), slab([-3.0, -0.02, -3.0], [3.0, 0.0, 3.0])),
                node("GroupA", Some(0), vec![]),
                node("Stool", Some(8), slab([1.0, 0.0, -2.0], [1.2, 0.2, -1.8])),
                node("GroupB", Some(0), vec![]),
                node(
                    "Stool",
                    Some(10),
                    slab([-1.0, 0.0, -2.0], [-0.8, 0.2, -1.8]),
                ),
            ],
        };
        let d = derive(&tree, "t", DVec3::Z, &ReadOptions::default()).unwrap();
        let names: Vec<&str> = d.scene.objects.iter().map(|o| o.name.as_str()).collect();
        assert_eq!(
            names,
            ["Chair", "Mug", "Stool in GroupA", "Stool in GroupB"]
        );
        assert_eq!(d.scene.objects[3].labels.aliases, ["GroupB Stool"]);
        let bounds = d.scene.bounds.unwrap();
        assert_eq!(bounds.min.y, 0.0);
        assert_eq!(bounds.min.x, -3.0);
    }

    #[test]
    fn a_room_mesh_is_the_room() {
        let tree = Tree {
            nodes: vec![
                node("Room", None, slab([-2.0, -0.1, -2.0], [2.0, 2.6, 2.0])),
                node("Bed", None, slab([0.0, 0.0, 0.0], [1.4, 0.5, 2.0])),
                node("Lamp", None, slab([-1.0, 0.0, -1.0], [-0.8, 1.5, -0.8])),
            ],
        };
        let d = derive(&tree, "t", DVec3::Z, &ReadOptions::default()).unwrap();
        assert_eq!(d.scene.objects.len(), 2);
        let b = d.scene.bounds.unwrap();
        assert_eq!((b.min.y, b.max.x), (0.0, 2.0));
    }

    #[test]
    fn things_on_walls_and_floors_are_not_the_room() {
        let tree = Tree {
            nodes: vec![
                node("Floor", None, slab([-3.0, -0.02, -3.0], [3.0, 0.0, 3.0])),
                node(
                    "Wall_North",
                    None,
                    slab([-3.0, 0.0, -3.1], [3.0, 2.6, -3.0]),
                ),
                node("WallClock", None, slab([0.0, 1.8, -3.0], [0.3, 2.1, -2.95])),
                node("Wall_Shelf", None, slab([1.0, 1.2, -3.0], [1.8, 1.5, -2.7])),
                node("FloorRug", None, slab([-1.0, 0.0, -1.0], [1.0, 0.01, 1.0])),
            ],
        };
        let d = derive(&tree, "t", DVec3::Z, &ReadOptions::default()).unwrap();
        let names: Vec<&str> = d.scene.objects.iter().map(|o| o.name.as_str()).collect();
        assert_eq!(names, ["WallClock", "Wall_Shelf", "FloorRug"]);
        assert_eq!(d.scene.bounds.unwrap().min.z, -3.0);
    }

    #[test]
    fn separate_children_make_a_group() {
        let tree = Tree {
            nodes: vec![
                node("Stuff", None, vec![]),
                node("Lamp", Some(0), slab([0.0, 0.0, 0.0], [0.2, 1.0, 0.2])),
                node("Stool", Some(0), slab([2.0, 0.0, 0.0], [2.4, 0.5, 0.4])),
            ],
        };
        let d = derive(&tree, "t", DVec3::Z, &ReadOptions::default()).unwrap();
        assert_eq!(d.scene.objects.len(), 2);
    }

    #[test]
    fn millimetres_are_refused_unless_told() {
        let tree = Tree {
            nodes: vec![
                node("Desk", None, slab([0.0, 0.0, 0.0], [1200.0, 750.0, 600.0])),
                node(
                    "Monitor",
                    None,
                    slab([0.0, 750.0, 0.0], [500.0, 1100.0, 200.0]),
                ),
            ],
        };
        let e = derive(&tree, "t", DVec3::Z, &ReadOptions::default())
            .err()
            .unwrap();
        assert!(
            matches!(
                e,
                FormatError::Units {
                    guess: Units::Millimetres,
                    ..
                }
            ),
            "{e:?}"
        );
        assert!(e.to_string().contains("--units mm"), "{e}");
        let told = ReadOptions {
            units: Some(Units::Metres),
            ..ReadOptions::default()
        };
        assert!(derive(&tree, "t", DVec3::Z, &told).is_ok());
    }

    #[test]
    fn fronts_follow_the_node_rotation() {
        let mut n = node("Armchair", None, slab([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]));
        n.world = DMat4::from_rotation_y(std::f64::consts::FRAC_PI_2);
        let tree = Tree { nodes: vec![n] };
        let d = derive(&tree, "t", DVec3::Z, &ReadOptions::default()).unwrap();
        assert!((d.scene.objects[0].front - DVec3::X).length() < 1e-12);
    }
}

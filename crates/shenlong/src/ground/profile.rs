//! What a person calls an object whose name says nothing of what it is (`pCube1`,
//! `polySurface7`, `group4_mesh`, `Object_12`): read from its box and from what rests on
//! it. A table is something with things on it at table height, a bench a low and long box,
//! a stack a box with another of about its size on top.
//!
//! Only such anonymous objects answer to these words, and only where no object's name,
//! category or synonym does: in a scene with a `Dining Table`, "the table" is that table.

use super::ident::Identifier;
use crate::geometry::Aabb;
use crate::scene::Scene;

/// A kind of object a person recognises by its box.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Profile {
    /// A table, desk or counter: something rests on it, its top at table height.
    Surface,
    /// A bench: low, and long for its depth.
    Bench,
    /// A stack or pile: another object of about its footprint rests on it.
    Stack,
    /// A seat, chair or stool: a small box drawn up to a table ([`Profile::Surface`]).
    Seat,
    /// A door: a tall, thin panel of a door's width standing at a wall of the room.
    Door,
}

/// A table's top is at least this high above the floor, in metres (and a support whose top
/// is, is a surface things are put on, not a rug or a mat)…
pub(crate) const SURFACE_MIN_TOP: f64 = 0.3;
/// …and at most this high.
const SURFACE_MAX_TOP: f64 = 1.3;
/// A table longer than 1.5 times its depth is at least this deep, in metres.
const SURFACE_MIN_DEPTH: f64 = 0.5;
/// A bench is at most this high, in metres…
const BENCH_MAX_HEIGHT: f64 = 0.6;
/// …at least this long…
const BENCH_MIN_LENGTH: f64 = 1.0;
/// …and at least this many times longer than deep.
const BENCH_MIN_RATIO: f64 = 2.5;
/// A seat is at least this high, in metres…
const SEAT_MIN_HEIGHT: f64 = 0.3;
/// …at most this high…
const SEAT_MAX_HEIGHT: f64 = 1.1;
/// …and at most this wide.
const SEAT_MAX_WIDTH: f64 = 0.7;
/// A door is at least this high, in metres…
const DOOR_MIN_HEIGHT: f64 = 1.7;
/// …at most this thick…
const DOOR_MAX_THICKNESS: f64 = 0.15;
/// …at least this wide…
const DOOR_MIN_WIDTH: f64 = 0.6;
/// …at most this wide…
const DOOR_MAX_WIDTH: f64 = 1.3;
/// …and within this of a wall.
const DOOR_WALL_GAP: f64 = 0.2;
/// What rests on a stack's base covers at least this share of the base's top.
const STACK_MIN_COVER: f64 = 0.5;

/// The profile a noun names, whether it is plural, and its singular: `table`, `desks`,
/// `bench`, `stack`.
#[must_use]
pub(crate) fn noun(w: &str) -> Option<(Profile, bool, &'static str)> {
    const NOUNS: &[(&str, Profile)] = &[
        ("table", Profile::Surface),
        ("desk", Profile::Surface),
        ("counter", Profile::Surface),
        ("worktop", Profile::Surface),
        ("workbench", Profile::Surface),
        ("bench", Profile::Bench),
        ("stack", Profile::Stack),
        ("pile", Profile::Stack),
        ("door", Profile::Door),
        ("seat", Profile::Seat),
        ("chair", Profile::Seat),
        ("stool", Profile::Seat),
    ];
    NOUNS.iter().find_map(|&(one, profile)| {
        if w == one {
            Some((profile, false, one))
        } else {
            let rest = w.strip_prefix(one)?;
            matches!(rest, "s" | "es").then_some((profile, true, one))
        }
    })
}

/// The words of exported names that say what a node is to the tool, not what the object
/// is to a person: a modelling tool's primitives and its words for nodes.
const EMPTY_WORDS: &[&str] = &[
    "cube",
    "box",
    "sphere",
    "icosphere",
    "uvsphere",
    "cylinder",
    "cone",
    "torus",
    "plane",
    "circle",
    "mesh",
    "group",
    "grp",
    "object",
    "obj",
    "geo",
    "geometry",
    "node",
    "poly",
    "surface",
    "polysurface",
    "shape",
    "null",
    "instance",
    "model",
    "part",
    "pasted",
    "transform",
    "body",
    "solid",
];

/// Whether a name read as `id` says nothing of what its object is: every word of it is a
/// primitive, a word for a node, a single letter or a number.
#[must_use]
pub(crate) fn is_anonymous(id: &Identifier) -> bool {
    std::iter::once(&id.base)
        .chain(id.other.as_ref())
        .flat_map(|kind| kind.split(' '))
        .all(|w| w.len() <= 1 || w.chars().all(|c| c.is_ascii_digit()) || EMPTY_WORDS.contains(&w))
}

/// Whether `object`'s box, and what rests on it (`load`: the objects resting on it),
/// fits `profile`.
#[must_use]
pub(crate) fn fits(scene: &Scene, object: usize, load: &[usize], profile: Profile) -> bool {
    let b = scene.objects[object].world_aabb();
    let s = b.size();
    let (long, deep) = (s.x.max(s.z), s.x.min(s.z));
    let load: Vec<Aabb> = load
        .iter()
        .map(|&u| scene.objects[u].world_aabb())
        .collect();
    match profile {
        Profile::Surface => {
            // Things on it, none covering it as a stacked box would.
            let top = b.max.y - scene.floor();
            // (Long, narrow and low is a chest or a shelf: a table is deep enough to sit at
            // or square.)
            (SURFACE_MIN_TOP..=SURFACE_MAX_TOP).contains(&top)
                && s.y <= 1.5 * long
                && (deep >= SURFACE_MIN_DEPTH || long <= 1.5 * deep)
                && !load.is_empty()
                && !load.iter().any(|u| stacked(&b, u))
        }
        Profile::Bench => {
            s.y <= BENCH_MAX_HEIGHT && long >= BENCH_MIN_LENGTH && long >= BENCH_MIN_RATIO * deep
        }
        Profile::Stack => load.iter().any(|u| stacked(&b, u)),
        Profile::Seat => {
            (SEAT_MIN_HEIGHT..=SEAT_MAX_HEIGHT).contains(&s.y) && long <= SEAT_MAX_WIDTH
        }
        Profile::Door => {
            let at_wall = scene
                .bounds
                .is_some_and(|room| super::select::near_a_wall(&room, &b, DOOR_WALL_GAP));
            at_wall
                && s.y >= DOOR_MIN_HEIGHT
                && deep <= DOOR_MAX_THICKNESS
                && (DOOR_MIN_WIDTH..=DOOR_MAX_WIDTH).contains(&long)
        }
    }
}

/// Of the `anonymous` objects, the seats: a seat's size ([`fits`]) and drawn up to one
/// that is a table (the nearest object standing up is a table, within reach of its
/// footprint: [`crate::ground::depend::belongs_to`]).
#[must_use]
pub(crate) fn seats(scene: &Scene, anonymous: &[usize], loads: &[Vec<usize>]) -> Vec<usize> {
    let tables: Vec<usize> = anonymous
        .iter()
        .copied()
        .filter(|&o| fits(scene, o, &loads[o], Profile::Surface))
        .collect();
    if tables.is_empty() {
        return Vec::new();
    }
    let sized: Vec<usize> = anonymous
        .iter()
        .copied()
        .filter(|&o| !tables.contains(&o) && fits(scene, o, &loads[o], Profile::Seat))
        .collect();
    let boxes = scene.world_aabbs();
    sized
        .iter()
        .copied()
        .filter(|&o| super::depend::belongs_to(scene, &boxes, o, &tables, &sized))
        .collect()
}

/// Whether `upper`, resting on `lower`, is about its footprint: stacked on it.
fn stacked(lower: &Aabb, upper: &Aabb) -> bool {
    let (l, u) = (lower.size(), upper.size());
    let (below, above) = (l.x * l.z, u.x * u.z);
    below > 0.0 && above >= STACK_MIN_COVER * below && above <= below / STACK_MIN_COVER
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ground::lexicon::Lexicon;

    #[test]
    fn names_of_primitives_and_nodes_say_nothing() {
        let lexicon = Lexicon::builtin();
        for name in [
            "pCube1",
            "polySurface7",
            "group4_mesh",
            "Object_12",
            "Cube.004",
        ] {
            assert!(
                is_anonymous(&super::super::ident::read(name, lexicon)),
                "{name}"
            );
        }
        for name in ["Table_Coffee", "SM_Chair_01", "Plant_Fern", "Lamp.001"] {
            assert!(
                !is_anonymous(&super::super::ident::read(name, lexicon)),
                "{name}"
            );
        }
    }
}

//! What an object is as a thing that stands somewhere: floor furniture (chairs, tables,
//! sofas, cabinets — which stay on the floor) or a portable thing (a mug, a lamp, a book —
//! which may go on a surface). Placement reads it: collision resolution never lifts floor
//! furniture onto another object, and "next to" keeps it on the floor
//! (docs/collisions.md, "Placement guarantees").
//!
//! The kind comes from the lexicon (the object's category, else the head noun of its name
//! as [`super::ident`] reads it): a kind under `furniture` or `appliance`, or one the
//! lexicon does not know, is floor furniture when the object is also big enough to stand
//! on the floor by itself ([`FLOOR_HEIGHT`] tall with a footprint of [`FLOOR_FOOTPRINT`]);
//! a known kind of anything else (electronics, containers, plants) only when it is
//! [`TALL`] or covers [`WIDE`] of floor. So a table lamp (furniture to WordNet, but small)
//! may be put on a desk, and an unnamed 0.9 m box with a 0.5 m² footprint is floor
//! furniture.

use super::ident;
use super::lexicon::Lexicon;
use super::words::normalize;
use crate::scene::mesh::Measured;
use crate::scene::{Form, Scene};

/// Height from which furniture, an appliance or an object of unknown kind stands on the
/// floor, in metres.
pub const FLOOR_HEIGHT: f64 = 0.35;
/// Footprint from which furniture, an appliance or an object of unknown kind stands on
/// the floor, in square metres.
pub const FLOOR_FOOTPRINT: f64 = 0.1;
/// Height from which anything stands on the floor, in metres.
pub const TALL: f64 = 1.0;
/// Footprint from which anything stands on the floor, in square metres.
pub const WIDE: f64 = 0.5;

/// Whether object `i` of `scene` is floor furniture.
#[must_use]
pub fn is_floor_bound(scene: &Scene, i: usize) -> bool {
    let o = &scene.objects[i];
    let size = o.world_aabb().size();
    let furniture = furniture_kind(Lexicon::builtin(), o.labels.category.as_deref(), &o.name);
    stands_on_floor(furniture, size.y, size.x * size.z)
}

/// What of object `i`'s box is solid: as its scene file says (`form`); else as its mesh
/// shows (`scene::mesh`: room under it, room inside it, or neither), but for a case of
/// shelves, which keeps its shelves; else a top on legs
/// for a table, a desk or a counter (by the lexicon: its category, else its name's head
/// noun — a table lamp is a lamp) at least [`Form`]'s knee height tall, an open container
/// for a box, a basket, a bin, a toolbox, a drawer, a bag, a crate or a bucket — each
/// turned about the vertical by quarter turns only (its legs and walls along its box's
/// sides); else solid.
#[must_use]
pub fn form_of(scene: &Scene, i: usize) -> Form {
    let o = &scene.objects[i];
    if let Some(form) = o.form {
        return form;
    }
    let q = o.similarity().rotation;
    let x = q * glam::DVec3::X;
    let square = (q * glam::DVec3::Y - glam::DVec3::Y).length() < 1e-6
        && (x.x.abs() < 1e-6 || x.z.abs() < 1e-6);
    let tall = o.world_aabb().size().y >= crate::scene::form::KNEE_HEIGHT;
    let table = || {
        filed_under(
            Lexicon::builtin(),
            o.labels.category.as_deref(),
            &o.name,
            &["table", "desk", "counter"],
        ) == Some(true)
    };
    let container = || {
        filed_under(
            Lexicon::builtin(),
            o.labels.category.as_deref(),
            &o.name,
            &[
                "box",
                "basket",
                "bin",
                "toolbox",
                "drawer",
                "bag",
                "crate",
                "bucket",
                "container",
            ],
        ) == Some(true)
    };
    // A bookcase, a set of shelves, a cabinet or a cupboard standing at least as tall as
    // a shelf's spacing (not a filing cabinet: drawers, not shelves).
    let shelves = || {
        o.world_aabb().size().y >= crate::scene::form::SHELF_SPACING
            && !o.name.to_lowercase().contains("filing")
            && filed_under(
                Lexicon::builtin(),
                o.labels.category.as_deref(),
                &o.name,
                &[
                    "bookcase",
                    "bookshelf",
                    "shelving",
                    "shelves",
                    "cabinet",
                    "cupboard",
                    "hutch",
                ],
            ) == Some(true)
    };
    let by_kind = if square && tall && table() {
        Form::ON_LEGS
    } else if square && container() {
        Form::Open
    } else if square && shelves() {
        Form::SHELVES
    } else {
        Form::Solid
    };
    match o.measured.filter(|_| square) {
        None => by_kind,
        // A bookcase on legs (or whose boards do not show) keeps its shelves.
        Some(m) if by_kind.shelves() && !matches!(m, Measured::Shelves(_)) => by_kind,
        Some(Measured::Under { underside }) => Form::OnLegs {
            underside: Some(underside),
        },
        Some(Measured::Inside) => Form::Open,
        Some(Measured::Shelves(boards)) => Form::Shelves {
            boards: Some(boards),
        },
        // Its mesh shows no room under it or in it, whatever its kind.
        Some(Measured::Neither) => Form::Solid,
    }
}

/// The seat and back of object `i` when it is a chair (not a stool: no back) standing
/// upright and turned by quarter turns, so that its back is across one side of its box:
/// the side away from where it faces.
#[must_use]
pub fn seat_of(scene: &Scene, i: usize) -> Option<crate::scene::Seat> {
    let o = &scene.objects[i];
    let chair = filed_under(
        Lexicon::builtin(),
        o.labels.category.as_deref(),
        &o.name,
        &["chair"],
    ) == Some(true);
    let stool = filed_under(
        Lexicon::builtin(),
        o.labels.category.as_deref(),
        &o.name,
        &["stool"],
    ) == Some(true);
    if !chair || stool {
        return None;
    }
    let front = o.world_front();
    let axis = [0, 2]
        .into_iter()
        .find(|&k| front[k].abs() > 1.0 - 1e-6 && front.y.abs() < 1e-6)?;
    Some(crate::scene::Seat::of(
        &o.world_aabb(),
        axis,
        front[axis] < 0.0,
    ))
}

/// How object `i` may share the box of object `j`, if at all: `j`'s form (the room under
/// its top, or inside it), and `i`'s seat and back when it is a chair.
#[must_use]
pub fn room_of(scene: &Scene, i: usize, j: usize) -> Option<crate::scene::Room> {
    let form = form_of(scene, j);
    let seat = seat_of(scene, i);
    (form != Form::Solid || seat.is_some()).then_some(crate::scene::Room { form, seat })
}

/// Whether an object of this kind (`Some(true)` furniture or appliance, `Some(false)`
/// another known kind, `None` unknown) and size stands on the floor.
#[must_use]
pub fn stands_on_floor(furniture: Option<bool>, height: f64, footprint: f64) -> bool {
    if height >= TALL || footprint >= WIDE {
        return true;
    }
    furniture != Some(false) && height >= FLOOR_HEIGHT && footprint >= FLOOR_FOOTPRINT
}

/// Whether the lexicon files the object's kind under furniture or appliances: from its
/// category when it has one, else from its name; `None` when neither names a kind the
/// lexicon knows.
#[must_use]
pub fn furniture_kind(lexicon: &Lexicon, category: Option<&str>, name: &str) -> Option<bool> {
    filed_under(lexicon, category, name, &["furniture", "appliance"])
}

/// Whether the lexicon files the object's kind under a seat (a chair, a stool, a bench, a
/// sofa): from its category when it has one, else from its name; `None` when neither
/// names a kind the lexicon knows.
#[must_use]
pub fn seat_kind(lexicon: &Lexicon, category: Option<&str>, name: &str) -> Option<bool> {
    filed_under(lexicon, category, name, &["seat"])
}

/// Whether the lexicon files the object's kind (its category, else its name) under one of
/// `roots` or as one of them; `None` when neither names a kind the lexicon knows.
fn filed_under(
    lexicon: &Lexicon,
    category: Option<&str>,
    name: &str,
    roots: &[&str],
) -> Option<bool> {
    let mut phrases = Vec::new();
    if let Some(c) = category {
        phrases.push(normalize(c));
    }
    let id = ident::read(name, lexicon);
    phrases.push(id.base);
    phrases.extend(id.other);
    let roots: Vec<usize> = roots
        .iter()
        .flat_map(|w| lexicon.concepts_of(w).iter().copied())
        .collect();
    phrases.iter().find_map(|p| {
        let concepts = concepts_of_head(lexicon, p);
        (!concepts.is_empty()).then(|| {
            concepts.iter().any(|&c| {
                roots.contains(&c)
                    || lexicon
                        .concept(c)
                        .hypernyms
                        .iter()
                        .any(|h| roots.contains(h))
            })
        })
    })
}

/// The concepts a phrase names: the whole phrase, else its longest ending the lexicon
/// knows (`oak wardrobe` → wardrobe), singular or plural.
fn concepts_of_head(lexicon: &Lexicon, phrase: &str) -> Vec<usize> {
    let words: Vec<&str> = phrase.split(' ').filter(|w| !w.is_empty()).collect();
    for start in 0..words.len() {
        let tail = words[start..].join(" ");
        let mut found: Vec<usize> = lexicon.concepts_of(&tail).to_vec();
        if found.is_empty() {
            for s in lexicon.singulars(&tail) {
                found.extend_from_slice(lexicon.concepts_of(&s));
            }
        }
        if !found.is_empty() {
            return found;
        }
    }
    Vec::new()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kind(category: Option<&str>, name: &str) -> Option<bool> {
        furniture_kind(Lexicon::builtin(), category, name)
    }

    #[test]
    fn kinds_come_from_the_category_or_the_name() {
        assert_eq!(kind(None, "Chair_Wood.001"), Some(true));
        assert_eq!(kind(None, "SM_Sofa_01"), Some(true));
        assert_eq!(kind(None, "Wardrobe_Oak"), Some(true));
        assert_eq!(kind(Some("fridge"), "thing 3"), Some(true));
        assert_eq!(kind(None, "Mug_Coffee"), Some(false));
        assert_eq!(kind(None, "TV_Screen"), Some(false));
        assert_eq!(kind(None, "Zorblax_7"), None);
    }

    #[test]
    fn size_decides_within_a_kind() {
        // A chair, a table lamp (furniture to WordNet), a 65-inch tv, a rug, an unnamed
        // crate-sized box, a potted tree.
        assert!(stands_on_floor(Some(true), 0.9, 0.25));
        assert!(!stands_on_floor(Some(true), 0.5, 0.07));
        assert!(!stands_on_floor(Some(false), 0.85, 0.12));
        assert!(stands_on_floor(None, 0.01, 4.0));
        assert!(stands_on_floor(None, 0.6, 0.2));
        assert!(stands_on_floor(Some(false), 1.6, 0.2));
        assert!(!stands_on_floor(None, 0.2, 0.04));
    }
}

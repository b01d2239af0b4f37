//! For the stages' unit tests: an instruction with variables read against boxes given by
//! hand (no scene, every object unturned and facing +Z), its answers evaluated as the
//! translator evaluates them, so a test asserts where each object goes, not what was
//! printed.

use super::{answer, Known};
use crate::expr::{self, Bindings, ObjectBox};
use cga::Similarity;
use glam::DVec3;

/// The room of the unit tests: 6 m wide (x −3 … 3), 3 m high, 5 m deep (z −2.5 … 2.5).
pub(super) const ROOM: ([f64; 3], [f64; 3]) = ([-3.0, 0.0, -2.5], [3.0, 3.0, 2.5]);

/// A box by its minimum and maximum corners.
pub(super) type Box3 = ([f64; 3], [f64; 3]);

/// A box `size` wide, high and deep standing on the floor, centred at (`x`, `z`).
pub(super) fn standing(size: [f64; 3], x: f64, z: f64) -> Box3 {
    on(size, x, 0.0, z)
}

/// A box `size` wide, high and deep with its bottom at height `y`, centred at (`x`, `z`).
pub(super) fn on(size: [f64; 3], x: f64, y: f64, z: f64) -> Box3 {
    (
        [x - size[0] / 2.0, y, z - size[2] / 2.0],
        [x + size[0] / 2.0, y + size[1], z + size[2] / 2.0],
    )
}

/// The bindings of `boxes` (`X1`, `X2`, … in order), all facing +Z, and of the room
/// ([`ROOM`]) when `room`.
fn bindings(boxes: &[Box3], room: bool) -> Bindings {
    let mut b = Bindings::new();
    let object = |(min, max): Box3| ObjectBox {
        min: DVec3::from(min),
        max: DVec3::from(max),
        front: DVec3::Z,
    };
    for (k, &x) in boxes.iter().enumerate() {
        b.bind(format!("X{}", k + 1), object(x));
    }
    if room {
        b.bind("room", object(ROOM));
    }
    b
}

/// Reads `query` about `boxes` (the variables, in order) in a scene with the room
/// ([`ROOM`]) or without, and evaluates each variable's answer: per variable, what the
/// instruction does to it (the identity where it does nothing).
///
/// # Errors
/// The reader's refusal.
pub(super) fn outcome(query: &str, boxes: &[Box3], room: bool) -> Result<Vec<Similarity>, String> {
    let known = Known {
        room,
        yaw: vec![0.0; boxes.len()],
        sizes: boxes
            .iter()
            .map(|(min, max)| [max[0] - min[0], max[1] - min[1], max[2] - min[2]])
            .collect(),
        ..Known::default()
    };
    let entries = answer(query, boxes.len(), &known).map_err(|e| e.to_string())?;
    let bindings = bindings(boxes, room);
    let mut out = vec![Similarity::IDENTITY; boxes.len()];
    for e in entries {
        let mut m = cga::Multivector::ONE;
        for x in &e.expressions {
            let item = expr::evaluate_tree(x, &bindings)
                .and_then(|v| expr::to_transformation(&v))
                .map_err(|err| err.to_string())?;
            m = item.versor * m;
        }
        out[e.variable] = expr::to_transformation(&m)
            .map_err(|err| err.to_string())?
            .similarity;
    }
    Ok(out)
}

/// How far each variable moves under `query` in the room ([`outcome`]).
///
/// # Panics
/// When the reader refuses it.
pub(super) fn moves(query: &str, boxes: &[Box3]) -> Vec<DVec3> {
    outcome(query, boxes, true)
        .unwrap_or_else(|e| panic!("{query}: {e}"))
        .iter()
        .map(|s| s.translation)
        .collect()
}

/// How far each variable turns about the vertical under `query`, in degrees (+ is
/// counter-clockwise seen from above: +Z toward +X).
///
/// # Panics
/// When the reader refuses it.
pub(super) fn turns(query: &str, boxes: &[Box3]) -> Vec<f64> {
    outcome(query, boxes, true)
        .unwrap_or_else(|e| panic!("{query}: {e}"))
        .iter()
        .map(|s| {
            let f = s.rotation * DVec3::Z;
            f.x.atan2(f.z).to_degrees()
        })
        .collect()
}

/// Whether `a` is `b` within 1e-9 on every axis.
pub(super) fn close(a: DVec3, b: [f64; 3]) -> bool {
    (a - DVec3::from(b)).abs().max_element() < 1e-9
}

//! Which object rests on which.

use super::Scene;
use crate::geometry::{Aabb, FloorGrid};

/// How far above another object's top an object's bottom may be and still rest on it,
/// in metres. Objects also count as resting when they sink slightly into their support.
pub const SUPPORT_GAP: f64 = 0.01;

/// How far above the floor an object's bottom may be and still stand on the floor (on a
/// rug), in metres.
pub const FLOOR_LEVEL: f64 = 0.05;

/// Marks, for each object without a support from the file, the object it rests on: the
/// one whose top is within [`SUPPORT_GAP`] of its bottom, that its footprint's centre lies
/// over, and that it rises above (so two supports can never form a cycle). Among several,
/// the highest top wins, then the largest footprint overlap. An object that rests on no
/// top but stands inside another's box, above its bottom (a book on a bookcase's shelf),
/// is held by the smallest such object.
pub fn detect(scene: &mut Scene) {
    let boxes = scene.world_aabbs();
    let grid = FloorGrid::new(&boxes);
    for i in 0..boxes.len() {
        if !scene.objects[i].support_from_file {
            scene.objects[i].support = support_of(scene, &boxes, &grid, i);
        }
    }
}

/// [`detect`] for what `changed` (objects whose boxes moved) can have changed: the changed
/// objects themselves, what rested on them, and what stands over their new footprints —
/// except the objects marked in `hung` (those that hung when the edit began): they never
/// come to rest on what moved under them (a chair pushed under a whiteboard does not carry
/// the whiteboard away), while a lamp whose table went away comes to rest on the table
/// moved under it. `boxes` and `grid` must already hold the new boxes. Costs what moved,
/// not the scene.
pub fn detect_around(
    scene: &mut Scene,
    boxes: &[Aabb],
    grid: &FloorGrid,
    changed: &[usize],
    hung: &[bool],
) {
    let mut candidates: Vec<usize> = changed.to_vec();
    let mut moved = vec![false; scene.objects.len()];
    for &c in changed {
        if let Some(m) = moved.get_mut(c) {
            *m = true;
        }
    }
    for (i, o) in scene.objects.iter().enumerate() {
        if o.support
            .is_some_and(|s| moved.get(s).copied().unwrap_or(false))
        {
            candidates.push(i);
        }
    }
    for &c in changed {
        candidates.extend(
            grid.near_box(&boxes[c])
                .into_iter()
                .filter(|&j| !hung.get(j).copied().unwrap_or(false)),
        );
    }
    candidates.sort_unstable();
    candidates.dedup();
    for i in candidates {
        if scene.objects[i].support_from_file {
            continue;
        }
        // What still rests on its support keeps it (a lamp carried with its nightstand
        // into the bed's box still stands on the nightstand, not on the bed).
        let keeps = scene.objects[i].support.is_some_and(|s| {
            s != i && (rests(scene, &boxes[i], &boxes[s]) || inside(&boxes[i], &boxes[s]))
        });
        if !keeps {
            scene.objects[i].support = support_of(scene, boxes, grid, i);
        }
    }
}

/// How high above the floor a top must be to carry anything, in metres: a rug 1 cm thick
/// carries the coffee table standing on it (moving the rug moves the table, as people
/// expect), a decal with no thickness carries nothing.
const CARRYING_TOP: f64 = 1e-3;

/// Whether box `a` rests on box `b` by the rule of [`detect`]: its bottom within
/// [`SUPPORT_GAP`] of `b`'s top, that top above the floor (by [`CARRYING_TOP`]), `a`
/// reaching above it, its centre over `b`'s footprint.
fn rests(scene: &Scene, a: &Aabb, b: &Aabb) -> bool {
    let centre = a.center();
    b.max.y > scene.floor() + CARRYING_TOP
        && (a.min.y - b.max.y).abs() <= SUPPORT_GAP
        && a.max.y > b.max.y + 1e-3
        && centre.x >= b.min.x
        && centre.x <= b.max.x
        && centre.z >= b.min.z
        && centre.z <= b.max.z
}

/// What object `i` rests on, by the rule of [`detect`].
fn support_of(scene: &Scene, boxes: &[Aabb], grid: &FloorGrid, i: usize) -> Option<usize> {
    let a = &boxes[i];
    if a.min.y <= scene.floor() + CARRYING_TOP {
        return None;
    }
    let mut best: Option<(usize, f64, f64)> = None;
    let centre = a.center();
    for j in grid.near_point(centre.x, centre.z) {
        let b = &boxes[j];
        if i == j {
            continue;
        }
        if !rests(scene, a, b) {
            continue;
        }
        let overlap = a.footprint_overlap(b);
        let better = match best {
            None => true,
            Some((_, top, area)) => {
                b.max.y > top + 1e-9 || (b.max.y >= top - 1e-9 && overlap > area)
            }
        };
        if better {
            best = Some((j, b.max.y, overlap));
        }
    }
    best.map(|(j, _, _)| j)
        .or_else(|| container_of(boxes, grid, i))
}

/// Whether box `a` stands inside box `b` rather than on its top: its bottom within `b`'s
/// height, above `b`'s bottom, and its footprint within `b`'s (to 1 cm) — a book on a
/// bookcase's shelf, a cushion sunk in a sofa, a drill in a toolbox.
fn inside(a: &Aabb, b: &Aabb) -> bool {
    const MARGIN: f64 = 0.01;
    a.min.y > b.min.y + 1e-3
        && a.min.y < b.max.y - SUPPORT_GAP
        && a.min.x >= b.min.x - MARGIN
        && a.max.x <= b.max.x + MARGIN
        && a.min.z >= b.min.z - MARGIN
        && a.max.z <= b.max.z + MARGIN
}

/// For an object that rests on no top: the smallest object whose box it stands inside
/// ([`inside`]), so that it moves with what holds it.
fn container_of(boxes: &[Aabb], grid: &FloorGrid, i: usize) -> Option<usize> {
    let a = &boxes[i];
    let volume = |b: &Aabb| {
        let s = b.size();
        s.x * s.y * s.z
    };
    let centre = a.center();
    grid.near_point(centre.x, centre.z)
        .filter(|&j| j != i && inside(a, &boxes[j]) && volume(&boxes[j]) > volume(a))
        .min_by(|&j, &k| volume(&boxes[j]).total_cmp(&volume(&boxes[k])))
}

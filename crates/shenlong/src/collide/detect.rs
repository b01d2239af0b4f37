//! Detection: which overlaps does an edit create?

use super::EPSILON;
use crate::geometry::{Aabb, FloorGrid};
use crate::scene::form::clear_in;
use crate::scene::Room;
use glam::DVec3;

/// What an object collides with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Obstacle {
    /// Another object, by index.
    Object(usize),
    /// The floor (y = 0, or the room's `min.y`).
    Floor,
    /// A wall of the room: the axis (0 = x, 2 = z) and side (false = min, true = max).
    Wall {
        /// 0 for the x walls, 2 for the z walls.
        axis: usize,
        /// Whether it is the wall at the room's maximum along that axis.
        max_side: bool,
    },
    /// The room's ceiling.
    Ceiling,
}

impl Obstacle {
    /// A name for reports: the object's name, or `the floor`, `the left wall`, ….
    pub fn describe(&self, scene: &crate::scene::Scene) -> String {
        match self {
            Obstacle::Object(i) => format!("'{}'", scene.objects[*i].name),
            Obstacle::Floor => "the floor".into(),
            Obstacle::Ceiling => "the ceiling".into(),
            Obstacle::Wall {
                axis: 0,
                max_side: false,
            } => "the left wall (−x)".into(),
            Obstacle::Wall {
                axis: 0,
                max_side: true,
            } => "the right wall (+x)".into(),
            Obstacle::Wall {
                max_side: false, ..
            } => "the back wall (−z)".into(),
            Obstacle::Wall { max_side: true, .. } => "the front wall (+z)".into(),
        }
    }
}

/// One collision: an object of a moved group overlapping an obstacle.
#[derive(Clone, Debug, PartialEq)]
pub struct Overlap {
    /// The moved object.
    pub object: usize,
    /// What it overlaps.
    pub with: Obstacle,
    /// How deep the overlap is along x, y, z (metres).
    pub depth: DVec3,
}

/// Overlap volume of two boxes (0 when they do not overlap).
pub(crate) fn overlap_volume(a: &Aabb, b: &Aabb) -> f64 {
    let o = a.overlap(b);
    if o.cmpgt(DVec3::ZERO).all() {
        o.x * o.y * o.z
    } else {
        0.0
    }
}

/// The thickest slab lying on the floor that furniture stands on rather than collides
/// with (a rug, a mat), in metres.
pub const FLOOR_COVERING: f64 = 0.03;

/// The narrowest a floor covering is across, in metres: a magazine or a laptop put on the
/// floor is no rug to stand things on.
pub const FLOOR_COVERING_WIDTH: f64 = 0.4;

/// Whether `b` is a floor covering ([`FLOOR_COVERING`], [`FLOOR_COVERING_WIDTH`]) lying
/// on the floor at `floor`.
fn covers_floor(b: &Aabb, floor: f64) -> bool {
    let size = b.size();
    size.y <= FLOOR_COVERING
        && size.x.min(size.z) >= FLOOR_COVERING_WIDTH
        && (b.min.y - floor).abs() <= FLOOR_COVERING
}

/// Whether `a` and `b` meet only as something standing on a rug does: one of them a
/// floor covering, the other standing on the floor over it (its bottom no higher than
/// the covering's top) — or both coverings.
pub(crate) fn stands_on_covering(a: &Aabb, b: &Aabb, floor: f64) -> bool {
    let over =
        |x: &Aabb, cover: &Aabb| covers_floor(cover, floor) && x.min.y <= cover.max.y + EPSILON;
    over(a, b) || over(b, a)
}

/// Whether the overlap of `a` and `b` is a collision given how much they overlapped before
/// the edit: a new overlap, or a pre-existing one made larger.
pub(crate) fn collides(a: &Aabb, b: &Aabb, volume_before: f64) -> bool {
    if !a.intersects(b, EPSILON) {
        return false;
    }
    if volume_before <= 0.0 {
        return true;
    }
    overlap_volume(a, b) > volume_before * (1.0 + 1e-9) + EPSILON.powi(3)
}

/// How far `b` sticks out of the room, per obstacle: floor, walls, ceiling.
pub(crate) fn room_violations(b: &Aabb, floor: f64, room: Option<&Aabb>) -> Vec<(Obstacle, f64)> {
    let mut out = Vec::new();
    if b.min.y < floor - EPSILON {
        out.push((Obstacle::Floor, floor - b.min.y));
    }
    if let Some(r) = room {
        for axis in [0, 2] {
            if b.min[axis] < r.min[axis] - EPSILON {
                out.push((
                    Obstacle::Wall {
                        axis,
                        max_side: false,
                    },
                    r.min[axis] - b.min[axis],
                ));
            }
            if b.max[axis] > r.max[axis] + EPSILON {
                out.push((
                    Obstacle::Wall {
                        axis,
                        max_side: true,
                    },
                    b.max[axis] - r.max[axis],
                ));
            }
        }
        if b.max.y > r.max.y + EPSILON {
            out.push((Obstacle::Ceiling, b.max.y - r.max.y));
        }
    }
    out
}

/// The collisions of the objects in `groups` (each a set of object indices that moved
/// together) in the scene whose boxes are `after`, against every other object and the
/// room; `before` are the boxes before the edit, for pre-existing overlaps.
/// `under(i, j)`: the form of object `j` when object `i` may stand in its room — under a
/// top on legs, inside an open container (`scene::form`).
pub fn find_collisions(
    before: &[Aabb],
    after: &[Aabb],
    groups: &[Vec<usize>],
    floor: f64,
    room: Option<&Aabb>,
    under: &dyn Fn(usize, usize) -> Option<Room>,
) -> Vec<Overlap> {
    find_collisions_in(
        &FloorGrid::new(after),
        before,
        after,
        groups,
        floor,
        room,
        under,
    )
}

/// [`find_collisions`] with a grid over `after` already built.
pub fn find_collisions_in(
    grid: &FloorGrid,
    before: &[Aabb],
    after: &[Aabb],
    groups: &[Vec<usize>],
    floor: f64,
    room: Option<&Aabb>,
    under: &dyn Fn(usize, usize) -> Option<Room>,
) -> Vec<Overlap> {
    let mut group_of = vec![usize::MAX; after.len()];
    for (g, members) in groups.iter().enumerate() {
        for &i in members {
            group_of[i] = g;
        }
    }
    let mut out = Vec::new();
    for members in groups {
        for &i in members {
            let a = &after[i];
            for j in grid.near_box(a) {
                // Same group: they moved together. Two moved groups: report the pair once.
                if group_of[j] == group_of[i] || (group_of[j] != usize::MAX && j < i) {
                    continue;
                }
                // Standing on a rug, or in the room of what it was put under or in.
                let apart = || {
                    stands_on_covering(a, &after[j], floor)
                        || under(i, j).is_some_and(|f| clear_in(a, &after[j], f))
                        || under(j, i).is_some_and(|f| clear_in(&after[j], a, f))
                };
                if collides(a, &after[j], overlap_volume(&before[i], &before[j])) && !apart() {
                    out.push(Overlap {
                        object: i,
                        with: Obstacle::Object(j),
                        depth: a.overlap(&after[j]),
                    });
                }
            }
            let was = room_violations(&before[i], floor, room);
            for (obstacle, depth) in room_violations(a, floor, room) {
                let before_depth = was
                    .iter()
                    .find(|(o, _)| *o == obstacle)
                    .map_or(0.0, |(_, d)| *d);
                if depth > before_depth + EPSILON {
                    out.push(Overlap {
                        object: i,
                        with: obstacle,
                        depth: DVec3::splat(depth),
                    });
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube(x: f64, y: f64, z: f64, s: f64) -> Aabb {
        Aabb::new(DVec3::new(x, y, z), DVec3::new(x + s, y + s, z + s))
    }

    #[test]
    fn touching_is_not_colliding_and_overlapping_is() {
        let before = [cube(0.0, 0.0, 0.0, 1.0), cube(3.0, 0.0, 0.0, 1.0)];
        let touching = [cube(2.0, 0.0, 0.0, 1.0), before[1]];
        assert!(
            find_collisions(&before, &touching, &[vec![0]], 0.0, None, &|_, _| None).is_empty()
        );
        let on_top = [cube(3.0, 1.0, 0.0, 1.0), before[1]];
        assert!(find_collisions(&before, &on_top, &[vec![0]], 0.0, None, &|_, _| None).is_empty());
        let into = [cube(2.5, 0.0, 0.0, 1.0), before[1]];
        let found = find_collisions(&before, &into, &[vec![0]], 0.0, None, &|_, _| None);
        assert_eq!(found.len(), 1);
        assert_eq!(found[0].with, Obstacle::Object(1));
        assert!((found[0].depth.x - 0.5).abs() < 1e-12);
    }

    #[test]
    fn pre_existing_overlaps_are_allowed_unless_deepened() {
        // A cushion half inside a sofa's box.
        let sofa = Aabb::new(DVec3::ZERO, DVec3::new(2.0, 0.9, 1.0));
        let cushion = cube(0.5, 0.4, 0.2, 0.4);
        let before = [cushion, sofa];
        let slid = [cushion.translated(DVec3::new(0.3, 0.0, 0.0)), sofa];
        assert!(find_collisions(&before, &slid, &[vec![0]], 0.0, None, &|_, _| None).is_empty());
        let pushed_in = [cushion.translated(DVec3::new(0.0, -0.3, 0.0)), sofa];
        assert!(
            find_collisions(&before, &pushed_in, &[vec![0]], 0.0, None, &|_, _| None).is_empty(),
            "same volume inside"
        );
        let bigger = [
            Aabb::new(cushion.min, cushion.max + DVec3::splat(0.2)),
            sofa,
        ];
        assert_eq!(
            find_collisions(&before, &bigger, &[vec![0]], 0.0, None, &|_, _| None).len(),
            1
        );
    }

    #[test]
    fn floor_walls_and_ceiling() {
        let room = Aabb::new(DVec3::new(-2.0, 0.0, -2.0), DVec3::new(2.0, 2.5, 2.0));
        let before = [cube(0.0, 0.0, 0.0, 1.0)];
        let cases = [
            (cube(0.0, -0.5, 0.0, 1.0), Obstacle::Floor),
            (
                cube(1.5, 0.0, 0.0, 1.0),
                Obstacle::Wall {
                    axis: 0,
                    max_side: true,
                },
            ),
            (
                cube(0.0, 0.0, -2.5, 1.0),
                Obstacle::Wall {
                    axis: 2,
                    max_side: false,
                },
            ),
            (cube(0.0, 2.0, 0.0, 1.0), Obstacle::Ceiling),
        ];
        for (after, expected) in cases {
            let found =
                find_collisions(&before, &[after], &[vec![0]], 0.0, Some(&room), &|_, _| {
                    None
                });
            assert_eq!(found.len(), 1, "{expected:?}");
            assert_eq!(found[0].with, expected);
        }
        // Without bounds there are no walls, only the floor.
        assert!(find_collisions(
            &before,
            &[cube(5.0, 0.0, 0.0, 1.0)],
            &[vec![0]],
            0.0,
            None,
            &|_, _| None
        )
        .is_empty());
    }

    #[test]
    fn groups_move_as_one_and_moved_groups_collide_with_each_other() {
        let table = Aabb::new(DVec3::ZERO, DVec3::new(1.0, 0.8, 1.0));
        let cup = cube(0.4, 0.8, 0.4, 0.1);
        let chair = cube(3.0, 0.0, 0.0, 0.5);
        let before = [table, cup, chair];
        // Table and cup move together; the cup on the table is no collision.
        let shift = DVec3::new(0.5, 0.0, 0.0);
        let after = [table.translated(shift), cup.translated(shift), chair];
        assert!(
            find_collisions(&before, &after, &[vec![0, 1]], 0.0, None, &|_, _| None).is_empty()
        );
        // Two groups moved into each other: one collision, reported once.
        let after = [
            table.translated(DVec3::new(2.5, 0.0, 0.0)),
            cup.translated(DVec3::new(2.5, 0.0, 0.0)),
            chair.translated(DVec3::new(-0.2, 0.0, 0.0)),
        ];
        let found = find_collisions(
            &before,
            &after,
            &[vec![0, 1], vec![2]],
            0.0,
            None,
            &|_, _| None,
        );
        assert_eq!(found.len(), 1, "{found:?}");
    }
}

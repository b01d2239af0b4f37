//! Picking among several objects that fit a phrase: by place in the room, by size, by
//! order along a direction, and by relation to another object. Every pick needs a clear
//! winner: when two candidates are too close to call, nothing is picked.

use super::words::{Axis, Degree, Measure, Shape};
use crate::geometry::Aabb;
use crate::scene::Scene;
use glam::DVec3;

/// Positions closer than this along an axis cannot be told apart, in metres.
pub(crate) const POSITION_MARGIN: f64 = 0.05;
/// Sizes closer than this ratio cannot be told apart.
pub(crate) const SIZE_RATIO: f64 = 1.1;
/// The nearest candidate must be this much nearer than the next, in metres…
pub(crate) const DISTANCE_MARGIN: f64 = 0.1;
/// …or this many times nearer.
pub(crate) const DISTANCE_RATIO: f64 = 1.25;
/// "next to", "by", "beside", "near": at most this far (gap between boxes), in metres.
pub(crate) const NEAR_LIMIT: f64 = 1.5;

/// A relation to another object that picks candidates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Relation {
    /// Resting on it (`the book on the side table`).
    On,
    /// Resting on it, said as where it is taken from (`take the cups off the table`):
    /// never where it goes, so it always picks or checks.
    Off,
    /// Resting on it or inside it, said as where it comes from (`the mug from the back
    /// counter`, `the milk from the fridge`): never where it goes.
    From,
    /// Carrying it (`the desk with the lamp on it`).
    Carries,
    /// Carrying it, said as "the same N as it" (`the same bench as the microscope`): it
    /// always says which, wherever the phrase stands.
    SameAs,
    /// Inside its box (`the apple in the fridge`).
    Inside,
    /// Under it.
    Under,
    /// Above or over it (`the painting above the sofa`).
    Above,
    /// Next to, by, beside, near it.
    Near,
    /// Nearest to it.
    Nearest,
    /// Farthest from it.
    Farthest,
    /// In front of it (+z).
    InFront,
    /// Behind it (−z).
    Behind,
    /// To its left (−x).
    LeftOf,
    /// To its right (+x).
    RightOf,
    /// Between the two targets (`the chair between chair 12 and chair 14`).
    Between,
    /// Across something from it (`the chair opposite chair 2`, `across from the sofa`):
    /// a third object stands between them on the floor plan.
    Opposite,
}

impl Relation {
    /// Whether the words of this relation can also say where something goes (`next to`,
    /// `on`, `under`, `behind` …), as opposed to only picking (`nearest`, `carrying`).
    #[must_use]
    pub fn can_be_a_destination(self) -> bool {
        !matches!(
            self,
            Self::Nearest | Self::Farthest | Self::Carries | Self::SameAs | Self::Off | Self::From
        )
    }
}

fn boxes(scene: &Scene, objects: &[usize]) -> Vec<Aabb> {
    objects
        .iter()
        .map(|&i| scene.objects[i].world_aabb())
        .collect()
}

/// The `need` candidates at one end of a sorting key (smallest keys first), when they are
/// clearly apart from the rest; `None` when too close to call.
fn take_extreme(
    candidates: &[usize],
    keys: &[f64],
    need: usize,
    separated: impl Fn(f64, f64) -> bool,
) -> Option<Vec<usize>> {
    if need >= candidates.len() {
        return Some(candidates.to_vec());
    }
    let mut order: Vec<usize> = (0..candidates.len()).collect();
    order.sort_by(|&a, &b| keys[a].total_cmp(&keys[b]));
    let (last_in, first_out) = (keys[order[need - 1]], keys[order[need]]);
    separated(last_in, first_out).then(|| order[..need].iter().map(|&k| candidates[k]).collect())
}

/// The `need` candidates farthest along a direction (`front left` = (−1, 0, +1)), when
/// clearly apart from the rest. A diagonal needs twice the margin of a side.
pub(crate) fn by_direction(
    scene: &Scene,
    candidates: &[usize],
    direction: DVec3,
    need: usize,
) -> Option<Vec<usize>> {
    let axes = [direction.x, direction.y, direction.z]
        .iter()
        .filter(|c| **c != 0.0)
        .count();
    let margin = if axes > 1 {
        2.0 * POSITION_MARGIN
    } else {
        POSITION_MARGIN
    };
    let d = direction.normalize_or_zero();
    let keys: Vec<f64> = boxes(scene, candidates)
        .iter()
        .map(|b| -b.center().dot(d))
        .collect();
    take_extreme(candidates, &keys, need, |a, b| b - a > margin)
}

/// All the candidates at one end of a direction (`the front chairs`): those within
/// [`POSITION_MARGIN`] of the farthest along it.
pub(crate) fn at_direction(scene: &Scene, candidates: &[usize], direction: DVec3) -> Vec<usize> {
    let d = direction.normalize_or_zero();
    let keys: Vec<f64> = boxes(scene, candidates)
        .iter()
        .map(|b| -b.center().dot(d))
        .collect();
    let best = keys.iter().copied().fold(f64::INFINITY, f64::min);
    candidates
        .iter()
        .zip(&keys)
        .filter(|(_, &k)| k - best <= POSITION_MARGIN)
        .map(|(&c, _)| c)
        .collect()
}

/// All the candidates at one side: those within [`POSITION_MARGIN`] of the extreme.
pub(crate) fn at_side(scene: &Scene, candidates: &[usize], axis: Axis, sign: f64) -> Vec<usize> {
    let mut direction = DVec3::ZERO;
    direction[axis as usize] = sign;
    at_direction(scene, candidates, direction)
}

/// The middle one of an odd number of candidates, along the axis they spread most on.
pub(crate) fn middle(scene: &Scene, candidates: &[usize]) -> Option<usize> {
    if candidates.len() < 3 || candidates.len() % 2 == 0 {
        return None;
    }
    let order = along_spread(scene, candidates);
    let m = order.len() / 2;
    (order[m].0 - order[m - 1].0 > POSITION_MARGIN && order[m + 1].0 - order[m].0 > POSITION_MARGIN)
        .then_some(order[m].1)
}

/// `candidates` in order along the horizontal axis their centres spread most on (x on a
/// tie), each with its centre's coordinate on it: the line "the middle one" and "the end
/// ones" are read along.
fn along_spread(scene: &Scene, candidates: &[usize]) -> Vec<(f64, usize)> {
    let b = boxes(scene, candidates);
    let spread = |axis: Axis| {
        let v: Vec<f64> = b.iter().map(|b| axis.of(b.center())).collect();
        v.iter().cloned().fold(f64::MIN, f64::max) - v.iter().cloned().fold(f64::MAX, f64::min)
    };
    let axis = if spread(Axis::X) >= spread(Axis::Z) {
        Axis::X
    } else {
        Axis::Z
    };
    let mut order: Vec<(f64, usize)> = b
        .iter()
        .zip(candidates)
        .map(|(b, &i)| (axis.of(b.center()), i))
        .collect();
    order.sort_by(|a, b| a.0.total_cmp(&b.0));
    order
}

/// The first and last of `candidates` (three or more) along the axis they spread most
/// on: "the end stools". `None` where either is not clearly apart from its neighbour.
pub(crate) fn ends(scene: &Scene, candidates: &[usize]) -> Option<Vec<usize>> {
    if candidates.len() < 3 {
        return None;
    }
    let order = along_spread(scene, candidates);
    let n = order.len();
    (order[1].0 - order[0].0 > POSITION_MARGIN && order[n - 1].0 - order[n - 2].0 > POSITION_MARGIN)
        .then(|| vec![order[0].1, order[n - 1].1])
}

/// The candidates biggest or smallest by a measure. A comparative or plain word
/// (`bigger`, `big`) compares exactly two.
pub(crate) fn by_size(
    scene: &Scene,
    candidates: &[usize],
    measure: Measure,
    sign: f64,
    degree: Degree,
    need: usize,
) -> Result<Vec<usize>, SizeError> {
    let keys = size_keys(scene, candidates, measure, sign);
    if degree != Degree::Superlative && candidates.len() > 2 && need == 1 {
        // "the small box" among nine: the few that stand out as small, if any do.
        return match (degree, standout(candidates, &keys)) {
            (Degree::Plain, Some(group)) if group.len() == 1 => Ok(group),
            (Degree::Plain, Some(group)) => Err(SizeError::Several(group)),
            _ => Err(SizeError::ComparesTwo),
        };
    }
    take_extreme(candidates, &keys, need, |a, b| b - a > SIZE_RATIO.ln()).ok_or(SizeError::TooClose)
}

/// The candidates a plain size word names as a group (`the small boxes`): those that stand
/// out by [`STANDOUT_RATIO`] from the rest at that end, at most half of them.
pub(crate) fn by_size_group(
    scene: &Scene,
    candidates: &[usize],
    measure: Measure,
    sign: f64,
) -> Option<Vec<usize>> {
    if candidates.len() <= 2 {
        return None;
    }
    standout(candidates, &size_keys(scene, candidates, measure, sign))
}

/// Per candidate, its size by `measure` as a sorting key: the log of the size, smallest
/// key first for the end `sign` names (`sign` +1: the biggest first). The log makes "10 %
/// bigger" a fixed margin.
fn size_keys(scene: &Scene, candidates: &[usize], measure: Measure, sign: f64) -> Vec<f64> {
    boxes(scene, candidates)
        .iter()
        .map(|b| {
            let s = b.size();
            let m = match measure {
                Measure::Volume => s.x * s.y * s.z,
                Measure::Height => s.y,
                Measure::Length => s.x.max(s.z),
            };
            -sign * m.max(1e-12).ln()
        })
        .collect()
}

/// A size ratio that sets a few objects apart from the rest ("the small boxes" are at
/// least this many times smaller than every other box).
pub(crate) const STANDOUT_RATIO: f64 = 1.6;

/// The fewest candidates at the small-key end that stand apart from all the others by
/// [`STANDOUT_RATIO`], at most half of them; `None` when no such group stands out.
fn standout(candidates: &[usize], keys: &[f64]) -> Option<Vec<usize>> {
    let mut order: Vec<usize> = (0..candidates.len()).collect();
    order.sort_by(|&a, &b| keys[a].total_cmp(&keys[b]));
    (1..=candidates.len() / 2)
        .find(|&k| keys[order[k]] - keys[order[k - 1]] > STANDOUT_RATIO.ln())
        .map(|k| order[..k].iter().map(|&i| candidates[i]).collect())
}

/// Whether `object`'s box has the shape a shape word names.
#[must_use]
pub(crate) fn has_shape(scene: &Scene, object: usize, shape: Shape) -> bool {
    let s = scene.objects[object].world_aabb().size();
    let (wide, deep, high) = (s.x.max(s.z), s.x.min(s.z), s.y);
    let slender = wide <= 0.5 * high;
    match shape {
        Shape::Flat => high <= 0.25 * deep,
        Shape::Slender => slender,
        Shape::Thin => {
            let mut d = [s.x, s.y, s.z];
            d.sort_by(f64::total_cmp);
            slender || d[0] <= 0.25 * d[1]
        }
    }
}

/// Why a size word picked nothing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum SizeError {
    /// `bigger` with more than two candidates, or a plain word with none standing out.
    ComparesTwo,
    /// The sizes are too close to call.
    TooClose,
    /// A plain word (`the small box`) with several standing out alike: these.
    Several(Vec<usize>),
}

/// The `k`-th candidate (from 1; `usize::MAX` = the last) counted along a direction, or by
/// distance from a point.
pub(crate) fn nth(scene: &Scene, candidates: &[usize], k: usize, from: Direction) -> Option<usize> {
    let b = boxes(scene, candidates);
    let keys: Vec<f64> = b
        .iter()
        .map(|b| match from {
            Direction::Side(axis, sign) => -sign * axis.of(b.center()),
            Direction::From(p) => (b.center() - p).length(),
        })
        .collect();
    let mut order: Vec<usize> = (0..candidates.len()).collect();
    order.sort_by(|&a, &c| keys[a].total_cmp(&keys[c]));
    let k = if k == usize::MAX { order.len() } else { k };
    if k == 0 || k > order.len() {
        return None;
    }
    let at = keys[order[k - 1]];
    let apart =
        |j: usize| j == 0 || j > order.len() || (keys[order[j - 1]] - at).abs() > POSITION_MARGIN;
    (apart(k - 1) && apart(k + 1)).then_some(candidates[order[k - 1]])
}

/// Where an ordinal counts from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Direction {
    /// From one side of the room: `from the left` = (x, −1).
    Side(Axis, f64),
    /// From a point (another object's centre).
    From(DVec3),
}

/// Gap between two boxes in 3D (0 when they touch or overlap).
fn gap(a: &Aabb, b: &Aabb) -> f64 {
    let d = (a.min - b.max).max(b.min - a.max).max(DVec3::ZERO);
    d.length()
}

/// The candidates in `relation` to some of the `targets` (one object, or every object a
/// still ambiguous phrase fits): `need` of them, clearly picked (`usize::MAX`: all that
/// stand in a membership relation). `None` when no candidate, or no clear one, does.
pub(crate) fn by_relation(
    scene: &Scene,
    candidates: &[usize],
    relation: Relation,
    targets: &[usize],
    need: usize,
) -> Option<Vec<usize>> {
    let pool: Vec<usize> = candidates
        .iter()
        .copied()
        .filter(|c| !targets.contains(c))
        .collect();
    let target_boxes = boxes(scene, targets);
    // (candidate, key) of those that stand in the relation to some target; smallest key
    // is best.
    let mut fits: Vec<(usize, f64)> = if relation == Relation::Between {
        // Measured against both targets at once.
        let [a, b] = target_boxes.as_slice() else {
            return None;
        };
        pool.iter()
            .filter_map(|&c| between_key(&scene.objects[c].world_aabb(), a, b).map(|k| (c, k)))
            .collect()
    } else {
        pool.iter()
            .zip(&boxes(scene, &pool))
            .filter_map(|(&c, cb)| {
                targets
                    .iter()
                    .zip(&target_boxes)
                    .filter_map(|(&t, tb)| relation_key(scene, (c, cb), relation, (t, tb)))
                    .reduce(f64::min)
                    .map(|key| (c, key))
            })
            .collect()
    };
    if fits.is_empty() {
        return None;
    }
    straight_first(scene, &mut fits, relation, &target_boxes);
    if matches!(
        relation,
        Relation::On
            | Relation::Off
            | Relation::From
            | Relation::Under
            | Relation::Carries
            | Relation::SameAs
            | Relation::Inside
    ) {
        // Membership relations: all that stand in it, when that is the number wanted.
        return (fits.len() == need || need == usize::MAX)
            .then(|| fits.iter().map(|f| f.0).collect());
    }
    let need = need.min(fits.len());
    fits.sort_by(|a, b| a.1.total_cmp(&b.1));
    if need < fits.len() {
        let (last_in, first_out) = (fits[need - 1].1, fits[need].1);
        let clear = first_out - last_in > DISTANCE_MARGIN
            || (relation != Relation::Farthest
                && first_out > DISTANCE_RATIO * last_in.max(1e-9)
                && first_out - last_in > 0.02);
        if !clear {
            return None;
        }
    }
    Some(fits[..need].iter().map(|f| f.0).collect())
}

/// "the chair in front of chair 9" in rows of chairs: the one straight in front of it, not
/// the diagonal neighbour nearly as near. For a side relation (in front, behind, left,
/// right), where some of the `fits` overlap a target across that side's axis, only those
/// are kept.
fn straight_first(
    scene: &Scene,
    fits: &mut Vec<(usize, f64)>,
    relation: Relation,
    target_boxes: &[Aabb],
) {
    let across = match relation {
        Relation::InFront | Relation::Behind => 0,
        Relation::LeftOf | Relation::RightOf => 2,
        _ => return,
    };
    let straight = |c: usize| {
        let cb = scene.objects[c].world_aabb();
        target_boxes
            .iter()
            .any(|tb| cb.min[across] < tb.max[across] && cb.max[across] > tb.min[across])
    };
    if fits.iter().any(|&(c, _)| straight(c)) {
        fits.retain(|&(c, _)| straight(c));
    }
}

/// Whether box `a`'s centre is inside box `b`.
fn inside(a: &Aabb, b: &Aabb) -> bool {
    let p = a.center();
    p.cmpge(b.min).all() && p.cmple(b.max).all()
}

/// Whether `upper` rests on `lower`: its support, or its bottom on the other's top over it.
fn rests_on(scene: &Scene, (upper, ub): (usize, &Aabb), (lower, lb): (usize, &Aabb)) -> bool {
    scene.objects[upper].support == Some(lower)
        || ((ub.min.y - lb.max.y).abs() < 0.05 && ub.floor_gap(lb) <= 0.0)
}

/// How well a candidate stands in `relation` to a target (smaller is better), or `None`
/// when it does not.
fn relation_key(
    scene: &Scene,
    (c, cb): (usize, &Aabb),
    relation: Relation,
    (t, tb): (usize, &Aabb),
) -> Option<f64> {
    let key = match relation {
        Relation::On | Relation::Off => rests_on(scene, (c, cb), (t, tb)).then_some(0.0)?,
        Relation::Carries | Relation::SameAs => rests_on(scene, (t, tb), (c, cb)).then_some(0.0)?,
        Relation::Inside => inside(cb, tb).then_some(0.0)?,
        Relation::From => (rests_on(scene, (c, cb), (t, tb)) || inside(cb, tb)).then_some(0.0)?,
        Relation::Under => (cb.floor_gap(tb) <= 0.0
            && cb.center().y < tb.center().y
            && scene.objects[c].support != Some(t))
        .then_some(0.0)?,
        Relation::Above => (cb.min.y >= tb.max.y - 0.05).then(|| cb.floor_gap(tb))?,
        Relation::Near => Some(gap(cb, tb)).filter(|g| *g <= NEAR_LIMIT)?,
        Relation::Nearest => gap(cb, tb),
        Relation::Farthest => -(cb.center() - tb.center()).length(),
        Relation::InFront => (cb.center().z > tb.max.z).then(|| gap(cb, tb))?,
        Relation::Behind => (cb.center().z < tb.min.z).then(|| gap(cb, tb))?,
        Relation::LeftOf => (cb.center().x < tb.min.x).then(|| gap(cb, tb))?,
        Relation::RightOf => (cb.center().x > tb.max.x).then(|| gap(cb, tb))?,
        Relation::Opposite => {
            across(scene, (c, cb), (t, tb)).then(|| flat_distance(cb.center(), tb.center()))?
        }
        // Measured against both targets at once ([`between_key`]).
        Relation::Between => return None,
    };
    Some(key)
}

/// The distance between two points on the floor plan.
fn flat_distance(a: DVec3, b: DVec3) -> f64 {
    glam::DVec2::new(a.x - b.x, a.z - b.z).length()
}

/// How far box `c`'s centre stands off the line between the centres of `a` and `b` on
/// the floor plan, where it projects onto the middle of that segment (a fifth in from
/// either end); `None` otherwise.
fn between_key(c: &Aabb, a: &Aabb, b: &Aabb) -> Option<f64> {
    let flat = |v: DVec3| glam::DVec2::new(v.x, v.z);
    let (p, q, x) = (flat(a.center()), flat(b.center()), flat(c.center()));
    let d = q - p;
    let t = (x - p).dot(d) / d.length_squared().max(1e-12);
    (0.2..=0.8).contains(&t).then(|| (p + d * t - x).length())
}

/// Whether something else — a third object taller than a rug — stands between `c` and
/// `t` on the floor plan: the segment between their centres crosses its footprint.
fn across(scene: &Scene, (c, cb): (usize, &Aabb), (t, tb): (usize, &Aabb)) -> bool {
    let (p, q) = (cb.center(), tb.center());
    scene.objects.iter().enumerate().any(|(o, object)| {
        if o == c || o == t {
            return false;
        }
        let ob = object.world_aabb();
        ob.size().y > 0.05 && segment_crosses_footprint(p, q, &ob)
    })
}

/// Whether the floor-plan segment from `p` to `q` passes through box `b`'s footprint
/// (slab clipping on x and z).
fn segment_crosses_footprint(p: DVec3, q: DVec3, b: &Aabb) -> bool {
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    for e in [0, 2] {
        let d = q[e] - p[e];
        if d.abs() < 1e-12 {
            if p[e] < b.min[e] || p[e] > b.max[e] {
                return false;
            }
            continue;
        }
        let (t0, t1) = ((b.min[e] - p[e]) / d, (b.max[e] - p[e]) / d);
        lo = lo.max(t0.min(t1));
        hi = hi.min(t0.max(t1));
    }
    lo <= hi
}

/// A place in the room that picks an object standing there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum RoomPlace {
    /// A corner: the sides named (x sign, z sign), else whichever corner is nearest.
    Corner(Option<f64>, Option<f64>),
    /// The middle of the room.
    Middle,
    /// On a wall: hanging on it or standing against it.
    Wall,
    /// By one wall (`by the left wall`): within [`BY_WALL_REACH`] of it.
    ByWall(Axis, f64),
    /// On or against one wall (`the bookcase against the back wall`): of those no other
    /// wall is nearer, the ones nearest it, within [`ON_WALL_SPREAD`] of the nearest,
    /// which is within [`BY_WALL_REACH`].
    OnWall(Axis, f64),
}

/// How much further from a wall than the nearest an object "against the wall" may stand.
pub(crate) const ON_WALL_SPREAD: f64 = 0.15;

/// How close to a wall an object "by the wall" is (the gap between its box and the wall).
pub(crate) const BY_WALL_REACH: f64 = 1.0;

/// How close to a wall an object "on the wall" is.
pub(crate) const WALL_GAP: f64 = 0.05;
/// How close to both walls of a corner an object "in the corner" is.
pub(crate) const CORNER_REACH: f64 = 0.5;
/// How close to the room's middle an object "in the middle of the room" is (its centre),
/// as a fraction of the room's smaller horizontal extent.
pub(crate) const MIDDLE_REACH: f64 = 0.25;

/// The candidates a room place keeps: of those there at all (within [`CORNER_REACH`] of
/// both walls of the corner, within [`MIDDLE_REACH`] of the room's smaller extent of the
/// middle), the one nearest it,
/// with a clear margin over the next ([`DISTANCE_MARGIN`], [`DISTANCE_RATIO`]); or every
/// one within [`WALL_GAP`] of a wall, or [`BY_WALL_REACH`] of the wall named. `None` when
/// none is clearly there.
pub(crate) fn in_room(scene: &Scene, candidates: &[usize], place: RoomPlace) -> Option<Vec<usize>> {
    let room = scene.bounds?;
    let b = boxes(scene, candidates);
    let flat = |v: glam::DVec3| glam::DVec2::new(v.x, v.z);
    let distance = |bx: &Aabb| -> f64 {
        let c = flat(bx.center());
        match place {
            RoomPlace::Middle => (c - flat(room.center())).length(),
            RoomPlace::Corner(x, z) => {
                let xs: Vec<f64> = match x {
                    Some(s) if s < 0.0 => vec![room.min.x],
                    Some(_) => vec![room.max.x],
                    None => vec![room.min.x, room.max.x],
                };
                let zs: Vec<f64> = match z {
                    Some(s) if s < 0.0 => vec![room.min.z],
                    Some(_) => vec![room.max.z],
                    None => vec![room.min.z, room.max.z],
                };
                xs.iter()
                    .flat_map(|&cx| zs.iter().map(move |&cz| glam::DVec2::new(cx, cz)))
                    .map(|corner| (c - corner).length())
                    .fold(f64::INFINITY, f64::min)
            }
            RoomPlace::Wall | RoomPlace::ByWall(..) | RoomPlace::OnWall(..) => 0.0,
        }
    };
    if let RoomPlace::OnWall(axis, sign) = place {
        // Against this wall, not the one round the corner: no other wall is nearer.
        let gap = |bx: &Aabb| wall_gap(&room, bx, axis, sign);
        let its_wall = |bx: &Aabb| gap(bx) <= nearest_wall(&room, bx).1 + 1e-3;
        let there: Vec<(usize, f64)> = candidates
            .iter()
            .zip(&b)
            .filter(|(_, bx)| its_wall(bx))
            .map(|(&i, bx)| (i, gap(bx)))
            .collect();
        let nearest = there.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        if nearest > BY_WALL_REACH {
            return None;
        }
        let kept = there
            .iter()
            .filter(|p| p.1 <= nearest + ON_WALL_SPREAD)
            .map(|p| p.0)
            .collect();
        return Some(kept);
    }
    if matches!(place, RoomPlace::Wall | RoomPlace::ByWall(..)) {
        // Along a wall, nearer or further from it says nothing of which: every one there.
        let against = |bx: &Aabb| match place {
            RoomPlace::ByWall(axis, sign) => wall_gap(&room, bx, axis, sign) <= BY_WALL_REACH,
            _ => near_a_wall(&room, bx, WALL_GAP),
        };
        let kept: Vec<usize> = candidates
            .iter()
            .zip(&b)
            .filter(|(_, bx)| against(bx))
            .map(|(&i, _)| i)
            .collect();
        return (!kept.is_empty()).then_some(kept);
    }
    // To be there at all: within [`CORNER_REACH`] of both walls of a corner, or within
    // [`MIDDLE_REACH`] of the room's middle.
    let there = |bx: &Aabb| match place {
        RoomPlace::Corner(x, z) => {
            let near_x = |sign: f64| {
                if sign < 0.0 {
                    bx.min.x - room.min.x <= CORNER_REACH
                } else {
                    room.max.x - bx.max.x <= CORNER_REACH
                }
            };
            let near_z = |sign: f64| {
                if sign < 0.0 {
                    bx.min.z - room.min.z <= CORNER_REACH
                } else {
                    room.max.z - bx.max.z <= CORNER_REACH
                }
            };
            let xs = x.map_or_else(|| vec![-1.0, 1.0], |s| vec![s]);
            let zs = z.map_or_else(|| vec![-1.0, 1.0], |s| vec![s]);
            xs.iter().any(|&sx| near_x(sx))
                && zs.iter().any(|&sz| near_z(sz))
                && xs
                    .iter()
                    .any(|&sx| zs.iter().any(|&sz| near_x(sx) && near_z(sz)))
        }
        RoomPlace::Middle => {
            let extent = (room.max.x - room.min.x).min(room.max.z - room.min.z);
            (flat(bx.center()) - flat(room.center())).length() <= MIDDLE_REACH * extent
        }
        RoomPlace::Wall | RoomPlace::ByWall(..) | RoomPlace::OnWall(..) => true,
    };
    let mut order: Vec<(f64, usize)> = b
        .iter()
        .zip(candidates.iter().copied())
        .filter(|(bx, _)| there(bx))
        .map(|(bx, i)| (distance(bx), i))
        .collect();
    order.sort_by(|a, b| a.0.total_cmp(&b.0));
    match order.as_slice() {
        [(_, one)] => Some(vec![*one]),
        [(d0, first), (d1, _), ..] => {
            (d1 - d0 > DISTANCE_MARGIN && *d1 > d0 * DISTANCE_RATIO).then(|| vec![*first])
        }
        [] => None,
    }
}

/// Whether a box stands within `gap` of any of the room's four walls.
#[must_use]
pub(crate) fn near_a_wall(room: &Aabb, b: &Aabb, gap: f64) -> bool {
    nearest_wall(room, b).1 <= gap
}

/// The one wall every candidate stands against (its nearest, within [`BY_WALL_REACH`]):
/// "from the window" where the windows are all in the left wall is from the left. `None`
/// where they stand at different walls, away from the walls, or there is no room.
pub(crate) fn common_wall(scene: &Scene, candidates: &[usize]) -> Option<(Axis, f64)> {
    let room = scene.bounds?;
    let mut common = None;
    for b in boxes(scene, candidates) {
        let (wall, gap) = nearest_wall(&room, &b);
        if gap > BY_WALL_REACH || common.is_some_and(|c| c != wall) {
            return None;
        }
        common = Some(wall);
    }
    common
}

/// The room's wall nearest box `b` (its axis and side; the first of left, right, back,
/// front on a tie) and the gap to it.
fn nearest_wall(room: &Aabb, b: &Aabb) -> ((Axis, f64), f64) {
    [
        (Axis::X, -1.0),
        (Axis::X, 1.0),
        (Axis::Z, -1.0),
        (Axis::Z, 1.0),
    ]
    .into_iter()
    .map(|(a, s)| ((a, s), wall_gap(room, b, a, s)))
    .fold(((Axis::X, -1.0), f64::INFINITY), |best, w| {
        if w.1 < best.1 {
            w
        } else {
            best
        }
    })
}

/// The gap between a box and the room's wall on side (`axis`, `sign`).
fn wall_gap(room: &Aabb, b: &Aabb, axis: Axis, sign: f64) -> f64 {
    let a = axis as usize;
    if sign < 0.0 {
        b.min[a] - room.min[a]
    } else {
        room.max[a] - b.max[a]
    }
}

/// Which line of objects a phrase names: "the back row", "the second row", "the left
/// column", "row 3".
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Line {
    /// A row (objects side by side across the room, left to right), counted from the
    /// front: the `n`th (1-based; `usize::MAX` the last).
    Row(usize),
    /// A column (objects one behind another), counted from the left.
    Column(usize),
    /// The middle row or column (`columns` when a column), of an odd number of them.
    Middle { columns: bool },
}

/// The lines the objects stand in: rows (by the depth of their centres, front first) or
/// columns (by their left-right centres, left first). A new line starts where the next
/// centre is further on than half the objects' median extent along that axis; `None`
/// when they make fewer than two lines.
#[must_use]
pub(crate) fn lines(scene: &Scene, objects: &[usize], columns: bool) -> Option<Vec<Vec<usize>>> {
    let b = boxes(scene, objects);
    let axis = if columns { 0 } else { 2 };
    let mut extents: Vec<f64> = b.iter().map(|x| x.size()[axis]).collect();
    extents.sort_by(f64::total_cmp);
    let tolerance = 0.5 * extents.get(extents.len() / 2).copied().unwrap_or(0.0);
    let mut order: Vec<(f64, usize)> = b
        .iter()
        .zip(objects)
        .map(|(x, &o)| (x.center()[axis], o))
        .collect();
    // Rows from the front (+z first); columns from the left (−x first).
    if columns {
        order.sort_by(|a, b| a.0.total_cmp(&b.0));
    } else {
        order.sort_by(|a, b| b.0.total_cmp(&a.0));
    }
    let mut out: Vec<Vec<usize>> = Vec::new();
    let mut last = f64::NAN;
    for (c, o) in order {
        if out.is_empty() || (c - last).abs() > tolerance {
            out.push(Vec::new());
        }
        if let Some(line) = out.last_mut() {
            line.push(o);
        }
        last = c;
    }
    // One object standing apart is no line of its own when it is of another family than
    // the lines (the teacher's desk behind rows of numbered student desks); one of the
    // same family makes the lines unclear.
    if out.iter().any(|l| l.len() >= 2) {
        let families: Vec<String> = out
            .iter()
            .filter(|l| l.len() >= 2)
            .flatten()
            .map(|&o| family(&scene.objects[o].name))
            .collect();
        let mut kept = Vec::with_capacity(out.len());
        for line in out {
            match line.as_slice() {
                [one] if families.contains(&family(&scene.objects[*one].name)) => return None,
                [_] => {}
                _ => kept.push(line),
            }
        }
        out = kept;
    }
    (out.len() >= 2).then_some(out)
}

/// A name without its instance number, as names are compared: `exam desk` for `Exam Desk
/// 05`, `stool bar` for `Stool_Bar.002`.
fn family(name: &str) -> String {
    let normalized = super::words::normalize(name);
    super::words::split_number(&normalized).0.to_string()
}

/// The objects of one line ([`lines`]); `None` when they stand in no such lines or there
/// is no such one.
#[must_use]
pub(crate) fn in_line(scene: &Scene, objects: &[usize], line: Line) -> Option<Vec<usize>> {
    let (columns, n) = match line {
        Line::Row(n) => (false, n),
        Line::Column(n) => (true, n),
        Line::Middle { columns } => (columns, 0),
    };
    let all = lines(scene, objects, columns)?;
    let index = match line {
        Line::Middle { .. } => (all.len() % 2 == 1).then_some(all.len() / 2)?,
        _ if n == usize::MAX => all.len() - 1,
        _ => n.checked_sub(1).filter(|&k| k < all.len())?,
    };
    all.into_iter().nth(index)
}

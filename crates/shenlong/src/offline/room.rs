//! Places in the room, written with the `room` variable (the scene's bounds): its centre,
//! corners and walls, the floor, and how far an object can go toward a wall.

use super::amounts::FAR_METRES;
use super::build::*;
use crate::expr::Expr;

/// Clearance kept from walls, in metres: none, as "against the wall" means touching it
/// (and touching is not colliding).
pub const CLEARANCE: f64 = 0.0;

/// A place in the room.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Place {
    /// The centre of the floor.
    Centre,
    /// A corner: the sides named (x side, z side), else the nearest.
    Corner(Option<f64>, Option<f64>),
    /// A wall: the one named (axis, sign), else the nearest.
    Wall(Option<(usize, f64)>),
    /// Against the wall named (axis, sign), centred along it ("centre it on the left
    /// wall", "the middle of the back wall").
    WallCentre(usize, f64),
}

/// Flush against the min or max wall along an axis.
fn to_wall(s: usize, e: usize, sign: f64) -> Expr {
    if sign > 0.0 {
        scaled_axis(
            sub(
                sub(dot(room("max"), axis(e)), num(CLEARANCE)),
                dot(var(s, "max"), axis(e)),
            ),
            e,
        )
    } else {
        scaled_axis(
            sub(
                add(dot(room("min"), axis(e)), num(CLEARANCE)),
                dot(var(s, "min"), axis(e)),
            ),
            e,
        )
    }
}

/// 1 when the object is on the max side of the room's centre along an axis, else 0.
fn max_side(s: usize, e: usize) -> Expr {
    step(dot(sub(var(s, "center"), room("center")), axis(e)))
}

/// Against the nearer wall along an axis.
fn nearer_wall(s: usize, e: usize) -> Expr {
    let p = max_side(s, e);
    add(
        mul(p.clone(), to_wall(s, e, 1.0)),
        mul(sub(num(1.0), p), to_wall(s, e, -1.0)),
    )
}

/// `along(0)` where subject `s` is nearer an x wall than a z wall, else `along(2)`: what
/// to do at the nearest of the four walls (compared by the distances to the nearer wall of
/// each axis).
fn at_nearest_wall(s: usize, along: impl Fn(usize) -> Expr) -> Expr {
    let distance = |e: usize| {
        let half = dot(sub(room("max"), room("min")), axis(e));
        sub(
            div(half, num(2.0)),
            call(
                "abs",
                vec![dot(sub(var(s, "center"), room("center")), axis(e))],
            ),
        )
    };
    let x_nearer = step(sub(distance(2), distance(0)));
    add(
        mul(x_nearer.clone(), along(0)),
        mul(sub(num(1.0), x_nearer), along(2)),
    )
}

/// "away from the wall": `amount` metres straight out from a wall — the one named
/// (`wall`: its axis and side), else the nearest of the four.
pub(crate) fn away_from_wall(s: usize, wall: Option<(usize, f64)>, amount: f64) -> Expr {
    // Out from the nearer wall along axis `e`: towards the room's centre.
    let out = |e: usize| {
        let p = max_side(s, e);
        scaled_axis(mul(num(amount), sub(num(1.0), mul(num(2.0), p))), e)
    };
    match wall {
        Some((e, sign)) => scaled_axis(num(-sign * amount), e),
        None => at_nearest_wall(s, out),
    }
}

/// "a bit towards the middle of the room": along the floor towards the room's centre by
/// `amount` (never past it), or halfway with none. A `group` moved so goes together, the
/// way from the middle of their centres: the beds along the left wall move straight out
/// from it, not each on its own diagonal.
pub(crate) fn towards_centre(group: &[usize], amount: Option<f64>) -> Expr {
    let middle = match group {
        [one] => var(*one, "center"),
        _ => mul(
            num(1.0 / group.len().max(1) as f64),
            super::build::sum(group.iter().map(|&k| var(k, "center"))),
        ),
    };
    let f = flat(sub(room("center"), middle));
    match amount {
        Some(x) => {
            let length = call("abs", vec![f.clone()]);
            // (At the centre already: no way towards it, and no motion.)
            let share = div(
                call("min", vec![num(x), length.clone()]),
                call("max", vec![num(1e-9), length]),
            );
            mul(share, f)
        }
        None => mul(num(0.5), f),
    }
}

/// "a bit closer to the back wall": towards a wall (the one named, else the nearest) by
/// `amount`, never closer than [`CLEARANCE`]; with no amount, halfway to it.
pub(crate) fn towards_wall(s: usize, wall: Option<(usize, f64)>, amount: Option<f64>) -> Expr {
    let by = |e: usize, sign: f64| {
        let left = room_left(s, e, sign);
        let length = match amount {
            Some(x) => call("min", vec![num(x), left]),
            None => mul(num(0.5), left),
        };
        scaled_axis(mul(num(sign), length), e)
    };
    match wall {
        Some((e, sign)) => by(e, sign),
        None => at_nearest_wall(s, |e| {
            let p = max_side(s, e);
            add(
                mul(p.clone(), by(e, 1.0)),
                mul(sub(num(1.0), p), by(e, -1.0)),
            )
        }),
    }
}

/// "to the other side of the room": mirrored through the room's centre along the
/// horizontal axis on which it stands furthest from the centre (for its room: the
/// offset over the room's half size).
pub(crate) fn other_side_of_room(s: usize) -> Expr {
    let offset = |e: usize| dot(sub(var(s, "center"), room("center")), axis(e));
    let share = |e: usize| {
        div(
            call("abs", vec![offset(e)]),
            div(dot(sub(room("max"), room("min")), axis(e)), num(2.0)),
        )
    };
    let x_further = step(sub(share(0), share(2)));
    add(
        mul(x_further.clone(), scaled_axis(mul(num(-2.0), offset(0)), 0)),
        mul(
            sub(num(1.0), x_further),
            scaled_axis(mul(num(-2.0), offset(2)), 2),
        ),
    )
}

/// The translation that takes subject `s` to a place in the room.
pub(crate) fn place(p: Place, s: usize) -> Expr {
    let centre = |e: usize| along(sub(room("center"), var(s, "center")), e);
    match p {
        Place::Centre => add(centre(0), centre(2)),
        Place::Corner(x, z) => {
            let x = x.map_or_else(|| nearer_wall(s, 0), |sign| to_wall(s, 0, sign));
            let z = z.map_or_else(|| nearer_wall(s, 2), |sign| to_wall(s, 2, sign));
            add(x, z)
        }
        Place::Wall(Some((e, sign))) => to_wall(s, e, sign),
        Place::WallCentre(e, sign) => add(to_wall(s, e, sign), centre(2 - e)),
        Place::Wall(None) => at_nearest_wall(s, |e| nearer_wall(s, e)),
    }
}

/// How far subject `s` can go along a direction before the wall (at least 0).
fn room_left(s: usize, e: usize, sign: f64) -> Expr {
    let d = if sign > 0.0 {
        sub(
            sub(dot(room("max"), axis(e)), num(CLEARANCE)),
            dot(var(s, "max"), axis(e)),
        )
    } else {
        sub(
            dot(var(s, "min"), axis(e)),
            add(dot(room("min"), axis(e)), num(CLEARANCE)),
        )
    };
    call("max", vec![num(0.0), d])
}

/// "a lot to the left": [`FAR_METRES`] or up to the wall, whichever is less (the full
/// amount when the scene has no room).
pub(crate) fn far(s: usize, e: usize, sign: f64, has_room: bool) -> Expr {
    if has_room && e != 1 {
        scaled_axis(
            mul(
                num(sign),
                call("min", vec![num(FAR_METRES), room_left(s, e, sign)]),
            ),
            e,
        )
    } else {
        scaled_axis(num(sign * FAR_METRES), e)
    }
}

/// "all the way to the left": against that wall.
pub(crate) fn all_the_way(s: usize, e: usize, sign: f64) -> Expr {
    to_wall(s, e, sign)
}

/// The floor height: the room's `min.y`, or 0 without a room.
pub(crate) fn floor(has_room: bool) -> Expr {
    if has_room {
        dot(room("min"), axis(1))
    } else {
        num(0.0)
    }
}

/// Down onto the floor, where it is.
pub(crate) fn onto_floor(s: usize, has_room: bool) -> Expr {
    scaled_axis(sub(floor(has_room), dot(var(s, "min"), axis(1))), 1)
}

//! Relations to other objects, as translation vectors written with only the objects'
//! boxes (`X2.max`, `X1.center`, …): never the scene's numbers, so answers are
//! scene-independent. Targets are taken where earlier clauses of the instruction left them.

use super::build::*;
use crate::expr::Expr;
use std::collections::BTreeMap;

/// Gap left between objects placed next to each other, in metres.
pub const GAP: f64 = 0.05;

/// What a clause asks of one variable.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Step {
    /// A translation by this vector (inside `T(...)`).
    Translate(Expr),
    /// A rotor or dilator, applied about the pivot.
    Turn(Expr),
}

/// The steps so far, per variable.
pub(crate) type Steps = BTreeMap<usize, Vec<Step>>;

/// `X{k}.attribute` where earlier clauses left it: its points shifted by their
/// translations (its size is its size wherever it is).
pub(crate) fn boxed(k: usize, attribute: &str, steps: &Steps) -> Expr {
    if attribute == "size" {
        return var(k, attribute);
    }
    let moves: Vec<Expr> = steps
        .get(&k)
        .into_iter()
        .flatten()
        .filter_map(|s| match s {
            Step::Translate(v) => Some(v.clone()),
            Step::Turn(_) => None,
        })
        .collect();
    if moves.is_empty() {
        var(k, attribute)
    } else {
        add(var(k, attribute), sum(moves))
    }
}

/// How a person says the side of an object on axis `e` toward `sign`: `to the right of`,
/// `to the left of`, `in front of`, `behind`, `above`, `below`.
pub(crate) fn side_name(e: usize, sign: f64) -> &'static str {
    match (e, sign > 0.0) {
        (0, true) => "to the right of",
        (0, false) => "to the left of",
        (1, true) => "above",
        (1, false) => "below",
        (_, true) => "in front of",
        (_, false) => "behind",
    }
}

/// The relations a clause may name.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Relation {
    /// On top of.
    On,
    /// Under.
    Under,
    /// In an open container or on a shelf of a case of shelves: resting this high above
    /// the target's bottom (its floor inside), within its walls.
    In(f64),
    /// Against one side: (axis, sign).
    Side(usize, f64),
    /// On the top, at one end: (axis, sign).
    OnEnd(usize, f64),
    /// As [`Relation::Side`], the given gap (metres, under [`GAP`]) from the target's face:
    /// what fits on the surface the target rests on only closer to it than [`GAP`].
    SideGap(usize, f64, f64),
    /// Next to, beside, by, near: the side of the target nearest the object.
    NextTo,
    /// Next to the target on the surface it rests on (`on X2 next to X3`, the variable of
    /// the surface given): the side of the target toward the surface's centre, so the
    /// object stays on the surface.
    NextToOn(usize),
    /// Between two targets on the surface they rest on (`on X2 between X3 and X4`, the
    /// variable of the surface given).
    BetweenOn(usize),
    /// To its place, standing on the same level (`to X2`, `at X2`).
    To,
    /// Straight toward it until 5 cm from it, along the axis they are apart on, nothing
    /// else changed, when they overlap across that axis; else against its nearest face
    /// (`all the way to X2`, `right up to X2`).
    UpTo,
    /// As [`Relation::UpTo`] but touching (`against X2`, `flush against X2`, `until it
    /// touches X2`): a person who says "against" means contact, and touching is not
    /// colliding.
    Against,
    /// Along (axis, sign) until touching the target (`slide X1 right until it touches
    /// X2`): the reader has checked that the target lies straight that way.
    AgainstAlong(usize, f64),
    /// Between two targets.
    Between,
    /// Away from by an amount.
    Away(f64),
    /// Away from the face of the target the subject stands alongside, straight out from
    /// it along the axis given, by the amount (a chair pulled away from the long side of
    /// a table).
    AwayFromFace(f64, usize),
    /// Closer by an amount, or halfway with none.
    Closer(Option<f64>),
    /// Onto the floor beside it (`off X2`).
    Off,
    /// At a chair's place (`at X2's place`): on the table it is drawn up to, in front of
    /// it ([`super::Known::at_its_seat`]); the variable of that table when it is named
    /// (`on X3 at X2's place`).
    AtSeat(Option<usize>),
    /// Mirrored through it, along the axis the object is offset most (`to the other side of
    /// X2`).
    OtherSide,
}

impl Relation {
    /// Whether the relation sets all three coordinates of its subject from its targets
    /// (on, under, beside, between, to, off): where an earlier clause left the subject
    /// then matters only for which side it goes, so those moves are forgotten rather than
    /// carried into every term (`take X1 off X2 and put it next to X3`).
    #[must_use]
    pub(crate) fn places(self) -> bool {
        matches!(
            self,
            Relation::On
                | Relation::Under
                | Relation::Side(..)
                | Relation::OnEnd(..)
                | Relation::SideGap(..)
                | Relation::NextTo
                | Relation::NextToOn(_)
                | Relation::BetweenOn(_)
                | Relation::To
                | Relation::Between
                | Relation::Off
        )
    }
}

/// Where a subject put beside a target (next to, a side, to, between) stands.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Level {
    /// On the target's level (its bottom).
    Target,
    /// On the floor: floor furniture beside something on a desk; anything beside
    /// something that hangs on a wall.
    Floor,
    /// On the top of this variable, the surface the target rests on (`on X2 next to X3`).
    Surface(usize),
    /// On the target's level moved down by this much (metres): the top of the surface
    /// under a target that floats a little above it (as in ProcTHOR's data).
    Under(f64),
}

/// The vector that takes subject `s` into `relation` with `targets`, standing on `level`
/// where it is put beside a target.
pub(crate) fn vector(
    relation: Relation,
    s: usize,
    targets: &[usize],
    steps: &Steps,
    floor: &Expr,
    level: Level,
) -> Option<Expr> {
    let t = *targets.first()?;
    let b = |attribute: &str| boxed(t, attribute, steps);
    let a = |attribute: &str| boxed(s, attribute, steps);
    let centre = |axis_index: usize| along(sub(b("center"), a("center")), axis_index);
    let level = match level {
        Level::Floor => scaled_axis(sub(floor.clone(), dot(a("min"), axis(1))), 1),
        Level::Target => along(sub(b("min"), a("min")), 1),
        Level::Surface(y) => on_surface_level(s, t, y, steps),
        Level::Under(d) => add(along(sub(b("min"), a("min")), 1), scaled_axis(num(-d), 1)),
    };
    Some(match relation {
        Relation::On => sum([
            scaled_axis(sub(dot(b("max"), axis(1)), dot(a("min"), axis(1))), 1),
            centre(0),
            centre(2),
        ]),
        // On the level the target stands on (the floor under a table, a table top under a
        // bowl), or the floor under what hangs on a wall; whether it fits is checked once
        // placed (`Near::Under`).
        Relation::Under => sum([level.clone(), centre(0), centre(2)]),
        // On the bottom inside its walls (whether it fits is checked once placed,
        // `Near::Inside`).
        Relation::In(floor) => sum([
            along(sub(b("min"), a("min")), 1),
            scaled_axis(num(floor), 1),
            centre(0),
            centre(2),
        ]),
        Relation::Side(e, sign) => side(s, t, steps, e, sign, level, GAP),
        Relation::OnEnd(e, sign) => {
            // On the top, centred across, its face GAP inside the target's face at that end
            // — less where the two are nearly as long, so it never goes the other way.
            let slack = div(
                sub(dot(b("size"), axis(e)), dot(a("size"), axis(e))),
                num(2.0),
            );
            let inset = call("min", vec![num(GAP), call("max", vec![num(0.0), slack])]);
            let end = if sign > 0.0 {
                sub(sub(dot(b("max"), axis(e)), inset), dot(a("max"), axis(e)))
            } else {
                sub(add(dot(b("min"), axis(e)), inset), dot(a("min"), axis(e)))
            };
            sum([
                scaled_axis(sub(dot(b("max"), axis(1)), dot(a("min"), axis(1))), 1),
                centre(2 - e),
                scaled_axis(end, e),
            ])
        }
        Relation::SideGap(e, sign, gap) => side(s, t, steps, e, sign, level, gap),
        Relation::NextTo => next_to(s, t, steps, level, boxed(s, "center", steps), GAP),
        Relation::NextToOn(surface) => next_to(
            s,
            t,
            steps,
            on_surface_level(s, t, surface, steps),
            boxed(surface, "center", steps),
            GAP,
        ),
        Relation::BetweenOn(surface) => {
            let c = boxed(*targets.get(1)?, "center", steps);
            let mid = sub(div(add(b("center"), c), num(2.0)), a("center"));
            let level = on_surface_level(s, t, surface, steps);
            sum([along(mid.clone(), 0), along(mid, 2), level])
        }
        Relation::To => sum([centre(0), centre(2), level]),
        Relation::UpTo => up_to(s, t, steps, GAP),
        Relation::Against => up_to(s, t, steps, 0.0),
        Relation::AgainstAlong(e, sign) => {
            let gap = if sign > 0.0 {
                sub(dot(b("min"), axis(e)), dot(a("max"), axis(e)))
            } else {
                sub(dot(b("max"), axis(e)), dot(a("min"), axis(e)))
            };
            scaled_axis(gap, e)
        }
        Relation::Between => {
            let c = boxed(*targets.get(1)?, "center", steps);
            let mid = sub(div(add(b("center"), c), num(2.0)), a("center"));
            sum([along(mid.clone(), 0), along(mid, 2), level])
        }
        Relation::Away(amount) => {
            let f = flat(sub(middle(targets, steps), a("center")));
            neg(mul(num(amount), div(f.clone(), call("abs", vec![f]))))
        }
        Relation::AwayFromFace(amount, e) => {
            // Straight out along axis `e`, on the subject's side of the target.
            let d = dot(sub(a("center"), b("center")), axis(e));
            scaled_axis(mul(num(amount), div(d.clone(), call("abs", vec![d]))), e)
        }
        Relation::Closer(amount) => {
            let f = flat(sub(middle(targets, steps), a("center")));
            match amount {
                Some(x) => mul(num(x), div(f.clone(), call("abs", vec![f]))),
                None => mul(num(0.5), f),
            }
        }
        Relation::Off => {
            // Beside the target, on the floor.
            let down = scaled_axis(sub(floor.clone(), dot(a("min"), axis(1))), 1);
            let beside = next_to(s, t, steps, num(0.0), boxed(s, "center", steps), GAP);
            add(beside, down)
        }
        Relation::OtherSide => other_side(s, t, steps),
        // Measured from the scene by the reader ([`super::Known::at_its_seat`]).
        Relation::AtSeat(_) => return None,
    })
}

/// Against the face of target `t` on side (axis `e`, `sign`), [`GAP`] from it, centred on
/// it across, standing on `level`.
fn side(s: usize, t: usize, steps: &Steps, e: usize, sign: f64, level: Expr, gap: f64) -> Expr {
    let b = |attribute: &str| boxed(t, attribute, steps);
    let a = |attribute: &str| boxed(s, attribute, steps);
    let gap = num(gap);
    let other = 2 - e;
    let along_axis = if sign > 0.0 {
        scaled_axis(
            sub(add(dot(b("max"), axis(e)), gap), dot(a("min"), axis(e))),
            e,
        )
    } else {
        scaled_axis(
            sub(sub(dot(b("min"), axis(e)), gap), dot(a("max"), axis(e))),
            e,
        )
    };
    sum([
        along_axis,
        along(sub(b("center"), a("center")), other),
        level,
    ])
}

/// The middle of `targets` (the mean of their centres; one target's centre): what
/// "towards the loungers" goes towards, and what objects spread apart from.
pub(crate) fn middle(targets: &[usize], steps: &Steps) -> Expr {
    let total = targets
        .iter()
        .map(|&t| boxed(t, "center", steps))
        .reduce(add)
        .unwrap_or_else(|| num(0.0));
    if targets.len() > 1 {
        div(total, num(targets.len() as f64))
    } else {
        total
    }
}

/// Mirrored through target `t`, along the horizontal axis subject `s` is offset from it
/// most.
fn other_side(s: usize, t: usize, steps: &Steps) -> Expr {
    let d = sub(boxed(t, "center", steps), boxed(s, "center", steps));
    let dx = call("abs", vec![dot(d.clone(), axis(0))]);
    let dz = call("abs", vec![dot(d.clone(), axis(2))]);
    let q = step(sub(dx, dz));
    add(
        mul(q.clone(), mul(num(2.0), along(d.clone(), 0))),
        mul(sub(num(1.0), q), mul(num(2.0), along(d, 2))),
    )
}

/// The vertical move that sets subject `s` on `surface` beside `t`, which rests on it: at
/// `t`'s bottom, or at the surface's top where `t` stands above it (so a pillow's level on
/// a sofa's seat, inside the sofa's box, but never a vase's that floats over a desk).
fn on_surface_level(s: usize, t: usize, surface: usize, steps: &Steps) -> Expr {
    let bottom = call(
        "min",
        vec![
            dot(boxed(t, "min", steps), axis(1)),
            dot(boxed(surface, "max", steps), axis(1)),
        ],
    );
    scaled_axis(sub(bottom, dot(boxed(s, "min", steps), axis(1))), 1)
}

/// Several objects put on one surface, side by side in the order given, centred on it
/// along its longer horizontal axis with [`GAP`] between them: the translation of the
/// `k`-th of `subjects`.
pub(crate) fn side_by_side(subjects: &[usize], k: usize, t: usize, steps: &Steps) -> Expr {
    let b = |attribute: &str| boxed(t, attribute, steps);
    let s = subjects[k];
    let layout = |e: usize| {
        let width = |j: usize| dot(var(subjects[j], "size"), axis(e));
        let total = add(
            sum((0..subjects.len()).map(width)),
            num(GAP * (subjects.len() as f64 - 1.0)),
        );
        let before = sum((0..k).map(|j| add(width(j), num(GAP))));
        // Where its centre goes along e, minus where it is.
        let at = add(
            sub(dot(b("center"), axis(e)), div(total, num(2.0))),
            add(before, div(width(k), num(2.0))),
        );
        scaled_axis(sub(at, dot(boxed(s, "center", steps), axis(e))), e)
    };
    let centre = |e: usize| along(sub(b("center"), boxed(s, "center", steps)), e);
    let up = scaled_axis(
        sub(dot(b("max"), axis(1)), dot(boxed(s, "min", steps), axis(1))),
        1,
    );
    // Along x when the surface is wider than deep, else along z.
    let q = step(sub(dot(b("size"), axis(0)), dot(b("size"), axis(2))));
    sum([
        mul(q.clone(), add(layout(0), centre(2))),
        mul(sub(num(1.0), q), add(layout(2), centre(0))),
        up,
    ])
}

/// The move along axis `e` that puts subject `s` `gap` from the face of target `t` on
/// the side where `reference` lies (ties go to +).
fn to_face(s: usize, t: usize, steps: &Steps, e: usize, reference: &Expr, gap: f64) -> Expr {
    let b = |attribute: &str| boxed(t, attribute, steps);
    let a = |attribute: &str| boxed(s, attribute, steps);
    let p = step(dot(sub(reference.clone(), b("center")), axis(e)));
    let plus = sub(
        add(dot(b("max"), axis(e)), num(gap)),
        dot(a("min"), axis(e)),
    );
    let minus = sub(
        sub(dot(b("min"), axis(e)), num(gap)),
        dot(a("max"), axis(e)),
    );
    mul(
        add(mul(p.clone(), plus), mul(sub(num(1.0), p), minus)),
        axis(e),
    )
}

/// Straight toward the target, along the horizontal axis they are apart on (in the
/// target's proportions, as [`next_to`] chooses), until `gap` from its face.
fn up_to(s: usize, t: usize, steps: &Steps, gap: f64) -> Expr {
    let b = |attribute: &str| boxed(t, attribute, steps);
    let a = |attribute: &str| boxed(s, attribute, steps);
    let side = |e: usize| to_face(s, t, steps, e, &a("center"), gap);
    let dx = call("abs", vec![dot(sub(a("center"), b("center")), axis(0))]);
    let dz = call("abs", vec![dot(sub(a("center"), b("center")), axis(2))]);
    let q = step(sub(
        mul(dx, dot(b("size"), axis(2))),
        mul(dz, dot(b("size"), axis(0))),
    ));
    let straight = add(
        mul(q.clone(), side(0)),
        mul(sub(num(1.0), q.clone()), side(2)),
    );
    // Straight only when the two overlap across that axis (the coffee table in front of
    // the sofa); otherwise a straight move would stop beside nothing, so it goes against
    // the target's nearest face as `next to` does.
    let overlap = |e: usize| {
        step(sub(
            call("min", vec![dot(a("max"), axis(e)), dot(b("max"), axis(e))]),
            call("max", vec![dot(a("min"), axis(e)), dot(b("min"), axis(e))]),
        ))
    };
    let across = add(
        mul(q.clone(), overlap(2)),
        mul(sub(num(1.0), q), overlap(0)),
    );
    add(
        mul(across.clone(), straight),
        mul(
            sub(num(1.0), across),
            next_to(s, t, steps, num(0.0), a("center"), gap),
        ),
    )
}

/// Against the face of the target nearest the object: its x faces when the object lies
/// more to the side than in front or behind (in the target's own proportions), else its z
/// faces; on each axis the face on the object's side (ties go to +); `gap` from it; centred
/// along that face; `level` added. Which face is chosen from where `reference` lies (the
/// object's centre, or the centre of the surface both stand on).
fn next_to(s: usize, t: usize, steps: &Steps, level: Expr, reference: Expr, gap: f64) -> Expr {
    let b = |attribute: &str| boxed(t, attribute, steps);
    let a = |attribute: &str| boxed(s, attribute, steps);
    let centre = |axis_index: usize| along(sub(b("center"), a("center")), axis_index);
    let side = |e: usize| to_face(s, t, steps, e, &reference, gap);
    let dx = call(
        "abs",
        vec![dot(sub(reference.clone(), b("center")), axis(0))],
    );
    let dz = call(
        "abs",
        vec![dot(sub(reference.clone(), b("center")), axis(2))],
    );
    let q = step(sub(
        mul(dx, dot(b("size"), axis(2))),
        mul(dz, dot(b("size"), axis(0))),
    ));
    sum([
        mul(q.clone(), add(side(0), centre(2))),
        mul(sub(num(1.0), q), add(side(2), centre(0))),
        level,
    ])
}

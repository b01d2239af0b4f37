//! Turns: facing an object ("turn X1 to face X2", "its back to X2", "towards X2"), facing
//! the way another faces ("the same way as X2"), facing the room ("face the left wall",
//! "face the middle of the room"), turning by an angle ("45 degrees clockwise", "a
//! quarter turn to the left", "turn it around", about a named axis, as seen from below),
//! and straightening to the room's walls. Every turn about the vertical is written as the
//! difference of two headings, so it holds whatever the object's current turn.

use super::amounts::{self, DEFAULT_DEGREES};
use super::build::*;
use super::clause::Clause;
use super::reader::{mark_to_the, not_read, Direction, Produced, ReadError, Reader};
use super::relations::{boxed, Step};
use super::view::View;
use super::words::{self, Token};
use crate::expr::Expr;

/// A facing phrase: "to face X2", "so that it faces X2", "towards X2", "away from X2",
/// "its back to X2".
#[derive(Clone, Debug)]
pub(super) struct Facing {
    /// The words of the phrase before the target.
    pub range: std::ops::Range<usize>,
    /// The variable faced.
    pub target: usize,
    /// Where the target stands in the clause.
    pub target_at: usize,
    /// Whether the back, not the front, is turned to it.
    pub away: bool,
}

/// The facing phrase of a clause, if any. `it_means`: what a free "it" after the phrase
/// stands for, when it is not the subject.
pub(super) fn find_facing(c: &Clause, it_means: Option<usize>) -> Option<Facing> {
    const FORMS: &[(&[&str], bool)] = &[
        (&["so", "that", "its", "back", "is", "to"], true),
        (&["so", "its", "back", "is", "to"], true),
        (&["with", "its", "back", "facing"], true),
        (&["so", "that", "it", "faces", "away", "from"], true),
        (&["so", "it", "faces", "away", "from"], true),
        (&["to", "face", "away", "from"], true),
        (&["face", "away", "from"], true),
        (&["facing", "away", "from"], true),
        (&["with", "its", "back", "to"], true),
        (&["its", "back", "to"], true),
        (&["their", "back", "to"], true),
        (&["their", "backs", "to"], true),
        (&["so", "that", "it", "is", "facing"], false),
        (&["so", "that", "it's", "facing"], false),
        (&["so", "it's", "facing"], false),
        (&["so", "it", "is", "facing"], false),
        (&["so", "that", "it", "faces"], false),
        (&["so", "that", "they", "face"], false),
        (&["so", "it", "faces"], false),
        (&["to", "face"], false),
        (&["to", "look", "at"], false),
        (&["facing"], false),
        (&["faces"], false),
        (&["face"], false),
    ];
    for (words, away) in FORMS {
        if let Some(i) = c.find(words) {
            if let Some((t, v)) = c.variable_after(i + words.len()) {
                return Some(Facing {
                    range: i..t,
                    target: v,
                    target_at: t,
                    away: *away,
                });
            }
            let t = i + words.len();
            if let (Some(v), Some("it")) = (it_means, c.word(t)) {
                if c.free(t) && c.word(t + 1).is_none() {
                    return Some(Facing {
                        range: i..t,
                        target: v,
                        target_at: t,
                        away: *away,
                    });
                }
            }
        }
    }
    None
}

/// The target at `at` and those listed after it ("face X2 and X3", "X2, X3 and X4": what
/// a plural names), marked read: several are faced by their middle.
fn more_targets(c: &mut Clause, first: usize, at: usize) -> Vec<usize> {
    let mut targets = vec![first];
    let mut k = at + 1;
    while (c.words_at(k, &["and"]) || matches!(c.token(k), Some(Token::Separator))) && c.free(k + 1)
    {
        let Some(Token::Variable(v)) = c.token(k + 1) else {
            break;
        };
        targets.push(*v);
        c.mark(k..k + 2);
        k += 2;
    }
    targets
}

/// "turn X1 towards X2" (to face it) or "turn X1's back to X2" (templated "turn X1 back
/// to X2": facing away), read as a facing phrase.
fn turned_to(c: &Clause) -> Option<Facing> {
    for w in ["towards", "toward"] {
        if let Some(i) = c.find(&[w]) {
            if let Some((t, v)) = c.variable_after(i + 1) {
                return Some(Facing {
                    range: i..t,
                    target: v,
                    target_at: t,
                    away: false,
                });
            }
        }
    }
    let i = c.find(&["back", "to"])?;
    let (t, v) = c.variable_after(i + 2)?;
    Some(Facing {
        range: i..t,
        target: v,
        target_at: t,
        away: true,
    })
}

/// The heading of a horizontal direction about the vertical: θ with +θ about +Y taking +Z
/// toward +X, so θ = atan2(x, z).
fn heading(v: Expr) -> Expr {
    call("atan2", vec![dot(v.clone(), axis(0)), dot(v, axis(2))])
}

/// A turn by `d` degrees, in radians.
fn degrees_of(d: f64) -> Expr {
    degrees(d)
}

/// The direction subject `s` faces when it faces the room: the named wall (`side`) when
/// `wall` is said with a side, the nearest wall when `wall` is said alone (away from the
/// room's centre, along the axis it is nearer a wall on), else the room's centre.
fn room_direction(s: usize, wall: bool, side: Option<Direction>) -> Expr {
    match (wall, side) {
        // A named wall: its direction.
        (true, Some((e, sign))) => scaled_axis(num(sign), e),
        // The nearest wall: away from the room's centre, along the axis it is nearer a
        // wall on.
        (true, None) => {
            let off = sub(var(s, "center"), room("center"));
            let slack = |e: usize| {
                sub(
                    div(dot(sub(room("max"), room("min")), axis(e)), num(2.0)),
                    call("abs", vec![dot(off.clone(), axis(e))]),
                )
            };
            let x_nearer = step(sub(slack(2), slack(0)));
            add(
                mul(x_nearer.clone(), along(off.clone(), 0)),
                mul(sub(num(1.0), x_nearer), along(off, 2)),
            )
        }
        // The room's centre.
        _ => sub(room("center"), var(s, "center")),
    }
}

/// "about the x axis", "around z", "in the e1 e2 plane": the rotation plane (default:
/// about the vertical, `e3 ^ e1`).
fn rotation_plane(c: &mut Clause) -> (usize, usize) {
    if let Some(i) = c.find(&["axis"]) {
        if i > 0 {
            let name = c.word(i - 1).unwrap_or("");
            let plane = match name {
                "x" | "e1" => Some((1, 2)),
                "y" | "e2" | "vertical" => Some((2, 0)),
                "z" | "e3" => Some((0, 1)),
                _ => None,
            };
            if let Some(p) = plane {
                c.mark(i - 1..i + 1);
                for k in (i.saturating_sub(3)..i - 1).rev() {
                    if matches!(c.word(k), Some("about" | "around" | "along" | "the" | "on")) {
                        c.mark(k..k + 1);
                    }
                }
                return p;
            }
        }
    }
    (2, 0)
}

/// How far a turn goes, in degrees, before its sense is read: the amount named, else a
/// half turn for "around", "round", "over" and "flip" (those words read), else
/// [`DEFAULT_DEGREES`].
fn turn_degrees(c: &mut Clause) -> f64 {
    let amount = amounts::angle(c);
    let has = |c: &Clause, w: &str| c.find(&[w]);
    let degrees = match amount {
        Some(a) => a,
        None if has(c, "around").is_some()
            || has(c, "round").is_some()
            || has(c, "over").is_some() =>
        {
            180.0
        }
        None if c.word(0).is_some_and(|w| w == "flip") => 180.0,
        None => DEFAULT_DEGREES,
    };
    for w in ["around", "round", "over"] {
        if let Some(i) = has(c, w) {
            c.mark(i..i + 1);
        }
    }
    degrees
}

/// The turn of `degrees` with its sense read: counter-clockwise or to the left is +,
/// clockwise or to the right −, the sense reversed when seen from below; typos of the turn
/// words ("clockwsie") corrected.
fn turn_sense(c: &mut Clause, mut degrees: f64) -> f64 {
    for i in 0..c.len() {
        if let Some(fixed) = c.word(i).filter(|_| c.free(i)).and_then(words::correct) {
            if matches!(fixed, "clockwise" | "counterclockwise" | "anticlockwise") {
                c.replace(i, fixed);
            }
        }
    }
    let has = |c: &Clause, w: &str| c.find(&[w]);
    let counter = ["counterclockwise", "anticlockwise", "ccw"]
        .iter()
        .find_map(|w| has(c, w));
    let clockwise = ["clockwise", "cw"].iter().find_map(|w| has(c, w));
    let view = c.view;
    if let Some(i) = counter {
        c.mark(i..i + 1);
        degrees = degrees.abs();
    } else if let Some(i) = clockwise {
        c.mark(i..i + 1);
        degrees = -degrees.abs();
    } else if let Some(i) = has(c, "left") {
        c.mark(i..i + 1);
        mark_to_the(c, i);
        degrees = degrees.abs();
    } else if let Some(i) = has(c, "right") {
        c.mark(i..i + 1);
        mark_to_the(c, i);
        degrees = -degrees.abs();
    }
    if view == Some(View::Below) && (counter.is_some() || clockwise.is_some()) {
        // Seen from below, clockwise is counter-clockwise from above.
        degrees = -degrees;
    }
    degrees
}

/// How much of the way to a target's centre a kept facing adds to the way to its nearest
/// point ([`Reader::keep_facing`]): enough to decide within the footprint, too little to
/// matter outside it.
const FACE_CENTRE_SHARE: f64 = 0.001;
impl Reader<'_> {
    /// A turn: to face what `facing` names, else the same way as another object, else the
    /// room, else towards an object or with the back to it, else by an angle.
    pub(super) fn rotate(
        &mut self,
        c: &mut Clause,
        facing: Option<Facing>,
        text: &str,
    ) -> Result<Produced, ReadError> {
        if let Some(turned) = self.face_each_other(c, text) {
            return turned;
        }
        if let Some(f) = facing {
            return self.face(c, f, text);
        }
        if let Some(turned) = self.same_way_as(c, text) {
            return turned;
        }
        if let Some(turned) = self.face_room(c, text) {
            return turned;
        }
        if let Some(f) = turned_to(c) {
            return self.face(c, f, text);
        }
        self.turn_by_angle(c, text)
    }

    /// Each subject (the variables before the phrase) turned about the vertical so that
    /// its front (or back) points at the target, both where earlier clauses left them.
    fn face(&mut self, c: &mut Clause, f: Facing, text: &str) -> Result<Produced, ReadError> {
        c.mark(f.range.clone());
        c.mark(f.target_at..f.target_at + 1);
        let targets = more_targets(c, f.target, f.target_at);
        let subjects = self.subjects(c, Some(f.range.start));
        if subjects.is_empty() || subjects.iter().any(|s| targets.contains(s)) {
            return Err(not_read(text, text));
        }
        self.last_subjects = subjects.clone();
        // "turn X1 slightly towards X2", "30 degrees towards X2", "so it faces more
        // towards X2": that far round towards facing it, never past it.
        let mut limit = super::amounts::angle(c);
        if let Some(i) = c.find(&["more"]).filter(|&i| c.free(i)) {
            c.mark(i..i + 1);
            limit = limit.or(Some(super::amounts::BIT_DEGREES));
        }
        for i in 0..c.len() {
            if matches!(
                c.word(i),
                Some(
                    "around"
                        | "round"
                        | "so"
                        | "that"
                        | "is"
                        | "it"
                        | "them"
                        | "they"
                        | "are"
                        | "faces"
                        | "face"
                )
            ) {
                c.mark(i..i + 1);
            }
        }
        // "keep it facing X2"; "turn it to face X2 and X3" (the windows along a wall):
        // square on to what is faced, towards the nearest point of the box around it.
        if c.keep_facing || (targets.len() > 1 && !f.away && limit.is_none()) {
            return Ok(subjects
                .iter()
                .map(|&s| (s, self.keep_facing(s, &targets)))
                .collect());
        }
        Ok(subjects
            .iter()
            .map(|&s| (s, self.turn_to_face(s, &targets, f.away, limit)))
            .collect())
    }

    /// The turn of subject `s` about the vertical so that its front (or back, `away`)
    /// points at `targets` (the middle of several), at most `limit` degrees the short way round. +θ about +Y takes
    /// +Z toward +X, so θ = atan2(dx, dz); away adds a half turn. Both where earlier
    /// clauses left them ("move X1 next to X2 and turn it to face X2" faces X2 from beside
    /// it).
    fn turn_to_face(&self, s: usize, targets: &[usize], away: bool, limit: Option<f64>) -> Step {
        let d = sub(
            super::relations::middle(targets, &self.steps),
            boxed(s, "center", &self.steps),
        );
        let mut angle = sub(heading(d), heading(var(s, "front")));
        if away {
            angle = add(angle, name("pi"));
        }
        if let Some(most) = limit {
            // The turn the short way round (−π … π), at most `most` degrees.
            let short = call(
                "atan2",
                vec![call("sin", vec![angle.clone()]), call("cos", vec![angle])],
            );
            let bound = degrees(most.abs());
            angle = call(
                "max",
                vec![neg(bound.clone()), call("min", vec![short, bound])],
            );
        }
        Step::Turn(rotor(angle, (2, 0)))
    }

    /// "…, and keep it facing X2": the turn of subject `s` that leaves its front square on
    /// to `targets` where earlier clauses left them — towards the nearest point of the
    /// box around their footprints, as a chair faces the long side of its table, not the
    /// table's far-off centre (which is what "turn it to face X2" faces), and a chair
    /// turned to face the windows faces the wall they are in. A thousandth of the way
    /// to their middle is added, so a subject within the box still faces its middle.
    fn keep_facing(&self, s: usize, targets: &[usize]) -> Step {
        let at = |e: usize| dot(boxed(s, "center", &self.steps), axis(e));
        // The box around every target, along axis `e`.
        let bound = |attribute: &str, f: &str, e: usize| {
            targets
                .iter()
                .map(|&t| dot(boxed(t, attribute, &self.steps), axis(e)))
                .reduce(|a, b| call(f, vec![a, b]))
                .unwrap_or_else(|| at(e))
        };
        let nearest = |e: usize| {
            call(
                "max",
                vec![
                    bound("min", "min", e),
                    call("min", vec![at(e), bound("max", "max", e)]),
                ],
            )
        };
        let to_centre = sub(
            super::relations::middle(targets, &self.steps),
            boxed(s, "center", &self.steps),
        );
        let way = sum([
            scaled_axis(sub(nearest(0), at(0)), 0),
            scaled_axis(sub(nearest(2), at(2)), 2),
            mul(num(FACE_CENTRE_SHARE), to_centre),
        ]);
        Step::Turn(rotor(sub(heading(way), heading(var(s, "front"))), (2, 0)))
    }

    /// "turn X1 and X2 to face each other": each of two turned to face the other. `None`
    /// when the clause does not say so.
    fn face_each_other(
        &mut self,
        c: &mut Clause,
        text: &str,
    ) -> Option<Result<Produced, ReadError>> {
        let at = (1..c.len()).find(|&i| {
            (c.words_at(i, &["each", "other"]) || c.words_at(i, &["one", "another"]))
                && matches!(c.word(i - 1), Some("face" | "faces" | "facing"))
                && c.free(i - 1)
        })?;
        let start = if at >= 2 && c.words_at(at - 2, &["to"]) {
            at - 2
        } else {
            at - 1
        };
        c.mark(start..at + 2);
        let subjects = self.subjects(c, Some(start));
        let [a, b] = subjects.as_slice() else {
            return Some(Err(not_read(text, text)));
        };
        let (a, b) = (*a, *b);
        self.last_subjects = subjects.clone();
        Some(Ok(vec![
            (a, self.turn_to_face(a, &[b], false, None)),
            (b, self.turn_to_face(b, &[a], false, None)),
        ]))
    }

    /// "face the same way as X2", "in the same direction as X2": its front along X2's.
    /// `None` when the clause says neither.
    fn same_way_as(&mut self, c: &mut Clause, text: &str) -> Option<Result<Produced, ReadError>> {
        for words in [
            &["the", "same", "way", "as"][..],
            &["the", "same", "direction", "as"],
            &["same", "way", "as"],
            &["same", "direction", "as"],
        ] {
            if let Some(i) = c.find(words) {
                if let Some((t, v)) = c.variable_after(i + words.len()) {
                    c.mark(i..t + 1);
                    c.mark_every(&[
                        "to", "face", "faces", "facing", "point", "in", "so", "that", "it", "is",
                    ]);
                    return Some(self.turn_each(c, i, text, |s| {
                        sub(heading(var(v, "front")), heading(var(s, "front")))
                    }));
                }
            }
        }
        None
    }

    /// "face the left wall", "face the middle of the room", "face the wall" (the nearest):
    /// `None` when the clause names no wall, centre or room, or the scene has no room.
    fn face_room(&mut self, c: &mut Clause, text: &str) -> Option<Result<Produced, ReadError>> {
        let i = ["face", "faces", "facing"]
            .iter()
            .find_map(|w| c.find(&[w]))?;
        let wall = c.find(&["wall"]);
        let centre = ["centre", "center", "middle"]
            .iter()
            .find_map(|w| c.find(&[w]));
        let room_word = c.find(&["room"]);
        if !((wall.is_some() || centre.is_some() || room_word.is_some()) && self.facts.known.room) {
            return None;
        }
        c.mark(i..i + 1);
        let side = [
            ("left", (0usize, -1.0)),
            ("right", (0, 1.0)),
            ("back", (2, -1.0)),
            ("front", (2, 1.0)),
        ]
        .iter()
        .find_map(|(w, d)| c.find(&[w]).map(|k| (k, *d)));
        for k in [wall, centre, room_word].into_iter().flatten() {
            c.mark(k..k + 1);
        }
        if let Some((k, _)) = side {
            c.mark(k..k + 1);
        }
        // ("turn them around so they face the back wall": what they face says how far.)
        c.mark_every(&[
            "to", "of", "the", "so", "that", "it", "is", "towards", "toward", "they", "are",
            "around", "round",
        ]);
        let (wall, side) = (wall.is_some(), side.map(|(_, d)| d));
        Some(self.turn_each(c, i, text, |s| {
            sub(
                heading(room_direction(s, wall, side)),
                heading(var(s, "front")),
            )
        }))
    }

    /// A turn by an angle ("45 degrees clockwise", "a quarter turn to the left", "turn it
    /// around"), about the vertical or a named axis.
    fn turn_by_angle(&mut self, c: &mut Clause, text: &str) -> Result<Produced, ReadError> {
        let subjects = self.required_subjects(c, text)?;
        let plane = rotation_plane(c);
        let degrees = turn_degrees(c);
        let degrees = turn_sense(c, degrees);
        Ok(subjects
            .iter()
            .map(|&s| (s, Step::Turn(rotor(degrees_of(degrees), plane))))
            .collect())
    }

    /// Turns each subject (the variables before token `cut`) about the vertical by the
    /// angle `angle(subject)`.
    fn turn_each(
        &mut self,
        c: &mut Clause,
        cut: usize,
        text: &str,
        angle: impl Fn(usize) -> Expr,
    ) -> Result<Produced, ReadError> {
        let subjects = self.subjects(c, Some(cut));
        if subjects.is_empty() {
            return Err(not_read(text, text));
        }
        self.last_subjects = subjects.clone();
        Ok(subjects
            .iter()
            .map(|&s| (s, Step::Turn(rotor(angle(s), (2, 0)))))
            .collect())
    }

    /// "straighten X1", "square it with the walls": each subject's heading snapped to the
    /// nearest multiple of 90° of the room (from its known turn).
    pub(super) fn straighten(&mut self, c: &mut Clause, text: &str) -> Result<Produced, ReadError> {
        let subjects = self.required_subjects(c, text)?;
        for i in 0..c.len() {
            if matches!(
                c.word(i),
                Some(
                    "up" | "with"
                        | "to"
                        | "the"
                        | "walls"
                        | "wall"
                        | "room"
                        | "square"
                        | "out"
                        | "align"
                        | "aligned"
                )
            ) {
                c.mark(i..i + 1);
            }
        }
        // Snap each heading to the nearest multiple of 90° of the room.
        Ok(subjects
            .iter()
            .map(|&s| {
                let yaw = self.facts.known.yaw.get(s).copied().unwrap_or(0.0);
                let delta = (yaw / 90.0).round() * 90.0 - yaw;
                (s, Step::Turn(rotor(degrees_of(delta), (2, 0))))
            })
            .collect())
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{outcome, standing, turns};

    #[test]
    fn facing_turns_the_front_to_the_target_and_away_turns_the_back() {
        // X2 straight to the right of X1 (+X): facing it is a quarter turn from +Z.
        let boxes = [
            standing([0.5, 0.8, 0.5], 0.0, 0.0),
            standing([0.5, 1.0, 0.5], 2.0, 0.0),
        ];
        for q in [
            "turn X1 to face X2",
            "turn X1 towards X2",
            "rotate X1 so that it faces X2",
        ] {
            assert!((turns(q, &boxes)[0] - 90.0).abs() < 1e-9, "{q}");
        }
        for q in ["turn X1 back to X2", "turn X1 to face away from X2"] {
            assert!((turns(q, &boxes)[0].abs() - 90.0).abs() < 1e-9, "{q}");
            assert!(turns(q, &boxes)[0] < 0.0, "{q}");
        }
        // Facing itself is not read.
        assert!(outcome("turn X1 to face X1", &boxes, true).is_err());
    }

    #[test]
    fn facing_the_room_uses_its_walls_and_centre() {
        // X1 right of the room's centre and nearer the right wall than the front or back.
        let boxes = [standing([0.5, 0.8, 0.5], 2.0, 0.5)];
        let turn = |q: &str| turns(q, &boxes)[0];
        assert!((turn("make X1 face the left wall") + 90.0).abs() < 1e-9);
        assert!((turn("make X1 face the back wall").abs() - 180.0).abs() < 1e-9);
        // The nearest wall: the right one, straight away from the centre along x.
        assert!((turn("turn X1 to face the wall") - 90.0).abs() < 1e-9);
        let centre = (-2.0f64).atan2(-0.5).to_degrees();
        assert!((turn("turn X1 to face the middle of the room") - centre).abs() < 1e-9);
    }

    #[test]
    fn angles_take_their_sense_from_the_words_and_the_view() {
        let boxes = [standing([0.5, 0.8, 0.5], 0.0, 0.0)];
        let turn = |q: &str| turns(q, &boxes)[0];
        assert!((turn("rotate X1 45 degrees clockwise") + 45.0).abs() < 1e-9);
        assert!((turn("rotate X1 45 degrees counterclockwise") - 45.0).abs() < 1e-9);
        assert!((turn("turn X1 a quarter turn to the left") - 90.0).abs() < 1e-9);
        assert!((turn("turn X1 30 degrees clockwsie") + 30.0).abs() < 1e-9);
        assert!((turn("rotate X1 45 degrees clockwise as seen from below") - 45.0).abs() < 1e-9);
        assert!((turn("turn X1 around").abs() - 180.0).abs() < 1e-9);
        assert!((turn("turn X1") - 90.0).abs() < 1e-9);
    }

    #[test]
    fn the_same_way_as_another_takes_its_heading() {
        let boxes = [
            standing([0.5, 0.8, 0.5], 0.0, 0.0),
            standing([0.5, 1.0, 0.5], 2.0, 1.0),
        ];
        // Both face +Z: nothing turns.
        assert!(turns("turn X1 to face the same way as X2", &boxes)[0].abs() < 1e-9);
    }
}

//! Reading one clause: its verb, subjects and what it asks (a move, a relation, a place in
//! the room, a turn, a scale, a swap, a row), marking every word it reads. A clause with a
//! word left unread is refused — the translator never acts on part of an instruction.

use super::amounts::{self, Length, DEFAULT_DEGREES, DEFAULT_METRES};
use super::build::*;
use super::clause::Clause;
use super::relations::{self, boxed, Level, Relation, Step, Steps, GAP};
use super::room::{self, Place};
use super::view::{view_at, View};
use super::words::{self, Action, Token};
use crate::expr::Expr;
use crate::translate::Near;
use std::collections::BTreeMap;

/// What the translator knows besides the query: how many variables, and what is known of
/// their objects ([`super::Known`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Facts<'k> {
    /// Variables bound.
    pub variables: usize,
    /// What is known of them.
    pub known: &'k super::Known<'k>,
}

/// The state carried from clause to clause.
pub(crate) struct Reader<'a> {
    pub facts: &'a Facts<'a>,
    pub steps: Steps,
    /// Per variable, what it was last put next to or between.
    pub near: BTreeMap<usize, Near>,
    last_subjects: Vec<usize>,
    /// The objects the last relation was to ("next to X2"): what "it" means after "face"
    /// when "it" is the clause's subject ("… and turn it to face it").
    last_targets: Vec<usize>,
    last_action: Option<Action>,
    last_steps: Vec<Step>,
}

/// The message for words the translator could not read.
pub(crate) fn not_read(unread: &str, clause: &str) -> String {
    if unread == clause || unread.is_empty() {
        format!(
            "the offline translator could not read \"{}\"; rephrase it, or use a language model (openai:MODEL, ollama:MODEL, or offline+openai:MODEL to ask one only for what the offline translator cannot read)",
            clause.trim()
        )
    } else {
        format!(
            "the offline translator could not read \"{unread}\" in \"{}\"; rephrase it, or use a language model (openai:MODEL, ollama:MODEL, or offline+openai:MODEL to ask one only for what the offline translator cannot read)",
            clause.trim()
        )
    }
}

/// A direction as (axis 0..2, sign).
type Direction = (usize, f64);

/// A verb form: `moving` → move, `turned` → turn, one-letter typos corrected.
fn verb_of(w: &str) -> Option<(Action, Option<Direction>)> {
    if let Some(v) = words::verb(w) {
        return Some(v);
    }
    if let Some(stem) = w.strip_suffix("ing") {
        for candidate in [stem.to_string(), format!("{stem}e")] {
            if let Some(v) = words::verb(&candidate) {
                return Some(v);
            }
        }
    }
    words::correct(w).and_then(words::verb)
}

impl<'a> Reader<'a> {
    pub fn new(facts: &'a Facts<'a>) -> Self {
        Self {
            facts,
            steps: Steps::new(),
            near: BTreeMap::new(),
            last_subjects: Vec::new(),
            last_targets: Vec::new(),
            last_action: None,
            last_steps: Vec::new(),
        }
    }

    /// Reads one clause and records its steps.
    pub fn clause(&mut self, c: &mut Clause) -> Result<(), String> {
        // Discourse around the instruction: greetings and request frames at the start,
        // thanks and sign-offs at the end (crate::discourse).
        c.mark_discourse();
        c.view = mark_view(c);
        c.until_blocked = amounts::until_blocked(c);
        super::idioms::rewrite(c);
        // "have X1 and X2 trade places": the causative `have` before the objects.
        if let Some(i) = (0..c.len()).find(|&i| c.free(i)) {
            if c.words_at(i, &["have"]) && c.variable_after(i + 1).is_some() {
                c.mark(i..i + 1);
            }
        }
        // A clause of fillers only ("…, thanks"): nothing to do.
        if c.unread().is_empty() {
            return Ok(());
        }
        let produced = if let Some(repeated) = self.repeat(c) {
            repeated
        } else {
            self.read(c)?
        };
        let unread = c.unread();
        if !unread.is_empty() {
            return Err(not_read(&unread.join(" "), &c.text()));
        }
        if let Some(&(first, _)) = produced.first() {
            self.last_steps = produced
                .iter()
                .filter(|(v, _)| *v == first)
                .map(|(_, s)| s.clone())
                .collect();
        }
        for (v, step) in produced {
            if v >= self.facts.variables {
                return Err(format!(
                    "the instruction names X{} but only {} objects are named",
                    v + 1,
                    self.facts.variables
                ));
            }
            self.steps.entry(v).or_default().push(step);
        }
        Ok(())
    }

    /// The verb of the clause, marked read; particles (`pick up`, `line up`) too.
    fn verb(&mut self, c: &mut Clause) -> Option<(Action, Option<Direction>, usize)> {
        for i in 0..c.len() {
            let Some(w) = c.word(i).filter(|_| c.free(i)) else {
                continue;
            };
            // "back" or "down" as verbs do not exist; "set down", "put back" are particles.
            if let Some((action, implied)) = verb_of(w) {
                c.mark(i..i + 1);
                if matches!(action, Action::Take | Action::Align) && c.words_at(i + 1, &["up"]) {
                    c.mark(i + 1..i + 2);
                }
                return Some((action, implied, i));
            }
        }
        None
    }

    /// The subjects: the unread variables before `cut` (all with none), else the pronoun's
    /// objects (`it`, `them`, `both`).
    /// The clause's subjects (see [`Self::subjects`]), remembered for "it" and "them" in
    /// later clauses; a clause whose verb needs a subject and has none is not read.
    fn required_subjects(&mut self, c: &mut Clause, text: &str) -> Result<Vec<usize>, String> {
        let subjects = self.subjects(c, None);
        if subjects.is_empty() {
            return Err(not_read(text, text));
        }
        self.last_subjects = subjects.clone();
        Ok(subjects)
    }

    fn subjects(&mut self, c: &mut Clause, cut: Option<usize>) -> Vec<usize> {
        let vars: Vec<(usize, usize)> = c
            .variables()
            .into_iter()
            .filter(|(i, _)| cut.is_none_or(|k| *i < k))
            .collect();
        let mut subjects: Vec<usize> = Vec::new();
        for &(i, v) in &vars {
            c.mark(i..i + 1);
            if !subjects.contains(&v) {
                subjects.push(v);
            }
            // "X1, X2 and X3", "both X1 and X2".
            for k in [i + 1] {
                if (c.words_at(k, &["and"]) || matches!(c.token(k), Some(Token::Separator)))
                    && vars.iter().any(|(j, _)| *j > k)
                {
                    c.mark(k..k + 1);
                }
            }
        }
        for i in 0..c.len() {
            if c.free(i)
                && cut.is_none_or(|k| i < k)
                && (matches!(
                    c.word(i),
                    Some("it" | "them" | "both" | "they" | "everything" | "these" | "those")
                ) || (matches!(c.word(i), Some("all" | "each"))
                    && c.words_at(i + 1, &["of", "them"])))
            {
                c.mark(i..i + 1);
                if c.words_at(i + 1, &["of", "them"]) {
                    c.mark(i + 1..i + 3);
                }
            }
        }
        if subjects.is_empty() {
            subjects = self.last_subjects.clone();
        }
        subjects
    }

    fn read(&mut self, c: &mut Clause) -> Result<Vec<(usize, Step)>, String> {
        let text = c.text();
        let verb = self.verb(c);
        // "face it" where "it" is the object turned: the one thing named as the last
        // relation's target (an object cannot face itself).
        let other = match self.last_targets.as_slice() {
            &[t] if !self.last_subjects.contains(&t) => Some(t),
            _ => None,
        };
        let facing = find_facing(c, other);
        let (mut action, implied) = match verb {
            Some((a, implied, _)) => (a, implied),
            None => match self.last_action {
                Some(a) => (a, None),
                None if facing.is_some() => (Action::Rotate, None),
                // "I'd like X1 on X2", "X1 to the left".
                None if !c.variables().is_empty() => (Action::Move, None),
                None => return Err(not_read(&text, &text)),
            },
        };
        let face_word = (0..c.len())
            .any(|i| c.free(i) && matches!(c.word(i), Some("face" | "faces" | "facing")));
        if (facing.is_some() || face_word) && matches!(action, Action::Scale | Action::Move) {
            // "make X1 face X2", "have X1 face X2".
            action = Action::Rotate;
        }
        self.last_action = Some(action);
        match action {
            // "take X1 off X2", "take X1 to X2": a take with a place is a move.
            Action::Take if find_relation(c).is_some() => self.move_(c, Action::Move, None, &text),
            Action::Take => {
                self.required_subjects(c, &text)?;
                // The taking itself moves nothing: a later clause says where.
                Ok(Vec::new())
            }
            Action::Swap => self.swap(c, &text),
            Action::Align => self.align(c, &text),
            Action::Rotate => self.rotate(c, facing, &text),
            Action::Scale => self.scale(c, &text),
            Action::Straighten => self.straighten(c, &text),
            Action::Centre | Action::Move => self.move_(c, action, implied, &text),
        }
    }

    /// "do the same for X2", "X2 too", "move X2 the other way", "mirror that for X2": the
    /// previous clause's steps, repeated, reversed or mirrored left–right.
    fn repeat(&mut self, c: &mut Clause) -> Option<Vec<(usize, Step)>> {
        if self.last_steps.is_empty() {
            return None;
        }
        let has = |w: &str| (0..c.len()).any(|i| c.word(i) == Some(w));
        let same = has("same") || has("likewise") || has("too") || (has("as") && has("well"));
        let opposite = has("opposite") || (has("other") && has("way")) || has("reverse");
        let mirror = has("mirror") || has("mirrored") || has("symmetrically");
        let content = (0..c.len()).any(|i| {
            matches!(c.token(i), Some(Token::Number(_)))
                || c.word(i).is_some_and(|w| {
                    words::direction(w).is_some()
                        || matches!(
                            w,
                            "on" | "onto"
                                | "next"
                                | "beside"
                                | "under"
                                | "behind"
                                | "between"
                                | "degrees"
                                | "clockwise"
                        )
                })
        });
        if !(same || opposite || mirror) || content {
            return None;
        }
        // Relations name their subject's own box: repeat only plain moves and turns.
        let plain = self.last_steps.iter().all(|s| match s {
            Step::Translate(v) => !v.to_string().contains('X'),
            Step::Turn(_) => true,
        });
        if !plain {
            return None;
        }
        let vars = c.variables();
        let single = vars.len() == 1;
        let mut subjects: Vec<usize> = vars.iter().map(|(_, v)| *v).collect();
        subjects.retain(|v| !self.last_subjects.contains(v) || single);
        if subjects.is_empty() {
            return None;
        }
        for (i, _) in &vars {
            c.mark(*i..*i + 1);
        }
        for i in 0..c.len() {
            if matches!(
                c.word(i),
                Some(
                    "same"
                        | "likewise"
                        | "too"
                        | "as"
                        | "well"
                        | "opposite"
                        | "other"
                        | "way"
                        | "reverse"
                        | "mirror"
                        | "mirrored"
                        | "symmetrically"
                        | "do"
                        | "for"
                        | "with"
                        | "that"
                        | "thing"
                        | "move"
                        | "to"
                        | "it"
                        | "this"
                        | "direction"
                )
            ) {
                c.mark(i..i + 1);
            }
        }
        let transform = |step: &Step| -> Step {
            match step {
                Step::Translate(v) if opposite => Step::Translate(neg(v.clone())),
                Step::Translate(v) if mirror => {
                    Step::Translate(sub(v.clone(), mul(num(2.0), along(v.clone(), 0))))
                }
                Step::Turn(e) if opposite || mirror => Step::Turn(reverse(e.clone())),
                other => other.clone(),
            }
        };
        self.last_subjects = subjects.clone();
        Some(
            subjects
                .iter()
                .flat_map(|&s| self.last_steps.iter().map(move |step| (s, transform(step))))
                .collect(),
        )
    }

    fn swap(&mut self, c: &mut Clause, text: &str) -> Result<Vec<(usize, Step)>, String> {
        let vars = c.variables();
        if vars.len() < 2 {
            return Err(not_read(text, text));
        }
        for i in 0..c.len() {
            if matches!(
                c.word(i),
                Some(
                    "positions"
                        | "position"
                        | "places"
                        | "place"
                        | "spots"
                        | "of"
                        | "with"
                        | "and"
                        | "around"
                        | "over"
                        | "round"
                )
            ) {
                c.mark(i..i + 1);
            }
        }
        let (a, b) = (vars[0].1, vars[1].1);
        c.mark(vars[0].0..vars[0].0 + 1);
        c.mark(vars[1].0..vars[1].0 + 1);
        self.last_subjects = vec![a, b];
        let to = |from: usize, to: usize| {
            sum([
                along(sub(var(to, "center"), var(from, "center")), 0),
                along(sub(var(to, "center"), var(from, "center")), 2),
                along(sub(var(to, "min"), var(from, "min")), 1),
            ])
        };
        Ok(vec![
            (a, Step::Translate(to(a, b))),
            (b, Step::Translate(to(b, a))),
        ])
    }

    fn align(&mut self, c: &mut Clause, text: &str) -> Result<Vec<(usize, Step)>, String> {
        let axis_named = named_axis(c);
        let with = c.find(&["with"]).or_else(|| c.find(&["to"]));
        let vars = c.variables();
        if with.is_none() && vars.len() >= 2 {
            // "line up X1, X2 and X3", "arrange them in a row": each after the first goes
            // right of the one before, level with and centred on the first.
            for i in 0..c.len() {
                if matches!(
                    c.word(i),
                    Some("and" | "in" | "a" | "row" | "line" | "next" | "to" | "each" | "other")
                ) || matches!(c.token(i), Some(Token::Separator))
                {
                    c.mark(i..i + 1);
                }
            }
            let row: Vec<usize> = vars.iter().map(|(_, v)| *v).collect();
            for (i, _) in &vars {
                c.mark(*i..*i + 1);
            }
            self.last_subjects = row.clone();
            let mut local = self.steps.clone();
            let mut out = Vec::new();
            for pair in row.windows(2) {
                let (prev, s, first) = (pair[0], pair[1], row[0]);
                let v = sum([
                    scaled_axis(
                        sub(
                            add(dot(boxed(prev, "max", &local), axis(0)), num(GAP)),
                            dot(var(s, "min"), axis(0)),
                        ),
                        0,
                    ),
                    along(sub(boxed(first, "center", &local), var(s, "center")), 2),
                    along(sub(boxed(first, "min", &local), var(s, "min")), 1),
                ]);
                local.entry(s).or_default().push(Step::Translate(v.clone()));
                out.push((s, Step::Translate(v)));
            }
            return Ok(out);
        }
        let with = with.ok_or_else(|| not_read(text, text))?;
        c.mark(with..with + 1);
        let (tpos, target) = c
            .variable_after(with + 1)
            .ok_or_else(|| not_read(text, text))?;
        c.mark(tpos..tpos + 1);
        let subjects = self.subjects(c, Some(with));
        if subjects.is_empty() {
            return Err(not_read(text, text));
        }
        self.last_subjects = subjects.clone();
        let e = axis_named.unwrap_or(0);
        Ok(subjects
            .iter()
            .map(|&s| {
                (
                    s,
                    Step::Translate(along(
                        sub(boxed(target, "center", &self.steps), var(s, "center")),
                        e,
                    )),
                )
            })
            .collect())
    }

    fn rotate(
        &mut self,
        c: &mut Clause,
        facing: Option<Facing>,
        text: &str,
    ) -> Result<Vec<(usize, Step)>, String> {
        if let Some(f) = facing {
            c.mark(f.range.clone());
            c.mark(f.target_at..f.target_at + 1);
            let subjects = self.subjects(c, Some(f.range.start));
            if subjects.is_empty() || subjects.contains(&f.target) {
                return Err(not_read(text, text));
            }
            self.last_subjects = subjects.clone();
            for i in 0..c.len() {
                if matches!(
                    c.word(i),
                    Some(
                        "around" | "round" | "so" | "that" | "is" | "it" | "them" | "they" | "are"
                    )
                ) {
                    c.mark(i..i + 1);
                }
            }
            return Ok(subjects
                .iter()
                .map(|&s| {
                    // About the vertical, so that the front (+Z) points at the target: +θ
                    // about +Y takes +Z toward +X, so θ = atan2(dx, dz); away adds a half turn.
                    // Both where earlier clauses left them ("move X1 next to X2 and turn
                    // it to face X2" faces X2 from beside it).
                    let d = sub(
                        boxed(f.target, "center", &self.steps),
                        boxed(s, "center", &self.steps),
                    );
                    let mut angle = sub(heading(d), heading(var(s, "front")));
                    if f.away {
                        angle = add(angle, name("pi"));
                    }
                    (s, Step::Turn(rotor(angle, (2, 0))))
                })
                .collect());
        }
        // "face the same way as X2", "in the same direction as X2": its front along X2's.
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
                    return self.turn_each(c, i, text, |s| {
                        sub(heading(var(v, "front")), heading(var(s, "front")))
                    });
                }
            }
        }
        // "face the left wall", "face the middle of the room", "face the wall".
        if let Some(i) = ["face", "faces", "facing"]
            .iter()
            .find_map(|w| c.find(&[w]))
        {
            let wall = c.find(&["wall"]);
            let centre = ["centre", "center", "middle"]
                .iter()
                .find_map(|w| c.find(&[w]));
            let room_word = c.find(&["room"]);
            if (wall.is_some() || centre.is_some() || room_word.is_some()) && self.facts.known.room
            {
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
                c.mark_every(&[
                    "to", "of", "the", "so", "that", "it", "is", "towards", "toward",
                ]);
                return self.turn_each(c, i, text, |s| {
                    let target = match (wall, side) {
                        // A named wall: its direction.
                        (Some(_), Some((_, (e, sign)))) => scaled_axis(num(sign), e),
                        // The nearest wall: away from the room's centre, along the axis
                        // it is nearer a wall on.
                        (Some(_), None) => {
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
                    };
                    sub(heading(target), heading(var(s, "front")))
                });
            }
        }
        // "turn X1 towards X2": to face it.
        for w in ["towards", "toward"] {
            if let Some(i) = c.find(&[w]) {
                if let Some((t, v)) = c.variable_after(i + 1) {
                    let f = Facing {
                        range: i..t,
                        target: v,
                        target_at: t,
                        away: false,
                    };
                    return self.rotate(c, Some(f), text);
                }
            }
        }
        // "turn X1's back to X2" (templated "turn X1 back to X2"): facing away.
        if let Some(i) = c.find(&["back", "to"]) {
            if let Some((t, v)) = c.variable_after(i + 2) {
                let f = Facing {
                    range: i..t,
                    target: v,
                    target_at: t,
                    away: true,
                };
                return self.rotate(c, Some(f), text);
            }
        }
        let subjects = self.required_subjects(c, text)?;
        let plane = rotation_plane(c);
        let amount = amounts::angle(c);
        let has = |c: &Clause, w: &str| c.find(&[w]);
        let mut degrees = match amount {
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
        // Typos of the turn words: "clockwsie".
        for i in 0..c.len() {
            if let Some(fixed) = c.word(i).filter(|_| c.free(i)).and_then(words::correct) {
                if matches!(fixed, "clockwise" | "counterclockwise" | "anticlockwise") {
                    c.replace(i, fixed);
                }
            }
        }
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
    ) -> Result<Vec<(usize, Step)>, String> {
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

    fn scale(&mut self, c: &mut Clause, text: &str) -> Result<Vec<(usize, Step)>, String> {
        let subjects = self.required_subjects(c, text)?;
        let factor = amounts::scale(c).ok_or_else(|| not_read(text, text))?;
        Ok(subjects
            .iter()
            .map(|&s| (s, Step::Turn(dilator(factor))))
            .collect())
    }

    fn straighten(&mut self, c: &mut Clause, text: &str) -> Result<Vec<(usize, Step)>, String> {
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

    fn move_(
        &mut self,
        c: &mut Clause,
        action: Action,
        implied: Option<(usize, f64)>,
        text: &str,
    ) -> Result<Vec<(usize, Step)>, String> {
        // A relation to an object named before: "move X2 next to it".
        let pronoun_target = if find_relation(c).is_none() {
            self.pronoun_relation(c)
        } else {
            None
        };
        if let Some((r, targets)) = pronoun_target {
            c.mark(r.clone());
            let subjects = self.subjects(c, Some(r.start));
            if subjects.is_empty() || targets.iter().any(|t| subjects.contains(t)) {
                return Err(not_read(text, text));
            }
            let kind = MARKERS
                .iter()
                .find(|(w, _)| c.words_at_any(r.start, w))
                .map(|(_, k)| *k);
            let relation = match kind {
                Some(RelKind::Fixed(rel)) => rel,
                Some(RelKind::Away) => Relation::Away(DEFAULT_METRES),
                Some(RelKind::Closer) | None => Relation::Closer(None),
            };
            return self.each(&subjects, relation, &targets, text);
        }
        // A relation to another object.
        if let Some(r) = find_relation(c) {
            let subjects = self.subjects(c, Some(r.range.start));
            if subjects.is_empty() {
                return Err(not_read(text, text));
            }
            c.mark(r.range.clone());
            for &(i, _) in &r.targets {
                c.mark(i..i + 1);
            }
            // "up onto", "back to", "over to": particles.
            if r.range.start > 0 {
                let p = r.range.start - 1;
                if matches!(c.word(p), Some("up" | "down" | "back" | "over" | "across"))
                    && c.free(p)
                {
                    c.mark(p..p + 1);
                }
            }
            let targets: Vec<usize> = r.targets.iter().map(|(_, v)| *v).collect();
            let relation = match r.kind {
                // "slide X1 right until it touches X2", "push X1 left against X2": along
                // that direction, when X2 lies straight that way.
                RelKind::Fixed(Relation::Against) => {
                    match self.direction_before(c, r.range.start) {
                        Some((e, sign)) => {
                            for &s in &subjects {
                                self.facts.known.straight_ahead(s, targets[0], e, sign)?;
                            }
                            Relation::AgainstAlong(e, sign)
                        }
                        None => Relation::Against,
                    }
                }
                RelKind::Fixed(rel) => rel,
                RelKind::Away => {
                    Relation::Away(length_value(amounts::length(c, true)).unwrap_or(DEFAULT_METRES))
                }
                RelKind::Closer => Relation::Closer(length_value(amounts::length(c, true))),
            };
            // "bring the bowl to the table": a small thing goes on the table's top.
            let to_word = c
                .word(r.range.start)
                .is_some_and(|w| matches!(w, "to" | "at"));
            let relation = if relation == Relation::To
                && to_word
                && targets.len() == 1
                && subjects
                    .iter()
                    .all(|&s| self.facts.known.small_onto(s, targets[0]))
            {
                Relation::On
            } else {
                relation
            };
            // "on X2 next to X3", "on X2 to the left of X3": one destination, beside X3 on
            // the surface X2.
            let relation = match (relation, find_relation(c)) {
                (Relation::On, Some(second)) if targets.len() == 1 => {
                    let surface = targets[0];
                    let combined = match (second.kind, second.targets.len()) {
                        (RelKind::Fixed(Relation::NextTo), 1) => Some(Relation::NextToOn(surface)),
                        (RelKind::Fixed(side @ Relation::Side(..)), 1) => Some(side),
                        (RelKind::Fixed(Relation::Between), 2) => {
                            Some(Relation::BetweenOn(surface))
                        }
                        _ => None,
                    };
                    match combined {
                        Some(rel) => {
                            // The marker, the targets and what joins them ("and").
                            let last = second.targets.last().map_or(0, |&(i, _)| i);
                            c.mark(second.range.start..last + 1);
                            let on: Vec<usize> = second.targets.iter().map(|&(_, v)| v).collect();
                            return self.each(&subjects, rel, &on, text);
                        }
                        None => relation,
                    }
                }
                (relation, _) => relation,
            };
            if relation == Relation::On && subjects.len() > 1 {
                // "put the mug and the bowl on the dresser": side by side on it.
                self.last_subjects = subjects.clone();
                return Ok(subjects
                    .iter()
                    .enumerate()
                    .map(|(k, &s)| {
                        let v = relations::side_by_side(&subjects, k, targets[0], &self.steps);
                        (s, Step::Translate(v))
                    })
                    .collect());
            }
            return self.each(&subjects, relation, &targets, text);
        }
        let subjects = self.required_subjects(c, text)?;
        // A place in the room.
        if let Some(place) = self.room_place(c, action, text)? {
            return Ok(subjects
                .iter()
                .map(|&s| (s, Step::Translate(place(s))))
                .collect());
        }
        // Directions and an amount.
        let mut dirs: Vec<(usize, f64)> = Vec::new();
        for i in 0..c.len() {
            if !c.free(i) {
                continue;
            }
            let Some(w) = c.word(i) else { continue };
            let d = words::direction(w).or_else(|| words::correct(w).and_then(words::direction));
            if let Some(d) = d {
                c.mark(i..i + 1);
                mark_to_the(c, i);
                if !dirs.contains(&d) {
                    dirs.push(d);
                }
                if c.words_at(i + 1, &["side"]) {
                    c.mark(i + 1..i + 2);
                }
            }
        }
        // "further left", "a bit more to the right": a bit.
        let more = ["further", "farther", "more"]
            .iter()
            .find_map(|w| c.find(&[w]));
        let mut amount = amounts::length(c, true);
        if let Some(i) = more {
            c.mark(i..i + 1);
            if amount.is_none() {
                amount = Some(Length::Metres(amounts::BIT_METRES));
            }
        }
        if dirs.is_empty() {
            if let Some(d) = implied {
                dirs.push(d);
            }
        }
        if dirs.is_empty() {
            return Err(not_read(text, text));
        }
        for i in 0..c.len() {
            if matches!(
                c.word(i),
                Some("over" | "across" | "along" | "on" | "its" | "way")
            ) && c.free(i)
            {
                c.mark(i..i + 1);
            }
        }
        let mut out = Vec::new();
        for &s in &subjects {
            let parts = dirs
                .iter()
                .map(|&(e, sign)| self.along(s, e, sign, amount, text))
                .collect::<Result<Vec<Expr>, String>>()?;
            out.push((s, Step::Translate(sum(parts))));
        }
        Ok(out)
    }

    /// The one horizontal direction word before `end` not read yet (`right`, `to the
    /// left`, `forward`), read; `None` when there is none or more than one.
    fn direction_before(&self, c: &mut Clause, end: usize) -> Option<(usize, f64)> {
        let found: Vec<(usize, (usize, f64))> = (0..end)
            .filter(|&i| c.free(i))
            .filter_map(|i| Some((i, words::direction(c.word(i)?)?)))
            .collect();
        match found.as_slice() {
            [(i, d)] if d.0 != 1 => {
                let (i, d) = (*i, *d);
                c.mark(i..i + 1);
                mark_to_the(c, i);
                Some(d)
            }
            _ => None,
        }
    }

    /// The move of variable `s` along axis `e` (with `sign`) by `amount`.
    fn along(
        &self,
        s: usize,
        e: usize,
        sign: f64,
        amount: Option<Length>,
        text: &str,
    ) -> Result<Expr, String> {
        let has_room = self.facts.known.room;
        Ok(match amount {
            Some(Length::Metres(m)) => scaled_axis(num(sign * m), e),
            Some(Length::Far) => room::far(s, e, sign, has_room),
            Some(Length::ToWall) if has_room && e != 1 => room::all_the_way(s, e, sign),
            Some(Length::ToWall) if e == 1 && sign < 0.0 => room::onto_floor(s, has_room),
            Some(Length::ToWall) => scaled_axis(num(sign * DEFAULT_METRES), e),
            // "as far as it will go": up to the first obstacle, measured now.
            Some(Length::UntilBlocked) => {
                let run = self.facts.known.run(s, e, sign).ok_or_else(|| {
                    format!(
                        "nothing stops X{} that way in \"{text}\": say how far",
                        s + 1
                    )
                })?;
                scaled_axis(num(sign * run), e)
            }
            None => scaled_axis(num(sign * DEFAULT_METRES), e),
        })
    }

    /// A relation whose object is a pronoun for the objects named before ("next to it",
    /// "on top of them"): the words' range, and those objects.
    fn pronoun_relation(&self, c: &Clause) -> Option<(std::ops::Range<usize>, Vec<usize>)> {
        if self.last_subjects.is_empty() {
            return None;
        }
        for (words, _) in MARKERS {
            for i in 0..c.len() {
                if c.words_at(i, words)
                    && matches!(c.word(i + words.len()), Some("it" | "them"))
                    && c.free(i + words.len())
                {
                    return Some((i..i + words.len() + 1, self.last_subjects.clone()));
                }
            }
        }
        None
    }

    /// Each subject moved into `relation` with `targets`.
    fn each(
        &mut self,
        subjects: &[usize],
        relation: Relation,
        targets: &[usize],
        text: &str,
    ) -> Result<Vec<(usize, Step)>, String> {
        self.last_subjects = subjects.to_vec();
        self.last_targets = targets.to_vec();
        let near = match (relation, targets) {
            (
                Relation::NextTo
                | Relation::NextToOn(_)
                | Relation::Side(..)
                | Relation::Against
                | Relation::AgainstAlong(..),
                &[t, ..],
            ) => Some(Near::Beside(t)),
            (Relation::Between | Relation::BetweenOn(_), &[a, b, ..]) => Some(Near::Between(a, b)),
            _ => None,
        };
        subjects
            .iter()
            .map(|&s| {
                let v = self.vector(relation, s, targets, text)?;
                match near {
                    Some(n) => self.near.insert(s, n),
                    None => self.near.remove(&s),
                };
                Ok((s, Step::Translate(v)))
            })
            .collect()
    }

    /// The vector that takes subject `s` into `relation` with `targets`, placed as a
    /// person would: beside a target that rests on a surface, on a side of it where the
    /// subject fits on that surface; on the floor where the subject is floor furniture
    /// and the target stands higher, or the target hangs on a wall.
    ///
    /// # Errors
    /// Beside a target on a surface, no side of it where the subject fits on the surface;
    /// or the words of `text` not read.
    fn vector(
        &self,
        relation: Relation,
        s: usize,
        targets: &[usize],
        text: &str,
    ) -> Result<Expr, String> {
        let floor = room::floor(self.facts.known.room);
        let t = *targets.first().ok_or_else(|| not_read(text, text))?;
        // Where an earlier clause moved the target, the scene's numbers no longer say
        // where it is.
        let unmoved = |v: usize| !self.steps.contains_key(&v);
        let as_is = unmoved(t);
        let known = self.facts.known;
        let mut level = Level::Target;
        let relation = match relation {
            Relation::NextTo if as_is => match known.side_on_support(s, t)? {
                Some(side) => {
                    let d = known.float_above_support(t);
                    if d > 0.0 {
                        level = Level::Under(d);
                    }
                    side
                }
                None => relation,
            },
            Relation::NextToOn(y) if as_is && unmoved(y) => {
                level = Level::Surface(y);
                known.side_on_surface(s, t, y)?.unwrap_or(relation)
            }
            Relation::BetweenOn(y) if targets.iter().chain([&y]).all(|&v| unmoved(v)) => {
                let w = *targets.get(1).ok_or_else(|| not_read(text, text))?;
                known.between_on(s, t, w, y)?;
                relation
            }
            r => r,
        };
        let beside = matches!(
            relation,
            Relation::NextTo | Relation::Side(..) | Relation::To | Relation::Between
        );
        if beside && as_is && known.grounded_beside(s, t) {
            level = Level::Floor;
        }
        relations::vector(relation, s, targets, &self.steps, &floor, level)
            .ok_or_else(|| not_read(text, text))
    }

    /// The room's centre, corners, walls, the floor, or its front/back ("towards the back of
    /// the room"); `Ok(None)` when the clause names none.
    #[allow(clippy::type_complexity)]
    fn room_place(
        &mut self,
        c: &mut Clause,
        action: Action,
        text: &str,
    ) -> Result<Option<Box<dyn Fn(usize) -> Expr>>, String> {
        let has_room = self.facts.known.room;
        let need_room = |c: &Clause| -> Result<(), String> {
            if has_room {
                Ok(())
            } else {
                Err(format!("the scene has no room (no \"bounds\"), so \"{}\" has no walls or centre to go to", c.text()))
            }
        };
        let room_words = |c: &mut Clause| {
            for i in 0..c.len() {
                if c.free(i)
                    && (c.word(i).is_some_and(is_room_word)
                        || matches!(
                            c.word(i),
                            Some(
                                "of" | "in"
                                    | "into"
                                    | "to"
                                    | "the"
                                    | "at"
                                    | "against"
                                    | "up"
                                    | "towards"
                                    | "toward"
                                    | "far"
                                    | "very"
                                    | "living"
                                    | "dining"
                                    | "put"
                            )
                        ))
                {
                    c.mark(i..i + 1);
                }
            }
        };
        for floor_words in [
            &["on", "the", "floor"][..],
            &["onto", "the", "floor"],
            &["to", "the", "floor"],
            &["on", "the", "ground"],
            &["to", "the", "ground"],
            &["onto", "the", "ground"],
        ] {
            if let Some(i) = c.find(floor_words) {
                c.mark(i..i + floor_words.len());
                if i > 0 && c.words_at(i - 1, &["down"]) {
                    c.mark(i - 1..i);
                }
                return Ok(Some(Box::new(move |s| room::onto_floor(s, has_room))));
            }
        }
        if let Some(i) = c.find(&["corner"]) {
            need_room(c)?;
            c.mark(i..i + 1);
            let side = |c: &mut Clause, words: &[&str]| -> bool {
                if let Some(k) = words.iter().find_map(|w| c.find(&[w])) {
                    c.mark(k..k + 1);
                    true
                } else {
                    false
                }
            };
            let x = if side(c, &["left"]) {
                Some(-1.0)
            } else if side(c, &["right"]) {
                Some(1.0)
            } else {
                None
            };
            let z = if side(c, &["back", "rear", "far"]) {
                Some(-1.0)
            } else if side(c, &["front", "near"]) {
                Some(1.0)
            } else {
                None
            };
            room_words(c);
            return Ok(Some(Box::new(move |s| room::place(Place::Corner(x, z), s))));
        }
        if let Some(i) = c.find(&["wall"]).or_else(|| c.find(&["walls"])) {
            need_room(c)?;
            c.mark(i..i + 1);
            let side = [
                ("left", (0, -1.0)),
                ("right", (0, 1.0)),
                ("back", (2, -1.0)),
                ("rear", (2, -1.0)),
                ("far", (2, -1.0)),
                ("front", (2, 1.0)),
            ]
            .iter()
            .find_map(|(w, d)| c.find(&[w]).map(|k| (k, *d)));
            if let Some((k, _)) = side {
                c.mark(k..k + 1);
            }
            room_words(c);
            let wall = side.map(|(_, d)| d);
            return Ok(Some(Box::new(move |s| room::place(Place::Wall(wall), s))));
        }
        let centre_word = ["centre", "center", "middle"]
            .iter()
            .find_map(|w| c.find(&[w]));
        if centre_word.is_some() || action == Action::Centre {
            need_room(c)?;
            if let Some(i) = centre_word {
                c.mark(i..i + 1);
            }
            room_words(c);
            return Ok(Some(Box::new(move |s| room::place(Place::Centre, s))));
        }
        // "towards the back of the room", "to the front of the room".
        for (i, w) in (0..c.len()).filter_map(|i| c.word(i).map(|w| (i, w.to_string()))) {
            if let Some((e, sign)) = words::direction(&w) {
                let of_room =
                    c.words_at(i + 1, &["of", "the"]) && c.word(i + 3).is_some_and(is_room_word);
                if of_room && c.free(i) {
                    need_room(c)?;
                    let towards = i >= 2
                        && (c.words_at(i - 2, &["towards", "the"])
                            || c.words_at(i - 2, &["toward", "the"]));
                    c.mark(i..i + 4);
                    mark_to_the(c, i);
                    let _ = text;
                    return Ok(Some(if towards {
                        Box::new(move |s| room::far(s, e, sign, true))
                    } else {
                        Box::new(move |s| room::all_the_way(s, e, sign))
                    }));
                }
            }
        }
        Ok(None)
    }
}

/// The heading of a horizontal direction about the vertical: θ with +θ about +Y taking +Z
/// toward +X, so θ = atan2(x, z).
fn heading(v: Expr) -> Expr {
    call("atan2", vec![dot(v.clone(), axis(0)), dot(v, axis(2))])
}

fn length_value(l: Option<Length>) -> Option<f64> {
    match l {
        Some(Length::Metres(m)) => Some(m),
        Some(Length::Far) => Some(amounts::FAR_METRES),
        _ => None,
    }
}

fn degrees_of(d: f64) -> Expr {
    degrees(d)
}

/// Room words: `room`, and room types (`bedroom`, `kitchen`): the scene's bounds.
/// Words for the room as a whole (`the middle of the kitchen`).
pub(super) fn is_room_word(w: &str) -> bool {
    matches!(
        w,
        "room"
            | "bedroom"
            | "kitchen"
            | "bathroom"
            | "office"
            | "livingroom"
            | "lounge"
            | "classroom"
            | "workshop"
            | "cellar"
            | "study"
            | "hall"
            | "hallway"
            | "space"
            | "area"
            | "garage"
            | "den"
            | "diningroom"
    )
}

/// Marks `to the` / `towards the` / `to its` before position `i`.
fn mark_to_the(c: &mut Clause, i: usize) {
    for words in [
        &["to", "the"][..],
        &["towards", "the"],
        &["toward", "the"],
        &["to", "its"],
        &["on", "the"],
        &["to"],
        &["towards"],
        &["toward"],
    ] {
        let n = words.len();
        if i >= n && c.words_at(i - n, words) {
            c.mark(i - n..i);
            return;
        }
    }
}

/// How a relation's amount is read.
#[derive(Clone, Copy, Debug, PartialEq)]
enum RelKind {
    Fixed(Relation),
    Away,
    Closer,
}

/// A relation phrase found in a clause.
struct Found {
    kind: RelKind,
    range: std::ops::Range<usize>,
    targets: Vec<(usize, usize)>,
}

/// The relation markers, longest first.
const MARKERS: &[(&[&str], RelKind)] = &[
    (
        &["to", "the", "other", "side", "of"],
        RelKind::Fixed(Relation::OtherSide),
    ),
    (
        &["on", "the", "other", "side", "of"],
        RelKind::Fixed(Relation::OtherSide),
    ),
    (
        &["the", "other", "side", "of"],
        RelKind::Fixed(Relation::OtherSide),
    ),
    (&["further", "away", "from"], RelKind::Away),
    (&["farther", "away", "from"], RelKind::Away),
    (
        &["to", "the", "left", "of"],
        RelKind::Fixed(Relation::Side(0, -1.0)),
    ),
    (
        &["to", "the", "right", "of"],
        RelKind::Fixed(Relation::Side(0, 1.0)),
    ),
    (
        &["on", "the", "left", "of"],
        RelKind::Fixed(Relation::Side(0, -1.0)),
    ),
    (
        &["on", "the", "right", "of"],
        RelKind::Fixed(Relation::Side(0, 1.0)),
    ),
    (
        &["at", "the", "back", "of"],
        RelKind::Fixed(Relation::Side(2, -1.0)),
    ),
    (
        &["at", "the", "front", "of"],
        RelKind::Fixed(Relation::Side(2, 1.0)),
    ),
    (
        &["in", "front", "of"],
        RelKind::Fixed(Relation::Side(2, 1.0)),
    ),
    (
        &["in", "back", "of"],
        RelKind::Fixed(Relation::Side(2, -1.0)),
    ),
    (&["on", "top", "of"], RelKind::Fixed(Relation::On)),
    (&["on", "to"], RelKind::Fixed(Relation::On)),
    (&["next", "to"], RelKind::Fixed(Relation::NextTo)),
    (&["close", "to"], RelKind::Fixed(Relation::NextTo)),
    (&["near", "to"], RelKind::Fixed(Relation::NextTo)),
    (&["adjacent", "to"], RelKind::Fixed(Relation::NextTo)),
    (&["up", "against"], RelKind::Fixed(Relation::Against)),
    (&["halfway", "between"], RelKind::Fixed(Relation::Between)),
    (&["away", "from"], RelKind::Away),
    (&["further", "from"], RelKind::Away),
    (&["farther", "from"], RelKind::Away),
    (&["closer", "to"], RelKind::Closer),
    (&["nearer", "to"], RelKind::Closer),
    (&["off", "of"], RelKind::Fixed(Relation::Off)),
    (&["left", "of"], RelKind::Fixed(Relation::Side(0, -1.0))),
    (&["right", "of"], RelKind::Fixed(Relation::Side(0, 1.0))),
    (&["back", "of"], RelKind::Fixed(Relation::Side(2, -1.0))),
    (&["onto"], RelKind::Fixed(Relation::On)),
    (&["atop"], RelKind::Fixed(Relation::On)),
    (&["upon"], RelKind::Fixed(Relation::On)),
    (&["over"], RelKind::Fixed(Relation::On)),
    (&["above"], RelKind::Fixed(Relation::On)),
    (&["on"], RelKind::Fixed(Relation::On)),
    (&["beside"], RelKind::Fixed(Relation::NextTo)),
    (&["besides"], RelKind::Fixed(Relation::NextTo)),
    (&["by"], RelKind::Fixed(Relation::NextTo)),
    (&["near"], RelKind::Fixed(Relation::NextTo)),
    (&["nearby"], RelKind::Fixed(Relation::NextTo)),
    (&["alongside"], RelKind::Fixed(Relation::NextTo)),
    (&["against"], RelKind::Fixed(Relation::Against)),
    (&["under"], RelKind::Fixed(Relation::Under)),
    (&["underneath"], RelKind::Fixed(Relation::Under)),
    (&["below"], RelKind::Fixed(Relation::Under)),
    (&["beneath"], RelKind::Fixed(Relation::Under)),
    (&["behind"], RelKind::Fixed(Relation::Side(2, -1.0))),
    (&["between"], RelKind::Fixed(Relation::Between)),
    (&["opposite"], RelKind::Fixed(Relation::OtherSide)),
    (&["off"], RelKind::Fixed(Relation::Off)),
    (&["closer"], RelKind::Closer),
    (&["nearer"], RelKind::Closer),
    (&["toward"], RelKind::Closer),
    (&["towards"], RelKind::Closer),
    (&["into"], RelKind::Fixed(Relation::To)),
    (&["inside"], RelKind::Fixed(Relation::To)),
    (&["in"], RelKind::Fixed(Relation::To)),
    (&["to"], RelKind::Fixed(Relation::To)),
    (&["upto"], RelKind::Fixed(Relation::UpTo)),
    (&["at"], RelKind::Fixed(Relation::To)),
];

/// The first relation marker followed by an object (two for `between X2 and X3`).
fn find_relation(c: &Clause) -> Option<Found> {
    let mut best: Option<Found> = None;
    for (words, kind) in MARKERS {
        for i in 0..c.len() {
            if !c.words_at(i, words) {
                continue;
            }
            let after = i + words.len();
            let Some((t, v)) = c.variable_after(after) else {
                continue;
            };
            let mut targets = vec![(t, v)];
            let mut end = t + 1;
            if *kind == RelKind::Fixed(Relation::Between) {
                let and = (end..c.len()).find(|&k| c.words_at(k, &["and"]))?;
                let (t2, v2) = c.variable_after(and + 1)?;
                targets.push((t2, v2));
                end = t2 + 1;
            }
            // Articles between the marker and the object are read with it.
            let found = Found {
                kind: *kind,
                range: i..after.max(t).min(end),
                targets,
            };
            if best.as_ref().is_none_or(|b| i < b.range.start) {
                best = Some(found);
            }
            break;
        }
    }
    let mut f = best?;
    // The range covers the marker and any articles up to the first target.
    let first_target = f.targets[0].0;
    f.range = f.range.start..first_target;
    Some(f)
}

/// A facing phrase: "to face X2", "so that it faces X2", "towards X2", "away from X2",
/// "its back to X2".
#[derive(Clone, Debug)]
struct Facing {
    range: std::ops::Range<usize>,
    target: usize,
    target_at: usize,
    away: bool,
}

/// `it_means`: what a free "it" after the phrase stands for, when it is not the subject.
fn find_facing(c: &Clause, it_means: Option<usize>) -> Option<Facing> {
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

/// The axis named by "along the x axis" (for align).
fn named_axis(c: &mut Clause) -> Option<usize> {
    let i = c.find(&["axis"])?;
    let a = match c.word(i.checked_sub(1)?)? {
        "x" | "e1" => 0,
        "y" | "e2" => 1,
        "z" | "e3" => 2,
        _ => return None,
    };
    c.mark(i - 1..i + 1);
    for k in (i.saturating_sub(3)..i - 1).rev() {
        if matches!(c.word(k), Some("along" | "the" | "on" | "in")) {
            c.mark(k..k + 1);
        }
    }
    Some(a)
}

/// Marks the view a turn is given in read ([`super::view`]), wherever it stands in the
/// clause, and returns it.
fn mark_view(c: &mut Clause) -> Option<View> {
    let owned: Vec<String> = (0..c.len())
        .map(|i| c.word(i).unwrap_or("").to_string())
        .collect();
    let words: Vec<&str> = owned.iter().map(String::as_str).collect();
    for i in 0..c.len() {
        if let Some((n, view)) = view_at(&words, i) {
            if (i..i + n).all(|k| c.free(k)) {
                c.mark(i..i + n);
                return Some(view);
            }
        }
    }
    None
}

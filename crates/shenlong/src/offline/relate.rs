//! Moves to a relation with other objects: finding the relation phrase ("next to X2", "on
//! top of X2", "between X2 and X3", "a bit closer to X2", "next to it"), its subjects and
//! targets, and what it means here — "against X2" along a direction said before it ("slide
//! X1 right until it touches X2"), a small thing "to" a table goes on it, "on X2 next to
//! X3" is one place on X2, several things "on X2" go side by side — then each subject's
//! vector, placed as a person would ([`Reader::vector`]).

use super::amounts::{self, Length, DEFAULT_METRES};
use super::build;
use super::clause::Clause;
use super::reader::{not_read, Produced, ReadError, Reader};
use super::relations::{self, Level, Relation, Step};
use super::room;
use crate::expr::Expr;
use crate::translate::Near;
use std::ops::Range;

/// How a relation's amount is read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum RelKind {
    /// A relation with no amount.
    Fixed(Relation),
    /// Away from the target by the amount named ([`DEFAULT_METRES`] with none).
    Away,
    /// Closer to the target by the amount named (halfway with none).
    Closer,
    /// At one end or side of the target (axis, sign): on its top at that end for a small
    /// thing that goes on it ("the lamp to the right end of its table"), else beside that
    /// face ("chair 6 to the left end of the table").
    End(usize, f64),
    /// In, into or inside the target: on the bottom of an open container (a box, a
    /// basket: `scene::form`), else refused ([`ReadError::Inside`]), since the target is a
    /// solid box and the nearest free place would be beside it.
    Inside,
}

/// A relation phrase found in a clause.
pub(super) struct Found {
    /// How its amount is read.
    kind: RelKind,
    /// The marker and any articles up to the first target.
    range: Range<usize>,
    /// The targets: (position, variable), two for `between X2 and X3`.
    targets: Vec<(usize, usize)>,
    /// A word after the target that is part of the phrase (`place` in `at X2's place`).
    trailing: Option<usize>,
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
    // "pull X1 back from X2", "out from X2": away from it.
    (&["further", "out", "from"], RelKind::Away),
    (&["further", "back", "from"], RelKind::Away),
    // "to the left end of X2", "at the far end of X2", "on the right side of X2".
    (&["to", "the", "left", "end", "of"], RelKind::End(0, -1.0)),
    (&["to", "the", "left", "side", "of"], RelKind::End(0, -1.0)),
    (&["to", "the", "right", "end", "of"], RelKind::End(0, 1.0)),
    (&["to", "the", "right", "side", "of"], RelKind::End(0, 1.0)),
    (&["to", "the", "far", "end", "of"], RelKind::End(2, -1.0)),
    (&["to", "the", "back", "end", "of"], RelKind::End(2, -1.0)),
    (&["to", "the", "back", "side", "of"], RelKind::End(2, -1.0)),
    (&["to", "the", "near", "end", "of"], RelKind::End(2, 1.0)),
    (&["to", "the", "front", "end", "of"], RelKind::End(2, 1.0)),
    (&["to", "the", "front", "side", "of"], RelKind::End(2, 1.0)),
    (&["at", "the", "left", "end", "of"], RelKind::End(0, -1.0)),
    (&["at", "the", "left", "side", "of"], RelKind::End(0, -1.0)),
    (&["at", "the", "right", "end", "of"], RelKind::End(0, 1.0)),
    (&["at", "the", "right", "side", "of"], RelKind::End(0, 1.0)),
    (&["at", "the", "far", "end", "of"], RelKind::End(2, -1.0)),
    (&["at", "the", "back", "end", "of"], RelKind::End(2, -1.0)),
    (&["at", "the", "back", "side", "of"], RelKind::End(2, -1.0)),
    (&["at", "the", "near", "end", "of"], RelKind::End(2, 1.0)),
    (&["at", "the", "front", "end", "of"], RelKind::End(2, 1.0)),
    (&["at", "the", "front", "side", "of"], RelKind::End(2, 1.0)),
    (&["on", "the", "left", "end", "of"], RelKind::End(0, -1.0)),
    (&["on", "the", "left", "side", "of"], RelKind::End(0, -1.0)),
    (&["on", "the", "right", "end", "of"], RelKind::End(0, 1.0)),
    (&["on", "the", "right", "side", "of"], RelKind::End(0, 1.0)),
    (&["on", "the", "far", "end", "of"], RelKind::End(2, -1.0)),
    (&["on", "the", "back", "end", "of"], RelKind::End(2, -1.0)),
    (&["on", "the", "back", "side", "of"], RelKind::End(2, -1.0)),
    (&["on", "the", "near", "end", "of"], RelKind::End(2, 1.0)),
    (&["on", "the", "front", "end", "of"], RelKind::End(2, 1.0)),
    (&["on", "the", "front", "side", "of"], RelKind::End(2, 1.0)),
    (&["by", "the", "left", "end", "of"], RelKind::End(0, -1.0)),
    (&["by", "the", "left", "side", "of"], RelKind::End(0, -1.0)),
    (&["by", "the", "right", "end", "of"], RelKind::End(0, 1.0)),
    (&["by", "the", "right", "side", "of"], RelKind::End(0, 1.0)),
    (&["by", "the", "far", "end", "of"], RelKind::End(2, -1.0)),
    (&["by", "the", "back", "end", "of"], RelKind::End(2, -1.0)),
    (&["by", "the", "back", "side", "of"], RelKind::End(2, -1.0)),
    (&["by", "the", "near", "end", "of"], RelKind::End(2, 1.0)),
    (&["by", "the", "front", "end", "of"], RelKind::End(2, 1.0)),
    (&["by", "the", "front", "side", "of"], RelKind::End(2, 1.0)),
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
    (&["back", "from"], RelKind::Away),
    (&["out", "from"], RelKind::Away),
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
    (&["into"], RelKind::Inside),
    (&["inside"], RelKind::Inside),
    (&["in"], RelKind::Inside),
    (&["to"], RelKind::Fixed(Relation::To)),
    (&["upto"], RelKind::Fixed(Relation::UpTo)),
    (&["at"], RelKind::Fixed(Relation::To)),
];

/// The first relation marker followed by an object (two for `between X2 and X3`).
pub(super) fn find_relation(c: &Clause) -> Option<Found> {
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
            } else {
                // "closer to X3 and X4": every object named is a target (the reader then
                // refuses what does not say which goes where).
                while c.words_at(end, &["and"]) {
                    match c.token(end + 1) {
                        Some(super::words::Token::Variable(v2)) => {
                            targets.push((end + 1, *v2));
                            end += 2;
                        }
                        _ => break,
                    }
                }
            }
            // "at X2's place": the place at the table of the chair X2.
            let seat = *words == ["at"]
                && targets.len() == 1
                && matches!(c.word(end), Some("place" | "spot" | "seat" | "setting"));
            // Articles between the marker and the object are read with it.
            let found = Found {
                kind: if seat {
                    RelKind::Fixed(Relation::AtSeat(None))
                } else {
                    *kind
                },
                range: i..after.max(t).min(end),
                targets,
                trailing: seat.then_some(end),
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

/// The length a relation's amount names, in metres (`far`: [`amounts::FAR_METRES`]).
fn length_value(l: Option<Length>) -> Option<f64> {
    match l {
        Some(Length::Metres(m)) => Some(m),
        Some(Length::Far) => Some(amounts::FAR_METRES),
        _ => None,
    }
}

/// Marks the relation phrase read: its marker, its targets, and a particle before it
/// ("up onto", "back to", "over to").
fn mark_relation(c: &mut Clause, r: &Found) {
    c.mark(r.range.clone());
    for &(i, _) in &r.targets {
        c.mark(i..i + 1);
    }
    if let Some(i) = r.trailing {
        c.mark(i..i + 1);
    }
    // "right next to", "just behind", "directly in front of": the same place.
    if r.range.start > 0
        && c.free(r.range.start - 1)
        && matches!(
            c.word(r.range.start - 1),
            Some("right" | "just" | "directly" | "immediately")
        )
    {
        c.mark(r.range.start - 1..r.range.start);
    }
    // "on X2, (roughly) in the middle": on it is centred on it already.
    if matches!(r.kind, RelKind::Fixed(Relation::On)) {
        for words in [
            &["roughly", "in", "the", "middle"][..],
            &["in", "the", "middle"],
            &["in", "the", "centre"],
            &["in", "the", "center"],
        ] {
            if let Some(i) = c.find(words) {
                if (i..i + words.len()).all(|k| c.free(k)) {
                    c.mark(i..i + words.len());
                    break;
                }
            }
        }
    }
    mark_particles_before(c, r.range.start);
}

/// Marks a particle before a relation starting at token `start` read: "up onto", "back
/// to", "over to"; `in` before a move towards something ("push X1 in toward X2", "tuck
/// X1 in a bit closer to X2", "tuck X1 in flush against X2", "pull X1 back in against
/// it"), vague amounts and words already read between; `out` before a move away ("scoot
/// X1 out a bit further from X2"); `to` before a place ("X1 to between X2 and X3").
fn mark_particles_before(c: &mut Clause, start: usize) {
    if start > 0 {
        let p = start - 1;
        let toward = matches!(
            c.word(start),
            Some("toward" | "towards" | "to" | "closer" | "nearer" | "against" | "flush" | "up")
        );
        let mut q = p;
        while q > 0
            && (!c.free(q)
                || matches!(
                    c.word(q),
                    Some("a" | "bit" | "little" | "tad" | "touch" | "slightly")
                ))
        {
            q -= 1;
        }
        if matches!(c.word(p), Some("up" | "down" | "back" | "over" | "across")) && c.free(p) {
            c.mark(p..p + 1);
        } else if c.word(p) == Some("in")
            && c.free(p)
            && matches!(
                c.word(start),
                Some("under" | "underneath" | "beneath" | "below")
            )
        {
            // "push X1 in under X2": in, under it.
            c.mark(p..p + 1);
        } else if c.word(p) == Some("away")
            && c.free(p)
            && matches!(
                c.word(start),
                Some("in" | "into" | "inside" | "on" | "onto")
            )
        {
            // "put X1 away in X2": put away, in it.
            c.mark(p..p + 1);
        } else if matches!(c.word(start), Some("further" | "farther" | "away"))
            && c.word(q) == Some("out")
            && c.free(q)
        {
            // "scoot X1 out a bit further from X2": out, away from it.
            c.mark(q..q + 1);
        } else if toward && c.word(q) == Some("in") && c.free(q) {
            c.mark(q..q + 1);
            // "pull X1 back in against X2": pulled back to it.
            if q > 0 && c.word(q - 1) == Some("back") && c.free(q - 1) {
                c.mark(q - 1..q);
            }
        } else if c.word(p) == Some("to")
            && c.free(p)
            && matches!(
                c.word(start),
                Some("between" | "beside" | "behind" | "next" | "under" | "underneath")
            )
        {
            // "X1 to between X2 and X3" (an arrow read as `to`): the place after it.
            c.mark(p..p + 1);
        }
    }
}

/// Marks "on the floor" (or "onto / to the floor", "on the ground", with a "down" before
/// it) where the clause has it free: the level a relation beside something puts its
/// subjects on.
fn floor_words(c: &mut Clause) -> bool {
    for words in [
        &["on", "the", "floor"][..],
        &["onto", "the", "floor"],
        &["to", "the", "floor"],
        &["on", "the", "ground"],
        &["onto", "the", "ground"],
        &["to", "the", "ground"],
    ] {
        if let Some(i) = c.find(words) {
            if (i..i + words.len()).all(|k| c.free(k)) {
                c.mark(i..i + words.len());
                if i > 0 && c.words_at(i - 1, &["down"]) && c.free(i - 1) {
                    c.mark(i - 1..i);
                }
                return true;
            }
        }
    }
    false
}

/// What `on X2` combined with a second relation on the same surface means ("on X2 next
/// to X3", "on X2 to the left of X3", "on X2 between X3 and X4"), with `surface` X2.
fn on_surface(surface: usize, second: &Found) -> Option<Relation> {
    match (second.kind, second.targets.len()) {
        (RelKind::Fixed(Relation::NextTo), 1) => Some(Relation::NextToOn(surface)),
        (RelKind::Fixed(side @ Relation::Side(..)), 1) => Some(side),
        (RelKind::Fixed(Relation::Between), 2) => Some(Relation::BetweenOn(surface)),
        (RelKind::Fixed(Relation::AtSeat(_)), 1) => Some(Relation::AtSeat(Some(surface))),
        _ => None,
    }
}

impl Reader<'_> {
    /// A relation whose object is a pronoun for the objects named before ("next to it",
    /// "on top of them"): the words' range, and those objects.
    pub(super) fn pronoun_relation(&self, c: &Clause) -> Option<(Range<usize>, Vec<usize>)> {
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

    /// "move X2 next to it": the subjects (the variables before the phrase `r`) moved
    /// into the relation with `targets`, the objects named before.
    pub(super) fn relate_to_pronoun(
        &mut self,
        c: &mut Clause,
        r: Range<usize>,
        targets: &[usize],
        text: &str,
    ) -> Result<Produced, ReadError> {
        c.mark(r.clone());
        mark_particles_before(c, r.start);
        let subjects = self.subjects(c, Some(r.start));
        if subjects.is_empty() || targets.iter().any(|t| subjects.contains(t)) {
            return Err(not_read(text, text));
        }
        let kind = MARKERS
            .iter()
            .find(|(w, _)| c.words_at_any(r.start, w))
            .map(|(_, k)| *k);
        let relation = match kind {
            Some(RelKind::Inside) => match targets.first() {
                // "tuck the chair into the desk": under a top on legs.
                Some(&target) if self.facts.known.tucks_under(&subjects, target) => Relation::Under,
                Some(&target) => match self.facts.known.inside_floor(&subjects, target, c.shelf) {
                    Some(floor) => Relation::In(floor),
                    None => return Err(self.inside(&subjects, target)),
                },
                None => return Err(not_read(text, text)),
            },
            Some(RelKind::Fixed(rel)) => rel,
            // ("at the left end of it": beside that face.)
            Some(RelKind::End(e, sign)) => Relation::Side(e, sign),
            Some(RelKind::Away) => Relation::Away(DEFAULT_METRES),
            Some(RelKind::Closer) | None => Relation::Closer(None),
        };
        self.each(&subjects, relation, targets, text)
    }

    /// The refusal of putting `subjects` in, into or inside `container`.
    fn inside(&self, subjects: &[usize], container: usize) -> ReadError {
        let known = self.facts.known;
        ReadError::Inside {
            object: subjects
                .iter()
                .map(|&s| known.label(s))
                .collect::<Vec<_>>()
                .join(" and "),
            container: known.label(container),
        }
    }

    /// The subjects (the variables before the phrase) moved into the relation `r` names.
    pub(super) fn relate(
        &mut self,
        c: &mut Clause,
        r: Found,
        text: &str,
    ) -> Result<Produced, ReadError> {
        // "move X1 off X2 onto X3": where it is taken from, then where it goes.
        if r.kind == RelKind::Fixed(Relation::Off) {
            let end = r.targets.last().map_or(r.range.end, |&(t, _)| t + 1);
            let mut probe = c.clone();
            probe.mark(r.range.start..end);
            if let Some(next) = find_relation(&probe).filter(|n| n.range.start >= end) {
                *c = probe;
                return self.relate(c, next, text);
            }
        }
        let subjects = self.subjects(c, Some(r.range.start));
        if subjects.is_empty() {
            return Err(not_read(text, text));
        }
        mark_relation(c, &r);
        let targets: Vec<usize> = r.targets.iter().map(|(_, v)| *v).collect();
        let relation = self.relation(c, &r, &subjects, &targets)?;
        // "closer to X3 and X4" for several objects, "next to their desks": which one
        // each goes to is not said (only "between" takes two), so nothing is guessed. One
        // object towards or away from several goes by their middle ("towards the
        // loungers").
        let two_ends = matches!(relation, Relation::Between | Relation::BetweenOn(_));
        let by_middle =
            subjects.len() == 1 && matches!(relation, Relation::Closer(_) | Relation::Away(_));
        if targets.len() > 1 && !two_ends && !by_middle {
            let known = self.facts.known;
            let names: Vec<String> = targets.iter().map(|&t| known.label(t)).collect();
            return Err(ReadError::Unclear(format!(
                "which of {} each object goes to is not said in \"{text}\": name one, or say it for each",
                names.join(" and ")
            )));
        }
        // "on the floor next to X2", "down on the ground beside X2": beside X2, on the floor.
        let beside = matches!(
            relation,
            Relation::NextTo | Relation::Side(..) | Relation::Between | Relation::To
        );
        if beside && floor_words(c) {
            self.on_floor = true;
            let produced = self.each(&subjects, relation, &targets, text);
            self.on_floor = false;
            return produced;
        }
        // "on X2 next to X3", "on X2 to the left of X3": one destination, beside X3 on the
        // surface X2.
        if relation == Relation::On && targets.len() == 1 {
            if let Some(second) = find_relation(c) {
                if let Some(rel) = on_surface(targets[0], &second) {
                    // The marker, the targets and what joins them ("and").
                    let last = second.targets.last().map_or(0, |&(i, _)| i);
                    c.mark(second.range.start..last + 1);
                    if let Some(i) = second.trailing {
                        c.mark(i..i + 1);
                    }
                    let on: Vec<usize> = second.targets.iter().map(|&(_, v)| v).collect();
                    return self.each(&subjects, rel, &on, text);
                }
            }
        }
        if relation == Relation::On && subjects.len() > 1 {
            // "put the mug and the bowl (together) on the dresser": side by side on it.
            if let Some(i) = c.find(&["together"]).filter(|&i| c.free(i)) {
                c.mark(i..i + 1);
            }
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
        self.each(&subjects, relation, &targets, text)
    }

    /// The relation phrase `r` means here, its amount read: "against X2" after a direction
    /// is along it (refused when X2 does not lie straight that way), and a small thing
    /// "to" or "at" one target goes on it ("bring the bowl to the table").
    ///
    /// # Errors
    /// The target of "against" along a direction does not lie straight that way.
    fn relation(
        &self,
        c: &mut Clause,
        r: &Found,
        subjects: &[usize],
        targets: &[usize],
    ) -> Result<Relation, ReadError> {
        let relation = match r.kind {
            RelKind::Inside if self.facts.known.tucks_under(subjects, targets[0]) => {
                Relation::Under
            }
            RelKind::Inside => match self.facts.known.inside_floor(subjects, targets[0], c.shelf) {
                Some(floor) => Relation::In(floor),
                None => return Err(self.inside(subjects, targets[0])),
            },
            // "slide X1 right until it touches X2", "push X1 left against X2": along
            // that direction, when X2 lies straight that way.
            RelKind::Fixed(Relation::Against) => match self.direction_before(c, r.range.start) {
                Some((e, sign)) => {
                    for &s in subjects {
                        self.facts.known.straight_ahead(s, targets[0], e, sign)?;
                    }
                    Relation::AgainstAlong(e, sign)
                }
                None => Relation::Against,
            },
            RelKind::Fixed(rel) => rel,
            RelKind::Away => {
                Relation::Away(length_value(amounts::length(c, true)).unwrap_or(DEFAULT_METRES))
            }
            RelKind::Closer => Relation::Closer(length_value(amounts::length(c, true))),
            RelKind::End(e, sign) => {
                let known = self.facts.known;
                let onto =
                    |s: usize| known.small_onto(s, targets[0]) || known.rests_on(s, targets[0]);
                if targets.len() == 1 && subjects.iter().all(|&s| onto(s)) {
                    Relation::OnEnd(e, sign)
                } else {
                    Relation::Side(e, sign)
                }
            }
        };
        // "bring the bowl to the table": a small thing goes on the table's top.
        let to_word = c
            .word(r.range.start)
            .is_some_and(|w| matches!(w, "to" | "at"));
        let small = |s: usize| self.facts.known.small_onto(s, targets[0]);
        Ok(
            if relation == Relation::To
                && to_word
                && targets.len() == 1
                && subjects.iter().all(|&s| small(s))
            {
                Relation::On
            } else {
                relation
            },
        )
    }

    /// Each subject moved into `relation` with `targets`, remembered as what later
    /// clauses' "it" and "them" mean and as what each was put beside or between.
    fn each(
        &mut self,
        subjects: &[usize],
        relation: Relation,
        targets: &[usize],
        text: &str,
    ) -> Result<Produced, ReadError> {
        self.last_subjects = subjects.to_vec();
        self.last_targets = targets.to_vec();
        let near = match (relation, targets) {
            (
                Relation::NextTo
                | Relation::NextToOn(_)
                | Relation::Side(..)
                | Relation::SideGap(..)
                | Relation::Against
                | Relation::AgainstAlong(..),
                &[t, ..],
            ) => Some(Near::Beside(t)),
            (Relation::Between | Relation::BetweenOn(_), &[a, b, ..]) => Some(Near::Between(a, b)),
            (Relation::Under, &[t, ..]) => Some(Near::Under(t)),
            (Relation::In(_), &[t, ..]) => Some(Near::Inside(t)),
            _ => None,
        };
        // "table 4 and its chairs towards the door": a table with what stands drawn up
        // to it goes as one, along the first's line (each on its own line would pull
        // them apart); "the chairs closer to the table" go each its own way.
        let together = matches!(relation, Relation::Closer(_) | Relation::Away(_))
            && subjects.len() > 1
            && self.facts.known.unit_with(subjects[0], &subjects[1..]);
        let mut produced = Vec::new();
        for &s in subjects {
            let lead = if together { subjects[0] } else { s };
            if relation.places() && !targets.contains(&s) {
                self.forget_moves(s);
            }
            let v = self.vector(relation, lead, targets, text)?;
            match near {
                Some(n) => self.near.insert(s, n),
                None => self.near.remove(&s),
            };
            // In a box or on a shelf it fits only turned: a quarter turn about its pivot
            // first (which keeps its box's centre and bottom, what the vector is written
            // from).
            if let (Relation::In(floor), &[t, ..]) = (relation, targets) {
                if self.facts.known.turn_to_fit(s, t, floor) {
                    let quarter = build::rotor(build::degrees(90.0), (2, 0));
                    produced.push((s, Step::Turn(quarter)));
                }
            }
            produced.push((s, Step::Translate(v)));
        }
        Ok(produced)
    }

    /// Forgets the translations earlier clauses gave variable `s`, which a relation that
    /// sets where it stands ([`Relation::places`]) replaces: its vector is then written
    /// from where `s` stood, and the answer does not carry every earlier move into each of
    /// its terms. Its turns stay, and so does the record that it moved.
    fn forget_moves(&mut self, s: usize) {
        if let Some(list) = self.steps.get_mut(&s) {
            list.retain(|step| matches!(step, Step::Turn(_)));
        }
    }

    /// Places measured from the scene rather than written over the bound boxes: a chair's
    /// place as where a thing goes — "at X2's place" ([`Relation::AtSeat`]), and "in front
    /// of X2" for a thing on the table seat X2 is drawn up to: on that table, in front of
    /// the seat ([`super::Known::at_its_seat`]). `None` for other
    /// relations and where these do not apply.
    ///
    /// # Errors
    /// At a chair's place where the chair is drawn up to no table (or another than the
    /// one named), or where an earlier clause moved the chair or the table.
    fn measured_in_scene(
        &self,
        relation: Relation,
        s: usize,
        t: usize,
    ) -> Option<Result<Expr, ReadError>> {
        let known = self.facts.known;
        let unmoved = |v: usize| !self.steps.contains_key(&v);
        let constant =
            |v: glam::DVec3| build::sum((0..3).map(|e| build::scaled_axis(build::num(v[e]), e)));
        match relation {
            Relation::Side(2, 1.0) if unmoved(t) => known
                .at_its_seat(s, t, None)
                .filter(|_| known.on_seat_table(s, t))
                .map(|v| Ok(constant(v))),
            Relation::AtSeat(table) => {
                let placed = unmoved(t) && table.is_none_or(unmoved);
                Some(
                    known
                        .at_its_seat(s, t, table)
                        .filter(|_| placed)
                        .map(constant)
                        .ok_or_else(|| {
                            ReadError::Unclear(format!(
                                "{} is drawn up to no table{} to put {} in front of it: say where it goes",
                                known.label(t),
                                table.map(|y| format!(" like {}", known.label(y))).unwrap_or_default(),
                                known.label(s)
                            ))
                        }),
                )
            }
            _ => None,
        }
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
    ) -> Result<Expr, ReadError> {
        let floor = room::floor(self.facts.known.room);
        let t = *targets.first().ok_or_else(|| not_read(text, text))?;
        // Where an earlier clause moved the target, the scene's numbers no longer say
        // where it is.
        let unmoved = |v: usize| !self.steps.contains_key(&v);
        let as_is = unmoved(t);
        let known = self.facts.known;
        if let Some(measured) = self.measured_in_scene(relation, s, t) {
            return measured;
        }
        let mut level = Level::Target;
        let relation = match relation {
            r if self.on_floor => {
                level = Level::Floor;
                r
            }
            // Under what hangs on a wall: on the floor below it.
            Relation::Under if as_is && known.hangs(t) => {
                level = Level::Floor;
                relation
            }
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
            // "to the left of the machine" on a bench: only where it stays on the bench.
            Relation::Side(e, sign) if as_is => match known.side_on_its_support(s, t, e, sign)? {
                Some(side) => {
                    let d = known.float_above_support(t);
                    if d > 0.0 {
                        level = Level::Under(d);
                    }
                    side
                }
                None => relation,
            },
            Relation::Away(amount) if as_is && targets.len() == 1 => match known.alongside(s, t) {
                Some(e) => Relation::AwayFromFace(amount, e),
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
            Relation::NextTo
                | Relation::Side(..)
                | Relation::SideGap(..)
                | Relation::To
                | Relation::Between
        );
        if beside && as_is && known.grounded_beside(s, t) {
            level = Level::Floor;
        }
        relations::vector(relation, s, targets, &self.steps, &floor, level)
            .ok_or_else(|| not_read(text, text))
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{close, moves, on, outcome, standing};
    use super::super::GAP;

    /// A table (X2) with a mug (X1) on the floor to its left, a vase (X3) on the table,
    /// and a chair (X4) in front of it.
    fn table() -> Vec<super::super::testing::Box3> {
        vec![
            standing([0.1, 0.1, 0.1], -1.0, 0.0),
            standing([1.0, 0.75, 0.6], 0.0, 0.0),
            on([0.2, 0.3, 0.2], 0.2, 0.75, 0.1),
            standing([0.5, 0.9, 0.5], 0.0, 1.5),
        ]
    }

    #[test]
    fn at_an_end_never_goes_the_other_way() {
        // A tray nearly as long as the table, on it: "at the left end" moves it left (by
        // the little slack there is), never right to keep a 5 cm inset.
        let mut boxes = table();
        boxes.push(on([0.98, 0.05, 0.3], 0.0, 0.75, 0.0));
        let m = moves("move X5 to the left end of X2", &boxes)[4];
        assert!(m.x <= 0.0 && m.x >= -0.011, "{m}");
    }

    #[test]
    fn a_placement_replaces_the_moves_before_it() {
        // Off the table, then beside the chair on the floor: where it is put is all that
        // counts, and the answer stays short enough to be read back by the language.
        let q = "take X3 off X2 and put it on the floor next to X4";
        let m = moves(q, &table())[2];
        // Behind the chair (the side facing where the vase stood), GAP from its face.
        assert!(close(m, [-0.2, -0.75, 1.25 - GAP - 0.2]), "{m}");
        let reply = super::super::reply_for(q, 4).unwrap();
        assert!(
            reply.len() < crate::expr::Limits::default().max_length,
            "{reply}"
        );
        // A move after the placement still counts.
        let after = moves("put X3 on X4 and move it 10 cm left", &table())[2];
        let on = moves("put X3 on X4", &table())[2];
        assert!(close(after - on, [-0.1, 0.0, 0.0]), "{after} {on}");
    }

    #[test]
    fn on_under_next_to_and_a_side() {
        let m = |q: &str| moves(q, &table())[0];
        assert!(close(m("put X1 on X2"), [1.0, 0.75, 0.0]));
        assert!(close(m("put X1 on top of X2"), [1.0, 0.75, 0.0]));
        assert!(close(m("put X1 under X2"), [1.0, 0.0, 0.0]));
        // Next to: the table's face nearest the mug, GAP from it, centred along it.
        let next = m("put X1 next to X2");
        assert!(close(next, [-0.5 - GAP - (-0.95), 0.0, 0.0]), "{next}");
        let right = m("put X1 to the right of X2");
        assert!(close(right, [0.5 + GAP - (-1.05), 0.0, 0.0]), "{right}");
    }

    #[test]
    fn a_small_thing_to_a_table_goes_on_it_and_a_chair_to_its_place() {
        let m = moves("bring X1 to X2", &table());
        assert!(close(m[0], [1.0, 0.75, 0.0]));
        // The chair is not small beside the table: to its place on the floor.
        let m = moves("move X4 to X2", &table());
        assert!(close(m[3], [0.0, 0.0, -1.5]));
    }

    #[test]
    fn on_a_surface_next_to_something_on_it() {
        // On the table, beside the vase: the vase's face towards the table's centre (−x),
        // GAP from it, at the vase's level.
        let m = moves("put X1 on X2 next to X3", &table());
        assert!(close(m[0], [0.1 - GAP - (-0.95), 0.75, 0.1]), "{}", m[0]);
    }

    #[test]
    fn several_on_one_surface_go_side_by_side() {
        let m = moves("put X1 and X3 on X2", &table());
        // Along x (the table is wider than deep), centred: total 0.1 + GAP + 0.2.
        let total = 0.1 + GAP + 0.2;
        assert!(
            close(m[0], [-total / 2.0 + 0.05 + 1.0, 0.75, 0.0]),
            "{}",
            m[0]
        );
        let x3 = -total / 2.0 + 0.1 + GAP + 0.1;
        assert!(close(m[2], [x3 - 0.2, 0.0, -0.1]), "{}", m[2]);
    }

    #[test]
    fn against_along_a_direction_and_next_to_it() {
        // Without a scene nothing is known of where it lies: taken as straight.
        let m = moves("slide X1 right until it touches X2", &table());
        assert!(close(m[0], [-0.5 - (-0.95), 0.0, 0.0]), "{}", m[0]);
        // A pronoun for the last subject: "next to it".
        let m = moves("move X1 30 cm left and put X4 next to it", &table());
        // X1 went to x −1.3; the chair (z 1.5) lies more in front of it than to its side
        // in X1's proportions: against X1's front face, centred on it.
        assert!(close(m[3], [-1.3, 0.0, 0.05 + GAP - 1.25]), "{}", m[3]);
        assert!(outcome("put X1 next to it", &table(), true).is_err());
    }
}

//! Moves by directions and an amount: "20 cm to the left", "forward and to the right", "a
//! bit further left", "up 1 ft", "all the way to the left", "as far right as it will go".
//! Every direction named moves by the one amount (none: [`DEFAULT_METRES`]); a verb may
//! imply the direction ("lift", "lower", "push").

use super::amounts::{self, Length, DEFAULT_METRES};
use super::build::*;
use super::clause::Clause;
use super::reader::{mark_to_the, not_read, Direction, Produced, ReadError, Reader};
use super::relations::Step;
use super::room;
use super::words;
use crate::expr::Expr;

/// The direction words of the clause (`left`, `to the right`, `forward`, `the left side`),
/// typos corrected, read; each once, in the order named.
fn directions(c: &mut Clause) -> Vec<Direction> {
    let mut dirs: Vec<Direction> = Vec::new();
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
    dirs
}

/// The amount of a move, read: the length named; with "further", "farther" or "more" and
/// none named, a bit ([`amounts::BIT_METRES`]); with a verb that is itself a small move
/// ("nudge", "budge", "scoot") and none named, a bit too.
fn amount(c: &mut Clause) -> Option<Length> {
    // (The verb is read by now: looked for read or not.)
    let small_verb = (0..c.len()).any(|i| {
        ["nudge", "budge", "scoot", "scooch", "scootch", "jiggle"]
            .iter()
            .any(|w| c.words_at_any(i, &[w]))
    });
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
    if small_verb && amount.is_none() {
        amount = Some(Length::Metres(amounts::BIT_METRES));
    }
    amount
}

impl Reader<'_> {
    /// Each of `subjects` moved along every direction the clause names (else the one the
    /// verb implies) by its amount.
    pub(super) fn shift(
        &mut self,
        c: &mut Clause,
        subjects: &[usize],
        implied: Option<Direction>,
        text: &str,
    ) -> Result<Produced, ReadError> {
        let mut dirs = directions(c);
        let amount = amount(c);
        if dirs.is_empty() {
            if let Some(tucked) = self.in_or_out(c, subjects, amount, text) {
                return tucked;
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
        self.last_shift = Some((subjects.to_vec(), dirs.clone()));
        let mut out = Vec::new();
        for &s in subjects {
            let parts = dirs
                .iter()
                .map(|&(e, sign)| self.along(s, e, sign, amount, text))
                .collect::<Result<Vec<Expr>, ReadError>>()?;
            out.push((s, Step::Translate(sum(parts))));
        }
        Ok(out)
    }

    /// "push X1 in (a smidge)", "pull X1 out a bit", "tuck X1 in": towards or away from
    /// what each subject is drawn up to ([`super::Known::drawn_up_to`], a chair's table),
    /// by the amount (pushed in with none: until it touches; pulled out: a bit). `None`
    /// when the clause says neither.
    fn in_or_out(
        &mut self,
        c: &mut Clause,
        subjects: &[usize],
        amount: Option<Length>,
        text: &str,
    ) -> Option<Result<Produced, ReadError>> {
        let i = (0..c.len()).find(|&i| c.words_at(i, &["in"]) || c.words_at(i, &["out"]))?;
        let inwards = c.words_at(i, &["in"]);
        c.mark(i..i + 1);
        let mut out = Vec::new();
        for &s in subjects {
            let Some(((e, sign), gap)) = self.facts.known.drawn_up_to(s) else {
                return Some(Err(ReadError::Unclear(format!(
                    "{} is drawn up to nothing to push it in or pull it out from, in \"{text}\": say where",
                    self.facts.known.label(s)
                ))));
            };
            let sign = if inwards { sign } else { -sign };
            // Pushed in: to the table's face, or a chair under its top.
            let (pushed, table) = self.facts.known.push_in(s).unwrap_or((gap, None));
            if let (true, Some(table)) = (inwards, table) {
                self.near
                    .insert(s, crate::translate::Near::PushedUnder(table));
            }
            let metres = match amount {
                Some(Length::Metres(m)) => m,
                // "push it all the way in": as far as pushing it in goes.
                None | Some(Length::ToWall | Length::UntilBlocked) if inwards => pushed,
                None => amounts::BIT_METRES,
                Some(_) => return Some(Err(not_read(text, text))),
            };
            out.push((s, Step::Translate(scaled_axis(num(sign * metres), e))));
        }
        Some(Ok(out))
    }

    /// The one horizontal direction word before `end` not read yet (`right`, `to the
    /// left`, `forward`), read; `None` when there is none or more than one.
    pub(super) fn direction_before(&self, c: &mut Clause, end: usize) -> Option<Direction> {
        let found: Vec<(usize, Direction)> = (0..end)
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
    ) -> Result<Expr, ReadError> {
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
                    ReadError::Unclear(format!(
                        "nothing stops {} that way in \"{text}\": say how far",
                        self.facts.known.label(s)
                    ))
                })?;
                scaled_axis(num(sign * run), e)
            }
            None => scaled_axis(num(sign * DEFAULT_METRES), e),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{close, moves, on, outcome, standing, ROOM};

    #[test]
    fn directions_share_the_amount() {
        let boxes = [standing([0.4, 0.5, 0.4], 0.0, 0.0)];
        let m = |q: &str| moves(q, &boxes)[0];
        assert!(close(m("move X1 20 cm to the left"), [-0.2, 0.0, 0.0]));
        assert!(close(
            m("move X1 30 cm forward and to the right"),
            [0.3, 0.0, 0.3]
        ));
        assert!(close(m("move X1 1 ft up"), [0.0, 0.3048, 0.0]));
        assert!(close(m("move X1 back"), [0.0, 0.0, -1.0]));
        assert!(close(m("move X1 a bit further left"), [-0.1, 0.0, 0.0]));
        assert!(close(m("nudge X1 left"), [-0.1, 0.0, 0.0]));
        assert!(close(m("nudge X1 30 cm left"), [-0.3, 0.0, 0.0]));
        assert!(close(m("move X1 further left"), [-0.1, 0.0, 0.0]));
        assert!(close(m("move X1 to the lfet"), [-1.0, 0.0, 0.0]));
    }

    #[test]
    fn all_the_way_and_far_stop_at_the_wall() {
        let boxes = [on([0.4, 0.5, 0.4], 2.5, 0.5, 0.0)];
        let m = |q: &str| moves(q, &boxes)[0];
        let right = ROOM.1[0] - 2.7;
        assert!(close(
            m("move X1 all the way to the right"),
            [right, 0.0, 0.0]
        ));
        assert!(close(m("move X1 a lot to the right"), [right, 0.0, 0.0]));
        assert!(close(m("move X1 a lot to the left"), [-1.0, 0.0, 0.0]));
        assert!(close(m("move X1 all the way down"), [0.0, -0.5, 0.0]));
        // No direction, no verb that implies one: not read.
        assert!(outcome("move X1 20 cm", &boxes, true).is_err());
    }
}

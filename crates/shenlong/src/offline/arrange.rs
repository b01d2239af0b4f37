//! Arrangements of several objects: swapping two ("swap X1 and X2", "have X1 and X2 trade
//! places"), lining several up in a row ("line up X1, X2 and X3"), and aligning objects
//! with another along an axis ("align X1 with X2 along the z axis").

use super::build::*;
use super::clause::Clause;
use super::reader::{not_read, Produced, ReadError, Reader};
use super::relations::{boxed, Step, GAP};
use super::words::Token;

/// From where `from` stands to where `to` stands before the edit: centred there, its
/// bottom on `to`'s bottom.
fn to_place_of(from: usize, to: usize) -> crate::expr::Expr {
    sum([
        along(sub(var(to, "center"), var(from, "center")), 0),
        along(sub(var(to, "center"), var(from, "center")), 2),
        along(sub(var(to, "min"), var(from, "min")), 1),
    ])
}

/// The axis named by "along the x axis" (for align), its words read.
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

impl Reader<'_> {
    /// "swap X1 and X2": each goes to the other's place, centred where it stood, on its
    /// floor level.
    pub(super) fn swap(&mut self, c: &mut Clause, text: &str) -> Result<Produced, ReadError> {
        let vars = c.variables();
        if vars.is_empty() && self.last_subjects.len() == 2 {
            // "X1 and X2: swap them" ("swap 'em", "swap the two"): the two named before.
            let pronoun = (0..c.len())
                .find(|&i| c.free(i) && matches!(c.word(i), Some("them" | "em" | "both" | "they")));
            if let Some(i) = pronoun {
                c.mark(i..i + 1);
                c.mark_every(&["places", "positions", "round", "around", "over"]);
                let (a, b) = (self.last_subjects[0], self.last_subjects[1]);
                return Ok(Self::swapped(a, b));
            }
        }
        if vars.len() < 2 {
            return Err(not_read(text, text));
        }
        // "swap the chairs" with four chairs: which two is not said.
        if vars.len() > 2 {
            let known = self.facts.known;
            let names: Vec<String> = vars.iter().map(|&(_, v)| known.label(v)).collect();
            return Err(ReadError::Unclear(format!(
                "a swap takes two objects, and {} are named: say which two",
                names.join(", ")
            )));
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
                        | "spot"
                        | "corners"
                        | "corner"
                        | "sides"
                        | "seats"
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
        Ok(Self::swapped(a, b))
    }

    /// Each of `a` and `b` to the other's place, centred where it stood, on its floor
    /// level.
    fn swapped(a: usize, b: usize) -> Produced {
        vec![
            (a, Step::Translate(to_place_of(a, b))),
            (b, Step::Translate(to_place_of(b, a))),
        ]
    }

    /// "put X1 where X2 is", "X1 goes where X2 was": X1 to the place X2 stands in before
    /// the edit, centred there on its floor level, as one half of a swap ("… and X2 where
    /// X1 is" is the other half, read against the scene as it was). `None` when the clause
    /// says no such place.
    pub(super) fn where_is(
        &mut self,
        c: &mut Clause,
        text: &str,
    ) -> Option<Result<Produced, ReadError>> {
        let w = (0..c.len()).find(|&i| {
            c.free(i)
                && c.word(i) == Some("where")
                && matches!(c.token(i + 1), Some(Token::Variable(_)))
                && matches!(
                    c.word(i + 2),
                    Some("is" | "was" | "stands" | "stood" | "sits" | "sat" | "are" | "were")
                )
        })?;
        let Some(Token::Variable(t)) = c.token(w + 1).cloned() else {
            return None;
        };
        c.mark(w..w + 3);
        c.mark_every(&["now", "currently", "right", "to", "goes", "go"]);
        let subjects = match self.required_subjects(c, text) {
            Ok(s) => s,
            Err(e) => return Some(Err(e)),
        };
        Some(match subjects.as_slice() {
            [s] if *s != t => Ok(vec![(*s, Step::Translate(to_place_of(*s, t)))]),
            _ => Err(ReadError::Unclear(format!(
                "only one object can go where another is, in \"{}\"",
                text.trim()
            ))),
        })
    }

    /// "align X1 with X2" (along x, or the axis named): centred on X2 along that axis.
    /// With no `with` and several objects, a row ([`Reader::row`]).
    pub(super) fn align(&mut self, c: &mut Clause, text: &str) -> Result<Produced, ReadError> {
        let axis_named = named_axis(c);
        let with = c.find(&["with"]).or_else(|| c.find(&["to"]));
        let vars = c.variables();
        if with.is_none() && vars.len() >= 2 {
            return Ok(self.row(c, &vars));
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

    /// "line up X1, X2 and X3", "arrange them in a row": each of `vars` (the variables with
    /// their positions) after the first goes right of the one before, [`GAP`] from it,
    /// level with and centred on the first.
    fn row(&mut self, c: &mut Clause, vars: &[(usize, usize)]) -> Produced {
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
        for (i, _) in vars {
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
        out
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{close, moves, standing, Box3};
    use super::GAP;

    fn three() -> [Box3; 3] {
        [
            standing([0.4, 0.5, 0.4], -1.0, 1.0),
            standing([0.6, 0.8, 0.2], 1.0, -1.0),
            standing([0.2, 0.3, 0.2], 2.0, 0.5),
        ]
    }

    #[test]
    fn a_swap_exchanges_the_places() {
        let m = moves("swap X1 and X2", &three());
        assert!(close(m[0], [2.0, 0.0, -2.0]));
        assert!(close(m[1], [-2.0, 0.0, 2.0]));
        assert!(close(m[2], [0.0; 3]));
    }

    #[test]
    fn a_row_goes_right_of_the_first_level_and_centred_with_it() {
        let m = moves("line up X1, X2 and X3", &three());
        assert!(close(m[0], [0.0; 3]));
        // X2's left face GAP right of X1's right face (−0.8), centred on X1 along z.
        assert!(close(m[1], [-0.8 + GAP + 0.3 - 1.0, 0.0, 2.0]));
        // X3 GAP right of X2 where X2 went (its right face at −0.15).
        let x2_right = -0.8 + GAP + 0.6;
        assert!(close(m[2], [x2_right + GAP + 0.1 - 2.0, 0.0, 0.5]));
    }

    #[test]
    fn aligning_centres_along_the_axis_named() {
        let m = moves("align X1 with X2", &three());
        assert!(close(m[0], [2.0, 0.0, 0.0]));
        let m = moves("align X1 with X2 along the z axis", &three());
        assert!(close(m[0], [0.0, 0.0, -2.0]));
    }
}

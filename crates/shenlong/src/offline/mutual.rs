//! Moves of several objects relative to one another: "move X1 and X2 closer together",
//! "slide X1 and X2 towards each other", "push X1 and X2 a bit apart", "spread X1, X2 and
//! X3 further apart". Each subject moves along the line from the subjects' middle (their
//! centres' mean; for two, the line between them) through its own centre: inwards for
//! "together", outwards for "apart". A length is how much the gap between two changes, so
//! each moves half of it; a vague amount ("a bit apart") is each one's move.

use super::amounts::{self, Length};
use super::build::{call, div, flat, mul, num, sub};
use super::clause::Clause;
use super::reader::{not_read, Produced, ReadError, Reader};
use super::relations::{boxed, middle, Step};

/// Which way the subjects go relative to one another.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Way {
    /// Towards their middle.
    Together,
    /// Away from their middle.
    Apart,
}

/// The phrases that say it, longest first.
const PHRASES: &[(&[&str], Way)] = &[
    (&["further", "away", "from", "each", "other"], Way::Apart),
    (&["farther", "away", "from", "each", "other"], Way::Apart),
    (&["away", "from", "each", "other"], Way::Apart),
    (&["further", "from", "each", "other"], Way::Apart),
    (&["closer", "to", "each", "other"], Way::Together),
    (&["nearer", "to", "each", "other"], Way::Together),
    (&["in", "towards", "each", "other"], Way::Together),
    (&["towards", "each", "other"], Way::Together),
    (&["toward", "each", "other"], Way::Together),
    (&["closer", "together"], Way::Together),
    (&["nearer", "together"], Way::Together),
    (&["further", "apart"], Way::Apart),
    (&["farther", "apart"], Way::Apart),
    (&["wider", "apart"], Way::Apart),
    (&["apart"], Way::Apart),
];

/// How far each moves with no amount said: a bit.
const EACH_BY_DEFAULT: f64 = amounts::BIT_METRES;

impl Reader<'_> {
    /// The clause as a move of its subjects relative to one another, when it says one and
    /// names at least two subjects; `None` otherwise (the phrase is then not read here).
    ///
    /// # Errors
    /// An amount that is not a length ("as far as it will go").
    pub(super) fn mutual(
        &mut self,
        c: &mut Clause,
        text: &str,
    ) -> Option<Result<Produced, ReadError>> {
        let (at, len, way) = (0..c.len()).find_map(|i| {
            PHRASES
                .iter()
                .find(|(words, _)| (i..i + words.len()).all(|k| c.free(k)) && c.words_at(i, words))
                .map(|(words, way)| (i, words.len(), *way))
        })?;
        let named = c.variables().into_iter().filter(|&(i, _)| i < at).count();
        if named < 2 {
            return None;
        }
        c.mark(at..at + len);
        let subjects = match self.required_subjects(c, text) {
            Ok(s) => s,
            Err(e) => return Some(Err(e)),
        };
        // "a bit apart": each a bit (an amount named vaguely is each one's move, as
        // everywhere else); "1 m closer together": the gap 1 m less, so half each.
        let vague = amounts::says_vague(c);
        let each = match amounts::length(c, true) {
            Some(Length::Metres(m)) if vague => m,
            Some(Length::Metres(m)) => m / 2.0,
            Some(Length::Far) => amounts::FAR_METRES / 2.0,
            None => EACH_BY_DEFAULT,
            Some(_) => return Some(Err(not_read(text, text))),
        };
        let centre = middle(&subjects, &self.steps);
        let sign = match way {
            Way::Together => -1.0,
            Way::Apart => 1.0,
        };
        Some(Ok(subjects
            .iter()
            .map(|&s| {
                let out = flat(sub(boxed(s, "center", &self.steps), centre.clone()));
                let unit = div(out.clone(), call("abs", vec![out]));
                (s, Step::Translate(mul(num(sign * each), unit)))
            })
            .collect()))
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{moves, standing};

    #[test]
    fn together_and_apart_along_the_line_between_them() {
        let two = [
            standing([0.4, 0.5, 0.4], -1.0, 0.0),
            standing([0.4, 0.5, 0.4], 1.0, 0.0),
        ];
        let m = moves("move X1 and X2 1 m closer together", &two);
        assert!(
            (m[0].x - 0.5).abs() < 1e-9 && (m[1].x + 0.5).abs() < 1e-9,
            "{m:?}"
        );
        let m = moves("push X1 and X2 a bit apart", &two);
        assert!(
            m[0].x < -0.01 && m[1].x > 0.01 && m[0].z.abs() < 1e-9,
            "{m:?}"
        );
        let m = moves("slide X1 and X2 a little toward each other", &two);
        assert!(m[0].x > 0.0 && m[1].x < 0.0, "{m:?}");
    }

    #[test]
    fn three_spread_from_their_middle() {
        let three = [
            standing([0.4, 0.5, 0.4], -1.0, 0.0),
            standing([0.4, 0.5, 0.4], 1.0, 0.0),
            standing([0.4, 0.5, 0.4], 0.0, 1.0),
        ];
        let m = moves("spread X1, X2 and X3 further apart", &three);
        assert!(m[0].x < 0.0 && m[1].x > 0.0 && m[2].z > 0.0, "{m:?}");
    }
}

//! Repeats: "do the same for X2", "X2 too", "move X2 the other way", "mirror that for X2":
//! the previous clause's plain moves and turns, applied to other objects as they were,
//! reversed, or mirrored left–right. A clause that says what to do itself (a number, a
//! direction, a relation) is not a repeat.

use super::build::*;
use super::clause::Clause;
use super::reader::{Produced, Reader};
use super::relations::Step;
use super::words::{self, Token};

/// How a repeat changes the steps it repeats.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Repeat {
    /// As they were ("the same", "too", "likewise", "as well").
    Same,
    /// Reversed ("the opposite", "the other way", "in reverse").
    Opposite,
    /// Mirrored left–right ("mirror that", "symmetrically").
    Mirror,
}

/// The words that make a repeat, read once it is one.
const REPEAT_WORDS: &[&str] = &[
    "same",
    "likewise",
    "too",
    "as",
    "well",
    "opposite",
    "other",
    "way",
    "reverse",
    "mirror",
    "mirrored",
    "symmetrically",
    "do",
    "for",
    "with",
    "that",
    "thing",
    "move",
    "to",
    "it",
    "this",
    "direction",
];

/// The repeat the clause asks for, by its words read or not; `None` when it asks for none,
/// or says what to do itself (a number, a direction, a relation, a turn).
fn repeat_of(c: &Clause) -> Option<Repeat> {
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
    if content {
        return None;
    }
    // Reversing wins over mirroring, and both over repeating as is.
    if opposite {
        Some(Repeat::Opposite)
    } else if mirror {
        Some(Repeat::Mirror)
    } else if same {
        Some(Repeat::Same)
    } else {
        None
    }
}

/// `step` as the repeat makes it.
fn transform(step: &Step, repeat: Repeat) -> Step {
    match (step, repeat) {
        (Step::Translate(v), Repeat::Opposite) => Step::Translate(neg(v.clone())),
        (Step::Translate(v), Repeat::Mirror) => {
            Step::Translate(sub(v.clone(), mul(num(2.0), along(v.clone(), 0))))
        }
        (Step::Turn(e), Repeat::Opposite | Repeat::Mirror) => Step::Turn(reverse(e.clone())),
        (other, _) => other.clone(),
    }
}

impl Reader<'_> {
    /// The previous clause's steps repeated for this clause's objects ([`Repeat`]); `None`
    /// when the clause is no repeat, the previous clause did nothing or placed its objects
    /// by a relation (relations name their subject's own box), or names no other object.
    pub(super) fn repeat(&mut self, c: &mut Clause) -> Option<Produced> {
        if self.last_steps.is_empty() {
            return None;
        }
        let repeat = repeat_of(c)?;
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
            if c.word(i).is_some_and(|w| REPEAT_WORDS.contains(&w)) {
                c.mark(i..i + 1);
            }
        }
        self.last_subjects = subjects.clone();
        Some(
            subjects
                .iter()
                .flat_map(|&s| {
                    self.last_steps
                        .iter()
                        .map(move |step| (s, transform(step, repeat)))
                })
                .collect(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{close, moves, standing, turns, Box3};

    fn two() -> [Box3; 2] {
        [
            standing([0.4, 0.5, 0.4], -1.0, 0.0),
            standing([0.4, 0.5, 0.4], 1.0, 0.0),
        ]
    }

    #[test]
    fn the_same_the_other_way_and_mirrored() {
        let m = moves(
            "move X1 30 cm left and 20 cm forward and do the same for X2",
            &two(),
        );
        // "and 20 cm forward" is its own clause: the last clause's move is what repeats.
        assert!(close(m[0], [-0.3, 0.0, 0.2]));
        assert!(close(m[1], [0.0, 0.0, 0.2]));
        let m = moves("move X1 30 cm left, then move X2 the other way", &two());
        assert!(close(m[1], [0.3, 0.0, 0.0]));
        let m = moves(
            "move X1 30 cm left and 10 cm up, and mirror that for X2",
            &two(),
        );
        assert!(close(m[1], [0.0, 0.1, 0.0]));
        let m = moves("move X1 30 cm left and X2 too", &two());
        assert!(close(m[1], [-0.3, 0.0, 0.0]));
    }

    #[test]
    fn a_turn_mirrored_is_the_other_sense() {
        let t = turns(
            "turn X1 30 degrees clockwise and mirror that for X2",
            &two(),
        );
        assert!((t[0] + 30.0).abs() < 1e-9 && (t[1] - 30.0).abs() < 1e-9);
    }

    #[test]
    fn a_relation_is_not_repeated() {
        let boxes = two();
        let result = super::super::testing::outcome(
            "put X1 next to X2 and do the same for X2",
            &boxes,
            true,
        );
        assert!(result.is_err());
    }
}

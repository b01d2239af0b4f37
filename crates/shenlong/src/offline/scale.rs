//! Scale factors: `by 1.5`, `20 percent smaller`, `down by 20 %`, `to 80 % of its size`,
//! `half as big`, `twice the size`, `by a third`, `three times bigger`, `a bit smaller`,
//! `bigger` (documented defaults in docs/offline.md). The first amount in the clause says
//! the factor; the size words say which way it goes.

use super::amounts::{fraction_at, number_at, BIT, FAR};
use super::build::dilator;
use super::clause::Clause;
use super::reader::{not_read, Produced, ReadError, Reader};
use super::relations::Step;
use super::words::Token;

/// Whether the clause asks to make the object smaller (`smaller`, `shrink`, `down`,
/// `reduce`) or larger.
fn shrinking(c: &Clause) -> Option<bool> {
    for i in 0..c.len() {
        match c.word(i) {
            Some(
                "smaller" | "shrink" | "shrunk" | "reduce" | "decrease" | "down" | "less"
                | "tinier" | "halve",
            ) => return Some(true),
            Some(
                "bigger" | "larger" | "grow" | "enlarge" | "up" | "increase" | "magnify" | "taller"
                | "double" | "triple",
            ) => return Some(false),
            _ => {}
        }
    }
    None
}

/// The size words of a scale clause that carry no number of their own, read once the
/// factor is known.
const SIZE_WORDS: &[&str] = &[
    "smaller", "bigger", "larger", "taller", "tinier", "shrink", "grow", "enlarge", "reduce",
    "decrease", "increase", "magnify", "down", "up", "size", "its", "of", "in", "original",
    "current", "as", "big", "large", "small", "the", "scale", "resize", "make", "it", "them",
];

/// A number at `i` with what follows it: `N percent` (`to N percent`: of the size),
/// `N times`, `N x`, `N as big`; its words read. `down`: the clause shrinks.
fn number_factor_at(c: &mut Clause, i: usize, down: bool) -> Option<f64> {
    let (n, len) = number_at(c, i)?;
    if c.word(i + len) == Some("percent") {
        let to = i > 0 && c.word(i - 1) == Some("to");
        c.mark(i..i + len + 1);
        if to {
            c.mark(i - 1..i);
        }
        c.mark_by(i);
        return Some(if to {
            n / 100.0
        } else if down {
            1.0 - n / 100.0
        } else {
            1.0 + n / 100.0
        });
    }
    // "three times bigger", "3 times as big", "3 times smaller".
    if c.word(i + len) == Some("times") || c.word(i + len) == Some("x") {
        c.mark(i..i + len + 1);
        return Some(if down { 1.0 / n } else { n });
    }
    if c.words_at(i + len, &["as"]) {
        c.mark(i..i + len);
        return Some(n);
    }
    None
}

/// "by a factor of N", "factor of N" at `i`, its words read.
fn factor_of_at(c: &mut Clause, i: usize, down: bool) -> Option<f64> {
    if !(c.words_at(i, &["a", "factor", "of"]) || c.words_at(i, &["factor", "of"])) {
        return None;
    }
    let len = if c.words_at(i, &["a"]) { 3 } else { 2 };
    let (n, l) = number_at(c, i + len)?;
    c.mark(i..i + len + l);
    c.mark_by(i);
    Some(if down && n > 1.0 { 1.0 / n } else { n })
}

/// A word that is a factor at `i` (`twice`, `double`, `thrice`, `triple`, `halve`), read.
fn word_factor_at(c: &mut Clause, i: usize) -> Option<f64> {
    let mut factor = None;
    for (words, f) in [
        (&["twice"][..], 2.0),
        (&["double"][..], 2.0),
        (&["thrice"][..], 3.0),
        (&["triple"][..], 3.0),
        (&["halve"][..], 0.5),
    ] {
        if c.words_at(i, words) {
            c.mark(i..i + words.len());
            factor = Some(f);
        }
    }
    factor
}

/// A fraction at `i`: "by half", "by a third" (a change by that part), "to half its
/// size", "to a third of its size", "half as big", "half the size" (that part of the
/// size); its words read.
fn fraction_factor_at(c: &mut Clause, i: usize, shrink: Option<bool>) -> Option<f64> {
    let (f, len) = fraction_at(c, i)?;
    let to = i > 0 && c.word(i - 1) == Some("to");
    let by = i > 0 && c.word(i - 1) == Some("by");
    let as_big = c.words_at(i + len, &["as"])
        || c.words_at(i + len, &["the", "size"])
        || c.words_at(i + len, &["its", "size"])
        || c.words_at(i + len, &["of", "its"]);
    c.mark(i..i + len);
    if to || by {
        c.mark(i - 1..i);
    }
    Some(if to || as_big || (!by && shrink.is_none()) {
        f
    } else if shrink == Some(true) {
        1.0 - f
    } else {
        1.0 + f
    })
}

/// A bare number at `i`: "by 1.5", "scale it 2", "to 0.8"; its words read.
fn bare_factor_at(c: &mut Clause, i: usize, down: bool) -> Option<f64> {
    let (n, len) = number_at(c, i)?;
    if !(n > 0.0 && matches!(c.token(i), Some(Token::Number(_)))) {
        return None;
    }
    c.mark(i..i + len);
    c.mark_by(i);
    if i > 0 && c.word(i - 1) == Some("to") {
        c.mark(i - 1..i);
    }
    Some(if down && n > 1.0 { 1.0 / n } else { n })
}

/// The factor the first amount of the clause says, its words read; `None` when it names
/// no amount.
fn named_factor(c: &mut Clause, shrink: Option<bool>) -> Option<f64> {
    let down = shrink == Some(true);
    for i in 0..c.len() {
        if !c.free(i) {
            continue;
        }
        let factor = number_factor_at(c, i, down)
            .or_else(|| factor_of_at(c, i, down))
            .or_else(|| word_factor_at(c, i))
            .or_else(|| fraction_factor_at(c, i, shrink))
            .or_else(|| bare_factor_at(c, i, down));
        if factor.is_some() {
            return factor;
        }
    }
    None
}

/// No number: a vague change with documented defaults — a bit (×0.9, ×1.1), much (×0.5,
/// ×2), else ×0.8 or ×1.25; its words read. `None` when the clause says neither smaller
/// nor larger.
fn vague_factor(c: &mut Clause, shrink: Option<bool>) -> Option<f64> {
    let bit = (0..c.len()).any(|i| BIT.iter().any(|w| c.free(i) && c.words_at(i, w)));
    let much = (0..c.len()).any(|i| {
        c.free(i)
            && (c.words_at(i, &["much"]) || c.words_at(i, &["a", "lot"]) || c.words_at(i, &["way"]))
    });
    for i in 0..c.len() {
        for w in BIT.iter().chain(FAR) {
            if c.free(i) && c.words_at(i, w) {
                c.mark(i..i + w.len());
            }
        }
    }
    Some(match (shrink?, bit, much) {
        (true, true, _) => 0.9,
        (false, true, _) => 1.1,
        (true, _, true) => 0.5,
        (false, _, true) => 2.0,
        (true, false, false) => 0.8,
        (false, false, false) => 1.25,
    })
}

/// Finds a scale factor ([`self`]) and reads the size words.
pub(crate) fn scale(c: &mut Clause) -> Option<f64> {
    let shrink = shrinking(c);
    // "double the size of X1", "halve it": the verb is the factor, unless a number says
    // otherwise.
    let verb_factor = (0..c.len()).find_map(|i| match c.word(i) {
        Some("double") => Some(2.0),
        Some("triple") => Some(3.0),
        Some("halve") => Some(0.5),
        _ => None,
    });
    let factor = match named_factor(c, shrink).or(verb_factor) {
        Some(f) => f,
        None => vague_factor(c, shrink)?,
    };
    // The size words are read now: "20 percent smaller", "twice as big".
    for i in 0..c.len() {
        if let Some(w) = c.word(i) {
            if c.free(i) && SIZE_WORDS.contains(&w) {
                c.mark(i..i + 1);
            }
        }
    }
    (factor > 0.0 && factor.is_finite()).then_some(factor)
}

impl Reader<'_> {
    /// "make X1 20 % bigger": each subject scaled about itself by the factor ([`scale`]).
    pub(super) fn scale(&mut self, c: &mut Clause, text: &str) -> Result<Produced, ReadError> {
        let subjects = self.required_subjects(c, text)?;
        let factor = scale(c).ok_or_else(|| not_read(text, text))?;
        Ok(subjects
            .iter()
            .map(|&s| (s, Step::Turn(dilator(factor))))
            .collect())
    }
}

#[cfg(test)]
mod tests {
    use super::super::clause::split;
    use super::super::testing::{outcome, standing};
    use super::super::words::tokenize;

    /// The factor read from `text`, and whether every word of it was read.
    fn factor(text: &str) -> (Option<f64>, bool) {
        let mut c = split(&tokenize(text)).remove(0);
        let f = super::scale(&mut c);
        (f, c.unread().is_empty())
    }

    #[test]
    fn numbers_fractions_and_words_say_the_factor() {
        for (text, want) in [
            ("20 percent smaller", 0.8),
            ("up by 20 percent", 1.2),
            ("to 80 percent of its size", 0.8),
            ("three times bigger", 3.0),
            ("3 times smaller", 1.0 / 3.0),
            ("by a factor of 2", 2.0),
            ("smaller by a factor of 4", 0.25),
            ("twice as big", 2.0),
            ("by a third", 4.0 / 3.0),
            ("smaller by a third", 2.0 / 3.0),
            ("to half its size", 0.5),
            ("half as big", 0.5),
            ("by 1.5", 1.5),
            ("down by 2", 0.5),
        ] {
            let (f, read) = factor(text);
            let f = f.unwrap_or_else(|| panic!("{text}: no factor"));
            assert!((f - want).abs() < 1e-12, "{text}: {f}");
            assert!(read, "{text}: words left");
        }
    }

    #[test]
    fn vague_changes_have_defaults_and_need_a_sense() {
        for (text, want) in [
            ("a bit smaller", 0.9),
            ("a bit bigger", 1.1),
            ("much smaller", 0.5),
            ("a lot bigger", 2.0),
            ("smaller", 0.8),
            ("bigger", 1.25),
        ] {
            assert_eq!(factor(text).0, Some(want), "{text}");
        }
        assert_eq!(factor("a bit").0, None);
    }

    #[test]
    fn a_scale_changes_only_the_size() {
        let boxes = [standing([0.4, 0.5, 0.4], 1.0, 0.0)];
        let s = outcome("make X1 20 % bigger", &boxes, true).unwrap();
        assert!((s[0].scale - 1.2).abs() < 1e-9);
        assert!(s[0].translation.length() < 1e-9);
        let doubled = outcome("double the size of X1", &boxes, true).unwrap();
        assert!((doubled[0].scale - 2.0).abs() < 1e-9);
    }
}

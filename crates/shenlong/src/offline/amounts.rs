//! Amounts: lengths, angles and scale factors, written as numbers with units, spoken
//! compounds ("a metre and a half") or vague words ("a bit") with documented defaults.

use super::clause::Clause;
use super::words::{angle_unit, length_unit, number_word, Token};

/// "a bit", "slightly", "a little", "a touch", "just a bit": a small amount.
pub const BIT_METRES: f64 = 0.10;
/// "a smidge", "a hair", "a tiny bit", "a fraction": a tiny amount.
pub const TINY_METRES: f64 = 0.05;
/// The small amount for turns.
pub const BIT_DEGREES: f64 = 15.0;
/// "a lot", "far", "way over": this far, or to the nearest wall if that is nearer.
pub const FAR_METRES: f64 = 1.0;
/// The default move with no amount.
pub const DEFAULT_METRES: f64 = 1.0;
/// The default turn with no amount.
pub const DEFAULT_DEGREES: f64 = 90.0;
/// "a few" of a unit.
pub const FEW: f64 = 3.0;
/// "a couple of" a unit.
pub const COUPLE: f64 = 2.0;

/// A length an instruction names.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Length {
    /// So many metres.
    Metres(f64),
    /// Far: [`FAR_METRES`] or to the nearest wall, whichever is less.
    Far,
    /// All the way: against the wall.
    ToWall,
    /// As far as it will go: up to the first obstacle in the way (or the wall), 1 cm short.
    UntilBlocked,
}

/// "as far as it will go", "until it hits something": up to the first obstacle.
const UNTIL_BLOCKED: &[&[&str]] = &[
    &["as", "far", "as", "it", "will", "go"],
    &["as", "far", "as", "it", "can", "go"],
    &["as", "far", "as", "it", "would", "go"],
    &["as", "far", "as", "it'll", "go"],
    &["as", "far", "as", "it", "goes"],
    &["as", "far", "as", "they", "will", "go"],
    &["as", "far", "as", "they", "can", "go"],
    &["as", "far", "as", "they", "go"],
    &["as", "far", "as", "possible"],
    &["as", "far", "as", "you", "can"],
    &["until", "it", "hits", "something"],
    &["until", "it", "hits", "anything"],
    &["until", "it", "touches", "something"],
    &["until", "it", "bumps", "into", "something"],
    &["until", "it", "stops"],
    &["till", "it", "hits", "something"],
    &["until", "it's", "blocked"],
];

/// Finds "as far as it will go" (also with the direction inside: "as far right as it
/// will go", the direction left for the reader), marks it read and says whether it was
/// there.
pub(crate) fn until_blocked(c: &mut Clause) -> bool {
    for i in 0..c.len() {
        if let Some(p) = UNTIL_BLOCKED.iter().find(|p| c.words_at(i, p)) {
            c.mark(i..i + p.len());
            return true;
        }
        // "as far right as it will go".
        if c.words_at(i, &["as", "far"])
            && c.word(i + 2).and_then(super::words::direction).is_some()
        {
            if let Some(p) = UNTIL_BLOCKED
                .iter()
                .find(|p| p[0] == "as" && c.words_at(i + 3, &p[2..]))
            {
                c.mark(i..i + 2);
                c.mark(i + 3..i + 3 + p.len() - 2);
                return true;
            }
        }
    }
    false
}

/// The small-amount phrases, longest first; each counts as a bit.
const BIT: &[&[&str]] = &[
    &["just", "a", "little", "bit"],
    &["a", "tiny", "bit"],
    &["a", "little", "bit"],
    &["just", "a", "bit"],
    &["a", "wee", "bit"],
    &["a", "bit", "more"],
    &["a", "little", "more"],
    &["a", "bit"],
    &["a", "little"],
    &["a", "touch"],
    &["a", "tad"],
    &["a", "smidge"],
    &["a", "hair"],
    &["a", "fraction"],
    &["slightly"],
    &["somewhat"],
    &["marginally"],
    &["bit"],
];

/// The small-amount phrases that say "tiny": [`TINY_METRES`] (turns take the small angle).
const TINY: &[&[&str]] = &[
    &["a", "tiny", "bit"],
    &["a", "smidge"],
    &["a", "hair"],
    &["a", "fraction"],
];

/// "a good bit", "a fair bit", "quite a bit": more than a bit, less than a lot.
pub const GOOD_BIT_METRES: f64 = 0.30;

/// The moderate-amount phrases ([`GOOD_BIT_METRES`]).
const GOOD_BIT: &[&[&str]] = &[
    &["a", "good", "bit"],
    &["a", "fair", "bit"],
    &["quite", "a", "bit"],
    &["a", "fair", "way"],
    &["a", "good", "few", "centimetres"],
];

/// The large-amount phrases.
const FAR: &[&[&str]] = &[
    &["a", "long", "way"],
    &["a", "good", "way"],
    &["way", "over"],
    &["a", "lot"],
    &["far"],
    &["much"],
    &["way"],
];

/// A number at token `i`, spoken or written, and how many tokens it takes: `2`, `two`,
/// `one and a half`, `two and a half`, `half`, `a quarter of`, `three quarters of`.
fn number_at(c: &Clause, i: usize) -> Option<(f64, usize)> {
    let base = match c.token(i)? {
        Token::Number(n) => *n,
        Token::Word(w) => number_word(w)?,
        _ => return None,
    };
    // "one and a half", "2 and a half".
    if c.words_at(i + 1, &["and", "a", "half"]) {
        return Some((base + 0.5, 4));
    }
    if c.words_at(i + 1, &["and", "a", "quarter"]) {
        return Some((base + 0.25, 4));
    }
    // "three quarters of a", "two thirds of a".
    for (word, part) in [("quarters", 0.25), ("thirds", 1.0 / 3.0)] {
        if c.words_at(i + 1, &[word]) {
            let mut len = 2;
            if c.words_at(i + 2, &["of"]) {
                len = 3;
                if c.words_at(i + 3, &["a"]) || c.words_at(i + 3, &["an"]) {
                    len = 4;
                }
            }
            return Some((base * part, len));
        }
    }
    Some((base, 1))
}

/// A fraction word at `i` and its length: `half a`, `a half`, `a quarter of a`, `a third
/// of`.
fn fraction_at(c: &Clause, i: usize) -> Option<(f64, usize)> {
    for (words, value) in [
        (&["half", "a"][..], 0.5),
        (&["half", "an"][..], 0.5),
        (&["a", "half"][..], 0.5),
        (&["half"][..], 0.5),
        (&["a", "quarter", "of", "a"][..], 0.25),
        (&["a", "quarter", "of"][..], 0.25),
        (&["a", "quarter"][..], 0.25),
        (&["quarter", "of", "a"][..], 0.25),
        (&["quarter"][..], 0.25),
        (&["a", "third", "of", "a"][..], 1.0 / 3.0),
        (&["a", "third", "of"][..], 1.0 / 3.0),
        (&["a", "third"][..], 1.0 / 3.0),
    ] {
        if c.words_at(i, words) {
            return Some((value, words.len()));
        }
    }
    None
}

/// Finds a length in the clause, marks its tokens read, and returns it. With `bare`, a
/// number without a unit is metres ("2 units" and "2" read alike).
pub(crate) fn length(c: &mut Clause, bare: bool) -> Option<Length> {
    if std::mem::take(&mut c.until_blocked) {
        return Some(Length::UntilBlocked);
    }
    for i in 0..c.len() {
        if !c.free(i) {
            continue;
        }
        if c.words_at(i, &["all", "the", "way"]) {
            c.mark(i..i + 3);
            return Some(Length::ToWall);
        }
        // "a few centimetres", "a couple of feet".
        for (words, n) in [
            (&["a", "few"][..], FEW),
            (&["a", "couple", "of"][..], COUPLE),
            (&["a", "couple"][..], COUPLE),
            (&["couple", "of"][..], COUPLE),
        ] {
            if c.words_at(i, words) {
                if let Some(unit) = c.word(i + words.len()).and_then(length_unit) {
                    c.mark(i..i + words.len() + 1);
                    c.mark_by(i);
                    return Some(Length::Metres(n * unit));
                }
            }
        }
        // "a metre and a half", "an inch".
        if c.words_at(i, &["a"]) || c.words_at(i, &["an"]) || c.words_at(i, &["one"]) {
            if let Some(unit) = c.word(i + 1).and_then(length_unit) {
                let mut len = 2;
                let mut n = 1.0;
                if c.words_at(i + 2, &["and", "a", "half"]) {
                    n = 1.5;
                    len = 5;
                }
                c.mark(i..i + len);
                c.mark_by(i);
                return Some(Length::Metres(n * unit));
            }
        }
        if let Some((f, len)) = fraction_at(c, i) {
            if let Some(unit) = c.word(i + len).and_then(length_unit) {
                c.mark(i..i + len + 1);
                c.mark_by(i);
                return Some(Length::Metres(f * unit));
            }
        }
        if let Some((n, len)) = number_at(c, i) {
            if let Some(unit) = c.word(i + len).and_then(length_unit) {
                // "2 in front of" is not inches.
                let inches_not = c.word(i + len) == Some("in")
                    && matches!(c.word(i + len + 1), Some("front" | "the" | "a" | "back"));
                if !inches_not {
                    c.mark(i..i + len + 1);
                    c.mark_by(i);
                    return Some(Length::Metres(n * unit));
                }
            }
            let is_angle = c.word(i + len).and_then(angle_unit).is_some()
                || c.word(i + len) == Some("percent")
                || c.word(i + len) == Some("times");
            if bare
                && !is_angle
                && matches!(c.token(i), Some(Token::Number(_)) | Some(Token::Word(_)))
            {
                // A number word alone is a count elsewhere ("one of"); only digits are bare
                // lengths, and spoken ones before "and a half".
                if matches!(c.token(i), Some(Token::Number(_))) || len > 1 {
                    c.mark(i..i + len);
                    c.mark_by(i);
                    return Some(Length::Metres(n));
                }
            }
        }
    }
    for i in 0..c.len() {
        for words in GOOD_BIT {
            if c.free(i) && c.words_at(i, words) {
                c.mark(i..i + words.len());
                c.mark_by(i);
                return Some(Length::Metres(GOOD_BIT_METRES));
            }
        }
        for words in BIT {
            if c.free(i) && c.words_at(i, words) {
                c.mark(i..i + words.len());
                c.mark_by(i);
                let tiny = TINY.contains(words);
                return Some(Length::Metres(if tiny { TINY_METRES } else { BIT_METRES }));
            }
        }
        for words in FAR {
            if c.free(i) && c.words_at(i, words) {
                c.mark(i..i + words.len());
                return Some(Length::Far);
            }
        }
    }
    None
}

/// Finds an angle in degrees: `45 degrees`, `a quarter turn`, `half a turn`, `a bit`.
pub(crate) fn angle(c: &mut Clause) -> Option<f64> {
    for i in 0..c.len() {
        if !c.free(i) {
            continue;
        }
        for (words, d) in [
            (&["a", "quarter", "turn"][..], 90.0),
            (&["a", "quarter", "of", "a", "turn"][..], 90.0),
            (&["quarter", "turn"][..], 90.0),
            (&["a", "half", "turn"][..], 180.0),
            (&["half", "a", "turn"][..], 180.0),
            (&["half", "turn"][..], 180.0),
            (&["a", "full", "turn"][..], 360.0),
            (&["full", "turn"][..], 360.0),
            (&["three", "quarters", "of", "a", "turn"][..], 270.0),
            (&["a", "quarter"][..], 90.0),
        ] {
            if c.words_at(i, words) {
                c.mark(i..i + words.len());
                c.mark_by(i);
                return Some(d);
            }
        }
        if let Some((n, len)) = number_at(c, i) {
            if let Some(unit) = c.word(i + len).and_then(angle_unit) {
                c.mark(i..i + len + 1);
                c.mark_by(i);
                return Some(n * unit);
            }
            if matches!(c.token(i), Some(Token::Number(_)))
                && c.word(i + len).and_then(length_unit).is_none()
            {
                c.mark(i..i + len);
                c.mark_by(i);
                return Some(n);
            }
        }
    }
    for i in 0..c.len() {
        for words in BIT {
            if c.free(i) && c.words_at(i, words) {
                c.mark(i..i + words.len());
                c.mark_by(i);
                return Some(BIT_DEGREES);
            }
        }
    }
    None
}

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

/// Finds a scale factor: `by 1.5`, `20 percent smaller`, `down by 20 %`, `to 80 % of its
/// size`, `half as big`, `twice the size`, `by a third`, `three times bigger`, `a bit
/// smaller`, `bigger` (documented defaults in docs/offline.md).
pub(crate) fn scale(c: &mut Clause) -> Option<f64> {
    let shrink = shrinking(c);
    let down = shrink == Some(true);
    // "double the size of X1", "halve it": the verb is the factor, unless a number says
    // otherwise.
    let verb_factor = (0..c.len()).find_map(|i| match c.word(i) {
        Some("double") => Some(2.0),
        Some("triple") => Some(3.0),
        Some("halve") => Some(0.5),
        _ => None,
    });
    let mut factor = None;
    for i in 0..c.len() {
        if !c.free(i) {
            continue;
        }
        // N percent.
        if let Some((n, len)) = number_at(c, i) {
            if c.word(i + len) == Some("percent") {
                let to = i > 0 && c.word(i - 1) == Some("to");
                c.mark(i..i + len + 1);
                if to {
                    c.mark(i - 1..i);
                }
                c.mark_by(i);
                factor = Some(if to {
                    n / 100.0
                } else if down {
                    1.0 - n / 100.0
                } else {
                    1.0 + n / 100.0
                });
                break;
            }
            // "three times bigger", "3 times as big", "3 times smaller".
            if c.word(i + len) == Some("times") || c.word(i + len) == Some("x") {
                c.mark(i..i + len + 1);
                factor = Some(if down { 1.0 / n } else { n });
                break;
            }
            if c.words_at(i + len, &["as"]) {
                c.mark(i..i + len);
                factor = Some(n);
                break;
            }
        }
        // "by a factor of N".
        if c.words_at(i, &["a", "factor", "of"]) || c.words_at(i, &["factor", "of"]) {
            let len = if c.words_at(i, &["a"]) { 3 } else { 2 };
            if let Some((n, l)) = number_at(c, i + len) {
                c.mark(i..i + len + l);
                c.mark_by(i);
                factor = Some(if down && n > 1.0 { 1.0 / n } else { n });
                break;
            }
        }
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
        if factor.is_some() {
            break;
        }
        // "by half", "by a third", "to half its size", "to a third of its size", "half as
        // big", "half the size".
        if let Some((f, len)) = fraction_at(c, i) {
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
            factor = Some(if to || as_big || (!by && shrink.is_none()) {
                f
            } else if down {
                1.0 - f
            } else {
                1.0 + f
            });
            break;
        }
        // "by 1.5", "scale it 2", "to 0.8".
        if let Some((n, len)) = number_at(c, i) {
            if n > 0.0 && matches!(c.token(i), Some(Token::Number(_))) {
                c.mark(i..i + len);
                c.mark_by(i);
                if i > 0 && c.word(i - 1) == Some("to") {
                    c.mark(i - 1..i);
                }
                factor = Some(if down && n > 1.0 { 1.0 / n } else { n });
                break;
            }
        }
    }
    let factor = match factor.or(verb_factor) {
        Some(f) => f,
        None => {
            // No number: a vague change with documented defaults.
            let bit = (0..c.len()).any(|i| BIT.iter().any(|w| c.free(i) && c.words_at(i, w)));
            let much = (0..c.len()).any(|i| {
                c.free(i)
                    && (c.words_at(i, &["much"])
                        || c.words_at(i, &["a", "lot"])
                        || c.words_at(i, &["way"]))
            });
            for i in 0..c.len() {
                for w in BIT.iter().chain(FAR) {
                    if c.free(i) && c.words_at(i, w) {
                        c.mark(i..i + w.len());
                    }
                }
            }
            match (shrink?, bit, much) {
                (true, true, _) => 0.9,
                (false, true, _) => 1.1,
                (true, _, true) => 0.5,
                (false, _, true) => 2.0,
                (true, false, false) => 0.8,
                (false, false, false) => 1.25,
            }
        }
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

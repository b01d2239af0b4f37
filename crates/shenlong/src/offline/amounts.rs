//! Amounts: lengths and angles, written as numbers with units, spoken compounds ("a metre
//! and a half") or vague words ("a bit") with documented defaults; the numbers and vague
//! words scale factors are read from too ([`super::scale`]).

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
pub(super) const BIT: &[&[&str]] = &[
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
pub(super) const FAR: &[&[&str]] = &[
    &["quite", "a", "long", "way"],
    &["quite", "a", "lot"],
    &["a", "long", "way"],
    &["a", "good", "way"],
    &["way", "over"],
    &["a", "lot"],
    &["loads"],
    &["heaps"],
    &["tons"],
    &["far"],
    &["much"],
    &["way"],
];

/// A number at token `i`, spoken or written, and how many tokens it takes: `2`, `two`,
/// `one and a half`, `two and a half`, `half`, `a quarter of`, `three quarters of`.
pub(super) fn number_at(c: &Clause, i: usize) -> Option<(f64, usize)> {
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
pub(super) fn fraction_at(c: &Clause, i: usize) -> Option<(f64, usize)> {
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
                let inches_not = not_inches(c, i + len);
                if !inches_not {
                    c.mark(i..i + len + 1);
                    c.mark_by(i);
                    let rest = smaller_part(c, i + len + 1, unit);
                    return Some(Length::Metres(n * unit + rest));
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
    vague_length(c)
}

/// Whether the `in` at `k` starts a place, not inches: `in front of`, `in the …`, `in a
/// …`, `in back of` ("6 in back" is six inches back).
fn not_inches(c: &Clause, k: usize) -> bool {
    c.word(k) == Some("in")
        && (matches!(c.word(k + 1), Some("front" | "the" | "a"))
            || c.word(k + 1) == Some("back") && c.word(k + 2) == Some("of"))
}

/// The second part of a compound length after a part in `unit` ends at token `j`: "6 in"
/// of `2 ft 6 in`, "and 20 cm" of `1 m and 20 cm`, in a smaller unit; its words read.
/// Zero where none follows.
fn smaller_part(c: &mut Clause, j: usize, unit: f64) -> f64 {
    let start = if c.words_at(j, &["and"]) { j + 1 } else { j };
    let Some((m, len)) = number_at(c, start) else {
        return 0.0;
    };
    let Some(smaller) = c.word(start + len).and_then(length_unit) else {
        return 0.0;
    };
    let inches_not = not_inches(c, start + len);
    if smaller >= unit || inches_not || !c.free(start) {
        return 0.0;
    }
    c.mark(j..start + len + 1);
    m * smaller
}

/// Whether the clause's amount is a vague one ("a bit", "a good bit", "slightly"): the
/// first length [`length`] would read there is one of those phrases. Nothing is marked.
pub(crate) fn says_vague(c: &Clause) -> bool {
    let mut probe = c.clone();
    probe.until_blocked = false;
    let before: Vec<bool> = (0..probe.len()).map(|i| probe.free(i)).collect();
    let Some(Length::Metres(_)) = length(&mut probe, true) else {
        return false;
    };
    // The words the length read: a vague phrase has no number and no unit among them.
    (0..probe.len())
        .filter(|&i| before[i] && !probe.free(i))
        .all(|i| matches!(probe.token(i), Some(Token::Word(w)) if length_unit(w).is_none()))
}

/// A move named as a small one ("a nudge", "a tiny nudge", "a little push", "a gentle
/// shove"): an article, perhaps a word of smallness, a noun of pushing. Its length in
/// tokens at `i`, and whether it is a tiny one.
pub(super) fn small_move_at(c: &Clause, i: usize) -> Option<(usize, bool)> {
    let push = |w: &str| matches!(w, "nudge" | "push" | "shove" | "bump" | "tap" | "budge");
    let free = |k: usize| c.free(k);
    if !(matches!(c.word(i), Some("a" | "an")) && free(i)) {
        return None;
    }
    let small = c.word(i + 1).filter(|w| {
        matches!(
            *w,
            "slight" | "small" | "little" | "tiny" | "wee" | "gentle" | "quick" | "minor"
        )
    });
    let at = if small.is_some() { i + 2 } else { i + 1 };
    (c.word(at).is_some_and(push) && (i..=at).all(free))
        .then_some((at + 1 - i, matches!(small, Some("tiny" | "wee"))))
}

/// A vague length ("a good bit", "a bit", "a tiny bit", "a lot", "a nudge"), its words
/// read.
fn vague_length(c: &mut Clause) -> Option<Length> {
    for i in 0..c.len() {
        if let Some((len, tiny)) = small_move_at(c, i) {
            c.mark(i..i + len);
            return Some(Length::Metres(if tiny { TINY_METRES } else { BIT_METRES }));
        }
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
        if let Some(len) = small_turn_at(c, i) {
            c.mark(i..i + len);
            return Some(BIT_DEGREES);
        }
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

/// A turn named as a small one ("a slight turn", "a little twist", "a small spin", "a
/// gentle nudge round"): an article, a word of smallness, a noun of turning. Its length
/// in tokens at `i`.
fn small_turn_at(c: &Clause, i: usize) -> Option<usize> {
    let small = |w: &str| {
        matches!(
            w,
            "slight" | "small" | "little" | "tiny" | "wee" | "gentle" | "quick" | "minor"
        )
    };
    let turn = |w: &str| {
        matches!(
            w,
            "turn" | "spin" | "twist" | "rotation" | "swivel" | "tilt" | "angle"
        )
    };
    let free = |k: usize| c.free(k);
    let article = matches!(c.word(i), Some("a" | "an")) && free(i);
    let at = if article { i + 1 } else { i };
    (c.word(at).is_some_and(small) && c.word(at + 1).is_some_and(turn) && free(at) && free(at + 1))
        .then_some(at + 2 - i)
}

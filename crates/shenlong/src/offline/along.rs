//! What is said to go along with a moved object: "move X1 back 30 cm, with everything on
//! it", "… with X2" (what rests on it, named), "swap X1 with X3, including what's on
//! them", "rotate X1 a quarter turn, keeping what's on it on it", "take whatever's on it
//! along". A small grammar over the clause's free words:
//!
//! `LEAD THING [ON] [TAIL]` — LEAD: with, including, keeping, keep, take, taking,
//! bringing, plus, along with, together with; THING: variables, or the words for what is on
//! something (everything, whatever's, what's, the stuff, their things …); ON: on it, on
//! them, on top; TAIL: on it, on them, along, with it, with them, too, as well, included.
//! With no LEAD, the TAIL must close it: "…, X2 and all", "…, X2 included", "…, X2 on top
//! too", "stuff on it included"; named things may say where they are ("X2 on top").
//!
//! What rests on a moved object goes with it anyway (carried, turns included); the phrase
//! is read when every object it names belongs to one of the moved ones — rests on it
//! (directly or through others: nothing more to do) or is drawn up to it (`…, X2 and X3
//! and all`: "stools and all": the same moves; a turn is not read, as it would spin each
//! in place). Otherwise it is left unread and the instruction refused: "with X2" for
//! something standing elsewhere is not a request this reader can check.

use super::clause::Clause;
use super::reader::{Produced, Reader};
use super::relations::Step;
use super::words::Token;
use std::ops::Range;

/// The words that open the phrase, longest first.
const LEADS: &[&[&str]] = &[
    &["along", "with"],
    &["together", "with"],
    &["and", "take"],
    &["and", "keep"],
    &["with"],
    &["including"],
    &["keeping"],
    &["keep"],
    &["take"],
    &["taking"],
    &["bringing"],
    &["plus"],
];

/// The words for what is on something, with what may come before them.
const THINGS: &[&[&str]] = &[
    &["everything", "that's"],
    &["everything"],
    &["whatever's"],
    &["whatever", "is"],
    &["what's"],
    &["what", "is"],
    &["all", "the", "stuff"],
    &["the", "stuff"],
    &["its", "stuff"],
    &["their", "stuff"],
    &["the", "things"],
    &["its", "things"],
    &["their", "things"],
    &["stuff"],
    &["things"],
];

/// Where it is.
const ONS: &[&[&str]] = &[
    &["on", "top", "of", "it"],
    &["on", "it"],
    &["on", "them"],
    &["on", "top"],
];

/// What may close the phrase.
const TAILS: &[&[&str]] = &[
    &["and", "all"],
    &["included"],
    &["on", "it"],
    &["on", "them"],
    &["along"],
    &["with", "it"],
    &["with", "them"],
    &["too"],
    &["as", "well"],
];

/// The phrase in `c`: its tokens and the variables it names (empty for "everything on
/// it").
pub(super) fn phrase(c: &Clause) -> Option<(Range<usize>, Vec<usize>)> {
    let longest = |at: usize, options: &[&[&str]]| {
        options
            .iter()
            .find(|w| (at..at + w.len()).all(|k| c.free(k)) && c.words_at(at, w))
            .map(|w| w.len())
    };
    for i in 0..c.len() {
        // "…, X2 and X3 and all" ("stools and all"), "…, X2 included", "stuff on it
        // included" need no lead word.
        let bare = (matches!(c.token(i), Some(Token::Variable(_))) || longest(i, THINGS).is_some())
            && (i == 0 || !c.free(i - 1) || matches!(c.token(i - 1), Some(Token::Separator)));
        let Some(lead) = longest(i, LEADS).or(bare.then_some(0)) else {
            continue;
        };
        let mut k = i + lead;
        let mut named = Vec::new();
        while let Some(Token::Variable(v)) = c.token(k).filter(|_| c.free(k)) {
            named.push(*v);
            k += 1;
            // "X3, X4 and X5".
            let joiner = (c.words_at(k, &["and"]) || matches!(c.token(k), Some(Token::Separator)))
                && matches!(c.token(k + 1), Some(Token::Variable(_)));
            if joiner {
                k += 1;
            }
        }
        if !named.is_empty() {
            // "…, the monkey on top too", "keep X2 and X3 on it": where the named thing
            // is (its "it" may be read already, as the moved object).
            if let Some(on) = ONS
                .iter()
                .find(|w| c.free(k) && c.words_at_any(k, w))
                .map(|w| w.len())
            {
                k += on;
            }
        } else {
            // "with all its stuff" ("its" may be read already, as a possessive).
            if c.free(k)
                && c.word(k) == Some("all")
                && matches!(c.word(k + 1), Some("its" | "their"))
            {
                k += 1;
            }
            if !c.free(k) && matches!(c.word(k), Some("its" | "their")) {
                k += 1;
            }
            let Some(thing) = longest(k, THINGS) else {
                continue;
            };
            // "its stuff", "their things" say whose; "the stuff" needs "on it".
            let whose = (k..k + thing)
                .chain(k.checked_sub(1))
                .any(|j| matches!(c.word(j), Some("its" | "their")));
            match longest(k + thing, ONS) {
                Some(on) => k += thing + on,
                None if whose => k += thing,
                None => continue,
            }
        }
        let tail = longest(k, TAILS);
        let closes_bare = |k: usize| {
            [
                &["and", "all"][..],
                &["included"],
                &["too"],
                &["as", "well"],
            ]
            .iter()
            .any(|t| c.words_at(k, t))
        };
        if lead == 0 && !tail.is_some_and(|_| closes_bare(k)) {
            continue;
        }
        if let Some(tail) = tail {
            k += tail;
        }
        // The phrase ends the clause (a separator may follow), or, led by its word, only
        // how far and where follows, naming no object ("move X1 with X2 1 m to the
        // right").
        let ends = (k..c.len()).all(|j| matches!(c.token(j), Some(Token::Separator)) || !c.free(j));
        let then_amount = lead > 0
            && !named.is_empty()
            && (k..c.len()).all(|j| !matches!(c.token(j), Some(Token::Variable(_))));
        if ends || then_amount {
            return Some((i..k, named));
        }
    }
    None
}

impl Reader<'_> {
    /// Reads the phrase of what goes along with `moved` (the subjects this clause or the
    /// last one moved, with their steps): its words marked, each object it names given
    /// the steps of the object it rests on. `None` where the clause has no such phrase or
    /// it names something that rests on none of them.
    pub(super) fn goes_along(&self, c: &mut Clause, moved: &Produced) -> Option<Produced> {
        let (range, named) = phrase(c)?;
        let subjects: Vec<usize> = moved.iter().map(|(v, _)| *v).collect();
        if subjects.is_empty() {
            return None;
        }
        let mut out = Vec::new();
        for &v in &named {
            let known = self.facts.known;
            let carrier = subjects
                .iter()
                .copied()
                .find(|&s| known.belongs(v, s, &named) == Some(true))?;
            // What rests on it is carried with it, turns included: nothing of its own.
            if known.carried(v, carrier) {
                continue;
            }
            // What is drawn up to it takes its moves; a turn of its own would spin it in
            // place instead of round with the table, so that is not read.
            let steps: Vec<&Step> = moved
                .iter()
                .filter(|(s, _)| *s == carrier)
                .map(|(_, step)| step)
                .collect();
            if steps.iter().any(|step| matches!(step, Step::Turn(_))) {
                return None;
            }
            out.extend(steps.into_iter().map(|step| (v, step.clone())));
        }
        c.mark(range);
        Some(out)
    }
}

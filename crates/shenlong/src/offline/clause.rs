//! Clauses: an instruction split at `and`, `then`, commas and sentence ends (but not the
//! `and` of `between X2 and X3`, of a list of objects, of `forward and to the right`, or of
//! `a metre and a half`), each with a record of which of its words were read.

use super::words::{self, Token};
use std::ops::Range;

/// One clause and which of its tokens have been read.
#[derive(Clone, Debug)]
pub(crate) struct Clause {
    tokens: Vec<Token>,
    used: Vec<bool>,
    /// The view a turn in it is seen from, once read ([`super::view`]).
    pub view: Option<super::view::View>,
    /// Whether it says "as far as it will go" (read before anything takes its `it`),
    /// until an amount is read from it.
    pub until_blocked: bool,
}

impl Clause {
    /// A clause of these tokens, none read yet.
    pub fn new(tokens: Vec<Token>) -> Self {
        let used = vec![false; tokens.len()];
        Self {
            tokens,
            used,
            view: None,
            until_blocked: false,
        }
    }

    /// How many tokens.
    pub fn len(&self) -> usize {
        self.tokens.len()
    }

    /// The token at `i`.
    pub fn token(&self, i: usize) -> Option<&Token> {
        self.tokens.get(i)
    }

    /// The word at `i`, if it is one.
    pub fn word(&self, i: usize) -> Option<&str> {
        match self.tokens.get(i) {
            Some(Token::Word(w)) => Some(w),
            _ => None,
        }
    }

    /// Whether token `i` exists and is not read yet.
    pub fn free(&self, i: usize) -> bool {
        self.used.get(i).is_some_and(|u| !u)
    }

    /// Whether the unread words at `i` are `words`.
    pub fn words_at(&self, i: usize, words: &[&str]) -> bool {
        words
            .iter()
            .enumerate()
            .all(|(k, w)| self.free(i + k) && self.word(i + k) == Some(*w))
    }

    /// Replaces the word at `i` (a typo by what it stands for).
    pub fn replace(&mut self, i: usize, word: &str) {
        if let Some(t) = self.tokens.get_mut(i) {
            *t = Token::Word(word.to_string());
        }
    }

    /// Whether `words` stand at `i`, read or not.
    pub fn words_at_any(&self, i: usize, words: &[&str]) -> bool {
        words
            .iter()
            .enumerate()
            .all(|(k, w)| self.word(i + k) == Some(*w))
    }

    /// The first unread position where `words` stand.
    pub fn find(&self, words: &[&str]) -> Option<usize> {
        (0..self.len()).find(|&i| self.words_at(i, words))
    }

    /// Marks tokens read.
    pub fn mark(&mut self, range: Range<usize>) {
        for i in range {
            if let Some(u) = self.used.get_mut(i) {
                *u = true;
            }
        }
    }

    /// Marks read every token, anywhere in the clause, that is one of `words` (the filler
    /// of a construct already recognised: "so that it faces", "towards the").
    pub fn mark_every(&mut self, words: &[&str]) {
        for k in 0..self.len() {
            if self.word(k).is_some_and(|w| words.contains(&w)) {
                self.mark(k..k + 1);
            }
        }
    }

    /// Marks read the discourse around the clause's instruction ([`crate::discourse`]):
    /// greetings, request frames and leading hedges at its start (after any articles are
    /// left for the noun phrase), thanks and sign-offs at its end, and `as well` anywhere.
    pub fn mark_discourse(&mut self) {
        let words: Vec<&str> = self
            .tokens
            .iter()
            .map(|t| match t {
                Token::Word(w) => w.as_str(),
                _ => "",
            })
            .collect();
        let core = crate::discourse::core(&words);
        let mut end = self.len();
        // Separators at the end do not hide a sign-off before them.
        while end > 0 && matches!(self.tokens[end - 1], Token::Separator) {
            end -= 1;
        }
        let tail = if end < words.len() {
            crate::discourse::core(&words[..end]).end
        } else {
            core.end
        };
        self.mark(0..core.start);
        self.mark(tail.max(core.start)..end);
        if let Some(i) = self.find(&["as", "well"]) {
            self.mark(i..i + 2);
        }
        self.mark_approximations();
    }

    /// Marks read the words that say an amount is approximate — `about`, `roughly`,
    /// `approximately`, `around` right before a number, `or so`, `or thereabouts`,
    /// `give or take` and `-ish` after one: the amount is read as given.
    fn mark_approximations(&mut self) {
        let number_at = |c: &Self, i: usize| match c.tokens.get(i) {
            Some(Token::Number(_)) => true,
            Some(Token::Word(w)) => {
                words::number_word(w).is_some() || matches!(w.as_str(), "half" | "a" | "an")
            }
            _ => false,
        };
        for i in 0..self.len() {
            let before_number = match self.word(i) {
                // "around a" is a turn ("turn it around a bit"): only before digits or a
                // unit ("around a metre").
                Some("around") => {
                    matches!(self.tokens.get(i + 1), Some(Token::Number(_)))
                        || self.word(i + 2).and_then(words::length_unit).is_some()
                }
                Some(
                    "about" | "roughly" | "approximately" | "approx" | "circa" | "maybe" | "like",
                ) => number_at(self, i + 1),
                _ => false,
            };
            if before_number && self.free(i) {
                self.mark(i..i + 1);
            }
        }
        for words in [
            &["or", "so"][..],
            &["or", "thereabouts"],
            &["give", "or", "take"],
            &["ish"],
        ] {
            while let Some(i) = self.find(words) {
                self.mark(i..i + words.len());
            }
        }
    }

    /// Marks a `by` before position `i` read (`by 20 cm`).
    pub fn mark_by(&mut self, i: usize) {
        if i > 0 && self.words_at(i - 1, &["by"]) {
            self.mark(i - 1..i);
        }
    }

    /// The unread variables, with their positions.
    pub fn variables(&self) -> Vec<(usize, usize)> {
        (0..self.len())
            .filter(|&i| self.free(i))
            .filter_map(|i| match self.tokens[i] {
                Token::Variable(v) => Some((i, v)),
                _ => None,
            })
            .collect()
    }

    /// The next unread variable at or after `i`, skipping articles and `right`/`just`.
    pub fn variable_after(&self, mut i: usize) -> Option<(usize, usize)> {
        while i < self.len() {
            match &self.tokens[i] {
                Token::Variable(v) if self.free(i) => return Some((i, *v)),
                Token::Word(w)
                    if matches!(
                        w.as_str(),
                        "the" | "a" | "an" | "right" | "just" | "directly"
                    ) =>
                {
                    i += 1
                }
                _ => return None,
            }
        }
        None
    }

    /// The words not read that are not fillers, as text: what the translator could not
    /// read, empty when everything was.
    pub fn unread(&self) -> Vec<String> {
        (0..self.len())
            .filter(|&i| self.free(i))
            .filter_map(|i| match &self.tokens[i] {
                Token::Word(w) if crate::discourse::filler(w) => None,
                Token::Word(w) => Some(w.clone()),
                Token::Number(n) => Some(format!("{n}")),
                Token::Variable(v) => Some(format!("X{}", v + 1)),
                Token::Separator => None,
            })
            .collect()
    }

    /// The clause as text, for messages.
    pub fn text(&self) -> String {
        self.tokens
            .iter()
            .filter_map(|t| match t {
                Token::Word(w) => Some(w.clone()),
                Token::Number(n) => Some(format!("{n}")),
                Token::Variable(v) => Some(format!("X{}", v + 1)),
                Token::Separator => None,
            })
            .collect::<Vec<_>>()
            .join(" ")
    }
}

/// Words that start a new clause.
fn breaks(w: &str) -> bool {
    matches!(w, "and" | "then" | "afterwards" | "finally")
}

/// Splits tokens into clauses. `and` stays inside a clause when it joins two objects
/// (`X1 and X2` as subjects, `between X2 and X3`, `swap X1 and X2`), two directions
/// (`forward and to the right`, `down and left`) or an amount (`a metre and a half`).
pub(crate) fn split(tokens: &[Token]) -> Vec<Clause> {
    let word = |k: usize| match tokens.get(k) {
        Some(Token::Word(w)) => Some(w.as_str()),
        _ => None,
    };
    let var_near = |i: usize, step: isize| -> bool {
        let mut k = i as isize + step;
        while k >= 0 && (k as usize) < tokens.len() {
            match &tokens[k as usize] {
                Token::Variable(_) => return true,
                Token::Word(w) if matches!(w.as_str(), "the" | "a" | "an" | "both") => k += step,
                _ => return false,
            }
        }
        false
    };
    let direction_near = |i: usize, step: isize| -> bool {
        let mut k = i as isize + step;
        while k >= 0 && (k as usize) < tokens.len() {
            match &tokens[k as usize] {
                Token::Word(w) if words::direction(w).is_some() => return true,
                Token::Word(w) if matches!(w.as_str(), "to" | "the" | "towards" | "toward") => {
                    k += step
                }
                _ => return false,
            }
        }
        false
    };
    let mut out: Vec<Vec<Token>> = vec![Vec::new()];
    let mut i = 0;
    while i < tokens.len() {
        let t = &tokens[i];
        let is_and = word(i) == Some("and");
        let current = out.last().expect("one clause at least");
        let current_words: Vec<&str> = current
            .iter()
            .filter_map(|t| match t {
                Token::Word(w) => Some(w.as_str()),
                _ => None,
            })
            .collect();
        let list_mark = is_and || (matches!(t, Token::Separator) && word(i + 1) != Some("then"));
        if list_mark && var_near(i, -1) && var_near(i, 1) {
            let list_context = current_words.iter().any(|w| {
                matches!(
                    *w,
                    "between" | "swap" | "exchange" | "switch" | "interchange" | "trade"
                )
            });
            // After the verb only articles and variables so far: a list of subjects.
            let only_subjects = current.iter().all(|t| match t {
                Token::Variable(_) | Token::Separator => true,
                Token::Word(w) => {
                    words::verb(w).is_some()
                        || crate::discourse::filler(w)
                        || matches!(
                            w.as_str(),
                            "both"
                                | "have"
                                | "all"
                                | "of"
                                | "positions"
                                | "position"
                                | "places"
                                | "place"
                                | "up"
                                | "could"
                                | "can"
                                | "would"
                                | "will"
                                | "you"
                                | "let's"
                                | "lets"
                                | "i'd"
                                | "like"
                                | "want"
                                | "i"
                                | "please"
                                | "need"
                                | "go"
                                | "ahead"
                                | "pick"
                                | "each"
                                | "line"
                                | "arrange"
                                | "align"
                        )
                        || words::correct(w).is_some_and(|c| words::verb(c).is_some())
                }
                Token::Number(_) => false,
            });
            if list_context || only_subjects {
                out.last_mut().expect("one clause").push(t.clone());
                i += 1;
                continue;
            }
        }
        if is_and && direction_near(i, -1) && direction_near(i, 1) {
            out.last_mut().expect("one clause").push(t.clone());
            i += 1;
            continue;
        }
        if is_and && word(i + 1) == Some("a") && matches!(word(i + 2), Some("half" | "quarter")) {
            out.last_mut().expect("one clause").push(t.clone());
            i += 1;
            continue;
        }
        // "a half turn, clockwise as seen from above": a comma before a qualifier of the
        // turn (or of the amount: "20 cm, roughly") does not start a clause.
        if matches!(t, Token::Separator)
            && matches!(
                word(i + 1),
                Some(
                    "clockwise"
                        | "counterclockwise"
                        | "anticlockwise"
                        | "roughly"
                        | "approximately"
                        | "more"
                )
            )
            && !matches!(word(i + 2), Some(w) if words::verb(w).is_some())
            || matches!(t, Token::Separator) && {
                let rest: Vec<&str> = (i + 1..tokens.len())
                    .map(|k| word(k).unwrap_or(""))
                    .collect();
                super::view::view_at(&rest, 0).is_some()
            }
        {
            i += 1;
            continue;
        }
        // "from a bird's eye view, turn …": a view before the comma belongs to the turn.
        if matches!(t, Token::Separator) {
            let so_far: Vec<&str> = out
                .last()
                .map(|c| {
                    c.iter()
                        .map(|t| match t {
                            Token::Word(w) => w.as_str(),
                            _ => "",
                        })
                        .collect()
                })
                .unwrap_or_default();
            if !so_far.is_empty()
                && super::view::view_at(&so_far, 0).is_some_and(|(n, _)| n == so_far.len())
            {
                i += 1;
                continue;
            }
        }
        let after_that = word(i) == Some("after") && word(i + 1) == Some("that");
        let is_break = matches!(t, Token::Separator) || word(i).is_some_and(breaks) || after_that;
        if is_break {
            // "after that", "and then": one break.
            if word(i) == Some("after") && word(i + 1) == Some("that") {
                i += 1;
            }
            out.push(Vec::new());
            i += 1;
            continue;
        }
        out.last_mut().expect("one clause").push(t.clone());
        i += 1;
    }
    out.into_iter()
        .filter(|c| !c.is_empty())
        .map(Clause::new)
        .collect()
}

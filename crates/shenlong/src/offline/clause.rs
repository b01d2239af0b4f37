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
    /// Whether it says to keep facing something ("keep it facing X2"): a facing square on
    /// to the target's nearest side, not towards its centre.
    pub keep_facing: bool,
    /// The shelf it names of what it puts things in ("on the top shelf of X2").
    pub shelf: Option<crate::scene::form::Shelf>,
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
            keep_facing: false,
            shelf: None,
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

    /// Replaces the token at `i` (an idiom read as the construct it stands for).
    pub fn set(&mut self, i: usize, token: Token) {
        if let Some(t) = self.tokens.get_mut(i) {
            *t = token;
        }
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

    /// Which tokens of `range` are read, to put back with [`Self::restore`].
    pub fn saved(&self, range: Range<usize>) -> Vec<bool> {
        range.map(|i| !self.free(i)).collect()
    }

    /// Puts back what [`Self::saved`] recorded from token `start`.
    pub fn restore(&mut self, start: usize, saved: &[bool]) {
        for (k, &used) in saved.iter().enumerate() {
            if let Some(u) = self.used.get_mut(start + k) {
                *u = used;
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
    /// `give or take` and `-ish` after one: the amount is read as given; and `roughly`
    /// before a place ("roughly in the middle of X2"): the place is read as given.
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
                // "put X1 roughly in the middle of X2", "roughly together": where it goes,
                // as near as that.
                Some("roughly" | "approximately" | "approx") => {
                    number_at(self, i + 1)
                        || matches!(
                            self.word(i + 1),
                            Some(
                                "in" | "on"
                                    | "at"
                                    | "to"
                                    | "onto"
                                    | "next"
                                    | "near"
                                    | "by"
                                    | "beside"
                                    | "between"
                                    | "together"
                                    | "under"
                                    | "against"
                                    | "where"
                            )
                        )
                        // "…, roughly" at the end of the clause.
                        || self.word(i + 1).is_none()
                            && matches!(self.tokens.get(i + 1), None | Some(Token::Separator))
                }
                Some("about" | "circa" | "maybe" | "like") => number_at(self, i + 1),
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
        // "10 cm left each", "a quarter turn each": the same for every one, as it is.
        let last = (0..self.len())
            .rev()
            .find(|&i| !matches!(self.tokens.get(i), Some(Token::Separator)));
        if let Some(i) = last.filter(|&i| i > 0 && self.word(i) == Some("each") && self.free(i)) {
            self.mark(i..i + 1);
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

    /// The next unread variable at or after `i`, skipping articles, `right`/`just` and
    /// words already read.
    pub fn variable_after(&self, mut i: usize) -> Option<(usize, usize)> {
        while i < self.len() {
            match &self.tokens[i] {
                Token::Variable(v) if self.free(i) => return Some((i, *v)),
                // (Words an idiom has read are fillers: "from the ends of X2".)
                Token::Word(w)
                    if !self.free(i)
                        || matches!(
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

/// The word at `k` of `tokens`, if it is one.
fn word(tokens: &[Token], k: usize) -> Option<&str> {
    match tokens.get(k) {
        Some(Token::Word(w)) => Some(w.as_str()),
        _ => None,
    }
}

/// The words of `tokens`, anything else as an empty word.
fn words_of(tokens: &[Token]) -> Vec<&str> {
    tokens
        .iter()
        .map(|t| match t {
            Token::Word(w) => w.as_str(),
            _ => "",
        })
        .collect()
}

/// Whether a variable stands next to position `i` in direction `step` (±1), past articles
/// and `both`.
fn var_near(tokens: &[Token], i: usize, step: isize) -> bool {
    let mut k = i as isize + step;
    while k >= 0 && (k as usize) < tokens.len() {
        match &tokens[k as usize] {
            Token::Variable(_) => return true,
            Token::Word(w) if matches!(w.as_str(), "the" | "a" | "an" | "both") => k += step,
            _ => return false,
        }
    }
    false
}

/// Whether a direction word stands next to position `i` in direction `step` (±1), past
/// `to`, `the`, `towards`.
fn direction_near(tokens: &[Token], i: usize, step: isize) -> bool {
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
}

/// The words that may stand before a list of subjects, beside verbs and fillers ("could
/// you have both X1 and X2 …", "line up X1, X2 and X3").
const BEFORE_SUBJECTS: &[&str] = &[
    "both",
    "have",
    "all",
    "of",
    "positions",
    "position",
    "places",
    "place",
    "up",
    "could",
    "can",
    "would",
    "will",
    "you",
    "let's",
    "lets",
    "i'd",
    "like",
    "want",
    "i",
    "please",
    "need",
    "go",
    "ahead",
    "pick",
    "each",
    "line",
    "arrange",
    "align",
    // "…, and keep X2 and X3 on it", "keeping X2 and X3 where they are".
    "keep",
    "keeping",
    "leave",
    "leaving",
];

/// Whether the clause so far (`current`) is a verb and a list of subjects begun: only
/// verbs, fillers, the words of [`BEFORE_SUBJECTS`] and variables.
fn only_subjects(current: &[Token]) -> bool {
    current.iter().all(|t| match t {
        Token::Variable(_) | Token::Separator => true,
        Token::Word(w) => {
            words::verb(w).is_some()
                || crate::discourse::filler(w)
                || BEFORE_SUBJECTS.contains(&w.as_str())
                || words::correct(w).is_some_and(|c| words::verb(c).is_some())
        }
        Token::Number(_) => false,
    })
}

/// Whether the `and` or comma at `i` joins two objects of one list (`X1 and X2` as
/// subjects, `between X2 and X3`, `swap X1 and X2`) in the clause so far, `current`.
fn joins_objects(tokens: &[Token], i: usize, current: &[Token]) -> bool {
    let list_mark = word(tokens, i) == Some("and")
        || (matches!(tokens[i], Token::Separator) && word(tokens, i + 1) != Some("then"));
    if !(list_mark && var_near(tokens, i, -1) && var_near(tokens, i, 1)) {
        return false;
    }
    let list_context = current.iter().any(|t| {
        matches!(
            t,
            Token::Word(w) if matches!(
                w.as_str(),
                // "in the middle of X2 and X3" is between them.
                "between" | "middle" | "centre" | "center"
            ) || matches!(words::verb(w), Some((words::Action::Swap, _)))
        )
    });
    // A list that ends the instruction or its sentence ("towards X2 and X3", "with X2
    // and X3"): the rest of this clause, not a clause of objects alone.
    let mut k = i + 1;
    while matches!(tokens.get(k), Some(Token::Variable(_)))
        || word(tokens, k) == Some("and") && matches!(tokens.get(k + 1), Some(Token::Variable(_)))
        || matches!(tokens.get(k), Some(Token::Separator))
            && matches!(tokens.get(k + 1), Some(Token::Variable(_)))
    {
        k += 1;
    }
    let list_ends = !matches!(tokens.get(k), Some(Token::Word(_)));
    // After the verb only articles and variables so far: a list of subjects.
    list_context || list_ends || only_subjects(current)
}

/// Whether the token at `i` stays inside the clause so far (`current`): an `and` or comma
/// joining two objects, an `and` joining two directions (`forward and to the right`) or
/// an amount (`a metre and a half`).
fn stays_inside(tokens: &[Token], i: usize, current: &[Token]) -> bool {
    let is_and = word(tokens, i) == Some("and");
    // "…, X2 and X3 and all": the closing "and all" is the list's.
    let and_all = is_and
        && word(tokens, i + 1) == Some("all")
        && !matches!(tokens.get(i + 2), Some(Token::Word(_) | Token::Variable(_)));
    and_all
        || joins_objects(tokens, i, current)
        || is_and && direction_near(tokens, i, -1) && direction_near(tokens, i, 1)
        || is_and
            && word(tokens, i + 1) == Some("a")
            && matches!(word(tokens, i + 2), Some("half" | "quarter"))
}

/// Whether the token at `i` is a comma that neither ends the clause nor is kept: before a
/// qualifier of the turn or the amount ("a half turn, clockwise as seen from above", "20
/// cm, roughly"), or after a view that begins the clause so far, `current` ("from a bird's
/// eye view, turn …").
/// The most words a view ("from a bird's eye view", "as seen from the door") takes.
const VIEW_WORDS: usize = 16;

fn dropped_comma(tokens: &[Token], i: usize, current: &[Token]) -> bool {
    if !matches!(tokens[i], Token::Separator) {
        return false;
    }
    let qualifier = matches!(
        word(tokens, i + 1),
        Some(
            "clockwise"
                | "counterclockwise"
                | "anticlockwise"
                | "roughly"
                | "approximately"
                | "more"
        )
    ) && !matches!(word(tokens, i + 2), Some(w) if words::verb(w).is_some());
    // A view is a few words ("from a bird's eye view"): only that many are looked at, so
    // a list of thousands of objects costs each comma a few words, not the list.
    let view_after = {
        let rest: Vec<&str> = (i + 1..tokens.len().min(i + 1 + VIEW_WORDS))
            .map(|k| word(tokens, k).unwrap_or(""))
            .collect();
        super::view::view_at(&rest, 0).is_some()
    };
    let view_before = current.len() <= VIEW_WORDS && {
        let so_far = words_of(current);
        !so_far.is_empty()
            && super::view::view_at(&so_far, 0).is_some_and(|(n, _)| n == so_far.len())
    };
    // "move X1 and X2, 30 cm forward": the verb and its objects, then how far.
    let amount_after = only_subjects(current)
        && current.iter().any(|t| matches!(t, Token::Variable(_)))
        && (matches!(tokens.get(i + 1), Some(Token::Number(_)))
            || word(tokens, i + 1).is_some_and(|w| words::direction(w).is_some()));
    qualifier || view_after || view_before || amount_after
}

/// How many tokens the clause break at `i` takes (a comma, `and`, `then`, `afterwards`,
/// `finally`: 1; `after that`: 2), or `None` where no clause ends.
fn break_at(tokens: &[Token], i: usize) -> Option<usize> {
    if word(tokens, i) == Some("after") && word(tokens, i + 1) == Some("that") {
        return Some(2);
    }
    // "…, but keep it facing X2": `but` before a verb starts a clause.
    let but_then = word(tokens, i) == Some("but")
        && word(tokens, i + 1).is_some_and(|w| w == "keep" || super::words::verb(w).is_some());
    (matches!(tokens[i], Token::Separator) || word(tokens, i).is_some_and(breaks) || but_then)
        .then_some(1)
}

/// Splits tokens into clauses. `and` stays inside a clause when it joins two objects
/// (`X1 and X2` as subjects, `between X2 and X3`, `swap X1 and X2`), two directions
/// (`forward and to the right`, `down and left`) or an amount (`a metre and a half`).
pub(crate) fn split(tokens: &[Token]) -> Vec<Clause> {
    let mut out: Vec<Vec<Token>> = vec![Vec::new()];
    let mut i = 0;
    while i < tokens.len() {
        let current = out.last().expect("one clause at least");
        if stays_inside(tokens, i, current) {
            out.last_mut().expect("one clause").push(tokens[i].clone());
            i += 1;
        } else if dropped_comma(tokens, i, current) {
            i += 1;
        } else if let Some(n) = break_at(tokens, i) {
            out.push(Vec::new());
            i += n;
        } else {
            out.last_mut().expect("one clause").push(tokens[i].clone());
            i += 1;
        }
    }
    out.into_iter()
        .filter(|c| !c.is_empty())
        .map(Clause::new)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::super::words::tokenize;
    use super::split;

    /// The clauses of `text`, as their words.
    fn clauses(text: &str) -> Vec<String> {
        split(&tokenize(text)).iter().map(|c| c.text()).collect()
    }

    #[test]
    fn clauses_end_at_and_then_commas_and_after_that() {
        assert_eq!(
            clauses("move X1 left and then turn it, after that lift X2").len(),
            3
        );
        assert_eq!(clauses("move X1 left. Finally lift X2").len(), 2);
    }

    #[test]
    fn and_stays_inside_for_lists_directions_and_amounts() {
        for text in [
            "move X1 and X2 to the left",
            "put X1 between X2 and X3",
            "swap X1 and X2",
            "line up X1, X2 and X3",
            "move X1 forward and to the right",
            "move X1 a metre and a half left",
        ] {
            assert_eq!(clauses(text).len(), 1, "{text}: {:?}", clauses(text));
        }
        // After a move, "and X2" starts a clause of its own.
        assert_eq!(clauses("move X1 left and X2 right").len(), 2);
    }

    #[test]
    fn a_comma_before_a_qualifier_or_after_a_view_is_dropped() {
        for text in [
            "turn X1 a half turn, clockwise as seen from above",
            "move X1 20 cm to the left, roughly",
            "from a bird's eye view, turn X1 clockwise",
        ] {
            let c = clauses(text);
            assert_eq!(c.len(), 1, "{text}: {c:?}");
        }
    }
}

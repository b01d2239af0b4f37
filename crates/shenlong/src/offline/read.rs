//! Reading one clause: its verb, subjects and what it asks, marking every word it reads. A
//! clause with a word left unread is refused — the translator never acts on part of an
//! instruction.
//!
//! The clause is first prepared (its discourse, view and idioms read), then repeated
//! ([`super::repeat`]) or read by its verb, which says the stage that reads the rest:
//! - a move: to a relation with other objects ([`super::relate`]), to a place in the room
//!   ([`super::room_place`]), or by directions and an amount ([`super::shift`]);
//! - a turn, or a straightening ([`super::rotate`]);
//! - a scale ([`super::scale`]);
//! - a swap, a row or an alignment ([`super::arrange`]).

use super::clause::Clause;
use super::reader::{not_read, Direction, Produced, ReadError, Reader};
use super::relate::find_relation;
use super::relations::Step;
use super::room_place::room_place;
use super::rotate::find_facing;
use super::view::{view_at, View};
use super::words::{self, Action, Token};
use crate::translate::Near;

/// Verbs that with "back" and nothing more return an object ("put the chair back");
/// other verbs with "back" move it backwards ("push the chair back").
const RETURNING_VERBS: &[&str] = &[
    "put", "set", "place", "placed", "stick", "pop", "get", "bring", "brought",
];

/// The words after "back" (or in place of it) that say "where it was", pronouns left
/// out (the reader has read "it" as its object by then).
const WHERE_IT_WAS: &[&[&str]] = &[
    &["where", "was"],
    &["where", "were"],
    &["to", "where", "was"],
    &["to", "where", "were"],
    &["where", "belongs"],
    &["where", "belong"],
    &["in", "place"],
    &["to", "place"],
    &["to", "old", "place"],
    &["to", "old", "spot"],
    &["to", "original", "place"],
    &["to", "original", "position"],
    &["to", "original", "positions"],
    &["to", "original", "spot"],
    &["where", "started"],
];

/// Whether the clause asks to return its objects to where they were before: a returning
/// verb at `verb_at` whose only other words are its objects and "back" ("put X1 back"),
/// or any verb followed by "back where it was", "to its original position" and the like.
/// Read as a move backwards, "put the chair back" would move it a metre away.
fn asks_return(c: &Clause, verb_at: usize) -> bool {
    let verb = c.word(verb_at).unwrap_or("");
    let rest: Vec<&str> = (verb_at + 1..c.len())
        .filter(|&i| c.free(i) && !matches!(c.token(i), Some(Token::Variable(_))))
        .filter_map(|i| c.word(i))
        .filter(|w| {
            !matches!(
                *w,
                "and" | "it" | "they" | "them" | "its" | "their" | "please"
            )
        })
        .collect();
    let (back, tail) = match rest.split_first() {
        Some((&"back", tail)) => (true, tail),
        _ => (false, rest.as_slice()),
    };
    // ("put X1 back again"; "move X1 again" is no return.)
    let tail = if back && tail == ["again"] {
        &[][..]
    } else {
        tail
    };
    (back && tail.is_empty() && RETURNING_VERBS.contains(&verb))
        || (!tail.is_empty() && WHERE_IT_WAS.contains(&tail))
}

/// A verb form: `moving` → move, `turned` → turn, one-letter typos corrected.
fn verb_of(w: &str) -> Option<(Action, Option<Direction>)> {
    if let Some(v) = words::verb(w) {
        return Some(v);
    }
    if let Some(stem) = w.strip_suffix("ing") {
        for candidate in [stem.to_string(), format!("{stem}e")] {
            if let Some(v) = words::verb(&candidate) {
                return Some(v);
            }
        }
    }
    words::correct(w).and_then(words::verb)
}

/// Marks the view a turn is given in read ([`super::view`]), wherever it stands in the
/// clause, and returns it.
fn mark_view(c: &mut Clause) -> Option<View> {
    let owned: Vec<String> = (0..c.len())
        .map(|i| c.word(i).unwrap_or("").to_string())
        .collect();
    let words: Vec<&str> = owned.iter().map(String::as_str).collect();
    for i in 0..c.len() {
        if let Some((n, view)) = view_at(&words, i) {
            if (i..i + n).all(|k| c.free(k)) {
                c.mark(i..i + n);
                return Some(view);
            }
        }
    }
    None
}

/// Reads what surrounds the clause's request before the request itself: the discourse
/// around the instruction (greetings and request frames at the start, thanks and sign-offs
/// at the end: [`crate::discourse`]), the view a turn is seen from, "as far as it will go",
/// the idioms ([`super::idioms`]) and a causative "have" ("have X1 and X2 trade places").
fn prepare(c: &mut Clause) {
    c.mark_discourse();
    c.view = mark_view(c);
    c.until_blocked = super::amounts::until_blocked(c);
    super::idioms::rewrite(c);
    // "have X1 and X2 trade places": the causative `have` before the objects.
    if let Some(i) = (0..c.len()).find(|&i| c.free(i)) {
        if c.words_at(i, &["have"]) && c.variable_after(i + 1).is_some() {
            c.mark(i..i + 1);
        }
    }
}

/// Marks the pronouns for the subjects before `cut` (all with none) read: `it`, `them`,
/// `both`, `they`, `everything`, `these`, `those`, `all of them`, `each of them`.
fn mark_pronouns(c: &mut Clause, cut: Option<usize>) {
    for i in 0..c.len() {
        if c.free(i)
            && cut.is_none_or(|k| i < k)
            && (matches!(
                c.word(i),
                Some("it" | "them" | "em" | "both" | "they" | "everything" | "these" | "those")
            ) || (matches!(c.word(i), Some("all" | "each"))
                && c.words_at(i + 1, &["of", "them"])))
        {
            c.mark(i..i + 1);
            if c.words_at(i + 1, &["of", "them"]) {
                c.mark(i + 1..i + 3);
            }
        }
    }
}

impl Reader<'_> {
    /// Reads one clause and records its steps.
    ///
    /// # Errors
    /// A word of the clause not read (quoted), or a variable beyond those bound.
    pub fn clause(&mut self, c: &mut Clause) -> Result<(), ReadError> {
        self.wall_of_objects(c);
        self.foot_of_object(c);
        prepare(c);
        let shifted = self.last_shift.take();
        // A clause of fillers only ("…, thanks"): nothing to do.
        if c.unread().is_empty() {
            return Ok(());
        }
        if let Some(explained) = self.gloss(c, shifted.as_ref()) {
            return explained;
        }
        // "…, with everything on it": a clause of what goes along with the last one's.
        let last = std::mem::take(&mut self.last_produced);
        let mut probe = c.clone();
        if let Some(along) = self.goes_along(&mut probe, &last) {
            if probe.unread().is_empty() {
                *c = probe;
                self.last_produced = last;
                return self.record(along);
            }
        }
        if let Some(kept) = self.keep_on(c) {
            return kept;
        }
        self.shift_on_its_support(c);
        let mut produced = if let Some(repeated) = self.repeat(c) {
            repeated
        } else if self.topic(c) || self.remark(c) {
            return Ok(());
        } else {
            // "move X1 right along with X2", "swap X1 and X2, X3 and X4 and all": X2 (X3,
            // X4) is no subject of the move; the phrase is set aside while it is read.
            let action = (0..c.len())
                .filter(|&i| c.free(i))
                .find_map(|i| c.word(i).and_then(verb_of))
                .map(|(a, _)| a);
            // (After "swap", "with X2" is the other one swapped.)
            let along = super::along::phrase(c).filter(|(range, named)| {
                !named.is_empty()
                    && match action {
                        Some(Action::Move) => true,
                        Some(Action::Swap) => c.word(range.start) != Some("with"),
                        _ => false,
                    }
            });
            let saved = along.as_ref().map(|(range, _)| {
                let saved = c.saved(range.clone());
                c.mark(range.clone());
                (range.start, saved)
            });
            let produced = self.read(c)?;
            if let Some((start, saved)) = saved {
                c.restore(start, &saved);
            }
            produced
        };
        // "move X1 back 30 cm with everything on it": the rest of this clause.
        if !c.unread().is_empty() {
            if let Some(along) = self.goes_along(c, &produced) {
                produced.extend(along);
            }
        }
        let unread = c.unread();
        if !unread.is_empty() {
            return Err(not_read(&unread.join(" "), &c.text()));
        }
        self.record(produced)
    }

    /// "move X1 a bit to the right, towards X2": a clause of only "towards X2" (or
    /// "closer to", "nearer to", "in the direction of") after a shift says why, not a
    /// second move. It is read when `X2` lies ahead of every subject along the shift's
    /// direction, and refused, naming both, where the shift takes one away from it.
    /// `None` for any other clause.
    fn gloss(
        &self,
        c: &mut Clause,
        shifted: Option<&(Vec<usize>, Vec<Direction>)>,
    ) -> Option<Result<(), ReadError>> {
        let (subjects, dirs) = shifted?;
        let free: Vec<usize> = (0..c.len()).filter(|&i| c.free(i)).collect();
        let words: Vec<&str> = free.iter().map(|&i| c.word(i).unwrap_or("")).collect();
        let lead = match words.as_slice() {
            ["towards" | "toward", ..] => 1,
            ["closer" | "nearer", "to", ..] => 2,
            ["in", "the", "direction", "of", ..] => 4,
            _ => return None,
        };
        let rest = &free[lead..];
        let target = match rest {
            [v] => *v,
            [the, v] if c.word(*the) == Some("the") => *v,
            _ => return None,
        };
        let Some(Token::Variable(t)) = c.token(target) else {
            return None;
        };
        let t = *t;
        if subjects.contains(&t) {
            return None;
        }
        let mut way = glam::DVec3::ZERO;
        for &(e, sign) in dirs {
            way[e] += sign;
        }
        way.y = 0.0;
        if way.length() < 1e-9 {
            return None;
        }
        for &s in subjects {
            if self.facts.known.heads_towards(s, t, way) == Some(false) {
                let known = self.facts.known;
                return Some(Err(ReadError::Unclear(format!(
                    "moving {} that way takes it away from {}, not towards it: say which you mean",
                    known.label(s),
                    known.label(t)
                ))));
            }
        }
        for &i in &free {
            c.mark(i..i + 1);
        }
        Some(Ok(()))
    }

    /// "…, keep it on X3" after a move: the objects moved last (or those named) must still
    /// rest on `X3` once placed — a check, not a motion ([`Near::On`]). They must rest on
    /// it now; where one does not, the clause is refused naming both. `None` for any other
    /// clause, or with nothing moved before.
    fn keep_on(&mut self, c: &mut Clause) -> Option<Result<(), ReadError>> {
        let free: Vec<usize> = (0..c.len()).filter(|&i| c.free(i)).collect();
        let (first, rest) = free.split_first()?;
        if !matches!(c.word(*first), Some("keep" | "leave")) || self.last_subjects.is_empty() {
            return None;
        }
        let mut named = Vec::new();
        let mut k = 0;
        while let Some(&i) = rest.get(k) {
            match (c.token(i), c.word(i)) {
                (Some(Token::Variable(v)), _) => named.push(*v),
                (_, Some("it" | "them" | "both" | "and")) => {}
                _ => break,
            }
            k += 1;
        }
        let tail: Vec<&Token> = rest[k..].iter().filter_map(|&i| c.token(i)).collect();
        // "…, and keep X2 and X3 on it": on the one object moved last.
        let moved_last = match self.last_subjects.as_slice() {
            [one] if !named.is_empty() && !named.contains(one) => Some(*one),
            _ => None,
        };
        let target = match tail.as_slice() {
            [Token::Word(on), Token::Variable(t)] if on == "on" => *t,
            [Token::Word(on), Token::Word(the), Token::Variable(t)]
                if on == "on" && the == "the" =>
            {
                *t
            }
            [Token::Word(on), Token::Word(it)] if on == "on" && it == "it" => moved_last?,
            // (The "it" may be read already, as the last clause's object.)
            [Token::Word(on)] if on == "on" && c.word(rest[k] + 1) == Some("it") => moved_last?,
            _ => return None,
        };
        let subjects = if named.is_empty() {
            self.last_subjects.clone()
        } else {
            named
        };
        let known = self.facts.known;
        for &s in &subjects {
            if !known.rests_on(s, target) {
                return Some(Err(ReadError::Unclear(format!(
                    "{} is not on {} now, so it cannot stay on it: say where it goes",
                    known.label(s),
                    known.label(target)
                ))));
            }
            self.near.entry(s).or_insert(Near::On(target));
        }
        for &i in &free {
            c.mark(i..i + 1);
        }
        Some(Ok(()))
    }

    /// "stash X1 20 cm further back on X2", "slide X1 left a bit on X2" with X1 resting
    /// on X2: the shift keeps it on X2, which is checked once placed ([`Near::On`]), not
    /// a move onto X2. The clause's words "on X2", at its end, are read here.
    fn shift_on_its_support(&mut self, c: &mut Clause) {
        let vars = c.variables();
        let (Some(&(_, s)), Some(&(at, t))) = (vars.first(), vars.last()) else {
            return;
        };
        let ends = at + 1 == c.len() || matches!(c.token(at + 1), Some(Token::Separator));
        let on = at > 0 && c.free(at - 1) && c.word(at - 1) == Some("on");
        let shift = (0..c.len()).any(|i| {
            c.free(i)
                && c.word(i)
                    .is_some_and(|w| super::words::direction(w).is_some())
        });
        if s == t || !ends || !on || !shift || !self.facts.known.rests_on(s, t) {
            return;
        }
        c.mark(at - 1..at + 1);
        self.near.entry(s).or_insert(Near::On(t));
    }

    /// A remark about the objects before what is to be done with them ("X1 is way too low,
    /// bring it up", "X1 is sticking out, push it in"): the objects, `is` (`are`, `looks`,
    /// `seems`), and words that ask nothing the reader knows — no verb, direction, number
    /// or other object (a relation word without an object relates nothing). They are what "it" and "them" mean next; read, it is `true`. Only
    /// where more clauses follow: a remark alone asks for nothing.
    fn remark(&mut self, c: &mut Clause) -> bool {
        if !self.more_follow {
            return false;
        }
        let free: Vec<usize> = (0..c.len()).filter(|&i| c.free(i)).collect();
        let named = free
            .iter()
            .take_while(|&&i| {
                matches!(c.token(i), Some(Token::Variable(_))) || c.words_at(i, &["and"])
            })
            .count();
        let subjects: Vec<usize> = free[..named]
            .iter()
            .filter_map(|&i| match c.token(i) {
                Some(Token::Variable(v)) => Some(*v),
                _ => None,
            })
            .collect();
        // "X1 is …", or a complaint with the verb left out ("X1's too close to X2", where
        // the grounder took the "'s" with the name).
        let copula = free.get(named).is_some_and(|&i| {
            matches!(
                c.word(i),
                Some("is" | "are" | "looks" | "look" | "seems" | "seem" | "too")
            )
        });
        let rest = free.get(named + 1..).unwrap_or(&[]);
        let asks_nothing = !rest.is_empty()
            && rest.iter().all(|&i| match c.token(i) {
                // "is sticking out": a state, not a request.
                Some(Token::Word(w)) => {
                    (words::verb(w).is_none() || w.ends_with("ing"))
                        && words::direction(w).is_none()
                        && words::length_unit(w).is_none()
                }
                // "is too close to X2": the state names another object.
                Some(Token::Variable(_)) => true,
                _ => false,
            });
        if subjects.is_empty() || !copula || !asks_nothing {
            return false;
        }
        for &i in &free {
            c.mark(i..i + 1);
        }
        self.last_subjects = subjects;
        true
    }

    /// A topic ("Cushion_Blue: move it 15 cm right"): a clause of objects named alone,
    /// what "it" and "them" mean next; or the group the next clause picks from ("of X1
    /// and X2, turn X1 …"); read, it is `true`.
    fn topic(&mut self, c: &mut Clause) -> bool {
        let mut free: Vec<usize> = (0..c.len()).filter(|&i| c.free(i)).collect();
        // "of X1 and X2, turn X1 …": the group the next clause picks from (the grounder
        // has said which), not what "it" means.
        let partitive = free.first().copied().filter(|&i| c.words_at(i, &["of"]));
        if partitive.is_some() {
            free.remove(0);
        }
        let topic: Vec<usize> = free
            .iter()
            .filter_map(|&i| match c.token(i) {
                Some(Token::Variable(v)) => Some(*v),
                _ => None,
            })
            .collect();
        let only_objects = free.iter().all(|&i| {
            matches!(c.token(i), Some(Token::Variable(_) | Token::Separator))
                || c.words_at(i, &["and"])
        });
        // Objects named alone at the end ask for nothing ("… closer to X3 and X4" split
        // at "and"): not read, so the instruction is refused rather than X4 ignored.
        if topic.is_empty() || !only_objects || !self.more_follow {
            return false;
        }
        for &i in &free {
            c.mark(i..i + 1);
        }
        match partitive {
            Some(of) => c.mark(of..of + 1),
            None => self.last_subjects = topic,
        }
        true
    }

    /// Records a clause's steps, and the first variable's as what "do the same" repeats.
    ///
    /// # Errors
    /// A variable beyond those bound.
    fn record(&mut self, produced: Produced) -> Result<(), ReadError> {
        self.last_produced.clone_from(&produced);
        if let Some(&(first, _)) = produced.first() {
            self.last_steps = produced
                .iter()
                .filter(|(v, _)| *v == first)
                .map(|(_, s)| s.clone())
                .collect();
        }
        for (v, step) in produced {
            if v >= self.facts.variables {
                return Err(ReadError::Unbound {
                    variable: v + 1,
                    bound: self.facts.variables,
                });
            }
            self.steps.entry(v).or_default().push(step);
        }
        Ok(())
    }

    /// The verb of the clause, marked read; particles (`pick up`, `line up`) too.
    fn verb(&mut self, c: &mut Clause) -> Option<(Action, Option<Direction>, usize)> {
        for i in 0..c.len() {
            let Some(w) = c.word(i).filter(|_| c.free(i)) else {
                continue;
            };
            // "back" or "down" as verbs do not exist; "set down", "put back" are particles.
            if let Some((action, implied)) = verb_of(w) {
                c.mark(i..i + 1);
                if matches!(action, Action::Take | Action::Align) && c.words_at(i + 1, &["up"]) {
                    c.mark(i + 1..i + 2);
                }
                // "pick X1 up and put it …": the particle after the objects. (Not "line
                // X1 and X2 up with X3", which asks to align them with X3 where they
                // stand: not read.)
                if action == Action::Take {
                    let after_objects = (i + 2..c.len()).find(|&k| {
                        c.words_at(k, &["up"]) && matches!(c.token(k - 1), Some(Token::Variable(_)))
                    });
                    if let Some(k) = after_objects {
                        c.mark(k..k + 1);
                    }
                }
                return Some((action, implied, i));
            }
        }
        None
    }

    /// The clause's subjects (see [`Self::subjects`]), remembered for "it" and "them" in
    /// later clauses; a clause whose verb needs a subject and has none is not read.
    pub(super) fn required_subjects(
        &mut self,
        c: &mut Clause,
        text: &str,
    ) -> Result<Vec<usize>, ReadError> {
        let subjects = self.subjects(c, None);
        if subjects.is_empty() {
            return Err(not_read(text, text));
        }
        self.last_subjects = subjects.clone();
        Ok(subjects)
    }

    /// The subjects: the unread variables before `cut` (all with none), else the pronoun's
    /// objects (`it`, `them`, `both`): the last clause's subjects.
    pub(super) fn subjects(&mut self, c: &mut Clause, cut: Option<usize>) -> Vec<usize> {
        let vars: Vec<(usize, usize)> = c
            .variables()
            .into_iter()
            .filter(|(i, _)| cut.is_none_or(|k| *i < k))
            .collect();
        let mut subjects: Vec<usize> = Vec::new();
        for &(i, v) in &vars {
            c.mark(i..i + 1);
            if !subjects.contains(&v) {
                subjects.push(v);
            }
            // "X1, X2 and X3", "both X1 and X2".
            let k = i + 1;
            if (c.words_at(k, &["and"]) || matches!(c.token(k), Some(Token::Separator)))
                && vars.iter().any(|(j, _)| *j > k)
            {
                c.mark(k..k + 1);
            }
            // "X1 together with X2 and X3" (what the grounder found on it): one list.
            let with = c.words_at(k, &["together", "with"]) || c.words_at(k, &["along", "with"]);
            if with && vars.iter().any(|(j, _)| *j == k + 2) {
                c.mark(k..k + 2);
            }
        }
        mark_pronouns(c, cut);
        if subjects.is_empty() {
            subjects = self.last_subjects.clone();
        }
        subjects
    }

    /// Reads the clause by its verb (the last clause's with none; a turn when it says
    /// "face"), dispatching to the stage that reads the rest.
    fn read(&mut self, c: &mut Clause) -> Result<Produced, ReadError> {
        let text = c.text();
        let verb = self.verb(c);
        // "face it" where "it" is the object turned: the one thing named as the last
        // relation's target (an object cannot face itself).
        // Else, when the clause names its own object ("move X1 forward and turn X2 to face
        // it"), the one object the last clause moved.
        let named: Vec<usize> = c.variables().iter().map(|&(_, v)| v).collect();
        let other = match (self.last_targets.as_slice(), self.last_subjects.as_slice()) {
            (&[t], _) if !self.last_subjects.contains(&t) => Some(t),
            (_, &[s]) if !named.is_empty() && !named.contains(&s) => Some(s),
            _ => None,
        };
        let facing = find_facing(c, other);
        if let Some((_, _, at)) = verb {
            if asks_return(c, at) {
                return Err(ReadError::Return);
            }
        }
        let (mut action, implied) = match verb {
            Some((a, implied, _)) => (a, implied),
            None => match self.last_action {
                Some(a) => (a, None),
                None if facing.is_some() => (Action::Rotate, None),
                // "I'd like X1 on X2", "X1 to the left".
                None if !c.variables().is_empty() => (Action::Move, None),
                None => return Err(not_read(&text, &text)),
            },
        };
        // "give X1 a little nudge back": "give" with a push, not a turn, is a move.
        if action == Action::Rotate
            && (0..c.len()).any(|i| super::amounts::small_move_at(c, i).is_some())
        {
            action = Action::Move;
        }
        let face_word = (0..c.len())
            .any(|i| c.free(i) && matches!(c.word(i), Some("face" | "faces" | "facing")));
        if (facing.is_some() || face_word) && matches!(action, Action::Scale | Action::Move) {
            // "make X1 face X2", "have X1 face X2".
            action = Action::Rotate;
        }
        self.last_action = Some(action);
        match action {
            // "take X1 off X2", "take X1 to X2": a take with a place is a move.
            Action::Take if find_relation(c).is_some() => self.move_(c, Action::Move, None, &text),
            Action::Take => {
                self.required_subjects(c, &text)?;
                // "take the top crate down (off, out) and put it …": where from, said as
                // a particle, before the clause that says where to.
                if self.more_follow {
                    for i in 0..c.len() {
                        if c.free(i) && matches!(c.word(i), Some("down" | "off" | "out")) {
                            c.mark(i..i + 1);
                        }
                    }
                }
                // The taking itself moves nothing: a later clause says where.
                Ok(Vec::new())
            }
            Action::Swap => self.swap(c, &text),
            Action::Align => self.align(c, &text),
            Action::Rotate => self.rotate(c, facing, &text),
            Action::Scale => self.scale(c, &text),
            Action::Straighten => self.straighten(c, &text),
            Action::Centre | Action::Move => self.move_(c, action, implied, &text),
        }
    }

    /// "at the foot of X2" (of a bed), "at the head of X2", "towards the foot of X2": the
    /// side X2's front (its back) faces, said as a side the readers know — "in front of
    /// X2" for an unturned bed, "to the right of X2" for one turned a quarter turn, and
    /// "forward" for "towards the foot". Left as it is where X2 is turned other than by
    /// quarter turns, or is wider across its front than it is long (a table's head is a
    /// short end).
    fn foot_of_object(&self, c: &mut Clause) {
        for i in 1..c.len().saturating_sub(3) {
            let Some(Token::Variable(t)) = c.token(i + 3).cloned() else {
                continue;
            };
            let end = match c.word(i + 1) {
                Some("foot") => false,
                Some("head") => true,
                _ => continue,
            };
            let lead = c.word(i - 1).unwrap_or("");
            let towards = matches!(lead, "towards" | "toward");
            if !(c.words_at(i, &["the"]) && c.words_at(i + 2, &["of"]))
                || !(towards || matches!(lead, "at" | "to" | "by"))
                || !(i - 1..i + 4).all(|k| c.free(k))
            {
                continue;
            }
            let (Some(&yaw), Some(size)) =
                (self.facts.known.yaw.get(t), self.facts.known.sizes.get(t))
            else {
                continue;
            };
            let quarter = (yaw / 90.0).round();
            if (yaw - quarter * 90.0).abs() > 10.0 {
                continue;
            }
            // A bed's foot and head are the ends of its length, which runs along its front;
            // a table's head is a short end, not its back: not read where the front runs
            // across the object's shorter side.
            let along_front = if (quarter as i64).rem_euclid(2) == 0 {
                2
            } else {
                0
            };
            if size[along_front] < size[2 - along_front] {
                continue;
            }
            // The front of an unturned object is +z; each quarter turn takes +z to +x.
            let turns = (quarter as i64 + i64::from(end) * 2).rem_euclid(4);
            let (side, relation): (&str, [&str; 4]) = match turns {
                0 => ("forward", ["", "in", "front", "of"]),
                1 => ("right", ["to", "the", "right", "of"]),
                2 => ("back", ["", "", "", "behind"]),
                _ => ("left", ["to", "the", "left", "of"]),
            };
            if towards {
                // "10 cm towards the foot of X2": that way.
                c.mark(i - 1..i + 1);
                c.set(i + 1, Token::Word(side.to_string()));
                c.mark(i + 2..i + 4);
            } else {
                for (k, w) in relation.iter().enumerate() {
                    if w.is_empty() {
                        c.mark(i - 1 + k..i + k);
                    } else {
                        c.set(i - 1 + k, Token::Word((*w).to_string()));
                    }
                }
            }
            return;
        }
    }

    /// "toward the X2 wall" (the window wall, the whiteboard wall), "toward the wall behind
    /// X2": the wall X2 is nearest, said as its side ("toward the back wall") for the
    /// reader of places in the room.
    fn wall_of_objects(&self, c: &mut Clause) {
        // "towards the wall behind X2" (by, near, beside X2): the wall X2 is nearest, said
        // as its side; X2 is read.
        for i in 0..c.len() {
            let Some(Token::Variable(t)) = c.token(i + 2).cloned() else {
                continue;
            };
            let by = matches!(c.word(i + 1), Some("behind" | "by" | "near" | "beside"));
            if !(by && c.free(i) && c.words_at(i, &["wall"]) && c.free(i + 2)) {
                continue;
            }
            if let Some(side) = self.facts.known.nearest_wall(t) {
                c.set(i, Token::Word(side.to_string()));
                c.set(i + 1, Token::Word("wall".to_string()));
                c.mark(i + 2..i + 3);
            }
        }
        for i in 0..c.len() {
            let Some(Token::Variable(t)) = c.token(i).cloned() else {
                continue;
            };
            if !(c.free(i) && c.words_at(i + 1, &["wall"])) {
                continue;
            }
            if let Some(side) = self.facts.known.nearest_wall(t) {
                c.set(i, Token::Word(side.to_string()));
            }
        }
    }

    /// "drag X1 into the corner by X2" (near, next to, nearest): the room's corner on
    /// X2's side of its centre along both axes. `None` where the clause says no such
    /// thing, or the scene has no room.
    fn corner_by(&mut self, c: &mut Clause, text: &str) -> Option<Result<Produced, ReadError>> {
        let i = (0..c.len()).find(|&i| c.free(i) && c.word(i) == Some("corner"))?;
        let by = match (c.word(i + 1), c.word(i + 2)) {
            (Some("next" | "closest" | "nearest"), Some("to")) => 2,
            (Some("by" | "near" | "nearest" | "beside"), _) => 1,
            _ => return None,
        };
        let mut k = i + 1 + by;
        if c.word(k) == Some("the") {
            k += 1;
        }
        let Some(Token::Variable(t)) = c.token(k).cloned() else {
            return None;
        };
        let (x, z) = self.facts.known.corner_towards(t)?;
        c.mark(i..k + 1);
        for lead in [
            &["into", "the"][..],
            &["in", "the"],
            &["to", "the"],
            &["the"],
        ] {
            if i >= lead.len() && c.words_at(i - lead.len(), lead) {
                c.mark(i - lead.len()..i);
                break;
            }
        }
        let subjects = match self.required_subjects(c, text) {
            Ok(s) => s,
            Err(e) => return Some(Err(e)),
        };
        let place = super::room_place::RoomPlace::At(super::room::Place::Corner(Some(x), Some(z)));
        Some(Ok(subjects
            .iter()
            .map(|&s| (s, Step::Translate(place.vector(s, &subjects, true))))
            .collect()))
    }

    /// A move: to a relation with an object named before ("next to it") or named here
    /// ([`super::relate`]), else to a place in the room ([`super::room_place`]), else by
    /// directions and an amount ([`super::shift`]; `implied`: the verb's direction).
    fn move_(
        &mut self,
        c: &mut Clause,
        action: Action,
        implied: Option<Direction>,
        text: &str,
    ) -> Result<Produced, ReadError> {
        // A relation to an object named before: "move X2 next to it".
        if find_relation(c).is_none() {
            if let Some((r, targets)) = self.pronoun_relation(c) {
                return self.relate_to_pronoun(c, r, &targets, text);
            }
        }
        // Objects moved relative to one another: "X1 and X2 closer together".
        if let Some(produced) = self.mutual(c, text) {
            return produced;
        }
        // "put X1 where X2 is".
        if let Some(produced) = self.where_is(c, text) {
            return produced;
        }
        // "into the corner by X2": the room's corner nearest it.
        if let Some(produced) = self.corner_by(c, text) {
            return produced;
        }
        // A relation to another object.
        if let Some(r) = find_relation(c) {
            return self.relate(c, r, text);
        }
        let subjects = self.required_subjects(c, text)?;
        // A place in the room.
        let has_room = self.facts.known.room;
        if let Some(place) = room_place(c, action, has_room)? {
            // Objects together on one side of the room move together; others each alone.
            let together = self.facts.known.together_off_centre(&subjects);
            return Ok(subjects
                .iter()
                .map(|&s| {
                    let group = if together { &subjects[..] } else { &[s][..] };
                    (s, Step::Translate(place.vector(s, group, has_room)))
                })
                .collect());
        }
        // Directions and an amount.
        self.shift(c, &subjects, implied, text)
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{close, moves, outcome, standing, Box3};

    fn two() -> [Box3; 2] {
        [
            standing([0.4, 0.5, 0.4], -1.0, 0.0),
            standing([0.4, 0.5, 0.4], 1.0, 0.0),
        ]
    }

    #[test]
    fn a_clause_without_a_verb_takes_the_last_one_and_it_the_last_subjects() {
        let m = moves("move X1 20 cm left, X2 30 cm right", &two());
        assert!(close(m[0], [-0.2, 0.0, 0.0]) && close(m[1], [0.3, 0.0, 0.0]));
        let m = moves("lift X2 10 cm and then move it 20 cm forward", &two());
        assert!(close(m[1], [0.0, 0.1, 0.2]) && close(m[0], [0.0; 3]));
        let m = moves(
            "could you please move both X1 and X2 left by 5 cm, thanks",
            &two(),
        );
        assert!(close(m[0], [-0.05, 0.0, 0.0]) && close(m[1], [-0.05, 0.0, 0.0]));
    }

    #[test]
    fn a_word_left_unread_refuses_the_whole_instruction() {
        let refused = outcome("move X1 left and sing X2 a song", &two(), true).unwrap_err();
        assert!(refused.contains("could not read"), "{refused}");
        let refused = outcome("move X3 left", &two(), true).unwrap_err();
        assert!(refused.contains("only 2 objects"), "{refused}");
        // Taking alone moves nothing: a later clause says where.
        let m = moves("pick up X1 and put it on X2", &two());
        assert!(close(m[0], [2.0, 0.5, 0.0]));
    }

    #[test]
    fn put_back_asks_for_an_earlier_pose_and_is_refused_but_a_push_back_moves() {
        for q in [
            "put X1 back",
            "set X1 back please",
            "move X1 back to where it was",
            "put X1 and X2 back where they were",
            "put X1 back in its place",
            "put X1 back, thanks",
        ] {
            let refused = outcome(q, &two(), true).unwrap_err();
            assert!(refused.contains("where it was before"), "{q}: {refused}");
        }
        // With a length, or with a verb that pushes, "back" is a direction.
        let m = moves("put X1 back 20 cm", &two());
        assert!(close(m[0], [0.0, 0.0, -0.2]), "{:?}", m[0]);
        let m = moves("push X1 back", &two());
        assert!(m[0][2] < -0.05, "{:?}", m[0]);
    }
}

//! Noun phrases: a head with the words around it, read in stages, each keeping the
//! candidates it can tell apart —
//!
//! 1. the opening: the determiners (`both`, `all the`, `every`) and how many they ask for,
//!    and a selector before `of the` (`the bigger of the two boxes`);
//! 2. the candidates: what the head names, kept by the words before it that say what the
//!    objects are ([`pre`](super::pre): `the red chair`, `the other chair`);
//! 3. the modifier after the head ([`post`](super::post)), when [`attach`](super::attach)
//!    says it picks or describes (`the book on the side table`);
//! 4. the picks by place and size before the head (`the left speaker`, `the bigger box`);
//! 5. `itself` (the one named before) and the members a group leaves out
//!    ([`exclude`](super::exclude): `all the chairs except chair 3`);
//! 6. the last checks: an ordinal with nothing to count from, a generic noun with
//!    nothing to say which, the number asked for; then a group in a stable order.

use super::attach::{Choice, PostText};
use super::error::{self, GroundError};
use super::pre::Premods;
use super::select::{self, Direction, Relation};
use super::{modifier, words, Head, Mode, Np, Post, Reader, Reason, ReasonKind};
use std::ops::Range;
use words::Count;

/// A noun phrase being read: where it is so far, how many objects it asks for, and the
/// candidates it has come to.
struct Draft {
    /// Where it starts: its determiner, or its first word.
    start: usize,
    /// The token after the last word read so far.
    end: usize,
    /// How many objects it asks for.
    count: Count,
    /// The candidates left, in order.
    objects: Vec<usize>,
    /// Why, so far.
    reasons: Vec<Reason>,
    /// The head's candidates before any pick: what "the other one" picks from.
    pool: Vec<usize>,
    /// Modifiers before the head (or a selector before `of the`) pick: the candidates are
    /// every object the head names literally.
    modified: bool,
    /// A modifier after the head has picked or described: a second one ("the box against
    /// the wall with the monkey on it") narrows what it left.
    posted: bool,
    /// What the modifier after the head left, for a size word before it to pick from
    /// ("the tall box by the door": the boxes by the door): what a contrasting "the short
    /// one" picks from next.
    near: Option<Vec<usize>>,
}

/// How a noun phrase opens: where it starts, how many its determiners ask for, and a
/// selector before `of` a group.
struct Opening {
    /// Where it starts: its determiner (or the `the` before a selector), or its first word.
    start: usize,
    /// How many its determiners (or a plural head) ask for.
    count: Count,
    /// "the bigger of the two boxes": the token of the selector.
    outer: Option<usize>,
}

/// Words after an object found on a surface named before that only say so again ("next
/// to the plate that's there").
const RESTATED: &[&[&str]] = &[
    &["that", "is", "on", "it"],
    &["that", "are", "on", "it"],
    &["which", "is", "on", "it"],
    &["which", "are", "on", "it"],
    &["that", "is", "there"],
    &["that", "are", "there"],
    &["which", "is", "there"],
    &["that's", "on", "it"],
    &["that's", "there"],
    &["on", "it"],
    &["there"],
];

impl Reader<'_> {
    /// Reads the noun phrase around a head: determiner and modifiers before it, and (when
    /// `mode` is [`Mode::Main`] and the noun alone fits several) a modifier after it.
    ///
    /// # Errors
    /// A phrase that fits no object, several where it asks for one, or a modifier that
    /// cannot pick.
    pub(super) fn noun_phrase(
        &self,
        head: Head,
        bound: &[usize],
        mode: Mode,
    ) -> Result<Np, GroundError> {
        let h = head.range.start;
        let first = self.premodifier_start(h);
        let opening = self.opening(&head, first);
        let mut at: Vec<usize> = (first..h).collect();
        at.extend(opening.outer);
        let mut mods = self.premodifiers(&at);
        let mut draft = self.candidates(&head, &opening, &mods, !at.is_empty(), bound)?;
        self.post_stage(&head, &mut draft, &mut mods, bound, mode)?;
        if draft.posted && mode != Mode::Nested && self.carrying_follows(draft.end) {
            self.post_stage(&head, &mut draft, &mut mods, bound, mode)?;
        }
        let objects = std::mem::take(&mut draft.objects);
        // Several left by the modifier after the head for a size word before it to pick
        // from: the group a contrasting "the short one" picks from next.
        let sized = (first..h).any(|k| self.word(k).and_then(words::size_word).is_some());
        if draft.posted && sized && objects.len() > 1 {
            draft.near = Some(objects.clone());
        }
        let phrase = self.span_text(&(draft.start..draft.end));
        draft.objects = self.pick_by_premodifiers(
            &head,
            draft.count,
            &mut mods,
            objects,
            &mut draft.reasons,
            &phrase,
        )?;
        self.itself(&mut draft, bound);
        // (Inside a modifier only "that N": "the chairs at that table".)
        let main_or_that = mode == Mode::Main || self.is_word(draft.start, &["that", "this"]);
        if main_or_that && draft.count == Count::One {
            self.bridge(&head, &mut draft, bound);
        }
        if mode == Mode::Main && matches!(draft.count, Count::All) && !head.generic {
            self.leave_out(&head, &mut draft, bound)?;
        }
        if mods.ordinal.is_none() {
            self.taken_from(&mut draft, bound);
        }
        self.finish(head, draft, mods.ordinal, mode)
    }

    /// "take the vase off the table", "the book from the shelf", "the keys out of the
    /// bowl": of several the phrase fits, the one what was named before it rests on —
    /// where a thing is taken from is where it is.
    fn taken_from(&self, draft: &mut Draft, bound: &[usize]) {
        let before = |n: usize| draft.start.checked_sub(n).and_then(|k| self.word(k));
        let source = matches!(before(1), Some("off" | "from"))
            || (before(1) == Some("of") && before(2) == Some("out"));
        // Nothing named before: what "it" means (the selection).
        let bound = if bound.is_empty() {
            self.selection.as_slice()
        } else {
            bound
        };
        if !source || draft.count != Count::One || draft.objects.len() < 2 || bound.is_empty() {
            return;
        }
        let holding: Vec<usize> = draft
            .objects
            .iter()
            .copied()
            .filter(|&o| {
                bound
                    .iter()
                    .any(|&b| self.scene.objects[b].support == Some(o))
            })
            .collect();
        if let [one] = holding.as_slice() {
            draft.objects = vec![*one];
            draft.reasons.push(modifier(&format!(
                "{} is what {} rests on",
                self.name(*one),
                error::list(
                    &bound
                        .iter()
                        .filter(|&&b| self.scene.objects[b].support == Some(*one))
                        .map(|&b| self.name(b))
                        .collect::<Vec<_>>()
                )
            )));
        }
    }

    /// How the phrase of `head` opens, before token `first` (where the modifiers before
    /// the head start).
    fn opening(&self, head: &Head, first: usize) -> Opening {
        let (start, count) = self.determiners(head, first);
        match self.selector_of_group(start, count) {
            Some(m) => Opening {
                start: m - 1,
                count,
                outer: Some(m),
            },
            None => Opening {
                start,
                count,
                outer: None,
            },
        }
    }

    /// The determiners before token `first` (where the modifiers before the head start):
    /// where the phrase starts, and how many it asks for (`both`, `all the`, `every`, a
    /// plural noun).
    fn determiners(&self, head: &Head, first: usize) -> (usize, Count) {
        let mut start = first;
        let mut count = if head.plural { Count::All } else { Count::One };
        if start > 0 && self.word(start - 1).is_some_and(words::is_determiner) {
            start -= 1;
            match self.word(start).unwrap_or("") {
                "both" => count = Count::Exactly(2),
                "all" | "every" | "each" => count = Count::All,
                "these" | "those" if head.plural => count = Count::All,
                _ => {}
            }
            // "all the", "both of the", "all of the".
            if self.word(start) == Some("the") && start > 0 && !self.consumed[start - 1] {
                if self.is_word(start - 1, &["all", "both", "each"]) {
                    start -= 1;
                } else if self.is_word(start - 1, &["of"])
                    && start > 1
                    && self.is_word(start - 2, &["all", "both", "each"])
                {
                    start -= 2;
                }
                match self.word(start).unwrap_or("") {
                    "both" => count = Count::Exactly(2),
                    "all" | "each" => count = Count::All,
                    _ => {}
                }
            }
        }
        (start, count)
    }

    /// "the bigger of the two boxes", "the left one of the two": the selector before `of`
    /// a group starting at `start` (the phrase then starts at the `the` before it).
    fn selector_of_group(&self, start: usize, count: Count) -> Option<usize> {
        // Only of a group: "the left of the dresser" is a place, not a pick.
        let of_a_group = !matches!(count, Count::One);
        if !(of_a_group
            && start >= 2
            && self.is_word(start - 1, &["of"])
            && !self.consumed[start - 2])
        {
            return None;
        }
        let m = start - 2;
        let w = self.word(m).unwrap_or("");
        let selector = words::size_word(w).is_some()
            || words::side_word(w).is_some()
            || words::ordinal(w).is_some();
        (selector && m > 0 && self.is_word(m - 1, &["the"]) && !self.consumed[m - 1]).then_some(m)
    }

    /// The candidates before any modifier after the head: what it names (with modifiers,
    /// every object it names literally: "the smallest barrel" compares 'barrel', 'barrel
    /// 2' and 'small barrel'), kept by the words that say what they are, and the number
    /// asked for (`the bigger of the two boxes`: two fit, one is picked).
    ///
    /// # Errors
    /// A colour or material no candidate has; a group of the wrong size before `of`.
    fn candidates(
        &self,
        head: &Head,
        opening: &Opening,
        mods: &Premods,
        modified: bool,
        bound: &[usize],
    ) -> Result<Draft, GroundError> {
        let start = opening.start;
        let mut objects = if modified {
            head.literal.clone()
        } else {
            head.objects.clone()
        };
        let mut reasons = vec![head.reason.clone()];
        if let Some(t) = &head.typo {
            reasons.push(t.clone());
        }
        // "the red and blue cushions" where 'Cushion_Blue' is named "blue cushion": the
        // head holds the last colour; the others pick among what the noun alone names.
        let named_with_last = mods.either
            && head.range.len() > 1
            && self.word(head.range.start).is_some_and(words::is_colour);
        if named_with_last {
            let base = self
                .head_at(head.range.start + 1)
                .filter(|b| b.range.end == head.range.end);
            if let Some(base) = base {
                let mut union = objects.clone();
                for w in &mods.picks {
                    let one = std::slice::from_ref(w);
                    let fits = self.pick_by_words(
                        &base,
                        one,
                        base.literal.clone(),
                        &mut reasons,
                        bound,
                        start,
                    )?;
                    for o in fits {
                        if !union.contains(&o) {
                            union.push(o);
                        }
                    }
                }
                objects = union;
                reasons.push(super::modifier("each colour named its own objects"));
            }
        }
        let objects = if named_with_last {
            objects
        } else if mods.either && mods.picks.len() > 1 {
            // "the red and blue cushions": the red ones and the blue ones.
            let mut union: Vec<usize> = Vec::new();
            for w in &mods.picks {
                let one = std::slice::from_ref(w);
                let fits =
                    self.pick_by_words(head, one, objects.clone(), &mut reasons, bound, start)?;
                for o in fits {
                    if !union.contains(&o) {
                        union.push(o);
                    }
                }
            }
            objects.retain(|o| union.contains(o));
            objects
        } else {
            self.pick_by_words(head, &mods.picks, objects, &mut reasons, bound, start)?
        };
        let mut count = mods.count.unwrap_or(opening.count);
        if opening.outer.is_some() {
            // "the bigger of the two boxes": two fit, one is picked.
            if let Count::Exactly(n) = count {
                if objects.len() != n {
                    let range = start..head.range.end;
                    return Err(GroundError::Count {
                        phrase: self.span_text(&range),
                        span: self.byte_span(&range),
                        wanted: n,
                        found: self.names(&objects),
                    });
                }
            }
            count = Count::One;
        }
        Ok(Draft {
            start,
            end: head.range.end,
            count,
            objects,
            reasons,
            pool: head.literal.clone(),
            modified,
            posted: false,
            near: None,
        })
    }

    /// The modifier after the head, applied when it picks or describes: the candidates it
    /// keeps, and the phrase then ends after it (unless it says where the object is taken
    /// from, which stays in the instruction).
    ///
    /// # Errors
    /// A modifier that keeps none of the candidates or cannot tell them apart; a nearest
    /// or farthest of a group with no number.
    fn post_stage(
        &self,
        head: &Head,
        draft: &mut Draft,
        mods: &mut Premods,
        bound: &[usize],
        mode: Mode,
    ) -> Result<(), GroundError> {
        // "a shelf of the bookcase", "the second shelf in the shelving unit": a part of
        // the case of shelves named right after it, which the translator reads; the
        // phrase stands for the case, nothing before the head picks, and the case is
        // its own phrase next (`drop_parts` then takes this one out).
        if let Some(case) = self.part_of_shelves(head, draft, bound)? {
            draft.objects = case;
            *mods = Premods::default();
            return Ok(());
        }
        let wanted = draft.count.wanted(draft.objects.len());
        let group = matches!(draft.count, Count::All) && !head.generic;
        let choice = Choice {
            picks: (draft.objects.len() != wanted && !group)
                || mods.ordinal.is_some()
                || head.generic,
            group,
            selectors_first: mods.selectors(),
        };
        let Some((p, p_end)) =
            self.attached_post(head, draft, mods.ordinal, choice, bound, mode)?
        else {
            return Ok(());
        };
        let p_kind = match &p {
            Post::Relation(r, _) => Some(*r),
            _ => None,
        };
        if !draft.modified && !draft.posted {
            draft.objects = head.literal.clone();
        }
        // "the second table from the window in the front row": the line first, then the
        // order along it.
        let mut p_end = p_end;
        let ordered = matches!(p, Post::From(_) | Post::FromObject(_) | Post::Side(..));
        if mods.ordinal.is_some() && ordered {
            if let Some((Post::Line(line), l_end)) = self.line_at(p_end) {
                let in_line = select::in_line(self.scene, &draft.objects, line);
                if let Some(kept) = in_line.filter(|k| !k.is_empty()) {
                    draft.objects = kept;
                    p_end = l_end;
                }
            }
        }
        let words = self.span_text(&(draft.end..p_end));
        let at = self.span_text(&(draft.start..p_end));
        // With modifiers before the noun still to pick ("the front painting on the right
        // wall"), or for a group, the modifier after it keeps every object it fits.
        let filter = mods.selectors() || group;
        if group && matches!(p, Post::Relation(Relation::Nearest | Relation::Farthest, _)) {
            return Err(GroundError::NoPick {
                phrase: at,
                reason: format!(
                    "say how many ('the two {} {words}')",
                    error::plural(&head.text)
                ),
            });
        }
        // "everything on the shelf" is all it names; "the thing on the left" one, the one
        // furthest that way.
        let one_at_a_side = matches!(draft.count, Count::One) && matches!(p, Post::Side(..));
        let wanted = if (head.generic && !one_at_a_side) || filter {
            usize::MAX
        } else {
            wanted
        };
        let text = PostText {
            at: &at,
            words: &words,
        };
        let objects = std::mem::take(&mut draft.objects);
        draft.objects =
            self.apply_post(p, objects, &mut mods.ordinal, filter, wanted, head, &text)?;
        draft.reasons.push(modifier(&format!(
            "\"{words}\" picked {}",
            error::list(&self.names(&draft.objects))
        )));
        // Where it is taken from stays in the instruction: it is also where the
        // object leaves ("take X1 off X2").
        if !matches!(p_kind, Some(Relation::Off)) {
            draft.end = p_end;
        }
        draft.posted = true;
        Ok(())
    }

    /// Whether what it carries is said at token `k`, after a first modifier ("… against
    /// the left wall with the monkey on it", "… holding the vase"): a second modifier
    /// of the same phrase. Not what belongs to it ("with its chairs", "with everything
    /// on it"), which [`Self::with_dependents`] and the translator read.
    fn carrying_follows(&self, k: usize) -> bool {
        self.is_word(k, &["with", "holding", "carrying"])
            && !self.is_word(
                k + 1,
                &[
                    "its",
                    "their",
                    "everything",
                    "all",
                    "what",
                    "whatever",
                    "anything",
                ],
            )
    }

    /// The cases of shelves a phrase whose head is "shelf" or "shelves" is a part of
    /// ([`Self::case_of_shelf`]).
    fn part_of_shelves(
        &self,
        head: &Head,
        draft: &Draft,
        bound: &[usize],
    ) -> Result<Option<Vec<usize>>, GroundError> {
        if !matches!(head.text.as_str(), "shelf" | "shelves") || draft.end != head.range.end {
            return Ok(None);
        }
        Ok(self.case_of_shelf(draft.end, bound)?.map(|(case, _)| case))
    }

    /// After a shelf ending at token `k`: the cases of shelves of "of", "in" or "on" right
    /// after it (past "from the top": "the second shelf from the top of the bookcase"),
    /// when each is a case of shelves, and where their phrase ends.
    ///
    /// # Errors
    /// The phrase after it cannot be grounded.
    pub(super) fn case_of_shelf(
        &self,
        k: usize,
        bound: &[usize],
    ) -> Result<Option<(Vec<usize>, usize)>, GroundError> {
        let mut k = k;
        if self.is_word(k, &["from"])
            && self.is_word(k + 1, &["the"])
            && self.is_word(k + 2, &["top", "bottom"])
        {
            k += 3;
        }
        // "of" is no relation: the phrase after it, read on its own.
        let found = if self.is_word(k, &["of"]) {
            self.nested_np(k + 1, bound)?
        } else if self.is_word(k, &["in", "on"]) {
            match self.post_modifier(k, bound)? {
                Some((Post::Relation(_, targets), end)) => Some((targets, end)),
                _ => None,
            }
        } else {
            None
        };
        Ok(found.filter(|(targets, _)| {
            !targets.is_empty()
                && targets
                    .iter()
                    .all(|&t| super::kind::form_of(self.scene, t).shelves())
        }))
    }

    /// The modifier after the head of a phrase on its own (`mode` [`Mode::Main`]), if it
    /// picks or describes; `from` an object after an ordinal is where counting starts.
    fn attached_post(
        &self,
        head: &Head,
        draft: &Draft,
        ordinal: Option<usize>,
        choice: Choice,
        bound: &[usize],
        mode: Mode,
    ) -> Result<Option<(Post, usize)>, GroundError> {
        // A nested phrase reads no modifier of its own, but "the same bench as the
        // microscope" (in "the beaker on the same bench as the microscope") says which
        // bench — once: a chain of them is not followed.
        let same_as = || {
            (draft.start..draft.end).any(|i| self.word(i) == Some("same"))
                && self.word(draft.end) == Some("as")
                && !(draft.end + 1..draft.end + 5).any(|i| self.word(i) == Some("same"))
        };
        let post = if mode != Mode::Nested || same_as() {
            self.post_modifier(draft.end, bound)?
        } else {
            None
        };
        let post = post.map(|(p, p_end)| match p {
            Post::FromObject(t) if ordinal.is_some() => {
                let c = self.scene.objects[t].world_aabb().center();
                (Post::From(Direction::From(c)), p_end)
            }
            p => (p, p_end),
        });
        self.attach(post, head, draft.start, &draft.objects, choice)
    }

    /// "everything on the right nightstand but not the nightstand itself": the one
    /// named before, or what the objects named before stand on.
    fn itself(&self, draft: &mut Draft, bound: &[usize]) {
        if !(draft.objects.len() > 1 && self.is_word(draft.end, &["itself", "themselves"])) {
            return;
        }
        let mentioned: Vec<usize> = bound
            .iter()
            .flat_map(|&b| [Some(b), self.scene.objects[b].support])
            .flatten()
            .collect();
        let kept: Vec<usize> = draft
            .objects
            .iter()
            .copied()
            .filter(|o| mentioned.contains(o))
            .collect();
        if !kept.is_empty() {
            draft.reasons.push(modifier(&format!(
                "\"itself\": {}, named before",
                error::list(&self.names(&kept))
            )));
            draft.objects = kept;
        }
    }

    /// "move chair 8 further from the table", "keep the vase on the table", "keep it
    /// facing the table": where "the N" fits several but is said as what an object named
    /// before is measured from (after `from`, `closer to`, `towards`, `facing`, `the edge
    /// of`, `keep … on`), it is the one of them that object rests on or is drawn up to,
    /// or the one named before ("closer to coffee table 2 but keep it facing the table";
    /// after `that` or `this`, wherever it stands: "… between the chairs at that table").
    /// Only where exactly one fits; otherwise the phrase stays as it was (and is refused
    /// as ambiguous). Not after `on`, `to` or `next to`, where "the table" is where
    /// something goes and may well be another one.
    fn bridge(&self, head: &Head, draft: &mut Draft, bound: &[usize]) {
        if draft.objects.len() < 2 || bound.is_empty() {
            return;
        }
        // "… at that table": a demonstrative points at the one named before, anywhere.
        let demonstrative = self.is_word(draft.start, &["that", "this"]);
        if !demonstrative && !self.is_word(draft.start, &["the"]) {
            return;
        }
        if !demonstrative && !self.measured_from(draft.start) {
            self.on_named(head, draft, bound);
            return;
        }
        let named: Vec<usize> = draft
            .objects
            .iter()
            .copied()
            .filter(|o| bound.contains(o))
            .collect();
        if let [one] = named.as_slice() {
            draft.reasons.push(modifier(&format!(
                "the {} named before: {}",
                head.text,
                self.name(*one)
            )));
            draft.objects = named;
            return;
        }
        if let Some((owner, of)) = self.owner_of_named(&draft.objects, bound) {
            draft.reasons.push(modifier(&format!(
                "the one {} rests on or is drawn up to: {}",
                self.name(of),
                self.name(owner)
            )));
            draft.objects = vec![owner];
        }
    }

    /// "put the atlas on reading table 2, to the right of the lamp": "the N" that fits
    /// several, said as where something goes beside (after `of`, `to`, `beside`, `by`,
    /// `near`, `behind`, `between … and`) or as what stays ("… but keep the lamp where it
    /// is"), is the one of them resting on an object named before, where exactly one
    /// does.
    fn on_named(&self, head: &Head, draft: &mut Draft, bound: &[usize]) {
        let placed_by = draft.start > 0
            && self.is_word(
                draft.start - 1,
                &[
                    "of", "to", "beside", "by", "near", "behind", "between", "and",
                ],
            );
        // "move table 1 left, keeping the lamp where it is": the lamp on it.
        let held = super::hold::cue_before(&self.tokens, draft.start);
        if !placed_by && !held {
            return;
        }
        let on: Vec<(usize, usize)> = draft
            .objects
            .iter()
            .filter_map(|&c| {
                let s = self.scene.objects[c].support?;
                bound.contains(&s).then_some((c, s))
            })
            .collect();
        if let [(one, under)] = on.as_slice() {
            draft.reasons.push(modifier(&format!(
                "the {} on {}, named before: {}",
                head.text,
                self.name(*under),
                self.name(*one)
            )));
            draft.objects = vec![*one];
            // "the plate that's there", "the cup that is on it": said again, read.
            let words: Vec<&str> = (0..self.tokens.len())
                .map(|k| self.word(k).unwrap_or(""))
                .collect();
            let said_again = crate::discourse::longest_phrase(&words, draft.end, RESTATED)
                .filter(|&n| (draft.end..draft.end + n).all(|k| !self.consumed[k]));
            draft.end += said_again.unwrap_or(0);
        }
    }

    /// Whether the words before token `start` say that what follows is what something is
    /// measured from or kept at, not where it goes ([`Self::bridge`]).
    fn measured_from(&self, start: usize) -> bool {
        let before = |n: usize| start.checked_sub(n).and_then(|k| self.word(k));
        match before(1) {
            Some("from" | "towards" | "toward" | "facing" | "face" | "faces") => true,
            Some("to") => matches!(before(2), Some("closer" | "nearer")),
            Some("of") => matches!(
                before(2),
                Some("edge" | "middle" | "centre" | "center" | "end" | "corner")
            ),
            Some("on") => (2..=4).any(|n| matches!(before(n), Some("keep" | "stay" | "stays"))),
            _ => false,
        }
    }

    /// "all the chairs except the front-left one", "every chair but chair 3": the group
    /// without the members it leaves out, and the phrase then ends after them.
    ///
    /// # Errors
    /// A left-out object that is not one of the group, or a left-out phrase that fits
    /// several where it names one.
    fn leave_out(
        &self,
        head: &Head,
        draft: &mut Draft,
        bound: &[usize],
    ) -> Result<(), GroundError> {
        let end = draft.end;
        let Some((excluded, e_end)) = self.exclusion(end, &draft.objects, &head.text, bound)?
        else {
            return Ok(());
        };
        let at = self.span_text(&(draft.start..e_end));
        if let Some(&stray) = excluded.iter().find(|o| !draft.objects.contains(o)) {
            return Err(GroundError::NoPick {
                phrase: at,
                reason: format!("'{}' is not one of them", self.name(stray)),
            });
        }
        draft.objects.retain(|o| !excluded.contains(o));
        draft.reasons.push(modifier(&format!(
            "\"{}\" left out {}",
            self.span_text(&(end..e_end)),
            error::list(&self.names(&excluded))
        )));
        draft.end = e_end;
        Ok(())
    }

    /// The last checks of a noun phrase: an ordinal with no direction, a generic noun with
    /// nothing to say which, the count asked for, a typo that fits several; then a group in
    /// a stable order (left to right, then back to front).
    ///
    /// # Errors
    /// Any of those checks.
    fn finish(
        &self,
        head: Head,
        draft: Draft,
        ordinal: Option<usize>,
        mode: Mode,
    ) -> Result<Np, GroundError> {
        let Draft {
            start,
            end,
            count,
            mut objects,
            mut reasons,
            pool,
            near,
            ..
        } = draft;
        let phrase = self.span_text(&(start..end));
        if let Some(o) = ordinal {
            objects = self.pick_numbered(&head, o, objects, &mut reasons, &phrase)?;
        }
        // "everything", "the thing" with nothing after it to say which — unless the words
        // before it did ("the flat thing").
        if head.generic && end == head.range.end && objects.len() == head.objects.len() {
            return Err(GroundError::NoPick {
                phrase,
                reason: "say which things ('everything on the table')".into(),
            });
        }
        self.check_count(&head, count, &objects, start..end, mode)?;
        if objects.len() > 1 && mode == Mode::Main {
            reasons.push(Reason {
                kind: ReasonKind::Group,
                detail: format!("{} objects", objects.len()),
            });
            self.in_stable_order(&mut objects);
        }
        Ok(Np {
            range: start..end,
            objects,
            pool,
            near,
            reasons,
            head: head.text,
            owners: None,
        })
    }

    /// An ordinal `o` that nothing has used up: among objects numbered 1 to n
    /// (`SM_Chair_01` … `SM_Chair_04`), "the second chair" is the one numbered 2, as its
    /// name says.
    ///
    /// # Errors
    /// Several candidates left with no direction to count from.
    fn pick_numbered(
        &self,
        head: &Head,
        o: usize,
        mut objects: Vec<usize>,
        reasons: &mut Vec<Reason>,
        phrase: &str,
    ) -> Result<Vec<usize>, GroundError> {
        let mut numbers: Vec<Option<u32>> =
            objects.iter().map(|&x| self.g.index.number(x)).collect();
        numbers.sort_unstable();
        let counted = numbers
            .iter()
            .enumerate()
            .all(|(k, n)| *n == u32::try_from(k + 1).ok());
        if objects.len() > 1 && counted {
            let picked = objects
                .iter()
                .copied()
                .find(|&x| self.g.index.number(x) == u32::try_from(o).ok());
            if let Some(picked) = picked {
                objects = vec![picked];
                reasons.push(modifier(&format!(
                    "\"{}\" picked {}, numbered {o} of 1 to {}",
                    ordinal_word(o),
                    self.name(picked),
                    numbers.len()
                )));
            }
        }
        if objects.len() > 1 {
            return Err(GroundError::NoPick {
                reason: format!(
                    "{} from where? say 'the {} {} from the left' or name one ('{}')",
                    ordinal_word(o),
                    ordinal_word(o),
                    head.text,
                    self.name(objects[0])
                ),
                phrase: phrase.to_string(),
            });
        }
        Ok(objects)
    }

    /// Whether the candidates left are what the phrase (tokens `range`) asks for: some,
    /// as many as its count, and one for a typo; a phrase inside a modifier
    /// ([`Mode::Nested`]) may fit several.
    ///
    /// # Errors
    /// None fits, several where one is asked for, another number than asked for, or a
    /// typo that fits several.
    fn check_count(
        &self,
        head: &Head,
        count: Count,
        objects: &[usize],
        range: Range<usize>,
        mode: Mode,
    ) -> Result<(), GroundError> {
        let phrase = self.span_text(&range);
        let wanted = count.wanted(objects.len());
        if objects.is_empty() {
            return Err(GroundError::Unknown {
                phrase,
                suggestions: Vec::new(),
            });
        }
        let ambiguous_ok = mode == Mode::Nested && count == Count::One;
        if objects.len() != wanted && !ambiguous_ok {
            return Err(match count {
                Count::One => self.ambiguous(&range, &head.text, objects, 2),
                _ => GroundError::Count {
                    phrase,
                    span: self.byte_span(&range),
                    wanted,
                    found: self.names(objects),
                },
            });
        }
        if head.typo.is_some() && objects.len() != 1 && mode == Mode::Main {
            return Err(GroundError::Unknown {
                phrase,
                suggestions: self.names(objects),
            });
        }
        Ok(())
    }

    /// Sorts a group into the order it binds in: left to right, then back to front.
    fn in_stable_order(&self, objects: &mut [usize]) {
        objects.sort_by(|&a, &b| {
            let (ca, cb) = (
                self.scene.objects[a].world_aabb().center(),
                self.scene.objects[b].world_aabb().center(),
            );
            ca.x.total_cmp(&cb.x)
                .then(ca.z.total_cmp(&cb.z))
                .then(a.cmp(&b))
        });
    }
}

/// An ordinal in words, for messages (`2` → `second`).
fn ordinal_word(n: usize) -> &'static str {
    match n {
        1 => "first",
        2 => "second",
        3 => "third",
        4 => "fourth",
        5 => "fifth",
        6 => "sixth",
        7 => "seventh",
        8 => "eighth",
        9 => "ninth",
        10 => "tenth",
        _ => "last",
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::{means, refused, with_reader};
    use super::*;

    /// The objects of the noun phrase whose head is at token `k` of `text`, by name, read
    /// on its own ([`Mode::Main`]) or inside a modifier ([`Mode::Nested`]).
    fn phrase(
        scene: &str,
        text: &str,
        k: usize,
        mode: Mode,
    ) -> Result<(Range<usize>, Vec<String>), GroundError> {
        with_reader(scene, text, |r| {
            let np = r.noun_phrase(r.head_at(k).unwrap(), &[], mode)?;
            Ok((np.range.clone(), r.names(&np.objects)))
        })
    }

    #[test]
    fn determiners_say_how_many_and_where_the_phrase_starts() {
        let (range, objects) =
            phrase("dining_room", "move all of the chairs back", 4, Mode::Main).unwrap();
        assert_eq!(range, 1..5);
        assert_eq!(objects, ["chair", "chair 3", "chair 2", "chair 4"]);
        let (range, objects) =
            phrase("living_room", "move both speakers back", 2, Mode::Main).unwrap();
        assert_eq!((range, objects.len()), (1..3, 2));
        let (range, objects) = phrase(
            "living_room",
            "move the bigger of the two lamps left",
            6,
            Mode::Main,
        )
        .unwrap();
        assert_eq!((range, objects), (1..7, vec!["floor lamp".to_string()]));
        let e = phrase("dining_room", "move the two chairs left", 3, Mode::Main).unwrap_err();
        assert!(matches!(e, GroundError::Count { wanted: 2, .. }), "{e}");
    }

    #[test]
    fn a_phrase_inside_a_modifier_may_fit_several() {
        let (_, objects) = phrase("dining_room", "on the chair", 2, Mode::Nested).unwrap();
        assert_eq!(objects, ["chair", "chair 2", "chair 3", "chair 4"]);
        let e = phrase("dining_room", "move the chair left", 2, Mode::Main).unwrap_err();
        assert!(matches!(e, GroundError::Ambiguous { .. }), "{e}");
        // Inside a modifier there is no modifier after the head.
        let (range, objects) =
            phrase("living_room", "the lamp on the side table", 1, Mode::Nested).unwrap();
        assert_eq!((range, objects.len()), (0..2, 2));
    }

    #[test]
    fn a_modifier_after_the_head_picks_and_ends_the_phrase() {
        let (range, objects) = phrase(
            "living_room",
            "move the lamp on the side table left",
            2,
            Mode::Main,
        )
        .unwrap();
        assert_eq!((range, objects), (1..7, vec!["table lamp".to_string()]));
        refused(
            "dining_room",
            "lift the chairs nearest the sideboard 10 cm",
            &["say how many"],
        );
    }

    #[test]
    fn ordinals_need_somewhere_to_count_from() {
        means(
            "classroom",
            "turn the second student chair from the right",
            &[&["student chair 2"]],
        );
        means(
            "classroom",
            "move the third student chair from the left",
            &[&["student chair 3"]],
        );
        refused(
            "dining_room",
            "move the second chair",
            &["second from where?"],
        );
        // Desks in two rows: "third from the left" ties.
        refused(
            "classroom",
            "move the third student desk from the left",
            &["student desk"],
        );
    }

    #[test]
    fn groups_bind_every_member_left_to_right() {
        means(
            "dining_room",
            "move all the chairs back",
            &[&["chair", "chair 3", "chair 2", "chair 4"]],
        );
        means(
            "living_room",
            "move both speakers back",
            &[&["speaker", "speaker 2"]],
        );
        means(
            "kitchen",
            "move the two stools left",
            &[&["stool", "stool 2"]],
        );
        means(
            "dining_room",
            "lift the plates",
            &[&["plate", "plate 3", "plate 2", "plate 4"]],
        );
        means(
            "dining_room",
            "move the chairs on the left 20 cm to the left",
            &[&["chair", "chair 3"]],
        );
    }

    #[test]
    fn ambiguity_is_refused_naming_the_candidates() {
        let m = refused(
            "dining_room",
            "move the chair left",
            &["chair", "chair 2", "chair 3", "chair 4"],
        );
        assert!(m.starts_with("\"the chair\" could mean"), "{m}");
        assert!(m.contains("name one ('"), "{m}");
        refused(
            "living_room",
            "move the speaker left",
            &["speaker", "speaker 2"],
        );
        refused(
            "living_room",
            "move the lamp left",
            &["floor lamp", "table lamp"],
        );
        refused(
            "dining_room",
            "move the two chairs left",
            &["chair", "chair 2", "chair 3", "chair 4"],
        );
    }
}

//! The reader's state, carried from clause to clause, and what every stage of the reader
//! shares: what a clause produced, the refusal of words left unread, directions, `to the`.
//! Below [`super::read`] (which dispatches a clause to its stage) and every stage, so that
//! none of them imports another upwards.

use super::clause::Clause;
use super::relations::{Step, Steps};
use super::words::Action;
use crate::translate::Near;
use std::collections::BTreeMap;

/// What the translator knows besides the query: how many variables, and what is known of
/// their objects ([`super::Known`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Facts<'k> {
    /// Variables bound.
    pub variables: usize,
    /// What is known of them.
    pub known: &'k super::Known<'k>,
}

/// The state carried from clause to clause.
pub(crate) struct Reader<'a> {
    /// What is known besides the query.
    pub facts: &'a Facts<'a>,
    /// The steps read so far, per variable.
    pub steps: Steps,
    /// Per variable, what it was last put next to or between.
    pub near: BTreeMap<usize, Near>,
    /// The subjects of the last clause: what "it" and "them" mean.
    pub(super) last_subjects: Vec<usize>,
    /// The objects the last relation was to ("next to X2"): what "it" means after "face"
    /// when "it" is the clause's subject ("… and turn it to face it").
    pub(super) last_targets: Vec<usize>,
    /// The verb of the last clause that had one: the verb of a clause without one
    /// ("move X1 left, X2 right").
    pub(super) last_action: Option<Action>,
    /// The first variable's steps of the last clause: what "do the same" repeats.
    pub(super) last_steps: Vec<Step>,
    /// Whether the relation being read puts its subjects on the floor ("on the floor next
    /// to X2"), whatever the target stands on.
    pub(super) on_floor: bool,
    /// The subjects and directions of the last clause when it was a shift ("move X1 a bit
    /// to the right"): what a following "towards X2" may only explain.
    pub(super) last_shift: Option<(Vec<usize>, Vec<Direction>)>,
    /// What the last clause produced: what "…, with everything on it" adds to.
    pub(super) last_produced: Produced,
    /// Whether more clauses follow the one being read: a remark about the objects ("X1 is
    /// way too low, bring it up") is read only before what is to be done.
    pub(super) more_follow: bool,
    /// Whether the clause refused was read and refused on its meaning ("put X1 back"): no
    /// other translator should be asked to read it (a model might read a move backwards).
    pub(super) settled: bool,
}

/// What one clause asks: each variable with one step, in order.
pub(super) type Produced = Vec<(usize, Step)>;

/// The message for words the translator could not read: those words (the clause, objects
/// as X1 …, only when none of it was read). Front ends add their own advice (the CLI
/// names `--llm`).
pub(crate) fn not_read(unread: &str, clause: &str) -> String {
    if unread == clause || unread.is_empty() {
        format!(
            "the offline translator could not read \"{}\"; rephrase it",
            clause.trim()
        )
    } else {
        format!("the offline translator could not read \"{unread}\"; rephrase it")
    }
}

/// A direction as (axis 0..2, sign).
pub(super) type Direction = (usize, f64);

/// Marks `to the` / `towards the` / `to its` before position `i`.
pub(super) fn mark_to_the(c: &mut Clause, i: usize) {
    for words in [
        &["to", "the"][..],
        &["towards", "the"],
        &["toward", "the"],
        &["to", "its"],
        &["on", "the"],
        &["to"],
        &["towards"],
        &["toward"],
    ] {
        let n = words.len();
        if i >= n && c.words_at(i - n, words) {
            c.mark(i - n..i);
            return;
        }
    }
}

impl<'a> Reader<'a> {
    /// A reader of an instruction about these facts, with nothing read yet.
    pub fn new(facts: &'a Facts<'a>) -> Self {
        Self {
            facts,
            steps: Steps::new(),
            near: BTreeMap::new(),
            last_subjects: Vec::new(),
            last_targets: Vec::new(),
            on_floor: false,
            last_action: None,
            last_steps: Vec::new(),
            last_shift: None,
            last_produced: Vec::new(),
            more_follow: false,
            settled: false,
        }
    }
}

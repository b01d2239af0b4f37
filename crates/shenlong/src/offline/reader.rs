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
}

/// What one clause asks: each variable with one step, in order.
pub(super) type Produced = Vec<(usize, Step)>;

/// Why the offline translator gives no answer: the kind of refusal, and one line for the
/// user. Front ends add their own advice (the CLI names `--llm` for [`ReadError::Unread`]).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ReadError {
    /// Words it could not read: those words (the clause, objects as X1 …, only when none of
    /// it was read). Another translator (a model) may read them.
    #[error("the offline translator could not read \"{0}\"; rephrase it")]
    Unread(String),
    /// Read, but what is asked is left open or goes against the scene (a swap of three, a
    /// way that leads away from the target, an object drawn up to nothing): what to say.
    #[error("{0}")]
    Unclear(String),
    /// Read, but the object does not fit where it is to go: where else to say.
    #[error("{0}")]
    NoFit(String),
    /// An amount that must be a length and is not ("2 degrees closer to the wall").
    #[error("an amount {0} must be a length")]
    NotALength(&'static str),
    /// A place in the room, in a scene without one.
    #[error("the scene has no room (no \"bounds\"), so \"{0}\" has no walls or centre to go to")]
    NoRoom(String),
    /// A variable beyond those bound.
    #[error("the instruction names X{variable} but only {bound} objects are named")]
    Unbound {
        /// The variable's number (X3 is 3).
        variable: usize,
        /// How many are bound.
        bound: usize,
    },
    /// "In", "into" or "inside" an object: objects are solid boxes here, with no room
    /// inside (a wheelbarrow, a box, a bookcase), so putting one in another would end
    /// beside it.
    #[error("Shenlong sees each object as a solid box, so it cannot put {object} inside {container} yet; say \"on {container}\" to put it on top, or where beside it it goes")]
    Inside {
        /// What was to go in.
        object: String,
        /// What it was to go in.
        container: String,
    },
    /// "Put … back" asks for a pose before an earlier edit, which a one-shot edit has not.
    #[error("\"put … back\" asks for where it was before an earlier edit, and there is none to return to here; to move it backwards, say how far (\"move it back 50 cm\")")]
    Return,
}

impl ReadError {
    /// Whether it was read and refused on its meaning ("put X1 back", "put X1 in X2"), not
    /// for words it does not read: no other translator (a model, which might read a move
    /// backwards or put the object beside its container) should be asked instead.
    #[must_use]
    pub fn settled(&self) -> bool {
        matches!(self, Self::Return | Self::Inside { .. })
    }
}

/// The refusal of words the translator could not read: those words, or the clause when
/// none of it was read.
pub(crate) fn not_read(unread: &str, clause: &str) -> ReadError {
    if unread == clause || unread.is_empty() {
        ReadError::Unread(clause.trim().to_string())
    } else {
        ReadError::Unread(unread.to_string())
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
        }
    }
}

//! Why an operation on a session was refused, as data: a kind every front end answers by
//! (an HTTP status, MCP's `isError`, a Python exception class, the CLI's exit), the one
//! line for people, and for a phrase that could mean several objects the choices ready
//! to offer.

use crate::ground::Ambiguity;
use crate::pipeline::{EditError, EditErrorKind};
use serde::Serialize;

/// The kinds of refusal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ErrorKind {
    /// The request is malformed: an empty or over-long instruction, an unknown object
    /// named in `selected` or bound to an expression, an object bound twice, a motion
    /// beyond what poses hold exactly.
    BadInput,
    /// The instruction names nothing the scene has, or the translator cannot read it, or
    /// the expression is not a transformation.
    NotUnderstood,
    /// A phrase could mean several objects: `ambiguity` names them, each with the
    /// instruction that would choose it.
    Ambiguous,
    /// No collision-free placement was found, or only one away from where the object was
    /// put.
    NoFreePlace,
    /// The edit would move an object the instruction holds where it is, or take its
    /// support from under it.
    HeldWouldMove,
    /// The language model or its server failed, or gave no usable answer.
    Model,
    /// There is no change to undo.
    NothingToUndo,
    /// There is no undone change to redo.
    NothingToRedo,
    /// The scene cannot be written in the format asked for.
    Export,
    /// A bug in Shenlong, caught before it could take the process down; nothing changed.
    Internal,
}

impl ErrorKind {
    /// The kind's name as every front end writes it (`not_understood`).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::BadInput => "bad_input",
            Self::NotUnderstood => "not_understood",
            Self::Ambiguous => "ambiguous",
            Self::NoFreePlace => "no_free_place",
            Self::HeldWouldMove => "held_would_move",
            Self::Model => "model",
            Self::NothingToUndo => "nothing_to_undo",
            Self::NothingToRedo => "nothing_to_redo",
            Self::Export => "export",
            Self::Internal => "internal",
        }
    }
}

/// An operation refused; the session's scene is as it was.
///
/// Written as `{"kind": "ambiguous", "error": "…", "ambiguity": {…}}` by every front end.
#[derive(Clone, Debug, PartialEq, Serialize, thiserror::Error)]
#[error("{message}")]
pub struct OpError {
    /// What kind of refusal.
    pub kind: ErrorKind,
    /// One line for people: what and where.
    #[serde(rename = "error")]
    pub message: String,
    /// For [`ErrorKind::Ambiguous`]: the phrase, the objects it could mean and the
    /// instruction that names each one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ambiguity: Option<Box<Choices>>,
    /// For [`ErrorKind::NotUnderstood`]: the translator left words unread, which another
    /// translator (a language model) may read.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub unread: bool,
    /// The instruction an edit refused, as it ran: what a correction ("the left one")
    /// leans on once the session hears of the refusal ([`crate::session::Session::conclude`]).
    #[serde(skip)]
    pub(crate) refused: Option<String>,
}

impl OpError {
    /// A refusal of `kind` without choices.
    #[must_use]
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Self {
        Self {
            kind,
            message: message.into(),
            ambiguity: None,
            unread: false,
            refused: None,
        }
    }

    /// An edit's error; `instruction` is what the user typed, for the choices.
    #[must_use]
    pub fn from_edit(error: EditError, instruction: &str) -> Self {
        let ambiguity = error
            .ambiguity
            .as_ref()
            .map(|a| Box::new(Choices::new(instruction, a)));
        let kind = match error.kind {
            EditErrorKind::BadInput | EditErrorKind::Motion => ErrorKind::BadInput,
            EditErrorKind::Instruction if ambiguity.is_some() => ErrorKind::Ambiguous,
            EditErrorKind::Instruction | EditErrorKind::NotUnderstood | EditErrorKind::Unread => {
                ErrorKind::NotUnderstood
            }
            EditErrorKind::Model => ErrorKind::Model,
            EditErrorKind::Placement => ErrorKind::NoFreePlace,
            EditErrorKind::Held => ErrorKind::HeldWouldMove,
        };
        Self {
            kind,
            unread: error.kind == EditErrorKind::Unread,
            message: error.message,
            ambiguity,
            refused: None,
        }
    }
}

/// The most choices a refusal lists (a page shows them as buttons); `total` says how many
/// there are.
pub const MAX_CHOICES: usize = 24;

/// A refusal's choice between objects.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Choices {
    /// The phrase as written.
    pub phrase: String,
    /// Its bytes in the trimmed instruction.
    pub span: [usize; 2],
    /// The objects it could mean (the first [`MAX_CHOICES`]).
    pub objects: Vec<String>,
    /// How many objects it could mean.
    pub total: usize,
    /// For each object listed, the instruction that names it.
    pub choices: Vec<Choice>,
}

/// One object a phrase could mean, and how to say it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Choice {
    /// The object's name.
    pub object: String,
    /// The instruction with the phrase replaced by the quoted name; `None` when the name
    /// cannot be quoted or the instruction would be too long.
    pub instruction: Option<String>,
}

impl Choices {
    /// The choices `ambiguity` leaves in `instruction`.
    #[must_use]
    pub fn new(instruction: &str, ambiguity: &Ambiguity) -> Self {
        let text = instruction.trim();
        let shown = &ambiguity.objects[..ambiguity.objects.len().min(MAX_CHOICES)];
        Self {
            phrase: ambiguity.phrase.clone(),
            span: ambiguity.span,
            objects: shown.to_vec(),
            total: ambiguity.objects.len(),
            choices: shown
                .iter()
                .map(|name| Choice {
                    object: name.clone(),
                    instruction: naming(text, ambiguity.span, name),
                })
                .collect(),
        }
    }
}

/// `text` with the bytes `span` replaced by `name` in quotes the grounder reads as one
/// name: the first pair whose closing quote is not in the name (`'…'`, `"…"`, `‘…’`,
/// `“…”`, `` `…` ``; an apostrophe right after a letter would not open a quote).
fn naming(text: &str, span: [usize; 2], name: &str) -> Option<String> {
    let [start, end] = span;
    if start > end || name.is_empty() {
        return None;
    }
    let (before, after) = (text.get(..start)?, text.get(end..)?);
    let after_word = before
        .chars()
        .next_back()
        .is_some_and(char::is_alphanumeric);
    let (open, close) = [('\'', '\''), ('"', '"'), ('‘', '’'), ('“', '”'), ('`', '`')]
        .into_iter()
        .find(|&(open, close)| !(name.contains(close) || (after_word && open == '\'')))?;
    let named = format!("{before}{open}{name}{close}{after}");
    (named.chars().count() <= crate::ground::MAX_INSTRUCTION_CHARS).then_some(named)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_candidate_is_named_in_the_first_quotes_that_hold_it() {
        let text = "move the chair 20 cm to the left";
        assert_eq!(
            naming(text, [5, 14], "chair 3").as_deref(),
            Some("move 'chair 3' 20 cm to the left")
        );
        assert_eq!(
            naming(text, [5, 14], "Bob's chair").as_deref(),
            Some("move \"Bob's chair\" 20 cm to the left")
        );
        assert_eq!(
            naming(text, [5, 14], "Bob's \"big\" chair").as_deref(),
            Some("move ‘Bob's \"big\" chair’ 20 cm to the left")
        );
        // Right after a letter an apostrophe is part of the word, not a quote.
        assert_eq!(naming("ab", [1, 2], "n").as_deref(), Some("a\"n\""));
        // A name that every closing quote is in cannot be named.
        assert_eq!(naming(text, [5, 14], "a'b\"c’d”e`"), None);
    }

    #[test]
    fn a_span_that_is_not_the_instructions_own_names_nothing() {
        let text = "move the café chair left";
        // Inside the two bytes of 'é', backwards, past the end.
        assert_eq!(naming(text, [9, 13], "x"), None);
        assert_eq!(naming(text, [14, 9], "x"), None);
        assert_eq!(naming(text, [9, 99], "x"), None);
        assert_eq!(naming(text, [9, 20], "").as_deref(), None);
        assert_eq!(
            naming(text, [5, 20], "chair 2").as_deref(),
            Some("move 'chair 2' left")
        );
        // An instruction the name would make too long is not offered.
        let long = "n".repeat(crate::ground::MAX_INSTRUCTION_CHARS);
        assert_eq!(naming(text, [5, 20], &long), None);
    }

    #[test]
    fn kinds_are_written_as_their_names() {
        for kind in [
            ErrorKind::BadInput,
            ErrorKind::NotUnderstood,
            ErrorKind::Ambiguous,
            ErrorKind::NoFreePlace,
            ErrorKind::HeldWouldMove,
            ErrorKind::Model,
            ErrorKind::NothingToUndo,
            ErrorKind::NothingToRedo,
            ErrorKind::Export,
            ErrorKind::Internal,
        ] {
            assert_eq!(
                serde_json::to_value(kind).unwrap(),
                serde_json::Value::from(kind.name())
            );
        }
    }
}

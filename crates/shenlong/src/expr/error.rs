//! Errors of the expression language, with where they happened.

use std::fmt;
use std::ops::Range;

/// A byte range in the expression text.
pub type Span = Range<usize>;

/// Which kind of problem an expression has: a caller (a retry loop, a benchmark's
/// tally) can tell a typo from a wrong answer without reading the message.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum ExprErrorKind {
    /// Not written in the expression language (a stray character, an unclosed bracket).
    Syntax,
    /// Written well but meaningless: an unknown name, the wrong kind of value, a
    /// division by zero.
    Meaning,
    /// Past a limit that keeps evaluation bounded (length, size, steps).
    Limit,
    /// Evaluates, but not to a transformation of the form T·R·D.
    NotATransformation,
    /// A model's reply not in the shape asked for (no JSON object, unknown or repeated
    /// variables, no change).
    Reply,
}

/// What is wrong with an expression, and where.
///
/// The message is written for whoever wrote the expression to act on — a person, or a
/// language model that receives it in a retry — so it names the problem and, where there
/// is one, the fix.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExprError {
    /// Which kind of problem.
    pub kind: ExprErrorKind,
    /// What is wrong.
    pub message: String,
    /// 1-based character column where the problem starts, when it has a place.
    pub column: Option<usize>,
}

impl ExprError {
    /// An error of `kind` at `span` of `source`.
    #[must_use]
    pub fn at(kind: ExprErrorKind, message: impl Into<String>, span: &Span, source: &str) -> Self {
        let start = span.start.min(source.len());
        let column = source.get(..start).map_or(start, |s| s.chars().count()) + 1;
        Self {
            kind,
            message: message.into(),
            column: Some(column),
        }
    }

    /// An error of `kind` with no particular place (the whole expression).
    #[must_use]
    pub fn whole(kind: ExprErrorKind, message: impl Into<String>) -> Self {
        Self {
            kind,
            message: message.into(),
            column: None,
        }
    }

    /// The same error, its message after `context` (`X1 item 2`), kind and column kept.
    #[must_use]
    pub fn within(self, context: &str) -> Self {
        Self {
            message: format!("{context}: {}", self.message),
            ..self
        }
    }
}

impl fmt::Display for ExprError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.column {
            Some(column) => write!(f, "{} at column {column}", self.message),
            None => f.write_str(&self.message),
        }
    }
}

impl std::error::Error for ExprError {}

//! Errors of the expression language, with where they happened.

use std::fmt;
use std::ops::Range;

/// A byte range in the expression text.
pub type Span = Range<usize>;

/// What is wrong with an expression, and where.
///
/// The message is written for whoever wrote the expression to act on — a person, or a
/// language model that receives it in a retry — so it names the problem and, where there
/// is one, the fix.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExprError {
    /// What is wrong.
    pub message: String,
    /// 1-based character column where the problem starts, when it has a place.
    pub column: Option<usize>,
}

impl ExprError {
    /// An error at `span` of `source`.
    pub fn at(message: impl Into<String>, span: &Span, source: &str) -> Self {
        let start = span.start.min(source.len());
        let column = source.get(..start).map_or(start, |s| s.chars().count()) + 1;
        Self {
            message: message.into(),
            column: Some(column),
        }
    }

    /// An error with no particular place (the whole expression).
    pub fn whole(message: impl Into<String>) -> Self {
        Self {
            message: message.into(),
            column: None,
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

//! The CGA expression language: what a language model writes, and what Shenlong evaluates.
//!
//! `T(((X2.max | e2) - (X1.min | e2)) * e2)` is parsed ([`parse`]) into a syntax tree,
//! evaluated against the bound objects' bounding boxes ([`evaluate`]) and checked to be a
//! transformation `T·R·D` ([`evaluate_transformation`]). Nothing is ever executed: names
//! resolve to a fixed table, and input length, nesting depth, tree size and evaluation
//! steps are all limited ([`Limits`]). Errors say what is wrong and at which column, in
//! words a model can act on in a retry. `docs/expressions.md` is the user's reference.

mod ast;
mod error;
mod eval;
mod lexer;
mod parser;
pub mod reply;

pub use ast::{BinaryOp, Expr, ExprKind, UnaryOp};
pub use error::{ExprError, ExprErrorKind, Span};
pub use eval::Dialect;

use cga::{Multivector, Similarity};
use glam::DVec3;

/// Limits that keep hostile or runaway input cheap to reject.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Longest expression text, in bytes.
    pub max_length: usize,
    /// Deepest nesting of parentheses, calls and operators.
    pub max_depth: usize,
    /// Most nodes in the syntax tree.
    pub max_nodes: usize,
    /// Most evaluation steps (one per node visited).
    pub max_steps: usize,
    /// Largest whole-number power of a multivector.
    pub max_exponent: u32,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            max_length: 4096,
            max_depth: 64,
            max_nodes: 1024,
            max_steps: 4096,
            max_exponent: 64,
        }
    }
}

/// An object's world axis-aligned bounding box, as the language sees it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ObjectBox {
    /// The corner with the smallest coordinates (`X1.min`).
    pub min: DVec3,
    /// The corner with the largest coordinates (`X1.max`).
    pub max: DVec3,
    /// The world direction the object faces (`X1.front`), a unit vector.
    pub front: DVec3,
}

/// The variables `X1 … Xn` and the boxes of the objects they stand for.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Bindings {
    entries: Vec<(String, ObjectBox)>,
}

impl Bindings {
    /// No variables.
    pub fn new() -> Self {
        Self::default()
    }

    /// Binds `variable` (such as `"X1"`) to a box, replacing an earlier binding.
    pub fn bind(&mut self, variable: impl Into<String>, object: ObjectBox) {
        let variable = variable.into();
        match self.entries.iter_mut().find(|(v, _)| *v == variable) {
            Some(entry) => entry.1 = object,
            None => self.entries.push((variable, object)),
        }
    }

    /// The bound variable names, in binding order.
    pub fn variables(&self) -> impl Iterator<Item = &str> {
        self.entries.iter().map(|(v, _)| v.as_str())
    }

    /// The box bound to `variable`.
    pub fn get(&self, variable: &str) -> Option<&ObjectBox> {
        self.entries
            .iter()
            .find(|(v, _)| v == variable)
            .map(|(_, b)| b)
    }

    fn index_of(&self, variable: &str) -> Option<usize> {
        self.entries.iter().position(|(v, _)| v == variable)
    }

    fn variable(&self, index: usize) -> &str {
        &self.entries[index].0
    }

    fn object(&self, index: usize) -> &ObjectBox {
        &self.entries[index].1
    }
}

/// A checked transformation: its versor and that versor's decomposition.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transformation {
    /// The versor `M`, normalised so that `M M̃ = 1`.
    pub versor: Multivector,
    /// `M = T·R·D` as translation, rotation and scale.
    pub similarity: Similarity,
}

impl Transformation {
    /// The transformation that changes nothing.
    pub const IDENTITY: Self = Self {
        versor: Multivector::ONE,
        similarity: Similarity::IDENTITY,
    };
}

/// Parses an expression with the default limits.
pub fn parse(source: &str) -> Result<Expr, ExprError> {
    parser::parse(source, &Limits::default())
}

/// Parses an expression with the given limits.
pub fn parse_with(source: &str, limits: &Limits) -> Result<Expr, ExprError> {
    parser::parse(source, limits)
}

/// Parses and evaluates an expression to a multivector (of any kind).
pub fn evaluate(source: &str, bindings: &Bindings) -> Result<Multivector, ExprError> {
    evaluate_with(source, bindings, &Limits::default())
}

/// [`evaluate`] with the given limits.
pub fn evaluate_with(
    source: &str,
    bindings: &Bindings,
    limits: &Limits,
) -> Result<Multivector, ExprError> {
    let expr = parser::parse(source, limits)?;
    eval::Evaluator::new(source, bindings, limits).evaluate(&expr)
}

/// Parses and evaluates an expression of the given dialect.
pub fn evaluate_in(
    source: &str,
    bindings: &Bindings,
    dialect: Dialect,
) -> Result<Multivector, ExprError> {
    let limits = Limits::default();
    let expr = parser::parse(source, &limits)?;
    eval::Evaluator::new(source, bindings, &limits)
        .with_dialect(dialect)
        .evaluate(&expr)
}

/// Evaluates a syntax tree built by a program (the offline translator builds its answers
/// as trees), in the CGA dialect, within the default limits. Errors point into the tree's
/// printed text.
pub fn evaluate_tree(tree: &Expr, bindings: &Bindings) -> Result<Multivector, ExprError> {
    let limits = Limits::default();
    let source = tree.to_string();
    eval::Evaluator::new(&source, bindings, &limits).evaluate(tree)
}

/// Parses and evaluates an expression that must be a transformation `T·R·D`.
pub fn evaluate_transformation(
    source: &str,
    bindings: &Bindings,
) -> Result<Transformation, ExprError> {
    let m = evaluate(source, bindings)?;
    to_transformation(&m)
}

/// Evaluates a list of expressions applied in order, `M = Mₙ ··· M₁`, each of which must be
/// a transformation. Errors name the failing item (`item 2: …`) when there are several.
pub fn compose<S: AsRef<str>>(
    sources: &[S],
    bindings: &Bindings,
) -> Result<Transformation, ExprError> {
    if sources.is_empty() {
        return Err(ExprError::whole(
            ExprErrorKind::Reply,
            "the list of expressions is empty: give at least one transformation",
        ));
    }
    let mut m = Multivector::ONE;
    for (i, source) in sources.iter().enumerate() {
        let item = evaluate_transformation(source.as_ref(), bindings).map_err(|e| {
            if sources.len() > 1 {
                e.within(&format!("item {} of the list", i + 1))
            } else {
                e
            }
        })?;
        m = item.versor * m;
    }
    to_transformation(&m)
}

/// Checks that a multivector is a transformation `T·R·D` and decomposes it.
pub fn to_transformation(m: &Multivector) -> Result<Transformation, ExprError> {
    let tolerance = 1e-9 * m.max_abs().max(1.0);
    let grades = m.grades_present(tolerance);
    if grades == 0b10 {
        return Err(ExprError::whole(
            ExprErrorKind::NotATransformation,
            "result is a vector, not a transformation: wrap a translation vector in T(...)",
        ));
    }
    if grades == 0 {
        return Err(ExprError::whole(
            ExprErrorKind::NotATransformation,
            "result is zero, not a transformation: a transformation such as T(1 * e1) is never zero",
        ));
    }
    let similarity = Similarity::from_versor(m).map_err(|e| {
        ExprError::whole(ExprErrorKind::NotATransformation, match e {
            cga::CgaError::NotSimilarity(why) => format!(
                "result is not a transformation of the form T·R·D (translation, rotation, uniform scale): {why}"
            ),
            other => format!("result is not a transformation: {other}"),
        })
    })?;
    let versor = similarity
        .to_versor()
        .map_err(|e| ExprError::whole(ExprErrorKind::NotATransformation, e.to_string()))?;
    Ok(Transformation { versor, similarity })
}

#[cfg(test)]
mod tests;

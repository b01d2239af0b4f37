//! Errors of the algebra.

use thiserror::Error;

/// What went wrong in an operation of the algebra. Messages are written to be read by the
/// person (or language model) who wrote the expression.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CgaError {
    /// The multivector has no inverse.
    #[error("the multivector {0} is not invertible")]
    NotInvertible(String),
    /// A conformal point at infinity (zero weight) has no Euclidean position.
    #[error("the point is at infinity: it has no Euclidean position")]
    PointAtInfinity,
    /// `R(θ, u, v)` was given two vectors whose outer product vanishes or is not a
    /// Euclidean plane.
    #[error("u and v span no plane: {0}")]
    NoPlane(String),
    /// A dilation factor that is not a finite number greater than zero.
    #[error("D({0}): scale must be > 0")]
    BadScale(f64),
    /// The multivector is not a product of a translation, a rotation and a uniform scaling.
    #[error("not a transformation of the form T·R·D: {0}")]
    NotSimilarity(String),
    /// A value that is not a finite number.
    #[error("not a finite number: {0}")]
    NotFinite(String),
}

//! Conformal geometric algebra for 3D: the algebra G(4,1).
//!
//! Basis vectors `e1, e2, e3` span Euclidean space (x right, y up, z forward), `e4² = +1`
//! and `e5² = −1` add the conformal dimensions, with the null vectors
//! `eo = ½(e5 − e4)` (the origin) and `einf = e4 + e5` (infinity). Conventions match the
//! Python `clifford` library's `g3c` layout, so its expressions and results carry over:
//! the same blade order, the same `|` (Hestenes inner product) and the same versors
//! `T(t) = 1 − ½ t einf`, `R(θ, u, v) = cos(θ/2) − sin(θ/2) (u∧v)/|u∧v|`,
//! `D(s) = cosh(ln s / 2) − sinh(ln s / 2) e45`.
//!
//! ```
//! use cga::{Multivector, Similarity};
//! use glam::DVec3;
//!
//! let t = Multivector::translator(DVec3::new(1.0, 0.0, 0.0));
//! let r = Multivector::rotor(std::f64::consts::FRAC_PI_2, &Multivector::e3(), &Multivector::e1())?;
//! let m = t * r; // rotate a quarter turn about +Y, then move 1 along +X
//! let p = m.transform_point(DVec3::new(0.0, 0.0, 1.0))?;
//! assert!((p - DVec3::new(2.0, 0.0, 0.0)).length() < 1e-12);
//! let s = Similarity::from_versor(&m)?;
//! assert!((s.translation - DVec3::X).length() < 1e-12);
//! # Ok::<(), cga::CgaError>(())
//! ```

#![warn(missing_docs)]

pub mod blade;
mod conformal;
mod dispatch;
mod error;
mod even;
#[allow(clippy::all)]
#[rustfmt::skip]
mod generated;
mod multivector;
mod point_map;
mod similarity;
mod versor;

pub use blade::{BLADE_COUNT, BLADE_NAMES};
pub use error::CgaError;
pub use even::{Motor, Rotor};
pub use multivector::Multivector;
pub use point_map::PointMap;
pub use similarity::Similarity;

/// Relative tolerance used when checking that a multivector has a required form
/// (a versor, a rotor, a point).
pub const TOLERANCE: f64 = 1e-6;

//! Shenlong: instruction-based repositioning of separate 3D objects with conformal
//! geometric algebra.
//!
//! One module per stage of the data flow (see ARCHITECTURE.md):
//! - [`expr`]: the CGA expression language a model answers in — parse, check, evaluate.

#![warn(missing_docs)]

pub mod expr;

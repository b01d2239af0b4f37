//! Shenlong: instruction-based repositioning of separate 3D objects with conformal
//! geometric algebra.
//!
//! One module per stage of the data flow (see ARCHITECTURE.md):
//! - [`geometry`]: bounding volumes.
//! - [`scene`]: the scene model — objects, poses as versors, pivots, supports, undo.
//! - [`format`]: scene files — scene JSON — read and written back in their own shape.
//! - [`expr`]: the CGA expression language a model answers in — parse, check, evaluate.
//! - [`io`]: atomic file writes.
//! - [`session`]: one scene edited over time, with undo, redo and a history.

#![warn(missing_docs)]

pub mod bench;
pub mod collide;
pub mod discourse;
pub mod examples;
pub mod expr;
pub mod format;
pub mod geometry;
pub mod ground;
pub mod io;
pub(crate) mod lex;
pub mod llm;
pub mod number;
pub mod offline;
pub mod pipeline;
pub mod render;
pub mod scene;
pub mod session;
pub mod translate;

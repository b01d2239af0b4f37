//! Collisions: finding the overlaps an edit created, and moving the edited objects to the
//! nearest placement free of them.
//!
//! A language model reasons locally about the objects an instruction names, so an edit can
//! push an object into another. Shenlong then searches, like the paper's depth-first grid
//! search (and Holodeck's solver), for the nearest collision-free placement — but in exact
//! order of increasing displacement, so the first valid placement is the nearest one, and
//! with a broad phase so large scenes stay cheap.
//!
//! - An object and everything resting on it move as one **group**; everything else, the
//!   floor, and the room's walls and ceiling (when the scene has bounds) are fixed.
//! - **Touching is not colliding**: boxes must overlap by more than [`EPSILON`] on all three
//!   axes. Overlaps that existed before the edit are not collisions unless the edit made
//!   them larger (real scenes have small objects inside a sofa's box).

mod detect;
mod resolve;

pub use detect::{find_collisions, find_collisions_in, Obstacle, Overlap};
pub use resolve::{
    resolve, resolve_with, Adjustment, Boxes, FloorBound, Kinds, Resolution, ResolveError,
    ResolveOptions, SearchEnd,
};

/// How far two boxes must overlap on every axis to collide, in metres.
pub const EPSILON: f64 = 1e-4;

/// The largest horizontal gap, in metres, between an object put "next to" (beside, left
/// of, in front of, …) another and that other, once collisions are resolved: farther than
/// this, the nearest free place is no longer next to it and the edit is refused.
pub const NEXT_TO_MAX_GAP: f64 = 0.5;

//! What an operation on a session did, as data every front end writes the same way: the
//! CLI's `--json`, the HTTP API, MCP and Python.

use crate::pipeline::{Binding, CollisionReport, EditReport};
use crate::scene::Object;
use serde::Serialize;

/// The operations a session offers that change the scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Operation {
    /// An instruction in words.
    Edit,
    /// A CGA expression applied to one object.
    Apply,
    /// The last change taken back.
    Undo,
    /// The last undone change made again.
    Redo,
}

/// Why an object moved.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum How {
    /// The operation moved it: the instruction or expression named it, or an undo or redo
    /// put it back.
    Moved,
    /// It rests on a moved object and went with it.
    Carried,
    /// Collision resolution moved it out of the way.
    Pushed,
}

/// An object's pose as the scene file writes it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Pose {
    /// Translation, metres.
    pub position: [f64; 3],
    /// Rotation, unit quaternion `[x, y, z, w]`.
    pub rotation: [f64; 4],
    /// Uniform scale.
    pub scale: f64,
}

impl Pose {
    /// `object`'s pose, its numbers tidied as the scene JSON writes them.
    #[must_use]
    pub fn of(object: &Object) -> Self {
        let s = object.similarity();
        let tidy = crate::number::tidy;
        Self {
            position: s.translation.to_array().map(tidy),
            rotation: s.rotation.to_array().map(tidy),
            scale: tidy(s.scale),
        }
    }
}

/// One object an operation moved.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Moved {
    /// Its name.
    pub object: String,
    /// Why it moved.
    pub how: How,
    /// Where it was.
    pub before: Pose,
    /// Where it is.
    pub after: Pose,
}

/// How an edit's instruction or an expression was read.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Understood {
    /// The instruction with its objects as variables (`put X1 on X2`), or the expression.
    pub query: String,
    /// Which object each variable stands for.
    pub bindings: Vec<Binding>,
}

/// What an operation did.
#[derive(Clone, Debug, Serialize)]
pub struct Outcome {
    /// Which operation.
    pub operation: Operation,
    /// The change's id in the history: the new change for an edit or apply (`None` when
    /// nothing moved and nothing was recorded), the change taken back or made again for an
    /// undo or redo.
    pub history_id: Option<u64>,
    /// Every object whose pose changed, with both poses.
    pub moved: Vec<Moved>,
    /// How the instruction or expression was read (edit and apply).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub understood: Option<Understood>,
    /// What people should know: objects moved to clear a collision, overlaps left, objects
    /// held where they are.
    pub notes: Vec<String>,
    /// The change was made but something around it failed (the scene could not be saved).
    pub warnings: Vec<String>,
    /// The whole edit report — grounding, the translator's exchanges, expressions, versors,
    /// timings — when asked for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub report: Option<Box<EditReport>>,
}

/// The notes about what collision resolution did and what was held.
#[must_use]
pub fn notes(
    collisions_resolved: &[CollisionReport],
    overlaps_remaining: &[String],
    held: &[String],
) -> Vec<String> {
    let mut notes: Vec<String> = collisions_resolved
        .iter()
        .map(|c| {
            let d = c.displacement.map(crate::number::tidy);
            format!(
                "moved '{}' by [{}, {}, {}] m to clear {}{}",
                c.object,
                d[0],
                d[1],
                d[2],
                c.collided_with.join(", "),
                c.lifted_onto
                    .as_ref()
                    .map(|o| format!(", onto '{o}'"))
                    .unwrap_or_default()
            )
        })
        .collect();
    notes.extend(
        overlaps_remaining
            .iter()
            .map(|o| format!("{o} (collisions allowed)")),
    );
    notes.extend(held.iter().map(|h| format!("'{h}' held where it is")));
    notes
}

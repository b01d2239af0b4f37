//! The instruction pipeline, one module per stage of the data flow:
//! [`template`] (names → variables) → [`translate`] (a model or the offline translator,
//! through [`prompts`]) → evaluation (`crate::expr`) → apply with carrying (`crate::scene`)
//! → collisions (`crate::collide`) → [`edit`] (the orchestration and its report).

pub mod backends;
pub mod edit;
pub mod prompts;
pub mod template;
pub mod translate;

pub use edit::{edit, edit_with, Edit, EditError, EditErrorKind, EditOptions, EditReport};

use crate::expr::{Bindings, ObjectBox};
use crate::scene::Scene;

/// The variables of an expression about `objects` of `scene`: `X1`, `X2`, … bound to their
/// world boxes in order, and (an extension) `room` when the scene has bounds.
pub fn bindings(scene: &Scene, objects: &[usize]) -> Bindings {
    let mut bindings = Bindings::new();
    for (k, &i) in objects.iter().enumerate() {
        let b = scene.objects[i].world_aabb();
        bindings.bind(
            Templated::variable(k),
            ObjectBox {
                min: b.min,
                max: b.max,
            },
        );
    }
    if let Some(room) = scene.bounds {
        bindings.bind(
            "room",
            ObjectBox {
                min: room.min,
                max: room.max,
            },
        );
    }
    bindings
}
pub use prompts::System;
pub use template::{template, template_with, Templated};
pub use translate::{LlmTranslator, TranslateError, Translation, Translator};

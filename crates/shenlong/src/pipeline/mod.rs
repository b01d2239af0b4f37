//! The instruction pipeline, one module per stage of the data flow:
//! [`template`] (names → variables) → [`translate`] (a model or the offline translator,
//! through [`prompts`]) → evaluation (`crate::expr`) → apply with carrying (`crate::scene`)
//! → collisions (`crate::collide`) → [`edit`] (the orchestration and its report).

pub mod backends;
pub mod cascade;
pub mod edit;
pub mod prompts;
pub mod template;
pub mod translate;

pub use edit::{
    apply_expression, apply_expression_bound, edit, edit_with, place, Binding, CollisionReport,
    Edit, EditError, EditErrorKind, EditOptions, EditReport, Lexical, Placed,
};

pub use crate::translate::bindings;

pub use prompts::System;
pub use template::{template, template_selected, template_with, Templated};
pub use translate::{LlmTranslator, TranslateError, Translation, Translator};

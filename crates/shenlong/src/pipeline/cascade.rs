//! Offline first, a model for the rest: the cascade translator (`--llm offline+openai:MODEL`).
//!
//! The offline translator answers when it reads the whole instruction (microseconds, free,
//! exact); only an instruction it refuses as not understood goes to the model, with the
//! offline refusal kept in the translation. Grounding happens before any translator, so an
//! ambiguous or unknown object is refused before either is asked: that refusal is final.

use super::prompts::System;
use crate::offline::OfflineTranslator;
use crate::scene::Scene;
use crate::translate::{Templated, TranslateError, TranslateErrorKind, Translation, Translator};

/// The offline translator, then a model for what it does not read.
pub struct Cascade {
    offline: OfflineTranslator,
    model: Box<dyn Translator>,
}

/// A cascade over a model that does not answer in CGA.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error("a cascade answers in CGA (its offline part cannot answer in '{}'): choose the cga prompt system", .0.name())]
pub struct NotCga(pub System);

impl Cascade {
    /// A cascade over `model` (which must answer in CGA, as the offline translator does).
    ///
    /// # Errors
    /// If the model's prompt system is not CGA.
    pub fn new(model: Box<dyn Translator>) -> Result<Self, NotCga> {
        if model.system() != System::Cga {
            return Err(NotCga(model.system()));
        }
        Ok(Self {
            offline: OfflineTranslator::new(),
            model,
        })
    }
}

impl Translator for Cascade {
    fn name(&self) -> String {
        format!("offline+{}", self.model.name())
    }

    fn system(&self) -> System {
        System::Cga
    }

    fn translate(
        &self,
        templated: &Templated,
        scene: &Scene,
    ) -> Result<Translation, TranslateError> {
        let refusal = match self.offline.translate(templated, scene) {
            Ok(translation) => return Ok(translation),
            // (Refused on its meaning, "put the chair back": no model is asked.)
            Err(e) if e.kind == TranslateErrorKind::NotUnderstood => e.message,
            Err(e) => return Err(e),
        };
        match self.model.translate(templated, scene) {
            Ok(mut translation) => {
                translation.offline_refusal = Some(refusal);
                Ok(translation)
            }
            Err(e) => Err(TranslateError {
                message: format!("{} (the offline translator: {refusal})", e.message),
                ..e
            }),
        }
    }
}

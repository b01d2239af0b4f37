//! Translation: a templated instruction → one transformation per variable, behind one
//! seam ([`Translator`]) for language models and the built-in offline translator.

use super::prompts::{Answer, System};
use super::template::Templated;
use crate::llm::cache::Cache;
use crate::llm::record::{Record, Recorder};
use crate::llm::{Backend, Message, Usage};
use crate::scene::Scene;
use serde::Serialize;
use std::time::{Duration, Instant};

/// One request and reply, as the report shows it.
#[derive(Clone, Debug, Serialize)]
pub struct Exchange {
    /// The messages sent.
    pub messages: Vec<Message>,
    /// The reply, or the empty string when the backend failed.
    pub reply: String,
    /// Time the reply took, in milliseconds (0 for a cache hit).
    pub elapsed_ms: f64,
    /// Token counts.
    pub usage: Usage,
    /// What was wrong with the reply, sent back to the model in the next attempt.
    pub error: Option<String>,
    /// Whether the reply came from the cache.
    pub cached: bool,
}

/// The result of translating one instruction.
#[derive(Clone, Debug)]
pub struct Translation {
    /// One answer per variable the reply changes.
    pub answers: Vec<Answer>,
    /// Every exchange, retries included.
    pub exchanges: Vec<Exchange>,
    /// Attempts after the first.
    pub retries: usize,
    /// Whether the valid reply came from the cache.
    pub cache_hit: bool,
    /// Response time, retries included (the paper's measure).
    pub elapsed: Duration,
}

/// Why an instruction could not be translated.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TranslateError {
    /// One line for the user.
    pub message: String,
    /// Whether the instruction itself was not understood (as opposed to a model or its
    /// server failing).
    pub not_understood: bool,
}

impl TranslateError {
    /// A model or server failure.
    pub fn model(message: impl Into<String>) -> Self {
        Self {
            message: message.into(),
            not_understood: false,
        }
    }

    /// An instruction the translator cannot read.
    pub fn not_understood(message: impl Into<String>) -> Self {
        Self {
            message: message.into(),
            not_understood: true,
        }
    }
}

impl std::fmt::Display for TranslateError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for TranslateError {}

/// Turns templated instructions into transformations.
pub trait Translator: Send + Sync {
    /// The translator's name for reports: `offline`, or the model.
    fn name(&self) -> String;
    /// The prompt system it answers in.
    fn system(&self) -> System;
    /// Translates one instruction.
    fn translate(
        &self,
        templated: &Templated,
        scene: &Scene,
    ) -> Result<Translation, TranslateError>;
}

/// A language model prompted with one of the three systems, retrying with the error when a
/// reply cannot be used.
pub struct LlmTranslator {
    /// The model.
    pub backend: Box<dyn Backend>,
    /// The prompt system.
    pub system: System,
    /// Attempts after the first when a reply is invalid.
    pub retries: usize,
    /// Where valid replies are kept, if anywhere.
    pub cache: Option<Cache>,
    /// Where every exchange is recorded, if anywhere.
    pub recorder: Option<Recorder>,
}

impl Translator for LlmTranslator {
    fn name(&self) -> String {
        self.backend.model().to_string()
    }

    fn system(&self) -> System {
        self.system
    }

    fn translate(
        &self,
        templated: &Templated,
        scene: &Scene,
    ) -> Result<Translation, TranslateError> {
        let started = Instant::now();
        let (name, version, model) = (
            self.system.name(),
            self.system.version(),
            self.backend.model().to_string(),
        );
        let first = self.system.messages(templated, scene);
        let mut exchanges = Vec::new();
        if let Some(cache) = &self.cache {
            if let Some(reply) = cache.get(name, version, &model, &first) {
                if let Ok(answers) = self.system.parse_reply(&reply, templated, scene) {
                    exchanges.push(Exchange {
                        messages: first,
                        reply,
                        elapsed_ms: 0.0,
                        usage: Usage::default(),
                        error: None,
                        cached: true,
                    });
                    return Ok(Translation {
                        answers,
                        exchanges,
                        retries: 0,
                        cache_hit: true,
                        elapsed: started.elapsed(),
                    });
                }
            }
        }
        let mut messages = first.clone();
        for attempt in 0..=self.retries {
            let completion = self
                .backend
                .complete(&messages)
                .map_err(|e| TranslateError::model(format!("{model}: {}", e.message)))?;
            if let Some(recorder) = &self.recorder {
                let record = Record {
                    system: name.into(),
                    prompt_version: version.into(),
                    model: model.clone(),
                    messages: messages.clone(),
                    reply: completion.text.clone(),
                    elapsed_ms: completion.elapsed.as_secs_f64() * 1000.0,
                    usage: completion.usage,
                };
                recorder.append(&record).map_err(|e| {
                    TranslateError::model(format!(
                        "cannot record to {}: {e}",
                        recorder.path().display()
                    ))
                })?;
            }
            let parsed = self.system.parse_reply(&completion.text, templated, scene);
            exchanges.push(Exchange {
                messages: messages.clone(),
                reply: completion.text.clone(),
                elapsed_ms: completion.elapsed.as_secs_f64() * 1000.0,
                usage: completion.usage,
                error: parsed.as_ref().err().map(ToString::to_string),
                cached: false,
            });
            match parsed {
                Ok(answers) => {
                    if let Some(cache) = &self.cache {
                        // A cache that cannot be written only costs a later request.
                        let _ = cache.put(name, version, &model, &first, &completion.text);
                    }
                    return Ok(Translation {
                        answers,
                        exchanges,
                        retries: attempt,
                        cache_hit: false,
                        elapsed: started.elapsed(),
                    });
                }
                Err(error) => {
                    messages.push(Message::new("assistant", completion.text));
                    messages.push(Message::new(
                        "user",
                        format!("Your answer could not be used: {error}. Answer again with one JSON object, following the rules."),
                    ));
                }
            }
        }
        let last = exchanges
            .last()
            .and_then(|e| e.error.clone())
            .unwrap_or_default();
        Err(TranslateError::model(format!(
            "{model} gave no usable answer after {} attempts; the last error: {last}",
            self.retries + 1
        )))
    }
}

//! Translation: a templated instruction → one transformation per variable, behind one
//! seam ([`Translator`]) for language models and the built-in offline translator.

#[cfg(feature = "models")]
use crate::llm::cache::Cache;
use crate::llm::record::{Record, Recorder};
use crate::llm::{Backend, Message};
use crate::scene::Scene;
pub use crate::translate::{Exchange, TranslateError, Translation, Translator};
use crate::translate::{ReplyCounts, System, Templated};
use std::time::{Duration, Instant};

pub use crate::llm::MAX_REPLY_BYTES;

/// A language model prompted with one of the three systems, retrying with the error when a
/// reply cannot be used.
pub struct LlmTranslator {
    /// The model.
    pub backend: Box<dyn Backend>,
    /// The prompt system.
    pub system: System,
    /// Attempts after the first when a reply is invalid.
    pub retries: usize,
    /// Time allowed for the whole translation.
    pub deadline: Duration,
    /// Where valid replies are kept, if anywhere.
    #[cfg(feature = "models")]
    pub cache: Option<Cache>,
    /// Where every exchange is recorded, if anywhere.
    pub recorder: Option<Recorder>,
}

impl LlmTranslator {
    /// The cached answer to these first messages, when there is one that still reads.
    #[cfg(feature = "models")]
    fn cached(
        &self,
        first: &[Message],
        templated: &Templated,
        scene: &Scene,
        started: Instant,
    ) -> Option<Translation> {
        let cache = self.cache.as_ref()?;
        let scope = self.backend.cache_scope();
        let reply = cache.get(self.system.name(), self.system.version(), &scope, first)?;
        let answers = self.system.parse_reply(&reply, templated, scene).ok()?;
        Some(Translation {
            answers,
            exchanges: vec![Exchange {
                messages: first.to_vec(),
                reply,
                elapsed_ms: 0.0,
                usage: crate::llm::Usage::default(),
                error: None,
                cached: true,
            }],
            retries: 0,
            cache_hit: true,
            elapsed: started.elapsed(),
            answered_by: self.name(),
            offline_refusal: None,
            replies: ReplyCounts {
                received: 1,
                parsed: 1,
                valid: 1,
            },
        })
    }

    /// Without the `models` feature there is no reply cache.
    #[cfg(not(feature = "models"))]
    fn cached(&self, _: &[Message], _: &Templated, _: &Scene, _: Instant) -> Option<Translation> {
        None
    }

    /// Keeps a valid reply to these first messages in the cache, if there is one (a
    /// cache that cannot be written only costs a later request).
    fn keep(&self, first: &[Message], reply: &str) {
        #[cfg(feature = "models")]
        if let Some(cache) = &self.cache {
            let scope = self.backend.cache_scope();
            let _ = cache.put(
                self.system.name(),
                self.system.version(),
                &scope,
                first,
                reply,
            );
        }
        #[cfg(not(feature = "models"))]
        let _ = (first, reply);
    }

    /// Appends the exchange to the record file, when recording.
    fn record(
        &self,
        messages: &[Message],
        completion: &crate::llm::Completion,
    ) -> Result<(), TranslateError> {
        let Some(recorder) = &self.recorder else {
            return Ok(());
        };
        let record = Record {
            system: self.system.name().into(),
            prompt_version: self.system.version().into(),
            model: self.backend.model().to_string(),
            messages: messages.to_vec(),
            reply: cap(&completion.text),
            elapsed_ms: completion.elapsed.as_secs_f64() * 1000.0,
            usage: completion.usage,
        };
        recorder.append(&record).map_err(|e| {
            TranslateError::model(format!(
                "cannot record to {}: {e}",
                recorder.path().display()
            ))
        })
    }

    /// The answers a reply gives, or why it cannot be used (too large to read).
    fn read_reply(
        &self,
        text: &str,
        templated: &Templated,
        scene: &Scene,
    ) -> Result<Vec<crate::translate::Answer>, crate::expr::ExprError> {
        if text.len() > MAX_REPLY_BYTES {
            return Err(crate::expr::ExprError::whole(crate::expr::ExprErrorKind::Limit, format!(
                "the reply is too large ({} KiB; at most {} KiB): answer with one short JSON object",
                text.len() / 1024,
                MAX_REPLY_BYTES / 1024
            )));
        }
        self.system.parse_reply(text, templated, scene)
    }
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
        let model = self.backend.model().to_string();
        if let Some(name) = leaked_name(&templated.query, scene) {
            return Err(TranslateError::not_understood(format!(
                "'{name}' is still written in the instruction after grounding, so it is not sent to the model; name the object so grounding reads it (quote it: '{name}')"
            )));
        }
        let first = self.system.messages(templated, scene);
        if let Some(hit) = self.cached(&first, templated, scene, started) {
            return Ok(hit);
        }
        let mut exchanges = Vec::new();
        let mut replies = ReplyCounts::default();
        let mut messages = first.clone();
        for attempt in 0..=self.retries {
            if attempt > 0 && started.elapsed() > self.deadline {
                return Err(TranslateError::model(format!(
                    "{model} gave no usable answer within the deadline of {:.0} s ({attempt} attempts)",
                    self.deadline.as_secs_f64()
                ))
                .with_replies(replies));
            }
            let completion = self.backend.complete(&messages).map_err(|e| {
                TranslateError::model(format!("{model}: {e}")).with_replies(replies)
            })?;
            self.record(&messages, &completion)?;
            let too_large = completion.text.len() > MAX_REPLY_BYTES;
            let parsed = self.read_reply(&completion.text, templated, scene);
            replies.received += 1;
            if !too_large && self.system.reply_parses(&completion.text) {
                replies.parsed += 1;
            }
            if parsed.is_ok() {
                replies.valid += 1;
            }
            exchanges.push(Exchange {
                messages: messages.clone(),
                reply: cap(&completion.text),
                elapsed_ms: completion.elapsed.as_secs_f64() * 1000.0,
                usage: completion.usage,
                error: parsed.as_ref().err().map(ToString::to_string),
                cached: false,
            });
            match parsed {
                Ok(answers) => {
                    self.keep(&first, &completion.text);
                    return Ok(Translation {
                        answers,
                        exchanges,
                        retries: attempt,
                        cache_hit: false,
                        elapsed: started.elapsed(),
                        answered_by: self.name(),
                        offline_refusal: None,
                        replies,
                    });
                }
                Err(error) => {
                    // A reply too large is not sent back: the retry says so instead.
                    let said = if too_large {
                        format!("[a reply of {} KiB]", completion.text.len() / 1024)
                    } else {
                        completion.text
                    };
                    messages.push(Message::new("assistant", said));
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
        ))
        .with_replies(replies))
    }
}

/// The first object name still written in a templated query, word for word (case, spaces
/// and hyphens aside): object names never reach a model, so such a query is not sent.
pub fn leaked_name(query: &str, scene: &Scene) -> Option<String> {
    // Compounds that contain a name's word without naming it.
    let query = query
        .to_lowercase()
        .replace("counter-clockwise", "counterclockwise")
        .replace("counter clockwise", "counterclockwise");
    let words: Vec<String> = crate::ground::words::normalize(&query)
        .split(' ')
        .filter(|w| !w.is_empty())
        .map(str::to_string)
        .collect();
    let compact: Vec<String> = words.clone();
    for object in &scene.objects {
        let name = crate::ground::words::normalize(&object.name);
        let parts: Vec<&str> = name.split(' ').filter(|w| !w.is_empty()).collect();
        if parts.is_empty() || (parts.len() == 1 && parts[0].chars().count() < 4) {
            continue;
        }
        let joined = crate::ground::words::compact(&name);
        let found = words
            .windows(parts.len())
            .any(|w| w.iter().map(String::as_str).eq(parts.iter().copied()))
            || compact.contains(&joined);
        if found {
            return Some(object.name.clone());
        }
    }
    None
}

/// A reply as reports and records keep it: whole up to [`MAX_REPLY_BYTES`], else its
/// start and how long it was.
fn cap(text: &str) -> String {
    if text.len() <= MAX_REPLY_BYTES {
        return text.to_string();
    }
    let mut end = MAX_REPLY_BYTES;
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    format!("{}… [{} bytes in all]", &text[..end], text.len())
}

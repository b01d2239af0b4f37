//! Choosing a translator from a `--llm` spec: `offline`, `openai:MODEL`, `ollama:MODEL`,
//! `replay:FILE`, or a cascade `offline+SPEC` (the offline translator first, the model for
//! what it does not read).

use super::prompts::System;
use super::translate::{LlmTranslator, Translator};
use crate::llm::cache::Cache;
use crate::llm::openai::{ClientOptions, OpenAiClient, OLLAMA_BASE_URL, OPENAI_BASE_URL};
use crate::llm::record::Recorder;
use crate::llm::replay::Replay;
use crate::llm::Backend;
use std::path::PathBuf;
use std::time::Duration;

/// Everything besides the spec that configures a translator.
#[derive(Clone, Debug)]
pub struct TranslatorSettings {
    /// The prompt system.
    pub system: System,
    /// Attempts after the first when a reply is invalid.
    pub retries: usize,
    /// Overrides the server's base URL.
    pub base_url: Option<String>,
    /// The API key (default: OPENAI_API_KEY for `openai:`).
    pub api_key: Option<String>,
    /// Time allowed for one request.
    pub timeout: Duration,
    /// Time allowed to connect to the model server.
    pub connect_timeout: Duration,
    /// Time allowed for a whole translation: every attempt, retry and wait.
    pub deadline: Duration,
    /// Where replies are cached; `None` disables the cache.
    pub cache_dir: Option<PathBuf>,
    /// Where exchanges are recorded.
    pub record: Option<PathBuf>,
}

impl Default for TranslatorSettings {
    fn default() -> Self {
        Self {
            system: System::Cga,
            retries: 5,
            base_url: None,
            api_key: None,
            timeout: Duration::from_secs(120),
            connect_timeout: Duration::from_secs(10),
            deadline: Duration::from_secs(300),
            cache_dir: Cache::default_dir(),
            record: None,
        }
    }
}

/// The translator a spec names.
pub fn translator(
    spec: &str,
    settings: &TranslatorSettings,
) -> Result<Box<dyn Translator>, String> {
    let spec = spec.trim();
    if let Some(model) = spec.strip_prefix("offline+") {
        if model.trim().is_empty() || model.trim().starts_with("offline") {
            return Err(format!(
                "translator '{spec}': a cascade is offline+MODEL, e.g. offline+openai:gpt-4o"
            ));
        }
        let model = translator(model, settings)?;
        return Ok(Box::new(super::cascade::Cascade::new(model)?));
    }
    let (kind, rest) = spec.split_once(':').unwrap_or((spec, ""));
    let backend: Box<dyn Backend> = match kind {
        "offline" => {
            if settings.system != System::Cga {
                return Err(format!(
                    "the offline translator answers in CGA only: choose the cga prompt system, or a model (openai:MODEL) for '{}'",
                    settings.system.name()
                ));
            }
            return Ok(Box::new(crate::offline::OfflineTranslator::new()));
        }
        "openai" | "ollama" => {
            if rest.is_empty() {
                return Err(format!(
                    "the translator {kind}:MODEL needs a model name, e.g. {kind}:{}",
                    if kind == "openai" {
                        "gpt-4o"
                    } else {
                        "llama3.1"
                    }
                ));
            }
            let env_base = if kind == "openai" {
                std::env::var("OPENAI_BASE_URL")
                    .ok()
                    .filter(|s| !s.is_empty())
            } else {
                None
            };
            let default_base = if kind == "openai" {
                OPENAI_BASE_URL
            } else {
                OLLAMA_BASE_URL
            };
            let base_url = settings
                .base_url
                .clone()
                .or(env_base)
                .unwrap_or_else(|| default_base.to_string());
            let api_key = settings.api_key.clone().or_else(|| {
                if kind == "openai" {
                    std::env::var("OPENAI_API_KEY")
                        .ok()
                        .filter(|s| !s.is_empty())
                } else {
                    None
                }
            });
            if kind == "openai" && api_key.is_none() && base_url == OPENAI_BASE_URL {
                return Err("the translator openai:MODEL needs OPENAI_API_KEY (or the base URL of a local OpenAI-compatible server)".into());
            }
            let mut options = ClientOptions::new(base_url, rest, api_key);
            options.request_timeout = settings.timeout;
            options.connect_timeout = settings.connect_timeout;
            options.deadline = settings.deadline;
            Box::new(OpenAiClient::new(options))
        }
        "replay" => {
            if rest.is_empty() {
                return Err("the translator replay:FILE needs the file of recorded exchanges".into());
            }
            Box::new(Replay::load(std::path::Path::new(rest)).map_err(|e| e.message)?)
        }
        other => {
            return Err(format!(
                "unknown translator '{other}': use offline, openai:MODEL, ollama:MODEL, replay:FILE, or offline+ one of those"
            ))
        }
    };
    let recorder = match &settings.record {
        Some(path) => Some(
            Recorder::open(path)
                .map_err(|e| format!("cannot open {} to record: {e}", path.display()))?,
        ),
        None => None,
    };
    // Replays are deterministic already; caching them would only hide the file's answers.
    let cache = if kind == "replay" {
        None
    } else {
        settings.cache_dir.clone().map(Cache::new)
    };
    Ok(Box::new(LlmTranslator {
        backend,
        system: settings.system,
        retries: settings.retries,
        deadline: settings.deadline,
        cache,
        recorder,
    }))
}

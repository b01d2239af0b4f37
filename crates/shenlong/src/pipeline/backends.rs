//! Choosing a translator: a [`Spec`] — `offline`, `openai:MODEL`, `ollama:MODEL`,
//! `replay:FILE`, or a cascade `offline+SPEC` (the offline translator first, the model for
//! what it does not read) — parsed once where it is given (a flag, a request), and the
//! [`TranslatorSettings`] around it.

use super::prompts::System;
use super::translate::{LlmTranslator, Translator};
#[cfg(feature = "models")]
use crate::llm::cache::Cache;
#[cfg(feature = "models")]
use crate::llm::openai::{ClientOptions, OpenAiClient, OLLAMA_BASE_URL, OPENAI_BASE_URL};
use crate::llm::record::Recorder;
use crate::llm::replay::Replay;
use crate::llm::Backend;
use std::path::PathBuf;
use std::str::FromStr;
use std::time::Duration;

/// A translator, as `--llm` names it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Spec {
    /// The built-in offline translator.
    Offline,
    /// A model on an OpenAI-compatible server: `openai:MODEL`.
    OpenAi {
        /// The model's name.
        model: String,
    },
    /// A model on an Ollama server: `ollama:MODEL`.
    Ollama {
        /// The model's name.
        model: String,
    },
    /// Answers recorded with `--record`: `replay:FILE`.
    Replay {
        /// The file of recorded exchanges.
        file: PathBuf,
    },
    /// The offline translator first, the model (never another cascade or `offline`) for
    /// what it does not read: `offline+SPEC`.
    Cascade(Box<Spec>),
}

/// A `--llm` value that names no translator.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SpecError {
    /// `offline+` without a model after it, or with `offline` again.
    #[error("translator '{0}': a cascade is offline+MODEL, e.g. offline+openai:gpt-4o")]
    Cascade(String),
    /// `openai:` or `ollama:` without a model.
    #[error("the translator {kind}:MODEL needs a model name, e.g. {kind}:{example}")]
    NoModel {
        /// `openai` or `ollama`.
        kind: &'static str,
        /// A model of that kind.
        example: &'static str,
    },
    /// `replay:` without a file.
    #[error("the translator replay:FILE needs the file of recorded exchanges")]
    NoReplayFile,
    /// Anything else.
    #[error("unknown translator '{0}': use offline, openai:MODEL, ollama:MODEL, replay:FILE, or offline+ one of those")]
    Unknown(String),
}

impl FromStr for Spec {
    type Err = SpecError;

    fn from_str(text: &str) -> Result<Self, SpecError> {
        let text = text.trim();
        if let Some(model) = text.strip_prefix("offline+") {
            let model = model.trim();
            if model.is_empty() || model.starts_with("offline") {
                return Err(SpecError::Cascade(text.chars().take(80).collect()));
            }
            return Ok(Self::Cascade(Box::new(model.parse()?)));
        }
        let (kind, rest) = text.split_once(':').unwrap_or((text, ""));
        match kind {
            "offline" if rest.is_empty() => Ok(Self::Offline),
            "openai" | "ollama" if rest.trim().is_empty() => Err(SpecError::NoModel {
                kind: if kind == "openai" { "openai" } else { "ollama" },
                example: if kind == "openai" {
                    "gpt-4o"
                } else {
                    "llama3.1"
                },
            }),
            "openai" => Ok(Self::OpenAi {
                model: rest.to_string(),
            }),
            "ollama" => Ok(Self::Ollama {
                model: rest.to_string(),
            }),
            "replay" if rest.is_empty() => Err(SpecError::NoReplayFile),
            "replay" => Ok(Self::Replay {
                file: PathBuf::from(rest),
            }),
            _ => Err(SpecError::Unknown(kind.chars().take(80).collect())),
        }
    }
}

impl std::fmt::Display for Spec {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Offline => f.write_str("offline"),
            Self::OpenAi { model } => write!(f, "openai:{model}"),
            Self::Ollama { model } => write!(f, "ollama:{model}"),
            Self::Replay { file } => write!(f, "replay:{}", file.display()),
            Self::Cascade(model) => write!(f, "offline+{model}"),
        }
    }
}

/// A translator that cannot be made from its spec and settings.
#[derive(Debug, thiserror::Error)]
pub enum BackendError {
    /// The offline translator with a prompt system other than CGA.
    #[error("the offline translator answers in CGA only: choose the cga prompt system, or a model (openai:MODEL) for '{}'", .0.name())]
    OfflineNeedsCga(System),
    /// `openai:MODEL` at OpenAI itself without a key.
    #[error("the translator openai:MODEL needs OPENAI_API_KEY (or the base URL of a local OpenAI-compatible server)")]
    NoApiKey,
    /// The replay file cannot be read.
    #[error("{0}")]
    Replay(String),
    /// The file to record exchanges in cannot be opened.
    #[error("cannot open {} to record: {source}", .path.display())]
    Record {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A model server's translator, in a library built without the `models` feature.
    #[error("the translator {0} needs a model server, and this build has no client for one (the `models` feature)")]
    NoModels(String),
    /// A cascade whose model does not answer in CGA.
    #[error(transparent)]
    Cascade(#[from] super::cascade::NotCga),
}

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
            cache_dir: default_cache_dir(),
            record: None,
        }
    }
}

/// The translator `spec` names, with `settings`.
///
/// # Errors
/// The offline translator with another system than CGA, OpenAI without a key, a replay
/// file that cannot be read, a record file that cannot be opened.
pub fn translator(
    spec: &Spec,
    settings: &TranslatorSettings,
) -> Result<Box<dyn Translator>, BackendError> {
    let backend: Box<dyn Backend> = match spec {
        Spec::Cascade(model) => {
            let model = translator(model, settings)?;
            return Ok(Box::new(super::cascade::Cascade::new(model)?));
        }
        Spec::Offline => {
            if settings.system != System::Cga {
                return Err(BackendError::OfflineNeedsCga(settings.system));
            }
            return Ok(Box::new(crate::offline::OfflineTranslator::new()));
        }
        Spec::Replay { file } => {
            Box::new(Replay::load(file).map_err(|e| BackendError::Replay(e.to_string()))?)
        }
        #[cfg(feature = "models")]
        Spec::OpenAi { model } => Box::new(model_client(true, model, settings)?),
        #[cfg(feature = "models")]
        Spec::Ollama { model } => Box::new(model_client(false, model, settings)?),
        #[cfg(not(feature = "models"))]
        Spec::OpenAi { .. } | Spec::Ollama { .. } => {
            return Err(BackendError::NoModels(spec.to_string()))
        }
    };
    let recorder = match &settings.record {
        Some(path) => Some(Recorder::open(path).map_err(|source| BackendError::Record {
            path: path.clone(),
            source,
        })?),
        None => None,
    };
    Ok(Box::new(LlmTranslator {
        backend,
        system: settings.system,
        retries: settings.retries,
        deadline: settings.deadline,
        // Replays are deterministic already; caching them would only hide the file's
        // answers.
        #[cfg(feature = "models")]
        cache: if matches!(spec, Spec::Replay { .. }) {
            None
        } else {
            settings.cache_dir.clone().map(Cache::new)
        },
        recorder,
    }))
}

/// Where replies are cached by default: the user's cache folder (`models` feature).
fn default_cache_dir() -> Option<PathBuf> {
    #[cfg(feature = "models")]
    return Cache::default_dir();
    #[cfg(not(feature = "models"))]
    None
}

/// The client of an OpenAI-compatible (`openai`) or Ollama server for `model`: the base
/// URL from the settings, else `OPENAI_BASE_URL` (for OpenAI), else the default; the key
/// from the settings, else `OPENAI_API_KEY` (for OpenAI).
#[cfg(feature = "models")]
fn model_client(
    openai: bool,
    model: &str,
    settings: &TranslatorSettings,
) -> Result<OpenAiClient, BackendError> {
    let from_env = |name: &str| std::env::var(name).ok().filter(|s| !s.is_empty());
    let base_url = settings
        .base_url
        .clone()
        .or_else(|| openai.then(|| from_env("OPENAI_BASE_URL")).flatten())
        .unwrap_or_else(|| {
            if openai {
                OPENAI_BASE_URL
            } else {
                OLLAMA_BASE_URL
            }
            .to_string()
        });
    let api_key = settings
        .api_key
        .clone()
        .or_else(|| openai.then(|| from_env("OPENAI_API_KEY")).flatten());
    if openai && api_key.is_none() && base_url == OPENAI_BASE_URL {
        return Err(BackendError::NoApiKey);
    }
    let mut options = ClientOptions::new(base_url, model, api_key);
    options.request_timeout = settings.timeout;
    options.connect_timeout = settings.connect_timeout;
    options.deadline = settings.deadline;
    Ok(OpenAiClient::new(options))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn specs_read_and_write_back() {
        for text in [
            "offline",
            "openai:gpt-4o",
            "ollama:llama3.1",
            "replay:answers.jsonl",
            "offline+openai:gpt-4o",
        ] {
            let spec: Spec = text.parse().unwrap();
            assert_eq!(spec.to_string(), text);
        }
        assert_eq!(" offline ".parse::<Spec>(), Ok(Spec::Offline));
    }

    #[test]
    fn bad_specs_say_what_is_missing() {
        for (text, expected) in [
            ("offline+", "a cascade is offline+MODEL"),
            ("offline+offline", "a cascade is offline+MODEL"),
            ("openai:", "needs a model name, e.g. openai:gpt-4o"),
            ("ollama", "needs a model name, e.g. ollama:llama3.1"),
            ("replay:", "needs the file"),
            ("gemini:pro", "unknown translator 'gemini'"),
            ("offline:x", "unknown translator 'offline'"),
        ] {
            let e = text.parse::<Spec>().unwrap_err().to_string();
            assert!(e.contains(expected), "{text}: {e}");
        }
    }
}

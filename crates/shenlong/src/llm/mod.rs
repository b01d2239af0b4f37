//! Language-model backends: one seam ([`Backend`]) with an OpenAI-compatible HTTP client
//! (OpenAI, Ollama, vLLM, llama.cpp, LM Studio), a replay of recorded exchanges, and the
//! cache and recorder around them.

pub mod cache;
pub mod openai;
pub mod record;
pub mod replay;
pub mod tokens;

use serde::{Deserialize, Serialize};
use std::time::Duration;

/// One chat message.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Message {
    /// `system`, `user` or `assistant`.
    pub role: String,
    /// The text.
    pub content: String,
}

impl Message {
    /// A message with this role and text.
    pub fn new(role: &str, content: impl Into<String>) -> Self {
        Self {
            role: role.to_string(),
            content: content.into(),
        }
    }
}

/// Token counts of one exchange.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Usage {
    /// Tokens sent.
    pub prompt_tokens: u64,
    /// Tokens received.
    pub completion_tokens: u64,
    /// Whether the counts were estimated locally (the server gave none).
    #[serde(default)]
    pub estimated: bool,
}

/// A model's reply.
#[derive(Clone, Debug, PartialEq)]
pub struct Completion {
    /// The text of the reply.
    pub text: String,
    /// Token counts.
    pub usage: Usage,
    /// Time from request to reply, including any waits for retries.
    pub elapsed: Duration,
}

/// Why a backend gave no reply.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LlmError {
    /// One line for the user; never contains the API key.
    pub message: String,
}

impl std::fmt::Display for LlmError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for LlmError {}

/// A language model that answers chat messages.
pub trait Backend: Send + Sync {
    /// The model's name, for reports and cache keys.
    fn model(&self) -> &str;
    /// The model's reply to `messages`.
    fn complete(&self, messages: &[Message]) -> Result<Completion, LlmError>;
}

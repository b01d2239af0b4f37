//! Language-model backends: one seam ([`Backend`]) with an OpenAI-compatible HTTP client
//! (OpenAI, Ollama, vLLM, llama.cpp, LM Studio), a replay of recorded exchanges, and the
//! cache and recorder around them. The HTTP client, its token estimates and the reply
//! cache are the `models` feature (on by default): without it, the library still
//! translates offline and replays recorded answers.

#[cfg(feature = "models")]
pub mod cache;
#[cfg(feature = "models")]
pub mod openai;
pub mod record;
pub mod replay;
#[cfg(feature = "models")]
pub mod tokens;

use serde::{Deserialize, Serialize};
use std::time::Duration;

/// The longest reply read from a model, in bytes: a larger one is refused, never echoed
/// back in a retry, and recorded only in part. A model server's HTTP body is read up to
/// `openai::MAX_BODY_BYTES` (this and room for the JSON around it) and no further.
pub const MAX_REPLY_BYTES: usize = 256 * 1024;

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

/// Why a backend gave no reply. Every text in it has had the API key taken out.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum LlmError {
    /// The request failed — the server's status, the transport, the form of its reply —
    /// on the last of `attempts` tries.
    #[error("{reason}{}", tries(*.attempts))]
    Request {
        /// What failed, one line.
        reason: String,
        /// How many tries were made.
        attempts: u32,
    },
    /// Another try would have had to wait past the deadline.
    #[error("{reason} (gave up: waiting {:.0} s more would pass the deadline of {:.0} s)", .wait.as_secs_f64(), .deadline.as_secs_f64())]
    GaveUp {
        /// What failed on the last try.
        reason: String,
        /// The wait another try needed.
        wait: Duration,
        /// The deadline of the whole translation.
        deadline: Duration,
    },
    /// The server asked every request to wait past the deadline.
    #[error("the server asked every request to wait past the deadline of {:.0} s", .0.as_secs_f64())]
    Throttled(Duration),
    /// A recording (`replay:FILE`) cannot be read.
    #[error("cannot read {path}: {reason}")]
    Unreadable {
        /// The file.
        path: String,
        /// Why.
        reason: String,
    },
    /// A line of a recording is not an exchange.
    #[error("{path} line {line}: not a recorded exchange: {reason}")]
    BadRecord {
        /// The file.
        path: String,
        /// The line, from 1.
        line: usize,
        /// Why.
        reason: String,
    },
    /// A recording has no reply to this request.
    #[error("{recording} has no recorded reply for this request (last user message: {user:?})")]
    NotRecorded {
        /// The file.
        recording: String,
        /// The request's last user message, cut to 120 characters.
        user: String,
    },
}

/// " (after N attempts)" for more than one.
fn tries(attempts: u32) -> String {
    if attempts > 1 {
        format!(" (after {attempts} attempts)")
    } else {
        String::new()
    }
}

/// A language model that answers chat messages.
pub trait Backend: Send + Sync {
    /// The model's name, for reports.
    fn model(&self) -> &str;
    /// What the reply cache keys this backend's answers by: the model, and for a server
    /// the server too (two servers may serve different models under one name).
    fn cache_scope(&self) -> String {
        self.model().to_string()
    }
    /// The model's reply to `messages`.
    fn complete(&self, messages: &[Message]) -> Result<Completion, LlmError>;
}

/// Removes secrets from text that came from a model server before it is shown anywhere
/// (stderr, reports, HTTP answers): the API key itself, `sk-…` tokens and `Bearer …`
/// credentials. A server that echoes the request's `Authorization` header in an error
/// body cannot make Shenlong print it.
#[must_use]
pub fn redact(text: &str, key: Option<&str>) -> String {
    const HIDDEN: &str = "[redacted]";
    let mut out = match key.map(str::trim).filter(|k| k.len() >= 4) {
        Some(k) => text.replace(k, HIDDEN),
        None => text.to_string(),
    };
    let token_char =
        |c: char| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.' | '~' | '+' | '/' | '=');
    for marker in ["Bearer ", "bearer ", "sk-"] {
        let mut result = String::with_capacity(out.len());
        let mut rest = out.as_str();
        while let Some(at) = rest.find(marker) {
            let after = &rest[at + marker.len()..];
            let len = after.find(|c: char| !token_char(c)).unwrap_or(after.len());
            let boundary = at == 0 || !rest[..at].ends_with(|c: char| c.is_ascii_alphanumeric());
            if len >= 8 && boundary && !after.starts_with(HIDDEN) {
                result.push_str(&rest[..at]);
                result.push_str(if marker == "sk-" { HIDDEN } else { marker });
                if marker != "sk-" {
                    result.push_str(HIDDEN);
                }
                rest = &after[len..];
            } else {
                result.push_str(&rest[..at + marker.len()]);
                rest = after;
            }
        }
        result.push_str(rest);
        out = result;
    }
    out
}

#[cfg(test)]
mod redact_tests {
    use super::redact;

    #[test]
    fn keys_and_tokens_are_hidden() {
        let body = r#"{"error": {"message": "bad key sk-abcdef1234567890 in header Authorization: Bearer sk-abcdef1234567890"}}"#;
        let r = redact(body, Some("sk-abcdef1234567890"));
        assert!(!r.contains("abcdef"), "{r}");
        assert!(r.contains("[redacted]"));
        let r = redact("Authorization: Bearer zz.top-secret_token", None);
        assert_eq!(r, "Authorization: Bearer [redacted]");
        let r = redact("my key is hunter2hunter2!", Some("hunter2hunter2"));
        assert_eq!(r, "my key is [redacted]!");
        // Words that merely contain the markers are left alone.
        assert_eq!(
            redact("a task-list of desk-lamps", None),
            "a task-list of desk-lamps"
        );
    }
}

//! A thin typed client for OpenAI-compatible chat completions.
//!
//! Why ureq: a blocking client fits the command line's one request at a time, pulls in few
//! dependencies, and the web server runs it on a blocking thread. The request is the
//! standard `POST {base}/chat/completions` with `model`, `messages` and `temperature: 0`.

use super::{tokens, Backend, Completion, LlmError, Message, Usage};
use serde_json::{json, Value};
use std::io::Read;
use std::time::{Duration, Instant};

/// The official OpenAI endpoint.
pub const OPENAI_BASE_URL: &str = "https://api.openai.com/v1";
/// Ollama's OpenAI-compatible endpoint.
pub const OLLAMA_BASE_URL: &str = "http://localhost:11434/v1";

/// The longest wait a server's `Retry-After` may ask for, in seconds.
pub const MAX_RETRY_AFTER_SECS: f64 = 30.0;

/// The most bytes of a model server's HTTP body read: a reply of [`super::MAX_REPLY_BYTES`]
/// and 64 KiB for the JSON around it. Reading stops there, whatever the server sends (an
/// endless stream costs one request and this much), and the reply is refused, not retried:
/// a reply too large is the model's doing, and asking again would only read it again.
pub const MAX_BODY_BYTES: u64 = super::MAX_REPLY_BYTES as u64 + 64 * 1024;

/// Connection settings.
#[derive(Clone, Debug)]
pub struct ClientOptions {
    /// Base URL, up to and including `/v1`.
    pub base_url: String,
    /// Bearer token; never printed or logged.
    pub api_key: Option<String>,
    /// The model name.
    pub model: String,
    /// Time allowed to connect.
    pub connect_timeout: Duration,
    /// Time allowed for one request, reply included.
    pub request_timeout: Duration,
    /// Requests made at most for one completion (429, 5xx and network errors are retried).
    pub max_attempts: u32,
    /// First wait between attempts; it doubles each time, unless the server says
    /// `Retry-After`.
    pub backoff: Duration,
    /// Time allowed for one completion, every attempt and wait included.
    pub deadline: Duration,
}

impl ClientOptions {
    /// Options with the usual timeouts (10 s to connect, 120 s a request, 4 attempts).
    pub fn new(
        base_url: impl Into<String>,
        model: impl Into<String>,
        api_key: Option<String>,
    ) -> Self {
        Self {
            base_url: base_url.into(),
            api_key,
            model: model.into(),
            connect_timeout: Duration::from_secs(10),
            request_timeout: Duration::from_secs(120),
            max_attempts: 4,
            backoff: Duration::from_secs(1),
            deadline: Duration::from_secs(300),
        }
    }
}

/// Why one request failed, and whether another attempt may succeed.
struct AttemptError {
    /// What failed, one line.
    reason: String,
    retry: bool,
    /// The wait the server asked for (`Retry-After`).
    retry_after: Option<Duration>,
}

impl AttemptError {
    fn new(message: impl Into<String>, retry: bool, retry_after: Option<Duration>) -> Self {
        Self {
            reason: message.into(),
            retry,
            retry_after,
        }
    }
}

/// A client for one model on one server.
pub struct OpenAiClient {
    options: ClientOptions,
    agent: ureq::Agent,
    /// When a 429 asked every request to wait: shared by every client of the same server
    /// in the process (every thread and every prompt system of a benchmark), so a pool of
    /// concurrent jobs backs off together instead of hammering the server.
    not_before: std::sync::Arc<std::sync::Mutex<Option<Instant>>>,
}

/// The back-off shared by the clients of one server (by base URL).
fn server_gate(base_url: &str) -> std::sync::Arc<std::sync::Mutex<Option<Instant>>> {
    type Gates =
        std::collections::HashMap<String, std::sync::Arc<std::sync::Mutex<Option<Instant>>>>;
    static GATES: std::sync::OnceLock<std::sync::Mutex<Gates>> = std::sync::OnceLock::new();
    let mut gates = GATES
        .get_or_init(Default::default)
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    std::sync::Arc::clone(
        gates
            .entry(base_url.trim_end_matches('/').to_string())
            .or_default(),
    )
}

impl OpenAiClient {
    /// A client with these options.
    pub fn new(options: ClientOptions) -> Self {
        let agent = ureq::Agent::config_builder()
            .timeout_connect(Some(options.connect_timeout))
            .timeout_global(Some(options.request_timeout))
            .http_status_as_error(false)
            .build()
            .into();
        let not_before = server_gate(&options.base_url);
        Self {
            options,
            agent,
            not_before,
        }
    }

    /// Waits until the pool's back-off (if any) has passed; `false` when that would pass
    /// the deadline of a completion started at `started`.
    fn wait_for_pool(&self, started: Instant) -> bool {
        let until = *self
            .not_before
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        if let Some(until) = until {
            let now = Instant::now();
            if until > now {
                if started.elapsed() + (until - now) > self.options.deadline {
                    return false;
                }
                std::thread::sleep(until - now);
            }
        }
        true
    }

    fn url(&self) -> String {
        format!(
            "{}/chat/completions",
            self.options.base_url.trim_end_matches('/')
        )
    }

    /// One request: the reply and its usage, or why not.
    fn attempt(&self, body: &Value) -> Result<(String, Option<Usage>), AttemptError> {
        let mut request = self
            .agent
            .post(&self.url())
            .header("Content-Type", "application/json");
        if let Some(key) = &self.options.api_key {
            request = request.header("Authorization", &format!("Bearer {key}"));
        }
        let mut response = match request.send_json(body) {
            Ok(r) => r,
            Err(ureq::Error::Timeout(_)) => {
                let message = format!(
                    "the model server at {} did not answer within {} s",
                    self.options.base_url,
                    self.options.request_timeout.as_secs_f64()
                );
                return Err(AttemptError::new(message, true, None));
            }
            Err(e) => {
                let message = format!(
                    "cannot reach the model server at {}: {e}",
                    self.options.base_url
                );
                return Err(AttemptError::new(message, true, None));
            }
        };
        let status = response.status().as_u16();
        let retry_after = response
            .headers()
            .get("retry-after")
            .and_then(|v| v.to_str().ok())
            .and_then(|v| v.trim().parse::<f64>().ok())
            .filter(|s| s.is_finite() && *s >= 0.0)
            .map(|s| Duration::from_secs_f64(s.min(MAX_RETRY_AFTER_SECS)));
        // At most one byte past the limit is read: enough to know the reply is too large.
        let mut bytes = Vec::new();
        std::io::Read::take(
            response.body_mut().with_config().reader(),
            MAX_BODY_BYTES + 1,
        )
        .read_to_end(&mut bytes)
        .map_err(|e| {
            AttemptError::new(
                format!("cannot read the model server's reply: {e}"),
                true,
                None,
            )
        })?;
        if bytes.len() as u64 > MAX_BODY_BYTES {
            let message = format!(
                "the model server's reply (HTTP {status}) is larger than {} KiB; reading stopped there, and a reply that large is not asked for again",
                MAX_BODY_BYTES / 1024
            );
            return Err(AttemptError::new(message, false, None));
        }
        let text = String::from_utf8(bytes).map_err(|e| {
            AttemptError::new(
                format!("the model server's reply is not UTF-8: {e}"),
                false,
                None,
            )
        })?;
        if status != 200 {
            let detail = serde_json::from_str::<Value>(&text)
                .ok()
                .and_then(|v| {
                    v.pointer("/error/message")
                        .and_then(Value::as_str)
                        .map(str::to_string)
                })
                .unwrap_or_else(|| text.chars().take(200).collect());
            let hint = match status {
                401 | 403 => " (check OPENAI_API_KEY)",
                404 => " (check the model name and the base URL)",
                _ => "",
            };
            let retry = status == 429 || status >= 500;
            let message = format!("the model server answered HTTP {status}{hint}: {detail}");
            return Err(AttemptError::new(message, retry, retry_after));
        }
        let value: Value = serde_json::from_str(&text).map_err(|e| {
            AttemptError::new(
                format!("the model server's reply is not JSON: {e}"),
                false,
                None,
            )
        })?;
        let content = value
            .pointer("/choices/0/message/content")
            .and_then(Value::as_str)
            .ok_or_else(|| {
                AttemptError::new(
                    "the model server's reply has no choices[0].message.content",
                    false,
                    None,
                )
            })?;
        let usage = value.get("usage").and_then(|u| {
            Some(Usage {
                prompt_tokens: u.get("prompt_tokens")?.as_u64()?,
                completion_tokens: u.get("completion_tokens")?.as_u64()?,
                estimated: false,
            })
        });
        Ok((content.to_string(), usage))
    }
}

impl Backend for OpenAiClient {
    fn model(&self) -> &str {
        &self.options.model
    }

    fn cache_scope(&self) -> String {
        format!(
            "{} @ {}",
            self.options.model,
            self.options.base_url.trim_end_matches('/')
        )
    }

    fn complete(&self, messages: &[Message]) -> Result<Completion, LlmError> {
        let started = Instant::now();
        let body = json!({"model": self.options.model, "messages": messages, "temperature": 0});
        let mut wait = self.options.backoff;
        let mut last = None;
        for attempt in 1..=self.options.max_attempts.max(1) {
            if !self.wait_for_pool(started) {
                return Err(LlmError::Throttled(self.options.deadline));
            }
            let key = self.options.api_key.as_deref();
            match self.attempt(&body) {
                Ok((text, usage)) => {
                    let text = super::redact(&text, key);
                    let usage = usage.unwrap_or_else(|| tokens::estimate(messages, &text));
                    return Ok(Completion {
                        text,
                        usage,
                        elapsed: started.elapsed(),
                    });
                }
                Err(AttemptError {
                    reason,
                    retry,
                    retry_after,
                }) => {
                    if !retry || attempt == self.options.max_attempts {
                        return Err(LlmError::Request {
                            reason: super::redact(&reason, key),
                            attempts: attempt,
                        });
                    }
                    let pause = retry_after.unwrap_or(wait);
                    if retry_after.is_some() {
                        // The server's wait holds for every request on this client.
                        let until = Instant::now() + pause;
                        let mut shared = self
                            .not_before
                            .lock()
                            .unwrap_or_else(std::sync::PoisonError::into_inner);
                        if shared.is_none_or(|t| t < until) {
                            *shared = Some(until);
                        }
                    }
                    if started.elapsed() + pause > self.options.deadline {
                        return Err(LlmError::GaveUp {
                            reason: super::redact(&reason, key),
                            wait: pause,
                            deadline: self.options.deadline,
                        });
                    }
                    std::thread::sleep(pause);
                    wait *= 2;
                    last = Some(reason);
                }
            }
        }
        // (Every last attempt returns above; this is what the loop would leave.)
        Err(LlmError::Request {
            reason: super::redact(
                &last.unwrap_or_else(|| "no attempt was made".into()),
                self.options.api_key.as_deref(),
            ),
            attempts: self.options.max_attempts,
        })
    }
}

//! `replay:FILE`: answers from recorded exchanges, for deterministic runs and published
//! transcripts. A request is answered by the first unused record whose messages are
//! exactly the request's.

use super::record::Record;
use super::{Backend, Completion, LlmError, Message};
use std::path::Path;
use std::sync::Mutex;
use std::time::Duration;

/// A backend that replays a recording.
pub struct Replay {
    records: Vec<Record>,
    used: Mutex<Vec<bool>>,
    model: String,
    source: String,
}

impl Replay {
    /// Loads a recording (JSON lines written by `--record`).
    pub fn load(path: &Path) -> Result<Self, LlmError> {
        let text = crate::io::read_text_limited(path, crate::io::MAX_READ_BYTES).map_err(|e| {
            LlmError::Unreadable {
                path: path.display().to_string(),
                reason: e.to_string(),
            }
        })?;
        let mut records = Vec::new();
        for (n, line) in text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty())
        {
            let record: Record = serde_json::from_str(line).map_err(|e| LlmError::BadRecord {
                path: path.display().to_string(),
                line: n + 1,
                reason: e.to_string(),
            })?;
            records.push(record);
        }
        let model = records
            .first()
            .map_or_else(|| "replay".to_string(), |r| r.model.clone());
        Ok(Self {
            used: Mutex::new(vec![false; records.len()]),
            records,
            model,
            source: path.display().to_string(),
        })
    }
}

impl Backend for Replay {
    fn model(&self) -> &str {
        &self.model
    }

    fn complete(&self, messages: &[Message]) -> Result<Completion, LlmError> {
        let mut used = self.used.lock().unwrap_or_else(|e| e.into_inner());
        let found = self
            .records
            .iter()
            .enumerate()
            .find(|(i, r)| !used[*i] && r.messages == messages)
            .or_else(|| {
                self.records
                    .iter()
                    .enumerate()
                    .find(|(_, r)| r.messages == messages)
            });
        let Some((i, record)) = found else {
            let user = messages
                .iter()
                .rev()
                .find(|m| m.role == "user")
                .map_or("", |m| m.content.as_str());
            let user: String = user.chars().take(120).collect();
            return Err(LlmError::NotRecorded {
                recording: self.source.clone(),
                user,
            });
        };
        used[i] = true;
        Ok(Completion {
            text: record.reply.clone(),
            usage: record.usage,
            // A hostile record cannot overflow the duration.
            elapsed: Duration::try_from_secs_f64(record.elapsed_ms / 1000.0).unwrap_or_default(),
        })
    }
}

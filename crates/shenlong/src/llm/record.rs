//! Recording exchanges as JSON lines (`--record FILE`), the input of `replay:FILE`.

use super::{Message, Usage};
use serde::{Deserialize, Serialize};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// One recorded exchange: one JSON line.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Record {
    /// The prompt system.
    pub system: String,
    /// The prompt's version.
    pub prompt_version: String,
    /// The model.
    pub model: String,
    /// The request's messages.
    pub messages: Vec<Message>,
    /// The model's reply.
    pub reply: String,
    /// Time the reply took, in milliseconds.
    pub elapsed_ms: f64,
    /// Token counts.
    pub usage: Usage,
}

/// Appends records to a file, one JSON line each, flushed after every line.
pub struct Recorder {
    path: PathBuf,
    file: Mutex<std::fs::File>,
}

impl Recorder {
    /// Opens (creating) the file for appending.
    pub fn open(path: &Path) -> std::io::Result<Self> {
        let file = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(path)?;
        Ok(Self {
            path: path.to_path_buf(),
            file: Mutex::new(file),
        })
    }

    /// Appends one record.
    pub fn append(&self, record: &Record) -> std::io::Result<()> {
        let mut line = serde_json::to_string(record).expect("records serialise");
        line.push('\n');
        let mut file = self.file.lock().unwrap_or_else(|e| e.into_inner());
        file.write_all(line.as_bytes())?;
        file.flush()
    }

    /// The file records go to.
    pub fn path(&self) -> &Path {
        &self.path
    }
}

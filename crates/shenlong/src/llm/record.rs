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

/// Appends records to a file, one JSON line each, flushed after every line. The file is
/// created at the first record: a run whose model never answers leaves no empty file.
pub struct Recorder {
    path: PathBuf,
    file: Mutex<Option<std::fs::File>>,
}

impl Recorder {
    /// A recorder for `path`; checks now that the file can be opened for appending, without
    /// creating it.
    pub fn open(path: &Path) -> std::io::Result<Self> {
        if path.exists() {
            std::fs::OpenOptions::new().append(true).open(path)?;
        } else {
            let dir = path
                .parent()
                .filter(|p| !p.as_os_str().is_empty())
                .unwrap_or(Path::new("."));
            if !dir.is_dir() {
                return Err(std::io::Error::new(
                    std::io::ErrorKind::NotFound,
                    format!("no folder {}", dir.display()),
                ));
            }
        }
        Ok(Self {
            path: path.to_path_buf(),
            file: Mutex::new(None),
        })
    }

    /// Appends one record.
    pub fn append(&self, record: &Record) -> std::io::Result<()> {
        let mut line = serde_json::to_string(record).expect("records serialise");
        line.push('\n');
        let mut file = self.file.lock().unwrap_or_else(|e| e.into_inner());
        if file.is_none() {
            *file = Some(
                std::fs::OpenOptions::new()
                    .create(true)
                    .append(true)
                    .open(&self.path)?,
            );
        }
        let f = file.as_mut().expect("opened above");
        f.write_all(line.as_bytes())?;
        f.flush()
    }

    /// The file records go to.
    pub fn path(&self) -> &Path {
        &self.path
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_file_until_the_first_record() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("log.jsonl");
        let r = Recorder::open(&path).unwrap();
        assert!(!path.exists());
        r.append(&Record {
            system: "cga".into(),
            prompt_version: "cga-4".into(),
            model: "m".into(),
            messages: Vec::new(),
            reply: "{}".into(),
            elapsed_ms: 1.0,
            usage: Usage::default(),
        })
        .unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap().lines().count(), 1);
        assert!(Recorder::open(&dir.path().join("no/such/dir/log.jsonl")).is_err());
    }
}

//! A cache of valid replies, keyed by (prompt system, prompt version, model, the request's
//! messages). A CGA request's only message besides the fixed system prompt is the
//! templated query, so one reply serves every scene; the baselines' messages carry the
//! scene's numbers, so they hit only for an identical prompt.

use sha2::{Digest, Sha256};
use std::path::{Path, PathBuf};

use super::Message;

/// Replies stored as files named by the hash of their key.
#[derive(Clone, Debug)]
pub struct Cache {
    dir: PathBuf,
}

impl Cache {
    /// The default folder: the user's cache directory, `shenlong/replies`.
    pub fn default_dir() -> Option<PathBuf> {
        dirs::cache_dir().map(|d| d.join("shenlong").join("replies"))
    }

    /// A cache in `dir` (created when first written).
    pub fn new(dir: impl Into<PathBuf>) -> Self {
        Self { dir: dir.into() }
    }

    /// The folder.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    fn path(&self, system: &str, version: &str, model: &str, messages: &[Message]) -> PathBuf {
        let mut hash = Sha256::new();
        for part in [system, version, model] {
            hash.update(part.as_bytes());
            hash.update([0]);
        }
        hash.update(serde_json::to_vec(messages).expect("messages serialise"));
        let digest = hash.finalize();
        let name: String = digest.iter().map(|b| format!("{b:02x}")).collect();
        self.dir.join(format!("{name}.json"))
    }

    /// The cached reply, if any.
    pub fn get(
        &self,
        system: &str,
        version: &str,
        model: &str,
        messages: &[Message],
    ) -> Option<String> {
        let text = std::fs::read_to_string(self.path(system, version, model, messages)).ok()?;
        let value: serde_json::Value = serde_json::from_str(&text).ok()?;
        value.get("reply")?.as_str().map(str::to_string)
    }

    /// Stores a valid reply. Failing to write is not an error worth stopping an edit for;
    /// it is returned for the caller to report.
    pub fn put(
        &self,
        system: &str,
        version: &str,
        model: &str,
        messages: &[Message],
        reply: &str,
    ) -> std::io::Result<()> {
        std::fs::create_dir_all(&self.dir)?;
        let user = messages
            .iter()
            .rev()
            .find(|m| m.role == "user")
            .map_or("", |m| m.content.as_str());
        let value = serde_json::json!({"system": system, "prompt_version": version, "model": model, "query": user, "reply": reply});
        crate::io::write_atomic(
            &self.path(system, version, model, messages),
            value.to_string().as_bytes(),
        )
    }
}

//! One module per subcommand.

pub mod apply;
pub mod convert;
pub mod eval;
pub mod examples;
pub mod render;

use anyhow::{Context, Result};
use shenlong::format::SceneFile;
use std::io::Write;
use std::path::Path;

/// Loads a scene file, or a built-in example given as `example:NAME`.
pub fn load_scene(spec: &str) -> Result<SceneFile> {
    if let Some(name) = spec.strip_prefix("example:") {
        let scene = shenlong::examples::build(name)
            .with_context(|| format!("unknown example '{name}': `shenlong examples` lists them"))?;
        return Ok(SceneFile {
            scene,
            document: shenlong::format::Document::None,
            path: None,
        });
    }
    Ok(SceneFile::load(Path::new(spec))?)
}

/// Writes bytes to stdout in one go.
pub fn write_stdout(bytes: &[u8]) -> Result<()> {
    let mut out = std::io::stdout().lock();
    out.write_all(bytes)
        .context("cannot write to standard output")?;
    out.flush().context("cannot write to standard output")?;
    Ok(())
}

//! `shenlong examples`: list or write the built-in example scenes.

use anyhow::{Context, Result};
use shenlong::format::{Document, Format, SceneFile};
use std::path::PathBuf;

/// List the built-in example scenes, or write one as a scene file.
#[derive(clap::Args)]
#[command(after_help = "Examples:
  shenlong examples
  shenlong examples workshop -o workshop.json")]
pub struct Args {
    /// The example to write; without it, the list is printed.
    name: Option<String>,
    /// Where to write it (format by extension); stdout when omitted.
    #[arg(short, long, value_name = "FILE")]
    output: Option<PathBuf>,
}

pub fn run(args: Args) -> Result<()> {
    let Some(name) = args.name else {
        let mut text = String::new();
        for (name, description) in shenlong::examples::list() {
            let n = shenlong::examples::build(name).map_or(0, |s| s.objects.len());
            text.push_str(&format!("{name:<16} {n:>3} objects  {description}\n"));
        }
        return super::write_stdout(text.as_bytes());
    };
    let scene = shenlong::examples::build(&name)
        .with_context(|| format!("unknown example '{name}': `shenlong examples` lists them"))?;
    let file = SceneFile {
        scene,
        document: Document::None,
        path: None,
    };
    match args.output {
        Some(path) => file.save(&path)?,
        None => super::write_stdout(&file.to_bytes(Format::SceneJson)?)?,
    }
    Ok(())
}

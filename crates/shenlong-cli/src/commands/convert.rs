//! `shenlong convert`: between scene formats.

use anyhow::Result;
use std::path::PathBuf;

/// Convert a scene between formats, chosen by the files' extensions.
#[derive(clap::Args)]
#[command(after_help = "Example:
  shenlong convert example:kitchen kitchen.json")]
pub struct Args {
    /// The input scene (or example:NAME).
    input: String,
    /// The output file; its extension chooses the format.
    output: PathBuf,
}

pub fn run(args: Args) -> Result<()> {
    let file = super::load_scene(&args.input)?;
    file.save(&args.output)?;
    Ok(())
}

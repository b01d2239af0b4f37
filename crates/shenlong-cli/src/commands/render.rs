//! `shenlong render`: a top-down picture of a scene.

use anyhow::{bail, Context, Result};
use std::path::PathBuf;

/// Draw a top-down plan of a scene as SVG or PNG (by the output's extension).
///
/// Objects appear as their footprints with names and a tick toward their front; objects
/// resting on others are drawn in orange. With --before, the objects that moved since
/// that scene are green, their old places dashed, with arrows from old to new.
#[derive(clap::Args)]
#[command(after_help = "Examples:
  shenlong render examples/living_room.json -o living_room.png
  shenlong render edited.json --before examples/workshop.json -o edit.svg")]
pub struct Args {
    #[command(flatten)]
    read: super::ReadArgs,
    /// The scene (or example:NAME).
    scene: String,
    /// The picture to write: .svg or .png.
    #[arg(short, long, value_name = "FILE")]
    output: PathBuf,
    /// The scene before an edit (the same objects), to show what moved.
    #[arg(long, value_name = "OLD")]
    before: Option<String>,
}

pub fn run(args: Args) -> Result<()> {
    let scene = super::load_scene_with(&args.scene, &args.read)?.scene;
    let before = args
        .before
        .as_deref()
        .map(|b| super::load_scene_with(b, &args.read))
        .transpose()?
        .map(|f| f.scene);
    if let Some(before) = &before {
        let same = before.objects.len() == scene.objects.len()
            && before
                .objects
                .iter()
                .zip(&scene.objects)
                .all(|(a, b)| a.name == b.name);
        if !same {
            bail!("--before must be the same scene before the edit: its objects differ");
        }
    }
    let svg = shenlong::render::plan_svg(&scene, before.as_ref());
    let ext = args
        .output
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let bytes = match ext.as_deref() {
        Some("svg") => svg.into_bytes(),
        Some("png") => png(&svg)?,
        _ => bail!(
            "{}: the picture must be .svg or .png",
            args.output.display()
        ),
    };
    shenlong::io::write_atomic(&args.output, &bytes)
        .with_context(|| format!("cannot write {}", args.output.display()))
}

#[cfg(feature = "png")]
fn png(svg: &str) -> Result<Vec<u8>> {
    shenlong::render::svg_to_png(svg).map_err(anyhow::Error::msg)
}

#[cfg(not(feature = "png"))]
fn png(_: &str) -> Result<Vec<u8>> {
    bail!("this build has no PNG support (built without the 'png' feature): write .svg")
}

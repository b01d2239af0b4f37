//! `shenlong convert`: between scene formats, and importing ProcTHOR/Holodeck houses.

use anyhow::{bail, Result};
use shenlong::format::procthor::AssetDatabase;
use shenlong::format::SceneFile;
use std::path::{Path, PathBuf};

/// Convert a scene between formats, chosen by the files' extensions.
///
/// Scene JSON (.json) and glTF (.gltf, .glb) are read; a glTF scene is written back as
/// glTF of the same kind, or as scene JSON (each mesh as its world box). ProcTHOR and
/// Holodeck houses are imported with --from procthor and the asset database for sizes.
#[derive(clap::Args)]
#[command(after_help = "Examples:
  shenlong convert example:kitchen kitchen.json
  shenlong convert model.glb model.json
  shenlong convert houses.jsonl house3.json --from procthor --assets asset-database.json --house 3")]
pub struct Args {
    #[command(flatten)]
    read: super::ReadArgs,
    /// The input scene (or example:NAME).
    input: String,
    /// The output file; its extension chooses the format.
    output: PathBuf,
    /// Read the input as this format instead of by extension: procthor (houses, one a
    /// line in .jsonl).
    #[arg(long, value_name = "FORMAT", value_parser = ["procthor"])]
    from: Option<String>,
    /// ProcTHOR's asset-database.json, for object sizes (with --from procthor).
    #[arg(long, value_name = "DB")]
    assets: Option<PathBuf>,
    /// Which house of a .jsonl file, from 0 (with --from procthor).
    #[arg(long, value_name = "N", default_value_t = 0)]
    house: usize,
}

pub fn run(args: Args) -> Result<()> {
    let file = match args.from.as_deref() {
        Some("procthor") => {
            let Some(db) = &args.assets else {
                bail!("--from procthor needs --assets asset-database.json for the objects' sizes");
            };
            if args.read.given() {
                bail!("--units and --front are for glTF and USD files; a ProcTHOR house is in metres and says its fronts");
            }
            let assets = AssetDatabase::load(db)?;
            SceneFile::load_house(Path::new(&args.input), args.house, &assets)?
        }
        _ => {
            if args.assets.is_some() {
                bail!("--assets goes with --from procthor");
            }
            super::load_scene_with(&args.input, &args.read)?
        }
    };
    file.save(&args.output)?;
    Ok(())
}

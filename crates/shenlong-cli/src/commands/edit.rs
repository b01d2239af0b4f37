//! `shenlong edit`: the main job — an instruction applied to a scene.

use anyhow::{Context, Result};
use shenlong::pipeline::backends::translator;
use shenlong::pipeline::{edit, EditOptions, System};
use std::path::PathBuf;

/// Edit a scene by instruction: "move the 'sofa' to the right".
///
/// Object names go in quotes (or are recognised as whole words). The instruction is
/// templated (names → X1, X2, …), translated into CGA transformations by the built-in
/// offline translator or a language model, applied about each object's pivot (carrying
/// what rests on it), and collisions are resolved. The edited scene goes to OUT (stdout
/// if omitted) in the input's format; nothing is written on failure.
#[derive(clap::Args)]
#[command(after_help = "Examples:
  shenlong edit examples/workshop.json \"put the 'orange bottle' on top of the 'tool table'\" -o edited.json
  shenlong edit examples/living_room.json \"rotate the 'armchair' 45 degrees clockwise\" --json report.json -o out.json
  shenlong edit room.glb \"move the 'Cube' 2 units up\" --llm openai:gpt-4o -o moved.glb
  shenlong edit room.json \"swap the 'lamp' and the 'plant'\" --llm ollama:llama3.1 --system euclidean
  shenlong edit room.json \"turn it 90 degrees\" --selected 'armchair' -o out.json

Backends (--llm): offline (built in, no network), openai:MODEL (OPENAI_API_KEY,
OPENAI_BASE_URL), ollama:MODEL (localhost:11434), replay:FILE (answers recorded with
--record). See docs/llm.md.")]
pub struct Args {
    #[command(flatten)]
    read: super::ReadArgs,
    /// The scene file (or example:NAME).
    scene: String,
    /// The instruction, with object names in quotes.
    instruction: String,
    /// Where to write the edited scene (format by extension); stdout when omitted.
    #[arg(short, long, value_name = "OUT")]
    output: Option<PathBuf>,
    /// The prompt system: cga (Shenlong), euclidean or omniverse (the paper's baselines).
    #[arg(long, value_name = "SYSTEM", default_value = "cga", value_parser = ["cga", "euclidean", "omniverse"])]
    system: String,
    /// Write the edit report as JSON: to FILE, or to stderr without a value.
    #[arg(long, value_name = "FILE", num_args = 0..=1, default_missing_value = "-")]
    json: Option<String>,
    /// Do not carry the objects resting on a moved object.
    #[arg(long)]
    no_carry: bool,
    /// An object the user has selected (repeat for several): "it", "them" or "the
    /// selection" with nothing named before them mean the selected objects.
    #[arg(long = "selected", value_name = "NAME")]
    selected: Vec<String>,
    /// Also write the edit as ThreeDWorld commands to this file.
    #[arg(long, value_name = "FILE")]
    tdw: Option<PathBuf>,
    /// For a USD stage: write OUT (a .usda) as a layer over the input — its sublayer — that
    /// holds only `over`s of the edited prims, USD's non-destructive way; the input is
    /// never written.
    #[arg(long, requires = "output")]
    usd_layer: bool,
    #[command(flatten)]
    translator: super::TranslatorArgs,
    #[command(flatten)]
    collisions: super::CollisionArgs,
}

pub fn run(args: Args) -> Result<()> {
    let system = System::from_name(&args.system).expect("clap checked the name");
    let settings = args.translator.settings(system)?;
    let mut file = super::load_scene_with(&args.scene, &args.read)?;
    let translator = translator(&args.translator.llm, &settings).map_err(super::llm_error)?;
    let options = EditOptions {
        carry: !args.no_carry,
        collisions: args.collisions.resolve_options()?,
        selection: args
            .selected
            .iter()
            .map(|name| {
                file.scene
                    .resolve(name)
                    .map_err(|e| anyhow::anyhow!("--selected: {e}"))
            })
            .collect::<Result<_>>()?,
    };
    // The scene as it was, for the ThreeDWorld commands only: no copy otherwise.
    let before = args.tdw.is_some().then(|| file.scene.clone());
    let result = edit(
        &mut file.scene,
        &args.instruction,
        translator.as_ref(),
        &options,
    )
    // The flag is the command line's to name; the library's message does not.
    .map_err(super::edit_error)?;
    let report = serde_json::to_string_pretty(&result.report)
        .map_err(|e| anyhow::anyhow!("cannot write the edit report: {e}"))?;

    // The report file is made ready first: when it cannot be written, neither is the
    // scene (a failed command changes no file).
    let json_file = match args.json.as_deref() {
        Some(path) if path != "-" => Some(
            shenlong::io::prepare(std::path::Path::new(path), format!("{report}\n").as_bytes())
                .with_context(|| format!("cannot write {path}"))?,
        ),
        _ => None,
    };
    // A stream (a pipe, `/dev/full`) fails only when it is written: it is written before
    // the scene, so that a report that cannot be written leaves the scene unwritten.
    let json_file = match json_file {
        Some(stream @ shenlong::io::Prepared::InPlace { .. }) => {
            stream
                .commit()
                .with_context(|| format!("cannot write {}", args.json.as_deref().unwrap_or("")))?;
            None
        }
        other => other,
    };
    super::write_edit(
        &file,
        before.as_ref(),
        super::Output {
            path: args.output.as_deref(),
            usd_layer: args.usd_layer,
        },
        args.tdw.as_deref(),
    )?;
    if let (Some(prepared), Some(path)) = (json_file, args.json.as_deref()) {
        prepared
            .commit()
            .with_context(|| format!("cannot write {path}"))?;
    }
    match args.json.as_deref() {
        Some("-") => eprintln!("{}", shenlong_cli::terminal::safe_json(&report)),
        Some(_) => {}
        None => {
            for c in &result.report.collisions_resolved {
                let d = c.displacement;
                shenlong_cli::say!(
                    "note: moved '{}' by [{:.3}, {:.3}, {:.3}] m to clear {}",
                    c.object,
                    d[0],
                    d[1],
                    d[2],
                    c.collided_with.join(", ")
                );
            }
            for o in &result.report.overlaps_remaining {
                shenlong_cli::say!("note: {o} (--allow-collisions)");
            }
        }
    }
    Ok(())
}

//! `shenlong edit`: the main job — an instruction applied to a scene.

use anyhow::Result;
use shenlong::pipeline::backends::translator;
use shenlong::pipeline::{EditOptions, System};
use shenlong::session::{EditRequest, Session};
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
    #[arg(long, value_name = "SYSTEM", default_value = "cga")]
    system: System,
    /// Write the edit's outcome as JSON — what moved, notes, the instruction as
    /// understood and the whole report — to FILE, or to stderr without a value (where a
    /// refusal is written too, as JSON: kind, error, ambiguity).
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
    let system = args.system;
    let settings = args.translator.settings(system)?;
    let file = super::load_scene_with(&args.scene, &args.read)?;
    let translator = translator(&args.translator.llm, &settings).map_err(super::llm_error)?;
    let options = EditOptions::new(!args.no_carry, args.collisions.resolve_options()?);
    let mut session = Session::saving_on_request(file, None);
    let request = EditRequest {
        instruction: &args.instruction,
        selected: &args.selected,
        report: true,
    };
    let offline = args.translator.llm == shenlong::pipeline::backends::Spec::Offline;
    let outcome = session
        .edit(&request, translator.as_ref(), &options)
        .map_err(|e| super::refused(e, args.json.as_deref(), offline))?;
    super::finish(
        &session,
        &outcome,
        args.json.as_deref(),
        super::Output {
            path: args.output.as_deref(),
            usd_layer: args.usd_layer,
        },
        args.tdw.as_deref(),
    )
}

//! `shenlong edit`: the main job — an instruction applied to a scene.

use anyhow::{bail, Context, Result};
use shenlong::format::Format;
use shenlong::pipeline::backends::{translator, TranslatorSettings};
use shenlong::pipeline::{edit, EditOptions, System};
use std::path::PathBuf;
use std::time::Duration;

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

Backends (--llm): offline (built in, no network), openai:MODEL (OPENAI_API_KEY,
OPENAI_BASE_URL), ollama:MODEL (localhost:11434), replay:FILE (answers recorded with
--record). See docs/llm.md.")]
pub struct Args {
    /// The scene file (or example:NAME).
    scene: String,
    /// The instruction, with object names in quotes.
    instruction: String,
    /// Where to write the edited scene (format by extension); stdout when omitted.
    #[arg(short, long, value_name = "OUT")]
    output: Option<PathBuf>,
    /// The translator: offline, openai:MODEL, ollama:MODEL or replay:FILE.
    #[arg(long, value_name = "BACKEND", default_value = "offline")]
    llm: String,
    /// The prompt system: cga (Shenlong), euclidean or omniverse (the paper's baselines).
    #[arg(long, value_name = "SYSTEM", default_value = "cga", value_parser = ["cga", "euclidean", "omniverse"])]
    system: String,
    /// Write the edit report as JSON: to FILE, or to stderr without a value.
    #[arg(long, value_name = "FILE", num_args = 0..=1, default_missing_value = "-")]
    json: Option<String>,
    /// Do not carry the objects resting on a moved object.
    #[arg(long)]
    no_carry: bool,
    /// Attempts after the first when the model's reply cannot be used.
    #[arg(long, value_name = "N", default_value_t = 5)]
    retries: usize,
    /// Append every exchange with the model to FILE (JSON lines; replay with replay:FILE).
    #[arg(long, value_name = "FILE")]
    record: Option<PathBuf>,
    /// Where replies are cached (default: the user's cache folder, shenlong/replies).
    #[arg(long, value_name = "DIR")]
    cache_dir: Option<PathBuf>,
    /// Do not read or write the reply cache.
    #[arg(long)]
    no_cache: bool,
    /// The model server's base URL (overrides OPENAI_BASE_URL and the defaults).
    #[arg(long, value_name = "URL")]
    base_url: Option<String>,
    /// Seconds allowed for one request to the model.
    #[arg(long, value_name = "S", default_value_t = 120.0)]
    timeout: f64,
    /// Also write the edit as ThreeDWorld commands to this file.
    #[arg(long, value_name = "FILE")]
    tdw: Option<PathBuf>,
    #[command(flatten)]
    collisions: super::CollisionArgs,
}

pub fn run(args: Args) -> Result<()> {
    if !(args.timeout.is_finite() && args.timeout > 0.0) {
        bail!("--timeout {}: give a number of seconds > 0", args.timeout);
    }
    let system = System::from_name(&args.system).expect("clap checked the name");
    let settings = TranslatorSettings {
        system,
        retries: args.retries,
        base_url: args.base_url.clone(),
        api_key: None,
        timeout: Duration::from_secs_f64(args.timeout),
        cache_dir: if args.no_cache {
            None
        } else {
            args.cache_dir
                .clone()
                .or_else(shenlong::llm::cache::Cache::default_dir)
        },
        record: args.record.clone(),
    };
    let mut file = super::load_scene(&args.scene)?;
    let translator = translator(&args.llm, &settings).map_err(anyhow::Error::msg)?;
    let options = EditOptions {
        carry: !args.no_carry,
        collisions: if args.collisions.no_collide() {
            None
        } else {
            Some(args.collisions.options()?)
        },
    };
    let before = file.scene.clone();
    let result = edit(
        &mut file.scene,
        &args.instruction,
        translator.as_ref(),
        &options,
    )?;
    let report = serde_json::to_string_pretty(&result.report).expect("reports serialise");

    // Render every output before writing any; then write the scene, the commands, the report.
    let scene_bytes = match &args.output {
        Some(path) => file.to_bytes(Format::from_path(path)?)?,
        None => file.to_bytes(match &file.path {
            Some(p) => Format::from_path(p)?,
            None => Format::SceneJson,
        })?,
    };
    let tdw = args.tdw.as_ref().map(|path| {
        let commands = shenlong::format::tdw::edit(&before, &file.scene, &file.tdw_ids());
        (
            path,
            shenlong::format::pretty::to_string(&serde_json::Value::Array(commands)),
        )
    });
    match &args.output {
        Some(path) => file.save(path)?,
        None => super::write_stdout(&scene_bytes)?,
    }
    if let Some((path, text)) = tdw {
        shenlong::io::write_atomic(path, text.as_bytes())
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    match args.json.as_deref() {
        Some("-") => eprintln!("{report}"),
        Some(path) => {
            shenlong::io::write_atomic(std::path::Path::new(path), format!("{report}\n").as_bytes())
                .with_context(|| format!("cannot write {path}"))?
        }
        None => {
            for c in &result.report.collisions_resolved {
                let d = c.displacement;
                eprintln!(
                    "note: moved '{}' by [{:.3}, {:.3}, {:.3}] m to clear {}",
                    c.object,
                    d[0],
                    d[1],
                    d[2],
                    c.collided_with.join(", ")
                );
            }
            for o in &result.report.overlaps_remaining {
                eprintln!("note: {o} (--allow-collisions)");
            }
        }
    }
    Ok(())
}

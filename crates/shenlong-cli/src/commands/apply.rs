//! `shenlong apply`: apply one CGA expression to one object, with no translator.

use anyhow::{Context, Result};
use shenlong::session::{bound_objects, ApplyRequest, Session};
use std::path::PathBuf;

/// Apply a CGA expression to one object of a scene and write the result.
///
/// The expression may use X1 for the object. Objects resting on it are carried along
/// unless --no-carry. If the result collides with other objects, the floor or the walls,
/// the object (with what rests on it) moves to the nearest free placement; what was
/// adjusted is said on stderr. The output has the input's format and shape.
#[derive(clap::Args)]
#[command(after_help = "Example:
  shenlong apply examples/workshop.json --object 'tool table' --expr 'T(0.5 * e1)' -o moved.json
  shenlong apply examples/workshop.json --object chair --expr 'R(pi/2, e3, e1)' -o turned.json --tdw turn.tdw.json")]
pub struct Args {
    #[command(flatten)]
    read: super::ReadArgs,
    /// The scene file (or example:NAME).
    scene: String,
    /// The object to transform.
    #[arg(long, value_name = "NAME")]
    object: String,
    /// The transformation, e.g. "T(0.5 * e1)"; X1 is the object.
    #[arg(long, value_name = "EXPR")]
    expr: String,
    /// Where to write the edited scene (format by extension); stdout when omitted.
    #[arg(short, long, value_name = "OUT")]
    output: Option<PathBuf>,
    /// Do not carry the objects resting on this one.
    #[arg(long)]
    no_carry: bool,
    /// Another object the expression uses, as VARIABLE=NAME: `--bind 'X2=tool table'`
    /// (X2, X3 … in order).
    #[arg(long = "bind", value_name = "X2=NAME")]
    bind: Vec<String>,
    /// Write the outcome as JSON — what moved, notes, the expression as understood — to
    /// FILE, or to stderr without a value (where a refusal is written too, as JSON).
    #[arg(long, value_name = "FILE", num_args = 0..=1, default_missing_value = "-")]
    json: Option<String>,
    /// Also write the edit as ThreeDWorld commands (teleport_object, rotate_object_to,
    /// scale_object) to this file.
    #[arg(long, value_name = "FILE")]
    tdw: Option<PathBuf>,
    #[command(flatten)]
    collisions: super::CollisionArgs,
}

pub fn run(args: Args) -> Result<()> {
    let file = super::load_scene_with(&args.scene, &args.read)?;
    let options = args.collisions.edit_options(!args.no_carry)?;
    let mut bind = std::collections::BTreeMap::new();
    for pair in &args.bind {
        let (variable, name) = pair
            .split_once('=')
            .with_context(|| format!("--bind {pair}: give VARIABLE=NAME, as X2='tool table'"))?;
        bind.insert(variable.trim().to_string(), name.to_string());
    }
    let mut session = Session::saving_on_request(file, None);
    let result = bound_objects(&args.object, &bind).and_then(|objects| {
        session.apply(
            &ApplyRequest {
                objects: &objects,
                expression: &args.expr,
            },
            &options,
        )
    });
    let outcome = result.map_err(|e| {
        super::refused(e, args.json.as_deref(), false).context(format!("--expr {}", args.expr))
    })?;
    super::finish(
        &session,
        &outcome,
        args.json.as_deref(),
        super::Output {
            path: args.output.as_deref(),
            usd_layer: false,
        },
        args.tdw.as_deref(),
    )
}

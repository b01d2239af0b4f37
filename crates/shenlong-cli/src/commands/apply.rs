//! `shenlong apply`: apply one CGA expression to one object, with no translator.

use anyhow::Result;
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
    /// Also write the edit as ThreeDWorld commands (teleport_object, rotate_object_to,
    /// scale_object) to this file.
    #[arg(long, value_name = "FILE")]
    tdw: Option<PathBuf>,
    #[command(flatten)]
    collisions: super::CollisionArgs,
}

pub fn run(args: Args) -> Result<()> {
    let mut file = super::load_scene_with(&args.scene, &args.read)?;
    let options = args.collisions.edit_options(!args.no_carry)?;
    // The scene as it was, for the ThreeDWorld commands only: no copy otherwise.
    let before = args.tdw.is_some().then(|| file.scene.clone());
    let (placed, _) =
        shenlong::pipeline::apply_expression(&mut file.scene, &args.object, &args.expr, &options)
            .map_err(|e| super::edit_error(e).context(format!("--expr {}", args.expr)))?;
    super::collision_notes(&placed);
    super::write_edit(
        &file,
        before.as_ref(),
        super::Output {
            path: args.output.as_deref(),
            usd_layer: false,
        },
        args.tdw.as_deref(),
    )?;
    Ok(())
}

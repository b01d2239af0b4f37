//! `shenlong eval`: evaluate a CGA expression by hand.

use anyhow::{bail, Context, Result};
use cga::BLADE_NAMES;
use shenlong::expr::{self, Bindings, ObjectBox};

/// Evaluate a CGA expression and print the transformation it is.
///
/// Variables X1, X2, … stand for objects of a scene: `--scene FILE --bind X1=NAME`.
/// Prints the versor and its decomposition into translation, rotation (quaternion
/// [x, y, z, w]) and scale.
#[derive(clap::Args)]
#[command(after_help = "Examples:
  shenlong eval \"T(2 * e1) * R(pi/2, e3, e1)\"
  shenlong eval \"T(((X2.max | e2) - (X1.min | e2)) * e2)\" --scene example:workshop \\
      --bind X1='orange bottle' --bind X2='tool table' --json

The language is described in docs/expressions.md.")]
pub struct Args {
    /// The expression, e.g. "T(-1 * e1)" or "R(np.pi/2, e3, e1)".
    expression: String,
    /// Scene whose objects the variables stand for (a file, or example:NAME).
    #[arg(long, value_name = "FILE")]
    scene: Option<String>,
    /// Bind a variable to an object of the scene: X1=NAME (repeatable).
    #[arg(long = "bind", value_name = "X1=NAME")]
    bindings: Vec<String>,
    /// Print exactly one JSON object: {"versor", "translation", "rotation", "scale"}.
    #[arg(long)]
    json: bool,
    /// Print the value whatever it is (a vector, a scalar…), without requiring T·R·D.
    #[arg(long)]
    raw: bool,
}

pub fn run(args: Args) -> Result<()> {
    let bindings = bindings(&args)?;
    if args.raw {
        let value = expr::evaluate(&args.expression, &bindings)?;
        let text = if args.json {
            serde_json::json!({"multivector": value.coefficients().to_vec(), "text": value.to_string()})
                .to_string()
        } else {
            value.to_string()
        };
        return super::write_stdout(format!("{text}\n").as_bytes());
    }
    let t = expr::evaluate_transformation(&args.expression, &bindings)?;
    let s = t.similarity;
    let output = if args.json {
        serde_json::json!({
            "versor": t.versor.coefficients().to_vec(),
            "translation": s.translation.to_array(),
            "rotation": s.rotation.to_array(),
            "scale": s.scale,
        })
        .to_string()
    } else {
        let (axis, angle) = s.rotation.to_axis_angle();
        let terms: Vec<String> = t
            .versor
            .coefficients()
            .iter()
            .zip(BLADE_NAMES)
            .filter(|(c, _)| c.abs() > 1e-15)
            .map(|(c, b)| format!("{c:+.6} {b}"))
            .collect();
        format!(
            "versor       {}\ntranslation  [{:.6}, {:.6}, {:.6}]\nrotation     [{:.6}, {:.6}, {:.6}, {:.6}]  ({:.3}° about [{:.3}, {:.3}, {:.3}])\nscale        {:.6}",
            terms.join(" "),
            s.translation.x, s.translation.y, s.translation.z,
            s.rotation.x, s.rotation.y, s.rotation.z, s.rotation.w,
            angle.to_degrees(), axis.x, axis.y, axis.z,
            s.scale
        )
    };
    super::write_stdout(format!("{output}\n").as_bytes())
}

fn bindings(args: &Args) -> Result<Bindings> {
    let mut bindings = Bindings::new();
    if args.bindings.is_empty() {
        return Ok(bindings);
    }
    let Some(spec) = &args.scene else {
        bail!("--bind needs --scene: the objects the variables stand for");
    };
    let file = super::load_scene(spec)?;
    for binding in &args.bindings {
        let (variable, name) = binding
            .split_once('=')
            .with_context(|| format!("--bind {binding}: write it as X1=NAME"))?;
        let variable = variable.trim();
        let valid = variable.len() > 1
            && variable.starts_with('X')
            && variable[1..].bytes().all(|b| b.is_ascii_digit());
        if !valid {
            bail!("--bind {binding}: the variable must be X1, X2, …");
        }
        let index = file.scene.resolve(name).map_err(anyhow::Error::msg)?;
        let object = &file.scene.objects[index];
        let aabb = object.world_aabb();
        bindings.bind(
            variable,
            ObjectBox {
                min: aabb.min,
                max: aabb.max,
                front: object.world_front(),
            },
        );
    }
    Ok(bindings)
}

//! The three prompt systems: Shenlong's CGA prompt and the paper's two baselines. Each
//! builds the messages for a templated instruction and reads the reply into one
//! transformation per variable. The prompts live in `prompts/*.md`, each with a version
//! string that goes into cache keys and reports.

use crate::expr::{self, reply, Dialect, ExprError, ExprErrorKind, Transformation};
use crate::llm::Message;
use crate::scene::{Scene, Shape};
use crate::translate::Templated;
pub use crate::translate::{Answer, System};
use cga::{Multivector, Similarity};
use glam::{DQuat, DVec3, EulerRot};
use serde_json::Value;

const CGA_PROMPT: &str = include_str!("../../prompts/cga.md");
const EUCLIDEAN_PROMPT: &str = include_str!("../../prompts/euclidean.md");
const OMNIVERSE_PROMPT: &str = include_str!("../../prompts/omniverse.md");

impl System {
    /// The system prompt, without its version comment.
    pub fn prompt(self) -> &'static str {
        let text = match self {
            System::Cga => CGA_PROMPT,
            System::Euclidean => EUCLIDEAN_PROMPT,
            System::Omniverse => OMNIVERSE_PROMPT,
        };
        text.split_once("-->\n").map_or(text, |(_, rest)| rest)
    }

    /// The prompt's version (`cga-1`).
    pub fn version(self) -> &'static str {
        let text = match self {
            System::Cga => CGA_PROMPT,
            System::Euclidean => EUCLIDEAN_PROMPT,
            System::Omniverse => OMNIVERSE_PROMPT,
        };
        text.split("version:")
            .nth(1)
            .and_then(|s| s.split("-->").next())
            .map_or("unversioned", str::trim)
    }

    /// The messages for a templated instruction.
    pub fn messages(self, templated: &Templated, scene: &Scene) -> Vec<Message> {
        let user = match self {
            System::Cga => format!("Instruction: {}", templated.query),
            System::Euclidean => {
                let mut lines = vec!["Objects:".to_string()];
                for (k, &i) in templated.objects.iter().enumerate() {
                    let b = scene.objects[i].world_aabb();
                    lines.push(format!(
                        "{}: min [{}], max [{}]",
                        Templated::variable(k),
                        numbers(b.min.to_array()),
                        numbers(b.max.to_array())
                    ));
                }
                lines.push(format!("Instruction: {}", templated.query));
                lines.join("\n")
            }
            System::Omniverse => {
                let objects: Vec<String> = templated
                    .objects
                    .iter()
                    .enumerate()
                    .map(|(k, &i)| {
                        let (size, centre, euler) = omniverse_pose(scene, i);
                        format!(
                            "{}: dimensions [{}], centre [{}], rotation [{}], front [{}]",
                            Templated::variable(k),
                            numbers(size.to_array()),
                            numbers(centre.to_array()),
                            numbers(euler),
                            numbers(scene.objects[i].world_front().to_array())
                        )
                    })
                    .collect();
                format!(
                    "Objects: {}\nInstruction: {}",
                    objects.join("; "),
                    templated.query
                )
            }
        };
        vec![
            Message::new("system", self.prompt()),
            Message::new("user", user),
        ]
    }

    /// Whether a reply parses in this system: its answer can be found and every
    /// expression in it is well formed (for Omniverse, a JSON object naming the variables)
    /// — whether or not it then evaluates to a transformation.
    #[must_use]
    pub fn reply_parses(self, text: &str) -> bool {
        match self {
            System::Cga | System::Euclidean => {
                reply::extract_cga_reply(text).is_ok_and(|entries| {
                    !entries.is_empty()
                        && entries
                            .iter()
                            .flat_map(|e| e.expressions.iter())
                            .all(|source| expr::parse(source).is_ok())
                })
            }
            System::Omniverse => reply::parse_relaxed_objects(text)
                .iter()
                .any(|(_, m)| m.keys().any(|k| k.trim().starts_with(['X', 'x']))),
        }
    }

    /// Reads a reply into one transformation per variable. Errors are written for the
    /// model to correct in a retry.
    pub fn parse_reply(
        self,
        text: &str,
        templated: &Templated,
        scene: &Scene,
    ) -> Result<Vec<Answer>, ExprError> {
        let bindings = super::bindings(scene, &templated.objects);
        let object_of = |variable: &str| -> Result<usize, ExprError> {
            let k: usize = variable[1..].parse().unwrap_or(0);
            templated
                .objects
                .get(k.wrapping_sub(1))
                .copied()
                .ok_or_else(|| {
                    let bound: Vec<String> = (0..templated.objects.len())
                        .map(Templated::variable)
                        .collect();
                    ExprError::whole(
                        ExprErrorKind::Reply,
                        format!(
                            "the reply names {variable}, but the instruction only has {}",
                            if bound.is_empty() {
                                "no variables".to_string()
                            } else {
                                bound.join(", ")
                            }
                        ),
                    )
                })
        };
        let mut answers = Vec::new();
        match self {
            System::Cga | System::Euclidean => {
                let dialect = if self == System::Cga {
                    Dialect::Cga
                } else {
                    Dialect::Euclidean
                };
                for entry in reply::extract_cga_reply(text)? {
                    let object = object_of(&entry.variable)?;
                    let mut m = Multivector::ONE;
                    for (n, source) in entry.expressions.iter().enumerate() {
                        let item = expr::evaluate_in(source, &bindings, dialect)
                            .and_then(|v| expr::to_transformation(&v))
                            .map_err(|e| {
                                let which = if entry.expressions.len() > 1 {
                                    format!(" item {}", n + 1)
                                } else {
                                    String::new()
                                };
                                e.within(&format!("{}{which}", entry.variable))
                            })?;
                        m = item.versor * m;
                    }
                    let transformation = expr::to_transformation(&m)?;
                    answers.push(Answer {
                        near: None,
                        variable: entry.variable,
                        object,
                        expressions: entry.expressions,
                        transformation,
                    });
                }
            }
            System::Omniverse => {
                let objects = reply::parse_relaxed_objects(text);
                let Some((_, map)) = objects
                    .iter()
                    .rev()
                    .find(|(_, m)| m.keys().any(|k| k.trim().starts_with(['X', 'x'])))
                else {
                    return Err(ExprError::whole(ExprErrorKind::Reply,
                        "no JSON object naming the variables found in the reply: answer with one JSON object such as {\"X1\": {\"position\": [0, 0.5, 0], \"rotation\": [0, 0, 0]}}",
                    ));
                };
                for (key, value) in map {
                    let variable = format!("X{}", key.trim().trim_start_matches(['X', 'x']));
                    if variable.len() < 2 || !variable[1..].bytes().all(|b| b.is_ascii_digit()) {
                        continue;
                    }
                    let object = object_of(&variable)?;
                    let transformation = omniverse_transformation(scene, object, value)
                        .map_err(|m| m.within(&variable))?;
                    answers.push(Answer {
                        near: None,
                        variable,
                        object,
                        expressions: vec![value.to_string()],
                        transformation,
                    });
                }
            }
        }
        if answers.is_empty() {
            return Err(ExprError::whole(
                ExprErrorKind::Reply,
                "the reply changes no object: give a transformation for at least one variable",
            ));
        }
        Ok(answers)
    }
}

fn numbers<const N: usize>(values: [f64; N]) -> String {
    values
        .iter()
        .map(|v| format!("{}", (v * 1e4).round() / 1e4 + 0.0))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Euler angles in degrees, applied about X, then Y, then Z: `R = Rz·Ry·Rx`.
fn euler_to_quat(degrees: [f64; 3]) -> DQuat {
    let [x, y, z] = degrees.map(f64::to_radians);
    DQuat::from_euler(EulerRot::ZYX, z, y, x)
}

fn quat_to_euler(q: DQuat) -> [f64; 3] {
    let (z, y, x) = q.to_euler(EulerRot::ZYX);
    [x.to_degrees(), y.to_degrees(), z.to_degrees()]
}

/// The local centre of an object's shape.
fn local_centre(scene: &Scene, i: usize) -> DVec3 {
    let object = &scene.objects[i];
    match &object.shape {
        Shape::Box { size } => DVec3::new(0.0, size.y * 0.5, 0.0),
        Shape::Points { .. } => crate::geometry::Aabb::from_points(object.local_points())
            .map_or(DVec3::ZERO, |b| b.center()),
    }
}

/// Size (world box), centre and Euler angles, as the omniverse prompt gives them.
fn omniverse_pose(scene: &Scene, i: usize) -> (DVec3, DVec3, [f64; 3]) {
    let object = &scene.objects[i];
    let pose = object.similarity();
    let centre = pose.transform_point(local_centre(scene, i));
    (
        object.world_aabb().size(),
        centre,
        quat_to_euler(pose.rotation),
    )
}

/// The transformation (about the pivot) that brings an object to the centre and Euler
/// angles the omniverse reply gives.
fn omniverse_transformation(
    scene: &Scene,
    i: usize,
    value: &Value,
) -> Result<Transformation, ExprError> {
    let triple = |key: &str| -> Result<Option<[f64; 3]>, ExprError> {
        match value.get(key) {
            None | Some(Value::Null) => Ok(None),
            Some(v) => {
                let list = v.as_array().filter(|a| a.len() == 3).ok_or_else(|| {
                    ExprError::whole(
                        ExprErrorKind::Reply,
                        format!("\"{key}\" must be a list of three numbers"),
                    )
                })?;
                let mut out = [0.0; 3];
                for (k, item) in list.iter().enumerate() {
                    out[k] = item.as_f64().filter(|x| x.is_finite()).ok_or_else(|| {
                        ExprError::whole(
                            ExprErrorKind::Reply,
                            format!("\"{key}\"[{k}] must be a number"),
                        )
                    })?;
                }
                Ok(Some(out))
            }
        }
    };
    if !value.is_object() {
        return Err(ExprError::whole(
            ExprErrorKind::Reply,
            "give an object with \"position\" and \"rotation\"",
        ));
    }
    let (_, centre, euler) = omniverse_pose(scene, i);
    let target_centre = triple("position")?.map_or(centre, DVec3::from);
    let target_rotation = euler_to_quat(triple("rotation")?.unwrap_or(euler));
    let pose = scene.objects[i].similarity();
    let delta = (target_rotation * pose.rotation.inverse()).normalize();
    let pivot = scene.objects[i].pivot_point();
    // Turning about the pivot moves the centre; the translation makes up the rest.
    let turned_centre = pivot + delta * (centre - pivot);
    let m = Similarity {
        translation: target_centre - turned_centre,
        rotation: delta,
        scale: 1.0,
    }
    .to_versor()
    .map_err(|e| ExprError::whole(ExprErrorKind::NotATransformation, e.to_string()))?;
    expr::to_transformation(&m)
}

#[cfg(test)]
mod tests;

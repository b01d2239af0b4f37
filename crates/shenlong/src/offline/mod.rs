//! The built-in offline translator (`--llm offline`, the default): a templated instruction
//! to the same CGA answer a language model would give, with no network and no model.
//!
//! It is a small grammar, not a list of sentences, one module per stage:
//! - [`words`]: tokens, and the closed word lists (verbs, directions, units, fillers), with
//!   one-letter typos of verbs and directions corrected;
//! - [`clause`]: clauses split at `and`, `then`, commas, each recording which words it read;
//! - [`amounts`]: lengths, angles and scale factors — numbers, spoken compounds, vague
//!   amounts with documented defaults, both directions of every relative change;
//! - [`relations`]: relations to other objects, from their boxes only;
//! - [`room`]: the room's centre, corners, walls and floor;
//! - [`read`]: one clause's verb, subjects and meaning; every word must be read.
//!
//! Answers are expression trees ([`crate::expr::Expr`]) written with only `X_i.min/.max/
//! .center/.size`, `room`, `e1 e2 e3`, `T`, `R`, `D` — never the scene's numbers but for a
//! straightening's snap — evaluated directly; the reply it reports is printed from them.
//! An instruction any word of which is unread is refused, quoting the unread words.

pub mod amounts;
mod build;
mod clause;
mod idioms;
mod read;
mod relations;
mod room;
mod view;
mod words;

pub use relations::GAP;

use crate::expr::{self, Bindings, Expr};
use crate::llm::{Message, Usage};
use crate::scene::Scene;
use crate::translate::{
    bindings, Answer, Exchange, System, Templated, TranslateError, Translation, Translator,
};
use read::{Facts, Reader};
use relations::Step;
use std::time::Instant;

/// The offline translator.
#[derive(Clone, Debug, Default)]
pub struct OfflineTranslator;

impl OfflineTranslator {
    /// The translator.
    pub fn new() -> Self {
        Self
    }
}

/// One variable's answer: the transformations, applied in order.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// The variable, from 0 (`X1`).
    pub variable: usize,
    /// The expressions, first applied first.
    pub expressions: Vec<Expr>,
}

/// Reads an instruction with variables into expression trees, one entry per variable it
/// changes. `room`: whether the scene has bounds; `yaw`: each variable's current turn about
/// the vertical in degrees (for "straighten"); `sizes`: each variable's world box size
/// (for "to X2": a small thing goes on X2's top), or empty.
///
/// # Errors
/// The unread part of the instruction, quoted.
pub fn answer(
    query: &str,
    variables: usize,
    room: bool,
    yaw: &[f64],
    sizes: &[[f64; 3]],
) -> Result<Vec<Entry>, String> {
    let facts = Facts {
        variables,
        room,
        yaw: yaw.to_vec(),
        sizes: sizes.to_vec(),
    };
    let tokens = words::tokenize(query);
    let mut reader = Reader::new(&facts);
    for mut c in clause::split(&tokens) {
        reader.clause(&mut c)?;
    }
    if reader.steps.is_empty() {
        return Err(read::not_read(query, query));
    }
    // A list acts in the pivot frame of the object's original place: turns and scales go
    // first (about the object itself), then the translations (which commute).
    Ok(reader
        .steps
        .iter()
        .map(|(&v, list)| {
            let mut expressions: Vec<Expr> = list
                .iter()
                .filter_map(|s| match s {
                    Step::Turn(e) => Some(e.clone()),
                    Step::Translate(_) => None,
                })
                .collect();
            let moves: Vec<Expr> = list
                .iter()
                .filter_map(|s| match s {
                    Step::Translate(v) => Some(v.clone()),
                    Step::Turn(_) => None,
                })
                .collect();
            if !moves.is_empty() {
                expressions.push(build::translator(build::sum(moves)));
            }
            Entry {
                variable: v,
                expressions,
            }
        })
        .collect())
}

/// The reply as a model would write it: `{"X1": "T(...)"}`, printed from the trees.
pub fn reply_text(entries: &[Entry]) -> String {
    let items: Vec<String> = entries
        .iter()
        .map(|e| {
            let exprs: Vec<String> = e.expressions.iter().map(|x| x.to_string()).collect();
            let value = if exprs.len() == 1 {
                serde_json::Value::String(exprs[0].clone())
            } else {
                serde_json::Value::from(exprs)
            };
            format!("\"X{}\": {value}", e.variable + 1)
        })
        .collect();
    format!("{{{}}}", items.join(", "))
}

/// Reads an instruction into the reply text a model would give (for tools and tests).
///
/// # Errors
/// As [`answer`].
pub fn reply_for(query: &str, variables: usize) -> Result<String, String> {
    answer(query, variables, true, &vec![0.0; variables], &[]).map(|e| reply_text(&e))
}

impl Translator for OfflineTranslator {
    fn name(&self) -> String {
        "offline".into()
    }

    fn system(&self) -> System {
        System::Cga
    }

    fn translate(
        &self,
        templated: &Templated,
        scene: &Scene,
    ) -> Result<Translation, TranslateError> {
        let started = Instant::now();
        let yaw: Vec<f64> = templated
            .objects
            .iter()
            .map(|&i| {
                let q = scene.objects[i].similarity().rotation;
                let (axis, angle) = q.to_axis_angle();
                (angle * axis.y.signum()).to_degrees()
            })
            .collect();
        let sizes: Vec<[f64; 3]> = templated
            .objects
            .iter()
            .map(|&i| scene.objects[i].world_aabb().size().to_array())
            .collect();
        let entries = answer(
            &templated.query,
            templated.objects.len(),
            scene.bounds.is_some(),
            &yaw,
            &sizes,
        )
        .map_err(TranslateError::not_understood)?;
        let bindings: Bindings = bindings(scene, &templated.objects);
        let reply = reply_text(&entries);
        let mut answers = Vec::new();
        for e in &entries {
            let mut m = cga::Multivector::ONE;
            for x in &e.expressions {
                let item = expr::evaluate_tree(x, &bindings)
                    .and_then(|v| expr::to_transformation(&v))
                    .map_err(|err| {
                        TranslateError::not_understood(format!(
                            "the offline translator cannot do \"{}\" in this scene ({err})",
                            templated.query
                        ))
                    })?;
                m = item.versor * m;
            }
            let transformation = expr::to_transformation(&m).map_err(|err| {
                TranslateError::not_understood(format!(
                    "the offline translator cannot do \"{}\" in this scene ({err})",
                    templated.query
                ))
            })?;
            answers.push(Answer {
                variable: Templated::variable(e.variable),
                object: templated.objects[e.variable],
                expressions: e.expressions.iter().map(ToString::to_string).collect(),
                transformation,
            });
        }
        let exchange = Exchange {
            messages: vec![Message::new(
                "user",
                format!("Instruction: {}", templated.query),
            )],
            reply,
            elapsed_ms: started.elapsed().as_secs_f64() * 1000.0,
            usage: Usage::default(),
            error: None,
            cached: false,
        };
        Ok(Translation {
            answers,
            exchanges: vec![exchange],
            retries: 0,
            cache_hit: false,
            elapsed: started.elapsed(),
            answered_by: "offline".into(),
            offline_refusal: None,
            replies: Default::default(),
        })
    }
}

#[cfg(test)]
mod tests;

//! The checks of SPEC §6, evaluated on the scene before and after an edit. Each failure
//! says what was measured. Distances are metres, angles degrees; defaults are in
//! docs/benchmark.md.

mod motion;
mod parse;
mod relation;
mod whole;

pub use parse::CheckError;

/// Why a check failed: what was measured, in one line (`'mug' moved by [0.1, 0, 0]
/// (wanted [-1, any, any])`).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct Failure(pub String);

use crate::geometry::Aabb;
use crate::scene::Scene;
use glam::{DQuat, DVec3};
use std::collections::HashMap;

/// An object reference: a placeholder (`"A"`) or an object's name.
pub type ObjectRef = String;

/// One check. Each variant's documentation names its fields; docs/benchmark.md gives the
/// defaults.
#[allow(missing_docs)]
#[derive(Clone, Debug, PartialEq)]
pub enum Check {
    /// Moved by `delta` (per axis; `None` = any), within `tol`: the displacement of the
    /// bottom centre of its box (its pivot).
    Moved {
        object: ObjectRef,
        delta: [Option<f64>; 3],
        tol: f64,
    },
    /// Moved at least `min` along `axis`, and little along the others.
    Direction {
        object: ObjectRef,
        axis: (usize, f64),
        min: f64,
    },
    /// Turned by `degrees` about `axis` (either way with `either_sign`), within `tol`.
    Rotated {
        object: ObjectRef,
        axis: usize,
        degrees: f64,
        either_sign: bool,
        tol: f64,
    },
    /// Scaled by `factor`, within `tol` (relative).
    Scaled {
        object: ObjectRef,
        factor: f64,
        tol: f64,
    },
    /// Resting on the top face of `support`, its centre over it.
    OnTop {
        object: ObjectRef,
        support: ObjectRef,
        tol: f64,
    },
    /// Beside `other`: not inside it, horizontally within `max_gap`, at a shared height.
    NextTo {
        object: ObjectRef,
        other: ObjectRef,
        max_gap: f64,
    },
    /// On one side (left/right/front/behind) of `other`, within `max_gap`.
    Side {
        object: ObjectRef,
        other: ObjectRef,
        side: (usize, f64),
        max_gap: f64,
    },
    /// Entirely above `other`.
    Above {
        object: ObjectRef,
        other: ObjectRef,
        tol: f64,
    },
    /// Entirely below `other`.
    Below {
        object: ObjectRef,
        other: ObjectRef,
        tol: f64,
    },
    /// Between `a` and `b` on the floor plan.
    Between {
        object: ObjectRef,
        a: ObjectRef,
        b: ObjectRef,
        tol: f64,
    },
    /// Centred with `other` along `axis`.
    Aligned {
        object: ObjectRef,
        other: ObjectRef,
        axis: usize,
        tol: f64,
    },
    /// Bottom centre at `position` (per axis; `None` = any).
    At {
        object: ObjectRef,
        position: [Option<f64>; 3],
        tol: f64,
    },
    /// Front (local +Z) turned toward `target`, within `tol` degrees.
    Faces {
        object: ObjectRef,
        target: ObjectRef,
        tol: f64,
    },
    /// Centre distance to `other` within [`min`, `max`].
    Distance {
        object: ObjectRef,
        other: ObjectRef,
        min: f64,
        max: f64,
    },
    /// These objects (or all the others) did not move.
    Unchanged { objects: Option<Vec<ObjectRef>> },
    /// The edit created no collision.
    NoCollision,
    /// Every object is inside the room (or no farther out than before).
    InsideBounds,
    /// Extension: the edit must be refused — fail, change nothing — with a message that
    /// names each of `mentions` (the candidates of an ambiguous phrase, say).
    Refused { mentions: Vec<ObjectRef> },
    /// Extension: `object` now stands where `other` stood and the other way round (bottom
    /// centres, within `tol`).
    Swapped {
        object: ObjectRef,
        other: ObjectRef,
        tol: f64,
    },
}

impl Check {
    /// The objects the check is about (its `object` field; both objects of a swap): what
    /// the instruction acts on, so not among the "others" that must stay unchanged.
    pub fn subjects(&self) -> Vec<&ObjectRef> {
        if let Check::Swapped { object, other, .. } = self {
            return vec![object, other];
        }
        let one: Option<&ObjectRef> = match self {
            Check::Moved { object, .. }
            | Check::Direction { object, .. }
            | Check::Rotated { object, .. }
            | Check::Scaled { object, .. }
            | Check::At { object, .. }
            | Check::OnTop { object, .. }
            | Check::NextTo { object, .. }
            | Check::Side { object, .. }
            | Check::Above { object, .. }
            | Check::Below { object, .. }
            | Check::Aligned { object, .. }
            | Check::Faces { object, .. }
            | Check::Distance { object, .. }
            | Check::Between { object, .. }
            | Check::Swapped { object, .. } => Some(object),
            Check::Unchanged { .. }
            | Check::NoCollision
            | Check::InsideBounds
            | Check::Refused { .. } => None,
        };
        one.into_iter().collect()
    }

    /// The object references the check uses.
    pub fn placeholders(&self) -> Vec<String> {
        let refs: Vec<&ObjectRef> = match self {
            Check::Moved { object, .. }
            | Check::Direction { object, .. }
            | Check::Rotated { object, .. }
            | Check::Scaled { object, .. }
            | Check::At { object, .. } => vec![object],
            Check::OnTop {
                object,
                support: other,
                ..
            }
            | Check::NextTo { object, other, .. }
            | Check::Side { object, other, .. }
            | Check::Above { object, other, .. }
            | Check::Below { object, other, .. }
            | Check::Aligned { object, other, .. }
            | Check::Faces {
                object,
                target: other,
                ..
            }
            | Check::Distance { object, other, .. }
            | Check::Swapped { object, other, .. } => vec![object, other],
            Check::Between { object, a, b, .. } => vec![object, a, b],
            Check::Unchanged {
                objects: Some(list),
            } => list.iter().collect(),
            Check::Refused { mentions } => mentions.iter().collect(),
            Check::Unchanged { objects: None } | Check::NoCollision | Check::InsideBounds => vec![],
        };
        refs.into_iter().cloned().collect()
    }

    /// Evaluates a `refused` check on a failed edit's message: each mention (a placeholder
    /// or a name) must be named in it. Other checks pass on a refusal only if they hold on
    /// the unchanged scene.
    pub fn evaluate_refusal(
        &self,
        message: &str,
        scene: &Scene,
        bound: &HashMap<String, usize>,
    ) -> Result<(), Failure> {
        match self {
            Check::Refused { mentions } => {
                for m in mentions {
                    let name = bound
                        .get(m)
                        .map_or(m.as_str(), |&i| scene.objects[i].name.as_str());
                    if !message.to_lowercase().contains(&name.to_lowercase()) {
                        return Err(Failure(format!(
                            "the refusal does not name '{name}': {message}"
                        )));
                    }
                }
                Ok(())
            }
            _ => self.evaluate(scene, scene, bound),
        }
    }

    /// Evaluates the check; `Err` says why it failed. `bound` maps placeholders to
    /// objects; other names are looked up in the scene.
    pub fn evaluate(
        &self,
        before: &Scene,
        after: &Scene,
        bound: &HashMap<String, usize>,
    ) -> Result<(), Failure> {
        let c = Ctx {
            before,
            after,
            bound,
        };
        match self {
            Check::Moved { object, delta, tol } => motion::moved(&c, object, delta, *tol),
            Check::Direction {
                object,
                axis: (axis, sign),
                min,
            } => motion::direction(&c, object, (*axis, *sign), *min),
            Check::Rotated {
                object,
                axis,
                degrees,
                either_sign,
                tol,
            } => motion::rotated(&c, object, *axis, *degrees, *either_sign, *tol),
            Check::Scaled {
                object,
                factor,
                tol,
            } => motion::scaled(&c, object, *factor, *tol),
            Check::At {
                object,
                position,
                tol,
            } => motion::at(&c, object, position, *tol),
            Check::Swapped { object, other, tol } => motion::swapped(&c, object, other, *tol),
            Check::Unchanged { objects } => whole::unchanged(&c, objects),
            Check::NoCollision => whole::no_collision(&c),
            Check::InsideBounds => whole::inside_bounds(&c),
            Check::OnTop {
                object,
                support,
                tol,
            } => relation::on_top(&c, object, support, *tol),
            Check::NextTo {
                object,
                other,
                max_gap,
            } => relation::next_to(&c, object, other, *max_gap),
            Check::Side {
                object,
                other,
                side: (axis, sign),
                max_gap,
            } => relation::side(&c, object, other, (*axis, *sign), *max_gap),
            Check::Above { object, other, tol } => relation::above(&c, object, other, *tol),
            Check::Below { object, other, tol } => relation::below(&c, object, other, *tol),
            Check::Between { object, a, b, tol } => relation::between(&c, object, a, b, *tol),
            Check::Aligned {
                object,
                other,
                axis,
                tol,
            } => relation::aligned(&c, object, other, *axis, *tol),
            Check::Faces {
                object,
                target,
                tol,
            } => relation::faces(&c, object, target, *tol),
            Check::Distance {
                object,
                other,
                min,
                max,
            } => relation::distance(&c, object, other, *min, *max),
            Check::Refused { .. } => Err(Failure(
                "the edit succeeded, but it should have been refused".to_string(),
            )),
        }
    }
}

/// What a check is evaluated against: the scene before and after the edit, and the
/// placeholders bound to objects.
pub(super) struct Ctx<'a> {
    pub(super) before: &'a Scene,
    pub(super) after: &'a Scene,
    pub(super) bound: &'a HashMap<String, usize>,
}

impl Ctx<'_> {
    /// The object a reference names: a bound placeholder, else an object's name.
    fn find(&self, r: &ObjectRef) -> Result<usize, Failure> {
        self.bound
            .get(r)
            .copied()
            .or_else(|| self.after.find(r))
            .ok_or_else(|| Failure(format!("no object '{r}' in the scene")))
    }

    /// Object `i`'s world box before the edit.
    fn b0(&self, i: usize) -> Aabb {
        self.before.objects[i].world_aabb()
    }

    /// Object `i`'s world box after the edit.
    fn b1(&self, i: usize) -> Aabb {
        self.after.objects[i].world_aabb()
    }

    /// Object `i`'s name.
    fn name(&self, i: usize) -> String {
        self.after.objects[i].name.clone()
    }
}

fn v3(v: DVec3) -> String {
    format!("[{:.3}, {:.3}, {:.3}]", v.x, v.y, v.z)
}

fn opt3(v: &[Option<f64>; 3]) -> String {
    let parts: Vec<String> = v
        .iter()
        .map(|x| x.map_or("any".into(), |x| format!("{x}")))
        .collect();
    format!("[{}]", parts.join(", "))
}

fn overlap_xz(a: &Aabb, b: &Aabb) -> bool {
    a.footprint_overlap(b) > 0.0
}

/// The turn of `q` about the unit axis `axis`, in degrees (its twist component).
fn signed_angle_about(q: DQuat, axis: DVec3) -> f64 {
    let v = DVec3::new(q.x, q.y, q.z);
    let projected = axis * v.dot(axis);
    let twist = DQuat::from_xyzw(projected.x, projected.y, projected.z, q.w);
    if twist.length() < 1e-12 {
        return 180.0;
    }
    let twist = twist.normalize();
    let (twist_axis, angle) = twist.to_axis_angle();
    let signed = if twist_axis.dot(axis) < 0.0 {
        -angle
    } else {
        angle
    };
    let degrees = signed.to_degrees();
    // Into (−180, 180].
    let mut d = degrees % 360.0;
    if d > 180.0 {
        d -= 360.0;
    } else if d <= -180.0 {
        d += 360.0;
    }
    d
}

fn angle_difference(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(360.0);
    d.min(360.0 - d)
}

#[cfg(test)]
mod tests;

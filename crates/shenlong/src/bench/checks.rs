//! The checks of SPEC §6, evaluated on the scene before and after an edit. Each failure
//! says what was measured. Distances are metres, angles degrees; defaults are in
//! docs/benchmark.md.

use crate::collide::find_collisions;
use crate::geometry::Aabb;
use crate::scene::Scene;
use glam::{DQuat, DVec3};
use serde_json::{Map, Value};
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

const CHECKS: &[(&str, &[&str])] = &[
    ("moved", &["object", "delta", "tol"]),
    ("direction", &["object", "axis", "min"]),
    (
        "rotated",
        &["object", "axis", "degrees", "either_sign", "tol"],
    ),
    ("scaled", &["object", "factor", "tol"]),
    ("on_top", &["object", "support", "tol"]),
    ("next_to", &["object", "other", "max_gap"]),
    ("side", &["object", "other", "side", "max_gap"]),
    ("above", &["object", "other", "tol"]),
    ("below", &["object", "other", "tol"]),
    ("between", &["object", "a", "b", "tol"]),
    ("aligned", &["object", "other", "axis", "tol"]),
    ("at", &["object", "position", "tol"]),
    ("faces", &["object", "target", "tol"]),
    ("distance", &["object", "other", "min", "max"]),
    ("unchanged", &["objects"]),
    ("no_collision", &[]),
    ("inside_bounds", &[]),
    ("swapped", &["object", "other", "tol"]),
    ("refused", &["mentions"]),
];

fn axis_of(text: &str) -> Option<(usize, f64)> {
    let t = text.trim().to_lowercase();
    let (sign, name) = match t.strip_prefix('-') {
        Some(rest) => (-1.0, rest.to_string()),
        None => (1.0, t.trim_start_matches('+').to_string()),
    };
    let axis = match name.as_str() {
        "x" | "e1" => 0,
        "y" | "e2" => 1,
        "z" | "e3" => 2,
        _ => return None,
    };
    Some((axis, sign))
}

impl Check {
    /// Reads a check from its JSON object; unknown checks and fields are errors.
    pub fn parse(value: &Value) -> Result<Self, String> {
        let map = value
            .as_object()
            .ok_or("a check must be an object with a \"check\" field")?;
        let name = map
            .get("check")
            .and_then(Value::as_str)
            .ok_or("missing \"check\": the check's name")?;
        let fields = CHECKS
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, f)| *f)
            .ok_or_else(|| {
                format!(
                    "unknown check '{name}': use {}",
                    CHECKS
                        .iter()
                        .map(|(n, _)| *n)
                        .collect::<Vec<_>>()
                        .join(", ")
                )
            })?;
        if let Some(extra) = map
            .keys()
            .find(|k| *k != "check" && !fields.contains(&k.as_str()))
        {
            return Err(format!(
                "check '{name}' has no field '{extra}' (it takes {})",
                if fields.is_empty() {
                    "none".to_string()
                } else {
                    fields.join(", ")
                }
            ));
        }
        let f = Fields { map, name };
        Ok(match name {
            "moved" => Check::Moved {
                object: f.object("object")?,
                delta: f.triple("delta")?.unwrap_or([None; 3]),
                tol: f.number("tol", 0.05)?,
            },
            "direction" => Check::Direction {
                object: f.object("object")?,
                axis: f.axis("axis")?,
                min: f.number("min", 0.05)?,
            },
            "rotated" => Check::Rotated {
                object: f.object("object")?,
                axis: f.optional_axis("axis")?.map_or(1, |a| a.0),
                degrees: f.number("degrees", 90.0)?,
                either_sign: f
                    .map
                    .get("either_sign")
                    .and_then(Value::as_bool)
                    .unwrap_or(false),
                tol: f.number("tol", 5.0)?,
            },
            "scaled" => Check::Scaled {
                object: f.object("object")?,
                factor: f.required_number("factor")?,
                tol: f.number("tol", 0.02)?,
            },
            "on_top" => Check::OnTop {
                object: f.object("object")?,
                support: f.object("support")?,
                tol: f.number("tol", 0.03)?,
            },
            "next_to" => Check::NextTo {
                object: f.object("object")?,
                other: f.object("other")?,
                max_gap: f.number("max_gap", 0.3)?,
            },
            "side" => {
                let side = f
                    .map
                    .get("side")
                    .and_then(Value::as_str)
                    .ok_or("check 'side' needs \"side\": left, right, front or behind")?;
                let side = match side {
                    "left" => (0, -1.0),
                    "right" => (0, 1.0),
                    "front" => (2, 1.0),
                    "behind" | "back" => (2, -1.0),
                    other => {
                        return Err(format!(
                        "check 'side': unknown side '{other}': use left, right, front or behind"
                    ))
                    }
                };
                Check::Side {
                    object: f.object("object")?,
                    other: f.object("other")?,
                    side,
                    max_gap: f.number("max_gap", 0.5)?,
                }
            }
            "above" => Check::Above {
                object: f.object("object")?,
                other: f.object("other")?,
                tol: f.number("tol", 0.03)?,
            },
            "below" => Check::Below {
                object: f.object("object")?,
                other: f.object("other")?,
                tol: f.number("tol", 0.03)?,
            },
            "between" => Check::Between {
                object: f.object("object")?,
                a: f.object("a")?,
                b: f.object("b")?,
                tol: f.number("tol", 0.3)?,
            },
            "aligned" => Check::Aligned {
                object: f.object("object")?,
                other: f.object("other")?,
                axis: f.axis("axis")?.0,
                tol: f.number("tol", 0.05)?,
            },
            "at" => Check::At {
                object: f.object("object")?,
                position: f
                    .triple("position")?
                    .ok_or("check 'at' needs \"position\": [x, y, z]")?,
                tol: f.number("tol", 0.05)?,
            },
            "faces" => Check::Faces {
                object: f.object("object")?,
                target: f.object("target")?,
                tol: f.number("tol", 20.0)?,
            },
            "distance" => Check::Distance {
                object: f.object("object")?,
                other: f.object("other")?,
                min: f.number("min", 0.0)?,
                max: f.number("max", f64::INFINITY)?,
            },
            "unchanged" => Check::Unchanged {
                objects: match f.map.get("objects") {
                    None => None,
                    Some(Value::String(s)) if s == "others" => None,
                    Some(Value::Array(items)) => Some(
                        items
                            .iter()
                            .map(|v| {
                                v.as_str()
                                    .map(str::to_string)
                                    .ok_or("check 'unchanged': objects must be names")
                            })
                            .collect::<Result<_, _>>()?,
                    ),
                    Some(_) => {
                        return Err(
                            "check 'unchanged': objects must be a list of names or \"others\""
                                .into(),
                        )
                    }
                },
            },
            "no_collision" => Check::NoCollision,
            "refused" => Check::Refused {
                mentions: match f.map.get("mentions") {
                    None => Vec::new(),
                    Some(Value::Array(items)) => items
                        .iter()
                        .map(|v| {
                            v.as_str()
                                .map(str::to_string)
                                .ok_or("check 'refused': mentions must be names")
                        })
                        .collect::<Result<_, _>>()?,
                    Some(_) => {
                        return Err("check 'refused': mentions must be a list of names".into())
                    }
                },
            },
            "swapped" => Check::Swapped {
                object: f.object("object")?,
                other: f.object("other")?,
                tol: f.number("tol", 0.05)?,
            },
            _ => Check::InsideBounds,
        })
    }

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
    ) -> Result<(), String> {
        match self {
            Check::Refused { mentions } => {
                for m in mentions {
                    let name = bound
                        .get(m)
                        .map_or(m.as_str(), |&i| scene.objects[i].name.as_str());
                    if !message.to_lowercase().contains(&name.to_lowercase()) {
                        return Err(format!("the refusal does not name '{name}': {message}"));
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
    ) -> Result<(), String> {
        let find = |r: &ObjectRef| -> Result<usize, String> {
            bound
                .get(r)
                .copied()
                .or_else(|| after.find(r))
                .ok_or_else(|| format!("no object '{r}' in the scene"))
        };
        let b0 = |i: usize| before.objects[i].world_aabb();
        let b1 = |i: usize| after.objects[i].world_aabb();
        let name = |i: usize| after.objects[i].name.clone();
        match self {
            Check::Moved { object, delta, tol } => {
                let i = find(object)?;
                let d = b1(i).bottom_center() - b0(i).bottom_center();
                for axis in 0..3 {
                    if let Some(want) = delta[axis] {
                        if (d[axis] - want).abs() > *tol {
                            return Err(format!(
                                "'{}' moved by {} (wanted {})",
                                name(i),
                                v3(d),
                                opt3(delta)
                            ));
                        }
                    }
                }
                Ok(())
            }
            Check::Direction {
                object,
                axis: (axis, sign),
                min,
            } => {
                let i = find(object)?;
                let d = b1(i).bottom_center() - b0(i).bottom_center();
                let along = d[*axis] * sign;
                let across = (0..3)
                    .filter(|a| a != axis)
                    .map(|a| d[a].abs())
                    .fold(0.0, f64::max);
                if along < *min {
                    return Err(format!(
                        "'{}' moved {:.3} m that way (at least {min} wanted): {}",
                        name(i),
                        along,
                        v3(d)
                    ));
                }
                if across > (0.1f64).max(0.25 * along) {
                    return Err(format!(
                        "'{}' also moved {:.3} m across: {}",
                        name(i),
                        across,
                        v3(d)
                    ));
                }
                Ok(())
            }
            Check::Rotated {
                object,
                axis,
                degrees,
                either_sign,
                tol,
            } => {
                let i = find(object)?;
                let delta = after.objects[i].similarity().rotation
                    * before.objects[i].similarity().rotation.inverse();
                let mut want = DVec3::ZERO;
                want[*axis] = 1.0;
                let turned = signed_angle_about(delta, want);
                let off = |target: f64| angle_difference(turned, target);
                let ok = off(*degrees) <= *tol || (*either_sign && off(-degrees) <= *tol);
                // Anything but a turn about the axis counts against it.
                let residual = (DQuat::from_axis_angle(want, turned.to_radians()).inverse()
                    * delta)
                    .to_axis_angle()
                    .1
                    .to_degrees();
                if !ok || residual > *tol {
                    return Err(format!(
                        "'{}' turned {:.1}° about {} (wanted {}{degrees}°), off-axis {:.1}°",
                        name(i),
                        turned,
                        ["x", "y", "z"][*axis],
                        if *either_sign { "±" } else { "" },
                        residual
                    ));
                }
                Ok(())
            }
            Check::Scaled {
                object,
                factor,
                tol,
            } => {
                let i = find(object)?;
                let s = after.objects[i].similarity().scale / before.objects[i].similarity().scale;
                if (s / factor - 1.0).abs() > *tol {
                    return Err(format!("'{}' scaled by {s:.3} (wanted {factor})", name(i)));
                }
                Ok(())
            }
            Check::OnTop {
                object,
                support,
                tol,
            } => {
                let (i, j) = (find(object)?, find(support)?);
                let (a, b) = (b1(i), b1(j));
                let c = a.center();
                let over = c.x >= b.min.x - 0.01
                    && c.x <= b.max.x + 0.01
                    && c.z >= b.min.z - 0.01
                    && c.z <= b.max.z + 0.01;
                if (a.min.y - b.max.y).abs() > *tol || !over {
                    return Err(format!("'{}' (bottom {:.3}, centre {}) is not on top of '{}' (top {:.3}, {} to {})", name(i), a.min.y, v3(c), name(j), b.max.y, v3(b.min), v3(b.max)));
                }
                Ok(())
            }
            Check::NextTo {
                object,
                other,
                max_gap,
            } => {
                let (i, j) = (find(object)?, find(other)?);
                let (a, b) = (b1(i), b1(j));
                let o = a.overlap(&b);
                let gap = (-o.x).max(0.0).hypot((-o.z).max(0.0));
                let inside = o.x > 0.02 && o.z > 0.02 && o.y > 0.02;
                let level = o.y > -0.05;
                if inside || gap > *max_gap || !level {
                    return Err(format!(
                        "'{}' is not next to '{}': gap {:.3} m{}{}",
                        name(i),
                        name(j),
                        gap,
                        if inside { ", overlapping" } else { "" },
                        if level { "" } else { ", at another height" }
                    ));
                }
                Ok(())
            }
            Check::Side {
                object,
                other,
                side: (axis, sign),
                max_gap,
            } => {
                let (i, j) = (find(object)?, find(other)?);
                let (a, b) = (b1(i), b1(j));
                let gap = if *sign > 0.0 {
                    a.min[*axis] - b.max[*axis]
                } else {
                    b.min[*axis] - a.max[*axis]
                };
                let across = 2 - axis;
                let overlapping_across =
                    a.max[across] > b.min[across] - 0.05 && a.min[across] < b.max[across] + 0.05;
                if gap < -0.02 || gap > *max_gap || !overlapping_across {
                    return Err(format!(
                        "'{}' is not on that side of '{}': gap {:.3} m along {}, {}",
                        name(i),
                        name(j),
                        gap,
                        ["x", "y", "z"][*axis],
                        if overlapping_across {
                            "facing it"
                        } else {
                            "off to the side"
                        }
                    ));
                }
                Ok(())
            }
            Check::Above { object, other, tol } => {
                let (i, j) = (find(object)?, find(other)?);
                if b1(i).min.y < b1(j).max.y - tol {
                    return Err(format!(
                        "'{}' (bottom {:.3}) is not above '{}' (top {:.3})",
                        name(i),
                        b1(i).min.y,
                        name(j),
                        b1(j).max.y
                    ));
                }
                Ok(())
            }
            Check::Below { object, other, tol } => {
                let (i, j) = (find(object)?, find(other)?);
                if b1(i).max.y > b1(j).min.y + tol
                    && !(b1(i).center().y < b1(j).center().y && overlap_xz(&b1(i), &b1(j)))
                {
                    return Err(format!(
                        "'{}' (top {:.3}) is not below '{}' (bottom {:.3})",
                        name(i),
                        b1(i).max.y,
                        name(j),
                        b1(j).min.y
                    ));
                }
                Ok(())
            }
            Check::Between { object, a, b, tol } => {
                let (i, ja, jb) = (find(object)?, find(a)?, find(b)?);
                let flat = |v: DVec3| glam::DVec2::new(v.x, v.z);
                let (p, pa, pb) = (
                    flat(b1(i).center()),
                    flat(b1(ja).center()),
                    flat(b1(jb).center()),
                );
                let seg = pb - pa;
                let t = if seg.length_squared() > 0.0 {
                    (p - pa).dot(seg) / seg.length_squared()
                } else {
                    0.0
                };
                let off = (p - (pa + seg * t.clamp(0.0, 1.0))).length();
                if !(-0.05..=1.05).contains(&t) || off > *tol {
                    return Err(format!(
                        "'{}' is not between '{}' and '{}' (at {:.2} along, {:.3} m off the line)",
                        name(i),
                        name(ja),
                        name(jb),
                        t,
                        off
                    ));
                }
                Ok(())
            }
            Check::Aligned {
                object,
                other,
                axis,
                tol,
            } => {
                let (i, j) = (find(object)?, find(other)?);
                let d = b1(i).center()[*axis] - b1(j).center()[*axis];
                if d.abs() > *tol {
                    return Err(format!(
                        "'{}' and '{}' are {:.3} m apart along {}",
                        name(i),
                        name(j),
                        d.abs(),
                        ["x", "y", "z"][*axis]
                    ));
                }
                Ok(())
            }
            Check::At {
                object,
                position,
                tol,
            } => {
                let i = find(object)?;
                let p = b1(i).bottom_center();
                for axis in 0..3 {
                    if let Some(want) = position[axis] {
                        if (p[axis] - want).abs() > *tol {
                            return Err(format!(
                                "'{}' is at {} (wanted {})",
                                name(i),
                                v3(p),
                                opt3(position)
                            ));
                        }
                    }
                }
                Ok(())
            }
            Check::Faces {
                object,
                target,
                tol,
            } => {
                let (i, j) = (find(object)?, find(target)?);
                let forward = after.objects[i].world_front();
                let to = b1(j).center() - b1(i).center();
                let (f2, t2) = (
                    glam::DVec2::new(forward.x, forward.z),
                    glam::DVec2::new(to.x, to.z),
                );
                if f2.length() < 1e-9 || t2.length() < 1e-9 {
                    return Err(format!(
                        "'{}' has no horizontal front or '{}' is right above it",
                        name(i),
                        name(j)
                    ));
                }
                let angle = f2.angle_to(t2).to_degrees().abs();
                if angle > *tol {
                    return Err(format!(
                        "'{}' faces {:.0}° away from '{}'",
                        name(i),
                        angle,
                        name(j)
                    ));
                }
                Ok(())
            }
            Check::Distance {
                object,
                other,
                min,
                max,
            } => {
                let (i, j) = (find(object)?, find(other)?);
                let d = (b1(i).center() - b1(j).center()).length();
                if d < *min || d > *max {
                    return Err(format!(
                        "'{}' is {:.3} m from '{}' (wanted {min} to {max})",
                        name(i),
                        d,
                        name(j)
                    ));
                }
                Ok(())
            }
            Check::Unchanged { objects } => {
                let list: Vec<usize> = match objects {
                    Some(list) => list.iter().map(find).collect::<Result<_, _>>()?,
                    None => {
                        let mut named: Vec<usize> = bound.values().copied().collect();
                        for &k in bound.values() {
                            named.extend(before.carried_by(k));
                        }
                        (0..after.objects.len())
                            .filter(|k| !named.contains(k))
                            .collect()
                    }
                };
                for i in list {
                    let (p, q) = (
                        before.objects[i].similarity(),
                        after.objects[i].similarity(),
                    );
                    if (p.translation - q.translation).length() > 1e-6
                        || p.rotation.dot(q.rotation).abs() < 1.0 - 1e-9
                        || (p.scale - q.scale).abs() > 1e-9
                    {
                        return Err(format!("'{}' changed but should not have", name(i)));
                    }
                }
                Ok(())
            }
            Check::NoCollision => {
                let (bb, ab) = (before.world_aabbs(), after.world_aabbs());
                let moved: Vec<usize> = (0..ab.len())
                    .filter(|&i| {
                        (ab[i].min - bb[i].min).length() > 1e-9
                            || (ab[i].max - bb[i].max).length() > 1e-9
                    })
                    .collect();
                let groups: Vec<Vec<usize>> = moved.iter().map(|&i| vec![i]).collect();
                let found =
                    find_collisions(&bb, &ab, &groups, after.floor(), after.bounds.as_ref());
                match found.first() {
                    None => Ok(()),
                    Some(c) => Err(format!(
                        "'{}' collides with {}",
                        after.objects[c.object].name,
                        c.with.describe(after)
                    )),
                }
            }
            Check::Refused { .. } => {
                Err("the edit succeeded, but it should have been refused".to_string())
            }
            Check::Swapped { object, other, tol } => {
                let (i, j) = (find(object)?, find(other)?);
                let (ai, aj) = (b1(i).bottom_center(), b1(j).bottom_center());
                let (bi, bj) = (b0(i).bottom_center(), b0(j).bottom_center());
                if (ai - bj).length() > *tol || (aj - bi).length() > *tol {
                    return Err(format!(
                        "'{}' is {:.3} m from where '{}' was, and '{}' {:.3} m from where '{}' was",
                        name(i),
                        (ai - bj).length(),
                        name(j),
                        name(j),
                        (aj - bi).length(),
                        name(i)
                    ));
                }
                Ok(())
            }
            Check::InsideBounds => {
                let Some(room) = after.bounds else {
                    return Ok(());
                };
                for i in 0..after.objects.len() {
                    let (a, b) = (b1(i), b0(i));
                    let out = |x: &Aabb| {
                        (room.min - x.min)
                            .max(x.max - room.max)
                            .max_element()
                            .max(0.0)
                    };
                    if out(&a) > out(&b) + 1e-3 {
                        return Err(format!(
                            "'{}' sticks {:.3} m out of the room",
                            name(i),
                            out(&a)
                        ));
                    }
                }
                Ok(())
            }
        }
    }
}

struct Fields<'a> {
    map: &'a Map<String, Value>,
    name: &'a str,
}

impl Fields<'_> {
    fn object(&self, key: &str) -> Result<String, String> {
        self.map
            .get(key)
            .and_then(Value::as_str)
            .map(str::to_string)
            .ok_or_else(|| {
                format!(
                    "check '{}' needs \"{key}\": a placeholder or an object name",
                    self.name
                )
            })
    }
    fn number(&self, key: &str, default: f64) -> Result<f64, String> {
        match self.map.get(key) {
            None | Some(Value::Null) => Ok(default),
            Some(v) => v
                .as_f64()
                .filter(|x| !x.is_nan())
                .ok_or_else(|| format!("check '{}': \"{key}\" must be a number", self.name)),
        }
    }
    fn required_number(&self, key: &str) -> Result<f64, String> {
        self.map
            .get(key)
            .and_then(Value::as_f64)
            .ok_or_else(|| format!("check '{}' needs \"{key}\": a number", self.name))
    }
    fn optional_axis(&self, key: &str) -> Result<Option<(usize, f64)>, String> {
        match self.map.get(key) {
            None | Some(Value::Null) => Ok(None),
            Some(Value::String(s)) => axis_of(s).map(Some).ok_or_else(|| {
                format!(
                    "check '{}': unknown axis '{s}': use +x, -x, +y, -y, +z or -z",
                    self.name
                )
            }),
            Some(_) => Err(format!(
                "check '{}': \"{key}\" must be an axis such as \"+x\"",
                self.name
            )),
        }
    }
    fn axis(&self, key: &str) -> Result<(usize, f64), String> {
        self.optional_axis(key)?.ok_or_else(|| {
            format!(
                "check '{}' needs \"{key}\": +x, -x, +y, -y, +z or -z",
                self.name
            )
        })
    }
    fn triple(&self, key: &str) -> Result<Option<[Option<f64>; 3]>, String> {
        match self.map.get(key) {
            None | Some(Value::Null) => Ok(None),
            Some(Value::Array(items)) if items.len() == 3 => {
                let mut out = [None; 3];
                for (k, item) in items.iter().enumerate() {
                    out[k] = match item {
                        Value::Null => None,
                        v => Some(v.as_f64().ok_or_else(|| {
                            format!(
                                "check '{}': \"{key}\"[{k}] must be a number or null",
                                self.name
                            )
                        })?),
                    };
                }
                Ok(Some(out))
            }
            Some(_) => Err(format!(
                "check '{}': \"{key}\" must be [x, y, z] (null for any)",
                self.name
            )),
        }
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

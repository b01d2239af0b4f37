//! A check as a suite writes it (SPEC §6), read by serde: the check's name in `"check"`,
//! its fields beside it, unknown names and fields refused; then the defaults of
//! docs/benchmark.md filled in.

use super::{Check, ObjectRef};
use serde::Deserialize;

/// Why a check cannot be read.
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
pub struct CheckError(#[from] serde_json::Error);

/// A direction along an axis: `+x`, `-y`, `e3` … as (axis, sign).
#[derive(Clone, Copy, Debug)]
struct Axis(usize, f64);

impl<'de> Deserialize<'de> for Axis {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let text = String::deserialize(d)?;
        let t = text.trim().to_lowercase();
        let (sign, name) = match t.strip_prefix('-') {
            Some(rest) => (-1.0, rest),
            None => (1.0, t.trim_start_matches('+')),
        };
        let axis = match name {
            "x" | "e1" => 0,
            "y" | "e2" => 1,
            "z" | "e3" => 2,
            _ => {
                return Err(serde::de::Error::custom(format!(
                    "unknown axis '{}': use +x, -x, +y, -y, +z or -z",
                    text.chars().take(40).collect::<String>()
                )))
            }
        };
        Ok(Self(axis, sign))
    }
}

/// A side of another object.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(rename_all = "lowercase")]
enum Side {
    Left,
    Right,
    Front,
    #[serde(alias = "back")]
    Behind,
}

impl Side {
    fn axis(self) -> (usize, f64) {
        match self {
            Self::Left => (0, -1.0),
            Self::Right => (0, 1.0),
            Self::Front => (2, 1.0),
            Self::Behind => (2, -1.0),
        }
    }
}

/// `"others"` or a list of names.
#[derive(Debug, Deserialize)]
#[serde(untagged)]
enum Objects {
    List(Vec<ObjectRef>),
    Others(OthersWord),
}

#[derive(Debug, Deserialize)]
enum OthersWord {
    #[serde(rename = "others")]
    Others,
}

/// A point or displacement per axis, `null` for any.
type Triple = [Option<f64>; 3];

/// The checks as written, with their defaults not yet filled in.
#[derive(Debug, Deserialize)]
#[serde(tag = "check", rename_all = "snake_case", deny_unknown_fields)]
enum Raw {
    Moved {
        object: ObjectRef,
        delta: Option<Triple>,
        tol: Option<f64>,
    },
    Direction {
        object: ObjectRef,
        axis: Axis,
        min: Option<f64>,
    },
    Rotated {
        object: ObjectRef,
        axis: Option<Axis>,
        degrees: Option<f64>,
        either_sign: Option<bool>,
        tol: Option<f64>,
    },
    Scaled {
        object: ObjectRef,
        factor: f64,
        tol: Option<f64>,
    },
    OnTop {
        object: ObjectRef,
        support: ObjectRef,
        tol: Option<f64>,
    },
    NextTo {
        object: ObjectRef,
        other: ObjectRef,
        max_gap: Option<f64>,
    },
    Side {
        object: ObjectRef,
        other: ObjectRef,
        side: Side,
        max_gap: Option<f64>,
    },
    Above {
        object: ObjectRef,
        other: ObjectRef,
        tol: Option<f64>,
    },
    Below {
        object: ObjectRef,
        other: ObjectRef,
        tol: Option<f64>,
    },
    Between {
        object: ObjectRef,
        a: ObjectRef,
        b: ObjectRef,
        tol: Option<f64>,
    },
    Aligned {
        object: ObjectRef,
        other: ObjectRef,
        axis: Axis,
        tol: Option<f64>,
    },
    At {
        object: ObjectRef,
        position: Triple,
        tol: Option<f64>,
    },
    Faces {
        object: ObjectRef,
        target: ObjectRef,
        tol: Option<f64>,
    },
    Distance {
        object: ObjectRef,
        other: ObjectRef,
        min: Option<f64>,
        max: Option<f64>,
    },
    Unchanged {
        objects: Option<Objects>,
    },
    NoCollision {},
    InsideBounds {},
    Swapped {
        object: ObjectRef,
        other: ObjectRef,
        tol: Option<f64>,
    },
    Refused {
        #[serde(default)]
        mentions: Vec<ObjectRef>,
    },
}

impl Check {
    /// Reads a check from its JSON object; unknown checks and fields are errors, and
    /// missing optional fields take the defaults of docs/benchmark.md.
    ///
    /// # Errors
    /// Not an object, no or an unknown `"check"`, an unknown field, a field of the wrong
    /// type, a missing required field.
    pub fn parse(value: &serde_json::Value) -> Result<Self, CheckError> {
        Ok(Raw::deserialize(value)?.with_defaults())
    }
}

impl Raw {
    fn with_defaults(self) -> Check {
        let or = Option::unwrap_or;
        match self {
            Raw::Moved { object, delta, tol } => Check::Moved {
                object,
                delta: delta.unwrap_or([None; 3]),
                tol: or(tol, 0.05),
            },
            Raw::Direction { object, axis, min } => Check::Direction {
                object,
                axis: (axis.0, axis.1),
                min: or(min, 0.05),
            },
            Raw::Rotated {
                object,
                axis,
                degrees,
                either_sign,
                tol,
            } => Check::Rotated {
                object,
                axis: axis.map_or(1, |a| a.0),
                degrees: or(degrees, 90.0),
                either_sign: either_sign.unwrap_or(false),
                tol: or(tol, 5.0),
            },
            Raw::Scaled {
                object,
                factor,
                tol,
            } => Check::Scaled {
                object,
                factor,
                tol: or(tol, 0.02),
            },
            Raw::At {
                object,
                position,
                tol,
            } => Check::At {
                object,
                position,
                tol: or(tol, 0.05),
            },
            Raw::Unchanged { objects } => Check::Unchanged {
                objects: match objects {
                    Some(Objects::List(list)) => Some(list),
                    Some(Objects::Others(OthersWord::Others)) | None => None,
                },
            },
            Raw::NoCollision {} => Check::NoCollision,
            Raw::InsideBounds {} => Check::InsideBounds,
            Raw::Swapped { object, other, tol } => Check::Swapped {
                object,
                other,
                tol: or(tol, 0.05),
            },
            Raw::Refused { mentions } => Check::Refused { mentions },
            relation => relation.relation_with_defaults(),
        }
    }

    /// [`Raw::with_defaults`] for the checks of where an object ended relative to another.
    fn relation_with_defaults(self) -> Check {
        let or = Option::unwrap_or;
        match self {
            Raw::OnTop {
                object,
                support,
                tol,
            } => Check::OnTop {
                object,
                support,
                tol: or(tol, 0.03),
            },
            Raw::NextTo {
                object,
                other,
                max_gap,
            } => Check::NextTo {
                object,
                other,
                max_gap: or(max_gap, 0.3),
            },
            Raw::Side {
                object,
                other,
                side,
                max_gap,
            } => Check::Side {
                object,
                other,
                side: side.axis(),
                max_gap: or(max_gap, 0.5),
            },
            Raw::Above { object, other, tol } => Check::Above {
                object,
                other,
                tol: or(tol, 0.03),
            },
            Raw::Below { object, other, tol } => Check::Below {
                object,
                other,
                tol: or(tol, 0.03),
            },
            Raw::Between { object, a, b, tol } => Check::Between {
                object,
                a,
                b,
                tol: or(tol, 0.3),
            },
            Raw::Aligned {
                object,
                other,
                axis,
                tol,
            } => Check::Aligned {
                object,
                other,
                axis: axis.0,
                tol: or(tol, 0.05),
            },
            Raw::Faces {
                object,
                target,
                tol,
            } => Check::Faces {
                object,
                target,
                tol: or(tol, 20.0),
            },
            Raw::Distance {
                object,
                other,
                min,
                max,
            } => Check::Distance {
                object,
                other,
                min: or(min, 0.0),
                max: or(max, f64::INFINITY),
            },
            Raw::Moved { .. }
            | Raw::Direction { .. }
            | Raw::Rotated { .. }
            | Raw::Scaled { .. }
            | Raw::At { .. }
            | Raw::Unchanged { .. }
            | Raw::NoCollision {}
            | Raw::InsideBounds {}
            | Raw::Swapped { .. }
            | Raw::Refused { .. } => self.with_defaults(),
        }
    }
}

//! The translator seam: what every translator — the offline one and the language models
//! behind the three prompt systems — takes (a [`Templated`] instruction and the scene) and
//! gives (a [`Translation`]: one [`Answer`] per variable), below both the pipeline and the
//! offline translator so neither depends on the other.

use crate::expr::{Bindings, ObjectBox, Transformation};
use crate::ground::Phrase;
use crate::llm::{Message, Usage};
use crate::scene::Scene;
use serde::Serialize;
use std::time::Duration;

/// An instruction with its object phrases replaced by variables.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Templated {
    /// The instruction as the user wrote it.
    pub instruction: String,
    /// The instruction with variables: `move X1 next to X2`.
    pub query: String,
    /// The objects the variables stand for, in order: `objects[0]` is X1.
    pub objects: Vec<usize>,
    /// The phrases grounded, with the objects they mean and why.
    pub phrases: Vec<Phrase>,
    /// The objects the instruction says must stay where they are ("… but leave the chair
    /// where it is"): bound to no variable; placement neither carries nor moves them.
    pub held: Vec<usize>,
}

impl Templated {
    /// The variable name of the `k`-th bound object (from 0): `X1`, `X2`, ….
    pub fn variable(k: usize) -> String {
        format!("X{}", k + 1)
    }
}

/// A prompt system.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum System {
    /// Shenlong: the model answers in CGA expressions; only the templated query is sent.
    Cga,
    /// After "Language Models as Zero-Shot Trajectory Generators": matrices composed from
    /// templated functions, with the named objects' boxes given as numbers.
    Euclidean,
    /// After NVIDIA Omniverse's AI Room Generator: the named objects' sizes, centres and
    /// Euler angles in, their final centres and Euler angles out.
    Omniverse,
}

impl std::str::FromStr for System {
    type Err = SystemError;

    /// `cga`, `euclidean` or `omniverse` (any case).
    fn from_str(name: &str) -> Result<Self, SystemError> {
        Self::parse(name)
    }
}

/// A prompt system's name that names none.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SystemError {
    /// A name that is not a system's.
    #[error("unknown system '{0}': use cga, euclidean, omniverse")]
    Unknown(String),
    /// A list with no name in it.
    #[error("no prompt system named: use cga, euclidean, omniverse")]
    None,
}

impl System {
    /// All systems.
    pub const ALL: [System; 3] = [System::Cga, System::Euclidean, System::Omniverse];

    /// The name used on the command line and in reports.
    pub fn name(self) -> &'static str {
        match self {
            System::Cga => "cga",
            System::Euclidean => "euclidean",
            System::Omniverse => "omniverse",
        }
    }

    /// The system by name.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|s| s.name() == name.trim().to_lowercase())
    }

    /// [`System::from_name`], with the error a person reads.
    ///
    /// # Errors
    /// An unknown name, with the names there are.
    pub fn parse(name: &str) -> Result<Self, SystemError> {
        Self::from_name(name).ok_or_else(|| SystemError::Unknown(name.chars().take(80).collect()))
    }

    /// Systems named in a list separated by commas (`cga,euclidean`), each once, in order.
    ///
    /// # Errors
    /// An unknown name, or a list that names none.
    pub fn parse_list(text: &str) -> Result<Vec<Self>, SystemError> {
        let mut systems = Vec::new();
        for name in text.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            let system = Self::parse(name)?;
            if !systems.contains(&system) {
                systems.push(system);
            }
        }
        if systems.is_empty() {
            return Err(SystemError::None);
        }
        Ok(systems)
    }
}

/// One variable's answer.
#[derive(Clone, Debug, PartialEq)]
pub struct Answer {
    /// `X1`, `X2`, ….
    pub variable: String,
    /// The object it stands for.
    pub object: usize,
    /// What the model wrote for it (expressions, or the pose as JSON for omniverse).
    pub expressions: Vec<String>,
    /// The transformation, about the object's pivot.
    pub transformation: Transformation,
    /// What the object was put next to or between, when the translator knows it (the
    /// offline translator does; a model's reply does not say): placement refuses to
    /// leave it elsewhere ([`crate::collide::NEXT_TO_MAX_GAP`]).
    pub near: Option<Near>,
}

/// What an object was put near, which placement keeps it near.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Near {
    /// Next to (beside, on a side of) this one.
    Beside(usize),
    /// Between these two.
    Between(usize, usize),
    /// Still resting on this one ("…, keep it on the table").
    On(usize),
    /// Under this one: its footprint over the object's centre, its underside above the
    /// object's top.
    Under(usize),
    /// In this open container: within its walls, on its bottom or on what is in it.
    Inside(usize),
    /// Pushed in towards this object of the scene — an object index, never a variable —
    /// as a chair is pushed in at the table it is drawn up to: it may go under its top.
    PushedUnder(usize),
}

impl Near {
    /// The same relation to other indices (variables → objects).
    #[must_use]
    pub fn map(self, f: impl Fn(usize) -> usize) -> Self {
        match self {
            Self::Beside(t) => Self::Beside(f(t)),
            Self::Between(a, b) => Self::Between(f(a), f(b)),
            Self::On(t) => Self::On(f(t)),
            Self::Under(t) => Self::Under(f(t)),
            Self::Inside(t) => Self::Inside(f(t)),
            Self::PushedUnder(object) => Self::PushedUnder(object),
        }
    }
}

/// The variables of an expression about `objects` of `scene`: `X1`, `X2`, … bound to their
/// world boxes in order, and (an extension) `room` when the scene has bounds.
pub fn bindings(scene: &Scene, objects: &[usize]) -> Bindings {
    let mut bindings = Bindings::new();
    for (k, &i) in objects.iter().enumerate() {
        let o = &scene.objects[i];
        let b = o.world_aabb();
        bindings.bind(
            Templated::variable(k),
            ObjectBox {
                min: b.min,
                max: b.max,
                front: o.world_front(),
            },
        );
    }
    if let Some(room) = scene.bounds {
        bindings.bind(
            "room",
            ObjectBox {
                min: room.min,
                max: room.max,
                // The room faces the viewer.
                front: glam::DVec3::Z,
            },
        );
    }
    bindings
}
/// One request and reply, as the report shows it.
#[derive(Clone, Debug, Serialize)]
pub struct Exchange {
    /// The messages sent.
    pub messages: Vec<Message>,
    /// The reply, or the empty string when the backend failed.
    pub reply: String,
    /// Time the reply took, in milliseconds (0 for a cache hit).
    pub elapsed_ms: f64,
    /// Token counts.
    pub usage: Usage,
    /// What was wrong with the reply, sent back to the model in the next attempt.
    pub error: Option<String>,
    /// Whether the reply came from the cache.
    pub cached: bool,
}

/// The result of translating one instruction.
#[derive(Clone, Debug)]
pub struct Translation {
    /// One answer per variable the reply changes.
    pub answers: Vec<Answer>,
    /// Every exchange, retries included.
    pub exchanges: Vec<Exchange>,
    /// Attempts after the first.
    pub retries: usize,
    /// Whether the valid reply came from the cache.
    pub cache_hit: bool,
    /// Response time, retries included (the paper's measure).
    pub elapsed: Duration,
    /// Which translator answered: `offline`, or the model's name.
    pub answered_by: String,
    /// For a cascade that went to the model: why the offline translator did not answer.
    pub offline_refusal: Option<String>,
    /// What became of the model's replies.
    pub replies: ReplyCounts,
}

/// What became of a model's replies to one instruction, retries included: how many came
/// back, how many parse (the answer could be found and its expressions are well formed),
/// and how many evaluate to a valid `T·R·D` for every variable. The offline translator
/// sends no request and counts none.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, serde::Deserialize)]
pub struct ReplyCounts {
    /// Replies received.
    pub received: usize,
    /// Of which parse.
    pub parsed: usize,
    /// Of which evaluate to a transformation `T·R·D`.
    pub valid: usize,
}

/// Why an instruction could not be translated.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct TranslateError {
    /// One line for the user.
    pub message: String,
    /// Which kind of failure.
    pub kind: TranslateErrorKind,
    /// The replies received before giving up.
    pub replies: ReplyCounts,
}

/// The kinds of translation failure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TranslateErrorKind {
    /// The model or its server failed, or gave no usable answer.
    Model,
    /// The translator could not read the instruction: another (a model after the offline
    /// translator) may.
    NotUnderstood,
    /// Read and refused on its meaning ("put the chair back" with no earlier pose): no
    /// other translator is asked.
    Settled,
}

impl TranslateError {
    fn of(kind: TranslateErrorKind, message: impl Into<String>) -> Self {
        Self {
            message: message.into(),
            kind,
            replies: ReplyCounts::default(),
        }
    }

    /// A model or server failure.
    pub fn model(message: impl Into<String>) -> Self {
        Self::of(TranslateErrorKind::Model, message)
    }

    /// An instruction the translator cannot read.
    pub fn not_understood(message: impl Into<String>) -> Self {
        Self::of(TranslateErrorKind::NotUnderstood, message)
    }

    /// An instruction read and refused on its meaning: no other translator is asked.
    pub fn settled(message: impl Into<String>) -> Self {
        Self::of(TranslateErrorKind::Settled, message)
    }

    /// The same error, with the replies received.
    #[must_use]
    pub fn with_replies(self, replies: ReplyCounts) -> Self {
        Self { replies, ..self }
    }
}

/// Turns templated instructions into transformations.
pub trait Translator: Send + Sync {
    /// The translator's name for reports: `offline`, or the model.
    fn name(&self) -> String;
    /// The prompt system it answers in.
    fn system(&self) -> System;
    /// Translates one instruction.
    fn translate(
        &self,
        templated: &Templated,
        scene: &Scene,
    ) -> Result<Translation, TranslateError>;
}

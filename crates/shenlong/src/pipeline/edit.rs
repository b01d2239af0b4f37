//! An edit end to end: template → translate → apply (with carrying) → resolve collisions,
//! with a report of everything that happened. The scene is changed only when every stage
//! succeeded.

use super::template::Templated;
use super::translate::{Exchange, Translator};
use crate::collide::{self, ResolveOptions};
use crate::ground::{GroundError, Grounder, Reason};
use crate::scene::{AppliedMotion, Scene};
use crate::translate::{Near, ReplyCounts, TranslateErrorKind};
use serde::Serialize;
use std::time::Instant;

/// How an edit runs.
#[derive(Clone, Debug)]
pub struct EditOptions {
    /// Carry the objects resting on a moved object.
    pub carry: bool,
    /// Collision resolution; `None` skips it (`--no-collide`).
    pub collisions: Option<ResolveOptions>,
    /// The objects the user has selected (indices), which "it", "them" or "the
    /// selection" mean when nothing is named before them; empty for none.
    pub selection: Vec<usize>,
    /// The `selection` is what a conversation's last edit moved, not what the user
    /// selected (the reasons say which).
    pub selection_is_last_edit: bool,
}

impl EditOptions {
    /// Carrying what rests on a moved object as `carry` says, collisions resolved with
    /// `collisions` (`None`: not looked for), nothing selected: what every front end asks.
    #[must_use]
    pub fn new(carry: bool, collisions: Option<ResolveOptions>) -> Self {
        Self {
            carry,
            collisions,
            selection: Vec::new(),
            selection_is_last_edit: false,
        }
    }
}

impl Default for EditOptions {
    fn default() -> Self {
        Self {
            carry: true,
            selection: Vec::new(),
            selection_is_last_edit: false,
            collisions: Some(ResolveOptions::default()),
        }
    }
}

/// What an edit did, for people and programs (`--json`).
#[derive(Clone, Debug, Serialize)]
pub struct EditReport {
    /// The instruction as given.
    pub instruction: String,
    /// The instruction with variables.
    pub query: String,
    /// Which object each variable stands for.
    pub bindings: Vec<Binding>,
    /// Each phrase of the instruction that names objects: the objects and why.
    pub grounding: Vec<GroundedPhrase>,
    /// The prompt system.
    pub system: String,
    /// The prompt's version.
    pub prompt_version: String,
    /// The translator: `offline`, the model, or a cascade `offline+MODEL`.
    pub model: String,
    /// Which translator answered: `offline`, or the model's name (for a cascade, the part
    /// that answered).
    pub answered_by: String,
    /// For a cascade that went to the model: why the offline translator did not answer.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub offline_refusal: Option<String>,
    /// What became of the model's replies (received, parsed, valid); zero for offline.
    pub replies: ReplyCounts,
    /// Every request and reply.
    pub exchanges: Vec<Exchange>,
    /// Attempts after the first.
    pub retries: usize,
    /// Whether the answer came from the cache.
    pub cache_hit: bool,
    /// Per changed object: the expressions and the transformation.
    pub objects: Vec<ObjectChange>,
    /// Objects moved to clear collisions.
    pub collisions_resolved: Vec<CollisionReport>,
    /// Overlaps left in place (`--allow-collisions`).
    pub overlaps_remaining: Vec<String>,
    /// Objects carried along with the ones they rest on.
    pub carried: Vec<String>,
    /// Objects the instruction said must stay where they are ("… but leave the chair
    /// where it is"), held in place.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub held: Vec<String>,
    /// Milliseconds per stage.
    pub timings_ms: Timings,
    /// Tokens sent and received, over all exchanges.
    pub tokens: Tokens,
}

/// A variable and its object.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Binding {
    /// `X1`.
    pub variable: String,
    /// The object's name.
    pub object: String,
}

/// A phrase of the instruction and the objects it was read as.
#[derive(Clone, Debug, Serialize)]
pub struct GroundedPhrase {
    /// The phrase as written: `the picture above the sofa`.
    pub phrase: String,
    /// Its byte range in the instruction.
    pub span: [usize; 2],
    /// The objects' names.
    pub objects: Vec<String>,
    /// Their variables.
    pub variables: Vec<String>,
    /// How the phrase was read.
    pub reasons: Vec<Reason>,
}

/// One object's change.
#[derive(Clone, Debug, Serialize)]
pub struct ObjectChange {
    /// `X1`.
    pub variable: String,
    /// The object's name.
    pub object: String,
    /// What the translator wrote.
    pub expressions: Vec<String>,
    /// Translation about the pivot, metres.
    pub translation: [f64; 3],
    /// Rotation, quaternion `[x, y, z, w]`.
    pub rotation: [f64; 4],
    /// The rotation's angle in degrees.
    pub rotation_degrees: f64,
    /// Uniform scale.
    pub scale: f64,
    /// The versor's 32 coefficients.
    pub versor: Vec<f64>,
}

/// One resolved collision.
#[derive(Clone, Debug, Serialize)]
pub struct CollisionReport {
    /// The moved object.
    pub object: String,
    /// Where the edit put it (bottom centre of its box).
    pub requested: [f64; 3],
    /// Where it ended.
    pub resolved: [f64; 3],
    /// The displacement.
    pub displacement: [f64; 3],
    /// What it collided with.
    pub collided_with: Vec<String>,
    /// The object it was lifted onto because nothing on its own level was free, if any.
    pub lifted_onto: Option<String>,
}

/// Stage timings in milliseconds.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Timings {
    /// Grounding and templating.
    pub template: f64,
    /// Translation (the model's response time, retries included).
    pub translate: f64,
    /// Applying the transformations.
    pub apply: f64,
    /// Collision detection and resolution.
    pub collide: f64,
    /// Of which finding the collisions and preparing the search (linear in the scene).
    pub collide_setup: f64,
    /// Of which the search for free placements (what the collision budget bounds).
    pub collide_search: f64,
    /// All of it.
    pub total: f64,
}

/// Token totals.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Tokens {
    /// Sent.
    pub prompt: u64,
    /// Received.
    pub completion: u64,
    /// Whether any count was estimated locally.
    pub estimated: bool,
}

impl EditReport {
    /// The report of an edit that went through: how the instruction was grounded and
    /// templated, what the translator answered, what placing it did, and the timings.
    fn new(
        scene: &Scene,
        templated: &Templated,
        translation: super::translate::Translation,
        translator: &dyn Translator,
        placed: Placed,
        timings: Timings,
    ) -> Self {
        let name = |i: usize| scene.objects[i].name.clone();
        let tokens = translation
            .exchanges
            .iter()
            .fold(Tokens::default(), |mut t, e| {
                t.prompt += e.usage.prompt_tokens;
                t.completion += e.usage.completion_tokens;
                t.estimated |= e.usage.estimated;
                t
            });
        let objects = translation
            .answers
            .iter()
            .map(|a| {
                let s = a.transformation.similarity;
                ObjectChange {
                    variable: a.variable.clone(),
                    object: name(a.object),
                    expressions: a.expressions.clone(),
                    translation: s.translation.to_array(),
                    rotation: s.rotation.to_array(),
                    rotation_degrees: s.rotation.to_axis_angle().1.to_degrees(),
                    scale: s.scale,
                    versor: a.transformation.versor.coefficients().to_vec(),
                }
            })
            .collect();
        let system = translator.system();
        let variable_of = |object: usize| {
            let k = templated
                .objects
                .iter()
                .position(|&o| o == object)
                .expect("every grounded object is bound");
            Templated::variable(k)
        };
        let grounding = templated
            .phrases
            .iter()
            .map(|p| GroundedPhrase {
                phrase: p.text.clone(),
                span: [p.span.start, p.span.end],
                objects: p.objects.iter().map(|&o| name(o)).collect(),
                variables: p.objects.iter().map(|&o| variable_of(o)).collect(),
                reasons: p.reasons.clone(),
            })
            .collect();
        Self {
            instruction: templated.instruction.clone(),
            query: templated.query.clone(),
            bindings: templated
                .objects
                .iter()
                .enumerate()
                .map(|(k, &i)| Binding {
                    variable: Templated::variable(k),
                    object: name(i),
                })
                .collect(),
            grounding,
            system: system.name().into(),
            prompt_version: system.version().into(),
            model: translator.name(),
            answered_by: translation.answered_by,
            offline_refusal: translation.offline_refusal,
            replies: translation.replies,
            exchanges: translation.exchanges,
            retries: translation.retries,
            cache_hit: translation.cache_hit,
            objects,
            collisions_resolved: placed.collisions_resolved,
            overlaps_remaining: placed.overlaps_remaining,
            carried: placed.carried,
            held: templated.held.iter().map(|&o| name(o)).collect(),
            timings_ms: timings,
            tokens,
        }
    }
}

/// Why an edit failed; the scene is unchanged.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EditError {
    /// One line for the user.
    pub message: String,
    /// Which kind of failure.
    pub kind: EditErrorKind,
    /// The model's replies received before the translation failed (none otherwise).
    pub replies: ReplyCounts,
    /// The choice a grounding refusal leaves to the user (the phrase and the objects it
    /// could mean), for a page or program to offer; `None` for other failures.
    pub ambiguity: Option<crate::ground::Ambiguity>,
}

/// The kinds of edit failure, for callers that answer differently (the HTTP API: 4xx for
/// the user's input, 5xx for a model server).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EditErrorKind {
    /// The request itself is malformed: an empty or over-long instruction, an unknown
    /// object given by name (a selection, an expression's binding), an object bound twice.
    BadInput,
    /// Grounding refused the instruction: it names no object, an object the scene lacks,
    /// or a phrase that could mean several (`ambiguity`).
    Instruction,
    /// The translator read the instruction and refused it on its meaning ("put it back"
    /// with no earlier pose), or the expression is not a transformation.
    NotUnderstood,
    /// The translator left words of the instruction unread: another (a language model)
    /// may read them.
    Unread,
    /// A motion beyond what poses hold exactly (a translation of 10²⁰ m).
    Motion,
    /// The model or its server failed, or gave no usable answer.
    Model,
    /// No collision-free placement was found.
    Placement,
    /// The edit cannot be done with what the instruction holds in place where it is.
    Held,
}

impl std::fmt::Display for EditError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for EditError {}

/// The result of a successful edit.
#[derive(Clone, Debug)]
pub struct Edit {
    /// The report.
    pub report: EditReport,
    /// The objects the translator's answers moved (what they carried and what collision
    /// resolution shifted is in the report).
    pub moved: Vec<usize>,
    /// The motions applied, in order: what undo takes back.
    pub motions: Vec<AppliedMotion>,
}

fn ms(since: Instant) -> f64 {
    since.elapsed().as_secs_f64() * 1000.0
}

/// Runs an instruction on the scene. On any error the scene is left as it was.
///
/// Builds the scene's name index for grounding; to run many instructions on one scene,
/// build a [`Grounder`] once and use [`edit_with`].
pub fn edit(
    scene: &mut Scene,
    instruction: &str,
    translator: &dyn Translator,
    options: &EditOptions,
) -> Result<Edit, EditError> {
    let grounder = Grounder::new(scene);
    edit_with(scene, &grounder, instruction, translator, options)
}

/// [`edit`] with a grounder built for this scene (its names; poses may have changed).
pub fn edit_with(
    scene: &mut Scene,
    grounder: &Grounder,
    instruction: &str,
    translator: &dyn Translator,
    options: &EditOptions,
) -> Result<Edit, EditError> {
    let started = Instant::now();
    let mut timings = Timings::default();
    let t0 = Instant::now();
    let templated: Templated = super::template::template_focused(
        grounder,
        instruction,
        scene,
        &options.selection,
        options.selection_is_last_edit,
    )
    .map_err(|e| EditError {
        message: e.to_string(),
        kind: match e {
            GroundError::Empty | GroundError::TooLong { .. } => EditErrorKind::BadInput,
            _ => EditErrorKind::Instruction,
        },
        replies: ReplyCounts::default(),
        ambiguity: e.ambiguity(),
    })?;
    timings.template = ms(t0);

    let t0 = Instant::now();
    let translation = translator
        .translate(&templated, scene)
        .map_err(|e| EditError {
            kind: match e.kind {
                TranslateErrorKind::NotUnderstood => EditErrorKind::Unread,
                TranslateErrorKind::Settled => EditErrorKind::NotUnderstood,
                TranslateErrorKind::Model => EditErrorKind::Model,
            },
            message: e.message,
            replies: e.replies,
            ambiguity: None,
        })?;
    timings.translate = ms(t0);

    // The answers' transformations as the translator split them, T·R·D: not split again.
    let moves: Vec<(usize, cga::Similarity)> = translation
        .answers
        .iter()
        .map(|a| (a.object, a.transformation.similarity))
        .collect();
    let near: Vec<(usize, Near)> = translation
        .answers
        .iter()
        .filter_map(|a| a.near.map(|n| (a.object, n)))
        .collect();
    let mut placed = place_holding(scene, &moves, options, &templated.held, &near)?;
    timings.apply = placed.apply_ms;
    timings.collide = placed.collide_ms;
    timings.collide_setup = placed.collide_setup_ms;
    timings.collide_search = placed.collide_search_ms;
    let moved = std::mem::take(&mut placed.moved);
    let motions = std::mem::take(&mut placed.motions);
    timings.total = ms(started);
    let report = EditReport::new(scene, &templated, translation, translator, placed, timings);
    Ok(Edit {
        report,
        moved,
        motions,
    })
}

/// What placing an edit's motions did to the scene.
#[derive(Clone, Debug)]
pub struct Placed {
    /// The objects moved by the motions themselves.
    pub moved: Vec<usize>,
    /// The motions applied, in order — the edit's and collision resolution's: what undo
    /// takes back ([`Scene::undo`] them last first).
    pub motions: Vec<AppliedMotion>,
    /// Objects carried along with the ones they rest on.
    pub carried: Vec<String>,
    /// Objects moved to clear collisions.
    pub collisions_resolved: Vec<CollisionReport>,
    /// Overlaps left in place (when collisions are allowed).
    pub overlaps_remaining: Vec<String>,
    /// Milliseconds applying the motions.
    pub apply_ms: f64,
    /// Milliseconds resolving collisions (setup and search).
    pub collide_ms: f64,
    /// Of which finding the collisions and preparing the search, linear in the scene.
    pub collide_setup_ms: f64,
    /// Of which searching for free placements (what `--collision-budget` bounds).
    pub collide_search_ms: f64,
}

/// Applies motions to objects of `scene` — each about its object's pivot, carrying what
/// rests on it, supports re-detected around what moved — then resolves collisions. The
/// one way every edit is applied: instructions, expressions from the command line and
/// the server. Every motion is computed against the scene as it was: an object carried by
/// an earlier motion first goes back, then takes its own.
///
/// The world boxes are computed once and the floor grid built once; each motion updates
/// them for the objects it moved, so an edit costs what it moved plus one pass over the
/// scene.
///
/// # Errors
/// A motion beyond the exact range, or no free placement; `scene` is then as it was.
pub fn place(
    scene: &mut Scene,
    moves: &[(usize, cga::Similarity)],
    options: &EditOptions,
) -> Result<Placed, EditError> {
    place_holding(scene, moves, options, &[], &[])
}

/// [`place`] with objects held where they are (what an instruction says must not move):
/// they are not carried, collision resolution does not move them, and the edit is refused
/// when it would move one or take its support from under it. Each `(object, near)` of
/// `near` was put next to or between others: the edit is refused when the nearest free
/// placement left it elsewhere ([`check_near`]).
///
/// # Errors
/// As [`place`], a held object that would move or be left in the air, and an object no
/// longer next to what it was put next to.
pub fn place_holding(
    scene: &mut Scene,
    moves: &[(usize, cga::Similarity)],
    options: &EditOptions,
    held: &[usize],
    near: &[(usize, Near)],
) -> Result<Placed, EditError> {
    let supports: Vec<(Option<usize>, bool)> = scene
        .objects
        .iter()
        .map(|o| (o.support, o.support_from_file))
        .collect();
    let mut motions = Vec::new();
    // What the edit puts under a table, with what rests on it, may stand in the room
    // under its top.
    let under: Vec<(usize, usize)> = near
        .iter()
        .filter_map(|&(o, n)| match n {
            Near::Under(t) | Near::Inside(t) | Near::PushedUnder(t) => Some((o, t)),
            _ => None,
        })
        .flat_map(|(o, t)| {
            std::iter::once(o)
                .chain(scene.carried_by(o))
                .map(move |i| (i, t))
                .collect::<Vec<_>>()
        })
        .collect();
    let result = place_into(scene, moves, options, held, &under, &mut motions)
        .and_then(|placed| check_held(scene, held, &supports, &motions).map(|()| placed))
        .and_then(|placed| {
            // Under something: checked only where collisions are resolved; without (or
            // with collisions allowed) an overlapping place under it is what was asked.
            let resolved = options
                .collisions
                .as_ref()
                .is_some_and(|c| !c.allow_collisions);
            let near: Vec<(usize, Near)> = near
                .iter()
                .copied()
                .filter(|(_, n)| resolved || !matches!(n, Near::Under(_) | Near::Inside(_)))
                .collect();
            check_near(scene, &near).map(|()| placed)
        });
    if result.is_err() {
        for m in motions.iter().rev() {
            scene.undo(m);
        }
        for (o, (support, from_file)) in scene.objects.iter_mut().zip(supports) {
            o.support = support;
            o.support_from_file = from_file;
        }
    }
    result.map(|placed| Placed { motions, ..placed })
}

/// A placement refusal: no free place, or not where it was put.
fn placement_error(message: String) -> EditError {
    EditError {
        message,
        kind: EditErrorKind::Placement,
        replies: ReplyCounts::default(),
        ambiguity: None,
    }
}

/// A placement refusal for a held object.
fn held_error(message: String) -> EditError {
    EditError {
        message,
        kind: EditErrorKind::Held,
        replies: ReplyCounts::default(),
        ambiguity: None,
    }
}

/// How far the centre of an object put between two others may end off the segment
/// between their centres (floor plan), metres: the benchmark's `between` tolerance.
const BETWEEN_TOLERANCE: f64 = 0.3;

/// Refuses a placement that left an object where it was not put: farther from what it was
/// put next to than [`collide::NEXT_TO_MAX_GAP`], off what it was to stay on, or, put
/// between two objects, with its
/// centre not projecting onto the segment between theirs or more than
/// [`BETWEEN_TOLERANCE`] off it —
/// collision resolution found free space only elsewhere. The gap is measured on the floor
/// plan to the other object, or, for an object on the floor, to what the other stands on
/// (a chair put next to a lamp on a desk stands next to the desk).
fn check_near(scene: &Scene, near: &[(usize, Near)]) -> Result<(), EditError> {
    let refuse = placement_error;
    for &(object, near) in near {
        let other = match near {
            Near::Beside(other) => other,
            // Only room to go into, not a place it must end in.
            Near::PushedUnder(_) => continue,
            Near::Under(above) => {
                check_under(scene, object, above)?;
                continue;
            }
            Near::Inside(container) => {
                check_inside(scene, object, container)?;
                continue;
            }
            Near::On(support) => {
                if scene.objects[object].support != Some(support) {
                    return Err(refuse(format!(
                        "'{}' would end off '{}', which it is to stay on",
                        scene.objects[object].name, scene.objects[support].name
                    )));
                }
                continue;
            }
            Near::Between(p, q) => {
                let flat = |i: usize| {
                    let c = scene.objects[i].world_aabb().center();
                    glam::DVec2::new(c.x, c.z)
                };
                let (c, a, b) = (flat(object), flat(p), flat(q));
                let d = b - a;
                let t = (c - a).dot(d) / d.length_squared().max(1e-12);
                let off = (a + d * t.clamp(0.0, 1.0) - c).length();
                if !(-1e-6..=1.0 + 1e-6).contains(&t) || off > BETWEEN_TOLERANCE {
                    return Err(refuse(format!(
                        "no free place for '{}' between '{}' and '{}': the nearest free one is {off:.2} m off the line between them",
                        scene.objects[object].name, scene.objects[p].name, scene.objects[q].name
                    )));
                }
                continue;
            }
        };
        let a = scene.objects[object].world_aabb();
        let on_floor = a.min.y <= scene.floor() + crate::scene::FLOOR_LEVEL;
        let mut gap = f64::INFINITY;
        let mut next = Some(other);
        let mut hops = 0;
        while let Some(j) = next.filter(|_| hops < 8) {
            gap = gap.min(a.floor_gap(&scene.objects[j].world_aabb()));
            // Down the stack only from the floor.
            next = scene.objects[j].support.filter(|_| on_floor);
            hops += 1;
        }
        if gap > collide::NEXT_TO_MAX_GAP {
            return Err(refuse(format!(
                "no free place for '{}' next to '{}': the nearest free one is {gap:.2} m from it",
                scene.objects[object].name, scene.objects[other].name
            )));
        }
    }
    Ok(())
}

/// Whether `object` ended inside `container`: within the walls of an open container, above
/// its bottom, below its rim; on a shelf of a case of shelves, under the shelf above.
fn check_inside(scene: &Scene, object: usize, container: usize) -> Result<(), EditError> {
    use crate::scene::form;
    let a = scene.objects[object].world_aabb();
    let b = scene.objects[container].world_aabb();
    let case_form = crate::ground::kind::form_of(scene, container);
    let shelves = case_form.shelves();
    let inside = if shelves {
        form::clear_shelved(&a, &b, case_form)
    } else {
        form::clear_inside(&a, &b)
    };
    if inside {
        return Ok(());
    }
    let (name, target) = (&scene.objects[object].name, &scene.objects[container].name);
    let size = a.size();
    if shelves {
        let rooms = form::compartments(&b, case_form);
        let fits = rooms
            .iter()
            .any(|room| size.cmple(room.size() + 1e-9).all());
        let room = rooms.first().map_or(b.size(), |r| r.size());
        return Err(placement_error(if fits {
            format!("there is no free room left on the shelves of '{target}' for '{name}'")
        } else {
            format!(
                "'{name}' does not fit on a shelf of '{target}': its shelves are {:.2} × {:.2} m and {:.2} m apart, and '{name}' is {:.2} × {:.2} × {:.2} m",
                room.x, room.z, room.y, size.x, size.y, size.z
            )
        }));
    }
    let room = form::inside(&b).size();
    Err(placement_error(if size.cmple(room).all() {
        format!("there is no free room left in '{target}' for '{name}'")
    } else {
        format!(
            "'{name}' does not fit in '{target}': its inside is {:.2} × {:.2} × {:.2} m, and '{name}' is {:.2} × {:.2} × {:.2} m",
            room.x, room.y, room.z, size.x, size.y, size.z
        )
    }))
}

/// The objects' kinds as the lexicon says them, for collision resolution: floor furniture,
/// tops on legs, open containers and chairs (`ground::kind`, `scene::form`).
pub struct Lexical<'a> {
    /// (object, target) pairs where the edit put the object under or in the target.
    under: &'a [(usize, usize)],
    /// Each object's seat and back, once looked up.
    seats: std::cell::RefCell<rustc_hash::FxHashMap<usize, Option<crate::scene::Seat>>>,
}

impl<'a> Lexical<'a> {
    /// The kinds for an edit that put each `(object, target)` of `under` under or in the
    /// target.
    #[must_use]
    pub fn new(under: &'a [(usize, usize)]) -> Self {
        Self {
            under,
            seats: std::cell::RefCell::default(),
        }
    }
}

impl collide::Kinds for Lexical<'_> {
    fn floor_bound(&self, scene: &Scene, i: usize) -> bool {
        crate::ground::kind::is_floor_bound(scene, i)
    }

    fn room(&self, scene: &Scene, i: usize, j: usize) -> Option<crate::scene::Room> {
        if self.under.contains(&(i, j)) {
            return crate::ground::kind::room_of(scene, i, j);
        }
        // A chair shares any other box with its seat and back only; it goes under or in
        // only what the edit put it under or in.
        let seat = *self
            .seats
            .borrow_mut()
            .entry(i)
            .or_insert_with(|| crate::ground::kind::seat_of(scene, i));
        seat.map(|seat| crate::scene::Room {
            form: crate::scene::Form::Solid,
            seat: Some(seat),
        })
    }
}

/// Whether `object` ended under `above`: its centre within `above`'s footprint and its
/// top no higher than `above`'s underside (what rests on the floor under a table top).
/// Every object is a box from its bottom up here, so under furniture that stands on the
/// floor there is no room: the nearest free place is beside it, and that is refused
/// rather than done.
fn check_under(scene: &Scene, object: usize, above: usize) -> Result<(), EditError> {
    let a = scene.objects[object].world_aabb();
    let b = scene.objects[above].world_aabb();
    let c = a.center();
    let over = c.x >= b.min.x && c.x <= b.max.x && c.z >= b.min.z && c.z <= b.max.z;
    let shared = crate::ground::kind::room_of(scene, object, above).filter(|r| r.form.on_legs());
    let on_legs = shared.is_some();
    // Below its bottom, in the room under its top (a chair's seat under it, its back
    // out), or flat (a rug under a bed).
    let under = a.max.y <= b.min.y + 1e-6
        || shared.is_some_and(|r| crate::scene::form::clear_in(&a, &b, r))
        || a.size().y <= crate::scene::FLOOR_LEVEL;
    // What must fit in the room under the top: a chair's seat, else all of it.
    let height = shared
        .and_then(|r| r.seat)
        .map_or(a.size().y, |seat| seat.height);
    if over && under {
        return Ok(());
    }
    let (name, target) = (&scene.objects[object].name, &scene.objects[above].name);
    let room = match shared {
        Some(r) => crate::scene::form::knee_room(&b, r.form),
        None => b.min.y - scene.floor(),
    };
    Err(placement_error(if on_legs && height > room {
        format!(
            "'{name}' cannot go under '{target}': there is {room:.2} m under its top, and '{name}' is {height:.2} m tall{}",
            if height < a.size().y { " to its seat" } else { "" }
        )
    } else if shared.is_some_and(|r| r.seat.is_some()) {
        format!(
            "'{name}' cannot be tucked under '{target}': its back would meet the top; turn it to face '{target}' first"
        )
    } else if on_legs {
        format!(
            "'{name}' cannot go under '{target}': it does not fit between its legs ({:.2} × {:.2} m, and '{name}' is {:.2} × {:.2} m)",
            b.size().x,
            b.size().z,
            a.size().x,
            a.size().z
        )
    } else if room > crate::scene::FLOOR_LEVEL {
        format!(
            "'{name}' cannot go under '{target}': there is {room:.2} m under it, and '{name}' is {:.2} m tall",
            a.size().y
        )
    } else {
        format!(
            "'{name}' cannot go under '{target}': Shenlong sees '{target}' as a solid box down to the floor, so there is no room under it; put it beside or on it"
        )
    }))
}

/// Refuses a placement that moved a held object or left one in the air (its support
/// moved from under it).
fn check_held(
    scene: &Scene,
    held: &[usize],
    supports: &[(Option<usize>, bool)],
    motions: &[AppliedMotion],
) -> Result<(), EditError> {
    for &h in held {
        let name = &scene.objects[h].name;
        if motions.iter().any(|m| m.objects().any(|o| o == h)) {
            return Err(held_error(format!(
                "'{name}' is to stay where it is, but the edit would move it"
            )));
        }
        let Some(support) = supports[h].0 else {
            continue;
        };
        if scene.hangs(h) {
            return Err(held_error(format!(
                "'{name}' is to stay where it is, but '{}' would move from under it",
                scene.objects[support].name
            )));
        }
    }
    Ok(())
}

fn place_into(
    scene: &mut Scene,
    moves: &[(usize, cga::Similarity)],
    options: &EditOptions,
    held: &[usize],
    under: &[(usize, usize)],
    motions: &mut Vec<AppliedMotion>,
) -> Result<Placed, EditError> {
    let t0 = Instant::now();
    if let Some(&(object, _)) = moves.iter().find(|(o, _)| held.contains(o)) {
        return Err(held_error(format!(
            "'{}' is named both to move and to stay where it is",
            scene.objects[object].name
        )));
    }
    let mut boxes = EditBoxes::new(scene);
    let (moved, carried) = apply_moves(scene, moves, options.carry, held, &mut boxes, motions)?;
    let apply_ms = ms(t0);
    let t0 = Instant::now();
    let resolved = match &options.collisions {
        Some(resolve_options) => {
            let kinds = Lexical::new(under);
            resolve_collisions(scene, &moved, resolve_options, &kinds, &mut boxes, motions)?
        }
        None => Resolved::default(),
    };
    Ok(Placed {
        moved,
        motions: Vec::new(),
        carried,
        collisions_resolved: resolved.collisions_resolved,
        overlaps_remaining: resolved.overlaps_remaining,
        apply_ms,
        collide_ms: ms(t0),
        collide_setup_ms: resolved.setup_ms,
        collide_search_ms: resolved.search_ms,
    })
}

/// The world boxes of an edit being placed: as they were, as they are now (with a floor
/// grid over them, both kept up to date), and which objects hung when the edit began (a
/// whiteboard never comes to rest on what moves under it).
struct EditBoxes {
    before: Vec<crate::geometry::Aabb>,
    now: Vec<crate::geometry::Aabb>,
    grid: crate::geometry::FloorGrid,
    hung: Vec<bool>,
}

impl EditBoxes {
    fn new(scene: &Scene) -> Self {
        let before = scene.world_aabbs();
        let hung = before
            .iter()
            .enumerate()
            .map(|(i, b)| scene.hangs_at(i, b))
            .collect();
        let now = before.clone();
        let grid = crate::geometry::FloorGrid::new(&now);
        Self {
            before,
            now,
            grid,
            hung,
        }
    }

    /// Brings the boxes of the objects `motion` moved up to date; those objects.
    fn update(&mut self, scene: &Scene, motion: &AppliedMotion) -> Vec<usize> {
        let changed: Vec<usize> = motion.objects().collect();
        for &i in &changed {
            let old = self.now[i];
            self.now[i] = scene.objects[i].world_aabb();
            self.grid.update(i, &old, &self.now[i]);
        }
        changed
    }

    /// Re-detects what rests on what around the objects `changed`.
    fn resupport(&self, scene: &mut Scene, changed: &[usize]) {
        scene.detect_supports_around(&self.now, &self.grid, changed, &self.hung);
    }
}

/// Applies each motion about its object's pivot, carrying what rests on it (unless
/// `carry` is off; never what is held); every motion computed against the scene as it
/// was, so an object carried by an earlier motion first goes back, then takes its own.
/// The objects moved, and the names of those carried.
fn apply_moves(
    scene: &mut Scene,
    moves: &[(usize, cga::Similarity)],
    carry: bool,
    held: &[usize],
    boxes: &mut EditBoxes,
    motions: &mut Vec<AppliedMotion>,
) -> Result<(Vec<usize>, Vec<String>), EditError> {
    let mut moved = Vec::new();
    let mut carried = Vec::new();
    // World motion each object has picked up so far in this edit by being carried.
    let mut carried_motion: Vec<Option<cga::Similarity>> = vec![None; scene.objects.len()];
    for &(object, ref step) in moves {
        if let Some(w) = carried_motion[object].take() {
            // It goes back with what it carries now, as its own motion will carry it: a
            // box on it that took its own motion already stays where that put it ("the
            // shelf and everything on it", in any order).
            let mut group = vec![object];
            if carry {
                group.extend(scene.carried_by_except(object, held));
            }
            let back = scene.apply_world(&group, &w.inverse());
            for m in back.moves.iter().filter(|m| m.object != object) {
                let so_far = carried_motion[m.object].unwrap_or(cga::Similarity::IDENTITY);
                carried_motion[m.object] = Some(m.world * so_far);
            }
            boxes.update(scene, &back);
            motions.push(back);
        }
        let motion = scene
            .move_holding(object, step, carry, held)
            .map_err(|e| EditError {
                message: e.to_string(),
                kind: EditErrorKind::Motion,
                replies: ReplyCounts::default(),
                ambiguity: None,
            })?;
        for m in &motion.moves {
            if m.object != object {
                let so_far = carried_motion[m.object].unwrap_or(cga::Similarity::IDENTITY);
                carried_motion[m.object] = Some(m.world * so_far);
            }
        }
        for i in motion.objects().filter(|&i| i != object) {
            if !carried.contains(&scene.objects[i].name) {
                carried.push(scene.objects[i].name.clone());
            }
        }
        moved.push(object);
        let changed = boxes.update(scene, &motion);
        motions.push(motion);
        // The moved object rests wherever it was put now, not on its old support: a later
        // motion that moves the old support must not carry it back.
        scene.objects[object].support_from_file = false;
        boxes.resupport(scene, &changed);
    }
    Ok((moved, carried))
}

/// What collision resolution did, as the report says it.
#[derive(Default)]
struct Resolved {
    collisions_resolved: Vec<CollisionReport>,
    overlaps_remaining: Vec<String>,
    setup_ms: f64,
    search_ms: f64,
}

/// Moves each colliding group to the nearest free placement ([`collide::resolve_with`]);
/// refuses a resolution that would quietly undo the whole move.
fn resolve_collisions(
    scene: &mut Scene,
    moved: &[usize],
    resolve_options: &ResolveOptions,
    kinds: &Lexical<'_>,
    boxes: &mut EditBoxes,
    motions: &mut Vec<AppliedMotion>,
) -> Result<Resolved, EditError> {
    let placement = |message: String| EditError {
        message,
        kind: EditErrorKind::Placement,
        replies: ReplyCounts::default(),
        ambiguity: None,
    };
    let resolution = collide::resolve_with(
        scene,
        collide::Boxes {
            before: &boxes.before,
            after: &mut boxes.now,
            grid: &mut boxes.grid,
        },
        moved,
        kinds,
        resolve_options,
    )
    .map_err(|e| placement(e.to_string()))?;
    let changed: Vec<usize> = resolution.motion.objects().collect();
    motions.push(resolution.motion.clone());
    let mut resolved = Resolved {
        setup_ms: resolution.setup_ms,
        search_ms: resolution.search_ms,
        ..Resolved::default()
    };
    for a in &resolution.adjustments {
        let describe = |obstacles: &[collide::Obstacle]| -> Vec<String> {
            obstacles.iter().map(|o| o.describe(scene)).collect()
        };
        // Resolution that undoes the whole move leaves a silent no-op: say so instead.
        let start = boxes.before[a.object].bottom_center();
        let wanted = (a.requested - start).length();
        if wanted > 0.02 && (a.resolved - start).length() < 0.01 {
            return Err(placement(format!(
                "'{}' cannot go there: it collides with {}, and the nearest free place is where it already is",
                scene.objects[a.object].name,
                describe(&a.collided_with).join(", ")
            )));
        }
        resolved.collisions_resolved.push(CollisionReport {
            object: scene.objects[a.object].name.clone(),
            requested: a.requested.to_array(),
            resolved: a.resolved.to_array(),
            displacement: a.displacement.to_array(),
            collided_with: describe(&a.collided_with),
            lifted_onto: a.lifted_onto.map(|j| scene.objects[j].name.clone()),
        });
    }
    for o in &resolution.remaining {
        resolved.overlaps_remaining.push(format!(
            "'{}' overlaps {}",
            scene.objects[o.object].name,
            o.with.describe(scene)
        ));
    }
    if !changed.is_empty() {
        boxes.resupport(scene, &changed);
    }
    Ok(resolved)
}

/// Applies one CGA expression to one object (it is X1; `room` is bound when the scene has
/// bounds), through [`place`]: on an error the scene is as it was.
///
/// # Errors
/// An unknown object, an expression that is not a transformation, or what [`place`]
/// refuses.
pub fn apply_expression(
    scene: &mut Scene,
    object: &str,
    expression: &str,
    options: &EditOptions,
) -> Result<(Placed, crate::expr::Transformation), EditError> {
    apply_expression_bound(scene, &[object], expression, options)
}

/// [`apply_expression`] with more objects bound: `objects[0]` is X1, the object moved;
/// `objects[1]` is X2, and so on, whose boxes the expression may use
/// (`T(((X2.max | e2) - (X1.min | e2)) * e2)` puts X1 on X2).
///
/// # Errors
/// As [`apply_expression`]; also no object, or one named twice.
pub fn apply_expression_bound(
    scene: &mut Scene,
    objects: &[&str],
    expression: &str,
    options: &EditOptions,
) -> Result<(Placed, crate::expr::Transformation), EditError> {
    let instruction = |message: String| EditError {
        message,
        kind: EditErrorKind::BadInput,
        replies: ReplyCounts::default(),
        ambiguity: None,
    };
    if objects.is_empty() {
        return Err(instruction("name the object to move (X1)".into()));
    }
    let mut indices = Vec::with_capacity(objects.len());
    for name in objects {
        let index = scene
            .resolve(name)
            .map_err(|e| instruction(e.to_string()))?;
        if indices.contains(&index) {
            return Err(instruction(format!(
                "'{}' is bound twice: each variable names a different object",
                scene.objects[index].name
            )));
        }
        indices.push(index);
    }
    let bindings = super::bindings(scene, &indices);
    let t = crate::expr::evaluate_transformation(expression, &bindings).map_err(|e| EditError {
        message: e.to_string(),
        kind: EditErrorKind::NotUnderstood,
        replies: ReplyCounts::default(),
        ambiguity: None,
    })?;
    Ok((place(scene, &[(indices[0], t.similarity)], options)?, t))
}

#[cfg(test)]
mod place_tests {
    use super::*;
    use crate::scene::Object;
    use glam::DVec3;

    fn room() -> Scene {
        let mut s = Scene::new("t");
        s.push_box("table", [1.0, 0.8, 1.0], [0.0, 0.0, 0.0]);
        s.push_box("cup", [0.1, 0.1, 0.1], [0.0, 0.8, 0.0]);
        s.push_box("wall block", [0.5, 2.0, 20.0], [3.0, 0.0, 0.0]);
        s.detect_supports();
        s
    }

    fn options() -> EditOptions {
        EditOptions {
            carry: true,
            collisions: Some(ResolveOptions {
                radius: 0.5,
                ..ResolveOptions::default()
            }),
            ..EditOptions::default()
        }
    }

    #[test]
    fn what_hangs_is_not_carried_by_what_moves_under_it_but_a_lamp_finds_its_new_table() {
        // A whiteboard on the wall, its bottom at a chair's height; two side tables, a lamp
        // on the first.
        let mut s = Scene::new("t");
        let board = s.push_box("whiteboard", [1.8, 1.1, 0.03], [0.0, 1.1, -2.0]);
        let chair = s.push_box("chair", [0.6, 1.1, 0.6], [2.0, 0.0, 0.0]);
        let left = s.push_box("left table", [0.5, 0.6, 0.5], [-2.0, 0.0, 1.0]);
        let right = s.push_box("right table", [0.5, 0.6, 0.5], [2.0, 0.0, 2.0]);
        let lamp = s.push_box("lamp", [0.2, 0.4, 0.2], [-2.0, 0.6, 1.0]);
        s.detect_supports();
        // The chair right under the board's bottom edge: touching, not carrying.
        let under = cga::Similarity::translation(DVec3::new(-2.0, 0.0, -1.7));
        place(&mut s, &[(chair, under)], &EditOptions::default()).unwrap();
        assert_eq!(s.objects[board].support, None);
        // The tables swapped with the lamp held: it now stands on the right table.
        let swap = [
            (
                left,
                cga::Similarity::translation(DVec3::new(4.0, 0.0, 1.0)),
            ),
            (
                right,
                cga::Similarity::translation(DVec3::new(-4.0, 0.0, -1.0)),
            ),
        ];
        place_holding(&mut s, &swap, &EditOptions::default(), &[lamp], &[]).unwrap();
        assert_eq!(s.objects[lamp].support, Some(right));
    }

    #[test]
    fn a_failed_placement_leaves_the_scene_as_it_was() {
        let mut scene = room();
        let poses: Vec<_> = scene.objects.iter().map(Object::similarity).collect();
        let supports: Vec<_> = scene.objects.iter().map(|o| o.support).collect();
        assert_eq!(supports[1], Some(0));
        // Into the middle of the wall block, with no free place within 0.5 m.
        let m = cga::Similarity::translation(DVec3::new(3.0, 0.0, 0.0));
        let e = place(&mut scene, &[(0, m)], &options()).unwrap_err();
        assert_eq!(e.kind, EditErrorKind::Placement, "{e}");
        let after: Vec<_> = scene.objects.iter().map(Object::similarity).collect();
        assert_eq!(after, poses);
        let now: Vec<_> = scene.objects.iter().map(|o| o.support).collect();
        assert_eq!(now, supports);
        // A motion beyond the limits is refused the same way.
        let far = cga::Similarity::translation(DVec3::new(5e6, 0.0, 0.0));
        assert!(place(&mut scene, &[(1, far)], &options()).is_err());
        let after: Vec<_> = scene.objects.iter().map(Object::similarity).collect();
        assert_eq!(after, poses);
    }

    #[test]
    fn a_cup_taken_off_the_table_is_not_carried_by_it_later() {
        let mut scene = room();
        let off = cga::Similarity::translation(DVec3::new(1.5, -0.8, 0.0));
        place(&mut scene, &[(1, off)], &options()).unwrap();
        assert_eq!(
            scene.objects[1].support, None,
            "the cup is on the floor now"
        );
        let cup = scene.objects[1].world_aabb();
        place(
            &mut scene,
            &[(0, cga::Similarity::translation(DVec3::new(0.0, 0.0, -1.0)))],
            &options(),
        )
        .unwrap();
        assert_eq!(scene.objects[1].world_aabb(), cup, "the cup stayed");
        // And one put back on the table is carried again.
        let back = cga::Similarity::translation(DVec3::new(-1.5, 0.8, -1.0));
        place(&mut scene, &[(1, back)], &options()).unwrap();
        assert_eq!(scene.objects[1].support, Some(0));
    }
}

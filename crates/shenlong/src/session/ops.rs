//! The operations that change a session's scene — edit by instruction, apply an
//! expression — run in one of two ways with one result:
//! - in place ([`Session::edit`], [`Session::apply`]): the edit changes the scene itself
//!   and, on any error, leaves it exactly as it was (`pipeline::place` undoes every motion
//!   it applied); undo records the motions' objects as they were — no copy of the scene;
//! - on a working copy ([`Session::working`], then [`Working::edit`] or
//!   [`Working::apply`] away from any lock, then [`Session::land`]): what a server does so
//!   that reads go on while a language model thinks.

use super::conversation::{self, Context, Edited, Plan};
use super::error::{ErrorKind, OpError};
use super::outcome::{self, How, Moved, Operation, Outcome, Pose, Understood};
use super::{diff, Session};
use crate::ground::Grounder;
use crate::pipeline::{Binding, EditOptions, EditReport, Translator};
use crate::scene::{AppliedMotion, Object, Scene};
use std::collections::BTreeMap;
use std::sync::Arc;

/// What an edit asks for, besides how it runs ([`EditOptions`]).
#[derive(Clone, Copy, Debug, Default)]
pub struct EditRequest<'a> {
    /// The instruction, in words.
    pub instruction: &'a str,
    /// The objects the user has selected, by name: what "it" and "them" mean when
    /// nothing is named before them.
    pub selected: &'a [String],
    /// Answer the whole edit report with the outcome.
    pub report: bool,
}

/// A CGA expression to apply: `objects[0]` is X1, the object moved; the others are X2,
/// X3 … whose boxes the expression may use.
#[derive(Clone, Copy, Debug)]
pub struct ApplyRequest<'a> {
    /// The objects bound, by name, X1 first.
    pub objects: &'a [String],
    /// The expression.
    pub expression: &'a str,
}

/// A copy of the session's scene to run one operation on, away from the session (and any
/// lock around it); [`Session::conclude`] swaps its result in.
pub struct Working {
    scene: Scene,
    grounder: Arc<Grounder>,
    context: Context,
    /// The objects the latest change changed, as they were before it: what a correction
    /// ("no, the other one") takes back first.
    previous: Option<Vec<(usize, Object)>>,
}

/// A finished operation on a working copy, not yet in the session.
pub struct Pending(Then);

/// What landing a finished operation does.
enum Then {
    /// Make this scene the session's (after taking the latest change back, with
    /// `undo_first`).
    Land {
        scene: Scene,
        done: Box<Done>,
        undo_first: bool,
    },
    /// Take the latest change back.
    Undo,
}

/// What an operation did, besides the scene it left.
struct Done {
    operation: Operation,
    text: String,
    /// The objects the operation moved itself.
    moved: Vec<usize>,
    carried: Vec<String>,
    understood: Understood,
    notes: Vec<String>,
    report: Option<Box<EditReport>>,
    /// What the next turn may lean on: the instruction as run and its phrases.
    turn: Edited,
    /// A repeat of the last motions: the instruction they came from stays the one to
    /// lean on.
    repeats: bool,
}

/// The objects `selected` names, by index.
fn selection(scene: &Scene, request: &EditRequest<'_>) -> Result<Vec<usize>, OpError> {
    request
        .selected
        .iter()
        .map(|name| {
            scene
                .resolve(name)
                .map_err(|e| OpError::new(ErrorKind::BadInput, format!("selected: {e}")))
        })
        .collect()
}

/// Runs a plan other than an undo on `scene` (on an error, it is as it was); what it did
/// and the motions it applied.
fn run(
    scene: &mut Scene,
    grounder: &Grounder,
    plan: Plan,
    request: &EditRequest<'_>,
    translator: &dyn Translator,
    options: &EditOptions,
) -> Result<(Done, Vec<AppliedMotion>), OpError> {
    match plan {
        Plan::Edit {
            instruction,
            focus,
            from_last,
            ..
        } => {
            let options = EditOptions {
                selection_is_last_edit: from_last,
                ..options.clone()
            };
            edit(
                scene,
                grounder,
                &instruction,
                focus,
                request,
                translator,
                &options,
            )
        }
        Plan::Motions(moves) => motions(scene, &moves, request.instruction, options),
        Plan::Restore { states, named } => restore(scene, states, named, request.instruction),
        Plan::Undo => Err(OpError::new(
            ErrorKind::Internal,
            "an undo is not run as an edit",
        )),
    }
}

/// Runs an instruction on `scene` (on an error, it is as it was) with `focus` as what
/// "it" means; what it did and the motions it applied.
fn edit(
    scene: &mut Scene,
    grounder: &Grounder,
    instruction: &str,
    focus: Vec<usize>,
    request: &EditRequest<'_>,
    translator: &dyn Translator,
    options: &EditOptions,
) -> Result<(Done, Vec<AppliedMotion>), OpError> {
    // "It" with nothing edited or selected, and no object named before it in the
    // instruction ("put the lamp on the table and turn it" names one; "put that on the
    // sofa" does not).
    if let (true, Some(pronoun)) = (
        focus.is_empty(),
        crate::ground::selection_words(instruction),
    ) {
        let unpointed = match grounder.ground(instruction, scene) {
            Err(crate::ground::GroundError::NoObject { .. }) => true,
            Ok(g) => g.phrases.iter().all(|p| p.span.start > pronoun.start),
            Err(_) => false,
        };
        if unpointed {
            return Err(conversation::nothing_before(instruction));
        }
    }
    let options = EditOptions {
        selection: focus,
        ..options.clone()
    };
    let made = crate::pipeline::edit_with(scene, grounder, instruction, translator, &options)
        .map_err(|e| OpError {
            refused: Some(instruction.trim().to_string()),
            ..OpError::from_edit(e, instruction)
        })?;
    let r = &made.report;
    let done = Done {
        operation: Operation::Edit,
        text: request.instruction.to_string(),
        moved: made.moved,
        carried: r.carried.clone(),
        understood: Understood {
            query: r.query.clone(),
            bindings: r.bindings.clone(),
        },
        notes: outcome::notes(&r.collisions_resolved, &r.overlaps_remaining, &r.held),
        turn: Edited {
            instruction: Some(r.instruction.trim().to_string()),
            phrases: r
                .grounding
                .iter()
                .map(|g| {
                    let objects = g.objects.iter().filter_map(|n| scene.find(n)).collect();
                    (g.span[0]..g.span[1], objects)
                })
                .collect(),
            ..Edited::default()
        },
        repeats: false,
        report: request.report.then(|| Box::new(made.report)),
    };
    Ok((done, made.motions))
}

/// The variables X1, X2 … for `objects`.
fn bindings_of(scene: &Scene, objects: &[usize]) -> Vec<Binding> {
    objects
        .iter()
        .enumerate()
        .map(|(k, &i)| Binding {
            variable: crate::translate::Templated::variable(k),
            object: scene.objects[i].name.clone(),
        })
        .collect()
}

/// Applies motions (a repeat of the last ones) to `scene` through placement.
fn motions(
    scene: &mut Scene,
    moves: &[(usize, cga::Similarity)],
    text: &str,
    options: &EditOptions,
) -> Result<(Done, Vec<AppliedMotion>), OpError> {
    let placed =
        crate::pipeline::place(scene, moves, options).map_err(|e| OpError::from_edit(e, text))?;
    let acted: Vec<usize> = moves.iter().map(|m| m.0).collect();
    let done = Done {
        operation: Operation::Edit,
        text: text.to_string(),
        moved: placed.moved,
        carried: placed.carried,
        understood: Understood {
            query: text.trim().to_string(),
            bindings: bindings_of(scene, &acted),
        },
        notes: outcome::notes(&placed.collisions_resolved, &placed.overlaps_remaining, &[]),
        report: None,
        turn: Edited::default(),
        repeats: true,
    };
    Ok((done, placed.motions))
}

/// Puts objects back in earlier states; refused when one would now overlap another.
fn restore(
    scene: &mut Scene,
    states: Vec<(usize, Object)>,
    named: usize,
    text: &str,
) -> Result<(Done, Vec<AppliedMotion>), OpError> {
    let boxes_before = scene.world_aabbs();
    let supports: Vec<Option<usize>> = states
        .iter()
        .map(|(i, _)| scene.objects[*i].support)
        .collect();
    let mut applied = Vec::new();
    for (i, state) in &states {
        let world = state
            .similarity()
            .compose(&scene.objects[*i].similarity().inverse());
        applied.push(scene.apply_world(&[*i], &world));
        scene.objects[*i].support = state.support;
    }
    let group: Vec<usize> = states.iter().map(|s| s.0).collect();
    let found = crate::collide::find_collisions(
        &boxes_before,
        &scene.world_aabbs(),
        std::slice::from_ref(&group),
        scene.floor(),
        scene.bounds.as_ref(),
        // Back where it stood: under a table or in a box too, if it stood there.
        &|i, j| crate::ground::kind::room_of(scene, i, j),
    );
    let taken = found.iter().find_map(|o| match o.with {
        crate::collide::Obstacle::Object(j) => Some((o.object, j)),
        _ => None,
    });
    if let Some((object, j)) = taken {
        let message = format!(
            "'{}' cannot go back where it was: '{}' stands there now",
            scene.objects[object].name, scene.objects[j].name
        );
        for m in applied.iter().rev() {
            scene.undo(m);
        }
        for ((i, _), support) in states.iter().zip(supports) {
            scene.objects[*i].support = support;
        }
        return Err(OpError::new(ErrorKind::NoFreePlace, message));
    }
    let done = Done {
        operation: Operation::Edit,
        text: text.to_string(),
        moved: group[..named].to_vec(),
        carried: group[named..]
            .iter()
            .map(|&i| scene.objects[i].name.clone())
            .collect(),
        understood: Understood {
            query: text.trim().to_string(),
            bindings: bindings_of(scene, &group[..named]),
        },
        notes: Vec::new(),
        report: None,
        turn: Edited::default(),
        repeats: false,
    };
    Ok((done, applied))
}

/// Applies an expression to `scene` (on an error, it is as it was); what it did and the
/// motions it applied.
fn apply(
    scene: &mut Scene,
    request: &ApplyRequest<'_>,
    options: &EditOptions,
) -> Result<(Done, Vec<AppliedMotion>), OpError> {
    let names: Vec<&str> = request.objects.iter().map(String::as_str).collect();
    let (placed, _) =
        crate::pipeline::apply_expression_bound(scene, &names, request.expression, options)
            .map_err(|e| OpError::from_edit(e, request.expression))?;
    let bindings = names
        .iter()
        .enumerate()
        .map(|(k, name)| Binding {
            variable: crate::translate::Templated::variable(k),
            // The name as the scene spells it (the request may differ in case).
            object: scene
                .find(name)
                .map_or_else(|| (*name).to_string(), |i| scene.objects[i].name.clone()),
        })
        .collect();
    let done = Done {
        operation: Operation::Apply,
        text: format!("{}: {}", names[0], request.expression),
        moved: placed.moved,
        carried: placed.carried,
        understood: Understood {
            query: request.expression.to_string(),
            bindings,
        },
        notes: outcome::notes(&placed.collisions_resolved, &placed.overlaps_remaining, &[]),
        report: None,
        turn: Edited::default(),
        repeats: false,
    };
    Ok((done, placed.motions))
}

impl Working {
    /// The scene being worked on.
    #[must_use]
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// Runs an instruction: a new one, or a follow-up of the turn before
    /// ([docs/conversation.md](../../docs/conversation.md)).
    ///
    /// # Errors
    /// An unknown selected object; a follow-up with nothing to lean on; whatever the edit
    /// refuses ([`OpError::from_edit`]).
    pub fn edit(
        mut self,
        request: &EditRequest<'_>,
        translator: &dyn Translator,
        options: &EditOptions,
    ) -> Result<Pending, OpError> {
        let selected = selection(&self.scene, request)?;
        let plan =
            self.context
                .plan(request.instruction, &selected, &self.scene, &self.grounder)?;
        let undo_first = match plan {
            Plan::Undo => return Ok(Pending(Then::Undo)),
            Plan::Edit { undo_first, .. } => undo_first,
            _ => false,
        };
        if undo_first {
            let previous = self.previous.take().ok_or_else(nothing_to_correct)?;
            for (i, state) in previous {
                self.scene.objects[i] = state;
            }
        }
        let (done, _) = run(
            &mut self.scene,
            &self.grounder,
            plan,
            request,
            translator,
            options,
        )?;
        Ok(Pending(Then::Land {
            scene: self.scene,
            done: Box::new(done),
            undo_first,
        }))
    }

    /// Applies an expression.
    ///
    /// # Errors
    /// No object, an unknown one or one bound twice; an expression that is not a
    /// transformation; what placement refuses.
    pub fn apply(
        mut self,
        request: &ApplyRequest<'_>,
        options: &EditOptions,
    ) -> Result<Pending, OpError> {
        let (done, _) = apply(&mut self.scene, request, options)?;
        Ok(Pending(Then::Land {
            scene: self.scene,
            done: Box::new(done),
            undo_first: false,
        }))
    }
}

/// A correction's outcome with what taking the corrected change back moved, first (an
/// object the correction moves again is listed once, from where the change left it).
fn with_taken_back(mut outcome: Outcome, taken_back: Option<Outcome>) -> Outcome {
    let Some(undo) = taken_back else {
        return outcome;
    };
    let mut moved: Vec<Moved> = Vec::new();
    for back in undo.moved {
        match outcome.moved.iter().position(|m| m.object == back.object) {
            Some(k) => {
                let mut again = outcome.moved.remove(k);
                again.before = back.before;
                moved.push(again);
            }
            None => moved.push(back),
        }
    }
    moved.append(&mut outcome.moved);
    outcome.moved = moved;
    outcome
}

/// The refusal of a correction with no change before it to correct.
fn nothing_to_correct() -> OpError {
    OpError::new(
        ErrorKind::NotUnderstood,
        "there is no change before this to correct: say the whole instruction",
    )
}

impl Session {
    /// The scene's name index, built once.
    pub fn grounder(&self) -> Arc<Grounder> {
        Arc::clone(
            self.grounder
                .get_or_init(|| Arc::new(Grounder::new(&self.file.scene))),
        )
    }

    /// A copy of the scene to run an operation on ([`Working::edit`], [`Working::apply`]),
    /// with what the conversation remembers; [`Session::conclude`] its result.
    #[must_use]
    pub fn working(&self) -> Working {
        let previous = (self.latest_undone == Some(false))
            .then(|| self.undo.last())
            .flatten()
            .map(|step| {
                step.changes
                    .iter()
                    .map(|(i, a, _)| (*i, a.clone()))
                    .collect()
            });
        Working {
            scene: self.file.scene.clone(),
            grounder: self.grounder(),
            context: self.context.clone(),
            previous,
        }
    }

    /// Runs an instruction on the scene, in place, and records it: a new one, or a
    /// follow-up of the turn before.
    ///
    /// # Errors
    /// As [`Working::edit`]; the scene is then as it was.
    pub fn edit(
        &mut self,
        request: &EditRequest<'_>,
        translator: &dyn Translator,
        options: &EditOptions,
    ) -> Result<Outcome, OpError> {
        let grounder = self.grounder();
        let selected = selection(&self.file.scene, request)?;
        let plan =
            self.context
                .plan(request.instruction, &selected, &self.file.scene, &grounder)?;
        let undo_first = match plan {
            Plan::Undo => return self.undo(),
            Plan::Edit { undo_first, .. } => undo_first,
            _ => false,
        };
        let context = self.context.clone();
        let taken_back = if undo_first {
            if self.latest_undone != Some(false) {
                return Err(nothing_to_correct());
            }
            Some(self.step_outcome(true).map_err(|_| nothing_to_correct())?)
        } else {
            None
        };
        let supports = supports(&self.file.scene);
        match run(
            &mut self.file.scene,
            &grounder,
            plan,
            request,
            translator,
            options,
        ) {
            Ok((done, motions)) => {
                let changes = changes_since(&self.file.scene, &motions, &supports);
                Ok(with_taken_back(self.finish(changes, done), taken_back))
            }
            Err(e) => {
                if taken_back.is_some() {
                    // The correction failed: the change it took back comes back, and
                    // the conversation is as it was.
                    let _ = self.step_outcome(false);
                    self.context = context;
                }
                self.hear(&e);
                Err(e)
            }
        }
    }

    /// Applies a CGA expression to one object, in place, and records it.
    ///
    /// # Errors
    /// As [`Working::apply`]; the scene is then as it was.
    pub fn apply(
        &mut self,
        request: &ApplyRequest<'_>,
        options: &EditOptions,
    ) -> Result<Outcome, OpError> {
        let supports = supports(&self.file.scene);
        let (done, motions) = apply(&mut self.file.scene, request, options)?;
        let changes = changes_since(&self.file.scene, &motions, &supports);
        Ok(self.finish(changes, done))
    }

    /// Concludes an operation run on a working copy: makes its scene the session's,
    /// recording what it changed, or hears its refusal (what a correction leans on).
    ///
    /// # Errors
    /// The operation's refusal, as it was; nothing to undo for an "undo that".
    pub fn conclude(&mut self, result: Result<Pending, OpError>) -> Result<Outcome, OpError> {
        match result {
            Err(e) => {
                self.hear(&e);
                Err(e)
            }
            Ok(Pending(Then::Undo)) => self.undo(),
            Ok(Pending(Then::Land {
                scene,
                done,
                undo_first,
            })) => {
                // Take the corrected change back, so that it can be redone.
                let taken_back = (undo_first && self.latest_undone == Some(false))
                    .then(|| self.step_outcome(true).ok())
                    .flatten();
                let changes = diff(&self.file.scene, &scene);
                self.file.scene = scene;
                Ok(with_taken_back(self.finish(changes, *done), taken_back))
            }
        }
    }

    /// Remembers a refused instruction, for a correction to lean on.
    fn hear(&mut self, e: &OpError) {
        if let Some(instruction) = &e.refused {
            self.context.refused(instruction, e.ambiguity.clone());
        }
    }

    /// Records the changes of an operation already made and says what it did.
    fn finish(&mut self, changes: Vec<(usize, Object, Object)>, done: Done) -> Outcome {
        let moved = changes
            .iter()
            .filter(|(_, a, b)| a.pose_differs(b))
            .map(|(i, a, b)| Moved {
                object: b.name.clone(),
                how: if done.moved.contains(i) {
                    How::Moved
                } else if done.carried.contains(&b.name) {
                    How::Carried
                } else {
                    How::Pushed
                },
                before: Pose::of(a),
                after: Pose::of(b),
            })
            .collect();
        let kind = match done.operation {
            Operation::Apply => "apply",
            _ => "edit",
        };
        let mut turn = done.turn;
        turn.motions = conversation::motions_of(&changes, &done.moved);
        turn.acted = done.moved;
        if done.repeats {
            // A repeat keeps the instruction it repeats, for "and the mug too".
            turn.instruction = self.context.last_instruction().map(|(i, p)| {
                turn.phrases = p;
                i
            });
        }
        // What it moved, as it was, for "put it back": read before the history takes the
        // changes.
        let states = (!changes.is_empty())
            .then(|| conversation::moved_states(&turn.acted, &changes, &self.file.scene));
        let change = self.record(changes, kind, &done.text);
        if let Some(states) = states {
            self.context.edited(turn, change.id.map(|id| (id, states)));
        }
        Outcome {
            operation: done.operation,
            history_id: change.id,
            moved,
            understood: Some(done.understood),
            notes: done.notes,
            warnings: change.save_error.into_iter().collect(),
            report: done.report,
        }
    }
}

/// Each object's support, and whether it came from the file, before an operation.
fn supports(scene: &Scene) -> Vec<(Option<usize>, bool)> {
    scene
        .objects
        .iter()
        .map(|o| (o.support, o.support_from_file))
        .collect()
}

/// The objects an operation made in place changed, as they were and as they are, in
/// object order: those its motions moved (as they were before the first motion) and
/// those whose support changed — what [`diff`] finds, without a copy of the scene.
fn changes_since(
    scene: &Scene,
    motions: &[AppliedMotion],
    supports: &[(Option<usize>, bool)],
) -> Vec<(usize, Object, Object)> {
    let mut before: BTreeMap<usize, Object> = BTreeMap::new();
    for m in motions.iter().flat_map(|a| &a.moves) {
        before
            .entry(m.object)
            .or_insert_with(|| scene.objects[m.object].as_it_was(m.before, supports[m.object]));
    }
    for (i, o) in scene.objects.iter().enumerate() {
        if o.support != supports[i].0 {
            before
                .entry(i)
                .or_insert_with(|| o.as_it_was(o.similarity(), supports[i]));
        }
    }
    before
        .into_iter()
        .map(|(i, a)| (i, a, scene.objects[i].clone()))
        .filter(|(_, a, b)| a.pose_differs(b) || a.support != b.support)
        .collect()
}

/// The longest object name a request may bind: a name no object could have is refused
/// before anything quotes it.
pub const MAX_NAME_CHARS: usize = 1000;

/// The objects an expression binds, X1 first: `object`, then `bind`'s X2, X3 … in order.
///
/// # Errors
/// [`ErrorKind::BadInput`]: a gap in the variables (X3 without X2), a variable other than
/// X2 … Xn, a name longer than [`MAX_NAME_CHARS`].
pub fn bound_objects(
    object: &str,
    bind: &std::collections::BTreeMap<String, String>,
) -> Result<Vec<String>, OpError> {
    let mut names = vec![object.to_string()];
    for k in 0..bind.len() {
        let variable = crate::translate::Templated::variable(k + 1);
        let name = bind.get(&variable).ok_or_else(|| {
            let given: Vec<String> = bind.keys().map(|k| k.chars().take(40).collect()).collect();
            OpError::new(
                ErrorKind::BadInput,
                format!(
                    "bind X2, X3, … in order: {variable} is missing (got {})",
                    given.join(", ")
                ),
            )
        })?;
        names.push(name.clone());
    }
    if names.iter().any(|n| n.chars().count() > MAX_NAME_CHARS) {
        return Err(OpError::new(
            ErrorKind::BadInput,
            format!("an object name is longer than {MAX_NAME_CHARS} characters"),
        ));
    }
    Ok(names)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::{Document, SceneFile};
    use crate::offline::OfflineTranslator;

    fn file() -> SceneFile {
        let mut s = Scene::new("study");
        s.push_box("desk", [1.4, 0.75, 0.7], [0.0, 0.0, 0.0]);
        s.push_box("lamp", [0.2, 0.45, 0.2], [0.5, 0.75, 0.0]);
        s.push_box("book", [0.2, 0.05, 0.3], [-0.4, 0.75, 0.0]);
        s.push_box("chair", [0.5, 0.9, 0.5], [2.0, 0.0, 0.0]);
        s.push_box("cabinet", [0.8, 1.2, 0.5], [-1.6, 0.0, 0.0]);
        s.detect_supports();
        SceneFile {
            scene: s,
            document: Document::None,
            path: None,
        }
    }

    /// An outcome without what differs by nature between two runs (the report's timings).
    fn shape(outcome: &Outcome) -> serde_json::Value {
        let mut v = serde_json::to_value(outcome).unwrap();
        v.as_object_mut().unwrap().remove("report");
        v
    }

    fn poses(session: &Session) -> Vec<(cga::Similarity, Option<usize>)> {
        session
            .file
            .scene
            .objects
            .iter()
            .map(|o| (o.similarity(), o.support))
            .collect()
    }

    #[test]
    fn in_place_and_on_a_working_copy_an_edit_does_and_undoes_the_same() {
        let options = EditOptions::default();
        let no_carry = EditOptions {
            carry: false,
            ..EditOptions::default()
        };
        let edits: [(&str, &EditOptions); 4] = [
            ("move the desk 30 cm to the left", &options),
            // Into the cabinet: collision resolution moves it on.
            ("move the chair 3.5 m to the left", &options),
            // The desk leaves the lamp and the book behind: their supports change.
            ("move the desk 1 m forward", &no_carry),
            ("turn the lamp 90 degrees", &options),
        ];
        let mut direct = Session::new(file(), None);
        let mut copied = Session::new(file(), None);
        let original = poses(&direct);
        for (instruction, options) in edits {
            let request = EditRequest {
                instruction,
                selected: &[],
                report: false,
            };
            let a = direct
                .edit(&request, &OfflineTranslator::new(), options)
                .unwrap();
            let b = copied
                .working()
                .edit(&request, &OfflineTranslator::new(), options)
                .and_then(|p| copied.conclude(Ok(p)))
                .unwrap();
            assert_eq!(shape(&a), shape(&b), "{instruction}");
            assert!(!a.moved.is_empty(), "{instruction}");
            assert_eq!(poses(&direct), poses(&copied), "{instruction}");
            if instruction.contains("chair") {
                assert!(!a.notes.is_empty(), "a collision was resolved: {a:?}");
            }
            if instruction.contains("forward") {
                let lamp = direct.file.scene.find("lamp").unwrap();
                assert_eq!(direct.file.scene.objects[lamp].support, None, "left behind");
            }
        }
        let expression = ApplyRequest {
            objects: &["book".to_string()],
            expression: "T(0.1*e1)",
        };
        let a = direct.apply(&expression, &EditOptions::default()).unwrap();
        let b = copied
            .working()
            .apply(&expression, &EditOptions::default())
            .and_then(|p| copied.conclude(Ok(p)))
            .unwrap();
        assert_eq!(shape(&a), shape(&b));
        assert_eq!(direct.history().len(), 5);
        // Undone all the way, both are the scene they began as, bit for bit.
        while direct.can_undo() {
            let (a, b) = (direct.undo().unwrap(), copied.undo().unwrap());
            assert_eq!(shape(&a), shape(&b));
        }
        assert_eq!(poses(&direct), original);
        assert_eq!(poses(&copied), original);
        assert_eq!(direct.undo().unwrap_err().kind, ErrorKind::NothingToUndo);
    }

    #[test]
    fn a_refusal_in_place_leaves_the_scene_and_the_history_as_they_were() {
        let mut session = Session::new(file(), None);
        let before = poses(&session);
        let request = EditRequest {
            instruction: "move the sofa 1 m to the left",
            selected: &[],
            report: false,
        };
        let e = session
            .edit(&request, &OfflineTranslator::new(), &EditOptions::default())
            .unwrap_err();
        assert_eq!(e.kind, ErrorKind::NotUnderstood);
        assert_eq!(poses(&session), before);
        assert!(session.history().is_empty() && !session.can_undo());
    }
}

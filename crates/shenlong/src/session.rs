//! The operation layer: one scene being edited over time, as every front end keeps it —
//! the CLI, the editor's server, the MCP server and the Python package. Each operation
//! (edit, apply, undo, redo, export) answers an [`Outcome`] or an [`OpError`], data that
//! every front end writes in one shape; undo and redo keep the states of the objects each
//! change touched (not copies of the scene); a history; saving to the one file given at
//! start-up (after each change, or when asked).
//!
//! An edit runs on a working copy of the scene ([`Session::working`]) and is swapped in
//! when it succeeded ([`Session::land`]): a server can answer reads while a language model
//! thinks, and nobody ever sees half an edit.

pub mod error;
pub mod outcome;

pub use error::{Choice, Choices, ErrorKind, OpError};
pub use outcome::{How, Moved, Operation, Outcome, Pose, Understood};

use crate::format::{Format, SceneFile};
use crate::ground::Grounder;
use crate::pipeline::{EditOptions, Translator};
use crate::scene::{Object, Scene};
use std::path::PathBuf;
use std::sync::{Arc, OnceLock};

/// One entry of the history.
#[derive(Clone, Debug, serde::Serialize)]
pub struct HistoryItem {
    /// Running number.
    pub id: u64,
    /// `edit` or `apply`.
    pub kind: String,
    /// The instruction or expression.
    pub text: String,
    /// The objects that changed.
    pub objects: Vec<String>,
    /// Whether it is currently undone.
    pub undone: bool,
}

/// One change, as the objects it changed: each one's state before and after (its pose and
/// what it rests on), so a step costs what it changed, not a copy of the scene.
struct Step {
    id: u64,
    changes: Vec<(usize, Object, Object)>,
}

impl Step {
    fn bytes(&self) -> usize {
        self.changes
            .iter()
            .map(|(_, a, b)| object_bytes(a) + object_bytes(b))
            .sum()
    }

    /// Puts the objects back as they were (`undo`) or as the change left them.
    fn apply(&self, scene: &mut Scene, undo: bool) {
        for (i, before, after) in &self.changes {
            scene.objects[*i] = if undo { before.clone() } else { after.clone() };
        }
    }
}

fn object_bytes(o: &Object) -> usize {
    std::mem::size_of::<Object>()
        + o.name.len()
        + match &o.shape {
            crate::scene::Shape::Points { points } => points.len() * 24,
            crate::scene::Shape::Box { .. } => 0,
        }
}

/// The scene could not be written to the session's file; the change stays in memory.
#[derive(Debug, thiserror::Error)]
#[error("the edit was made but could not be saved: {0}")]
pub struct SaveError(#[from] crate::format::FormatError);

/// The most memory the undo history keeps; the oldest steps go first past it.
pub const MAX_HISTORY_BYTES: usize = 64 << 20;

/// Why undo or redo did nothing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StepError {
    /// The stack is empty.
    Nothing,
}

/// What [`Session::commit`] or [`Session::step`] did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Change {
    /// The change's id (`None` when it moved nothing and was not recorded).
    pub id: Option<u64>,
    /// The change was made and kept, but the save file could not be written: why.
    pub save_error: Option<String>,
}

/// A scene being edited, with its history.
pub struct Session {
    /// The scene and the document it came from.
    pub file: SceneFile,
    undo: Vec<Step>,
    redo: Vec<Step>,
    history: Vec<HistoryItem>,
    next_id: u64,
    save: Option<PathBuf>,
    autosave: bool,
    history_budget: usize,
    /// The scene's name index, built on the first edit: edits move objects, never rename
    /// them.
    grounder: OnceLock<Arc<Grounder>>,
    /// The objects the latest change (a commit, an undo, a redo) changed, as they were
    /// before it: what [`Session::before_last_change`] shows.
    last_before: Option<Vec<(usize, Object)>>,
}

impl Session {
    /// A session on `file`, saving to `save` after each change.
    pub fn new(file: SceneFile, save: Option<PathBuf>) -> Self {
        Self {
            file,
            undo: Vec::new(),
            redo: Vec::new(),
            history: Vec::new(),
            next_id: 1,
            save,
            autosave: true,
            history_budget: MAX_HISTORY_BYTES,
            grounder: OnceLock::new(),
            last_before: None,
        }
    }

    /// Sets the most memory the undo history keeps (default [`MAX_HISTORY_BYTES`]).
    pub fn set_history_budget(&mut self, bytes: usize) {
        self.history_budget = bytes;
    }

    /// A session on `file` that saves to `save` only when [`Session::save`] is called.
    pub fn saving_on_request(file: SceneFile, save: Option<PathBuf>) -> Self {
        Self {
            autosave: false,
            ..Self::new(file, save)
        }
    }

    /// Whether there is something to undo / redo.
    pub fn can_undo(&self) -> bool {
        !self.undo.is_empty()
    }

    /// See [`Session::can_undo`].
    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }

    /// The history, oldest first.
    pub fn history(&self) -> &[HistoryItem] {
        &self.history
    }

    /// Makes `after` (the current scene, edited) the scene: what it changed goes on the
    /// undo stack (a change that moved nothing is not recorded, and has no id); redo is
    /// cleared; the scene is saved. A failed save loses nothing: the change stays, in
    /// memory and in the history, and the failure is reported with it.
    pub fn commit(&mut self, after: Scene, kind: &str, text: &str) -> Change {
        let before = &self.file.scene;
        let changes: Vec<(usize, Object, Object)> = before
            .objects
            .iter()
            .zip(&after.objects)
            .enumerate()
            .filter(|(_, (a, b))| a.pose_differs(b) || a.support != b.support)
            .map(|(i, (a, b))| (i, a.clone(), b.clone()))
            .collect();
        if changes.is_empty() {
            return Change {
                id: None,
                save_error: None,
            };
        }
        let changed: Vec<String> = changes
            .iter()
            .filter(|(_, a, b)| a.pose_differs(b))
            .map(|(_, _, b)| b.name.clone())
            .collect();
        let id = self.next_id;
        self.next_id += 1;
        self.last_before = Some(changes.iter().map(|(i, a, _)| (*i, a.clone())).collect());
        self.undo.push(Step { id, changes });
        // Keep the history within its budget, dropping the oldest steps.
        let mut total: usize = self.undo.iter().map(Step::bytes).sum();
        while total > self.history_budget && self.undo.len() > 1 {
            let dropped = self.undo.remove(0);
            total -= dropped.bytes();
            self.history.retain(|h| h.id != dropped.id);
        }
        self.redo.clear();
        self.history.retain(|h| !h.undone);
        self.history.push(HistoryItem {
            id,
            kind: kind.into(),
            text: text.into(),
            objects: changed,
            undone: false,
        });
        self.file.scene = after;
        Change {
            id: Some(id),
            save_error: self
                .autosave
                .then(|| self.save().err().map(|e| e.to_string()))
                .flatten(),
        }
    }

    /// Undoes (`undo`) or redoes the last step and saves.
    ///
    /// # Errors
    /// [`StepError::Nothing`] when there is nothing to do.
    pub fn step(&mut self, undo: bool) -> Result<Change, StepError> {
        let popped = if undo {
            self.undo.pop()
        } else {
            self.redo.pop()
        };
        let Some(step) = popped else {
            return Err(StepError::Nothing);
        };
        self.last_before = Some(
            step.changes
                .iter()
                .map(|(i, _, _)| (*i, self.file.scene.objects[*i].clone()))
                .collect(),
        );
        step.apply(&mut self.file.scene, undo);
        let id = step.id;
        if undo {
            self.redo.push(step);
        } else {
            self.undo.push(step);
        }
        if let Some(item) = self.history.iter_mut().find(|h| h.id == id) {
            item.undone = undo;
        }
        Ok(Change {
            id: Some(id),
            save_error: self
                .autosave
                .then(|| self.save().err().map(|e| e.to_string()))
                .flatten(),
        })
    }

    /// Writes the scene to the save file, if there is one (atomically).
    ///
    /// # Errors
    /// The file could not be written; the change is kept in memory.
    pub fn save(&self) -> Result<(), SaveError> {
        match &self.save {
            Some(path) => Ok(self.file.save(path)?),
            None => Ok(()),
        }
    }

    /// The scene as it was before the latest change (an edit, an apply, an undo or a
    /// redo), made when asked; `None` before any change.
    #[must_use]
    pub fn before_last_change(&self) -> Option<Scene> {
        let before = self.last_before.as_ref()?;
        let mut scene = self.file.scene.clone();
        for (i, object) in before {
            scene.objects[*i] = object.clone();
        }
        Some(scene)
    }

    /// The file the session saves to.
    pub fn save_path(&self) -> Option<&std::path::Path> {
        self.save.as_deref()
    }
}

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
/// lock around it); [`Session::land`] swaps its result in.
pub struct Working {
    scene: Scene,
    grounder: Arc<Grounder>,
}

/// A finished operation not yet in the session.
pub struct Pending {
    scene: Scene,
    operation: Operation,
    text: String,
    /// The objects the operation moved itself.
    moved: Vec<usize>,
    carried: Vec<String>,
    understood: Option<Understood>,
    notes: Vec<String>,
    report: Option<Box<crate::pipeline::EditReport>>,
}

impl Working {
    /// The scene being worked on.
    #[must_use]
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// Runs an instruction.
    ///
    /// # Errors
    /// An unknown selected object; whatever the edit refuses ([`OpError::from_edit`]).
    pub fn edit(
        mut self,
        request: &EditRequest<'_>,
        translator: &dyn Translator,
        options: &EditOptions,
    ) -> Result<Pending, OpError> {
        let selection = request
            .selected
            .iter()
            .map(|name| {
                self.scene
                    .resolve(name)
                    .map_err(|e| OpError::new(ErrorKind::BadInput, format!("selected: {e}")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let options = EditOptions {
            selection,
            ..options.clone()
        };
        let done = crate::pipeline::edit_with(
            &mut self.scene,
            &self.grounder,
            request.instruction,
            translator,
            &options,
        )
        .map_err(|e| OpError::from_edit(e, request.instruction))?;
        let r = &done.report;
        Ok(Pending {
            operation: Operation::Edit,
            text: request.instruction.to_string(),
            moved: done.moved,
            carried: r.carried.clone(),
            understood: Some(Understood {
                query: r.query.clone(),
                bindings: r.bindings.clone(),
            }),
            notes: outcome::notes(&r.collisions_resolved, &r.overlaps_remaining, &r.held),
            report: request.report.then(|| Box::new(done.report)),
            scene: self.scene,
        })
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
        let names: Vec<&str> = request.objects.iter().map(String::as_str).collect();
        let (placed, _) = crate::pipeline::apply_expression_bound(
            &mut self.scene,
            &names,
            request.expression,
            options,
        )
        .map_err(|e| OpError::from_edit(e, request.expression))?;
        let bindings = names
            .iter()
            .enumerate()
            .map(|(k, name)| crate::pipeline::Binding {
                variable: crate::translate::Templated::variable(k),
                // The name as the scene spells it (the request may differ in case).
                object: self.scene.find(name).map_or_else(
                    || (*name).to_string(),
                    |i| self.scene.objects[i].name.clone(),
                ),
            })
            .collect();
        let text = format!("{}: {}", names[0], request.expression);
        Ok(Pending {
            operation: Operation::Apply,
            text,
            moved: placed.moved,
            carried: placed.carried.clone(),
            understood: Some(Understood {
                query: request.expression.to_string(),
                bindings,
            }),
            notes: outcome::notes(&placed.collisions_resolved, &placed.overlaps_remaining, &[]),
            report: None,
            scene: self.scene,
        })
    }
}

impl Session {
    /// The scene's name index, built once.
    pub fn grounder(&self) -> Arc<Grounder> {
        Arc::clone(
            self.grounder
                .get_or_init(|| Arc::new(Grounder::new(&self.file.scene))),
        )
    }

    /// A copy of the scene to run an operation on ([`Working::edit`], [`Working::apply`]);
    /// [`Session::land`] its result.
    #[must_use]
    pub fn working(&self) -> Working {
        Working {
            scene: self.file.scene.clone(),
            grounder: self.grounder(),
        }
    }

    /// Runs an instruction on the scene and records it.
    ///
    /// # Errors
    /// As [`Working::edit`]; the scene is then as it was.
    pub fn edit(
        &mut self,
        request: &EditRequest<'_>,
        translator: &dyn Translator,
        options: &EditOptions,
    ) -> Result<Outcome, OpError> {
        let pending = self.working().edit(request, translator, options)?;
        Ok(self.land(pending))
    }

    /// Applies a CGA expression to one object and records it.
    ///
    /// # Errors
    /// As [`Working::apply`]; the scene is then as it was.
    pub fn apply(
        &mut self,
        request: &ApplyRequest<'_>,
        options: &EditOptions,
    ) -> Result<Outcome, OpError> {
        let pending = self.working().apply(request, options)?;
        Ok(self.land(pending))
    }

    /// Makes a finished operation's scene the session's, recording what it changed.
    pub fn land(&mut self, pending: Pending) -> Outcome {
        let moved = self.moved_between(&pending.scene, |i, name| {
            if pending.moved.contains(&i) {
                How::Moved
            } else if pending.carried.iter().any(|c| c == name) {
                How::Carried
            } else {
                How::Pushed
            }
        });
        let kind = match pending.operation {
            Operation::Apply => "apply",
            _ => "edit",
        };
        let change = self.commit(pending.scene, kind, &pending.text);
        Outcome {
            operation: pending.operation,
            history_id: change.id,
            moved,
            understood: pending.understood,
            notes: pending.notes,
            warnings: change.save_error.into_iter().collect(),
            report: pending.report,
        }
    }

    /// Each object whose pose differs between the session's scene and `after`, with why
    /// (`how` of its index and name).
    fn moved_between(&self, after: &Scene, how: impl Fn(usize, &str) -> How) -> Vec<Moved> {
        self.file
            .scene
            .objects
            .iter()
            .zip(&after.objects)
            .enumerate()
            .filter(|(_, (a, b))| a.pose_differs(b))
            .map(|(i, (a, b))| Moved {
                object: b.name.clone(),
                how: how(i, &b.name),
                before: Pose::of(a),
                after: Pose::of(b),
            })
            .collect()
    }

    /// Takes back the last change.
    ///
    /// # Errors
    /// [`ErrorKind::NothingToUndo`].
    pub fn undo(&mut self) -> Result<Outcome, OpError> {
        self.step_outcome(true)
    }

    /// Makes the last undone change again.
    ///
    /// # Errors
    /// [`ErrorKind::NothingToRedo`].
    pub fn redo(&mut self) -> Result<Outcome, OpError> {
        self.step_outcome(false)
    }

    fn step_outcome(&mut self, undo: bool) -> Result<Outcome, OpError> {
        let (operation, kind, verb) = if undo {
            (Operation::Undo, ErrorKind::NothingToUndo, "undo")
        } else {
            (Operation::Redo, ErrorKind::NothingToRedo, "redo")
        };
        let change = self
            .step(undo)
            .map_err(|StepError::Nothing| OpError::new(kind, format!("nothing to {verb}")))?;
        let scene = &self.file.scene;
        let moved = self
            .last_before
            .iter()
            .flatten()
            .filter(|(i, a)| a.pose_differs(&scene.objects[*i]))
            .map(|(i, a)| Moved {
                object: a.name.clone(),
                how: How::Moved,
                before: Pose::of(a),
                after: Pose::of(&scene.objects[*i]),
            })
            .collect();
        Ok(Outcome {
            operation,
            history_id: change.id,
            moved,
            understood: None,
            notes: Vec::new(),
            warnings: change.save_error.into_iter().collect(),
            report: None,
        })
    }

    /// The scene as a file's bytes.
    ///
    /// # Errors
    /// [`ErrorKind::Export`]: the format cannot hold this scene (`usda` for a scene not
    /// read from USD …).
    pub fn export(&self, format: Format) -> Result<Vec<u8>, OpError> {
        self.file
            .to_bytes(format)
            .map_err(|e| OpError::new(ErrorKind::Export, e.to_string()))
    }
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

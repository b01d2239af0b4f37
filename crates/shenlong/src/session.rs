//! The operation layer: one scene being edited over time, as every front end keeps it —
//! the CLI, the editor's server, the MCP server and the Python package. Each operation
//! (edit, apply, undo, redo, export) answers an [`Outcome`] or an [`OpError`], data that
//! every front end writes in one shape; undo and redo keep the states of the objects each
//! change touched (not copies of the scene); a history; saving to the one file given at
//! start-up (after each change, or when asked).
//!
//! An edit runs in place ([`Session::edit`]: the scene is as it was on any error, and undo
//! records the motions' objects as they were), or on a working copy
//! ([`Session::working`]) swapped in when it succeeded ([`Session::land`]): a server
//! answers reads while a language model thinks, and nobody ever sees half an edit. Both
//! give the same outcome and the same undo (`session/ops.rs`).

mod conversation;
pub mod error;
pub mod follow_up;
mod ops;
pub mod outcome;

pub use error::{Choice, Choices, ErrorKind, OpError};
pub use ops::{bound_objects, ApplyRequest, EditRequest, Pending, Working, MAX_NAME_CHARS};
pub use outcome::{How, Moved, Operation, Outcome, Pose, Understood};

use crate::format::{Format, SceneFile};
use crate::ground::Grounder;
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

/// Each object whose pose or support differs between `before` and `after`, with both.
fn diff(before: &Scene, after: &Scene) -> Vec<(usize, Object, Object)> {
    before
        .objects
        .iter()
        .zip(&after.objects)
        .enumerate()
        .filter(|(_, (a, b))| a.pose_differs(b) || a.support != b.support)
        .map(|(i, (a, b))| (i, a.clone(), b.clone()))
        .collect()
}

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
    /// Which way the latest change went: `Some(false)` for a commit or a redo (its step on
    /// top of the undo stack), `Some(true)` for an undo (on top of the redo stack); `None`
    /// before any.
    latest_undone: Option<bool>,
    /// What the conversation remembers of the turn before.
    context: conversation::Context,
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
            latest_undone: None,
            context: conversation::Context::default(),
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
        let changes = diff(&self.file.scene, &after);
        self.file.scene = after;
        self.record(changes, kind, text)
    }

    /// Records a change already made to the scene — each object it changed, as it was and
    /// as it is — on the undo stack and in the history, and saves.
    fn record(&mut self, changes: Vec<(usize, Object, Object)>, kind: &str, text: &str) -> Change {
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
        self.latest_undone = Some(false);
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
        self.latest_undone = Some(undo);
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
        let mut scene = self.file.scene.clone();
        for (i, from, _) in self.latest_changes()? {
            scene.objects[i] = from.clone();
        }
        Some(scene)
    }

    /// The objects the latest change (a commit, an undo, a redo) changed, each as it was
    /// before the change and as the change left it: read off the step on top of the stack
    /// it went to.
    fn latest_changes(&self) -> Option<impl Iterator<Item = (usize, &Object, &Object)>> {
        let undone = self.latest_undone?;
        let step = if undone {
            self.redo.last()
        } else {
            self.undo.last()
        }?;
        Some(step.changes.iter().map(move |(i, before, after)| {
            if undone {
                (*i, after, before)
            } else {
                (*i, before, after)
            }
        }))
    }

    /// The file the session saves to.
    pub fn save_path(&self) -> Option<&std::path::Path> {
        self.save.as_deref()
    }
}

impl Session {
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

    pub(crate) fn step_outcome(&mut self, undo: bool) -> Result<Outcome, OpError> {
        let (operation, kind, verb) = if undo {
            (Operation::Undo, ErrorKind::NothingToUndo, "undo")
        } else {
            (Operation::Redo, ErrorKind::NothingToRedo, "redo")
        };
        let change = self
            .step(undo)
            .map_err(|StepError::Nothing| OpError::new(kind, format!("nothing to {verb}")))?;
        let changed: Vec<(usize, Object, Object)> = self
            .latest_changes()
            .into_iter()
            .flatten()
            .map(|(i, from, to)| (i, from.clone(), to.clone()))
            .collect();
        if let Some(id) = change.id {
            self.context.stepped(id, undo, &changed, &self.file.scene);
        }
        let moved = changed
            .iter()
            .filter(|(_, from, to)| from.pose_differs(to))
            .map(|(_, from, to)| Moved {
                object: to.name.clone(),
                how: How::Moved,
                before: Pose::of(from),
                after: Pose::of(to),
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

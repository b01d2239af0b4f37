//! One scene being edited over time, as the editor's server, the MCP server and the Python
//! package keep it: the scene file, undo and redo as the poses each change replaced, a
//! history, and saving to the one file given at start-up (after each change, or when
//! asked).

use crate::format::SceneFile;
use crate::scene::{Object, Scene};
use std::path::PathBuf;

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
            save_error: self.autosave.then(|| self.save().err()).flatten(),
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
            save_error: self.autosave.then(|| self.save().err()).flatten(),
        })
    }

    /// Writes the scene to the save file, if there is one (atomically).
    ///
    /// # Errors
    /// A message saying the change was made but not saved.
    pub fn save(&self) -> Result<(), String> {
        match &self.save {
            Some(path) => self
                .file
                .save(path)
                .map_err(|e| format!("the edit was made but could not be saved: {e}")),
            None => Ok(()),
        }
    }

    /// The file the session saves to.
    pub fn save_path(&self) -> Option<&std::path::Path> {
        self.save.as_deref()
    }
}

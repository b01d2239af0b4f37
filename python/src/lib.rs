//! `shenlong._native`: the Shenlong library for Python, built with PyO3 and maturin.
//!
//! The Python package (`python/py/shenlong`) wraps this module: values cross as JSON text
//! (Python's `json` on one side, serde on the other), so the only types here are strings,
//! numbers, booleans and lists of them. Every call that works on a scene releases the GIL;
//! edits run on a copy of the scene, committed only when they succeed, so a refusal, an
//! error or even a bug (a panic, caught here) leaves the scene exactly as it was and
//! reaches Python as `EditError`, never as a panic.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use shenlong::bench::folder;
use shenlong::bench::run::{check_shard, RunOptions};
use shenlong::bench::Suite;
use shenlong::format::procthor::{self, AssetDatabase};
use shenlong::format::{json, Document, Format, SceneFile};
use shenlong::pipeline::backends::{translator, Spec, SpecError, TranslatorSettings};
use shenlong::pipeline::{EditOptions, System, Translator};
use shenlong::scene::listing::listing;
use shenlong::session::{
    bound_objects, ApplyRequest, EditRequest, ErrorKind, OpError, Outcome, Session,
};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;
use std::sync::atomic::AtomicBool;

pyo3::create_exception!(
    _native,
    EditError,
    PyValueError,
    "An instruction Shenlong refused, or bad input: the message is one line saying what and where; the scene is as it was. args: (message, the refusal as JSON: kind, error, ambiguity)."
);

/// A refusal as Python sees it: `EditError(message, json)`, the JSON being the refusal as
/// every front end writes it (`shenlong` raises the subclass of its kind).
fn refusal(error: &OpError) -> PyErr {
    let json = serde_json::to_string(error).unwrap_or_default();
    EditError::new_err((error.message.clone(), json))
}

fn error(message: impl std::fmt::Display) -> PyErr {
    refusal(&OpError::new(ErrorKind::BadInput, message.to_string()))
}

/// An operation's answer as JSON, or its refusal.
fn outcome_json(result: Result<Outcome, OpError>) -> Result<String, OpError> {
    let outcome = result?;
    serde_json::to_string(&outcome).map_err(|e| {
        OpError::new(
            ErrorKind::Internal,
            format!("the change was made but its outcome cannot be written as JSON: {e}"),
        )
    })
}

/// Runs `f`, turning a panic (a bug) into an error that says so.
fn guarded<T>(f: impl FnOnce() -> Result<T, String>) -> Result<T, String> {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or_else(|panic| {
        let what = panic
            .downcast_ref::<&str>()
            .map(|s| (*s).to_string())
            .or_else(|| panic.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown".into());
        Err(format!(
            "internal error (a bug in Shenlong, please report it): {what}; nothing was changed"
        ))
    })
}

/// Runs `f` without the GIL, guarded against panics.
fn detached<T: Send>(py: Python<'_>, f: impl FnOnce() -> Result<T, String> + Send) -> PyResult<T> {
    py.detach(|| guarded(f)).map_err(error)
}

/// Runs an operation on the session without the GIL, after the calls before it, guarded
/// against panics (a bug answers an `internal` refusal; the scene is as it was: edits and
/// applies run on a working copy swapped in at their end).
fn operate(
    py: Python<'_>,
    session: &std::sync::Mutex<Session>,
    f: impl FnOnce(&mut Session) -> Result<String, OpError> + Send,
) -> PyResult<String> {
    let result = py.detach(|| {
        catch_unwind(AssertUnwindSafe(|| {
            f(&mut session
                .lock()
                .unwrap_or_else(std::sync::PoisonError::into_inner))
        }))
        .unwrap_or_else(|_| {
            Err(OpError::new(
                ErrorKind::Internal,
                "internal error (a bug in Shenlong, please report it); nothing was changed",
            ))
        })
    });
    result.map_err(|e| refusal(&e))
}

fn to_json<T: serde::Serialize>(value: &T) -> Result<String, String> {
    serde_json::to_string(value).map_err(|e| format!("cannot write the answer as JSON: {e}"))
}

fn make_translator(llm: &str, system: System) -> Result<Box<dyn Translator>, String> {
    make_translator_at(llm, system, None)
}

/// The translator `llm` names, with a model server's base URL when given.
fn make_translator_at(
    llm: &str,
    system: System,
    base_url: Option<String>,
) -> Result<Box<dyn Translator>, String> {
    let spec: Spec = llm.parse().map_err(|e: SpecError| e.to_string())?;
    translator(
        &spec,
        &TranslatorSettings {
            system,
            base_url,
            ..TranslatorSettings::default()
        },
    )
    .map_err(|e| e.to_string())
}

fn collisions(collide: bool) -> Option<shenlong::collide::ResolveOptions> {
    collide.then(shenlong::collide::ResolveOptions::default)
}

/// A scene being edited, with undo and redo (`shenlong.Scene` wraps it). One `Scene` may
/// be used from several threads: its calls take turns (each holds the scene for the whole
/// call, without the GIL, so other Python threads run meanwhile).
#[pyclass(module = "shenlong._native", name = "Scene", frozen)]
struct PyScene {
    session: std::sync::Mutex<Session>,
}

impl PyScene {
    fn new(file: SceneFile) -> Self {
        Self {
            session: std::sync::Mutex::new(Session::saving_on_request(file, None)),
        }
    }

    /// The session, for a quick read under the GIL: no call holds it while it waits for
    /// the GIL, so this never deadlocks. (A call that panicked left it as it was: every
    /// change is made on a copy and committed at its end.)
    fn lock(&self) -> std::sync::MutexGuard<'_, Session> {
        self.session
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    /// Runs `f` on the session without the GIL, after the calls before it.
    fn with<T: Send>(
        &self,
        py: Python<'_>,
        f: impl FnOnce(&mut Session) -> Result<T, String> + Send,
    ) -> PyResult<T> {
        detached(py, move || f(&mut self.lock()))
    }

    /// Undoes (`undo`) or redoes the last change; `None` when there is nothing to.
    fn step(&self, py: Python<'_>, undo: bool) -> PyResult<Option<String>> {
        let answer = operate(py, &self.session, move |session| {
            let result = if undo { session.undo() } else { session.redo() };
            match result {
                Err(e) if matches!(e.kind, ErrorKind::NothingToUndo | ErrorKind::NothingToRedo) => {
                    Ok(String::new())
                }
                other => outcome_json(other),
            }
        })?;
        Ok((!answer.is_empty()).then_some(answer))
    }
}

#[pymethods]
impl PyScene {
    /// Reads a scene file (`.json`, `.gltf`, `.glb`, `.usda`, `.usdc`, `.usdz`); a glTF or
    /// USD file with `units` (`mm`, `cm`, `m`, `in`, `ft`) and `front` (`+z`, `-y` …) when
    /// its own conventions are missing or wrong.
    #[staticmethod]
    #[pyo3(signature = (path, units=None, front=None))]
    fn load(
        py: Python<'_>,
        path: PathBuf,
        units: Option<String>,
        front: Option<String>,
    ) -> PyResult<Self> {
        detached(py, move || {
            let options = shenlong::format::ReadOptions {
                units: units.as_deref().map(str::parse).transpose()?,
                front: front.as_deref().map(str::parse).transpose()?,
            };
            SceneFile::load_with(&path, &options)
                .map(Self::new)
                .map_err(|e| e.to_string())
        })
    }

    /// A scene from scene-JSON text; `name` names a scene without a `"name"`.
    #[staticmethod]
    fn from_json(py: Python<'_>, text: String, name: String) -> PyResult<Self> {
        detached(py, move || {
            let read = json::read_string(text, &name).map_err(|e| e.to_string())?;
            Ok(Self::new(SceneFile {
                scene: read.scene,
                document: Document::SceneJson(read.document),
                path: None,
            }))
        })
    }

    /// A ProcTHOR / Holodeck house (JSON text) with its asset database (JSON text).
    #[staticmethod]
    fn from_procthor(py: Python<'_>, house: String, assets: String) -> PyResult<Self> {
        detached(py, move || {
            let house: serde_json::Value =
                serde_json::from_str(&house).map_err(|e| format!("the house is not JSON: {e}"))?;
            if !procthor::looks_like_house(&house) {
                return Err(
                    "the house has no rooms and objects of a ProcTHOR/Holodeck house".into(),
                );
            }
            let assets = AssetDatabase::from_json(&assets)
                .map_err(|e| format!("the asset database: {e}"))?;
            let name = house
                .get("id")
                .and_then(serde_json::Value::as_str)
                .unwrap_or("house")
                .to_string();
            let document = procthor::convert(&house, &assets, &name).map_err(|e| e.to_string())?;
            let (scene, document) =
                json::scene_from_value(&document, &name).map_err(|e| e.to_string())?;
            Ok(Self::new(SceneFile {
                scene,
                document: Document::SceneJson(document),
                path: None,
            }))
        })
    }

    /// The scene's name.
    #[getter]
    fn name(&self) -> String {
        self.lock().file.scene.name.clone()
    }

    /// The number of objects.
    fn len(&self) -> usize {
        self.lock().file.scene.objects.len()
    }

    /// Every object as JSON: name, position, rotation, scale, size, world_box, front,
    /// rests_on.
    fn objects_json(&self, py: Python<'_>) -> PyResult<String> {
        self.with(py, |session| to_json(&listing(&session.file.scene).objects))
    }

    /// The scene as scene-JSON text.
    fn to_json(&self, py: Python<'_>) -> PyResult<String> {
        self.with(py, |session| {
            let bytes = session
                .file
                .to_bytes(Format::SceneJson)
                .map_err(|e| e.to_string())?;
            String::from_utf8(bytes).map_err(|e| e.to_string())
        })
    }

    /// The history as JSON, oldest first.
    fn history_json(&self) -> PyResult<String> {
        to_json(&self.lock().history()).map_err(error)
    }

    /// Runs an instruction; returns its outcome as JSON.
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (instruction, llm, system, collide, carry, selected, report=false, base_url=None))]
    fn edit(
        &self,
        py: Python<'_>,
        instruction: String,
        llm: String,
        system: String,
        collide: bool,
        carry: bool,
        selected: Vec<String>,
        report: bool,
        base_url: Option<String>,
    ) -> PyResult<String> {
        let system = System::parse(&system).map_err(error)?;
        let translator = make_translator_at(&llm, system, base_url).map_err(error)?;
        let options = EditOptions::new(carry, collisions(collide));
        operate(py, &self.session, move |session| {
            let request = EditRequest {
                instruction: &instruction,
                selected: &selected,
                report,
            };
            // On a working copy: even a bug caught mid-edit leaves the scene as it was.
            let pending = session
                .working()
                .edit(&request, translator.as_ref(), &options);
            outcome_json(session.conclude(pending))
        })
    }

    /// Applies one CGA expression to one object (X1; `bind` names X2, X3 …); returns its
    /// outcome as JSON.
    #[pyo3(signature = (name, expr, collide, carry, bind=std::collections::BTreeMap::new()))]
    fn apply(
        &self,
        py: Python<'_>,
        name: String,
        expr: String,
        collide: bool,
        carry: bool,
        bind: std::collections::BTreeMap<String, String>,
    ) -> PyResult<String> {
        let objects = bound_objects(&name, &bind).map_err(|e| refusal(&e))?;
        let options = EditOptions::new(carry, collisions(collide));
        operate(py, &self.session, move |session| {
            let request = ApplyRequest {
                objects: &objects,
                expression: &expr,
            };
            let pending = session.working().apply(&request, &options);
            outcome_json(session.conclude(pending))
        })
    }

    /// Undoes the last change; its outcome as JSON, `None` when there is none.
    fn undo(&self, py: Python<'_>) -> PyResult<Option<String>> {
        self.step(py, true)
    }

    /// Redoes the last undone change; its outcome as JSON, `None` when there is none.
    fn redo(&self, py: Python<'_>) -> PyResult<Option<String>> {
        self.step(py, false)
    }

    /// Writes the scene atomically, the format by extension.
    fn save(&self, py: Python<'_>, path: PathBuf) -> PyResult<()> {
        self.with(py, move |session| {
            session.file.save(&path).map_err(|e| e.to_string())
        })
    }
}

/// Evaluates a CGA expression with no objects; the versor M = T·R·D as JSON.
#[pyfunction]
fn eval_json(py: Python<'_>, expr: String) -> PyResult<String> {
    detached(py, move || {
        let t = shenlong::expr::evaluate_transformation(&expr, &shenlong::expr::Bindings::new())
            .map_err(|e| e.to_string())?;
        let s = t.similarity;
        to_json(&serde_json::json!({
            "versor": t.versor.coefficients().to_vec(),
            "translation": s.translation.to_array(),
            "rotation": s.rotation.to_array(),
            "scale": s.scale,
        }))
    })
}

/// Runs a suite into the folder `out` (as `shenlong bench`); the report as JSON.
/// `progress(done, total)` is called as instances finish, if given.
#[pyfunction]
#[pyo3(signature = (suite, out, llm, systems, collide, limit, jobs, shard, progress=None))]
#[allow(clippy::too_many_arguments)]
fn bench_json(
    py: Python<'_>,
    suite: PathBuf,
    out: PathBuf,
    llm: String,
    systems: String,
    collide: bool,
    limit: Option<usize>,
    jobs: usize,
    shard: Option<(usize, usize)>,
    progress: Option<Py<PyAny>>,
) -> PyResult<String> {
    if jobs == 0 {
        return Err(error("jobs must be at least 1"));
    }
    if let Some((k, n)) = shard {
        check_shard(k, n).map_err(error)?;
    }
    detached(py, move || {
        let suite = Suite::load(&suite).map_err(|e| e.to_string())?;
        let systems = System::parse_list(&systems).map_err(|e| e.to_string())?;
        // Everything is checked before anything runs: scenes, backends.
        let scenes = suite.load_scenes().map_err(|e| e.to_string())?;
        let translators = systems
            .iter()
            .map(|&system| Ok((system, make_translator(&llm, system)?)))
            .collect::<Result<Vec<(System, Box<dyn Translator>)>, String>>()?;
        let options = RunOptions {
            systems,
            jobs,
            limit,
            collide,
            shard,
        };
        let tell = |done: usize, total: usize| {
            if let Some(callback) = &progress {
                // A callback that raises is the caller's to see; the run goes on.
                Python::attach(|py| {
                    if let Err(e) = callback.call1(py, (done, total)) {
                        e.print(py);
                    }
                });
            }
        };
        let finished = folder::run_into(
            &out,
            &suite,
            &scenes,
            &translators,
            &options,
            &tell,
            &AtomicBool::new(false),
        )
        .map_err(|e| e.to_string())?;
        to_json(&finished.report)
    })
}

/// One report from the folders of a run's shards (as `shenlong bench --merge`); JSON.
#[pyfunction]
fn bench_merge_json(py: Python<'_>, dirs: Vec<PathBuf>, out: PathBuf) -> PyResult<String> {
    detached(py, move || {
        let merged = folder::merge(&dirs, &out).map_err(|e| e.to_string())?;
        to_json(&merged.report)
    })
}

/// The native module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("EditError", m.py().get_type::<EditError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_class::<PyScene>()?;
    m.add_function(wrap_pyfunction!(eval_json, m)?)?;
    m.add_function(wrap_pyfunction!(bench_json, m)?)?;
    m.add_function(wrap_pyfunction!(bench_merge_json, m)?)?;
    Ok(())
}

//! Running a suite: every instance through the pipeline for each system, checked, with
//! results appended as JSON lines so an interrupted run can resume.

use super::instantiate::{instantiate, Instance};
use super::suite::Suite;
use crate::pipeline::{edit, EditOptions, System, Translator};
use crate::scene::Scene;
use serde::{Deserialize, Serialize};
use std::collections::{HashMap, HashSet};
use std::io::Write;
use std::path::Path;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

/// The result of one instance for one system.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Outcome {
    /// The instance id (`query@scene#variation`).
    pub instance: String,
    /// The query id.
    pub query: String,
    /// Its category.
    pub category: String,
    /// The scene's name.
    pub scene: String,
    /// The prompt system.
    pub system: String,
    /// The instruction as run.
    pub instruction: String,
    /// Whether every check passed.
    pub success: bool,
    /// The checks that failed, with their reasons.
    pub failures: Vec<String>,
    /// The pipeline's error, when the edit failed.
    pub error: Option<String>,
    /// Response time of the translator, retries included, in milliseconds.
    pub response_ms: f64,
    /// Attempts after the first.
    pub retries: usize,
    /// Tokens sent.
    pub prompt_tokens: u64,
    /// Tokens received.
    pub completion_tokens: u64,
    /// Whether the answer came from the cache.
    pub cache_hit: bool,
    /// Which translator answered (`offline` or the model; for a cascade, the part that
    /// answered), when one did.
    #[serde(default)]
    pub answered_by: Option<String>,
    /// What became of the model's replies: received, parsed, valid `T·R·D`.
    #[serde(default)]
    pub replies: crate::translate::ReplyCounts,
}

/// How a run goes.
#[derive(Clone, Debug)]
pub struct RunOptions {
    /// The systems to compare.
    pub systems: Vec<System>,
    /// Instances run at once.
    pub jobs: usize,
    /// Run at most this many instances per system.
    pub limit: Option<usize>,
    /// Resolve collisions as `edit` does (off: the run measures the translator alone).
    pub collide: bool,
    /// Run only shard `K` of `N` (1-based): the instances whose position in the suite's
    /// fixed order is `K − 1` modulo `N`, so `N` machines split a run between them and
    /// their results merge into the same report as one run.
    pub shard: Option<(usize, usize)>,
}

/// Checks a shard `K/N` for [`RunOptions::shard`]: `1 ≤ K ≤ N`.
///
/// # Errors
/// A shard outside that range, said as `shard K/N: …`.
pub fn check_shard(k: usize, n: usize) -> Result<(), ShardError> {
    if n == 0 || k == 0 || k > n {
        return Err(ShardError::OutOfRange { k, n });
    }
    if n > MAX_SHARDS {
        return Err(ShardError::TooMany { k, n });
    }
    Ok(())
}

/// A shard `K/N` that names none.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ShardError {
    /// K outside 1..=N.
    #[error("shard {k}/{n}: K must be between 1 and N")]
    OutOfRange {
        /// The shard.
        k: usize,
        /// Of how many.
        n: usize,
    },
    /// More shards than [`MAX_SHARDS`].
    #[error("shard {k}/{n}: a run is split into {MAX_SHARDS} shards at most")]
    TooMany {
        /// The shard.
        k: usize,
        /// Of how many.
        n: usize,
    },
}

/// The most shards a run is split into (more than any pool of machines a user has).
pub const MAX_SHARDS: usize = 10_000;

/// Every instance of a suite on its scenes, in a fixed order.
pub fn instances(suite: &Suite, scenes: &[Scene]) -> Vec<Instance> {
    let mut out = Vec::new();
    for (s, scene) in scenes.iter().enumerate() {
        for q in 0..suite.queries.len() {
            out.extend(instantiate(suite, q, s, scene));
        }
    }
    out
}

/// Runs one instance and checks it.
pub fn run_one(
    suite: &Suite,
    scene: &Scene,
    instance: &Instance,
    translator: &dyn Translator,
    collide: bool,
) -> Outcome {
    let query = &suite.queries[instance.query];
    let mut after = scene.clone();
    let options = EditOptions::new(true, collide.then(Default::default));
    let result = edit(&mut after, &instance.instruction, translator, &options);
    // The placeholders, and the objects the checks are about by name: "others" are the
    // objects none of these name (a swap's other object is a subject of its own check).
    let mut bound: HashMap<String, usize> = instance.bound.iter().cloned().collect();
    for check in &query.expect {
        for name in check.subjects() {
            if !bound.contains_key(name) {
                if let Some(i) = scene.find(name) {
                    bound.insert(name.clone(), i);
                }
            }
        }
    }
    let mut outcome = Outcome {
        instance: instance.id.clone(),
        query: query.id.clone(),
        category: query.category.clone(),
        scene: scene.name.clone(),
        system: translator.system().name().into(),
        instruction: instance.instruction.clone(),
        success: false,
        failures: Vec::new(),
        error: None,
        response_ms: 0.0,
        retries: 0,
        prompt_tokens: 0,
        completion_tokens: 0,
        cache_hit: false,
        answered_by: None,
        replies: Default::default(),
    };
    let expects_refusal = query
        .expect
        .iter()
        .any(|c| matches!(c, super::checks::Check::Refused { .. }));
    match result {
        Err(e) if expects_refusal => {
            outcome.replies = e.replies;
            for check in &query.expect {
                if let Err(reason) = check.evaluate_refusal(&e.message, scene, &bound) {
                    outcome.failures.push(reason.0);
                }
            }
            outcome.success = outcome.failures.is_empty();
            outcome.error = Some(e.message);
        }
        Err(e) => {
            outcome.replies = e.replies;
            outcome.error = Some(e.message);
        }
        Ok(edit) => {
            let r = &edit.report;
            outcome.response_ms = r.timings_ms.translate;
            outcome.retries = r.retries;
            outcome.prompt_tokens = r.tokens.prompt;
            outcome.completion_tokens = r.tokens.completion;
            outcome.cache_hit = r.cache_hit;
            outcome.answered_by = Some(r.answered_by.clone());
            outcome.replies = r.replies;
            for check in &query.expect {
                if let Err(reason) = check.evaluate(scene, &after, &bound) {
                    outcome.failures.push(reason.0);
                }
            }
            outcome.success = outcome.failures.is_empty();
        }
    }
    outcome
}

/// Runs the suite for every system, skipping what `results` (a JSON-lines file) already
/// holds and appending each new outcome to it. `progress` is told of each instance done;
/// `stop` ends the run early (between instances). Returns every outcome, old and new.
#[allow(clippy::too_many_arguments)]
pub fn run(
    suite: &Suite,
    scenes: &[Scene],
    translators: &[(System, Box<dyn Translator>)],
    options: &RunOptions,
    results: &Path,
    progress: &(dyn Fn(usize, usize) + Sync),
    stop: &AtomicBool,
) -> std::io::Result<Vec<Outcome>> {
    let mut done: Vec<Outcome> =
        match crate::io::read_text_limited(results, crate::io::MAX_READ_BYTES) {
            Ok(text) => text
                .lines()
                .filter_map(|l| serde_json::from_str(l).ok())
                .collect(),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Vec::new(),
            Err(e) => return Err(e),
        };
    let finished: HashSet<(String, String)> = done
        .iter()
        .map(|o| (o.system.clone(), o.instance.clone()))
        .collect();
    let all = instances(suite, scenes);
    let mut work: Vec<(usize, &Instance)> = Vec::new();
    for (t, (system, _)) in translators.iter().enumerate() {
        let limit = options.limit.unwrap_or(usize::MAX);
        for (position, instance) in all.iter().take(limit).enumerate() {
            if let Some((k, n)) = options.shard {
                if position % n != k - 1 {
                    continue;
                }
            }
            if !finished.contains(&(system.name().to_string(), instance.id.clone())) {
                work.push((t, instance));
            }
        }
    }
    let total = work.len();
    let file = Mutex::new(
        std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(results)?,
    );
    let next = AtomicUsize::new(0);
    let completed = AtomicUsize::new(0);
    let fresh = Mutex::new(Vec::new());
    let write_error = Mutex::new(None);
    std::thread::scope(|scope| {
        for _ in 0..options.jobs.max(1) {
            scope.spawn(|| loop {
                if stop.load(Ordering::Relaxed) {
                    return;
                }
                let k = next.fetch_add(1, Ordering::Relaxed);
                let Some(&(t, instance)) = work.get(k) else {
                    return;
                };
                let outcome = run_one(
                    suite,
                    &scenes[instance.scene],
                    instance,
                    translators[t].1.as_ref(),
                    options.collide,
                );
                let mut line = serde_json::to_string(&outcome).expect("outcomes serialise");
                line.push('\n');
                {
                    let mut f = file.lock().unwrap_or_else(|e| e.into_inner());
                    if let Err(e) = f.write_all(line.as_bytes()).and_then(|_| f.flush()) {
                        *write_error.lock().unwrap_or_else(|e| e.into_inner()) = Some(e);
                        stop.store(true, Ordering::Relaxed);
                    }
                }
                fresh
                    .lock()
                    .unwrap_or_else(|e| e.into_inner())
                    .push(outcome);
                progress(completed.fetch_add(1, Ordering::Relaxed) + 1, total);
            });
        }
    });
    if let Some(e) = write_error.into_inner().unwrap_or_else(|e| e.into_inner()) {
        return Err(e);
    }
    done.extend(fresh.into_inner().unwrap_or_else(|e| e.into_inner()));
    Ok(done)
}

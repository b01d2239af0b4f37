//! A run's folder: what `shenlong bench --out DIR`, `shenlong.bench` and each shard of a
//! Ray run write — `results.jsonl` as outcomes come (an interrupted run resumes from it),
//! `run.json` (what ran, so the shards of one comparison can be merged), `report.json`,
//! `report.md` and the charts — and the merge of several such folders into one report, the
//! same figures as one unsharded run.

use super::report::{self, Report};
use super::run::{run, Outcome, RunOptions};
use super::Suite;
use crate::pipeline::{System, Translator};
use crate::scene::Scene;
use serde::{Deserialize, Serialize};
use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;

/// The results file of a run's folder.
pub const RESULTS: &str = "results.jsonl";
/// The description of a run (`run.json`).
pub const RUN: &str = "run.json";

/// What a run was, kept beside its results (`run.json`) so that shards can be merged.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct RunInfo {
    /// The suite's name.
    pub suite: String,
    /// The translator's name (offline, or the model).
    pub model: String,
    /// The prompt systems run, by name.
    pub systems: Vec<String>,
    /// Shard `K` of `N`, if the run was one.
    pub shard: Option<(usize, usize)>,
}

/// A folder that cannot be read or written, or folders that do not merge.
#[derive(Debug, thiserror::Error)]
pub enum FolderError {
    /// A file could not be read or written.
    #[error("cannot {action} {}: {source}", path.display())]
    Io {
        /// `read`, `write` or `create`.
        action: &'static str,
        /// The file or folder.
        path: PathBuf,
        /// Why.
        #[source]
        source: std::io::Error,
    },
    /// `run.json` is not a run's description.
    #[error("{} is not a run's description: {source}", path.display())]
    RunInfo {
        /// The file.
        path: PathBuf,
        /// Why.
        #[source]
        source: serde_json::Error,
    },
    /// Two folders of different comparisons.
    #[error("{} ran '{}' with {}, but the first ran '{}' with {}: only runs of one comparison merge", dir.display(), this.0, this.1, first.0, first.1)]
    Mismatch {
        /// The folder that differs.
        dir: PathBuf,
        /// Its suite and model.
        this: (String, String),
        /// The first folder's suite and model.
        first: (String, String),
    },
    /// Nothing to merge.
    #[error("no folder to merge")]
    Empty,
    /// `run.json` names a shard no run makes.
    #[error("{}: {reason}", path.display())]
    BadShard {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: super::run::ShardError,
    },
}

fn io<'a>(action: &'static str, path: &'a Path) -> impl FnOnce(std::io::Error) -> FolderError + 'a {
    move |source| FolderError::Io {
        action,
        path: path.to_path_buf(),
        source,
    }
}

/// What [`run_into`] and [`merge`] did.
#[derive(Clone, Debug)]
pub struct Finished {
    /// The report written.
    pub report: Report,
    /// Every outcome the report covers.
    pub outcomes: usize,
    /// What the caller should tell the user (lines skipped, shards missing).
    pub warnings: Vec<String>,
}

/// Runs `suite` into the folder `out` (made if needed): results appended to
/// `out/results.jsonl` as they come (what it already holds is not run again), then
/// `run.json`, the report and the charts. `progress` and `stop` are as [`run`]'s; a
/// stopped run still writes the report of what was done.
///
/// # Errors
/// A file that cannot be written.
pub fn run_into(
    out: &Path,
    suite: &Suite,
    scenes: &[Scene],
    translators: &[(System, Box<dyn Translator>)],
    options: &RunOptions,
    progress: &(dyn Fn(usize, usize) + Sync),
    stop: &AtomicBool,
) -> Result<Finished, FolderError> {
    std::fs::create_dir_all(out).map_err(io("create", out))?;
    let results = out.join(RESULTS);
    let outcomes = run(
        suite,
        scenes,
        translators,
        options,
        &results,
        progress,
        stop,
    )
    .map_err(io("write", &results))?;
    // Only the systems asked for, in case the folder holds others from earlier runs.
    let names: Vec<&str> = options.systems.iter().map(|s| s.name()).collect();
    let outcomes: Vec<Outcome> = outcomes
        .into_iter()
        .filter(|o| names.contains(&o.system.as_str()))
        .collect();
    let model = translators
        .first()
        .map_or_else(String::new, |(_, t)| t.name());
    let info = RunInfo {
        suite: suite.name.clone(),
        model: model.clone(),
        systems: names.iter().map(|s| (*s).to_string()).collect(),
        shard: options.shard,
    };
    let path = out.join(RUN);
    crate::io::write_atomic(
        &path,
        serde_json::to_string_pretty(&info)
            .expect("run info serialises")
            .as_bytes(),
    )
    .map_err(io("write", &path))?;
    let report = report::build(&suite.name, &model, &outcomes);
    write_report(out, &report)?;
    Ok(Finished {
        report,
        outcomes: outcomes.len(),
        warnings: Vec::new(),
    })
}

/// One report, written to `out`, from the folders of several runs of the same suite and
/// translator (the shards of one comparison): each outcome counted once, lines cut short
/// (a run killed mid-write) skipped with a warning, shards of `N` that are not among the
/// folders named in the report's `missing_shards`.
///
/// # Errors
/// A folder that is not a run's, folders of different comparisons, a file that cannot be
/// read or written.
pub fn merge(dirs: &[PathBuf], out: &Path) -> Result<Finished, FolderError> {
    let mut info: Option<RunInfo> = None;
    let mut seen = HashSet::new();
    let mut shards: Vec<(usize, usize)> = Vec::new();
    let mut outcomes = Vec::new();
    let mut warnings = Vec::new();
    for dir in dirs {
        let meta = dir.join(RUN);
        let text = crate::io::read_text_limited(&meta, crate::io::MAX_READ_BYTES)
            .map_err(io("read", &meta))?;
        let this: RunInfo = serde_json::from_str(&text).map_err(|source| FolderError::RunInfo {
            path: meta.clone(),
            source,
        })?;
        if let Some(first) = &info {
            if (&first.suite, &first.model) != (&this.suite, &this.model) {
                return Err(FolderError::Mismatch {
                    dir: dir.clone(),
                    this: (this.suite, this.model),
                    first: (first.suite.clone(), first.model.clone()),
                });
            }
        }
        let results = dir.join(RESULTS);
        let text = crate::io::read_text_limited(&results, crate::io::MAX_READ_BYTES)
            .map_err(io("read", &results))?;
        let mut unreadable = 0;
        for line in text.lines().filter(|l| !l.trim().is_empty()) {
            // As a resumed run does, a line cut short is skipped.
            let Ok(outcome) = serde_json::from_str::<Outcome>(line) else {
                unreadable += 1;
                continue;
            };
            if seen.insert((outcome.system.clone(), outcome.instance.clone())) {
                outcomes.push(outcome);
            }
        }
        if unreadable > 0 {
            warnings.push(format!(
                "{}: {unreadable} unreadable line(s) skipped (run that shard again to redo them)",
                results.display()
            ));
        }
        if let Some((k, n)) = this.shard {
            super::run::check_shard(k, n).map_err(|reason| FolderError::BadShard {
                path: meta.clone(),
                reason,
            })?;
            shards.push((k, n));
        }
        if info.is_none() {
            info = Some(this);
        }
    }
    let info = info.ok_or(FolderError::Empty)?;
    let missing = missing_shards(&shards);
    if !missing.is_empty() {
        warnings.push(format!(
            "shard(s) {} are not among the folders: the report covers part of the run",
            missing.join(", ")
        ));
    }
    std::fs::create_dir_all(out).map_err(io("create", out))?;
    let mut report = report::build(&info.suite, &info.model, &outcomes);
    report.missing_shards = missing;
    write_report(out, &report)?;
    Ok(Finished {
        report,
        outcomes: outcomes.len(),
        warnings,
    })
}

/// The shards `K/N` of the first folder's `N` that no folder ran.
fn missing_shards(shards: &[(usize, usize)]) -> Vec<String> {
    let Some(&(_, n)) = shards.first() else {
        return Vec::new();
    };
    let have: HashSet<usize> = shards
        .iter()
        .filter(|(_, m)| *m == n)
        .map(|(k, _)| *k)
        .collect();
    (1..=n)
        .filter(|k| !have.contains(k))
        .map(|k| format!("{k}/{n}"))
        .collect()
}

/// A chart: file stem, title, the figure drawn, its unit.
type Chart = (
    &'static str,
    &'static str,
    fn(&report::Figures) -> f64,
    &'static str,
);

/// Writes `report.json`, `report.md` and the charts (SVG; PNG too with the `png` feature)
/// to `out`, each atomically.
///
/// # Errors
/// A file that cannot be written.
pub fn write_report(out: &Path, rep: &Report) -> Result<(), FolderError> {
    let write = |name: &str, bytes: &[u8]| -> Result<(), FolderError> {
        let path = out.join(name);
        crate::io::write_atomic(&path, bytes).map_err(io("write", &path))
    };
    write(
        "report.json",
        serde_json::to_string_pretty(rep)
            .expect("reports serialise")
            .as_bytes(),
    )?;
    write("report.md", report::markdown(rep).as_bytes())?;
    let charts: [Chart; 4] = [
        (
            "success",
            "Success rate per category",
            |f| f.success_rate,
            "%",
        ),
        (
            "response",
            "Mean response time per category",
            |f| f.response_ms_mean,
            "ms",
        ),
        (
            "parse",
            "Model replies that parse, per category",
            |f| f.parse_rate,
            "%",
        ),
        (
            "valid",
            "Model replies that evaluate to a valid T·R·D, per category",
            |f| f.valid_rate,
            "%",
        ),
    ];
    for (name, title, value, unit) in charts {
        let svg = report::chart(rep, title, value, unit);
        write(&format!("{name}.svg"), svg.as_bytes())?;
        #[cfg(feature = "png")]
        {
            let png = crate::render::svg_to_png(&svg).map_err(|e| FolderError::Io {
                action: "write",
                path: out.join(format!("{name}.png")),
                source: std::io::Error::other(e),
            })?;
            write(&format!("{name}.png"), &png)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn missing_shards_are_those_of_n_no_folder_ran() {
        assert_eq!(missing_shards(&[]), Vec::<String>::new());
        assert_eq!(missing_shards(&[(1, 3), (3, 3)]), vec!["2/3".to_string()]);
        assert!(missing_shards(&[(2, 2), (1, 2)]).is_empty());
    }

    #[test]
    fn no_folder_is_an_error_and_a_folder_without_run_json_names_it() {
        let tmp = tempfile::tempdir().unwrap();
        assert!(matches!(merge(&[], tmp.path()), Err(FolderError::Empty)));
        let e = merge(&[tmp.path().to_path_buf()], &tmp.path().join("out")).unwrap_err();
        assert!(e.to_string().contains("run.json"), "{e}");
        assert!(!tmp.path().join("out").exists());
    }
}

//! `shenlong bench`: the paper's comparison, automatic and reproducible.

use anyhow::{bail, Context, Result};
use shenlong::bench::report;
use shenlong::bench::run::{run, RunOptions};
use shenlong::bench::Suite;
use shenlong::pipeline::backends::translator;
use shenlong::pipeline::{System, Translator};
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// Run a benchmark suite through one or more prompt systems and report success rates,
/// response times and tests of significance.
///
/// Every instantiated query is run through the pipeline and checked; results go to
/// OUT/results.jsonl as they come, so an interrupted run (Ctrl-C) resumes where it
/// stopped when run again with the same --out. The report is OUT/report.json,
/// OUT/report.md and charts (success, response time, replies that parse and that evaluate
/// to a valid T·R·D; SVG and PNG).
///
/// A large comparison can be split across machines with --shard K/N (for instance as an
/// array job on a cluster scheduler), each shard writing its own OUT; `--merge DIR…`
/// then builds one report from them, the same as an unsharded run's.
#[derive(clap::Args)]
#[command(after_help = "Examples:
  shenlong bench bench/dev.suite.json
  shenlong bench bench/dev.suite.json --llm openai:gpt-4o --system cga,euclidean,omniverse --jobs 8 --out results/gpt-4o
  shenlong bench bench/natural.suite.json --llm offline+openai:gpt-4o --collide --out results/cascade
  shenlong bench bench/dev.suite.json --llm openai:gpt-4o --shard 3/8 --out results/shard-3   # e.g. SLURM_ARRAY_TASK_ID=3
  shenlong bench --merge results/shard-* --out results/merged

See docs/benchmark.md for the suite format and the checks.")]
pub struct Args {
    /// The suite file (*.suite.json).
    #[arg(required_unless_present = "merge")]
    suite: Option<PathBuf>,
    /// Run only shard K of N (1-based) of the instances, e.g. 3/8.
    #[arg(long, value_name = "K/N", value_parser = parse_shard, conflicts_with = "merge")]
    shard: Option<(usize, usize)>,
    /// Build one report from the results of several runs (the shards of one comparison)
    /// into --out, instead of running anything.
    #[arg(long, value_name = "DIR", num_args = 1.., conflicts_with = "suite")]
    merge: Vec<PathBuf>,
    /// The prompt systems to compare, separated by commas.
    #[arg(long, value_name = "SYSTEMS", default_value = "cga")]
    system: String,
    /// Instances run at once (the model server is the bottleneck; vLLM and Ollama batch).
    #[arg(long, value_name = "N", default_value_t = 1)]
    jobs: usize,
    /// Where results and the report go (default: bench-results/SUITE-NAME).
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Run at most N instances per system.
    #[arg(long, value_name = "N")]
    limit: Option<usize>,
    /// Resolve collisions as `edit` does (off: the run measures the translator alone).
    #[arg(long)]
    collide: bool,
    #[command(flatten)]
    translator: super::TranslatorArgs,
}

/// `K/N` with 1 ≤ K ≤ N.
fn parse_shard(text: &str) -> Result<(usize, usize), String> {
    let (k, n) = text
        .split_once('/')
        .ok_or_else(|| format!("'{text}' is not K/N, e.g. 3/8"))?;
    let (k, n): (usize, usize) = (
        k.trim()
            .parse()
            .map_err(|_| format!("'{k}' is not a shard number"))?,
        n.trim()
            .parse()
            .map_err(|_| format!("'{n}' is not a number of shards"))?,
    );
    if n == 0 || k == 0 || k > n {
        return Err(format!("shard {k}/{n}: K must be between 1 and N"));
    }
    Ok((k, n))
}

/// What a run was, kept beside its results (`run.json`) so that shards can be merged.
#[derive(serde::Serialize, serde::Deserialize, PartialEq, Debug)]
struct RunInfo {
    suite: String,
    model: String,
    systems: Vec<String>,
    shard: Option<(usize, usize)>,
}

pub fn run_bench(args: Args) -> Result<()> {
    if !args.merge.is_empty() {
        return merge(&args.merge, args.out.as_deref());
    }
    let suite_path = args
        .suite
        .as_ref()
        .expect("clap requires the suite without --merge");
    let suite = Suite::load(suite_path)?;
    let mut systems = Vec::new();
    for name in args
        .system
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
    {
        let system = System::from_name(name)
            .with_context(|| format!("unknown system '{name}': use cga, euclidean, omniverse"))?;
        if !systems.contains(&system) {
            systems.push(system);
        }
    }
    if systems.is_empty() {
        bail!("--system names no system");
    }
    if args.jobs == 0 {
        bail!("--jobs must be at least 1");
    }
    // Everything is checked before anything runs: scenes, backends.
    let scenes = suite.load_scenes().map_err(anyhow::Error::msg)?;
    let mut translators: Vec<(System, Box<dyn Translator>)> = Vec::new();
    for &system in &systems {
        let settings = args.translator.settings(system)?;
        translators.push((
            system,
            translator(&args.translator.llm, &settings).map_err(super::llm_error)?,
        ));
    }
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("bench-results").join(&suite.name));
    std::fs::create_dir_all(&out).with_context(|| format!("cannot create {}", out.display()))?;

    let stop = Arc::new(AtomicBool::new(false));
    {
        let stop = Arc::clone(&stop);
        // A second Ctrl-C while stopping is left to the default handler's absence: the
        // run stops after the instances in flight.
        let _ = ctrlc::set_handler(move || stop.store(true, Ordering::Relaxed));
    }
    let bar = indicatif::ProgressBar::new(0);
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "{prefix} [{bar:30}] {pos}/{len} {elapsed_precise} ETA {eta}",
        )
        .expect("a valid template")
        .progress_chars("=> "),
    );
    bar.set_prefix(
        shenlong_cli::terminal::safe(&format!("{} ({})", suite.name, args.translator.llm))
            .into_owned(),
    );
    let options = RunOptions {
        systems: systems.clone(),
        jobs: args.jobs,
        limit: args.limit,
        collide: args.collide,
        shard: args.shard,
    };
    let progress = |done: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    };
    let results_path = out.join("results.jsonl");
    let outcomes = run(
        &suite,
        &scenes,
        &translators,
        &options,
        &results_path,
        &progress,
        &stop,
    )
    .with_context(|| format!("cannot write {}", results_path.display()))?;
    bar.finish_and_clear();

    // Only the systems asked for, in case the folder holds others from earlier runs.
    let names: Vec<&str> = systems.iter().map(|s| s.name()).collect();
    let outcomes: Vec<_> = outcomes
        .into_iter()
        .filter(|o| names.contains(&o.system.as_str()))
        .collect();
    let model = translators
        .first()
        .map_or_else(String::new, |(_, t)| t.name());
    let info = RunInfo {
        suite: suite.name.clone(),
        model: model.clone(),
        systems: names.iter().map(|s| s.to_string()).collect(),
        shard: args.shard,
    };
    shenlong::io::write_atomic(
        &out.join("run.json"),
        serde_json::to_string_pretty(&info)
            .expect("run info serialises")
            .as_bytes(),
    )
    .with_context(|| format!("cannot write {}", out.join("run.json").display()))?;
    let rep = report::build(&suite.name, &model, &outcomes);
    write_report(&out, &rep)?;
    if stop.load(Ordering::Relaxed) {
        bail!("interrupted: the report covers the {} instances done; run the same command again to resume", outcomes.len());
    }
    Ok(())
}

/// Writes report.json, report.md and the charts to `out`, and prints the summary.
fn write_report(out: &std::path::Path, rep: &report::Report) -> Result<()> {
    let write = |name: &str, bytes: &[u8]| -> Result<()> {
        shenlong::io::write_atomic(&out.join(name), bytes)
            .with_context(|| format!("cannot write {}", out.join(name).display()))
    };
    write(
        "report.json",
        serde_json::to_string_pretty(rep)
            .expect("reports serialise")
            .as_bytes(),
    )?;
    write("report.md", report::markdown(rep).as_bytes())?;
    let charts = [
        (
            "success",
            report::chart(rep, "Success rate per category", |f| f.success_rate, "%"),
        ),
        (
            "response",
            report::chart(
                rep,
                "Mean response time per category",
                |f| f.response_ms_mean,
                "ms",
            ),
        ),
        (
            "parse",
            report::chart(
                rep,
                "Model replies that parse, per category",
                |f| f.parse_rate,
                "%",
            ),
        ),
        (
            "valid",
            report::chart(
                rep,
                "Model replies that evaluate to a valid T·R·D, per category",
                |f| f.valid_rate,
                "%",
            ),
        ),
    ];
    for (name, svg) in &charts {
        write(&format!("{name}.svg"), svg.as_bytes())?;
        #[cfg(feature = "png")]
        write(
            &format!("{name}.png"),
            &shenlong::render::svg_to_png(svg).map_err(anyhow::Error::msg)?,
        )?;
    }
    super::write_stdout(report::summary(rep).as_bytes())?;
    shenlong_cli::say!("report: {}", out.join("report.md").display());
    Ok(())
}

/// One report from the results of several runs of the same suite and translator.
fn merge(dirs: &[PathBuf], out: Option<&std::path::Path>) -> Result<()> {
    let out = out.context("--merge needs --out DIR for the merged report")?;
    let mut info: Option<RunInfo> = None;
    let mut seen = std::collections::HashSet::new();
    let mut shards: Vec<(Option<(usize, usize)>, usize)> = Vec::new();
    let mut outcomes = Vec::new();
    for dir in dirs {
        let meta = dir.join("run.json");
        let text = std::fs::read_to_string(&meta).with_context(|| {
            format!(
                "cannot read {} (is {} a bench --out?)",
                meta.display(),
                dir.display()
            )
        })?;
        let this: RunInfo = serde_json::from_str(&text)
            .with_context(|| format!("{} is not a run's description", meta.display()))?;
        if let Some(first) = &info {
            if (&first.suite, &first.model) != (&this.suite, &this.model) {
                bail!(
                    "{} ran '{}' with {}, but the first ran '{}' with {}: only runs of one comparison merge",
                    dir.display(),
                    this.suite,
                    this.model,
                    first.suite,
                    first.model
                );
            }
        }
        let results = dir.join("results.jsonl");
        let text = std::fs::read_to_string(&results)
            .with_context(|| format!("cannot read {}", results.display()))?;
        let mut unreadable = 0;
        for line in text.lines().filter(|l| !l.trim().is_empty()) {
            // As a resumed run does, a line cut short (a run killed mid-write) is skipped.
            let Ok(outcome) = serde_json::from_str::<shenlong::bench::run::Outcome>(line) else {
                unreadable += 1;
                continue;
            };
            if seen.insert((outcome.system.clone(), outcome.instance.clone())) {
                outcomes.push(outcome);
            }
        }
        if unreadable > 0 {
            shenlong_cli::say!(
                "shenlong: warning: {}: {unreadable} unreadable line(s) skipped (run that shard again to redo them)",
                results.display()
            );
        }
        if let Some((_, n)) = this.shard {
            shards.push((this.shard, n));
        }
        if info.is_none() {
            info = Some(this);
        }
    }
    let info = info.context("--merge names no folder")?;
    if let Some(&(_, n)) = shards.first() {
        let mut have: Vec<usize> = shards
            .iter()
            .filter(|(_, m)| *m == n)
            .filter_map(|(s, _)| s.map(|(k, _)| k))
            .collect();
        have.sort_unstable();
        have.dedup();
        let missing: Vec<String> = (1..=n)
            .filter(|k| !have.contains(k))
            .map(|k| format!("{k}/{n}"))
            .collect();
        if !missing.is_empty() {
            shenlong_cli::say!(
                "shenlong: warning: shard(s) {} are not among the folders: the report covers part of the run",
                missing.join(", ")
            );
        }
    }
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    let rep = report::build(&info.suite, &info.model, &outcomes);
    write_report(out, &rep)
}

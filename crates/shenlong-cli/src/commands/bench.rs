//! `shenlong bench`: the paper's comparison, automatic and reproducible.

use anyhow::{bail, Context, Result};
use shenlong::bench::run::RunOptions;
use shenlong::bench::{folder, report, Suite};
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
    shenlong::bench::run::check_shard(k, n).map_err(|e| e.to_string())?;
    Ok((k, n))
}

pub fn run_bench(args: Args) -> Result<()> {
    if !args.merge.is_empty() {
        let out = args
            .out
            .as_deref()
            .context("--merge needs --out DIR for the merged report")?;
        let merged = folder::merge(&args.merge, out)?;
        return finish(out, &merged);
    }
    let suite_path = args
        .suite
        .as_ref()
        .expect("clap requires the suite without --merge");
    let suite = Suite::load(suite_path)?;
    let systems = System::parse_list(&args.system).map_err(|e| anyhow::anyhow!("--system: {e}"))?;
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
        systems,
        jobs: args.jobs,
        limit: args.limit,
        collide: args.collide,
        shard: args.shard,
    };
    let progress = |done: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    };
    let finished = folder::run_into(
        &out,
        &suite,
        &scenes,
        &translators,
        &options,
        &progress,
        &stop,
    )?;
    bar.finish_and_clear();
    finish(&out, &finished)?;
    if stop.load(Ordering::Relaxed) {
        bail!("interrupted: the report covers the {} instances done; run the same command again to resume", finished.outcomes);
    }
    Ok(())
}

/// Says what the run or merge left to say, and where the report is.
fn finish(out: &std::path::Path, finished: &folder::Finished) -> Result<()> {
    for warning in &finished.warnings {
        shenlong_cli::say!("shenlong: warning: {warning}");
    }
    super::write_stdout(report::summary(&finished.report).as_bytes())?;
    shenlong_cli::say!("report: {}", out.join("report.md").display());
    Ok(())
}

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
/// OUT/report.md and charts (success.svg, response.svg, and .png).
#[derive(clap::Args)]
#[command(after_help = "Examples:
  shenlong bench bench/dev.suite.json
  shenlong bench bench/dev.suite.json --llm openai:gpt-4o --system cga,euclidean,omniverse --jobs 8 --out results/gpt-4o

See docs/benchmark.md for the suite format and the checks.")]
pub struct Args {
    /// The suite file (*.suite.json).
    suite: PathBuf,
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

pub fn run_bench(args: Args) -> Result<()> {
    let suite = Suite::load(&args.suite)?;
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
            translator(&args.translator.llm, &settings).map_err(anyhow::Error::msg)?,
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
    bar.set_prefix(format!("{} ({})", suite.name, args.translator.llm));
    let options = RunOptions {
        systems: systems.clone(),
        jobs: args.jobs,
        limit: args.limit,
        collide: args.collide,
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
    let rep = report::build(&suite.name, &model, &outcomes);
    let write = |name: &str, bytes: &[u8]| -> Result<()> {
        shenlong::io::write_atomic(&out.join(name), bytes)
            .with_context(|| format!("cannot write {}", out.join(name).display()))
    };
    write(
        "report.json",
        serde_json::to_string_pretty(&rep)
            .expect("reports serialise")
            .as_bytes(),
    )?;
    write("report.md", report::markdown(&rep).as_bytes())?;
    let success = report::chart(&rep, "Success rate per category", |f| f.success_rate, "%");
    let response = report::chart(
        &rep,
        "Mean response time per category",
        |f| f.response_ms_mean,
        "ms",
    );
    write("success.svg", success.as_bytes())?;
    write("response.svg", response.as_bytes())?;
    #[cfg(feature = "png")]
    for (name, svg) in [("success.png", &success), ("response.png", &response)] {
        write(
            name,
            &shenlong::render::svg_to_png(svg).map_err(anyhow::Error::msg)?,
        )?;
    }
    super::write_stdout(report::summary(&rep).as_bytes())?;
    eprintln!("report: {}", out.join("report.md").display());
    if stop.load(Ordering::Relaxed) {
        bail!("interrupted: the report covers the {} instances done; run the same command again to resume", outcomes.len());
    }
    Ok(())
}

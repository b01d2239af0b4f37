//! The natural dev suites: instructions typed the way people type (no quotes, synonyms,
//! typos, plurals, picks by place, size and relation, refusals), on the built-in scenes
//! (`bench/natural.suite.json`) and on real ProcTHOR houses
//! (`bench/natural-procthor.suite.json`, which reads the shared data and skips without it).
//!
//! The floors below are the measured rates less a margin (docs/grounding.md has the
//! figures); the one target that has no margin is the worst failure: an edit that
//! succeeded on the wrong object or by the wrong amount.

mod support;

use shenlong::bench::report;
use shenlong::bench::run::{run, Outcome, RunOptions};
use shenlong::bench::{SceneSource, Suite};
use shenlong::offline::OfflineTranslator;
use shenlong::pipeline::{System, Translator};
use std::path::Path;
use std::sync::atomic::AtomicBool;
use support::shared_data::shared_data;

fn load(name: &str) -> Option<Suite> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../bench")
        .join(name);
    let mut suite = Suite::load(&path).unwrap();
    // House scenes name the shared data beside the repository; honour
    // SHENLONG_SHARED_DATA as every test does.
    for source in &mut suite.scenes {
        if let SceneSource::House { houses, assets, .. } = source {
            let file = |p: &Path| format!("procthor/{}", p.file_name().unwrap().to_string_lossy());
            *houses = shared_data(&file(houses))?;
            *assets = shared_data(&file(assets))?;
        }
    }
    Some(suite)
}

fn run_offline(suite: &Suite) -> Vec<Outcome> {
    let scenes = suite.load_scenes().unwrap();
    let dir = tempfile::tempdir().unwrap();
    let translators: Vec<(System, Box<dyn Translator>)> =
        vec![(System::Cga, Box::new(OfflineTranslator::new()))];
    let options = RunOptions {
        systems: vec![System::Cga],
        jobs: 2,
        limit: None,
        collide: true,
    };
    run(
        suite,
        &scenes,
        &translators,
        &options,
        &dir.path().join("results.jsonl"),
        &|_, _| {},
        &AtomicBool::new(false),
    )
    .unwrap()
}

fn check(name: &str, outcomes: &[Outcome], floor: f64) {
    let wrong: Vec<String> = outcomes
        .iter()
        .filter(|o| !o.success && o.error.is_none())
        .map(|o| format!("{} ({}): {}", o.instruction, o.scene, o.failures.join("; ")))
        .collect();
    assert!(
        wrong.is_empty(),
        "{name}: {} edits succeeded but did the wrong thing:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
    let report = report::build(name, "offline", outcomes);
    let rate = report.systems["cga"].overall.success_rate;
    let failed: Vec<String> = outcomes
        .iter()
        .filter(|o| !o.success)
        .map(|o| {
            format!(
                "{} ({}): {}",
                o.instruction,
                o.scene,
                o.error.clone().unwrap_or_default()
            )
        })
        .collect();
    assert!(
        rate >= floor,
        "{name}: {rate:.3} < {floor}\n{}",
        failed.join("\n")
    );
    // Refusals are counted as passing only when they were asked for.
    let refusals = outcomes
        .iter()
        .filter(|o| o.query.starts_with("refuse"))
        .count();
    assert!(refusals > 0);
}

#[test]
fn the_natural_suite_on_the_built_in_scenes() {
    let suite = load("natural.suite.json").unwrap();
    let outcomes = run_offline(&suite);
    assert!(outcomes.len() >= 300, "{}", outcomes.len());
    check("natural", &outcomes, 0.93);
}

#[test]
fn the_natural_suite_on_real_procthor_houses() {
    let Some(suite) = load("natural-procthor.suite.json") else {
        return;
    };
    let outcomes = run_offline(&suite);
    assert!(outcomes.len() >= 190, "{}", outcomes.len());
    check("natural-procthor", &outcomes, 0.95);
}

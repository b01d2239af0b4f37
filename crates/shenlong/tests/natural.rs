//! The natural dev suites: instructions typed the way people type — naming objects (no
//! quotes, synonyms, typos, plurals, picks by place, size and relation) on the built-in
//! scenes (`bench/natural.suite.json`) and on real ProcTHOR houses
//! (`bench/natural-procthor.suite.json`, which reads the shared data and skips without
//! it), and phrasing the edit (vague and spoken amounts, relative changes, take … put, the
//! room, polite forms, typos; `bench/natural-phrasing.suite.json`) — through the offline
//! translator and, for the model path, through a mock model server.
//!
//! The floors below are the measured rates less a margin (docs/grounding.md has the
//! figures); the one target that has no margin is the worst failure: an edit that
//! succeeded on the wrong object or by the wrong amount.

mod support;

use shenlong::llm::openai::{ClientOptions, OpenAiClient};
use shenlong::pipeline::LlmTranslator;
use support::mock_llm::{Handler, MockLlm, Reply};

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
    run_with(suite, Box::new(OfflineTranslator::new()))
}

fn run_with(suite: &Suite, translator: Box<dyn Translator>) -> Vec<Outcome> {
    let scenes = suite.load_scenes().unwrap();
    let dir = tempfile::tempdir().unwrap();
    let translators: Vec<(System, Box<dyn Translator>)> = vec![(System::Cga, translator)];
    let options = RunOptions {
        systems: vec![System::Cga],
        jobs: 2,
        limit: None,
        collide: true,
        shard: None,
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
}

/// The third round's suite, written by a helper who had not read the reader's code, on
/// three scenes of its own: names as 3D tools export them, chat around the instruction,
/// amounts towards a place, what must not move, vague amounts, verbs, picks by where
/// things are, views of a turn, spellings and placements (`bench/natural-v3.suite.json`).
#[test]
fn the_natural_v3_suite_on_exported_names_and_chat() {
    let suite = load("natural-v3.suite.json").unwrap();
    let outcomes = run_offline(&suite);
    assert_eq!(outcomes.len(), 417);
    check("natural-v3", &outcomes, 0.95);
}

/// A second blind suite of round three (`bench/holdout/holdout.suite.json`, 150 queries on
/// a Unity-named bedroom and a workshop of look-alike tools), written after the first
/// round-three changes by a helper who had read neither the code nor the other suites.
/// Measured once before it was read (86.0 %, one wrong edit); it is a dev suite now.
#[test]
fn the_holdout_suite_of_round_three() {
    let suite = load("holdout/holdout.suite.json").unwrap();
    let outcomes = run_offline(&suite);
    assert_eq!(outcomes.len(), 150);
    check("holdout", &outcomes, 0.90);
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

#[test]
fn the_natural_phrasing_suite() {
    let suite = load("natural-phrasing.suite.json").unwrap();
    let outcomes = run_offline(&suite);
    assert!(outcomes.len() >= 300, "{}", outcomes.len());
    check("natural-phrasing", &outcomes, 0.97);
    // Every category at 95 % at least.
    let report = report::build("natural-phrasing", "offline", &outcomes);
    for (category, figures) in &report.systems["cga"].categories {
        assert!(
            figures.success_rate >= 0.95,
            "{category}: {}",
            figures.success_rate
        );
    }
}

/// The model path: the grounded, templated query goes through the CGA prompt and the real
/// HTTP client to a mock server that answers as a model would (from the query alone, with
/// the offline grammar), and the reply is parsed and evaluated like any model's. Each
/// instance must end as it does offline — except straightening, which depends on the
/// object's current turn, which a model of the query alone cannot know.
#[test]
fn the_natural_suites_through_a_model_server() {
    let handler: Handler = std::sync::Arc::new(|body| {
        let user = body["messages"][1]["content"].as_str().unwrap_or_default();
        let query = user.trim_start_matches("Instruction: ");
        let variables = (1..20)
            .take_while(|k| query.contains(&format!("X{k}")))
            .count();
        match shenlong::offline::reply_for(query, variables) {
            Ok(reply) => Reply::Content(format!("```json\n{reply}\n```")),
            Err(_) => Reply::Content("I cannot do that.".into()),
        }
    });
    let server = MockLlm::start_with(handler, 20_000, 4);
    for name in ["natural.suite.json", "natural-phrasing.suite.json"] {
        let suite = load(name).unwrap();
        let mut options = ClientOptions::new(server.url.clone(), "mock-model", None);
        options.backoff = std::time::Duration::from_millis(5);
        let model = LlmTranslator {
            backend: Box::new(OpenAiClient::new(options)),
            system: System::Cga,
            retries: 0,
            deadline: std::time::Duration::from_secs(300),
            cache: None,
            recorder: None,
        };
        let through_model = run_with(&suite, Box::new(model));
        let offline = run_offline(&suite);
        let by_id = |o: &[Outcome]| -> std::collections::HashMap<String, bool> {
            o.iter().map(|x| (x.instance.clone(), x.success)).collect()
        };
        let (a, b) = (by_id(&through_model), by_id(&offline));
        for o in &through_model {
            if o.instruction.contains("straighten") || o.instruction.contains("square") {
                continue;
            }
            assert_eq!(
                a[&o.instance],
                b[&o.instance],
                "{name}: {} ({})",
                o.instruction,
                o.error.clone().unwrap_or_default()
            );
        }
        let wrong = through_model
            .iter()
            .filter(|o| {
                !o.success
                    && o.error.is_none()
                    && !o.instruction.contains("straighten")
                    && !o.instruction.contains("square")
            })
            .count();
        assert_eq!(wrong, 0, "{name}: wrong edits through the model path");
    }
    assert!(server.count() > 500);
}

/// The hard section on fronts and placements: facing with the objects' own fronts (ProcTHOR
/// furniture already turned), surfaces that already hold things, several objects on one
/// surface, the floor, staying on a level, stacks, and full surfaces refused.
#[test]
fn the_natural_placement_suite() {
    let Some(suite) = load("natural-placement.suite.json") else {
        return;
    };
    let outcomes = run_offline(&suite);
    assert!(outcomes.len() >= 100, "{}", outcomes.len());
    check("natural-placement", &outcomes, 0.95);
}

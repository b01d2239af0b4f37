//! The benchmark end to end: the project's dev suite (bench/dev.suite.json, 2,500
//! instances) through the offline translator and through a language model behind the real
//! HTTP client (a mock server answering on 127.0.0.1), with the offline translator's
//! targets checked.

mod support;

use shenlong::bench::report;
use shenlong::bench::run::{instances, run, RunOptions};
use shenlong::bench::Suite;
use shenlong::llm::openai::{ClientOptions, OpenAiClient};
use shenlong::pipeline::{LlmTranslator, System, Translator};
use std::path::Path;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;
use support::mock_llm::{MockLlm, Reply};

fn dev_suite() -> (Suite, Vec<shenlong::scene::Scene>) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../bench/dev.suite.json");
    let suite = Suite::load(&path).unwrap();
    let scenes = suite.load_scenes().unwrap();
    (suite, scenes)
}

fn run_all(translator: Box<dyn Translator>, jobs: usize) -> report::Report {
    let (suite, scenes) = dev_suite();
    let dir = tempfile::tempdir().unwrap();
    let translators = vec![(System::Cga, translator)];
    let options = RunOptions {
        systems: vec![System::Cga],
        jobs,
        limit: None,
        collide: false,
        shard: None,
    };
    let outcomes = run(
        &suite,
        &scenes,
        &translators,
        &options,
        &dir.path().join("results.jsonl"),
        &|_, _| {},
        &AtomicBool::new(false),
    )
    .unwrap();
    assert_eq!(
        outcomes.len(),
        2_500,
        "10 scenes × 50 queries × 5 variations"
    );
    report::build(&suite.name, "test", &outcomes)
}

#[test]
fn the_offline_translator_meets_its_targets_on_the_dev_suite() {
    let report = run_all(Box::new(shenlong::offline::OfflineTranslator::new()), 2);
    let cga = &report.systems["cga"];
    for (category, figures) in &cga.categories {
        let target = if category == "hard" { 0.70 } else { 0.95 };
        assert!(
            figures.success_rate >= target,
            "{category}: {:.3} < {target}\n{}",
            figures.success_rate,
            report::summary(&report)
        );
        assert_eq!(figures.n, 500);
    }
}

#[test]
fn the_dev_suite_through_a_model_server() {
    // The mock answers each CGA request as a model would, from the templated query; the
    // request goes through the real HTTP client, reply extraction and retries.
    let handler: support::mock_llm::Handler = Arc::new(|body| {
        let user = body["messages"][1]["content"].as_str().unwrap_or_default();
        let query = user.trim_start_matches("Instruction: ");
        let variables = (1..10)
            .take_while(|k| query.contains(&format!("X{k}")))
            .count();
        match shenlong::offline::reply_for(query, variables) {
            Ok(reply) => Reply::Content(format!("Here you go:\n```json\n{reply}\n```")),
            Err(_) => Reply::Content("I am not sure.".into()),
        }
    });
    let server = MockLlm::start_with(handler, 20_000, 4);
    let mut options = ClientOptions::new(server.url.clone(), "mock-model", None);
    options.backoff = std::time::Duration::from_millis(5);
    let translator = LlmTranslator {
        backend: Box::new(OpenAiClient::new(options)),
        system: System::Cga,
        retries: 1,
        deadline: std::time::Duration::from_secs(300),
        cache: None,
        recorder: None,
    };
    let report = run_all(Box::new(translator), 4);
    let offline = run_all(Box::new(shenlong::offline::OfflineTranslator::new()), 2);
    for (category, figures) in &report.systems["cga"].categories {
        let expected = offline.systems["cga"].categories[category].success_rate;
        assert!(
            (figures.success_rate - expected).abs() < 1e-9,
            "{category}: {} vs {expected}",
            figures.success_rate
        );
        assert!(figures.prompt_tokens > 0);
    }
    assert!(server.count() >= 2_500);
}

#[test]
fn instantiation_is_reproducible_from_the_seed() {
    let (suite, scenes) = dev_suite();
    let a = instances(&suite, &scenes);
    let b = instances(&suite, &scenes);
    assert_eq!(a, b);
    assert_eq!(a.len(), 2_500);
    let mut other = suite.clone();
    other.seed += 1;
    let c = instances(&other, &scenes);
    assert_ne!(a, c, "another seed picks other objects");
    // Every instance binds distinct objects, and its text names them.
    for i in &a {
        let mut objects: Vec<usize> = i.bound.iter().map(|(_, o)| *o).collect();
        let n = objects.len();
        objects.sort();
        objects.dedup();
        assert_eq!(objects.len(), n, "{}", i.id);
        assert!(!i.instruction.contains('{'), "{}", i.instruction);
    }
}

#[test]
fn an_interrupted_run_resumes_where_it_stopped() {
    let (suite, scenes) = dev_suite();
    let dir = tempfile::tempdir().unwrap();
    let results = dir.path().join("results.jsonl");
    let translators: Vec<(System, Box<dyn Translator>)> = vec![(
        System::Cga,
        Box::new(shenlong::offline::OfflineTranslator::new()),
    )];
    let first = RunOptions {
        systems: vec![System::Cga],
        jobs: 1,
        limit: Some(100),
        collide: false,
        shard: None,
    };
    run(
        &suite,
        &scenes,
        &translators,
        &first,
        &results,
        &|_, _| {},
        &AtomicBool::new(false),
    )
    .unwrap();
    assert_eq!(
        std::fs::read_to_string(&results).unwrap().lines().count(),
        100
    );
    let counted = std::sync::atomic::AtomicUsize::new(0);
    let all = RunOptions {
        limit: None,
        ..first
    };
    let outcomes = run(
        &suite,
        &scenes,
        &translators,
        &all,
        &results,
        &|_, _| {
            counted.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        },
        &AtomicBool::new(false),
    )
    .unwrap();
    assert_eq!(outcomes.len(), 2_500);
    assert_eq!(
        counted.into_inner(),
        2_400,
        "only the instances not done before"
    );
    // A stop flag set before the run leaves the file as it was.
    let stopped = run(
        &suite,
        &scenes,
        &translators,
        &all,
        &dir.path().join("other.jsonl"),
        &|_, _| {},
        &AtomicBool::new(true),
    )
    .unwrap();
    assert!(stopped.is_empty());
}

#[test]
fn bad_suites_fail_before_anything_runs() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let err = |text: &str| Suite::parse(text, dir).unwrap_err().to_string();
    let base = r#"{"name": "t", "scenes": ["s.json"], "queries": [{"id": "q", "category": "simple", "text": "move the '{A}' left", "expect": [{"check": "moved", "object": "A", "delta": [-1, 0, 0]}]}]}"#;
    assert!(Suite::parse(base, dir).is_ok());
    assert!(err(&base.replace("\"simple\"", "\"easy\"")).contains("unknown category 'easy'"));
    assert!(err(&base.replace("\"moved\"", "\"teleported\""))
        .contains("expect[0]: unknown variant `teleported`"));
    assert!(err(&base.replace("\"object\": \"A\"", "\"object\": \"B\""))
        .contains("names {B}, which the text does not have"));
    // A query with no placeholder may name an object `TV`.
    let plain = base
        .replace("'{A}'", "TV")
        .replace("\"object\": \"A\"", "\"object\": \"TV\"");
    assert!(Suite::parse(&plain, dir).is_ok(), "{plain}");
    assert!(
        err(&base.replace("\"queries\"", "\"variations\": 0, \"queries\""))
            .contains("variations must be at least 1")
    );
    assert!(err(&base.replace(
        "\"expect\"",
        "\"pick\": {\"A\": {\"tall\": true}}, \"expect\""
    ))
    .contains("pick.A: unknown field `tall`"));
    assert!(err(&base.replace("\"name\": \"t\",", "")).contains("missing field `name`"));
    assert!(err("{").contains("invalid suite at line 1"));
}

#[test]
fn a_query_runs_on_the_scenes_it_names_by_name_or_file_and_no_other_name_passes() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("hall.json"),
        r#"{"name": "exam hall", "objects": [{"name": "desk", "size": [1, 0.75, 0.6], "position": [0, 0, 0]}]}"#,
    )
    .unwrap();
    let suite = |scenes: &str| {
        let text = format!(
            r#"{{"name": "t", "scenes": ["hall.json"], "queries": [{{"id": "q", "category": "simple", "text": "move the desk left", "scenes": [{scenes}], "expect": [{{"check": "moved", "object": "desk", "delta": [-1, 0, 0]}}]}}]}}"#
        );
        Suite::parse(&text, dir.path()).unwrap()
    };
    for named in [r#""exam hall""#, r#""hall.json""#] {
        let s = suite(named);
        let scenes = s.load_scenes().unwrap();
        assert_eq!(instances(&s, &scenes).len(), 1, "{named}");
    }
    let s = suite(r#""hall""#);
    let e = s.load_scenes().unwrap_err().to_string();
    assert!(
        e.contains("scenes names 'hall'") && e.contains("exam hall"),
        "{e}"
    );
}

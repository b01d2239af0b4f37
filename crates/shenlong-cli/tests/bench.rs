//! `shenlong bench` through the cascade, scored by kind, split into shards and merged.

#[path = "../../shenlong/tests/support/mock_llm.rs"]
mod mock_llm;

mod support;

use mock_llm::{MockLlm, Reply};
use serde_json::Value;
use std::path::{Path, PathBuf};
use support::{shenlong_with_env, stderr};

/// A suite some of whose instructions the offline translator does not read (they go to
/// the model): the fifth held-out suite.
fn suite() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../bench/holdout5/holdout5.suite.json")
}

fn bench(server: &MockLlm, out: &Path, extra: &[&str]) {
    let suite = suite();
    let mut args = vec![
        "bench",
        suite.to_str().unwrap(),
        "--llm",
        "offline+openai:mock-model",
        "--base-url",
        &server.url,
        "--collide",
        "--no-cache",
        "--jobs",
        "2",
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    let o = shenlong_with_env(&args, &[("OPENAI_API_KEY", "sk-bench")]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// The report without what depends on the clock.
fn untimed(mut v: Value) -> Value {
    fn strip(v: &mut Value) {
        match v {
            Value::Object(map) => {
                map.retain(|k, _| !k.contains("response") && !k.ends_with("_ms"));
                map.values_mut().for_each(strip);
            }
            Value::Array(items) => {
                items.retain(|i| i.get("measure").is_none_or(|m| m != "response_ms"));
                items.iter_mut().for_each(strip);
            }
            _ => {}
        }
    }
    strip(&mut v);
    v
}

fn report(dir: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).unwrap()).unwrap()
}

#[test]
fn a_cascade_benchmark_is_scored_by_kind_and_shards_merge_into_the_same_report() {
    // Whatever the offline translator cannot read, the model answers with a valid
    // transformation that moves nothing (so those instances fail their checks).
    let server = MockLlm::start(vec![Reply::Content("{\"X1\": \"T(0*e1)\"}".into()); 400]);
    let dir = tempfile::tempdir().unwrap();
    let whole = dir.path().join("whole");
    bench(&server, &whole, &[]);
    let asked = server.count();
    let r = report(&whole);
    let cga = &r["systems"]["cga"]["overall"];
    let n = cga["n"].as_u64().unwrap();
    let offline = cga["answered_offline"].as_u64().unwrap();
    let model = cga["answered_by_model"].as_u64().unwrap();
    assert!(offline > n / 2, "most are answered offline: {cga}");
    assert!(model > 0, "some went to the model: {cga}");
    assert_eq!(
        cga["replies"].as_u64().unwrap(),
        asked as u64,
        "one reply per model answer"
    );
    assert_eq!(cga["parse_rate"], 1.0);
    assert_eq!(cga["valid_rate"], 1.0);
    assert_eq!(
        cga["model_success_rate"], 0.0,
        "the mock's answers move nothing"
    );
    let md = std::fs::read_to_string(whole.join("report.md")).unwrap();
    assert!(md.contains("What went wrong, by kind"), "{md}");
    assert!(whole.join("parse.svg").exists() && whole.join("valid.svg").exists());

    // Two shards, merged: the same figures as the whole run.
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    bench(&server, &a, &["--shard", "1/2"]);
    bench(&server, &b, &["--shard", "2/2"]);
    let ra = report(&a);
    assert!(ra["systems"]["cga"]["overall"]["n"].as_u64().unwrap() < n);
    let merged = dir.path().join("merged");
    let o = support::shenlong(&[
        "bench",
        "--merge",
        a.to_str().unwrap(),
        b.to_str().unwrap(),
        "--out",
        merged.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(untimed(report(&merged)), untimed(report(&whole)));

    // Runs of different comparisons do not merge.
    let other = dir.path().join("other");
    std::fs::create_dir_all(&other).unwrap();
    std::fs::write(
        other.join("run.json"),
        r#"{"suite": "dev", "model": "offline", "systems": ["cga"], "shard": null}"#,
    )
    .unwrap();
    std::fs::write(other.join("results.jsonl"), "").unwrap();
    let o = support::shenlong(&[
        "bench",
        "--merge",
        a.to_str().unwrap(),
        other.to_str().unwrap(),
        "--out",
        dir.path().join("bad").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("only runs of one comparison merge"),
        "{}",
        stderr(&o)
    );
    let o = support::shenlong(&["bench", "--shard", "3/2", suite().to_str().unwrap()]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("K must be between 1 and N"),
        "{}",
        stderr(&o)
    );
}

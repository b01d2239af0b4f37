//! `shenlong edit` as a user runs it: offline, and against a mock model server.

#[path = "../../shenlong/tests/support/mock_llm.rs"]
mod mock_llm;

mod support;

use mock_llm::{MockLlm, Reply};
use std::path::Path;
use support::{examples_dir, object, read_json, shenlong, shenlong_with_env, stderr};

#[test]
fn the_readme_command_works_offline() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("edited.json");
    let report = dir.path().join("report.json");
    let scene = examples_dir().join("workshop.json");
    let o = shenlong(&[
        "edit",
        scene.to_str().unwrap(),
        "put the 'orange bottle' on top of the 'tool table'",
        "-o",
        out.to_str().unwrap(),
        "--json",
        report.to_str().unwrap(),
        "--no-cache",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v = read_json(&out);
    let bottle = object(&v, "orange bottle");
    assert_eq!(bottle["position"][1], 0.9);
    // `--json` writes the outcome, as every front end answers it, with the whole report.
    let outcome = read_json(&report);
    assert_eq!(outcome["operation"], "edit");
    assert_eq!(outcome["moved"][0]["object"], "orange bottle");
    assert_eq!(outcome["moved"][0]["how"], "moved");
    assert_eq!(outcome["moved"][0]["after"]["position"][1], 0.9);
    assert_eq!(outcome["understood"]["query"], "put X1 on top of X2");
    let r = &outcome["report"];
    assert_eq!(r["query"], "put X1 on top of X2");
    assert_eq!(r["bindings"][1]["object"], "tool table");
    assert_eq!(r["model"], "offline");
    assert_eq!(r["system"], "cga");
    for key in [
        "exchanges",
        "objects",
        "collisions_resolved",
        "timings_ms",
        "tokens",
        "retries",
        "cache_hit",
    ] {
        assert!(r.get(key).is_some(), "the report has {key}");
    }
}

#[test]
fn an_unknown_object_fails_with_a_suggestion_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    std::fs::write(&out, "keep").unwrap();
    let o = shenlong(&[
        "edit",
        "example:living_room",
        "move the 'sofaa' left",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert_eq!(
        stderr(&o).trim(),
        "shenlong: unknown object 'sofaa' — did you mean 'sofa'?"
    );
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "keep");
    let o = shenlong(&[
        "edit",
        "example:living_room",
        "sing a song about the 'sofa'",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("could not read")
            && stderr(&o).contains("--llm")
            && stderr(&o).matches("offline+openai:MODEL").count() == 1,
        "{}",
        stderr(&o)
    );
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "keep");
}

#[test]
fn an_openai_compatible_server_through_base_url() {
    let server = MockLlm::start(vec![Reply::Content(
        "Sure:\n```json\n{\"X1\": \"T(-1 * e1)\"}\n```".into(),
    )]);
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    let o = shenlong_with_env(
        &[
            "edit",
            "example:living_room",
            "move the 'sofa' to the left",
            "--llm",
            "openai:gpt-test",
            "--base-url",
            &server.url,
            "-o",
            out.to_str().unwrap(),
            "--no-cache",
        ],
        &[("OPENAI_API_KEY", "sk-cli-secret")],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("sk-cli-secret"));
    let r = &server.captured()[0];
    assert_eq!(r.header("authorization"), Some("Bearer sk-cli-secret"));
    assert_eq!(r.body["model"], "gpt-test");
    let v = read_json(&out);
    let sofa = object(&v, "sofa");
    assert_eq!(sofa["position"], serde_json::json!([-1, 0, -1.9]));
}

#[test]
fn a_model_that_never_answers_right_leaves_the_output_alone() {
    let server = MockLlm::start(vec![Reply::Content("{\"X1\": \"X1.max\"}".into()); 3]);
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    std::fs::write(&out, "keep").unwrap();
    let o = shenlong(&[
        "edit",
        "example:living_room",
        "move the 'sofa' up",
        "--llm",
        "ollama:mock",
        "--base-url",
        &server.url,
        "--retries",
        "2",
        "-o",
        out.to_str().unwrap(),
        "--no-cache",
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert_eq!(e.lines().count(), 1, "{e}");
    assert!(
        e.contains(
            "mock gave no usable answer after 3 attempts; the last error: X1: result is a vector"
        ),
        "{e}"
    );
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "keep");
}

#[test]
fn backend_specs_are_checked() {
    for (option, value, message) in [
        ("--llm", "openai:gpt-4o", "needs OPENAI_API_KEY"),
        (
            "--llm",
            "claude",
            "'--llm <BACKEND>': unknown translator 'claude'",
        ),
        (
            "--system",
            "omniverse",
            "the offline translator answers in CGA only",
        ),
        // Regression: a duration this long overflowed and panicked.
        (
            "--timeout",
            "1e20",
            "--timeout 100000000000000000000: give a number of seconds",
        ),
        ("--connect-timeout", "0", "give a number of seconds > 0"),
        ("--retries", "many", "invalid value 'many' for '--retries"),
    ] {
        let o = shenlong(&[
            "edit",
            "example:office",
            "move the 'plant' left",
            option,
            value,
        ]);
        assert!(
            stderr(&o).contains(message),
            "{option} {value}: {}",
            stderr(&o)
        );
        assert!(
            matches!(o.status.code(), Some(1 | 2)),
            "{option} {value}: no panic"
        );
        assert_eq!(stderr(&o).lines().count(), 1, "{option} {value}: one line");
    }
}

#[test]
fn bench_writes_the_report_and_charts() {
    let dir = tempfile::tempdir().unwrap();
    let suite = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../bench/dev.suite.json");
    let out = dir.path().join("out");
    let o = shenlong(&[
        "bench",
        suite.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--limit",
        "120",
        "--no-cache",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let table = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(
        table.contains("cga") && table.contains("overall"),
        "{table}"
    );
    for file in [
        "report.json",
        "report.md",
        "success.svg",
        "response.svg",
        "success.png",
        "results.jsonl",
    ] {
        assert!(out.join(file).is_file(), "{file}");
    }
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(
        md.contains("| cga | 80.0 % | 18 s |"),
        "the paper's figures beside ours"
    );
    let bad = dir.path().join("bad.suite.json");
    std::fs::write(
        &bad,
        r#"{"name": "x", "scenes": ["nowhere.json"], "queries": []}"#,
    )
    .unwrap();
    let o = shenlong(&[
        "bench",
        bad.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("nowhere.json"), "{}", stderr(&o));
}

#[test]
fn natural_names_are_grounded_and_reported() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("edited.json");
    let report = dir.path().join("report.json");
    let o = shenlong(&[
        "edit",
        "example:living_room",
        "move the couch 30 cm to the left and turn the right-hand speaker 90 degrees",
        "-o",
        out.to_str().unwrap(),
        "--json",
        report.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v = read_json(&out);
    assert_eq!(object(&v, "sofa")["position"][0], -0.3);
    assert!(object(&v, "speaker 2")["rotation"].is_array());
    assert!(object(&v, "speaker")["rotation"].is_null());
    let outcome = read_json(&report);
    let r = &outcome["report"];
    assert_eq!(r["grounding"][0]["phrase"], "the couch");
    assert_eq!(r["grounding"][0]["objects"][0], "sofa");
    assert_eq!(r["grounding"][0]["reasons"][0]["kind"], "synonym");
    assert_eq!(r["grounding"][1]["objects"][0], "speaker 2");
    assert_eq!(r["grounding"][1]["reasons"][1]["kind"], "modifier");
}

#[test]
fn an_ambiguous_phrase_is_refused_naming_the_candidates_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    let o = shenlong(&[
        "edit",
        "example:dining_room",
        "move the chair 30 cm to the left",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    let e = stderr(&o);
    assert_eq!(e.lines().count(), 1, "{e}");
    assert!(
        e.starts_with("shenlong: \"the chair\" could mean chair, chair 2, chair 3 and chair 4: name one ('chair 3') or say which ('the left chair', 'the chair nearest the "),
        "{e}"
    );
    assert!(!out.exists());
}

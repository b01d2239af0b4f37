//! The real HTTP client and the pipeline against a mock OpenAI-compatible server on
//! 127.0.0.1.

mod support;

use shenlong::llm::cache::Cache;
use shenlong::llm::openai::{ClientOptions, OpenAiClient};
use shenlong::llm::record::Recorder;
use shenlong::llm::replay::Replay;
use shenlong::pipeline::{edit, Edit, EditError, EditOptions, LlmTranslator, System};
use std::time::Duration;
use support::mock_llm::{MockLlm, Reply};

const ON_TOP: &str = "T(((X2.max | e2) - (X1.min | e2)) * e2 + ((X2.center - X1.center) | e1) * e1 + ((X2.center - X1.center) | e3) * e3)";

fn client(server: &MockLlm, key: Option<&str>) -> OpenAiClient {
    let mut options = ClientOptions::new(server.url.clone(), "mock-model", key.map(str::to_string));
    options.backoff = Duration::from_millis(10);
    options.request_timeout = Duration::from_secs(5);
    OpenAiClient::new(options)
}

fn translator(server: &MockLlm, system: System) -> LlmTranslator {
    LlmTranslator {
        backend: Box::new(client(server, Some("sk-test-secret"))),
        system,
        retries: 5,
        deadline: std::time::Duration::from_secs(300),
        cache: None,
        recorder: None,
    }
}

fn workshop() -> shenlong::scene::Scene {
    shenlong::examples::build("workshop").unwrap()
}

/// Runs [`INSTRUCTION`] on `scene` through the mock server, in the given prompt system.
fn edit_workshop(
    scene: &mut shenlong::scene::Scene,
    server: &MockLlm,
    system: System,
) -> Result<Edit, EditError> {
    edit(
        scene,
        INSTRUCTION,
        &translator(server, system),
        &EditOptions::default(),
    )
}

const INSTRUCTION: &str = "put the 'orange bottle' on top of the 'tool table'";

fn bottle_on_table(scene: &shenlong::scene::Scene) -> bool {
    let b = scene.objects[scene.find("orange bottle").unwrap()].world_aabb();
    (b.min.y - 0.9).abs() < 1e-9
}

#[test]
fn request_shape_and_a_cga_edit() {
    let server = MockLlm::start(vec![Reply::Content(format!("{{\"X1\": \"{ON_TOP}\"}}"))]);
    let mut scene = workshop();
    let result = edit_workshop(&mut scene, &server, System::Cga).unwrap();
    assert!(bottle_on_table(&scene));
    let requests = server.captured();
    assert_eq!(requests.len(), 1);
    let r = &requests[0];
    assert_eq!(r.path, "/v1/chat/completions");
    assert_eq!(r.header("authorization"), Some("Bearer sk-test-secret"));
    assert_eq!(r.body["model"], "mock-model");
    assert_eq!(r.body["temperature"], 0);
    let messages = r.body["messages"].as_array().unwrap();
    assert_eq!(messages[0]["role"], "system");
    assert_eq!(
        messages[1],
        serde_json::json!({"role": "user", "content": "Instruction: put X1 on top of X2"})
    );
    assert_eq!(result.report.tokens.prompt, 321);
    assert_eq!(result.report.model, "mock-model");
    // The key appears nowhere in the report.
    assert!(!serde_json::to_string(&result.report)
        .unwrap()
        .contains("sk-test-secret"));
}

#[test]
fn replies_in_prose_fences_and_python_dicts() {
    for reply in [
        format!("Let me think.\n1. X1 must go up.\n```json\n{{\"X1\": \"{ON_TOP}\"}}\n```\nDone!"),
        format!("```python\n{{'X1': '{ON_TOP}',}}\n```"),
    ] {
        let server = MockLlm::start(vec![Reply::Content(reply)]);
        let mut scene = workshop();
        edit_workshop(&mut scene, &server, System::Cga).unwrap();
        assert!(bottle_on_table(&scene));
    }
}

#[test]
fn a_broken_reply_is_retried_with_the_error() {
    let server = MockLlm::start(vec![
        Reply::Content("{\"X1\": \"T(X2.max | e2\"}".into()),
        Reply::Content(format!("{{\"X1\": \"{ON_TOP}\"}}")),
    ]);
    let mut scene = workshop();
    let result = edit_workshop(&mut scene, &server, System::Cga).unwrap();
    assert!(bottle_on_table(&scene));
    assert_eq!(result.report.retries, 1);
    let second = &server.captured()[1].body["messages"];
    let messages = second.as_array().unwrap();
    assert_eq!(messages.len(), 4, "system, user, the bad answer, the error");
    assert_eq!(messages[2]["role"], "assistant");
    let feedback = messages[3]["content"].as_str().unwrap();
    assert!(
        feedback.contains("X1: expected ')' but found the end of the expression at column 14"),
        "{feedback}"
    );
    assert_eq!(result.report.exchanges.len(), 2);
    assert!(result.report.exchanges[0].error.is_some());
}

#[test]
fn rate_limits_are_retried_honouring_retry_after() {
    let server = MockLlm::start(vec![
        Reply::Raw(
            429,
            vec![("Retry-After".into(), "0".into())],
            "{\"error\": {\"message\": \"slow down\"}}".into(),
        ),
        Reply::Raw(503, vec![], "overloaded".into()),
        Reply::Content(format!("{{\"X1\": \"{ON_TOP}\"}}")),
    ]);
    let mut scene = workshop();
    edit_workshop(&mut scene, &server, System::Cga).unwrap();
    assert!(bottle_on_table(&scene));
    assert_eq!(server.count(), 3);
}

#[test]
fn a_server_that_never_answers_times_out_clearly() {
    let server = MockLlm::start(vec![Reply::Hang(Duration::from_secs(3)); 2]);
    let mut options = ClientOptions::new(server.url.clone(), "mock-model", None);
    options.request_timeout = Duration::from_millis(500);
    options.max_attempts = 2;
    options.backoff = Duration::from_millis(10);
    let t = LlmTranslator {
        backend: Box::new(OpenAiClient::new(options)),
        system: System::Cga,
        retries: 5,
        deadline: std::time::Duration::from_secs(300),
        cache: None,
        recorder: None,
    };
    let mut scene = workshop();
    let before = scene.clone();
    let e = edit(&mut scene, INSTRUCTION, &t, &EditOptions::default()).unwrap_err();
    assert!(e.message.contains("did not answer within 0.5 s"), "{e}");
    assert!(e.message.contains("after 2 attempts"), "{e}");
    assert_eq!(
        scene.objects[1].similarity(),
        before.objects[1].similarity(),
        "nothing changed"
    );
}

#[test]
fn five_bad_replies_give_up_cleanly() {
    let server = MockLlm::start(vec![
        Reply::Content("I would move the bottle up.".into());
        6
    ]);
    let mut scene = workshop();
    let before = scene.clone();
    let e = edit_workshop(&mut scene, &server, System::Cga).unwrap_err();
    assert!(
        e.message
            .starts_with("mock-model gave no usable answer after 6 attempts"),
        "{e}"
    );
    assert!(e.message.contains("no JSON object found"), "{e}");
    assert_eq!(server.count(), 6);
    assert_eq!(
        scene.objects[1].similarity(),
        before.objects[1].similarity()
    );
}

#[test]
fn http_errors_name_the_cause_without_the_key() {
    let server = MockLlm::start(vec![Reply::Raw(
        401,
        vec![],
        "{\"error\": {\"message\": \"Incorrect API key provided: sk-te****cret\"}}".into(),
    )]);
    let mut scene = workshop();
    let e = edit_workshop(&mut scene, &server, System::Cga).unwrap_err();
    assert!(e.message.contains("HTTP 401 (check OPENAI_API_KEY)"), "{e}");
    assert!(!e.message.contains("sk-test-secret"));
}

#[test]
fn the_cache_serves_one_reply_to_every_scene() {
    let dir = tempfile::tempdir().unwrap();
    let server = MockLlm::start(vec![Reply::Content("{\"X1\": \"T(0.5 * e1)\"}".into())]);
    let make = || LlmTranslator {
        backend: Box::new(client(&server, None)),
        system: System::Cga,
        retries: 0,
        deadline: std::time::Duration::from_secs(300),
        cache: Some(Cache::new(dir.path())),
        recorder: None,
    };
    let mut kitchen = shenlong::examples::build("kitchen").unwrap();
    let mut office = shenlong::examples::build("office").unwrap();
    let first = edit(
        &mut kitchen,
        "move the 'trash can' to the right",
        &make(),
        &EditOptions::default(),
    )
    .unwrap();
    assert!(!first.report.cache_hit);
    // A different scene, a different object, the same templated query: no request.
    let second = edit(
        &mut office,
        "move the 'plant' to the right",
        &make(),
        &EditOptions::default(),
    )
    .unwrap();
    assert!(second.report.cache_hit);
    assert_eq!(server.count(), 1);
    let plant = office.objects[office.find("plant").unwrap()].similarity();
    assert!((plant.translation.x - (-3.1 + 0.5)).abs() < 1e-9);
    // Another server serving a model of the same name is asked, not answered from the
    // first one's cache.
    let other = MockLlm::start(vec![Reply::Content("{\"X1\": \"T(0.5*e1)\"}".into())]);
    let elsewhere = LlmTranslator {
        backend: Box::new(client(&other, None)),
        ..make()
    };
    let mut kitchen = shenlong::examples::build("kitchen").unwrap();
    let third = edit(
        &mut kitchen,
        "move the 'trash can' to the right",
        &elsewhere,
        &EditOptions::default(),
    )
    .unwrap();
    assert!(!third.report.cache_hit);
    assert_eq!(other.count(), 1);
}

#[test]
fn record_then_replay_gives_the_same_edit() {
    let dir = tempfile::tempdir().unwrap();
    let log = dir.path().join("exchanges.jsonl");
    let server = MockLlm::start(vec![
        Reply::ContentNoUsage("{\"X1\": \"R(np.pi/2, e3\"}".into()),
        Reply::ContentNoUsage("{\"X1\": \"R(np.pi/2, e3, e1)\"}".into()),
    ]);
    let recorded = LlmTranslator {
        backend: Box::new(client(&server, None)),
        system: System::Cga,
        retries: 2,
        deadline: std::time::Duration::from_secs(300),
        cache: None,
        recorder: Some(Recorder::open(&log).unwrap()),
    };
    let mut a = workshop();
    let first = edit(
        &mut a,
        "turn the 'stool' a quarter",
        &recorded,
        &EditOptions::default(),
    )
    .unwrap();
    assert!(
        first.report.tokens.estimated,
        "no usage from the server: counted locally"
    );
    assert!(first.report.tokens.prompt > 100);
    assert_eq!(std::fs::read_to_string(&log).unwrap().lines().count(), 2);
    let replay = LlmTranslator {
        backend: Box::new(Replay::load(&log).unwrap()),
        system: System::Cga,
        retries: 2,
        deadline: std::time::Duration::from_secs(300),
        cache: None,
        recorder: None,
    };
    let mut b = workshop();
    let second = edit(
        &mut b,
        "turn the 'stool' a quarter",
        &replay,
        &EditOptions::default(),
    )
    .unwrap();
    assert_eq!(second.report.retries, 1);
    let stool = |s: &shenlong::scene::Scene| s.objects[s.find("stool").unwrap()].similarity();
    assert_eq!(stool(&a), stool(&b));
    // A request that was never recorded is a clear error.
    let e = edit(
        &mut b,
        "move the 'stool' up",
        &replay,
        &EditOptions::default(),
    )
    .unwrap_err();
    assert!(
        e.message.contains("has no recorded reply for this request"),
        "{e}"
    );
}

#[test]
fn the_baselines_work_against_the_server_too() {
    let server = MockLlm::start(vec![
        Reply::Content("{\"X1\": \"translation(X2.center[0] - X1.center[0], X2.max[1] - X1.min[1], X2.center[2] - X1.center[2])\"}".into()),
        Reply::Content("{\"X1\": {\"position\": [0, 1.025, 0], \"rotation\": [0, 0, 0]}}".into()),
    ]);
    for system in [System::Euclidean, System::Omniverse] {
        let mut scene = workshop();
        let result = edit_workshop(&mut scene, &server, system).unwrap();
        assert!(bottle_on_table(&scene), "{}", system.name());
        assert_eq!(result.report.system, system.name());
    }
    let captured = server.captured();
    let euclidean_user = captured[0].body["messages"][1]["content"].as_str().unwrap();
    assert!(
        euclidean_user.contains("X2: min [-0.8, 0, -0.4], max [0.8, 0.9, 0.4]"),
        "{euclidean_user}"
    );
    let omniverse_user = captured[1].body["messages"][1]["content"].as_str().unwrap();
    assert!(
        omniverse_user.contains("X1: dimensions [0.08, 0.25, 0.08], centre [-2, 0.125, 1.2]"),
        "{omniverse_user}"
    );
}

#[test]
fn a_model_server_that_echoes_the_key_cannot_make_it_appear() {
    // A 401 body with the bearer token verbatim, as some proxies answer.
    let server = MockLlm::start(vec![Reply::Raw(
        401,
        vec![],
        "{\"error\": {\"message\": \"invalid credentials: Authorization: Bearer sk-test-secret (sk-test-secret)\"}}".into(),
    )]);
    let mut scene = workshop();
    let e = edit_workshop(&mut scene, &server, System::Cga).unwrap_err();
    assert!(e.message.contains("HTTP 401"), "{e}");
    assert!(!e.message.contains("sk-test-secret"), "{e}");
    assert!(e.message.contains("[redacted]"), "{e}");
}

#[test]
fn object_names_never_reach_the_model_in_any_system() {
    // Unquoted names, a synonym, a typo, a group and a pick: only variables are sent.
    let instructions = [
        "put the orange bottle on the tool table",
        "move the trash barrel to the left",
        "put the hammer and the screwdriver on the workbench",
        "move the drill a metre to the right",
    ];
    let names: Vec<String> = workshop().objects.iter().map(|o| o.name.clone()).collect();
    for system in System::ALL {
        for instruction in instructions {
            let server = MockLlm::start(vec![Reply::Content("{\"X1\": \"T(0.1 * e1)\"}".into())]);
            let mut scene = workshop();
            let t = translator(&server, system);
            let _ = edit(&mut scene, instruction, &t, &EditOptions::default());
            let requests = server.requests.lock().unwrap().clone();
            assert!(!requests.is_empty(), "{instruction}: nothing was sent");
            for r in &requests {
                let sent = r.body["messages"].to_string().to_lowercase();
                // The prompts themselves use a few common words (a 'table' in an example);
                // the user's message must carry none of the scene's names.
                let user = r.body["messages"][1]["content"]
                    .as_str()
                    .unwrap_or_default()
                    .to_lowercase();
                for name in &names {
                    assert!(
                        !user.contains(&name.to_lowercase()),
                        "{}: '{name}' reached the model in {user:?}",
                        system.name()
                    );
                }
                assert!(!sent.contains("orange bottle"), "{sent}");
            }
        }
    }
}

#[test]
fn a_query_that_still_names_an_object_is_not_sent() {
    use shenlong::pipeline::Translator;
    let server = MockLlm::start(vec![Reply::Content("{\"X1\": \"T(0.1 * e1)\"}".into())]);
    let scene = workshop();
    let hammer = scene.find("hammer").unwrap();
    // As if grounding had missed "tool-table": the name must not go out.
    let templated = shenlong::pipeline::Templated {
        instruction: "put the hammer on the tool-table".into(),
        query: "put X1 on the Tool-Table".into(),
        objects: vec![hammer],
        phrases: Vec::new(),
        held: Vec::new(),
    };
    let e = translator(&server, System::Cga)
        .translate(&templated, &scene)
        .unwrap_err();
    assert!(e.message.contains("'tool table' is still written"), "{e}");
    assert_eq!(server.count(), 0, "nothing was sent");
}

#[test]
fn an_oversized_reply_is_refused_and_never_sent_back() {
    let huge = format!(
        "{{\"X1\": \"T(0.1 * e1)\", \"pad\": \"{}\"}}",
        "x".repeat(300 * 1024)
    );
    let server = MockLlm::start(vec![
        Reply::Content(huge),
        Reply::Content(format!("{{\"X1\": \"{ON_TOP}\"}}")),
    ]);
    let mut scene = workshop();
    let edit = edit_workshop(&mut scene, &server, System::Cga).unwrap();
    assert_eq!(edit.report.retries, 1);
    let first_error = edit.report.exchanges[0].error.clone().unwrap_or_default();
    assert!(first_error.contains("too large"), "{first_error}");
    // The retry request does not carry the 300 KiB back.
    let requests = server.requests.lock().unwrap().clone();
    let retry = requests[1].body.to_string();
    assert!(retry.len() < 64 * 1024, "{} bytes", retry.len());
    assert!(edit.report.exchanges[0].reply.len() <= 257 * 1024);
}

#[test]
fn an_endless_reply_is_read_up_to_the_limit_once_and_refused() {
    let sent = std::sync::Arc::new(std::sync::atomic::AtomicUsize::new(0));
    // Four replies scripted: a client that retried would come back for them.
    let server = MockLlm::start(vec![Reply::Endless(std::sync::Arc::clone(&sent)); 4]);
    let mut options = ClientOptions::new(server.url.clone(), "mock-model", None);
    options.backoff = Duration::from_millis(10);
    options.request_timeout = Duration::from_secs(60);
    let t = LlmTranslator {
        backend: Box::new(OpenAiClient::new(options)),
        system: System::Cga,
        retries: 5,
        deadline: Duration::from_secs(300),
        cache: None,
        recorder: None,
    };
    let started = std::time::Instant::now();
    let mut scene = workshop();
    let e = edit(&mut scene, INSTRUCTION, &t, &EditOptions::default()).unwrap_err();
    let elapsed = started.elapsed();
    assert!(e.message.contains("larger than 320 KiB"), "{e}");
    assert_eq!(e.message.lines().count(), 1, "{e}");
    assert!(!e.message.contains("attempts"), "{e}");
    assert!(elapsed < Duration::from_secs(3), "{elapsed:?}");
    assert_eq!(server.count(), 1, "one request, not retried");
    // What the server got out is the limit and what the sockets' buffers held, far short
    // of the 16 MiB an attempt used to read.
    let sent = sent.load(std::sync::atomic::Ordering::SeqCst);
    assert!(sent < 8 << 20, "{sent} bytes sent");
}

#[test]
fn a_long_retry_after_cannot_outlast_the_deadline() {
    let server = MockLlm::start(vec![
        Reply::Raw(
            429,
            vec![("Retry-After".into(), "3600".into())],
            "slow down".into(),
        ),
        Reply::Content(format!("{{\"X1\": \"{ON_TOP}\"}}")),
    ]);
    let mut options = ClientOptions::new(server.url.clone(), "mock-model", None);
    options.backoff = Duration::from_millis(10);
    options.deadline = Duration::from_secs(5);
    let t = LlmTranslator {
        backend: Box::new(OpenAiClient::new(options)),
        system: System::Cga,
        retries: 1,
        deadline: Duration::from_secs(5),
        cache: None,
        recorder: None,
    };
    let started = std::time::Instant::now();
    let mut scene = workshop();
    // Retry-After is capped at 30 s, past the 5 s deadline: it gives up at once.
    let e = edit(&mut scene, INSTRUCTION, &t, &EditOptions::default()).unwrap_err();
    assert!(e.message.contains("deadline"), "{e}");
    assert!(
        started.elapsed() < Duration::from_secs(4),
        "{:?}",
        started.elapsed()
    );
}

mod cascade {
    use super::*;
    use shenlong::pipeline::cascade::Cascade;
    use shenlong::pipeline::EditErrorKind;

    fn cascade(server: &MockLlm) -> Cascade {
        Cascade::new(Box::new(translator(server, System::Cga))).unwrap()
    }

    #[test]
    fn what_the_offline_translator_reads_sends_no_request() {
        let server = MockLlm::start(vec![]);
        let mut scene = workshop();
        let result = edit(
            &mut scene,
            INSTRUCTION,
            &cascade(&server),
            &EditOptions::default(),
        )
        .unwrap();
        assert!(bottle_on_table(&scene));
        assert!(server.captured().is_empty(), "no request was sent");
        assert_eq!(result.report.answered_by, "offline");
        assert_eq!(result.report.model, "offline+mock-model");
        assert!(result.report.offline_refusal.is_none());
    }

    #[test]
    fn what_it_reads_and_refuses_is_never_sent_to_the_model() {
        // A model might read "put it back" as a move backwards; the offline translator
        // reads it and refuses it (there is no earlier pose), and nothing is asked.
        let server = MockLlm::start(vec![Reply::Content(format!("{{\"X1\": \"{ON_TOP}\"}}"))]);
        let mut scene = workshop();
        let before = scene.clone();
        let refused = edit(
            &mut scene,
            "put the 'orange bottle' back",
            &cascade(&server),
            &EditOptions::default(),
        )
        .unwrap_err();
        assert!(refused.message.contains("where it was before"), "{refused}");
        assert!(server.captured().is_empty(), "no request was sent");
        for (a, b) in scene.objects.iter().zip(&before.objects) {
            assert_eq!(a.world_aabb(), b.world_aabb(), "{} moved", a.name);
        }
    }

    #[test]
    fn what_it_cannot_read_goes_to_the_model_once() {
        let server = MockLlm::start(vec![Reply::Content(format!("{{\"X1\": \"{ON_TOP}\"}}"))]);
        let mut scene = workshop();
        let instruction = "have the 'orange bottle' perform a graceful hop onto the 'tool table'";
        let result = edit(
            &mut scene,
            instruction,
            &cascade(&server),
            &EditOptions::default(),
        )
        .unwrap();
        assert!(bottle_on_table(&scene), "the model's answer was applied");
        assert_eq!(server.captured().len(), 1);
        assert_eq!(result.report.answered_by, "mock-model");
        let refusal = result.report.offline_refusal.as_deref().unwrap();
        assert!(refusal.contains("could not read"), "{refusal}");
        // The model saw variables, not names.
        let body = server.captured()[0].body.to_string();
        assert!(
            !body.contains("orange bottle") && !body.contains("tool table"),
            "{body}"
        );
    }

    #[test]
    fn a_grounding_refusal_is_final() {
        let server = MockLlm::start(vec![Reply::Content("{\"X1\": \"T(e1)\"}".into())]);
        let mut scene = shenlong::examples::build("living_room").unwrap();
        let before: Vec<_> = scene.objects.iter().map(|o| o.similarity()).collect();
        for instruction in [
            "have the lamp perform a graceful hop",
            "have the piano perform a graceful hop",
        ] {
            let e = edit(
                &mut scene,
                instruction,
                &cascade(&server),
                &EditOptions::default(),
            )
            .unwrap_err();
            assert_eq!(e.kind, EditErrorKind::Instruction, "{instruction}: {e}");
        }
        assert!(
            server.captured().is_empty(),
            "no request for an ambiguous or unknown object"
        );
        let after: Vec<_> = scene.objects.iter().map(|o| o.similarity()).collect();
        assert_eq!(after, before);
    }

    #[test]
    fn the_spec_builds_a_cascade() {
        let server = MockLlm::start(vec![]);
        let settings = shenlong::pipeline::backends::TranslatorSettings {
            base_url: Some(server.url.clone()),
            api_key: Some("sk-x".into()),
            cache_dir: None,
            ..Default::default()
        };
        use shenlong::pipeline::backends::{translator, Spec};
        let spec: Spec = "offline+openai:m1".parse().unwrap();
        let t = translator(&spec, &settings).unwrap();
        assert_eq!(t.name(), "offline+m1");
        for bad in ["offline+", "offline+offline", "offline+nothing:x"] {
            assert!(bad.parse::<Spec>().is_err(), "{bad}");
        }
        let euclidean = shenlong::pipeline::backends::TranslatorSettings {
            system: System::Euclidean,
            ..settings
        };
        let e = translator(&spec, &euclidean).err().unwrap().to_string();
        assert!(e.contains("CGA"), "{e}");
    }
}

#[test]
fn a_rate_limit_holds_every_request_of_the_pool() {
    use shenlong::llm::{Backend, Message};
    let server = MockLlm::start(vec![
        Reply::Raw(
            429,
            vec![("Retry-After".into(), "1".into())],
            "{\"error\": {\"message\": \"slow down\"}}".into(),
        ),
        Reply::Content("{\"X1\": \"T(e1)\"}".into()),
        Reply::Content("{\"X1\": \"T(e1)\"}".into()),
    ]);
    // Two clients of one server (as a benchmark makes one per prompt system).
    let (client, other) = (client(&server, Some("sk-x")), client(&server, Some("sk-x")));
    let messages = vec![Message::new("user", "Instruction: move X1 right")];
    let (a, b) = std::thread::scope(|scope| {
        let first = scope.spawn(|| client.complete(&messages).map(|_| ()));
        // The second job starts after the first was told to wait (the 429 served, and a
        // moment for the first client to read it).
        while server.count() < 1 {
            std::thread::sleep(Duration::from_millis(5));
        }
        std::thread::sleep(Duration::from_millis(300));
        let started = std::time::Instant::now();
        let second = other.complete(&messages).map(|_| started.elapsed());
        (first.join().unwrap(), second)
    });
    a.unwrap();
    let waited = b.unwrap();
    // Without the shared back-off it is answered at once (a few milliseconds).
    assert!(
        waited >= Duration::from_millis(400),
        "the second request waited {waited:?} for the server's Retry-After"
    );
    assert_eq!(server.count(), 3);
}

#[test]
fn replies_are_scored_by_kind() {
    // A reply with no answer, one that parses but is not a transformation, then a good one.
    let server = MockLlm::start(vec![
        Reply::Content("I would move it somewhere nice.".into()),
        Reply::Content("{\"X1\": \"X1.max\"}".into()),
        Reply::Content(format!("{{\"X1\": \"{ON_TOP}\"}}")),
    ]);
    let mut scene = workshop();
    let result = edit_workshop(&mut scene, &server, System::Cga).unwrap();
    let r = result.report.replies;
    assert_eq!((r.received, r.parsed, r.valid), (3, 2, 1), "{r:?}");
    // A model that never gets there: the counts come with the failure.
    let server = MockLlm::start(vec![Reply::Content("{\"X1\": \"T(\"}".into()); 6]);
    let e = edit_workshop(&mut workshop(), &server, System::Cga).unwrap_err();
    assert_eq!(
        (e.replies.received, e.replies.parsed, e.replies.valid),
        (6, 0, 0)
    );
    // The baselines are scored in their own terms.
    assert!(System::Omniverse.reply_parses("{\"X1\": {\"position\": [0, 1, 0]}}"));
    assert!(!System::Omniverse.reply_parses("no object here"));
    assert!(System::Euclidean.reply_parses("{\"X1\": \"translation(1, 0, 0)\"}"));
    assert!(!System::Cga.reply_parses("{\"X1\": \"T(1 *\"}"));
}

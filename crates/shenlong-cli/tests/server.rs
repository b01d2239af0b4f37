//! The editor's HTTP API: the router driven in-process, and the server over loopback.

use axum::body::{to_bytes, Body};
use axum::http::{Request, StatusCode};
use serde_json::{json, Value};
use shenlong::pipeline::backends::TranslatorSettings;
use shenlong::pipeline::System;
use shenlong_cli::server::{router, serve, App, ServeSettings};
use std::sync::Arc;
use tower::ServiceExt;

// One rule for finding the shared test data, kept with the library's integration tests.
#[path = "../../shenlong/tests/support/shared_data.rs"]
mod shared_data;
mod support;

/// Offline, no cache; a model server's base URL, collisions on or off, `--save`.
fn settings(
    base_url: Option<String>,
    collide: bool,
    save: Option<std::path::PathBuf>,
) -> ServeSettings {
    ServeSettings {
        llm: shenlong::pipeline::backends::Spec::Offline,
        system: System::Cga,
        translator: TranslatorSettings {
            cache_dir: None,
            base_url,
            ..TranslatorSettings::default()
        },
        collisions: collide.then(Default::default),
        save,
    }
}

/// A scene as a file read from nowhere (no document to write back into).
fn file_of(scene: shenlong::scene::Scene) -> shenlong::format::SceneFile {
    shenlong::format::SceneFile {
        scene,
        document: shenlong::format::Document::None,
        path: None,
    }
}

fn app(save: Option<std::path::PathBuf>) -> Arc<App> {
    let scene = shenlong::examples::build("workshop").unwrap();
    let file = file_of(scene);
    App::new(file, settings(None, true, save))
}

async fn call(
    app: &Arc<App>,
    method: &str,
    path: &str,
    body: Option<&str>,
) -> (StatusCode, Value, Vec<u8>) {
    let request = Request::builder()
        .method(method)
        .uri(path)
        .header("host", "127.0.0.1:8080")
        .header("content-type", "application/json")
        .body(body.map_or_else(Body::empty, |b| Body::from(b.to_string())))
        .unwrap();
    let response = router(Arc::clone(app)).oneshot(request).await.unwrap();
    let status = response.status();
    let bytes = to_bytes(response.into_body(), 16 * 1024 * 1024)
        .await
        .unwrap()
        .to_vec();
    let value = serde_json::from_slice(&bytes).unwrap_or(Value::Null);
    (status, value, bytes)
}

fn position(scene: &Value, name: &str) -> Value {
    support::object(&scene["scene"], name)["position"].clone()
}

#[tokio::test]
async fn edit_undo_redo_history() {
    let dir = tempfile::tempdir().unwrap();
    let saved = dir.path().join("saved.json");
    let app = app(Some(saved.clone()));
    let (status, report, _) = call(
        &app,
        "POST",
        "/api/edit",
        Some(r#"{"instruction": "put the 'orange bottle' on top of the 'tool table'"}"#),
    )
    .await;
    assert_eq!(status, StatusCode::OK, "{report}");
    assert_eq!(report["understood"]["query"], "put X1 on top of X2");
    assert_eq!(report["report"]["query"], "put X1 on top of X2");
    assert_eq!(report["moved"][0]["object"], "orange bottle");
    let (_, scene, _) = call(&app, "GET", "/api/scene", None).await;
    assert_eq!(position(&scene, "orange bottle"), json!([0, 0.9, 0]));
    assert_eq!(scene["can_undo"], true);
    // --save wrote the edited scene.
    let file: Value = serde_json::from_str(&std::fs::read_to_string(&saved).unwrap()).unwrap();
    assert!(file["objects"]
        .as_array()
        .unwrap()
        .iter()
        .any(|o| o["name"] == "orange bottle" && o["position"] == json!([0, 0.9, 0])));
    let (status, undone, _) = call(&app, "POST", "/api/undo", None).await;
    assert_eq!(status, StatusCode::OK);
    assert_eq!(undone["operation"], "undo");
    assert_eq!(undone["history_id"], report["history_id"]);
    assert_eq!(undone["moved"][0]["object"], "orange bottle");
    assert_eq!(
        undone["moved"][0]["after"]["position"],
        json!([-2.0, 0.0, 1.2])
    );
    let (_, scene, _) = call(&app, "GET", "/api/scene", None).await;
    assert_eq!(position(&scene, "orange bottle"), json!([-2, 0, 1.2]));
    let (_, history, _) = call(&app, "GET", "/api/history", None).await;
    assert_eq!(history["history"][0]["undone"], true);
    let (status, redone, _) = call(&app, "POST", "/api/redo", None).await;
    assert_eq!(status, StatusCode::OK);
    assert_eq!(redone["operation"], "redo");
    let (_, scene, _) = call(&app, "GET", "/api/scene", None).await;
    assert_eq!(position(&scene, "orange bottle"), json!([0, 0.9, 0]));
    let (status, e, _) = call(&app, "POST", "/api/redo", None).await;
    assert_eq!(
        (status, e["error"].as_str().unwrap(), e["kind"].as_str()),
        (
            StatusCode::CONFLICT,
            "nothing to redo",
            Some("nothing_to_redo")
        )
    );
}

#[tokio::test]
async fn bad_input_gets_4xx_with_the_reason() {
    let app = app(None);
    let cases = [
        (
            r#"{"instruction": "move the 'sofaa' left"}"#,
            StatusCode::UNPROCESSABLE_ENTITY,
            "unknown object 'sofaa'",
        ),
        (
            r#"{"instruction": "sing about the 'stool'"}"#,
            StatusCode::UNPROCESSABLE_ENTITY,
            "could not read",
        ),
        (
            r#"{"instruction": 3}"#,
            StatusCode::UNPROCESSABLE_ENTITY,
            "invalid type",
        ),
        ("not json", StatusCode::BAD_REQUEST, "bad JSON body"),
        (
            r#"{"instruction": "move the 'stool' left", "colour": "red"}"#,
            StatusCode::UNPROCESSABLE_ENTITY,
            "unknown field `colour`",
        ),
        (
            r#"{"instruction": "move the 'stool' left", "system": "magic"}"#,
            StatusCode::BAD_REQUEST,
            "unknown system 'magic'",
        ),
        (
            r#"{"instruction": "move the 'stool' left", "llm": "claude"}"#,
            StatusCode::BAD_REQUEST,
            "'claude' is not one of them",
        ),
    ];
    for (body, expected, message) in cases {
        let (status, value, _) = call(&app, "POST", "/api/edit", Some(body)).await;
        let error = value["error"].as_str().unwrap_or_default().to_string();
        assert!(status.is_client_error(), "{body}: {status}");
        assert!(
            status == expected || error.contains(message),
            "{body}: {status} {error}"
        );
        assert!(error.contains(message), "{body}: {error}");
    }
    let long = json!({"instruction": "a".repeat(3000)}).to_string();
    assert_eq!(
        call(&app, "POST", "/api/edit", Some(&long)).await.0,
        StatusCode::PAYLOAD_TOO_LARGE
    );
    let huge = json!({"instruction": "a".repeat(100_000)}).to_string();
    let (status, value, _) = call(&app, "POST", "/api/edit", Some(&huge)).await;
    assert_eq!(status, StatusCode::PAYLOAD_TOO_LARGE, "{value}");
    let (status, value, _) = call(
        &app,
        "POST",
        "/api/apply",
        Some(r#"{"object": "stool", "expr": "T(e1"}"#),
    )
    .await;
    assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY);
    assert!(value["error"].as_str().unwrap().contains("expected ')'"));
    assert_eq!(
        call(&app, "POST", "/api/undo", None).await.0,
        StatusCode::CONFLICT
    );
    assert_eq!(
        call(&app, "GET", "/api/export?format=obj", None).await.0,
        StatusCode::BAD_REQUEST
    );
    assert_eq!(
        call(&app, "GET", "/api/nothing", None).await.0,
        StatusCode::NOT_FOUND
    );
    assert_eq!(
        call(&app, "GET", "/../Cargo.toml", None).await.0,
        StatusCode::NOT_FOUND
    );
}

#[tokio::test]
async fn apply_export_and_the_page() {
    let app = app(None);
    let (status, value, _) = call(
        &app,
        "POST",
        "/api/apply",
        Some(r#"{"object": "stool", "expr": "T(0.5 * e1)"}"#),
    )
    .await;
    assert_eq!(status, StatusCode::OK, "{value}");
    let (_, scene, _) = call(&app, "GET", "/api/scene", None).await;
    assert_eq!(position(&scene, "stool"), json!([0.5, 0, 1]));
    let (status, _, bytes) = call(&app, "GET", "/api/export?format=json", None).await;
    assert_eq!(status, StatusCode::OK);
    let exported: Value = serde_json::from_slice(&bytes).unwrap();
    assert_eq!(exported["name"], "workshop");
    let (status, commands, _) = call(&app, "GET", "/api/export?format=tdw", None).await;
    assert_eq!(status, StatusCode::OK);
    assert_eq!(commands[0]["$type"], "teleport_object");
    let (status, _, page) = call(&app, "GET", "/", None).await;
    assert_eq!(status, StatusCode::OK);
    let page = String::from_utf8(page).unwrap();
    assert!(
        page.contains("/vendor/three/three.module.js") && !page.contains("https://"),
        "no CDN"
    );
    assert_eq!(
        call(&app, "GET", "/vendor/three/OrbitControls.js", None)
            .await
            .0,
        StatusCode::OK
    );
    // A glTF export of a scene that did not come from glTF: a new glTF of its boxes.
    let (status, _, glb) = call(&app, "GET", "/api/export?format=glb", None).await;
    assert_eq!(status, StatusCode::OK);
    let (back, _) =
        shenlong::format::gltf::read_bytes(glb, std::path::Path::new("."), "x").unwrap();
    assert!(back.objects.len() > 5);
}

#[test]
fn over_loopback_a_slow_edit_does_not_block_reads() {
    // A model server that first says "busy, retry in 1.5 s", then answers.
    #[path = "../../shenlong/tests/support/mock_llm.rs"]
    mod mock_llm;
    let slow = mock_llm::MockLlm::start(vec![
        mock_llm::Reply::Raw(
            503,
            vec![("Retry-After".into(), "1.5".into())],
            "busy".into(),
        ),
        mock_llm::Reply::Content("{\"X1\": \"T(1 * e1)\"}".into()),
    ]);
    let scene = shenlong::examples::build("workshop").unwrap();
    let file = file_of(scene);
    // The server is started with the model; a request may choose it (or "offline").
    let app = App::new(
        file,
        ServeSettings {
            llm: "ollama:mock".parse().unwrap(),
            ..settings(Some(slow.url.clone()), false, None)
        },
    );
    let runtime = tokio::runtime::Runtime::new().unwrap();
    let listener = runtime
        .block_on(tokio::net::TcpListener::bind("127.0.0.1:0"))
        .unwrap();
    let address = listener.local_addr().unwrap();
    runtime.spawn(serve(app, listener));
    let editor = std::thread::spawn(move || {
        let body =
            json!({"instruction": "move the 'stool' right", "llm": "ollama:mock"}).to_string();
        let mut response = ureq::post(&format!("http://{address}/api/edit"))
            .header("content-type", "application/json")
            .send(body)
            .unwrap();
        response.body_mut().read_json::<Value>().unwrap()
    });
    std::thread::sleep(std::time::Duration::from_millis(300));
    let started = std::time::Instant::now();
    let scene: Value = ureq::get(&format!("http://{address}/api/scene"))
        .call()
        .unwrap()
        .body_mut()
        .read_json()
        .unwrap();
    assert!(
        started.elapsed() < std::time::Duration::from_millis(500),
        "reads are not blocked by an edit"
    );
    assert_eq!(
        position(&scene, "stool"),
        json!([0, 0, 1]),
        "the edit is not in yet"
    );
    let report = editor.join().unwrap();
    assert_eq!(report["report"]["model"], "mock", "{report}");
    assert_eq!(slow.count(), 2);
    let scene: Value = ureq::get(&format!("http://{address}/api/scene"))
        .call()
        .unwrap()
        .body_mut()
        .read_json()
        .unwrap();
    assert_eq!(position(&scene, "stool"), json!([1, 0, 1]));
}

#[tokio::test]
async fn a_glb_scene_serves_its_model_and_edits_reach_it() {
    let Some(path) = shared_data::shared_data("gltf/DepthOfFieldExample.glb") else {
        return;
    };
    let file = shenlong::format::SceneFile::load(&path).unwrap();
    let glb = App::new(file, settings(None, false, None));
    let (_, scene, _) = call(&glb, "GET", "/api/scene", None).await;
    assert_eq!(scene["model"], "/api/model");
    let (status, _, before) = call(&glb, "GET", "/api/model", None).await;
    assert_eq!(status, StatusCode::OK);
    assert!(before.starts_with(b"glTF"));
    let (status, report, _) = call(
        &glb,
        "POST",
        "/api/edit",
        Some(r#"{"instruction": "move the 'Cube' 0.5 units up"}"#),
    )
    .await;
    assert_eq!(status, StatusCode::OK, "{report}");
    let (_, _, after) = call(&glb, "GET", "/api/model", None).await;
    assert_ne!(before, after, "the model follows the edit");
    let dir = tempfile::tempdir().unwrap();
    let edited = dir.path().join("edited.glb");
    std::fs::write(&edited, &after).unwrap();
    let reread = shenlong::format::SceneFile::load(&edited).unwrap();
    let original = shenlong::format::SceneFile::load(&path).unwrap();
    let cube = |f: &shenlong::format::SceneFile| {
        f.scene.objects[f.scene.find("Cube").unwrap()]
            .world_aabb()
            .min
            .y
    };
    assert!((cube(&reread) - cube(&original) - 0.5).abs() < 1e-5);
    // A scene that is not glTF has no model.
    assert_eq!(
        call(&app(None), "GET", "/api/model", None).await.0,
        StatusCode::NOT_FOUND
    );
}

async fn raw(app: &Arc<App>, request: Request<Body>) -> (StatusCode, Value) {
    let response = router(Arc::clone(app)).oneshot(request).await.unwrap();
    let status = response.status();
    let bytes = to_bytes(response.into_body(), 1 << 20).await.unwrap();
    (
        status,
        serde_json::from_slice(&bytes).unwrap_or(Value::Null),
    )
}

#[tokio::test]
async fn a_request_cannot_choose_a_backend_that_reads_files() {
    let dir = tempfile::tempdir().unwrap();
    let secret = dir.path().join("secret.jsonl");
    std::fs::write(&secret, "{\"reply\": \"TOP-SECRET\"}\n").unwrap();
    let app = app(None);
    for llm in [
        format!("replay:{}", secret.display()),
        "replay:/etc/shadow".to_string(),
        "replay:/dev/zero".to_string(),
        "openai:gpt-4o".to_string(),
    ] {
        let body = json!({"instruction": "move the 'hammer' left", "llm": llm}).to_string();
        let (status, value, _) = call(&app, "POST", "/api/edit", Some(&body)).await;
        assert_eq!(status, StatusCode::BAD_REQUEST, "{llm}: {value}");
        let message = value["error"].as_str().unwrap();
        assert!(
            message.contains("offers the translators 'offline'"),
            "{message}"
        );
        assert!(
            !message.contains("TOP-SECRET") && !message.contains("exist"),
            "{message}"
        );
    }
    // The fixed set still works.
    let body = json!({"instruction": "move the 'hammer' left", "llm": "offline"}).to_string();
    let (status, _, _) = call(&app, "POST", "/api/edit", Some(&body)).await;
    assert_eq!(status, StatusCode::OK);
}

#[tokio::test]
async fn cross_site_requests_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let saved = dir.path().join("saved.json");
    let app = app(Some(saved.clone()));
    let body = json!({"instruction": "move the 'hammer' left"}).to_string();
    let (status, _, _) = call(&app, "POST", "/api/edit", Some(&body)).await;
    assert_eq!(status, StatusCode::OK);
    let before = std::fs::read(&saved).unwrap();
    let request = |content_type: &str, host: &str, origin: Option<&str>| {
        let mut r = Request::builder()
            .method("POST")
            .uri("/api/undo")
            .header("host", host)
            .header("content-type", content_type);
        if let Some(o) = origin {
            r = r.header("origin", o);
        }
        r.body(Body::from("{}")).unwrap()
    };
    // A text/plain POST needs no CORS preflight: refused.
    let (status, v) = raw(&app, request("text/plain", "127.0.0.1:8080", None)).await;
    assert_eq!(status, StatusCode::UNSUPPORTED_MEDIA_TYPE, "{v}");
    // Another site's page.
    let (status, v) = raw(
        &app,
        request(
            "application/json",
            "127.0.0.1:8080",
            Some("http://evil.example"),
        ),
    )
    .await;
    assert_eq!(status, StatusCode::FORBIDDEN, "{v}");
    // DNS rebinding: the attacker's name in Host.
    let (status, v) = raw(&app, request("application/json", "evil.example:8080", None)).await;
    assert_eq!(status, StatusCode::FORBIDDEN, "{v}");
    let get = Request::builder()
        .uri("/api/scene")
        .header("host", "rebind.evil.example")
        .body(Body::empty())
        .unwrap();
    assert_eq!(raw(&app, get).await.0, StatusCode::FORBIDDEN);
    // Nothing was undone, nothing rewritten.
    assert_eq!(std::fs::read(&saved).unwrap(), before);
    // The page's own requests pass: same-origin, JSON.
    for (host, origin) in [
        ("localhost:8080", Some("http://localhost:8080")),
        ("[::1]:9000", None),
    ] {
        let (status, v) = raw(
            &app,
            request("application/json; charset=utf-8", host, origin),
        )
        .await;
        assert_eq!(status, StatusCode::OK, "{host}: {v}");
        let (status, _, _) = call(&app, "POST", "/api/redo", Some("{}")).await;
        assert_eq!(status, StatusCode::OK);
    }
}

#[tokio::test]
async fn export_query_errors_are_json() {
    let app = app(None);
    for path in [
        "/api/export?format=json&format=glb",
        "/api/export?fmt=json",
        "/api/export?format=svg",
    ] {
        let (status, value, _) = call(&app, "GET", path, None).await;
        assert_eq!(status, StatusCode::BAD_REQUEST, "{path}");
        assert!(value["error"].is_string(), "{path}: {value}");
    }
}

#[tokio::test]
async fn a_change_that_moves_nothing_is_not_recorded() {
    let app = app(None);
    // "X1 to X1's own place": nothing moves.
    let body = json!({"object": "hammer", "expr": "T(0 * e1)"}).to_string();
    let (status, value, _) = call(&app, "POST", "/api/apply", Some(&body)).await;
    assert_eq!(status, StatusCode::OK, "{value}");
    assert!(value["history_id"].is_null(), "{value}");
    let (_, history, _) = call(&app, "GET", "/api/history", None).await;
    assert_eq!(history["history"].as_array().unwrap().len(), 0);
    let (status, _, _) = call(&app, "POST", "/api/undo", Some("{}")).await;
    assert_eq!(status, StatusCode::CONFLICT);
}

#[tokio::test]
async fn after_an_apply_moves_the_bottle_off_the_table_moving_the_table_leaves_it() {
    // Regression: /api/apply did not re-detect supports, so the table still carried the
    // bottle it no longer held.
    let app = app(None);
    let body =
        json!({"object": "orange bottle", "expr": "T(-2.5 * e1 + ((-0.9) * e2))"}).to_string();
    let (status, value, _) = call(&app, "POST", "/api/apply", Some(&body)).await;
    assert_eq!(status, StatusCode::OK, "{value}");
    let (_, scene, _) = call(&app, "GET", "/api/scene", None).await;
    let bottle = position(&scene, "orange bottle");
    let body = json!({"instruction": "move the 'tool table' 0.5 m back"}).to_string();
    let (status, value, _) = call(&app, "POST", "/api/edit", Some(&body)).await;
    assert_eq!(status, StatusCode::OK, "{value}");
    let (_, scene, _) = call(&app, "GET", "/api/scene", None).await;
    assert_eq!(
        position(&scene, "orange bottle"),
        bottle,
        "the bottle stayed where it was put"
    );
}

#[test]
fn slow_clients_are_cut_off_and_do_not_starve_others() {
    use std::io::{Read, Write};
    let (_runtime, address) = serve_over_loopback_within(
        workshop_file(),
        shenlong_cli::server::Limits {
            header_timeout: std::time::Duration::from_millis(800),
            body_timeout: std::time::Duration::from_millis(800),
            max_connections: 512,
        },
    );
    // 300 clients that never finish their headers.
    let mut slow: Vec<std::net::TcpStream> = (0..300)
        .map(|_| {
            let mut s = std::net::TcpStream::connect(address).unwrap();
            s.write_all(b"GET /api/scene HTTP/1.1\r\nHost: 127.0.0.1\r\n")
                .unwrap();
            s
        })
        .collect();
    // A normal request is still answered at once.
    let started = std::time::Instant::now();
    let scene: Value = ureq::get(&format!("http://{address}/api/scene"))
        .call()
        .unwrap()
        .body_mut()
        .read_json()
        .unwrap();
    assert!(scene["scene"]["objects"].is_array());
    assert!(
        started.elapsed() < std::time::Duration::from_millis(700),
        "{:?}",
        started.elapsed()
    );
    // The slow ones are closed once their headers are late.
    std::thread::sleep(std::time::Duration::from_millis(1500));
    let mut closed = 0;
    for s in &mut slow {
        s.set_read_timeout(Some(std::time::Duration::from_millis(200)))
            .unwrap();
        let mut buf = [0u8; 256];
        if s.read(&mut buf).is_ok() {
            closed += 1;
        }
    }
    assert_eq!(closed, slow.len(), "every slow connection was closed");
}

#[tokio::test]
async fn a_save_that_fails_later_keeps_the_edit_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let folder = dir.path().join("out");
    std::fs::create_dir(&folder).unwrap();
    let save = folder.join("edited.json");
    let app = app(Some(save.clone()));
    // The folder goes away after start-up (a disk unmounted, a folder deleted).
    std::fs::remove_dir(&folder).unwrap();
    let (status, report, _) = call(
        &app,
        "POST",
        "/api/edit",
        Some(r#"{"instruction": "put the 'orange bottle' on top of the 'tool table'"}"#),
    )
    .await;
    assert_eq!(status, StatusCode::OK, "{report}");
    let warning = report["warnings"][0].as_str().unwrap();
    assert!(warning.contains("could not be saved"), "{warning}");
    assert!(report["history_id"].is_u64(), "the edit is in the history");
    let (_, scene, _) = call(&app, "GET", "/api/scene", None).await;
    assert_eq!(
        position(&scene, "orange bottle")[1],
        0.9,
        "and in the scene"
    );
    // Once the folder is back, the next change saves everything.
    std::fs::create_dir(&folder).unwrap();
    let (status, undone, _) = call(&app, "POST", "/api/undo", Some("{}")).await;
    assert_eq!(status, StatusCode::OK);
    assert_eq!(undone["warnings"], json!([]), "{undone}");
    assert!(save.exists());
}

#[test]
fn the_history_keeps_within_its_byte_budget() {
    use shenlong::session::Session;
    // Each change moves every object of a scene of 2,000, so each step costs about
    // 2 × 2,000 objects; a budget of 3 such steps keeps the last 3.
    let mut scene = shenlong::scene::Scene::new("many");
    for i in 0..2_000 {
        scene.objects.push(
            shenlong::scene::Object::new_box(
                format!("box {i}"),
                glam::DVec3::ONE,
                glam::DVec3::new(i as f64 * 2.0, 0.0, 0.0),
                glam::DQuat::IDENTITY,
                1.0,
            )
            .unwrap(),
        );
    }
    let file = file_of(scene);
    let mut session = Session::new(file, None);
    let one_step = 2 * 2_000 * (std::mem::size_of::<shenlong::scene::Object>() + 8);
    session.set_history_budget(3 * one_step + one_step / 2);
    for k in 1..=10 {
        let mut after = session.file.scene.clone();
        for i in 0..after.objects.len() {
            after
                .apply(
                    i,
                    &cga::Multivector::translator(glam::DVec3::Z * 0.1),
                    false,
                )
                .unwrap();
        }
        assert_eq!(
            session.commit(after, "apply", &format!("step {k}")).id,
            Some(k)
        );
    }
    let kept: Vec<u64> = session.history().iter().map(|h| h.id).collect();
    assert_eq!(kept, vec![8, 9, 10], "the oldest steps went first");
    for _ in 0..3 {
        assert!(session.step(true).is_ok());
    }
    assert!(session.step(true).is_err(), "nothing older to undo");
    // A change that moves nothing is not recorded.
    let same = session.file.scene.clone();
    assert_eq!(session.commit(same, "apply", "nothing").id, None);
}

/// `shenlong serve` for `file` on a loopback port, on a multi-threaded runtime (worker
/// threads with their usual 2 MiB stacks); the runtime stops the server when dropped.
fn serve_over_loopback(
    file: shenlong::format::SceneFile,
) -> (tokio::runtime::Runtime, std::net::SocketAddr) {
    serve_over_loopback_within(file, shenlong_cli::server::Limits::default())
}

/// [`serve_over_loopback`] within `limits`.
fn serve_over_loopback_within(
    file: shenlong::format::SceneFile,
    limits: shenlong_cli::server::Limits,
) -> (tokio::runtime::Runtime, std::net::SocketAddr) {
    let app = App::new(file, settings(None, false, None));
    let runtime = tokio::runtime::Runtime::new().unwrap();
    let listener = runtime
        .block_on(tokio::net::TcpListener::bind("127.0.0.1:0"))
        .unwrap();
    let address = listener.local_addr().unwrap();
    runtime.spawn(shenlong_cli::server::serve_with(app, listener, limits));
    (runtime, address)
}

/// The workshop, as a scene file with no document.
fn workshop_file() -> shenlong::format::SceneFile {
    file_of(shenlong::examples::build("workshop").unwrap())
}

/// A GET over loopback: the status, or the transport error (the server stopped).
fn get(address: std::net::SocketAddr, path: &str) -> Result<u16, String> {
    let agent: ureq::Agent = ureq::Agent::config_builder()
        .http_status_as_error(false)
        .timeout_global(Some(std::time::Duration::from_secs(60)))
        .build()
        .into();
    agent
        .get(&format!("http://{address}{path}"))
        .call()
        .map(|r| r.status().as_u16())
        .map_err(|e| e.to_string())
}

#[test]
fn a_scene_nested_too_deep_never_stops_the_server() {
    let dir = tempfile::tempdir().unwrap();
    // 200 levels of brackets in an unknown field: refused when read, naming the limit,
    // or (were it read) answered, never a panic that leaves the server mute.
    let deep = dir.path().join("deep.json");
    std::fs::write(&deep, support::nested_scene_json(200)).unwrap();
    match shenlong::format::SceneFile::load(&deep) {
        Err(e) => assert!(
            e.to_string()
                .ends_with("deep.json: nesting deeper than 100 levels at line 2, column 166"),
            "{}",
            e.to_string()
        ),
        Ok(file) => {
            let (_runtime, address) = serve_over_loopback(file);
            let status = get(address, "/api/scene");
            assert!(status.is_ok(), "the scene is answered: {status:?}");
            assert_eq!(
                get(address, "/api/history"),
                Ok(200),
                "and the next request"
            );
        }
    }
    // At the limit: read, served, and the server answers on.
    let at_limit = dir.path().join("at-limit.json");
    std::fs::write(&at_limit, support::nested_scene_json(97)).unwrap();
    let file = shenlong::format::SceneFile::load(&at_limit).unwrap();
    let (_runtime, address) = serve_over_loopback(file);
    assert_eq!(get(address, "/api/scene"), Ok(200));
    assert_eq!(get(address, "/api/scene"), Ok(200));
    assert_eq!(get(address, "/api/history"), Ok(200));
}

#[test]
fn a_deep_gltf_hierarchy_is_applied_and_exported_without_a_crash() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("chain.gltf");
    std::fs::write(&path, support::deep_chain_gltf(8_000)).unwrap();
    let file = shenlong::format::SceneFile::load(&path).unwrap();
    let (_runtime, address) = serve_over_loopback(file);
    // The chain of empty nodes over one mesh is one object, named by its top node.
    let body = json!({"object": "n0", "expr": "T(e1)"}).to_string();
    let mut response = ureq::post(&format!("http://{address}/api/apply"))
        .header("content-type", "application/json")
        .send(body)
        .unwrap();
    let applied: Value = response.body_mut().read_json().unwrap();
    assert_eq!(
        applied["moved"][0]["after"]["position"],
        json!([1.0, 0.0, 0.0]),
        "{applied}"
    );
    let exported = ureq::get(&format!("http://{address}/api/export?format=gltf"))
        .call()
        .unwrap()
        .body_mut()
        .with_config()
        .limit(64 << 20)
        .read_to_vec()
        .unwrap();
    let edited = dir.path().join("edited.gltf");
    std::fs::write(&edited, exported).unwrap();
    let reread = shenlong::format::SceneFile::load(&edited).unwrap();
    let min = reread.scene.objects[0].world_aabb().min;
    assert!(
        (min - glam::DVec3::new(1.0, 8.0, 0.0)).length() < 1e-6,
        "{min:?}"
    );
    assert_eq!(get(address, "/api/model"), Ok(200));
    assert_eq!(get(address, "/api/scene"), Ok(200));
}

#[tokio::test]
async fn a_refusal_among_thousands_answers_a_few_choices_and_the_total() {
    let mut scene = shenlong::scene::Scene::new("hall");
    for i in 0..3000 {
        scene.objects.push(
            shenlong::scene::Object::new_box(
                format!("chair {}", i + 1),
                glam::DVec3::new(0.5, 0.9, 0.5),
                glam::DVec3::new((i % 60) as f64, 0.0, (i / 60) as f64),
                glam::DQuat::IDENTITY,
                1.0,
            )
            .unwrap(),
        );
    }
    let file = file_of(scene);
    let app = App::new(file, settings(None, true, None));
    let body = json!({"instruction": "move the chair 1 m left"}).to_string();
    let (status, answer, bytes) = call(&app, "POST", "/api/edit", Some(&body)).await;
    assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY, "{answer}");
    assert!(bytes.len() < 16_000, "{} bytes", bytes.len());
    let ambiguity = &answer["ambiguity"];
    assert_eq!(ambiguity["total"], 3000, "{answer}");
    assert_eq!(ambiguity["choices"].as_array().unwrap().len(), 24);
}

/// A one-triangle glTF whose buffer is a `data:` URI, and an image at `image_uri` if given.
fn triangle_gltf(dir: &std::path::Path, image_uri: Option<&str>) -> std::path::PathBuf {
    use base64::Engine as _;
    let positions: [f32; 9] = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0];
    let bytes: Vec<u8> = positions.iter().flat_map(|f| f.to_le_bytes()).collect();
    let data = base64::engine::general_purpose::STANDARD.encode(&bytes);
    let mut gltf = json!({
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "Tri", "mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                        "min": [0.0, 0.0, 0.0], "max": [1.0, 1.0, 0.0]}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "buffers": [{"byteLength": 36, "uri": format!("data:application/octet-stream;base64,{data}")}]
    });
    if let Some(uri) = image_uri {
        gltf["images"] = json!([{"uri": uri}]);
    }
    let path = dir.join("tri.gltf");
    std::fs::write(&path, serde_json::to_vec(&gltf).unwrap()).unwrap();
    path
}

#[tokio::test]
async fn the_page_is_never_framed_and_never_calls_out() {
    let dir = tempfile::tempdir().unwrap();
    // Every answer, the page and a refusal alike, forbids framing and remote content.
    for path in ["/", "/app.js", "/api/scene", "/api/nothing"] {
        let response = router(app(None))
            .oneshot(Request::get(path).body(Body::empty()).unwrap())
            .await
            .unwrap();
        let headers = response.headers();
        let policy = headers["content-security-policy"].to_str().unwrap();
        assert!(
            policy.contains("frame-ancestors 'none'"),
            "{path}: {policy}"
        );
        assert!(policy.contains("default-src 'none'"), "{path}");
        assert!(policy.contains("img-src 'self' data: blob:;"), "{path}");
        assert_eq!(headers["x-frame-options"], "DENY", "{path}");
        assert_eq!(headers["x-content-type-options"], "nosniff", "{path}");
    }
    // A scene whose image is a remote URL is drawn as boxes: the page is never handed it.
    let beacon = triangle_gltf(dir.path(), Some("http://127.0.0.1:9/beacon.png"));
    let file = shenlong::format::SceneFile::load(&beacon).unwrap();
    let served = App::new(file, settings(None, false, None));
    let (_, scene, _) = call(&served, "GET", "/api/scene", None).await;
    assert_eq!(scene["model"], Value::Null);
    assert_eq!(
        call(&served, "GET", "/api/model", None).await.0,
        StatusCode::NOT_FOUND
    );
    // The same scene with everything inside it is served as a model.
    let inside = tempfile::tempdir().unwrap();
    let embedded = triangle_gltf(inside.path(), None);
    let file = shenlong::format::SceneFile::load(&embedded).unwrap();
    let served = App::new(file, settings(None, false, None));
    let (status, _, body) = call(&served, "GET", "/api/model", None).await;
    assert_eq!(status, StatusCode::OK);
    assert!(!String::from_utf8_lossy(&body).contains("http://"));
}

#[test]
fn slow_request_bodies_are_cut_off_and_do_not_starve_others() {
    use std::io::{Read, Write};
    // As few connections as slow clients: without a body timeout they would hold them all.
    let (_runtime, address) = serve_over_loopback_within(
        workshop_file(),
        shenlong_cli::server::Limits {
            header_timeout: std::time::Duration::from_secs(10),
            body_timeout: std::time::Duration::from_millis(600),
            max_connections: 40,
        },
    );
    // 40 clients send their headers and 10 bytes of a 1,000-byte body, then nothing.
    let mut slow: Vec<std::net::TcpStream> = (0..40)
        .map(|_| {
            let mut s = std::net::TcpStream::connect(address).unwrap();
            s.write_all(
                b"POST /api/edit HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\nContent-Length: 1000\r\n\r\n{\"instruc",
            )
            .unwrap();
            s
        })
        .collect();
    std::thread::sleep(std::time::Duration::from_millis(300));
    // A normal request is answered once the slow bodies time out, well within 5 s.
    let started = std::time::Instant::now();
    let scene: Value = ureq::get(&format!("http://{address}/api/scene"))
        .config()
        .timeout_global(Some(std::time::Duration::from_secs(5)))
        .build()
        .call()
        .unwrap()
        .body_mut()
        .read_json()
        .unwrap();
    assert!(scene["scene"]["objects"].is_array());
    assert!(
        started.elapsed() < std::time::Duration::from_secs(3),
        "{:?}",
        started.elapsed()
    );
    // Each slow client got a 408.
    let mut timed_out = 0;
    for s in &mut slow {
        s.set_read_timeout(Some(std::time::Duration::from_millis(500)))
            .unwrap();
        let mut buf = [0u8; 64];
        if let Ok(n) = s.read(&mut buf) {
            if String::from_utf8_lossy(&buf[..n]).starts_with("HTTP/1.1 408") {
                timed_out += 1;
            }
        }
    }
    assert_eq!(timed_out, slow.len());
}

/// The kitchen the editor's end-to-end test opens: four identical chairs around a dining
/// table, and an object whose name is markup.
const KITCHEN: &str = include_str!("../web/e2e/kitchen.json");

/// A server for the scene JSON `text` (offline, collisions on), with the folder it is in.
fn app_for(text: &str) -> (tempfile::TempDir, Arc<App>) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.json");
    std::fs::write(&path, text).unwrap();
    let file = shenlong::format::SceneFile::load(&path).unwrap();
    (dir, App::new(file, settings(None, true, None)))
}

fn edit_body(instruction: &str) -> String {
    json!({ "instruction": instruction }).to_string()
}

/// `POST /api/edit` with `instruction`: the status and the answer.
async fn post_edit(app: &Arc<App>, instruction: &str) -> (StatusCode, Value) {
    let (status, value, _) = call(app, "POST", "/api/edit", Some(&edit_body(instruction))).await;
    (status, value)
}

#[tokio::test]
async fn an_ambiguous_phrase_is_answered_with_its_candidates_as_data() {
    let (_dir, app) = app_for(KITCHEN);
    let chairs = json!(["chair 1", "chair 2", "chair 3", "chair 4"]);
    // Spaces around the instruction: the span counts in the trimmed instruction.
    let typed = "  move the chair 20 cm to the left ";
    let (status, value) = post_edit(&app, typed).await;
    assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY, "{value}");
    let error = value["error"].as_str().unwrap();
    assert!(error.contains("could mean chair 1, chair 2"), "{error}");
    assert!(!error.contains('\n'), "one line: {error}");
    let ambiguity = &value["ambiguity"];
    assert_eq!(ambiguity["phrase"], "the chair");
    assert_eq!(ambiguity["span"], json!([5, 14]));
    assert_eq!(&typed.trim()[5..14], "the chair");
    assert_eq!(ambiguity["objects"], chairs);
    let choices = ambiguity["choices"].as_array().unwrap();
    assert_eq!(choices.len(), 4);
    for (choice, chair) in choices.iter().zip(chairs.as_array().unwrap()) {
        assert_eq!(&choice["object"], chair);
        assert_eq!(
            choice["instruction"],
            format!("move '{}' 20 cm to the left", chair.as_str().unwrap())
        );
    }
    // Nothing moved, nothing recorded.
    let (_, history, _) = call(&app, "GET", "/api/history", None).await;
    assert_eq!(history, json!({"history": [], "last_edit": null}));

    // A choice, sent back as it is, moves that chair and no other.
    let chosen = choices[2]["instruction"].as_str().unwrap();
    let (status, report) = post_edit(&app, chosen).await;
    assert_eq!(status, StatusCode::OK, "{report}");
    assert_eq!(
        report["moved"],
        json!([{
            "object": "chair 3",
            "how": "moved",
            "before": {"position": [-0.45, 0.0, 0.75], "rotation": [0.0, 1.0, 0.0, 0.0], "scale": 1.0},
            "after": {"position": [-0.65, 0.0, 0.75], "rotation": [0.0, 1.0, 0.0, 0.0], "scale": 1.0},
        }])
    );
    // Each grounded phrase's span is its bytes in the report's instruction.
    let instruction = report["report"]["instruction"].as_str().unwrap();
    for phrase in report["report"]["grounding"].as_array().unwrap() {
        let [start, end] = [0, 1].map(|k| phrase["span"][k].as_u64().unwrap() as usize);
        assert_eq!(instruction[start..end], phrase["phrase"], "{phrase}");
    }
    assert_eq!(
        report["report"]["grounding"][0]["objects"],
        json!(["chair 3"])
    );
    let (_, scene, _) = call(&app, "GET", "/api/scene", None).await;
    assert_eq!(position(&scene, "chair 3"), json!([-0.65, 0, 0.75]));
    assert_eq!(position(&scene, "chair 1"), json!([-0.45, 0, -0.75]));

    // A phrase that asks for another number of objects leaves a choice too.
    let (status, value) = post_edit(&app, "move the two chairs 20 cm to the left").await;
    assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY, "{value}");
    assert_eq!(value["ambiguity"]["phrase"], "the two chairs");
    assert_eq!(value["ambiguity"]["objects"], chairs);

    // Other refusals answer their kind and the message alone.
    for (body, expected, kind) in [
        (
            edit_body("move the 'sofaa' left"),
            StatusCode::UNPROCESSABLE_ENTITY,
            "not_understood",
        ),
        (
            edit_body("sing to the fridge"),
            StatusCode::UNPROCESSABLE_ENTITY,
            "not_understood",
        ),
        ("not json".to_string(), StatusCode::BAD_REQUEST, "bad_input"),
    ] {
        let (status, value, _) = call(&app, "POST", "/api/edit", Some(&body)).await;
        assert_eq!(status, expected, "{body}: {value}");
        assert!(value["error"].is_string(), "{body}: {value}");
        assert_eq!(value["kind"], kind, "{body}: {value}");
        assert!(value.get("ambiguity").is_none(), "{body}: {value}");
    }
}

#[tokio::test]
async fn each_candidate_is_named_in_quotes_its_name_does_not_hold() {
    let (_dir, app) = app_for(
        r#"{"name": "lamps", "objects": [
            {"name": "Bob's lamp", "size": [0.3, 1, 0.3], "position": [0, 0, 0]},
            {"name": "Ann's \"big\" lamp", "size": [0.3, 1, 0.3], "position": [2, 0, 0]},
            {"name": "<img src=x onerror=alert(1)> lamp", "size": [0.3, 0.3, 0.3], "position": [-2, 0, 0]}
        ]}"#,
    );
    let (status, value) = post_edit(&app, "move the lamp 1 m to the left").await;
    assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY, "{value}");
    let choices = value["ambiguity"]["choices"].as_array().unwrap().clone();
    let instructions: Vec<&str> = choices
        .iter()
        .map(|c| c["instruction"].as_str().unwrap())
        .collect();
    assert_eq!(
        instructions,
        [
            "move \"Bob's lamp\" 1 m to the left",
            "move ‘Ann's \"big\" lamp’ 1 m to the left",
            "move '<img src=x onerror=alert(1)> lamp' 1 m to the left",
        ]
    );
    // Each one names its lamp: run, it moves that lamp 1 m to the left, and is undone.
    for choice in &choices {
        let name = choice["object"].as_str().unwrap();
        let instruction = choice["instruction"].as_str().unwrap();
        let (_, before, _) = call(&app, "GET", "/api/scene", None).await;
        let x = position(&before, name)[0].as_f64().unwrap();
        let (status, report) = post_edit(&app, instruction).await;
        assert_eq!(status, StatusCode::OK, "{instruction}: {report}");
        assert_eq!(report["moved"].as_array().unwrap().len(), 1, "{report}");
        assert_eq!(report["moved"][0]["object"], name);
        assert_eq!(
            report["moved"][0]["after"]["position"][0].as_f64().unwrap(),
            x - 1.0
        );
        assert_eq!(
            call(&app, "POST", "/api/undo", None).await.0,
            StatusCode::OK
        );
    }
}

#[tokio::test]
async fn the_last_edit_and_an_example_of_the_scene_are_there_for_a_page_opened_later() {
    let (_dir, app) = app_for(KITCHEN);
    // The example instruction names this scene's own objects and is understood.
    let (status, scene, _) = call(&app, "GET", "/api/scene", None).await;
    assert_eq!(status, StatusCode::OK);
    let example = scene["example"].as_str().unwrap().to_string();
    assert_eq!(example, "put the kettle on the dining table");
    let (status, report) = post_edit(&app, &example).await;
    assert_eq!(status, StatusCode::OK, "{report}");
    assert_eq!(report["understood"]["bindings"][0]["object"], "kettle");
    assert_eq!(
        report["understood"]["bindings"][1]["object"],
        "dining table"
    );
    let id = report["history_id"].clone();
    // The history holds the last edit's whole answer, for a page opened after it.
    let (_, history, _) = call(&app, "GET", "/api/history", None).await;
    assert_eq!(history["history"][0]["id"], id);
    assert_eq!(history["last_edit"], report);
    // It stays the last edit when it is undone (the history says so) or followed by an
    // expression applied; a new edit replaces it.
    assert_eq!(
        call(&app, "POST", "/api/undo", None).await.0,
        StatusCode::OK
    );
    let (_, history, _) = call(&app, "GET", "/api/history", None).await;
    assert_eq!(history["history"][0]["undone"], true);
    assert_eq!(history["last_edit"]["history_id"], id);
    let (status, report) = post_edit(&app, "move the fridge 10 cm to the left").await;
    assert_eq!(status, StatusCode::OK, "{report}");
    let (_, history, _) = call(&app, "GET", "/api/history", None).await;
    assert_eq!(
        history["last_edit"]["report"]["instruction"],
        "move the fridge 10 cm to the left"
    );
    assert_eq!(
        history["last_edit"]["moved"][0]["before"]["position"],
        json!([2.1, 0.0, -1.6])
    );

    // The workshop's example is its own, and a scene whose names are no plain words has
    // none (the page keeps its generic placeholder).
    let (_, workshop, _) = call(&self::app(None), "GET", "/api/scene", None).await;
    assert_eq!(workshop["example"], "put the screwdriver on the workbench");
    let (_dir, hostile) = app_for(
        r#"{"name": "x", "objects": [{"name": "<img src=x onerror=alert(1)>", "size": [1, 1, 1], "position": [0, 0, 0]}]}"#,
    );
    let (_, scene, _) = call(&hostile, "GET", "/api/scene", None).await;
    assert_eq!(scene["example"], Value::Null);
}

#[test]
fn over_loopback_a_choice_is_json_a_browser_can_read_and_send_back() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("kitchen.json");
    std::fs::write(&path, KITCHEN).unwrap();
    let (_runtime, address) =
        serve_over_loopback(shenlong::format::SceneFile::load(&path).unwrap());
    let agent: ureq::Agent = ureq::Agent::config_builder()
        .http_status_as_error(false)
        .timeout_global(Some(std::time::Duration::from_secs(60)))
        .build()
        .into();
    let post = |instruction: &str| {
        let mut response = agent
            .post(&format!("http://{address}/api/edit"))
            .header("content-type", "application/json")
            .send(edit_body(instruction))
            .unwrap();
        let kind = response
            .headers()
            .get("content-type")
            .map(|v| v.to_str().unwrap().to_string());
        let body: Value = serde_json::from_str(&response.body_mut().read_to_string().unwrap())
            .expect("the answer is JSON");
        (response.status().as_u16(), kind, body)
    };
    let (status, kind, body) = post("move the chair 20 cm to the left");
    assert_eq!(status, 422, "{body}");
    assert_eq!(kind.as_deref(), Some("application/json"));
    assert_eq!(body["ambiguity"]["objects"].as_array().unwrap().len(), 4);
    let chosen = body["ambiguity"]["choices"][0]["instruction"]
        .as_str()
        .unwrap()
        .to_string();
    let (status, _, report) = post(&chosen);
    assert_eq!(status, 200, "{report}");
    assert_eq!(report["moved"][0]["object"], "chair 1");
}

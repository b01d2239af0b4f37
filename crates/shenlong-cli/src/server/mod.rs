//! `shenlong serve`: one scene in memory, a JSON API to edit it, and a 3D page.
//!
//! Reads take the scene's lock only for as long as it takes to copy what they return.
//! Edits are serialised by their own lock and run on a blocking thread against a snapshot,
//! so a long language-model call never blocks other requests; the result is swapped in
//! when it is ready. Every change can be undone and redone, and with `--save` the scene is
//! written (atomically) after each one.

pub mod assets;

use axum::body::Bytes;
use axum::extract::rejection::JsonRejection;
use axum::extract::{DefaultBodyLimit, Query, State};
use axum::http::{header, StatusCode, Uri};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use axum::{Json, Router};
use serde::Deserialize;
use serde_json::{json, Value};
use shenlong::collide::ResolveOptions;
use shenlong::format::{Document, Format, SceneFile};
use shenlong::pipeline::backends::{translator, Spec, TranslatorSettings};
use shenlong::pipeline::{EditOptions, System};
use shenlong::session::{ApplyRequest as Apply, EditRequest as Edit, ErrorKind, OpError, Session};
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

/// Largest request body, in bytes.
pub const MAX_BODY: usize = 64 * 1024;
/// Longest instruction, in characters.
pub const MAX_INSTRUCTION: usize = shenlong::pipeline::template::MAX_INSTRUCTION_CHARS;

/// How the server edits.
#[derive(Clone, Debug)]
pub struct ServeSettings {
    /// The default `--llm` backend.
    pub llm: Spec,
    /// The default prompt system.
    pub system: System,
    /// Translator settings (retries, cache, base URL, timeout). The API key stays here.
    pub translator: TranslatorSettings,
    /// Collision resolution; `None` skips it.
    pub collisions: Option<ResolveOptions>,
    /// Where to save the scene after each change.
    pub save: Option<PathBuf>,
}

struct Inner {
    session: Session,
}

/// The server's state.
pub struct App {
    inner: Mutex<Inner>,
    edits: tokio::sync::Mutex<()>,
    settings: ServeSettings,
    /// The address the server listens on, besides loopback, that a `Host` may name.
    bound: Mutex<Option<std::net::IpAddr>>,
    /// The answer to the last instruction edit (its report, `history_id` and `moved`), so
    /// a page opened later shows it.
    last_edit: Mutex<Option<Arc<Value>>>,
    /// An instruction made of the scene's own objects, for the page's placeholder; made
    /// once, on the first request for the scene.
    example: std::sync::OnceLock<Option<String>>,
}

impl App {
    /// A server for this scene.
    pub fn new(file: SceneFile, settings: ServeSettings) -> Arc<Self> {
        Arc::new(Self {
            inner: Mutex::new(Inner {
                session: Session::new(file, settings.save.clone()),
            }),
            edits: tokio::sync::Mutex::new(()),
            settings,
            bound: Mutex::new(None),
            last_edit: Mutex::new(None),
            example: std::sync::OnceLock::new(),
        })
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Inner> {
        self.inner.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// An error answer: a status and the refusal as every front end writes it,
/// `{"kind": "…", "error": "…", "ambiguity": {…}}` ([`OpError`]).
#[derive(Debug)]
pub struct ApiError {
    status: StatusCode,
    error: OpError,
}

impl ApiError {
    /// A refusal of the request itself (its JSON, its size, its origin …): `bad_input`.
    fn new(status: StatusCode, message: impl Into<String>) -> Self {
        Self {
            status,
            error: OpError::new(ErrorKind::BadInput, message),
        }
    }

    /// A failure of the server, not of the request.
    fn internal(message: impl Into<String>) -> Self {
        Self {
            status: StatusCode::INTERNAL_SERVER_ERROR,
            error: OpError::new(ErrorKind::Internal, message),
        }
    }
}

/// The HTTP status of a refusal's kind: 422 for what the request asked, 409 for what the
/// scene does not allow now, 502 for a model server, 500 for a bug.
#[must_use]
pub fn status_of(kind: ErrorKind) -> StatusCode {
    match kind {
        ErrorKind::BadInput
        | ErrorKind::NotUnderstood
        | ErrorKind::Ambiguous
        | ErrorKind::Export => StatusCode::UNPROCESSABLE_ENTITY,
        ErrorKind::NoFreePlace
        | ErrorKind::HeldWouldMove
        | ErrorKind::NothingToUndo
        | ErrorKind::NothingToRedo => StatusCode::CONFLICT,
        ErrorKind::Model => StatusCode::BAD_GATEWAY,
        ErrorKind::Internal => StatusCode::INTERNAL_SERVER_ERROR,
    }
}

impl From<OpError> for ApiError {
    fn from(error: OpError) -> Self {
        Self {
            status: status_of(error.kind),
            error,
        }
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        (self.status, Json(json!(self.error))).into_response()
    }
}

fn bad(message: impl Into<String>) -> ApiError {
    ApiError::new(StatusCode::BAD_REQUEST, message.into())
}

fn json_body<T>(body: Result<Json<T>, JsonRejection>) -> Result<T, ApiError> {
    body.map(|Json(v)| v).map_err(|e| match e {
        JsonRejection::BytesRejection(b) if b.status() == StatusCode::PAYLOAD_TOO_LARGE => {
            ApiError::new(
                StatusCode::PAYLOAD_TOO_LARGE,
                format!("the request body is larger than {MAX_BODY} bytes"),
            )
        }
        other => bad(format!("bad JSON body: {}", other.body_text())),
    })
}

/// Whether a `Host` or `Origin` host names this machine's loopback (any port), or the
/// address the server was bound to.
fn local_host(host: &str, bound: Option<std::net::IpAddr>) -> bool {
    let host = host.trim();
    // Strip the port: `[::1]:8080`, `127.0.0.1:8080`, `localhost:8080`.
    let name = if let Some(rest) = host.strip_prefix('[') {
        rest.split(']').next().unwrap_or_default()
    } else {
        host.rsplit_once(':')
            .filter(|(_, port)| port.chars().all(|c| c.is_ascii_digit()))
            .map_or(host, |(h, _)| h)
    };
    if name.eq_ignore_ascii_case("localhost") {
        return true;
    }
    match name.parse::<std::net::IpAddr>() {
        Ok(ip) => ip.is_loopback() || Some(ip) == bound,
        Err(_) => false,
    }
}

/// Refuses what a web page on another site could send: a `Host` that is not this machine
/// (DNS rebinding), an `Origin` of another site, and a state-changing request that is not
/// `application/json` (a form or a `text/plain` fetch needs no preflight).
async fn guard(
    State(app): State<Arc<App>>,
    request: axum::extract::Request,
    next: axum::middleware::Next,
) -> Response {
    let headers = request.headers();
    let forbidden = |message: String| ApiError::new(StatusCode::FORBIDDEN, message).into_response();
    let bound = *app.bound.lock().unwrap_or_else(|e| e.into_inner());
    let host = headers
        .get(header::HOST)
        .and_then(|h| h.to_str().ok())
        .or_else(|| request.uri().authority().map(|a| a.as_str()));
    match host {
        Some(h) if local_host(h, bound) => {}
        Some(h) => {
            return forbidden(format!(
                "the Host header '{}' is not this server's address",
                h.chars().take(100).collect::<String>()
            ))
        }
        None => return forbidden("the request has no Host header".into()),
    }
    if let Some(origin) = headers.get(header::ORIGIN) {
        let origin = origin.to_str().unwrap_or("");
        let host = origin
            .strip_prefix("http://")
            .or_else(|| origin.strip_prefix("https://"))
            .unwrap_or("");
        if !local_host(host.trim_end_matches('/'), bound) {
            return forbidden(format!(
                "requests from the origin '{}' are not allowed",
                origin.chars().take(100).collect::<String>()
            ));
        }
    }
    if request.method() != axum::http::Method::GET && request.method() != axum::http::Method::HEAD {
        let json = headers
            .get(header::CONTENT_TYPE)
            .and_then(|c| c.to_str().ok())
            .is_some_and(|c| {
                c.split(';')
                    .next()
                    .is_some_and(|t| t.trim().eq_ignore_ascii_case("application/json"))
            });
        if !json {
            return ApiError::new(
                StatusCode::UNSUPPORTED_MEDIA_TYPE,
                "state-changing requests must be sent as Content-Type: application/json",
            )
            .into_response();
        }
    }
    next.run(request).await
}

/// The router: the API and the page, with the default body timeout.
pub fn router(app: Arc<App>) -> Router {
    router_with(app, BODY_TIMEOUT)
}

/// The router, each request's body to be read in full within `body_timeout`.
pub fn router_with(app: Arc<App>, body_timeout: std::time::Duration) -> Router {
    Router::new()
        .route("/api/scene", get(scene))
        .route("/api/edit", post(edit_scene))
        .route("/api/apply", post(apply))
        .route("/api/undo", post(undo))
        .route("/api/redo", post(redo))
        .route("/api/history", get(history))
        .route("/api/export", get(export))
        .route("/api/model", get(model))
        .fallback(get(asset))
        .layer(DefaultBodyLimit::max(MAX_BODY))
        .layer(axum::middleware::from_fn_with_state(
            Arc::clone(&app),
            guard,
        ))
        .layer(axum::middleware::from_fn(
            move |request: axum::extract::Request, next: axum::middleware::Next| {
                read_body_within(request, next, body_timeout)
            },
        ))
        .layer(axum::middleware::from_fn(security_headers))
        .with_state(app)
}

/// Reads a request's body in full (up to the body limit) within `timeout` before anything
/// handles it: a client that sends its headers and then a body a byte at a time, or part
/// of one and then nothing, gets a 408 and its connection back, instead of holding it.
async fn read_body_within(
    request: axum::extract::Request,
    next: axum::middleware::Next,
    timeout: std::time::Duration,
) -> Response {
    let (parts, body) = request.into_parts();
    match tokio::time::timeout(timeout, axum::body::to_bytes(body, MAX_BODY)).await {
        Ok(Ok(bytes)) => {
            next.run(axum::extract::Request::from_parts(
                parts,
                axum::body::Body::from(bytes),
            ))
            .await
        }
        Ok(Err(_)) => ApiError::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            format!("the request body is larger than {MAX_BODY} bytes, or broke off"),
        )
        .into_response(),
        Err(_) => ApiError::new(
            StatusCode::REQUEST_TIMEOUT,
            format!(
                "the request body did not arrive within {} s",
                timeout.as_secs_f64()
            ),
        )
        .into_response(),
    }
}

/// Headers on every answer, refusals included: a strict Content-Security-Policy
/// ([`assets::content_security_policy`]), no framing, no content sniffing, no referrer.
async fn security_headers(
    request: axum::extract::Request,
    next: axum::middleware::Next,
) -> Response {
    let mut response = next.run(request).await;
    let headers = response.headers_mut();
    if let Ok(policy) = header::HeaderValue::from_str(assets::content_security_policy()) {
        headers.insert(header::CONTENT_SECURITY_POLICY, policy);
    }
    headers.insert(
        header::X_FRAME_OPTIONS,
        header::HeaderValue::from_static("DENY"),
    );
    headers.insert(
        header::X_CONTENT_TYPE_OPTIONS,
        header::HeaderValue::from_static("nosniff"),
    );
    headers.insert(
        header::REFERRER_POLICY,
        header::HeaderValue::from_static("no-referrer"),
    );
    response
}

async fn asset(uri: Uri) -> Response {
    match assets::find(uri.path()) {
        Some((content_type, bytes)) => (
            [
                (header::CONTENT_TYPE, content_type),
                (header::CACHE_CONTROL, "no-cache"),
            ],
            bytes,
        )
            .into_response(),
        None if uri.path().starts_with("/api/") => ApiError::new(
            StatusCode::NOT_FOUND,
            format!("no API endpoint {}", uri.path()),
        )
        .into_response(),
        None => ApiError::new(StatusCode::NOT_FOUND, format!("nothing at {}", uri.path()))
            .into_response(),
    }
}

/// The scene as the page draws it: scene-file JSON (boxes) plus supports. Whatever the
/// file held, a scene that cannot be shown is an error answer, never a panic.
fn scene_json(inner: &Inner) -> Result<Value, ApiError> {
    let cannot = |e: String| ApiError::internal(format!("cannot show the scene: {e}"));
    let bytes = inner
        .session
        .file
        .to_bytes(Format::SceneJson)
        .map_err(|e| cannot(e.to_string()))?;
    let mut value: Value = serde_json::from_slice(&bytes).map_err(|e| cannot(e.to_string()))?;
    let supports: Vec<Value> = inner
        .session
        .file
        .scene
        .objects
        .iter()
        .map(|o| {
            o.support.map_or(Value::Null, |s| {
                Value::String(inner.session.file.scene.objects[s].name.clone())
            })
        })
        .collect();
    if let Some(objects) = value.get_mut("objects").and_then(Value::as_array_mut) {
        for (o, s) in objects.iter_mut().zip(supports) {
            if let Some(map) = o.as_object_mut() {
                map.insert("resting_on".into(), s);
            }
        }
    }
    Ok(json!({
        "scene": value,
        "can_undo": inner.session.can_undo(),
        "can_redo": inner.session.can_redo(),
        "model": model_bytes(inner).is_some().then_some("/api/model"),
    }))
}

/// The scene's meshes as glTF, when its source is a GLB or `.gltf` whose buffers and
/// images are all inside it (one with buffers in other files, or any URI to elsewhere, is
/// drawn as boxes).
fn model_bytes(inner: &Inner) -> Option<Vec<u8>> {
    let Document::Gltf(document) = &inner.session.file.document else {
        return None;
    };
    // A URI to anywhere else (`http://…/beacon.png`, a file beside it) is never handed to
    // the page: the scene is drawn as boxes instead.
    if !document.embedded_only() {
        return None;
    }
    match document.container() {
        shenlong::format::gltf::Container::Glb => inner.session.file.to_bytes(Format::Glb).ok(),
        shenlong::format::gltf::Container::Gltf { .. } => {
            inner.session.file.to_bytes(Format::Gltf).ok()
        }
    }
}

async fn model(State(app): State<Arc<App>>) -> Result<Response, ApiError> {
    let inner = app.lock();
    let bytes = model_bytes(&inner).ok_or_else(|| {
        ApiError::new(
            StatusCode::NOT_FOUND,
            "this scene has no self-contained glTF model: it is drawn as boxes",
        )
    })?;
    let content_type = if bytes.starts_with(b"glTF") {
        "model/gltf-binary"
    } else {
        "model/gltf+json"
    };
    Ok((
        [
            (header::CONTENT_TYPE, content_type),
            (header::CACHE_CONTROL, "no-cache"),
        ],
        Bytes::from(bytes),
    )
        .into_response())
}

async fn scene(State(app): State<Arc<App>>) -> Result<Json<Value>, ApiError> {
    let inner = app.lock();
    let mut value = scene_json(&inner)?;
    let example = app
        .example
        .get_or_init(|| example_instruction(&app, &inner.session));
    value["example"] = json!(example);
    Ok(Json(value))
}

/// Whether a name reads well in an example instruction: short, plain words.
fn plain_name(name: &str) -> bool {
    !name.trim().is_empty()
        && name.chars().count() <= 40
        && name
            .chars()
            .all(|c| c.is_alphanumeric() || matches!(c, ' ' | '-' | '_' | '.'))
}

/// An instruction made of the scene's own objects that the scene's grounding and the
/// offline translator both read: `put the screwdriver on the workbench` (its smallest
/// object on the object with the largest footprint it does not already rest on), or
/// `move the screwdriver 30 cm to the left`; `None` when no object has a plain name.
fn example_instruction(app: &App, session: &Session) -> Option<String> {
    let scene = &session.file.scene;
    let grounder = session.grounder();
    let plain: Vec<usize> = (0..scene.objects.len())
        .filter(|&i| plain_name(&scene.objects[i].name))
        .collect();
    let boxes: Vec<shenlong::geometry::Aabb> = plain
        .iter()
        .map(|&i| scene.objects[i].world_aabb())
        .collect();
    let volume = |k: usize| {
        let s = boxes[k].size();
        s.x * s.y * s.z
    };
    let footprint = |k: usize| {
        let s = boxes[k].size();
        s.x * s.z
    };
    let small = (0..plain.len()).min_by(|&a, &b| volume(a).total_cmp(&volume(b)))?;
    let s = plain[small];
    let big = (0..plain.len())
        .filter(|&k| plain[k] != s && Some(plain[k]) != scene.objects[s].support)
        .max_by(|&a, &b| footprint(a).total_cmp(&footprint(b)))
        .map(|k| plain[k]);
    let name = |i: usize| scene.objects[i].name.as_str();
    let mut tries: Vec<(String, Vec<usize>)> = Vec::new();
    if let Some(b) = big {
        tries.push((
            format!("put the {} on the {}", name(s), name(b)),
            vec![s, b],
        ));
        tries.push((
            format!("put the '{}' on the '{}'", name(s), name(b)),
            vec![s, b],
        ));
    }
    tries.push((format!("move the {} 30 cm to the left", name(s)), vec![s]));
    tries.push((format!("move the '{}' 30 cm to the left", name(s)), vec![s]));
    let offline = translator(
        &Spec::Offline,
        &TranslatorSettings {
            system: app.settings.system,
            ..app.settings.translator.clone()
        },
    )
    .ok()?;
    tries.into_iter().find_map(|(text, objects)| {
        let templated = shenlong::pipeline::template_with(&grounder, &text, scene).ok()?;
        (templated.objects == objects && offline.translate(&templated, scene).is_ok())
            .then_some(text)
    })
}

/// The translator a request may choose: `offline`, or the one the server was started
/// with. A request never names a backend of its own: `replay:FILE` or a model server
/// would let a web page read files or spend the user's key.
fn allowed_llm(configured: &Spec, requested: Option<&str>) -> Result<Spec, ApiError> {
    let requested = match requested.map(str::trim) {
        None | Some("") => return Ok(configured.clone()),
        Some(r) => r,
    };
    match requested.parse::<Spec>() {
        Ok(spec) if spec == Spec::Offline || spec == *configured => Ok(spec),
        _ => Err(bad(format!(
            "this server offers the translators 'offline' and '{configured}' (its --llm); '{}' is not one of them",
            requested.chars().take(80).collect::<String>()
        ))),
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct EditRequest {
    instruction: String,
    llm: Option<String>,
    system: Option<String>,
    /// The objects selected, by name: what "it" and "them" mean.
    #[serde(default)]
    selected: Vec<String>,
    /// Answer the whole edit report with the outcome (the page shows it).
    #[serde(default = "yes")]
    report: bool,
}

fn yes() -> bool {
    true
}

/// How edits run here: carrying, and the server's collision settings.
fn edit_options(app: &App) -> EditOptions {
    EditOptions::new(true, app.settings.collisions.clone())
}

/// An outcome as JSON, kept as the last edit's for a page opened later when it is one.
fn answer(outcome: &shenlong::session::Outcome) -> Result<Value, ApiError> {
    serde_json::to_value(outcome).map_err(|e| {
        ApiError::internal(format!(
            "the change was made (history {:?}) but its outcome cannot be written: {e}",
            outcome.history_id
        ))
    })
}

async fn edit_scene(
    State(app): State<Arc<App>>,
    body: Result<Json<EditRequest>, JsonRejection>,
) -> Result<Json<Value>, ApiError> {
    let request = json_body(body)?;
    if request.instruction.chars().count() > MAX_INSTRUCTION {
        return Err(ApiError::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            format!("the instruction is longer than {MAX_INSTRUCTION} characters"),
        ));
    }
    let system = match &request.system {
        Some(name) => System::parse(name).map_err(|e| bad(e.to_string()))?,
        None => app.settings.system,
    };
    let llm = allowed_llm(&app.settings.llm, request.llm.as_deref())?;
    let settings = TranslatorSettings {
        system,
        ..app.settings.translator.clone()
    };
    let translator = translator(&llm, &settings).map_err(|e| bad(e.to_string()))?;
    let options = edit_options(&app);
    // One edit at a time; reads go on meanwhile, on the scene as it was.
    let _turn = app.edits.lock().await;
    let working = app.lock().session.working();
    let pending = tokio::task::spawn_blocking(move || {
        let edit = Edit {
            instruction: &request.instruction,
            selected: &request.selected,
            report: true,
        };
        (
            working.edit(&edit, translator.as_ref(), &options),
            request.report,
        )
    })
    .await
    .map_err(|e| ApiError::internal(format!("the edit stopped: {e}")))?;
    let (pending, with_report) = pending;
    // A refusal is heard too: a correction ("the left one") leans on it.
    let mut outcome = app.lock().session.conclude(pending)?;
    let kept = Arc::new(answer(&outcome)?);
    *app.last_edit.lock().unwrap_or_else(|e| e.into_inner()) = Some(Arc::clone(&kept));
    if !with_report {
        outcome.report = None;
        return Ok(Json(answer(&outcome)?));
    }
    Ok(Json(Value::clone(&kept)))
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ApplyRequest {
    /// The object moved: X1.
    object: String,
    /// The expression (`expr` is read too).
    #[serde(alias = "expr")]
    expression: String,
    /// Other objects the expression uses, by variable: `{"X2": "tool table"}`.
    #[serde(default)]
    bind: std::collections::BTreeMap<String, String>,
}

async fn apply(
    State(app): State<Arc<App>>,
    body: Result<Json<ApplyRequest>, JsonRejection>,
) -> Result<Json<Value>, ApiError> {
    let request = json_body(body)?;
    let objects = shenlong::session::bound_objects(&request.object, &request.bind)?;
    let options = edit_options(&app);
    let _turn = app.edits.lock().await;
    let working = app.lock().session.working();
    // Collision search can take its budget: off the async workers.
    let pending = tokio::task::spawn_blocking(move || {
        working.apply(
            &Apply {
                objects: &objects,
                expression: &request.expression,
            },
            &options,
        )
    })
    .await
    .map_err(|e| ApiError::internal(format!("the edit stopped: {e}")))?;
    let outcome = app.lock().session.conclude(pending)?;
    Ok(Json(answer(&outcome)?))
}

fn step(app: &App, undo: bool) -> Result<Json<Value>, ApiError> {
    let mut inner = app.lock();
    let outcome = if undo {
        inner.session.undo()
    } else {
        inner.session.redo()
    }?;
    Ok(Json(answer(&outcome)?))
}

async fn undo(State(app): State<Arc<App>>) -> Result<Json<Value>, ApiError> {
    let _turn = app.edits.lock().await;
    step(&app, true)
}

async fn redo(State(app): State<Arc<App>>) -> Result<Json<Value>, ApiError> {
    let _turn = app.edits.lock().await;
    step(&app, false)
}

async fn history(State(app): State<Arc<App>>) -> Json<Value> {
    let last_edit = app
        .last_edit
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .clone();
    Json(json!({
        "history": app.lock().session.history(),
        "last_edit": last_edit.as_deref(),
    }))
}

async fn export(
    State(app): State<Arc<App>>,
    query: Result<Query<Vec<(String, String)>>, axum::extract::rejection::QueryRejection>,
) -> Result<Response, ApiError> {
    let Query(pairs) = query.map_err(|e| bad(format!("bad query: {}", e.body_text())))?;
    let formats: Vec<&String> = pairs
        .iter()
        .filter(|(k, _)| k == "format")
        .map(|(_, v)| v)
        .collect();
    if let Some((k, _)) = pairs.iter().find(|(k, _)| k != "format") {
        return Err(bad(format!(
            "unknown query parameter '{k}': use format=json|glb|gltf|usda|tdw"
        )));
    }
    if formats.len() > 1 {
        return Err(bad("give format= once"));
    }
    let name = formats
        .first()
        .map_or_else(|| "json".to_string(), |f| f.to_string());
    let (format, content_type, extension) = match name.as_str() {
        "json" => (Format::SceneJson, "application/json", "json"),
        "glb" => (Format::Glb, "model/gltf-binary", "glb"),
        "gltf" => (Format::Gltf, "model/gltf+json", "gltf"),
        "usda" => (Format::Usda, "model/vnd.usda", "usda"),
        "tdw" => (Format::TdwCommands, "application/json", "tdw.json"),
        other => {
            return Err(bad(format!(
                "unknown format '{other}': use json, glb, gltf, usda or tdw"
            )))
        }
    };
    let inner = app.lock();
    let bytes = inner
        .session
        .file
        .to_bytes(format)
        .map_err(|e| OpError::new(ErrorKind::Export, e.to_string()))?;
    let filename = format!(
        "{}.{extension}",
        inner
            .session
            .file
            .scene
            .name
            .replace(|c: char| !c.is_alphanumeric() && c != '-' && c != '_', "_")
    );
    Ok((
        [
            (header::CONTENT_TYPE, content_type.to_string()),
            (
                header::CONTENT_DISPOSITION,
                format!("attachment; filename=\"{filename}\""),
            ),
        ],
        Bytes::from(bytes),
    )
        .into_response())
}

/// How long a client may take to send a request's headers (and, between requests on a
/// kept-alive connection, the next one's) before the connection is closed.
pub const HEADER_TIMEOUT: std::time::Duration = std::time::Duration::from_secs(10);
/// How long a client may take to send a request's body once its headers are in.
pub const BODY_TIMEOUT: std::time::Duration = std::time::Duration::from_secs(10);
/// The most connections served at once; more wait to be accepted.
pub const MAX_CONNECTIONS: usize = 512;

/// What a client may hold of the server, and for how long.
#[derive(Clone, Copy, Debug)]
pub struct Limits {
    /// To send a request's headers (and, on a kept-alive connection, the next request's).
    pub header_timeout: std::time::Duration,
    /// To send a request's body once its headers are in.
    pub body_timeout: std::time::Duration,
    /// Connections served at once; more wait to be accepted.
    pub max_connections: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            header_timeout: HEADER_TIMEOUT,
            body_timeout: BODY_TIMEOUT,
            max_connections: MAX_CONNECTIONS,
        }
    }
}

/// Serves until Ctrl-C, with the default limits.
pub async fn serve(app: Arc<App>, listener: tokio::net::TcpListener) -> std::io::Result<()> {
    serve_with(app, listener, Limits::default()).await
}

/// Serves until Ctrl-C within `limits`: each connection must send its headers, and each
/// request its body, in time, and at most so many are served at once, so slow or idle
/// clients cannot starve the others.
pub async fn serve_with(
    app: Arc<App>,
    listener: tokio::net::TcpListener,
    limits: Limits,
) -> std::io::Result<()> {
    let Limits {
        header_timeout,
        body_timeout,
        max_connections,
    } = limits;
    *app.bound.lock().unwrap_or_else(|e| e.into_inner()) = Some(listener.local_addr()?.ip());
    let service = router_with(app, body_timeout);
    let permits = Arc::new(tokio::sync::Semaphore::new(max_connections.max(1)));
    let shutdown = tokio::signal::ctrl_c();
    tokio::pin!(shutdown);
    loop {
        let permit = tokio::select! {
            _ = &mut shutdown => return Ok(()),
            permit = Arc::clone(&permits).acquire_owned() => permit.expect("the semaphore is never closed"),
        };
        let (stream, _) = tokio::select! {
            _ = &mut shutdown => return Ok(()),
            accepted = listener.accept() => match accepted {
                Ok(a) => a,
                // A failed accept (too many open files, a reset) ends that connection only.
                Err(_) => continue,
            },
        };
        let service = service.clone();
        tokio::spawn(async move {
            let io = hyper_util::rt::TokioIo::new(stream);
            let hyper_service = hyper_util::service::TowerToHyperService::new(service);
            let _ = hyper::server::conn::http1::Builder::new()
                .timer(hyper_util::rt::TokioTimer::new())
                .header_read_timeout(header_timeout)
                .serve_connection(io, hyper_service)
                .await;
            drop(permit);
        });
    }
}

//! `shenlong mcp`: the scene as a Model Context Protocol server over stdio, for AI
//! assistants. One scene is kept in memory ([`Session`]: undo, redo, history); the tools
//! list it, edit it by instruction (the whole pipeline: grounding, the server's translator,
//! evaluation, collisions), apply CGA expressions, undo and redo, render the plan, save to
//! the one file given at start-up and export it. The scene is also a resource,
//! `scene://current`, whose subscribers are told after each change.
//!
//! Nothing a client sends chooses a file to read or write, and nothing a client or a model
//! says is executed: instructions and expressions are read by Shenlong's grammar and
//! expression language. Every failure is a tool error (`isError: true`) with one line.

use base64::Engine as _;
use rmcp::handler::server::router::tool::ToolRouter;
use rmcp::handler::server::wrapper::Parameters;
use rmcp::model::{
    CallToolResult, ContentBlock, ListResourcesResult, PaginatedRequestParams,
    ReadResourceRequestParams, ReadResourceResponse, ReadResourceResult, Resource,
    ResourceContents, ResourceUpdatedNotificationParam, ServerCapabilities, ServerConfig,
    SubscribeRequestParams, UnsubscribeRequestParams,
};
use rmcp::service::RequestContext;
use rmcp::{schemars, tool, tool_handler, tool_router, ErrorData, Json, Peer, RoleServer};
use serde::Deserialize;
use shenlong::collide::ResolveOptions;
use shenlong::format::{Format, SceneFile};
use shenlong::pipeline::{EditOptions, Translator};
use shenlong::scene::listing::{listing, SceneListing};
use shenlong::session::{
    bound_objects, ApplyRequest as Apply, EditRequest as Edit, OpError, Outcome, Session,
};
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

/// The URI of the scene resource.
pub const SCENE_URI: &str = "scene://current";

/// How the server edits: chosen on the command line, never by a client.
pub struct McpSettings {
    /// The translator, made once at start-up (`offline`, `openai:MODEL`, a cascade …);
    /// the API key stays in it.
    pub translator: Box<dyn Translator>,
    /// Collision resolution; `None` skips it.
    pub collisions: Option<ResolveOptions>,
    /// The file `save` writes.
    pub save: Option<PathBuf>,
}

struct State {
    session: Mutex<Session>,
    /// One change at a time.
    edits: tokio::sync::Mutex<()>,
    settings: McpSettings,
    subscribed: AtomicBool,
}

/// The MCP server.
#[derive(Clone)]
pub struct ShenlongMcp {
    state: Arc<State>,
    tool_router: ToolRouter<Self>,
}

/// `edit`'s input.
#[derive(Debug, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct EditRequest {
    /// What to do, in words: "put the 'orange bottle' on top of the 'tool table'", "move
    /// the couch a bit to the left", "turn the chair nearest the desk to face the TV".
    pub instruction: String,
    /// Objects the user has selected, by name: what "it", "them" and "the selection" mean
    /// when the instruction names nothing before them.
    #[serde(default)]
    pub selected: Vec<String>,
    /// Also answer the whole edit report (grounding of each phrase, the translator's
    /// exchanges, expressions, versors, timings): several kilobytes.
    #[serde(default)]
    pub report: bool,
}

/// `apply`'s input.
#[derive(Debug, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ApplyRequest {
    /// The object to move; it is X1 in the expression.
    pub object: String,
    /// A CGA expression for X1's transformation, e.g. `T(0.5*e1)`.
    pub expression: String,
    /// Other objects the expression uses, by variable: `{"X2": "tool table"}` (X2, X3, …
    /// in order, with no gaps).
    #[serde(default)]
    pub bind: BTreeMap<String, String>,
}

/// `render`'s input.
#[derive(Debug, Default, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RenderRequest {
    /// Also draw where things were before the last change, with what moved highlighted.
    #[serde(default)]
    pub before: bool,
}

/// `export`'s input.
#[derive(Debug, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ExportRequest {
    /// `json` (Shenlong scene JSON), `gltf`, `glb` (only for a scene read from glTF),
    /// `usda` (only for a scene read from a USD stage) or `tdw` (ThreeDWorld commands).
    pub format: ExportFormat,
}

/// The formats `export` writes.
#[derive(Clone, Copy, Debug, schemars::JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum ExportFormat {
    /// Shenlong scene JSON.
    Json,
    /// glTF JSON (a glTF source with its moved nodes rewritten; any other scene as a new
    /// glTF of boxes).
    Gltf,
    /// Binary glTF (likewise).
    Glb,
    /// USD as text (the source must be a USD stage: the original with the moved prims'
    /// transforms rewritten).
    Usda,
    /// ThreeDWorld commands placing every object.
    Tdw,
}

impl<'de> Deserialize<'de> for ExportFormat {
    /// By name; an unknown name is quoted in the error cut to 40 characters, so that a
    /// 10 MB `format` is not echoed back.
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let name = String::deserialize(d)?;
        Ok(match name.as_str() {
            "json" => Self::Json,
            "gltf" => Self::Gltf,
            "glb" => Self::Glb,
            "usda" => Self::Usda,
            "tdw" => Self::Tdw,
            other => {
                let shown: String = other.chars().take(40).collect();
                let cut = if other.chars().count() > 40 {
                    "…"
                } else {
                    ""
                };
                return Err(serde::de::Error::custom(format!(
                    "unknown format '{shown}{cut}': use json, gltf, glb, usda or tdw"
                )));
            }
        })
    }
}

const APPLY_DESCRIPTION: &str = "Apply a CGA (conformal geometric algebra) expression to one object, for an assistant that writes the transformation itself. Nothing is executed: the expression is parsed and evaluated by Shenlong's expression language, checked to be a translation·rotation·uniform scale, applied about the object's pivot (the bottom centre of its box), carrying what rests on it, then collisions are resolved.\n\nFrame: metres, right-handed, +Y up, +X right, +Z towards the viewer (front); e1, e2, e3 are the x, y, z unit vectors. The object is X1; bind others as X2, X3… with `bind`.\nVersors, one example each:\n- T(v) translates by the vector v: T(0.5*e1) moves 0.5 m right.\n- R(angle, u, v) rotates by angle (radians) in the plane from u to v: R(pi/2, e3, e1) turns a quarter turn counter-clockwise seen from above.\n- D(s) scales uniformly about the pivot: D(2) doubles the size.\n- Compose with *, right to left: T(e2) * R(pi/4, e3, e1) turns, then lifts 1 m.\nBoxes (points and vectors of the world box), one example each; `| e2` takes the y component (| binds loosely: parenthesise it):\n- X1.min, X1.max: the low and high corners: T(((X2.max | e2) - (X1.min | e2)) * e2) puts X1's bottom at X2's top height.\n- X1.center: T(((X2.center - X1.center) | e1) * e1) lines X1 up with X2 along x.\n- X1.size: T((X1.size | e1) * e1) moves X1 by its own width to the right.\n- X1.front: the direction X1 faces: T(0.3 * X1.front) moves it 30 cm forward.\nExample, X1 on top of X2: T(((X2.max | e2) - (X1.min | e2)) * e2 + ((X2.center - X1.center) | e1) * e1 + ((X2.center - X1.center) | e3) * e3).";

impl ShenlongMcp {
    /// A server for this scene.
    pub fn new(file: SceneFile, settings: McpSettings) -> Self {
        let session = Session::saving_on_request(file, settings.save.clone());
        Self {
            state: Arc::new(State {
                session: Mutex::new(session),
                edits: tokio::sync::Mutex::new(()),
                settings,
                subscribed: AtomicBool::new(false),
            }),
            tool_router: Self::tool_router(),
        }
    }

    fn session(&self) -> std::sync::MutexGuard<'_, Session> {
        self.state
            .session
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    fn options(&self) -> EditOptions {
        EditOptions::new(true, self.state.settings.collisions.clone())
    }

    /// An operation's answer: its outcome, or its refusal as a tool error with the same
    /// data (`{"kind", "error", "ambiguity"}`); subscribers are told when it changed
    /// the scene.
    async fn answer(
        &self,
        result: Result<Outcome, OpError>,
        peer: &Peer<RoleServer>,
    ) -> Result<CallToolResult, ToolError> {
        match result {
            Ok(outcome) => {
                if outcome.history_id.is_some() {
                    self.notify(peer).await;
                }
                let value = serde_json::to_value(&outcome).map_err(|e| e.to_string())?;
                Ok(CallToolResult::structured(value))
            }
            Err(mut error) => {
                error.message = cut(error.message);
                let value = serde_json::to_value(&error).map_err(|e| e.to_string())?;
                Ok(CallToolResult::structured_error(value))
            }
        }
    }

    async fn notify(&self, peer: &Peer<RoleServer>) {
        if self.state.subscribed.load(Ordering::Relaxed) {
            // A client that went away is not an error of the change.
            let _ = peer
                .notify_resource_updated(ResourceUpdatedNotificationParam::new(SCENE_URI))
                .await;
        }
    }

    fn scene_text(&self) -> Result<String, String> {
        let bytes = self
            .session()
            .file
            .to_bytes(Format::SceneJson)
            .map_err(|e| e.to_string())?;
        String::from_utf8(bytes).map_err(|e| e.to_string())
    }
}

/// The longest error text a tool answers with: what an error quotes of a huge argument
/// (a 10 MB object name) is cut, so an answer stays small.
const MAX_ERROR_CHARS: usize = 2000;

/// A tool's error: one line, cut to [`MAX_ERROR_CHARS`].
#[derive(Debug)]
pub struct ToolError(String);

impl From<String> for ToolError {
    fn from(message: String) -> Self {
        Self(message)
    }
}

impl From<&str> for ToolError {
    fn from(message: &str) -> Self {
        Self(message.to_string())
    }
}

/// `message` cut to [`MAX_ERROR_CHARS`].
fn cut(message: String) -> String {
    match message.char_indices().nth(MAX_ERROR_CHARS) {
        Some((at, _)) => format!("{}… (cut at {MAX_ERROR_CHARS} characters)", &message[..at]),
        None => message,
    }
}

impl rmcp::model::IntoContents for ToolError {
    fn into_contents(self) -> Vec<rmcp::model::ContentBlock> {
        vec![rmcp::model::ContentBlock::text(cut(self.0))]
    }
}

#[tool_router]
impl ShenlongMcp {
    /// The scene's objects.
    #[tool(
        description = "List the scene's objects: for each its name, position (bottom centre), size, rotation (quaternion [x, y, z, w]), scale, world box, the direction it faces, and what it rests on. Metres; +Y up, +X right, +Z towards the viewer.",
        annotations(read_only_hint = true)
    )]
    async fn list_objects(&self) -> Result<Json<SceneListing>, ToolError> {
        Ok(Json(listing(&self.session().file.scene)))
    }

    /// An edit by instruction.
    #[tool(
        description = "Edit the scene by an instruction in words, as a person would say it: \"put the orange bottle on top of the tool table\", \"move the couch a bit to the left\", \"turn the chair nearest the desk to face the TV\", \"put the mug and the bowl on the dresser\". Shenlong finds the objects meant (or refuses, naming the candidates — it never guesses), translates the instruction into exact CGA transformations, applies them and resolves collisions. Answers what moved (each object with how — moved, carried or pushed — and its pose before and after), notes (collisions cleared, objects held), and the instruction as understood (objects as variables X1, X2 … and what each stands for); with report: true also the whole edit report. A refusal is an error whose `kind` says why (not_understood, ambiguous, no_free_place, held_would_move, bad_input, model) and, for `ambiguous`, `ambiguity.choices`: each candidate with the instruction that names it, ready to send. The server keeps the conversation: after an edit, \"it\", \"them\" and \"that\" mean what the last edit moved, and follow-ups need no names — \"a bit more\", \"again\", \"not so far\", \"no, the other one\", \"no, on the shelf\", \"and the lamp too\", \"put it back\", \"undo that\"; after an ambiguous refusal, \"the left one\" picks. `selected` names the objects \"it\" and \"them\" mean, over the last edit's. Name objects when starting something new (a name, or a description such as \"the chair by the window\"). Undo with `undo`."
    )]
    async fn edit(
        &self,
        Parameters(request): Parameters<EditRequest>,
        peer: Peer<RoleServer>,
    ) -> Result<CallToolResult, ToolError> {
        let _turn = self.state.edits.lock().await;
        let working = self.session().working();
        let state = Arc::clone(&self.state);
        let options = self.options();
        let pending = tokio::task::spawn_blocking(move || {
            let edit = Edit {
                instruction: &request.instruction,
                selected: &request.selected,
                report: request.report,
            };
            working.edit(&edit, state.settings.translator.as_ref(), &options)
        })
        .await
        .map_err(|e| format!("the edit stopped: {e}"))?;
        let result = self.session().conclude(pending);
        self.answer(result, &peer).await
    }

    /// An expression applied to one object.
    #[tool(description = APPLY_DESCRIPTION)]
    async fn apply(
        &self,
        Parameters(request): Parameters<ApplyRequest>,
        peer: Peer<RoleServer>,
    ) -> Result<CallToolResult, ToolError> {
        let objects = match bound_objects(&request.object, &request.bind) {
            Ok(objects) => objects,
            Err(e) => return self.answer(Err(e), &peer).await,
        };
        let _turn = self.state.edits.lock().await;
        let working = self.session().working();
        let options = self.options();
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
        .map_err(|e| format!("the edit stopped: {e}"))?;
        let result = self.session().conclude(pending);
        self.answer(result, &peer).await
    }

    /// Undo the last change.
    #[tool(
        description = "Undo the last change (edit, apply or redo). Answers the change's history_id and what moved back (each object's pose before and after); an error of kind nothing_to_undo when there is none."
    )]
    async fn undo(&self, peer: Peer<RoleServer>) -> Result<CallToolResult, ToolError> {
        self.step(true, &peer).await
    }

    /// Redo the last undone change.
    #[tool(
        description = "Redo the last undone change. Answers the change's history_id and what moved; an error of kind nothing_to_redo when there is none."
    )]
    async fn redo(&self, peer: Peer<RoleServer>) -> Result<CallToolResult, ToolError> {
        self.step(false, &peer).await
    }

    /// The history of changes.
    #[tool(
        description = "The changes made so far, oldest first: id, kind (edit or apply), the instruction or expression, the objects that moved, and whether it is undone.",
        annotations(read_only_hint = true)
    )]
    async fn history(&self) -> Result<CallToolResult, ToolError> {
        let session = self.session();
        Ok(CallToolResult::structured(serde_json::json!({
            "history": session.history(),
            "can_undo": session.can_undo(),
            "can_redo": session.can_redo(),
        })))
    }

    /// The top-down plan as a picture.
    #[tool(
        description = "The scene seen from above as a PNG picture (a plan: +X right, +Z down the page). With before: true, also where things were before the last change, with what moved highlighted.",
        annotations(read_only_hint = true)
    )]
    async fn render(
        &self,
        Parameters(request): Parameters<RenderRequest>,
    ) -> Result<CallToolResult, ToolError> {
        // The plan is drawn from the session's scene as it is, with no copy of it; only
        // the picture is made off the async workers.
        let svg = {
            let session = self.session();
            let previous = request
                .before
                .then(|| session.before_last_change())
                .flatten();
            shenlong::render::plan_svg(&session.file.scene, previous.as_ref())
        };
        let png = tokio::task::spawn_blocking(move || shenlong::render::svg_to_png(&svg))
            .await
            .map_err(|e| format!("the render stopped: {e}"))?
            .map_err(|e| e.to_string())?;
        let data = base64::engine::general_purpose::STANDARD.encode(png);
        Ok(CallToolResult::success(vec![ContentBlock::image(
            data,
            "image/png",
        )]))
    }

    /// Save to the `--save` file.
    #[tool(
        description = "Save the scene to the file the server was started with (--save), atomically. The file cannot be chosen here."
    )]
    async fn save(&self) -> Result<CallToolResult, ToolError> {
        let session = self.session();
        let Some(path) = session.save_path().map(std::path::Path::to_path_buf) else {
            return Err(
                "this server was started without --save, so it has no file to save to".into(),
            );
        };
        session.save().map_err(|e| e.to_string())?;
        Ok(CallToolResult::structured(
            serde_json::json!({"saved": path.display().to_string()}),
        ))
    }

    /// The scene in a format, as content.
    #[tool(
        description = "The scene as a file's content: json (Shenlong scene JSON), gltf or glb (a scene read from glTF/GLB: the original with the moved nodes rewritten; any other: a new glTF of its boxes), usda (a scene read from a USD stage: its root layer with only the moved prims' transform lines changed; any other: a new stage of boxes), or tdw (ThreeDWorld commands). Text formats come as text, glb as a base64 resource.",
        annotations(read_only_hint = true)
    )]
    async fn export(
        &self,
        Parameters(request): Parameters<ExportRequest>,
    ) -> Result<CallToolResult, ToolError> {
        let (format, mime, extension) = match request.format {
            ExportFormat::Json => (Format::SceneJson, "application/json", "json"),
            ExportFormat::Gltf => (Format::Gltf, "model/gltf+json", "gltf"),
            ExportFormat::Glb => (Format::Glb, "model/gltf-binary", "glb"),
            ExportFormat::Usda => (Format::Usda, "model/vnd.usda", "usda"),
            ExportFormat::Tdw => (Format::TdwCommands, "application/json", "tdw.json"),
        };
        let bytes = self
            .session()
            .file
            .to_bytes(format)
            .map_err(|e| e.to_string())?;
        let uri = format!("scene://current.{extension}");
        let contents = match String::from_utf8(bytes) {
            Ok(text) if !matches!(format, Format::Glb) => ResourceContents::TextResourceContents {
                uri,
                mime_type: Some(mime.into()),
                text,
                meta: None,
            },
            Ok(text) => blob(uri, mime, text.into_bytes()),
            Err(e) => blob(uri, mime, e.into_bytes()),
        };
        Ok(CallToolResult::success(vec![ContentBlock::resource(
            contents,
        )]))
    }
}

fn blob(uri: String, mime: &str, bytes: Vec<u8>) -> ResourceContents {
    ResourceContents::BlobResourceContents {
        uri,
        mime_type: Some(mime.into()),
        blob: base64::engine::general_purpose::STANDARD.encode(bytes),
        meta: None,
    }
}

impl ShenlongMcp {
    async fn step(&self, undo: bool, peer: &Peer<RoleServer>) -> Result<CallToolResult, ToolError> {
        let _turn = self.state.edits.lock().await;
        let result = if undo {
            self.session().undo()
        } else {
            self.session().redo()
        };
        self.answer(result, peer).await
    }
}

#[tool_handler(router = self.tool_router)]
impl rmcp::ServerHandler for ShenlongMcp {
    fn get_info(&self) -> ServerConfig {
        ServerConfig::new(
            ServerCapabilities::builder()
                .enable_tools()
                .enable_resources()
                .enable_resources_subscribe()
                .build(),
        )
        .with_instructions(
            "Shenlong edits one 3D scene of separate objects, exactly and safely. Call list_objects to see it; edit with an instruction in words (edit) or a CGA expression (apply); undo/redo; render shows the plan; save writes the server's own file. The scene is also the resource scene://current.",
        )
    }

    async fn list_resources(
        &self,
        _request: Option<PaginatedRequestParams>,
        _context: RequestContext<RoleServer>,
    ) -> Result<ListResourcesResult, ErrorData> {
        let name = self.session().file.scene.name.clone();
        Ok(ListResourcesResult::with_all_items(vec![Resource::new(
            SCENE_URI, name,
        )
        .with_description("The scene being edited, as Shenlong scene JSON")
        .with_mime_type("application/json")]))
    }

    async fn read_resource(
        &self,
        request: ReadResourceRequestParams,
        _context: RequestContext<RoleServer>,
    ) -> Result<ReadResourceResponse, ErrorData> {
        if request.uri != SCENE_URI {
            return Err(ErrorData::resource_not_found(
                format!("no resource {}: the scene is {SCENE_URI}", request.uri),
                None,
            ));
        }
        Ok(
            ReadResourceResult::new(vec![ResourceContents::TextResourceContents {
                uri: SCENE_URI.into(),
                mime_type: Some("application/json".into()),
                text: self
                    .scene_text()
                    .map_err(|m| ErrorData::internal_error(m, None))?,
                meta: None,
            }])
            .into(),
        )
    }

    async fn subscribe(
        &self,
        request: SubscribeRequestParams,
        _context: RequestContext<RoleServer>,
    ) -> Result<(), ErrorData> {
        if request.uri != SCENE_URI {
            return Err(ErrorData::resource_not_found(
                format!("no resource {}", request.uri),
                None,
            ));
        }
        self.state.subscribed.store(true, Ordering::Relaxed);
        Ok(())
    }

    async fn unsubscribe(
        &self,
        _request: UnsubscribeRequestParams,
        _context: RequestContext<RoleServer>,
    ) -> Result<(), ErrorData> {
        self.state.subscribed.store(false, Ordering::Relaxed);
        Ok(())
    }
}

/// Serves `file` over stdin/stdout until the client closes it.
///
/// # Errors
/// The transport failed to start or broke.
pub async fn serve_stdio(file: SceneFile, settings: McpSettings) -> anyhow::Result<()> {
    use rmcp::ServiceExt;
    let server = ShenlongMcp::new(file, settings)
        .serve(rmcp::transport::stdio())
        .await
        .map_err(|e| anyhow::anyhow!("cannot start the MCP server: {e}"))?;
    server
        .waiting()
        .await
        .map_err(|e| anyhow::anyhow!("the MCP server stopped: {e}"))?;
    Ok(())
}

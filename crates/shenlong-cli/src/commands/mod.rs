//! One module per subcommand.

pub mod apply;
pub mod bench;
pub mod chat;
pub mod convert;
pub mod edit;
pub mod eval;
pub mod examples;
pub mod mcp;
pub mod render;
pub mod serve;

use anyhow::{Context, Result};
use shenlong::format::SceneFile;
use std::io::Write;
use std::path::Path;

/// How a glTF or USD file is read when its own conventions are missing or wrong.
#[derive(clap::Args, Clone, Copy, Debug, Default)]
pub struct ReadArgs {
    /// The units a glTF or USD file is modelled in — mm, cm, m, in or ft — when its own
    /// are missing or wrong (a CAD export in millimetres). Without it, a file whose
    /// furniture is tens of metres across is refused, naming the units it looks modelled in.
    #[arg(long, value_name = "UNITS")]
    units: Option<shenlong::format::Units>,
    /// The axis a glTF or USD file's models face, in the file's own frame: +x, -x, +y, -y,
    /// +z or -z (default: +z for glTF and Y-up USD, -y for Z-up USD as Blender writes it).
    /// A node's own `shenlong:front` wins.
    #[arg(long, value_name = "AXIS", allow_hyphen_values = true)]
    front: Option<shenlong::format::Axis>,
}

impl ReadArgs {
    /// Whether either was given.
    #[must_use]
    pub fn given(&self) -> bool {
        self.units.is_some() || self.front.is_some()
    }

    /// The library's options.
    #[must_use]
    pub fn options(&self) -> shenlong::format::ReadOptions {
        shenlong::format::ReadOptions {
            units: self.units,
            front: self.front,
        }
    }
}

/// Loads a scene file, or a built-in example given as `example:NAME`.
pub fn load_scene(spec: &str) -> Result<SceneFile> {
    load_scene_with(spec, &ReadArgs::default())
}

/// Loads a scene file read as `read` says, or a built-in example given as `example:NAME`.
pub fn load_scene_with(spec: &str, read: &ReadArgs) -> Result<SceneFile> {
    if let Some(name) = spec.strip_prefix("example:") {
        let scene = shenlong::examples::build(name)
            .with_context(|| format!("unknown example '{name}': `shenlong examples` lists them"))?;
        return Ok(SceneFile {
            scene,
            document: shenlong::format::Document::None,
            path: None,
        });
    }
    Ok(SceneFile::load_with(Path::new(spec), &read.options())?)
}

/// Writes an edited scene to `output` (format by extension) or, without one, to stdout in
/// the input's format; then, with `tdw`, the edit from `before` (the scene as it was,
/// needed only then) as ThreeDWorld commands. The commands are rendered before anything
/// is written.
/// Where an edited scene goes: a file (by its extension), stdout without one; for a USD
/// stage, optionally as a layer over the input.
#[derive(Clone, Copy, Default)]
pub struct Output<'a> {
    /// The file; stdout when `None`.
    pub path: Option<&'a Path>,
    /// Write a USD layer over the input instead of the whole stage.
    pub usd_layer: bool,
}

pub fn write_edit(
    file: &SceneFile,
    before: Option<&shenlong::scene::Scene>,
    output: Output<'_>,
    tdw: Option<&Path>,
) -> Result<()> {
    let commands = tdw.zip(before).map(|(path, before)| {
        let list = shenlong::format::tdw::edit(before, &file.scene, &file.tdw_ids());
        (
            path,
            shenlong::format::pretty::to_string(&serde_json::Value::Array(list)),
        )
    });
    // The commands are made ready before the scene is written, and a stream among them
    // written first: when they cannot be written, neither is the scene.
    let commands = match commands {
        Some((path, text)) => {
            let prepared = shenlong::io::prepare(path, text.as_bytes())
                .with_context(|| format!("cannot write {}", path.display()))?;
            match prepared {
                stream @ shenlong::io::Prepared::InPlace { .. } => {
                    stream
                        .commit()
                        .with_context(|| format!("cannot write {}", path.display()))?;
                    None
                }
                staged => Some((path, staged)),
            }
        }
        None => None,
    };
    match output.path {
        Some(path) if output.usd_layer => file.save_usd_layer(path)?,
        Some(path) => file.save(path)?,
        None => {
            let format = match &file.path {
                Some(p) => shenlong::format::Format::from_path(p)?,
                None => shenlong::format::Format::SceneJson,
            };
            write_stdout(&file.to_bytes(format)?)?;
        }
    }
    if let Some((path, prepared)) = commands {
        prepared
            .commit()
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    Ok(())
}

/// Writes bytes to stdout in one go.
pub fn write_stdout(bytes: &[u8]) -> Result<()> {
    let mut out = std::io::stdout().lock();
    out.write_all(bytes)
        .context("cannot write to standard output")?;
    out.flush().context("cannot write to standard output")?;
    Ok(())
}

/// Collision resolution, as every editing command offers it.
#[derive(clap::Args, Debug)]
pub struct CollisionArgs {
    /// Do not look for collisions at all.
    #[arg(long)]
    no_collide: bool,
    /// Apply the edit even when no free placement is found, and list the overlaps.
    #[arg(long)]
    allow_collisions: bool,
    /// Spacing of the search grid, in metres.
    #[arg(long, value_name = "M", default_value_t = 0.05)]
    step: f64,
    /// Horizontal clearance a moved object keeps from others, in metres.
    #[arg(long, value_name = "M", default_value_t = 0.02)]
    buffer: f64,
    /// Farthest an object is moved to clear a collision, in metres.
    #[arg(long, value_name = "M", default_value_t = 2.0)]
    search_radius: f64,
}

impl CollisionArgs {
    /// Whether collisions are skipped entirely.
    pub fn no_collide(&self) -> bool {
        self.no_collide
    }

    /// The resolver's options, checked; `None` with `--no-collide`.
    pub fn resolve_options(&self) -> Result<Option<shenlong::collide::ResolveOptions>> {
        if self.no_collide() {
            Ok(None)
        } else {
            self.options().map(Some)
        }
    }

    /// The resolver's options, checked.
    pub fn options(&self) -> Result<shenlong::collide::ResolveOptions> {
        for (name, value) in [
            ("--step", self.step),
            ("--buffer", self.buffer),
            ("--search-radius", self.search_radius),
        ] {
            if !value.is_finite() || value < 0.0 || (name == "--step" && value <= 0.0) {
                anyhow::bail!(
                    "{name} {value}: give a distance in metres{}",
                    if name == "--step" { " > 0" } else { " ≥ 0" }
                );
            }
        }
        if self.search_radius / self.step > 2000.0 {
            anyhow::bail!(
                "--search-radius / --step is {}: at most 2000 grid steps are searched",
                self.search_radius / self.step
            );
        }
        Ok(shenlong::collide::ResolveOptions {
            step: self.step,
            buffer: self.buffer,
            radius: self.search_radius,
            allow_collisions: self.allow_collisions,
            ..Default::default()
        })
    }

    /// The edit options these flags ask for.
    pub fn edit_options(&self, carry: bool) -> Result<shenlong::pipeline::EditOptions> {
        Ok(shenlong::pipeline::EditOptions::new(
            carry,
            self.resolve_options()?,
        ))
    }
}

/// The translator, as every command that translates instructions offers it.
#[derive(clap::Args, Debug)]
pub struct TranslatorArgs {
    /// The translator: offline, openai:MODEL, ollama:MODEL, replay:FILE, or a cascade
    /// offline+openai:MODEL (the model only for what the offline translator cannot read).
    #[arg(long, value_name = "BACKEND", default_value = "offline")]
    pub llm: shenlong::pipeline::backends::Spec,
    /// Attempts after the first when the model's reply cannot be used.
    #[arg(long, value_name = "N", default_value_t = 5)]
    pub retries: usize,
    /// Append every exchange with the model to FILE (JSON lines; replay with replay:FILE).
    #[arg(long, value_name = "FILE")]
    pub record: Option<std::path::PathBuf>,
    /// Where replies are cached (default: the user's cache folder, shenlong/replies).
    #[arg(long, value_name = "DIR")]
    pub cache_dir: Option<std::path::PathBuf>,
    /// Do not read or write the reply cache.
    #[arg(long)]
    pub no_cache: bool,
    /// The model server's base URL (overrides OPENAI_BASE_URL and the defaults).
    #[arg(long, value_name = "URL")]
    pub base_url: Option<String>,
    /// Seconds allowed for one request to the model, reply included.
    #[arg(long, value_name = "S", default_value_t = 120.0)]
    pub timeout: f64,
    /// Seconds allowed to connect to the model server.
    #[arg(long, value_name = "S", default_value_t = 10.0)]
    pub connect_timeout: f64,
    /// Seconds allowed for the whole translation of an instruction: every request, retry
    /// and wait (a server's Retry-After is honoured up to 30 s).
    #[arg(long, value_name = "S", default_value_t = 300.0)]
    pub deadline: f64,
}

impl TranslatorArgs {
    /// The translator settings for a prompt system, checked.
    pub fn settings(
        &self,
        system: shenlong::pipeline::System,
    ) -> Result<shenlong::pipeline::backends::TranslatorSettings> {
        for (flag, value) in [
            ("--timeout", self.timeout),
            ("--connect-timeout", self.connect_timeout),
            ("--deadline", self.deadline),
        ] {
            // A day at most: longer is a typo, and past ~1.8e19 s a duration overflows.
            if !(value.is_finite() && value > 0.0 && value <= 86_400.0) {
                anyhow::bail!("{flag} {value}: give a number of seconds > 0 and at most 86400");
            }
        }
        Ok(shenlong::pipeline::backends::TranslatorSettings {
            system,
            retries: self.retries,
            base_url: self.base_url.clone(),
            api_key: None,
            timeout: std::time::Duration::from_secs_f64(self.timeout),
            connect_timeout: std::time::Duration::from_secs_f64(self.connect_timeout),
            deadline: std::time::Duration::from_secs_f64(self.deadline),
            cache_dir: if self.no_cache {
                None
            } else {
                self.cache_dir
                    .clone()
                    .or_else(shenlong::llm::cache::Cache::default_dir)
            },
            record: self.record.clone(),
        })
    }
}

/// Says on stderr what an operation's notes say: collisions cleared, overlaps left,
/// objects held.
pub fn notes(notes: &[String]) {
    for note in notes {
        shenlong_cli::say!("note: {note}");
    }
}

/// An outcome's JSON to write with `--json FILE`: made ready before the scene is written
/// and committed after it, so a failed command changes no file; a stream (a pipe,
/// `/dev/full`) is written first, since it fails only when written.
pub struct JsonOut {
    path: String,
    prepared: Option<shenlong::io::Prepared>,
}

impl JsonOut {
    /// Readies `json` for `--json PATH` (`None` or `-`: nothing to ready).
    pub fn prepare(path: Option<&str>, json: &str) -> Result<Option<Self>> {
        let Some(path) = path.filter(|p| *p != "-") else {
            return Ok(None);
        };
        let prepared = shenlong::io::prepare(Path::new(path), format!("{json}\n").as_bytes())
            .with_context(|| format!("cannot write {path}"))?;
        let prepared = match prepared {
            stream @ shenlong::io::Prepared::InPlace { .. } => {
                stream
                    .commit()
                    .with_context(|| format!("cannot write {path}"))?;
                None
            }
            staged => Some(staged),
        };
        Ok(Some(Self {
            path: path.to_string(),
            prepared,
        }))
    }

    /// Writes it, once the scene is written.
    pub fn commit(self) -> Result<()> {
        match self.prepared {
            Some(prepared) => prepared
                .commit()
                .with_context(|| format!("cannot write {}", self.path)),
            None => Ok(()),
        }
    }
}

/// The tail every editing command shares once its operation answered: the outcome as
/// JSON for `--json` (a file made ready before the scene and written after it, or stderr
/// for `-`), the edited scene to `output` (with the ThreeDWorld commands of the change for
/// `tdw`), and without `--json` the notes on stderr.
pub fn finish(
    session: &shenlong::session::Session,
    outcome: &shenlong::session::Outcome,
    json: Option<&str>,
    output: Output<'_>,
    tdw: Option<&Path>,
) -> Result<()> {
    let text = serde_json::to_string_pretty(outcome)
        .map_err(|e| anyhow::anyhow!("cannot write the outcome: {e}"))?;
    let json_file = JsonOut::prepare(json, &text)?;
    // The scene as it was, for the ThreeDWorld commands only: no copy otherwise (and the
    // scene itself when nothing changed).
    let before = tdw.and_then(|_| session.before_last_change());
    let before = before
        .as_ref()
        .or(tdw.is_some().then_some(&session.file.scene));
    write_edit(&session.file, before, output, tdw)?;
    if let Some(json_file) = json_file {
        json_file.commit()?;
    }
    match json {
        Some("-") => eprintln!("{}", shenlong_cli::terminal::safe_json(&text)),
        Some(_) => {}
        None => notes(&outcome.notes),
    }
    Ok(())
}

/// A refused operation, said by the command line: with `--json -`, the refusal's JSON on
/// one line of stderr first, as the HTTP API and MCP answer it; then the error to print
/// ([`refusal`]).
pub fn refused(
    refusal_: shenlong::session::OpError,
    json: Option<&str>,
    offline: bool,
) -> anyhow::Error {
    if json == Some("-") {
        let line = serde_json::to_string(&refusal_).unwrap_or_default();
        eprintln!("{}", shenlong_cli::terminal::safe_json(&line));
    }
    refusal(refusal_, offline)
}

/// A translator that cannot be made, in the command line's terms: the flag that would
/// make it, chosen by the error's kind.
pub fn llm_error(error: shenlong::pipeline::backends::BackendError) -> anyhow::Error {
    use shenlong::pipeline::backends::BackendError;
    match error {
        BackendError::OfflineNeedsCga(system) => anyhow::anyhow!(
            "--llm: the offline translator answers in CGA only: use --system cga, or a model (openai:MODEL) for '{}'",
            system.name()
        ),
        BackendError::NoApiKey => anyhow::anyhow!(
            "--llm: the translator openai:MODEL needs OPENAI_API_KEY (or --base-url for a local OpenAI-compatible server)"
        ),
        other => anyhow::Error::new(other).context("--llm"),
    }
}

/// A refusal as the command line says it: the library's line, then, by the refusal's
/// kind, the flag that changes the outcome where there is one.
pub fn refusal(refusal: shenlong::session::OpError, offline: bool) -> anyhow::Error {
    use shenlong::session::ErrorKind;
    let hint = match refusal.kind {
        ErrorKind::NoFreePlace => Some("use --allow-collisions to apply the edit anyway"),
        ErrorKind::NotUnderstood if offline && refusal.unread => Some(
            "or use a language model with --llm (openai:MODEL, ollama:MODEL, or offline+openai:MODEL to ask one only for what the offline translator cannot read)",
        ),
        _ => None,
    };
    match hint {
        Some(hint) => anyhow::anyhow!("{}; {hint}", refusal.message),
        None => anyhow::Error::new(refusal),
    }
}

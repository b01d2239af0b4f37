//! `shenlong serve`: the interactive editor.

use anyhow::{Context, Result};
use shenlong::pipeline::backends::TranslatorSettings;
use shenlong::pipeline::System;
use shenlong_cli::server::{serve, App, ServeSettings};
use std::path::PathBuf;

/// Serve a scene in a 3D web editor: type instructions, see them happen, undo, export.
///
/// One scene is kept in memory (a file or example:NAME). The page and its scripts are in
/// the binary; nothing is loaded from elsewhere. The model's API key stays on the server.
#[derive(clap::Args)]
#[command(after_help = "Examples:
  shenlong serve examples/living_room.json
  shenlong serve example:workshop --addr 127.0.0.1:9000 --save edited.json
  shenlong serve room.glb --llm openai:gpt-4o

Then open the address in a browser. API: GET /api/scene, POST /api/edit
{\"instruction\"}, POST /api/undo, POST /api/redo, GET /api/history,
GET /api/export?format=json|glb|gltf|usda|tdw, POST /api/apply {\"object\", \"expr\"}.")]
pub struct Args {
    #[command(flatten)]
    read: super::ReadArgs,
    /// The scene (a file or example:NAME).
    scene: String,
    /// Address to listen on.
    #[arg(long, value_name = "ADDR", default_value = "127.0.0.1:8080")]
    addr: String,
    /// Write the scene to this file after every change (atomically).
    #[arg(long, value_name = "FILE")]
    save: Option<PathBuf>,
    /// Listen on an address other machines can reach. The API has no authentication:
    /// anyone who can reach the address can edit the scene and spend the model's key.
    #[arg(long)]
    allow_remote: bool,
    /// The default prompt system.
    #[arg(long, value_name = "SYSTEM", default_value = "cga")]
    system: System,
    #[command(flatten)]
    translator: super::TranslatorArgs,
    #[command(flatten)]
    collisions: super::CollisionArgs,
}

pub fn run(args: Args) -> Result<()> {
    let file = super::load_scene_with(&args.scene, &args.read)?;
    if let Some(save) = &args.save {
        check_save(&file, save)?;
    }
    let system = args.system;
    let settings = ServeSettings {
        llm: args.translator.llm.clone(),
        system,
        translator: args.translator.settings(system)?,
        collisions: args.collisions.resolve_options()?,
        save: args.save.clone(),
    };
    // Fail on a bad default backend now rather than at the first edit.
    shenlong::pipeline::backends::translator(
        &settings.llm,
        &TranslatorSettings {
            system: settings.system,
            ..settings.translator.clone()
        },
    )
    .map_err(super::llm_error)?;
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
        .context("cannot start the server's runtime")?;
    runtime.block_on(async {
        let listener = tokio::net::TcpListener::bind(&args.addr)
            .await
            .with_context(|| format!("cannot listen on {}", args.addr))?;
        let address = listener.local_addr()?;
        if !address.ip().is_loopback() {
            if !args.allow_remote {
                anyhow::bail!(
                    "{address} can be reached from other machines and the API has no authentication; listen on 127.0.0.1, or pass --allow-remote"
                );
            }
            shenlong_cli::say!(
                "shenlong: warning: listening on {address}: anyone who can reach it can edit the scene{}",
                if settings.llm == shenlong::pipeline::backends::Spec::Offline { "" } else { " and use the model's key" }
            );
        }
        shenlong_cli::say!(
            "shenlong: editing '{}' at http://{address}/ (Ctrl-C to stop)",
            file.scene.name
        );
        let settings = settings;
        serve(App::new(file, settings), listener)
            .await
            .context("the server stopped")
    })
}

/// Checks at start-up that `--save` can be written in the scene's format, so that no edit
/// is applied in memory and then fails to save.
pub(super) fn check_save(file: &shenlong::format::SceneFile, save: &std::path::Path) -> Result<()> {
    let format = shenlong::format::Format::from_path(save)
        .map_err(|e| anyhow::anyhow!("--save {}: {e}", save.display()))?;
    file.to_bytes(format)
        .map_err(|e| anyhow::anyhow!("--save {}: {e}", save.display()))?;
    let dir = save
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(std::path::Path::new("."));
    let probe = dir.join(format!(".shenlong-save-check-{}", std::process::id()));
    std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&probe)
        .with_context(|| {
            format!(
                "--save {}: cannot write in {}",
                save.display(),
                dir.display()
            )
        })?;
    let _ = std::fs::remove_file(&probe);
    Ok(())
}

//! `shenlong mcp`: the scene as a Model Context Protocol server for AI assistants.

use anyhow::{Context, Result};
use shenlong::pipeline::System;
use shenlong_cli::mcp::{serve_stdio, McpSettings};
use std::path::PathBuf;

/// Serve a scene to an AI assistant over the Model Context Protocol (stdio).
///
/// Tools: list_objects, edit {instruction}, apply {object, expression, bind}, undo, redo,
/// history, render {before}, save, export {format}; the scene is the resource
/// scene://current. The assistant never chooses a file: `save` writes the --save file.
/// Logs go to stderr; stdout carries the protocol.
#[derive(clap::Args)]
#[command(after_help = "Examples:
  shenlong mcp examples/living_room.json --save edited.json
  shenlong mcp room.glb --save room-edited.glb --llm openai:gpt-4o

Claude Desktop (claude_desktop_config.json):
  {\"mcpServers\": {\"shenlong\": {\"command\": \"shenlong\",
    \"args\": [\"mcp\", \"/path/to/scene.json\", \"--save\", \"/path/to/edited.json\"]}}}

See docs/mcp.md.")]
pub struct Args {
    #[command(flatten)]
    read: super::ReadArgs,
    /// The scene (a file or example:NAME).
    scene: String,
    /// The file the `save` tool writes (atomically); checked at start-up.
    #[arg(long, value_name = "FILE")]
    save: Option<PathBuf>,
    /// The prompt system for a model translator.
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
        super::serve::check_save(&file, save)?;
    }
    let system = args.system;
    let settings = McpSettings {
        // Made once, here: a bad backend fails now rather than at the first edit.
        translator: shenlong::pipeline::backends::translator(
            &args.translator.llm,
            &args.translator.settings(system)?,
        )
        .map_err(super::llm_error)?,
        collisions: args.collisions.resolve_options()?,
        save: args.save.clone(),
    };
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .context("cannot start the MCP server's runtime")?;
    shenlong_cli::say!("shenlong: serving '{}' over MCP on stdio", file.scene.name);
    runtime.block_on(serve_stdio(file, settings))
}

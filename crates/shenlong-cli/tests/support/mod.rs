//! Helpers shared by the CLI's integration tests: running the binary as a user does, and
//! reading what it wrote.

#![allow(dead_code)]

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs `shenlong` with `args`, without the caller's OpenAI settings.
pub fn shenlong(args: &[&str]) -> Output {
    shenlong_with_env(args, &[])
}

/// Runs `shenlong` with `args` and only the given OpenAI settings (`env`).
pub fn shenlong_with_env(args: &[&str], env: &[(&str, &str)]) -> Output {
    let mut command = Command::new(env!("CARGO_BIN_EXE_shenlong"));
    command
        .args(args)
        .env_remove("OPENAI_API_KEY")
        .env_remove("OPENAI_BASE_URL");
    for (k, v) in env {
        command.env(k, v);
    }
    command.output().expect("the binary runs")
}

/// What the run printed on stdout.
pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// What the run printed on stderr.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The repository's `examples/` folder.
pub fn examples_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// A JSON file the run wrote.
pub fn read_json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The object called `name` in a scene's JSON.
#[track_caller]
pub fn object<'a>(scene: &'a Value, name: &str) -> &'a Value {
    scene["objects"]
        .as_array()
        .expect("the scene has objects")
        .iter()
        .find(|o| o["name"] == name)
        .unwrap_or_else(|| panic!("no object '{name}'"))
}

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

/// A glTF chain of `depth` nodes, `n0` → `n1` → …, each the only child of the one before
/// and 1 mm above it; the last one has a triangle mesh. Generated, never committed: at
/// 100,000 nodes it is 7 MB.
pub fn deep_chain_gltf(depth: usize) -> String {
    // Three vertices, (0, 0, 0), (1, 0, 0), (0, 0, 1), as little-endian f32 in base64.
    let data = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAAAAAAIA/";
    let mut nodes = String::with_capacity(depth * 64);
    for i in 0..depth {
        if i > 0 {
            nodes.push(',');
        }
        nodes.push_str(&format!(
            r#"{{"name": "n{i}", "translation": [0, 0.001, 0]"#
        ));
        if i + 1 < depth {
            nodes.push_str(&format!(r#", "children": [{}]"#, i + 1));
        } else {
            nodes.push_str(r#", "mesh": 0"#);
        }
        nodes.push('}');
    }
    format!(
        r#"{{"asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": [0]}}],
        "nodes": [{nodes}],
        "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}}}]}}],
        "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
            "min": [0, 0, 0], "max": [1, 0, 1]}}],
        "bufferViews": [{{"buffer": 0, "byteLength": 36}}],
        "buffers": [{{"byteLength": 36, "uri": "data:application/octet-stream;base64,{data}"}}]}}"#
    )
}

/// A scene-JSON file whose one object has `depth` levels of brackets in an unknown field
/// (the whole file nests `depth + 3` levels).
pub fn nested_scene_json(depth: usize) -> String {
    format!(
        "{{\"objects\": [\n  {{\"name\": \"box\", \"size\": [1, 1, 1], \"position\": [0, 0, 0], \"junk\": {}{}}}]}}\n",
        "[".repeat(depth),
        "]".repeat(depth)
    )
}

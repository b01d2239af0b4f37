//! `shenlong mcp` spoken to over stdio, as an MCP client would: newline-delimited JSON-RPC.

use serde_json::{json, Value};
use std::io::{BufRead, BufReader, Write};
use std::process::{Child, ChildStdin, ChildStdout, Command, Stdio};

struct Client {
    child: Child,
    stdin: ChildStdin,
    stdout: BufReader<ChildStdout>,
    next_id: u64,
    notifications: Vec<Value>,
}

impl Client {
    fn start(args: &[&str]) -> Self {
        let mut child = Command::new(env!("CARGO_BIN_EXE_shenlong"))
            .arg("mcp")
            .args(args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("the binary starts");
        let stdin = child.stdin.take().unwrap();
        let stdout = BufReader::new(child.stdout.take().unwrap());
        let mut client = Self {
            child,
            stdin,
            stdout,
            next_id: 1,
            notifications: Vec::new(),
        };
        let init = client.request(
            "initialize",
            json!({
                "protocolVersion": "2025-06-18",
                "capabilities": {},
                "clientInfo": {"name": "shenlong-tests", "version": "1"}
            }),
        );
        assert!(
            init["result"]["capabilities"]["tools"].is_object(),
            "{init}"
        );
        client.send(&json!({"jsonrpc": "2.0", "method": "notifications/initialized"}));
        client
    }

    fn send(&mut self, message: &Value) {
        writeln!(self.stdin, "{message}").unwrap();
        self.stdin.flush().unwrap();
    }

    /// Sends a request and returns its response, keeping notifications that come first.
    fn request(&mut self, method: &str, params: Value) -> Value {
        let id = self.next_id;
        self.next_id += 1;
        self.send(&json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        loop {
            let mut line = String::new();
            let n = self.stdout.read_line(&mut line).unwrap();
            assert!(n > 0, "the server closed stdout while {method} was pending");
            let message: Value = serde_json::from_str(&line).expect("one JSON message a line");
            if message.get("id") == Some(&json!(id)) {
                return message;
            }
            self.notifications.push(message);
        }
    }

    fn call(&mut self, tool: &str, arguments: Value) -> Value {
        let response = self.request("tools/call", json!({"name": tool, "arguments": arguments}));
        response["result"].clone()
    }

    fn finish(mut self) {
        drop(self.stdin);
        let status = self.child.wait().unwrap();
        assert!(
            status.success(),
            "the server exits cleanly when stdin closes"
        );
    }
}

impl Client {
    /// One object of `list_objects`, by name.
    fn object(&mut self, name: &str) -> Value {
        let listing = self.call("list_objects", json!({}));
        listing["structuredContent"]["objects"]
            .as_array()
            .unwrap()
            .iter()
            .find(|o| o["name"] == name)
            .unwrap_or_else(|| panic!("no {name} in {listing}"))
            .clone()
    }
}

fn text(result: &Value) -> String {
    result["content"][0]["text"]
        .as_str()
        .unwrap_or("")
        .to_string()
}

#[test]
fn an_assistant_edits_a_scene_over_mcp() {
    let dir = tempfile::tempdir().unwrap();
    let save = dir.path().join("edited.json");
    let save_arg = save.to_str().unwrap();
    let mut c = Client::start(&["example:workshop", "--save", save_arg]);

    let tools = c.request("tools/list", json!({}));
    let names: Vec<&str> = tools["result"]["tools"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| t["name"].as_str().unwrap())
        .collect();
    for tool in [
        "list_objects",
        "edit",
        "apply",
        "undo",
        "redo",
        "history",
        "render",
        "save",
        "export",
    ] {
        assert!(names.contains(&tool), "{tool} missing from {names:?}");
    }
    let list_tool = tools["result"]["tools"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["name"] == "list_objects")
        .unwrap();
    assert!(list_tool["outputSchema"]["properties"]["objects"].is_object());

    assert_eq!(c.object("vise")["rests_on"], "workbench");
    let table = c.object("tool table");
    let table_top = table["world_box"]["max"][1].as_f64().unwrap();

    // Subscribe to the scene, then edit by instruction.
    let subscribed = c.request("resources/subscribe", json!({"uri": "scene://current"}));
    assert!(subscribed.get("error").is_none(), "{subscribed}");
    let edited = c.call(
        "edit",
        json!({"instruction": "put the 'orange bottle' on top of the 'tool table'"}),
    );
    assert_ne!(edited["isError"], true, "{edited}");
    // A compact outcome: what moved, and the instruction as understood; no report.
    let outcome = &edited["structuredContent"];
    assert_eq!(outcome["moved"][0]["object"], "orange bottle", "{edited}");
    assert_eq!(outcome["moved"][0]["how"], "moved");
    assert_eq!(outcome["understood"]["query"], "put X1 on top of X2");
    assert_eq!(outcome["understood"]["bindings"][1]["object"], "tool table");
    assert!(outcome.get("report").is_none(), "{edited}");
    assert!(
        edited.to_string().len() < 2_000,
        "{} bytes",
        edited.to_string().len()
    );
    assert!(c
        .notifications
        .iter()
        .any(|n| n["method"] == "notifications/resources/updated"
            && n["params"]["uri"] == "scene://current"));
    let bottle = c.object("orange bottle");
    assert_eq!(bottle["rests_on"], "tool table");
    let bottom = bottle["world_box"]["min"][1].as_f64().unwrap();
    assert!(
        (bottom - table_top).abs() < 1e-9,
        "on top: {bottom} vs {table_top}"
    );

    // Refusals are tool errors with one line; the scene is unchanged.
    let unknown = c.call("edit", json!({"instruction": "move the piano to the left"}));
    assert_eq!(unknown["isError"], true);
    assert!(text(&unknown).contains("piano"), "{unknown}");
    assert_eq!(
        unknown["structuredContent"]["kind"], "not_understood",
        "{unknown}"
    );
    // An ambiguous phrase: its choices as data, each an instruction ready to send.
    let ambiguous = c.call("edit", json!({"instruction": "move the can 10 cm left"}));
    assert_eq!(ambiguous["isError"], true);
    let choices = &ambiguous["structuredContent"]["ambiguity"]["choices"];
    assert_eq!(
        ambiguous["structuredContent"]["kind"], "ambiguous",
        "{ambiguous}"
    );
    assert_eq!(choices.as_array().map(Vec::len), Some(2), "{ambiguous}");
    let chosen = c.call("edit", json!({"instruction": choices[1]["instruction"]}));
    assert_ne!(chosen["isError"], true, "{chosen}");
    assert_eq!(
        chosen["structuredContent"]["moved"][0]["object"],
        choices[1]["object"]
    );
    assert_ne!(c.call("undo", json!({}))["isError"], true);
    let hostile = c.call(
        "apply",
        json!({"object": "tool table", "expression": "std::fs::read(\"/etc/passwd\")"}),
    );
    assert_eq!(hostile["isError"], true, "{hostile}");
    let bad_bind = c.call(
        "apply",
        json!({"object": "tool table", "expression": "T(e1)", "bind": {"X3": "workbench"}}),
    );
    assert_eq!(bad_bind["isError"], true, "{bad_bind}");

    // Apply an expression with a bound object: the table onto nothing, just 1 m right.
    let applied = c.call(
        "apply",
        json!({"object": "tool table", "expression": "T(1*e1)"}),
    );
    assert_ne!(applied["isError"], true, "{applied}");
    let table = c.object("tool table");
    assert!(
        (table["position"][0].as_f64().unwrap() - 1.0).abs() < 1e-9,
        "{table}"
    );
    assert!((table["world_box"]["max"][1].as_f64().unwrap() - table_top).abs() < 1e-9);

    // Undo the apply, then redo and undo it again; the history says so.
    let undone = c.call("undo", json!({}));
    assert_ne!(undone["isError"], true, "{undone}");
    assert_eq!(c.object("tool table")["position"][0], 0.0);
    assert_ne!(c.call("redo", json!({}))["isError"], true);
    assert_ne!(c.call("undo", json!({}))["isError"], true);
    let history = c.call("history", json!({}));
    let items = history["structuredContent"]["history"].as_array().unwrap();
    assert_eq!(items.len(), 2, "{history}");
    assert_eq!(items[1]["undone"], true);
    let nothing = c.call("redo", json!({}));
    assert_ne!(nothing["isError"], true, "one redo is left");
    assert_eq!(c.call("redo", json!({}))["isError"], true, "then nothing");

    // The plan as a PNG, with what moved highlighted.
    let render = c.call("render", json!({"before": true}));
    assert_eq!(render["content"][0]["type"], "image");
    assert_eq!(render["content"][0]["mimeType"], "image/png");
    use base64::Engine as _;
    let png = base64::engine::general_purpose::STANDARD
        .decode(render["content"][0]["data"].as_str().unwrap())
        .unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");

    // Save writes the --save file; export returns the scene as content.
    assert!(!save.exists(), "nothing is written until save is called");
    let saved = c.call("save", json!({}));
    assert_ne!(saved["isError"], true, "{saved}");
    let written: Value = serde_json::from_str(&std::fs::read_to_string(&save).unwrap()).unwrap();
    assert!(written["objects"].as_array().unwrap().len() > 5);
    let export = c.call("export", json!({"format": "tdw"}));
    assert_eq!(export["content"][0]["type"], "resource");
    let exported: Value =
        serde_json::from_str(export["content"][0]["resource"]["text"].as_str().unwrap()).unwrap();
    assert!(exported.as_array().unwrap().len() > 5);
    let glb = c.call("export", json!({"format": "glb"}));
    assert_ne!(
        glb["isError"], true,
        "a JSON scene exports as a new glTF of boxes: {glb}"
    );

    // The scene as a resource.
    let read = c.request("resources/read", json!({"uri": "scene://current"}));
    let scene: Value =
        serde_json::from_str(read["result"]["contents"][0]["text"].as_str().unwrap()).unwrap();
    assert_eq!(scene["name"], "workshop");
    let other = c.request("resources/read", json!({"uri": "file:///etc/passwd"}));
    assert!(other.get("error").is_some(), "{other}");

    // Inputs are checked against the tools' schemas, and a bad one does not stop the server.
    let bad = c.request(
        "tools/call",
        json!({"name": "edit", "arguments": {"instruction": 42}}),
    );
    assert!(
        bad.get("error").is_some() || bad["result"]["isError"] == true,
        "{bad}"
    );
    let extra = c.request(
        "tools/call",
        json!({"name": "save", "arguments": {"path": "/tmp/elsewhere.json"}}),
    );
    assert!(!std::path::Path::new("/tmp/elsewhere.json").exists());
    let _ = extra;
    assert_ne!(c.call("list_objects", json!({}))["isError"], true);
    c.finish();
}

#[test]
fn save_without_a_save_file_is_a_tool_error() {
    let mut c = Client::start(&["example:office"]);
    let saved = c.call("save", json!({}));
    assert_eq!(saved["isError"], true);
    assert!(text(&saved).contains("--save"), "{saved}");
    c.finish();
}

#[test]
fn errors_never_echo_huge_arguments() {
    let mut c = Client::start(&["example:office"]);
    // A 2 MB object name: refused before anything quotes it.
    let huge = "x".repeat(2_000_000);
    let applied = c.call("apply", json!({"object": huge, "expression": "T(e1)"}));
    assert_eq!(applied["isError"], true);
    let message = text(&applied);
    assert!(message.len() < 3_000, "{} bytes", message.len());
    assert!(message.contains("longer than"), "{message}");
    // A long instruction that names nothing: the error is cut.
    let words = "banana ".repeat(280);
    let edited = c.call("edit", json!({"instruction": words}));
    assert_eq!(edited["isError"], true);
    assert!(
        text(&edited).chars().count() <= 2_100,
        "{}",
        text(&edited).len()
    );
    // A 10 MB export format: the answer quotes 40 characters of it.
    let format = "y".repeat(10_000_000);
    let exported = c.request(
        "tools/call",
        json!({"name": "export", "arguments": {"format": format}}),
    );
    let answer = exported.to_string();
    assert!(answer.len() < 3_000, "{} bytes", answer.len());
    assert!(answer.contains("unknown format"), "{answer}");
    c.finish();
}

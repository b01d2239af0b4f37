//! The `shenlong` binary, run as a user runs it.

mod support;

use std::process::Output;
use support::{examples_dir, object, read_json, shenlong, stderr, stdout};

#[track_caller]
fn assert_fails_cleanly(o: &Output, message: &str) {
    assert!(!o.status.success(), "expected failure");
    assert!(
        o.stdout.is_empty(),
        "nothing on stdout on error: {}",
        stdout(o)
    );
    let err = stderr(o);
    assert_eq!(err.lines().count(), 1, "one line on stderr: {err}");
    assert!(err.contains(message), "{err}");
}

#[test]
fn eval_json_is_one_object_of_the_documented_shape() {
    let o = shenlong(&["eval", "T(2 * e1) * R(pi/2, e3, e1)", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["versor"].as_array().unwrap().len(), 32);
    let t: Vec<f64> = serde_json::from_value(v["translation"].clone()).unwrap();
    assert!(
        (t[0] - 2.0).abs() < 1e-12 && t[1].abs() < 1e-12 && t[2].abs() < 1e-12,
        "{t:?}"
    );
    let q: Vec<f64> = serde_json::from_value(v["rotation"].clone()).unwrap();
    assert!(
        (q[1] - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-12,
        "{q:?}"
    );
    assert_eq!(v["scale"], 1.0);
}

#[test]
fn eval_with_a_scene_binds_variables() {
    let scene = examples_dir().join("workshop.json");
    let o = shenlong(&[
        "eval",
        "T(((X2.max | e2) - (X1.min | e2)) * e2)",
        "--scene",
        scene.to_str().unwrap(),
        "--bind",
        "X1=orange bottle",
        "--bind",
        "X2=Tool Table",
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["translation"], serde_json::json!([0.0, 0.9, 0.0]));
}

#[test]
fn eval_errors_are_one_line_and_say_where() {
    assert_fails_cleanly(
        &shenlong(&["eval", "T(e1 * 2"]),
        "expected ')' but found the end of the expression at column 9",
    );
    assert_fails_cleanly(
        &shenlong(&["eval", "X1.max"]),
        "unknown name 'X1' (bound: none)",
    );
    assert_fails_cleanly(
        &shenlong(&["eval", "e1 + e2"]),
        "result is a vector, not a transformation",
    );
    assert_fails_cleanly(
        &shenlong(&["eval", "T(X1.max)", "--bind", "X1=sofa"]),
        "--bind needs --scene",
    );
    assert_fails_cleanly(
        &shenlong(&[
            "eval",
            "T(X1.max)",
            "--scene",
            "example:workshop",
            "--bind",
            "X1=tool tabel",
        ]),
        "unknown object 'tool tabel' — did you mean 'tool table'",
    );
    let o = shenlong(&["eval", "e1 + e2", "--raw"]);
    assert_eq!(stdout(&o).trim(), "1 e1 + 1 e2");
}

#[test]
fn apply_writes_the_edit_and_carries_resting_objects() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("moved.json");
    let scene = examples_dir().join("workshop.json");
    let o = shenlong(&[
        "apply",
        scene.to_str().unwrap(),
        "--object",
        "tool table",
        "--expr",
        "T(0.5 * e1)",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v = read_json(&out);
    let find = |name: &str| object(&v, name);
    assert_eq!(
        find("tool table")["position"],
        serde_json::json!([0.5, 0, 0])
    );
    // The hammer rests on the table and travels with it.
    assert_eq!(
        find("hammer")["position"],
        serde_json::json!([0.1, 0.9, 0.1])
    );
    // The bottle on the floor stays.
    assert_eq!(
        find("orange bottle")["position"],
        serde_json::json!([-2, 0, 1.2])
    );
}

#[test]
fn failed_apply_leaves_the_output_untouched() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    std::fs::write(&out, "precious").unwrap();
    for expr in ["T(e1", "D(-1)", "T(X2.max)"] {
        let o = shenlong(&[
            "apply",
            "example:workshop",
            "--object",
            "tool table",
            "--expr",
            expr,
            "-o",
            out.to_str().unwrap(),
        ]);
        assert!(!o.status.success(), "{expr}");
        assert_eq!(stderr(&o).lines().count(), 1);
    }
    let o = shenlong(&[
        "apply",
        "example:workshop",
        "--object",
        "sofa",
        "--expr",
        "T(e1)",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_fails_cleanly(&o, "unknown object 'sofa'");
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "precious");
    let entries: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(entries.len(), 1, "no temporary files left behind");
}

#[test]
fn bad_scene_files_fail_with_the_field_named() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.json");
    std::fs::write(
        &bad,
        r#"{"objects": [{"name": "a", "size": [1, 0, 1], "position": [0, 0, 0]}]}"#,
    )
    .unwrap();
    let o = shenlong(&[
        "convert",
        bad.to_str().unwrap(),
        dir.path().join("out.json").to_str().unwrap(),
    ]);
    assert_fails_cleanly(&o, "bad.json: objects[0].size[1] must be > 0");
    assert!(!dir.path().join("out.json").exists());
    let o = shenlong(&[
        "convert",
        "example:kitchen",
        dir.path().join("k.obj").to_str().unwrap(),
    ]);
    assert_fails_cleanly(&o, "unknown scene format '.obj'");
    // A file that is not there: said once, with the system's reason once.
    let missing = dir.path().join("missing.json");
    let o = shenlong(&["edit", missing.to_str().unwrap(), "move X1 left"]);
    assert_fails_cleanly(&o, "cannot read");
    let err = stderr(&o);
    assert_eq!(err.matches("cannot read").count(), 1, "{err}");
    assert_eq!(err.matches("missing.json").count(), 1, "{err}");
    assert_eq!(err.matches("No such file").count(), 1, "{err}");
}

#[test]
fn examples_list_and_write() {
    let o = shenlong(&["examples"]);
    assert!(o.status.success());
    assert!(stdout(&o).lines().count() >= 10);
    let o = shenlong(&["examples", "workshop"]);
    let expected = std::fs::read_to_string(examples_dir().join("workshop.json")).unwrap();
    assert_eq!(stdout(&o), expected);
    assert_fails_cleanly(
        &shenlong(&["examples", "moon base"]),
        "unknown example 'moon base'",
    );
}

#[test]
fn help_explains_each_command() {
    for command in ["eval", "apply", "convert", "examples"] {
        let o = shenlong(&[command, "--help"]);
        assert!(o.status.success());
        assert!(
            stdout(&o).contains("Example"),
            "{command} --help shows an example"
        );
    }
}

#[test]
fn apply_exports_the_edit_as_tdw_commands() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("moved.json");
    let tdw = dir.path().join("edit.tdw.json");
    let o = shenlong(&[
        "apply",
        "example:workshop",
        "--object",
        "tool table",
        "--expr",
        "T(0.5 * e1 + e3)",
        "-o",
        out.to_str().unwrap(),
        "--tdw",
        tdw.to_str().unwrap(),
        "--no-collide",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let commands: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&tdw).unwrap()).unwrap();
    let commands = commands.as_array().unwrap();
    // The table (id 1) and the three tools resting on it move; z is mirrored for Unity.
    assert_eq!(commands.len(), 4, "{commands:?}");
    assert_eq!(
        commands[0],
        serde_json::json!({"$type": "teleport_object", "id": 1, "position": {"x": 0.5, "y": 0.0, "z": -1.0}})
    );
    assert!(commands.iter().all(|c| c["$type"] == "teleport_object"));
}

#[test]
fn render_draws_svg_and_png() {
    let dir = tempfile::tempdir().unwrap();
    let edited = dir.path().join("edited.json");
    let o = shenlong(&[
        "apply",
        "example:office",
        "--object",
        "meeting table",
        "--expr",
        "T(-0.5 * e1)",
        "-o",
        edited.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = dir.path().join("edit.svg");
    let o = shenlong(&[
        "render",
        edited.to_str().unwrap(),
        "--before",
        "example:office",
        "-o",
        svg.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg") && text.contains(">meeting table</text>"));
    assert_eq!(
        text.matches("marker-end").count(),
        3,
        "the table, the notebook and the cup moved"
    );
    let png = dir.path().join("plan.png");
    let o = shenlong(&["render", "example:office", "-o", png.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
    assert_fails_cleanly(
        &shenlong(&["render", "example:office", "-o", "plan.gif"]),
        "must be .svg or .png",
    );
    assert_fails_cleanly(
        &shenlong(&[
            "render",
            "example:office",
            "--before",
            "example:kitchen",
            "-o",
            svg.to_str().unwrap(),
        ]),
        "--before must be the same scene",
    );
}

#[test]
fn apply_resolves_collisions_unless_told_not_to() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    // The stool (0.4 wide, at z = 1.0) pushed 1 m back lands inside the tool table.
    let out_text = out.to_str().unwrap().to_string();
    let args = |extra: &[&'static str]| -> Vec<String> {
        let mut a: Vec<String> = [
            "apply",
            "example:workshop",
            "--object",
            "stool",
            "--expr",
            "T(-1 * e3)",
            "-o",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        a.push(out_text.clone());
        a.extend(extra.iter().map(|s| s.to_string()));
        a
    };
    let shenlong = |a: Vec<String>| shenlong(&a.iter().map(String::as_str).collect::<Vec<_>>());
    let o = shenlong(args(&[]));
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("note: moved 'stool' by"),
        "{}",
        stderr(&o)
    );
    assert!(
        stderr(&o).contains("to clear 'tool table'"),
        "{}",
        stderr(&o)
    );
    let v = read_json(&out);
    let stool = object(&v, "stool");
    let z = stool["position"][2].as_f64().unwrap();
    // Backed out the way it came, clear of the table (z ≤ 0.4) by the 2 cm buffer, on the
    // 5 cm grid: 0.65.
    assert!((z - 0.65).abs() < 1e-9, "just in front of the table: {z}");
    let o = shenlong(args(&["--no-collide"]));
    assert!(o.status.success());
    let v = read_json(&out);
    let stool = object(&v, "stool");
    assert_eq!(stool["position"], serde_json::json!([0, 0, 0]));
    assert_fails_cleanly(
        &shenlong(args(&["--step", "0"])),
        "--step 0: give a distance in metres > 0",
    );
}

#[test]
fn serve_refuses_an_address_others_can_reach_and_a_save_it_cannot_write() {
    let o = shenlong(&["serve", "example:workshop", "--addr", "0.0.0.0:0"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("--allow-remote"), "{}", stderr(&o));
    // A .usdc save (Shenlong writes USD as .usda) would fail at every edit: refused at
    // start.
    let dir = tempfile::tempdir().unwrap();
    let save = dir.path().join("out.usdc");
    let o = shenlong(&[
        "serve",
        "example:workshop",
        "--save",
        save.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("--save"), "{}", stderr(&o));
    assert!(!save.exists());
}

#[test]
fn an_edit_beyond_the_exact_range_is_refused_not_panicked_on() {
    for expr in ["T(1e8*e1)", "D(1e300)", "T(1e300*e2)"] {
        let o = shenlong(&[
            "apply",
            "example:workshop",
            "--object",
            "hammer",
            "--expr",
            expr,
        ]);
        assert_eq!(o.status.code(), Some(1), "{expr}: {}", stderr(&o));
        assert_eq!(stderr(&o).lines().count(), 1, "{expr}: {}", stderr(&o));
    }
}

#[test]
fn edits_of_deep_gltf_hierarchies_do_not_crash() {
    let dir = tempfile::tempdir().unwrap();
    for depth in [8_000, 100_000] {
        let input = dir.path().join(format!("chain{depth}.gltf"));
        std::fs::write(&input, support::deep_chain_gltf(depth)).unwrap();
        // The chain of empty nodes over one mesh is one object, named by its top node.
        let leaf = "n0".to_string();
        let edited = dir.path().join(format!("edited{depth}.gltf"));
        let applied = dir.path().join(format!("applied{depth}.gltf"));
        let instruction = format!("move the '{leaf}' 1 m to the right");
        for (args, output) in [
            (
                vec![
                    "edit",
                    input.to_str().unwrap(),
                    &instruction,
                    "-o",
                    edited.to_str().unwrap(),
                ],
                &edited,
            ),
            (
                vec![
                    "apply",
                    input.to_str().unwrap(),
                    "--object",
                    &leaf,
                    "--expr",
                    "T(e1)",
                    "-o",
                    applied.to_str().unwrap(),
                ],
                &applied,
            ),
        ] {
            let o = shenlong(&args);
            // Not killed by a signal (a stack overflow aborts), and done.
            assert!(
                o.status.code().is_some(),
                "{depth} {}: {:?}",
                args[0],
                o.status
            );
            assert!(o.status.success(), "{depth} {}: {}", args[0], stderr(&o));
            let reread = shenlong::format::SceneFile::load(output).unwrap();
            let min = reread.scene.objects[0].world_aabb().min;
            let y = 0.001 * depth as f64;
            assert!(
                (min - glam::DVec3::new(1.0, y, 0.0)).length() < 1e-6,
                "{depth} {}: {min:?}",
                args[0]
            );
        }
    }
}

#[test]
fn a_scene_nested_too_deep_is_refused_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("deep.json");
    std::fs::write(&input, support::nested_scene_json(200)).unwrap();
    let output = dir.path().join("out.json");
    let o = shenlong(&["convert", input.to_str().unwrap(), output.to_str().unwrap()]);
    assert_fails_cleanly(
        &o,
        "deep.json: nesting deeper than 100 levels at line 2, column 166",
    );
    assert!(!output.exists());
}

#[test]
fn a_gltf_cannot_choose_where_its_resources_are_written() {
    let root = tempfile::tempdir().unwrap();
    let download = root.path().join("download");
    let home = root.path().join("home");
    std::fs::create_dir_all(download.join(".ssh")).unwrap();
    std::fs::create_dir_all(download.join(".config/autostart")).unwrap();
    std::fs::create_dir_all(&home).unwrap();
    // The triangle's positions as `.bash_profile`, a key as a second buffer, a desktop
    // entry as an image.
    let triangle = base64::Engine::decode(
        &base64::engine::general_purpose::STANDARD,
        "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAAAAAAIA/",
    )
    .unwrap();
    std::fs::write(download.join(".bash_profile"), &triangle).unwrap();
    std::fs::write(download.join(".ssh/authorized_keys"), [b'k'; 36]).unwrap();
    std::fs::write(
        download.join(".config/autostart/evil.desktop"),
        "[Desktop Entry]\nExec=evil\n",
    )
    .unwrap();
    let scene = support::deep_chain_gltf(1)
        .replace(
            r#""buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAAAAAAIA/"}]"#,
            r#""buffers": [{"byteLength": 36, "uri": ".bash_profile"}, {"byteLength": 36, "uri": ".ssh/authorized_keys"}],
            "images": [{"uri": ".config/autostart/evil.desktop"}]"#,
        );
    assert!(scene.contains(".bash_profile"));
    let input = download.join("scene.gltf");
    std::fs::write(&input, scene).unwrap();
    let output = home.join("edited.gltf");
    for command in [
        vec!["convert", input.to_str().unwrap(), output.to_str().unwrap()],
        vec![
            "apply",
            input.to_str().unwrap(),
            "--object",
            "n0",
            "--expr",
            "T(e1)",
            "-o",
            output.to_str().unwrap(),
        ],
    ] {
        let o = shenlong(&command);
        assert!(o.status.success(), "{}: {}", command[0], stderr(&o));
        let mut written: Vec<String> = std::fs::read_dir(&home)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        written.sort();
        assert_eq!(
            written,
            [
                "edited.gltf",
                "edited_0.bin",
                "edited_1.bin",
                "edited_2.bin"
            ],
            "{}",
            command[0]
        );
        let reread = shenlong::format::SceneFile::load(&output).unwrap();
        assert_eq!(reread.scene.objects.len(), 1);
    }
    let mut beside: Vec<String> = std::fs::read_dir(root.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    beside.sort();
    assert_eq!(
        beside,
        ["download", "home"],
        "nothing outside the output folder"
    );
}

/// The built-in workshop written as `workshop.json` in `dir`.
fn workshop_scene(dir: &std::path::Path) -> std::path::PathBuf {
    let scene = dir.join("workshop.json");
    let o = shenlong(&["examples", "workshop", "-o", scene.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    scene
}

#[test]
fn a_report_that_cannot_be_written_leaves_the_scene_output_unwritten() {
    let dir = tempfile::tempdir().unwrap();
    let scene = workshop_scene(dir.path());
    let out = dir.path().join("edited.json");
    let report = dir.path().join("no such folder").join("report.json");
    let o = shenlong(&[
        "edit",
        scene.to_str().unwrap(),
        "move the 'hammer' 10 cm left",
        "-o",
        out.to_str().unwrap(),
        "--json",
        report.to_str().unwrap(),
    ]);
    assert_fails_cleanly(&o, "report.json");
    assert!(
        !out.exists(),
        "the scene was written though the report could not be"
    );
}

#[cfg(unix)]
#[test]
fn a_report_linked_to_a_stream_is_written_through_the_link() {
    let dir = tempfile::tempdir().unwrap();
    let scene = workshop_scene(dir.path());
    let link = dir.path().join("report.json");
    std::os::unix::fs::symlink("/dev/null", &link).unwrap();
    let out = dir.path().join("edited.json");
    let o = shenlong(&[
        "edit",
        scene.to_str().unwrap(),
        "move the 'hammer' 10 cm left",
        "-o",
        out.to_str().unwrap(),
        "--json",
        link.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink(),
        "the link was replaced"
    );
}

#[test]
fn control_and_bidi_characters_never_reach_the_terminal() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("evil.json");
    let evil = "sofa\u{1b}]0;pwned\u{7}\u{202e}";
    std::fs::write(
        &scene,
        serde_json::json!({"name": "evil\u{1b}]0;pwned\u{7}", "objects": [
            {"name": evil, "position": [0, 0, 0], "size": [2, 0.8, 0.9]},
            {"name": "lamp\u{2066}x\u{9b}\u{0}\u{200f}\u{61c}", "position": [3, 0, 0], "size": [0.4, 1.5, 0.4]}
        ]})
        .to_string(),
    )
    .unwrap();
    let scene = scene.to_str().unwrap();
    let raw = |c: char| {
        matches!(c, '\u{0}'..='\u{1f}' | '\u{7f}'..='\u{9f}' | '\u{61c}' | '\u{200e}' | '\u{200f}'
            | '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}')
            && c != '\n'
    };
    let runs: [(&[&str], &str); 4] = [
        // "names no object": the scene's names quoted, and an instruction with ESC in it.
        (
            &[
                "edit",
                scene,
                "move the \u{1b}[31mwardrobe\u{202e} to the left",
            ],
            "names no object",
        ),
        // "did you mean": the name asked for and the name suggested.
        (
            &[
                "eval",
                "T(X1.max)",
                "--scene",
                scene,
                "--bind",
                "X1=sofa\u{1b}]0;pwned\u{7}",
            ],
            "did you mean 'sofa\\u{1b}]0;pwned\\u{7}\\u{202e}'",
        ),
        (
            &["edit", scene, "move the sofa to the left"],
            "did you mean",
        ),
        // An argument clap refuses, quoted in its error.
        (
            &["edit", scene, "x", "--system", "\u{1b}[2J\u{202e}"],
            "invalid value",
        ),
    ];
    for (args, message) in runs {
        let o = shenlong(args);
        assert!(!o.status.success(), "{args:?}");
        let err = stderr(&o);
        assert!(err.contains(message), "{args:?}: {err}");
        assert!(!err.chars().any(raw), "{args:?}: {err:?}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    // The JSON report on stderr is still JSON, with the same names, escaped.
    let instruction = format!("move the '{evil}' 1 m to the left");
    let o = shenlong(&["edit", scene, &instruction, "--json", "-"]);
    let err = stderr(&o);
    assert!(o.status.success(), "{err}");
    assert!(!err.chars().any(raw), "{err:?}");
    let report: serde_json::Value = serde_json::from_str(err.trim()).unwrap();
    assert_eq!(
        report["understood"]["bindings"][0]["object"], evil,
        "{report}"
    );
}

#[test]
fn pictures_of_a_gltf_edit_show_what_moved() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("room.glb");
    let edited = dir.path().join("edited.glb");
    let picture = dir.path().join("edit.svg");
    let o = shenlong(&["convert", "example:living_room", input.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let o = shenlong(&[
        "edit",
        input.to_str().unwrap(),
        "move the sofa 30 cm to the left",
        "-o",
        edited.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let o = shenlong(&[
        "render",
        edited.to_str().unwrap(),
        "--before",
        input.to_str().unwrap(),
        "-o",
        picture.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&picture).unwrap();
    // One arrow from the sofa's old place to its new one: only the sofa moved.
    assert_eq!(
        svg.matches("marker-end=\"url(#arrow)\"").count(),
        1,
        "{svg}"
    );
}

#[test]
fn a_file_for_a_missing_folder_and_bad_units_are_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("no/such/folder/out.gltf");
    let o = shenlong(&["convert", "example:workshop", missing.to_str().unwrap()]);
    assert_fails_cleanly(&o, "does not exist");
    assert!(!missing.exists());
    let o = shenlong(&[
        "edit",
        "example:workshop",
        "move the 'tool table' 1 m left",
        "--units",
        "furlongs",
    ]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("mm, cm, m, in or ft"), "{}", stderr(&o));
    // Units are for glTF and USD files: scene JSON is in metres.
    let o = shenlong(&[
        "edit",
        &format!("{}/workshop.json", examples_dir().display()),
        "move the 'tool table' 1 m left",
        "--units",
        "mm",
    ]);
    assert_fails_cleanly(&o, "glTF and USD files only");
}

#[cfg(unix)]
#[test]
fn a_report_that_cannot_be_written_leaves_the_scene_unwritten() {
    let dir = tempfile::tempdir().unwrap();
    let full = dir.path().join("full.json");
    std::os::unix::fs::symlink("/dev/full", &full).unwrap();
    let edited = dir.path().join("edited.json");
    let o = shenlong(&[
        "edit",
        "example:workshop",
        "move the 'tool table' 1 m left",
        "-o",
        edited.to_str().unwrap(),
        "--json",
        full.to_str().unwrap(),
    ]);
    assert_fails_cleanly(&o, "cannot write");
    assert!(!edited.exists(), "the scene is not written");
}

#[cfg(unix)]
#[test]
fn pipes_and_endless_devices_are_refused_as_scenes_suites_and_houses() {
    let dir = tempfile::tempdir().unwrap();
    let mut inputs = Vec::new();
    for name in ["pipe.json", "pipe.gltf", "pipe.glb"] {
        let p = dir.path().join(name);
        assert!(std::process::Command::new("mkfifo")
            .arg(&p)
            .status()
            .unwrap()
            .success());
        inputs.push(p);
    }
    for name in ["zero.json", "zero.gltf", "zero.glb"] {
        let p = dir.path().join(name);
        std::os::unix::fs::symlink("/dev/zero", &p).unwrap();
        inputs.push(p);
    }
    for input in &inputs {
        let out = dir.path().join("out.json");
        let o = shenlong(&["convert", input.to_str().unwrap(), out.to_str().unwrap()]);
        assert_fails_cleanly(&o, "not a regular file");
        assert!(!out.exists());
    }
    // A ProcTHOR house file and asset database that are pipes.
    let db = dir.path().join("assets.json");
    std::os::unix::fs::symlink("/dev/zero", &db).unwrap();
    let o = shenlong(&[
        "convert",
        inputs[0].to_str().unwrap(),
        dir.path().join("h.json").to_str().unwrap(),
        "--from",
        "procthor",
        "--assets",
        db.to_str().unwrap(),
    ]);
    assert_fails_cleanly(&o, "not a regular file");
    // A suite whose scene is a pipe (suites are downloaded).
    let suite = dir.path().join("hostile.suite.json");
    std::fs::write(
        &suite,
        r#"{"name": "hostile", "scenes": ["pipe.json"], "queries": [{"id": "q", "category": "simple", "text": "move the box 1 m left", "expect": [{"check": "moved", "object": "box"}]}]}"#,
    )
    .unwrap();
    let o = shenlong(&[
        "bench",
        suite.to_str().unwrap(),
        "--out",
        dir.path().join("run").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("not a regular file"), "{}", stderr(&o));
}

#[test]
fn a_shard_folder_claiming_a_trillion_shards_is_refused_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let shard = dir.path().join("shard");
    std::fs::create_dir(&shard).unwrap();
    std::fs::write(
        shard.join("run.json"),
        r#"{"suite": "s", "model": "offline", "systems": ["cga"], "shard": [1, 1000000000000]}"#,
    )
    .unwrap();
    std::fs::write(shard.join("results.jsonl"), "").unwrap();
    let start = std::time::Instant::now();
    let o = shenlong(&[
        "bench",
        "--merge",
        shard.to_str().unwrap(),
        "--out",
        dir.path().join("merged").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("10000 shards at most"),
        "{}",
        stderr(&o)
    );
    assert!(start.elapsed() < std::time::Duration::from_secs(10));
}

#[test]
fn a_group_edit_of_thousands_is_not_quadratic() {
    // 5,000 chairs moved together, colliding with nothing: each costs a walk of its
    // supports, not a search of every other chair's load (this took hours before).
    let dir = tempfile::tempdir().unwrap();
    let objects: Vec<serde_json::Value> = (0..5000)
        .map(|i| {
            serde_json::json!({"name": format!("chair {}", i + 1), "category": "chair",
                "position": [(i % 100) as f64, 0.0, (i / 100) as f64], "size": [0.5, 0.9, 0.5]})
        })
        .collect();
    let scene = dir.path().join("hall.json");
    std::fs::write(
        &scene,
        serde_json::json!({"name": "hall", "objects": objects}).to_string(),
    )
    .unwrap();
    let out = dir.path().join("out.json");
    let o = shenlong(&[
        "edit",
        scene.to_str().unwrap(),
        "move all the chairs 1 m up",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let edited: serde_json::Value = serde_json::from_slice(&std::fs::read(&out).unwrap()).unwrap();
    assert_eq!(edited["objects"][4999]["position"][1], 1);
}

//! `shenlong chat` as people use it: scripted from a pipe, and typed at a terminal (a
//! pseudo-terminal, with line editing and history), the scene saved where asked.

mod support;

use std::io::Write;
use std::process::{Command, Stdio};
use support::{examples_dir, object, read_json};

fn position(scene: &serde_json::Value, name: &str) -> [f64; 3] {
    let p = &object(scene, name)["position"];
    [0, 1, 2].map(|k| p[k].as_f64().unwrap())
}

fn near(a: [f64; 3], b: [f64; 3]) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-6)
}

/// Runs the chat on `turns` from a pipe; its status, stdout and stderr.
fn piped(args: &[&str], turns: &str) -> (bool, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_shenlong"))
        .arg("chat")
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(turns.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_piped_conversation_is_read_a_turn_a_line_and_saved_on_leaving() {
    let dir = tempfile::tempdir().unwrap();
    let scene = examples_dir().join("living_room.json");
    let start = position(&read_json(&scene), "armchair");
    let saved = dir.path().join("edited.json");
    let turns = "move the armchair 50 cm to the right\na bit more\n\nmove the ottoman 30 cm forward\nput the armchair back\n/history\n";
    let (ok, out, err) = piped(
        &[scene.to_str().unwrap(), "--save", saved.to_str().unwrap()],
        turns,
    );
    assert!(ok, "{err}");
    assert!(out.contains("'armchair': moved 0.50 m"), "{out}");
    assert!(out.contains("'armchair': moved 0.10 m"), "{out}");
    assert!(
        out.contains("'magazine'") && out.contains("(carried)"),
        "{out}"
    );
    assert!(
        out.contains("move the ottoman 30 cm forward"),
        "the history: {out}"
    );
    let edited = read_json(&saved);
    assert!(near(
        position(&edited, "armchair"),
        [start[0] + 0.5, start[1], start[2]]
    ));
    assert!(err.is_empty(), "{err}");
}

#[test]
fn a_selection_is_what_it_means_for_the_next_edit() {
    let scene = examples_dir().join("living_room.json");
    let start = read_json(&scene);
    let (ok, out, err) = piped(
        &[scene.to_str().unwrap(), "--json"],
        "move the armchair 20 cm to the right\n/select ottoman\nmove it 10 cm to the left\nmove it 10 cm to the left\n/select nothing here\n",
    );
    assert!(ok, "{err}");
    let answers: Vec<serde_json::Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let moved = |k: usize| {
        answers[k]["moved"][0]["object"]
            .as_str()
            .unwrap()
            .to_string()
    };
    assert_eq!(moved(0), "armchair");
    assert_eq!(moved(1), "ottoman", "the selection wins over the last edit");
    assert_eq!(
        moved(2),
        "ottoman",
        "then \"it\" is what the last edit moved: {out}"
    );
    let x = |v: &serde_json::Value, name: &str| position(v, name)[0];
    assert!(
        (answers[2]["moved"][0]["after"]["position"][0]
            .as_f64()
            .unwrap()
            - (x(&start, "ottoman") - 0.2))
            .abs()
            < 1e-6
    );
    assert!(err.contains("/select:"), "an unknown name is said: {err}");
}

#[test]
fn piped_refusals_are_one_line_each_and_the_status_says_so() {
    let scene = examples_dir().join("living_room.json");
    let (ok, out, err) = piped(
        &[scene.to_str().unwrap(), "--json"],
        "move it 10 cm to the right\nput the sofa back\nmove the sofa 10 cm forward\n",
    );
    assert!(!ok);
    let answers: Vec<serde_json::Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(answers.len(), 3, "{out}");
    assert_eq!(answers[0]["kind"], "not_understood");
    assert!(answers[0]["error"]
        .as_str()
        .unwrap()
        .contains("points at nothing"));
    assert_eq!(answers[1]["kind"], "not_understood");
    assert_eq!(answers[2]["operation"], "edit");
    assert!(err.contains("2 turns were refused"), "{err}");
    assert!(
        err.contains("not written"),
        "leaving says the changes were not kept: {err}"
    );
}

#[cfg(unix)]
mod terminal {
    use super::*;
    use std::fs::File;
    use std::io::Read;
    use std::os::fd::{FromRawFd, OwnedFd};
    use std::sync::mpsc;
    use std::time::{Duration, Instant};

    /// A pseudo-terminal: the side the test types on and reads from, and the side the
    /// chat gets as its terminal.
    fn pty() -> (File, OwnedFd) {
        let (mut master, mut slave) = (0, 0);
        // SAFETY: openpty writes two descriptors; null name, termios and size are allowed.
        let done = unsafe {
            libc::openpty(
                &mut master,
                &mut slave,
                std::ptr::null_mut(),
                std::ptr::null(),
                std::ptr::null(),
            )
        };
        assert_eq!(done, 0, "openpty");
        // SAFETY: both descriptors are new and ours.
        unsafe { (File::from_raw_fd(master), OwnedFd::from_raw_fd(slave)) }
    }

    /// Reads what the chat prints until `text` shows, or fails after 20 s.
    fn expect(from: &mpsc::Receiver<u8>, seen: &mut String, text: &str) {
        let deadline = Instant::now() + Duration::from_secs(20);
        let mut bytes = Vec::new();
        while !seen.contains(text) {
            let left = deadline.saturating_duration_since(Instant::now());
            match from.recv_timeout(left) {
                Ok(b) => {
                    bytes.push(b);
                    *seen = String::from_utf8_lossy(&bytes).into_owned();
                }
                Err(_) => panic!("waited for {text:?}; the terminal shows: {seen:?}"),
            }
        }
        seen.clear();
    }

    #[test]
    fn a_conversation_typed_at_a_terminal_with_line_editing() {
        let dir = tempfile::tempdir().unwrap();
        let scene = examples_dir().join("living_room.json");
        let start = position(&read_json(&scene), "armchair");
        let saved = dir.path().join("edited.json");
        let (mut master, slave) = pty();
        let mut child = Command::new(env!("CARGO_BIN_EXE_shenlong"))
            .args([
                "chat",
                scene.to_str().unwrap(),
                "--save",
                saved.to_str().unwrap(),
            ])
            .env("TERM", "xterm")
            .stdin(Stdio::from(slave.try_clone().unwrap()))
            .stdout(Stdio::from(slave.try_clone().unwrap()))
            .stderr(Stdio::from(slave))
            .spawn()
            .unwrap();
        let (tx, rx) = mpsc::channel();
        let mut reader = master.try_clone().unwrap();
        std::thread::spawn(move || {
            let mut buf = [0u8; 1024];
            while let Ok(n) = reader.read(&mut buf) {
                if n == 0 || buf[..n].iter().any(|&b| tx.send(b).is_err()) {
                    break;
                }
            }
        });
        let mut seen = String::new();
        expect(&rx, &mut seen, "shenlong> ");
        // A typo mended with Backspace before Enter.
        master
            .write_all(b"move the armchair 50 cm to the rihgt\x7f\x7f\x7fght\r")
            .unwrap();
        expect(&rx, &mut seen, "moved 0.50 m");
        master.write_all(b"a bit more\r").unwrap();
        expect(&rx, &mut seen, "moved 0.10 m");
        // Up: the last line again, from the history.
        master.write_all(b"\x1b[A\r").unwrap();
        expect(&rx, &mut seen, "moved 0.10 m");
        master.write_all(b"put it back\r").unwrap();
        expect(&rx, &mut seen, "moved 0.10 m");
        master.write_all(b"/save\r").unwrap();
        expect(&rx, &mut seen, "saved");
        master.write_all(b"/quit\r").unwrap();
        let status = child.wait().unwrap();
        assert!(status.success());
        let edited = read_json(&saved);
        assert!(
            near(
                position(&edited, "armchair"),
                [start[0] + 0.6, start[1], start[2]]
            ),
            "{:?}",
            position(&edited, "armchair")
        );
    }
}

//! Hostile and broken USD stages, run as a user runs the binary: each is refused in one
//! line, in bounded time, and the process is never killed by a signal.

mod support;

use std::path::{Path, PathBuf};
use std::process::Output;
use std::time::{Duration, Instant};
use support::stderr;

/// Runs `shenlong edit FILE "move the 'A' 1 m left" -o OUT` with a short USD time budget.
fn edit(file: &Path, out: &Path) -> (Output, Duration) {
    let start = Instant::now();
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_shenlong"))
        .args([
            "edit",
            file.to_str().unwrap(),
            "move the 'A' 1 m to the left",
            "-o",
            out.to_str().unwrap(),
        ])
        .env("SHENLONG_USD_SECONDS", "4")
        .output()
        .unwrap();
    (o, start.elapsed())
}

#[track_caller]
fn refused(file: &Path, says: &str) {
    let out = file.with_file_name("out.usda");
    let (o, took) = edit(file, &out);
    assert!(
        o.status.code().is_some(),
        "{}: killed by a signal: {:?}",
        file.display(),
        o.status
    );
    assert_eq!(
        o.status.code(),
        Some(1),
        "{}: {}",
        file.display(),
        stderr(&o)
    );
    let err = stderr(&o);
    assert_eq!(err.lines().count(), 1, "one line: {err}");
    assert!(
        err.contains(says),
        "{}: expected '{says}' in: {err}",
        file.display()
    );
    assert!(!out.exists(), "nothing written");
    assert!(
        took < Duration::from_secs(30),
        "{}: took {took:?}",
        file.display()
    );
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

const HEADER: &str =
    "#usda 1.0\n(\n    defaultPrim = \"World\"\n    metersPerUnit = 1\n    upAxis = \"Y\"\n)\n";

/// Refused in one line, or read and edited — never killed by a signal, never hung.
#[track_caller]
fn refused_or_read(file: &Path) {
    let out = file.with_file_name("out.usda");
    let (o, took) = edit(file, &out);
    assert!(
        o.status.code().is_some(),
        "{}: {:?}",
        file.display(),
        o.status
    );
    assert!(
        took < Duration::from_secs(30),
        "{}: took {took:?}",
        file.display()
    );
    if o.status.success() {
        assert!(out.exists());
    } else {
        assert_eq!(stderr(&o).lines().count(), 1, "{}", stderr(&o));
        assert!(!out.exists());
    }
}

#[test]
fn arc_cycles_are_refused_not_crashed_on() {
    let dir = tempfile::tempdir().unwrap();
    let own = write(
        dir.path(),
        "self.usda",
        &format!("{HEADER}def Xform \"World\"\n{{\n    def Cube \"A\" (\n        specializes = </World/A>\n    )\n    {{\n    }}\n}}\n"),
    );
    refused_or_read(&own);
    let pair = write(
        dir.path(),
        "pair.usda",
        &format!("{HEADER}def Xform \"World\"\n{{\n    def Cube \"A\" (\n        inherits = </World/B>\n    )\n    {{\n    }}\n    def Cube \"B\" (\n        inherits = </World/A>\n    )\n    {{\n    }}\n}}\n"),
    );
    refused_or_read(&pair);
}

#[test]
fn exponential_composition_ends_in_bounded_time() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = format!("{HEADER}def Xform \"World\"\n{{\n    def Cube \"A\" (\n        references = [</L1>, </L1>]\n    )\n    {{\n    }}\n}}\n");
    for level in 1..24 {
        text.push_str(&format!(
            "def Xform \"L{level}\" (\n    references = [</L{n}>, </L{n}>]\n)\n{{\n    def Cube \"C{level}\"\n    {{\n    }}\n}}\n",
            n = level + 1
        ));
    }
    text.push_str("def Xform \"L24\"\n{\n}\n");
    let file = write(dir.path(), "exp.usda", &text);
    // Refused, whatever the reason the child gives (its time, its memory); or read, if
    // the USD crate composes it without blowing up — but never hung or killed.
    let (o, took) = edit(&file, &dir.path().join("out.usda"));
    assert!(o.status.code().is_some(), "{:?}", o.status);
    assert!(took < Duration::from_secs(30), "took {took:?}");
    if !o.status.success() {
        assert_eq!(stderr(&o).lines().count(), 1, "{}", stderr(&o));
    }
}

#[test]
fn nesting_hidden_behind_a_comment_and_deep_sublayers_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let depth = 30_000;
    let mut text = format!("{HEADER}# it's a deep one\ndef Xform \"World\"\n{{\n");
    for k in 0..depth {
        text.push_str(&format!("def Xform \"P{k}\" {{\n"));
    }
    text.push_str("def Cube \"A\" {}\n");
    for _ in 0..depth {
        text.push_str("}\n");
    }
    text.push_str("}\n");
    let deep = write(dir.path(), "deep.usda", &text);
    refused(&deep, "nesting deeper than 100 levels");
    // The same deep layer reached through a sublayer: the child may crash, never this
    // process.
    let top = write(
        dir.path(),
        "top.usda",
        "#usda 1.0\n(\n    subLayers = [\n        @./deep.usda@\n    ]\n)\n",
    );
    refused(&top, "");
}

#[test]
fn units_names_links_and_pipes() {
    let dir = tempfile::tempdir().unwrap();
    let tiny = write(
        dir.path(),
        "tiny.usda",
        "#usda 1.0\n(\n    metersPerUnit = 1e-300\n)\ndef Cube \"A\"\n{\n}\n",
    );
    refused(&tiny, "metersPerUnit");

    // A FIFO as a sublayer inside the folder: refused as what it is.
    #[cfg(unix)]
    {
        let fifo = dir.path().join("pipe.usda");
        let made = std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .is_ok_and(|s| s.success());
        if made {
            let top = write(
                dir.path(),
                "withpipe.usda",
                "#usda 1.0\n(\n    subLayers = [\n        @./pipe.usda@\n    ]\n)\ndef Cube \"A\"\n{\n}\n",
            );
            refused(&top, "is not a regular file");
        }
    }

    // `--usd-layer -o LINK` where LINK names the input: refused, the input unharmed.
    #[cfg(unix)]
    {
        let input = write(
            dir.path(),
            "stage.usda",
            &format!("{HEADER}def Xform \"World\"\n{{\n    def Cube \"A\"\n    {{\n    }}\n    def Cube \"B\"\n    {{\n        double3 xformOp:translate = (5, 0, 0)\n        uniform token[] xformOpOrder = [\"xformOp:translate\"]\n    }}\n}}\n"),
        );
        let before = std::fs::read(&input).unwrap();
        let link = dir.path().join("current.usda");
        std::os::unix::fs::symlink(&input, &link).unwrap();
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_shenlong"))
            .args([
                "edit",
                input.to_str().unwrap(),
                "move the 'A' 1 m to the left",
                "-o",
                link.to_str().unwrap(),
                "--usd-layer",
            ])
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
        assert!(
            stderr(&o).contains("cannot replace the stage itself"),
            "{}",
            stderr(&o)
        );
        assert_eq!(
            std::fs::read(&input).unwrap(),
            before,
            "the input is unharmed"
        );
    }
}

#[test]
fn a_compressed_package_is_refused_before_anything_inflates() {
    // A zip whose one entry is deflated (method 8): a .usdz stores its files uncompressed.
    let dir = tempfile::tempdir().unwrap();
    let name = b"a.usda";
    let data = b"\x03\x00"; // an empty deflate stream
    let mut zip = Vec::new();
    zip.extend_from_slice(&[0x50, 0x4b, 0x03, 0x04, 20, 0, 0, 0, 8, 0, 0, 0, 0, 0]);
    zip.extend_from_slice(&0u32.to_le_bytes()); // crc
    zip.extend_from_slice(&(data.len() as u32).to_le_bytes());
    zip.extend_from_slice(&(2u32 << 30).to_le_bytes()); // claims 2 GiB inflated
    zip.extend_from_slice(&(name.len() as u16).to_le_bytes());
    zip.extend_from_slice(&0u16.to_le_bytes());
    zip.extend_from_slice(name);
    zip.extend_from_slice(data);
    let cd = zip.len();
    zip.extend_from_slice(&[0x50, 0x4b, 0x01, 0x02, 20, 0, 20, 0, 0, 0, 8, 0, 0, 0, 0, 0]);
    zip.extend_from_slice(&0u32.to_le_bytes());
    zip.extend_from_slice(&(data.len() as u32).to_le_bytes());
    zip.extend_from_slice(&(2u32 << 30).to_le_bytes());
    zip.extend_from_slice(&(name.len() as u16).to_le_bytes());
    zip.extend_from_slice(&[0; 12]);
    zip.extend_from_slice(&0u32.to_le_bytes()); // local header offset
    zip.extend_from_slice(name);
    let cd_size = zip.len() - cd;
    zip.extend_from_slice(&[0x50, 0x4b, 0x05, 0x06, 0, 0, 0, 0, 1, 0, 1, 0]);
    zip.extend_from_slice(&(cd_size as u32).to_le_bytes());
    zip.extend_from_slice(&(cd as u32).to_le_bytes());
    zip.extend_from_slice(&0u16.to_le_bytes());
    let bomb = dir.path().join("bomb.usdz");
    std::fs::write(&bomb, zip).unwrap();
    refused(&bomb, "compressed");
}

#[test]
fn a_huge_self_contained_layer_is_read_within_the_childs_budget() {
    // Two million empty prims: a layer Shenlong reads itself, whose tree grows to
    // gigabytes. It is read in the reading child, so its time budget (4 s here) ends it
    // and this process answers in one line.
    let dir = tempfile::tempdir().unwrap();
    let mut text = format!("{HEADER}def Xform \"World\"\n{{\n");
    for k in 0..2_000_000 {
        text.push_str(&format!("def Xform \"P{k}\" {{}}\n"));
    }
    text.push_str("def Cube \"A\" {}\n}\n");
    let file = write(dir.path(), "huge.usda", &text);
    refused(&file, "took more than 4 s");
}

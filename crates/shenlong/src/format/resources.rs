//! The buffers and images of a `.gltf` written to another folder.
//!
//! They are copied beside the output, flat, under names Shenlong makes: the output's stem,
//! an index and the original extension when it is a known resource type (`edited_0.bin`,
//! `edited_1.png`; anything else becomes `.bin`), and the written file's URIs name the
//! copies. No path from the file chooses where anything is written, so a hostile file
//! cannot plant `~/.bash_profile` or `~/.ssh/authorized_keys`, nor write through a linked
//! subfolder. A link or anything but a regular file where a copy goes is refused; every
//! file is written in full to a temporary file in the output folder before any is renamed
//! into place, the glTF last, so a failure leaves the folder as it was.

use super::gltf::{self, Container, GltfDocument, MAX_RESOURCE_BYTES};
use super::FormatError;
use crate::io::Staged;
use std::collections::HashMap;
use std::io::{Read, Write};
use std::path::{Path, PathBuf};

/// The extensions a copy keeps (compared case-insensitively); any other, or none, gives
/// `.bin`, so a copy is never named as a program, a script or a desktop entry.
pub const KEPT_EXTENSIONS: &[&str] = &[
    "bin", "glbin", "png", "jpg", "jpeg", "webp", "avif", "gif", "bmp", "tga", "ktx", "ktx2",
    "dds", "basis", "hdr", "exr",
];

/// The longest part of the output's stem a copy's name keeps, in characters.
const MAX_STEM_CHARS: usize = 100;

/// What writing a `.gltf` in another folder copies.
#[derive(Debug)]
pub(crate) struct Copies {
    /// Each external URI as the file has it → the URI of its copy.
    pub uris: HashMap<String, String>,
    /// (source, destination), one per distinct source file.
    files: Vec<(PathBuf, PathBuf)>,
}

/// What saving `document` as `output` copies; `None` when nothing is: a binary glTF, a file
/// with no external resources, or an output in its source's folder (which keeps its URIs).
///
/// # Errors
/// A resource that cannot be read from the source's folder ([`gltf::resolve_uri`]).
pub(crate) fn plan(document: &GltfDocument, output: &Path) -> Result<Option<Copies>, FormatError> {
    let Container::Gltf { base_dir } = document.container() else {
        return Ok(None);
    };
    let uris = document.external_uris();
    if uris.is_empty() {
        return Ok(None);
    }
    let out_dir = folder_of(output);
    let base = if base_dir.as_os_str().is_empty() {
        Path::new(".")
    } else {
        base_dir.as_path()
    };
    if let (Ok(a), Ok(b)) = (base.canonicalize(), out_dir.canonicalize()) {
        if a == b {
            return Ok(None);
        }
    }
    let stem = stem_of(output);
    let mut copies = Copies {
        uris: HashMap::new(),
        files: Vec::new(),
    };
    // One copy per file, however many URIs name it.
    let mut by_source: HashMap<PathBuf, String> = HashMap::new();
    for uri in uris {
        if copies.uris.contains_key(&uri) {
            continue;
        }
        let source =
            gltf::resolve_uri(base, &uri).map_err(|e| FormatError::invalid(e.to_string()))?;
        let key = source.canonicalize().unwrap_or_else(|_| source.clone());
        let new_uri = match by_source.get(&key) {
            Some(u) => u.clone(),
            None => {
                let name = format!(
                    "{stem}_{}.{}",
                    copies.files.len(),
                    extension_of(&gltf::percent_decode(&uri))
                );
                copies.files.push((source, out_dir.join(&name)));
                let u = percent_encode(&name);
                by_source.insert(key, u.clone());
                u
            }
        };
        copies.uris.insert(uri, new_uri);
    }
    Ok(Some(copies))
}

/// Writes the copies and `bytes` at `output`, all or nothing (but for a failed rename,
/// after which the copies it made new are removed again).
///
/// # Errors
/// A link or a non-regular file where a copy goes, or a failed read or write.
pub(crate) fn write_all(copies: &Copies, output: &Path, bytes: &[u8]) -> Result<(), FormatError> {
    let mut existed = Vec::with_capacity(copies.files.len());
    for (_, target) in &copies.files {
        existed.push(check_destination(target)?);
    }
    let mut staged: Vec<Staged> = Vec::with_capacity(copies.files.len());
    for (source, target) in &copies.files {
        let file = crate::io::stage(target, |file| copy_into(source, file)).map_err(|e| {
            FormatError::invalid(format!(
                "cannot copy {} to {}: {e}",
                source.display(),
                target.display()
            ))
        })?;
        staged.push(file);
    }
    let main = crate::io::stage(output, |file| file.write_all(bytes))
        .map_err(|e| FormatError::write(output, e))?;
    // Everything is on disk; now into place, the glTF last.
    let mut made: Vec<PathBuf> = Vec::new();
    let undo = |made: &[PathBuf]| {
        for m in made {
            let _ = std::fs::remove_file(m);
        }
    };
    for (file, existed) in staged.into_iter().zip(existed) {
        let target = file.target().to_path_buf();
        if let Err(e) = file.commit() {
            undo(&made);
            return Err(FormatError::write(&target, e));
        }
        if !existed {
            made.push(target);
        }
    }
    main.commit().map_err(|e| {
        undo(&made);
        FormatError::write(output, e)
    })
}

/// Whether a regular file is at `target` (it will be replaced); a link, a folder or any
/// other kind of file there is refused.
fn check_destination(target: &Path) -> Result<bool, FormatError> {
    match std::fs::symlink_metadata(target) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(false),
        Err(e) => Err(FormatError::write(target, e)),
        Ok(m) if m.file_type().is_symlink() => Err(FormatError::write(
            target,
            std::io::Error::other("it is a link, and Shenlong does not write through links"),
        )),
        Ok(m) if !m.is_file() => Err(FormatError::write(
            target,
            std::io::Error::other("it is not a regular file"),
        )),
        Ok(_) => Ok(true),
    }
}

/// Copies `source` (a regular file inside the glTF's folder, as [`gltf::resolve_uri`]
/// checked) into `file`, at most [`MAX_RESOURCE_BYTES`].
fn copy_into(source: &Path, file: &mut std::fs::File) -> std::io::Result<()> {
    let reader = std::fs::File::open(source)?;
    let copied = std::io::copy(&mut reader.take(MAX_RESOURCE_BYTES + 1), file)?;
    if copied > MAX_RESOURCE_BYTES {
        return Err(std::io::Error::other(format!(
            "it is larger than {} MiB",
            MAX_RESOURCE_BYTES >> 20
        )));
    }
    Ok(())
}

fn folder_of(output: &Path) -> PathBuf {
    match output.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// The output's stem as a name's first part: letters, digits, `-` and `_` kept, anything
/// else `_`, at most [`MAX_STEM_CHARS`].
fn stem_of(output: &Path) -> String {
    let stem: String = output
        .file_stem()
        .map(|s| s.to_string_lossy())
        .unwrap_or_default()
        .chars()
        .map(|c| {
            if c.is_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .take(MAX_STEM_CHARS)
        .collect();
    if stem.is_empty() {
        "scene".into()
    } else {
        stem
    }
}

/// The extension a copy of `path` gets: its own when it is in [`KEPT_EXTENSIONS`], else
/// `bin`.
fn extension_of(path: &str) -> &'static str {
    let ext = Path::new(path)
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    KEPT_EXTENSIONS
        .iter()
        .find(|k| **k == ext)
        .copied()
        .unwrap_or("bin")
}

/// A file name as a URI: bytes other than ASCII letters, digits and `-._~` as `%XX`.
fn percent_encode(name: &str) -> String {
    let mut out = String::with_capacity(name.len());
    for b in name.bytes() {
        if b.is_ascii_alphanumeric() || b"-._~".contains(&b) {
            out.push(b as char);
        } else {
            out.push_str(&format!("%{b:02X}"));
        }
    }
    out
}

#[cfg(all(test, unix))]
mod tests {
    use crate::format::{Document, SceneFile};
    use cga::Multivector;
    use glam::DVec3;
    use std::collections::BTreeSet;
    use std::path::{Path, PathBuf};

    fn triangle() -> Vec<u8> {
        let mut bytes = Vec::new();
        for v in [0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0] {
            bytes.extend_from_slice(&v.to_le_bytes());
        }
        bytes
    }

    /// A one-triangle glTF: its positions in the first of `buffers` (36 bytes each), and
    /// `images` that nothing draws.
    fn gltf(buffers: &[&str], images: &[&str]) -> String {
        let buffers: Vec<String> = buffers
            .iter()
            .map(|u| format!(r#"{{"byteLength": 36, "uri": "{u}"}}"#))
            .collect();
        let images: Vec<String> = images
            .iter()
            .map(|u| format!(r#"{{"uri": "{u}"}}"#))
            .collect();
        format!(
            r#"{{"asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": [0]}}],
            "nodes": [{{"name": "tri", "mesh": 0}}],
            "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}}}]}}],
            "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 0]}}],
            "bufferViews": [{{"buffer": 0, "byteLength": 36}}],
            "buffers": [{}], "images": [{}]}}"#,
            buffers.join(", "),
            images.join(", ")
        )
    }

    /// Every path under `dir`, relative to it (links not followed).
    fn listing(dir: &Path) -> BTreeSet<String> {
        let mut out = BTreeSet::new();
        let mut stack = vec![dir.to_path_buf()];
        while let Some(d) = stack.pop() {
            for entry in std::fs::read_dir(&d).unwrap() {
                let entry = entry.unwrap();
                let path = entry.path();
                out.insert(
                    path.strip_prefix(dir)
                        .unwrap()
                        .to_string_lossy()
                        .into_owned(),
                );
                if entry.file_type().unwrap().is_dir() {
                    stack.push(path);
                }
            }
        }
        out
    }

    fn set(items: &[&str]) -> BTreeSet<String> {
        items.iter().map(|s| s.to_string()).collect()
    }

    /// A hostile download: a scene whose resources sit in the folder under names that,
    /// copied as they are, would land in the user's dotfiles.
    fn hostile_download(root: &Path) -> PathBuf {
        let input = root.join("download");
        for (path, bytes) in [
            (".bash_profile", triangle()),
            (
                ".ssh/authorized_keys",
                b"ssh-ed25519 AAAA attacker -------".repeat(2)[..36].to_vec(),
            ),
            ("sub/dir/x.bin", vec![7u8; 36]),
            (
                ".config/autostart/evil.desktop",
                b"[Desktop Entry]\nExec=evil\n".to_vec(),
            ),
            ("tex.png", b"\x89PNG not really".to_vec()),
        ] {
            let file = input.join(path);
            std::fs::create_dir_all(file.parent().unwrap()).unwrap();
            std::fs::write(file, bytes).unwrap();
        }
        let scene = input.join("scene.gltf");
        std::fs::write(
            &scene,
            gltf(
                &[".bash_profile", ".ssh/authorized_keys", "sub/dir/x.bin"],
                &[
                    ".config/autostart/evil.desktop",
                    "tex.png",
                    "./tex.png",
                    "sub/dir/x.bin",
                ],
            ),
        )
        .unwrap();
        scene
    }

    #[test]
    fn resources_are_copied_flat_under_names_shenlong_makes() {
        let root = tempfile::tempdir().unwrap();
        let scene = hostile_download(root.path());
        let home = root.path().join("home");
        let elsewhere = root.path().join("elsewhere");
        std::fs::create_dir_all(&home).unwrap();
        std::fs::create_dir_all(&elsewhere).unwrap();
        // A subfolder of the output folder that links elsewhere.
        std::os::unix::fs::symlink(&elsewhere, home.join("sub")).unwrap();

        let mut file = SceneFile::load(&scene).unwrap();
        file.scene
            .apply(0, &Multivector::translator(DVec3::X), false)
            .unwrap();
        let expected = file.scene.objects[0].world_aabb();
        let output = home.join("edited.gltf");
        file.save(&output).unwrap();

        let named = set(&[
            "edited.gltf",
            "edited_0.bin",
            "edited_1.bin",
            "edited_2.bin",
            "edited_3.bin",
            "edited_4.png",
            "sub",
        ]);
        assert_eq!(listing(&home), named, "only files Shenlong named, flat");
        assert!(listing(&elsewhere).is_empty(), "nothing through the link");
        assert_eq!(
            listing(root.path())
                .into_iter()
                .filter(|p| !p.starts_with("download") && !p.starts_with("home"))
                .collect::<Vec<_>>(),
            ["elsewhere"],
            "nothing outside the output folder"
        );

        // The edited file loads, its mesh moved, and names only the copies.
        let reread = SceneFile::load(&output).unwrap();
        let got = reread.scene.objects[0].world_aabb();
        assert!((got.min - expected.min).length() < 1e-6, "{got:?}");
        let Document::Gltf(document) = &reread.document else {
            unreachable!()
        };
        assert_eq!(
            document.external_uris(),
            [
                "edited_0.bin",
                "edited_1.bin",
                "edited_2.bin",
                "edited_3.bin",
                "edited_4.png",
                "edited_4.png",
                "edited_2.bin"
            ]
        );
        let source = scene.parent().unwrap();
        for (copy, original) in [
            ("edited_0.bin", ".bash_profile"),
            ("edited_1.bin", ".ssh/authorized_keys"),
            ("edited_2.bin", "sub/dir/x.bin"),
            ("edited_3.bin", ".config/autostart/evil.desktop"),
            ("edited_4.png", "tex.png"),
        ] {
            assert_eq!(
                std::fs::read(home.join(copy)).unwrap(),
                std::fs::read(source.join(original)).unwrap(),
                "{copy}"
            );
        }

        // Written again (the copies are replaced), and the copy of a copy is named anew.
        file.save(&output).unwrap();
        assert_eq!(listing(&home), named);
        let again = home.join("again");
        std::fs::create_dir(&again).unwrap();
        reread.save(&again.join("twice.gltf")).unwrap();
        assert_eq!(
            listing(&again),
            set(&[
                "twice.gltf",
                "twice_0.bin",
                "twice_1.bin",
                "twice_2.bin",
                "twice_3.bin",
                "twice_4.png"
            ])
        );
        assert_eq!(
            SceneFile::load(&again.join("twice.gltf"))
                .unwrap()
                .scene
                .objects
                .len(),
            1
        );

        // Written beside its source, the file keeps its URIs and nothing is copied.
        let before = listing(source);
        file.save(&source.join("edited.gltf")).unwrap();
        let mut after = before.clone();
        after.insert("edited.gltf".into());
        assert_eq!(listing(source), after);
    }

    #[test]
    fn a_link_at_a_destination_is_refused_and_nothing_is_written() {
        let root = tempfile::tempdir().unwrap();
        let scene = hostile_download(root.path());
        let home = root.path().join("home");
        std::fs::create_dir_all(&home).unwrap();
        let victim = root.path().join("victim.txt");
        std::fs::write(&victim, b"precious").unwrap();
        std::os::unix::fs::symlink(&victim, home.join("edited_0.bin")).unwrap();

        let file = SceneFile::load(&scene).unwrap();
        let e = file.save(&home.join("edited.gltf")).unwrap_err();
        assert!(e.to_string().contains("edited_0.bin"), "{}", e.to_string());
        assert!(e.to_string().contains("link"), "{}", e.to_string());
        assert_eq!(std::fs::read(&victim).unwrap(), b"precious");
        assert_eq!(
            listing(&home),
            set(&["edited_0.bin"]),
            "nothing else written"
        );
        assert!(std::fs::symlink_metadata(home.join("edited_0.bin"))
            .unwrap()
            .file_type()
            .is_symlink());

        // A dangling link, and a folder, are refused the same way.
        std::fs::remove_file(home.join("edited_0.bin")).unwrap();
        std::os::unix::fs::symlink(root.path().join("planted"), home.join("edited_1.bin")).unwrap();
        let e = file.save(&home.join("edited.gltf")).unwrap_err();
        assert!(e.to_string().contains("edited_1.bin"), "{}", e.to_string());
        assert!(!root.path().join("planted").exists());
        std::fs::remove_file(home.join("edited_1.bin")).unwrap();
        std::fs::create_dir(home.join("edited_2.bin")).unwrap();
        let e = file.save(&home.join("edited.gltf")).unwrap_err();
        assert!(e.to_string().contains("edited_2.bin"), "{}", e.to_string());
        assert_eq!(listing(&home), set(&["edited_2.bin"]));
    }

    #[test]
    fn a_resource_outside_the_folder_fails_the_save_before_anything_is_written() {
        let root = tempfile::tempdir().unwrap();
        let input = root.path().join("a/b/download");
        std::fs::create_dir_all(&input).unwrap();
        std::fs::write(input.join("ok.bin"), triangle()).unwrap();
        std::fs::write(root.path().join(".bash_profile"), b"mine").unwrap();
        let home = root.path().join("home");
        std::fs::create_dir_all(&home).unwrap();
        for image in [
            "../../../.bash_profile",
            "/etc/passwd",
            "%2E%2E/%2E%2E/x.png",
        ] {
            let scene = input.join("scene.gltf");
            std::fs::write(&scene, gltf(&["ok.bin"], &[image])).unwrap();
            // (Images are not read to find the objects.)
            let file = SceneFile::load(&scene).unwrap();
            let e = file.save(&home.join("edited.gltf")).unwrap_err();
            assert!(e.to_string().contains("outside"), "{image}: {}", e);
            assert!(listing(&home).is_empty(), "{image}: {:?}", listing(&home));
        }
        assert_eq!(
            std::fs::read(root.path().join(".bash_profile")).unwrap(),
            b"mine"
        );
    }
}

//! Scene file formats: reading them into a [`Scene`] and writing edits back.
//!
//! | format | read | write |
//! |---|---|---|
//! | scene JSON (`.json`, SPEC §2) | [`json`] | [`json`], in the input's shape |
//! | glTF 2.0 (`.gltf`, `.glb`) | [`gltf`]: mesh nodes as objects | [`gltf`]: only moved nodes change |
//! | ProcTHOR / Holodeck house (`.json`, `.jsonl`) | [`procthor`], with the asset database | — (converted to scene JSON) |
//! | ThreeDWorld commands (`.tdw.json`) | — | [`tdw`]: `teleport_object`, `rotate_object_to`, `scale_object` |
//!
//! [`SceneFile`] pairs a scene with the document it came from, so that writing changes
//! only what the edit changed.

pub mod facts;
pub mod gltf;
mod gltf_new;
pub mod json;
pub mod pretty;
pub mod procthor;
mod resources;
pub mod tdw;
mod transform;
#[cfg(feature = "usd")]
pub mod usd;

pub use facts::{Axis, ReadOptions, Units};

use crate::scene::Scene;
use std::fmt;
use std::path::{Path, PathBuf};

pub use crate::number::{tidy, tidy_json};

/// The deepest nesting of lists and objects a JSON file may have (scene JSON, glTF, ProcTHOR
/// houses and asset databases). Real files nest a dozen levels at most; the limit keeps
/// every tree built from a file (and every answer that wraps it) well within what
/// `serde_json` parses (127 levels).
pub const MAX_JSON_DEPTH: usize = 100;

/// Refuses JSON nested deeper than [`MAX_JSON_DEPTH`], saying where: one pass over the
/// bytes, brackets inside strings not counted. (Parsing with borrowed raw values, as the
/// scene-JSON reader does, skips unknown fields without a depth limit; the text is kept
/// and parsed again as a tree by whoever serves it.)
pub(crate) fn check_json_depth(text: &[u8]) -> Result<(), FormatError> {
    let mut depth = 0usize;
    let mut i = 0;
    while i < text.len() {
        // To the next byte that can change the depth: a bracket or a string's quote.
        match text[i..].iter().position(|&b| STRUCTURAL[b as usize]) {
            Some(k) => i += k,
            None => break,
        }
        match text[i] {
            b'"' => {
                // The string's end: its next quote not escaped (SIMD search).
                i += 1;
                loop {
                    match memchr::memchr2(b'"', b'\\', &text[i..]) {
                        Some(k) if text[i + k] == b'\\' => i = (i + k + 2).min(text.len()),
                        Some(k) => {
                            i += k + 1;
                            break;
                        }
                        None => return Ok(()),
                    }
                }
                continue;
            }
            b'[' | b'{' => {
                depth += 1;
                if depth > MAX_JSON_DEPTH {
                    return Err(too_deep(text, i));
                }
            }
            _ => depth = depth.saturating_sub(1),
        }
        i += 1;
    }
    Ok(())
}

#[cfg(test)]
mod depth_scan_tests {
    use super::check_json_depth;

    #[test]
    fn strings_escapes_and_ends_are_scanned_without_a_panic() {
        assert!(check_json_depth(br#"{"a": "[[[", "b": "\"[", "c": [1]}"#).is_ok());
        assert!(check_json_depth(b"\"abc\\").is_ok());
        assert!(check_json_depth(b"\"\\").is_ok());
        let deep = "[".repeat(101);
        assert!(check_json_depth(deep.as_bytes()).is_err());
        let quoted = format!("\"{deep}\"");
        assert!(check_json_depth(quoted.as_bytes()).is_ok());
    }
}

/// The bytes that open strings, lists and objects, or close lists and objects.
const STRUCTURAL: [bool; 256] = {
    let mut table = [false; 256];
    table[b'"' as usize] = true;
    table[b'[' as usize] = true;
    table[b']' as usize] = true;
    table[b'{' as usize] = true;
    table[b'}' as usize] = true;
    table
};

/// The error for nesting past [`MAX_JSON_DEPTH`] at byte `i`, with its line and column.
fn too_deep(text: &[u8], i: usize) -> FormatError {
    let before = &text[..i];
    let line = before.iter().filter(|&&c| c == b'\n').count() + 1;
    let line_start = before
        .iter()
        .rposition(|&c| c == b'\n')
        .map_or(0, |p| p + 1);
    // Columns count bytes from 1, as serde_json's do.
    let column = i - line_start + 1;
    FormatError::new(format!(
        "nesting deeper than {MAX_JSON_DEPTH} levels at line {line}, column {column}"
    ))
}

/// A problem with a scene file: what is wrong and, in the message, where.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FormatError {
    /// What is wrong, naming the field (`objects[3].size[1] must be > 0`).
    pub message: String,
}

impl FormatError {
    /// An error with this message.
    pub fn new(message: impl Into<String>) -> Self {
        Self {
            message: message.into(),
        }
    }

    /// The same error, prefixed with the file it is about.
    pub fn in_file(self, path: &Path) -> Self {
        Self::new(format!("{}: {}", path.display(), self.message))
    }
}

impl fmt::Display for FormatError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for FormatError {}

/// Why a file a scene points to is not read ([`file_inside`]).
#[derive(Debug)]
pub(crate) enum NotInside {
    /// It does not exist (or its path cannot be resolved).
    Missing,
    /// It resolves (through `..` or a link) to outside the folder.
    Outside,
    /// Its metadata cannot be read.
    Unreadable(std::io::Error),
    /// A folder, device or pipe.
    NotAFile,
    /// Larger than [`gltf::MAX_RESOURCE_BYTES`].
    TooLarge,
}

/// Whether `path` is a regular file inside the folder `real_base` (canonical) of at most
/// [`gltf::MAX_RESOURCE_BYTES`]: the one check for the files other files point to (glTF
/// buffers and images, USD sublayers, references and payloads).
pub(crate) fn file_inside(path: &Path, real_base: &Path) -> Result<(), NotInside> {
    let real = path.canonicalize().map_err(|_| NotInside::Missing)?;
    if !real.starts_with(real_base) {
        return Err(NotInside::Outside);
    }
    let meta = std::fs::metadata(&real).map_err(NotInside::Unreadable)?;
    if !meta.is_file() {
        return Err(NotInside::NotAFile);
    }
    if meta.len() > gltf::MAX_RESOURCE_BYTES {
        return Err(NotInside::TooLarge);
    }
    Ok(())
}

/// The formats Shenlong reads and writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Shenlong's scene JSON (SPEC §2).
    SceneJson,
    /// glTF 2.0 as JSON with external or embedded buffers.
    Gltf,
    /// glTF 2.0 binary.
    Glb,
    /// ThreeDWorld commands placing the objects (`.tdw.json`, write only).
    TdwCommands,
    /// A USD stage as text (`.usda`).
    Usda,
    /// A USD stage as a binary crate (`.usdc`, `.usd`).
    Usdc,
    /// A USD package (`.usdz`, read only).
    Usdz,
}

fn name_ends_with(path: &Path, suffix: &str) -> bool {
    path.file_name()
        .and_then(|n| n.to_str())
        .is_some_and(|n| n.to_ascii_lowercase().ends_with(suffix))
}

impl Format {
    /// The format a path's extension names.
    pub fn from_path(path: &Path) -> Result<Self, FormatError> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .unwrap_or_default();
        match ext.as_str() {
            "json" if name_ends_with(path, ".tdw.json") => Ok(Format::TdwCommands),
            "json" => Ok(Format::SceneJson),
            "jsonl" => Err(FormatError::new(format!(
                "{}: unknown scene format '.jsonl': a file of ProcTHOR/Holodeck houses is imported as houses, with their asset database",
                path.display()
            ))),
            "gltf" => Ok(Format::Gltf),
            "glb" => Ok(Format::Glb),
            "usda" => Ok(Format::Usda),
            "usdc" | "usd" => Ok(Format::Usdc),
            "usdz" => Ok(Format::Usdz),
            other => Err(FormatError::new(format!(
                "{}: unknown scene format '.{other}': use .json, .gltf, .glb, .usda, .usdc or .usdz",
                path.display()
            ))),
        }
    }
}

/// Where a scene came from, kept for writing it back.
#[derive(Clone, Debug)]
pub enum Document {
    /// Built in memory: written fresh.
    None,
    /// A scene JSON document.
    SceneJson(json::JsonDocument),
    /// A glTF document.
    Gltf(Box<gltf::GltfDocument>),
    /// A USD stage.
    #[cfg(feature = "usd")]
    Usd(Box<usd::UsdDocument>),
}

/// A scene and the document it was read from.
#[derive(Clone, Debug)]
pub struct SceneFile {
    /// The scene.
    pub scene: Scene,
    /// The source document.
    pub document: Document,
    /// The file it was read from, if any.
    pub path: Option<PathBuf>,
}

impl SceneFile {
    /// Reads a scene file, choosing the format by extension.
    pub fn load(path: &Path) -> Result<Self, FormatError> {
        Self::load_with(path, &ReadOptions::default())
    }

    /// Reads a scene file, choosing the format by extension, with the units and front
    /// axis a glTF or USD file is to be read with.
    ///
    /// # Errors
    /// As [`SceneFile::load`]; and options given for a format that takes none (scene JSON
    /// is in metres and says its fronts).
    pub fn load_with(path: &Path, options: &ReadOptions) -> Result<Self, FormatError> {
        let format = Format::from_path(path)?;
        let node_based = matches!(
            format,
            Format::Gltf | Format::Glb | Format::Usda | Format::Usdc | Format::Usdz
        );
        if !node_based && (options.units.is_some() || options.front.is_some()) {
            return Err(FormatError::new(format!(
                "{}: units and a front axis are given for glTF and USD files only (scene JSON is in metres and names its fronts)",
                path.display()
            )));
        }
        let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("scene");
        match format {
            Format::SceneJson => {
                let text =
                    crate::io::read_text_limited(path, crate::io::MAX_READ_BYTES).map_err(|e| {
                        FormatError::new(format!("cannot read {}: {e}", path.display()))
                    })?;
                let loaded = json::read_string(text, stem).map_err(|e| {
                    // (Read again on this error path only: the text went into the document.)
                    let house = crate::io::read_text_limited(path, crate::io::MAX_READ_BYTES)
                        .ok()
                        .and_then(|t| serde_json::from_str::<serde_json::Value>(&t).ok())
                        .is_some_and(|v| procthor::looks_like_house(&v));
                    if house {
                        FormatError::new(format!(
                            "{}: this is a ProcTHOR/Holodeck house, not a scene file: import it as a house, with its asset database",
                            path.display()
                        ))
                    } else {
                        e.in_file(path)
                    }
                })?;
                Ok(Self {
                    scene: loaded.scene,
                    document: Document::SceneJson(loaded.document),
                    path: Some(path.to_path_buf()),
                })
            }
            Format::TdwCommands => Err(FormatError::new(format!(
                "{}: ThreeDWorld commands are an output format; read the scene they came from",
                path.display()
            ))),
            Format::Gltf | Format::Glb => {
                let (scene, document) = gltf::read(path, options).map_err(|e| e.in_file(path))?;
                Ok(Self {
                    scene,
                    document: Document::Gltf(Box::new(document)),
                    path: Some(path.to_path_buf()),
                })
            }
            #[cfg(feature = "usd")]
            Format::Usda | Format::Usdc | Format::Usdz => {
                let (scene, document) = usd::read(path, options).map_err(|e| e.in_file(path))?;
                Ok(Self {
                    scene,
                    document: Document::Usd(Box::new(document)),
                    path: Some(path.to_path_buf()),
                })
            }
            #[cfg(not(feature = "usd"))]
            Format::Usda | Format::Usdc | Format::Usdz => Err(FormatError::new(format!(
                "{}: this build of Shenlong reads no USD (built without the `usd` feature)",
                path.display()
            ))),
        }
    }

    /// Imports house number `index` of a ProcTHOR/Holodeck file (`.json`, or `.jsonl` with
    /// one house a line), with object sizes from the asset database.
    pub fn load_house(
        path: &Path,
        index: usize,
        assets: &procthor::AssetDatabase,
    ) -> Result<Self, FormatError> {
        let document = procthor::read_file(path, index, assets)?;
        let name = document["name"].as_str().unwrap_or("house").to_string();
        let (scene, document) =
            json::scene_from_value(&document, &name).map_err(|e| e.in_file(path))?;
        Ok(Self {
            scene,
            document: Document::SceneJson(document),
            path: Some(path.to_path_buf()),
        })
    }

    /// The ThreeDWorld object id of each object: its `tdw_id` field in a scene-JSON
    /// document, else its position in the scene counting from 1.
    pub fn tdw_ids(&self) -> Vec<i64> {
        (0..self.scene.objects.len())
            .map(|i| {
                let field = match &self.document {
                    Document::SceneJson(document) => document.object_field(i, "tdw_id"),
                    _ => None,
                };
                field
                    .as_ref()
                    .and_then(serde_json::Value::as_i64)
                    .unwrap_or(i as i64 + 1)
            })
            .collect()
    }

    /// The scene in the given format, as bytes.
    pub fn to_bytes(&self, format: Format) -> Result<Vec<u8>, FormatError> {
        self.bytes_for(format, None)
    }

    /// The scene in the given format, as bytes to be written in the folder `target`
    /// (a USD stage's relative asset paths are made to resolve from there).
    fn bytes_for(&self, format: Format, target: Option<&Path>) -> Result<Vec<u8>, FormatError> {
        match format {
            Format::SceneJson => {
                let original = match &self.document {
                    Document::SceneJson(v) => Some(v),
                    _ => None,
                };
                Ok(json::write(&self.scene, original).into_bytes())
            }
            Format::TdwCommands => {
                let commands = tdw::place_all(&self.scene, &self.tdw_ids());
                Ok(pretty::to_string(&serde_json::Value::Array(commands)).into_bytes())
            }
            Format::Gltf | Format::Glb => {
                let Document::Gltf(document) = &self.document else {
                    // A scene from elsewhere: a new glTF of boxes.
                    return gltf_new::write_new(&self.scene, format == Format::Glb);
                };
                let source_is_glb = *document.container() == gltf::Container::Glb;
                if source_is_glb != (format == Format::Glb) {
                    return Err(FormatError::new(format!(
                        "the source is {}; write the edit to a {} file",
                        if source_is_glb {
                            "binary glTF"
                        } else {
                            "glTF JSON"
                        },
                        if source_is_glb { ".glb" } else { ".gltf" }
                    )));
                }
                gltf::write(&self.scene, document)
            }
            Format::Usda | Format::Usdc | Format::Usdz => self.usd_bytes(format, target),
        }
    }

    /// The edited stage in a USD container.
    #[cfg(feature = "usd")]
    fn usd_bytes(&self, format: Format, target: Option<&Path>) -> Result<Vec<u8>, FormatError> {
        let Document::Usd(document) = &self.document else {
            // A scene from elsewhere: a new stage of boxes.
            return match format {
                Format::Usda => Ok(usd::write_new(&self.scene)),
                _ => Err(FormatError::new(
                    "a scene read from no USD stage is written as a new .usda",
                )),
            };
        };
        let container = match format {
            Format::Usda => usd::UsdContainer::Usda,
            Format::Usdc => usd::UsdContainer::Usdc,
            _ => usd::UsdContainer::Usdz,
        };
        usd::write(&self.scene, document, container, target)
    }

    #[cfg(not(feature = "usd"))]
    fn usd_bytes(&self, _format: Format, _target: Option<&Path>) -> Result<Vec<u8>, FormatError> {
        Err(FormatError::new(
            "this build of Shenlong writes no USD (built without the `usd` feature)",
        ))
    }

    /// Writes the edit as a USD layer at `path` (`.usda`) that sublayers the stage it was
    /// read from and holds only `over`s of the edited prims — USD's non-destructive way —
    /// atomically.
    ///
    /// # Errors
    /// The scene was not read from a USD stage, `path` is no `.usda`, or it cannot be
    /// written.
    #[cfg(feature = "usd")]
    pub fn save_usd_layer(&self, path: &Path) -> Result<(), FormatError> {
        let Document::Usd(document) = &self.document else {
            return Err(FormatError::new(
                "a USD layer is written over a USD stage: the scene was not read from one",
            ));
        };
        if Format::from_path(path)? != Format::Usda {
            return Err(FormatError::new(format!(
                "{}: a layer is written as .usda",
                path.display()
            )));
        }
        let sublayer = usd::sublayer_path(&document.source, path)?;
        let bytes = usd::write_layer(&self.scene, document, &sublayer)?;
        crate::io::write_atomic(path, &bytes)
            .map_err(|e| FormatError::new(format!("cannot write {}: {e}", path.display())))
    }

    /// Writes the scene to `path` (format by extension) atomically: on any error the
    /// file is not created or changed. A `.gltf` written in another folder than its source
    /// gets copies of its buffers and images beside it, under names Shenlong makes
    /// (`resources`), all or nothing.
    pub fn save(&self, path: &Path) -> Result<(), FormatError> {
        let format = Format::from_path(path)?;
        if path.is_dir() {
            return Err(FormatError::new(format!(
                "cannot write {}: it is a folder",
                path.display()
            )));
        }
        if let (Format::Gltf, Document::Gltf(document)) = (format, &self.document) {
            if let Some(copies) = resources::plan(document, path)? {
                let bytes = gltf::write_relocated(&self.scene, document, &copies.uris)?;
                return resources::write_all(&copies, path, &bytes);
            }
        }
        let folder = match path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        if !folder.is_dir() {
            return Err(FormatError::new(format!(
                "cannot write {}: the folder {} does not exist",
                path.display(),
                folder.display()
            )));
        }
        let bytes = self.bytes_for(format, Some(folder))?;
        crate::io::write_atomic(path, &bytes)
            .map_err(|e| FormatError::new(format!("cannot write {}: {e}", path.display())))
    }
}

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
    FormatError::too_large(format!(
        "nesting deeper than {MAX_JSON_DEPTH} levels at line {line}, column {column}"
    ))
}

/// A problem with a scene file: what is wrong and where.
///
/// The kind is data; the message names the field or the line (`objects[3].size[1] must
/// be > 0`), so the one line printed is enough to find and fix it. Errors from the file
/// system keep theirs as the [source](std::error::Error::source).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum FormatError {
    /// A file cannot be read.
    #[error("cannot read {}: {source}", path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// Why.
        #[source]
        source: std::io::Error,
    },
    /// A file cannot be written (nothing was written).
    #[error("cannot write {}: {source}", path.display())]
    Write {
        /// The file.
        path: PathBuf,
        /// Why.
        #[source]
        source: std::io::Error,
    },
    /// The text is not well-formed.
    #[error("invalid {what} at line {line}, column {column}: {message}")]
    Syntax {
        /// What it should have been (`JSON`, `glTF JSON`).
        what: &'static str,
        /// 1-based line.
        line: usize,
        /// 1-based column, in bytes.
        column: usize,
        /// What is wrong there.
        message: String,
    },
    /// The content breaks the format's rules (a field missing, out of range, or pointing
    /// at nothing); the message names the field.
    #[error("{0}")]
    Invalid(String),
    /// Past one of the limits that keep reading bounded: size, nesting, count or time.
    #[error("{0}")]
    TooLarge(String),
    /// Not a format, or a use of one, that Shenlong reads or writes here.
    #[error("{0}")]
    Unsupported(String),
    /// The objects are far too large for metres: the file looks modelled in `guess`.
    #[error(
        "its objects are {median:.0} m across (median): it looks modelled in {} rather than metres; read it with units {} (`--units {}`), or `--units m` to keep metres",
        guess.name(),
        guess.short(),
        guess.short()
    )]
    Units {
        /// The median of the objects' largest extents, read as metres.
        median: f64,
        /// The units that bring them nearest furniture sizes.
        guess: Units,
    },
    /// An error in the named file.
    #[error("{}: {source}", path.display())]
    InFile {
        /// The file.
        path: PathBuf,
        /// The error.
        #[source]
        source: Box<FormatError>,
    },
}

impl FormatError {
    /// The same error, naming the file it is about (unless it already does).
    #[must_use]
    pub fn in_file(self, path: &Path) -> Self {
        match self {
            Self::Read { .. } | Self::Write { .. } | Self::InFile { .. } => self,
            other => Self::InFile {
                path: path.to_path_buf(),
                source: Box::new(other),
            },
        }
    }

    /// `path` cannot be read, for `source`.
    #[must_use]
    pub fn read(path: &Path, source: std::io::Error) -> Self {
        Self::Read {
            path: path.to_path_buf(),
            source,
        }
    }

    /// `path` cannot be written, for `source`.
    #[must_use]
    pub fn write(path: &Path, source: std::io::Error) -> Self {
        Self::Write {
            path: path.to_path_buf(),
            source,
        }
    }

    /// The content breaks the format's rules, as `message` says.
    #[must_use]
    pub fn invalid(message: impl Into<String>) -> Self {
        Self::Invalid(message.into())
    }

    /// Past a limit, as `message` says.
    #[must_use]
    pub fn too_large(message: impl Into<String>) -> Self {
        Self::TooLarge(message.into())
    }

    /// Not supported, as `message` says.
    #[must_use]
    pub fn unsupported(message: impl Into<String>) -> Self {
        Self::Unsupported(message.into())
    }

    /// Text that is not `what` (`JSON`, `glTF JSON`), as `serde_json` found it.
    #[must_use]
    pub fn json_syntax(what: &'static str, e: &serde_json::Error) -> Self {
        Self::Syntax {
            what,
            line: e.line(),
            column: e.column(),
            message: strip_position(&e.to_string()),
        }
    }

    /// The error under any [`FormatError::InFile`] wrapping.
    #[must_use]
    pub fn innermost(&self) -> &Self {
        match self {
            Self::InFile { source, .. } => source.innermost(),
            other => other,
        }
    }
}

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

/// A `serde_json` message without its trailing "at line L column C" (said apart).
pub(crate) fn strip_position(message: &str) -> String {
    match message.rfind(" at line ") {
        Some(i) => message[..i].to_string(),
        None => message.to_string(),
    }
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
            "jsonl" => Err(FormatError::unsupported(format!(
                "{}: unknown scene format '.jsonl': a file of ProcTHOR/Holodeck houses is imported as houses, with their asset database",
                path.display()
            ))),
            "gltf" => Ok(Format::Gltf),
            "glb" => Ok(Format::Glb),
            "usda" => Ok(Format::Usda),
            "usdc" | "usd" => Ok(Format::Usdc),
            "usdz" => Ok(Format::Usdz),
            other => Err(FormatError::unsupported(format!(
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
            return Err(FormatError::unsupported(format!(
                "{}: units and a front axis are given for glTF and USD files only (scene JSON is in metres and names its fronts)",
                path.display()
            )));
        }
        let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("scene");
        match format {
            Format::SceneJson => {
                let text = crate::io::read_text_limited(path, crate::io::MAX_READ_BYTES)
                    .map_err(|e| FormatError::read(path, e))?;
                let loaded = json::read_string(text, stem).map_err(|e| {
                    // (Read again on this error path only: the text went into the document.)
                    let house = crate::io::read_text_limited(path, crate::io::MAX_READ_BYTES)
                        .ok()
                        .and_then(|t| serde_json::from_str::<serde_json::Value>(&t).ok())
                        .is_some_and(|v| procthor::looks_like_house(&v));
                    if house {
                        FormatError::unsupported(format!(
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
            Format::TdwCommands => Err(FormatError::unsupported(format!(
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
            Format::Usda | Format::Usdc | Format::Usdz => Err(FormatError::unsupported(format!(
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
                    return Err(FormatError::invalid(format!(
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
                _ => Err(FormatError::invalid(
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
        Err(FormatError::unsupported(
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
            return Err(FormatError::invalid(
                "a USD layer is written over a USD stage: the scene was not read from one",
            ));
        };
        if Format::from_path(path)? != Format::Usda {
            return Err(FormatError::invalid(format!(
                "{}: a layer is written as .usda",
                path.display()
            )));
        }
        let sublayer = usd::sublayer_path(&document.source, path)?;
        let bytes = usd::write_layer(&self.scene, document, &sublayer)?;
        crate::io::write_atomic(path, &bytes).map_err(|e| FormatError::write(path, e))
    }

    /// Writes the scene to `path` (format by extension) atomically: on any error the
    /// file is not created or changed. A `.gltf` written in another folder than its source
    /// gets copies of its buffers and images beside it, under names Shenlong makes
    /// (`resources`), all or nothing.
    pub fn save(&self, path: &Path) -> Result<(), FormatError> {
        let format = Format::from_path(path)?;
        if path.is_dir() {
            return Err(FormatError::write(
                path,
                std::io::Error::other("it is a folder"),
            ));
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
            return Err(FormatError::write(
                path,
                std::io::Error::new(
                    std::io::ErrorKind::NotFound,
                    format!("the folder {} does not exist", folder.display()),
                ),
            ));
        }
        let bytes = self.bytes_for(format, Some(folder))?;
        crate::io::write_atomic(path, &bytes).map_err(|e| FormatError::write(path, e))
    }
}

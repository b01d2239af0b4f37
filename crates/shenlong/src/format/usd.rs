//! USD stages (`.usda`, `.usdc`, `.usdz`): a stage as a scene of separate objects whose
//! transforms Shenlong edits, everything else kept exactly.
//!
//! - **Reading**: a `.usda` that needs no composition is read by Shenlong's own layer
//!   reader ([`layer`]); any other stage is composed by the `openusd` crate. Either runs in
//!   the reading child process, within its time and memory budget ([`sandbox`]). Both are walked alike ([`walk`], [`xform`]).
//! - **Objects** are the prims of kind `component` where the stage uses model kinds; else
//!   the prims directly under the default prim (or under the root when none is set) — each
//!   one that has geometry below it.
//! - **Boxes** come from geometry: `Mesh` (and every point-based prim's) `points`, the
//!   extents of `Cube` (`size`), `Sphere` (`radius`), `Cylinder`, `Cone` and `Capsule`
//!   (`radius`, `height`, `axis`), else an authored `extent`; each through the full
//!   `xformOp` stack of the prim and every ancestor (translate, rotate, orient, scale,
//!   transform, `!invert!`, `!resetXformStack!`), at the default time.
//! - **Frame**: Shenlong's is Y-up metres (SPEC §1). A stage's `upAxis` (Y or Z) and
//!   `metersPerUnit` (USD's fallback, 0.01, when unauthored) map it there exactly: a Z-up
//!   point `(x, y, z)` is `(x, z, −y)`, times metres per unit; and back on writing.
//! - **Writing** changes only the edited prims' transforms: each gets the op stack
//!   `xformOp:translate:shenlong`, `xformOp:orient:shenlong`, `xformOp:scale:shenlong` (or
//!   `xformOp:transform:shenlong` when its new local transform is no translate·rotate·scale)
//!   as its `xformOpOrder`; every other prim, attribute, material, variant and metadata is
//!   kept. Written as `.usda` or `.usdc`; or, with [`write_layer`], as a `.usda` layer that
//!   sublayers the input and holds only `over`s of the edited prims.
//! - **Files** other than the input (sublayers, references, payloads) are read only from
//!   inside the input's folder ([`FolderResolver`]); a `.usda` nested deeper than
//!   [`super::MAX_JSON_DEPTH`] levels and any file over [`MAX_USD_BYTES`] are refused.

use super::FormatError;
use crate::scene::Scene;
use glam::{DMat4, DVec3};
use openusd::ar::{self, Asset, DefaultResolver, ResolvedPath, Resolver};
use openusd::sdf::{self, Value};
use openusd::usd::{Prim, Stage};
use std::path::{Path, PathBuf};
use walk::Source as _;
use xform::Attr;

/// The largest USD file read, and the largest file a stage may pull in: the limit of
/// every file a scene points to.
pub const MAX_USD_BYTES: u64 = super::gltf::MAX_RESOURCE_BYTES;

/// The most prims a stage's walk visits.
const MAX_PRIMS: usize = 4_000_000;

/// Which way is up in a stage.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UpAxis {
    /// +Y, as Shenlong's frame.
    Y,
    /// +Z: a point `(x, y, z)` is Shenlong's `(x, z, −y)`.
    Z,
}

/// How a stage maps to Shenlong's frame: its up axis and metres per unit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StageFrame {
    /// The stage's `upAxis`.
    pub up: UpAxis,
    /// The stage's `metersPerUnit`.
    pub meters_per_unit: f64,
}

impl StageFrame {
    /// The frame read in `units` instead of the stage's `metersPerUnit`, when given.
    #[must_use]
    pub fn in_units(self, units: Option<super::facts::Units>) -> Self {
        Self {
            meters_per_unit: units.map_or(self.meters_per_unit, super::facts::Units::meters),
            ..self
        }
    }

    /// The matrix taking stage coordinates to Shenlong's (a rotation and a uniform scale).
    #[must_use]
    pub fn to_shenlong(self) -> DMat4 {
        let turn = match self.up {
            UpAxis::Y => DMat4::IDENTITY,
            // (x, y, z) → (x, z, −y): −90° about +X.
            UpAxis::Z => DMat4::from_rotation_x(-std::f64::consts::FRAC_PI_2),
        };
        DMat4::from_scale(DVec3::splat(self.meters_per_unit)) * turn
    }
}

/// The file a stage came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UsdContainer {
    /// Text.
    Usda,
    /// Binary crate.
    Usdc,
    /// A zip package.
    Usdz,
}

/// One object of a stage: its prim and its transforms before the edit (stage units,
/// column vectors).
#[derive(Clone, Debug)]
pub struct UsdObject {
    /// The prim's path (`/World/Table`).
    pub path: String,
    /// Its local-to-world transform.
    pub world: DMat4,
    /// Its parent's local-to-world transform (identity for a root prim, or where the prim
    /// resets the transform stack).
    pub parent_world: DMat4,
    /// The object (index into the objects) nearest above it, if any: its motion moves this
    /// one's parent.
    pub ancestor: Option<usize>,
    /// The name Shenlong wrote for it (`shenlong:name`), when the stage is one it made.
    pub name: Option<String>,
    /// Whether it resets the transform stack: its new op order keeps the reset.
    pub resets: bool,
}

/// What writing a stage back needs: where it came from and its objects' prims.
#[derive(Clone, Debug)]
pub struct UsdDocument {
    /// The file read.
    pub source: PathBuf,
    /// Its container.
    pub container: UsdContainer,
    /// The frame it is read in (its `metersPerUnit` replaced by the units the run gave).
    pub frame: StageFrame,
    /// The stage's own `metersPerUnit` (written on a layer over it).
    pub authored_meters_per_unit: f64,
    /// Its default prim, if set.
    pub default_prim: Option<String>,
    /// The objects, in the scene's order.
    pub objects: Vec<UsdObject>,
}

/// Asset paths a resolver refused, each with the reason in words.
pub type Refusals = std::sync::Arc<std::sync::Mutex<Vec<(String, String)>>>;

/// A resolver that reads only inside one folder: sublayers, references and payloads that
/// climb out of it (`../`, an absolute path elsewhere, a link out) or are no regular file
/// of at most [`MAX_USD_BYTES`] resolve to nothing, as glTF URIs do.
pub struct FolderResolver {
    root: PathBuf,
    inner: DefaultResolver,
    /// The asset paths refused, each with why, for the error that names them.
    refused: Refusals,
}

impl FolderResolver {
    /// A resolver for the files inside `folder`.
    ///
    /// # Errors
    /// When the folder cannot be found.
    pub fn new(folder: &Path) -> std::io::Result<Self> {
        let folder = if folder.as_os_str().is_empty() {
            Path::new(".")
        } else {
            folder
        };
        let root = folder.canonicalize()?;
        Ok(Self {
            inner: DefaultResolver::with_search_paths([root.clone()]),
            root,
            refused: std::sync::Arc::default(),
        })
    }

    /// The list the resolver adds each refused asset path to.
    #[must_use]
    pub fn refusals(&self) -> Refusals {
        self.refused.clone()
    }

    /// Whether a resolved path is a regular file inside the folder (a file inside a
    /// package: its package), or why not.
    fn inside(&self, resolved: &ResolvedPath) -> Result<(), super::NotInside> {
        let text = resolved.to_string_lossy();
        let outer = ar::split_package_relative_path_outer(&text)
            .map_or_else(|| text.to_string(), |(package, _)| package);
        super::file_inside(Path::new(&outer), &self.root)
    }
}

impl Resolver for FolderResolver {
    fn create_identifier(&self, asset_path: &str, anchor: Option<&ResolvedPath>) -> String {
        self.inner.create_identifier(asset_path, anchor)
    }

    fn resolve(&self, asset_path: &str) -> Option<ResolvedPath> {
        let resolved = self.inner.resolve(asset_path)?;
        match self.inside(&resolved) {
            Ok(()) => Some(resolved),
            Err(why) => {
                if let Ok(mut list) = self.refused.lock() {
                    list.push((asset_path.to_string(), why_not(&why)));
                }
                None
            }
        }
    }

    fn resolve_for_new_asset(&self, _asset_path: &str) -> Option<ResolvedPath> {
        None
    }

    fn open_asset(&self, resolved_path: &ResolvedPath) -> std::io::Result<Box<dyn Asset>> {
        if let Err(why) = self.inside(resolved_path) {
            return Err(std::io::Error::new(
                std::io::ErrorKind::PermissionDenied,
                why_not(&why),
            ));
        }
        self.inner.open_asset(resolved_path)
    }

    fn identity(&self) -> String {
        format!("shenlong-folder:{}", self.root.display())
    }
}

fn err(message: impl Into<String>) -> FormatError {
    FormatError::invalid(message)
}

/// The container a path's extension names.
fn container_of(path: &Path) -> Result<UsdContainer, FormatError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    match ext.as_str() {
        "usda" => Ok(UsdContainer::Usda),
        "usdc" | "usd" => Ok(UsdContainer::Usdc),
        "usdz" => Ok(UsdContainer::Usdz),
        other => Err(err(format!("'.{other}' is no USD file"))),
    }
}

/// Refuses text nested deeper than [`super::MAX_JSON_DEPTH`] levels of `{ [ (`, before
/// the parser sees it, saying where ([`patch::check_depth`]).
fn check_nesting(text: &str) -> Result<(), FormatError> {
    patch::check_depth(text, super::MAX_JSON_DEPTH)
}

/// A stage opened and walked once.
struct Opened {
    stage: Stage,
    /// Whether any prim of kind `component` is a model (the stage uses model kinds).
    uses_kinds: bool,
}

/// Whether a stage's file is a regular file within [`MAX_USD_BYTES`] (a FIFO, a device or
/// a link to `/dev/zero` is refused before anything is read): its size.
fn check_file(path: &Path) -> Result<u64, FormatError> {
    crate::io::open_limited(path, MAX_USD_BYTES)
        .map(|(_, len)| len)
        .map_err(|e| FormatError::read(path, e))
}

/// Whether a `.usdz` package is as USD makes them: a zip whose files are stored, not
/// compressed (so nothing in it inflates: no zip bomb), each within the package. Reads
/// only its end record and central directory, not the files.
fn check_package(path: &Path) -> Result<(), FormatError> {
    use std::io::{Read, Seek, SeekFrom};
    let cannot = |e: std::io::Error| FormatError::read(path, e);
    let bad = |what: &str| err(format!("not a USD package: {what}"));
    let (mut file, total) = crate::io::open_limited(path, MAX_USD_BYTES).map_err(cannot)?;
    // The end of central directory record: its signature within the last 64 KiB + 22.
    let tail_len = total.min(65_557);
    let mut tail = vec![0u8; usize::try_from(tail_len).unwrap_or(0)];
    file.seek(SeekFrom::End(-(tail_len as i64)))
        .and_then(|_| file.read_exact(&mut tail))
        .map_err(cannot)?;
    let eocd = (0..tail.len().saturating_sub(21))
        .rev()
        .find(|&k| tail[k..k + 4] == [0x50, 0x4b, 0x05, 0x06])
        .ok_or_else(|| bad("no zip directory"))?;
    let u16_at = |b: &[u8], k: usize| -> Option<u64> {
        Some(u64::from(u16::from_le_bytes(
            b.get(k..k + 2)?.try_into().ok()?,
        )))
    };
    let u32_at = |b: &[u8], k: usize| -> Option<u64> {
        Some(u64::from(u32::from_le_bytes(
            b.get(k..k + 4)?.try_into().ok()?,
        )))
    };
    let cut = || bad("a cut or corrupt zip directory");
    let entries = u16_at(&tail, eocd + 10).ok_or_else(cut)?;
    let size = u32_at(&tail, eocd + 12).ok_or_else(cut)?;
    let offset = u32_at(&tail, eocd + 16).ok_or_else(cut)?;
    if offset.saturating_add(size) > total {
        return Err(cut());
    }
    let mut directory = vec![0u8; usize::try_from(size).map_err(|_| cut())?];
    file.seek(SeekFrom::Start(offset))
        .and_then(|_| file.read_exact(&mut directory))
        .map_err(cannot)?;
    let mut at = 0usize;
    for _ in 0..entries {
        let b = directory.as_slice();
        if b.get(at..at + 4) != Some(&[0x50, 0x4b, 0x01, 0x02][..]) {
            return Err(cut());
        }
        let field = |k: usize, four: bool| {
            if four {
                u32_at(b, at + k)
            } else {
                u16_at(b, at + k)
            }
            .ok_or_else(cut)
        };
        let (method, compressed, inflated) =
            (field(10, false)?, field(20, true)?, field(24, true)?);
        if method != 0 {
            return Err(bad(
                "its files are compressed (a .usdz stores them uncompressed), so it is not read",
            ));
        }
        if compressed != inflated || inflated > total {
            return Err(bad("a file in it is larger than the package"));
        }
        let names = field(28, false)? + field(30, false)? + field(32, false)?;
        at += 46 + usize::try_from(names).map_err(|_| cut())?;
    }
    Ok(())
}

/// Opens a stage, reading only inside its folder, and walks it once. The file itself was
/// checked by [`read`] before the reading child began ([`check_file`]).
fn open_stage(path: &Path) -> Result<Opened, FormatError> {
    if container_of(path)? == UsdContainer::Usda {
        let text = crate::io::read_text_limited(path, MAX_USD_BYTES)
            .map_err(|e| FormatError::read(path, e))?;
        check_nesting(&text)?;
    }
    let folder = path.parent().unwrap_or(Path::new("."));
    let resolver = FolderResolver::new(folder).map_err(|e| FormatError::read(folder, e))?;
    let refused = resolver.refusals();
    let real = path
        .canonicalize()
        .map_err(|e| FormatError::read(path, e))?;
    let stage = Stage::builder()
        .resolver(resolver)
        .open(&real.to_string_lossy())
        .map_err(|e| {
            err(one_line(&format!(
                "not a USD stage Shenlong can read: {e:#}"
            )))
        })?;
    // Composition is lazy: walk the stage once so every arc is resolved now. The same
    // walk sees whether the stage uses model kinds: a prim of kind `component` reached
    // through prims with a kind, `Xform`s, `Scope`s or untyped prims (models sit near the
    // top: a component is never under a gprim).
    let mut uses_kinds = false;
    let mut stack = vec![(stage.prim(sdf::Path::abs_root()), true)];
    while let Some((p, on_model_path)) = stack.pop() {
        uses_kinds |= on_model_path && is_component(&p);
        let children = p
            .children()
            .map_err(|e| err(one_line(&format!("{}: {e:#}", p.path()))))?;
        stack.extend(children.into_iter().map(|c| {
            let model_path = on_model_path
                && (c.kind().ok().flatten().is_some()
                    || c.type_name()
                        .ok()
                        .flatten()
                        .is_some_and(|t| matches!(t.as_str(), "Xform" | "Scope" | "")));
            (c, model_path)
        }));
        if refused.lock().is_ok_and(|l| !l.is_empty()) {
            break;
        }
    }
    if let Some((first, why)) = refused.lock().ok().and_then(|l| l.first().cloned()) {
        return Err(err(format!(
            "'{}' {why}",
            first.chars().take(200).collect::<String>()
        )));
    }
    Ok(Opened { stage, uses_kinds })
}

/// The first line of a message, at most 300 characters.
fn one_line(message: &str) -> String {
    let line = message.lines().next().unwrap_or_default();
    line.chars().take(300).collect()
}

/// The stage's frame from its metadata.
fn frame_of(stage: &Stage) -> Result<StageFrame, FormatError> {
    let up = match stage.stage_metadata("upAxis").ok().flatten() {
        None => None,
        Some(Value::Token(t)) => Some(t.as_str().to_string()),
        Some(Value::String(t)) => Some(t),
        Some(other) => return Err(err(format!("upAxis {other:?} is neither \"Y\" nor \"Z\""))),
    };
    let meters_per_unit = match stage.stage_metadata("metersPerUnit").ok().flatten() {
        None => None,
        Some(v) => Some(scalar(&v).ok_or_else(|| err("metersPerUnit is not a number"))?),
    };
    stage_frame(up.as_deref(), meters_per_unit)
}

/// The frame a stage's `upAxis` and `metersPerUnit` give (USD's fallbacks, Y and 0.01,
/// where unauthored).
///
/// # Errors
/// An up axis other than Y or Z; metres per unit outside 1e-9 to 1e9.
fn stage_frame(up: Option<&str>, meters_per_unit: Option<f64>) -> Result<StageFrame, FormatError> {
    let up = match up {
        None | Some("Y") => UpAxis::Y,
        Some("Z") => UpAxis::Z,
        Some(other) => return Err(err(format!("upAxis {other:?} is neither \"Y\" nor \"Z\""))),
    };
    let meters_per_unit = meters_per_unit.unwrap_or(0.01);
    if !(meters_per_unit.is_finite() && (1e-9..=1e9).contains(&meters_per_unit)) {
        return Err(err(format!(
            "metersPerUnit {meters_per_unit} is not a number between 1e-9 and 1e9 (a nanometre and a million kilometres)"
        )));
    }
    Ok(StageFrame {
        up,
        meters_per_unit,
    })
}

fn scalar(v: &Value) -> Option<f64> {
    match v {
        Value::Double(d) => Some(*d),
        Value::Float(f) => Some(f64::from(*f)),
        Value::Half(h) => Some(f64::from(h.to_f32())),
        Value::Int(i) => Some(f64::from(*i)),
        Value::Int64(i) => Some(*i as f64),
        _ => None,
    }
}

/// A USD matrix (row-major, row vectors) as Shenlong's (column vectors).
fn matrix(m: &openusd::gf::Matrix4d) -> DMat4 {
    DMat4::from_cols_array(&m.0)
}

/// Shenlong's matrix as USD's.
fn to_usd_matrix(m: DMat4) -> openusd::gf::Matrix4d {
    openusd::gf::Matrix4d(m.to_cols_array())
}

/// What the writer needs of each prim of the tree.
#[derive(Debug)]
struct PrimInfo {
    /// Whether its op order starts with `!resetXformStack!` (its parent's transform does
    /// not apply to it).
    resets: bool,
    path: String,
    world: DMat4,
    parent_world: DMat4,
}

/// Reads a stage as a scene: objects with their world boxes in Shenlong's frame, chosen,
/// named and put in their room by the step every node-based format shares
/// ([`super::facts`]). The stage is opened and walked in a child process with a time and
/// memory budget ([`sandbox`]), so that no stage can crash or exhaust this one.
///
/// # Errors
/// A file that is no USD stage Shenlong can read, nests too deep or is too large, or whose
/// reading crashed or ran out of time or memory; a stage whose `upAxis` or
/// `metersPerUnit` is unusable; one with no object.
pub fn read(
    path: &Path,
    options: &super::facts::ReadOptions,
) -> Result<(Scene, UsdDocument), FormatError> {
    let container = container_of(path)?;
    let size = check_file(path)?;
    if container == UsdContainer::Usdz {
        check_package(path)?;
    }
    // Either reader runs in the reading child, within its time and memory budget: a few
    // megabytes of prims make gigabytes of tree, which must not be this process's.
    let budget = sandbox::Budget::for_bytes(size);
    let bytes = sandbox::run(budget, || {
        let walked = match own_walk(path, container, options)? {
            Some(walked) => walked,
            None => walk(path, options)?,
        };
        Ok(walked.encode())
    })?;
    let walked = wire::Walked::decode(&bytes)?;
    let frame = walked.frame.in_units(options.units);
    let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("stage");
    let front = match frame.up {
        UpAxis::Y => DVec3::Z,
        UpAxis::Z => DVec3::NEG_Y,
    };
    let derived = super::facts::derive(&walked.tree, stem, front, options)?;
    if derived.scene.objects.is_empty() {
        return Err(err(
            "no object: no prim with geometry under the default prim (or the root)",
        ));
    }
    let prims = &walked.prims;
    let objects = derived
        .nodes
        .iter()
        .zip(&derived.ancestors)
        .map(|(&n, &ancestor)| UsdObject {
            path: prims[n].path.clone(),
            world: prims[n].world,
            parent_world: prims[n].parent_world,
            ancestor,
            name: walked.tree.nodes[n].given_name.clone(),
            resets: prims[n].resets,
        })
        .collect();
    let document = UsdDocument {
        source: path.to_path_buf(),
        container,
        frame,
        authored_meters_per_unit: walked.frame.meters_per_unit,
        default_prim: walked.default_prim,
        objects,
    };
    Ok((derived.scene, document))
}

/// A `.usda` that needs no composition, read and walked by Shenlong's own reader in this
/// process ([`layer`]); `None` for any other stage (the composing reader's, [`walk`]).
///
/// # Errors
/// The file cannot be read, or nests too deep, holds too many prims or an unusable frame.
fn own_walk(
    path: &Path,
    container: UsdContainer,
    options: &super::facts::ReadOptions,
) -> Result<Option<wire::Walked>, FormatError> {
    if container != UsdContainer::Usda {
        return Ok(None);
    }
    let text = crate::io::read_text_limited(path, MAX_USD_BYTES)
        .map_err(|e| FormatError::read(path, e))?;
    let parsed = layer::read(&text, MAX_PRIMS)?;
    drop(text);
    match parsed {
        layer::Parsed::Layer(layer) => walk_layer(&layer, options),
        layer::Parsed::Compose => Ok(None),
    }
}

/// Opens a stage and walks its prims, parents first: the tree the shared reading step
/// needs, what writing needs of each prim, the frame as authored and the default prim.
/// Runs in the reading child process ([`sandbox`]).
fn walk(path: &Path, options: &super::facts::ReadOptions) -> Result<wire::Walked, FormatError> {
    let Opened { stage, uses_kinds } = open_stage(path)?;
    let authored = frame_of(&stage)?;
    let default_prim = stage.default_prim().map(|t| t.as_str().to_string());
    // The walk starts at the default prim (a group such as `/World` is recognised as
    // one), else at the root's children.
    let starts: Vec<walk::Visit<Prim>> = match &default_prim {
        Some(name) => {
            let root = stage.prim(format!("/{name}").as_str());
            let parent_world = match root.path().parent() {
                Some(p) if p != sdf::Path::abs_root() => world_of(&stage, &stage.prim(p))?,
                _ => DMat4::IDENTITY,
            };
            vec![walk::Visit {
                prim: root,
                parent_world,
                parent: None,
            }]
        }
        None => stage
            .children(&stage.prim(sdf::Path::abs_root()))?
            .into_iter()
            .map(|prim| walk::Visit {
                prim,
                parent_world: DMat4::IDENTITY,
                parent: None,
            })
            .collect(),
    };
    let (tree, prims) = walk::Walk {
        to_shenlong: authored.in_units(options.units).to_shenlong(),
        uses_kinds,
        max_prims: MAX_PRIMS,
        expected: 0,
    }
    .run(&stage, starts)?;
    Ok(wire::Walked {
        tree,
        prims,
        frame: authored,
        default_prim,
    })
}

/// Walks a layer Shenlong read itself ([`layer`]) as [`walk`] walks a composed stage;
/// `None` when its default prim is none of its root prims (composition says what then).
fn walk_layer(
    layer: &layer::Layer,
    options: &super::facts::ReadOptions,
) -> Result<Option<wire::Walked>, FormatError> {
    let authored = stage_frame(layer.up_axis.as_deref(), layer.meters_per_unit)?;
    let starts: Vec<usize> = match &layer.default_prim {
        Some(name) => {
            let path = format!("/{name}");
            match layer.roots.iter().find(|&&r| layer.prims[r].path == path) {
                Some(&root) => vec![root],
                None => return Ok(None),
            }
        }
        None => layer.roots.clone(),
    };
    let starts = starts
        .into_iter()
        .map(|prim| walk::Visit {
            prim,
            parent_world: DMat4::IDENTITY,
            parent: None,
        })
        .collect();
    let (tree, prims) = walk::Walk {
        to_shenlong: authored.in_units(options.units).to_shenlong(),
        uses_kinds: layer.uses_kinds(),
        max_prims: MAX_PRIMS,
        expected: layer.prims.len(),
    }
    .run(layer, starts)?;
    Ok(Some(wire::Walked {
        tree,
        prims,
        frame: authored,
        default_prim: layer.default_prim.clone(),
    }))
}

/// The composed stage's prims as a walk's source.
impl walk::Source for Stage {
    type Prim = Prim;

    fn children(&self, prim: &Prim) -> Result<Vec<Prim>, FormatError> {
        prim.children()
            .map_err(|e| err(one_line(&format!("{}: {e:#}", prim.path()))))
    }
    fn path(&self, prim: &Prim) -> String {
        prim.path().to_string()
    }
    fn type_name(&self, prim: &Prim) -> String {
        prim.type_name()
            .ok()
            .flatten()
            .map(|t| t.as_str().to_string())
            .unwrap_or_default()
    }
    fn active(&self, prim: &Prim) -> bool {
        prim.is_active().unwrap_or(true)
    }
    fn component(&self, prim: &Prim) -> bool {
        is_component(prim)
    }
    fn attr(&self, prim: &Prim, name: &str) -> Option<Attr> {
        prim.attribute(name)
            .get::<Value>()
            .ok()
            .flatten()
            .and_then(attr_of)
    }
}

/// Whether a prim is a model of kind `component` (or a kind derived from it).
fn is_component(prim: &Prim) -> bool {
    prim.kind()
        .ok()
        .flatten()
        .is_some_and(|k| k.as_str() == "component")
}

/// A composed attribute's value as the walk reads it.
fn attr_of(value: Value) -> Option<Attr> {
    let v3 = |x: f64, y: f64, z: f64| DVec3::new(x, y, z);
    Some(match value {
        Value::Double(_) | Value::Float(_) | Value::Half(_) | Value::Int(_) | Value::Int64(_) => {
            Attr::Scalar(scalar(&value)?)
        }
        Value::Vec3d(a) => Attr::Vec3(v3(a.x, a.y, a.z)),
        Value::Vec3f(a) => Attr::Vec3(v3(a.x.into(), a.y.into(), a.z.into())),
        Value::Vec3h(a) => Attr::Vec3(v3(
            a.x.to_f32().into(),
            a.y.to_f32().into(),
            a.z.to_f32().into(),
        )),
        Value::Quatd(q) => Attr::quat(q.w, q.x, q.y, q.z),
        Value::Quatf(q) => Attr::quat(q.w.into(), q.x.into(), q.y.into(), q.z.into()),
        Value::Quath(q) => Attr::quat(
            q.w.to_f32().into(),
            q.x.to_f32().into(),
            q.y.to_f32().into(),
            q.z.to_f32().into(),
        ),
        Value::Matrix4d(m) => Attr::Matrix(Box::new(matrix(&m))),
        Value::Token(t) => Attr::Text(t.as_str().to_string()),
        Value::String(s) => Attr::Text(unescape(&s)),
        Value::TokenVec(v) => Attr::Texts(v.into_iter().map(|t| t.as_str().to_string()).collect()),
        Value::StringVec(v) => Attr::Texts(v),
        Value::TokenListOp(op) => Attr::Texts(
            op.flatten()
                .into_iter()
                .map(|t| t.as_str().to_string())
                .collect(),
        ),
        Value::Vec3fVec(v) => Attr::Points(
            v.iter()
                .map(|p| v3(p.x.into(), p.y.into(), p.z.into()))
                .collect(),
        ),
        Value::Vec3dVec(v) => Attr::Points(v.iter().map(|p| v3(p.x, p.y, p.z)).collect()),
        Value::IntVec(v) => Attr::Ints(v.into_iter().map(i64::from).collect()),
        _ => return None,
    })
}

/// The local-to-world transform of a prim, from the root down.
fn world_of(stage: &Stage, prim: &Prim) -> Result<DMat4, FormatError> {
    let mut chain: Vec<Prim> = Vec::new();
    let mut path = prim.path().clone();
    loop {
        chain.push(stage.prim(path.clone()));
        match path.parent() {
            Some(parent) if parent != sdf::Path::abs_root() => path = parent,
            _ => break,
        }
    }
    let mut world = DMat4::IDENTITY;
    for p in chain.iter().rev() {
        let (local, resets) =
            xform::local_transform(&|name| stage.attr(p, name), &p.path().to_string())?;
        world = if resets { local } else { world * local };
    }
    Ok(world)
}

/// The new local transform of each object that moved (stage units, column vectors).
fn new_locals(scene: &Scene, document: &UsdDocument) -> Result<Vec<Option<DMat4>>, FormatError> {
    if scene.objects.len() != document.objects.len() {
        return Err(err("the scene's objects no longer match the stage's prims"));
    }
    let c = document.frame.to_shenlong();
    let c_inv = c.inverse();
    // Each object's world motion, in stage units.
    let deltas: Vec<Option<DMat4>> = scene
        .objects
        .iter()
        .map(|o| super::transform::world_motion(o).map(|m| c_inv * m * c))
        .collect();
    let mut out = vec![None; deltas.len()];
    for (k, object) in document.objects.iter().enumerate() {
        let parent_delta = object.ancestor.and_then(|a| deltas[a]);
        if deltas[k].is_none() && parent_delta.is_none() {
            continue;
        }
        let new_world = deltas[k].unwrap_or(DMat4::IDENTITY) * object.world;
        let new_parent = parent_delta.unwrap_or(DMat4::IDENTITY) * object.parent_world;
        if new_parent.determinant().abs() < 1e-300 {
            return Err(err(format!(
                "{}: its parent's transform cannot be inverted",
                object.path
            )));
        }
        let local = new_parent.inverse() * new_world;
        let old_local = object.parent_world.inverse() * object.world;
        if !super::transform::nearly_equal(&local, &old_local, 1e-12) {
            out[k] = Some(local);
        }
    }
    Ok(out)
}

/// The ops that write a local transform: translate, orient, scale when it is one; else
/// one matrix.
fn ops_for(local: DMat4) -> Vec<(String, &'static str, Value)> {
    let trs = super::transform::as_trs(&local).filter(|(scale, _, _)| scale.min_element() > 0.0);
    if let Some((scale, rotation, translation)) = trs {
        vec![
            (
                "xformOp:translate:shenlong".to_string(),
                "double3",
                Value::Vec3d(openusd::gf::Vec3d {
                    x: translation.x,
                    y: translation.y,
                    z: translation.z,
                }),
            ),
            (
                "xformOp:orient:shenlong".to_string(),
                "quatd",
                Value::Quatd(openusd::gf::Quatd {
                    w: rotation.w,
                    x: rotation.x,
                    y: rotation.y,
                    z: rotation.z,
                }),
            ),
            (
                "xformOp:scale:shenlong".to_string(),
                "double3",
                Value::Vec3d(openusd::gf::Vec3d {
                    x: scale.x,
                    y: scale.y,
                    z: scale.z,
                }),
            ),
        ]
    } else {
        vec![(
            "xformOp:transform:shenlong".to_string(),
            "matrix4d",
            Value::Matrix4d(to_usd_matrix(local)),
        )]
    }
}

/// The edited stage in `container`, to be written in the folder `target` (when known):
/// for a `.usda` source, its root layer's text with only the edited prims' transform lines
/// changed ([`patch`]) and, written in another folder, its relative asset paths made to
/// resolve from there; for a `.usdc` or `.usdz` source, a `.usda` layer over it
/// ([`write_layer`]). `.usdc` is not written. An unchanged stage written in its own
/// container and folder is the same bytes.
///
/// # Errors
/// `.usdc` or `.usdz` asked for, or the source cannot be read again.
pub fn write(
    scene: &Scene,
    document: &UsdDocument,
    container: UsdContainer,
    target: Option<&Path>,
) -> Result<Vec<u8>, FormatError> {
    let locals = new_locals(scene, document)?;
    let source_folder = match document.source.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let same_folder = target.is_none_or(|t| same_dir(t, source_folder));
    if locals.iter().all(Option::is_none) && container == document.container && same_folder {
        return std::fs::read(&document.source).map_err(|e| FormatError::read(&document.source, e));
    }
    if container != UsdContainer::Usda {
        return Err(FormatError::unsupported(
            "Shenlong writes USD edits as .usda text: write the edit to a .usda file (or as a layer over the stage with --usd-layer)",
        ));
    }
    if document.container != UsdContainer::Usda {
        let real = document
            .source
            .canonicalize()
            .map_err(|e| err(format!("cannot find the source: {e}")))?;
        let folder = target
            .map(|t| {
                t.canonicalize()
                    .map_err(|e| err(format!("cannot find the folder {}: {e}", t.display())))
            })
            .transpose()?;
        return write_layer(scene, document, &source_name(&real, folder.as_deref()));
    }
    let text = std::fs::read_to_string(&document.source)
        .map_err(|e| FormatError::read(&document.source, e))?;
    let edits: Vec<(String, patch::Ops)> = document
        .objects
        .iter()
        .zip(&locals)
        .filter_map(|(o, l)| l.map(|l| (o.path.clone(), ops_text(&ops_for(l), o.resets))))
        .collect();
    let from = source_folder
        .canonicalize()
        .map_err(|e| err(format!("cannot find the stage's folder: {e}")))?;
    let to = match target {
        Some(t) if !same_folder => Some(
            t.canonicalize()
                .map_err(|e| err(format!("cannot find the folder {}: {e}", t.display())))?,
        ),
        _ => None,
    };
    let moves = to.map(|to| patch::Move { from, to });
    patch::patch(&text, &edits, moves.as_ref()).map(String::into_bytes)
}

/// Whether two folders are the same one.
fn same_dir(a: &Path, b: &Path) -> bool {
    let norm = |p: &Path| {
        let p = if p.as_os_str().is_empty() {
            Path::new(".")
        } else {
            p
        };
        p.canonicalize().ok()
    };
    matches!((norm(a), norm(b)), (Some(x), Some(y)) if x == y)
}

/// The ops as usda statements: (name, type, value text); first, for a prim that resets
/// the transform stack, the reset (named in the order, no statement of its own).
fn ops_text(ops: &[(String, &'static str, Value)], resets: bool) -> patch::Ops {
    let reset = resets.then(|| (patch::RESET.to_string(), "", String::new()));
    reset
        .into_iter()
        .chain(ops.iter().map(|(n, t, v)| (n.clone(), *t, usda_value(v))))
        .collect()
}

/// The edit as a `.usda` layer that sublayers the input (by `sublayer`, the path written
/// for it) and holds only `over`s of the edited prims with their new op stacks, and the
/// stage metadata a root layer must carry (`upAxis`, `metersPerUnit`, `defaultPrim`).
///
/// # Errors
/// As [`write`].
pub fn write_layer(
    scene: &Scene,
    document: &UsdDocument,
    sublayer: &str,
) -> Result<Vec<u8>, FormatError> {
    let locals = new_locals(scene, document)?;
    let mut text = String::from("#usda 1.0\n(\n");
    text.push_str("    doc = \"An edit by Shenlong, over the layer below\"\n");
    if let Some(d) = &document.default_prim {
        text.push_str(&format!("    defaultPrim = \"{}\"\n", escape(d)));
    }
    text.push_str(&format!(
        "    metersPerUnit = {}\n",
        number(document.authored_meters_per_unit)
    ));
    if sublayer.contains('@') {
        return Err(err(format!(
            "the stage's path '{sublayer}' holds an '@', which a layer cannot name it by; move or rename it"
        )));
    }
    text.push_str(&format!("    subLayers = [\n        @{sublayer}@\n    ]\n"));
    text.push_str(&format!(
        "    upAxis = \"{}\"\n)\n",
        match document.frame.up {
            UpAxis::Y => "Y",
            UpAxis::Z => "Z",
        }
    ));
    // A tree of `over`s: each edited prim under the overs of its ancestors.
    let mut tree = patch::Overs::default();
    for (object, local) in document.objects.iter().zip(&locals) {
        if let Some(local) = local {
            tree.insert(&object.path, ops_text(&ops_for(*local), object.resets));
        }
    }
    tree.write(&mut text, "");
    Ok(text.into_bytes())
}

/// How a layer written at `layer` names the stage it sublayers (`source`): `./name` beside
/// it, else the source's absolute path.
///
/// # Errors
/// The layer would replace its own source, or the source cannot be found.
pub fn sublayer_path(source: &Path, layer: &Path) -> Result<String, FormatError> {
    let real = source
        .canonicalize()
        .map_err(|e| err(format!("cannot find {}: {e}", source.display())))?;
    let folder = layer
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let layer_folder = folder
        .canonicalize()
        .map_err(|e| err(format!("cannot find the folder {}: {e}", folder.display())))?;
    let name = layer.file_name().map(|n| layer_folder.join(n));
    // Where the layer would really be written: through a link, the file it names.
    let target = layer.canonicalize().ok().or(name);
    if target.as_deref() == Some(real.as_path()) {
        return Err(err(
            "a layer over a stage cannot replace the stage itself: write it to another file",
        ));
    }
    Ok(source_name(&real, Some(&layer_folder)))
}

/// How a layer in the folder `layer_folder` names the stage `real` it sublayers (both
/// canonical): `./name` beside it, else its absolute path.
fn source_name(real: &Path, layer_folder: Option<&Path>) -> String {
    match (real.parent(), real.file_name().and_then(|n| n.to_str())) {
        (Some(parent), Some(file)) if Some(parent) == layer_folder => format!("./{file}"),
        _ => real.to_string_lossy().into_owned(),
    }
}

/// A new `.usda` stage of the scene, for a scene read from no USD stage (`shenlong
/// convert room.json room.usda`): Y-up, metres, under the default prim `/World`, each
/// object an `Xform` at its pivot with its turn and scale, holding a `Cube` of its box (a
/// box of points — a glTF mesh — as its world box), its name in `shenlong:name`, a front
/// other than +Z in `shenlong:front` and its category in `shenlong:category`; the room's
/// bounds as slabs reading recognises (`Room_Floor`, `Room_Wall_…`, `Room_Ceiling`).
/// Prim names are the objects' names made identifiers (`coffee table` → `coffee_table`,
/// unique).
#[must_use]
pub fn write_new(scene: &Scene) -> Vec<u8> {
    let mut text = String::from(
        "#usda 1.0\n(\n    defaultPrim = \"World\"\n    doc = \"Written by Shenlong\"\n    metersPerUnit = 1\n    upAxis = \"Y\"\n)\n\ndef Xform \"World\"\n{\n",
    );
    let mut names = Identifiers::default();
    for object in &scene.objects {
        let name = names.make(&object.name);
        let (pose, size) = super::transform::box_pose(object);
        let t = pose.translation;
        let q = pose.rotation;
        text.push_str(&format!(
            "    def Xform \"{name}\"\n    {{\n        custom string shenlong:name = \"{}\"\n",
            escape(&object.name)
        ));
        if (object.front - DVec3::Z).length() > 1e-12 {
            let f = object.front;
            text.push_str(&format!(
                "        custom double3 shenlong:front = ({}, {}, {})\n",
                number(f.x),
                number(f.y),
                number(f.z)
            ));
        }
        if let Some(category) = &object.labels.category {
            text.push_str(&format!(
                "        custom string shenlong:category = \"{}\"\n",
                escape(category)
            ));
        }
        text.push_str(&format!(
            "        double3 xformOp:translate = ({}, {}, {})\n        quatd xformOp:orient = ({}, {}, {}, {})\n        double3 xformOp:scale = ({s}, {s}, {s})\n        uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:orient\", \"xformOp:scale\"]\n\n",
            number(t.x), number(t.y), number(t.z),
            number(q.w), number(q.x), number(q.y), number(q.z),
            s = number(pose.scale),
        ));
        text.push_str(&cube(
            "Box",
            "        ",
            DVec3::new(0.0, size.y / 2.0, 0.0),
            size,
        ));
        text.push_str("    }\n\n");
    }
    for (name, slab) in scene
        .bounds
        .as_ref()
        .map(super::facts::room_slabs)
        .unwrap_or_default()
    {
        let name = names.make(name);
        text.push_str(&cube(&name, "    ", slab.center(), slab.size()));
        text.push('\n');
    }
    text.push_str("}\n");
    text.into_bytes()
}

/// A `Cube` prim scaled to `size` and centred at `centre`, at `pad`.
fn cube(name: &str, pad: &str, centre: DVec3, size: DVec3) -> String {
    format!(
        "{pad}def Cube \"{name}\"\n{pad}{{\n{pad}    double size = 1\n{pad}    double3 xformOp:translate = ({}, {}, {})\n{pad}    double3 xformOp:scale = ({}, {}, {})\n{pad}    uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:scale\"]\n{pad}}}\n",
        number(centre.x),
        number(centre.y),
        number(centre.z),
        number(size.x),
        number(size.y),
        number(size.z),
    )
}

/// USD prim names made from object names: letters, digits and `_`, not starting with a
/// digit, each unique (a number appended where two names become one). Each name costs a
/// hash look-up or a few, however many names collide.
#[derive(Default)]
struct Identifiers {
    used: std::collections::HashSet<String>,
    /// Per base, the next number to try.
    next: std::collections::HashMap<String, usize>,
}

impl Identifiers {
    fn make(&mut self, name: &str) -> String {
        let mut base: String = name
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
            .collect();
        if base.is_empty() || base.starts_with(|c: char| c.is_ascii_digit()) {
            base.insert(0, '_');
        }
        let mut candidate = base.clone();
        let mut k = self.next.get(&base).copied().unwrap_or(2);
        while self.used.contains(&candidate) {
            candidate = format!("{base}_{k}");
            k += 1;
        }
        self.next.insert(base, k);
        self.used.insert(candidate.clone());
        candidate
    }
}

/// A string for a usda quoted string.
fn escape(s: &str) -> String {
    s.replace('\\', "\\\\").replace('"', "\\\"")
}

/// A usda string's text as written, its escapes undone (the USD crate keeps them): what
/// [`escape`] wrote reads back as it was.
fn unescape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut chars = s.chars();
    while let Some(c) = chars.next() {
        if c != '\\' {
            out.push(c);
            continue;
        }
        match chars.next() {
            Some('n') => out.push('\n'),
            Some('t') => out.push('\t'),
            Some(other) => out.push(other),
            None => out.push('\\'),
        }
    }
    out
}

/// A number as usda writes it: shortest round-trip form.
fn number(x: f64) -> String {
    let s = format!("{x:?}");
    s.strip_suffix(".0").map_or(s.clone(), str::to_string)
}

/// A computed number as short as it can be written while within `1e-12 × scale` of it
/// (so rounding noise such as `-1.8369701987210297e-16` or `0.30000000000000004` does not
/// reach the file): 0 below that, else the fewest significant digits that stay within.
fn clean(x: f64, scale: f64) -> String {
    let tolerance = 1e-12 * scale.abs().max(x.abs()).max(f64::MIN_POSITIVE);
    if x.abs() <= tolerance {
        return "0".to_string();
    }
    for digits in 1..=17 {
        let text = format!("{x:.*e}", digits - 1);
        if let Ok(y) = text.parse::<f64>() {
            if (y - x).abs() <= tolerance {
                return number(y);
            }
        }
    }
    number(x)
}

/// An op's value as usda text.
fn usda_value(v: &Value) -> String {
    match v {
        Value::Vec3d(a) => {
            let scale = a.x.abs().max(a.y.abs()).max(a.z.abs()).max(1.0);
            format!(
                "({}, {}, {})",
                clean(a.x, scale),
                clean(a.y, scale),
                clean(a.z, scale)
            )
        }
        Value::Quatd(q) => format!(
            "({}, {}, {}, {})",
            clean(q.w, 1.0),
            clean(q.x, 1.0),
            clean(q.y, 1.0),
            clean(q.z, 1.0)
        ),
        Value::Matrix4d(m) => {
            let rows: Vec<String> =
                m.0.chunks(4)
                    .map(|r| {
                        format!(
                            "({}, {}, {}, {})",
                            number(r[0]),
                            number(r[1]),
                            number(r[2]),
                            number(r[3])
                        )
                    })
                    .collect();
            format!("( {} )", rows.join(", "))
        }
        _ => String::new(),
    }
}

/// For the fuzz target: the code of Shenlong's own that reads a stage's bytes in this
/// process — the nesting check, the layer reader and its walk, the text scanner and patcher (an edit of `/A` and of
/// `/World/A`, the output scanned again), the walk's decoder — on any input. Never
/// panics, whatever the bytes.
#[doc(hidden)]
pub fn fuzz_own_readers(bytes: &[u8]) {
    let _ = wire::Walked::decode(bytes);
    let Ok(text) = std::str::from_utf8(bytes) else {
        return;
    };
    let _ = check_nesting(text);
    if let Ok(layer::Parsed::Layer(layer)) = layer::read(text, 100_000) {
        let _ = walk_layer(&layer, &super::facts::ReadOptions::default());
    }
    let ops: patch::Ops = vec![
        (patch::RESET.to_string(), "", String::new()),
        (
            "xformOp:translate:shenlong".to_string(),
            "double3",
            "(1, 0, 0)".to_string(),
        ),
    ];
    let edits = vec![
        ("/A".to_string(), ops.clone()),
        ("/World/A".to_string(), ops),
    ];
    if let Ok(out) = patch::patch(text, &edits, None) {
        // What the patcher writes scans again.
        let _ = patch::Outline::scan(&out);
    }
}

mod layer;
mod lex;
mod patch;
mod sandbox;
/// Why an asset a stage points to is not read, as the refusal says it (after the path).
fn why_not(why: &super::NotInside) -> String {
    match why {
        super::NotInside::Outside => {
            "is outside the stage's folder; only files inside it are read".to_string()
        }
        super::NotInside::Missing => "does not exist".to_string(),
        super::NotInside::NotAFile => {
            "is not a regular file (a folder, pipe or device); only files are read".to_string()
        }
        super::NotInside::TooLarge => format!("is larger than {} MiB", MAX_USD_BYTES >> 20),
        super::NotInside::Unreadable(e) => format!("cannot be read: {e}"),
    }
}

#[cfg(test)]
mod tests;
mod walk;
mod wire;
mod xform;

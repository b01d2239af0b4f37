//! The benchmark suite format (SPEC §6), read strictly: a suite written by others runs
//! unchanged, and a bad suite fails with a clear error before anything runs.

use super::checks::Check;
use serde::Deserialize;
use serde_json::Value;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The query categories of the paper.
pub const CATEGORIES: [&str; 5] = [
    "simple",
    "compositional",
    "fuzzy",
    "compositional_fuzzy",
    "hard",
];

/// A suite, validated.
#[derive(Clone, Debug)]
pub struct Suite {
    /// The suite's name.
    pub name: String,
    /// Scene files, resolved against the suite's folder.
    pub scenes: Vec<SceneSource>,
    /// Instantiations per query and scene.
    pub variations: usize,
    /// Seed of the instantiation.
    pub seed: u64,
    /// The queries.
    pub queries: Vec<Query>,
}

/// One query template.
#[derive(Clone, Debug)]
pub struct Query {
    /// Unique id.
    pub id: String,
    /// One of [`CATEGORIES`].
    pub category: String,
    /// The instruction, with placeholders `{A}`.
    pub text: String,
    /// Placeholders and their constraints, in order of first appearance in the text.
    pub pick: Vec<(String, Pick)>,
    /// The checks.
    pub expect: Vec<Check>,
    /// Extension: the names of the scenes it runs on (all when `None`).
    pub scenes: Option<Vec<String>>,
}

/// Where a suite's scene comes from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SceneSource {
    /// A scene file (scene JSON, glTF).
    File(PathBuf),
    /// Extension: house `house` of a ProcTHOR/Holodeck file, with the asset database for
    /// sizes: `{"procthor": "houses.jsonl", "house": 3, "assets": "asset-database.json"}`.
    House {
        /// The houses file.
        houses: PathBuf,
        /// Which house, from 0.
        house: usize,
        /// The asset database.
        assets: PathBuf,
    },
}

impl SceneSource {
    /// A stable label: the path, with `#house` for a house. Seeds the picks.
    pub fn label(&self) -> String {
        match self {
            SceneSource::File(p) => p.to_string_lossy().into_owned(),
            SceneSource::House { houses, house, .. } => {
                format!("{}#{house}", houses.to_string_lossy())
            }
        }
    }

    /// The files it reads, for callers that check they exist.
    pub fn files(&self) -> Vec<&Path> {
        match self {
            SceneSource::File(p) => vec![p.as_path()],
            SceneSource::House { houses, assets, .. } => vec![houses.as_path(), assets.as_path()],
        }
    }
}

impl Suite {
    /// Loads every scene of the suite, in order; an asset database is read once.
    ///
    /// # Errors
    /// The first scene that cannot be read, naming it.
    pub fn load_scenes(&self) -> Result<Vec<crate::scene::Scene>, SuiteError> {
        use crate::format::{procthor::AssetDatabase, SceneFile};
        let mut databases: Vec<(PathBuf, AssetDatabase)> = Vec::new();
        let mut out = Vec::new();
        for source in &self.scenes {
            let scene = match source {
                SceneSource::File(path) => {
                    SceneFile::load(path)
                        .map_err(|source| SuiteError::Scene {
                            what: "scene".into(),
                            path: path.clone(),
                            source,
                        })?
                        .scene
                }
                SceneSource::House {
                    houses,
                    house,
                    assets,
                } => {
                    if !databases.iter().any(|(p, _)| p == assets) {
                        let db =
                            AssetDatabase::load(assets).map_err(|source| SuiteError::Scene {
                                what: "assets".into(),
                                path: assets.clone(),
                                source,
                            })?;
                        databases.push((assets.clone(), db));
                    }
                    let db = &databases
                        .iter()
                        .find(|(p, _)| p == assets)
                        .expect("loaded")
                        .1;
                    SceneFile::load_house(houses, *house, db)
                        .map_err(|source| SuiteError::Scene {
                            what: format!("house #{house} of"),
                            path: houses.clone(),
                            source,
                        })?
                        .scene
                }
            };
            out.push(scene);
        }
        self.check_query_scenes(&out)?;
        Ok(out)
    }

    /// Whether `name`, from a query's `scenes`, means scene `index` (read as `scene`): its
    /// name, or the file name the suite lists it by (`boardroom.json`).
    #[must_use]
    pub fn names_scene(&self, name: &str, index: usize, scene: &crate::scene::Scene) -> bool {
        name == scene.name
            || matches!(self.scenes.get(index), Some(SceneSource::File(path))
                if path.file_name().is_some_and(|f| f == name))
    }

    /// Every scene a query's `scenes` lists is one of the suite's: a query that runs
    /// nowhere is a mistake in the suite, not a query to skip.
    fn check_query_scenes(&self, scenes: &[crate::scene::Scene]) -> Result<(), SuiteError> {
        for (i, q) in self.queries.iter().enumerate() {
            for name in q.scenes.iter().flatten() {
                let known = scenes
                    .iter()
                    .enumerate()
                    .any(|(k, scene)| self.names_scene(name, k, scene));
                if !known {
                    let names: Vec<&str> = scenes.iter().map(|s| s.name.as_str()).collect();
                    return Err(err(format!(
                        "queries[{i}] ('{}'): scenes names '{name}', which is none of the suite's scenes (named {})",
                        q.id,
                        names.join(", ")
                    )));
                }
            }
        }
        Ok(())
    }
}

/// Constraints on the object a placeholder picks.
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Pick {
    /// Standing on the floor (true) or resting on something (false).
    pub on_floor: Option<bool>,
    /// Resting on another object.
    pub resting: Option<bool>,
    /// Carrying other objects.
    pub carries: Option<bool>,
    /// Height at least, metres.
    pub min_height: Option<f64>,
    /// Height at most, metres.
    pub max_height: Option<f64>,
    /// Footprint area at least, m².
    pub min_footprint: Option<f64>,
    /// Footprint area at most, m².
    pub max_footprint: Option<f64>,
    /// Largest extent at most, metres.
    pub max_size: Option<f64>,
    /// The name contains this text.
    pub name_contains: Option<String>,
    /// Extension: not rotated (facing +Z), for queries whose answer depends on the
    /// object's current orientation, which its box does not show.
    pub unrotated: Option<bool>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSuite {
    name: String,
    scenes: Vec<RawScene>,
    #[serde(default = "one")]
    variations: usize,
    #[serde(default)]
    seed: u64,
    queries: Vec<RawQuery>,
}

fn one() -> usize {
    1
}

#[derive(Deserialize)]
#[serde(untagged)]
enum RawScene {
    File(String),
    House(RawHouse),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawHouse {
    procthor: String,
    house: usize,
    assets: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawQuery {
    id: String,
    category: String,
    text: String,
    #[serde(default)]
    scenes: Option<Vec<String>>,
    #[serde(default)]
    pick: BTreeMap<String, Value>,
    expect: Vec<Value>,
}

/// Why a suite cannot run: the kind as data, the message naming the field or file.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SuiteError {
    /// The suite file cannot be read.
    #[error("cannot read {}: {source}", path.display())]
    Read {
        /// The suite file.
        path: PathBuf,
        /// Why.
        #[source]
        source: std::io::Error,
    },
    /// A scene (or a house, or its asset database) the suite names cannot be read.
    #[error("suite {what} {}: {source}", path.display())]
    Scene {
        /// `scene`, `house #N of` or `assets`.
        what: String,
        /// Its file.
        path: PathBuf,
        /// Why.
        #[source]
        source: crate::format::FormatError,
    },
    /// The suite breaks the format's rules; the message names the field
    /// (`instances[3].expect[0]: …`).
    #[error("{0}")]
    Invalid(String),
    /// An error in the named suite file.
    #[error("{}: {source}", path.display())]
    InFile {
        /// The suite file.
        path: PathBuf,
        /// The error.
        #[source]
        source: Box<SuiteError>,
    },
}

fn err(message: impl Into<String>) -> SuiteError {
    SuiteError::Invalid(message.into())
}

impl Suite {
    /// Reads and validates a suite file.
    pub fn load(path: &Path) -> Result<Self, SuiteError> {
        let text =
            crate::io::read_text_limited(path, crate::io::MAX_READ_BYTES).map_err(|source| {
                SuiteError::Read {
                    path: path.to_path_buf(),
                    source,
                }
            })?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Self::parse(&text, &dir).map_err(|e| SuiteError::InFile {
            path: path.to_path_buf(),
            source: Box::new(e),
        })
    }

    /// Parses a suite; scene paths are resolved against `dir`.
    pub fn parse(text: &str, dir: &Path) -> Result<Self, SuiteError> {
        let raw: RawSuite = serde_json::from_str(text).map_err(|e| {
            err(format!(
                "invalid suite at line {}, column {}: {e}",
                e.line(),
                e.column()
            ))
        })?;
        if raw.scenes.is_empty() {
            return Err(err("scenes: the suite names no scene"));
        }
        if raw.variations == 0 {
            return Err(err("variations must be at least 1"));
        }
        let mut queries = Vec::new();
        for (i, q) in raw.queries.into_iter().enumerate() {
            let at = format!("queries[{i}] ('{}')", q.id);
            if queries.iter().any(|p: &Query| p.id == q.id) {
                return Err(err(format!("{at}: the id is used twice")));
            }
            if !CATEGORIES.contains(&q.category.as_str()) {
                return Err(err(format!(
                    "{at}: unknown category '{}': use {}",
                    q.category,
                    CATEGORIES.join(", ")
                )));
            }
            let placeholders = placeholders(&q.text);
            let mut pick = Vec::new();
            for name in &placeholders {
                let constraint = match q.pick.get(name) {
                    Some(v) => serde_json::from_value::<Pick>(v.clone())
                        .map_err(|e| err(format!("{at}: pick.{name}: {e}")))?,
                    None => Pick::default(),
                };
                pick.push((name.clone(), constraint));
            }
            if let Some(extra) = q.pick.keys().find(|k| !placeholders.contains(k)) {
                return Err(err(format!(
                    "{at}: pick.{extra} is not a placeholder of the text"
                )));
            }
            let mut expect = Vec::new();
            for (k, value) in q.expect.iter().enumerate() {
                let check =
                    Check::parse(value).map_err(|m| err(format!("{at}: expect[{k}]: {m}")))?;
                // In a templated query, a short capital name no placeholder has is a typo
                // of one; in a query with none (`TV`), it is an object's name.
                for name in check.placeholders() {
                    if !placeholders.is_empty()
                        && !placeholders.contains(&name)
                        && name.len() <= 2
                        && name.chars().all(|c| c.is_ascii_uppercase())
                    {
                        return Err(err(format!(
                            "{at}: expect[{k}] names {{{name}}}, which the text does not have"
                        )));
                    }
                }
                expect.push(check);
            }
            if expect.is_empty() {
                return Err(err(format!("{at}: expect has no check")));
            }
            if q.scenes.as_ref().is_some_and(Vec::is_empty) {
                return Err(err(format!("{at}: scenes lists no scene")));
            }
            queries.push(Query {
                id: q.id,
                category: q.category,
                text: q.text,
                pick,
                expect,
                scenes: q.scenes,
            });
        }
        Ok(Self {
            name: raw.name,
            scenes: raw
                .scenes
                .iter()
                .map(|s| match s {
                    RawScene::File(p) => SceneSource::File(dir.join(p)),
                    RawScene::House(h) => SceneSource::House {
                        houses: dir.join(&h.procthor),
                        house: h.house,
                        assets: dir.join(&h.assets),
                    },
                })
                .collect(),
            variations: raw.variations,
            seed: raw.seed,
            queries,
        })
    }
}

/// The placeholders `{A}` of a text, in order of first appearance.
pub fn placeholders(text: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut rest = text;
    while let Some(start) = rest.find('{') {
        let Some(len) = rest[start + 1..].find('}') else {
            break;
        };
        let name = &rest[start + 1..start + 1 + len];
        if !name.is_empty()
            && name.chars().all(|c| c.is_alphanumeric() || c == '_')
            && !out.iter().any(|n| n == name)
        {
            out.push(name.to_string());
        }
        rest = &rest[start + 1 + len..];
    }
    out
}

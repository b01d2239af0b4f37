//! ProcTHOR and Holodeck houses (the scenes the paper evaluated on), imported with the
//! ProcTHOR asset database for object sizes.
//!
//! A house lists `objects[]` with an `assetId`, a `position` (the centre of the object's
//! box, metres) and a `rotation` (Euler degrees, Unity's order: z, then x, then y), with
//! small objects nested as `children` of what they rest on. Unity is left-handed; Shenlong
//! mirrors Z at this boundary (SPEC §1): a point `(x, y, z)` becomes `(x, y, −z)` and a
//! rotation `Ry(y)·Rx(x)·Rz(z)` becomes `Ry(−y)·Rx(−x)·Rz(z)`.
//!
//! Objects are named from their type in plain words (`TVStand` → `tv stand`), numbered
//! from the second of a kind (`remote control 2`). The import is a scene-JSON document
//! that keeps `id`, `assetId` and `objectType`, and records supports as `"on"`.

use super::{tidy, FormatError};
use serde_json::{json, Map, Value};
use std::collections::HashMap;
use std::path::Path;

/// Asset sizes from ProcTHOR's `asset-database.json`: per object type, the assets with
/// their `assetId` and local `boundingBox {x, y, z}`.
#[derive(Clone, Debug, Default)]
pub struct AssetDatabase {
    assets: HashMap<String, (String, [f64; 3])>,
}

impl AssetDatabase {
    /// Reads the database file.
    pub fn load(path: &Path) -> Result<Self, FormatError> {
        let text = crate::io::read_text_limited(path, crate::io::MAX_READ_BYTES)
            .map_err(|e| FormatError::read(path, e))?;
        Self::from_json(&text).map_err(|e| e.in_file(path))
    }

    /// Parses the database.
    pub fn from_json(text: &str) -> Result<Self, FormatError> {
        super::check_json_depth(text.as_bytes())?;
        let value: Value =
            serde_json::from_str(text).map_err(|e| FormatError::json_syntax("JSON", &e))?;
        let types = value.as_object().ok_or_else(|| {
            FormatError::invalid("the asset database must map object types to lists of assets")
        })?;
        let mut assets = HashMap::new();
        for (object_type, list) in types {
            for (i, asset) in list.as_array().into_iter().flatten().enumerate() {
                let at = format!("{object_type}[{i}]");
                let id = asset
                    .get("assetId")
                    .and_then(Value::as_str)
                    .ok_or_else(|| FormatError::invalid(format!("{at}: missing \"assetId\"")))?;
                let b = asset.get("boundingBox").ok_or_else(|| {
                    FormatError::invalid(format!("{at} ('{id}'): missing \"boundingBox\""))
                })?;
                let mut size = [0.0; 3];
                for (k, axis) in ["x", "y", "z"].iter().enumerate() {
                    size[k] = b
                        .get(*axis)
                        .and_then(Value::as_f64)
                        .filter(|v| v.is_finite() && *v > 0.0)
                        .ok_or_else(|| {
                            FormatError::invalid(format!(
                                "{at} ('{id}'): boundingBox.{axis} must be a number > 0"
                            ))
                        })?;
                }
                assets.insert(id.to_string(), (object_type.clone(), size));
            }
        }
        Ok(Self { assets })
    }

    /// The object type and size of an asset.
    pub fn get(&self, asset_id: &str) -> Option<(&str, [f64; 3])> {
        self.assets.get(asset_id).map(|(t, s)| (t.as_str(), *s))
    }

    /// Number of assets.
    pub fn len(&self) -> usize {
        self.assets.len()
    }

    /// Whether there are no assets.
    pub fn is_empty(&self) -> bool {
        self.assets.is_empty()
    }
}

/// Whether a parsed JSON document looks like a ProcTHOR/Holodeck house rather than a
/// scene file: objects with `assetId` and no `size`.
pub fn looks_like_house(document: &Value) -> bool {
    document
        .get("objects")
        .and_then(Value::as_array)
        .and_then(|o| o.first())
        .is_some_and(|o| o.get("assetId").is_some() && o.get("size").is_none())
}

/// Reads house number `index` (from 0) of a file holding one house (`.json`) or one per
/// line (`.jsonl`), and converts it to a scene-JSON document.
pub fn read_file(path: &Path, index: usize, assets: &AssetDatabase) -> Result<Value, FormatError> {
    let text = crate::io::read_text_limited(path, crate::io::MAX_READ_BYTES)
        .map_err(|e| FormatError::read(path, e))?;
    super::check_json_depth(text.as_bytes()).map_err(|e| e.in_file(path))?;
    let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("house");
    let lines: Vec<&str> = text.lines().filter(|l| !l.trim().is_empty()).collect();
    let (house_text, line) = if lines.len() > 1
        && lines[0].trim_start().starts_with('{')
        && serde_json::from_str::<Value>(lines[0]).is_ok()
    {
        let text = lines.get(index).ok_or_else(|| {
            FormatError::invalid(format!(
                "{} holds {} houses; house {index} is out of range (they are counted from 0)",
                path.display(),
                lines.len()
            ))
        })?;
        (*text, Some(index + 1))
    } else {
        if index > 0 {
            return Err(FormatError::invalid(format!(
                "{} holds one house; house {index} is out of range (it is house 0)",
                path.display()
            )));
        }
        (text.as_str(), None)
    };
    let house: Value = serde_json::from_str(house_text).map_err(|e| {
        let syntax = FormatError::json_syntax("JSON", &e);
        match (line, syntax) {
            (
                Some(l),
                FormatError::Syntax {
                    what,
                    column,
                    message,
                    ..
                },
            ) => FormatError::Syntax {
                what,
                line: l,
                column,
                message,
            },
            (_, syntax) => syntax,
        }
        .in_file(path)
    })?;
    let name = match line {
        Some(_) => format!("{stem} {index}"),
        None => stem.to_string(),
    };
    convert(&house, assets, &name).map_err(|e| e.in_file(path))
}

/// Converts a parsed house to a scene-JSON document.
pub fn convert(house: &Value, assets: &AssetDatabase, name: &str) -> Result<Value, FormatError> {
    let objects = house
        .get("objects")
        .and_then(Value::as_array)
        .ok_or_else(|| FormatError::invalid("the house has no \"objects\" list"))?;
    let mut out = Vec::new();
    let mut counts: HashMap<String, usize> = HashMap::new();
    // Depth first, each object before its children (names are numbered in this order),
    // on a stack of its own: no recursion, however deep the children nest.
    let mut stack: Vec<(&Value, String, Option<String>)> = objects
        .iter()
        .enumerate()
        .rev()
        .map(|(i, object)| (object, format!("objects[{i}]"), None))
        .collect();
    while let Some((object, at, parent)) = stack.pop() {
        let name = convert_object(
            object,
            &at,
            parent.as_deref(),
            assets,
            &mut counts,
            &mut out,
        )?;
        let children = object
            .get("children")
            .and_then(Value::as_array)
            .map_or(&[][..], Vec::as_slice);
        for (k, child) in children.iter().enumerate().rev() {
            stack.push((child, format!("{at}.children[{k}]"), Some(name.clone())));
        }
    }
    let mut root = Map::new();
    root.insert("name".into(), Value::String(name.to_string()));
    if let Some(bounds) = room_bounds(house, &out) {
        root.insert("bounds".into(), bounds);
    }
    root.insert("objects".into(), Value::Array(out));
    root.insert("source".into(), json!({"format": "procthor", "frame": "converted from Unity's left-handed frame by mirroring z"}));
    Ok(Value::Object(root))
}

/// Converts one object (not its children) into `out`; gives the name it got.
fn convert_object(
    object: &Value,
    at: &str,
    parent: Option<&str>,
    assets: &AssetDatabase,
    counts: &mut HashMap<String, usize>,
    out: &mut Vec<Value>,
) -> Result<String, FormatError> {
    let asset_id = object
        .get("assetId")
        .and_then(Value::as_str)
        .ok_or_else(|| FormatError::invalid(format!("{at}: missing \"assetId\"")))?;
    let (object_type, size) = assets.get(asset_id).ok_or_else(|| {
        FormatError::invalid(format!(
            "{at}: asset '{asset_id}' is not in the asset database"
        ))
    })?;
    let xyz = |key: &str| -> Result<[f64; 3], FormatError> {
        let v = object.get(key).ok_or_else(|| {
            FormatError::invalid(format!("{at} ('{asset_id}'): missing \"{key}\""))
        })?;
        let mut out = [0.0; 3];
        for (k, axis) in ["x", "y", "z"].iter().enumerate() {
            out[k] = v
                .get(*axis)
                .and_then(Value::as_f64)
                .filter(|x| x.is_finite())
                .ok_or_else(|| {
                    FormatError::invalid(format!(
                        "{at} ('{asset_id}'): {key}.{axis} must be a finite number"
                    ))
                })?;
        }
        Ok(out)
    };
    let centre_unity = xyz("position")?;
    let euler = match object.get("rotation") {
        Some(_) => xyz("rotation")?,
        None => [0.0; 3],
    };
    let rotation = unity_euler_to_quat(euler);
    // q and −q are the same rotation; files read better with w ≥ 0.
    let rotation = if rotation.w < 0.0 {
        -rotation
    } else {
        rotation
    };
    let centre = glam::DVec3::new(centre_unity[0], centre_unity[1], -centre_unity[2]);
    let bottom = centre + rotation * glam::DVec3::new(0.0, -0.5 * size[1], 0.0);

    let base = human_name(object_type);
    let n = counts.entry(base.clone()).or_insert(0);
    *n += 1;
    let name = if *n == 1 { base } else { format!("{base} {n}") };

    let mut map = Map::new();
    map.insert("name".into(), Value::String(name.clone()));
    map.insert("size".into(), json!(size));
    map.insert(
        "position".into(),
        json!([tidy(bottom.x), tidy(bottom.y), tidy(bottom.z)]),
    );
    if !rotation.abs_diff_eq(glam::DQuat::IDENTITY, 1e-12) {
        let r = rotation.to_array().map(tidy);
        map.insert("rotation".into(), json!(r));
    }
    if let Some(parent) = parent {
        map.insert("on".into(), Value::String(parent.to_string()));
    }
    // Unity's forward (+Z) is −Z after the mirror: ProcTHOR assets face local −Z here.
    map.insert("front".into(), json!([0.0, 0.0, -1.0]));
    map.insert("objectType".into(), Value::String(object_type.to_string()));
    map.insert("assetId".into(), Value::String(asset_id.to_string()));
    if let Some(id) = object.get("id") {
        map.insert("id".into(), id.clone());
    }
    out.push(Value::Object(map));
    Ok(name)
}

/// Unity Euler angles in degrees (applied z, then x, then y) to a quaternion in
/// Shenlong's right-handed frame: conjugating by the z mirror negates the x and y angles.
pub fn unity_euler_to_quat(degrees: [f64; 3]) -> glam::DQuat {
    let [x, y, z] = degrees.map(f64::to_radians);
    glam::DQuat::from_rotation_y(-y)
        * glam::DQuat::from_rotation_x(-x)
        * glam::DQuat::from_rotation_z(z)
}

/// The room: the floor polygons' extent, up to the walls' height.
fn room_bounds(house: &Value, objects: &[Value]) -> Option<Value> {
    let mut min = [f64::INFINITY; 3];
    let mut max = [f64::NEG_INFINITY; 3];
    for room in house.get("rooms")?.as_array()? {
        for p in room.get("floorPolygon")?.as_array()? {
            let (x, z) = (p.get("x")?.as_f64()?, -p.get("z")?.as_f64()?);
            min[0] = min[0].min(x);
            max[0] = max[0].max(x);
            min[2] = min[2].min(z);
            max[2] = max[2].max(z);
        }
    }
    let wall_top = house
        .get("walls")
        .and_then(Value::as_array)
        .into_iter()
        .flatten()
        .flat_map(|w| {
            w.get("polygon")
                .and_then(Value::as_array)
                .cloned()
                .unwrap_or_default()
        })
        .filter_map(|p| p.get("y").and_then(Value::as_f64))
        .fold(0.0f64, f64::max);
    let object_top = objects
        .iter()
        .filter_map(|o| {
            Some(o.get("position")?.get(1)?.as_f64()? + o.get("size")?.get(1)?.as_f64()?)
        })
        .fold(0.0f64, f64::max);
    min[1] = 0.0;
    max[1] = if wall_top > 0.0 {
        wall_top
    } else {
        object_top.max(2.5)
    };
    (min[0] < max[0] && min[2] < max[2])
        .then(|| json!({"min": min.map(tidy), "max": max.map(tidy)}))
}

/// An object type in plain lower-case words: `TVStand` → `tv stand`, `CellPhone` →
/// `cell phone`; a few compounds read better joined.
pub fn human_name(object_type: &str) -> String {
    match object_type {
        "ArmChair" => return "armchair".into(),
        "CounterTop" => return "countertop".into(),
        "KeyChain" => return "keychain".into(),
        "HousePlant" => return "houseplant".into(),
        "DogBed" => return "dog bed".into(),
        _ => {}
    }
    let chars: Vec<char> = object_type.chars().collect();
    let mut words: Vec<String> = Vec::new();
    let mut current = String::new();
    for (i, &c) in chars.iter().enumerate() {
        let boundary = i > 0
            && c.is_uppercase()
            && (chars[i - 1].is_lowercase()
                || chars[i - 1].is_ascii_digit()
                || chars.get(i + 1).is_some_and(|n| n.is_lowercase()));
        if boundary && !current.is_empty() {
            words.push(std::mem::take(&mut current));
        }
        if c == '_' || c == ' ' {
            if !current.is_empty() {
                words.push(std::mem::take(&mut current));
            }
            continue;
        }
        current.push(c);
    }
    if !current.is_empty() {
        words.push(current);
    }
    words.join(" ").to_lowercase()
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn human_names() {
        assert_eq!(human_name("TVStand"), "tv stand");
        assert_eq!(human_name("RemoteControl"), "remote control");
        assert_eq!(human_name("CD"), "cd");
        assert_eq!(human_name("ArmChair"), "armchair");
        assert_eq!(human_name("PaperTowelRoll"), "paper towel roll");
        assert_eq!(human_name("Sofa"), "sofa");
    }

    #[test]
    fn unity_rotation_mirrors_to_the_right_handed_frame() {
        // Unity's +90° about Y turns +Z toward +X; mirrored, Unity's +Z is our −Z and the
        // turn takes our −Z to +X: a −90° turn about +Y here.
        let q = unity_euler_to_quat([0.0, 90.0, 0.0]);
        assert!((q * DVec3::NEG_Z - DVec3::X).length() < 1e-12);
        // A general rotation: mirror the Unity matrix by S = diag(1, 1, −1) on both sides.
        let (x, y, z) = (20f64.to_radians(), 35f64.to_radians(), -50f64.to_radians());
        let unity = glam::DMat3::from_rotation_y(y)
            * glam::DMat3::from_rotation_x(x)
            * glam::DMat3::from_rotation_z(z);
        let s = glam::DMat3::from_diagonal(DVec3::new(1.0, 1.0, -1.0));
        let ours = glam::DMat3::from_quat(unity_euler_to_quat([20.0, 35.0, -50.0]));
        assert!((s * unity * s).abs_diff_eq(ours, 1e-12));
    }

    #[test]
    fn deeply_nested_children_are_refused_with_the_limit_not_a_crash() {
        let db = AssetDatabase::from_json(
            r#"{"Box": [{"assetId": "Box_1", "boundingBox": {"x": 1, "y": 1, "z": 1}}]}"#,
        )
        .unwrap();
        let object = r#"{"assetId": "Box_1", "position": {"x": 0, "y": 0.5, "z": 0}"#;
        let house = |depth: usize| {
            let mut text = String::new();
            for _ in 0..depth {
                text.push_str(object);
                text.push_str(r#", "children": ["#);
            }
            text.push_str(object);
            text.push('}');
            for _ in 0..depth {
                text.push_str("]}");
            }
            format!(r#"{{"rooms": [], "objects": [{text}]}}"#)
        };
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("house.json");
        // 48 levels of children are 99 levels of JSON: read, each on its parent.
        std::fs::write(&path, house(48)).unwrap();
        let doc = read_file(&path, 0, &db).unwrap();
        let objects = doc["objects"].as_array().unwrap();
        assert_eq!(objects.len(), 49);
        assert_eq!(objects[48]["on"], objects[47]["name"]);
        assert_eq!(objects[1]["name"], "box 2");
        std::fs::write(&path, house(5000)).unwrap();
        let e = read_file(&path, 0, &db).unwrap_err();
        assert!(
            e.to_string()
                .contains("nesting deeper than 100 levels at line 1, column "),
            "{}",
            e.to_string()
        );
    }

    #[test]
    fn converts_a_small_house() {
        let db = AssetDatabase::from_json(r#"{"Sofa": [{"assetId": "Sofa_1", "boundingBox": {"x": 2, "y": 0.8, "z": 0.9}}],
            "RemoteControl": [{"assetId": "Remote_1", "boundingBox": {"x": 0.05, "y": 0.02, "z": 0.15}}]}"#).unwrap();
        let house: Value = serde_json::from_str(r#"{"rooms": [{"floorPolygon": [{"x": 0, "y": 0, "z": 0}, {"x": 4, "y": 0, "z": 5}]}],
            "walls": [{"polygon": [{"x": 0, "y": 2.5, "z": 0}]}],
            "objects": [{"id": "1", "assetId": "Sofa_1", "position": {"x": 1, "y": 0.4, "z": 2}, "rotation": {"x": 0, "y": 90, "z": 0},
              "children": [{"id": "2", "assetId": "Remote_1", "position": {"x": 1, "y": 0.81, "z": 2}, "rotation": {"x": 0, "y": 0, "z": 0}}]},
              {"id": "3", "assetId": "Remote_1", "position": {"x": 3, "y": 0.01, "z": 1}}]}"#).unwrap();
        let doc = convert(&house, &db, "h").unwrap();
        let objects = doc["objects"].as_array().unwrap();
        assert_eq!(objects[0]["name"], "sofa");
        assert_eq!(objects[0]["position"], json!([1.0, 0.0, -2.0]));
        assert_eq!(objects[1]["name"], "remote control");
        assert_eq!(objects[1]["on"], "sofa");
        assert_eq!(objects[2]["name"], "remote control 2");
        assert_eq!(
            doc["bounds"],
            json!({"min": [0.0, 0.0, -5.0], "max": [4.0, 2.5, 0.0]})
        );
        let (scene, _) = super::super::json::scene_from_value(&doc, "h").unwrap();
        assert_eq!(scene.objects[1].support, Some(0));
        assert!(scene.objects[1].support_from_file);
        let unknown = house.to_string().replace("Sofa_1", "Sofa_9");
        let e = convert(&serde_json::from_str(&unknown).unwrap(), &db, "h").unwrap_err();
        assert_eq!(
            e.to_string(),
            "objects[0]: asset 'Sofa_9' is not in the asset database"
        );
    }
}

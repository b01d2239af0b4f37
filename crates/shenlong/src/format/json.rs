//! Shenlong's scene JSON (SPEC §2): read with validation, written back in the input's
//! shape with every unknown field kept.

use super::FormatError;
use crate::geometry::Aabb;
use crate::scene::{Labels, Object, Scene, MAX_COORDINATE, MAX_SCALE, MIN_SCALE};
use cga::Similarity;
use glam::{DQuat, DVec3};
use serde_json::{Map, Value};
use std::collections::HashMap;

/// A scene read from scene JSON, with the document it came from.
#[derive(Clone, Debug)]
pub struct JsonScene {
    /// The scene.
    pub scene: Scene,
    /// The parsed document, kept so that writing preserves every other field.
    pub document: Value,
}

/// Parses and validates scene JSON. `fallback_name` names a scene without a `"name"`.
pub fn read(text: &str, fallback_name: &str) -> Result<JsonScene, FormatError> {
    // A UTF-8 byte-order mark, as some editors write, is not part of the JSON.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let document: Value = serde_json::from_str(text).map_err(|e| {
        FormatError::new(format!(
            "invalid JSON at line {}, column {}: {}",
            e.line(),
            e.column(),
            strip_position(&e.to_string())
        ))
    })?;
    let scene = scene_from_value(&document, fallback_name)?;
    Ok(JsonScene { scene, document })
}

fn strip_position(message: &str) -> String {
    match message.rfind(" at line ") {
        Some(i) => message[..i].to_string(),
        None => message.to_string(),
    }
}

/// Builds a scene from a parsed scene-JSON document, validating every field.
pub fn scene_from_value(document: &Value, fallback_name: &str) -> Result<Scene, FormatError> {
    let root = document.as_object().ok_or_else(|| {
        FormatError::new("the scene must be a JSON object with an \"objects\" list")
    })?;
    let name = match root.get("name") {
        None | Some(Value::Null) => fallback_name.to_string(),
        Some(Value::String(s)) => s.clone(),
        Some(_) => return Err(FormatError::new("name must be a string")),
    };
    let mut scene = Scene::new(name);
    if let Some(bounds) = root.get("bounds").filter(|b| !b.is_null()) {
        let b = bounds
            .as_object()
            .ok_or_else(|| FormatError::new("bounds must be an object with \"min\" and \"max\""))?;
        let min = vec3(b.get("min"), "bounds.min")?;
        let max = vec3(b.get("max"), "bounds.max")?;
        for axis in 0..3 {
            if min[axis] >= max[axis] {
                return Err(FormatError::new(format!(
                    "bounds.min[{axis}] must be less than bounds.max[{axis}]"
                )));
            }
        }
        scene.bounds = Some(Aabb::new(min, max));
    }
    let objects = root
        .get("objects")
        .ok_or_else(|| FormatError::new("missing \"objects\": the list of the scene's objects"))?
        .as_array()
        .ok_or_else(|| FormatError::new("objects must be a list"))?;
    // Names compared case-insensitively, through an index: a scan per object would make
    // reading quadratic in the number of objects.
    let mut by_name: HashMap<String, usize> = HashMap::with_capacity(objects.len());
    for (i, value) in objects.iter().enumerate() {
        let object = object_from_value(value, i)?;
        if let Some(&j) = by_name.get(&object.name.trim().to_lowercase()) {
            return Err(FormatError::new(format!(
                "objects[{i}].name '{}' duplicates objects[{j}].name '{}' (names are compared case-insensitively)",
                object.name, scene.objects[j].name
            )));
        }
        by_name.insert(object.name.trim().to_lowercase(), i);
        scene.objects.push(object);
    }
    resolve_on_fields(objects, &mut scene, &by_name)?;
    scene.detect_supports();
    Ok(scene)
}

/// The optional `"on"` field (a Shenlong extension of SPEC §2) names the object this one
/// rests on; it is carried along with it.
fn resolve_on_fields(
    objects: &[Value],
    scene: &mut Scene,
    by_name: &HashMap<String, usize>,
) -> Result<(), FormatError> {
    for (i, value) in objects.iter().enumerate() {
        let Some(on) = value.get("on").filter(|v| !v.is_null()) else {
            continue;
        };
        let name = on.as_str().ok_or_else(|| {
            FormatError::new(format!(
                "objects[{i}].on must be the name of another object"
            ))
        })?;
        let j = by_name
            .get(&name.trim().to_lowercase())
            .copied()
            .ok_or_else(|| {
                FormatError::new(format!(
                    "objects[{i}].on '{name}' names no object of the scene"
                ))
            })?;
        if j == i {
            return Err(FormatError::new(format!(
                "objects[{i}].on names the object itself"
            )));
        }
        scene.objects[i].support = Some(j);
        scene.objects[i].support_from_file = true;
    }
    // A chain of supports must end on the floor.
    for start in 0..scene.objects.len() {
        let mut current = start;
        for _ in 0..=scene.objects.len() {
            match scene.objects[current].support {
                Some(next) => current = next,
                None => break,
            }
            if current == start {
                return Err(FormatError::new(format!(
                    "objects[{start}].on: the objects rest on each other in a circle"
                )));
            }
        }
    }
    Ok(())
}

fn object_from_value(value: &Value, i: usize) -> Result<Object, FormatError> {
    let o = value
        .as_object()
        .ok_or_else(|| FormatError::new(format!("objects[{i}] must be an object")))?;
    let at = |field: &str| format!("objects[{i}].{field}");
    let name = match o.get("name") {
        Some(Value::String(s)) if !s.trim().is_empty() => s.clone(),
        Some(Value::String(_)) => {
            return Err(FormatError::new(format!(
                "{} must not be empty",
                at("name")
            )))
        }
        Some(_) => return Err(FormatError::new(format!("{} must be a string", at("name")))),
        None => return Err(FormatError::new(format!("objects[{i}]: missing \"name\""))),
    };
    let size = match o.get("size") {
        None => {
            return Err(FormatError::new(format!(
                "objects[{i}] ('{name}'): missing \"size\" [w, h, d]"
            )))
        }
        some => vec3(some, &at("size"))?,
    };
    for axis in 0..3 {
        if size[axis] <= 0.0 {
            return Err(FormatError::new(format!(
                "{}[{axis}] must be > 0",
                at("size")
            )));
        }
        if size[axis] > MAX_COORDINATE {
            return Err(FormatError::new(format!(
                "{}[{axis}] must be at most {MAX_COORDINATE:.0e} m",
                at("size")
            )));
        }
    }
    let position = match o.get("position") {
        None => {
            return Err(FormatError::new(format!(
                "objects[{i}] ('{name}'): missing \"position\" [x, y, z]"
            )))
        }
        some => vec3(some, &at("position"))?,
    };
    for axis in 0..3 {
        if position[axis].abs() > MAX_COORDINATE {
            return Err(FormatError::new(format!(
                "{}[{axis}] must be within ±{MAX_COORDINATE:.0e} m",
                at("position")
            )));
        }
    }
    let rotation = rotation(o.get("rotation"), &at("rotation"))?;
    let scale = match o.get("scale") {
        None | Some(Value::Null) => 1.0,
        Some(v) => {
            let s = number(v, &at("scale"))?;
            if !(MIN_SCALE..=MAX_SCALE).contains(&s) {
                return Err(FormatError::new(format!(
                    "{} must be in [{MIN_SCALE:.0e}, {MAX_SCALE:.0e}]",
                    at("scale")
                )));
            }
            s
        }
    };
    let mut object = Object::new_box(name, size, position, rotation, scale)
        .map_err(|e| FormatError::new(format!("objects[{i}]: {e}")))?;
    object.labels = labels(o, i)?;
    if let Some(front) = o.get("front").filter(|v| !v.is_null()) {
        let f = vec3(Some(front), &at("front"))?;
        if f.length() < 1e-9 {
            return Err(FormatError::new(format!(
                "{} must be a non-zero direction [x, y, z]",
                at("front")
            )));
        }
        object.front = f.normalize();
    }
    Ok(object)
}

/// The optional words for an object (a documented extension of SPEC §2): `category` (a
/// string; else a ProcTHOR `objectType` in plain words), `aliases` (strings), and the
/// attributes `color` / `colour` / `material` (a string or a list of strings).
fn labels(o: &Map<String, Value>, i: usize) -> Result<Labels, FormatError> {
    let strings = |field: &str, list_ok: bool| -> Result<Vec<String>, FormatError> {
        match o.get(field) {
            None | Some(Value::Null) => Ok(Vec::new()),
            Some(Value::String(s)) => Ok(vec![s.trim().to_string()]),
            Some(Value::Array(items)) if list_ok => items
                .iter()
                .enumerate()
                .map(|(k, v)| {
                    v.as_str().map(|s| s.trim().to_string()).ok_or_else(|| {
                        FormatError::new(format!("objects[{i}].{field}[{k}] must be a string"))
                    })
                })
                .collect(),
            Some(_) if list_ok => Err(FormatError::new(format!(
                "objects[{i}].{field} must be a string or a list of strings"
            ))),
            Some(_) => Err(FormatError::new(format!(
                "objects[{i}].{field} must be a string"
            ))),
        }
    };
    let mut category = strings("category", false)?.pop();
    if category.is_none() {
        if let Some(Value::String(t)) = o.get("objectType") {
            category = Some(super::procthor::human_name(t));
        }
    }
    let mut attributes = strings("color", true)?;
    attributes.extend(strings("colour", true)?);
    attributes.extend(strings("material", true)?);
    Ok(Labels {
        category: category.filter(|c| !c.is_empty()),
        aliases: strings("aliases", true)?
            .into_iter()
            .filter(|a| !a.is_empty())
            .collect(),
        attributes: attributes.into_iter().filter(|a| !a.is_empty()).collect(),
    })
}

/// A pose as written in the file: position, rotation, scale.
pub(crate) fn pose_of(o: &Map<String, Value>) -> Option<(DVec3, DQuat, f64)> {
    let position = vec3(o.get("position"), "").ok()?;
    let rotation = rotation(o.get("rotation"), "").ok()?;
    let scale = o.get("scale").and_then(Value::as_f64).unwrap_or(1.0);
    Some((position, rotation, scale))
}

fn rotation(value: Option<&Value>, at: &str) -> Result<DQuat, FormatError> {
    let Some(value) = value.filter(|v| !v.is_null()) else {
        return Ok(DQuat::IDENTITY);
    };
    let list = value
        .as_array()
        .filter(|a| a.len() == 4)
        .ok_or_else(|| FormatError::new(format!("{at} must be a quaternion [x, y, z, w]")))?;
    let mut q = [0.0; 4];
    for (k, v) in list.iter().enumerate() {
        q[k] = number(v, &format!("{at}[{k}]"))?;
    }
    // Scaled down first, so components near f64::MAX do not overflow the length.
    let big = q.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let q = if big > 1.0 { q.map(|x| x / big) } else { q };
    let q = DQuat::from_array(q);
    let length = q.length();
    if length.is_nan() || length <= 1e-9 {
        return Err(FormatError::new(format!(
            "{at} must be a non-zero quaternion [x, y, z, w]"
        )));
    }
    Ok(q / length)
}

fn vec3(value: Option<&Value>, at: &str) -> Result<DVec3, FormatError> {
    let list = value
        .and_then(Value::as_array)
        .filter(|a| a.len() == 3)
        .ok_or_else(|| {
            FormatError::new(format!("{at} must be a list of three numbers [x, y, z]"))
        })?;
    let mut v = [0.0; 3];
    for (k, item) in list.iter().enumerate() {
        v[k] = number(item, &format!("{at}[{k}]"))?;
    }
    Ok(DVec3::from(v))
}

fn number(value: &Value, at: &str) -> Result<f64, FormatError> {
    match value.as_f64() {
        Some(x) if x.is_finite() => Ok(x),
        _ => Err(FormatError::new(format!(
            "{at} must be a finite number, found {value}"
        ))),
    }
}

/// Writes the scene as scene JSON. With the `original` document, the output has its
/// shape: every field is kept, and only the poses of objects that moved are rewritten
/// (`rotation` and `scale` are added only when they differ from their defaults).
pub fn write(scene: &Scene, original: Option<&Value>) -> String {
    let mut document = original.cloned().unwrap_or_else(|| fresh_document(scene));
    if let Some(objects) = document.get_mut("objects").and_then(Value::as_array_mut) {
        for (object, value) in scene.objects.iter().zip(objects.iter_mut()) {
            if let Some(map) = value.as_object_mut() {
                update_pose(object, map);
            }
        }
    }
    super::pretty::to_string(&document)
}

fn fresh_document(scene: &Scene) -> Value {
    let mut root = Map::new();
    root.insert("name".into(), Value::String(scene.name.clone()));
    if let Some(b) = scene.bounds {
        root.insert(
            "bounds".into(),
            serde_json::json!({"min": numbers(b.min.to_array()), "max": numbers(b.max.to_array())}),
        );
    }
    let objects = scene
        .objects
        .iter()
        .map(|o| {
            let size = match &o.shape {
                crate::scene::Shape::Box { size } => *size,
                // A mesh becomes its world box; a flat one gets a hair of thickness,
                // since a box's size must be > 0.
                crate::scene::Shape::Points { .. } => {
                    o.world_aabb().size().max(DVec3::splat(MIN_SIZE))
                }
            };
            // The pose is filled in by `update_pose`, like any moved object's.
            let mut v = serde_json::json!({"name": o.name, "size": numbers(size.to_array())});
            if (o.front - DVec3::Z).length() > 1e-12 {
                v["front"] = serde_json::json!(numbers(o.front.to_array()));
            }
            v
        })
        .collect();
    root.insert("objects".into(), Value::Array(objects));
    Value::Object(root)
}

/// The smallest box extent written for a flat mesh, in metres.
const MIN_SIZE: f64 = 1e-6;

/// The pose a scene file records: a box's own pose, or for a mesh its world box's bottom
/// centre, unrotated and unscaled.
fn file_pose(object: &Object) -> Similarity {
    match object.shape {
        crate::scene::Shape::Box { .. } => object.similarity(),
        crate::scene::Shape::Points { .. } => Similarity {
            translation: object.world_aabb().bottom_center(),
            ..Similarity::IDENTITY
        },
    }
}

fn update_pose(object: &Object, map: &mut Map<String, Value>) {
    let pose = file_pose(object);
    let unchanged = pose_of(map).is_some_and(|(p, q, s)| {
        (p - pose.translation).abs().max_element() < 1e-12
            && (q.dot(pose.rotation).abs() - 1.0).abs() < 1e-12
            && (s - pose.scale).abs() < 1e-12
    });
    if unchanged {
        return;
    }
    map.insert("position".into(), numbers(pose.translation.to_array()));
    if map.contains_key("rotation") || !pose.rotation.abs_diff_eq(DQuat::IDENTITY, 1e-12) {
        map.insert("rotation".into(), numbers(pose.rotation.to_array()));
    }
    if map.contains_key("scale") || (pose.scale - 1.0).abs() > 1e-12 {
        map.insert("scale".into(), tidy(pose.scale));
    }
}

fn numbers<const N: usize>(values: [f64; N]) -> Value {
    Value::Array(values.into_iter().map(tidy).collect())
}

/// A number for a file: rounded to a nanometre (`super::tidy`); whole numbers are written
/// without a fraction.
fn tidy(x: f64) -> Value {
    let rounded = super::tidy(x);
    if rounded.fract() == 0.0 && rounded.abs() < 1e15 {
        Value::from(rounded as i64)
    } else {
        Value::from(rounded)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cga::Multivector;

    const WORKSHOP: &str = r#"{
  "name": "workshop",
  "units": "metres",
  "bounds": {"min": [-4, 0, -3], "max": [4, 3, 3]},
  "objects": [
    {"name": "tool table", "position": [0, 0, 0], "size": [1.6, 0.9, 0.8], "material": "oak"},
    {"name": "orange bottle", "position": [0.3, 0.9, 0.1], "size": [0.08, 0.25, 0.08],
     "rotation": [0, 0, 0, 1], "scale": 1.0, "tags": ["glass", {"fragile": true}]}
  ],
  "camera": {"fov": 60}
}"#;

    fn err(text: &str) -> String {
        read(text, "x").unwrap_err().to_string()
    }

    #[test]
    fn reads_the_spec_example() {
        let s = read(WORKSHOP, "fallback").unwrap().scene;
        assert_eq!(s.name, "workshop");
        assert_eq!(s.objects.len(), 2);
        assert_eq!(s.objects[1].support, Some(0));
        assert_eq!(s.bounds.unwrap().max, DVec3::new(4.0, 3.0, 3.0));
    }

    #[test]
    fn round_trip_keeps_everything_and_the_shape() {
        let loaded = read(WORKSHOP, "x").unwrap();
        let text = write(&loaded.scene, Some(&loaded.document));
        let again: Value = serde_json::from_str(&text).unwrap();
        assert_eq!(
            again, loaded.document,
            "unchanged scene, identical document"
        );
        let reread = read(&text, "x").unwrap().scene;
        assert_eq!(
            reread.objects[0].similarity(),
            loaded.scene.objects[0].similarity()
        );
    }

    #[test]
    fn edits_rewrite_only_the_moved_poses() {
        let mut loaded = read(WORKSHOP, "x").unwrap();
        loaded
            .scene
            .apply(0, &Multivector::translator(DVec3::new(0.1, 0.0, 0.2)), true)
            .unwrap();
        let text = write(&loaded.scene, Some(&loaded.document));
        let v: Value = serde_json::from_str(&text).unwrap();
        let table = &v["objects"][0];
        assert_eq!(table["position"], serde_json::json!([0.1, 0, 0.2]));
        assert_eq!(table["material"], "oak");
        assert!(
            table.get("rotation").is_none(),
            "no field added that was not needed"
        );
        let bottle = &v["objects"][1];
        assert_eq!(bottle["position"], serde_json::json!([0.4, 0.9, 0.3]));
        assert_eq!(bottle["tags"][1]["fragile"], true);
        assert_eq!(v["camera"]["fov"], 60);
        assert_eq!(v["units"], "metres");
    }

    #[test]
    fn validation_errors_name_the_field() {
        let base: Value = serde_json::from_str(WORKSHOP).unwrap();
        let with = |path: &[&str], value: Value| {
            let mut v = base.clone();
            let mut cursor = &mut v;
            for (k, key) in path.iter().enumerate() {
                cursor = match key.parse::<usize>() {
                    Ok(i) => &mut cursor[i],
                    Err(_) if k == path.len() - 1 => {
                        cursor
                            .as_object_mut()
                            .unwrap()
                            .insert(key.to_string(), value.clone());
                        return err(&v.to_string());
                    }
                    Err(_) => &mut cursor[*key],
                };
            }
            *cursor = value;
            err(&v.to_string())
        };
        assert_eq!(
            with(&["objects", "1", "size", "1"], serde_json::json!(0)),
            "objects[1].size[1] must be > 0"
        );
        assert_eq!(with(&["objects", "1", "name"], serde_json::json!("Tool Table")), "objects[1].name 'Tool Table' duplicates objects[0].name 'tool table' (names are compared case-insensitively)");
        assert_eq!(
            with(
                &["objects", "0", "position"],
                serde_json::json!([0, "a", 0])
            ),
            "objects[0].position[1] must be a finite number, found \"a\""
        );
        assert_eq!(
            with(
                &["objects", "0", "rotation"],
                serde_json::json!([0, 0, 0, 0])
            ),
            "objects[0].rotation must be a non-zero quaternion [x, y, z, w]"
        );
        assert_eq!(
            with(&["objects", "0", "scale"], serde_json::json!(-2)),
            "objects[0].scale must be in [1e-6, 1e6]"
        );
        assert_eq!(
            with(&["bounds", "min"], serde_json::json!([5, 0, 0])),
            "bounds.min[0] must be less than bounds.max[0]"
        );
        let mut v = base.clone();
        v["objects"][0].as_object_mut().unwrap().remove("size");
        assert_eq!(
            err(&v.to_string()),
            "objects[0] ('tool table'): missing \"size\" [w, h, d]"
        );
        assert!(err("{\"objects\": [}").starts_with("invalid JSON at line 1, column 14"));
        assert_eq!(
            err("[]"),
            "the scene must be a JSON object with an \"objects\" list"
        );
        assert_eq!(
            err("{}"),
            "missing \"objects\": the list of the scene's objects"
        );
        // NaN cannot be written in JSON; a huge number is out of range.
        let huge = r#"{"objects": [{"name": "a", "size": [1, 1, 1], "position": [1e999, 0, 0]}]}"#;
        assert!(err(huge).contains("number out of range"), "{}", err(huge));
    }
}

#[cfg(test)]
mod bom_tests {
    #[test]
    fn a_byte_order_mark_is_not_an_error() {
        let text = "\u{feff}{\"objects\": [{\"name\": \"a\", \"size\": [1, 1, 1], \"position\": [0, 0, 0], \"front\": [0, 0, -2]}]}";
        let scene = super::read(text, "t").unwrap().scene;
        assert_eq!(scene.objects[0].front, glam::DVec3::NEG_Z);
        let e = super::read("{\"objects\": [{\"name\": \"a\", \"size\": [1, 1, 1], \"position\": [0, 0, 0], \"front\": [0, 0, 0]}]}", "t").unwrap_err();
        assert!(
            e.message
                .contains("objects[0].front must be a non-zero direction"),
            "{}",
            e.message
        );
    }
}

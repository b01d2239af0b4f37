//! Shenlong's scene JSON (SPEC §2): read with validation, written back in the input's
//! shape with every unknown field kept.
//!
//! Reading keeps the text, not a parsed tree: `serde_json` checks the whole document and
//! hands back each object's fields as borrowed slices ([`RawValue`]); the poses are parsed
//! straight into numbers, and an error message is built only when something is wrong.
//! Writing copies the text and rewrites only the `position`, `rotation` and `scale` of
//! the objects that moved, so it costs what changed, and a file under version control
//! shows only the edit in its diff.

use super::{strip_position, tidy_json, FormatError};
use crate::geometry::Aabb;
use crate::scene::{Labels, Object, Scene, MAX_COORDINATE, MAX_SCALE, MIN_SCALE};
use cga::Similarity;
use glam::{DQuat, DVec3};
use rustc_hash::FxHashMap;
use serde::Deserialize;
use serde_json::value::RawValue;
use serde_json::{Map, Value};
use std::ops::Range;

/// A scene read from scene JSON, with the document it came from.
#[derive(Clone, Debug)]
pub struct JsonScene {
    /// The scene.
    pub scene: Scene,
    /// The document, kept so that writing preserves every other field and byte.
    pub document: JsonDocument,
}

/// A scene-JSON document as read: its text and where each object's pose is written.
#[derive(Clone, Debug)]
pub struct JsonDocument {
    text: String,
    objects: Vec<PoseFields>,
}

/// Where one object's pose is in the text, and the pose as written.
#[derive(Clone, Debug)]
struct PoseFields {
    /// The object's `{…}`.
    object: Range<usize>,
    /// The value of `position`.
    position: Range<usize>,
    /// The value of `rotation`, if the field is there.
    rotation: Option<Range<usize>>,
    /// The value of `scale`, if the field is there.
    scale: Option<Range<usize>>,
    /// The value of `on`, if the field is there, and the support it names (`None` for
    /// `null`): rewritten when an edit leaves the object resting elsewhere.
    on: Option<(Range<usize>, Option<usize>)>,
    /// The pose as the file has it.
    read: Similarity,
}

impl JsonDocument {
    /// The document's text (without a byte-order mark).
    #[must_use]
    pub fn text(&self) -> &str {
        &self.text
    }

    /// A top-level field of object `index`, parsed (`tdw_id`); `None` when the object or
    /// the field is missing.
    #[must_use]
    pub fn object_field(&self, index: usize, field: &str) -> Option<Value> {
        let span = self.objects.get(index)?.object.clone();
        // (Owned keys: a key written with escapes cannot be borrowed from the text.)
        let fields: FxHashMap<String, &RawValue> = serde_json::from_str(&self.text[span]).ok()?;
        serde_json::from_str(fields.get(field)?.get()).ok()
    }
}

/// A field that is present, `null` included (serde would read a `null` as absent, and the
/// writer must know the key is there to rewrite it rather than add a second one).
fn present<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<&'de RawValue>, D::Error> {
    <&'de RawValue>::deserialize(d).map(Some)
}

#[derive(Deserialize)]
struct RawRoot<'a> {
    #[serde(borrow, default, deserialize_with = "present")]
    name: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    bounds: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    objects: Option<&'a RawValue>,
}

#[derive(Deserialize)]
struct RawObject<'a> {
    #[serde(borrow, default, deserialize_with = "present")]
    name: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    size: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    position: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    rotation: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    scale: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    front: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    on: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    category: Option<&'a RawValue>,
    #[serde(borrow, default, rename = "objectType", deserialize_with = "present")]
    object_type: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    aliases: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    color: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    colour: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    material: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    form: Option<&'a RawValue>,
    #[serde(borrow, default, deserialize_with = "present")]
    room_below: Option<&'a RawValue>,
}

/// Parses and validates scene JSON. `fallback_name` names a scene without a `"name"`.
pub fn read(text: &str, fallback_name: &str) -> Result<JsonScene, FormatError> {
    read_string(text.to_string(), fallback_name)
}

/// [`read`], keeping `text` itself as the document (no copy of a large file).
pub fn read_string(mut text: String, fallback_name: &str) -> Result<JsonScene, FormatError> {
    // A UTF-8 byte-order mark, as some editors write, is not part of the JSON.
    if text.starts_with('\u{feff}') {
        text.drain(..'\u{feff}'.len_utf8());
    }
    super::check_json_depth(text.as_bytes())?;
    let (scene, objects) = parse(&text, fallback_name)?;
    Ok(JsonScene {
        scene,
        document: JsonDocument { text, objects },
    })
}

/// Builds a scene from a parsed scene-JSON document (a ProcTHOR import), validating every
/// field; the document to write it back is its indented text.
pub fn scene_from_value(
    document: &Value,
    fallback_name: &str,
) -> Result<(Scene, JsonDocument), FormatError> {
    let loaded = read(&super::pretty::to_string(document), fallback_name)?;
    Ok((loaded.scene, loaded.document))
}

/// Where `slice` (borrowed from `text`) starts in `text`.
fn offset(text: &str, slice: &str) -> usize {
    slice.as_ptr() as usize - text.as_ptr() as usize
}

fn span(text: &str, raw: &RawValue) -> Range<usize> {
    let start = offset(text, raw.get());
    start..start + raw.get().len()
}

/// A `serde_json` error in `slice` (borrowed from `text`), placed in the whole text.
fn json_error(text: &str, slice: &str, e: &serde_json::Error) -> FormatError {
    let start = offset(text, slice);
    let before = &text[..start];
    let line0 = before.matches('\n').count() + 1;
    let col0 = before.len() - before.rfind('\n').map_or(0, |i| i + 1);
    let (line, column) = if e.line() <= 1 {
        (line0, col0 + e.column())
    } else {
        (line0 + e.line() - 1, e.column())
    };
    FormatError::Syntax {
        what: "JSON",
        line,
        column,
        message: strip_position(&e.to_string()),
    }
}

/// A field's value as a tree, for the checks that name what is wrong.
fn value_of(text: &str, raw: &RawValue) -> Result<Value, FormatError> {
    serde_json::from_str(raw.get()).map_err(|e| json_error(text, raw.get(), &e))
}

fn starts_with(raw: &str, c: char) -> bool {
    raw.trim_start().starts_with(c)
}

fn parse(text: &str, fallback_name: &str) -> Result<(Scene, Vec<PoseFields>), FormatError> {
    let root: Result<RawRoot<'_>, _> = serde_json::from_str(text);
    let root = match root {
        Err(e) if e.classify() == serde_json::error::Category::Data && !starts_with(text, '{') => {
            return Err(FormatError::invalid(
                "the scene must be a JSON object with an \"objects\" list",
            ))
        }
        Err(e) => return Err(FormatError::json_syntax("JSON", &e)),
        Ok(_) if !starts_with(text, '{') => {
            return Err(FormatError::invalid(
                "the scene must be a JSON object with an \"objects\" list",
            ))
        }
        Ok(root) => root,
    };
    let name = match root.name.map(|raw| value_of(text, raw)).transpose()? {
        None | Some(Value::Null) => fallback_name.to_string(),
        Some(Value::String(s)) => s,
        Some(_) => return Err(FormatError::invalid("name must be a string")),
    };
    let mut scene = Scene::new(name);
    if let Some(bounds) = root.bounds.map(|raw| value_of(text, raw)).transpose()? {
        if !bounds.is_null() {
            let b = bounds.as_object().ok_or_else(|| {
                FormatError::invalid("bounds must be an object with \"min\" and \"max\"")
            })?;
            let min = vec3(b.get("min"), "bounds.min")?;
            let max = vec3(b.get("max"), "bounds.max")?;
            for axis in 0..3 {
                if min[axis] >= max[axis] {
                    return Err(FormatError::invalid(format!(
                        "bounds.min[{axis}] must be less than bounds.max[{axis}]"
                    )));
                }
            }
            scene.bounds = Some(Aabb::new(min, max));
        }
    }
    let objects = root.objects.ok_or_else(|| {
        FormatError::invalid("missing \"objects\": the list of the scene's objects")
    })?;
    let objects: Vec<&RawValue> = if starts_with(objects.get(), '[') {
        serde_json::from_str(objects.get()).map_err(|e| json_error(text, objects.get(), &e))?
    } else {
        return Err(FormatError::invalid("objects must be a list"));
    };
    // Names compared case-insensitively, through an index: a scan per object would make
    // reading quadratic in the number of objects.
    let mut by_name: FxHashMap<String, usize> =
        FxHashMap::with_capacity_and_hasher(objects.len(), Default::default());
    let mut fields = Vec::with_capacity(objects.len());
    let mut on_fields: Vec<(usize, &RawValue)> = Vec::new();
    scene.objects.reserve(objects.len());
    for (i, raw) in objects.iter().enumerate() {
        let (object, pose, on) = object_from_raw(text, raw, i)?;
        let key = object.name.trim().to_lowercase();
        if let Some(&j) = by_name.get(&key) {
            return Err(FormatError::invalid(format!(
                "objects[{i}].name '{}' duplicates objects[{j}].name '{}' (names are compared case-insensitively)",
                object.name, scene.objects[j].name
            )));
        }
        by_name.insert(key, i);
        scene.objects.push(object);
        fields.push(pose);
        if let Some(on) = on {
            on_fields.push((i, on));
        }
    }
    resolve_on_fields(text, &on_fields, &mut scene, &by_name)?;
    for &(i, _) in &on_fields {
        if let Some((_, support)) = &mut fields[i].on {
            *support = scene.objects[i].support;
        }
    }
    scene.detect_supports();
    Ok((scene, fields))
}

/// The optional `"on"` field (a Shenlong extension of SPEC §2) names the object this one
/// rests on; it is carried along with it.
fn resolve_on_fields(
    text: &str,
    on_fields: &[(usize, &RawValue)],
    scene: &mut Scene,
    by_name: &FxHashMap<String, usize>,
) -> Result<(), FormatError> {
    for &(i, raw) in on_fields {
        let on = value_of(text, raw)?;
        if on.is_null() {
            continue;
        }
        let name = on.as_str().ok_or_else(|| {
            FormatError::invalid(format!(
                "objects[{i}].on must be the name of another object"
            ))
        })?;
        let j = by_name
            .get(&name.trim().to_lowercase())
            .copied()
            .ok_or_else(|| {
                FormatError::invalid(format!(
                    "objects[{i}].on '{name}' names no object of the scene"
                ))
            })?;
        if j == i {
            return Err(FormatError::invalid(format!(
                "objects[{i}].on names the object itself"
            )));
        }
        scene.objects[i].support = Some(j);
        scene.objects[i].support_from_file = true;
    }
    // A chain of supports must end on the floor: follow each chain once, marking where
    // it was seen (linear in the objects however the chains run).
    let n = scene.objects.len();
    let mut state = vec![0u8; n]; // 0 unseen, 1 on the current chain, 2 ends on the floor
    for start in 0..n {
        let mut chain = Vec::new();
        let mut current = Some(start);
        while let Some(c) = current {
            match state[c] {
                2 => break,
                1 => {
                    return Err(FormatError::invalid(format!(
                        "objects[{c}].on: the objects rest on each other in a circle"
                    )))
                }
                _ => {
                    state[c] = 1;
                    chain.push(c);
                    current = scene.objects[c].support;
                }
            }
        }
        for c in chain {
            state[c] = 2;
        }
    }
    Ok(())
}

/// A list of finite numbers (`[f64; 3]`, `[f64; 4]`), fast; `None` when the text is
/// anything else.
fn numbers_of<T: serde::de::DeserializeOwned + AsRef<[f64]>>(raw: &RawValue) -> Option<T> {
    let v: T = serde_json::from_str(raw.get()).ok()?;
    v.as_ref().iter().all(|x| x.is_finite()).then_some(v)
}

/// A required or optional three-number field: fast when it is one, else the message that
/// says what is wrong with it.
fn vec3_field(
    text: &str,
    raw: Option<&RawValue>,
    at: &dyn Fn() -> String,
) -> Result<Option<DVec3>, FormatError> {
    let Some(raw) = raw else { return Ok(None) };
    if let Some(v) = numbers_of::<[f64; 3]>(raw) {
        return Ok(Some(DVec3::from(v)));
    }
    let value = value_of(text, raw)?;
    if value.is_null() {
        return Ok(None);
    }
    vec3(Some(&value), &at()).map(Some)
}

fn object_from_raw<'a>(
    text: &'a str,
    raw: &'a RawValue,
    i: usize,
) -> Result<(Object, PoseFields, Option<&'a RawValue>), FormatError> {
    if !starts_with(raw.get(), '{') {
        return Err(FormatError::invalid(format!(
            "objects[{i}] must be an object"
        )));
    }
    let o: RawObject<'a> = serde_json::from_str(raw.get()).map_err(|e| {
        if e.classify() == serde_json::error::Category::Data {
            FormatError::invalid(format!("objects[{i}]: {}", strip_position(&e.to_string())))
        } else {
            json_error(text, raw.get(), &e)
        }
    })?;
    let field = |name: &str| format!("objects[{i}].{name}");
    let name = match o.name {
        None => {
            return Err(FormatError::invalid(format!(
                "objects[{i}]: missing \"name\""
            )))
        }
        Some(raw) => match serde_json::from_str::<String>(raw.get()) {
            Ok(s) if !s.trim().is_empty() => s,
            Ok(_) => {
                return Err(FormatError::invalid(format!(
                    "{} must not be empty",
                    field("name")
                )))
            }
            Err(_) => {
                value_of(text, raw)?;
                return Err(FormatError::invalid(format!(
                    "{} must be a string",
                    field("name")
                )));
            }
        },
    };
    let size = vec3_field(text, o.size, &|| field("size"))?.ok_or_else(|| {
        FormatError::invalid(format!(
            "objects[{i}] ('{name}'): missing \"size\" [w, h, d]"
        ))
    })?;
    for axis in 0..3 {
        if size[axis] <= 0.0 {
            return Err(FormatError::invalid(format!(
                "{}[{axis}] must be > 0",
                field("size")
            )));
        }
        if size[axis] > MAX_COORDINATE {
            return Err(FormatError::invalid(format!(
                "{}[{axis}] must be at most {MAX_COORDINATE:.0e} m",
                field("size")
            )));
        }
    }
    let missing_position = || {
        FormatError::invalid(format!(
            "objects[{i}] ('{name}'): missing \"position\" [x, y, z]"
        ))
    };
    let position_raw = o.position.ok_or_else(missing_position)?;
    let position = vec3_field(text, Some(position_raw), &|| field("position"))?
        .ok_or_else(missing_position)?;
    for axis in 0..3 {
        if position[axis].abs() > MAX_COORDINATE {
            return Err(FormatError::invalid(format!(
                "{}[{axis}] must be within ±{MAX_COORDINATE:.0e} m",
                field("position")
            )));
        }
    }
    let rotation = match o.rotation {
        None => DQuat::IDENTITY,
        Some(raw) => match numbers_of::<[f64; 4]>(raw) {
            Some(q) => quaternion(q, &|| field("rotation"))?,
            None => rotation(Some(&value_of(text, raw)?), &field("rotation"))?,
        },
    };
    let scale = match o.scale {
        None => 1.0,
        Some(raw) => scale_of(text, raw, &field("scale"))?,
    };
    let mut object = Object::new_box(name, size, position, rotation, scale)
        .map_err(|e| FormatError::invalid(format!("objects[{i}]: {e}")))?;
    object.labels = labels(text, &o, i)?;
    object.form = o.form.map(|raw| form(raw, i)).transpose()?;
    if let Some(raw) = o.room_below {
        object.form = Some(room_below(raw, object.form, size.y * scale, i)?);
    }
    if let Some(f) = vec3_field(text, o.front, &|| field("front"))? {
        if f.length() < 1e-9 {
            return Err(FormatError::invalid(format!(
                "{} must be a non-zero direction [x, y, z]",
                field("front")
            )));
        }
        object.front = f.normalize();
    }
    let pose = PoseFields {
        object: span(text, raw),
        position: span(text, position_raw),
        rotation: o.rotation.map(|r| span(text, r)),
        scale: o.scale.map(|r| span(text, r)),
        on: o.on.map(|r| (span(text, r), None)),
        read: Similarity {
            translation: position,
            rotation,
            scale,
        },
    };
    Ok((object, pose, o.on))
}

/// An object's `scale`: a finite number within [`MIN_SCALE`, `MAX_SCALE`], `null` for 1.
fn scale_of(text: &str, raw: &RawValue, field: &str) -> Result<f64, FormatError> {
    let s = match serde_json::from_str::<f64>(raw.get()) {
        Ok(s) if s.is_finite() => s,
        _ => {
            let v = value_of(text, raw)?;
            if v.is_null() {
                1.0
            } else {
                number(&v, field)?
            }
        }
    };
    if !(MIN_SCALE..=MAX_SCALE).contains(&s) {
        return Err(FormatError::invalid(format!(
            "{field} must be in [{MIN_SCALE:.0e}, {MAX_SCALE:.0e}]"
        )));
    }
    Ok(s)
}

/// An object's `form` (a documented extension of SPEC §2): what of its box is solid.
fn form(raw: &RawValue, i: usize) -> Result<crate::scene::Form, FormatError> {
    serde_json::from_str::<String>(raw.get())
        .ok()
        .and_then(|name| crate::scene::Form::from_name(&name))
        .ok_or_else(|| {
            FormatError::invalid(format!(
                "objects[{i}].form must be \"solid\", \"on_legs\" (a top on legs, with room below), \"open\" (an open container) or \"shelves\" (a case of shelves)"
            ))
        })
}

/// An object's `room_below` (a documented extension of SPEC §2): how high the room under
/// a top on legs reaches from its bottom, in metres (a bed whose frame stands 0.25 m off
/// the floor), with `form` "on_legs" or none; `height` is the object's.
fn room_below(
    raw: &RawValue,
    form: Option<crate::scene::Form>,
    height: f64,
    i: usize,
) -> Result<crate::scene::Form, FormatError> {
    if form.is_some_and(|f| !f.on_legs()) {
        return Err(FormatError::invalid(format!(
            "objects[{i}].room_below goes with \"form\": \"on_legs\" (or no form), not \"{}\"",
            form.map_or("", crate::scene::Form::name)
        )));
    }
    let metres = serde_json::from_str::<f64>(raw.get())
        .ok()
        .filter(|m| m.is_finite() && (0.0..=height).contains(m))
        .ok_or_else(|| {
            FormatError::invalid(format!(
                "objects[{i}].room_below must be a number of metres from 0 to the object's height ({height:.3} m)"
            ))
        })?;
    let permille = (metres / height * 1000.0).round().clamp(0.0, 1000.0) as u16;
    Ok(crate::scene::Form::OnLegs {
        underside: Some(permille),
    })
}

/// The optional words for an object (a documented extension of SPEC §2): `category` (a
/// string; else a ProcTHOR `objectType` in plain words), `aliases` (strings), and the
/// attributes `color` / `colour` / `material` (a string or a list of strings).
fn labels(text: &str, o: &RawObject<'_>, i: usize) -> Result<Labels, FormatError> {
    let strings = |raw: Option<&RawValue>,
                   field: &str,
                   list_ok: bool|
     -> Result<Vec<String>, FormatError> {
        let Some(raw) = raw else {
            return Ok(Vec::new());
        };
        match value_of(text, raw)? {
            Value::Null => Ok(Vec::new()),
            Value::String(s) => Ok(vec![s.trim().to_string()]),
            Value::Array(items) if list_ok => items
                .iter()
                .enumerate()
                .map(|(k, v)| {
                    v.as_str().map(|s| s.trim().to_string()).ok_or_else(|| {
                        FormatError::invalid(format!("objects[{i}].{field}[{k}] must be a string"))
                    })
                })
                .collect(),
            _ if list_ok => Err(FormatError::invalid(format!(
                "objects[{i}].{field} must be a string or a list of strings"
            ))),
            _ => Err(FormatError::invalid(format!(
                "objects[{i}].{field} must be a string"
            ))),
        }
    };
    let mut category = strings(o.category, "category", false)?.pop();
    if category.is_none() {
        if let Some(raw) = o.object_type {
            if let Ok(t) = serde_json::from_str::<String>(raw.get()) {
                category = Some(super::procthor::human_name(&t));
            }
        }
    }
    let mut attributes = strings(o.color, "color", true)?;
    attributes.extend(strings(o.colour, "colour", true)?);
    attributes.extend(strings(o.material, "material", true)?);
    Ok(Labels {
        category: category.filter(|c| !c.is_empty()),
        aliases: strings(o.aliases, "aliases", true)?
            .into_iter()
            .filter(|a| !a.is_empty())
            .collect(),
        attributes: attributes.into_iter().filter(|a| !a.is_empty()).collect(),
    })
}

/// A quaternion from four finite numbers, normalised safely.
fn quaternion(q: [f64; 4], at: &dyn Fn() -> String) -> Result<DQuat, FormatError> {
    // Scaled down first, so components near f64::MAX do not overflow the length.
    let big = q.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let q = if big > 1.0 { q.map(|x| x / big) } else { q };
    let q = DQuat::from_array(q);
    let length = q.length();
    if length.is_nan() || length <= 1e-9 {
        return Err(FormatError::invalid(format!(
            "{} must be a non-zero quaternion [x, y, z, w]",
            at()
        )));
    }
    Ok(q / length)
}

fn rotation(value: Option<&Value>, at: &str) -> Result<DQuat, FormatError> {
    let Some(value) = value.filter(|v| !v.is_null()) else {
        return Ok(DQuat::IDENTITY);
    };
    let list = value
        .as_array()
        .filter(|a| a.len() == 4)
        .ok_or_else(|| FormatError::invalid(format!("{at} must be a quaternion [x, y, z, w]")))?;
    let mut q = [0.0; 4];
    for (k, v) in list.iter().enumerate() {
        q[k] = number(v, &format!("{at}[{k}]"))?;
    }
    quaternion(q, &|| at.to_string())
}

fn vec3(value: Option<&Value>, at: &str) -> Result<DVec3, FormatError> {
    let list = value
        .and_then(Value::as_array)
        .filter(|a| a.len() == 3)
        .ok_or_else(|| {
            FormatError::invalid(format!("{at} must be a list of three numbers [x, y, z]"))
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
        _ => Err(FormatError::invalid(format!(
            "{at} must be a finite number, found {value}"
        ))),
    }
}

/// Writes the scene as scene JSON. With the `original` document, the output is its text
/// with only the poses of objects that moved rewritten in place (`rotation` and `scale`
/// are added only when they differ from their defaults); without it, a fresh indented
/// document.
pub fn write(scene: &Scene, original: Option<&JsonDocument>) -> String {
    match original {
        Some(document) if document.objects.len() == scene.objects.len() => patched(scene, document),
        _ => super::pretty::to_string(&fresh_document(scene)),
    }
}

/// The document's text with the moved objects' pose fields replaced (or added after
/// `position`): every other byte as it was.
fn patched(scene: &Scene, document: &JsonDocument) -> String {
    // (where, order, what): a replacement of `where`, or an insertion when it is empty.
    let mut edits: Vec<(Range<usize>, u8, String)> = Vec::new();
    for (object, fields) in scene.objects.iter().zip(&document.objects) {
        let pose = file_pose(object);
        let read = fields.read;
        let moved = (read.translation - pose.translation).abs().max_element() >= 1e-12;
        let turned = (read.rotation.dot(pose.rotation).abs() - 1.0).abs() >= 1e-12;
        let scaled = (read.scale - pose.scale).abs() >= 1e-12;
        if moved {
            edits.push((
                fields.position.clone(),
                0,
                list_text(&pose.translation.to_array()),
            ));
        }
        let after_position = fields.position.end..fields.position.end;
        match &fields.rotation {
            Some(r) if turned => edits.push((r.clone(), 0, list_text(&pose.rotation.to_array()))),
            None if turned => edits.push((
                after_position.clone(),
                1,
                format!(", \"rotation\": {}", list_text(&pose.rotation.to_array())),
            )),
            _ => {}
        }
        match &fields.scale {
            Some(r) if scaled => edits.push((r.clone(), 0, number_text(pose.scale))),
            None if scaled => edits.push((
                after_position,
                2,
                format!(", \"scale\": {}", number_text(pose.scale)),
            )),
            _ => {}
        }
        // An object the file put `on` a support and that rests elsewhere now (a lamp moved
        // from its table to the floor) names its new support, or `null`: a stale name
        // would carry it with the old table when the file is read again.
        if let Some((range, read)) = &fields.on {
            if object.support != *read {
                let now = object.support.map_or(Value::Null, |s| {
                    Value::String(scene.objects[s].name.clone())
                });
                edits.push((range.clone(), 0, now.to_string()));
            }
        }
    }
    edits.sort_by_key(|(range, order, _)| (range.start, *order));
    let text = &document.text;
    let mut out = String::with_capacity(text.len() + edits.len() * 16 + 1);
    let mut at = 0;
    for (range, _, replacement) in &edits {
        out.push_str(&text[at..range.start]);
        out.push_str(replacement);
        at = range.end;
    }
    out.push_str(&text[at..]);
    if !out.ends_with('\n') {
        out.push('\n');
    }
    out
}

/// `[a, b, c]`, each number as [`tidy_json`] writes it.
fn list_text(values: &[f64]) -> String {
    let items: Vec<String> = values.iter().map(|&x| number_text(x)).collect();
    format!("[{}]", items.join(", "))
}

fn number_text(x: f64) -> String {
    tidy_json(x).to_string()
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
            let pose = file_pose(o);
            let mut v = serde_json::json!({
                "name": o.name,
                "size": numbers(size.to_array()),
                "position": numbers(pose.translation.to_array()),
            });
            if !pose.rotation.abs_diff_eq(DQuat::IDENTITY, 1e-12) {
                v["rotation"] = numbers(pose.rotation.to_array());
            }
            if (pose.scale - 1.0).abs() > 1e-12 {
                v["scale"] = tidy_json(pose.scale);
            }
            if (o.front - DVec3::Z).length() > 1e-12 {
                v["front"] = serde_json::json!(numbers(o.front.to_array()));
            }
            if let Some(form) = written_form(o) {
                v["form"] = Value::String(form.name().into());
                if let crate::scene::Form::OnLegs {
                    underside: Some(permille),
                } = form
                {
                    let below = o.world_aabb().size().y * f64::from(permille) / 1000.0;
                    v["room_below"] = tidy_json((below * 1e4).round() / 1e4);
                }
            }
            v
        })
        .collect();
    root.insert("objects".into(), Value::Array(objects));
    Value::Object(root)
}

/// The form a new scene file records for an object: its own, else what its mesh shows of
/// room under it (with how high: `room_below`) or in it (`scene::mesh`); a mesh that shows
/// neither leaves its kind to decide when the file is read.
fn written_form(object: &Object) -> Option<crate::scene::Form> {
    use crate::scene::{mesh::Measured, Form};
    object.form.or(match object.measured? {
        Measured::Under { underside } => Some(Form::OnLegs {
            underside: Some(underside),
        }),
        Measured::Inside => Some(Form::Open),
        Measured::Shelves(_) => Some(Form::SHELVES),
        Measured::Neither => None,
    })
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

fn numbers<const N: usize>(values: [f64; N]) -> Value {
    Value::Array(values.into_iter().map(tidy_json).collect())
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
        assert_eq!(
            text,
            format!("{WORKSHOP}\n"),
            "unchanged scene, identical text"
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
        // Only the moved poses changed: every other line is as it was.
        let changed: Vec<(&str, &str)> = WORKSHOP
            .lines()
            .zip(text.lines())
            .filter(|(a, b)| a != b)
            .collect();
        assert_eq!(changed.len(), 2, "{changed:?}");
    }

    #[test]
    fn an_on_field_names_where_the_object_rests_after_the_edit() {
        let text = r#"{"objects": [
  {"name": "Table", "size": [1, 0.8, 1], "position": [0, 0, 0]},
  {"name": "Lamp", "size": [0.2, 0.4, 0.2], "position": [0, 0.8, 0], "on": "Table"},
  {"name": "Shelf", "size": [1, 1, 0.4], "position": [3, 0, 0]},
  {"name": "Vase", "size": [0.1, 0.3, 0.1], "position": [0.3, 0.8, 0], "on": "Table"}
]}"#;
        let mut loaded = read(text, "x").unwrap();
        // The lamp goes to the floor; the vase onto the shelf, as an edit re-detects them.
        let down = Multivector::translator(DVec3::new(1.5, -0.8, 0.0));
        loaded.scene.apply(1, &down, false).unwrap();
        let over = Multivector::translator(DVec3::new(2.7, 0.2, 0.0));
        loaded.scene.apply(3, &over, false).unwrap();
        for i in [1, 3] {
            loaded.scene.objects[i].support_from_file = false;
        }
        loaded.scene.detect_supports();
        let written = write(&loaded.scene, Some(&loaded.document));
        let v: Value = serde_json::from_str(&written).unwrap();
        assert_eq!(v["objects"][1]["on"], Value::Null);
        assert_eq!(v["objects"][3]["on"], "Shelf");
        // Read again, the table carries neither.
        let again = read(&written, "x").unwrap();
        assert_eq!(again.scene.objects[1].support, None);
        assert_eq!(again.scene.objects[3].support, Some(2));
        // An object still on its support keeps its field as written.
        let unchanged = write(
            &read(text, "x").unwrap().scene,
            Some(&read(text, "x").unwrap().document),
        );
        assert_eq!(unchanged, format!("{text}\n"));
    }

    #[test]
    fn fields_a_moved_object_lacked_are_added_after_its_position() {
        let mut loaded = read(WORKSHOP, "x").unwrap();
        let turn = Multivector::rotor(0.5, &Multivector::e3(), &Multivector::e1()).unwrap()
            * Multivector::dilator(2.0).unwrap();
        loaded.scene.apply(0, &turn, false).unwrap();
        let text = write(&loaded.scene, Some(&loaded.document));
        let v: Value = serde_json::from_str(&text).unwrap();
        let table = &v["objects"][0];
        assert_eq!(table["scale"], 2);
        assert!(table["rotation"].as_array().is_some_and(|q| q.len() == 4));
        assert_eq!(table["material"], "oak");
        let reread = read(&text, "x").unwrap().scene;
        let (a, b) = (
            reread.objects[0].similarity(),
            loaded.scene.objects[0].similarity(),
        );
        assert!((a.translation - b.translation).length() < 1e-9);
        assert!(a.rotation.dot(b.rotation).abs() > 1.0 - 1e-12);
        // Fields written before `position`, and a document on one line.
        let compact = r#"{"objects":[{"rotation":[0,0,0,1],"name":"a","size":[1,1,1],"position":[0,0,0],"tdw_id":7}]}"#;
        let mut loaded = read(compact, "x").unwrap();
        loaded
            .scene
            .apply(0, &Multivector::translator(DVec3::X), false)
            .unwrap();
        let text = write(&loaded.scene, Some(&loaded.document));
        assert_eq!(
            text,
            "{\"objects\":[{\"rotation\":[0,0,0,1],\"name\":\"a\",\"size\":[1,1,1],\"position\":[1, 0, 0],\"tdw_id\":7}]}\n"
        );
        assert_eq!(
            loaded.document.object_field(0, "tdw_id"),
            Some(Value::from(7))
        );
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
        // A repeated field is ambiguous: refused, not read as the last one.
        let twice = r#"{"objects": [{"name": "a", "size": [1, 1, 1], "position": [0, 0, 0], "position": [1, 0, 0]}]}"#;
        assert_eq!(err(twice), "objects[0]: duplicate field `position`");
        // Errors inside an object say where in the file.
        let bad = "{\"objects\": [\n  {\"name\": \"a\", \"size\": [1, 1, 1], \"position\": [1e999, 0, 0]}]}";
        assert!(
            err(bad).starts_with("invalid JSON at line 2, column "),
            "{}",
            err(bad)
        );
        // The kind and the place are data.
        match read(bad, "t").map(|_| ()).unwrap_err() {
            FormatError::Syntax { what, line, .. } => assert_eq!((what, line), ("JSON", 2)),
            other => panic!("{other:?}"),
        }
        let missing = read("{\"objects\": [{\"name\": \"a\"}]}", "t").map(|_| ());
        assert!(
            matches!(missing, Err(FormatError::Invalid(ref m)) if m.contains("size")),
            "{missing:?}"
        );
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
            e.to_string()
                .contains("objects[0].front must be a non-zero direction"),
            "{}",
            e.to_string()
        );
    }
}

#[cfg(test)]
mod depth_tests {
    /// A one-object scene with `depth` levels of brackets in an unknown field.
    fn nested(depth: usize) -> String {
        format!(
            "{{\"objects\": [\n  {{\"name\": \"a\", \"size\": [1, 1, 1], \"position\": [0, 0, 0], \"junk\": {}{}}}]}}",
            "[".repeat(depth),
            "]".repeat(depth)
        )
    }

    #[test]
    fn nesting_beyond_the_limit_is_refused_with_where() {
        // Root, list and object are three levels: 97 more reach the limit.
        let loaded = super::read(&nested(97), "t").unwrap();
        // What the servers do with a scene: the text parses as a tree.
        serde_json::from_str::<serde_json::Value>(loaded.document.text()).unwrap();
        let e = super::read(&nested(200), "t").unwrap_err();
        assert_eq!(
            e.to_string(),
            "nesting deeper than 100 levels at line 2, column 164"
        );
        // Brackets inside strings are text.
        let text = nested(1).replace("\"a\"", &format!("\"{}\"", "[{".repeat(300)));
        assert_eq!(super::read(&text, "t").unwrap().scene.objects.len(), 1);
        let escaped = nested(1).replace("\"a\"", "\"a\\\"[[[[\"");
        assert_eq!(super::read(&escaped, "t").unwrap().scene.objects.len(), 1);
    }
}

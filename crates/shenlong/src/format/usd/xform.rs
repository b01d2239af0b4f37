//! What the walk reads of a prim's attributes, whoever read them (the composed stage of
//! the `openusd` crate, or Shenlong's own layer reader, [`super::layer`]): the values as
//! one small type ([`Attr`]), and the transform ops and geometry extents computed from them.

use super::super::FormatError;
use glam::{DMat4, DQuat, DVec3};

/// An attribute's default value, as the walk needs it.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Attr {
    /// A number (`double`, `float`, `half`, `int` …).
    Scalar(f64),
    /// A 3-vector (`double3`, `float3`, `point3f` …).
    Vec3(DVec3),
    /// A quaternion, normalised (or the zero quaternion as written).
    Quat(DQuat),
    /// A `matrix4d` (column vectors: USD's rows are its columns).
    Matrix(Box<DMat4>),
    /// A `token`, `string` or `asset`, its escapes undone.
    Text(String),
    /// A `token[]` or `string[]`.
    Texts(Vec<String>),
    /// An array of 3-vectors (`point3f[] points`, `float3[] extent`).
    Points(Vec<DVec3>),
    /// An array of integers (`int[] faceVertexIndices`).
    Ints(Vec<i64>),
}

impl Attr {
    fn scalar(&self) -> Option<f64> {
        match self {
            Attr::Scalar(x) => Some(*x),
            _ => None,
        }
    }

    fn vec3(&self) -> Option<DVec3> {
        match self {
            Attr::Vec3(v) => Some(*v),
            _ => None,
        }
    }

    /// The text of a token or string.
    pub(super) fn text(&self) -> Option<&str> {
        match self {
            Attr::Text(t) => Some(t),
            _ => None,
        }
    }

    /// A direction: a finite, non-zero 3-vector.
    pub(super) fn direction(&self) -> Option<DVec3> {
        self.vec3().filter(|d| d.is_finite() && d.length() > 0.0)
    }

    /// A quaternion from its parts as USD writes them (real part first), normalised.
    pub(super) fn quat(w: f64, x: f64, y: f64, z: f64) -> Self {
        let q = DQuat::from_xyzw(x, y, z, w);
        Attr::Quat(if q.length() > 0.0 { q.normalize() } else { q })
    }
}

/// How the walk reads one prim's attributes: by name, the default value.
pub(super) type Attrs<'a> = &'a dyn Fn(&str) -> Option<Attr>;

/// The order of a prim's transform ops, as authored.
fn op_order(attrs: Attrs<'_>) -> Vec<String> {
    match attrs("xformOpOrder") {
        Some(Attr::Texts(v)) => v,
        _ => Vec::new(),
    }
}

/// One op's matrix (column vectors); `path` names the prim in errors.
fn op_matrix(attrs: Attrs<'_>, path: &str, op: &str) -> Result<DMat4, FormatError> {
    let (inverted, name) = match op.strip_prefix("!invert!") {
        Some(rest) => (true, rest),
        None => (false, op),
    };
    let Some(value) = attrs(name) else {
        return Ok(DMat4::IDENTITY);
    };
    let kind = name
        .strip_prefix("xformOp:")
        .and_then(|k| k.split(':').next())
        .unwrap_or_default();
    let number = |default: f64| value.scalar().unwrap_or(default);
    let angle = || number(0.0).to_radians();
    let m = match kind {
        "translate" => DMat4::from_translation(value.vec3().unwrap_or(DVec3::ZERO)),
        "translateX" => DMat4::from_translation(DVec3::X * number(0.0)),
        "translateY" => DMat4::from_translation(DVec3::Y * number(0.0)),
        "translateZ" => DMat4::from_translation(DVec3::Z * number(0.0)),
        "scale" => DMat4::from_scale(value.vec3().unwrap_or(DVec3::ONE)),
        "scaleX" => DMat4::from_scale(DVec3::new(number(1.0), 1.0, 1.0)),
        "scaleY" => DMat4::from_scale(DVec3::new(1.0, number(1.0), 1.0)),
        "scaleZ" => DMat4::from_scale(DVec3::new(1.0, 1.0, number(1.0))),
        "rotateX" => DMat4::from_rotation_x(angle()),
        "rotateY" => DMat4::from_rotation_y(angle()),
        "rotateZ" => DMat4::from_rotation_z(angle()),
        "orient" => match value {
            Attr::Quat(q) if q.length() > 0.0 => DMat4::from_quat(q),
            _ => DMat4::IDENTITY,
        },
        "transform" => match value {
            Attr::Matrix(m) => *m,
            _ => DMat4::IDENTITY,
        },
        k if k.starts_with("rotate")
            && k.len() == 9
            && k[6..].bytes().all(|b| matches!(b, b'X' | b'Y' | b'Z')) =>
        {
            let v = value.vec3().unwrap_or(DVec3::ZERO);
            let r = |axis: u8| match axis {
                b'X' => DMat4::from_rotation_x(v.x.to_radians()),
                b'Y' => DMat4::from_rotation_y(v.y.to_radians()),
                _ => DMat4::from_rotation_z(v.z.to_radians()),
            };
            // `rotateXYZ` turns about X first, then Y, then Z.
            let axes = &k.as_bytes()[6..];
            r(axes[2]) * r(axes[1]) * r(axes[0])
        }
        _ => DMat4::IDENTITY,
    };
    if !m.is_finite() {
        return Err(FormatError::invalid(format!(
            "{path}: the transform op {name} is not finite"
        )));
    }
    if inverted {
        if m.determinant().abs() < 1e-300 {
            return Err(FormatError::invalid(format!(
                "{path}: the inverted op {name} cannot be inverted"
            )));
        }
        Ok(m.inverse())
    } else {
        Ok(m)
    }
}

/// A prim's local transform, and whether it resets the transform stack.
///
/// # Errors
/// An op that is not finite, or an inverted op that cannot be inverted.
pub(super) fn local_transform(attrs: Attrs<'_>, path: &str) -> Result<(DMat4, bool), FormatError> {
    let order = op_order(attrs);
    let resets = order.first().is_some_and(|o| o == super::patch::RESET);
    // The first op listed is the outermost: M = op0 · op1 · … (column vectors).
    let mut m = DMat4::IDENTITY;
    for op in order.iter().filter(|o| *o != super::patch::RESET) {
        m *= op_matrix(attrs, path, op)?;
    }
    Ok((m, resets))
}

/// The eight corners of the box from `lo` to `hi`.
fn corners(lo: DVec3, hi: DVec3) -> Vec<DVec3> {
    (0..8)
        .map(|k| {
            DVec3::new(
                if k & 1 == 0 { lo.x } else { hi.x },
                if k & 2 == 0 { lo.y } else { hi.y },
                if k & 4 == 0 { lo.z } else { hi.z },
            )
        })
        .collect()
}

/// The points a gprim's geometry spans, in its own space: its points, or the corners of
/// its extent (for the implicit shapes, the extent their sizes give).
pub(super) fn geometry_points(attrs: Attrs<'_>, type_name: &str) -> Vec<DVec3> {
    let number = |name: &str, default: f64| attrs(name).and_then(|v| v.scalar()).unwrap_or(default);
    let upright = |r: f64, half: f64| {
        let axis = attrs("axis");
        let (lo, hi) = match axis.as_ref().and_then(Attr::text) {
            Some("X") => (DVec3::new(-half, -r, -r), DVec3::new(half, r, r)),
            Some("Y") => (DVec3::new(-r, -half, -r), DVec3::new(r, half, r)),
            _ => (DVec3::new(-r, -r, -half), DVec3::new(r, r, half)),
        };
        corners(lo, hi)
    };
    match type_name {
        "Cube" => {
            let h = number("size", 2.0) / 2.0;
            corners(DVec3::splat(-h), DVec3::splat(h))
        }
        "Sphere" => {
            let r = number("radius", 1.0);
            corners(DVec3::splat(-r), DVec3::splat(r))
        }
        "Cylinder" | "Cone" => upright(number("radius", 1.0), number("height", 2.0) / 2.0),
        "Capsule" => {
            let r = number("radius", 0.5);
            upright(r, number("height", 1.0) / 2.0 + r)
        }
        _ => match (attrs("points"), attrs("extent")) {
            (Some(Attr::Points(points)), _) if !points.is_empty() => points,
            (_, Some(Attr::Points(extent))) if extent.len() == 2 => corners(extent[0], extent[1]),
            _ => Vec::new(),
        },
    }
}

/// Whether the walk reads an attribute of this name (transforms, geometry sizes and
/// points, Shenlong's own): the layer reader keeps only these.
#[must_use]
pub(super) fn wanted(name: &str) -> bool {
    name.starts_with("xformOp:")
        || name.starts_with("shenlong:")
        || matches!(
            name,
            "xformOpOrder"
                | "size"
                | "radius"
                | "height"
                | "axis"
                | "points"
                | "extent"
                | "faceVertexCounts"
                | "faceVertexIndices"
        )
}

/// A `Mesh`'s faces as triangles (each polygon as a fan from its first corner), as indices
/// into its `points` (`count` of them); faces with a corner out of range are left out, and
/// past [`MAX_TRIANGLES`] in all, the rest (the prim then keeps the form of its kind).
///
/// [`MAX_TRIANGLES`]: crate::scene::mesh::MAX_TRIANGLES
pub(super) fn geometry_triangles(attrs: Attrs<'_>, type_name: &str, count: usize) -> Vec<[u32; 3]> {
    // Only a mesh's own points are what its faces index (not its extent's corners).
    let own_points = matches!(attrs("points"), Some(Attr::Points(p)) if p.len() == count);
    if type_name != "Mesh" || !own_points {
        return Vec::new();
    }
    let (Some(Attr::Ints(sizes)), Some(Attr::Ints(corners))) =
        (attrs("faceVertexCounts"), attrs("faceVertexIndices"))
    else {
        return Vec::new();
    };
    let index = |k: i64| u32::try_from(k).ok().filter(|&k| (k as usize) < count);
    let mut out = Vec::new();
    let mut at = 0usize;
    for &size in &sizes {
        let Some(face) = usize::try_from(size)
            .ok()
            .and_then(|n| corners.get(at..at.checked_add(n)?))
        else {
            break;
        };
        at += face.len();
        let face: Option<Vec<u32>> = face.iter().map(|&k| index(k)).collect();
        if let Some(face) = face.filter(|f| f.len() >= 3) {
            for w in face[1..].windows(2) {
                if out.len() > crate::scene::mesh::MAX_TRIANGLES {
                    return out;
                }
                out.push([face[0], w[0], w[1]]);
            }
        }
    }
    out
}

//! What an object's mesh shows of the room under it or in it (docs/collisions.md,
//! "Shapes from meshes").
//!
//! A file that carries meshes (glTF, USD) says more than a box: a table's legs leave the
//! space under its top free, a crate's inside is empty. [`measure`] reads that off the
//! triangles in one pass: it clips each to the column down the middle of the object's
//! footprint (its box less 15% on each side, clear of legs, walls and aprons) for the
//! lowest and highest points of the mesh there. Free from its bottom up to the lowest, and
//! open to a side there (rays against the triangles, with `parry3d`), is the room under a
//! top; free from its top down to the highest, a low bottom, is the inside of an open
//! container. [`crate::ground::kind::form_of`]
//! turns that into a [`super::Form`].

use glam::DVec3;
use parry3d_f64::math::Vector;
use parry3d_f64::query::{Ray, RayCast};
use parry3d_f64::shape::Triangle;

use crate::geometry::Aabb;

/// What a mesh shows of the room under or in the object.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Measured {
    /// Room under it from its bottom up to `underside` thousandths of its height, open to
    /// a side: a table, a desk, a stool, a bed or a sofa on legs.
    Under {
        /// The height of the room below, in thousandths of the object's height.
        underside: u16,
    },
    /// Room inside it, open at the top, above a bottom: a crate, a bin, a bowl.
    Inside,
    /// Boards one above another with room between them open to a side: a bookcase, a
    /// shelving unit, a tiered stand.
    Shelves(super::form::Boards),
    /// Neither: what stands in the middle of its footprint fills it from its bottom, and
    /// it is closed at its top (a cabinet, a block, a pedestal table).
    Neither,
}

/// The most triangles measured; a mesh with more keeps the form of its kind.
pub const MAX_TRIANGLES: usize = 2_000_000;

/// The share of the footprint left out on each side of the column looked down.
const MARGIN: f64 = 0.15;

/// The least room under an object that counts, in metres: what a rug slides under.
const LEAST_ROOM: f64 = 0.02;

/// The least room between two boards of a case of shelves, in metres.
const LEAST_SHELF: f64 = 0.08;

/// The most of its height an open container's bottom may take.
const MOST_BOTTOM: f64 = 0.35;

/// What the mesh of `vertices` (world positions, metres) and `triangles` (indices into
/// them) shows of the room under or in it; `None` when it shows nothing a box does not:
/// no triangles, a plain box (every vertex a corner of the box), something flat or thin,
/// or more than [`MAX_TRIANGLES`].
#[must_use]
pub fn measure(vertices: &[DVec3], triangles: &[[u32; 3]]) -> Option<Measured> {
    if triangles.is_empty() || triangles.len() > MAX_TRIANGLES {
        return None;
    }
    let bounds = Aabb::from_points(vertices.iter().copied())?;
    let size = bounds.size();
    if size.min_element() < LEAST_ROOM || !size.is_finite() || plain_box(vertices, &bounds) {
        return None;
    }
    let mesh = Column::new(vertices, triangles, &bounds)?;
    // parry's ray tests are not documented to be free of panics on every degenerate
    // triangle; a panic here must not take down the caller (a server, a Python
    // interpreter): the object then keeps the form of its kind.
    std::panic::catch_unwind(|| mesh.measure()).ok().flatten()
}

/// Whether every vertex is a corner of `bounds`: a box drawn as a mesh.
fn plain_box(vertices: &[DVec3], bounds: &Aabb) -> bool {
    let tolerance = bounds.size().max_element() * 1e-6;
    let at = |v: f64, lo: f64, hi: f64| (v - lo).abs() <= tolerance || (v - hi).abs() <= tolerance;
    vertices.iter().all(|p| {
        at(p.x, bounds.min.x, bounds.max.x)
            && at(p.y, bounds.min.y, bounds.max.y)
            && at(p.z, bounds.min.z, bounds.max.z)
    })
}

/// A mesh, moved so that its box starts at the origin, and the column down the middle of
/// its footprint.
struct Column {
    /// The triangles in range and of an area above zero, their corners moved.
    triangles: Vec<[DVec3; 3]>,
    /// The box's height.
    height: f64,
    /// The column's footprint, low and high corners (x, z).
    lo: (f64, f64),
    hi: (f64, f64),
    /// The box's size along x and z.
    width: (f64, f64),
}

impl Column {
    /// The mesh of the triangles whose indices are in range and whose area is not zero;
    /// `None` when none is left.
    fn new(vertices: &[DVec3], triangles: &[[u32; 3]], bounds: &Aabb) -> Option<Self> {
        let kept: Vec<[DVec3; 3]> = triangles
            .iter()
            .filter_map(|t| {
                let [a, b, c] = t.map(|k| vertices.get(k as usize).map(|p| *p - bounds.min));
                let corners = [a?, b?, c?];
                let [a, b, c] = corners;
                ((b - a).cross(c - a).length_squared() > 0.0).then_some(corners)
            })
            .collect();
        if kept.is_empty() {
            return None;
        }
        let size = bounds.size();
        Some(Self {
            triangles: kept,
            height: size.y,
            lo: (size.x * MARGIN, size.z * MARGIN),
            hi: (size.x * (1.0 - MARGIN), size.z * (1.0 - MARGIN)),
            width: (size.x, size.z),
        })
    }

    /// The heights at which the triangles meet the column, merged into the bands they
    /// fill, lowest first; faces less than [`LEAST_SHELF`] apart are one band (the top and
    /// bottom faces of one board).
    fn bands(&self) -> Vec<(f64, f64)> {
        let mut spans: Vec<(f64, f64)> = self
            .triangles
            .iter()
            .filter_map(|t| span_in(t, self.lo, self.hi))
            .collect();
        spans.sort_by(|a, b| a.0.total_cmp(&b.0));
        let touch = LEAST_SHELF.min(self.height * 0.1);
        let mut bands: Vec<(f64, f64)> = Vec::new();
        for (lo, hi) in spans {
            match bands.last_mut() {
                Some(last) if lo <= last.1 + touch => last.1 = last.1.max(hi),
                _ => bands.push((lo, hi)),
            }
        }
        bands
    }

    /// Three boards or more with at least [`LEAST_SHELF`] of room between each two, open
    /// to a side: the boards, in thousandths of the height.
    fn shelves(&self, bands: &[(f64, f64)]) -> Option<super::form::Boards> {
        if bands.len() < 3 || bands.len() > super::form::MAX_BOARDS {
            return None;
        }
        let open = bands.windows(2).all(|pair| {
            let (below, above) = (pair[0].1, pair[1].0);
            above - below >= LEAST_SHELF && self.open_sideways((below + above) / 2.0)
        });
        let thousandths = |y: f64| (y / self.height * 1000.0).round().clamp(0.0, 1000.0) as u16;
        let levels: Vec<(u16, u16)> = bands
            .iter()
            .map(|&(lo, hi)| (thousandths(lo), thousandths(hi)))
            .collect();
        open.then(|| super::form::Boards::new(&levels)).flatten()
    }

    /// Whether a ray from the middle of the column at height `y` leaves the mesh's box
    /// along x or z without meeting a triangle (parry's ray and triangle test).
    fn open_sideways(&self, y: f64) -> bool {
        let origin = Vector::new(
            (self.lo.0 + self.hi.0) / 2.0,
            y,
            (self.lo.1 + self.hi.1) / 2.0,
        );
        let reach = self.width.0.max(self.width.1) * 2.0;
        let across: Vec<Triangle> = self
            .triangles
            .iter()
            .filter(|t| t.iter().any(|p| p.y >= y) && t.iter().any(|p| p.y <= y))
            .map(|t| {
                let [a, b, c] = t.map(|p| Vector::new(p.x, p.y, p.z));
                Triangle::new(a, b, c)
            })
            .collect();
        [Vector::X, Vector::NEG_X, Vector::Z, Vector::NEG_Z]
            .into_iter()
            .any(|dir| {
                let ray = Ray::new(origin, dir);
                !across.iter().any(|t| t.intersects_local_ray(&ray, reach))
            })
    }

    /// What the column shows (see [`measure`]).
    fn measure(&self) -> Option<Measured> {
        let h = self.height;
        let bands = self.bands();
        // Nothing down the middle at all (a frame, a ring): nothing to read.
        let (under, top) = (bands.first()?.0, bands.last()?.1);
        if let Some(boards) = self.shelves(&bands) {
            return Some(Measured::Shelves(boards));
        }
        if under >= LEAST_ROOM && self.open_sideways(under / 2.0) {
            let underside = (under / h * 1000.0).floor().clamp(0.0, 1000.0) as u16;
            return Some(Measured::Under { underside });
        }
        // Free from the top down to a bottom: the highest the mesh reaches in the column.
        if top < h - LEAST_ROOM && top <= MOST_BOTTOM * h {
            return Some(Measured::Inside);
        }
        Some(Measured::Neither)
    }
}

/// The lowest and highest heights of triangle `t` within the column `[lo, hi]` (x, z):
/// the triangle clipped to it (Sutherland–Hodgman against its four sides), if anything is
/// left.
fn span_in(t: &[DVec3; 3], lo: (f64, f64), hi: (f64, f64)) -> Option<(f64, f64)> {
    let outside = |axis: usize, bound: f64, above: bool| {
        t.iter().all(|p| {
            if above {
                p[axis] < bound
            } else {
                p[axis] > bound
            }
        })
    };
    if outside(0, lo.0, true)
        || outside(0, hi.0, false)
        || outside(2, lo.1, true)
        || outside(2, hi.1, false)
    {
        return None;
    }
    let mut poly: Vec<DVec3> = t.to_vec();
    for (axis, bound, above) in [
        (0, lo.0, true),
        (0, hi.0, false),
        (2, lo.1, true),
        (2, hi.1, false),
    ] {
        poly = clip(&poly, axis, bound, above);
        if poly.is_empty() {
            return None;
        }
    }
    let low = poly.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
    let high = poly.iter().map(|p| p.y).fold(f64::NEG_INFINITY, f64::max);
    Some((low, high))
}

/// The polygon `poly` less what lies below `bound` along `axis` (`above`), or above it.
fn clip(poly: &[DVec3], axis: usize, bound: f64, above: bool) -> Vec<DVec3> {
    let inside = |p: &DVec3| {
        if above {
            p[axis] >= bound
        } else {
            p[axis] <= bound
        }
    };
    let mut out = Vec::with_capacity(poly.len() + 2);
    for (k, a) in poly.iter().enumerate() {
        let b = &poly[(k + 1) % poly.len()];
        if inside(a) {
            out.push(*a);
        }
        if inside(a) != inside(b) {
            let t = (bound - a[axis]) / (b[axis] - a[axis]);
            out.push(*a + (*b - *a) * t);
        }
    }
    out
}

/// Boxes as meshes, for the tests of the readers that measure them.
#[cfg(test)]
pub(crate) mod boxes {
    use glam::DVec3;

    /// The six faces of a box as quads over [`corners`].
    pub(crate) const QUADS: [[u32; 4]; 6] = [
        [0, 1, 3, 2],
        [4, 6, 7, 5],
        [0, 4, 5, 1],
        [2, 3, 7, 6],
        [0, 2, 6, 4],
        [1, 5, 7, 3],
    ];

    /// The 8 corners of the box from `lo` to `hi`: corner `k` takes `hi` along x, y and z
    /// where bit 0, 1 and 2 of `k` is set.
    pub(crate) fn corners(lo: [f64; 3], hi: [f64; 3]) -> [DVec3; 8] {
        std::array::from_fn(|k| {
            let pick = |bit: usize, a: usize| if k & bit == 0 { lo[a] } else { hi[a] };
            DVec3::new(pick(1, 0), pick(2, 1), pick(4, 2))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 12 triangles of the box from `lo` to `hi`, its vertices appended to `v`.
    fn cuboid(v: &mut Vec<DVec3>, t: &mut Vec<[u32; 3]>, lo: [f64; 3], hi: [f64; 3]) {
        let base = v.len() as u32;
        v.extend(boxes::corners(lo, hi));
        for f in boxes::QUADS {
            t.push([base + f[0], base + f[1], base + f[2]]);
            t.push([base + f[0], base + f[2], base + f[3]]);
        }
    }

    #[test]
    fn a_table_on_legs_leaves_room_under_its_top() {
        let (mut v, mut t) = (Vec::new(), Vec::new());
        cuboid(&mut v, &mut t, [0.0, 0.7, 0.0], [1.2, 0.75, 0.8]);
        for (x, z) in [(0.0, 0.0), (1.14, 0.0), (0.0, 0.74), (1.14, 0.74)] {
            cuboid(&mut v, &mut t, [x, 0.0, z], [x + 0.06, 0.7, z + 0.06]);
        }
        let Some(Measured::Under { underside }) = measure(&v, &t) else {
            panic!("{:?}", measure(&v, &t));
        };
        // 0.7 of 0.75 m.
        assert!((930..=934).contains(&underside), "{underside}");
    }

    #[test]
    fn an_open_crate_has_room_inside_and_a_closed_one_none() {
        let (mut v, mut t) = (Vec::new(), Vec::new());
        cuboid(&mut v, &mut t, [0.0, 0.0, 0.0], [0.5, 0.02, 0.4]);
        cuboid(&mut v, &mut t, [0.0, 0.0, 0.0], [0.02, 0.3, 0.4]);
        cuboid(&mut v, &mut t, [0.48, 0.0, 0.0], [0.5, 0.3, 0.4]);
        cuboid(&mut v, &mut t, [0.0, 0.0, 0.0], [0.5, 0.3, 0.02]);
        cuboid(&mut v, &mut t, [0.0, 0.0, 0.38], [0.5, 0.3, 0.4]);
        assert_eq!(measure(&v, &t), Some(Measured::Inside));
        // With a lid: closed.
        cuboid(&mut v, &mut t, [0.0, 0.28, 0.0], [0.5, 0.3, 0.4]);
        assert_eq!(measure(&v, &t), Some(Measured::Neither));
        // A plain box says nothing a box does not.
        let (mut v, mut t) = (Vec::new(), Vec::new());
        cuboid(&mut v, &mut t, [0.0, 0.0, 0.0], [0.5, 0.3, 0.4]);
        assert_eq!(measure(&v, &t), None);
    }

    #[test]
    fn a_bed_on_short_legs_leaves_a_gap_and_bad_input_reads_as_nothing() {
        let (mut v, mut t) = (Vec::new(), Vec::new());
        // A frame and mattress from 0.2 m to 0.55 m, a headboard to 1.0 m, legs.
        cuboid(&mut v, &mut t, [0.0, 0.2, 0.0], [1.6, 0.55, 2.0]);
        cuboid(&mut v, &mut t, [0.0, 0.0, 1.95], [1.6, 1.0, 2.0]);
        for (x, z) in [(0.0, 0.0), (1.55, 0.0), (0.0, 1.9), (1.55, 1.9)] {
            cuboid(&mut v, &mut t, [x, 0.0, z], [x + 0.05, 0.2, z + 0.05]);
        }
        let Some(Measured::Under { underside }) = measure(&v, &t) else {
            panic!("{:?}", measure(&v, &t));
        };
        assert!((198..=201).contains(&underside), "{underside}");
        // Indices out of range and degenerate triangles are left out, not read.
        assert_eq!(measure(&v, &[[0, 1, 99_999]]), None);
        assert_eq!(measure(&v, &[[0, 0, 0]]), None);
        assert_eq!(measure(&[], &[]), None);
    }

    #[test]
    fn a_bookcase_shows_its_own_boards() {
        let (mut v, mut t) = (Vec::new(), Vec::new());
        // Sides and a back, boards at 0, 0.5, 1.2 and 1.78 m (2 cm thick).
        cuboid(&mut v, &mut t, [0.0, 0.0, 0.0], [0.02, 1.8, 0.3]);
        cuboid(&mut v, &mut t, [0.78, 0.0, 0.0], [0.8, 1.8, 0.3]);
        cuboid(&mut v, &mut t, [0.0, 0.0, 0.0], [0.8, 1.8, 0.02]);
        for y in [0.0, 0.5, 1.2, 1.78] {
            cuboid(&mut v, &mut t, [0.02, y, 0.02], [0.78, y + 0.02, 0.3]);
        }
        let Some(Measured::Shelves(boards)) = measure(&v, &t) else {
            panic!("{:?}", measure(&v, &t));
        };
        assert_eq!(
            boards.levels(),
            [(0, 11), (278, 289), (667, 678), (989, 1000)]
        );
        let case = Aabb::new(DVec3::ZERO, DVec3::new(0.8, 1.8, 0.3));
        let rooms = crate::scene::form::compartments(
            &case,
            crate::scene::Form::Shelves {
                boards: Some(boards),
            },
        );
        assert_eq!(rooms.len(), 3);
        assert!((rooms[1].min.y - 0.52).abs() < 2e-3 && (rooms[1].max.y - 1.2).abs() < 2e-3);
        // With doors across its front it shows no room between its boards.
        cuboid(&mut v, &mut t, [0.0, 0.0, 0.29], [0.8, 1.8, 0.3]);
        assert_eq!(measure(&v, &t), Some(Measured::Neither));
    }
}

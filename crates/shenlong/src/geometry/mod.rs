//! Bounding volumes: the axis-aligned box every later stage works with, and a floor grid
//! to find boxes near one another without comparing every pair.

mod grid;

pub use grid::FloorGrid;

use glam::DVec3;

/// An axis-aligned bounding box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// The corner with the smallest coordinates.
    pub min: DVec3,
    /// The corner with the largest coordinates.
    pub max: DVec3,
}

impl Aabb {
    /// The box with the given corners.
    pub const fn new(min: DVec3, max: DVec3) -> Self {
        Self { min, max }
    }

    /// The smallest box holding all `points`; `None` when there are none.
    pub fn from_points(points: impl IntoIterator<Item = DVec3>) -> Option<Self> {
        let mut iter = points.into_iter();
        let first = iter.next()?;
        Some(iter.fold(Self::new(first, first), |b, p| {
            Self::new(b.min.min(p), b.max.max(p))
        }))
    }

    /// The centre.
    pub fn center(&self) -> DVec3 {
        (self.min + self.max) * 0.5
    }

    /// The extents along x, y, z.
    pub fn size(&self) -> DVec3 {
        self.max - self.min
    }

    /// The centre of the bottom face (the pivot of glTF objects).
    pub fn bottom_center(&self) -> DVec3 {
        let c = self.center();
        DVec3::new(c.x, self.min.y, c.z)
    }

    /// The 8 corners.
    pub fn corners(&self) -> [DVec3; 8] {
        let (a, b) = (self.min, self.max);
        [
            DVec3::new(a.x, a.y, a.z),
            DVec3::new(b.x, a.y, a.z),
            DVec3::new(a.x, b.y, a.z),
            DVec3::new(b.x, b.y, a.z),
            DVec3::new(a.x, a.y, b.z),
            DVec3::new(b.x, a.y, b.z),
            DVec3::new(a.x, b.y, b.z),
            DVec3::new(b.x, b.y, b.z),
        ]
    }

    /// The smallest box holding both.
    pub fn union(&self, other: &Self) -> Self {
        Self::new(self.min.min(other.min), self.max.max(other.max))
    }

    /// How far the boxes overlap along each axis (negative: the gap between them).
    pub fn overlap(&self, other: &Self) -> DVec3 {
        self.max.min(other.max) - self.min.max(other.min)
    }

    /// Whether the boxes overlap by more than `epsilon` on all three axes; touching is not
    /// overlapping.
    pub fn intersects(&self, other: &Self, epsilon: f64) -> bool {
        self.overlap(other).cmpgt(DVec3::splat(epsilon)).all()
    }

    /// Overlap area of the two boxes' footprints on the floor (the x–z plane).
    pub fn footprint_overlap(&self, other: &Self) -> f64 {
        let o = self.overlap(other);
        o.x.max(0.0) * o.z.max(0.0)
    }

    /// Whether this box's footprint lies within `other`'s on the floor plan (to 1 nm).
    #[must_use]
    pub fn footprint_within(&self, other: &Self) -> bool {
        self.min.x >= other.min.x - 1e-9
            && self.max.x <= other.max.x + 1e-9
            && self.min.z >= other.min.z - 1e-9
            && self.max.z <= other.max.z + 1e-9
    }

    /// The horizontal distance between the two boxes' footprints on the floor plan (0 where
    /// they touch or overlap).
    #[must_use]
    pub fn floor_gap(&self, other: &Self) -> f64 {
        let dx = (other.min.x - self.max.x)
            .max(self.min.x - other.max.x)
            .max(0.0);
        let dz = (other.min.z - self.max.z)
            .max(self.min.z - other.max.z)
            .max(0.0);
        dx.hypot(dz)
    }

    /// The box moved by `offset`.
    pub fn translated(&self, offset: DVec3) -> Self {
        Self::new(self.min + offset, self.max + offset)
    }

    /// Whether every coordinate is finite.
    pub fn is_finite(&self) -> bool {
        self.min.is_finite() && self.max.is_finite()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn touching_is_not_overlapping() {
        let a = Aabb::new(DVec3::ZERO, DVec3::ONE);
        let b = a.translated(DVec3::X);
        assert!(!a.intersects(&b, 1e-6));
        assert!(a.intersects(&a.translated(DVec3::splat(0.5)), 1e-6));
        assert_eq!(
            a.footprint_overlap(&a.translated(DVec3::new(0.5, 5.0, 0.5))),
            0.25
        );
        assert_eq!(
            Aabb::from_points([DVec3::X, -DVec3::Y]).unwrap().size(),
            DVec3::new(1.0, 1.0, 0.0)
        );
        assert!(Aabb::from_points([]).is_none());
    }
}

//! The transform arithmetic the writers of node-based formats share (glTF nodes, USD
//! prims): an object's world motion as a matrix, comparison of transforms relative to
//! their size, and a matrix read as translate · rotate · scale when it is one.

use crate::scene::{Object, Shape};
use glam::{DMat4, DQuat, DVec3};

/// An object's world motion since it was read (its pose, which starts at the identity
/// for objects of these formats), as a matrix on column vectors; `None` while it has not
/// moved.
#[must_use]
pub(crate) fn world_motion(object: &Object) -> Option<DMat4> {
    let s = object.similarity();
    let moved = s.translation.length() > 0.0
        || !s.rotation.abs_diff_eq(DQuat::IDENTITY, 0.0)
        || s.scale != 1.0;
    moved.then(|| {
        DMat4::from_scale_rotation_translation(DVec3::splat(s.scale), s.rotation, s.translation)
    })
}

/// Whether `a` equals `b` within `relative` times `b`'s size (1 plus its largest entry).
#[must_use]
pub(crate) fn nearly_equal(a: &DMat4, b: &DMat4, relative: f64) -> bool {
    let size = 1.0 + b.abs().to_cols_array().iter().copied().fold(0.0, f64::max);
    a.abs_diff_eq(*b, relative * size)
}

/// `m` as (scale, rotation, translation) when they give it back to 1e-9 of its size;
/// `None` for a transform with shear.
#[must_use]
pub(crate) fn as_trs(m: &DMat4) -> Option<(DVec3, DQuat, DVec3)> {
    let (scale, rotation, translation) = m.to_scale_rotation_translation();
    let rebuilt = DMat4::from_scale_rotation_translation(scale, rotation, translation);
    nearly_equal(&rebuilt, m, 1e-9).then_some((scale, rotation, translation))
}

/// An object as a box for a new file (a glTF or USD stage written from scene JSON): its
/// pose and the box's size about its bottom centre — a box object's own; for a mesh's
/// points, its world box at the identity turn.
#[must_use]
pub(crate) fn box_pose(object: &Object) -> (cga::Similarity, DVec3) {
    match &object.shape {
        Shape::Box { size } => (object.similarity(), *size),
        Shape::Points { .. } => {
            let b = object.world_aabb();
            let pose = cga::Similarity {
                translation: b.bottom_center(),
                rotation: DQuat::IDENTITY,
                scale: 1.0,
            };
            (pose, b.size())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trs_is_recognised_and_shear_is_not() {
        let trs = DMat4::from_scale_rotation_translation(
            DVec3::new(1.0, 2.0, 3.0),
            DQuat::from_rotation_y(0.4),
            DVec3::new(4.0, 5.0, 6.0),
        );
        let (s, _, t) = as_trs(&trs).unwrap();
        assert!((s - DVec3::new(1.0, 2.0, 3.0)).length() < 1e-9);
        assert!((t - DVec3::new(4.0, 5.0, 6.0)).length() < 1e-12);
        let mut shear = DMat4::IDENTITY;
        shear.y_axis.x = 0.5;
        assert!(as_trs(&shear).is_none());
        // Relative to the size: 1e-9 off in a matrix of entries near 1e6 is equal.
        let big = DMat4::from_translation(DVec3::splat(1e6));
        let near = DMat4::from_translation(DVec3::splat(1e6 + 1e-4));
        assert!(nearly_equal(&near, &big, 1e-9));
        assert!(!nearly_equal(&near, &big, 1e-12));
    }
}

//! A versor's action on points, precomputed.

use crate::{CgaError, Multivector};
use glam::{DMat3, DVec3};

/// The action of an even versor `M` on Euclidean points, `x ↦ down(M up(x) M̃)`, prepared
/// once for moving many points (box corners, mesh vertices).
///
/// Under `G(4,1) ≅ Mat(2, Cl(3,0))`, `M` is a matrix `[[a, b], [c, d]]` and moves `x` to
/// `(c + dx)(a + bx)⁻¹`. For a similarity (any product of translators, rotors and
/// dilators) `b` is zero and the map is affine, `x ↦ Lx + t`: 9 multiply-adds per point.
/// A versor with a transversion keeps the Möbius form. Neither squares coordinates, so the
/// result is as precise far from the origin as near it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointMap {
    action: Action,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Action {
    /// `x ↦ linear · x + translation`.
    Affine { linear: DMat3, translation: DVec3 },
    /// `x ↦ (c + dx)(a + bx)⁻¹`, with the matrix as [`crate::generated::vahlen_even`] lays it out.
    Moebius { vahlen: [f64; 16] },
}

impl PointMap {
    /// Precomputes the action of the even versor `m`.
    ///
    /// # Errors
    /// If `m` has odd grades, is not finite, or sends every point to infinity (`a` is
    /// zero where `b` is).
    pub fn new(m: &Multivector) -> Result<Self, CgaError> {
        if !m.is_finite() {
            return Err(CgaError::NotFinite(m.to_string()));
        }
        if !m.is_even() {
            return Err(CgaError::NotSimilarity(format!(
                "{m} has odd grades; a point map needs an even versor"
            )));
        }
        let vahlen = crate::generated::vahlen_even(m.coefficients());
        if vahlen[4..8].iter().any(|&b| b != 0.0) {
            return Ok(Self {
                action: Action::Moebius { vahlen },
            });
        }
        // b = 0: x' = (c + dx) ã / |a|². The translation is the image of the origin, and
        // column k of the linear part is the image of e_k with c set to zero, so nothing
        // is found by subtracting nearly equal numbers.
        let (origin, weight) = crate::generated::moebius_point(&vahlen, &[0.0; 3]);
        if weight == 0.0 || !weight.is_finite() {
            return Err(CgaError::PointAtInfinity);
        }
        let mut without_c = vahlen;
        without_c[8..12].fill(0.0);
        let column = |axis: DVec3| {
            DVec3::from_array(crate::generated::moebius_point(&without_c, &axis.to_array()).0)
                / weight
        };
        Ok(Self {
            action: Action::Affine {
                linear: DMat3::from_cols(column(DVec3::X), column(DVec3::Y), column(DVec3::Z)),
                translation: DVec3::from_array(origin) / weight,
            },
        })
    }

    /// Applies the map to a Euclidean point: `down(M up(x) M̃)`.
    ///
    /// # Errors
    /// [`CgaError::PointAtInfinity`] where a transversion sends `x` to infinity; a
    /// similarity never fails.
    #[inline]
    pub fn transform_point(&self, x: DVec3) -> Result<DVec3, CgaError> {
        match &self.action {
            Action::Affine {
                linear,
                translation,
            } => Ok(*linear * x + *translation),
            Action::Moebius { vahlen } => {
                let (position, weight) = crate::generated::moebius_point(vahlen, &x.to_array());
                crate::conformal::point_from_weighted(DVec3::from_array(position), weight)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Similarity;
    use glam::DQuat;

    #[test]
    fn matches_sandwich() {
        let m = Similarity {
            translation: DVec3::new(1.0, -2.0, 0.5),
            rotation: DQuat::from_rotation_y(0.4) * DQuat::from_rotation_x(1.1),
            scale: 0.7,
        }
        .to_versor()
        .unwrap();
        let map = PointMap::new(&m).unwrap();
        assert!(matches!(map.action, Action::Affine { .. }), "{map:?}");
        for x in [DVec3::ZERO, DVec3::new(3.0, 4.0, -5.0), DVec3::splat(-0.25)] {
            let a = map.transform_point(x).unwrap();
            let b = m.transform_point(x).unwrap();
            assert!((a - b).length() < 1e-12, "{a} vs {b}");
        }
        assert!(PointMap::new(&Multivector::e1()).is_err());
        assert!(PointMap::new(&Multivector::ZERO).is_err());
    }

    #[test]
    fn transversions_keep_the_moebius_form() {
        let c = DVec3::new(0.0, 0.5, 0.0);
        let k = Multivector::scalar(1.0) + (Multivector::from_vector(c) ^ Multivector::eo());
        let map = PointMap::new(&k).unwrap();
        assert!(matches!(map.action, Action::Moebius { .. }));
        for x in [DVec3::ZERO, DVec3::new(3.0, 4.0, -5.0), DVec3::splat(-0.25)] {
            let a = map.transform_point(x).unwrap();
            let b = k.transform_point(x).unwrap();
            assert!((a - b).length() < 1e-12, "{a} vs {b}");
        }
        assert_eq!(
            map.transform_point(DVec3::new(0.0, 2.0, 0.0)),
            Err(CgaError::PointAtInfinity)
        );
    }

    #[test]
    fn far_from_the_origin_the_map_stays_exact() {
        let s = Similarity {
            translation: DVec3::new(-2.5e6, 1.25e6, 3.0e5),
            rotation: DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.7),
            scale: 1.5,
        };
        let map = PointMap::new(&s.to_versor().unwrap()).unwrap();
        let x = DVec3::new(1.0e6 + 0.125, -2.0e6 + 0.5, 7.0e5 - 0.25);
        let error = (map.transform_point(x).unwrap() - s.transform_point(x)).length();
        // The earlier 5×5 map over e1 … e5 was off by 7e5 here (it squared coordinates).
        assert!(error < 1e-8, "error {error}");
    }
}

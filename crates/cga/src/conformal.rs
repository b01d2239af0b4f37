//! Conformal embedding: points and spheres.

use crate::{CgaError, Multivector};
use glam::DVec3;

impl Multivector {
    /// The conformal point of a Euclidean position: `up(x) = x + ½x² einf + eo`.
    pub fn up(x: DVec3) -> Self {
        Self::from_vector(x) + Self::einf() * (0.5 * x.length_squared()) + Self::eo()
    }

    /// The Euclidean position of a conformal point, normalising its weight `−X·einf` first
    /// (so any non-zero multiple of `up(x)` gives `x`).
    pub fn down(&self) -> Result<DVec3, CgaError> {
        let weight = self.weight();
        if !weight.is_finite() || weight.abs() <= 1e-12 * self.max_abs() || weight == 0.0 {
            return Err(CgaError::PointAtInfinity);
        }
        Ok(self.euclidean_vector() / weight)
    }

    /// The weight `−X·einf` of a point or dual sphere (1 for `up(x)`).
    pub fn weight(&self) -> f64 {
        // X·einf for X = … + a e4 + b e5 is a − b.
        self[5] - self[4]
    }

    /// The dual sphere with centre `c` and radius `r`: `up(c) − ½r² einf`. A point is the
    /// sphere of radius 0.
    pub fn sphere(center: DVec3, radius: f64) -> Self {
        Self::up(center) - Self::einf() * (0.5 * radius * radius)
    }

    /// Centre and radius of a dual sphere (any non-zero weight); the radius comes from
    /// `S² = r²` after normalising.
    pub fn sphere_center_radius(&self) -> Result<(DVec3, f64), CgaError> {
        let weight = self.weight();
        if weight.abs() <= 1e-12 * self.max_abs() || !weight.is_finite() {
            return Err(CgaError::NotSimilarity(
                "the sphere has zero weight (it is a plane or at infinity)".into(),
            ));
        }
        let normalised = *self / weight;
        let r2 = normalised.grade(1).scalar_product(&normalised.grade(1));
        if r2 < -crate::TOLERANCE * normalised.max_abs().max(1.0) {
            return Err(CgaError::NotSimilarity(format!(
                "the sphere is imaginary (r² = {r2})"
            )));
        }
        Ok((normalised.euclidean_vector(), r2.max(0.0).sqrt()))
    }

    /// Applies the versor `self` to a Euclidean point: `down(M up(x) M⁻¹)`.
    ///
    /// Even versors (every product of translators, rotors and dilators) take a fast path:
    /// the Möbius form `x' = (c + dx)(a + bx)⁻¹` of the versor's 2×2 matrix over Cl(3,0),
    /// 43 products instead of the sandwich's 160, and no `x²` term to lose precision far
    /// from the origin. Odd versors (reflections) use the full sandwich. For an even
    /// multivector that is not a versor the image is not a point, and neither route means
    /// anything.
    pub fn transform_point(&self, x: DVec3) -> Result<DVec3, CgaError> {
        if self.is_even() {
            let vahlen = crate::generated::vahlen_even(self.coefficients());
            let (position, weight) = crate::generated::moebius_point(&vahlen, &x.to_array());
            point_from_weighted(DVec3::from_array(position), weight)
        } else {
            self.sandwich(&Self::up(x))?.down()
        }
    }
}

/// `position / weight`, or [`CgaError::PointAtInfinity`] when the weight is zero, not
/// finite, or negligible against the position (the point went to infinity).
pub(crate) fn point_from_weighted(position: DVec3, weight: f64) -> Result<DVec3, CgaError> {
    if weight == 0.0 || !weight.is_finite() || weight.abs() <= 1e-12 * position.abs().max_element()
    {
        return Err(CgaError::PointAtInfinity);
    }
    Ok(position / weight)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn up_down_examples() {
        assert_eq!(
            Multivector::up(DVec3::X),
            Multivector::e1() + Multivector::e5()
        );
        assert_eq!(Multivector::up(DVec3::ZERO), Multivector::eo());
        let p = DVec3::new(1.5, -2.0, 0.25);
        assert!(((Multivector::up(p) * 3.0).down().unwrap() - p).length() < 1e-15);
        assert_eq!(Multivector::einf().down(), Err(CgaError::PointAtInfinity));
    }

    #[test]
    fn points_far_from_the_origin_keep_their_precision() {
        let s = crate::Similarity {
            translation: DVec3::new(-2.5e6, 1.25e6, 3.0e5),
            rotation: glam::DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.7),
            scale: 1.5,
        };
        let m = s.to_versor().unwrap();
        let x = DVec3::new(1.0e6 + 0.125, -2.0e6 + 0.5, 7.0e5 - 0.25);
        let expected = s.transform_point(x);
        // |x|² is 5e12 here: the dense sandwich M up(x) M̃, which carries it, is off by 160.
        let error = (m.transform_point(x).unwrap() - expected).length();
        assert!(error < 1e-8, "error {error}");
    }

    #[test]
    fn a_transversion_can_send_a_point_to_infinity() {
        // K = 1 + c∧eo maps x to x(1 − cx)⁻¹, which is at infinity for x = c/|c|².
        let c = DVec3::new(0.0, 0.5, 0.0);
        let k = Multivector::scalar(1.0) + (Multivector::from_vector(c) ^ Multivector::eo());
        assert_eq!(
            k.transform_point(DVec3::new(0.0, 2.0, 0.0)),
            Err(CgaError::PointAtInfinity)
        );
        let moved = k.transform_point(DVec3::new(0.0, 1.0, 0.0)).unwrap();
        let by_sandwich = k
            .sandwich(&Multivector::up(DVec3::Y))
            .unwrap()
            .down()
            .unwrap();
        assert!(
            (moved - by_sandwich).length() < 1e-15,
            "{moved} vs {by_sandwich}"
        );
    }

    #[test]
    fn sphere_round_trip() {
        let c = DVec3::new(1.0, 2.0, 3.0);
        let (c2, r) = (Multivector::sphere(c, 0.5) * -2.0)
            .sphere_center_radius()
            .unwrap();
        assert!((c2 - c).length() < 1e-12);
        assert!((r - 0.5).abs() < 1e-12);
        // A point lies on a sphere exactly when their inner product vanishes.
        let s = Multivector::sphere(c, 0.5);
        let on = Multivector::up(c + DVec3::new(0.0, 0.5, 0.0));
        assert!((s | on).scalar_part().abs() < 1e-12);
    }
}

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
    /// Even versors (every product of translators, rotors and dilators) take a fast path
    /// that multiplies only the grades involved; others use the full sandwich.
    pub fn transform_point(&self, x: DVec3) -> Result<DVec3, CgaError> {
        let c = self.coefficients();
        let odd = [1, 2, 3, 4, 5, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 31];
        if odd.iter().all(|&i| c[i] == 0.0) {
            let h = 0.5 * x.length_squared();
            // up(x) = x + ½x² einf + eo: e4 gets ½x² − ½, e5 gets ½x² + ½.
            let image =
                crate::generated::sandwich_even_vector(c, &[x.x, x.y, x.z, h - 0.5, h + 0.5]);
            point_from_image(&image)
        } else {
            self.sandwich(&Self::up(x))?.down()
        }
    }
}

/// The Euclidean point of the `e1 … e5` coefficients of a conformal point's image:
/// its Euclidean part over its weight `e5 − e4`.
pub(crate) fn point_from_image(image: &[f64; 5]) -> Result<DVec3, CgaError> {
    let weight = image[4] - image[3];
    let position = DVec3::new(image[0], image[1], image[2]);
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

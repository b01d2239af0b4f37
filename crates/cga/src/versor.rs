//! Versors: translators, rotors, dilators, and rotor ↔ quaternion.

use crate::{CgaError, Multivector, TOLERANCE};
use glam::{DQuat, DVec3};

/// Canonical indices of the Euclidean bivectors.
const E12: usize = 6;
const E13: usize = 7;
const E23: usize = 10;
/// Canonical index of `e45 = einf ∧ eo`.
const E45: usize = 15;

impl Multivector {
    /// The translator by the Euclidean vector `t`: `T(t) = 1 − ½ t einf`.
    pub fn translator(t: DVec3) -> Self {
        Self::ONE - Self::from_vector(t) * Self::einf() * 0.5
    }

    /// The rotor turning `u` toward `v` by `angle` radians in the plane `u ∧ v`:
    /// `R = cos(θ/2) − sin(θ/2) B` with `B` the unit bivector of `u ∧ v`. So
    /// `rotor(θ, e1, e2)` is +θ about +Z and `rotor(θ, e3, e1)` is +θ about +Y.
    ///
    /// `u ∧ v` must be a non-zero Euclidean plane.
    pub fn rotor(angle: f64, u: &Self, v: &Self) -> Result<Self, CgaError> {
        if !angle.is_finite() {
            return Err(CgaError::NotFinite(format!("rotation angle {angle}")));
        }
        let plane = (*u ^ *v).grade(2);
        let euclidean = plane[E12].hypot(plane[E13]).hypot(plane[E23]);
        let other = (plane - euclidean_bivector_part(&plane)).max_abs();
        if euclidean <= 1e-12 || !euclidean.is_finite() {
            return Err(CgaError::NoPlane(format!(
                "{u} and {v} are parallel or zero; give two different directions such as e1, e3"
            )));
        }
        if other > TOLERANCE * euclidean {
            return Err(CgaError::NoPlane(format!(
                "{plane} is not a Euclidean plane; use directions built from e1, e2, e3"
            )));
        }
        let unit = euclidean_bivector_part(&plane) / euclidean;
        let (s, c) = (0.5 * angle).sin_cos();
        Ok(Self::scalar(c) - unit * s)
    }

    /// The dilator scaling by `s > 0` about the origin:
    /// `D(s) = cosh(ln s / 2) − sinh(ln s / 2) e45`.
    pub fn dilator(s: f64) -> Result<Self, CgaError> {
        if !(s.is_finite() && s > 0.0) {
            return Err(CgaError::BadScale(s));
        }
        let half = 0.5 * s.ln();
        let mut d = Self::scalar(half.cosh());
        d[E45] = -half.sinh();
        Ok(d)
    }

    /// The rotor of a unit quaternion `[x, y, z, w]` (same rotation, right-hand rule):
    /// `R = w − x e23 + y e13 − z e12`.
    pub fn rotor_from_quat(q: DQuat) -> Self {
        let mut r = Self::scalar(q.w);
        r[E23] = -q.x;
        r[E13] = q.y;
        r[E12] = -q.z;
        r
    }

    /// The unit quaternion `[x, y, z, w]` of the rotor part of `self` (its scalar and
    /// Euclidean bivector coefficients, normalised), with `w ≥ 0`. The inverse of
    /// [`Multivector::rotor_from_quat`] up to the sign of the quaternion.
    pub fn rotor_to_quat(&self) -> DQuat {
        let q = DQuat::from_xyzw(-self[E23], self[E13], -self[E12], self[0]).normalize();
        let q = if q.w < 0.0 { -q } else { q };
        // Adding zero turns -0.0 into 0.0, so outputs never show "-0".
        DQuat::from_array(q.to_array().map(|c| c + 0.0))
    }
}

fn euclidean_bivector_part(m: &Multivector) -> Multivector {
    let mut out = Multivector::ZERO;
    for i in [E12, E13, E23] {
        out[i] = m[i];
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).length() < 1e-12
    }

    #[test]
    fn translator_moves_points() {
        let t = Multivector::translator(DVec3::new(1.0, 2.0, 3.0));
        let p = t.transform_point(DVec3::new(1.0, 1.0, 1.0)).unwrap();
        assert!(close(p, DVec3::new(2.0, 3.0, 4.0)));
    }

    #[test]
    fn rotor_senses_follow_spec() {
        let (e1, e2, e3) = (Multivector::e1(), Multivector::e2(), Multivector::e3());
        // +90° about +Z takes +X to +Y.
        let rz = Multivector::rotor(FRAC_PI_2, &e1, &e2).unwrap();
        assert!(close(rz.transform_point(DVec3::X).unwrap(), DVec3::Y));
        // +90° about +Y takes +Z to +X (SPEC §1).
        let ry = Multivector::rotor(FRAC_PI_2, &e3, &e1).unwrap();
        assert!(close(ry.transform_point(DVec3::Z).unwrap(), DVec3::X));
        let q = ry.rotor_to_quat();
        assert!(q.abs_diff_eq(DQuat::from_rotation_y(FRAC_PI_2), 1e-12));
    }

    #[test]
    fn rotor_errors() {
        let e1 = Multivector::e1();
        assert!(matches!(
            Multivector::rotor(1.0, &e1, &(e1 * 2.0)),
            Err(CgaError::NoPlane(_))
        ));
        assert!(matches!(
            Multivector::rotor(1.0, &e1, &Multivector::e4()),
            Err(CgaError::NoPlane(_))
        ));
        assert!(Multivector::rotor(f64::NAN, &e1, &Multivector::e2()).is_err());
    }

    #[test]
    fn dilator_scales_about_origin() {
        let d = Multivector::dilator(2.0).unwrap();
        assert!(close(
            d.transform_point(DVec3::new(1.0, -1.0, 0.5)).unwrap(),
            DVec3::new(2.0, -2.0, 1.0)
        ));
        assert_eq!(Multivector::dilator(-1.0), Err(CgaError::BadScale(-1.0)));
        assert_eq!(Multivector::dilator(0.0), Err(CgaError::BadScale(0.0)));
    }
}

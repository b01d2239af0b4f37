//! Typed even versors: rotors and motors stored on their own few blades, with products
//! that compute only those (generated from the blade rules like every kernel).
//!
//! A [`Multivector`] product runs the dense 32 × 32 kernel (≈ 65 ns); a rotor has 4
//! coefficients and a motor 8, and the groups are closed, so `Rotor * Rotor` is a
//! quaternion product (16 terms) and `Motor * Motor` a dual-quaternion one (48 terms).
//! Convert with `From`/`TryFrom` at the edges: `Multivector::from(motor)` for the
//! expression language, `Motor::try_from(&m)` to check that a multivector is one.
//!
//! ```
//! use cga::{Motor, Rotor, Multivector};
//! use glam::{DQuat, DVec3};
//!
//! let turn = Rotor::from_quat(DQuat::from_rotation_y(std::f64::consts::FRAC_PI_2));
//! let m = Motor::translator(DVec3::X) * Motor::from(turn);
//! let p = m.transform_point(DVec3::Z);
//! assert!((p - DVec3::new(2.0, 0.0, 0.0)).length() < 1e-12);
//! // The same as the dense product of the same versors.
//! let dense = Multivector::translator(DVec3::X) * Multivector::from(turn);
//! assert!((Multivector::from(m) - dense).max_abs() < 1e-15);
//! ```

use crate::{generated, CgaError, Multivector, TOLERANCE};
use glam::{DQuat, DVec3};
use std::ops::Mul;

/// Canonical blade indices of `1, e12, e13, e23`.
const ROTOR_BLADES: [usize; 4] = [0, 6, 7, 10];
/// Canonical indices of the blade pairs `e_i4, e_i5` that carry `e_i einf`, and of
/// `e1234, e1235` for `e123 einf`.
const EINF_PAIRS: [(usize, usize); 4] = [(8, 9), (11, 12), (13, 14), (26, 27)];

/// A rotor `R = a + b e12 + c e13 + d e23`: a rotation about the origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rotor(pub [f64; 4]);

/// A motor `M = T·R` on `[1, e12, e13, e23, e1∞, e2∞, e3∞, e123∞]` (∞ = einf =
/// e4 + e5): a rigid motion, rotation then translation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motor(pub [f64; 8]);

impl Rotor {
    /// No rotation.
    pub const IDENTITY: Self = Self([1.0, 0.0, 0.0, 0.0]);

    /// The rotor of a unit quaternion (the same rotation, right-hand rule), as
    /// [`Multivector::rotor_from_quat`].
    #[must_use]
    pub fn from_quat(q: DQuat) -> Self {
        Self([q.w, -q.z, q.y, -q.x])
    }

    /// The unit quaternion of this rotor, normalised, with `w ≥ 0`.
    #[must_use]
    pub fn to_quat(&self) -> DQuat {
        let [w, e12, e13, e23] = self.0;
        let q = DQuat::from_xyzw(-e23, e13, -e12, w).normalize();
        if q.w < 0.0 {
            -q
        } else {
            q
        }
    }

    /// The reverse `R̃` (the inverse of a unit rotor).
    #[must_use]
    pub fn reverse(&self) -> Self {
        let [w, a, b, c] = self.0;
        Self([w, -a, -b, -c])
    }
}

impl Motor {
    /// No motion.
    pub const IDENTITY: Self = Self([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);

    /// The translator `T(t) = 1 − ½ t einf`.
    #[must_use]
    pub fn translator(t: DVec3) -> Self {
        Self([1.0, 0.0, 0.0, 0.0, -0.5 * t.x, -0.5 * t.y, -0.5 * t.z, 0.0])
    }

    /// The rotor part `R` (`M = T·R`).
    #[must_use]
    pub fn rotor(&self) -> Rotor {
        Rotor([self.0[0], self.0[1], self.0[2], self.0[3]])
    }

    /// The translation part `t` (`M = T(t)·R`), for a unit rotor part.
    #[must_use]
    pub fn translation(&self) -> DVec3 {
        DVec3::from_array(generated::motor_translation(&self.0))
    }

    /// The reverse `M̃` (the inverse of a unit motor).
    #[must_use]
    pub fn reverse(&self) -> Self {
        let [s, a, b, c, d, e, f, g] = self.0;
        // Bivectors (e12…, e_i∞) change sign; the grade-4 e123∞ does not.
        Self([s, -a, -b, -c, -d, -e, -f, g])
    }

    /// Applies the motion to a Euclidean point: `R x R̃ + t`, through the rotation as a
    /// quaternion (no conformal point is built, so it is exact far from the origin).
    #[must_use]
    pub fn transform_point(&self, x: DVec3) -> DVec3 {
        let [w, e12, e13, e23] = self.rotor().0;
        let q = DQuat::from_xyzw(-e23, e13, -e12, w);
        q * x + self.translation()
    }
}

impl Mul for Rotor {
    type Output = Self;
    /// The geometric product on the rotor's own blades (16 terms).
    #[inline]
    fn mul(self, rhs: Self) -> Self {
        Self(generated::rotor_product(&self.0, &rhs.0))
    }
}

impl Mul for Motor {
    type Output = Self;
    /// The geometric product on the motor's own blades (48 terms).
    #[inline]
    fn mul(self, rhs: Self) -> Self {
        Self(generated::motor_product(&self.0, &rhs.0))
    }
}

impl From<Rotor> for Motor {
    fn from(r: Rotor) -> Self {
        let [a, b, c, d] = r.0;
        Self([a, b, c, d, 0.0, 0.0, 0.0, 0.0])
    }
}

impl From<Rotor> for Multivector {
    fn from(r: Rotor) -> Self {
        let mut m = Multivector::ZERO;
        for (k, &i) in ROTOR_BLADES.iter().enumerate() {
            m[i] = r.0[k];
        }
        m
    }
}

impl From<Motor> for Multivector {
    fn from(motor: Motor) -> Self {
        let mut m = Multivector::from(motor.rotor());
        for (k, &(i4, i5)) in EINF_PAIRS.iter().enumerate() {
            m[i4] = motor.0[4 + k];
            m[i5] = motor.0[4 + k];
        }
        m
    }
}

/// Whether `m` has nothing (to `TOLERANCE` of its size) outside the blades `keep` allows.
fn only_on(m: &Multivector, keep: impl Fn(usize) -> bool) -> bool {
    let size = m.max_abs().max(f64::MIN_POSITIVE);
    (0..crate::BLADE_COUNT).all(|i| keep(i) || m[i].abs() <= TOLERANCE * size)
}

impl TryFrom<&Multivector> for Rotor {
    type Error = CgaError;
    /// The rotor `m` is, if it has only scalar and Euclidean bivector parts.
    fn try_from(m: &Multivector) -> Result<Self, CgaError> {
        if !m.is_finite() {
            return Err(CgaError::NotFinite(m.to_string()));
        }
        if !only_on(m, |i| ROTOR_BLADES.contains(&i)) {
            return Err(CgaError::NotSimilarity(format!("{m} is not a rotor")));
        }
        Ok(Self(ROTOR_BLADES.map(|i| m[i])))
    }
}

impl TryFrom<&Multivector> for Motor {
    type Error = CgaError;
    /// The motor `m` is, if it lies on the motor blades with equal `e_i4` and `e_i5`
    /// parts (an `e_i einf`).
    fn try_from(m: &Multivector) -> Result<Self, CgaError> {
        if !m.is_finite() {
            return Err(CgaError::NotFinite(m.to_string()));
        }
        let on_blades = only_on(m, |i| {
            ROTOR_BLADES.contains(&i) || EINF_PAIRS.iter().any(|&(a, b)| i == a || i == b)
        });
        let size = m.max_abs().max(f64::MIN_POSITIVE);
        let paired = EINF_PAIRS
            .iter()
            .all(|&(a, b)| (m[a] - m[b]).abs() <= TOLERANCE * size);
        if !(on_blades && paired) {
            return Err(CgaError::NotSimilarity(format!(
                "{m} is not a motor (a rotation and a translation)"
            )));
        }
        let mut c = [0.0; 8];
        for (k, &i) in ROTOR_BLADES.iter().enumerate() {
            c[k] = m[i];
        }
        for (k, &(a, b)) in EINF_PAIRS.iter().enumerate() {
            c[4 + k] = 0.5 * (m[a] + m[b]);
        }
        Ok(Self(c))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn motors() -> Vec<Motor> {
        let axes = [
            DVec3::new(1.0, 2.0, 3.0),
            DVec3::new(-0.3, 0.1, 0.9),
            DVec3::Y,
        ];
        let mut out = Vec::new();
        for (k, axis) in axes.iter().enumerate() {
            let q = DQuat::from_axis_angle(axis.normalize(), 0.4 + k as f64);
            let t = DVec3::new(k as f64 - 1.5, 2.0 * k as f64, -0.7);
            out.push(Motor::translator(t) * Motor::from(Rotor::from_quat(q)));
        }
        out.push(Motor::IDENTITY);
        out
    }

    #[test]
    fn typed_products_equal_the_dense_product() {
        for a in motors() {
            for b in motors() {
                let typed = Multivector::from(a * b);
                let dense = Multivector::from(a) * Multivector::from(b);
                assert!((typed - dense).max_abs() < 1e-14, "{typed} vs {dense}");
                let (ra, rb) = (a.rotor(), b.rotor());
                let r = Multivector::from(ra * rb);
                assert!((r - Multivector::from(ra) * Multivector::from(rb)).max_abs() < 1e-14);
            }
        }
    }

    #[test]
    fn a_motor_moves_points_as_its_versor_does() {
        for m in motors() {
            let v = Multivector::from(m);
            for x in [DVec3::ZERO, DVec3::new(1.0, -2.0, 0.5), DVec3::splat(1e6)] {
                let expected = v.transform_point(x).unwrap();
                let got = m.transform_point(x);
                assert!(
                    (got - expected).length() <= 1e-9 * expected.length().max(1.0),
                    "{got} vs {expected}"
                );
            }
            // Translation and rotor parts give the motor back.
            let rebuilt = Motor::translator(m.translation()) * Motor::from(m.rotor());
            assert!((Multivector::from(rebuilt) - Multivector::from(m)).max_abs() < 1e-12);
            // The reverse undoes it.
            let one = Multivector::from(m * m.reverse());
            assert!((one - Multivector::ONE).max_abs() < 1e-12);
        }
    }

    #[test]
    fn conversions_check_the_form() {
        let m = motors()[0];
        assert_eq!(Motor::try_from(&Multivector::from(m)).unwrap(), m);
        let r = m.rotor();
        assert_eq!(Rotor::try_from(&Multivector::from(r)).unwrap(), r);
        assert!(
            Rotor::try_from(&Multivector::from(m)).is_err(),
            "it translates"
        );
        let dilator = Multivector::dilator(2.0).unwrap();
        assert!(Motor::try_from(&dilator).is_err(), "a dilator is no motor");
        assert!(Motor::try_from(&Multivector::e1()).is_err());
        let q = DQuat::from_rotation_x(0.3);
        assert!(Rotor::from_quat(q).to_quat().abs_diff_eq(q, 1e-15));
    }
}

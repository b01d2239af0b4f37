//! A versor's decomposition into translation, rotation and uniform scale.

use crate::{CgaError, Multivector, TOLERANCE};
use glam::{DQuat, DVec3};

/// A similarity transformation `x ↦ s·q(x) + t`: the decomposition `M = T·R·D` of a
/// versor into a translation `t`, a rotation `q` (unit quaternion `[x, y, z, w]`,
/// `w ≥ 0`) and a uniform scale `s > 0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Similarity {
    /// Translation `t`.
    pub translation: DVec3,
    /// Rotation `q`, a unit quaternion.
    pub rotation: DQuat,
    /// Uniform scale `s > 0`.
    pub scale: f64,
}

impl Default for Similarity {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Similarity {
    /// The identity transformation.
    pub const IDENTITY: Self = Self {
        translation: DVec3::ZERO,
        rotation: DQuat::IDENTITY,
        scale: 1.0,
    };

    /// The versor `T(t)·R(q)·D(s)`.
    ///
    /// # Errors
    /// If the scale is not a finite number > 0.
    pub fn to_versor(&self) -> Result<Multivector, CgaError> {
        let t = Multivector::translator(self.translation);
        let r = Multivector::rotor_from_quat(self.rotation.normalize());
        let d = Multivector::dilator(self.scale)?;
        Ok(t.geometric_even_even(&r).geometric_even_even(&d))
    }

    /// Applies the transformation to a Euclidean point: `s·q(x) + t`.
    #[must_use]
    pub fn transform_point(&self, x: DVec3) -> DVec3 {
        self.rotation * (x * self.scale) + self.translation
    }

    /// Whether every component is finite, the scale is > 0 and the rotation is a unit
    /// quaternion (to rounding).
    #[must_use]
    pub fn is_valid(&self) -> bool {
        self.translation.is_finite()
            && self.rotation.is_finite()
            && (self.rotation.length_squared() - 1.0).abs() < 1e-9
            && self.scale.is_finite()
            && self.scale > 0.0
    }

    /// The transformation `self ∘ other`: `other` first, then `self` — the versor product
    /// `self · other`, computed on the parts: `s = s₁s₂`, `q = q₁q₂`, `t = s₁q₁(t₂) + t₁`.
    ///
    /// The rotation is renormalised and given `w ≥ 0`, so composing many steps never lets
    /// rounding build up into a shear or a drifting scale, and the translation is exact to
    /// the rounding of one multiply-add per component (no sandwich of conformal points,
    /// which carry `½|x|²`).
    #[must_use]
    pub fn compose(&self, other: &Self) -> Self {
        let mut rotation = (self.rotation * other.rotation).normalize();
        if rotation.w < 0.0 {
            rotation = -rotation;
        }
        Self {
            translation: self.transform_point(other.translation),
            rotation,
            scale: self.scale * other.scale,
        }
    }

    /// The inverse transformation: `x ↦ q⁻¹(x − t) / s`.
    #[must_use]
    pub fn inverse(&self) -> Self {
        let rotation = self.rotation.conjugate();
        Self {
            translation: -(rotation * self.translation) / self.scale,
            rotation,
            scale: 1.0 / self.scale,
        }
    }

    /// The translation by `t`.
    #[must_use]
    pub fn translation(t: DVec3) -> Self {
        Self {
            translation: t,
            ..Self::IDENTITY
        }
    }

    /// `self` acting about the point `p` instead of the origin: `T(p)·self·T(p)⁻¹`.
    #[must_use]
    pub fn about(&self, p: DVec3) -> Self {
        Self {
            translation: self.translation + p - self.rotation * (p * self.scale),
            ..*self
        }
    }

    /// Decomposes a versor `M` (any non-zero multiple of a product of translators, rotors
    /// and dilators) into `T·R·D`.
    ///
    /// `M` is normalised; the rotor is M's Euclidean part (`cosh(ln s / 2)·R`); the scale —
    /// the radius of the image of the unit sphere — comes from the e45-carrying part
    /// (`−sinh(ln s / 2)·R e45`); the translation — the image's centre — is read from
    /// `T = M D(s)⁻¹ R̃ = 1 − ½ t einf`. `T·R·D` rebuilt from these must equal `M`. No
    /// step cancels large terms, so the result stays exact far from the origin, and exact
    /// inputs give exact outputs. Anything else — a vector, a reflection, a transversion, a NaN — is an error
    /// that says what the multivector is instead.
    pub fn from_versor(m: &Multivector) -> Result<Self, CgaError> {
        if !m.is_finite() {
            return Err(CgaError::NotFinite(m.to_string()));
        }
        let size = m.max_abs();
        if size == 0.0 {
            return Err(CgaError::NotSimilarity("the result is zero".into()));
        }
        let odd = m.odd().max_abs();
        if odd > TOLERANCE * size {
            let hint = if m.even().max_abs() <= TOLERANCE * size && m.grade(1).max_abs() >= odd {
                "the result is a vector, not a transformation: wrap a translation vector in T(...)"
                    .to_string()
            } else {
                format!("{m} has odd grades (a reflection or a vector)")
            };
            return Err(CgaError::NotSimilarity(hint));
        }
        let m = m.even();
        let mm = m.geometric_even_even(&m.reverse());
        let n = mm.scalar_part();
        let non_scalar = (mm - Multivector::scalar(n)).max_abs();
        if n <= 0.0 || non_scalar > TOLERANCE * n.abs().max(f64::MIN_POSITIVE) {
            return Err(CgaError::NotSimilarity(format!(
                "{m} is not a versor (M·~M is not a positive scalar)"
            )));
        }
        let m = m / n.sqrt();

        // The blades without e4 or e5 come only from T's scalar, R, and D's scalar: they are
        // cosh(ln s / 2)·R. Reading R there needs no cancellation at all.
        let mut rotor_part = Multivector::ZERO;
        for i in [0, 6, 7, 10] {
            rotor_part[i] = m[i];
        }
        let weight = rotor_part.norm_squared().sqrt();
        if !(weight > 0.0 && weight.is_finite()) {
            return Err(CgaError::NotSimilarity(format!("{m} has no rotation part")));
        }
        let rotation = rotor_part.rotor_to_quat();
        // D(s) = cosh a − sinh a e45 with a = ln(s)/2, so the e45-carrying blades of M are
        // (R·e45)·(−sinh a): their coefficients are −tanh a times the Euclidean ones, and T
        // never reaches them. This gives s exactly (s = 1 when M has no dilation).
        let euclidean = [m[0], m[6], m[7], m[10]];
        let dilated = [m[15], m[28], m[29], m[30]];
        let dot: f64 = euclidean.iter().zip(&dilated).map(|(a, b)| a * b).sum();
        let tanh_a = -dot / (weight * weight);
        let scale = (1.0 + tanh_a) / (1.0 - tanh_a);
        if !(scale > 0.0 && scale.is_finite()) {
            return Err(CgaError::NotSimilarity(format!(
                "{m} has no finite positive scale"
            )));
        }
        // With R and s known, T = M D(s)⁻¹ R̃ = 1 − ½ t einf, whose e_i4 coefficients are
        // −½ tᵢ: the translation, read without dividing by a weight.
        // (R with the sign it has in M, not the canonical w ≥ 0 one, so that T comes out
        // with scalar part +1 whatever sign M was given.)
        let translator = m
            .geometric_even_even(&Multivector::dilator(1.0 / scale)?)
            .geometric_even_even(&(rotor_part / weight).reverse());
        // (+ 0.0 turns −0.0 into 0.0, so outputs never show "-0".)
        let translation = DVec3::new(
            -2.0 * translator[8],
            -2.0 * translator[11],
            -2.0 * translator[13],
        ) + DVec3::ZERO;
        // Whatever M was, it must be exactly T·R·D (up to sign): anything else bends lines.
        let rebuilt = Multivector::translator(translation)
            .geometric_even_even(&Multivector::rotor_from_quat(rotation))
            .geometric_even_even(&Multivector::dilator(scale)?);
        let tolerance = TOLERANCE * m.max_abs().max(1.0);
        let matches = |sign: f64| (rebuilt * sign - m).max_abs() <= tolerance;
        if !(matches(1.0) || matches(-1.0)) {
            return Err(CgaError::NotSimilarity(format!(
                "{m} is not a translation, rotation and uniform scaling (it bends lines: a transversion or a general conformal map)"
            )));
        }
        Ok(Self {
            translation,
            rotation,
            scale,
        })
    }
}

impl std::ops::Mul for Similarity {
    type Output = Self;

    /// `a * b` is [`Similarity::compose`]: `b` first, then `a`, as for versors.
    fn mul(self, rhs: Self) -> Self {
        self.compose(&rhs)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> [Similarity; 3] {
        [
            Similarity {
                translation: DVec3::new(1.0, -2.0, 0.5),
                rotation: DQuat::from_rotation_y(0.7),
                scale: 1.5,
            },
            Similarity {
                translation: DVec3::new(-3.0, 0.25, 4.0),
                rotation: DQuat::from_axis_angle(DVec3::new(1.0, 2.0, -0.5).normalize(), 2.9),
                scale: 0.4,
            },
            Similarity::translation(DVec3::new(0.0, 0.0, -7.0)),
        ]
    }

    #[test]
    fn composing_parts_matches_the_versor_product() {
        for a in sample() {
            for b in sample() {
                let parts = a * b;
                let product =
                    Similarity::from_versor(&(a.to_versor().unwrap() * b.to_versor().unwrap()))
                        .unwrap();
                assert!((parts.translation - product.translation).length() < 1e-12);
                assert!(parts.rotation.dot(product.rotation).abs() > 1.0 - 1e-12);
                assert!((parts.scale - product.scale).abs() < 1e-12);
                let x = DVec3::new(0.3, 1.7, -2.2);
                let twice = a.transform_point(b.transform_point(x));
                assert!((parts.transform_point(x) - twice).length() < 1e-12);
            }
        }
    }

    #[test]
    fn inverse_and_about() {
        for a in sample() {
            let i = a * a.inverse();
            assert!(i.translation.length() < 1e-12);
            assert!((i.scale - 1.0).abs() < 1e-15);
            assert!(i.rotation.abs_diff_eq(DQuat::IDENTITY, 1e-12));
            let p = DVec3::new(5.0, -1.0, 2.0);
            let about = a.about(p);
            let versor =
                Multivector::translator(p) * a.to_versor().unwrap() * Multivector::translator(-p);
            let expected = Similarity::from_versor(&versor).unwrap();
            assert!((about.translation - expected.translation).length() < 1e-12);
            // The pivot itself only moves by a's rotation-free part about it.
            assert!((about.transform_point(p) - (p + a.translation)).length() < 1e-12);
        }
    }

    #[test]
    fn a_large_move_and_back_leaves_the_pose_as_it_was() {
        let pose = sample()[1];
        let far = Similarity::translation(DVec3::new(1e6, 0.0, 0.0));
        let back = far.inverse() * (far * pose);
        assert_eq!(back.rotation, pose.rotation);
        assert_eq!(back.scale, pose.scale);
        assert!((back.translation - pose.translation).length() < 1e-9);
    }

    #[test]
    fn identity_and_examples() {
        let s = Similarity::from_versor(&Multivector::ONE).unwrap();
        assert_eq!(s.scale, 1.0);
        assert!(s.translation.length() < 1e-15);
        let m = Multivector::translator(DVec3::new(0.0, 0.0, -1.0))
            * Multivector::rotor(1.0, &Multivector::e1(), &Multivector::e2()).unwrap()
            * Multivector::dilator(3.0).unwrap()
            * -2.0;
        let s = Similarity::from_versor(&m).unwrap();
        assert!((s.translation - DVec3::new(0.0, 0.0, -1.0)).length() < 1e-12);
        assert!((s.scale - 3.0).abs() < 1e-12);
        assert!(s.rotation.abs_diff_eq(DQuat::from_rotation_z(1.0), 1e-12));
    }

    #[test]
    fn rejects_non_similarities() {
        let vector = Similarity::from_versor(&Multivector::e1()).unwrap_err();
        assert!(
            vector
                .to_string()
                .contains("wrap a translation vector in T(...)"),
            "{vector}"
        );
        assert!(Similarity::from_versor(&Multivector::ZERO).is_err());
        let nan = Multivector::scalar(f64::NAN);
        assert!(matches!(
            Similarity::from_versor(&nan),
            Err(CgaError::NotFinite(_))
        ));
        // A transversion 1 + eo·b maps the sphere to a sphere but is not T·R·D.
        let transversion = Multivector::ONE + Multivector::eo() * Multivector::e1() * 0.3;
        assert!(Similarity::from_versor(&transversion).is_err());
        // A bivector that is not a rotor.
        let boost = Multivector::ONE + Multivector::blade_by_name("e14").unwrap();
        assert!(Similarity::from_versor(&boost).is_err());
    }
}

#[cfg(test)]
mod far_from_origin {
    use super::*;

    #[test]
    fn scale_stays_exact_for_objects_far_from_the_origin() {
        for distance in [1.0, 470.0, 1e4, 1e6] {
            let s = Similarity {
                translation: DVec3::new(distance, -0.5 * distance, 0.3 * distance),
                rotation: DQuat::from_rotation_y(0.3),
                scale: 1.0,
            };
            let d = Similarity::from_versor(&s.to_versor().unwrap()).unwrap();
            assert!(
                (d.scale - 1.0).abs() < 1e-12,
                "at {distance}: scale {}",
                d.scale
            );
            assert!((d.translation - s.translation).length() < 1e-12 * distance.max(1.0) * 10.0);
        }
    }
}

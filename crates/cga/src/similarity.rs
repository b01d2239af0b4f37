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
    pub fn transform_point(&self, x: DVec3) -> DVec3 {
        self.rotation * (x * self.scale) + self.translation
    }

    /// Decomposes a versor `M` (any non-zero multiple of a product of translators, rotors
    /// and dilators) into `T·R·D`.
    ///
    /// `M` is normalised; the image of a sphere about the origin gives the translation (its
    /// centre, the image of the origin) and the scale (its radius, read from the image of
    /// infinity, `M einf M̃ = s einf`); the rotor is M's Euclidean part. `T·R·D` rebuilt
    /// from these must equal `M`. Every step stays exact for objects far from the origin. Anything else — a vector, a reflection, a transversion, a NaN — is an error
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

        // T and R fix infinity and D(s) scales it: M einf M̃ = s einf. Reading the scale
        // there avoids the cancellation of the sphere's S² = r², whose terms grow as |t|⁴
        // and lose digits for objects far from the origin.
        let infinity = m.sandwich_even_on_vector(&Multivector::einf());
        let scale = 0.5 * (infinity[4] + infinity[5]);
        let mut off_infinity = infinity;
        off_infinity[4] -= scale;
        off_infinity[5] -= scale;
        if !(scale > 0.0 && scale.is_finite())
            || off_infinity.max_abs() > TOLERANCE * scale.abs().max(1.0)
        {
            return Err(CgaError::NotSimilarity(format!(
                "{m} does not keep infinity at infinity (it is not a translation, rotation and uniform scaling)"
            )));
        }
        // The centre of the image of a sphere about the origin — the image of the origin.
        let translation = m
            .sandwich_even_on_vector(&Multivector::eo())
            .down()
            .map_err(|_| CgaError::NotSimilarity(format!("{m} sends the origin to infinity")))?;
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

#[cfg(test)]
mod tests {
    use super::*;

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

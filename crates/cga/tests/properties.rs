//! Algebraic laws checked on random inputs.

use cga::{Multivector, PointMap, Similarity};
use glam::{DQuat, DVec3};
use proptest::prelude::*;

fn coefficient() -> impl Strategy<Value = f64> {
    -10.0f64..10.0
}

fn multivector() -> impl Strategy<Value = Multivector> {
    prop::array::uniform32(coefficient()).prop_map(Multivector::from_coefficients)
}

fn vector() -> impl Strategy<Value = Multivector> {
    prop::array::uniform5(coefficient()).prop_map(|c| {
        let mut m = Multivector::ZERO;
        for (i, x) in c.into_iter().enumerate() {
            m[i + 1] = x;
        }
        m
    })
}

fn point() -> impl Strategy<Value = DVec3> {
    (coefficient(), coefficient(), coefficient()).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn quat() -> impl Strategy<Value = DQuat> {
    (point(), -10.0f64..10.0).prop_filter_map("axis must be non-zero", |(axis, angle)| {
        (axis.length() > 1e-3).then(|| DQuat::from_axis_angle(axis.normalize(), angle))
    })
}

fn similarity() -> impl Strategy<Value = Similarity> {
    (point(), quat(), 0.05f64..20.0).prop_map(|(translation, rotation, scale)| Similarity {
        translation,
        rotation,
        scale,
    })
}

/// Relative closeness for products of numbers up to ~10: errors grow with magnitude.
fn close(a: &Multivector, b: &Multivector, tol: f64) -> bool {
    a.is_close(b, tol)
}

proptest! {
    #[test]
    fn geometric_product_is_associative(a in multivector(), b in multivector(), c in multivector()) {
        prop_assert!(close(&((a * b) * c), &(a * (b * c)), 1e-12));
    }

    #[test]
    fn geometric_product_distributes(a in multivector(), b in multivector(), c in multivector()) {
        prop_assert!(close(&(a * (b + c)), &(a * b + a * c), 1e-12));
        prop_assert!(close(&((b + c) * a), &(b * a + c * a), 1e-12));
    }

    #[test]
    fn vector_product_is_inner_plus_outer(u in vector(), v in vector()) {
        prop_assert!(close(&(u * v), &((u | v) + (u ^ v)), 1e-12));
        // For vectors the inner product is the symmetric part.
        prop_assert!(close(&(u | v), &((u * v + v * u) * 0.5), 1e-12));
    }

    #[test]
    fn inverse_is_two_sided(a in multivector()) {
        if let Ok(inv) = a.inverse() {
            prop_assert!(close(&(a * inv), &Multivector::ONE, 1e-7));
            prop_assert!(close(&(inv * a), &Multivector::ONE, 1e-7));
        }
    }

    #[test]
    fn versor_inverse(s in similarity()) {
        let m = s.to_versor().unwrap();
        let inv = m.inverse().unwrap();
        prop_assert!(close(&(m * inv), &Multivector::ONE, 1e-9));
    }

    #[test]
    fn up_is_null_and_down_inverts_it(x in point(), w in 0.1f64..10.0) {
        let p = Multivector::up(x);
        prop_assert!((p * p).max_abs() <= 1e-10 * (1.0 + x.length_squared()));
        let back = (p * w).down().unwrap();
        prop_assert!((back - x).length() <= 1e-12 * (1.0 + x.length()));
    }

    #[test]
    fn decomposition_round_trips(s in similarity()) {
        let m = s.to_versor().unwrap();
        let d = Similarity::from_versor(&m).unwrap();
        prop_assert!((d.translation - s.translation).length() < 1e-8 * (1.0 + s.translation.length()));
        prop_assert!((d.scale - s.scale).abs() < 1e-8 * s.scale);
        prop_assert!(d.rotation.dot(s.rotation).abs() > 1.0 - 1e-10);
        prop_assert!(d.to_versor().unwrap().is_close(&m, 1e-8) || d.to_versor().unwrap().is_close(&-m, 1e-8));
    }

    #[test]
    fn decomposition_of_scaled_versor(s in similarity(), k in prop_oneof![-5.0f64..-0.1, 0.1f64..5.0]) {
        let d = Similarity::from_versor(&(s.to_versor().unwrap() * k)).unwrap();
        prop_assert!((d.scale - s.scale).abs() < 1e-8 * s.scale);
    }

    #[test]
    fn quaternion_rotor_round_trip(q in quat()) {
        let back = Multivector::rotor_from_quat(q).rotor_to_quat();
        prop_assert!(back.dot(q).abs() > 1.0 - 1e-12);
        prop_assert!(back.w >= 0.0);
    }

    #[test]
    fn rotor_matches_quaternion_rotation(q in quat(), x in point()) {
        let r = Multivector::rotor_from_quat(q);
        let by_rotor = r.transform_point(x).unwrap();
        prop_assert!((by_rotor - q * x).length() < 1e-10 * (1.0 + x.length()));
    }

    #[test]
    fn versor_moves_points_like_its_decomposition(s in similarity(), x in point()) {
        let m = s.to_versor().unwrap();
        let expected = s.transform_point(x);
        let tol = 1e-8 * (1.0 + expected.length());
        prop_assert!((m.transform_point(x).unwrap() - expected).length() < tol);
        prop_assert!((PointMap::new(&m).unwrap().transform_point(x).unwrap() - expected).length() < tol);
    }

    #[test]
    fn even_versors_move_points_like_the_full_sandwich(
        s in similarity(),
        c in point(),
        k in 0.0f64..0.05,
        x in point(),
    ) {
        // A transversion K = 1 + c∧eo (a versor: K K̃ = 1) makes M a general conformal map,
        // so the fast path's transversion terms are exercised too.
        let transversion = Multivector::scalar(1.0) + (Multivector::from_vector(c * k) ^ Multivector::eo());
        let m = s.to_versor().unwrap() * transversion;
        let Ok(expected) = m.sandwich(&Multivector::up(x)).and_then(|y| y.down()) else {
            return Ok(());
        };
        prop_assume!(expected.length() < 1e4);
        let fast = m.transform_point(x).unwrap();
        prop_assert!((fast - expected).length() < 1e-9 * (1.0 + expected.length()), "{fast} vs {expected}");
    }

    #[test]
    fn rotor_of_two_vectors_turns_u_toward_v(angle in -6.0f64..6.0, u in point(), v in point()) {
        let r = Multivector::rotor(angle, &Multivector::from_vector(u), &Multivector::from_vector(v));
        prop_assume!(u.cross(v).length() > 1e-3);
        let r = r.unwrap();
        let axis = u.cross(v).normalize();
        let q = DQuat::from_axis_angle(axis, angle);
        prop_assert!((r.transform_point(u).unwrap() - q * u).length() < 1e-9 * (1.0 + u.length()));
    }
}

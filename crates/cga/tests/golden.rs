//! The kernel against golden values from an independent implementation, the Python
//! `clifford` library (see tools/golden/gen_cga_golden.py).

use cga::{Multivector, Similarity, BLADE_NAMES};
use glam::{DQuat, DVec3};
use serde::Deserialize;

#[derive(Deserialize)]
struct Golden {
    blades: Vec<String>,
    products: Vec<Products>,
    points: Vec<Point>,
    versors: Vec<Versor>,
    decompositions: Vec<Decomposition>,
}

#[derive(Deserialize)]
struct Products {
    a: Vec<f64>,
    b: Vec<f64>,
    geometric: Vec<f64>,
    outer: Vec<f64>,
    inner: Vec<f64>,
    left_contraction: Vec<f64>,
    reverse: Vec<f64>,
    grade_involution: Vec<f64>,
    conjugate: Vec<f64>,
    dual: Vec<f64>,
    norm_squared: f64,
    inverse: Vec<f64>,
}

#[derive(Deserialize)]
struct Point {
    x: [f64; 3],
    up: Vec<f64>,
}

#[derive(Deserialize)]
struct Versor {
    kind: String,
    t: Option<[f64; 3]>,
    s: Option<f64>,
    angle: Option<f64>,
    u: Option<[f64; 3]>,
    v: Option<[f64; 3]>,
    versor: Vec<f64>,
}

#[derive(Deserialize)]
struct Decomposition {
    translation: [f64; 3],
    rotation: [f64; 4],
    scale: f64,
    versor: Vec<f64>,
    point: [f64; 3],
    image: [f64; 3],
}

fn golden() -> Golden {
    let text = include_str!("data/golden.json");
    serde_json::from_str(text).expect("golden.json parses")
}

fn mv(c: &[f64]) -> Multivector {
    Multivector::from_coefficients(c.try_into().expect("32 coefficients"))
}

#[track_caller]
fn assert_close(label: &str, ours: Multivector, theirs: &[f64], tol: f64) {
    let theirs = mv(theirs);
    assert!(
        ours.is_close(&theirs, tol),
        "{label}: ours {ours} vs clifford {theirs}"
    );
}

#[test]
fn blade_order_matches_clifford() {
    let g = golden();
    for (ours, theirs) in BLADE_NAMES.iter().zip(&g.blades) {
        // clifford prints blades as "(1^e12)" and the scalar as "1".
        let theirs = theirs.trim_start_matches("(1^").trim_end_matches(')');
        assert_eq!(*ours, theirs);
    }
}

#[test]
fn products_and_involutions_match_clifford() {
    for (i, case) in golden().products.iter().enumerate() {
        let (a, b) = (mv(&case.a), mv(&case.b));
        assert_close(&format!("#{i} a*b"), a * b, &case.geometric, 1e-12);
        assert_close(&format!("#{i} a^b"), a ^ b, &case.outer, 1e-12);
        assert_close(&format!("#{i} a|b"), a | b, &case.inner, 1e-12);
        assert_close(
            &format!("#{i} a<<b"),
            a.left_contraction(&b),
            &case.left_contraction,
            1e-12,
        );
        assert_close(&format!("#{i} ~a"), a.reverse(), &case.reverse, 0.0);
        assert_close(
            &format!("#{i} involution"),
            a.grade_involution(),
            &case.grade_involution,
            0.0,
        );
        assert_close(
            &format!("#{i} conjugate"),
            a.conjugate(),
            &case.conjugate,
            0.0,
        );
        assert_close(&format!("#{i} dual"), a.dual(), &case.dual, 1e-15);
        assert!(
            (a.norm_squared() - case.norm_squared).abs() < 1e-10,
            "#{i} mag2"
        );
        let inv = a.inverse().expect("random multivectors are invertible");
        assert_close(&format!("#{i} inverse"), inv, &case.inverse, 1e-8);
    }
}

#[test]
fn points_match_clifford() {
    for case in golden().points {
        let x = DVec3::from(case.x);
        assert_close("up", Multivector::up(x), &case.up, 1e-14);
        assert!((mv(&case.up).down().unwrap() - x).length() < 1e-12);
    }
}

#[test]
fn versors_match_clifford() {
    for case in golden().versors {
        let ours = match case.kind.as_str() {
            "T" => Multivector::translator(DVec3::from(case.t.unwrap())),
            "D" => Multivector::dilator(case.s.unwrap()).unwrap(),
            "R" => Multivector::rotor(
                case.angle.unwrap(),
                &Multivector::from_vector(DVec3::from(case.u.unwrap())),
                &Multivector::from_vector(DVec3::from(case.v.unwrap())),
            )
            .unwrap(),
            other => panic!("unknown kind {other}"),
        };
        // clifford's rotor comes from its series exponential, good to about 1e-11.
        let tol = if case.kind == "R" { 1e-9 } else { 1e-12 };
        assert_close(&case.kind, ours, &case.versor, tol);
    }
}

#[test]
fn decompositions_match_clifford_and_scipy() {
    for (i, case) in golden().decompositions.iter().enumerate() {
        let m = mv(&case.versor);
        let d = Similarity::from_versor(&m).unwrap_or_else(|e| panic!("#{i}: {e}"));
        assert!(
            (d.translation - DVec3::from(case.translation)).length() < 1e-9,
            "#{i} t"
        );
        assert!((d.scale - case.scale).abs() < 1e-9, "#{i} s");
        let q = DQuat::from_array(case.rotation);
        assert!(
            d.rotation.dot(q).abs() > 1.0 - 1e-12,
            "#{i} q: {} vs {q}",
            d.rotation
        );
        let expected = Similarity {
            translation: DVec3::from(case.translation),
            rotation: q,
            scale: case.scale,
        }
        .to_versor()
        .unwrap();
        assert!(
            expected.is_close(&m, 1e-9) || expected.is_close(&-m, 1e-9),
            "#{i} T·R·D"
        );
        let image = m.transform_point(DVec3::from(case.point)).unwrap();
        assert!(
            (image - DVec3::from(case.image)).length() < 1e-9,
            "#{i} image"
        );
    }
}

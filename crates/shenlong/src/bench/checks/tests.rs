use super::*;
use cga::{Multivector, Similarity};
use serde_json::json;

fn room() -> Scene {
    let mut s = Scene::new("room");
    s.bounds = Some(Aabb::new(
        DVec3::new(-4.0, 0.0, -4.0),
        DVec3::new(4.0, 3.0, 4.0),
    ));
    for (name, size, at) in [
        ("table", [1.2, 0.75, 0.8], [0.0, 0.0, 0.0]),
        ("cup", [0.1, 0.1, 0.1], [0.2, 0.75, 0.1]),
        ("chair", [0.5, 0.9, 0.5], [2.0, 0.0, 0.0]),
        ("lamp", [0.3, 1.5, 0.3], [-2.0, 0.0, 2.0]),
        ("sofa", [2.0, 0.9, 0.9], [0.0, 0.0, -3.0]),
        ("pillow", [0.4, 0.3, 0.2], [0.5, 0.4, -3.0]),
    ] {
        s.push_box(name, size, at);
    }
    s.detect_supports();
    s
}

fn moved(s: &Scene, name: &str, m: Multivector) -> Scene {
    let mut after = s.clone();
    let i = after.find(name).unwrap();
    after.apply(i, &m, true).unwrap();
    after
}

fn check(value: serde_json::Value, before: &Scene, after: &Scene) -> Result<(), String> {
    Check::parse(&value)
        .unwrap()
        .evaluate(before, after, &HashMap::new())
        .map_err(|f| f.0)
}

fn t(x: f64, y: f64, z: f64) -> Multivector {
    Multivector::translator(DVec3::new(x, y, z))
}

#[test]
fn moved_and_direction() {
    let s = room();
    let a = moved(&s, "chair", t(1.0, 0.0, 0.0));
    assert!(check(
        json!({"check": "moved", "object": "chair", "delta": [1, 0, 0]}),
        &s,
        &a
    )
    .is_ok());
    assert!(check(
        json!({"check": "moved", "object": "chair", "delta": [1, null, null]}),
        &s,
        &a
    )
    .is_ok());
    let e = check(
        json!({"check": "moved", "object": "chair", "delta": [2, 0, 0]}),
        &s,
        &a,
    )
    .unwrap_err();
    assert!(
        e.starts_with("'chair' moved by [1.000, 0.000, 0.000]"),
        "{e}"
    );
    assert!(check(
        json!({"check": "direction", "object": "chair", "axis": "+x", "min": 0.5}),
        &s,
        &a
    )
    .is_ok());
    assert!(check(
        json!({"check": "direction", "object": "chair", "axis": "-x"}),
        &s,
        &a
    )
    .is_err());
    let diagonal = moved(&s, "chair", t(1.0, 0.0, 1.0));
    assert!(check(
        json!({"check": "direction", "object": "chair", "axis": "+x"}),
        &s,
        &diagonal
    )
    .unwrap_err()
    .contains("also moved"));
}

#[test]
fn rotated_and_scaled_and_faces() {
    let s = room();
    let r = Multivector::rotor(
        std::f64::consts::FRAC_PI_2,
        &Multivector::e3(),
        &Multivector::e1(),
    )
    .unwrap();
    let a = moved(&s, "chair", r);
    assert!(check(
        json!({"check": "rotated", "object": "chair", "axis": "y", "degrees": 90}),
        &s,
        &a
    )
    .is_ok());
    assert!(check(
        json!({"check": "rotated", "object": "chair", "degrees": -90}),
        &s,
        &a
    )
    .is_err());
    assert!(check(
        json!({"check": "rotated", "object": "chair", "degrees": -90, "either_sign": true}),
        &s,
        &a
    )
    .is_ok());
    let x = moved(
        &s,
        "chair",
        Multivector::rotor(
            std::f64::consts::FRAC_PI_2,
            &Multivector::e2(),
            &Multivector::e3(),
        )
        .unwrap(),
    );
    assert!(
        check(
            json!({"check": "rotated", "object": "chair", "axis": "y", "degrees": 90}),
            &s,
            &x
        )
        .is_err(),
        "a turn about x is not about y"
    );
    let big = moved(&s, "lamp", Multivector::dilator(2.0).unwrap());
    assert!(check(
        json!({"check": "scaled", "object": "lamp", "factor": 2}),
        &s,
        &big
    )
    .is_ok());
    assert!(check(
        json!({"check": "scaled", "object": "lamp", "factor": 3}),
        &s,
        &big
    )
    .is_err());
    // The chair at x = 2 faces +z; turned −90° about y it faces −x, toward the table.
    let turned = moved(
        &s,
        "chair",
        Multivector::rotor(
            -std::f64::consts::FRAC_PI_2,
            &Multivector::e3(),
            &Multivector::e1(),
        )
        .unwrap(),
    );
    assert!(check(
        json!({"check": "faces", "object": "chair", "target": "table"}),
        &s,
        &turned
    )
    .is_ok());
    assert!(check(
        json!({"check": "faces", "object": "chair", "target": "table"}),
        &s,
        &s
    )
    .is_err());
}

#[test]
fn on_top_above_below() {
    let s = room();
    let on = moved(&s, "lamp", t(2.0, 0.75, -2.0));
    assert!(check(
        json!({"check": "on_top", "object": "lamp", "support": "table"}),
        &s,
        &on
    )
    .is_ok());
    assert!(check(
        json!({"check": "above", "object": "lamp", "other": "table"}),
        &s,
        &on
    )
    .is_ok());
    assert!(check(
        json!({"check": "below", "object": "table", "other": "lamp"}),
        &s,
        &on
    )
    .is_ok());
    let beside = moved(&s, "lamp", t(3.0, 0.75, -2.0));
    assert!(check(
        json!({"check": "on_top", "object": "lamp", "support": "table"}),
        &s,
        &beside
    )
    .unwrap_err()
    .contains("is not on top of"));
    assert!(check(
        json!({"check": "above", "object": "lamp", "other": "table"}),
        &s,
        &s
    )
    .is_err());
}

#[test]
fn next_to_side_between_aligned_distance_at() {
    let s = room();
    // The chair right next to the table's right side (table x ≤ 0.6, chair half-width 0.25).
    let next = moved(&s, "chair", t(0.6 + 0.05 + 0.25 - 2.0, 0.0, 0.0));
    assert!(check(
        json!({"check": "next_to", "object": "chair", "other": "table"}),
        &s,
        &next
    )
    .is_ok());
    assert!(check(
        json!({"check": "side", "object": "chair", "other": "table", "side": "right"}),
        &s,
        &next
    )
    .is_ok());
    assert!(check(
        json!({"check": "side", "object": "chair", "other": "table", "side": "left"}),
        &s,
        &next
    )
    .is_err());
    assert!(check(
        json!({"check": "next_to", "object": "chair", "other": "table"}),
        &s,
        &s
    )
    .unwrap_err()
    .contains("gap 1.150"));
    assert!(check(
        json!({"check": "aligned", "object": "chair", "other": "table", "axis": "z"}),
        &s,
        &next
    )
    .is_ok());
    assert!(check(
        json!({"check": "aligned", "object": "lamp", "other": "table", "axis": "z"}),
        &s,
        &s
    )
    .is_err());
    let mid = moved(&s, "lamp", t(3.0, 0.0, -2.0));
    assert!(check(
        json!({"check": "between", "object": "lamp", "a": "table", "b": "chair"}),
        &s,
        &mid
    )
    .is_ok());
    assert!(check(
        json!({"check": "between", "object": "lamp", "a": "table", "b": "chair"}),
        &s,
        &s
    )
    .is_err());
    assert!(check(
        json!({"check": "distance", "object": "chair", "other": "table", "max": 1.0}),
        &s,
        &next
    )
    .is_ok());
    assert!(check(
        json!({"check": "distance", "object": "chair", "other": "table", "max": 1.0}),
        &s,
        &s
    )
    .is_err());
    assert!(check(
        json!({"check": "at", "object": "chair", "position": [2, 0, null]}),
        &s,
        &s
    )
    .is_ok());
    assert!(check(
        json!({"check": "at", "object": "chair", "position": [0, 0, 0]}),
        &s,
        &s
    )
    .is_err());
}

#[test]
fn unchanged_collisions_and_bounds() {
    let s = room();
    let a = moved(&s, "table", t(0.0, 0.0, 1.0));
    // "others": everything but the bound objects and what they carry (the cup).
    let bound: HashMap<String, usize> = [("A".to_string(), s.find("table").unwrap())].into();
    let others = Check::parse(&json!({"check": "unchanged", "objects": "others"})).unwrap();
    assert!(others.evaluate(&s, &a, &bound).is_ok());
    assert!(others
        .evaluate(&s, &a, &HashMap::new())
        .unwrap_err()
        .0
        .contains("'table' changed"));
    assert!(check(json!({"check": "unchanged", "objects": ["lamp"]}), &s, &a).is_ok());
    assert!(check(json!({"check": "no_collision"}), &s, &a).is_ok());
    let into = moved(&s, "chair", t(-1.8, 0.0, 0.0));
    assert!(check(json!({"check": "no_collision"}), &s, &into)
        .unwrap_err()
        .contains("'chair' collides with 'table'"));
    // The pillow sits inside the sofa's box already: moving it within is no collision.
    let pillow = moved(&s, "pillow", t(-0.5, 0.0, 0.0));
    assert!(check(json!({"check": "no_collision"}), &s, &pillow).is_ok());
    let out = moved(&s, "lamp", t(-3.0, 0.0, 0.0));
    assert!(check(json!({"check": "inside_bounds"}), &s, &out)
        .unwrap_err()
        .contains("out of the room"));
    assert!(check(json!({"check": "inside_bounds"}), &s, &a).is_ok());
    let _ = Similarity::IDENTITY;
}

#[test]
fn parsing_is_strict() {
    let error = |v: serde_json::Value| Check::parse(&v).unwrap_err().to_string();
    let e = error(json!({"check": "teleported", "object": "A"}));
    assert!(e.contains("teleported") && e.contains("moved"), "{e}");
    let e = error(json!({"check": "moved", "object": "A", "delta": [1, 0, 0], "tolerance": 1}));
    assert!(
        e.contains("unknown field `tolerance`") && e.contains("`tol`"),
        "{e}"
    );
    let e = error(json!({"check": "direction", "object": "A", "axis": "up"}));
    assert!(e.contains("unknown axis 'up'"), "{e}");
    let e = error(json!({"check": "side", "object": "A", "other": "B", "side": "above"}));
    assert!(e.contains("above") && e.contains("behind"), "{e}");
    assert!(Check::parse(&json!({"object": "A"})).is_err());
    assert!(Check::parse(&json!({"check": "no_collision", "object": "A"})).is_err());
    let e = error(json!({"check": "scaled", "object": "A"}));
    assert!(e.contains("missing field `factor`"), "{e}");
    let e = error(json!({"check": "unchanged", "objects": "everything"}));
    assert!(e.contains("did not match"), "{e}");
}

#[test]
fn parsing_fills_in_the_defaults() {
    assert_eq!(
        Check::parse(&json!({"check": "rotated", "object": "A"})).unwrap(),
        Check::Rotated {
            object: "A".into(),
            axis: 1,
            degrees: 90.0,
            either_sign: false,
            tol: 5.0
        }
    );
    assert_eq!(
        Check::parse(
            &json!({"check": "side", "object": "A", "other": "B", "side": "back", "max_gap": null})
        )
        .unwrap(),
        Check::Side {
            object: "A".into(),
            other: "B".into(),
            side: (2, -1.0),
            max_gap: 0.5
        }
    );
    assert_eq!(
        Check::parse(&json!({"check": "at", "object": "A", "position": [1, null, 2]})).unwrap(),
        Check::At {
            object: "A".into(),
            position: [Some(1.0), None, Some(2.0)],
            tol: 0.05
        }
    );
    assert_eq!(
        Check::parse(&json!({"check": "unchanged", "objects": ["A", "B"]})).unwrap(),
        Check::Unchanged {
            objects: Some(vec!["A".into(), "B".into()])
        }
    );
    assert_eq!(
        Check::parse(&json!({"check": "inside_bounds"})).unwrap(),
        Check::InsideBounds
    );
}

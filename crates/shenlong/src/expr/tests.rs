//! Tests of the language as a whole: evaluation, errors, the paper's expressions, golden
//! values from `clifford`, and printing.

use super::*;
use glam::{DQuat, DVec3};
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};

fn two_objects() -> Bindings {
    let mut b = Bindings::new();
    // A bottle standing on the floor and a table whose top is at y = 0.9.
    b.bind(
        "X1",
        ObjectBox {
            min: DVec3::new(-0.05, 0.0, -0.05),
            max: DVec3::new(0.05, 0.3, 0.05),
            front: DVec3::Z,
        },
    );
    b.bind(
        "X2",
        ObjectBox {
            min: DVec3::new(1.2, 0.0, -0.4),
            max: DVec3::new(2.8, 0.9, 0.4),
            front: DVec3::NEG_X,
        },
    );
    b
}

fn eval(s: &str) -> Multivector {
    evaluate(s, &two_objects()).unwrap_or_else(|e| panic!("{s}: {e}"))
}

fn transformation(s: &str) -> Similarity {
    evaluate_transformation(s, &two_objects())
        .unwrap_or_else(|e| panic!("{s}: {e}"))
        .similarity
}

fn error(s: &str) -> String {
    match evaluate_transformation(s, &two_objects()) {
        Ok(t) => panic!("{s} evaluated to {:?}", t.similarity),
        Err(e) => e.to_string(),
    }
}

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).length() < 1e-9
}

#[test]
fn numbers_and_arithmetic() {
    assert_eq!(eval("1 + 2 * 3"), Multivector::scalar(7.0));
    assert_eq!(eval("(1 + 2) * 3"), Multivector::scalar(9.0));
    assert_eq!(eval("7 - 2 - 1"), Multivector::scalar(4.0));
    assert_eq!(eval("8 / 4 / 2"), Multivector::scalar(1.0));
    assert_eq!(eval("-2 ** 2"), Multivector::scalar(-4.0));
    assert_eq!(eval("2 ** 3 ** 2"), Multivector::scalar(512.0));
    assert_eq!(eval("2 ** -1"), Multivector::scalar(0.5));
    assert_eq!(eval("4 ** 0.5"), Multivector::scalar(2.0));
    assert_eq!(eval("+3"), Multivector::scalar(3.0));
    assert_eq!(eval("1.5e1"), Multivector::scalar(15.0));
}

#[test]
fn every_operator_on_blades() {
    let e = |n: &str| Multivector::blade_by_name(n).unwrap();
    assert_eq!(eval("e1 * e2"), e("e12"));
    assert_eq!(eval("e2 * e1"), -e("e12"));
    assert_eq!(eval("e1 ^ e1"), Multivector::ZERO);
    assert_eq!(eval("e1 ^ e2 ^ e3"), e("e123"));
    assert_eq!(eval("e1 | e1"), Multivector::ONE);
    assert_eq!(eval("e1 | e12"), e("e2"));
    assert_eq!(eval("2 | e1"), Multivector::ZERO);
    assert_eq!(eval("~e12"), -e("e12"));
    assert_eq!(eval("e12 ** 2"), -Multivector::ONE);
    assert!(eval("e12 ** -1").is_close(&-e("e12"), 1e-15));
    assert_eq!(eval("e1 / 2"), e("e1") * 0.5);
    assert_eq!(eval("e31"), -e("e13"));
    assert_eq!(eval("eo"), Multivector::eo());
    assert_eq!(eval("e0"), Multivector::eo());
    assert_eq!(eval("no"), Multivector::eo());
    assert_eq!(eval("ninf"), Multivector::einf());
    assert_eq!(eval("einf | eo"), -Multivector::ONE);
    assert_eq!(eval("e4 ** 2 + e5 ** 2"), Multivector::ZERO);
}

#[test]
fn precedence_matches_python_clifford() {
    // `|` binds loosest: (e1 + e2) | e1 = 1, not e1 + (e2 | e1).
    assert_eq!(eval("e1 + e2 | e1"), Multivector::ONE);
    // `^` below `+`: e1 ^ (e2 + e3).
    assert_eq!(eval("e1 ^ e2 + e3"), eval("e12 + e13"));
    // `*` above `+`.
    assert_eq!(eval("e1 + e2 * e3"), eval("e1 + e23"));
    // `|` below `^`: (e1 ^ e2) | e2 = e1 … and the ^ applies first.
    assert_eq!(eval("e1 ^ e2 | e2"), eval("e1"));
    // Unary minus below `**`.
    assert_eq!(eval("-e12 ** 2"), Multivector::ONE);
}

#[test]
fn names_constants_functions() {
    let s = |x: f64| Multivector::scalar(x);
    assert_eq!(eval("pi"), s(PI));
    assert_eq!(eval("np.pi"), s(PI));
    assert_eq!(eval("math.pi"), s(PI));
    assert!(eval("sin(pi / 2)").is_close(&s(1.0), 1e-15));
    assert!(eval("np.cos(0)").is_close(&s(1.0), 1e-15));
    assert!(eval("math.tan(pi / 4)").is_close(&s(1.0), 1e-15));
    assert!(eval("asin(1)").is_close(&s(FRAC_PI_2), 1e-15));
    assert!(eval("acos(1)").is_close(&s(0.0), 1e-15));
    assert!(eval("atan(1) * 4").is_close(&s(PI), 1e-15));
    assert!(eval("atan2(1, 0)").is_close(&s(FRAC_PI_2), 1e-15));
    assert_eq!(eval("sqrt(16)"), s(4.0));
    assert_eq!(eval("abs(-3)"), s(3.0));
    assert_eq!(eval("abs(3 * e1 + 4 * e2)"), s(5.0));
    assert_eq!(eval("min(3, 1, 2)"), s(1.0));
    assert_eq!(eval("max(3, 1, 2)"), s(3.0));
    assert!(eval("radians(180)").is_close(&s(PI), 1e-15));
    assert!(eval("np.degrees(np.pi)").is_close(&s(180.0), 1e-12));
}

#[test]
fn object_attributes() {
    assert_eq!(eval("X2.max | e2"), Multivector::scalar(0.9));
    assert_eq!(
        eval("X1.min"),
        Multivector::from_vector(DVec3::new(-0.05, 0.0, -0.05))
    );
    assert!(
        eval("X2.center").is_close(&Multivector::from_vector(DVec3::new(2.0, 0.45, 0.0)), 1e-15)
    );
    assert!(eval("X2.size").is_close(&Multivector::from_vector(DVec3::new(1.6, 0.9, 0.8)), 1e-15));
}

#[test]
fn constructors() {
    let t = transformation("T(2 * e1 - e3)");
    assert!(close(t.translation, DVec3::new(2.0, 0.0, -1.0)));
    assert!(close(
        transformation("T(1, 2, 3)").translation,
        DVec3::new(1.0, 2.0, 3.0)
    ));
    let r = transformation("R(np.pi/2, e3, e1)");
    assert!(r
        .rotation
        .abs_diff_eq(DQuat::from_rotation_y(FRAC_PI_2), 1e-12));
    let r = transformation("R(np.pi/2, e1, e2)");
    assert!(r
        .rotation
        .abs_diff_eq(DQuat::from_rotation_z(FRAC_PI_2), 1e-12));
    let d = transformation("D(2)");
    assert!((d.scale - 2.0).abs() < 1e-12);
    let p = eval("down(T(e1) * up(e2) * ~T(e1))");
    assert!(p.is_close(&eval("e1 + e2"), 1e-12));
    assert!(eval("up(0 * e1)").is_close(&Multivector::eo(), 1e-15));
}

#[test]
fn the_papers_expressions_mean_what_they_say() {
    // Move left one unit.
    assert!(close(transformation("T(-1 * e1)").translation, -DVec3::X));
    // A quarter turn about the vertical (from +Z toward +X is +90° about +Y).
    let r = transformation("R(np.pi/2, e3, e1)");
    assert!(close(r.rotation * DVec3::Z, DVec3::X));
    // Put X1 on top of X2: lift X1's bottom to X2's top.
    let on_top = transformation("T(((X2.max | e2) - (X1.min | e2)) * e2)");
    assert!(close(on_top.translation, DVec3::new(0.0, 0.9, 0.0)));
    // Composition: translators commute, so two moves add up.
    let both = transformation("T(e1) * T(2 * e3)");
    assert!(close(both.translation, DVec3::new(1.0, 0.0, 2.0)));
    // Next to X2 on its left: X1's max x to X2's min x.
    let next = transformation("T(((X2.min | e1) - (X1.max | e1)) * e1)");
    assert!(close(next.translation, DVec3::new(1.15, 0.0, 0.0)));
    // A list applies first to last: rotate, then move.
    let listed = compose(&["R(pi/2, e3, e1)", "T(e1)"], &two_objects()).unwrap();
    let m = listed.versor;
    assert!(close(
        m.transform_point(DVec3::Z).unwrap(),
        DVec3::new(2.0, 0.0, 0.0)
    ));
    assert!(close(listed.similarity.translation, DVec3::X));
}

#[test]
fn a_rotor_by_plane_and_angle_is_the_rotor_from_u_to_v() {
    for (short, long) in [
        ("R(e12, pi/2)", "R(pi/2, e1, e2)"),
        ("R(pi/3, e31)", "R(pi/3, e3, e1)"),
        ("R(e13, 0.7)", "R(0.7, e1, e3)"),
        ("R(2 * e23, -1.2)", "R(-1.2, e2, e3)"),
        ("T(e1) * R(e12, pi/2)", "T(e1) * R(pi/2, e1, e2)"),
    ] {
        let (a, b) = (transformation(short), transformation(long));
        assert!(close(a.translation, b.translation), "{short}");
        assert!(
            a.rotation.dot(b.rotation).abs() > 1.0 - 1e-12,
            "{short}: {:?} vs {:?}",
            a.rotation,
            b.rotation
        );
    }
}

#[test]
fn error_messages_say_what_and_where() {
    assert_eq!(
        error("T(e1 * 2"),
        "expected ')' but found the end of the expression at column 9"
    );
    assert_eq!(
        error("T(X9.max)"),
        "unknown name 'X9' (bound: X1, X2) at column 3"
    );
    assert_eq!(error("R(pi)"), "R needs three arguments: angle, u, v (got 1); for example R(pi/2, e3, e1) turns +90° about +Y at column 1");
    assert!(error("R(pi, e1)")
        .starts_with("the plane of R must be a Euclidean bivector such as e12, e31 or e23"));
    assert!(
        error("R(pi, e1)").ends_with("at column 7"),
        "{}",
        error("R(pi, e1)")
    );
    assert!(error("R(e12, e3)").starts_with("R with two arguments takes a plane and an angle"));
    assert_eq!(
        error("X1.max - X1.min"),
        "result is a vector, not a transformation: wrap a translation vector in T(...)"
    );
    assert_eq!(error("D(-1)"), "D(-1): scale must be > 0 at column 1");
    assert_eq!(error("T(e1 / 0)"), "division by zero at column 8");
    assert_eq!(error("T(e1 / (0 * 1))"), "division by zero at column 8");
    assert!(error("R(pi, e1, 2 * e1)").starts_with("u and v span no plane"));
    assert!(error("T(e1 / e2)").starts_with("division by the multivector 1 e2"));
    assert_eq!(
        error("T(2)"),
        "T needs a vector, not the number 2: write a direction, as in T(2 * e1) at column 3"
    );
    assert!(error("T(e4)").starts_with("T needs a Euclidean vector"));
    assert!(error("X1").starts_with("X1 is an object, not a value: use X1.min"));
    assert!(error("T(X1.bottom)").starts_with("X1 has no attribute 'bottom'"));
    assert!(error("T").starts_with("T is a function: call it"));
    assert!(error("np").starts_with("'np' is a module"));
    assert_eq!(
        error("Tt(e1)"),
        "unknown name 'Tt' — did you mean 'T'? at column 1"
    );
    assert!(error("T(e6)").starts_with("unknown blade 'e6'"));
    assert!(error("T(e11)").starts_with("unknown blade 'e11'"));
    assert!(error("sqrt(-1)").starts_with("sqrt(-1) is undefined: it needs a number ≥ 0"));
    assert!(error("acos(2)").contains("in [-1, 1]"));
    assert!(error("sin(e1)").starts_with("sin needs a number here"));
    assert!(error("e1 ** 0.5").starts_with("a multivector can only be raised to a whole number"));
    assert!(error("e1 ** 100").starts_with("a multivector can only be raised"));
    assert!(error("0").starts_with("result is zero"));
    assert!(error("e1 + e12").starts_with("result is not a transformation of the form T·R·D"));
    assert!(error("1 + eo * e1").starts_with("result is not a transformation of the form T·R·D"));
    assert!(error("R(e1, e1, e2)").starts_with("the angle of R must be a number"));
    assert!(error("R(1, e12, e2)").starts_with("u of R(angle, u, v) must be a vector"));
    assert!(error("min(1)").starts_with("min needs at least two numbers"));
    assert!(error("math.e1").starts_with("'math' has no name 'e1'"));
    assert!(error("10 ** 400").contains("not a finite number"));
    assert!(error("T(1e300 * 1e300 * e1)").contains("not a finite number"));
}

#[test]
fn hostile_input_fails_fast_without_running_anything() {
    assert!(error("__import__('os')").starts_with("unexpected character '''"));
    assert!(error("__import__").starts_with("unknown name '__import__'"));
    assert!(error("exec").starts_with("unknown name 'exec'"));
    assert!(error(&"T(".repeat(5000)).contains("characters long"));
    assert!(error(&"T(".repeat(1000)).contains("nests more than 64 levels"));
    assert!(error(&"x".repeat(10 * 1024 * 1024)).contains("characters long"));
    assert!(error(&vec!["e1"; 1100].join("+")).contains("too large"));
    assert!(error("(e1 + e2) ** 64 ** 64").contains("whole number"));
    let tight = Limits {
        max_steps: 5,
        ..Limits::default()
    };
    let e = evaluate_with("T(e1 + e2 + e3)", &two_objects(), &tight).unwrap_err();
    assert!(e.message.contains("more than 5 steps"), "{e}");
}

#[test]
fn compose_names_the_failing_item() {
    let e = compose(&["T(e1)", "D(0)"], &two_objects()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "item 2 of the list: D(0): scale must be > 0 at column 1"
    );
    assert!(compose::<&str>(&[], &two_objects()).is_err());
}

#[test]
fn golden_products_through_the_language() {
    #[derive(serde::Deserialize)]
    struct Golden {
        products: Vec<Case>,
    }
    #[derive(serde::Deserialize)]
    struct Case {
        a: Vec<f64>,
        b: Vec<f64>,
        geometric: Vec<f64>,
        outer: Vec<f64>,
        inner: Vec<f64>,
        reverse: Vec<f64>,
    }
    let text = include_str!("../../../cga/tests/data/golden.json");
    let golden: Golden = serde_json::from_str(text).unwrap();
    let literal = |c: &[f64]| {
        let terms: Vec<String> = c
            .iter()
            .zip(cga::BLADE_NAMES)
            .map(|(x, blade)| {
                if blade == "1" {
                    format!("({x:?})")
                } else {
                    format!("({x:?}) * {blade}")
                }
            })
            .collect();
        format!("({})", terms.join(" + "))
    };
    let mv = |c: &[f64]| Multivector::from_coefficients(c.try_into().unwrap());
    for case in golden.products.iter().take(10) {
        let (a, b) = (literal(&case.a), literal(&case.b));
        let b_ = Bindings::new();
        let check = |expr: String, expected: &[f64]| {
            let ours = evaluate(&expr, &b_).unwrap();
            assert!(ours.is_close(&mv(expected), 1e-12), "{expr}");
        };
        check(format!("{a} * {b}"), &case.geometric);
        check(format!("{a} ^ {b}"), &case.outer);
        check(format!("{a} | {b}"), &case.inner);
        check(format!("~{a}"), &case.reverse);
    }
}

fn arbitrary_expr() -> impl Strategy<Value = Expr> {
    let leaf = prop_oneof![
        (0.0f64..1e6).prop_map(ExprKind::Number),
        prop::sample::select(vec!["e1", "e23", "X1", "pi", "eo", "einf"])
            .prop_map(|n| ExprKind::Name(n.to_string())),
    ]
    .prop_map(|kind| Expr { kind, span: 0..0 });
    leaf.prop_recursive(6, 64, 4, |inner| {
        let boxed = |e: Expr| Box::new(e);
        prop_oneof![
            (
                prop::sample::select(vec![
                    BinaryOp::Inner,
                    BinaryOp::Outer,
                    BinaryOp::Add,
                    BinaryOp::Sub,
                    BinaryOp::Mul,
                    BinaryOp::Div,
                    BinaryOp::Pow
                ]),
                inner.clone(),
                inner.clone()
            )
                .prop_map(move |(op, a, b)| ExprKind::Binary(op, boxed(a), boxed(b))),
            (
                prop::sample::select(vec![UnaryOp::Neg, UnaryOp::Plus, UnaryOp::Reverse]),
                inner.clone()
            )
                .prop_map(move |(op, a)| ExprKind::Unary(op, boxed(a))),
            (
                prop::sample::select(vec!["T", "R", "sin", "np.cos"]),
                prop::collection::vec(inner.clone(), 0..4)
            )
                .prop_map(|(f, args)| {
                    let callee = match f.split_once('.') {
                        Some((m, n)) => Expr {
                            kind: ExprKind::Attribute(
                                Box::new(Expr {
                                    kind: ExprKind::Name(m.into()),
                                    span: 0..0,
                                }),
                                n.into(),
                            ),
                            span: 0..0,
                        },
                        None => Expr {
                            kind: ExprKind::Name(f.into()),
                            span: 0..0,
                        },
                    };
                    ExprKind::Call(Box::new(callee), args)
                }),
            (
                inner,
                prop::sample::select(vec!["min", "max", "center", "size"])
            )
                .prop_map(|(base, attr)| ExprKind::Attribute(Box::new(base), attr.into())),
        ]
        .prop_map(|kind| Expr { kind, span: 0..0 })
    })
}

proptest! {
    #[test]
    fn printing_then_parsing_gives_the_same_tree(expr in arbitrary_expr()) {
        let text = expr.to_string();
        let parsed = parse(&text).map_err(|e| TestCaseError::fail(format!("{text}: {e}")))?;
        prop_assert_eq!(parsed, expr);
    }

    #[test]
    fn evaluation_never_panics(text in "[-+*/^|~(),. 0-9eXnpi1-5a-zT]{0,60}") {
        let _ = evaluate_transformation(&text, &two_objects());
    }
}

#[test]
fn documented_examples_evaluate_to_what_they_say() {
    let doc = include_str!("../../../../docs/expressions.md");
    let section = doc
        .split("## Examples")
        .nth(1)
        .and_then(|s| s.split("## Errors").next())
        .expect("docs/expressions.md has an Examples section");
    let mut checked = 0;
    for row in section
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| instruction"))
    {
        let cells: Vec<&str> = row.split(" | ").collect();
        let expr = cells[1]
            .trim()
            .trim_end_matches('|')
            .trim()
            .trim_matches('`')
            .replace("\\|", "|");
        let result = if expr.starts_with('[') {
            let items: Vec<String> = serde_json::from_str(&expr).unwrap();
            compose(&items, &two_objects())
        } else {
            evaluate_transformation(&expr, &two_objects())
        };
        let t = result.unwrap_or_else(|e| panic!("{expr}: {e}"));
        if cells[0].contains("on top of") {
            // The bottle lands centred on the table's top.
            let bottom_centre = t.similarity.transform_point(DVec3::ZERO);
            assert!(
                close(bottom_centre, DVec3::new(2.0, 0.9, 0.0)),
                "{bottom_centre}"
            );
        }
        checked += 1;
    }
    assert!(checked >= 8, "only {checked} documented examples found");
}

#[test]
fn the_euclidean_dialect() {
    let e = |s: &str| {
        evaluate_in(s, &two_objects(), Dialect::Euclidean)
            .unwrap_or_else(|err| panic!("{s}: {err}"))
    };
    let t = to_transformation(&e("translation(2, 0, -1)"))
        .unwrap()
        .similarity;
    assert!(close(t.translation, DVec3::new(2.0, 0.0, -1.0)));
    let r = to_transformation(&e("rotation_y(np.pi / 2)"))
        .unwrap()
        .similarity;
    assert!(
        close(r.rotation * DVec3::Z, DVec3::X),
        "+90° about y takes +z to +x"
    );
    let m = e("translation(0, 0, -1) @ rotation_y(np.pi)");
    assert!(close(
        m.transform_point(DVec3::Z).unwrap(),
        DVec3::new(0.0, 0.0, -2.0)
    ));
    let on_top = to_transformation(&e("translation(X2.center[0] - X1.center[0], X2.max[1] - X1.min[1], X2.center[2] - X1.center[2])")).unwrap();
    assert!(close(
        on_top.similarity.translation,
        DVec3::new(2.0, 0.9, 0.0)
    ));
    assert!(
        to_transformation(&e("scaling(2) @ identity()"))
            .unwrap()
            .similarity
            .scale
            - 2.0
            < 1e-12
    );
    let err = |s: &str| {
        evaluate_in(s, &two_objects(), Dialect::Euclidean)
            .unwrap_err()
            .to_string()
    };
    assert!(
        err("T(e1)").starts_with("'T' is not available here"),
        "{}",
        err("T(e1)")
    );
    assert!(err("X1.min[3]").starts_with("an index must be 0, 1 or 2"));
    assert!(err("scaling(-1)").starts_with("scaling(-1): scale must be > 0"));
    // And the CGA dialect refuses the Euclidean constructs, saying what to write instead.
    assert!(error("T(X1.max[1] * e2)").starts_with("indexing is not part of the CGA language"));
    assert!(error("T(e1) @ T(e2)").starts_with("'@' is not part of the CGA language"));
    assert!(error("translation(1, 0, 0)").starts_with("unknown name 'translation'"));
}

#[test]
fn front_is_the_world_direction_an_object_faces() {
    let b = two_objects();
    let v = crate::expr::evaluate("X2.front", &b).unwrap();
    assert!((v.coefficients()[1] + 1.0).abs() < 1e-12, "{v:?}");
    // Turning X1 to face the way X2 faces: from +Z to −X is −90° about +Y.
    let t = crate::expr::evaluate_transformation(
        "R(atan2(X2.front | e1, X2.front | e3) - atan2(X1.front | e1, X1.front | e3), e3, e1)",
        &b,
    )
    .unwrap();
    let turned = t.similarity.rotation * glam::DVec3::Z;
    assert!((turned - glam::DVec3::NEG_X).length() < 1e-12, "{turned}");
}

#[test]
fn errors_say_their_kind() {
    let kind = |source: &str| {
        evaluate_transformation(source, &two_objects())
            .err()
            .map(|e| e.kind)
    };
    assert_eq!(kind("T(1 * e1"), Some(ExprErrorKind::Syntax));
    assert_eq!(kind("T(1 $ e1)"), Some(ExprErrorKind::Syntax));
    assert_eq!(kind("T(1 * e9)"), Some(ExprErrorKind::Meaning));
    assert_eq!(kind("T(1 / 0 * e1)"), Some(ExprErrorKind::Meaning));
    assert_eq!(kind("e1"), Some(ExprErrorKind::NotATransformation));
    assert_eq!(
        kind("0 * T(1 * e1)"),
        Some(ExprErrorKind::NotATransformation)
    );
    let long = format!("T({} e1)", "1 + ".repeat(100_000));
    assert_eq!(kind(&long), Some(ExprErrorKind::Limit));
    let reply = reply::extract_cga_reply("I would move it left.").unwrap_err();
    assert_eq!(reply.kind, ExprErrorKind::Reply);
    // The context a list or a reply adds keeps the kind and the column.
    let e = evaluate_transformation("T(1 * e9)", &two_objects()).unwrap_err();
    let within = e.clone().within("X1");
    assert_eq!((within.kind, within.column), (e.kind, e.column));
    assert!(within.message.starts_with("X1: "), "{}", within.message);
}

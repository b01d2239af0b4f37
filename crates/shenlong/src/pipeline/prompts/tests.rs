use super::*;
use crate::pipeline::template;

fn workshop() -> Scene {
    crate::examples::build("workshop").unwrap()
}

#[test]
fn prompts_are_snapshotted() {
    let scene = workshop();
    let t = template("put the 'orange bottle' on top of the 'tool table'", &scene).unwrap();
    for system in System::ALL {
        let messages = system.messages(&t, &scene);
        let text = messages
            .iter()
            .map(|m| format!("[{}]\n{}", m.role, m.content))
            .collect::<Vec<_>>()
            .join("\n\n");
        insta::assert_snapshot!(format!("prompt_{}", system.name()), text);
    }
}

#[test]
fn versions_and_names() {
    assert_eq!(System::Cga.version(), "cga-4");
    assert_eq!(System::Euclidean.version(), "euclidean-3");
    assert_eq!(System::Omniverse.version(), "omniverse-3");
    assert_eq!(System::from_name("CGA"), Some(System::Cga));
    assert!(!System::Cga.prompt().contains("version:"));
}

#[test]
fn the_cga_user_message_is_only_the_templated_query() {
    let scene = workshop();
    let t = template("put the 'orange bottle' on top of the 'tool table'", &scene).unwrap();
    let messages = System::Cga.messages(&t, &scene);
    assert_eq!(messages[1].content, "Instruction: put X1 on top of X2");
    assert!(!messages.iter().any(|m| m.content.contains("orange")));
}

#[test]
fn all_three_systems_put_the_bottle_on_the_table() {
    let scene = workshop();
    let t = template("put the 'orange bottle' on top of the 'tool table'", &scene).unwrap();
    let replies = [
        (System::Cga, r#"{"X1": "T(((X2.max | e2) - (X1.min | e2)) * e2 + ((X2.center - X1.center) | e1) * e1 + ((X2.center - X1.center) | e3) * e3)"}"#.to_string()),
        (System::Euclidean, r#"{"X1": "translation(X2.center[0] - X1.center[0], X2.max[1] - X1.min[1], X2.center[2] - X1.center[2])"}"#.to_string()),
        (System::Omniverse, r#"{"X1": {"position": [0, 1.025, 0], "rotation": [0, 0, 0]}}"#.to_string()),
    ];
    for (system, reply) in replies {
        let answers = system
            .parse_reply(&reply, &t, &scene)
            .unwrap_or_else(|e| panic!("{}: {e}", system.name()));
        assert_eq!(answers.len(), 1);
        let mut s = scene.clone();
        s.apply(answers[0].object, &answers[0].transformation.versor, true)
            .unwrap();
        let bottle = s.objects[answers[0].object].world_aabb();
        assert!(
            (bottle.min.y - 0.9).abs() < 1e-9,
            "{}: {bottle:?}",
            system.name()
        );
        assert!(
            (bottle.center().x).abs() < 1e-9 && bottle.center().z.abs() < 1e-9,
            "{}: {bottle:?}",
            system.name()
        );
    }
}

#[test]
fn omniverse_turns_about_the_pivot_and_keeps_the_centre() {
    let scene = workshop();
    let t = template("turn the 'stool' a quarter", &scene).unwrap();
    let reply = r#"{"X1": {"position": [0, 0.35, 1], "rotation": [0, 90, 0]}}"#;
    let a = &System::Omniverse.parse_reply(reply, &t, &scene).unwrap()[0];
    let s = a.transformation.similarity;
    assert!(s.translation.length() < 1e-9, "{s:?}");
    assert!(s
        .rotation
        .abs_diff_eq(DQuat::from_rotation_y(std::f64::consts::FRAC_PI_2), 1e-9));
}

#[test]
fn reply_errors_are_for_the_model() {
    let scene = workshop();
    let t = template("move the 'stool' left", &scene).unwrap();
    let e = System::Cga
        .parse_reply(r#"{"X2": "T(e1)"}"#, &t, &scene)
        .unwrap_err();
    assert_eq!(
        e.message,
        "the reply names X2, but the instruction only has X1"
    );
    let e = System::Cga
        .parse_reply(r#"{"X1": "X1.max"}"#, &t, &scene)
        .unwrap_err();
    assert_eq!(
        e.message,
        "X1: result is a vector, not a transformation: wrap a translation vector in T(...)"
    );
    let e = System::Cga
        .parse_reply(r#"{"X1": ["T(e1)", "D(0)"]}"#, &t, &scene)
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "X1 item 2: D(0): scale must be > 0 at column 1"
    );
    let e = System::Omniverse
        .parse_reply(r#"{"X1": {"position": [0, "up", 0]}}"#, &t, &scene)
        .unwrap_err();
    assert_eq!(e.message, "X1: \"position\"[1] must be a number");
}

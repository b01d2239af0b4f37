use super::*;
use std::f64::consts::FRAC_PI_2;

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).length() < 1e-9
}

/// A table with a bottle on it and a chair beside it.
fn workshop() -> Scene {
    let mut s = Scene::new("workshop");
    s.push_box("tool table", [1.6, 0.9, 0.8], [0.0, 0.0, 0.0]);
    s.push_box("orange bottle", [0.08, 0.25, 0.08], [0.3, 0.9, 0.1]);
    s.push_box("chair", [0.5, 0.9, 0.5], [2.0, 0.0, 0.0]);
    s.detect_supports();
    s
}

#[test]
fn world_aabb_of_a_box_uses_the_bottom_centre_pivot() {
    let s = workshop();
    let b = s.objects[0].world_aabb();
    assert!(close(b.min, DVec3::new(-0.8, 0.0, -0.4)));
    assert!(close(b.max, DVec3::new(0.8, 0.9, 0.4)));
}

#[test]
fn world_aabb_of_a_rotated_scaled_box() {
    let o = Object::new_box(
        "plank",
        DVec3::new(2.0, 0.1, 0.5),
        DVec3::new(1.0, 0.0, 0.0),
        DQuat::from_rotation_y(FRAC_PI_2),
        2.0,
    )
    .unwrap();
    let b = o.world_aabb();
    // A quarter turn about +Y swaps x and z extents; scale 2 doubles them.
    assert!(close(b.min, DVec3::new(0.5, 0.0, -2.0)));
    assert!(close(b.max, DVec3::new(1.5, 0.2, 2.0)));
}

#[test]
fn supports_are_detected_from_geometry() {
    let s = workshop();
    assert_eq!(s.objects[1].support, Some(0));
    assert_eq!(s.objects[0].support, None);
    assert_eq!(s.objects[2].support, None);
    assert_eq!(s.carried_by(0), vec![1]);
}

#[test]
fn a_rug_carries_what_stands_on_it_and_the_floor_carries_nothing() {
    let mut s = Scene::new("lounge");
    let rug = s.push_box("rug", [2.4, 0.01, 1.6], [0.0, 0.0, 0.0]);
    let table = s.push_box("coffee table", [1.2, 0.42, 0.6], [0.0, 0.01, 0.0]);
    let mug = s.push_box("mug", [0.1, 0.1, 0.1], [0.0, 0.43, 0.0]);
    let decal = s.push_box("decal", [1.0, 0.0, 1.0], [2.0, 0.0, 0.0]);
    let chair = s.push_box("chair", [0.5, 0.9, 0.5], [2.0, 0.0, 0.0]);
    s.detect_supports();
    assert_eq!(s.objects[table].support, Some(rug));
    assert_eq!(s.objects[mug].support, Some(table));
    assert_eq!(
        s.objects[chair].support, None,
        "a decal with no thickness carries nothing"
    );
    assert_eq!(s.objects[decal].support, None);
    assert_eq!(s.carried_by(rug), vec![table, mug]);
}

#[test]
fn translation_moves_the_pivot_and_carries_what_rests_on_it() {
    let mut s = workshop();
    let m = Multivector::translator(DVec3::new(1.0, 0.0, 0.0));
    let motion = s.apply(0, &m, true).unwrap();
    assert_eq!(motion.objects().collect::<Vec<_>>(), vec![0, 1]);
    assert!(close(s.objects[0].similarity().translation, DVec3::X));
    assert!(close(
        s.objects[1].similarity().translation,
        DVec3::new(1.3, 0.9, 0.1)
    ));
    assert!(close(
        s.objects[2].similarity().translation,
        DVec3::new(2.0, 0.0, 0.0)
    ));
}

#[test]
fn without_carry_only_the_object_moves() {
    let mut s = workshop();
    s.apply(0, &Multivector::translator(DVec3::X), false)
        .unwrap();
    assert!(close(
        s.objects[1].similarity().translation,
        DVec3::new(0.3, 0.9, 0.1)
    ));
}

#[test]
fn rotation_turns_about_the_pivot_with_world_axes() {
    let mut s = workshop();
    let r = Multivector::rotor(FRAC_PI_2, &Multivector::e3(), &Multivector::e1()).unwrap();
    s.apply(2, &r, true).unwrap();
    let chair = s.objects[2].similarity();
    // The pivot stays; the rotation is q · rotation.
    assert!(close(chair.translation, DVec3::new(2.0, 0.0, 0.0)));
    assert!(chair
        .rotation
        .abs_diff_eq(DQuat::from_rotation_y(FRAC_PI_2), 1e-12));
    // The table turns and carries the bottle around the table's pivot: (0.3, _, 0.1) → (0.1, _, -0.3).
    s.apply(0, &r, true).unwrap();
    assert!(close(
        s.objects[1].similarity().translation,
        DVec3::new(0.1, 0.9, -0.3)
    ));
}

#[test]
fn scale_about_the_pivot_keeps_the_bottom_on_the_floor() {
    let mut s = workshop();
    s.apply(2, &Multivector::dilator(2.0).unwrap(), true)
        .unwrap();
    let b = s.objects[2].world_aabb();
    assert!((b.min.y).abs() < 1e-12);
    assert!((b.max.y - 1.8).abs() < 1e-12);
    assert!((s.objects[2].similarity().scale - 2.0).abs() < 1e-12);
}

#[test]
fn spec_section_3_composition() {
    // position' = position + t, rotation' = q · rotation, scale' = s · scale.
    let mut s = Scene::new("t");
    let q0 = DQuat::from_rotation_x(0.3);
    s.objects
        .push(Object::new_box("a", DVec3::ONE, DVec3::new(1.0, 2.0, 3.0), q0, 1.5).unwrap());
    let step = Similarity {
        translation: DVec3::new(-1.0, 0.5, 2.0),
        rotation: DQuat::from_rotation_y(0.7),
        scale: 0.5,
    };
    s.apply(0, &step.to_versor().unwrap(), false).unwrap();
    let after = s.objects[0].similarity();
    assert!(close(after.translation, DVec3::new(0.0, 2.5, 5.0)));
    assert!(
        after.rotation.abs_diff_eq(step.rotation * q0, 1e-12)
            || after.rotation.abs_diff_eq(-(step.rotation * q0), 1e-12)
    );
    assert!((after.scale - 0.75).abs() < 1e-12);
}

#[test]
fn undo_is_exact() {
    let mut s = workshop();
    let before: Vec<_> = s.objects.iter().map(Object::similarity).collect();
    let m = Similarity {
        translation: DVec3::new(0.4, 0.2, -1.0),
        rotation: DQuat::from_rotation_y(1.1),
        scale: 1.3,
    }
    .to_versor()
    .unwrap();
    let motion = s.apply(0, &m, true).unwrap();
    s.undo(&motion);
    for (o, b) in s.objects.iter().zip(before) {
        let a = o.similarity();
        assert!(close(a.translation, b.translation), "{}", o.name);
        assert!(a.rotation.abs_diff_eq(b.rotation, 1e-12));
        assert!((a.scale - b.scale).abs() < 1e-12);
    }
}

#[test]
fn bottom_centre_pivot_for_points() {
    let points = vec![DVec3::new(4.0, 1.0, 0.0), DVec3::new(6.0, 3.0, 2.0)];
    let mut s = Scene::new("g");
    s.objects.push(
        Object::new(
            "m",
            Shape::Points { points },
            Similarity::IDENTITY,
            Pivot::BottomCenter,
        )
        .unwrap(),
    );
    assert!(close(s.objects[0].pivot_point(), DVec3::new(5.0, 1.0, 1.0)));
    s.apply(0, &Multivector::dilator(2.0).unwrap(), false)
        .unwrap();
    let b = s.objects[0].world_aabb();
    assert!(close(b.min, DVec3::new(3.0, 1.0, -1.0)));
    assert!(close(b.max, DVec3::new(7.0, 5.0, 3.0)));
}

#[test]
fn find_is_case_insensitive() {
    let s = workshop();
    assert_eq!(s.find("Tool Table"), Some(0));
    assert_eq!(s.find(" ORANGE bottle "), Some(1));
    assert_eq!(s.find("sofa"), None);
}

#[test]
fn unknown_names_get_suggestions() {
    let s = workshop();
    assert_eq!(
        s.resolve("tool tabel").unwrap_err().to_string(),
        "unknown object 'tool tabel' — did you mean 'tool table'?"
    );
    assert_eq!(
        s.resolve("xyz").unwrap_err().to_string(),
        "unknown object 'xyz'"
    );
    assert_eq!(s.resolve("CHAIR"), Ok(2));
}

#[test]
fn huge_poses_are_refused_not_panicked_on() {
    let big = |field: &str, value: &str| {
        // The field replaces the default of the same name (a repeated key is an error).
        let fields = [("\"size\"", "[1, 1, 1]"), ("\"position\"", "[0, 0, 0]")]
            .iter()
            .filter(|(f, _)| *f != field)
            .map(|(f, v)| format!("{f}: {v}, "))
            .collect::<String>();
        let text = format!(r#"{{"objects": [{{"name": "box", {fields}{field}: {value}}}]}}"#);
        crate::format::json::read(&text, "t")
            .map(|_| ())
            .unwrap_err()
            .to_string()
    };
    assert!(big("\"position\"", "[3e8, 0, 0]").contains("within ±1e6"));
    assert!(big("\"scale\"", "1e12").contains("must be in [1e-6, 1e6]"));
    assert!(big("\"size\"", "[1e308, 1, 1]").contains("at most 1e6"));
    // Huge quaternion components are only a direction.
    let text = r#"{"objects": [{"name": "box", "size": [1, 1, 1], "position": [0, 0, 0], "rotation": [0, 1e300, 0, 1e300]}]}"#;
    let mut scene = crate::format::json::read(text, "t").unwrap().scene;
    assert!(scene.objects[0].similarity().rotation.is_normalized());
    // An edit that would go beyond the limits is refused before anything moves.
    let before = scene.objects[0].similarity();
    let m = Multivector::translator(DVec3::new(1e8, 0.0, 0.0));
    let e = scene.apply(0, &m, true).unwrap_err();
    assert!(matches!(e, MotionError::TooFar { .. }), "{e}");
    assert!(e.to_string().contains("beyond"), "{e}");
    let d = Multivector::dilator(1e9).unwrap();
    assert!(matches!(
        scene.apply(0, &d, true),
        Err(MotionError::Scale(_))
    ));
    // Within the transformation's own limits, but the pose would leave them.
    let near = Multivector::translator(DVec3::new(1.5e6, 0.0, 0.0));
    assert!(matches!(
        scene.apply(0, &near, true),
        Err(MotionError::LeavesLimits(_))
    ));
    // A reflection is not a motion.
    assert!(matches!(
        scene.apply(0, &Multivector::e1(), true),
        Err(MotionError::NotSimilarity(_))
    ));
    assert_eq!(scene.objects[0].similarity(), before);
}

#[test]
fn poses_stay_exact_through_far_moves_and_back() {
    // Kept as versors, T(1e8) then T(−1e8) moved a box 4 cm, turned it and scaled it by
    // 1.000000001; kept as parts, a hundred trips to the edge of the range and back leave
    // rotation and scale bit for bit and the position within a nanometre.
    let mut s = Scene::new("far");
    let rotation = DQuat::from_axis_angle(DVec3::new(0.2, 1.0, -0.4).normalize(), 0.9);
    s.objects.push(
        Object::new_box(
            "box",
            DVec3::ONE,
            DVec3::new(0.3, 0.0, -0.7),
            rotation,
            1.25,
        )
        .unwrap(),
    );
    let start = s.objects[0].similarity();
    let there = Multivector::translator(DVec3::new(9e5, 0.0, -9e5));
    let back = Multivector::translator(DVec3::new(-9e5, 0.0, 9e5));
    for _ in 0..100 {
        s.apply(0, &there, false).unwrap();
        s.apply(0, &back, false).unwrap();
    }
    let end = s.objects[0].similarity();
    assert_eq!(end.rotation, start.rotation);
    assert_eq!(end.scale, start.scale);
    assert!(
        (end.translation - start.translation).length() < 1e-9,
        "{end:?}"
    );
    // Turning about the pivot a full circle in 360 steps comes back to the same pose.
    let step =
        Multivector::rotor(1f64.to_radians(), &Multivector::e3(), &Multivector::e1()).unwrap();
    for _ in 0..360 {
        s.apply(0, &step, false).unwrap();
    }
    let turned = s.objects[0].similarity();
    assert!(turned.rotation.dot(start.rotation).abs() > 1.0 - 1e-12);
    assert!((turned.translation - start.translation).length() < 1e-9);
    assert_eq!(turned.scale, start.scale);
}

#[test]
fn undo_restores_poses_bit_for_bit() {
    let mut s = workshop();
    let before: Vec<_> = s.objects.iter().map(Object::similarity).collect();
    let m = Multivector::rotor(0.37, &Multivector::e3(), &Multivector::e1()).unwrap()
        * Multivector::dilator(1.7).unwrap();
    let a = s.apply(0, &m, true).unwrap();
    let b = s
        .apply(0, &Multivector::translator(DVec3::new(0.1, 0.0, 0.3)), true)
        .unwrap();
    s.undo(&b);
    s.undo(&a);
    let after: Vec<_> = s.objects.iter().map(Object::similarity).collect();
    assert_eq!(after, before);
}

#[test]
fn supports_found_around_what_moved_match_a_full_detection() {
    // Stacks of boxes on a grid; move a few (onto others, off, away) and compare the
    // supports re-detected around them with a detection over the whole scene.
    let mut s = Scene::new("stacks");
    for i in 0..60 {
        let (x, z) = ((i % 6) as f64 * 2.0, (i / 6 % 5) as f64 * 2.0);
        let level = (i / 30) as f64;
        s.push_box(&format!("b{i}"), [1.0, 1.0, 1.0], [x, level, z]);
    }
    s.detect_supports();
    let moves = [
        (3, DVec3::new(2.0, 1.0, 0.0)),   // onto its neighbour
        (33, DVec3::new(0.0, -1.0, 7.0)), // off its stack, to the floor
        (10, DVec3::new(0.3, 0.0, 0.0)),  // slid under what rests on it
        (45, DVec3::new(-2.0, 0.0, 0.0)), // along the top level
    ];
    for (i, t) in moves {
        let mut boxes = s.world_aabbs();
        let mut grid = crate::geometry::FloorGrid::new(&boxes);
        let motion = s.apply(i, &Multivector::translator(t), false).unwrap();
        let changed: Vec<usize> = motion.objects().collect();
        for &c in &changed {
            let old = boxes[c];
            boxes[c] = s.objects[c].world_aabb();
            grid.update(c, &old, &boxes[c]);
        }
        let mut full = s.clone();
        full.detect_supports();
        s.detect_supports_around(&boxes, &grid, &changed, &[]);
        let around: Vec<_> = s.objects.iter().map(|o| o.support).collect();
        let everywhere: Vec<_> = full.objects.iter().map(|o| o.support).collect();
        assert_eq!(around, everywhere, "after moving b{i}");
    }
}

//! The offline translator, asserted on where objects end up.

use super::*;
use crate::geometry::Aabb;
use crate::pipeline::{edit, EditOptions};
use glam::DVec3;

fn run(scene_name: &str, instruction: &str) -> (Scene, Scene) {
    let before = crate::examples::build(scene_name).unwrap();
    let mut after = before.clone();
    let options = EditOptions {
        collisions: None,
        ..EditOptions::default()
    };
    edit(&mut after, instruction, &OfflineTranslator::new(), &options)
        .unwrap_or_else(|e| panic!("{instruction}: {e}"));
    (before, after)
}

fn refused(scene_name: &str, instruction: &str) -> String {
    let mut scene = crate::examples::build(scene_name).unwrap();
    let options = EditOptions::default();
    match edit(&mut scene, instruction, &OfflineTranslator::new(), &options) {
        Ok(e) => panic!(
            "{instruction}: should be refused, but moved {:?}",
            e.report
                .objects
                .iter()
                .map(|o| &o.object)
                .collect::<Vec<_>>()
        ),
        Err(e) => e.message,
    }
}

fn aabb(scene: &Scene, name: &str) -> Aabb {
    scene.objects[scene.find(name).unwrap()].world_aabb()
}

fn moved(before: &Scene, after: &Scene, name: &str) -> DVec3 {
    aabb(after, name).bottom_center() - aabb(before, name).bottom_center()
}

fn close(a: DVec3, b: [f64; 3]) -> bool {
    (a - DVec3::from(b)).length() < 1e-6
}

#[test]
fn several_objects_on_one_surface_are_laid_out_side_by_side() {
    // Two to four objects on the coffee table (1.1 m × 0.6 m): along x, in the order
    // named, each on its top, none overlapping.
    for names in [
        &["vase", "remote control"][..],
        &["vase", "remote control", "book"],
        &["vase", "remote control", "book", "magazine"],
        &["vase", "remote control", "book", "magazine", "table lamp"],
    ] {
        let phrases: Vec<String> = names.iter().map(|n| format!("the {n}")).collect();
        let list = format!(
            "{} and {}",
            phrases[..phrases.len() - 1].join(", "),
            phrases[phrases.len() - 1]
        );
        let mut scene = crate::examples::build("living_room").unwrap();
        let instruction = format!("put {list} on the coffee table");
        edit(
            &mut scene,
            &instruction,
            &OfflineTranslator::new(),
            &EditOptions::default(),
        )
        .unwrap_or_else(|e| panic!("{instruction}: {e}"));
        let table = aabb(&scene, "coffee table");
        let boxes: Vec<Aabb> = names.iter().map(|n| aabb(&scene, n)).collect();
        for (n, b) in names.iter().zip(&boxes) {
            assert!(
                (b.min.y - table.max.y).abs() < 1e-6,
                "{instruction}: {n} {b:?}"
            );
            let c = b.center();
            assert!(
                c.x > table.min.x && c.x < table.max.x && c.z > table.min.z && c.z < table.max.z,
                "{instruction}: {n} is off the table"
            );
        }
        for i in 0..boxes.len() {
            for j in i + 1..boxes.len() {
                assert!(
                    !boxes[i].intersects(&boxes[j], 1e-9),
                    "{instruction}: {} overlaps {}",
                    names[i],
                    names[j]
                );
            }
        }
        for pair in boxes.windows(2) {
            assert!(
                pair[0].center().x < pair[1].center().x,
                "{instruction}: not in order"
            );
        }
    }
}

#[test]
fn plain_moves_turns_scales() {
    let (b, a) = run("living_room", "move the sofa 2 m to the left");
    assert!(close(moved(&b, &a, "sofa"), [-2.0, 0.0, 0.0]));
    let (b, a) = run("living_room", "push the ottoman back 50 cm");
    assert!(close(moved(&b, &a, "ottoman"), [0.0, 0.0, -0.5]));
    let (b, a) = run("living_room", "lift the vase by 20cm");
    assert!(close(moved(&b, &a, "vase"), [0.0, 0.2, 0.0]));
}

fn yaw(scene: &Scene, name: &str) -> f64 {
    let q = scene.objects[scene.find(name).unwrap()]
        .similarity()
        .rotation;
    let (axis, angle) = q.to_axis_angle();
    (angle * axis.y.signum()).to_degrees()
}

fn scale_of(scene: &Scene, name: &str) -> f64 {
    scene.objects[scene.find(name).unwrap()].similarity().scale
}

#[test]
fn vague_amounts_have_documented_defaults() {
    let (b, a) = run("living_room", "nudge the armchair a bit to the right");
    assert!(close(moved(&b, &a, "armchair"), [0.1, 0.0, 0.0]));
    let (b, a) = run("living_room", "move the ottoman a few centimetres left");
    assert!(close(moved(&b, &a, "ottoman"), [-0.03, 0.0, 0.0]));
    let (b, a) = run("living_room", "move the ottoman a few inches forward");
    assert!(close(moved(&b, &a, "ottoman"), [0.0, 0.0, 3.0 * 0.0254]));
    let (b, a) = run("living_room", "move the ottoman a couple of feet back");
    assert!(close(moved(&b, &a, "ottoman"), [0.0, 0.0, -0.6096]));
    let (b, a) = run("living_room", "turn the ottoman slightly clockwise");
    assert!((yaw(&a, "ottoman") - yaw(&b, "ottoman") + 15.0).abs() < 1e-6);
    // "a lot" is 1 m or up to the wall: the ottoman (x from −1.5) can go 1 m left.
    let (b, a) = run("living_room", "move the ottoman a lot to the left");
    assert!(close(moved(&b, &a, "ottoman"), [-1.0, 0.0, 0.0]));
    // The floor lamp is 0.38 m from the left wall: "way over" stops against it.
    let (_, a) = run("living_room", "move the floor lamp way over to the left");
    assert!((aabb(&a, "floor lamp").min.x + 3.0).abs() < 1e-9);
    let (_, a) = run("living_room", "push the ottoman all the way to the left");
    assert!((aabb(&a, "ottoman").min.x + 3.0).abs() < 1e-9);
}

#[test]
fn spoken_and_compound_numbers() {
    for (instruction, dx) in [
        ("move the ottoman a metre and a half to the right", 1.5),
        ("move the ottoman one and a half metres to the right", 1.5),
        (
            "move the ottoman two and a half feet to the right",
            2.5 * 0.3048,
        ),
        ("move the ottoman 1.5m to the right", 1.5),
        ("move the ottoman 150cm to the right", 1.5),
        ("move the ottoman half a metre to the right", 0.5),
        (
            "move the ottoman three quarters of a metre to the right",
            0.75,
        ),
    ] {
        let (b, a) = run("living_room", instruction);
        assert!(
            close(moved(&b, &a, "ottoman"), [dx, 0.0, 0.0]),
            "{instruction}"
        );
    }
}

#[test]
fn relative_changes_go_both_ways() {
    for (instruction, factor) in [
        ("make the vase 20 % smaller", 0.8),
        ("make the vase 20 % bigger", 1.2),
        ("scale the tv down by 20 %", 0.8),
        ("scale the tv up by 20%", 1.2),
        ("shrink the vase by a third", 2.0 / 3.0),
        ("grow the vase by half", 1.5),
        ("scale the vase to 80 % of its size", 0.8),
        ("make the vase half as big", 0.5),
        ("make the vase twice as big", 2.0),
        ("make the vase three times bigger", 3.0),
        ("make the vase a bit smaller", 0.9),
        ("make the vase bigger", 1.25),
        ("double the size of the vase", 2.0),
    ] {
        let (b, a) = run("living_room", instruction);
        let name = if instruction.contains("tv") {
            "tv"
        } else {
            "vase"
        };
        let f = scale_of(&a, name) / scale_of(&b, name);
        assert!((f - factor).abs() < 1e-9, "{instruction}: {f}");
    }
}

#[test]
fn take_put_off_and_the_floor() {
    let (_, a) = run("living_room", "take the vase and put it on the side table");
    let (v, t) = (aabb(&a, "vase"), aabb(&a, "side table"));
    assert!((v.min.y - t.max.y).abs() < 1e-9);
    let (_, a) = run("living_room", "pick up the remote and drop it on the sofa");
    assert!((aabb(&a, "remote control").min.y - aabb(&a, "sofa").max.y).abs() < 1e-9);
    // Off the coffee table: on the floor, beside it.
    let (_, a) = run("living_room", "take the vase off the coffee table");
    let (v, t) = (aabb(&a, "vase"), aabb(&a, "coffee table"));
    assert!(v.min.y.abs() < 1e-9, "{v:?}");
    assert!(v.max.x < t.min.x || v.min.x > t.max.x || v.max.z < t.min.z || v.min.z > t.max.z);
    let (b, a) = run("living_room", "put the book on the floor");
    assert!(aabb(&a, "book").min.y.abs() < 1e-9);
    let d = moved(&b, &a, "book");
    assert!(d.x.abs() < 1e-9 && d.z.abs() < 1e-9);
}

#[test]
fn places_in_the_room() {
    let (_, a) = run("living_room", "centre the ottoman in the room");
    let c = aabb(&a, "ottoman").center();
    assert!(c.x.abs() < 1e-9 && c.z.abs() < 1e-9);
    let (_, a) = run(
        "bedroom",
        "move the laundry basket to the middle of the bedroom",
    );
    let c = aabb(&a, "laundry basket").center();
    assert!(c.x.abs() < 1e-9 && c.z.abs() < 1e-9);
    let (_, a) = run("living_room", "push the plant into the back left corner");
    let b = aabb(&a, "plant");
    assert!(
        (b.min.x + 3.0).abs() < 1e-9 && (b.min.z + 2.5).abs() < 1e-9,
        "{b:?}"
    );
    let (_, a) = run("living_room", "put the ottoman against the wall");
    assert!((aabb(&a, "ottoman").min.x + 3.0).abs() < 1e-9);
    let (_, a) = run("living_room", "move the ottoman to the back of the room");
    assert!((aabb(&a, "ottoman").min.z + 2.5).abs() < 1e-9);
}

#[test]
fn closer_further_and_the_other_side() {
    let flat = |v: DVec3| glam::DVec2::new(v.x, v.z).length();
    let d = |s: &Scene| flat(aabb(s, "ottoman").center() - aabb(s, "sofa").center());
    let (b, a) = run("living_room", "move the ottoman a bit closer to the sofa");
    assert!((d(&b) - d(&a) - 0.1).abs() < 1e-9);
    let (b, a) = run("living_room", "move the ottoman further from the sofa");
    assert!((d(&a) - d(&b) - 1.0).abs() < 1e-9);
    let (b, a) = run("living_room", "move the ottoman away from the sofa by 2 m");
    assert!((d(&a) - d(&b) - 2.0).abs() < 1e-9);
    // The left speaker (x −1.1) goes to the other side of the tv (x 0): x +1.1.
    let (_, a) = run(
        "living_room",
        "put the left speaker on the other side of the tv",
    );
    assert!((aabb(&a, "speaker").center().x - 1.1).abs() < 1e-9);
}

#[test]
fn diagonals_and_too() {
    let (b, a) = run(
        "living_room",
        "move the ottoman 30 cm forward and to the left",
    );
    assert!(close(moved(&b, &a, "ottoman"), [-0.3, 0.0, 0.3]));
    let (b, a) = run("living_room", "move the vase down and to the left");
    let m = moved(&b, &a, "vase");
    assert!(m.x < -0.5 && m.y < -0.2, "{m}");
    let (b, a) = run(
        "living_room",
        "move the ottoman 30 cm to the left and the armchair 30 cm to the left too",
    );
    assert!(close(moved(&b, &a, "ottoman"), [-0.3, 0.0, 0.0]));
    assert!(close(moved(&b, &a, "armchair"), [-0.3, 0.0, 0.0]));
    let (b, a) = run(
        "living_room",
        "move the ottoman 30 cm left and do the same for the armchair",
    );
    assert!(close(moved(&b, &a, "armchair"), [-0.3, 0.0, 0.0]));
}

#[test]
fn turns_straighten_and_backs() {
    let (b, a) = run("living_room", "turn the ottoman around");
    assert!((yaw(&a, "ottoman") - yaw(&b, "ottoman")).abs() - 180.0 < 1e-6);
    // The book is turned 20°: straightening turns it back by 20°.
    let (_, a) = run("living_room", "straighten the book");
    assert!(yaw(&a, "book").abs() < 1e-6, "{}", yaw(&a, "book"));
    let (_, a) = run("living_room", "square the magazine with the walls");
    assert!(yaw(&a, "magazine").abs() < 1e-6);
    // Its back to the sofa: its front (+Z) points away from the sofa.
    let (_, a) = run("living_room", "turn the ottoman's back to the sofa");
    let o = &a.objects[a.find("ottoman").unwrap()];
    let front = o.similarity().rotation * DVec3::Z;
    let to_sofa = aabb(&a, "sofa").center() - aabb(&a, "ottoman").center();
    assert!(front.dot(to_sofa) < 0.0);
}

#[test]
fn polite_forms_typos_and_punctuation() {
    for instruction in [
        "could you move the ottoman 30 cm to the left?",
        "please move the ottoman 30 cm to the left",
        "let's move the ottoman 30 cm to the left.",
        "would you mind moving the ottoman 30 cm to the left",
        "Move the ottoman 30 cm to the left!",
        "moev the ottoman 30 cm to the lfet",
        "can you move the ottoman 30 cm to the left, thanks",
    ] {
        let (b, a) = run("living_room", instruction);
        assert!(
            close(moved(&b, &a, "ottoman"), [-0.3, 0.0, 0.0]),
            "{instruction}"
        );
    }
    let (_, a) = run("living_room", "I'd like the vase on the side table");
    assert!((aabb(&a, "vase").min.y - aabb(&a, "side table").max.y).abs() < 1e-9);
}

#[test]
fn nothing_is_acted_on_from_a_partial_reading() {
    for instruction in [
        "move the sofa left and sing a song",
        "put the vase somewhere nice",
        "move the ottoman by an amount to the left",
        "rotate the ottoman a smidgeon",
        "make the coffee table prettier",
        "move the sofa left by eleventy cm",
        "move the ottoman left-ish then wiggle it",
        "take the vase",
    ] {
        let m = refused("living_room", instruction);
        assert!(m.contains("could not read"), "{instruction}: {m}");
    }
}

#[test]
fn answers_are_trees_printed_for_the_report() {
    let entries = answer(
        "put X1 on top of X2",
        2,
        &Known {
            room: true,
            yaw: vec![0.0, 0.0],
            ..Known::default()
        },
    )
    .unwrap();
    assert_eq!(entries.len(), 1);
    let text = reply_text(&entries);
    // The printed reply parses back to the same tree.
    let reply: serde_json::Value = serde_json::from_str(&text).unwrap();
    let parsed = crate::expr::parse(reply["X1"].as_str().unwrap()).unwrap();
    assert_eq!(parsed, entries[0].expressions[0]);
}

#[test]
fn next_to_takes_the_nearest_side_in_either_axis() {
    // In the office, the water cooler (x −3.2, z 0.6) is left of the meeting table
    // (x 0.5, z 1.2): it lands against the table's left face.
    let (_, a) = run("office", "put the water cooler next to the meeting table");
    let (w, t) = (aabb(&a, "water cooler"), aabb(&a, "meeting table"));
    assert!((t.min.x - w.max.x - GAP).abs() < 1e-9 && (w.center().z - t.center().z).abs() < 1e-9);
}

#[test]
fn rows_swaps_and_stacks() {
    let (_, a) = run(
        "living_room",
        "line up the left speaker, the right speaker and the plant",
    );
    let (s1, s2, p) = (
        aabb(&a, "speaker"),
        aabb(&a, "speaker 2"),
        aabb(&a, "plant"),
    );
    assert!((s2.min.x - s1.max.x - GAP).abs() < 1e-9 && (p.min.x - s2.max.x - GAP).abs() < 1e-9);
    let (b, a) = run("living_room", "swap the ottoman and the armchair");
    assert!((aabb(&a, "ottoman").center().x - aabb(&b, "armchair").center().x).abs() < 1e-9);
    let (_, a) = run(
        "workshop",
        "stack the cardboard box on the tool table and the orange bottle on the cardboard box",
    );
    let (bx, bo) = (aabb(&a, "cardboard box"), aabb(&a, "orange bottle"));
    assert!((bo.min.y - bx.max.y).abs() < 1e-9);
}

fn heading_of(scene: &Scene, name: &str) -> DVec3 {
    scene.objects[scene.find(name).unwrap()].world_front()
}

#[test]
fn facing_uses_the_objects_fronts() {
    // The living room's armchair is turned 90° (it faces +X); turned to face the tv (at
    // z 2.3), its front points at the tv whatever its turn was.
    let (_, a) = run("living_room", "turn the armchair to face the tv");
    let f = heading_of(&a, "armchair");
    let d = aabb(&a, "tv").center() - aabb(&a, "armchair").center();
    let d = DVec3::new(d.x, 0.0, d.z).normalize();
    assert!((f - d).length() < 1e-9, "{f} {d}");
    // The same way as the tv stand (which is turned 180°: it faces −Z).
    let (_, a) = run(
        "living_room",
        "turn the armchair to face the same way as the tv stand",
    );
    assert!((heading_of(&a, "armchair") - heading_of(&a, "tv stand")).length() < 1e-9);
    let (_, a) = run("living_room", "make the ottoman face the left wall");
    assert!((heading_of(&a, "ottoman") - DVec3::NEG_X).length() < 1e-9);
    let (_, a) = run(
        "living_room",
        "turn the ottoman to face the middle of the room",
    );
    let d = -aabb(&a, "ottoman").center();
    assert!((heading_of(&a, "ottoman") - DVec3::new(d.x, 0.0, d.z).normalize()).length() < 1e-9);
}

mod facing_properties {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

        /// Whatever way an object is turned, and whatever way its front points locally,
        /// "turn it to face X" leaves its front pointing at X on the floor plan.
        #[test]
        fn facing_works_for_any_current_turn(yaw in -180.0f64..180.0, tx in -2.5f64..2.5, tz in -2.0f64..2.0, minus_z: bool) {
            let mut scene = Scene::new("t");
            let mut chair = crate::scene::Object::new_box(
                "chair",
                DVec3::new(0.5, 0.9, 0.5),
                DVec3::ZERO,
                glam::DQuat::from_rotation_y(yaw.to_radians()),
                1.0,
            )
            .unwrap();
            if minus_z {
                chair.front = DVec3::NEG_Z;
            }
            scene.objects.push(chair);
            prop_assume!(tx.hypot(tz) > 0.8);
            scene.push_box("lamp", [0.3, 1.5, 0.3], [tx, 0.0, tz]);
            let options = EditOptions { collisions: None, ..EditOptions::default() };
            edit(&mut scene, "turn the chair to face the lamp", &OfflineTranslator::new(), &options).unwrap();
            let f = scene.objects[0].world_front();
            let d = DVec3::new(tx, 0.0, tz).normalize();
            prop_assert!((f - d).length() < 1e-9, "front {f}, wanted {d}");
        }
    }
}

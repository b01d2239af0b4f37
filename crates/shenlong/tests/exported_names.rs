//! Names as 3D tools export them (`Sofa_Fabric`, `Lamp_Table.003`, `SM_FloorLamp_01`), end
//! to end through the offline translator: where
//! each object ends up (or that the edit is refused, naming the candidates).

use glam::DVec3;
use shenlong::geometry::Aabb;
use shenlong::offline::OfflineTranslator;
use shenlong::pipeline::{edit, EditOptions};
use shenlong::scene::{Object, Scene};

/// Adds an unturned, unscaled box standing on `at`.
fn push_box(scene: &mut Scene, name: &str, size: [f64; 3], at: [f64; 3]) {
    let object = Object::new_box(
        name,
        DVec3::from(size),
        DVec3::from(at),
        glam::DQuat::IDENTITY,
        1.0,
    )
    .expect("a finite box");
    scene.objects.push(object);
}

/// A living room exported from Blender: no categories, names as the tool wrote them.
fn exported() -> Scene {
    let mut s = Scene::new("exported");
    s.bounds = Some(Aabb {
        min: DVec3::new(-4.0, 0.0, -3.0),
        max: DVec3::new(4.0, 3.0, 3.0),
    });
    for (name, size, at) in [
        ("Sofa_Fabric", [2.0, 0.8, 0.9], [0.0, 0.0, -2.4]),
        ("SideTable_L", [0.5, 0.55, 0.5], [-1.4, 0.0, -2.5]),
        ("SideTable_R", [0.5, 0.55, 0.5], [1.4, 0.0, -2.5]),
        ("Lamp_Table.003", [0.3, 0.5, 0.3], [-1.4, 0.55, -2.5]),
        ("SM_FloorLamp_01", [0.4, 1.6, 0.4], [2.2, 0.0, -2.5]),
        ("Chair_Wood", [0.5, 0.9, 0.5], [-2.0, 0.0, 0.0]),
        ("Chair_Wood.001", [0.5, 0.9, 0.5], [-1.0, 0.0, 0.0]),
        ("Table_Round", [1.0, 0.75, 1.0], [0.0, 0.0, 0.5]),
        ("Vase_Ceramic", [0.15, 0.3, 0.15], [0.0, 0.75, 0.5]),
        ("TV_Stand", [1.6, 0.5, 0.4], [0.0, 0.0, 2.5]),
        ("TV_Screen", [1.2, 0.7, 0.1], [0.0, 0.5, 2.5]),
        ("Remote_TV", [0.05, 0.02, 0.15], [0.7, 0.5, 2.5]),
        ("Clock_Wall", [0.4, 0.4, 0.05], [-3.0, 1.8, -2.97]),
        ("Ottoman", [0.6, 0.4, 0.6], [2.0, 0.0, 0.0]),
        ("Rug_Wool", [2.4, 0.01, 1.2], [0.0, 0.0, -1.0]),
        ("Table_Coffee", [1.0, 0.4, 0.6], [0.0, 0.01, -1.0]),
        ("Books_Stack", [0.25, 0.1, 0.2], [0.2, 0.41, -1.0]),
        ("Lamp_Standing.001", [0.35, 1.5, 0.35], [3.7, 0.0, 2.7]),
    ] {
        push_box(&mut s, name, size, at);
    }
    s.detect_supports();
    s
}

fn run(scene: &Scene, instruction: &str) -> Scene {
    let mut after = scene.clone();
    edit(
        &mut after,
        instruction,
        &OfflineTranslator::new(),
        &EditOptions::default(),
    )
    .unwrap_or_else(|e| panic!("{instruction}: {e}"));
    after
}

fn refused(scene: &Scene, instruction: &str, mentions: &[&str]) {
    let mut after = scene.clone();
    let message = match edit(
        &mut after,
        instruction,
        &OfflineTranslator::new(),
        &EditOptions::default(),
    ) {
        Ok(_) => panic!("{instruction}: should be refused"),
        Err(e) => e.message,
    };
    for m in mentions {
        assert!(
            message.contains(m),
            "{instruction}: {message} should name {m}"
        );
    }
    for (a, b) in scene.objects.iter().zip(&after.objects) {
        assert_eq!(
            a.similarity(),
            b.similarity(),
            "{instruction}: a refusal changes nothing"
        );
    }
}

fn moved(before: &Scene, after: &Scene, name: &str) -> DVec3 {
    let i = before.find(name).unwrap();
    after.objects[i].world_aabb().min - before.objects[i].world_aabb().min
}

fn only_moved(before: &Scene, after: &Scene, expected: &[(&str, [f64; 3])]) {
    for o in &before.objects {
        let want = expected
            .iter()
            .find(|(n, _)| *n == o.name)
            .map_or(DVec3::ZERO, |(_, d)| DVec3::from(*d));
        let got = moved(before, after, &o.name);
        assert!(
            (got - want).length() < 1e-6,
            "'{}' moved by {got:?}, wanted {want:?}",
            o.name
        );
    }
}

#[test]
fn exported_names_mean_what_a_person_means() {
    let s = exported();
    let a = run(&s, "move the left side table 20 cm forward");
    // The lamp on it goes with it; nothing else moves.
    only_moved(
        &s,
        &a,
        &[
            ("SideTable_L", [0.0, 0.0, 0.2]),
            ("Lamp_Table.003", [0.0, 0.0, 0.2]),
        ],
    );
    let a = run(&s, "move the vase 10 cm to the right");
    only_moved(&s, &a, &[("Vase_Ceramic", [0.1, 0.0, 0.0])]);
    let a = run(&s, "move the remote 5 cm left");
    only_moved(&s, &a, &[("Remote_TV", [-0.05, 0.0, 0.0])]);
    let a = run(&s, "move Chair_Wood 10 cm back");
    only_moved(&s, &a, &[("Chair_Wood", [0.0, 0.0, -0.1])]);
    let a = run(&s, "move wood chair 001 10 cm back");
    only_moved(&s, &a, &[("Chair_Wood.001", [0.0, 0.0, -0.1])]);
    // A colour must pick: this ottoman is not grey, however the colour is spelt.
    refused(
        &s,
        "turn the gray-coloured ottoman around",
        &["grey", "Ottoman"],
    );
    let i = s.find("Ottoman").unwrap();
    // "the TV" is the screen, not the remote for it.
    let a = run(&s, "move the ottoman 20 cm towards the TV");
    let d = moved(&s, &a, "Ottoman");
    let tv = (s.objects[s.find("TV_Screen").unwrap()]
        .world_aabb()
        .center()
        - s.objects[i].world_aabb().center())
    .with_y(0.0)
    .normalize();
    assert!((d - tv * 0.2).length() < 1e-6, "{d:?}");
    // A wall clock is no wall: "the left wall" is the room's.
    let a = run(&s, "push the ottoman flush against the right wall");
    assert!((a.objects[i].world_aabb().max.x - 4.0).abs() < 1e-6);
}

#[test]
fn names_that_answer_to_two_kinds_are_refused_when_both_fit() {
    let s = exported();
    refused(
        &s,
        "move the lamp 10 cm left",
        &["Lamp_Table.003", "SM_FloorLamp_01"],
    );
    refused(
        &s,
        "move the side table left",
        &["SideTable_L", "SideTable_R"],
    );
    refused(
        &s,
        "move the wooden chair left",
        &["Chair_Wood", "Chair_Wood.001"],
    );
}

#[test]
fn chat_around_the_instruction_changes_nothing() {
    let s = exported();
    for text in [
        "hey can u move the ottoman a bit left thx",
        "good morning! would you be so kind as to move the ottoman 10 cm to the left? cheers",
        "ty in advance! pls scoot the ottoman 10cm left",
        "sorry to bother you, quick one: move the ottoman left a bit if that's ok",
        "I'd like the ottoman moved 10 cm left",
    ] {
        let a = run(&s, text);
        only_moved(&s, &a, &[("Ottoman", [-0.1, 0.0, 0.0])]);
    }
}

#[test]
fn what_must_not_move_is_held() {
    let s = exported();
    // Not carried: the lamp stays, still on the table it overhangs.
    let a = run(
        &s,
        "move the left side table 10 cm left but leave the table lamp where it is",
    );
    only_moved(&s, &a, &[("SideTable_L", [-0.1, 0.0, 0.0])]);
    // What stands on the coffee table goes with it though the rug under it is held.
    let a = run(
        &s,
        "don't touch the rug, just move the coffee table 10 cm to the right",
    );
    only_moved(
        &s,
        &a,
        &[
            ("Table_Coffee", [0.1, 0.0, 0.0]),
            ("Books_Stack", [0.1, 0.0, 0.0]),
        ],
    );
    let a = run(
        &s,
        "move the coffee table 10 cm right, keep the books where they are",
    );
    only_moved(&s, &a, &[("Table_Coffee", [0.1, 0.0, 0.0])]);
    // A move that leaves the held lamp in the air is refused.
    refused(
        &s,
        "move the left side table 1 m to the left but leave the table lamp where it is",
        &["Lamp_Table.003", "SideTable_L"],
    );
    refused(&s, "don't move the rug", &["Rug_Wool"]);
}

#[test]
fn amounts_towards_places_and_as_far_as_it_goes() {
    let s = exported();
    let a = run(&s, "move the ottoman 30 cm towards the front wall");
    only_moved(&s, &a, &[("Ottoman", [0.0, 0.0, 0.3])]);
    // Up to the first thing in the way (the floor lamp's box is in the ottoman's path).
    let a = run(&s, "push the ottoman back as far as it will go");
    let lamp = s.objects[s.find("SM_FloorLamp_01").unwrap()].world_aabb();
    let i = s.find("Ottoman").unwrap();
    assert!((a.objects[i].world_aabb().min.z - (lamp.max.z + 0.01)).abs() < 1e-6);
    // Seen from below, clockwise is the other way.
    let above = run(
        &s,
        "turn the ottoman 90 degrees clockwise as seen from above",
    );
    let below = run(
        &s,
        "turn the ottoman 90 degrees clockwise as seen from below",
    );
    let yaw = |sc: &Scene| {
        let (axis, angle) = sc.objects[i].similarity().rotation.to_axis_angle();
        (angle * axis.y.signum()).to_degrees()
    };
    assert!((yaw(&above) + 90.0).abs() < 1e-6, "{}", yaw(&above));
    assert!((yaw(&below) - 90.0).abs() < 1e-6, "{}", yaw(&below));
}

#[test]
fn motion_verbs_from_the_lexicon() {
    let s = exported();
    for verb in ["park", "budge", "haul", "wheel", "inch"] {
        let a = run(&s, &format!("{verb} the ottoman 10 cm to the left"));
        only_moved(&s, &a, &[("Ottoman", [-0.1, 0.0, 0.0])]);
    }
}

#[test]
fn a_destination_after_a_verb_of_placing_is_not_a_pick() {
    let mut s = exported();
    push_box(&mut s, "Mug_Coffee", [0.1, 0.1, 0.1], [-0.3, 0.75, 0.3]);
    push_box(&mut s, "Mug_Coffee.001", [0.1, 0.1, 0.1], [2.0, 0.4, 0.0]);
    s.detect_supports();
    // Two mugs: "next to the vase" is where one goes, not which.
    refused(
        &s,
        "put the mug next to the vase",
        &["Mug_Coffee", "Mug_Coffee.001"],
    );
    // On the round table next to the vase: beside the vase, on the table.
    let a = run(&s, "put Mug_Coffee.001 on the round table next to the vase");
    let mug = a.objects[a.find("Mug_Coffee.001").unwrap()].world_aabb();
    let table = a.objects[a.find("Table_Round").unwrap()].world_aabb();
    let vase = a.objects[a.find("Vase_Ceramic").unwrap()].world_aabb();
    assert!((mug.min.y - table.max.y).abs() < 1e-6, "on the table");
    assert!(mug.min.x >= table.min.x && mug.max.x <= table.max.x);
    assert!(mug.min.z >= table.min.z && mug.max.z <= table.max.z);
    let gap = (vase.min.x - mug.max.x)
        .max(mug.min.x - vase.max.x)
        .max(vase.min.z - mug.max.z)
        .max(mug.min.z - vase.max.z);
    assert!((0.0..=0.06).contains(&gap), "next to the vase: gap {gap}");
}

#[test]
fn where_an_object_is_in_the_room_says_which() {
    let s = exported();
    // Of three lamps, one stands in a corner.
    let a = run(&s, "move the lamp in the corner 10 cm to the left");
    only_moved(&s, &a, &[("Lamp_Standing.001", [-0.1, 0.0, 0.0])]);
    let a = run(&s, "move the clock on the wall 20 cm down");
    only_moved(&s, &a, &[("Clock_Wall", [0.0, -0.2, 0.0])]);
    // A description that does not hold is refused, not ignored.
    refused(
        &s,
        "move the ottoman in the corner 10 cm left",
        &["Ottoman"],
    );
    // After a verb of placing, a room place that would have to pick is where one goes.
    refused(
        &s,
        "put the lamp in the corner",
        &["Lamp_Table.003", "SM_FloorLamp_01", "Lamp_Standing.001"],
    );
}

/// A study with two books (one a closed compound), two tables with cups, a wardrobe with
/// a chair beside it, a wall shelf with a book and a pouf.
fn study() -> Scene {
    let mut s = Scene::new("study");
    s.bounds = Some(Aabb {
        min: DVec3::new(-3.0, 0.0, -3.0),
        max: DVec3::new(3.0, 3.0, 3.0),
    });
    for (name, size, at) in [
        ("Desk_Teacher", [1.4, 0.75, 0.7], [0.0, 0.0, -2.0]),
        ("Textbook", [0.2, 0.04, 0.28], [-0.4, 0.75, -2.0]),
        ("Book_Exercise", [0.2, 0.02, 0.28], [0.4, 0.75, -2.0]),
        ("Table_L", [0.8, 0.75, 0.8], [-1.5, 0.0, 1.0]),
        ("Table_R", [0.8, 0.75, 0.8], [1.5, 0.0, 1.0]),
        ("Cup.000", [0.08, 0.1, 0.08], [-1.5, 0.75, 1.0]),
        ("Cup.001", [0.08, 0.1, 0.08], [1.3, 0.75, 1.0]),
        ("Cup.002", [0.08, 0.1, 0.08], [1.7, 0.75, 1.0]),
        ("Wardrobe", [1.0, 2.0, 0.6], [-2.4, 0.0, -1.0]),
        ("Chair_Reading", [0.6, 0.9, 0.6], [-1.3, 0.0, -1.1]),
        ("Shelf_Wall", [1.0, 0.03, 0.25], [2.0, 1.4, -2.8]),
        ("Novel", [0.05, 0.2, 0.15], [2.0, 1.43, -2.8]),
        ("Pouf", [0.5, 0.4, 0.5], [0.0, 0.0, 0.0]),
    ] {
        push_box(&mut s, name, size, at);
    }
    s.detect_supports();
    s
}

#[test]
fn a_closed_compound_is_as_much_its_kind_as_an_open_one() {
    // 'Textbook' is a book as much as 'Book_Exercise' (an exercise book) is.
    let s = study();
    refused(
        &s,
        "put the book on the pouf",
        &["Textbook", "Book_Exercise"],
    );
    let a = run(&s, "put the left book on the pouf");
    assert!(moved(&s, &a, "Textbook").length() > 0.5);
    assert_eq!(moved(&s, &a, "Book_Exercise"), DVec3::ZERO);
}

#[test]
fn against_an_object_is_touching_it_straight_on() {
    // The chair stands 0.3 m right of the wardrobe, overlapping it in depth: it slides
    // left until it touches, keeping its depth.
    let s = study();
    let a = run(&s, "move the reading chair flush against the wardrobe");
    only_moved(&s, &a, &[("Chair_Reading", [-0.3, 0.0, 0.0])]);
    let a = run(&s, "push the reading chair up against the wardrobe");
    only_moved(&s, &a, &[("Chair_Reading", [-0.3, 0.0, 0.0])]);
}

#[test]
fn where_a_thing_is_taken_from_says_which_and_stays_in_the_instruction() {
    let s = study();
    let a = run(
        &s,
        "take the cups off the right table and put them on the teacher desk",
    );
    let desk_top = 0.75;
    for cup in ["Cup.001", "Cup.002"] {
        let i = s.find(cup).unwrap();
        let b = a.objects[i].world_aabb();
        assert!((b.min.y - desk_top).abs() < 1e-6, "{cup}: {b:?}");
        assert!(b.center().z < -1.5, "{cup}: {b:?}");
    }
    assert_eq!(moved(&s, &a, "Cup.000"), DVec3::ZERO);
    // One cup off a table with two: which one is not said.
    refused(
        &s,
        "take the cup off the right table",
        &["Cup.001", "Cup.002"],
    );
}

#[test]
fn a_later_clause_places_the_object_from_where_the_earlier_one_left_it() {
    let s = study();
    let a = run(&s, "take the novel off the shelf and put it on the pouf");
    let i = s.find("Novel").unwrap();
    let b = a.objects[i].world_aabb();
    assert!((b.min.y - 0.4).abs() < 1e-6, "{b:?}");
    assert!(
        b.center().x.abs() < 1e-6 && b.center().z.abs() < 1e-6,
        "{b:?}"
    );
}

/// A diner exported from a game engine: numbered chairs from 1, bar stools numbered as
/// Blender copies them, a plant and a till named by words the lexicon does not know.
fn diner() -> Scene {
    let mut s = Scene::new("diner");
    s.bounds = Some(Aabb {
        min: DVec3::new(-4.0, 0.0, -3.0),
        max: DVec3::new(4.0, 3.0, 3.0),
    });
    for (name, size, at) in [
        ("SM_DiningTable_01", [1.6, 0.75, 0.9], [0.0, 0.0, 0.0]),
        ("SM_Chair_01", [0.45, 0.9, 0.45], [-0.5, 0.0, -0.8]),
        ("SM_Chair_02", [0.45, 0.9, 0.45], [0.5, 0.0, -0.8]),
        ("SM_Chair_03", [0.45, 0.9, 0.45], [-0.5, 0.0, 0.8]),
        ("SM_Chair_04", [0.45, 0.9, 0.45], [0.5, 0.0, 0.8]),
        ("Stool_Bar.001", [0.4, 0.75, 0.4], [-2.0, 0.0, 2.0]),
        ("Stool_Bar.002", [0.4, 0.75, 0.4], [-1.0, 0.0, 2.0]),
        ("Plant_Fern", [0.5, 1.0, 0.5], [3.5, 0.0, -2.5]),
        ("Counter_Main", [2.0, 1.0, 0.6], [2.5, 0.0, 2.5]),
        ("Till_POS", [0.4, 0.3, 0.4], [2.0, 1.0, 2.5]),
        ("Books_Stack", [0.3, 0.1, 0.2], [3.0, 1.0, 2.5]),
        ("Remote", [0.05, 0.02, 0.15], [0.0, 0.75, 0.0]),
        ("teacher desk", [1.2, 0.75, 0.6], [-3.0, 0.0, 0.0]),
    ] {
        push_box(&mut s, name, size, at);
    }
    s.detect_supports();
    s
}

#[test]
fn numbers_in_exported_names_say_which() {
    let s = diner();
    // By kind and number: "stool 2" is 'Stool_Bar.002'.
    let a = run(&s, "move stool 1 10cm left and stool 2 10cm right");
    only_moved(
        &s,
        &a,
        &[
            ("Stool_Bar.001", [-0.1, 0.0, 0.0]),
            ("Stool_Bar.002", [0.1, 0.0, 0.0]),
        ],
    );
    // Numbered 1 to 4: "the second chair" is the one numbered 2.
    let a = run(&s, "push the second chair 10cm to the right");
    only_moved(&s, &a, &[("SM_Chair_02", [0.1, 0.0, 0.0])]);
    // With an unnumbered chair among them, numbers do not count them: refused.
    let mut t = diner();
    push_box(&mut t, "Chair_Office", [0.5, 0.9, 0.5], [-3.0, 0.0, 2.0]);
    refused(
        &t,
        "push the second chair 10cm to the right",
        &["from where"],
    );
}

#[test]
fn a_word_of_a_name_the_lexicon_lacks_names_it_alone() {
    let s = diner();
    let a = run(&s, "move the fern a bit to the left");
    only_moved(&s, &a, &[("Plant_Fern", [-0.1, 0.0, 0.0])]);
    let a = run(&s, "hey could u move the till 25cm to the left");
    only_moved(&s, &a, &[("Till_POS", [-0.25, 0.0, 0.0])]);
    // Not before a noun ("the dining chair" is no dining table), not as a typo's reading
    // ("stick" is no 'Books_Stack').
    refused(&s, "move the dining chair 10cm left", &["SM_Chair_01"]);
    let a = run(&s, "stick the remote on the counter");
    assert_eq!(moved(&s, &a, "Books_Stack"), DVec3::ZERO);
    assert!(moved(&s, &a, "Remote").y > 0.2);
}

#[test]
fn possessives_without_apostrophes_and_typos_of_the_readers_words() {
    let s = diner();
    let a = run(&s, "move the teachers desk 20cm to the left");
    only_moved(&s, &a, &[("teacher desk", [-0.2, 0.0, 0.0])]);
    let a = run(&s, "move the fern 30 cm foward");
    only_moved(&s, &a, &[("Plant_Fern", [0.0, 0.0, 0.3])]);
    let a = run(&s, "turn the fern 90 degress clockwise");
    let i = s.find("Plant_Fern").unwrap();
    assert!(
        (a.objects[i]
            .similarity()
            .rotation
            .to_euler(glam::EulerRot::YXZ)
            .0
            .to_degrees()
            + 90.0)
            .abs()
            < 1e-6
    );
}

#[test]
fn until_it_touches_and_all_the_way_to_a_wall() {
    let s = study();
    let a = run(
        &s,
        "slide the reading chair left until it touches the wardrobe",
    );
    only_moved(&s, &a, &[("Chair_Reading", [-0.3, 0.0, 0.0])]);
    let a = run(
        &s,
        "slide the reading chair to the left until it's flush against the wardrobe",
    );
    only_moved(&s, &a, &[("Chair_Reading", [-0.3, 0.0, 0.0])]);
    let a = run(&s, "push the reading chair right up against the wardrobe");
    only_moved(&s, &a, &[("Chair_Reading", [-0.3, 0.0, 0.0])]);
    // The wardrobe is not to the chair's right: refused, never moved the other way.
    refused(
        &s,
        "slide the reading chair right until it touches the wardrobe",
        &["Wardrobe", "never reaches"],
    );
    let a = run(&s, "push the pouf all the way to the left wall");
    only_moved(&s, &a, &[("Pouf", [-2.75, 0.0, 0.0])]);
    let a = run(&s, "slide the pouf all the way back to the wall");
    only_moved(&s, &a, &[("Pouf", [0.0, 0.0, -2.75])]);
}

#[test]
fn where_a_thing_comes_from_says_which() {
    let s = study();
    let a = run(&s, "put the cup from the left table on the pouf");
    let i = s.find("Cup.000").unwrap();
    assert!((a.objects[i].world_aabb().min.y - 0.4).abs() < 1e-6);
    for other in ["Cup.001", "Cup.002"] {
        assert_eq!(moved(&s, &a, other), DVec3::ZERO);
    }
    refused(
        &s,
        "put the cup from the right table on the pouf",
        &["Cup.001", "Cup.002"],
    );
    // After an ordinal, "from" is still where the counting starts.
    let a = run(&s, "move the first cup from the left 10 cm back");
    only_moved(&s, &a, &[("Cup.000", [0.0, 0.0, -0.1])]);
}

#[test]
fn a_thing_is_what_its_modifier_names() {
    let s = study();
    let a = run(&s, "move the thing on the shelf 10 cm left");
    only_moved(&s, &a, &[("Novel", [-0.1, 0.0, 0.0])]);
    let a = run(&s, "move whatever's on the shelf onto the pouf");
    let i = s.find("Novel").unwrap();
    assert!((a.objects[i].world_aabb().min.y - 0.4).abs() < 1e-6);
    // Two things on the desk: which is not said.
    refused(
        &s,
        "move the thing on the teacher desk 10 cm left",
        &["Textbook", "Book_Exercise"],
    );
    // With no modifier, a thing is nothing in particular.
    refused(&s, "move the thing 10 cm left", &[]);
}

#[test]
fn it_and_itself_in_what_must_stay() {
    let s = study();
    // "the cup on it": the one on the table just named, of three cups; held, so the
    // table cannot move from under it.
    refused(
        &s,
        "move the left table 60 cm to the right but leave the cup on it where it is",
        &["Cup.000", "Table_L"],
    );
    // Moved less, the table still holds the cup where it is.
    let a = run(
        &s,
        "move the left table 10 cm to the right but leave the cup on it where it is",
    );
    only_moved(&s, &a, &[("Table_L", [0.1, 0.0, 0.0])]);
    let a = run(
        &s,
        "move everything on the right table 5cm forward but not the table itself",
    );
    only_moved(
        &s,
        &a,
        &[("Cup.001", [0.0, 0.0, 0.05]), ("Cup.002", [0.0, 0.0, 0.05])],
    );
}

#[test]
fn a_topic_and_a_need_to_move_are_read_as_moves() {
    let s = study();
    let a = run(&s, "Pouf: move it 15 cm to the right");
    only_moved(&s, &a, &[("Pouf", [0.15, 0.0, 0.0])]);
    let a = run(&s, "the pouf needs to go 2 feet to the left");
    only_moved(&s, &a, &[("Pouf", [-0.6096, 0.0, 0.0])]);
    let a = run(&s, "the pouf should be moved 20 cm back");
    only_moved(&s, &a, &[("Pouf", [0.0, 0.0, -0.2])]);
    // Named alone, nothing is said to happen to them.
    refused(&s, "the pouf, the novel", &[]);
}

/// A loft exported from an engine: a door and two windows as objects, mugs on two shelves.
fn loft() -> Scene {
    let mut s = Scene::new("loft");
    s.bounds = Some(Aabb {
        min: DVec3::new(-4.0, 0.0, -3.0),
        max: DVec3::new(4.0, 3.0, 3.0),
    });
    for (name, size, at) in [
        ("Door_Entrance", [1.0, 2.1, 0.1], [3.0, 0.0, 2.95]),
        ("Window_Street", [1.5, 1.2, 0.1], [-2.0, 1.0, -2.95]),
        ("Window_Yard", [1.5, 1.2, 0.1], [2.0, 1.0, -2.95]),
        ("Beanbag_Grey", [0.8, 0.6, 0.8], [0.0, 0.0, 0.0]),
        ("ShelfUnit_L", [1.0, 1.2, 0.4], [-3.0, 0.0, 0.0]),
        ("ShelfUnit_R", [1.0, 1.2, 0.4], [3.0, 0.0, 0.0]),
        ("Mug_Blue", [0.1, 0.1, 0.1], [-3.0, 1.2, 0.0]),
        ("Mug_Red", [0.1, 0.1, 0.1], [2.8, 1.2, 0.0]),
        ("Table_Coffee", [1.0, 0.45, 0.6], [0.0, 0.0, 1.5]),
    ] {
        push_box(&mut s, name, size, at);
    }
    s.detect_supports();
    s
}

#[test]
fn doors_and_windows_are_objects_and_typos_of_glue_words_and_colours_are_read() {
    let s = loft();
    // "towards the door": along the line to the door's centre, seen from above.
    let a = run(&s, "scoot the beanbag 20 cm toward the door");
    let d = moved(&s, &a, "Beanbag_Grey");
    let to_door = DVec3::new(3.0, 0.0, 2.95 + 0.05 - 0.4).normalize();
    assert!((d - to_door * 0.2).length() < 0.02, "{d:?}");
    // "bleu" is blue (a colour, two letters swapped); "teh" is the.
    let a = run(&s, "move the bleu mug 10 cm to teh left");
    only_moved(&s, &a, &[("Mug_Blue", [-0.1, 0.0, 0.0])]);
    // Another destination follows: "on the shelf" says which mug.
    let a = run(&s, "move the mug on the left shelf to the coffee table");
    let i = s.find("Mug_Blue").unwrap();
    assert!((a.objects[i].world_aabb().min.y - 0.45).abs() < 1e-6);
    // Closest to which window is not said.
    refused(
        &s,
        "move the mug closest to the window 5 cm left",
        &["Window_Street", "Window_Yard"],
    );
}

/// A table with two chairs drawn up to it, a bin in a corner and a whiteboard.
fn meeting() -> Scene {
    let mut s = Scene::new("meeting");
    s.bounds = Some(Aabb {
        min: DVec3::new(-3.0, 0.0, -3.0),
        max: DVec3::new(3.0, 3.0, 3.0),
    });
    for (name, size, at) in [
        ("table", [2.0, 0.75, 1.0], [0.0, 0.0, 0.0]),
        ("chair 1", [0.5, 0.9, 0.5], [-0.5, 0.0, 0.95]),
        ("chair 2", [0.5, 0.9, 0.5], [0.5, 0.0, -0.95]),
        ("bin", [0.3, 0.4, 0.3], [2.5, 0.0, 2.5]),
        ("whiteboard", [1.6, 1.0, 0.05], [0.0, 1.0, -2.97]),
    ] {
        push_box(&mut s, name, size, at);
    }
    s.detect_supports();
    s
}

#[test]
fn a_chair_is_pushed_in_and_pulled_out_from_its_table() {
    let s = meeting();
    // Chair 1 stands 0.2 m in front of the table: in until it touches, or by an amount.
    let a = run(&s, "push chair 1 in");
    only_moved(&s, &a, &[("chair 1", [0.0, 0.0, -0.2])]);
    let a = run(&s, "push chair 1 in 5 cm");
    only_moved(&s, &a, &[("chair 1", [0.0, 0.0, -0.05])]);
    // Chair 2 is behind it: out is further back.
    let a = run(&s, "pull chair 2 out a bit");
    only_moved(&s, &a, &[("chair 2", [0.0, 0.0, -0.1])]);
    // Nothing near the bin to push it in towards.
    refused(&s, "push the bin in a bit", &["drawn up to nothing"]);
}

#[test]
fn face_it_after_another_move_and_what_none_of_a_group_may_do() {
    let s = meeting();
    // "it": the one object the last clause moved, when this clause names its own.
    let a = run(
        &s,
        "move chair 1 20 cm to the right and turn chair 2 to face it",
    );
    let i = s.find("chair 2").unwrap();
    let turned = a.objects[i].similarity().rotation;
    let front = turned * DVec3::Z;
    let to_chair_1 = DVec3::new(-0.5 + 0.2 - 0.5, 0.0, 0.95 + 0.95).normalize();
    assert!(front.dot(to_chair_1) > 0.999, "{front:?}");
    // "till it hits the wall": all the way that way.
    let a = run(&s, "push the bin back till it hits the wall");
    let b = a.objects[s.find("bin").unwrap()].world_aabb();
    assert!((b.min.z + 3.0).abs() < 1e-9, "{b:?}");
    // "don't move any of the chairs": every chair held; the table cannot then slide
    // into them.
    let a = run(
        &s,
        "move the table 5 cm to the left but don't move any of the chairs",
    );
    only_moved(&s, &a, &[("table", [-0.05, 0.0, 0.0])]);
}

#[test]
fn the_red_one_after_the_blue_mug_is_the_red_mug() {
    let s = loft();
    let a = run(&s, "put the blue mug next to the red one");
    let (b, r) = (
        a.objects[s.find("Mug_Blue").unwrap()].world_aabb(),
        a.objects[s.find("Mug_Red").unwrap()].world_aabb(),
    );
    assert!(b.center().distance(r.center()) < 0.3, "{b:?} {r:?}");
    assert_eq!(moved(&s, &a, "Mug_Red"), DVec3::ZERO);
}

/// Where an object's box ended up: its centre.
fn centre_of(s: &Scene, name: &str) -> DVec3 {
    s.objects[s.find(name).unwrap()].world_aabb().center()
}

#[test]
fn round_four_amounts_frames_and_the_middle_of_an_object() {
    let s = exported();
    let moved = |text: &str, name: &str| {
        let after = run(&s, text);
        centre_of(&after, name) - centre_of(&s, name)
    };
    let near = |a: DVec3, b: DVec3| (a - b).length() < 1e-6;
    // Feet and inches, with marks or words; a compound length.
    assert!(near(
        moved("move the ottoman 2'6\" back", "Ottoman"),
        DVec3::new(0.0, 0.0, -0.762)
    ));
    assert!(near(
        moved("move the ottoman 2 ft 6 in back", "Ottoman"),
        DVec3::new(0.0, 0.0, -0.762)
    ));
    // No verb: the objects, then how far and where.
    assert!(near(
        moved("ottoman: 30 cm left", "Ottoman"),
        DVec3::new(-0.3, 0.0, 0.0)
    ));
    assert!(near(
        moved("the ottoman, 10 cm forward", "Ottoman"),
        DVec3::new(0.0, 0.0, 0.1)
    ));
    // Obligations and questions about the object.
    assert!(near(
        moved("the ottoman should be 1 m to the left", "Ottoman"),
        DVec3::new(-1.0, 0.0, 0.0)
    ));
    assert!(near(
        moved("coudl the ottoman go 20 cm forward", "Ottoman"),
        DVec3::new(0.0, 0.0, 0.2)
    ));
    // Away from a wall: straight out from the nearest one, or the one named.
    assert!(near(
        moved("pull the sofa 30 cm away from the wall", "Sofa_Fabric"),
        DVec3::new(0.0, 0.0, 0.3)
    ));
    assert!(near(
        moved("move the ottoman 20 cm away from the right wall", "Ottoman"),
        DVec3::new(-0.2, 0.0, 0.0)
    ));
    // "should be" before anything but a relation or an amount with a direction: refused.
    refused(&s, "the ottoman should be 1 m from the wall", &[]);
    // The middle of an object is on it, centred; of two, between them.
    let after = run(&s, "put the remote in the middle of the ottoman");
    let (remote, table) = (
        after.objects[after.find("Remote_TV").unwrap()].world_aabb(),
        after.objects[after.find("Ottoman").unwrap()].world_aabb(),
    );
    assert!((remote.min.y - table.max.y).abs() < 1e-6, "{remote:?}");
    assert!((remote.center().x - table.center().x).abs() < 1e-6);
    assert!((remote.center().z - table.center().z).abs() < 1e-6);
    let after = run(&s, "put the remote in the middle of the wooden chairs");
    let mid = (centre_of(&s, "Chair_Wood") + centre_of(&s, "Chair_Wood.001")) / 2.0;
    let o = centre_of(&after, "Remote_TV");
    assert!(
        (o.x - mid.x).abs() < 1e-6 && (o.z - mid.z).abs() < 1e-6,
        "{o} {mid}"
    );
}

#[test]
fn a_table_and_what_is_drawn_up_to_it_move_as_one() {
    let s = exported();
    let after = run(
        &s,
        "move the round table and its chairs 30 cm towards the tv stand",
    );
    let delta = |name: &str| centre_of(&after, name) - centre_of(&s, name);
    // The chair drawn up to the table goes with it, along the table's line; the other
    // wooden chair stands apart and stays.
    let (table, chair) = (delta("Table_Round"), delta("Chair_Wood.001"));
    assert!((table.length() - 0.3).abs() < 1e-6, "{table}");
    assert!((table - chair).length() < 1e-6, "{table} {chair}");
    assert!(delta("Chair_Wood").length() < 1e-9);
    // Moved as one into the way of the other chair and the wall: cleared as one.
    let after = run(&s, "move the round table and its chairs 2 m left");
    let delta = |name: &str| centre_of(&after, name) - centre_of(&s, name);
    let (table, chair) = (delta("Table_Round"), delta("Chair_Wood.001"));
    assert!((table - chair).length() < 1e-6, "{table} {chair}");
    // Several chairs closer to a table go each their own way.
    let after = run(&s, "move the wooden chairs 10 cm closer to the round table");
    let (a, b) = (
        centre_of(&after, "Chair_Wood") - centre_of(&s, "Chair_Wood"),
        centre_of(&after, "Chair_Wood.001") - centre_of(&s, "Chair_Wood.001"),
    );
    assert!((a - b).length() > 1e-3, "{a} {b}");
}

#[test]
fn two_objects_next_to_each_other() {
    let s = exported();
    for text in [
        "put the wooden chairs next to each other",
        "put Chair_Wood and Chair_Wood.001 side by side",
    ] {
        let after = run(&s, text);
        // The first stays; the second stands beside it, 5 cm off, on the floor.
        assert!((centre_of(&after, "Chair_Wood") - centre_of(&s, "Chair_Wood")).length() < 1e-9);
        let (a, b) = (
            after.objects[after.find("Chair_Wood").unwrap()].world_aabb(),
            after.objects[after.find("Chair_Wood.001").unwrap()].world_aabb(),
        );
        let gap = (b.min.x - a.max.x)
            .max(a.min.x - b.max.x)
            .max((b.min.z - a.max.z).max(a.min.z - b.max.z));
        assert!((gap - 0.05).abs() < 1e-6, "{text}: {gap}");
        assert!(b.min.y.abs() < 1e-9);
    }
}

#[test]
fn the_other_end_of_a_surface() {
    let s = exported();
    // The books lie right of the coffee table's centre (x 0.2 of its 1 m): to its other end
    // is as far left, on its top.
    for text in [
        "move the books to the other end of the coffee table",
        "put the books at the far end of the coffee table",
    ] {
        let after = run(&s, text);
        let (b, t) = (
            centre_of(&after, "Books_Stack"),
            centre_of(&s, "Table_Coffee"),
        );
        assert!((b.x - (t.x - 0.2)).abs() < 1e-6, "{text}: {b}");
        let books = after.objects[after.find("Books_Stack").unwrap()].world_aabb();
        let table = after.objects[after.find("Table_Coffee").unwrap()].world_aabb();
        assert!((books.min.y - table.max.y).abs() < 1e-6, "{text}");
    }
}

//! The five placements of issue 25 and the wrong edits of issue 41 (family 9), each on a
//! scene authored here with the same arrangement as the report (and names other than the dev suites' scenes), through the
//! whole pipeline (offline translator, collision resolution). Each test asserts where the
//! object ends up — its level, its footprint, its gap and what it overlaps — never a
//! string.

use shenlong::collide::NEXT_TO_MAX_GAP;
use shenlong::format::json;
use shenlong::geometry::Aabb;
use shenlong::offline::OfflineTranslator;
use shenlong::pipeline::{edit, EditOptions};
use shenlong::scene::Scene;

/// Level tolerance, metres.
const LEVEL: f64 = 0.011;
/// Overlap that counts, metres on every axis (touching is not colliding).
const OVERLAP: f64 = 1e-3;

fn scene(text: &str) -> Scene {
    json::read(text, "case").unwrap().scene
}

fn run(scene: &mut Scene, instruction: &str) {
    let translator = OfflineTranslator::new();
    if let Err(e) = edit(scene, instruction, &translator, &EditOptions::default()) {
        panic!("{instruction:?} was refused: {}", e.message);
    }
}

fn aabb(scene: &Scene, name: &str) -> Aabb {
    scene.objects[scene.find(name).unwrap()].world_aabb()
}

/// The horizontal gap between `name` and `other`, asserted to be at most what "next to"
/// may leave.
fn next_to(scene: &Scene, name: &str, other: &str) -> f64 {
    let g = aabb(scene, name).floor_gap(&aabb(scene, other));
    assert!(g <= NEXT_TO_MAX_GAP, "{name} {g:.2} m from {other}");
    g
}

fn footprint_within(inner: &Aabb, outer: &Aabb) -> bool {
    inner.min.x >= outer.min.x - LEVEL
        && inner.max.x <= outer.max.x + LEVEL
        && inner.min.z >= outer.min.z - LEVEL
        && inner.max.z <= outer.max.z + LEVEL
}

/// `name` overlaps no other object of the scene.
fn overlaps_nothing(scene: &Scene, name: &str) {
    let i = scene.find(name).unwrap();
    let b = scene.objects[i].world_aabb();
    for (j, other) in scene.objects.iter().enumerate() {
        if j != i {
            assert!(
                !b.intersects(&other.world_aabb(), OVERLAP),
                "{name} ends inside {}: {b:?} vs {:?}",
                other.name,
                other.world_aabb()
            );
        }
    }
}

/// Rests on `support`'s top with its footprint within it.
fn rests_on(scene: &Scene, name: &str, support: &str) {
    let b = aabb(scene, name);
    let s = aabb(scene, support);
    assert!(
        (b.min.y - s.max.y).abs() < LEVEL,
        "{name} floats or sinks: bottom {:.3}, {support}'s top {:.3}",
        b.min.y,
        s.max.y
    );
    assert!(
        footprint_within(&b, &s),
        "{name} overhangs {support}: {b:?} vs {s:?}"
    );
}

const STUDY: &str = r#"{
  "name": "study",
  "bounds": {"min": [-3, 0, -3], "max": [3, 2.6, 3]},
  "objects": [
    {"name": "writing desk", "position": [1.0, 0, -2.4], "size": [1.4, 0.74, 0.7]},
    {"name": "laptop", "position": [0.7, 0.74, -2.45], "size": [0.33, 0.02, 0.23]},
    {"name": "mug", "position": [1.55, 0.74, -2.2], "size": [0.09, 0.1, 0.09]},
    {"name": "notebook", "position": [1.2, 0.74, -2.5], "size": [0.21, 0.02, 0.3]},
    {"name": "chair", "position": [1.0, 0, -1.6], "size": [0.5, 0.9, 0.5], "rotation": [0, 1, 0, 0]},
    {"name": "bookshelf", "position": [-2.6, 0, 0], "size": [0.35, 1.9, 1.0]}
  ]
}"#;

#[test]
fn a_mug_put_next_to_a_laptop_on_a_desk_stays_on_the_desk() {
    let mut s = scene(STUDY);
    run(&mut s, "put the mug next to the laptop");
    rests_on(&s, "mug", "writing desk");
    next_to(&s, "mug", "laptop");
    overlaps_nothing(&s, "mug");
}

const LOUNGE: &str = r#"{
  "name": "lounge",
  "bounds": {"min": [-4, 0, -3], "max": [4, 2.7, 3]},
  "objects": [
    {"name": "Sofa", "position": [0, 0, -2.3], "size": [2.1, 0.85, 0.9]},
    {"name": "SideTable_L", "position": [-1.55, 0, -2.4], "size": [0.8, 0.55, 0.5]},
    {"name": "SideTable_R", "position": [1.45, 0, -2.4], "size": [0.5, 0.55, 0.5]},
    {"name": "Lamp_Table", "position": [-1.78, 0.55, -2.4], "size": [0.28, 0.55, 0.28]},
    {"name": "Cushion", "position": [0.5, 0.45, -2.3], "size": [0.36, 0.12, 0.36]},
    {"name": "Blanket", "position": [-0.5, 0.45, -2.3], "size": [0.6, 0.1, 0.5]},
    {"name": "CoffeeTable", "position": [0, 0, -0.8], "size": [1.1, 0.42, 0.6]},
    {"name": "Rug", "position": [0, 0, -0.9], "size": [2.4, 0.01, 1.7]}
  ]
}"#;

#[test]
fn a_cushion_put_on_a_side_table_with_a_lamp_lands_beside_the_lamp() {
    let mut s = scene(LOUNGE);
    run(&mut s, "put the cushion on the left side table");
    rests_on(&s, "Cushion", "SideTable_L");
    overlaps_nothing(&s, "Cushion");
    // The lamp stayed where it stood.
    let lamp = aabb(&s, "Lamp_Table");
    assert!((lamp.min.y - 0.55).abs() < LEVEL && (lamp.center().x + 1.78).abs() < 1e-6);

    // What has no room beside the lamp is refused, naming the lamp; nothing moves.
    let mut s = scene(LOUNGE);
    let before = s.world_aabbs();
    let translator = OfflineTranslator::new();
    let e = edit(
        &mut s,
        "put the blanket on the left side table",
        &translator,
        &EditOptions::default(),
    )
    .unwrap_err();
    assert!(e.message.contains("Lamp_Table"), "{}", e.message);
    assert_eq!(s.world_aabbs(), before);
}

const MEETING: &str = r#"{
  "name": "meeting room",
  "bounds": {"min": [-3.5, 0, -3], "max": [3.5, 2.8, 3]},
  "objects": [
    {"name": "whiteboard", "position": [-1.5, 1.0, -2.985], "size": [1.6, 1.0, 0.03]},
    {"name": "meeting table", "position": [0.5, 0, 0], "size": [2.0, 0.75, 1.0]},
    {"name": "office chair 1", "position": [2.6, 0, 1.8], "size": [0.6, 1.05, 0.6], "color": "grey"},
    {"name": "office chair 2", "position": [-1.0, 0, 1.8], "size": [0.6, 1.05, 0.6], "color": "black"},
    {"name": "cabinet", "position": [-0.4, 0, -2.75], "size": [0.8, 0.9, 0.45]},
    {"name": "projector", "position": [0.5, 0.75, 0], "size": [0.3, 0.1, 0.25]}
  ]
}"#;

#[test]
fn a_chair_moved_next_to_a_whiteboard_and_turned_to_face_it_stays_on_the_floor() {
    let mut s = scene(MEETING);
    run(
        &mut s,
        "move the grey office chair next to the whiteboard and turn it to face it",
    );
    let chair = "office chair 1";
    let b = aabb(&s, chair);
    assert!(
        b.min.y.abs() < LEVEL,
        "the chair was lifted to {:.2}",
        b.min.y
    );
    next_to(&s, chair, "whiteboard");
    let front = s.objects[s.find(chair).unwrap()].world_front();
    let to = aabb(&s, "whiteboard").center() - b.center();
    let to = glam::DVec3::new(to.x, 0.0, to.z).normalize();
    assert!(
        front.dot(to) > 0.95,
        "the chair faces {front:?}, the whiteboard is towards {to:?}"
    );
    overlaps_nothing(&s, chair);
}

const DEN: &str = r#"{
  "name": "den",
  "bounds": {"min": [-3, 0, -3], "max": [3, 2.6, 3]},
  "objects": [
    {"name": "tv stand", "position": [0, 0, -2.7], "size": [1.6, 0.5, 0.45]},
    {"name": "television", "position": [0, 0.5, -2.72], "size": [1.3, 0.75, 0.22]},
    {"name": "armchair", "position": [0, 0, 1.0], "size": [0.85, 0.9, 0.85], "rotation": [0, 1, 0, 0]},
    {"name": "side table", "position": [0.8, 0, 1.0], "size": [0.45, 0.55, 0.45]},
    {"name": "credit card", "position": [0.8, 0.55, 1.0], "size": [0.086, 0.001, 0.054]}
  ]
}"#;

#[test]
fn a_card_put_on_a_tv_stand_with_a_television_lands_beside_it_not_inside() {
    let mut s = scene(DEN);
    run(&mut s, "put the credit card on the tv stand");
    rests_on(&s, "credit card", "tv stand");
    overlaps_nothing(&s, "credit card");
}

const BEDROOM: &str = r#"{
  "name": "bedroom",
  "bounds": {"min": [-3, 0, -3], "max": [3, 2.6, 3]},
  "objects": [
    {"name": "dresser", "position": [-1.8, 0, -2.7], "size": [1.2, 0.8, 0.5]},
    {"name": "desk lamp", "position": [-1.45, 0.8, -2.75], "size": [0.2, 0.45, 0.2]},
    {"name": "jewellery box", "position": [-2.2, 0.8, -2.7], "size": [0.25, 0.1, 0.18]},
    {"name": "desk", "position": [1.6, 0, -2.6], "size": [1.2, 0.75, 0.6]},
    {"name": "mug", "position": [1.3, 0.75, -2.5], "size": [0.09, 0.1, 0.09]},
    {"name": "bed", "position": [0, 0, 1.2], "size": [1.6, 0.55, 2.0]}
  ]
}"#;

#[test]
fn on_a_dresser_next_to_a_lamp_is_one_destination() {
    let mut s = scene(BEDROOM);
    run(&mut s, "put the mug on the dresser next to the desk lamp");
    rests_on(&s, "mug", "dresser");
    let g = next_to(&s, "mug", "desk lamp");
    // Nearer the lamp than the jewellery box at the other end of the dresser.
    let to_box = aabb(&s, "mug").floor_gap(&aabb(&s, "jewellery box"));
    assert!(
        g < to_box,
        "mug {g:.2} m from the lamp, {to_box:.2} m from the box"
    );
    overlaps_nothing(&s, "mug");
}

/// The living room of issue 41's family 9: two side tables with names that end in their
/// side, a lamp on the left one; a bench with a coffee machine flush with its left end.
const SIDE_TABLES: &str = r#"{
  "name": "lounge",
  "bounds": {"min": [-3.5, 0, -3], "max": [3.5, 3, 3]},
  "objects": [
    {"name": "Sofa", "position": [0, 0, -2.0], "size": [2.0, 0.85, 0.9]},
    {"name": "Side Table Left", "position": [-1.4, 0, -2.0], "size": [0.5, 0.55, 0.5]},
    {"name": "Side Table Right", "position": [1.4, 0, -2.0], "size": [0.5, 0.55, 0.5]},
    {"name": "Lamp", "position": [-1.4, 0.55, -2.0], "size": [0.3, 0.5, 0.3], "on": "Side Table Left"},
    {"name": "Coffee Table", "position": [1.5, 0, 0.3], "size": [1.0, 0.45, 0.6]},
    {"name": "Bench", "position": [-2.0, 0, 1.5], "size": [1.6, 0.9, 0.6]},
    {"name": "Coffee Machine", "position": [-2.625, 0.9, 1.5], "size": [0.35, 0.4, 0.35], "on": "Bench"},
    {"name": "Cup", "position": [1.1, 0.45, 0.5], "size": [0.09, 0.1, 0.09], "on": "Coffee Table"}
  ]
}"#;

#[test]
fn a_lamp_sent_to_the_other_side_table_stands_on_it() {
    for instruction in [
        "move the lamp to the other side table",
        "move the lamp to the right side table",
        "put the lamp on the side table on the right",
    ] {
        let mut s = scene(SIDE_TABLES);
        run(&mut s, instruction);
        rests_on(&s, "Lamp", "Side Table Right");
        overlaps_nothing(&s, "Lamp");
        // The coffee table (further right than either side table) is not "the side
        // table on the right".
        assert_eq!(
            aabb(&s, "Coffee Table"),
            aabb(&scene(SIDE_TABLES), "Coffee Table")
        );
    }
}

#[test]
fn a_cup_beside_a_machine_on_a_bench_stays_on_the_bench_or_is_refused() {
    // Behind the machine there is room on the bench only closer than the usual gap.
    let mut s = scene(SIDE_TABLES);
    run(&mut s, "put the cup behind the coffee machine");
    rests_on(&s, "Cup", "Bench");
    assert!(aabb(&s, "Cup").max.z <= aabb(&s, "Coffee Machine").min.z + 1e-9);
    overlaps_nothing(&s, "Cup");
    // To its left is over the bench's end: refused, the scene as it was.
    let mut s = scene(SIDE_TABLES);
    let translator = OfflineTranslator::new();
    let refused = edit(
        &mut s,
        "put the cup to the left of the coffee machine",
        &translator,
        &EditOptions::default(),
    );
    assert!(refused.is_err(), "the cup was put over the bench's edge");
    assert_eq!(aabb(&s, "Cup"), aabb(&scene(SIDE_TABLES), "Cup"));
}

/// Under a table there is room below its top, off its legs: a stool slides under, a
/// tall one is refused; under a cabinet (solid to the floor) there is no room: refused,
/// the scene as it was — never put beside it (issue 44's silent wrong edit). A flat rug
/// slides under a bed; under a shelf hung above the floor a short crate fits, a tall one
/// is refused.
#[test]
fn under_is_under_or_refused_never_beside() {
    let text = r#"{"objects": [
        {"name": "work table", "size": [1.6, 0.9, 0.8], "position": [0, 0, 0]},
        {"name": "stool", "size": [0.4, 0.6, 0.4], "position": [0, 0, 1.5]},
        {"name": "bar stool", "size": [0.4, 1.0, 0.4], "position": [1, 0, 1.5]},
        {"name": "cabinet", "size": [1.0, 0.9, 0.5], "position": [0, 0, -2]},
        {"name": "bed", "size": [1.6, 0.5, 2.0], "position": [3, 0, 0]},
        {"name": "rug", "size": [1.2, 0.01, 0.8], "position": [3, 0, 2]},
        {"name": "wall shelf", "size": [1.0, 0.3, 0.3], "position": [-3, 0.8, 0]},
        {"name": "crate", "size": [0.4, 0.3, 0.3], "position": [-3, 0, 1.5]},
        {"name": "tall crate", "size": [0.4, 1.0, 0.3], "position": [-2, 0, 1.5]}
    ]}"#;
    let translator = OfflineTranslator::new();
    let options = EditOptions::default();
    let mut s = scene(text);
    run(&mut s, "push the stool under the work table");
    let (stool, table) = (aabb(&s, "stool"), aabb(&s, "work table"));
    let c = stool.center();
    assert!(c.x > table.min.x && c.x < table.max.x && c.z > table.min.z && c.z < table.max.z);
    assert!(stool.max.y < table.max.y && stool.min.y.abs() < LEVEL);
    overlaps_nothing_but(&s, "stool", "work table");
    let before: Vec<_> = s.objects.iter().map(|o| o.similarity()).collect();
    let e = edit(
        &mut s,
        "put the bar stool under the work table",
        &translator,
        &options,
    )
    .expect_err("refused");
    assert!(e.message.contains("tall"), "{}", e.message);
    let e = edit(
        &mut s,
        "put the crate under the cabinet",
        &translator,
        &options,
    )
    .expect_err("refused");
    assert!(e.message.contains("cannot go under"), "{}", e.message);
    let after: Vec<_> = s.objects.iter().map(|o| o.similarity()).collect();
    assert_eq!(before, after, "nothing moved");
    run(&mut s, "slide the rug under the bed");
    let (rug, bed) = (aabb(&s, "rug"), aabb(&s, "bed"));
    let c = rug.center();
    assert!(c.x > bed.min.x && c.x < bed.max.x && c.z > bed.min.z && c.z < bed.max.z);
    run(&mut s, "put the crate under the wall shelf");
    let (crate_, shelf) = (aabb(&s, "crate"), aabb(&s, "wall shelf"));
    assert!(crate_.max.y <= shelf.min.y + 1e-6 && (crate_.min.y).abs() < LEVEL);
    let e = edit(
        &mut s,
        "put the tall crate under the wall shelf",
        &translator,
        &options,
    )
    .expect_err("refused");
    assert!(e.message.contains("tall"), "{}", e.message);
}

/// A chair taller than a desk's knee room is tucked as a chair is: its seat under the
/// top, its back out at the edge, what stands on the desk untouched; pushed in, the same;
/// facing away, it is refused, saying to turn it.
#[test]
fn a_chair_is_tucked_seat_under_back_out() {
    // The desk against the back wall, the chair before it facing it (front −z), a
    // monitor on the desk near its front edge.
    let text = r#"{"bounds": {"min": [-2, 0, -2], "max": [2, 2.6, 2]},
      "objects": [
        {"name": "desk", "size": [1.4, 0.75, 0.7], "position": [0, 0, -1.6]},
        {"name": "monitor", "size": [0.5, 0.4, 0.15], "position": [0, 0.75, -1.4]},
        {"name": "office chair", "size": [0.55, 0.95, 0.55], "position": [0, 0, -0.8],
         "rotation": [0, 1, 0, 0]}
    ]}"#;
    let seat_under_back_out = |s: &Scene| {
        let (chair, desk) = (aabb(s, "office chair"), aabb(s, "desk"));
        // Its seat (the lower half) reaches under the top, its back (the rear 12 cm)
        // stays out of the desk.
        assert!(chair.min.z < desk.max.z - 0.1, "{chair:?} {desk:?}");
        assert!(
            chair.max.z - 0.12 >= desk.max.z - 1e-6,
            "{chair:?} {desk:?}"
        );
        assert!((chair.min.y).abs() < LEVEL);
    };
    for instruction in [
        "tuck the office chair under the desk",
        "push the office chair in",
        "tuck the office chair in",
        "tuck in the office chair",
        "push the office chair all the way in",
        "tuck the office chair into the desk",
        "slide the office chair in under the desk",
        "tuck the office chair neatly under the desk",
    ] {
        let mut s = scene(text);
        let monitor = aabb(&s, "monitor");
        run(&mut s, instruction);
        seat_under_back_out(&s);
        assert_eq!(aabb(&s, "monitor").min, monitor.min, "{instruction}");
    }
    // Facing away (front +z, its back towards the desk): turn it first.
    let away = text.replace("\"rotation\": [0, 1, 0, 0]", "\"rotation\": [0, 0, 0, 1]");
    let mut s = scene(&away);
    let e = edit(
        &mut s,
        "tuck the office chair under the desk",
        &OfflineTranslator::new(),
        &EditOptions::default(),
    )
    .expect_err("refused");
    assert!(e.message.contains("turn it to face"), "{}", e.message);
}

/// In a bookcase: on a shelf, within its walls, under the shelf above — the lowest with
/// room, or the one named ("the top shelf of …"); too tall for any shelf, refused; a
/// filing cabinet has drawers, not shelves: refused as solid.
#[test]
fn in_a_bookcase_is_on_a_shelf_or_refused() {
    let text = r#"{"objects": [
        {"name": "bookcase", "size": [0.9, 1.8, 0.35], "position": [0, 0, 0]},
        {"name": "book", "size": [0.15, 0.22, 0.03], "position": [2, 0, 0]},
        {"name": "novel", "size": [0.14, 0.2, 0.03], "position": [2.5, 0, 0]},
        {"name": "floor vase", "size": [0.3, 0.6, 0.3], "position": [3, 0, 1]},
        {"name": "filing cabinet", "size": [0.5, 1.2, 0.6], "position": [-2, 0, 0]}
    ]}"#;
    let translator = OfflineTranslator::new();
    let options = EditOptions::default();
    let mut s = scene(text);
    run(&mut s, "put the book in the bookcase");
    let (book, case) = (aabb(&s, "book"), aabb(&s, "bookcase"));
    assert!(
        shenlong::scene::form::clear_shelved(&book, &case, shenlong::scene::Form::SHELVES),
        "{book:?}"
    );
    assert!(
        (book.min.y - shenlong::scene::form::WALL).abs() < LEVEL,
        "the lowest shelf"
    );
    for said in [
        "put the novel on a shelf in the bookcase",
        "put the novel away in the bookcase",
        "place the novel on the bookcase shelf",
        "put the novel on one of the shelves of the bookcase",
    ] {
        let mut t = s.clone();
        run(&mut t, said);
        assert!(
            shenlong::scene::form::clear_shelved(
                &aabb(&t, "novel"),
                &case,
                shenlong::scene::Form::SHELVES
            ),
            "{said}"
        );
    }
    run(&mut s, "put the novel on the top shelf of the bookcase");
    let novel = aabb(&s, "novel");
    assert!(shenlong::scene::form::clear_shelved(
        &novel,
        &case,
        shenlong::scene::Form::SHELVES
    ));
    assert!(novel.min.y > 1.4 && novel.max.y < case.max.y, "{novel:?}");
    let e = edit(
        &mut s,
        "put the floor vase in the bookcase",
        &translator,
        &options,
    )
    .expect_err("refused");
    assert!(
        e.message.contains("does not fit on a shelf"),
        "{}",
        e.message
    );
    let e = edit(
        &mut s,
        "put the book in the filing cabinet",
        &translator,
        &options,
    )
    .expect_err("refused");
    assert!(e.message.contains("solid box"), "{}", e.message);
}

/// A shelf of a bookcase is a part of it even where a wall shelf would make "a shelf"
/// name two objects: "a shelf of the bookcase", "the second shelf from the top of …",
/// "the bottom shelf in …".
#[test]
fn a_shelf_of_a_bookcase_is_a_part_beside_a_wall_shelf() {
    let text = r#"{"objects": [
        {"name": "bookshelf", "size": [0.8, 1.8, 0.3], "position": [0, 0, -2]},
        {"name": "wall shelf", "size": [0.6, 0.03, 0.2], "position": [2, 1.5, -2.4]},
        {"name": "shelving unit", "size": [1.0, 1.6, 0.4], "position": [-2, 0, -2]},
        {"name": "book", "size": [0.15, 0.22, 0.03], "position": [1.5, 0, 0]}
    ]}"#;
    let s = scene(text);
    let wall = aabb(&s, "wall shelf");
    for (said, case, level) in [
        (
            "put the book on a shelf of the bookshelf",
            "bookshelf",
            0.02,
        ),
        (
            "put the book on the second shelf from the top of the bookshelf",
            "bookshelf",
            1.22,
        ),
        (
            "put the book on the second shelf from the bottom in the shelving unit",
            "shelving unit",
            0.34,
        ),
        (
            "put the book on the top shelf on the shelving unit",
            "shelving unit",
            1.30,
        ),
    ] {
        let mut t = s.clone();
        run(&mut t, said);
        let (book, case_box) = (aabb(&t, "book"), aabb(&t, case));
        assert!(
            shenlong::scene::form::clear_shelved(&book, &case_box, shenlong::scene::Form::SHELVES),
            "{said}: {book:?}"
        );
        assert!((book.min.y - level).abs() < LEVEL, "{said}: {book:?}");
        assert_eq!(aabb(&t, "wall shelf"), wall, "{said}");
    }
}

/// A scene file says how high the room under a bed reaches (`room_below`): a tray slides
/// under, a stool is refused saying so; a wrong value is refused naming the field.
#[test]
fn a_scene_file_says_the_room_below_a_bed() {
    let text = r#"{"objects": [
        {"name": "bed", "size": [1.6, 0.6, 2.0], "position": [0, 0, 0], "room_below": 0.25},
        {"name": "tray", "size": [0.6, 0.15, 0.4], "position": [2, 0, 0]},
        {"name": "stool", "size": [0.35, 0.45, 0.35], "position": [-2, 0, 0]}
    ]}"#;
    let mut s = scene(text);
    run(&mut s, "slide the tray under the bed");
    let (tray, bed) = (aabb(&s, "tray"), aabb(&s, "bed"));
    assert!(
        tray.min.y.abs() < LEVEL && tray.max.y <= 0.25 + LEVEL,
        "{tray:?}"
    );
    assert!(footprint_within(&tray, &bed), "{tray:?}");
    let e = edit(
        &mut s,
        "put the stool under the bed",
        &OfflineTranslator::new(),
        &EditOptions::default(),
    )
    .expect_err("refused");
    assert!(e.message.contains("0.25 m"), "{}", e.message);
    for bad in [
        r#"{"objects": [{"name": "bed", "size": [1, 0.6, 2], "position": [0, 0, 0], "room_below": 0.9}]}"#,
        r#"{"objects": [{"name": "bed", "size": [1, 0.6, 2], "position": [0, 0, 0], "room_below": 0.2, "form": "open"}]}"#,
    ] {
        let e = json::read(bad, "bad").map(|_| ()).unwrap_err().to_string();
        assert!(e.contains("objects[0].room_below"), "{e}");
    }
}

/// "Put X back on Y": "back" says it was there before, not a way; where a thing is taken
/// from is what it rests on ("off the table" with two tables).
#[test]
fn back_onto_and_off_what_it_rests_on() {
    let text = r#"{"objects": [
        {"name": "coffee table", "size": [1.1, 0.45, 0.6], "position": [0, 0, 0]},
        {"name": "side table", "size": [0.5, 0.55, 0.5], "position": [2, 0, 0]},
        {"name": "mug", "size": [0.1, 0.1, 0.1], "position": [0, 0.45, 0]}
    ]}"#;
    let mut s = scene(text);
    let side = aabb(&s, "side table");
    run(&mut s, "put the mug back on the side table");
    rests_on(&s, "mug", "side table");
    assert_eq!(aabb(&s, "side table"), side);
    let mut s = scene(text);
    run(&mut s, "take the mug off the table");
    let mug = aabb(&s, "mug");
    assert!(mug.min.y.abs() < LEVEL, "on the floor: {mug:?}");
}

/// What fits in a box or on a shelf only turned is turned a quarter turn about the
/// vertical, as a person would: a book deeper than the shelf, a rolling pin longer than
/// the crate is deep; what fits neither way is refused.
#[test]
fn what_fits_only_turned_is_turned_a_quarter_turn() {
    let text = r#"{"objects": [
        {"name": "bookcase", "size": [0.8, 1.8, 0.3], "position": [0, 0, -2]},
        {"name": "book", "size": [0.04, 0.24, 0.35], "position": [1.5, 0, 0]},
        {"name": "crate", "size": [0.6, 0.3, 0.35], "position": [-1.5, 0, 0]},
        {"name": "rolling pin", "size": [0.08, 0.08, 0.45], "position": [1, 0, 1]},
        {"name": "poster tube", "size": [0.1, 0.1, 0.9], "position": [2, 0, 1]}
    ]}"#;
    let mut s = scene(text);
    let (book, pin) = (aabb(&s, "book"), aabb(&s, "rolling pin"));
    run(&mut s, "put the book in the bookcase");
    let (after, case) = (aabb(&s, "book"), aabb(&s, "bookcase"));
    assert!(
        shenlong::scene::form::clear_shelved(&after, &case, shenlong::scene::Form::SHELVES),
        "{after:?}"
    );
    assert!(
        (after.size().x - book.size().z).abs() < 1e-9
            && (after.size().z - book.size().x).abs() < 1e-9,
        "turned: {after:?}"
    );
    run(&mut s, "put the rolling pin in the crate");
    let (after, crate_box) = (aabb(&s, "rolling pin"), aabb(&s, "crate"));
    assert!(
        shenlong::scene::form::clear_inside(&after, &crate_box),
        "{after:?}"
    );
    assert!(
        (after.size().x - pin.size().z).abs() < 1e-9,
        "turned: {after:?}"
    );
    let e = edit(
        &mut s,
        "put the poster tube in the crate",
        &OfflineTranslator::new(),
        &EditOptions::default(),
    )
    .expect_err("refused");
    assert!(e.message.contains("does not fit"), "{}", e.message);
}

/// `name` overlaps no object but `allowed` (and what it stood in before).
fn overlaps_nothing_but(scene: &Scene, name: &str, allowed: &str) {
    let a = aabb(scene, name);
    for o in &scene.objects {
        if o.name == name || o.name == allowed {
            continue;
        }
        let b = o.world_aabb();
        let overlap = a.overlap(&b);
        assert!(
            !(overlap.x > OVERLAP && overlap.y > OVERLAP && overlap.z > OVERLAP),
            "{name} overlaps {}",
            o.name
        );
    }
}

/// A scene file says an object's form: a cabinet on legs has room below; a table said
/// solid has none. A form it does not know is refused, naming the field.
#[test]
fn a_scene_file_says_what_is_on_legs() {
    let text = r#"{"objects": [
        {"name": "cabinet", "size": [1.0, 0.9, 0.6], "position": [0, 0, 0], "form": "on_legs"},
        {"name": "table", "size": [1.0, 0.9, 0.6], "position": [3, 0, 0], "form": "solid"},
        {"name": "box", "size": [0.3, 0.3, 0.3], "position": [0, 0, 2]},
        {"name": "crate", "size": [0.3, 0.3, 0.3], "position": [3, 0, 2]}
    ]}"#;
    let mut s = scene(text);
    run(&mut s, "put the box under the cabinet");
    assert!(aabb(&s, "box").max.y < aabb(&s, "cabinet").max.y);
    let e = edit(
        &mut s,
        "put the crate under the table",
        &OfflineTranslator::new(),
        &EditOptions::default(),
    )
    .expect_err("refused");
    assert!(e.message.contains("cannot go under"), "{}", e.message);
    let bad = text.replace("\"solid\"", "\"hollow\"");
    let e = json::read(&bad, "case")
        .map(|_| ())
        .unwrap_err()
        .to_string();
    assert!(e.contains("objects[1].form"), "{e}");
}

/// In a box: on its bottom, within its walls; what is too big for it, or a solid target,
/// is refused, never put beside it.
#[test]
fn in_a_container_is_inside_or_refused_never_beside() {
    let text = r#"{"objects": [
        {"name": "bench", "size": [2.0, 0.9, 0.6], "position": [0, 0, 0], "form": "solid"},
        {"name": "toolbox", "size": [0.5, 0.25, 0.25], "position": [-0.5, 0.9, 0]},
        {"name": "drill", "size": [0.25, 0.22, 0.08], "position": [0.5, 0.9, 0.1]},
        {"name": "saw", "size": [0.6, 0.1, 0.15], "position": [0.2, 0.9, -0.1]},
        {"name": "dresser", "size": [0.8, 1.0, 0.5], "position": [3, 0, 0]},
        {"name": "cup", "size": [0.08, 0.1, 0.08], "position": [0.8, 0.9, -0.2]}
    ]}"#;
    let translator = OfflineTranslator::new();
    let options = EditOptions::default();
    let mut s = scene(text);
    for (said, name) in [
        ("stow the drill away in the toolbox", "drill"),
        ("throw the cup in the toolbox", "cup"),
    ] {
        let mut t = s.clone();
        run(&mut t, said);
        assert!(
            shenlong::scene::form::clear_inside(&aabb(&t, name), &aabb(&t, "toolbox")),
            "{said}"
        );
    }
    run(&mut s, "put the drill in the toolbox");
    let (drill, toolbox) = (aabb(&s, "drill"), aabb(&s, "toolbox"));
    assert!(
        shenlong::scene::form::clear_inside(&drill, &toolbox),
        "{drill:?} in {toolbox:?}"
    );
    overlaps_nothing_but(&s, "drill", "toolbox");
    let before: Vec<_> = s.objects.iter().map(|o| o.similarity()).collect();
    let e = edit(&mut s, "put the saw in the toolbox", &translator, &options).expect_err("refused");
    assert!(e.message.contains("does not fit"), "{}", e.message);
    let e = edit(&mut s, "put the cup in the dresser", &translator, &options).expect_err("refused");
    assert!(e.message.contains("solid box"), "{}", e.message);
    let after: Vec<_> = s.objects.iter().map(|o| o.similarity()).collect();
    assert_eq!(before, after, "nothing moved");
}

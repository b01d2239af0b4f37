//! Grounding, construct by construct, on the built-in scenes: each test says which objects
//! a phrase must mean, or that it must be refused with its candidates named.

use super::*;
use crate::scene::Scene;

/// A built-in example scene.
pub(super) fn scene(name: &str) -> Scene {
    crate::examples::build(name).unwrap()
}

/// The objects of each phrase, by name.
pub(super) fn g(scene: &Scene, text: &str) -> Result<Vec<Vec<String>>, GroundError> {
    let grounding = Grounder::new(scene).ground(text, scene)?;
    Ok(grounding
        .phrases
        .iter()
        .map(|p| {
            p.objects
                .iter()
                .map(|&o| scene.objects[o].name.clone())
                .collect()
        })
        .collect())
}

/// Asserts that `text` in the built-in scene `scene_name` grounds to these phrases' objects
/// (by name, in binding order).
pub(super) fn means(scene_name: &str, text: &str, expected: &[&[&str]]) {
    let s = scene(scene_name);
    let got = g(&s, text).unwrap_or_else(|e| panic!("{text}: {e}"));
    let want: Vec<Vec<String>> = expected
        .iter()
        .map(|p| p.iter().map(|n| n.to_string()).collect())
        .collect();
    assert_eq!(got, want, "{text}");
}

/// Asserts that `text` in the built-in scene `scene_name` is refused with a message that
/// names each of `mentions`; returns the message.
pub(super) fn refused(scene_name: &str, text: &str, mentions: &[&str]) -> String {
    let s = scene(scene_name);
    let e = g(&s, text).map(|p| format!("{p:?}")).unwrap_err();
    let message = e.to_string();
    for m in mentions {
        assert!(message.contains(m), "{text}: {message} should name {m}");
    }
    message
}

/// Runs `f` on a reader of `text` in the built-in scene `scene_name`: for a stage's own
/// tests.
pub(super) fn with_reader<T>(scene_name: &str, text: &str, f: impl FnOnce(&Reader<'_>) -> T) -> T {
    let s = scene(scene_name);
    let grounder = Grounder::new(&s);
    let reader = Reader::new(&grounder, &s, text);
    f(&reader)
}

#[test]
fn typos_of_long_words_only_when_they_lead_to_one_object() {
    means("living_room", "move the ottomann left", &[&["ottoman"]]);
    means("living_room", "move the bokshelf left", &[&["bookshelf"]]);
    // Short words are not corrected.
    assert!(g(&scene("living_room"), "move the sfa left").is_err());
}

#[test]
fn unknown_objects_and_instructions_naming_none() {
    let m = refused("living_room", "move the piano left", &[]);
    assert!(m.contains("\"the piano\" matches no object"), "{m}");
    let m = refused("living_room", "move it left", &[]);
    assert!(m.contains("names no object"), "{m}");
    let m = refused("living_room", "move the 'sofaa' left", &["sofa"]);
    assert!(m.contains("unknown object 'sofaa'"), "{m}");
}

#[test]
fn reasons_are_reported() {
    let s = scene("living_room");
    let grounding = Grounder::new(&s).ground("move the couch left", &s).unwrap();
    let p = &grounding.phrases[0];
    assert_eq!(p.text, "the couch");
    assert_eq!(p.reasons[0].kind, ReasonKind::Synonym);
}

#[test]
fn scene_json_categories_aliases_and_colours() {
    let text = r#"{"objects": [
        {"name": "obj_17", "category": "armchair", "color": "red", "size": [1, 1, 1], "position": [-1, 0, 0]},
        {"name": "obj_18", "category": "armchair", "color": "blue", "size": [1, 1, 1], "position": [1, 0, 0]},
        {"name": "Big Bertha", "aliases": ["the beast", "speaker"], "size": [1, 1, 1], "position": [0, 0, 3]}
    ]}"#;
    let s = crate::format::json::read(text, "t").unwrap().scene;
    assert_eq!(
        g(&s, "move the red armchair left").unwrap(),
        vec![vec!["obj_17".to_string()]]
    );
    assert_eq!(
        g(&s, "move the blue chair left").unwrap(),
        vec![vec!["obj_18".to_string()]]
    );
    assert_eq!(
        g(&s, "move the speaker left").unwrap(),
        vec![vec!["Big Bertha".to_string()]]
    );
    let e = g(&s, "move the green armchair left").unwrap_err();
    assert!(e.to_string().contains("no armchair is green"), "{e}");
}

#[test]
fn pronouns_with_nothing_before_them_mean_the_selection() {
    let s = scene("living_room");
    let grounder = Grounder::new(&s);
    let armchairs: Vec<usize> = ["armchair", "ottoman"]
        .iter()
        .map(|n| s.find(n).unwrap())
        .collect();
    let names = |g: &Grounding| -> Vec<Vec<String>> {
        g.phrases
            .iter()
            .map(|p| {
                p.objects
                    .iter()
                    .map(|&o| s.objects[o].name.clone())
                    .collect()
            })
            .collect()
    };
    let one = &armchairs[..1];
    let g = grounder
        .ground_with_selection("turn it 90 degrees", &s, one)
        .unwrap();
    assert_eq!(names(&g), vec![vec![s.objects[one[0]].name.clone()]]);
    assert_eq!(g.phrases[0].text, "it");
    assert_eq!(g.phrases[0].reasons[0].kind, ReasonKind::Selection);
    let g = grounder
        .ground_with_selection("move the selected objects 1 m to the left", &s, &armchairs)
        .unwrap();
    assert_eq!(g.phrases[0].text, "the selected objects");
    assert_eq!(g.phrases[0].objects, armchairs);
    // Something named first: "it" refers back to it, not to the selection.
    let g = grounder
        .ground_with_selection("move the sofa left and turn it", &s, one)
        .unwrap();
    assert!(g
        .phrases
        .iter()
        .all(|p| p.reasons[0].kind != ReasonKind::Selection));
    // The selection and a named object.
    let g = grounder
        .ground_with_selection("put it next to the sofa", &s, one)
        .unwrap();
    assert_eq!(g.phrases.len(), 2);
    assert_eq!(g.phrases[0].objects, one);
    // "those two", "both of those", "the pair of them": the selection.
    for said in [
        "move those two forward a bit",
        "push both of those right",
        "shift the pair of them left",
    ] {
        let g = grounder
            .ground_with_selection(said, &s, &armchairs)
            .unwrap();
        assert_eq!(g.phrases[0].objects, armchairs, "{said}");
        assert_eq!(
            g.phrases[0].reasons[0].kind,
            ReasonKind::Selection,
            "{said}"
        );
    }
    // Without a selection, "it" alone still names nothing.
    assert!(matches!(
        grounder.ground("turn it 90 degrees", &s),
        Err(GroundError::NoObject { .. })
    ));
}

#[test]
fn names_typed_as_they_are_and_kinds_the_scene_lacks() {
    let mut s = scene("dining_room");
    s.objects[0].name = "Chair (2)".into();
    s.objects[1].name = "Lamp [left]".into();
    assert_eq!(g(&s, "move Chair (2) right 1 m").unwrap(), [["Chair (2)"]]);
    assert_eq!(g(&s, "push lamp [LEFT] back").unwrap(), [["Lamp [left]"]]);
    // Already quoted, it stays as it was.
    assert_eq!(g(&s, "move 'Chair (2)' left").unwrap(), [["Chair (2)"]]);
    // A kind of object the scene has none of is said so, by its word.
    let e = g(&s, "move the window left").unwrap_err();
    assert!(
        matches!(&e, GroundError::Absent { word, .. } if word == "window"),
        "{e}"
    );
    assert!(
        e.to_string().starts_with("there is no window in the scene"),
        "{e}"
    );
    // The floor and the walls are always there: never "there is no floor".
    let e = g(&s, "move the gizmo on the floor by the wall").unwrap_err();
    assert!(matches!(e, GroundError::NoObject { .. }), "{e}");
}

/// An exam hall: three rows of four numbered desks, each with a stool behind it, and a
/// teacher's desk standing apart at the back.
fn exam_hall() -> Scene {
    let mut s = Scene::new("exam hall");
    let mut k = 1;
    for row in 0..3 {
        for col in 0..4 {
            let (x, z) = (-3.0 + 2.0 * f64::from(col), -2.0 + 2.0 * f64::from(row));
            s.push_box(&format!("Exam Desk {k:02}"), [1.2, 0.75, 0.6], [x, 0.0, z]);
            s.push_box(&format!("Stool {k}"), [0.4, 0.45, 0.4], [x, 0.0, z + 0.6]);
            k += 1;
        }
    }
    s.push_box("Invigilator Desk", [1.6, 0.75, 0.8], [0.0, 0.0, -4.0]);
    s
}

#[test]
fn rows_and_columns_of_alike_objects() {
    let s = exam_hall();
    let names = |text: &str| g(&s, text).unwrap_or_else(|e| panic!("{text}: {e}"));
    // Rows count from the front (+z); the teacher's desk standing apart is no row.
    assert_eq!(
        names("move the desks in the back row back 20 cm"),
        [[
            "Exam Desk 01",
            "Exam Desk 02",
            "Exam Desk 03",
            "Exam Desk 04"
        ]]
    );
    assert_eq!(
        names("move the back row of desks back 20 cm"),
        [[
            "Exam Desk 01",
            "Exam Desk 02",
            "Exam Desk 03",
            "Exam Desk 04"
        ]]
    );
    assert_eq!(
        names("move the stools in the front row left"),
        [["Stool 9", "Stool 10", "Stool 11", "Stool 12"]]
    );
    assert_eq!(
        names("move the desks in row 2 forward"),
        [[
            "Exam Desk 05",
            "Exam Desk 06",
            "Exam Desk 07",
            "Exam Desk 08"
        ]]
    );
    assert_eq!(
        names("move the desks in the left column right"),
        [["Exam Desk 01", "Exam Desk 05", "Exam Desk 09"]]
    );
    assert_eq!(
        names("the left stool in the back row, 20 cm right"),
        [["Stool 1"]]
    );
    // An ordinal counts along the line: a row from the left, a column from the front.
    assert_eq!(
        names("move the second desk in the front row left"),
        [["Exam Desk 10"]]
    );
    assert_eq!(
        names("move the last desk in row 2 back"),
        [["Exam Desk 08"]]
    );
    assert_eq!(
        names("move the second desk in the left column left"),
        [["Exam Desk 05"]]
    );
    // One desk of a row is not said: refused naming the row.
    let e = g(&s, "move the desk in the back row left").unwrap_err();
    assert!(e.mentions().len() == 4, "{e}");
    // No fourth row.
    assert!(g(&s, "move the desks in the fourth row left").is_err());
    // The one-of-a-kind desk is only a line of its own when nothing else is.
    let mut lone = exam_hall();
    lone.objects.last_mut().unwrap().name = "Exam Desk 13".into();
    assert!(g(&lone, "move the desks in the back row left").is_err());
}

#[test]
fn an_object_and_what_belongs_to_it() {
    let s = exam_hall();
    let names = |text: &str| g(&s, text).unwrap_or_else(|e| panic!("{text}: {e}"));
    assert_eq!(
        names("move desk 2 and its stool left 30 cm"),
        [["Exam Desk 02", "Stool 2"]]
    );
    assert_eq!(
        names("move desks 1 and 2 along with their stools back"),
        [["Exam Desk 01", "Exam Desk 02", "Stool 1", "Stool 2"]]
    );
    assert_eq!(
        names("push desk 7 with its stool forward"),
        [["Exam Desk 07", "Stool 7"]]
    );
    // Cut short, or with a word for any object: answered, never a panic.
    for text in [
        "move desk 2 and its",
        "move desk 2 with their",
        "move the object",
    ] {
        let _ = g(&s, text);
    }
    // The teacher's desk has no stool drawn up to it: refused, not guessed.
    let e = g(&s, "move the invigilator desk and its stool left").unwrap_err();
    assert!(e.to_string().contains("no stool"), "{e}");
}

#[test]
fn a_left_out_phrase_reads_its_own_modifier() {
    let s = exam_hall();
    let left_out = |text: &str| {
        let moved: Vec<String> = g(&s, text).unwrap_or_else(|e| panic!("{text}: {e}"))[0].clone();
        let mut out: Vec<String> = (1..=12)
            .map(|k| format!("Stool {k}"))
            .filter(|n| !moved.contains(n))
            .collect();
        out.sort();
        out
    };
    assert_eq!(
        left_out("move all the stools except the one by desk 5 back"),
        ["Stool 5"]
    );
    assert_eq!(
        left_out("move all the stools except the ones in the back row back"),
        ["Stool 1", "Stool 2", "Stool 3", "Stool 4"]
    );
    // One that is not one: refused, naming them.
    assert!(g(
        &s,
        "move all the stools except the one in the back row back"
    )
    .is_err());
}

#[test]
fn number_one_is_the_unnumbered_first_of_copies_numbered_from_two() {
    // "student desk", "student desk 2" … "student desk 6" beside a "teacher desk".
    means("classroom", "move desk 1 left", &[&["student desk"]]);
    means(
        "classroom",
        "move desks 1 and 4 forward",
        &[&["student desk", "student desk 4"]],
    );
    // A range typed as one word.
    means(
        "classroom",
        "move chairs 1-3 left 10 cm",
        &[&["student chair", "student chair 2", "student chair 3"]],
    );
    means(
        "classroom",
        "move desks 3-5 back",
        &[&["student desk 4", "student desk 5", "student desk 3"]],
    );
}

#[test]
fn where_a_thing_is_taken_from_is_what_it_rests_on() {
    // Two tables; the vase and the book rest on the coffee table, the lamp on the side
    // table.
    means(
        "living_room",
        "take the vase off the table",
        &[&["vase"], &["coffee table"]],
    );
    means(
        "living_room",
        "take the table lamp off the table",
        &[&["table lamp"], &["side table"]],
    );
    // "it": the selection, on the coffee table.
    let s = scene("living_room");
    let vase = [s.find("vase").unwrap()];
    let g = Grounder::new(&s)
        .ground_with_selection("take it off the table", &s, &vase)
        .unwrap();
    let table = g.phrases.iter().find(|p| p.text.contains("table")).unwrap();
    assert_eq!(table.objects, [s.find("coffee table").unwrap()]);
    // Resting on neither: still refused.
    refused(
        "living_room",
        "take the sofa off the table",
        &["sofa", "table"],
    );
}

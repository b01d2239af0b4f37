//! Grounding, construct by construct, on the built-in scenes: each test says which objects
//! a phrase must mean, or that it must be refused with its candidates named.

use super::*;
use crate::scene::Scene;

fn scene(name: &str) -> Scene {
    crate::examples::build(name).unwrap()
}

/// The objects of each phrase, by name.
fn g(scene: &Scene, text: &str) -> Result<Vec<Vec<String>>, GroundError> {
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

fn means(scene_name: &str, text: &str, expected: &[&[&str]]) {
    let s = scene(scene_name);
    let got = g(&s, text).unwrap_or_else(|e| panic!("{text}: {e}"));
    let want: Vec<Vec<String>> = expected
        .iter()
        .map(|p| p.iter().map(|n| n.to_string()).collect())
        .collect();
    assert_eq!(got, want, "{text}");
}

fn refused(scene_name: &str, text: &str, mentions: &[&str]) -> String {
    let s = scene(scene_name);
    let e = g(&s, text).map(|p| format!("{p:?}")).unwrap_err();
    let message = e.to_string();
    for m in mentions {
        assert!(message.contains(m), "{text}: {message} should name {m}");
    }
    message
}

#[test]
fn names_as_people_write_them() {
    means("living_room", "move the sofa to the left", &[&["sofa"]]);
    means(
        "living_room",
        "move the Coffee-Table left",
        &[&["coffee table"]],
    );
    means(
        "living_room",
        "move the coffeetable left",
        &[&["coffee table"]],
    );
    means("living_room", "move TV STAND left", &[&["tv stand"]]);
    means("dining_room", "move chair 3 left", &[&["chair 3"]]);
    means("dining_room", "move chair #3 left", &[&["chair 3"]]);
    means("dining_room", "move chair number 3 left", &[&["chair 3"]]);
    means(
        "workshop",
        "put the hammer on the workbench",
        &[&["hammer"], &["workbench"]],
    );
    // Quoted names always win.
    means("living_room", "move the 'sofa' left", &[&["sofa"]]);
}

#[test]
fn synonyms_categories_and_hypernyms() {
    means("living_room", "move the couch left", &[&["sofa"]]);
    means("living_room", "turn the television", &[&["tv"]]);
    means("kitchen", "open the refrigerator", &[&["fridge"]]);
    // A last word of the name: the only lamp of the bedroom is the 'bedside lamp'.
    means("bedroom", "lift the lamp 10 cm", &[&["bedside lamp"]]);
    // A broader category: the living room's only chair is the armchair.
    means("living_room", "move the chair left", &[&["armchair"]]);
    // A literal word of a name beats a synonym: "cup" is the office's coffee cup.
    means("office", "move the cup left", &[&["coffee cup"]]);
}

#[test]
fn containers_are_named_by_what_they_hold() {
    means(
        "bathroom",
        "move the shampoo 10 cm left",
        &[&["shampoo bottle"]],
    );
    means(
        "bathroom",
        "move the soap 10 cm left",
        &[&["soap dispenser"]],
    );
    means(
        "wine_cellar",
        "move the red wine 10 cm left",
        &[&["red wine bottle"]],
    );
    // Not every compound: the living room's 'tv stand' is not "the tv" when a tv exists.
    means("living_room", "move the tv 10 cm left", &[&["tv"]]);
}

#[test]
fn typos_of_long_words_only_when_they_lead_to_one_object() {
    means("living_room", "move the ottomann left", &[&["ottoman"]]);
    means("living_room", "move the bokshelf left", &[&["bookshelf"]]);
    // Short words are not corrected.
    assert!(g(&scene("living_room"), "move the sfa left").is_err());
}

#[test]
fn picking_by_place_size_and_order() {
    means(
        "living_room",
        "move the left speaker right",
        &[&["speaker"]],
    );
    means(
        "living_room",
        "move the right-hand speaker left",
        &[&["speaker 2"]],
    );
    means(
        "living_room",
        "move the speaker on the right back",
        &[&["speaker 2"]],
    );
    means(
        "dining_room",
        "move the front left chair back",
        &[&["chair 3"]],
    );
    means(
        "classroom",
        "turn the second student chair from the right",
        &[&["student chair 2"]],
    );
    means(
        "classroom",
        "move the third student chair from the left",
        &[&["student chair 3"]],
    );
    means(
        "classroom",
        "move the middle student chair back",
        &[&["student chair 2"]],
    );
    means(
        "living_room",
        "move the bigger lamp left",
        &[&["floor lamp"]],
    );
    means(
        "living_room",
        "move the bigger of the two lamps left",
        &[&["floor lamp"]],
    );
    // Equal speakers: "taller" cannot pick; desks in two rows: "third from the left" ties.
    refused(
        "living_room",
        "move the taller speaker",
        &["speaker", "speaker 2"],
    );
    refused(
        "classroom",
        "move the third student desk from the left",
        &["student desk"],
    );
    refused("dining_room", "move the second chair", &["chair"]);
}

#[test]
fn picking_by_relation() {
    // "the lamp on the side table" is the table lamp; "the lamp nearest the sofa" too.
    means(
        "living_room",
        "move the lamp on the side table left",
        &[&["table lamp"]],
    );
    means(
        "living_room",
        "raise the lamp nearest the armchair",
        &[&["floor lamp"]],
    );
    // The four plates stand as far from the candle: nothing to pick.
    refused(
        "dining_room",
        "move the plate closest to the candle left",
        &["plate"],
    );
    means(
        "dining_room",
        "put the chair nearest the plant next to the sideboard",
        &[&["chair 4"], &["sideboard"]],
    );
    // "the painting over the sofa" picks; it never moves the sofa.
    // One book, and the clause goes on ("left"): "on the coffee table" describes it.
    means(
        "living_room",
        "move the book on the coffee table left",
        &[&["book"]],
    );
    // With no amount or place after it, it is where the book goes.
    means(
        "living_room",
        "put the book on the side table",
        &[&["book"], &["side table"]],
    );
    // A description that does not hold is refused.
    refused(
        "living_room",
        "move the book on the side table 10 cm left",
        &["book", "side table"],
    );
}

#[test]
fn a_relation_is_a_destination_when_the_noun_is_already_one_object() {
    // One remote: "on the coffee table" is where it goes, and both are bound.
    means(
        "living_room",
        "put the remote on the side table",
        &[&["remote control"], &["side table"]],
    );
}

#[test]
fn groups_bind_every_member() {
    means(
        "living_room",
        "move both speakers back",
        &[&["speaker", "speaker 2"]],
    );
    means(
        "kitchen",
        "move the two stools left",
        &[&["stool", "stool 2"]],
    );
    means(
        "dining_room",
        "move all the chairs back",
        &[&["chair", "chair 3", "chair 2", "chair 4"]],
    );
    means(
        "dining_room",
        "lift the plates",
        &[&["plate", "plate 3", "plate 2", "plate 4"]],
    );
    refused(
        "dining_room",
        "move the two chairs left",
        &["chair", "chair 2", "chair 3", "chair 4"],
    );
}

#[test]
fn the_other_one() {
    means(
        "living_room",
        "move the left speaker 1 m left and the other one 1 m right",
        &[&["speaker"], &["speaker 2"]],
    );
    means(
        "living_room",
        "move the right speaker back and the other speaker forward",
        &[&["speaker 2"], &["speaker"]],
    );
}

#[test]
fn ambiguity_is_refused_naming_the_candidates() {
    let m = refused(
        "dining_room",
        "move the chair left",
        &["chair", "chair 2", "chair 3", "chair 4"],
    );
    assert!(m.starts_with("\"the chair\" could mean"), "{m}");
    assert!(m.contains("name one ('"), "{m}");
    refused(
        "living_room",
        "move the speaker left",
        &["speaker", "speaker 2"],
    );
    refused(
        "living_room",
        "move the lamp left",
        &["floor lamp", "table lamp"],
    );
    // Two plates at the same x cannot be told apart by "left".
    refused("dining_room", "move the left plate", &["plate"]);
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
fn grammar_words_are_not_objects() {
    // The kitchen has a 'counter'; "counter clockwise" does not name it.
    means(
        "kitchen",
        "turn the kettle counter clockwise",
        &[&["kettle"]],
    );
    // "can you" is not the paint can.
    means("workshop", "can you move the hammer left", &[&["hammer"]]);
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
fn the_left_of_an_object_is_a_place_not_a_pick() {
    means(
        "bedroom",
        "put the laundry basket to the left of the dresser",
        &[&["laundry basket"], &["dresser"]],
    );
}

#[test]
fn amounts_are_not_name_numbers() {
    // "the speaker 2 m" is an amount after an ambiguous phrase, not 'speaker 2'.
    refused(
        "living_room",
        "move the speaker 2 m to the left",
        &["speaker", "speaker 2"],
    );
    means(
        "living_room",
        "move speaker 2 2 m to the left",
        &[&["speaker 2"]],
    );
}

#[test]
fn groups_with_modifiers_keep_the_members_they_name() {
    means(
        "dining_room",
        "move the front chairs 20 cm forward",
        &[&["chair 3", "chair 4"]],
    );
    means(
        "dining_room",
        "move the chairs on the left 20 cm to the left",
        &[&["chair", "chair 3"]],
    );
    means(
        "dining_room",
        "lift all the chairs except the front-left one 10 cm",
        &[&["chair", "chair 2", "chair 4"]],
    );
    means(
        "dining_room",
        "lift every chair but chair 3 10 cm",
        &[&["chair", "chair 2", "chair 4"]],
    );
    refused(
        "dining_room",
        "lift the chairs nearest the sideboard 10 cm",
        &["say how many"],
    );
}

#[test]
fn a_description_of_a_single_object_is_not_a_destination() {
    // The tv is the only tv: "on the tv stand" describes it, and the stand is not bound.
    means(
        "living_room",
        "rotate the tv on the tv stand 30 degrees",
        &[&["tv"]],
    );
    means(
        "bedroom",
        "put the lamp on the other nightstand",
        &[&["bedside lamp"], &["nightstand 2"]],
    );
}

#[test]
fn colours_and_one() {
    let text = r#"{"objects": [
        {"name": "a", "category": "armchair", "color": "red", "size": [1, 1, 1], "position": [-1, 0, 0]},
        {"name": "b", "category": "armchair", "color": "blue", "size": [1, 1, 1], "position": [1, 0, 0]}
    ]}"#;
    let s = crate::format::json::read(text, "t").unwrap().scene;
    assert_eq!(
        g(&s, "move the blue one left").unwrap(),
        vec![vec!["b".to_string()]]
    );
    // "the left one" with nothing before it is not the leftmost object of the scene.
    assert!(g(&s, "move the left one right").is_err());
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
    // Without a selection, "it" alone still names nothing.
    assert!(matches!(
        grounder.ground("turn it 90 degrees", &s),
        Err(GroundError::NoObject { .. })
    ));
}

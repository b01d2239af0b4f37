//! A session's conversation, as a user has it: each kind of follow-up, in place (the CLI's
//! `chat`) and on a working copy (the servers and Python), with the same outcome. Asserts
//! where things end up.

use glam::DVec3;
use shenlong::format::SceneFile;
use shenlong::offline::OfflineTranslator;
use shenlong::pipeline::EditOptions;
use shenlong::session::{EditRequest, ErrorKind, OpError, Outcome, Session};
use std::path::Path;

fn living_room() -> Session {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/living_room.json");
    Session::new(SceneFile::load(&path).unwrap(), None)
}

/// How a front end runs an edit.
#[derive(Clone, Copy, Debug)]
enum Path_ {
    InPlace,
    Working,
}

fn say(session: &mut Session, how: Path_, text: &str) -> Result<Outcome, OpError> {
    let request = EditRequest {
        instruction: text,
        selected: &[],
        report: false,
    };
    let translator = OfflineTranslator::new();
    let options = EditOptions::default();
    match how {
        Path_::InPlace => session.edit(&request, &translator, &options),
        Path_::Working => {
            let pending = session.working().edit(&request, &translator, &options);
            session.conclude(pending)
        }
    }
}

fn at(session: &Session, name: &str) -> DVec3 {
    let scene = &session.file.scene;
    scene.objects[scene.find(name).unwrap()]
        .similarity()
        .translation
}

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).length() < 1e-6
}

const BOTH: [Path_; 2] = [Path_::InPlace, Path_::Working];

#[test]
fn it_means_what_the_last_edit_moved_and_nothing_at_the_start() {
    for how in BOTH {
        let mut s = living_room();
        let e = say(&mut s, how, "move it 10 cm to the right").unwrap_err();
        assert_eq!(e.kind, ErrorKind::NotUnderstood, "{how:?}");
        assert!(e.message.contains("points at nothing"), "{}", e.message);
        let start = at(&s, "armchair");
        say(&mut s, how, "move the armchair 50 cm to the right").unwrap();
        let out = say(&mut s, how, "move it 10 cm to the left").unwrap();
        assert_eq!(out.moved[0].object, "armchair", "{how:?}");
        assert!(close(at(&s, "armchair"), start + DVec3::X * 0.4), "{how:?}");
        let out = say(&mut s, how, "turn that 90 degrees").unwrap();
        assert_eq!(out.moved[0].object, "armchair", "{how:?}");
    }
}

#[test]
fn repeats_and_adjustments_go_along_the_last_motion() {
    for how in BOTH {
        let mut s = living_room();
        let start = at(&s, "armchair");
        say(&mut s, how, "move the armchair 50 cm to the right").unwrap();
        say(&mut s, how, "again").unwrap();
        assert!(close(at(&s, "armchair"), start + DVec3::X), "again {how:?}");
        say(&mut s, how, "not so far").unwrap();
        assert!(
            close(at(&s, "armchair"), start + DVec3::X * 0.75),
            "not so far {how:?}"
        );
        let mut s = living_room();
        say(&mut s, how, "move the armchair 50 cm to the right").unwrap();
        say(&mut s, how, "a bit more").unwrap();
        assert!(
            close(at(&s, "armchair"), start + DVec3::X * 0.6),
            "a bit more {how:?}"
        );
        say(&mut s, how, "twice as far").unwrap();
        assert!(
            close(at(&s, "armchair"), start + DVec3::X * 0.7),
            "twice as far {how:?}"
        );
        say(&mut s, how, "more to the left").unwrap();
        assert!(
            close(at(&s, "armchair"), start + DVec3::X * 0.6),
            "more to the left {how:?}"
        );
    }
}

#[test]
fn corrections_take_the_last_edit_back_and_choose_again() {
    for how in BOTH {
        let mut s = living_room();
        let (left, right) = (at(&s, "speaker"), at(&s, "speaker 2"));
        // After an edit: the other one.
        say(&mut s, how, "move the left speaker 10 cm to the left").unwrap();
        let out = say(&mut s, how, "no, the other one").unwrap();
        assert!(close(at(&s, "speaker"), left), "{how:?}");
        assert!(
            close(at(&s, "speaker 2"), right - DVec3::X * 0.1),
            "{how:?}"
        );
        assert!(out.moved.iter().any(|m| m.object == "speaker"), "{out:?}");
        // After a refusal: the phrase it could not choose for.
        let mut s = living_room();
        let e = say(&mut s, how, "move the speaker 10 cm to the left").unwrap_err();
        assert_eq!(e.kind, ErrorKind::Ambiguous);
        say(&mut s, how, "the left one").unwrap();
        assert!(close(at(&s, "speaker"), left - DVec3::X * 0.1), "{how:?}");
        assert!(close(at(&s, "speaker 2"), right), "{how:?}");
    }
}

#[test]
fn a_correction_of_the_place_puts_it_there_instead() {
    for how in BOTH {
        let mut s = living_room();
        let vase = at(&s, "vase");
        say(&mut s, how, "put the vase on the bookshelf").unwrap();
        say(&mut s, how, "no, on the coffee table").unwrap();
        let scene = &s.file.scene;
        let (v, t) = (
            scene.find("vase").unwrap(),
            scene.find("coffee table").unwrap(),
        );
        assert_eq!(scene.objects[v].support, Some(t), "{how:?}");
        assert!(!close(at(&s, "vase"), vase));
        // One change in the history: the corrected one was taken back.
        assert_eq!(s.history().iter().filter(|h| !h.undone).count(), 1);
    }
}

#[test]
fn the_same_for_another_object() {
    for how in BOTH {
        let mut s = living_room();
        let (ottoman, armchair, lamp) =
            (at(&s, "ottoman"), at(&s, "armchair"), at(&s, "floor lamp"));
        say(&mut s, how, "move the ottoman 30 cm to the right").unwrap();
        say(&mut s, how, "and the armchair too").unwrap();
        say(&mut s, how, "do the same with the floor lamp").unwrap();
        assert!(
            close(at(&s, "ottoman"), ottoman + DVec3::X * 0.3),
            "{how:?}"
        );
        assert!(
            close(at(&s, "armchair"), armchair + DVec3::X * 0.3),
            "{how:?}"
        );
        assert!(
            close(at(&s, "floor lamp"), lamp + DVec3::X * 0.3),
            "{how:?}"
        );
    }
}

#[test]
fn put_back_returns_it_and_what_it_carried() {
    for how in BOTH {
        let mut s = living_room();
        let e = say(&mut s, how, "put the ottoman back").unwrap_err();
        assert!(e.message.contains("has not been moved"), "{}", e.message);
        let (ottoman, magazine, armchair) =
            (at(&s, "ottoman"), at(&s, "magazine"), at(&s, "armchair"));
        say(&mut s, how, "move the ottoman 30 cm to the right").unwrap();
        assert!(!close(at(&s, "magazine"), magazine), "carried");
        say(&mut s, how, "move the armchair 20 cm to the left").unwrap();
        let out = say(&mut s, how, "put the ottoman back where it was").unwrap();
        assert!(close(at(&s, "ottoman"), ottoman), "{how:?}");
        assert!(close(at(&s, "magazine"), magazine), "{how:?}");
        assert!(!close(at(&s, "armchair"), armchair), "the armchair stays");
        assert_eq!(out.moved.len(), 2, "{out:?}");
        let how_moved: Vec<_> = out
            .moved
            .iter()
            .map(|m| (m.object.as_str(), m.how))
            .collect();
        assert_eq!(
            how_moved,
            [
                ("ottoman", shenlong::session::How::Moved),
                ("magazine", shenlong::session::How::Carried)
            ]
        );
        say(&mut s, how, "undo that").unwrap();
        assert!(!close(at(&s, "ottoman"), ottoman), "undone {how:?}");
    }
}

#[test]
fn both_paths_give_the_same_conversation() {
    let turns = [
        "move the armchair 50 cm to the right",
        "a bit more",
        "move the speaker 10 cm to the left",
        "the right one",
        "no, the other one",
        "and the ottoman too",
        "put it back",
        "undo that",
        "put the vase on the bookshelf",
        "no, on the coffee table",
    ];
    let (mut a, mut b) = (living_room(), living_room());
    for turn in turns {
        let x = say(&mut a, Path_::InPlace, turn).map(|o| serde_json::to_value(o).unwrap());
        let y = say(&mut b, Path_::Working, turn).map(|o| serde_json::to_value(o).unwrap());
        assert_eq!(x, y, "{turn}");
    }
}

#[test]
fn follow_ups_said_other_ways() {
    for how in BOTH {
        let mut s = living_room();
        let start = at(&s, "armchair");
        say(&mut s, how, "move the armchair 30 cm to the right").unwrap();
        say(&mut s, how, "another 10 cm").unwrap();
        assert!(close(at(&s, "armchair"), start + DVec3::X * 0.4), "{how:?}");
        say(&mut s, how, "push it a bit further").unwrap();
        assert!(close(at(&s, "armchair"), start + DVec3::X * 0.5), "{how:?}");
        // A bare number in the unit said before; "half as much again" goes on, not back.
        let mut t = living_room();
        say(&mut t, how, "move the armchair 30 cm to the right").unwrap();
        say(&mut t, how, "another 5").unwrap();
        assert!(
            close(at(&t, "armchair"), start + DVec3::X * 0.35),
            "{how:?}"
        );
        say(&mut t, how, "half as much again").unwrap();
        assert!(
            close(at(&t, "armchair"), start + DVec3::X * 0.375),
            "{how:?}"
        );
        // The other speaker too.
        let (left, right) = (at(&s, "speaker"), at(&s, "speaker 2"));
        say(&mut s, how, "move the left speaker 10 cm to the left").unwrap();
        say(&mut s, how, "the other one too").unwrap();
        assert!(close(at(&s, "speaker"), left - DVec3::X * 0.1), "{how:?}");
        assert!(
            close(at(&s, "speaker 2"), right - DVec3::X * 0.1),
            "{how:?}"
        );
        // The other way, and the wrong one of two.
        let mut s = living_room();
        say(&mut s, how, "move the armchair 30 cm to the right").unwrap();
        say(&mut s, how, "no, left").unwrap();
        assert!(close(at(&s, "armchair"), start - DVec3::X * 0.3), "{how:?}");
        // The same again another way: kept, and moved that far that way too.
        say(&mut s, how, "the same again but forward").unwrap();
        assert!(
            close(at(&s, "armchair"), start - DVec3::X * 0.3 + DVec3::Z * 0.3),
            "{how:?}"
        );
        say(&mut s, how, "move the left speaker 10 cm to the left").unwrap();
        say(&mut s, how, "wrong speaker").unwrap();
        assert!(close(at(&s, "speaker"), left), "{how:?}");
        assert!(
            close(at(&s, "speaker 2"), right - DVec3::X * 0.1),
            "{how:?}"
        );
        // A destination alone, after an edit: there instead.
        let mut s = living_room();
        say(&mut s, how, "put the vase on the bookshelf").unwrap();
        say(&mut s, how, "actually, onto the coffee table").unwrap();
        let scene = &s.file.scene;
        let (v, t) = (
            scene.find("vase").unwrap(),
            scene.find("coffee table").unwrap(),
        );
        assert_eq!(scene.objects[v].support, Some(t), "{how:?}");
    }
}

#[test]
fn a_bare_phrase_correcting_an_edit_with_a_destination_is_read_by_kind_and_size() {
    for how in BOTH {
        let mut s = living_room();
        let vase = at(&s, "vase");
        say(&mut s, how, "put the vase on the bookshelf").unwrap();
        let moved = at(&s, "vase");
        // "the side table": neither a vase nor a bookshelf, and furniture as the
        // bookshelf is: the place.
        say(&mut s, how, "no, the coffee table").unwrap();
        let scene = &s.file.scene;
        let (v, t) = (
            scene.find("vase").unwrap(),
            scene.find("coffee table").unwrap(),
        );
        assert_eq!(scene.objects[v].support, Some(t), "{how:?}");
        // "the book": the size of the vase, not of the table: what moves.
        let mut s = living_room();
        let book = at(&s, "book");
        say(&mut s, how, "put the vase on the coffee table").unwrap();
        say(&mut s, how, "no, the book").unwrap();
        assert!(close(at(&s, "vase"), vase), "the vase went back {how:?}");
        assert!(!close(at(&s, "book"), book), "the book moved {how:?}");
        assert!(!close(moved, vase));
    }
}

#[test]
fn several_changes_are_taken_back_together() {
    for how in BOTH {
        let mut s = living_room();
        let e = say(&mut s, how, "undo both").unwrap_err();
        assert!(
            e.message.contains("nothing has been moved"),
            "{}",
            e.message
        );
        let (armchair, ottoman, magazine) =
            (at(&s, "armchair"), at(&s, "ottoman"), at(&s, "magazine"));
        say(&mut s, how, "move the armchair 30 cm to the right").unwrap();
        say(&mut s, how, "move the ottoman 20 cm forward").unwrap();
        let e = say(&mut s, how, "undo the last 3 changes").unwrap_err();
        assert!(e.message.contains("only 2 changes"), "{}", e.message);
        say(&mut s, how, "undo both").unwrap();
        assert!(close(at(&s, "armchair"), armchair), "{how:?}");
        assert!(close(at(&s, "ottoman"), ottoman), "{how:?}");
        assert!(close(at(&s, "magazine"), magazine), "carried {how:?}");
        // Everything, said as a return.
        say(&mut s, how, "move the armchair 30 cm to the right").unwrap();
        say(&mut s, how, "a bit more").unwrap();
        say(&mut s, how, "move the ottoman 20 cm forward").unwrap();
        say(&mut s, how, "put everything back where it was").unwrap();
        assert!(close(at(&s, "armchair"), armchair), "{how:?}");
        assert!(close(at(&s, "ottoman"), ottoman), "{how:?}");
    }
}

#[test]
fn the_other_one_and_both_are_put_back_from_what_the_session_moved() {
    for how in BOTH {
        let mut s = living_room();
        let (armchair, ottoman) = (at(&s, "armchair"), at(&s, "ottoman"));
        say(&mut s, how, "move the armchair 30 cm to the right").unwrap();
        say(&mut s, how, "move the ottoman 20 cm forward").unwrap();
        say(&mut s, how, "put the ottoman back").unwrap();
        assert!(!close(at(&s, "armchair"), armchair), "{how:?}");
        say(&mut s, how, "now put the other one back too").unwrap();
        assert!(close(at(&s, "armchair"), armchair), "{how:?}");
        assert!(close(at(&s, "ottoman"), ottoman), "{how:?}");
        let mut s = living_room();
        say(&mut s, how, "move the armchair 30 cm to the right").unwrap();
        say(&mut s, how, "move the ottoman 20 cm forward").unwrap();
        say(&mut s, how, "put them both back").unwrap();
        assert!(close(at(&s, "armchair"), armchair), "{how:?}");
        assert!(close(at(&s, "ottoman"), ottoman), "{how:?}");
    }
}

#[test]
fn what_is_put_back_onto_something_moved_since_lands_on_it() {
    for how in BOTH {
        let mut s = living_room();
        let (ottoman, magazine) = (at(&s, "ottoman"), at(&s, "magazine"));
        say(&mut s, how, "put the magazine on the sofa").unwrap();
        say(&mut s, how, "move the ottoman 20 cm to the left").unwrap();
        say(&mut s, how, "put the magazine back where it was").unwrap();
        let shift = at(&s, "ottoman") - ottoman;
        assert!(close(shift, DVec3::X * -0.2), "{how:?}");
        assert!(close(at(&s, "magazine"), magazine + shift), "{how:?}");
        let scene = &s.file.scene;
        let (m, o) = (
            scene.find("magazine").unwrap(),
            scene.find("ottoman").unwrap(),
        );
        assert_eq!(scene.objects[m].support, Some(o), "{how:?}");
    }
}

#[test]
fn the_other_table_is_another_destination() {
    for how in BOTH {
        let mut s = living_room();
        say(&mut s, how, "put the book on the tv stand").unwrap();
        let e = say(&mut s, how, "no, the other table").unwrap_err();
        assert!(e.message.contains("went to no table"), "{}", e.message);
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/office.json");
        let mut s = Session::new(SceneFile::load(&path).unwrap(), None);
        say(&mut s, how, "put the coffee cup on the desk 2").unwrap();
        say(&mut s, how, "no, the other desk").unwrap();
        let scene = &s.file.scene;
        let (cup, desk) = (
            scene.find("coffee cup").unwrap(),
            scene.find("desk").unwrap(),
        );
        assert_eq!(scene.objects[cup].support, Some(desk), "{how:?}");
    }
}

#[test]
fn a_way_and_an_amount_alone_move_what_was_moved() {
    for how in BOTH {
        let mut s = living_room();
        let start = at(&s, "armchair");
        say(&mut s, how, "move the armchair 30 cm to the right").unwrap();
        say(&mut s, how, "yes, 10 cm to the left").unwrap();
        assert!(close(at(&s, "armchair"), start + DVec3::X * 0.2), "{how:?}");
        let e = say(&mut s, how, "back a bit").unwrap_err();
        assert!(e.message.contains("two ways"), "{}", e.message);
        // "no, put it back" is a return, never a move backwards.
        say(&mut s, how, "no, put it back").unwrap();
        assert!(close(at(&s, "armchair"), start + DVec3::X * 0.3), "{how:?}");
    }
}

mod any_turns {
    use super::*;
    use proptest::prelude::*;

    const PIECES: [&str; 34] = [
        "move",
        "the",
        "armchair",
        "it",
        "no,",
        "a bit",
        "more",
        "again",
        "put",
        "back",
        "and",
        "too",
        "the other one",
        "on",
        "coffee table",
        "left",
        "undo",
        "that",
        "instead",
        "where it was",
        "20 cm",
        "speaker",
        "twice as far",
        "é\u{130}",
        "both",
        "everything",
        "yes,",
        "not that one",
        "undo the last 3",
        "start over",
        "10cm",
        "1-3",
        "the top shelf of",
        "bookshelf",
    ];

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// Any turns, in any order: an outcome or a refusal, never a panic; a refusal
        /// leaves the scene as it was.
        #[test]
        fn any_conversation_answers_or_refuses(turns in prop::collection::vec(prop::collection::vec(0..PIECES.len(), 1..6), 1..6)) {
            let mut s = living_room();
            for turn in turns {
                let text: Vec<&str> = turn.iter().map(|&k| PIECES[k]).collect();
                let text = text.join(" ");
                let before: Vec<_> = s.file.scene.objects.iter().map(|o| o.similarity()).collect();
                let how = if text.len() % 2 == 0 { Path_::InPlace } else { Path_::Working };
                if say(&mut s, how, &text).is_err() {
                    let after: Vec<_> = s.file.scene.objects.iter().map(|o| o.similarity()).collect();
                    prop_assert_eq!(before, after, "{}", text);
                }
            }
        }
    }

    #[test]
    fn any_text_reads_as_a_follow_up_or_not_without_panicking() {
        for text in [
            "",
            ",",
            "no",
            "no,",
            "back",
            "put back",
            "\u{130}\u{130} back where",
            "and too",
            "instead",
            "not on",
            "another",
            "another 1e999 cm",
            "another -5 cm",
            "5 more",
            "wrong",
            "the other",
        ] {
            let _ = shenlong::session::follow_up::read(text, true);
            let _ = shenlong::session::follow_up::read(text, false);
        }
    }
}

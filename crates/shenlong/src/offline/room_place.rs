//! Reading a place in the room: the floor ("on the floor"), a corner ("into the back left
//! corner", the nearest with no side named), a wall ("against the left wall", the nearest
//! with none), the centre ("to the middle of the kitchen", "centre X1"), and a side of the
//! room ("to the back of the room", "towards the front of the room"). Where they are is
//! written by [`super::room`]; a scene without a room refuses all but the floor.

use super::clause::Clause;
use super::reader::{mark_to_the, Direction, ReadError};
use super::room::{self, Place};
use super::words::{self, Action};
use crate::expr::Expr;

/// A place in the room a clause names.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum RoomPlace {
    /// Down onto the floor, where it is.
    Floor,
    /// The centre, a corner or a wall.
    At(Place),
    /// Towards a side of the room ("towards the back of the room"): [`room::far`].
    Towards(Direction),
    /// To a side of the room ("to the back of the room"): against that wall.
    ToSide(Direction),
    /// Straight out from a wall (the one named, else the nearest) by so many metres.
    AwayFromWall(Option<Direction>, f64),
    /// Mirrored through the room's centre ("to the other side of the room").
    OtherSide,
    /// Towards the room's centre by so many metres, or halfway with no amount ("a bit
    /// towards the middle of the room").
    TowardsCentre(Option<f64>),
    /// Closer to a wall (the one named, else the nearest) by so many metres, or halfway
    /// with no amount ("a bit closer to the back wall").
    CloserToWall(Option<Direction>, Option<f64>),
}

impl RoomPlace {
    /// The translation that takes subject `s`, one of `group` moved there together, there
    /// (`has_room`: whether the scene has room bounds).
    pub(super) fn vector(self, s: usize, group: &[usize], has_room: bool) -> Expr {
        match self {
            Self::Floor => room::onto_floor(s, has_room),
            Self::At(place) => room::place(place, s),
            Self::Towards((e, sign)) => room::far(s, e, sign, true),
            Self::ToSide((e, sign)) => room::all_the_way(s, e, sign),
            Self::AwayFromWall(wall, amount) => room::away_from_wall(s, wall, amount),
            Self::OtherSide => room::other_side_of_room(s),
            Self::TowardsCentre(amount) => room::towards_centre(group, amount),
            Self::CloserToWall(wall, amount) => room::towards_wall(s, wall, amount),
        }
    }
}

/// Room words: `room`, and room types (`bedroom`, `kitchen`): the scene's bounds.
/// Words for the room as a whole (`the middle of the kitchen`).
pub(super) fn is_room_word(w: &str) -> bool {
    matches!(
        w,
        "room"
            | "bedroom"
            | "kitchen"
            | "bathroom"
            | "office"
            | "livingroom"
            | "lounge"
            | "classroom"
            | "workshop"
            | "cellar"
            | "study"
            | "hall"
            | "hallway"
            | "space"
            | "area"
            | "garage"
            | "den"
            | "diningroom"
    )
}

/// Refuses a place in the room in a scene without one.
fn need_room(c: &Clause, has_room: bool) -> Result<(), ReadError> {
    if has_room {
        Ok(())
    } else {
        Err(ReadError::NoRoom(c.text()))
    }
}

/// Marks read the words around a place in the room: room words and the prepositions and
/// articles of "into the far corner of the living room".
fn mark_room_words(c: &mut Clause) {
    for i in 0..c.len() {
        if c.free(i)
            && (c.word(i).is_some_and(is_room_word)
                || matches!(
                    c.word(i),
                    Some(
                        "of" | "in"
                            | "into"
                            | "to"
                            | "the"
                            | "at"
                            | "against"
                            | "up"
                            | "towards"
                            | "toward"
                            | "far"
                            | "very"
                            | "living"
                            | "dining"
                            | "put"
                    )
                ))
        {
            c.mark(i..i + 1);
        }
    }
}

/// "on the floor", "down to the ground".
fn floor(c: &mut Clause) -> Option<RoomPlace> {
    for floor_words in [
        &["on", "the", "floor"][..],
        &["onto", "the", "floor"],
        &["to", "the", "floor"],
        &["on", "the", "ground"],
        &["to", "floor"],
        &["on", "floor"],
        &["onto", "floor"],
        &["to", "the", "ground"],
        &["onto", "the", "ground"],
    ] {
        if let Some(i) = c.find(floor_words) {
            c.mark(i..i + floor_words.len());
            if i > 0 && c.words_at(i - 1, &["down"]) {
                c.mark(i - 1..i);
            }
            return Some(RoomPlace::Floor);
        }
    }
    None
}

/// "into the back left corner", "in a corner" (the nearest along each axis not named).
fn corner(c: &mut Clause, has_room: bool) -> Result<Option<RoomPlace>, ReadError> {
    let Some(i) = c.find(&["corner"]) else {
        return Ok(None);
    };
    need_room(c, has_room)?;
    c.mark(i..i + 1);
    let side = |c: &mut Clause, words: &[&str]| -> bool {
        if let Some(k) = words.iter().find_map(|w| c.find(&[w])) {
            c.mark(k..k + 1);
            true
        } else {
            false
        }
    };
    let x = if side(c, &["left"]) {
        Some(-1.0)
    } else if side(c, &["right"]) {
        Some(1.0)
    } else {
        None
    };
    let z = if side(c, &["back", "rear", "far"]) {
        Some(-1.0)
    } else if side(c, &["front", "near"]) {
        Some(1.0)
    } else {
        None
    };
    mark_room_words(c);
    Ok(Some(RoomPlace::At(Place::Corner(x, z))))
}

/// "centre X1 on (against, along) the left wall", "to the middle of the back wall":
/// against the wall named, centred along it. `None` where no side is named or nothing
/// says centre.
fn wall_centre(
    c: &mut Clause,
    action: Action,
    has_room: bool,
) -> Result<Option<RoomPlace>, ReadError> {
    let Some(i) = c.find(&["wall"]) else {
        return Ok(None);
    };
    let Some((e, sign)) = i
        .checked_sub(1)
        .and_then(|k| c.word(k))
        .and_then(super::words::direction)
        .filter(|&(e, _)| e != 1)
    else {
        return Ok(None);
    };
    // "the middle of the left wall", "the centre of the back wall".
    let of_the = i >= 4
        && c.words_at(i - 3, &["of", "the"])
        && matches!(c.word(i - 4), Some("middle" | "centre" | "center"));
    if !(of_the || action == Action::Centre) {
        return Ok(None);
    }
    need_room(c, has_room)?;
    c.mark(i - 1..i + 1);
    if of_the {
        c.mark(i - 4..i - 1);
    }
    for k in 0..i {
        if c.free(k) && matches!(c.word(k), Some("on" | "along" | "against")) {
            c.mark(k..k + 1);
        }
    }
    mark_room_words(c);
    Ok(Some(RoomPlace::At(Place::WallCentre(e, sign))))
}

/// "against the left wall", "to the wall" (the nearest).
fn wall(c: &mut Clause, has_room: bool) -> Result<Option<RoomPlace>, ReadError> {
    let Some(i) = c.find(&["wall"]).or_else(|| c.find(&["walls"])) else {
        return Ok(None);
    };
    need_room(c, has_room)?;
    c.mark(i..i + 1);
    let side = [
        ("left", (0, -1.0)),
        ("right", (0, 1.0)),
        ("back", (2, -1.0)),
        ("rear", (2, -1.0)),
        ("far", (2, -1.0)),
        ("front", (2, 1.0)),
    ]
    .iter()
    .find_map(|(w, d)| c.find(&[w]).map(|k| (k, *d)));
    if let Some((k, _)) = side {
        c.mark(k..k + 1);
    }
    mark_room_words(c);
    let wall = side.map(|(_, d)| d);
    // "away from the wall", "20 cm away from the left wall", "a bit further from the
    // wall", "out from the wall": straight out from it.
    let away = [
        &["further", "away", "from"][..],
        &["farther", "away", "from"],
        &["away", "from"],
        &["further", "from"],
        &["farther", "from"],
        &["out", "from"],
        &["back", "from"],
    ]
    .iter()
    .find_map(|w| {
        c.find(w)
            .filter(|&a| a < i && c.free(a))
            .map(|a| (a, w.len()))
    });
    // "a bit closer to the back wall", "nearer the wall": part of the way to it.
    let closer = [
        &["closer", "to"][..],
        &["nearer", "to"],
        &["closer"],
        &["nearer"],
    ]
    .iter()
    .find_map(|w| {
        c.find(w)
            .filter(|&a| a < i && c.free(a))
            .map(|a| (a, w.len()))
    });
    if let Some((a, len)) = closer {
        c.mark(a..a + len);
        let amount = match super::amounts::length(c, false) {
            Some(super::amounts::Length::Metres(m)) => Some(m),
            None => None,
            Some(_) => return Err(ReadError::NotALength("closer to a wall")),
        };
        return Ok(Some(RoomPlace::CloserToWall(wall, amount)));
    }
    if let Some((a, len)) = away {
        c.mark(a..a + len);
        let amount = match super::amounts::length(c, false) {
            Some(super::amounts::Length::Metres(m)) => m,
            None => super::amounts::DEFAULT_METRES,
            Some(_) => return Err(ReadError::NotALength("away from a wall")),
        };
        return Ok(Some(RoomPlace::AwayFromWall(wall, amount)));
    }
    Ok(Some(RoomPlace::At(Place::Wall(wall))))
}

/// "to the middle of the room", "centre X1" (the verb says it).
fn centre(c: &mut Clause, action: Action, has_room: bool) -> Result<Option<RoomPlace>, ReadError> {
    let centre_word = ["centre", "center", "middle"]
        .iter()
        .find_map(|w| c.find(&[w]));
    if centre_word.is_none() && action != Action::Centre {
        return Ok(None);
    }
    // "the middle of X3" is an object's middle, not the room's.
    if centre_word.is_some_and(|i| {
        c.words_at(i + 1, &["of"])
            && matches!(c.token(i + 2), Some(super::words::Token::Variable(_)))
    }) {
        return Ok(None);
    }
    need_room(c, has_room)?;
    // "towards the middle of the room" goes part of the way: the amount said, else half.
    let towards = centre_word.filter(|&i| {
        i >= 2 && (c.words_at(i - 2, &["towards", "the"]) || c.words_at(i - 2, &["toward", "the"]))
    });
    if let Some(i) = centre_word {
        c.mark(i..i + 1);
    }
    mark_room_words(c);
    if towards.is_some() {
        let amount = match super::amounts::length(c, false) {
            Some(super::amounts::Length::Metres(m)) => Some(m),
            None => None,
            Some(_) => return Err(ReadError::NotALength("towards the middle of the room")),
        };
        return Ok(Some(RoomPlace::TowardsCentre(amount)));
    }
    Ok(Some(RoomPlace::At(Place::Centre)))
}

/// "to the other side of the room", "across the room": mirrored through its centre.
fn other_side(c: &mut Clause, has_room: bool) -> Result<Option<RoomPlace>, ReadError> {
    for i in 0..c.len() {
        let other_side = c.words_at(i, &["the", "other", "side", "of", "the"])
            && c.word(i + 5).is_some_and(is_room_word);
        let across = c.words_at(i, &["across", "the"]) && c.word(i + 2).is_some_and(is_room_word);
        if other_side || across {
            need_room(c, has_room)?;
            let end = if other_side { i + 6 } else { i + 3 };
            c.mark(i..end);
            if i > 0 && (c.words_at(i - 1, &["on"]) || c.words_at(i - 1, &["over"])) {
                c.mark(i - 1..i);
            }
            mark_to_the(c, i);
            return Ok(Some(RoomPlace::OtherSide));
        }
    }
    Ok(None)
}

/// "towards the back of the room" (a way towards that wall), "to the front of the room"
/// (against it).
fn side_of_room(c: &mut Clause, has_room: bool) -> Result<Option<RoomPlace>, ReadError> {
    for (i, w) in (0..c.len()).filter_map(|i| c.word(i).map(|w| (i, w.to_string()))) {
        if let Some(d) = words::direction(&w) {
            let of_room =
                c.words_at(i + 1, &["of", "the"]) && c.word(i + 3).is_some_and(is_room_word);
            if of_room && c.free(i) {
                need_room(c, has_room)?;
                let towards = i >= 2
                    && (c.words_at(i - 2, &["towards", "the"])
                        || c.words_at(i - 2, &["toward", "the"]));
                c.mark(i..i + 4);
                mark_to_the(c, i);
                return Ok(Some(if towards {
                    RoomPlace::Towards(d)
                } else {
                    RoomPlace::ToSide(d)
                }));
            }
        }
    }
    Ok(None)
}

/// The room's centre, corners, walls, the floor, or its front/back ("towards the back of
/// the room") the clause names, its words read; `Ok(None)` when it names none.
///
/// # Errors
/// A place other than the floor in a scene without a room.
pub(super) fn room_place(
    c: &mut Clause,
    action: Action,
    has_room: bool,
) -> Result<Option<RoomPlace>, ReadError> {
    if let Some(place) = floor(c) {
        return Ok(Some(place));
    }
    if let Some(place) = other_side(c, has_room)? {
        return Ok(Some(place));
    }
    if let Some(place) = corner(c, has_room)? {
        return Ok(Some(place));
    }
    if let Some(place) = wall_centre(c, action, has_room)? {
        return Ok(Some(place));
    }
    if let Some(place) = wall(c, has_room)? {
        return Ok(Some(place));
    }
    if let Some(place) = centre(c, action, has_room)? {
        return Ok(Some(place));
    }
    side_of_room(c, has_room)
}

#[cfg(test)]
mod tests {
    use super::super::testing::{close, moves, on, outcome, standing, ROOM};

    #[test]
    fn corners_walls_and_the_centre() {
        // X1 0.4 wide and deep, right of the room's centre (x 0.8 … 1.2) and a little in
        // front of it (z 0.1 … 0.5).
        let boxes = [standing([0.4, 0.5, 0.4], 1.0, 0.3)];
        let m = |q: &str| moves(q, &boxes)[0];
        let (min, max) = ROOM;
        // The back left corner: its left face on the left wall, its back on the back one.
        assert!(close(
            m("push X1 into the back left corner"),
            [min[0] - 0.8, 0.0, min[2] - 0.1]
        ));
        // The nearest corner: right and front.
        assert!(close(
            m("move X1 into the corner"),
            [max[0] - 1.2, 0.0, max[2] - 0.5]
        ));
        assert!(close(
            m("put X1 against the left wall"),
            [min[0] - 0.8, 0.0, 0.0]
        ));
        // The nearest wall: the right one (2 m from its centre; the front is 2.2 m).
        assert!(close(
            m("put X1 against the wall"),
            [max[0] - 1.2, 0.0, 0.0]
        ));
        assert!(close(m("centre X1 in the room"), [-1.0, 0.0, -0.3]));
        // The other side: mirrored along x, where it stands furthest out (x 1.0 of a
        // half width, z 0.3).
        assert!(close(
            m("move X1 to the other side of the room"),
            [-2.0, 0.0, 0.0]
        ));
        assert!(close(m("move X1 across the room"), [-2.0, 0.0, 0.0]));
        assert!(close(
            m("move X1 to the middle of the kitchen"),
            [-1.0, 0.0, -0.3]
        ));
    }

    #[test]
    fn the_floor_and_the_sides_of_the_room() {
        let boxes = [on([0.2, 0.3, 0.2], 0.0, 0.75, 0.0)];
        let m = |q: &str| moves(q, &boxes)[0];
        assert!(close(m("put X1 on the floor"), [0.0, -0.75, 0.0]));
        // Against the back wall, and 1 m towards it (FAR_METRES, the wall is further).
        assert!(close(
            m("move X1 to the back of the room"),
            [0.0, 0.0, ROOM.0[2] + 0.1]
        ));
        assert!(close(
            m("move X1 towards the back of the room"),
            [0.0, 0.0, -1.0]
        ));
    }

    #[test]
    fn without_a_room_only_the_floor_is_a_place() {
        let boxes = [on([0.2, 0.3, 0.2], 0.0, 0.75, 0.0)];
        let down = outcome("put X1 on the floor", &boxes, false).unwrap();
        assert!(close(down[0].translation, [0.0, -0.75, 0.0]));
        let refused = outcome("move X1 to the left wall", &boxes, false).unwrap_err();
        assert!(refused.contains("no room"), "{refused}");
    }
}

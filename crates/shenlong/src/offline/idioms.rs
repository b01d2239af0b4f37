//! Idioms: phrases people use that say what another construct of the reader says, read
//! as that construct before the clause is read (the words are kept, so what the reader
//! could not read is still quoted as typed).
//!
//! | written | read as |
//! |---|---|
//! | `30 cm towards the back wall`, `half a metre toward the front of the room`, `towards the right wall until it hits something` | `30 cm back`, `half a metre forward`, `right until it hits something` (an amount along the direction of that wall) |
//! | `all the way to X2`, `all the way up to X2`, `right up to X2`, `up to X2` | straight toward X2 until 5 cm from it (`upto X2`) |
//! | `flush against the left wall`, `flush with X2` | `against …` |
//! | `right up against X2` | `up against X2` (`right` says how close, not where) |
//! | `until it touches X2`, `until it's flush against X2`, `till it hits X2`, `until they meet X2` | `against X2` (with a direction before it: along that direction, checked) |
//! | `forward till it hits the wall`, `till it reaches the back wall` | `all the way forward`, `all the way back` |
//! | `all the way to the left wall`, `all the way back to the wall` | `against the left wall`, `against the back wall` |
//! | `point X1 at X2`, `aim X1 at X2`, `so it points at X2`, `pointing towards X2` | `turn X1 face X2`, `so it faces X2`, `facing X2` |
//! | `X1 needs to go 2 feet left`, `X1 should be moved …`, `X1 has to move …`, `X1 should be 1 m to the left`, `could X1 go …`, `can X1 be moved …` | `X1 2 feet left` (a move: the objects named, then where) |
//! | `pull X1 out from X2`, `out from under X2` | `away from X2` |
//! | `in the middle of X2`, `to the centre of X2`, `onto the center of X2` | `on X2` (on its top, centred: a rug's middle is on the rug) |
//! | `in the middle of X2 and X3` | `between X2 and X3` |
//! | `somewhere on X2`, `somewhere near X2` | `on X2`, `near X2` |
//! | `to the other end of X2`, `at the far end of X2` | `to the other side of X2` (mirrored through its centre: on a counter, its other end) |
//! | `put X1 and X2 next to each other`, `… side by side`, `… beside each other`, `… together` | `put X2 next to X1` (the first stays) |
//! | `on the top shelf of X2`, `onto the bottom shelf of X2`, `on the second shelf from the top of X2`, `in the middle shelf of X2` | `in X2`, on that shelf |

use super::amounts;
use super::clause::Clause;
use super::room_place::is_room_word;

/// The side of a room a word names, as the direction word the reader knows.
fn side_direction(w: &str) -> Option<&'static str> {
    Some(match w {
        "left" => "left",
        "right" => "right",
        "back" | "rear" | "far" => "back",
        "front" | "near" => "forward",
        _ => return None,
    })
}

/// Reads the clause's idioms as the constructs they stand for.
pub(crate) fn rewrite(c: &mut Clause) {
    towards_a_wall_by_an_amount(c);
    all_the_way_to_a_wall(c);
    right_up_against(c);
    until_touching(c);
    pointing(c);
    keep_facing(c);
    so_that_it_is(c);
    well_away(c);
    from_its_ends(c);
    middle_of_an_object(c);
    somewhere(c);
    each_other(c);
    other_end(c);
    needs_to_go(c);
    passive(c);
    all_the_way_to(c);
    flush(c);
    out_from(c);
    from_where_it_is(c);
    edge_of(c);
    shelf_of(c);
    particle_first(c);
    back_onto(c);
}

/// "Back" between putting something and where it goes says it was there before, not a
/// way: `put X1 back on X2`, `set X1 and X2 back in X3` → `put X1 on X2`.
fn back_onto(c: &mut Clause) {
    use super::words::Token;
    for i in 0..c.len() {
        if !one_of(
            c,
            i,
            &["put", "place", "set", "stick", "pop", "return", "get"],
        ) {
            continue;
        }
        let mut end = i + 1;
        while matches!(c.token(end), Some(Token::Variable(_)))
            || (c.words_at(end, &["and"]) && matches!(c.token(end + 1), Some(Token::Variable(_))))
        {
            end += 1;
        }
        let place = [
            "on",
            "onto",
            "in",
            "into",
            "inside",
            "under",
            "underneath",
            "beneath",
            "next",
            "beside",
            "against",
            "by",
            "near",
            "atop",
        ];
        if end > i + 1 && c.words_at(end, &["back"]) && c.free(end) && one_of(c, end + 1, &place) {
            c.mark(end..end + 1);
            return;
        }
    }
}

/// The particle said before what it moves: `push in X1`, `tuck in X1 and X2`, `pull out
/// X1` → `push X1 in`, … (the objects, then the particle, as the reader of pushing in
/// reads them).
fn particle_first(c: &mut Clause) {
    use super::words::Token;
    for i in 0..c.len() {
        let verb = one_of(
            c,
            i,
            &["push", "tuck", "pull", "slide", "scoot", "shove", "draw"],
        );
        if !verb || !one_of(c, i + 1, &["in", "out"]) {
            continue;
        }
        // The objects after it: variables joined by "and".
        let mut end = i + 2;
        while matches!(c.token(end), Some(Token::Variable(_)))
            || (c.words_at(end, &["and"]) && matches!(c.token(end + 1), Some(Token::Variable(_))))
        {
            end += 1;
        }
        if end == i + 2 {
            continue;
        }
        let Some(particle) = c.token(i + 1).cloned() else {
            continue;
        };
        for k in i + 1..end - 1 {
            if let Some(next) = c.token(k + 1).cloned() {
                c.set(k, next);
            }
        }
        c.set(end - 1, particle);
        return;
    }
}

/// A shelf of what things go in: `on the top shelf of X2`, `onto the lowest shelf of X2`,
/// `on the second shelf from the top of X2`, `on the bottom shelf in X2` → `in X2` with the
/// shelf kept
/// ([`Clause::shelf`]). "The second shelf" alone does not say from where: not read.
fn shelf_of(c: &mut Clause) {
    use crate::scene::form::Shelf;
    let is_var =
        |c: &Clause, k: usize| matches!(c.token(k), Some(super::words::Token::Variable(_)));
    // A count from one end ("second"), not "last".
    let ordinal = |w: &str| crate::ground::words::ordinal(w).filter(|&k| k != usize::MAX);
    for i in 0..c.len() {
        if !one_of(c, i, &["on", "onto", "in", "into", "to"]) || !c.words_at_any(i + 1, &["the"]) {
            continue;
        }
        let Some(w) = c.word(i + 2).filter(|_| c.free(i + 2)) else {
            continue;
        };
        // "the top shelf of X2", "the second shelf from the top of X2", "the second
        // highest shelf of X2".
        let (shelf, of) = match (w, c.word(i + 3)) {
            ("top" | "highest" | "uppermost" | "upper", Some("shelf")) => (Shelf::Top, i + 4),
            ("bottom" | "lowest" | "lower", Some("shelf")) => (Shelf::Bottom, i + 4),
            ("middle" | "centre" | "center", Some("shelf")) => (Shelf::Middle, i + 4),
            (_, Some("highest" | "top")) if c.words_at(i + 4, &["shelf"]) => {
                let Some(k) = ordinal(w) else { continue };
                (Shelf::FromTop(k), i + 5)
            }
            (_, Some("lowest" | "bottom")) if c.words_at(i + 4, &["shelf"]) => {
                let Some(k) = ordinal(w) else { continue };
                (Shelf::FromBottom(k), i + 5)
            }
            (_, Some("shelf")) if c.words_at_any(i + 4, &["from", "the"]) => {
                let Some(k) = ordinal(w) else { continue };
                match c.word(i + 6) {
                    Some("top") => (Shelf::FromTop(k), i + 7),
                    Some("bottom") => (Shelf::FromBottom(k), i + 7),
                    _ => continue,
                }
            }
            _ => continue,
        };
        // "… of X2", "… in X2".
        if !one_of(c, of, &["of", "in", "on"]) || !is_var(c, of + 1) {
            continue;
        }
        c.mark(i..of);
        c.replace(of, "in");
        c.shelf = Some(shelf);
        return;
    }
    any_shelf_of(c);
}

/// A shelf, not said which, of what things go in: `on X2's shelf`, `on the X2 shelves`
/// (X2 a bookcase), `on a shelf in X2`, `on one of the shelves of X2`, `on one of X2
/// shelves` → `in X2`: its lowest shelf with room.
fn any_shelf_of(c: &mut Clause) {
    let is_var =
        |c: &Clause, k: usize| matches!(c.token(k), Some(super::words::Token::Variable(_)));
    let shelf =
        |c: &Clause, k: usize| c.words_at_any(k, &["shelf"]) || c.words_at_any(k, &["shelves"]);
    for i in 0..c.len() {
        if !one_of(c, i, &["on", "onto", "in", "into"]) {
            continue;
        }
        // "on X2 shelf", "on X2's shelves": the word after the target.
        let mut k = i + 1;
        if c.words_at_any(k, &["one", "of"]) {
            k += 2;
        }
        if c.words_at_any(k, &["the"]) || c.words_at_any(k, &["a"]) {
            k += 1;
        }
        if is_var(c, k) && (shelf(c, k + 1) || (c.words_at_any(k + 1, &["s"]) && shelf(c, k + 2))) {
            let end = if shelf(c, k + 1) { k + 2 } else { k + 3 };
            c.mark(i + 1..k);
            c.mark(k + 1..end);
            c.replace(i, "in");
            return;
        }
        // "on a shelf in X2", "on one of the shelves of X2".
        if shelf(c, k) && one_of(c, k + 1, &["in", "of", "on"]) && is_var(c, k + 2) {
            c.mark(i..k + 1);
            c.replace(k + 1, "in");
            return;
        }
    }
}

/// The edge of an object is its end: `to the left edge of X2` → `to the left end of X2`;
/// `a bit towards the front edge (end) of X2` is that way: `a bit forward` (X2 read).
fn edge_of(c: &mut Clause) {
    let is_var =
        |c: &Clause, k: usize| matches!(c.token(k), Some(super::words::Token::Variable(_)));
    for i in 0..c.len() {
        let side = c.word(i + 2).and_then(|w| {
            super::words::direction(w)
                .filter(|&(e, _)| e != 1)
                .map(|_| w.to_string())
                .or_else(|| (w == "far").then(|| "back".to_string()))
        });
        let Some(side) = side else { continue };
        if !(c.words_at(i + 1, &["the"])
            && one_of(c, i + 3, &["edge", "end"])
            && c.words_at(i + 4, &["of"])
            && is_var(c, i + 5))
        {
            continue;
        }
        if one_of(c, i, &["towards", "toward"]) {
            c.mark(i..i + 2);
            c.set(i + 2, super::words::Token::Word(side));
            c.mark(i + 3..i + 6);
            return;
        }
        if one_of(c, i, &["to", "at", "on", "by"]) && c.words_at(i + 3, &["edge"]) {
            c.replace(i + 3, "end");
            return;
        }
    }
}

/// "10 cm to the left of where it is (now)", "… from where it is", "… from its current
/// position": where a shift starts from is where the object is; the words are read.
fn from_where_it_is(c: &mut Clause) {
    const TAILS: [&[&str]; 8] = [
        &["of", "where", "it", "is", "now"],
        &["of", "where", "it", "is"],
        &["from", "where", "it", "is", "now"],
        &["from", "where", "it", "is"],
        &["of", "where", "they", "are"],
        &["from", "where", "they", "are"],
        &["from", "its", "current", "position"],
        &["from", "their", "current", "positions"],
    ];
    for i in 1..c.len() {
        let after_direction = c
            .word(i - 1)
            .is_some_and(|w| super::words::direction(w).is_some());
        if !after_direction {
            continue;
        }
        if let Some(words) = TAILS.iter().find(|w| c.words_at(i, w)) {
            c.mark(i..i + words.len());
            return;
        }
    }
}

/// `AMOUNT towards the SIDE wall` / `… of the room` → `AMOUNT SIDE`.
fn towards_a_wall_by_an_amount(c: &mut Clause) {
    let has_amount = {
        let mut probe = c.clone();
        matches!(
            amounts::length(&mut probe, false),
            Some(amounts::Length::Metres(_) | amounts::Length::UntilBlocked)
        )
    };
    if !has_amount {
        return;
    }
    for i in 0..c.len() {
        if !(c.words_at(i, &["towards"]) || c.words_at(i, &["toward"])) {
            continue;
        }
        let mut k = i + 1;
        if c.words_at(k, &["the"]) {
            k += 1;
        }
        let Some(direction) = c.word(k).and_then(side_direction) else {
            continue;
        };
        let rest = if c.words_at(k + 1, &["wall"]) {
            1
        } else if c.words_at(k + 1, &["of", "the"]) && c.word(k + 3).is_some_and(is_room_word) {
            3
        } else if c.words_at(k + 1, &["side", "of", "the"])
            && c.word(k + 4).is_some_and(is_room_word)
        {
            4
        } else {
            continue;
        };
        c.mark(i..k);
        c.replace(k, direction);
        c.mark(k + 1..k + 1 + rest);
        return;
    }
}

/// `all the way (up) to X2`, `right up to X2`, `up to X2` → `upto X2`: straight toward
/// it until 5 cm from it.
fn all_the_way_to(c: &mut Clause) {
    for (words, to) in [
        (&["all", "the", "way", "up", "to"][..], 4),
        (&["all", "the", "way", "over", "to"], 4),
        (&["all", "the", "way", "to"], 3),
        (&["right", "up", "to"], 2),
        (&["up", "to"], 1),
    ] {
        if let Some(i) = c.find(words) {
            let target = i + words.len();
            let article = usize::from(c.words_at(target, &["the"]));
            if matches!(
                c.token(target + article),
                Some(super::words::Token::Variable(_))
            ) {
                c.mark(i..i + to);
                c.replace(i + to, "upto");
                return;
            }
        }
    }
}

/// `flush against …`, `flush with …`, `flush to …` → `against …`.
fn flush(c: &mut Clause) {
    if let Some(i) = c.find(&["flush"]) {
        if c.words_at(i + 1, &["against"]) {
            c.mark(i..i + 1);
        } else if c.words_at(i + 1, &["with"]) || c.words_at(i + 1, &["to"]) {
            c.mark(i..i + 1);
            c.replace(i + 1, "against");
        }
    }
}

/// `out from X2`, `out from under X2` → `away from X2`.
fn out_from(c: &mut Clause) {
    for words in [&["out", "from", "under"][..], &["out", "from"]] {
        if let Some(i) = c.find(words) {
            c.replace(i, "away");
            c.mark(i + 2..i + words.len());
            return;
        }
    }
}

/// Whether one of `options` stands unread at `k`.
fn one_of(c: &Clause, k: usize, options: &[&str]) -> bool {
    options.iter().any(|w| c.words_at(k, &[w]))
}

/// `all the way (DIR) to the (SIDE) wall` → `against the SIDE wall`, the side from the
/// direction where the wall has none (`all the way back to the wall`).
fn all_the_way_to_a_wall(c: &mut Clause) {
    let Some(i) = c.find(&["all", "the", "way"]) else {
        return;
    };
    let mut k = i + 3;
    let direction = c.word(k).and_then(side_direction);
    if direction.is_some() || c.words_at(k, &["over"]) || c.words_at(k, &["across"]) {
        k += 1;
    }
    if !c.words_at(k, &["to", "the"]) {
        return;
    }
    let side = c.word(k + 2).and_then(side_direction);
    let wall = if side.is_some() { k + 3 } else { k + 2 };
    if !c.words_at(wall, &["wall"]) {
        return;
    }
    let Some(side) = side.or(direction) else {
        return;
    };
    // The words become `against the SIDE wall` in the last four places before `wall`'s
    // end; the rest is read.
    c.mark(i..wall - 3);
    for (at, word) in [(wall - 3, "against"), (wall - 2, "the"), (wall - 1, side)] {
        c.replace(at, word);
    }
}

/// `right up against X2` → `up against X2`.
fn right_up_against(c: &mut Clause) {
    if let Some(i) = c.find(&["right", "up", "against"]) {
        c.mark(i..i + 1);
    }
}

/// `until it touches X2`, `until it's flush against X2`, `till it hits X2` → `against X2`.
fn until_touching(c: &mut Clause) {
    let Some(i) = (0..c.len()).find(|&i| one_of(c, i, &["until", "till", "til"])) else {
        return;
    };
    let mut k = i + 1;
    if one_of(c, k, &["it", "they"]) {
        k += 1;
        if one_of(c, k, &["is", "are"]) {
            k += 1;
        }
    } else if one_of(c, k, &["it's", "its", "they're"]) {
        k += 1;
    }
    if c.words_at(k, &["flush"]) {
        k += 1;
    }
    let touching = [
        "against", "touches", "touching", "touch", "hits", "reaches", "meets", "with",
    ];
    if k == i + 1 || !one_of(c, k, &touching) {
        return;
    }
    let article = usize::from(c.words_at(k + 1, &["the"]));
    let target = k + 1 + article;
    if matches!(c.token(target), Some(super::words::Token::Variable(_))) {
        c.mark(i..k);
        c.replace(k, "against");
        return;
    }
    // "push X1 forward till it hits the wall" (or "the back wall"): all the way that way.
    let side = c.word(target).and_then(side_direction);
    let wall = target + usize::from(side.is_some());
    if c.words_at(wall, &["wall"]) && k >= i + 2 {
        c.mark(i..k - 2);
        for (at, word) in [(k - 2, "all"), (k - 1, "the"), (k, "way")] {
            c.replace(at, word);
        }
        c.mark(k + 1..target);
        if let Some(side) = side {
            c.replace(target, side);
        }
        c.mark(wall..wall + 1);
    }
}

/// The middle of an object is on it, centred: `in the middle of X2` → `on X2` (and the
/// middle of two objects is between them: `in the middle of X2 and X3` → `between X2 and
/// X3`); towards the middle of an object is towards it. The room's middle ("the middle of
/// the room") is another place, read elsewhere.
fn middle_of_an_object(c: &mut Clause) {
    let is_var =
        |c: &Clause, k: usize| matches!(c.token(k), Some(super::words::Token::Variable(_)));
    for i in 0..c.len() {
        if !one_of(c, i, &["in", "to", "into", "at", "onto"])
            || !c.words_at(i + 1, &["the"])
            || !one_of(c, i + 2, &["middle", "centre", "center"])
            || !c.words_at(i + 3, &["of"])
            || !is_var(c, i + 4)
        {
            continue;
        }
        let two = c.words_at(i + 5, &["and"]) && is_var(c, i + 6);
        // The word before the target says it; the words before it are read.
        c.mark(i..i + 3);
        c.replace(i + 3, if two { "between" } else { "on" });
        return;
    }
    // "so it's centred on X2": on X2 is centred on it.
    for i in 0..c.len() {
        if one_of(c, i, &["centred", "centered", "centre", "center"])
            && one_of(c, i + 1, &["on", "over"])
            && is_var(c, i + 2)
        {
            c.mark(i..i + 1);
        }
    }
    // "towards the middle of X2" (of one object) is towards X2: its centre is what
    // "towards" aims at anyway.
    for i in 0..c.len() {
        if one_of(c, i, &["towards", "toward"])
            && c.words_at(i + 1, &["the"])
            && one_of(c, i + 2, &["middle", "centre", "center"])
            && c.words_at(i + 3, &["of"])
            && is_var(c, i + 4)
            && !(c.words_at(i + 5, &["and"]) && is_var(c, i + 6))
        {
            c.mark(i + 1..i + 4);
            return;
        }
    }
}

/// `somewhere on X2`, `somewhere near X2`: the place the relation gives (where it fits
/// best) is somewhere; the word is read.
fn somewhere(c: &mut Clause) {
    for i in 0..c.len() {
        if c.words_at(i, &["somewhere"])
            && one_of(
                c,
                i + 1,
                &[
                    "on", "onto", "in", "near", "next", "by", "beside", "under", "against",
                ],
            )
        {
            c.mark(i..i + 1);
            return;
        }
    }
}

/// Two objects next to each other: `X1 and X2 next to each other` (`side by side`,
/// `beside each other`, `together`) → `X2 next to X1`, the first staying where it is.
fn each_other(c: &mut Clause) {
    use super::words::Token;
    const TOGETHER: [&[&str]; 5] = [
        &["next", "to", "each", "other"],
        &["beside", "each", "other"],
        &["side", "by", "side"],
        &["alongside", "each", "other"],
        &["together"],
    ];
    for a in 0..c.len() {
        let (Some(&Token::Variable(first)), Some(&Token::Variable(second))) =
            (c.token(a), c.token(a + 2))
        else {
            continue;
        };
        if !c.words_at(a + 1, &["and"]) || matches!(c.token(a + 3), Some(Token::Variable(_))) {
            continue;
        }
        let Some(words) = TOGETHER.iter().find(|w| c.words_at(a + 3, w)) else {
            continue;
        };
        let end = a + 3 + words.len();
        // Only the two: not a list of three, nor two after another object.
        if a > 0 && matches!(c.token(a - 1), Some(Token::Variable(_))) {
            continue;
        }
        // "move X1 and X2 together 50 cm left": as one, by the amount that follows.
        let moved_as_one = words.len() == 1
            && (matches!(c.token(end), Some(Token::Number(_)))
                || c.word(end)
                    .is_some_and(|w| super::words::direction(w).is_some() || w == "by"));
        if moved_as_one {
            c.mark(a + 3..end);
            return;
        }
        c.set(a, Token::Variable(second));
        c.set(a + 1, Token::Word("next".into()));
        c.set(a + 2, Token::Word("to".into()));
        c.set(a + 3, Token::Variable(first));
        c.mark(a + 4..end);
        return;
    }
}

/// `to the other end of X2` (`the far end of X2`): the other side of it, mirrored through
/// its centre along the axis the object stands furthest out on — on a counter, its other
/// end, on its top.
fn other_end(c: &mut Clause) {
    for i in 0..c.len() {
        if one_of(c, i, &["other", "far", "opposite"])
            && c.words_at(i + 1, &["end", "of"])
            && matches!(c.token(i + 3), Some(super::words::Token::Variable(_)))
        {
            c.replace(i, "other");
            c.replace(i + 1, "side");
            // "at the far end of X2" is where it goes: "to".
            if i >= 2 && c.words_at(i - 2, &["at", "the"]) {
                c.replace(i - 2, "to");
            }
            return;
        }
    }
}

/// Pointing is facing: `point X1 at X2` / `aim X1 towards X2` / `face X1 to X2` / `orient
/// X1 toward X2` → `turn X1 face X2`; `points at`, `pointing at`, `point at` → `faces`,
/// `facing`, `face`.
fn pointing(c: &mut Clause) {
    for i in 0..c.len() {
        let Some(w) = c.word(i).filter(|_| c.free(i)) else {
            continue;
        };
        let facing = match w {
            "point" | "aim" | "face" | "orient" | "angle" => "face",
            "points" | "aims" => "faces",
            "pointing" | "aiming" | "pointed" | "aimed" => "facing",
            _ => continue,
        };
        // A verb of facing takes its target after "to" too ("face the chair to the tv").
        let at: &[&str] = if matches!(w, "face" | "orient" | "angle") {
            &["at", "towards", "toward", "to"]
        } else {
            &["at", "towards", "toward"]
        };
        // (Only a pointing word says "points at X2": "at an angle to X2" is no facing.)
        if !matches!(w, "face" | "orient" | "angle") && one_of(c, i + 1, at) {
            // `faces at X2` reads as `faces the X2`: the article is what the reader of
            // facing skips before its target.
            c.replace(i, facing);
            c.replace(i + 1, "the");
            return;
        }
        // "point X1 (and X2) at X2": the verb, its objects, then where.
        let mut k = i + 1;
        while matches!(c.token(k), Some(super::words::Token::Variable(_)))
            || c.words_at(k, &["and"])
        {
            k += 1;
        }
        // (The verb first: only discourse read before it.)
        let first = (0..i).all(|j| !c.free(j));
        if k > i + 1 && first && one_of(c, k, at) {
            c.replace(i, "turn");
            c.replace(k, "face");
            return;
        }
    }
}

/// A facing to keep after a move is a turn to face, square on to the target's nearest
/// side ([`Clause::keep_facing`]): `keep X1 facing X2` / `keep it facing X2` (`them`, `both`)
/// → `turn X1 face X2` (after `pointing`: `keep it pointed at X2` too). Only with the
/// clause's first words: "keep" elsewhere is not read.
fn keep_facing(c: &mut Clause) {
    let Some(i) = (0..c.len()).find(|&i| c.free(i)) else {
        return;
    };
    if !c.words_at(i, &["keep"]) {
        return;
    }
    let mut k = i + 1;
    while matches!(c.token(k), Some(super::words::Token::Variable(_)))
        || matches!(c.word(k), Some("it" | "them" | "both" | "and"))
    {
        k += 1;
    }
    if k > i + 1 && c.word(k) == Some("facing") {
        c.replace(i, "turn");
        c.replace(k, "face");
        c.keep_facing = true;
    }
}

/// Where a move is to leave its objects said as a purpose: `move X1 so it sits between
/// X2 and X3`, `… so that they are next to X2`, `… so it's behind X2` → `move X1 between
/// X2 and X3`: "so (that) it sits" read, the place left for the move's reader. Only before
/// a place ([`where_to_be`], or `behind`, `in front of`).
fn so_that_it_is(c: &mut Clause) {
    for i in 0..c.len() {
        if !c.words_at(i, &["so"]) {
            continue;
        }
        let mut k = i + 1;
        if c.words_at(k, &["that"]) {
            k += 1;
        }
        let fused = one_of(c, k, &["it's", "they're"]);
        let subject = fused
            || one_of(c, k, &["it", "they"])
            || matches!(c.token(k), Some(super::words::Token::Variable(_)));
        if !subject {
            continue;
        }
        k += 1;
        if !fused {
            if one_of(c, k, &["ends", "end"]) && c.words_at(k + 1, &["up"]) {
                k += 2;
            } else if one_of(
                c,
                k,
                &[
                    "sits", "sit", "is", "are", "stands", "stand", "rests", "lies",
                ],
            ) {
                k += 1;
            } else {
                continue;
            }
        }
        let mut place = k;
        while one_of(c, place, &["directly", "right", "just", "exactly"]) {
            place += 1;
        }
        let placed = where_to_be(c, place)
            || one_of(c, place, &["behind"])
            || c.words_at(place, &["in", "front", "of"]);
        if placed && (i..k).all(|j| c.free(j)) {
            c.mark(i..k);
            return;
        }
    }
}

/// "pull X1 well away from the wall", "well clear of X2": `well` says clearly, not how
/// far; read, the rest is the move's.
fn well_away(c: &mut Clause) {
    for i in 0..c.len() {
        if c.words_at(i, &["well"]) && one_of(c, i + 1, &["away", "clear", "out", "back", "over"]) {
            c.mark(i..i + 1);
        }
    }
}

/// "further out from the ends of X2", "away from the side of X2": away from X2 — each
/// object is at one of its ends or sides, and moves out from the one it is at.
fn from_its_ends(c: &mut Clause) {
    for i in 0..c.len() {
        if !c.words_at(i, &["from", "the"]) {
            continue;
        }
        let part = one_of(c, i + 2, &["ends", "end", "sides", "side"]);
        let target = matches!(c.token(i + 4), Some(super::words::Token::Variable(_)));
        if part && c.words_at(i + 3, &["of"]) && target {
            c.mark(i + 1..i + 4);
        }
    }
}

/// Whether the words from `i` say where something is to be, as a move reads it: a
/// relation ("on X2", "next to X2", "closer to X2", "in front of X2", "in the corner",
/// "to the left of X2"), or an amount and a direction ("1 m to the left", "20 cm further
/// back"). Anything else ("1 m from the wall", "bigger") is not
/// read as a move.
fn where_to_be(c: &Clause, mut i: usize) -> bool {
    // (Words read already — "centred" in "centred on X2" — are passed over.)
    while i < c.len() && !c.free(i) {
        i += 1;
    }
    const RELATIONS: [&str; 32] = [
        "in",
        "at",
        "to",
        "behind",
        "along",
        "alongside",
        "opposite",
        "across",
        "up",
        "flush",
        "over",
        // ("centred" and "centered" are read as "centre".)
        "centre",
        "center",
        "on",
        "onto",
        "next",
        "beside",
        "by",
        "near",
        "against",
        "under",
        "underneath",
        "below",
        "beneath",
        "above",
        "between",
        "inside",
        "closer",
        "nearer",
        "further",
        "farther",
        "facing",
    ];
    const DIRECTIONS: [&str; 10] = [
        "left",
        "right",
        "forward",
        "forwards",
        "back",
        "backward",
        "backwards",
        "up",
        "down",
        "higher",
    ];
    if one_of(c, i, &RELATIONS) {
        return true;
    }
    let Some((_, len)) = amounts::number_at(c, i) else {
        return false;
    };
    let unit = i + len;
    if c.word(unit).and_then(super::words::length_unit).is_none() {
        return false;
    }
    let mut k = unit + 1;
    while one_of(c, k, &["to", "the", "further", "farther", "more"]) {
        k += 1;
    }
    one_of(c, k, &DIRECTIONS)
}

/// The modal verbs of an obligation, a wish or a question ("needs to go", "could X1 go").
const MODALS: [&str; 11] = [
    "needs", "need", "has", "have", "should", "must", "ought", "wants", "want", "can", "could",
];

/// The words at `k` that say the objects are to move — `go`, `move`, `sit`, `stand`, `be
/// moved` (`shifted`, `pushed` …) — and the token after them.
fn to_move_at(c: &Clause, k: usize) -> Option<usize> {
    const MOVED: [&str; 7] = [
        "moved", "shifted", "pushed", "placed", "put", "slid", "nudged",
    ];
    if one_of(c, k, &["go", "move", "sit", "stand"]) {
        Some(k + 1)
    } else if c.words_at(k, &["be"]) && one_of(c, k + 1, &MOVED) {
        Some(k + 2)
    } else {
        None
    }
}

/// `X1 needs to go …`, `X1 should be moved …`, `X1 has to move …`, `X1 should be 1 m to
/// the left`: the words after the objects that say they are to move, read; the clause is
/// then a move of the objects. Else a question with the objects inside ([`could_it_go`]).
fn needs_to_go(c: &mut Clause) {
    for i in 1..c.len() {
        let after_objects = matches!(c.token(i - 1), Some(super::words::Token::Variable(_)));
        if !after_objects || !one_of(c, i, &MODALS) {
            continue;
        }
        let mut k = i + 1;
        if c.words_at(k, &["to"]) {
            k += 1;
        }
        // "X1 and X2 should both face X3", "… should all turn": the quantifier is read.
        let quantified = one_of(c, k, &["both", "all", "each"]);
        if quantified {
            k += 1;
        }
        // "X1 should be 1 m to the left", "X1 needs to be on X2", "X1 should be way
        // further to the right": where it is to be.
        let to_be = || {
            if !c.words_at(k, &["be"]) {
                return None;
            }
            // The vague amount stays for the reader of amounts.
            let after = k + 1 + vague_words_at(c, k + 1);
            where_to_be(c, after).then_some(k + 1)
        };
        if let Some(end) = to_move_at(c, k).or_else(to_be) {
            c.mark(i..end);
            return;
        }
        // "X1 should be bigger", "X1 needs to be a bit smaller": made so.
        let sized = c.words_at(k, &["be"]) && {
            let after = k + 1 + vague_words_at(c, k + 1);
            one_of(
                c,
                after,
                &["bigger", "smaller", "larger", "taller", "tinier"],
            )
        };
        if sized {
            c.mark(i..k);
            c.replace(k, "make");
            return;
        }
        // "X1 needs to face X2", "X1 should swap with X2", "X1 has to turn": the modal
        // (and its `to`) read, the verb left for the clause's reader.
        let verb_follows = c
            .word(k)
            .is_some_and(|w| super::words::verb(w).is_some() || matches!(w, "face" | "come"));
        if verb_follows {
            if c.words_at(k, &["come"]) {
                c.mark(k..k + 1);
            }
            c.mark(i..k);
            return;
        }
    }
    could_it_go(c);
}

/// How many words at `i` say a vague amount before where something is to be ("way",
/// "a bit", "much", "slightly"): those are the amount's, read by the reader later.
fn vague_words_at(c: &Clause, i: usize) -> usize {
    const VAGUE: [&[&str]; 7] = [
        &["a", "little", "bit"],
        &["a", "bit"],
        &["a", "little"],
        &["way"],
        &["much"],
        &["slightly"],
        &["far"],
    ];
    VAGUE
        .iter()
        .find(|w| c.words_at(i, w))
        .map_or(0, |w| w.len())
}

/// "X1 and X2 get turned 90 degrees", "X1 is to be moved left", "X3 gets pushed back":
/// the auxiliary after the objects is read, so the participle is the clause's verb.
fn passive(c: &mut Clause) {
    for i in 1..c.len() {
        let after_objects = matches!(c.token(i - 1), Some(super::words::Token::Variable(_)));
        if !after_objects || !c.free(i) {
            continue;
        }
        let aux = match c.word(i) {
            Some("get" | "gets" | "got" | "are" | "is" | "be" | "been") => 1,
            _ => continue,
        };
        let participle = c.word(i + aux).is_some_and(|w| {
            (w.ends_with("ed") || matches!(w, "put" | "set" | "spun" | "slid" | "shrunk"))
                && super::words::verb(w).is_some()
        });
        if participle {
            c.mark(i..i + aux);
            return;
        }
    }
}

/// A question with the objects inside: "could X1 go …", "can X1 be moved …", "can X1 and
/// X2 all turn …" (its modal typed as people type it: "coudl", "cna").
fn could_it_go(c: &mut Clause) {
    let modal_first = c.free(0)
        && c.word(0)
            .is_some_and(|w| MODALS.contains(&crate::discourse::canonical(w)));
    if !modal_first {
        return;
    }
    let mut k = 1;
    while matches!(c.token(k), Some(super::words::Token::Variable(_)))
        || (c.words_at(k, &["and"]) || matches!(c.token(k), Some(super::words::Token::Separator)))
            && matches!(c.token(k + 1), Some(super::words::Token::Variable(_)))
    {
        k += 1;
    }
    if k == 1 {
        return;
    }
    // "can X1, X2 and X3 all turn to face X4": the quantifier is read.
    let quantifier = one_of(c, k, &["both", "all", "each"]);
    let verb_at = k + usize::from(quantifier);
    if let Some(end) = to_move_at(c, verb_at) {
        c.mark(0..1);
        c.mark(k..end);
    } else if c
        .word(verb_at)
        .is_some_and(|w| super::words::verb(w).is_some() || w == "face")
    {
        // The verb is left for the clause's reader.
        c.mark(0..1);
        c.mark(k..verb_at);
    }
}

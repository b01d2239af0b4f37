//! Post-modifiers: the words after a head that may say which object it is — a side or
//! the middle (`the speaker on the right`), the floor, a place in the room (`the chair in
//! the corner`), an order from a side or an object (`the second chair from the window`),
//! what it carries (`the table with the lamp on it`), or a relation to other objects
//! (`the book on the side table`, `the lamp nearest the sofa`), whose objects are read as
//! a noun phrase of their own.
//!
//! This stage only reads the words and the objects they name; whether they pick, describe
//! or say where the object goes is [`attach`](super::attach)'s to decide.

use super::select::{self, Direction, Relation};
use super::{words, GroundError, Mode, Post, Reader, MAX_TARGETS};
use words::Kind;

impl Reader<'_> {
    /// A modifier after the noun at token `k`: `on the left`, `on the right wall`, `in the
    /// middle`, `from the window`, `nearest the sofa`, `on the side table`, `that is next
    /// to the bed`, `with the lamp on it`.
    pub(super) fn post_modifier(
        &self,
        k: usize,
        bound: &[usize],
    ) -> Result<Option<(Post, usize)>, GroundError> {
        let mut j = k;
        while j < self.tokens.len()
            && self.word(j).is_some_and(words::is_relative_filler)
            && self.relation_at(j).is_none()
        {
            j += 1;
        }
        if let Some(line) = self.line_at(j) {
            return Ok(Some(line));
        }
        if let Some(place) = self.side_place_at(j) {
            return Ok(Some(place));
        }
        if let Some(room) = self.room_place_at(j) {
            return Ok(Some(room));
        }
        let w = self.word(j).unwrap_or("");
        if w == "from" {
            return self.origin_at(j, bound);
        }
        // "the same bench as the centrifuge": the bench the centrifuge stands on.
        let same_before = (k.saturating_sub(4)..k).any(|i| self.word(i) == Some("same"));
        if w == "as" && same_before {
            if let Some((targets, end)) = self.nested_np(j + 1, bound)? {
                return Ok(Some((Post::Relation(Relation::SameAs, targets), end)));
            }
        }
        // without a lamp, with no books on it, that has nothing on it.
        if let Some(lacks) = self.lacking_at(j, bound)? {
            return Ok(Some(lacks));
        }
        // "swap the mixer with the plate stack": the second of the pair, not what the
        // first carries.
        if w == "with" && self.swap_verb_before(k) {
            return Ok(None);
        }
        // with the lamp (on it), that has the clock on it, holding the vase.
        if matches!(
            w,
            "with" | "has" | "holds" | "holding" | "carrying" | "having"
        ) {
            return self.carrying_at(j, bound);
        }
        // "the chair between chair 12 and chair 14", "… between the two beds".
        if w == "between" {
            return Ok(self.between_at(j, bound));
        }
        if let Some((relation, after)) = self.relation_at(j) {
            if let Some((targets, end)) = self.nested_np(after, bound)? {
                // "the cup closest to the window" with two windows: closest to which is
                // not said (only what rests on or in any of them is one set).
                let measured = matches!(
                    relation,
                    Relation::Nearest
                        | Relation::Farthest
                        | Relation::LeftOf
                        | Relation::RightOf
                        | Relation::InFront
                        | Relation::Behind
                );
                if measured && targets.len() > 1 {
                    let range = after..end;
                    let noun = self
                        .span_text(&range)
                        .split(' ')
                        .skip_while(|w| words::is_determiner(&w.to_lowercase()))
                        .collect::<Vec<_>>()
                        .join(" ")
                        .to_lowercase();
                    return Err(self.ambiguous(&range, &noun, &targets, 0));
                }
                return Ok(Some((Post::Relation(relation, targets), end)));
            }
        }
        Ok(None)
    }

    /// A line named before its objects at token `k`: "the back row of tables", "the
    /// whole front row of desks", "the left column of benches", "the second row of
    /// chairs", "all the front-row chairs" — the objects of the plural noun (after `of`,
    /// or right after the line's words) that stand in that line, as a phrase of its own.
    /// `None` where the words are not that.
    ///
    /// # Errors
    /// A second plural noun ("… of desks and chairs") whose objects stand in no such line.
    pub(super) fn line_of_at(&self, k: usize) -> Result<Option<super::Np>, GroundError> {
        let w = |i: usize| self.word(i).unwrap_or("");
        let mut j = k;
        if w(j) == "all" {
            j += 1;
        }
        if w(j) == "the" {
            j += 1;
        }
        if matches!(w(j), "whole" | "entire") {
            j += 1;
        }
        // "front row" or, written as one word, "front-row": which line, and the token after.
        let (which, line_word, after) = match w(j).split_once('-') {
            Some((which, line)) => (which, line, j + 1),
            None => (w(j), w(j + 1), j + 2),
        };
        let columns = match line_word {
            "row" => false,
            "column" => true,
            _ => return Ok(None),
        };
        // "the back row of desks", or as words before the noun: "all the front-row chairs".
        let of = usize::from(w(after) == "of");
        if (of == 0 && self.head_at(after).is_none()) || (k..after + of).any(|i| self.consumed[i]) {
            return Ok(None);
        }
        let line = match (which, columns) {
            ("front", false) => select::Line::Row(1),
            ("back" | "rear" | "last", false) => select::Line::Row(usize::MAX),
            ("left", true) => select::Line::Column(1),
            ("right" | "last", true) => select::Line::Column(usize::MAX),
            ("middle" | "center" | "centre", _) => select::Line::Middle { columns },
            (other, _) => {
                let Some(n) = words::ordinal(other).filter(|&n| n != usize::MAX) else {
                    return Ok(None);
                };
                if columns {
                    select::Line::Column(n)
                } else {
                    select::Line::Row(n)
                }
            }
        };
        let mut h = after + of;
        if of == 1 && w(h) == "the" {
            h += 1;
        }
        let Some(head) = self.head_at(h) else {
            return Ok(None);
        };
        if !head.plural || head.generic {
            return Ok(None);
        }
        let Some(mut objects) = select::in_line(self.scene, &head.objects, line) else {
            return Ok(None);
        };
        let mut end = head.range.end;
        // "the back row of desks and chairs": the row of each — or, where the second do
        // not stand in such rows, refused (never every chair).
        if self.is_word(end, &["and"]) {
            if let Some(second) = self.head_at(end + 1).filter(|s| s.plural && !s.generic) {
                let Some(more) = select::in_line(self.scene, &second.objects, line) else {
                    return Err(GroundError::NoPick {
                        phrase: self.span_text(&(k..second.range.end)),
                        reason: format!(
                            "the {} do not stand in such rows or columns; name them",
                            super::error::plural(&second.text)
                        ),
                    });
                };
                objects.extend(more);
                end = second.range.end;
            }
        }
        let detail = format!(
            "{} stand in that {}",
            super::error::list(&self.names(&objects)),
            if columns { "column" } else { "row" }
        );
        // ("the other one" after it picks among all of the noun's, not the row's.)
        let mut np = super::Np::group(k..end, objects, head.text, detail);
        np.pool = head.objects;
        Ok(Some(np))
    }

    /// A row or column at token `j`, and where it ends: `in the back row`, `in the front
    /// row`, `in the second row`, `in the last row`, `in the middle row`, `in the left
    /// column`, `in row 3`, `of the third column`. Rows count from the front, columns
    /// from the left.
    pub(super) fn line_at(&self, j: usize) -> Option<(Post, usize)> {
        let w = |k: usize| self.word(k).unwrap_or("");
        if !matches!(w(j), "in" | "on" | "of" | "at" | "from") {
            return None;
        }
        let line_word = |k: usize| match w(k) {
            "row" | "rows" | "line" => Some(false),
            "column" | "columns" | "col" => Some(true),
            _ => None,
        };
        // "in row 3", "in column 2".
        if let Some(columns) = line_word(j + 1) {
            let n = match self.tokens.get(j + 2).map(|t| &t.kind) {
                Some(Kind::Number(n)) if n.fract() == 0.0 && *n >= 1.0 && *n < 1000.0 => {
                    *n as usize
                }
                _ => return None,
            };
            let line = if columns {
                select::Line::Column(n)
            } else {
                select::Line::Row(n)
            };
            return Some((Post::Line(line), j + 3));
        }
        if w(j + 1) != "the" {
            return None;
        }
        let which = w(j + 2);
        let columns = line_word(j + 3)?;
        let line = match (which, columns) {
            ("front", false) => select::Line::Row(1),
            ("back" | "rear", false) => select::Line::Row(usize::MAX),
            ("left", true) => select::Line::Column(1),
            ("right", true) => select::Line::Column(usize::MAX),
            ("middle" | "center" | "centre", _) => select::Line::Middle { columns },
            (other, _) => {
                let n = words::ordinal(other)?;
                if columns {
                    select::Line::Column(n)
                } else {
                    select::Line::Row(n)
                }
            }
        };
        Some((Post::Line(line), j + 4))
    }

    /// The floor, a side or the middle at token `j`, and where it ends: `on the floor`, `on
    /// the left`, `on the far right`, `on the left-hand side`, `on the right wall`, `at the
    /// front`, `in the middle`.
    pub(super) fn side_place_at(&self, j: usize) -> Option<(Post, usize)> {
        let w = |k: usize| self.word(k).unwrap_or("");
        if matches!(w(j), "on" | "at")
            && w(j + 1) == "the"
            && matches!(w(j + 2), "floor" | "ground")
        {
            return Some((Post::Floor, j + 3));
        }
        // ("to the left" is a direction, not a place: it is not read here.)
        if !(matches!(w(j), "on" | "at" | "in" | "against" | "along") && w(j + 1) == "the") {
            return None;
        }
        let mut s = j + 2;
        if w(s) == "far" || w(s) == "very" {
            s += 1;
        }
        if let Some((axis, sign)) = words::side_word(w(s)) {
            // "at the left desk" names a desk, "in the back left corner" a place; "on
            // the left" is a side.
            let next = w(s + 1);
            let names_a_place = |word: &str| matches!(word, "corner" | "corners");
            let corner = names_a_place(next)
                || (words::side_word(next).is_some() && names_a_place(w(s + 2)));
            // "on the left and right tables" names tables.
            let coordinated = s + 1 < self.tokens.len() && self.coordinates(s + 1);
            if next != "of" && self.head_at(s + 1).is_none() && !corner && !coordinated {
                let mut end = s + 1;
                // "the bookcase against the back wall": one against that wall, never merely
                // the one furthest back (without walls, the one furthest back).
                if w(end) == "wall" && axis != words::Axis::Y && self.scene.bounds.is_some() {
                    return Some((Post::Room(select::RoomPlace::OnWall(axis, sign)), end + 1));
                }
                if matches!(w(end), "side" | "end" | "wall") {
                    end += 1;
                } else if w(end) == "hand" && w(end + 1) == "side" {
                    end += 2;
                }
                // "at the left end of the table" is a relation to the table.
                if w(end) == "of" {
                    return None;
                }
                return Some((Post::Side(axis, sign), end));
            }
        }
        if matches!(w(s), "middle" | "center" | "centre") && w(s + 1) != "of" {
            return Some((Post::Middle, s + 1));
        }
        None
    }

    /// `from the left` (an order from a side) or `from` an object (an order from it, or
    /// where it is taken from) at token `j`, the word `from`.
    fn origin_at(&self, j: usize, bound: &[usize]) -> Result<Option<(Post, usize)>, GroundError> {
        let w = |k: usize| self.word(k).unwrap_or("");
        if w(j + 1) == "the" {
            if let Some((axis, sign)) = words::side_word(w(j + 2)) {
                // "from the left", not "from the left table".
                if w(j + 3) != "of" && !self.head_follows(j + 3) {
                    let mut end = j + 3;
                    if matches!(w(end), "side" | "end" | "wall") {
                        end += 1;
                    }
                    return Ok(Some((Post::From(Direction::Side(axis, sign)), end)));
                }
            }
        }
        // "the second table from the window" with every window in the left wall: from
        // the left, whichever window.
        if w(j + 1) == "the" {
            if let Some(head) = self.head_at(j + 2).filter(|h| h.objects.len() > 1) {
                if let Some((axis, sign)) = select::common_wall(self.scene, &head.objects) {
                    let side = Direction::Side(axis, sign);
                    return Ok(Some((Post::From(side), head.range.end)));
                }
            }
        }
        if let Some((targets, end)) = self.nested_np(j + 1, bound)? {
            if let [one] = targets.as_slice() {
                return Ok(Some((Post::FromObject(*one), end)));
            }
        }
        Ok(None)
    }

    /// What an object lacks at token `j`: `without a lamp`, `with no books on it`, `that
    /// has no lamp`, `that doesn't have a lamp`, `with nothing on it`.
    fn lacking_at(&self, j: usize, bound: &[usize]) -> Result<Option<(Post, usize)>, GroundError> {
        let w = |k: usize| self.word(k).unwrap_or("");
        let after = match (w(j), w(j + 1), w(j + 2)) {
            ("without", _, _) => j + 1,
            ("with" | "has", "no" | "nothing", _) => j + 1,
            ("doesn't" | "hasn't", "have" | "got", _) => j + 2,
            ("does" | "has", "not", "have" | "got") => j + 3,
            _ => return Ok(None),
        };
        let mut k = after;
        if matches!(w(k), "nothing" | "anything") {
            k += 1;
            return Ok(Some((Post::Lacks(None), self.on_it_tail(k))));
        }
        if matches!(w(k), "no" | "any" | "a" | "an") {
            k += 1;
        }
        let Some((targets, end)) = self.nested_np(k, bound)? else {
            return Ok(None);
        };
        Ok(Some((Post::Lacks(Some(targets)), self.on_it_tail(end))))
    }

    /// Where "on it" / "on top" after what an object carries ends, from token `k`.
    fn on_it_tail(&self, k: usize) -> usize {
        let w = |i: usize| self.word(i).unwrap_or("");
        match (w(k), w(k + 1)) {
            ("on", "it" | "top" | "them") => k + 2,
            _ => k,
        }
    }

    /// What an object carries, after `with`, `has`, `holding`… at token `j`: `with the lamp
    /// on it`, `that has the clock on top`.
    fn carrying_at(&self, j: usize, bound: &[usize]) -> Result<Option<(Post, usize)>, GroundError> {
        let w = |k: usize| self.word(k).unwrap_or("");
        let Some((targets, mut end)) = self.nested_np(j + 1, bound)? else {
            return Ok(None);
        };
        for tail in [
            &["on", "top", "of", "it"][..],
            &["on", "top"],
            &["on", "it"],
            &["in", "it"],
            &["on"],
        ] {
            if tail.iter().enumerate().all(|(t, x)| w(end + t) == *x)
                && (tail.len() > 1 || matches!(w(end + 1), "it" | ""))
            {
                end += tail.len();
                break;
            }
        }
        Ok(Some((Post::Relation(Relation::Carries, targets), end)))
    }

    /// A place in the room after a noun, and where it ends: `in the (back left) corner`,
    /// `in the middle of the room` (or of the kitchen, …), `on the wall`.
    fn room_place_at(&self, j: usize) -> Option<(Post, usize)> {
        let w = |k: usize| self.word(k).unwrap_or("");
        if let Some(by) = self.by_wall_at(j) {
            return Some(by);
        }
        if !(matches!(w(j), "in" | "at" | "on" | "against") && w(j + 1) == "the") {
            return None;
        }
        let mut s = j + 2;
        let (mut x, mut z) = (None, None);
        while let Some(parts) = words::side_parts(w(s)) {
            for (axis, sign) in parts {
                match axis {
                    words::Axis::X => x = Some(sign),
                    words::Axis::Z => z = Some(sign),
                    words::Axis::Y => return None,
                }
            }
            s += 1;
        }
        match w(s) {
            "corner" if matches!(w(j), "in" | "at") => {
                Some((Post::Room(select::RoomPlace::Corner(x, z)), s + 1))
            }
            "middle" | "centre" | "center"
                if x.is_none() && z.is_none() && w(s + 1) == "of" && w(s + 2) == "the" =>
            {
                let room = w(s + 3);
                let names_room = self.g.lexicon.concepts_of(room).iter().any(|&c| {
                    let concept = self.g.lexicon.concept(c);
                    concept.term == "room"
                        || concept
                            .hypernyms
                            .iter()
                            .any(|&h| self.g.lexicon.concept(h).term == "room")
                });
                (room == "room" || names_room)
                    .then_some((Post::Room(select::RoomPlace::Middle), s + 4))
            }
            "wall" if x.is_none() && z.is_none() && matches!(w(j), "on" | "against") => {
                Some((Post::Room(select::RoomPlace::Wall), s + 1))
            }
            _ => None,
        }
    }

    /// One wall of the room, after a word of nearness at token `j`, and where it ends: `by
    /// the left wall`, `near the back wall`, `next to the far right wall`, `along the
    /// front wall`.
    fn by_wall_at(&self, j: usize) -> Option<(Post, usize)> {
        let w = |k: usize| self.word(k).unwrap_or("");
        let mut s = match (w(j), w(j + 1)) {
            ("by" | "near" | "beside" | "along" | "alongside", "the") => j + 2,
            ("next" | "close" | "near", "to") if w(j + 2) == "the" => j + 3,
            _ => return None,
        };
        // "the far right wall"; "the far wall" is the back one.
        if w(s) == "far" && words::side_word(w(s + 1)).is_some() {
            s += 1;
        }
        let (axis, sign) = words::side_word(w(s))?;
        (axis != words::Axis::Y && w(s + 1) == "wall")
            .then_some((Post::Room(select::RoomPlace::ByWall(axis, sign)), s + 2))
    }

    /// "between A and B" (or "between the two Ns") at token `j`: the two objects, as a
    /// relation, and the token after them. `None` where the words name no two objects.
    fn between_at(&self, j: usize, bound: &[usize]) -> Option<(Post, usize)> {
        // (Words that name no two objects here are left for the reader of the sentence:
        // "put the lamp on table 6 between the two chairs at that table".)
        let (first, end) = self.nested_np(j + 1, bound).ok().flatten()?;
        let (targets, end) = match first.as_slice() {
            [_, _] => (first, end),
            [a] if self.is_word(end, &["and"]) => {
                match self.nested_np(end + 1, bound).ok().flatten() {
                    Some((second, end)) if second.len() == 1 && second[0] != *a => {
                        (vec![*a, second[0]], end)
                    }
                    _ => return None,
                }
            }
            _ => return None,
        };
        Some((Post::Relation(Relation::Between, targets), end))
    }

    /// A relation word group at `j` and where its object starts.
    pub(super) fn relation_at(&self, j: usize) -> Option<(Relation, usize)> {
        let w = |k: usize| self.word(k).unwrap_or("");
        let four = (w(j), w(j + 1), w(j + 2), w(j + 3));
        let by_four = match four {
            ("to" | "on" | "at", "the", "left", "of") => Some(Relation::LeftOf),
            ("to" | "on" | "at", "the", "right", "of") => Some(Relation::RightOf),
            ("at" | "on" | "in", "the", "back" | "rear", "of") => Some(Relation::Behind),
            ("at" | "on" | "in", "the", "front", "of") => Some(Relation::InFront),
            _ => None,
        };
        if let Some(r) = by_four {
            return Some((r, j + 4));
        }
        // "the bench at the foot of the bed", "the lamp at the head of the table": by it.
        if matches!(w(j), "at" | "by")
            && w(j + 1) == "the"
            && matches!(w(j + 2), "foot" | "head")
            && w(j + 3) == "of"
        {
            return Some((Relation::Near, j + 4));
        }
        // "at the left end of the table", "on the far side of the desk".
        if matches!(w(j), "at" | "on" | "by" | "to")
            && w(j + 1) == "the"
            && matches!(w(j + 3), "end" | "side")
            && w(j + 4) == "of"
        {
            let r = match w(j + 2) {
                "left" => Some(Relation::LeftOf),
                "right" => Some(Relation::RightOf),
                "far" | "back" => Some(Relation::Behind),
                "near" | "front" => Some(Relation::InFront),
                _ => None,
            };
            if let Some(r) = r {
                return Some((r, j + 5));
            }
        }
        let (r, len) = match (w(j), w(j + 1), w(j + 2)) {
            ("on", "top", "of") => (Relation::On, 3),
            ("in", "front", "of") => (Relation::InFront, 3),
            ("in", "back", "of") => (Relation::Behind, 3),
            ("left", "of", _) => (Relation::LeftOf, 2),
            ("right", "of", _) => (Relation::RightOf, 2),
            ("next", "to", _) => (Relation::Near, 2),
            ("close", "to", _) => (Relation::Near, 2),
            ("near", "to", _) => (Relation::Near, 2),
            ("nearest", "to", _) | ("closest", "to", _) => (Relation::Nearest, 2),
            ("farthest" | "furthest", "from", _) => (Relation::Farthest, 2),
            ("farthest" | "furthest", "away", "from") => (Relation::Farthest, 3),
            ("on" | "onto" | "upon" | "atop", _, _) => (Relation::On, 1),
            // Where a thing is taken from is where it rests: "the cups off the table".
            ("off", "of", _) => (Relation::Off, 2),
            ("off", _, _) => (Relation::Off, 1),
            ("under" | "below" | "beneath" | "underneath", _, _) => (Relation::Under, 1),
            ("above" | "over", _, _) => (Relation::Above, 1),
            (
                "beside" | "by" | "near" | "alongside" | "nearby" | "at" | "around" | "round",
                _,
                _,
            ) => (Relation::Near, 1),
            ("nearest" | "closest", _, _) => (Relation::Nearest, 1),
            ("behind", _, _) => (Relation::Behind, 1),
            ("across", "from", _) => (Relation::Opposite, 2),
            ("opposite", "to", _) => (Relation::Opposite, 2),
            ("opposite", _, _) => (Relation::Opposite, 1),
            ("in" | "inside" | "within", _, _) => (Relation::Inside, 1),
            _ => return None,
        };
        Some((r, j + len))
    }

    /// The other object(s) of a modifier (`the side table` in `the book on the side
    /// table`): one object, or every object a still ambiguous phrase fits (`the phone on
    /// the chair` looks at every chair).
    pub(super) fn nested_np(
        &self,
        j: usize,
        bound: &[usize],
    ) -> Result<Option<(Vec<usize>, usize)>, GroundError> {
        if let Some(Kind::Quoted(name)) = self.tokens.get(j).map(|t| &t.kind) {
            return Ok(self.scene.find(name).map(|i| (vec![i], j + 1)));
        }
        // "the lamp on it": the object named last ("them": the objects).
        match self.word(j) {
            Some("it") if self.antecedent.len() == 1 => {
                return Ok(Some((self.antecedent.clone(), j + 1)));
            }
            Some("them") if self.group.len() > 1 => {
                return Ok(Some((self.group.clone(), j + 1)));
            }
            _ => {}
        }
        // Skip the determiner and modifiers to the head.
        let mut h = j;
        while h < self.tokens.len() && h < j + 5 {
            if self.head_at(h).is_some() {
                break;
            }
            let w = self.word(h).unwrap_or("");
            if !(words::is_determiner(w) || self.is_premodifier(h) || self.coordinates(h)) {
                return Ok(None);
            }
            h += 1;
        }
        let Some(head) = self.head_at(h) else {
            return Ok(None);
        };
        if head.generic {
            return Ok(None);
        }
        let text = head.text.clone();
        let np = self.noun_phrase(head, bound, Mode::Nested)?;
        if np.range.start > j {
            return Ok(None);
        }
        // A few fitting objects are all looked at ("the phone on the chair"); past that the
        // phrase itself is what needs saying better.
        if np.objects.len() > MAX_TARGETS {
            return Err(self.ambiguous(&np.range, &text, &np.objects, 2));
        }
        Ok(Some((np.objects, np.range.end)))
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::{means, refused, with_reader};
    use super::*;

    /// The post-modifier of `text` at token `k`: what kind, the names of the objects it
    /// relates to, and the token after it.
    fn post(scene: &str, text: &str, k: usize) -> Option<(String, Vec<String>, usize)> {
        with_reader(scene, text, |r| {
            let (p, end) = r.post_modifier(k, &[]).unwrap()?;
            let (kind, targets) = match p {
                Post::Relation(relation, targets) => (format!("{relation:?}"), targets),
                Post::FromObject(t) => ("FromObject".to_string(), vec![t]),
                other => (format!("{other:?}"), Vec::new()),
            };
            Some((kind, r.names(&targets), end))
        })
    }

    #[test]
    fn sides_places_and_orders_are_read_with_their_end() {
        let p = post("living_room", "move the speaker on the right back", 3).unwrap();
        assert_eq!((p.0.starts_with("Side(X"), p.2), (true, 6));
        let p = post("living_room", "move the speaker on the left-hand side", 3).unwrap();
        assert_eq!(p.2, 7);
        // "on the left desk" names a desk: no side.
        assert!(post("office", "the chair at the left desk", 2)
            .is_none_or(|p| !p.0.starts_with("Side")));
        let p = post("dining_room", "the chair in the back left corner", 2).unwrap();
        assert!(p.0.starts_with("Room(Corner"), "{p:?}");
        let p = post("dining_room", "the second chair from the left", 3).unwrap();
        assert!(p.0.starts_with("From(Side"), "{p:?}");
    }

    #[test]
    fn relations_name_their_objects() {
        let p = post("living_room", "move the lamp on the side table left", 3).unwrap();
        assert_eq!(p, ("On".to_string(), vec!["side table".to_string()], 7));
        let p = post("living_room", "the lamp that is nearest to the armchair", 2).unwrap();
        assert_eq!(p, ("Nearest".to_string(), vec!["armchair".to_string()], 8));
        let p = post("living_room", "the table with the vase on it", 2).unwrap();
        assert_eq!(p, ("Carries".to_string(), vec!["vase".to_string()], 7));
        // "the phone on the chair": every chair the phrase fits is looked at.
        let p = post("dining_room", "the plate on the chair", 2).unwrap();
        assert_eq!(p.1, ["chair", "chair 2", "chair 3", "chair 4"]);
        assert!(post("living_room", "move the sofa left", 3).is_none());
    }

    #[test]
    fn picking_by_side() {
        means(
            "living_room",
            "move the speaker on the right back",
            &[&["speaker 2"]],
        );
        refused(
            "living_room",
            "move the speaker on the floor",
            &["speaker", "speaker 2"],
        );
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
    }

    #[test]
    fn the_left_of_an_object_is_a_place_not_a_pick() {
        means(
            "bedroom",
            "put the laundry basket to the left of the dresser",
            &[&["laundry basket"], &["dresser"]],
        );
    }
}

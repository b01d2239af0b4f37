//! Attachment: whether a modifier after a noun picks among its objects, describes the one
//! it names, or is where the object goes and is left for the translator — and, when it
//! picks, applying it.
//!
//! `the book on the side table` with two books: it picks. `move the book on the coffee
//! table 10 cm left` with one: the clause goes on, so it describes (and is checked). `put
//! the book on the side table` with one book: it is the destination. After a verb of
//! placing, a relation that would have to pick (`put the spoon next to the toaster` with
//! two spoons) is refused naming the candidates: it is where a spoon goes, not which.

use super::error::{self, GroundError};
use super::select::{self, Direction, Relation};
use super::{words, Head, Post, Reader};
use words::Kind;

/// What the words before a post-modifier have decided.
#[derive(Clone, Copy, Debug)]
pub(super) struct Choice {
    /// The noun alone does not pick what is wanted (or an ordinal or a generic noun waits
    /// for the modifier).
    pub picks: bool,
    /// The phrase names a group.
    pub group: bool,
    /// Modifiers before the noun (sides, sizes, middle) already pick.
    pub selectors_first: bool,
}

/// The words of a post-modifier, for messages.
pub(super) struct PostText<'t> {
    /// The phrase up to the end of the modifier.
    pub at: &'t str,
    /// The modifier's own words.
    pub words: &'t str,
}

impl Reader<'_> {
    /// The post-modifier to apply to the phrase starting at `start`, if it picks or
    /// describes; `None` when it is left for the translator as where the object goes.
    ///
    /// # Errors
    /// A relation after a verb of placing that would have to pick.
    pub(super) fn attach(
        &self,
        post: Option<(Post, usize)>,
        head: &Head,
        start: usize,
        objects: &[usize],
        choice: Choice,
    ) -> Result<Option<(Post, usize)>, GroundError> {
        let Choice {
            picks,
            group,
            selectors_first,
        } = choice;
        // A modifier after the noun picks when the noun alone does not (`the book on the
        // side table` with two books), and describes when the clause goes on with its own
        // amount or place, or has a verb that takes none (`move the book on the table 10
        // cm left`, `rotate the tv on the stand`). Otherwise it is where the object goes
        // (`put the book on the side table`) and is left for the translator.
        // The object of a relation ("on top of the magazine on the ottoman") is where
        // something goes: a modifier after it can only describe it.
        let destination = start > 0
            && self.word(start - 1).is_some_and(|w| {
                words::is_preposition(w) && !matches!(w, "up" | "than" | "as" | "like" | "for")
            });
        // "put the phone on the desk next to the mug": a relation to something that rests
        // on the destination is the rest of the destination, not a description of it.
        let rest_of_destination = destination && self.rests_on_any(post.as_ref(), objects);
        // "put the cup on the table at chair 8's place": the chair's place is the rest of
        // the destination, never which table.
        let at_a_seat = destination
            && post.as_ref().is_some_and(|(_, p_end)| {
                self.is_word(*p_end, &["place", "spot", "seat", "setting"])
            });
        if at_a_seat {
            return Ok(None);
        }
        // "a shelf in the bookcase": a part of what the modifier names, not a shelf that
        // stands in it (the part is read by the translator).
        let part_of_shelves = matches!(head.text.as_str(), "shelf" | "shelves")
            && matches!(&post, Some((Post::Relation(_, targets), _)) if !targets.is_empty()
            && targets.iter().all(|&t| {
                super::kind::form_of(self.scene, t) .shelves()
            }));
        if part_of_shelves {
            return Ok(None);
        }
        // "move the mug off the table onto the counter": after where it is taken from,
        // "onto" (into, to) says where it goes, never which table.
        let after_source = start > 0
            && self.is_word(start - 1, &["off", "from"])
            && self.is_word(head.range.end, &["onto", "into", "to"])
            && matches!(post, Some((Post::Relation(..), _)));
        if after_source {
            return Ok(None);
        }
        // Where it is taken from ("the cups off the table") is never where it goes.
        let source = matches!(
            post,
            Some((
                Post::Relation(Relation::Off | Relation::From, _) | Post::FromObject(_),
                _
            ))
        );
        // "put the lamp on the side table on the right" with two side tables: "on the
        // right" says which side table, not where the lamp goes; the clause goes on only
        // after it.
        // "on the second shelf from the top of the bookcase": the clause goes on after
        // the case the shelf is a part of.
        let own_place_of_targets = |p: &Post, p_end: usize| match p {
            Post::Relation(_, targets) if targets.len() > 1 => {
                self.side_place_at(p_end).map_or(p_end, |(_, end)| end)
            }
            _ => self.after_shelf_part(p_end),
        };
        // "the thing on the cupboard", "everything on the shelf": a generic noun says
        // nothing of which without its modifier, so the modifier is never a destination.
        let same_as = matches!(post, Some((Post::Relation(Relation::SameAs, _), _)));
        // "the small box that's on the floor", "put the mug that's on the island next to
        // the kettle": a relative clause says which, always.
        let relative = matches!(
            self.word(head.range.end),
            Some("that" | "which" | "that's" | "thats")
        );
        let describes = !rest_of_destination
            && !same_as
            && post.as_ref().is_some_and(|(p, p_end)| {
                source
                    || relative
                    // A row or column before "and their chairs" says which tables ("the
                    // tables in the back row and their chairs").
                    || (matches!(p, Post::Line(_))
                        && self.is_word(*p_end, &["and"])
                        && self.is_word(*p_end + 1, &["its", "their"]))
                    // "every seat round the table except …": what is left out of it.
                    || self.is_word(*p_end, &["except", "excluding", "apart", "besides", "bar"])
                    || head.generic
                    || super::hold::cue_before(&self.tokens, start)
                    || (self.clause_goes_on(own_place_of_targets(p, *p_end))
                        && !self.floor_then_relation(p, *p_end))
                    || self.topic_before(start, *p_end)
                    || self.verb_takes_no_place(start)
                    || destination
            });
        // A relation or place after a noun the modifiers before it already pick among
        // ("the left stool next to the chair", "the top crate on the floor") is where it
        // goes, unless it clearly describes.
        let post = post.filter(|(p, _)| {
            !selectors_first
                || describes
                || !matches!(p, Post::Relation(..) | Post::Floor | Post::Room(_))
        });
        // "put the spoon next to the toaster" with two spoons: after a verb of placing the
        // relation is where the spoon goes, not which spoon; refuse, naming them.
        if picks && !describes && !group {
            if let Some((p @ (Post::Relation(..) | Post::Room(_) | Post::Floor), p_end)) = &post {
                let can_be_a_destination = match p {
                    Post::Relation(rel, _) => rel.can_be_a_destination(),
                    _ => true,
                };
                if can_be_a_destination
                    && !self.clause_goes_on(*p_end)
                    && self.placing_verb_before(start)
                {
                    return Err(self.ambiguous(&(start..head.range.end), &head.text, objects, 0));
                }
            }
        }
        if describes && !picks && self.false_of_one_placed(post.as_ref(), start, objects) {
            return Ok(None);
        }
        Ok(post.filter(|_| picks || describes))
    }

    /// Where the case of shelves a shelf ends a phrase at `p_end` is a part of ends ("…
    /// shelf from the top of the bookcase"): after that case's phrase; else `p_end`.
    fn after_shelf_part(&self, p_end: usize) -> usize {
        let shelf = p_end
            .checked_sub(1)
            .is_some_and(|k| self.is_word(k, &["shelf", "shelves"]));
        match self.case_of_shelf(p_end, &[]) {
            Ok(Some((_, end))) if shelf => end,
            _ => p_end,
        }
    }

    /// Whether `post` is a relation beside (near, in front, behind, left, right, between)
    /// objects that all rest on one of `objects`.
    fn rests_on_any(&self, post: Option<&(Post, usize)>, objects: &[usize]) -> bool {
        post.is_some_and(|(p, _)| match p {
            Post::Relation(
                Relation::Near
                | Relation::InFront
                | Relation::Behind
                | Relation::LeftOf
                | Relation::RightOf
                | Relation::Between,
                targets,
            ) => {
                !targets.is_empty()
                    && targets.iter().all(|&t| {
                        objects
                            .iter()
                            .any(|&o| self.scene.objects[t].support == Some(o))
                    })
            }
            _ => false,
        })
    }

    /// "put drill 2 on the workbench next to drill 1": whether "on X", after the one
    /// object a placing verb names and before a second relation ("next to", "between"),
    /// is not true of it — then the two are where the object goes, not a description of
    /// it (found false, it would refuse the edit). With an amount after it instead ("move
    /// the book on the side table 10 cm left") it stays a description, and is refused.
    fn false_of_one_placed(
        &self,
        post: Option<&(Post, usize)>,
        start: usize,
        objects: &[usize],
    ) -> bool {
        let Some((Post::Relation(Relation::On, targets), end)) = post else {
            return false;
        };
        let second = self.relation_at(*end).is_some() || self.is_word(*end, &["between"]);
        objects.len() == 1
            && second
            && self.placing_verb_before(start)
            && select::by_relation(self.scene, objects, Relation::On, targets, 1).is_none()
    }

    /// Applies a post-modifier to the candidates: the ones it keeps.
    ///
    /// # Errors
    /// A modifier that picks none, or cannot tell the candidates apart.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn apply_post(
        &self,
        p: Post,
        mut objects: Vec<usize>,
        ordinal: &mut Option<usize>,
        filter: bool,
        wanted: usize,
        head: &Head,
        text: &PostText<'_>,
    ) -> Result<Vec<usize>, GroundError> {
        let (at, words) = (text.at.to_string(), text.words);
        match p {
            Post::Floor => objects = self.keep_on_floor(objects, wanted, at)?,
            Post::Side(axis, sign) => {
                if let Some(o) = ordinal.take() {
                    let picked = select::nth(self.scene, &objects, o, Direction::Side(axis, sign))
                        .ok_or_else(|| self.too_close(&at, &objects, words))?;
                    objects = vec![picked];
                } else if filter {
                    objects = select::at_side(self.scene, &objects, axis, sign);
                } else {
                    let mut direction = glam::DVec3::ZERO;
                    direction[axis as usize] = sign;
                    objects = select::by_direction(
                        self.scene,
                        &objects,
                        direction,
                        wanted.min(objects.len()),
                    )
                    .ok_or_else(|| self.too_close(&at, &objects, words))?;
                }
            }
            Post::Room(place) => {
                let kept = select::in_room(self.scene, &objects, place).ok_or_else(|| {
                    if self.scene.bounds.is_none() {
                        GroundError::NoPick {
                            phrase: at.clone(),
                            reason: "the scene has no room (no \"bounds\") to be in".into(),
                        }
                    } else {
                        self.not_there(head, &objects, text)
                    }
                })?;
                objects = kept;
            }
            Post::Line(line) => {
                let columns = matches!(
                    line,
                    select::Line::Column(_) | select::Line::Middle { columns: true }
                );
                objects = select::in_line(self.scene, &objects, line).ok_or_else(|| {
                    GroundError::NoPick {
                        phrase: at.clone(),
                        reason: format!(
                            "{} do not stand in such rows or columns, or there is no such one; name one ('{}')",
                            error::list(&self.names(&objects)),
                            self.names(&objects[..1]).join("")
                        ),
                    }
                })?;
                // "the second desk in the front row": along the line as it is read, a row
                // from the left, a column from the front.
                if let Some(o) = ordinal.take() {
                    let from = if columns {
                        Direction::Side(words::Axis::Z, 1.0)
                    } else {
                        Direction::Side(words::Axis::X, -1.0)
                    };
                    let picked = select::nth(self.scene, &objects, o, from)
                        .ok_or_else(|| self.too_close(&at, &objects, words))?;
                    objects = vec![picked];
                }
            }
            Post::Lacks(targets) => objects = self.keep_lacking(objects, targets.as_deref(), at)?,
            Post::Middle => {
                let picked = select::middle(self.scene, &objects)
                    .ok_or_else(|| self.too_close(&at, &objects, "in the middle"))?;
                objects = vec![picked];
            }
            Post::From(direction) => {
                let o = ordinal.take().unwrap_or(1);
                let picked = select::nth(self.scene, &objects, o, direction)
                    .ok_or_else(|| self.too_close(&at, &objects, words))?;
                objects = vec![picked];
            }
            Post::FromObject(t) => {
                objects = select::by_relation(self.scene, &objects, Relation::From, &[t], wanted)
                    .ok_or_else(|| self.not_there(head, &objects, text))?;
            }
            Post::Relation(relation, targets) => {
                objects = select::by_relation(self.scene, &objects, relation, &targets, wanted)
                    .ok_or_else(|| self.not_there(head, &objects, text))?;
            }
        }
        Ok(objects)
    }

    /// The refusal for a post-modifier that keeps none of the candidates, or cannot tell
    /// one from the others.
    /// `objects` standing on the floor (resting on nothing), `wanted` of them (any number
    /// with `usize::MAX`); `at` is the phrase, for messages.
    fn keep_on_floor(
        &self,
        objects: Vec<usize>,
        wanted: usize,
        at: String,
    ) -> Result<Vec<usize>, GroundError> {
        let floor = self.scene.floor();
        let on_floor: Vec<usize> = objects
            .iter()
            .copied()
            .filter(|&o| {
                self.scene.objects[o].support.is_none()
                    && self.scene.objects[o].world_aabb().min.y <= floor + 0.05
            })
            .collect();
        if on_floor.is_empty() || (wanted != usize::MAX && on_floor.len() != wanted) {
            return Err(GroundError::NoPick {
                phrase: at,
                reason: format!(
                    "{} on the floor ({} of {})",
                    if on_floor.is_empty() {
                        "none is"
                    } else {
                        "not one is"
                    },
                    on_floor.len(),
                    error::list(&self.names(&objects))
                ),
            });
        }
        Ok(on_floor)
    }

    /// `objects` that nothing of `targets` rests on (nothing at all with `None`): "the
    /// table without a lamp", "the empty desk". The objects resting on something are found
    /// in one pass over the scene.
    fn keep_lacking(
        &self,
        objects: Vec<usize>,
        targets: Option<&[usize]>,
        at: String,
    ) -> Result<Vec<usize>, GroundError> {
        let carriers: std::collections::HashSet<usize> = self
            .scene
            .objects
            .iter()
            .enumerate()
            .filter(|(i, _)| targets.is_none_or(|t| t.contains(i)))
            .filter_map(|(_, u)| u.support)
            .collect();
        let kept: Vec<usize> = objects
            .iter()
            .copied()
            .filter(|o| !carriers.contains(o))
            .collect();
        if kept.is_empty() {
            return Err(GroundError::NoPick {
                phrase: at,
                reason: format!(
                    "every one has that on it ({})",
                    error::list(&self.names(&objects))
                ),
            });
        }
        Ok(kept)
    }

    fn not_there(&self, head: &Head, objects: &[usize], text: &PostText<'_>) -> GroundError {
        let words = text.words;
        GroundError::NoPick {
            phrase: text.at.to_string(),
            reason: if head.generic {
                format!("nothing is {words}")
            } else if objects.len() == 1 {
                format!("the {} is not {words}", self.name(objects[0]))
            } else {
                format!(
                    "no single {} is clearly {words} (the {} here are {})",
                    head.text,
                    error::plural(&head.text),
                    error::list(&self.names(objects))
                )
            },
        }
    }

    /// Whether a verb that puts an object somewhere stands right before token `k`
    /// (`put`, `move`, `place` — not `turn`, `take` or `swap`, which take no place).
    fn placing_verb_before(&self, k: usize) -> bool {
        k > 0
            && self.word(k - 1).is_some_and(|w| {
                words::is_verb(w)
                    && !words::turns_or_scales(w)
                    && !matches!(
                        super::verbs::verb(w),
                        Some((
                            super::verbs::Action::Scale
                                | super::verbs::Action::Swap
                                | super::verbs::Action::Align
                                | super::verbs::Action::Take,
                            _
                        ))
                    )
            })
    }

    /// Whether the clause goes on after token `k` with an amount, a direction or a place
    /// of its own: then a modifier before `k` describes the object rather than saying
    /// where it goes.
    fn clause_goes_on(&self, k: usize) -> bool {
        let place_or_amount = |w: &str| {
            words::side_word(w).is_some()
                || words::count_word(w).is_some()
                || matches!(
                    w,
                    "up" | "down"
                        | "upward"
                        | "upwards"
                        | "downward"
                        | "downwards"
                        | "forward"
                        | "forwards"
                        | "backward"
                        | "backwards"
                        | "ahead"
                        | "clockwise"
                        | "counterclockwise"
                        | "anticlockwise"
                        | "around"
                        | "degrees"
                        | "away"
                        | "closer"
                        | "nearer"
                        | "half"
                        | "twice"
                        | "towards"
                        | "toward"
                        | "further"
                        | "farther"
                        | "apart"
                        | "together"
                )
        };
        // Another destination right after ("move the mug on the shelf to the coffee
        // table"): the modifier was not where the object goes.
        if self.is_word(k, &["to", "onto", "into"]) {
            return true;
        }
        for t in &self.tokens[k.min(self.tokens.len())..] {
            match &t.kind {
                Kind::Punct(',' | ';' | '.' | '!' | '?') => return false,
                Kind::Number(_) => return true,
                Kind::Word(w) if matches!(w.as_str(), "and" | "then") => return false,
                Kind::Word(w) if place_or_amount(w) => return true,
                _ => {}
            }
        }
        false
    }

    /// Whether `p` is the floor and a relation follows it at `end`: "on the floor near the
    /// bin", "on the floor next to the desk" is one place to go, not the floor picking.
    fn floor_then_relation(&self, p: &Post, mut end: usize) -> bool {
        while self.is_word(end, &["somewhere", "just", "right", "roughly", "about"]) {
            end += 1;
        }
        matches!(p, Post::Floor)
            && (self.relation_at(end).is_some()
                || self.is_word(end, &["near", "by", "beside", "behind", "between"]))
    }

    /// Whether the phrase from token `start` to `end` is a topic the instruction names
    /// first and then says what to do with: no verb before it, and after it a dash, colon
    /// or comma and a verb ("the long bench against the left wall - pull it out a bit").
    /// Its modifier then says which object, never where it goes.
    fn topic_before(&self, start: usize, end: usize) -> bool {
        let separated = matches!(
            self.tokens.get(end).map(|t| &t.kind),
            Some(Kind::Punct(',' | '-' | '—' | '–' | ':' | ';'))
        );
        let verb_after = (end + 1..(end + 4).min(self.tokens.len()))
            .any(|k| self.word(k).is_some_and(words::is_verb));
        let verb_before = (0..start).any(|k| self.word(k).is_some_and(words::is_verb));
        separated && verb_after && !verb_before
    }

    /// The verb of the clause before token `k`, if any: the nearest verb back to the
    /// clause's start (a comma, `and`, `then` or a sentence end).
    pub(super) fn clause_verb_before(&self, k: usize) -> Option<&str> {
        for t in self.tokens[..k.min(self.tokens.len())].iter().rev() {
            match &t.kind {
                Kind::Punct(',' | ';' | '.' | '!' | '?') => return None,
                Kind::Word(w) if matches!(w.as_str(), "and" | "then") => return None,
                Kind::Word(w) if words::is_verb(w) => return Some(w),
                _ => {}
            }
        }
        None
    }

    /// Whether the verb of the clause before token `k` trades places (`swap`, `switch`):
    /// then `with` after its first object names the second, never what the first carries.
    pub(super) fn swap_verb_before(&self, k: usize) -> bool {
        self.clause_verb_before(k)
            .is_some_and(|w| matches!(super::verbs::verb(w), Some((super::verbs::Action::Swap, _))))
    }

    /// Whether the verb of the clause before token `k` takes no place to put the object
    /// (`rotate`, `scale`, `lift`, `spread`, `swap`): then `the tv on the stand` describes
    /// the tv.
    fn verb_takes_no_place(&self, k: usize) -> bool {
        // Moving objects apart or trading their places puts them nowhere.
        self.clause_verb_before(k).is_some_and(|w| {
            words::turns_or_scales(w)
                || matches!(
                    w,
                    "lift" | "raise" | "lower" | "elevate" | "spread" | "separate"
                )
        }) || self.swap_verb_before(k)
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::{means, refused, with_reader};

    #[test]
    fn the_clause_around_a_modifier_is_read() {
        with_reader("living_room", "put the book on the side table", |r| {
            assert!(r.placing_verb_before(1));
            assert!(!r.clause_goes_on(7));
            assert!(!r.verb_takes_no_place(1));
        });
        with_reader(
            "living_room",
            "rotate the tv on the tv stand 30 degrees",
            |r| {
                assert!(!r.placing_verb_before(1));
                assert!(r.clause_goes_on(7));
                assert!(r.verb_takes_no_place(1));
            },
        );
        // A clause ends at "and": what follows is not its amount.
        with_reader(
            "living_room",
            "move the book on the table and 2 chairs",
            |r| {
                assert!(!r.clause_goes_on(6));
            },
        );
    }

    #[test]
    fn a_relation_is_a_destination_when_the_noun_is_already_one_object() {
        // One remote: "on the side table" is where it goes, and both are bound.
        means(
            "living_room",
            "put the remote on the side table",
            &[&["remote control"], &["side table"]],
        );
        // With no amount or place after it, it is where the book goes.
        means(
            "living_room",
            "put the book on the side table",
            &[&["book"], &["side table"]],
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
        // One book, and the clause goes on ("left"): "on the coffee table" describes it.
        means(
            "living_room",
            "move the book on the coffee table left",
            &[&["book"]],
        );
        // A description that does not hold is refused.
        refused(
            "living_room",
            "move the book on the side table 10 cm left",
            &["book", "side table"],
        );
    }

    #[test]
    fn after_a_verb_of_placing_a_relation_that_would_pick_is_refused() {
        // Two speakers: "next to the sofa" is where a speaker goes, not which.
        refused(
            "living_room",
            "put the speaker next to the sofa",
            &["speaker", "speaker 2"],
        );
    }
}

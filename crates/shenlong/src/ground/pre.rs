//! Premodifiers: the words between a determiner and its head, and what they pick.
//!
//! `the two stools` says how many; `the third chair` counts (from a side it still waits
//! for); `the red chair`, `the teacher's desk` keep the objects a word of the name or an
//! attribute describes; `the other chair` leaves out the one named before (or the one the
//! objects named before stand on); `the left speaker`, `the bigger box`, `the middle
//! chair` pick by place and size, each needing a clear winner. Words before a head with no
//! determiner before them are not read as modifiers (`turn left chair 3`).

use super::error::{self, GroundError};
use super::select::{self, Direction, SizeError};
use super::{modifier, words, Head, Reader, Reason};
use words::{Count, Kind};

/// What the modifiers before a noun say, read from the words.
#[derive(Debug, Default)]
pub(super) struct Premods {
    /// A number or a count word: how many (`the two chairs`).
    pub count: Option<Count>,
    /// "the second …", waiting for a direction.
    pub ordinal: Option<usize>,
    /// "left", "front-right": (axis, sign, the word).
    pub sides: Vec<(words::Axis, f64, String)>,
    /// "bigger", "tallest".
    pub sizes: Vec<String>,
    /// "the middle …".
    pub middle: bool,
    /// "the end stools", "the two end tables": the first and last of a line.
    pub ends: bool,
    /// "the red and blue cushions", "the left and right tables": the words before the
    /// noun are alternatives, each naming some of the objects.
    pub either: bool,
    /// Words that keep the objects they describe, in order: `other`, and words of names
    /// or attributes (`red`, `teacher`).
    pub picks: Vec<String>,
}

impl Premods {
    /// Whether modifiers by place or size (sides, sizes, middle) pick.
    pub fn selectors(&self) -> bool {
        !self.sides.is_empty() || !self.sizes.is_empty() || self.middle || self.ends
    }
}

impl Reader<'_> {
    /// Whether token `k` can be a modifier before a head: a number, a side, a size, an
    /// ordinal, a count, a colour, `other`, `middle`, or a word that describes some object.
    pub(super) fn is_premodifier(&self, k: usize) -> bool {
        if self.consumed[k] {
            return false;
        }
        match &self.tokens[k].kind {
            Kind::Number(_) if self.measure_at(k) => true,
            Kind::Number(x) => x.fract() == 0.0 && *x >= 1.0 && *x <= 100.0,
            // The unit of a size said before the noun: "the 65 inch tv".
            Kind::Word(_) if k > 0 && self.measure_at(k - 1) => true,
            Kind::Word(w) if words::is_determiner(w) => false,
            Kind::Word(w) => {
                let w = w.trim_end_matches("'s");
                words::side_parts(w).is_some()
                    || words::normalize(w).is_empty()
                    || words::size_word(w).is_some()
                    || words::shape_word(w).is_some()
                    || matches!(w, "empty" | "bare")
                    || words::ordinal(w).is_some()
                    || words::count_word(w).is_some()
                    || matches!(
                        w,
                        "other"
                            | "middle"
                            | "end"
                            | "center"
                            | "centre"
                            | "far"
                            | "same"
                            | "whole"
                            | "entire"
                    )
                    || words::is_colour(w)
                    || words::is_colour(&words::normalize(w))
                    || self
                        .g
                        .index
                        .descriptor_words
                        .contains(words::normalize(w).as_str())
            }
            _ => false,
        }
    }

    /// Whether token `k` is the `and` (or comma) between two colours or two sides before
    /// a plural noun: "the red and blue cushions", "the left and right tables".
    pub(super) fn coordinates(&self, k: usize) -> bool {
        let joins = self.is_word(k, &["and"]) || matches!(self.tokens[k].kind, Kind::Punct(','));
        let alike = |i: usize| {
            self.word(i).is_some_and(|w| {
                words::is_colour(w) || words::side_word(w).is_some_and(|(a, _)| a != words::Axis::Y)
            }) && !self.consumed[i]
        };
        joins && k > 0 && alike(k - 1) && alike(k + 1) && {
            // Only before a plural head, after the colours or sides.
            let mut j = k + 1;
            while alike(j) || (j > k + 1 && self.coordinates_at_plain(j)) {
                j += 1;
            }
            self.head_at(j).is_some_and(|h| h.plural)
        }
    }

    /// A joining word at `j` (for [`Self::coordinates`]'s walk over a list).
    fn coordinates_at_plain(&self, j: usize) -> bool {
        self.is_word(j, &["and"])
            || matches!(self.tokens.get(j).map(|t| &t.kind), Some(Kind::Punct(',')))
    }

    /// Where the modifiers before the head at `h` start, when a determiner opens them; else
    /// `h` itself.
    pub(super) fn premodifier_start(&self, h: usize) -> usize {
        let mut k = h;
        while k > 0 && (self.is_premodifier(k - 1) || self.coordinates(k - 1)) {
            k -= 1;
        }
        if k < h && !(k > 0 && self.word(k - 1).is_some_and(words::is_determiner)) {
            // Modifiers with no determiner before them are not read as modifiers.
            return h;
        }
        k
    }

    /// Whether token `k` is a number and the next a unit of length, right before a noun: a
    /// size said before it ("the 65 inch tv", "the 2 m table").
    fn measure_at(&self, k: usize) -> bool {
        matches!(self.tokens[k].kind, Kind::Number(_))
            && self.is_word(
                k + 1,
                &["inch", "in", "inches", "cm", "m", "mm", "ft", "foot"],
            )
            && self.head_at(k + 2).is_some()
    }

    /// Reads the modifiers at tokens `at` (in order).
    pub(super) fn premodifiers(&self, at: &[usize]) -> Premods {
        let mut mods = Premods::default();
        for &m in at {
            match &self.tokens[m].kind {
                // "the 65 inch tv": a size the name says, not a count.
                Kind::Number(_) if self.measure_at(m) => {}
                Kind::Word(_) if m > 0 && self.measure_at(m - 1) => {}
                Kind::Number(x) => mods.count = Some(Count::Exactly(*x as usize)),
                Kind::Punct(',') => mods.either = true,
                Kind::Word(w) if w == "and" => mods.either = true,
                Kind::Word(w) => {
                    let w = w.trim_end_matches("'s");
                    if let Some(n) = words::count_word(w) {
                        mods.count = Some(Count::Exactly(n));
                    } else if let Some(o) = words::ordinal(w) {
                        mods.ordinal = Some(o);
                    } else if matches!(w, "same" | "whole" | "entire") {
                        // "the same chair", "the whole credenza" (with what is on it, as
                        // always): no pick.
                    } else if let Some(parts) = words::side_parts(w) {
                        mods.sides
                            .extend(parts.into_iter().map(|(a, s)| (a, s, w.to_string())));
                    } else if words::size_word(w).is_some() {
                        mods.sizes.push(w.to_string());
                    } else if matches!(w, "middle" | "center" | "centre") {
                        mods.middle = true;
                    } else if w == "end" {
                        mods.ends = true;
                    } else {
                        mods.picks.push(w.to_string());
                    }
                }
                _ => {}
            }
        }
        mods
    }

    /// The candidates the words of [`Premods::picks`] keep, in order: `other` leaves out
    /// the objects named before (`bound`); a word of a name or an attribute keeps the
    /// objects it describes. `start` is where the phrase starts, for messages.
    ///
    /// # Errors
    /// A colour or material that no candidate has.
    pub(super) fn pick_by_words(
        &self,
        head: &Head,
        picks: &[String],
        mut objects: Vec<usize>,
        reasons: &mut Vec<Reason>,
        bound: &[usize],
        start: usize,
    ) -> Result<Vec<usize>, GroundError> {
        for w in picks {
            if w == "other" {
                objects = self.pick_other(objects, reasons, bound);
                continue;
            }
            let d = words::normalize(w);
            let shape = words::shape_word(w);
            // "the empty coffee table": nothing rests on it (what carries something,
            // found in one pass).
            let empty = matches!(w.as_str(), "empty" | "bare");
            let carriers: std::collections::HashSet<usize> = if empty {
                self.scene
                    .objects
                    .iter()
                    .filter_map(|u| u.support)
                    .collect()
            } else {
                std::collections::HashSet::new()
            };
            let fits: Vec<usize> = objects
                .iter()
                .copied()
                .filter(|&o| match shape {
                    _ if empty => !carriers.contains(&o),
                    Some(shape) => select::has_shape(self.scene, o, shape),
                    None => self.g.index.describes(o, &d),
                })
                .collect();
            if fits.is_empty() {
                // A colour or material must pick; a word of another object's
                // name ("the dining chair") says nothing about these.
                if words::is_colour(w)
                    || words::is_colour(&d)
                    || shape.is_some()
                    || empty
                    || self.g.index.attribute_words.contains(d.as_str())
                {
                    return Err(GroundError::NoPick {
                        phrase: self.span_text(&(start..head.range.end)),
                        reason: format!(
                            "no {} is {d}: the {} here are {}",
                            head.text,
                            error::plural(&head.text),
                            error::list(&self.names(&objects))
                        ),
                    });
                }
            } else {
                if fits.len() < objects.len() {
                    reasons.push(modifier(&format!(
                        "\"{w}\" picked {}",
                        error::list(&self.names(&fits))
                    )));
                }
                objects = fits;
            }
        }
        Ok(objects)
    }

    /// `other`: the candidates not named before (`bound`), or else not the ones the
    /// objects named before stand on ("put the lamp on the other nightstand").
    fn pick_other(
        &self,
        mut objects: Vec<usize>,
        reasons: &mut Vec<Reason>,
        bound: &[usize],
    ) -> Vec<usize> {
        let before = objects.len();
        objects.retain(|o| !bound.contains(o));
        if objects.len() < before {
            reasons.push(modifier("\"other\": not the one named before"));
        } else {
            // "put the lamp on the other nightstand": not the one the
            // objects named before stand on.
            let supports: Vec<usize> = bound
                .iter()
                .filter_map(|&b| self.scene.objects[b].support)
                .collect();
            objects.retain(|o| !supports.contains(o));
            if objects.len() < before {
                reasons.push(modifier("\"other\": not the one it stands on now"));
            }
        }
        objects
    }

    /// Selection: the candidates the modifiers before the noun keep — by side (with an
    /// ordinal, the n-th from that side), by size, in the middle — each needing a clear
    /// winner. `phrase` is the phrase so far, for messages.
    ///
    /// # Errors
    /// A modifier that cannot tell the candidates apart.
    pub(super) fn pick_by_premodifiers(
        &self,
        head: &Head,
        count: Count,
        mods: &mut Premods,
        mut objects: Vec<usize>,
        reasons: &mut Vec<Reason>,
        phrase: &str,
    ) -> Result<Vec<usize>, GroundError> {
        if mods.either && mods.sides.len() > 1 {
            // "the left and right tables": the one furthest each way.
            let mut union: Vec<usize> = Vec::new();
            for (axis, sign, w) in &mods.sides {
                let mut direction = glam::DVec3::ZERO;
                direction[*axis as usize] = *sign;
                let one = select::by_direction(self.scene, &objects, direction, 1)
                    .ok_or_else(|| self.too_close(phrase, &objects, w))?;
                for o in one {
                    if !union.contains(&o) {
                        union.push(o);
                    }
                }
            }
            reasons.push(modifier(&format!(
                "each side picked {}",
                error::list(&self.names(&union))
            )));
            objects = union;
        } else if !mods.sides.is_empty() {
            objects = self.pick_by_sides(count, mods, objects, reasons, phrase)?;
        }
        for w in &mods.sizes {
            objects = self.pick_by_size(head, count, w, objects, reasons, phrase)?;
        }
        if mods.ends && objects.len() > 2 {
            let picked = select::ends(self.scene, &objects)
                .ok_or_else(|| self.too_close(phrase, &objects, "at the ends"))?;
            reasons.push(modifier(&format!(
                "\"end\" picked {}",
                error::list(&self.names(&picked))
            )));
            objects = picked;
        }
        if mods.middle && objects.len() > 1 {
            let picked = select::middle(self.scene, &objects)
                .ok_or_else(|| self.too_close(phrase, &objects, "in the middle"))?;
            reasons.push(modifier(&format!(
                "\"middle\" picked {}",
                self.name(picked)
            )));
            objects = vec![picked];
        }
        Ok(objects)
    }

    /// The candidates at the sides of [`Premods::sides`]: the n-th from that side after
    /// an ordinal (which it uses up), every one at that end for a group, else as many as
    /// asked for nearest that end.
    fn pick_by_sides(
        &self,
        count: Count,
        mods: &mut Premods,
        mut objects: Vec<usize>,
        reasons: &mut Vec<Reason>,
        phrase: &str,
    ) -> Result<Vec<usize>, GroundError> {
        let mut words_used: Vec<String> = mods.sides.iter().map(|s| s.2.clone()).collect();
        words_used.dedup();
        let label = words_used.join(" ");
        if let (Some(o), [(axis, sign, _)]) = (mods.ordinal, mods.sides.as_slice()) {
            // "the second left chair": the second from the left.
            let picked = select::nth(self.scene, &objects, o, Direction::Side(*axis, *sign))
                .ok_or_else(|| self.too_close(phrase, &objects, &label))?;
            objects = vec![picked];
            mods.ordinal = None;
        } else {
            let mut direction = glam::DVec3::ZERO;
            for (axis, sign, _) in &mods.sides {
                let mut unit = glam::DVec3::ZERO;
                unit[*axis as usize] = *sign;
                if direction.dot(unit) <= 0.0 {
                    direction += unit;
                }
            }
            if matches!(count, Count::All) {
                // "the front chairs": every one at that end.
                objects = select::at_direction(self.scene, &objects, direction);
            } else {
                let n = count.wanted(objects.len());
                let picked = select::by_direction(self.scene, &objects, direction, n)
                    .ok_or_else(|| self.too_close(phrase, &objects, &label))?;
                objects = picked;
            }
        }
        reasons.push(modifier(&format!(
            "\"{label}\" picked {}",
            error::list(&self.names(&objects))
        )));
        Ok(objects)
    }

    /// The candidates the size word `w` keeps: as many as asked for, clearly the
    /// biggest (or smallest, tallest…).
    fn pick_by_size(
        &self,
        head: &Head,
        count: Count,
        w: &str,
        objects: Vec<usize>,
        reasons: &mut Vec<Reason>,
        phrase: &str,
    ) -> Result<Vec<usize>, GroundError> {
        let (measure, sign, degree) = words::size_word(w).expect("a size word");
        if matches!(count, Count::All) && objects.len() > 1 {
            // "the small boxes": the few that stand out as small.
            if degree == words::Degree::Plain {
                if let Some(group) = select::by_size_group(self.scene, &objects, measure, sign) {
                    reasons.push(modifier(&format!(
                        "\"{w}\" picked {}",
                        error::list(&self.names(&group))
                    )));
                    return Ok(group);
                }
            }
            return Err(GroundError::NoPick {
                phrase: phrase.to_string(),
                reason: format!(
                    "say how many ('the two {} {}') or name them",
                    superlative(w),
                    error::plural(&head.text)
                ),
            });
        }
        let n = count.wanted(objects.len());
        let picked =
            select::by_size(self.scene, &objects, measure, sign, degree, n).map_err(|e| {
                GroundError::NoPick {
                    phrase: phrase.to_string(),
                    reason: match e {
                        SizeError::ComparesTwo => format!(
                            "\"{w}\" compares two, but {} {} fit ({}); say 'the {}' or name one",
                            objects.len(),
                            error::plural(&head.text),
                            error::list(&self.names(&objects)),
                            superlative(w)
                        ),
                        SizeError::TooClose => format!(
                            "{} are too close in size to tell which is {w}; name one ('{}')",
                            error::list(&self.names(&objects)),
                            self.name(objects[0])
                        ),
                        SizeError::Several(group) => format!(
                            "{} are all {w}; name one ('{}')",
                            error::list(&self.names(&group)),
                            self.name(group[0])
                        ),
                    },
                }
            })?;
        if picked.len() < objects.len() {
            reasons.push(modifier(&format!(
                "\"{w}\" picked {}",
                error::list(&self.names(&picked))
            )));
        }
        Ok(picked)
    }
}

/// The superlative of a size word, for messages (`bigger` → `biggest`).
fn superlative(w: &str) -> String {
    match w {
        "big" | "bigger" => "biggest".into(),
        "large" | "larger" => "largest".into(),
        "small" | "smaller" | "little" | "tiny" => "smallest".into(),
        "tall" | "taller" => "tallest".into(),
        "short" | "shorter" => "shortest".into(),
        "long" | "longer" => "longest".into(),
        "wide" | "wider" => "widest".into(),
        "narrow" | "narrower" => "narrowest".into(),
        other => other.into(),
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::{means, refused, with_reader};
    use super::*;

    /// The modifiers before the head at token `h` of `text`, read.
    fn premods(text: &str, h: usize) -> Premods {
        with_reader("living_room", text, |r| {
            let first = r.premodifier_start(h);
            r.premodifiers(&(first..h).collect::<Vec<_>>())
        })
    }

    #[test]
    fn the_words_before_a_head_are_read() {
        let m = premods("move the two front-left red chairs", 5);
        assert_eq!(m.count, Some(Count::Exactly(2)));
        assert_eq!(m.sides.len(), 2);
        assert_eq!(m.picks, ["red"]);
        let m = premods("move the second biggest box", 4);
        assert_eq!((m.ordinal, m.sizes), (Some(2), vec!["biggest".to_string()]));
        // With no determiner before them, they are no modifiers.
        let m = premods("turn left speaker 2", 2);
        assert!(m.sides.is_empty());
    }

    #[test]
    fn sides_pick_one_or_the_ones_at_that_end() {
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
            "dining_room",
            "move the front left chair back",
            &[&["chair 3"]],
        );
        means(
            "dining_room",
            "move the front chairs 20 cm forward",
            &[&["chair 3", "chair 4"]],
        );
        // Two plates at the same x cannot be told apart by "left".
        refused("dining_room", "move the left plate", &["plate"]);
    }

    #[test]
    fn sizes_and_the_middle_need_a_clear_winner() {
        means(
            "living_room",
            "move the bigger lamp left",
            &[&["floor lamp"]],
        );
        means(
            "classroom",
            "move the middle student chair back",
            &[&["student chair 2"]],
        );
        // Equal speakers: "taller" cannot pick.
        refused(
            "living_room",
            "move the taller speaker",
            &["speaker", "speaker 2"],
        );
        refused("dining_room", "lift the biggest chairs", &["say how many"]);
    }

    #[test]
    fn words_of_names_and_attributes_keep_what_they_describe() {
        let text = r#"{"objects": [
            {"name": "obj_17", "category": "armchair", "color": "red", "size": [1, 1, 1], "position": [-1, 0, 0]},
            {"name": "obj_18", "category": "armchair", "color": "blue", "size": [1, 1, 1], "position": [1, 0, 0]}
        ]}"#;
        let s = crate::format::json::read(text, "t").unwrap().scene;
        let grounder = super::super::Grounder::new(&s);
        let reader = Reader::new(&grounder, &s, "the red armchair");
        let head = reader.head_at(2).unwrap();
        let mut reasons = Vec::new();
        let picks = ["red".to_string()];
        let kept = reader
            .pick_by_words(&head, &picks, head.literal.clone(), &mut reasons, &[], 0)
            .unwrap();
        assert_eq!(reader.names(&kept), ["obj_17"]);
        let picks = ["green".to_string()];
        let e = reader
            .pick_by_words(&head, &picks, head.literal.clone(), &mut reasons, &[], 0)
            .unwrap_err();
        assert!(e.to_string().contains("no armchair is green"), "{e}");
        // "other": not the one named before, or not the one it stands on now.
        means(
            "living_room",
            "move the right speaker back and the other speaker forward",
            &[&["speaker 2"], &["speaker"]],
        );
        means(
            "bedroom",
            "put the lamp on the other nightstand",
            &[&["bedside lamp"], &["nightstand 2"]],
        );
    }
}

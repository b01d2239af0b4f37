//! Heads: the noun a phrase is built around, and the objects it names before any modifier
//! picks among them.
//!
//! A head is, longest words first: an object's name as the tool exported it
//! (`Lamp_Table.003`, only that object); a name, alias, category or synonym, or the plural
//! of one (`the couch`, `the hammers`); a name and an instance number (`wood chair 001`);
//! a name written without its spaces (`dogbed`); a generic noun that needs a modifier to
//! say which (`everything`, `the thing`). `one`, `ones` and `others` stand for the noun of
//! the phrase before (`the other one`). A number followed by a unit ends the words of a
//! head (`the speaker 2 m to the left` is no 'speaker 2'), and a word that is a noun
//! only after a determiner ("can you…", "turn it counter clockwise") opens no phrase.

use super::index::{self, Hit, Tier};
use super::profile;
use super::{grammar_word, words, Head, Np, Reader, Reason, ReasonKind};
use std::ops::Range;
use words::Kind;

/// The nouns of a collection of things, named by the things: a 'magazine stack' is "the
/// magazines".
const COLLECTIONS: &[&str] = &["stack", "pile", "heap", "bundle", "set", "bunch", "pair"];

impl Reader<'_> {
    /// An object's name typed as the tool exported it (`Chair_Wood`, `Lamp_Table.003`):
    /// that object only, not its family.
    fn identifier_at(&self, k: usize) -> Option<Head> {
        let w = self.word(k)?;
        if !w.contains(['_', '.']) {
            return self.capitalised_at(k);
        }
        // Unity's copies: `Lamp_Bedside (1)` is its own object, never `Lamp_Bedside`.
        let copy = matches!(
            (
                self.tokens.get(k + 1).map(|t| &t.kind),
                self.tokens.get(k + 2).map(|t| &t.kind),
                self.tokens.get(k + 3).map(|t| &t.kind),
            ),
            (
                Some(Kind::Punct('(')),
                Some(Kind::Number(_)),
                Some(Kind::Punct(')'))
            )
        );
        let end = if copy { k + 4 } else { k + 1 };
        let raw = &self.text[self.tokens[k].span.start..self.tokens[end - 1].span.end];
        let object = self.scene.find(raw)?;
        Some(self.exact_name_head(k..end, object, raw))
    }

    /// An object's one-word name typed as it is written, capital and all, with no
    /// determiner before it (`put Suzanne on Cube` beside `Cube.001` … `Cube.010`): that
    /// object, not every cube. Not before a number (`Chair 2` is chair 2).
    fn capitalised_at(&self, k: usize) -> Option<Head> {
        let span = self.tokens[k].span.clone();
        let raw = self.text.get(span)?;
        let &object = self.g.index.capitalised.get(raw)?;
        let determiner = k > 0 && self.word(k - 1).is_some_and(words::is_determiner);
        let numbered = matches!(
            self.tokens.get(k + 1).map(|t| &t.kind),
            Some(Kind::Number(_))
        );
        if determiner || numbered {
            return None;
        }
        Some(self.exact_name_head(k..k + 1, object, raw))
    }

    /// The head of one object's own name typed at tokens `range` (`raw` as written): that
    /// object only, literally too.
    fn exact_name_head(&self, range: Range<usize>, object: usize, raw: &str) -> Head {
        let mut head = self.make_head(
            range,
            vec![object],
            Tier::Name,
            false,
            words::normalize(raw),
            raw,
            None,
        );
        head.literal = vec![object];
        head
    }

    /// The longest name, category or synonym starting at token `k`.
    pub(super) fn head_at(&self, k: usize) -> Option<Head> {
        if k >= self.tokens.len() {
            return None;
        }
        // "the tall object", "the thing by the door": a word for any object, even where
        // an exported name holds it (`Object_3`), unless a number makes it that name.
        let numbered = matches!(
            self.tokens.get(k + 1).map(|t| &t.kind),
            Some(Kind::Number(_))
        ) && !self.unit_follows(k + 2);
        if !numbered {
            if let Some(generic) = self.generic_at(k) {
                return Some(generic);
            }
        }
        if let Some(head) = self.identifier_at(k) {
            return Some(head);
        }
        let (pieces, ends) = self.name_pieces(k)?;
        (1..=pieces.len())
            .rev()
            .find_map(|len| self.head_of_words(k..ends[len - 1], &pieces[..len]))
            .or_else(|| self.generic_at(k))
            .or_else(|| self.profile_at(k))
    }

    /// A word for what an object looks like at token `k` (`table`, `bench`, `stack`) that
    /// no name answers to: the objects with names that say nothing whose box fits it
    /// ([`profile`](super::profile)).
    fn profile_at(&self, k: usize) -> Option<Head> {
        let w = self.word(k)?;
        let (profile, plural, one) = profile::noun(w)?;
        if self.g.index.anonymous.is_empty() {
            return None;
        }
        let loads = self.scene.resting_on_each();
        let anonymous = &self.g.index.anonymous;
        let objects: Vec<usize> = if profile == profile::Profile::Seat {
            profile::seats(self.scene, anonymous, &loads)
        } else {
            anonymous
                .iter()
                .copied()
                .filter(|&o| profile::fits(self.scene, o, &loads[o], profile))
                .collect()
        };
        if objects.is_empty() {
            return None;
        }
        let text = one.to_string();
        Some(Head {
            range: k..k + 1,
            literal: objects.clone(),
            objects,
            generic: false,
            tier: Tier::Hypernym,
            plural,
            reason: Reason {
                kind: ReasonKind::Category,
                detail: format!(
                    "\"{w}\": by its box, a {text} (its name says nothing of what it is)"
                ),
            },
            text,
            typo: None,
        })
    }

    /// The words from token `k` that may be part of a name (a `#` or `number` before a
    /// number is skipped), each with the token after it; `None` when token `k` is none.
    fn name_pieces(&self, k: usize) -> Option<(Vec<&str>, Vec<usize>)> {
        let max = self.g.index.max_words + 1;
        let mut pieces: Vec<&str> = Vec::new();
        let mut ends: Vec<usize> = Vec::new();
        let mut j = k;
        while j < self.tokens.len() && pieces.len() < max * 2 && !self.consumed[j] {
            // "the box 2 m to the right": a number with a unit is an amount, not a name's.
            if matches!(self.tokens[j].kind, Kind::Number(_)) && self.unit_follows(j + 1) {
                break;
            }
            match &self.words[j] {
                Some(w) if w.is_empty() && j > k => {}
                Some(w) if !w.is_empty() => {
                    pieces.push(w);
                    ends.push(j + 1);
                }
                _ => break,
            }
            j += 1;
        }
        if pieces.is_empty() || self.words[k].as_deref().is_none_or(str::is_empty) {
            return None;
        }
        Some((pieces, ends))
    }

    /// The head the words `pieces` (tokens `range`) make, if they name something: a name,
    /// category or synonym (or the plural of one), a name and an instance number, or a
    /// name written without its spaces.
    fn head_of_words(&self, range: Range<usize>, pieces: &[&str]) -> Option<Head> {
        let index = &self.g.index;
        let phrase = pieces.join(" ");
        let typo = self.typo_in(&range);
        if let Some((objects, end)) = self.numbered_list(range.end, &phrase) {
            return Some(self.make_head(
                range.start..end,
                objects,
                Tier::Name,
                true,
                phrase.clone(),
                &phrase,
                typo.clone(),
            ));
        }
        if let Some(head) = self.named_head(range.clone(), pieces, &phrase, typo.as_ref()) {
            return Some(head);
        }
        // "wood chair 001": a name as it reads and an instance number.
        let (base, number) = words::split_number(&phrase);
        if let Some(objects) = number.and_then(|n| index.numbered(base, n)) {
            return Some(self.make_head(
                range,
                objects,
                Tier::Name,
                false,
                phrase.clone(),
                &phrase,
                typo,
            ));
        }
        if phrase.contains(' ') || phrase.chars().count() >= 4 {
            if let Some(objects) = index.lookup_compact(&phrase) {
                let head = self.make_head(
                    range,
                    objects,
                    Tier::Name,
                    false,
                    phrase.clone(),
                    &phrase,
                    typo,
                );
                return Some(Head {
                    reason: Reason {
                        kind: ReasonKind::Variant,
                        detail: format!(
                            "\"{}\" is written like the name",
                            self.span_text(&head.range)
                        ),
                    },
                    ..head
                });
            }
        }
        None
    }

    /// The head of the words `pieces` (tokens `range`, normalised as `phrase`) as the
    /// index has them: a name, alias, category or synonym, or the plural of one.
    fn named_head(
        &self,
        range: Range<usize>,
        pieces: &[&str],
        phrase: &str,
        typo: Option<&Reason>,
    ) -> Option<Head> {
        let index = &self.g.index;
        // A plural reads as the plural of a name before it reads as a synonym that
        // happens to be written the same ("eggs" among WordNet's words for an egg).
        // A possessive written without its apostrophe ("the teachers chair") reads as
        // the name it is one letter from.
        let direct = index
            .lookup(phrase)
            .or_else(|| self.possessive_name(pieces));
        let plural = self
            .g
            .lexicon
            .singulars(phrase)
            .into_iter()
            .find_map(|singular| index.lookup(&singular).map(|hit| (singular, hit)));
        // (the hit, whether it is read as a plural, and the singular it was read as)
        let chosen = match (direct, plural) {
            (Some(hit), plural) if plural.as_ref().is_none_or(|(_, p)| hit.tier < p.tier) => {
                Some((hit, false, None))
            }
            (_, Some((singular, hit))) => Some((hit, true, Some(singular))),
            _ => self.collective(phrase),
        };
        // A word of a name said alone is the object only where no noun follows it
        // ("the dining chair" is no 'DiningTable', "the coffee grinder" no
        // 'CoffeeMachine'), and only as written ("stick" is no typo of 'Books_Stack').
        let (hit, plural, singular) = chosen.filter(|(hit, _, _)| {
            hit.tier != Tier::NameWord || (typo.is_none() && !self.noun_at(range.end))
        })?;
        let via = hit.via.to_string();
        let text = singular.unwrap_or_else(|| phrase.to_string());
        Some(self.make_head(
            range,
            hit.objects,
            hit.tier,
            plural,
            text,
            &via,
            typo.cloned(),
        ))
    }

    /// "the magazines" for a 'magazine stack', "the books" for a 'book pile': a plural
    /// that names nothing read as a collection of those things, one object ([`COLLECTIONS`]).
    /// The hit, read as a plural, and the name it was read as.
    fn collective(&self, phrase: &str) -> Option<(Hit<'_>, bool, Option<String>)> {
        let index = &self.g.index;
        self.g
            .lexicon
            .singulars(phrase)
            .into_iter()
            .find_map(|singular| {
                COLLECTIONS.iter().find_map(|c| {
                    let name = format!("{singular} {c}");
                    index.lookup(&name).map(|hit| (hit, true, Some(name)))
                })
            })
    }

    /// Whether the phrase starting at token `start` is a partitive opening its clause
    /// ("of the two stools, …"): the group a later "one" picks from.
    fn partitive(&self, start: usize) -> bool {
        start > 0
            && self.is_word(start - 1, &["of"])
            && (start == 1 || matches!(self.tokens[start - 2].kind, Kind::Punct(_)))
    }

    /// The typo corrected among tokens `range`, as a reason.
    fn typo_in(&self, range: &Range<usize>) -> Option<Reason> {
        range.clone().find_map(|t| {
            self.typos[t].as_ref().map(|from| Reason {
                kind: ReasonKind::Typo,
                detail: format!(
                    "\"{from}\" read as \"{}\"",
                    self.words[t].as_deref().unwrap_or("")
                ),
            })
        })
    }

    /// A generic noun at token `k` (`everything`, `the things`, `the thing`, `whatever`):
    /// every object, for the modifier after it to say which.
    fn generic_at(&self, k: usize) -> Option<Head> {
        // ("object" is also a prefix exported names carry, which name matching drops.)
        let w = self
            .words
            .get(k)?
            .as_deref()
            .filter(|w| !w.is_empty())
            .or_else(|| self.word(k))
            .unwrap_or("");
        // "the thing on the cupboard" is one object; "everything on the shelf", "whatever's
        // on top of the bookcase" all that the modifier names.
        // "with its stuff", "their things": what is on them, which the translator reads.
        if k > 0 && self.is_word(k - 1, &["its", "their"]) {
            return None;
        }
        let plural = match w {
            "everything" | "things" | "stuff" | "items" | "objects" | "whatever" | "whatever's" => {
                true
            }
            "thing" | "item" | "object" => false,
            _ => return None,
        };
        let all: Vec<usize> = (0..self.scene.objects.len()).collect();
        Some(Head {
            range: k..k + 1,
            literal: all.clone(),
            objects: all,
            generic: true,
            tier: Tier::Category,
            plural,
            text: "thing".into(),
            reason: Reason {
                kind: ReasonKind::Group,
                detail: format!("\"{w}\": the objects the modifier names"),
            },
            typo: None,
        })
    }

    /// A plural kind and several instance numbers (`desks 3 to 6`, `stools 1 and 4`,
    /// `tables 1, 2 and 5`): `phrase` ends in the first number and the list goes on from
    /// token `end`. The objects of every number and the token after the list; `None`
    /// unless every number names one object of the kind. A range typed as one word,
    /// `chairs 9-12`, comes from `lex` as its two numbers and the dash.
    fn numbered_list(&self, end: usize, phrase: &str) -> Option<(Vec<usize>, usize)> {
        const MAX_RANGE: u32 = 200;
        let (base, last) = phrase.rsplit_once(' ')?;
        let mut numbers = vec![last.parse::<u32>().ok()?];
        let number_at = |k: usize| match self.tokens.get(k).map(|t| &t.kind) {
            Some(Kind::Number(n)) if n.fract() == 0.0 && *n >= 0.0 && !self.unit_follows(k + 1) => {
                u32::try_from(*n as u64).ok()
            }
            _ => None,
        };
        let mut j = end;
        loop {
            let joiner = if self.is_word(j, &["and", "&"]) {
                1
            } else if matches!(self.tokens.get(j).map(|t| &t.kind), Some(Kind::Punct(','))) {
                if self.is_word(j + 1, &["and"]) {
                    2
                } else {
                    1
                }
            } else {
                0
            };
            let range_word = self.is_word(j, &["to", "through", "thru"])
                || matches!(
                    self.tokens.get(j).map(|t| &t.kind),
                    Some(Kind::Punct('-' | '–'))
                );
            if joiner > 0 {
                if let Some(n) = number_at(j + joiner) {
                    numbers.push(n);
                    j += joiner + 1;
                    continue;
                }
            } else if range_word {
                let from = *numbers.last()?;
                if let Some(to) = number_at(j + 1).filter(|&t| t > from && t - from <= MAX_RANGE) {
                    numbers.extend(from + 1..=to);
                    j += 2;
                    continue;
                }
            }
            break;
        }
        // Only a plural kind takes a list ("desks 3 and 4"): "swap desk 3 and 4", "desk 3
        // to 5" may be two things or a destination.
        let plural =
            !self.g.lexicon.singulars(base).is_empty() || !words::singular(base).is_empty();
        if numbers.len() < 2 || !plural {
            return None;
        }
        let mut bases = vec![base.to_string()];
        bases.extend(self.g.lexicon.singulars(base));
        bases.extend(words::singular(base));
        bases.into_iter().find_map(|b| {
            let mut objects: Vec<usize> = Vec::new();
            // Each number one object: "seats 3 and 4" over chairs and stools numbered
            // alike says nothing clear.
            for &n in &numbers {
                match self.g.index.numbered(&b, n)?.as_slice() {
                    [one] => objects.push(*one),
                    _ => return None,
                }
            }
            objects.sort_unstable();
            objects.dedup();
            Some((objects, j))
        })
    }

    /// A head of the objects a phrase names at `tier`, with the reason it names them
    /// (`via`: the word of the object it came through) and every object its words name
    /// literally.
    #[allow(clippy::too_many_arguments)]
    fn make_head(
        &self,
        range: Range<usize>,
        objects: Vec<usize>,
        tier: Tier,
        plural: bool,
        text: String,
        via: &str,
        typo: Option<Reason>,
    ) -> Head {
        let written = self.span_text(&range);
        let exact = objects.len() == 1 && self.scene.objects[objects[0]].name == written;
        let (kind, detail) = match tier {
            Tier::Name if exact => (ReasonKind::Exact, format!("\"{written}\" is the name")),
            Tier::Name => (
                ReasonKind::Variant,
                format!("\"{written}\" is the name written differently"),
            ),
            Tier::Alias => (ReasonKind::Alias, format!("\"{written}\" is an alias")),
            Tier::Category | Tier::Compound => {
                (ReasonKind::Category, format!("a '{via}' is a {text}"))
            }
            Tier::Synonym => (
                ReasonKind::Synonym,
                format!("\"{text}\" is a synonym of '{via}'"),
            ),
            Tier::Hypernym => (
                ReasonKind::Hypernym,
                format!("a '{via}' is a kind of {text}"),
            ),
            Tier::NameWord => (
                ReasonKind::Variant,
                format!("\"{text}\" is a word of the name '{via}'"),
            ),
        };
        let mut literal = self.g.index.lookup_literal(&text, tier >= Tier::Category);
        if literal.is_empty() || tier > Tier::Compound {
            literal = objects.clone();
        }
        Head {
            range,
            objects,
            literal,
            generic: false,
            tier,
            plural,
            text,
            reason: Reason { kind, detail },
            typo,
        }
    }

    /// `one` / `ones` / `others` standing for the noun of the phrase before: `the left
    /// one`, `the other one`, `the others`.
    pub(super) fn anaphor_at(&self, k: usize, nps: &[Np], bound: &[usize]) -> Option<Head> {
        let w = self.word(k)?;
        let (plural, other) = match w {
            "one" => (false, false),
            "ones" => (true, false),
            "others" => (true, true),
            // ("each other" is the two objects named, not another one.)
            "other" if k > 0 && self.is_word(k - 1, &["each"]) => return None,
            "other"
                if !self.head_follows(k + 1)
                    && !self.is_word(k + 1, &["one", "ones"])
                    && !self.word(k + 1).is_some_and(words::is_place_noun) =>
            {
                (false, true)
            }
            _ => return None,
        };
        if self.is_word(k + 1, &["of"]) {
            return None;
        }
        // "the blue one" with nothing before it: one of all the objects, which its
        // modifiers must pick.
        let everything: Vec<usize>;
        let contrast: Vec<usize>;
        let (pool, text) = match nps.last() {
            // "of the two stools at the island, … the left one": one of those two.
            Some(previous) if self.partitive(previous.range.start) => {
                (&previous.objects, previous.head.clone())
            }
            // "the tall box by the door … the short one": with a size word of its own and
            // no modifier after it, one of the boxes by the door the size word picked
            // among, not of every box.
            Some(previous)
                if previous.near.is_some()
                    && k > 0
                    && self.word(k - 1).and_then(words::size_word).is_some()
                    && !self.word(k + 1).is_some_and(|w| {
                        words::is_preposition(w)
                            || matches!(w, "closest" | "nearest" | "that" | "which" | "with")
                    }) =>
            {
                // Of those, the ones that stand where the one named stands (on the floor,
                // or on the same thing): the short box beside the tall one, not the cube on
                // top of it.
                let near = previous.near.as_deref().unwrap_or(&previous.pool);
                let level = |o: usize| self.scene.objects[o].support;
                contrast = match previous.objects.as_slice() {
                    [one] => near
                        .iter()
                        .copied()
                        .filter(|&o| level(o) == level(*one))
                        .collect(),
                    _ => near.to_vec(),
                };
                (&contrast, previous.head.clone())
            }
            Some(previous) => (&previous.pool, previous.head.clone()),
            None if k > 0
                && !other
                && self.word(k - 1).is_some_and(|w| {
                    words::is_colour(w) || self.g.index.attribute_words.contains(w)
                }) =>
            {
                everything = (0..self.scene.objects.len()).collect();
                (&everything, "object".to_string())
            }
            None => return None,
        };
        // "the blue mug … the red one": one of the mugs — the kind the last phrase named
        // (the last word of its head), not only the blue ones its own name picked.
        let kind = text.rsplit(' ').next().unwrap_or_default().to_string();
        let wider = if kind != text {
            self.g.index.lookup_literal(&kind, true)
        } else {
            Vec::new()
        };
        let partitive = nps.last().is_some_and(|p| self.partitive(p.range.start));
        let (mut objects, text) =
            if !partitive && wider.len() > pool.len() && pool.iter().all(|o| wider.contains(o)) {
                (wider, kind)
            } else {
                (pool.clone(), text)
            };
        if other {
            objects.retain(|o| !bound.contains(o));
        }
        Some(Head {
            range: k..k + 1,
            literal: objects.clone(),
            objects,
            generic: false,
            tier: Tier::Name,
            plural,
            reason: Reason {
                kind: ReasonKind::Modifier,
                detail: format!("\"{w}\" stands for the {text} named before"),
            },
            text,
            typo: None,
        })
    }

    /// Whether a unit of length, angle or proportion stands at token `k`.
    pub(super) fn unit_follows(&self, k: usize) -> bool {
        let w = |k: usize| self.word(k).unwrap_or("");
        match w(k) {
            "m" | "cm" | "mm" | "km" | "ft" | "foot" | "feet" | "inch" | "inches" | "metre"
            | "metres" | "meter" | "meters" | "centimetre" | "centimetres" | "centimeter"
            | "centimeters" | "millimetre" | "millimetres" | "millimeter" | "millimeters"
            | "units" | "unit" | "degrees" | "degree" | "deg" | "radians" | "percent" | "times"
            | "x" | "yards" | "yard" | "°" => true,
            // "2 in to the left" is inches; "chair 2 in front of" is not, nor "chair 6 in
            // 15 cm" (pushed in by an amount of its own) or "chair 6 in a bit".
            "in" => {
                !matches!(
                    w(k + 1),
                    "front" | "the" | "a" | "its" | "back" | "by" | "until"
                ) && !matches!(
                    self.tokens.get(k + 1).map(|t| &t.kind),
                    Some(Kind::Number(_))
                ) && !w(k + 1).is_empty()
            }
            _ => matches!(
                self.tokens.get(k).map(|t| &t.kind),
                Some(Kind::Punct('%' | '°'))
            ),
        }
    }

    /// The hit of a name read with a possessive's `s` dropped from one word before the
    /// last ("teachers chair" for 'teacher chair'), at the name or category tier only.
    fn possessive_name(&self, pieces: &[&str]) -> Option<index::Hit<'_>> {
        if pieces.len() < 2 {
            return None;
        }
        (0..pieces.len() - 1).find_map(|i| {
            let stem = pieces[i].strip_suffix('s').filter(|s| s.len() >= 3)?;
            let mut words: Vec<&str> = pieces.to_vec();
            words[i] = stem;
            self.g
                .index
                .lookup(&words.join(" "))
                .filter(|h| h.tier <= Tier::Category)
        })
    }

    /// Whether token `k` is a noun: one the lexicon knows (or the plural of one), or a word
    /// of an object's name.
    fn noun_at(&self, k: usize) -> bool {
        let Some(w) = self.word(k).filter(|w| !w.is_empty()) else {
            return false;
        };
        let lexicon = self.g.lexicon;
        lexicon.knows(w)
            || lexicon.singulars(w).iter().any(|s| lexicon.knows(s))
            || self.g.index.lookup(w).is_some()
    }

    /// Whether a head starts at token `k`.
    pub(super) fn head_follows(&self, k: usize) -> bool {
        k < self.tokens.len() && self.head_at(k).is_some()
    }

    /// Whether the head's text is one token that reads as an exported identifier, not a
    /// word: letters and digits run together (`pTorus1`, `mesh22`), an underscore or a
    /// period inside it, or a capital after a lower-case letter.
    fn looks_exported(&self, head: &Head) -> bool {
        if head.range.len() != 1 {
            return false;
        }
        let raw = &self.text[self.tokens[head.range.start].span.clone()];
        let chars: Vec<char> = raw.chars().collect();
        let mixed = chars.windows(2).any(|p| {
            (p[0].is_alphabetic() && p[1].is_ascii_digit())
                || (p[0].is_lowercase() && p[1].is_uppercase())
        });
        mixed || (raw.contains(['_', '.']) && chars.iter().all(|c| !c.is_whitespace()))
    }

    /// Whether the words before a head let it start a noun phrase: a determiner, a verb,
    /// a preposition, a conjunction or punctuation, or the start; an exported name opens
    /// one anywhere.
    pub(super) fn opens_ok(&self, head: &Head) -> bool {
        let k = self.premodifier_start(head.range.start);
        let det = k > 0 && self.word(k - 1).is_some_and(words::is_determiner);
        if det {
            return true;
        }
        let h = head.range.start;
        // An object's exact name written as a tool exports it (`pTorus1`, `SM_Lamp_02`,
        // `Chair.001`) means that object wherever it stands ("give pTorus1 a spin").
        if head.tier == Tier::Name && self.looks_exported(head) {
            return true;
        }
        // So does a numbered name said whole ("… until it touches chair 15").
        let numbered = head.range.len() > 1
            && matches!(
                self.tokens.get(head.range.end - 1).map(|t| &t.kind),
                Some(Kind::Number(_))
            );
        if head.tier == Tier::Name && head.objects.len() == 1 && numbered {
            return true;
        }
        let w = self.word(h).unwrap_or("");
        // A single grammar word ("can you…", "stand it up", "turn it counter clockwise")
        // or an anaphor ("one", "other") is a noun only after a determiner.
        let needs_determiner = head.range.len() == 1
            && ((grammar_word(w) && head.tier != Tier::Name)
                || words::is_verb(w)
                || matches!(
                    w,
                    "can" | "light" | "counter" | "one" | "ones" | "other" | "others"
                ));
        if needs_determiner {
            return false;
        }
        if h == 0 {
            return true;
        }
        match &self.tokens[h - 1].kind {
            Kind::Punct(c) => matches!(c, ',' | ';' | ':' | '.' | '!' | '?' | '(' | '-'),
            Kind::Word(w) => words::opens_phrase(w),
            Kind::Number(_) => true,
            Kind::Quoted(_) => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::{g, means, refused, scene, with_reader};
    use super::*;

    /// The head at token `k` of `text`: its tokens and the names of its objects.
    fn head(scene: &str, text: &str, k: usize) -> Option<(Range<usize>, Vec<String>)> {
        with_reader(scene, text, |r| {
            r.head_at(k).map(|h| (h.range.clone(), r.names(&h.objects)))
        })
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
    fn a_kind_with_a_list_or_a_range_of_numbers() {
        // The dining room's chairs: 'chair', 'chair 2', 'chair 3', 'chair 4'.
        means(
            "dining_room",
            "move chairs 2 and 4 left",
            &[&["chair 2", "chair 4"]],
        );
        means(
            "dining_room",
            "move chairs 2, 3 and 4 left 10 cm",
            &[&["chair 3", "chair 2", "chair 4"]],
        );
        means(
            "dining_room",
            "move chairs 2 to 4 left",
            &[&["chair 3", "chair 2", "chair 4"]],
        );
        // A range typed as one word is not read as one (a blind suite's wrong edit).
        assert_ne!(
            head("dining_room", "move chairs 3-4 left", 1).map(|h| h.0),
            Some(1..3)
        );
        // An amount is no number of the list; a number no chair has is no list.
        means("dining_room", "move chair 2 and 3 m left", &[&["chair 2"]]);
        assert_ne!(
            head("dining_room", "move chairs 2 and 9 left", 1).map(|h| h.0),
            Some(1..5)
        );
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
    fn the_longest_words_that_name_something_are_the_head() {
        let (range, objects) = head("living_room", "move the coffee table left", 2).unwrap();
        assert_eq!((range, objects), (2..4, vec!["coffee table".to_string()]));
        // Without its spaces, and with a number after `#` or `number`.
        let (range, objects) = head("living_room", "move the coffeetable left", 2).unwrap();
        assert_eq!((range, objects), (2..3, vec!["coffee table".to_string()]));
        let (range, objects) = head("dining_room", "move chair number 3 left", 1).unwrap();
        assert_eq!((range, objects), (1..4, vec!["chair 3".to_string()]));
        // A category names every object of it; a word that names nothing is no head.
        let (_, objects) = head("living_room", "move the lamps left", 2).unwrap();
        assert_eq!(objects, ["floor lamp", "table lamp"]);
        assert!(head("living_room", "move the lamps left", 0).is_none());
    }

    #[test]
    fn a_number_with_a_unit_is_an_amount_not_part_of_a_name() {
        let (range, objects) = head("living_room", "move the speaker 2 m left", 2).unwrap();
        assert_eq!(
            (range, objects),
            (2..3, vec!["speaker".into(), "speaker 2".into()])
        );
        let (range, objects) = head("living_room", "move speaker 2 2 m left", 1).unwrap();
        assert_eq!((range, objects), (1..3, vec!["speaker 2".to_string()]));
    }

    #[test]
    fn exported_names_and_possessives() {
        let text = r#"{"objects": [
            {"name": "Lamp_Table.003", "size": [1, 1, 1], "position": [-1, 0, 0]},
            {"name": "Lamp_Table.004", "size": [1, 1, 1], "position": [1, 0, 0]}
        ]}"#;
        let s = crate::format::json::read(text, "t").unwrap().scene;
        let grounder = super::super::Grounder::new(&s);
        let reader = Reader::new(&grounder, &s, "move Lamp_Table.004 left");
        let head = reader.head_at(1).unwrap();
        assert_eq!(reader.names(&head.objects), ["Lamp_Table.004"]);
        // "the teachers chair": the 'teacher chair', its apostrophe left out.
        means(
            "classroom",
            "move the teachers chair left",
            &[&["teacher chair"]],
        );
    }

    #[test]
    fn generic_nouns_name_what_their_modifier_names() {
        let (_, objects) = head("living_room", "lift everything 5 cm", 1).unwrap();
        assert_eq!(objects.len(), scene("living_room").objects.len());
        means(
            "living_room",
            "lift everything on the coffee table 5 cm",
            &[&["vase", "book", "remote control"]],
        );
        means(
            "living_room",
            "lift the thing on the ottoman 5 cm",
            &[&["magazine"]],
        );
        refused("living_room", "lift everything 5 cm", &["say which things"]);
    }

    #[test]
    fn one_stands_for_the_noun_before() {
        means(
            "living_room",
            "move the left speaker 1 m left and the other one 1 m right",
            &[&["speaker"], &["speaker 2"]],
        );
        means(
            "living_room",
            "move the left speaker back and the others forward",
            &[&["speaker"], &["speaker 2"]],
        );
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
}

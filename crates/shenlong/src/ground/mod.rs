//! Grounding: the objects an instruction means, in the words people use — or a refusal
//! that names the candidates. It runs before templating, for every translator.
//!
//! `lift the picture above the sofa by 10 cm` in a room with three paintings grounds
//! "the picture above the sofa" to 'painting 2' ("picture" is a synonym of painting;
//! "above the sofa" picked it), and templating makes it `lift X1 by 10 cm`.
//!
//! What a phrase may be (docs/grounding.md has the whole list):
//! - a name: quoted (always wins), or unquoted with any case, hyphens, spaces or plural
//!   (`Dog-Bed`, `dogbed`, `the hammers`), numbered (`chair 7`, `chair #7`, `chair number
//!   7`);
//! - a category or synonym, from the object's own fields (`category`, `aliases`, ProcTHOR
//!   types, glTF mesh names) and from the WordNet-distilled [`Lexicon`];
//! - a word one edit off a name word (five letters or more, when that leads to one object);
//! - with modifiers that pick among several: place (`the left armchair`, `the one on the
//!   right`), size (`the bigger box`), order (`the third chair from the left`), relation to
//!   another object (`the lamp nearest the sofa`, `the book on the side table`), a word of
//!   the name or an attribute (`the red chair`, `the teacher's desk`), `the other one`;
//! - a group: `both armchairs`, `the two stools`, `all the chairs`, `every lamp`.
//!
//! A modifier after the noun (`the book on the side table`) is read as picking only when
//! the noun alone fits several objects; otherwise it is left for the translator as where
//! to put the object (`put the book on the side table`). Nothing is guessed: a phrase
//! that still fits several objects, or none, is refused ([`GroundError`]).

mod attach;
mod error;
mod hold;
pub mod ident;
mod index;
pub mod kind;
pub mod lexicon;
mod select;
pub mod verbs;
pub mod words;

pub use error::{Ambiguity, GroundError};
pub use lexicon::Lexicon;

use crate::scene::Scene;
use attach::{Choice, PostText};
use index::{NameIndex, Tier};
use select::{Direction, Relation, SizeError};
use serde::Serialize;
use std::ops::Range;
use words::{Count, Kind, Token};

/// Longest instruction accepted, in characters.
pub const MAX_INSTRUCTION_CHARS: usize = 2_000;

/// The most objects an ambiguous phrase inside a modifier may stand for: `the phone on
/// the chair` looks at every chair when there are at most this many.
pub const MAX_TARGETS: usize = 8;

/// Shortest written word a typo is corrected in.
pub const TYPO_MIN_LETTERS: usize = 5;

/// How a phrase was read.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ReasonKind {
    /// A quoted name.
    Quoted,
    /// The object's name as written.
    Exact,
    /// The name with other case, spacing, hyphens, number or plural.
    Variant,
    /// One of the object's aliases.
    Alias,
    /// Its category, or a last word of its name.
    Category,
    /// A synonym from the lexicon.
    Synonym,
    /// A broader category from the lexicon.
    Hypernym,
    /// A word read as the name word one edit away.
    Typo,
    /// A modifier picked among several.
    Modifier,
    /// A group: several objects.
    Group,
    /// A pronoun or "the selection" with nothing named before it: the objects the user
    /// has selected (in an editor such as Blender).
    Selection,
}

/// One reason, with the words it concerns.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Reason {
    /// What kind.
    pub kind: ReasonKind,
    /// In words: `"couch" is a synonym of 'sofa'`.
    pub detail: String,
}

/// One referring phrase and the objects it means.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Phrase {
    /// Where it is in the instruction, in bytes.
    pub span: Range<usize>,
    /// The phrase as written.
    pub text: String,
    /// The objects (indices into the scene), in the order they are bound.
    pub objects: Vec<usize>,
    /// Why.
    pub reasons: Vec<Reason>,
}

/// An instruction's phrases and objects.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Grounding {
    /// The instruction as given (trimmed).
    pub instruction: String,
    /// The referring phrases, in order (without the held ones).
    pub phrases: Vec<Phrase>,
    /// The phrases named only to keep their objects where they are ("… but leave the
    /// chair where it is"): not bound to variables; placement holds their objects.
    pub held: Vec<Phrase>,
    /// The bytes of the instruction that say what is held, cut from the query.
    pub cuts: Vec<Range<usize>>,
}

/// Grounds instructions on one scene. Build it once per scene (the name index and the
/// lexicon lookups are done here); each [`Grounder::ground`] reads only the instruction
/// and the boxes of the candidates it compares.
#[derive(Clone, Debug)]
pub struct Grounder {
    index: NameIndex,
    lexicon: &'static Lexicon,
    objects: usize,
}

/// A head noun found at a position.
#[derive(Clone, Debug)]
struct Head {
    /// Token range of the head.
    range: Range<usize>,
    /// Candidates, by match.
    objects: Vec<usize>,
    /// Every object the head names literally (name, alias, category): what modifiers
    /// pick among.
    literal: Vec<usize>,
    /// `everything`, `the things`: a head that needs a modifier to say which.
    generic: bool,
    tier: Tier,
    plural: bool,
    /// The head as a person wrote it, normalised (`chair`).
    text: String,
    reason: Reason,
    typo: Option<Reason>,
}

/// A noun phrase read.
#[derive(Clone, Debug)]
struct Np {
    range: Range<usize>,
    objects: Vec<usize>,
    /// The head's candidates before any pick: what "the other one" picks from.
    pool: Vec<usize>,
    reasons: Vec<Reason>,
    head: String,
}

/// The objects a noun phrase has come to, why, and what its noun named before any pick.
struct Candidates {
    objects: Vec<usize>,
    reasons: Vec<Reason>,
    pool: Vec<usize>,
}

/// A modifier after the noun.
#[derive(Clone, Debug)]
enum Post {
    /// On the floor: standing on nothing.
    Floor,
    Side(words::Axis, f64),
    Middle,
    From(Direction),
    /// `from X`: an order from it after an ordinal ("the first chair from the window"),
    /// else where it is taken from ("the mug from the back counter").
    FromObject(usize),
    Relation(Relation, Vec<usize>),
    /// A place in the room: "in the corner", "in the middle of the room", "on the wall".
    Room(select::RoomPlace),
}

/// Whether a noun phrase stands on its own, or names the other object of a modifier
/// (where several fitting objects are fine: `the phone on the chair` looks at every chair).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    Main,
    Nested,
}

/// The instruction's words with corrections, shared by the readers.
struct Reader<'a> {
    g: &'a Grounder,
    scene: &'a Scene,
    text: &'a str,
    tokens: Vec<Token>,
    /// Per token: its normalised word(s) for name matching (`None`: cannot be in a
    /// name; `Some("")`: skipped inside a name, like `#` or `number`).
    words: Vec<Option<String>>,
    /// Per token: the typo it was corrected from.
    typos: Vec<Option<String>>,
    consumed: Vec<bool>,
    /// The objects of the last phrase grounded: what "it" after a relation word means
    /// (`… not the lamp on it`).
    antecedent: Vec<usize>,
}

impl Grounder {
    /// Indexes a scene's names with the built-in lexicon.
    #[must_use]
    pub fn new(scene: &Scene) -> Self {
        Self::with_lexicon(scene, Lexicon::builtin())
    }

    /// Indexes a scene's names with a given lexicon.
    #[must_use]
    pub fn with_lexicon(scene: &Scene, lexicon: &'static Lexicon) -> Self {
        Self {
            index: NameIndex::new(scene, lexicon),
            lexicon,
            objects: scene.objects.len(),
        }
    }

    /// Finds the phrases of `instruction` that name objects of `scene` (the scene this
    /// grounder was built for, in its current state).
    ///
    /// # Errors
    /// A phrase that fits no object, several with nothing to pick one, or a different
    /// number than it asks for; an instruction that names no object.
    pub fn ground(&self, instruction: &str, scene: &Scene) -> Result<Grounding, GroundError> {
        self.ground_with_selection(instruction, scene, &[])
    }

    /// [`Grounder::ground`] where the user has objects selected: "it", "them", "the
    /// selection" or "the selected object(s)" with no object named before them mean
    /// those objects (a pronoun after a named object still refers back to it).
    ///
    /// # Errors
    /// As [`Grounder::ground`].
    pub fn ground_with_selection(
        &self,
        instruction: &str,
        scene: &Scene,
        selection: &[usize],
    ) -> Result<Grounding, GroundError> {
        let text = instruction.trim();
        if text.is_empty() {
            return Err(GroundError::Empty);
        }
        if text.chars().count() > MAX_INSTRUCTION_CHARS {
            return Err(GroundError::TooLong {
                max: MAX_INSTRUCTION_CHARS,
            });
        }
        assert_eq!(
            scene.objects.len(),
            self.objects,
            "a Grounder serves the scene it was built for"
        );
        let mut reader = Reader::new(self, scene, text);
        let mut phrases = match reader.read() {
            Ok(phrases) => phrases,
            // An instruction that names nothing but speaks of the selection.
            Err(GroundError::NoObject { .. }) if !selection.is_empty() => Vec::new(),
            Err(e) => return Err(e),
        };
        if let Some(phrase) = selection_phrase(text, scene, selection, &phrases) {
            phrases.insert(0, phrase);
        }
        if phrases.is_empty() {
            return Err(GroundError::NoObject {
                names: scene
                    .objects
                    .iter()
                    .take(6)
                    .map(|o| o.name.clone())
                    .collect(),
                total: scene.objects.len(),
            });
        }
        let (phrases, held, cuts) = separate_holds(&reader.tokens, phrases);
        if phrases.is_empty() {
            return Err(GroundError::OnlyHeld {
                held: held
                    .iter()
                    .flat_map(|p| p.objects.iter().map(|&o| scene.objects[o].name.clone()))
                    .collect(),
            });
        }
        Ok(Grounding {
            instruction: text.to_string(),
            phrases,
            held,
            cuts,
        })
    }
}

/// Splits the phrases held in place ([`hold`]) from the others; a group that takes in a
/// held object lets it go ("move the chairs but not chair 2").
fn separate_holds(
    tokens: &[words::Token],
    phrases: Vec<Phrase>,
) -> (Vec<Phrase>, Vec<Phrase>, Vec<Range<usize>>) {
    let holds = hold::find(tokens, &phrases);
    if holds.is_empty() {
        return (phrases, Vec::new(), Vec::new());
    }
    let cuts = holds.iter().map(|h| h.cut.clone()).collect();
    let mut held = Vec::new();
    let mut kept = Vec::new();
    for (i, p) in phrases.into_iter().enumerate() {
        if holds.iter().any(|h| h.phrase == i) {
            held.push(p);
        } else {
            kept.push(p);
        }
    }
    let held_objects: Vec<usize> = held.iter().flat_map(|p| p.objects.clone()).collect();
    for p in &mut kept {
        if p.objects.len() > 1 {
            p.objects.retain(|o| !held_objects.contains(o));
        }
    }
    kept.retain(|p| !p.objects.is_empty());
    (kept, held, cuts)
}

/// The phrase for the selection: the first "it" / "them" / "the selection" / "the selected
/// object(s)" before any named object, or `None`.
fn selection_phrase(
    text: &str,
    scene: &Scene,
    selection: &[usize],
    phrases: &[Phrase],
) -> Option<Phrase> {
    if selection.is_empty() {
        return None;
    }
    let before = phrases.first().map_or(text.len(), |p| p.span.start);
    let tokens = words::tokenize(&text[..before]);
    let word = |k: usize| match tokens.get(k).map(|t| &t.kind) {
        Some(Kind::Word(w)) => w.to_lowercase(),
        _ => String::new(),
    };
    for k in 0..tokens.len() {
        let w = word(k);
        let range = match w.as_str() {
            "it" | "them" => k..k + 1,
            "selection" if word(k.wrapping_sub(1)) == "the" => k - 1..k + 1,
            "selection" => k..k + 1,
            "selected" => {
                let start = if word(k.wrapping_sub(1)) == "the" {
                    k - 1
                } else {
                    k
                };
                let end = match word(k + 1).as_str() {
                    "object" | "objects" | "one" | "ones" | "items" | "item" | "things" => k + 2,
                    _ => k + 1,
                };
                start..end
            }
            _ => continue,
        };
        let span = tokens[range.start].span.start..tokens[range.end - 1].span.end;
        let names: Vec<String> = selection
            .iter()
            .map(|&i| format!("'{}'", scene.objects[i].name))
            .collect();
        return Some(Phrase {
            text: text[span.clone()].to_string(),
            span,
            objects: selection.to_vec(),
            reasons: vec![Reason {
                kind: ReasonKind::Selection,
                detail: format!(
                    "\"{}\" is the selection: {}",
                    &text[tokens[range.start].span.start..tokens[range.end - 1].span.end],
                    error::list(&names)
                ),
            }],
        });
    }
    None
}

fn grammar_word(w: &str) -> bool {
    crate::discourse::is_discourse_word(w)
        || words::is_verb(w)
        || words::is_preposition(w)
        || words::is_determiner(w)
        || words::side_word(w).is_some()
        || words::size_word(w).is_some()
        || words::ordinal(w).is_some()
        || words::count_word(w).is_some()
        || words::is_place_noun(w)
        || words::is_relative_filler(w)
        || matches!(
            w,
            "can"
                | "could"
                | "would"
                | "will"
                | "should"
                | "may"
                | "might"
                | "must"
                | "it"
                | "them"
                | "they"
                | "you"
                | "me"
                | "us"
                | "i"
                | "we"
                | "please"
                | "and"
                | "or"
                | "then"
                | "so"
                | "light"
                | "down"
                | "away"
                | "off"
                | "out"
                | "again"
                | "clockwise"
                | "counterclockwise"
                | "anticlockwise"
                | "counter"
                | "too"
                | "also"
                | "very"
                | "much"
                | "more"
                | "less"
                | "bit"
                | "little"
                | "slightly"
                | "degrees"
                | "cm"
                | "m"
                | "mm"
                | "ft"
                | "in"
                | "inches"
                | "feet"
        )
}

impl<'a> Reader<'a> {
    fn new(g: &'a Grounder, scene: &'a Scene, text: &'a str) -> Self {
        let tokens = words::tokenize(text);
        let n = tokens.len();
        let mut words: Vec<Option<String>> = Vec::with_capacity(n);
        for (k, t) in tokens.iter().enumerate() {
            let next_is_number =
                matches!(tokens.get(k + 1).map(|t| &t.kind), Some(Kind::Number(_)));
            words.push(match &t.kind {
                Kind::Word(w)
                    if next_is_number && matches!(w.as_str(), "number" | "no" | "nr" | "num") =>
                {
                    Some(String::new())
                }
                Kind::Word(w) => Some(words::normalize(w.trim_end_matches("'s"))),
                Kind::Number(x) if x.fract() == 0.0 && *x >= 0.0 && *x < 1e6 => {
                    Some(format!("{x}"))
                }
                Kind::Punct('#') if next_is_number => Some(String::new()),
                _ => None,
            });
        }
        let mut reader = Reader {
            g,
            scene,
            text,
            tokens,
            words,
            typos: vec![None; n],
            consumed: vec![false; n],
            antecedent: Vec::new(),
        };
        reader.correct_typos();
        reader
    }

    /// Reads a word of five letters or more that is no known word as the index word one
    /// edit away, when there is exactly one.
    fn correct_typos(&mut self) {
        for k in 0..self.tokens.len() {
            let Some(w) = self.tokens[k].word() else {
                continue;
            };
            if w.chars().count() < TYPO_MIN_LETTERS
                || !w.chars().all(char::is_alphabetic)
                || grammar_word(w)
                || self.g.index.knows_word(w)
                || self.g.lexicon.knows(w)
                || self
                    .g
                    .lexicon
                    .singulars(w)
                    .iter()
                    .any(|s| self.g.index.knows_word(s) || self.g.lexicon.knows(s))
            {
                continue;
            }
            let near = self.g.index.one_edit_away(w);
            if let [one] = near.as_slice() {
                self.typos[k] = Some(w.to_string());
                self.words[k] = Some(one.to_string());
            } else if let Some(stem) = w
                .strip_suffix('s')
                .filter(|s| s.chars().count() >= TYPO_MIN_LETTERS - 1)
            {
                // A typo in a plural: "speakrs".
                if let [one] = self.g.index.one_edit_away(stem).as_slice() {
                    self.typos[k] = Some(w.to_string());
                    self.words[k] = Some(format!("{one}s"));
                }
            }
        }
    }

    fn word(&self, k: usize) -> Option<&str> {
        self.tokens.get(k).and_then(Token::word)
    }

    fn is_word(&self, k: usize, options: &[&str]) -> bool {
        self.word(k).is_some_and(|w| options.contains(&w))
    }

    fn span_text(&self, range: &Range<usize>) -> String {
        self.text[self.byte_span(range)].to_string()
    }

    /// The bytes of the instruction that tokens `range` cover.
    fn byte_span(&self, range: &Range<usize>) -> Range<usize> {
        self.tokens[range.start].span.start..self.tokens[range.end - 1].span.end
    }

    fn name(&self, i: usize) -> String {
        self.scene.objects[i].name.clone()
    }

    fn names(&self, objects: &[usize]) -> Vec<String> {
        objects.iter().map(|&i| self.name(i)).collect()
    }

    /// Every phrase, left to right.
    fn read(&mut self) -> Result<Vec<Phrase>, GroundError> {
        let mut phrases: Vec<Phrase> = Vec::new();
        let mut nps: Vec<Np> = Vec::new();
        let mut k = 0;
        while k < self.tokens.len() {
            if self.consumed[k] {
                k += 1;
                continue;
            }
            if let Kind::Quoted(name) = &self.tokens[k].kind {
                let index = self
                    .scene
                    .resolve(name)
                    .map_err(|_| GroundError::UnknownName {
                        name: name.trim().to_string(),
                        suggestions: suggest(self.scene, name),
                    })?;
                let mut start = k;
                if k > 0
                    && !self.consumed[k - 1]
                    && self.is_word(k - 1, &["the", "a", "an", "this", "that"])
                {
                    start = k - 1;
                }
                let np = Np {
                    range: start..k + 1,
                    objects: vec![index],
                    pool: vec![index],
                    reasons: vec![Reason {
                        kind: ReasonKind::Quoted,
                        detail: format!("'{}' is quoted", name.trim()),
                    }],
                    head: words::normalize(name),
                };
                self.commit(np, &mut phrases, &mut nps);
                k += 1;
                continue;
            }
            let bound: Vec<usize> = phrases.iter().flat_map(|p| p.objects.clone()).collect();
            let head = self.head_at(k).or_else(|| self.anaphor_at(k, &nps, &bound));
            match head {
                Some(head) if self.opens_ok(&head) => {
                    let end = head.range.end;
                    let np = self.noun_phrase(head, &bound, Mode::Main)?;
                    self.commit(np, &mut phrases, &mut nps);
                    k = end;
                }
                _ => {
                    self.check_unknown(k)?;
                    k += 1;
                }
            }
        }
        Ok(phrases)
    }

    fn commit(&mut self, np: Np, phrases: &mut Vec<Phrase>, nps: &mut Vec<Np>) {
        for c in np.range.clone() {
            self.consumed[c] = true;
        }
        phrases.push(Phrase {
            span: self.tokens[np.range.start].span.start..self.tokens[np.range.end - 1].span.end,
            text: self.span_text(&np.range),
            objects: np.objects.clone(),
            reasons: np.reasons.clone(),
        });
        self.antecedent.clone_from(&np.objects);
        nps.push(np);
    }

    /// An object's name typed as the tool exported it (`Chair_Wood`, `Lamp_Table.003`):
    /// that object only, not its family.
    fn identifier_at(&self, k: usize) -> Option<Head> {
        let w = self.word(k)?;
        if !w.contains(['_', '.']) {
            return None;
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
        let mut head = self.make_head(
            k..end,
            vec![object],
            Tier::Name,
            false,
            words::normalize(raw),
            raw,
            None,
        );
        head.literal = vec![object];
        Some(head)
    }

    /// The longest name, category or synonym starting at token `k`.
    fn head_at(&self, k: usize) -> Option<Head> {
        if let Some(head) = self.identifier_at(k) {
            return Some(head);
        }
        let index = &self.g.index;
        let max = index.max_words + 1;
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
        for len in (1..=pieces.len()).rev() {
            let phrase = pieces[..len].join(" ");
            let range = k..ends[len - 1];
            let typo = range.clone().find_map(|t| {
                self.typos[t].as_ref().map(|from| Reason {
                    kind: ReasonKind::Typo,
                    detail: format!(
                        "\"{from}\" read as \"{}\"",
                        self.words[t].as_deref().unwrap_or("")
                    ),
                })
            });
            // A plural reads as the plural of a name before it reads as a synonym that
            // happens to be written the same ("eggs" among WordNet's words for an egg).
            // A possessive written without its apostrophe ("the teachers chair") reads as
            // the name it is one letter from.
            let direct = index
                .lookup(&phrase)
                .or_else(|| self.possessive_name(&pieces[..len]));
            let plural = self
                .g
                .lexicon
                .singulars(&phrase)
                .into_iter()
                .find_map(|singular| index.lookup(&singular).map(|hit| (singular, hit)));
            // (the hit, whether it is read as a plural, and the singular it was read as)
            let chosen = match (direct, plural) {
                (Some(hit), plural) if plural.as_ref().is_none_or(|(_, p)| hit.tier < p.tier) => {
                    Some((hit, false, None))
                }
                (_, Some((singular, hit))) => Some((hit, true, Some(singular))),
                _ => None,
            };
            // A word of a name said alone is the object only where no noun follows it
            // ("the dining chair" is no 'DiningTable', "the coffee grinder" no
            // 'CoffeeMachine'), and only as written ("stick" is no typo of 'Books_Stack').
            let chosen = chosen.filter(|(hit, _, _)| {
                hit.tier != Tier::NameWord || (typo.is_none() && !self.noun_at(ends[len - 1]))
            });
            if let Some((hit, plural, singular)) = chosen {
                let via = hit.via.to_string();
                let text = singular.unwrap_or(phrase);
                return Some(self.make_head(
                    range,
                    hit.objects,
                    hit.tier,
                    plural,
                    text,
                    &via,
                    typo,
                ));
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
        }
        let w = self.words[k].as_deref().unwrap_or("");
        // "the thing on the cupboard" is one object; "everything on the shelf", "whatever's
        // on top of the bookcase" all that the modifier names.
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
    fn anaphor_at(&self, k: usize, nps: &[Np], bound: &[usize]) -> Option<Head> {
        let w = self.word(k)?;
        let (plural, other) = match w {
            "one" => (false, false),
            "ones" => (true, false),
            "others" => (true, true),
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
        let (pool, text) = match nps.last() {
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
        let mut objects = pool.clone();
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

    /// `except the front-left one`, `but chair 3`, `apart from chair 2 and chair 4` after a
    /// group at token `k`: the objects left out, and where the phrase ends.
    fn exclusion(
        &self,
        k: usize,
        group: &[usize],
        head: &str,
        bound: &[usize],
    ) -> Result<Option<(Vec<usize>, usize)>, GroundError> {
        let w = |k: usize| self.word(k).unwrap_or("");
        let mut q = match (w(k), w(k + 1)) {
            ("except" | "excepting", "for")
            | ("apart" | "aside", "from")
            | ("other", "than")
            | ("save", "for") => k + 2,
            ("except" | "excepting" | "but" | "excluding" | "minus" | "bar", _) => k + 1,
            _ => return Ok(None),
        };
        let mut excluded = Vec::new();
        loop {
            // Skip to the head: a name, or "one" for one of the group.
            let mut h = q;
            while h < self.tokens.len()
                && h < q + 5
                && self.head_at(h).is_none()
                && !self.is_word(h, &["one", "ones"])
            {
                if !(self.word(h).is_some_and(words::is_determiner) || self.is_premodifier(h)) {
                    return Ok(None);
                }
                h += 1;
            }
            let head = match self.head_at(h) {
                Some(head) => head,
                None if self.is_word(h, &["one", "ones"]) => Head {
                    range: h..h + 1,
                    objects: group.to_vec(),
                    literal: group.to_vec(),
                    generic: false,
                    tier: Tier::Name,
                    plural: self.is_word(h, &["ones"]),
                    text: head.to_string(),
                    reason: modifier("one of them"),
                    typo: None,
                },
                None => return Ok(None),
            };
            let plural = head.plural;
            let text = head.text.clone();
            let np = self.noun_phrase(head, bound, Mode::Nested)?;
            if np.objects.len() > 1 && !plural {
                let names = self.names(&np.objects);
                return Err(GroundError::Ambiguous {
                    phrase: self.span_text(&np.range),
                    span: self.byte_span(&np.range),
                    example: names[names.len().min(3) - 1].clone(),
                    hints: self.hints(&text, &np.objects),
                    candidates: names,
                });
            }
            excluded.extend(np.objects);
            q = np.range.end;
            if self.is_word(q, &["and", "or"])
                || matches!(self.tokens.get(q).map(|t| &t.kind), Some(Kind::Punct(',')))
            {
                let next = q + 1;
                // Another excluded phrase follows only if a name or "the … one" does.
                let more = (next..(next + 4).min(self.tokens.len()))
                    .any(|t| self.head_at(t).is_some() || self.is_word(t, &["one"]));
                if more && !self.word(next).is_some_and(words::is_verb) {
                    q = next;
                    continue;
                }
            }
            return Ok(Some((excluded, q)));
        }
    }

    /// Whether a unit of length, angle or proportion stands at token `k`.
    fn unit_follows(&self, k: usize) -> bool {
        let w = |k: usize| self.word(k).unwrap_or("");
        match w(k) {
            "m" | "cm" | "mm" | "km" | "ft" | "foot" | "feet" | "inch" | "inches" | "metre"
            | "metres" | "meter" | "meters" | "centimetre" | "centimetres" | "centimeter"
            | "centimeters" | "millimetre" | "millimetres" | "millimeter" | "millimeters"
            | "units" | "unit" | "degrees" | "degree" | "deg" | "radians" | "percent" | "times"
            | "x" | "yards" | "yard" | "°" => true,
            // "2 in to the left" is inches; "chair 2 in front of" is not.
            "in" => !matches!(w(k + 1), "front" | "the" | "a" | "its" | "back"),
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

    fn head_follows(&self, k: usize) -> bool {
        k < self.tokens.len() && self.head_at(k).is_some()
    }

    /// Whether the words before a head let it start a noun phrase: a determiner, a verb,
    /// a preposition, a conjunction or punctuation, or the start.
    fn opens_ok(&self, head: &Head) -> bool {
        let k = self.premodifier_start(head.range.start);
        let det = k > 0 && self.word(k - 1).is_some_and(words::is_determiner);
        if det {
            return true;
        }
        let h = head.range.start;
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

    fn is_premodifier(&self, k: usize) -> bool {
        if self.consumed[k] {
            return false;
        }
        match &self.tokens[k].kind {
            Kind::Number(x) => x.fract() == 0.0 && *x >= 1.0 && *x <= 100.0,
            Kind::Word(w) if words::is_determiner(w) => false,
            Kind::Word(w) => {
                let w = w.trim_end_matches("'s");
                words::side_parts(w).is_some()
                    || words::normalize(w).is_empty()
                    || words::size_word(w).is_some()
                    || words::ordinal(w).is_some()
                    || words::count_word(w).is_some()
                    || matches!(w, "other" | "middle" | "center" | "centre" | "far" | "same")
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

    /// Where the modifiers before the head at `h` start, when a determiner opens them; else
    /// `h` itself.
    fn premodifier_start(&self, h: usize) -> usize {
        let mut k = h;
        while k > 0 && self.is_premodifier(k - 1) {
            k -= 1;
        }
        if k < h && !(k > 0 && self.word(k - 1).is_some_and(words::is_determiner)) {
            // Modifiers with no determiner before them are not read as modifiers.
            return h;
        }
        k
    }

    /// Reads the noun phrase around a head: determiner and modifiers before it, and (when
    /// `post` and the noun alone fits several) a modifier after it.
    fn noun_phrase(&self, head: Head, bound: &[usize], mode: Mode) -> Result<Np, GroundError> {
        let h = head.range.start;
        let mut start = self.premodifier_start(h);
        let premods: Vec<usize> = (start..h).collect();
        let mut count = if head.plural { Count::All } else { Count::One };
        if start > 0 && self.word(start - 1).is_some_and(words::is_determiner) {
            start -= 1;
            match self.word(start).unwrap_or("") {
                "both" => count = Count::Exactly(2),
                "all" | "every" | "each" => count = Count::All,
                "these" | "those" if head.plural => count = Count::All,
                _ => {}
            }
            // "all the", "both of the", "all of the".
            if self.word(start) == Some("the") && start > 0 && !self.consumed[start - 1] {
                if self.is_word(start - 1, &["all", "both", "each"]) {
                    start -= 1;
                } else if self.is_word(start - 1, &["of"])
                    && start > 1
                    && self.is_word(start - 2, &["all", "both", "each"])
                {
                    start -= 2;
                }
                match self.word(start).unwrap_or("") {
                    "both" => count = Count::Exactly(2),
                    "all" | "each" => count = Count::All,
                    _ => {}
                }
            }
        }
        // "the bigger of the two boxes", "the left one of the two".
        let mut outer: Vec<usize> = Vec::new();
        let mut outer_count = None;
        // Only of a group: "the left of the dresser" is a place, not a pick.
        let of_a_group = !matches!(count, Count::One);
        if of_a_group && start >= 2 && self.is_word(start - 1, &["of"]) && !self.consumed[start - 2]
        {
            let m = start - 2;
            let w = self.word(m).unwrap_or("");
            let selector = words::size_word(w).is_some()
                || words::side_word(w).is_some()
                || words::ordinal(w).is_some();
            if selector && m > 0 && self.is_word(m - 1, &["the"]) && !self.consumed[m - 1] {
                outer.push(m);
                start = m - 1;
                outer_count = Some(Count::One);
            }
        }
        // With modifiers, every object the noun names literally is a candidate: "the
        // smallest barrel" compares 'barrel', 'barrel 2' and 'small barrel'.
        let modified = !premods.is_empty() || !outer.is_empty();
        let mut objects = if modified {
            head.literal.clone()
        } else {
            head.objects.clone()
        };
        let pool = head.literal.clone();
        let mut reasons = vec![head.reason.clone()];
        if let Some(t) = &head.typo {
            reasons.push(t.clone());
        }
        let mut ordinal: Option<usize> = None;
        let mut sides: Vec<(words::Axis, f64, String)> = Vec::new();
        let mut sizes: Vec<String> = Vec::new();
        let mut middle = false;
        for &m in premods.iter().chain(&outer) {
            match &self.tokens[m].kind {
                Kind::Number(x) => count = Count::Exactly(*x as usize),
                Kind::Word(w) => {
                    let w = w.trim_end_matches("'s");
                    if let Some(n) = words::count_word(w) {
                        count = Count::Exactly(n);
                    } else if let Some(o) = words::ordinal(w) {
                        ordinal = Some(o);
                    } else if w == "other" {
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
                    } else if w == "same" {
                        // "the same chair": no pick.
                    } else if let Some(parts) = words::side_parts(w) {
                        sides.extend(parts.into_iter().map(|(a, s)| (a, s, w.to_string())));
                    } else if words::size_word(w).is_some() {
                        sizes.push(w.to_string());
                    } else if matches!(w, "middle" | "center" | "centre") {
                        middle = true;
                    } else {
                        let d = words::normalize(w);
                        let fits: Vec<usize> = objects
                            .iter()
                            .copied()
                            .filter(|&o| self.g.index.describes(o, &d))
                            .collect();
                        if fits.is_empty() {
                            // A colour or material must pick; a word of another object's
                            // name ("the dining chair") says nothing about these.
                            if words::is_colour(w)
                                || words::is_colour(&d)
                                || self.g.index.attribute_words.contains(d.as_str())
                            {
                                return Err(GroundError::NoPick {
                                    phrase: self.span_text(&(start..head.range.end)),
                                    reason: format!(
                                        "no {} is {d}: the {}s here are {}",
                                        head.text,
                                        head.text,
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
                }
                _ => {}
            }
        }
        // "the bigger of the two boxes": two fit, one is picked.
        if let (Some(c), Count::Exactly(n)) = (outer_count, count) {
            if objects.len() != n {
                return Err(GroundError::Count {
                    phrase: self.span_text(&(start..head.range.end)),
                    span: self.byte_span(&(start..head.range.end)),
                    wanted: n,
                    found: self.names(&objects),
                });
            }
            count = c;
        } else if let Some(c) = outer_count {
            count = c;
        }
        let mut end = head.range.end;
        let phrase_so_far = |end: usize| self.span_text(&(start..end));
        let wanted = count.wanted(objects.len());
        let group = matches!(count, Count::All) && !head.generic;
        let post = if mode == Mode::Main {
            self.post_modifier(end, bound)?
        } else {
            None
        };
        let post = post.map(|(p, p_end)| match p {
            Post::FromObject(t) if ordinal.is_some() => {
                let c = self.scene.objects[t].world_aabb().center();
                (Post::From(Direction::From(c)), p_end)
            }
            p => (p, p_end),
        });
        let picks = (objects.len() != wanted && !group) || ordinal.is_some() || head.generic;
        let selectors_first = !sides.is_empty() || !sizes.is_empty() || middle;
        let post = self.attach(
            post,
            &head,
            start,
            &objects,
            Choice {
                picks,
                group,
                selectors_first,
            },
        )?;
        if let Some((p, p_end)) = post {
            let p_kind = match &p {
                Post::Relation(r, _) => Some(*r),
                _ => None,
            };
            if !modified {
                objects = head.literal.clone();
            }
            {
                let words = self.span_text(&(end..p_end));
                let at = self.span_text(&(start..p_end));
                // With modifiers before the noun still to pick ("the front painting on the
                // right wall"), or for a group, the modifier after it keeps every object
                // it fits.
                let filter = !sides.is_empty() || !sizes.is_empty() || middle || group;
                if group && matches!(p, Post::Relation(Relation::Nearest | Relation::Farthest, _)) {
                    return Err(GroundError::NoPick {
                        phrase: at,
                        reason: format!("say how many ('the two {}s {words}')", head.text),
                    });
                }
                let wanted = if head.generic || filter {
                    usize::MAX
                } else {
                    wanted
                };
                let text = PostText {
                    at: &at,
                    words: &words,
                };
                objects =
                    self.apply_post(p, objects, &mut ordinal, filter, wanted, &head, &text)?;
                reasons.push(modifier(&format!(
                    "\"{words}\" picked {}",
                    error::list(&self.names(&objects))
                )));
                // Where it is taken from stays in the instruction: it is also where the
                // object leaves ("take X1 off X2").
                if !matches!(p_kind, Some(Relation::Off)) {
                    end = p_end;
                }
            }
        }
        objects = self.pick_by_premodifiers(
            &head,
            count,
            Premods {
                ordinal: &mut ordinal,
                sides: &sides,
                sizes: &sizes,
                middle,
            },
            objects,
            &mut reasons,
            &phrase_so_far(end),
        )?;
        // "everything on the right nightstand but not the nightstand itself": the one
        // named before, or what the objects named before stand on.
        if objects.len() > 1 && self.is_word(end, &["itself", "themselves"]) {
            let mentioned: Vec<usize> = bound
                .iter()
                .flat_map(|&b| [Some(b), self.scene.objects[b].support])
                .flatten()
                .collect();
            let kept: Vec<usize> = objects
                .iter()
                .copied()
                .filter(|o| mentioned.contains(o))
                .collect();
            if !kept.is_empty() {
                reasons.push(modifier(&format!(
                    "\"itself\": {}, named before",
                    error::list(&self.names(&kept))
                )));
                objects = kept;
            }
        }
        // "all the chairs except the front-left one", "every chair but chair 3".
        if mode == Mode::Main && matches!(count, Count::All) && !head.generic {
            if let Some((excluded, e_end)) = self.exclusion(end, &objects, &head.text, bound)? {
                let at = self.span_text(&(start..e_end));
                if let Some(&stray) = excluded.iter().find(|o| !objects.contains(o)) {
                    return Err(GroundError::NoPick {
                        phrase: at,
                        reason: format!("'{}' is not one of them", self.name(stray)),
                    });
                }
                objects.retain(|o| !excluded.contains(o));
                reasons.push(modifier(&format!(
                    "\"{}\" left out {}",
                    self.span_text(&(end..e_end)),
                    error::list(&self.names(&excluded))
                )));
                end = e_end;
            }
        }
        self.finish(
            head,
            start..end,
            count,
            ordinal,
            mode,
            Candidates {
                objects,
                reasons,
                pool,
            },
        )
    }

    /// The last checks of a noun phrase: an ordinal with no direction, a generic noun with
    /// nothing to say which, the count asked for, a typo that fits several; then a group in
    /// a stable order (left to right, then back to front).
    fn finish(
        &self,
        head: Head,
        range: Range<usize>,
        count: Count,
        ordinal: Option<usize>,
        mode: Mode,
        found: Candidates,
    ) -> Result<Np, GroundError> {
        let Candidates {
            mut objects,
            mut reasons,
            pool,
        } = found;
        let (start, end) = (range.start, range.end);
        let phrase = self.span_text(&(start..end));
        if let Some(o) = ordinal {
            // Numbered 1 to n (`SM_Chair_01` … `SM_Chair_04`): "the second chair" is the
            // one numbered 2, as its name says.
            let mut numbers: Vec<Option<u32>> =
                objects.iter().map(|&x| self.g.index.number(x)).collect();
            numbers.sort_unstable();
            let counted = numbers
                .iter()
                .enumerate()
                .all(|(k, n)| *n == u32::try_from(k + 1).ok());
            if objects.len() > 1 && counted {
                let picked = objects
                    .iter()
                    .copied()
                    .find(|&x| self.g.index.number(x) == u32::try_from(o).ok());
                if let Some(picked) = picked {
                    objects = vec![picked];
                    reasons.push(modifier(&format!(
                        "\"{}\" picked {}, numbered {o} of 1 to {}",
                        ordinal_word(o),
                        self.name(picked),
                        numbers.len()
                    )));
                }
            }
            if objects.len() > 1 {
                return Err(GroundError::NoPick {
                    reason: format!(
                        "{} from where? say 'the {} {} from the left' or name one ('{}')",
                        ordinal_word(o),
                        ordinal_word(o),
                        head.text,
                        self.name(objects[0])
                    ),
                    phrase,
                });
            }
        }
        if head.generic && end == head.range.end {
            return Err(GroundError::NoPick {
                phrase,
                reason: "say which things ('everything on the table')".into(),
            });
        }
        let wanted = count.wanted(objects.len());
        if objects.is_empty() {
            return Err(GroundError::Unknown {
                phrase,
                suggestions: Vec::new(),
            });
        }
        let ambiguous_ok = mode == Mode::Nested && count == Count::One;
        if objects.len() != wanted && !ambiguous_ok {
            let names = self.names(&objects);
            return Err(match count {
                Count::One => GroundError::Ambiguous {
                    phrase,
                    span: self.byte_span(&(start..end)),
                    example: names[names.len().min(3) - 1].clone(),
                    hints: self.hints(&head.text, &objects),
                    candidates: names,
                },
                _ => GroundError::Count {
                    phrase,
                    span: self.byte_span(&(start..end)),
                    wanted,
                    found: names,
                },
            });
        }
        if head.typo.is_some() && objects.len() != 1 && mode == Mode::Main {
            return Err(GroundError::Unknown {
                phrase,
                suggestions: self.names(&objects),
            });
        }
        if objects.len() > 1 && mode == Mode::Main {
            reasons.push(Reason {
                kind: ReasonKind::Group,
                detail: format!("{} objects", objects.len()),
            });
            // Groups bind in a stable order: left to right, then back to front.
            objects.sort_by(|&a, &b| {
                let (ca, cb) = (
                    self.scene.objects[a].world_aabb().center(),
                    self.scene.objects[b].world_aabb().center(),
                );
                ca.x.total_cmp(&cb.x)
                    .then(ca.z.total_cmp(&cb.z))
                    .then(a.cmp(&b))
            });
        }
        Ok(Np {
            range: start..end,
            objects,
            pool,
            reasons,
            head: head.text,
        })
    }

    fn too_close(&self, phrase: &str, objects: &[usize], word: &str) -> GroundError {
        GroundError::NoPick {
            phrase: phrase.to_string(),
            reason: format!(
                "{} are too close to tell which is {word}; name one ('{}')",
                error::list(&self.names(objects)),
                self.name(objects[0])
            ),
        }
    }

    /// Ways to say which, with a real neighbour: `the left chair`, `the chair nearest the
    /// table`.
    fn hints(&self, head: &str, candidates: &[usize]) -> Vec<String> {
        let mut hints = vec![format!("the left {head}")];
        let c = self.scene.objects[candidates[0]].world_aabb().center();
        let mut is_candidate = vec![false; self.scene.objects.len()];
        for &k in candidates {
            is_candidate[k] = true;
        }
        let other = (0..self.scene.objects.len())
            .filter(|&i| !is_candidate[i])
            .map(|i| {
                (
                    i,
                    (self.scene.objects[i].world_aabb().center() - c).length_squared(),
                )
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(i, _)| i);
        if let Some(o) = other {
            hints.push(format!("the {head} nearest the {}", self.name(o)));
        }
        hints
    }

    /// Whether the clause goes on after token `k` with an amount, a direction or a place
    /// of its own: then a modifier before `k` describes the object rather than saying
    /// where it goes.
    /// Whether a verb that puts an object somewhere stands right before token `k`
    /// (`put`, `move`, `place` — not `turn`, `take` or `swap`, which take no place).
    fn placing_verb_before(&self, k: usize) -> bool {
        k > 0
            && self.word(k - 1).is_some_and(|w| {
                words::is_verb(w)
                    && !words::turns_or_scales(w)
                    && !matches!(
                        w,
                        "make"
                            | "swap"
                            | "switch"
                            | "exchange"
                            | "interchange"
                            | "align"
                            | "line"
                            | "take"
                            | "grab"
                            | "pick"
                            | "fetch"
                    )
            })
    }

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
                )
        };
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

    /// Whether the verb of the clause before token `k` takes no place to put the object
    /// (`rotate`, `scale`, `lift`): then `the tv on the stand` describes the tv.
    fn verb_takes_no_place(&self, k: usize) -> bool {
        for t in self.tokens[..k.min(self.tokens.len())].iter().rev() {
            match &t.kind {
                Kind::Punct(',' | ';' | '.' | '!' | '?') => return false,
                Kind::Word(w) if matches!(w.as_str(), "and" | "then") => return false,
                Kind::Word(w) if words::is_verb(w) => {
                    return words::turns_or_scales(w)
                        || matches!(w.as_str(), "lift" | "raise" | "lower" | "elevate");
                }
                _ => {}
            }
        }
        false
    }

    /// A modifier after the noun at token `k`: `on the left`, `on the right wall`, `in the
    /// middle`, `from the window`, `nearest the sofa`, `on the side table`, `that is next
    /// to the bed`, `with the lamp on it`.
    fn post_modifier(
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
        let w = |k: usize| self.word(k).unwrap_or("");
        // on the left, on the far right, on the left-hand side, on the right wall, at the
        // front, at the back.
        if matches!(w(j), "on" | "at")
            && w(j + 1) == "the"
            && matches!(w(j + 2), "floor" | "ground")
        {
            return Ok(Some((Post::Floor, j + 3)));
        }
        // ("to the left" is a direction, not a place: it is not read here.)
        if matches!(w(j), "on" | "at" | "in" | "against" | "along") && w(j + 1) == "the" {
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
                if next != "of" && self.head_at(s + 1).is_none() && !corner {
                    let mut end = s + 1;
                    if matches!(w(end), "side" | "end" | "wall") {
                        end += 1;
                    } else if w(end) == "hand" && w(end + 1) == "side" {
                        end += 2;
                    }
                    return Ok(Some((Post::Side(axis, sign), end)));
                }
            }
            if matches!(w(s), "middle" | "center" | "centre") && w(s + 1) != "of" {
                return Ok(Some((Post::Middle, s + 1)));
            }
        }
        if let Some(room) = self.room_place_at(j) {
            return Ok(Some(room));
        }
        if w(j) == "from" {
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
            if let Some((targets, end)) = self.nested_np(j + 1, bound)? {
                if let [one] = targets.as_slice() {
                    return Ok(Some((Post::FromObject(*one), end)));
                }
            }
            return Ok(None);
        }
        // with the lamp (on it), that has the clock on it, holding the vase.
        if matches!(
            w(j),
            "with" | "has" | "holds" | "holding" | "carrying" | "having"
        ) {
            if let Some((targets, mut end)) = self.nested_np(j + 1, bound)? {
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
                return Ok(Some((Post::Relation(Relation::Carries, targets), end)));
            }
            return Ok(None);
        }
        if let Some((relation, after)) = self.relation_at(j) {
            if let Some((targets, end)) = self.nested_np(after, bound)? {
                return Ok(Some((Post::Relation(relation, targets), end)));
            }
        }
        Ok(None)
    }

    /// A place in the room after a noun, and where it ends: `in the (back left) corner`,
    /// `in the middle of the room` (or of the kitchen, …), `on the wall`.
    fn room_place_at(&self, j: usize) -> Option<(Post, usize)> {
        let w = |k: usize| self.word(k).unwrap_or("");
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

    /// A relation word group at `j` and where its object starts.
    fn relation_at(&self, j: usize) -> Option<(Relation, usize)> {
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
            ("beside" | "by" | "near" | "alongside" | "nearby" | "at", _, _) => (Relation::Near, 1),
            ("nearest" | "closest", _, _) => (Relation::Nearest, 1),
            ("behind", _, _) => (Relation::Behind, 1),
            ("in" | "inside" | "within", _, _) => (Relation::Inside, 1),
            _ => return None,
        };
        Some((r, j + len))
    }

    /// The other object(s) of a modifier (`the side table` in `the book on the side
    /// table`): one object, or every object a still ambiguous phrase fits (`the phone on
    /// the chair` looks at every chair).
    fn nested_np(
        &self,
        j: usize,
        bound: &[usize],
    ) -> Result<Option<(Vec<usize>, usize)>, GroundError> {
        if let Some(Kind::Quoted(name)) = self.tokens.get(j).map(|t| &t.kind) {
            return Ok(self.scene.find(name).map(|i| (vec![i], j + 1)));
        }
        // "the lamp on it": the object named last ("them": the objects).
        let pronoun = match self.word(j) {
            Some("it") => self.antecedent.len() == 1,
            Some("them") => self.antecedent.len() > 1,
            _ => false,
        };
        if pronoun {
            return Ok(Some((self.antecedent.clone(), j + 1)));
        }
        // Skip the determiner and modifiers to the head.
        let mut h = j;
        while h < self.tokens.len() && h < j + 5 {
            if self.head_at(h).is_some() {
                break;
            }
            let w = self.word(h).unwrap_or("");
            if !(words::is_determiner(w) || self.is_premodifier(h)) {
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
            let names = self.names(&np.objects);
            return Err(GroundError::Ambiguous {
                phrase: self.span_text(&np.range),
                span: self.byte_span(&np.range),
                example: names[2].clone(),
                hints: self.hints(&text, &np.objects),
                candidates: names,
            });
        }
        Ok(Some((np.objects, np.range.end)))
    }

    /// Refuses a noun the lexicon knows, after a determiner, that no object answers to:
    /// `move the piano` in a room with no piano.
    fn check_unknown(&self, k: usize) -> Result<(), GroundError> {
        let Some(w) = self.word(k) else { return Ok(()) };
        if grammar_word(w) || self.consumed[k] {
            return Ok(());
        }
        let det =
            k > 0 && self.word(k - 1).is_some_and(words::is_determiner) && !self.consumed[k - 1];
        if !det {
            return Ok(());
        }
        // Up to three words: "coffee machine".
        for len in (1..=3).rev() {
            if k + len > self.tokens.len() {
                continue;
            }
            let pieces: Option<Vec<String>> = (k..k + len)
                .map(|t| self.word(t).map(words::normalize))
                .collect();
            let Some(pieces) = pieces else { continue };
            let phrase = pieces.join(" ");
            let known = self.g.lexicon.knows(&phrase)
                || self
                    .g
                    .lexicon
                    .singulars(&phrase)
                    .iter()
                    .any(|s| self.g.lexicon.knows(s));
            let is_room = self.g.lexicon.concepts_of(&phrase).iter().any(|&c| {
                self.g
                    .lexicon
                    .concept(c)
                    .hypernyms
                    .iter()
                    .any(|&h| self.g.lexicon.concept(h).term == "room")
                    || self.g.lexicon.concept(c).term == "room"
            });
            if known && !is_room && !words::is_place_noun(&phrase) {
                return Err(GroundError::Unknown {
                    phrase: self.span_text(&(k - 1..k + len)),
                    suggestions: suggest(self.scene, &phrase),
                });
            }
        }
        Ok(())
    }
}

/// The modifiers before a noun that pick by place or size, read from the words.
struct Premods<'m> {
    /// "the second …", waiting for a direction.
    ordinal: &'m mut Option<usize>,
    /// "left", "front-right": (axis, sign, the word).
    sides: &'m [(words::Axis, f64, String)],
    /// "bigger", "tallest".
    sizes: &'m [String],
    /// "the middle …".
    middle: bool,
}

impl Reader<'_> {
    /// Selection: the candidates the modifiers before the noun keep — by side (with an
    /// ordinal, the n-th from that side), by size, in the middle — each needing a clear
    /// winner. `phrase` is the phrase so far, for messages.
    fn pick_by_premodifiers(
        &self,
        head: &Head,
        count: Count,
        mods: Premods<'_>,
        mut objects: Vec<usize>,
        reasons: &mut Vec<Reason>,
        phrase: &str,
    ) -> Result<Vec<usize>, GroundError> {
        if !mods.sides.is_empty() {
            let mut words_used: Vec<String> = mods.sides.iter().map(|s| s.2.clone()).collect();
            words_used.dedup();
            let label = words_used.join(" ");
            if let (Some(o), [(axis, sign, _)]) = (*mods.ordinal, mods.sides) {
                // "the second left chair": the second from the left.
                let picked = select::nth(self.scene, &objects, o, Direction::Side(*axis, *sign))
                    .ok_or_else(|| self.too_close(phrase, &objects, &label))?;
                objects = vec![picked];
                *mods.ordinal = None;
            } else {
                let mut direction = glam::DVec3::ZERO;
                for (axis, sign, _) in mods.sides {
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
        }
        for w in mods.sizes {
            if matches!(count, Count::All) && objects.len() > 1 {
                return Err(GroundError::NoPick {
                    phrase: phrase.to_string(),
                    reason: format!(
                        "say how many ('the two {} {}s') or name them",
                        superlative(w),
                        head.text
                    ),
                });
            }
            let (measure, sign, degree) = words::size_word(w).expect("a size word");
            let n = count.wanted(objects.len());
            let picked =
                select::by_size(self.scene, &objects, measure, sign, degree, n).map_err(|e| {
                    GroundError::NoPick {
                        phrase: phrase.to_string(),
                        reason: match e {
                            SizeError::ComparesTwo => format!(
                            "\"{w}\" compares two, but {} {}s fit ({}); say 'the {}' or name one",
                            objects.len(),
                            head.text,
                            error::list(&self.names(&objects)),
                            superlative(w)
                        ),
                            SizeError::TooClose => format!(
                                "{} are too close in size to tell which is {w}; name one ('{}')",
                                error::list(&self.names(&objects)),
                                self.name(objects[0])
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
}

fn modifier(detail: &str) -> Reason {
    Reason {
        kind: ReasonKind::Modifier,
        detail: detail.to_string(),
    }
}

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

fn ordinal_word(n: usize) -> &'static str {
    match n {
        1 => "first",
        2 => "second",
        3 => "third",
        4 => "fourth",
        5 => "fifth",
        6 => "sixth",
        7 => "seventh",
        8 => "eighth",
        9 => "ninth",
        10 => "tenth",
        _ => "last",
    }
}

/// The scene's names nearest a written one.
fn suggest(scene: &Scene, written: &str) -> Vec<String> {
    let wanted = words::normalize(written);
    let mut scored: Vec<(f64, &str)> = scene
        .objects
        .iter()
        .map(|o| {
            (
                strsim::jaro_winkler(&wanted, &words::normalize(&o.name)),
                o.name.as_str(),
            )
        })
        .filter(|(score, _)| *score >= 0.75)
        .collect();
    scored.sort_by(|a, b| b.0.total_cmp(&a.0));
    scored
        .into_iter()
        .take(3)
        .map(|(_, n)| n.to_string())
        .collect()
}

#[cfg(test)]
mod tests;

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
//!
//! The reader goes left to right, and each phrase goes through stages, each in its own
//! module: `head` finds the noun a phrase is built around and the objects it names;
//! `phrase` reads the phrase around it — `pre` the modifiers before it, `post` the one
//! after it (which `attach` decides picks, describes or is where the object goes),
//! `exclude` the members a group leaves out — and makes the last checks. `select` does
//! the geometric picks, `index` the names, `hold` the phrases held in place.

mod attach;
pub(crate) mod depend;
mod error;
mod exclude;
mod head;
mod hold;
pub mod ident;
mod index;
pub mod kind;
pub mod lexicon;
mod phrase;
mod post;
mod pre;
pub(crate) mod profile;
mod select;
pub mod verbs;
pub mod words;

pub use error::{Ambiguity, GroundError};
pub use lexicon::Lexicon;

use crate::scene::Scene;
use index::{NameIndex, Tier};
use select::{Direction, Relation};
use serde::Serialize;
use std::ops::Range;
use words::{Kind, Token};

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
    /// The names with brackets (`Chair (2)`, `Lamp [left]`), lower-cased, longest first:
    /// typed as they are, they are those objects.
    bracketed: Vec<String>,
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
    /// How well it names its candidates.
    tier: Tier,
    /// A plural (`the chairs`): a group.
    plural: bool,
    /// The head as a person wrote it, normalised (`chair`).
    text: String,
    /// Why it names its candidates.
    reason: Reason,
    /// A typo corrected in its words.
    typo: Option<Reason>,
}

/// A noun phrase read.
#[derive(Clone, Debug)]
struct Np {
    /// Its tokens.
    range: Range<usize>,
    /// The objects it means (a group left to right, then back to front).
    objects: Vec<usize>,
    /// The head's candidates before any pick: what "the other one" picks from.
    pool: Vec<usize>,
    /// What a modifier after the head left for a size word to pick from ("the tall box
    /// by the door": the boxes by the door): what a contrasting "the short one" picks
    /// from.
    near: Option<Vec<usize>>,
    reasons: Vec<Reason>,
    /// Its head's text: what "one" stands for next.
    head: String,
    /// Where what belongs to them was added ("table 4 and its chairs"): the phrase's own
    /// objects, which "it" after it means.
    owners: Option<Vec<usize>>,
}

impl Np {
    /// A phrase at tokens `range` naming a group of objects (their pool too), for the
    /// reason `detail`; `head` is what "one" stands for next.
    fn group(range: Range<usize>, objects: Vec<usize>, head: String, detail: String) -> Self {
        Self {
            range,
            pool: objects.clone(),
            near: None,
            objects,
            reasons: vec![Reason {
                kind: ReasonKind::Group,
                detail,
            }],
            head,
            owners: None,
        }
    }
}

/// A modifier after the noun.
#[derive(Clone, Debug)]
enum Post {
    /// On the floor: standing on nothing.
    Floor,
    /// At a side: "on the left", "at the back".
    Side(words::Axis, f64),
    /// "in the middle".
    Middle,
    /// An order from a side or a point: "from the left" (after an ordinal, or first).
    From(Direction),
    /// `from X`: an order from it after an ordinal ("the first chair from the window"),
    /// else where it is taken from ("the mug from the back counter").
    FromObject(usize),
    /// A relation to the objects of a nested phrase: "on the side table".
    Relation(Relation, Vec<usize>),
    /// A place in the room: "in the corner", "in the middle of the room", "on the wall".
    Room(select::RoomPlace),
    /// A row or column the objects stand in: "in the back row", "in row 3".
    Line(select::Line),
    /// Nothing of these rests on it ("without a lamp", "with no books on it"), or nothing
    /// at all (`None`: "with nothing on it").
    Lacks(Option<Vec<usize>>),
}

/// Whether a noun phrase stands on its own, or names the other object of a modifier
/// (where several fitting objects are fine: `the phone on the chair` looks at every chair).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    /// A phrase on its own.
    Main,
    /// The other object of a modifier (`the side table` in `the book on the side table`).
    Nested,
    /// A phrase left out of a group (`the one by the door` in `all the chairs except the
    /// one by the door`): it reads a modifier after it, as a phrase on its own does, but
    /// leaves nothing out itself.
    LeftOut,
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
    /// The objects of the last list of phrases grounded ("X1 and X2"): what "them" after
    /// a relation word means.
    group: Vec<usize>,
    /// What "it" or "them" with nothing named before means (the selection, or what the
    /// last edit moved): what a thing is taken from rests under it ("take it off the
    /// table").
    selection: Vec<usize>,
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
        let mut bracketed: Vec<String> = scene
            .objects
            .iter()
            .filter(|o| o.name.contains(['(', ')', '[', ']']) && !o.name.contains(['\'', '"']))
            .map(|o| o.name.to_lowercase())
            .collect();
        bracketed.sort_by_key(|n| std::cmp::Reverse(n.len()));
        Self {
            index: NameIndex::new(scene, lexicon),
            lexicon,
            objects: scene.objects.len(),
            bracketed,
        }
    }

    /// The instruction with each name with brackets typed as it is (`move Chair (2)
    /// left`) quoted, as a quoted name always means its object. Names already inside
    /// quotes, or inside a longer word, are left alone.
    fn quote_bracketed<'t>(&self, text: &'t str) -> std::borrow::Cow<'t, str> {
        if self.bracketed.is_empty() || !text.contains(['(', '[']) {
            return std::borrow::Cow::Borrowed(text);
        }
        let mut out = text.to_string();
        for name in &self.bracketed {
            let lower = out.to_lowercase();
            // Lower-casing may change byte lengths outside ASCII: only a text it keeps.
            if lower.len() != out.len() {
                break;
            }
            let Some(at) = lower
                .match_indices(name.as_str())
                .map(|(i, _)| i)
                .find(|&i| {
                    let before = lower[..i].chars().next_back();
                    let after = lower[i + name.len()..].chars().next();
                    let quotes_before = lower[..i].matches(['\'', '"']).count();
                    !before.is_some_and(char::is_alphanumeric)
                        && !after.is_some_and(char::is_alphanumeric)
                        && quotes_before % 2 == 0
                })
            else {
                continue;
            };
            out.insert(at + name.len(), '"');
            out.insert(at, '"');
        }
        std::borrow::Cow::Owned(out)
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

    /// The kind of object an instruction that grounds to nothing speaks of ("move the
    /// window left": `window`): a word after a determiner that the lexicon knows as a kind
    /// of object, as typed.
    fn absent_kind(&self, text: &str) -> Option<String> {
        let tokens = words::tokenize(text);
        tokens.windows(2).find_map(|pair| {
            let det = pair[0].word()?;
            let word = pair[1].word()?;
            let known = self.lexicon.knows(word)
                || self
                    .lexicon
                    .singulars(word)
                    .iter()
                    .any(|s| self.lexicon.knows(s));
            // Place nouns ("the window", "the door") are kinds a person looks for too.
            // The floor, the walls and the room are always there, named or not.
            let grammar = crate::discourse::is_discourse_word(word)
                || words::is_room_part(word)
                || words::is_verb(word)
                || words::side_word(word).is_some()
                || words::size_word(word).is_some()
                || words::ordinal(word).is_some()
                || words::count_word(word).is_some();
            (matches!(
                det,
                "the" | "a" | "an" | "that" | "this" | "my" | "those" | "these"
            ) && known
                && !grammar)
                .then(|| word.to_string())
        })
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
        self.ground_with_focus(instruction, scene, selection, false)
    }

    /// [`Grounder::ground_with_selection`] where the objects "it" means are either the
    /// selection or (`last_edit`) what the conversation's last edit moved, as the reasons
    /// say.
    ///
    /// # Errors
    /// As [`Grounder::ground`].
    pub fn ground_with_focus(
        &self,
        instruction: &str,
        scene: &Scene,
        selection: &[usize],
        last_edit: bool,
    ) -> Result<Grounding, GroundError> {
        let quoted = self.quote_bracketed(instruction.trim());
        let marked = words::imperial_marks(&quoted);
        let lined = words::line_of_objects(&marked);
        let text = lined.as_ref();
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
        reader.selection = selection.to_vec();
        let mut phrases = match reader.read() {
            Ok(phrases) => phrases,
            // An instruction that names nothing but speaks of the selection.
            Err(GroundError::NoObject { .. }) if !selection.is_empty() => Vec::new(),
            Err(e) => return Err(e),
        };
        if let Some(phrase) = selection_phrase(text, scene, selection, &phrases, last_edit) {
            let at = phrases
                .iter()
                .position(|p| p.span.start > phrase.span.start)
                .unwrap_or(phrases.len());
            phrases.insert(at, phrase);
        }
        if phrases.is_empty() {
            if let Some(word) = self.absent_kind(text) {
                return Err(GroundError::absent(word, scene));
            }
            return Err(GroundError::NoObject {
                names: error::first_names(scene),
                total: scene.objects.len(),
            });
        }
        let (phrases, mut held, mut cuts) = separate_holds(&reader.tokens, phrases);
        // "…, but don't move anything else": every object not named is held.
        if let Some(cut) = hold::everything_else(&reader.tokens) {
            // (What rests on a named object goes with it.)
            let mut named = vec![false; scene.objects.len()];
            for &o in phrases.iter().chain(&held).flat_map(|p| &p.objects) {
                named[o] = true;
                for c in scene.carried_by(o) {
                    named[c] = true;
                }
            }
            held.push(Phrase {
                span: cut.clone(),
                text: text[cut.clone()].trim_start_matches([',', ' ']).to_string(),
                objects: (0..scene.objects.len()).filter(|&o| !named[o]).collect(),
                reasons: vec![Reason {
                    kind: ReasonKind::Group,
                    detail: "every object not named stays where it is".into(),
                }],
            });
            cuts.push(cut);
        }
        let phrases = drop_parts(text, drop_restated(text, phrases, &mut cuts, scene)?, scene);
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

/// Drops a phrase in brackets right after another that names the same objects ("the
/// door (Cube.009)"): it says again which, not another object. Its brackets and words are
/// cut from the query.
///
/// # Errors
/// A phrase in brackets that names other objects than the one before it: which is meant
/// is not clear.
fn drop_restated(
    text: &str,
    phrases: Vec<Phrase>,
    cuts: &mut Vec<Range<usize>>,
    scene: &Scene,
) -> Result<Vec<Phrase>, GroundError> {
    let mut kept: Vec<Phrase> = Vec::with_capacity(phrases.len());
    for p in phrases {
        let bracketed = kept.last().filter(|prev| {
            prev.span.end <= p.span.start
                && text[prev.span.end..p.span.start].trim() == "("
                && text[p.span.end..].trim_start().starts_with(')')
        });
        match bracketed {
            Some(prev) if prev.objects == p.objects => {
                let open = text[..p.span.start].rfind('(').unwrap_or(p.span.start);
                let close = p.span.end + text[p.span.end..].find(')').map_or(0, |k| k + 1);
                cuts.push(open..close);
            }
            Some(prev) => {
                let names = |objects: &[usize]| {
                    error::list(
                        &objects
                            .iter()
                            .map(|&o| scene.objects[o].name.clone())
                            .collect::<Vec<_>>(),
                    )
                };
                return Err(GroundError::NoPick {
                    phrase: format!("{} ({})", prev.text, p.text),
                    reason: format!(
                        "\"{}\" is {}, not {}; say which",
                        prev.text,
                        names(&prev.objects),
                        names(&p.objects)
                    ),
                });
            }
            None => kept.push(p),
        }
    }
    Ok(kept)
}

/// The phrases that name a shelf of the case of shelves named right after them ("the top
/// shelf of the bookcase", "the second shelf from the top of the bookcase"): a part of
/// that object, not an object — the words stay for the translator, which reads which
/// shelf.
fn drop_parts(text: &str, phrases: Vec<Phrase>, scene: &Scene) -> Vec<Phrase> {
    let mut kept: Vec<Phrase> = Vec::with_capacity(phrases.len());
    for (k, p) in phrases.iter().enumerate() {
        let part = p
            .text
            .rsplit(' ')
            .next()
            .is_some_and(|w| matches!(w.to_lowercase().as_str(), "shelf" | "shelves"));
        let whole = phrases.get(k + 1).filter(|q| {
            text.get(p.span.end..q.span.start).is_some_and(|between| {
                let between = between.trim().to_lowercase();
                // "the second shelf from the top of the bookcase".
                let between = ["from the top ", "from the bottom "]
                    .iter()
                    .find_map(|from| between.strip_prefix(from))
                    .unwrap_or(&between);
                matches!(between.trim(), "of" | "in" | "on")
            }) && q.objects.iter().all(|&o| kind::form_of(scene, o).shelves())
        });
        if !(part && whole.is_some()) {
            kept.push(p.clone());
        }
    }
    kept
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
/// object(s)" before any named object ([`selection_words`]), or `None`.
fn selection_phrase(
    text: &str,
    scene: &Scene,
    selection: &[usize],
    phrases: &[Phrase],
    last_edit: bool,
) -> Option<Phrase> {
    if selection.is_empty() {
        return None;
    }
    let before = phrases.first().map_or(text.len(), |p| p.span.start);
    let span = selection_words(&text[..before]).or_else(|| pronoun_as_place(text, phrases))?;
    let names: Vec<String> = selection
        .iter()
        .map(|&i| format!("'{}'", scene.objects[i].name))
        .collect();
    Some(Phrase {
        text: text[span.clone()].to_string(),
        objects: selection.to_vec(),
        reasons: vec![Reason {
            kind: ReasonKind::Selection,
            detail: format!(
                "\"{}\" is {}: {}",
                &text[span.clone()],
                if last_edit {
                    "what the last edit moved"
                } else {
                    "the selection"
                },
                error::list(&names)
            ),
        }],
        span,
    })
}

/// The pronoun of "put the lamp on it": a verb's one object, then a place whose object is
/// "it" or "them" — which cannot be that object itself, so it is the selection. Its bytes.
fn pronoun_as_place(text: &str, phrases: &[Phrase]) -> Option<Range<usize>> {
    let [object] = phrases else {
        return None;
    };
    let from = object.span.end;
    let tokens = words::tokenize(text.get(from..)?);
    let word = |k: usize| match tokens.get(k).map(|t| &t.kind) {
        Some(Kind::Word(w)) => w.to_lowercase(),
        _ => String::new(),
    };
    let mut k = 0;
    // "on", "onto", "next to", "on top of", "in front of".
    while k < 4 && (words::is_preposition(&word(k)) || matches!(word(k).as_str(), "top" | "front"))
    {
        k += 1;
    }
    let place = k > 0 && !matches!(word(0).as_str(), "of" | "with" | "as" | "like" | "than");
    (place && matches!(word(k).as_str(), "it" | "them"))
        .then(|| from + tokens[k].span.start..from + tokens[k].span.end)
}

/// The bytes of the first words of `text` that point at the selection, or at what was
/// just moved: "it", "them", "the selection", "the selected object(s)", and "that" (or
/// "this", "those", "these") as a pronoun — before a preposition, a side, a number or
/// nothing, not a determiner.
#[must_use]
pub fn selection_words(text: &str) -> Option<Range<usize>> {
    let tokens = words::tokenize(text);
    let word = |k: usize| match tokens.get(k).map(|t| &t.kind) {
        Some(Kind::Word(w)) => w.to_lowercase(),
        _ => String::new(),
    };
    for k in 0..tokens.len() {
        let w = word(k);
        let range = match w.as_str() {
            // "both of them", "all of them", "them both", "them all".
            "them" => {
                let quantified = word(k.wrapping_sub(1)) == "of"
                    && matches!(
                        word(k.wrapping_sub(2)).as_str(),
                        "both" | "all" | "each" | "two" | "three" | "pair"
                    );
                let start = match (quantified, word(k.wrapping_sub(3)).as_str()) {
                    (true, "the") => k - 3,
                    (true, _) => k - 2,
                    (false, _) => k,
                };
                let end = if matches!(word(k + 1).as_str(), "both" | "all") {
                    k + 2
                } else {
                    k + 1
                };
                start..end
            }
            "it" => k..k + 1,
            // "those two", "these three", "both of those".
            "those" | "these"
                if matches!(word(k + 1).as_str(), "two" | "three" | "both" | "all")
                    || (word(k.wrapping_sub(1)) == "of"
                        && matches!(word(k.wrapping_sub(2)).as_str(), "both" | "all" | "each")) =>
            {
                let start = if word(k.wrapping_sub(1)) == "of" {
                    k - 2
                } else {
                    k
                };
                let end = if matches!(word(k + 1).as_str(), "two" | "three" | "both" | "all") {
                    k + 2
                } else {
                    k + 1
                };
                start..end
            }
            "that" | "this" | "those" | "these"
                if tokens.get(k + 1).is_none_or(|t| match &t.kind {
                    Kind::Word(next) => {
                        words::is_preposition(&next.to_lowercase())
                            || words::side_word(&next.to_lowercase()).is_some()
                    }
                    _ => true,
                }) =>
            {
                k..k + 1
            }
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
        return Some(tokens[range.start].span.start..tokens[range.end - 1].span.end);
    }
    None
}

/// Whether `w` is a word of the grammar (a verb, preposition, determiner, modifier,
/// pronoun, unit…): never corrected as a typo, and a noun only after a determiner.
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
        || words::shape_word(w).is_some()
        || words::is_degree_word(w)
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
    /// Reads `text`'s words, with `#` / `number` before a number skipped and typos
    /// corrected.
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
            group: Vec::new(),
            selection: Vec::new(),
        };
        reader.correct_typos();
        reader.number_words();
        reader
    }

    /// Reads a word of five letters or more that is no known word as the index word one
    /// edit away, when there is exactly one.
    fn correct_typos(&mut self) {
        for k in 0..self.tokens.len() {
            let Some(w) = self.tokens[k].word() else {
                continue;
            };
            let n = w.chars().count();
            // Four letters: only two neighbours swapped ("bleu"), which rarely makes another
            // word; five or more: any one edit.
            let swap_only = n == TYPO_MIN_LETTERS - 1;
            if n < TYPO_MIN_LETTERS - 1
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
            let mut near = self.g.index.one_edit_away(w);
            if swap_only {
                // (Of colours only: a four-letter name swapped is too often another.)
                near.retain(|c| words::is_colour(c) && words::neighbours_swapped(w, c));
            }
            if let [one] = near.as_slice() {
                self.typos[k] = Some(w.to_string());
                self.words[k] = Some(one.to_string());
            } else if let Some(stem) = w
                .strip_suffix('s')
                .filter(|s| !swap_only && s.chars().count() >= TYPO_MIN_LETTERS - 1)
            {
                // A typo in a plural: "speakrs".
                if let [one] = self.g.index.one_edit_away(stem).as_slice() {
                    self.typos[k] = Some(w.to_string());
                    self.words[k] = Some(format!("{one}s"));
                }
            }
        }
    }

    /// The word at token `k` as written, if it is one.
    fn word(&self, k: usize) -> Option<&str> {
        self.tokens.get(k).and_then(Token::word)
    }

    /// Whether the word at token `k` is one of `options`.
    fn is_word(&self, k: usize, options: &[&str]) -> bool {
        self.word(k).is_some_and(|w| options.contains(&w))
    }

    /// The instruction's text of tokens `range`.
    fn span_text(&self, range: &Range<usize>) -> String {
        self.text[self.byte_span(range)].to_string()
    }

    /// The bytes of the instruction that tokens `range` cover.
    fn byte_span(&self, range: &Range<usize>) -> Range<usize> {
        self.tokens[range.start].span.start..self.tokens[range.end - 1].span.end
    }

    /// The name of object `i`.
    fn name(&self, i: usize) -> String {
        self.scene.objects[i].name.clone()
    }

    /// The names of `objects`.
    fn names(&self, objects: &[usize]) -> Vec<String> {
        objects.iter().map(|&i| self.name(i)).collect()
    }

    /// Every phrase, left to right.
    fn read(&mut self) -> Result<Vec<Phrase>, GroundError> {
        let mut phrases: Vec<Phrase> = Vec::new();
        let mut nps: Vec<Np> = Vec::new();
        let else_words = hold::else_words(&self.tokens);
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
                    near: None,
                    reasons: vec![Reason {
                        kind: ReasonKind::Quoted,
                        detail: format!("'{}' is quoted", name.trim()),
                    }],
                    head: words::normalize(name),
                    owners: None,
                };
                self.commit(np, &mut phrases, &mut nps);
                k += 1;
                continue;
            }
            // "… anything else": no object of its own ([`hold::everything_else`]).
            if let Some(n) = else_words[k] {
                k += n;
                continue;
            }
            // "… its bench": what the objects named last rest on or are drawn up to;
            // "…, stools and all": what belongs to them.
            let owned = self.antecedent.clone();
            if let Some(np) = self
                .possessed_at(k, &owned)
                .or_else(|| self.and_all_at(k, &owned))
            {
                let end = np.range.end;
                self.commit(np, &mut phrases, &mut nps);
                k = end;
                continue;
            }
            // "the back row of tables (and their chairs)".
            if let Some(np) = self.line_of_at(k)? {
                let np = self.with_dependents(np, false)?;
                let end = np.range.end;
                self.commit(np, &mut phrases, &mut nps);
                k = end;
                continue;
            }
            let bound: Vec<usize> = phrases.iter().flat_map(|p| p.objects.clone()).collect();
            let head = self.head_at(k).or_else(|| self.anaphor_at(k, &nps, &bound));
            match head {
                Some(head) if self.opens_ok(&head) => {
                    let end = head.range.end;
                    let generic = head.generic;
                    let np = self.noun_phrase(head, &bound, Mode::Main)?;
                    let np = self.with_dependents(np, generic)?;
                    let end = end.max(np.range.end);
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

    /// Takes a noun phrase as read: its tokens are used up, it is a phrase of the
    /// grounding, and what "it" refers to next.
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
        // "the benches and the shelf … on them": a list joined by "and" or commas is
        // what "them" means.
        let joined = nps.last().is_some_and(|prev| {
            let gap = prev.range.end..np.range.start;
            (1..=2).contains(&gap.len())
                && gap.clone().all(|i| {
                    self.is_word(i, &["and", "plus"])
                        || matches!(self.tokens[i].kind, Kind::Punct(','))
                })
        });
        if joined {
            self.group.extend(np.objects.iter().copied());
        } else {
            self.group.clone_from(&np.objects);
        }
        // ("table 4 and its chairs and everything on it": "it" is the table.)
        self.antecedent
            .clone_from(np.owners.as_ref().unwrap_or(&np.objects));
        nps.push(np);
    }

    /// The refusal for a pick by `word` that cannot tell `objects` apart.
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

    /// The refusal of the phrase at `range` (its head noun `noun`) that could mean each
    /// of `objects`: named, with the candidate at position `example` (or the last) as the
    /// one to name and [`Self::hints`] for saying which.
    fn ambiguous(
        &self,
        range: &Range<usize>,
        noun: &str,
        objects: &[usize],
        example: usize,
    ) -> GroundError {
        let names = self.names(objects);
        GroundError::Ambiguous {
            phrase: self.span_text(range),
            span: self.byte_span(range),
            example: names[example.min(names.len() - 1)].clone(),
            hints: self.hints(noun, objects),
            candidates: names,
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

    /// "desk five", "chair twelve": a number word right after a noun is an instance
    /// number when an object is named so (`Desk 5`), and no amount goes on after it
    /// ("move the stool two and a half feet", "… two five cm" keep their amounts).
    fn number_words(&mut self) {
        for k in 1..self.tokens.len() {
            let Some(n) = self.word(k).and_then(crate::lex::number_word) else {
                continue;
            };
            let Some(base) = self.words[k - 1].as_deref().filter(|w| !w.is_empty()) else {
                continue;
            };
            let number = n as u32;
            // ("two and a half feet", "three point five metres", "five or six cm": an
            // amount goes on.)
            let amount_goes_on = self.unit_follows(k + 1)
                || self.word(k + 1).is_some_and(|w| {
                    crate::lex::number_word(w).is_some()
                        || matches!(
                            w,
                            "and" | "point" | "dot" | "half" | "quarter" | "or" | "plus" | "times"
                        )
                });
            if amount_goes_on || self.g.index.numbered(base, number).is_none() {
                continue;
            }
            self.words[k] = Some(number.to_string());
        }
    }

    /// Refuses a noun the lexicon knows, after a determiner, that no object answers to:
    /// `move the piano` in a room with no piano.
    fn check_unknown(&self, k: usize) -> Result<(), GroundError> {
        let Some(w) = self.word(k) else { return Ok(()) };
        // (A window or a door is an object a scene may lack, though a place word: "there
        // is no window".)
        let object_place = words::is_place_noun(w) && !words::is_room_part(w);
        if (grammar_word(w) && !object_place) || self.consumed[k] {
            return Ok(());
        }
        let det =
            k > 0 && self.word(k - 1).is_some_and(words::is_determiner) && !self.consumed[k - 1];
        if !det {
            return Ok(());
        }
        if object_place {
            return Err(GroundError::absent(self.span_text(&(k..k + 1)), self.scene));
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
            if known && !is_room && !words::is_room_part(&phrase) {
                return Err(GroundError::Unknown {
                    phrase: self.span_text(&(k - 1..k + len)),
                    suggestions: suggest(self.scene, &phrase),
                });
            }
        }
        Ok(())
    }
}

/// A reason of kind [`ReasonKind::Modifier`].
fn modifier(detail: &str) -> Reason {
    Reason {
        kind: ReasonKind::Modifier,
        detail: detail.to_string(),
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

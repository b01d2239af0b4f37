//! The name index of a scene: every phrase a person may use for each object, built once
//! per scene, with how well it names the object.

use super::ident::{self, Identifier, NameSide};
use super::lexicon::Lexicon;
use super::words::{compact, normalize, split_number};
use crate::scene::Scene;
use hashbrown::HashTable;
use rustc_hash::{FxHashMap, FxHashSet, FxHasher};
use std::hash::Hasher;

/// How a phrase names an object, best first. A phrase means the objects it names at the
/// best tier present: "the cup" means the 'coffee cup' (a literal word of its name) rather
/// than the 'mug' (a synonym).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) enum Tier {
    /// The object's name, or its name without the number (`chair` for 'chair 2').
    Name,
    /// One of the object's own aliases.
    Alias,
    /// Its category, or the last words of its name (`lamp` for 'floor lamp').
    Category,
    /// The end of a closed compound that the lexicon says it is (`book` for 'textbook',
    /// `chair` for 'armchair'): as good as [`Tier::Category`] where the best an object
    /// is named is by category ("the book" with a 'textbook' and an 'exercise book' means
    /// either), but not beside objects named by it ("the left chair" with 'chair',
    /// 'chair 2' and an 'armchair' picks between the chairs).
    Compound,
    /// A synonym of its name or category (`couch` for 'sofa').
    Synonym,
    /// A broader category (`seat` for 'armchair').
    Hypernym,
    /// A word of its name the lexicon does not know, said alone (`the fern` for
    /// 'Plant_Fern', `the till` for 'Till_POS'): a variety or a trade word people call
    /// the object by. The weakest tier: only where nothing names the phrase otherwise.
    NameWord,
}

/// A box whose smallest side is at least this share of its largest is round enough for a
/// sphere to be called a ball.
const ROUND_RATIO: f64 = 0.7;

/// What a modelling tool's primitive shape looks like to a person.
fn shape_words(primitive: &str) -> &'static [&'static str] {
    match primitive {
        "cube" => &["box", "block"],
        "sphere" | "icosphere" | "uvsphere" => &["ball", "sphere", "globe"],
        "cylinder" => &["cylinder", "column"],
        "torus" => &["ring", "donut", "doughnut"],
        "plane" => &["sheet", "panel"],
        // Blender's monkey head.
        "suzanne" => &["monkey", "monkey head", "monkey's head"],
        _ => &[],
    }
}

/// How a broader word `hyper` names an object called `kind`: as its category where `kind`
/// is a closed compound ending in it ('textbook' is a book as 'exercise book' is, and
/// 'armchair' a chair as 'desk chair' is), else as a hypernym.
fn hypernym_tier(kind: &str, hyper: &str) -> Tier {
    let closed = !kind.contains(' ') && !hyper.contains(' ');
    match kind.strip_suffix(hyper) {
        Some(first) if closed && first.len() >= 3 && hyper.len() >= 3 => Tier::Compound,
        _ => Tier::Hypernym,
    }
}

/// Whether a word of a name, unknown to the lexicon, can stand alone for the object: a
/// word of three letters or more that is no colour, size, side or part of the room
/// (which describe or place, never name).
fn own_word(lexicon: &Lexicon, w: &str) -> bool {
    use super::words;
    w.len() >= 3
        && w.chars().all(|c| c.is_ascii_alphabetic())
        && !lexicon.knows(w)
        && lexicon.singulars(w).iter().all(|s| !lexicon.knows(s))
        && !words::is_colour(w)
        && words::size_word(w).is_none()
        && words::side_word(w).is_none()
        && !words::is_place_noun(w)
        && !words::is_determiner(w)
}

/// What a posting names: a group of objects that share every phrase but their own names
/// (which [`Names`] indexes).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Target(u32);

/// Every object's normalised name, in one buffer, hashed by the name and by the name
/// without spaces: no allocation per object, so a scene of a million objects is indexed
/// (and dropped) quickly.
#[derive(Clone, Debug, Default)]
struct Names {
    text: String,
    /// Where each object's name ends in `text` (it starts where the previous one ends).
    ends: Vec<usize>,
    /// Objects by `hash(name)`.
    by_name: HashTable<u32>,
    /// Objects by `hash(name without spaces)`.
    by_compact: HashTable<u32>,
}

fn hash_str(s: &str) -> u64 {
    let mut h = FxHasher::default();
    h.write(s.as_bytes());
    h.finish()
}

/// The hash of `s` without its whitespace, computed without building it.
fn hash_compact(s: &str) -> u64 {
    let mut h = FxHasher::default();
    for c in s.chars().filter(|c| !c.is_whitespace()) {
        let mut buf = [0; 4];
        h.write(c.encode_utf8(&mut buf).as_bytes());
    }
    h.finish()
}

fn compact_eq(a: &str, b: &str) -> bool {
    a.chars()
        .filter(|c| !c.is_whitespace())
        .eq(b.chars().filter(|c| !c.is_whitespace()))
}

impl Names {
    fn get(&self, object: u32) -> &str {
        let i = object as usize;
        let start = if i == 0 { 0 } else { self.ends[i - 1] };
        &self.text[start..self.ends[i]]
    }

    fn push(&mut self, name: &str) {
        let object = self.ends.len() as u32;
        self.text.push_str(name);
        self.ends.push(self.text.len());
        let ends = &self.ends;
        let text = &self.text;
        let rehash = |by: fn(&str) -> u64| {
            move |&o: &u32| {
                let i = o as usize;
                let start = if i == 0 { 0 } else { ends[i - 1] };
                by(&text[start..ends[i]])
            }
        };
        self.by_name
            .insert_unique(hash_str(name), object, rehash(hash_str));
        self.by_compact
            .insert_unique(hash_compact(name), object, rehash(hash_compact));
    }

    /// The objects whose normalised name is `phrase`.
    fn named<'a>(&'a self, phrase: &'a str) -> impl Iterator<Item = u32> + 'a {
        self.by_name
            .iter_hash(hash_str(phrase))
            .copied()
            .filter(move |&o| self.get(o) == phrase)
    }

    /// The objects whose normalised name without spaces is `phrase` without spaces.
    fn named_compact<'a>(&'a self, phrase: &'a str) -> impl Iterator<Item = u32> + 'a {
        self.by_compact
            .iter_hash(hash_compact(phrase))
            .copied()
            .filter(move |&o| compact_eq(self.get(o), phrase))
    }
}

/// Which word of the object a phrase came through, for reports (`sofa` for `couch`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Via {
    /// The object's own (normalised) name.
    Name,
    /// An interned word ([`NameIndex::vias`]).
    Word(u32),
}

/// One way a phrase names a target.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Posting {
    target: Target,
    tier: Tier,
    via: Via,
}

/// The objects a phrase names at its best tier.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Hit<'a> {
    /// How well the phrase names them.
    pub tier: Tier,
    /// The objects, in scene order.
    pub objects: Vec<usize>,
    /// For reports: the word of the first object the phrase came through.
    pub via: &'a str,
}

/// Objects named alike: the same name without its number, aliases, category and
/// attributes, so the same phrases (synonyms, hypernyms, kinds) name all of them. A
/// warehouse of 100,000 'box N' is one group; its phrases are indexed once.
#[derive(Clone, Debug, Default)]
struct Group {
    objects: Vec<u32>,
    /// The words of the group's names, category, aliases and attributes, for picking by
    /// a word (`the red chair`, `the teacher's desk`).
    descriptors: FxHashSet<Box<str>>,
}

/// Words for containers, which people name by their contents.
const CONTAINERS: &[&str] = &[
    "bottle",
    "bottles",
    "dispenser",
    "jar",
    "jug",
    "carton",
    "tub",
    "tube",
    "packet",
    "pack",
    "bag",
    "sack",
    "tin",
    "canister",
    "decanter",
    "pot",
];

/// The index.
#[derive(Clone, Debug, Default)]
pub(crate) struct NameIndex {
    /// Normalised phrase → what it names.
    terms: FxHashMap<Box<str>, Vec<Posting>>,
    /// A base name without spaces (`dogbed`) → the groups of that base name.
    compact: FxHashMap<Box<str>, Vec<u32>>,
    /// The objects' own names.
    names: Names,
    /// Per object: its group.
    group_of: Vec<u32>,
    /// Per object: the instance number its name ends in (`3` for `Lamp_Table.003`).
    numbers: Vec<Option<u32>>,
    groups: Vec<Group>,
    /// The words postings came through.
    vias: Vec<Box<str>>,
    /// Every word that can describe some object.
    pub descriptor_words: FxHashSet<Box<str>>,
    /// The words of the objects' attributes (colours, materials): a phrase that uses one
    /// must be picking by it.
    pub attribute_words: FxHashSet<Box<str>>,
    /// Single words of all terms, by length in characters, for typo correction.
    vocabulary: Vec<Vec<Box<str>>>,
    /// The longest term, in words.
    pub max_words: usize,
    /// The objects whose names say nothing of what they are (`pCube1`, `Object_12`), with
    /// no alias or category: what [`profile`](super::profile) words may name.
    pub anonymous: Vec<usize>,
    /// Names of one capitalised word (`Cube`, `Cylinder`, `Suzanne` as Blender names its
    /// first of each), as written, and the one object so named.
    pub capitalised: FxHashMap<Box<str>, usize>,
}

/// What makes objects named alike: the name without its number (as written, and as read:
/// kind, other reading, side), aliases, category, attributes (normalised).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
struct GroupKey {
    written: String,
    kind: String,
    other: Option<String>,
    side: Option<NameSide>,
    aliases: Vec<String>,
    category: Option<String>,
    attributes: Vec<String>,
}

/// Builds the index, interning `via` words as it goes.
#[derive(Default)]
struct Builder {
    index: NameIndex,
    via_ids: FxHashMap<Box<str>, u32>,
    group_ids: FxHashMap<GroupKey, u32>,
}

impl Builder {
    fn via(&mut self, word: &str) -> Via {
        if let Some(&id) = self.via_ids.get(word) {
            return Via::Word(id);
        }
        let id = self.index.vias.len() as u32;
        self.index.vias.push(word.into());
        self.via_ids.insert(word.into(), id);
        Via::Word(id)
    }

    /// Adds a phrase for a target; a target keeps its best tier for a phrase (and the
    /// Files `target` under a name written without its spaces (`coffeetable`), once.
    fn add_compact(&mut self, compacted: &str, target: Target) {
        let list = self.index.compact.entry(compacted.into()).or_default();
        if list.last() != Some(&target.0) {
            list.push(target.0);
        }
    }

    /// word it first came through at that tier).
    fn add(&mut self, phrase: &str, target: Target, tier: Tier, via: Via) {
        if phrase.is_empty() {
            return;
        }
        let index = &mut self.index;
        index.max_words = index.max_words.max(phrase.split(' ').count());
        let list = match index.terms.get_mut(phrase) {
            Some(list) => list,
            None => index.terms.entry(phrase.into()).or_default(),
        };
        // Targets are indexed one after another, so a target's posting for a phrase, if
        // any, is the list's last: no scan of a list that may hold thousands.
        match list.last_mut().filter(|p| p.target == target) {
            Some(p) if p.tier <= tier => {}
            Some(p) => {
                p.tier = tier;
                p.via = via;
            }
            None => list.push(Posting { target, tier, via }),
        }
    }

    /// The group of objects named like this one, made (with all its phrases) the first
    /// time such an object is seen.
    fn group(
        &mut self,
        object: &crate::scene::Object,
        written: &str,
        id: &Identifier,
        lexicon: &Lexicon,
    ) -> u32 {
        let labels = Labels::of(object);
        let key = GroupKey {
            written: written.to_string(),
            kind: id.base.clone(),
            other: id.other.clone(),
            side: id.side,
            aliases: labels.aliases.clone(),
            category: labels.category.clone(),
            attributes: labels.attributes.clone(),
        };
        if let Some(&g) = self.group_ids.get(&key) {
            return g;
        }
        let g = self.index.groups.len() as u32;
        self.index.groups.push(Group::default());
        self.group_ids.insert(key, g);
        let target = Target(g);

        let mut descriptors: FxHashSet<Box<str>> = FxHashSet::default();
        self.add_names(target, written, id, &mut descriptors);
        let mut kinds = self.add_kinds(target, id, &labels);
        self.add_tails(target, &mut kinds, &mut descriptors);
        // Words of a kind next to each other typed as one ("the firepit" for
        // `SM_FirePit_Round`, "the sidetable").
        for (kind, _) in &kinds {
            let w: Vec<&str> = kind.split(' ').collect();
            for a in 0..w.len() {
                for b in a + 2..=w.len() {
                    self.add_compact(&w[a..b].concat(), target);
                }
            }
        }
        for attribute in &labels.attributes {
            for w in attribute.split(' ') {
                descriptors.insert(w.into());
                self.index.attribute_words.insert(w.into());
            }
        }
        self.add_lexicon(target, &kinds, lexicon);
        let round = {
            let size = object.world_aabb().size();
            let (lo, hi) = (
                size.x.min(size.y).min(size.z),
                size.x.max(size.y).max(size.z),
            );
            hi > 0.0 && lo >= ROUND_RATIO * hi
        };
        self.add_shapes(target, &kinds, round);
        self.add_name_words(target, id, lexicon);
        descriptors.retain(|d| d.chars().any(char::is_alphabetic));
        self.index
            .descriptor_words
            .extend(descriptors.iter().cloned());
        self.index.groups[g as usize].descriptors = descriptors;
        g
    }

    /// A group's own names: as written and as read (`base`), without spaces, and with the
    /// side its name says (`SideTable_L` is "the left side table").
    fn add_names(
        &mut self,
        target: Target,
        written: &str,
        id: &Identifier,
        descriptors: &mut FxHashSet<Box<str>>,
    ) {
        let base = id.base.as_str();
        self.add(written, target, Tier::Name, Via::Name);
        self.add(base, target, Tier::Name, Via::Name);
        for b in [written, base] {
            self.add_compact(&compact(b), target);
        }
        if let Some(side) = id.side {
            // `SideTable_L` is "the left side table" by its name.
            let via = self.via(base);
            self.add(&format!("{} {base}", side.word()), target, Tier::Name, via);
            descriptors.insert(side.word().into());
        }
    }

    /// What a group is called besides its name — the other order of its name, its aliases,
    /// its category, what its container holds — added; returns every kind it is called
    /// (each with whether it is a whole name, not the end of one).
    fn add_kinds(
        &mut self,
        target: Target,
        id: &Identifier,
        labels: &Labels,
    ) -> Vec<(String, bool)> {
        let base = id.base.as_str();
        let mut kinds: Vec<(String, bool)> = vec![(base.to_string(), true)];
        if let Some(other) = &id.other {
            // Both orders of the name are objects (`Lamp_Table`): it answers to both.
            let via = self.via(base);
            self.add(other, target, Tier::Category, via);
            kinds.push((other.clone(), true));
        }
        for a in &labels.aliases {
            let via = self.via(a);
            self.add(a, target, Tier::Alias, via);
            kinds.push((split_number(a).0.to_string(), true));
        }
        if let Some(c) = &labels.category {
            let via = self.via(c);
            self.add(c, target, Tier::Category, via);
            kinds.push((c.clone(), true));
        }
        // A container is named by what it holds: 'shampoo bottle' is "the shampoo",
        // 'soap dispenser' "the soap", 'red wine bottle' "the red wine".
        let w: Vec<&str> = base.split(' ').collect();
        if w.len() >= 2 && CONTAINERS.contains(&w[w.len() - 1]) {
            let content = w[..w.len() - 1].join(" ");
            let via = self.via(base);
            self.add(&content, target, Tier::Category, via);
        }
        kinds
    }

    /// The last words of each kind, as categories: 'floor lamp' is a lamp, 'red wine
    /// bottle' a wine bottle and a bottle. They join `kinds` (not as whole names), and
    /// every word of a kind describes the group.
    fn add_tails(
        &mut self,
        target: Target,
        kinds: &mut Vec<(String, bool)>,
        descriptors: &mut FxHashSet<Box<str>>,
    ) {
        for (kind, _) in kinds.clone() {
            let w: Vec<&str> = kind.split(' ').collect();
            let via = self.via(&kind);
            for k in 1..w.len() {
                // A letter or a lone digit ends names as a code (`Parasol_A`, `Bench A 1`),
                // never as what the object is: "the BBQ a bit" is no parasol.
                if k == w.len() - 1 && w[k].chars().count() == 1 {
                    continue;
                }
                let tail = w[k..].join(" ");
                self.add(&tail, target, Tier::Category, via);
                kinds.push((tail, false));
            }
            // One word of a longer name with its head: 'coffee round table'
            // (`Table_Coffee_Round`) is a coffee table as well as a round table.
            if let [modifiers @ .., _, head] = w.as_slice() {
                for m in modifiers {
                    let pair = format!("{m} {head}");
                    self.add(&pair, target, Tier::Category, via);
                    kinds.push((pair, false));
                }
            }
            descriptors.extend(w.iter().map(|&s| Box::<str>::from(s)));
        }
    }

    /// Lexicon: synonyms of what the group is called, and its hypernyms.
    fn add_lexicon(&mut self, target: Target, kinds: &[(String, bool)], lexicon: &Lexicon) {
        for (kind, whole) in kinds {
            let via = self.via(kind);
            for &c in lexicon.concepts_of(kind) {
                let concept = lexicon.concept(c);
                let tier = if *whole {
                    Tier::Synonym
                } else {
                    Tier::Category
                };
                for s in std::iter::once(&concept.term).chain(&concept.synonyms) {
                    self.add(s, target, tier.max(Tier::Synonym), via);
                }
                for &h in &concept.hypernyms {
                    let hyper = lexicon.concept(h);
                    for s in std::iter::once(&hyper.term).chain(&hyper.synonyms) {
                        self.add(s, target, hypernym_tier(kind, s), via);
                    }
                }
            }
        }
    }

    /// A modelling tool's primitive (`pCube7`, `Sphere.002`, `pTorus1`: the names Maya
    /// and Blender give the shapes they make) answers to what the shape looks like: a
    /// cube is a box, a sphere a ball (when its box is `round`). Only a kind that is the
    /// primitive's word alone.
    fn add_shapes(&mut self, target: Target, kinds: &[(String, bool)], round: bool) {
        for (kind, _) in kinds {
            let last = kind.rsplit(' ').next().unwrap_or("");
            let primitive = kind == last || kind.split(' ').count() == 2 && kind.starts_with("p ");
            if !primitive {
                continue;
            }
            let via = self.via(kind);
            // A sphere squashed flat (a bean bag) is no ball.
            for &look in shape_words(last) {
                if round || !matches!(look, "ball" | "globe") {
                    self.add(look, target, Tier::Synonym, via);
                }
            }
        }
    }

    /// Words of the name the lexicon does not know: what people may call it by.
    fn add_name_words(&mut self, target: Target, id: &Identifier, lexicon: &Lexicon) {
        for kind in std::iter::once(&id.base).chain(id.other.as_ref()) {
            for w in kind.split(' ') {
                if own_word(lexicon, w) {
                    self.add(w, target, Tier::NameWord, Via::Name);
                }
            }
        }
    }
}

/// An object's labels, normalised: aliases, category (without an instance number) and
/// attributes.
struct Labels {
    aliases: Vec<String>,
    category: Option<String>,
    attributes: Vec<String>,
}

impl Labels {
    /// The labels of `object`.
    fn of(object: &crate::scene::Object) -> Self {
        Self {
            aliases: object.labels.aliases.iter().map(|a| normalize(a)).collect(),
            category: object.labels.category.as_ref().map(|c| {
                let c = normalize(c);
                split_number(&c).0.to_string()
            }),
            attributes: object
                .labels
                .attributes
                .iter()
                .map(|a| normalize(a))
                .collect(),
        }
    }
}

impl NameIndex {
    /// Indexes every object of the scene.
    pub fn new(scene: &Scene, lexicon: &Lexicon) -> Self {
        let mut b = Builder::default();
        b.index.max_words = 1;
        b.index.names.ends.reserve(scene.objects.len());
        b.index.group_of.reserve(scene.objects.len());
        for (i, object) in scene.objects.iter().enumerate() {
            let i = i as u32;
            let name = normalize(&object.name);
            let (written, _) = split_number(&name);
            let id = ident::read(&object.name, lexicon);
            b.index.max_words = b.index.max_words.max(name.split(' ').count());
            let g = b.group(object, written, &id, lexicon);
            b.index.groups[g as usize].objects.push(i);
            b.index.group_of.push(g);
            b.index.numbers.push(id.number);
            b.index.names.push(&name);
            if object.labels.aliases.is_empty()
                && object.labels.category.is_none()
                && super::profile::is_anonymous(&id)
            {
                b.index.anonymous.push(i as usize);
            }
            let one_word = object.name.chars().next().is_some_and(char::is_uppercase)
                && object.name.chars().all(char::is_alphabetic);
            if one_word {
                b.index
                    .capitalised
                    .entry(object.name.as_str().into())
                    .or_insert(i as usize);
            }
        }
        let mut index = b.index;
        let mut vocabulary: FxHashSet<&str> = FxHashSet::default();
        for o in 0..index.names.ends.len() as u32 {
            for w in index.names.get(o).split(' ') {
                if w.chars().all(char::is_alphabetic) {
                    vocabulary.insert(w);
                }
            }
        }
        for key in index.terms.keys() {
            for w in key.split(' ') {
                if w.chars().all(char::is_alphabetic) {
                    vocabulary.insert(w);
                }
            }
        }
        let mut by_length: Vec<Vec<Box<str>>> = Vec::new();
        for w in vocabulary {
            let n = w.chars().count();
            if by_length.len() <= n {
                by_length.resize(n + 1, Vec::new());
            }
            by_length[n].push(w.into());
        }
        for list in &mut by_length {
            list.sort();
        }
        index.vocabulary = by_length;
        index
    }

    fn objects_of(&self, target: Target) -> &[u32] {
        &self.groups[target.0 as usize].objects
    }

    fn via_text(&self, via: Via, object: u32) -> &str {
        match via {
            Via::Name => self.names.get(object),
            Via::Word(id) => &self.vias[id as usize],
        }
    }

    /// The objects a normalised phrase names, at the best tier present.
    pub fn lookup(&self, phrase: &str) -> Option<Hit<'_>> {
        let list = self.terms.get(phrase).map_or(&[][..], Vec::as_slice);
        // An object's own name is the best tier there is.
        let mut named: Vec<(u32, Via)> = self.names.named(phrase).map(|o| (o, Via::Name)).collect();
        let tier = if named.is_empty() {
            match list.iter().map(|p| p.tier).min()? {
                Tier::Compound => Tier::Category,
                t => t,
            }
        } else {
            Tier::Name
        };
        // (object, via) of every posting at that tier, then in scene order; an object
        // named twice keeps the way that came first (its own name first). Closed
        // compounds count with their category.
        let at = |t: Tier| t == tier || (tier == Tier::Category && t == Tier::Compound);
        for p in list.iter().filter(|p| at(p.tier)) {
            named.extend(self.objects_of(p.target).iter().map(|&o| (o, p.via)));
        }
        named.sort_by_key(|&(o, _)| o);
        named.dedup_by_key(|&mut (o, _)| o);
        let (first, via) = *named.first()?;
        Some(Hit {
            tier,
            via: self.via_text(via, first),
            objects: named.into_iter().map(|(o, _)| o as usize).collect(),
        })
    }

    /// Every object a normalised phrase names literally — by name, alias or category, the
    /// best tiers — when it names any that way: what modifiers pick among (`the smallest
    /// barrel` compares 'barrel', 'barrel 2' and 'small barrel').
    /// Closed compounds (`armchair` for "chair") count only when `compounds`: when the
    /// phrase names nothing better than a category.
    pub fn lookup_literal(&self, phrase: &str, compounds: bool) -> Vec<usize> {
        let best = if compounds {
            Tier::Compound
        } else {
            Tier::Category
        };
        let mut out: Vec<usize> = self
            .terms
            .get(phrase)
            .into_iter()
            .flatten()
            .filter(|p| p.tier <= best)
            .flat_map(|p| self.objects_of(p.target).iter().map(|&o| o as usize))
            .chain(self.names.named(phrase).map(|o| o as usize))
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    }

    /// The instance number of an object's name (`2` for `SM_Chair_02`).
    #[must_use]
    pub fn number(&self, object: usize) -> Option<u32> {
        self.numbers.get(object).copied().flatten()
    }

    /// The objects a name and an instance number name (`wood chair 1` for
    /// `Chair_Wood.001`, whose name reads as "wood chair"), when that is not a name itself;
    /// by any word that names them (`stool 2` for `Stool_Bar.002`, `desk 5` for `Student
    /// Desk 05` beside an unnumbered `Teacher Desk`): the number is what tells them apart.
    ///
    /// Number 1 is also the one unnumbered object beside its own numbered copies that
    /// start at 2 (`desk 1` for `Student Desk` beside `Student Desk 2` … and no
    /// `Student Desk 1`): that is how a tool numbers copies.
    pub fn numbered(&self, base: &str, number: u32) -> Option<Vec<usize>> {
        let hit = self.lookup(base)?;
        let out: Vec<usize> = hit
            .objects
            .iter()
            .copied()
            .filter(|&o| self.numbers[o] == Some(number))
            .collect();
        if !out.is_empty() || number != 1 {
            return (!out.is_empty()).then_some(out);
        }
        let copies: Vec<&str> = hit
            .objects
            .iter()
            .filter(|&&o| self.numbers[o] == Some(2))
            .map(|&o| split_number(self.names.get(o as u32)).0)
            .collect();
        let first: Vec<usize> = hit
            .objects
            .iter()
            .copied()
            .filter(|&o| self.numbers[o].is_none() && copies.contains(&self.names.get(o as u32)))
            .collect();
        (!first.is_empty()).then_some(first)
    }

    /// The objects whose name or base name is this phrase without spaces (`dogbed`).
    pub fn lookup_compact(&self, phrase: &str) -> Option<Vec<usize>> {
        let groups = self.compact.get(compact(phrase).as_str());
        let mut out: Vec<usize> = groups
            .into_iter()
            .flatten()
            .flat_map(|&g| self.objects_of(Target(g)).iter().map(|&o| o as usize))
            .chain(self.names.named_compact(phrase).map(|o| o as usize))
            .collect();
        if out.is_empty() {
            return None;
        }
        out.sort_unstable();
        out.dedup();
        Some(out)
    }

    /// Whether `word` (normalised) describes object `object`: a word of its name, category,
    /// aliases or attributes.
    pub fn describes(&self, object: usize, word: &str) -> bool {
        self.groups[self.group_of[object] as usize]
            .descriptors
            .contains(word)
    }

    /// Whether a word occurs in some term.
    pub fn knows_word(&self, word: &str) -> bool {
        self.vocabulary
            .get(word.chars().count())
            .is_some_and(|l| l.binary_search_by(|w| (**w).cmp(word)).is_ok())
    }

    /// The words of the index one edit (insertion, deletion, substitution or swap of two
    /// neighbours) away from `word`.
    pub fn one_edit_away(&self, word: &str) -> Vec<&str> {
        let n = word.chars().count();
        let mut out = Vec::new();
        for len in n.saturating_sub(1)..=n + 1 {
            for w in self.vocabulary.get(len).into_iter().flatten() {
                if strsim::osa_distance(word, w) == 1 {
                    out.push(&**w);
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::{means, scene};
    use super::*;

    /// The index of a built-in scene.
    fn index(name: &str) -> (Scene, NameIndex) {
        let s = scene(name);
        let index = NameIndex::new(&s, Lexicon::builtin());
        (s, index)
    }

    /// The names of the objects a phrase names, and at what tier.
    fn lookup(scene: &Scene, index: &NameIndex, phrase: &str) -> Option<(Tier, Vec<String>)> {
        let hit = index.lookup(phrase)?;
        let names = hit
            .objects
            .iter()
            .map(|&o| scene.objects[o].name.clone())
            .collect();
        Some((hit.tier, names))
    }

    #[test]
    fn a_group_is_named_by_its_name_kinds_and_lexicon() {
        let (s, index) = index("living_room");
        let name = |n: &str| vec![n.to_string()];
        assert_eq!(lookup(&s, &index, "sofa"), Some((Tier::Name, name("sofa"))));
        // The last words of a name are its kind.
        assert_eq!(
            lookup(&s, &index, "lamp"),
            Some((
                Tier::Category,
                vec!["floor lamp".into(), "table lamp".into()]
            ))
        );
        // A synonym, and a broader category.
        assert_eq!(
            lookup(&s, &index, "couch"),
            Some((Tier::Synonym, name("sofa")))
        );
        assert_eq!(
            lookup(&s, &index, "television"),
            Some((Tier::Synonym, name("tv")))
        );
        assert_eq!(lookup(&s, &index, "piano"), None);
        // Numbered alike: one group, two objects.
        assert_eq!(
            lookup(&s, &index, "speaker").map(|h| h.1),
            Some(vec!["speaker".into(), "speaker 2".into()])
        );
        assert_eq!(
            index.lookup_compact("coffeetable").map(|o| o.len()),
            Some(1)
        );
        let table = s.find("coffee table").unwrap();
        assert!(index.describes(table, "coffee") && !index.describes(table, "side"));
    }

    #[test]
    fn a_category_and_aliases_name_the_objects_of_a_scene_file() {
        let text = r#"{"objects": [
            {"name": "obj_17", "category": "armchair", "color": "red", "size": [1, 1, 1], "position": [-1, 0, 0]},
            {"name": "Big Bertha", "aliases": ["the beast", "speaker"], "size": [1, 1, 1], "position": [0, 0, 3]}
        ]}"#;
        let s = crate::format::json::read(text, "t").unwrap().scene;
        let index = NameIndex::new(&s, Lexicon::builtin());
        assert_eq!(
            lookup(&s, &index, "armchair"),
            Some((Tier::Category, vec!["obj_17".into()]))
        );
        assert_eq!(
            lookup(&s, &index, "speaker"),
            Some((Tier::Alias, vec!["Big Bertha".into()]))
        );
        assert!(index.attribute_words.contains("red"));
        assert!(index.describes(0, "red"));
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
}

//! The name index of a scene: every phrase a person may use for each object, built once
//! per scene, with how well it names the object.

use super::lexicon::Lexicon;
use super::words::{compact, normalize, split_number};
use crate::scene::Scene;
use std::collections::{HashMap, HashSet};

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
    /// A synonym of its name or category (`couch` for 'sofa').
    Synonym,
    /// A broader category (`seat` for 'armchair').
    Hypernym,
}

/// One way a phrase names an object.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Entry {
    /// The object.
    pub object: usize,
    /// How well.
    pub tier: Tier,
    /// For reports: the word of the object this came through (`sofa` for `couch`).
    pub via: String,
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
    /// Normalised phrase → the objects it names.
    terms: HashMap<String, Vec<Entry>>,
    /// A name or base name without spaces (`dogbed`) → objects.
    compact: HashMap<String, Vec<usize>>,
    /// Per object: its normalised name.
    pub names: Vec<String>,
    /// Per object: the words of its name, category, aliases and attributes, for picking by
    /// a word (`the red chair`, `the teacher's desk`).
    pub descriptors: Vec<HashSet<String>>,
    /// Every word that can describe some object.
    pub descriptor_words: HashSet<String>,
    /// The words of the objects' attributes (colours, materials): a phrase that uses one
    /// must be picking by it.
    pub attribute_words: HashSet<String>,
    /// Single words of all terms, by length in characters, for typo correction.
    vocabulary: Vec<Vec<String>>,
    /// The longest term, in words.
    pub max_words: usize,
}

impl NameIndex {
    /// Indexes every object of the scene.
    pub fn new(scene: &Scene, lexicon: &Lexicon) -> Self {
        let mut index = NameIndex {
            max_words: 1,
            ..NameIndex::default()
        };
        let mut vocabulary: HashSet<String> = HashSet::new();
        for (i, object) in scene.objects.iter().enumerate() {
            let name = normalize(&object.name);
            let (base, _) = split_number(&name);
            let base = base.to_string();
            index.add(&name, i, Tier::Name, &name);
            index.add(&base, i, Tier::Name, &name);
            for key in [compact(&name), compact(&base)] {
                let list = index.compact.entry(key).or_default();
                if !list.contains(&i) {
                    list.push(i);
                }
            }
            let mut descriptors: HashSet<String> = HashSet::new();
            let mut kinds: Vec<(String, bool)> = vec![(base.clone(), true)];
            for alias in &object.labels.aliases {
                let a = normalize(alias);
                index.add(&a, i, Tier::Alias, &a);
                kinds.push((split_number(&a).0.to_string(), true));
            }
            if let Some(category) = &object.labels.category {
                let c = normalize(category);
                let c = split_number(&c).0.to_string();
                index.add(&c, i, Tier::Category, &c);
                kinds.push((c, true));
            }
            // A container is named by what it holds: 'shampoo bottle' is "the shampoo",
            // 'soap dispenser' "the soap", 'red wine bottle' "the red wine".
            {
                let w: Vec<&str> = base.split(' ').collect();
                if w.len() >= 2 && CONTAINERS.contains(&w[w.len() - 1]) {
                    let content = w[..w.len() - 1].join(" ");
                    index.add(&content, i, Tier::Category, &base);
                }
            }
            // The last words of a name are its kind: 'floor lamp' is a lamp, 'red wine
            // bottle' a wine bottle and a bottle.
            for (kind, _) in kinds.clone() {
                let w: Vec<&str> = kind.split(' ').collect();
                for k in 1..w.len() {
                    let tail = w[k..].join(" ");
                    index.add(&tail, i, Tier::Category, &kind);
                    kinds.push((tail, false));
                }
                descriptors.extend(w.iter().map(|s| s.to_string()));
            }
            for attribute in &object.labels.attributes {
                for w in normalize(attribute).split(' ') {
                    descriptors.insert(w.to_string());
                    index.attribute_words.insert(w.to_string());
                }
            }
            // Lexicon: synonyms of what the object is called, and its hypernyms.
            for (kind, whole) in &kinds {
                for &c in lexicon.concepts_of(kind) {
                    let concept = lexicon.concept(c);
                    let tier = if *whole {
                        Tier::Synonym
                    } else {
                        Tier::Category
                    };
                    for s in std::iter::once(&concept.term).chain(&concept.synonyms) {
                        index.add(s, i, tier.max(Tier::Synonym), kind);
                    }
                    for &h in &concept.hypernyms {
                        let hyper = lexicon.concept(h);
                        for s in std::iter::once(&hyper.term).chain(&hyper.synonyms) {
                            index.add(s, i, Tier::Hypernym, kind);
                        }
                    }
                }
            }
            descriptors.retain(|d| d.chars().any(char::is_alphabetic));
            index.descriptor_words.extend(descriptors.iter().cloned());
            index.descriptors.push(descriptors);
            index.names.push(name);
        }
        for key in index.terms.keys() {
            for w in key.split(' ') {
                if w.chars().all(char::is_alphabetic) {
                    vocabulary.insert(w.to_string());
                }
            }
        }
        let mut by_length: Vec<Vec<String>> = Vec::new();
        for w in vocabulary {
            let n = w.chars().count();
            if by_length.len() <= n {
                by_length.resize(n + 1, Vec::new());
            }
            by_length[n].push(w);
        }
        for list in &mut by_length {
            list.sort();
        }
        index.vocabulary = by_length;
        index
    }

    fn add(&mut self, phrase: &str, object: usize, tier: Tier, via: &str) {
        if phrase.is_empty() {
            return;
        }
        self.max_words = self.max_words.max(phrase.split(' ').count());
        // Objects are indexed one after another, so an object's entry for a phrase, if
        // any, is the list's last: no scan of a list that may hold thousands.
        let list = match self.terms.get_mut(phrase) {
            Some(list) => list,
            None => self.terms.entry(phrase.to_string()).or_default(),
        };
        match list.last_mut().filter(|e| e.object == object) {
            Some(e) if e.tier <= tier => {}
            Some(e) => {
                e.tier = tier;
                e.via = via.to_string();
            }
            None => list.push(Entry {
                object,
                tier,
                via: via.to_string(),
            }),
        }
    }

    /// The objects a normalised phrase names, at the best tier present.
    pub fn lookup(&self, phrase: &str) -> Option<(Tier, Vec<&Entry>)> {
        let list = self.terms.get(phrase)?;
        let best = list.iter().map(|e| e.tier).min()?;
        Some((best, list.iter().filter(|e| e.tier == best).collect()))
    }

    /// Every object a normalised phrase names literally — by name, alias or category, the
    /// best tiers — when it names any that way: what modifiers pick among (`the smallest
    /// barrel` compares 'barrel', 'barrel 2' and 'small barrel').
    pub fn lookup_literal(&self, phrase: &str) -> Vec<usize> {
        self.terms
            .get(phrase)
            .into_iter()
            .flatten()
            .filter(|e| e.tier <= Tier::Category)
            .map(|e| e.object)
            .collect()
    }

    /// The objects whose name or base name is this phrase without spaces (`dogbed`).
    pub fn lookup_compact(&self, phrase: &str) -> Option<&[usize]> {
        self.compact.get(&compact(phrase)).map(Vec::as_slice)
    }

    /// Whether a word occurs in some term.
    pub fn knows_word(&self, word: &str) -> bool {
        self.vocabulary
            .get(word.chars().count())
            .is_some_and(|l| l.binary_search_by(|w| w.as_str().cmp(word)).is_ok())
    }

    /// The words of the index one edit (insertion, deletion, substitution or swap of two
    /// neighbours) away from `word`.
    pub fn one_edit_away(&self, word: &str) -> Vec<&str> {
        let n = word.chars().count();
        let mut out = Vec::new();
        for len in n.saturating_sub(1)..=n + 1 {
            for w in self.vocabulary.get(len).into_iter().flatten() {
                if strsim::osa_distance(word, w) == 1 {
                    out.push(w.as_str());
                }
            }
        }
        out
    }
}

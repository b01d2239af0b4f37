//! The lexicon of indoor-scene nouns: for each category its synonyms and its hypernyms
//! (the broader categories it belongs to), distilled from WordNet's noun synsets by
//! `tools/lexicon/build_lexicon.py` into `lexicon.txt` (committed; regenerate with that
//! script). See `docs/grounding.md`.

use super::words;
use std::collections::HashMap;
use std::sync::OnceLock;

/// One category of the lexicon.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Concept {
    /// Its seed term: `sofa`.
    pub term: String,
    /// Other words for it: `couch`, `settee`.
    pub synonyms: Vec<String>,
    /// The broader concepts it belongs to (indices), transitively closed: `seat`,
    /// `furniture`.
    pub hypernyms: Vec<usize>,
}

/// The lexicon: concepts, an index from every phrase to the concepts it names, and
/// irregular plurals.
#[derive(Clone, Debug, Default)]
pub struct Lexicon {
    concepts: Vec<Concept>,
    by_phrase: HashMap<String, Vec<usize>>,
    plurals: HashMap<String, String>,
}

/// Why a lexicon file cannot be read.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("lexicon line {line}: {message}")]
pub struct LexiconError {
    /// The line, from 1.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

impl Lexicon {
    /// The lexicon built into Shenlong, parsed once.
    #[must_use]
    pub fn builtin() -> &'static Lexicon {
        static LEXICON: OnceLock<Lexicon> = OnceLock::new();
        LEXICON.get_or_init(|| {
            Lexicon::parse(include_str!("lexicon.txt"))
                .expect("the built-in lexicon is valid (tested)")
        })
    }

    /// Parses the lexicon format: `term<TAB>syn|syn<TAB>hyper|hyper` per concept, and
    /// `~plural<TAB>singular` for irregular plurals; `#` starts a comment line.
    ///
    /// # Errors
    /// A line that is not of that form, or a hypernym that names no concept.
    pub fn parse(text: &str) -> Result<Self, LexiconError> {
        let mut lexicon = Lexicon::default();
        let mut raw_hypernyms: Vec<(usize, Vec<String>)> = Vec::new();
        let mut by_term: HashMap<String, usize> = HashMap::new();
        for (n, line) in text.lines().enumerate() {
            let line = line.trim_end_matches('\r');
            if line.trim().is_empty() || line.starts_with('#') {
                continue;
            }
            let err = |message: &str| LexiconError {
                line: n + 1,
                message: message.to_string(),
            };
            if let Some(rest) = line.strip_prefix('~') {
                let (plural, singular) = rest
                    .split_once('\t')
                    .ok_or_else(|| err("a plural line is ~plural<TAB>singular"))?;
                lexicon
                    .plurals
                    .insert(words::normalize(plural), words::normalize(singular));
                continue;
            }
            let mut fields = line.split('\t');
            let term = words::normalize(fields.next().unwrap_or_default());
            if term.is_empty() {
                return Err(err("empty term"));
            }
            let list = |f: Option<&str>| -> Vec<String> {
                f.unwrap_or_default()
                    .split('|')
                    .map(words::normalize)
                    .filter(|s| !s.is_empty())
                    .collect()
            };
            let synonyms = list(fields.next());
            let hypernyms = list(fields.next());
            if fields.next().is_some() {
                return Err(err("more than three fields"));
            }
            if by_term.contains_key(&term) {
                return Err(err(&format!("'{term}' is listed twice")));
            }
            let id = lexicon.concepts.len();
            by_term.insert(term.clone(), id);
            raw_hypernyms.push((id, hypernyms));
            lexicon.concepts.push(Concept {
                term,
                synonyms: synonyms.into_iter().filter(|s| !s.is_empty()).collect(),
                hypernyms: Vec::new(),
            });
        }
        for (id, names) in raw_hypernyms {
            let mut ids: Vec<usize> = Vec::new();
            for name in names {
                let h = *by_term.get(&name).ok_or_else(|| LexiconError {
                    line: 0,
                    message: format!(
                        "'{}' names the hypernym '{name}', which is no concept",
                        lexicon.concepts[id].term
                    ),
                })?;
                if h != id && !ids.contains(&h) {
                    ids.push(h);
                }
            }
            lexicon.concepts[id].hypernyms = ids;
        }
        // Close the hypernyms transitively, so "armchair" is a "seat" when it is a "chair".
        for id in 0..lexicon.concepts.len() {
            let mut closed = lexicon.concepts[id].hypernyms.clone();
            let mut k = 0;
            while k < closed.len() && closed.len() < 64 {
                let next = lexicon.concepts[closed[k]].hypernyms.clone();
                for h in next {
                    if h != id && !closed.contains(&h) {
                        closed.push(h);
                    }
                }
                k += 1;
            }
            lexicon.concepts[id].hypernyms = closed;
        }
        for (id, c) in lexicon.concepts.iter().enumerate() {
            for phrase in std::iter::once(&c.term).chain(&c.synonyms) {
                let ids = lexicon.by_phrase.entry(phrase.clone()).or_default();
                if !ids.contains(&id) {
                    ids.push(id);
                }
            }
        }
        Ok(lexicon)
    }

    /// The concepts a (normalised) phrase names: as a term or as a synonym.
    #[must_use]
    pub fn concepts_of(&self, phrase: &str) -> &[usize] {
        self.by_phrase.get(phrase).map_or(&[], Vec::as_slice)
    }

    /// A concept.
    #[must_use]
    pub fn concept(&self, id: usize) -> &Concept {
        &self.concepts[id]
    }

    /// Every concept.
    #[must_use]
    pub fn concepts(&self) -> &[Concept] {
        &self.concepts
    }

    /// Whether a (normalised) phrase is a noun of the lexicon.
    #[must_use]
    pub fn knows(&self, phrase: &str) -> bool {
        self.by_phrase.contains_key(phrase)
    }

    /// The singulars a plural phrase may stand for: irregular ones from the lexicon, then
    /// the regular ones, formed on the last word.
    #[must_use]
    pub fn singulars(&self, phrase: &str) -> Vec<String> {
        let mut out = Vec::new();
        if let Some(s) = self.plurals.get(phrase) {
            out.push(s.clone());
        }
        let (head, last) = match phrase.rsplit_once(' ') {
            Some((h, l)) => (Some(h), l),
            None => (None, phrase),
        };
        if let Some(s) = self.plurals.get(last) {
            out.push(match head {
                Some(h) => format!("{h} {s}"),
                None => s.clone(),
            });
        }
        for s in words::singular(last) {
            out.push(match head {
                Some(h) => format!("{h} {s}"),
                None => s,
            });
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_closes_hypernyms() {
        let l = Lexicon::parse(
            "# c\nfurniture\t\t\nseat\t\tfurniture\nchair\t\tseat\narmchair\tarm chair\tchair\n~knives\tknife\n",
        )
        .unwrap();
        let a = l.concepts_of("arm chair")[0];
        let names: Vec<&str> = l
            .concept(a)
            .hypernyms
            .iter()
            .map(|&h| l.concept(h).term.as_str())
            .collect();
        assert_eq!(names, ["chair", "seat", "furniture"]);
        assert_eq!(l.singulars("butter knives")[0], "butter knife");
        assert!(Lexicon::parse("a\tb\tnothing\n").is_err());
        assert!(Lexicon::parse("a\tb\tc\td\n").is_err());
    }

    #[test]
    fn the_builtin_lexicon_is_valid_and_knows_indoor_words() {
        let l = Lexicon::builtin();
        assert!(l.concepts().len() >= 200, "{}", l.concepts().len());
        let same = |a: &str, b: &str| {
            l.concepts_of(a)
                .iter()
                .any(|c| l.concepts_of(b).contains(c))
        };
        assert!(same("couch", "sofa"));
        assert!(same("tv", "television"));
        assert!(same("fridge", "refrigerator"));
        // British and American names of the same furniture.
        assert!(same("standard lamp", "floor lamp"));
        assert!(same("standing lamp", "floor lamp"));
        assert!(same("hutch", "china cabinet"));
        assert!(!same("sofa", "table"));
    }
}

//! The verbs that move an object to a place ("park", "tuck", "haul", "scoot"), distilled
//! from WordNet 3.0 by `tools/lexicon/build_verbs.py` into `verbs.txt`: troponyms of
//! "move, displace" and "put, set, place" with a caused-motion frame, less a documented
//! exclusion list, plus a few additions. The grounder reads a noun phrase after one as an
//! object; the offline translator reads one as a move.

use rustc_hash::{FxHashMap, FxHashSet};
use std::sync::OnceLock;

/// The generated list.
const TEXT: &str = include_str!("verbs.txt");

/// The verbs, and the irregular forms by the verb they are of.
#[derive(Debug, Default)]
struct Verbs {
    lemmas: FxHashSet<&'static str>,
    irregular: FxHashMap<&'static str, &'static str>,
}

fn verbs() -> &'static Verbs {
    static VERBS: OnceLock<Verbs> = OnceLock::new();
    VERBS.get_or_init(|| {
        let mut v = Verbs::default();
        for line in TEXT.lines() {
            if line.starts_with('#') || line.is_empty() {
                continue;
            }
            if let Some(rest) = line.strip_prefix('~') {
                if let Some((form, lemma)) = rest.split_once('\t') {
                    v.irregular.insert(form, lemma);
                }
            } else {
                v.lemmas.insert(line);
            }
        }
        v
    })
}

/// The verb a word is a form of (`parked` → `park`, `tucking` → `tuck`, `brought` →
/// `bring`), when it is one of the motion verbs.
#[must_use]
pub fn motion_verb(word: &str) -> Option<&'static str> {
    let v = verbs();
    if let Some(&lemma) = v.lemmas.get(word) {
        return Some(lemma);
    }
    if let Some(&lemma) = v.irregular.get(word) {
        return Some(lemma);
    }
    let mut stems: Vec<String> = Vec::new();
    for suffix in ["ing", "ed", "es", "s", "d"] {
        if let Some(stem) = word.strip_suffix(suffix).filter(|s| s.len() >= 2) {
            stems.push(stem.to_string());
            if suffix == "ing" || suffix == "ed" {
                stems.push(format!("{stem}e"));
            }
        }
    }
    stems.iter().find_map(|s| v.lemmas.get(s.as_str()).copied())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn motion_verbs_and_their_forms() {
        for (w, lemma) in [
            ("park", "park"),
            ("parked", "park"),
            ("tuck", "tuck"),
            ("tucking", "tuck"),
            ("haul", "haul"),
            ("hauls", "haul"),
            ("scoot", "scoot"),
            ("budge", "budge"),
            ("relocating", "relocate"),
            ("brought", "bring"),
            ("placed", "place"),
        ] {
            assert_eq!(motion_verb(w), Some(lemma), "{w}");
        }
    }

    #[test]
    fn verbs_of_other_meanings_are_not_motion_verbs() {
        for w in [
            "turn", "hit", "take", "get", "leave", "keep", "aim", "scatter", "replace",
        ] {
            assert_eq!(motion_verb(w), None, "{w}");
        }
    }
}

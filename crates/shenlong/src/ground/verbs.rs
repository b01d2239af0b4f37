//! The verbs that move an object to a place ("park", "tuck", "haul", "scoot"), distilled
//! from WordNet 3.0 by `tools/lexicon/build_verbs.py` into `verbs.txt`: troponyms of
//! "move, displace" and "put, set, place" with a caused-motion frame, less a documented
//! exclusion list, plus a few additions. The grounder reads a noun phrase after one as an
//! object; the offline translator reads one as a move. [`verb`] is the one table of the
//! verbs both read, with the action each names.

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

/// What a verb does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Action {
    /// Move, put, place, push, lift (with an implied direction for some).
    Move,
    /// Rotate, turn, spin.
    Rotate,
    /// Scale, resize, grow, shrink.
    Scale,
    /// Swap two objects' places.
    Swap,
    /// Align one with another, or line several up.
    Align,
    /// Take, pick up, grab: holds the objects for a later clause (`… and put it on X2`).
    Take,
    /// Centre (in the room).
    Centre,
    /// Straighten, square with the walls.
    Straighten,
}

/// A verb: its action and an implied direction (`lift` = up).
pub(crate) fn verb(w: &str) -> Option<(Action, Option<(usize, f64)>)> {
    use Action::*;
    Some(match w {
        "move" | "moved" | "moving" | "shift" | "shifted" | "push" | "pushed" | "slide"
        | "nudge" | "translate" | "put" | "place" | "placed" | "set" | "bring" | "position"
        | "reposition" | "relocate" | "carry" | "drag" | "pull" | "stack" | "pile" | "sit"
        | "stand" | "roll" | "shove" | "scoot" | "send" | "hang" | "mount" | "get" | "stick"
        | "leave" | "lay" | "shuffle" | "spread" | "separate"
        // "X1 goes on X2" ("go" alone opens "go ahead and …").
        | "goes"
        // Casual verbs of putting: "chuck the remote on the armchair".
        | "chuck" | "toss" | "plonk" | "plop" | "bung" | "stash" => (Move, None),
        "take" | "grab" | "pick" | "fetch" => (Take, None),
        "swap" | "exchange" | "switch" | "interchange" | "trade" => (Swap, None),
        "align" | "line" => (Align, None),
        "raise" | "raised" | "lift" | "lifted" | "elevate" | "hoist" => (Move, Some((1, 1.0))),
        "lower" | "lowered" | "drop" | "sink" => (Move, Some((1, -1.0))),
        "rotate" | "rotated" | "turn" | "turned" | "spin" | "twist" | "revolve" | "flip"
        | "swivel" | "pivot" | "angle" | "give" | "swing" | "swung" | "spun" => (Rotate, None),
        "scale" | "scaled" | "resize" | "resized" | "enlarge" | "grow" | "shrink" | "double"
        | "halve" | "triple" | "magnify" | "reduce" | "make" | "shrunk" => (Scale, None),
        "center" | "centre" => (Centre, None),
        "straighten" | "square" => (Straighten, None),
        // Every other verb that moves an object to a place (the WordNet-derived list).
        w if motion_verb(w).is_some() => (Move, None),
        _ => return None,
    })
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

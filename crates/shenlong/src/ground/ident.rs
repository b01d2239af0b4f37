//! Identifiers → words: how an object's name, as 3D tools export it, reads as the words
//! a person uses for it. One reader for every format (scene JSON, glTF node and mesh
//! names, ProcTHOR ids, Blender objects).
//!
//! - Parts are split at `_`, `-`, `.`, spaces and the like; inside a part camelCase and
//!   letter/digit boundaries split words (`SideTable` → `side table`).
//! - Engine prefixes (`SM_`, `SK_`, `BP_`, `GEO_`, `Mesh_`, `obj_`, `Prop_`) and mesh
//!   suffixes (`_geo`, `_mesh`, `_LOD0`) are dropped.
//! - A trailing number (`.001`, `_01`, ` 2`) is an instance number.
//! - A trailing `L` / `R` / `Left` / `Right` part (Blender's mirror convention) is a side,
//!   as is a trailing side word of a name written with spaces (`Side Table Left`).
//! - The head noun is found with the lexicon whichever side of an underscore it stands on:
//!   `Vase_Ceramic` is a ceramic vase (the head first, as Blender and game engines order
//!   `Category_Variant`), `TV_Stand` a TV stand (the words as written, a compound the
//!   lexicon knows), `Remote_TV` a TV remote. Where both orders are objects the lexicon
//!   knows (`Lamp_Table`: a lamp table, and a table lamp), the name answers to both
//!   equally, so "the lamp" beside another lamp is refused naming both.
//! - Words separated only by spaces are English as written (`table lamp`).

use super::lexicon::Lexicon;
use super::words::normalize;

/// Which side a name says an object is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum NameSide {
    /// `_L`, `_Left`.
    Left,
    /// `_R`, `_Right`.
    Right,
}

impl NameSide {
    /// The word people use: `left` or `right`.
    #[must_use]
    pub fn word(self) -> &'static str {
        match self {
            Self::Left => "left",
            Self::Right => "right",
        }
    }
}

/// An object's name read as words.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Identifier {
    /// What kind of object the name says, in English order, without prefix, instance
    /// number or side (`ceramic vase` for `Vase_Ceramic.003`).
    pub base: String,
    /// The other order's reading, where both orders name objects the lexicon knows
    /// (`table lamp` for `Lamp_Table`): the name answers to it as well as to `base`.
    pub other: Option<String>,
    /// The instance number (`3` for `.003`).
    pub number: Option<u32>,
    /// The side the name says (`SideTable_L`).
    pub side: Option<NameSide>,
}

/// Prefixes engines and DCC tools put before an object's kind.
const PREFIXES: &[&str] = &[
    "sm", "sk", "bp", "geo", "mesh", "obj", "object", "prop", "mdl", "model", "static",
];

/// Materials a name may give after its kind (`Vase_Ceramic`): they describe, never name.
const MATERIALS: &[&str] = &[
    "wood",
    "wooden",
    "oak",
    "pine",
    "walnut",
    "metal",
    "steel",
    "iron",
    "brass",
    "glass",
    "plastic",
    "ceramic",
    "stone",
    "marble",
    "leather",
    "fabric",
    "wicker",
    "rattan",
    "concrete",
    "teak",
    "bamboo",
    "velvet",
    "wool",
    "cotton",
    "chrome",
    "gold",
    "silver",
    "copper",
    "clay",
    "porcelain",
];

/// Suffixes that say what the node is, not what the object is.
const SUFFIXES: &[&str] = &[
    "geo", "mesh", "lod", "lod0", "lod1", "lod2", "low", "high", "grp",
];

/// The word of a part of one word.
fn single(part: &[String]) -> Option<&str> {
    match part {
        [w] => Some(w.as_str()),
        _ => None,
    }
}

fn is_number(word: &str) -> bool {
    !word.is_empty() && word.bytes().all(|b| b.is_ascii_digit())
}

fn side_of(word: &str) -> Option<NameSide> {
    match word {
        "l" | "left" | "lft" => Some(NameSide::Left),
        "r" | "right" | "rgt" => Some(NameSide::Right),
        _ => None,
    }
}

/// A code that tells alike objects apart: a single letter (`A` of `Parasol_A`), any but
/// the sides' `l` and `r`, or a letter and digits (`A1` of `Bench A1`).
fn code_letter(w: &str) -> bool {
    let mut chars = w.chars();
    let Some(first) = chars.next() else {
        return false;
    };
    let rest: Vec<char> = chars.collect();
    first.is_alphabetic()
        && (rest.is_empty() && first != 'l' && first != 'r'
            || !rest.is_empty() && rest.iter().all(char::is_ascii_digit))
}

/// The parts of a name, each as its normalised words.
fn parts(name: &str) -> Vec<Vec<String>> {
    name.split(['_', '-', '.', '#', '(', ')', ',', '/', ':', '|'])
        .filter(|p| !p.is_empty())
        .map(|p| {
            normalize(p)
                .split(' ')
                .filter(|w| !w.is_empty())
                .map(str::to_string)
                .collect::<Vec<_>>()
        })
        .filter(|p: &Vec<String>| !p.is_empty())
        .collect()
}

/// Whether the lexicon knows this phrase as an object (or the singular of one).
fn known(lexicon: &Lexicon, phrase: &str) -> bool {
    lexicon.knows(phrase) || lexicon.singulars(phrase).iter().any(|s| lexicon.knows(s))
}

/// Whether the last word of a phrase is an object noun the lexicon knows (a word for a
/// part of the room, as `wall` in `Clock_Wall`, is a place, not the object's kind).
fn headed(lexicon: &Lexicon, phrase: &str) -> bool {
    phrase
        .rsplit(' ')
        .next()
        .is_some_and(|last| known(lexicon, last) && !super::words::places_in_room(last))
}

/// The common simple name — one word of letters and an instance number (`box-5023`,
/// `Chair 7`, `lamp_01`, `stool`) — read without splitting it into parts: what [`read`]
/// gives for it, at the cost of one pass and one allocation (a scene of 100,000 such
/// objects is read for every edit). `None` for any other name.
fn simple(name: &str) -> Option<Identifier> {
    let (word, digits) = super::words::simple_name(name)?;
    if PREFIXES.contains(&word.as_str())
        || SUFFIXES.contains(&word.as_str())
        || side_of(&word).is_some()
    {
        return None;
    }
    Some(Identifier {
        base: word,
        other: None,
        number: (!digits.is_empty())
            .then(|| digits.parse::<u32>().ok())
            .flatten(),
        side: None,
    })
}

/// Reads an object's name.
#[must_use]
pub fn read(name: &str, lexicon: &Lexicon) -> Identifier {
    simple(name).unwrap_or_else(|| read_parts(name, lexicon))
}

/// [`read`] by the name's parts.
fn read_parts(name: &str, lexicon: &Lexicon) -> Identifier {
    let mut parts = parts(name);
    // A part of several words that ends in a number or a side (`chair 2`, `FloorLamp01`,
    // `Side Table Left`, `Speaker Left 2`): split them off, each its own part, in order.
    if let Some(at) = parts.len().checked_sub(1) {
        for _ in 0..2 {
            let part = &mut parts[at];
            // Only whole side words: a letter after a number is a unit (`Beaker 1L`). A
            // lone letter after a word is a code (`Bench A1`, `Table B`).
            let splits = part.len() > 1
                && part.last().is_some_and(|w| {
                    is_number(w) || matches!(w.as_str(), "left" | "right") || code_letter(w)
                })
                && !(part.len() > 1 && is_number(&part[part.len() - 2]));
            if !splits {
                break;
            }
            let w = part.pop().unwrap_or_default();
            // A code written after the kind with a space (`Bench A1`) says which bench;
            // one given its own part (`Notebook_A5`) may be a kind's word, as below.
            if !code_letter(&w) || w.chars().count() == 1 {
                parts.insert(at + 1, vec![w]);
            }
        }
    }
    if parts.len() > 1 && single(&parts[0]).is_some_and(|w| PREFIXES.contains(&w)) {
        parts.remove(0);
    }
    let mut number = None;
    let mut side = None;
    let mut coded = false;
    // Trailing number, side, code letter and mesh suffixes, in any order
    // (`SideTable_L.001`, `Bench A1`).
    while parts.len() > 1 {
        let Some(w) = single(&parts[parts.len() - 1]).map(str::to_string) else {
            break;
        };
        if is_number(&w) && number.is_none() {
            number = w.parse::<u32>().ok();
        } else if let Some(s) = side_of(&w).filter(|_| side.is_none()) {
            side = Some(s);
        } else if SUFFIXES.contains(&w.as_str()) {
        } else if code_letter(&w) && w.chars().count() == 1 && !coded {
            // `Parasol_A`, `Bench A1`: a code that tells alike objects apart, not a kind.
            coded = true;
        } else {
            break;
        }
        parts.pop();
    }
    let join = |ps: &[Vec<String>]| -> String {
        ps.iter()
            .flatten()
            .map(String::as_str)
            .collect::<Vec<_>>()
            .join(" ")
    };
    let written = join(&parts);
    if parts.len() < 2 {
        return Identifier {
            base: written,
            other: None,
            number,
            side,
        };
    }
    // The head first (`Vase_Ceramic`): the first part moved to the end.
    let mut rotated = parts[1..].to_vec();
    rotated.push(parts[0].clone());
    let head_first = join(&rotated);
    // `Knife_Block`, `Plate_Stack`, `Sink_Unit`: read head first ("block knife") where
    // only that order is a noun the lexicon knows, and as written too — what people call
    // it ("the knife block", "the sink unit") — unless its last word is a part of the
    // room (`Clock_Wall`) or describes (`Cushion_Red`, `Vase_Ceramic`).
    let as_written = |written: String| {
        let last = written.rsplit(' ').next().unwrap_or("");
        let describes = super::words::is_colour(last)
            || super::words::size_word(last).is_some()
            || MATERIALS.contains(&last);
        (!super::words::places_in_room(last) && !describes).then_some(written)
    };
    let (base, other) = match (known(lexicon, &written), known(lexicon, &head_first)) {
        (true, false) => (written, None),
        (false, true) => (head_first, None),
        (true, true) => (written, Some(head_first)),
        (false, false) => match (headed(lexicon, &written), headed(lexicon, &head_first)) {
            (true, false) | (false, false) => (written, None),
            (false, true) => (head_first, as_written(written)),
            (true, true) => (written, Some(head_first)),
        },
    };
    Identifier {
        base,
        other,
        number,
        side,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(name: &str) -> Identifier {
        read(name, Lexicon::builtin())
    }

    #[test]
    fn a_name_read_head_first_answers_as_written_too_unless_a_describing_word_ends_it() {
        let id = r("SM_Knife_Block");
        assert_eq!(id.other.as_deref(), Some("knife block"), "{id:?}");
        // A word that is also a measure ("unit", "area") is no part of the room.
        let id = r("SM_Sink_Unit");
        assert_eq!(id.other.as_deref(), Some("sink unit"), "{id:?}");
        for name in ["Cushion_Red", "Clock_Wall", "Vase_Ceramic"] {
            let id = r(name);
            assert!(
                id.other.as_deref().is_none_or(|o| !o.ends_with("red")
                    && !o.ends_with("wall")
                    && !o.ends_with("ceramic")),
                "{name}: {id:?}"
            );
        }
    }

    #[test]
    fn simple_names_read_as_the_full_reading_reads_them() {
        for name in [
            "box-5023",
            "Chair 7",
            "lamp_01",
            "stool",
            "Sofa",
            "mesh_3",
            "left_2",
            "gray-1",
            "node 4",
            "chair99999999999",
            "ab",
            "Box.001",
            "table-",
            "l_2",
            "sm_chair",
        ] {
            // The fast path's reading is the full one's.
            assert_eq!(r(name), read_parts(name, Lexicon::builtin()), "{name}");
        }
    }

    #[test]
    fn exported_names_read_as_their_kind() {
        assert_eq!(r("Chair_Wood").base, "wood chair");
        assert_eq!(r("Chair_Wood.001").number, Some(1));
        assert_eq!(r("Vase_Ceramic").base, "ceramic vase");
        assert_eq!(r("Remote_TV").base, "tv remote");
        assert_eq!(r("TV_Stand").base, "tv stand");
        assert_eq!(r("Frame_Picture").base, "picture frame");
        // A plant pot and a pot plant are both things: the name answers to both.
        assert_eq!(r("Plant_Pot").other.as_deref(), Some("pot plant"));
        assert_eq!(r("Table_Round").base, "round table");
        let floor = r("SM_FloorLamp_01");
        assert_eq!((floor.base.as_str(), floor.number), ("floor lamp", Some(1)));
        assert_eq!(r("CoffeeTable").base, "coffee table");
        // A room word is where the object is, not what it is.
        let clock = r("Clock_Wall");
        assert_eq!((clock.base.as_str(), clock.other), ("wall clock", None));
        // A door is an object of the scene, not a part of the room.
        assert_eq!(r("Door_Entrance").base, "entrance door");
        assert_eq!(r("Window_Shopfront").base, "shopfront window");
        assert_eq!(r("sofa").base, "sofa");
        assert_eq!(r("chair 3").number, Some(3));
        assert_eq!(r("chair 3").base, "chair");
        // A code (one letter, then digits) is one word, not a letter and an instance
        // number.
        let a5 = r("Notebook_A5");
        assert_eq!((a5.base.as_str(), a5.number), ("a5 notebook", None));
    }

    #[test]
    fn sides_and_suffixes() {
        let l = r("SideTable_L");
        assert_eq!(
            (l.base.as_str(), l.side),
            ("side table", Some(NameSide::Left))
        );
        let rr = r("SideTable_R.001");
        assert_eq!(
            (rr.base.as_str(), rr.side, rr.number),
            ("side table", Some(NameSide::Right), Some(1))
        );
        assert_eq!(r("Sofa_geo").base, "sofa");
        // A name that is only a side word keeps it.
        assert_eq!(r("Left").base, "left");
        // Written with spaces, a trailing side is a side too, before or after a number.
        for (name, number) in [("Side Table Left", None), ("Speaker Left 2", Some(2))] {
            let id = r(name);
            assert_eq!(
                (id.side, id.number),
                (Some(NameSide::Left), number),
                "{name}"
            );
        }
        assert_eq!(r("Side Table Left").base, "side table");
        assert_eq!(r("Speaker Left 2").base, "speaker");
        // A letter after a number is a unit, not a side.
        assert_eq!(r("Beaker 1L").side, None);
        // A lone letter is a code among alike objects, not their kind.
        for (name, number) in [
            ("Bench A1", None),
            ("SM_Parasol_A", None),
            ("Table B", None),
        ] {
            let id = r(name);
            assert_eq!((id.side, id.number), (None, number), "{name}");
            assert!(
                !id.base.ends_with(" a") && !id.base.ends_with(" b"),
                "{name}: {}",
                id.base
            );
        }
        assert_eq!(r("Bench A1").base, "bench");
        assert_eq!(r("Night Stand Right").side, Some(NameSide::Right));
    }

    #[test]
    fn both_orders_known_answer_to_both() {
        let lamp = r("Lamp_Table.003");
        assert_eq!(lamp.base, "lamp table");
        assert_eq!(lamp.other.as_deref(), Some("table lamp"));
        // Spaces: English as written.
        assert_eq!(r("table lamp").other, None);
        assert_eq!(r("table lamp").base, "table lamp");
        assert_eq!(lamp.number, Some(3));
    }
}

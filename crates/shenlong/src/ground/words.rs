//! Words of an instruction for grounding: tokens with their byte spans, and the closed
//! word classes a noun phrase is built from (determiners, counts, ordinals, spatial and
//! size modifiers, relation words).

pub(crate) use crate::lex::{tokenize, Kind, Token};

/// Feet and inches written with marks (`2'6"`, `6"`, `3′`, `18″`) as words (`2 ft 6 in`,
/// `6 in`, `3 ft`, `18 in`), so that one reading of lengths serves them. A mark after a
/// number is a unit unless it closes a quoted name (`'Chair 2'`): a `'` or `"` with an
/// odd number of the same quote opened before it is a closing quote.
#[must_use]
pub fn imperial_marks(text: &str) -> std::borrow::Cow<'_, str> {
    if !text.contains(['\'', '"', '′', '″']) {
        return std::borrow::Cow::Borrowed(text);
    }
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len() + 8);
    // Quotes opened so far, by character (a mark that was a unit is not counted).
    let (mut singles, mut doubles) = (0usize, 0usize);
    for (k, &c) in chars.iter().enumerate() {
        // A number standing alone ends here: digits (and a point) after a space, a
        // bracket or the start, not the end of a name (`SM_Chair_02'`).
        let run = chars[..k]
            .iter()
            .rev()
            .take_while(|d| d.is_ascii_digit() || **d == '.')
            .count();
        // `chair 2's back` is a possessive, not feet.
        let letter_follows = chars.get(k + 1).is_some_and(|d| d.is_alphabetic());
        let after_number = run > 0
            && !letter_follows
            && chars[k - 1].is_ascii_digit()
            && chars[k - run].is_ascii_digit()
            && (k == run || !(chars[k - run - 1].is_alphanumeric() || chars[k - run - 1] == '_'));
        let unit = match c {
            '\'' if after_number && singles % 2 == 0 => Some("ft"),
            '"' if after_number && doubles % 2 == 0 => Some("in"),
            '′' if after_number => Some("ft"),
            '″' if after_number => Some("in"),
            _ => None,
        };
        if let Some(unit) = unit {
            out.push(' ');
            out.push_str(unit);
            if chars.get(k + 1).is_some_and(char::is_ascii_digit) {
                out.push(' ');
            }
            continue;
        }
        let in_word = k > 0 && chars[k - 1].is_alphanumeric();
        match c {
            '\'' if !in_word || singles % 2 == 1 => singles += 1,
            '"' => doubles += 1,
            _ => {}
        }
        out.push(c);
    }
    std::borrow::Cow::Owned(out)
}

/// "the back row of desks", "the second column of chairs" said as "the desks in the back
/// row", "the chairs in the second column": the objects first, so that the line is read
/// as the modifier after them. One word after `of` (and its `the`) is the objects'.
#[must_use]
pub fn line_of_objects(text: &str) -> std::borrow::Cow<'_, str> {
    let tokens = tokenize(text);
    let w = |k: usize| tokens.get(k).and_then(Token::word).unwrap_or("");
    for k in 0..tokens.len() {
        let which = w(k + 1);
        let line = matches!(w(k + 2), "row" | "column" | "line");
        let which_ok = side_word(which).is_some()
            || ordinal(which).is_some()
            || matches!(which, "middle" | "centre" | "center");
        if w(k) != "the" || !line || !which_ok || w(k + 3) != "of" {
            continue;
        }
        let noun = if w(k + 4) == "the" { k + 5 } else { k + 4 };
        let Some(objects) = tokens.get(noun).and_then(Token::word) else {
            continue;
        };
        if !objects.ends_with('s') {
            continue;
        }
        let start = tokens[k].span.start;
        let end = tokens[noun].span.end;
        let rewritten = format!(
            "the {} in the {which} {}",
            &text[tokens[noun].span.clone()],
            w(k + 2)
        );
        return std::borrow::Cow::Owned(format!("{}{rewritten}{}", &text[..start], &text[end..]));
    }
    std::borrow::Cow::Borrowed(text)
}

/// Normalises a name or phrase for comparison: lower case, `-` `_` `.` as spaces, runs of
/// spaces folded, camelCase split (`SheenChair` → `sheen chair`), a trailing `.001`-style
/// suffix kept as a number (`chair.001` → `chair 1`).
pub fn normalize(name: &str) -> String {
    normalize_simple(name).unwrap_or_else(|| normalize_full(name))
}

/// [`normalize`], character by character.
fn normalize_full(name: &str) -> String {
    let mut spaced = String::with_capacity(name.len() + 4);
    let mut prev: Option<char> = None;
    // Letters since the word began: a single letter before digits is a code (`A5`).
    let mut letters = 0usize;
    for c in name.trim().chars() {
        let split_camel = prev.is_some_and(|p| p.is_lowercase()) && c.is_uppercase();
        let split_digit =
            prev.is_some_and(|p| p.is_alphabetic()) && c.is_ascii_digit() && letters != 1
                || prev.is_some_and(|p| p.is_ascii_digit()) && c.is_alphabetic();
        if c.is_alphabetic() {
            letters = if split_camel || prev.is_some_and(|p| !p.is_alphabetic()) {
                1
            } else {
                letters + 1
            };
        } else if !c.is_ascii_digit() {
            letters = 0;
        }
        if split_camel || split_digit {
            spaced.push(' ');
        }
        if matches!(c, '-' | '_' | '.' | '#' | '(' | ')' | ',' | '/') || c.is_whitespace() {
            spaced.push(' ');
        } else if c.is_ascii() {
            spaced.push(c.to_ascii_lowercase());
        } else {
            spaced.extend(c.to_lowercase());
        }
        prev = Some(c);
    }
    // Words joined by single spaces, without allocating each one.
    let mut out = String::with_capacity(spaced.len());
    for w in spaced.split_whitespace() {
        // `001` → `1`: numbered copies in glTF files.
        let w = if w.len() > 1 && w.bytes().all(|c| c.is_ascii_digit()) {
            match w.trim_start_matches('0') {
                "" => "0",
                digits => digits,
            }
        } else {
            w
        };
        if w == "node" {
            continue;
        }
        let w = spelling(w);
        if w.is_empty() {
            continue;
        }
        if !out.is_empty() {
            out.push(' ');
        }
        out.push_str(w);
    }
    out
}

/// The common simple name — one word of two letters or more (its first letter may be a
/// capital) and an instance number after at most one separator (`box-5023`, `Chair 7`,
/// `lamp_01`, `stool`) — as its word in lower case and the number's digits, in one pass;
/// `None` for any other name, and for a word [`normalize`] would change (`node`, `gray`).
/// Read this way by [`normalize`] and the identifier reader alike (a scene of 100,000 such
/// objects is read for every edit).
pub(crate) fn simple_name(name: &str) -> Option<(String, &str)> {
    let bytes = name.as_bytes();
    let letters = bytes.iter().take_while(|b| b.is_ascii_alphabetic()).count();
    if letters < 2 || bytes[1..letters].iter().any(u8::is_ascii_uppercase) {
        return None;
    }
    let rest = &name[letters..];
    let digits = match rest.as_bytes().first() {
        Some(b'-' | b'_' | b' ' | b'.') => &rest[1..],
        _ => rest,
    };
    if !digits.bytes().all(|b| b.is_ascii_digit()) || (digits.is_empty() && !rest.is_empty()) {
        return None;
    }
    let word = name[..letters].to_ascii_lowercase();
    if word == "node" || spelling(&word) != word {
        return None;
    }
    Some((word, digits))
}

/// [`normalize`] of a [`simple_name`]: the word, then the number without leading zeros.
fn normalize_simple(name: &str) -> Option<String> {
    let (mut out, digits) = simple_name(name)?;
    if !digits.is_empty() {
        out.push(' ');
        let trimmed = digits.trim_start_matches('0');
        out.push_str(if trimmed.is_empty() { "0" } else { trimmed });
    }
    Some(out)
}

/// One spelling for words people spell two ways, and the noun for a material adjective,
/// so that names and instructions compare equal whichever was typed: `gray` → `grey`,
/// `colors` → `colours`, `wooden` → `wood`, `woollen` → `wool`, `metallic` → `metal`;
/// `coloured` / `colored` / `colour` / `color` say nothing (`grey-coloured` is `grey`)
/// and are dropped (the empty string).
#[must_use]
pub fn spelling(word: &str) -> &str {
    match word {
        "gray" => "grey",
        "grayish" | "greyish" => "grey",
        "colors" => "colours",
        "wooden" => "wood",
        "woolen" | "woollen" | "wooly" | "woolly" => "wool",
        "metallic" | "metal's" => "metal",
        "leathery" => "leather",
        "glassy" => "glass",
        "marble's" => "marble",
        "aluminum" => "aluminium",
        "favorite" => "favourite",
        // American and British spellings of things in rooms.
        "tire" => "tyre",
        "tires" => "tyres",
        "catalog" => "catalogue",
        "catalogs" => "catalogues",
        "theater" => "theatre",
        "jewelry" => "jewellery",
        "fiber" => "fibre",
        "armor" => "armour",
        "pajamas" => "pyjamas",
        "mold" => "mould",
        "cozy" => "cosy",
        "liter" => "litre",
        "liters" => "litres",
        // "the grey-coloured chair" is the grey chair.
        "coloured" | "colored" | "colour" | "color" => "",
        other => other,
    }
}

/// A name without its spaces: `dog bed` and `dogbed` compare equal.
pub fn compact(normalized: &str) -> String {
    normalized.chars().filter(|c| !c.is_whitespace()).collect()
}

/// Splits a trailing number off a normalised name: `chair 7` → (`chair`, 7).
pub fn split_number(normalized: &str) -> (&str, Option<u32>) {
    match normalized.rsplit_once(' ') {
        Some((base, n)) if !base.is_empty() => match n.parse::<u32>() {
            Ok(n) => (base, Some(n)),
            Err(_) => (normalized, None),
        },
        _ => (normalized, None),
    }
}

/// The singular of a regular English plural (`chairs`, `boxes`, `shelves`, `batteries`),
/// or `None` when the word does not look plural. Irregular plurals come from the lexicon.
pub fn singular(word: &str) -> Vec<String> {
    let mut out = Vec::new();
    if word.len() < 3 || !word.ends_with('s') || word.ends_with("ss") || word.ends_with("us") {
        return out;
    }
    if let Some(stem) = word.strip_suffix("ies") {
        out.push(format!("{stem}y"));
    }
    if let Some(stem) = word.strip_suffix("ves") {
        out.push(format!("{stem}f"));
        out.push(format!("{stem}fe"));
    }
    if let Some(stem) = word.strip_suffix("es") {
        if stem.ends_with("sh")
            || stem.ends_with("ch")
            || stem.ends_with('x')
            || stem.ends_with('s')
            || stem.ends_with('z')
            || stem.ends_with('o')
        {
            out.push(stem.to_string());
        }
    }
    out.push(word[..word.len() - 1].to_string());
    out
}

/// Verbs that turn, scale or straighten an object where it is, and so take no place (as
/// the one verb table, [`super::verbs::verb`], files them), and `face`.
pub(crate) fn turns_or_scales(w: &str) -> bool {
    w == "face"
        || matches!(
            super::verbs::verb(w),
            Some((
                super::verbs::Action::Rotate
                    | super::verbs::Action::Scale
                    | super::verbs::Action::Straighten,
                _
            ))
        )
}

/// Determiners and quantifiers that open a noun phrase.
pub(crate) fn is_determiner(w: &str) -> bool {
    matches!(
        w,
        "the"
            | "a"
            | "an"
            | "this"
            | "that"
            | "these"
            | "those"
            | "my"
            | "our"
            | "your"
            | "his"
            | "her"
            | "their"
            | "both"
            | "all"
            | "every"
            | "each"
            // "whichever bench is closest to the desk": the one the modifier picks.
            | "whichever"
            | "any"
    )
}

/// How many objects a phrase asks for, from its determiner or count word.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Count {
    /// One object (a singular noun).
    One,
    /// Exactly this many (`both` = 2, `the three chairs`).
    Exactly(usize),
    /// All that fit (`all`, `every`, `each`, a plural noun).
    All,
}

impl Count {
    /// How many objects a phrase with this count asks for, of `have` that fit.
    #[must_use]
    pub(crate) fn wanted(self, have: usize) -> usize {
        match self {
            Count::One => 1,
            Count::Exactly(n) => n,
            Count::All => have,
        }
    }
}

/// `two` → 2 … `ten` → 10 (counts of a group).
pub(crate) fn count_word(w: &str) -> Option<usize> {
    Some(match w {
        "two" | "pair" => 2,
        "three" => 3,
        "four" => 4,
        "five" => 5,
        "six" => 6,
        "seven" => 7,
        "eight" => 8,
        "nine" => 9,
        "ten" => 10,
        _ => return None,
    })
}

/// `first` → 1, `3rd` → 3, `last` → `usize::MAX`.
pub(crate) fn ordinal(w: &str) -> Option<usize> {
    Some(match w {
        "first" | "1st" => 1,
        "second" | "2nd" => 2,
        "third" | "3rd" => 3,
        "fourth" | "4th" => 4,
        "fifth" | "5th" => 5,
        "sixth" | "6th" => 6,
        "seventh" | "7th" => 7,
        "eighth" | "8th" => 8,
        "ninth" | "9th" => 9,
        "tenth" | "10th" => 10,
        "last" | "final" => usize::MAX,
        _ => return None,
    })
}

/// An axis of the world frame (SPEC §1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Axis {
    /// x: left (−) to right (+).
    X,
    /// y: down (−) to up (+).
    Y,
    /// z: back (−) to front (+).
    Z,
}

impl Axis {
    /// The coordinate along this axis.
    pub fn of(self, v: glam::DVec3) -> f64 {
        match self {
            Axis::X => v.x,
            Axis::Y => v.y,
            Axis::Z => v.z,
        }
    }
}

/// A place word: the end of an axis (`left` = x−, `front` = z+, `top` = y+).
pub(crate) fn side_word(w: &str) -> Option<(Axis, f64)> {
    Some(match w {
        "left" | "leftmost" | "left-most" | "left-hand" | "lefthand" => (Axis::X, -1.0),
        "right" | "rightmost" | "right-most" | "right-hand" | "righthand" => (Axis::X, 1.0),
        "front" | "frontmost" | "front-most" | "nearest" | "near" => (Axis::Z, 1.0),
        "back" | "rear" | "backmost" | "back-most" | "rearmost" | "far" | "farthest"
        | "furthest" => (Axis::Z, -1.0),
        "top" | "topmost" | "top-most" | "upper" | "uppermost" | "higher" | "highest" => {
            (Axis::Y, 1.0)
        }
        "bottom" | "bottommost" | "bottom-most" | "lowest" | "lowermost" => (Axis::Y, -1.0),
        _ => return None,
    })
}

/// The sides a word names: one (`left`), or several for a compound (`back-left`,
/// `front-right`).
pub(crate) fn side_parts(w: &str) -> Option<Vec<(Axis, f64)>> {
    if let Some(one) = side_word(w) {
        return Some(vec![one]);
    }
    let parts: Option<Vec<(Axis, f64)>> = w.split('-').map(side_word).collect();
    parts.filter(|p| p.len() > 1)
}

/// What a size word measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Measure {
    /// The box's volume.
    Volume,
    /// The box's height.
    Height,
    /// The box's largest horizontal extent.
    Length,
}

/// Whether a size word compares two (`bigger`), picks one of all (`biggest`) or is plain
/// (`big`, read as comparing two).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Degree {
    /// `big`, `small`.
    Plain,
    /// `bigger`, `smaller`.
    Comparative,
    /// `biggest`, `smallest`.
    Superlative,
}

/// A size word: what it measures, the sign (+1 = more), its degree.
pub(crate) fn size_word(w: &str) -> Option<(Measure, f64, Degree)> {
    use Degree::*;
    use Measure::*;
    Some(match w {
        "big" | "large" | "huge" => (Volume, 1.0, Plain),
        "bigger" | "larger" => (Volume, 1.0, Comparative),
        "biggest" | "largest" => (Volume, 1.0, Superlative),
        "small" | "little" | "tiny" => (Volume, -1.0, Plain),
        "smaller" => (Volume, -1.0, Comparative),
        "smallest" => (Volume, -1.0, Superlative),
        "tall" => (Height, 1.0, Plain),
        "taller" => (Height, 1.0, Comparative),
        "tallest" => (Height, 1.0, Superlative),
        "short" | "low" => (Height, -1.0, Plain),
        "shorter" => (Height, -1.0, Comparative),
        "shortest" => (Height, -1.0, Superlative),
        "long" | "wide" => (Length, 1.0, Plain),
        "longer" | "wider" => (Length, 1.0, Comparative),
        "longest" | "widest" => (Length, 1.0, Superlative),
        "narrow" => (Length, -1.0, Plain),
        "narrower" => (Length, -1.0, Comparative),
        "narrowest" => (Length, -1.0, Superlative),
        _ => return None,
    })
}

/// Words that say how much, never an object's name or its typo ("a slight turn" is no
/// "light").
pub(crate) fn is_degree_word(w: &str) -> bool {
    matches!(
        w,
        "slight"
            | "slightly"
            | "gentle"
            | "gently"
            | "tiny"
            | "wee"
            | "touch"
            | "tad"
            | "smidge"
            | "nudge"
            | "bit"
            | "little"
    )
}

/// What a shape word says of an object's box, whatever the object is called.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Shape {
    /// `flat`: much lower than it is wide and deep (a mat, a plate, a board lying down).
    Flat,
    /// `skinny`, `slender`: much taller than it is wide (a pole, a column, a floor lamp).
    Slender,
    /// `thin`: slender, or much thinner one way than the others (a panel, a board).
    Thin,
}

/// The shape word `w` (`flat`, `skinny`, `thin` …), read from an object's box.
pub(crate) fn shape_word(w: &str) -> Option<Shape> {
    Some(match w {
        "flat" | "flattish" => Shape::Flat,
        "skinny" | "slender" | "slim" | "spindly" | "lanky" => Shape::Slender,
        "thin" => Shape::Thin,
        _ => return None,
    })
}

/// Words that may stand before a noun phrase's head and open it: a determiner, a verb of
/// the instruction, a preposition or a conjunction. A candidate head after anything else
/// (`turn the vase counter clockwise`, `can you …`) is not read as an object.
pub(crate) fn opens_phrase(w: &str) -> bool {
    is_determiner(w)
        || is_verb(w)
        || is_preposition(w)
        || matches!(
            w,
            "and"
                | "or"
                | "then"
                | "please"
                | "also"
                | "now"
                | "too"
                | "plus"
                | "with"
                | "not"
                | "but"
                | "have"
                | "except"
                | "leave"
                | "keep"
                | "touch"
                | "moving"
                | "touching"
                | "disturb"
                | "disturbing"
                // A question or a wish about an object: "could stool 3 go …", "I want
                // desk 5 …", "I'd like table 2 …".
                | "can"
                | "could"
                | "would"
                | "will"
                | "should"
                | "must"
                | "might"
                | "may"
                | "want"
                | "wants"
                | "like"
                | "need"
                | "needs"
        )
}

/// Prepositions after which a noun phrase may follow.
pub(crate) fn is_preposition(w: &str) -> bool {
    matches!(
        w,
        "on" | "onto"
            | "upon"
            | "atop"
            | "of"
            | "to"
            | "into"
            | "in"
            | "at"
            | "by"
            | "near"
            | "beside"
            | "besides"
            | "next"
            | "from"
            | "off"
            | "under"
            | "below"
            | "beneath"
            | "underneath"
            | "above"
            | "over"
            | "behind"
            | "between"
            | "toward"
            | "towards"
            | "against"
            | "alongside"
            | "around"
            | "facing"
            | "past"
            | "than"
            | "as"
            | "like"
            | "nearest"
            | "closest"
            | "nearer"
            | "closer"
            | "farther"
            | "further"
            | "farthest"
            | "furthest"
            | "among"
            | "across"
            | "beyond"
            | "within"
            | "inside"
            | "outside"
            | "about"
            | "for"
            | "up"
    )
}

/// Verbs of instructions (used to tell a phrase's start, not to translate).
pub(crate) fn is_verb(w: &str) -> bool {
    // The verbs of the one verb lexicon, and the words that act as one before an object
    // in a request ("face the chair to…", "I want the desk…", "let's move…").
    super::verbs::verb(w).is_some()
        || matches!(
            w,
            "arrange"
                | "do"
                | "face"
                | "keep"
                | "let's"
                | "lets"
                | "like"
                | "mirror"
                | "moev"
                | "need"
                | "point"
                | "see"
                | "want"
        )
}

/// Words for a part of the room itself (its floor, walls, corners, sides), which no
/// object's name is headed by: `Clock_Wall` is a wall clock. Doors and windows are places
/// too ([`is_place_noun`]) but also objects of a scene (`Door_Entrance`).
pub(crate) fn is_room_part(w: &str) -> bool {
    is_place_noun(w) && !matches!(w, "window" | "windows" | "door" | "doors" | "doorway")
}

/// Words for where in the room something is (`Clock_Wall`, `Lamp_Ceiling`, `Shelf_Corner`):
/// at the end of an exported name they place the object, never name its kind. Unlike
/// [`is_room_part`], no word for an amount or a spot (`unit`, `area`, `bit`).
pub(crate) fn places_in_room(w: &str) -> bool {
    matches!(
        w,
        "floor"
            | "ground"
            | "wall"
            | "walls"
            | "ceiling"
            | "corner"
            | "corners"
            | "middle"
            | "centre"
            | "center"
            | "side"
            | "sides"
            | "edge"
            | "room"
            | "front"
            | "back"
            | "top"
            | "bottom"
            | "left"
            | "right"
            | "end"
    )
}

/// Nouns for places and amounts rather than objects: never an unknown object. The places
/// in the room ([`places_in_room`]), doors and windows, and words for a spot or an amount.
pub(crate) fn is_place_noun(w: &str) -> bool {
    places_in_room(w)
        || matches!(
            w,
            "window"
                | "windows"
                | "door"
                | "doors"
                | "doorway"
                | "way"
                | "spot"
                | "place"
                | "position"
                | "positions"
                | "places"
                | "area"
                | "space"
                | "angle"
                | "direction"
                | "axis"
                | "row"
                | "line"
                | "half"
                | "quarter"
                | "third"
                | "bit"
                | "amount"
                | "size"
                | "height"
                | "width"
                | "length"
                | "distance"
                | "degree"
                | "degrees"
                | "turn"
                | "metre"
                | "meter"
                | "metres"
                | "meters"
                | "foot"
                | "feet"
                | "inch"
                | "inches"
                | "unit"
                | "units"
                | "order"
                | "same"
                | "other"
                | "one"
                | "ones"
                | "lot"
                | "touch"
                | "couple"
                | "few"
                | "time"
                | "times"
                | "percent"
                | "scene"
                | "house"
                | "kitchen"
                | "bedroom"
                | "bathroom"
                | "office"
        )
}

/// Whether `b` is `a` with two neighbouring letters swapped ("moev" for move, "bleu" for
/// blue): the one typo both readers accept on four-letter words.
#[must_use]
pub(crate) fn neighbours_swapped(a: &str, b: &str) -> bool {
    strsim::osa_distance(a, b) == 1 && strsim::hamming(a, b) == Ok(2)
}

/// Colour words, which must pick something when a phrase uses them.
pub(crate) fn is_colour(w: &str) -> bool {
    matches!(
        w,
        "red"
            | "orange"
            | "yellow"
            | "green"
            | "blue"
            | "purple"
            | "violet"
            | "pink"
            | "brown"
            | "black"
            | "white"
            | "grey"
            | "gray"
            | "silver"
            | "gold"
            | "golden"
            | "beige"
            | "cream"
            | "teal"
            | "navy"
    )
}

/// Words between a head and its relation that add nothing: `the lamp that is next to …`.
pub(crate) fn is_relative_filler(w: &str) -> bool {
    matches!(
        w,
        "that"
            | "which"
            | "who"
            | "is"
            | "that's"
            | "thats"
            | "which's"
            | "sitting"
            | "standing"
            | "lying"
            | "resting"
            | "placed"
            | "located"
            | "hanging"
            | "sits"
            | "stands"
            | "currently"
            | "right"
            | "just"
            | "directly"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn feet_and_inches_marks_are_units_but_quotes_stay_quotes() {
        for (typed, read) in [
            ("move it 2'6\" left", "move it 2 ft 6 in left"),
            ("bin: 6\" forward", "bin: 6 in forward"),
            ("push it 3′ back", "push it 3 ft back"),
            ("raise it 1.5\"", "raise it 1.5 in"),
            ("move 'Chair 2' 1' left", "move 'Chair 2' 1 ft left"),
            ("move \"Desk 5\" 6\" right", "move \"Desk 5\" 6 in right"),
            ("move the sofa's cushion 2 m", "move the sofa's cushion 2 m"),
            ("move SM_Chair_02' left", "move SM_Chair_02' left"),
            (
                "turn chair 2's back to the board",
                "turn chair 2's back to the board",
            ),
        ] {
            assert_eq!(imperial_marks(typed), read, "{typed}");
        }
    }

    #[test]
    fn names_and_words_spelt_either_side_of_the_atlantic_compare_equal() {
        for (a, b) in [
            ("Tire_Rack", "tyre rack"),
            ("card catalog", "Card_Catalogue"),
            ("gray chair", "Chair_Grey"),
            ("jewelry box", "JewelleryBox"),
        ] {
            let (x, y) = (normalize(a), normalize(b));
            let mut x: Vec<&str> = x.split(' ').collect();
            let mut y: Vec<&str> = y.split(' ').collect();
            x.sort_unstable();
            y.sort_unstable();
            assert_eq!(x, y, "{a} / {b}");
        }
    }

    #[test]
    fn a_line_of_objects_is_said_objects_first() {
        assert_eq!(
            line_of_objects("move the back row of desks 20 cm back"),
            "move the desks in the back row 20 cm back"
        );
        assert_eq!(
            line_of_objects("shift the second column of the chairs left"),
            "shift the chairs in the second column left"
        );
        assert_eq!(line_of_objects("move the desk left"), "move the desk left");
        assert_eq!(
            line_of_objects("the row of the desk"),
            "the row of the desk"
        );
    }

    #[test]
    fn tokens_keep_their_spans() {
        let text = "Put the ‘Dog-Bed’ by chair #7, please.";
        let t = tokenize(text);
        let words: Vec<String> = t
            .iter()
            .map(|t| match &t.kind {
                Kind::Word(w) => w.clone(),
                Kind::Number(n) => format!("{n}"),
                Kind::Quoted(q) => format!("'{q}'"),
                Kind::Punct(c) => c.to_string(),
            })
            .collect();
        assert_eq!(
            words,
            [
                "put",
                "the",
                "'Dog-Bed'",
                "by",
                "chair",
                "#",
                "7",
                ",",
                "please",
                "."
            ]
        );
        assert_eq!(&text[t[2].span.clone()], "‘Dog-Bed’");
        assert_eq!(&text[t[8].span.clone()], "please");
        assert_eq!(tokenize("the sofa's arm")[1].word(), Some("sofa's"));
        assert_eq!(tokenize("1.5m")[0].word(), Some("1.5m"));
    }

    #[test]
    fn names_normalise() {
        assert_eq!(normalize("Dog-Bed"), "dog bed");
        // The one-pass reading of simple names is the full one's.
        for name in [
            "box-5023",
            "lamp_01",
            "stool",
            "chair 000",
            "node 4",
            "gray-2",
            "ab.7",
            "x5",
        ] {
            assert_eq!(normalize(name), normalize_full(name), "{name}");
        }
        assert_eq!(normalize("SheenChair"), "sheen chair");
        assert_eq!(normalize("Sphere.010"), "sphere 10");
        assert_eq!(normalize("garbage_can  2"), "garbage can 2");
        assert_eq!(normalize("TVStand"), "tvstand");
        assert_eq!(normalize("large.box"), "large box");
        assert_eq!(normalize("chair7"), "chair 7");
        assert_eq!(normalize("Cube (node 4)"), "cube 4");
        assert_eq!(compact("dog bed"), "dogbed");
        assert_eq!(split_number("chair 7"), ("chair", Some(7)));
        assert_eq!(split_number("chair"), ("chair", None));
    }

    #[test]
    fn plurals() {
        assert!(singular("chairs").contains(&"chair".to_string()));
        assert!(singular("boxes").contains(&"box".to_string()));
        assert!(singular("benches").contains(&"bench".to_string()));
        assert!(singular("shelves").contains(&"shelf".to_string()));
        assert!(singular("batteries").contains(&"battery".to_string()));
        assert!(singular("glass").is_empty());
        assert!(singular("bus").is_empty());
    }
}

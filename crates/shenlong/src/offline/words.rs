//! The words the offline translator reads: tokens of a templated query, and its closed
//! word lists (verbs, directions, units, fillers), with one-letter typos of verbs and
//! directions corrected.

/// A token of a templated instruction.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Token {
    /// A lower-case word.
    Word(String),
    /// A number.
    Number(f64),
    /// A variable `X{k+1}`.
    Variable(usize),
    /// `,`, `;`, `.`, `!`, `?`, `:`.
    Separator,
}

/// Splits a templated query into tokens, over the one tokenizer of instructions
/// ([`crate::lex`], quotes read as marks): `1.5m` → 1.5, `m`; `3/4` → 0.75; `°` →
/// degrees; `%` → percent; words joined by `_` are split, and hyphenated ones too
/// (`forward-left`) except known compounds (`counter-clockwise`); `,` `;` `.` `!` `?` `:`
/// separate; other marks are dropped.
pub(crate) fn tokenize(query: &str) -> Vec<Token> {
    use crate::lex::{tokenize_with, Kind, Quotes};
    let lexed = tokenize_with(query, Quotes::Marks);
    let mut tokens = Vec::with_capacity(lexed.len());
    let mut k = 0;
    while k < lexed.len() {
        match &lexed[k].kind {
            Kind::Number(a) => match (lexed.get(k + 1), lexed.get(k + 2)) {
                // "3/4", "1 / 2": a fraction.
                (Some(slash), Some(b)) if slash.kind == Kind::Punct('/') => match b.kind {
                    Kind::Number(b) if b != 0.0 => {
                        tokens.push(Token::Number(a / b));
                        k += 3;
                        continue;
                    }
                    _ => tokens.push(Token::Number(*a)),
                },
                _ => tokens.push(Token::Number(*a)),
            },
            Kind::Word(w) => {
                let compound = |first: &str| {
                    matches!(first, "counter" | "anti")
                        && lexed.get(k + 1).and_then(crate::lex::Token::word) == Some("clockwise")
                };
                if compound(w) {
                    tokens.push(Token::Word(format!("{w}clockwise")));
                    k += 2;
                    continue;
                }
                for part in w.split('_').filter(|p| !p.is_empty()) {
                    word_tokens(part, &mut tokens);
                }
            }
            Kind::Quoted(name) => word_tokens(name, &mut tokens),
            Kind::Punct(',' | ';' | '.' | '!' | '?' | ':') => tokens.push(Token::Separator),
            Kind::Punct('°') => tokens.push(Token::Word("degrees".into())),
            Kind::Punct('%') => tokens.push(Token::Word("percent".into())),
            Kind::Punct(_) => {}
        }
        k += 1;
    }
    plus_in_lists(&mut tokens);
    subject_then_amount(&mut tokens);
    tokens
}

/// `X1 plus X2` (`X1 + X2`) is `X1 and X2`: a list of objects joined either way.
fn plus_in_lists(tokens: &mut [Token]) {
    for k in 1..tokens.len().saturating_sub(1) {
        let between = matches!(tokens[k - 1], Token::Variable(_))
            && matches!(tokens[k + 1], Token::Variable(_));
        if between && matches!(&tokens[k], Token::Word(w) if w == "plus") {
            tokens[k] = Token::Word("and".into());
        }
    }
}

/// The reader's tokens of one word of the tokenizer: a variable (`x2`), a number, a
/// number with its unit (`1.5m`), the parts of a hyphenated word with their numbers and
/// units (`20cm-ish`), or the word, a typo of a word the reader knows read as that word
/// ("degress", "foward"; real words never are).
fn word_tokens(word: &str, tokens: &mut Vec<Token>) {
    let w = word
        .trim_matches(|c: char| c == '.' || c == '\'' || c == '-')
        .replace("counter-clockwise", "counterclockwise")
        .replace("anti-clockwise", "anticlockwise");
    if w.is_empty() {
        return;
    }
    if let Some(n) = w
        .strip_prefix('x')
        .and_then(|d| d.parse::<usize>().ok())
        .filter(|n| *n >= 1)
    {
        tokens.push(Token::Variable(n - 1));
    } else if let Ok(n) = w.parse::<f64>() {
        if n.is_finite() {
            tokens.push(Token::Number(n));
        }
    } else if let Some((n, unit)) = split_number_unit(&w) {
        tokens.push(Token::Number(n));
        tokens.push(Token::Word(unit));
    } else if w.contains('-') {
        for part in w.split('-').filter(|p| !p.is_empty()) {
            // "20cm-ish": a number with its unit stays one.
            match (part.parse::<f64>(), split_number_unit(part)) {
                (Ok(n), _) if n.is_finite() => tokens.push(Token::Number(n)),
                (_, Some((n, unit))) => {
                    tokens.push(Token::Number(n));
                    tokens.push(Token::Word(unit));
                }
                _ => tokens.push(Token::Word(part.to_string())),
            }
        }
    } else {
        let w = if is_a_word(&w) {
            w
        } else {
            correct(&w).map_or(w, str::to_string)
        };
        tokens.push(Token::Word(w));
    }
}

/// "X1: 30 cm left", "X1, 10 cm back": the objects named first, then, after a colon or a
/// comma, how far and where, with no verb. The separator joins them into one clause (a
/// list's comma, "X1, X2 and X3", is kept).
fn subject_then_amount(tokens: &mut Vec<Token>) {
    // The list: variables, "and", and commas followed by another variable.
    let in_list = |i: usize| match &tokens[i] {
        Token::Variable(_) => true,
        Token::Word(w) => w == "and",
        Token::Separator => matches!(tokens.get(i + 1), Some(Token::Variable(_))),
        _ => false,
    };
    let subjects = (0..tokens.len()).take_while(|&i| in_list(i)).count();
    if subjects == 0 || tokens.get(subjects) != Some(&Token::Separator) {
        return;
    }
    let amount_or_way = match tokens.get(subjects + 1) {
        Some(Token::Number(_)) => true,
        Some(Token::Word(w)) => matches!(
            w.as_str(),
            "a" | "an"
                | "half"
                | "about"
                | "around"
                | "roughly"
                | "approximately"
                | "left"
                | "right"
                | "forward"
                | "forwards"
                | "back"
                | "backward"
                | "backwards"
                | "up"
                | "down"
                | "slightly"
        ),
        _ => false,
    };
    if amount_or_way {
        tokens.remove(subjects);
    }
}

/// `2m` → (2, "m"), `90deg` → (90, "deg").
fn split_number_unit(w: &str) -> Option<(f64, String)> {
    let split = w.find(|c: char| c.is_alphabetic())?;
    let (n, unit) = w.split_at(split);
    let n: f64 = n.parse().ok()?;
    (n.is_finite() && unit.chars().all(char::is_alphabetic)).then(|| (n, unit.to_string()))
}

/// Number words: `two` → 2, `twenty` → 20 ([`crate::lex::number_word`]).
pub(crate) fn number_word(w: &str) -> Option<f64> {
    crate::lex::number_word(w)
}

/// Length units to metres.
pub(crate) fn length_unit(w: &str) -> Option<f64> {
    Some(match w {
        "m" | "meter" | "meters" | "metre" | "metres" | "unit" | "units" => 1.0,
        "cm" | "centimeter" | "centimeters" | "centimetre" | "centimetres" | "cms" => 0.01,
        "mm" | "millimeter" | "millimeters" | "millimetre" | "millimetres" => 0.001,
        "ft" | "foot" | "feet" => 0.3048,
        "in" | "inch" | "inches" => 0.0254,
        "yard" | "yards" | "yd" => 0.9144,
        _ => return None,
    })
}

/// Angle units to degrees.
pub(crate) fn angle_unit(w: &str) -> Option<f64> {
    Some(match w {
        "degree" | "degrees" | "deg" | "degs" => 1.0,
        "radian" | "radians" | "rad" | "rads" => 180.0 / std::f64::consts::PI,
        "turn" | "turns" | "revolution" | "revolutions" => 360.0,
        _ => return None,
    })
}

pub(crate) use crate::ground::verbs::{verb, Action};

/// A direction word as (axis 0..2, sign).
pub(crate) fn direction(w: &str) -> Option<(usize, f64)> {
    Some(match w {
        "left" | "leftward" | "leftwards" | "west" => (0, -1.0),
        "right" | "rightward" | "rightwards" | "east" => (0, 1.0),
        "up" | "upward" | "upwards" | "higher" | "above" => (1, 1.0),
        "down" | "downward" | "downwards" | "lower" => (1, -1.0),
        "forward" | "forwards" | "front" | "ahead" | "south" | "frontward" | "frontwards" => {
            (2, 1.0)
        }
        "back" | "backward" | "backwards" | "rear" | "north" => (2, -1.0),
        _ => return None,
    })
}

/// Every word the translator knows, for typo correction.
const KNOWN: &[&str] = &[
    "move",
    "shift",
    "push",
    "slide",
    "nudge",
    "place",
    "bring",
    "position",
    "relocate",
    "carry",
    "drag",
    "pull",
    "stack",
    "roll",
    "shove",
    "scoot",
    "raise",
    "lift",
    "lower",
    "drop",
    "rotate",
    "turn",
    "spin",
    "twist",
    "flip",
    "swivel",
    "scale",
    "resize",
    "enlarge",
    "grow",
    "shrink",
    "swap",
    "switch",
    "exchange",
    "align",
    "center",
    "centre",
    "straighten",
    "left",
    "right",
    "forward",
    "forwards",
    "backward",
    "backwards",
    "back",
    "upward",
    "downward",
    "clockwise",
    "counterclockwise",
    "anticlockwise",
    "degrees",
    "metre",
    "metres",
    "meter",
    "meters",
    "centimetres",
    "centimeters",
    "inches",
    "feet",
    "bigger",
    "smaller",
    "larger",
    "closer",
    "further",
    "farther",
    "towards",
    "toward",
    "between",
    "behind",
    "beside",
    "under",
    "below",
    "above",
    "front",
    "corner",
    "middle",
    "room",
    "wall",
    "floor",
    "please",
    "slightly",
    "little",
    "around",
];

/// Whether a word is one the reader or the lexicon knows as it is (a verb, a direction, a
/// unit, an object noun): never read as a typo of another ("stick" is not "stack").
fn is_a_word(w: &str) -> bool {
    verb(w).is_some()
        || direction(w).is_some()
        || length_unit(w).is_some()
        || angle_unit(w).is_some()
        || number_word(w).is_some()
        || crate::ground::Lexicon::builtin().knows(w)
}

/// The known word one edit (insertion, deletion, substitution, swap of neighbours) from a
/// word of four letters or more, when exactly one is.
pub(crate) fn correct(w: &str) -> Option<&'static str> {
    // Short words are too close to others for edit distance: only these, as typed.
    const SHORT: &[(&str, &str)] = &[
        ("bak", "back"),
        ("bck", "back"),
        ("lft", "left"),
        ("rgt", "right"),
        ("fwd", "forward"),
        ("frwd", "forward"),
    ];
    if let Some(&(_, meant)) = SHORT.iter().find(|(typed, _)| *typed == w) {
        return Some(meant);
    }
    let n = w.chars().count();
    if n < 4 || KNOWN.contains(&w) || COMMON.contains(&w) || !w.chars().all(char::is_alphabetic) {
        return None;
    }
    // On four-letter words only a swap of two neighbours ("moev", "lfet"), which rarely
    // makes another word; on longer ones any one edit.
    let close = |k: &&&str| {
        let k: &str = k;
        if n == 4 {
            crate::ground::words::neighbours_swapped(w, k)
        } else {
            strsim::osa_distance(w, k) == 1
        }
    };
    let near: Vec<&str> = KNOWN.iter().filter(close).copied().collect();
    match near.as_slice() {
        [one] => Some(one),
        // Typing rarely gets the first letter wrong: "foward" is "forward", not "toward".
        _ => {
            let first = w.chars().next();
            let mut same = near.iter().filter(|k| k.chars().next() == first);
            let one = same.next()?;
            same.next().is_none().then_some(*one)
        }
    }
}

/// Real words one edit from a known word, which must never be read as its typo ("light
/// the candle" is not "right").
const COMMON: &[&str] = &[
    "light", "night", "sight", "tight", "fight", "might", "eight", "bright", "flight", "weight",
    "height", "slice", "glide", "flour", "floors", "lover", "mover", "moved", "fronts", "wallet",
    "rooms", "roomy", "below", "lowers", "spine", "spins", "twine", "swift", "sweep", "drift",
    "shrine", "cooler", "closet", "closes", "closed", "clover",
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens() {
        assert_eq!(
            tokenize("Move X1 1.5m forward-left, please."),
            vec![
                Token::Word("move".into()),
                Token::Variable(0),
                Token::Number(1.5),
                Token::Word("m".into()),
                Token::Word("forward".into()),
                Token::Word("left".into()),
                Token::Separator,
                Token::Word("please".into()),
                Token::Separator,
            ]
        );
        assert_eq!(
            tokenize("turn it counter-clockwise")[2],
            Token::Word("counterclockwise".into())
        );
        assert_eq!(tokenize("3/4")[0], Token::Number(0.75));
        assert_eq!(tokenize("let's")[0], Token::Word("let's".into()));
    }

    #[test]
    fn typos() {
        assert_eq!(correct("moev"), Some("move"));
        assert_eq!(correct("rigth"), Some("right"));
        assert_eq!(correct("lfet"), Some("left"));
        assert_eq!(correct("move"), None);
        assert_eq!(correct("mvoe"), Some("move"));
        assert_eq!(correct("light"), None);
        assert_eq!(correct("love"), None);
        assert_eq!(correct("clockwsie"), Some("clockwise"));
        assert_eq!(correct("forwrad"), Some("forward"));
        assert_eq!(correct("foward"), Some("forward"));
        assert_eq!(correct("degress"), Some("degrees"));
        assert_eq!(tokenize("to teh left")[1], Token::Word("the".into()));
        assert_eq!(
            tokenize("turn X1 90 degress")[3],
            Token::Word("degrees".into())
        );
    }
}

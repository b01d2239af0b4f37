//! The follow-ups of a conversation, read from their words: what a turn that leans on the
//! turn before asks for ("a bit more", "put it back", "and the mug too", "no, the other
//! one", "no, on the shelf"). A small grammar over the instruction's core — the words left
//! once greetings, thanks and request frames are set aside ([`crate::discourse::core`]) —
//! never a list of sentences: an instruction that fits none of its forms is an instruction
//! of its own, read as any other.

use std::ops::Range;

/// How much of the last motion a repeat makes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Amount {
    /// This many times the last motion, again (negative: back along it).
    Times(f64),
    /// A small amount along the last motion ("a bit more": +1; "a bit less": −1), at most
    /// the last motion itself (or half of it, going back).
    Bit(f64),
    /// This many metres more along the last motion ("another 10 cm").
    Metres(f64),
    /// This many degrees more along the last turn ("15 more degrees").
    Degrees(f64),
    /// This many more of the unit the last instruction said ("another 5" after "move it
    /// 20 cm left"), which the conversation reads ([`in_unit_of`]).
    Bare(f64),
}

/// How many of the session's last changes a follow-up takes back.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Steps {
    /// The last this many.
    Last(usize),
    /// Every change of the session.
    All,
}

/// What "put … back" puts back.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Which {
    /// What the last edit moved ("put it back").
    Last,
    /// The objects a phrase names ("put the lamp back").
    Named(String),
    /// The one object moved in the session that the last turn did not act on ("put the
    /// other one back").
    Other,
    /// The last two objects moved ("put them both back").
    Both,
    /// The first object moved in the session ("put the first one back").
    First,
    /// Everything moved in the session, where it was at its start ("put everything
    /// back").
    All,
}

/// A follow-up, and the words it carries.
#[derive(Clone, Debug, PartialEq)]
pub enum FollowUp {
    /// The last motion again, or scaled along its own direction.
    Repeat(Amount),
    /// A move of what the last edit moved, in words (`move it a bit to the left`).
    Toward(String),
    /// The last change taken back.
    Undo,
    /// Several changes taken back ("undo both", "undo the last three", "undo
    /// everything").
    UndoMany(Steps),
    /// Objects put back where they were before the edit that last moved them.
    Back(Which),
    /// The last instruction for other objects too (the phrase naming them).
    Also(String),
    /// The last instruction on another object (the phrase naming it), the last edit undone
    /// first.
    Instead(String),
    /// The last instruction with another destination (the prepositional phrase), the last
    /// edit undone first.
    InsteadPlace(String),
    /// The last instruction the other way ("no, left"), the last edit undone first.
    InsteadWay(String),
    /// The last instruction again, another way ("the same again but to the right",
    /// "again, but left"): the way that replaces its own.
    SameWay(String),
    /// A follow-up that reads two ways, and the refusal that says which words to use.
    Unclear(String),
}

/// The words that say a way to move (the offline reader's own directions) or to turn.
pub(crate) fn is_direction(w: &str) -> bool {
    crate::offline::words::direction(w).is_some()
        || matches!(w, "clockwise" | "counterclockwise" | "anticlockwise")
}

/// A word of the instruction: its lower-case text and its bytes.
#[derive(Clone, Debug)]
struct Word {
    text: String,
    span: Range<usize>,
}

/// The instruction's words (letters, digits, apostrophes and quotes kept in words; other
/// punctuation separates them).
fn words(text: &str) -> Vec<Word> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in text
        .char_indices()
        .chain(std::iter::once((text.len(), ' ')))
    {
        let part = c.is_alphanumeric() || matches!(c, '\'' | '’' | '-' | '.' | '_');
        match (part, start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                let raw = text[s..i].trim_end_matches('.');
                if !raw.is_empty() {
                    out.push(Word {
                        text: raw.to_lowercase(),
                        span: s..s + raw.len(),
                    });
                }
                start = None;
            }
            _ => {}
        }
    }
    out
}

/// Words that only say a follow-up is one ("no", "ok then", "I meant").
const CORRECTING: [&[&str]; 28] = [
    &["that", "was", "wrong"],
    &["that's", "wrong"],
    &["thats", "wrong"],
    &["that's", "not", "right"],
    &["not", "right"],
    &["no", "i", "meant"],
    &["no", "i", "mean"],
    &["i", "meant"],
    &["i", "mean"],
    &["i", "said"],
    &["not", "that", "one"],
    &["wrong", "one"],
    &["not", "this", "one"],
    &["make", "that"],
    &["no", "wait"],
    &["no", "sorry"],
    &["sorry"],
    &["oops"],
    &["wait"],
    &["actually"],
    &["rather"],
    &["instead"],
    &["nope"],
    &["nah"],
    &["no"],
    &["try"],
    &["how", "about"],
    &["what", "about"],
];

/// Words that only acknowledge the turn before ("yes, more", "ok good, now a bit left").
fn acknowledging(w: &str) -> bool {
    matches!(
        w,
        "yes"
            | "yeah"
            | "yep"
            | "yup"
            | "ok"
            | "okay"
            | "k"
            | "good"
            | "great"
            | "nice"
            | "perfect"
            | "cool"
            | "lovely"
            | "better"
            | "hmm"
            | "hm"
            | "mm"
            | "alright"
            | "fine"
            | "that's"
            | "thats"
            | "looks"
    )
}

/// Whether the words hold a verb that starts a clause: the first word, one after "and",
/// "then", "to", "also", "please", "just" or "now", or one before what it acts on ("…,
/// put the lamp"); "the tv stand" ends on a noun.
fn verb_clause(w: &[&str]) -> bool {
    w.iter().enumerate().any(|(i, x)| {
        crate::ground::words::is_verb(x)
            && (i == 0
                || matches!(
                    w[i - 1],
                    "and" | "then" | "to" | "also" | "please" | "just" | "now"
                )
                || w.get(i + 1).is_some_and(|next| {
                    matches!(
                        *next,
                        "the"
                            | "a"
                            | "an"
                            | "my"
                            | "it"
                            | "them"
                            | "this"
                            | "that"
                            | "these"
                            | "those"
                            | "all"
                            | "both"
                            | "everything"
                    )
                }))
    })
}

/// Small amounts ("a bit", "slightly").
const BIT: [&[&str]; 19] = [
    &["just", "a", "little", "bit"],
    &["a", "tiny", "little", "bit"],
    &["little", "bit"],
    &["a", "smidgen"],
    &["just", "a", "bit"],
    &["a", "little", "bit"],
    &["a", "tiny", "bit"],
    &["a", "wee", "bit"],
    &["a", "bit"],
    &["a", "little"],
    &["a", "tad"],
    &["a", "touch"],
    &["a", "smidge"],
    &["a", "hair"],
    &["tiny", "bit"],
    &["slightly"],
    &["little"],
    &["some"],
    &["bit"],
];

/// The length of the longest of `options` that `w` starts with.
fn starts(w: &[&str], options: &[&[&str]]) -> Option<usize> {
    options
        .iter()
        .filter(|o| w.len() >= o.len() && w[..o.len()] == ***o)
        .map(|o| o.len())
        .max()
}

/// What `instruction` asks of the turn before, if it is a follow-up; `after_refusal`: the
/// turn before was refused for an ambiguous phrase, so a bare noun phrase picks for it.
#[must_use]
pub fn read(instruction: &str, after_refusal: bool) -> Option<FollowUp> {
    let all = words(instruction);
    let lower: Vec<&str> = all.iter().map(|w| w.text.as_str()).collect();
    let core = crate::discourse::core(&lower);
    // The discourse set aside takes words a follow-up is made of: they come back.
    let kept = |w: &str| {
        matches!(
            w,
            "and"
                | "also"
                | "again"
                | "too"
                | "no"
                | "nope"
                | "more"
                | "actually"
                | "instead"
                | "rather"
                | "wait"
                | "sorry"
                | "oops"
        )
    };
    let (mut start, mut end) = (core.start, core.end.max(core.start));
    while start > 0 && kept(lower[start - 1]) {
        start -= 1;
    }
    while end < lower.len() && kept(lower[end]) {
        end += 1;
    }
    // "yes, more", "ok good, now a bit to the left": the acknowledgement set aside.
    while start < end && acknowledging(lower[start]) {
        start += 1;
    }
    // "now the table": the discourse set aside said that a phrase alone is the next one.
    let after_now = start > 0 && matches!(lower[start - 1], "now" | "then");
    let words = &all[start..end];
    let w: Vec<&str> = lower[start..end].to_vec();
    if w.is_empty() {
        return None;
    }
    let text = |from: usize, to: usize| -> String {
        match (
            words.get(from),
            to.checked_sub(1).and_then(|t| words.get(t)),
        ) {
            (Some(first), Some(last)) if from < to => {
                instruction[first.span.start..last.span.end].to_string()
            }
            _ => String::new(),
        }
    };
    // "no, no, …", "no wait, I meant …": every opener set aside.
    let mut n = 0;
    while let Some(k) = starts(&w[n..], &CORRECTING) {
        n += k;
    }
    // "…, not the table": what is not meant, set aside.
    let not_at = w
        .iter()
        .enumerate()
        .skip(n + 1)
        // ("…, not enough": no correction.)
        .find(|(k, x)| **x == "not" && !matches!(w.get(k + 1), Some(&("enough" | "far" | "quite"))))
        .map_or(w.len(), |(k, _)| k);
    // "move the lamp, not the sofa" is an instruction of its own; "put it on the shelf,
    // not the table" corrects the turn before.
    let whole_instruction = n == 0
        && starts_with_verb(&w)
        && !matches!(w.get(1), Some(&("it" | "them" | "that" | "this")));
    if n > 0 || (not_at < w.len() && !whole_instruction) {
        let said = |from: usize, to: usize| text(from + n, to + n);
        return after_opener(&w[..n], &w[n..], not_at - n, &said);
    }
    // "not on the shelf, on the table", "not the sofa, the armchair".
    if w[0] == "not"
        && w.len() > 2
        && (place_word(w[1]) || matches!(w[1], "the" | "a" | "an" | "my"))
    {
        return correction(&w, &text);
    }
    // "… instead", "… rather".
    if w.len() > 1 && matches!(w[w.len() - 1], "instead" | "rather") {
        return correction(&w[..w.len() - 1], &text);
    }
    // "the other one", "wrong chair", "not that chair": another of the same; "wrong, put
    // it back": an opener before a clause of its own.
    match w.as_slice() {
        ["wrong", rest @ ..] if starts_with_verb(rest) => {
            return after_opener(&w[..1], rest, rest.len(), &|from, to| {
                text(from + 1, to + 1)
            });
        }
        ["the", "other", ..] | ["other", ..] if !starts_with_verb(&w) && !w.contains(&"too") => {
            return Some(FollowUp::Instead(text(0, w.len())));
        }
        ["wrong", noun] | ["not", "that" | "this", noun]
            if *noun != "one" && !degree_word(noun) =>
        {
            return Some(FollowUp::Instead(format!("the other {noun}")));
        }
        // "wrong table, the tv stand": what replaces it follows.
        ["wrong", noun, rest @ ..] if *noun != "one" && !rest.is_empty() => {
            return correction(rest, &|from, to| text(from + 2, to + 2));
        }
        _ => {}
    }
    undo(&w)
        .or_else(|| back(&w, &text))
        .or_else(|| same_way(&w))
        .or_else(|| repeat(&w, &text))
        .or_else(|| toward_alone(&w, &text))
        .or_else(|| also(&w, &text, after_now))
        .or_else(|| destination_alone(&w, &text))
        .or_else(|| {
            // After a refusal a bare noun phrase picks; after an edit, one that says "one"
            // ("the right one", "the one by the window") is another of its kind.
            let one = matches!(w[0], "the" | "that" | "this")
                && w.iter().any(|x| matches!(*x, "one" | "ones"));
            ((after_refusal || one) && !starts_with_verb(&w))
                .then(|| FollowUp::Instead(text(0, w.len())))
        })
}

/// What follows the openers that make a turn a correction (`opener`: "no", "I meant",
/// "not that one"), up to the word `not_at` of `rest` (where "…, not the table" starts).
fn after_opener(
    opener: &[&str],
    rest: &[&str],
    not_at: usize,
    said: &dyn Fn(usize, usize) -> String,
) -> Option<FollowUp> {
    // "not that one", "wrong one" alone: the other one.
    if rest.is_empty()
        && matches!(
            opener,
            [.., "not", "that" | "this", "one"] | [.., "wrong", "one"]
        )
    {
        return Some(FollowUp::Instead("the other one".into()));
    }
    // "no, put it back", "nah, undo", "no, a bit less": a follow-up of its own after the
    // opener, not a correction.
    if !opener.is_empty() {
        if let Some(own) = undo(rest)
            .or_else(|| back(rest, said))
            .or_else(|| repeat(rest, said))
        {
            return Some(own);
        }
    }
    correction(&rest[..not_at.min(rest.len())], said)
}

/// A destination said alone ("onto the chair", "next to the sofa"): where the last
/// edit's objects should have gone instead.
fn destination_alone(w: &[&str], text: &dyn Fn(usize, usize) -> String) -> Option<FollowUp> {
    let first = *w.first()?;
    let determiner = |x: Option<&&str>| {
        x.is_some_and(|x| matches!(*x, "the" | "a" | "an" | "my" | "that" | "this" | "those"))
    };
    let place = matches!(
        first,
        "on" | "onto"
            | "into"
            | "under"
            | "underneath"
            | "beneath"
            | "beside"
            | "behind"
            | "next"
            | "near"
            | "against"
            | "inside"
            | "atop"
            | "between"
            | "in"
    ) || (first == "by" && determiner(w.get(1)));
    (place && w.len() > 1 && !verb_clause(&w[1..]))
        .then(|| FollowUp::InsteadPlace(text(0, w.len())))
}

/// "no, on the shelf" (a destination) or "no, the other one" (an object).
fn correction(w: &[&str], text: &dyn Fn(usize, usize) -> String) -> Option<FollowUp> {
    match w {
        // "do it to the other one instead", "do that with the lamp": another object.
        ["do", "it" | "that" | "this", "to" | "with" | "for", rest @ ..]
        | ["do", "the", "same", "to" | "with" | "for", rest @ ..]
            if !rest.is_empty() =>
        {
            let from = w.len() - rest.len();
            return Some(FollowUp::Instead(text(from, w.len())));
        }
        // "not that speaker": the other one of its kind.
        ["not", "that" | "this", noun] if *noun != "one" && !degree_word(noun) => {
            return Some(FollowUp::Instead(format!("the other {noun}")));
        }
        _ => {}
    }
    // "put it on the table instead", "move it left instead": the verb and what it moved
    // set aside.
    let skip = match w {
        [verb, "it" | "them" | "that" | "this", ..] if crate::ground::words::is_verb(verb) => 2,
        [verb, ..] if crate::ground::words::is_verb(verb) => {
            // "move the lamp instead": another object, said with a verb.
            let rest = &w[1..];
            let plain = !rest.is_empty()
                && !rest.iter().any(|x| {
                    crate::ground::words::is_preposition(x)
                        || is_direction(x)
                        || x.parse::<f64>().is_ok()
                });
            return plain.then(|| FollowUp::Instead(text(1, w.len())));
        }
        _ => 0,
    };
    let w = &w[skip..];
    let first = *w.first()?;
    let said = |from: usize| text(from + skip, w.len() + skip);
    if w.iter()
        .all(|x| is_direction(x) || matches!(*x, "to" | "the" | "a" | "bit"))
        && w.iter().any(|x| is_direction(x))
    {
        let way = w.iter().rev().find(|x| is_direction(x))?;
        return Some(FollowUp::InsteadWay((*way).to_string()));
    }
    // "not on the shelf, on the table": the second place; "not the sofa, the armchair":
    // the second object.
    if first == "not" {
        let determiner = |x: &str| matches!(x, "the" | "a" | "an" | "my" | "that" | "this");
        let places = w.get(1).is_some_and(|x| place_word(x));
        let second =
            w.iter()
                .enumerate()
                .skip(2)
                .find(|(_, x)| if places { place_word(x) } else { determiner(x) });
        let (k, _) = second?;
        return Some(if place_word(w[k]) {
            FollowUp::InsteadPlace(said(k))
        } else {
            FollowUp::Instead(said(k))
        });
    }
    if verb_clause(&w[1..]) {
        None
    } else if place_word(first) {
        Some(FollowUp::InsteadPlace(said(0)))
    } else if skip == 0 {
        Some(FollowUp::Instead(said(0)))
    } else {
        None
    }
}

/// A word that starts a place ("on", "next", "beside").
fn place_word(w: &str) -> bool {
    crate::ground::words::is_preposition(w) && !matches!(w, "of" | "with" | "by" | "for" | "from")
        || matches!(w, "next" | "beside" | "behind")
}

fn starts_with_verb(w: &[&str]) -> bool {
    w.first().is_some_and(|f| crate::ground::words::is_verb(f))
}

/// "undo", "undo that", "take that back".
fn undo(w: &[&str]) -> Option<FollowUp> {
    let pronoun = |x: &str| {
        matches!(
            x,
            "that"
                | "it"
                | "this"
                | "the"
                | "last"
                | "change"
                | "edit"
                | "one"
                | "move"
                | "step"
                | "please"
        )
    };
    if let Some(steps) = undo_steps(w) {
        return Some(FollowUp::UndoMany(steps));
    }
    match w {
        // "undo", "undo what you just did", "undo the last thing": the last change.
        ["undo", rest @ ..]
            if !rest
                .iter()
                .any(|x| crate::ground::words::is_verb(x) && !pronoun(x)) =>
        {
            Some(FollowUp::Undo)
        }
        // "reverse that", "reverse the last move" (not "reverse the sofa": a turn).
        ["revert" | "cancel" | "scratch" | "reverse", rest @ ..]
            if rest.iter().all(|x| pronoun(x)) && !rest.is_empty() && rest != ["it"] =>
        {
            Some(FollowUp::Undo)
        }
        ["take", "that" | "it", "back"]
        | ["go", "back", "one" | "a", "step"]
        | ["never", "mind"]
        | ["nevermind"]
        | ["revert"]
        | ["forget", "it" | "that"] => Some(FollowUp::Undo),
        _ => None,
    }
}

/// "undo both", "undo twice", "undo the last 3 changes", "undo everything", "start
/// over": more than the last change.
fn undo_steps(w: &[&str]) -> Option<Steps> {
    let change = |x: &[&str]| {
        matches!(
            x,
            [] | ["changes" | "edits" | "moves" | "steps" | "ones" | "things"]
                | ["changes" | "edits" | "moves" | "steps", "please"]
                | ["please"]
        )
    };
    let count = |x: &str| number(x).filter(|n| n.fract() == 0.0 && *n >= 1.0 && *n <= 64.0);
    match w {
        ["start", "over" | "again"] | ["start", "from", "scratch"] => Some(Steps::All),
        ["undo" | "revert" | "reset", rest @ ..] => match rest {
            ["everything" | "all", tail @ ..] if change(tail) => Some(Steps::All),
            ["all", "the" | "my", "changes" | "edits" | "moves"] | ["it", "all"] => {
                Some(Steps::All)
            }
            ["both", tail @ ..] | ["them", "both", tail @ ..] if change(tail) => {
                Some(Steps::Last(2))
            }
            ["twice"] | ["twice", "please"] => Some(Steps::Last(2)),
            ["three", "times"] | ["thrice"] => Some(Steps::Last(3)),
            [n, "times", tail @ ..] if change(tail) => count(n).map(|n| Steps::Last(n as usize)),
            ["the", "last", n, tail @ ..] | ["last", n, tail @ ..] if change(tail) => count(n)
                .filter(|n| *n > 1.0)
                .map(|n| Steps::Last(n as usize)),
            ["those", "two" | "2", tail @ ..] if change(tail) => Some(Steps::Last(2)),
            _ => None,
        },
        _ => None,
    }
}

/// What the words between "put" and "back" name.
fn which(object: &[&str], text: &dyn Fn() -> String) -> Which {
    match object {
        [] | ["it" | "them" | "that" | "those" | "this" | "these"] => Which::Last,
        // "restore its position", "reset the position".
        ["its" | "their" | "the", "position" | "place" | "spot" | "pose" | "location"] => {
            Which::Last
        }
        ["everything"]
        | ["it" | "them", "all"]
        | ["all"]
        | ["all", "of", "them"]
        | ["the", "scene" | "room"] => Which::All,
        ["both"] | ["them", "both"] | ["both", "of", "them"] => Which::Both,
        ["the", "other", "one"] | ["the", "other"] => Which::Other,
        ["the", "first", "one"] | ["the", "first"] => Which::First,
        _ => Which::Named(text()),
    }
}

/// Whether `rest` says where something was ("where it was", "to its original place",
/// "the way it was before", or nothing).
fn where_it_was(rest: &[&str]) -> bool {
    let mut rest = match rest {
        ["to" | "in" | "into", r @ ..] => r,
        r => r,
    };
    // "… too", "… as well", "… please".
    while let [r @ .., "too" | "please" | "also"] | [r @ .., "as", "well"] = rest {
        rest = r;
    }
    // "… before", "… at first", "… to begin with".
    while let [r @ .., "before"] | [r @ .., "at", "first"] | [r @ .., "originally"] = rest {
        rest = r;
    }
    let earlier = |x: &str| {
        matches!(
            x,
            "place"
                | "spot"
                | "position"
                | "pose"
                | "location"
                | "old"
                | "original"
                | "first"
                | "previous"
                | "former"
                | "earlier"
                | "starting"
                | "initial"
                | "usual"
                | "last"
        )
    };
    match rest {
        [] | ["again"] => true,
        ["where" | "how" | "as", "it" | "they" | "he" | "she", verb, ..]
        | ["the", "way", "it" | "they", verb, ..] => matches!(
            *verb,
            "was"
                | "were"
                | "used"
                | "started"
                | "came"
                | "belongs"
                | "belong"
                | "belonged"
                | "stood"
                | "sat"
                | "had"
                | "is"
                | "are"
        ),
        // "its place", "the original position", "their old spot".
        ["its" | "their" | "the", what @ ..] => !what.is_empty() && what.iter().all(|x| earlier(x)),
        _ => false,
    }
}

/// "move it back", with no amount and nothing after, by a verb that is not one of
/// putting (`putting`): where it was, or backwards? Refused, saying both.
fn back_or_backwards(
    w: &[&str],
    putting: &dyn Fn(&str) -> bool,
    text: &dyn Fn(usize, usize) -> String,
) -> Option<FollowUp> {
    let ([first, "it" | "them" | "that" | "this", "back"]
    | [first, "it" | "them" | "that" | "this", "back", "please"]
    | [first, "back", "it" | "them" | "that" | "this"]) = w
    else {
        return None;
    };
    (!putting(first) && crate::ground::words::is_verb(first)).then(|| {
        FollowUp::Unclear(format!(
            "\"{}\" reads two ways: say \"put it back\" to return it where it was, or how far to move it backwards (\"{first} it back 50 cm\")",
            text(0, w.len())
        ))
    })
}

/// "put it back", "put the chair back where it was", "back where it was", "return the
/// lamp to where it was".
fn back(w: &[&str], text: &dyn Fn(usize, usize) -> String) -> Option<FollowUp> {
    let verb = |x: &str| {
        matches!(
            x,
            "put" | "bring" | "set" | "place" | "return" | "restore" | "get" | "reset"
        )
    };
    if let Some(unclear) = back_or_backwards(w, &verb, text) {
        return Some(unclear);
    }
    // Any motion verb, when where it was follows: "move it back to where it was", "move
    // it to where it was", "slide the lamp to its original spot".
    if let [first, ..] = w {
        if !verb(first) && crate::ground::words::is_verb(first) {
            if let Some(k) = w.iter().position(|&x| x == "back") {
                let rest = &w[k + 1..];
                if k >= 1 && !rest.is_empty() && where_it_was(rest) {
                    return Some(FollowUp::Back(which(&w[1..k], &|| text(1, k))));
                }
            }
            if let Some(k) = w.iter().position(|&x| matches!(x, "to" | "where")) {
                let place = &w[k..];
                let said = !matches!(place, ["to"] | ["to", "again"]);
                if k >= 1 && said && where_it_was(place) {
                    return Some(FollowUp::Back(which(&w[1..k], &|| text(1, k))));
                }
            }
        }
    }
    if let [first, ..] = w {
        if verb(first) {
            let at = w.iter().position(|&x| x == "back");
            // "put X back [where it was]"; "return X [to where it was]".
            // "put back the lamp [where it was]": the particle before the object.
            if at == Some(1) && w.len() > 2 && !where_it_was(&w[2..]) {
                let end = w
                    .iter()
                    .skip(2)
                    .position(|&x| matches!(x, "where" | "to" | "how" | "as"))
                    .map_or(w.len(), |p| p + 2);
                if !where_it_was(&w[end..]) {
                    return None;
                }
                return Some(FollowUp::Back(which(&w[2..end], &|| text(2, end))));
            }
            let (object_end, rest) = match (at, w.iter().position(|&x| x == "where")) {
                (Some(k), _) => (k, &w[k + 1..]),
                // "put it where it was"; "return it to where it started".
                (None, Some(k)) if k > 1 && w[k - 1] == "to" => (k - 1, &w[k - 1..]),
                (None, Some(k)) => (k, &w[k..]),
                (None, None) if matches!(*first, "return" | "restore" | "reset") => {
                    let k = w.iter().position(|&x| x == "to").unwrap_or(w.len());
                    (k, &w[k..])
                }
                (None, None) => return None,
            };
            if object_end < 1 || !where_it_was(rest) {
                return None;
            }
            return Some(FollowUp::Back(which(&w[1..object_end], &|| {
                text(1, object_end)
            })));
        }
    }
    // "go back", "go back please", "go back to how it was": where it was.
    if let ["go" | "get" | "change" | "switch", "back", rest @ ..] = w {
        if where_it_was(rest) {
            return Some(FollowUp::Back(Which::Last));
        }
    }
    // "the lamp back where it was", "everything back to how it was": said without a verb.
    if let Some(k) = w.iter().position(|&x| x == "back") {
        if k > 0 && where_it_was(&w[k + 1..]) && !w[k + 1..].is_empty() && !verb_clause(&w[..k]) {
            return Some(FollowUp::Back(which(&w[..k], &|| text(0, k))));
        }
    }
    // "original position please", "old spot": the place alone.
    if let [first, ..] = w {
        if matches!(
            *first,
            "original" | "previous" | "old" | "former" | "initial"
        ) {
            let mut said = vec!["the"];
            said.extend_from_slice(w);
            if where_it_was(&said) {
                return Some(FollowUp::Back(Which::Last));
            }
        }
    }
    // "back where it was", "back to where it was", "where it was".
    let rest = match w {
        ["back", "to", r @ ..] | ["back", r @ ..] => r,
        r => r,
    };
    (matches!(
        rest.first(),
        Some(&("where" | "how" | "as" | "the" | "its"))
    ) && where_it_was(rest))
    .then_some(FollowUp::Back(Which::Last))
}

/// "again", "a bit more", "twice as far", "not so far", "more to the left", "another 10
/// cm"; also after a motion verb and what it moved ("move it a bit more", "push them
/// further", "turn it again").
fn repeat(w: &[&str], text: &dyn Fn(usize, usize) -> String) -> Option<FollowUp> {
    // "go on", "keep going", "double that": whole forms first, then with a verb set aside.
    if let Some(own) = repeat_of(w, text) {
        return Some(own);
    }
    let skip = match w {
        [verb, "it" | "them" | "that" | "this" | "those" | "these", ..]
            if crate::ground::words::is_verb(verb) =>
        {
            2
        }
        ["go" | "push" | "move" | "turn" | "rotate" | "slide" | "spin", ..] => 1,
        _ => 0,
    };
    if skip > 0 {
        let said = |from: usize, to: usize| text(from + skip, to + skip);
        return repeat_of(&w[skip..], &said);
    }
    repeat_of(w, text)
}

/// The length or angle of "10 cm", "15 degrees", "another 2 inches", "10cm".
fn amount(w: &[&str]) -> Option<(Amount, usize)> {
    let (number, unit, used) = match w {
        [n, unit, ..] if number(n).is_some() => (number(n)?, *unit, 2),
        [glued, ..] => {
            let cut = glued.find(|c: char| !(c.is_ascii_digit() || c == '.'))?;
            (glued[..cut].parse::<f64>().ok()?, &glued[cut..], 1)
        }
        [] => return None,
    };
    if let Some(per) = crate::offline::words::length_unit(unit) {
        return Some((Amount::Metres(number * per), used));
    }
    let per = crate::offline::words::angle_unit(unit)?;
    Some((Amount::Degrees(number * per), used))
}

/// A number in digits or words.
fn number(w: &str) -> Option<f64> {
    w.parse::<f64>()
        .ok()
        .filter(|n| n.is_finite() && *n > 0.0)
        .or_else(|| crate::lex::number_word(w))
}

/// "an inch", "a couple of inches", "a few degrees": one, two or three of the unit.
fn counted(w: &[&str]) -> Option<(Amount, usize)> {
    let (count, at) = match w {
        ["a", "couple", "of", ..] => ("2", 3),
        ["a", "few", ..] => ("3", 2),
        ["a" | "an" | "one", ..] => ("1", 1),
        _ => return None,
    };
    let (a, _) = amount(&[count, w.get(at)?])?;
    Some((a, at + 1))
}

/// "another 10 cm", "10 cm more", "5 more degrees", "a further 20 cm", "an inch more",
/// "another 5" (the unit of the last instruction).
fn explicit(w: &[&str]) -> Option<Amount> {
    let (rest, opener) = match w {
        ["another" | "additional", rest @ ..] | ["a", "further" | "another", rest @ ..] => {
            (rest, true)
        }
        rest => (rest, false),
    };
    // A number without a unit: "another 5", "5 more".
    match rest {
        // "another inch", "a further degree".
        [unit] | [unit, "please"] if opener && number(unit).is_none() => {
            return amount(&["1", unit]).map(|(a, _)| a);
        }
        [n] | [n, "please"] if opener && number(n).is_some() => {
            return number(n).map(Amount::Bare);
        }
        [n, "more"] | [n, "more", "please"] if !opener && number(n).is_some() => {
            return number(n).map(Amount::Bare);
        }
        _ => {}
    }
    if let Some((a, used)) = amount(rest).or_else(|| counted(rest)) {
        let tail = &rest[used..];
        let ok = if opener {
            tail.is_empty()
        } else {
            matches!(
                tail,
                ["more" | "further" | "farther"] | ["more" | "further" | "farther", "please"]
            )
        };
        return ok.then_some(a);
    }
    // "5 more degrees"
    if let [n, "more", unit] = rest {
        return amount(&[n, unit]).map(|(a, _)| a);
    }
    None
}

/// The amount `n` of a bare "another 5" in the unit of the first amount `instruction`
/// says ("move it 20 cm left": centimetres; "turn it 15 degrees": degrees); `None` when
/// it says none.
#[must_use]
pub(crate) fn in_unit_of(n: f64, instruction: &str) -> Option<Amount> {
    let said = words(instruction);
    let w: Vec<&str> = said.iter().map(|x| x.text.as_str()).collect();
    (0..w.len()).find_map(|k| {
        let unit = match amount(&w[k..])? {
            (_, 2) => w[k + 1].to_string(),
            // Glued: "20cm".
            _ => w[k]
                .trim_start_matches(|c: char| c.is_ascii_digit() || c == '.')
                .to_string(),
        };
        amount(&["1", &unit]).map(|(a, _)| match a {
            Amount::Metres(m) => Amount::Metres(n * m),
            Amount::Degrees(d) => Amount::Degrees(n * d),
            other => other,
        })
    })
}

/// "twice more", "3 more times", "repeat that twice": the last motion that many times
/// again.
fn more_times(w: &[&str]) -> Option<Amount> {
    let times = |x: &str| match x {
        "twice" => Some(2.0),
        "thrice" => Some(3.0),
        _ => None,
    };
    let n = match w {
        [t, "more"] | [t, "more", "please"] | ["repeat", t] => times(t)?,
        [n, "more", "times"] | [n, "more", "times", "please"] | ["repeat", n, "times"] => {
            number(n)?
        }
        ["repeat", "it" | "that", t] => times(t)?,
        ["repeat", "it" | "that", n, "times"] => number(n)?,
        _ => return None,
    };
    (n.fract() == 0.0 && (1.0..=10.0).contains(&n)).then_some(Amount::Times(n))
}

/// The whole of what says the last motion did not go far enough: a small step more.
const NOT_ENOUGH: [&[&str]; 8] = [
    &["not", "far", "enough"],
    &["not", "enough"],
    &["not", "quite", "far", "enough"],
    &["that's", "not", "enough"],
    &["thats", "not", "enough"],
    &["that's", "not", "far", "enough"],
    &["it's", "not", "far", "enough"],
    &["more", "than", "that"],
];

/// [`repeat`] once any motion verb is set aside.
/// The whole of what says the last motion again.
const AGAIN: [&[&str]; 17] = [
    &["again"],
    &["once", "more"],
    &["one", "more", "time"],
    &["do", "it", "again"],
    &["do", "that", "again"],
    &["same", "again"],
    &["repeat"],
    &["repeat", "that"],
    &["keep", "going"],
    &["another", "bit"],
    &["go", "on"],
    &["and", "again"],
    &["carry", "on"],
    &["continue"],
    &["double", "that"],
    &["the", "same", "again"],
    &["keep", "it", "going"],
];

/// The whole of what says the last motion went too far.
const TOO_FAR: [&[&str]; 17] = [
    &["not", "so", "far"],
    &["not", "as", "far"],
    &["not", "that", "far"],
    &["not", "so", "much"],
    &["not", "as", "much"],
    &["too", "far"],
    &["too", "much"],
    &["less"],
    &["halfway", "back"],
    &["half", "that"],
    &["halve", "it"],
    &["halve", "that"],
    &["that's", "too", "far"],
    &["thats", "too", "far"],
    &["it's", "too", "far"],
    &["that's", "too", "much"],
    &["way", "too", "far"],
];

/// "again", "do the same again", "once again please", "repeat the last move" (the last
/// motion once more); "not so far", "too much" (back by half of it).
fn same_again(w: &[&str]) -> Option<Amount> {
    if AGAIN.contains(&w) {
        return Some(Amount::Times(1.0));
    }
    // "again" or "repeat" with nothing but words that point at the last motion.
    let filler = |x: &str| {
        matches!(
            x,
            "do" | "it"
                | "that"
                | "this"
                | "the"
                | "same"
                | "once"
                | "one"
                | "more"
                | "time"
                | "please"
                | "just"
                | "thing"
                | "motion"
                | "move"
                | "step"
                | "last"
                | "edit"
                | "again"
                | "repeat"
                | "and"
                | "so"
                | "distance"
                | "amount"
        )
    };
    if w.iter().any(|x| matches!(*x, "again" | "repeat")) && w.iter().all(|x| filler(x)) {
        return Some(Amount::Times(1.0));
    }
    if NOT_ENOUGH.contains(&w) {
        return Some(Amount::Bit(1.0));
    }
    TOO_FAR.contains(&w).then_some(Amount::Times(-0.5))
}

fn repeat_of(w: &[&str], text: &dyn Fn(usize, usize) -> String) -> Option<FollowUp> {
    // "now a bit more", "even further", "further still": words that only lean on the
    // comparison, set aside.
    let lead = w
        .iter()
        .take_while(|x| matches!(**x, "now" | "then" | "and" | "even" | "still" | "yet"))
        .count();
    let trail = w[lead..]
        .iter()
        .rev()
        .take_while(|x| matches!(**x, "still" | "yet" | "please" | "then" | "now"))
        .count();
    if lead + trail > 0 {
        let inner = &w[lead..w.len() - trail];
        if inner.is_empty() {
            return None;
        }
        return repeat_of(inner, &|from, to| text(from + lead, to + lead));
    }
    if let Some(a) = explicit(w)
        .or_else(|| more_times(w))
        .or_else(|| a_few_more(w))
        .or_else(|| same_again(w))
        .or_else(|| times_as_far(w))
    {
        return Some(FollowUp::Repeat(a));
    }
    // [a bit] more|further|less [direction …]
    let bit = starts(w, &BIT);
    let at = bit.unwrap_or(0) + usize::from(w.get(bit.unwrap_or(0)) == Some(&"even"));
    let head = *w.get(at)?;
    let rest = &w[at + 1..];
    let sign = match head {
        "more" | "further" | "farther" => 1.0,
        "less" => -1.0,
        _ => return None,
    };
    if rest.is_empty() || rest == ["please"] {
        return Some(FollowUp::Repeat(match bit {
            Some(_) => Amount::Bit(sign),
            None => Amount::Times(sign.max(-0.5)),
        }));
    }
    // "more to the left", "a bit further left": a move of its own, a small one.
    let first = rest[0];
    let direction = crate::ground::words::is_preposition(first)
        || is_direction(first)
        || matches!(first, "away" | "toward" | "towards" | "over");
    (sign > 0.0 && direction)
        .then(|| FollowUp::Toward(format!("move it a bit {}", text(at + 1, w.len()))))
}

/// What says the last instruction again, before another way ("the same again but …").
const SAME: [&[&str]; 12] = [
    &["the", "same", "again"],
    &["same", "again"],
    &["do", "the", "same"],
    &["do", "that", "again"],
    &["do", "it", "again"],
    &["the", "same", "thing"],
    &["same", "thing"],
    &["the", "same", "distance"],
    &["same", "distance"],
    &["the", "same"],
    &["same"],
    &["again"],
];

/// "the same again but to the right", "again, but left", "same distance to the left",
/// "do the same this time backwards": the last instruction again with another way (one
/// direction word, with "to the" before it or not).
fn same_way(w: &[&str]) -> Option<FollowUp> {
    let k = starts(w, &SAME)?;
    let mut rest = &w[k..];
    if let ["but" | "only" | "just", tail @ ..] | ["this", "time", tail @ ..] = rest {
        rest = tail;
    }
    if let ["this", "time", tail @ ..] = rest {
        rest = tail;
    }
    let way = match rest {
        [way]
        | ["to", way]
        | ["to", "the", way]
        | [way, "instead"]
        | ["to", "the", way, "instead"] => *way,
        _ => return None,
    };
    (is_direction(way) && way != "back").then(|| FollowUp::SameWay(way.to_string()))
}

/// Words that say how far or how much, not an object ("not that far").
fn degree_word(w: &str) -> bool {
    matches!(
        w,
        "far" | "much" | "many" | "close" | "big" | "high" | "low" | "fast" | "long"
    )
}

/// "a few more cm", "a couple more degrees", "a few more": a few of the unit (three;
/// a couple: two), or a small amount without one.
fn a_few_more(w: &[&str]) -> Option<Amount> {
    let (count, rest) = match w {
        ["a", "few", "more", rest @ ..] | ["few", "more", rest @ ..] => (3.0, rest),
        ["a", "couple", "more", rest @ ..] | ["a", "couple", "of", "more", rest @ ..] => {
            (2.0, rest)
        }
        _ => return None,
    };
    match rest {
        [] | ["please"] => Some(Amount::Bit(1.0)),
        [unit] | [unit, "please"] => {
            if let Some(per) = crate::offline::words::length_unit(unit) {
                Some(Amount::Metres(count * per))
            } else {
                crate::offline::words::angle_unit(unit).map(|per| Amount::Degrees(count * per))
            }
        }
        _ => None,
    }
}

/// "twice as far", "three times as much", "half as far", "twice that", "double the
/// distance".
fn times_as_far(w: &[&str]) -> Option<Amount> {
    let (factor, rest) = match w {
        ["twice" | "double", rest @ ..] => (2.0, rest),
        ["triple", rest @ ..] => (3.0, rest),
        ["half", rest @ ..] => (0.5, rest),
        ["three", "times", rest @ ..] => (3.0, rest),
        ["two", "times", rest @ ..] => (2.0, rest),
        _ => return None,
    };
    if matches!(
        rest,
        ["that"] | ["the", "distance" | "amount" | "angle" | "turn" | "move"]
    ) {
        return Some(Amount::Times(factor - 1.0));
    }
    // "half as much again", "twice as far again": that much more; without "again", that
    // much in all.
    match rest {
        ["as", "far" | "much", "again"] => Some(Amount::Times(factor)),
        ["as", "far" | "much", ..] => Some(Amount::Times(factor - 1.0)),
        _ => None,
    }
}

/// A way and an amount said alone ("a bit to the left", "10 cm up", "and a little
/// forward", "15 degrees clockwise"): a move (or a turn) of what the last edit moved.
/// "Back" alone reads two ways — towards where it was, or backwards — and is refused.
fn toward_alone(w: &[&str], text: &dyn Fn(usize, usize) -> String) -> Option<FollowUp> {
    let lead = w
        .iter()
        .take_while(|x| matches!(**x, "and" | "now" | "then" | "just"))
        .count();
    let rest = &w[lead..];
    let small = |x: &str| {
        BIT.iter().any(|b| b.contains(&x))
            || matches!(
                x,
                "to" | "the" | "a" | "an" | "more" | "by" | "over" | "please" | "side" | "way"
            )
    };
    let unit = |x: &str| {
        crate::offline::words::length_unit(x).is_some()
            || crate::offline::words::angle_unit(x).is_some()
    };
    // A number only with its unit ("10 cm", "10cm"), never alone ("the right one").
    let measure = |x: &str| amount(&[x]).is_some() || unit(x);
    let fits = rest.iter().enumerate().all(|(k, x)| {
        is_direction(x)
            || small(x)
            || measure(x)
            || (number(x).is_some() && rest.get(k + 1).is_some_and(|u| unit(u)))
    });
    let ways: Vec<&str> = rest.iter().copied().filter(|x| is_direction(x)).collect();
    if rest.is_empty() || !fits || ways.is_empty() {
        return None;
    }
    let said = text(lead, w.len());
    if ways.iter().all(|x| *x == "back") {
        return Some(FollowUp::Unclear(format!(
            "\"{said}\" reads two ways: say \"a bit less\" to go part of the way back, or \"move it backwards {}\" to move it backwards",
            if rest.iter().any(|x| measure(x)) { "that far" } else { "a bit" }
        )));
    }
    let turn = rest.iter().any(|x| {
        crate::offline::words::angle_unit(x).is_some()
            || matches!(*x, "clockwise" | "counterclockwise" | "anticlockwise")
    });
    Some(FollowUp::Toward(format!(
        "{} it {said}",
        if turn { "turn" } else { "move" }
    )))
}

/// "and the mug too", "the bowl as well", "same for the chairs", "do the same with the
/// coffee table", "also the lamp".
fn also(w: &[&str], text: &dyn Fn(usize, usize) -> String, now: bool) -> Option<FollowUp> {
    let same = starts(
        w,
        &[
            &["do", "the", "same", "for"],
            &["do", "the", "same", "with"],
            &["do", "the", "same", "to"],
            &["do", "that", "to"],
            &["do", "that", "with"],
            &["do", "that", "for"],
            &["the", "same", "for"],
            &["the", "same", "with"],
            &["the", "same", "to"],
            &["same", "thing", "for"],
            &["same", "thing", "with"],
            &["same", "goes", "for"],
            &["repeat", "that", "for"],
            &["repeat", "that", "with"],
            &["repeat", "for"],
            &["repeat", "with"],
            &["do", "it", "to"],
            &["do", "it", "for"],
            &["do", "it", "with"],
            &["ditto", "for"],
            &["likewise", "for"],
            &["likewise"],
            &["ditto"],
            &["now"],
            &["do"],
            &["same", "for"],
            &["same", "with"],
            &["same", "to"],
            &["and", "also"],
            &["also"],
            &["and"],
        ],
    )
    .unwrap_or(0);
    let mut end = w.len();
    for tail in [&["as", "well"][..], &["too"], &["also"]] {
        if w[..end].ends_with(tail) {
            end -= tail.len();
        }
    }
    let nothing_adds = same == 0 && end == w.len() && !now;
    // "and the lamp": a phrase, not an instruction ("and move the lamp left").
    let said = &w[same..end.max(same)];
    let ends_on_a_side = said
        .last()
        .is_some_and(|x| crate::ground::words::side_word(x).is_some());
    let phrase = !(verb_clause(said) || ends_on_a_side);
    if end <= same || nothing_adds || !phrase {
        return None;
    }
    Some(FollowUp::Also(text(same, end)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_kind_is_read_from_its_form() {
        let r = |t: &str| read(t, false);
        assert_eq!(r("again"), Some(FollowUp::Repeat(Amount::Times(1.0))));
        assert_eq!(
            r("ok, do it again please"),
            Some(FollowUp::Repeat(Amount::Times(1.0)))
        );
        assert_eq!(r("a bit more"), Some(FollowUp::Repeat(Amount::Bit(1.0))));
        assert_eq!(
            r("a little less"),
            Some(FollowUp::Repeat(Amount::Bit(-1.0)))
        );
        assert_eq!(r("further"), Some(FollowUp::Repeat(Amount::Times(1.0))));
        assert_eq!(
            r("twice as far"),
            Some(FollowUp::Repeat(Amount::Times(1.0)))
        );
        assert_eq!(
            r("half as far"),
            Some(FollowUp::Repeat(Amount::Times(-0.5)))
        );
        assert_eq!(r("not so far"), Some(FollowUp::Repeat(Amount::Times(-0.5))));
        assert_eq!(
            r("more to the left"),
            Some(FollowUp::Toward("move it a bit to the left".into()))
        );
        assert_eq!(r("undo that"), Some(FollowUp::Undo));
        assert_eq!(r("put it back"), Some(FollowUp::Back(Which::Last)));
        assert_eq!(r("back where it was"), Some(FollowUp::Back(Which::Last)));
        assert_eq!(
            r("put the armchair back where it was"),
            Some(FollowUp::Back(Which::Named("the armchair".into())))
        );
        assert_eq!(r("and the mug too"), Some(FollowUp::Also("the mug".into())));
        assert_eq!(
            r("do the same with the coffee table"),
            Some(FollowUp::Also("the coffee table".into()))
        );
        assert_eq!(
            r("same for the chairs"),
            Some(FollowUp::Also("the chairs".into()))
        );
        assert_eq!(
            r("the bowl as well"),
            Some(FollowUp::Also("the bowl".into()))
        );
        assert_eq!(r("ok, again"), Some(FollowUp::Repeat(Amount::Times(1.0))));
        assert_eq!(
            r("no, the other one"),
            Some(FollowUp::Instead("the other one".into()))
        );
        assert_eq!(
            r("no, on the shelf"),
            Some(FollowUp::InsteadPlace("on the shelf".into()))
        );
        assert_eq!(
            read("the left one", true),
            Some(FollowUp::Instead("the left one".into()))
        );
    }

    #[test]
    fn a_bare_number_takes_the_unit_the_last_instruction_said() {
        let metres = |a: Option<Amount>| match a {
            Some(Amount::Metres(m)) => Some((m * 1e6).round() / 1e6),
            _ => None,
        };
        assert_eq!(
            metres(in_unit_of(5.0, "move the sofa 20 cm left")),
            Some(0.05)
        );
        assert_eq!(metres(in_unit_of(2.0, "push it 20cm back")), Some(0.02));
        assert_eq!(
            metres(in_unit_of(1.0, "move the rug 2 feet left")),
            Some(0.3048)
        );
        assert_eq!(
            in_unit_of(15.0, "turn the chair 30 degrees"),
            Some(Amount::Degrees(15.0))
        );
        assert_eq!(in_unit_of(5.0, "put the lamp on the table"), None);
    }

    #[test]
    fn each_kind_is_read_said_other_ways() {
        use FollowUp::*;
        let r = |t: &str| read(t, false);
        let cases: Vec<(&str, FollowUp)> = vec![
            ("move it a bit more", Repeat(Amount::Bit(1.0))),
            ("push them further", Repeat(Amount::Times(1.0))),
            ("another 10 cm", Repeat(Amount::Metres(0.1))),
            ("20cm more please", Repeat(Amount::Metres(0.2))),
            ("15 more degrees", Repeat(Amount::Degrees(15.0))),
            ("that's too far", Repeat(Amount::Times(-0.5))),
            ("turn it some more", Repeat(Amount::Bit(1.0))),
            ("and again", Repeat(Amount::Times(1.0))),
            ("do the same again", Repeat(Amount::Times(1.0))),
            ("repeat the last move", Repeat(Amount::Times(1.0))),
            (
                "actually, onto the sofa",
                InsteadPlace("onto the sofa".into()),
            ),
            (
                "next to the sofa instead",
                InsteadPlace("next to the sofa".into()),
            ),
            ("no, left", InsteadWay("left".into())),
            ("same again but to the right", SameWay("right".into())),
            ("wrong, put it back", Back(Which::Last)),
            ("that's not right, undo", Undo),
            ("reverse that", Undo),
            ("go back one step", Undo),
            ("return it to where it started", Back(Which::Last)),
            ("original position please", Back(Which::Last)),
            ("another 5", Repeat(Amount::Bare(5.0))),
            ("5 more", Repeat(Amount::Bare(5.0))),
            ("an inch more", Repeat(Amount::Metres(0.0254))),
            ("another inch", Repeat(Amount::Metres(0.0254))),
            ("twice more", Repeat(Amount::Times(2.0))),
            ("do it 3 more times", Repeat(Amount::Times(3.0))),
            ("half as much again", Repeat(Amount::Times(0.5))),
            ("half as far", Repeat(Amount::Times(-0.5))),
            ("not far enough", Repeat(Amount::Bit(1.0))),
            ("still not enough", Repeat(Amount::Bit(1.0))),
            ("the same distance again", Repeat(Amount::Times(1.0))),
            ("little bit more", Repeat(Amount::Bit(1.0))),
            ("again, but left", SameWay("left".into())),
            ("do the same this time backwards", SameWay("backwards".into())),
            ("same distance to the left", SameWay("left".into())),
            ("no, to the left", InsteadWay("left".into())),
            (
                "put it on the table instead",
                InsteadPlace("on the table".into()),
            ),
            ("move the lamp instead", Instead("the lamp".into())),
            (
                "not on the shelf, on the table",
                InsteadPlace("on the table".into()),
            ),
            ("no no, on the shelf", InsteadPlace("on the shelf".into())),
            (
                "on the shelf, not the table",
                InsteadPlace("on the shelf".into()),
            ),
            ("not the sofa, the armchair", Instead("the armchair".into())),
            ("the armchair, not the sofa", Instead("the armchair".into())),
            ("the other one", Instead("the other one".into())),
            ("wrong chair", Instead("the other chair".into())),
            ("and the lamp", Also("the lamp".into())),
            ("and the left lamp too", Also("the left lamp".into())),
            ("do the lamp too", Also("the lamp".into())),
            ("now the table", Also("the table".into())),
            ("same goes for the lamp", Also("the lamp".into())),
            ("undo the last move", Undo),
            ("undo what you just did", Undo),
            ("scratch that", Undo),
            ("move it back to where it was", Back(Which::Last)),
            ("back to where it was", Back(Which::Last)),
            ("reset the lamp", Back(Which::Named("the lamp".into()))),
            ("go on", Repeat(Amount::Times(1.0))),
            ("further still", Repeat(Amount::Times(1.0))),
            ("yes, more", Repeat(Amount::Times(1.0))),
            ("ok good, now a little further", Repeat(Amount::Bit(1.0))),
            ("not that far", Repeat(Amount::Times(-0.5))),
            ("twice that", Repeat(Amount::Times(1.0))),
            ("double the distance", Repeat(Amount::Times(1.0))),
            ("a few more cm", Repeat(Amount::Metres(0.03))),
            ("a bit to the left", Toward("move it a bit to the left".into())),
            ("and 10 cm up", Toward("move it 10 cm up".into())),
            ("15 degrees clockwise", Toward("turn it 15 degrees clockwise".into())),
            ("nah, undo", Undo),
            ("revert", Undo),
            ("undo both", UndoMany(Steps::Last(2))),
            ("undo the last three changes", UndoMany(Steps::Last(3))),
            ("undo twice", UndoMany(Steps::Last(2))),
            ("undo everything", UndoMany(Steps::All)),
            ("start over", UndoMany(Steps::All)),
            ("no, put it back", Back(Which::Last)),
            ("put it where it was", Back(Which::Last)),
            ("go back", Back(Which::Last)),
            ("put the other one back too", Back(Which::Other)),
            ("put them both back", Back(Which::Both)),
            ("put everything back where it was", Back(Which::All)),
            ("the lamp back where it was", Back(Which::Named("the lamp".into()))),
            ("put it back the way it was", Back(Which::Last)),
            ("put it back to its previous position", Back(Which::Last)),
            ("back to how it was before", Back(Which::Last)),
            ("restore its position", Back(Which::Last)),
            ("put back the lamp", Back(Which::Named("the lamp".into()))),
            ("move it to where it was", Back(Which::Last)),
            ("slide the lamp to its original spot", Back(Which::Named("the lamp".into()))),
            ("put the ottoman back in its place", Back(Which::Named("the ottoman".into()))),
            ("go back to how it was", Back(Which::Last)),
            (
                "move it back",
                Unclear("\"move it back\" reads two ways: say \"put it back\" to return it where it was, or how far to move it backwards (\"move it back 50 cm\")".into()),
            ),
            ("wrong one", Instead("the other one".into())),
            ("not that one", Instead("the other one".into())),
            ("no, not that speaker", Instead("the other speaker".into())),
            ("the right one", Instead("the right one".into())),
            ("wrong table, the tv stand", Instead("the tv stand".into())),
            ("no, the tv stand", Instead("the tv stand".into())),
            ("rather on the tv stand", InsteadPlace("on the tv stand".into())),
            ("on the tv stand instead", InsteadPlace("on the tv stand".into())),
            (
                "do it to the other one instead",
                Instead("the other one".into()),
            ),
        ];
        for (text, expected) in cases {
            assert_eq!(r(text), Some(expected), "{text}");
        }
    }

    #[test]
    fn whole_instructions_are_not_follow_ups() {
        for t in [
            "move the chair back",
            "move the chair back 50 cm",
            "put the mug on the shelf",
            "move it 10 cm to the right",
            "and move the lamp left",
            "move the lamp 10 cm more to the left",
            "turn it around",
            "by 20 cm",
            "and the lamp left",
            "move the lamp back to the wall",
            "cancel",
            "next to the sofa, put the lamp",
            "undo moving the lamp",
            "move the lamp, not the sofa",
            "move the lamp a bit more to the left",
            "no, move the lamp left",
            "turn the chair around",
            "move the book to the first shelf",
            "put it back in the first drawer",
            "move it to the left",
            "go back 10 cm",
        ] {
            assert_eq!(read(t, false), None, "{t}");
        }
        assert_eq!(read("move the lamp left", true), None);
    }
}

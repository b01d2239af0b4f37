//! The built-in offline translator (`--llm offline`, the default): templated English to
//! the same CGA reply a language model would give, with no network and no model.
//!
//! It is a small grammar, not a list of sentences: a tokeniser; a clause splitter (`and`,
//! `then`, commas — but not the `and` of `between X2 and X3`); phrase patterns with
//! synonyms for verbs, directions, relations, amounts and units; and a semantic layer that
//! writes expressions with only `X_i.min/.max/.center/.size`, `e1 e2 e3`, `T`, `R`, `D` —
//! never the scene's numbers, so its answers are scene-independent and cacheable like a
//! model's. The reply then goes through the same parser and evaluator as a model's.
//! Instructions it cannot read fail with the part it could not read quoted.

use crate::llm::{Message, Usage};
use crate::pipeline::prompts::System;
use crate::pipeline::template::Templated;
use crate::pipeline::translate::{Exchange, TranslateError, Translation, Translator};
use crate::scene::Scene;
use std::collections::BTreeMap;
use std::time::Instant;

/// Gap left between objects placed next to each other, in metres.
const GAP: f64 = 0.05;

/// The offline translator.
#[derive(Clone, Debug, Default)]
pub struct OfflineTranslator;

impl OfflineTranslator {
    /// The translator.
    pub fn new() -> Self {
        Self
    }
}

impl Translator for OfflineTranslator {
    fn name(&self) -> String {
        "offline".into()
    }

    fn system(&self) -> System {
        System::Cga
    }

    fn translate(
        &self,
        templated: &Templated,
        scene: &Scene,
    ) -> Result<Translation, TranslateError> {
        let started = Instant::now();
        let reply = reply_for(&templated.query, templated.objects.len())
            .map_err(TranslateError::not_understood)?;
        let answers = System::Cga
            .parse_reply(&reply, templated, scene)
            .map_err(|e| TranslateError::model(format!("the offline translator wrote an invalid answer ({e}); please report this instruction")))?;
        let exchange = Exchange {
            messages: vec![Message::new(
                "user",
                format!("Instruction: {}", templated.query),
            )],
            reply,
            elapsed_ms: started.elapsed().as_secs_f64() * 1000.0,
            usage: Usage::default(),
            error: None,
            cached: false,
        };
        Ok(Translation {
            answers,
            exchanges: vec![exchange],
            retries: 0,
            cache_hit: false,
            elapsed: started.elapsed(),
        })
    }
}

/// A token of an instruction.
#[derive(Clone, Debug, PartialEq)]
enum Token {
    Word(String),
    Number(f64),
    Variable(usize),
    Separator,
}

fn tokenize(query: &str) -> Vec<Token> {
    let mut tokens = Vec::new();
    let lower = query
        .to_lowercase()
        .replace('°', " degrees ")
        .replace('%', " percent ");
    let mut word = String::new();
    let flush = |word: &mut String, tokens: &mut Vec<Token>| {
        if word.is_empty() {
            return;
        }
        let w = std::mem::take(word);
        if let Some(n) = w
            .strip_prefix('x')
            .and_then(|d| d.parse::<usize>().ok())
            .filter(|n| *n >= 1)
        {
            tokens.push(Token::Variable(n - 1));
        } else if let Some((a, b)) = w
            .split_once('/')
            .and_then(|(a, b)| Some((a.parse::<f64>().ok()?, b.parse::<f64>().ok()?)))
        {
            tokens.push(Token::Number(a / b));
        } else if let Ok(n) = w.parse::<f64>() {
            tokens.push(Token::Number(n));
        } else if let Some((n, unit)) = split_number_unit(&w) {
            tokens.push(Token::Number(n));
            tokens.push(Token::Word(unit));
        } else {
            tokens.push(Token::Word(w));
        }
    };
    for c in lower.chars() {
        if c.is_alphanumeric() || c == '.' || c == '/' || (c == '-' && word.is_empty()) {
            word.push(c);
        } else {
            flush(&mut word, &mut tokens);
            if matches!(c, ',' | ';') {
                tokens.push(Token::Separator);
            }
        }
    }
    flush(&mut word, &mut tokens);
    // A trailing period of a sentence sticks to the last word; strip it.
    tokens
        .into_iter()
        .map(|t| match t {
            Token::Word(w) if w.ends_with('.') && w.len() > 1 => {
                Token::Word(w.trim_end_matches('.').to_string())
            }
            other => other,
        })
        .collect()
}

/// `2m` → (2, "m"), `90deg` → (90, "deg").
fn split_number_unit(w: &str) -> Option<(f64, String)> {
    let split = w.find(|c: char| c.is_alphabetic())?;
    let (n, unit) = w.split_at(split);
    Some((n.parse().ok()?, unit.to_string()))
}

fn number_word(w: &str) -> Option<f64> {
    Some(match w {
        "a" | "an" | "one" | "once" => 1.0,
        "two" | "twice" | "double" => 2.0,
        "three" | "thrice" | "triple" => 3.0,
        "four" => 4.0,
        "five" => 5.0,
        "six" => 6.0,
        "seven" => 7.0,
        "eight" => 8.0,
        "nine" => 9.0,
        "ten" => 10.0,
        "twenty" => 20.0,
        "thirty" => 30.0,
        "forty" | "fourty" => 40.0,
        "forty-five" => 45.0,
        "fifty" => 50.0,
        "sixty" => 60.0,
        "ninety" => 90.0,
        "hundred" => 100.0,
        "half" => 0.5,
        "quarter" => 0.25,
        "third" => 1.0 / 3.0,
        _ => return None,
    })
}

/// Length units to metres.
fn length_unit(w: &str) -> Option<f64> {
    Some(match w {
        "m" | "meter" | "meters" | "metre" | "metres" | "unit" | "units" => 1.0,
        "cm" | "centimeter" | "centimeters" | "centimetre" | "centimetres" => 0.01,
        "mm" | "millimeter" | "millimeters" | "millimetre" | "millimetres" => 0.001,
        "ft" | "foot" | "feet" => 0.3048,
        "in" | "inch" | "inches" => 0.0254,
        _ => return None,
    })
}

/// Angle units to degrees.
fn angle_unit(w: &str) -> Option<f64> {
    Some(match w {
        "degree" | "degrees" | "deg" | "degs" => 1.0,
        "radian" | "radians" | "rad" | "rads" => 180.0 / std::f64::consts::PI,
        "turn" | "turns" | "revolution" | "revolutions" => 360.0,
        _ => return None,
    })
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Action {
    Move,
    Rotate,
    Scale,
    Swap,
    Align,
}

/// What a clause asks of one variable.
#[derive(Clone, Debug, PartialEq)]
enum Step {
    /// A translation by this vector expression (inside `T(...)`).
    Translate(String),
    /// A rotor or dilator expression, applied about the pivot.
    Turn(String),
}

impl Step {
    /// The vector of a translation.
    fn translation(&self) -> Option<&str> {
        match self {
            Step::Translate(v) => Some(v),
            Step::Turn(_) => None,
        }
    }

    /// The expression of a turn or scale.
    fn turn(&self) -> Option<&str> {
        match self {
            Step::Turn(e) => Some(e),
            Step::Translate(_) => None,
        }
    }
}

/// A direction as (axis index 0..2, sign).
fn direction(w: &str) -> Option<(usize, f64)> {
    Some(match w {
        "left" | "leftward" | "leftwards" | "west" => (0, -1.0),
        "right" | "rightward" | "rightwards" | "east" => (0, 1.0),
        "up" | "upward" | "upwards" | "higher" | "above" => (1, 1.0),
        "down" | "downward" | "downwards" | "lower" => (1, -1.0),
        "forward" | "forwards" | "front" | "ahead" | "south" => (2, 1.0),
        "back" | "backward" | "backwards" | "rear" | "north" => (2, -1.0),
        _ => return None,
    })
}

const AXIS: [&str; 3] = ["e1", "e2", "e3"];

fn verb(w: &str) -> Option<(Action, Option<(usize, f64)>)> {
    Some(match w {
        "move" | "shift" | "push" | "slide" | "nudge" | "translate" | "put" | "place" | "set"
        | "bring" | "take" | "position" | "relocate" | "carry" | "drag" | "pull" | "stack"
        | "pile" | "sit" | "stand" => (Action::Move, None),
        "swap" | "exchange" | "switch" | "interchange" => (Action::Swap, None),
        "align" | "line" => (Action::Align, None),
        "raise" | "lift" | "elevate" => (Action::Move, Some((1, 1.0))),
        "lower" | "drop" | "sink" => (Action::Move, Some((1, -1.0))),
        "rotate" | "turn" | "spin" | "twist" | "revolve" | "flip" | "swivel" | "pivot" => {
            (Action::Rotate, None)
        }
        "scale" | "resize" | "enlarge" | "grow" | "shrink" | "double" | "halve" | "triple"
        | "magnify" | "reduce" | "make" => (Action::Scale, None),
        _ => return None,
    })
}

/// Reads an instruction with variables into a CGA reply.
pub fn reply_for(query: &str, variables: usize) -> Result<String, String> {
    let tokens = tokenize(query);
    let clauses = split_clauses(&tokens);
    let mut steps: BTreeMap<usize, Vec<Step>> = BTreeMap::new();
    let mut last_subjects: Vec<usize> = Vec::new();
    let mut last_action: Option<Action> = None;
    let mut last_steps: Vec<Step> = Vec::new();
    for clause in clauses {
        if clause.is_empty() {
            continue;
        }
        let produced = match repeat_previous(&clause, &last_steps, &last_subjects) {
            Some(repeated) => repeated,
            None => read_clause(&clause, &mut last_subjects, &mut last_action, &steps)?,
        };
        if let Some(&(first, _)) = produced.first() {
            last_steps = produced
                .iter()
                .filter(|(v, _)| *v == first)
                .map(|(_, s)| s.clone())
                .collect();
        }
        for (var, step) in produced {
            steps.entry(var).or_default().push(step);
        }
    }
    if steps.is_empty() {
        return Err(not_understood(query));
    }
    if let Some(v) = steps.keys().find(|&&v| v >= variables) {
        return Err(format!(
            "the instruction names X{} but only {} objects are quoted",
            v + 1,
            variables
        ));
    }
    // A list acts in the pivot frame of the object's original place: turns and scales go
    // first (about the object itself), then the translations (which commute).
    let entries: Vec<String> = steps
        .iter()
        .map(|(v, list)| {
            let mut exprs: Vec<String> = list
                .iter()
                .filter_map(|s| s.turn().map(str::to_string))
                .collect();
            let moves: Vec<&str> = list.iter().filter_map(Step::translation).collect();
            if !moves.is_empty() {
                exprs.push(format!("T({})", moves.join(" + ")));
            }
            if exprs.len() == 1 {
                format!("\"X{}\": \"{}\"", v + 1, exprs[0])
            } else {
                let items: Vec<String> = exprs.iter().map(|e| format!("\"{e}\"")).collect();
                format!("\"X{}\": [{}]", v + 1, items.join(", "))
            }
        })
        .collect();
    Ok(format!("{{{}}}", entries.join(", ")))
}

/// "do the same for X2", "move X2 the other way", "mirror that for X2": the previous
/// clause's steps, repeated, reversed or mirrored left–right for the variables named.
fn repeat_previous(
    clause: &[Token],
    last: &[Step],
    last_subjects: &[usize],
) -> Option<Vec<(usize, Step)>> {
    let words = word_list(clause);
    let has = |w: &str| words.contains(&w);
    let same = has("same") || has("likewise") || has("too") || has("also");
    let opposite = has("opposite") || (has("other") && has("way")) || has("reverse");
    let mirror = has("mirror") || has("mirrored") || has("symmetrically");
    if last.is_empty()
        || !(same || opposite || mirror)
        || words.iter().any(|w| direction(w).is_some())
    {
        return None;
    }
    let mut subjects: Vec<usize> = clause
        .iter()
        .filter_map(|t| {
            if let Token::Variable(v) = t {
                Some(*v)
            } else {
                None
            }
        })
        .collect();
    let single = subjects.len() == 1;
    subjects.retain(|v| !last_subjects.contains(v) || single);
    if subjects.is_empty() {
        return None;
    }
    let transform = |step: &Step| -> Step {
        match step {
            Step::Translate(v) if opposite => Step::Translate(format!("-1 * ({v})")),
            Step::Translate(v) if mirror => {
                Step::Translate(format!("({v}) - 2 * (({v}) | e1) * e1"))
            }
            Step::Turn(e) if opposite || mirror => Step::Turn(format!("~{e}")),
            other => other.clone(),
        }
    };
    // Relations name their subject's own box (X1.min …): repeat only plain moves and turns.
    if last
        .iter()
        .any(|s| matches!(s, Step::Translate(v) if v.contains('X')))
    {
        return None;
    }
    Some(
        subjects
            .iter()
            .flat_map(|&s| last.iter().map(move |step| (s, transform(step))))
            .collect(),
    )
}

/// `X2.max`, shifted by what earlier clauses of the instruction moved X2 by.
fn boxed(var: usize, attribute: &str, steps: &BTreeMap<usize, Vec<Step>>) -> String {
    let moves: Vec<&str> = steps
        .get(&var)
        .into_iter()
        .flatten()
        .filter_map(Step::translation)
        .collect();
    if moves.is_empty() {
        format!("X{}.{attribute}", var + 1)
    } else {
        format!("(X{}.{attribute} + {})", var + 1, moves.join(" + "))
    }
}

fn not_understood(part: &str) -> String {
    format!(
        "the offline translator could not read \"{}\"; rephrase it, or use a language model with --llm openai:MODEL or --llm ollama:MODEL",
        part.trim()
    )
}

/// The words of a token list, without numbers, variables and separators.
fn word_list(tokens: &[Token]) -> Vec<&str> {
    tokens
        .iter()
        .filter_map(|t| {
            if let Token::Word(w) = t {
                Some(w.as_str())
            } else {
                None
            }
        })
        .collect()
}

fn words_of(clause: &[Token]) -> String {
    clause
        .iter()
        .map(|t| match t {
            Token::Word(w) => w.clone(),
            Token::Number(n) => format!("{n}"),
            Token::Variable(v) => format!("X{}", v + 1),
            Token::Separator => ",".into(),
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// Words that may stand between variables of a list: `the X1 and the X2`.
fn filler(w: &str) -> bool {
    matches!(
        w,
        "the"
            | "a"
            | "an"
            | "both"
            | "all"
            | "of"
            | "positions"
            | "position"
            | "places"
            | "place"
            | "up"
    )
}

/// Splits at `and`, `then`, `after that`, commas — keeping `between X2 and X3`, `swap X1
/// and X2` and subject lists such as `move both X1 and X2 up` together.
fn split_clauses(tokens: &[Token]) -> Vec<Vec<Token>> {
    let word = |k: usize| match tokens.get(k) {
        Some(Token::Word(w)) => Some(w.as_str()),
        _ => None,
    };
    // The variable next to position i, skipping articles, in direction `step`.
    let var_near = |i: usize, step: isize| -> bool {
        let mut k = i as isize + step;
        while k >= 0 && (k as usize) < tokens.len() {
            match &tokens[k as usize] {
                Token::Variable(_) => return true,
                Token::Word(w) if matches!(w.as_str(), "the" | "a" | "an") => k += step,
                _ => return false,
            }
        }
        false
    };
    let mut clauses = vec![Vec::new()];
    for (i, t) in tokens.iter().enumerate() {
        let is_and = word(i) == Some("and");
        let is_list_mark = is_and || matches!(t, Token::Separator);
        if is_list_mark && var_near(i, -1) && var_near(i, 1) {
            let current = clauses.last().expect("one clause at least");
            let words = word_list(current);
            let list_context = words
                .iter()
                .any(|w| matches!(*w, "between" | "swap" | "exchange" | "switch"));
            // After the verb only articles and variables so far: a list of subjects.
            let verb_at = words.iter().position(|w| verb(w).is_some());
            let only_subjects = match verb_at {
                Some(v) => words[v + 1..].iter().all(|w| filler(w)),
                None => words.iter().all(|w| filler(w)),
            };
            if list_context || only_subjects {
                clauses.last_mut().expect("one clause").push(t.clone());
                continue;
            }
        }
        let is_break = is_and
            || matches!(t, Token::Separator)
            || matches!(word(i), Some("then" | "finally" | "afterwards"));
        if is_break {
            clauses.push(Vec::new());
            continue;
        }
        clauses.last_mut().expect("one clause").push(t.clone());
    }
    clauses.retain(|c| !c.is_empty() && !c.iter().all(|t| matches!(t, Token::Word(w) if w == "it" || w == "them" || w == "after" || w == "that")));
    clauses
}

fn read_clause(
    clause: &[Token],
    last_subjects: &mut Vec<usize>,
    last_action: &mut Option<Action>,
    steps: &BTreeMap<usize, Vec<Step>>,
) -> Result<Vec<(usize, Step)>, String> {
    let text = words_of(clause);
    let words: Vec<&str> = clause
        .iter()
        .map(|t| {
            if let Token::Word(w) = t {
                w.as_str()
            } else {
                ""
            }
        })
        .collect();
    let has = |w: &str| words.contains(&w);
    let vars: Vec<(usize, usize)> = clause
        .iter()
        .enumerate()
        .filter_map(|(i, t)| {
            if let Token::Variable(v) = t {
                Some((i, *v))
            } else {
                None
            }
        })
        .collect();

    let verb_at = words.iter().position(|w| verb(w).is_some());
    let (mut action, verb_direction) = match verb_at.and_then(|i| verb(words[i])) {
        Some(v) => v,
        None => match *last_action {
            Some(a) => (a, None),
            None => return Err(not_understood(&text)),
        },
    };
    if verb_at.is_some_and(|i| words[i] == "make") && !words.iter().any(|w| size_word(w).is_some())
    {
        return Err(not_understood(&text));
    }
    // "turn X1 to face X2", "rotate X1 so that it faces X2".
    let facing = words
        .iter()
        .position(|w| matches!(*w, "face" | "faces" | "facing"))
        .filter(|&i| vars.iter().any(|(j, _)| *j > i));
    if facing.is_some() {
        action = Action::Rotate;
    }
    *last_action = Some(action);

    let at = |var: usize, attribute: &str| boxed(var, attribute, steps);
    match action {
        Action::Swap => {
            if vars.len() < 2 {
                return Err(not_understood(&text));
            }
            let (a, b) = (vars[0].1, vars[1].1);
            *last_subjects = vec![a, b];
            let to = |from: usize, to: usize| {
                let (f, t) = (format!("X{}", from + 1), format!("X{}", to + 1));
                format!("((({t}.center - {f}.center) | e1) * e1 + (({t}.center - {f}.center) | e3) * e3 + (({t}.min - {f}.min) | e2) * e2)")
            };
            return Ok(vec![
                (a, Step::Translate(to(a, b))),
                (b, Step::Translate(to(b, a))),
            ]);
        }
        Action::Align if vars.len() >= 3 || (vars.len() >= 2 && !has("with") && !has("to")) => {
            // "line up X1, X2 and X3", "arrange them in a row": each after the first goes to
            // the right of the one before, level with and centred on the first.
            let row: Vec<usize> = vars.iter().map(|(_, v)| *v).collect();
            *last_subjects = row.clone();
            let mut local = steps.clone();
            let mut out = Vec::new();
            for pair in row.windows(2) {
                let (prev, s) = (pair[0], pair[1]);
                let first = row[0];
                let v = format!(
                    "(({} | e1) + {} - (X{n}.min | e1)) * e1 + (({} - X{n}.center) | e3) * e3 + (({} - X{n}.min) | e2) * e2",
                    boxed(prev, "max", &local),
                    fmt(GAP),
                    boxed(first, "center", &local),
                    boxed(first, "min", &local),
                    n = s + 1
                );
                local.entry(s).or_default().push(Step::Translate(v.clone()));
                out.push((s, Step::Translate(v)));
            }
            return Ok(out);
        }
        Action::Align => {
            if vars.len() < 2 {
                return Err(not_understood(&text));
            }
            let (a, b) = (vars[0].1, vars[1].1);
            *last_subjects = vec![a];
            let axis = named_axis(&words).unwrap_or(0);
            let e = AXIS[axis];
            return Ok(vec![(
                a,
                Step::Translate(format!(
                    "(({} - X{}.center) | {e}) * {e}",
                    at(b, "center"),
                    a + 1
                )),
            )]);
        }
        _ => {}
    }

    // Subjects: the variables before a relation word that an object follows; for turns
    // and scales every variable before "to face", or all of them.
    let relation_at = words
        .iter()
        .enumerate()
        .position(|(i, w)| is_relation_word(w) && vars.iter().any(|(j, _)| *j > i));
    let cut = match action {
        Action::Move => relation_at,
        _ => facing,
    };
    let mut subjects: Vec<usize> = vars
        .iter()
        .filter(|(i, _)| cut.is_none_or(|r| *i < r))
        .map(|(_, v)| *v)
        .collect();
    if subjects.is_empty() {
        // "it", "them", "both", or nothing: the objects named last.
        subjects = last_subjects.clone();
    }
    if subjects.is_empty() {
        return Err(not_understood(&text));
    }
    *last_subjects = subjects.clone();
    let objects: Vec<usize> = vars
        .iter()
        .filter(|(i, _)| cut.is_some_and(|r| *i > r))
        .map(|(_, v)| *v)
        .collect();

    let mut out = Vec::new();
    match action {
        Action::Move if relation_at.is_none() && room_phrase(&words).is_some() => {
            let place = room_phrase(&words).expect("checked");
            for &s in &subjects {
                out.push((s, Step::Translate(room_target(place, &words, s))));
            }
        }
        Action::Move
            if relation_at.is_some_and(|r| {
                matches!(words[r], "from" | "toward" | "towards")
                    || words[..r]
                        .iter()
                        .any(|w| matches!(*w, "away" | "closer" | "nearer"))
            }) =>
        {
            let target = *objects.first().ok_or_else(|| not_understood(&text))?;
            let amount = find_amount(clause, Kind::Length);
            for &s in &subjects {
                let d = format!("({} - X{}.center)", at(target, "center"), s + 1);
                let flat = format!("(({d} | e1) * e1 + ({d} | e3) * e3)");
                let away = has("away") || (has("from") && !has("closer"));
                let v = match (away, amount) {
                    (true, a) => format!("-{} * {flat} / abs({flat})", fmt(a.unwrap_or(1.0))),
                    (false, Some(a)) => format!("{} * {flat} / abs({flat})", fmt(a)),
                    // "closer to X2" with no amount: halve the distance.
                    (false, None) => format!("0.5 * {flat}"),
                };
                out.push((s, Step::Translate(v)));
            }
        }
        Action::Move => {
            if let Some(r) = relation_at {
                for &s in &subjects {
                    let v = relation(&words[r..], s, &objects, steps)
                        .ok_or_else(|| not_understood(&text))?;
                    out.push((s, Step::Translate(v)));
                }
            } else {
                let (axis, sign) = find_direction(&words)
                    .or(verb_direction)
                    .ok_or_else(|| not_understood(&text))?;
                let amount = find_amount(clause, Kind::Length).unwrap_or(1.0);
                for &s in &subjects {
                    out.push((
                        s,
                        Step::Translate(format!("{} * {}", fmt(sign * amount), AXIS[axis])),
                    ));
                }
            }
        }
        Action::Rotate => {
            if let (Some(_), Some(&target)) = (facing, objects.first()) {
                for &s in &subjects {
                    // Turn about the vertical so that the front (+Z) points at the target;
                    // +θ about +Y takes +Z toward +X, so θ = atan2(dx, dz).
                    let d = format!("({} - X{}.center)", at(target, "center"), s + 1);
                    out.push((
                        s,
                        Step::Turn(format!("R(atan2({d} | e1, {d} | e3), e3, e1)")),
                    ));
                }
                return Ok(out);
            }
            let amount = find_amount(clause, Kind::Angle);
            // "turn it around" and "flip it" with no amount are half turns.
            let mut degrees = match amount {
                Some(a) => a,
                None if has("around") || has("flip") => 180.0,
                None => 90.0,
            };
            let counter = has("counterclockwise")
                || has("anticlockwise")
                || has("counter")
                || has("anti")
                || has("ccw");
            if (has("clockwise") || has("cw")) && !counter {
                degrees = -degrees;
            }
            if has("left") && !has("clockwise") {
                degrees = degrees.abs();
            }
            if has("right") && !has("clockwise") {
                degrees = -degrees.abs();
            }
            let plane = rotation_plane(&words);
            for &s in &subjects {
                out.push((
                    s,
                    Step::Turn(format!("R({} * pi / 180, {})", fmt(degrees), plane)),
                ));
            }
        }
        Action::Scale => {
            let factor = scale_factor(clause, &words).ok_or_else(|| not_understood(&text))?;
            for &s in &subjects {
                out.push((s, Step::Turn(format!("D({})", fmt(factor)))));
            }
        }
        Action::Swap | Action::Align => unreachable!("handled above"),
    }
    Ok(out)
}

/// A place in the room an instruction names.
#[derive(Clone, Copy, Debug, PartialEq)]
enum RoomPlace {
    Centre,
    Corner,
    Wall,
}

fn room_phrase(words: &[&str]) -> Option<RoomPlace> {
    let has = |w: &str| words.contains(&w);
    if has("corner") {
        Some(RoomPlace::Corner)
    } else if has("wall") || has("walls") {
        Some(RoomPlace::Wall)
    } else if (has("centre") || has("center") || has("middle"))
        && (has("room") || !words.contains(&"of"))
    {
        Some(RoomPlace::Centre)
    } else {
        None
    }
}

/// The translation to a place in the room, written with the `room` variable. Walls and
/// corners keep a 2 cm clearance; "the wall" or "the corner" with no side is the nearest.
fn room_target(place: RoomPlace, words: &[&str], s: usize) -> String {
    let a = format!("X{}", s + 1);
    let has = |w: &str| words.contains(&w);
    let clear = "0.02";
    let centre = |e: &str| format!("((room.center - {a}.center) | {e}) * {e}");
    // Flush against the min or max wall along an axis.
    let to_min = |e: &str| format!("(((room.min | {e}) + {clear} - ({a}.min | {e})) * {e})");
    let to_max = |e: &str| format!("(((room.max | {e}) - {clear} - ({a}.max | {e})) * {e})");
    // 1 when the object is on the max side of the room's centre along e, else 0.
    let side_p = |e: &str| {
        let d = format!("((({a}.center - room.center) | {e}) + 1e-12)");
        format!("((1 + {d} / abs({d})) / 2)")
    };
    let nearest = |e: &str| {
        format!(
            "({p} * {} + (1 - {p}) * {})",
            to_max(e),
            to_min(e),
            p = side_p(e)
        )
    };
    let x = if has("left") {
        Some(to_min("e1"))
    } else if has("right") {
        Some(to_max("e1"))
    } else {
        None
    };
    let z = if has("back") || has("rear") || has("far") {
        Some(to_min("e3"))
    } else if has("front") || has("near") {
        Some(to_max("e3"))
    } else {
        None
    };
    match place {
        RoomPlace::Centre => format!("{} + {}", centre("e1"), centre("e3")),
        RoomPlace::Corner => format!(
            "{} + {}",
            x.unwrap_or_else(|| nearest("e1")),
            z.unwrap_or_else(|| nearest("e3"))
        ),
        RoomPlace::Wall => match (x, z) {
            (Some(x), _) => x,
            (None, Some(z)) => z,
            (None, None) => {
                // The nearer of the nearest x wall and the nearest z wall.
                let gap = |e: &str| {
                    format!("(((room.max - room.min) | {e}) / 2 - abs(({a}.center - room.center) | {e}))")
                };
                let q = format!(
                    "((1 + ({gz} - {gx} + 1e-12) / abs({gz} - {gx} + 1e-12)) / 2)",
                    gx = gap("e1"),
                    gz = gap("e3")
                );
                format!("{q} * {} + (1 - {q}) * {}", nearest("e1"), nearest("e3"))
            }
        },
    }
}

/// "along the x axis", "on the z axis", "horizontally" (x), "vertically" (y).
fn named_axis(words: &[&str]) -> Option<usize> {
    let at = words.iter().position(|w| *w == "axis");
    if let Some(i) = at {
        if let Some(name) = i.checked_sub(1).and_then(|k| words.get(k)) {
            return match *name {
                "x" | "e1" => Some(0),
                "y" | "e2" => Some(1),
                "z" | "e3" => Some(2),
                _ => None,
            };
        }
    }
    if words.contains(&"vertically") || words.contains(&"height") {
        return Some(1);
    }
    if words
        .iter()
        .any(|w| matches!(*w, "depth" | "front" | "forward" | "back"))
    {
        return Some(2);
    }
    None
}

fn fmt(x: f64) -> String {
    let r = (x * 1e9).round() / 1e9;
    if r.fract() == 0.0 {
        format!("{}", r as i64)
    } else {
        format!("{r}")
    }
}

#[derive(Clone, Copy, PartialEq)]
enum Kind {
    Length,
    Angle,
}

/// The amount of a clause: a number (or number word, or fraction) with an optional unit.
fn find_amount(clause: &[Token], kind: Kind) -> Option<f64> {
    for (i, t) in clause.iter().enumerate() {
        let (value, next) = match t {
            Token::Number(n) => (*n, i + 1),
            Token::Word(w) => match number_word(w) {
                // "a" and "an" count only before a unit ("a metre", "a quarter turn").
                Some(n) if (w == "a" || w == "an") => match clause.get(i + 1) {
                    Some(Token::Word(u))
                        if (kind == Kind::Length && length_unit(u).is_some())
                            || (kind == Kind::Angle && angle_unit(u).is_some()) =>
                    {
                        (n, i + 1)
                    }
                    Some(Token::Word(q)) if number_word(q).is_some() && q != "a" => continue,
                    _ => continue,
                },
                Some(n)
                    if !matches!(
                        w.as_str(),
                        "double" | "twice" | "triple" | "thrice" | "once"
                    ) =>
                {
                    (n, i + 1)
                }
                _ => continue,
            },
            _ => continue,
        };
        // "half a turn", "a quarter turn", "half turn".
        let mut value = value;
        let mut k = next;
        if let Some(Token::Word(w)) = clause.get(k) {
            if let Some(m) = number_word(w).filter(|_| w != "a" && w != "an") {
                value *= m;
                k += 1;
            } else if w == "a" || w == "an" {
                k += 1;
            }
        }
        let unit = match clause.get(k) {
            Some(Token::Word(w)) => Some(w.as_str()),
            _ => None,
        };
        match kind {
            Kind::Length => {
                if unit.and_then(angle_unit).is_some() {
                    continue;
                }
                return Some(value * unit.and_then(length_unit).unwrap_or(1.0));
            }
            Kind::Angle => {
                if unit.and_then(length_unit).is_some() && unit != Some("in") {
                    continue;
                }
                return Some(value * unit.and_then(angle_unit).unwrap_or(1.0));
            }
        }
    }
    None
}

fn find_direction(words: &[&str]) -> Option<(usize, f64)> {
    // "toward the front", "to the back", "forward".
    words.iter().find_map(|w| direction(w))
}

fn size_word(w: &str) -> Option<f64> {
    Some(match w {
        "bigger" | "larger" | "enlarge" | "grow" | "double" | "twice" => 2.0,
        "smaller" | "shrink" | "halve" | "half" => 0.5,
        "triple" | "thrice" => 3.0,
        _ => return None,
    })
}

fn scale_factor(clause: &[Token], words: &[&str]) -> Option<f64> {
    let has = |w: &str| words.contains(&w);
    if has("percent") {
        let n = clause.iter().find_map(|t| {
            if let Token::Number(n) = t {
                Some(*n)
            } else {
                None
            }
        })?;
        // "by 50 percent" grows by half; "to 50 percent" sets the size.
        return Some(if has("to") {
            n / 100.0
        } else if has("shrink") || has("reduce") {
            1.0 - n / 100.0
        } else {
            1.0 + n / 100.0
        });
    }
    if let Some(n) = clause.iter().find_map(|t| {
        if let Token::Number(n) = t {
            Some(*n)
        } else {
            None
        }
    }) {
        return (n > 0.0).then(|| {
            if has("shrink") || has("reduce") {
                if n > 1.0 {
                    1.0 / n
                } else {
                    n
                }
            } else {
                n
            }
        });
    }
    if has("half") || has("halve") {
        return Some(0.5);
    }
    if has("twice") || has("double") {
        return Some(2.0);
    }
    if has("triple") || has("thrice") || has("three") {
        return Some(3.0);
    }
    words
        .iter()
        .find_map(|w| size_word(w))
        .or_else(|| (has("scale") || has("resize")).then_some(2.0))
}

fn rotation_plane(words: &[&str]) -> &'static str {
    let has = |w: &str| words.contains(&w);
    let axis = words
        .iter()
        .position(|w| *w == "axis")
        .and_then(|i| words.get(i.wrapping_sub(1)))
        .copied();
    if has("e1") && has("e2") {
        return "e1, e2";
    }
    if has("e2") && has("e3") {
        return "e2, e3";
    }
    match axis {
        Some("x") | Some("e1") => "e2, e3",
        Some("z") | Some("e3") => "e1, e2",
        _ => "e3, e1",
    }
}

fn is_relation_word(w: &str) -> bool {
    matches!(
        w,
        "from"
            | "on"
            | "onto"
            | "atop"
            | "top"
            | "next"
            | "beside"
            | "by"
            | "near"
            | "nearby"
            | "alongside"
            | "adjacent"
            | "of"
            | "under"
            | "below"
            | "beneath"
            | "underneath"
            | "behind"
            | "between"
            | "with"
            | "toward"
            | "towards"
            | "to"
            | "against"
            | "in"
            | "at"
            | "left"
            | "right"
            | "front"
    )
}

/// The translation vector for a relation phrase (`on top of X2`, `next to X2`, `left of
/// X2`, …), using the targets' boxes as earlier clauses left them.
fn relation(
    words: &[&str],
    s: usize,
    objects: &[usize],
    steps: &BTreeMap<usize, Vec<Step>>,
) -> Option<String> {
    let a = format!("X{}", s + 1);
    let has = |w: &str| words.contains(&w);
    let target = *objects.first()?;
    let b = |attribute: &str| boxed(target, attribute, steps);
    let centre = |axis: &str| format!("(({} - {a}.center) | {axis}) * {axis}", b("center"));
    let level = format!("(({} - {a}.min) | e2) * e2", b("min"));
    if has("between") && objects.len() >= 2 {
        let c = boxed(objects[1], "center", steps);
        let mid = format!("(({} + {c}) / 2 - {a}.center)", b("center"));
        return Some(format!("({mid} | e1) * e1 + ({mid} | e3) * e3 + {level}"));
    }
    if has("on") || has("onto") || has("atop") || has("top") {
        return Some(format!(
            "(({} | e2) - ({a}.min | e2)) * e2 + {} + {}",
            b("max"),
            centre("e1"),
            centre("e3")
        ));
    }
    if has("under") || has("below") || has("beneath") || has("underneath") {
        return Some(format!(
            "(({} | e2) - ({a}.min | e2)) * e2 + {} + {}",
            b("min"),
            centre("e1"),
            centre("e3")
        ));
    }
    let gap = fmt(GAP);
    let side = |axis: usize, sign: f64| -> String {
        let e = AXIS[axis];
        let other = AXIS[2 - axis];
        let along = if sign > 0.0 {
            format!("(({} | {e}) + {gap} - ({a}.min | {e})) * {e}", b("max"))
        } else {
            format!("(({} | {e}) - {gap} - ({a}.max | {e})) * {e}", b("min"))
        };
        format!("{along} + {} + {level}", centre(other))
    };
    if has("left") {
        return Some(side(0, -1.0));
    }
    if has("right") {
        return Some(side(0, 1.0));
    }
    if has("front") {
        return Some(side(2, 1.0));
    }
    if has("behind") || has("back") {
        return Some(side(2, -1.0));
    }
    if has("next")
        || has("beside")
        || has("by")
        || has("near")
        || has("nearby")
        || has("alongside")
        || has("adjacent")
        || has("close")
    {
        // The side of the target nearest X_a: its x faces when X_a lies more to the side
        // than in front or behind (compared in the target's own proportions), else its z
        // faces; on each axis, the face on X_a's side (ties go to +).
        let step = |d: &str| format!("((1 + ({d} + 1e-12) / abs({d} + 1e-12)) / 2)");
        let along = |e: &str| {
            let d = format!("(({a}.center - {}) | {e})", b("center"));
            let p = step(&d);
            let plus = format!("(({} | {e}) + {gap} - ({a}.min | {e}))", b("max"));
            let minus = format!("(({} | {e}) - {gap} - ({a}.max | {e}))", b("min"));
            format!("({p} * {plus} + (1 - {p}) * {minus}) * {e}")
        };
        let dx = format!("abs(({a}.center - {}) | e1)", b("center"));
        let dz = format!("abs(({a}.center - {}) | e3)", b("center"));
        let q = step(&format!(
            "({dx} * ({} | e3) - {dz} * ({} | e1))",
            b("size"),
            b("size")
        ));
        return Some(format!(
            "{q} * ({} + {}) + (1 - {q}) * ({} + {}) + {level}",
            along("e1"),
            centre("e3"),
            along("e3"),
            centre("e1")
        ));
    }
    if has("at") || has("to") || has("with") || has("toward") || has("towards") || has("in") {
        // "move X1 to X2": to its place, standing on the same level.
        return Some(format!("{} + {} + {level}", centre("e1"), centre("e3")));
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(q: &str) -> String {
        reply_for(q, 3).unwrap_or_else(|e| panic!("{q}: {e}"))
    }

    #[test]
    fn simple_moves_rotations_scales() {
        assert_eq!(r("move the X1 to the right"), r#"{"X1": "T(1 * e1)"}"#);
        assert_eq!(r("move X1 2 units to the left"), r#"{"X1": "T(-2 * e1)"}"#);
        assert_eq!(r("push X1 back 50 cm"), r#"{"X1": "T(-0.5 * e3)"}"#);
        assert_eq!(r("lift X1 by 20cm"), r#"{"X1": "T(0.2 * e2)"}"#);
        assert_eq!(
            r("rotate X1 by 45 degrees clockwise"),
            r#"{"X1": "R(-45 * pi / 180, e3, e1)"}"#
        );
        assert_eq!(
            r("turn X1 a quarter turn"),
            r#"{"X1": "R(90 * pi / 180, e3, e1)"}"#
        );
        assert_eq!(
            r("turn X1 around"),
            r#"{"X1": "R(180 * pi / 180, e3, e1)"}"#
        );
        assert_eq!(r("make X1 twice as big"), r#"{"X1": "D(2)"}"#);
        assert_eq!(r("shrink X1 to half its size"), r#"{"X1": "D(0.5)"}"#);
    }

    #[test]
    fn compositions_and_pronouns() {
        assert_eq!(
            r("rotate X1 by 90 degrees and move it 0.5 m to the right"),
            r#"{"X1": ["R(90 * pi / 180, e3, e1)", "T(0.5 * e1)"]}"#
        );
        assert_eq!(
            r("move X1 left and X2 right"),
            r#"{"X1": "T(-1 * e1)", "X2": "T(1 * e1)"}"#
        );
    }

    #[test]
    fn relations_use_only_the_objects_boxes() {
        let on = r("put X1 on top of X2");
        assert!(on.contains("X2.max | e2"), "{on}");
        // Apart from variable and blade names, no number at all: nothing from a scene.
        let mut rest = on.clone();
        for name in ["X1", "X2", "X3", "e1", "e2", "e3"] {
            rest = rest.replace(name, "");
        }
        assert!(!rest.chars().any(|c| c.is_ascii_digit()), "{on}");
        let between = r("place the X1 between the X2 and the X3");
        assert!(between.contains("X2.center + X3.center"), "{between}");
        // Stacking: X3 goes onto X1's new top, X1's move included.
        let stack = r("stack the X1 on the X2 and the X3 on the X1");
        assert!(stack.contains("(X1.max + ((X2.max | e2)"), "{stack}");
        assert!(r("swap the X1 and the X2").contains("\"X2\""));
        assert!(r("align the X1 with the X2 along the z axis").contains("| e3) * e3"));
        assert!(r("turn the X1 to face the X2").starts_with("{\"X1\": \"R(atan2("));
    }

    #[test]
    fn room_places_distances_rows_and_repeats() {
        let centre = r("move the X1 to the centre of the room");
        assert!(centre.contains("room.center - X1.center"), "{centre}");
        assert!(r("push the X1 into the back left corner").contains("room.min | e3"));
        assert!(r("put the X1 in the corner").contains("room.max | e1"));
        assert!(r("move the X1 against the right wall").contains("room.max | e1"));
        assert!(r("put the X1 against the wall").contains("abs"));
        assert!(r("move the X1 away from the X2 by 2 m").starts_with("{\"X1\": \"T(-2 * "));
        assert!(r("bring the X1 closer to the X2").starts_with("{\"X1\": \"T(0.5 * "));
        let row = r("line up the X1, the X2 and the X3");
        assert!(
            row.contains("\"X2\"") && row.contains("\"X3\"") && !row.contains("\"X1\""),
            "{row}"
        );
        assert_eq!(
            r("move X1 1 m to the left and move X2 the other way"),
            r#"{"X1": "T(-1 * e1)", "X2": "T(-1 * (-1 * e1))"}"#
        );
        assert_eq!(
            r("turn X1 45 degrees and do the same for X2"),
            r#"{"X1": "R(45 * pi / 180, e3, e1)", "X2": "R(45 * pi / 180, e3, e1)"}"#
        );
        assert!(r("move X1 0.5 m to the right and mirror that for X2")
            .contains("- 2 * ((0.5 * e1) | e1) * e1"));
    }

    #[test]
    fn unreadable_instructions_fail_clearly() {
        let e = reply_for("please do something nice with X1", 1).unwrap_err();
        assert!(
            e.contains("could not read") && e.contains("--llm openai:MODEL"),
            "{e}"
        );
    }
}

#[cfg(test)]
mod scene_tests {
    //! The room constructs on a built-in scene, end to end through the evaluator.
    use super::*;
    use crate::pipeline::{edit, EditOptions};

    fn run(instruction: &str) -> Scene {
        let mut scene = crate::examples::build("living_room").unwrap();
        let options = EditOptions {
            collisions: None,
            ..EditOptions::default()
        };
        edit(&mut scene, instruction, &OfflineTranslator::new(), &options)
            .unwrap_or_else(|e| panic!("{instruction}: {e}"));
        scene
    }

    fn aabb(scene: &Scene, name: &str) -> crate::geometry::Aabb {
        scene.objects[scene.find(name).unwrap()].world_aabb()
    }

    #[test]
    fn room_places_land_where_they_say() {
        // The room spans x ∈ [−3, 3], z ∈ [−2.5, 2.5].
        let s = run("move the 'ottoman' to the centre of the room");
        let c = aabb(&s, "ottoman").center();
        assert!(c.x.abs() < 1e-9 && c.z.abs() < 1e-9, "{c}");
        let s = run("push the 'plant' into the back left corner");
        let b = aabb(&s, "plant");
        assert!(
            (b.min.x + 2.98).abs() < 1e-9 && (b.min.z + 2.48).abs() < 1e-9,
            "{b:?}"
        );
        // The ottoman (centre x −1.2, z 0.4) is nearest the left wall of the x walls and
        // the front wall of the z walls; the left wall (1.8 m from its centre) is nearer
        // than the front one (2.1 m).
        let s = run("put the 'ottoman' against the wall");
        let b = aabb(&s, "ottoman");
        assert!((b.min.x + 2.98).abs() < 1e-9, "{b:?}");
        let s = run("move the 'ottoman' away from the 'sofa' by 1 m");
        let (before, after) = (crate::examples::build("living_room").unwrap(), s);
        let d0 = aabb(&before, "ottoman").center() - aabb(&before, "sofa").center();
        let d1 = aabb(&after, "ottoman").center() - aabb(&after, "sofa").center();
        let flat = |v: glam::DVec3| glam::DVec2::new(v.x, v.z).length();
        assert!((flat(d1) - flat(d0) - 1.0).abs() < 1e-9);
        let s = run("line up the 'speaker', the 'speaker 2' and the 'plant'");
        let (a, b, c) = (
            aabb(&s, "speaker"),
            aabb(&s, "speaker 2"),
            aabb(&s, "plant"),
        );
        assert!((b.min.x - a.max.x - GAP).abs() < 1e-9 && (c.min.x - b.max.x - GAP).abs() < 1e-9);
        assert!(
            (b.center().z - a.center().z).abs() < 1e-9
                && (c.center().z - a.center().z).abs() < 1e-9
        );
    }
}

#[cfg(test)]
mod next_to_tests {
    use super::*;
    use crate::pipeline::{edit, EditOptions};

    #[test]
    fn next_to_takes_the_nearest_side_in_either_axis() {
        // In the office, the water cooler (x −3.2, z 0.6) is left of the meeting table
        // (x 0.5, z 1.2): it lands against the table's left face. The coffee cup (on the
        // table, z 1.4) is in front of nothing but behind the whiteboard (z 2.9), which is
        // wide and thin: it lands against the whiteboard's back (−z) face.
        for (instruction, object, check) in [
            (
                "put the 'water cooler' next to the 'meeting table'",
                "water cooler",
                "left",
            ),
            (
                "put the 'coffee cup' beside the 'whiteboard'",
                "coffee cup",
                "back",
            ),
        ] {
            let mut scene = crate::examples::build("office").unwrap();
            let options = EditOptions {
                collisions: None,
                ..EditOptions::default()
            };
            edit(&mut scene, instruction, &OfflineTranslator::new(), &options).unwrap();
            let a = scene.objects[scene.find(object).unwrap()].world_aabb();
            let other = if check == "left" {
                "meeting table"
            } else {
                "whiteboard"
            };
            let b = scene.objects[scene.find(other).unwrap()].world_aabb();
            match check {
                "left" => assert!(
                    (b.min.x - a.max.x - GAP).abs() < 1e-9
                        && (a.center().z - b.center().z).abs() < 1e-9,
                    "{a:?} {b:?}"
                ),
                _ => assert!(
                    (b.min.z - a.max.z - GAP).abs() < 1e-9
                        && (a.center().x - b.center().x).abs() < 1e-9,
                    "{a:?} {b:?}"
                ),
            }
        }
    }
}

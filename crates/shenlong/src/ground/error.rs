//! Why an instruction's words cannot be grounded: each a one-line message that names the
//! phrase, the objects it could mean, and how to say which.

/// A grounding refusal. Nothing is edited.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum GroundError {
    /// The instruction is empty.
    #[error("the instruction is empty")]
    Empty,
    /// The instruction is too long.
    #[error("the instruction is longer than {max} characters")]
    TooLong {
        /// The limit.
        max: usize,
    },
    /// A quoted name that is no object's.
    #[error("unknown object '{name}'{}", did_you_mean(suggestions))]
    UnknownName {
        /// The name as quoted.
        name: String,
        /// The nearest names.
        suggestions: Vec<String>,
    },
    /// A noun phrase that fits no object.
    #[error(
        "\"{phrase}\" matches no object in the scene{}",
        did_you_mean(suggestions)
    )]
    Unknown {
        /// The phrase.
        phrase: String,
        /// The nearest names.
        suggestions: Vec<String>,
    },
    /// A phrase that fits several objects with nothing to pick one.
    #[error("\"{phrase}\" could mean {}: name one ('{example}') or say which ({})", list(candidates), hints.iter().map(|h| format!("'{h}'")).collect::<Vec<_>>().join(", "))]
    Ambiguous {
        /// The phrase.
        phrase: String,
        /// Where the phrase is: bytes of the trimmed instruction.
        span: std::ops::Range<usize>,
        /// Every object it fits.
        candidates: Vec<String>,
        /// One of them, to show how to name one.
        example: String,
        /// Ways to say which, in this scene's words.
        hints: Vec<String>,
    },
    /// A phrase that asks for a number of objects other than the number that fit.
    #[error("\"{phrase}\" names {wanted}, but {} fit: {}; name them or say which", found.len(), list(found))]
    Count {
        /// The phrase.
        phrase: String,
        /// Where the phrase is: bytes of the trimmed instruction.
        span: std::ops::Range<usize>,
        /// How many it asks for.
        wanted: usize,
        /// The objects that fit.
        found: Vec<String>,
    },
    /// A modifier that picks nothing, or cannot pick clearly.
    #[error("\"{phrase}\": {reason}")]
    NoPick {
        /// The phrase.
        phrase: String,
        /// What went wrong, with the candidates.
        reason: String,
    },
    /// The instruction names objects only to keep them where they are.
    #[error(
        "the instruction only says what must stay where it is ({}); say what to move",
        list(held)
    )]
    OnlyHeld {
        /// The objects held.
        held: Vec<String>,
    },
    /// The instruction names a kind of object the scene has none of ("the window").
    #[error(
        "there is no {word} in the scene; name one of its objects (it has {total}: {}{})",
        names.join(", "),
        if *total > names.len() { ", …" } else { "" }
    )]
    Absent {
        /// The word, as typed.
        word: String,
        /// The first of the scene's names.
        names: Vec<String>,
        /// How many objects the scene has.
        total: usize,
    },
    /// The instruction names no object of the scene.
    #[error(
        "the instruction names no object of the scene; name one (it has {total}: {}{})",
        names.join(", "),
        if *total > names.len() { ", …" } else { "" }
    )]
    NoObject {
        /// The first of the scene's names.
        names: Vec<String>,
        /// How many objects the scene has.
        total: usize,
    },
}

fn did_you_mean(suggestions: &[String]) -> String {
    match suggestions {
        [] => String::new(),
        [one] => format!(" — did you mean '{one}'?"),
        [a, b, ..] => format!(" — did you mean '{a}' or '{b}'?"),
    }
}

/// The plural of a noun for messages: `boxes`, `benches`, `shelves` left aside — `-es`
/// after s, x, z, ch and sh, `-ies` after a consonant and y, else `-s`.
#[must_use]
pub(crate) fn plural(noun: &str) -> String {
    let consonant_y = noun.ends_with('y')
        && noun
            .chars()
            .rev()
            .nth(1)
            .is_some_and(|c| !"aeiou".contains(c));
    if ["s", "x", "z", "ch", "sh"]
        .iter()
        .any(|e| noun.ends_with(e))
    {
        format!("{noun}es")
    } else if consonant_y {
        format!("{}ies", &noun[..noun.len() - 1])
    } else {
        format!("{noun}s")
    }
}

/// `a, b and c`; long lists shortened: `a, b, c, …, z (12 objects)`.
pub(crate) fn list(names: &[String]) -> String {
    match names.len() {
        0 => "nothing".into(),
        1 => names[0].clone(),
        n if n <= 8 => format!("{} and {}", names[..n - 1].join(", "), names[n - 1]),
        n => format!(
            "{}, … and {} ({n} objects)",
            names[..6].join(", "),
            names[n - 1]
        ),
    }
}

/// A choice a refusal leaves to the user: the phrase, where it stands in the (trimmed)
/// instruction, and the objects it competes for. Replacing `span` by one of `objects`,
/// quoted, makes an instruction that names that one.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Ambiguity {
    /// The phrase as typed.
    pub phrase: String,
    /// Its bytes in the trimmed instruction: `[start, end)`.
    pub span: [usize; 2],
    /// The objects it could mean, by name.
    pub objects: Vec<String>,
}

impl GroundError {
    /// "There is no window in the scene": no object of the kind `word` names, with the
    /// first of `scene`'s names.
    #[must_use]
    pub(crate) fn absent(word: String, scene: &crate::scene::Scene) -> Self {
        GroundError::Absent {
            word,
            names: first_names(scene),
            total: scene.objects.len(),
        }
    }

    /// The choice a refusal leaves between objects: the candidates of an ambiguous
    /// phrase, or the objects that fit a phrase that asks for another number of them.
    #[must_use]
    pub fn ambiguity(&self) -> Option<Ambiguity> {
        match self {
            GroundError::Ambiguous {
                phrase,
                span,
                candidates,
                ..
            } => Some(Ambiguity {
                phrase: phrase.clone(),
                span: [span.start, span.end],
                objects: candidates.clone(),
            }),
            GroundError::Count {
                phrase,
                span,
                found,
                ..
            } => Some(Ambiguity {
                phrase: phrase.clone(),
                span: [span.start, span.end],
                objects: found.clone(),
            }),
            _ => None,
        }
    }

    /// The objects a refusal names (candidates, or suggestions), for programs.
    #[must_use]
    pub fn mentions(&self) -> &[String] {
        match self {
            GroundError::UnknownName { suggestions, .. }
            | GroundError::Unknown { suggestions, .. } => suggestions,
            GroundError::Ambiguous { candidates, .. } => candidates,
            GroundError::Count { found, .. } => found,
            GroundError::NoObject { names, .. } => names,
            _ => &[],
        }
    }
}

/// The first six of a scene's names, for a refusal that lists what the scene has.
pub(crate) fn first_names(scene: &crate::scene::Scene) -> Vec<String> {
    scene
        .objects
        .iter()
        .take(6)
        .map(|o| o.name.clone())
        .collect()
}

#[cfg(test)]
mod plural_tests {
    #[test]
    fn plurals_for_messages() {
        for (one, many) in [
            ("box", "boxes"),
            ("bench", "benches"),
            ("lamp", "lamps"),
            ("body", "bodies"),
            ("tray", "trays"),
            ("glass", "glasses"),
        ] {
            assert_eq!(super::plural(one), many);
        }
    }
}

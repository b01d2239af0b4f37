//! Discourse: the words people type around an instruction that never change the edit —
//! greetings, thanks, sign-offs, hedges, text-speak and the request frames that carry the
//! action ("would you be so kind as to move …", "can u turn …").
//!
//! This is a closed, documented class ([docs/offline.md](../../docs/offline.md)): a word
//! that is not in it and that no other part of the reader reads still refuses the
//! instruction. Nothing here may change what is moved, where or how far: the lists hold
//! no direction, amount, negation, quantifier or object word. Both the grounder (which
//! must not take "morning" or "cheers" for a missing object) and the offline translator
//! (which must read every word) use these lists; they work on lower-case words.

/// Text-speak and spelling variants of the discourse words, as the word they stand for
/// (`u` → `you`, `pls` → `please`, `thx` → `thanks`). Other words are returned as they are.
#[must_use]
pub fn canonical(word: &str) -> &str {
    // Greetings typed long: "hiii", "heyyy", "hellooo".
    let stretched = |stem: &str, last: char| {
        word.strip_prefix(stem)
            .is_some_and(|rest| !rest.is_empty() && rest.chars().all(|c| c == last))
    };
    if stretched("hi", 'i') {
        return "hi";
    }
    if stretched("hey", 'y') {
        return "hey";
    }
    if stretched("hello", 'o') {
        return "hello";
    }
    match word {
        "u" | "ya" | "yu" => "you",
        "ur" => "your",
        "pls" | "plz" | "plez" | "pleeze" | "pleaze" | "plse" => "please",
        "thx" | "thnx" | "thanx" | "tx" | "thks" | "tnx" | "ty" | "tysm" | "thankyou" => "thanks",
        "im" => "i'm",
        "id" => "i'd",
        "wanna" => "want",
        "gonna" => "going",
        "ok" | "k" | "kk" | "okey" | "okie" => "okay",
        "mornin" | "gm" => "morning",
        "sec" | "second" | "moment" | "min" | "minute" | "mo" => "sec",
        "hiya" | "heya" => "hi",
        other => frame_typo(other).unwrap_or(other),
    }
}

/// The words of request frames a typo is read through (`coudl`, `pleae`, `cna`, `yuo`).
const FRAME_WORDS: [&str; 7] = ["could", "would", "please", "can", "you", "should", "want"];

/// The request-frame word `word` is a typo of: two neighbouring letters swapped (`cna`,
/// `coudl`), or, in a word of five letters or more, one letter left out (`pleae`, `coud`)
/// or one doubled (`pleasse`). Never a letter replaced: "world" is no typo of "would".
fn frame_typo(word: &str) -> Option<&'static str> {
    let w = word.as_bytes();
    FRAME_WORDS.into_iter().find(|frame| {
        let f = frame.as_bytes();
        let swapped = w.len() == f.len()
            && w.len() >= 3
            && (0..w.len() - 1).any(|i| {
                w[i] != w[i + 1]
                    && w[i] == f[i + 1]
                    && w[i + 1] == f[i]
                    && w[..i] == f[..i]
                    && w[i + 2..] == f[i + 2..]
            });
        let dropped = f.len() >= 5
            && w.len() + 1 == f.len()
            && (0..f.len()).any(|i| w[..i] == f[..i] && w[i..] == f[i + 1..]);
        let doubled = f.len() >= 5
            && w.len() == f.len() + 1
            && (1..w.len()).any(|i| w[i] == w[i - 1] && w[..i] == f[..i] && w[i + 1..] == f[i..]);
        swapped || dropped || doubled
    })
}

/// Single words that may stand anywhere in an instruction and mean nothing for the edit:
/// articles, politeness, hedges, impatience and thanks.
#[must_use]
pub fn filler(word: &str) -> bool {
    matches!(
        canonical(word),
        "the"
            | "a"
            | "an"
            | "please"
            | "kindly"
            | "just"
            | "now"
            | "okay"
            | "alright"
            | "so"
            | "thanks"
            | "thank"
            | "cheers"
            | "you"
            | "then"
            | "hey"
            | "hi"
            | "hello"
            | "yo"
            | "um"
            | "umm"
            | "uh"
            | "er"
            | "erm"
            | "hmm"
            | "oh"
            | "too"
            | "and"
            | "also"
            | "again"
            | "over"
            | "its"
            | "their"
            | "some"
            | "gently"
            | "carefully"
            | "neatly"
            | "nicely"
            | "properly"
            | "tidily"
            | "slowly"
            | "quickly"
            | "simply"
            | "straight"
            | "directly"
            | "exactly"
            | "already"
            | "maybe"
            | "perhaps"
            | "possibly"
            | "actually"
            | "basically"
            | "honestly"
            | "lol"
            | "sorry"
            | "mate"
            | "buddy"
            | "pal"
            | "friend"
            | "instead"
            | "asap"
    )
}

/// Phrases that open an instruction (greetings) or a request (frames that carry the
/// action of the verb after them), longest first within a family.
const OPENERS: &[&[&str]] = &[
    // Greetings.
    &["good", "morning"],
    &["good", "afternoon"],
    &["good", "evening"],
    &["good", "day"],
    &["hello", "there"],
    &["hi", "there"],
    &["hey", "there"],
    &["morning"],
    &["afternoon"],
    &["evening"],
    &["sorry", "to", "bother", "you"],
    &["sorry", "to", "bug", "you"],
    &["quick", "one"],
    &["quick", "question"],
    &["quick", "q"],
    &["if", "poss"],
    &["if", "possible"],
    &["quick", "request"],
    &["when", "you", "get", "a", "sec"],
    &["when", "you", "have", "a", "sec"],
    &["if", "you", "have", "a", "sec"],
    &["thanks", "in", "advance"],
    &["need"],
    // Request frames: the verb that follows is the action.
    &["would", "you", "be", "so", "kind", "as", "to"],
    &["would", "you", "be", "kind", "enough", "to"],
    &["would", "you", "be", "able", "to"],
    &["could", "you", "be", "so", "kind", "as", "to"],
    &["i'd", "appreciate", "it", "if", "you", "could"],
    &["i", "would", "appreciate", "it", "if", "you", "could"],
    &["i'd", "love", "it", "if", "you", "could"],
    &["i'd", "love", "it", "if", "you", "would"],
    &["is", "it", "possible", "to"],
    &["would", "it", "be", "possible", "to"],
    &["are", "you", "able", "to"],
    &["do", "you", "think", "you", "could"],
    &["do", "you", "mind"],
    &["would", "you", "mind"],
    &["could", "you", "possibly"],
    &["can", "you", "possibly"],
    &["could", "you", "please"],
    &["can", "you", "please"],
    &["would", "you", "please"],
    &["will", "you", "please"],
    &["could", "you", "just"],
    &["can", "you", "just"],
    &["could", "you"],
    &["can", "you"],
    &["would", "you"],
    &["will", "you"],
    &["please", "could", "you"],
    &["please", "can", "you"],
    &["could", "i", "get", "you", "to"],
    &["can", "i", "get", "you", "to"],
    &["i'd", "like", "you", "to"],
    &["i", "would", "like", "you", "to"],
    &["i", "want", "you", "to"],
    &["i", "need", "you", "to"],
    &["i'd", "like", "to"],
    &["i", "would", "like", "to"],
    &["i", "want", "to"],
    &["i", "need", "to"],
    &["i'd", "like"],
    &["i", "would", "like"],
    &["i", "want"],
    &["i", "need"],
    &["help", "me"],
    &["let's"],
    &["lets"],
    &["let", "us"],
    &["go", "ahead", "and"],
    &["try", "to"],
    &["please"],
    &["kindly"],
];

/// Phrases that close an instruction: thanks and sign-offs, and the hedges people add at
/// the end ("… for me", "… if you can").
const CLOSERS: &[&[&str]] = &[
    &["thank", "you", "so", "much"],
    &["thank", "you", "very", "much"],
    &["thanks", "so", "much"],
    &["thanks", "a", "lot"],
    &["thanks", "a", "bunch"],
    &["thanks", "in", "advance"],
    &["many", "thanks"],
    &["if", "that's", "ok"],
    &["if", "that's", "okay"],
    &["if", "that's", "alright"],
    &["if", "that", "is", "okay"],
    &["if", "that's", "possible"],
    &["if", "poss"],
    &["ta", "very", "much"],
    &["ta"],
    &["when", "you", "get", "a", "sec"],
    &["asap"],
    &["much", "appreciated"],
    &["thank", "you"],
    &["if", "you", "don't", "mind"],
    &["if", "you", "do", "not", "mind"],
    &["when", "you", "get", "a", "chance"],
    &["when", "you", "can"],
    &["if", "you", "can"],
    &["if", "you", "could"],
    &["if", "possible"],
    &["real", "quick"],
    &["for", "me"],
    &["for", "now"],
    &["for", "the", "moment"],
    &["for", "the", "time", "being"],
    &["appreciated"],
    &["thanks"],
    &["cheers"],
    &["please"],
];

/// Whether the words from `at` are `phrase`. The readers' one matcher of fixed phrases
/// (discourse here, holds in the grounder, views of a turn in the offline translator).
#[must_use]
pub fn phrase_at(words: &[&str], at: usize, phrase: &[&str]) -> bool {
    phrase.len() <= words.len().saturating_sub(at)
        && phrase.iter().zip(&words[at..]).all(|(p, w)| p == w)
}

/// The length, in words, of the longest of `options` standing at `at`.
#[must_use]
pub fn longest_phrase(words: &[&str], at: usize, options: &[&[&str]]) -> Option<usize> {
    options
        .iter()
        .filter(|o| phrase_at(words, at, o))
        .map(|o| o.len())
        .max()
}

/// The length, in words, of the longest sign-off that ends exactly at `end` (exclusive)
/// in canonical words.
fn closer_before(words: &[&str], end: usize) -> Option<usize> {
    CLOSERS
        .iter()
        .filter(|p| p.len() <= end && phrase_at(words, end - p.len(), p))
        .map(|p| p.len())
        .max()
}

/// Whether `word` is a discourse word that could be taken for a noun: the fillers and the
/// single-word greetings and thanks. The grounder does not take such a word for the name
/// of a missing object ("good morning", "cheers").
#[must_use]
pub fn is_discourse_word(word: &str) -> bool {
    let w = canonical(word);
    filler(w) || matches!(w, "morning" | "afternoon" | "evening" | "appreciated")
}

/// Where an instruction's words start and end once the discourse around them is set
/// aside: greetings and request frames at the start, sign-offs at the end (repeatedly, so
/// "hey, good morning, could you …" and "… for me, thanks!" are both read). Returns the
/// range of the words that carry the instruction.
#[must_use]
pub fn core(words: &[&str]) -> std::ops::Range<usize> {
    let words: Vec<&str> = words.iter().map(|w| canonical(w)).collect();
    // Sign-offs first, so a clause that is all thanks ("ty in advance!") is all set aside.
    let mut end = words.len();
    while let Some(n) = closer_before(&words, end) {
        end -= n;
    }
    let mut start = 0;
    loop {
        if let Some(n) = longest_phrase(&words[..end], start, OPENERS) {
            start += n;
        } else if start < end && filler(words[start]) && !is_article(words[start]) {
            start += 1;
        } else {
            break;
        }
    }
    start..end.max(start)
}

fn is_article(w: &str) -> bool {
    matches!(w, "the" | "a" | "an")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn typos_of_request_frames_read_as_the_frame() {
        for (typed, frame) in [
            ("coudl", "could"),
            ("cna", "can"),
            ("pleae", "please"),
            ("pelase", "please"),
            ("yuo", "you"),
            ("woudl", "would"),
            ("pleasse", "please"),
        ] {
            assert_eq!(canonical(typed), frame, "{typed}");
        }
        // A letter replaced is another word; short words lose nothing.
        for word in [
            "world", "cloud", "can", "could", "yo", "cab", "plate", "wants",
        ] {
            assert!(
                canonical(word) == word || FRAME_WORDS.contains(&word),
                "{word}"
            );
        }
        assert_eq!(
            core_of("coudl you pleae move the mug left"),
            "move the mug left"
        );
    }

    fn core_of(s: &str) -> String {
        let w: Vec<&str> = s.split(' ').collect();
        w[core(&w)].join(" ")
    }

    #[test]
    fn greetings_frames_and_sign_offs_are_set_aside() {
        assert_eq!(
            core_of("hey can u move the lamp left thx"),
            "move the lamp left"
        );
        assert_eq!(
            core_of("good morning would you be so kind as to turn the chair"),
            "turn the chair"
        );
        assert_eq!(
            core_of("hello there could you possibly move it for me thank you so much"),
            "move it"
        );
        assert_eq!(core_of("pls move the bin if you can"), "move the bin");
        assert_eq!(
            core_of("put the laptop on the cabinet for now"),
            "put the laptop on the cabinet"
        );
        assert_eq!(core_of("i'd like the lamp moved"), "the lamp moved");
        assert_eq!(core_of("ty in advance"), "");
        assert_eq!(
            core_of("sorry to bother you could the lamp go left"),
            "could the lamp go left"
        );
    }

    #[test]
    fn words_that_change_the_edit_are_never_discourse() {
        for w in [
            "not", "don't", "left", "right", "back", "more", "less", "only", "all", "both",
            "every", "no", "leave", "keep", "half", "bit",
        ] {
            assert!(!is_discourse_word(w), "{w}");
        }
        // The articles stay for the noun phrase that follows.
        assert_eq!(core_of("the lamp left"), "the lamp left");
    }

    #[test]
    fn text_speak_is_canonical() {
        assert_eq!(canonical("u"), "you");
        assert_eq!(canonical("plz"), "please");
        assert_eq!(canonical("ty"), "thanks");
        assert!(filler("thx"));
        assert!(filler("cheers"));
    }
}

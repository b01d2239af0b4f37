//! What must not move: the phrases an instruction names only to keep them where they are
//! ("… but leave the chair where it is", "don't touch the rug, just …", "…, not the
//! dresser itself", "move armchair 1 but not armchair 2", "keep the books where they
//! are", "without moving the lamp").
//!
//! A held phrase is not bound to a variable: its words (the whole hold clause) are cut
//! from the query the translator reads, and its objects are handed to placement, which
//! neither carries them nor lets collision resolution move them, and refuses the edit if
//! it cannot be done with them where they are.

use super::words::{Kind, Token};
use super::Phrase;
use crate::discourse::{longest_phrase, phrase_at};
use std::ops::Range;

/// A phrase held in place, and the words of the instruction that say so.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Hold {
    /// Which phrase (index into the grounded phrases).
    pub phrase: usize,
    /// The bytes of the instruction the hold clause spans, cut from the query.
    pub cut: Range<usize>,
}

/// Words before a phrase that hold it (the last word stands right before the phrase), and
/// what must follow the phrase: one of [`AFTER`] (`keep the books where they are`, not
/// `keep the chair 1 m from the desk`), or for most also the end of its clause.
const BEFORE: &[(&[&str], Need)] = &[
    (&["don't", "touch"], Need::EndOrAfter),
    (&["dont", "touch"], Need::EndOrAfter),
    (&["do", "not", "touch"], Need::EndOrAfter),
    (&["don't", "move"], Need::EndOrAfter),
    (&["dont", "move"], Need::EndOrAfter),
    (&["do", "not", "move"], Need::EndOrAfter),
    (&["never", "move"], Need::EndOrAfter),
    (&["don't", "disturb"], Need::EndOrAfter),
    (&["don't", "shift"], Need::EndOrAfter),
    (&["don't", "bump"], Need::EndOrAfter),
    (&["don't", "move", "any", "of"], Need::EndOrAfter),
    (&["dont", "move", "any", "of"], Need::EndOrAfter),
    (&["do", "not", "move", "any", "of"], Need::EndOrAfter),
    (&["don't", "touch", "any", "of"], Need::EndOrAfter),
    (&["dont", "touch", "any", "of"], Need::EndOrAfter),
    (&["do", "not", "touch", "any", "of"], Need::EndOrAfter),
    (&["without", "moving", "any", "of"], Need::EndOrAfter),
    (&["leave", "all", "of"], Need::EndOrAfter),
    (&["keep", "all", "of"], Need::After),
    (&["without", "moving"], Need::EndOrAfter),
    (&["without", "touching"], Need::EndOrAfter),
    (&["without", "disturbing"], Need::EndOrAfter),
    (&["leave"], Need::EndOrAfter),
    (&["keep"], Need::After),
    (&["keeping"], Need::After),
    (&["leaving"], Need::After),
    (&["not"], Need::EndOrAfter),
    (&["except", "for"], Need::Nothing),
    (&["except"], Need::Nothing),
    (&["apart", "from"], Need::Nothing),
    (&["other", "than"], Need::Nothing),
    (&["excluding"], Need::Nothing),
];

/// Whether a hold needs words after its phrase.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Need {
    /// One of [`AFTER`], or the end of the clause.
    EndOrAfter,
    /// One of [`AFTER`].
    After,
    /// Nothing: the words before say it all (`except the laptop`, wherever it stands).
    Nothing,
}

/// Words after a phrase that say it stays.
const AFTER: &[&[&str]] = &[
    &["where", "it", "is"],
    &["where", "they", "are"],
    &["where", "it's"],
    &["where", "they're"],
    &["where", "it", "was"],
    &["where", "they", "were"],
    &["in", "its", "place"],
    &["in", "their", "place"],
    &["in", "place"],
    &["as", "it", "is"],
    &["as", "they", "are"],
    &["as", "is"],
    &["alone"],
    &["be"],
    &["untouched"],
    &["put"],
    &["still"],
    &["itself"],
    &["themselves"],
    &["either"],
];

/// Verbs after a phrase at the start of a clause that say it stays (`the rug stays`).
const STAYS: &[&[&str]] = &[
    &["stays"],
    &["stay"],
    &["remains"],
    &["should", "stay"],
    &["must", "stay"],
    &["has", "to", "stay"],
    &["needs", "to", "stay"],
    &["can", "stay"],
    &["should", "not", "move"],
    &["shouldn't", "move"],
    &["must", "not", "move"],
    &["mustn't", "move"],
];

/// Words that join a hold clause to the instruction, cut with it.
fn joins(w: &str) -> bool {
    matches!(
        w,
        "but" | "and" | "yet" | "while" | "though" | "please" | "just" | "only"
    )
}

/// Whether the clause ends at token `at`: the end, punctuation, or a word that starts the
/// next clause.
fn clause_ends(tokens: &[Token], at: usize) -> bool {
    match tokens.get(at) {
        None => true,
        Some(t) => match &t.kind {
            Kind::Word(w) => matches!(
                crate::discourse::canonical(w),
                "and" | "but" | "then" | "just" | "only" | "so" | "please" | "thanks" | "cheers"
            ),
            Kind::Punct(_) => true,
            Kind::Number(_) | Kind::Quoted(_) => false,
        },
    }
}

/// The token range a phrase spans.
fn token_range(tokens: &[Token], span: &Range<usize>) -> Option<Range<usize>> {
    let start = tokens.iter().position(|t| t.span.start == span.start)?;
    let end = tokens.iter().rposition(|t| t.span.end == span.end)? + 1;
    (start < end).then_some(start..end)
}

/// Whether a cue that holds a phrase in place ends right before token `start` (`don't
/// move`, `keep`, `leave`, `not`): what follows is named to stay, so a relation after it
/// says which, never where it goes (`… but leave the cup on it where it is`).
pub(crate) fn cue_before(tokens: &[Token], start: usize) -> bool {
    let words: Vec<&str> = tokens.iter().map(|t| t.word().unwrap_or("")).collect();
    BEFORE
        .iter()
        .any(|(cue, _)| start >= cue.len() && phrase_at(&words, start - cue.len(), cue))
}

/// The words for everything not named ("… but don't move anything else").
/// ("the others" and "the rest" are not among them: "move the others right" names them.)
const EVERYTHING_ELSE: &[&[&str]] = &[
    &["anything", "else"],
    &["everything", "else"],
    &["nothing", "else"],
    &["all", "else"],
];

/// Per token, how many tokens from it say "everything else" ([`EVERYTHING_ELSE`]): no
/// object's phrase, but what [`everything_else`] holds.
pub(crate) fn else_words(tokens: &[Token]) -> Vec<Option<usize>> {
    let words: Vec<&str> = tokens.iter().map(|t| t.word().unwrap_or("")).collect();
    (0..words.len())
        .map(|k| longest_phrase(&words, k, EVERYTHING_ELSE))
        .collect()
}

/// The bytes of a clause that holds everything not named in place ("…, but don't move
/// anything else", "leave everything else where it is", "without moving anything else",
/// "nothing else moves", "everything else stays"), cut from the query, or `None`.
pub(crate) fn everything_else(tokens: &[Token]) -> Option<Range<usize>> {
    let words: Vec<&str> = tokens.iter().map(|t| t.word().unwrap_or("")).collect();
    for i in 0..tokens.len() {
        let Some(n) = longest_phrase(&words, i, EVERYTHING_ELSE) else {
            continue;
        };
        let cue = BEFORE
            .iter()
            .filter(|(cue, need)| *need != Need::Nothing && i >= cue.len())
            .find(|(cue, _)| phrase_at(&words, i - cue.len(), cue))
            .map(|(cue, _)| cue.len());
        let start = match cue {
            Some(len) => i - len,
            // "nothing else moves", "everything else stays".
            None if longest_phrase(&words, i + n, STAYS).is_some()
                || matches!(words.get(i + n), Some(&("moves" | "move"))) =>
            {
                i
            }
            None => continue,
        };
        let mut end = i + n;
        end += longest_phrase(&words, end, STAYS)
            .or_else(|| matches!(words.get(end), Some(&("moves" | "move"))).then_some(1))
            .unwrap_or(0);
        end += longest_phrase(&words, end, AFTER).unwrap_or(0);
        if clause_ends(tokens, end) {
            return Some(cut(tokens, start, end));
        }
    }
    None
}

/// The phrases the instruction holds in place, a list held by one cue included ("leave
/// the bin and the left side table where they are").
pub(crate) fn find(tokens: &[Token], phrases: &[Phrase]) -> Vec<Hold> {
    let words: Vec<&str> = tokens.iter().map(|t| t.word().unwrap_or("")).collect();
    let mut out = single(tokens, &words, phrases);
    let mut p = 1;
    while p < phrases.len() {
        let Some(h) = out.iter().position(|h| h.phrase == p - 1) else {
            p += 1;
            continue;
        };
        if out.iter().any(|h| h.phrase == p) {
            p += 1;
            continue;
        }
        let (Some(prev), Some(this)) = (
            token_range(tokens, &phrases[p - 1].span),
            token_range(tokens, &phrases[p].span),
        ) else {
            p += 1;
            continue;
        };
        // Only `and`, `or` and commas between the two phrases.
        if !joined(tokens, &prev, &this) {
            p += 1;
            continue;
        }
        let after = longest_phrase(&words, this.end, AFTER).unwrap_or(0);
        let end = this.end + after;
        if !clause_ends(tokens, end) {
            p += 1;
            continue;
        }
        let start = out[h].cut.start;
        out[h].cut = start..tokens[end - 1].span.end;
        out.push(Hold {
            phrase: p,
            cut: out[h].cut.clone(),
        });
        p += 1;
    }
    out
}

/// Whether phrase `p` opens a list of phrases joined by `and`, `or` or commas whose last
/// is followed by words that say they stay ("keep the laptop and the phone where they
/// are"): [`find`] then holds the others with it.
fn list_then_after(tokens: &[Token], words: &[&str], phrases: &[Phrase], p: usize) -> bool {
    let mut prev = match token_range(tokens, &phrases[p].span) {
        Some(r) => r,
        None => return false,
    };
    for phrase in &phrases[p + 1..] {
        let Some(this) = token_range(tokens, &phrase.span) else {
            return false;
        };
        if !joined(tokens, &prev, &this) {
            return false;
        }
        if longest_phrase(words, this.end, AFTER).is_some() {
            return true;
        }
        prev = this;
    }
    false
}

/// Whether only `and`, `or`, `nor` and commas stand between token ranges `prev` and
/// `this`, and something does.
fn joined(tokens: &[Token], prev: &Range<usize>, this: &Range<usize>) -> bool {
    prev.end < this.start
        && (prev.end..this.start).all(|k| match &tokens[k].kind {
            Kind::Word(w) => matches!(w.as_str(), "and" | "or" | "nor"),
            Kind::Punct(',') => true,
            _ => false,
        })
}

/// Each phrase held by a cue of its own.
fn single(tokens: &[Token], words: &[&str], phrases: &[Phrase]) -> Vec<Hold> {
    let mut out = Vec::new();
    for (p, phrase) in phrases.iter().enumerate() {
        let Some(range) = token_range(tokens, &phrase.span) else {
            continue;
        };
        let after = longest_phrase(words, range.end, AFTER);
        let end = range.end + after.unwrap_or(0);
        let ends = clause_ends(tokens, end);
        let before = BEFORE.iter().find(|(cue, need)| {
            range.start >= cue.len()
                && phrase_at(words, range.start - cue.len(), cue)
                && match need {
                    Need::After => after.is_some() || list_then_after(tokens, words, phrases, p),
                    Need::EndOrAfter => after.is_some() || ends,
                    Need::Nothing => true,
                }
        });
        let start = if let Some((cue, _)) = before {
            range.start - cue.len()
        } else {
            // `the rug stays where it is`: a phrase that opens its clause, then `stays`.
            let opens = range.start == 0
                || match &tokens[range.start - 1].kind {
                    Kind::Word(w) => joins(w),
                    Kind::Punct(_) => true,
                    Kind::Number(_) | Kind::Quoted(_) => false,
                };
            let Some(n) = longest_phrase(words, range.end, STAYS).filter(|_| opens) else {
                continue;
            };
            let after = longest_phrase(words, range.end + n, AFTER).unwrap_or(0);
            let end = range.end + n + after;
            if !clause_ends(tokens, end) {
                continue;
            }
            out.push(Hold {
                phrase: p,
                cut: cut(tokens, range.start, end),
            });
            continue;
        };
        let anywhere = before.is_some_and(|(_, need)| *need == Need::Nothing);
        if !anywhere && !ends && !clause_ends(tokens, end) {
            continue;
        }
        out.push(Hold {
            phrase: p,
            cut: cut(tokens, start, end),
        });
    }
    out
}

/// The bytes from token `start` (with the joining words and the comma before it) to
/// token `end` (exclusive).
fn cut(tokens: &[Token], mut start: usize, end: usize) -> Range<usize> {
    while start > 0 && tokens[start - 1].word().is_some_and(joins) {
        start -= 1;
    }
    if start > 0 && matches!(tokens[start - 1].kind, Kind::Punct(',' | ';')) {
        start -= 1;
    }
    tokens[start].span.start..tokens[end - 1].span.end
}

#[cfg(test)]
mod tests {
    use super::super::words::tokenize;
    use super::*;

    /// The holds of `text`, where each `[…]` marks a phrase (brackets removed).
    fn holds(marked: &str) -> (String, Vec<(usize, String)>) {
        let mut text = String::new();
        let mut phrases = Vec::new();
        let mut open = None;
        for c in marked.chars() {
            match c {
                '[' => open = Some(text.len()),
                ']' => {
                    let s = open.take().unwrap();
                    phrases.push(Phrase {
                        span: s..text.len(),
                        text: text[s..].to_string(),
                        objects: vec![phrases.len()],
                        reasons: Vec::new(),
                    });
                }
                c => text.push(c),
            }
        }
        let tokens = tokenize(&text);
        let found = find(&tokens, &phrases)
            .into_iter()
            .map(|h| (h.phrase, text[h.cut].to_string()))
            .collect();
        (text, found)
    }

    #[test]
    fn hold_clauses_are_found_with_their_words() {
        assert_eq!(
            holds("move [the desk] 15 cm right but leave [the chair] where it is").1,
            vec![(1, "but leave the chair where it is".to_string())]
        );
        assert_eq!(
            holds("don't touch [the rug], just move [the coffee table]").1,
            vec![(0, "don't touch the rug".to_string())]
        );
        assert_eq!(
            holds("move [the lamp] on the dresser, not [the dresser] itself").1,
            vec![(1, ", not the dresser itself".to_string())]
        );
        assert_eq!(
            holds("move [armchair 1] but not [armchair 2]").1,
            vec![(1, "but not armchair 2".to_string())]
        );
        assert_eq!(
            holds("keep [the books] where they are and move [the shelf] left").1,
            vec![(0, "keep the books where they are".to_string())]
        );
        assert_eq!(
            holds("move [the table] left without moving [the lamp]").1,
            vec![(1, "without moving the lamp".to_string())]
        );
        assert_eq!(
            holds("move [the desk] left, [the chair] stays where it is").1,
            vec![(1, ", the chair stays where it is".to_string())]
        );
    }

    #[test]
    fn a_list_is_held_by_one_cue() {
        let (_, found) =
            holds("turn [the armchair], leave [the bin] and [the left side table] where they are");
        assert_eq!(
            found,
            vec![
                (
                    1,
                    ", leave the bin and the left side table where they are".to_string()
                ),
                (
                    2,
                    ", leave the bin and the left side table where they are".to_string()
                )
            ]
        );
        let (_, found) = holds("move [everything on the desk] left except [the laptop]");
        assert_eq!(found, vec![(1, "except the laptop".to_string())]);
        let (_, found) =
            holds("slide [everything on the dresser] except [the blue book] 10 cm left");
        assert_eq!(found, vec![(1, "except the blue book".to_string())]);
    }

    #[test]
    fn words_that_do_not_hold_are_not_holds() {
        // `keep` with a distance is no hold; `not` inside an amount neither.
        assert!(holds("keep [the chair] 1 m from [the desk]").1.is_empty());
        assert!(holds("move [the chair] not too far left").1.is_empty());
        assert!(holds("leave [the mug] next to [the sink]").1.is_empty());
    }
}

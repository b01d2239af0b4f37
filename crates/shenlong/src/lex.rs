//! The one tokenizer of instructions: the grounder reads its tokens, and the offline
//! translator reads the templated query through the same tokens ([`crate::offline`]
//! maps them to its own: variables, numbers with units, fractions, typos). Words are
//! lower-cased with their byte spans kept; an exported name typed as written stays one
//! word (`Chair.001`, `SM_Chair_02`, `side-table`), camelCase splits into its words, and
//! quoted names are one token when [`Quotes::Names`].

use std::ops::Range;

/// One token of an instruction.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Token {
    /// What it is.
    pub kind: Kind,
    /// Where it is in the instruction, in bytes.
    pub span: Range<usize>,
}

/// The kinds of token.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Kind {
    /// A word, lower-cased (`right-hand`, `teacher's`, `2m`).
    Word(String),
    /// A plain number (`7`, `1.5`).
    Number(f64),
    /// A quoted name, without its quotes.
    Quoted(String),
    /// Punctuation: `,` `.` `;` `#` `!` `?` …
    Punct(char),
}

impl Token {
    /// The word, if this is one.
    pub fn word(&self) -> Option<&str> {
        match &self.kind {
            Kind::Word(w) => Some(w),
            _ => None,
        }
    }
}

/// Whether quotes delimit names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Quotes {
    /// `'…'`, `"…"`, `‘…’`, `“…”` and `` `…` `` around words are one [`Kind::Quoted`]
    /// token: a name as the user wrote it (the grounder).
    Names,
    /// Quote marks are punctuation (the templated query, whose names are variables).
    Marks,
}

const QUOTES: &[(char, char)] = &[('\'', '\''), ('"', '"'), ('‘', '’'), ('“', '”'), ('`', '`')];

/// Splits an instruction into tokens. Quoted names (`'…'`, `"…"`, `‘…’`, `“…”`) are one
/// token; an apostrophe inside a word (`sofa's`, `don't`) is part of the word.
/// Number words, for both readers of instructions: `two` → 2, `fourteen` → 14, `twenty`
/// → 20, `hundred` → 100 (amounts: "two metres"; instance numbers: "desk five").
pub(crate) fn number_word(w: &str) -> Option<f64> {
    Some(match w {
        "zero" => 0.0,
        "one" => 1.0,
        "two" => 2.0,
        "three" => 3.0,
        "four" => 4.0,
        "five" => 5.0,
        "six" => 6.0,
        "seven" => 7.0,
        "eight" => 8.0,
        "nine" => 9.0,
        "ten" => 10.0,
        "eleven" => 11.0,
        "twelve" => 12.0,
        "thirteen" => 13.0,
        "fourteen" => 14.0,
        "fifteen" => 15.0,
        "sixteen" => 16.0,
        "seventeen" => 17.0,
        "eighteen" => 18.0,
        "nineteen" => 19.0,
        "twenty" => 20.0,
        "thirty" => 30.0,
        "forty" | "fourty" => 40.0,
        "fifty" => 50.0,
        "sixty" => 60.0,
        "seventy" => 70.0,
        "eighty" => 80.0,
        "ninety" => 90.0,
        "hundred" => 100.0,
        _ => return None,
    })
}

pub(crate) fn tokenize(text: &str) -> Vec<Token> {
    tokenize_with(text, Quotes::Names)
}

/// "9-12" (at bytes `span`): a range of numbers typed as one word, as its two numbers and
/// the dash between them.
fn number_range(word: &str, span: std::ops::Range<usize>) -> Option<[Token; 3]> {
    let (from, to) = word.split_once('-')?;
    let digits = |x: &str| !x.is_empty() && x.len() <= 4 && x.bytes().all(|d| d.is_ascii_digit());
    if !(digits(from) && digits(to)) {
        return None;
    }
    let dash = span.start + from.len();
    Some([
        Token {
            kind: Kind::Number(from.parse().ok()?),
            span: span.start..dash,
        },
        Token {
            kind: Kind::Punct('-'),
            span: dash..dash + 1,
        },
        Token {
            kind: Kind::Number(to.parse().ok()?),
            span: dash + 1..span.end,
        },
    ])
}

/// [`tokenize`], with quotes read as `quotes` says.
pub(crate) fn tokenize_with(text: &str, quotes: Quotes) -> Vec<Token> {
    let chars: Vec<(usize, char)> = text.char_indices().collect();
    let end_of = |k: usize| chars.get(k).map_or(text.len(), |&(b, _)| b);
    let mut tokens = Vec::new();
    let mut k = 0;
    while k < chars.len() {
        let (start, c) = chars[k];
        let inside_word = c == '\'' && k > 0 && chars[k - 1].1.is_alphanumeric();
        if let Some(&(_, close)) = QUOTES.iter().find(|(open, _)| *open == c) {
            if !inside_word && quotes == Quotes::Names {
                if let Some(len) = chars[k + 1..].iter().position(|&(_, d)| d == close) {
                    let name: String = chars[k + 1..k + 1 + len].iter().map(|&(_, c)| c).collect();
                    tokens.push(Token {
                        kind: Kind::Quoted(name),
                        span: start..end_of(k + len + 2),
                    });
                    k += len + 2;
                    continue;
                }
            }
        }
        if c.is_alphanumeric() {
            let mut j = k;
            while j < chars.len() {
                let d = chars[j].1;
                let joins = matches!(d, '-' | '\'' | '’' | '.' | '_')
                    && j + 1 < chars.len()
                    && chars[j + 1].1.is_alphanumeric()
                    && j > k
                    // A period joins digits (1.5), and an exported name's number
                    // (`Chair.001`, `Lamp_Table.003`) or parts (`Chair_Wood.Left`).
                    && (d != '.'
                        || chars[j + 1].1.is_ascii_digit()
                            && (chars[j - 1].1.is_ascii_digit() || chars[j - 1].1.is_alphabetic())
                        || chars[k..j].iter().any(|&(_, c)| c == '_'));
                if d.is_alphanumeric() || joins {
                    j += 1;
                } else {
                    break;
                }
            }
            let raw: String = chars[k..j].iter().map(|&(_, c)| c).collect();
            // `GroupB`, `SideTable` typed as a name is written: its words, as names are
            // read ([`normalize`] splits camelCase the same way).
            if let Some(parts) = camel_parts(&chars[k..j]) {
                for (a, b) in parts {
                    let word: String = chars[k + a..k + b].iter().map(|&(_, c)| c).collect();
                    tokens.push(Token {
                        kind: Kind::Word(word.to_lowercase()),
                        span: chars[k + a].0..end_of(k + b),
                    });
                }
                k = j;
                continue;
            }
            let lower = raw.to_lowercase().replace('’', "'");
            let span = start..end_of(j);
            if let Some(words) = run_together(&lower) {
                // "abit": "a" on its first letter, "bit" on the rest.
                let split = start + words[0].len();
                tokens.push(Token {
                    kind: Kind::Word(words[0].to_string()),
                    span: start..split,
                });
                tokens.push(Token {
                    kind: Kind::Word(words[1].to_string()),
                    span: split..span.end,
                });
                k = j;
                continue;
            }
            if let Some(range) = number_range(&lower, span.clone()) {
                tokens.extend(range);
                k = j;
                continue;
            }
            let kind = match lower.parse::<f64>() {
                Ok(n) if n.is_finite() => Kind::Number(n),
                _ => Kind::Word(function_word_typo(&lower).map_or(lower, str::to_string)),
            };
            tokens.push(Token { kind, span });
            k = j;
            continue;
        }
        if !c.is_whitespace() {
            // `&`, `+` and arrows between words are the words people read them as.
            let arrow = c == '-' && chars.get(k + 1).is_some_and(|&(_, d)| d == '>');
            let end = if arrow { k + 2 } else { k + 1 };
            // An arrow before a place is "to"; before an amount, it only separates
            // ("bin → 30 cm left"), as a colon does.
            let amount_after = chars[end..]
                .iter()
                .find(|&&(_, d)| !d.is_whitespace())
                .is_some_and(|&(_, d)| d.is_ascii_digit());
            let kind = match c {
                '&' => Kind::Word("and".into()),
                '+' => Kind::Word("plus".into()),
                '→' | '⇒' | '⟶' if amount_after => Kind::Punct(':'),
                '→' | '⇒' | '⟶' => Kind::Word("to".into()),
                _ if arrow && amount_after => Kind::Punct(':'),
                _ if arrow => Kind::Word("to".into()),
                _ => Kind::Punct(c),
            };
            tokens.push(Token {
                kind,
                span: start..end_of(end),
            });
            k = end;
            continue;
        }
        k += 1;
    }
    tokens
}

/// The words of a token of letters only with a lower-case letter followed by a capital
/// (`GroupB` → `Group`, `B`), as ranges of `chars`; `None` for any other token.
fn camel_parts(chars: &[(usize, char)]) -> Option<Vec<(usize, usize)>> {
    if !chars.iter().all(|&(_, c)| c.is_alphabetic()) {
        return None;
    }
    let mut cuts = vec![0];
    for i in 1..chars.len() {
        if chars[i - 1].1.is_lowercase() && chars[i].1.is_uppercase() {
            cuts.push(i);
        }
    }
    if cuts.len() < 2 {
        return None;
    }
    cuts.push(chars.len());
    Some(cuts.windows(2).map(|w| (w[0], w[1])).collect())
}

/// The classic typos of the words that glue a sentence (`teh`, `adn`): swaps no other
/// word is spelt as. Both readers see the word meant.
fn function_word_typo(w: &str) -> Option<&'static str> {
    Some(match w {
        "teh" | "hte" => "the",
        "adn" | "nad" => "and",
        "taht" => "that",
        "wiht" | "wtih" => "with",
        "nto" => "not",
        _ => return None,
    })
}

/// Two short words typed as one (`abit`, `alittle`, `alot`): the two words.
fn run_together(w: &str) -> Option<[&'static str; 2]> {
    Some(match w {
        "abit" => ["a", "bit"],
        "alittle" => ["a", "little"],
        "alot" => ["a", "lot"],
        "atad" => ["a", "tad"],
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(text: &str, quotes: Quotes) -> Vec<String> {
        tokenize_with(text, quotes)
            .into_iter()
            .map(|t| match t.kind {
                Kind::Word(w) => w,
                Kind::Number(n) => format!("#{n}"),
                Kind::Quoted(q) => format!("'{q}'"),
                Kind::Punct(c) => c.to_string(),
            })
            .collect()
    }

    #[test]
    fn a_range_typed_as_one_word_is_its_numbers() {
        assert_eq!(
            words("chairs 9-12 left", Quotes::Names),
            ["chairs", "#9", "-", "#12", "left"]
        );
        // Letters keep it a word: a name's pieces.
        assert_eq!(words("Shelf-2 A-3", Quotes::Names), ["shelf-2", "a-3"]);
        // Its bytes are the text's.
        let t = tokenize_with("x 10-20", Quotes::Names);
        assert_eq!(
            t.iter().map(|t| t.span.clone()).collect::<Vec<_>>(),
            [0..1, 2..4, 4..5, 5..7]
        );
    }

    #[test]
    fn names_numbers_and_quotes() {
        assert_eq!(
            words(
                "Move 'Chair 2' 1.5m, SM_Lamp_02 and Chair.001",
                Quotes::Names
            ),
            [
                "move",
                "'Chair 2'",
                "1.5m",
                ",",
                "sm_lamp_02",
                "and",
                "chair.001"
            ]
        );
        // Quotes as marks: the words inside are words.
        assert_eq!(
            words("move 'Chair 2' left", Quotes::Marks),
            ["move", "'", "chair", "#2", "'", "left"]
        );
        assert_eq!(
            words("GroupB sofa's", Quotes::Names),
            ["group", "b", "sofa's"]
        );
    }

    #[test]
    fn glue_word_typos_are_the_words_meant_with_their_spans() {
        assert_eq!(
            words("move teh bin abit left adn back", Quotes::Names),
            ["move", "the", "bin", "a", "bit", "left", "and", "back"]
        );
        assert_eq!(
            words("desk & chair + lamp", Quotes::Names),
            ["desk", "and", "chair", "plus", "lamp"]
        );
        assert_eq!(
            words(
                "lamp → floor, bin -> corner, cup → 3 cm left",
                Quotes::Names
            ),
            [
                "lamp", "to", "floor", ",", "bin", "to", "corner", ",", "cup", ":", "#3", "cm",
                "left"
            ]
        );
        let t = tokenize("nudge it abit");
        assert_eq!((t[2].span.clone(), t[3].span.clone()), (9..10, 10..13));
    }
}

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
pub(crate) fn tokenize(text: &str) -> Vec<Token> {
    tokenize_with(text, Quotes::Names)
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
            let kind = match lower.parse::<f64>() {
                Ok(n) if n.is_finite() => Kind::Number(n),
                _ => Kind::Word(lower),
            };
            tokens.push(Token {
                kind,
                span: start..end_of(j),
            });
            k = j;
            continue;
        }
        if !c.is_whitespace() {
            tokens.push(Token {
                kind: Kind::Punct(c),
                span: start..end_of(k + 1),
            });
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

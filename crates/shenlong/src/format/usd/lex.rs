//! The tokens of a `.usda` layer, read once for every use of its text: the nesting check,
//! the outline the patcher edits ([`super::patch`]) and the layer reader
//! ([`super::layer`]). Strings (triple-quoted too), asset paths, prim paths and comments are
//! read as USD reads them, so no quote in a comment (`# it's`) hides what follows.

use super::super::FormatError;

/// The lexical states the scanner passes through.
pub(super) struct Lexer<'a> {
    pub(super) text: &'a [u8],
    pub(super) pos: usize,
}

/// One token of a layer: what matters for its outline.
#[derive(Debug, PartialEq)]
pub(super) enum Token {
    /// `{ ( [`
    Open(u8),
    /// `} ) ]`
    Close(u8),
    /// A quoted string, unescaped.
    Str(String),
    /// A bare word (identifier, keyword, number, namespaced name).
    Word(String),
    /// An asset path, by its span.
    Asset(usize, usize),
    /// `=` and other punctuation.
    Punct(u8),
    /// The end of a line.
    Newline,
}

impl<'a> Lexer<'a> {
    /// The next token and where it starts; `None` at the end.
    pub(super) fn next(&mut self) -> Result<Option<(usize, Token)>, FormatError> {
        let t = self.text;
        while self.pos < t.len() {
            let c = t[self.pos];
            let start = self.pos;
            match c {
                b'\n' => {
                    self.pos += 1;
                    return Ok(Some((start, Token::Newline)));
                }
                b' ' | b'\t' | b'\r' => self.pos += 1,
                b'#' => {
                    while self.pos < t.len() && t[self.pos] != b'\n' {
                        self.pos += 1;
                    }
                }
                b'{' | b'(' | b'[' => {
                    self.pos += 1;
                    return Ok(Some((start, Token::Open(c))));
                }
                b'}' | b')' | b']' => {
                    self.pos += 1;
                    return Ok(Some((start, Token::Close(c))));
                }
                b'"' | b'\'' => return self.string(c).map(|s| Some((start, Token::Str(s)))),
                b'@' => {
                    let triple = t[self.pos..].starts_with(b"@@@");
                    let end = if triple {
                        find(t, self.pos + 3, b"@@@").map(|e| e + 3)
                    } else {
                        find(t, self.pos + 1, b"@").map(|e| e + 1)
                    };
                    let end = end.ok_or_else(|| unclosed(t, start, "asset path"))?;
                    self.pos = end;
                    return Ok(Some((start, Token::Asset(start, end))));
                }
                b'<' => {
                    let end =
                        find(t, self.pos + 1, b">").ok_or_else(|| unclosed(t, start, "path"))?;
                    self.pos = end + 1;
                    return Ok(Some((start, Token::Punct(b'<'))));
                }
                c if c.is_ascii_alphanumeric()
                    || c == b'_'
                    || c == b'-'
                    || c == b'.'
                    || c >= 0x80 =>
                {
                    while self.pos < t.len() {
                        let d = t[self.pos];
                        if d.is_ascii_alphanumeric()
                            || matches!(d, b'_' | b'-' | b'.' | b':' | b'+')
                            || d >= 0x80
                        {
                            self.pos += 1;
                        } else {
                            break;
                        }
                    }
                    let word = String::from_utf8_lossy(&t[start..self.pos]).into_owned();
                    return Ok(Some((start, Token::Word(word))));
                }
                _ => {
                    self.pos += 1;
                    return Ok(Some((start, Token::Punct(c))));
                }
            }
        }
        Ok(None)
    }

    /// A quoted string (single, double or triple quotes), unescaped.
    fn string(&mut self, quote: u8) -> Result<String, FormatError> {
        let t = self.text;
        let start = self.pos;
        let triple = t[self.pos..].starts_with(&[quote, quote, quote]);
        self.pos += if triple { 3 } else { 1 };
        let mut out = Vec::new();
        while self.pos < t.len() {
            let c = t[self.pos];
            if c == b'\\' && self.pos + 1 < t.len() {
                out.push(t[self.pos + 1]);
                self.pos += 2;
                continue;
            }
            if c == quote && (!triple || t[self.pos..].starts_with(&[quote, quote, quote])) {
                self.pos += if triple { 3 } else { 1 };
                return Ok(String::from_utf8_lossy(&out).into_owned());
            }
            if c == b'\n' && !triple {
                break;
            }
            out.push(c);
            self.pos += 1;
        }
        Err(unclosed(t, start, "string"))
    }
}

pub(super) fn find(t: &[u8], from: usize, needle: &[u8]) -> Option<usize> {
    t.get(from..)?
        .windows(needle.len())
        .position(|w| w == needle)
        .map(|p| p + from)
}

pub(super) fn line_of(t: &[u8], at: usize) -> usize {
    t[..at.min(t.len())].iter().filter(|&&c| c == b'\n').count() + 1
}

pub(super) fn unclosed(t: &[u8], at: usize, what: &str) -> FormatError {
    FormatError::invalid(format!("an unclosed {what} at line {}", line_of(t, at)))
}

//! Tokens of the expression language.

use super::error::{ExprError, ExprErrorKind, Span};

/// One token and where it is.
#[derive(Clone, Debug, PartialEq)]
pub struct Token {
    /// What the token is.
    pub kind: TokenKind,
    /// Where it is in the text.
    pub span: Span,
}

/// The kinds of token.
#[derive(Clone, Debug, PartialEq)]
pub enum TokenKind {
    /// A number literal (always finite and non-negative; `-` is an operator).
    Number(f64),
    /// A name: `e1`, `X2`, `np`, `sin`.
    Name(String),
    /// `(`
    LParen,
    /// `)`
    RParen,
    /// `,`
    Comma,
    /// `.`
    Dot,
    /// `|` inner product
    Pipe,
    /// `^` outer product
    Caret,
    /// `+`
    Plus,
    /// `-`
    Minus,
    /// `*` geometric product
    Star,
    /// `**` power
    StarStar,
    /// `/`
    Slash,
    /// `~` reverse
    Tilde,
    /// `@` matrix product (the Euclidean dialect)
    At,
    /// `[`
    LBracket,
    /// `]`
    RBracket,
    /// End of the text.
    End,
}

impl TokenKind {
    /// How the token reads in an error message.
    pub fn describe(&self) -> String {
        match self {
            TokenKind::Number(n) => format!("number {n}"),
            TokenKind::Name(n) => format!("name '{n}'"),
            TokenKind::LParen => "'('".into(),
            TokenKind::RParen => "')'".into(),
            TokenKind::Comma => "','".into(),
            TokenKind::Dot => "'.'".into(),
            TokenKind::Pipe => "'|'".into(),
            TokenKind::Caret => "'^'".into(),
            TokenKind::Plus => "'+'".into(),
            TokenKind::Minus => "'-'".into(),
            TokenKind::Star => "'*'".into(),
            TokenKind::StarStar => "'**'".into(),
            TokenKind::Slash => "'/'".into(),
            TokenKind::Tilde => "'~'".into(),
            TokenKind::At => "'@'".into(),
            TokenKind::LBracket => "'['".into(),
            TokenKind::RBracket => "']'".into(),
            TokenKind::End => "the end of the expression".into(),
        }
    }
}

/// Splits `source` into tokens, ending with [`TokenKind::End`].
pub fn tokenize(source: &str) -> Result<Vec<Token>, ExprError> {
    let bytes = source.as_bytes();
    let mut tokens = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        let start = i;
        let single = |kind| Token {
            kind,
            span: start..start + 1,
        };
        match c {
            b' ' | b'\t' | b'\n' | b'\r' => {
                i += 1;
                continue;
            }
            b'(' => tokens.push(single(TokenKind::LParen)),
            b')' => tokens.push(single(TokenKind::RParen)),
            b',' => tokens.push(single(TokenKind::Comma)),
            b'|' => tokens.push(single(TokenKind::Pipe)),
            b'^' => tokens.push(single(TokenKind::Caret)),
            b'+' => tokens.push(single(TokenKind::Plus)),
            b'-' => tokens.push(single(TokenKind::Minus)),
            b'/' => tokens.push(single(TokenKind::Slash)),
            b'~' => tokens.push(single(TokenKind::Tilde)),
            b'@' => tokens.push(single(TokenKind::At)),
            b'[' => tokens.push(single(TokenKind::LBracket)),
            b']' => tokens.push(single(TokenKind::RBracket)),
            b'*' => {
                if bytes.get(i + 1) == Some(&b'*') {
                    tokens.push(Token {
                        kind: TokenKind::StarStar,
                        span: start..start + 2,
                    });
                    i += 2;
                    continue;
                }
                tokens.push(single(TokenKind::Star));
            }
            b'.' if !bytes.get(i + 1).is_some_and(u8::is_ascii_digit) => {
                tokens.push(single(TokenKind::Dot))
            }
            b'0'..=b'9' | b'.' => {
                let (value, end) = number(source, start)?;
                tokens.push(Token {
                    kind: TokenKind::Number(value),
                    span: start..end,
                });
                i = end;
                continue;
            }
            c if c == b'_' || c.is_ascii_alphabetic() => {
                let mut end = i + 1;
                while end < bytes.len()
                    && (bytes[end] == b'_' || bytes[end].is_ascii_alphanumeric())
                {
                    end += 1;
                }
                tokens.push(Token {
                    kind: TokenKind::Name(source[start..end].to_string()),
                    span: start..end,
                });
                i = end;
                continue;
            }
            _ => {
                let ch = source[start..].chars().next().unwrap_or('?');
                let hint = match ch {
                    '\'' | '"' => ": the language has no strings",
                    '{' | '}' => ": use ( ) to group; there are no sets or dicts",
                    '=' => ": there are no assignments or comparisons",
                    _ => "",
                };
                return Err(ExprError::at(
                    ExprErrorKind::Syntax,
                    format!("unexpected character '{ch}'{hint}"),
                    &(start..start + ch.len_utf8()),
                    source,
                ));
            }
        }
        i += 1;
    }
    tokens.push(Token {
        kind: TokenKind::End,
        span: source.len()..source.len(),
    });
    Ok(tokens)
}

/// Reads a number literal (`12`, `1.5`, `.5`, `2.`, `1e-3`) starting at `start`.
fn number(source: &str, start: usize) -> Result<(f64, usize), ExprError> {
    let bytes = source.as_bytes();
    let mut end = start;
    let digits = |mut end: usize| {
        while end < bytes.len() && bytes[end].is_ascii_digit() {
            end += 1;
        }
        end
    };
    end = digits(end);
    if end < bytes.len() && bytes[end] == b'.' {
        end = digits(end + 1);
    }
    if end < bytes.len() && (bytes[end] == b'e' || bytes[end] == b'E') {
        let mut exp = end + 1;
        if exp < bytes.len() && (bytes[exp] == b'+' || bytes[exp] == b'-') {
            exp += 1;
        }
        let exp_end = digits(exp);
        if exp_end == exp {
            return Err(ExprError::at(
                ExprErrorKind::Syntax,
                "malformed number: the exponent needs digits",
                &(start..exp_end),
                source,
            ));
        }
        end = exp_end;
    }
    let text = &source[start..end];
    let value: f64 = text.parse().map_err(|_| {
        ExprError::at(
            ExprErrorKind::Syntax,
            format!("malformed number '{text}'"),
            &(start..end),
            source,
        )
    })?;
    if !value.is_finite() {
        return Err(ExprError::at(
            ExprErrorKind::Syntax,
            format!("number '{text}' is too large"),
            &(start..end),
            source,
        ));
    }
    if end < bytes.len() && (bytes[end].is_ascii_alphabetic() || bytes[end] == b'_') {
        return Err(ExprError::at(
            ExprErrorKind::Syntax,
            format!(
                "a number runs into a name: write '{text} * {}' with an explicit *",
                &source[end..]
                    .split(|c: char| !c.is_ascii_alphanumeric() && c != '_')
                    .next()
                    .unwrap_or("")
            ),
            &(start..end + 1),
            source,
        ));
    }
    Ok((value, end))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(s: &str) -> Vec<TokenKind> {
        tokenize(s).unwrap().into_iter().map(|t| t.kind).collect()
    }

    #[test]
    fn numbers() {
        for (text, value) in [
            ("12", 12.0),
            ("1.5", 1.5),
            (".5", 0.5),
            ("2.", 2.0),
            ("1e-3", 1e-3),
            ("2.5E+2", 250.0),
        ] {
            assert_eq!(
                kinds(text),
                vec![TokenKind::Number(value), TokenKind::End],
                "{text}"
            );
        }
        assert!(tokenize("1e").unwrap_err().message.contains("exponent"));
        assert!(tokenize("1e999").unwrap_err().message.contains("too large"));
        assert_eq!(tokenize("2e1").unwrap()[0].kind, TokenKind::Number(20.0));
        let e = tokenize("2pi").unwrap_err();
        assert!(e.message.contains("'2 * pi'"), "{e}");
    }

    #[test]
    fn operators_and_names() {
        assert_eq!(
            kinds("X1.max|e2**2"),
            vec![
                TokenKind::Name("X1".into()),
                TokenKind::Dot,
                TokenKind::Name("max".into()),
                TokenKind::Pipe,
                TokenKind::Name("e2".into()),
                TokenKind::StarStar,
                TokenKind::Number(2.0),
                TokenKind::End
            ]
        );
    }

    #[test]
    fn unexpected_characters_say_where() {
        let e = tokenize("__import__('os')").unwrap_err();
        assert_eq!(
            e.to_string(),
            "unexpected character ''': the language has no strings at column 12"
        );
        let e = tokenize("T(é)").unwrap_err();
        assert_eq!(e.column, Some(3));
    }
}

//! Finding the answer in a language model's reply.
//!
//! Models wrap their JSON in prose, numbered reasoning and code fences, write Python dicts
//! (single quotes, `True`, trailing commas), and sometimes leave an expression unquoted.
//! [`parse_relaxed_objects`] reads every object in the text leniently;
//! [`extract_cga_reply`] takes the last one that names variables (`X1`, `X2`, …).

use super::error::{ExprError, ExprErrorKind};
use serde_json::{Map, Value};

/// Longest reply that is searched, in bytes; the rest is ignored.
pub const MAX_REPLY_LENGTH: usize = 256 * 1024;

/// Deepest nesting of objects and lists read.
const MAX_DEPTH: usize = 32;

/// Most places an object is tried from (the last ones in the text), which bounds the work
/// on a hostile reply full of braces.
const MAX_ATTEMPTS: usize = 512;

/// One variable's answer: the expressions to apply, in order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReplyEntry {
    /// The variable, normalised to `X<n>`.
    pub variable: String,
    /// The expressions, applied first to last (`M = Mₙ ··· M₁`).
    pub expressions: Vec<String>,
}

/// Every JSON-like object in `text`, leniently read, with the byte offset where it starts.
/// Objects nested in others are listed too, after their parent. Only the last
/// `MAX_ATTEMPTS` opening braces of the first [`MAX_REPLY_LENGTH`] bytes are tried.
pub fn parse_relaxed_objects(text: &str) -> Vec<(usize, Map<String, Value>)> {
    let text = truncate(text, MAX_REPLY_LENGTH);
    let starts: Vec<usize> = text.match_indices('{').map(|(i, _)| i).collect();
    let mut found = Vec::new();
    for &start in &starts[starts.len().saturating_sub(MAX_ATTEMPTS)..] {
        let mut reader = Reader {
            text,
            pos: start,
            depth: 0,
        };
        if let Some(Value::Object(map)) = reader.value(true) {
            found.push((start, map));
        }
    }
    found
}

/// The per-variable expressions of a CGA reply: the last object in `text` with a key
/// `X<n>` (case-insensitive). Values are an expression or a list of expressions.
///
/// Errors are written for the model that produced the reply.
pub fn extract_cga_reply(text: &str) -> Result<Vec<ReplyEntry>, ExprError> {
    let objects = parse_relaxed_objects(text);
    if objects.is_empty() {
        return Err(ExprError::whole(ExprErrorKind::Reply,
            "no JSON object found in the reply: answer with one JSON object that maps each variable to an expression, such as {\"X1\": \"T(1 * e1)\"}",
        ));
    }
    let chosen = objects
        .iter()
        .rev()
        .find(|(_, map)| map.keys().any(|k| variable_name(k).is_some()));
    let Some((_, map)) = chosen else {
        return Err(ExprError::whole(ExprErrorKind::Reply,
            "the JSON object in the reply names no variables: its keys must be the variables X1, X2, … such as {\"X1\": \"T(1 * e1)\"}",
        ));
    };
    let mut entries = Vec::new();
    for (key, value) in map {
        let Some(variable) = variable_name(key) else {
            continue;
        };
        let expressions = match value {
            Value::String(s) => vec![s.clone()],
            Value::Array(items) => items
                .iter()
                .map(|item| match item {
                    Value::String(s) => Ok(s.clone()),
                    other => Err(ExprError::whole(ExprErrorKind::Reply, format!(
                        "the list for {variable} must hold expression strings, found {other}"
                    ))),
                })
                .collect::<Result<_, _>>()?,
            other => {
                return Err(ExprError::whole(ExprErrorKind::Reply, format!(
                    "the value for {variable} must be an expression string or a list of them, found {other}"
                )))
            }
        };
        if entries.iter().any(|e: &ReplyEntry| e.variable == variable) {
            return Err(ExprError::whole(
                ExprErrorKind::Reply,
                format!("the reply names {variable} twice: give one entry per variable"),
            ));
        }
        entries.push(ReplyEntry {
            variable,
            expressions,
        });
    }
    Ok(entries)
}

/// `X3` for keys `X3`, `x3`, ` X3 `; None for other keys.
fn variable_name(key: &str) -> Option<String> {
    let key = key.trim();
    let digits = key.strip_prefix('X').or_else(|| key.strip_prefix('x'))?;
    (!digits.is_empty() && digits.len() <= 6 && digits.bytes().all(|b| b.is_ascii_digit()))
        .then(|| format!("X{}", digits.trim_start_matches('0')))
        .filter(|v| v.len() > 1)
}

fn truncate(text: &str, max: usize) -> &str {
    if text.len() <= max {
        return text;
    }
    let mut end = max;
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    &text[..end]
}

/// A lenient reader of JSON and Python literals.
struct Reader<'a> {
    text: &'a str,
    pos: usize,
    depth: usize,
}

impl Reader<'_> {
    fn peek(&self) -> Option<u8> {
        self.text.as_bytes().get(self.pos).copied()
    }

    fn skip_space(&mut self) {
        while let Some(b) = self.peek() {
            if b.is_ascii_whitespace() {
                self.pos += 1;
            } else if b == b'#'
                || (b == b'/' && self.text.as_bytes().get(self.pos + 1) == Some(&b'/'))
            {
                while let Some(b) = self.peek() {
                    if b == b'\n' {
                        break;
                    }
                    self.pos += 1;
                }
            } else {
                break;
            }
        }
    }

    /// A value; `in_object` allows the unquoted-expression fallback the caller handles.
    fn value(&mut self, top: bool) -> Option<Value> {
        self.skip_space();
        match self.peek()? {
            b'{' => self.object(),
            b'[' => self.array(b']'),
            b'(' if !top => self.array(b')'),
            b'"' | b'\'' => self.string().map(Value::String),
            b'-' | b'0'..=b'9' => self.number(),
            _ => self.word(),
        }
    }

    fn enter(&mut self) -> Option<()> {
        self.depth += 1;
        (self.depth <= MAX_DEPTH).then_some(())
    }

    fn object(&mut self) -> Option<Value> {
        self.enter()?;
        self.pos += 1; // '{'
        let mut map = Map::new();
        loop {
            self.skip_space();
            match self.peek()? {
                b'}' => {
                    self.pos += 1;
                    self.depth -= 1;
                    return Some(Value::Object(map));
                }
                b'"' | b'\'' => {}
                b if b.is_ascii_alphabetic() || b == b'_' => {}
                _ => return None,
            }
            let key = match self.peek()? {
                b'"' | b'\'' => self.string()?,
                _ => self.identifier()?,
            };
            self.skip_space();
            if self.peek()? != b':' {
                return None;
            }
            self.pos += 1;
            let start = self.pos;
            let value = match self.value(false) {
                Some(v) if self.at_value_end() => v,
                _ => {
                    // An unquoted expression: the raw text up to the next top-level ',' or '}'.
                    self.pos = start;
                    Value::String(self.raw_expression()?)
                }
            };
            map.insert(key, value);
            self.skip_space();
            match self.peek()? {
                b',' => self.pos += 1,
                b'}' => {}
                _ => return None,
            }
        }
    }

    fn at_value_end(&mut self) -> bool {
        self.skip_space();
        matches!(self.peek(), Some(b',') | Some(b'}'))
    }

    fn raw_expression(&mut self) -> Option<String> {
        let start = self.pos;
        let mut depth = 0i32;
        while let Some(b) = self.peek() {
            match b {
                b'(' | b'[' => depth += 1,
                b')' | b']' => depth -= 1,
                b',' | b'}' if depth == 0 => break,
                b'{' | b'"' | b'\'' | b'\n' => return None,
                _ => {}
            }
            self.pos += 1;
        }
        let raw = self.text[start..self.pos].trim();
        (!raw.is_empty() && depth == 0).then(|| raw.to_string())
    }

    fn array(&mut self, close: u8) -> Option<Value> {
        self.enter()?;
        self.pos += 1;
        let mut items = Vec::new();
        loop {
            self.skip_space();
            if self.peek()? == close {
                self.pos += 1;
                self.depth -= 1;
                return Some(Value::Array(items));
            }
            items.push(self.value(false)?);
            self.skip_space();
            match self.peek()? {
                b',' => self.pos += 1,
                b if b == close => {}
                _ => return None,
            }
        }
    }

    fn string(&mut self) -> Option<String> {
        let quote = self.peek()?;
        self.pos += 1;
        let mut out = String::new();
        loop {
            let rest = &self.text[self.pos..];
            let c = rest.chars().next()?;
            self.pos += c.len_utf8();
            match c {
                c if c as u32 == quote as u32 => return Some(out),
                '\\' => {
                    let e = self.text[self.pos..].chars().next()?;
                    self.pos += e.len_utf8();
                    match e {
                        'n' => out.push('\n'),
                        't' => out.push('\t'),
                        'r' => out.push('\r'),
                        'u' => {
                            let hex = self.text.get(self.pos..self.pos + 4)?;
                            let code = u32::from_str_radix(hex, 16).ok()?;
                            out.push(char::from_u32(code).unwrap_or('\u{fffd}'));
                            self.pos += 4;
                        }
                        other => out.push(other),
                    }
                }
                '\n' => return None,
                c => out.push(c),
            }
        }
    }

    fn number(&mut self) -> Option<Value> {
        let start = self.pos;
        while let Some(b) = self.peek() {
            if b.is_ascii_digit() || matches!(b, b'-' | b'+' | b'.' | b'e' | b'E') {
                self.pos += 1;
            } else {
                break;
            }
        }
        let x: f64 = self.text[start..self.pos].parse().ok()?;
        serde_json::Number::from_f64(x).map(Value::Number)
    }

    fn identifier(&mut self) -> Option<String> {
        let start = self.pos;
        while let Some(b) = self.peek() {
            if b.is_ascii_alphanumeric() || b == b'_' {
                self.pos += 1;
            } else {
                break;
            }
        }
        (self.pos > start).then(|| self.text[start..self.pos].to_string())
    }

    fn word(&mut self) -> Option<Value> {
        match self.identifier()?.as_str() {
            "true" | "True" => Some(Value::Bool(true)),
            "false" | "False" => Some(Value::Bool(false)),
            "null" | "None" => Some(Value::Null),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entries(text: &str) -> Vec<(String, Vec<String>)> {
        extract_cga_reply(text)
            .unwrap()
            .into_iter()
            .map(|e| (e.variable, e.expressions))
            .collect()
    }

    fn one(var: &str, expr: &str) -> Vec<(String, Vec<String>)> {
        vec![(var.to_string(), vec![expr.to_string()])]
    }

    #[test]
    fn plain_json() {
        assert_eq!(entries(r#"{"X1": "T(1 * e1)"}"#), one("X1", "T(1 * e1)"));
    }

    #[test]
    fn prose_and_fences() {
        let reply = "Sure! Here is my reasoning:\n1. The sofa moves right.\n2. So we translate along e1.\n\n```json\n{\n  \"X1\": \"T(1 * e1)\"\n}\n```\nLet me know!";
        assert_eq!(entries(reply), one("X1", "T(1 * e1)"));
        let python = "```python\n{'X1': 'R(np.pi/2, e3, e1)', 'X2': ['T(e1)', 'D(2)'],}\n```";
        assert_eq!(
            entries(python),
            vec![
                ("X1".to_string(), vec!["R(np.pi/2, e3, e1)".to_string()]),
                (
                    "X2".to_string(),
                    vec!["T(e1)".to_string(), "D(2)".to_string()]
                ),
            ]
        );
    }

    #[test]
    fn last_object_that_names_variables_wins() {
        let reply = "For example {\"X1\": \"T(e2)\"} would lift it. The answer: {\"X1\": \"T(-1 * e1)\"} {\"note\": 1}";
        assert_eq!(entries(reply), one("X1", "T(-1 * e1)"));
        let nested = r#"{"transformations": {"x1": "T(e3)"}, "explanation": "forward"}"#;
        assert_eq!(entries(nested), one("X1", "T(e3)"));
    }

    #[test]
    fn unquoted_expressions_and_escapes() {
        assert_eq!(
            entries("{X1: T(((X2.max | e2) - (X1.min | e2)) * e2), X2: R(pi, e1, e3)}"),
            vec![
                (
                    "X1".into(),
                    vec!["T(((X2.max | e2) - (X1.min | e2)) * e2)".into()]
                ),
                ("X2".into(), vec!["R(pi, e1, e3)".into()]),
            ]
        );
        assert_eq!(
            entries(r#"{"X1": "T(1 * e1) \u0020"}"#),
            one("X1", "T(1 * e1)  ")
        );
        assert_eq!(
            entries(r"{'X1': 'T(e1)', 'why': 'it\'s right'}"),
            one("X1", "T(e1)")
        );
    }

    #[test]
    fn clear_errors() {
        let e = extract_cga_reply("I cannot do that.").unwrap_err();
        assert!(e.message.starts_with("no JSON object found"), "{e}");
        let e = extract_cga_reply(r#"{"sofa": "T(e1)"}"#).unwrap_err();
        assert!(e.message.contains("names no variables"), "{e}");
        let e = extract_cga_reply(r#"{"X1": 3}"#).unwrap_err();
        assert!(e.message.contains("must be an expression string"), "{e}");
        let e = extract_cga_reply(r#"{"X1": "T(e1)", "x1": "T(e2)"}"#).unwrap_err();
        assert!(e.message.contains("twice"), "{e}");
    }

    #[test]
    fn hostile_replies_are_cheap() {
        let braces = "{".repeat(100_000);
        assert!(extract_cga_reply(&braces).is_err());
        let huge = "x".repeat(10_000_000);
        assert!(extract_cga_reply(&huge).is_err());
    }
}

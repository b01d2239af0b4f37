//! Text from users and files, made safe to print to a terminal.
//!
//! Object names, scene names, instructions and paths are quoted in errors and notes; a
//! hostile scene could name an object `\x1b]0;pwned\x07` (a terminal escape sequence that
//! retitles the window, or worse) or hide text behind a bidi override (`\u{202e}`). Every
//! line the binary prints to stderr goes through [`safe`], which shows such characters as
//! `\u{…}` instead of sending them.

use std::borrow::Cow;

/// Whether `c` must not reach a terminal as it is: C0 controls (NUL, BEL, ESC…), DEL, C1
/// controls (`\u{9b}` is a one-byte CSI), the bidi embeddings, overrides, isolates and
/// marks, and the line and paragraph separators.
pub fn is_unsafe(c: char) -> bool {
    matches!(c,
        '\u{0}'..='\u{1f}'
        | '\u{7f}'..='\u{9f}'
        | '\u{61c}'
        | '\u{200e}' | '\u{200f}'
        | '\u{2028}'..='\u{202e}'
        | '\u{2066}'..='\u{2069}')
}

/// `text` with every [`is_unsafe`] character written `\u{…}` (hexadecimal, as Rust writes
/// it); borrowed when nothing needed escaping.
pub fn safe(text: &str) -> Cow<'_, str> {
    if !text.chars().any(is_unsafe) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 16);
    for c in text.chars() {
        if is_unsafe(c) {
            out.push_str(&format!("\\u{{{:x}}}", c as u32));
        } else {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

/// JSON text with every [`is_unsafe`] character left in it written as a JSON escape
/// (`\u202e`): the same document, safe to print. (Outside strings JSON is ASCII without
/// controls, so such characters can only be inside strings, where the escape means the
/// same character.)
pub fn safe_json(json: &str) -> Cow<'_, str> {
    if !json.chars().any(is_unsafe) {
        return Cow::Borrowed(json);
    }
    let mut out = String::with_capacity(json.len() + 16);
    for c in json.chars() {
        if is_unsafe(c) && !matches!(c, '\n' | '\t' | '\r') {
            out.push_str(&format!("\\u{:04x}", c as u32));
        } else {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

/// Prints one line to stderr, made [`safe`].
#[macro_export]
macro_rules! say {
    ($($arg:tt)*) => {
        eprintln!("{}", $crate::terminal::safe(&format!($($arg)*)))
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn controls_and_bidi_are_shown_not_sent() {
        assert_eq!(
            safe("a\u{1b}]0;pwned\u{7}b\u{202e}c\u{9b}d\u{0}\u{2066}\u{200f}\u{61c}"),
            "a\\u{1b}]0;pwned\\u{7}b\\u{202e}c\\u{9b}d\\u{0}\\u{2066}\\u{200f}\\u{61c}"
        );
        assert!(matches!(safe("tool table — é 中"), Cow::Borrowed(_)));
        let json = serde_json::json!({"name": "x\u{202e}\u{1b}y\u{9b}"}).to_string();
        let shown = safe_json(&json);
        assert!(!shown.chars().any(is_unsafe), "{shown}");
        let back: serde_json::Value = serde_json::from_str(&shown).unwrap();
        assert_eq!(back["name"], "x\u{202e}\u{1b}y\u{9b}");
    }
}

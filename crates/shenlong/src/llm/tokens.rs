//! Token counts estimated locally when a server reports none.

use super::{Message, Usage};
use std::sync::OnceLock;

fn encoder() -> Option<&'static tiktoken_rs::CoreBPE> {
    static ENCODER: OnceLock<Option<tiktoken_rs::CoreBPE>> = OnceLock::new();
    ENCODER
        .get_or_init(|| tiktoken_rs::cl100k_base().ok())
        .as_ref()
}

/// Counts the tokens of `text` with the cl100k tokenizer (GPT-4's); about a quarter of
/// the characters if the tokenizer cannot be loaded.
pub fn count(text: &str) -> u64 {
    match encoder() {
        Some(bpe) => bpe.encode_ordinary(text).len() as u64,
        None => (text.chars().count() as u64).div_ceil(4),
    }
}

/// The usage of an exchange, counted locally: 4 tokens of framing per message, as the
/// chat format adds.
pub fn estimate(messages: &[Message], reply: &str) -> Usage {
    let prompt = messages.iter().map(|m| 4 + count(&m.content)).sum::<u64>() + 3;
    Usage {
        prompt_tokens: prompt,
        completion_tokens: count(reply),
        estimated: true,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_like_the_tokenizer() {
        assert_eq!(count("hello world"), 2);
        let u = estimate(
            &[Message::new("user", "move X1 left")],
            "{\"X1\": \"T(-1 * e1)\"}",
        );
        assert!(u.estimated && u.prompt_tokens > 4 && u.completion_tokens > 5);
    }
}

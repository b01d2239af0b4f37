//! Numbers as files and answers write them: rounded to a nanometre (or nano-unit), so that
//! rounding noise (`0.30000000000000004`) never reaches a file or a user. Below every
//! stage: the scene's listing, the formats and the session's outcomes use it.

/// A number rounded to a nanometre (or nano-unit); −0 becomes 0.
#[must_use]
pub fn tidy(x: f64) -> f64 {
    let r = (x * 1e9).round() / 1e9;
    if r == 0.0 {
        0.0
    } else {
        r
    }
}

/// A number as the scene files write it: rounded by [`tidy`]; whole numbers without a
/// fraction.
#[must_use]
pub fn tidy_json(x: f64) -> serde_json::Value {
    let rounded = tidy(x);
    if rounded.fract() == 0.0 && rounded.abs() < 1e15 {
        serde_json::Value::from(rounded as i64)
    } else {
        serde_json::Value::from(rounded)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn noise_and_negative_zero_are_tidied() {
        assert_eq!(tidy(0.1 + 0.2), 0.3);
        assert_eq!(tidy(-0.0).to_bits(), 0.0f64.to_bits());
        assert_eq!(tidy_json(2.0), serde_json::json!(2));
        assert_eq!(tidy_json(0.25), serde_json::json!(0.25));
    }
}

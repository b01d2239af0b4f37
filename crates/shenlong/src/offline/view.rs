//! Where a turn is seen from: "clockwise as seen from above", "viewed from overhead",
//! "looking down", "in top-down view", "from a bird's eye view" (the default view of
//! SPEC §1, so they change nothing), and "as seen from below" (which reverses the sense).
//! A small grammar rather than a list: an optional lead (`as`, `when`, `if`, `while`),
//! an optional verb of seeing (`seen`, `viewed`, `looking (at it)`, `looked at`, `you'd
//! see it`, `you look (at it)`) with an optional `down`, then where from.

use crate::discourse::{longest_phrase, phrase_at};

/// The view a turn's sense is given in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum View {
    /// From above: the default.
    Above,
    /// From below: clockwise and counter-clockwise swap.
    Below,
}

const LEADS: &[&[&str]] = &[&["as"], &["when"], &["if"], &["while"]];
const SEERS: &[&[&str]] = &[
    &["seen"],
    &["viewed"],
    &["looking", "at", "it"],
    &["looking"],
    &["looked", "at"],
    &["you'd", "see", "it"],
    &["you", "would", "see", "it"],
    &["you", "see", "it"],
    &["you", "look", "at", "it"],
    &["you", "look"],
    &["it's", "seen"],
];
const ABOVE: &[&[&str]] = &[
    &["from", "above"],
    &["from", "overhead"],
    &["from", "the", "top"],
    &["from", "up", "top"],
    &["from", "on", "top"],
    &["from", "the", "ceiling"],
    &["from", "a", "bird's", "eye", "view"],
    &["from", "bird's", "eye", "view"],
];
const BELOW: &[&[&str]] = &[
    &["from", "below"],
    &["from", "underneath"],
    &["from", "beneath"],
    &["from", "the", "bottom"],
    &["from", "under"],
];
/// Whole phrases that name the top view.
const TOP_VIEW: &[&[&str]] = &[
    &["in", "top", "down", "view"],
    &["in", "a", "top", "down", "view"],
    &["in", "the", "top", "down", "view"],
    &["in", "top", "view"],
    &["in", "plan", "view"],
    &["in", "plan"],
    &["top", "down"],
    &["bird's", "eye", "view"],
    &["in", "a", "bird's", "eye", "view"],
];

/// The view phrase starting at word `i`: its length and the view.
pub(crate) fn view_at(words: &[&str], i: usize) -> Option<(usize, View)> {
    if let Some(n) = longest_phrase(words, i, TOP_VIEW) {
        return Some((n, View::Above));
    }
    let mut k = i + longest_phrase(words, i, LEADS).unwrap_or(0);
    let seer = longest_phrase(words, k, SEERS);
    k += seer.unwrap_or(0);
    let down = phrase_at(words, k, &["down"]);
    if down {
        k += 1;
    }
    if let Some(n) = longest_phrase(words, k, ABOVE) {
        return Some((k + n - i, View::Above));
    }
    if let Some(n) = longest_phrase(words, k, BELOW) {
        return Some((k + n - i, View::Below));
    }
    // "looking down": from above, with nothing after.
    (seer.is_some() && down).then_some((k - i, View::Above))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(s: &str) -> Option<(usize, View)> {
        let w: Vec<&str> = s.split(' ').collect();
        view_at(&w, 0)
    }

    #[test]
    fn views_are_read_by_their_parts() {
        for s in [
            "as seen from above",
            "viewed from overhead",
            "when viewed from above",
            "when looking from above",
            "looking down from above",
            "looking from the top",
            "as you'd see it from above",
            "from a bird's eye view",
            "in top down view",
            "seen from above",
            "from the top",
            "looking down",
        ] {
            let n = s.split(' ').count();
            assert_eq!(v(s), Some((n, View::Above)), "{s}");
        }
        assert_eq!(v("as seen from below"), Some((4, View::Below)));
        assert_eq!(v("from the left"), None);
        assert_eq!(v("as far"), None);
    }
}

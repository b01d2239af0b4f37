//! Exclusion: the members a group leaves out — `all the chairs except the front-left one`,
//! `every chair but chair 3`, `the chairs apart from chair 2 and chair 4`.
//!
//! Each left-out phrase is a noun phrase of its own, read among the group (`one` is one
//! of them); a singular one must name one object, and a list goes on while a name or
//! `the … one` follows `and`, `or` or a comma.

use super::index::Tier;
use super::{modifier, words, GroundError, Head, Mode, Reader};
use words::Kind;

impl Reader<'_> {
    /// `except the front-left one`, `but chair 3`, `apart from chair 2 and chair 4` after a
    /// group at token `k`: the objects left out, and where the phrase ends. `noun` is the
    /// group's noun, which `one` stands for.
    ///
    /// # Errors
    /// A left-out phrase that fits several objects where it names one.
    pub(super) fn exclusion(
        &self,
        k: usize,
        group: &[usize],
        noun: &str,
        bound: &[usize],
    ) -> Result<Option<(Vec<usize>, usize)>, GroundError> {
        let w = |k: usize| self.word(k).unwrap_or("");
        let mut q = match (w(k), w(k + 1)) {
            ("except" | "excepting", "for")
            | ("apart" | "aside", "from")
            | ("other", "than")
            | ("save", "for") => k + 2,
            ("except" | "excepting" | "but" | "excluding" | "minus" | "bar", _) => k + 1,
            _ => return Ok(None),
        };
        let mut excluded = Vec::new();
        loop {
            let Some(head) = self.excluded_head(q, group, noun) else {
                return Ok(None);
            };
            let plural = head.plural;
            let text = head.text.clone();
            let np = self.noun_phrase(head, bound, Mode::LeftOut)?;
            if np.objects.len() > 1 && !plural {
                return Err(self.ambiguous(&np.range, &text, &np.objects, 2));
            }
            excluded.extend(np.objects);
            q = np.range.end;
            if self.is_word(q, &["and", "or"])
                || matches!(self.tokens.get(q).map(|t| &t.kind), Some(Kind::Punct(',')))
            {
                let next = q + 1;
                // Another excluded phrase follows only if a name or "the … one" does.
                let more = (next..(next + 4).min(self.tokens.len()))
                    .any(|t| self.head_at(t).is_some() || self.is_word(t, &["one"]));
                if more && !self.word(next).is_some_and(words::is_verb) {
                    q = next;
                    continue;
                }
            }
            return Ok(Some((excluded, q)));
        }
    }

    /// The head of a left-out phrase starting at token `q` (after its determiner and
    /// modifiers): a name, or `one` / `ones` standing for the group's noun.
    fn excluded_head(&self, q: usize, group: &[usize], noun: &str) -> Option<Head> {
        // Skip to the head: a name, or "one" for one of the group.
        let mut h = q;
        while h < self.tokens.len()
            && h < q + 5
            && self.head_at(h).is_none()
            && !self.is_word(h, &["one", "ones"])
        {
            if !(self.word(h).is_some_and(words::is_determiner) || self.is_premodifier(h)) {
                return None;
            }
            h += 1;
        }
        match self.head_at(h) {
            Some(head) => Some(head),
            None if self.is_word(h, &["one", "ones"]) => Some(Head {
                range: h..h + 1,
                objects: group.to_vec(),
                literal: group.to_vec(),
                generic: false,
                tier: Tier::Name,
                plural: self.is_word(h, &["ones"]),
                text: noun.to_string(),
                reason: modifier("one of them"),
                typo: None,
            }),
            None => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::{means, refused, with_reader};

    /// The names left out of the group `group` (names) by the words at token `k` of
    /// `text`, and the token after them.
    fn left_out(text: &str, k: usize, group: &[&str]) -> Option<(Vec<String>, usize)> {
        with_reader("dining_room", text, |r| {
            let group: Vec<usize> = group.iter().map(|n| r.scene.find(n).unwrap()).collect();
            let (excluded, end) = r.exclusion(k, &group, "chair", &[]).unwrap()?;
            Some((r.names(&excluded), end))
        })
    }

    #[test]
    fn the_left_out_phrases_are_read_with_their_end() {
        let all = ["chair", "chair 2", "chair 3", "chair 4"];
        let (names, end) = left_out("lift all the chairs but chair 3 10 cm", 4, &all).unwrap();
        assert_eq!((names, end), (vec!["chair 3".to_string()], 7));
        let (names, end) = left_out(
            "lift the chairs apart from chair 2 and chair 4 now",
            3,
            &all,
        )
        .unwrap();
        assert_eq!(names, ["chair 2", "chair 4"]);
        assert_eq!(end, 10);
        let (names, _) =
            left_out("lift all the chairs except the front-left one", 4, &all).unwrap();
        assert_eq!(names, ["chair 3"]);
        // No exclusion word: nothing is left out.
        assert!(left_out("lift all the chairs 10 cm", 4, &all).is_none());
    }

    #[test]
    fn groups_leave_out_what_follows_except_or_but() {
        means(
            "dining_room",
            "lift all the chairs except the front-left one 10 cm",
            &[&["chair", "chair 2", "chair 4"]],
        );
        means(
            "dining_room",
            "lift every chair but chair 3 10 cm",
            &[&["chair", "chair 2", "chair 4"]],
        );
        // What is left out must be one of them, and say which.
        refused(
            "dining_room",
            "lift all the chairs except the sideboard",
            &["'sideboard' is not one of them"],
        );
        refused(
            "dining_room",
            "lift all the chairs except the chair",
            &["chair 2"],
        );
    }
}

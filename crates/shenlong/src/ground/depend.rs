//! Dependents: what belongs to the objects a phrase names, said after it — "table 4 and
//! its chairs", "the desk with its stool", "the beds along with their tables" — found from
//! the scene: what rests on one of them, or stands drawn up to one of them (nearer to it
//! than to anything else, within [`DRAWN_UP_METRES`] of its footprint).

use super::{GroundError, Np, Reader, Reason, ReasonKind};
use crate::geometry::Aabb;
use crate::scene::Scene;

/// How far a chair may stand from its table's footprint and still be drawn up to it.
pub(crate) const DRAWN_UP_METRES: f64 = 0.5;

/// The words that join dependents to a phrase, longest first.
const JOINS: &[&[&str]] = &[
    &["along", "with"],
    &["together", "with"],
    &["and", "also"],
    &["and"],
    &["with"],
    &["plus"],
];

impl Reader<'_> {
    /// `np` with the dependents said right after it ("and its chairs"), when they are;
    /// unchanged otherwise. After a `generic` phrase ("table 2 with everything on it and
    /// its chairs") "its" is the object named before it, not what is on it.
    ///
    /// # Errors
    /// Dependents of a kind none of whose objects belong to the phrase's objects.
    pub(super) fn with_dependents(&mut self, mut np: Np, generic: bool) -> Result<Np, GroundError> {
        let k = np.range.end;
        // "bench A2, its stools and whatever's on it": a comma joins too.
        let comma = matches!(
            self.tokens.get(k).map(|t| &t.kind),
            Some(super::words::Kind::Punct(','))
        );
        let join = JOINS
            .iter()
            .find(|j| {
                j.iter()
                    .enumerate()
                    .all(|(i, w)| self.is_word(k + i, &[w]) && !self.consumed[k + i])
            })
            .map(|j| j.len())
            .or(comma.then_some(1));
        let Some(join) = join else {
            return Ok(np);
        };
        let owner = k + join;
        if !self.is_word(owner, &["its", "their"]) {
            return Ok(np);
        }
        // "its two armchairs": a count said is checked against what is found.
        let count = self
            .word(owner + 1)
            .and_then(super::words::count_word)
            .filter(|_| self.word(owner + 1) != Some("pair"));
        let noun = owner + 1 + usize::from(count.is_some());
        let Some(head) = self.head_at(noun) else {
            return Ok(np);
        };
        let boxes = self.scene.world_aabbs();
        let owners = if generic && !self.antecedent.is_empty() {
            self.antecedent.clone()
        } else {
            np.objects.clone()
        };
        let mut found = self.dependents_of_kind(&head, &owners, &boxes);
        // "its chairs and lamp", "their stools and their lamps": more kinds, each found.
        let end = if found.is_empty() {
            head.range.end
        } else {
            self.more_dependents(head.range.end, &owners, &boxes, &mut found)
        };
        let range = np.range.start..end;
        if found.is_empty() {
            return Err(GroundError::NoPick {
                phrase: self.span_text(&range),
                reason: format!(
                    "no {} rests on or is drawn up to {}",
                    head.text,
                    super::error::list(&self.names(&owners))
                ),
            });
        }
        if let Some(n) = count.filter(|&n| n != found.len()) {
            return Err(GroundError::NoPick {
                phrase: self.span_text(&range),
                reason: format!(
                    "{n} were said, but {} ({}) rest on or are drawn up to {}",
                    found.len(),
                    super::error::list(&self.names(&found)),
                    super::error::list(&self.names(&owners))
                ),
            });
        }
        np.reasons.push(Reason {
            kind: ReasonKind::Group,
            detail: format!(
                "{} rest on or are drawn up to it",
                super::error::list(&self.names(&found))
            ),
        });
        np.owners.get_or_insert_with(|| np.objects.clone());
        np.objects.extend(found);
        np.range = range;
        Ok(np)
    }
}

impl Reader<'_> {
    /// The objects of `head`'s kind (not `owners` themselves) that belong to `owners`
    /// ([`belongs_to`]).
    fn dependents_of_kind(
        &self,
        head: &super::Head,
        owners: &[usize],
        boxes: &[Aabb],
    ) -> Vec<usize> {
        let kind: Vec<usize> = head
            .literal
            .iter()
            .chain(&head.objects)
            .copied()
            .filter(|o| !owners.contains(o))
            .collect();
        kind.iter()
            .copied()
            .filter(|&d| belongs_to(self.scene, boxes, d, owners, &kind))
            .collect()
    }
}

impl Reader<'_> {
    /// "its bench", "their tables" at token `k` (the possessive) with the objects named
    /// last (`owned`): the objects of the head's kind that they rest on or are drawn up to
    /// ("stool 12 … its bench", "the beaker … its bench"). `None` where no head follows,
    /// nothing was named before, or none of the kind owns them.
    pub(super) fn possessed_at(&self, k: usize, owned: &[usize]) -> Option<Np> {
        if owned.is_empty() || !self.is_word(k, &["its", "their"]) || self.consumed[k] {
            return None;
        }
        let head = self.head_at(k + 1)?;
        if head.generic {
            return None;
        }
        let boxes = self.scene.world_aabbs();
        let owners: Vec<usize> = head
            .objects
            .iter()
            .copied()
            .filter(|&c| {
                !owned.contains(&c)
                    && owned.iter().any(|&a| {
                        self.scene.rests_on_through(a, c)
                            || belongs_to(self.scene, &boxes, a, &[c], owned)
                    })
            })
            .collect();
        if !owners.is_empty() {
            let detail = format!(
                "{} what {} rests on or is drawn up to",
                super::error::list(&self.names(&owners)),
                super::error::list(&self.names(owned))
            );
            return Some(Np::group(k..head.range.end, owners, head.text, detail));
        }
        // "table 6 … along with its chairs and lamp": what belongs to them, kind by kind.
        let mut found = self.dependents_of_kind(&head, owned, &boxes);
        if found.is_empty() {
            return None;
        }
        let end = self.more_dependents(head.range.end, owned, &boxes, &mut found);
        let detail = format!(
            "{} rest on or are drawn up to {}",
            super::error::list(&self.names(&found)),
            super::error::list(&self.names(owned))
        );
        Some(Np::group(k..end, found, head.text, detail))
    }

    /// After dependents ending at token `end`: "and lamp", "and their lamps" — more kinds
    /// that belong to `owners`, added to `found`. The token after the last one read.
    fn more_dependents(
        &self,
        mut end: usize,
        owners: &[usize],
        boxes: &[Aabb],
        found: &mut Vec<usize>,
    ) -> usize {
        while self.is_word(end, &["and"]) {
            let at = end + 1 + usize::from(self.is_word(end + 1, &["its", "their"]));
            let Some(more) = self.head_at(at).filter(|h| !h.generic) else {
                break;
            };
            let also = self.dependents_of_kind(&more, owners, boxes);
            if also.is_empty() {
                break;
            }
            found.extend(also);
            end = more.range.end;
        }
        found.sort_unstable();
        found.dedup();
        end
    }
}

impl Reader<'_> {
    /// "…, stools and all", "chairs and all", "…, chairs too" at token `k`: the objects of
    /// that kind that belong to the objects named last (`owners`: resting on one, or drawn
    /// up to one), as a phrase of their own up to the end of "and all". `None` where the words are not
    /// that, or none of the kind belongs to them.
    pub(super) fn and_all_at(&self, k: usize, owners: &[usize]) -> Option<Np> {
        if owners.is_empty() || self.consumed[k] {
            return None;
        }
        let head = self.head_at(k)?;
        let end = head.range.end;
        // "stools and all"; after a comma also "chairs too", "chairs as well", "chairs
        // included".
        let after_comma =
            k > 0 && matches!(self.tokens[k - 1].kind, super::words::Kind::Punct(','));
        let closer = if self.is_word(end, &["and"]) && self.is_word(end + 1, &["all"]) {
            2
        } else if after_comma && self.is_word(end, &["too", "included"]) {
            1
        } else if after_comma && self.is_word(end, &["as"]) && self.is_word(end + 1, &["well"]) {
            2
        } else {
            return None;
        };
        if head.generic || !head.plural {
            return None;
        }
        let closes = match self.tokens.get(end + closer).map(|t| &t.kind) {
            None => true,
            Some(super::words::Kind::Punct(c)) => matches!(c, ',' | '.' | ';' | '!' | '?'),
            _ => false,
        };
        if !closes {
            return None;
        }
        let kind: Vec<usize> = head
            .objects
            .iter()
            .copied()
            .filter(|o| !owners.contains(o))
            .collect();
        let boxes = self.scene.world_aabbs();
        let found: Vec<usize> = kind
            .iter()
            .copied()
            .filter(|&d| belongs_to(self.scene, &boxes, d, owners, &kind))
            .collect();
        if found.is_empty() {
            return None;
        }
        let detail = format!(
            "{} rest on or are drawn up to {}",
            super::error::list(&self.names(&found)),
            super::error::list(&self.names(owners))
        );
        // "and all" ("too" …) stays in the text: it tells the translator they go along.
        Some(Np::group(k..end, found, head.text, detail))
    }
}

impl Reader<'_> {
    /// Of `candidates`, the one object that an object named before (`bound`, not itself a
    /// candidate) rests on — directly or through what it stands on — or is drawn up to
    /// ([`belongs_to`]), with that object. `None` where none or several do.
    pub(super) fn owner_of_named(
        &self,
        candidates: &[usize],
        bound: &[usize],
    ) -> Option<(usize, usize)> {
        let boxes = self.scene.world_aabbs();
        let mut found: Option<(usize, usize)> = None;
        for &a in bound.iter().filter(|a| !candidates.contains(a)) {
            for &c in candidates {
                if self.scene.rests_on_through(a, c)
                    || belongs_to(self.scene, &boxes, a, &[c], bound)
                {
                    match found {
                        Some((o, _)) if o != c => return None,
                        _ => found = Some((c, a)),
                    }
                }
            }
        }
        found
    }
}

/// Whether object `d` belongs to one of `owners`: it rests on one, or stands drawn up to
/// one — the nearest object standing up (taller than 5 cm: not a rug) that is not of its
/// own kind (`kind`) is an owner, within [`DRAWN_UP_METRES`] of its footprint.
pub(crate) fn belongs_to(
    scene: &Scene,
    boxes: &[Aabb],
    d: usize,
    owners: &[usize],
    kind: &[usize],
) -> bool {
    if scene.objects[d]
        .support
        .is_some_and(|s| owners.contains(&s))
    {
        return true;
    }
    drawn_up_to(scene, boxes, d, kind).is_some_and(|o| owners.contains(&o))
}

/// What object `d` stands drawn up to: the nearest object standing up (taller than 5 cm:
/// a rug under it is not what it is drawn up to) that is not of its own kind (`kind`),
/// within [`DRAWN_UP_METRES`] of its footprint.
pub(crate) fn drawn_up_to(
    scene: &Scene,
    boxes: &[Aabb],
    d: usize,
    kind: &[usize],
) -> Option<usize> {
    (0..scene.objects.len())
        .filter(|&o| o != d && !kind.contains(&o) && boxes[o].size().y > 0.05)
        .map(|o| (boxes[d].floor_gap(&boxes[o]), o))
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .filter(|&(g, _)| g <= DRAWN_UP_METRES)
        .map(|(_, o)| o)
}

//! A session's conversation: what it remembers of the turn before, and how a follow-up
//! ([`super::follow_up`]) becomes an operation — an instruction to run with what "it"
//! means, motions to repeat, poses to go back to, or an undo.
//!
//! Nothing here guesses: a follow-up with nothing before it to lean on is refused in one
//! line that says why.

use super::error::{Choices, ErrorKind, OpError};
use super::follow_up::{self, Amount, FollowUp, Steps, Which};
use crate::ground::Grounder;
use crate::scene::{Object, Scene};
use cga::Similarity;
use glam::DQuat;
#[cfg(test)]
use glam::DVec3;
use std::ops::Range;
use std::sync::Arc;

/// How many earlier edits "put it back" can reach.
const MAX_RETURNS: usize = 64;

/// The phrases of an instruction that named objects: their bytes and objects.
pub(crate) type Phrases = Vec<(Range<usize>, Vec<usize>)>;

/// What the conversation remembers; cheap to copy into a working copy.
#[derive(Clone, Debug, Default)]
pub(crate) struct Context {
    /// The last operation that moved objects.
    edit: Option<Arc<Edited>>,
    /// An instruction refused since then.
    refusal: Option<Arc<Refusal>>,
    returns: Arc<Vec<ReturnPoint>>,
}

/// An instruction refused, with the phrase that could mean several objects, if that was
/// why.
#[derive(Clone, Debug)]
struct Refusal {
    instruction: String,
    ambiguity: Option<Box<Choices>>,
}

/// What an operation that moved objects leaves for the next turn.
#[derive(Clone, Debug, Default)]
pub(crate) struct Edited {
    /// The instruction as run (trimmed); `None` for a repeat, an apply, an undo.
    pub instruction: Option<String>,
    /// The objects it moved itself: what "it" means next.
    pub acted: Vec<usize>,
    /// The phrases of the instruction that named objects: their bytes and objects.
    pub phrases: Phrases,
    /// Each acted object's motion about its pivot, for "again" and "a bit more".
    pub motions: Vec<(usize, Similarity)>,
}

impl Edited {
    /// The phrase of the instruction that named what the edit moved: its bytes and
    /// objects.
    fn acted_phrase(&self) -> Option<&(Range<usize>, Vec<usize>)> {
        self.phrases
            .iter()
            .find(|(_, objects)| objects.iter().any(|o| self.acted.contains(o)))
    }

    /// The instruction as run, or the refusal saying that the last change was none whose
    /// `part` can be changed.
    fn instruction_to_change(&self, part: &str) -> Result<&str, OpError> {
        self.instruction.as_deref().ok_or_else(|| {
            refuse(format!(
                "the last change was not an instruction whose {part} can be changed: say the whole instruction"
            ))
        })
    }
}

/// An object a change moved: its index, the acted object it went with (itself, or what
/// carried it), its state before, its pose after, and the pose then of what it rested on
/// before (so that it goes back onto it where that has moved since).
pub(crate) type MovedState = (usize, usize, Object, Similarity, Option<Similarity>);

/// The objects one change moved, as they were before it, for "put it back".
#[derive(Clone, Debug)]
struct ReturnPoint {
    id: u64,
    objects: Vec<MovedState>,
}

/// What `changes` (each object as it was and as it is in `scene`) moved, each with the
/// one of `acted` it went with.
pub(crate) fn moved_states(
    acted: &[usize],
    changes: &[(usize, Object, Object)],
    scene: &Scene,
) -> Vec<MovedState> {
    let pose_before = |s: usize| {
        changes
            .iter()
            .find(|(j, _, _)| *j == s)
            .map_or_else(|| scene.objects[s].similarity(), |(_, a, _)| a.similarity())
    };
    changes
        .iter()
        .filter(|(_, a, b)| a.pose_differs(b))
        .map(|(i, a, b)| {
            let support = a
                .support
                .filter(|&s| s < scene.objects.len())
                .map(pose_before);
            (
                *i,
                group_of(scene, *i, acted),
                a.clone(),
                b.similarity(),
                support,
            )
        })
        .collect()
}

/// What a turn asks the session to do.
#[derive(Debug)]
pub(crate) enum Plan {
    /// Run an instruction; `focus`: what "it" means (with `from_last`: the last edit's
    /// objects, not a selection); `undo_first`: take the last change back before.
    Edit {
        instruction: String,
        focus: Vec<usize>,
        from_last: bool,
        undo_first: bool,
    },
    /// Apply these motions (about each object's pivot).
    Motions(Vec<(usize, Similarity)>),
    /// Put these objects back in these states: the ones named first (`named` of them),
    /// then what they carried.
    Restore {
        states: Vec<(usize, Object)>,
        named: usize,
    },
    /// Take the last change back.
    Undo,
}

/// A refusal of a follow-up.
fn refuse(message: impl Into<String>) -> OpError {
    OpError::new(ErrorKind::NotUnderstood, message)
}

impl Context {
    /// The objects "it" means now: what the last edit moved.
    pub fn focus(&self) -> &[usize] {
        self.edit.as_deref().map_or(&[], |e| &e.acted)
    }

    /// The last edit's instruction and its phrases, if it had one.
    pub fn last_instruction(&self) -> Option<(String, Phrases)> {
        let e = self.edit.as_deref()?;
        e.instruction.clone().map(|i| (i, e.phrases.clone()))
    }

    /// Remembers a refused instruction.
    pub fn refused(&mut self, instruction: &str, ambiguity: Option<Box<Choices>>) {
        self.refusal = Some(Arc::new(Refusal {
            instruction: instruction.trim().to_string(),
            ambiguity,
        }));
    }

    /// Remembers a change made: the turn, and (`moved`: its id and [`moved_states`])
    /// the objects it moved as they were.
    pub fn edited(&mut self, turn: Edited, moved: Option<(u64, Vec<MovedState>)>) {
        if let Some((id, objects)) = moved {
            let returns = Arc::make_mut(&mut self.returns);
            returns.push(ReturnPoint { id, objects });
            if returns.len() > MAX_RETURNS {
                returns.remove(0);
            }
        }
        self.edit = Some(Arc::new(turn));
        self.refusal = None;
    }

    /// Hears an undo (`undo`) or a redo of change `id`, which changed `changes`: an undone
    /// change is no longer one to put things back from; a redone one is again. "It" is
    /// then what the step moved.
    pub fn stepped(
        &mut self,
        id: u64,
        undo: bool,
        changes: &[(usize, Object, Object)],
        scene: &Scene,
    ) {
        let moved: Vec<usize> = changes
            .iter()
            .filter(|(_, a, b)| a.pose_differs(b))
            .map(|(i, _, _)| *i)
            .collect();
        let turn = Edited {
            acted: moved,
            ..Edited::default()
        };
        if undo {
            Arc::make_mut(&mut self.returns).retain(|r| r.id != id);
            self.edit = Some(Arc::new(turn));
            self.refusal = None;
        } else {
            let states = moved_states(&turn.acted, changes, scene);
            self.edited(turn, Some((id, states)));
        }
    }

    /// What `instruction` asks for, given the turn before and the `selected` objects.
    ///
    /// # Errors
    /// A follow-up with nothing to lean on, or that cannot be carried out as said.
    pub fn plan(
        &self,
        instruction: &str,
        selected: &[usize],
        scene: &Scene,
        grounder: &Grounder,
    ) -> Result<Plan, OpError> {
        let after_refusal = self.refusal.as_ref().is_some_and(|r| r.ambiguity.is_some());
        let plain = |text: String| {
            let (focus, from_last) = if selected.is_empty() {
                (self.focus().to_vec(), true)
            } else {
                (selected.to_vec(), false)
            };
            Plan::Edit {
                instruction: text,
                focus,
                from_last,
                undo_first: false,
            }
        };
        let Some(follow) = follow_up::read(instruction, after_refusal) else {
            return Ok(plain(instruction.to_string()));
        };
        match follow {
            FollowUp::Repeat(amount) => Ok(Plan::Motions(self.repeat(amount)?)),
            FollowUp::Toward(text) => {
                if self.focus().is_empty() && selected.is_empty() {
                    return Err(nothing_before(instruction));
                }
                Ok(plain(text))
            }
            FollowUp::Undo => Ok(Plan::Undo),
            FollowUp::UndoMany(steps) => self.undo_many(steps, scene),
            FollowUp::Back(Which::All) => self.undo_many(Steps::All, scene),
            FollowUp::Back(which) => self.back(&which, selected, scene, grounder),
            FollowUp::Also(np) => {
                let (text, head) = self.replace_acted(&np)?;
                // "the other one too": the one other object the noun names.
                let text = if mentions_other(&np) {
                    self.other(&head, scene, grounder)?
                } else {
                    text
                };
                Ok(Plan::Edit {
                    instruction: text,
                    focus: Vec::new(),
                    from_last: true,
                    undo_first: false,
                })
            }
            FollowUp::Instead(np) => self.instead(&np, scene, grounder),
            FollowUp::InsteadPlace(pp) => self.instead_place(&pp),
            FollowUp::InsteadWay(way) => self.instead_way(&way, true),
            FollowUp::SameWay(way) => self.instead_way(&way, false),
            FollowUp::Unclear(_) if self.focus().is_empty() && selected.is_empty() => {
                Err(nothing_before(instruction))
            }
            FollowUp::Unclear(why) => Err(refuse(why)),
        }
    }

    /// The last edit, or a refusal saying there is none.
    fn last_edit(&self, what: &str) -> Result<&Edited, OpError> {
        match self.edit.as_deref() {
            Some(e) if !e.acted.is_empty() => Ok(e),
            _ => Err(refuse(format!(
                "\"{what}\" follows an edit, and there is none before it in this session: say the whole instruction"
            ))),
        }
    }

    /// The last edit's motions again, scaled.
    fn repeat(&self, amount: Amount) -> Result<Vec<(usize, Similarity)>, OpError> {
        let last = self.last_edit("again")?;
        if last.motions.is_empty() {
            return Err(refuse(
                "the last change was not a motion to repeat: say the whole instruction",
            ));
        }
        let k = match amount {
            Amount::Bare(n) => {
                let said = last
                    .instruction
                    .as_deref()
                    .and_then(|text| follow_up::in_unit_of(n, text))
                    .ok_or_else(|| {
                        refuse(format!(
                            "\"{n}\" of what? the last instruction said no unit: say \"another {n} cm\" or \"{n} more degrees\""
                        ))
                    })?;
                return self.repeat(said);
            }
            Amount::Times(k) => k,
            Amount::Bit(sign) => {
                let (_, m) = last.motions[0];
                let angle = m.rotation.to_axis_angle().1.abs();
                let small = if m.translation.length() > 1e-9 {
                    crate::offline::amounts::BIT_METRES / m.translation.length()
                } else if angle > 1e-9 {
                    crate::offline::amounts::BIT_DEGREES.to_radians() / angle
                } else {
                    0.5
                };
                sign * small.min(if sign < 0.0 { 0.5 } else { 1.0 })
            }
            Amount::Metres(metres) => {
                let length = last.motions[0].1.translation.length();
                if length < 1e-9 {
                    return Err(refuse(
                        "the last change was not a move: say which way to move it",
                    ));
                }
                metres / length
            }
            Amount::Degrees(degrees) => {
                let angle = last.motions[0].1.rotation.to_axis_angle().1.abs();
                if angle < 1e-9 {
                    return Err(refuse(
                        "the last change was not a turn: say which way to turn it",
                    ));
                }
                degrees.to_radians() / angle
            }
        };
        Ok(last
            .motions
            .iter()
            .map(|&(i, m)| (i, scaled(&m, k)))
            .collect())
    }

    /// "Undo both", "undo everything": each object the last `steps` changes moved, as it
    /// was before the first of them.
    fn undo_many(&self, steps: Steps, scene: &Scene) -> Result<Plan, OpError> {
        let total = self.returns.len();
        let n = match steps {
            Steps::All => total,
            Steps::Last(n) => n,
        };
        if total == 0 {
            return Err(refuse(
                "nothing has been moved in this session: there is nothing to take back",
            ));
        }
        if n > total {
            return Err(refuse(format!(
                "only {total} change{} of this session can be taken back, not {n}: say \"undo everything\" for all of them",
                if total == 1 { "" } else { "s" }
            )));
        }
        let mut states: Vec<(usize, Object)> = Vec::new();
        for point in &self.returns[total - n..] {
            for (i, _, before, _, _) in &point.objects {
                if !states.iter().any(|(j, _)| j == i) {
                    states.push((*i, before.clone()));
                }
            }
        }
        let named = states.len();
        if states
            .iter()
            .all(|(i, s)| !scene.objects[*i].pose_differs(s))
        {
            return Err(refuse("everything is already where it was"));
        }
        Ok(Plan::Restore { states, named })
    }

    /// The objects moved themselves in the session, the most recent first, each once.
    fn moved_in_session(&self) -> Vec<usize> {
        let mut out: Vec<usize> = Vec::new();
        for point in self.returns.iter().rev() {
            for (i, with, _, _, _) in &point.objects {
                if i == with && !out.contains(i) {
                    out.push(*i);
                }
            }
        }
        out
    }

    /// The objects "put … back" means, by `which`.
    fn back_targets(
        &self,
        which: &Which,
        selected: &[usize],
        scene: &Scene,
        grounder: &Grounder,
    ) -> Result<Vec<usize>, OpError> {
        let moved = self.moved_in_session();
        Ok(match which {
            Which::Named(words) => ground_phrase(words, scene, grounder)?,
            Which::Last | Which::All if !selected.is_empty() => selected.to_vec(),
            Which::Last | Which::All => self.last_edit("put it back")?.acted.clone(),
            Which::Other => {
                let others: Vec<usize> = moved
                    .iter()
                    .copied()
                    .filter(|o| !self.focus().contains(o))
                    .collect();
                match others.as_slice() {
                    [one] => vec![*one],
                    [] => {
                        return Err(refuse(
                            "\"the other one\": nothing else has been moved in this session",
                        ))
                    }
                    many => {
                        return Err(refuse(format!(
                            "\"the other one\" could be any of {} objects moved in this session: {}; name it",
                            many.len(),
                            names_of(scene, many)
                        )))
                    }
                }
            }
            Which::Both => match moved.as_slice() {
                [a, b] => vec![*a, *b],
                [_] | [] => {
                    return Err(refuse(
                        "\"both\": only one object has been moved in this session",
                    ))
                }
                many => {
                    return Err(refuse(format!(
                    "\"both\" of which? {} objects have been moved in this session: {}; name them",
                    many.len(),
                    names_of(scene, many)
                )))
                }
            },
            Which::First => {
                let Some(first) = moved.last() else {
                    return Err(refuse(
                        "nothing has been moved in this session: there is nothing to put back",
                    ));
                };
                vec![*first]
            }
        })
    }

    /// Where to put objects back: the state each had before the last change that moved it.
    fn back(
        &self,
        which: &Which,
        selected: &[usize],
        scene: &Scene,
        grounder: &Grounder,
    ) -> Result<Plan, OpError> {
        let targets = self.back_targets(which, selected, scene, grounder)?;
        let mut named: Vec<(usize, Object)> = Vec::new();
        let mut carried: Vec<(usize, Object)> = Vec::new();
        for t in targets {
            let point = self
                .returns
                .iter()
                .rev()
                .find(|r| r.objects.iter().any(|o| o.0 == t))
                .ok_or_else(|| refuse(format!(
                    "'{}' has not been moved in this session: there is no earlier place to put it back to",
                    scene.objects[t].name
                )))?;
            for (i, with, before, after, support) in &point.objects {
                if *i == t {
                    named.push((*i, onto_support(before, *support, scene)));
                } else if *with == t && scene.objects[*i].similarity() == *after {
                    // What went with it, and has not moved since.
                    carried.push((*i, before.clone()));
                }
            }
        }
        carried.retain(|(i, _)| !named.iter().any(|n| n.0 == *i));
        carried.dedup_by_key(|c| c.0);
        let count = named.len();
        named.extend(carried);
        Ok(Plan::Restore {
            states: named,
            named: count,
        })
    }

    /// The last instruction with the phrase naming what it moved replaced by `np`; the
    /// phrase's head noun, for "one".
    fn replace_acted(&self, np: &str) -> Result<(String, String), OpError> {
        let last = self.last_edit(np)?;
        let instruction = last.instruction_to_change("object")?;
        let (span, _) = last
            .acted_phrase()
            .ok_or_else(|| refuse("could not tell which words of the last instruction named what it moved: say the whole instruction"))?;
        let head = head_noun(instruction.get(span.clone()).unwrap_or_default());
        let np = with_determiner(&with_head(np, &head));
        Ok((splice(instruction, span.start, span.end, &np)?, head))
    }

    /// "no, the left one": after a refusal, the refused instruction with the phrase it
    /// could not choose for replaced; after an edit, the edit undone and made again on the
    /// object named now.
    fn instead(&self, np: &str, scene: &Scene, grounder: &Grounder) -> Result<Plan, OpError> {
        if let Some(Refusal {
            instruction,
            ambiguity: Some(choices),
        }) = self.refusal.as_deref()
        {
            if mentions_other(np) {
                return Err(refuse(format!(
                    "\"{np}\" has nothing to be other than: nothing was chosen; name one of {}",
                    choices
                        .objects
                        .iter()
                        .map(|o| format!("'{o}'"))
                        .collect::<Vec<_>>()
                        .join(", ")
                )));
            }
            let head = head_noun(&choices.phrase);
            let bare = np.trim_matches(|c: char| !c.is_alphanumeric());
            let picks = np
                .split_whitespace()
                .any(|w| matches!(w.to_lowercase().as_str(), "one" | "ones"))
                || head_noun(np) == head
                || choices.objects.iter().any(|o| o.eq_ignore_ascii_case(bare));
            if !picks {
                return Err(refuse(format!(
                    "\"{np}\" is not one of the {} \"{}\" could mean: {}",
                    choices.total,
                    choices.phrase,
                    choices
                        .objects
                        .iter()
                        .map(|o| format!("'{o}'"))
                        .collect::<Vec<_>>()
                        .join(", ")
                )));
            }
            let [start, end] = choices.span;
            let np = with_head(np, &head);
            let text = splice(instruction, start, end, &np)?;
            return Ok(Plan::Edit {
                instruction: text,
                focus: Vec::new(),
                from_last: false,
                undo_first: false,
            });
        }
        let (text, head) = self.replace_acted(np)?;
        let said = head_noun(np);
        let text = if mentions_other(np) && !matches!(said.as_str(), "other" | "") && said != head {
            self.other_destination(np, &said, scene, grounder)?
        } else if mentions_other(np) {
            self.other(&head, scene, grounder)?
        } else if let Some(text) = self.destination_named(np, &head, scene, grounder)? {
            text
        } else {
            text
        };
        Ok(Plan::Edit {
            instruction: text,
            focus: Vec::new(),
            from_last: false,
            undo_first: true,
        })
    }

    /// For "no, the table" after "put the mug on the shelf": the last instruction with
    /// its destination replaced when the phrase means the destination; `None` when it
    /// means what moved (or says "one"), or there is no destination; refused when it could
    /// be either. What it means: the same noun as one of them, else the objects it names
    /// are among those the noun of one names, else they are the size of one and not the
    /// other (twice as near on a log scale).
    fn destination_named(
        &self,
        np: &str,
        acted_head: &str,
        scene: &Scene,
        grounder: &Grounder,
    ) -> Result<Option<String>, OpError> {
        let last = self.last_edit(np)?;
        let instruction = last.instruction.as_deref().unwrap_or_default();
        let said = head_noun(np);
        let says_one = np
            .split_whitespace()
            .any(|w| matches!(w.to_lowercase().as_str(), "one" | "ones"));
        if says_one || said == acted_head {
            return Ok(None);
        }
        let Some((acted_span, acted)) = last.acted_phrase() else {
            return Ok(None);
        };
        let Some((span, target)) = last.phrases.iter().find(|(s, _)| s.start >= acted_span.end)
        else {
            return Ok(None);
        };
        let destination = head_noun(instruction.get(span.clone()).unwrap_or_default());
        let as_destination = || splice(instruction, span.start, span.end, np).map(Some);
        if said == destination {
            return as_destination();
        }
        let named = ground_phrase(np, scene, grounder)?;
        let among = |head: &str| {
            let kind = ground_all(head, scene, grounder);
            named.iter().any(|o| kind.contains(o))
        };
        match (among(acted_head), among(&destination)) {
            (true, false) => return Ok(None),
            (false, true) => return as_destination(),
            _ => {}
        }
        let size = |objects: &[usize]| {
            objects
                .iter()
                .map(|&i| scene.objects[i].world_aabb().size().max_element())
                .fold(0.0_f64, f64::max)
                .max(1e-6)
                .ln()
        };
        let (n, a, d) = (size(&named), size(acted), size(target));
        let twice = std::f64::consts::LN_2;
        if (n - a).abs() + twice < (n - d).abs() {
            return Ok(None);
        }
        if (n - d).abs() + twice < (n - a).abs() {
            return as_destination();
        }
        Err(refuse(format!(
            "\"{np}\" instead of what: the {acted_head} moved, or the {destination} it went to? say \"no, move {np}\" or \"no, on {np}\""
        )))
    }

    /// "no, the other table" after "put the vase on the coffee table": the last
    /// instruction with its destination replaced by the one other object `noun` names;
    /// refused when `noun` is not what the destination was, or names none or several
    /// others.
    fn other_destination(
        &self,
        np: &str,
        noun: &str,
        scene: &Scene,
        grounder: &Grounder,
    ) -> Result<String, OpError> {
        let last = self.last_edit(np)?;
        let instruction = last.instruction_to_change("destination")?;
        let acted_end = last.acted_phrase().map_or(0, |(s, _)| s.end);
        let named = ground_all(noun, scene, grounder);
        let destination = last
            .phrases
            .iter()
            .find(|(s, objects)| s.start >= acted_end && objects.iter().any(|o| named.contains(o)));
        let Some((span, target)) = destination else {
            return Err(refuse(format!(
                "\"{np}\": the last edit went to no {noun}, and moved no {noun}; name the object"
            )));
        };
        let others: Vec<usize> = named
            .into_iter()
            .filter(|o| !target.contains(o) && !last.acted.contains(o))
            .collect();
        match others.as_slice() {
            [one] => splice(
                instruction,
                span.start,
                span.end,
                &quoted(&scene.objects[*one].name),
            ),
            [] => Err(refuse(format!(
                "there is no other {noun} than the one it went to"
            ))),
            many => Err(refuse(format!(
                "\"{np}\" could be any of {} {noun}s: {}; name it",
                many.len(),
                names_of(scene, many)
            ))),
        }
    }

    /// "no, the other one": the last instruction on the one other object its phrase's
    /// head noun names.
    fn other(&self, head: &str, scene: &Scene, grounder: &Grounder) -> Result<String, OpError> {
        let last = self.last_edit("the other one")?;
        let named = ground_all(head, scene, grounder);
        let others: Vec<usize> = named
            .into_iter()
            .filter(|o| !last.acted.contains(o))
            .collect();
        match others.as_slice() {
            [one] => Ok(self.replace_acted(&quoted(&scene.objects[*one].name))?.0),
            [] => Err(refuse(format!(
                "there is no other {head} than the one just moved"
            ))),
            many => Err(refuse(format!(
                "\"the other one\" could be any of {} {head}s: {}; name it",
                many.len(),
                names_of(scene, many)
            ))),
        }
    }

    /// "no, left" (`undo_first`): the last edit undone and made again the other way — its
    /// first word of direction after what it moved, replaced; "the same again but left":
    /// made again that way, the last edit kept.
    fn instead_way(&self, way: &str, undo_first: bool) -> Result<Plan, OpError> {
        let last = self.last_edit(way)?;
        let instruction = last.instruction_to_change("direction")?;
        let acted_end = last.acted_phrase().map_or(0, |(s, _)| s.end);
        let found = word_after(instruction, acted_end, follow_up::is_direction);
        let way_said = found.ok_or_else(|| {
            refuse(format!(
                "\"{instruction}\" says no way to change: say the whole instruction"
            ))
        })?;
        Ok(Plan::Edit {
            instruction: splice(instruction, way_said.start, way_said.end, way)?,
            focus: Vec::new(),
            from_last: false,
            undo_first,
        })
    }

    /// "no, on the shelf": the last edit undone and made again with this destination.
    fn instead_place(&self, pp: &str) -> Result<Plan, OpError> {
        let last = self.last_edit(pp)?;
        let instruction = last.instruction_to_change("destination")?;
        let acted_end = last.acted_phrase().map_or(0, |(s, _)| s.end);
        let place = |w: &str| {
            crate::ground::words::is_preposition(w) || matches!(w, "next" | "beside" | "behind")
        };
        let start = word_after(instruction, acted_end, place)
            .map(|r| r.start)
            .ok_or_else(|| {
                refuse(format!(
                    "\"{instruction}\" says no place to change: say the whole instruction"
                ))
            })?;
        let end = last
            .phrases
            .iter()
            .filter(|(s, _)| s.start >= start)
            .map(|(s, _)| s.end)
            .max()
            .unwrap_or(instruction.len());
        let text = splice(instruction, start, end, pp)?;
        Ok(Plan::Edit {
            instruction: text,
            focus: Vec::new(),
            from_last: false,
            undo_first: true,
        })
    }
}

/// `np` with "the" before it when it starts with a bare noun or modifier ("right
/// speaker" → "the right speaker"), so that it reads as a phrase wherever it is put.
fn with_determiner(np: &str) -> String {
    let first = np
        .split_whitespace()
        .next()
        .unwrap_or_default()
        .to_lowercase();
    let determined = matches!(
        first.as_str(),
        "the"
            | "a"
            | "an"
            | "my"
            | "that"
            | "this"
            | "those"
            | "these"
            | "both"
            | "all"
            | "every"
            | "each"
            | "its"
            | "their"
            | "his"
            | "her"
            | "our"
            | "your"
            | "some"
            | "it"
            | "them"
    ) || !first.starts_with(char::is_alphabetic);
    if determined {
        np.to_string()
    } else {
        format!("the {np}")
    }
}

/// The first eight of `objects`' names, quoted, for a refusal that lists candidates.
fn names_of(scene: &Scene, objects: &[usize]) -> String {
    objects
        .iter()
        .take(8)
        .map(|&i| format!("'{}'", scene.objects[i].name))
        .collect::<Vec<_>>()
        .join(", ")
}

/// An object's name quoted for an instruction, so that it is read as that name.
fn quoted(name: &str) -> String {
    if name.contains('"') {
        format!("'{name}'")
    } else {
        format!("\"{name}\"")
    }
}

/// Whether a phrase says "other" ("the other one").
fn mentions_other(np: &str) -> bool {
    np.split_whitespace()
        .any(|w| w.eq_ignore_ascii_case("other"))
}

/// `before`, moved with what it rested on where that has moved since (`then`: its pose
/// then): "put the magazine back" after the ottoman under it moved puts it back on the
/// ottoman, where it lay on it.
fn onto_support(before: &Object, then: Option<Similarity>, scene: &Scene) -> Object {
    let (Some(s), Some(then)) = (before.support, then) else {
        return before.clone();
    };
    let Some(support) = scene.objects.get(s) else {
        return before.clone();
    };
    let now = support.similarity();
    if now == then {
        return before.clone();
    }
    let motion = now.compose(&then.inverse());
    before.as_it_was(
        motion.compose(&before.similarity()),
        (before.support, before.support_from_file),
    )
}

/// `text` with bytes `start..end` replaced by `with`.
fn splice(text: &str, start: usize, end: usize, with: &str) -> Result<String, OpError> {
    match (text.get(..start), text.get(end..)) {
        (Some(before), Some(after)) if start <= end => Ok(format!("{before}{with}{after}")),
        _ => Err(refuse("could not tell which words of the last instruction to change: say the whole instruction")),
    }
}

/// The refusal of an instruction that points ("it", "that") at nothing.
pub(crate) fn nothing_before(instruction: &str) -> OpError {
    refuse(format!(
        "\"{}\" points at nothing yet: nothing was edited or selected before it in this session; name the object",
        instruction.trim()
    ))
}

/// The acted object that `i` went with in a change: itself, or the acted object its
/// supports lead to.
fn group_of(scene: &Scene, i: usize, acted: &[usize]) -> usize {
    let mut at = i;
    for _ in 0..32 {
        if acted.contains(&at) {
            return at;
        }
        match scene.objects[at].support {
            Some(s) => at = s,
            None => break,
        }
    }
    i
}

/// `m` scaled along itself: `k` times its translation, angle and log-scale.
fn scaled(m: &Similarity, k: f64) -> Similarity {
    let (axis, angle) = m.rotation.to_axis_angle();
    let rotation = if angle.abs() < 1e-12 || !axis.is_finite() {
        DQuat::IDENTITY
    } else {
        DQuat::from_axis_angle(axis, angle * k)
    };
    Similarity {
        translation: m.translation * k,
        rotation,
        scale: m.scale.powf(k),
    }
}

/// Each acted object's motion about its pivot, from its states before and after.
pub(crate) fn motions_of(
    changes: &[(usize, Object, Object)],
    acted: &[usize],
) -> Vec<(usize, Similarity)> {
    changes
        .iter()
        .filter(|(i, a, b)| acted.contains(i) && a.pose_differs(b))
        .map(|(i, a, b)| {
            let world = b.similarity().compose(&a.similarity().inverse());
            (*i, world.about(-a.pivot_point()))
        })
        .collect()
}

/// The noun a phrase is built around: its last word before any preposition, without an
/// instance number or quotes ("the chair by the window" → `chair`).
fn head_noun(phrase: &str) -> String {
    let words: Vec<&str> = phrase
        .split(|c: char| c.is_whitespace() || matches!(c, '\'' | '"' | '‘' | '’' | '“' | '”' | '`'))
        .filter(|w| !w.is_empty())
        .collect();
    let end = words
        .iter()
        .skip(1)
        .position(|w| crate::ground::words::is_preposition(&w.to_lowercase()))
        .map_or(words.len(), |k| k + 1);
    words[..end]
        .iter()
        .rev()
        .find(|w| w.chars().any(char::is_alphabetic) && !w.eq_ignore_ascii_case("one"))
        .map_or_else(String::new, |w| w.to_lowercase())
}

/// `np` with "one" / "ones" said as `head` ("the left one" → "the left chair").
fn with_head(np: &str, head: &str) -> String {
    if head.is_empty() {
        return np.to_string();
    }
    np.split(' ')
        .map(|w| match w.to_lowercase().as_str() {
            "one" => head.to_string(),
            "ones" => format!("{head}s"),
            _ => w.to_string(),
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// The bytes of the first word of `text` from byte `from` on that passes `test` (lower
/// case, without punctuation around it).
fn word_after(text: &str, from: usize, test: impl Fn(&str) -> bool) -> Option<Range<usize>> {
    let mut at = 0;
    for word in text.split(' ') {
        let start = at;
        at += word.len() + 1;
        let bare = word.trim_matches(|c: char| !c.is_alphanumeric());
        let offset = word.find(|c: char| c.is_alphanumeric()).unwrap_or(0);
        if start >= from && test(&bare.to_lowercase()) {
            return Some(start + offset..start + offset + bare.len());
        }
    }
    None
}

/// The objects a noun phrase names, one or more, or a refusal naming the candidates.
fn ground_phrase(words: &str, scene: &Scene, grounder: &Grounder) -> Result<Vec<usize>, OpError> {
    let grounding = grounder
        .ground(&format!("move {words}"), scene)
        .map_err(|e| {
            let choices = e
                .ambiguity()
                .map(|a| Box::new(Choices::new(&format!("move {words}"), &a)));
            OpError {
                kind: if choices.is_some() {
                    ErrorKind::Ambiguous
                } else {
                    ErrorKind::NotUnderstood
                },
                ambiguity: choices,
                ..refuse(e.to_string())
            }
        })?;
    let objects: Vec<usize> = grounding
        .phrases
        .iter()
        .flat_map(|p| p.objects.clone())
        .collect();
    if objects.is_empty() {
        return Err(refuse(format!("\"{words}\" names no object of the scene")));
    }
    Ok(objects)
}

/// Every object the noun `head` names (all the chairs).
fn ground_all(head: &str, scene: &Scene, grounder: &Grounder) -> Vec<usize> {
    match grounder.ground(&format!("move the {head}"), scene) {
        Ok(g) => g.phrases.iter().flat_map(|p| p.objects.clone()).collect(),
        Err(e) => e
            .ambiguity()
            .map(|a| a.objects.iter().filter_map(|n| scene.find(n)).collect())
            .unwrap_or_default(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_motion_scales_along_itself() {
        let m = Similarity {
            translation: DVec3::new(-1.0, 0.0, 0.0),
            rotation: DQuat::from_rotation_y(0.5),
            scale: 4.0,
        };
        let half = scaled(&m, 0.5);
        assert!((half.translation.x + 0.5).abs() < 1e-12);
        assert!((half.rotation.to_axis_angle().1 - 0.25).abs() < 1e-12);
        assert!((half.scale - 2.0).abs() < 1e-12);
        let back = scaled(&m, -1.0);
        assert!((back.translation.x - 1.0).abs() < 1e-12);
    }

    #[test]
    fn one_is_said_as_the_head_noun() {
        assert_eq!(head_noun("the chair by the window"), "chair");
        assert_eq!(head_noun("'Chair 2'"), "chair");
        assert_eq!(with_head("the left one", "chair"), "the left chair");
    }
}

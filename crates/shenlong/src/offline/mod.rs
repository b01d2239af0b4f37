//! The built-in offline translator (`--llm offline`, the default): a templated instruction
//! to the same CGA answer a language model would give, with no network and no model.
//!
//! It is a small grammar, not a list of sentences, one module per stage:
//! - [`words`]: tokens, and the closed word lists (verbs, directions, units, fillers), with
//!   one-letter typos of verbs and directions corrected;
//! - [`clause`]: clauses split at `and`, `then`, commas, each recording which words it read;
//! - [`idioms`]: phrases read as another construct of the reader says it;
//! - [`amounts`]: lengths and angles — numbers, spoken compounds, vague amounts with
//!   documented defaults;
//! - [`read`]: one clause's verb and subjects, every word of it read, and the stage its
//!   verb says:
//!   - [`relate`]: a move to a relation with other objects (what the relation is, its
//!     subjects and targets), written by [`relations`] from their boxes only;
//!   - [`room_place`]: a move to a place in the room, written by [`room`];
//!   - [`shift`]: a move by directions and an amount;
//!   - [`rotate`]: turns, facing and straightening;
//!   - [`scale`]: scale factors, both directions of every relative change;
//!   - [`arrange`]: swaps, rows and alignments;
//!   - [`repeat`]: "do the same for X2", reversed or mirrored.
//!
//! Answers are expression trees ([`crate::expr::Expr`]) written with only `X_i.min/.max/
//! .center/.size`, `room`, `e1 e2 e3`, `T`, `R`, `D` — never the scene's numbers but for a
//! straightening's snap — evaluated directly; the reply it reports is printed from them.
//! An instruction any word of which is unread is refused, quoting the unread words.

mod along;
pub mod amounts;
mod arrange;
mod build;
mod clause;
mod idioms;
mod mutual;
mod read;
mod reader;
mod relate;
mod relations;
mod repeat;
mod room;
mod room_place;
mod rotate;
mod scale;
mod shift;
#[cfg(test)]
mod testing;
mod view;
pub(crate) mod words;

pub use relations::GAP;

use crate::expr::{self, Bindings, Expr};
use crate::llm::{Message, Usage};
use crate::scene::Scene;
use crate::translate::{
    bindings, Answer, Exchange, System, Templated, TranslateError, Translation, Translator,
};
pub use reader::ReadError;
use reader::{Facts, Reader};
use relations::Step;
use std::time::Instant;

/// The offline translator.
#[derive(Clone, Debug, Default)]
pub struct OfflineTranslator;

impl OfflineTranslator {
    /// The translator.
    pub fn new() -> Self {
        Self
    }
}

/// One variable's answer: the transformations, applied in order.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// The variable, from 0 (`X1`).
    pub variable: usize,
    /// The expressions, first applied first.
    pub expressions: Vec<Expr>,
    /// What it was last put next to or between (variables), if anything.
    pub near: Option<crate::translate::Near>,
}

/// How far box `b` lies ahead of box `a` along axis `e` in the direction `sign`: the gap
/// between the facing faces (negative where they overlap along it or `b` is behind).
fn gap_ahead(a: &crate::geometry::Aabb, b: &crate::geometry::Aabb, e: usize, sign: f64) -> f64 {
    if sign > 0.0 {
        b.min[e] - a.max[e]
    } else {
        a.min[e] - b.max[e]
    }
}

/// How far from a table a chair may stand and still be "pushed in" to it, in metres.
pub const TUCK_REACH: f64 = 0.6;

/// What the reader knows of the bound objects, beyond their variables: all measured from
/// the scene before the edit. Everything may be left empty (a scene with a room, unturned
/// objects, nothing measured). What only some instructions need ("as far as it will go":
/// every box of the scene) is measured when first asked for, never on every edit.
#[derive(Debug, Default)]
pub struct Known<'s> {
    /// Whether the scene has room bounds.
    pub room: bool,
    /// Per variable: its turn about the vertical in degrees (for "straighten").
    pub yaw: Vec<f64>,
    /// Per variable: the size of its world box (for "to X2": a small thing goes on X2's
    /// top).
    pub sizes: Vec<[f64; 3]>,
    /// The scene and the variables' objects, for what is measured on demand.
    scene: Option<(&'s Scene, &'s [usize])>,
    /// The scene's world boxes, once measured.
    boxes: std::cell::OnceCell<Vec<crate::geometry::Aabb>>,
}

impl<'s> Known<'s> {
    /// What the reader knows of `objects` (the variables, in order) in `scene`.
    #[must_use]
    pub fn of(scene: &'s Scene, objects: &'s [usize]) -> Self {
        Self {
            room: scene.bounds.is_some(),
            yaw: objects
                .iter()
                .map(|&i| {
                    let q = scene.objects[i].similarity().rotation;
                    let (axis, angle) = q.to_axis_angle();
                    (angle * axis.y.signum()).to_degrees()
                })
                .collect(),
            sizes: objects
                .iter()
                .map(|&i| scene.objects[i].world_aabb().size().to_array())
                .collect(),
            scene: Some((scene, objects)),
            boxes: std::cell::OnceCell::new(),
        }
    }

    /// How far variable `s` can go along horizontal axis `e` (0 or 2) with `sign` before
    /// it meets another object or a wall, 1 cm short ([`runs`]); `None` where nothing
    /// stops it or nothing is known.
    pub(crate) fn run(&self, s: usize, e: usize, sign: f64) -> Option<f64> {
        let k = match (e, sign > 0.0) {
            (0, false) => 0,
            (0, true) => 1,
            (2, false) => 2,
            (2, true) => 3,
            _ => return None,
        };
        let (scene, objects) = self.scene?;
        let object = *objects.get(s)?;
        let boxes = self.boxes.get_or_init(|| scene.world_aabbs());
        Some(runs(scene, boxes, object)[k]).filter(|d| d.is_finite())
    }

    /// Whether target `t` lies straight along horizontal axis `e` with `sign` from
    /// subject `s`, so that moving that way makes them touch: ahead of it (or touching)
    /// and overlapping it across. Nothing known: taken as so.
    ///
    /// # Errors
    /// One line saying why not.
    pub(crate) fn straight_ahead(
        &self,
        s: usize,
        t: usize,
        e: usize,
        sign: f64,
    ) -> Result<(), ReadError> {
        let Some((scene, objects)) = self.scene else {
            return Ok(());
        };
        let (Some(&a), Some(&b)) = (objects.get(s), objects.get(t)) else {
            return Ok(());
        };
        let boxes = self.boxes.get_or_init(|| scene.world_aabbs());
        let (sa, sb) = (&boxes[a], &boxes[b]);
        let ahead = gap_ahead(sa, sb, e, sign);
        let overlap = sa.overlap(sb)[2 - e];
        let way = match (e, sign > 0.0) {
            (0, false) => "left",
            (0, true) => "right",
            (_, false) => "back",
            (_, true) => "forward",
        };
        if ahead < -1e-6 {
            return Err(ReadError::Unclear(format!(
                "'{}' is not {way} of '{}': moving it {way} never reaches it",
                scene.objects[b].name, scene.objects[a].name
            )));
        }
        if overlap <= 1e-6 {
            return Err(ReadError::Unclear(format!(
                "'{}' is not straight {way} of '{}': moving it {way} passes it by",
                scene.objects[b].name, scene.objects[a].name
            )));
        }
        Ok(())
    }

    /// What variable `s` is drawn up to, as a chair to a table: the nearest object with a
    /// bigger footprint that overlaps it across one horizontal axis and is at most
    /// [`TUCK_REACH`] from it along the other (or reaches under it). Returned as the
    /// direction towards it (axis, sign) and the gap to its face (0 when they touch or
    /// overlap). `None`: nothing is near, or nothing is known.
    pub(crate) fn drawn_up_to(&self, s: usize) -> Option<((usize, f64), f64)> {
        self.drawn_up_to_object(s).map(|(way, gap, _)| (way, gap))
    }

    /// How far pushing variable `s` in moves it: to the face of what it is drawn up to
    /// (the gap), or, for a chair facing a top on legs it fits under to its seat, until
    /// its seat is under the top and its back at the top's edge (`scene::form::Seat`).
    /// With it, the table (an object of the scene) when the chair goes under its top.
    pub(crate) fn push_in(&self, s: usize) -> Option<(f64, Option<usize>)> {
        let ((e, sign), gap, table) = self.drawn_up_to_object(s)?;
        let (scene, objects) = self.scene?;
        let me = *objects.get(s)?;
        let tucked = || {
            let room = crate::ground::kind::room_of(scene, me, table)?;
            let seat = room.seat?;
            let boxes = self.boxes.get_or_init(|| scene.world_aabbs());
            let knee = crate::scene::form::knee_room(&boxes[table], room.form);
            // Its back away from the table, its seat low enough.
            let back_away = seat.axis == e && seat.max_side == (sign < 0.0);
            (room.form.on_legs() && back_away && seat.height <= knee)
                .then(|| gap + (boxes[me].size()[e] - seat.depth).max(0.0))
        };
        Some(tucked().map_or((gap, None), |d| (d, Some(table))))
    }

    /// [`Known::drawn_up_to`], with the object it is drawn up to.
    fn drawn_up_to_object(&self, s: usize) -> Option<((usize, f64), f64, usize)> {
        let (scene, objects) = self.scene?;
        let me = *objects.get(s)?;
        let boxes = self.boxes.get_or_init(|| scene.world_aabbs());
        let a = boxes[me];
        let footprint = |b: &crate::geometry::Aabb| b.size().x * b.size().z;
        let mut best: Option<((usize, f64), f64, usize)> = None;
        for (j, b) in boxes.iter().enumerate() {
            let overlap = a.overlap(b);
            if j == me || footprint(b) <= footprint(&a) || overlap.y <= 0.0 {
                continue;
            }
            for e in [0usize, 2] {
                if overlap[2 - e] <= 0.0 {
                    continue;
                }
                let sign = (b.center()[e] - a.center()[e]).signum();
                let gap = gap_ahead(&a, b, e, sign);
                if gap > TUCK_REACH || sign == 0.0 {
                    continue;
                }
                let gap = gap.max(0.0);
                if best.is_none_or(|(_, g, _)| gap < g) {
                    best = Some(((e, sign), gap, j));
                }
            }
        }
        best
    }

    /// The table chair `t` is drawn up to, as an object, with the scene and boxes: of the
    /// table-high objects with a bigger footprint than the chair's (not its neighbour),
    /// the nearest, within [`crate::ground::depend::DRAWN_UP_METRES`] of its footprint.
    fn seat_table(&self, t: usize) -> Option<(&Scene, &[crate::geometry::Aabb], usize)> {
        let (scene, objects) = self.scene?;
        let b = *objects.get(t)?;
        let boxes = self.boxes.get_or_init(|| scene.world_aabbs());
        if !self.stays_on_floor(t) {
            return None;
        }
        let footprint = |a: &crate::geometry::Aabb| a.size().x * a.size().z;
        let top = scene.floor() + crate::ground::profile::SURFACE_MIN_TOP;
        let (gap, table) = boxes
            .iter()
            .enumerate()
            .filter(|&(o, a)| o != b && footprint(a) > footprint(&boxes[b]) && a.max.y >= top)
            .map(|(o, a)| (boxes[b].floor_gap(a), o))
            .min_by(|x, y| x.0.total_cmp(&y.0))?;
        (gap <= crate::ground::depend::DRAWN_UP_METRES).then_some((scene, boxes.as_slice(), table))
    }

    /// Whether variable `s` rests on the table that `t`, a seat by its kind
    /// ([`crate::ground::kind::seat_kind`]: a chair, a stool), is drawn up to.
    pub(crate) fn on_seat_table(&self, s: usize, t: usize) -> bool {
        let (Some((scene, _, table)), Some((&a, &b))) = (
            self.seat_table(t),
            self.scene.and_then(|(_, o)| o.get(s).zip(o.get(t))),
        ) else {
            return false;
        };
        let seat = &scene.objects[b];
        let is_seat = crate::ground::kind::seat_kind(
            crate::ground::lexicon::Lexicon::builtin(),
            seat.labels.category.as_deref(),
            &seat.name,
        );
        is_seat == Some(true) && scene.objects[a].support == Some(table)
    }

    /// "put the laptop at chair 3's place", "… in front of chair 3": the move that puts
    /// variable `s` on the top of the table chair `t` is drawn up to, in front of the
    /// chair — the chair's centre brought onto the top, inset by half the thing and
    /// [`AT_SEAT_INSET`] from the edge. `None` unless `t` stands on the floor drawn up to a
    /// table-high surface (the one of variable `table` where one is named), `s` is no
    /// floor furniture, and `s` fits on that top.
    pub(crate) fn at_its_seat(
        &self,
        s: usize,
        t: usize,
        table: Option<usize>,
    ) -> Option<glam::DVec3> {
        let (_, boxes, surface) = self.seat_table(t)?;
        let (_, objects) = self.scene?;
        let a = *objects.get(s)?;
        let named = table.map(|y| objects.get(y).copied());
        if a == surface || self.stays_on_floor(s) || named.is_some_and(|y| y != Some(surface)) {
            return None;
        }
        let (me, top, seat) = (boxes[a], boxes[surface], boxes[*objects.get(t)?].center());
        let mut to = glam::DVec3::ZERO;
        for e in [0, 2] {
            let half = me.size()[e] / 2.0 + AT_SEAT_INSET;
            let (lo, hi) = (top.min[e] + half, top.max[e] - half);
            if lo > hi {
                return None;
            }
            to[e] = seat[e].clamp(lo, hi) - me.center()[e];
        }
        to.y = top.max.y - me.min.y;
        Some(to)
    }

    /// Whether variables `group` stand together on one side of the room's centre: every
    /// one's way to the centre has a part along the way from their middle to it (the beds
    /// along one wall, not chairs in opposite corners). One object always does.
    pub(crate) fn together_off_centre(&self, group: &[usize]) -> bool {
        let Some((scene, objects)) = self.scene else {
            return group.len() == 1;
        };
        let Some(room) = scene.bounds else {
            return group.len() == 1;
        };
        let flat = |v: glam::DVec3| glam::DVec2::new(v.x, v.z);
        let centres: Vec<glam::DVec2> = group
            .iter()
            .filter_map(|&v| objects.get(v))
            .map(|&o| flat(scene.objects[o].world_aabb().center()))
            .collect();
        if centres.len() != group.len() || centres.is_empty() {
            return false;
        }
        let middle = centres.iter().copied().sum::<glam::DVec2>() / centres.len() as f64;
        let way = flat(room.center()) - middle;
        way.length() > 1e-6
            && centres
                .iter()
                .all(|&c| (flat(room.center()) - c).dot(way) > 0.0)
    }

    /// The wall of the room variable `t` is nearest (its box's gap to it), as the word for
    /// its side (`left`, `right`, `back`, `front`); `None` without a room.
    pub(crate) fn nearest_wall(&self, t: usize) -> Option<&'static str> {
        let (scene, objects) = self.scene?;
        let room = scene.bounds?;
        let b = scene.objects[*objects.get(t)?].world_aabb();
        [
            (b.min.x - room.min.x, "left"),
            (room.max.x - b.max.x, "right"),
            (b.min.z - room.min.z, "back"),
            (room.max.z - b.max.z, "front"),
        ]
        .into_iter()
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, side)| side)
    }

    /// The room's corner on variable `t`'s side of the room's centre, as the signs along
    /// x and z; `None` without a room, or where `t` stands on a centre line.
    pub(crate) fn corner_towards(&self, t: usize) -> Option<(f64, f64)> {
        let (scene, objects) = self.scene?;
        let room = scene.bounds?;
        let at = scene.objects[*objects.get(t)?].world_aabb().center() - room.center();
        (at.x.abs() > 1e-6 && at.z.abs() > 1e-6).then(|| (at.x.signum(), at.z.signum()))
    }

    /// Whether variables `others` are smaller things standing within half a metre of
    /// variable `lead`'s box (a table and the chairs drawn up to it, each with under two
    /// thirds of its footprint): one thing to move together.
    pub(crate) fn unit_with(&self, lead: usize, others: &[usize]) -> bool {
        let Some((scene, objects)) = self.scene else {
            return false;
        };
        let boxes = self.boxes.get_or_init(|| scene.world_aabbs());
        let Some(a) = objects.get(lead).map(|&o| boxes[o]) else {
            return false;
        };
        others.iter().all(|&v| {
            objects.get(v).is_some_and(|&o| {
                let b = boxes[o];
                let footprint = |x: &crate::geometry::Aabb| x.size().x * x.size().z;
                if footprint(&b) * 1.5 > footprint(&a) {
                    return false;
                }
                a.floor_gap(&b) <= 0.5
            })
        })
    }

    /// Whether variable `s` is a thing that `to X2` puts on `t`'s top ("carry the mug over
    /// to the coffee table", "move the lamp to the other side table"): its footprint fits
    /// on `t`'s, `t`'s top is within reach (1.3 m), and it is either small beside `t`
    /// (under a twentieth of its volume) or stands on a surface now — what rests on one
    /// table and is sent to another goes onto it, not onto the floor beside it. A chair
    /// "to the table" is neither and goes to its place on the floor.
    pub(crate) fn small_onto(&self, s: usize, t: usize) -> bool {
        let (Some(a), Some(b)) = (self.sizes.get(s), self.sizes.get(t)) else {
            return false;
        };
        let volume = |v: &[f64; 3]| v[0] * v[1] * v[2];
        let fits = a[0] <= b[0] && a[2] <= b[2] && b[1] <= 1.3 && !self.stays_on_floor(s);
        fits && (volume(a) * 20.0 < volume(b) || self.on_a_surface_to_a_surface(s, t))
    }

    /// Whether variable `s`'s object rests on variable `t`'s now.
    pub(crate) fn rests_on(&self, s: usize, t: usize) -> bool {
        let Some((scene, objects)) = self.scene else {
            return false;
        };
        let (Some(&a), Some(&b)) = (objects.get(s), objects.get(t)) else {
            return false;
        };
        scene.objects[a].support == Some(b)
    }

    /// Whether variable `s` rests on another object's top now and `t` has a top to stand
    /// on: `t` stands on the floor or on something (it does not hang on a wall).
    fn on_a_surface_to_a_surface(&self, s: usize, t: usize) -> bool {
        let Some((scene, objects)) = self.scene else {
            return false;
        };
        let (Some(&a), Some(&b)) = (objects.get(s), objects.get(t)) else {
            return false;
        };
        scene.objects[a].support.is_some_and(|on| on != b) && !scene.hangs(b)
    }
}

impl Known<'_> {
    /// Whether variable `s` stays on the floor: floor furniture ([`crate::ground::kind`])
    /// that does not hang, and does not stand on a table or counter now (a stand mixer on
    /// a prep table is moved as a thing on a surface; a chair on a rug stays down).
    pub(crate) fn stays_on_floor(&self, s: usize) -> bool {
        let Some((scene, objects)) = self.scene else {
            return false;
        };
        let on_a_surface = |a: usize| {
            scene.objects[a].support.is_some_and(|t| {
                scene.objects[t].world_aabb().max.y
                    >= scene.floor() + crate::ground::profile::SURFACE_MIN_TOP
            })
        };
        objects.get(s).is_some_and(|&a| {
            crate::ground::kind::is_floor_bound(scene, a) && !scene.hangs(a) && !on_a_surface(a)
        })
    }

    /// How high above the bottom of `t`'s object `subjects` rest put in it, if it has
    /// room inside (`scene::form`): an open container's floor; in a case of shelves, the
    /// lowest shelf tall and wide enough for the largest of them with room left on it
    /// (else the lowest tall and wide enough: whether there is room is checked once
    /// placed); `shelf`: that shelf. `None`: solid, no such shelf, or nothing known.
    pub(crate) fn inside_floor(
        &self,
        subjects: &[usize],
        t: usize,
        shelf: Option<crate::scene::form::Shelf>,
    ) -> Option<f64> {
        use crate::scene::{form, Form};
        let (scene, objects) = self.scene?;
        let case = *objects.get(t)?;
        let boxes = self.boxes.get_or_init(|| scene.world_aabbs());
        let b = boxes[case];
        let case_form = crate::ground::kind::form_of(scene, case);
        match case_form {
            Form::Open if shelf.is_none() => Some(form::inside(&b).min.y - b.min.y),
            Form::Shelves { .. } if shelf.is_some() => shelf?
                .pick(&form::compartments(&b, case_form))
                .map(|room| room.min.y - b.min.y),
            Form::Shelves { .. } => {
                let moving: Vec<usize> = subjects
                    .iter()
                    .filter_map(|&s| objects.get(s).copied())
                    .collect();
                let need = moving
                    .iter()
                    .map(|&o| boxes[o].size())
                    .fold(glam::DVec3::ZERO, glam::DVec3::max);
                let area = |x: &crate::geometry::Aabb| x.size().x * x.size().z;
                // As it stands, or turned a quarter turn ([`Known::turn_to_fit`]).
                let fits = |room: &crate::geometry::Aabb| {
                    let room = room.size() + 1e-9;
                    need.cmple(room).all() || quarter_turned(need).cmple(room).all()
                };
                let rooms: Vec<_> = form::compartments(&b, case_form)
                    .into_iter()
                    .filter(fits)
                    .collect();
                // What already stands on a shelf: the footprint it takes there.
                let used = |room: &crate::geometry::Aabb| {
                    (0..boxes.len())
                        .filter(|&j| j != case && !moving.contains(&j))
                        .filter(|&j| boxes[j].intersects(room, 1e-6))
                        .map(|j| boxes[j].footprint_overlap(room))
                        .sum::<f64>()
                };
                let free = rooms
                    .iter()
                    .find(|room| used(room) + need.x * need.z <= 0.9 * area(room));
                // Too big for every shelf: the lowest, where the placement check says so.
                let lowest = form::compartments(&b, case_form).into_iter().next();
                free.or(rooms.first())
                    .copied()
                    .or(lowest)
                    .map(|room| room.min.y - b.min.y)
            }
            _ => None,
        }
    }

    /// Whether variable `s`, put in `t` resting `floor` above its bottom (an open
    /// container's room, or the shelf at that height), fits there only turned a quarter
    /// turn about the vertical — as a person turns a book to go on a shelf: its footprint
    /// too long for the room one way and not the other. A quarter turn about the vertical
    /// swaps the extents of any object's world box along x and z.
    pub(crate) fn turn_to_fit(&self, s: usize, t: usize, floor: f64) -> bool {
        use crate::scene::{form, Form};
        let Some((scene, objects)) = self.scene else {
            return false;
        };
        let (Some(&o), Some(&case)) = (objects.get(s), objects.get(t)) else {
            return false;
        };
        let boxes = self.boxes.get_or_init(|| scene.world_aabbs());
        let b = boxes[case];
        let case_form = crate::ground::kind::form_of(scene, case);
        let room = match case_form {
            Form::Open => Some(form::inside(&b)),
            Form::Shelves { .. } => form::compartments(&b, case_form)
                .into_iter()
                .find(|r| (r.min.y - b.min.y - floor).abs() < 1e-9),
            _ => None,
        };
        let Some(room) = room.map(|r| r.size() + 1e-9) else {
            return false;
        };
        let need = boxes[o].size();
        !need.cmple(room).all() && quarter_turned(need).cmple(room).all()
    }

    /// Whether `subjects` put "in" `t` go under it: `t` is a top on legs (a desk, a
    /// table) and they are seats or floor furniture ("tuck the chair into the desk").
    pub(crate) fn tucks_under(&self, subjects: &[usize], t: usize) -> bool {
        let Some((scene, objects)) = self.scene else {
            return false;
        };
        let Some(&table) = objects.get(t) else {
            return false;
        };
        crate::ground::kind::form_of(scene, table).on_legs()
            && !subjects.is_empty()
            && subjects.iter().all(|&s| {
                objects.get(s).is_some_and(|&o| {
                    crate::ground::kind::seat_of(scene, o).is_some()
                        || crate::ground::kind::is_floor_bound(scene, o)
                })
            })
    }

    /// Whether `t`'s object hangs (on a wall, above the floor, resting on nothing).
    pub(crate) fn hangs(&self, t: usize) -> bool {
        self.scene
            .and_then(|(scene, objects)| objects.get(t).map(|&b| scene.hangs(b)))
            .unwrap_or(false)
    }

    /// Whether "next to", a side of, "to" or "between" target `t` puts subject `s` on the
    /// floor rather than on `t`'s level: `s` stays on the floor and `t` stands above it (a
    /// laptop on a desk), or `t` hangs (a whiteboard on the wall) and `s` does not.
    pub(crate) fn grounded_beside(&self, s: usize, t: usize) -> bool {
        let Some((scene, objects)) = self.scene else {
            return false;
        };
        let (Some(&a), Some(&b)) = (objects.get(s), objects.get(t)) else {
            return false;
        };
        // What hangs beside what hangs stays on the wall (a picture by the clock).
        if scene.hangs(a) {
            return false;
        }
        let raised =
            scene.objects[b].world_aabb().min.y > scene.floor() + crate::scene::FLOOR_LEVEL;
        scene.hangs(b) || (raised && self.stays_on_floor(s))
    }

    /// The scene, `s`'s and `t`'s objects and the surface `t` rests on, where `s` is put
    /// beside `t` on that surface: `t` rests on something other than `s`, and `s` does
    /// not stay on the floor. `None` otherwise, or where nothing is known of the scene.
    fn beside_on_support(&self, s: usize, t: usize) -> Option<(&Scene, usize, usize, usize)> {
        let (scene, objects) = self.scene?;
        let (a, b) = (*objects.get(s)?, *objects.get(t)?);
        let surface = scene.objects[b].support?;
        (surface != a && !self.stays_on_floor(s)).then_some((scene, a, b, surface))
    }

    /// For "next to `t`" where `t` rests on a surface and `s` does not stay on the floor:
    /// the side of `t` on that surface where `s` fits ([`Known::side_on`]). `Ok(None)` when
    /// `t` rests on nothing or `s` stays on the floor ("next to" then keeps its face).
    ///
    /// # Errors
    /// As [`Known::side_on`].
    pub(crate) fn side_on_support(
        &self,
        s: usize,
        t: usize,
    ) -> Result<Option<relations::Relation>, ReadError> {
        let Some((scene, a, b, surface)) = self.beside_on_support(s, t) else {
            return Ok(None);
        };
        Self::side_on(scene, a, b, surface).map(Some)
    }

    /// Whether variable `v`'s object belongs to variable `s`'s: it rests on it (directly
    /// or on what rests on it), or is drawn up to it as a chair to its table
    /// ([`crate::ground::depend::belongs_to`]; the variables `alike`, named with it, are
    /// not what it is drawn up to: a chair's neighbour is no table); `None` where nothing
    /// is known of the scene.
    pub(crate) fn belongs(&self, v: usize, s: usize, alike: &[usize]) -> Option<bool> {
        let (scene, objects) = self.scene?;
        let (a, b) = (*objects.get(v)?, *objects.get(s)?);
        let boxes = self.boxes.get_or_init(|| scene.world_aabbs());
        let kind: Vec<usize> = std::iter::once(a)
            .chain(alike.iter().filter_map(|&k| objects.get(k).copied()))
            .collect();
        Some(
            scene.rests_on_through(a, b)
                || crate::ground::depend::belongs_to(scene, boxes, a, &[b], &kind),
        )
    }

    /// Whether variable `v`'s object is carried by variable `s`'s: it rests on it, directly
    /// or on what rests on it.
    pub(crate) fn carried(&self, v: usize, s: usize) -> bool {
        let Some((scene, objects)) = self.scene else {
            return false;
        };
        match (objects.get(v), objects.get(s)) {
            (Some(&a), Some(&b)) => scene.rests_on_through(a, b),
            _ => false,
        }
    }

    /// How a message names variable `v`: its object's name in quotes, or `X{v+1}` where
    /// nothing is known of the scene.
    pub(crate) fn label(&self, v: usize) -> String {
        self.scene
            .and_then(|(scene, objects)| {
                objects
                    .get(v)
                    .map(|&o| format!("'{}'", scene.objects[o].name))
            })
            .unwrap_or_else(|| format!("X{}", v + 1))
    }

    /// Whether moving variable `s` along `way` (a horizontal direction) takes it towards
    /// variable `t` — `t`'s centre lies ahead of `s`'s along it; `None` where nothing is
    /// known of the scene.
    pub(crate) fn heads_towards(&self, s: usize, t: usize, way: glam::DVec3) -> Option<bool> {
        let (scene, objects) = self.scene?;
        let (a, b) = (*objects.get(s)?, *objects.get(t)?);
        let mut to =
            scene.objects[b].world_aabb().center() - scene.objects[a].world_aabb().center();
        to.y = 0.0;
        Some(to.dot(way) > 1e-9)
    }

    /// The horizontal axis along which subject `s` stands out from one face of target `t`:
    /// its centre within the target's footprint across the other axis and outside it
    /// along this one, within [`TUCK_REACH`] of that face (a chair at a table's side), so
    /// "away from `t`" is straight out from that face. `None` otherwise, or where nothing
    /// is known of the scene.
    pub(crate) fn alongside(&self, s: usize, t: usize) -> Option<usize> {
        let (scene, objects) = self.scene?;
        let (a, b) = (*objects.get(s)?, *objects.get(t)?);
        let (c, target) = (
            scene.objects[a].world_aabb().center(),
            scene.objects[b].world_aabb(),
        );
        let within = |e: usize| c[e] >= target.min[e] && c[e] <= target.max[e];
        let e = match (within(0), within(2)) {
            (true, false) => 2,
            (false, true) => 0,
            _ => return None,
        };
        // Drawn up to that face (within reach of it), as a chair to a table: something
        // standing metres off is moved away along the line between them.
        let me = scene.objects[a].world_aabb();
        let gap = (me.min[e] - target.max[e]).max(target.min[e] - me.max[e]);
        (gap <= TUCK_REACH).then_some(e)
    }

    /// How far target `t` floats above the top of the surface it rests on (metres, 0 when
    /// it stands on it or rests on nothing): ProcTHOR's data sets some objects a few
    /// centimetres above their tables.
    pub(crate) fn float_above_support(&self, t: usize) -> f64 {
        let Some((scene, objects)) = self.scene else {
            return 0.0;
        };
        let Some(&b) = objects.get(t) else {
            return 0.0;
        };
        scene.objects[b].support.map_or(0.0, |surface| {
            let d = scene.objects[b].world_aabb().min.y - scene.objects[surface].world_aabb().max.y;
            if d > crate::scene::SUPPORT_GAP / 10.0 {
                d
            } else {
                0.0
            }
        })
    }

    /// For "on `y` next to `t`": the side of `t` on `y` where `s` fits ([`Known::side_on`]);
    /// `Ok(None)` when nothing is known of the scene.
    ///
    /// # Errors
    /// As [`Known::side_on`].
    pub(crate) fn side_on_surface(
        &self,
        s: usize,
        t: usize,
        y: usize,
    ) -> Result<Option<relations::Relation>, ReadError> {
        let Some((scene, objects)) = self.scene else {
            return Ok(None);
        };
        match (objects.get(s), objects.get(t), objects.get(y)) {
            (Some(&a), Some(&b), Some(&c)) => Self::side_on(scene, a, b, c).map(Some),
            _ => Ok(None),
        }
    }

    /// For "on `y` between `z` and `w`": refuses what cannot be placed there — `s` at the
    /// midpoint not within `y`'s top, or not fitting in the space between the two.
    ///
    /// # Errors
    /// One line naming the objects.
    pub(crate) fn between_on(
        &self,
        s: usize,
        z: usize,
        w: usize,
        y: usize,
    ) -> Result<(), ReadError> {
        let Some((scene, objects)) = self.scene else {
            return Ok(());
        };
        let (Some(&a), Some(&p), Some(&q), Some(&c)) = (
            objects.get(s),
            objects.get(z),
            objects.get(w),
            objects.get(y),
        ) else {
            return Ok(());
        };
        let name = |i: usize| &scene.objects[i].name;
        for i in [p, q] {
            Self::not_sunk(scene, i, c)?;
        }
        let (me, pb, qb, top) = (
            scene.objects[a].world_aabb(),
            scene.objects[p].world_aabb(),
            scene.objects[q].world_aabb(),
            scene.objects[c].world_aabb(),
        );
        let mid = (pb.center() + qb.center()) / 2.0;
        let at_mid = me.translated(glam::DVec3::new(
            mid.x - me.center().x,
            0.0,
            mid.z - me.center().z,
        ));
        let on_top = at_mid.footprint_within(&top);
        // The space between them along the axis they are apart on.
        let d = qb.center() - pb.center();
        let e = if d.x.abs() >= d.z.abs() { 0 } else { 2 };
        let (near, far) = if d[e] >= 0.0 { (pb, qb) } else { (qb, pb) };
        let room = far.min[e] - near.max[e];
        if !on_top || room < me.size()[e] {
            return Err(ReadError::NoFit(format!(
                "'{}' does not fit on '{}' between '{}' and '{}'; say where else it should go",
                name(a),
                name(c),
                name(p),
                name(q)
            )));
        }
        Ok(())
    }

    /// Refuses a place beside `b` on `surface` when `b` stands inside the surface's box (an
    /// egg in a fridge, a pillow in a sofa's seat): anything put beside it would end inside
    /// the surface.
    fn not_sunk(scene: &Scene, b: usize, surface: usize) -> Result<(), ReadError> {
        let (target, top) = (
            scene.objects[b].world_aabb(),
            scene.objects[surface].world_aabb(),
        );
        if target.min.y < top.max.y - crate::scene::SUPPORT_GAP {
            return Err(ReadError::NoFit(format!(
                "'{}' stands inside '{}', so nothing put beside it would stand on '{}'; say where else it should go",
                scene.objects[b].name, scene.objects[surface].name, scene.objects[surface].name
            )));
        }
        Ok(())
    }

    /// The first side of object `b`, in the order "next to" chooses (the face nearest `a`,
    /// then the nearer face across, then the far ones), where object `a`, set [`GAP`] from
    /// that face and centred along it, lies within `surface`'s top.
    ///
    /// # Errors
    /// `b` stands inside `surface` ([`Known::not_sunk`]), or `a` fits on no side: one line
    /// naming the three.
    fn side_on(
        scene: &Scene,
        a: usize,
        b: usize,
        surface: usize,
    ) -> Result<relations::Relation, ReadError> {
        Self::not_sunk(scene, b, surface)?;
        let (me, target, top) = (
            scene.objects[a].world_aabb(),
            scene.objects[b].world_aabb(),
            scene.objects[surface].world_aabb(),
        );
        let (mc, tc, ts) = (me.center(), target.center(), target.size());
        let sign = |d: f64| if d >= 0.0 { 1.0 } else { -1.0 };
        let (dx, dz) = (mc.x - tc.x, mc.z - tc.z);
        // As `next_to` chooses: the x faces when the subject lies more to the side than in
        // front or behind, in the target's proportions.
        let first_x = dx.abs() * ts.z > dz.abs() * ts.x;
        let (x, z) = ((0, sign(dx)), (2, sign(dz)));
        let order = if first_x {
            [x, z, (0, -x.1), (2, -z.1)]
        } else {
            [z, x, (2, -z.1), (0, -x.1)]
        };
        order
            .into_iter()
            .find_map(|(e, sign)| Self::side_within(&me, &target, &top, e, sign))
            .ok_or_else(|| {
                ReadError::NoFit(format!(
                    "'{}' does not fit next to '{}' on '{}': there is no room on any side of it; say where else it should go",
                    scene.objects[a].name, scene.objects[b].name, scene.objects[surface].name
                ))
            })
    }
}

impl Known<'_> {
    /// The gap from `target`'s face on axis `e` toward `sign` at which box `me`, centred
    /// along that face, lies within `top`'s footprint: [`GAP`] where it fits so, else the
    /// largest smaller gap (down to touching) that fits; `None` where it does not fit even
    /// touching.
    fn gap_beside(
        me: &crate::geometry::Aabb,
        target: &crate::geometry::Aabb,
        top: &crate::geometry::Aabb,
        e: usize,
        sign: f64,
    ) -> Option<f64> {
        let at = |gap: f64| {
            let mut offset = target.center() - me.center();
            offset.y = 0.0;
            offset[e] = if sign > 0.0 {
                target.max[e] + gap - me.min[e]
            } else {
                target.min[e] - gap - me.max[e]
            };
            me.translated(offset).footprint_within(top)
        };
        if at(GAP) {
            return Some(GAP);
        }
        let size = me.max[e] - me.min[e];
        let room = if sign > 0.0 {
            top.max[e] - target.max[e] - size
        } else {
            target.min[e] - top.min[e] - size
        };
        // A hair inside the edge, so that rounding never leaves it over it.
        let gap = (room - 1e-6).min(GAP);
        (gap >= 0.0 && at(gap)).then_some(gap)
    }

    /// The relation that sets `me` on the side of `target` on axis `e` toward `sign`
    /// within `top`: [`relations::Relation::Side`], or [`relations::Relation::SideGap`]
    /// closer than [`GAP`] where only that fits; `None` where it does not fit.
    fn side_within(
        me: &crate::geometry::Aabb,
        target: &crate::geometry::Aabb,
        top: &crate::geometry::Aabb,
        e: usize,
        sign: f64,
    ) -> Option<relations::Relation> {
        Self::gap_beside(me, target, top, e, sign).map(|gap| {
            if gap >= GAP {
                relations::Relation::Side(e, sign)
            } else {
                relations::Relation::SideGap(e, sign, gap)
            }
        })
    }

    /// For "to the left of `t`" (a side `e`, `sign`) where `t` rests on a surface and `s`
    /// does not stay on the floor: the relation that keeps `s` on that surface's top —
    /// nothing put on a surface overhangs it — or `Ok(None)` where `t` rests on nothing.
    ///
    /// # Errors
    /// One line naming the three, when `s` does not fit on that side.
    pub(crate) fn side_on_its_support(
        &self,
        s: usize,
        t: usize,
        e: usize,
        sign: f64,
    ) -> Result<Option<relations::Relation>, ReadError> {
        let Some((scene, a, b, surface)) = self.beside_on_support(s, t) else {
            return Ok(None);
        };
        let (me, target, top) = (
            scene.objects[a].world_aabb(),
            scene.objects[b].world_aabb(),
            scene.objects[surface].world_aabb(),
        );
        match Self::side_within(&me, &target, &top, e, sign) {
            Some(relation) => Ok(Some(relation)),
            None => Err(ReadError::NoFit(format!(
                "'{}' does not fit {} '{}' on '{}': it would hang over the edge; say where else it should go",
                scene.objects[a].name,
                relations::side_name(e, sign),
                scene.objects[b].name,
                scene.objects[surface].name
            ))),
        }
    }
}

/// How far in from a table's edge a thing put in front of a chair drawn up to it stands,
/// beyond its own half size, metres.
const AT_SEAT_INSET: f64 = 0.05;

/// How far object `i` can slide along −x, +x, −z, +z: to the nearest face of an object
/// whose box overlaps its path (across the other horizontal axis and in height, by more
/// than the support gap, so the floor's rug and what it stands on do not stop it), or to
/// the room's wall, 1 cm short; what rests on it goes with it and does not count.
fn runs(scene: &Scene, boxes: &[crate::geometry::Aabb], i: usize) -> [f64; 4] {
    const SHORT: f64 = 0.01;
    let me = boxes[i];
    let carried = scene.carried_by(i);
    let overlaps =
        |a0: f64, a1: f64, b0: f64, b1: f64| a1.min(b1) - a0.max(b0) > crate::scene::SUPPORT_GAP;
    let mut out = [f64::INFINITY; 4];
    if let Some(b) = &scene.bounds {
        out = [
            me.min.x - b.min.x,
            b.max.x - me.max.x,
            me.min.z - b.min.z,
            b.max.z - me.max.z,
        ];
    }
    for (j, other) in boxes.iter().enumerate() {
        if j == i || carried.contains(&j) || !overlaps(me.min.y, me.max.y, other.min.y, other.max.y)
        {
            continue;
        }
        if overlaps(me.min.z, me.max.z, other.min.z, other.max.z) {
            if other.max.x <= me.min.x + SHORT {
                out[0] = out[0].min(me.min.x - other.max.x);
            } else if other.min.x >= me.max.x - SHORT {
                out[1] = out[1].min(other.min.x - me.max.x);
            }
        }
        if overlaps(me.min.x, me.max.x, other.min.x, other.max.x) {
            if other.max.z <= me.min.z + SHORT {
                out[2] = out[2].min(me.min.z - other.max.z);
            } else if other.min.z >= me.max.z - SHORT {
                out[3] = out[3].min(other.min.z - me.max.z);
            }
        }
    }
    out.map(|d| (d - SHORT).max(0.0))
}

/// Reads an instruction with variables into expression trees, one entry per variable it
/// changes, with what is `known` of the bound objects.
///
/// # Errors
/// Why it gives no answer: the unread part of the instruction, quoted, or what the
/// instruction leaves open.
pub fn answer(query: &str, variables: usize, known: &Known<'_>) -> Result<Vec<Entry>, ReadError> {
    let facts = Facts { variables, known };
    let tokens = words::tokenize(query);
    let mut reader = Reader::new(&facts);
    let clauses = clause::split(&tokens);
    let last = clauses.len().saturating_sub(1);
    for (k, mut c) in clauses.into_iter().enumerate() {
        reader.more_follow = k < last;
        reader.clause(&mut c)?;
    }
    if reader.steps.is_empty() {
        return Err(reader::not_read(query, query));
    }
    // A list acts in the pivot frame of the object's original place: turns and scales go
    // first (about the object itself), then the translations (which commute).
    Ok(reader
        .steps
        .iter()
        .map(|(&v, list)| {
            let mut expressions: Vec<Expr> = list
                .iter()
                .filter_map(|s| match s {
                    Step::Turn(e) => Some(e.clone()),
                    Step::Translate(_) => None,
                })
                .collect();
            let moves: Vec<Expr> = list
                .iter()
                .filter_map(|s| match s {
                    Step::Translate(v) => Some(v.clone()),
                    Step::Turn(_) => None,
                })
                .collect();
            if !moves.is_empty() {
                expressions.push(build::translator(build::sum(moves)));
            }
            Entry {
                variable: v,
                expressions,
                near: reader.near.get(&v).copied(),
            }
        })
        .collect())
}

/// The reply as a model would write it: `{"X1": "T(...)"}`, printed from the trees.
pub fn reply_text(entries: &[Entry]) -> String {
    let items: Vec<String> = entries
        .iter()
        .map(|e| {
            let exprs: Vec<String> = e.expressions.iter().map(|x| x.to_string()).collect();
            let value = if exprs.len() == 1 {
                serde_json::Value::String(exprs[0].clone())
            } else {
                serde_json::Value::from(exprs)
            };
            format!("\"X{}\": {value}", e.variable + 1)
        })
        .collect();
    format!("{{{}}}", items.join(", "))
}

/// Reads an instruction into the reply text a model would give (for tools and tests).
///
/// # Errors
/// As [`answer`].
pub fn reply_for(query: &str, variables: usize) -> Result<String, ReadError> {
    let known = Known {
        room: true,
        yaw: vec![0.0; variables],
        ..Known::default()
    };
    answer(query, variables, &known).map(|e| reply_text(&e))
}

impl Translator for OfflineTranslator {
    fn name(&self) -> String {
        "offline".into()
    }

    fn system(&self) -> System {
        System::Cga
    }

    fn translate(
        &self,
        templated: &Templated,
        scene: &Scene,
    ) -> Result<Translation, TranslateError> {
        let started = Instant::now();
        let known = Known::of(scene, &templated.objects);
        let entries = answer(&templated.query, templated.objects.len(), &known).map_err(|r| {
            if r.settled() {
                TranslateError::settled(r.to_string())
            } else {
                TranslateError::not_understood(r.to_string())
            }
        })?;
        let bindings: Bindings = bindings(scene, &templated.objects);
        let reply = reply_text(&entries);
        let mut answers = Vec::new();
        for e in &entries {
            let mut m = cga::Multivector::ONE;
            for x in &e.expressions {
                let item = expr::evaluate_tree(x, &bindings)
                    .and_then(|v| expr::to_transformation(&v))
                    .map_err(|err| {
                        TranslateError::not_understood(format!(
                            "the offline translator cannot do \"{}\" in this scene ({err})",
                            templated.query
                        ))
                    })?;
                m = item.versor * m;
            }
            let transformation = expr::to_transformation(&m).map_err(|err| {
                TranslateError::not_understood(format!(
                    "the offline translator cannot do \"{}\" in this scene ({err})",
                    templated.query
                ))
            })?;
            answers.push(Answer {
                variable: Templated::variable(e.variable),
                object: templated.objects[e.variable],
                expressions: e.expressions.iter().map(ToString::to_string).collect(),
                transformation,
                near: e.near.map(|n| n.map(|v| templated.objects[v])),
            });
        }
        let exchange = Exchange {
            messages: vec![Message::new(
                "user",
                format!("Instruction: {}", templated.query),
            )],
            reply,
            elapsed_ms: started.elapsed().as_secs_f64() * 1000.0,
            usage: Usage::default(),
            error: None,
            cached: false,
        };
        Ok(Translation {
            answers,
            exchanges: vec![exchange],
            retries: 0,
            cache_hit: false,
            elapsed: started.elapsed(),
            answered_by: "offline".into(),
            offline_refusal: None,
            replies: Default::default(),
        })
    }
}

/// The size of a world box turned a quarter turn about the vertical: its x and z swapped.
fn quarter_turned(size: glam::DVec3) -> glam::DVec3 {
    glam::DVec3::new(size.z, size.y, size.x)
}

#[cfg(test)]
mod tests;

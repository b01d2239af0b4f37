//! Resolution: the nearest collision-free placement for the moved groups.

use super::detect::{
    collides, find_collisions_in, overlap_volume, room_violations, stands_on_covering, Obstacle,
    Overlap,
};
use super::EPSILON;
use crate::geometry::{Aabb, FloorGrid};
use crate::scene::form::clear_in;
use crate::scene::{AppliedMotion, Form, Room, Scene};
use glam::{DVec2, DVec3};
use std::cmp::Ordering;
use std::collections::BinaryHeap;
use std::time::{Duration, Instant};

/// How the search runs.
#[derive(Clone, Debug, PartialEq)]
pub struct ResolveOptions {
    /// Spacing of the horizontal candidate grid, in metres.
    pub step: f64,
    /// Horizontal clearance a resolved placement keeps from other objects and walls, so
    /// objects are not left wedged against each other (metres).
    pub buffer: f64,
    /// Largest displacement searched, in metres.
    pub radius: f64,
    /// Time after which the search gives up.
    pub time_budget: Duration,
    /// Apply the edit even when no free placement is found, and report the overlaps.
    pub allow_collisions: bool,
}

impl Default for ResolveOptions {
    fn default() -> Self {
        Self {
            step: 0.05,
            buffer: 0.02,
            radius: 2.0,
            time_budget: Duration::from_millis(500),
            allow_collisions: false,
        }
    }
}

/// What resolution did to one group.
#[derive(Clone, Debug, PartialEq)]
pub struct Adjustment {
    /// The group's edited object.
    pub object: usize,
    /// Every object of the group (the edited one and those resting on it).
    pub group: Vec<usize>,
    /// Where the edit put the object: the bottom centre of its box.
    pub requested: DVec3,
    /// Where it ended: the bottom centre of its box.
    pub resolved: DVec3,
    /// The translation resolution applied.
    pub displacement: DVec3,
    /// What it collided with at the requested placement.
    pub collided_with: Vec<Obstacle>,
    /// The object it was lifted onto, when no spot on its own level was free.
    pub lifted_onto: Option<usize>,
}

/// The result of resolution.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Resolution {
    /// The groups that were moved to free placements.
    pub adjustments: Vec<Adjustment>,
    /// Overlaps left in place (only with `allow_collisions`).
    pub remaining: Vec<Overlap>,
    /// The translations applied, for undo.
    pub motion: AppliedMotion,
    /// How many candidate placements were tested.
    pub candidates_tested: usize,
    /// Milliseconds finding the collisions and preparing the search (linear in the scene).
    pub setup_ms: f64,
    /// Milliseconds searching for free placements (what the time budget bounds).
    pub search_ms: f64,
}

fn ms(since: Instant) -> f64 {
    since.elapsed().as_secs_f64() * 1000.0
}

/// Why the edit cannot be placed: which object, what blocks it, and why the search ended.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ResolveError {
    /// Put on a top face that is full where it would go.
    #[error("no free spot for '{object}' on top of '{surface}': it is full where '{object}' would go ({} in the way)", blocking.join(", "))]
    SurfaceFull {
        /// The object placed.
        object: String,
        /// What it was put on.
        surface: String,
        /// What is in the way.
        blocking: Vec<String>,
    },
    /// No free placement within the search's reach or time.
    #[error("no collision-free placement for '{object}' ({end}): it collides with {}", blocking.join(", "))]
    NoPlace {
        /// The object placed.
        object: String,
        /// Why the search ended.
        end: SearchEnd,
        /// What it collides with.
        blocking: Vec<String>,
    },
}

/// How a search for a free placement ended without one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SearchEnd {
    /// Its time budget ran out.
    OutOfTime(Duration),
    /// Nothing free within the radius, in metres.
    OutOfReach(f64),
}

impl std::fmt::Display for SearchEnd {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::OutOfTime(budget) => {
                write!(f, "the search stopped after {} ms", budget.as_millis())
            }
            Self::OutOfReach(radius) => write!(f, "none within {radius} m"),
        }
    }
}

/// What the caller knows of the objects' kinds, which resolution reads
/// (`ground::kind::Lexical` reads them from the lexicon).
pub trait Kinds {
    /// Whether object `i` is floor furniture, which resolution never lifts onto anything
    /// (lifting is for small things).
    fn floor_bound(&self, scene: &Scene, i: usize) -> bool;
    /// The form of object `j` when object `i` may stand in its room: `j` is a top on legs
    /// that `i` was put under, or an open container `i` was put in (`scene::form`).
    fn room(&self, scene: &Scene, i: usize, j: usize) -> Option<Room>;
}

/// A floor-furniture test alone is the kinds of a caller that puts nothing under
/// anything.
impl<F: Fn(&Scene, usize) -> bool> Kinds for F {
    fn floor_bound(&self, scene: &Scene, i: usize) -> bool {
        self(scene, i)
    }

    fn room(&self, _: &Scene, _: usize, _: usize) -> Option<Room> {
        None
    }
}

/// The kinds of the objects, as the caller knows them.
pub type FloorBound<'a> = &'a dyn Kinds;

/// Finds collisions the edit created among `moved` objects (the edited ones; what rests on
/// them moves with them) and moves each colliding group to the nearest free placement.
/// `before` are the world boxes before the edit, in object order.
///
/// # Errors
/// No free placement within the radius or the time budget (unless collisions are
/// allowed); the scene is then as it was.
pub fn resolve(
    scene: &mut Scene,
    before: &[Aabb],
    moved: &[usize],
    floor_bound: FloorBound<'_>,
    options: &ResolveOptions,
) -> Result<Resolution, ResolveError> {
    let mut after = scene.world_aabbs();
    let mut grid = FloorGrid::new(&after);
    let boxes = Boxes {
        before,
        after: &mut after,
        grid: &mut grid,
    };
    resolve_with(scene, boxes, moved, floor_bound, options)
}

/// The world boxes an edit is resolved with: `before` the edit, `after` it (kept up to
/// date as groups move) and a floor grid over `after`.
pub struct Boxes<'b> {
    /// Before the edit, in object order.
    pub before: &'b [Aabb],
    /// After it, in object order.
    pub after: &'b mut [Aabb],
    /// A grid over `after`.
    pub grid: &'b mut FloorGrid,
}

/// [`resolve`] with the world boxes after the edit (`after`) and a grid over them, both
/// kept up to date as groups move. Setup is linear in the scene and always runs; the time
/// budget covers the search only. On an error the scene, `after` and `grid` are as they
/// were.
///
/// # Errors
/// As [`resolve`].
pub fn resolve_with(
    scene: &mut Scene,
    boxes: Boxes<'_>,
    moved: &[usize],
    floor_bound: FloorBound<'_>,
    options: &ResolveOptions,
) -> Result<Resolution, ResolveError> {
    let Boxes {
        before,
        after,
        grid,
    } = boxes;
    let mut resolution = Resolution::default();
    // The boxes as they were, of every object the search moves, to put back exactly.
    let mut saved: Vec<(usize, Aabb)> = Vec::new();
    match search(
        scene,
        before,
        after,
        grid,
        moved,
        options,
        floor_bound,
        &mut resolution,
        &mut saved,
    ) {
        Ok(()) => Ok(resolution),
        Err(e) => {
            for &(i, old) in saved.iter().rev() {
                let now = after[i];
                grid.update(i, &now, &old);
                after[i] = old;
            }
            scene.undo(&resolution.motion);
            Err(e)
        }
    }
}

#[allow(clippy::too_many_arguments)]
/// The search for free placements, one group after another: what every group's search
/// shares.
struct Search<'s> {
    scene: &'s mut Scene,
    before: &'s [Aabb],
    after: &'s mut [Aabb],
    grid: &'s mut FloorGrid,
    options: &'s ResolveOptions,
    floor_bound: FloorBound<'s>,
    resolution: &'s mut Resolution,
    saved: &'s mut Vec<(usize, Aabb)>,
    floor: f64,
    room: Option<Aabb>,
    /// When the search (not the setup) started: what the time budget bounds.
    started: Instant,
    /// The horizontal grid of offsets, nearest first.
    horizontal: Vec<DVec2>,
}

/// Where one group stands before its search: what it collides with, what can be in its
/// way, and the level the edit put it on.
struct Group<'g> {
    objects: &'g [usize],
    /// Its edited object.
    root: usize,
    hits: Vec<Obstacle>,
    obstacles: Vec<usize>,
    /// The bottom centre the edit asked for.
    requested: DVec3,
    /// The top face it stands on there, if any (else the floor).
    surface: Option<usize>,
}

#[allow(clippy::too_many_arguments)]
fn search(
    scene: &mut Scene,
    before: &[Aabb],
    after: &mut [Aabb],
    grid: &mut FloorGrid,
    moved: &[usize],
    options: &ResolveOptions,
    floor_bound: FloorBound<'_>,
    resolution: &mut Resolution,
    saved: &mut Vec<(usize, Aabb)>,
) -> Result<(), ResolveError> {
    let setup = Instant::now();
    let groups = rigid(groups(scene, moved), before, after);
    let floor = scene.floor();
    let room = scene.bounds;
    let under = |i: usize, j: usize| floor_bound.room(scene, i, j);
    let collisions = find_collisions_in(grid, before, after, &groups, floor, room.as_ref(), &under);
    if collisions.is_empty() {
        resolution.setup_ms = ms(setup);
        return Ok(());
    }
    let mut in_group = vec![false; after.len()];
    for &i in groups.iter().flatten() {
        in_group[i] = true;
    }
    resolution.setup_ms = ms(setup);
    // The budget starts here: what came before is proportional to the scene and always
    // runs, however large it is.
    let mut search = Search {
        scene,
        before,
        after,
        grid,
        options,
        floor_bound,
        resolution,
        saved,
        floor,
        room,
        started: Instant::now(),
        horizontal: horizontal_offsets(options.step, options.radius),
    };
    for (g, group) in groups.iter().enumerate() {
        let hits = hits_of(&collisions, group);
        if hits.is_empty() {
            continue;
        }
        let group = search.stand(&groups, g, hits, &in_group);
        search.place(group)?;
    }
    search.resolution.search_ms = ms(search.started);
    Ok(())
}

/// What a group collides with: each obstacle once, a collision with another group's
/// object named by that object.
fn hits_of(collisions: &[Overlap], group: &[usize]) -> Vec<Obstacle> {
    collisions
        .iter()
        .filter(|c| {
            group.contains(&c.object) || matches!(c.with, Obstacle::Object(j) if group.contains(&j))
        })
        .map(|c| match c.with {
            Obstacle::Object(j) if group.contains(&j) => Obstacle::Object(c.object),
            other => other,
        })
        .fold(Vec::new(), |mut acc, o| {
            if !acc.contains(&o) {
                acc.push(o);
            }
            acc
        })
}

impl Search<'_> {
    /// Group `g` as it stands: the obstacles that can matter (fixed ones near its reach,
    /// and the other groups) and the level the edit put it on — the top of an object it
    /// stands on there, or the floor. Resolution slides along that level first, keeping a
    /// placement on a top face on that face, and lifts onto another object only when
    /// nothing on the level is free within the radius.
    fn stand<'g>(
        &self,
        groups: &'g [Vec<usize>],
        g: usize,
        hits: Vec<Obstacle>,
        in_group: &[bool],
    ) -> Group<'g> {
        let group = &groups[g];
        let span = self.span(group);
        let reach = self.options.radius + self.options.buffer + self.options.step;
        let region = Aabb::new(
            span.min - DVec3::splat(reach),
            span.max + DVec3::splat(reach),
        );
        let mut obstacles: Vec<usize> = self
            .grid
            .near_box(&region)
            .into_iter()
            .filter(|&k| !in_group[k])
            .collect();
        obstacles.extend(
            groups
                .iter()
                .enumerate()
                .filter(|(h, _)| *h != g)
                .flat_map(|(_, m)| m.iter().copied()),
        );
        let after = &*self.after;
        obstacles.retain(|&j| after[j].max.y >= region.min.y && after[j].min.y <= region.max.y);
        let root = group[0];
        let requested = after[root].bottom_center();
        let surface = obstacles.iter().copied().find(|&j| {
            let t = after[j];
            (after[root].min.y - t.max.y).abs() < 0.01
                && requested.x >= t.min.x
                && requested.x <= t.max.x
                && requested.z >= t.min.z
                && requested.z <= t.max.z
        });
        Group {
            objects: group,
            root,
            hits,
            obstacles,
            requested,
            surface,
        }
    }

    /// The union of the group's boxes.
    fn span(&self, group: &[usize]) -> Aabb {
        group
            .iter()
            .map(|&i| self.after[i])
            .reduce(|a, b| a.union(&b))
            .expect("groups are not empty")
    }

    /// Moves the group to the nearest free placement, leaves it overlapping (collisions
    /// allowed), or refuses.
    fn place(&mut self, group: Group<'_>) -> Result<(), ResolveError> {
        match self.nearest_free(&group) {
            // An earlier group's move already freed this one.
            Some(offset) if offset == DVec3::ZERO => Ok(()),
            Some(offset) => {
                self.shift(group, offset);
                Ok(())
            }
            None if self.options.allow_collisions => {
                let (kinds, scene) = (self.floor_bound, &*self.scene);
                let left = find_collisions_in(
                    self.grid,
                    self.before,
                    self.after,
                    std::slice::from_ref(&group.objects.to_vec()),
                    self.floor,
                    self.room.as_ref(),
                    &|i, j| kinds.room(scene, i, j),
                );
                self.resolution.remaining.extend(left);
                Ok(())
            }
            None => Err(self.no_place(&group)),
        }
    }

    /// The nearest free offset for the group: on its level first, then lifted onto
    /// surfaces (never for floor furniture, nor off a top face), then, on a top face, a
    /// finer search of that face; among equally near ones, the one closest to where the
    /// object was before the edit (it backs out the way it came). `None` when nothing is
    /// free within the radius or the time budget ran out.
    fn nearest_free(&mut self, group: &Group<'_>) -> Option<DVec3> {
        let after = &*self.after;
        let (root, requested, surface) = (group.root, group.requested, group.surface);
        let span = self.span(group.objects);
        let lifts = lifts(
            &span,
            &group.obstacles,
            after,
            self.floor,
            self.options.radius,
        );
        // Within the face when the edit put it within (a placement on the surface);
        // its footprint's centre over the face when it already overhung (real furniture
        // overhangs: a tv turned on its stand).
        let contained = surface.is_some_and(|j| after[root].footprint_within(&after[j]));
        let on_surface = |offset: DVec3| -> bool {
            let Some(j) = surface else { return true };
            if offset.y.abs() > 1e-12 {
                return true;
            }
            let t = after[j];
            let b = after[root].translated(offset);
            if contained {
                return b.footprint_within(&t);
            }
            let c = b.center();
            c.x >= t.min.x && c.x <= t.max.x && c.z >= t.min.z && c.z <= t.max.z
        };
        let origin = self.before[root].bottom_center();
        // The level first (no lift, or back up to the floor), then lifts onto surfaces.
        let floor = self.floor;
        let level: Vec<f64> = lifts
            .iter()
            .copied()
            .filter(|&dy| dy.abs() < 1e-12 || after[root].min.y + dy <= floor + EPSILON)
            .collect();
        // Put on a top face, it stays on that face: never stacked on what stands there
        // (a stack is asked for by the instruction, which puts it on that object's top).
        // Floor furniture is never lifted onto anything: lifting is for small things.
        let raised: Vec<f64> =
            if surface.is_some() || self.floor_bound.floor_bound(self.scene, root) {
                Vec::new()
            } else {
                lifts
                    .iter()
                    .copied()
                    .filter(|dy| !level.contains(dy))
                    .collect()
            };
        // On a top face, a free spot may be narrower than the grid: after the grid, the
        // face is searched again, [`SURFACE_REFINE`] times finer.
        // (Made only when the grid found nothing.)
        let options = self.options;
        let fine: std::cell::OnceCell<Vec<DVec2>> = std::cell::OnceCell::new();
        let refined = std::iter::once(()).flat_map(|()| {
            let offsets = fine.get_or_init(|| {
                surface.map_or_else(Vec::new, |j| {
                    let face = after[j].size();
                    let reach = face.x.hypot(face.z).min(options.radius);
                    horizontal_offsets(options.step / SURFACE_REFINE, reach)
                })
            });
            ordered_candidates(offsets, &[0.0])
        });
        let candidates = ordered_candidates(&self.horizontal, &level)
            .chain(ordered_candidates(&self.horizontal, &raised))
            .chain(refined)
            .filter(|&offset| on_surface(offset));
        // Which of the group may stand in the room of which obstacle (put under a table,
        // in a box).
        let under: Vec<(usize, usize, Room)> = group
            .objects
            .iter()
            .flat_map(|&i| group.obstacles.iter().map(move |&j| (i, j)))
            .filter_map(|(i, j)| self.floor_bound.room(self.scene, i, j).map(|f| (i, j, f)))
            .collect();
        let check = Placement {
            group: group.objects,
            obstacles: &group.obstacles,
            before: self.before,
            after,
            floor,
            room: self.room.as_ref(),
            under: &under,
        };
        let order = |a: &DVec3, b: &DVec3| {
            let (da, db) = (
                (requested + *a - origin).length_squared(),
                (requested + *b - origin).length_squared(),
            );
            da.total_cmp(&db)
        };
        first_free(
            candidates,
            order,
            |offset| {
                check.is_free(
                    offset,
                    if offset == DVec3::ZERO {
                        0.0
                    } else {
                        options.buffer
                    },
                )
            },
            &mut self.resolution.candidates_tested,
            self.started,
            options.time_budget,
        )
    }

    /// Moves the group by `offset` and records the adjustment.
    fn shift(&mut self, group: Group<'_>, offset: DVec3) {
        let w = cga::Similarity::translation(offset);
        let motion = self.scene.apply_world(group.objects, &w);
        self.resolution.motion.moves.extend(motion.moves);
        for &i in group.objects {
            let old = self.after[i];
            self.saved.push((i, old));
            self.after[i] = old.translated(offset);
            self.grid.update(i, &old, &self.after[i]);
        }
        let after = &*self.after;
        let root = group.root;
        let bottom = after[root].min.y;
        let centre = after[root].center();
        let lifted_onto = if offset.y > EPSILON && bottom > self.floor + EPSILON {
            group
                .obstacles
                .iter()
                .copied()
                .filter(|&j| (after[j].max.y - bottom).abs() < 1e-6)
                .min_by(|&a, &b| {
                    (after[a].center() - centre)
                        .length_squared()
                        .total_cmp(&(after[b].center() - centre).length_squared())
                })
        } else {
            None
        };
        self.resolution.adjustments.push(Adjustment {
            object: root,
            group: group.objects.to_vec(),
            requested: group.requested,
            resolved: group.requested + offset,
            displacement: offset,
            collided_with: group.hits,
            lifted_onto,
        });
    }

    /// Why no placement was found: what is in the way, and whether the search ran out of
    /// time or space.
    fn no_place(&self, group: &Group<'_>) -> ResolveError {
        let scene = &*self.scene;
        let object = scene.objects[group.root].name.clone();
        let blocking: Vec<String> = group.hits.iter().map(|o| o.describe(scene)).collect();
        if let Some(j) = group.surface {
            return ResolveError::SurfaceFull {
                object,
                surface: scene.objects[j].name.clone(),
                blocking,
            };
        }
        let end = if self.started.elapsed() > self.options.time_budget {
            SearchEnd::OutOfTime(self.options.time_budget)
        } else {
            SearchEnd::OutOfReach(self.options.radius)
        };
        ResolveError::NoPlace {
            object,
            end,
            blocking,
        }
    }
}

/// The first candidate offset that is free, taking candidates equally near together and,
/// among them, in `order`; `None` when none is, or when the time budget ran out (checked
/// every 256 candidates, counted in `tested`).
fn first_free(
    candidates: impl Iterator<Item = DVec3>,
    order: impl Fn(&DVec3, &DVec3) -> Ordering,
    is_free: impl Fn(DVec3) -> bool,
    tested: &mut usize,
    started: Instant,
    budget: Duration,
) -> Option<DVec3> {
    let mut candidates = candidates.peekable();
    let mut ties: Vec<DVec3> = Vec::new();
    while let Some(first) = candidates.next() {
        ties.clear();
        ties.push(first);
        while let Some(next) =
            candidates.next_if(|c| (c.length_squared() - first.length_squared()).abs() < 1e-12)
        {
            ties.push(next);
        }
        ties.sort_by(&order);
        for &offset in &ties {
            *tested += 1;
            if *tested % 256 == 0 && started.elapsed() > budget {
                return None;
            }
            if is_free(offset) {
                return Some(offset);
            }
        }
    }
    None
}

/// The edited objects with what rests on them; an object carried by an earlier edited
/// object belongs to that object's group.
fn groups(scene: &Scene, moved: &[usize]) -> Vec<Vec<usize>> {
    let n = scene.objects.len();
    let mut assigned = vec![false; n];
    let mut is_moved = vec![false; n];
    for &m in moved {
        if let Some(flag) = is_moved.get_mut(m) {
            *flag = true;
        }
    }
    // Whether an edited object rests, directly or through others, on another edited
    // object: a walk down its chain of supports (each object has one), not a search of
    // every other edited object's load — a group edit of n objects costs n walks.
    let on_moved = |m: usize| {
        let mut support = scene.objects[m].support;
        for _ in 0..n {
            match support {
                Some(k) if k == m => return false,
                Some(k) if is_moved.get(k).copied().unwrap_or(false) => return true,
                Some(k) => support = scene.objects.get(k).and_then(|o| o.support),
                None => return false,
            }
        }
        false
    };
    let mut groups = Vec::new();
    // Edited objects carried by another edited object join that object's group.
    let roots: Vec<usize> = moved.iter().copied().filter(|&m| !on_moved(m)).collect();
    for root in roots {
        if assigned[root] {
            continue;
        }
        let mut group = vec![root];
        group.extend(scene.carried_by(root).into_iter().filter(|&i| !assigned[i]));
        for &i in &group {
            assigned[i] = true;
        }
        groups.push(group);
    }
    groups
}

/// The most objects a rigid group ([`rigid`]) joins.
const MAX_RIGID: usize = 16;

/// Groups moved together as one thing join: edited groups whose first objects moved by the
/// same translation, unturned and unscaled, and stood within half a metre of each other
/// before (a table and the chairs drawn up to it, moved by "table 4 and its chairs") are
/// placed as one, so that clearing an obstacle keeps them together. Large group edits of
/// one motion (every chair of a hall) stay apart: a join is at most [`MAX_RIGID`] objects,
/// and groups are compared only within one motion (to a micrometre) of at most 64 groups,
/// found by one pass over the groups.
fn rigid(groups: Vec<Vec<usize>>, before: &[Aabb], after: &[Aabb]) -> Vec<Vec<usize>> {
    const NEAR: f64 = 0.5;
    const MAX_COMPARED: usize = 64;
    // The groups of each motion: its translation in micrometres.
    let mut by_motion: std::collections::HashMap<[i64; 3], Vec<usize>> =
        std::collections::HashMap::new();
    for (k, g) in groups.iter().enumerate() {
        let r = g[0];
        let m = after[r].center() - before[r].center();
        let unturned = (after[r].size() - before[r].size()).length() < 1e-9;
        if unturned && m.length() >= 1e-9 {
            let key = (m * 1e6).round().to_array().map(|x| x as i64);
            by_motion.entry(key).or_default().push(k);
        }
    }
    let mut parent: Vec<usize> = (0..groups.len()).collect();
    let find = |parent: &mut Vec<usize>, mut i: usize| {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    };
    let mut size: Vec<usize> = groups.iter().map(Vec::len).collect();
    for same in by_motion.values().filter(|s| s.len() <= MAX_COMPARED) {
        for (n, &a) in same.iter().enumerate() {
            for &b in &same[n + 1..] {
                if before[groups[a][0]].floor_gap(&before[groups[b][0]]) > NEAR {
                    continue;
                }
                let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
                if ra != rb && size[ra] + size[rb] <= MAX_RIGID {
                    parent[rb] = ra;
                    size[ra] += size[rb];
                }
            }
        }
    }
    let mut joined: Vec<Vec<usize>> = vec![Vec::new(); groups.len()];
    for (i, g) in groups.into_iter().enumerate() {
        let r = find(&mut parent, i);
        joined[r].extend(g);
    }
    joined.into_iter().filter(|g| !g.is_empty()).collect()
}

/// Checks candidate placements of one group.
struct Placement<'a> {
    group: &'a [usize],
    obstacles: &'a [usize],
    before: &'a [Aabb],
    after: &'a [Aabb],
    floor: f64,
    room: Option<&'a Aabb>,
    /// (a member of the group, an obstacle, its form) where the member may stand in the
    /// obstacle's room.
    under: &'a [(usize, usize, Room)],
}

impl Placement<'_> {
    /// Whether the group moved by `offset` collides with nothing: other objects (kept
    /// `buffer` away horizontally unless the overlap existed before), the floor, walls and
    /// ceiling.
    fn is_free(&self, offset: DVec3, buffer: f64) -> bool {
        let pad = DVec3::new(buffer, 0.0, buffer);
        for &i in self.group {
            let moved = self.after[i].translated(offset);
            let padded = Aabb::new(moved.min - pad, moved.max + pad);
            for &j in self.obstacles {
                let volume_before = overlap_volume(&self.before[i], &self.before[j]);
                let blocked = if stands_on_covering(&moved, &self.after[j], self.floor)
                    || self.under.iter().any(|&(m, o, f)| {
                        // A chair's seat and back beside a solid box keep the buffer;
                        // the room under a top or in a box is measured as it is.
                        let own = if f.form == Form::Solid {
                            &padded
                        } else {
                            &moved
                        };
                        (m, o) == (i, j) && clear_in(own, &self.after[j], f)
                    }) {
                    false
                } else if volume_before > 0.0 {
                    collides(&moved, &self.after[j], volume_before)
                } else {
                    padded.intersects(&self.after[j], EPSILON)
                };
                if blocked {
                    return false;
                }
            }
            let was = room_violations(&self.before[i], self.floor, self.room);
            for (obstacle, depth) in room_violations(&padded, self.floor, self.room) {
                let before_depth = was
                    .iter()
                    .find(|(o, _)| *o == obstacle)
                    .map_or(0.0, |(_, d)| *d);
                if depth > before_depth + EPSILON {
                    return false;
                }
            }
        }
        true
    }
}

/// How many times finer than the grid a top face is searched when the grid finds no free
/// spot on it (a mug beside a plate on a small side table fits in a gap of a few
/// centimetres).
const SURFACE_REFINE: f64 = 5.0;

/// Horizontal offsets within `radius` on a grid of `step`, nearest first (ties broken by
/// coordinates, so the order is deterministic).
pub(crate) fn horizontal_offsets(step: f64, radius: f64) -> Vec<DVec2> {
    let n = (radius / step).floor() as i64;
    let mut offsets: Vec<(i64, i64)> = Vec::new();
    for i in -n..=n {
        for k in -n..=n {
            if ((i * i + k * k) as f64) * step * step <= radius * radius + 1e-12 {
                offsets.push((i, k));
            }
        }
    }
    offsets.sort_by_key(|&(i, k)| (i * i + k * k, i, k));
    offsets
        .into_iter()
        .map(|(i, k)| DVec2::new(i as f64 * step, k as f64 * step))
        .collect()
}

/// Vertical offsets to try: none, and those that set the group's bottom on the top of a
/// nearby obstacle or on the floor (lifting onto a surface, as in the paper), up to
/// `radius`, lowest first.
fn lifts(span: &Aabb, obstacles: &[usize], boxes: &[Aabb], floor: f64, radius: f64) -> Vec<f64> {
    let mut lifts = vec![0.0];
    if span.min.y < floor - EPSILON {
        lifts.push(floor - span.min.y);
    }
    for &j in obstacles {
        let lift = boxes[j].max.y - span.min.y;
        if lift > EPSILON && lift <= radius {
            lifts.push(lift);
        }
    }
    lifts.sort_by(f64::total_cmp);
    lifts.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    lifts
}

/// Every (horizontal, vertical) combination in order of increasing total displacement: a
/// k-way merge of the horizontal list (already sorted) for each vertical offset.
fn ordered_candidates<'a>(
    horizontal: &'a [DVec2],
    lifts: &'a [f64],
) -> impl Iterator<Item = DVec3> + 'a {
    #[derive(PartialEq)]
    struct Next {
        length2: f64,
        lift: usize,
        index: usize,
    }
    impl Eq for Next {}
    impl Ord for Next {
        fn cmp(&self, other: &Self) -> Ordering {
            // Reversed: BinaryHeap is a max-heap and the nearest must come first.
            other
                .length2
                .total_cmp(&self.length2)
                .then(other.lift.cmp(&self.lift))
                .then(other.index.cmp(&self.index))
        }
    }
    impl PartialOrd for Next {
        fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
            Some(self.cmp(other))
        }
    }
    let mut heap: BinaryHeap<Next> = lifts
        .iter()
        .enumerate()
        .filter(|_| !horizontal.is_empty())
        .map(|(lift, dy)| Next {
            length2: dy * dy,
            lift,
            index: 0,
        })
        .collect();
    std::iter::from_fn(move || {
        let next = heap.pop()?;
        let h = horizontal[next.index];
        let dy = lifts[next.lift];
        if next.index + 1 < horizontal.len() {
            let h2 = horizontal[next.index + 1];
            heap.push(Next {
                length2: h2.length_squared() + dy * dy,
                lift: next.lift,
                index: next.index + 1,
            });
        }
        Some(DVec3::new(h.x, dy, h.y))
    })
}

#[cfg(test)]
mod tests;

//! The placement guarantees of docs/collisions.md, checked as properties over every scene
//! the project has — the built-in examples, the dev suites' scenes, the ProcTHOR houses
//! and glTF files of ../shared/data (skipped with a message when absent) — for every
//! (object, destination) pair that makes sense, through the whole pipeline (offline
//! translator, collision resolution). Each pair must either be refused with a one-line
//! reason or end as the guarantee says: never a silent wrong placement.
//!
//! 1. **on Y**: bottom on Y's top, footprint within Y's, nothing new overlapped.
//! 2. **next to Y**: on Y's support level (on the surface Y rests on; on the floor when Y
//!    hangs or the object is floor furniture), horizontal gap at most [`MAX_GAP`], nothing
//!    new overlapped.
//! 3. **no lift**: floor furniture ends on the floor (or the level it stood on), never on
//!    another object.
//! 4. **pre-existing overlaps**: the placed object overlaps nothing it did not overlap
//!    before.
//! 5. **on Y next to Z**, **on Y between Z and W**: one destination.
//! 6. **under Y**: on the level Y stands on, its centre within Y's footprint, its top no
//!    higher than Y's underside — under the top of a table on legs, off its legs; a chair
//!    tucked, its seat so and its back out — or flat
//!    (a rug), nothing new overlapped — or refused, never beside Y.
//! 7. **in Y**: within the walls of an open container Y, above its bottom, below its rim,
//!    or on a shelf of a case of shelves Y, nothing new overlapped — or refused (a solid Y,
//!    or no room), never beside Y; floor furniture put in a table on legs, as under it (6).
//!
//! The counts per scene and property are printed (`cargo test --test placement_properties
//! -- --nocapture`) and quoted in docs/collisions.md.

mod support;

use shenlong::format::procthor::AssetDatabase;
use shenlong::format::SceneFile;
use shenlong::geometry::Aabb;
use shenlong::ground::kind::is_floor_bound;
use shenlong::ground::Grounder;
use shenlong::offline::OfflineTranslator;
use shenlong::pipeline::{edit_with, EditOptions};
use shenlong::scene::Scene;
use std::collections::BTreeMap;
use std::path::Path;
use support::shared_data::shared_data;

/// The largest horizontal gap "next to" may leave, metres (docs/collisions.md).
const MAX_GAP: f64 = shenlong::collide::NEXT_TO_MAX_GAP;
/// Level tolerance, metres.
const LEVEL: f64 = 0.011;
/// Overlap that counts, metres on every axis (collisions.md: touching is not colliding).
const OVERLAP: f64 = 1e-3;
/// Pairs tried per scene and property, at most (spread evenly over all pairs).
const PER_SCENE: usize = 120;

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Property {
    On,
    NextTo,
    NoLift,
    OnNextTo,
    OnBetween,
    Under,
    In,
}

#[derive(Default, Debug)]
struct Count {
    placed: usize,
    refused: usize,
}

fn scenes() -> Vec<(String, Scene)> {
    let mut out: Vec<(String, Scene)> = shenlong::examples::list()
        .map(|(name, _)| (name.to_string(), shenlong::examples::build(name).unwrap()))
        .collect();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../bench");
    for dir in ["scenes", "holdout"] {
        let mut files: Vec<_> = std::fs::read_dir(root.join(dir))
            .unwrap()
            .filter_map(Result::ok)
            .map(|e| e.path())
            .filter(|p| p.extension().is_some_and(|x| x == "json") && !is_suite(p))
            .collect();
        files.sort();
        for f in files {
            let scene = SceneFile::load(&f).unwrap().scene;
            out.push((f.file_stem().unwrap().to_string_lossy().into_owned(), scene));
        }
    }
    if let (Some(houses), Some(assets)) = (
        shared_data("procthor/houses.jsonl"),
        shared_data("procthor/asset-database.json"),
    ) {
        let assets = AssetDatabase::load(&assets).unwrap();
        for index in 0..30 {
            let scene = SceneFile::load_house(&houses, index, &assets)
                .unwrap()
                .scene;
            out.push((format!("house {index}"), scene));
        }
    }
    for file in ["CornellBox.glb", "Cubes.glb"] {
        if let Some(path) = shared_data(&format!("gltf/{file}")) {
            // The Cornell box is modelled in millimetres.
            let options = shenlong::format::ReadOptions {
                units: (file == "CornellBox.glb").then_some(shenlong::format::Units::Millimetres),
                ..Default::default()
            };
            out.push((
                file.to_string(),
                SceneFile::load_with(&path, &options).unwrap().scene,
            ));
        }
    }
    out
}

fn is_suite(p: &Path) -> bool {
    p.to_string_lossy().ends_with(".suite.json")
}

/// What a scene offers the properties: boxes, supports, kinds.
struct Facts {
    boxes: Vec<Aabb>,
    floor: f64,
    bound: Vec<bool>,
    /// Objects one may name in quotes (no quote inside the name).
    nameable: Vec<bool>,
}

impl Facts {
    fn of(scene: &Scene) -> Self {
        Self {
            boxes: scene.world_aabbs(),
            floor: scene.floor(),
            bound: (0..scene.objects.len())
                .map(|i| is_floor_bound(scene, i))
                .collect(),
            nameable: scene
                .objects
                .iter()
                .map(|o| !o.name.contains('\'') && !o.name.trim().is_empty())
                .collect(),
        }
    }

    fn area(&self, i: usize) -> f64 {
        let s = self.boxes[i].size();
        s.x * s.z
    }

    /// A thing one can pick up and put somewhere: not floor furniture, not room-sized,
    /// standing on the floor or on something (not hanging on a wall).
    fn portable(&self, scene: &Scene, i: usize) -> bool {
        let b = self.boxes[i];
        !self.bound[i]
            && self.nameable[i]
            && (scene.objects[i].support.is_some() || b.min.y <= self.floor + LEVEL)
    }

    /// A top one can put `x` on: its footprint covers `x`'s, within reach, not resting on
    /// `x`, and nothing taller than it is stood on it already.
    fn surface_for(&self, scene: &Scene, x: usize, y: usize) -> bool {
        let (a, b) = (self.boxes[x].size(), self.boxes[y].size());
        x != y
            && self.nameable[y]
            && b.y <= 1.5
            && b.y >= 0.05
            && a.x <= b.x
            && a.z <= b.z
            && !scene.carried_by(x).contains(&y)
    }
}

/// `n` items of `all`, spread evenly (all of them when there are fewer).
fn spread<T: Clone>(all: &[T], n: usize) -> Vec<T> {
    if all.len() <= n {
        return all.to_vec();
    }
    (0..n).map(|k| all[k * all.len() / n].clone()).collect()
}

/// What went wrong with one placement, or `None`.
type Verdict = Option<String>;

/// Runs `instruction` on a copy of `scene`: `Ok(boxes after)` or `Err(refusal)`.
fn run(
    scene: &Scene,
    grounder: &Grounder,
    instruction: &str,
) -> Result<(Scene, Vec<Aabb>), String> {
    let mut s = scene.clone();
    match edit_with(
        &mut s,
        grounder,
        instruction,
        &OfflineTranslator::new(),
        &EditOptions::default(),
    ) {
        Ok(_) => {
            let boxes = s.world_aabbs();
            Ok((s, boxes))
        }
        Err(e) => Err(e.message),
    }
}

fn overlaps(a: &Aabb, b: &Aabb) -> bool {
    // Furniture stands on a rug: a slab at most 3 cm thick and 40 cm across lying on the
    // floor (y = 0 in these scenes), with the other's bottom no higher than its top.
    let rug = |r: &Aabb| {
        let size = r.size();
        size.y <= 0.03 && size.x.min(size.z) >= 0.4 && r.min.y.abs() <= 0.03
    };
    let stands_on = |x: &Aabb, r: &Aabb| rug(r) && x.min.y <= r.max.y + 1e-4;
    a.overlap(b).cmpgt(glam::DVec3::splat(OVERLAP)).all() && !stands_on(a, b) && !stands_on(b, a)
}

/// Property 4 for every object that moved: nothing overlapped now that was not before.
fn nothing_new_overlapped(scene: &Scene, before: &[Aabb], after: &[Aabb]) -> Verdict {
    // A chair is its seat and its back (docs/collisions.md, "Shapes by kind").
    let seats: Vec<_> = (0..after.len())
        .map(|i| shenlong::ground::kind::seat_of(scene, i))
        .collect();
    let meet = |i: usize, j: usize| match (seats[i], seats[j]) {
        (Some(s), _) => s.parts(&after[i]).iter().any(|p| overlaps(p, &after[j])),
        (None, Some(s)) => s.parts(&after[j]).iter().any(|p| overlaps(&after[i], p)),
        (None, None) => overlaps(&after[i], &after[j]),
    };
    for i in 0..after.len() {
        if (after[i].min - before[i].min).length() < 1e-9 {
            continue;
        }
        for j in 0..after.len() {
            if i != j && meet(i, j) && !overlaps(&before[i], &before[j]) {
                return Some(format!(
                    "'{}' now overlaps '{}'",
                    scene.objects[i].name, scene.objects[j].name
                ));
            }
        }
    }
    None
}

fn within(a: &Aabb, b: &Aabb) -> bool {
    a.min.x >= b.min.x - 1e-6
        && a.max.x <= b.max.x + 1e-6
        && a.min.z >= b.min.z - 1e-6
        && a.max.z <= b.max.z + 1e-6
}

fn centre_over(a: &Aabb, b: &Aabb) -> bool {
    let c = a.center();
    c.x >= b.min.x - 1e-6 && c.x <= b.max.x + 1e-6 && c.z >= b.min.z - 1e-6 && c.z <= b.max.z + 1e-6
}

fn gap(a: &Aabb, b: &Aabb) -> f64 {
    a.floor_gap(b)
}

/// Property 1.
fn check_on(scene: &Scene, f: &Facts, x: usize, y: usize, after: &[Aabb]) -> Verdict {
    let (a, b) = (after[x], after[y]);
    if (a.min.y - b.max.y).abs() > LEVEL {
        return Some(format!(
            "bottom at {:.3}, top of Y at {:.3}",
            a.min.y, b.max.y
        ));
    }
    if !(within(&a, &b) || f.area(x) > f.area(y) * 0.999 && centre_over(&a, &b)) {
        return Some(format!("footprint {a:?} not within {b:?}"));
    }
    nothing_new_overlapped(scene, &f.boxes, after)
}

/// Whether object `i` hangs: rests on nothing, above the floor.
fn hangs(scene: &Scene, f: &Facts, i: usize) -> bool {
    scene.objects[i].support.is_none() && f.boxes[i].min.y > f.floor + LEVEL
}

/// The gap on the floor plan from `a` to object `y` or what `y` stands on.
fn gap_to_stack(scene: &Scene, a: &Aabb, after: &[Aabb], y: usize) -> f64 {
    let mut g = f64::INFINITY;
    let mut next = Some(y);
    while let Some(j) = next {
        g = g.min(gap(a, &after[j]));
        next = scene.objects[j].support.filter(|&s| s != y);
    }
    g
}

/// Property 2 (and 3 for floor furniture).
fn check_next_to(scene: &Scene, f: &Facts, x: usize, y: usize, after: &[Aabb]) -> Verdict {
    let a = after[x];
    // Floor furniture stays down, unless it stands on a table or counter now (a coffee
    // machine on a counter is moved as a thing on a surface).
    let on_a_surface = scene.objects[x]
        .support
        .is_some_and(|s| f.boxes[s].max.y >= f.floor + 0.3);
    let stays = f.bound[x] && !hangs(scene, f, x) && !on_a_surface;
    let y_hangs = hangs(scene, f, y);
    let level = if (stays && f.boxes[y].min.y > f.floor + 0.05) || (y_hangs && !hangs(scene, f, x))
    {
        f.floor
    } else {
        // On the surface Y rests on: its top, where Y floats a little above it.
        let top = scene.objects[y]
            .support
            .map_or(f64::INFINITY, |s| f.boxes[s].max.y);
        f.boxes[y].min.y.min(top)
    };
    // The floor holds it up, unless it already stood below (a glTF scene's floor is
    // only y = 0).
    let level = if f.boxes[x].min.y >= f.floor - LEVEL {
        level.max(f.floor)
    } else {
        level
    };
    // What stood below the floor may also be set on it.
    let below = f.boxes[x].min.y < f.floor - LEVEL && (a.min.y - f.floor).abs() <= LEVEL;
    if (a.min.y - level).abs() > LEVEL && !below {
        return Some(format!(
            "bottom at {:.3}, expected level {level:.3}",
            a.min.y
        ));
    }
    if let Some(s) = scene.objects[y].support.filter(|_| !stays && !y_hangs) {
        if !within(&a, &after[s]) {
            return Some(format!(
                "off '{}', the surface Y rests on",
                scene.objects[s].name
            ));
        }
    }
    let g = if a.min.y <= f.floor + 0.05 {
        gap_to_stack(scene, &a, after, y)
    } else {
        gap(&a, &after[y])
    };
    if g > MAX_GAP + 1e-6 {
        return Some(format!("gap {g:.3} m"));
    }
    nothing_new_overlapped(scene, &f.boxes, after)
}

/// Property 3: floor furniture sent to another object stays on its level.
fn check_no_lift(scene: &Scene, f: &Facts, x: usize, after: &[Aabb]) -> Verdict {
    let a = after[x];
    let stood = f.boxes[x].min.y;
    // The floor's level is the floor or a rug on it.
    if (a.min.y - stood).abs() > LEVEL && a.min.y > f.floor + 0.05 {
        return Some(format!("lifted from {stood:.3} to {:.3}", a.min.y));
    }
    nothing_new_overlapped(scene, &f.boxes, after)
}

/// On Y beside Z, which rests on Y: bottom at Z's bottom or Y's top, whichever is lower
/// (a pillow's level on a sofa's seat), footprint within Y's, nothing new overlapped.
fn check_on_beside(
    scene: &Scene,
    f: &Facts,
    x: usize,
    y: usize,
    z: usize,
    after: &[Aabb],
) -> Verdict {
    let (a, b) = (after[x], after[y]);
    let level = f.boxes[z].min.y.min(b.max.y);
    if (a.min.y - level).abs() > LEVEL {
        return Some(format!(
            "bottom at {:.3}, expected level {level:.3}",
            a.min.y
        ));
    }
    if !(within(&a, &b) || f.area(x) > f.area(y) * 0.999 && centre_over(&a, &b)) {
        return Some(format!("footprint {a:?} not within {b:?}"));
    }
    nothing_new_overlapped(scene, &f.boxes, after)
}

/// Property 5, "on Y next to Z".
fn check_on_next_to(
    scene: &Scene,
    f: &Facts,
    x: usize,
    y: usize,
    z: usize,
    after: &[Aabb],
) -> Verdict {
    check_on_beside(scene, f, x, y, z, after).or_else(|| {
        let g = gap(&after[x], &after[z]);
        (g > MAX_GAP + 1e-6).then(|| format!("gap to Z {g:.3} m"))
    })
}

/// Property 5, "on Y between Z and W".
fn check_on_between(
    scene: &Scene,
    f: &Facts,
    x: usize,
    y: usize,
    z: usize,
    w: usize,
    after: &[Aabb],
) -> Verdict {
    check_on_beside(scene, f, x, y, z, after).or_else(|| {
        let (c, p, q) = (after[x].center(), after[z].center(), after[w].center());
        let (c, p, q) = (
            glam::DVec2::new(c.x, c.z),
            glam::DVec2::new(p.x, p.z),
            glam::DVec2::new(q.x, q.z),
        );
        let d = q - p;
        let t = ((c - p).dot(d) / d.length_squared()).clamp(-1.0, 2.0);
        let off = (p + d * t - c).length();
        (!(0.0..=1.0).contains(&t) || off > 0.3)
            .then(|| format!("not between: t {t:.2}, {off:.2} m off the line"))
    })
}

/// Under Y: on the level Y stands on (the floor under what hangs), centred within Y's
/// footprint, below Y's underside (or flat), nothing new overlapped.
fn check_under(scene: &Scene, f: &Facts, x: usize, y: usize, after: &[Aabb]) -> Verdict {
    let (a, b) = (&after[x], &after[y]);
    if !centre_over(a, b) {
        return Some(format!("not under: {a:?} beside {b:?}"));
    }
    let level = if scene.hangs(y) { f.floor } else { b.min.y };
    if (a.min.y - level).abs() > LEVEL {
        return Some(format!("not on {level:.3}: {:.3}", a.min.y));
    }
    // Under a top on legs: in the room below it, off its legs (a chair: its seat, its back
    // out); it may meet Y there.
    let form = shenlong::ground::kind::form_of(scene, y);
    let on_legs = form.on_legs();
    let tucked = shenlong::ground::kind::seat_of(scene, x)
        .is_some_and(|seat| shenlong::scene::form::clear_tucked(a, b, form, seat));
    if on_legs && (shenlong::scene::form::clear_under(a, b, form) || tucked) {
        let away = Aabb::new(b.min - 1e3, b.min - 1e3);
        let (mut before, mut after) = (f.boxes.clone(), after.to_vec());
        before[y] = away;
        after[y] = away;
        return nothing_new_overlapped(scene, &before, &after);
    }
    if a.max.y > b.min.y + LEVEL && a.size().y > 0.05 {
        return Some(format!(
            "top {:.3} above the underside {:.3}",
            a.max.y, b.min.y
        ));
    }
    // A flat thing slides under what stands where it lies: it overlaps nothing new that
    // reaches below its bottom.
    if a.size().y <= 0.05 {
        let clash = (0..after.len()).find(|&j| {
            j != x
                && after[j].min.y < a.min.y - LEVEL
                && overlaps(a, &after[j])
                && !overlaps(&f.boxes[x], &f.boxes[j])
        });
        return clash.map(|j| {
            format!(
                "'{}' now overlaps '{}'",
                scene.objects[x].name, scene.objects[j].name
            )
        });
    }
    nothing_new_overlapped(scene, &f.boxes, after)
}

/// In Y: within Y's room (an open container), nothing new overlapped but Y.
fn check_in(scene: &Scene, f: &Facts, x: usize, y: usize, after: &[Aabb]) -> Verdict {
    let (a, b) = (&after[x], &after[y]);
    let inside = match shenlong::ground::kind::form_of(scene, y) {
        shenlong::scene::Form::Open => shenlong::scene::form::clear_inside(a, b),
        form @ shenlong::scene::Form::Shelves { .. } => {
            shenlong::scene::form::clear_shelved(a, b, form)
        }
        // Floor furniture put "in" a table or a desk goes under it ("tuck the chair into
        // the desk").
        shenlong::scene::Form::OnLegs { .. } => return check_under(scene, f, x, y, after),
        _ => {
            return Some(format!(
                "put in '{}', which is no container",
                scene.objects[y].name
            ))
        }
    };
    if !inside {
        return Some(format!("not inside: {a:?} in {b:?}"));
    }
    let away = Aabb::new(b.min - 1e3, b.min - 1e3);
    let (mut before, mut after) = (f.boxes.clone(), after.to_vec());
    before[y] = away;
    after[y] = away;
    nothing_new_overlapped(scene, &before, &after)
}

/// "put X under Y" for pairs of a portable or floor-bound X and any other Y.
fn under_pairs(scene: &Scene, f: &Facts) -> Vec<(usize, usize)> {
    let n = scene.objects.len();
    (0..n)
        .filter(|&x| f.nameable[x] && (f.portable(scene, x) || f.bound[x]))
        .flat_map(|x| (0..n).map(move |y| (x, y)))
        .filter(|&(x, y)| {
            x != y
                && f.nameable[y]
                && !scene.carried_by(x).contains(&y)
                && !scene.carried_by(y).contains(&x)
        })
        .collect()
}

#[test]
fn placements_keep_their_guarantees_on_every_scene() {
    let mut counts: BTreeMap<(String, Property), Count> = BTreeMap::new();
    let mut failures: Vec<String> = Vec::new();
    let mut record =
        |scene: &str, p: Property, instruction: &str, outcome: Result<Verdict, String>| {
            let c = counts.entry((scene.to_string(), p)).or_default();
            match outcome {
                Ok(None) => c.placed += 1,
                Ok(Some(why)) => failures.push(format!("{scene}: \"{instruction}\": {why}")),
                Err(message) => {
                    assert!(
                        !message.contains('\n'),
                        "{scene}: \"{instruction}\": a refusal of several lines: {message}"
                    );
                    c.refused += 1;
                }
            }
        };
    for (name, scene) in scenes() {
        let grounder = Grounder::new(&scene);
        let f = Facts::of(&scene);
        let n = scene.objects.len();
        let q = |i: usize| &scene.objects[i].name;
        let on_pairs: Vec<(usize, usize)> = (0..n)
            .filter(|&x| f.portable(&scene, x))
            .flat_map(|x| (0..n).map(move |y| (x, y)))
            .filter(|&(x, y)| f.surface_for(&scene, x, y))
            .collect();
        for (x, y) in spread(&on_pairs, PER_SCENE) {
            let text = format!("put the '{}' on the '{}'", q(x), q(y));
            let out =
                run(&scene, &grounder, &text).map(|(_, after)| check_on(&scene, &f, x, y, &after));
            record(&name, Property::On, &text, out);
        }
        let next_pairs: Vec<(usize, usize)> = (0..n)
            .filter(|&x| f.nameable[x] && (f.portable(&scene, x) || f.bound[x]))
            .flat_map(|x| (0..n).map(move |y| (x, y)))
            .filter(|&(x, y)| {
                x != y
                    && f.nameable[y]
                    && !scene.carried_by(x).contains(&y)
                    && !scene.carried_by(y).contains(&x)
            })
            .collect();
        for (x, y) in spread(&next_pairs, PER_SCENE) {
            let text = format!("put the '{}' next to the '{}'", q(x), q(y));
            let out = run(&scene, &grounder, &text)
                .map(|(_, after)| check_next_to(&scene, &f, x, y, &after));
            record(&name, Property::NextTo, &text, out);
        }
        let lift_pairs: Vec<(usize, usize)> = (0..n)
            .filter(|&x| f.bound[x] && f.nameable[x] && f.boxes[x].min.y <= f.floor + 0.05)
            .flat_map(|x| (0..n).map(move |y| (x, y)))
            .filter(|&(x, y)| x != y && f.nameable[y] && !scene.carried_by(x).contains(&y))
            .collect();
        for (x, y) in spread(&lift_pairs, PER_SCENE) {
            let text = format!("move the '{}' to the '{}'", q(x), q(y));
            let out = run(&scene, &grounder, &text)
                .map(|(_, after)| check_no_lift(&scene, &f, x, &after));
            record(&name, Property::NoLift, &text, out);
        }
        for (x, y) in spread(&under_pairs(&scene, &f), PER_SCENE) {
            let text = format!("put the '{}' in the '{}'", q(x), q(y));
            let out =
                run(&scene, &grounder, &text).map(|(_, after)| check_in(&scene, &f, x, y, &after));
            record(&name, Property::In, &text, out);
        }
        for (x, y) in spread(&under_pairs(&scene, &f), PER_SCENE) {
            let text = format!("put the '{}' under the '{}'", q(x), q(y));
            let out = run(&scene, &grounder, &text)
                .map(|(_, after)| check_under(&scene, &f, x, y, &after));
            record(&name, Property::Under, &text, out);
        }
        // On Y next to Z, on Y between Z and W: Z and W stand on Y.
        let on_y = |y: usize| -> Vec<usize> {
            (0..n)
                .filter(|&z| scene.objects[z].support == Some(y) && f.nameable[z])
                .collect()
        };
        let mut next: Vec<(usize, usize, usize)> = Vec::new();
        let mut between: Vec<(usize, usize, usize, usize)> = Vec::new();
        for &(x, y) in &on_pairs {
            let standing = on_y(y);
            for (k, &z) in standing.iter().enumerate() {
                if z == x {
                    continue;
                }
                next.push((x, y, z));
                for &w in &standing[k + 1..] {
                    if w != x {
                        between.push((x, y, z, w));
                    }
                }
            }
        }
        for (x, y, z) in spread(&next, PER_SCENE) {
            let text = format!(
                "put the '{}' on the '{}' next to the '{}'",
                q(x),
                q(y),
                q(z)
            );
            let out = run(&scene, &grounder, &text)
                .map(|(_, after)| check_on_next_to(&scene, &f, x, y, z, &after));
            record(&name, Property::OnNextTo, &text, out);
        }
        for (x, y, z, w) in spread(&between, PER_SCENE) {
            let text = format!(
                "put the '{}' on the '{}' between the '{}' and the '{}'",
                q(x),
                q(y),
                q(z),
                q(w)
            );
            let out = run(&scene, &grounder, &text)
                .map(|(_, after)| check_on_between(&scene, &f, x, y, z, w, &after));
            record(&name, Property::OnBetween, &text, out);
        }
    }
    let mut totals: BTreeMap<Property, Count> = BTreeMap::new();
    for ((scene, p), c) in &counts {
        println!(
            "{scene:24} {p:?}: {} placed, {} refused",
            c.placed, c.refused
        );
        let t = totals.entry(*p).or_default();
        t.placed += c.placed;
        t.refused += c.refused;
    }
    for (p, c) in &totals {
        println!(
            "all scenes {p:?}: {} pairs, {} placed, {} refused",
            c.placed + c.refused,
            c.placed,
            c.refused
        );
    }
    assert!(
        failures.is_empty(),
        "{} placements broke a guarantee:\n{}",
        failures.len(),
        failures
            .iter()
            .take(60)
            .cloned()
            .collect::<Vec<_>>()
            .join("\n")
    );
}

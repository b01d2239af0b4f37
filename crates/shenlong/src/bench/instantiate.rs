//! Instantiating a suite's queries on its scenes: picking objects for the placeholders,
//! reproducibly from the seed.

use super::suite::{Pick, Query, Suite};
use crate::scene::Scene;

/// One runnable query: a query template with objects picked in one scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Instance {
    /// `query-id@scene#variation`, unique in a run.
    pub id: String,
    /// Index of the query in the suite.
    pub query: usize,
    /// Index of the scene in the suite.
    pub scene: usize,
    /// Which variation (from 0).
    pub variation: usize,
    /// The instruction with the names filled in.
    pub instruction: String,
    /// Placeholder → object index.
    pub bound: Vec<(String, usize)>,
}

/// SplitMix64: a tiny generator with a fixed algorithm, so a seed gives the same picks in
/// every version of Shenlong.
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// The next number.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number in `0..n` (`n > 0`).
    pub fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n as u64) as usize
    }
}

fn hash(text: &str) -> u64 {
    // FNV-1a: stable across runs and platforms.
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

fn fits(scene: &Scene, i: usize, pick: &Pick) -> bool {
    let o = &scene.objects[i];
    let b = o.world_aabb();
    let floor = scene.floor();
    let on_floor = b.min.y <= floor + 0.01;
    let resting = o.support.is_some();
    let carries = scene.objects.iter().any(|p| p.support == Some(i));
    let size = b.size();
    let footprint = size.x * size.z;
    pick.on_floor.is_none_or(|want| want == on_floor)
        && pick.resting.is_none_or(|want| want == resting)
        && pick.carries.is_none_or(|want| want == carries)
        && pick.min_height.is_none_or(|h| size.y >= h)
        && pick.max_height.is_none_or(|h| size.y <= h)
        && pick.min_footprint.is_none_or(|f| footprint >= f)
        && pick.max_footprint.is_none_or(|f| footprint <= f)
        && pick.max_size.is_none_or(|m| size.max_element() <= m)
        && pick
            .name_contains
            .as_ref()
            .is_none_or(|n| o.name.to_lowercase().contains(&n.to_lowercase()))
        && pick.unrotated.is_none_or(|want| {
            want == o
                .similarity()
                .rotation
                .abs_diff_eq(glam::DQuat::IDENTITY, 1e-9)
        })
}

/// The instances of one query in one scene: `variations` picks, each of distinct objects
/// that meet the constraints. Fewer come back when the scene has too few fitting objects.
pub fn instantiate(
    suite: &Suite,
    query_index: usize,
    scene_index: usize,
    scene: &Scene,
) -> Vec<Instance> {
    let query: &Query = &suite.queries[query_index];
    if query.scenes.as_ref().is_some_and(|names| {
        !names
            .iter()
            .any(|n| suite.names_scene(n, scene_index, scene))
    }) {
        return Vec::new();
    }
    let mut rng = SplitMix64::new(
        suite.seed ^ hash(&query.id) ^ hash(&suite.scenes[scene_index].label()).rotate_left(17),
    );
    let candidates: Vec<Vec<usize>> = query
        .pick
        .iter()
        .map(|(_, p)| {
            (0..scene.objects.len())
                .filter(|&i| fits(scene, i, p))
                .collect()
        })
        .collect();
    let mut out = Vec::new();
    // A query without placeholders names its objects itself: once per scene.
    let variations = if query.pick.is_empty() {
        1
    } else {
        suite.variations
    };
    let mut seen: Vec<Vec<usize>> = Vec::new();
    let mut attempts = 0;
    while out.len() < variations && attempts < suite.variations * 50 {
        attempts += 1;
        let mut chosen: Vec<usize> = Vec::new();
        let mut ok = true;
        for list in &candidates {
            let free: Vec<usize> = list
                .iter()
                .copied()
                .filter(|i| !chosen.contains(i))
                .collect();
            if free.is_empty() {
                ok = false;
                break;
            }
            chosen.push(free[rng.below(free.len())]);
        }
        if !ok || seen.contains(&chosen) && attempts < suite.variations * 10 {
            if !ok {
                break;
            }
            continue;
        }
        seen.push(chosen.clone());
        let mut instruction = query.text.clone();
        let mut bound = Vec::new();
        for ((name, _), &i) in query.pick.iter().zip(&chosen) {
            instruction = instruction.replace(&format!("{{{name}}}"), &scene.objects[i].name);
            bound.push((name.clone(), i));
        }
        let variation = out.len();
        out.push(Instance {
            id: format!("{}@{}#{}", query.id, scene.name, variation),
            query: query_index,
            scene: scene_index,
            variation,
            instruction,
            bound,
        });
    }
    out
}

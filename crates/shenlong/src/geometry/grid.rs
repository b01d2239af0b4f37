//! A uniform grid over the floor (the x–z plane) for finding boxes near a point or box.
//!
//! Why a uniform grid: scene objects are of similar size within a factor of a few
//! hundred and spread over a floor, so hashing footprints into square cells sized to the
//! typical object gives O(1) candidates per query and builds in one pass; a BVH would buy
//! nothing for such data and cost a sort. Objects much larger than the cell (a room-sized
//! rug) are kept aside and checked with every query, so one of them cannot flood the grid.

use super::Aabb;
use rustc_hash::FxHashMap;

/// Most cells one box may occupy before it is kept aside as large.
const MAX_CELLS_PER_BOX: i64 = 64;

/// Boxes bucketed by the floor cells their footprints overlap.
#[derive(Clone, Debug)]
pub struct FloorGrid {
    cell: f64,
    cells: FxHashMap<(i64, i64), Vec<usize>>,
    large: Vec<usize>,
}

impl FloorGrid {
    /// A grid over `boxes` (indices are their positions in the slice), with cells sized to
    /// the boxes' median footprint extent.
    pub fn new(boxes: &[Aabb]) -> Self {
        let mut extents: Vec<f64> = boxes
            .iter()
            .map(|b| b.size().x.max(b.size().z))
            .filter(|e| e.is_finite() && *e > 0.0)
            .collect();
        // The median by selection, not a sort: linear in the boxes.
        let middle = extents.len() / 2;
        let median = if extents.is_empty() {
            1.0
        } else {
            *extents.select_nth_unstable_by(middle, f64::total_cmp).1
        };
        let cell = (median * 2.0).max(1e-3);
        let mut grid = Self {
            cell,
            cells: FxHashMap::default(),
            large: Vec::new(),
        };
        for (i, b) in boxes.iter().enumerate() {
            grid.insert(i, b);
        }
        grid
    }

    fn range(&self, b: &Aabb) -> (i64, i64, i64, i64) {
        let f = |v: f64| (v / self.cell).floor().clamp(-1e15, 1e15) as i64;
        (f(b.min.x), f(b.max.x), f(b.min.z), f(b.max.z))
    }

    /// The cells a box occupies, or `None` when it is kept aside as large (or not finite).
    fn cells_of(&self, b: &Aabb) -> Option<(i64, i64, i64, i64)> {
        if !b.is_finite() {
            return None;
        }
        let (x0, x1, z0, z1) = self.range(b);
        ((x1 - x0 + 1).saturating_mul(z1 - z0 + 1) <= MAX_CELLS_PER_BOX).then_some((x0, x1, z0, z1))
    }

    fn insert(&mut self, index: usize, b: &Aabb) {
        let Some((x0, x1, z0, z1)) = self.cells_of(b) else {
            self.large.push(index);
            return;
        };
        for x in x0..=x1 {
            for z in z0..=z1 {
                self.cells.entry((x, z)).or_default().push(index);
            }
        }
    }

    /// Moves box `index` from where `old` put it to where `new` puts it: one box's cells,
    /// not a rebuild.
    pub fn update(&mut self, index: usize, old: &Aabb, new: &Aabb) {
        self.remove(index, old);
        self.insert(index, new);
    }

    fn remove(&mut self, index: usize, b: &Aabb) {
        let Some((x0, x1, z0, z1)) = self.cells_of(b) else {
            self.large.retain(|&i| i != index);
            return;
        };
        for x in x0..=x1 {
            for z in z0..=z1 {
                if let Some(list) = self.cells.get_mut(&(x, z)) {
                    list.retain(|&i| i != index);
                    if list.is_empty() {
                        self.cells.remove(&(x, z));
                    }
                }
            }
        }
    }

    /// Indices of the boxes whose footprint may contain the floor point `(x, z)`
    /// (a superset: check the boxes themselves).
    pub fn near_point(&self, x: f64, z: f64) -> impl Iterator<Item = usize> + '_ {
        let key = (
            (x / self.cell).floor() as i64,
            (z / self.cell).floor() as i64,
        );
        self.cells
            .get(&key)
            .into_iter()
            .flatten()
            .chain(&self.large)
            .copied()
    }

    /// Indices of the boxes whose footprint may overlap the footprint of `b`, each once
    /// (a superset: check the boxes themselves).
    pub fn near_box(&self, b: &Aabb) -> Vec<usize> {
        let mut out: Vec<usize> = self.large.clone();
        let (x0, x1, z0, z1) = self.range(b);
        if (x1 - x0 + 1).saturating_mul(z1 - z0 + 1) > MAX_CELLS_PER_BOX * 16 {
            // A query box far larger than the cells: every cell's contents.
            out.extend(self.cells.values().flatten());
        } else {
            for x in x0..=x1 {
                for z in z0..=z1 {
                    if let Some(list) = self.cells.get(&(x, z)) {
                        out.extend(list);
                    }
                }
            }
        }
        out.sort_unstable();
        out.dedup();
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    fn unit(x: f64, z: f64) -> Aabb {
        Aabb::new(DVec3::new(x, 0.0, z), DVec3::new(x + 1.0, 1.0, z + 1.0))
    }

    #[test]
    fn finds_what_is_near_and_nothing_missing() {
        let mut boxes: Vec<Aabb> = (0..100)
            .map(|i| unit((i % 10) as f64 * 3.0, (i / 10) as f64 * 3.0))
            .collect();
        boxes.push(Aabb::new(DVec3::splat(-100.0), DVec3::splat(100.0))); // a huge one
        let grid = FloorGrid::new(&boxes);
        let near: Vec<usize> = grid.near_point(3.5, 0.5).collect();
        assert!(near.contains(&1) && near.contains(&100));
        assert!(near.len() < 10, "{near:?}");
        // Exhaustive check against brute force for box queries.
        for q in [
            unit(2.5, 2.5),
            unit(-5.0, -5.0),
            Aabb::new(DVec3::splat(0.0), DVec3::splat(30.0)),
        ] {
            let got = grid.near_box(&q);
            for (i, b) in boxes.iter().enumerate() {
                if b.footprint_overlap(&q) > 0.0 {
                    assert!(got.contains(&i), "missed {i} for {q:?}");
                }
            }
        }
    }

    #[test]
    fn an_update_moves_one_box_as_a_rebuild_would() {
        let mut boxes: Vec<Aabb> = (0..50)
            .map(|i| unit((i % 10) as f64 * 3.0, (i / 10) as f64 * 3.0))
            .collect();
        boxes.push(Aabb::new(DVec3::splat(-100.0), DVec3::splat(100.0)));
        let mut grid = FloorGrid::new(&boxes);
        for (i, to) in [(3, unit(40.0, 40.0)), (50, unit(-7.0, 2.0)), (7, boxes[50])] {
            let old = boxes[i];
            boxes[i] = to;
            grid.update(i, &old, &to);
        }
        for q in [
            unit(40.2, 40.2),
            unit(-7.0, 2.0),
            unit(9.0, 0.0),
            unit(0.0, 0.0),
        ] {
            let got = grid.near_box(&q);
            for (i, b) in boxes.iter().enumerate() {
                if b.footprint_overlap(&q) > 0.0 {
                    assert!(got.contains(&i), "missed {i} for {q:?}");
                }
            }
        }
        assert!(
            !grid.near_box(&unit(9.0, 0.0)).contains(&3),
            "3 left its old cell"
        );
    }
}

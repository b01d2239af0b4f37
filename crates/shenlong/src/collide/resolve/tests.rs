use super::*;
use crate::collide::{find_collisions, Obstacle, EPSILON};
use crate::ground::kind::is_floor_bound;
use cga::Multivector;
use proptest::prelude::*;

/// Moves object `i` by `t` (carrying), then resolves.
fn edit(
    scene: &mut Scene,
    i: usize,
    t: DVec3,
    options: &ResolveOptions,
) -> Result<Resolution, ResolveError> {
    let before = scene.world_aabbs();
    scene.apply(i, &Multivector::translator(t), true).unwrap();
    resolve(scene, &before, &[i], &is_floor_bound, options)
}

fn room() -> Scene {
    let mut s = Scene::new("room");
    s.bounds = Some(Aabb::new(
        DVec3::new(-3.0, 0.0, -3.0),
        DVec3::new(3.0, 2.5, 3.0),
    ));
    s
}

#[test]
fn no_collision_means_no_adjustment() {
    let mut s = room();
    let a = s.push_box("a", [0.5, 0.5, 0.5], [0.0, 0.0, 0.0]);
    s.push_box("b", [0.5, 0.5, 0.5], [2.0, 0.0, 0.0]);
    let r = edit(
        &mut s,
        a,
        DVec3::new(1.0, 0.0, 0.0),
        &ResolveOptions::default(),
    )
    .unwrap();
    assert!(r.adjustments.is_empty());
    assert_eq!(r.candidates_tested, 0);
}

#[test]
fn pushed_into_another_object_it_stops_beside_it_with_the_buffer() {
    let mut s = room();
    let a = s.push_box("crate", [0.5, 0.5, 0.5], [0.0, 0.0, 0.0]);
    s.push_box("cabinet", [1.0, 1.0, 1.0], [2.0, 0.0, 0.0]);
    // Asked to move to x = 1.8: deep inside the cabinet (x ∈ [1.5, 2.5]).
    let r = edit(
        &mut s,
        a,
        DVec3::new(1.8, 0.0, 0.0),
        &ResolveOptions::default(),
    )
    .unwrap();
    assert_eq!(r.adjustments.len(), 1);
    let adj = &r.adjustments[0];
    assert_eq!(adj.collided_with, vec![Obstacle::Object(1)]);
    // Nearest: back out along −x until the crate's right side clears the cabinet's left by
    // 2 cm: right side at ≤ 1.48, so centre ≤ 1.23; the grid step is 5 cm from 1.8 → 1.20.
    assert!(
        (adj.displacement - DVec3::new(-0.6, 0.0, 0.0)).length() < 1e-9,
        "{:?}",
        adj.displacement
    );
    let b = s.objects[a].world_aabb();
    assert!((b.max.x - 1.45).abs() < 1e-9);
    assert!(find_collisions(
        &s.world_aabbs(),
        &s.world_aabbs(),
        &[vec![a]],
        0.0,
        s.bounds.as_ref(),
        &|_, _| None
    )
    .is_empty());
}

#[test]
fn resting_objects_move_with_their_support() {
    let mut s = room();
    let table = s.push_box("table", [1.0, 0.8, 1.0], [0.0, 0.0, 0.0]);
    let cup = s.push_box("cup", [0.1, 0.1, 0.1], [0.2, 0.8, 0.2]);
    s.push_box("sofa", [2.0, 0.9, 1.0], [0.0, 0.0, 2.0]);
    s.detect_supports();
    assert_eq!(s.objects[cup].support, Some(table));
    let relative = s.objects[cup].world_aabb().min - s.objects[table].world_aabb().min;
    let r = edit(
        &mut s,
        table,
        DVec3::new(0.0, 0.0, 1.5),
        &ResolveOptions::default(),
    )
    .unwrap();
    let adj = &r.adjustments[0];
    assert_eq!(adj.group, vec![table, cup]);
    let (t, c) = (s.objects[table].world_aabb(), s.objects[cup].world_aabb());
    assert!(
        (c.min.y - t.max.y).abs() < 1e-12,
        "the cup is still on the table"
    );
    assert!(
        (c.min - t.min - relative).length() < 1e-9,
        "and at the same place on it"
    );
}

#[test]
fn the_floor_and_the_walls_push_back() {
    let mut s = room();
    let a = s.push_box("box", [0.5, 0.5, 0.5], [0.0, 0.0, 0.0]);
    let r = edit(
        &mut s,
        a,
        DVec3::new(0.0, -0.3, 0.0),
        &ResolveOptions::default(),
    )
    .unwrap();
    assert_eq!(r.adjustments[0].collided_with, vec![Obstacle::Floor]);
    assert!(
        (s.objects[a].world_aabb().min.y).abs() < 1e-9,
        "back on the floor"
    );
    let r = edit(
        &mut s,
        a,
        DVec3::new(3.0, 0.0, 0.0),
        &ResolveOptions::default(),
    )
    .unwrap();
    assert_eq!(
        r.adjustments[0].collided_with,
        vec![Obstacle::Wall {
            axis: 0,
            max_side: true
        }]
    );
    let b = s.objects[a].world_aabb();
    assert!(b.max.x <= 3.0 - 0.02 + 1e-9 && b.max.x > 2.9, "{b:?}");
}

#[test]
fn several_moved_objects_do_not_collide_with_each_other() {
    let mut s = room();
    let a = s.push_box("a", [0.5, 0.5, 0.5], [-2.0, 0.0, 0.0]);
    let b = s.push_box("b", [0.5, 0.5, 0.5], [2.0, 0.0, 0.0]);
    let before = s.world_aabbs();
    // Both sent to the same spot.
    s.apply(a, &Multivector::translator(DVec3::new(2.0, 0.0, 0.0)), true)
        .unwrap();
    s.apply(
        b,
        &Multivector::translator(DVec3::new(-2.0, 0.0, 0.0)),
        true,
    )
    .unwrap();
    let r = resolve(
        &mut s,
        &before,
        &[a, b],
        &is_floor_bound,
        &ResolveOptions::default(),
    )
    .unwrap();
    assert_eq!(
        r.adjustments.len(),
        1,
        "one of the two yields: {:?}",
        r.adjustments
    );
    let boxes = s.world_aabbs();
    assert!(!boxes[a].intersects(&boxes[b], EPSILON));
}

#[test]
fn lifting_onto_a_surface_is_a_resolution() {
    // A room barely larger than the desk: no floor spot fits the book.
    let mut s = Scene::new("study");
    s.bounds = Some(Aabb::new(
        DVec3::new(-0.8, 0.0, -0.5),
        DVec3::new(0.8, 2.5, 0.5),
    ));
    s.push_box("desk", [1.4, 0.75, 0.7], [0.0, 0.0, 0.0]);
    let book = s.push_box("book", [0.2, 0.05, 0.3], [0.4, 0.75, 0.0]);
    // Pushed down into the desk, it goes back onto the desk's top.
    let r = edit(
        &mut s,
        book,
        DVec3::new(0.0, -0.75, 0.0),
        &ResolveOptions::default(),
    )
    .unwrap();
    assert_eq!(r.adjustments.len(), 1);
    let b = s.objects[book].world_aabb();
    assert!((b.min.y - 0.75).abs() < 1e-9, "on the desk: {b:?}");
    assert!((r.adjustments[0].displacement - DVec3::new(0.0, 0.75, 0.0)).length() < 1e-9);
}

#[test]
fn no_placement_names_what_blocks_and_changes_nothing_else() {
    let mut s = Scene::new("tight");
    s.bounds = Some(Aabb::new(
        DVec3::new(-1.0, 0.0, -1.0),
        DVec3::new(1.0, 1.0, 1.0),
    ));
    let a = s.push_box("piano", [1.9, 0.9, 0.9], [0.0, 0.0, -0.5]);
    s.push_box("bench", [1.9, 0.9, 0.9], [0.0, 0.0, 0.5]);
    let options = ResolveOptions {
        radius: 0.3,
        ..ResolveOptions::default()
    };
    let e = edit(&mut s, a, DVec3::new(0.0, 0.0, 0.6), &options).unwrap_err();
    assert_eq!(
        e.to_string(),
        "no collision-free placement for 'piano' (none within 0.3 m): it collides with 'bench'"
    );
    let mut s2 = Scene::new("tight");
    s2.bounds = s.bounds;
    s2.push_box("piano", [1.9, 0.9, 0.9], [0.0, 0.0, -0.5]);
    s2.push_box("bench", [1.9, 0.9, 0.9], [0.0, 0.0, 0.5]);
    let options = ResolveOptions {
        allow_collisions: true,
        ..options
    };
    let r = edit(&mut s2, a, DVec3::new(0.0, 0.0, 0.6), &options).unwrap();
    assert!(r.adjustments.is_empty());
    assert_eq!(r.remaining.len(), 1);
    assert_eq!(r.remaining[0].with, Obstacle::Object(1));
}

#[test]
fn pre_existing_overlaps_do_not_trigger_resolution() {
    let mut s = room();
    let sofa = s.push_box("sofa", [2.0, 0.9, 0.9], [0.0, 0.0, 0.0]);
    let pillow = s.push_box("pillow", [0.4, 0.3, 0.2], [0.5, 0.4, 0.0]);
    let r = edit(
        &mut s,
        pillow,
        DVec3::new(-0.8, 0.0, 0.0),
        &ResolveOptions::default(),
    )
    .unwrap();
    assert!(r.adjustments.is_empty(), "{:?}", r.adjustments);
    let _ = sofa;
}

#[test]
fn candidates_come_nearest_first() {
    let h = horizontal_offsets(0.05, 0.3);
    let lifts = [0.0, 0.1, 0.75];
    let all: Vec<DVec3> = ordered_candidates(&h, &lifts).collect();
    assert_eq!(all.len(), h.len() * 3);
    assert_eq!(all[0], DVec3::ZERO);
    for pair in all.windows(2) {
        assert!(pair[0].length_squared() <= pair[1].length_squared() + 1e-12);
    }
}

/// An independent validity check: brute force over every other object and the room.
fn free_by_brute_force(
    scene: &Scene,
    before: &[Aabb],
    group: &[usize],
    boxes: &[Aabb],
    offset: DVec3,
    buffer: f64,
) -> bool {
    for &i in group {
        let m = boxes[i].translated(offset);
        let p = Aabb::new(
            m.min - DVec3::new(buffer, 0.0, buffer),
            m.max + DVec3::new(buffer, 0.0, buffer),
        );
        for j in 0..boxes.len() {
            if group.contains(&j) {
                continue;
            }
            let o = m.overlap(&boxes[j]);
            let pre = before[i].overlap(&before[j]);
            let pre_volume = if pre.cmpgt(DVec3::ZERO).all() {
                pre.x * pre.y * pre.z
            } else {
                0.0
            };
            if pre_volume > 0.0 {
                if o.cmpgt(DVec3::splat(EPSILON)).all()
                    && o.x * o.y * o.z > pre_volume * (1.0 + 1e-9) + EPSILON.powi(3)
                {
                    return false;
                }
            } else if p.overlap(&boxes[j]).cmpgt(DVec3::splat(EPSILON)).all() {
                return false;
            }
        }
        if let Some(r) = scene.bounds {
            if p.min.x < r.min.x - EPSILON
                || p.max.x > r.max.x + EPSILON
                || p.min.z < r.min.z - EPSILON
                || p.max.z > r.max.z + EPSILON
                || p.max.y > r.max.y + EPSILON
            {
                return false;
            }
        }
        if p.min.y < scene.floor() - EPSILON {
            return false;
        }
    }
    true
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn resolved_placements_are_free_and_nearest(
        boxes in prop::collection::vec((-2.5f64..2.0, -2.5f64..2.0, 0.2f64..0.8, 0.2f64..1.2), 3..9),
        target in (-2.0f64..2.0, -2.0f64..2.0),
    ) {
        let mut s = room();
        // Lay out boxes on the floor, skipping any that would overlap those placed.
        for (k, (x, z, w, h)) in boxes.iter().enumerate() {
            let b = Aabb::new(DVec3::new(*x, 0.0, *z), DVec3::new(x + w, *h, z + w));
            if s.world_aabbs().iter().any(|o| o.intersects(&b, EPSILON)) { continue; }
            s.push_box(&format!("o{k}"), [*w, *h, *w], [x + w / 2.0, 0.0, z + w / 2.0]);
        }
        prop_assume!(s.objects.len() >= 2);
        let options = ResolveOptions { radius: 1.0, step: 0.1, ..ResolveOptions::default() };
        let before = s.world_aabbs();
        let start = s.objects[0].world_aabb().bottom_center();
        let requested = DVec3::new(target.0, 0.0, target.1) - start;
        s.apply(0, &Multivector::translator(requested), true).unwrap();
        let after = s.world_aabbs();
        match resolve(&mut s, &before, &[0], &is_floor_bound, &options) {
            Ok(r) => {
                let offset = r.adjustments.first().map_or(DVec3::ZERO, |a| a.displacement);
                let buffer = if offset == DVec3::ZERO { 0.0 } else { options.buffer };
                prop_assert!(free_by_brute_force(&s, &before, &[0], &after, offset, buffer));
                // No spot on the floor nearer than the chosen one is free; and a lift onto
                // another object only when no floor spot within the radius is.
                let lifted = offset.y > 1e-9;
                let lifts: Vec<f64> = std::iter::once(0.0).chain(after.iter().skip(1).map(|b| b.max.y - after[0].min.y)).filter(|l| *l >= 0.0 && *l <= options.radius).collect();
                for h in horizontal_offsets(options.step, options.radius) {
                    let level = DVec3::new(h.x, 0.0, h.y);
                    if lifted || level.length() < offset.length() - 1e-9 {
                        let buffer = if level == DVec3::ZERO { 0.0 } else { options.buffer };
                        prop_assert!(!free_by_brute_force(&s, &before, &[0], &after, level, buffer), "{level} is free on the floor, but {offset} was chosen");
                    }
                    if lifted {
                        for &dy in &lifts {
                            let c = DVec3::new(h.x, dy, h.y);
                            if dy > 0.0 && c.length() < offset.length() - 1e-9 {
                                prop_assert!(!free_by_brute_force(&s, &before, &[0], &after, c, options.buffer), "{c} is free and nearer than {offset}");
                            }
                        }
                    }
                }
            }
            Err(e) => prop_assert!(e.to_string().starts_with("no collision-free placement"), "{e}"),
        }
    }
}

#[test]
fn put_on_an_occupied_surface_it_lands_beside_what_is_there_not_on_it() {
    let mut s = room();
    let table = s.push_box("table", [1.2, 0.75, 0.8], [0.0, 0.0, 0.0]);
    let _bowl = s.push_box("bowl", [0.3, 0.1, 0.3], [0.0, 0.75, 0.0]);
    let mug = s.push_box("mug", [0.1, 0.1, 0.1], [1.5, 0.0, 1.5]);
    s.detect_supports();
    // The edit puts the mug at the table's centre, into the bowl.
    let r = edit(
        &mut s,
        mug,
        DVec3::new(-1.5, 0.75, -1.5),
        &ResolveOptions::default(),
    )
    .unwrap();
    let (m, t) = (s.objects[mug].world_aabb(), s.objects[table].world_aabb());
    assert!(
        (m.min.y - 0.75).abs() < 1e-9,
        "on the table's top, not on the bowl: {m:?}"
    );
    assert!(
        m.min.x >= t.min.x - 1e-9
            && m.max.x <= t.max.x + 1e-9
            && m.min.z >= t.min.z - 1e-9
            && m.max.z <= t.max.z + 1e-9
    );
    assert_eq!(r.adjustments[0].lifted_onto, None);
}

#[test]
fn a_gap_on_a_top_face_narrower_than_the_grid_is_found() {
    // A 45 cm side table with an 18 cm plate in its middle: a 9 cm mug fits beside the
    // plate only between 15.5 and 18 cm from the centre, which the 5 cm grid misses.
    let mut s = room();
    let table = s.push_box("side table", [0.45, 0.55, 0.45], [0.0, 0.0, 0.0]);
    let plate = s.push_box("plate", [0.18, 0.015, 0.18], [0.0, 0.55, 0.0]);
    let mug = s.push_box("mug", [0.09, 0.1, 0.09], [1.5, 0.0, 1.5]);
    s.detect_supports();
    let r = edit(
        &mut s,
        mug,
        DVec3::new(-1.5, 0.55, -1.5),
        &ResolveOptions::default(),
    )
    .unwrap();
    let (m, t, p) = (
        s.objects[mug].world_aabb(),
        s.objects[table].world_aabb(),
        s.objects[plate].world_aabb(),
    );
    assert!((m.min.y - 0.55).abs() < 1e-9, "{m:?}");
    assert!(m.footprint_within(&t), "overhangs the table: {m:?}");
    assert!(m.footprint_overlap(&p) <= 1e-9, "in the plate: {m:?}");
    assert_eq!(r.adjustments.len(), 1);
}

#[test]
fn furniture_stands_on_a_rug_and_a_rug_slides_under_furniture() {
    let mut s = room();
    let rug = s.push_box("rug", [1.6, 0.01, 1.0], [0.0, 0.0, 0.0]);
    let basket = s.push_box("basket", [0.45, 0.55, 0.35], [2.0, 0.0, 2.0]);
    s.push_box("bed", [1.6, 0.55, 2.1], [0.0, 0.0, -1.9]);
    s.detect_supports();
    // Onto the rug's footprint, standing on the floor: no collision, nothing moved.
    let r = edit(
        &mut s,
        basket,
        DVec3::new(-2.0, 0.0, -2.0),
        &ResolveOptions::default(),
    )
    .unwrap();
    assert!(r.adjustments.is_empty(), "{:?}", r.adjustments);
    // The rug under the bed.
    let r = edit(
        &mut s,
        rug,
        DVec3::new(0.0, 0.0, -1.5),
        &ResolveOptions::default(),
    )
    .unwrap();
    assert!(r.adjustments.is_empty(), "{:?}", r.adjustments);
    // A box dropped into the bed still collides.
    let r = edit(
        &mut s,
        basket,
        DVec3::new(0.0, 0.0, -1.9),
        &ResolveOptions::default(),
    )
    .unwrap();
    assert_eq!(r.adjustments.len(), 1);
}

#[test]
fn a_full_surface_is_refused_saying_so() {
    let mut s = room();
    let _stool = s.push_box("stool", [0.4, 0.5, 0.4], [0.0, 0.0, 0.0]);
    let _book = s.push_box("book", [0.4, 0.05, 0.4], [0.0, 0.5, 0.0]);
    let cup = s.push_box("cup", [0.1, 0.1, 0.1], [1.5, 0.0, 1.5]);
    s.detect_supports();
    let e = edit(
        &mut s,
        cup,
        DVec3::new(-1.5, 0.5, -1.5),
        &ResolveOptions::default(),
    )
    .unwrap_err();
    assert!(
        e.to_string()
            .contains("no free spot for 'cup' on top of 'stool'"),
        "{e}"
    );
    assert!(e.to_string().contains("'book'"), "{e}");
}

/// A closet barely larger than the crate standing in it (the crate's index is 0): pushed
/// down into the crate, what stands on it can only go back on top of it.
fn closet() -> Scene {
    let mut s = Scene::new("closet");
    s.bounds = Some(Aabb::new(
        DVec3::new(-0.4, 0.0, -0.4),
        DVec3::new(0.4, 2.5, 0.4),
    ));
    s.push_box("crate", [0.7, 0.4, 0.7], [0.0, 0.0, 0.0]);
    s
}

#[test]
fn off_a_surface_a_lift_is_the_last_resort_and_is_reported() {
    let mut s = closet();
    let crate_ = 0;
    let b = s.push_box("box", [0.3, 0.3, 0.3], [0.0, 0.4, 0.0]);
    let r = edit(
        &mut s,
        b,
        DVec3::new(0.0, -0.4, 0.0),
        &ResolveOptions::default(),
    )
    .unwrap();
    assert_eq!(
        r.adjustments[0].lifted_onto,
        Some(crate_),
        "{:?}",
        r.adjustments
    );
}

#[test]
fn an_object_moved_on_the_floor_stays_on_the_floor() {
    // Pushed into a low box, the chair slides beside it rather than onto it.
    let mut s = room();
    let _crate_ = s.push_box("crate", [0.6, 0.3, 0.6], [0.0, 0.0, 0.0]);
    let chair = s.push_box("chair", [0.5, 0.9, 0.5], [1.0, 0.0, 0.0]);
    edit(
        &mut s,
        chair,
        DVec3::new(-0.9, 0.0, 0.0),
        &ResolveOptions::default(),
    )
    .unwrap();
    assert!(s.objects[chair].world_aabb().min.y.abs() < 1e-9);
}

#[test]
fn floor_furniture_is_never_lifted_onto_another_object() {
    // Where a box could only go back on the crate, a chair is refused instead of being
    // stood on it.
    let mut s = closet();
    let chair = s.push_box("chair", [0.4, 0.9, 0.4], [0.0, 0.4, 0.0]);
    let e = edit(
        &mut s,
        chair,
        DVec3::new(0.0, -0.4, 0.0),
        &ResolveOptions::default(),
    )
    .unwrap_err();
    assert!(
        e.to_string()
            .starts_with("no collision-free placement for 'chair'"),
        "{e}"
    );
}

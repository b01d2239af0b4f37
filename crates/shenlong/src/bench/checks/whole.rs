//! Checks of the whole scene: what must not have moved, no new collision, everything
//! inside the room.

use super::{Ctx, Failure, ObjectRef};
use crate::collide::find_collisions;
use crate::geometry::Aabb;

/// These objects — or every object the check's placeholders do not name, with what they carried — did not move.
pub(super) fn unchanged(c: &Ctx<'_>, objects: &Option<Vec<ObjectRef>>) -> Result<(), Failure> {
    let list: Vec<usize> = match objects {
        Some(list) => list.iter().map(|r| c.find(r)).collect::<Result<_, _>>()?,
        None => {
            let mut named: Vec<usize> = c.bound.values().copied().collect();
            for &k in c.bound.values() {
                named.extend(c.before.carried_by(k));
            }
            (0..c.after.objects.len())
                .filter(|k| !named.contains(k))
                .collect()
        }
    };
    for i in list {
        let (p, q) = (
            c.before.objects[i].similarity(),
            c.after.objects[i].similarity(),
        );
        if (p.translation - q.translation).length() > 1e-6
            || p.rotation.dot(q.rotation).abs() < 1.0 - 1e-9
            || (p.scale - q.scale).abs() > 1e-9
        {
            return Err(Failure(format!(
                "'{}' changed but should not have",
                c.name(i)
            )));
        }
    }
    Ok(())
}

/// The edit created no collision.
pub(super) fn no_collision(c: &Ctx<'_>) -> Result<(), Failure> {
    let (bb, ab) = (c.before.world_aabbs(), c.after.world_aabbs());
    let moved: Vec<usize> = (0..ab.len())
        .filter(|&i| {
            (ab[i].min - bb[i].min).length() > 1e-9 || (ab[i].max - bb[i].max).length() > 1e-9
        })
        .collect();
    let groups: Vec<Vec<usize>> = moved.iter().map(|&i| vec![i]).collect();
    // Anything may stand in the room under a table or in a box: the judge does not know
    // what was put where.
    let under = |i: usize, j: usize| crate::ground::kind::room_of(c.after, i, j);
    let found = find_collisions(
        &bb,
        &ab,
        &groups,
        c.after.floor(),
        c.after.bounds.as_ref(),
        &under,
    );
    match found.first() {
        None => Ok(()),
        Some(hit) => Err(Failure(format!(
            "'{}' collides with {}",
            c.after.objects[hit.object].name,
            hit.with.describe(c.after)
        ))),
    }
}

/// Every object inside the room, or no farther out than before.
pub(super) fn inside_bounds(c: &Ctx<'_>) -> Result<(), Failure> {
    let Some(room) = c.after.bounds else {
        return Ok(());
    };
    for i in 0..c.after.objects.len() {
        let (a, b) = (c.b1(i), c.b0(i));
        let out = |x: &Aabb| {
            (room.min - x.min)
                .max(x.max - room.max)
                .max_element()
                .max(0.0)
        };
        if out(&a) > out(&b) + 1e-3 {
            return Err(Failure(format!(
                "'{}' sticks {:.3} m out of the room",
                c.name(i),
                out(&a)
            )));
        }
    }
    Ok(())
}

//! Checks of where an object ended relative to another: on it, next to it, on one side,
//! above or below, between two, aligned, facing, at a distance.

use super::{overlap_xz, v3, Ctx, Failure, ObjectRef};
use glam::DVec3;

/// Resting on the top face of `support`, its centre over it.
pub(super) fn on_top(
    c: &Ctx<'_>,
    object: &ObjectRef,
    support: &ObjectRef,
    tol: f64,
) -> Result<(), Failure> {
    let (i, j) = (c.find(object)?, c.find(support)?);
    let (a, b) = (c.b1(i), c.b1(j));
    let centre = a.center();
    let over = centre.x >= b.min.x - 0.01
        && centre.x <= b.max.x + 0.01
        && centre.z >= b.min.z - 0.01
        && centre.z <= b.max.z + 0.01;
    if (a.min.y - b.max.y).abs() > tol || !over {
        return Err(Failure(format!(
            "'{}' (bottom {:.3}, centre {}) is not on top of '{}' (top {:.3}, {} to {})",
            c.name(i),
            a.min.y,
            v3(centre),
            c.name(j),
            b.max.y,
            v3(b.min),
            v3(b.max)
        )));
    }
    Ok(())
}

/// Beside `other`: not inside it, horizontally within `max_gap`, at a shared height.
pub(super) fn next_to(
    c: &Ctx<'_>,
    object: &ObjectRef,
    other: &ObjectRef,
    max_gap: f64,
) -> Result<(), Failure> {
    let (i, j) = (c.find(object)?, c.find(other)?);
    let (a, b) = (c.b1(i), c.b1(j));
    let o = a.overlap(&b);
    let gap = (-o.x).max(0.0).hypot((-o.z).max(0.0));
    let inside = o.x > 0.02 && o.z > 0.02 && o.y > 0.02;
    let level = o.y > -0.05;
    if inside || gap > max_gap || !level {
        return Err(Failure(format!(
            "'{}' is not next to '{}': gap {:.3} m{}{}",
            c.name(i),
            c.name(j),
            gap,
            if inside { ", overlapping" } else { "" },
            if level { "" } else { ", at another height" }
        )));
    }
    Ok(())
}

/// On one side of `other`, within `max_gap`, facing it.
pub(super) fn side(
    c: &Ctx<'_>,
    object: &ObjectRef,
    other: &ObjectRef,
    (axis, sign): (usize, f64),
    max_gap: f64,
) -> Result<(), Failure> {
    let (i, j) = (c.find(object)?, c.find(other)?);
    let (a, b) = (c.b1(i), c.b1(j));
    let gap = if sign > 0.0 {
        a.min[axis] - b.max[axis]
    } else {
        b.min[axis] - a.max[axis]
    };
    let across = 2 - axis;
    let overlapping_across =
        a.max[across] > b.min[across] - 0.05 && a.min[across] < b.max[across] + 0.05;
    if gap < -0.02 || gap > max_gap || !overlapping_across {
        return Err(Failure(format!(
            "'{}' is not on that side of '{}': gap {:.3} m along {}, {}",
            c.name(i),
            c.name(j),
            gap,
            ["x", "y", "z"][axis],
            if overlapping_across {
                "facing it"
            } else {
                "off to the side"
            }
        )));
    }
    Ok(())
}

/// Entirely above `other`.
pub(super) fn above(
    c: &Ctx<'_>,
    object: &ObjectRef,
    other: &ObjectRef,
    tol: f64,
) -> Result<(), Failure> {
    let (i, j) = (c.find(object)?, c.find(other)?);
    let (a, b) = (c.b1(i), c.b1(j));
    if a.min.y < b.max.y - tol {
        return Err(Failure(format!(
            "'{}' (bottom {:.3}) is not above '{}' (top {:.3})",
            c.name(i),
            a.min.y,
            c.name(j),
            b.max.y
        )));
    }
    Ok(())
}

/// Entirely below `other` (or under it, lower and overlapping its footprint).
pub(super) fn below(
    c: &Ctx<'_>,
    object: &ObjectRef,
    other: &ObjectRef,
    tol: f64,
) -> Result<(), Failure> {
    let (i, j) = (c.find(object)?, c.find(other)?);
    let (a, b) = (c.b1(i), c.b1(j));
    if a.max.y > b.min.y + tol && !(a.center().y < b.center().y && overlap_xz(&a, &b)) {
        return Err(Failure(format!(
            "'{}' (top {:.3}) is not below '{}' (bottom {:.3})",
            c.name(i),
            a.max.y,
            c.name(j),
            b.min.y
        )));
    }
    Ok(())
}

/// Between `a` and `b` on the floor plan.
pub(super) fn between(
    c: &Ctx<'_>,
    object: &ObjectRef,
    a: &ObjectRef,
    b: &ObjectRef,
    tol: f64,
) -> Result<(), Failure> {
    let (i, ja, jb) = (c.find(object)?, c.find(a)?, c.find(b)?);
    let flat = |v: DVec3| glam::DVec2::new(v.x, v.z);
    let (p, pa, pb) = (
        flat(c.b1(i).center()),
        flat(c.b1(ja).center()),
        flat(c.b1(jb).center()),
    );
    let seg = pb - pa;
    let t = if seg.length_squared() > 0.0 {
        (p - pa).dot(seg) / seg.length_squared()
    } else {
        0.0
    };
    let off = (p - (pa + seg * t.clamp(0.0, 1.0))).length();
    if !(-0.05..=1.05).contains(&t) || off > tol {
        return Err(Failure(format!(
            "'{}' is not between '{}' and '{}' (at {:.2} along, {:.3} m off the line)",
            c.name(i),
            c.name(ja),
            c.name(jb),
            t,
            off
        )));
    }
    Ok(())
}

/// Centred with `other` along `axis`.
pub(super) fn aligned(
    c: &Ctx<'_>,
    object: &ObjectRef,
    other: &ObjectRef,
    axis: usize,
    tol: f64,
) -> Result<(), Failure> {
    let (i, j) = (c.find(object)?, c.find(other)?);
    let d = c.b1(i).center()[axis] - c.b1(j).center()[axis];
    if d.abs() > tol {
        return Err(Failure(format!(
            "'{}' and '{}' are {:.3} m apart along {}",
            c.name(i),
            c.name(j),
            d.abs(),
            ["x", "y", "z"][axis]
        )));
    }
    Ok(())
}

/// Its front turned toward `target`, within `tol` degrees.
pub(super) fn faces(
    c: &Ctx<'_>,
    object: &ObjectRef,
    target: &ObjectRef,
    tol: f64,
) -> Result<(), Failure> {
    let (i, j) = (c.find(object)?, c.find(target)?);
    let forward = c.after.objects[i].world_front();
    let to = c.b1(j).center() - c.b1(i).center();
    let (f2, t2) = (
        glam::DVec2::new(forward.x, forward.z),
        glam::DVec2::new(to.x, to.z),
    );
    if f2.length() < 1e-9 || t2.length() < 1e-9 {
        return Err(Failure(format!(
            "'{}' has no horizontal front or '{}' is right above it",
            c.name(i),
            c.name(j)
        )));
    }
    let angle = f2.angle_to(t2).to_degrees().abs();
    if angle > tol {
        return Err(Failure(format!(
            "'{}' faces {:.0}° away from '{}'",
            c.name(i),
            angle,
            c.name(j)
        )));
    }
    Ok(())
}

/// Centre distance to `other` within [`min`, `max`].
pub(super) fn distance(
    c: &Ctx<'_>,
    object: &ObjectRef,
    other: &ObjectRef,
    min: f64,
    max: f64,
) -> Result<(), Failure> {
    let (i, j) = (c.find(object)?, c.find(other)?);
    let d = (c.b1(i).center() - c.b1(j).center()).length();
    if d < min || d > max {
        return Err(Failure(format!(
            "'{}' is {:.3} m from '{}' (wanted {min} to {max})",
            c.name(i),
            d,
            c.name(j)
        )));
    }
    Ok(())
}

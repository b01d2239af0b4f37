//! Checks of how an object moved: by how much, which way, turned, scaled, where it ended,
//! swapped with another.

use super::{angle_difference, opt3, signed_angle_about, v3, Ctx, Failure, ObjectRef};
use glam::{DQuat, DVec3};

/// Moved by `delta` (per axis; `None` = any), within `tol`: the displacement of the bottom centre of its box.
pub(super) fn moved(
    c: &Ctx<'_>,
    object: &ObjectRef,
    delta: &[Option<f64>; 3],
    tol: f64,
) -> Result<(), Failure> {
    let i = c.find(object)?;
    let d = c.b1(i).bottom_center() - c.b0(i).bottom_center();
    for axis in 0..3 {
        if let Some(want) = delta[axis] {
            if (d[axis] - want).abs() > tol {
                return Err(Failure(format!(
                    "'{}' moved by {} (wanted {})",
                    c.name(i),
                    v3(d),
                    opt3(delta)
                )));
            }
        }
    }
    Ok(())
}

/// Moved at least `min` along the axis, and little along the others.
pub(super) fn direction(
    c: &Ctx<'_>,
    object: &ObjectRef,
    (axis, sign): (usize, f64),
    min: f64,
) -> Result<(), Failure> {
    let i = c.find(object)?;
    let d = c.b1(i).bottom_center() - c.b0(i).bottom_center();
    let along = d[axis] * sign;
    let across = (0..3)
        .filter(|&a| a != axis)
        .map(|a| d[a].abs())
        .fold(0.0, f64::max);
    if along < min {
        return Err(Failure(format!(
            "'{}' moved {:.3} m that way (at least {min} wanted): {}",
            c.name(i),
            along,
            v3(d)
        )));
    }
    if across > (0.1f64).max(0.25 * along) {
        return Err(Failure(format!(
            "'{}' also moved {:.3} m across: {}",
            c.name(i),
            across,
            v3(d)
        )));
    }
    Ok(())
}

/// Turned by `degrees` about `axis` (either way with `either_sign`), within `tol`; anything but that turn counts against it.
pub(super) fn rotated(
    c: &Ctx<'_>,
    object: &ObjectRef,
    axis: usize,
    degrees: f64,
    either_sign: bool,
    tol: f64,
) -> Result<(), Failure> {
    let i = c.find(object)?;
    let delta = c.after.objects[i].similarity().rotation
        * c.before.objects[i].similarity().rotation.inverse();
    let mut want = DVec3::ZERO;
    want[axis] = 1.0;
    let turned = signed_angle_about(delta, want);
    let off = |target: f64| angle_difference(turned, target);
    let ok = off(degrees) <= tol || (either_sign && off(-degrees) <= tol);
    // Anything but a turn about the axis counts against it.
    let residual = (DQuat::from_axis_angle(want, turned.to_radians()).inverse() * delta)
        .to_axis_angle()
        .1
        .to_degrees();
    if !ok || residual > tol {
        return Err(Failure(format!(
            "'{}' turned {:.1}° about {} (wanted {}{degrees}°), off-axis {:.1}°",
            c.name(i),
            turned,
            ["x", "y", "z"][axis],
            if either_sign { "±" } else { "" },
            residual
        )));
    }
    Ok(())
}

/// Scaled by `factor`, within `tol` (relative).
pub(super) fn scaled(
    c: &Ctx<'_>,
    object: &ObjectRef,
    factor: f64,
    tol: f64,
) -> Result<(), Failure> {
    let i = c.find(object)?;
    let s = c.after.objects[i].similarity().scale / c.before.objects[i].similarity().scale;
    if (s / factor - 1.0).abs() > tol {
        return Err(Failure(format!(
            "'{}' scaled by {s:.3} (wanted {factor})",
            c.name(i)
        )));
    }
    Ok(())
}

/// Bottom centre at `position` (per axis; `None` = any).
pub(super) fn at(
    c: &Ctx<'_>,
    object: &ObjectRef,
    position: &[Option<f64>; 3],
    tol: f64,
) -> Result<(), Failure> {
    let i = c.find(object)?;
    let p = c.b1(i).bottom_center();
    for axis in 0..3 {
        if let Some(want) = position[axis] {
            if (p[axis] - want).abs() > tol {
                return Err(Failure(format!(
                    "'{}' is at {} (wanted {})",
                    c.name(i),
                    v3(p),
                    opt3(position)
                )));
            }
        }
    }
    Ok(())
}

/// Each of the two stands where the other stood (bottom centres, within `tol`).
pub(super) fn swapped(
    c: &Ctx<'_>,
    object: &ObjectRef,
    other: &ObjectRef,
    tol: f64,
) -> Result<(), Failure> {
    let (i, j) = (c.find(object)?, c.find(other)?);
    let (ai, aj) = (c.b1(i).bottom_center(), c.b1(j).bottom_center());
    let (bi, bj) = (c.b0(i).bottom_center(), c.b0(j).bottom_center());
    if (ai - bj).length() > tol || (aj - bi).length() > tol {
        return Err(Failure(format!(
            "'{}' is {:.3} m from where '{}' was, and '{}' {:.3} m from where '{}' was",
            c.name(i),
            (ai - bj).length(),
            c.name(j),
            c.name(j),
            (aj - bi).length(),
            c.name(i)
        )));
    }
    Ok(())
}

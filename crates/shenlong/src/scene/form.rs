//! What of an object's box is solid: all of it, or a top on legs with room below — a
//! table, a desk, a counter — where a chair is tucked and a stool slides under
//! (docs/collisions.md, "Shapes by kind").
//!
//! A top on legs is read from the object's box: a slab [`top`] thick at the top of the
//! box, and a square leg [`LEG`] wide at each corner of its footprint, from the floor to
//! the slab. What stands clear of those parts does not collide with it.

use crate::geometry::Aabb;

/// What of an object's box is solid.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Form {
    /// The whole box.
    #[default]
    Solid,
    /// A top on four legs, with room below it.
    OnLegs,
    /// An open container: a bottom and four walls, open at the top, with room inside.
    Open,
}

impl Form {
    /// The form a scene file names (`"solid"`, `"on_legs"`), if it names one.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        match name
            .trim()
            .to_ascii_lowercase()
            .replace([' ', '-'], "_")
            .as_str()
        {
            "solid" | "box" => Some(Self::Solid),
            "on_legs" | "legs" | "table" => Some(Self::OnLegs),
            "open" | "container" => Some(Self::Open),
            _ => None,
        }
    }

    /// The name a scene file writes.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Solid => "solid",
            Self::OnLegs => "on_legs",
            Self::Open => "open",
        }
    }
}

/// The side of the square leg at each corner of a top on legs, in metres.
pub const LEG: f64 = 0.06;

/// The lowest a top on legs is from the floor to leave room below it, in metres: a
/// coffee table is solid to what goes under it.
pub const KNEE_HEIGHT: f64 = 0.5;

/// The thickness of the top of a table whose box is `table`: 4 cm, at most a quarter of
/// its height.
#[must_use]
pub fn top(table: &Aabb) -> f64 {
    0.04_f64.min(table.size().y * 0.25)
}

/// The height of the room under the top of `table`, from its bottom.
#[must_use]
pub fn knee_room(table: &Aabb) -> f64 {
    table.size().y - top(table)
}

/// How far apart two boxes may touch without colliding, in metres.
const TOUCH: f64 = 1e-6;

/// Whether `a` stands clear of the solid parts of the top on legs whose box is `table`:
/// below its top and off its legs.
#[must_use]
pub fn clear_under(a: &Aabb, table: &Aabb) -> bool {
    if table.size().y < KNEE_HEIGHT || a.max.y > table.max.y - top(table) + TOUCH {
        return false;
    }
    let leg = LEG.min(table.size().x / 2.0).min(table.size().z / 2.0);
    let hits = |lo: f64, hi: f64, from: f64, to: f64| lo < to - TOUCH && hi > from + TOUCH;
    for (x0, x1) in [
        (table.min.x, table.min.x + leg),
        (table.max.x - leg, table.max.x),
    ] {
        for (z0, z1) in [
            (table.min.z, table.min.z + leg),
            (table.max.z - leg, table.max.z),
        ] {
            if hits(a.min.x, a.max.x, x0, x1) && hits(a.min.z, a.max.z, z0, z1) {
                return false;
            }
        }
    }
    true
}

/// The thickness of an open container's walls and bottom, in metres.
pub const WALL: f64 = 0.02;

/// The room inside the open container whose box is `container`: within its walls, above
/// its bottom, up to its rim.
#[must_use]
pub fn inside(container: &Aabb) -> Aabb {
    let wall = WALL.min(container.size().min_element() / 4.0);
    let side = glam::DVec3::new(wall, 0.0, wall);
    Aabb::new(
        container.min + side + glam::DVec3::new(0.0, wall, 0.0),
        container.max - side,
    )
}

/// Whether `a` lies within the room inside the open container whose box is `container`.
#[must_use]
pub fn clear_inside(a: &Aabb, container: &Aabb) -> bool {
    let room = inside(container);
    (a.min - room.min).min_element() >= -TOUCH && (room.max - a.max).min_element() >= -TOUCH
}

/// Whether `a` stands clear of the solid parts of `b`, an object of form `form`: in the
/// room under a top on legs, or inside an open container.
#[must_use]
pub fn clear_in(a: &Aabb, b: &Aabb, form: Form) -> bool {
    match form {
        Form::Solid => false,
        Form::OnLegs => clear_under(a, b),
        Form::Open => clear_inside(a, b),
    }
}

/// Whether boxes `a` and `b` of forms `fa` and `fb` meet only where one stands in the
/// room under the other.
#[must_use]
pub fn apart(a: &Aabb, fa: Form, b: &Aabb, fb: Form) -> bool {
    (fb == Form::OnLegs && clear_under(a, b)) || (fa == Form::OnLegs && clear_under(b, a))
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    fn b(min: [f64; 3], max: [f64; 3]) -> Aabb {
        Aabb::new(DVec3::from(min), DVec3::from(max))
    }

    #[test]
    fn under_the_top_and_off_the_legs_is_clear() {
        let desk = b([0.0, 0.0, 0.0], [1.2, 0.75, 0.6]);
        // A chair tucked in from the front, half under.
        assert!(clear_under(&b([0.4, 0.0, 0.3], [0.85, 0.7, 0.8]), &desk));
        // Too tall: it meets the top.
        assert!(!clear_under(&b([0.4, 0.0, 0.3], [0.85, 0.9, 0.8]), &desk));
        // On a leg.
        assert!(!clear_under(&b([-0.2, 0.0, 0.4], [0.1, 0.5, 0.8]), &desk));
        // A low table leaves no room.
        let coffee = b([0.0, 0.0, 0.0], [1.0, 0.45, 0.6]);
        assert!(!clear_under(&b([0.3, 0.0, 0.2], [0.5, 0.2, 0.4]), &coffee));
        assert!(apart(
            &b([0.4, 0.0, 0.3], [0.85, 0.7, 0.8]),
            Form::Solid,
            &desk,
            Form::OnLegs
        ));
        assert!(!apart(
            &b([0.4, 0.0, 0.3], [0.85, 0.7, 0.8]),
            Form::Solid,
            &desk,
            Form::Solid
        ));
        assert_eq!(Form::from_name("On legs"), Some(Form::OnLegs));
        assert_eq!(Form::from_name("solid"), Some(Form::Solid));
        // In a box 0.4 × 0.3 × 0.3: within its walls, above its bottom.
        let toolbox = b([0.0, 0.0, 0.0], [0.4, 0.3, 0.3]);
        assert!(clear_inside(
            &b([0.05, 0.02, 0.05], [0.35, 0.25, 0.25]),
            &toolbox
        ));
        assert!(
            !clear_inside(&b([0.05, 0.0, 0.05], [0.35, 0.25, 0.25]), &toolbox),
            "through its bottom"
        );
        assert!(
            !clear_inside(&b([0.05, 0.02, 0.05], [0.45, 0.25, 0.25]), &toolbox),
            "through a wall"
        );
        assert!(
            !clear_inside(&b([0.05, 0.02, 0.05], [0.35, 0.35, 0.25]), &toolbox),
            "over the rim"
        );
    }
}

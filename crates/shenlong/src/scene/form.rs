//! What of an object's box is solid: all of it, or a top on legs with room below — a
//! table, a desk, a counter — where a chair is tucked and a stool slides under
//! (docs/collisions.md, "Shapes by kind").
//!
//! A top on legs is read from the object's box: a slab [`top`] thick at the top of the
//! box (or, measured from a mesh, down to its underside), and a square leg [`LEG`] wide at
//! each corner of its footprint, from the floor to the slab. What stands clear of those
//! parts does not collide with it.

use crate::geometry::Aabb;

/// What of an object's box is solid.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Form {
    /// The whole box.
    #[default]
    Solid,
    /// A top on four legs, with room below it.
    OnLegs {
        /// How high the room below reaches, in thousandths of the box's height, as
        /// measured from the object's mesh (`scene::mesh`); `None`: up to a top [`top`]
        /// thick, when the box stands at least [`KNEE_HEIGHT`] tall.
        underside: Option<u16>,
    },
    /// An open container: a bottom and four walls, open at the top, with room inside.
    Open,
    /// A case of shelves — a bookcase, a cabinet: walls, a back, a top and a bottom, and
    /// shelves between them [`SHELF_SPACING`] apart, with room on each shelf — or, measured
    /// from its mesh, its own boards.
    Shelves {
        /// Its boards as its mesh shows them (`scene::mesh`); `None`: evenly spaced.
        boards: Option<Boards>,
    },
}

/// The most shelf boards kept from a mesh.
pub const MAX_BOARDS: usize = 16;

/// The boards of a case of shelves measured from its mesh: each board's bottom and top,
/// in thousandths of the case's height, lowest first.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Boards {
    levels: [(u16, u16); MAX_BOARDS],
    count: u8,
}

impl Boards {
    /// The boards of `levels` (bottom and top, thousandths, lowest first); `None` for
    /// fewer than two or more than [`MAX_BOARDS`].
    #[must_use]
    pub fn new(levels: &[(u16, u16)]) -> Option<Self> {
        if levels.len() < 2 || levels.len() > MAX_BOARDS {
            return None;
        }
        let mut out = [(0, 0); MAX_BOARDS];
        out[..levels.len()].copy_from_slice(levels);
        Some(Self {
            levels: out,
            count: u8::try_from(levels.len()).ok()?,
        })
    }

    /// The boards, lowest first.
    #[must_use]
    pub fn levels(&self) -> &[(u16, u16)] {
        &self.levels[..usize::from(self.count)]
    }
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
            "on_legs" | "legs" | "table" => Some(Self::ON_LEGS),
            "open" | "container" => Some(Self::Open),
            "shelves" | "shelved" | "bookcase" | "cabinet" => Some(Self::SHELVES),
            _ => None,
        }
    }

    /// A top on legs whose room below is read from its box ([`top`], [`KNEE_HEIGHT`]).
    pub const ON_LEGS: Self = Self::OnLegs { underside: None };

    /// A case of shelves whose boards are evenly spaced ([`compartments`]).
    pub const SHELVES: Self = Self::Shelves { boards: None };

    /// Whether it is a case of shelves, however its boards are known.
    #[must_use]
    pub fn shelves(self) -> bool {
        matches!(self, Self::Shelves { .. })
    }

    /// Whether it is a top on legs, however its room below is known.
    #[must_use]
    pub fn on_legs(self) -> bool {
        matches!(self, Self::OnLegs { .. })
    }

    /// The name a scene file writes.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Solid => "solid",
            Self::OnLegs { .. } => "on_legs",
            Self::Open => "open",
            Self::Shelves { .. } => "shelves",
        }
    }
}

/// The side of the square leg at each corner of a top on legs, in metres.
pub const LEG: f64 = 0.06;

/// The lowest a top on legs read from its box (not measured from a mesh) stands to leave
/// room below it, in metres: a coffee table 0.45 m tall has 0.41 m under its top; a
/// footstool-high table is solid to what goes under it.
pub const KNEE_HEIGHT: f64 = 0.35;

/// The thickness of the top of a table whose box is `table`: 4 cm, at most a quarter of
/// its height.
#[must_use]
pub fn top(table: &Aabb) -> f64 {
    0.04_f64.min(table.size().y * 0.25)
}

/// The height of the room under the top of `table`, of form `form`, from its bottom: 0
/// when it is no top on legs, or one too low to leave room below.
#[must_use]
pub fn knee_room(table: &Aabb, form: Form) -> f64 {
    match form {
        Form::OnLegs {
            underside: Some(permille),
        } => table.size().y * f64::from(permille.min(1000)) / 1000.0,
        Form::OnLegs { underside: None } if table.size().y >= KNEE_HEIGHT => {
            table.size().y - top(table)
        }
        _ => 0.0,
    }
}

/// How far apart two boxes may touch without colliding, in metres.
const TOUCH: f64 = 1e-6;

/// Whether `a` stands clear of the solid parts of the top on legs of form `form` whose
/// box is `table`: below its top and off its legs.
#[must_use]
pub fn clear_under(a: &Aabb, table: &Aabb, form: Form) -> bool {
    let room = knee_room(table, form);
    if room <= 0.0 || a.max.y > table.min.y + room + TOUCH {
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

/// How far apart the shelves of a case of shelves are, at most, in metres: a bookcase's.
pub const SHELF_SPACING: f64 = 0.35;

/// The room on each shelf of the case of shelves of form `form` whose box is `case`,
/// lowest first: within its walls, from each board's top to the underside of the board
/// above. Boards as measured from its mesh, or [`WALL`] thick at the bottom, between, and
/// at the top, evenly spaced, at most [`SHELF_SPACING`] apart.
#[must_use]
pub fn compartments(case: &Aabb, form: Form) -> Vec<Aabb> {
    let size = case.size();
    let wall = WALL.min(size.min_element() / 4.0);
    if let Form::Shelves {
        boards: Some(boards),
    } = form
    {
        let at = |t: u16| case.min.y + size.y * f64::from(t.min(1000)) / 1000.0;
        return boards
            .levels()
            .windows(2)
            .map(|pair| {
                Aabb::new(
                    glam::DVec3::new(case.min.x + wall, at(pair[0].1), case.min.z + wall),
                    glam::DVec3::new(
                        case.max.x - wall,
                        at(pair[1].0).max(at(pair[0].1)),
                        case.max.z - wall,
                    ),
                )
            })
            .collect();
    }
    let count = ((size.y - wall) / SHELF_SPACING).ceil().clamp(1.0, 64.0) as usize;
    let pitch = size.y / count as f64;
    (0..count)
        .map(|k| {
            let bottom = case.min.y + k as f64 * pitch + wall;
            let top = if k + 1 == count {
                case.max.y - wall
            } else {
                case.min.y + (k + 1) as f64 * pitch
            };
            Aabb::new(
                glam::DVec3::new(case.min.x + wall, bottom, case.min.z + wall),
                glam::DVec3::new(case.max.x - wall, top.max(bottom), case.max.z - wall),
            )
        })
        .collect()
}

/// Which shelf of a case of shelves ("the top shelf", "the second shelf from the bottom").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shelf {
    /// The highest.
    Top,
    /// The lowest.
    Bottom,
    /// The one nearest the middle of the case's height (the lower of two as near).
    Middle,
    /// This many down from the top (1: the top).
    FromTop(usize),
    /// This many up from the bottom (1: the bottom).
    FromBottom(usize),
}

impl Shelf {
    /// The room on this shelf of `rooms` ([`compartments`], lowest first), if there is
    /// such a shelf.
    #[must_use]
    pub fn pick(self, rooms: &[Aabb]) -> Option<Aabb> {
        let n = rooms.len();
        let k = match self {
            Self::Bottom => 0,
            Self::Top => n.checked_sub(1)?,
            Self::Middle => (n.checked_sub(1)?) / 2,
            Self::FromTop(k) => n.checked_sub(k)?,
            Self::FromBottom(k) => k.checked_sub(1)?,
        };
        rooms.get(k).copied()
    }
}

/// Whether `a` lies on one shelf of the case of shelves of form `form` whose box is
/// `case`.
#[must_use]
pub fn clear_shelved(a: &Aabb, case: &Aabb, form: Form) -> bool {
    compartments(case, form).iter().any(|room| {
        (a.min - room.min).min_element() >= -TOUCH && (room.max - a.max).min_element() >= -TOUCH
    })
}

/// Whether `a` lies within the room inside the open container whose box is `container`.
#[must_use]
pub fn clear_inside(a: &Aabb, container: &Aabb) -> bool {
    let room = inside(container);
    (a.min - room.min).min_element() >= -TOUCH && (room.max - a.max).min_element() >= -TOUCH
}

/// A chair's parts as boxes see them: a seat across its whole footprint, and a back
/// along one side of it up to its full height. Tucked under a table, the seat goes under
/// the top and the back stays out.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Seat {
    /// The height of the seat above the chair's bottom, in metres.
    pub height: f64,
    /// The world axis its back is across from its front: 0 (x) or 2 (z).
    pub axis: usize,
    /// Whether the back is on the side of larger coordinates along `axis`.
    pub max_side: bool,
    /// How deep the back is along `axis`, in metres.
    pub depth: f64,
}

impl Seat {
    /// The highest a chair's seat is, in metres.
    pub const MAX_HEIGHT: f64 = 0.5;
    /// The deepest a chair's back is, in metres.
    pub const MAX_BACK: f64 = 0.12;

    /// The seat of a chair whose box is `chair`, with its back across `axis` on the side
    /// `max_side`: the seat at most [`Seat::MAX_HEIGHT`] (and 55% of the chair's height),
    /// the back at most [`Seat::MAX_BACK`] deep (and a quarter of the chair's depth).
    #[must_use]
    pub fn of(chair: &Aabb, axis: usize, max_side: bool) -> Self {
        let size = chair.size();
        Self {
            height: Self::MAX_HEIGHT.min(size.y * 0.55),
            axis,
            max_side,
            depth: Self::MAX_BACK.min(size[axis] * 0.25),
        }
    }
}

/// How an object may share the box of the one it was put under or in: that one's form,
/// and the moving object's seat and back when it is a chair.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Room {
    /// The form of the object whose room it is.
    pub form: Form,
    /// The seat of the object in that room, if it is a chair.
    pub seat: Option<Seat>,
}

impl From<Form> for Room {
    fn from(form: Form) -> Self {
        Self { form, seat: None }
    }
}

impl Seat {
    /// The boxes of the seat and of the back of a chair whose box is `chair`.
    #[must_use]
    pub fn parts(self, chair: &Aabb) -> [Aabb; 2] {
        let seat = Aabb::new(
            chair.min,
            glam::DVec3::new(
                chair.max.x,
                (chair.min.y + self.height).min(chair.max.y),
                chair.max.z,
            ),
        );
        let (mut back_min, mut back_max) = (chair.min, chair.max);
        if self.max_side {
            back_min[self.axis] = (chair.max[self.axis] - self.depth).max(chair.min[self.axis]);
        } else {
            back_max[self.axis] = (chair.min[self.axis] + self.depth).min(chair.max[self.axis]);
        }
        [seat, Aabb::new(back_min, back_max)]
    }
}

/// Whether chair `a`, with `seat`, is tucked under the top on legs of form `form` whose
/// box is `table`: its seat in the room under the top and off the legs, its back outside
/// the table.
#[must_use]
pub fn clear_tucked(a: &Aabb, table: &Aabb, form: Form, seat: Seat) -> bool {
    let [seat_box, back] = seat.parts(a);
    clear_under(&seat_box, table, form) && !back.intersects(table, TOUCH)
}

/// Whether `a` stands clear of the solid parts of `b` in `room`: in the room under a top
/// on legs (a chair's seat under it and its back out), inside an open container, or —
/// a chair — with neither its seat nor its back in `b`'s box (the room above a seat in
/// front of its back is free: a table's edge, what stands on it).
#[must_use]
pub fn clear_in(a: &Aabb, b: &Aabb, room: Room) -> bool {
    let in_form = match room.form {
        Form::Solid => false,
        Form::OnLegs { .. } => {
            clear_under(a, b, room.form)
                || room
                    .seat
                    .is_some_and(|seat| clear_tucked(a, b, room.form, seat))
        }
        Form::Open => clear_inside(a, b),
        Form::Shelves { .. } => clear_shelved(a, b, room.form),
    };
    in_form
        || room
            .seat
            .is_some_and(|seat| seat.parts(a).iter().all(|p| !p.intersects(b, TOUCH)))
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
        assert!(clear_under(
            &b([0.4, 0.0, 0.3], [0.85, 0.7, 0.8]),
            &desk,
            Form::ON_LEGS
        ));
        // Too tall: it meets the top.
        assert!(!clear_under(
            &b([0.4, 0.0, 0.3], [0.85, 0.9, 0.8]),
            &desk,
            Form::ON_LEGS
        ));
        // On a leg.
        assert!(!clear_under(
            &b([-0.2, 0.0, 0.4], [0.1, 0.5, 0.8]),
            &desk,
            Form::ON_LEGS
        ));
        // A footstool-high table leaves no room.
        let low = b([0.0, 0.0, 0.0], [1.0, 0.3, 0.6]);
        assert!(!clear_under(
            &b([0.3, 0.0, 0.2], [0.5, 0.2, 0.4]),
            &low,
            Form::ON_LEGS
        ));
        // A chair 0.95 m tall, its back on its +z side: its seat under the top, its back
        // out; pushed in further, its back meets the top.
        let chair = |z: f64| b([0.3, 0.0, z], [0.85, 0.95, z + 0.55]);
        let seat = Seat::of(&chair(0.0), 2, true);
        assert!(clear_tucked(&chair(0.4), &desk, Form::ON_LEGS, seat));
        assert!(!clear_tucked(&chair(0.0), &desk, Form::ON_LEGS, seat));
        assert!(!clear_under(&chair(0.4), &desk, Form::ON_LEGS));
        // Its back towards the desk: never tucked.
        let facing_away = Seat::of(&chair(0.0), 2, false);
        assert!(!clear_tucked(
            &chair(0.4),
            &desk,
            Form::ON_LEGS,
            facing_away
        ));
        assert!(clear_in(
            &chair(0.4),
            &desk,
            Room {
                form: Form::ON_LEGS,
                seat: Some(seat)
            }
        ));
        assert!(!clear_in(&chair(0.4), &desk, Form::ON_LEGS.into()));
        // Beside a box whose corner is above its seat, in front of its back: clear.
        let crate_box = b([0.7, 0.6, 0.0], [1.2, 1.0, 0.55]);
        let solid = Room {
            form: Form::Solid,
            seat: Some(seat),
        };
        assert!(clear_in(&chair(0.2), &crate_box, solid));
        assert!(!clear_in(&chair(0.2), &crate_box, Form::Solid.into()));
        // A bookcase 1.8 m tall: six shelves 0.3 m apart, 0.28 m of room on each.
        let bookcase = b([0.0, 0.0, 0.0], [0.9, 1.8, 0.35]);
        let rooms = compartments(&bookcase, Form::SHELVES);
        assert_eq!(rooms.len(), 6);
        assert!((rooms[0].min.y - WALL).abs() < 1e-9 && (rooms[0].max.y - 0.3).abs() < 1e-9);
        assert!((rooms[5].max.y - (1.8 - WALL)).abs() < 1e-9);
        let book = |y: f64| b([0.3, y, 0.05], [0.33, y + 0.22, 0.2]);
        assert!(clear_shelved(&book(WALL), &bookcase, Form::SHELVES));
        assert!(clear_shelved(&book(0.3 + WALL), &bookcase, Form::SHELVES));
        // Through a board, or sticking out of the back.
        assert!(!clear_shelved(&book(0.2), &bookcase, Form::SHELVES));
        assert!(!clear_shelved(
            &b([0.3, WALL, 0.2], [0.33, 0.24, 0.4]),
            &bookcase,
            Form::SHELVES
        ));
        assert_eq!(Shelf::Top.pick(&rooms), Some(rooms[5]));
        assert_eq!(Shelf::Bottom.pick(&rooms), Some(rooms[0]));
        assert_eq!(Shelf::Middle.pick(&rooms), Some(rooms[2]));
        assert_eq!(Shelf::FromTop(2).pick(&rooms), Some(rooms[4]));
        assert_eq!(Shelf::FromBottom(7).pick(&rooms), None);
        assert_eq!(Form::from_name("shelves"), Some(Form::SHELVES));
        assert_eq!(Form::from_name("On legs"), Some(Form::ON_LEGS));
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

    #[test]
    fn the_room_under_a_top_is_read_from_its_box_or_measured() {
        // A coffee table 0.45 m tall has 0.41 m below its top.
        let coffee = b([0.0, 0.0, 0.0], [1.0, 0.45, 0.6]);
        assert!(clear_under(
            &b([0.3, 0.0, 0.2], [0.5, 0.4, 0.4]),
            &coffee,
            Form::ON_LEGS
        ));
        // Measured from a mesh: a bed whose frame leaves 0.2 m below it (a third of its
        // 0.6 m): a drawer 0.15 m tall goes under, a stool 0.45 m tall does not.
        let bed = b([0.0, 0.0, 0.0], [1.6, 0.6, 2.0]);
        let raised = Form::OnLegs {
            underside: Some(333),
        };
        assert!((knee_room(&bed, raised) - 0.1998).abs() < 1e-9);
        assert!(clear_under(
            &b([0.3, 0.0, 0.3], [1.0, 0.15, 1.0]),
            &bed,
            raised
        ));
        assert!(!clear_under(
            &b([0.3, 0.0, 0.3], [0.7, 0.45, 0.7]),
            &bed,
            raised
        ));
        assert_eq!(knee_room(&bed, Form::Solid), 0.0);
    }
}

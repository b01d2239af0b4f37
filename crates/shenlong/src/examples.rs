//! The built-in example scenes: ten rooms of the kinds the paper evaluated on, with
//! realistic sizes (metres) and objects resting on others.
//!
//! Each scene is a table of objects. A floor object gives its footprint centre `[x, z]`;
//! a resting object names its support and gives its offset from the support's top centre,
//! so it sits exactly on the support's top face (offsets are along the world axes, whatever
//! the support's yaw). `yaw` turns an object about +Y, in
//! degrees; its front (local +Z) faces +Z at yaw 0.

use crate::geometry::Aabb;
use crate::scene::{Object, Scene};
use glam::{DQuat, DVec3};

/// One object of an example: name, size `[w, h, d]`, support (None: the floor),
/// position `[x, z]` (on the floor) or offset `[dx, dz]` (on the support), yaw in degrees.
type Item = (&'static str, [f64; 3], Option<&'static str>, [f64; 2], f64);

/// One example: name, one-line description, room half-extents `[x, height, z]`, objects.
struct Example {
    name: &'static str,
    description: &'static str,
    room: [f64; 3],
    items: &'static [Item],
}

const EXAMPLES: &[Example] = &[
    Example {
        name: "living_room",
        description: "sofa facing a TV stand, coffee table, armchair, shelves, lamps",
        room: [3.0, 2.8, 2.5],
        items: &[
            ("sofa", [2.2, 0.85, 0.9], None, [0.0, -1.9], 0.0),
            ("coffee table", [1.1, 0.45, 0.6], None, [0.0, -0.6], 0.0),
            ("tv stand", [1.6, 0.5, 0.45], None, [0.0, 2.2], 180.0),
            ("tv", [1.2, 0.7, 0.08], Some("tv stand"), [0.0, 0.1], 180.0),
            ("armchair", [0.9, 0.9, 0.85], None, [-2.2, -0.4], 90.0),
            ("ottoman", [0.6, 0.45, 0.6], None, [-1.2, 0.4], 0.0),
            ("floor lamp", [0.4, 1.6, 0.4], None, [-2.6, -2.1], 0.0),
            ("side table", [0.5, 0.55, 0.5], None, [1.6, -2.0], 0.0),
            (
                "table lamp",
                [0.3, 0.45, 0.3],
                Some("side table"),
                [0.0, 0.0],
                0.0,
            ),
            (
                "remote control",
                [0.05, 0.02, 0.17],
                Some("coffee table"),
                [0.3, 0.1],
                0.0,
            ),
            (
                "vase",
                [0.15, 0.3, 0.15],
                Some("coffee table"),
                [-0.3, 0.0],
                0.0,
            ),
            (
                "book",
                [0.15, 0.04, 0.22],
                Some("coffee table"),
                [0.05, -0.1],
                20.0,
            ),
            ("bookshelf", [0.9, 1.8, 0.35], None, [2.8, 0.0], -90.0),
            ("plant", [0.5, 1.2, 0.5], None, [2.6, 2.1], 0.0),
            ("speaker", [0.25, 1.0, 0.25], None, [-1.1, 2.2], 0.0),
            ("speaker 2", [0.25, 1.0, 0.25], None, [1.1, 2.2], 0.0),
            (
                "magazine",
                [0.21, 0.01, 0.28],
                Some("ottoman"),
                [0.0, 0.0],
                10.0,
            ),
            (
                "game console",
                [0.3, 0.08, 0.25],
                Some("tv stand"),
                [0.4, -0.08],
                180.0,
            ),
        ],
    },
    Example {
        name: "bedroom",
        description: "double bed with nightstands, wardrobe, desk and dresser",
        room: [2.5, 2.7, 2.2],
        items: &[
            ("bed", [1.6, 0.55, 2.1], None, [0.0, -1.1], 0.0),
            ("pillow", [0.6, 0.15, 0.4], Some("bed"), [-0.4, -0.8], 0.0),
            ("pillow 2", [0.6, 0.15, 0.4], Some("bed"), [0.4, -0.8], 0.0),
            ("nightstand", [0.5, 0.55, 0.4], None, [-1.2, -1.9], 0.0),
            ("nightstand 2", [0.5, 0.55, 0.4], None, [1.2, -1.9], 0.0),
            (
                "bedside lamp",
                [0.25, 0.4, 0.25],
                Some("nightstand"),
                [0.0, 0.0],
                0.0,
            ),
            (
                "alarm clock",
                [0.12, 0.1, 0.06],
                Some("nightstand 2"),
                [0.1, 0.0],
                0.0,
            ),
            ("wardrobe", [1.2, 2.0, 0.6], None, [-1.8, 1.5], 90.0),
            ("dresser", [1.0, 0.8, 0.45], None, [1.4, 1.9], 180.0),
            (
                "mirror",
                [0.6, 0.8, 0.04],
                Some("dresser"),
                [0.0, 0.15],
                180.0,
            ),
            (
                "jewelry box",
                [0.2, 0.1, 0.15],
                Some("dresser"),
                [-0.3, -0.05],
                0.0,
            ),
            ("desk", [1.2, 0.75, 0.6], None, [2.1, 0.2], -90.0),
            ("desk chair", [0.5, 0.9, 0.5], None, [1.5, 0.2], 90.0),
            (
                "laptop",
                [0.33, 0.02, 0.23],
                Some("desk"),
                [0.0, 0.0],
                -90.0,
            ),
            ("laundry basket", [0.45, 0.55, 0.35], None, [-0.6, 1.9], 0.0),
            ("rug", [1.6, 0.01, 1.0], None, [0.0, 0.6], 0.0),
        ],
    },
    Example {
        name: "kitchen",
        description: "counters, island with stools, fridge, stove, table with dishes",
        room: [3.0, 2.7, 2.5],
        items: &[
            ("counter", [2.4, 0.9, 0.6], None, [-0.6, -2.2], 0.0),
            ("stove", [0.75, 0.9, 0.65], None, [1.1, -2.17], 0.0),
            ("fridge", [0.8, 1.8, 0.7], None, [2.5, -2.1], 0.0),
            ("sink", [0.6, 0.2, 0.45], Some("counter"), [-0.6, 0.0], 0.0),
            (
                "microwave",
                [0.5, 0.3, 0.38],
                Some("counter"),
                [0.7, 0.0],
                0.0,
            ),
            (
                "kettle",
                [0.22, 0.25, 0.16],
                Some("counter"),
                [-1.05, 0.05],
                0.0,
            ),
            ("pot", [0.3, 0.2, 0.3], Some("stove"), [-0.15, 0.1], 0.0),
            ("kitchen island", [1.8, 0.9, 0.9], None, [0.0, 0.0], 0.0),
            (
                "fruit bowl",
                [0.3, 0.12, 0.3],
                Some("kitchen island"),
                [-0.4, 0.0],
                0.0,
            ),
            (
                "cutting board",
                [0.4, 0.02, 0.25],
                Some("kitchen island"),
                [0.4, 0.1],
                0.0,
            ),
            (
                "knife",
                [0.3, 0.02, 0.03],
                Some("cutting board"),
                [0.0, 0.0],
                0.0,
            ),
            ("stool", [0.4, 0.65, 0.4], None, [-0.5, 0.8], 0.0),
            ("stool 2", [0.4, 0.65, 0.4], None, [0.5, 0.8], 0.0),
            ("dining table", [1.4, 0.75, 0.9], None, [-1.6, 1.6], 0.0),
            (
                "plate",
                [0.26, 0.02, 0.26],
                Some("dining table"),
                [-0.3, 0.0],
                0.0,
            ),
            (
                "mug",
                [0.09, 0.1, 0.09],
                Some("dining table"),
                [0.3, 0.1],
                0.0,
            ),
            ("trash can", [0.35, 0.6, 0.35], None, [2.6, 0.2], 0.0),
            ("chair", [0.45, 0.9, 0.5], None, [-1.6, 0.9], 0.0),
        ],
    },
    Example {
        name: "wine_cellar",
        description: "wine racks, barrels, a tasting table with bottles and glasses",
        room: [3.5, 2.4, 2.5],
        items: &[
            ("wine rack", [1.5, 2.0, 0.4], None, [-1.6, -2.25], 0.0),
            ("wine rack 2", [1.5, 2.0, 0.4], None, [0.2, -2.25], 0.0),
            ("wine rack 3", [1.5, 2.0, 0.4], None, [3.2, 0.0], -90.0),
            ("barrel", [0.7, 0.95, 0.7], None, [-3.0, 1.8], 0.0),
            ("barrel 2", [0.7, 0.95, 0.7], None, [-2.1, 1.8], 0.0),
            (
                "small barrel",
                [0.45, 0.6, 0.45],
                Some("barrel"),
                [0.0, 0.0],
                0.0,
            ),
            ("tasting table", [1.6, 0.9, 0.8], None, [0.0, 0.3], 0.0),
            (
                "red wine bottle",
                [0.08, 0.32, 0.08],
                Some("tasting table"),
                [-0.4, 0.0],
                0.0,
            ),
            (
                "white wine bottle",
                [0.08, 0.32, 0.08],
                Some("tasting table"),
                [-0.25, 0.1],
                0.0,
            ),
            (
                "wine glass",
                [0.08, 0.2, 0.08],
                Some("tasting table"),
                [0.2, 0.15],
                0.0,
            ),
            (
                "wine glass 2",
                [0.08, 0.2, 0.08],
                Some("tasting table"),
                [0.35, -0.1],
                0.0,
            ),
            (
                "decanter",
                [0.2, 0.28, 0.2],
                Some("tasting table"),
                [0.0, -0.2],
                0.0,
            ),
            (
                "cheese board",
                [0.4, 0.03, 0.3],
                Some("tasting table"),
                [0.55, 0.15],
                0.0,
            ),
            ("bar stool", [0.4, 0.75, 0.4], None, [-0.5, 1.1], 0.0),
            ("bar stool 2", [0.4, 0.75, 0.4], None, [0.5, 1.1], 0.0),
            ("crate", [0.5, 0.35, 0.4], None, [2.4, 1.9], 15.0),
            (
                "crate 2",
                [0.5, 0.35, 0.4],
                Some("crate"),
                [0.0, 0.0],
                -10.0,
            ),
            (
                "lantern",
                [0.2, 0.35, 0.2],
                Some("barrel 2"),
                [0.0, 0.0],
                0.0,
            ),
        ],
    },
    Example {
        name: "operating_room",
        description: "operating table, instrument trolley and tray, anesthesia machine, cabinets",
        room: [3.0, 3.0, 3.0],
        items: &[
            ("operating table", [0.6, 0.9, 2.0], None, [0.0, 0.0], 0.0),
            ("linen cart", [0.6, 1.0, 0.45], None, [2.4, -0.6], 0.0),
            (
                "instrument trolley",
                [0.8, 0.9, 0.5],
                None,
                [1.2, 0.4],
                -90.0,
            ),
            (
                "instrument tray",
                [0.45, 0.05, 0.3],
                Some("instrument trolley"),
                [0.0, 0.0],
                -90.0,
            ),
            (
                "scalpel",
                [0.15, 0.01, 0.02],
                Some("instrument tray"),
                [0.0, -0.08],
                -90.0,
            ),
            (
                "forceps",
                [0.16, 0.015, 0.03],
                Some("instrument tray"),
                [0.0, 0.08],
                -90.0,
            ),
            (
                "anesthesia machine",
                [0.7, 1.5, 0.7],
                None,
                [-1.0, -1.6],
                0.0,
            ),
            (
                "patient monitor",
                [0.35, 0.3, 0.15],
                Some("anesthesia machine"),
                [0.0, 0.0],
                0.0,
            ),
            ("iv stand", [0.5, 1.9, 0.5], None, [-0.8, 0.6], 0.0),
            ("supply cabinet", [1.2, 1.9, 0.5], None, [-2.7, 0.5], 90.0),
            (
                "supply cabinet 2",
                [1.2, 1.9, 0.5],
                None,
                [-2.7, -1.0],
                90.0,
            ),
            ("waste bin", [0.4, 0.5, 0.4], None, [1.5, -1.6], 0.0),
            ("surgeon stool", [0.45, 0.6, 0.45], None, [0.8, -0.9], 0.0),
            ("mayo stand", [0.5, 1.0, 0.35], None, [-0.7, 1.3], 0.0),
            ("suction unit", [0.4, 0.8, 0.4], None, [1.6, 1.6], 0.0),
            (
                "defibrillator",
                [0.3, 0.25, 0.25],
                Some("supply cabinet"),
                [0.0, 0.0],
                90.0,
            ),
        ],
    },
    Example {
        name: "workshop",
        description: "tool table with an orange bottle, workbench, shelves, machines",
        room: [4.0, 3.0, 3.0],
        items: &[
            ("tool table", [1.6, 0.9, 0.8], None, [0.0, 0.0], 0.0),
            ("orange bottle", [0.08, 0.25, 0.08], None, [-2.0, 1.2], 0.0),
            ("workbench", [2.0, 0.95, 0.8], None, [-1.8, -2.5], 0.0),
            ("vise", [0.25, 0.2, 0.3], Some("workbench"), [0.7, 0.1], 0.0),
            (
                "hammer",
                [0.32, 0.04, 0.11],
                Some("tool table"),
                [-0.4, 0.1],
                30.0,
            ),
            (
                "screwdriver",
                [0.22, 0.03, 0.03],
                Some("tool table"),
                [0.1, -0.2],
                0.0,
            ),
            (
                "toolbox",
                [0.5, 0.25, 0.25],
                Some("workbench"),
                [-0.5, 0.0],
                0.0,
            ),
            (
                "drill",
                [0.25, 0.22, 0.08],
                Some("tool table"),
                [0.5, 0.15],
                0.0,
            ),
            ("metal shelf", [1.2, 1.8, 0.45], None, [3.7, 0.0], -90.0),
            (
                "paint can",
                [0.18, 0.2, 0.18],
                Some("metal shelf"),
                [0.0, -0.3],
                0.0,
            ),
            ("drill press", [0.5, 1.6, 0.6], None, [1.8, -2.6], 0.0),
            ("table saw", [1.0, 0.9, 0.7], None, [2.2, 1.8], 0.0),
            ("stool", [0.4, 0.7, 0.4], None, [0.0, 1.0], 0.0),
            ("trash barrel", [0.55, 0.8, 0.55], None, [-3.6, 2.6], 0.0),
            ("plank", [2.0, 0.04, 0.2], None, [-0.3, 2.5], 0.0),
            ("cardboard box", [0.6, 0.4, 0.4], None, [-3.4, 0.3], 0.0),
            (
                "oil can",
                [0.12, 0.18, 0.12],
                Some("cardboard box"),
                [0.1, 0.0],
                0.0,
            ),
        ],
    },
    Example {
        name: "office",
        description: "desks with monitors and chairs, filing cabinets, a meeting table",
        room: [3.5, 2.8, 3.0],
        items: &[
            ("desk", [1.4, 0.75, 0.7], None, [-2.0, -2.4], 0.0),
            ("desk 2", [1.4, 0.75, 0.7], None, [0.0, -2.4], 0.0),
            (
                "monitor",
                [0.55, 0.45, 0.2],
                Some("desk"),
                [0.0, -0.15],
                0.0,
            ),
            (
                "monitor 2",
                [0.55, 0.45, 0.2],
                Some("desk 2"),
                [0.0, -0.15],
                0.0,
            ),
            (
                "keyboard",
                [0.44, 0.03, 0.14],
                Some("desk"),
                [0.0, 0.15],
                0.0,
            ),
            ("office chair", [0.6, 1.1, 0.6], None, [-2.0, -1.6], 180.0),
            ("office chair 2", [0.6, 1.1, 0.6], None, [0.0, -1.6], 180.0),
            ("filing cabinet", [0.45, 1.3, 0.6], None, [3.2, -2.6], 0.0),
            (
                "printer",
                [0.45, 0.3, 0.4],
                Some("filing cabinet"),
                [0.0, 0.0],
                0.0,
            ),
            ("meeting table", [2.0, 0.75, 1.0], None, [0.5, 1.2], 0.0),
            (
                "notebook",
                [0.15, 0.015, 0.21],
                Some("meeting table"),
                [-0.5, 0.0],
                0.0,
            ),
            (
                "coffee cup",
                [0.08, 0.1, 0.08],
                Some("meeting table"),
                [0.3, 0.2],
                0.0,
            ),
            ("whiteboard", [1.8, 1.2, 0.05], None, [0.5, 2.9], 180.0),
            ("plant", [0.5, 1.3, 0.5], None, [-3.1, 2.5], 0.0),
            ("bookcase", [0.8, 2.0, 0.35], None, [3.3, 1.0], -90.0),
            ("water cooler", [0.35, 1.2, 0.35], None, [-3.2, 0.6], 0.0),
            (
                "desk lamp",
                [0.2, 0.45, 0.2],
                Some("desk 2"),
                [0.5, -0.2],
                0.0,
            ),
        ],
    },
    Example {
        name: "classroom",
        description: "rows of student desks and chairs facing a teacher's desk and board",
        room: [4.0, 3.0, 3.5],
        items: &[
            ("teacher desk", [1.5, 0.75, 0.7], None, [0.0, -2.45], 0.0),
            ("teacher chair", [0.6, 1.0, 0.6], None, [0.0, -3.1], 0.0),
            ("blackboard", [3.0, 1.2, 0.05], None, [0.0, -3.47], 0.0),
            (
                "globe",
                [0.3, 0.45, 0.3],
                Some("teacher desk"),
                [-0.5, 0.0],
                0.0,
            ),
            (
                "apple",
                [0.08, 0.08, 0.08],
                Some("teacher desk"),
                [0.5, 0.1],
                0.0,
            ),
            ("student desk", [0.7, 0.7, 0.5], None, [-1.5, -0.5], 0.0),
            ("student desk 2", [0.7, 0.7, 0.5], None, [0.0, -0.5], 0.0),
            ("student desk 3", [0.7, 0.7, 0.5], None, [1.5, -0.5], 0.0),
            ("student desk 4", [0.7, 0.7, 0.5], None, [-1.5, 1.2], 0.0),
            ("student desk 5", [0.7, 0.7, 0.5], None, [0.0, 1.2], 0.0),
            ("student desk 6", [0.7, 0.7, 0.5], None, [1.5, 1.2], 0.0),
            ("student chair", [0.4, 0.8, 0.4], None, [-1.5, 0.1], 180.0),
            ("student chair 2", [0.4, 0.8, 0.4], None, [0.0, 0.1], 180.0),
            ("student chair 3", [0.4, 0.8, 0.4], None, [1.5, 0.1], 180.0),
            (
                "textbook",
                [0.2, 0.03, 0.27],
                Some("student desk"),
                [0.0, 0.0],
                5.0,
            ),
            (
                "pencil case",
                [0.2, 0.05, 0.07],
                Some("student desk 2"),
                [0.15, 0.0],
                0.0,
            ),
            ("bookshelf", [1.2, 1.6, 0.35], None, [3.8, 0.5], -90.0),
            ("trash can", [0.3, 0.45, 0.3], None, [3.6, -3.1], 0.0),
            ("backpack", [0.3, 0.45, 0.2], None, [-2.3, 0.1], 90.0),
        ],
    },
    Example {
        name: "dining_room",
        description: "a dining table laid for four, chairs, a sideboard and a cabinet",
        room: [3.0, 2.8, 2.5],
        items: &[
            ("dining table", [1.8, 0.75, 1.0], None, [0.0, 0.0], 0.0),
            ("chair", [0.45, 0.95, 0.5], None, [-0.45, -0.8], 0.0),
            ("chair 2", [0.45, 0.95, 0.5], None, [0.45, -0.8], 0.0),
            ("chair 3", [0.45, 0.95, 0.5], None, [-0.45, 0.8], 180.0),
            ("chair 4", [0.45, 0.95, 0.5], None, [0.45, 0.8], 180.0),
            (
                "plate",
                [0.27, 0.02, 0.27],
                Some("dining table"),
                [-0.45, -0.3],
                0.0,
            ),
            (
                "plate 2",
                [0.27, 0.02, 0.27],
                Some("dining table"),
                [0.45, -0.3],
                0.0,
            ),
            (
                "plate 3",
                [0.27, 0.02, 0.27],
                Some("dining table"),
                [-0.45, 0.3],
                0.0,
            ),
            (
                "plate 4",
                [0.27, 0.02, 0.27],
                Some("dining table"),
                [0.45, 0.3],
                0.0,
            ),
            (
                "candle",
                [0.07, 0.25, 0.07],
                Some("dining table"),
                [0.0, 0.0],
                0.0,
            ),
            (
                "water jug",
                [0.14, 0.25, 0.14],
                Some("dining table"),
                [0.15, 0.1],
                0.0,
            ),
            ("sideboard", [1.6, 0.85, 0.45], None, [0.0, 2.2], 180.0),
            (
                "fruit bowl",
                [0.3, 0.12, 0.3],
                Some("sideboard"),
                [-0.4, 0.0],
                0.0,
            ),
            ("china cabinet", [1.0, 1.9, 0.45], None, [-2.7, 0.0], 90.0),
            ("chandelier", [0.7, 0.5, 0.7], None, [0.0, -2.0], 0.0),
            ("plant", [0.45, 1.1, 0.45], None, [2.6, 2.1], 0.0),
        ],
    },
    Example {
        name: "bathroom",
        description: "bathtub, toilet, sink cabinet with toiletries, towel rack",
        room: [1.8, 2.6, 1.6],
        items: &[
            ("bathtub", [1.7, 0.55, 0.75], None, [0.0, -1.2], 0.0),
            ("toilet", [0.4, 0.8, 0.65], None, [-1.4, 0.3], 90.0),
            ("sink cabinet", [0.8, 0.85, 0.5], None, [1.2, 0.6], -90.0),
            (
                "soap dispenser",
                [0.08, 0.18, 0.08],
                Some("sink cabinet"),
                [0.0, 0.25],
                0.0,
            ),
            (
                "toothbrush cup",
                [0.08, 0.12, 0.08],
                Some("sink cabinet"),
                [0.0, -0.25],
                0.0,
            ),
            ("towel rack", [0.6, 1.0, 0.3], None, [0.2, 1.4], 180.0),
            (
                "towel",
                [0.5, 0.05, 0.3],
                Some("towel rack"),
                [0.0, 0.0],
                180.0,
            ),
            ("laundry hamper", [0.4, 0.6, 0.4], None, [-1.4, 1.2], 0.0),
            ("bath mat", [0.8, 0.01, 0.5], None, [0.0, -0.45], 0.0),
            (
                "shampoo bottle",
                [0.07, 0.22, 0.05],
                Some("bathtub"),
                [0.7, -0.25],
                0.0,
            ),
            (
                "rubber duck",
                [0.1, 0.08, 0.08],
                Some("bathtub"),
                [-0.6, 0.0],
                30.0,
            ),
            ("trash bin", [0.25, 0.3, 0.25], None, [-1.5, -0.4], 0.0),
            (
                "toilet paper",
                [0.11, 0.1, 0.11],
                Some("trash bin"),
                [0.0, 0.0],
                0.0,
            ),
            ("stool", [0.35, 0.45, 0.35], None, [0.6, 0.1], 0.0),
            ("candle", [0.08, 0.1, 0.08], Some("stool"), [0.0, 0.0], 0.0),
        ],
    },
];

/// The names and one-line descriptions of the built-in examples.
pub fn list() -> impl Iterator<Item = (&'static str, &'static str)> {
    EXAMPLES.iter().map(|e| (e.name, e.description))
}

/// Builds the example scene with this name (`-` and `_` are interchangeable).
pub fn build(name: &str) -> Option<Scene> {
    let wanted = name.trim().replace('-', "_").to_lowercase();
    let example = EXAMPLES.iter().find(|e| e.name == wanted)?;
    let mut scene = Scene::new(example.name);
    let [hx, height, hz] = example.room;
    scene.bounds = Some(Aabb::new(
        DVec3::new(-hx, 0.0, -hz),
        DVec3::new(hx, height, hz),
    ));
    for &(name, size, support, place, yaw) in example.items {
        let position = match support {
            None => DVec3::new(place[0], 0.0, place[1]),
            Some(support) => {
                let index = scene.find(support).unwrap_or_else(|| {
                    panic!(
                        "example {}: '{support}' must come before '{name}'",
                        example.name
                    )
                });
                let top = scene.objects[index].world_aabb();
                let c = top.center();
                DVec3::new(c.x + place[0], top.max.y, c.z + place[1])
            }
        };
        let object = Object::new_box(
            name,
            DVec3::from(size),
            position,
            DQuat::from_rotation_y(yaw.to_radians()),
            1.0,
        )
        .expect("example sizes and scales are valid");
        scene.objects.push(object);
    }
    scene.detect_supports();
    Some(scene)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ten_examples_of_fifteen_to_forty_objects() {
        assert!(list().count() >= 10);
        let mut problems = Vec::new();
        for (name, _) in list() {
            let scene = build(name).unwrap();
            let n = scene.objects.len();
            if !(15..=40).contains(&n) {
                problems.push(format!("{name} has {n} objects"));
            }
            let resting = scene.objects.iter().filter(|o| o.support.is_some()).count();
            if resting < 3 {
                problems.push(format!("{name}: only {resting} objects rest on others"));
            }
            let bounds = scene.bounds.unwrap();
            let boxes = scene.world_aabbs();
            // Nothing floats: an object above the floor rests on something.
            for (o, b) in scene.objects.iter().zip(&boxes) {
                if b.min.y > 1e-9 && o.support.is_none() {
                    problems.push(format!("{name}: '{}' floats at y = {:.3}", o.name, b.min.y));
                }
            }
            for (o, b) in scene.objects.iter().zip(&boxes) {
                if !(b.min.cmpge(bounds.min - 1e-9).all() && b.max.cmple(bounds.max + 1e-9).all()) {
                    problems.push(format!("{name}: '{}' is outside the room", o.name));
                }
            }
            // Nothing overlaps in a built-in example (touching is fine).
            for i in 0..boxes.len() {
                for j in i + 1..boxes.len() {
                    if boxes[i].intersects(&boxes[j], 1e-6) {
                        problems.push(format!(
                            "{name}: '{}' overlaps '{}'",
                            scene.objects[i].name, scene.objects[j].name
                        ));
                    }
                }
            }
        }
        assert!(problems.is_empty(), "{}", problems.join("\n"));
    }

    #[test]
    fn names_resolve_with_dashes() {
        assert!(build("living-room").is_some());
        assert!(build("nowhere").is_none());
    }
}

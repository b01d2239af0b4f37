//! Parse and evaluate arbitrary text as a CGA expression: it must never panic, hang or
//! exhaust memory, whatever the input; and a parsed tree must print to text that parses
//! back to the same tree.
#![no_main]

use glam::DVec3;
use libfuzzer_sys::fuzz_target;
use shenlong::expr::{self, Bindings, ObjectBox};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let mut bindings = Bindings::new();
    bindings.bind(
        "X1",
        ObjectBox {
            min: DVec3::new(-0.5, 0.0, -0.5),
            max: DVec3::new(0.5, 1.0, 0.5),
            front: DVec3::Z,
        },
    );
    bindings.bind(
        "X2",
        ObjectBox {
            min: DVec3::new(1.0, 0.0, 1.0),
            max: DVec3::new(2.0, 0.8, 3.0),
            front: DVec3::NEG_X,
        },
    );
    let _ = expr::evaluate_transformation(text, &bindings);
    if let Ok(tree) = expr::parse(text) {
        let printed = tree.to_string();
        // Printing adds parentheses, which may cross the depth or length limit; only
        // trees that fit must read back identically.
        if let Ok(again) = expr::parse(&printed) {
            assert_eq!(again, tree, "{text:?} printed as {printed:?}");
        }
    }
});

//! Read arbitrary bytes as a USD stage — `.usda` text, a `.usdc` crate or a `.usdz`
//! package, by the first byte — through `format::usd::read`, as every front end does:
//! never a panic, a hang or runaway memory in this process (the stage is read in a child
//! process with a budget, whose crash is an error here). A stage that reads is edited
//! (its first object moved) and written back as `.usda` text, through the text patcher.
#![no_main]

use libfuzzer_sys::fuzz_target;
use shenlong::format::usd::{self, UsdContainer};
use shenlong::format::ReadOptions;

fuzz_target!(|data: &[u8]| {
    let Some((&kind, body)) = data.split_first() else {
        return;
    };
    let extension = match kind % 3 {
        0 => "usda",
        1 => "usdc",
        _ => "usdz",
    };
    let Ok(dir) = tempfile::tempdir() else { return };
    let path = dir.path().join(format!("stage.{extension}"));
    if std::fs::write(&path, body).is_err() {
        return;
    }
    if let Ok((mut scene, document)) = usd::read(&path, &ReadOptions::default()) {
        let m = cga::Multivector::translator(glam::DVec3::new(0.5, 0.0, -0.25));
        if scene.apply(0, &m, true).is_ok() {
            let _ = usd::write(&scene, &document, UsdContainer::Usda, Some(dir.path()));
        }
    }
});

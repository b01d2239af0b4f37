//! USD stages from arbitrary bytes, two ways:
//! - Shenlong's own readers in this process (`format::usd::fuzz_own_readers`: the nesting
//!   check, the `.usda` text scanner and patcher, the decoder of a walk sent back by the
//!   reading child), where coverage guides the fuzzer: never a panic or a hang;
//! - the whole read as every front end does it (`format::usd::read`: the stage opened in a
//!   child process with a budget), `.usda`, `.usdc` or `.usdz` by the first byte: this
//!   process never crashes, whatever the USD crate does in the child; a stage that reads
//!   is edited and written back as `.usda` text.
#![no_main]

use libfuzzer_sys::fuzz_target;
use shenlong::format::usd::{self, UsdContainer};
use shenlong::format::ReadOptions;

fuzz_target!(|data: &[u8]| {
    usd::fuzz_own_readers(data);
    let Some((&kind, body)) = data.split_first() else {
        return;
    };
    // The whole read forks a child: one input in 16, to keep the run fast.
    if kind % 16 >= 3 {
        return;
    }
    let extension = ["usda", "usdc", "usdz"][usize::from(kind % 16)];
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

//! Read arbitrary bytes as scene JSON, write the scene back and read that again: never a
//! panic, a hang or runaway memory; what was read writes back readable.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    if let Ok(loaded) = shenlong::format::json::read(&text, "fuzz") {
        let written = shenlong::format::json::write(&loaded.scene, Some(&loaded.document));
        shenlong::format::json::read(&written, "fuzz").expect("a written scene reads back");
    }
});

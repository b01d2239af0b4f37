//! Extract the answer from an arbitrary "model reply": never a panic or a hang.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let _ = shenlong::expr::reply::extract_cga_reply(&text);
});

//! Read arbitrary bytes as glTF or GLB (from a folder with nothing else in it): never a
//! panic, a hang or runaway memory.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let dir = std::path::Path::new("/nonexistent-shenlong-fuzz");
    if let Ok((scene, document)) = shenlong::format::gltf::read_bytes(data.to_vec(), dir, "fuzz") {
        let _ = shenlong::format::gltf::write(&scene, &document);
    }
});

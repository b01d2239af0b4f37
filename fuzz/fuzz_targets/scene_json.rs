//! Read arbitrary bytes as scene JSON, write the scene back and read that again: never a
//! panic, a hang or runaway memory; what was read writes back readable, unchanged or with
//! its first object moved, turned and scaled (the in-place rewrite of pose fields).
#![no_main]

use libfuzzer_sys::fuzz_target;
use shenlong::format::json;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    if let Ok(mut loaded) = json::read(&text, "fuzz") {
        let written = json::write(&loaded.scene, Some(&loaded.document));
        json::read(&written, "fuzz").expect("a written scene reads back");
        if loaded.scene.objects.is_empty() {
            return;
        }
        let m = cga::Multivector::translator(glam::DVec3::new(0.5, 0.25, -1.0))
            * cga::Multivector::rotor(0.3, &cga::Multivector::e3(), &cga::Multivector::e1())
                .expect("a plane")
            * cga::Multivector::dilator(1.5).expect("a scale");
        if loaded.scene.apply(0, &m, true).is_ok() {
            let written = json::write(&loaded.scene, Some(&loaded.document));
            let again = json::read(&written, "fuzz").expect("an edited scene reads back");
            let (a, b) = (
                again.scene.objects[0].similarity(),
                loaded.scene.objects[0].similarity(),
            );
            assert!((a.translation - b.translation).length() < 1e-6, "{a:?} {b:?}");
        }
    }
});

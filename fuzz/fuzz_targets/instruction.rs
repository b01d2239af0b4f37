//! Run an arbitrary instruction through grounding, templating and the offline translator
//! on a built-in scene, and apply what it answers: never a panic or a hang — a refusal or
//! an edit.
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::sync::OnceLock;

fn scenes() -> &'static [(shenlong::scene::Scene, shenlong::ground::Grounder)] {
    static SCENES: OnceLock<Vec<(shenlong::scene::Scene, shenlong::ground::Grounder)>> =
        OnceLock::new();
    SCENES.get_or_init(|| {
        ["living_room", "dining_room", "kitchen"]
            .iter()
            .map(|n| {
                let s = shenlong::examples::build(n).expect("a built-in scene");
                let g = shenlong::ground::Grounder::new(&s);
                (s, g)
            })
            .collect()
    })
}

fuzz_target!(|data: &[u8]| {
    let Some((&pick, rest)) = data.split_first() else {
        return;
    };
    let (scene, grounder) = &scenes()[pick as usize % scenes().len()];
    let text = String::from_utf8_lossy(rest);
    let mut scene = scene.clone();
    let _ = shenlong::pipeline::edit_with(
        &mut scene,
        grounder,
        &text,
        &shenlong::offline::OfflineTranslator::new(),
        &shenlong::pipeline::EditOptions::default(),
    );
});

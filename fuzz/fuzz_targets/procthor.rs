//! Convert an arbitrary ProcTHOR/Holodeck house (JSON) with a small asset database, then
//! read the result as a scene: never a panic or a hang.
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::sync::OnceLock;

fn assets() -> &'static shenlong::format::procthor::AssetDatabase {
    static DB: OnceLock<shenlong::format::procthor::AssetDatabase> = OnceLock::new();
    DB.get_or_init(|| {
        shenlong::format::procthor::AssetDatabase::from_json(
            r#"{"Sofa": [{"assetId": "Sofa_1", "boundingBox": {"x": 2, "y": 0.8, "z": 0.9}}],
                "Chair": [{"assetId": "Chair_1", "boundingBox": {"x": 0.5, "y": 0.9, "z": 0.5}}],
                "RemoteControl": [{"assetId": "Remote_1", "boundingBox": {"x": 0.05, "y": 0.02, "z": 0.15}}]}"#,
        )
        .expect("a valid database")
    })
}

fuzz_target!(|data: &[u8]| {
    let Ok(house) = serde_json::from_slice::<serde_json::Value>(data) else {
        return;
    };
    if let Ok(doc) = shenlong::format::procthor::convert(&house, assets(), "fuzz") {
        let _ = shenlong::format::json::scene_from_value(&doc, "fuzz");
    }
});

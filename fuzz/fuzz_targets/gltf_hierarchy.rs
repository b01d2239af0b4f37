//! glTF node hierarchies built from the fuzzer's bytes — any depth, shared children,
//! cycles, roots with parents, out-of-range indices, accessors with any `byteStride`,
//! offset and count — read, edited (the first mesh moved, turned and scaled, carrying what
//! rests on it) and written back: never a panic, a hang or runaway memory.
#![no_main]

use libfuzzer_sys::fuzz_target;
use serde_json::{json, Value};

/// One vertex buffer of 64 floats, as a `data:` URI.
const BUFFER_FLOATS: usize = 64;

fn buffer_uri() -> String {
    const ALPHABET: &[u8] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let bytes: Vec<u8> = (0..BUFFER_FLOATS)
        .flat_map(|i| ((i % 7) as f32 * 0.25).to_le_bytes())
        .collect();
    let mut out = String::from("data:application/octet-stream;base64,");
    for chunk in bytes.chunks(3) {
        let b = [chunk[0], *chunk.get(1).unwrap_or(&0), *chunk.get(2).unwrap_or(&0)];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(ALPHABET[((n >> (18 - 6 * k)) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

fuzz_target!(|data: &[u8]| {
    if data.len() < 4 {
        return;
    }
    let mut bytes = data.iter().copied();
    let mut next = move || bytes.next().unwrap_or(0);
    // Up to a few thousand nodes: a long chain when the bytes say "child = next".
    let count = 1 + (usize::from(next()) << 4 | usize::from(next() >> 4)).min(4000);
    let chain = next() & 1 == 1;
    let mut nodes: Vec<Value> = Vec::with_capacity(count);
    for i in 0..count {
        let mut node = json!({"name": format!("n{i}")});
        let b = next();
        if chain && i + 1 < count {
            node["children"] = json!([i + 1]);
        } else if b & 0b11 == 0b11 {
            // Any index, in range or not: a cycle, a shared child, a dangling one.
            node["children"] = json!([usize::from(next()) % (count + 2)]);
        }
        if b & 0b100 != 0 {
            node["mesh"] = json!(0);
        }
        if b & 0b1000 != 0 {
            node["translation"] = json!([f32::from(next()) * 0.01, 0.0, 0.0]);
        }
        nodes.push(node);
    }
    let stride = usize::from(next() % 20);
    let offset = usize::from(next() % 40) * 4;
    let vertices = 1 + usize::from(next() % 30);
    let mut view = json!({"buffer": 0, "byteOffset": offset, "byteLength": (BUFFER_FLOATS * 4).saturating_sub(offset)});
    if stride > 0 {
        view["byteStride"] = json!(stride);
    }
    let roots: Vec<usize> = (0..count.min(1 + usize::from(next() % 4))).collect();
    let gltf = json!({
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": roots}],
        "nodes": nodes,
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": vertices, "type": "VEC3",
                        "min": [0.0, 0.0, 0.0], "max": [1.5, 1.5, 1.5]}],
        "bufferViews": [view],
        "buffers": [{"byteLength": BUFFER_FLOATS * 4, "uri": buffer_uri()}],
    });
    let text = serde_json::to_vec(&gltf).unwrap_or_default();
    let dir = std::path::Path::new("/nonexistent-shenlong-fuzz");
    let Ok((mut scene, document)) = shenlong::format::gltf::read_bytes(text, dir, "fuzz") else {
        return;
    };
    if !scene.objects.is_empty() {
        let motion = cga::Multivector::translator(glam::DVec3::new(0.3, 0.0, 0.0))
            * cga::Multivector::rotor(0.7, &cga::Multivector::e3(), &cga::Multivector::e1())
                .expect("a plane")
            * cga::Multivector::dilator(1.5).expect("a scale");
        let _ = scene.apply(0, &motion, true);
    }
    let _ = shenlong::format::gltf::write(&scene, &document);
});

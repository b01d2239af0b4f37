//! The page and its scripts, compiled into the binary. Only these paths are served: no
//! request ever names a file on disk.

/// The vendored three.js release.
pub const THREE_VERSION: &str = "0.187.0";

/// `(path, content type, bytes)` for every served asset.
pub const ASSETS: &[(&str, &str, &[u8])] = &[
    (
        "/",
        "text/html; charset=utf-8",
        include_bytes!("../../web/index.html"),
    ),
    (
        "/app.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../../web/app.js"),
    ),
    (
        "/style.css",
        "text/css; charset=utf-8",
        include_bytes!("../../web/style.css"),
    ),
    (
        "/vendor/three/three.module.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../../web/vendor/three/three.module.js"),
    ),
    (
        "/vendor/three/three.core.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../../web/vendor/three/three.core.js"),
    ),
    (
        "/vendor/three/OrbitControls.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../../web/vendor/three/OrbitControls.js"),
    ),
    (
        "/vendor/three/VRButton.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../../web/vendor/three/VRButton.js"),
    ),
    (
        "/vendor/three/loaders/GLTFLoader.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../../web/vendor/three/loaders/GLTFLoader.js"),
    ),
    (
        "/vendor/three/utils/BufferGeometryUtils.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../../web/vendor/three/utils/BufferGeometryUtils.js"),
    ),
    (
        "/vendor/three/utils/SkeletonUtils.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../../web/vendor/three/utils/SkeletonUtils.js"),
    ),
    (
        "/vendor/three/LICENSE",
        "text/plain; charset=utf-8",
        include_bytes!("../../web/vendor/three/LICENSE"),
    ),
];

/// The asset at `path`, if it is one.
pub fn find(path: &str) -> Option<(&'static str, &'static [u8])> {
    let path = if path == "/index.html" { "/" } else { path };
    ASSETS
        .iter()
        .find(|(p, _, _)| *p == path)
        .map(|(_, t, b)| (*t, *b))
}

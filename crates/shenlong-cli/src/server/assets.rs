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

/// The `Content-Security-Policy` every answer carries: the page's own script, styles,
/// images and API only — no remote script, image or connection (a scene's
/// `http://…/beacon.png` is never fetched), no plugins, no framing by another site (its
/// buttons cannot be overlaid). The page's one inline script, its import map, is allowed
/// by its hash.
#[must_use]
pub fn content_security_policy() -> &'static str {
    static POLICY: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    POLICY.get_or_init(|| {
        let page = find("/").map_or(&b""[..], |(_, bytes)| bytes);
        let page = String::from_utf8_lossy(page);
        let hashes: Vec<String> = inline_scripts(&page)
            .map(|script| {
                use base64::Engine as _;
                use sha2::Digest as _;
                let digest = sha2::Sha256::digest(script.as_bytes());
                format!(
                    "'sha256-{}'",
                    base64::engine::general_purpose::STANDARD.encode(digest)
                )
            })
            .collect();
        format!(
            "default-src 'none'; script-src 'self' {}; style-src 'self'; img-src 'self' data: blob:; \
             connect-src 'self' data: blob:; worker-src 'self' blob:; font-src 'self'; \
             object-src 'none'; base-uri 'none'; form-action 'none'; frame-ancestors 'none'",
            hashes.join(" ")
        )
    })
}

/// The text of each inline `<script>` of a page (one with no `src`).
fn inline_scripts(page: &str) -> impl Iterator<Item = &str> {
    page.split("<script").skip(1).filter_map(|rest| {
        let (open, body) = rest.split_once('>')?;
        if open.contains("src=") {
            return None;
        }
        body.split_once("</script>").map(|(script, _)| script)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_policy_allows_the_import_map_by_its_hash_and_nothing_remote() {
        let policy = content_security_policy();
        assert!(policy.contains("frame-ancestors 'none'"));
        assert!(policy.contains("img-src 'self' data: blob:;"));
        assert!(!policy.contains("http"));
        // The page has exactly one inline script, the import map.
        let page = String::from_utf8_lossy(find("/").unwrap().1).into_owned();
        assert_eq!(inline_scripts(&page).count(), 1);
        assert!(policy.contains("'sha256-"));
    }
}

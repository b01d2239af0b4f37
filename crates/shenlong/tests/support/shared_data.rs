//! Where the real scene data made by others lives: `../shared/data` beside the repository,
//! or `$SHENLONG_SHARED_DATA`. Tests that need it skip, with a message, when it is absent.
//! The CLI crate's tests include this file by path, so there is one rule for both crates.

#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// The path of `relative` inside the shared data, or `None` after printing why the test
/// skips when it is not there.
pub fn shared_data(relative: &str) -> Option<PathBuf> {
    let root = std::env::var_os("SHENLONG_SHARED_DATA")
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            // Every crate of the workspace sits two levels below the repository root.
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/data")
        });
    let path = root.join(relative);
    if path.exists() {
        Some(path)
    } else {
        eprintln!(
            "skipping: {} not found (the shared test data is absent)",
            path.display()
        );
        None
    }
}

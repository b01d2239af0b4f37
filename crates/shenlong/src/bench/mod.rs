//! The benchmark: suites of instructions with machine-checkable expectations (SPEC §6),
//! run through the pipeline for each prompt system, with reports, charts and tests of
//! significance — the paper's comparison, automatic and reproducible.

pub mod checks;
pub mod folder;
pub mod instantiate;
pub mod report;
pub mod run;
pub mod stats;
pub mod suite;

pub use suite::{SceneSource, Suite, SuiteError};

//! polyguard-cli: the `polyguard` command-line tool, the harness that pits the engine
//! against the exact oracle and the exact truth, and the case JSON Lines I/O
//! (`docs/cases.md`).
//!
//! - [`case`]: reading case lines into the engine's [`polyguard::api::Case`].
//! - [`harness`]: seeded and fuzzer-driven case generators, classification of engine
//!   answers against paper A and the truth, minimisation, reports and pictures.
//! - [`commands`]: `detect`, `detect-earth`, `detect-batch`, `assure`, `conflicts` and
//!   `generate`, the only code that prints.
#![deny(missing_docs)]

pub mod case;
pub mod commands;
pub mod harness;

//! polyguard-cli: the `polyguard` command-line tool. Its [`commands`] (`detect`,
//! `detect-batch`, `detect-earth`, `assure`, `conflicts`, `generate`, and the way out's
//! `bands`, `recover`, `offset`) are the only code
//! that parses arguments and prints; the case format, the generators, the classification
//! and the reports are the harness crate's (`polyguard-harness`).
#![deny(missing_docs)]

pub mod commands;

//! The hunt of intervals and keep-in exits (docs/cases.md, "Separation and fences";
//! docs/assurance.md, "Intervals"): cases drawn where the sets inside, near_D and
//! breach_D are hard ([`gen`]), the verdict of the engine's certified spans against the
//! oracle's exact components ([`judge`]), and the counts of a campaign ([`report`]).

pub mod gen;
pub mod judge;
pub mod report;

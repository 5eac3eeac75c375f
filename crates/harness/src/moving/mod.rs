//! The hunt of moving features (docs/moving-features.md; docs/assurance.md, "Moving
//! features"): whole flights against static and keyframed areas on the plane, drawn
//! where the sets inside and near_{D,H} are hard ([`gen`]), the verdict of the planar
//! engine's certified spans against the oracle's exact truth ([`judge`]), and the counts
//! of a campaign ([`report`]).

pub mod gen;
pub mod judge;
pub mod report;

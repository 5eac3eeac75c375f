//! polyguard-oracle: paper A (Narkawicz & Hagen, "Algorithms for collision
//! detection between a point and a moving polygon") evaluated in exact rational
//! arithmetic, and the exact ground truth of a detection case.
//!
//! Module for module it mirrors the binary-float engine, but it is written from the
//! paper alone. No binary floating point is used in any decision: inputs are
//! converted exactly ([`convert`]), square roots are never taken (numbers
//! (p + q√d)/r are ordered by sign analysis in [`qfield`]).
//!
//! Each paper function is written once, generic over a [`kernel::Kernel`]: the
//! exact kernel ([`Exact`]) decides every sign exactly; the interval kernel
//! ([`kernel::Intervals`], the one other module that touches floats) certifies
//! signs with rigorous interval arithmetic and abstains when it cannot. The
//! default entry points run each paper-function call in intervals first and fall
//! back to the exact kernel for that call (as CGAL's filtered kernels do), so every
//! answer is the exact one ([`paper_detect_unfiltered`] and [`truth_unfiltered`]
//! run the exact kernel alone).
//!
//! ```
//! use polyguard_oracle::{paper_detect, truth, CaseInput, ExactCase, Q, Truth};
//! let square = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]];
//! let c = CaseInput { lookahead: 10.0, buff: 0.01, fac: 1e-4, pos: &[-5.0, 5.0],
//!     vel: &[1.0, 0.0], vertices: &square, velocities: &[], slab: None };
//! let exact = ExactCase::<Q>::new(&c).unwrap();
//! assert!(paper_detect(&exact).detected);
//! match truth(&exact) {
//!     Truth::Enters { entry_time } => assert_eq!(entry_time.as_rational_string().as_deref(), Some("5/1")),
//!     other => panic!("{other:?}"),
//! }
//! ```
//!
//! # Layers
//! Each module uses only the modules before it in this order, so that there is no
//! import circle (scripts/check-structure.py checks it):
//! 1. numbers: [`field`] (the exact field, [`V2`]), then [`qfield`] (quadratic
//!    irrationals), [`time`] (an answer's exact time) and [`algebraic`] (real
//!    algebraic numbers: the ends of the sets of times);
//! 2. input: [`error`] (what the oracle refuses), then [`convert`] (floats and text
//!    made exact);
//! 3. [`kernel`]: the exact and the interval kernel, and how a paper function's calls
//!    run in them (with the float isolation of polynomial roots);
//! 4. paper A, in the paper's order: [`quad`] (§I) → [`contain`] (§II.B–E) →
//!    [`proximity`] (§II.G) → [`detect`] (§II.F, §II.H, §II.I, §III) →
//!    [`well_formed`](mod@well_formed) (§II.J) → [`ring`] (§II's simple polygon);
//! 5. [`case`]: a validated case and paper A's answer for it;
//! 6. [`truth`](mod@truth): the exact ground truth of a case;
//! 7. [`intervals`](mod@intervals): the exact sets of times a point is inside, near or
//!    breaching the polygon, then [`fence`]: keep-in exit detection, [`offset`]: the
//!    exact offset and inset problems and the check of a result, and
//!    [`bands`](mod@bands): whether one velocity is in conflict, exactly;
//! 8. [`recovery`]: the exact minimum distance to a recovery point (the way out of P's
//!    D-neighbourhood or into its D-core), on [`tower`]'s nested square roots (a number
//!    layer beside [`qfield`]);
//! 9. [`moving`]: the exact truth of moving features on the plane (a flight of timed
//!    fixes against static or keyframed areas), pieced together from [`intervals`](mod@intervals).

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod algebraic;
pub mod bands;
pub mod case;
pub mod contain;
pub mod convert;
pub mod detect;
pub mod error;
pub mod fence;
pub mod field;
pub mod intervals;
pub mod kernel;
pub mod moving;
pub mod offset;
pub mod proximity;
pub mod qfield;
pub mod quad;
pub mod recovery;
pub mod ring;
pub mod time;
pub mod tower;
pub mod truth;
pub mod well_formed;

pub use algebraic::{Poly, RealAlg};
pub use case::{
    paper_detect, paper_detect_unfiltered, paper_detect_with, CaseInput, ExactCase, PaperAnswer,
    Vertical,
};
pub use convert::Input;
pub use detect::{Method, Sign};
pub use error::OracleError;
pub use fence::{detect_exit, detect_exit_of};
#[cfg(feature = "rug")]
pub use field::R;
pub use field::{Arith, ExactField, Q, V2};
pub use intervals::{
    intervals, intervals_of, Components, Heights, Relation, Separation, Undefined,
};
pub use kernel::{Decided, Exact, Kernel};
pub use time::ExactTime;
pub use truth::{truth, truth_unfiltered, truth_with, Truth};

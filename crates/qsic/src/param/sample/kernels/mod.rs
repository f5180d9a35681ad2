//! Float kernels of the sampler, each behind one caller: double-double arithmetic
//! ([`dd`]), Horner's rule on four coordinates ([`horner`]), `sin`/`cos` and the grid
//! rotations ([`trig`]), safeguarded Newton ([`newton`]). Each states its accuracy at its
//! definition; none decides a sign, a rank or a root count (those are exact, upstream).

pub(super) mod dd;
pub(super) mod horner;
pub(super) mod newton;
pub(super) mod trig;

/// Four coordinates at once.
pub(super) type Lanes = [f64; 4];

//! TODO(doc)

pub(super) mod dd;
pub(super) mod horner;
pub(super) mod newton;
pub(super) mod trig;

/// Four coordinates at once.
pub(super) type Lanes = [f64; 4];

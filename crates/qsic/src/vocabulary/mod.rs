//! The plain types answers are made of, shared by the routes that produce them: the
//! classification's vocabulary (pencil kinds, complex and real types, components and
//! singular points) and the curve in ℝ³ of the affine view. They depend on nothing of the
//! crate, so the general routes (`classify`, `affine`) and their accelerators (`natural`)
//! all build them without depending on each other; `classify` and `affine` re-export them.

mod affine;
mod class;

pub use affine::{AffineComponent, AffineCurve, AffineSingularPoint};
pub use class::{
    ComplexType, Component, ComponentKind, Description, Morphology, PencilKind, RealType,
    SingularPointKind, SingularPoints,
};

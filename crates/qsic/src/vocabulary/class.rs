//! The vocabulary of the classification: pencil kinds, complex and real types, and
//! the structured description of the real components (see `docs/taxonomy.md`).

use std::fmt;

/// What kind of pencil `λA − μB` the two quadrics span.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PencilKind {
    /// `det(λA − μB)` is not identically zero: one of the 35 cases.
    Regular,
    /// `det(λA − μB) ≡ 0` and `A`, `B` are not proportional.
    Singular,
    /// `A` and `B` are proportional: the intersection is the quadric itself.
    Single,
}

impl PencilKind {
    /// The stable key used in JSON output: `regular`, `singular` or `single`.
    pub fn key(self) -> &'static str {
        match self {
            PencilKind::Regular => "regular",
            PencilKind::Singular => "singular",
            PencilKind::Single => "single",
        }
    }
}

macro_rules! keyed_enum {
    ($(#[$m:meta])* $name:ident { $($(#[$vm:meta])* $v:ident => $k:literal,)* }) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum $name { $($(#[$vm])* $v,)* }
        impl $name {
            /// Every variant, in declaration order.
            pub const ALL: &'static [$name] = &[$($name::$v,)*];
            /// The stable machine-readable key (taxonomy.md).
            pub fn key(self) -> &'static str { match self { $($name::$v => $k,)* } }
            /// The variant with this key, if any.
            pub fn from_key(key: &str) -> Option<Self> {
                match key { $($k => Some($name::$v),)* _ => None }
            }
        }
        impl fmt::Display for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result { f.write_str(self.key()) }
        }
    };
}

keyed_enum! {
    /// The type of the intersection over the complex numbers.
    ComplexType {
        /// Nonsingular quartic (cases 1–4).
        SmoothQuartic => "smooth_quartic",
        /// Quartic with a node (cases 5–8).
        NodalQuartic => "nodal_quartic",
        /// Quartic with a cusp (case 11).
        CuspidalQuartic => "cuspidal_quartic",
        /// Twisted cubic and a line meeting it twice (cases 9, 10).
        CubicAndSecantLine => "cubic_and_secant_line",
        /// Twisted cubic and a tangent line (case 12).
        CubicAndTangentLine => "cubic_and_tangent_line",
        /// Two conics meeting at two points (cases 13–18).
        TwoSecantConics => "two_secant_conics",
        /// Two conics tangent at a point (cases 21, 22).
        TwoTangentConics => "two_tangent_conics",
        /// One conic counted twice (cases 19, 20).
        DoubleConic => "double_conic",
        /// A conic and two lines meeting on it (cases 26, 27).
        ConicAndTwoLinesCrossing => "conic_and_two_lines_crossing",
        /// A conic and two lines meeting off it (cases 23–25).
        ConicAndTwoLinesNotCrossing => "conic_and_two_lines_not_crossing",
        /// Four lines forming a skew quadrilateral (cases 28–31).
        SkewQuadrilateral => "skew_quadrilateral",
        /// Two crossing lines, each counted twice (cases 32, 33).
        TwoSecantDoubleLines => "two_secant_double_lines",
        /// A double line and two simple lines (cases 34, 35).
        TwoSimpleLinesAndDoubleLine => "two_simple_lines_and_double_line",
        /// Singular pencil: a conic and a double line.
        ConicAndDoubleLine => "conic_and_double_line",
        /// Singular pencil: four lines through one point.
        FourConcurrentLines => "four_concurrent_lines",
        /// Singular pencil: two lines and a double line through one point.
        TwoConcurrentLinesAndDoubleLine => "two_concurrent_lines_and_double_line",
        /// Singular pencil: a line and a triple line.
        LineAndTripleLine => "line_and_triple_line",
        /// Singular pencil: two crossing double lines.
        TwoConcurrentDoubleLines => "two_concurrent_double_lines",
        /// Singular pencil: a cone and a double plane tangent along a line.
        QuadrupleLine => "quadruple_line",
        /// Singular pencil: every member is a pair of planes through one line.
        QuadrupleLineOfPlanePairs => "quadruple_line_of_plane_pairs",
        /// Singular pencil: a common plane and a line.
        LineAndPlane => "line_and_plane",
        /// Singular pencil: a common plane.
        Plane => "plane",
        /// Single quadric of rank 4.
        SmoothQuadric => "smooth_quadric",
        /// Single quadric of rank 3.
        Cone => "cone",
        /// Single quadric of rank 2.
        PairOfPlanes => "pair_of_planes",
        /// Single quadric of rank 1.
        DoublePlane => "double_plane",
    }
}

keyed_enum! {
    /// What is real of the intersection; [`RealType::Same`] means "the same name as the complex type".
    RealType {
        /// The real type has the complex type's name (everything is real as described).
        Same => "same",
        /// No real point.
        Empty => "empty",
        /// Smooth quartic, two affinely finite components (case 1).
        TwoFiniteComponents => "two_finite_components",
        /// Smooth quartic, one affinely finite component (case 3).
        OneFiniteComponent => "one_finite_component",
        /// Smooth quartic, two affinely infinite components (case 4).
        TwoInfiniteComponents => "two_infinite_components",
        /// Only one real point.
        Point => "point",
        /// A closed component plus an isolated node (case 6).
        IsolatedNode => "isolated_node",
        /// Affinely finite (cases 5, 13).
        AffinelyFinite => "affinely_finite",
        /// Affinely infinite (cases 8, 18).
        AffinelyInfinite => "affinely_infinite",
        /// Cubic and a line meeting it at two imaginary points (case 10).
        CubicAndNonsecantLine => "cubic_and_nonsecant_line",
        /// Two imaginary conics tangent at a real point (case 22).
        DoublePoint => "double_point",
        /// Two real points.
        TwoPoints => "two_points",
        /// Two real conics with imaginary meeting points (case 14).
        TwoNonsecantConics => "two_nonsecant_conics",
        /// One real conic, one imaginary (case 17).
        OneConic => "one_conic",
        /// A real conic (case 27).
        Conic => "conic",
        /// A real conic and a real point (case 24).
        ConicAndPoint => "conic_and_point",
        /// Two real lines (case 31).
        TwoLines => "two_lines",
        /// A real double line (case 34; singular pencils).
        DoubleLine => "double_line",
        /// Two real concurrent lines (singular pencils).
        TwoConcurrentLines => "two_concurrent_lines",
        /// Single smooth quadric of inertia (3,1).
        Inertia31 => "inertia_3_1",
        /// Single smooth quadric of inertia (2,2).
        Inertia22 => "inertia_2_2",
        /// Single real cone, inertia (2,1).
        RealCone => "real_cone",
        /// Two conjugate planes meeting in a real line.
        Line => "line",
    }
}

/// The morphology of an intersection: complex type and real type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Morphology {
    /// Type over ℂ.
    pub complex: ComplexType,
    /// What is real of it.
    pub real: RealType,
}

impl Morphology {
    /// The `real_type` key as reported: the complex key when the real type is [`RealType::Same`].
    pub fn real_key(&self) -> &'static str {
        match self.real {
            RealType::Same => self.complex.key(),
            r => r.key(),
        }
    }
}

/// The kind of a real component of the intersection.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ComponentKind {
    /// An isolated real point.
    Point,
    /// A straight line.
    Line,
    /// A conic.
    Conic,
    /// A twisted cubic.
    Cubic,
    /// A branch of an irreducible quartic.
    Quartic,
    /// A plane (singular pencils).
    Plane,
    /// A whole quadric (a quadric paired with itself).
    Quadric,
}

impl ComponentKind {
    /// Stable key used in JSON.
    pub fn key(self) -> &'static str {
        match self {
            ComponentKind::Point => "point",
            ComponentKind::Line => "line",
            ComponentKind::Conic => "conic",
            ComponentKind::Cubic => "cubic",
            ComponentKind::Quartic => "quartic",
            ComponentKind::Plane => "plane",
            ComponentKind::Quadric => "quadric",
        }
    }

    /// The degree of a curve of this kind: 0 for a point, `None` for a plane or a quadric.
    pub fn degree(self) -> Option<u32> {
        match self {
            ComponentKind::Point => Some(0),
            ComponentKind::Line => Some(1),
            ComponentKind::Conic => Some(2),
            ComponentKind::Cubic => Some(3),
            ComponentKind::Quartic => Some(4),
            ComponentKind::Plane | ComponentKind::Quadric => None,
        }
    }
}

/// A family of equal real components: `count` components of this kind, each of this multiplicity.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Component {
    /// Point, line, conic, …
    pub kind: ComponentKind,
    /// 1 for a simple component, 2 for a double line or conic, …
    pub multiplicity: u8,
    /// How many such components.
    pub count: u8,
    /// `Some(true)` if each is affinely finite (bounded in some affine chart), `Some(false)` if
    /// never, `None` where the notion is not meaningful or not fixed by the class.
    pub closed: Option<bool>,
}

/// The kind of a real singular point of the intersection curve.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SingularPointKind {
    /// An isolated real point of the curve (two conjugate branches).
    Acnode,
    /// Two real branches crossing transversally.
    Crunode,
    /// A cusp.
    Cusp,
    /// Two branches tangent to each other.
    Tangency,
    /// Three or more branches (or a multiple component) through one point.
    Multiple,
}

impl SingularPointKind {
    /// Stable key used in JSON.
    pub fn key(self) -> &'static str {
        match self {
            SingularPointKind::Acnode => "acnode",
            SingularPointKind::Crunode => "crunode",
            SingularPointKind::Cusp => "cusp",
            SingularPointKind::Tangency => "tangency",
            SingularPointKind::Multiple => "multiple",
        }
    }
}

/// `count` real singular points of one kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SingularPoints {
    /// Their kind.
    pub kind: SingularPointKind,
    /// How many.
    pub count: u8,
}

/// The structured description of the real intersection, derived from the class.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Description {
    /// Real components, grouped by kind and multiplicity. Empty when nothing is real.
    pub components: Vec<Component>,
    /// Real singular points of the curve (meeting points of components included).
    pub singular_points: Vec<SingularPoints>,
    /// One line for humans.
    pub summary: &'static str,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The singular point keys of the JSON schema (README, `singular_points[]`).
    #[test]
    fn singular_point_keys_are_the_schema_ones() {
        use SingularPointKind as S;
        let kinds = [S::Acnode, S::Crunode, S::Cusp, S::Tangency, S::Multiple];
        let keys = kinds.map(S::key);
        assert_eq!(keys, ["acnode", "crunode", "cusp", "tangency", "multiple"]);
    }
}

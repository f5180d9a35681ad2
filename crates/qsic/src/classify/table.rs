//! The 35 morphologies of a regular pencil (Tu, Wang, Mourrain, Wang, CAGD 2009, Tables 1–3),
//! with the corrections of `shared/papers/ERRATA.md`: one pair of parentheses per unit of
//! root multiplicity, case 10 as `[22]_0`, a second class for case 16.
//!
//! The notations are written as the paper prints them and read by the compiler (module
//! `notation`): a malformed entry, or one whose index sequence disagrees with its signature
//! sequence or Segre characteristic, does not compile.

use super::notation::{case_class, case_segre, IndexSequence, Segre, SignatureSequence};
use crate::vocabulary::{
    ComplexType as C, Component, ComponentKind as K, Description, RealType as R,
    SingularPointKind as S, SingularPoints,
};

/// One row of the table: a case and the sequences that characterise it.
pub(crate) struct CaseRow {
    /// The paper's case number, 1–35.
    pub case: u8,
    /// Segre characteristic with the number of distinct real roots.
    pub segre: Segre,
    /// The signature sequences of the case (one per inequivalent class), each with its index sequence.
    pub sequences: &'static [(SignatureSequence, IndexSequence)],
    pub complex: C,
    pub real: R,
    pub components: &'static [(K, u8, u8, Option<bool>)],
    pub singular: &'static [(S, u8)],
    pub summary: &'static str,
}

impl CaseRow {
    pub fn description(&self) -> Description {
        Description {
            components: self
                .components
                .iter()
                .map(|&(kind, multiplicity, count, closed)| Component {
                    kind,
                    multiplicity,
                    count,
                    closed,
                })
                .collect(),
            singular_points: self
                .singular
                .iter()
                .map(|&(kind, count)| SingularPoints { kind, count })
                .collect(),
            summary: self.summary,
        }
    }
}

const CLOSED: Option<bool> = Some(true);
const OPEN: Option<bool> = Some(false);

macro_rules! row {
    ($case:expr, $segre:expr, [$(($sig:expr, $idx:expr)),+], $c:ident, $r:ident,
     [$(($k:ident, $m:expr, $n:expr, $cl:expr)),*], [$(($s:ident, $sn:expr)),*], $sum:expr) => {
        CaseRow {
            case: $case,
            segre: case_segre($segre),
            sequences: &[$(case_class($segre, $sig, $idx)),+],
            complex: C::$c,
            real: R::$r,
            components: &[$((K::$k, $m, $n, $cl)),*],
            singular: &[$((S::$s, $sn)),*],
            summary: $sum,
        }
    };
}

/// All 35 cases, in order.
pub(crate) static CASES: [CaseRow; 35] = [
    row!(1, "[1111]_4", [("(1,(1,2),2,(1,2),1,(1,2),2,(2,1),3)", "<1|2|1|2|3>")], SmoothQuartic, TwoFiniteComponents,
        [(Quartic, 1, 2, CLOSED)], [], "nonsingular quartic with two closed real components"),
    row!(2, "[1111]_4", [("(0,(0,3),1,(1,2),2,(2,1),3,(3,0),4)", "<0|1|2|3|4>")], SmoothQuartic, Empty,
        [], [], "nonsingular quartic with no real point"),
    row!(3, "[1111]_2", [("(1,(1,2),2,(2,1),3)", "<1|2|3>")], SmoothQuartic, OneFiniteComponent,
        [(Quartic, 1, 1, CLOSED)], [], "nonsingular quartic with one closed real component"),
    row!(4, "[1111]_0", [("(2)", "<2>")], SmoothQuartic, TwoInfiniteComponents,
        [(Quartic, 1, 2, OPEN)], [], "nonsingular quartic with two open real components"),
    row!(5, "[211]_3", [("(2,((2,1)),2,(2,1),3,(2,1),2)", "<2~~-2|3|2>")], NodalQuartic, AffinelyFinite,
        [(Quartic, 1, 1, CLOSED)], [(Crunode, 1)], "nodal quartic: one closed real component crossing itself at a crunode"),
    row!(6, "[211]_3", [("(1,((1,2)),1,(1,2),2,(2,1),3)", "<1~~-1|2|3>")], NodalQuartic, IsolatedNode,
        [(Quartic, 1, 1, CLOSED), (Point, 1, 1, CLOSED)], [(Acnode, 1)], "nodal quartic: one closed real component and an isolated real node (acnode)"),
    row!(7, "[211]_3", [("(1,((0,3)),1,(1,2),2,(2,1),3)", "<1~~+1|2|3>")], NodalQuartic, Point,
        [(Point, 1, 1, CLOSED)], [(Acnode, 1)], "nodal quartic whose only real point is its isolated node (acnode)"),
    row!(8, "[211]_1", [("(2,((2,1)),2)", "<2~~-2>")], NodalQuartic, AffinelyInfinite,
        [(Quartic, 1, 1, OPEN)], [(Crunode, 1)], "nodal quartic: one open real component crossing itself at a crunode"),
    row!(9, "[22]_2", [("(2,((2,1)),2,((2,1)),2)", "<2~~-2~~-2>")], CubicAndSecantLine, Same,
        [(Cubic, 1, 1, OPEN), (Line, 1, 1, OPEN)], [(Crunode, 2)], "a real twisted cubic and a real line meeting at two real points"),
    row!(10, "[22]_0", [("(2)", "<2>")], CubicAndSecantLine, CubicAndNonsecantLine,
        [(Cubic, 1, 1, OPEN), (Line, 1, 1, OPEN)], [], "a real twisted cubic and a real line meeting at two imaginary points"),
    row!(11, "[31]_2", [("(1,(((1,2))),2,(2,1),3)", "<1~~~+2|3>")], CuspidalQuartic, Same,
        [(Quartic, 1, 1, CLOSED)], [(Cusp, 1)], "cuspidal quartic: one closed real component with a real cusp"),
    row!(12, "[4]_1", [("(2,((((2,1)))),2)", "<2~~~~-2>")], CubicAndTangentLine, Same,
        [(Cubic, 1, 1, OPEN), (Line, 1, 1, OPEN)], [(Tangency, 1)], "a real twisted cubic and a real line tangent to it at one real point"),
    row!(13, "[(11)11]_3", [("(2,((1,1)),2,(1,2),1,(1,2),2)", "<2||2|1|2>")], TwoSecantConics, AffinelyFinite,
        [(Conic, 1, 2, CLOSED)], [(Crunode, 2)], "two real conics meeting at two real points; both can be ellipses"),
    row!(14, "[(11)11]_3", [("(1,((1,1)),3,(2,1),2,(2,1),3)", "<1||3|2|3>")], TwoSecantConics, TwoNonsecantConics,
        [(Conic, 1, 2, CLOSED)], [], "two real conics meeting at two imaginary points"),
    row!(15, "[(11)11]_3", [("(1,((0,2)),1,(1,2),2,(2,1),3)", "<1||1|2|3>")], TwoSecantConics, TwoPoints,
        [(Point, 1, 2, CLOSED)], [(Acnode, 2)], "two imaginary conics meeting at two real points, the only real points"),
    row!(16, "[(11)11]_3", [("(0,((0,2)),2,(2,1),3,(3,0),4)", "<0||2|3|4>"), ("(1,((1,1)),3,(3,0),4,(3,0),3)", "<1||3|4|3>")], TwoSecantConics, Empty,
        [], [], "two imaginary conics meeting at imaginary points: no real point"),
    row!(17, "[(11)11]_1", [("(1,((1,1)),3)", "<1||3>")], TwoSecantConics, OneConic,
        [(Conic, 1, 1, CLOSED)], [], "one real conic and one imaginary conic"),
    row!(18, "[(11)11]_1", [("(2,((1,1)),2)", "<2||2>")], TwoSecantConics, AffinelyInfinite,
        [(Conic, 1, 2, CLOSED)], [(Crunode, 2)], "two real conics meeting at two real points; never both ellipses in one affine chart"),
    row!(19, "[(111)1]_2", [("(1,(((0,1))),2,(2,1),3)", "<1|||2|3>")], DoubleConic, Same,
        [(Conic, 2, 1, CLOSED)], [], "a real conic counted twice"),
    row!(20, "[(111)1]_2", [("(0,(((0,1))),3,(3,0),4)", "<0|||3|4>")], DoubleConic, Empty,
        [], [], "an imaginary conic counted twice: no real point"),
    row!(21, "[(21)1]_2", [("(1,(((1,1))),2,(2,1),3)", "<1~~-|2|3>")], TwoTangentConics, Same,
        [(Conic, 1, 2, CLOSED)], [(Tangency, 1)], "two real conics tangent at one real point"),
    row!(22, "[(21)1]_2", [("(1,(((0,2))),2,(2,1),3)", "<1~~+|2|3>")], TwoTangentConics, DoublePoint,
        [(Point, 1, 1, CLOSED)], [(Tangency, 1)], "two imaginary conics tangent at a real point, the only real point"),
    row!(23, "[2(11)]_2", [("(2,((2,1)),2,((1,1)),2)", "<2~~-2||2>")], ConicAndTwoLinesNotCrossing, Same,
        [(Conic, 1, 1, CLOSED), (Line, 1, 2, OPEN)], [(Crunode, 3)], "a real conic and two real lines meeting pairwise at three real points"),
    row!(24, "[2(11)]_2", [("(1,((1,2)),1,((1,1)),3)", "<1~~-1||3>")], ConicAndTwoLinesNotCrossing, ConicAndPoint,
        [(Conic, 1, 1, CLOSED), (Point, 1, 1, CLOSED)], [(Acnode, 1)], "a real conic and two conjugate lines meeting at a real point off the conic"),
    row!(25, "[2(11)]_2", [("(1,((0,3)),1,((1,1)),3)", "<1~~+1||3>")], ConicAndTwoLinesNotCrossing, Point,
        [(Point, 1, 1, CLOSED)], [(Acnode, 1)], "an imaginary conic and two conjugate lines whose real meeting point is the only real point"),
    row!(26, "[(31)]_1", [("(2,((((1,1)))),2)", "<2~~~-|2>")], ConicAndTwoLinesCrossing, Same,
        [(Conic, 1, 1, CLOSED), (Line, 1, 2, OPEN)], [(Multiple, 1)], "a real conic and two real lines, all through one real point"),
    row!(27, "[(31)]_1", [("(1,((((1,1)))),3)", "<1~~~+|3>")], ConicAndTwoLinesCrossing, Conic,
        [(Conic, 1, 1, CLOSED)], [(Multiple, 1)], "a real conic and two conjugate lines through one real point of it"),
    row!(28, "[(11)(11)]_2", [("(2,((1,1)),2,((1,1)),2)", "<2||2||2>")], SkewQuadrilateral, Same,
        [(Line, 1, 4, OPEN)], [(Crunode, 4)], "four real lines forming a skew quadrilateral"),
    row!(29, "[(11)(11)]_2", [("(0,((0,2)),2,((2,0)),4)", "<0||2||4>")], SkewQuadrilateral, Empty,
        [], [], "four imaginary lines: no real point"),
    row!(30, "[(11)(11)]_2", [("(1,((0,2)),1,((1,1)),3)", "<1||1||3>")], SkewQuadrilateral, TwoPoints,
        [(Point, 1, 2, CLOSED)], [(Acnode, 2)], "two pairs of conjugate lines, each pair meeting at a real point"),
    row!(31, "[(11)(11)]_0", [("(2)", "<2>")], SkewQuadrilateral, TwoLines,
        [(Line, 1, 2, OPEN)], [], "two real skew lines and two imaginary lines"),
    row!(32, "[(211)]_1", [("(2,((((1,0)))),2)", "<2~~-||2>")], TwoSecantDoubleLines, Same,
        [(Line, 2, 2, OPEN)], [(Multiple, 1)], "two real crossing lines, each counted twice"),
    row!(33, "[(211)]_1", [("(1,((((1,0)))),3)", "<1~~-||3>")], TwoSecantDoubleLines, Point,
        [(Point, 1, 1, CLOSED)], [(Multiple, 1)], "two conjugate lines counted twice, meeting at the only real point"),
    row!(34, "[(22)]_1", [("(2,((((2,0)))),2)", "<2~~-~~-2>")], TwoSimpleLinesAndDoubleLine, DoubleLine,
        [(Line, 2, 1, OPEN)], [], "a real double line and two conjugate skew lines"),
    row!(35, "[(22)]_1", [("(2,((((1,1)))),2)", "<2~~-~~+2>")], TwoSimpleLinesAndDoubleLine, Same,
        [(Line, 2, 1, OPEN), (Line, 1, 2, OPEN)], [(Multiple, 2)], "a real double line and two real skew lines, each meeting it"),
];

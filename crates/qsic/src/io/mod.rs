//! Reading quadrics from text and from numeric tables, exactly.
//!
//! | entry point | reads |
//! |---|---|
//! | [`parse_number`] | one rational number: `-7`, `3/4`, `0.1`, `2.5e-3` |
//! | [`parse_quadric`] | a polynomial of degree 2 in `x, y, z, w`, affine or homogeneous; one of degree 1 (a plane) as its double plane |
//! | [`parse_quadric_or_plane`] | the same, and whether the polynomial was a plane |
//! | [`quadric_from_rows`] | a 4×4 matrix of number strings |
//! | [`quadric_from_array`] | the same as an array `[[S; 4]; 4]` |
//! | [`quadric_from_f64_rows`] | a 4×4 matrix of `f64`, each converted exactly |
//! | [`parse_rational_function`] | an expression in chosen variables with any division: a quotient of polynomials |
//! | [`moving_matrix_from_rows`] | a 4×4 matrix of rational functions of `t`: a [`MovingMatrix`] over one denominator |
//! | [`moving_matrix_from_polys`] | a symmetric matrix of polynomials in `t` over a denominator, computed rather than read: the same |
//! | [`moving_matrix_from_polynomial`] | a quadratic form in `x, y, z, w` with coefficients rational in `t` (a linear one as its double plane): the same |
//!
//! Polynomials and rational functions are read by one Pratt parser (`expression`); the
//! quadric reader is that parser in a grammar of degree ≤ 2 in `x, y, z, w`, with a
//! machine-arithmetic reader in front for plain sums of terms.
//!
//! Every value is exact: `0.1` is one tenth. Numbers of up to 18 digits are read in machine
//! arithmetic and the quadric built from them without big numbers (see [`crate::quadric`]);
//! longer ones, and every error, go through the big rationals of [`parse_number`]. Input sizes are bounded by
//! [`crate::limits`], so no string, however built, makes a reader panic or run long.

mod expression;
mod moving;
mod number;
mod polynomial;

pub use expression::{parse_rational_function, RationalFunction, Variable, VARIABLE_NAMES};
pub use moving::{
    moving_matrix_from_polynomial, moving_matrix_from_polys, moving_matrix_from_rows, MovingMatrix,
};
use number::parse_number_small;
pub use number::{parse_number, shortest_decimal};
pub use polynomial::{
    parse_plane, parse_quadric, parse_quadric_big_route, parse_quadric_or_plane, plane_as_quadric,
};

use crate::error::Error;
use crate::quadric::{Quadric, SmallRational};
use dashu_ratio::RBig;

/// Checks that `rows` is 4×4, as [`Error::Shape`] describes.
fn check_shape<T>(rows: &[Vec<T>]) -> Result<(), Error> {
    let bad_row = rows.iter().map(Vec::len).find(|&len| len != 4);
    if rows.len() != 4 || bad_row.is_some() {
        return Err(Error::Shape {
            rows: rows.len(),
            cols: bad_row,
        });
    }
    Ok(())
}

/// Builds a quadric from a 4×4 matrix of number strings, each read by [`parse_number`].
///
/// # Errors
/// - [`Error::Shape`] if `rows` is not 4 rows of 4 entries;
/// - [`Error::Entry`] (0-based row and column) wrapping the [`Error::BadNumber`]
///   or [`Error::Limit`] of the first entry that cannot be read, row by row;
/// - then as [`Quadric::from_matrix`]: [`Error::NotSymmetric`], [`Error::ZeroQuadric`].
///
/// # Examples
/// ```
/// use qsic::io::quadric_from_rows;
///
/// let rows = [
///     ["1", "0", "0", "0"],
///     ["0", "1/2", "0", "0"],
///     ["0", "0", "0.25", "0"],
///     ["0", "0", "0", "-1e0"],
/// ]
/// .map(|row| row.to_vec());
/// let q = quadric_from_rows(&rows)?;
/// assert_eq!(q.to_polynomial_string(), "x^2 + 1/2*y^2 + 1/4*z^2 - w^2");
///
/// let mut bad = rows.clone();
/// bad[2][1] = "1/0";
/// assert!(matches!(
///     quadric_from_rows(&bad),
///     Err(qsic::error::Error::Entry { row: 2, col: 1, .. })
/// ));
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn quadric_from_rows<S: AsRef<str>>(rows: &[Vec<S>]) -> Result<Quadric, Error> {
    check_shape(rows)?;
    quadric_from_entries(|i, j| rows[i][j].as_ref())
}

/// [`quadric_from_rows`] for a 4×4 array of number strings (no shape to check).
///
/// # Errors
/// As [`quadric_from_rows`], but for [`Error::Shape`].
///
/// # Examples
/// ```
/// use qsic::io::quadric_from_array;
///
/// let q = quadric_from_array(&[["1", "0", "0", "0"], ["0", "3/2", "0", "0"], ["0"; 4], ["0"; 4]])?;
/// assert_eq!(q.small_integer_matrix().map(|m| (m[0][0], m[1][1])), Some((2, 3)));
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn quadric_from_array<S: AsRef<str>>(m: &[[S; 4]; 4]) -> Result<Quadric, Error> {
    quadric_from_entries(|i, j| m[i][j].as_ref())
}

/// The quadric of the 4×4 number texts `entry(i, j)`: in machine arithmetic when every
/// text is a small number, else (and for every error) by the big-rational route.
fn quadric_from_entries<'a>(entry: impl Fn(usize, usize) -> &'a str) -> Result<Quadric, Error> {
    let mut small = [[SmallRational::ZERO; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            let text = entry(i, j);
            // Below the diagonal, the text of the mirror entry, already read, is usually
            // repeated: the same text has the same value.
            if j < i && text == entry(j, i) {
                small[i][j] = small[j][i];
                continue;
            }
            match parse_number_small(text) {
                Some(v) => small[i][j] = v,
                None => return quadric_from_entries_big_route(entry),
            }
        }
    }
    Quadric::from_small_rationals(&small)
}

/// [`quadric_from_rows`] through big rationals only ([`parse_number`], then
/// [`Quadric::from_matrix_big_route`]): the general route, which the machine route must
/// equal (differential tests).
///
/// # Errors
/// As [`quadric_from_rows`].
#[doc(hidden)]
pub fn quadric_from_rows_big_route<S: AsRef<str>>(rows: &[Vec<S>]) -> Result<Quadric, Error> {
    check_shape(rows)?;
    quadric_from_entries_big_route(|i, j| rows[i][j].as_ref())
}

fn quadric_from_entries_big_route<'a>(
    entry: impl Fn(usize, usize) -> &'a str,
) -> Result<Quadric, Error> {
    let mut m: [[RBig; 4]; 4] = Default::default();
    for (i, row) in m.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = parse_number(entry(i, j)).map_err(|e| Error::Entry {
                row: i,
                col: j,
                source: Box::new(e),
            })?;
        }
    }
    Quadric::from_matrix_big_route(m)
}

/// Builds a quadric from a 4×4 matrix of `f64`, each entry converted exactly
/// (as [`Quadric::from_f64`]: `0.1` becomes the dyadic rational the float holds).
///
/// # Errors
/// [`Error::Shape`] if `rows` is not 4 rows of 4 entries, then as
/// [`Quadric::from_f64`]: [`Error::NotFinite`], [`Error::NotSymmetric`], [`Error::ZeroQuadric`].
///
/// # Examples
/// ```
/// use qsic::io::quadric_from_f64_rows;
///
/// let mut rows = vec![vec![0.0; 4]; 4];
/// rows[0][0] = 0.5;
/// rows[3][3] = -2.0;
/// let q = quadric_from_f64_rows(&rows)?;
/// assert_eq!(q.to_polynomial_string(), "1/2*x^2 - 2*w^2");
/// assert!(quadric_from_f64_rows(&rows[..3]).is_err());
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn quadric_from_f64_rows(rows: &[Vec<f64>]) -> Result<Quadric, Error> {
    check_shape(rows)?;
    let mut m = [[0.0; 4]; 4];
    for (dst, src) in m.iter_mut().zip(rows) {
        dst.copy_from_slice(src);
    }
    Quadric::from_f64(m)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn strings(m: [[&str; 4]; 4]) -> Vec<Vec<String>> {
        m.iter()
            .map(|r| r.iter().map(|s| s.to_string()).collect())
            .collect()
    }

    const IDENTITY: [[&str; 4]; 4] = [
        ["1", "0", "0", "0"],
        ["0", "1", "0", "0"],
        ["0", "0", "1", "0"],
        ["0", "0", "0", "-1"],
    ];

    #[test]
    fn reads_string_matrices_exactly() {
        let mut m = IDENTITY;
        m[0][1] = "0.1";
        m[1][0] = "1/10";
        let q = quadric_from_rows(&strings(m)).expect("a valid matrix");
        assert_eq!(q.entry(0, 1), &RBig::from_parts(1.into(), 10u8.into()));
        assert_eq!(q, quadric_from_rows(&m.map(|r| r.to_vec())).expect("same"));
    }

    #[test]
    fn string_matrix_errors() {
        let mut asym = IDENTITY;
        asym[0][2] = "2";
        let mut bad = IDENTITY;
        bad[3][1] = "x";
        let mut huge = IDENTITY;
        huge[1][1] = "1e100000";
        assert!(matches!(
            quadric_from_rows(&strings(asym)),
            Err(Error::NotSymmetric { row: 0, col: 2, .. })
        ));
        match quadric_from_rows(&strings(bad)) {
            Err(Error::Entry {
                row: 3,
                col: 1,
                source,
            }) => {
                assert!(matches!(*source, Error::BadNumber { .. }))
            }
            other => panic!("expected an entry error, got {other:?}"),
        }
        match quadric_from_rows(&strings(huge)) {
            Err(Error::Entry {
                row: 1,
                col: 1,
                source,
            }) => {
                assert!(matches!(*source, Error::Limit { .. }))
            }
            other => panic!("expected an entry error, got {other:?}"),
        }
        assert_eq!(
            quadric_from_rows(&strings([["0"; 4]; 4])),
            Err(Error::ZeroQuadric)
        );
    }

    #[test]
    fn shape_errors() {
        let three = vec![vec!["1"; 4]; 3];
        assert_eq!(
            quadric_from_rows(&three),
            Err(Error::Shape {
                rows: 3,
                cols: None
            })
        );
        let mut ragged = vec![vec!["1"; 4]; 4];
        ragged[2].push("1");
        assert_eq!(
            quadric_from_rows(&ragged),
            Err(Error::Shape {
                rows: 4,
                cols: Some(5)
            })
        );
        let floats = vec![vec![1.0; 3]; 4];
        assert_eq!(
            quadric_from_f64_rows(&floats),
            Err(Error::Shape {
                rows: 4,
                cols: Some(3)
            })
        );
    }

    #[test]
    fn reads_float_matrices_exactly() {
        let mut rows = vec![vec![0.0; 4]; 4];
        rows[1][2] = 0.1;
        rows[2][1] = 0.1;
        let q = quadric_from_f64_rows(&rows).expect("a valid matrix");
        let exact = RBig::try_from(0.1f64).expect("finite");
        assert_eq!(q.entry(1, 2), &exact);
        assert_ne!(q.entry(1, 2), &RBig::from_parts(1.into(), 10u8.into()));
        rows[0][0] = f64::NAN;
        assert_eq!(
            quadric_from_f64_rows(&rows),
            Err(Error::NotFinite { row: 0, col: 0 })
        );
    }
}

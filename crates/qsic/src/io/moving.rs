//! Moving quadrics: 4×4 symmetric matrices whose entries are rational functions of `t`,
//! read from a matrix of strings or from a quadratic form, put over one denominator.

use super::expression::{read, Grammar, RationalFunction, Variable};
use super::number::excerpt;
use super::polynomial::{form_in_xyzw, square_of_plane, XyzwForm};
use super::{check_shape, parse_rational_function};
use crate::error::Error;
use crate::limits::{MAX_DEGREE, MAX_MOVING_MATRIX_BITS};
use crate::quadric::Quadric;
use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;
use qsic_algebra::mpoly::{bits, MPoly};
use qsic_algebra::Poly;

/// A moving quadric `A(t) = g(t)·M(t) / d(t)`: a symmetric matrix `M` of polynomials in `t`
/// without a common factor, and the scalar `g/d` that the entries of `A` share, in
/// canonical form.
///
/// Canonical: `M` has integer coefficients and its 16 entries have no common factor in
/// `ℤ[t]` (no common root, no common integer content); `g` and `d` are coprime integer
/// polynomials (content included) with positive leading coefficients; so two moving
/// matrices are equal exactly when they are the same function of `t`, and every reader
/// clears a factor common to all entries the same way (`t·x² + t·y² − t` is the quadric
/// `x² + y² − w²` at every `t`, `t = 0` included).
///
/// The quadric at `t` is `M(t)` ([`MovingMatrix::quadric_at`]): the same surface as
/// `A(t)` where `g(t)/d(t)` is defined and nonzero (scaled by `d(t)/g(t)`, whose sign may
/// flip the inertia), and its limit where `g(t) = 0` or `d(t) = 0`; it is never the zero
/// form.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MovingMatrix {
    numerators: [[Poly; 4]; 4],
    factor: Poly,
    denominator: Poly,
}

impl MovingMatrix {
    /// The symmetric matrix `M(t)`, its entries without a common factor.
    pub fn numerators(&self) -> &[[Poly; 4]; 4] {
        &self.numerators
    }

    /// The factor `g(t)` common to all the entries of `A(t)·d(t)`.
    pub fn factor(&self) -> &Poly {
        &self.factor
    }

    /// The common denominator `d(t)`.
    pub fn denominator(&self) -> &Poly {
        &self.denominator
    }

    /// `A(t) = g(t)·M(t)/d(t)` at a rational `t`, or `None` where `d(t) = 0`.
    pub fn at(&self, t: &RBig) -> Option<[[RBig; 4]; 4]> {
        let d = self.denominator.eval_rational(t);
        if d.is_zero() {
            return None;
        }
        let scale = self.factor.eval_rational(t) / d;
        Some(std::array::from_fn(|i| {
            std::array::from_fn(|j| self.numerators[i][j].eval_rational(t) * &scale)
        }))
    }

    /// The quadric `M(t)` at a rational `t`.
    ///
    /// # Errors
    /// None in practice: the entries of `M` have no common root. [`Error::ZeroQuadric`]
    /// would name that case.
    pub fn quadric_at(&self, t: &RBig) -> Result<Quadric, Error> {
        Quadric::from_matrix(std::array::from_fn(|i| {
            std::array::from_fn(|j| self.numerators[i][j].eval_rational(t))
        }))
    }
}

/// Reads a moving quadric from a 4×4 matrix of rational functions of `t`, each read by
/// [`parse_rational_function`] (`"(t**2 - 1)/(t**2 + 1)"`, `"-2*t/(t^2+1)"`, `"1/2"`),
/// and clears the denominators: `M = lcm(denominators)·A` (see [`MovingMatrix`]).
///
/// # Errors
/// - [`Error::Shape`] if `rows` is not 4 rows of 4 entries;
/// - [`Error::Entry`] (0-based row and column) wrapping the error of the first entry that
///   cannot be read, row by row (a name other than `t` is an [`Error::UnknownVariable`]);
/// - [`Error::Limit`] if the coefficients of all entries together have more than
///   [`MAX_MOVING_MATRIX_BITS`] bits, or the common denominator a degree above
///   [`MAX_DEGREE`];
/// - [`Error::NotSymmetric`] (with the two texts) if `Aᵢⱼ ≠ Aⱼᵢ` as rational functions;
/// - [`Error::ZeroQuadric`] if every entry is zero.
///
/// # Examples
/// ```
/// use dashu_ratio::RBig;
/// use qsic::io::moving_matrix_from_rows;
/// use qsic_algebra::Poly;
///
/// // Example 4.1 of Jia et al. (2013): the lcm of the denominators is (3t − 4)².
/// let (a, b) = ("4/(9*t**2 - 24*t + 16)", "-2/(3*t - 4)");
/// let rows = [[a, "0", "0", b], ["0", "4", "0", "0"], ["0", "0", "4", "0"], [b, "0", "0", "0"]];
/// let m = moving_matrix_from_rows(&rows.map(|r| r.to_vec()))?;
/// assert_eq!(m.denominator(), &Poly::from_i64s(&[16, -24, 9]));
/// // The factor 2 common to all entries of (3t − 4)²·A comes out: A = 2·M/(3t − 4)².
/// assert_eq!(m.factor(), &Poly::from_i64s(&[2]));
/// assert_eq!(m.numerators()[0][3], Poly::from_i64s(&[4, -3])); // −(3t − 4)
/// assert_eq!(m.at(&RBig::from(2)).map(|a| a[0][0].clone()), Some(RBig::ONE));
/// assert!(m.at(&RBig::from_parts(4.into(), 3u8.into())).is_none()); // a pole
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn moving_matrix_from_rows<S: AsRef<str>>(rows: &[Vec<S>]) -> Result<MovingMatrix, Error> {
    check_shape(rows)?;
    let t = Variable::T.index();
    let mut entries: Vec<Vec<RationalFunction>> = Vec::with_capacity(4);
    for (i, row) in rows.iter().enumerate() {
        let mut read_row = Vec::with_capacity(4);
        for (j, text) in row.iter().enumerate() {
            let f = parse_rational_function(text.as_ref(), &[Variable::T]).map_err(|e| {
                Error::Entry {
                    row: i,
                    col: j,
                    source: Box::new(e),
                }
            })?;
            read_row.push(f);
        }
        entries.push(read_row);
    }
    let size = entries
        .iter()
        .flatten()
        .map(|f| size_in_bits(f.numerator()) + size_in_bits(f.denominator()))
        .sum();
    check_moving_size(size)?;
    for i in 0..4 {
        for j in i + 1..4 {
            if !entries[i][j].same_as(&entries[j][i]) {
                return Err(Error::NotSymmetric {
                    row: i,
                    col: j,
                    a: excerpt(rows[i][j].as_ref().trim()),
                    b: excerpt(rows[j][i].as_ref().trim()),
                });
            }
        }
    }
    if entries.iter().flatten().all(|f| f.numerator().is_zero()) {
        return Err(Error::ZeroQuadric);
    }
    // The lcm of the denominators, primitive (Gauss: primitive factors, primitive products).
    let mut common = Poly::constant(IBig::ONE);
    for f in entries.iter().flatten() {
        let d = integer_poly(f.denominator(), t);
        if common.div_exact(&d).is_none() {
            let g = common.gcd(&d);
            common = (&common * &d).div_exact(&g).unwrap_or(common);
            let degree = common.degree().unwrap_or(0);
            if degree > MAX_DEGREE as usize {
                return Err(Error::Limit {
                    what: format!("degree {degree} of the common denominator"),
                    limit: MAX_DEGREE as usize,
                });
            }
        }
    }
    let numerators = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let f = &entries[i][j];
            // d divides the primitive `common` in ℤ[t] (Gauss's lemma).
            let cofactor = common
                .div_exact(&integer_poly(f.denominator(), t))
                .unwrap_or_default();
            rational_times(&dense(f.numerator(), t), &cofactor)
        })
    });
    Ok(canonical(numerators, common))
}

/// Reads a moving quadric from a quadratic form in `x, y, z, w` whose coefficients are
/// rational functions of `t`, such as `x^2 + t*y^2 - (1+t^2)/(1-t)*z*w`: the same
/// grammar as [`parse_rational_function`] with the variables `x, y, z, w, t`, divisions
/// by expressions in `t` only. As in [`parse_quadric`](super::parse_quadric), a form
/// that uses `w` must be homogeneous of degree 2 in `x, y, z, w`; one that does not is
/// an affine equation in `x, y, z`, homogenised with `w`; and a form of degree 1 in
/// `x, y, z, w` (`z - t`, `x - t*w`) is a moving plane `ℓ(t)`, read as its double plane
/// `ℓ(t)²`.
///
/// # Errors
/// - as [`parse_rational_function`] ([`Error::Syntax`] for a division by an expression in
///   `x, y, z, w`);
/// - [`Error::Degree`] naming a term of degree above 2 in `x, y, z, w`, or, in a form
///   using `w`, of another degree than the others;
/// - [`Error::Limit`] if the coefficients have more than [`MAX_MOVING_MATRIX_BITS`] bits;
/// - [`Error::ZeroQuadric`] if the form is zero.
///
/// # Examples
/// ```
/// use qsic::io::{moving_matrix_from_polynomial, moving_matrix_from_rows};
///
/// let m = moving_matrix_from_polynomial("x^2 + t*y^2 - (1+t^2)/(1-t)*z*w")?;
/// // The entry of z·w is −(1 + t²)/(2 − 2t): the common denominator is 2(t − 1).
/// assert_eq!(m.denominator(), &qsic_algebra::Poly::from_i64s(&[-2, 2]));
/// assert_eq!(m.numerators()[2][3], qsic_algebra::Poly::from_i64s(&[1, 0, 1]));
/// let half = "(1+t^2)/(2t-2)";
/// let rows = [["1", "0", "0", "0"], ["0", "t", "0", "0"], ["0", "0", "0", half], ["0", "0", half, "0"]];
/// assert_eq!(moving_matrix_from_rows(&rows.map(|r| r.to_vec()))?, m);
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn moving_matrix_from_polynomial(text: &str) -> Result<MovingMatrix, Error> {
    let grammar = Grammar {
        variables: &[
            Variable::X,
            Variable::Y,
            Variable::Z,
            Variable::W,
            Variable::T,
        ],
        denominator_variables: &[Variable::T],
        quadric: false,
    };
    let f = read(text, &grammar)?;
    check_moving_size(size_in_bits(f.numerator()) + size_in_bits(f.denominator()))?;
    if f.numerator().is_zero() {
        return Err(Error::ZeroQuadric);
    }
    let t = Variable::T.index();
    // A plane ℓ(t) = n/d is the double plane ℓ(t)² = n²/d².
    let (form, denominator) = match form_in_xyzw(f.numerator())? {
        XyzwForm::Quadric(form) => (form.into_owned(), f.denominator().clone()),
        XyzwForm::Plane(l) => {
            let (n, d) = (square_of_plane(&l)?, f.denominator() * f.denominator());
            check_moving_size(size_in_bits(&n) + size_in_bits(&d))?;
            (n, d)
        }
    };
    let form = form
        .quadratic_form(&[0, 1, 2, 3])
        .ok_or_else(|| Error::Degree {
            message: "a quadric is a form of degree 2".into(),
        })?;
    let numerators = std::array::from_fn(|i| std::array::from_fn(|j| dense(&form[i][j], t)));
    Ok(canonical(numerators, integer_poly(&denominator, t)))
}

/// A moving quadric from a symmetric matrix of polynomials in `t` with rational
/// coefficients over a nonzero denominator, `A(t) = entries(t) / denominator(t)`, put in
/// canonical form ([`MovingMatrix`]): the builder of the readers, for matrices computed
/// rather than read (a quadric under a rigid motion, [`crate::motion::rigid`]).
///
/// # Errors
/// - [`Error::NotSymmetric`] if `entries[i][j] ≠ entries[j][i]` (the texts are the two
///   polynomials);
/// - [`Error::ZeroQuadric`] if every entry is zero, [`Error::Algebra`] if the denominator
///   is;
/// - [`Error::Limit`] if the coefficients have more than [`MAX_MOVING_MATRIX_BITS`] bits.
///
/// # Examples
/// ```
/// use qsic::io::{moving_matrix_from_polynomial, moving_matrix_from_polys};
/// use qsic_algebra::{Poly, RBig};
///
/// let c = |v: &[i64]| Poly::new(v.iter().map(|&k| RBig::from(k)).collect());
/// let mut m: [[Poly<RBig>; 4]; 4] = Default::default();
/// (m[0][0], m[1][1], m[2][2]) = (c(&[1]), c(&[1]), c(&[1]));
/// (m[0][3], m[3][0], m[3][3]) = (c(&[0, -1]), c(&[0, -1]), c(&[-1, 0, 1]));
/// let moved = moving_matrix_from_polys(&m, &c(&[2]))?;
/// assert_eq!(moved.numerators(), moving_matrix_from_polynomial("(x - t)^2 + y^2 + z^2 - 1")?.numerators());
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn moving_matrix_from_polys(
    entries: &[[Poly<RBig>; 4]; 4],
    denominator: &Poly<RBig>,
) -> Result<MovingMatrix, Error> {
    for i in 0..4 {
        for j in i + 1..4 {
            if entries[i][j] != entries[j][i] {
                return Err(Error::NotSymmetric {
                    row: i,
                    col: j,
                    a: excerpt(&entries[i][j].to_string().replace('x', "t")),
                    b: excerpt(&entries[j][i].to_string().replace('x', "t")),
                });
            }
        }
    }
    if entries.iter().flatten().all(Poly::is_zero) {
        return Err(Error::ZeroQuadric);
    }
    if denominator.is_zero() {
        return Err(Error::Algebra(
            "a moving matrix over the zero denominator".into(),
        ));
    }
    use dashu_int::ops::BitTest;
    let rational_bits = |c: &RBig| c.numerator().bit_len() + c.denominator().bit_len();
    let size = entries
        .iter()
        .flatten()
        .chain(std::iter::once(denominator))
        .flat_map(|p| p.coeffs())
        .map(rational_bits)
        .sum();
    check_moving_size(size)?;
    // entries / denominator = (s·entries) / P with P = s·denominator in ℤ[t]
    let (d, s) = Poly::from_rational(denominator);
    let m = std::array::from_fn(|i| {
        std::array::from_fn(|j| entries[i][j].coeffs().iter().map(|c| c * &s).collect())
    });
    Ok(canonical(m, d))
}

/// Bits of all the coefficients of `p`.
fn size_in_bits(p: &MPoly) -> usize {
    p.terms().iter().map(|(_, c)| bits(c)).sum()
}

fn check_moving_size(size: usize) -> Result<(), Error> {
    if size > MAX_MOVING_MATRIX_BITS {
        return Err(Error::Limit {
            what: format!("{size} bits of coefficients in a moving matrix"),
            limit: MAX_MOVING_MATRIX_BITS,
        });
    }
    Ok(())
}

/// The dense coefficients in `t` of a polynomial in `t` alone.
fn dense(p: &MPoly, t: usize) -> Vec<RBig> {
    // Every reader caller allows no other variable here.
    p.to_univariate(t).unwrap_or_default()
}

/// A polynomial in `t` with integer coefficients (a denominator of a
/// [`RationalFunction`]) as a [`Poly`].
fn integer_poly(p: &MPoly, t: usize) -> Poly {
    Poly::new(dense(p, t).into_iter().map(|c| c.into_parts().0).collect())
}

/// `a · b` for a rational polynomial `a` and an integer one `b`, dense, lowest first.
fn rational_times(a: &[RBig], b: &Poly) -> Vec<RBig> {
    let b = b.coeffs();
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut out = vec![RBig::ZERO; a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * RBig::from(y.clone());
        }
    }
    out
}

/// The canonical [`MovingMatrix`] of `m / d` (see there), for `m ≠ 0` and `d ≠ 0`.
fn canonical(m: [[Vec<RBig>; 4]; 4], d: Poly) -> MovingMatrix {
    // Clear the denominators of the coefficients of m: A = M₀/d₀.
    let mut lcm = UBig::ONE;
    for c in m.iter().flatten().flatten() {
        let den = c.denominator();
        if !den.is_one() {
            let g = dashu_int::ops::Gcd::gcd(&lcm, den);
            lcm = &lcm / g * den;
        }
    }
    let lcm = IBig::from(lcm);
    let integer = |p: &Vec<RBig>| {
        Poly::new(
            p.iter()
                .map(|c| c.numerator() * (&lcm / IBig::from(c.denominator().clone())))
                .collect(),
        )
    };
    let mut numerators: [[Poly; 4]; 4] =
        std::array::from_fn(|i| std::array::from_fn(|j| integer(&m[i][j])));
    let denominator = d.scale(&lcm);
    // g: the primitive gcd of the entries (positive leading coefficient), and their
    // common integer content c, divided out of M₀: A = c·g·M / d₀.
    let mut g = Poly::zero();
    let mut content = IBig::ZERO;
    for p in numerators.iter().flatten() {
        if !(g.degree() == Some(0) && content.is_one()) {
            g = g.gcd(p);
            content = qsic_algebra::int_gcd(&content, &p.content());
        }
    }
    // m ≠ 0: g is a nonzero primitive polynomial and c a positive integer.
    if g.degree().unwrap_or(0) > 0 || !content.is_one() {
        let divisor = g.scale(&content);
        for p in numerators.iter_mut().flatten() {
            // Gauss: the primitive g divides each entry in ℤ[t], and c its content.
            *p = p.div_exact(&divisor).unwrap_or_else(|| p.clone());
        }
    }
    // Cancel the roots g shares with d₀, then the integer contents of c·g and d₀, and
    // give d a positive leading coefficient (the sign goes into M).
    let shared = g.gcd(&denominator);
    let (g, denominator) = if shared.degree().unwrap_or(0) > 0 {
        (
            g.div_exact(&shared).unwrap_or(g),
            denominator.div_exact(&shared).unwrap_or(denominator),
        )
    } else {
        (g, denominator)
    };
    let mut e = denominator.content();
    if denominator.leading() < IBig::ZERO {
        e = -e;
    }
    let k = qsic_algebra::int_gcd(&content, &e);
    let (p, q) = (&content / &k, &e / &k);
    let negative = q < IBig::ZERO;
    let (p, q) = if negative { (p, -q) } else { (p, q) };
    let denominator = divide_exactly(&denominator, &e).scale(&q);
    if negative {
        for p in numerators.iter_mut().flatten() {
            *p = -&*p;
        }
    }
    MovingMatrix {
        numerators,
        factor: g.scale(&p),
        denominator,
    }
}

/// `p / k` for an integer `k` dividing every coefficient.
fn divide_exactly(p: &Poly, k: &IBig) -> Poly {
    Poly::new(p.coeffs().iter().map(|c| c / k).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rows(m: [[&str; 4]; 4]) -> Vec<Vec<String>> {
        m.iter()
            .map(|r| r.iter().map(|s| s.to_string()).collect())
            .collect()
    }

    fn q(n: i64, d: u64) -> RBig {
        RBig::from_parts(IBig::from(n), UBig::from(d))
    }

    #[test]
    fn denominators_are_cleared_by_their_lcm() {
        let m = moving_matrix_from_rows(&rows([
            ["1/(t-1)", "0", "0", "0"],
            ["0", "1/(t+1)", "0", "0"],
            ["0", "0", "t/(2t^2 - 2)", "0"],
            ["0", "0", "0", "-1/2"],
        ]))
        .expect("a valid moving matrix");
        // lcm = t² − 1; M = diag(2(t+1), 2(t−1), t, −(t² − 1)) after clearing the halves.
        assert_eq!(m.denominator(), &Poly::from_i64s(&[-2, 0, 2]));
        let n = m.numerators();
        assert_eq!(n[0][0], Poly::from_i64s(&[2, 2]));
        assert_eq!(n[1][1], Poly::from_i64s(&[-2, 2]));
        assert_eq!(n[2][2], Poly::from_i64s(&[0, 1]));
        assert_eq!(n[3][3], Poly::from_i64s(&[1, 0, -1]));
        assert_eq!(m.at(&RBig::ONE), None);
        let at3 = m.at(&q(3, 1)).expect("d(3) ≠ 0");
        assert_eq!((at3[0][0].clone(), at3[2][2].clone()), (q(1, 2), q(3, 16)));
        // At the pole t = 1 the quadric is the limit: M(1) = diag(4, 0, 1, 0).
        let q1 = m.quadric_at(&RBig::ONE).expect("M(1) ≠ 0");
        assert_eq!(
            q1,
            Quadric::from_integers([[4, 0, 0, 0], [0; 4], [0, 0, 1, 0], [0; 4]]).expect("valid")
        );
    }

    #[test]
    fn common_factors_cancel() {
        // Every entry has the factor (t − 2)/(t − 2): nothing is left of it.
        let m = moving_matrix_from_rows(&rows([
            ["(t-2)/(t^2-4)", "0", "0", "0"],
            ["0", "(t^2 - 4)/(t^2 - 4)", "0", "0"],
            ["0", "0", "0", "0"],
            ["0", "0", "0", "0"],
        ]))
        .expect("valid");
        assert_eq!(m.denominator(), &Poly::from_i64s(&[2, 1]));
        assert_eq!(m.numerators()[0][0], Poly::from_i64s(&[1]));
        assert_eq!(m.numerators()[1][1], Poly::from_i64s(&[2, 1]));
        // A constant matrix: integer entries over an integer denominator, without a common factor.
        let c = moving_matrix_from_rows(&rows([
            ["1/2", "1/3", "0", "0"],
            ["1/3", "0", "0", "0"],
            ["0"; 4],
            ["0"; 4],
        ]))
        .expect("valid");
        assert_eq!(c.denominator(), &Poly::from_i64s(&[6]));
        assert_eq!(c.numerators()[0][0], Poly::from_i64s(&[3]));
        assert_eq!(c.numerators()[0][1], Poly::from_i64s(&[2]));
    }

    /// A factor common to all entries is cleared by every reader, so the quadric at one of
    /// its roots is the limit, never the zero form; `A(t)` keeps it.
    #[test]
    fn a_factor_common_to_all_entries_is_cleared() {
        let m = moving_matrix_from_polynomial("t*x^2 + t*y^2 + t*z^2 - t").expect("valid");
        let sphere = moving_matrix_from_polynomial("x^2 + y^2 + z^2 - 1").expect("valid");
        assert_eq!(m.numerators(), sphere.numerators());
        assert_eq!(m.factor(), &Poly::from_i64s(&[0, 1]));
        assert_eq!(m.denominator(), &Poly::from_i64s(&[1]));
        assert_eq!(m.quadric_at(&RBig::ZERO), sphere.quadric_at(&RBig::ZERO));
        assert_eq!(m.at(&RBig::ZERO).map(|a| a[0][0].clone()), Some(RBig::ZERO));
        assert_eq!(m.at(&q(3, 1)).map(|a| a[3][3].clone()), Some(q(-3, 1)));
        let rows = moving_matrix_from_rows(&rows([
            ["t", "0", "0", "0"],
            ["0", "t", "0", "0"],
            ["0", "0", "t", "0"],
            ["0", "0", "0", "-t"],
        ]));
        assert_eq!(rows, Ok(m));
        // −2(t² − 1)/(3(t − 1)): the factor −2(t + 1)/3 and the sign in M, d positive.
        let m = moving_matrix_from_polynomial("(2 - 2t^2)/(3t - 3)*(x^2 - y^2)").expect("valid");
        assert_eq!(m.factor(), &Poly::from_i64s(&[2, 2]));
        assert_eq!(m.denominator(), &Poly::from_i64s(&[3]));
        assert_eq!(m.numerators()[0][0], Poly::from_i64s(&[-1]));
        assert_eq!(m.at(&q(2, 1)).map(|a| a[0][0].clone()), Some(q(-2, 1)));
        // (t − 1)²·A over (t − 1): the shared root cancels, the rest stays in the factor.
        let m = moving_matrix_from_polynomial("(t-1)^2/(t-1)/(t+1)*x^2").expect("valid");
        assert_eq!(
            (m.factor(), m.denominator()),
            (&Poly::from_i64s(&[-1, 1]), &Poly::from_i64s(&[1, 1]))
        );
    }

    #[test]
    fn errors_name_the_entry() {
        let mut m = [["0"; 4]; 4];
        m[0][0] = "1";
        m[1][2] = "1/(1+t)";
        m[2][1] = "2/(2+2t)";
        assert!(moving_matrix_from_rows(&rows(m)).is_ok());
        m[2][1] = "1/(1-t)";
        assert_eq!(
            moving_matrix_from_rows(&rows(m)),
            Err(Error::NotSymmetric {
                row: 1,
                col: 2,
                a: "1/(1+t)".into(),
                b: "1/(1-t)".into()
            })
        );
        m[2][1] = "1/(x+t)";
        match moving_matrix_from_rows(&rows(m)) {
            Err(Error::Entry {
                row: 2,
                col: 1,
                source,
            }) => assert_eq!(
                *source,
                Error::UnknownVariable {
                    name: "x".into(),
                    column: 4,
                    allowed: "t".into()
                }
            ),
            other => panic!("{other:?}"),
        }
        m[2][1] = "1/(t-t)";
        assert!(matches!(
            moving_matrix_from_rows(&rows(m)),
            Err(Error::Entry { row: 2, col: 1, .. })
        ));
        assert_eq!(
            moving_matrix_from_rows(&rows([["0/(t+1)"; 4]; 4])),
            Err(Error::ZeroQuadric)
        );
        assert!(matches!(
            moving_matrix_from_rows(&vec![vec!["t"; 4]; 3]),
            Err(Error::Shape { rows: 3, .. })
        ));
        // Distinct denominators whose lcm has degree above MAX_DEGREE.
        let wide: Vec<Vec<String>> = (0..4)
            .map(|i: usize| {
                (0..4)
                    .map(|j: usize| format!("1/(t^7 - {})", 1 + i.min(j) * 4 + i.max(j)))
                    .collect()
            })
            .collect();
        assert!(matches!(
            moving_matrix_from_rows(&wide),
            Err(Error::Limit { .. })
        ));
        let huge = format!("{}t", "9".repeat(9000));
        let many = [[huge.as_str(); 4]; 4];
        assert!(matches!(
            moving_matrix_from_rows(&rows(many)),
            Err(Error::Limit { .. })
        ));
    }

    #[test]
    fn polynomial_form_errors() {
        let table: &[(&str, &str)] = &[
            ("x^3*t + y^2", "term 'x^3*t' has degree 3 in x, y, z, w"),
            ("x^2 + t*w", "term 'w*t' has degree 1; a form in x,y,z,w"),
            ("x*w + 1/(1+t)", "term '1' has degree 0; a form in x,y,z,w"),
        ];
        for (text, want) in table {
            match moving_matrix_from_polynomial(text) {
                Err(Error::Degree { message }) => {
                    assert!(message.starts_with(want), "{text:?}: {message}")
                }
                other => panic!("{text:?}: {other:?}"),
            }
        }
        // Affine: t·x is t·x·w, so A[0][3] = t/2.
        let affine = moving_matrix_from_polynomial("x^2 + t*x").expect("an affine form");
        assert_eq!(affine.numerators()[0][3], Poly::from_i64s(&[0, 1]));
        assert_eq!(affine.numerators()[0][0], Poly::from_i64s(&[2]));
        // Degree 1 in x, y, z, w: the double plane ℓ(t)², affine or homogeneous.
        let square = moving_matrix_from_polynomial("(z - t)^2").expect("a double plane");
        for plane in ["z - t", "z - t*w", "(z - t)*(1 + t^2)/(1 + t^2)"] {
            assert_eq!(
                moving_matrix_from_polynomial(plane),
                Ok(square.clone()),
                "{plane}"
            );
        }
        assert_eq!(
            moving_matrix_from_polynomial("x/(1 - t)"),
            moving_matrix_from_polynomial("x^2/(1 - t)^2")
        );
        assert!(matches!(
            moving_matrix_from_polynomial("x + t*w + 1"),
            Err(Error::Degree { .. })
        ));
        match moving_matrix_from_polynomial("x^2 + y/(x - t)") {
            Err(Error::Syntax { column: 8, message }) => assert_eq!(
                message,
                "can only divide by an expression in t, not by one in x, y, z, w"
            ),
            other => panic!("{other:?}"),
        }
        assert_eq!(
            moving_matrix_from_polynomial("t*x^2 - x^2*t"),
            Err(Error::ZeroQuadric)
        );
    }
}

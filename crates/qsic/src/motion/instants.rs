//! Candidate instants of a moving pencil: polynomials in `t` whose real roots contain every
//! instant where the class of `λA(t) − μB(t)` can change.
//!
//! Everything is a binary form in `(λ, μ)` over `ℤ[t]`, stored as its chart `μ = 1` (a
//! [`Poly<Poly>`], `ℤ[t][λ]`) with a formal degree, so a root at `λ = ∞` is an ordinary root
//! and resultants are taken with the formal degrees (Sylvester matrices): they vanish at `t₀`
//! exactly when the specialised forms share a root in `ℙ¹` (or one of them vanishes).
//!
//! **Work units.** Every function spends the caller's [`Budget`]: gcds over `ℤ[t]` per step
//! ([`Poly::gcd_within`]), gcds over `ℚ(t)` per step of their remainder sequence
//! ([`tprem_units`]), and each determinant by its route ([`det_within`]): Bareiss' elimination
//! its estimate ([`bareiss_units`]) before it starts, so a small budget stops before a long
//! elimination rather than after it; the modular route one prime at a time as it runs.
//!
//! **Determinants.** Every determinant over `ℤ[t]` of the motion stages (the Sylvester
//! matrices of the resultants and subresultants, the minors of `[M_A; M_B]`) goes through
//! [`det_within`], the one dispatch point: evaluation, interpolation and remaindering modulo
//! 61-bit primes ([`det_modular_within`]) where its units are fewer than Bareiss', else
//! Bareiss; [`DeterminantRoute::Bareiss`] forces the reference (the tests hold the two
//! routes equal).

use qsic_algebra::budget::{product_units, Budget, Exhausted};
use qsic_algebra::linalg::minors::det_bareiss;
use qsic_algebra::linalg::modular::{
    det_modular_within, modular_units, squarefree_by_specialisation,
};
use qsic_algebra::{IBig, Poly, Ring};

/// `ℤ[t][λ]`.
pub(crate) type TPoly = Poly<Poly>;

/// A binary form over `ℤ[t]`: its chart and formal degree (`degree ≥ deg chart`).
#[derive(Clone, Debug)]
pub(crate) struct Form {
    pub chart: TPoly,
    pub degree: usize,
}

impl Form {
    /// The coefficients of `λ^i μ^(d−i)`, `i = 0..=d` (trailing zeros kept).
    fn coefficients(&self) -> Vec<Poly> {
        (0..=self.degree).map(|i| self.chart.coeff(i)).collect()
    }
}

/// The gcd of the coefficients (polynomials in `t`) of `p` in `ℤ[t]`, integer content
/// included, with positive leading coefficient; zero for `p = 0`.
pub(crate) fn t_content(p: &TPoly, budget: &Budget) -> Result<Poly, Exhausted> {
    let mut g = Poly::zero();
    for c in p.coeffs() {
        if g.degree() != Some(0) {
            g = g.gcd_within(c, budget)?;
        }
    }
    if g.is_zero() {
        return Ok(g);
    }
    // the gcd of the integer contents, as the content of the polynomial they form
    let k = Poly::new(p.coeffs().iter().map(Poly::content).collect()).content();
    Ok(g.primitive_part().scale(&k))
}

/// `p` divided by its `t`-content and by the sign of its leading coefficient's leading
/// coefficient: primitive over `ℤ[t]`.
pub(crate) fn t_primitive(p: &TPoly, budget: &Budget) -> Result<TPoly, Exhausted> {
    let c = t_content(p, budget)?;
    if c.is_zero() {
        return Ok(p.clone());
    }
    let mut c = c;
    if p.leading().leading() < IBig::ZERO {
        c = c.neg();
    }
    for v in p.coeffs() {
        budget.spend(tpoly_product_units(v, &c))?;
    }
    Ok(p.map(|v| {
        v.div_exact(&c)
            .expect("the content divides every coefficient")
    }))
}

/// A gcd over `ℚ(t)` of two polynomials in `λ`, primitive over `ℤ[t]`.
pub(crate) fn gcd_t(a: &TPoly, b: &TPoly, budget: &Budget) -> Result<TPoly, Exhausted> {
    t_primitive(&a.gcd_domain_within(b, tprem_units, budget)?, budget)
}

/// The units of a product of two polynomials in `t` (schoolbook on the terms, the
/// coefficients' products by [`product_units`]).
pub(crate) fn tpoly_product_units(a: &Poly, b: &Poly) -> u64 {
    let terms = (a.degree().unwrap_or(0) as u64 + 1) * (b.degree().unwrap_or(0) as u64 + 1);
    terms.saturating_mul(product_units(a.max_bits(), b.max_bits()))
}

/// The largest degree in `t` and the largest coefficient size in bits of the coefficients
/// of a polynomial in `λ` over `ℤ[t]`.
fn t_sizes(p: &TPoly) -> (usize, usize) {
    p.coeffs().iter().fold((0, 0), |(d, b), c| {
        (d.max(c.degree().unwrap_or(0)), b.max(c.max_bits()))
    })
}

/// The units of one step of the subresultant sequence over `ℤ[t]` on `(a, b)`,
/// `deg_λ a ≥ deg_λ b`: `(δ + 2)(deg_λ b + 1)` products of polynomials in `t` of the sizes
/// of the two (the pseudo-remainder and its exact division).
pub(crate) fn tprem_units(a: &TPoly, b: &TPoly) -> u64 {
    let (m, n) = (a.degree().unwrap_or(0), b.degree().unwrap_or(0));
    let ((da, ba), (db, bb)) = (t_sizes(a), t_sizes(b));
    let delta = m.saturating_sub(n);
    let products = (delta as u64 + 2) * (n as u64 + 1);
    // the pseudo-remainder multiplies by lc(b)^(δ+1): its sizes grow by that factor
    let (dr, br) = (da + (delta + 1) * db, ba + (delta + 1) * bb);
    let terms = (dr as u64 + 1) * (db as u64 + 1);
    products
        .saturating_mul(terms)
        .saturating_mul(product_units(br, bb))
}

/// The estimated units of Bareiss' elimination on a square matrix over `ℤ[t]` whose
/// entries have degree ≤ `d` in `t` and coefficients of ≤ `b` bits: step `k` updates
/// `(n − k)²` entries by two products and one exact division of polynomials of degree
/// ≤ `k·d` whose coefficients have ≤ `k·b′` bits (`b′ = b + ⌈log₂(n(d + 1))⌉`, Hadamard's
/// bound on a `k × k` minor), each `(k·d + 1)²·product_units(k·b′, k·b′)`.
pub(crate) fn bareiss_units(rows: &[Vec<Poly>]) -> u64 {
    let n = rows.len();
    let (d, b) = rows.iter().flatten().fold((0, 0), |(d, b), c| {
        (d.max(c.degree().unwrap_or(0)), b.max(c.max_bits()))
    });
    let b = b + (usize::BITS - (n * (d + 1)).leading_zeros()) as usize;
    let mut units = 0u64;
    for k in 1..n {
        let entries = ((n - k) * (n - k)) as u64;
        let terms = ((k * d + 1) * (k * d + 1)) as u64;
        let one = terms.saturating_mul(product_units(k * b, k * b));
        units = units.saturating_add(entries.saturating_mul(3).saturating_mul(one));
    }
    units.max(n as u64)
}

/// How the determinants over `ℤ[t]` of a motion are computed ([`det_within`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum DeterminantRoute {
    /// The cheaper by the two estimates: modular ([`det_modular_within`]) where its units
    /// ([`modular_units`]) are fewer than Bareiss' ([`bareiss_units`]), else Bareiss.
    #[default]
    Fastest,
    /// The modular route always (for the tests that hold it equal to the reference).
    Modular,
    /// Bareiss' fraction-free elimination always: the reference.
    Bareiss,
}

/// The determinant of a square matrix over `ℤ[t]`, the one dispatch point (module docs):
/// by `route`, spending its units — Bareiss its estimate before it starts, the modular route
/// one prime at a time.
pub(crate) fn det_within(
    rows: Vec<Vec<Poly>>,
    route: DeterminantRoute,
    budget: &Budget,
) -> Result<Poly, Exhausted> {
    let bareiss = bareiss_units(&rows);
    let modular = match route {
        DeterminantRoute::Modular => true,
        // below 3×3 elimination is a few products: nothing to gain
        DeterminantRoute::Fastest => rows.len() >= 3 && modular_units(&rows) < bareiss,
        DeterminantRoute::Bareiss => false,
    };
    if modular {
        return det_modular_within(&rows, budget);
    }
    budget.spend(bareiss)?;
    Ok(det_bareiss(rows))
}

/// Square-free decomposition over `ℚ(t)` of a nonzero `f ∈ ℤ[t][λ]`: pairwise coprime,
/// square-free, `ℤ[t]`-primitive factors of positive degree in `λ` with their multiplicities.
///
/// With `P₀ = f`, `P_{j+1} = gcd(P_j, P_j′) = ∏ gᵢ^max(i−j−1, 0)`, the quotients
/// `s_j = P_j/P_{j+1} = ∏_{i>j} gᵢ` give `g_{j+1} = s_j/s_{j+1}` (at most four gcds here).
pub(crate) fn squarefree_decomposition_t(
    f: &TPoly,
    budget: &Budget,
) -> Result<Vec<(TPoly, usize)>, Exhausted> {
    let primitive = t_primitive(f, budget)?;
    // generic pencils: one specialisation modulo a prime proves `f` square-free, without
    // the remainder sequence over ℤ[t]
    if squarefree_by_specialisation(&primitive, budget)? {
        return Ok(vec![(primitive, 1)]);
    }
    let mut p = vec![primitive];
    while p.last().expect("nonempty").degree().unwrap_or(0) > 0 {
        let last = p.last().expect("nonempty");
        let next = gcd_t(last, &last.derivative(), budget)?;
        p.push(next);
    }
    let mut s: Vec<TPoly> = Vec::with_capacity(p.len());
    for w in p.windows(2) {
        budget.spend(tprem_units(&w[0], &w[1]))?;
        let q = w[0].div_exact(&w[1]).expect("the gcd divides (Gauss)");
        s.push(t_primitive(&q, budget)?);
    }
    let mut out = Vec::new();
    for i in 0..s.len() {
        let g = match s.get(i + 1) {
            Some(next) => {
                budget.spend(tprem_units(&s[i], next))?;
                let q = s[i].div_exact(next).expect("nested square-free parts");
                t_primitive(&q, budget)?
            }
            None => s[i].clone(),
        };
        if g.degree().unwrap_or(0) > 0 {
            out.push((g, i + 1));
        }
    }
    Ok(out)
}

/// The resultant of two binary forms over `ℤ[t]` with their formal degrees (the Sylvester
/// determinant); `Res(F, G) = F₀^n` for `deg F = 0` and vice versa.
pub(crate) fn resultant_forms(
    f: &Form,
    g: &Form,
    route: DeterminantRoute,
    budget: &Budget,
) -> Result<Poly, Exhausted> {
    let (m, n) = (f.degree, g.degree);
    let (fc, gc) = (f.coefficients(), g.coefficients());
    if m == 0 {
        budget.spend(tpoly_product_units(&fc[0], &fc[0]).saturating_mul(n as u64))?;
        return Ok(fc[0].pow(n));
    }
    if n == 0 {
        budget.spend(tpoly_product_units(&gc[0], &gc[0]).saturating_mul(m as u64))?;
        return Ok(gc[0].pow(m));
    }
    let size = m + n;
    let mut rows = vec![vec![Poly::zero(); size]; size];
    for r in 0..n {
        for (i, c) in fc.iter().enumerate() {
            // highest power first
            rows[r][r + m - i] = c.clone();
        }
    }
    for r in 0..m {
        for (i, c) in gc.iter().enumerate() {
            rows[n + r][r + n - i] = c.clone();
        }
    }
    det_within(rows, route, budget)
}

/// The `j`-th subresultant `S_j(a, b)` over `ℤ[t]` (`deg_λ a = m`, `deg_λ b = n`,
/// `j ≤ min(m, n)`, both nonzero): the determinant polynomial of the `(m + n − 2j)`-row
/// Sylvester matrix of `λ^(n−j−1)a, …, a, λ^(m−j−1)b, …, b` — the coefficient of `λ^k` the
/// determinant of its first `m + n − 2j − 1` columns and the column of `λ^k` — as
/// [`Poly::subresultant`] lays it out, each determinant by [`det_within`].
pub(crate) fn subresultant_within(
    a: &TPoly,
    b: &TPoly,
    j: usize,
    route: DeterminantRoute,
    budget: &Budget,
) -> Result<TPoly, Exhausted> {
    let (m, n) = (a.degree().unwrap_or(0), b.degree().unwrap_or(0));
    debug_assert!(!a.is_zero() && !b.is_zero() && j <= m.min(n));
    let rows = m + n - 2 * j;
    if rows == 0 {
        return Ok(b.clone());
    }
    let width = m + n - j;
    let mut sylvester: Vec<Vec<Poly>> = Vec::with_capacity(rows);
    for (p, count) in [(a, n - j), (b, m - j)] {
        for shift in (0..count).rev() {
            let mut row = vec![Poly::zero(); width];
            for (i, v) in p.coeffs().iter().enumerate() {
                row[width - 1 - (i + shift)] = v.clone();
            }
            sylvester.push(row);
        }
    }
    let mut coeffs = Vec::with_capacity(j + 1);
    for k in 0..=j {
        let column = width - 1 - k;
        let square: Vec<Vec<Poly>> = sylvester
            .iter()
            .map(|row| {
                let mut r = row[..rows - 1].to_vec();
                r.push(row[column].clone());
                r
            })
            .collect();
        coeffs.push(det_within(square, route, budget)?);
    }
    Ok(Poly::new(coeffs))
}

/// The discriminant of a binary form of degree `d ≥ 2` up to a nonzero integer factor:
/// `Res(∂F/∂λ, ∂F/∂μ)`, which vanishes at `t₀` exactly when `F(t₀)` has a repeated root in
/// `ℙ¹` (or is zero). `None` for `d < 2` (no condition).
pub(crate) fn discriminant_form(
    f: &Form,
    route: DeterminantRoute,
    budget: &Budget,
) -> Result<Option<Poly>, Exhausted> {
    let d = f.degree;
    if d < 2 {
        return Ok(None);
    }
    let c = f.coefficients();
    let dl: Vec<Poly> = (1..=d).map(|i| c[i].scale(&IBig::from(i))).collect();
    let dm: Vec<Poly> = (0..d).map(|i| c[i].scale(&IBig::from(d - i))).collect();
    let fl = Form {
        chart: Poly::new(dl),
        degree: d - 1,
    };
    let fm = Form {
        chart: Poly::new(dm),
        degree: d - 1,
    };
    Ok(Some(resultant_forms(&fl, &fm, route, budget)?))
}

/// The entries `λ·A(t) − B(t)` of the pencil's chart.
pub(crate) fn pencil_entries(a: &[[Poly; 4]; 4], b: &[[Poly; 4]; 4]) -> [[TPoly; 4]; 4] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| Poly::new(vec![b[i][j].neg(), a[i][j].clone()]))
    })
}

/// The gcd over `ℚ(t)` of the nonzero forms of degree `k` among `minors` (`D_k`, generic):
/// its chart, `ℤ[t]`-primitive, and its multiplicity at `λ = ∞`. Zero (and `k`) if all
/// vanish.
pub(crate) fn generic_gcd(
    minors: &[TPoly],
    k: usize,
    budget: &Budget,
) -> Result<(TPoly, usize), Exhausted> {
    let mut g = TPoly::zero();
    let mut mu = k;
    for m in minors.iter().filter(|m| !m.is_zero()) {
        g = g.gcd_domain_within(m, tprem_units, budget)?;
        mu = mu.min(k - m.degree().unwrap_or(0));
    }
    Ok((t_primitive(&g, budget)?, mu))
}

/// A polynomial in `t` vanishing where the stacked `8×4` matrix `[M_A; M_B]` has a rank
/// below its generic rank `r` (where `A(t)` and `B(t)` gain a common singular point): the
/// gcd of its `r×r` minors. Constant if the rank never drops.
pub(crate) fn common_kernel_condition(
    a: &[[Poly; 4]; 4],
    b: &[[Poly; 4]; 4],
    route: DeterminantRoute,
    budget: &Budget,
) -> Result<Poly, Exhausted> {
    let rows: Vec<&[Poly; 4]> = a.iter().chain(b.iter()).collect();
    for r in (1..=4).rev() {
        let mut g = Poly::zero();
        for row_set in subsets(8, r) {
            for col_set in subsets(4, r) {
                let m: Vec<Vec<Poly>> = row_set
                    .iter()
                    .map(|&i| col_set.iter().map(|&j| rows[i][j].clone()).collect())
                    .collect();
                g = g.gcd_within(&det_within(m, route, budget)?, budget)?;
                if g.degree() == Some(0) {
                    return Ok(g);
                }
            }
        }
        if !g.is_zero() {
            return Ok(g);
        }
    }
    Ok(Poly::constant(IBig::ONE))
}

/// The `r`-element subsets of `0..n`, increasing, each increasing.
fn subsets(n: usize, r: usize) -> Vec<Vec<usize>> {
    (0u32..1 << n)
        .filter(|m| m.count_ones() as usize == r)
        .map(|m| (0..n).filter(|i| m >> i & 1 == 1).collect())
        .collect()
}

/// Why [`rank_conditions`] gave no conditions.
#[derive(Debug)]
pub(crate) enum RankConditionError {
    /// Every tried pair of combinations has a zero resultant (not expected).
    NoSeparatingCombination(String),
    /// The budget ran out.
    Exhausted(Exhausted),
}

impl From<Exhausted> for RankConditionError {
    fn from(e: Exhausted) -> Self {
        RankConditionError::Exhausted(e)
    }
}

/// Polynomials in `t` vanishing wherever the gcd of the `k×k` minors (forms of degree `k`)
/// specialised at `t₀` has more roots than the generic gcd `D_k` specialised: the quotients
/// `mⱼ/D_k` then share a root at `t₀`. Two integer combinations of the quotients share it too,
/// so their resultant vanishes there; combinations are tried until the resultant is nonzero.
/// `Err` if every tried pair has a zero resultant (not expected for coprime quotients).
pub(crate) fn rank_conditions(
    minors: &[TPoly],
    k: usize,
    route: DeterminantRoute,
    budget: &Budget,
) -> Result<Vec<Poly>, RankConditionError> {
    let nonzero: Vec<&TPoly> = minors.iter().filter(|m| !m.is_zero()).collect();
    if nonzero.is_empty() {
        return Ok(Vec::new());
    }
    let (g, mu) = generic_gcd(minors, k, budget)?;
    let e = k - g.degree().unwrap_or(0) - mu;
    let mut quotients: Vec<TPoly> = Vec::with_capacity(nonzero.len());
    for m in &nonzero {
        budget.spend(tprem_units(m, &g))?;
        quotients.push(m.div_exact(&g).expect("the gcd divides each minor (Gauss)"));
    }
    if e == 0 {
        // constants in λ: they share a "root" where they all vanish
        let mut c = Poly::zero();
        for q in &quotients {
            c = c.gcd_within(&q.coeff(0), budget)?;
        }
        return Ok(vec![c]);
    }
    let combination = |s: i64| {
        let mut acc = TPoly::zero();
        let mut w = IBig::ONE;
        for q in &quotients {
            acc = &acc + &q.map(|c| c.scale(&w));
            w *= IBig::from(s);
        }
        Form {
            chart: acc,
            degree: e,
        }
    };
    // Each pair's resultant may have extra roots (where just those two combinations meet);
    // the gcd over three pairs keeps the common ones.
    let mut g = Poly::zero();
    let mut found = 0;
    for (s1, s2) in [(1, 2), (-3, 5), (7, -2), (4, 11), (-5, -9), (13, 6)] {
        let r = resultant_forms(&combination(s1), &combination(s2), route, budget)?;
        if !r.is_zero() {
            g = g.gcd_within(&r, budget)?;
            found += 1;
            if found == 3 {
                break;
            }
        }
    }
    if found == 0 {
        return Err(RankConditionError::NoSeparatingCombination(format!(
            "no separating combination of the {k}×{k} minors"
        )));
    }
    Ok(vec![g])
}

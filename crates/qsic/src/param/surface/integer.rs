//! The machine-integer route of [`super`]: small integer points of a member (the vectors
//! with entries in {−1, 0, 1} and the rational points of the lines joining them), the ruling
//! through such a point over ℤ[√δ] generic in the integer type ([`RulingInt`]: checked
//! `i128`, or `IBig` as its reference), and the integer members and radicands the choice
//! of a member needs. `None` wherever a number would leave its type: the caller then takes
//! the exact route of [`super`].

use super::*;

/// The integer matrix `k·S` (`k > 0` the least common denominator) if its entries are below
/// `2⁴⁰` in absolute value.
pub(super) fn small_integer_matrix(s: &[[RBig; 4]; 4]) -> Option<[[i128; 4]; 4]> {
    use dashu_int::ops::Gcd;
    let mut l = IBig::ONE;
    for v in s.iter().flatten() {
        let d = IBig::from(v.denominator().clone());
        let g = IBig::from(l.clone().gcd(&d));
        l = &l / &g * d;
    }
    let bound = IBig::ONE << 40;
    let mut out = [[0i128; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            let v = &s[i][j];
            let n = v.numerator() * &l / IBig::from(v.denominator().clone());
            if n.clone() * n.signum() >= bound {
                return None;
            }
            out[i][j] = i128::try_from(&n).ok()?;
        }
    }
    Some(out)
}

/// An integer point of `XᵀMX = 0` found cheaply (`M` an integer matrix, entries below
/// `2⁴⁰`), `None` if none of the tried ones is: the vectors with entries in {−1, 0, 1}, then
/// the rational points of the lines joining two of them (`M` restricted to `P + t·Q` has
/// rational roots iff `M(P,Q)² − M(P,P)M(Q,Q)` is a square). Exact `i128` arithmetic
/// (products below `2¹²⁰`).
pub(crate) fn small_point_of(m: &[[i128; 4]; 4]) -> Option<[i128; 4]> {
    if m.iter().flatten().all(|x| x.unsigned_abs() < 1 << 24) {
        // |M(P, Q)| < 2²⁸: every product below 2⁵⁷
        let small = m.map(|row| row.map(|x| x as i64));
        return small_point_in(&small).map(|v| v.map(i128::from));
    }
    small_point_in(m)
}

/// The 40 projective classes of nonzero vectors in {−1, 0, 1}⁴ (first nonzero entry 1).
pub(super) const SMALL_VECTORS: [[i8; 4]; 40] = small_vectors();

pub(super) const fn small_vectors() -> [[i8; 4]; 40] {
    let mut out = [[0i8; 4]; 40];
    let (mut n, mut code) = (0, 0);
    while code < 81 {
        let mut v = [0i8; 4];
        let (mut c, mut i) = (code, 0);
        while i < 4 {
            v[i] = (c % 3) as i8 - 1;
            c /= 3;
            i += 1;
        }
        let mut k = 0;
        while k < 4 && v[k] == 0 {
            k += 1;
        }
        if k < 4 && v[k] == 1 {
            out[n] = v;
            n += 1;
        }
        code += 1;
    }
    out
}

/// [`small_point_of`] in `i64` or `i128` (the caller bounds the entries).
pub(super) fn small_point_in<T>(m: &[[T; 4]; 4]) -> Option<[T; 4]>
where
    T: Copy
        + Default
        + PartialEq
        + From<i8>
        + Into<i128>
        + TryFrom<i128>
        + std::ops::Add<Output = T>
        + std::ops::Sub<Output = T>
        + std::ops::Mul<Output = T>,
{
    let vs: [[T; 4]; 40] = SMALL_VECTORS.map(|v| v.map(T::from));
    let mul = |x: &[T; 4]| -> [T; 4] {
        std::array::from_fn(|i| m[i][0] * x[0] + m[i][1] * x[1] + m[i][2] * x[2] + m[i][3] * x[3])
    };
    let dot =
        |x: &[T; 4], y: &[T; 4]| -> T { x[0] * y[0] + x[1] * y[1] + x[2] * y[2] + x[3] * y[3] };
    // the first isotropic vector, else all the values of the form
    let mut diag = [T::default(); 40];
    for (k, v) in vs.iter().enumerate() {
        diag[k] = dot(v, &mul(v));
        if diag[k] == T::default() {
            return Some(*v);
        }
    }
    for p in 0..40 {
        let mp = mul(&vs[p]);
        for q in p + 1..40 {
            let spq = dot(&mp, &vs[q]);
            let Some(r) = exact_sqrt((spq * spq - diag[p] * diag[q]).into()) else {
                continue;
            };
            let r = T::try_from(r).ok()?;
            // S(P + tQ) = 0 at t = (−S(P,Q) + r)/S(Q,Q): the point S(Q,Q)·P + (r − S(P,Q))·Q
            let (a, b) = (diag[q], r - spq);
            return Some(std::array::from_fn(|i| a * vs[p][i] + b * vs[q][i]));
        }
    }
    None
}

/// Integers for the fraction-free ruling ([`ruling_through`]): `i128` with every operation
/// checked (`None` on overflow sends the caller to `IBig`), and `IBig`, which never declines.
pub(crate) trait RulingInt: Clone + PartialEq + std::fmt::Debug {
    fn from_i128(v: i128) -> Self;
    fn is_zero(&self) -> bool;
    fn add(&self, o: &Self) -> Option<Self>;
    fn sub(&self, o: &Self) -> Option<Self>;
    fn mul(&self, o: &Self) -> Option<Self>;
    /// `gcd(|self|, |o|)`.
    fn gcd(&self, o: &Self) -> Self;
    /// `self / o`, `o` dividing `self`.
    fn div_exact(&self, o: &Self) -> Self;
    /// `self mod o == 0` for `o > 0`.
    fn divisible_by(&self, o: &Self) -> bool;
    /// `√self` when `self ≥ 0` is a perfect square.
    fn exact_sqrt(&self) -> Option<Self>;
    fn is_positive(&self) -> bool;
    fn to_ibig(&self) -> IBig;
    fn to_f64(&self) -> f64;
}

impl RulingInt for i128 {
    fn from_i128(v: i128) -> i128 {
        v
    }
    fn is_zero(&self) -> bool {
        *self == 0
    }
    fn add(&self, o: &i128) -> Option<i128> {
        self.checked_add(*o)
    }
    fn sub(&self, o: &i128) -> Option<i128> {
        self.checked_sub(*o)
    }
    fn mul(&self, o: &i128) -> Option<i128> {
        // one widening product for machine words, the overflow test only past them
        if let (Ok(x), Ok(y)) = (i64::try_from(*self), i64::try_from(*o)) {
            return Some(i128::from(x) * i128::from(y));
        }
        self.checked_mul(*o)
    }
    fn gcd(&self, o: &i128) -> i128 {
        let (mut x, mut y) = (self.unsigned_abs(), o.unsigned_abs());
        while y != 0 {
            if x <= u128::from(u64::MAX) && y <= u128::from(u64::MAX) {
                // the usual case: machine words
                let (mut a, mut b) = (x as u64, y as u64);
                while b != 0 {
                    (a, b) = (b, a % b);
                }
                return i128::from(a);
            }
            (x, y) = (y, x % y);
        }
        // below 2¹²⁷ unless both are i128::MIN, which checked products never reach
        x as i128
    }
    fn div_exact(&self, o: &i128) -> i128 {
        if let (Ok(x), Ok(y)) = (i64::try_from(*self), i64::try_from(*o)) {
            if y > 0 {
                return i128::from(x / y);
            }
        }
        self / o
    }
    fn divisible_by(&self, o: &i128) -> bool {
        if let (Ok(x), Ok(y)) = (i64::try_from(*self), i64::try_from(*o)) {
            if y > 0 {
                return x % y == 0;
            }
        }
        self % o == 0
    }
    fn exact_sqrt(&self) -> Option<i128> {
        // the correction steps of `exact_sqrt` square numbers near √n (no overflow below 2¹²⁰)
        if *self >= 1 << 120 {
            return None;
        }
        exact_sqrt(*self)
    }
    fn is_positive(&self) -> bool {
        *self > 0
    }
    fn to_ibig(&self) -> IBig {
        IBig::from(*self)
    }
    fn to_f64(&self) -> f64 {
        *self as f64
    }
}

impl RulingInt for IBig {
    fn from_i128(v: i128) -> IBig {
        IBig::from(v)
    }
    fn is_zero(&self) -> bool {
        *self == IBig::ZERO
    }
    fn add(&self, o: &IBig) -> Option<IBig> {
        Some(self + o)
    }
    fn sub(&self, o: &IBig) -> Option<IBig> {
        Some(self - o)
    }
    fn mul(&self, o: &IBig) -> Option<IBig> {
        Some(self * o)
    }
    fn gcd(&self, o: &IBig) -> IBig {
        use dashu_int::ops::Gcd;
        if self.is_zero() {
            return o * o.signum();
        }
        if o.is_zero() {
            return self * self.signum();
        }
        IBig::from(self.clone().gcd(o))
    }
    fn div_exact(&self, o: &IBig) -> IBig {
        self / o
    }
    fn divisible_by(&self, o: &IBig) -> bool {
        (self % o) == IBig::ZERO
    }
    fn exact_sqrt(&self) -> Option<IBig> {
        if *self < IBig::ZERO {
            return None;
        }
        Quadratic::sqrt(self)
            .as_rational()
            .map(|r| r.numerator().clone())
    }
    fn is_positive(&self) -> bool {
        *self > IBig::ZERO
    }
    fn to_ibig(&self) -> IBig {
        self.clone()
    }
    fn to_f64(&self) -> f64 {
        IBig::to_f64(self).value()
    }
}

/// `a + b√δ` over a [`RulingInt`] (`δ` held by the caller).
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Zs<T> {
    a: T,
    b: T,
}

impl<T: RulingInt> Zs<T> {
    fn int(a: T) -> Zs<T> {
        Zs {
            a,
            b: T::from_i128(0),
        }
    }
    fn zero() -> Zs<T> {
        Zs::int(T::from_i128(0))
    }
    fn is_zero(&self) -> bool {
        self.a.is_zero() && self.b.is_zero()
    }
    fn add(&self, o: &Zs<T>) -> Option<Zs<T>> {
        Some(Zs {
            a: self.a.add(&o.a)?,
            b: self.b.add(&o.b)?,
        })
    }
    fn neg(&self) -> Option<Zs<T>> {
        let zero = T::from_i128(0);
        Some(Zs {
            a: zero.sub(&self.a)?,
            b: zero.sub(&self.b)?,
        })
    }
    fn mul(&self, o: &Zs<T>, delta: &T) -> Option<Zs<T>> {
        if self.b.is_zero() && o.b.is_zero() {
            return Some(Zs::int(self.a.mul(&o.a)?));
        }
        Some(Zs {
            a: self.a.mul(&o.a)?.add(&self.b.mul(&o.b)?.mul(delta)?)?,
            b: self.a.mul(&o.b)?.add(&self.b.mul(&o.a)?)?,
        })
    }
    fn scale(&self, k: &T) -> Option<Zs<T>> {
        Some(Zs {
            a: self.a.mul(k)?,
            b: self.b.mul(k)?,
        })
    }
    /// `a + b√δ` with `root = √δ` ([`Quadratic::sqrt`], irrational): no square test.
    fn to_quadratic_in(&self, root: &Quadratic) -> Quadratic {
        if self.b.is_zero() {
            return Quadratic::rational(RBig::from(self.a.to_ibig()));
        }
        assert!(root.as_rational().is_none(), "δ is not a square");
        Quadratic::in_field_of(
            RBig::from(self.a.to_ibig()),
            RBig::from(self.b.to_ibig()),
            root,
        )
    }
}

/// The gcd of all the integers `a`, `b` of some elements of ℤ[√δ] (zero for all zeros).
pub(super) fn content<'a, T: RulingInt + 'a>(xs: impl IntoIterator<Item = &'a Zs<T>>) -> T {
    let mut g = T::from_i128(0);
    for x in xs {
        for part in [&x.a, &x.b] {
            if !part.is_zero() && g != T::from_i128(1) {
                g = g.gcd(part);
            }
        }
    }
    g
}

/// Each element divided by `g` (a common divisor; nothing for zero or one).
pub(super) fn divide_by<T: RulingInt>(xs: &mut [Zs<T>], g: &T) {
    if g.is_zero() || *g == T::from_i128(1) {
        return;
    }
    for x in xs.iter_mut() {
        x.a = x.a.div_exact(g);
        x.b = x.b.div_exact(g);
    }
}

/// The ruling of `S` through the integer point `p` of the integer matrix `M = k·S` (`k > 0`),
/// fraction-free in ℤ[√δ], `δ` the square-free part of `det M` (one for a square): `r = Mp`,
/// the tangent plane `Kₖ = rⱼeₖ − rₖeⱼ` (`e₁`, `e₂` two of them, made primitive), the binary
/// form `sᵢⱼ = eᵢᵀMeⱼ` on them and its lines `E± = (−s₁₂ ± t√δ)·e₁ + s₁₁·e₂` with
/// `t²δ = s₁₂² − s₁₁s₂₂` (over ℚ(√det M) since that discriminant times `(pᵀMx)²` is
/// `det M·det(p, e₁, e₂, x)²`), divided by their content; `c = E₊ᵀME₋`;
/// `g₀ = c·eⱼ − (ME₋)ⱼ·E₊`, `g₁ = c·g₀ − (g₀ᵀME₊)·E₋` (orthogonal to `E₊` and `E₋`, each
/// made primitive), `ρ = pᵀMg₁`, `f = 2ρ·g₁ − (g₁ᵀMg₁)·p` (isotropic, `pᵀMf = 2ρ²`); then
/// `b = p − u·E₊` and `d = 2ρ²·E₋ + u·c·f` (`pᵀMf·c = E₊ᵀM(2ρ²E₋)`, so `bᵀMd ≡ 0`), each
/// scaled to coprime integers. `Ok(None)` when an operation overflows `T` or `δ` does not
/// give an integral `t` (only when `δ` is not `det M`'s square-free part).
///
/// # Errors
/// [`Error::Algebra`] when `p` is in the kernel, the lines are not real or not distinct (`S`
/// is not a nonsingular quadric of inertia (2, 2) through `p`).
pub(super) fn ruling_through<T: RulingInt>(
    m: &[[T; 4]; 4],
    p: &[T; 4],
    delta: &T,
) -> Result<Option<RuledParameterization>, Error> {
    let zero = T::from_i128(0);
    let one = T::from_i128(1);
    macro_rules! ck {
        ($e:expr) => {
            match $e {
                Some(v) => v,
                None => return Ok(None),
            }
        };
    }
    let mv = |x: &[T; 4]| -> Option<[T; 4]> {
        try4(|i| {
            let mut acc = T::from_i128(0);
            for k in 0..4 {
                if !x[k].is_zero() && !m[i][k].is_zero() {
                    acc = acc.add(&m[i][k].mul(&x[k])?)?;
                }
            }
            Some(acc)
        })
    };
    let idot = |x: &[T; 4], y: &[T; 4]| -> Option<T> {
        let mut acc = T::from_i128(0);
        for i in 0..4 {
            if !x[i].is_zero() && !y[i].is_zero() {
                acc = acc.add(&x[i].mul(&y[i])?)?;
            }
        }
        Some(acc)
    };
    let primitive_int = |v: [T; 4]| -> [T; 4] {
        let g = v.iter().fold(T::from_i128(0), |g, x| g.gcd(x));
        if g.is_zero() || g == T::from_i128(1) {
            v
        } else {
            v.map(|x| x.div_exact(&g))
        }
    };
    let p = primitive_int(p.clone());
    let r = ck!(mv(&p));
    let j = (0..4)
        .find(|&k| !r[k].is_zero())
        .ok_or_else(|| Error::Algebra("a point in the kernel of a nonsingular quadric".into()))?;
    let k0 = (0..4)
        .find(|&k| k != j && !p[k].is_zero())
        .ok_or_else(|| Error::Algebra("tangent plane basis".into()))?;
    let mut rest = (0..4).filter(|&k| k != j && k != k0);
    let kernel_vector = |k: usize| -> Option<[T; 4]> {
        let mut v: [T; 4] = std::array::from_fn(|_| T::from_i128(0));
        v[k] = r[j].clone();
        v[j] = T::from_i128(0).sub(&r[k])?;
        Some(primitive_int(v))
    };
    let e1 = ck!(kernel_vector(rest.next().expect("two kernel vectors")));
    let e2 = ck!(kernel_vector(rest.next().expect("two kernel vectors")));
    let (me1, me2) = (ck!(mv(&e1)), ck!(mv(&e2)));
    let (s11, s12, s22) = (
        ck!(idot(&e1, &me1)),
        ck!(idot(&e1, &me2)),
        ck!(idot(&e2, &me2)),
    );
    let zvec = |x: &[T; 4]| -> [Zs<T>; 4] { x.clone().map(Zs::int) };
    let irrational = *delta != one;
    let (mut plus, mut minus) = if s11.is_zero() {
        let two_s12 = ck!(s12.add(&s12));
        let minus: [T; 4] = ck!(try4(|i| s22.mul(&e1[i])?.sub(&two_s12.mul(&e2[i])?)));
        (zvec(&e1), zvec(&minus))
    } else {
        let disc = ck!(ck!(s12.mul(&s12)).sub(&ck!(s11.mul(&s22))));
        if !disc.is_positive() {
            return Err(Error::Algebra(
                "no real lines through a point of an inertia (2, 2) member".into(),
            ));
        }
        let root = if irrational {
            if !disc.divisible_by(delta) {
                return Ok(None);
            }
            Zs {
                a: zero.clone(),
                b: ck!(disc.div_exact(delta).exact_sqrt()),
            }
        } else {
            Zs::int(ck!(disc.exact_sqrt()))
        };
        let minus_s12 = Zs::int(ck!(zero.sub(&s12)));
        let line = |rt: &Zs<T>| -> Option<[Zs<T>; 4]> {
            let k1 = minus_s12.add(rt)?;
            try4(|i| k1.scale(&e1[i])?.add(&Zs::int(s11.mul(&e2[i])?)))
        };
        (ck!(line(&root)), ck!(line(&ck!(root.neg()))))
    };
    {
        let g = content(plus.iter().chain(minus.iter()));
        divide_by(&mut plus, &g);
        divide_by(&mut minus, &g);
    }
    let d_t = if irrational {
        delta.clone()
    } else {
        zero.clone()
    };
    // balance the parameter: |E₊| about |p| (a power of two, exact), so that u has the
    // scale of the point and the roots of s(u) are neither huge nor tiny
    let root_delta = d_t.to_f64().abs().sqrt();
    let size = |v: &[Zs<T>]| -> f64 {
        v.iter()
            .map(|x| x.a.to_f64().abs() + x.b.to_f64().abs() * root_delta)
            .fold(0.0, f64::max)
    };
    let ratio = size(&zvec(&p)) / size(&plus);
    let two = T::from_i128(2);
    let pow2 = |e: usize| -> Option<T> {
        let mut k = T::from_i128(1);
        for _ in 0..e {
            k = k.mul(&two)?;
        }
        Some(k)
    };
    if ratio.is_finite() && ratio >= 2.0 {
        let k = ck!(pow2(ratio.log2().floor() as usize));
        plus = ck!(try4(|i| plus[i].scale(&k)));
    }
    let p: [T; 4] = if ratio.is_finite() && ratio > 0.0 && ratio <= 0.5 {
        let k = ck!(pow2((1.0 / ratio).log2().floor() as usize));
        ck!(try4(|i| p[i].mul(&k)))
    } else {
        p
    };
    let zmv = |x: &[Zs<T>; 4]| -> Option<[Zs<T>; 4]> {
        try4(|i| {
            let mut acc = Zs::zero();
            for k in 0..4 {
                if !x[k].is_zero() && !m[i][k].is_zero() {
                    acc = acc.add(&x[k].scale(&m[i][k])?)?;
                }
            }
            Some(acc)
        })
    };
    let zdot = |x: &[Zs<T>; 4], y: &[Zs<T>; 4]| -> Option<Zs<T>> {
        let mut acc = Zs::zero();
        for i in 0..4 {
            if !x[i].is_zero() && !y[i].is_zero() {
                acc = acc.add(&x[i].mul(&y[i], &d_t)?)?;
            }
        }
        Some(acc)
    };
    // a·x + b·y
    let comb = |a: &Zs<T>, x: &[Zs<T>; 4], b: &Zs<T>, y: &[Zs<T>; 4]| -> Option<[Zs<T>; 4]> {
        try4(|i| a.mul(&x[i], &d_t)?.add(&b.mul(&y[i], &d_t)?))
    };
    let m_minus = ck!(zmv(&minus));
    let c = ck!(zdot(&plus, &m_minus));
    if c.is_zero() {
        return Err(Error::Algebra(
            "the two lines through a point are not distinct".into(),
        ));
    }
    let mut ej: [Zs<T>; 4] = std::array::from_fn(|_| Zs::zero());
    ej[j] = Zs::int(one.clone());
    let mut g0 = ck!(comb(&c, &ej, &ck!(m_minus[j].neg()), &plus));
    let g = content(g0.iter());
    divide_by(&mut g0, &g);
    let g0_plus = ck!(zdot(&g0, &ck!(zmv(&plus))));
    let mut g1 = ck!(comb(&c, &g0, &ck!(g0_plus.neg()), &minus));
    let g = content(g1.iter());
    divide_by(&mut g1, &g);
    let zp = zvec(&p);
    let mg1 = ck!(zmv(&g1));
    let rho = ck!(zdot(&zp, &mg1));
    let g1g1 = ck!(zdot(&g1, &mg1));
    let two_z = Zs::int(two);
    let f = ck!(comb(
        &ck!(two_z.mul(&rho, &d_t)),
        &g1,
        &ck!(g1g1.neg()),
        &zp
    ));
    let two_rho2 = ck!(two_z.mul(&ck!(rho.mul(&rho, &d_t)), &d_t));
    // b and d each scaled to coprime integers
    let mut bz: [[Zs<T>; 2]; 4] = ck!(try4(|i| Some([zp[i].clone(), plus[i].neg()?])));
    let mut dz: [[Zs<T>; 2]; 4] = ck!(try4(|i| Some([
        two_rho2.mul(&minus[i], &d_t)?,
        c.mul(&f[i], &d_t)?
    ])));
    let g = content(bz.as_flattened());
    divide_by(bz.as_flattened_mut(), &g);
    let g = content(dz.as_flattened());
    divide_by(dz.as_flattened_mut(), &g);
    // one square test for all the coefficients (`δ` is not a square when irrational)
    let root = if irrational {
        Quadratic::sqrt(&d_t.to_ibig())
    } else {
        Quadratic::zero()
    };
    let to_poly = |v: &[Zs<T>]| -> Poly<Quadratic> {
        Poly::new(v.iter().map(|x| x.to_quadratic_in(&root)).collect())
    };
    let b: PolyVector = std::array::from_fn(|i| to_poly(&bz[i]));
    let d: PolyVector = std::array::from_fn(|i| to_poly(&dz[i]));
    let delta = radicand_of(b.iter().chain(d.iter()).flat_map(|x| x.coeffs()));
    Ok(Some(RuledParameterization { b, d, delta }))
}

/// `[f(0), f(1), f(2), f(3)]`, `None` if one is.
pub(super) fn try4<X>(mut f: impl FnMut(usize) -> Option<X>) -> Option<[X; 4]> {
    Some([f(0)?, f(1)?, f(2)?, f(3)?])
}

/// [`ruling_through`] in `i128` (entries of `M` and `p` as given), falling back to `IBig`
/// when an operation overflows: the same ruling either way.
///
/// # Errors
/// As [`ruling_through`].
pub(crate) fn ruling_through_small(
    m: &[[i128; 4]; 4],
    p: &[i128; 4],
    delta: &IBig,
) -> Result<Option<RuledParameterization>, Error> {
    if let Ok(dl) = i128::try_from(delta) {
        if let Some(r) = ruling_through(m, p, &dl)? {
            return Ok(Some(r));
        }
    }
    let mb: [[IBig; 4]; 4] = std::array::from_fn(|i| std::array::from_fn(|j| IBig::from(m[i][j])));
    let pb: [IBig; 4] = std::array::from_fn(|i| IBig::from(p[i]));
    ruling_through(&mb, &pb, delta)
}

/// The entries of an integer-valued rational matrix as `i128`, `None` if one is not an
/// integer or has `2⁴⁰` or more in absolute value.
pub(crate) fn integer_entries(s: &[[RBig; 4]; 4]) -> Option<[[i128; 4]; 4]> {
    let mut out = [[0i128; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            let v = &s[i][j];
            if *v.denominator() != dashu_int::UBig::ONE {
                return None;
            }
            let n = i128::try_from(v.numerator()).ok()?;
            if n.unsigned_abs() >= 1 << 40 {
                return None;
            }
            out[i][j] = n;
        }
    }
    Some(out)
}

/// `M = n·A − d·B` for `λ = n/d` (`d > 0`): `d` times the member `λA − B`, with `d`; `None`
/// when an entry reaches `2⁴⁰` in absolute value (the bound of [`small_point_of`]).
pub(crate) fn small_member(
    a: &[[i128; 4]; 4],
    b: &[[i128; 4]; 4],
    lambda: &RBig,
) -> Option<([[i128; 4]; 4], i128)> {
    let n = i128::try_from(lambda.numerator()).ok()?;
    let d = i128::try_from(&IBig::from(lambda.denominator().clone())).ok()?;
    if n.unsigned_abs() >= 1 << 60 || d >= 1 << 60 {
        return None;
    }
    let bits = |v: u128| 128 - v.leading_zeros();
    let max = |m: &[[i128; 4]; 4]| {
        m.as_flattened()
            .iter()
            .fold(0, |acc, v| acc | v.unsigned_abs())
    };
    // |n·a| < 2¹²⁵ and |d·b| < 2¹²⁵: no overflow (the common case), else checked
    let plain = bits(n.unsigned_abs()) + bits(max(a)) <= 125
        && bits(d.unsigned_abs()) + bits(max(b)) <= 125;
    let mut out = [[0i128; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            let v = if plain {
                n * a[i][j] - d * b[i][j]
            } else {
                n.checked_mul(a[i][j])?
                    .checked_sub(d.checked_mul(b[i][j])?)?
            };
            if v.unsigned_abs() >= 1 << 40 {
                return None;
            }
            out[i][j] = v;
        }
    }
    Some((out, d))
}

/// The member `M/d` as rationals (see [`small_member`]).
pub(crate) fn member_from_small(m: &[[i128; 4]; 4], d: i128) -> [[RBig; 4]; 4] {
    let den = IBig::from(d);
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            if d == 1 {
                RBig::from(m[i][j])
            } else {
                RBig::from_parts_signed(IBig::from(m[i][j]), den.clone())
            }
        })
    })
}

/// `det M` by the Laplace expansion along the first two rows, every operation checked
/// unless the entries are below `2³⁰` (then the 2 × 2 minors are below `2⁶¹`, their
/// products below `2¹²²` and the sum of six below `2¹²⁵`).
pub(super) fn det_checked(m: &[[i128; 4]; 4]) -> Option<i128> {
    if m.as_flattened().iter().all(|v| v.unsigned_abs() < 1 << 30) {
        let minor = |r0: usize, r1: usize, c0: usize, c1: usize| {
            m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]
        };
        return Some(
            minor(0, 1, 0, 1) * minor(2, 3, 2, 3) - minor(0, 1, 0, 2) * minor(2, 3, 1, 3)
                + minor(0, 1, 0, 3) * minor(2, 3, 1, 2)
                + minor(0, 1, 1, 2) * minor(2, 3, 0, 3)
                - minor(0, 1, 1, 3) * minor(2, 3, 0, 2)
                + minor(0, 1, 2, 3) * minor(2, 3, 0, 1),
        );
    }
    let minor = |r0: usize, r1: usize, c0: usize, c1: usize| -> Option<i128> {
        m[r0][c0]
            .checked_mul(m[r1][c1])?
            .checked_sub(m[r0][c1].checked_mul(m[r1][c0])?)
    };
    let mut acc = 0i128;
    // the columns of the top minor, the complementary ones, the sign
    for (c0, c1, d0, d1, sign) in [
        (0, 1, 2, 3, 1),
        (0, 2, 1, 3, -1),
        (0, 3, 1, 2, 1),
        (1, 2, 0, 3, 1),
        (1, 3, 0, 2, -1),
        (2, 3, 0, 1, 1),
    ] {
        let t = minor(0, 1, c0, c1)?.checked_mul(minor(2, 3, d0, d1)?)?;
        acc = if sign > 0 {
            acc.checked_add(t)?
        } else {
            acc.checked_sub(t)?
        };
    }
    Some(acc)
}

/// The square-free part `f` of `n > 0` (`n = k²f`): trial division by 2, 3 and the numbers
/// `6i ± 1` while their cube stays below the cofactor (then the cofactor has at most two
/// prime factors, all above the divisors tried, and is square-free unless a perfect square);
/// [`factorize`] when that would take divisors past `2¹²`. `None` if factoring fails.
pub(crate) fn squarefree_part(n: &IBig) -> Option<IBig> {
    if *n <= IBig::ZERO {
        return None;
    }
    if let Ok(v) = u64::try_from(n) {
        if let Some(f) = squarefree_part_u64(v) {
            return Some(IBig::from(f));
        }
    }
    let f = factorize(n).ok()?;
    Some(f.squarefree_split().0.value())
}

pub(super) fn squarefree_part_u64(n: u64) -> Option<u64> {
    const LIMIT: u64 = 1 << 12;
    // divides out d; whether its exponent was odd
    fn remove(d: u64, rest: &mut u64) -> bool {
        let mut odd = false;
        while *rest % d == 0 {
            *rest /= d;
            odd = !odd;
        }
        odd
    }
    let mut rest = n;
    let mut f = 1u64;
    for d in [2, 3] {
        if remove(d, &mut rest) {
            f *= d;
        }
    }
    let mut d = 5u64;
    loop {
        for dd in [d, d + 2] {
            if dd * dd * dd > rest {
                if rest > 1 && exact_sqrt(i128::from(rest)).is_none() {
                    f *= rest;
                }
                return Some(f);
            }
            if remove(dd, &mut rest) {
                f *= dd;
            }
        }
        d += 6;
        if d > LIMIT {
            return None;
        }
    }
}

/// The radicand of the rulings of the nonsingular member `M` of inertia (2, 2) through a
/// rational point: the square-free part of `det M` (`1` when it is a square). `None` when the
/// determinant overflows `i128`, is not positive, or cannot be factored.
pub(crate) fn member_radicand(m: &[[i128; 4]; 4]) -> Option<IBig> {
    let det = det_checked(m)?;
    if det <= 0 {
        return None;
    }
    squarefree_part(&IBig::from(det))
}

/// `k·S` with integer entries, `k > 0` the least common denominator.
pub(super) fn scaled_integer_matrix(s: &[[RBig; 4]; 4]) -> Option<[[IBig; 4]; 4]> {
    use dashu_int::ops::Gcd;
    let mut l = IBig::ONE;
    for v in s.iter().flatten() {
        let d = IBig::from(v.denominator().clone());
        let g = IBig::from(l.clone().gcd(&d));
        l = &l / &g * d;
    }
    let mut out: [[IBig; 4]; 4] = Default::default();
    for i in 0..4 {
        for j in 0..4 {
            let v = &s[i][j];
            out[i][j] = v.numerator() * &l / IBig::from(v.denominator().clone());
        }
    }
    Some(out)
}

//! The simplest rational of an open interval; a rational between two isolated roots and the
//! floor of one, independent of the isolating intervals' shape.
//!
//! "Simplest" orders rationals by denominator, then by absolute numerator. In an open
//! interval the least one is unique (two of one denominator with opposite numerators would
//! put 0, denominator 1, between them), and for `0 ≤ lo` it is the interval's element of the
//! Stern–Brocot tree nearest the root, which has both the least denominator and the least
//! numerator. It is found from the continued fractions of the ends: with `n = ⌊lo⌋`, either
//! `n + 1 < hi` is the answer, or every element is `n + 1/s` with `s` in
//! `(1/(hi − n), 1/(lo − n))` and the answer is `n + 1/s` for the simplest such `s` (a loop,
//! one step per partial quotient of the answer).

use super::RootInterval;
use dashu_int::ops::DivEuclid;
use dashu_int::IBig;
use dashu_ratio::RBig;
use std::cmp::Ordering;

/// The simplest rational (least denominator, then least absolute numerator) in the open
/// interval `(lo, hi)`; `None` stands for `−∞` (as `lo`) or `+∞` (as `hi`).
///
/// # Panics
/// If `lo ≥ hi` (an empty interval).
///
/// ```
/// # use qsic_algebra::{RBig, roots::simplest_rational_in};
/// let q = |n: i64, d: u64| RBig::from_parts(n.into(), d.into());
/// assert_eq!(simplest_rational_in(Some(&q(-5, 2)), Some(&q(3, 1))), RBig::ZERO);
/// assert_eq!(simplest_rational_in(Some(&q(3, 10)), Some(&q(4, 10))), q(1, 3));
/// assert_eq!(simplest_rational_in(Some(&q(-4, 10)), Some(&q(-3, 10))), q(-1, 3));
/// assert_eq!(simplest_rational_in(Some(&q(2, 1)), None), q(3, 1));
/// assert_eq!(simplest_rational_in(None, Some(&q(-7, 2))), q(-4, 1));
/// ```
pub fn simplest_rational_in(lo: Option<&RBig>, hi: Option<&RBig>) -> RBig {
    if let (Some(l), Some(h)) = (lo, hi) {
        assert!(l < h, "simplest_rational_in: empty interval ({l}, {h})");
    }
    let parts = |v: &RBig| (v.numerator().clone(), IBig::from(v.denominator().clone()));
    match (lo, hi) {
        (Some(l), _) if l >= &RBig::ZERO => simplest_nonnegative(parts(l), hi.map(parts)),
        (_, Some(h)) if h <= &RBig::ZERO => {
            let neg = |v: &RBig| parts(&-v);
            -simplest_nonnegative(neg(h), lo.map(neg))
        }
        _ => RBig::ZERO,
    }
}

/// [`simplest_rational_in`] for `0 ≤ lo < hi`, the ends as (numerator, positive denominator):
/// in `i128` when the ends fit and no step overflows, else with big integers.
fn simplest_nonnegative(lo: (IBig, IBig), hi: Option<(IBig, IBig)>) -> RBig {
    let small = |(n, d): &(IBig, IBig)| Some((i128::try_from(n).ok()?, i128::try_from(d).ok()?));
    let machine = match &hi {
        None => small(&lo).map(|l| (l, None)),
        Some(h) => small(&lo).zip(small(h)).map(|(l, h)| (l, Some(h))),
    };
    if let Some((n, d)) = machine.and_then(|(l, h)| simplest_nonnegative_i128(l, h)) {
        return RBig::from_parts_signed(n.into(), d.into());
    }
    simplest_nonnegative_big(lo, hi)
}

/// [`simplest_nonnegative`] in checked `i128`: the answer as (numerator, denominator), `None`
/// on overflow.
fn simplest_nonnegative_i128(
    mut lo: (i128, i128),
    mut hi: Option<(i128, i128)>,
) -> Option<(i128, i128)> {
    let (mut p, mut q, mut r, mut u) = (1i128, 0i128, 0i128, 1i128);
    loop {
        let n = lo.0.div_euclid(lo.1);
        let next = n.checked_add(1)?;
        let fits = match hi {
            None => true,
            Some((hn, hd)) => next.checked_mul(hd)? < hn,
        };
        if fits {
            let num = p.checked_mul(next)?.checked_add(q)?;
            let den = r.checked_mul(next)?.checked_add(u)?;
            return Some((num, den));
        }
        let (hn, hd) = hi?;
        let new_lo = (hd, hn.checked_sub(n.checked_mul(hd)?)?);
        let rest = lo.0.checked_sub(n.checked_mul(lo.1)?)?;
        hi = (rest != 0).then_some((lo.1, rest));
        lo = new_lo;
        (p, q, r, u) = (
            p.checked_mul(n)?.checked_add(q)?,
            p,
            r.checked_mul(n)?.checked_add(u)?,
            r,
        );
    }
}

/// [`simplest_nonnegative`] with big integers.
fn simplest_nonnegative_big(mut lo: (IBig, IBig), mut hi: Option<(IBig, IBig)>) -> RBig {
    // The answer is (p·s + q)/(r·s + u) for the simplest s of the current (lo, hi).
    let (mut p, mut q, mut r, mut u) = (IBig::ONE, IBig::ZERO, IBig::ZERO, IBig::ONE);
    loop {
        let n = (&lo.0).div_euclid(&lo.1);
        let next = &n + IBig::ONE;
        // next < hi, i.e. next·hd < hn
        if hi.as_ref().is_none_or(|(hn, hd)| &next * hd < *hn) {
            return RBig::from_parts_signed(&p * &next + q, &r * &next + u);
        }
        let (hn, hd) = hi.expect("bounded: checked above");
        // s ∈ (1/(hi − n), 1/(lo − n)); lo − n = 0 makes the upper end +∞
        let new_lo = (hd.clone(), hn - &n * &hd);
        let rest = &lo.0 - &n * &lo.1;
        hi = (!rest.is_zero()).then(|| (lo.1.clone(), rest));
        lo = new_lo;
        (p, q, r, u) = (&p * &n + &q, p, &r * &n + &u, r);
    }
}

/// Which of the two roots [`simplest_between_roots`] asks about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Bound {
    /// The root on the left.
    Left,
    /// The root on the right.
    Right,
}

/// A rational strictly between two reals `α < β` chosen by `pick` independently of how they
/// are isolated: each is given by an interval that isolates it as a root (`None`: `α = −∞`
/// or `β = +∞`; an exact interval for a known rational), and `side(b, q)` compares `q` with
/// the root `b` (`q.cmp(α)`) for a rational `q` strictly inside that root's open interval,
/// typically from the sign of its polynomial there.
///
/// `pick(lo, hi)` chooses a rational of the open interval `(lo, hi)` (`None` unbounded) such
/// that whenever `pick(L, H)` lies in `(l, h) ⊆ (L, H)`, `pick(l, h) = pick(L, H)`, and
/// that a bounded interval holds finitely many picks of its subintervals: the simplest
/// rational ([`simplest_rational_in`]) or the leftmost dyadic of least denominator
/// ([`simplest_between`](super::simplest_between)). The answer is `pick(α, β)`: the pick `q`
/// of `(lo(α), hi(β))` is the answer unless it falls in one of the open intervals on the
/// wrong side of its root; then the search interval shrinks to `q` on that side and goes on.
///
/// ```
/// # use qsic_algebra::{Poly, RBig, roots::{isolate_real_roots, between_roots, simplest_rational_in, Bound, RootInterval}};
/// # use std::cmp::Ordering;
/// // x² − 2: between −√2 and √2 lies 0; between √2 and +∞, 2
/// let p = Poly::from_i64s(&[-2, 0, 1]);
/// let r = isolate_real_roots(&p);
/// let side = |iv: &RootInterval, q: &RBig| -> Ordering {
///     let (at_q, at_lo) = (p.sign_at(q), p.sign_at(iv.lo()));
///     if at_q.is_zero() { Ordering::Equal } else if at_q == at_lo { Ordering::Less } else { Ordering::Greater }
/// };
/// let pick = |a: Option<&RootInterval>, b: Option<&RootInterval>| {
///     between_roots(a, b, simplest_rational_in, |s, q| side(if s == Bound::Left { a.unwrap() } else { b.unwrap() }, q))
/// };
/// assert_eq!(pick(Some(&r[0]), Some(&r[1])), RBig::ZERO);
/// assert_eq!(pick(Some(&r[1]), None), RBig::from(2));
/// // the wide interval (0, 100) of √2 gives the same answer
/// let wide = RootInterval::Open(RBig::ZERO, RBig::from(100));
/// assert_eq!(between_roots(Some(&wide), None, simplest_rational_in, |_, q| side(&wide, q)), RBig::from(2));
/// ```
pub fn between_roots(
    left: Option<&RootInterval>,
    right: Option<&RootInterval>,
    pick: impl Fn(Option<&RBig>, Option<&RBig>) -> RBig,
    mut side: impl FnMut(Bound, &RBig) -> Ordering,
) -> RBig {
    // lo ≤ α < left_hi and right_lo < β ≤ hi throughout; a pick on the wrong side of a root
    // also halves that root's interval, so that wide intervals cost O(log) picks
    let mut lo = left.map(|iv| iv.lo().clone());
    let mut hi = right.map(|iv| iv.hi().clone());
    let mut left_hi = match left {
        Some(RootInterval::Open(_, h)) => Some(h.clone()),
        _ => None,
    };
    let mut right_lo = match right {
        Some(RootInterval::Open(l, _)) => Some(l.clone()),
        _ => None,
    };
    let half = RBig::from_parts_signed(IBig::ONE, IBig::from(2));
    loop {
        let q = pick(lo.as_ref(), hi.as_ref());
        // q > lo ≥ lo(α): inside α's interval iff below its upper end
        if let Some(h) = &mut left_hi {
            if &q < h && side(Bound::Left, &q) != Ordering::Greater {
                let m = (&q + &*h) * &half;
                if side(Bound::Left, &m) == Ordering::Greater {
                    *h = m;
                    lo = Some(q);
                } else {
                    lo = Some(m);
                }
                continue;
            }
        }
        if let Some(l) = &mut right_lo {
            if &q > l && side(Bound::Right, &q) != Ordering::Less {
                let m = (&*l + &q) * &half;
                if side(Bound::Right, &m) == Ordering::Less {
                    *l = m;
                    hi = Some(q);
                } else {
                    hi = Some(m);
                }
                continue;
            }
        }
        return q;
    }
}

/// `⌊α⌋` for the root `α` isolated by `iv`, `side(q)` comparing a rational `q` inside the
/// open interval with `α` (as in [`between_roots`]): a binary search over the integers of
/// the interval.
///
/// ```
/// # use qsic_algebra::{IBig, RBig, roots::{floor_of_root, RootInterval}};
/// # use std::cmp::Ordering;
/// // √2 ∈ (−3, 7): q < √2 iff q < 0 or q² < 2
/// let iv = RootInterval::Open(RBig::from(-3), RBig::from(7));
/// let side = |q: &RBig| if q < &RBig::ZERO { Ordering::Less } else { (q * q).cmp(&RBig::from(2)) };
/// assert_eq!(floor_of_root(&iv, side), IBig::ONE);
/// ```
pub fn floor_of_root(iv: &RootInterval, mut side: impl FnMut(&RBig) -> Ordering) -> IBig {
    let (lo, hi) = match iv {
        RootInterval::Exact(v) => return v.floor(),
        RootInterval::Open(lo, hi) => (lo, hi),
    };
    // ⌊α⌋ ∈ [n, m): n = ⌊lo⌋ ≤ α, m = ⌈hi⌉ > α
    let (mut n, mut m) = (lo.floor(), hi.ceil());
    while &m - &n > IBig::ONE {
        let mid: IBig = (&n + &m) >> 1;
        if side(&RBig::from(mid.clone())) == Ordering::Greater {
            m = mid;
        } else {
            n = mid;
        }
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::SplitMix;

    /// By brute force: the least denominator `d` with a numerator in the interval, then the
    /// numerator of least absolute value.
    fn brute(lo: &RBig, hi: &RBig) -> RBig {
        for d in 1i64.. {
            let dd = RBig::from(d);
            let first = (lo * &dd).floor() + IBig::ONE;
            let last = (hi * &dd).ceil() - IBig::ONE;
            if first <= last {
                let n = if first > IBig::ZERO {
                    first
                } else if last < IBig::ZERO {
                    last
                } else {
                    IBig::ZERO
                };
                return RBig::from_parts_signed(n, IBig::from(d));
            }
        }
        unreachable!()
    }

    /// Random intervals with small ends of every sign: the answer is the brute-force one.
    #[test]
    fn simplest_rational_matches_brute_force() {
        let mut rng = SplitMix(5);
        for _ in 0..3000 {
            let den = rng.int(1, 200);
            let a = RBig::from_parts_signed(rng.int(-600, 600).into(), IBig::from(den));
            let b =
                &a + RBig::from_parts_signed(rng.int(1, 50).into(), IBig::from(rng.int(1, 300)));
            assert_eq!(
                simplest_rational_in(Some(&a), Some(&b)),
                brute(&a, &b),
                "({a}, {b})"
            );
        }
    }

    /// The machine route and the big-integer route agree (ends up to 2¹⁰⁰, overflowing
    /// `i128` in the loop for the largest).
    #[test]
    fn machine_and_big_routes_agree() {
        let mut rng = SplitMix(6);
        for bits in [8usize, 40, 62, 100] {
            for _ in 0..300 {
                let mut big =
                    || IBig::from(rng.next_u64() >> (64 - bits.min(63))) << bits.saturating_sub(63);
                let (a, b, c) = (big(), big() + IBig::ONE, big() + IBig::ONE);
                let lo = (a.clone(), b.clone());
                let hi = (&a * &c + &b, &b * &c); // lo + 1/c
                let want = simplest_nonnegative_big(lo.clone(), Some(hi.clone()));
                assert_eq!(simplest_nonnegative(lo.clone(), Some(hi)), want);
                assert_eq!(
                    simplest_nonnegative(lo.clone(), None),
                    simplest_nonnegative_big(lo, None)
                );
            }
        }
    }

    /// Unbounded intervals: the integer of least absolute value.
    #[test]
    fn half_lines_give_integers() {
        for v in -7i64..7 {
            let x = RBig::from_parts_signed(v.into(), IBig::from(3));
            let below = simplest_rational_in(None, Some(&x));
            let above = simplest_rational_in(Some(&x), None);
            assert_eq!(below, brute(&(&x - RBig::from(100)), &x));
            assert_eq!(above, brute(&x, &(&x + RBig::from(100))));
        }
        assert_eq!(simplest_rational_in(None, None), RBig::ZERO);
    }

    /// Between two known rationals given by open intervals of random widths around them
    /// (overlapping, reaching past each other, or exact): always the brute-force answer.
    #[test]
    fn between_roots_is_independent_of_the_intervals() {
        let mut rng = SplitMix(11);
        let rational = |rng: &mut SplitMix, den: i64| {
            RBig::from_parts_signed(rng.int(-400, 400).into(), IBig::from(rng.int(1, den)))
        };
        for _ in 0..2000 {
            let (a, b) = (rational(&mut rng, 60), rational(&mut rng, 60));
            if a == b {
                continue;
            }
            let (a, b) = if a < b { (a, b) } else { (b, a) };
            let want = brute(&a, &b);
            let around = |v: &RBig, rng: &mut SplitMix| match rng.int(0, 3) {
                0 => RootInterval::Exact(v.clone()),
                _ => {
                    let w = |rng: &mut SplitMix| {
                        RBig::from_parts_signed(rng.int(1, 3000).into(), IBig::from(rng.int(1, 97)))
                    };
                    RootInterval::Open(v - w(rng), v + w(rng))
                }
            };
            let (ia, ib) = (around(&a, &mut rng), around(&b, &mut rng));
            let sides = |s: Bound, q: &RBig| match s {
                Bound::Left => q.cmp(&a),
                Bound::Right => q.cmp(&b),
            };
            let got = between_roots(Some(&ia), Some(&ib), simplest_rational_in, sides);
            assert_eq!(got, want, "({a}, {b}) from {ia:?}, {ib:?}");
            let dyadic = |l: Option<&RBig>, h: Option<&RBig>| {
                super::super::simplest_between(l.unwrap(), h.unwrap(), false, false)
            };
            let got = between_roots(Some(&ia), Some(&ib), dyadic, sides);
            assert_eq!(
                got,
                dyadic(Some(&a), Some(&b)),
                "({a}, {b}) from {ia:?}, {ib:?}"
            );
            // half-lines: the simplest below a, above b
            let below = between_roots(None, Some(&ia), simplest_rational_in, |_, q| q.cmp(&a));
            assert_eq!(below, simplest_rational_in(None, Some(&a)));
            let above = between_roots(Some(&ib), None, simplest_rational_in, |_, q| q.cmp(&b));
            assert_eq!(above, simplest_rational_in(Some(&b), None));
            assert_eq!(floor_of_root(&ia, |q| q.cmp(&a)), a.floor());
            assert_eq!(floor_of_root(&ib, |q| q.cmp(&b)), b.floor());
        }
    }

    /// A root far inside a wide interval (10⁹ + 1/2 in (0, 2⁴⁰)): the picks halve the
    /// interval instead of walking the integers one by one.
    #[test]
    fn wide_intervals_cost_logarithmically_many_picks() {
        let a = RBig::from_parts_signed(IBig::from(2_000_000_001), IBig::from(2));
        let b = &a + RBig::from_parts_signed(IBig::ONE, IBig::from(1000));
        let wide = RootInterval::Open(RBig::ZERO, RBig::from(1u64 << 40));
        let mut calls = 0;
        let got = between_roots(
            Some(&wide),
            Some(&RootInterval::Exact(b.clone())),
            simplest_rational_in,
            |_, q| {
                calls += 1;
                q.cmp(&a)
            },
        );
        assert_eq!(got, brute(&a, &b));
        assert!(calls < 200, "{calls} side calls");
    }
}

//! Signs in ℚ(α) at degree 12, on named input families:
//! - `close_pairs_12`: `α` the seventh root of `T₆·(1024 T₆ − 1)` (six pairs of roots about
//!   `10⁻⁴` apart);
//! - `random_12`: `α` the first real root of a square-free degree-12 polynomial with
//!   coefficients in `[−20, 20]`.
//!
//! Elements are 100 polynomials of degree 11 with coefficients `n/d`, `|n| ≤ 9`, `d ≤ 5`.
//! - `sign_refined/*`: [`NumberFieldElement::sign`] once `α` has been refined by a first
//!   round of the same signs (the cost the issue asks to be microseconds);
//! - `algebraic_sign_refined/*`: [`AlgebraicReal::sign_of`] of the integer multiples, likewise;
//! - `sign_sturm_tarski/*`: the refinement-free Sturm–Tarski route, for comparison;
//! - `first_signs/*`: the same 100 signs from a fresh isolating interval (refinement included);
//! - `mul`, `inv`: products and inverses in the field.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use qsic_algebra::field::{NumberField, NumberFieldElement};
use qsic_algebra::roots::RootInterval;
use qsic_algebra::testing::SplitMix;
use qsic_algebra::{AlgebraicReal, Field, IBig, Poly, RBig, Ring};
use std::hint::black_box;

fn close_pairs_12() -> Poly {
    let (mut a, mut b) = (Poly::from_i64s(&[1]), Poly::from_i64s(&[0, 1]));
    for _ in 0..6 {
        let c = &(&Poly::from_i64s(&[0, 2]) * &b) - &a;
        (a, b) = (b, c);
    }
    &a * &(&a.scale(&IBig::from(1024)) - &Poly::from_i64s(&[1]))
}

fn random_12(rng: &mut SplitMix) -> Poly {
    loop {
        let mut c: Vec<i64> = (0..12).map(|_| rng.int(-20, 20)).collect();
        c.push(rng.int(1, 20));
        let p = Poly::from_i64s(&c);
        if p.is_squarefree() && p.count_real_roots_sturm() > 0 {
            return p;
        }
    }
}

/// The widest isolating interval of root `i` of the square-free `m` (between its
/// neighbours), so that a fresh number starts unrefined.
fn widest(m: &Poly, i: usize) -> (Poly, RootInterval) {
    let r = AlgebraicReal::real_roots_of(m);
    let lo = if i > 0 {
        r[i - 1].rational_between(&r[i])
    } else {
        r[i].interval().lo() - RBig::ONE
    };
    let hi = if i + 1 < r.len() {
        r[i].rational_between(&r[i + 1])
    } else {
        r[i].interval().hi() + RBig::ONE
    };
    (r[i].poly().clone(), RootInterval::Open(lo, hi))
}

fn bench(c: &mut Criterion) {
    let mut rng = SplitMix(5);
    let families = [
        ("close_pairs_12", widest(&close_pairs_12(), 6)),
        ("random_12", widest(&random_12(&mut SplitMix(12)), 0)),
    ];
    let coeffs: Vec<Poly<RBig>> = (0..100)
        .map(|_| {
            Poly::new(
                (0..12)
                    .map(|_| RBig::from_parts_signed(rng.int(-9, 9).into(), rng.int(1, 5).into()))
                    .collect(),
            )
        })
        .collect();
    let ints: Vec<Poly> = coeffs.iter().map(|c| Poly::from_rational(c).0).collect();
    let mut g = c.benchmark_group("number_field");
    g.throughput(Throughput::Elements(coeffs.len() as u64));
    for (name, (m, iv)) in &families {
        let fresh = || AlgebraicReal::from_isolating_interval(m, iv).expect("isolating");
        let alpha = fresh();
        let k = NumberField::new(&alpha);
        let elements: Vec<NumberFieldElement> = coeffs.iter().map(|c| k.element(c)).collect();
        let signs: Vec<_> = elements.iter().map(|e| e.sign()).collect();
        for (q, s) in ints.iter().zip(&signs) {
            assert_eq!(alpha.sign_of_sturm_tarski(q), *s, "{name}: {q}");
        }
        g.bench_function(format!("sign_refined/{name}"), |b| {
            b.iter(|| {
                for e in &elements {
                    black_box(e.sign());
                }
            })
        });
        g.bench_function(format!("algebraic_sign_refined/{name}"), |b| {
            b.iter(|| {
                for q in &ints {
                    black_box(alpha.sign_of(q));
                }
            })
        });
        g.bench_function(format!("sign_sturm_tarski/{name}"), |b| {
            b.iter(|| {
                for q in &ints {
                    black_box(alpha.sign_of_sturm_tarski(q));
                }
            })
        });
        g.bench_function(format!("first_signs/{name}"), |b| {
            b.iter(|| {
                let k = NumberField::new(&fresh());
                for c in &coeffs {
                    black_box(k.element(c).sign());
                }
            })
        });
        g.bench_function(format!("mul/{name}"), |b| {
            b.iter(|| {
                for (x, y) in elements.iter().zip(elements.iter().cycle().skip(1)) {
                    black_box(x.mul(y));
                }
            })
        });
        g.bench_function(format!("inv/{name}"), |b| {
            b.iter(|| {
                for e in &elements {
                    black_box(e.inv());
                }
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);

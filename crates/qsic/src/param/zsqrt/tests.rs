use super::fixed::*;
use super::levin::*;
use super::*;
use qsic_algebra::testing::SplitMix;

fn random_poly(rng: &mut SplitMix, bits: usize, irrational: bool, len: usize) -> ZPoly {
    let big =
        |rng: &mut SplitMix| IBig::from(rng.int(-999, 999)) << rng.int(0, bits as i64) as usize;
    (0..len)
        .map(|_| Zq {
            a: big(rng),
            b: if irrational { big(rng) } else { IBig::ZERO },
        })
        .collect()
}

/// The reduction as it was before the floats were kept beside the integers: every step
/// converts both vectors again and checks every operation (the reference below).
fn reduce_array_reference(t: &mut [[[i128; 8]; 2]; 2]) -> Option<()> {
    // the two halves of a mode: (w, j) cells
    let cells = |mode: usize, k: usize| -> [(usize, usize); 2] {
        if mode == 0 {
            [(k, 0), (k, 1)]
        } else {
            [(0, k), (1, k)]
        }
    };
    // binary gcd: shifts and subtractions, no 128-bit division
    let gcd = |mut x: u128, mut y: u128| {
        if x == 0 || y == 0 {
            return x | y;
        }
        let shift = (x | y).trailing_zeros();
        x >>= x.trailing_zeros();
        loop {
            y >>= y.trailing_zeros();
            if x > y {
                (x, y) = (y, x);
            }
            y -= x;
            if y == 0 {
                return x << shift;
            }
        }
    };
    for _round in 0..2 {
        let mut changed = false;
        for mode in 0..2 {
            for k in 0..2 {
                let c = cells(mode, k);
                let g = c.iter().flat_map(|&(w, j)| t[w][j]).fold(0u128, |g, v| {
                    if g == 1 {
                        1
                    } else {
                        gcd(g, v.unsigned_abs())
                    }
                });
                if g > 1 {
                    changed = true;
                    let g = i128::try_from(g).ok()?;
                    for (w, j) in c {
                        for v in &mut t[w][j] {
                            *v /= g;
                        }
                    }
                }
            }
            for _ in 0..8 {
                let f = |k: usize| -> [f64; 16] {
                    let c = cells(mode, k);
                    std::array::from_fn(|n| {
                        let v = t[c[n / 8].0][c[n / 8].1][n % 8];
                        // one instruction when it fits i64, else the two halves (the
                        // library call of `v as f64` costs more; `k` needs an approximation)
                        let small = v as i64;
                        if i128::from(small) == v {
                            small as f64
                        } else {
                            ((v >> 64) as i64 as f64) * 18_446_744_073_709_551_616.0
                                + (v as u64 as f64)
                        }
                    })
                };
                let (x, y) = (f(0), f(1));
                let dot = |p: &[f64; 16], q: &[f64; 16]| -> f64 {
                    p.iter().zip(q).map(|(a, b)| a * b).sum()
                };
                let (nx, ny) = (dot(&x, &x), dot(&y, &y));
                let (small, big, nsmall) = if nx <= ny { (0, 1, nx) } else { (1, 0, ny) };
                let k = (dot(&x, &y) / nsmall).round();
                if !(k.is_finite() && k != 0.0 && k.abs() < 1e30) {
                    break;
                }
                let k = k as i128;
                changed = true;
                let (sc, bc) = (cells(mode, small), cells(mode, big));
                for h in 0..2 {
                    let ((ws, js), (wb, jb)) = (sc[h], bc[h]);
                    for n in 0..8 {
                        let v = k.checked_mul(t[ws][js][n])?;
                        t[wb][jb][n] = t[wb][jb][n].checked_sub(v)?;
                    }
                }
            }
        }
        if !changed {
            break;
        }
    }
    Some(())
}

/// [`reduce_array`] takes the same steps as the reference on random arrays of small,
/// mixed, large and overflowing numbers (same results, same overflows).
#[test]
fn reduce_array_equals_the_reference() {
    let mut rng = SplitMix(71);
    // (reduced, changed, overflowed): every kind of outcome occurs (overflow rarely: a
    // step overflows only when |k·y| does while |x − k·y| may not)
    let mut seen = [0; 3];
    for case in 0..400 {
        let bits = [20, 40, 60, 90, 125][case % 5];
        let mut t = [[[0i128; 8]; 2]; 2];
        // a common factor in some cases, and a near-dependent pair of rows
        let g = i128::from(rng.int(1, 30));
        for w in 0..2 {
            for j in 0..2 {
                for n in 0..8 {
                    // |v| < 2^bits
                    let v = i128::from(rng.int(-999, 999)) << rng.int(0, bits - 10) as u32;
                    t[w][j][n] = if bits > 100 { v } else { v * g };
                }
            }
        }
        let k = i128::from(rng.int(-50, 50));
        for n in 0..8 {
            t[1][1][n] = (t[1][1][n] / 4).saturating_add(k.saturating_mul(t[0][1][n] / 4));
        }
        let (mut x, mut y) = (t, t);
        let (rx, ry) = (reduce_array(&mut x), reduce_array_reference(&mut y));
        assert_eq!(rx.is_some(), ry.is_some(), "{t:?}");
        if rx.is_some() {
            assert_eq!(x, y, "{t:?}");
            seen[0] += 1;
            seen[1] += usize::from(x != t);
        } else {
            seen[2] += 1;
        }
    }
    assert!(seen[0] > 10 && seen[1] > 10 && seen[2] > 0, "{seen:?}");
}

/// A ruling bloated by changes of `u` and `v` (and a common factor) comes back small,
/// and stays a ruling of the same surface: `bᵀSb`, `bᵀSd`, `dᵀSd` vanish identically.
#[test]
fn reduced_rulings_are_small_and_stay_on_the_surface() {
    use dashu_int::ops::BitTest;
    let mut rng = SplitMix(23);
    let size = |b: &[ZPoly; 4], d: &[ZPoly; 4]| {
        b.iter()
            .chain(d)
            .flatten()
            .map(|c| c.a.bit_len().max(c.b.bit_len()))
            .max()
            .unwrap_or(0)
    };
    // S = diag(1, 1, −1, −1) (x² + y² = z² + w²), with the lines
    // (x, y, z, w) = (1, u, 1, u) + v·(u, −1, −u, 1), over ℚ; and over ℚ(√2) for
    // x² + y² = 2z² + w²: (√2, √2u, 1, ... ) is not needed, ℚ is enough here
    let m: [[IBig; 4]; 4] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            IBig::from(if i != j {
                0
            } else if i < 2 {
                1
            } else {
                -1
            })
        })
    });
    let int = |v: i64| Zq::int(IBig::from(v));
    let base_b: [ZPoly; 4] = [
        vec![int(1)],
        vec![int(0), int(1)],
        vec![int(1)],
        vec![int(0), int(1)],
    ];
    let base_d: [ZPoly; 4] = [
        vec![int(0), int(1)],
        vec![int(-1)],
        vec![int(0), int(-1)],
        vec![int(1)],
    ];
    let on_surface = |b: &[ZPoly; 4], d: &[ZPoly; 4]| {
        [(b, b), (b, d), (d, d)]
            .iter()
            .all(|(x, y)| poly_form(&m, x, y, &IBig::ZERO).iter().all(Zq::is_zero))
    };
    assert!(on_surface(&base_b, &base_d));
    // a unimodular 2 × 2 matrix: a product of three elementary ones
    let unimodular = |rng: &mut SplitMix| -> [i64; 4] {
        let mut m = [1, 0, 0, 1];
        for step in 0..3 {
            let k = rng.int(-99, 99);
            let (a, b, c, d) = (m[0], m[1], m[2], m[3]);
            m = if step % 2 == 0 {
                [a + k * c, b + k * d, c, d]
            } else {
                [a, b, c + k * a, d + k * b]
            };
        }
        m
    };
    for _ in 0..50 {
        // u ↦ (p u + q)/(r u + s), then u ↦ f·u; b, d ↦ αb + βd, γb + δd; a common
        // factor g (all undone by valid changes: the reduction must find small numbers)
        let (mu, mv) = (unimodular(&mut rng), unimodular(&mut rng));
        let (f, g) = (rng.int(1, 99), rng.int(1, 99));
        let moebius = |p: &ZPoly| -> ZPoly {
            let c = |i: usize| p.get(i).map_or(0, |z| i64::try_from(&z.a).unwrap());
            let (c0, c1) = (c(0), c(1));
            // c0·(r u + s) + c1·(p u + q), then u ↦ f·u
            vec![
                int(c0 * mu[3] + c1 * mu[1]),
                int((c0 * mu[2] + c1 * mu[0]) * f),
            ]
        };
        let mix = |x: &ZPoly, y: &ZPoly, a: i64, b: i64| -> ZPoly {
            (0..2)
                .map(|i| {
                    let h = |p: &ZPoly| p.get(i).map_or(IBig::ZERO, |z| z.a.clone());
                    Zq::int((h(x) * a + h(y) * b) * g)
                })
                .collect()
        };
        let (mb, md): ([ZPoly; 4], [ZPoly; 4]) = (
            std::array::from_fn(|i| moebius(&base_b[i])),
            std::array::from_fn(|i| moebius(&base_d[i])),
        );
        let mut b: [ZPoly; 4] = std::array::from_fn(|i| mix(&mb[i], &md[i], mv[0], mv[1]));
        let mut d: [ZPoly; 4] = std::array::from_fn(|i| mix(&mb[i], &md[i], mv[2], mv[3]));
        assert!(on_surface(&b, &d));
        let before = size(&b, &d);
        // the direct route from the ruling over ℚ gives the same reduced ruling
        let (pb, pd): ([Poly<Quadratic>; 4], [Poly<Quadratic>; 4]) = (
            std::array::from_fn(|i| to_poly(&b[i], &IBig::ZERO)),
            std::array::from_fn(|i| to_poly(&d[i], &IBig::ZERO)),
        );
        let direct = reduced_ruling(&pb, &pd, &IBig::ZERO).expect("small and integral");
        assert!(reduce_ruling(&mut b, &mut d));
        assert_eq!(direct, (b.clone(), d.clone()));
        assert!(on_surface(&b, &d), "{b:?} {d:?}");
        assert!(
            size(&b, &d) <= 4 && size(&b, &d) < before,
            "{before} -> {b:?} {d:?}"
        );
    }
}

/// The conversions without gcds and square tests build the representations of the
/// general routes: [`to_poly`] and [`to_poly_down`] those of [`Quadratic::new`],
/// [`to_number_poly`] that of `curve::from_quadratic`, and [`log2_sizes`] the sizes of
/// the parent's `log2_size` on the converted coefficients (small, huge and zero numbers).
#[test]
fn conversions_equal_the_general_routes() {
    use qsic_algebra::field::NumberFieldElement;
    let mut rng = SplitMix(29);
    let same = |x: &NumberFieldElement, y: &NumberFieldElement| {
        x.numerator() == y.numerator()
            && x.denominator() == y.denominator()
            && x.field().is_some() == y.field().is_some()
            && x == y
    };
    let mut checked = 0;
    for (bits, delta) in [(4usize, 0i64), (10, 7), (60, 2), (200, 3), (1100, 5)] {
        let delta = IBig::from(delta);
        let huge_delta = IBig::from(7) << 1100;
        for d in [&delta, &huge_delta] {
            if delta.is_zero() && !d.is_zero() {
                continue;
            }
            let field = (!d.is_zero()).then(|| super::super::curve::sqrt_field(d));
            for len in 0..6 {
                let mut p = random_poly(&mut rng, bits, !d.is_zero(), len);
                for c in p.iter_mut() {
                    match rng.int(0, 3) {
                        0 => c.a = IBig::ZERO,
                        1 => c.b = IBig::ZERO,
                        _ => {}
                    }
                }
                let old = Poly::new(p.iter().map(|c| c.to_quadratic(d)).collect());
                assert_eq!(to_poly(&p, d), old);
                for e in [1usize, 5, 40] {
                    let den = dashu_int::UBig::ONE << e;
                    let part = |v: &IBig| RBig::from_parts(v.clone(), den.clone());
                    let want: Poly<Quadratic> = Poly::new(
                        p.iter()
                            .map(|c| Quadratic::new(part(&c.a), part(&c.b), d.clone()).unwrap())
                            .collect(),
                    );
                    assert_eq!(to_poly_down(&p, d, e), want);
                }
                let sizes: Vec<f64> = old
                    .coeffs()
                    .iter()
                    .map(crate::param::smooth::log2_size)
                    .collect();
                let new = log2_sizes(&p, d);
                // the trailing zeros of p have no coefficient in `old`
                assert!(new[sizes.len()..].iter().all(|v| *v == f64::NEG_INFINITY));
                assert_eq!(&new[..sizes.len()], &sizes[..], "{p:?}");
                let fast = to_number_poly(p.clone(), field.as_ref());
                let general = super::super::curve::poly_from_quadratic(&old, field.as_ref());
                assert_eq!(fast.coeffs().len(), general.coeffs().len());
                for (x, y) in fast.coeffs().iter().zip(general.coeffs()) {
                    assert!(same(x, y), "{x} vs {y}");
                    checked += 1;
                }
            }
        }
    }
    assert!(checked >= 100, "{checked}");
}

/// The checked machine forms of [`levin_big`] are the big-integer ones ([`poly_form`],
/// the other route) where they answer, and they decline where a form leaves `i128`
/// (coefficients of 60 bits: products of 120 bits times the matrix) or an input does.
#[test]
fn checked_forms_equal_the_big_ones() {
    let mut rng = SplitMix(77);
    let (mut answered, mut declined) = (0, 0);
    for bits in [0usize, 20, 40, 60, 130] {
        for _ in 0..20 {
            let irrational = rng.int(0, 1) == 1;
            let delta = IBig::from(if irrational { rng.int(2, 99) } else { 1 });
            let m: [[IBig; 4]; 4] = {
                let mut m: [[IBig; 4]; 4] = Default::default();
                for i in 0..4 {
                    for j in i..4 {
                        m[i][j] = IBig::from(rng.int(-999, 999));
                        m[j][i] = m[i][j].clone();
                    }
                }
                m
            };
            let mut poly = || {
                let len = 1 + rng.int(0, 2) as usize;
                let mut p = random_poly(&mut rng, bits, irrational, len);
                trim(&mut p);
                p
            };
            let b: [ZPoly; 4] = std::array::from_fn(|_| poly());
            let d: [ZPoly; 4] = std::array::from_fn(|_| poly());
            let want = (
                poly_form(&m, &b, &b, &delta),
                poly_form(&m, &b, &d, &delta),
                poly_form(&m, &d, &d, &delta),
            );
            match forms_checked(&m, &b, &d, &delta) {
                Some(mut got) => {
                    answered += 1;
                    let mut want = want;
                    for p in [
                        &mut got.0,
                        &mut got.1,
                        &mut got.2,
                        &mut want.0,
                        &mut want.1,
                        &mut want.2,
                    ] {
                        trim(p);
                    }
                    assert_eq!(got, want, "{bits} bits");
                }
                None => {
                    declined += 1;
                    assert!(bits >= 60, "declined at {bits} bits");
                }
            }
        }
    }
    assert!(
        answered >= 50 && declined >= 20,
        "{answered} answered, {declined} declined"
    );
}

/// [`scale_powers_of_two`] multiplies each coefficient by its power of two, on small and
/// big integers and zeros.
#[test]
fn scaling_by_powers_of_two() {
    let mut rng = SplitMix(31);
    for bits in [0usize, 20, 50, 70, 200] {
        for _ in 0..20 {
            let mut p = random_poly(&mut rng, bits, true, 5);
            p[rng.int(0, 4) as usize].a = IBig::ZERO;
            let exps: Vec<usize> = (0..5).map(|_| rng.int(0, 100) as usize).collect();
            let want: ZPoly = p
                .iter()
                .zip(&exps)
                .map(|(c, &e)| Zq {
                    a: &c.a * (IBig::ONE << e),
                    b: &c.b * (IBig::ONE << e),
                })
                .collect();
            scale_powers_of_two(&mut p, |i| exps[i]);
            assert_eq!(p, want);
        }
    }
}

/// The forms of a fixed ruling ([`FixedLevin`]) equal the big-integer ones on random
/// rulings and matrices of every size (declining only past the bounds of `levin_core`),
/// its `log₂` sizes of `s` equal [`log2_sizes`], and its shifts equal
/// [`scale_powers_of_two`] where they fit (and decline, changing nothing, where not).
#[test]
fn fixed_levin_equals_big_forms() {
    let mut rng = SplitMix(41);
    let (mut fixed, mut declined, mut shifted, mut too_far) = (0, 0, 0, 0);
    for (bits, delta) in [(3u32, 0i64), (8, 5), (20, 0), (28, 3), (40, 2), (60, 7)] {
        for _ in 0..40 {
            let mut v = |b: u32| i128::from(rng.int(-99, 99)) << rng.int(0, b as i64) as u32;
            let m: [[i128; 4]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| v(bits / 2)));
            let m: [[i128; 4]; 4] = std::array::from_fn(|i| {
                std::array::from_fn(|j| if i <= j { m[i][j] } else { m[j][i] })
            });
            let mut t = [[[0i128; 8]; 2]; 2];
            for x in t.as_flattened_mut().as_flattened_mut().chunks_mut(2) {
                x[0] = v(bits);
                x[1] = if delta == 0 { 0 } else { v(bits) };
            }
            let r = FixedRuling {
                delta: i128::from(delta),
                t,
            };
            let big_delta = IBig::from(delta);
            let (b, d) = r.to_zpolys();
            let mb = m.map(|row| row.map(IBig::from));
            let (s, a, alt) = levin_big(&mb, &b, &d, &big_delta);
            let Some(f) = FixedLevin::new(&m, &r) else {
                declined += 1;
                assert!(bits >= 20, "declined at {bits} bits");
                continue;
            };
            fixed += 1;
            let (fb, fd, fa, falt, fs) = f.into_zpolys();
            let trimmed = |mut p: ZPoly| {
                trim(&mut p);
                p
            };
            assert_eq!((&fb, &fd), (&b, &d));
            assert_eq!(fs, trimmed(s.clone()));
            assert_eq!(fa, a.clone().map(trimmed));
            assert_eq!(falt, alt.clone().map(trimmed));
            assert_eq!(f.s_log2_sizes(), log2_sizes(&fs, &big_delta));
            let k = rng.int(0, 16) as usize;
            let exponent = |degree: usize, i: usize| k * (degree + 1 - i.min(degree));
            let mut g = f;
            if g.shift(exponent) {
                shifted += 1;
                let (gb, gd, ga, galt, gs) = g.into_zpolys();
                let scaled = |mut p: ZPoly, degree: usize| {
                    scale_powers_of_two(&mut p, |i| exponent(degree, i));
                    p
                };
                assert_eq!(gb, fb.map(|p| scaled(p, 1)));
                assert_eq!(gd, fd.map(|p| scaled(p, 1)));
                assert_eq!(ga, fa.map(|p| scaled(p, 3)));
                assert_eq!(galt, falt.map(|p| scaled(p, 3)));
                assert_eq!(gs, scaled(fs, 4));
            } else {
                too_far += 1;
                assert_eq!(g.into_zpolys(), f.into_zpolys());
            }
        }
    }
    assert!(
        fixed > 100 && declined > 10 && shifted > 50 && too_far > 10,
        "{fixed} fixed, {declined} declined, {shifted} shifted, {too_far} too far"
    );
}

/// Products over ℤ[√δ] equal those of the same polynomials over ℚ(√δ) (`Poly<Quadratic>`,
/// another implementation): both parts irrational, one side rational, zero coefficients
/// among them; and `Zq::mul` with an integer on either side.
#[test]
fn products_equal_those_over_the_field() {
    let mut rng = SplitMix(23);
    for delta in [2i64, 3, 1_000_003] {
        let delta = IBig::from(delta) << 130; // δ far past the machine words
        let delta = &delta + IBig::from(3); // not a square
        for k in 0..60 {
            let (lx, ly) = (1 + k % 4, 1 + (k / 4) % 5);
            let mut x = random_poly(&mut rng, 90, k % 3 != 0, lx);
            let y = random_poly(&mut rng, 90, k % 5 != 0, ly);
            if k % 7 == 0 {
                x[0] = Zq::default();
            }
            let want = &to_poly(&x, &delta) * &to_poly(&y, &delta);
            assert_eq!(
                to_poly(&poly_mul(&x, &y, &delta), &delta),
                want,
                "{x:?} {y:?}"
            );
            let (p, q) = (&x[lx - 1], &y[ly - 1]);
            let r = Zq::int(q.a.clone());
            for (u, v) in [(p, q), (p, &r), (&r, p)] {
                let want = &u.to_quadratic(&delta) * &v.to_quadratic(&delta);
                assert_eq!(u.mul(v, &delta).to_quadratic(&delta), want);
            }
        }
    }
}

/// The machine-integer forms equal the big-integer ones: without checks (bounded), checked
/// (the bound fails, the numbers fit), and past i128 (the big fallback).
#[test]
fn machine_forms_equal_big_forms() {
    let mut rng = SplitMix(17);
    let (mut small, mut overflowed, mut bounded, mut checked_only) = (0, 0, 0, 0);
    for (bits, delta) in [
        (4usize, 0i64),
        (6, 11),
        (10, 7),
        (16, 0),
        (18, 2),
        (20, 0),
        (22, 3),
        (30, 2),
        (60, 3),
        (90, 5),
    ] {
        let delta = IBig::from(delta);
        for _ in 0..20 {
            let m: [[IBig; 4]; 4] = std::array::from_fn(|_| {
                std::array::from_fn(|_| {
                    IBig::from(rng.int(-50, 50)) << rng.int(0, bits as i64 / 2) as usize
                })
            });
            let irr = !delta.is_zero();
            // lines (2 coefficients) or a vertex and a conic (1 and 3)
            let (lb, ld) = if rng.int(0, 1) == 0 { (2, 2) } else { (1, 3) };
            let b: [ZPoly; 4] = std::array::from_fn(|_| random_poly(&mut rng, bits, irr, lb));
            let d: [ZPoly; 4] = std::array::from_fn(|_| random_poly(&mut rng, bits, irr, ld));
            let same = |x: &[Zq], y: &[Zq]| to_poly(x, &delta) == to_poly(y, &delta);
            let (e0, e1, e2) = (
                poly_form(&m, &b, &b, &delta),
                poly_form(&m, &b, &d, &delta),
                poly_form(&m, &d, &d, &delta),
            );
            let es = poly_sub(&poly_mul(&e1, &e1, &delta), &poly_mul(&e0, &e2, &delta));
            let (bs, ba, balt) = levin_big(&m, &b, &d, &delta);
            assert!(same(&bs, &es));
            let Some((s, a, alt)) = levin_small(&m, &b, &d, &delta) else {
                overflowed += 1;
                continue;
            };
            small += 1;
            let mi: [[i128; 4]; 4] =
                std::array::from_fn(|i| std::array::from_fn(|j| i128::try_from(&m[i][j]).unwrap()));
            let dl = i128::try_from(&delta).unwrap();
            let (slow, _) = levin_fixed(&mi, &b, &d, dl, true).expect("fits i128");
            assert_eq!((&s, &a, &alt), (&slow.0, &slow.1, &slow.2));
            let (_, unchecked) = levin_fixed(&mi, &b, &d, dl, false).expect("fits i128");
            if unchecked {
                bounded += 1;
            } else {
                checked_only += 1;
            }
            assert!(same(&s, &es));
            for i in 0..4 {
                let want = poly_sub(&poly_mul(&e2, &b[i], &delta), &poly_mul(&e1, &d[i], &delta));
                assert!(same(&a[i], &want) && same(&ba[i], &want));
                let want = poly_sub(&poly_mul(&e1, &b[i], &delta), &poly_mul(&e0, &d[i], &delta));
                assert!(same(&alt[i], &want) && same(&balt[i], &want));
            }
        }
    }
    assert!(
        small >= 80 && overflowed >= 50 && bounded >= 60 && checked_only >= 10,
        "{small} small ({bounded} bounded, {checked_only} checked), {overflowed} past i128"
    );
}

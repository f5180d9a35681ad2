//! Four concurrent lines under big disguises: two cones with the common vertex `(0:0:0:1)`
//! over conics of known meeting points, mapped by random integer congruences `PᵀAP` with
//! 20- and 60-digit entries. The curve must come out as four lines (the real ones exactly
//! on both quadrics, through the vertex), no factoring in the way, whatever the size.

use qsic::classify::SingularPointKind;
use qsic::param::{parameterize, ComponentParam, Number};
use qsic::quadric::Quadric;
use qsic_algebra::{IBig, RBig, Ring};

type Mat = [[RBig; 4]; 4];

/// A deterministic stream of decimal digits (SplitMix64).
struct Digits(u64);

impl Digits {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A signed integer of exactly `n` digits.
    fn integer(&mut self, n: usize) -> RBig {
        let mut s = String::new();
        s.push(char::from(b'1' + (self.next() % 9) as u8));
        for _ in 1..n {
            s.push(char::from(b'0' + (self.next() % 10) as u8));
        }
        let v: IBig = s.parse().expect("digits");
        RBig::from(if self.next() % 2 == 0 { v } else { -v })
    }
}

fn mul(x: &Mat, y: &Mat) -> Mat {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..4).fold(RBig::ZERO, |acc, k| acc + &x[i][k] * &y[k][j]))
    })
}

fn transpose(x: &Mat) -> Mat {
    std::array::from_fn(|i| std::array::from_fn(|j| x[j][i].clone()))
}

/// `P = L·U`, unit lower and upper triangular with `n`-digit entries: det 1, invertible.
fn random_map(rng: &mut Digits, n: usize) -> Mat {
    let tri = |rng: &mut Digits, upper: bool| -> Mat {
        std::array::from_fn(|i| {
            std::array::from_fn(|j| match (i == j, (j > i) == upper) {
                (true, _) => RBig::ONE,
                (false, true) => rng.integer(n),
                (false, false) => RBig::ZERO,
            })
        })
    };
    let l = tri(rng, false);
    let u = tri(rng, true);
    mul(&l, &u)
}

/// The cone over the conic `c` of the plane `w = 0` from `(0:0:0:1)`.
fn cone(c: Conic) -> Mat {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            if i < 3 && j < 3 {
                RBig::from(c[i][j])
            } else {
                RBig::ZERO
            }
        })
    })
}

fn value_at(m: &Mat, x: &[Number; 4]) -> Number {
    let mut s = Number::zero();
    for i in 0..4 {
        for j in 0..4 {
            let e = Number::rational(m[i][j].clone());
            s = s.add(&x[i].mul(&x[j]).mul(&e));
        }
    }
    s
}

/// A conic of the plane `w = 0`.
type Conic = [[i64; 3]; 3];

/// `(C, D, real lines)`: conics of the plane `w = 0` meeting in four distinct points.
const CONFIGURATIONS: [(Conic, Conic, usize); 3] = [
    // xz = y², 2xy + z² = 0: (1 : t : t²), t(t³ + 2) = 0 — one rational, one cubic
    (
        [[0, 0, 1], [0, -2, 0], [1, 0, 0]],
        [[0, 1, 0], [1, 0, 0], [0, 0, 1]],
        2,
    ),
    // x² = 2z², y² = 3z²: (±√2 : ±√3 : 1), four real points, none rational
    (
        [[1, 0, 0], [0, 0, 0], [0, 0, -2]],
        [[0, 0, 0], [0, 1, 0], [0, 0, -3]],
        4,
    ),
    // x² + y² = z², x² + 2y² + 3z² = 0: four non-real points
    (
        [[1, 0, 0], [0, 1, 0], [0, 0, -1]],
        [[1, 0, 0], [0, 2, 0], [0, 0, 3]],
        0,
    ),
];

#[test]
fn four_concurrent_lines_under_big_disguises_lie_on_both_quadrics() {
    let mut rng = Digits(34);
    for (c, d, real_lines) in CONFIGURATIONS {
        for digits in [20, 60] {
            let p = random_map(&mut rng, digits);
            let pt = transpose(&p);
            let a = mul(&mul(&pt, &cone(c)), &p);
            let b = mul(&mul(&pt, &cone(d)), &p);
            let qa = Quadric::from_matrix(a.clone()).expect("nonzero");
            let qb = Quadric::from_matrix(b.clone()).expect("nonzero");
            let curve = parameterize(&qa, &qb)
                .unwrap_or_else(|e| panic!("{digits} digits, {real_lines} real: {e}"));
            assert_eq!(curve.components.len(), 4, "{digits} digits");
            let real: Vec<_> = curve.components.iter().filter(|k| k.real).collect();
            assert_eq!(real.len(), real_lines, "{digits} digits");
            for line in real {
                let Some(param) = &line.param else {
                    panic!("a real line without parameterization")
                };
                assert!(param.lies_on(&a) && param.lies_on(&b), "{digits} digits");
                let ComponentParam::Rational { x, degree: 1 } = param else {
                    panic!("a line is X(u) = p + u·q")
                };
                // X(0) is the vertex P⁻¹(0:0:0:1): A and B vanish there to first order
                let vertex: [Number; 4] = std::array::from_fn(|i| x[i].coeff(0));
                assert!(vertex.iter().any(|v| !v.is_zero()));
                let direction: [Number; 4] = std::array::from_fn(|i| x[i].coeff(1));
                for m in [&a, &b] {
                    assert!(value_at(m, &vertex).is_zero());
                    assert!(value_at(m, &direction).is_zero());
                }
            }
            let [vertex] = &curve.singular_points[..] else {
                panic!("one multiple point, the vertex")
            };
            assert_eq!(vertex.kind, SingularPointKind::Multiple);
            for m in [&a, &b] {
                assert!(value_at(m, &vertex.point).is_zero());
            }
            assert_eq!(curve.connected.len(), 1);
        }
    }
}

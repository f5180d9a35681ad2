//! A machine-integer filter in front of [`super::recognize`]: most quadrics are not natural,
//! and this says so in a few dozen instructions, without the big-integer matrix.
//!
//! A natural quadric is a double plane (the 4×4 matrix `M` has rank 1) or its 3×3 block `Q`
//! has a repeated eigenvalue (a sphere: triple; a cylinder or cone of revolution: double).
//! `Q` symmetric has a repeated eigenvalue iff the discriminant of its characteristic
//! polynomial `λ³ − E₁λ² + E₂λ − E₃` vanishes:
//! `Δ = E₁²E₂² − 4E₂³ − 4E₁³E₃ + 18E₁E₂E₃ − 27E₃²`.
//! So `Δ ≠ 0` with `rank M > 1` proves the quadric is not natural; anything else goes to the
//! exact recognizer, which decides.
//!
//! **Bounds.** The entries come from [`crate::quadric::Quadric::small_integer_matrix`]
//! (below 2²⁴), so the rank-1 products `m_ij·m_kk` stay below 2⁴⁸. For `Δ`, with every
//! entry of `Q` below `2^k` in absolute value: `|E₁| ≤ 3·2^k`, `|E₂| ≤ 6·2^2k`,
//! `|E₃| ≤ 6·2^3k`, so the five terms of `Δ` are at most `(324 + 864 + 648 + 1944 + 972)·2^6k
//! < 2¹³·2^6k`, and every partial sum is below 2¹²⁷ when `k ≤` [`DISCRIMINANT_BITS`] `= 18`.
//! Larger blocks are passed on to the exact recognizer unfiltered.

/// The largest bit length of the block's entries for which `Δ` is computed in `i128`.
pub(crate) const DISCRIMINANT_BITS: u32 = 18;

/// `false` when the quadric of the primitive integer matrix `m` is proven not natural;
/// `true` when it may be (the exact recognizer decides).
pub(crate) fn may_be_natural(m: &[[i64; 4]; 4]) -> bool {
    if rank_one(m) {
        return true;
    }
    let limit = 1i64 << DISCRIMINANT_BITS;
    if m[..3]
        .iter()
        .any(|row| row[..3].iter().any(|v| v.abs() >= limit))
    {
        return true;
    }
    discriminant(m) == 0
}

/// Whether the symmetric `m` has rank 1: a nonzero diagonal pivot `k` with every
/// `m_ij·m_kk = m_ik·m_kj`.
fn rank_one(m: &[[i64; 4]; 4]) -> bool {
    let Some(k) = (0..4).find(|&k| m[k][k] != 0) else {
        return false;
    };
    let w = |i: usize, j: usize| i128::from(m[i][j]);
    (0..4).all(|i| (i..4).all(|j| w(i, j) * w(k, k) == w(i, k) * w(k, j)))
}

/// `Δ` of the characteristic polynomial of the 3×3 block, in `i128` (entries below
/// 2^[`DISCRIMINANT_BITS`]).
fn discriminant(m: &[[i64; 4]; 4]) -> i128 {
    let q = |i: usize, j: usize| i128::from(m[i][j]);
    debug_assert!((0..3).all(|i| (0..3).all(|j| q(i, j).abs() < 1 << DISCRIMINANT_BITS)));
    let e1 = q(0, 0) + q(1, 1) + q(2, 2);
    let minor = |i: usize, j: usize| q(i, i) * q(j, j) - q(i, j) * q(i, j);
    let e2 = minor(0, 1) + minor(0, 2) + minor(1, 2);
    let e3 = q(0, 0) * (q(1, 1) * q(2, 2) - q(1, 2) * q(1, 2))
        - q(0, 1) * (q(0, 1) * q(2, 2) - q(1, 2) * q(0, 2))
        + q(0, 2) * (q(0, 1) * q(1, 2) - q(1, 1) * q(0, 2));
    e1 * e1 * e2 * e2 - 4 * e2 * e2 * e2 - 4 * e1 * e1 * e1 * e3 + 18 * e1 * e2 * e3 - 27 * e3 * e3
}

#[cfg(test)]
mod tests {
    use super::*;

    fn matrix(text: &str) -> [[i64; 4]; 4] {
        *crate::io::parse_quadric(text)
            .unwrap()
            .small_integer_matrix()
            .unwrap()
    }

    #[test]
    fn natural_quadrics_pass_and_generic_ones_are_dropped() {
        for natural in [
            "x^2 + y^2 + z^2 - 1",
            "(x - 1)^2 + (y + 2)^2 + z^2 - 3",
            "x^2 + y^2 - 4",
            "(x + y)^2 + 2*z^2 - 1", // eigenvalues 2, 2, 0: a circular cylinder
            "x^2 + y^2 - 3*z^2",
            "(x - y + 2*z - 1)^2",
            "x^2 + 2*y^2 + 2*z^2 - 1", // a spheroid: not natural, but a double eigenvalue
        ] {
            assert!(may_be_natural(&matrix(natural)), "{natural}");
        }
        for generic in [
            "x^2 + 2*y^2 + 3*z^2 - 1",
            "x*y + y*z + 3*z^2 - x",
            "x^2 - y^2 + 5*z",
        ] {
            assert!(!may_be_natural(&matrix(generic)), "{generic}");
        }
    }

    /// Δ at the bound: the largest entries the `i128` form accepts do not overflow (test
    /// builds check every operation), and it equals `(λ₁ − λ₂)²(λ₁ − λ₃)²(λ₂ − λ₃)²` on a
    /// diagonal block.
    #[test]
    fn the_discriminant_at_its_bound() {
        let big = (1i64 << DISCRIMINANT_BITS) - 1;
        let mut m = [[big; 4]; 4];
        for (i, row) in m.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                if (i + j) % 2 == 1 {
                    *v = -big;
                }
            }
        }
        let _ = discriminant(&m);
        let d = |a: i64, b: i64, c: i64| {
            let mut m = [[0i64; 4]; 4];
            (m[0][0], m[1][1], m[2][2]) = (a, b, c);
            discriminant(&m)
        };
        assert_eq!(d(1, 2, 4), 36); // (1 − 2)²(1 − 4)²(2 − 4)²
        assert_eq!(
            d(-big, big, 0),
            (4 * i128::from(big).pow(2)) * i128::from(big).pow(4)
        );
        assert_eq!(d(3, 3, 7), 0);
    }
}

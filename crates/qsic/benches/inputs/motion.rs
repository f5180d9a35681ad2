//! The moving-quadric families of the `motion` bench and the `motion_families` example
//! (README, "Moving quadrics"): rigid motions built by `qsic::motion::rigid`, and random
//! moving pencils with fixed seeds.

#![allow(dead_code, clippy::needless_range_loop)]

use qsic::io::{moving_matrix_from_polynomial, moving_matrix_from_polys, MovingMatrix};
use qsic::motion::rigid::{RigidMotion, Rotation};
use qsic_algebra::testing::SplitMix;
use qsic_algebra::{IBig, Poly, RBig};

fn rational_poly(c: &[i64]) -> Poly<RBig> {
    Poly::new(c.iter().map(|&v| RBig::from(v)).collect())
}

/// The rigid families (module docs).
pub fn rigid_families() -> Vec<(&'static str, MovingMatrix, MovingMatrix)> {
    let q = |t: &str| moving_matrix_from_polynomial(t).expect("valid");
    let cayley = |axis: [i64; 3]| Rotation::Cayley {
        axis: axis.map(RBig::from),
    };
    let ellipsoid = q("x^2/4 + y^2 + z^2/9 - 1");
    let other = q("(x - 3)^2/9 + (y - 1)^2/4 + (z - 1/2)^2 - 1");
    let translate = RigidMotion::translation([
        rational_poly(&[-6, 2]),
        rational_poly(&[0, 1]),
        rational_poly(&[1]),
    ]);
    // turning about z until a tip touches B at (6/5, 8/5, 0), t = −2 (tests/rigid_contact.rs)
    let turn = RigidMotion {
        rotation: cayley([0, 0, 1]),
        ..RigidMotion::default()
    };
    let elongated = q("x^2/4 + y^2 + z^2 - 1");
    let near_tip = q("(x - 3)^2/9 + (y - 4)^2/9 + z^2/4 - 1");
    let screw = RigidMotion {
        rotation: cayley([0, 0, 1]),
        translation: [Poly::zero(), Poly::zero(), rational_poly(&[0, 1])],
        ..RigidMotion::default()
    };
    let cone_turn = RigidMotion {
        rotation: cayley([1, 0, 0]),
        center: [RBig::from(2), RBig::ZERO, RBig::ZERO],
        ..RigidMotion::default()
    };
    let cone = q("(x - 2)^2 + y^2 - (z - 1)^2/4");
    vec![
        (
            "ellipsoids_translation",
            translate.apply(&ellipsoid).expect("moved"),
            other.clone(),
        ),
        (
            "ellipsoids_rotation",
            turn.apply(&elongated).expect("moved"),
            near_tip,
        ),
        (
            "ellipsoids_screw",
            screw.apply(&ellipsoid).expect("moved"),
            other,
        ),
        (
            "cylinder_cone_rotating",
            q("x^2 + y^2 - 1"),
            cone_turn.apply(&cone).expect("moved"),
        ),
    ]
}

/// A random integer of at most `bits` bits (`|c| < 2^bits`), either sign.
fn random_integer(rng: &mut SplitMix, bits: usize) -> IBig {
    let mut c = IBig::ZERO;
    let mut left = bits;
    while left > 0 {
        let take = left.min(64);
        let word = if take == 64 {
            rng.next_u64()
        } else {
            rng.next_u64() >> (64 - take)
        };
        c = (c << take) + IBig::from(word);
        left -= take;
    }
    if rng.next_u64() & 1 == 1 {
        -c
    } else {
        c
    }
}

/// A random symmetric moving matrix: entries of degree `degree` in `t`, `bits`-bit
/// coefficients.
pub fn random_moving(rng: &mut SplitMix, degree: usize, bits: usize) -> MovingMatrix {
    let mut m: [[Poly<RBig>; 4]; 4] = Default::default();
    for i in 0..4 {
        for j in i..4 {
            let p = Poly::new(
                (0..=degree)
                    .map(|_| RBig::from(random_integer(rng, bits)))
                    .collect(),
            );
            m[i][j] = p.clone();
            m[j][i] = p;
        }
    }
    moving_matrix_from_polys(&m, &Poly::constant(RBig::ONE)).expect("a nonzero matrix")
}

/// The random families: (name, degree, bits, seed).
pub fn random_families(all: bool) -> Vec<(String, MovingMatrix, MovingMatrix)> {
    let mut sizes = vec![(1, 3), (1, 64), (2, 3), (2, 64), (4, 3), (4, 64)];
    if all {
        sizes.push((16, 512));
    }
    sizes
        .into_iter()
        .map(|(degree, bits)| {
            let mut rng = SplitMix(1000 + 100 * degree as u64 + bits as u64);
            let a = random_moving(&mut rng, degree, bits);
            let b = random_moving(&mut rng, degree, bits);
            (format!("random_degree{degree}_{bits}bit"), a, b)
        })
        .collect()
}

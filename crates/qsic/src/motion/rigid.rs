//! A quadric under a rigid motion whose rotation and translation are rational in `t`,
//! built exactly as a [`MovingMatrix`].
//!
//! The motion moves a point `x ∈ ℝ³` to `R(t)(x − p) + p + c(t)`: a rotation `R(t)` about
//! the centre `p` (a rational point, the origin by default), then the translation `c(t)`,
//! three polynomials in `t` with rational coefficients. A screw motion is a rotation about an
//! axis and a translation along it.
//!
//! **Rotations.** A quaternion path `q(t) = q₀ + q₁i + q₂j + q₃k` with polynomial components
//! (not all zero) gives `R = Q(q)/|q|²`, with `Q` the matrix of quadratic forms
//! ```text
//!     | q₀²+q₁²−q₂²−q₃²   2(q₁q₂ − q₀q₃)    2(q₁q₃ + q₀q₂)  |
//! Q = | 2(q₁q₂ + q₀q₃)    q₀²−q₁²+q₂²−q₃²   2(q₂q₃ − q₀q₁)  |,   |q|² = q₀²+q₁²+q₂²+q₃²,
//!     | 2(q₁q₃ − q₀q₂)    2(q₂q₃ + q₀q₁)    q₀²−q₁²−q₂²+q₃² |
//! ```
//! orthogonal with determinant 1 for every real `t` (`QᵀQ = |q|⁴ I`); a factor common to the
//! four components does not change `R` and is divided out first. The Cayley rotation about a
//! rational axis `a ≠ 0` is the path `q(t) = 1 + t(a₁i + a₂j + a₃k)`: the rotation by the
//! angle `θ` with `tan(θ/2) = t·|a|` (for a unit axis, `t = tan(θ/2)`, and `t → ±∞` is the
//! half turn), `R = (I + t[a]ₓ)(I − t[a]ₓ)⁻¹`, entries of degree 2 over `1 + |a|²t²`.
//!
//! **The moved quadric.** In homogeneous coordinates the motion is `T = [[R, d], [0, 1]]`
//! with `d = p − Rp + c`, and `T⁻¹ = [[Rᵀ, p − Rᵀ(p + c)], [0, 1]] = U/n` with `n = |q|²`
//! and the polynomial matrix `U = [[Qᵀ, n·p − Qᵀ(p + c)], [0, n]]`. A point `y` is on the
//! moved quadric exactly when `T⁻¹y` is on the quadric `A`, so the moved quadric is
//! `A′(t) = T⁻ᵀ A T⁻¹ = Uᵀ A U / n²`, put in canonical form by
//! [`moving_matrix_from_polys`]: for a Cayley rotation of a fixed quadric the entries have
//! degree 4 in `t` over `(1 + |a|²t²)²`, and a translation of degree `k` adds `2k`. `A` may
//! itself move (a [`MovingMatrix`]): the motion is applied at every `t`.

use crate::error::Error;
use crate::io::{moving_matrix_from_polys, parse_rational_function, MovingMatrix, Variable};
use qsic_algebra::{Poly, RBig};

/// A polynomial in `t` with rational coefficients.
pub type RationalPoly = Poly<RBig>;

/// The rotation of a [`RigidMotion`] (module docs).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Rotation {
    /// No rotation.
    Identity,
    /// The Cayley rotation about the axis `a` (nonzero, rational): the quaternion path
    /// `1 + t(a₁i + a₂j + a₃k)`, the angle `θ` with `tan(θ/2) = t·|a|`.
    Cayley {
        /// The axis direction `a`.
        axis: [RBig; 3],
    },
    /// The rotation of a quaternion path `q(t) = q₀ + q₁i + q₂j + q₃k`, components not all
    /// zero: `R = Q(q)/|q|²`.
    Quaternion([RationalPoly; 4]),
}

/// A rigid motion `x ↦ R(t)(x − center) + center + translation(t)` (module docs).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RigidMotion {
    /// The rotation `R(t)`.
    pub rotation: Rotation,
    /// The centre of the rotation (a point of its axis).
    pub center: [RBig; 3],
    /// The translation `c(t)`.
    pub translation: [RationalPoly; 3],
}

impl Default for RigidMotion {
    fn default() -> RigidMotion {
        RigidMotion {
            rotation: Rotation::Identity,
            center: [RBig::ZERO, RBig::ZERO, RBig::ZERO],
            translation: [Poly::zero(), Poly::zero(), Poly::zero()],
        }
    }
}

/// `Q(q)` of the module docs and `|q|²`.
fn rotation_of(q: &[RationalPoly; 4]) -> ([[RationalPoly; 3]; 3], RationalPoly) {
    let two = Poly::constant(RBig::from(2));
    let p = |i: usize, j: usize| &q[i] * &q[j];
    let sq: [RationalPoly; 4] = std::array::from_fn(|i| p(i, i));
    let diag = |k: usize| {
        // q₀² + q_k² − (the other two squares)
        let others = (1..4)
            .filter(|&i| i != k)
            .fold(Poly::zero(), |acc, i| &acc + &sq[i]);
        &(&sq[0] + &sq[k]) - &others
    };
    let off = |a: (usize, usize), b: (usize, usize), plus: bool| {
        let (x, y) = (p(a.0, a.1), p(b.0, b.1));
        &two * &(if plus { &x + &y } else { &x - &y })
    };
    let m = [
        [
            diag(1),
            off((1, 2), (0, 3), false),
            off((1, 3), (0, 2), true),
        ],
        [
            off((1, 2), (0, 3), true),
            diag(2),
            off((2, 3), (0, 1), false),
        ],
        [
            off((1, 3), (0, 2), false),
            off((2, 3), (0, 1), true),
            diag(3),
        ],
    ];
    let n = sq.iter().fold(Poly::zero(), |acc, s| &acc + s);
    (m, n)
}

/// The four components divided by their gcd over `ℚ[t]`.
fn reduced(q: &[RationalPoly; 4]) -> [RationalPoly; 4] {
    let ints: Vec<Poly> = q.iter().map(|c| Poly::from_rational(c).0).collect();
    let g = ints.iter().fold(Poly::zero(), |g, c| g.gcd(c));
    if g.degree().unwrap_or(0) == 0 {
        return q.clone();
    }
    let g = g.to_rational();
    std::array::from_fn(|i| {
        let (num, scale) = Poly::from_rational(&q[i]);
        // q_i = num/scale and g | num in ℤ[t] (Gauss)
        let quotient = num.div_exact(&Poly::from_rational(&g).0).unwrap_or(num);
        quotient.to_rational().scale(&(RBig::ONE / scale))
    })
}

impl RigidMotion {
    /// The translation by `c(t)`, no rotation.
    pub fn translation(c: [RationalPoly; 3]) -> RigidMotion {
        RigidMotion {
            translation: c,
            ..RigidMotion::default()
        }
    }

    /// The quaternion path of the rotation, its components without a common factor;
    /// `None` for no rotation.
    ///
    /// # Errors
    /// [`Error::InvalidMotion`] for a zero axis or a zero quaternion path.
    pub fn quaternion(&self) -> Result<Option<[RationalPoly; 4]>, Error> {
        match &self.rotation {
            Rotation::Identity => Ok(None),
            Rotation::Cayley { axis } => {
                if axis.iter().all(|a| *a == RBig::ZERO) {
                    return Err(Error::InvalidMotion("the rotation axis is zero".into()));
                }
                let t = |a: &RBig| Poly::new(vec![RBig::ZERO, a.clone()]);
                Ok(Some([
                    Poly::constant(RBig::ONE),
                    t(&axis[0]),
                    t(&axis[1]),
                    t(&axis[2]),
                ]))
            }
            Rotation::Quaternion(q) => {
                if q.iter().all(Poly::is_zero) {
                    return Err(Error::InvalidMotion(
                        "the quaternion path is zero (no rotation)".into(),
                    ));
                }
                Ok(Some(reduced(q)))
            }
        }
    }

    /// `(Q, n)` with the rotation `R(t) = Q(t)/n(t)` (module docs): the identity over 1 for
    /// no rotation.
    ///
    /// # Errors
    /// As [`Self::quaternion`].
    pub fn rotation_matrix(&self) -> Result<([[RationalPoly; 3]; 3], RationalPoly), Error> {
        Ok(match self.quaternion()? {
            Some(q) => rotation_of(&q),
            None => {
                let one = || Poly::constant(RBig::ONE);
                let m = std::array::from_fn(|i| {
                    std::array::from_fn(|j| if i == j { one() } else { Poly::zero() })
                });
                (m, one())
            }
        })
    }

    /// `(U, n)` with `T(t)⁻¹ = U(t)/n(t)`, the inverse of the motion in homogeneous
    /// coordinates `(x, y, z, w)` (module docs).
    ///
    /// # Errors
    /// As [`Self::quaternion`].
    pub fn inverse_matrix(&self) -> Result<([[RationalPoly; 4]; 4], RationalPoly), Error> {
        let (q, n) = self.rotation_matrix()?;
        let p = self.center.clone().map(Poly::constant);
        let shifted: [RationalPoly; 3] = std::array::from_fn(|i| &p[i] + &self.translation[i]);
        let mut u: [[RationalPoly; 4]; 4] = Default::default();
        for i in 0..3 {
            let mut last = &n * &p[i];
            for j in 0..3 {
                u[i][j] = q[j][i].clone(); // Qᵀ
                last = &last - &(&q[j][i] * &shifted[j]);
            }
            u[i][3] = last;
        }
        u[3][3] = n.clone();
        Ok((u, n))
    }

    /// The quadric `A(t)` moved by the motion: `T⁻ᵀ A T⁻¹` in canonical form (module docs).
    ///
    /// # Errors
    /// As [`Self::quaternion`]; [`Error::Limit`] if the moved matrix exceeds the bounds of
    /// a moving matrix ([`moving_matrix_from_polys`]).
    ///
    /// # Examples
    /// ```
    /// use qsic::io::moving_matrix_from_polynomial as moving;
    /// use qsic::motion::rigid::{RigidMotion, Rotation};
    /// use qsic_algebra::{Poly, RBig};
    ///
    /// // An ellipsoid turning about the z axis, t = tan(θ/2): at t = 1 a quarter turn.
    /// let turn = RigidMotion {
    ///     rotation: Rotation::Cayley { axis: [0, 0, 1].map(RBig::from) },
    ///     ..RigidMotion::default()
    /// };
    /// let moved = turn.apply(&moving("x^2/4 + y^2 + z^2 - 1")?)?;
    /// assert_eq!(moved.numerators()[0][0].degree(), Some(4));
    /// assert_eq!(moved.denominator(), &Poly::from_i64s(&[4, 0, 8, 0, 4])); // 4(1 + t²)²
    /// let quarter = moved.quadric_at(&RBig::ONE)?;
    /// let swapped = moving("x^2 + y^2/4 + z^2 - 1")?.quadric_at(&RBig::ONE)?;
    /// assert!(quarter.integer_matrix().is_proportional(swapped.integer_matrix()));
    /// # Ok::<(), qsic::Error>(())
    /// ```
    pub fn apply(&self, quadric: &MovingMatrix) -> Result<MovingMatrix, Error> {
        let (u, n) = self.inverse_matrix()?;
        let g = quadric.factor().to_rational();
        let m: [[RationalPoly; 4]; 4] = std::array::from_fn(|i| {
            std::array::from_fn(|j| &quadric.numerators()[i][j].to_rational() * &g)
        });
        // Uᵀ M U, with M U first
        let mu: [[RationalPoly; 4]; 4] = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                (0..4).fold(Poly::zero(), |acc, k| &acc + &(&m[i][k] * &u[k][j]))
            })
        });
        let mut out: [[RationalPoly; 4]; 4] = Default::default();
        for i in 0..4 {
            for j in i..4 {
                let e = (0..4).fold(Poly::zero(), |acc, k| &acc + &(&u[k][i] * &mu[k][j]));
                out[j][i] = e.clone();
                out[i][j] = e;
            }
        }
        let denominator = &(&n * &n) * &quadric.denominator().to_rational();
        moving_matrix_from_polys(&out, &denominator)
    }
}

/// Reads a polynomial in `t` with rational coefficients (`"t^2/2 - 3*t + 1"`, `"0.5"`), as
/// the components of a translation or a quaternion path are written: the reader of
/// [`parse_rational_function`] with the one variable `t`.
///
/// # Errors
/// The reader's errors; [`Error::InvalidMotion`] for a division by an expression in `t`.
///
/// # Examples
/// ```
/// use qsic::motion::rigid::parse_polynomial_in_t;
/// use qsic_algebra::{Poly, RBig};
/// let p = parse_polynomial_in_t("(t + 1)^2/2")?;
/// assert_eq!(p, Poly::new(vec![RBig::from_parts(1.into(), 2u8.into()), RBig::ONE, RBig::from_parts(1.into(), 2u8.into())]));
/// assert!(parse_polynomial_in_t("1/t").is_err());
/// # Ok::<(), qsic::Error>(())
/// ```
pub fn parse_polynomial_in_t(text: &str) -> Result<RationalPoly, Error> {
    let f = parse_rational_function(text, &[Variable::T])?;
    let t = Variable::T.index();
    let (Some(num), Some(den)) = (
        f.numerator().to_univariate(t),
        f.denominator().as_constant(),
    ) else {
        return Err(Error::InvalidMotion(format!(
            "'{}' is not a polynomial in t",
            crate::error::shorten_numbers(text.trim())
        )));
    };
    Ok(Poly::new(num.into_iter().map(|c| c / &den).collect()))
}

/// The quadric `quadric` moved by `motion`: [`RigidMotion::apply`].
///
/// # Errors
/// As [`RigidMotion::apply`].
pub fn moved_quadric(quadric: &MovingMatrix, motion: &RigidMotion) -> Result<MovingMatrix, Error> {
    motion.apply(quadric)
}

/// An integer as a constant polynomial, for tests and examples.
#[cfg(test)]
fn constant(v: i64) -> RationalPoly {
    Poly::constant(RBig::from(v))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::moving_matrix_from_polynomial as moving;

    fn proportional(a: &crate::Quadric, b: &crate::Quadric) -> bool {
        a.integer_matrix().is_proportional(b.integer_matrix())
    }

    /// `xᵀAx`.
    fn eval(a: &crate::Quadric, x: &[RBig; 4]) -> RBig {
        let m = a.matrix();
        (0..4)
            .flat_map(|i| (0..4).map(move |j| (i, j)))
            .fold(RBig::ZERO, |acc, (i, j)| acc + &m[i][j] * &x[i] * &x[j])
    }

    fn q(n: i64, d: u64) -> RBig {
        RBig::from_parts(n.into(), d.into())
    }

    fn t_times(k: i64) -> RationalPoly {
        Poly::new(vec![RBig::ZERO, RBig::from(k)])
    }

    fn cayley(axis: [i64; 3]) -> Rotation {
        Rotation::Cayley {
            axis: axis.map(RBig::from),
        }
    }

    /// `QᵀQ = |q|⁴ I` and `det Q = |q|⁶` identically in `t`, for a quaternion path of degree 2.
    #[test]
    fn quaternion_rotations_are_orthogonal() {
        let path = [
            Poly::new(vec![q(1, 1), q(0, 1), q(2, 3)]),
            t_times(1),
            constant(-2),
            Poly::new(vec![q(1, 2), q(-3, 1)]),
        ];
        let (m, n) = rotation_of(&path);
        let n2 = &n * &n;
        for i in 0..3 {
            for j in 0..3 {
                let dot = (0..3).fold(Poly::zero(), |acc, k| &acc + &(&m[k][i] * &m[k][j]));
                let want = if i == j { n2.clone() } else { Poly::zero() };
                assert_eq!(dot, want, "({i},{j})");
            }
        }
        let det = qsic_algebra::linalg::minors::det(&m);
        assert_eq!(det, &n2 * &n);
    }

    /// Known answers: a quarter turn (t = 1) about z swaps the x and y semi-axes; about an
    /// axis through a centre it moves the centre's image as a rotation of the plane; the
    /// Cayley rotation is the quaternion path 1 + t·a; a sphere about its centre does not
    /// move; a translation is the substitution x → x − c(t).
    #[test]
    fn moved_quadrics_have_known_answers() {
        let ellipsoid = moving("x^2/4 + y^2 + z^2 - 1").unwrap();
        let turn = RigidMotion {
            rotation: cayley([0, 0, 1]),
            ..RigidMotion::default()
        };
        let moved = turn.apply(&ellipsoid).unwrap();
        let at = |m: &MovingMatrix, t: &RBig| m.quadric_at(t).unwrap();
        let swapped = moving("x^2 + y^2/4 + z^2 - 1").unwrap();
        assert!(proportional(
            &at(&moved, &RBig::ONE),
            &at(&swapped, &RBig::ONE)
        ));
        assert!(proportional(
            &at(&moved, &RBig::ZERO),
            &at(&ellipsoid, &RBig::ZERO)
        ));
        // t = 1/2: cos θ = (1 − t²)/(1 + t²) = 3/5, sin θ = 4/5; the point (2, 0, 0) of the
        // ellipsoid goes to (6/5, 8/5, 0)
        let half = q(1, 2);
        let image = [q(6, 5), q(8, 5), RBig::ZERO, RBig::ONE];
        assert_eq!(eval(&at(&moved, &half), &image), RBig::ZERO);
        assert_ne!(
            eval(
                &at(&moved, &half),
                &[q(8, 5), q(6, 5), RBig::ZERO, RBig::ONE]
            ),
            RBig::ZERO
        );

        let via_quaternion = RigidMotion {
            rotation: Rotation::Quaternion([constant(1), Poly::zero(), Poly::zero(), t_times(1)]),
            ..RigidMotion::default()
        };
        assert_eq!(via_quaternion.apply(&ellipsoid).unwrap(), moved);
        // a common factor of the path changes nothing
        let scaled = RigidMotion {
            rotation: Rotation::Quaternion([
                Poly::new(vec![q(3, 1), q(3, 1)]),
                Poly::zero(),
                Poly::zero(),
                Poly::new(vec![RBig::ZERO, q(3, 1), q(3, 1)]),
            ]),
            ..RigidMotion::default()
        };
        assert_eq!(scaled.apply(&ellipsoid).unwrap(), moved);

        let sphere = moving("x^2 + y^2 + z^2 - 1").unwrap();
        let spin = RigidMotion {
            rotation: cayley([1, 2, 2]),
            ..RigidMotion::default()
        };
        assert_eq!(
            spin.apply(&sphere).unwrap().numerators(),
            sphere.numerators()
        );

        // about the z axis through (1, 0, 0): the origin goes to (1, −1, 0) at t = 1
        let small = moving("x^2 + y^2 + z^2 - 1/4").unwrap();
        let about = RigidMotion {
            rotation: cayley([0, 0, 1]),
            center: [RBig::ONE, RBig::ZERO, RBig::ZERO],
            ..RigidMotion::default()
        };
        let want = moving("(x - 1)^2 + (y + 1)^2 + z^2 - 1/4").unwrap();
        assert!(proportional(
            &at(&about.apply(&small).unwrap(), &RBig::ONE),
            &at(&want, &RBig::ONE)
        ));

        let slide = RigidMotion::translation([
            t_times(1),
            Poly::zero(),
            Poly::new(vec![q(0, 1), q(0, 1), q(1, 1)]),
        ]);
        assert_eq!(
            slide.apply(&sphere).unwrap(),
            moving("(x - t)^2 + y^2 + (z - t^2)^2 - 1").unwrap()
        );
    }

    /// A screw motion about z (rotation t = tan(θ/2), rise t along the axis) of a sphere
    /// centred off the axis: its centre is on the helix-like curve (R(t)·(2, 0), t).
    #[test]
    fn screw_motion_moves_the_centre_along_the_axis_and_around_it() {
        let sphere = moving("(x - 2)^2 + y^2 + z^2 - 1").unwrap();
        let screw = RigidMotion {
            rotation: cayley([0, 0, 1]),
            translation: [Poly::zero(), Poly::zero(), t_times(1)],
            ..RigidMotion::default()
        };
        let moved = screw.apply(&sphere).unwrap();
        for (t, c) in [
            (RBig::ZERO, [q(2, 1), q(0, 1), q(0, 1)]),
            (RBig::ONE, [q(0, 1), q(2, 1), q(1, 1)]),
            (q(1, 2), [q(6, 5), q(8, 5), q(1, 2)]),
            (q(-2, 1), [q(-6, 5), q(-8, 5), q(-2, 1)]),
        ] {
            let want = format!("(x - {})^2 + (y - {})^2 + (z - {})^2 - 1", c[0], c[1], c[2]);
            let want = moving(&want).unwrap().quadric_at(&t).unwrap();
            assert!(
                proportional(&moved.quadric_at(&t).unwrap(), &want),
                "t = {t}"
            );
        }
        // a sphere: one factor n = 1 + t² cancels, n·(|c(t)|² − 1) = (1 + t²)(t² + 3) is
        // the top degree; an ellipsoid keeps degree 4 + 2 (the rise, squared) over n²
        let degree = |m: &MovingMatrix| {
            m.numerators()
                .iter()
                .flatten()
                .filter_map(Poly::degree)
                .max()
        };
        assert_eq!(degree(&moved), Some(4));
        assert_eq!(moved.numerators()[3][3], Poly::from_i64s(&[3, 0, 4, 0, 1]));
        let ellipsoid = moving("(x - 2)^2 + y^2/4 + z^2 - 1").unwrap();
        let moved = screw.apply(&ellipsoid).unwrap();
        assert_eq!(degree(&moved), Some(6));
        assert_eq!(moved.denominator().degree(), Some(4));
    }

    #[test]
    fn zero_rotations_are_errors() {
        let sphere = moving("x^2 + y^2 + z^2 - 1").unwrap();
        let zero_axis = RigidMotion {
            rotation: cayley([0, 0, 0]),
            ..RigidMotion::default()
        };
        assert_eq!(
            zero_axis.apply(&sphere),
            Err(Error::InvalidMotion("the rotation axis is zero".into()))
        );
        let zero_path = RigidMotion {
            rotation: Rotation::Quaternion(Default::default()),
            ..RigidMotion::default()
        };
        assert!(matches!(
            zero_path.apply(&sphere),
            Err(Error::InvalidMotion(_))
        ));
    }
}

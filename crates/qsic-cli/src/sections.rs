//! The drawn region's geometry in floats: the cube, polylines clipped to it (Liang–Barsky),
//! and the surfaces' sections by axis-parallel planes (conics sampled from their canonical
//! forms). Nothing here decides anything: it only draws what the exact description says.

/// An axis-parallel cube.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Cube {
    /// Its centre.
    pub centre: [f64; 3],
    /// Half its side.
    pub half: f64,
}

impl Cube {
    pub(crate) fn lo(&self, i: usize) -> f64 {
        self.centre[i] - self.half
    }

    pub(crate) fn hi(&self, i: usize) -> f64 {
        self.centre[i] + self.half
    }

    /// The cube around the bounding box of `points` with a margin of an eighth of its
    /// largest side on each side (`None` for no points; a single point gets half-side
    /// `max(1, |p|/2)`).
    pub(crate) fn around(points: &[[f64; 3]]) -> Option<Cube> {
        let first = points.first()?;
        let (mut lo, mut hi) = (*first, *first);
        for p in points {
            for i in 0..3 {
                lo[i] = lo[i].min(p[i]);
                hi[i] = hi[i].max(p[i]);
            }
        }
        let centre = [0, 1, 2].map(|i| (lo[i] + hi[i]) / 2.0);
        let side = (0..3).map(|i| hi[i] - lo[i]).fold(0.0, f64::max);
        let half = if side > 0.0 {
            side * 0.5 * 1.25
        } else {
            (norm(&centre) / 2.0).max(1.0)
        };
        Some(Cube { centre, half })
    }
}

pub(crate) fn norm(p: &[f64; 3]) -> f64 {
    p.iter().map(|v| v * v).sum::<f64>().sqrt()
}

/// The part `[t0, t1]` of the segment `p + t(q − p)`, `t ∈ [0, 1]`, inside `cube`
/// (Liang–Barsky), or `None`.
pub(crate) fn clip_segment(p: &[f64; 3], q: &[f64; 3], cube: &Cube) -> Option<(f64, f64)> {
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for i in 0..3 {
        let d = q[i] - p[i];
        for (num, den) in [(p[i] - cube.lo(i), d), (cube.hi(i) - p[i], -d)] {
            // inside this side where num + den·t ≥ 0
            if den == 0.0 {
                if num < 0.0 {
                    return None;
                }
            } else {
                let t = -num / den;
                if den > 0.0 {
                    t0 = t0.max(t);
                } else {
                    t1 = t1.min(t);
                }
            }
        }
    }
    (t0 <= t1).then_some((t0, t1))
}

/// The parts of the polyline `points` inside `cube`, each a polyline; a single point is kept
/// when it is inside. Segments with a non-finite end are dropped.
pub(crate) fn clip_polyline(points: &[[f64; 3]], cube: &Cube) -> Vec<Vec<[f64; 3]>> {
    let inside = |p: &[f64; 3]| (0..3).all(|i| cube.lo(i) <= p[i] && p[i] <= cube.hi(i));
    if points.len() == 1 {
        return if inside(&points[0]) {
            vec![points.to_vec()]
        } else {
            Vec::new()
        };
    }
    let at = |p: &[f64; 3], q: &[f64; 3], t: f64| [0, 1, 2].map(|i| p[i] + t * (q[i] - p[i]));
    let mut out: Vec<Vec<[f64; 3]>> = Vec::new();
    let mut run: Vec<[f64; 3]> = Vec::new();
    for w in points.windows(2) {
        let (p, q) = (&w[0], &w[1]);
        let clipped = if p.iter().chain(q).all(|v| v.is_finite()) {
            clip_segment(p, q, cube)
        } else {
            None
        };
        match clipped {
            Some((t0, t1)) => {
                if t0 > 0.0 || run.is_empty() {
                    if run.len() > 1 {
                        out.push(std::mem::take(&mut run));
                    }
                    run = vec![at(p, q, t0)];
                }
                run.push(at(p, q, t1));
                if t1 < 1.0 {
                    out.push(std::mem::take(&mut run));
                }
            }
            None => {
                if run.len() > 1 {
                    out.push(std::mem::take(&mut run));
                }
                run.clear();
            }
        }
    }
    if run.len() > 1 {
        out.push(run);
    }
    out
}

/// The real points of the conic `a p² + 2b pq + c q² + 2d p + 2e q + f = 0` (coefficients
/// `[a, b, c, d, e, f]`) within distance `radius` of `centre`, as polylines (floats, for
/// drawing): from the canonical form after a rotation — ellipse, hyperbola (two branches),
/// parabola, line pair, parallel lines, one line; nothing for a point or an empty conic.
/// Lines and unbounded branches reach at least `radius` beyond `centre`.
pub(crate) fn conic_polylines(coef: [f64; 6], centre: [f64; 2], radius: f64) -> Vec<Vec<[f64; 2]>> {
    const N: usize = 72;
    let scale = coef.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if scale == 0.0 || !scale.is_finite() {
        return Vec::new();
    }
    let [a, b, c, d, e, f] = coef.map(|v| v / scale);
    let tol = 1e-9;
    let theta = 0.5 * (2.0 * b).atan2(a - c);
    let (s, co) = theta.sin_cos();
    // p = X·(co, s) + Y·(−s, co)
    let l1 = a * co * co + 2.0 * b * s * co + c * s * s;
    let l2 = a * s * s - 2.0 * b * s * co + c * co * co;
    let g1 = d * co + e * s;
    let g2 = -d * s + e * co;
    let to_p = |x: f64, y: f64| [x * co - y * s, x * s + y * co];
    // the centre and the radius in the rotated frame: where the parameters must reach
    let rc = [
        centre[0] * co + centre[1] * s,
        -centre[0] * s + centre[1] * co,
    ];
    let reach = |x0: f64, y0: f64| radius + ((x0 - rc[0]).powi(2) + (y0 - rc[1]).powi(2)).sqrt();
    let line = |x0: f64, y0: f64, dx: f64, dy: f64| {
        let r = reach(x0, y0);
        vec![
            to_p(x0 - r * dx, y0 - r * dy),
            to_p(x0 + r * dx, y0 + r * dy),
        ]
    };
    // the roots of l x² + 2g x + h = 0 (one for a double root)
    let roots = |l: f64, g: f64, h: f64| -> Vec<f64> {
        if l.abs() <= tol {
            return if g.abs() > tol {
                vec![-h / (2.0 * g)]
            } else {
                Vec::new()
            };
        }
        let disc = g * g - l * h;
        if disc.abs() <= tol {
            vec![-g / l]
        } else if disc > 0.0 {
            let r = disc.sqrt();
            vec![(-g - r) / l, (-g + r) / l]
        } else {
            Vec::new()
        }
    };
    match (l1.abs() > tol, l2.abs() > tol) {
        (true, true) => {
            let (x0, y0) = (-g1 / l1, -g2 / l2);
            let k = g1 * g1 / l1 + g2 * g2 / l2 - f;
            let shift = |x: f64, y: f64| to_p(x0 + x, y0 + y);
            if k.abs() <= tol {
                if l1 * l2 > 0.0 {
                    return Vec::new(); // a point
                }
                let m = (-l1 / l2).sqrt(); // Y = ±m X
                let n = (1.0 + m * m).sqrt();
                return vec![line(x0, y0, 1.0 / n, m / n), line(x0, y0, 1.0 / n, -m / n)];
            }
            if l1 * l2 > 0.0 {
                if k / l1 < 0.0 {
                    return Vec::new();
                }
                let (ra, rb) = ((k / l1).sqrt(), (k / l2).sqrt());
                return vec![(0..=N)
                    .map(|i| {
                        let t = std::f64::consts::TAU * i as f64 / N as f64;
                        shift(ra * t.cos(), rb * t.sin())
                    })
                    .collect()];
            }
            // a hyperbola: the transverse axis is the one where k / l > 0
            let (ra, rb, swap) = if k / l1 > 0.0 {
                ((k / l1).sqrt(), (-k / l2).sqrt(), false)
            } else {
                ((k / l2).sqrt(), (-k / l1).sqrt(), true)
            };
            let top = (reach(x0, y0) / ra.min(rb)).asinh() + 0.05;
            [1.0, -1.0]
                .iter()
                .map(|&sign| {
                    (0..=N)
                        .map(|i| {
                            let t = top * (2.0 * i as f64 / N as f64 - 1.0);
                            let (u, v) = (sign * ra * t.cosh(), rb * t.sinh());
                            if swap {
                                shift(v, u)
                            } else {
                                shift(u, v)
                            }
                        })
                        .collect()
                })
                .collect()
        }
        (true, false) | (false, true) => {
            // l X² + 2g X + 2h Y + f = 0 with X the axis of the nonzero eigenvalue
            let swap = l1.abs() <= tol;
            let (l, g, h) = if swap { (l2, g2, g1) } else { (l1, g1, g2) };
            let frame = |x: f64, y: f64| if swap { (y, x) } else { (x, y) };
            if h.abs() > tol {
                // a parabola Y = −(l X² + 2g X + f) / 2h, X around the vertex
                let x0 = -g / l;
                let (cx, _) = frame(rc[0], rc[1]);
                let r = radius + (x0 - cx).abs();
                let mut branch = Vec::with_capacity(2 * N + 1);
                for i in 0..=2 * N {
                    let x = x0 + r * (i as f64 / N as f64 - 1.0);
                    let y = -(l * x * x + 2.0 * g * x + f) / (2.0 * h);
                    let (u, v) = frame(x, y);
                    branch.push(to_p(u, v));
                }
                vec![branch]
            } else {
                roots(l, g, f)
                    .into_iter()
                    .map(|x| {
                        let (u, v) = frame(x, 0.0);
                        let (du, dv) = frame(0.0, 1.0);
                        line(u, v, du, dv)
                    })
                    .collect()
            }
        }
        (false, false) => {
            let n = (g1 * g1 + g2 * g2).sqrt();
            if n <= tol {
                return Vec::new();
            }
            // 2 g·X + f = 0: the point nearest the origin and the direction
            let t = -f / (2.0 * n * n);
            vec![line(g1 * t, g2 * t, -g2 / n, g1 / n)]
        }
    }
}

/// The sections of the surface `[x 1] M [x 1]ᵀ = 0` by `levels` planes `x_k = const` across
/// the cube, for each axis `k`, clipped to the cube: 3D polylines.
pub(crate) fn surface_sections(
    m: &[[f64; 4]; 4],
    cube: &Cube,
    levels: usize,
) -> Vec<Vec<[f64; 3]>> {
    let mut out = Vec::new();
    for k in 0..3 {
        let (i, j) = match k {
            0 => (1, 2),
            1 => (0, 2),
            _ => (0, 1),
        };
        for n in 0..levels {
            let t = cube.lo(k) + (n as f64 + 0.5) / levels as f64 * 2.0 * cube.half;
            let coef = [
                m[i][i],
                m[i][j],
                m[j][j],
                m[i][k] * t + m[i][3],
                m[j][k] * t + m[j][3],
                m[k][k] * t * t + 2.0 * m[k][3] * t + m[3][3],
            ];
            let centre = [cube.centre[i], cube.centre[j]];
            for line in conic_polylines(coef, centre, cube.half * std::f64::consts::SQRT_2) {
                let lifted: Vec<[f64; 3]> = line
                    .iter()
                    .map(|pq| {
                        let mut p = [0.0; 3];
                        p[i] = pq[0];
                        p[j] = pq[1];
                        p[k] = t;
                        p
                    })
                    .collect();
                out.extend(clip_polyline(&lifted, cube));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use qsic_algebra::testing::SplitMix;

    /// Uniform in `[0, 1)`.
    fn unit(rng: &mut SplitMix) -> f64 {
        (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    fn conic_at(c: &[f64; 6], p: &[f64; 2]) -> f64 {
        let [a, b, cc, d, e, f] = *c;
        a * p[0] * p[0]
            + 2.0 * b * p[0] * p[1]
            + cc * p[1] * p[1]
            + 2.0 * d * p[0]
            + 2.0 * e * p[1]
            + f
    }

    /// Every sampled point lies on its conic, in the expected number of polylines, for each
    /// canonical type moved by a random rotation and translation; lines and unbounded
    /// branches reach the requested radius.
    #[test]
    fn conic_sections_lie_on_the_conic() {
        // (canonical l1 X² + l2 Y² + 2 g1 X + 2 g2 Y + f, polylines)
        let types: [([f64; 5], usize); 9] = [
            ([1.0, 4.0, 0.0, 0.0, -4.0], 1),  // ellipse
            ([1.0, -1.0, 0.0, 0.0, -1.0], 2), // hyperbola
            ([-1.0, 1.0, 0.0, 0.0, -1.0], 2), // hyperbola, other axis
            ([1.0, -4.0, 0.0, 0.0, 0.0], 2),  // line pair
            ([1.0, 0.0, 0.0, -1.0, 0.0], 1),  // parabola
            ([1.0, 0.0, 0.0, 0.0, -1.0], 2),  // parallel lines
            ([1.0, 0.0, 0.0, 0.0, 0.0], 1),   // double line
            ([0.0, 0.0, 1.0, 0.5, -1.0], 1),  // one line
            ([1.0, 1.0, 0.0, 0.0, 1.0], 0),   // empty
        ];
        let mut rng = SplitMix(7);
        for (k, (t, count)) in types.iter().enumerate() {
            for _ in 0..8 {
                let angle = unit(&mut rng) * 6.0;
                let shift = [unit(&mut rng) * 4.0 - 2.0, unit(&mut rng) * 4.0 - 2.0];
                let (s, c) = f64::sin_cos(angle);
                // X = c(p − h) + s(q − k), Y = −s(p − h) + c(q − k)
                let [l1, l2, g1, g2, f] = *t;
                let a = l1 * c * c + l2 * s * s;
                let b = (l1 - l2) * c * s;
                let cc = l1 * s * s + l2 * c * c;
                let d0 = g1 * c - g2 * s;
                let e0 = g1 * s + g2 * c;
                // translate: p → p − h
                let (h, kk) = (shift[0], shift[1]);
                let d = d0 - a * h - b * kk;
                let e = e0 - b * h - cc * kk;
                let f1 =
                    a * h * h + 2.0 * b * h * kk + cc * kk * kk - 2.0 * d0 * h - 2.0 * e0 * kk + f;
                let coef = [a, b, cc, d, e, f1];
                let lines = conic_polylines(coef, [0.0, 0.0], 5.0);
                assert_eq!(lines.len(), *count, "type {k}: {coef:?}");
                for line in &lines {
                    assert!(line.len() >= 2);
                    for p in line {
                        let scale = 1.0 + p[0] * p[0] + p[1] * p[1];
                        assert!(conic_at(&coef, p).abs() < 1e-8 * scale, "type {k}: {p:?}");
                    }
                }
                if k != 0 {
                    // unbounded: the far points leave the disc of radius 5
                    let far = lines
                        .iter()
                        .flatten()
                        .map(|p| (p[0] * p[0] + p[1] * p[1]).sqrt())
                        .fold(0.0, f64::max);
                    assert!(*count == 0 || far >= 5.0, "type {k}: reaches {far}");
                } else {
                    let l = &lines[0];
                    assert!((l[0][0] - l[l.len() - 1][0]).abs() < 1e-12, "closed");
                }
            }
        }
    }

    #[test]
    fn clipping_keeps_the_parts_inside() {
        let cube = Cube {
            centre: [0.0; 3],
            half: 1.0,
        };
        // a line through the cube along x: one part from x = −1 to 1
        let parts = clip_polyline(&[[-3.0, 0.0, 0.0], [3.0, 0.0, 0.0]], &cube);
        assert_eq!(parts, vec![vec![[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0]]]);
        // in, out, in again: two parts; outside entirely: none
        let zig = [
            [0.0, 0.0, 0.0],
            [0.5, 0.0, 0.0],
            [3.0, 0.0, 0.0],
            [0.5, 0.5, 0.0],
            [0.0, 0.5, 0.0],
        ];
        let parts = clip_polyline(&zig, &cube);
        assert_eq!(parts.len(), 2);
        assert_eq!(
            parts[0],
            vec![[0.0, 0.0, 0.0], [0.5, 0.0, 0.0], [1.0, 0.0, 0.0]]
        );
        assert_eq!(parts[1].last(), Some(&[0.0, 0.5, 0.0]));
        assert!(clip_polyline(&[[2.0, 2.0, 0.0], [3.0, -2.0, 0.0]], &cube).is_empty());
        // every point of every part lies in the cube, and a non-finite point cuts the line
        let parts = clip_polyline(
            &[
                [0.0; 3],
                [f64::INFINITY, 0.0, 0.0],
                [0.2, 0.2, 0.2],
                [0.3, 0.2, 0.2],
            ],
            &cube,
        );
        assert_eq!(parts, vec![vec![[0.2, 0.2, 0.2], [0.3, 0.2, 0.2]]]);
        assert_eq!(clip_polyline(&[[5.0, 0.0, 0.0]], &cube).len(), 0);
        assert_eq!(clip_polyline(&[[0.5, 0.0, 0.0]], &cube).len(), 1);
    }
}

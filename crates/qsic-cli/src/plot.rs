//! `qsic plot A B -o out.svg`: the real intersection curve drawn in a 3D view, and the
//! eigenvalue curve of the pencil, as hand-written SVG.
//!
//! | entry point | does |
//! |---|---|
//! | [`plot_to_svg`] | the picture of a pair: the curve panel, and with [`PlotOptions::eigencurve`] the eigencurve panel below |
//! | `curve_panel` | the curve in ℝ³ (affine chart) seen by an orthographic camera, the surfaces faintly, the legend |
//! | [`eigencurve_panel`] | `det(λA − B − uI) = 0` in the `(λ, u)` plane, the index in each region, the real roots of `det(λA − B)` |
//! | [`snapshot`] | a small picture of the curve without legend (the snapshots of `qsic motion --plot`) |
//! | [`View`], [`parse_view`] | the camera's azimuth and elevation |
//!
//! Everything decided comes from the exact description: the pieces, their kinds and
//! boundedness, the singular points and their kinds, the class, the roots of `det(λA − B)` and
//! the index on each arc between them. Floating point is used only to draw: the points come
//! from [`qsic::param::sample::sample`] (the exact parameterization evaluated, never
//! marching), the surfaces are drawn as their sections by planes `x, y, z = const` (conics
//! sampled in floats from their canonical forms), and the eigenvalue branches are the sorted
//! eigenvalues of `λA − B` (Jacobi's method) at a grid of `λ`.
//!
//! The drawn region is a cube: around the finite points of the bounded pieces, isolated
//! points and finite singular points when there are any; else around the points of the
//! unbounded branches nearest the origin; else (no real point in ℝ³) around the ellipsoids
//! among the surfaces, or the unit cube at the origin. Unbounded branches are clipped to it,
//! and the legend says so.

pub use crate::eigencurve::eigencurve_panel;
use crate::param::curve_of;
use crate::plot_common::{anchor, common_of, Common};
use crate::sections::{clip_polyline, norm, surface_sections, Cube};
use crate::svg::{colour, document, push_text, push_title, short, wrap, Panel, WIDTH};
use qsic::affine::{affine_view, AffineView, Chart};
use qsic::param::sample::{sample, SampleOptions, Sampled};
use qsic::param::Curve;
use qsic::Quadric;
use qsic_algebra::RBig;
use std::fmt::Write as _;

/// The camera: azimuth (degrees, about the z axis from the x axis) and elevation (degrees
/// above the xy plane) of the viewing direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// Degrees about the z axis, from the x axis towards the y axis.
    pub azimuth: f64,
    /// Degrees above the xy plane, in `[−90, 90]`.
    pub elevation: f64,
}

impl Default for View {
    /// Azimuth 35°, elevation 25°.
    fn default() -> View {
        View {
            azimuth: 35.0,
            elevation: 25.0,
        }
    }
}

/// Reads `"AZIMUTH,ELEVATION"` (degrees, decimals).
///
/// # Errors
/// A message for anything else, or an elevation outside `[−90, 90]`.
///
/// ```
/// use qsic_cli::plot::{parse_view, View};
/// assert_eq!(parse_view("30,-10.5"), Ok(View { azimuth: 30.0, elevation: -10.5 }));
/// assert!(parse_view("30").is_err() && parse_view("0,91").is_err());
/// ```
pub fn parse_view(text: &str) -> Result<View, String> {
    let usage = || format!("--view: \"AZIMUTH,ELEVATION\" in degrees is required, not {text:?}");
    let (a, e) = text.split_once(',').ok_or_else(usage)?;
    let read = |s: &str| {
        s.trim()
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(usage)
    };
    let view = View {
        azimuth: read(a)?,
        elevation: read(e)?,
    };
    if !(-90.0..=90.0).contains(&view.elevation) {
        return Err(format!(
            "--view: the elevation {} is outside [-90, 90]",
            view.elevation
        ));
    }
    Ok(view)
}

/// What [`plot_to_svg`] draws.
#[derive(Clone, Debug, PartialEq)]
pub struct PlotOptions {
    /// The camera.
    pub view: View,
    /// At least this many points per piece ([`SampleOptions::points`]).
    pub points: usize,
    /// The plane at infinity `[a, b, c, d]` (default `w`).
    pub chart: [RBig; 4],
    /// Add the eigencurve panel.
    pub eigencurve: bool,
}

impl Default for PlotOptions {
    fn default() -> PlotOptions {
        PlotOptions {
            view: View::default(),
            points: 64,
            chart: SampleOptions::default().chart,
            eigencurve: false,
        }
    }
}

/// The SVG picture of the intersection of `a` and `b`; `planes[i]` marks an input given as a
/// plane (named `plane` in the legend).
///
/// # Errors
/// The message of [`curve_of`] (a class not covered: `not yet: …`), of an invalid chart, or of
/// the sampler (too many points).
///
/// # Examples
/// ```
/// use qsic::io::parse_quadric;
/// use qsic_cli::plot::{plot_to_svg, PlotOptions};
/// let a = parse_quadric("x^2+y^2+z^2-4").unwrap();
/// let b = parse_quadric("(x-1)^2+y^2-1").unwrap(); // Viviani's curve
/// let svg = plot_to_svg(&a, &b, [false; 2], &PlotOptions::default()).unwrap();
/// assert_eq!(svg.matches("<g class=\"piece\"").count(), 1);
/// assert_eq!(svg.matches("<g class=\"singular\"").count(), 1);
/// assert!(svg.contains("crunode"));
/// ```
pub fn plot_to_svg(
    a: &Quadric,
    b: &Quadric,
    planes: [bool; 2],
    options: &PlotOptions,
) -> Result<String, String> {
    let scene = Scene::new(a, b, planes, options)?;
    let mut panels = vec![curve_panel(&scene)];
    if options.eigencurve {
        panels.push(eigencurve_panel(a, b));
    }
    Ok(document(&panels))
}

/// The chart's plane as text: `w`, or `a*x + b*y + …`.
fn chart_text(form: &[RBig; 4]) -> String {
    let names = ["x", "y", "z", "w"];
    let terms: Vec<String> = form
        .iter()
        .zip(names)
        .filter(|(c, _)| **c != RBig::ZERO)
        .map(|(c, n)| {
            if *c == RBig::ONE {
                n.to_string()
            } else {
                format!("{c}*{n}")
            }
        })
        .collect();
    terms.join(" + ")
}

/// A float copy of a rational matrix, scaled so its largest entry has absolute value 1.
fn float_matrix(m: &[[RBig; 4]; 4]) -> [[f64; 4]; 4] {
    let f = m.clone().map(|row| row.map(|v| v.to_f64().value()));
    let max = f.iter().flatten().fold(0.0f64, |acc, v| acc.max(v.abs()));
    if max > 0.0 && max.is_finite() {
        f.map(|row| row.map(|v| v / max))
    } else {
        f
    }
}

/// The real singular points: kind key and affine coordinates (`None` at infinity), in the
/// order of [`Curve::singular_points`].
fn singular_points(view: &AffineView) -> Vec<(&'static str, Option<[f64; 3]>)> {
    let Ok(curve) = &view.curve else {
        return Vec::new();
    };
    curve
        .singular_points
        .iter()
        .map(|s| {
            let at = s.point.as_ref().map(|p| [0, 1, 2].map(|i| p[i].to_f64()));
            (s.kind.key(), at.filter(|p| p.iter().all(|v| v.is_finite())))
        })
        .collect()
}

/// How the cube was chosen (said in the legend).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Region {
    /// Around the bounded part of the curve.
    Bounded,
    /// Around the unbounded branches' points nearest the origin.
    Unbounded,
    /// No real point in ℝ³: around the surfaces.
    Surfaces,
    /// Only a common surface (no curve in ℝ³): around a point of it.
    Common,
}

/// The drawn cube (module docs).
fn region_of(
    sampled: &Sampled,
    singular: &[(&'static str, Option<[f64; 3]>)],
    view: &AffineView,
    surfaces: &[[[f64; 4]; 4]; 2],
    common: &[Common],
) -> (Cube, Region) {
    let finite = |p: &[f64; 3]| p.iter().all(|v| v.is_finite());
    let mut bounded: Vec<[f64; 3]> = singular.iter().filter_map(|s| s.1).collect();
    let mut nearest: Vec<[f64; 3]> = Vec::new();
    for piece in &sampled.pieces {
        if piece.affine.at_infinity {
            continue;
        }
        if piece.isolated || piece.affine.bounded {
            bounded.extend(piece.affine.branches.iter().flatten().filter(|p| finite(p)));
        } else {
            nearest.extend(piece.affine.branches.iter().filter_map(|b| {
                b.iter()
                    .filter(|p| finite(p))
                    .min_by(|p, q| norm(p).total_cmp(&norm(q)))
                    .copied()
            }));
        }
    }
    if let Some(cube) = Cube::around(&bounded) {
        return (cube, Region::Bounded);
    }
    if !nearest.is_empty() {
        let n = nearest.len() as f64;
        let mean = [0, 1, 2].map(|i| nearest.iter().map(|p| p[i]).sum::<f64>() / n);
        let spread = nearest
            .iter()
            .map(|p| norm(&[0, 1, 2].map(|i| p[i] - mean[i])))
            .fold(0.0, f64::max);
        let half = 2.0 * spread.max(norm(&mean) / 2.0);
        let half = if half > 0.0 && half.is_finite() {
            half
        } else {
            1.0
        };
        return (Cube { centre: mean, half }, Region::Unbounded);
    }
    let mut corners = Vec::new();
    let ellipsoids = view
        .surfaces
        .iter()
        .any(|s| s.is_some_and(|s| s.is_ellipsoid()));
    if let (Some((centre, half)), false) = (anchor(common), ellipsoids) {
        return (Cube { centre, half }, Region::Common);
    }
    for (k, name) in view.surfaces.iter().enumerate() {
        if name.is_some_and(|s| s.is_ellipsoid()) {
            if let Some((lo, hi)) = ellipsoid_box(&surfaces[k]) {
                corners.extend([lo, hi]);
            }
        }
    }
    let cube = Cube::around(&corners).unwrap_or(Cube {
        centre: [0.0; 3],
        half: 1.0,
    });
    (cube, Region::Surfaces)
}

/// The bounding box of the ellipsoid `[x 1] M [x 1]ᵀ = 0` (floats; `None` when the quadratic
/// part is not invertible or the ellipsoid has no real point).
fn ellipsoid_box(m: &[[f64; 4]; 4]) -> Option<([f64; 3], [f64; 3])> {
    let q = |i: usize, j: usize| m[i][j];
    // the adjugate of the 3×3 quadratic part
    let cof = |i: usize, j: usize| {
        let r: Vec<usize> = (0..3).filter(|&k| k != i).collect();
        let c: Vec<usize> = (0..3).filter(|&k| k != j).collect();
        let minor = q(r[0], c[0]) * q(r[1], c[1]) - q(r[0], c[1]) * q(r[1], c[0]);
        if (i + j) % 2 == 0 {
            minor
        } else {
            -minor
        }
    };
    let det = q(0, 0) * cof(0, 0) + q(0, 1) * cof(0, 1) + q(0, 2) * cof(0, 2);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let inv = |i: usize, j: usize| cof(j, i) / det;
    let g = [m[0][3], m[1][3], m[2][3]];
    let centre = [0, 1, 2].map(|i| -(0..3).map(|j| inv(i, j) * g[j]).sum::<f64>());
    // (x − c)ᵀQ(x − c) = k
    let k = -(m[3][3] + (0..3).map(|i| g[i] * centre[i]).sum::<f64>());
    let extent = [0, 1, 2].map(|i| k * inv(i, i));
    if extent.iter().any(|e| e.is_nan() || *e <= 0.0) {
        return None;
    }
    let e = extent.map(f64::sqrt);
    Some((
        [0, 1, 2].map(|i| centre[i] - e[i]),
        [0, 1, 2].map(|i| centre[i] + e[i]),
    ))
}

/// Everything the curve panel draws.
struct Scene {
    curve: Curve,
    sampled: Sampled,
    view: AffineView,
    singular: Vec<(&'static str, Option<[f64; 3]>)>,
    /// The surfaces' matrices in the chart's coordinates.
    surfaces: [[[f64; 4]; 4]; 2],
    /// The common surfaces (`A ∝ B`, a common plane), drawn after the pieces' colours.
    common: Vec<Common>,
    texts: [String; 2],
    cube: Cube,
    region: Region,
    camera: View,
    chart: String,
}

impl Scene {
    /// The curve, its points (two passes: the first fixes the cube, the second has chords
    /// within a pixel of it), the affine view and the cube.
    fn new(
        a: &Quadric,
        b: &Quadric,
        planes: [bool; 2],
        options: &PlotOptions,
    ) -> Result<Scene, String> {
        let curve = curve_of(Some(a), Some(b))?;
        let chart = Chart::new(options.chart.clone()).map_err(|e| e.to_string())?;
        let view = affine_view(Some(a), Some(b), &chart, planes);
        let mut sample_options = SampleOptions {
            points: options.points,
            tolerance: None,
            chart: options.chart.clone(),
        };
        let first = sample(&curve, &sample_options).map_err(|e| e.to_string())?;
        let surfaces = [a, b].map(|q| float_matrix(&chart.matrix_in_chart(q.matrix())));
        let singular = singular_points(&view);
        let common = common_of(&curve, &view, a, &chart, float_matrix);
        let (cube, region) = region_of(&first, &singular, &view, &surfaces, &common);
        sample_options.tolerance = Some(cube.half / 300.0);
        let sampled = sample(&curve, &sample_options).unwrap_or(first);
        Ok(Scene {
            curve,
            sampled,
            view,
            singular,
            surfaces,
            common,
            texts: [a, b].map(Quadric::to_polynomial_string),
            cube,
            region,
            camera: options.view,
            chart: chart_text(&options.chart),
        })
    }

    /// No real point in the chart.
    fn is_empty(&self) -> bool {
        self.sampled
            .pieces
            .iter()
            .all(|p| p.affine.at_infinity || p.affine.branches.is_empty())
            && self.common.iter().all(|c| c.matrix.is_none())
    }
}

/// A small picture of the curve of `a` and `b` (default chart and view) drawn into the page
/// rectangle `(left, top, width, height)`: the box, the surfaces faintly, the pieces in
/// their colours and the singular points, as in `qsic plot` without the legend; SVG elements
/// to place in a document.
///
/// # Errors
/// The message of [`plot_to_svg`].
pub fn snapshot(a: &Quadric, b: &Quadric, rect: (f64, f64, f64, f64)) -> Result<String, String> {
    let options = PlotOptions {
        points: 16,
        ..PlotOptions::default()
    };
    let scene = Scene::new(a, b, [false; 2], &options)?;
    let mut body = String::with_capacity(1 << 14);
    draw_scene(&mut body, &scene, rect, false);
    if scene.is_empty() {
        push_text(
            &mut body,
            rect.0 + rect.2 / 2.0,
            rect.1 + rect.3 / 2.0,
            "middle",
            "empty",
            "no real point",
        );
    }
    Ok(body)
}

/// An orthographic camera fitted to a page rectangle.
struct Camera {
    right: [f64; 3],
    up: [f64; 3],
    /// Towards the viewer.
    toward: [f64; 3],
    centre: [f64; 3],
    scale: f64,
    origin: (f64, f64),
}

impl Camera {
    /// Looks at `cube` from direction `view`, the cube's projection fitted into the page
    /// rectangle `(left, top, width, height)`.
    fn new(view: View, cube: &Cube, rect: (f64, f64, f64, f64)) -> Camera {
        let (az, el) = (view.azimuth.to_radians(), view.elevation.to_radians());
        let right = [-az.sin(), az.cos(), 0.0];
        let up = [-el.sin() * az.cos(), -el.sin() * az.sin(), el.cos()];
        let toward = [el.cos() * az.cos(), el.cos() * az.sin(), el.sin()];
        let mut camera = Camera {
            right,
            up,
            toward,
            centre: cube.centre,
            scale: 1.0,
            origin: (0.0, 0.0),
        };
        // the projected corners at scale 1
        let (mut w, mut h) = (0.0f64, 0.0f64);
        for k in 0..8 {
            let corner = [0, 1, 2].map(|i| {
                if k >> i & 1 == 1 {
                    cube.hi(i)
                } else {
                    cube.lo(i)
                }
            });
            let (x, y) = camera.project(&corner);
            w = w.max(x.abs());
            h = h.max(y.abs());
        }
        let (left, top, width, height) = rect;
        camera.scale = 0.95 * (width / (2.0 * w)).min(height / (2.0 * h));
        camera.origin = (left + width / 2.0, top + height / 2.0);
        camera
    }

    /// The signed distance of `p` from the plane through the cube's centre facing the
    /// viewer (positive in front).
    fn depth(&self, p: &[f64; 3]) -> f64 {
        (0..3)
            .map(|i| (p[i] - self.centre[i]) * self.toward[i])
            .sum()
    }

    /// `line` split where it crosses the plane of [`Camera::depth`] zero: runs with a flag,
    /// `true` behind.
    fn split_by_depth(&self, line: &[[f64; 3]]) -> Vec<(bool, Vec<[f64; 3]>)> {
        let mut out: Vec<(bool, Vec<[f64; 3]>)> = Vec::new();
        for (n, p) in line.iter().enumerate() {
            let behind = self.depth(p) < 0.0;
            match out.last_mut() {
                Some((b, run)) if *b == behind => run.push(*p),
                Some((_, run)) => {
                    // the crossing point ends one run and starts the next
                    let q = line[n - 1];
                    let (dq, dp) = (self.depth(&q), self.depth(p));
                    let t = dq / (dq - dp);
                    let x = [0, 1, 2].map(|i| q[i] + t * (p[i] - q[i]));
                    run.push(x);
                    out.push((behind, vec![x, *p]));
                }
                None => out.push((behind, vec![*p])),
            }
        }
        out
    }

    /// The page position of `p`.
    fn project(&self, p: &[f64; 3]) -> (f64, f64) {
        let d = [0, 1, 2].map(|i| p[i] - self.centre[i]);
        let dot = |v: &[f64; 3]| d[0] * v[0] + d[1] * v[1] + d[2] * v[2];
        (
            self.origin.0 + self.scale * dot(&self.right),
            self.origin.1 - self.scale * dot(&self.up),
        )
    }
}

/// Appends the path data `M x,y L x,y …` of `line` seen by `camera`.
fn push_path_data(out: &mut String, camera: &Camera, line: &[[f64; 3]]) {
    for (n, p) in line.iter().enumerate() {
        let (x, y) = camera.project(p);
        let _ = write!(out, "{}{x:.1},{y:.1}", if n == 0 { "M" } else { " L" });
    }
}

fn point_text(p: &[f64; 3]) -> String {
    format!("({}, {}, {})", short(p[0]), short(p[1]), short(p[2]))
}

/// The drawing rectangle of the curve panel.
const DRAW: (f64, f64, f64, f64) = (10.0, 40.0, 600.0, 580.0);
/// Left edge of the legend.
const LEGEND_X: f64 = 625.0;
/// Characters per legend line.
const LEGEND_CHARS: usize = 52;
/// Colours of the two surfaces' sections.
const SURFACE_COLOURS: [&str; 2] = ["#6f8299", "#99826f"];
/// Dashes of the two surfaces' sections (A solid, B dashed).
const SURFACE_DASHES: [&str; 2] = ["none", "4,3"];

/// The curve panel (module docs): the cube's edges with the axes' names and ranges, the
/// surfaces' sections (`<path class="surface">`), one `<g class="piece">` per real piece of
/// the curve in its own colour (clipped branches as paths, an isolated point as a dot), one
/// `<g class="singular">` per real singular point in ℝ³ with its kind, and the legend.
fn curve_panel(scene: &Scene) -> Panel {
    let mut body = String::with_capacity(1 << 16);
    push_text(
        &mut body,
        DRAW.0 + DRAW.2 / 2.0,
        24.0,
        "middle",
        "title",
        "The real intersection curve of A and B",
    );
    draw_scene(&mut body, scene, DRAW, true);
    if scene.is_empty() {
        let message = if scene.sampled.pieces.is_empty() && scene.common.is_empty() {
            "no real point: the real curve is empty"
        } else {
            "no real point in ℝ³: the real curve lies at infinity"
        };
        push_text(
            &mut body,
            DRAW.0 + DRAW.2 / 2.0,
            DRAW.1 + 40.0,
            "middle",
            "empty",
            message,
        );
    }
    let legend_bottom = push_legend(&mut body, scene);
    Panel {
        width: WIDTH,
        height: (DRAW.1 + DRAW.3 + 10.0).max(legend_bottom + 16.0),
        style: SCENE_STYLE.to_owned()
            + ".title{font-size:15px;font-weight:bold}.legend{font-size:12px}\
               .legend-head{font-size:12px;font-weight:bold}",
        body,
    }
}

/// The style rules of [`draw_scene`]'s elements.
pub(crate) const SCENE_STYLE: &str = ".axis{font-size:11px;fill:#555}\
    .box line{stroke:#999;stroke-width:0.6}\
    .surface{fill:none;stroke-width:0.7;stroke-opacity:0.45}\
    .piece{stroke-width:2.2;stroke-linejoin:round}.branch{fill:none}.far{stroke-opacity:0.45}\
    .isolated{stroke:#000;stroke-width:1}\
    .singular-mark{fill:#fff;stroke:#000;stroke-width:1.5}\
    .singular-label{font-size:11px;font-weight:bold}.empty{font-size:14px;fill:#b00}";

/// Draws the scene into the page rectangle `rect`: the cube's edges (with the axes' names
/// and ranges when `labels`), the surfaces' sections, the pieces and the singular points
/// (labelled by kind when `labels`).
fn draw_scene(body: &mut String, scene: &Scene, rect: (f64, f64, f64, f64), labels: bool) {
    let cube = &scene.cube;
    let camera = Camera::new(scene.camera, cube, rect);
    // the cube: hidden edges would need depth; all are drawn thin
    body.push_str("<g class=\"box\">\n");
    for k in 0..8usize {
        for i in 0..3 {
            if k >> i & 1 == 0 {
                let p = [0, 1, 2].map(|j| {
                    if k >> j & 1 == 1 {
                        cube.hi(j)
                    } else {
                        cube.lo(j)
                    }
                });
                let mut q = p;
                q[i] = cube.hi(i);
                let ((x1, y1), (x2, y2)) = (camera.project(&p), camera.project(&q));
                let _ = writeln!(
                    body,
                    "<line x1=\"{x1:.1}\" y1=\"{y1:.1}\" x2=\"{x2:.1}\" y2=\"{y2:.1}\"/>"
                );
            }
        }
    }
    let lo = [0, 1, 2].map(|i| cube.lo(i));
    for (i, name) in ["x", "y", "z"].iter().enumerate().filter(|_| labels) {
        let mut end = lo;
        end[i] = cube.hi(i);
        let (x, y) = camera.project(&end);
        let (x0, y0) = camera.project(&lo);
        let label = format!("{name} → {}", short(cube.hi(i)));
        // the label just beyond the edge's far end
        let (dx, dy) = (x - x0, y - y0);
        let len = (dx * dx + dy * dy).sqrt().max(1.0);
        push_text(
            body,
            x + 14.0 * dx / len,
            y + 14.0 * dy / len + 4.0,
            "middle",
            "axis",
            &label,
        );
    }
    body.push_str("</g>\n");

    // the surfaces, faintly
    for (k, m) in scene.surfaces.iter().enumerate() {
        let sections = surface_sections(m, cube, 5);
        let _ = write!(
            body,
            "<path class=\"surface\" data-surface=\"{}\" stroke=\"{}\" stroke-dasharray=\"{}\" d=\"",
            ["A", "B"][k],
            SURFACE_COLOURS[k],
            SURFACE_DASHES[k]
        );
        for line in &sections {
            push_path_data(body, &camera, line);
            body.push(' ');
        }
        body.push_str("\"/>\n");
    }

    // the pieces
    for (k, piece) in scene.sampled.pieces.iter().enumerate() {
        let kind = if piece.isolated {
            "point"
        } else {
            scene.curve.components[piece.component].kind.key()
        };
        let _ = writeln!(
            body,
            "<g class=\"piece\" data-piece=\"{k}\" data-kind=\"{kind}\" stroke=\"{}\" fill=\"{}\">",
            colour(k),
            colour(k)
        );
        let _ = write!(body, "<title>piece {}: {kind}</title>", k + 1);
        for branch in &piece.affine.branches {
            for line in clip_polyline(branch, cube) {
                if piece.isolated || line.len() == 1 {
                    let (x, y) = camera.project(&line[0]);
                    let _ = writeln!(
                        body,
                        "<circle class=\"isolated\" cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"6\"/>"
                    );
                } else {
                    // lighter behind the centre plane: a depth cue
                    for (behind, run) in camera.split_by_depth(&line) {
                        let class = if behind { "branch far" } else { "branch" };
                        let _ = write!(body, "<path class=\"{class}\" d=\"");
                        push_path_data(body, &camera, &run);
                        body.push_str("\"/>\n");
                    }
                }
            }
        }
        body.push_str("</g>\n");
    }

    // the common surfaces, in the colours after the pieces'
    let pieces = scene.sampled.pieces.len();
    for (k, c) in scene.common.iter().enumerate() {
        let Some(m) = &c.matrix else { continue };
        let _ = write!(
            body,
            "<g class=\"piece common\" data-piece=\"{}\" data-kind=\"surface\" data-name=\"{}\" stroke=\"{}\">",
            pieces + k,
            c.name,
            colour(pieces + k)
        );
        let _ = write!(
            body,
            "<title>common {}</title><path class=\"branch\" d=\"",
            c.name
        );
        for line in &surface_sections(m, cube, 7) {
            push_path_data(body, &camera, line);
            body.push(' ');
        }
        body.push_str("\"/></g>\n");
    }

    // the singular points in ℝ³
    for (kind, at) in &scene.singular {
        let Some(p) = at else { continue };
        let (x, y) = camera.project(p);
        let _ = write!(body, "<g class=\"singular\" data-kind=\"{kind}\">");
        push_title(body, &format!("{kind} at {}", point_text(p)));
        let _ = writeln!(
            body,
            "<rect class=\"singular-mark\" x=\"{:.1}\" y=\"{:.1}\" width=\"9\" height=\"9\" \
             transform=\"rotate(45 {x:.1} {y:.1})\"/>",
            x - 4.5,
            y - 4.5
        );
        if labels {
            push_text(body, x + 9.0, y - 7.0, "start", "singular-label", kind);
        }
        body.push_str("</g>\n");
    }
}

/// The legend of the curve panel at the right; returns its bottom.
fn push_legend(body: &mut String, scene: &Scene) -> f64 {
    let mut y = 40.0;
    // a legend entry wrapped into lines, continuation lines indented
    let line = |y: &mut f64, body: &mut String, class: &str, indent: f64, text: &str| {
        for (n, l) in wrap(text, LEGEND_CHARS).iter().enumerate() {
            let x = LEGEND_X + indent + if n > 0 { 10.0 } else { 0.0 };
            push_text(body, x, *y, "start", class, l);
            *y += 15.0;
        }
    };
    let names = scene
        .view
        .surfaces
        .map(|s| s.map_or("zero form", |s| s.key()));
    for k in 0..2 {
        line(
            &mut y,
            body,
            "legend",
            0.0,
            &format!("{}: {} = 0 ({})", ["A", "B"][k], scene.texts[k], names[k]),
        );
    }
    let c = crate::output::ClassificationJson::from(&scene.curve.classification);
    let class = match c.case {
        Some(k) => format!("{} pencil, case {k}", c.pencil),
        None => format!("{} pencil", c.pencil),
    };
    line(
        &mut y,
        body,
        "legend",
        0.0,
        &format!(
            "Class: {class}; complex type {}, real type {}",
            c.complex_type.unwrap_or("?"),
            c.real_type.unwrap_or("?")
        ),
    );
    line(
        &mut y,
        body,
        "legend",
        0.0,
        &format!(
            "In ℝ³ ({} = 0 at infinity): {}",
            scene.chart,
            scene.view.summary()
        ),
    );
    y += 6.0;
    line(&mut y, body, "legend-head", 0.0, "Real pieces (colours):");
    if scene.sampled.pieces.is_empty() && scene.common.is_empty() {
        line(
            &mut y,
            body,
            "legend",
            0.0,
            "none: the curve has no real point",
        );
    }
    for (k, piece) in scene.sampled.pieces.iter().enumerate() {
        let component = &scene.curve.components[piece.component];
        let what = if piece.isolated {
            match piece.affine.branches.first().and_then(|b| b.first()) {
                Some(p) => format!("isolated point {}", point_text(p)),
                None => "isolated point at infinity".into(),
            }
        } else {
            let mut s = component.kind.key().to_string();
            if component.multiplicity > 1 {
                let _ = write!(s, " (multiplicity {})", component.multiplicity);
            }
            if piece.affine.at_infinity {
                s.push_str(", at infinity (not drawn)");
            } else if piece.affine.bounded {
                s.push_str(", bounded");
            } else {
                s.push_str(", unbounded, clipped");
            }
            s
        };
        let _ = writeln!(
            body,
            "<rect class=\"swatch\" x=\"{LEGEND_X}\" y=\"{:.1}\" width=\"18\" height=\"5\" fill=\"{}\"/>",
            y - 6.0,
            colour(k)
        );
        line(&mut y, body, "legend", 24.0, &format!("{}: {what}", k + 1));
    }
    let pieces = scene.sampled.pieces.len();
    for (k, c) in scene.common.iter().enumerate() {
        let what = match c.matrix {
            Some(_) => format!("the common {}, drawn by its sections", c.name),
            None => format!("the common {}, at infinity (not drawn)", c.name),
        };
        let _ = writeln!(
            body,
            "<rect class=\"swatch\" x=\"{LEGEND_X}\" y=\"{:.1}\" width=\"18\" height=\"5\" fill=\"{}\"/>",
            y - 6.0,
            colour(pieces + k)
        );
        line(
            &mut y,
            body,
            "legend",
            24.0,
            &format!("{}: {what}", pieces + k + 1),
        );
    }
    let finite: Vec<_> = scene
        .singular
        .iter()
        .filter_map(|(k, p)| p.map(|p| (k, p)))
        .collect();
    let at_infinity = scene.singular.len() - finite.len();
    if !scene.singular.is_empty() {
        y += 6.0;
        line(&mut y, body, "legend-head", 0.0, "Singular points (◇):");
        for (kind, p) in &finite {
            line(
                &mut y,
                body,
                "legend",
                0.0,
                &format!("{kind} at {}", point_text(p)),
            );
        }
        if at_infinity > 0 {
            line(
                &mut y,
                body,
                "legend",
                0.0,
                &format!("{at_infinity} at infinity (not drawn)"),
            );
        }
    }
    y += 6.0;
    let cube = &scene.cube;
    let range = |i: usize| format!("[{}, {}]", short(cube.lo(i)), short(cube.hi(i)));
    let around = match scene.region {
        Region::Bounded => "around the bounded pieces, isolated and singular points",
        Region::Unbounded => "around the unbounded branches' points nearest the origin",
        Region::Surfaces if !scene.common.is_empty() => "around the surfaces",
        Region::Surfaces => "around the surfaces (no real point in ℝ³)",
        Region::Common => "around a point of the common surface",
    };
    let unbounded = scene
        .sampled
        .pieces
        .iter()
        .any(|p| !p.isolated && !p.affine.bounded && !p.affine.at_infinity);
    line(
        &mut y,
        body,
        "legend",
        0.0,
        &format!(
            "Box {} × {} × {}, {around}{}.",
            range(0),
            range(1),
            range(2),
            if unbounded {
                "; unbounded branches are clipped to it"
            } else {
                ""
            }
        ),
    );
    line(
        &mut y,
        body,
        "legend",
        0.0,
        "Faint lines: sections of A (solid) and B (dashed) by planes x, y, z = const. Curves \
         are lighter behind the plane through the box's centre facing the viewer.",
    );
    line(
        &mut y,
        body,
        "legend",
        0.0,
        &format!(
            "Orthographic view from azimuth {}°, elevation {}°.",
            short(scene.camera.azimuth),
            short(scene.camera.elevation)
        ),
    );
    y
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::eigencurve::{nice_ticks, symmetric_eigenvalues};
    use qsic_algebra::testing::SplitMix;

    /// Uniform in `[0, 1)`.
    fn unit(rng: &mut SplitMix) -> f64 {
        (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Eigenvalues of `R diag(e) Rᵀ` with `R` a product of random plane rotations are `e`.
    #[test]
    fn jacobi_recovers_known_eigenvalues() {
        let mut rng = SplitMix(3);
        for _ in 0..50 {
            let mut e = [0.0; 4];
            for v in &mut e {
                *v = (unit(&mut rng) - 0.5) * 20.0;
            }
            e[3] = e[1]; // a double eigenvalue too
            let mut m = [[0.0; 4]; 4];
            for i in 0..4 {
                m[i][i] = e[i];
            }
            for _ in 0..6 {
                let p = (rng.next_u64() % 4) as usize;
                let q = (p + 1 + (rng.next_u64() % 3) as usize) % 4;
                let (s, c) = f64::sin_cos(unit(&mut rng) * 6.0);
                // m ← G m Gᵀ with G the rotation in the (p, q) plane
                let mut g: [[f64; 4]; 4] =
                    std::array::from_fn(|i| std::array::from_fn(|j| f64::from(u8::from(i == j))));
                g[p][p] = c;
                g[q][q] = c;
                g[p][q] = -s;
                g[q][p] = s;
                let gm: [[f64; 4]; 4] = std::array::from_fn(|i| {
                    std::array::from_fn(|j| (0..4).map(|k| g[i][k] * m[k][j]).sum())
                });
                m = std::array::from_fn(|i| {
                    std::array::from_fn(|j| (0..4).map(|k| gm[i][k] * g[j][k]).sum())
                });
            }
            let mut want = e;
            want.sort_by(f64::total_cmp);
            let got = symmetric_eigenvalues(m);
            for (g, w) in got.iter().zip(&want) {
                assert!((g - w).abs() < 1e-9, "{got:?} {want:?}");
            }
        }
    }

    #[test]
    fn ticks_are_round_and_inside() {
        assert_eq!(nice_ticks(0.0, 6.0), [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        assert_eq!(nice_ticks(-1.3, 1.3), [-1.0, -0.5, 0.0, 0.5, 1.0]);
        assert!(nice_ticks(1.0, 1.0).is_empty());
        let t = nice_ticks(-0.0123, 0.0456);
        assert!(t.len() >= 4 && t.iter().all(|v| (-0.0123..=0.0456).contains(v)));
    }

    /// The camera maps the cube's centre to the rectangle's centre and keeps every corner in it;
    /// looking down the z axis, x goes right and y up.
    #[test]
    fn camera_fits_the_cube() {
        let cube = Cube {
            centre: [1.0, 2.0, 3.0],
            half: 2.0,
        };
        let rect = (10.0, 20.0, 300.0, 200.0);
        for view in [
            View::default(),
            View {
                azimuth: -120.0,
                elevation: 80.0,
            },
        ] {
            let cam = Camera::new(view, &cube, rect);
            let (x, y) = cam.project(&cube.centre);
            assert!((x - 160.0).abs() < 1e-9 && (y - 120.0).abs() < 1e-9);
            for k in 0..8 {
                let p = [0, 1, 2].map(|i| {
                    if k >> i & 1 == 1 {
                        cube.hi(i)
                    } else {
                        cube.lo(i)
                    }
                });
                let (x, y) = cam.project(&p);
                assert!(
                    (10.0..=310.0).contains(&x) && (20.0..=220.0).contains(&y),
                    "{x} {y}"
                );
            }
        }
        let top = Camera::new(
            View {
                azimuth: -90.0,
                elevation: 90.0,
            },
            &cube,
            rect,
        );
        let (x0, y0) = top.project(&cube.centre);
        let (x1, _) = top.project(&[2.0, 2.0, 3.0]);
        let (_, y1) = top.project(&[1.0, 3.0, 3.0]);
        assert!(x1 > x0 && y1 < y0);
    }

    /// A line through the cube's centre plane splits at a point of depth zero into a front
    /// and a back run that share it; the runs keep every original point in order.
    #[test]
    fn depth_split_at_the_centre_plane() {
        let cube = Cube {
            centre: [0.0; 3],
            half: 1.0,
        };
        let cam = Camera::new(View::default(), &cube, (0.0, 0.0, 100.0, 100.0));
        let t = cam.toward;
        let line: Vec<[f64; 3]> = (0..=10)
            .map(|k| {
                let s = k as f64 / 5.0 - 1.0 + 0.05;
                [t[0] * s + 0.1, t[1] * s, t[2] * s]
            })
            .collect();
        let runs = cam.split_by_depth(&line);
        assert_eq!(runs.len(), 2);
        assert!(runs[0].0 && !runs[1].0, "behind first, then in front");
        let shared = runs[0].1.last().unwrap();
        assert_eq!(Some(shared), runs[1].1.first());
        assert!(cam.depth(shared).abs() < 1e-12);
        let kept: Vec<[f64; 3]> = runs
            .iter()
            .flat_map(|(_, r)| r.iter().copied())
            .filter(|p| cam.depth(p).abs() > 1e-12)
            .collect();
        assert_eq!(kept, line);
        assert_eq!(cam.split_by_depth(&line[6..]).len(), 1);
    }

    #[test]
    fn short_numbers() {
        assert_eq!(short(2.0), "2");
        assert_eq!(short(-0.0), "0");
        assert_eq!(short(1.23456), "1.235");
        assert_eq!(short(-1e-7), "-1.00e-7");
        assert_eq!(short(123456.0), "1.23e5");
    }

    /// The ellipsoid's box from the float matrix: a sphere of radius 2 at (1, 0, 0), an
    /// ellipsoid with semi-axes 1, 2, 3, and none for a cylinder or an empty ellipsoid.
    #[test]
    fn ellipsoid_boxes() {
        let m = |q: &str| float_matrix(qsic::io::parse_quadric(q).unwrap().matrix());
        let (lo, hi) = ellipsoid_box(&m("(x-1)^2+y^2+z^2-4")).unwrap();
        for (got, want) in lo.iter().chain(&hi).zip([-1.0, -2.0, -2.0, 3.0, 2.0, 2.0]) {
            assert!((got - want).abs() < 1e-12, "{lo:?} {hi:?}");
        }
        let (lo, hi) = ellipsoid_box(&m("36*x^2+9*y^2+4*z^2-36")).unwrap();
        for (got, want) in lo.iter().chain(&hi).zip([-1.0, -2.0, -3.0, 1.0, 2.0, 3.0]) {
            assert!((got - want).abs() < 1e-12, "{lo:?} {hi:?}");
        }
        assert!(ellipsoid_box(&m("x^2+y^2-1")).is_none());
        assert!(ellipsoid_box(&m("x^2+y^2+z^2+1")).is_none());
    }
}

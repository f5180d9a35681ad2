//! Cost of `classify` with the affine view on natural-quadric pairs, by route: run under
//! callgrind (one thread) as `natural_cost ROUTE REPS`, ROUTE `natural` (the dispatch, natural
//! route first) or `general` (the general route alone), and subtract `natural_cost none 0`
//! (process start). Each pair is classified and its curve in ℝ³ computed REPS times.

use qsic::affine::{affine_view, Chart};
use qsic::io::parse_quadric;
use qsic::test_support::{classify_exact, general_affine_curve};

const PAIRS: &[(&str, &str)] = &[
    ("z-1/2", "x^2+y^2+z^2-1"),
    ("z-1", "x^2+y^2+z^2-1"),
    ("x+z", "x^2+y^2-1"),
    ("x-1", "x^2+y^2-1"),
    ("x+z-1", "x^2+y^2-z^2"),
    ("x", "x^2+y^2-z^2"),
    ("x^2+y^2+z^2-4", "(x-1)^2+y^2+z^2-4"),
    ("x^2+y^2+z^2-4", "(x-4)^2+y^2+z^2-4"),
    ("x^2+y^2+z^2-1", "x^2+y^2-1/4"),
    ("x^2+y^2-1", "(x-1)^2+y^2-1"),
    ("x^2+y^2-1", "(x-2)^2+y^2-1"),
    ("x^2+y^2-1", "(x-(2+1/10^9))^2+y^2-1"),
];

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let route = args.get(1).map_or("natural", String::as_str);
    let reps: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1);
    let pairs: Vec<_> = PAIRS
        .iter()
        .map(|(a, b)| (parse_quadric(a).unwrap(), parse_quadric(b).unwrap()))
        .collect();
    let chart = Chart::default();
    let mut sink = 0usize;
    for _ in 0..reps {
        for (a, b) in &pairs {
            match route {
                "natural" => {
                    let c = qsic::classify(a, b);
                    let v = affine_view(Some(a), Some(b), &chart, [false; 2]);
                    sink += usize::from(c.case.unwrap_or(0))
                        + v.curve.map_or(0, |c| c.components.len());
                }
                "general" => {
                    let c = classify_exact(a, b);
                    let v = general_affine_curve(a, b, &chart);
                    sink += usize::from(c.case.unwrap_or(0)) + v.map_or(0, |c| c.components.len());
                }
                _ => {}
            }
        }
    }
    println!("{sink}");
}

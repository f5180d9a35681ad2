//! `qsic._qsic`: the native half of the Python package `qsic` (the Python half, in
//! `python/qsic/__init__.py`, turns NumPy arrays and Python numbers into what these functions
//! take: exact number texts, or the raw bytes of `int64`/`float64` arrays).
//!
//! | function | answers |
//! |---|---|
//! | [`quadric_from_text`], [`quadric_from_entries`], [`quadric_from_machine`], [`quadric_from_shape`] | a [`NativeQuadric`] (or `None` for the zero form) |
//! | [`classify`] | the JSON line of `qsic classify --json` and the text report |
//! | [`classify_many`] | the columns of a batch, computed on all cores without the GIL |
//! | [`param`], [`sample`] | the JSON of `qsic param --json`, `qsic sample` |
//! | [`motion`], [`first_contact`] | the JSON of `qsic motion --json`, `qsic contact --json` |
//!
//! Every JSON text is made by the CLI crate's producers, so the Python dicts equal the CLI's
//! output. Errors are [`QsicError`] (a `ValueError`) carrying the library's message, with the
//! CLI's `A: `/`B: ` prefixes.

use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList, PyString};
use qsic::affine::Chart;
use qsic::io::{moving_matrix_from_rows, MovingMatrix};
use qsic::param::sample::SampleOptions;
use qsic::{classify_allowing_zero, Budget, Error, Quadric};
use qsic_algebra::RBig;
use qsic_cli::batch::{Answer, DEFAULT_LINE_BUDGET};
use qsic_cli::output::{classification_to_json_line, classify_report, ClassificationJson};
use rayon::prelude::*;
use std::collections::HashMap;
use std::panic::{self, AssertUnwindSafe};

create_exception!(
    qsic,
    QsicError,
    PyValueError,
    "Bad input for qsic: the message is the library's (a syntax error with its column, an entry (row,col), a limit, …)."
);

fn err(message: impl Into<String>) -> PyErr {
    QsicError::new_err(message.into())
}

/// A quadric as read, and whether it was written as a plane (its quadric the double plane).
#[pyclass(frozen, module = "qsic._qsic")]
pub struct NativeQuadric {
    quadric: Quadric,
    plane: bool,
}

#[pymethods]
impl NativeQuadric {
    /// The quadratic form as a polynomial in `x, y, z, w` (the matrix as given, not rescaled).
    fn polynomial(&self) -> String {
        self.quadric.to_polynomial_string()
    }

    /// The 16 entries of the symmetric matrix, row by row, as exact texts `p` or `p/q`.
    fn entries(&self) -> Vec<String> {
        self.quadric
            .matrix()
            .iter()
            .flatten()
            .map(ToString::to_string)
            .collect()
    }

    /// The input was a plane (a polynomial of degree 1), read as its double plane.
    fn is_plane(&self) -> bool {
        self.plane
    }

    /// Equal matrices (the same quadric with the same scale).
    fn equals(&self, other: &NativeQuadric) -> bool {
        self.quadric.matrix() == other.quadric.matrix()
    }
}

fn native(quadric: Quadric, plane: bool) -> NativeQuadric {
    NativeQuadric { quadric, plane }
}

/// `None` for the zero form, the quadric otherwise.
fn allow_zero(result: Result<Quadric, Error>) -> Result<Option<Quadric>, Error> {
    match result {
        Ok(q) => Ok(Some(q)),
        Err(Error::ZeroQuadric) => Ok(None),
        Err(e) => Err(e),
    }
}

/// A polynomial text (a degree-1 polynomial is a plane, read as its double plane) or a
/// JSON 4×4 array; `None` for the zero form.
#[pyfunction]
fn quadric_from_text(text: &str) -> PyResult<Option<NativeQuadric>> {
    let s = qsic_cli::input::surface_from_arg(text).map_err(|e| err(e.to_string()))?;
    Ok(s.quadric.map(|q| native(q, s.plane)))
}

/// A symmetric matrix from 16 exact number texts, row by row; `None` for the zero form.
#[pyfunction]
fn quadric_from_entries(texts: Vec<String>) -> PyResult<Option<NativeQuadric>> {
    let rows = rows_of(&texts).map_err(err)?;
    let q = allow_zero(qsic::io::quadric_from_array(&rows)).map_err(|e| err(e.to_string()))?;
    Ok(q.map(|q| native(q, false)))
}

/// A symmetric matrix from the native bytes of one 4×4 `int64` or `float64` array (`kind`
/// as in [`classify_many`]: `int64`, `float64`, `float64_shortest`), read as a batch row is,
/// without the 16 texts; `None` for the zero form.
#[pyfunction]
fn quadric_from_machine(kind: &str, data: &Bound<'_, PyAny>) -> PyResult<Option<NativeQuadric>> {
    let side = side(kind, data)?;
    if side.len() != 1 {
        return Err(err("the bytes of one 4×4 matrix"));
    }
    let q = side.quadric(0).map_err(err)?;
    Ok(q.map(|q| native(q, false)))
}

fn rows_of<S: AsRef<str>>(texts: &[S]) -> Result<[[&str; 4]; 4], String> {
    if texts.len() != 16 {
        return Err(format!(
            "a quadric matrix must be 4x4, got {} entries",
            texts.len()
        ));
    }
    Ok(std::array::from_fn(|i| {
        std::array::from_fn(|j| texts[4 * i + j].as_ref())
    }))
}

fn number(text: &str) -> Result<RBig, Error> {
    qsic::io::parse_number(text)
}

fn point(texts: &[String]) -> Result<[RBig; 3], Error> {
    if texts.len() != 3 {
        return Err(Error::InvalidShape(format!(
            "a point or vector has 3 coordinates, got {}",
            texts.len()
        )));
    }
    Ok([number(&texts[0])?, number(&texts[1])?, number(&texts[2])?])
}

fn pair(texts: &[String]) -> Result<[RBig; 2], Error> {
    if texts.len() != 2 {
        return Err(Error::InvalidShape(format!(
            "expected 2 values, got {}",
            texts.len()
        )));
    }
    Ok([number(&texts[0])?, number(&texts[1])?])
}

/// A shape of `qsic::shapes` by name; `args` are its parameters, each a list of number texts
/// (a point, a vector, squared semi-axes) or a one-element list (a scalar).
#[pyfunction]
fn quadric_from_shape(name: &str, args: Vec<Vec<String>>) -> PyResult<NativeQuadric> {
    let q = shape(name, &args).map_err(|e| err(e.to_string()))?;
    Ok(native(q, false))
}

fn shape(name: &str, args: &[Vec<String>]) -> Result<Quadric, Error> {
    use qsic::shapes as s;
    let arity = match name {
        "cylinder" | "cone" => 3,
        "plane_pair" => 4,
        _ => 2,
    };
    if args.len() != arity {
        return Err(Error::InvalidShape(format!(
            "{name} takes {arity} arguments, got {}",
            args.len()
        )));
    }
    let scalar = |k: usize| match args[k].as_slice() {
        [x] => number(x),
        _ => Err(Error::InvalidShape(format!(
            "argument {k} of {name} must be one number"
        ))),
    };
    let p = |k: usize| point(&args[k]);
    let two = |k: usize| pair(&args[k]);
    match name {
        "sphere" => s::sphere(&p(0)?, &scalar(1)?),
        "ellipsoid" => s::ellipsoid(&p(0)?, &p(1)?),
        "cylinder" => s::cylinder(&p(0)?, &p(1)?, &scalar(2)?),
        "elliptic_cylinder" => s::elliptic_cylinder(&two(0)?, &two(1)?),
        "cone" => s::cone(&p(0)?, &p(1)?, &scalar(2)?),
        "elliptic_cone" => s::elliptic_cone(&p(0)?, &two(1)?),
        "elliptic_paraboloid" => s::elliptic_paraboloid(&p(0)?, &two(1)?),
        "hyperbolic_paraboloid" => s::hyperbolic_paraboloid(&p(0)?, &two(1)?),
        "hyperboloid_one_sheet" => s::hyperboloid_one_sheet(&p(0)?, &p(1)?),
        "hyperboloid_two_sheets" => s::hyperboloid_two_sheets(&p(0)?, &p(1)?),
        "plane_pair" => s::plane_pair(&p(0)?, &scalar(1)?, &p(2)?, &scalar(3)?),
        _ => Err(Error::InvalidShape(format!("unknown shape '{name}'"))),
    }
}

/// The affine chart with `text = 0` at infinity (`None`: `w`), as `qsic classify --chart`.
fn chart_of(text: Option<&str>) -> PyResult<(Chart, String)> {
    match text {
        None => Ok((Chart::default(), "w".to_owned())),
        Some(text) => {
            let form = qsic_cli::sample::parse_chart(text).map_err(err)?;
            let chart = Chart::new(form).map_err(|e| err(e.to_string()))?;
            Ok((chart, text.to_owned()))
        }
    }
}

type Pair<'a> = (Option<&'a NativeQuadric>, Option<&'a NativeQuadric>);

fn quadrics<'a>(pair: Pair<'a>) -> (Option<&'a Quadric>, Option<&'a Quadric>, [bool; 2]) {
    let (a, b) = pair;
    (
        a.map(|q| &q.quadric),
        b.map(|q| &q.quadric),
        [a.is_some_and(|q| q.plane), b.is_some_and(|q| q.plane)],
    )
}

/// `f()`, or the message of its panic (a bug, reported instead of aborting the interpreter).
fn catch_panic<T>(f: impl FnOnce() -> T) -> Result<T, String> {
    panic::catch_unwind(AssertUnwindSafe(f)).map_err(|payload| {
        let what = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_default();
        format!("internal error (a bug): {what}")
    })
}

/// The JSON object of `qsic classify --json` (with the `"affine"` object unless `affine` is
/// false) and the text report of `qsic classify`.
#[pyfunction]
#[pyo3(signature = (a, b, affine = true, chart = None, budget = None))]
fn classify(
    py: Python<'_>,
    a: Option<PyRef<'_, NativeQuadric>>,
    b: Option<PyRef<'_, NativeQuadric>>,
    affine: bool,
    chart: Option<&str>,
    budget: Option<u64>,
) -> PyResult<(String, String)> {
    let (chart, chart_text) = chart_of(chart)?;
    let (qa, qb, planes) = quadrics((a.as_deref(), b.as_deref()));
    let budget = Budget::new(budget.unwrap_or(DEFAULT_LINE_BUDGET));
    py.detach(|| {
        catch_panic(|| {
            let c = classified(qa, qb, &budget)?;
            let mut line = classification_to_json_line(&c);
            let view = if affine {
                Some(
                    qsic::affine::affine_view_within(qa, qb, &chart, planes, &budget)
                        .map_err(|e| e.to_string())?,
                )
            } else {
                None
            };
            if let Some(view) = &view {
                line.pop();
                line.push_str(",\"affine\":");
                line.push_str(&qsic_cli::affine::to_json(view, &chart_text).to_string());
                line.push('}');
            }
            let text = classify_report(&c, view.as_ref(), &chart_text);
            Ok((line, text))
        })
        .and_then(|r| r)
    })
    .map_err(err)
}

/// One side of a batch: `N` matrices as the native bytes of an `int64` or `float64` array of
/// shape `(N, 4, 4)`, or `16·N` exact number texts with the messages of the rows the Python
/// half could not read (their texts are placeholders).
enum Side<'a> {
    Int(&'a [u8]),
    Float(&'a [u8]),
    /// `float64` bytes, each read as the shortest decimal that rounds to it.
    FloatShortest(&'a [u8]),
    Text {
        texts: Vec<String>,
        errors: HashMap<usize, String>,
    },
}

impl Side<'_> {
    fn len(&self) -> usize {
        match self {
            Side::Int(b) | Side::Float(b) | Side::FloatShortest(b) => b.len() / 128,
            Side::Text { texts, .. } => texts.len() / 16,
        }
    }

    /// The quadric of row `k` (`None`: the zero form), or why it cannot be read.
    fn quadric(&self, k: usize) -> Result<Option<Quadric>, String> {
        fn words(bytes: &[u8], k: usize) -> [[[u8; 8]; 4]; 4] {
            let row = &bytes[128 * k..128 * (k + 1)];
            std::array::from_fn(|i| {
                std::array::from_fn(|j| {
                    let at = 8 * (4 * i + j);
                    row[at..at + 8].try_into().expect("8 bytes")
                })
            })
        }
        let read = match self {
            Side::Int(bytes) => {
                let m = words(bytes, k).map(|r| r.map(i64::from_ne_bytes));
                allow_zero(Quadric::from_integers(m))
            }
            Side::Float(bytes) => {
                let m = words(bytes, k).map(|r| r.map(f64::from_ne_bytes));
                allow_zero(Quadric::from_f64(m))
            }
            Side::FloatShortest(bytes) => {
                let m = words(bytes, k).map(|r| r.map(f64::from_ne_bytes));
                let mut exact: [[RBig; 4]; 4] = Default::default();
                for (i, row) in m.iter().enumerate() {
                    for (j, &x) in row.iter().enumerate() {
                        exact[i][j] = qsic::io::shortest_decimal(x)
                            .ok_or(Error::NotFinite { row: i, col: j })
                            .map_err(|e| e.to_string())?;
                    }
                }
                allow_zero(Quadric::from_matrix(exact))
            }
            Side::Text { texts, errors } => {
                if let Some(message) = errors.get(&k) {
                    return Err(message.clone());
                }
                let rows = rows_of(&texts[16 * k..16 * (k + 1)]).expect("16 texts");
                allow_zero(qsic::io::quadric_from_array(&rows))
            }
        };
        read.map_err(|e| e.to_string())
    }
}

fn side<'a>(kind: &str, data: &'a Bound<'_, PyAny>) -> PyResult<Side<'a>> {
    let bytes = || -> PyResult<&'a [u8]> {
        let b = data.cast::<PyBytes>()?;
        let bytes = b.as_bytes();
        if bytes.len() % 128 != 0 {
            return Err(err("the bytes of an (N, 4, 4) array of 8-byte numbers"));
        }
        Ok(bytes)
    };
    match kind {
        "int64" => Ok(Side::Int(bytes()?)),
        "float64" => Ok(Side::Float(bytes()?)),
        "float64_shortest" => Ok(Side::FloatShortest(bytes()?)),
        "text" => {
            let (texts, errors): (Vec<String>, HashMap<usize, String>) = data.extract()?;
            if texts.len() % 16 != 0 {
                return Err(err("16 entries per matrix"));
            }
            if errors.keys().any(|&k| k >= texts.len() / 16) {
                return Err(err("an error for a row beyond the batch"));
            }
            Ok(Side::Text { texts, errors })
        }
        _ => Err(err(format!("unknown kind '{kind}'"))),
    }
}

/// What one row of a batch gives.
type Row = Result<(ClassificationJson, Option<String>), String>;

fn classify_row(
    a: &Side<'_>,
    b: &Side<'_>,
    k: usize,
    affine: Option<&(Chart, String)>,
    units: u64,
) -> Row {
    let qa = a.quadric(k).map_err(|e| format!("A: {e}"))?;
    let qb = b.quadric(k).map_err(|e| format!("B: {e}"))?;
    let budget = Budget::new(units);
    catch_panic(|| {
        let c = classified(qa.as_ref(), qb.as_ref(), &budget)?;
        let view = affine
            .map(|(chart, text)| {
                qsic_cli::affine::affine_json_within(
                    qa.as_ref(),
                    qb.as_ref(),
                    chart,
                    text,
                    [false, false],
                    &budget,
                )
                .map(|v| v.to_string())
            })
            .transpose()
            .map_err(|e| e.to_string())?;
        Ok((ClassificationJson::from(&c), view))
    })
    .and_then(|r| r)
}

/// The classification of a pair (either may be the zero form) spending `budget`.
fn classified(
    a: Option<&Quadric>,
    b: Option<&Quadric>,
    budget: &Budget,
) -> Result<qsic::Classification, String> {
    match (a, b) {
        (Some(a), Some(b)) => qsic::classify_within(a, b, budget).map_err(|e| e.to_string()),
        _ => classify_allowing_zero(a, b).map_err(|e| format!("A and B: both are zero: {e}")),
    }
}

/// The most threads [`classify_many`] takes: beyond the cores threads only add start-up and
/// scheduling cost; 256 is above the hardware threads of common machines and starts in a few
/// milliseconds, so no accepted value stalls the call on creating threads (`2³¹` threads
/// would exhaust the process's resources, `10⁵` take minutes to start).
const MAX_THREADS: usize = 256;

/// `threads` checked against `1..=MAX_THREADS`.
fn thread_count(threads: Option<i64>) -> PyResult<Option<usize>> {
    match threads {
        None => Ok(None),
        Some(t) => match usize::try_from(t) {
            Ok(t) if (1..=MAX_THREADS).contains(&t) => Ok(Some(t)),
            _ => Err(err(format!(
                "threads must be an integer from 1 to {MAX_THREADS}, got {t}"
            ))),
        },
    }
}

/// Python strings for the `&'static str` keys of the results, each made once per batch.
struct Strings<'py> {
    py: Python<'py>,
    made: HashMap<&'static str, Bound<'py, PyString>>,
}

impl<'py> Strings<'py> {
    fn get(&mut self, s: &'static str) -> Bound<'py, PyAny> {
        let py = self.py;
        self.made
            .entry(s)
            .or_insert_with(|| PyString::new(py, s))
            .clone()
            .into_any()
    }

    fn opt(&mut self, s: Option<&'static str>) -> Bound<'py, PyAny> {
        match s {
            Some(s) => self.get(s),
            None => self.py.None().into_bound(self.py),
        }
    }
}

/// Classifies row `k` of `a` against row `k` of `b` for every `k`, in parallel with the GIL
/// released (on `threads` threads, 1 to [`MAX_THREADS`], all cores by default; checked before
/// anything starts), and returns the columns: lists for
/// the string, list and error columns, the native bytes of an `int8` array for `case` (0:
/// none), and the `"affine"` objects as JSON texts when `affine`.
#[pyfunction]
#[pyo3(signature = (a_kind, a, b_kind, b, affine = false, chart = None, threads = None, budget = None))]
#[allow(clippy::too_many_arguments)]
fn classify_many<'py>(
    py: Python<'py>,
    a_kind: &str,
    a: &Bound<'py, PyAny>,
    b_kind: &str,
    b: &Bound<'py, PyAny>,
    affine: bool,
    chart: Option<&str>,
    threads: Option<i64>,
    budget: Option<u64>,
) -> PyResult<Bound<'py, PyDict>> {
    let units = budget.unwrap_or(DEFAULT_LINE_BUDGET);
    let threads = thread_count(threads)?;
    let a = side(a_kind, a)?;
    let b = side(b_kind, b)?;
    let n = a.len();
    if b.len() != n {
        return Err(err(format!(
            "A holds {n} matrices and B {}: the lengths must be equal",
            b.len()
        )));
    }
    let chart = if affine { Some(chart_of(chart)?) } else { None };
    let work = || -> Vec<Row> {
        (0..n)
            .into_par_iter()
            .map(|k| classify_row(&a, &b, k, chart.as_ref(), units))
            .collect()
    };
    let rows: Vec<Row> = py
        .detach(|| match threads {
            None => Ok(work()),
            Some(t) => rayon::ThreadPoolBuilder::new()
                .num_threads(t)
                .build()
                .map(|pool| pool.install(work))
                .map_err(|e| e.to_string()),
        })
        .map_err(err)?;
    columns(py, &rows, affine)
}

fn columns<'py>(py: Python<'py>, rows: &[Row], affine: bool) -> PyResult<Bound<'py, PyDict>> {
    let mut s = Strings {
        py,
        made: HashMap::new(),
    };
    let none = || py.None().into_bound(py);
    let names = [
        "pencil",
        "segre",
        "signature",
        "index_sequence",
        "complex_type",
        "real_type",
        "description",
    ];
    let mut text_columns: Vec<Vec<Bound<'py, PyAny>>> = names
        .iter()
        .map(|_| Vec::with_capacity(rows.len()))
        .collect();
    let mut cases = Vec::with_capacity(rows.len());
    let mut components = Vec::with_capacity(rows.len());
    let mut singular = Vec::with_capacity(rows.len());
    let mut affines = Vec::with_capacity(rows.len());
    let mut errors = Vec::with_capacity(rows.len());
    let (kind, multiplicity, count, closed) = (
        pyo3::intern!(py, "kind"),
        pyo3::intern!(py, "multiplicity"),
        pyo3::intern!(py, "count"),
        pyo3::intern!(py, "closed"),
    );
    for row in rows {
        match row {
            Ok((c, view)) => {
                let values = [
                    Some(c.pencil),
                    c.segre,
                    c.signature,
                    c.index_sequence,
                    c.complex_type,
                    c.real_type,
                    c.description,
                ];
                for (column, v) in text_columns.iter_mut().zip(values) {
                    column.push(s.opt(v));
                }
                cases.push(c.case.map_or(0, |k| k as i8));
                let list = PyList::empty(py);
                for comp in &c.components {
                    let d = PyDict::new(py);
                    d.set_item(kind, s.get(comp.kind))?;
                    d.set_item(multiplicity, comp.multiplicity)?;
                    d.set_item(count, comp.count)?;
                    d.set_item(closed, comp.closed)?;
                    list.append(d)?;
                }
                components.push(list.into_any());
                let list = PyList::empty(py);
                for p in &c.singular_points {
                    let d = PyDict::new(py);
                    d.set_item(kind, s.get(p.kind))?;
                    d.set_item(count, p.count)?;
                    list.append(d)?;
                }
                singular.push(list.into_any());
                affines.push(match view {
                    Some(v) => PyString::new(py, v).into_any(),
                    None => none(),
                });
                errors.push(none());
            }
            Err(message) => {
                for column in &mut text_columns {
                    column.push(none());
                }
                cases.push(0);
                components.push(none());
                singular.push(none());
                affines.push(none());
                errors.push(PyString::new(py, message).into_any());
            }
        }
    }
    let out = PyDict::new(py);
    for (name, column) in names.iter().zip(text_columns) {
        out.set_item(name, PyList::new(py, column)?)?;
    }
    let case_bytes: Vec<u8> = cases.iter().map(|&k| k as u8).collect();
    out.set_item("case", PyBytes::new(py, &case_bytes))?;
    out.set_item("components", PyList::new(py, components)?)?;
    out.set_item("singular_points", PyList::new(py, singular)?)?;
    if affine {
        out.set_item("affine", PyList::new(py, affines)?)?;
    }
    out.set_item("error", PyList::new(py, errors)?)?;
    Ok(out)
}

/// The JSON object a CLI answer (`qsic param`, `qsic sample`) gives for the pair, computed
/// without the GIL; a panic becomes an error.
fn answer_json(
    py: Python<'_>,
    answer: &(impl Answer + ?Sized),
    pair: Pair<'_>,
    budget: Option<u64>,
) -> PyResult<String> {
    let (qa, qb, planes) = quadrics(pair);
    let budget = Budget::new(budget.unwrap_or(DEFAULT_LINE_BUDGET));
    py.detach(|| {
        catch_panic(|| {
            answer
                .answer(qa, qb, planes, &budget)
                .map(|fields| format!("{{{fields}}}"))
        })
        .and_then(|r| r)
    })
    .map_err(err)
}

/// The JSON object of `qsic param --json` (`affine = false`: `--projective`; `chart`: `--chart`).
#[pyfunction]
#[pyo3(signature = (a, b, affine = true, chart = None, budget = None))]
fn param(
    py: Python<'_>,
    a: Option<PyRef<'_, NativeQuadric>>,
    b: Option<PyRef<'_, NativeQuadric>>,
    affine: bool,
    chart: Option<&str>,
    budget: Option<u64>,
) -> PyResult<String> {
    let answer = qsic_cli::param::Param {
        projective_only: !affine,
        chart: Some(chart_of(chart)?),
    };
    answer_json(py, &answer, (a.as_deref(), b.as_deref()), budget)
}

/// The JSON object of `qsic nurbs --json` (`bounds`: `--box`, six exact numbers
/// `X0,Y0,Z0,X1,Y1,Z1`), or with `step = true` the STEP text of `qsic nurbs --format step`.
#[pyfunction]
#[pyo3(signature = (a, b, bounds = None, step = false, budget = None, tolerance = None))]
fn nurbs(
    py: Python<'_>,
    a: Option<PyRef<'_, NativeQuadric>>,
    b: Option<PyRef<'_, NativeQuadric>>,
    bounds: Option<&str>,
    step: bool,
    budget: Option<u64>,
    tolerance: Option<f64>,
) -> PyResult<String> {
    let bounds = bounds
        .map(qsic_cli::nurbs::parse_box)
        .transpose()
        .map_err(err)?;
    let options = qsic::nurbs::NurbsOptions { bounds, tolerance };
    let format = if step {
        qsic_cli::nurbs::NurbsFormat::Step
    } else {
        qsic_cli::nurbs::NurbsFormat::Json
    };
    let (qa, qb, _) = quadrics((a.as_deref(), b.as_deref()));
    let budget = Budget::new(budget.unwrap_or(DEFAULT_LINE_BUDGET));
    py.detach(|| {
        catch_panic(|| qsic_cli::nurbs::render(qa, qb, &options, &budget, format)).and_then(|r| r)
    })
    .map_err(err)
}

/// The JSON object of `qsic sample --format json` with at least `points` points per piece,
/// chords within `tolerance` in the chart, and `chart = 0` at infinity (`None`: `w`);
/// `affine = false`: `--projective`.
#[pyfunction]
#[pyo3(signature = (a, b, points = 64, tolerance = None, chart = None, affine = true, budget = None))]
#[allow(clippy::too_many_arguments)]
fn sample(
    py: Python<'_>,
    a: Option<PyRef<'_, NativeQuadric>>,
    b: Option<PyRef<'_, NativeQuadric>>,
    points: usize,
    tolerance: Option<f64>,
    chart: Option<&str>,
    affine: bool,
    budget: Option<u64>,
) -> PyResult<String> {
    let mut options = SampleOptions {
        points,
        tolerance,
        ..SampleOptions::default()
    };
    if let Some(text) = chart {
        options.chart = qsic_cli::sample::parse_chart(text).map_err(err)?;
    }
    let answer = qsic_cli::sample::Sample {
        options,
        projective_only: !affine,
        chart_text: chart.unwrap_or("w").to_owned(),
    };
    answer_json(py, &answer, (a.as_deref(), b.as_deref()), budget)
}

/// A moving quadric: one text read as a `qsic motion` argument (a polynomial with
/// coefficients rational in `t`, or the JSON object of a rigid motion), or 16 texts.
fn moving(name: &str, texts: Vec<String>) -> PyResult<MovingMatrix> {
    if texts.len() == 1 {
        return qsic_cli::motion::moving_from_arg(&texts[0])
            .map_err(|e| err(format!("{name}: {e}")));
    }
    let rows: Vec<Vec<String>> = texts.chunks(4).map(<[String]>::to_vec).collect();
    moving_matrix_from_rows(&rows).map_err(|e| err(format!("{name}: {e}")))
}

/// The range `(t0, t1)` of `motion` and `first_contact`, read as `--range T0 T1` by the
/// library's one reader (`None`: an open side).
fn time_range(t0: Option<&str>, t1: Option<&str>) -> PyResult<qsic::motion::TimeRange> {
    qsic::motion::TimeRange::parse(t0.unwrap_or("-oo"), t1.unwrap_or("oo"))
        .map_err(|e| err(format!("range: {e}")))
}

/// The JSON object of `qsic motion --json --range T0 T1` (`None`: an open side), spending
/// at most `budget` work units (default [`DEFAULT_LINE_BUDGET`]).
#[pyfunction]
#[pyo3(signature = (a, b, t0 = None, t1 = None, budget = None))]
fn motion(
    py: Python<'_>,
    a: Vec<String>,
    b: Vec<String>,
    t0: Option<&str>,
    t1: Option<&str>,
    budget: Option<u64>,
) -> PyResult<String> {
    let (ma, mb) = (moving("A", a)?, moving("B", b)?);
    let range = time_range(t0, t1)?;
    let budget = Budget::new(budget.unwrap_or(DEFAULT_LINE_BUDGET));
    py.detach(|| {
        catch_panic(|| {
            qsic_cli::motion::analyze_within(ma, mb, &range, &budget)
                .map(|m| qsic_cli::motion::motion_to_json_line(&m))
                .map_err(|e| format!("A and B: {e}"))
        })
        .and_then(|r| r)
    })
    .map_err(err)
}

/// The JSON object of `qsic contact --json --range T0 T1` (`None`: an open side), spending
/// at most `budget` work units (default [`DEFAULT_LINE_BUDGET`]); with `first_only`, that of
/// `--first-only` (the instant alone).
#[pyfunction]
#[pyo3(signature = (a, b, t0 = None, t1 = None, budget = None, first_only = false))]
fn first_contact(
    py: Python<'_>,
    a: Vec<String>,
    b: Vec<String>,
    t0: Option<&str>,
    t1: Option<&str>,
    budget: Option<u64>,
    first_only: bool,
) -> PyResult<String> {
    let (ma, mb) = (moving("A", a)?, moving("B", b)?);
    let range = time_range(t0, t1)?;
    let budget = Budget::new(budget.unwrap_or(DEFAULT_LINE_BUDGET));
    py.detach(|| {
        catch_panic(|| {
            qsic_cli::contact::report_within(ma, mb, range, &budget, first_only)
                .map(|r| qsic_cli::contact::report_to_json_line(&r))
                .map_err(|e| format!("A and B: {e}"))
        })
        .and_then(|r| r)
    })
    .map_err(err)
}

#[pymodule]
fn _qsic(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("QsicError", m.py().get_type::<QsicError>())?;
    m.add("MAX_THREADS", MAX_THREADS)?;
    m.add("DEFAULT_BUDGET", DEFAULT_LINE_BUDGET)?;
    m.add("MAX_NUMBER_DIGITS", qsic::limits::MAX_NUMBER_DIGITS)?;
    m.add_class::<NativeQuadric>()?;
    m.add_function(wrap_pyfunction!(quadric_from_text, m)?)?;
    m.add_function(wrap_pyfunction!(quadric_from_entries, m)?)?;
    m.add_function(wrap_pyfunction!(quadric_from_machine, m)?)?;
    m.add_function(wrap_pyfunction!(quadric_from_shape, m)?)?;
    m.add_function(wrap_pyfunction!(classify, m)?)?;
    m.add_function(wrap_pyfunction!(classify_many, m)?)?;
    m.add_function(wrap_pyfunction!(param, m)?)?;
    m.add_function(wrap_pyfunction!(sample, m)?)?;
    m.add_function(wrap_pyfunction!(nurbs, m)?)?;
    m.add_function(wrap_pyfunction!(motion, m)?)?;
    m.add_function(wrap_pyfunction!(first_contact, m)?)?;
    Ok(())
}

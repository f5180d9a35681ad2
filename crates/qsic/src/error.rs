//! The one error type of the `qsic` crate.

use thiserror::Error;

/// Everything that can go wrong when building or reading a quadric.
///
/// A singular pencil, a quadric paired with itself or an empty intersection are
/// *classes*, never errors: classification of two valid quadrics cannot fail.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum Error {
    /// A polynomial or number string could not be read.
    ///
    /// `column` is the 1-based character position in the string where the problem starts.
    #[error("syntax error at column {column}: {message}")]
    Syntax {
        /// 1-based character column.
        column: usize,
        /// What was expected or found.
        message: String,
    },
    /// A name that is not one of the variables the reader allows (x, y, z, w for a quadric).
    #[error("unknown variable '{name}' at column {column} (allowed: {allowed})")]
    UnknownVariable {
        /// The name as written.
        name: String,
        /// 1-based character column.
        column: usize,
        /// The allowed variables, as a list: `x, y, z, w`.
        allowed: String,
    },
    /// A term whose degree is not allowed: above 2, or, in a form that uses `w`, not exactly 2.
    #[error("{message}")]
    Degree {
        /// Which term and why.
        message: String,
    },
    /// A matrix that is not 4×4.
    #[error("a quadric matrix must be 4x4, got {rows} rows{}", cols.map(|c| format!(" and a row of {c} entries")).unwrap_or_default())]
    Shape {
        /// Number of rows given.
        rows: usize,
        /// Length of the first row that is not 4 long, if any.
        cols: Option<usize>,
    },
    /// A matrix with `a[row][col] != a[col][row]` (0-based indices).
    #[error("matrix is not symmetric: entry ({row},{col}) = {a} but ({col},{row}) = {b}")]
    NotSymmetric {
        /// 0-based row.
        row: usize,
        /// 0-based column.
        col: usize,
        /// The value at (row, col).
        a: String,
        /// The value at (col, row).
        b: String,
    },
    /// All coefficients are zero: that is not a quadric.
    #[error("the zero form is not a quadric")]
    ZeroQuadric,
    /// A NaN or infinite floating-point value.
    #[error("entry ({row},{col}) is not a finite number")]
    NotFinite {
        /// 0-based row.
        row: usize,
        /// 0-based column.
        col: usize,
    },
    /// A number that cannot be read (e.g. a zero denominator).
    #[error("bad number '{text}': {message}")]
    BadNumber {
        /// The number as written.
        text: String,
        /// Why it was rejected.
        message: String,
    },
    /// An input larger than the documented limits (see [`crate::limits`]).
    #[error("input exceeds a limit: {what} (limit {limit})")]
    Limit {
        /// What is too large.
        what: String,
        /// The limit in force.
        limit: usize,
    },
    /// An entry of a matrix given as text could not be read (see [`crate::io::quadric_from_rows`]).
    #[error("entry ({row},{col}): {source}")]
    Entry {
        /// 0-based row.
        row: usize,
        /// 0-based column.
        col: usize,
        /// Why the entry was refused: [`Error::BadNumber`] or [`Error::Limit`].
        source: Box<Error>,
    },
    /// An invalid parameter of a shape constructor (e.g. a non-positive squared radius).
    #[error("invalid shape parameter: {0}")]
    InvalidShape(String),
    /// An option of a computation outside its range (e.g. a chord tolerance of
    /// [`crate::param::sample::sample`] that is not a positive finite number): says which
    /// option, the range and the value.
    #[error("invalid option: {0}")]
    InvalidOption(String),
    /// An affine chart that is not one (e.g. the zero form as the plane at infinity).
    #[error("invalid chart: {0}")]
    InvalidChart(String),
    /// A moving pencil outside what the motion analysis handles (no combination of minors
    /// separates the rank conditions; not expected).
    #[error("moving pencil not supported: {0}")]
    UnsupportedMotion(String),
    /// A time range `[t0, t1]` with `t0 > t1`; the message gives both.
    #[error("invalid time range: {0}")]
    InvalidRange(String),
    /// A quadric that does not bound a solid ellipsoid where one is needed
    /// ([`crate::solids`]): says which and what it is instead.
    #[error("not a solid ellipsoid: {0}")]
    NotEllipsoid(String),
    /// A parameterization this version cannot give: the class is not covered yet, or the
    /// sub-case needs an algebraic parameterization surface or a biquadratic field. Says which.
    #[error("parameterization not available: {0}")]
    Unsupported(String),
    /// An exact algebra step failed within its documented bounds (e.g. factoring in
    /// Legendre's theorem), or an internal consistency check of the parameterization.
    #[error("algebra: {0}")]
    Algebra(String),
}

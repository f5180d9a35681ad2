//! The one error type of the `qsic` crate, and [`shorten_numbers`], which every message
//! that names a user's number or text goes through.

use std::borrow::Cow;
use thiserror::Error;

/// Runs of more digits than this are shortened in messages by [`shorten_numbers`].
pub const LONG_NUMBER_DIGITS: usize = 40;

/// Digits kept at the start and at the end of a shortened number.
const KEPT_DIGITS: (usize, usize) = (10, 7);

/// `text` with every run of more than [`LONG_NUMBER_DIGITS`] decimal digits written as its
/// first ten and last seven digits and the digit count, `1234567890…4567890 (3000 digits)`;
/// shorter runs and everything else unchanged. A message naming a coefficient of thousands
/// of digits stays a line; the value itself is in the error's fields.
///
/// ```
/// use qsic::error::shorten_numbers;
/// let long = "1234567890".repeat(300);
/// assert_eq!(shorten_numbers(&format!("-{long}/7")), "-1234567890…4567890 (3000 digits)/7");
/// assert_eq!(shorten_numbers("entry (0,1) = 123/4"), "entry (0,1) = 123/4");
/// ```
pub fn shorten_numbers(text: &str) -> Cow<'_, str> {
    let b = text.as_bytes();
    let long_run = |start: usize| b[start..].iter().take_while(|c| c.is_ascii_digit()).count();
    let mut i = 0;
    let mut out: Option<String> = None;
    let mut copied = 0;
    while i < b.len() {
        if !b[i].is_ascii_digit() {
            i += 1;
            continue;
        }
        let len = long_run(i);
        if len > LONG_NUMBER_DIGITS {
            // Digits are ASCII: every cut below is a character boundary.
            let s = out.get_or_insert_with(|| String::with_capacity(text.len().min(256)));
            s.push_str(&text[copied..i]);
            s.push_str(&text[i..i + KEPT_DIGITS.0]);
            s.push('…');
            s.push_str(&text[i + len - KEPT_DIGITS.1..i + len]);
            s.push_str(&format!(" ({len} digits)"));
            copied = i + len;
        }
        i += len;
    }
    match out {
        None => Cow::Borrowed(text),
        Some(mut s) => {
            s.push_str(&text[copied..]);
            Cow::Owned(s)
        }
    }
}

/// Everything that can go wrong when building or reading a quadric.
///
/// A singular pencil, a quadric paired with itself or an empty intersection are
/// *classes*, never errors: classification of two valid quadrics cannot fail.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum Error {
    /// A polynomial or number string could not be read.
    ///
    /// `column` is the 1-based character position in the string where the problem starts.
    #[error("syntax error at column {column}: {}", shorten_numbers(.message))]
    Syntax {
        /// 1-based character column.
        column: usize,
        /// What was expected or found.
        message: String,
    },
    /// A name that is not one of the variables the reader allows (x, y, z, w for a quadric).
    #[error("unknown variable '{}' at column {column} (allowed: {allowed})", shorten_numbers(.name))]
    UnknownVariable {
        /// The name as written.
        name: String,
        /// 1-based character column.
        column: usize,
        /// The allowed variables, as a list: `x, y, z, w`.
        allowed: String,
    },
    /// A term whose degree is not allowed: above 2, or, in a form that uses `w`, not that of
    /// the form (2 for a quadric, 1 for a plane).
    #[error("{}", shorten_numbers(.message))]
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
    #[error(
        "matrix is not symmetric: entry ({row},{col}) = {} but ({col},{row}) = {}",
        shorten_numbers(.a),
        shorten_numbers(.b)
    )]
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
    #[error("bad number '{}': {}", shorten_numbers(.text), shorten_numbers(.message))]
    BadNumber {
        /// The number as written.
        text: String,
        /// Why it was rejected.
        message: String,
    },
    /// An input larger than the documented limits (see [`crate::limits`]).
    #[error("input exceeds a limit: {} (limit {limit})", shorten_numbers(.what))]
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
    #[error("invalid shape parameter: {}", shorten_numbers(.0))]
    InvalidShape(String),
    /// An option of a computation outside its range (e.g. a chord tolerance of
    /// [`crate::param::sample::sample`] that is not a positive finite number): says which
    /// option, the range and the value.
    #[error("invalid option: {0}")]
    InvalidOption(String),
    /// An affine chart that is not one (e.g. the zero form as the plane at infinity).
    #[error("invalid chart: {}", shorten_numbers(.0))]
    InvalidChart(String),
    /// A moving pencil outside what the motion analysis handles (no combination of minors
    /// separates the rank conditions; not expected).
    #[error("moving pencil not supported: {}", shorten_numbers(.0))]
    UnsupportedMotion(String),
    /// A time range that cannot be read or is empty (`t0 > t1`, a start at `+∞`, an end
    /// at `−∞`): says which end and why ([`crate::motion::TimeRange`]).
    #[error("invalid time range: {}", shorten_numbers(.0))]
    InvalidRange(String),
    /// A rigid motion that cannot be built: a zero rotation axis or quaternion path, a
    /// translation or quaternion component that is not a polynomial in `t`
    /// ([`crate::motion::rigid`]). Says which part and why.
    #[error("invalid rigid motion: {}", shorten_numbers(.0))]
    InvalidMotion(String),
    /// A quadric that does not bound a solid ellipsoid where one is needed
    /// ([`crate::solids`]): says which and what it is instead.
    #[error("not a solid ellipsoid: {}", shorten_numbers(.0))]
    NotEllipsoid(String),
    /// A parameterization this version cannot give: the class is not covered yet, or the
    /// sub-case needs an algebraic parameterization surface or a biquadratic field. Says which.
    #[error("parameterization not available: {}", shorten_numbers(.0))]
    Unsupported(String),
    /// An exact algebra step failed within its documented bounds (e.g. factoring in
    /// Legendre's theorem), or an internal consistency check of the parameterization.
    #[error("algebra: {}", shorten_numbers(.0))]
    Algebra(String),
    /// The computation spent its work budget ([`crate::Budget`]) before it was done: no
    /// answer, and nothing wrong with the input; a larger budget gives the answer.
    #[error(
        "over the work budget: {limit} units spent before the answer (a larger budget gives it)"
    )]
    BudgetExceeded {
        /// The budget's limit, in work units.
        limit: u64,
    },
}

impl From<qsic_algebra::Exhausted> for Error {
    fn from(e: qsic_algebra::Exhausted) -> Error {
        Error::BudgetExceeded { limit: e.limit }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_digit_runs_are_shortened_and_only_they() {
        let at_limit = "7".repeat(LONG_NUMBER_DIGITS);
        assert!(matches!(shorten_numbers(&at_limit), Cow::Borrowed(_)));
        let over = format!("1{at_limit}");
        assert_eq!(shorten_numbers(&over), "1777777777…7777777 (41 digits)");
        let two = format!("é {over}/{over}x, ({at_limit})");
        assert_eq!(
            shorten_numbers(&two),
            format!(
                "é 1777777777…7777777 (41 digits)/1777777777…7777777 (41 digits)x, ({at_limit})"
            )
        );
        // shortening is idempotent: the shortened form has no long run
        let once = shorten_numbers(&two).into_owned();
        assert_eq!(shorten_numbers(&once), once);
    }

    #[test]
    fn messages_shorten_the_numbers_they_name() {
        let n = "1234567890".repeat(300);
        let e = Error::NotSymmetric {
            row: 0,
            col: 1,
            a: n.clone(),
            b: format!("-{n}/3"),
        };
        assert_eq!(
            e.to_string(),
            "matrix is not symmetric: entry (0,1) = 1234567890…4567890 (3000 digits) but \
             (1,0) = -1234567890…4567890 (3000 digits)/3"
        );
        let e = Error::Degree {
            message: format!("term '{n}*x' has degree 1"),
        };
        assert_eq!(
            e.to_string(),
            "term '1234567890…4567890 (3000 digits)*x' has degree 1"
        );
        assert_eq!(
            Error::InvalidRange("the start 12 is above the end 3".into()).to_string(),
            "invalid time range: the start 12 is above the end 3"
        );
    }
}

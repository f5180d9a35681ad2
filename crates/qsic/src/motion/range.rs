//! The range of time of a motion: `[from, to]` with rational ends or `∓∞`, its one reading
//! from text (`--range T0 T1` of `qsic motion` and `qsic contact`, the `range` of the Python
//! functions) and the one spelling of infinity in their output; [`FirstContact`], the least
//! `t` of a range where a closed condition holds.

use crate::error::Error;
use crate::io::parse_number;
use qsic_algebra::{AlgebraicReal, RBig};

/// How `−∞` is written in every output: an open start of a range or an interval.
pub const MINUS_INFINITY: &str = "-oo";

/// How `+∞` is written in every output.
pub const PLUS_INFINITY: &str = "+oo";

/// The texts read as `−∞` by [`TimeRange::parse`].
const MINUS_INFINITY_SPELLINGS: [&str; 2] = ["-oo", "-inf"];

/// The texts read as `+∞` by [`TimeRange::parse`].
const PLUS_INFINITY_SPELLINGS: [&str; 4] = ["oo", "+oo", "inf", "+inf"];

/// A closed range `[from, to]` of `t` with rational ends; `None` for `∓∞`. Never empty:
/// `from ≤ to` when both are finite.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TimeRange {
    from: Option<RBig>,
    to: Option<RBig>,
}

/// One end of a range as written.
enum End {
    MinusInfinity,
    PlusInfinity,
    At(RBig),
}

/// Reads one end: a number as [`parse_number`] reads it, or a spelling of `±∞`.
fn read_end(text: &str, name: &str) -> Result<End, Error> {
    let trimmed = text.trim();
    if MINUS_INFINITY_SPELLINGS.contains(&trimmed) {
        return Ok(End::MinusInfinity);
    }
    if PLUS_INFINITY_SPELLINGS.contains(&trimmed) {
        return Ok(End::PlusInfinity);
    }
    parse_number(text)
        .map(End::At)
        .map_err(|e| Error::InvalidRange(format!("the {name} is not a number nor -oo / oo: {e}")))
}

impl TimeRange {
    /// The whole real line.
    pub fn all() -> TimeRange {
        TimeRange::default()
    }

    /// `[from, to]`.
    ///
    /// # Errors
    /// [`Error::InvalidRange`] if `from > to` (an empty range).
    pub fn new(from: Option<RBig>, to: Option<RBig>) -> Result<TimeRange, Error> {
        check_order(from.as_ref(), to.as_ref())?;
        Ok(TimeRange { from, to })
    }

    /// Reads a range from the texts of its ends, as `--range T0 T1` gives them: each an
    /// exact number ([`parse_number`]: `-2`, `1/3`, `0.25`, `1e-3`), or `-oo` (also `-inf`)
    /// for an open start and `oo` (`+oo`, `inf`, `+inf`) for an open end.
    ///
    /// # Errors
    /// [`Error::InvalidRange`] naming the end that is not a number, or saying why the range
    /// is empty: a start above the end, a start at `+∞`, an end at `−∞`.
    ///
    /// # Examples
    /// ```
    /// use qsic::motion::TimeRange;
    /// use qsic_algebra::RBig;
    ///
    /// let r = TimeRange::parse("-1/2", "oo")?;
    /// assert_eq!((r.from(), r.to()), (Some(&RBig::from_parts((-1).into(), 2u8.into())), None));
    /// assert_eq!(TimeRange::parse("-inf", "+oo")?, TimeRange::all());
    /// for empty in [("2", "1"), ("oo", "-oo"), ("-oo", "-oo"), ("oo", "oo")] {
    ///     assert!(TimeRange::parse(empty.0, empty.1).is_err());
    /// }
    /// # Ok::<(), qsic::Error>(())
    /// ```
    pub fn parse(t0: &str, t1: &str) -> Result<TimeRange, Error> {
        let (start, end) = (read_end(t0, "start")?, read_end(t1, "end")?);
        let empty = |why: &str| Err(Error::InvalidRange(format!("{why}: the range is empty")));
        let from = match start {
            End::PlusInfinity => return empty("the start is +oo"),
            End::MinusInfinity => None,
            End::At(v) => Some(v),
        };
        let to = match end {
            End::MinusInfinity => return empty("the end is -oo"),
            End::PlusInfinity => None,
            End::At(v) => Some(v),
        };
        TimeRange::new(from, to)
    }

    /// The start, `None` for `−∞`.
    pub fn from(&self) -> Option<&RBig> {
        self.from.as_ref()
    }

    /// The end, `None` for `+∞`.
    pub fn to(&self) -> Option<&RBig> {
        self.to.as_ref()
    }

    /// Whether `t` is after the start (strictly).
    pub(crate) fn after_start(&self, t: &AlgebraicReal) -> bool {
        self.from
            .as_ref()
            .is_none_or(|a| *t > AlgebraicReal::from_rational(a.clone()))
    }

    /// Whether `t` is not after the end.
    pub(crate) fn not_after_end(&self, t: &AlgebraicReal) -> bool {
        self.to
            .as_ref()
            .is_none_or(|b| *t <= AlgebraicReal::from_rational(b.clone()))
    }
}

/// [`Error::InvalidRange`] if `from > to`: the one message for an empty range.
pub(crate) fn check_order(from: Option<&RBig>, to: Option<&RBig>) -> Result<(), Error> {
    match (from, to) {
        (Some(a), Some(b)) if a > b => Err(Error::InvalidRange(format!(
            "the start {a} is above the end {b}: the range is empty"
        ))),
        _ => Ok(()),
    }
}

/// The least `t` of a range where a closed condition holds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FirstContact {
    /// It holds on a whole interval `(−∞, …)` of an unbounded range: there is no first `t`.
    FromMinusInfinity,
    /// The least `t` (the range's start if it holds there).
    At(AlgebraicReal),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_read_every_spelling_and_refuse_empty_ones() {
        let third = RBig::from_parts((-1).into(), 3u8.into());
        let r = TimeRange::parse(" -1/3 ", "0.25").expect("a range");
        assert_eq!(r.from(), Some(&third));
        assert_eq!(r.to(), Some(&RBig::from_parts(1.into(), 4u8.into())));
        for start in MINUS_INFINITY_SPELLINGS {
            for end in PLUS_INFINITY_SPELLINGS {
                assert_eq!(TimeRange::parse(start, end), Ok(TimeRange::all()));
            }
        }
        assert_eq!(
            TimeRange::parse("3", "3").map(|r| r.to().cloned()),
            Ok(Some(3.into()))
        );
        let refused = [
            (
                "2",
                "1",
                "the start 2 is above the end 1: the range is empty",
            ),
            ("oo", "-oo", "the start is +oo: the range is empty"),
            ("+inf", "1", "the start is +oo: the range is empty"),
            ("-oo", "-oo", "the end is -oo: the range is empty"),
            ("0", "-inf", "the end is -oo: the range is empty"),
            (
                "x",
                "1",
                "the start is not a number nor -oo / oo: bad number 'x'",
            ),
            (
                "1",
                "none",
                "the end is not a number nor -oo / oo: bad number 'none'",
            ),
        ];
        for (t0, t1, want) in refused {
            match TimeRange::parse(t0, t1) {
                Err(Error::InvalidRange(m)) => assert!(m.starts_with(want), "{t0} {t1}: {m}"),
                other => panic!("{t0} {t1}: {other:?}"),
            }
        }
        assert!(TimeRange::new(Some(RBig::ONE), Some(RBig::ZERO)).is_err());
    }
}

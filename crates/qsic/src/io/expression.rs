//! The expression reader: a lexer, then a Pratt parser over `+ − * /`, powers,
//! parentheses and implicit products that expands as it goes into a quotient of sparse
//! polynomials ([`MPoly`]), within the bounds of [`crate::limits`].

use super::number::{check_digits, excerpt, scan_numeral, NumeralError};
use crate::error::Error;
use crate::limits::{
    MAX_COEFFICIENT_BITS, MAX_DEGREE, MAX_EXPANSION_BITS, MAX_INPUT_LEN, MAX_NESTING_DEPTH,
    MAX_POWER_EXPONENT, MAX_TERMS, OVERHEAD_BITS,
};
use crate::quadric::push_number;
use dashu_ratio::RBig;
use qsic_algebra::mpoly::{bits, MPoly};
use std::fmt;

/// A variable the expression reader knows; its [`index`](Variable::index) numbers it in
/// the [`MPoly`] polynomials read.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Variable {
    /// `x`, index 0.
    X,
    /// `y`, index 1.
    Y,
    /// `z`, index 2.
    Z,
    /// `w`, index 3.
    W,
    /// `t`, index 4: the time of a moving quadric.
    T,
    /// `u`, index 5.
    U,
    /// `λ`, also written `lambda`, index 6: the parameter of a pencil.
    Lambda,
}

/// The names of the variables, by index (`λ` for [`Variable::Lambda`]).
pub const VARIABLE_NAMES: [&str; 7] = ["x", "y", "z", "w", "t", "u", "λ"];

impl Variable {
    /// Every variable, in the order of their indices.
    pub const ALL: [Variable; 7] = [
        Variable::X,
        Variable::Y,
        Variable::Z,
        Variable::W,
        Variable::T,
        Variable::U,
        Variable::Lambda,
    ];

    /// The index of the variable in an [`MPoly`].
    pub const fn index(self) -> usize {
        self as usize
    }

    /// The name, as printed.
    pub const fn name(self) -> &'static str {
        VARIABLE_NAMES[self.index()]
    }

    /// The variable written `name` (`λ` or `lambda` for [`Variable::Lambda`]).
    pub fn named(name: &str) -> Option<Variable> {
        match name {
            "lambda" => Some(Variable::Lambda),
            _ => Variable::ALL.into_iter().find(|v| v.name() == name),
        }
    }
}

/// The names of `vars`, as a list: `x, y, z, w`.
fn names(vars: &[Variable]) -> String {
    if vars.is_empty() {
        return "none".into();
    }
    vars.iter().map(|v| v.name()).collect::<Vec<_>>().join(", ")
}

/// A quotient of polynomials `numerator / denominator` in the variables of [`Variable`],
/// reduced by the rational content: the denominator has coprime integer coefficients and
/// a positive leading coefficient (that of its greatest monomial, [`MPoly`]'s order), and
/// is `1` when constant (so also for zero).
///
/// Common polynomial factors are not cancelled: `(t^2-1)/(t-1)` keeps its denominator.
/// Two quotients are the same function when `n₁·d₂ = n₂·d₁` ([`RationalFunction::same_as`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RationalFunction {
    numerator: MPoly,
    denominator: MPoly,
}

impl RationalFunction {
    /// `numerator / denominator` reduced by the rational content, or `None` if the
    /// denominator is zero or a variable without a name (index 7) occurs.
    pub fn new(numerator: MPoly, denominator: MPoly) -> Option<RationalFunction> {
        let unnamed = VARIABLE_NAMES.len();
        if denominator.is_zero() || numerator.uses(unnamed) || denominator.uses(unnamed) {
            return None;
        }
        let (numerator, denominator) = normalize(numerator, Some(denominator));
        Some(RationalFunction {
            numerator,
            denominator: denominator.unwrap_or_else(MPoly::one),
        })
    }

    /// The numerator.
    pub fn numerator(&self) -> &MPoly {
        &self.numerator
    }

    /// The denominator: coprime integer coefficients, positive leading coefficient.
    pub fn denominator(&self) -> &MPoly {
        &self.denominator
    }

    /// Numerator and denominator.
    pub fn into_parts(self) -> (MPoly, MPoly) {
        (self.numerator, self.denominator)
    }

    /// Whether the denominator is `1`.
    pub fn is_polynomial(&self) -> bool {
        self.denominator.is_one()
    }

    /// Whether the two are the same function: `n₁·d₂ = n₂·d₁`.
    pub fn same_as(&self, other: &RationalFunction) -> bool {
        if self.denominator == other.denominator {
            return self.numerator == other.numerator;
        }
        &self.numerator * &other.denominator == &other.numerator * &self.denominator
    }

    /// The value at `values` (indexed as [`Variable::index`]), or `None` where the
    /// denominator vanishes.
    ///
    /// # Panics
    /// If a variable that occurs has no value.
    pub fn eval(&self, values: &[RBig]) -> Option<RBig> {
        let den = self.denominator.eval(values);
        (!den.is_zero()).then(|| self.numerator.eval(values) / den)
    }
}

impl fmt::Display for RationalFunction {
    /// `numerator` alone if the denominator is 1, else `(numerator)/(denominator)`, in the
    /// syntax [`parse_rational_function`] reads: a coefficient longer than one numeral may
    /// be is written as a product of numerals (`(391*1e9999)`), as in
    /// [`Quadric::to_polynomial_string`](crate::Quadric::to_polynomial_string).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let write = |p: &MPoly| {
            p.to_string_with_numbers(&VARIABLE_NAMES, |c| {
                let mut s = String::new();
                push_number(&mut s, c);
                s
            })
        };
        let num = write(&self.numerator);
        if self.is_polynomial() {
            return f.write_str(&num);
        }
        write!(f, "({num})/({})", write(&self.denominator))
    }
}

/// `n / d` with `d` (if any) made primitive with a positive leading coefficient, and
/// `None` for a constant denominator (divided into `n`) or a zero numerator.
fn normalize(n: MPoly, d: Option<MPoly>) -> (MPoly, Option<MPoly>) {
    let Some(d) = d else {
        return (n, None);
    };
    if n.is_zero() {
        return (n, None);
    }
    if let Some(c) = d.as_constant() {
        return (n.scale(&(RBig::ONE / c)), None);
    }
    let mut c = d.content();
    if d.leading_coefficient() < RBig::ZERO {
        c = -c;
    }
    if c.is_one() {
        return (n, Some(d));
    }
    let inverse = RBig::ONE / c;
    (n.scale(&inverse), Some(d.scale(&inverse)))
}

/// Reads a rational function of the variables `allowed`: a polynomial expression in which
/// any division is allowed, expanded exactly into a numerator and a denominator.
///
/// # Grammar
/// A Pratt parser with these binding powers, loosest first:
///
/// ```text
/// a + b, a - b                 left-associative
/// a * b, a / b, a b            left-associative; juxtaposition before a variable or '('
/// +a, -a                       prefix signs: -x^2 is -(x^2), -x*y is (-x)*y
/// a^n, a**n                    n an integer literal of absolute value at most
///                              MAX_POWER_EXPONENT, written 2, -2, (-2) or (+2); chained
///                              powers x^2^2 are refused as ambiguous
/// ```
///
/// A negative power is a division: `t^-2` and `t**(-2)` are `1/t^2`, `(1+t)^-1` is
/// `1/(1+t)`, for any base that may be divided by (of [`parse_rational_function`], any
/// nonzero one; of a moving quadric, an expression in `t`; of a quadric, a number), within
/// the same limits as a positive power.
///
/// Atoms are numbers (unsigned numerals as in [`parse_number`](super::parse_number):
/// `3`, `0.25`, `1e-3`), variables (`x y z w t u`, and `λ` or `lambda`, those of
/// `allowed` only) and parenthesised expressions. A number after a complete operand
/// (`x 2`) is an error; write `2x`. The value is exact; the result is reduced by the
/// rational content only (see [`RationalFunction`]).
///
/// # Errors
/// - [`Error::Syntax`] with the 1-based character column for malformed input and for a
///   division by an expression that is identically zero (`1/(t-t)`, `0^-1`);
/// - [`Error::UnknownVariable`] for a name that is not in `allowed`;
/// - [`Error::Limit`] beyond the bounds of [`crate::limits`]: input length, digits,
///   decimal and power exponents, nesting, degree ([`MAX_DEGREE`], checked before each
///   product, naming the term), terms, coefficient sizes, total work.
///
/// # Examples
/// ```
/// use qsic::io::{parse_rational_function, Variable};
/// use dashu_ratio::RBig;
///
/// let f = parse_rational_function("(t^2 - 1)/(2*t^2 + 2)", &[Variable::T])?;
/// assert_eq!(f.to_string(), "(1/2*t^2 - 1/2)/(t^2 + 1)");
/// let at = |t: i32| f.eval(&[0, 0, 0, 0, t].map(RBig::from));
/// assert_eq!(at(3), Some(RBig::from_parts(2.into(), 5u8.into())));
///
/// assert!(parse_rational_function("1/(t - t)", &[Variable::T]).is_err());
/// assert!(parse_rational_function("x + t", &[Variable::T]).is_err());
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn parse_rational_function(
    text: &str,
    allowed: &[Variable],
) -> Result<RationalFunction, Error> {
    read(
        text,
        &Grammar {
            variables: allowed,
            denominator_variables: allowed,
            quadric: false,
        },
    )
}

/// What the reader accepts.
pub(crate) struct Grammar<'a> {
    /// The variables that may occur.
    pub variables: &'a [Variable],
    /// The variables that may occur in a divisor (others: a syntax error at the `/`).
    pub denominator_variables: &'a [Variable],
    /// The quadric reader: a product or power above degree 2 is an [`Error::Degree`]
    /// (else above [`MAX_DEGREE`] an [`Error::Limit`]), and an empty input is an "empty
    /// polynomial".
    pub quadric: bool,
}

/// Reads `text` by `grammar` (see [`parse_rational_function`]).
pub(crate) fn read(text: &str, grammar: &Grammar) -> Result<RationalFunction, Error> {
    if text.len() > MAX_INPUT_LEN {
        return Err(Error::Limit {
            what: format!("{} bytes in a polynomial string", text.len()),
            limit: MAX_INPUT_LEN,
        });
    }
    let mut budget = Budget {
        left: MAX_EXPANSION_BITS,
    };
    let tokens = tokenize(text, grammar.variables, &mut budget)?;
    let mut parser = Parser {
        text,
        tokens,
        pos: 0,
        depth: 0,
        budget,
        grammar,
    };
    let value = parser.parse()?;
    Ok(RationalFunction {
        numerator: value.num,
        denominator: value.den.unwrap_or_else(MPoly::one),
    })
}

/// What is left of [`MAX_EXPANSION_BITS`] for reading one expression.
#[derive(Debug)]
struct Budget {
    left: usize,
}

impl Budget {
    /// Takes `cost` from the budget.
    fn charge(&mut self, cost: usize) -> Result<(), Error> {
        match self.left.checked_sub(cost) {
            Some(left) => {
                self.left = left;
                Ok(())
            }
            None => Err(Error::Limit {
                what: "total size of the numbers computed while expanding the polynomial, in bits"
                    .into(),
                limit: MAX_EXPANSION_BITS,
            }),
        }
    }
}

/// Refuses a polynomial with too many terms or too large a coefficient.
fn check_size(p: &MPoly) -> Result<(), Error> {
    if p.num_terms() > MAX_TERMS {
        return Err(Error::Limit {
            what: format!("{} terms while expanding the polynomial", p.num_terms()),
            limit: MAX_TERMS,
        });
    }
    let largest = p.max_bits();
    if largest > MAX_COEFFICIENT_BITS {
        return Err(coefficient_limit(largest));
    }
    Ok(())
}

/// The refusal of a coefficient of `bits` bits.
#[cold]
fn coefficient_limit(bits: usize) -> Error {
    Error::Limit {
        what: format!("a coefficient of {bits} bits while expanding the polynomial"),
        limit: MAX_COEFFICIENT_BITS,
    }
}

/// `Σ (bits + OVERHEAD_BITS)` over the coefficients of `p`.
fn weight(p: &MPoly) -> usize {
    p.terms()
        .iter()
        .map(|(_, c)| bits(c) + OVERHEAD_BITS)
        .fold(0, usize::saturating_add)
}

/// A value met while reading: `num / den`, `den` normalised as in [`normalize`] (`None`
/// stands for 1).
#[derive(Debug)]
struct Value {
    num: MPoly,
    den: Option<MPoly>,
}

impl Value {
    fn polynomial(num: MPoly) -> Value {
        Value { num, den: None }
    }
}

/// A lexical token.
#[derive(Debug)]
enum Tok {
    Number(RBig),
    Variable(Variable),
    Plus,
    Minus,
    Star,
    Slash,
    /// `^` or `**`.
    Power,
    Open,
    Close,
    End,
}

/// A token with its place: 1-based character column and byte range.
#[derive(Debug)]
struct Token {
    tok: Tok,
    column: usize,
    start: usize,
    end: usize,
}

/// Splits `text` into tokens, ending with [`Tok::End`]; names must be in `variables`.
fn tokenize(text: &str, variables: &[Variable], budget: &mut Budget) -> Result<Vec<Token>, Error> {
    // A token takes at least one byte: no growth for short texts.
    let mut tokens = Vec::with_capacity((text.len() + 1).min(1024));
    let mut column = 1;
    let mut rest = text.char_indices().peekable();
    while let Some((start, ch)) = rest.next() {
        let mut len = ch.len_utf8();
        let mut width = 1;
        let tok = match ch {
            c if c.is_whitespace() => {
                column += 1;
                continue;
            }
            '+' => Tok::Plus,
            '-' => Tok::Minus,
            '/' => Tok::Slash,
            '^' => Tok::Power,
            '(' => Tok::Open,
            ')' => Tok::Close,
            '*' if rest.next_if(|&(_, c)| c == '*').is_some() => {
                (len, width) = (2, 2);
                Tok::Power
            }
            '*' => Tok::Star,
            '0'..='9' | '.' => {
                let (numeral, n) = scan_numeral(&text[start..]).map_err(|e| match e {
                    NumeralError::Limit(limit) => limit,
                    NumeralError::Malformed { message, .. } => Error::Syntax { column, message },
                })?;
                check_digits(numeral.digit_count())?;
                // A numeral is ASCII: its byte length is its width in characters.
                (len, width) = (n, n);
                if n > 1 {
                    rest.nth(n - 2);
                }
                let value = numeral.value();
                budget.charge(bits(&value) + OVERHEAD_BITS)?;
                Tok::Number(value)
            }
            c if c.is_alphabetic() || c == '_' => {
                while rest
                    .next_if(|&(_, c)| c.is_alphabetic() || c.is_ascii_digit() || c == '_')
                    .is_some()
                {}
                let end = rest.peek().map_or(text.len(), |&(i, _)| i);
                let name = &text[start..end];
                match Variable::named(name).filter(|v| variables.contains(v)) {
                    Some(v) => {
                        len = end - start;
                        width = name.chars().count();
                        Tok::Variable(v)
                    }
                    None => {
                        return Err(Error::UnknownVariable {
                            name: excerpt(name),
                            column,
                            allowed: names(variables),
                        })
                    }
                }
            }
            c => {
                return Err(Error::Syntax {
                    column,
                    message: format!("unexpected character '{c}'"),
                })
            }
        };
        tokens.push(Token {
            tok,
            column,
            start,
            end: start + len,
        });
        column += width;
    }
    tokens.push(Token {
        tok: Tok::End,
        column,
        start: text.len(),
        end: text.len(),
    });
    Ok(tokens)
}

/// The infix operators, juxtaposition included.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Op {
    Add,
    Sub,
    Mul,
    Div,
    Juxtapose,
}

/// The Pratt parser over the tokens, expanding as it goes.
struct Parser<'a> {
    text: &'a str,
    tokens: Vec<Token>,
    pos: usize,
    /// Open parentheses around the current token.
    depth: usize,
    budget: Budget,
    grammar: &'a Grammar<'a>,
}

impl Parser<'_> {
    fn peek(&self) -> &Token {
        // The last token is End and is never consumed, so `pos` stays in range.
        &self.tokens[self.pos.min(self.tokens.len() - 1)]
    }

    fn advance(&mut self) {
        if !matches!(self.peek().tok, Tok::End) {
            self.pos += 1;
        }
    }

    fn syntax(column: usize, message: impl Into<String>) -> Error {
        Error::Syntax {
            column,
            message: message.into(),
        }
    }

    /// What the current token is, for messages.
    fn describe(&self) -> String {
        let t = self.peek();
        match t.tok {
            Tok::End => "the end of the input".into(),
            Tok::Number(_) => format!("the number '{}'", excerpt(&self.text[t.start..t.end])),
            _ => format!("'{}'", &self.text[t.start..t.end]),
        }
    }

    /// The whole input as one value.
    fn parse(&mut self) -> Result<Value, Error> {
        if matches!(self.peek().tok, Tok::End) {
            let what = if self.grammar.quadric {
                "polynomial"
            } else {
                "expression"
            };
            return Err(Self::syntax(1, format!("empty {what}")));
        }
        let value = self.expression(0)?;
        let column = self.peek().column;
        match self.peek().tok {
            Tok::End => Ok(value),
            Tok::Close => Err(Self::syntax(column, "unmatched ')'")),
            Tok::Number(_) => Err(Self::syntax(
                column,
                format!(
                    "expected an operator before {}; write the number first, as in '2*x' or '2x'",
                    self.describe()
                ),
            )),
            _ => Err(Self::syntax(
                column,
                format!("expected an operator, found {}", self.describe()),
            )),
        }
    }

    /// The operators binding at least as tightly as `min_power`, left-associative: an
    /// operand, then `(operator operand)*` with each right operand read at one more.
    /// Recursion: at most three frames of this function per level of parentheses.
    fn expression(&mut self, min_power: u8) -> Result<Value, Error> {
        let first = self.pos;
        let mut lhs = self.signed_power()?;
        loop {
            let (op, power) = match self.peek().tok {
                Tok::Plus => (Op::Add, 1),
                Tok::Minus => (Op::Sub, 1),
                Tok::Star => (Op::Mul, 3),
                Tok::Slash => (Op::Div, 3),
                Tok::Variable(_) | Tok::Open => (Op::Juxtapose, 3),
                _ => break,
            };
            if power < min_power {
                break;
            }
            let column = self.peek().column;
            if op != Op::Juxtapose {
                self.advance();
            }
            let rhs = self.expression(power + 1)?;
            lhs = match op {
                Op::Add => self.add(lhs, rhs, false, first)?,
                Op::Sub => self.add(lhs, rhs, true, first)?,
                Op::Mul | Op::Juxtapose => self.mul(lhs, rhs, first)?,
                Op::Div => self.div(lhs, rhs, column, first)?,
            };
        }
        Ok(lhs)
    }

    /// A run of prefix signs (read by a loop, not recursion), then a power.
    fn signed_power(&mut self) -> Result<Value, Error> {
        let mut negative = false;
        while let Tok::Plus | Tok::Minus = self.peek().tok {
            negative ^= matches!(self.peek().tok, Tok::Minus);
            self.advance();
        }
        let mut value = self.power()?;
        if negative {
            value.num = -value.num;
        }
        Ok(value)
    }

    /// An atom, then optionally `^n`; a negative `n` divides 1 by `atom^|n|` (so only a
    /// base the grammar may divide by, and never zero).
    fn power(&mut self) -> Result<Value, Error> {
        let first = self.pos;
        let base = self.atom()?;
        if !matches!(self.peek().tok, Tok::Power) {
            return Ok(base);
        }
        self.advance();
        let column = self.peek().column;
        let (negative, n) = self.exponent()?;
        if matches!(self.peek().tok, Tok::Power) {
            return Err(Self::syntax(
                self.peek().column,
                "chained powers are ambiguous; use parentheses, as in '(x^2)^2'",
            ));
        }
        let value = self.pow(base, n, first)?;
        if !negative {
            return Ok(value);
        }
        let one = Value::polynomial(MPoly::one());
        self.div(one, value, column, first).map_err(|e| match e {
            Error::Syntax { column, message } => Error::Syntax {
                column,
                message: format!("a negative power is a division: {message}"),
            },
            e => e,
        })
    }

    /// The exponent after `^`: an integer literal, `-` and one, or either in parentheses
    /// with an optional sign (`2`, `-2`, `(-2)`, `(+2)`); whether it is negative, and its
    /// absolute value, at most [`MAX_POWER_EXPONENT`].
    fn exponent(&mut self) -> Result<(bool, u32), Error> {
        let open = matches!(self.peek().tok, Tok::Open).then(|| self.peek().column);
        if open.is_some() {
            self.advance();
        }
        let mut negative = false;
        match self.peek().tok {
            Tok::Minus => {
                negative = true;
                self.advance();
            }
            Tok::Plus if open.is_some() => self.advance(),
            _ => {}
        }
        let t = self.peek();
        let raw = &self.text[t.start..t.end];
        let column = t.column;
        if !matches!(t.tok, Tok::Number(_)) || !raw.bytes().all(|b| b.is_ascii_digit()) {
            return Err(Self::syntax(
                column,
                format!("the exponent must be an integer, found {}", self.describe()),
            ));
        }
        let digits = raw.trim_start_matches('0');
        let n = match digits.parse::<u32>() {
            Ok(n) if n as usize <= MAX_POWER_EXPONENT => n,
            _ if digits.is_empty() => 0,
            _ => {
                return Err(Error::Limit {
                    what: format!("exponent {} at column {column}", excerpt(raw)),
                    limit: MAX_POWER_EXPONENT,
                })
            }
        };
        self.advance();
        if let Some(open) = open {
            if !matches!(self.peek().tok, Tok::Close) {
                return Err(Self::syntax(
                    self.peek().column,
                    format!(
                        "expected ')' to close the '(' at column {open}, found {}",
                        self.describe()
                    ),
                ));
            }
            self.advance();
        }
        Ok((negative, n))
    }

    fn atom(&mut self) -> Result<Value, Error> {
        let column = self.peek().column;
        let here = self.pos.min(self.tokens.len() - 1);
        let value = match &mut self.tokens[here].tok {
            // Each token is read once: its number can be moved out.
            Tok::Number(v) => Value::polynomial(MPoly::constant(std::mem::take(v))),
            Tok::Variable(v) => Value::polynomial(MPoly::var(v.index())),
            Tok::Open => {
                if self.depth >= MAX_NESTING_DEPTH {
                    return Err(Error::Limit {
                        what: format!("nesting of parentheses at column {column}"),
                        limit: MAX_NESTING_DEPTH,
                    });
                }
                self.depth += 1;
                self.advance();
                let inner = self.expression(0)?;
                if !matches!(self.peek().tok, Tok::Close) {
                    return Err(Self::syntax(
                        self.peek().column,
                        format!(
                            "expected ')' to close the '(' at column {column}, found {}",
                            self.describe()
                        ),
                    ));
                }
                self.depth -= 1;
                inner
            }
            _ => {
                return Err(Self::syntax(
                    column,
                    format!(
                        "expected a number, a variable or '(', found {}",
                        self.describe()
                    ),
                ))
            }
        };
        self.advance();
        Ok(value)
    }

    /// The error for a product or power of degree `degree` above the bound, naming the
    /// source text from token `first` to the last one read.
    fn degree_error(&self, first: usize, degree: u32) -> Error {
        let last = self.tokens.len() - 1;
        let from = &self.tokens[first.min(last)];
        let to = &self.tokens[self.pos.saturating_sub(1).max(first).min(last)];
        let snippet = excerpt(self.text[from.start..to.end.max(from.start)].trim());
        if self.grammar.quadric {
            Error::Degree {
                message: format!(
                    "term '{snippet}' at column {} has degree {degree}; a quadric has degree at most 2",
                    from.column
                ),
            }
        } else {
            Error::Limit {
                what: format!("degree {degree} of '{snippet}' at column {}", from.column),
                limit: MAX_DEGREE as usize,
            }
        }
    }

    fn max_degree(&self) -> u32 {
        if self.grammar.quadric {
            2
        } else {
            MAX_DEGREE
        }
    }

    /// `a · b` within the bounds: degree and work checked before, sizes after.
    fn mul_poly(&mut self, a: MPoly, b: MPoly, first: usize) -> Result<MPoly, Error> {
        if a.is_zero() || b.is_zero() {
            return Ok(MPoly::zero());
        }
        let degree = a.total_degree() + b.total_degree();
        if degree > self.max_degree() {
            return Err(self.degree_error(first, degree));
        }
        let (wa, wb) = (weight(&a), weight(&b));
        let cost = wa
            .saturating_mul(b.num_terms())
            .saturating_add(wb.saturating_mul(a.num_terms()));
        self.budget.charge(cost)?;
        let p = a * b;
        check_size(&p)?;
        Ok(p)
    }

    /// `a ± b` within the bounds: the terms of `b` and the moves of those of `a` charged.
    fn add_poly(&mut self, a: MPoly, b: &MPoly, negative: bool) -> Result<MPoly, Error> {
        self.budget
            .charge(weight(b).saturating_add(a.num_terms()))?;
        let p = if negative { a - b } else { a + b };
        match b.terms() {
            // Only one coefficient changed.
            [(m, _)] if p.num_terms() <= MAX_TERMS => {
                let changed = p.coefficient(m).map_or(0, bits);
                if changed > MAX_COEFFICIENT_BITS {
                    return Err(coefficient_limit(changed));
                }
            }
            _ => check_size(&p)?,
        }
        Ok(p)
    }

    /// `p · c` for a constant `c`, within the bounds.
    fn scale(&mut self, p: &MPoly, c: &RBig) -> Result<MPoly, Error> {
        let p = p.scale(c);
        self.budget.charge(weight(&p))?;
        check_size(&p)?;
        Ok(p)
    }

    /// `n / d` normalised ([`normalize`]), within the bounds.
    fn quotient(&mut self, n: MPoly, d: Option<MPoly>) -> Result<Value, Error> {
        let (num, den) = normalize(n, d);
        self.budget.charge(weight(&num))?;
        check_size(&num)?;
        if let Some(d) = &den {
            check_size(d)?;
        }
        Ok(Value { num, den })
    }

    fn add(&mut self, a: Value, b: Value, negative: bool, first: usize) -> Result<Value, Error> {
        match (a.den, b.den) {
            (None, None) => Ok(Value::polynomial(self.add_poly(a.num, &b.num, negative)?)),
            (Some(da), Some(db)) if da == db => {
                let num = self.add_poly(a.num, &b.num, negative)?;
                self.quotient(num, Some(da))
            }
            (da, db) => {
                // a/da ± b/db = (a·db ± b·da) / (da·db), a missing denominator being 1.
                let left = match &db {
                    Some(db) => self.mul_poly(a.num, db.clone(), first)?,
                    None => a.num,
                };
                let right = match &da {
                    Some(da) => self.mul_poly(b.num, da.clone(), first)?,
                    None => b.num,
                };
                let num = self.add_poly(left, &right, negative)?;
                let den = self.mul_den(da, db, first)?;
                self.quotient(num, den)
            }
        }
    }

    /// The product of two optional denominators.
    fn mul_den(
        &mut self,
        a: Option<MPoly>,
        b: Option<MPoly>,
        first: usize,
    ) -> Result<Option<MPoly>, Error> {
        Ok(match (a, b) {
            (Some(a), Some(b)) => Some(self.mul_poly(a, b, first)?),
            (a, None) => a,
            (None, b) => b,
        })
    }

    fn mul(&mut self, a: Value, b: Value, first: usize) -> Result<Value, Error> {
        let num = self.mul_poly(a.num, b.num, first)?;
        if a.den.is_none() && b.den.is_none() {
            return Ok(Value::polynomial(num));
        }
        let den = self.mul_den(a.den, b.den, first)?;
        self.quotient(num, den)
    }

    /// `a / b`; `column` is that of the `/`.
    fn div(&mut self, a: Value, b: Value, column: usize, first: usize) -> Result<Value, Error> {
        if b.num.is_zero() {
            return Err(Self::syntax(column, "division by zero"));
        }
        if let (Some(c), None) = (b.num.as_constant(), &b.den) {
            let num = self.scale(&a.num, &(RBig::ONE / c))?;
            return Ok(Value { num, den: a.den });
        }
        let allowed = self.grammar.denominator_variables;
        let others: Vec<Variable> = self
            .grammar
            .variables
            .iter()
            .copied()
            .filter(|v| !allowed.contains(v))
            .collect();
        if others.iter().any(|v| b.num.uses(v.index())) {
            let message = if allowed.is_empty() {
                format!(
                    "can only divide by a number, not by an expression in {}",
                    names(&others)
                )
            } else {
                format!(
                    "can only divide by an expression in {}, not by one in {}",
                    names(allowed),
                    names(&others)
                )
            };
            return Err(Self::syntax(column, message));
        }
        // (a/da) / (b/db) = (a·db) / (da·b)
        let num = match b.den {
            Some(db) => self.mul_poly(a.num, db, first)?,
            None => a.num,
        };
        let den = self.mul_den(a.den, Some(b.num), first)?;
        self.quotient(num, den)
    }

    /// `base^n`, the degree checked before any product.
    fn pow(&mut self, base: Value, n: u32, first: usize) -> Result<Value, Error> {
        let degree = base
            .num
            .total_degree()
            .max(base.den.as_ref().map_or(0, MPoly::total_degree));
        if degree * n > self.max_degree() {
            return Err(self.degree_error(first, degree * n));
        }
        if n == 0 {
            return Ok(Value::polynomial(MPoly::one()));
        }
        let num = self.pow_poly(base.num, n, first)?;
        // A power of a primitive polynomial is primitive (Gauss), with a positive leading
        // coefficient if it had one: the denominator needs no normalising.
        let den = match base.den {
            Some(d) => Some(self.pow_poly(d, n, first)?),
            None => None,
        };
        Ok(Value { num, den })
    }

    /// `p^n` for `n ≥ 1` by `n − 1` products, each within the bounds.
    fn pow_poly(&mut self, p: MPoly, n: u32, first: usize) -> Result<MPoly, Error> {
        if n == 1 {
            return Ok(p);
        }
        let mut acc = p.clone();
        for _ in 2..n {
            acc = self.mul_poly(acc, p.clone(), first)?;
        }
        self.mul_poly(acc, p, first)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use dashu_int::{IBig, UBig};
    use proptest::prelude::*;
    use std::time::{Duration, Instant};

    const ALL: &[Variable] = &Variable::ALL;

    fn q(n: i64, d: u64) -> RBig {
        RBig::from_parts(IBig::from(n), UBig::from(d))
    }

    fn read_all(text: &str) -> RationalFunction {
        parse_rational_function(text, ALL).unwrap_or_else(|e| panic!("{text:?}: {e}"))
    }

    /// The values of x, y, z, w, t, u, λ at a test point.
    fn point(v: [i64; 7]) -> Vec<RBig> {
        v.iter().map(|&k| q(k, 1)).collect()
    }

    #[test]
    fn variables_by_name() {
        for v in Variable::ALL {
            assert_eq!(Variable::named(v.name()), Some(v));
            assert_eq!(VARIABLE_NAMES[v.index()], v.name());
        }
        assert_eq!(Variable::named("lambda"), Some(Variable::Lambda));
        assert_eq!(Variable::named("X"), None);
        let f = read_all("2lambda*λ - t u");
        let at = point([0, 0, 0, 0, 3, 5, 2]);
        assert_eq!(f.eval(&at), Some(q(8 - 15, 1)));
    }

    #[test]
    fn values_at_a_point() {
        // (expression, value at x=2, y=3, z=5, w=7, t=-1, u=4, λ=1/2 written as lambda=... )
        let at = {
            let mut p = point([2, 3, 5, 7, -1, 4, 0]);
            p[6] = q(1, 2);
            p
        };
        let table: &[(&str, RBig)] = &[
            ("x + y*z", q(17, 1)),
            ("-x^2", q(-4, 1)),
            ("(x+y)**2 / 5", q(5, 1)),
            ("1/2x", q(1, 1)),
            ("x/y/z", q(2, 15)),
            ("x - y - z", q(-6, 1)),
            ("2(x+1)(y-1)", q(12, 1)),
            ("(t**2 - 1)/(t**2 + 1)", q(0, 1)),
            ("4*t**2/(t**4 + 2*t**2 + 1)", q(1, 1)),
            ("(2*t**3 - 2*t)/(t**4 + 2*t**2 + 1)", q(0, 1)),
            ("1/x + 1/y", q(5, 6)),
            ("1/(1/x + 1/y)", q(6, 5)),
            ("(x/y)^3 * y^3", q(8, 1)),
            ("x^0 + 0^0", q(2, 1)),
            ("λ*lambda", q(1, 4)),
            ("1e-1*w + 2.5e1/u", q(7, 10) + q(25, 4)),
            ("- -x*-y", q(-6, 1)),
            ("x/(t+1) - x/(t+1)", q(0, 1)),
            // negative powers: x = 2, t = -1, u = 4
            ("x**(-2)", q(1, 4)),
            ("x^-2", q(1, 4)),
            ("(1+u)^-1", q(1, 5)),
            ("2^(-3)*u", q(1, 2)),
            ("(x/u)^(-2)", q(4, 1)),
            ("t^(+3) + t^(-3)", q(-2, 1)),
            ("x^-0", q(1, 1)),
        ];
        for (text, want) in table {
            assert_eq!(read_all(text).eval(&at).as_ref(), Some(want), "{text:?}");
        }
    }

    #[test]
    fn long_coefficients_print_in_a_form_read_back() {
        // Found by fuzzing: 111e9999 has 10 002 digits, more than one numeral may have.
        for text in [
            "111e9999*t",
            "1e-9999*t/(t+1)",
            "(7e9999+3)^2*x + 2/(3e9999*t + 1)",
        ] {
            let f = read_all(text);
            assert_eq!(read_all(&f.to_string()), f, "{text}");
        }
    }

    #[test]
    fn quotients_are_reduced_by_their_content() {
        let f = read_all("(6t^2 - 3)/(-9t + 3)");
        assert_eq!(f.to_string(), "(-2*t^2 + 1)/(3*t - 1)");
        assert_eq!(read_all("x/(4/3)").to_string(), "3/4*x");
        assert!(read_all("(t^2-1)/(t-1)").same_as(&read_all("t + 1")));
        assert!(!read_all("(t^2-1)/(t-1)").same_as(&read_all("t - 1")));
        assert!(read_all("0/(t-1)").is_polynomial());
        assert_eq!(RationalFunction::new(MPoly::one(), MPoly::zero()), None);
        assert_eq!(RationalFunction::new(MPoly::var(7), MPoly::one()), None);
        let (n, d) = (
            MPoly::var(4).scale(&q(3, 1)),
            MPoly::var(4).scale(&q(-6, 1)),
        );
        let f = RationalFunction::new(n, d).expect("a nonzero denominator");
        assert_eq!(f.to_string(), "(-1/2*t)/(t)");
        assert!(f.same_as(&read_all("-1/2")) && !f.is_polynomial());
    }

    #[test]
    fn syntax_errors_carry_columns_and_say_what() {
        let table: &[(&str, usize, &str)] = &[
            ("", 1, "empty expression"),
            (
                "x +",
                4,
                "expected a number, a variable or '(', found the end of the input",
            ),
            (
                "(t",
                3,
                "expected ')' to close the '(' at column 1, found the end of the input",
            ),
            ("t)", 2, "unmatched ')'"),
            ("t 2", 3, "expected an operator before the number '2'"),
            ("1/(t-t)", 2, "division by zero"),
            ("λ + 1/(x - x)^2", 6, "division by zero"),
            ("t^t", 3, "the exponent must be an integer, found 't'"),
            ("t^2^2", 4, "chained powers are ambiguous"),
            ("t^-2^2", 5, "chained powers are ambiguous"),
            ("t ? 1", 3, "unexpected character '?'"),
            ("λ ** - -1", 8, "the exponent must be an integer, found '-'"),
            ("t^+2", 3, "the exponent must be an integer, found '+'"),
            ("t^(-t)", 5, "the exponent must be an integer, found 't'"),
            ("t^(-2", 6, "expected ')' to close the '(' at column 3"),
            (
                "t^(2.5)",
                4,
                "the exponent must be an integer, found the number '2.5'",
            ),
            (
                "0^(-1)",
                3,
                "a negative power is a division: division by zero",
            ),
            (
                "(t - t)^-2",
                9,
                "a negative power is a division: division by zero",
            ),
        ];
        for (text, column, want) in table {
            match parse_rational_function(text, ALL) {
                Err(Error::Syntax { column: c, message }) => {
                    assert_eq!(c, *column, "{text:?}: {message}");
                    assert!(message.starts_with(want), "{text:?}: {message}");
                }
                other => panic!("{text:?}: expected a syntax error, got {other:?}"),
            }
        }
        assert_eq!(
            parse_rational_function("t + λ", &[Variable::T]),
            Err(Error::UnknownVariable {
                name: "λ".into(),
                column: 5,
                allowed: "t".into()
            })
        );
        assert_eq!(
            parse_rational_function("t", &[]),
            Err(Error::UnknownVariable {
                name: "t".into(),
                column: 1,
                allowed: "none".into()
            })
        );
        let only_t = Grammar {
            variables: &[Variable::X, Variable::T],
            denominator_variables: &[Variable::T],
            quadric: false,
        };
        match read("x/(1-t) + 1/(x*t)", &only_t) {
            Err(Error::Syntax {
                column: 12,
                message,
            }) => {
                assert_eq!(
                    message,
                    "can only divide by an expression in t, not by one in x"
                )
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn limits_are_enforced_quickly() {
        let start = Instant::now();
        let cases = [
            "t".repeat(MAX_INPUT_LEN + 1),
            "t^65".into(),
            "t^99999999999999999999".into(),
            format!(
                "{}t{}",
                "(".repeat(MAX_NESTING_DEPTH + 1),
                ")".repeat(MAX_NESTING_DEPTH + 1)
            ),
            format!("{}1", "t^16*".repeat(5)),
            format!("1/({})", "(t+1)^16*".repeat(4) + "t"),
            "(x+y+z+w+t+u+λ+1)^16".into(),
            "((x+y+z+w+t+u+λ+1)^8)^2".into(),
            format!(
                "{}1",
                "(x+1)*(y+1)*(z+1)*(w+1)*(t+1)*(u+1)*(λ+1)*".repeat(3)
            ),
            format!("t + {}", "1".repeat(20_000)),
            format!("{}t", "1e-9999*".repeat(20)),
            format!("t + {}1", "(1e-9999)^7+".repeat(8000)),
            format!("t + {}1", "1/(t+1e-9999)+".repeat(100)),
        ];
        for text in &cases {
            let result = parse_rational_function(text, ALL);
            assert!(
                matches!(result, Err(Error::Limit { .. })),
                "input {}: {result:?}",
                excerpt(text)
            );
        }
        assert!(
            start.elapsed() < Duration::from_secs(5),
            "took {:?}",
            start.elapsed()
        );
        // At the bounds: degree MAX_DEGREE, nesting MAX_NESTING_DEPTH.
        let f = read_all(&format!("{}1", "t^16*".repeat(4)));
        assert_eq!(f.numerator().total_degree(), MAX_DEGREE);
        let nested = format!(
            "{}t{}",
            "(".repeat(MAX_NESTING_DEPTH),
            ")".repeat(MAX_NESTING_DEPTH)
        );
        assert_eq!(read_all(&nested), read_all("t"));
    }

    #[test]
    fn deepest_recursion_fits_in_a_small_stack() {
        // Each level goes through a sum, a product and a power: the most frames per '('.
        let depth = MAX_NESTING_DEPTH;
        let text = format!("{}t{}", "(1+2*-".repeat(depth), ")".repeat(depth));
        let parsed = std::thread::Builder::new()
            .stack_size(512 * 1024)
            .spawn(move || parse_rational_function(&text, &[Variable::T]))
            .expect("a thread")
            .join()
            .expect("no stack overflow");
        // f(t) = 1 + 2·(−t) applied 64 times: f∘…∘f(0) = (1 − (−2)^64)/3.
        let at_zero = parsed.expect("within the limits").eval(&point([0; 7]));
        let want = (RBig::ONE - RBig::from(-2).pow(64)) / RBig::from(3);
        assert_eq!(at_zero, Some(want));
    }

    #[test]
    fn degree_errors_name_the_term() {
        match parse_rational_function("1 + t^16*t^16*t^16*t^16*t", ALL) {
            Err(Error::Limit { what, limit: 64 }) => {
                assert_eq!(what, "degree 65 of 't^16*t^16*t^16*t^16*t' at column 5")
            }
            other => panic!("{other:?}"),
        }
    }

    /// A random expression tree, printed with parentheses and evaluated exactly at a point
    /// by a second route (plain rational arithmetic, no polynomials).
    #[derive(Debug, Clone)]
    enum Tree {
        Number(i64, u64),
        Var(usize),
        Neg(Box<Tree>),
        Bin(Box<Tree>, char, Box<Tree>),
        Pow(Box<Tree>, i32),
    }

    impl Tree {
        fn text(&self) -> String {
            match self {
                Tree::Number(n, 1) => n.to_string(),
                Tree::Number(n, d) => format!("({n}/{d})"),
                Tree::Var(i) => VARIABLE_NAMES[*i].to_string(),
                Tree::Neg(a) => format!("-({})", a.text()),
                Tree::Bin(a, '·', b) => format!("({})({})", a.text(), b.text()),
                Tree::Bin(a, op, b) => format!("({}) {op} ({})", a.text(), b.text()),
                Tree::Pow(a, n) if *n < 0 && n % 2 == 0 => format!("({})**({n})", a.text()),
                Tree::Pow(a, n) => format!("({})^{n}", a.text()),
            }
        }

        /// The value, or `None` on a division by zero.
        fn eval(&self, at: &[RBig]) -> Option<RBig> {
            Some(match self {
                Tree::Number(n, d) => q(*n, *d),
                Tree::Var(i) => at[*i].clone(),
                Tree::Neg(a) => -a.eval(at)?,
                Tree::Bin(a, op, b) => {
                    let (a, b) = (a.eval(at)?, b.eval(at)?);
                    match op {
                        '+' => a + b,
                        '-' => a - b,
                        '/' if b.is_zero() => return None,
                        '/' => a / b,
                        _ => a * b,
                    }
                }
                Tree::Pow(a, n) => {
                    let a = a.eval(at)?;
                    if *n < 0 && a.is_zero() {
                        return None;
                    }
                    let p = a.pow(n.unsigned_abs() as isize);
                    if *n < 0 {
                        RBig::ONE / p
                    } else {
                        p
                    }
                }
            })
        }
    }

    fn tree() -> impl Strategy<Value = Tree> {
        let leaf = prop_oneof![
            (-9i64..=9, 1u64..=4).prop_map(|(n, d)| Tree::Number(n, d)),
            (0usize..7).prop_map(Tree::Var),
        ];
        leaf.prop_recursive(4, 24, 2, |inner| {
            prop_oneof![
                inner.clone().prop_map(|a| Tree::Neg(Box::new(a))),
                (
                    inner.clone(),
                    prop::sample::select(vec!['+', '-', '*', '/', '·']),
                    inner.clone()
                )
                    .prop_map(|(a, op, b)| Tree::Bin(Box::new(a), op, Box::new(b))),
                (inner, -3i32..4).prop_map(|(a, n)| Tree::Pow(Box::new(a), n)),
            ]
        })
    }

    proptest! {
        #[test]
        fn expressions_evaluate_as_their_trees(
            t in tree(),
            at in proptest::collection::vec((-5i64..=5, 1u64..=3).prop_map(|(n, d)| q(n, d)), 7),
        ) {
            let text = t.text();
            match parse_rational_function(&text, ALL) {
                Ok(f) => {
                    if let (Some(a), Some(b)) = (t.eval(&at), f.eval(&at)) {
                        prop_assert_eq!(a, b, "{}", text);
                    }
                    // Printing and reading again gives the same quotient.
                    prop_assert_eq!(read_all(&f.to_string()), f);
                }
                Err(Error::Syntax { message, .. }) => {
                    prop_assert!(message.ends_with("division by zero"), "{}: {}", text, message)
                }
                Err(Error::Limit { .. }) => {}
                Err(e) => prop_assert!(false, "{}: {}", text, e),
            }
        }

        #[test]
        fn arbitrary_strings_do_not_panic(text in "\\PC{0,60}") {
            let _ = parse_rational_function(&text, ALL);
        }

        #[test]
        fn expression_like_strings_do_not_panic(text in "[xtλ0-9+*/^(). eE-]{0,60}") {
            let _ = parse_rational_function(&text, ALL);
        }
    }
}

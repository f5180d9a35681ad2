//! Invariants of the library: the readers and the classifier. Also compiled into
//! `crates/qsic/tests/fuzz_regressions.rs`, so it uses nothing but `qsic` and `dashu_ratio`.

// Index loops read as the matrix formulas they implement.
#![allow(clippy::needless_range_loop)]

use dashu_ratio::RBig;
use qsic::io::{
    moving_matrix_from_polynomial, parse_number as read_number, parse_quadric,
    parse_rational_function, Variable,
};
use qsic::limits::MAX_INPUT_LEN;
use qsic::{classify, Error, Quadric};

/// The text the readers see: invalid UTF-8 replaced, so every input reaches them.
fn text(data: &[u8]) -> String {
    String::from_utf8_lossy(data).into_owned()
}

/// `parse_quadric` never panics, and what it accepts prints (`to_polynomial_string`) as a
/// polynomial that reads back as the same quadric, unless the printout is longer than
/// `MAX_INPUT_LEN` (`(1e9999+1)^7*(x+y+z+w)^2` has ten coefficients of 70 000 digits).
pub fn parse_polynomial(data: &[u8]) {
    let Ok(q) = parse_quadric(&text(data)) else {
        return;
    };
    let printed = q.to_polynomial_string();
    match parse_quadric(&printed) {
        Ok(again) => assert_eq!(again, q, "{printed:?} reads back as another quadric"),
        Err(Error::Limit { .. }) if printed.len() > MAX_INPUT_LEN => {}
        Err(e) => panic!("{printed:?} does not read back: {e}"),
    }
}

/// `parse_rational_function` (all variables) and `moving_matrix_from_polynomial` never
/// panic, and what the first accepts prints (`Display`) as an expression that reads back as
/// the same quotient, unless the printout is longer than `MAX_INPUT_LEN` (a short input
/// can expand to many long coefficients).
pub fn parse_expression(data: &[u8]) {
    let text = text(data);
    let _ = moving_matrix_from_polynomial(&text);
    let Ok(f) = parse_rational_function(&text, &Variable::ALL) else {
        return;
    };
    let printed = f.to_string();
    match parse_rational_function(&printed, &Variable::ALL) {
        Ok(again) => assert_eq!(again, f, "{printed:?} reads back as another quotient"),
        Err(Error::Limit { .. }) if printed.len() > MAX_INPUT_LEN => {}
        Err(e) => panic!("{printed:?} does not read back: {e}"),
    }
}

/// `parse_number` never panics; the polynomial reader reads the same text as the same
/// number (`(text)*x^2 + y^2` has it as the coefficient of `x²`); and its `p/q` form reads
/// back as the same number whenever that form is within the digit limit (scientific
/// notation reaches values whose `p/q` form is longer: `1e9999`).
pub fn parse_number(data: &[u8]) {
    let text = text(data);
    let Ok(v) = read_number(&text) else {
        return;
    };
    match parse_quadric(&format!("({text})*x^2 + y^2")) {
        Ok(q) => assert_eq!(q.entry(0, 0), &v, "the polynomial reader differs"),
        Err(e) => panic!("the polynomial reader refuses the number {text:?}: {e}"),
    }
    let printed = v.to_string();
    let digits = printed.bytes().filter(u8::is_ascii_digit).count();
    if digits <= qsic::limits::MAX_NUMBER_DIGITS {
        match read_number(&printed) {
            Ok(again) => assert_eq!(again, v, "{printed:?} reads back as another number"),
            Err(e) => panic!("{printed:?} does not read back: {e}"),
        }
    }
}

/// A pair of quadrics and a signed permutation of the coordinates, from bytes:
/// `[permutation, signs and width, then 20 entries]`. The entries (the upper triangles of
/// A and B, row by row) are 1, 2, 4 or 8 bytes each, little-endian, so that both the fast
/// path (entries below 2²⁴) and the exact path get inputs.
struct Case {
    a: Quadric,
    b: Quadric,
    permutation: [usize; 4],
    signs: [i64; 4],
}

fn decode(data: &[u8]) -> Option<Case> {
    let (&p, rest) = data.split_first()?;
    let (&s, rest) = rest.split_first()?;
    let width = 1usize << ((s >> 4) & 3);
    let mut entries = rest.chunks_exact(width).map(|c| {
        let mut bytes = [0u8; 8];
        bytes[..width].copy_from_slice(c);
        // sign-extend from `width` bytes
        let shift = 64 - 8 * width as u32;
        (i64::from_le_bytes(bytes) << shift) >> shift
    });
    let mut matrix = || -> Option<Quadric> {
        let mut m: [[RBig; 4]; 4] = Default::default();
        for i in 0..4 {
            for j in i..4 {
                let v = RBig::from(entries.next()?);
                m[j][i] = v.clone();
                m[i][j] = v;
            }
        }
        Quadric::from_matrix(m).ok()
    };
    let a = matrix()?;
    let b = matrix()?;
    let mut permutation = [0, 1, 2, 3];
    // the permutation numbered p mod 24 (factorial number system)
    let mut index = usize::from(p) % 24;
    for i in 0..4 {
        let radix = 4 - i;
        permutation[i..].rotate_left(index % radix);
        permutation[i + 1..].sort_unstable();
        index /= radix;
    }
    let signs = [0, 1, 2, 3].map(|k| if s >> k & 1 == 1 { -1 } else { 1 });
    Some(Case {
        a,
        b,
        permutation,
        signs,
    })
}

/// `PᵀMP` for the signed permutation `P`: entry `(i, j)` is `sᵢ sⱼ M[πᵢ][πⱼ]`.
fn transformed(q: &Quadric, permutation: [usize; 4], signs: [i64; 4]) -> Quadric {
    let m = q.matrix();
    let out: [[RBig; 4]; 4] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            RBig::from(signs[i] * signs[j]) * &m[permutation[i]][permutation[j]]
        })
    });
    Quadric::from_matrix(out).expect("a signed permutation keeps a matrix symmetric and nonzero")
}

/// `classify` never panics, and its answer does not change when A and B are swapped or
/// when the coordinates undergo a signed permutation.
pub fn classify_invariance(data: &[u8]) {
    let Some(case) = decode(data) else {
        return;
    };
    let c = classify(&case.a, &case.b);
    assert_eq!(classify(&case.b, &case.a), c, "swapping A and B");
    let pa = transformed(&case.a, case.permutation, case.signs);
    let pb = transformed(&case.b, case.permutation, case.signs);
    assert_eq!(
        classify(&pa, &pb),
        c,
        "permutation {:?}, signs {:?}",
        case.permutation,
        case.signs
    );
}

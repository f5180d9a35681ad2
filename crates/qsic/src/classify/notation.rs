//! The printed notations of the case table, read by the compiler: Segre characteristics
//! (`[(11)11]_3`), signature sequences (`(2,((2,1)),2,(2,1),3)`) and index sequences
//! (`<2~~-2|3|2>`, Tu et al. 2009, Section 2.4).
//!
//! Each is a typed constant that keeps its printed text: the readers are `const fn`s, and
//! [`case_class`] builds a table entry in the table's `static` initializer, so a malformed
//! or inconsistent entry is a compile error and nothing is read at run time.
//!
//! Consistency of one class ([`check_class`]): the index sequence has the signature
//! sequence's arcs; each of its roots has the signature root's multiplicity as the sum of
//! its Jordan blocks; and its roots' block structures are the real roots of the Segre
//! characteristic.

use crate::pencil::SigItem;

/// Most roots of a binary quartic, and most Jordan blocks of one root.
const MAX_ROOTS: usize = 4;

/// Jordan block sizes of each root, largest first and padded with zeros.
type Roots = [[u8; MAX_ROOTS]; MAX_ROOTS];

/// The Segre characteristic of a regular pencil with its number of distinct real roots,
/// as the class key uses it: every root's block sizes (largest first, zero padded), the
/// roots sorted, so that neither the printed order nor the order along λ matters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct SegreKey {
    roots: Roots,
    real: u8,
}

impl SegreKey {
    /// The key of the roots with these block sizes (one slice per root, any order), `real`
    /// of them real; `None` for more than four roots or blocks.
    pub fn new<'a>(roots: impl IntoIterator<Item = &'a [u8]>, real: usize) -> Option<SegreKey> {
        let mut out: Roots = [[0; MAX_ROOTS]; MAX_ROOTS];
        for (i, blocks) in roots.into_iter().enumerate() {
            if i == MAX_ROOTS || blocks.len() > MAX_ROOTS {
                return None;
            }
            out[i][..blocks.len()].copy_from_slice(blocks);
            out[i] = sorted_blocks(out[i]);
        }
        Some(SegreKey {
            roots: sorted_roots(out),
            real: u8::try_from(real).ok()?,
        })
    }
}

/// A Segre characteristic as printed, e.g. `[(11)11]_3`: the Jordan block sizes of each
/// root (a parenthesised group is one root), then the number of distinct real roots.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Segre {
    /// The printed form.
    pub text: &'static str,
    /// The class key.
    pub key: SegreKey,
}

impl Segre {
    /// Reads `[…]_r`; `None` unless the block sizes (digits 1–4, a group of at least two in
    /// parentheses) add up to 4 and `r` counts some of the roots, the others in conjugate pairs.
    pub const fn parse(text: &'static str) -> Option<Segre> {
        let b = text.as_bytes();
        if b.len() < 5 || b[0] != b'[' || b[b.len() - 3] != b']' || b[b.len() - 2] != b'_' {
            return None;
        }
        let Some(real) = digit(b, b.len() - 1) else {
            return None;
        };
        let end = b.len() - 3;
        let mut roots: Roots = [[0; MAX_ROOTS]; MAX_ROOTS];
        let (mut count, mut degree, mut i) = (0, 0, 1);
        while i < end {
            if count == MAX_ROOTS {
                return None;
            }
            let grouped = b[i] == b'(';
            if grouped {
                i += 1;
            }
            let mut blocks = 0;
            loop {
                match digit(b, i) {
                    Some(d) if d > 0 && blocks < MAX_ROOTS => {
                        roots[count][blocks] = d;
                        blocks += 1;
                        degree += d;
                        i += 1;
                    }
                    _ => return None,
                }
                if !grouped {
                    break;
                }
                if i < end && b[i] == b')' {
                    i += 1;
                    break;
                }
            }
            if grouped && blocks < 2 {
                return None;
            }
            roots[count] = sorted_blocks(roots[count]);
            count += 1;
        }
        if degree != 4 || real as usize > count || (count - real as usize) % 2 != 0 {
            return None;
        }
        Some(Segre {
            text,
            key: SegreKey {
                roots: sorted_roots(roots),
                real,
            },
        })
    }
}

/// Most items of a signature sequence: five arcs around four simple roots.
const MAX_ITEMS: usize = 2 * MAX_ROOTS + 1;

/// A signature sequence as printed, e.g. `(2,((2,1)),2,(2,1),3)`: `(I₀, R₁, I₁, …, R_k,
/// I_k)`, a bare number the positive eigenvalues on an arc, `(p,n)` in `m` pairs of
/// parentheses a root of multiplicity `m` whose member has inertia `(p, n)`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SignatureSequence {
    /// The printed form.
    pub text: &'static str,
    items: [SigItem; MAX_ITEMS],
    len: usize,
}

impl SignatureSequence {
    /// Reads the printed form; `None` unless arcs (digits 0–4) and roots (`p + n < 4`)
    /// alternate, the multiplicities add up to at most 4 and, with a root, the last arc is
    /// the swap `4 − I₀` of the first (the cut of the projective line).
    pub const fn parse(text: &'static str) -> Option<SignatureSequence> {
        let b = text.as_bytes();
        if b.len() < 3 || b[0] != b'(' || b[b.len() - 1] != b')' {
            return None;
        }
        let end = b.len() - 1;
        let mut items = [SigItem::Interval(0); MAX_ITEMS];
        let (mut len, mut degree, mut i) = (0, 0, 1);
        loop {
            let Some(arc) = digit(b, i) else {
                return None;
            };
            items[len] = SigItem::Interval(arc);
            len += 1;
            i += 1;
            if i == end {
                break;
            }
            if b[i] != b',' {
                return None;
            }
            i += 1;
            let mut mult = 0;
            while at(b, i) == b'(' {
                mult += 1;
                i += 1;
            }
            let (Some(p), b',', Some(n)) = (digit(b, i), at(b, i + 1), digit(b, i + 2)) else {
                return None;
            };
            i += 3;
            let mut closed = 0;
            while closed < mult {
                if at(b, i) != b')' {
                    return None;
                }
                closed += 1;
                i += 1;
            }
            degree += mult;
            if mult == 0 || p + n >= 4 || degree > 4 || at(b, i) != b',' {
                return None;
            }
            items[len] = SigItem::Root { p, n, mult };
            len += 1;
            i += 1;
        }
        if let (SigItem::Interval(first), SigItem::Interval(last)) = (items[0], items[len - 1]) {
            if len > 1 && first + last != 4 {
                return None;
            }
        }
        Some(SignatureSequence { text, items, len })
    }

    /// The arcs and roots, in order.
    pub fn items(&self) -> &[SigItem] {
        &self.items[..self.len]
    }
}

/// A Jordan block of a root in an index sequence.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum IndexBlock {
    /// `|`: a 1×1 block.
    Simple,
    /// `~…~±` with `size` tildes: a `size`×`size` block with the sign `ε` of its block in
    /// the quadric pair canonical form.
    Jordan { size: u8, positive: bool },
}

impl IndexBlock {
    const fn size(self) -> u8 {
        match self {
            IndexBlock::Simple => 1,
            IndexBlock::Jordan { size, .. } => size,
        }
    }
}

/// An index sequence as printed, e.g. `<2~~-2|3|2>`: the index on each arc, and between
/// two arcs the Jordan blocks of a real root.
#[derive(Clone, Copy, Debug)]
pub(crate) struct IndexSequence {
    /// The printed form.
    pub text: &'static str,
    arcs: [u8; MAX_ROOTS + 1],
    roots: [[IndexBlock; MAX_ROOTS]; MAX_ROOTS],
    /// The number of blocks of each root.
    blocks: [usize; MAX_ROOTS],
    len: usize,
}

impl IndexSequence {
    /// Reads `<…>`; `None` unless arcs (digits 0–4) and roots (one or more blocks: `|`, or
    /// two or more `~` and a sign) alternate, the block sizes adding up to at most 4.
    pub const fn parse(text: &'static str) -> Option<IndexSequence> {
        let b = text.as_bytes();
        if b.len() < 3 || b[0] != b'<' || b[b.len() - 1] != b'>' {
            return None;
        }
        let end = b.len() - 1;
        let mut seq = IndexSequence {
            text,
            arcs: [0; MAX_ROOTS + 1],
            roots: [[IndexBlock::Simple; MAX_ROOTS]; MAX_ROOTS],
            blocks: [0; MAX_ROOTS],
            len: 0,
        };
        let (mut degree, mut i) = (0, 1);
        loop {
            let Some(arc) = digit(b, i) else {
                return None;
            };
            seq.arcs[seq.len] = arc;
            i += 1;
            if i == end {
                return Some(seq);
            }
            while i < end && digit(b, i).is_none() {
                let block = if b[i] == b'|' {
                    i += 1;
                    IndexBlock::Simple
                } else {
                    let mut size = 0;
                    while at(b, i) == b'~' && size <= MAX_ROOTS as u8 {
                        size += 1;
                        i += 1;
                    }
                    let positive = match at(b, i) {
                        b'+' => true,
                        b'-' => false,
                        _ => return None,
                    };
                    i += 1;
                    if size < 2 {
                        return None;
                    }
                    IndexBlock::Jordan { size, positive }
                };
                degree += block.size();
                if degree > MAX_ROOTS as u8 {
                    return None;
                }
                seq.roots[seq.len][seq.blocks[seq.len]] = block;
                seq.blocks[seq.len] += 1;
            }
            if seq.blocks[seq.len] == 0 {
                return None;
            }
            seq.len += 1;
        }
    }
}

/// Checks that an index sequence describes the same class as a signature sequence and a
/// Segre characteristic (module docs); the error says what differs.
pub(crate) const fn check_class(
    segre: &Segre,
    signature: &SignatureSequence,
    index: &IndexSequence,
) -> Result<(), &'static str> {
    if signature.len != 2 * index.len + 1 {
        return Err("the index and signature sequences have different numbers of roots");
    }
    if index.len != segre.key.real as usize {
        return Err("the index sequence and the Segre characteristic count real roots differently");
    }
    let mut real: Roots = [[0; MAX_ROOTS]; MAX_ROOTS];
    let mut k = 0;
    while k <= index.len {
        if let SigItem::Interval(arc) = signature.items[2 * k] {
            if arc != index.arcs[k] {
                return Err("the index and signature sequences have different arcs");
            }
        }
        if k < index.len {
            let mut sum = 0;
            let mut j = 0;
            while j < index.blocks[k] {
                real[k][j] = index.roots[k][j].size();
                sum += real[k][j];
                j += 1;
            }
            real[k] = sorted_blocks(real[k]);
            if let SigItem::Root { mult, .. } = signature.items[2 * k + 1] {
                if mult != sum {
                    return Err(
                        "a root has different multiplicities in the index and signature sequences",
                    );
                }
            }
        }
        k += 1;
    }
    // The real roots' structures must be among the Segre roots, each used once.
    let mut used = [false; MAX_ROOTS];
    let mut r = 0;
    while r < index.len {
        let mut s = 0;
        while s < MAX_ROOTS && (used[s] || !same_blocks(&real[r], &segre.key.roots[s])) {
            s += 1;
        }
        if s == MAX_ROOTS {
            return Err(
                "a root of the index sequence is not a real root of the Segre characteristic",
            );
        }
        used[s] = true;
        r += 1;
    }
    Ok(())
}

/// A class of the case table, read and checked at compile time: the signature and index
/// sequences of one class of the case with this Segre characteristic.
///
/// # Panics
/// If a text is malformed or the three disagree ([`check_class`]); in the table's `static`
/// initializer this is a compile error.
pub(crate) const fn case_class(
    segre: &'static str,
    signature: &'static str,
    index: &'static str,
) -> (SignatureSequence, IndexSequence) {
    let Some(segre) = Segre::parse(segre) else {
        panic!("the case table: a malformed Segre characteristic");
    };
    let Some(signature) = SignatureSequence::parse(signature) else {
        panic!("the case table: a malformed signature sequence");
    };
    let Some(index) = IndexSequence::parse(index) else {
        panic!("the case table: a malformed index sequence");
    };
    if let Err(why) = check_class(&segre, &signature, &index) {
        panic!("{}", why);
    }
    (signature, index)
}

/// [`Segre::parse`] for the table.
///
/// # Panics
/// If `text` is malformed; a compile error in the table's `static` initializer.
pub(crate) const fn case_segre(text: &'static str) -> Segre {
    match Segre::parse(text) {
        Some(s) => s,
        None => panic!("the case table: a malformed Segre characteristic"),
    }
}

/// `b[i]`, or 0 past the end.
const fn at(b: &[u8], i: usize) -> u8 {
    if i < b.len() {
        b[i]
    } else {
        0
    }
}

/// The digit 0–4 at `b[i]`.
const fn digit(b: &[u8], i: usize) -> Option<u8> {
    match at(b, i) {
        c @ b'0'..=b'4' => Some(c - b'0'),
        _ => None,
    }
}

/// Block sizes largest first (insertion sort; a `const fn`).
const fn sorted_blocks(mut x: [u8; MAX_ROOTS]) -> [u8; MAX_ROOTS] {
    let mut i = 1;
    while i < MAX_ROOTS {
        let mut j = i;
        while j > 0 && x[j - 1] < x[j] {
            let t = x[j];
            x[j] = x[j - 1];
            x[j - 1] = t;
            j -= 1;
        }
        i += 1;
    }
    x
}

/// Roots in lexicographic order of their (sorted, padded) block sizes.
const fn sorted_roots(mut x: Roots) -> Roots {
    let mut i = 1;
    while i < MAX_ROOTS {
        let mut j = i;
        while j > 0 && lexicographically_less(&x[j], &x[j - 1]) {
            let t = x[j];
            x[j] = x[j - 1];
            x[j - 1] = t;
            j -= 1;
        }
        i += 1;
    }
    x
}

const fn lexicographically_less(a: &[u8; MAX_ROOTS], b: &[u8; MAX_ROOTS]) -> bool {
    let mut i = 0;
    while i < MAX_ROOTS {
        if a[i] != b[i] {
            return a[i] < b[i];
        }
        i += 1;
    }
    false
}

const fn same_blocks(a: &[u8; MAX_ROOTS], b: &[u8; MAX_ROOTS]) -> bool {
    !lexicographically_less(a, b) && !lexicographically_less(b, a)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn signature(text: &'static str) -> SignatureSequence {
        SignatureSequence::parse(text).expect("a valid signature sequence")
    }

    fn index(text: &'static str) -> IndexSequence {
        IndexSequence::parse(text).expect("a valid index sequence")
    }

    fn segre(text: &'static str) -> Segre {
        Segre::parse(text).expect("a valid Segre characteristic")
    }

    #[test]
    fn signature_sequences_read_and_refused() {
        let s = signature("(2,((2,1)),2,(2,1),3,(2,1),2)");
        assert_eq!(s.items().len(), 7);
        let root = |p, n, mult| SigItem::Root { p, n, mult };
        assert_eq!(s.items()[1], root(2, 1, 2));
        assert_eq!(s.items()[3], root(2, 1, 1));
        assert_eq!(s.items()[6], SigItem::Interval(2));
        assert_eq!(signature("(2)").items(), [SigItem::Interval(2)]);
        for (bad, why) in [
            ("(2,((2,1),2)", "unbalanced"),
            ("(2,(2,1))", "ends on a root"),
            ("(2,(2,1),3,,(2,1),2)", "an empty item"),
            ("(5)", "five positive eigenvalues"),
            ("(2,(2,2),2)", "a nonsingular member at a root"),
            ("(1,(1,2),2)", "the last arc is not the swap of the first"),
            ("(2,(((((2,1))))),2)", "multiplicity 5"),
            ("(1,(1,2),2,(1,2),1,(1,2),2,(2,1),2,(2,1),3)", "five roots"),
            ("(2, (2,1), 2)", "spaces"),
            ("2,(2,1),2", "no parentheses"),
        ] {
            assert!(SignatureSequence::parse(bad).is_none(), "{bad}: {why}");
        }
    }

    #[test]
    fn segre_characteristics_read_and_refused() {
        let key = |roots: &[&[u8]], real| SegreKey::new(roots.iter().copied(), real);
        assert_eq!(
            Some(segre("[(11)11]_3").key),
            key(&[&[1], &[1, 1], &[1]], 3)
        );
        assert_eq!(Some(segre("[2(11)]_2").key), key(&[&[1, 1], &[2]], 2));
        assert_eq!(Some(segre("[(211)]_1").key), key(&[&[1, 2, 1]], 1));
        assert_ne!(segre("[(11)11]_3").key, segre("[(11)11]_1").key);
        assert_ne!(segre("[22]_2").key, segre("[(22)]_1").key);
        assert_eq!(key(&[&[1], &[1], &[1], &[1], &[1]], 5), None);
        for (bad, why) in [
            ("[(1)111]_2", "a group of one block"),
            ("[211]_4", "more real roots than roots"),
            ("[1111]_3", "one non-real root without its conjugate"),
            ("[21]_1", "degree 3"),
            ("[(11)11]3", "no underscore"),
            ("[(11)11_3", "no closing bracket"),
            ("[(11)11]_5", "five real roots"),
            ("[0211]_3", "a block of size 0"),
            ("[11111]_1", "five roots"),
            ("[(11111)]_1", "five blocks"),
        ] {
            assert!(Segre::parse(bad).is_none(), "{bad}: {why}");
        }
    }

    #[test]
    fn index_sequences_read_and_refused() {
        let s = index("<2~~-2|3|2>");
        assert_eq!(s.len, 3);
        assert_eq!(s.arcs[..4], [2, 2, 3, 2]);
        let jordan = |size, positive| IndexBlock::Jordan { size, positive };
        assert_eq!(s.roots[0][..s.blocks[0]], [jordan(2, false)]);
        assert_eq!(s.roots[1][..s.blocks[1]], [IndexBlock::Simple]);
        let s = index("<1~~~+|3>");
        assert_eq!(
            s.roots[0][..s.blocks[0]],
            [jordan(3, true), IndexBlock::Simple]
        );
        let s = index("<2~~-~~+2>");
        assert_eq!(
            s.roots[0][..s.blocks[0]],
            [jordan(2, false), jordan(2, true)]
        );
        assert_eq!(index("<2>").len, 0);
        for (bad, why) in [
            ("<2~-2>", "a Jordan block of size 1"),
            ("<2~~2>", "no sign"),
            ("<2|>", "ends on a root"),
            ("<22>", "two arcs without a root"),
            ("<2~~~~~-2>", "size 5"),
            ("<1|2|1|2|3|2>", "five roots"),
            ("<5>", "index 5"),
            ("<2|2", "no closing bracket"),
        ] {
            assert!(IndexSequence::parse(bad).is_none(), "{bad}: {why}");
        }
    }

    /// Case 5 is consistent; changing an arc, a multiplicity or the Segre characteristic is
    /// caught, each with its own reason.
    #[test]
    fn inconsistent_classes_are_refused() {
        let (segre5, sig5) = (segre("[211]_3"), signature("(2,((2,1)),2,(2,1),3,(2,1),2)"));
        assert_eq!(check_class(&segre5, &sig5, &index("<2~~-2|3|2>")), Ok(()));
        let wrong = [
            (segre5, sig5, index("<2~~-2|2|2>"), "different arcs"),
            (segre5, sig5, index("<2|2|3|2>"), "different multiplicities"),
            (
                segre5,
                sig5,
                index("<2~~-2|3>"),
                "different numbers of roots",
            ),
            (
                segre("[(11)11]_3"),
                sig5,
                index("<2~~-2|3|2>"),
                "not a real root",
            ),
            (
                segre("[211]_1"),
                sig5,
                index("<2~~-2|3|2>"),
                "count real roots",
            ),
        ];
        for (segre, signature, index, why) in wrong {
            let got = check_class(&segre, &signature, &index);
            assert!(
                got.is_err_and(|e| e.contains(why)),
                "{}: {got:?}",
                index.text
            );
        }
    }
}

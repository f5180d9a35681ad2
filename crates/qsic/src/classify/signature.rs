//! Signature sequences: parsing the printed form, and the canonical form under the
//! equivalences of Section 2.4 (rotation, reversal, complement) with the corrected rotation
//! rule of ERRATA item 4: the root carried across λ = ∞ has its signature swapped.

use crate::pencil::SigItem;

/// The lexicographically least of all sequences equivalent to `seq`.
///
/// `seq` is `(I₀, R₁, I₁, …, R_k, I_k)` with `I_k` the swap of `I₀` (or the single `(I₀)`).
pub(crate) fn canonical(seq: &[SigItem]) -> Vec<SigItem> {
    let mut best: Option<Vec<SigItem>> = None;
    let mut consider = |s: Vec<SigItem>| {
        if best.as_ref().is_none_or(|b| s < *b) {
            best = Some(s);
        }
    };
    let roots = seq.len() / 2;
    let mut cur = seq.to_vec();
    for _ in 0..roots.max(1) {
        for reversed in [false, true] {
            for complemented in [false, true] {
                let mut s = cur.clone();
                if reversed {
                    s.reverse();
                }
                if complemented {
                    s = s.into_iter().map(SigItem::swapped).collect();
                }
                consider(s);
            }
        }
        if roots > 0 {
            cur = rotate(&cur);
        }
    }
    best.unwrap_or_default()
}

/// Moves the cut of the projective line past the first root: `(I₀, R₁, I₁, …, I_k)` becomes
/// `(I₁, …, I_k, R₁*, I₁*)`, `*` the swap.
fn rotate(seq: &[SigItem]) -> Vec<SigItem> {
    let mut out: Vec<SigItem> = seq[2..].to_vec();
    out.push(seq[1].swapped());
    out.push(seq[2].swapped());
    out
}

/// Parses the printed form, e.g. `(2,((2,1)),2,(2,1),3)`: bare numbers are arcs, a pair in
/// `m` parentheses is a root of multiplicity `m`.
pub(crate) fn parse(text: &str) -> Option<Vec<SigItem>> {
    let inner = text.strip_prefix('(')?.strip_suffix(')')?;
    let bytes = inner.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b',' => i += 1,
            b'(' => {
                let mut depth = 0;
                while bytes.get(i) == Some(&b'(') {
                    depth += 1;
                    i += 1;
                }
                let end = i + inner[i..].find(')')?;
                let (p, n) = inner[i..end].split_once(',')?;
                out.push(SigItem::Root {
                    p: p.trim().parse().ok()?,
                    n: n.trim().parse().ok()?,
                    mult: depth,
                });
                i = end;
                for _ in 0..depth {
                    if bytes.get(i) != Some(&b')') {
                        return None;
                    }
                    i += 1;
                }
            }
            _ => {
                let end = inner[i..].find(',').map_or(inner.len(), |e| i + e);
                out.push(SigItem::Interval(inner[i..end].trim().parse().ok()?));
                i = end;
            }
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parse_printed_sequences() {
        let s = parse("(2,((2,1)),2,(2,1),3,(2,1),2)").expect("valid");
        assert_eq!(s.len(), 7);
        assert_eq!(
            s[1],
            SigItem::Root {
                p: 2,
                n: 1,
                mult: 2
            }
        );
        assert_eq!(s[6], SigItem::Interval(2));
        assert_eq!(parse("(2)"), Some(vec![SigItem::Interval(2)]));
        assert!(parse("(2,((2,1),2)").is_none());
    }

    #[test]
    fn the_two_printed_forms_of_case_5_are_one_class() {
        // ERRATA item 4: equivalent only with the swap at infinity.
        let a = parse("(2,((2,1)),2,(2,1),3,(2,1),2)").expect("valid");
        let b = parse("(2,((1,2)),2,(2,1),3,(2,1),2)").expect("valid");
        assert_eq!(canonical(&a), canonical(&b));
    }

    /// The canonical form is the least equivalent sequence, as documented: no rotation,
    /// reversal or complement of it is smaller.
    #[test]
    fn canonical_is_the_least_equivalent_sequence() {
        let s = parse("(2,((2,1)),2,(2,1),3,(2,1),2)").expect("valid");
        let c = canonical(&s);
        let mut cur = s.clone();
        for _ in 0..s.len() / 2 {
            for r in [false, true] {
                for m in [false, true] {
                    let mut t = cur.clone();
                    if r {
                        t.reverse();
                    }
                    if m {
                        t = t.into_iter().map(SigItem::swapped).collect();
                    }
                    assert!(c <= t, "{c:?} > {t:?}");
                }
            }
            cur = rotate(&cur);
        }
        assert!(c < s);
    }

    #[test]
    fn case_16_has_two_classes_and_case_13_differs() {
        let a = parse("(0,((0,2)),2,(2,1),3,(3,0),4)").expect("valid");
        let b = parse("(1,((1,1)),3,(3,0),4,(3,0),3)").expect("valid");
        let c = parse("(2,((1,1)),2,(1,2),1,(1,2),2)").expect("valid");
        assert_ne!(canonical(&a), canonical(&b));
        assert_ne!(canonical(&a), canonical(&c));
    }
}

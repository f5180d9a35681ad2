//! Signature sequences: the canonical form under the equivalences of Section 2.4 (rotation,
//! reversal, complement) with the corrected rotation rule of ERRATA item 4: the root
//! carried across λ = ∞ has its signature swapped. The printed form is read in `notation`.

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::classify::notation::SignatureSequence;

    fn parse(text: &'static str) -> Vec<SigItem> {
        SignatureSequence::parse(text)
            .expect("a valid sequence")
            .items()
            .to_vec()
    }

    #[test]
    fn the_two_printed_forms_of_case_5_are_one_class() {
        // ERRATA item 4: equivalent only with the swap at infinity.
        let a = parse("(2,((2,1)),2,(2,1),3,(2,1),2)");
        let b = parse("(2,((1,2)),2,(2,1),3,(2,1),2)");
        assert_eq!(canonical(&a), canonical(&b));
    }

    /// The canonical form is the least equivalent sequence, as documented: no rotation,
    /// reversal or complement of it is smaller.
    #[test]
    fn canonical_is_the_least_equivalent_sequence() {
        let s = parse("(2,((2,1)),2,(2,1),3,(2,1),2)");
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
        let a = parse("(0,((0,2)),2,(2,1),3,(3,0),4)");
        let b = parse("(1,((1,1)),3,(3,0),4,(3,0),3)");
        let c = parse("(2,((1,1)),2,(1,2),1,(1,2),2)");
        assert_ne!(canonical(&a), canonical(&b));
        assert_ne!(canonical(&a), canonical(&c));
    }
}

use qsic_algebra::{roots::isolate_real_roots, IBig, Poly};
fn main() {
    let t = IBig::from(10).pow(6000);
    let mut p = Poly::new(vec![t.clone(), IBig::ONE]);
    for k in 1..=3 {
        p = &p * &Poly::new(vec![IBig::from(-k), t.clone()]);
    }
    p = &p * &Poly::from_i64s(&[-3, 0, 1]);
    let s = std::time::Instant::now();
    let r = isolate_real_roots(&p);
    eprintln!("isolate {:?} {}", s.elapsed(), r.len());
    let s = std::time::Instant::now();
    let n = p.count_real_roots_sturm();
    eprintln!("sturm {:?} {}", s.elapsed(), n);
}

use qsic::io::moving_matrix_from_polynomial;
use qsic::motion::MovingPencil;
use std::time::Instant;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (a, b) = (&args[1], &args[2]);
    let t = Instant::now();
    let p = MovingPencil::new(
        moving_matrix_from_polynomial(a).unwrap(),
        moving_matrix_from_polynomial(b).unwrap(),
    )
    .unwrap();
    let t1 = t.elapsed();
    let polys = p.candidate_polynomials().unwrap();
    let t2 = t.elapsed();
    let c = p.candidate_instants().unwrap();
    let t3 = t.elapsed();
    let m = p.variations();
    println!(
        "new {:?} polys {:?} instants {:?} (+{:?}) total {:?} {:?}",
        t1,
        t2,
        t3 - t2,
        c.iter().map(|c| c.poly().degree()).collect::<Vec<_>>(),
        t.elapsed() - t3,
        m.map(|m| (m.instants.len(), m.intervals.len()))
    );
    println!("{:?}", polys.iter().map(|p| p.degree()).collect::<Vec<_>>());
}

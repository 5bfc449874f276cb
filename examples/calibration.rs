//! The body against ANSUR II's measured people (docs/calibration.md): each
//! person of the odd survey rows built as `std::populations` builds one,
//! their model thumb-tip reach and seated overhead fingertip reach against
//! their own measured ones, women and men apart; beside them the best
//! linear predictor of each reach from the same measurements, fitted on the
//! even rows (the floor any model of these measurements can reach); and
//! std::people's percentile people against their sex's percentiles.
//!
//! `cargo run --release --example calibration` (every odd row: about a
//! minute); `-- --every N` takes every N-th odd row.

use nalgebra::{DMatrix, DVector};
use reach::ansur::survey;
use reach::calibration::{
    bodies, of_sex, percentile, reaches, standard_deviation, Reaches, COLUMNS, PERCENTILE_PEOPLE,
};
use reach::stdlib;

fn main() {
    let every: usize = std::env::args()
        .skip_while(|a| a != "--every")
        .nth(1)
        .and_then(|n| n.parse().ok())
        .unwrap_or(1);
    let rows = survey();
    let odd: Vec<usize> = (1..rows.rows.len()).step_by(2).step_by(every).collect();
    let mut model = Vec::with_capacity(odd.len());
    for chunk in odd.chunks(500) {
        let built = bodies(chunk).unwrap_or_else(|d| panic!("{}", d.render(false)));
        model.extend(
            built
                .iter()
                .map(|b| reaches(b).expect("a std::body person")),
        );
    }
    let column = |name: &str| rows.columns.iter().position(|c| c == name).unwrap();
    let (thumb, overhead) = (
        column("thumbtipreach"),
        column("overheadfingertipreachsitting"),
    );
    println!(
        "{} odd rows of ANSUR II (every {every}): model minus measured, mm\n",
        odd.len()
    );
    println!("| reach | sex | people | median error | 90th pct abs error | linear: median | linear: 90th pct abs |");
    println!("|---|---|---:|---:|---:|---:|---:|");
    for (label, measure, of) in [
        (
            "thumb-tip",
            thumb,
            (|r: &Reaches| r.thumb_tip_mm) as fn(&Reaches) -> f64,
        ),
        ("overhead, sitting", overhead, |r: &Reaches| r.overhead_mm),
    ] {
        for (sex, female) in [("women", true), ("men", false)] {
            let errors: Vec<f64> = odd
                .iter()
                .zip(&model)
                .filter(|(&row, _)| rows.rows[row].female == female)
                .map(|(&row, r)| of(r) - rows.rows[row].lengths_mm[measure])
                .collect();
            let abs: Vec<f64> = errors.iter().map(|e| e.abs()).collect();
            let (lin_median, lin_p90) = linear_floor(measure, female, &odd);
            println!(
                "| {label} | {sex} | {} | {:+.1} | {:.1} | {:+.1} | {:.1} |",
                errors.len(),
                percentile(&errors, 50.0),
                percentile(&abs, 90.0),
                lin_median,
                lin_p90
            );
        }
    }
    println!("\nstd::people against their sex's percentile of ANSUR II (all rows), mm\n");
    println!("| person | thumb-tip: model | measured (SD) | overhead: model | measured (SD) |");
    println!("|---|---:|---:|---:|---:|");
    for (name, female, p) in PERCENTILE_PEOPLE {
        let body = stdlib::body("people", name).unwrap_or_else(|d| panic!("{}", d.render(false)));
        let r = reaches(&body).expect("a std::body person");
        let t = of_sex("thumbtipreach", female);
        let o = of_sex("overheadfingertipreachsitting", female);
        println!(
            "| {name} | {:.0} | {:.0} ({:.0}) | {:.0} | {:.0} ({:.0}) |",
            r.thumb_tip_mm,
            percentile(&t, p),
            standard_deviation(&t),
            r.overhead_mm,
            percentile(&o, p),
            standard_deviation(&o)
        );
    }
}

/// The least-squares fit of column `measure` on the measurements
/// `ansur_adult` takes (and an intercept), on the even rows of one sex;
/// its median error and 90th-percentile absolute error on `odd` rows.
fn linear_floor(measure: usize, female: bool, odd: &[usize]) -> (f64, f64) {
    let rows = survey();
    let inputs: Vec<usize> = COLUMNS
        .iter()
        .map(|c| rows.columns.iter().position(|n| n == c).unwrap())
        .collect();
    let features = |row: usize| {
        let mut x = vec![1.0];
        x.extend(inputs.iter().map(|&i| rows.rows[row].lengths_mm[i]));
        x
    };
    let even: Vec<usize> = (0..rows.rows.len())
        .step_by(2)
        .filter(|&r| rows.rows[r].female == female)
        .collect();
    let n = inputs.len() + 1;
    let a = DMatrix::from_fn(even.len(), n, |i, j| features(even[i])[j]);
    let b = DVector::from_fn(even.len(), |i, _| rows.rows[even[i]].lengths_mm[measure]);
    let beta = a
        .svd(true, true)
        .solve(&b, 1e-9)
        .expect("a least-squares fit");
    let errors: Vec<f64> = odd
        .iter()
        .filter(|&&r| rows.rows[r].female == female)
        .map(|&r| {
            let x = DVector::from_vec(features(r));
            beta.dot(&x) - rows.rows[r].lengths_mm[measure]
        })
        .collect();
    let abs: Vec<f64> = errors.iter().map(|e| e.abs()).collect();
    (percentile(&errors, 50.0), percentile(&abs, 90.0))
}

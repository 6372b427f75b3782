//! Medians of repeated runs, as the benchmarks report them.

use std::time::Instant;

/// The median of `values` (the upper one of an even count); NaN for none.
pub fn median(mut values: Vec<f64>) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// The median wall time (s) of `runs ≥ 1` calls of `f`.
pub fn median_seconds(runs: usize, mut f: impl FnMut()) -> f64 {
    median(
        (0..runs)
            .map(|_| {
                let started = Instant::now();
                f();
                started.elapsed().as_secs_f64()
            })
            .collect(),
    )
}

/// The median over `reps` repetitions of the time per call (ns) of `f(0) … f(n − 1)`; the
/// results are kept from the optimiser.
pub fn median_ns_per_call<T>(n: usize, reps: usize, mut f: impl FnMut(usize) -> T) -> f64 {
    median(
        (0..reps)
            .map(|_| {
                let started = Instant::now();
                for i in 0..n {
                    std::hint::black_box(f(i));
                }
                started.elapsed().as_secs_f64() * 1e9 / n as f64
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_of_odd_and_even_counts() {
        assert!((median(vec![3.0, 1.0, 2.0]) - 2.0).abs() < f64::EPSILON);
        assert!((median(vec![4.0, 1.0, 3.0, 2.0]) - 3.0).abs() < f64::EPSILON);
        assert!(median(Vec::new()).is_nan());
    }
}

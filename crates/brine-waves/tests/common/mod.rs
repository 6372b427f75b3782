//! Helpers shared by the tracing tests.

/// First sign change of `f` on `[0, t_max]` by a march of `step` metres, refined by 60 bisections:
/// the reference a traced hit is compared with (it misses crossing pairs closer than `step`).
pub fn first_crossing(f: &dyn Fn(f64) -> f64, t_max: f64, step: f64) -> Option<f64> {
    let mut t = 0.0;
    let mut v = f(t);
    while t < t_max {
        let t2 = (t + step).min(t_max);
        let v2 = f(t2);
        if v.signum() != v2.signum() {
            let (mut a, mut b) = (t, t2);
            for _ in 0..60 {
                let m = 0.5 * (a + b);
                if f(m).signum() == v.signum() { a = m } else { b = m }
            }
            return Some(0.5 * (a + b));
        }
        t = t2;
        v = v2;
    }
    None
}

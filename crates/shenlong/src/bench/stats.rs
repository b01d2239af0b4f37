//! Statistics for comparing systems: means, standard deviations, Welch's t-test (its
//! p-value from the `stats` feature, on by default: without it, reports leave the tests of
//! significance out).

#[cfg(feature = "stats")]
use statrs::distribution::{ContinuousCDF, StudentsT};

/// Mean and sample standard deviation (0 for fewer than two values).
pub fn mean_std(values: &[f64]) -> (f64, f64) {
    if values.is_empty() {
        return (f64::NAN, f64::NAN);
    }
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    if values.len() < 2 {
        return (mean, 0.0);
    }
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, var.sqrt())
}

/// Welch's two-sample t-test: the t statistic, the Welch–Satterthwaite degrees of freedom
/// and the two-sided p-value. `None` when a sample has fewer than two values or both have
/// no variance.
#[cfg(feature = "stats")]
pub fn welch(a: &[f64], b: &[f64]) -> Option<(f64, f64, f64)> {
    if a.len() < 2 || b.len() < 2 {
        return None;
    }
    let (ma, sa) = mean_std(a);
    let (mb, sb) = mean_std(b);
    let (va, vb) = (sa * sa / a.len() as f64, sb * sb / b.len() as f64);
    if va + vb == 0.0 {
        return None;
    }
    let t = (ma - mb) / (va + vb).sqrt();
    let df =
        (va + vb).powi(2) / (va * va / (a.len() as f64 - 1.0) + vb * vb / (b.len() as f64 - 1.0));
    let dist = StudentsT::new(0.0, 1.0, df).ok()?;
    let p = 2.0 * (1.0 - dist.cdf(t.abs()));
    Some((t, df, p))
}

/// Without the `stats` feature there is no Student's t distribution: no test of
/// significance.
#[cfg(not(feature = "stats"))]
pub fn welch(_: &[f64], _: &[f64]) -> Option<(f64, f64, f64)> {
    None
}

#[cfg(all(test, feature = "stats"))]
mod tests {
    use super::*;

    #[test]
    fn welch_matches_a_known_example() {
        // scipy.stats.ttest_ind(a, b, equal_var=False) gives t = -2.0740146,
        // df = 10.2091854, p = 0.0642800.
        let a = [19.8, 20.4, 19.6, 17.8, 18.5, 18.9, 18.3, 18.9, 19.5, 22.0];
        let b = [28.2, 26.6, 20.1, 23.3, 25.2, 22.1, 17.7, 27.6, 20.6, 13.7];
        let (t, df, p) = welch(&a, &b).unwrap();
        assert!((t - -2.0740146).abs() < 1e-6, "{t}");
        assert!((df - 10.2091854).abs() < 1e-6, "{df}");
        assert!((p - 0.0642800).abs() < 1e-6, "{p}");
        assert!(welch(&[1.0], &a).is_none());
        let (m, s) = mean_std(&[1.0, 2.0, 3.0]);
        assert_eq!((m, s), (2.0, 1.0));
    }
}

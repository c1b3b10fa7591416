//! The statistics of a bench job's runs, and how two records compare
//! (specs/bench.md).

use serde_json::{json, Value};

/// Median, least, most and median absolute deviation of `values`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stats {
    pub median: f64,
    pub min: f64,
    pub max: f64,
    pub mad: f64,
}

fn median(sorted: &[f64]) -> f64 {
    let n = sorted.len();
    match n % 2 {
        1 => sorted[n / 2],
        _ => 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]),
    }
}

impl Stats {
    pub fn of(values: &[f64]) -> Self {
        assert!(!values.is_empty(), "statistics of no runs");
        let mut sorted = values.to_vec();
        sorted.sort_by(f64::total_cmp);
        let m = median(&sorted);
        let mut deviations: Vec<f64> = sorted.iter().map(|v| (v - m).abs()).collect();
        deviations.sort_by(f64::total_cmp);
        Stats {
            median: m,
            min: sorted[0],
            max: sorted[sorted.len() - 1],
            mad: median(&deviations),
        }
    }

    pub fn json(&self, samples: &[f64]) -> Value {
        json!({"median": self.median, "min": self.min, "max": self.max, "mad": self.mad, "runs": samples})
    }

    pub fn from_json(value: &Value) -> Option<Self> {
        let get = |k: &str| value.get(k)?.as_f64();
        Some(Stats {
            median: get("median")?,
            min: get("min")?,
            max: get("max")?,
            mad: get("mad")?,
        })
    }
}

/// How a job's wall time compares with the baseline's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Slower by no more than the tolerance, or faster.
    Within,
    /// Slower beyond the tolerance, but within the two records' noise.
    Noise,
    /// Slower beyond the tolerance and beyond the noise.
    Regression,
}

/// How many median absolute deviations either side of the median count as
/// a record's noise: robust to the odd run a busy machine slows down.
const NOISE_MADS: f64 = 2.0;

impl Stats {
    fn noise(&self) -> (f64, f64) {
        let spread = NOISE_MADS * self.mad;
        (self.median - spread, self.median + spread)
    }
}

/// `now` against `before` with a tolerance (0.05 for 5%): a regression only
/// where the median is slower beyond it and the two records' noise
/// intervals (median ± 2 MAD) do not overlap.
pub fn verdict(now: &Stats, before: &Stats, tolerance: f64) -> Verdict {
    if now.median <= before.median * (1.0 + tolerance) {
        Verdict::Within
    } else if now.noise().0 <= before.noise().1 {
        Verdict::Noise
    } else {
        Verdict::Regression
    }
}

/// `record`'s job of `job`'s name (a baseline's, to compare with).
pub fn same_job<'a>(record: Option<&'a Value>, job: &Value) -> Option<&'a Value> {
    record?["jobs"]
        .as_array()?
        .iter()
        .find(|j| j["name"] == job["name"])
}

/// A figure a job is judged by, this record's and the baseline's, and how
/// they compare.
pub struct Judged {
    pub figure: &'static str,
    pub now: Stats,
    pub before: Stats,
    pub verdict: Verdict,
}

/// The figures a load on the machine leaves alone (specs/bench.md): a job's
/// wall time over its floor's, run beside it, and its CPU seconds per frame.
const STEADY: [(&str, &[&str]); 2] = [
    ("floor ratio", &["floor", "ratio"]),
    ("CPU s/frame", &["cpu_seconds_per_frame"]),
];

/// `job` against the baseline's `before`, by each steady figure both
/// records hold; by wall time when they share none (an older record).
pub fn judge(job: &Value, before: &Value, tolerance: f64) -> Vec<Judged> {
    let get = |v: &Value, path: &[&str]| Stats::from_json(path.iter().fold(v, |v, k| &v[*k]));
    let judged = |figure: &'static str, path: &[&str]| {
        let (now, before) = (get(job, path)?, get(before, path)?);
        let verdict = verdict(&now, &before, tolerance);
        Some(Judged {
            figure,
            now,
            before,
            verdict,
        })
    };
    let steady: Vec<Judged> = STEADY
        .iter()
        .filter_map(|(figure, path)| judged(figure, path))
        .collect();
    match steady.is_empty() {
        true => judged("median wall", &["wall_seconds"])
            .into_iter()
            .collect(),
        false => steady,
    }
}

/// The coverage the paired interval keeps: 99%, not 95%, so that the same
/// build twice is "no difference" in nearly every trial on a noisy machine
/// (at 95%, 1 of 10 trials said "slower": specs/bench.md).
const CONFIDENCE: f64 = 0.99;

/// Paired runs' ratios (this build's over the other's): their median and a
/// distribution-free confidence interval for it, from the sign test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Paired {
    pub median: f64,
    pub low: f64,
    pub high: f64,
    /// The interval's coverage: at least 99% from 8 pairs on; with fewer,
    /// the range of the ratios, whose coverage is 1 - 2^(1-n).
    pub confidence: f64,
}

/// The sign test's interval for the median of `ratios`: the d-th smallest
/// and d-th largest ratio, d the most that keeps the coverage,
/// 1 - 2 P(Binomial(n, 1/2) < d), at CONFIDENCE or more (at least d = 1).
pub fn paired(ratios: &[f64]) -> Paired {
    let mut sorted = ratios.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    // P(X = d) and P(X <= d), X the ratios below the true median.
    let mut p = 0.5f64.powi(n as i32);
    let (mut cdf, mut d) = (p, 0);
    while d + 1 < n.div_ceil(2) {
        let next = p * (n - d) as f64 / (d + 1) as f64;
        if 1.0 - 2.0 * (cdf + next) < CONFIDENCE {
            break;
        }
        (p, cdf, d) = (next, cdf + next, d + 1);
    }
    Paired {
        median: median(&sorted),
        low: sorted[d],
        high: sorted[n - 1 - d],
        confidence: 1.0 - 2.0 * cdf,
    }
}

/// What paired runs of two builds say of this one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Difference {
    Faster,
    Slower,
    /// Neither: the interval holds 1, or the median is within the tolerance.
    None,
}

impl Difference {
    pub fn words(self) -> &'static str {
        match self {
            Difference::Faster => "faster",
            Difference::Slower => "slower",
            Difference::None => "no difference detected",
        }
    }
}

/// Slower when the whole interval is above 1 and the median beyond the
/// tolerance (0.05 for 5%); faster likewise below.
pub fn difference(p: &Paired, tolerance: f64) -> Difference {
    if p.low > 1.0 && p.median > 1.0 + tolerance {
        Difference::Slower
    } else if p.high < 1.0 && p.median < 1.0 / (1.0 + tolerance) {
        Difference::Faster
    } else {
        Difference::None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sign_test_interval_keeps_95_percent() {
        // 5 pairs: no interval reaches 95%; the range, at 1 - 2/32.
        let five = paired(&[1.3, 1.1, 1.2, 1.0, 1.4]);
        assert_eq!((five.low, five.high, five.median), (1.0, 1.4, 1.2));
        assert_eq!(five.confidence, 1.0 - 2.0 / 32.0);
        // 10 pairs: 1 - 2 x 11/1024 = 97.9% is not 99%: the range, 99.8%.
        let ten: Vec<f64> = (1..=10).map(|i| i as f64).collect();
        let p = paired(&ten);
        assert_eq!((p.low, p.high), (1.0, 10.0));
        assert!((p.confidence - (1.0 - 2.0 / 1024.0)).abs() < 1e-12);
        // 12 pairs: the 2nd to the 11th, 1 - 2 x 13/4096 = 99.4%.
        let twelve: Vec<f64> = (1..=12).map(|i| i as f64).collect();
        let p = paired(&twelve);
        assert_eq!((p.low, p.high), (2.0, 11.0));
        assert!((p.confidence - (1.0 - 26.0 / 4096.0)).abs() < 1e-12);
        // 20 pairs: P(X <= 3) = 0.0013, P(X <= 4) = 0.0059: the 4th to the 17th.
        let twenty: Vec<f64> = (1..=20).map(|i| i as f64).collect();
        assert_eq!((paired(&twenty).low, paired(&twenty).high), (4.0, 17.0));
    }

    #[test]
    fn a_difference_needs_the_interval_and_the_tolerance() {
        let at = |median: f64, low: f64, high: f64| Paired {
            median,
            low,
            high,
            confidence: 0.95,
        };
        assert_eq!(difference(&at(1.2, 1.1, 1.3), 0.05), Difference::Slower);
        assert_eq!(difference(&at(0.8, 0.7, 0.9), 0.05), Difference::Faster);
        assert_eq!(difference(&at(1.2, 0.9, 1.3), 0.05), Difference::None);
        // Surely slower, but by less than the tolerance.
        assert_eq!(difference(&at(1.02, 1.01, 1.03), 0.05), Difference::None);
    }

    #[test]
    fn a_job_is_judged_by_its_steady_figures_or_else_by_wall() {
        let stats = |m: f64| json!({"median": m, "min": m, "max": m, "mad": 0.0});
        let old = json!({"wall_seconds": stats(1.0)});
        let before = json!({"wall_seconds": stats(1.0), "floor": {"ratio": stats(2.0)},
                            "cpu_seconds_per_frame": stats(0.5)});
        // Twice the wall (a busy machine), the same ratio and CPU: no regression.
        let busy = json!({"wall_seconds": stats(2.0), "floor": {"ratio": stats(2.0)},
                          "cpu_seconds_per_frame": stats(0.5)});
        let judged = judge(&busy, &before, 0.05);
        let figures: Vec<_> = judged.iter().map(|j| (j.figure, j.verdict)).collect();
        assert_eq!(
            figures,
            [
                ("floor ratio", Verdict::Within),
                ("CPU s/frame", Verdict::Within)
            ]
        );
        // More CPU per frame alone is a regression (a slower codec moves the floor too).
        let codec = json!({"wall_seconds": stats(1.2), "floor": {"ratio": stats(2.0)},
                           "cpu_seconds_per_frame": stats(0.6)});
        assert_eq!(judge(&codec, &before, 0.05)[1].verdict, Verdict::Regression);
        // Against a record without them: wall.
        let judged = judge(&busy, &old, 0.05);
        assert_eq!(
            (judged[0].figure, judged[0].verdict),
            ("median wall", Verdict::Regression)
        );
    }
}

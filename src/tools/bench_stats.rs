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

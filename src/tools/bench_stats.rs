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
    /// How many values.
    pub runs: usize,
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
            runs: values.len(),
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
            runs: value["runs"].as_array().map_or(1, |r| r.len().max(1)),
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

/// How many standard errors apart two medians must be to count as a
/// difference: 2, one-sided 97.7% (specs/bench.md).
const NOISE_ERRORS: f64 = 2.0;

impl Stats {
    /// The standard error of the median, from the runs' spread: for normal
    /// noise 1.2533 sigma / sqrt(n), sigma estimated as 1.4826 MAD.
    fn median_error(&self) -> f64 {
        1.2533 * 1.4826 * self.mad / (self.runs as f64).sqrt()
    }
}

/// `now` against `before` with a tolerance (0.05 for 5%): a regression only
/// where the median is slower beyond it and the two medians differ beyond
/// their noise (2 standard errors of their difference).
pub fn verdict(now: &Stats, before: &Stats, tolerance: f64) -> Verdict {
    let error = now.median_error().hypot(before.median_error());
    if now.median <= before.median * (1.0 + tolerance) {
        Verdict::Within
    } else if now.median - before.median <= NOISE_ERRORS * error {
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

/// A job against its baseline: the figures compared, and whether the job
/// regressed by the rule of specs/bench.md.
pub struct Judgement {
    pub figures: Vec<Judged>,
    pub regression: bool,
}

/// The figures paired with the floor, run by run: the job's CPU time over
/// the floor's (which neither time-slicing nor a contention that slows both
/// alike moves), and its wall time over the floor's (which sees waiting).
const PAIRED: [(&str, &[&str]); 2] = [
    ("floor CPU ratio", &["floor", "cpu_ratio"]),
    ("floor ratio", &["floor", "ratio"]),
];

/// `job` against the baseline's `before` (specs/bench.md): by its two
/// ratios to the floor, a regression when both are slower beyond the
/// tolerance (two figures whose noise differs agree), or either is beyond
/// the tolerance and its noise and the other not faster beyond both;
/// without a floor (`--no-floor`), by its CPU seconds per frame; against an
/// older record, by its median wall time.
pub fn judge(job: &Value, before: &Value, tolerance: f64) -> Judgement {
    let get = |v: &Value, path: &[&str]| Stats::from_json(path.iter().fold(v, |v, k| &v[*k]));
    let judged = |&(figure, path): &(&'static str, &[&str])| {
        let (now, before) = (get(job, path)?, get(before, path)?);
        let verdict = verdict(&now, &before, tolerance);
        Some(Judged {
            figure,
            now,
            before,
            verdict,
        })
    };
    let paired: Vec<Judged> = PAIRED.iter().filter_map(judged).collect();
    if paired.len() == 2 {
        // Faster beyond the tolerance and the noise (the rule the other way).
        let faster = |j: &Judged| verdict(&j.before, &j.now, tolerance) == Verdict::Regression;
        let slower =
            |j: &Judged, other: &Judged| j.verdict == Verdict::Regression && !faster(other);
        let both = paired.iter().all(|j| j.verdict != Verdict::Within);
        let regression = both || slower(&paired[0], &paired[1]) || slower(&paired[1], &paired[0]);
        return Judgement {
            figures: paired,
            regression,
        };
    }
    let alone = [
        ("CPU s/frame", &["cpu_seconds_per_frame"][..]),
        ("median wall", &["wall_seconds"][..]),
    ];
    let figures: Vec<Judged> = alone.iter().filter_map(judged).take(1).collect();
    let regression = figures.iter().any(|j| j.verdict == Verdict::Regression);
    Judgement {
        figures,
        regression,
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
    fn a_job_is_judged_by_its_ratios_to_the_floor_or_else_alone() {
        let stats =
            |m: f64| json!({"median": m, "min": m, "max": m, "mad": 0.0, "runs": vec![m; 5]});
        let record = |wall: f64, ratio: f64, cpu_ratio: f64, cpu: f64| {
            json!({"wall_seconds": stats(wall), "cpu_seconds_per_frame": stats(cpu),
                   "floor": {"ratio": stats(ratio), "cpu_ratio": stats(cpu_ratio)}})
        };
        let before = record(1.0, 2.0, 1.5, 0.5);
        let verdicts =
            |j: &Judgement| -> Vec<_> { j.figures.iter().map(|f| (f.figure, f.verdict)).collect() };
        // Three times the wall and more CPU a frame (a busy machine), the
        // same ratios: no regression.
        let busy = judge(&record(3.0, 2.0, 1.5, 0.6), &before, 0.05);
        assert!(!busy.regression);
        assert_eq!(
            verdicts(&busy),
            [
                ("floor CPU ratio", Verdict::Within),
                ("floor ratio", Verdict::Within)
            ]
        );
        // Busy work planted in the job: both ratios up; a job that waits
        // (asleep): its wall ratio alone.
        assert!(judge(&record(1.2, 2.3, 1.7, 0.6), &before, 0.05).regression);
        // Both up beyond the tolerance, each within its noise: they agree.
        let noisy =
            |m: f64| json!({"median": m, "min": m, "max": m, "mad": 0.5, "runs": vec![m; 5]});
        let ratios = |ratio: Value, cpu_ratio: Value| {
            json!({"wall_seconds": stats(1.2), "cpu_seconds_per_frame": stats(0.5),
                   "floor": {"ratio": ratio, "cpu_ratio": cpu_ratio}})
        };
        let judged = judge(&ratios(noisy(2.2), noisy(1.6)), &before, 0.05);
        assert_eq!(
            verdicts(&judged),
            [
                ("floor CPU ratio", Verdict::Noise),
                ("floor ratio", Verdict::Noise)
            ]
        );
        assert!(judged.regression);
        // One up within its noise, the other within the tolerance: none.
        assert!(!judge(&ratios(noisy(2.2), stats(1.55)), &before, 0.05).regression);
        // The wall ratio up beyond its noise, the CPU ratio 7% lower within
        // its noise: the wall ratio's regression stands.
        assert!(judge(&ratios(stats(3.0), noisy(1.4)), &before, 0.05).regression);
        assert!(judge(&record(1.5, 3.0, 1.5, 0.5), &before, 0.05).regression);
        // One ratio up, the other faster beyond the tolerance: they
        // contradict each other, no regression.
        assert!(!judge(&record(1.0, 1.7, 1.8, 0.5), &before, 0.05).regression);
        // Without a floor: CPU per frame; against an older record: wall.
        let no_floor = |wall: f64, cpu: f64| json!({"wall_seconds": stats(wall), "cpu_seconds_per_frame": stats(cpu)});
        let judged = judge(&no_floor(1.0, 0.6), &before, 0.05);
        assert_eq!(verdicts(&judged), [("CPU s/frame", Verdict::Regression)]);
        let old = json!({"wall_seconds": stats(1.0)});
        let judged = judge(&busy_wall(), &old, 0.05);
        assert_eq!(verdicts(&judged), [("median wall", Verdict::Regression)]);
        assert!(judged.regression);
    }

    fn busy_wall() -> Value {
        json!({"wall_seconds": {"median": 2.0, "min": 2.0, "max": 2.0, "mad": 0.0, "runs": [2.0]}})
    }

    #[test]
    fn two_medians_differ_beyond_their_standard_errors() {
        // Seven runs each, MAD 0.06 about 1.0: the medians' standard error
        // 1.2533 x 1.4826 x 0.06 / sqrt(7) = 0.042 each, their difference's
        // 0.060; 2 of them, 0.119.
        let around =
            |m: f64| Stats::of(&[m - 0.1, m - 0.06, m - 0.06, m, m + 0.06, m + 0.06, m + 0.1]);
        assert!((around(1.0).mad - 0.06).abs() < 1e-12);
        assert_eq!(verdict(&around(1.04), &around(1.0), 0.05), Verdict::Within);
        assert_eq!(verdict(&around(1.10), &around(1.0), 0.05), Verdict::Noise);
        assert_eq!(
            verdict(&around(1.16), &around(1.0), 0.05),
            Verdict::Regression
        );
        // The same spread over 28 runs: half the error.
        let many = |m: f64| {
            let runs = [m - 0.1, m - 0.06, m - 0.06, m, m + 0.06, m + 0.06, m + 0.1];
            Stats::of(&runs.repeat(4))
        };
        assert_eq!(verdict(&many(1.08), &many(1.0), 0.05), Verdict::Regression);
    }
}

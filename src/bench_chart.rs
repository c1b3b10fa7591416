//! `bench --report FILE.svg`: each job's runs as dots on a wall-time axis of
//! its own, the baseline's beside them, medians as bars.

use serde_json::Value;
use std::fmt::Write;

const ROW: f64 = 56.0;
const LEFT: f64 = 150.0;
const WIDTH: f64 = 560.0;

fn runs(job: &Value) -> Vec<f64> {
    job["wall_seconds"]["runs"]
        .as_array()
        .map(|a| a.iter().filter_map(Value::as_f64).collect())
        .unwrap_or_default()
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// The chart of `record`'s jobs, with `baseline`'s runs of the same names.
pub fn svg(record: &Value, baseline: Option<&Value>) -> String {
    let jobs: &[Value] = record["jobs"].as_array().map_or(&[], Vec::as_slice);
    let height = 60.0 + ROW * jobs.len() as f64;
    let mut out = String::new();
    let _ = write!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{height}\" \
         font-family=\"sans-serif\" font-size=\"12\">\n\
         <rect width=\"{w}\" height=\"{height}\" fill=\"white\"/>\n\
         <text x=\"10\" y=\"20\" font-size=\"14\">exrcomp bench: wall seconds per run \
         (blue: this record, grey: baseline; bars: medians)</text>\n",
        w = LEFT + WIDTH + 90.0,
    );
    for (i, job) in jobs.iter().enumerate() {
        let name = job["name"].as_str().unwrap_or("?");
        let before = baseline
            .and_then(|b| {
                b["jobs"]
                    .as_array()?
                    .iter()
                    .find(|j| j["name"] == job["name"])
            })
            .map(runs)
            .unwrap_or_default();
        let now = runs(job);
        let top = 40.0 + ROW * i as f64;
        let most = now.iter().chain(&before).fold(1e-9f64, |m, &v| m.max(v)) * 1.1;
        let x = |v: f64| LEFT + WIDTH * v / most;
        let _ = write!(
            out,
            "<text x=\"10\" y=\"{}\">{}</text>\n<line x1=\"{LEFT}\" y1=\"{y}\" x2=\"{}\" y2=\"{y}\" \
             stroke=\"#999\"/>\n<text x=\"{}\" y=\"{y}\">{most:.3} s</text>\n",
            top + 24.0,
            escape(name),
            LEFT + WIDTH,
            LEFT + WIDTH + 6.0,
            y = top + ROW - 12.0,
        );
        for (values, y, colour) in [(&before, top + 12.0, "#888"), (&now, top + 30.0, "#1f6fd0")] {
            for &v in values.iter() {
                let _ = writeln!(
                    out,
                    "<circle cx=\"{:.1}\" cy=\"{y}\" r=\"4\" fill=\"{colour}\"><title>{v:.4} s</title></circle>",
                    x(v)
                );
            }
            if !values.is_empty() {
                let median = crate::bench::Stats::of(values).median;
                let _ = writeln!(
                    out,
                    "<line x1=\"{m:.1}\" y1=\"{}\" x2=\"{m:.1}\" y2=\"{}\" stroke=\"{colour}\" stroke-width=\"2\"/>",
                    y - 8.0,
                    y + 8.0,
                    m = x(median)
                );
            }
        }
    }
    out.push_str("</svg>\n");
    out
}

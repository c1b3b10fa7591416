//! `bench --report FILE.html`: one page that needs nothing else (no script,
//! no network, SVG inline): the jobs' figures, their runs against the
//! baseline's or the other build's, where their CPU goes stage by stage,
//! and with `--history` their throughput over earlier records
//! (specs/bench.md). The charts are bench_chart's shapes.

use crate::tools::bench_chart::{escape, render_svg, Chart, Shape, AXIS, LEFT, NOW, WIDTH};
use serde_json::Value;
use std::fmt::Write;
use std::path::Path;

/// The stages' colours, in `Stage::ALL`'s order.
const STAGES: [(&str, [u8; 3]); 4] = [
    ("decode", [0x4c, 0x9b, 0xe8]),
    ("compose", [0xe8, 0x9b, 0x3c]),
    ("encode", [0x5c, 0xb8, 0x5c]),
    ("write", [0xa0, 0x6c, 0xc8]),
];
const BAR: f64 = 18.0;

/// What the report shows: this record, what its runs are drawn against
/// (the baseline, or the other build's runs), earlier records.
pub struct Report<'a> {
    pub record: &'a Value,
    pub comparison: Option<&'a Value>,
    pub history: &'a [Value],
}

impl Report<'_> {
    /// The file for `path`: a chart (FILE.svg, FILE.png) or the page.
    pub fn file(&self, path: &Path) -> Vec<u8> {
        use crate::tools::bench_chart::{png, svg};
        match path.extension().and_then(|e| e.to_str()) {
            Some("png") => png(self.record, self.comparison),
            Some("html") => self.html().into_bytes(),
            _ => svg(self.record, self.comparison).into_bytes(),
        }
    }

    /// The page: well-formed XML too, so that it can be checked as such.
    fn html(&self) -> String {
        let r = self.record;
        let mut page = String::from(
            "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"/>\
             <title>exrcomp bench</title>\n<style>body{font-family:sans-serif;margin:1.5em}\
             table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:2px 8px;\
             text-align:right}td:first-child{text-align:left}\
             section{break-inside:avoid}</style></head>\n<body>\n<h1>exrcomp bench</h1>\n",
        );
        let _ = writeln!(
            page,
            "<p>exrcomp {} ({}), {} ({} cores), {}{}</p>",
            text(&r["exrcomp"]["version"]),
            text(&r["exrcomp"]["profile"]),
            text(&r["machine"]["model"]),
            text(&r["machine"]["cores"]),
            text(&r["date"]),
            r["commit"]
                .as_str()
                .map_or(String::new(), |c| format!(", commit {}", escape(c))),
        );
        page += &self.table();
        let against = match r["jobs"][0]["against"]["exrcomp"].as_str() {
            Some(other) => format!("grey: {}", escape(other)),
            None => "grey: the baseline".into(),
        };
        let sections = [
            (
                format!("Runs: wall seconds (blue: this record, {against})"),
                crate::tools::bench_chart::inline_svg(r, self.comparison),
            ),
            (
                "Stages: CPU seconds per run (medians), serial share".into(),
                render_svg(&stages(r), false),
            ),
        ];
        for (title, svg) in sections {
            let _ = writeln!(page, "<section><h2>{title}</h2>\n{svg}</section>");
        }
        if !self.history.is_empty() {
            let mut records: Vec<&Value> = self.history.iter().collect();
            records.push(r);
            let svg = render_svg(&history(&records), false);
            let _ = writeln!(
                page,
                "<section><h2>Throughput over time: megapixels per second</h2>\n{svg}</section>"
            );
        }
        page + "</body></html>\n"
    }

    /// A row per job: its figures and its verdict.
    fn table(&self) -> String {
        let mut table = String::from(
            "<table><tr><th>job</th><th>frames</th><th>wall s</th><th>/ floor</th>\
             <th>CPU s / frame</th><th>frames/s</th><th>MP/s</th><th>peak MiB</th>\
             <th>against</th></tr>\n",
        );
        for job in self.record["jobs"].as_array().into_iter().flatten() {
            let number = |v: &Value, digits: usize| {
                v.as_f64().map_or("-".into(), |v| format!("{v:.digits$}"))
            };
            let against = match job["against"]["verdict"].as_str() {
                Some(verdict) => format!(
                    "{}x: {verdict}",
                    number(&job["against"]["ratio"]["median"], 3)
                ),
                None => String::new(),
            };
            let peak = job["peak_rss_bytes"]["median"]
                .as_f64()
                .map(|b| b / 1048576.0);
            let _ = writeln!(
                table,
                "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>\
                 <td>{}</td><td>{}</td><td>{against}</td></tr>",
                text(&job["name"]),
                text(&job["frames"]),
                number(&job["wall_seconds"]["median"], 3),
                number(&job["floor"]["ratio"]["median"], 3),
                number(&job["cpu_seconds_per_frame"]["median"], 4),
                number(&job["frames_per_second"], 2),
                number(&job["megapixels_per_second"], 2),
                peak.map_or("-".into(), |p| format!("{p:.1}")),
            );
        }
        table + "</table>\n"
    }
}

/// A JSON value as escaped text (a string without its quotes).
fn text(value: &Value) -> String {
    match value {
        Value::String(s) => escape(s),
        Value::Null => "-".into(),
        other => escape(&other.to_string()),
    }
}

/// A stage's CPU seconds in a job's record: its thread's and the pool's.
fn stage_cpu(job: &Value, stage: &str) -> f64 {
    let figures = &job["stages"][stage];
    ["serial_cpu_s", "pool_cpu_s"]
        .iter()
        .filter_map(|k| figures[*k].as_f64())
        .sum()
}

/// A bar per job, its stages' CPU side by side on one scale, the serial
/// share and peak memory after it.
fn stages(record: &Value) -> Chart {
    let jobs: &[Value] = record["jobs"].as_array().map_or(&[], Vec::as_slice);
    let total = |job: &Value| STAGES.iter().map(|(s, _)| stage_cpu(job, s)).sum::<f64>();
    let most = jobs.iter().map(total).fold(1e-9, f64::max);
    let mut shapes = Vec::new();
    for (i, (stage, colour)) in STAGES.iter().enumerate() {
        let x = LEFT + 110.0 * i as f64;
        let title = format!("{stage} CPU");
        shapes.push(Shape::Rect {
            x,
            y: 8.0,
            w: 12.0,
            h: 12.0,
            colour: *colour,
            title,
        });
        let text = stage.to_string();
        shapes.push(Shape::Text {
            x: x + 16.0,
            y: 18.0,
            text,
        });
    }
    for (i, job) in jobs.iter().enumerate() {
        let y = 34.0 + (BAR + 14.0) * i as f64;
        let text = job["name"].as_str().unwrap_or("?").to_string();
        shapes.push(Shape::Text {
            x: 10.0,
            y: y + 13.0,
            text,
        });
        let mut x = LEFT;
        for (stage, colour) in STAGES {
            let seconds = stage_cpu(job, stage);
            let w = WIDTH * seconds / most;
            let title = format!("{stage}: {seconds} s CPU");
            shapes.push(Shape::Rect {
                x,
                y,
                w,
                h: BAR,
                colour,
                title,
            });
            x += w;
        }
        let share = job["serial_share"]
            .as_f64()
            .map_or("-".into(), |s| format!("{:.0}%", 100.0 * s));
        let peak = job["peak_rss_bytes"]["median"].as_f64().unwrap_or(0.0) / 1048576.0;
        let text = format!("{:.3} s, serial {share}, peak {peak:.0} MiB", total(job));
        shapes.push(Shape::Text {
            x: x + 6.0,
            y: y + 13.0,
            text,
        });
    }
    Chart {
        width: LEFT + WIDTH + 260.0,
        height: 40.0 + (BAR + 14.0) * jobs.len() as f64,
        shapes,
    }
}

/// What labels a record on the time axis: its commit, else its date.
fn label(record: &Value) -> String {
    match (record["commit"].as_str(), record["date"].as_str()) {
        (Some(commit), _) => commit.chars().take(10).collect(),
        (None, Some(date)) => date.get(5..16).unwrap_or(date).replace('T', " "),
        (None, None) => "?".into(),
    }
}

/// A row per job of the last record: its megapixels per second in each
/// record (a dot, joined by lines), on an axis from 0 to its best.
fn history(records: &[&Value]) -> Chart {
    const ROW: f64 = 110.0;
    let last = records[records.len() - 1];
    let jobs: &[Value] = last["jobs"].as_array().map_or(&[], Vec::as_slice);
    let step = WIDTH / records.len().max(2) as f64;
    let mut shapes = Vec::new();
    for (i, job) in jobs.iter().enumerate() {
        let top = 10.0 + ROW * i as f64;
        let rates: Vec<Option<f64>> = records
            .iter()
            .map(|r| {
                crate::tools::bench_stats::same_job(Some(r), job)?["megapixels_per_second"].as_f64()
            })
            .collect();
        let best = rates.iter().flatten().fold(1e-9f64, |m, &v| m.max(v)) * 1.1;
        let (base, height) = (top + 70.0, 60.0);
        let text = job["name"].as_str().unwrap_or("?").to_string();
        shapes.push(Shape::Text {
            x: 10.0,
            y: top + 30.0,
            text,
        });
        let (x2, text) = (LEFT + WIDTH, format!("{best:.1} MP/s"));
        shapes.push(Shape::Line {
            x1: LEFT,
            y1: base,
            x2,
            y2: base,
            colour: AXIS,
            width: 1.0,
        });
        shapes.push(Shape::Text {
            x: LEFT,
            y: top + 8.0,
            text,
        });
        let mut previous: Option<(f64, f64)> = None;
        for (k, (rate, record)) in rates.iter().zip(records).enumerate() {
            let x = LEFT + step * (k as f64 + 0.5);
            let text = label(record);
            shapes.push(Shape::Text {
                x: x - 30.0,
                y: base + 14.0 + 12.0 * (k % 2) as f64,
                text,
            });
            let Some(rate) = *rate else { continue };
            let y = base - height * rate / best;
            if let Some((x1, y1)) = previous {
                shapes.push(Shape::Line {
                    x1,
                    y1,
                    x2: x,
                    y2: y,
                    colour: NOW,
                    width: 1.0,
                });
            }
            let title = format!("{rate} MP/s");
            shapes.push(Shape::Dot {
                x,
                y,
                colour: NOW,
                title,
            });
            previous = Some((x, y));
        }
    }
    Chart {
        width: LEFT + WIDTH + 60.0,
        height: 20.0 + ROW * jobs.len() as f64,
        shapes,
    }
}

//! `bench --report FILE.svg|FILE.png`: each job's runs as dots on a
//! wall-time axis of its own, the baseline's beside them, medians as bars.
//! One layout of shapes, drawn as SVG or rasterised into a PNG.

use crate::io::media::{png_file, Rgb8};
use serde_json::Value;
use std::fmt::Write;

const ROW: f64 = 56.0;
pub const LEFT: f64 = 150.0;
pub const WIDTH: f64 = 560.0;
pub const NOW: [u8; 3] = [0x1f, 0x6f, 0xd0];
const BEFORE: [u8; 3] = [0x88, 0x88, 0x88];
pub const AXIS: [u8; 3] = [0x99, 0x99, 0x99];
const INK: [u8; 3] = [0, 0, 0];
const DOT: f64 = 4.0;

/// What a chart is made of, in pixels from the top left.
pub enum Shape {
    /// Text whose baseline starts at (x, y).
    Text { x: f64, y: f64, text: String },
    Line {
        x1: f64,
        y1: f64,
        x2: f64,
        y2: f64,
        colour: [u8; 3],
        width: f64,
    },
    /// A figure (a run): a dot, its value as a tooltip in SVG.
    Dot {
        x: f64,
        y: f64,
        colour: [u8; 3],
        title: String,
    },
    /// A filled box, its figure as a tooltip in SVG.
    Rect {
        x: f64,
        y: f64,
        w: f64,
        h: f64,
        colour: [u8; 3],
        title: String,
    },
}

pub struct Chart {
    pub width: f64,
    pub height: f64,
    pub shapes: Vec<Shape>,
}

fn runs(job: &Value) -> Vec<f64> {
    job["wall_seconds"]["runs"]
        .as_array()
        .map(|a| a.iter().filter_map(Value::as_f64).collect())
        .unwrap_or_default()
}

/// The chart of `record`'s jobs, with `baseline`'s runs of the same names.
fn layout(record: &Value, baseline: Option<&Value>) -> Chart {
    let jobs: &[Value] = record["jobs"].as_array().map_or(&[], Vec::as_slice);
    let mut shapes = vec![Shape::Text {
        x: 10.0,
        y: 20.0,
        text:
            "exrcomp bench: wall seconds per run (blue: this record, grey: baseline; bars: medians)"
                .into(),
    }];
    for (i, job) in jobs.iter().enumerate() {
        let before = crate::tools::bench_stats::same_job(baseline, job)
            .map(runs)
            .unwrap_or_default();
        let now = runs(job);
        let top = 40.0 + ROW * i as f64;
        let most = now.iter().chain(&before).fold(1e-9f64, |m, &v| m.max(v)) * 1.1;
        let x = |v: f64| LEFT + WIDTH * v / most;
        let axis = top + ROW - 12.0;
        shapes.push(Shape::Text {
            x: 10.0,
            y: top + 24.0,
            text: job["name"].as_str().unwrap_or("?").to_string(),
        });
        shapes.push(Shape::Line {
            x1: LEFT,
            y1: axis,
            x2: LEFT + WIDTH,
            y2: axis,
            colour: AXIS,
            width: 1.0,
        });
        shapes.push(Shape::Text {
            x: LEFT + WIDTH + 6.0,
            y: axis,
            text: format!("{most:.3} s"),
        });
        for (values, y, colour) in [(&before, top + 12.0, BEFORE), (&now, top + 30.0, NOW)] {
            shapes.extend(values.iter().map(|&v| Shape::Dot {
                x: x(v),
                y,
                colour,
                title: format!("{v} s"),
            }));
            if !values.is_empty() {
                let median = x(crate::tools::bench_stats::Stats::of(values).median);
                shapes.push(Shape::Line {
                    x1: median,
                    y1: y - 8.0,
                    x2: median,
                    y2: y + 8.0,
                    colour,
                    width: 2.0,
                });
            }
        }
    }
    Chart {
        width: LEFT + WIDTH + 90.0,
        height: 60.0 + ROW * jobs.len() as f64,
        shapes,
    }
}

pub fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

fn hex([r, g, b]: [u8; 3]) -> String {
    format!("#{r:02x}{g:02x}{b:02x}")
}

/// The chart as an SVG document.
pub fn svg(record: &Value, baseline: Option<&Value>) -> String {
    render_svg(&layout(record, baseline), true)
}

/// The runs' chart as SVG inside an HTML page.
pub fn inline_svg(record: &Value, comparison: Option<&Value>) -> String {
    render_svg(&layout(record, comparison), false)
}

/// `chart` as SVG: a document of its own (`standalone`, with its
/// namespace), or an element inside an HTML page, which needs none.
pub fn render_svg(chart: &Chart, standalone: bool) -> String {
    let mut out = String::new();
    let namespace = match standalone {
        true => " xmlns=\"http://www.w3.org/2000/svg\"",
        false => "",
    };
    let _ = writeln!(
        out,
        "<svg{namespace} width=\"{w}\" height=\"{h}\" \
         font-family=\"sans-serif\" font-size=\"12\">\n\
         <rect width=\"{w}\" height=\"{h}\" fill=\"white\"/>",
        w = chart.width,
        h = chart.height,
    );
    for shape in &chart.shapes {
        let _ = match shape {
            Shape::Text { x, y, text } => {
                writeln!(out, "<text x=\"{x}\" y=\"{y}\">{}</text>", escape(text))
            }
            Shape::Line { x1, y1, x2, y2, colour, width } => writeln!(
                out,
                "<line x1=\"{x1:.1}\" y1=\"{y1}\" x2=\"{x2:.1}\" y2=\"{y2}\" stroke=\"{}\" stroke-width=\"{width}\"/>",
                hex(*colour)
            ),
            Shape::Dot { x, y, colour, title } => writeln!(
                out,
                "<circle cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"{DOT}\" fill=\"{}\"><title>{}</title></circle>",
                hex(*colour),
                escape(title)
            ),
            Shape::Rect { x, y, w, h, colour, title } => writeln!(
                out,
                "<rect x=\"{x:.1}\" y=\"{y:.1}\" width=\"{w:.1}\" height=\"{h:.1}\" fill=\"{}\"><title>{}</title></rect>",
                hex(*colour),
                escape(title)
            ),
        };
    }
    out.push_str("</svg>\n");
    out
}

/// The chart as a PNG file: the same shapes, the text in the built-in font.
pub fn png(record: &Value, baseline: Option<&Value>) -> Vec<u8> {
    let chart = layout(record, baseline);
    let (width, height) = (chart.width.ceil() as usize, chart.height.ceil() as usize);
    let mut image = Rgb8 {
        width,
        height,
        pixels: vec![[255; 3]; width * height],
    };
    let mut set = |x: f64, y: f64, colour: [u8; 3]| {
        if x >= 0.0 && y >= 0.0 && (x as usize) < width && (y as usize) < height {
            image.pixels[y as usize * width + x as usize] = colour;
        }
    };
    for shape in &chart.shapes {
        match *shape {
            Shape::Text { x, y, ref text } => {
                // The glyphs stand on the baseline, as SVG's text does.
                let top = y - crate::draw::font::HEIGHT as f64;
                for (px, py) in crate::draw::font::pixels(text, 1) {
                    set(x + px as f64, top + py as f64, INK);
                }
            }
            Shape::Line {
                x1,
                y1,
                x2,
                y2,
                colour,
                width,
            } => {
                let steps = (x2 - x1).abs().max((y2 - y1).abs()).ceil().max(1.0) as usize;
                for k in 0..=steps {
                    let t = k as f64 / steps as f64;
                    let (x, y) = (x1 + (x2 - x1) * t, y1 + (y2 - y1) * t);
                    for w in 0..width.ceil() as usize {
                        // Thick lines widen across their direction.
                        match x1 == x2 {
                            true => set(x + w as f64, y, colour),
                            false => set(x, y + w as f64, colour),
                        }
                    }
                }
            }
            Shape::Rect {
                x, y, w, h, colour, ..
            } => {
                for py in y as usize..(y + h).ceil() as usize {
                    for px in x as usize..(x + w).ceil() as usize {
                        set(px as f64, py as f64, colour);
                    }
                }
            }
            Shape::Dot { x, y, colour, .. } => {
                let r = DOT as i32;
                for dy in -r..=r {
                    for dx in -r..=r {
                        if dx * dx + dy * dy <= r * r {
                            set(x + dx as f64, y + dy as f64, colour);
                        }
                    }
                }
            }
        }
    }
    png_file(&image)
}

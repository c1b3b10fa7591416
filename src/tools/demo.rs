//! `exrcomp demo`: a synthetic shot staged so that each effect shows, its
//! composite in one pass, and a contact sheet of what each step did
//! (specs/demo.md).

use crate::engine::graph::{Graph, GraphBuilder, NodeId};
use crate::engine::prepass::max_over_rows;
use crate::error::{Error, Result};
use crate::io::sequence::FramePattern;
use crate::ops::sources::plate::{PixelType, Plate, PlateKind};
use crate::ops::{defocus, diffrender, merge, vblur};
use crate::run::report::{count, Summary};
use crate::run::settings::{LayerArgs, RunArgs};
use crate::run::{add, input_job, plate_job, run_job, run_with_progress, JobInputs};
use std::path::Path;

/// The defocus's focus depth: the `Set`'s row at 47% of its height (its
/// depth runs 60 to 3, top to bottom, 1/Z linear).
pub const FOCUS: f32 = 6.0;
/// The motion blur's shutter, in frames (open the whole frame: 360 degrees).
pub const SHUTTER: f32 = 1.0;
/// The contact sheet's panel width (narrower plates: their own width).
pub const PANEL_WIDTH: usize = 480;

/// The contact sheet's columns, in order, and the sequence each shows.
const COLUMNS: [(&str, &str); 6] = [
    ("ball", "ball"),
    ("set", "set"),
    ("ball vblur", "moving"),
    ("set defocus", "defocused"),
    ("comp", "comp"),
    ("diffrender", "diffrender"),
];

/// The sequences the demo writes (`NAME.####.exr`), besides the sheet.
const SEQUENCES: [&str; 9] = [
    "ball",
    "set",
    "object",
    "proxy",
    "shadowed",
    "moving",
    "defocused",
    "diffrender",
    "comp",
];
/// The contact sheet's file name.
const SHEET: &str = "contact-sheet.png";
/// The file a demo writes into its folder before anything else: a folder
/// holding it is one a demo made, whose files a demo may write again.
pub const MARKER: &str = ".exrcomp-demo";

/// Claims `dir` for the demo, before anything is written: a missing or
/// empty folder, or one an earlier demo made (holding `MARKER`) and only
/// files of the names a demo writes. Any other folder holds files the demo
/// did not write, which it would replace or mix its own with: a usage error.
/// A dry run checks and writes nothing.
fn claim(dir: &Path, dry_run: bool) -> Result<()> {
    let refuse = |why: String| {
        Error::usage(format!(
            "demo: {} {why}: give a new or empty folder (--dir), or one an earlier demo wrote",
            dir.display()
        ))
    };
    let names: Vec<String> = match std::fs::read_dir(dir) {
        Ok(entries) => entries
            .map(|e| e.map(|e| e.file_name().to_string_lossy().into_owned()))
            .collect::<std::io::Result<_>>()
            .map_err(|e| Error::output(dir, None, e))?,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Vec::new(),
        Err(e) if e.kind() == std::io::ErrorKind::NotADirectory => {
            return Err(refuse("is not a folder".into()))
        }
        Err(e) => return Err(Error::output(dir, None, e)),
    };
    let marked = names.iter().any(|n| n == MARKER);
    let mut foreign: Vec<&String> = names
        .iter()
        .filter(|n| !(marked && written_by_demo(n)))
        .collect();
    foreign.sort();
    if let Some(first) = foreign.first() {
        let more = match foreign.len() {
            1 => String::new(),
            n => format!(" and {} more", n - 1),
        };
        return Err(refuse(format!(
            "holds files the demo did not write ({first}{more})"
        )));
    }
    match dry_run {
        true => Ok(()),
        false => crate::io::writer::write_whole(&dir.join(MARKER), b"exrcomp demo folder\n"),
    }
}

/// Whether `name` is one the demo writes: its marker, the contact sheet, a
/// frame of one of its sequences, or a temporary file of its writers.
fn written_by_demo(name: &str) -> bool {
    let frame = |n: &str| {
        n.rsplit_once('.').is_some_and(|(sequence, digits)| {
            SEQUENCES.contains(&sequence)
                && digits.len() >= 4
                && digits.bytes().all(|b| b.is_ascii_digit())
        })
    };
    let temporary = name.starts_with('.') && name.ends_with(".tmp") && name.contains(".exrcomp-");
    name == MARKER || name == SHEET || temporary || name.strip_suffix(".exr").is_some_and(frame)
}

/// Writes the shot's plates into `dir`, composites them (the ball
/// motion-blurred over the set defocused, one pass; the differential
/// rendering shot), each effect alone on a few frames, and the contact sheet.
pub fn demo(dir: &Path, length: usize, width: usize, height: usize, run: &RunArgs) -> Result<()> {
    claim(dir, run.dry_run)?;
    let first = 1001;
    let last = first + length as i64 - 1;
    let pattern = |name: &str| pattern(dir, name);
    // The plates show a progress bar but no summary: the composites' are the point.
    let plates = RunArgs {
        quiet: true,
        json: false,
        ..run.clone()
    };
    let talk = |line: String| talk(run, line);
    write_plates(dir, first..=last, (width, height), run, &plates)?;
    let all = RunArgs {
        frames: Some(format!("{first}-{last}")),
        ..run.clone()
    };
    let layers = LayerArgs::default();
    let effects = Effects::measure(&pattern("ball"), height, &all)?;

    // Each effect alone, on the frames the contact sheet shows.
    let shown: Vec<i64> = {
        let mut frames = vec![first, first + (length as i64 - 1) / 2, last];
        frames.dedup();
        frames
    };
    let listed: Vec<String> = shown.iter().map(i64::to_string).collect();
    let alone = RunArgs {
        frames: Some(listed.join(",")),
        ..plates.clone()
    };
    for (input, output) in [("ball", "moving"), ("set", "defocused")] {
        let (mut graph, nodes) = GraphBuilder::with_inputs(1);
        match input {
            "ball" => effects.blur(&mut graph, nodes[0])?,
            _ => effects.defocus(&mut graph, nodes[0])?,
        };
        let (job, summary) = input_job(
            JobInputs::of(&[pattern(input)]),
            &pattern(output),
            graph.finish(),
            0,
            &layers,
            &alone,
        )?;
        run_job(&job, output, &alone, summary)?;
    }

    // Differential rendering: the ball and its shadow, rendered on a proxy
    // ground, put into the set plate.
    let shot = [
        pattern("object"),
        pattern("proxy"),
        pattern("shadowed"),
        pattern("set"),
    ];
    let (mut graph, nodes) = GraphBuilder::with_inputs(shot.len());
    add(&mut graph, &diffrender::DIFFRENDER, &[], &nodes)?;
    let (job, summary) = input_job(
        JobInputs::of(&shot),
        &pattern("diffrender"),
        graph.finish(),
        3,
        &layers,
        &all,
    )?;
    talk(format!(
        "differential rendering into {}: object over the plate with the shadow it casts on the proxy",
        pattern("diffrender")
    ));
    run_job(&job, "diffrender", &all, summary)?;

    talk(format!(
        "one pass into {}: ball motion-blurred by its forward.u/v ({SHUTTER} frame shutter), over \
         the set defocused by its Z (focus {FOCUS}, hexagonal aperture)",
        pattern("comp")
    ));
    let inputs = [pattern("ball"), pattern("set")];
    let (mut graph, nodes) = GraphBuilder::with_inputs(inputs.len());
    let moving = effects.blur(&mut graph, nodes[0])?;
    let defocused = effects.defocus(&mut graph, nodes[1])?;
    add(&mut graph, &merge::OVER, &[], &[moving, defocused])?;
    let (job, summary) = input_job(
        JobInputs::of(&inputs),
        &pattern("comp"),
        graph.finish(),
        1,
        &layers,
        &all,
    )?;
    run_job(&job, "demo", &all, summary)?;

    write_sheet(dir, width, &shown, run)
}

/// `dir`'s sequence `name` (`name.####.exr`).
fn pattern(dir: &Path, name: &str) -> String {
    dir.join(format!("{name}.####.exr"))
        .to_string_lossy()
        .into_owned()
}

/// A line of the demo's story, unless `--quiet`.
fn talk(run: &RunArgs, line: String) {
    if !run.quiet {
        eprintln!("{line}");
    }
}

/// The shot's plates, `frames` of `size`, each with its progress bar.
fn write_plates(
    dir: &Path,
    frames: std::ops::RangeInclusive<i64>,
    (width, height): (usize, usize),
    run: &RunArgs,
    plates: &RunArgs,
) -> Result<()> {
    let length = frames.clone().count();
    let pattern = |name: &str| pattern(dir, name);
    let talk = |line: String| talk(run, line);
    let kinds = [
        ("ball", PlateKind::Ball, "Z, forward.u/v"),
        ("set", PlateKind::Set, "Z"),
        ("object", PlateKind::Object, "Z"),
        ("proxy", PlateKind::Proxy, "Z"),
        ("shadowed", PlateKind::Shadowed, "Z"),
    ];
    for (name, kind, extra) in kinds {
        let plate = Plate {
            kind,
            width,
            height,
            origin: (0, 0),
            pixel_type: PixelType::Half,
        };
        let output = FramePattern::output(&pattern(name))?;
        let job = plate_job(plate, output, frames.clone().collect(), plates)?;
        let progress = RunArgs {
            quiet: run.quiet,
            ..plates.clone()
        };
        let label = format!("writing {name}");
        let (report, _) = run_with_progress(&job, &label, &progress, Summary::default(), None)?;
        report.clear();
        talk(format!(
            "wrote {} ({}, {width}x{height} half RGBA + {extra})",
            pattern(name),
            count(length, "frame")
        ));
    }
    Ok(())
}

/// The contact sheet of the `shown` frames, and what the folder holds.
fn write_sheet(dir: &Path, width: usize, shown: &[i64], run: &RunArgs) -> Result<()> {
    let pattern = |name: &str| pattern(dir, name);
    let talk = |line: String| talk(run, line);
    let listed: Vec<String> = shown.iter().map(i64::to_string).collect();
    let sheet = dir.join(SHEET);
    let rows: Vec<(String, Vec<_>)> = shown
        .iter()
        .map(|&frame| {
            let files = COLUMNS
                .iter()
                .map(|(_, name)| FramePattern::parse(&pattern(name)).map(|p| p.path(frame)))
                .collect::<Result<_>>()?;
            Ok((format!("frame {frame}"), files))
        })
        .collect::<Result<_>>()?;
    let titles: Vec<&str> = COLUMNS.iter().map(|(title, _)| *title).collect();
    crate::tools::contact_sheet::write(&sheet, PANEL_WIDTH.min(width), &titles, &rows)?;
    let (files, bytes) = folder_size(dir)?;
    talk(format!(
        "contact sheet: {} (columns: {}; rows: {})",
        sheet.display(),
        titles.join(", "),
        listed.join(", ")
    ));
    talk(format!(
        "{} holds {:.1} MB in {}",
        dir.display(),
        bytes as f64 / 1e6,
        count(files, "file")
    ));
    Ok(())
}

/// The two effects' parameters: the defocus's scaled to the plate's height,
/// the motion blur's reach measured over the ball's frames.
struct Effects {
    defocus: [(&'static str, String); 4],
    reach: String,
}

impl Effects {
    fn measure(ball: &str, height: usize, run: &RunArgs) -> Result<Self> {
        let (job, _) = input_job(
            JobInputs::of(&[ball.to_string()]),
            ball,
            Graph::identity(),
            0,
            &LayerArgs::default(),
            &RunArgs {
                dry_run: true,
                ..run.clone()
            },
        )?;
        let reach = max_over_rows(&job, 0, ["forward.u", "forward.v"], |u, v| {
            vblur::rows_reached(SHUTTER, u, v)
        })?;
        // The nearest blur a 60th of the height (18 pixels at 1080), the
        // farthest 0.9 of that.
        let scale = (height as f32 / 60.0).max(1.0);
        Ok(Effects {
            defocus: [
                ("focus", FOCUS.to_string()),
                ("scale", scale.to_string()),
                ("max_radius", (scale.ceil() as u32).to_string()),
                ("aperture", "hexagon".to_string()),
            ],
            reach: reach.to_string(),
        })
    }

    fn blur(&self, graph: &mut GraphBuilder, input: NodeId) -> Result<NodeId> {
        let shutter = SHUTTER.to_string();
        let values = [
            ("scale", shutter.as_str()),
            ("max_displacement", &self.reach),
        ];
        add(graph, &vblur::VBLUR, &values, &[input])
    }

    fn defocus(&self, graph: &mut GraphBuilder, input: NodeId) -> Result<NodeId> {
        let values: Vec<(&str, &str)> =
            self.defocus.iter().map(|(k, v)| (*k, v.as_str())).collect();
        add(graph, &defocus::DEFOCUS, &values, &[input])
    }
}

/// The files in `dir` and their bytes.
fn folder_size(dir: &Path) -> Result<(usize, u64)> {
    let entries = std::fs::read_dir(dir).map_err(|e| Error::output(dir, None, e))?;
    let mut total = (0, 0);
    for entry in entries.flatten() {
        if let Some(meta) = entry.metadata().ok().filter(|m| m.is_file()) {
            total = (total.0 + 1, total.1 + meta.len());
        }
    }
    Ok(total)
}

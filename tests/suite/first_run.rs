//! What a new user meets first (issue 20): the demo's contact sheet, decoded
//! by Python's zlib and struct and measured; `--help`'s layout per command;
//! messages' grammar; the warnings where users slip; the README's commands
//! that make specs/examples runnable.

use crate::common::*;
use std::path::Path;
use std::process::Command;

fn ok(args: &[&str]) -> String {
    let out = run(args);
    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
    stderr(&out)
}

/// The sheet's panels: maximal rectangles of pixels other than the
/// background (24, 24, 32), found as runs over 40 pixels long (text is
/// never that wide a run), as (x, y, width, height), rows then columns.
fn panels(w: usize, h: usize, pixels: &[[u8; 3]]) -> Vec<(usize, usize, usize, usize)> {
    let background = [24, 24, 32];
    let runs = |y: usize| -> Vec<(usize, usize)> {
        let mut runs = Vec::new();
        let mut x = 0;
        while x < w {
            let start = x;
            while x < w && pixels[y * w + x] != background {
                x += 1;
            }
            if x - start > 40 {
                runs.push((start, x - start));
            }
            x += 1;
        }
        runs
    };
    let mut found = Vec::new();
    let mut y = 0;
    while y < h {
        let here = runs(y);
        if here.is_empty() {
            y += 1;
            continue;
        }
        let top = y;
        while y < h && runs(y) == here {
            y += 1;
        }
        found.extend(here.iter().map(|&(x, width)| (x, top, width, y - top)));
    }
    found
}

/// Median 10%-90% width of the vertical edges along row `y` of a panel: each
/// crossing of the row's middle level, measured within half a cell of it.
fn edge_width(
    pixels: &[[u8; 3]],
    w: usize,
    (px, py, pw, _): (usize, usize, usize, usize),
    y: usize,
    cell: f64,
) -> f64 {
    let row: Vec<f64> = (0..pw)
        .map(|x| {
            pixels[(py + y) * w + px + x]
                .iter()
                .map(|&v| v as f64)
                .sum()
        })
        .collect();
    let mut sorted = row.clone();
    sorted.sort_by(f64::total_cmp);
    let (low, high) = (sorted[pw / 20], sorted[pw - 1 - pw / 20]);
    let middle = (low + high) / 2.0;
    let half = (cell / 2.0) as usize;
    let mut widths = Vec::new();
    for x in half..pw - half - 1 {
        if (row[x] - middle) * (row[x + 1] - middle) > 0.0 {
            continue;
        }
        let window = &row[x - half + 1..=x + half];
        let (lo, hi) = window
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
        if hi - lo < (high - low) / 2.0 {
            continue;
        }
        let inside = window
            .iter()
            .filter(|&&v| v > lo + 0.1 * (hi - lo) && v < hi - 0.1 * (hi - lo))
            .count();
        widths.push(inside as f64 + 1.0);
    }
    assert!(widths.len() >= 4, "row {y}: edges {widths:?}");
    widths.sort_by(f64::total_cmp);
    widths[widths.len() / 2]
}

#[test]
fn the_demo_draws_a_contact_sheet_where_blur_grows_with_distance_from_focus() {
    let dir = tempfile::tempdir().unwrap();
    let shot = dir.path().join("shot");
    let (width, height) = (640, 360);
    let message = ok(&[
        "demo",
        "--dir",
        s(&shot),
        "--width",
        "640",
        "--height",
        "360",
        "--length",
        "3",
    ]);
    let sheet = shot.join("contact-sheet.png");
    assert!(
        message.contains(&format!("contact sheet: {}", sheet.display())),
        "{message}"
    );
    let last = message.lines().last().unwrap();
    assert!(
        last.starts_with(&format!("{} holds ", shot.display())) && last.contains(" MB in "),
        "{last}"
    );
    let Some((w, h, pixels)) = decode_png(&sheet) else {
        return;
    };
    let found = panels(w, h, &pixels);
    // Six columns (ball, set, ball vblur, set defocus, comp, diffrender),
    // three frames; panels 320 wide (the plate's width, under 480).
    assert_eq!(found.len(), 18, "{found:?}");
    let (pw, ph) = (found[0].2, found[0].3);
    assert_eq!((pw, ph), (width.min(480), height * width.min(480) / width));
    let defocus = found[3];
    // Depth 1/Z runs linear from 1/60 (top) to 1/3 (bottom); focus 6.
    let focus_row = ((1.0 / 6.0 - 1.0 / 60.0) / (1.0 / 3.0 - 1.0 / 60.0) * ph as f64) as usize;
    let cell = (height / 16) as f64 * pw as f64 / width as f64;
    // Rows in the middle of a cell row with no highlights (even rows).
    let middle_of = |y: usize| {
        let j = (y as f64 / cell) as usize;
        let j = j - j % 2;
        ((j as f64 + 0.5) * cell) as usize
    };
    let sharp = edge_width(&pixels, w, defocus, middle_of(focus_row), cell);
    let far = edge_width(&pixels, w, defocus, middle_of(ph / 10), cell);
    eprintln!("set defocus panel: edges {far} px wide far from focus, {sharp} px at it");
    assert!(
        far >= 2.0 * sharp,
        "edge widths: {far} px far from focus, {sharp} px at it"
    );
    // The unblurred set's edges are sharp at both depths.
    let set = found[1];
    let plain = edge_width(&pixels, w, set, middle_of(ph / 10), cell);
    assert!(plain <= sharp.max(2.0), "{plain}");
    // The ball streaks: its blurred panel covers more than the ball does.
    let covered = |(px, py, pw, ph): (usize, usize, usize, usize)| {
        (py..py + ph)
            .flat_map(|y| (px..px + pw).map(move |x| (x, y)))
            .filter(|&(x, y)| pixels[y * w + x].iter().any(|&v| v > 40))
            .count()
    };
    for row in 0..3 {
        let (ball, blurred) = (covered(found[row * 6]), covered(found[row * 6 + 2]));
        assert!(
            blurred as f64 > 1.15 * ball as f64,
            "frame row {row}: {blurred} vs {ball}"
        );
    }
}

/// The subcommands `exrcomp --help` lists.
fn commands() -> Vec<String> {
    let out = run(&["--help"]);
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    text.lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next().map(str::to_string))
        .filter(|c| !["help", "farm"].contains(&c.as_str()))
        .collect()
}

#[test]
fn help_lists_own_options_first_then_the_shared_ones_grouped() {
    let order = [
        "Arguments:",
        "Options:",
        "Layers, views and parts:",
        "Frames and sequences:",
        "Output:",
        "Run control:",
    ];
    for command in commands() {
        let out = run(&[command.as_str(), "-h"]);
        let help = String::from_utf8_lossy(&out.stdout).to_string();
        let at: Vec<usize> = order
            .iter()
            .filter_map(|h| help.find(&format!("\n{h}\n")))
            .collect();
        assert!(
            at.windows(2).all(|w| w[0] < w[1]),
            "{command}: headings out of order:\n{help}"
        );
        // Every positional and -o is described, on its line or the next.
        let lines: Vec<&str> = help.lines().collect();
        for (n, line) in lines.iter().enumerate() {
            if !(line.starts_with("  <") || line.contains("-o, --output")) {
                continue;
            }
            let name_end = line.find('>').unwrap() + 1;
            let next = lines.get(n + 1).copied().unwrap_or_default();
            assert!(
                !line[name_end..].trim().is_empty()
                    || (next.starts_with("          ") && !next.trim().is_empty()),
                "{command}: undescribed: {line}"
            );
        }
        if help.contains("--compression") {
            assert!(
                help.contains("(default: "),
                "{command}: --compression's default:\n{help}"
            );
        }
    }
    let help =
        |command: &str| String::from_utf8_lossy(&run(&[command, "--help"]).stdout).to_string();
    assert!(!help("generate").contains("--missing") && !help("generate").contains("--keep-going"));
    assert!(!help("demo").contains("--frames") && !help("demo").contains("--dry-run"));
    assert!(!help("over").contains("--all-parts") && help("blur").contains("--all-parts"));
    assert!(help("generate").contains("dwaa, dwab (default: zip)"));
    assert!(help("over").contains("(default: the BG input's, whose header the output keeps)"));
    assert!(help("transcode").contains("(default: the input's)"));
    // Own options before the shared ones.
    let over = help("defocus");
    assert!(over.find("--focus").unwrap() < over.find("--frames").unwrap());
    // Not offered means refused too, with the reason.
    let out = run(&["generate", "x.exr", "--missing", "skip"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("--missing does not apply to `generate`: it reads no input"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn one_frame_reads_in_the_singular_and_a_short_run_ends_with_its_count() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let p = |n: &str| d.join(format!("{n}.####.exr"));
    generate(&p("fg"), "fg", (32, 16), &["--frames", "1-3"]);
    generate(&p("bg"), "bg", (32, 16), &["--frames", "1-3"]);
    let one = ok(&[
        "over",
        s(&d.join("fg.0001.exr")),
        s(&d.join("bg.0001.exr")),
        "-o",
        s(&d.join("o.exr")),
    ]);
    assert!(
        one.lines().last().unwrap().starts_with("1 frame in "),
        "{one}"
    );
    assert!(one.contains(" frames/s, "), "{one}");
    let dry = ok(&[
        "over",
        s(&p("fg")),
        s(&p("bg")),
        "-o",
        s(&p("o")),
        "--frames",
        "2",
        "--dry-run",
    ]);
    assert!(dry.contains("would write 1 frame to"), "{dry}");
    std::fs::remove_file(d.join("bg.0002.exr")).unwrap();
    let held = ok(&[
        "over",
        s(&p("fg")),
        s(&p("bg")),
        "-o",
        s(&p("h")),
        "--missing",
        "hold",
    ]);
    assert!(
        held.contains("bg.####.exr: frame 2 held from the nearest earlier frame"),
        "{held}"
    );
    let skipped = ok(&[
        "over",
        s(&p("fg")),
        s(&p("bg")),
        "-o",
        s(&p("k")),
        "--frames",
        "1-3",
        "--missing",
        "skip",
    ]);
    let last = skipped.lines().last().unwrap();
    assert!(last.starts_with("2 frames in "), "{last}");
    assert!(
        last.ends_with("; 1 of the 3 frames named left out for missing input (--missing skip): 2"),
        "{last}"
    );
}

#[test]
fn warnings_say_what_was_assumed_once_a_run_and_quiet_silences_them() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let p = |n: &str| d.join(format!("{n}.####.exr"));
    generate(&p("fg"), "fg", (64, 48), &["--frames", "1-3"]);
    generate(&p("bg"), "bg", (96, 48), &["--frames", "1-3"]);
    generate(&p("plate"), "bg", (64, 48), &["--frames", "1-3"]);
    ok(&[
        "shuffle",
        s(&p("fg")),
        "-o",
        s(&p("rgb")),
        "--ch",
        "R,G,B",
        "-q",
    ]);
    let message = ok(&["over", s(&p("rgb")), s(&p("bg")), "-o", s(&p("o"))]);
    let display = format!(
        "exrcomp: warning: {}'s display window (0 0) - (63 47) is not {}'s (0 0) - (95 47): the output keeps {}'s",
        s(&p("rgb")), s(&p("bg")), s(&p("bg"))
    );
    assert_eq!(message.matches(&display).count(), 1, "{message}");
    let alpha = format!(
        "exrcomp: warning: {} has no alpha channel (A): it is taken as opaque (alpha 1 inside its data window), hiding {} there",
        s(&p("rgb")), s(&p("bg"))
    );
    assert_eq!(message.matches(&alpha).count(), 1, "{message}");
    assert!(message.contains("merge --op plus"), "{message}");
    // A foreground with alpha of the plate's size: no warning.
    let clean = ok(&["over", s(&p("fg")), s(&p("plate")), "-o", s(&p("c"))]);
    assert!(!clean.contains("warning"), "{clean}");
    let matte = ok(&[
        "diffmatte",
        s(&p("fg")),
        "--clean-plate",
        s(&p("bg")),
        "-o",
        s(&p("m")),
    ]);
    assert!(matte.contains(&format!(
        "exrcomp: warning: the clean plate {} (96x48 at 0, 0) is not the size and place of the footage {} (64x48 at 0, 0)",
        s(&p("bg")), s(&p("fg"))
    )), "{matte}");
    // A lossy compression kept by default, not one asked for.
    ok(&[
        "transcode",
        s(&p("plate")),
        "-o",
        s(&p("dwa")),
        "--compression",
        "dwaa",
        "-q",
    ]);
    let lossy = ok(&["grade", s(&p("dwa")), "-o", s(&p("g")), "--gain", "2"]);
    assert_eq!(
        lossy
            .matches(&format!(
                "exrcomp: warning: {} has dwaa compression, which is lossy, and the output keeps it",
                s(&p("dwa"))
            ))
            .count(),
        1,
        "{lossy}"
    );
    let asked = ok(&[
        "grade",
        s(&p("dwa")),
        "-o",
        s(&p("g2")),
        "--compression",
        "dwaa",
    ]);
    assert!(!asked.contains("warning"), "{asked}");
    let quiet = run(&["over", s(&p("rgb")), s(&p("bg")), "-o", s(&p("q")), "-q"]);
    assert!(
        quiet.status.success() && stderr(&quiet).is_empty(),
        "{}",
        stderr(&quiet)
    );
}

#[test]
fn the_readme_s_two_commands_make_the_examples_runnable() {
    let readme =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md")).unwrap();
    let block: Vec<&str> = readme
        .lines()
        .skip_while(|l| !l.starts_with("<!-- examples:"))
        .skip(2)
        .take_while(|l| !l.starts_with("```"))
        .collect();
    assert_eq!(block.len(), 2, "{block:?}");
    let dir = tempfile::tempdir().unwrap();
    let examples = dir.path().join("specs/examples");
    std::fs::create_dir_all(&examples).unwrap();
    for name in ["over.toml", "chain.toml"] {
        let from = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("specs/examples")
            .join(name);
        std::fs::copy(from, examples.join(name)).unwrap();
    }
    let bin = Path::new(env!("CARGO_BIN_EXE_exrcomp")).parent().unwrap();
    let path = format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    for line in block {
        let out = Command::new("sh")
            .args(["-ec", line])
            .current_dir(dir.path())
            .env("PATH", &path)
            .output()
            .unwrap();
        assert!(out.status.success(), "{line}: {}", stderr(&out));
    }
    for frame in 1..=4 {
        assert!(
            examples.join(format!("comp.{frame:04}.exr")).is_file(),
            "frame {frame}"
        );
    }
}

/// The demo writes only into a new or empty folder, or one an earlier demo
/// wrote (its marker file and demo names only); any other is refused before
/// anything is written, its files as they were.
#[test]
fn the_demo_refuses_a_folder_holding_files_it_did_not_write() {
    let dir = tempfile::tempdir().unwrap();
    let listing = |d: &Path| {
        let mut names: Vec<String> = std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    };
    let demo = |d: &Path| {
        run(&[
            "demo",
            "--dir",
            s(d),
            "--width",
            "64",
            "--height",
            "36",
            "--length",
            "1",
            "-q",
        ])
    };
    // Someone's own comp frame, and someone's notes.
    for (folder, file) in [("theirs", "comp.1001.exr"), ("notes", "notes.txt")] {
        let d = dir.path().join(folder);
        std::fs::create_dir(&d).unwrap();
        std::fs::write(d.join(file), "not the demo's").unwrap();
        let out = demo(&d);
        assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
        let text = stderr(&out);
        assert_eq!(text.lines().count(), 1, "{text}");
        assert!(
            text.contains(file) && text.contains("did not write"),
            "{text}"
        );
        assert_eq!(listing(&d), [file], "something was written");
        assert_eq!(std::fs::read(d.join(file)).unwrap(), b"not the demo's");
    }
    // A new folder, then the same folder again: the demo's own.
    let shot = dir.path().join("shot");
    for round in 0..2 {
        let out = demo(&shot);
        assert!(out.status.success(), "round {round}: {}", stderr(&out));
    }
    assert!(listing(&shot).contains(&"comp.1001.exr".to_string()));
    // Its own folder with a file of someone else's in it.
    std::fs::write(shot.join("notes.txt"), "mine").unwrap();
    let before = listing(&shot);
    let out = demo(&shot);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("notes.txt"), "{}", stderr(&out));
    assert_eq!(listing(&shot), before);
}

//! Review movies (.mov, .mp4) written through ffmpeg: what ffprobe reports
//! of each codec (codec, size, frames, rate, colour tags, timecode), the
//! frames decoded back by ffmpeg against the PNG path's, determinism, the
//! movie placed only when whole (killed runs, a missing ffmpeg), --resume,
//! job files and farms.

use crate::common::{exrcomp, generate, peer, run, s, started, stderr};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// ffmpeg and ffprobe, or `None` (a skipped check; a failure in CI).
fn ffmpeg() -> Option<(PathBuf, PathBuf)> {
    Some((peer("ffmpeg")?, peer("ffprobe")?))
}

/// 48 plates `bg.####.exr` of `size` at 25 fps from timecode 01:02:03:04
/// (`kind`: generate's `bg`, opaque, or `fg`, with alpha).
fn plates(d: &Path, kind: &str, size: (usize, usize)) -> PathBuf {
    let pattern = d.join(format!("{kind}.####.exr"));
    let args = [
        "--frames",
        "1-48",
        "--fps",
        "25",
        "--timecode",
        "01:02:03:04",
    ];
    generate(&pattern, kind, size, &args);
    pattern
}

/// `exrcomp transcode INPUT -o OUTPUT ARGS -q`, which must succeed.
fn movie(input: &Path, output: &Path, args: &[&str]) {
    let mut all = vec!["transcode", s(input), "-o", s(output), "-q"];
    all.extend(args);
    let out = run(&all);
    assert!(out.status.success(), "{}", stderr(&out));
}

/// ffprobe's view of the movie's video stream (frames counted), and the
/// timecode of its container (the tmcd track's).
fn probe(ffprobe: &Path, movie: &Path) -> (Value, Option<String>) {
    let out = Command::new(ffprobe)
        .args([
            "-v",
            "error",
            "-count_frames",
            "-show_streams",
            "-of",
            "json",
        ])
        .arg(movie)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    let json: Value = serde_json::from_slice(&out.stdout).unwrap();
    let streams = json["streams"].as_array().unwrap();
    let video = streams
        .iter()
        .find(|st| st["codec_type"] == "video")
        .unwrap();
    let timecode = streams
        .iter()
        .find(|st| st["codec_tag_string"] == "tmcd")
        .and_then(|st| st["tags"]["timecode"].as_str())
        .map(str::to_string);
    (video.clone(), timecode)
}

/// A movie to write: (input, output, options), what ffprobe says of it
/// (codec, profile, pixel format, rate), and its size.
type Case<'a> = (&'a Path, &'a str, &'a [&'a str], [&'a str; 4], (u64, u64));

#[test]
fn ffprobe_reports_each_codecs_size_frames_rate_colour_tags_and_timecode() {
    let Some((_, ffprobe)) = ffmpeg() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let small = plates(d, "bg", (64, 48));
    let alpha = plates(d, "fg", (64, 48));
    let dnxhr = d.join("dnx/bg.####.exr");
    generate(
        &dnxhr,
        "bg",
        (256, 144),
        &["--frames", "1-48", "--fps", "25"],
    );
    let cases: [Case; 6] = [
        (
            &small,
            "p.mov",
            &[],
            ["prores", "HQ", "yuv422p10le", "25/1"],
            (64, 48),
        ),
        (
            &alpha,
            "a.mov",
            &["--codec", "prores4444"],
            ["prores", "4444", "yuva444p12le", "25/1"],
            (64, 48),
        ),
        (
            &dnxhr,
            "d.mov",
            &["--codec", "dnxhr", "--fps", "24"],
            ["dnxhd", "DNXHR 444", "yuv444p10le", "24/1"],
            (256, 144),
        ),
        (
            &small,
            "h.mp4",
            &[],
            ["h264", "High", "yuv420p", "25/1"],
            (64, 48),
        ),
        (
            &small,
            "h.mov",
            &["--codec", "h264", "--fps", "24000/1001"],
            ["h264", "High", "yuv420p", "24000/1001"],
            (64, 48),
        ),
        (
            &small,
            "t.mov",
            &["--timecode", "10:00:00:00"],
            ["prores", "HQ", "yuv422p10le", "25/1"],
            (64, 48),
        ),
    ];
    for (input, name, args, [codec, profile, pix_fmt, rate], (w, h)) in cases {
        let output = d.join(name);
        movie(input, &output, args);
        let (video, timecode) = probe(&ffprobe, &output);
        let says = |key: &str| video[key].as_str().unwrap_or_default().to_string();
        assert_eq!(says("codec_name"), codec, "{name}");
        assert_eq!(says("profile"), profile, "{name}");
        assert_eq!(says("pix_fmt"), pix_fmt, "{name}");
        assert_eq!(
            (video["width"].as_u64(), video["height"].as_u64()),
            (Some(w), Some(h)),
            "{name}"
        );
        assert_eq!(says("nb_read_frames"), "48", "{name}");
        assert_eq!(says("r_frame_rate"), rate, "{name}");
        for key in ["color_primaries", "color_transfer", "color_space"] {
            assert_eq!(says(key), "bt709", "{name}: {key}");
        }
        assert_eq!(says("color_range"), "tv", "{name}");
        let expected = match name {
            "t.mov" => Some("10:00:00:00"),
            // The DNxHR plates have no timecode: nor has their movie.
            "d.mov" => None,
            _ => Some("01:02:03:04"),
        };
        assert_eq!(timecode.as_deref(), expected, "{name}");
    }
    // A slate is the movie's first frame, its timecode one frame earlier.
    let slated = d.join("slated.mov");
    movie(&small, &slated, &["--slate"]);
    let (video, timecode) = probe(&ffprobe, &slated);
    assert_eq!(video["nb_read_frames"], "49");
    assert_eq!(timecode.as_deref(), Some("01:02:03:03"));
}

/// The movie's frames decoded by ffmpeg as 8-bit RGB, frame after frame.
fn decoded(ffmpeg: &Path, movie: &Path) -> Vec<u8> {
    let out = Command::new(ffmpeg)
        .args(["-v", "error", "-i"])
        .arg(movie)
        .args([
            "-vf",
            "scale=flags=accurate_rnd+full_chroma_int",
            "-f",
            "rawvideo",
        ])
        .args(["-pix_fmt", "rgb24", "pipe:1"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    out.stdout
}

/// An 8-bit PNG's colour samples, RGB (the png crate decodes it; alpha,
/// straight, is left out as ffmpeg's RGB leaves it).
fn png_pixels(path: &Path) -> Vec<u8> {
    let file = std::fs::File::open(path).unwrap();
    let mut reader = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .unwrap();
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut pixels).unwrap();
    pixels.truncate(info.buffer_size());
    match info.color_type {
        png::ColorType::Rgb => pixels,
        png::ColorType::Rgba => pixels.chunks(4).flat_map(|p| &p[..3]).copied().collect(),
        other => panic!("{other:?}"),
    }
}

/// Peak signal-to-noise ratio of `a` against `b`, 8-bit samples, in dB.
fn psnr(a: &[u8], b: &[u8]) -> f64 {
    assert_eq!(a.len(), b.len());
    let squared: f64 = a
        .iter()
        .zip(b)
        .map(|(&x, &y)| (x as f64 - y as f64).powi(2))
        .sum();
    let mse = squared / a.len() as f64;
    10.0 * (255.0f64 * 255.0 / mse.max(1e-12)).log10()
}

/// Each codec's movie (H.264 in .mov and .mp4) against the PNG path's
/// frames (the same job, the same burn-in), at 256x144 (DNxHR's least is
/// 256x120): on the grainy plate, and on the set's checker with highlights,
/// dense detail where DNxHR HQ (36.1 dB) and H.264 at CRF 18 (37.2 dB on its
/// first frame) fell short. ffmpeg decodes with accurate chroma
/// interpolation, as a review player filters chroma: its default, nearest
/// chroma, costs 4:2:x codecs 1.3 dB.
#[test]
fn movie_frames_decoded_by_ffmpeg_are_within_40_db_of_the_png_paths() {
    let Some((ffmpeg, _)) = ffmpeg() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let burn = ["--burn-in", "{frame:4}"];
    let (w, h) = (256, 144);
    let frame = w * h * 3;
    for kind in ["bg", "set"] {
        let input = plates(d, kind, (w, h));
        let pngs = d.join(kind);
        movie(&input, &pngs.join("f.####.png"), &burn);
        for (name, codec) in [
            ("p.mov", "prores"),
            ("q.mov", "prores4444"),
            ("d.mov", "dnxhr"),
            ("h.mov", "h264"),
            ("h.mp4", "h264"),
        ] {
            let output = pngs.join(name);
            movie(&input, &output, &[&burn[..], &["--codec", codec]].concat());
            let frames = decoded(&ffmpeg, &output);
            assert_eq!(frames.len(), 48 * frame, "{kind} {name}");
            for (i, got) in frames.chunks(frame).enumerate() {
                let png = png_pixels(&pngs.join(format!("f.{:04}.png", i + 1)));
                let db = psnr(got, &png);
                assert!(db >= 40.0, "{kind} {name} frame {}: {db:.1} dB", i + 1);
            }
        }
    }
}

#[test]
fn the_same_job_writes_the_same_movie_and_resume_writes_it_again_whole() {
    let Some(_) = ffmpeg() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = plates(d, "bg", (64, 48));
    for (name, codec) in [
        ("p.mov", "prores"),
        ("d.mov", "prores4444"),
        ("h.mp4", "h264"),
    ] {
        let (a, b) = (d.join(format!("a{name}")), d.join(format!("b{name}")));
        movie(&input, &a, &["--codec", codec]);
        movie(&input, &b, &["--codec", codec]);
        assert!(
            std::fs::read(&a).unwrap() == std::fs::read(&b).unwrap(),
            "{name}"
        );
    }
    let output = d.join("ap.mov");
    std::fs::write(&output, "not this job's movie").unwrap();
    let out = run(&[
        "transcode",
        s(&input),
        "-o",
        s(&output),
        "--resume",
        "--json",
        "-q",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let summary: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(summary["frames"], 48);
    assert_eq!(
        std::fs::read(&output).unwrap(),
        std::fs::read(d.join("bp.mov")).unwrap()
    );
}

/// Files in `dir` but the plates: what a run left there.
fn left(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !n.ends_with(".exr"))
        .collect();
    names.sort();
    names
}

#[test]
fn a_movie_killed_mid_run_leaves_nothing_at_its_output() {
    let Some(_) = ffmpeg() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = plates(d, "bg", (640, 360));
    let output = d.join("m.mov");
    for signal in ["-INT", "-TERM", "-KILL"] {
        let args = [
            "transcode",
            s(&input),
            "-o",
            s(&output),
            "-q",
            "--strip-rows",
            "1",
        ];
        let mut child = started(&args);
        // Once ffmpeg writes the movie's temporary file (and a frame more).
        let start = Instant::now();
        while !left(d).iter().any(|n| n.starts_with(".m.mov.exrcomp-")) {
            assert!(
                start.elapsed() < Duration::from_secs(60),
                "no temporary file"
            );
            std::thread::sleep(Duration::from_millis(5));
        }
        std::thread::sleep(Duration::from_millis(100));
        crate::common::signal(&child, signal);
        let status = child.wait().unwrap();
        assert!(
            !status.success(),
            "{signal}: the run ended before the signal"
        );
        assert!(!output.exists(), "{signal}: a movie at the output");
        if signal != "-KILL" {
            assert_eq!(left(d), Vec::<String>::new(), "{signal}");
        }
    }
    // The next run removes the killed one's temporary and writes it whole,
    // once the ffmpeg it left has read the end of its input and stopped.
    std::thread::sleep(Duration::from_secs(1));
    movie(&input, &output, &["--frames", "1-2"]);
    assert_eq!(left(d), ["m.mov"]);
}

#[test]
fn without_ffmpeg_on_path_a_movie_is_refused_in_one_line_naming_the_package() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = d.join("bg.####.exr");
    generate(&input, "bg", (16, 8), &["--frames", "1-2"]);
    let empty = d.join("bin");
    std::fs::create_dir(&empty).unwrap();
    for name in ["m.mov", "m.mp4"] {
        let out = exrcomp()
            .args(["transcode", s(&input), "-o", s(&d.join(name))])
            .env("PATH", &empty)
            .output()
            .unwrap();
        let text = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{text}");
        assert_eq!(text.trim().lines().count(), 1, "{text}");
        assert!(text.contains("install the package ffmpeg"), "{text}");
        assert!(!d.join(name).exists());
    }
}

#[test]
fn movie_options_are_refused_where_they_do_not_apply() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = d.join("bg.####.exr");
    generate(&input, "bg", (16, 8), &["--frames", "1-2"]);
    let cases: [(&str, &[&str], &str); 4] = [
        ("m.mp4", &["--codec", "prores"], ".mp4 movies are H.264"),
        (
            "m.####.png",
            &["--codec", "h264"],
            "--codec applies to movies",
        ),
        (
            "m.mov",
            &["--bits", "16"],
            "--bits does not apply to movies",
        ),
        ("m.####.mov", &[], "a movie is one file"),
    ];
    for (name, args, says) in cases {
        let mut all = vec!["transcode", s(&input), "-o"];
        let output = d.join(name);
        all.push(s(&output));
        all.extend(args);
        let out = run(&all);
        assert_eq!(out.status.code(), Some(2), "{name}: {}", stderr(&out));
        assert!(stderr(&out).contains(says), "{name}: {}", stderr(&out));
    }
}

#[test]
fn a_job_file_writes_a_movie() {
    let Some((_, ffprobe)) = ffmpeg() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = plates(d, "bg", (64, 48));
    let (job, output) = (d.join("job.toml"), d.join("review.mov"));
    std::fs::write(
        &job,
        format!(
            "[[node]]\nname = \"in\"\nread = \"{}\"\n\n[[node]]\nname = \"out\"\nwrite = \"{}\"\n\
             inputs = [\"in\"]\ncodec = \"dnxhr\"\nfps = \"24\"\n",
            s(&input),
            s(&output)
        ),
    )
    .unwrap();
    // DNxHR takes frames of 256x120 and more: ffmpeg's refusal, in one line.
    let out = run(&["run", s(&job), "-q"]);
    assert_eq!(out.status.code(), Some(4), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("at least 256x120"),
        "{}",
        stderr(&out)
    );
    assert_eq!(stderr(&out).trim().lines().count(), 1, "{}", stderr(&out));
    assert_eq!(left(d), ["job.toml"]);
    let text = std::fs::read_to_string(&job)
        .unwrap()
        .replace("dnxhr", "prores4444");
    std::fs::write(&job, text).unwrap();
    let out = run(&["run", s(&job), "-q"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let (video, _) = probe(&ffprobe, &output);
    assert_eq!(video["profile"], "4444");
    assert_eq!(video["r_frame_rate"], "24/1");
    assert_eq!(video["nb_read_frames"], "48");
}

#[test]
fn a_farm_writes_a_movie_from_one_task() {
    let Some(_) = ffmpeg() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = d.join("bg.####.exr");
    generate(&input, "bg", (16, 8), &["--frames", "1-48"]);
    let farm = |chunk: &str| {
        exrcomp()
            .current_dir(d)
            .args([
                "farm", "openjd", "--frames", "1-48", "--chunk", chunk, "-o", "job.yaml", "--",
            ])
            .args(["transcode", s(&input), "-o", s(&d.join("m.mov"))])
            .output()
            .unwrap()
    };
    let out = farm("10");
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("give --chunk 48"), "{}", stderr(&out));
    assert!(!d.join("job.yaml").exists());
    let out = farm("48");
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(d.join("job.yaml").exists());
}

/// A movie has no frame numbers: `--missing skip` would shorten it and move
/// every later frame's timecode unseen, so it is refused before any work;
/// `hold` keeps the movie's length.
#[test]
fn missing_skip_is_refused_for_a_movie_and_hold_keeps_its_length() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = d.join("bg.####.exr");
    generate(&input, "bg", (16, 8), &["--frames", "1-4"]);
    std::fs::remove_file(d.join("bg.0003.exr")).unwrap();
    let output = d.join("m.mov");
    let out = run(&[
        "transcode",
        s(&input),
        "-o",
        s(&output),
        "--missing",
        "skip",
    ]);
    let text = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{text}");
    assert_eq!(text.trim().lines().count(), 1, "{text}");
    assert!(text.contains("--missing hold or --missing black"), "{text}");
    assert_eq!(left(d), Vec::<String>::new());
    let Some((_, ffprobe)) = ffmpeg() else {
        return;
    };
    movie(&input, &output, &["--missing", "hold"]);
    let (video, _) = probe(&ffprobe, &output);
    assert_eq!(video["nb_read_frames"], "4");
}

//! `exrcomp run JOB.toml`: the examples in specs/, chains equal to the same
//! steps run one by one, and errors that point at the job file's line.

use crate::common::*;
use exr::prelude::{Compression, LineOrder};
use std::path::Path;
use std::process::Command;

fn examples() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/examples")
}

/// Frames 1-4 of a float RGBA sequence `name` in `dir`.
fn sequence(dir: &Path, name: &str, seed: u64, x: i32, extra: bool) {
    for frame in 1..=4 {
        let img = random_rgba(seed * 10 + frame, x, -1, 33, 21, Kind::Float, extra);
        let path = dir.join(format!("{name}.{frame:04}.exr"));
        write_image(&path, &img, Compression::ZIP16, LineOrder::Increasing);
    }
}

#[test]
fn the_over_example_writes_what_exrcomp_over_writes() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    sequence(d, "fg", 1, 3, false);
    sequence(d, "bg", 2, -2, true);
    std::fs::copy(examples().join("over.toml"), d.join("over.toml")).unwrap();
    ok(&["run", s(&d.join("over.toml")), "-q"]);
    let (fg, bg, direct) = (
        d.join("fg.####.exr"),
        d.join("bg.####.exr"),
        d.join("direct.####.exr"),
    );
    ok(&["over", s(&fg), s(&bg), "-o", s(&direct), "-q"]);
    for frame in 1..=4 {
        let name = |n: &str| d.join(format!("{n}.{frame:04}.exr"));
        assert_eq!(
            std::fs::read(name("comp")).unwrap(),
            std::fs::read(name("direct")).unwrap(),
            "frame {frame}"
        );
    }
}

#[test]
fn the_chain_example_equals_its_steps_run_one_by_one() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // Named as the plates `exrcomp generate` makes, which the example reads.
    sequence(d, "ball", 3, 0, false);
    sequence(d, "bg", 4, 2, false);
    sequence(d, "fg", 5, -3, false);
    sequence(d, "set", 6, 1, true);
    std::fs::copy(examples().join("chain.toml"), d.join("chain.toml")).unwrap();
    ok(&["run", s(&d.join("chain.toml")), "-q", "--strip-rows", "5"]);
    // The same steps through files (float, so nothing is rounded between).
    let p = |n: &str| d.join(format!("{n}.####.exr"));
    ok(&["premult", s(&p("ball")), "-o", s(&p("s1")), "-q"]);
    ok(&[
        "merge",
        "--op",
        "multiply",
        "--mix",
        "0.5",
        s(&p("s1")),
        s(&p("bg")),
        "-o",
        s(&p("s2")),
        "-q",
    ]);
    ok(&[
        "stack",
        s(&p("fg")),
        s(&p("s2")),
        s(&p("set")),
        "-o",
        s(&p("s3")),
        "-q",
        "--compression",
        "zip",
    ]);
    for frame in 1..=4 {
        let name = |n: &str| d.join(format!("{n}.{frame:04}.exr"));
        assert_identical(&read_image(&name("comp")), &read_image(&name("s3")));
    }
    assert_peers_read(&d.join("comp.0001.exr"));
}

/// Writes `text` as a job file in `dir` with two inputs beside it; returns
/// the run's exit code and message.
fn run_job(dir: &Path, text: &str) -> (Option<i32>, String) {
    sequence(dir, "a", 7, 0, false);
    sequence(dir, "b", 8, 0, false);
    let job = dir.join("job.toml");
    std::fs::write(&job, text).unwrap();
    let out = run(&["run", s(&job), "-q"]);
    (out.status.code(), stderr(&out))
}

const READS: &str = "[[node]]\nname = \"a\"\nread = \"a.####.exr\"\n\n[[node]]\nname = \"b\"\nread = \"b.####.exr\"\n";

#[test]
fn errors_name_the_job_file_line() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let write = "\n[[node]]\nname = \"out\"\nwrite = \"o.####.exr\"\ninputs = [\"m\"]\n";
    // (job body after the two reads (lines 1-8), expected line, expected words)
    let cases = [
        // The node starts on line 9; its keys follow.
        ("[[node]]\nname = \"m\"\nop = \"over\"\ninputs = [\"a\", \"nope\"]\n", 12, "unknown node 'nope'"),
        ("[[node]]\nname = \"m\"\nop = \"over\"\ninputs = [\"a\"]\n", 9, "takes two inputs"),
        ("[[node]]\nname = \"m\"\nop = \"blend\"\ninputs = [\"a\", \"b\"]\n", 11, "unknown op 'blend'"),
        ("[[node]]\nname = \"m\"\nop = \"merge\"\noperator = \"bogus\"\ninputs = [\"a\", \"b\"]\n", 12, "unknown operator 'bogus'"),
        ("[[node]]\nname = \"m\"\nop = \"over\"\nmixx = 1\ninputs = [\"a\", \"b\"]\n", 12, "unknown field `mixx`"),
        ("[[node]]\nname = \"m\"\nop = \"over\"\ninputs = [\"a\", \"m2\"]\n\n[[node]]\nname = \"m2\"\nop = \"over\"\ninputs = [\"b\", \"m\"]\n", 9, "cycle"),
        ("[[node]]\nname = \"m\"\nop = \"over\"\ninputs = [\"a\" \"b\"]\n", 12, ""),
        // A key of another operation, a near miss, a missing parameter.
        ("[[node]]\nname = \"m\"\nop = \"over\"\nradius = 3\ninputs = [\"a\", \"b\"]\n", 12, "unknown field `radius` for node 'm'"),
        ("[[node]]\nname = \"m\"\nop = \"blur\"\nradios = 3\ninputs = [\"a\"]\n", 12, "did you mean `radius`?"),
        ("[[node]]\nname = \"m\"\nop = \"blur\"\ninputs = [\"a\"]\n", 9, "op 'blur' needs radius"),
        ("[[node]]\nname = \"m\"\nop = \"key\"\nclip_black = 0.5\nclip_white = 0.25\ninputs = [\"a\"]\n", 9, "clip_white must be above clip_black"),
        ("[[node]]\nname = \"m\"\nop = \"blur\"\nfilter = \"tent\"\nradius = 1\ninputs = [\"a\"]\n", 12, "unknown filter 'tent'"),
        // The command line's bounds hold in job files too, at the key's line.
        ("[[node]]\nname = \"m\"\nop = \"blur\"\nradius = 1000000\ninputs = [\"a\"]\n", 12, "radius must be a number from 0 to 4096"),
        ("[[node]]\nname = \"m\"\nop = \"over\"\nmix = nan\ninputs = [\"a\", \"b\"]\n", 12, "mix must be a number from 0 to 1, not NaN"),
        ("[[node]]\nname = \"m\"\nop = \"vblur\"\nscale = inf\nmax_displacement = 4\ninputs = [\"a\"]\n", 12, "scale must be"),
        ("[[node]]\nname = \"m\"\nop = \"vblur\"\nmax_displacement = 4000000000\ninputs = [\"a\"]\n", 12, "max_displacement must be"),
        ("[[node]]\nname = \"m\"\nop = \"stereo\"\neye = \"left\"\ndisparity = 1e30\ninputs = [\"a\"]\n", 13, "disparity must be"),
        ("[[node]]\nname = \"m\"\nop = \"defocus\"\nfocus = 1\nscale = 1e30\nmax_radius = 4\ninputs = [\"a\"]\n", 13, "scale must be"),
        ("[[node]]\nname = \"m\"\nop = \"key\"\ngain = -1\ninputs = [\"a\"]\n", 12, "gain must be"),
        ("[[node]]\nname = \"m\"\nop = \"dilate\"\nradius = 2000\ninputs = [\"a\"]\n", 12, "radius must be a number from 0 to 1024"),
        // A read's own mistakes at its own lines (inputs had been blamed on the write).
        ("[[node]]\nname = \"m\"\nread = \"a.####.exr\"\ninputs = [\"a\"]\n", 12, "node 'm' reads a file: a read node takes no inputs"),
    ];
    for (body, line, words) in cases {
        let (code, message) = run_job(d, &format!("{READS}\n{body}{write}"));
        assert_eq!(code, Some(2), "{body}: {message}");
        let at = format!("job.toml:{line}:");
        assert!(
            message.contains(&at) && message.contains(words),
            "{body}\nwanted {at} {words}: {message}"
        );
    }
    // A part neither a name nor an index, at its line.
    let read = "[[node]]\nname = \"m\"\nread = \"a.####.exr\"\npart = -1\n";
    let (code, message) = run_job(d, &format!("{read}{write}"));
    assert_eq!(code, Some(2), "{message}");
    assert!(
        message.contains("job.toml:4:") && message.contains("part is a part's name or index"),
        "{message}"
    );
    // Found when the frame is planned: a layer the inputs lack, at the node's line.
    let body =
        "[[node]]\nname = \"m\"\nop = \"over\"\nlayers = [\"diffuse\"]\ninputs = [\"a\", \"b\"]\n";
    let (code, message) = run_job(d, &format!("{READS}\n{body}{write}"));
    assert_eq!(code, Some(3), "{message}");
    assert!(
        message.contains("job.toml:9 (node 'm')") && message.contains("layer 'diffuse' not found"),
        "{message}"
    );
    // A node the write does not use; no write at all.
    let body = "[[node]]\nname = \"m\"\nop = \"over\"\ninputs = [\"a\", \"b\"]\n\n[[node]]\nname = \"out\"\nwrite = \"o.####.exr\"\ninputs = [\"a\"]\n";
    let (code, message) = run_job(d, &format!("{READS}\n{body}"));
    assert_eq!(code, Some(2), "{message}");
    assert!(
        message.contains("job.toml:5:") && message.contains("not used"),
        "{message}"
    );
    let (code, message) = run_job(d, READS);
    assert_eq!(code, Some(2), "{message}");
    assert!(message.contains("no write node"), "{message}");
}

#[test]
fn a_near_miss_gets_one_suggestion_not_the_list() {
    let dir = tempfile::tempdir().unwrap();
    let job = "[[node]]\nname = \"m\"\nop = \"blur\"\nradios = 3\ninputs = [\"a\"]\n";
    let (_, message) = run_job(
        dir.path(),
        &format!(
            "{READS}\n{job}\n[[node]]\nname = \"o\"\nwrite = \"o.####.exr\"\ninputs = [\"m\"]\n"
        ),
    );
    assert!(
        message.contains("unknown field `radios` for node 'm': did you mean `radius`?"),
        "{message}"
    );
    assert!(!message.contains("it takes"), "{message}");
    let (_, message) = run_job(dir.path(), &format!("{READS}\n[[node]]\nname = \"m\"\nop = \"blur\"\nsmoothness = 3\nradius = 1\ninputs = [\"a\"]\n"));
    assert!(message.contains("(it takes: "), "{message}");
}

#[test]
fn neighbourhood_ops_chain_with_merges_in_one_pass() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let p = |n: &str| d.join(format!("{n}.####.exr"));
    for (name, kind) in [("fg", "fg"), ("bg", "bg")] {
        generate(&p(name), kind, (64, 48), &["--frames", "1-2"]);
    }
    let job = "[[node]]\nname = \"fg\"\nread = \"fg.####.exr\"\n\n\
        [[node]]\nname = \"bg\"\nread = \"bg.####.exr\"\n\n\
        [[node]]\nname = \"dof\"\nop = \"defocus\"\nfocus = 5.0\nscale = 4.0\nmax_radius = 3\naperture = \"hexagon\"\ninputs = [\"fg\"]\n\n\
        [[node]]\nname = \"moving\"\nop = \"vblur\"\nscale = 0.5\nmax_displacement = 20\ninputs = [\"dof\"]\n\n\
        [[node]]\nname = \"comp\"\nop = \"over\"\ninputs = [\"moving\", \"bg\"]\n\n\
        [[node]]\nname = \"soft\"\nop = \"blur\"\nradius = 2\ninputs = [\"comp\"]\n\n\
        [[node]]\nname = \"eye\"\nop = \"stereo\"\neye = \"right\"\ndisparity = 30.0\ninputs = [\"soft\"]\n\n\
        [[node]]\nname = \"out\"\nwrite = \"unused.####.exr\"\ninputs = [\"eye\"]\n";
    std::fs::write(d.join("job.toml"), job).unwrap();
    ok(&[
        "run",
        s(&d.join("job.toml")),
        "-o",
        s(&p("comp")),
        "-q",
        "--strip-rows",
        "16",
    ]);
    assert!(
        !d.join("unused.0001.exr").exists(),
        "-o replaces the write node's file"
    );
    ok(&[
        "defocus",
        s(&p("fg")),
        "-o",
        s(&p("s1")),
        "--focus",
        "5",
        "--scale",
        "4",
        "--max-radius",
        "3",
        "--aperture",
        "hexagon",
        "-q",
    ]);
    ok(&[
        "vblur",
        s(&p("s1")),
        "-o",
        s(&p("s2")),
        "--scale",
        "0.5",
        "--max-displacement",
        "20",
        "-q",
    ]);
    ok(&["over", s(&p("s2")), s(&p("bg")), "-o", s(&p("s3")), "-q"]);
    ok(&[
        "blur",
        s(&p("s3")),
        "-o",
        s(&p("s4")),
        "--radius",
        "2",
        "-q",
    ]);
    ok(&[
        "stereo",
        s(&p("s4")),
        "-o",
        s(&p("s5")),
        "--eye",
        "right",
        "--disparity",
        "30",
        "-q",
    ]);
    for frame in 1..=2 {
        let name = |n: &str| d.join(format!("{n}.{frame:04}.exr"));
        assert_identical(&read_image(&name("comp")), &read_image(&name("s5")));
    }
}

/// A chain of a hundred thousand nodes: no recursion over the graph (the
/// call stack would overflow), and memory that does not grow with one strip
/// per node (each node's rows are freed once its consumers have read them).
#[test]
fn a_hundred_thousand_node_chain_runs_in_bounded_memory() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    generate(&d.join("in.exr"), "fg", (64, 48), &[]);
    let mut job = String::from("[[node]]\nname = \"n0\"\nread = \"in.exr\"\n");
    let nodes = 100_000;
    for i in 1..=nodes {
        job += &format!(
            "[[node]]\nname = \"n{i}\"\nop = \"premult\"\ninputs = [\"n{}\"]\n",
            i - 1
        );
    }
    job += &format!("[[node]]\nname = \"w\"\nwrite = \"out.exr\"\ninputs = [\"n{nodes}\"]\n");
    std::fs::write(d.join("chain.toml"), job).unwrap();
    // One 48-row strip of 64 px RGBA f32 per node would be 4.9 GB.
    let out = Command::new("sh")
        .arg("-c")
        .arg("ulimit -v 2097152; exec \"$0\" \"$@\"")
        .arg(env!("CARGO_BIN_EXE_exrcomp"))
        .args(["run", s(&d.join("chain.toml")), "-q"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{:?}: {}", out.status, stderr(&out));
    assert!(d.join("out.exr").exists());
}

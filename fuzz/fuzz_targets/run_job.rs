//! Runs whole jobs on arbitrary bytes taken as an EXR file, in-process, as
//! the command line would (`Cli` parsed from arguments, `commands::run`):
//!
//! - `over INPUT plate`: the input's chunks copied into strips wider than it
//!   (a 64x64 generated plate's window joins its own), merged, encoded;
//! - `over plate INPUT`: the input as the background, whose header is kept
//!   and whose blocks under a transparent foreground are passed through;
//! - `blur --radius 2 INPUT`: a ZIP or ZIPS input's strips decoded straight
//!   into planes (`decode_direct`), a filter with a halo;
//! - `flatten INPUT`: a deep input's samples flattened.
//!
//! Each writes to a scratch folder. Errors are expected; a panic (in any
//! pipeline thread), an abort, a timeout or an OOM is a bug, and so is an
//! internal error or a written output that exrcomp cannot read back.
#![no_main]

use clap::Parser;
use exrcomp::cli::Cli;
use exrcomp::error::Kind;
use exrcomp::io::reader::ExrFile;
use libfuzzer_sys::fuzz_target;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// One scratch folder per fuzzing process, with the plate generated once.
fn scratch() -> &'static PathBuf {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let shm = Path::new("/dev/shm");
        let base = if shm.is_dir() {
            shm.to_path_buf()
        } else {
            std::env::temp_dir()
        };
        let dir = base.join(format!("exrcomp-fuzz-job-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("scratch folder");
        let plate = dir.join("plate.exr");
        run(&[
            "generate",
            s(&plate),
            "--kind",
            "bg",
            "--width",
            "64",
            "--height",
            "64",
            "-q",
        ])
        .expect("the plate is generated");
        dir
    })
}

fn s(path: &Path) -> &str {
    path.to_str().expect("scratch paths are UTF-8")
}

fn run(args: &[&str]) -> exrcomp::error::Result<()> {
    let cli = Cli::try_parse_from(std::iter::once("exrcomp").chain(args.iter().copied()))
        .expect("the fuzz target's command lines parse");
    exrcomp::cli::commands::execute(cli.command).map(drop)
}

fuzz_target!(|data: &[u8]| {
    let dir = scratch();
    let (input, plate, out) = (
        dir.join("input.exr"),
        dir.join("plate.exr"),
        dir.join("out.exr"),
    );
    std::fs::write(&input, data).expect("write scratch file");
    // Most mutations break the header: skip the jobs, which would all stop
    // at the same place.
    if ExrFile::open(&input, None).is_err() {
        return;
    }
    let jobs: [&[&str]; 4] = [
        &["over", s(&input), s(&plate)],
        &["over", s(&plate), s(&input)],
        &["blur", "--radius", "2", s(&input)],
        &["flatten", s(&input)],
    ];
    for job in jobs {
        let _ = std::fs::remove_file(&out);
        let mut args = job.to_vec();
        args.extend(["-o", s(&out), "-q"]);
        match run(&args) {
            Ok(()) => {
                // What was written must read back whole.
                let written = ExrFile::open(&out, None).and_then(|f| f.check_part(0));
                if let Err(e) = written {
                    panic!("{args:?} wrote an output exrcomp cannot read: {e}");
                }
            }
            Err(e) => assert!(e.kind != Kind::Internal, "{args:?}: internal error: {e}"),
        }
    }
});

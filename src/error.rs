//! One error type for the whole program; its kind decides the exit code.

use std::fmt;
use std::path::Path;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Bad command line or job description.
    Usage,
    /// An input file is missing, damaged or unsupported.
    Input,
    /// An output could not be written.
    Output,
    /// A bug: an invariant of exrcomp itself broke, or it panicked.
    Internal,
    /// A pipeline stage stopped because another one failed; that one reports.
    Stopped,
    /// Ctrl-C or SIGTERM.
    Interrupted,
    /// `bench --baseline`: a job slower than the baseline beyond its noise.
    Regression,
}

impl Kind {
    /// Exit codes, as documented in the README.
    pub fn exit_code(self) -> i32 {
        match self {
            Kind::Internal | Kind::Stopped | Kind::Regression => 1,
            Kind::Usage => 2,
            Kind::Input => 3,
            Kind::Output => 4,
            // 128 + SIGINT, as shells report an interrupted command (143,
            // 128 + SIGTERM, after SIGTERM: `engine::interrupt::exit_code`).
            Kind::Interrupted => 130,
        }
    }
}

#[derive(Debug, Clone)]
pub struct Error {
    pub kind: Kind,
    pub message: String,
    /// The file and frame the message names (`Error::input`, `output`),
    /// for front ends that give them apart (the Python package's
    /// exceptions); `None` when the message names none.
    pub file: Option<std::path::PathBuf>,
    pub frame: Option<i64>,
}

pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    pub fn new(kind: Kind, message: impl Into<String>) -> Self {
        Error {
            kind,
            message: message.into(),
            file: None,
            frame: None,
        }
    }

    pub fn usage(message: impl Into<String>) -> Self {
        Self::new(Kind::Usage, message)
    }

    pub fn internal(message: impl Into<String>) -> Self {
        Self::new(Kind::Internal, message)
    }

    pub fn stopped() -> Self {
        Self::new(Kind::Stopped, "stopped because another stage failed")
    }

    /// An input problem, naming the file and, for sequences, the frame.
    pub fn input(path: &Path, frame: Option<i64>, message: impl fmt::Display) -> Self {
        Self::new(Kind::Input, located(path, frame, message)).at(path, frame)
    }

    /// An output problem, naming the file and, for sequences, the frame.
    pub fn output(path: &Path, frame: Option<i64>, message: impl fmt::Display) -> Self {
        Self::new(Kind::Output, located(path, frame, message)).at(path, frame)
    }

    fn at(self, path: &Path, frame: Option<i64>) -> Self {
        Error {
            file: Some(path.to_path_buf()),
            frame,
            ..self
        }
    }

    /// A panic (`guard::Panic`: its message and place), said as a bug to
    /// report; naming the output file and frame when a frame's work met it.
    pub fn panicked(output: Option<(&Path, Option<i64>)>, panic: impl fmt::Display) -> Self {
        let message = format!("internal error: {panic} (a bug: please report it with this line)");
        Self::internal(match output {
            Some((path, frame)) => located(path, frame, message),
            None => message,
        })
    }
}

fn located(path: &Path, frame: Option<i64>, message: impl fmt::Display) -> String {
    match frame {
        Some(frame) => format!("{} (frame {frame}): {message}", path.display()),
        None => format!("{}: {message}", path.display()),
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Error {}

//! An exrcomp command line given as text (a farm task's, a bench job's):
//! parsed as exrcomp parses it, with its file arguments found.

use crate::cli::Cli;
use crate::error::{Error, Result};
use clap::{CommandFactory, ValueHint};

/// What a file argument of the command is to the farm (OpenJD's dataFlow).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Flow {
    /// Read: an input, a job file.
    In,
    /// Written: `-o`.
    Out,
}

/// The command every task runs, but for `--frames`.
pub struct TaskCommand {
    pub args: Vec<String>,
    /// The arguments that are file names (absolute), by index in `args`.
    pub files: Vec<(usize, Flow)>,
}

/// `command` parsed as exrcomp parses it: its arguments (joined values
/// split, `--output=F` as `--output F`), the file arguments among them, the
/// subcommand's name and its matches.
pub fn parse_command(command: &[String]) -> Result<(TaskCommand, String, clap::ArgMatches)> {
    let args = split_joined_values(command);
    let matches = crate::cli::command()
        .try_get_matches_from(argv(&args))
        .and_then(|m| crate::cli::refuse_not_applicable(&m).map(|()| m))
        .map_err(|e| {
            // clap's first paragraph, on one line: its first line alone
            // may end in a colon whose list (the arguments missing) follows.
            let message = e.to_string();
            let lines = message.lines().map(str::trim);
            let first: Vec<&str> = lines.take_while(|l| !l.is_empty()).collect();
            Error::usage(format!(
                "the command to run does not parse: {}",
                first.join(" ").trim_start_matches("error: ")
            ))
        })?;
    let (name, sub) = matches.subcommand().expect("a subcommand is required");
    // A subcommand's indices count from its own name, which is args[0].
    let definition = Cli::command();
    let definition = definition
        .find_subcommand(name)
        .expect("the parsed subcommand exists");
    let mut files = Vec::new();
    for arg in definition.get_arguments() {
        if arg.get_value_hint() != ValueHint::FilePath {
            continue;
        }
        let flow = match arg.get_id().as_str() {
            "output" => Flow::Out,
            _ => Flow::In,
        };
        for at in sub.indices_of(arg.get_id().as_str()).into_iter().flatten() {
            // A value clap places outside the arguments is left alone, and
            // a config's name (`ocio://NAME`) is no file.
            if at < args.len() && !args[at].starts_with("ocio://") {
                files.push((at, flow));
            }
        }
    }
    files.sort_by_key(|&(at, _)| at);
    Ok((TaskCommand { args, files }, name.to_string(), sub.clone()))
}

pub fn argv(args: &[String]) -> impl Iterator<Item = String> + '_ {
    std::iter::once("exrcomp".to_string()).chain(args.iter().cloned())
}

/// `--name=value` as `--name value` and `-oVALUE` as `-o VALUE`, so that
/// every value is an argument of its own (clap's indices count them so).
fn split_joined_values(command: &[String]) -> Vec<String> {
    let mut args = Vec::new();
    let mut options = true;
    for arg in command {
        match arg.as_str() {
            "--" => {
                options = false;
                args.push(arg.clone());
            }
            a if options && a.starts_with("--") && a.contains('=') => {
                let (name, value) = a.split_once('=').expect("has =");
                args.extend([name.to_string(), value.to_string()]);
            }
            a if options && a.starts_with("-o") && a.len() > 2 => {
                args.extend(["-o".to_string(), a[2..].to_string()]);
            }
            _ => args.push(arg.clone()),
        }
    }
    args
}

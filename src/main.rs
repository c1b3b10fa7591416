//! The `exrcomp` command: the program of src/cli/program.rs.

fn main() {
    match exrcomp::cli::program::main(std::env::args_os()) {
        0 => {}
        code => std::process::exit(code),
    }
}

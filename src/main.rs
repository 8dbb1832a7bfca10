//! The `stressfield` command: parse arguments, run, print errors once, exit non-zero on failure.

mod cli;

use std::process::ExitCode;

use clap::Parser;

fn main() -> ExitCode {
    let args = cli::args::Args::parse();
    // An interruption (Ctrl-C, kill) removes the temporary files of unfinished outputs.
    if let Err(e) = stressfield::io::output::remove_pending_on_interrupt() {
        eprintln!("warning: cannot watch for interruptions ({e}): an interrupted run may leave .stressfield-*.part files");
    }
    match cli::run(args.command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            cli::console::print_err(&format!("error: {error:#}"));
            ExitCode::FAILURE
        }
    }
}

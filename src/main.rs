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
    let result = cli::run(args.command);
    // A debug counter: each command should solve a rough scene's contact once.
    if std::env::var_os("STRESSFIELD_COUNT_SOLVES").is_some() {
        cli::console::print_err(&format!(
            "rough contact solves: {}",
            stressfield::study::rough::scene_solves()
        ));
    }
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            cli::console::print_err(&format!("error: {}", cli::console::error_text(&error)));
            ExitCode::FAILURE
        }
    }
}

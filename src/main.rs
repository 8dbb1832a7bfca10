//! The `stressfield` command: parse arguments, run, print errors once, exit non-zero on failure.

mod cli;
mod commands;
mod compare_run;
mod surface_commands;

use std::process::ExitCode;

use clap::Parser;

fn main() -> ExitCode {
    let args = cli::Args::parse();
    match commands::run(args.command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            commands::print_err(&format!("error: {error:#}"));
            ExitCode::FAILURE
        }
    }
}

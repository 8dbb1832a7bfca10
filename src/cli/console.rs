//! Console helpers shared by the subcommands: quiet printing to standard output and error,
//! progress bars and spinners (hidden off a terminal and in CI).

use std::io::{IsTerminal, Write};

use anyhow::{Context, Result};
use indicatif::{ProgressBar, ProgressStyle};

/// Writes `text` to standard output (see [`with_stdout`]).
pub(crate) fn print_out(text: &str) -> Result<()> {
    with_stdout(|out| out.write_all(text.as_bytes()))
}

/// The one path of every command's output: `write` into standard output (buffered), then
/// flush. A closed pipe (`| head`) ends quietly, as the reader asked for no more; any other
/// failure (a full disk, `> /dev/full`) is an error naming standard output.
pub(crate) fn with_stdout(write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>) -> Result<()> {
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    match write(&mut out).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(e).context("cannot write to standard output"),
    }
}

/// Writes a line to standard error. Messages and errors are the last thing a run can say:
/// when standard error itself cannot be written (closed, full), there is nobody left to tell,
/// and the exit code still reports the failure.
pub(crate) fn print_err(line: &str) {
    let mut err = std::io::stderr().lock();
    let _ = writeln!(err, "{line}");
}

pub(crate) fn progress_bar(total: u64) -> ProgressBar {
    let quiet = !std::io::stderr().is_terminal() || std::env::var_os("CI").is_some();
    if quiet {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(total);
    if let Ok(style) =
        ProgressStyle::with_template("{spinner} {msg:24} [{bar:40}] {percent:>3}% {elapsed}")
    {
        bar.set_style(style.progress_chars("=> "));
    }
    bar
}

/// Prints a line above the progress bar, or on stderr when the bar is hidden (not a terminal).
pub(crate) fn say(bar: &ProgressBar, line: impl AsRef<str>) {
    if bar.is_hidden() {
        print_err(line.as_ref());
    } else {
        bar.println(line);
    }
}

/// A solver progress bar: iterations as they come (the total is not known).
pub(crate) fn solver_bar() -> ProgressBar {
    let bar = progress_bar(0);
    if !bar.is_hidden() {
        if let Ok(style) =
            ProgressStyle::with_template("{spinner} solving: iteration {pos}, {msg} {elapsed}")
        {
            bar.set_style(style);
        }
    }
    bar
}

/// A spinner with a message and the elapsed time, for work of unknown length (hidden where
/// progress bars are).
pub(crate) fn spinner(message: &str) -> ProgressBar {
    let bar = progress_bar(0);
    if !bar.is_hidden() {
        if let Ok(style) = ProgressStyle::with_template("{spinner} {msg} {elapsed}") {
            bar.set_style(style);
        }
        bar.set_message(message.to_string());
        bar.enable_steady_tick(std::time::Duration::from_millis(200));
    }
    bar
}

/// An error and its causes for the user, each said once ([`stressfield::io::text::error_text`]).
pub(crate) fn error_text(error: &anyhow::Error) -> String {
    stressfield::io::text::error_text(error)
}

#[cfg(test)]
mod tests {
    use anyhow::Context;

    /// Issue 24, class 16: the cause is said once.
    #[test]
    fn causes_are_said_once() {
        let io = std::io::Error::from(std::io::ErrorKind::NotFound);
        let read = stressfield::surface::read::ReadError::Io {
            path: "s.asc".into(),
            source: io,
        };
        let error = Err::<(), _>(read).context("surface").expect_err("error");
        let text = super::error_text(&error);
        assert_eq!(text.matches("not found").count(), 1, "{text}");
        assert!(text.starts_with("surface: cannot read s.asc: "), "{text}");
        // Causes not in the message before them are kept.
        let plain = Err::<(), _>(std::io::Error::other("disk full"))
            .context("writing out/a.png")
            .expect_err("error");
        assert_eq!(super::error_text(&plain), "writing out/a.png: disk full");
    }
}

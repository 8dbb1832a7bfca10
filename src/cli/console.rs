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

/// The progress of a command's study ([`stressfield::study::commands`]) on the terminal: the
/// rough contact's solver bar, the spinner of its subsurface maxima, then the heating's bar
/// (over its depths, or a gear's path of contact then the depths at its hottest point), each
/// replacing the one before. Records when the solve and the maxima ended, for
/// `STRESSFIELD_TIMINGS`.
pub(crate) struct StudyBars {
    bar: ProgressBar,
    phase: Phase,
    started: std::time::Instant,
    solved: Option<std::time::Duration>,
    maxima_done: Option<std::time::Duration>,
}

#[derive(Clone, Copy, PartialEq)]
enum Phase {
    Solving,
    Maxima,
    Heating { gears: bool },
    Idle,
}

impl StudyBars {
    /// The bars of `scene`'s study, the first shown at once (the solver's for a rough scene,
    /// the heating's for a heated Hertz scene).
    pub(crate) fn new(scene: &stressfield::scene::Scene) -> Self {
        let gears = scene.thermal.and_then(|t| t.gear).is_some();
        let phase = if scene.contact.kind == stressfield::scene::ContactKind::Rough {
            Phase::Solving
        } else if scene.thermal.is_some() && scene.contact.coating.is_none() {
            Phase::Heating { gears }
        } else {
            Phase::Idle
        };
        Self {
            bar: Self::bar_of(phase),
            phase,
            started: std::time::Instant::now(),
            solved: None,
            maxima_done: None,
        }
    }

    fn bar_of(phase: Phase) -> ProgressBar {
        use stressfield::study::{gear_heating::PATH_POINTS, thermal::DEPTHS_OVER_A};
        match phase {
            Phase::Solving => solver_bar(),
            Phase::Maxima | Phase::Idle => ProgressBar::hidden(),
            Phase::Heating { gears: false } => {
                let bar = progress_bar(DEPTHS_OVER_A.len() as u64);
                bar.set_message("thermal stress by depth");
                bar
            }
            Phase::Heating { gears: true } => {
                let bar = progress_bar((PATH_POINTS + DEPTHS_OVER_A.len()) as u64);
                bar.set_message("flash temperature along the path of contact");
                bar
            }
        }
    }

    /// Moves to `phase` (a new bar) unless already there.
    fn enter(&mut self, phase: Phase) {
        if self.phase != phase {
            self.bar.finish_and_clear();
            self.phase = phase;
            self.bar = Self::bar_of(phase);
        }
    }

    /// Shows `progress`; the command line always goes on (Ctrl-C ends the process).
    pub(crate) fn show(
        &mut self,
        progress: stressfield::study::commands::Progress,
    ) -> std::ops::ControlFlow<()> {
        use stressfield::study::commands::Progress;
        use stressfield::study::thermal::Progress as Heat;
        match progress {
            Progress::Solving {
                iteration,
                residual,
            } => {
                self.enter(Phase::Solving);
                self.bar.set_position(iteration as u64);
                self.bar.set_message(format!("residual {residual:.1e}"));
            }
            Progress::Maxima { depth_m } => {
                self.solved = Some(self.started.elapsed());
                self.bar.finish_and_clear();
                self.phase = Phase::Maxima;
                self.bar = spinner(&format!(
                    "subsurface maxima: DC-FFT layers down to {:.1} µm",
                    depth_m * 1e6
                ));
            }
            Progress::Heating(heat) => {
                if self.phase == Phase::Maxima {
                    self.maxima_done = Some(self.started.elapsed());
                }
                let gears = match self.phase {
                    Phase::Heating { gears } => gears,
                    _ => matches!(heat, Heat::Path { .. }),
                };
                self.enter(Phase::Heating { gears });
                let path = stressfield::study::gear_heating::PATH_POINTS;
                match (heat, gears) {
                    (Heat::Path { done, .. }, _) => self.bar.set_position(done as u64),
                    (Heat::Depth { done, .. }, true) => {
                        self.bar
                            .set_message("thermal stress by depth at the hottest point");
                        self.bar.set_position((path + done) as u64);
                    }
                    (Heat::Depth { done, total }, false) => {
                        self.bar.set_message("thermal stress by depth");
                        self.bar.set_length(total as u64);
                        self.bar.set_position(done as u64);
                    }
                    (Heat::Coupled { iteration, change }, _) => self.bar.set_message(format!(
                        "coupled iteration {iteration}: pressure change {change:.1e}"
                    )),
                }
            }
        }
        std::ops::ControlFlow::Continue(())
    }

    /// Clears the bar; with `STRESSFIELD_TIMINGS` set and a rough contact solved in
    /// `iterations`, prints the wall-clock times of the solve and of the subsurface maxima
    /// (for the README's scaling table; never in a report, which stays the same from run to
    /// run).
    pub(crate) fn finish(self, iterations: Option<usize>) {
        self.bar.finish_and_clear();
        let maxima_done = self.maxima_done.unwrap_or_else(|| self.started.elapsed());
        if let (Some(solved), Some(iterations)) = (self.solved, iterations) {
            if std::env::var_os("STRESSFIELD_TIMINGS").is_some() {
                eprintln!(
                    "timings: solve {:.3} s ({iterations} iterations), subsurface maxima {:.3} s",
                    solved.as_secs_f64(),
                    (maxima_done - solved).as_secs_f64()
                );
            }
        }
    }
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

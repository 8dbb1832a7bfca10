//! `render --compare DIR`: every drawn figure against its reference (the image, and the field
//! where DIR holds one), `--update`, one CI line per scene, the summary, the HTML report.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};

use super::args::{CompareArgs, MeasureArg};
use stressfield::io::input::{self, InputError};
use stressfield::io::output::{write_atomic, Staged};
use stressfield::regression::compare::{self, Tolerance};
use stressfield::regression::field_file::{self, PanelField};
use stressfield::regression::{self, FieldCheck, ImageCheck, ImageMeasure, SceneOutcome, Status};
use stressfield::render;

/// Per-channel tolerance of `--measure pixels` when none is given.
const DEFAULT_CHANNEL_TOLERANCE: u8 = 16;
/// RMS limit of `--measure rms` when none is given: pytest-mpl's default.
const DEFAULT_RMS_TOLERANCE: f64 = 2.0;
/// Field tolerance when none is given, in the figure's stress unit: far above the rounding
/// differences between machines (about 1e-13 of the values), far below any change of physics.
const DEFAULT_FIELD_TOLERANCE: f64 = 1e-6;

/// A validated `--compare` configuration.
#[derive(Debug)]
pub struct CompareOptions {
    pub reference_dir: PathBuf,
    pub measure: ImageMeasure,
    /// Absolute, in each figure's stress unit.
    pub field_tolerance: f64,
    /// The report goes to `<dir>/index.html`.
    pub report_dir: Option<PathBuf>,
    pub update: bool,
    /// `--save-field`: `--update` writes field references even where there were none.
    pub save_field: bool,
}

impl CompareOptions {
    /// The comparison asked for, if any (clap already refused comparison flags without
    /// `--compare`). The reference directory must exist, unless `--update` will fill it, and
    /// must not be the output directory `out_dir`.
    pub fn from_args(args: &CompareArgs, save_field: bool, out_dir: &Path) -> Result<Option<Self>> {
        let Some(reference_dir) = args.compare.clone() else {
            return Ok(None);
        };
        let measure = match args.measure {
            MeasureArg::Pixels => {
                if args.rms_tolerance.is_some() {
                    bail!("--rms-tolerance applies to --measure rms\nhint: add --measure rms, or give --tolerance and --max-differing-pixels for the default per-pixel measure");
                }
                ImageMeasure::Pixels(Tolerance {
                    per_channel: args.tolerance.unwrap_or(DEFAULT_CHANNEL_TOLERANCE),
                    max_differing_pixels: args.max_differing_pixels.unwrap_or(0),
                })
            }
            MeasureArg::Rms => {
                if args.tolerance.is_some() || args.max_differing_pixels.is_some() {
                    bail!("--tolerance and --max-differing-pixels apply to --measure pixels\nhint: with --measure rms, give the limit with --rms-tolerance (default {DEFAULT_RMS_TOLERANCE})");
                }
                let max = args.rms_tolerance.unwrap_or(DEFAULT_RMS_TOLERANCE);
                if !(max.is_finite() && max >= 0.0) {
                    bail!(
                        "--rms-tolerance must be a finite number >= 0 (levels of 255), got {}",
                        stressfield::io::text::number(max)
                    );
                }
                ImageMeasure::Rms { max }
            }
        };
        let field_tolerance = args.field_tolerance.unwrap_or(DEFAULT_FIELD_TOLERANCE);
        if !(field_tolerance.is_finite() && field_tolerance >= 0.0) {
            bail!(
                "--field-tolerance must be a finite number >= 0 (in the figure's stress unit), got {}",
                stressfield::io::text::number(field_tolerance)
            );
        }
        // A file given for the directory (issue 42, a leftover of round two: it was said
        // not to exist).
        if reference_dir.exists() && !reference_dir.is_dir() {
            bail!(
                "--compare {}: is not a directory (it is a file)\nhint: give the directory of the reference images (made with --update), e.g. --compare refs/",
                reference_dir.display()
            );
        }
        if args.update {
            std::fs::create_dir_all(&reference_dir).with_context(|| {
                format!(
                    "cannot create the reference directory {}",
                    reference_dir.display()
                )
            })?;
        } else if !reference_dir.is_dir() {
            bail!(
                "the reference directory {} does not exist\nhint: check the path, or create the references with --update",
                reference_dir.display()
            );
        }
        if same_directory(out_dir, &reference_dir) {
            bail!(
                "--out-dir and --compare name the same directory {}: the references would be overwritten before they are compared\nhint: render into another directory (--out-dir out); --update rewrites the references that differ",
                reference_dir.display()
            );
        }
        Ok(Some(Self {
            reference_dir,
            measure,
            field_tolerance,
            report_dir: args.report.clone(),
            update: args.update,
            save_field,
        }))
    }
}

/// Whether both paths exist and name the same directory.
fn same_directory(a: &Path, b: &Path) -> bool {
    match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    }
}

/// What `render` drew of one scene, for the comparison.
pub struct Rendered<'a> {
    pub name: &'a str,
    pub image: &'a image::RgbImage,
    /// The PNG bytes written to the output directory.
    pub png: &'a [u8],
    /// The panels' values (figures; a sheet has none).
    pub field: Option<&'a [PanelField]>,
    /// The figure's stress unit, e.g. "p0" or "MPa".
    pub stress_unit: &'a str,
    /// Each panel's coordinate labels, e.g. "x/a" and "z/a", or "x (mm)" and "z (mm)" (panels
    /// cut in different planes have different ones).
    pub axes: Vec<[String; 2]>,
}

/// A reference file: its bytes, or `None` when it does not exist; at most
/// [`input::REFERENCE_FILE_LIMIT`] bytes (a wrong file such as `/dev/zero` fails at once).
fn read_reference(path: &Path) -> Result<Option<Vec<u8>>> {
    match input::read_bytes(path, input::REFERENCE_FILE_LIMIT) {
        Ok(bytes) => Ok(Some(bytes)),
        Err(InputError::Io(e)) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
        Err(e) => Err(e).with_context(|| format!("cannot read {}", path.display())),
    }
}

/// Compares one scene with its references, writes or removes `<out_dir>/<scene>.diff.png`,
/// and (with `--update`) rewrites the references of a scene that differs.
pub fn check_scene(rendered: &Rendered, options: &CompareOptions, out_dir: &Path) -> SceneOutcome {
    let dir = &options.reference_dir;
    let png_path = dir.join(format!("{}.png", rendered.name));
    let field_path = dir.join(format!("{}.npz", rendered.name));
    let mut outcome = SceneOutcome {
        name: rendered.name.to_string(),
        status: Status::Passed,
        image: None,
        field: None,
        problem: None,
        written: Vec::new(),
        reference_png: None,
        actual_png: rendered.png.to_vec(),
        diff_png: None,
    };
    let mut problems = Vec::new();
    match read_reference(&png_path) {
        Ok(Some(bytes)) => match image::load_from_memory(&bytes) {
            Ok(expected) => {
                let expected = expected.to_rgb8();
                let tolerance = match options.measure {
                    ImageMeasure::Pixels(tolerance) => tolerance,
                    ImageMeasure::Rms { .. } => Tolerance {
                        per_channel: options.measure.diff_threshold(),
                        max_differing_pixels: 0,
                    },
                };
                let comparison = compare::compare(rendered.image, &expected, tolerance);
                if comparison.sizes_match() {
                    let diff = compare::diff_image(
                        rendered.image,
                        &expected,
                        options.measure.diff_threshold(),
                    );
                    outcome.diff_png = render::encode_png(&diff).ok();
                }
                outcome.image = Some(ImageCheck {
                    comparison,
                    measure: options.measure,
                });
                outcome.reference_png = Some(bytes);
            }
            Err(e) => problems.push(format!("cannot decode {}: {e}", png_path.display())),
        },
        Ok(None) => problems.push(format!(
            "no reference image {} (--update creates it)",
            png_path.display()
        )),
        Err(e) => problems.push(format!("{e:#}")),
    }
    let had_field = match read_reference(&field_path) {
        Ok(Some(bytes)) => {
            outcome.field = Some(field_check(rendered, &bytes, &field_path, options));
            true
        }
        Ok(None) => false,
        Err(e) => {
            problems.push(format!("{e:#}"));
            true
        }
    };
    if !problems.is_empty() {
        outcome.problem = Some(problems.join("; "));
    }
    // The diff image beside the output: for a failed image check; a stale one is removed.
    let diff_path = out_dir.join(format!("{}.diff.png", rendered.name));
    let image_failed = outcome.image.as_ref().is_some_and(|i| !i.passed());
    let diff_written = match (&outcome.diff_png, image_failed) {
        (Some(diff), true) => write_atomic(&diff_path, diff).map(|()| true),
        _ => {
            let _ = std::fs::remove_file(&diff_path);
            Ok(false)
        }
    };
    match diff_written {
        Ok(true) => outcome
            .written
            .push(format!("diff image {}", diff_path.display())),
        Ok(false) => {}
        Err(e) => add_problem(&mut outcome, format!("{e}")),
    }
    let passed = outcome.checks_passed();
    outcome.status = if passed {
        Status::Passed
    } else {
        Status::Failed
    };
    if options.update {
        // A scene that differs (or misses its image): image and field rewritten. A scene within
        // tolerance keeps its references; with --save-field it gains a missing field reference.
        let field = rendered.field.filter(|_| had_field || options.save_field);
        let mut staged = Staged::new();
        let staging = (|| -> Result<()> {
            if !passed {
                staged.add(&png_path, rendered.png)?;
            }
            if let Some(panels) = field.filter(|_| !passed || !had_field) {
                staged.add(&field_path, &field_file::encode(panels)?)?;
            }
            Ok(())
        })();
        let targets: Vec<String> = staged.targets().map(|p| p.display().to_string()).collect();
        match staging.and_then(|()| Ok(staged.commit()?)) {
            Ok(()) if targets.is_empty() => {}
            Ok(()) => {
                outcome.status = Status::Updated;
                outcome
                    .written
                    .push(format!("wrote {}", targets.join(", ")));
            }
            Err(e) => add_problem(&mut outcome, format!("cannot update the reference: {e:#}")),
        }
    }
    outcome
}

fn add_problem(outcome: &mut SceneOutcome, problem: String) {
    outcome.status = Status::Failed;
    outcome.problem = Some(match outcome.problem.take() {
        Some(earlier) => format!("{earlier}; {problem}"),
        None => problem,
    });
}

/// The field of a scene against the reference archive `bytes`.
fn field_check(
    rendered: &Rendered,
    bytes: &[u8],
    path: &Path,
    options: &CompareOptions,
) -> FieldCheck {
    let mismatch = |why: String| FieldCheck {
        tolerance: options.field_tolerance,
        unit: rendered.stress_unit.to_string(),
        axes: rendered.axes.first().cloned().unwrap_or_default(),
        largest: None,
        mismatch: Some(why),
    };
    let Some(actual) = rendered.field else {
        return mismatch(format!(
            "the reference {} holds a field but this scene draws a sheet (no field)",
            path.display()
        ));
    };
    let axes_of = |k: usize| rendered.axes.get(k).cloned().unwrap_or_default();
    match field_file::decode(bytes) {
        Ok(reference) => {
            let first = axes_of(0);
            let mut check = field_file::compare(
                actual,
                &reference,
                options.field_tolerance,
                rendered.stress_unit,
                [&first[0], &first[1]],
            );
            // The place of the largest difference in its own panel's coordinates.
            if let Some(largest) = &check.largest {
                check.axes = axes_of(largest.panel);
            }
            check
        }
        Err(e) => mismatch(format!("{}: {e}", path.display())),
    }
}

/// Ends a comparison run: writes the report, prints the summary line, and fails if any scene
/// failed its comparison or did not render.
pub fn finish(
    outcomes: &[SceneOutcome],
    options: &CompareOptions,
    out_dir: &Path,
    render_failures: &[String],
    recordings: usize,
    say: &dyn Fn(String),
) -> Result<()> {
    let count = |s: Status| outcomes.iter().filter(|o| o.status == s).count();
    let (failed, updated, passed) = (
        count(Status::Failed),
        count(Status::Updated),
        count(Status::Passed),
    );
    let reference_dir = options.reference_dir.display();
    let mut extra = String::new();
    if !render_failures.is_empty() {
        extra.push_str(&format!(
            "; {} scene(s) did not render: {}",
            render_failures.len(),
            render_failures.join(", ")
        ));
    }
    if recordings > 0 {
        extra.push_str(&format!(
            "; {recordings} recording scene(s) recorded, not compared"
        ));
    }
    if let Some(dir) = &options.report_dir {
        let context = format!("{} against {reference_dir}{extra}", out_dir.display());
        let html = regression::html_report(outcomes, &context, &options.measure);
        std::fs::create_dir_all(dir)
            .with_context(|| format!("cannot create the report directory {}", dir.display()))?;
        let path = dir.join("index.html");
        write_atomic(&path, html.as_bytes())?;
        extra.push_str(&format!("; report {}", path.display()));
    }
    let failed_names: Vec<&str> = outcomes
        .iter()
        .filter(|o| o.status == Status::Failed)
        .map(|o| o.name.as_str())
        .collect();
    let summary = format!(
        "regression: {failed} of {} scene(s) differ from the references in {reference_dir} ({updated} updated, {passed} passed){}{extra}",
        outcomes.len(),
        if failed_names.is_empty() {
            String::new()
        } else {
            format!(": {}", failed_names.join(", "))
        },
    );
    if failed > 0 || !render_failures.is_empty() {
        bail!(summary);
    }
    say(summary);
    Ok(())
}

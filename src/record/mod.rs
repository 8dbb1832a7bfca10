//! Rerun `.rrd` recordings of scenes, written to a file or streamed to a viewer step by step
//! as the steps are computed ([`sink`]).
//!
//! ## Layout of a recording (entity paths)
//! - `description`: markdown text of the scene, its contact, its `hertz` report, and how to
//!   read the views (static).
//! - `sections/<k>/field`: panel `k`'s field as a `DepthImage` (values in the figure's stress
//!   unit, so hovering reads them; the viewer calls them "Depth" in "m"), placed in the figure's
//!   coordinates (horizontal to the right, depth downwards) by a static `Transform3D`; one
//!   colour range for every step.
//! - `sections/<k>/colorbar/image` (the same colour map as an image beside the map),
//!   `.../ticks` and `.../labels` (tick values and the caption with the unit), static.
//! - `sections/<k>/title`: the step's parameters and the traction legend, as labels above the
//!   strip; `sections/<k>/tractions/p`, `.../q`: the profiles above the surface (`z < 0`);
//!   `sections/<k>/surface`; `sections/<k>/outline` (xy sections).
//! - `sections/<k>/maximum`, `sections/<k>/minimum` (the extremes the figure marks, with
//!   `label` and, when the label had to move, `leader`); `sections/<k>/material_points`.
//! - `sections/<k>/values`: the same values as a `Tensor` with named dimensions.
//! - `series/<k>/maximum`, `series/<k>/minimum`, `series/<k>/maximum_depth`,
//!   `series/<parameter>`: scalars per step; `charts/<k>/maximum`, `charts/<k>/depth`: the
//!   extremes and the depth of the maximum against the swept parameter, drawn as images.
//! - `history/<k>/point<j>/<component>`: stresses at material points as a load moves.
//! - `volume/iso/<m>` (iso-surfaces as meshes), `volume/contact` (outline, and `patch`
//!   shaded by the pressure), `volume/maximum`, `volume/surface` (the box's top face).
//! - `log`: one line per step.
//!
//! Rough and surface scenes are recorded by [`rough`]; coated scenes (and their
//! coating-thickness sweeps) by [`coated`]; speed sweeps (`parameter = "peclet"`,
//! scenes with `[thermal]`: `surface`, `section`, `charts/...` and `series/...` of body 1's
//! flash temperature) by [`thermal`].
//!
//! Steps are time points of a sequence timeline named after the sweep's parameter (`friction`,
//! `load`, `position`, `peclet`), or `step` (a single point) for a scene without a sweep. The
//! viewer layout ([`layout`]) gives the maps most of the window, the plots and documents tabs
//! beside.
//!
//! Uses: [`crate::study`], [`crate::figure`], [`crate::render`], [`crate::report`] and the
//! scene; it draws what they computed.

mod coated;
mod ehl;
mod isosurface;
mod layout;
mod panels;
pub mod plastic;
mod rough;
mod rough_depth;
mod section;
pub mod sink;
mod thermal;
mod volume;
pub mod wear;

use std::path::{Path, PathBuf};

use rerun::RecordingStream;

use crate::contact::rough::RoughSolution;
use crate::field::FieldError;
use crate::figure;
use crate::render::chart::{chart_png, Chart, PALETTE};
use crate::render::colormap::ColorScale;
use crate::render::{robust_top, ColorMap, Figure, Mark, Panel};
use crate::scene::{ContactKind, Scene, SweepParameter};
use crate::study;
use layout::{Layout, Node, View, ViewKind};
use panels::{chart_png_bytes, record_sections};
use section::Frame;
pub use sink::{Destination, DEFAULT_VIEWER_URL};

/// The application id of every recording.
pub const APPLICATION_ID: &str = "stressfield";

/// Errors while recording.
#[derive(Debug, thiserror::Error)]
pub enum RecordError {
    #[error(transparent)]
    Field(#[from] FieldError),
    #[error(transparent)]
    Thermal(#[from] crate::study::thermal::ThermalStudyError),
    #[error("sweep step {step}: {message}")]
    Step { step: usize, message: String },
    #[error(transparent)]
    Wear(#[from] crate::study::wear::WearStudyError),
    #[error("rerun: {0}")]
    Rerun(String),
    #[error("contact.body1.coating: a coated rough contact is not recorded (the recording's depth timeline draws the homogeneous body's planes)\nhint: `stressfield render` draws its sheet and `stressfield contact` reports its stresses in the coating, on the interface and in the substrate")]
    CoatedRough,
    #[error("cannot write {path}: {message}\nhint: check that the directory exists, is writable and has free space, or choose another with --out-dir or -o")]
    Output { path: PathBuf, message: String },
    #[error("standard output is a terminal, and a recording is binary\nhint: pipe it into a viewer: stressfield record SCENE -o - | rerun -")]
    Terminal,
    #[error("cannot write the recording to standard output: {0}")]
    Stdout(String),
    #[error("cannot stream to {url}: {message}\nhint: start a viewer first (`rerun`, from pip install \"rerun-sdk==0.36.*\") or use --spawn")]
    Viewer { url: String, message: String },
    #[error("cannot start a Rerun viewer: {0}\nhint: install the viewer matching this build, pip install \"rerun-sdk==0.36.*\" (it puts `rerun` on the PATH), or start one yourself and use --connect")]
    Spawn(String),
}

impl From<rerun::RecordingStreamError> for RecordError {
    fn from(error: rerun::RecordingStreamError) -> Self {
        RecordError::Rerun(error.to_string())
    }
}

/// What was recorded, for the caller's message.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Summary {
    pub steps: usize,
    pub panels: usize,
    /// Triangles of the iso-surfaces of the last step (0 without a volume).
    pub volume_triangles: usize,
}

/// Records `scene` to `destination`, each step sent as soon as it is computed. A file is
/// complete or absent: written into a temporary file and renamed at the end (see [`sink`]).
pub fn record_to(
    scene: &Scene,
    destination: &Destination,
    on_row: &(dyn Fn() + Sync),
) -> Result<Summary, RecordError> {
    record_to_with(scene, destination, on_row, None)
}

/// As [`record_to`], with a rough scene's contact already solved (`rough`, by
/// [`crate::study::rough::solve`]; `None`: solved here, once).
pub fn record_to_with(
    scene: &Scene,
    destination: &Destination,
    on_row: &(dyn Fn() + Sync),
    rough: Option<&RoughSolution>,
) -> Result<Summary, RecordError> {
    let output = sink::Output::open(destination, &scene.name)?;
    // A stream is watched as it arrives: the time cursor follows the newest step.
    let live = !matches!(destination, Destination::File(_));
    let summary = record_with(
        scene,
        &output.stream,
        live,
        on_row,
        &|| output.flush(),
        rough,
    )?;
    output.finish()?;
    Ok(summary)
}

/// Records a wear scene to `destination` from its study and its steps' sections, computed
/// once by the caller ([`crate::study::wear::study`], [`crate::study::wear::sections`]).
pub fn record_wear_to(
    scene: &Scene,
    destination: &Destination,
    study: &crate::study::wear::WearStudy,
    sections: &[crate::study::wear::StepSection],
) -> Result<Summary, RecordError> {
    let output = sink::Output::open(destination, &scene.name)?;
    let live = !matches!(destination, Destination::File(_));
    let summary = wear::record(scene, study, sections, &output.stream, live, &|| {
        output.flush()
    })?;
    output.finish()?;
    Ok(summary)
}

/// Records a `[plasticity]` scene's study (solved once by the caller) to `destination`.
pub fn record_plastic_to(
    scene: &Scene,
    destination: &Destination,
    study: &crate::study::plastic::PlasticStudy,
) -> Result<Summary, RecordError> {
    let output = sink::Output::open(destination, &scene.name)?;
    let live = !matches!(destination, Destination::File(_));
    let summary = plastic::record(scene, study, &output.stream, live, &|| output.flush())?;
    output.finish()?;
    Ok(summary)
}

/// Records `scene` into the file `path` (see [`record_to`]).
pub fn record_to_file(
    scene: &Scene,
    path: &Path,
    on_row: &(dyn Fn() + Sync),
) -> Result<Summary, RecordError> {
    record_to(scene, &Destination::File(path.to_path_buf()), on_row)
}

/// The name of the timeline of a scene's steps.
pub fn timeline(scene: &Scene) -> &'static str {
    if scene.wear.is_some() {
        return wear::TIMELINE;
    }
    if scene.plasticity.is_some() {
        return plastic::TIMELINE;
    }
    scene.sweep.as_ref().map_or("step", |s| s.parameter.key())
}

/// The swept parameter as a timeline of its own (issue 23, item 8): the viewer plots scalars
/// against a timeline, never against another logged value, so every step is also logged at
/// its parameter's value, an integer in the unit the timeline's name gives (`μ × 100`,
/// `W (N)`, `W (mN)`, `x0/a × 10`, `x0 (µm)`). The time panel opens on it, so the plots run
/// against the parameter. `None` for a single step, and for a speed sweep: its Péclet numbers
/// (or entrainment speeds) span decades, and its charts are drawn on logarithmic axes instead.
#[derive(Clone, Debug, PartialEq)]
pub struct ValueTimeline {
    pub name: String,
    /// Each step's value in the timeline's unit.
    pub values: Vec<i64>,
}

impl ValueTimeline {
    /// The timeline's name as the stream takes it.
    fn timeline(&self) -> Result<rerun::TimelineName, RecordError> {
        rerun::TimelineName::try_new(&self.name).map_err(|e| RecordError::Rerun(e.to_string()))
    }
}

/// See [`ValueTimeline`].
pub fn value_timeline(scene: &Scene) -> Option<ValueTimeline> {
    if is_speed_sweep(scene) || is_entrainment_sweep(scene) {
        return None;
    }
    let (label, xs) = panels::parameter_axis(scene)?;
    if xs.len() < 2 {
        return None;
    }
    let integral = |k: i32| {
        xs.iter().all(|&x| {
            let scaled = x * 10f64.powi(k);
            (scaled - scaled.round()).abs() <= 1e-9 * scaled.abs().max(1.0)
        })
    };
    // The coarsest power of ten that holds every value exactly; else one that resolves the
    // closest two values into a hundred units.
    let k = (0..=6).find(|&k| integral(k)).unwrap_or_else(|| {
        let mut sorted = xs.clone();
        sorted.sort_by(f64::total_cmp);
        let gap = sorted
            .windows(2)
            .map(|w| w[1] - w[0])
            .filter(|g| *g > 0.0)
            .fold(f64::INFINITY, f64::min);
        if gap.is_finite() {
            ((100.0 / gap).log10().ceil() as i32).clamp(0, 9)
        } else {
            0
        }
    });
    // A unit one prefix smaller where the label has one that takes it.
    let smaller = [
        (" (N)", " (mN)", " (µN)"),
        (" (mm)", " (µm)", " (nm)"),
        (" (kN/m)", " (N/m)", " (mN/m)"),
    ];
    let (name, k) = match smaller.iter().find(|(unit, ..)| label.ends_with(unit)) {
        Some((unit, milli, micro)) if (1..=6).contains(&k) => {
            let stem = &label[..label.len() - unit.len()];
            if k <= 3 {
                (format!("{stem}{milli}"), 3)
            } else {
                (format!("{stem}{micro}"), 6)
            }
        }
        _ if k == 0 => (label.clone(), 0),
        _ => (format!("{label} × {}", 10i64.pow(k as u32)), k),
    };
    Some(ValueTimeline {
        name,
        values: xs
            .iter()
            .map(|&x| (x * 10f64.powi(k)).round() as i64)
            .collect(),
    })
}

/// Whether `scene` sweeps the sliding speed (a Péclet sweep, recorded by [`thermal`]).
fn is_speed_sweep(scene: &Scene) -> bool {
    scene
        .sweep
        .as_ref()
        .is_some_and(|s| s.parameter == SweepParameter::Peclet)
}

/// Whether `scene` sweeps the lubricant's entrainment speed (recorded by [`ehl`]).
fn is_entrainment_sweep(scene: &Scene) -> bool {
    scene
        .sweep
        .as_ref()
        .is_some_and(|s| s.parameter == SweepParameter::EntrainmentSpeed)
}

/// Grid rows a recording of `scene` evaluates (its sections at every step), for progress;
/// recordings of rough, surface and coated scenes and speed sweeps report none.
pub fn rows(scene: &Scene) -> usize {
    if matches!(
        scene.contact.kind,
        ContactKind::Rough | ContactKind::Surface
    ) || is_speed_sweep(scene)
        || is_entrainment_sweep(scene)
        || scene.contact.coating.is_some()
    {
        return 0;
    }
    let steps = scene.sweep.as_ref().map_or(1, |s| s.values.len());
    let rows: usize = scene
        .panels
        .iter()
        .map(|p| study::plane(scene, p).v.count)
        .sum();
    steps * rows
}

/// Records every step of `scene` into `stream`; `on_row` is called once per evaluated grid
/// row ([`rows`] in all).
pub fn record_scene(
    scene: &Scene,
    stream: &RecordingStream,
    on_row: &(dyn Fn() + Sync),
) -> Result<Summary, RecordError> {
    record_with(
        scene,
        stream,
        false,
        on_row,
        &|| {
            stream
                .flush_blocking()
                .map_err(|e| RecordError::Rerun(e.to_string()))
        },
        None,
    )
}

/// Records `scene` into `stream`, calling `flush` after every step; a `live` stream (to a
/// viewer) opens with the time cursor following the newest step, a file at the first step;
/// `solved`: a rough scene's contact, if already solved.
fn record_with(
    scene: &Scene,
    stream: &RecordingStream,
    live: bool,
    on_row: &(dyn Fn() + Sync),
    flush: &dyn Fn() -> Result<(), RecordError>,
    solved: Option<&RoughSolution>,
) -> Result<Summary, RecordError> {
    // Steps are on the sweep's own timeline; the wall clock of logging is no timeline to
    // browse (the viewer would offer `log_time` beside it).
    stream.set_log_time_enabled(false);
    if scene.wear.is_some() {
        // The wear steps, solved here once (a caller that has them uses record_wear_to).
        let study = crate::study::wear::study(scene, &mut |_| {})?;
        let sections = crate::study::wear::sections(&study, &mut |_| {})?;
        return wear::record(scene, &study, &sections, stream, live, flush);
    }
    if matches!(
        scene.contact.kind,
        ContactKind::Rough | ContactKind::Surface
    ) {
        if scene.contact.coating.is_some() {
            return Err(RecordError::CoatedRough);
        }
        return rough::record(scene, stream, live, flush, solved);
    }
    if scene.contact.coating.is_some() {
        // A coated body's section, from its study (never the homogeneous panels).
        return coated::record(scene, stream, live, flush);
    }
    if is_speed_sweep(scene) {
        return thermal::record(scene, stream, live, flush);
    }
    if is_entrainment_sweep(scene) {
        return ehl::record(scene, stream, live, flush);
    }
    record_sections(scene, stream, live, on_row, flush)
}

/// The time of step `step` (counted from 0) on a sequence timeline: steps count from 1 on the
/// time panel, in titles, logs and history axes alike.
fn step_time(step: usize) -> i64 {
    step as i64 + 1
}

/// The text naming step `step` (counted from 0) of `steps` with its swept value `text`:
/// `step 40 of 61: x0 = 0.9a`, the number the time panel shows ([`step_time`]).
fn step_text(step: usize, steps: usize, text: &str) -> String {
    format!("step {} of {steps}: {text}", step_time(step))
}

/// The window the layout is planned for (the viewer's size when it opens a file varies; the
/// views scale with it).
const WINDOW_PX: (f64, f64) = (1600.0, 1000.0);
/// Width shares of the maps and of the side column.
const MAIN_SHARE: f32 = 2.6;
const SIDE_SHARE: f32 = 1.0;
/// Height shares of the sections and of the 3-D volume below them.
const SECTIONS_SHARE: f32 = 1.0;
const VOLUME_SHARE: f32 = 1.5;

/// Rounds `x > 0` up to two significant digits.
fn round_up(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return x;
    }
    let unit = 10f64.powf(x.log10().floor() - 1.0);
    (x / unit - 1e-9).ceil() * unit
}

/// The colour range of a panel for a whole sweep, from the values of a coarse preview of every
/// step (computed first, so that steps can be sent as they are computed): the figure's range
/// rule ([`ColorScale::for_range`]) with 3 % to spare, rounded up.
fn colour_range(map: ColorMap, lo: f64, hi: f64, fixed: Option<(f64, f64)>) -> (f64, f64) {
    if let Some(range) = fixed {
        return range;
    }
    let scale = ColorScale::for_range(map, lo, hi);
    let grow = |v: f64| {
        if v > 0.0 {
            round_up(1.03 * v)
        } else if v < 0.0 {
            -round_up(-1.03 * v)
        } else {
            0.0
        }
    };
    (grow(scale.lo), grow(scale.hi))
}

/// A plotted series' style: its name in the legend, its colour, a line 2 points wide.
fn series_line(name: impl Into<String>, [r, g, b]: [u8; 3]) -> rerun::SeriesLines {
    rerun::SeriesLines::new()
        .with_names([name.into()])
        .with_colors([rerun::Color::from_rgb(r, g, b)])
        .with_widths([2.0])
}

/// The Rerun colour map closest to a figure's.
fn rerun_colormap(map: ColorMap) -> rerun::components::Colormap {
    use rerun::components::Colormap;
    match map {
        ColorMap::Viridis => Colormap::Viridis,
        ColorMap::Inferno => Colormap::Inferno,
        ColorMap::Magma => Colormap::Magma,
        ColorMap::Plasma => Colormap::Plasma,
        // Rerun has no cividis; viridis is its nearest relative.
        ColorMap::Cividis => Colormap::Viridis,
        ColorMap::Turbo => Colormap::Turbo,
        // Rerun's one diverging map (red at the first end of its range, blue at the second:
        // the sections give it the high end first, `section::colour_range`).
        ColorMap::Diverging => Colormap::Spectral,
    }
}

/// The markdown description of a scene: title, contact, sweep and the `hertz` report.
pub fn describe(scene: &Scene) -> String {
    let mut text = format!(
        "# {}\n\n",
        scene.title.clone().unwrap_or_else(|| scene.name.clone())
    );
    // The panels' planes, each once: "xz section", "xz and yz sections".
    let mut sections: Vec<&str> = Vec::new();
    for panel in &scene.panels {
        if !sections.contains(&panel.section.key()) {
            sections.push(panel.section.key());
        }
    }
    let sections = match sections.as_slice() {
        [one] => format!("{one} section"),
        [init @ .., last] => format!("{} and {last} sections", init.join(", ")),
        [] => format!("{} section", scene.figure.section.key()),
    };
    text.push_str(&format!(
        "Scene `{}`: {} panel(s) of {} ({}), {sections}.\n\n",
        scene.name,
        scene.panels.len(),
        scene.figure.quantity.description(),
        scene
            .figure
            .stress_unit
            .label(scene.figure.quantity.symbol()),
    ));
    if let Some(sweep) = &scene.sweep {
        let first = sweep.describe(0, scene);
        let last = sweep.describe(sweep.values.len() - 1, scene);
        text.push_str(&format!(
            "**Sweep** over {}: {} steps, from {first} to {last}, on the timeline `{}` (steps counted from 1)",
            sweep.parameter.key(),
            sweep.values.len(),
            sweep.parameter.key()
        ));
        match value_timeline(scene) {
            Some(values) => text.push_str(&format!(
                " and on the timeline `{}`, the swept value itself ({} to {}). The time panel opens on the second, so the plots (hover them, zoom with the wheel) run against the swept value.\n\n",
                values.name,
                values.values[0],
                values.values[values.values.len() - 1]
            )),
            None => text.push_str(".\n\n"),
        }
        if sweep.parameter == SweepParameter::Position {
            text.push_str("The field is drawn in a fixed body frame as the contact's centre moves to x0: the stress history of each material point.");
            if sweep.values.len() > 1 && !sweep.material_points.is_empty() {
                let (from, to) = (sweep.values[0], sweep.values[sweep.values.len() - 1]);
                let unit = scene.figure.length_unit.suffix();
                text.push_str(&format!(
                    " The material points' histories (σxx, σzz, τxz, the principal shear τ1 and σvM) run against x0 (from {}{unit} to {}{unit}), like the extremes and the depth of the maximum.",
                    crate::io::text::number(from),
                    crate::io::text::number(to),
                ));
            }
            text.push_str("\n\n");
        }
    }
    text.push_str("Conventions: z points into the body (depth drawn downwards), tension positive, q = μp acts in +x on the body (trailing edge x = −a).\n\n");
    text.push_str(&format!(
        "**Reading the views.** Hovering the map shows `Val`: the value of {} in the unit of the colour bar ({}). The viewer also prints it as a \"Depth\" in m or mm, because the map is stored as a depth image: ignore that line. The colour range is the same at every step (from a coarse preview of all steps, rounded up); the marked extremes and the title row follow the step. The tab `values` holds the same numbers as a tensor (rows z, columns x, hover to read them) in the map's colours and colour range: read its colours on the map's colour bar.",
        scene.figure.quantity.symbol(),
        scene.figure.stress_unit.label(scene.figure.quantity.symbol()),
    ));
    if scene.volume.is_some() {
        text.push_str(" The 3-D view shows nested translucent iso-surfaces of the half box y ≤ 0 at the levels in its title (coloured on the map's colour bar, the outer ones more transparent; the cut face shows how they nest, and caps close them where the box cuts them), the contact patch's front half shaded by the pressure (white at its edge, dark red at its centre), the axes, the direction of the friction traction on the body (+x; trailing edge at x = −a) and the maximum the report gives; drag to turn it, scroll to zoom, double-click to return to the first view.");
    }
    text.push_str("\n\n");
    text.push_str("## Contact (`stressfield hertz`)\n\n```text\n");
    text.push_str(&crate::report::hertz(
        scene,
        &crate::study::assess::scene_maxima(scene),
    ));
    text.push_str("```\n");
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_single_spike_does_not_set_the_robust_top() {
        // 999 contact cells at up to 100 MPa, the rest out of contact, one cell at 6000.
        let mut values: Vec<f64> = (1..1000).map(|k| 0.1 * k as f64).collect();
        values.extend([0.0; 500]);
        values.push(6000.0);
        let (top, clipped) = robust_top(&values);
        assert!(clipped);
        assert!(top < 100.0 && top > 99.0, "{top}");
        // Without a spike nothing is clipped beyond the quantile's few cells.
        assert_eq!(robust_top(&[0.0, 2.0]), (2.0, false));
        assert_eq!(robust_top(&[0.0]), (0.0, false));
    }

    #[test]
    fn steps_count_from_one_in_every_text() {
        assert_eq!(step_time(0), 1);
        assert_eq!(step_text(39, 61, "x0 = 0.9a"), "step 40 of 61: x0 = 0.9a");
    }
}

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
//! Rough and surface scenes are recorded by [`rough`]; speed sweeps (`parameter = "peclet"`,
//! scenes with `[thermal]`: `surface`, `section`, `charts/...` and `series/...` of body 1's
//! flash temperature) by [`thermal`].
//!
//! Steps are time points of a sequence timeline named after the sweep's parameter (`friction`,
//! `load`, `position`, `peclet`), or `step` (a single point) for a scene without a sweep. The
//! viewer layout ([`layout`]) gives the maps most of the window, the plots and documents tabs
//! beside.

mod isosurface;
mod layout;
mod rough;
mod section;
pub mod sink;
mod thermal;
mod volume;

use std::path::{Path, PathBuf};

use rerun::RecordingStream;

use crate::contact::rough::RoughSolution;
use crate::field::FieldError;
use crate::figure;
use crate::render::chart::{chart_png, Chart, Series, Style, PALETTE};
use crate::render::colormap::ColorScale;
use crate::render::{ColorMap, Figure, Mark, Panel};
use crate::scene::{ContactKind, Scene, SweepParameter};
use crate::study;
use layout::{Layout, Node, View, ViewKind};
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
    #[error("rerun: {0}")]
    Rerun(String),
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
    scene.sweep.as_ref().map_or("step", |s| s.parameter.key())
}

/// Whether `scene` sweeps the sliding speed (a Péclet sweep, recorded by [`thermal`]).
fn is_speed_sweep(scene: &Scene) -> bool {
    scene
        .sweep
        .as_ref()
        .is_some_and(|s| s.parameter == SweepParameter::Peclet)
}

/// Grid rows a recording of `scene` evaluates (its sections at every step), for progress;
/// recordings of rough and surface scenes and speed sweeps report none.
pub fn rows(scene: &Scene) -> usize {
    if matches!(
        scene.contact.kind,
        ContactKind::Rough | ContactKind::Surface
    ) || is_speed_sweep(scene)
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
    if matches!(
        scene.contact.kind,
        ContactKind::Rough | ContactKind::Surface
    ) {
        return rough::record(scene, stream, live, flush, solved);
    }
    if is_speed_sweep(scene) {
        return thermal::record(scene, stream, live, flush);
    }
    record_sections(scene, stream, live, on_row, flush)
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

/// The size in pixels of each section view in the planned window.
fn section_view_px(scene: &Scene) -> (f64, f64) {
    let width = WINDOW_PX.0 * f64::from(MAIN_SHARE / (MAIN_SHARE + SIDE_SHARE)) - 20.0;
    let chrome = if scene.sweep.is_some() { 130.0 } else { 90.0 };
    let mut height = (WINDOW_PX.1 - chrome) / scene.panels.len().max(1) as f64;
    if scene.volume.is_some() {
        height *= f64::from(SECTIONS_SHARE / (SECTIONS_SHARE + VOLUME_SHARE));
    }
    (width, height)
}

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

/// The coarse preview of a scene: at most 81 samples across.
fn preview(scene: &Scene) -> Scene {
    let mut coarse = scene.clone();
    coarse.figure.resolution = scene.figure.resolution.min(81);
    coarse
}

fn step_scene(scene: &Scene, step: usize) -> Result<Scene, RecordError> {
    study::at_step(scene, step).map_err(|e| RecordError::Step {
        step,
        message: e.to_string(),
    })
}

/// The swept parameter's axis label and the value shown on it.
fn parameter_axis(scene: &Scene) -> Option<(String, Vec<f64>)> {
    let sweep = scene.sweep.as_ref()?;
    Some(match sweep.parameter {
        SweepParameter::Friction => ("μ".into(), sweep.values.clone()),
        SweepParameter::Load if scene.contact.kind == ContactKind::Line => (
            "P (kN/m)".into(),
            sweep.values.iter().map(|v| v * 1e-3).collect(),
        ),
        SweepParameter::Load => ("W (N)".into(), sweep.values.clone()),
        SweepParameter::Position => (
            scene.figure.length_unit.axis_label("x0"),
            sweep.values.clone(),
        ),
        SweepParameter::Peclet => ("Pe".into(), sweep.values.clone()),
    })
}

/// The recording of a section scene (line, point, elliptical, tractions).
fn record_sections(
    scene: &Scene,
    stream: &RecordingStream,
    live: bool,
    on_row: &(dyn Fn() + Sync),
    flush: &dyn Fn() -> Result<(), RecordError>,
) -> Result<Summary, RecordError> {
    let steps = scene.sweep.as_ref().map_or(1, |s| s.values.len());
    let timeline = timeline(scene);
    let panels = scene.panels.len();
    stream.log_static(
        "description",
        &rerun::TextDocument::from_markdown(describe(scene)),
    )?;
    // The colour ranges from a coarse preview of every step.
    let coarse = preview(scene);
    let mut spans = vec![(f64::INFINITY, f64::NEG_INFINITY); panels];
    let mut volume_largest = 0.0f64;
    for step in 0..steps {
        let coarse_step = step_scene(&coarse, step)?;
        let figure = figure::build(&coarse_step, &|| {})?;
        for (span, panel) in spans.iter_mut().zip(&figure.panels) {
            for &v in panel.values.iter().filter(|v| v.is_finite()) {
                *span = (span.0.min(v), span.1.max(v));
            }
        }
        if let Some(spec) = &scene.volume {
            let grid = volume::evaluate(&coarse_step, spec, (spec.points / 2).max(9))?;
            volume_largest = volume_largest.max(grid.largest());
        }
    }
    // The first step at full resolution: the frames of the views follow its axes.
    let first_scene = step_scene(scene, 0)?;
    let mut first = Some(figure::build(&first_scene, on_row)?);
    let figure0 = first.as_ref().expect("just built");
    let ranges: Vec<(f64, f64)> = figure0
        .panels
        .iter()
        .zip(&spans)
        .map(|(panel, &(lo, hi))| {
            let map = section::panel_colormap(figure0, panel);
            colour_range(map, lo, hi, panel.scale.as_ref().and_then(|s| s.range))
        })
        .collect();
    let view_px = section_view_px(scene);
    // The panels as drawn (a map seen from above with y up), and the material points there.
    let shown0: Vec<Panel> = figure0
        .panels
        .iter()
        .map(|panel| section::displayed(figure0, panel))
        .collect();
    let material: Vec<(f64, f64)> = scene
        .sweep
        .as_ref()
        .map(|s| {
            s.material_points
                .iter()
                .map(|&(x, z)| (x, if figure0.vertical_is_depth { z } else { -z }))
                .collect()
        })
        .unwrap_or_default();
    let frames: Vec<Frame> = shown0
        .iter()
        .zip(&ranges)
        .map(|(panel, &range)| {
            let longest = section::longest_tick(range)
                .max(section::panel_caption(figure0, panel).chars().count() / 2);
            let has_strip = figure0.vertical_is_depth && !panel.traction.is_empty();
            Frame::new(panel, has_strip, view_px, longest)
        })
        .collect();
    for (k, (panel, frame)) in shown0.iter().zip(&frames).enumerate() {
        let caption = section::panel_caption(figure0, panel);
        section::log_static(
            stream,
            &format!("sections/{k}"),
            frame,
            panel,
            &section::Fixed {
                map: section::panel_colormap(figure0, panel),
                caption: &caption,
                range: Some(ranges[k]),
                surface: figure0.vertical_is_depth,
                material: &material,
            },
        )?;
    }
    log_series_styles(stream, scene, figure0)?;
    let volume_setup = match &scene.volume {
        Some(spec) => {
            volume::log_static(stream, spec)?;
            let levels = volume::levels(spec, volume_largest);
            let scale = volume::scale(scene, spec, volume_largest);
            Some((spec, levels, scale))
        }
        None => None,
    };
    let levels: &[f64] = volume_setup
        .as_ref()
        .map_or(&[], |(_, levels, _)| levels.as_slice());
    layout::send(stream, &plan_layout(scene, figure0, &frames, levels), live)?;
    flush()?;
    let mut volume_triangles = 0;
    let mut history: Vec<Vec<(f64, f64, f64)>> = vec![Vec::new(); panels];
    for step in 0..steps {
        let step_scene = step_scene(scene, step)?;
        let figure = match first.take() {
            Some(figure) => figure,
            None => figure::build(&step_scene, on_row)?,
        };
        stream.set_time_sequence(timeline, step as i64);
        let mut title = String::new();
        if let Some(sweep) = &scene.sweep {
            let text = sweep.describe(step, scene);
            stream.log("log", &rerun::TextLog::new(format!("step {step}: {text}")))?;
            stream.log(
                format!("series/{}", sweep.parameter.key()),
                &rerun::Scalars::new([sweep.values[step]]),
            )?;
            title = format!("step {} of {steps}: {text}", step + 1);
        }
        for (k, panel) in figure.panels.iter().enumerate() {
            let panel_title = step_title(scene, step, &title, &figure, panel);
            let shown = section::displayed(&figure, panel);
            section::log_step(
                stream,
                section::When::Step,
                &format!("sections/{k}"),
                &frames[k],
                &figure,
                &shown,
                ranges[k],
                &section::Changing {
                    title: &panel_title,
                    notation: &section::Notation::of(&figure, panel),
                    mark: figure.mark,
                    material: &material,
                    values: true,
                },
            )?;
            let (largest, smallest) = section::extremes(panel, figure.mark);
            let largest = largest.or_else(|| section::extremes(panel, Mark::Max).0);
            if let Some(e) = largest {
                stream.log(
                    format!("series/{k}/maximum"),
                    &rerun::Scalars::new([e.value]),
                )?;
                if figure.vertical_is_depth {
                    stream.log(
                        format!("series/{k}/maximum_depth"),
                        &rerun::Scalars::new([e.v]),
                    )?;
                }
            }
            if let Some(e) = smallest {
                stream.log(
                    format!("series/{k}/minimum"),
                    &rerun::Scalars::new([e.value]),
                )?;
            }
            if steps > 1 {
                let value = |e: Option<section::Extreme>| e.map_or(f64::NAN, |e| e.value);
                history[k].push((
                    value(largest),
                    value(smallest),
                    largest.map_or(f64::NAN, |e| e.v),
                ));
                log_charts(
                    stream,
                    scene,
                    &figure,
                    k,
                    &history[k],
                    ranges[k],
                    &frames[k],
                )?;
            }
        }
        log_material_points(stream, &step_scene)?;
        if let Some((spec, levels, scale)) = &volume_setup {
            let grid = volume::evaluate(&step_scene, spec, spec.points)?;
            volume_triangles = volume::log_step(stream, &step_scene, spec, &grid, levels, scale)?;
        }
        flush()?;
    }
    Ok(Summary {
        steps,
        panels,
        volume_triangles,
    })
}

/// The title row of a panel at a step: the step and its parameter, then the rest of the
/// panel's subtitle (its groups are separated by two spaces, as in the PNG figure) without
/// repeating the parameter.
fn step_title(
    scene: &Scene,
    step: usize,
    title: &str,
    figure: &Figure,
    panel: &crate::render::Panel,
) -> String {
    let mut panel_title = title.to_string();
    let parameter = scene.sweep.as_ref().map(|s| s.describe(step, scene));
    let repeats = |part: &str| match (&parameter, scene.sweep.as_ref().map(|s| s.parameter)) {
        (Some(text), _) if part == text => true,
        // The subtitle writes the friction as the panel holds it.
        (_, Some(SweepParameter::Friction)) => part.starts_with("μ = "),
        _ => false,
    };
    let rest: Vec<&str> = panel
        .subtitle
        .split(",  ")
        .map(str::trim)
        .filter(|part| !part.is_empty() && !repeats(part))
        .collect();
    if !rest.is_empty() {
        if !panel_title.is_empty() {
            panel_title.push_str(",  ");
        }
        panel_title.push_str(&rest.join(",  "));
    }
    if panel_title.is_empty() {
        panel_title = figure.title.clone();
    }
    panel_title
}

/// Names and colours of the plotted series (static).
fn log_series_styles(
    stream: &RecordingStream,
    scene: &Scene,
    figure: &Figure,
) -> Result<(), RecordError> {
    let symbol = scene.figure.quantity.symbol();
    let line = |name: String, [r, g, b]: [u8; 3]| {
        rerun::SeriesLines::new()
            .with_names([name])
            .with_colors([rerun::Color::from_rgb(r, g, b)])
            .with_widths([2.0])
    };
    for k in 0..figure.panels.len() {
        stream.log_static(
            format!("series/{k}/maximum"),
            &line(format!("max {symbol}"), PALETTE[1]),
        )?;
        stream.log_static(
            format!("series/{k}/minimum"),
            &line(format!("min {symbol}"), PALETTE[0]),
        )?;
        stream.log_static(
            format!("series/{k}/maximum_depth"),
            &line(format!("depth of max {symbol}"), PALETTE[2]),
        )?;
    }
    if let Some(sweep) = &scene.sweep {
        stream.log_static(
            format!("series/{}", sweep.parameter.key()),
            &line(sweep.parameter.key().to_string(), PALETTE[6]),
        )?;
        for k in 0..figure.panels.len() {
            for j in 0..sweep.material_points.len() {
                for (c, (key, name)) in history_components(scene).into_iter().enumerate() {
                    stream.log_static(
                        format!("history/{k}/point{j}/{key}"),
                        &line(name, PALETTE[c % PALETTE.len()]),
                    )?;
                }
            }
        }
    }
    Ok(())
}

/// The stress components recorded at material points: `σxx`, `σzz`, `τxz` and the figure's
/// quantity when it is none of them, as `(key, symbol)`.
fn history_components(scene: &Scene) -> Vec<(&'static str, String)> {
    let mut components = vec![
        ("sxx", "σxx".to_string()),
        ("szz", "σzz".to_string()),
        ("sxz", "τxz".to_string()),
    ];
    let quantity = scene.figure.quantity;
    if !components.iter().any(|(key, _)| *key == quantity.key()) {
        components.push((quantity.key(), quantity.symbol().to_string()));
    }
    components
}

/// The extremes of panel `k` and the depth of its maximum against the swept parameter, for the
/// steps so far (the current one marked), drawn as chart images. `history` holds (max, min,
/// depth of max) per step.
fn log_charts(
    stream: &RecordingStream,
    scene: &Scene,
    figure: &Figure,
    k: usize,
    history: &[(f64, f64, f64)],
    range: (f64, f64),
    frame: &Frame,
) -> Result<(), RecordError> {
    let Some((x_label, xs)) = parameter_axis(scene) else {
        return Ok(());
    };
    let x_range = xs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let symbol = scene.figure.quantity.symbol();
    let current = history.len() - 1;
    let mut chart = Chart::new(
        &format!(
            "extremes of {symbol} against {}",
            x_label.split(' ').next().unwrap_or("")
        ),
        &x_label,
        &figure.value_label,
    );
    chart.x_range = Some(x_range);
    // A quarter of the span free above the data (the legend's corner), and a little below a
    // negative minimum, so that its line is not drawn on the axis.
    let headroom = |(lo, hi): (f64, f64)| {
        let span = hi - lo;
        (
            if lo < 0.0 { lo - 0.05 * span } else { lo },
            hi + 0.25 * span,
        )
    };
    chart.y_range = Some(headroom((range.0.min(0.0), range.1)));
    chart.width_px = 520;
    chart.height_px = 400;
    let add = |label: &str, column: usize, colour: [u8; 3], chart: &mut Chart| {
        let pick = |h: &(f64, f64, f64)| [h.0, h.1, h.2][column];
        let points: Vec<(f64, f64)> = history
            .iter()
            .zip(&xs)
            .map(|(h, &x)| (x, pick(h)))
            .filter(|(_, y)| y.is_finite())
            .collect();
        if points.is_empty() {
            return;
        }
        chart.series.push(Series {
            label: label.to_string(),
            points,
            style: Style::Line,
            colour,
        });
        let now = pick(&history[current]);
        if now.is_finite() {
            chart.series.push(Series {
                label: String::new(),
                points: vec![(xs[current], now)],
                style: Style::Markers,
                colour,
            });
        }
    };
    add(&format!("max {symbol}"), 0, PALETTE[1], &mut chart);
    add(&format!("min {symbol}"), 1, PALETTE[0], &mut chart);
    let png = chart_png_bytes;
    stream.log(
        format!("charts/{k}/maximum"),
        &rerun::EncodedImage::from_file_contents(png(&chart)?),
    )?;
    if figure.vertical_is_depth {
        let mut depth = Chart::new(
            &format!("depth of the maximum of {symbol}"),
            &x_label,
            &figure.z_label,
        );
        depth.x_range = Some(x_range);
        depth.y_range = Some(headroom((frame.v.0.max(0.0), frame.v.1)));
        depth.width_px = 520;
        depth.height_px = 400;
        add(&format!("depth of max {symbol}"), 2, PALETTE[2], &mut depth);
        stream.log(
            format!("charts/{k}/depth"),
            &rerun::EncodedImage::from_file_contents(png(&depth)?),
        )?;
    }
    Ok(())
}

/// A chart drawn as PNG bytes, for an `EncodedImage`.
fn chart_png_bytes(chart: &Chart) -> Result<Vec<u8>, RecordError> {
    let image = chart_png(chart).map_err(|e| RecordError::Rerun(e.to_string()))?;
    crate::render::encode_png(&image).map_err(|e| RecordError::Rerun(e.to_string()))
}

/// The viewer layout: the section maps (and the 3-D volume) take most of the window; beside
/// them, tabs of plots (against the swept parameter, by step, the stress histories) over tabs
/// of documents (the description, the raw values, the steps).
fn plan_layout(scene: &Scene, figure: &Figure, frames: &[Frame], levels: &[f64]) -> Layout {
    let section_name = |k: usize| {
        let mut name = format!(
            "{} · {} section",
            figure.value_label,
            scene.figure.section.key()
        );
        if figure.panels.len() > 1 {
            name = format!("panel {}: {name}", k + 1);
        }
        name
    };
    let sections: Vec<Node> = frames
        .iter()
        .enumerate()
        .map(|(k, frame)| {
            Node::View(
                View::new(
                    ViewKind::Spatial2D(Some(frame.bounds)),
                    section_name(k),
                    format!("sections/{k}"),
                )
                .with_contents(&["$origin/**", "- $origin/values"]),
            )
        })
        .collect();
    let sections = if sections.len() == 1 {
        sections.into_iter().next().expect("one")
    } else {
        Node::Vertical(sections, Vec::new())
    };
    let main = match &scene.volume {
        Some(spec) => Node::Vertical(
            vec![
                sections,
                Node::View(View::new(
                    ViewKind::Spatial3D(Some(volume::eye(spec))),
                    format!(
                        "volume: iso-surfaces of {} at {} (half box y ≥ 0, z down)",
                        spec.quantity.symbol(),
                        levels_text(scene, levels)
                    ),
                    "volume",
                )),
            ],
            vec![SECTIONS_SHARE, VOLUME_SHARE],
        ),
        None => sections,
    };
    let mut documents = vec![Node::View(View::new(
        ViewKind::TextDocument,
        "scene",
        "description",
    ))];
    for k in 0..figure.panels.len() {
        documents.push(Node::View(View::new(
            ViewKind::Tensor,
            format!("values {}", k + 1),
            format!("sections/{k}/values"),
        )));
    }
    // The first tab opens: a moving load's stress history, else the chart against the
    // parameter.
    let mut plots = Vec::new();
    if let Some(sweep) = scene.sweep.as_ref().filter(|s| s.values.len() > 1) {
        documents.push(Node::View(View::new(ViewKind::TextLog, "steps", "log")));
        let parameter = parameter_axis(scene).map_or(String::new(), |(label, _)| label);
        let parameter = parameter.split(' ').next().unwrap_or("").to_string();
        // The histories' unit as the colour bar writes it: `/ p0` or `(MPa)`.
        let unit = match figure.value_label.rsplit_once(" / ") {
            Some((_, unit)) => format!("/ {unit}"),
            None => figure
                .value_label
                .rfind(" (")
                .map_or(String::new(), |open| {
                    figure.value_label[open + 1..].to_string()
                }),
        };
        for k in 0..figure.panels.len() {
            for j in 0..sweep.material_points.len() {
                let (x, z) = sweep.material_points[j];
                plots.push(Node::View(View::new(
                    ViewKind::TimeSeries,
                    format!(
                        "point {j} at {}: stresses {unit} by step",
                        section::position_text(scene, x, z)
                    ),
                    format!("history/{k}/point{j}"),
                )));
            }
            plots.push(Node::View(View::new(
                ViewKind::Spatial2D(None),
                format!("extremes against {parameter}"),
                format!("charts/{k}/maximum"),
            )));
            if figure.vertical_is_depth {
                plots.push(Node::View(View::new(
                    ViewKind::Spatial2D(None),
                    format!("depth of the maximum against {parameter}"),
                    format!("charts/{k}/depth"),
                )));
            }
            plots.push(Node::View(
                View::new(
                    ViewKind::TimeSeries,
                    format!("extremes ({}) by step", figure.value_label),
                    format!("series/{k}"),
                )
                .with_contents(&["$origin/maximum", "$origin/minimum"]),
            ));
            if figure.vertical_is_depth {
                plots.push(Node::View(
                    View::new(
                        ViewKind::TimeSeries,
                        format!("depth of the maximum ({}) by step", figure.z_label),
                        format!("series/{k}"),
                    )
                    .with_contents(&["$origin/maximum_depth"]),
                ));
            }
        }
    }
    let documents = Node::Tabs(documents, 0);
    let side = if plots.is_empty() {
        documents
    } else {
        Node::Vertical(vec![Node::Tabs(plots, 0), documents], vec![1.3, 1.0])
    };
    Layout {
        root: Node::Horizontal(vec![main, side], vec![MAIN_SHARE, SIDE_SHARE]),
        timeline: scene
            .sweep
            .as_ref()
            .filter(|s| s.values.len() > 1)
            .map(|_| timeline(scene).to_string()),
    }
}

/// The iso-levels with their unit, innermost last: `0.198, 0.33, 0.46, 0.594 p0`.
fn levels_text(scene: &Scene, levels: &[f64]) -> String {
    let values: Vec<String> = levels.iter().map(|&l| section::short(l)).collect();
    let unit = section::stress_text(scene, 1.0);
    let unit = unit.trim_start_matches(|c: char| !c.is_whitespace());
    format!("{}{unit}", values.join(", "))
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
        // Rerun's one diverging map (red at the low end, blue at the high end).
        ColorMap::Diverging => Colormap::Spectral,
    }
}

/// Stresses at the sweep's material points (body frame) as a moving load passes: `σxx`,
/// `σzz`, `τxz` and the figure's quantity, in the figure's stress unit.
fn log_material_points(stream: &RecordingStream, scene: &Scene) -> Result<(), RecordError> {
    let Some(sweep) = &scene.sweep else {
        return Ok(());
    };
    if sweep.material_points.is_empty() {
        return Ok(());
    }
    let unit_over_a = study::length_unit_over_a(scene);
    let stress_per_p0 = study::DisplayUnits::of(scene).stress_per_p0;
    let quantity = scene.figure.quantity;
    for (k, panel) in scene.panels.iter().enumerate() {
        let solution = study::solution(scene, panel)
            .map_err(|e| RecordError::Field(FieldError::Numerical(e.to_string())))?;
        let y = match scene.figure.section {
            crate::scene::SectionKind::Xz => panel.at * unit_over_a,
            _ => 0.0,
        };
        for (j, &(x, z)) in sweep.material_points.iter().enumerate() {
            // Finite on the surface on a strip or cell edge too (the mean of the neighbours).
            let s = solution.finite_stress_over_p0(x * unit_over_a, y, z * unit_over_a);
            let base = format!("history/{k}/point{j}");
            for (key, _) in history_components(scene) {
                let value = match key {
                    "sxx" => s.xx,
                    "szz" => s.zz,
                    "sxz" => s.xz,
                    _ => quantity.of(&s),
                };
                stream.log(
                    format!("{base}/{key}"),
                    &rerun::Scalars::new([value * stress_per_p0]),
                )?;
            }
        }
    }
    Ok(())
}

/// The markdown description of a scene: title, contact, sweep and the `hertz` report.
pub fn describe(scene: &Scene) -> String {
    let mut text = format!(
        "# {}\n\n",
        scene.title.clone().unwrap_or_else(|| scene.name.clone())
    );
    text.push_str(&format!(
        "Scene `{}`: {} panel(s) of {} ({}), {} section.\n\n",
        scene.name,
        scene.panels.len(),
        scene.figure.quantity.description(),
        scene
            .figure
            .stress_unit
            .label(scene.figure.quantity.symbol()),
        scene.figure.section.key(),
    ));
    if let Some(sweep) = &scene.sweep {
        let first = sweep.describe(0, scene);
        let last = sweep.describe(sweep.values.len() - 1, scene);
        text.push_str(&format!(
            "**Sweep** over {}: {} steps, from {first} to {last}, on the timeline `{}`.\n\n",
            sweep.parameter.key(),
            sweep.values.len(),
            sweep.parameter.key()
        ));
        if sweep.parameter == SweepParameter::Position {
            text.push_str("The field is drawn in a fixed body frame as the contact's centre moves to x0: the stress history of each material point.\n\n");
        }
    }
    text.push_str("Conventions: z points into the body (depth drawn downwards), tension positive, q = μp acts in +x on the body (trailing edge x = −a).\n\n");
    text.push_str(&format!(
        "**Reading the views.** Hovering the map shows `Val`: the value of {} in the unit of the colour bar ({}). The viewer also prints it as a \"Depth\" in m or mm, because the map is stored as a depth image: ignore that line. The colour range is the same at every step (from a coarse preview of all steps, rounded up); the marked extremes and the title row follow the step.",
        scene.figure.quantity.symbol(),
        scene.figure.stress_unit.label(scene.figure.quantity.symbol()),
    ));
    if scene.volume.is_some() {
        text.push_str(" The 3-D view shows nested translucent iso-surfaces of the half box y ≥ 0 at the levels in its title (coloured on the map's colour bar, the outer ones more transparent; the cut face shows how they nest) and the contact patch shaded by the pressure (white at its edge, dark red at its centre); drag to turn it, scroll to zoom, double-click to return to the first view.");
    }
    text.push_str("\n\n");
    text.push_str("## Contact (`stressfield hertz`)\n\n```text\n");
    text.push_str(&crate::report::hertz(scene));
    text.push_str("```\n");
    text
}

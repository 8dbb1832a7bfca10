//! Recordings of surface and rough scenes.
//!
//! ## Entities
//! - `description`: the scene's report (the surface's statistics, or the solved contact's),
//!   and how to read the views.
//! - `sheet`: the rendered figure (with its colour bars and charts) as an image.
//! - `topography`: the height map as a 3-D mesh coloured by height (heights exaggerated so
//!   that the tallest relief is a fifth of the map's width; the factor is in the description).
//! - `maps/<k>`: the sheet's maps (topography, pressure, sections) as map views (see
//!   [`super::section`]): `field` (a depth image whose values read on hover), a colour bar with
//!   its unit, a title row, outlines and the labelled maximum; maps seen from above are drawn
//!   with y up, as in the figure.
//! - Rough scenes with a `[sweep]` of the load, on the timeline `load`: the map view
//!   `contact` (pressure in MPa, the spots outlined, the load and spot count in its title) at
//!   every load, also logged on a timeline of the load itself (`W (mN)`, see
//!   [`super::value_timeline`]), which the time panel opens on; and the series
//!   `series/load_n`, `series/contact_fraction`, `series/spots`, `series/max_pressure_mpa`,
//!   plotted natively against the load (the real area fraction, the spot count and the
//!   largest pressure against W).
//! - Rough scenes, on the timeline `depth` (layers numbered from the surface): the map view
//!   `depth`, the sheet's stress quantity in planes parallel to the surface from the surface
//!   down (the depth in its title), under the scene's own load.
//! - A view shows only what is logged on the timeline the time panel is on, so with a load
//!   sweep each timeline also holds one step of the other's views: on `load` (at its first
//!   step) the layer of the largest value, on `depth` (at its first step) the last load;
//!   their titles say which timeline steps through them.

use rerun::RecordingStream;

use super::layout::{Layout, Node, View, ViewKind};
use super::section::{self, Changing, Fixed, Frame, Notation, When};
use super::{RecordError, Summary};
use crate::contact::rough::{self, Control, RoughSolution};
use crate::field::Axis;
use crate::figure::{self, Drawing};
use crate::render::chart::{Cell, PALETTE};
use crate::render::{ColorMap, Figure, Mark, Panel};
use crate::report::rough::ContactReport;
use crate::scene::{ContactKind, Scene};
use crate::study::map_roll::Roll;
use crate::study::rough as rough_study;
use crate::study::rough_sheet;
use crate::surface::HeightMap;

pub(super) fn rerun_error(e: impl std::fmt::Display) -> RecordError {
    RecordError::Rerun(e.to_string())
}

/// Records a surface or rough scene (module doc); a `live` stream opens following the newest
/// step. Its grid rows are not reported as progress (how many there are depends on the solved
/// contact); [`super::rows`] counts none.
pub fn record(
    scene: &Scene,
    stream: &RecordingStream,
    live: bool,
    flush: &dyn Fn() -> Result<(), RecordError>,
    solved: Option<&RoughSolution>,
) -> Result<Summary, RecordError> {
    let on_row = &|| {};
    let surface = scene
        .surface
        .as_ref()
        .ok_or_else(|| rerun_error("the scene has no surface"))?;
    // A rough scene's contact, solved once (here, unless the caller did): the sheet, the
    // report and the depth steps use it.
    let owned;
    let solution: Option<&RoughSolution> = match (scene.contact.kind, solved) {
        (ContactKind::Rough, Some(solution)) => Some(solution),
        (ContactKind::Rough, None) => {
            owned = rough_study::solve(scene, &mut |_, _| {}).map_err(rerun_error)?;
            Some(&owned)
        }
        _ => None,
    };
    // A surface scene's characterisation, computed once: the sheet and the report use it.
    let characterisation = match solution {
        Some(_) => None,
        None => Some(crate::study::surface::characterise(scene).map_err(rerun_error)?),
    };
    // A rough contact's findings, computed once: the report states its maxima and the
    // sheet's section passes through them.
    let findings = match solution {
        Some(solution) => Some(rough_study::findings(scene, solution).map_err(rerun_error)?),
        None => None,
    };
    let drawing = match (&characterisation, solution, &findings) {
        (Some(c), _, _) => {
            Drawing::Sheet(crate::figure::surface::surface_sheet(scene, c).map_err(rerun_error)?)
        }
        (None, Some(solution), Some(findings)) => {
            let inputs =
                crate::study::drawing::rough_inputs(scene, solution, findings.maxima, on_row)
                    .map_err(rerun_error)?;
            figure::draw(scene, Some(solution), &inputs).map_err(rerun_error)?
        }
        _ => figure::compute_and_draw(scene, solution, on_row).map_err(rerun_error)?,
    };
    let Drawing::Sheet(sheet) = &drawing else {
        return Err(rerun_error("a surface scene draws a sheet"));
    };
    let png =
        crate::render::encode_png(&drawing.png().map_err(rerun_error)?).map_err(rerun_error)?;
    stream.log_static("sheet", &rerun::EncodedImage::from_file_contents(png))?;
    let exaggeration = log_topography(stream, &surface.heights)?;
    // A periodic contact's maps are drawn as the sheet draws them: rolled by whole cells so
    // that the report's maximum is at their centre (a contact on the seam drawn whole).
    let roll = match (solution, &findings) {
        (Some(solution), Some(findings)) => rough_sheet::display_roll(
            solution,
            &rough_sheet::ReportedMaximum::of(&findings.maxima, scene.figure.quantity).extreme,
        ),
        _ => Roll::NONE,
    };
    // The report's maximum: the depth steps include its depth and show its value there.
    let mut reported = None;
    let report = match (solution, &findings) {
        (Some(solution), Some(findings)) => {
            let maximum = findings.maxima.von_mises;
            reported = Some(super::rough_depth::Reported {
                value_pa: maximum.value_over_p0 * rough_study::REFERENCE_PRESSURE_PA,
                z: maximum.z_over_a,
                roll,
            });
            ContactReport::new(scene, solution, findings).text(scene)
        }
        _ => {
            let c = characterisation
                .as_ref()
                .ok_or_else(|| rerun_error("a surface scene is characterised"))?;
            let e_star = scene.contact.rough.and_then(|r| r.e_star_pa);
            let hardness = scene.contact.rough.and_then(|r| r.hardness_pa);
            crate::report::surface::SurfaceReport::new(c, e_star, hardness).text(c, &surface.source)
        }
    };
    // A load sweep's single-load views (figure, report, maps, topography, depth) are at the
    // scene's own load: say which step of the sweep that is.
    let shown_at = match solution.filter(|_| scene.sweep.is_some()) {
        Some(solution) => format!(
            "The figure, this report, the maps and the depth steps are under {}; the view \"pressure vs W\" steps through the loads, its colours {}.\n\n",
            load_text(scene, solution),
            contact_colours()
        ),
        None => String::new(),
    };
    stream.log_static(
        "description",
        &rerun::TextDocument::from_markdown(format!(
            "# {}\n\n{shown_at}```text\n{report}```\n\nThe `topography` mesh shows heights {exaggeration:.0} times exaggerated. \
             Maps are in µm; hovering a map shows `Val`, its value in the unit of its title (the viewer also prints it as a \"Depth\" in m or mm: ignore that line).",
            sheet.title
        )),
    )?;
    let maps: Vec<&Figure> = sheet
        .rows
        .iter()
        .flatten()
        .filter_map(|cell| match cell {
            Cell::Map(figure) => Some(figure),
            Cell::Chart(_) | Cell::Table(_) => None,
        })
        .collect();
    let rough = scene.contact.kind == ContactKind::Rough;
    let timeline = rough.then(|| match super::value_timeline(scene) {
        Some(values) if scene.sweep.is_some() => values.name,
        _ if scene.sweep.is_some() => "load".to_string(),
        _ => "depth".to_string(),
    });
    let view_px = main_view_px(timeline.is_some());
    let mut map_frames = Vec::with_capacity(maps.len());
    for (k, map) in maps.iter().enumerate() {
        let panel = &map.panels[0];
        let shown = section::displayed(map, panel);
        let range = map_range(map, panel, None);
        let frame = map_frame(map, &shown, range, view_px);
        let title = if panel.subtitle.is_empty() {
            map.title.clone()
        } else {
            panel.subtitle.clone()
        };
        let base = format!("maps/{k}");
        log_map_static(stream, &base, &frame, map, &shown, Some(range))?;
        log_map_step(
            stream,
            When::Static,
            &base,
            &frame,
            map,
            &shown,
            range,
            &title,
        )?;
        map_frames.push(frame);
    }
    // The views of the load sweep and of the depth steps, framed before they are computed
    // (their colour ranges are not known yet: the frames allow for six-character ticks).
    let surface_axes = surface_axes_um(&surface.heights, roll);
    let contact_frame = (rough && scene.sweep.is_some()).then(|| {
        let map = pressure_figure(Panel {
            subtitle: String::new(),
            x: surface_axes.0,
            z: surface_axes.1,
            values: ndarray::Array2::zeros((surface_axes.1.count, surface_axes.0.count)),
            traction: Vec::new(),
            half_width: 0.0,
            outlines: Vec::new(),
            scale: None,
            peak: None,
            axes: None,
        });
        let shown = section::displayed(&map, &map.panels[0]);
        Frame::new(&shown, false, view_px, 6)
    });
    let depth_frame = rough.then(|| {
        let shown = Panel {
            subtitle: String::new(),
            x: surface_axes.0,
            z: crate::field::Axis::new(
                -surface_axes.1.max,
                -surface_axes.1.min,
                surface_axes.1.count,
            ),
            values: ndarray::Array2::zeros((surface_axes.1.count, surface_axes.0.count)),
            traction: Vec::new(),
            half_width: 0.0,
            outlines: Vec::new(),
            scale: None,
            peak: None,
            axes: None,
        };
        Frame::new(&shown, false, view_px, 6)
    });
    let frames = Frames {
        maps: &map_frames,
        contact: contact_frame.as_ref(),
        depth: depth_frame.as_ref(),
        timeline,
    };
    super::layout::send(stream, &plan_layout(&maps, scene, &frames), live)?;
    flush()?;
    let mut steps = 1;
    if let Some(frame) = &contact_frame {
        steps = log_load_sweep(stream, scene, frame, roll, flush)?.max(1);
    }
    if let (Some(frame), Some(solution), Some(reported)) = (&depth_frame, solution, reported) {
        // The depth steps are at the scene's own load, on their own timeline (and, with a load
        // sweep, the layer of the report's maximum at the first load: see log_depth_steps).
        disable_load_timelines(stream, scene);
        let on_load = contact_frame.is_some();
        super::rough_depth::log_depth_steps(
            stream, scene, solution, reported, frame, on_load, on_row, flush,
        )?;
    }
    Ok(Summary {
        steps,
        panels: maps.len(),
        volume_triangles: 0,
    })
}

/// The size of a view in the main area (tabs beside the side column) in the planned window.
pub(super) fn main_view_px(has_timeline: bool) -> (f64, f64) {
    let (width, height) = super::WINDOW_PX;
    let share = f64::from(super::MAIN_SHARE / (super::MAIN_SHARE + super::SIDE_SHARE));
    let chrome = if has_timeline { 130.0 } else { 90.0 };
    (width * share - 20.0, height - chrome)
}

/// The colour range of a map: its scale's fixed range, or its values' by the figure's rule.
pub(super) fn map_range(map: &Figure, panel: &Panel, values: Option<(f64, f64)>) -> (f64, f64) {
    let (lo, hi) = values.unwrap_or_else(|| {
        panel
            .values
            .iter()
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
                (a.min(v), b.max(v))
            })
    });
    let colormap = section::panel_colormap(map, panel);
    let (lo, hi) =
        super::colour_range(colormap, lo, hi, panel.scale.as_ref().and_then(|s| s.range));
    (lo, if hi > lo { hi } else { lo + 1.0 })
}

/// The frame of a map (as [`section::displayed`]) in a view of `view_px`.
fn map_frame(map: &Figure, shown: &Panel, range: (f64, f64), view_px: (f64, f64)) -> Frame {
    let caption = section::panel_caption(map, shown);
    let ticks = section::longest_tick(range).max(caption.chars().count() / 2);
    Frame::new(shown, false, view_px, ticks)
}

/// Logs a map's static parts: placement, border and, with a fixed range, the colour bar.
pub(super) fn log_map_static(
    stream: &RecordingStream,
    base: &str,
    frame: &Frame,
    map: &Figure,
    shown: &Panel,
    range: Option<(f64, f64)>,
) -> Result<(), RecordError> {
    let caption = section::panel_caption(map, shown);
    section::log_static(
        stream,
        base,
        frame,
        shown,
        &Fixed {
            map: section::panel_colormap(map, shown),
            caption: &caption,
            range,
            surface: map.vertical_is_depth,
            material: &[],
        },
    )
}

/// Logs a map (as [`section::displayed`]) with its title row and labelled maximum.
#[allow(clippy::too_many_arguments)]
pub(super) fn log_map_step(
    stream: &RecordingStream,
    when: When,
    base: &str,
    frame: &Frame,
    map: &Figure,
    shown: &Panel,
    range: (f64, f64),
    title: &str,
) -> Result<(), RecordError> {
    section::log_step(
        stream,
        when,
        base,
        frame,
        map,
        shown,
        range,
        &Changing {
            title,
            notation: &Notation::of(map, shown),
            mark: map.mark,
            material: &[],
            values: false,
            traction_peak: None,
        },
    )
}

/// The axes of a height map's cells, in µm (cell centres).
fn surface_axes_um(map: &HeightMap, roll: Roll) -> (Axis, Axis) {
    let [dx, dy] = map.spacing_m();
    roll.axes(map.shape(), [dx * 1e6, dy * 1e6])
}

/// A map figure of the contact pressure (MPa) in µm, seen from above.
fn pressure_figure(panel: Panel) -> Figure {
    Figure {
        title: "pressure".into(),
        panels: vec![panel],
        value_label: "p (MPa)".into(),
        x_label: "x (µm)".into(),
        z_label: "y (µm)".into(),
        vertical_is_depth: false,
        traction_label: String::new(),
        colormap: ColorMap::Inferno,
        levels: crate::render::Levels::Count(0),
        mark: Mark::Max,
        panel_width_px: 400,
    }
}

/// The height map as a mesh coloured by height (at most 256 samples a side); returns the
/// vertical exaggeration.
fn log_topography(stream: &RecordingStream, map: &HeightMap) -> Result<f64, RecordError> {
    let [ny, nx] = map.shape();
    let [dx, dy] = map.spacing_m();
    let stride = nx.max(ny).div_ceil(256).max(1);
    let (cols, rows) = (nx.div_ceil(stride), ny.div_ceil(stride));
    let heights = map.heights_m();
    let (lo, hi) = heights
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let width_um = nx as f64 * dx * 1e6;
    let relief_um = ((hi - lo) * 1e6).max(f64::MIN_POSITIVE);
    let exaggeration = (0.2 * width_um / relief_um).max(1.0);
    let scale = crate::render::colormap::ColorScale::for_range(ColorMap::Viridis, lo, hi);
    let mut positions = Vec::with_capacity(cols * rows);
    let mut colors = Vec::with_capacity(cols * rows);
    for r in 0..rows {
        for c in 0..cols {
            let (j, i) = ((r * stride).min(ny - 1), (c * stride).min(nx - 1));
            let h = heights[[j, i]];
            positions.push([
                (i as f64 * dx * 1e6) as f32,
                (j as f64 * dy * 1e6) as f32,
                ((h - lo) * 1e6 * exaggeration) as f32,
            ]);
            let [red, green, blue] = scale.rgb(h);
            colors.push(rerun::Color::from_rgb(red, green, blue));
        }
    }
    let mut triangles = Vec::with_capacity(2 * cols * rows);
    for r in 0..rows - 1 {
        for c in 0..cols - 1 {
            let at = |r: usize, c: usize| (r * cols + c) as u32;
            triangles.push([at(r, c), at(r, c + 1), at(r + 1, c + 1)]);
            triangles.push([at(r, c), at(r + 1, c + 1), at(r + 1, c)]);
        }
    }
    stream.log_static("topography", &rerun::ViewCoordinates::RIGHT_HAND_Z_UP())?;
    stream.log_static(
        "topography/surface",
        &rerun::Mesh3D::new(positions)
            .with_triangle_indices(triangles)
            .with_vertex_colors(colors),
    )?;
    Ok(exaggeration)
}

/// The load sweep of a rough scene: each load solved, its pressure and spots logged on the
/// `load` timeline in the view framed by `frame`, with the charts against the load; returns
/// the number of steps.
fn log_load_sweep(
    stream: &RecordingStream,
    scene: &Scene,
    frame: &Frame,
    roll: Roll,
    flush: &dyn Fn() -> Result<(), RecordError>,
) -> Result<usize, RecordError> {
    let Some(sweep) = &scene.sweep else {
        return Ok(0);
    };
    let problem = rough_study::problem(scene).ok_or_else(|| rerun_error("no rough contact"))?;
    // Every load is solved first: the colour range covers the pressures of them all.
    let mut solutions = Vec::with_capacity(sweep.values.len());
    for &load in &sweep.values {
        let mut step = problem.clone();
        step.control = Control::Load { newtons: load };
        solutions.push(rough::solve(&step, &mut |_, _| {}).map_err(rerun_error)?);
    }
    let pressures_mpa: Vec<f64> = solutions
        .iter()
        .flat_map(|s| s.pressure_pa.iter().map(|p| p * 1e-6))
        .collect();
    let (top, clipped) = super::robust_top(&pressures_mpa);
    let surface = scene
        .surface
        .as_ref()
        .ok_or_else(|| rerun_error("no surface"))?;
    let (x, y) = surface_axes_um(&surface.heights, roll);
    let range = (0.0, super::round_up(1.03 * top).max(1e-9));
    let hardness_mpa = scene
        .contact
        .rough
        .and_then(|r| r.hardness_pa)
        .map(|h| h * 1e-6);
    let steps = sweep.values.len();
    let values = super::value_timeline(scene);
    for (path, name, colour) in [
        ("series/max_pressure_mpa", "largest p (MPa)", PALETTE[1]),
        ("series/contact_fraction", "real area A/A0", PALETTE[0]),
        ("series/spots", "contact spots", PALETTE[2]),
        ("series/load_n", "W (N)", PALETTE[6]),
    ] {
        stream.log_static(path, &super::series_line(name, colour))?;
    }
    let mut last = None;
    for (k, (solution, &load)) in solutions.iter().zip(&sweep.values).enumerate() {
        stream.set_time_sequence("load", super::step_time(k));
        if let Some(values) = &values {
            stream.set_time_sequence(values.timeline()?, values.values[k]);
        }
        let pressure_pa = roll.apply(solution.pressure_pa.view());
        let indicator = pressure_pa.mapv(|p| if p > 0.0 { 1.0 } else { 0.0 });
        let outlines = crate::render::contour_lines(indicator.view(), &x, &y, 0.5);
        let text = format!(
            "{}: {} spots, {} % in contact",
            sweep.describe(k, scene),
            solution.spots,
            section::short(100.0 * solution.contact_fraction)
        );
        let figure = pressure_figure(Panel {
            subtitle: text.clone(),
            x,
            z: y,
            values: pressure_pa.mapv(|p| p * 1e-6),
            traction: Vec::new(),
            half_width: 0.0,
            outlines,
            scale: None,
            peak: None,
            axes: None,
        });
        let shown = section::displayed(&figure, &figure.panels[0]);
        if k == 0 {
            log_map_static(stream, "contact", frame, &figure, &shown, Some(range))?;
        }
        let mut title = super::step_text(k, steps, &text);
        let max_mpa = solution.max_pressure_pa * 1e-6;
        // The solver caps the pressure at the hardness: a pressure at the cap is where the
        // elastic one would exceed it.
        if let Some(hardness) = hardness_mpa.filter(|_| solution.plastic_cells > 0) {
            title.push_str(&format!(
                ": {} cells at the hardness {} MPa (the elastic pressure would exceed it)",
                solution.plastic_cells,
                section::short(hardness)
            ));
        }
        if clipped && max_mpa > range.1 {
            title.push_str(&format!(
                " (beyond {} MPa in the top colour)",
                section::short(range.1)
            ));
        }
        log_map_step(
            stream,
            When::Step,
            "contact",
            frame,
            &figure,
            &shown,
            range,
            &title,
        )?;
        stream.log("log", &rerun::TextLog::new(title.clone()))?;
        stream.log("series/load_n", &rerun::Scalars::new([load]))?;
        stream.log(
            "series/contact_fraction",
            &rerun::Scalars::new([solution.contact_fraction]),
        )?;
        stream.log(
            "series/spots",
            &rerun::Scalars::new([solution.spots as f64]),
        )?;
        stream.log(
            "series/max_pressure_mpa",
            &rerun::Scalars::new([solution.max_pressure_pa * 1e-6]),
        )?;
        flush()?;
        last = Some((figure, shown, title));
    }
    // On the timeline `depth` the load's map shows the last load, not nothing (a view shows
    // only what is logged on the timeline the time panel is on).
    if let Some((figure, shown, title)) = last {
        disable_load_timelines(stream, scene);
        stream.set_time_sequence("depth", super::step_time(0));
        log_map_step(
            stream,
            When::Step,
            "contact",
            frame,
            &figure,
            &shown,
            range,
            &format!("{title} (the last load: the timeline \"load\" steps through the loads)"),
        )?;
        stream.disable_timeline("depth");
        flush()?;
    }
    Ok(solutions.len())
}

/// Stops logging on the load sweep's timelines (the step's and the load's own).
pub(super) fn disable_load_timelines(stream: &RecordingStream, scene: &Scene) {
    stream.disable_timeline("load");
    if let Some(values) = super::value_timeline(scene) {
        if let Ok(name) = values.timeline() {
            stream.disable_timeline(name);
        }
    }
}

/// How the pressure's colours are scaled in the view "pressure vs W" (issue 23, item 1).
fn contact_colours() -> String {
    format!(
        "run to the {} % quantile of all loads' pressures (one cell's spike does not set them; a pressure beyond is drawn in the top colour, its step's title says so and the labelled maximum keeps its value)",
        section::short(crate::render::ROBUST_QUANTILE * 100.0)
    )
}

/// The load of a solved contact and, with a load sweep, which step it is:
/// `W = 1 N (step 7 of 10)`, or `W = 0.8 N (not one of the swept loads)`.
pub(super) fn load_text(scene: &Scene, solution: &RoughSolution) -> String {
    let load = format!("W = {} N", crate::scene::compact(solution.load_n));
    let Some(sweep) = scene
        .sweep
        .as_ref()
        .filter(|s| s.parameter == crate::scene::SweepParameter::Load)
    else {
        return load;
    };
    match sweep
        .values
        .iter()
        .position(|&w| (w - solution.load_n).abs() <= 1e-9 * w.abs())
    {
        Some(k) => format!(
            "{load} ({})",
            super::step_text(k, sweep.values.len(), "").trim_end_matches(": ")
        ),
        None => format!("{load} (not one of the swept loads)"),
    }
}

/// The longest tab name of a map view: seven tabs of this many characters fit side by side in
/// the main area of the stock viewer's default window (issue 23, item 4).
const TAB_NAME_CHARS: usize = 16;

/// A map's tab name: its figure title is a sentence ("Contact pressure", "von Mises stress in
/// the xz section through the report's largest σvM"), too long for a tab, so the sheet's own
/// maps are named by what they show ("topography", "pressure", "σvM xz section", "σvM at
/// depth", the symbol taken from the colour bar's caption); any other map by its title, cut
/// to [`TAB_NAME_CHARS`] with an ellipsis (the full title stays in the view's own caption).
fn tab_name(map: &Figure) -> String {
    let title = map.title.as_str();
    let symbol = map
        .value_label
        .split(" (")
        .next()
        .unwrap_or("")
        .trim()
        .to_string();
    if title.starts_with("Topography") {
        return "topography".into();
    }
    if title.starts_with("Contact pressure") {
        return "pressure".into();
    }
    if title.contains("in the xz section") {
        return format!("{symbol} xz section");
    }
    if title.contains("at the depth of") {
        return format!("{symbol} at depth");
    }
    if title.chars().count() <= TAB_NAME_CHARS {
        return title.to_string();
    }
    let cut: String = title.chars().take(TAB_NAME_CHARS - 1).collect();
    format!("{}…", cut.trim_end())
}

/// The frames of the 2-D views that the layout shows.
struct Frames<'a> {
    maps: &'a [Frame],
    contact: Option<&'a Frame>,
    depth: Option<&'a Frame>,
    /// The timeline the time panel opens on.
    timeline: Option<String>,
}

/// The layout: the map views (for a rough scene first the pressure against load and the
/// stress through depth), the sheet image (the figure, with its colour bars and charts) in
/// tabs; beside them the charts against load (one quantity each) over the report, the 3-D
/// topography and the steps.
fn plan_layout(maps: &[&Figure], scene: &Scene, frames: &Frames<'_>) -> Layout {
    let view2d = |name: String, origin: &str, frame: Option<&Frame>| {
        Node::View(View::new(
            ViewKind::Spatial2D(frame.map(|f| f.bounds)),
            name,
            origin,
        ))
    };
    let mut main: Vec<Node> = Vec::new();
    if let Some(frame) = frames.contact {
        main.push(view2d(
            "pressure vs W (MPa)".to_string(),
            "contact",
            Some(frame),
        ));
    }
    if let Some(frame) = frames.depth {
        main.push(view2d(
            format!(
                "{} vs depth",
                scene
                    .figure
                    .stress_unit
                    .label(scene.figure.quantity.symbol())
            ),
            "depth",
            Some(frame),
        ));
    }
    main.push(view2d("figure".into(), "sheet", None));
    for (k, (map, frame)) in maps.iter().zip(frames.maps).enumerate() {
        main.push(view2d(tab_name(map), &format!("maps/{k}"), Some(frame)));
    }
    let main = Node::Tabs(main, 0);
    let mut side = vec![Node::View(View::new(
        ViewKind::TextDocument,
        "report",
        "description",
    ))];
    side.push(Node::View(View::new(
        ViewKind::Spatial3D(None),
        "topography",
        "topography",
    )));
    // Two tab groups of charts whose short names all fit (issue 23, item 4): the stresses
    // against depth and the peak pressure, then the real area and the spots.
    let mut plots = Vec::new();
    let mut counts = Vec::new();
    if frames.depth.is_some() {
        plots.push(view2d("σvM, τ vs z".into(), "charts/depth_maxima", None));
    }
    if frames.contact.is_some() {
        // Native plots against the load's own timeline (hover, zoom).
        let plot = |name: &str, path: &str| {
            Node::View(View::new(ViewKind::TimeSeries, name, "series").with_contents(&[path]))
        };
        plots.push(plot("peak p (MPa) vs W", "$origin/max_pressure_mpa"));
        counts.push(plot("A/A0 vs W", "$origin/contact_fraction"));
        counts.push(plot("spots vs W", "$origin/spots"));
        side.push(Node::View(View::new(ViewKind::TextLog, "steps", "log")));
    }
    let side = match (plots.is_empty(), counts.is_empty()) {
        (true, _) => Node::Tabs(side, 0),
        (false, true) => Node::Vertical(
            vec![Node::Tabs(plots, 0), Node::Tabs(side, 0)],
            vec![1.0, 1.0],
        ),
        (false, false) => Node::Vertical(
            vec![
                Node::Tabs(plots, 0),
                Node::Tabs(counts, 0),
                Node::Tabs(side, 0),
            ],
            vec![1.0, 1.0, 1.1],
        ),
    };
    Layout {
        root: Node::Horizontal(vec![main, side], vec![super::MAIN_SHARE, super::SIDE_SHARE]),
        timeline: frames.timeline.clone(),
    }
}

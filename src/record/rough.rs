//! Recordings of surface and rough scenes.
//!
//! ## Entities
//! - `description`: the scene's report (the surface's statistics, or the solved contact's).
//! - `sheet`: the rendered figure (with its colour bars and charts) as an image.
//! - `topography`: the height map as a 3-D mesh coloured by height (heights exaggerated so
//!   that the tallest relief is a fifth of the map's width; the factor is in the description).
//! - `maps/<k>/field`: the sheet's maps (topography, pressure, sections) as depth images whose
//!   values read on hover, placed in um, with outlines and the labelled maximum.
//! - Rough scenes with a `[sweep]` of the load, on the timeline `load`: `contact/pressure`
//!   (MPa) and `contact/spots` (outlines) at every load, and the series
//!   `series/contact_fraction`, `series/spots`, `series/max_pressure_mpa`.
//! - Rough scenes, on the timeline `depth` (um): `depth/field`, the sheet's stress quantity in
//!   planes parallel to the surface from the surface down, the field stepping through depth.

use rerun::RecordingStream;

use super::layout::{Layout, Node, View, ViewKind};
use super::{grid_maximum, log_panel_placement, rerun_colormap, RecordError, Summary};
use crate::contact::rough::{self, Control};
use crate::field::{self, Axis, Plane, Section};
use crate::figure::{self, Drawing};
use crate::render::chart::Cell;
use crate::render::{ColorMap, Figure};
use crate::rough_report::{search_depth_m, ContactReport};
use crate::scene::{ContactKind, Scene};
use crate::study::rough::{self as rough_study, REFERENCE_LENGTH_M};
use crate::surface::HeightMap;

fn rerun_error(e: impl std::fmt::Display) -> RecordError {
    RecordError::Rerun(e.to_string())
}

/// Records a surface or rough scene (module doc). Its grid rows are not reported as progress
/// (how many there are depends on the solved contact); [`super::rows`] counts none.
pub fn record(
    scene: &Scene,
    stream: &RecordingStream,
    flush: &dyn Fn() -> Result<(), RecordError>,
) -> Result<Summary, RecordError> {
    let on_row = &|| {};
    let surface = scene
        .surface
        .as_ref()
        .ok_or_else(|| rerun_error("the scene has no surface"))?;
    let drawing = figure::draw(scene, on_row).map_err(rerun_error)?;
    let Drawing::Sheet(sheet) = &drawing else {
        return Err(rerun_error("a surface scene draws a sheet"));
    };
    let png =
        crate::render::encode_png(&drawing.png().map_err(rerun_error)?).map_err(rerun_error)?;
    stream.log_static("sheet", &rerun::EncodedImage::from_file_contents(png))?;
    let exaggeration = log_topography(stream, &surface.heights)?;
    let report = match scene.contact.kind {
        ContactKind::Rough => {
            let solution = rough_study::solve(scene, &mut |_, _| {}).map_err(rerun_error)?;
            ContactReport::new(scene, &solution)
                .map_err(rerun_error)?
                .text(scene)
        }
        _ => {
            let c = crate::rough_figure::characterise(scene).map_err(rerun_error)?;
            let e_star = scene.contact.rough.and_then(|r| r.e_star_pa);
            let hardness = scene.contact.rough.and_then(|r| r.hardness_pa);
            crate::surface_report::SurfaceReport::new(&c, e_star, hardness)
                .text(&c, &surface.source)
        }
    };
    stream.log_static(
        "description",
        &rerun::TextDocument::from_markdown(format!(
            "# {}\n\n```text\n{report}```\n\nThe `topography` mesh shows heights {exaggeration:.0} times exaggerated. \
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
            Cell::Chart(_) => None,
        })
        .collect();
    for (k, map) in maps.iter().enumerate() {
        log_map(stream, &format!("maps/{k}"), map, None, true, true)?;
    }
    super::layout::send(stream, &plan_layout(&maps, scene))?;
    flush()?;
    let mut steps = 1;
    if scene.contact.kind == ContactKind::Rough {
        steps = log_load_sweep(stream, scene, flush)?.max(1);
        log_depth_steps(stream, scene, on_row, flush)?;
    }
    Ok(Summary {
        steps,
        panels: maps.len(),
        volume_triangles: 0,
    })
}

/// One map figure's single panel at `base`: field (depth image), placement, outlines, maximum.
fn log_map(
    stream: &RecordingStream,
    base: &str,
    map: &Figure,
    range: Option<(f64, f64)>,
    timeless: bool,
    place: bool,
) -> Result<(), RecordError> {
    let log = |path: String, archetype: &dyn rerun::AsComponents| {
        if timeless {
            stream.log_static(path, archetype)
        } else {
            stream.log(path, archetype)
        }
    };
    let panel = &map.panels[0];
    let colormap = panel.scale.as_ref().map_or(map.colormap, |s| s.colormap);
    let (lo, hi) = range.unwrap_or_else(|| {
        panel
            .values
            .iter()
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
                (a.min(v), b.max(v))
            })
    });
    let image = rerun::DepthImage::try_from(panel.values.mapv(|v| v as f32))
        .map_err(rerun_error)?
        .with_meter(1.0)
        .with_colormap(rerun_colormap(colormap))
        .with_depth_range(rerun::components::ValueRange::new(lo, hi.max(lo + 1e-12)));
    if place {
        log_panel_placement(stream, &format!("{base}/field"), panel)?;
    }
    log(format!("{base}/field"), &image)?;
    if !panel.outlines.is_empty() {
        let strips: Vec<Vec<[f32; 2]>> = panel
            .outlines
            .iter()
            .map(|line| line.iter().map(|&(u, v)| [u as f32, v as f32]).collect())
            .collect();
        log(
            format!("{base}/outline"),
            &rerun::LineStrips2D::new(strips)
                .with_colors([rerun::Color::from_rgb(255, 255, 255)])
                .with_radii([rerun::Radius::new_ui_points(0.75)]),
        )?;
    }
    if let Some(((iv, iu), value)) = grid_maximum(&panel.values) {
        let (u, v) = (panel.x.value(iu), panel.z.value(iv));
        log(
            format!("{base}/maximum"),
            &rerun::Points2D::new([[u as f32, v as f32]])
                .with_radii([rerun::Radius::new_ui_points(5.0)])
                .with_colors([rerun::Color::from_rgb(255, 255, 255)])
                .with_labels([format!("max {value:.4} ({})", panel.subtitle)]),
        )?;
    }
    Ok(())
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
/// `load` timeline; returns the number of steps.
fn log_load_sweep(
    stream: &RecordingStream,
    scene: &Scene,
    flush: &dyn Fn() -> Result<(), RecordError>,
) -> Result<usize, RecordError> {
    let Some(sweep) = &scene.sweep else {
        return Ok(0);
    };
    let problem = rough_study::problem(scene).ok_or_else(|| rerun_error("no rough contact"))?;
    let mut solutions = Vec::with_capacity(sweep.values.len());
    for &load in &sweep.values {
        let mut step = problem.clone();
        step.control = Control::Load { newtons: load };
        solutions.push(rough::solve(&step, &mut |_, _| {}).map_err(rerun_error)?);
    }
    let highest = solutions
        .iter()
        .map(|s| s.max_pressure_pa)
        .fold(0.0, f64::max)
        * 1e-6;
    let surface = scene
        .surface
        .as_ref()
        .ok_or_else(|| rerun_error("no surface"))?;
    let [dx, dy] = surface.heights.spacing_m();
    for (k, (solution, &load)) in solutions.iter().zip(&sweep.values).enumerate() {
        stream.set_time_sequence("load", k as i64);
        let [ny, nx] = surface.heights.shape();
        let x = Axis::new(0.5 * dx * 1e6, (nx as f64 - 0.5) * dx * 1e6, nx);
        let y = Axis::new(0.5 * dy * 1e6, (ny as f64 - 0.5) * dy * 1e6, ny);
        let indicator = solution
            .pressure_pa
            .mapv(|p| if p > 0.0 { 1.0 } else { 0.0 });
        let outlines = crate::render::contour_lines(indicator.view(), &x, &y, 0.5);
        let figure = Figure {
            title: "pressure".into(),
            panels: vec![crate::render::Panel {
                subtitle: format!(
                    "W = {load:.4} N: {} spots, {:.2} % in contact",
                    solution.spots,
                    100.0 * solution.contact_fraction
                ),
                x,
                z: y,
                values: solution.pressure_pa.mapv(|p| p * 1e-6),
                traction: Vec::new(),
                half_width: 0.0,
                outlines,
                scale: None,
            }],
            value_label: "p (MPa)".into(),
            x_label: "x (µm)".into(),
            z_label: "y (µm)".into(),
            vertical_is_depth: false,
            traction_label: String::new(),
            colormap: ColorMap::Inferno,
            levels: crate::render::Levels::Count(0),
            mark: crate::render::Mark::Max,
            panel_width_px: 400,
        };
        log_map(
            stream,
            "contact",
            &figure,
            Some((0.0, highest)),
            false,
            k == 0,
        )?;
        stream.log(
            "log",
            &rerun::TextLog::new(format!("step {k}: {}", figure.panels[0].subtitle)),
        )?;
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
    }
    Ok(solutions.len())
}

/// The scene's stress quantity in planes parallel to the surface, stepping down on the
/// `depth` timeline (um).
fn log_depth_steps(
    stream: &RecordingStream,
    scene: &Scene,
    on_row: &(dyn Fn() + Sync),
    flush: &dyn Fn() -> Result<(), RecordError>,
) -> Result<(), RecordError> {
    let solution = rough_study::solve(scene, &mut |_, _| {}).map_err(rerun_error)?;
    let stresses =
        rough_study::stress_solution(&solution, scene.contact.friction, scene.contact.poisson)
            .map_err(rerun_error)?;
    let [dx, dy] = solution.spacing_m;
    let (ny, nx) = solution.pressure_pa.dim();
    let (ax, ay) = (dx / REFERENCE_LENGTH_M, dy / REFERENCE_LENGTH_M);
    let cell = ax.min(ay);
    let deepest = search_depth_m(&solution) / REFERENCE_LENGTH_M;
    let layers = ((deepest / cell).ceil() as usize).clamp(1, 24);
    let step = (deepest / layers as f64).max(cell);
    let quantity = scene.figure.quantity;
    let per_pa = 1.0 / scene.figure.stress_unit.pascals(1.0);
    let mut maps = Vec::with_capacity(layers + 1);
    for k in 0..=layers {
        let z = k as f64 * step;
        let plane = Plane {
            section: Section::Xy { z },
            u: Axis::new(0.5 * ax, (nx as f64 - 0.5) * ax, nx),
            v: Axis::new(0.5 * ay, (ny as f64 - 0.5) * ay, ny),
        };
        let values = field::evaluate(&stresses, &plane, &[quantity], on_row)?;
        maps.push((
            z,
            values
                .values
                .index_axis(ndarray::Axis(1), 0)
                .mapv(|v| v * 1e6 * per_pa),
        ));
    }
    let (lo, hi) = maps
        .iter()
        .flat_map(|(_, m)| m.iter().copied())
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    for (k, (z, values)) in maps.into_iter().enumerate() {
        stream.set_time_sequence("depth", k as i64);
        let figure = Figure {
            title: quantity.description().into(),
            panels: vec![crate::render::Panel {
                subtitle: format!("z = {:.2} µm", z * REFERENCE_LENGTH_M * 1e6),
                x: Axis::new(0.5 * dx * 1e6, (nx as f64 - 0.5) * dx * 1e6, nx),
                z: Axis::new(0.5 * dy * 1e6, (ny as f64 - 0.5) * dy * 1e6, ny),
                values,
                traction: Vec::new(),
                half_width: 0.0,
                outlines: Vec::new(),
                scale: None,
            }],
            value_label: scene.figure.stress_unit.label(quantity.symbol()),
            x_label: "x (µm)".into(),
            z_label: "y (µm)".into(),
            vertical_is_depth: false,
            traction_label: String::new(),
            colormap: scene.figure.colormap,
            levels: crate::render::Levels::Count(0),
            mark: crate::render::Mark::Max,
            panel_width_px: 400,
        };
        log_map(stream, "depth", &figure, Some((lo, hi)), false, k == 0)?;
        stream.log(
            "series/depth_um",
            &rerun::Scalars::new([z * REFERENCE_LENGTH_M * 1e6]),
        )?;
        flush()?;
    }
    Ok(())
}

/// The layout: the sheet image (the figure, with its colour bars and charts) and the maps
/// take the window, the 3-D topography and the report in tabs beside them; for a rough load
/// sweep the pressure against load and the stress through depth come first, with one plot per
/// series.
fn plan_layout(maps: &[&Figure], scene: &Scene) -> Layout {
    let view2d =
        |name: String, origin: &str| Node::View(View::new(ViewKind::Spatial2D(None), name, origin));
    let mut main: Vec<Node> = Vec::new();
    let rough = scene.contact.kind == ContactKind::Rough;
    if rough && scene.sweep.is_some() {
        main.push(view2d("pressure (MPa) against load".into(), "contact"));
    }
    if rough {
        main.push(view2d(
            format!(
                "{} stepping through depth",
                scene
                    .figure
                    .stress_unit
                    .label(scene.figure.quantity.symbol())
            ),
            "depth",
        ));
    }
    main.push(view2d("figure".into(), "sheet"));
    for (k, map) in maps.iter().enumerate() {
        main.push(view2d(map.title.clone(), &format!("maps/{k}")));
    }
    let main = Node::Tabs(main, 0);
    let mut side = vec![Node::View(View::new(
        ViewKind::TextDocument,
        "report",
        "description",
    ))];
    side.push(Node::View(View::new(
        ViewKind::Spatial3D(None),
        "topography (heights exaggerated)",
        "topography",
    )));
    let mut plots = Vec::new();
    if rough && scene.sweep.is_some() {
        // One plot per quantity: their units differ.
        for (name, path) in [
            ("real area fraction", "series/contact_fraction"),
            ("contact spots", "series/spots"),
            ("max pressure (MPa)", "series/max_pressure_mpa"),
        ] {
            plots.push(Node::View(View::new(ViewKind::TimeSeries, name, path)));
        }
        side.push(Node::View(View::new(ViewKind::TextLog, "steps", "log")));
    }
    let side = if plots.is_empty() {
        Node::Tabs(side, 0)
    } else {
        Node::Vertical(
            vec![Node::Tabs(plots, 0), Node::Tabs(side, 0)],
            vec![1.0, 1.0],
        )
    };
    Layout {
        root: Node::Horizontal(vec![main, side], vec![2.6, 1.0]),
        timeline: rough.then(|| {
            if scene.sweep.is_some() {
                "load"
            } else {
                "depth"
            }
            .to_string()
        }),
    }
}

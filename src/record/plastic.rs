//! Recordings of `[plasticity]` scenes: the elastic-plastic point contact loaded and unloaded
//! step by step, from the study solved once ([`crate::study::plastic`], whose history keeps
//! each step's section on `y = 0`).
//!
//! ## Entities
//! - `description`: the `plastic` report and how to read the views.
//! - `sheet`: the rendered sheet ([`crate::figure::plastic`]) as an image.
//! - On the timeline `load step` (steps numbered from 1, loading then unloading):
//!   - `plastic/strain`: the equivalent plastic strain (× 10³) in the section `y = 0` (one colour
//!     range for all steps), the plastic zone (`εp = 1e-5`) outlined, the step's pressure
//!     `p/Y` in the strip above (its height fixed by the largest pressure of all steps);
//!   - `plastic/von_mises`: von Mises of the total stress over `Y` in the same section (one
//!     range), the yield line (`σvM = 0.995 (Y + h εp)`) outlined;
//!   - `curves/load_approach`, `curves/mean_pressure`: the sheet's two charts drawn with the
//!     steps so far (the curves grow step by step on fixed axes);
//!   - `series/...`: the load over first yield's, the largest and mean pressure over `Y`, the
//!     contact radius over `a_H` and the largest plastic strain, against the step;
//!   - `log`: one line per step.
//!
//! A line contact (plane strain) records the same over its half-width `b`, without the mean
//! pressure (the sheet has none: [`crate::figure::plastic`]), its load per unit length.

use rerun::RecordingStream;

use super::layout::{Layout, Node, View, ViewKind};
use super::rough::{main_view_px, rerun_error};
use super::section::{self, Changing, Fixed, Frame, Notation, When};
use super::{RecordError, Summary};
use crate::figure::plastic::{
    axes, load_approach_chart, mean_pressure_chart, outline, YIELD_LINE_FRACTION,
};
use crate::plasticity::loading::PLASTIC_ZONE_STRAIN;
use crate::render::chart::{chart_png, PALETTE};
use crate::render::{ColorMap, Figure, Levels, Mark, Panel, TractionSample};
use crate::report::plastic::PlasticReport;
use crate::scene::Scene;
use crate::study::plastic::history::first_yield;
use crate::study::plastic::PlasticStudy;

/// The timeline of the steps.
pub const TIMELINE: &str = "load step";

/// A section map over `unit` (`a_H`, or a line's `b`) with the pressure in the strip above.
fn section_figure(
    title: &str,
    value_label: &str,
    colormap: ColorMap,
    panel: Panel,
    unit: &str,
) -> Figure {
    Figure {
        title: title.into(),
        panels: vec![panel],
        value_label: value_label.into(),
        x_label: format!("x/{unit}"),
        z_label: format!("z/{unit}"),
        vertical_is_depth: true,
        traction_label: "p/Y".into(),
        colormap,
        levels: Levels::Count(0),
        mark: Mark::Max,
        panel_width_px: 800,
    }
}

/// A chart as an encoded PNG.
fn chart_image(chart: &crate::render::chart::Chart) -> Result<rerun::EncodedImage, RecordError> {
    let png =
        crate::render::encode_png(&chart_png(chart).map_err(rerun_error)?).map_err(rerun_error)?;
    Ok(rerun::EncodedImage::from_file_contents(png))
}

/// Records a `[plasticity]` scene's study; a `live` stream opens following the newest step.
pub fn record(
    scene: &Scene,
    study: &PlasticStudy,
    stream: &RecordingStream,
    live: bool,
    flush: &dyn Fn() -> Result<(), RecordError>,
) -> Result<Summary, RecordError> {
    stream.set_log_time_enabled(false);
    let sections = crate::study::plastic::history::sheet_sections(study);
    let title = scene.title.clone().unwrap_or_else(|| scene.name.clone());
    let sheet = crate::figure::plastic::plastic_sheet(&title, study, &sections);
    let png =
        crate::render::encode_png(&crate::render::chart::sheet_png(&sheet).map_err(rerun_error)?)
            .map_err(rerun_error)?;
    stream.log_static("sheet", &rerun::EncodedImage::from_file_contents(png))?;
    let report = PlasticReport::new(study).text(study);
    stream.log_static(
        "description",
        &rerun::TextDocument::from_markdown(format!(
            "# {}\n\n```text\n{report}```\n\nThe time panel steps through the load steps: loading, then unloading. The maps are the section y = 0 through the contact's axis (a line's x–z plane), in units of Hertz's contact radius a_H (a line's half-width b), depth downwards; hovering a map shows `Val`, its value in the unit of its title (the viewer also prints it as a \"Depth\" in m: ignore that line).\n\n**Reading the views.** `plastic strain`: the equivalent plastic strain, the plastic zone (εp > 1e-5) outlined, the step's pressure p/Y above the surface. `von Mises`: the total stress over Y, the yield line (σvM at the current yield stress Y + h εp) outlined; after unloading it is the residual stress. `load–approach` and `mean pressure`: the sheet's charts with the steps so far.",
            sheet.title
        )),
    )?;

    let y = study.spec.yield_strength_pa;
    let h = study.spec.hardening_modulus_pa;
    let a = study.hertz.size_m();
    let line = study.kind == crate::study::plastic::PlasticKind::Line;
    let unit = crate::figure::plastic::length_unit(study);
    let (x_axis, z_axis) = axes(study);
    let history = &study.history;
    let steps = history.points.len();
    let strain_top = history
        .sections
        .iter()
        .flat_map(|s| s.plastic_strain.iter())
        .fold(PLASTIC_ZONE_STRAIN, |m: f64, &v| m.max(v));
    // In units of 1e-3: the colour bar's ticks read 1, 2, 3 rather than 0.0 (εp ~ 1e-3).
    let strain_range = (0.0, super::round_up(1.03 * strain_top * 1e3));
    let von_mises_top = history
        .sections
        .iter()
        .flat_map(|s| s.von_mises_pa.iter())
        .fold(0.0, |m: f64, &v| m.max(v / y));
    let von_mises_range = (0.0, super::round_up(1.03 * von_mises_top).max(1e-9));
    let pressure_top = history
        .points
        .iter()
        .fold(0.0, |m: f64, p| m.max(p.max_pressure_pa / y));

    let view_px = main_view_px(true);
    let panel = |values: ndarray::Array2<f64>, traction, outlines| Panel {
        subtitle: String::new(),
        x: x_axis,
        z: z_axis,
        values,
        traction,
        half_width: 0.0,
        outlines,
        scale: None,
        peak: None,
        axes: None,
    };
    let blank = ndarray::Array2::zeros((z_axis.count, x_axis.count));
    let strip: Vec<TractionSample> = study
        .x_m
        .iter()
        .map(|&x| TractionSample {
            x: x / a,
            p: pressure_top,
            q: 0.0,
        })
        .collect();
    let strain_map = section_figure(
        "plastic strain",
        "εp × 10³",
        ColorMap::Viridis,
        panel(blank.clone(), strip.clone(), Vec::new()),
        unit,
    );
    let von_mises_map = section_figure(
        "von Mises",
        "σvM/Y",
        ColorMap::Magma,
        panel(blank, strip, Vec::new()),
        unit,
    );
    let frame_of = |map: &Figure, range: (f64, f64)| {
        let shown = section::displayed(map, &map.panels[0]);
        let ticks = section::longest_tick(range).max(6);
        (Frame::new(&shown, true, view_px, ticks), shown)
    };
    let (strain_frame, strain_shown) = frame_of(&strain_map, strain_range);
    let (von_mises_frame, von_mises_shown) = frame_of(&von_mises_map, von_mises_range);
    for (base, frame, map, shown, range) in [
        (
            "plastic/strain",
            &strain_frame,
            &strain_map,
            &strain_shown,
            strain_range,
        ),
        (
            "plastic/von_mises",
            &von_mises_frame,
            &von_mises_map,
            &von_mises_shown,
            von_mises_range,
        ),
    ] {
        let caption = section::panel_caption(map, shown);
        section::log_static(
            stream,
            base,
            frame,
            shown,
            &Fixed {
                map: section::panel_colormap(map, shown),
                caption: &caption,
                range: Some(range),
                surface: true,
                material: &[],
            },
        )?;
    }
    let series: [(&str, &str, [u8; 3]); 5] = [
        ("series/load_over_first_yield", "W/W_Y", PALETTE[4]),
        ("series/max_pressure_over_y", "p_max/Y", PALETTE[0]),
        ("series/mean_pressure_over_y", "p_m/Y", PALETTE[1]),
        (
            "series/contact_radius_over_a",
            if line {
                "half-width/b"
            } else {
                "√(A/π)/a_H"
            },
            PALETTE[2],
        ),
        ("series/max_plastic_strain", "largest εp", PALETTE[3]),
    ];
    for (path, name, colour) in &series {
        stream.log_static(*path, &super::series_line(*name, *colour))?;
    }
    super::layout::send(stream, &plan_layout(line), live)?;
    flush()?;

    let (load_y, _) = first_yield(study);
    for (k, (point, cut)) in history.points.iter().zip(&history.sections).enumerate() {
        stream.set_time_sequence(TIMELINE, super::step_time(k));
        let phase = if point.unloading {
            "unloading"
        } else {
            "loading"
        };
        let text = format!(
            "{phase}, W = {} {} = {} W_Y: p_max {} Y, εp max {}",
            section::short(point.load_n),
            if line { "N/m" } else { "N" },
            section::short(point.load_n / load_y),
            section::short(point.max_pressure_pa / y),
            section::short(point.max_plastic_strain)
        );
        let title = super::step_text(k, steps, &text);
        let traction: Vec<TractionSample> = study
            .x_m
            .iter()
            .zip(&cut.pressure_pa)
            .map(|(&x, &p)| TractionSample {
                x: x / a,
                p: p / y,
                q: study.friction * p / y,
            })
            .collect();
        let zone = outline(&cut.plastic_strain, &x_axis, &z_axis, PLASTIC_ZONE_STRAIN);
        let ratio = ndarray::Zip::from(&cut.von_mises_pa)
            .and(&cut.plastic_strain)
            .map_collect(|&v, &k| v / (y + h * k));
        let yield_line = outline(&ratio, &x_axis, &z_axis, YIELD_LINE_FRACTION);
        let maps = [
            (
                "plastic/strain",
                &strain_frame,
                &strain_map,
                cut.plastic_strain.mapv(|v| v * 1e3),
                zone,
                strain_range,
            ),
            (
                "plastic/von_mises",
                &von_mises_frame,
                &von_mises_map,
                cut.von_mises_pa.mapv(|v| v / y),
                yield_line,
                von_mises_range,
            ),
        ];
        for (base, frame, template, values, outlines, range) in maps {
            let mut map = template.clone();
            map.panels[0] = panel(values, traction.clone(), outlines);
            let shown = section::displayed(&map, &map.panels[0]);
            section::log_step(
                stream,
                When::Step,
                base,
                frame,
                &map,
                &shown,
                range,
                &Changing {
                    title: &title,
                    notation: &Notation::of(&map, &shown),
                    mark: map.mark,
                    material: &[],
                    values: false,
                    traction_peak: Some(pressure_top),
                },
            )?;
        }
        stream.log(
            "curves/load_approach",
            &chart_image(&load_approach_chart(study, k + 1))?,
        )?;
        if !line {
            stream.log(
                "curves/mean_pressure",
                &chart_image(&mean_pressure_chart(study, k + 1))?,
            )?;
        }
        let scalars = [
            ("series/load_over_first_yield", point.load_n / load_y),
            ("series/max_pressure_over_y", point.max_pressure_pa / y),
            ("series/mean_pressure_over_y", point.mean_pressure_pa / y),
            ("series/contact_radius_over_a", point.contact_radius_m / a),
            ("series/max_plastic_strain", point.max_plastic_strain),
        ];
        for (path, value) in scalars {
            stream.log(path, &rerun::Scalars::new([value]))?;
        }
        stream.log("log", &rerun::TextLog::new(title))?;
        flush()?;
    }
    Ok(Summary {
        steps,
        panels: 2,
        volume_triangles: 0,
    })
}

/// The layout: the two sections and the sheet in tabs; beside them the growing charts (a
/// line's without the mean pressure), the series against the step, and the report over the
/// steps' log.
fn plan_layout(line: bool) -> Layout {
    let view2d =
        |name: &str, origin: &str| Node::View(View::new(ViewKind::Spatial2D(None), name, origin));
    let main = vec![
        view2d("plastic strain (y = 0)", "plastic/strain"),
        view2d("von Mises / Y (y = 0)", "plastic/von_mises"),
        view2d("figure", "sheet"),
    ];
    let plot = |name: &str, paths: &[&str]| {
        Node::View(View::new(ViewKind::TimeSeries, name, "series").with_contents(paths))
    };
    let side = Node::Vertical(
        vec![
            Node::Tabs(
                if line {
                    vec![view2d("load–approach", "curves/load_approach")]
                } else {
                    vec![
                        view2d("load–approach", "curves/load_approach"),
                        view2d("mean pressure", "curves/mean_pressure"),
                    ]
                },
                0,
            ),
            Node::Tabs(
                vec![
                    plot(
                        "pressures / Y, load / W_Y",
                        &[
                            "$origin/max_pressure_over_y",
                            "$origin/mean_pressure_over_y",
                            "$origin/load_over_first_yield",
                        ],
                    ),
                    plot(
                        if line {
                            "half-width / b"
                        } else {
                            "contact radius / a_H"
                        },
                        &["$origin/contact_radius_over_a"],
                    ),
                    plot("largest εp", &["$origin/max_plastic_strain"]),
                ],
                0,
            ),
            Node::Tabs(
                vec![
                    Node::View(View::new(ViewKind::TextDocument, "report", "description")),
                    Node::View(View::new(ViewKind::TextLog, "steps", "log")),
                ],
                0,
            ),
        ],
        vec![1.3, 1.0, 0.9],
    );
    Layout {
        root: Node::Horizontal(
            vec![Node::Tabs(main, 0), side],
            vec![super::MAIN_SHARE, super::SIDE_SHARE],
        ),
        timeline: Some(TIMELINE.to_string()),
    }
}

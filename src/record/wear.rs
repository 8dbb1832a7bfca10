//! Recordings of wear scenes: the evolution of a rough contact along its sliding distance,
//! from the study solved once ([`crate::study::wear`]).
//!
//! ## Entities
//! - `description`: the `wear` report (every step's numbers) and how to read the views.
//! - `sheet`: the rendered figure (six distances, the charts) as an image.
//! - On the timeline `sliding distance` (steps numbered from 1) and on a timeline of the
//!   distance itself (`s (mm)`, or `s (µm)` for short distances, see
//!   [`super::ValueTimeline`]), which the time panel opens on:
//!   - `wear/pressure`: the contact pressure (MPa) on one colour range for all steps (to the
//!     hardness cap when reached: the capped cells in the top colour), or each step on its own
//!     when the steps' peaks span more than a decade (the colour bar at every step, the title
//!     says so); the cells at the cap outlined;
//!   - `wear/topography`: the worn heights below the unworn top (µm), one range for all, the
//!     scar outlined;
//!   - `wear/section`: the von Mises stress (MPa) in the xz section through the step's largest
//!     (one range for all steps, or each its own as the pressure's), its maximum labelled;
//!   - `series/...`: the real contact area and the scar (mm²), the plastic area (µm²), the worn
//!     volume with Archard's `k W s` (10³ µm³ or µm³), the largest pressure and von Mises
//!     stress (MPa) and, with `[thermal]`, the largest flash temperature (K), plotted natively
//!     against the distance;
//!   - `log`: one line per step.

use rerun::RecordingStream;

use super::layout::{Layout, Node, View, ViewKind};
use super::rough::{log_map_static, log_map_step, main_view_px, rerun_error};
use super::section::{self, Frame, When};
use super::{RecordError, Summary, ValueTimeline};
use crate::field::Axis;
use crate::render::chart::PALETTE;
use crate::render::{ColorMap, Figure, Levels, Mark, Panel};
use crate::report::wear::WearReport;
use crate::scene::Scene;
use crate::study::wear::{StepSection, WearKind, WearStudy};

/// The timeline of the steps.
pub const TIMELINE: &str = "sliding distance";

/// The distance of each step as an integer timeline: mm, or µm when the distances are short.
fn distance_timeline(study: &WearStudy) -> ValueTimeline {
    let last = study.steps.last().map_or(0.0, |s| s.sliding_distance_m);
    let (name, per_m) = if last >= 0.1 {
        ("s (mm)", 1e3)
    } else {
        ("s (µm)", 1e6)
    };
    ValueTimeline {
        name: name.into(),
        values: study
            .steps
            .iter()
            .map(|s| (s.sliding_distance_m * per_m).round() as i64)
            .collect(),
    }
}

/// A map figure seen from above, in µm.
fn plan_figure(
    title: &str,
    panel: Panel,
    value_label: &str,
    colormap: ColorMap,
    mark: Mark,
) -> Figure {
    Figure {
        title: title.into(),
        panels: vec![panel],
        value_label: value_label.into(),
        x_label: "x (µm)".into(),
        z_label: "y (µm)".into(),
        vertical_is_depth: false,
        traction_label: String::new(),
        colormap,
        levels: Levels::Count(0),
        mark,
        panel_width_px: 400,
    }
}

fn panel(x: Axis, z: Axis, values: ndarray::Array2<f64>, outlines: Vec<Vec<(f64, f64)>>) -> Panel {
    Panel {
        subtitle: String::new(),
        x,
        z,
        values,
        traction: Vec::new(),
        half_width: 0.0,
        outlines,
        scale: None,
        peak: None,
        axes: None,
    }
}

/// Records a wear scene's study (`sections`: its steps' sections, from
/// [`crate::study::wear::sections`]); a `live` stream opens following the newest step.
pub fn record(
    scene: &Scene,
    study: &WearStudy,
    sections: &[StepSection],
    stream: &RecordingStream,
    live: bool,
    flush: &dyn Fn() -> Result<(), RecordError>,
) -> Result<Summary, RecordError> {
    stream.set_log_time_enabled(false);
    let sheet = crate::figure::wear::wear_sheet(scene, study);
    let png =
        crate::render::encode_png(&crate::render::chart::sheet_png(&sheet).map_err(rerun_error)?)
            .map_err(rerun_error)?;
    stream.log_static("sheet", &rerun::EncodedImage::from_file_contents(png))?;
    let report = WearReport::new(study).text(scene);
    stream.log_static(
        "description",
        &rerun::TextDocument::from_markdown(format!(
            "# {}\n\n```text\n{report}```\n\nThe time panel steps through the sliding distance. Maps are in µm; hovering a map shows `Val`, its value in the unit of its title (the viewer also prints it as a \"Depth\" in m or mm: ignore that line).\n\n**Reading the views.** `pressure`: the cells at the hardness cap are outlined, and the title counts them. `worn topography`: the scar (the worn cells) is outlined. A title ending \"(own colour range)\" means that the steps' peaks span more than a decade, so each step's colours run from 0 to its own maximum: compare steps by the labelled maxima and the charts, not by colour. `worn volume`: with Archard's law, the volume summed from the local wear `k p ds` over the cells equals Archard's `k W s` (the pressure carries the load at every step), so its two lines lie on each other.",
            sheet.title
        )),
    )?;

    let first = &study.steps[0];
    let (ny, nx) = first.solution.pressure_pa.dim();
    let [dx, dy] = first.solution.spacing_m;
    let x = Axis::new(0.5 * dx * 1e6, (nx as f64 - 0.5) * dx * 1e6, nx);
    let y = Axis::new(0.5 * dy * 1e6, (ny as f64 - 0.5) * dy * 1e6, ny);
    let top = first
        .heights_m
        .iter()
        .fold(f64::NEG_INFINITY, |m, &h| m.max(h));
    let hardness_mpa = study.hardness_pa.map(|h| h * 1e-6);

    // One colour range per view for the whole evolution.
    let largest_p = study
        .steps
        .iter()
        .fold(0.0f64, |m, s| m.max(s.solution.max_pressure_pa * 1e-6));
    let p_range = match hardness_mpa {
        Some(h) if largest_p >= h * (1.0 - 1e-12) => (0.0, h),
        _ => (0.0, super::round_up(1.03 * largest_p).max(1e-9)),
    };
    let (h_lo, h_hi) = study
        .steps
        .iter()
        .flat_map(|s| s.heights_m.iter())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &h| {
            (a.min((h - top) * 1e6), b.max((h - top) * 1e6))
        });
    let h_range = (h_lo, if h_hi > h_lo { h_hi } else { h_lo + 1e-9 });
    let s_top = sections
        .iter()
        .flat_map(|s| s.values_pa.iter())
        .fold(0.0f64, |m, &v| m.max(v * 1e-6));
    let s_range = (0.0, super::round_up(1.03 * s_top).max(1e-9));
    // A view whose steps' peaks span more than a decade takes each step's range from its own
    // field (its colour bar at every step, the title says so): one range would leave the
    // worn steps one dark colour.
    let spans_a_decade = |peaks: &mut dyn Iterator<Item = f64>| {
        let (lo, hi) = peaks.fold((f64::INFINITY, 0.0f64), |(a, b), p| (a.min(p), b.max(p)));
        lo > 0.0 && hi / lo > 10.0
    };
    let own_p = spans_a_decade(&mut study.steps.iter().map(|s| s.solution.max_pressure_pa));
    let own_s = spans_a_decade(
        &mut sections
            .iter()
            .map(|s| s.values_pa.iter().fold(0.0f64, |m, &v| m.max(v))),
    );
    let own_range = |top: f64| (0.0, super::round_up(1.03 * top).max(1e-9));

    let view_px = main_view_px(true);
    let zeros = ndarray::Array2::zeros((ny, nx));
    let pressure_map = plan_figure(
        "pressure",
        panel(x, y, zeros.clone(), Vec::new()),
        "p (MPa)",
        ColorMap::Inferno,
        Mark::Max,
    );
    let topography_map = plan_figure(
        "worn topography",
        panel(x, y, zeros, Vec::new()),
        "height below the unworn top (µm)",
        ColorMap::Viridis,
        Mark::None,
    );
    let section_axes = sections.first().map(|s| {
        let um = crate::study::rough::REFERENCE_LENGTH_M * 1e6;
        (
            Axis::new(s.plane.u.min * um, s.plane.u.max * um, s.plane.u.count),
            Axis::new(s.plane.v.min * um, s.plane.v.max * um, s.plane.v.count),
        )
    });
    let section_map = |values: ndarray::Array2<f64>, subtitle: String| {
        let (u, v) = section_axes.unwrap_or((x, y));
        let mut p = panel(u, v, values, Vec::new());
        p.subtitle = subtitle;
        Figure {
            title: "σvM section".into(),
            panels: vec![p],
            value_label: "σvM (MPa)".into(),
            x_label: "x (µm)".into(),
            z_label: "z (µm)".into(),
            vertical_is_depth: true,
            traction_label: String::new(),
            colormap: scene.figure.colormap,
            levels: Levels::Count(0),
            mark: Mark::Max,
            panel_width_px: 800,
        }
    };
    let frame_of = |map: &Figure, range: (f64, f64)| {
        let shown = section::displayed(map, &map.panels[0]);
        let ticks = section::longest_tick(range).max(6);
        (Frame::new(&shown, false, view_px, ticks), shown)
    };
    let (pressure_frame, pressure_shown) = frame_of(&pressure_map, p_range);
    let (topography_frame, topography_shown) = frame_of(&topography_map, h_range);
    let blank_section = section_map(
        ndarray::Array2::zeros(section_axes.map_or((2, 2), |(u, v)| (v.count, u.count))),
        String::new(),
    );
    let (section_frame, section_shown) = frame_of(&blank_section, s_range);
    log_map_static(
        stream,
        "wear/pressure",
        &pressure_frame,
        &pressure_map,
        &pressure_shown,
        (!own_p).then_some(p_range),
    )?;
    log_map_static(
        stream,
        "wear/topography",
        &topography_frame,
        &topography_map,
        &topography_shown,
        Some(h_range),
    )?;
    if !sections.is_empty() {
        log_map_static(
            stream,
            "wear/section",
            &section_frame,
            &blank_section,
            &section_shown,
            (!own_s).then_some(s_range),
        )?;
    }

    let values = distance_timeline(study);
    let volume_per_m3 = if study.steps.iter().any(|s| s.worn_volume_m3 * 1e18 >= 1e4) {
        1e15
    } else {
        1e18
    };
    let volume_unit = if volume_per_m3 == 1e15 {
        "10³ µm³"
    } else {
        "µm³"
    };
    let thermal = study
        .steps
        .iter()
        .any(|s| s.max_temperature_rise_k.is_some());
    let mut series: Vec<(&str, String, [u8; 3])> = vec![
        ("series/scar_area_mm2", "scar (mm²)".into(), PALETTE[2]),
        (
            "series/contact_area_mm2",
            "real contact area (mm²)".into(),
            PALETTE[0],
        ),
        (
            "series/plastic_area_um2",
            "plastic area (µm²)".into(),
            PALETTE[1],
        ),
        (
            "series/worn_volume",
            format!("worn volume ({volume_unit})"),
            PALETTE[0],
        ),
        (
            "series/max_pressure_mpa",
            "largest p (MPa)".into(),
            PALETTE[3],
        ),
        (
            "series/von_mises_max_mpa",
            "largest σvM (MPa)".into(),
            PALETTE[4],
        ),
    ];
    let archard = match study.kind {
        WearKind::Archard {
            coefficient_m2_per_n,
            ..
        } => Some(coefficient_m2_per_n),
        WearKind::Series => None,
    };
    if archard.is_some() {
        series.push((
            "series/archard_volume",
            format!("Archard k W s ({volume_unit})"),
            PALETTE[1],
        ));
    }
    if thermal {
        series.push((
            "series/max_temperature_rise_k",
            "largest flash ΔT (K)".into(),
            PALETTE[3],
        ));
    }
    for (path, name, colour) in &series {
        stream.log_static(*path, &super::series_line(name.clone(), *colour))?;
    }
    super::layout::send(
        stream,
        &plan_layout(thermal, !sections.is_empty(), &values.name),
        live,
    )?;
    flush()?;

    let steps = study.steps.len();
    for (k, step) in study.steps.iter().enumerate() {
        stream.set_time_sequence(TIMELINE, super::step_time(k));
        stream.set_time_sequence(values.timeline()?, values.values[k]);
        let distance = match step.sliding_distance_m {
            s if s >= 1.0 => format!("s = {} m", crate::io::text::approx(s)),
            s => format!("s = {} mm", crate::io::text::approx(s * 1e3)),
        };
        let solution = &step.solution;
        // Pressure, the cells at the cap outlined.
        let p = solution.pressure_pa.mapv(|v| v * 1e-6);
        let outlines = match hardness_mpa {
            Some(h) => {
                let capped = p.mapv(|v| if v >= h * (1.0 - 1e-12) { 1.0 } else { 0.0 });
                crate::render::contour_lines(capped.view(), &x, &y, 0.5)
            }
            None => Vec::new(),
        };
        let mut pressure = pressure_map.clone();
        pressure.panels[0] = panel(x, y, p, outlines);
        let shown = section::displayed(&pressure, &pressure.panels[0]);
        // Short enough to clear the colour bar's label (the description says that the cells at
        // the cap are outlined and what "own colour range" means).
        let mut text = format!(
            "{distance}: {} spot{}, area {} mm², scar {} mm²",
            solution.spots,
            if solution.spots == 1 { "" } else { "s" },
            section::short(step.contact_area_m2() * 1e6),
            section::short(step.scar_area_m2() * 1e6)
        );
        if let Some(h) = hardness_mpa {
            text.push_str(&format!(
                "; {} cells at the hardness {} MPa",
                solution.plastic_cells,
                section::short(h)
            ));
        }
        let mut title = super::step_text(k, steps, &text);
        let range = if own_p {
            title.push_str(" (own colour range)");
            let range = match hardness_mpa {
                Some(h) if solution.max_pressure_pa * 1e-6 >= h * (1.0 - 1e-12) => (0.0, h),
                _ => own_range(solution.max_pressure_pa * 1e-6),
            };
            section::log_colour_bar(
                stream,
                When::Step,
                "wear/pressure",
                &pressure_frame,
                ColorMap::Inferno,
                "p (MPa)",
                range,
            )?;
            range
        } else {
            p_range
        };
        log_map_step(
            stream,
            When::Step,
            "wear/pressure",
            &pressure_frame,
            &pressure,
            &shown,
            range,
            &title,
        )?;
        // Topography, the scar outlined.
        let heights = step.heights_m.mapv(|h| (h - top) * 1e6);
        let scar_outline = if step.max_wear_depth_m > 0.0 {
            let threshold = 1e-3 * step.max_wear_depth_m;
            let scar = step
                .wear_depth_m
                .mapv(|w| if w > threshold { 1.0 } else { 0.0 });
            crate::render::contour_lines(scar.view(), &x, &y, 0.5)
        } else {
            Vec::new()
        };
        let mut topography = topography_map.clone();
        topography.panels[0] = panel(x, y, heights, scar_outline);
        let shown = section::displayed(&topography, &topography.panels[0]);
        let title = super::step_text(
            k,
            steps,
            &format!(
                "{distance}: deepest wear {} µm, worn {} {volume_unit}",
                section::short(step.max_wear_depth_m * 1e6),
                section::short(step.worn_volume_m3 * volume_per_m3)
            ),
        );
        log_map_step(
            stream,
            When::Step,
            "wear/topography",
            &topography_frame,
            &topography,
            &shown,
            h_range,
            &title,
        )?;
        // The section through the step's largest von Mises stress.
        if let Some(cut) = sections.get(k) {
            let maximum = step.maxima.von_mises;
            let um = crate::study::rough::REFERENCE_LENGTH_M * 1e6;
            let y_um = match cut.plane.section {
                crate::field::Section::Xz { y } => y * um,
                _ => f64::NAN,
            };
            let subtitle = format!(
                "{distance}: y = {} µm; the step's largest σvM {} MPa at x = {} µm, z = {} µm",
                section::short(y_um),
                section::short(
                    maximum.value_over_p0 * crate::study::rough::REFERENCE_PRESSURE_PA * 1e-6
                ),
                section::short(maximum.x_over_a * um),
                section::short(maximum.z_over_a * um),
            );
            let values = cut.values_pa.mapv(|v| v * 1e-6);
            let peak = values.iter().fold(0.0f64, |m, &v| m.max(v));
            let mut title = super::step_text(k, steps, &subtitle);
            let range = if own_s {
                title.push_str(" (own colour range)");
                let range = own_range(peak);
                section::log_colour_bar(
                    stream,
                    When::Step,
                    "wear/section",
                    &section_frame,
                    scene.figure.colormap,
                    "σvM (MPa)",
                    range,
                )?;
                range
            } else {
                s_range
            };
            let map = section_map(values, subtitle.clone());
            let shown = section::displayed(&map, &map.panels[0]);
            log_map_step(
                stream,
                When::Step,
                "wear/section",
                &section_frame,
                &map,
                &shown,
                range,
                &title,
            )?;
        }
        let report = crate::report::wear::StepReport::of(step);
        let mut scalars: Vec<(&str, f64)> = vec![
            ("series/scar_area_mm2", report.scar_area_m2 * 1e6),
            ("series/contact_area_mm2", report.contact_area_m2 * 1e6),
            ("series/plastic_area_um2", report.plastic_area_m2 * 1e12),
            ("series/worn_volume", report.worn_volume_m3 * volume_per_m3),
            ("series/max_pressure_mpa", report.max_pressure_pa * 1e-6),
            ("series/von_mises_max_mpa", report.von_mises_max_pa * 1e-6),
        ];
        if let Some(coefficient) = archard {
            scalars.push((
                "series/archard_volume",
                coefficient * study.load_n * step.sliding_distance_m * volume_per_m3,
            ));
        }
        if let Some(t) = report.max_temperature_rise_k {
            scalars.push(("series/max_temperature_rise_k", t));
        }
        for (path, value) in scalars {
            stream.log(path, &rerun::Scalars::new([value]))?;
        }
        stream.log(
            "log",
            &rerun::TextLog::new(super::step_text(k, steps, &text)),
        )?;
        flush()?;
    }
    Ok(Summary {
        steps,
        panels: 2 + usize::from(!sections.is_empty()),
        volume_triangles: 0,
    })
}

/// The layout: the maps (pressure, topography, section) and the figure in tabs; beside them
/// the charts against the distance (areas; the worn volume; pressure and stress; the flash
/// temperature) over the report and the steps.
fn plan_layout(thermal: bool, section: bool, timeline: &str) -> Layout {
    let view2d =
        |name: &str, origin: &str| Node::View(View::new(ViewKind::Spatial2D(None), name, origin));
    let mut main = vec![
        view2d("pressure (MPa)", "wear/pressure"),
        view2d("worn topography", "wear/topography"),
    ];
    if section {
        main.push(view2d("σvM section", "wear/section"));
    }
    main.push(view2d("figure", "sheet"));
    let plot = |name: &str, paths: &[&str]| {
        Node::View(View::new(ViewKind::TimeSeries, name, "series").with_contents(paths))
    };
    let mut areas = vec![
        plot(
            "scar, real area (mm²)",
            &["$origin/scar_area_mm2", "$origin/contact_area_mm2"],
        ),
        plot("plastic area (µm²)", &["$origin/plastic_area_um2"]),
    ];
    let mut loads = vec![
        plot(
            "worn volume",
            &["$origin/worn_volume", "$origin/archard_volume"],
        ),
        plot(
            "p, σvM max (MPa)",
            &["$origin/max_pressure_mpa", "$origin/von_mises_max_mpa"],
        ),
    ];
    if thermal {
        loads.push(plot("flash ΔT (K)", &["$origin/max_temperature_rise_k"]));
    }
    areas.truncate(2);
    let side = Node::Vertical(
        vec![
            Node::Tabs(areas, 0),
            Node::Tabs(loads, 0),
            Node::Tabs(
                vec![
                    Node::View(View::new(ViewKind::TextDocument, "report", "description")),
                    Node::View(View::new(ViewKind::TextLog, "steps", "log")),
                ],
                0,
            ),
        ],
        vec![1.0, 1.0, 1.1],
    );
    Layout {
        root: Node::Horizontal(
            vec![Node::Tabs(main, 0), side],
            vec![super::MAIN_SHARE, super::SIDE_SHARE],
        ),
        timeline: Some(timeline.to_string()),
    }
}

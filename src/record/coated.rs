//! Recordings of coated scenes (issue 40): the section `y = 0` of the coated body at every
//! step of a coating-thickness sweep (`[sweep] parameter = "coating_thickness"`), or the scene
//! alone as one step. Draws what [`crate::study::coated::sweep`] computed, with the figure of
//! [`crate::figure::coated`].
//!
//! ## Entities (steps on the timeline `coating_thickness`, or `step`)
//! - `description`: the sweep, how to read the views, and the first step's `hertz` report.
//! - `section`: von Mises stress (the figure's stress unit) in the plane of sliding through
//!   the coating and the substrate, in µm, depth downwards, the interface as a white line
//!   (it moves with the step), the tractions above, the maximum labelled; one frame (to the
//!   deepest step's drawn depth) and one colour range (0 to the sweep's largest value) for
//!   every step.
//! - `charts/maxima`: the largest von Mises stress in the coating and in the substrate, and
//!   the interface's largest shear, against `h` on a logarithmic axis; `charts/depth`: the
//!   depth of the overall maximum over `a` against `h/a`, with the interface `z = h` drawn,
//!   so the maximum is seen to travel between the substrate, the interface and the layer.
//! - `series/coating_thickness_um`, `series/von_mises_max`, `series/coating_von_mises_max`,
//!   `series/substrate_von_mises_max`, `series/interface_shear_max` (MPa),
//!   `series/max_depth_over_thickness` (below 1: in the coating; 1: at the interface; above:
//!   in the substrate): scalars per step.
//! - `log`: one line per step.

use rerun::RecordingStream;

use super::layout::{Layout, Node, View, ViewKind};
use super::rough::{log_map_static, log_map_step, main_view_px, rerun_error};
use super::section::{self, Frame, When};
use super::{RecordError, Summary};
use crate::figure::coated::{coated_figure_to_depth, drawn_depth_m};
use crate::render::chart::{Chart, Scale, Series, Style, PALETTE};
use crate::scene::Scene;
use crate::study::coated::CoatedStudy;

/// Where a step's largest von Mises stress lies.
fn place(study: &CoatedStudy) -> &'static str {
    let m = &study.maxima;
    let h = study.spec.thickness_m;
    if m.von_mises.z_m == h {
        if m.von_mises == m.coating_von_mises {
            "at the interface (coating side)"
        } else {
            "at the interface (substrate side)"
        }
    } else if m.von_mises.z_m < h {
        if m.von_mises.z_m == 0.0 {
            "at the coating's surface"
        } else {
            "inside the coating"
        }
    } else {
        "in the substrate"
    }
}

/// Records a coated scene (module doc); a `live` stream opens following the newest step.
pub fn record(
    scene: &Scene,
    stream: &RecordingStream,
    live: bool,
    flush: &dyn Fn() -> Result<(), RecordError>,
) -> Result<Summary, RecordError> {
    let studies = crate::study::coated::sweep(scene, &mut |_, _| {}).map_err(rerun_error)?;
    let steps = studies.len();
    let first = studies
        .first()
        .ok_or_else(|| rerun_error("a coated recording needs one step at least"))?;
    let timeline = super::timeline(scene);
    let depth = studies.iter().map(drawn_depth_m).fold(0.0, f64::max);
    let stress_unit = 1e-6; // the coated figure is in MPa
    let top = studies
        .iter()
        .map(|s| s.maxima.von_mises.value_pa * stress_unit)
        .fold(0.0, f64::max);
    let range = (0.0, super::round_up(1.03 * top).max(1e-9));
    stream.log_static(
        "description",
        &rerun::TextDocument::from_markdown(describe(scene, &studies, range)),
    )?;
    let (width, height) = main_view_px(steps > 1);
    let figure0 = coated_figure_to_depth(scene, first, depth);
    let shown0 = section::displayed(&figure0, &figure0.panels[0]);
    let caption = section::panel_caption(&figure0, &shown0);
    let ticks = section::longest_tick(range).max(caption.chars().count() / 2);
    let frame = Frame::new(&shown0, false, (width, height), ticks);
    log_map_static(stream, "section", &frame, &figure0, &shown0, Some(range))?;
    for (path, name, colour) in [
        ("series/von_mises_max", "σvM max (MPa)", PALETTE[0]),
        (
            "series/coating_von_mises_max",
            "coating σvM max (MPa)",
            PALETTE[1],
        ),
        (
            "series/substrate_von_mises_max",
            "substrate σvM max (MPa)",
            PALETTE[2],
        ),
        (
            "series/interface_shear_max",
            "interface shear max (MPa)",
            PALETTE[3],
        ),
        (
            "series/max_depth_over_thickness",
            "depth of the maximum / h",
            PALETTE[4],
        ),
        ("series/coating_thickness_um", "h (µm)", PALETTE[6]),
    ] {
        stream.log_static(path, &super::series_line(name, colour))?;
    }
    super::layout::send(stream, &plan_layout(&frame, timeline, steps > 1), live)?;
    flush()?;
    for (k, study) in studies.iter().enumerate() {
        stream.set_time_sequence(timeline, super::step_time(k));
        let text = match &scene.sweep {
            Some(sweep) => sweep.describe(k, scene),
            None => format!("h = {} µm", section::short(study.spec.thickness_m * 1e6)),
        };
        let figure = coated_figure_to_depth(scene, study, depth);
        let shown = section::displayed(&figure, &figure.panels[0]);
        let m = &study.maxima;
        let title = format!(
            "{}: σvM max {} MPa {}",
            super::step_text(k, steps, &text),
            section::short(m.von_mises.value_pa * stress_unit),
            place(study)
        );
        log_map_step(
            stream,
            When::Step,
            "section",
            &frame,
            &figure,
            &shown,
            range,
            &title,
        )?;
        let h = study.spec.thickness_m;
        stream.log(
            "log",
            &rerun::TextLog::new(format!(
                "{title}, at x = {} µm, z = {} µm (z/h = {}); coating {} MPa, substrate {} MPa, interface shear {} MPa",
                section::short(m.von_mises.x_m * 1e6),
                section::short(m.von_mises.z_m * 1e6),
                section::short(m.von_mises.z_m / h),
                section::short(m.coating_von_mises.value_pa * stress_unit),
                section::short(m.substrate_von_mises.value_pa * stress_unit),
                section::short(m.interface_shear.value_pa * stress_unit),
            )),
        )?;
        for (path, value) in [
            ("series/coating_thickness_um", h * 1e6),
            ("series/von_mises_max", m.von_mises.value_pa * stress_unit),
            (
                "series/coating_von_mises_max",
                m.coating_von_mises.value_pa * stress_unit,
            ),
            (
                "series/substrate_von_mises_max",
                m.substrate_von_mises.value_pa * stress_unit,
            ),
            (
                "series/interface_shear_max",
                m.interface_shear.value_pa * stress_unit,
            ),
            ("series/max_depth_over_thickness", m.von_mises.z_m / h),
        ] {
            stream.log(path, &rerun::Scalars::new([value]))?;
        }
        if steps > 1 {
            for (name, chart) in charts(&studies, k) {
                stream.log(
                    format!("charts/{name}"),
                    &rerun::EncodedImage::from_file_contents(super::chart_png_bytes(&chart)?),
                )?;
            }
        }
        flush()?;
    }
    Ok(Summary {
        steps,
        panels: 1,
        volume_triangles: 0,
    })
}

/// The charts at step `current` (every step drawn, the current one marked), by entity name.
pub(super) fn charts(studies: &[CoatedStudy], current: usize) -> Vec<(&'static str, Chart)> {
    let h_um = |s: &CoatedStudy| s.spec.thickness_m * 1e6;
    let (lo, hi) = studies.iter().fold((f64::INFINITY, 0.0f64), |(l, u), s| {
        (l.min(h_um(s)), u.max(h_um(s)))
    });
    let series = |label: &str,
                  colour: [u8; 3],
                  f: &dyn Fn(&CoatedStudy) -> f64,
                  x: &dyn Fn(&CoatedStudy) -> f64| {
        vec![
            Series {
                label: label.to_string(),
                points: studies.iter().map(|s| (x(s), f(s))).collect(),
                style: Style::Line,
                colour,
            },
            Series {
                label: String::new(),
                points: vec![(x(&studies[current]), f(&studies[current]))],
                style: Style::Markers,
                colour,
            },
        ]
    };
    let mpa = |pa: f64| pa * 1e-6;
    let mut maxima = Chart::new(
        "largest stresses against the coating's thickness",
        "h (µm)",
        "MPa",
    );
    maxima.x_scale = Scale::Log;
    maxima.x_range = Some((lo / 1.2, hi * 1.2));
    let top = studies
        .iter()
        .map(|s| s.maxima.von_mises.value_pa)
        .fold(0.0, f64::max);
    maxima.y_range = Some((0.0, mpa(1.1 * top)));
    maxima.series.extend(series(
        "σvM max in the coating",
        PALETTE[1],
        &|s| mpa(s.maxima.coating_von_mises.value_pa),
        &h_um,
    ));
    maxima.series.extend(series(
        "σvM max in the substrate",
        PALETTE[2],
        &|s| mpa(s.maxima.substrate_von_mises.value_pa),
        &h_um,
    ));
    maxima.series.extend(series(
        "interface shear max",
        PALETTE[3],
        &|s| mpa(s.maxima.interface_shear.value_pa),
        &h_um,
    ));
    // Where the overall maximum is, against h/a, with the interface z = h.
    let a = studies[0].hertz_semi_axes_m[0];
    let h_over_a = |s: &CoatedStudy| s.spec.thickness_m / a;
    let mut depth = Chart::new(
        "where the largest von Mises stress is",
        "h / a (a: the coating's Hertz contact)",
        "depth of the maximum / a",
    );
    depth.x_scale = Scale::Log;
    depth.x_range = Some((lo * 1e-6 / a / 1.2, hi * 1e-6 / a * 1.2));
    let deepest = studies
        .iter()
        .map(|s| s.maxima.von_mises.z_m / a)
        .fold(0.0, f64::max);
    depth.y_range = Some((0.0, (1.15 * deepest).max(1.0)));
    depth.series.push(Series {
        label: "the interface z = h".into(),
        points: studies.iter().map(|s| (h_over_a(s), h_over_a(s))).collect(),
        style: Style::Dashed,
        colour: PALETTE[6],
    });
    depth.series.extend(series(
        "depth of the maximum",
        PALETTE[0],
        &|s| s.maxima.von_mises.z_m / a,
        &h_over_a,
    ));
    // The shape of the charts' panel in the default window (as the Péclet sweep's charts),
    // so that the viewer fits the images without black bands.
    for chart in [&mut maxima, &mut depth] {
        chart.width_px = 520;
        chart.height_px = 560;
    }
    vec![("maxima", maxima), ("depth", depth)]
}

/// The layout: the section; beside it the charts over the description, the steps and the
/// series.
fn plan_layout(frame: &Frame, timeline: &str, sweeps: bool) -> Layout {
    let view2d = |name: &str, origin: &str, frame: Option<&Frame>| {
        Node::View(View::new(
            ViewKind::Spatial2D(frame.map(|f| f.bounds)),
            name,
            origin,
        ))
    };
    let main = view2d(
        "von Mises stress in the plane of sliding (MPa), depth down",
        "section",
        Some(frame),
    );
    let plots = vec![
        view2d("maxima vs h", "charts/maxima", None),
        view2d("depth vs h", "charts/depth", None),
    ];
    let by_step = Node::View(
        View::new(ViewKind::TimeSeries, "maxima by step", "series").with_contents(&[
            "$origin/von_mises_max",
            "$origin/coating_von_mises_max",
            "$origin/substrate_von_mises_max",
            "$origin/interface_shear_max",
        ]),
    );
    let documents = Node::Tabs(
        vec![
            Node::View(View::new(ViewKind::TextDocument, "scene", "description")),
            Node::View(View::new(ViewKind::TextLog, "steps", "log")),
            by_step,
        ],
        0,
    );
    let side = if sweeps {
        Node::Vertical(vec![Node::Tabs(plots, 0), documents], vec![1.3, 1.0])
    } else {
        documents
    };
    Layout {
        root: Node::Horizontal(vec![main, side], vec![super::MAIN_SHARE, super::SIDE_SHARE]),
        timeline: sweeps.then(|| timeline.to_string()),
    }
}

/// The markdown description: the sweep, how to read the views, the first step's report.
fn describe(scene: &Scene, studies: &[CoatedStudy], range: (f64, f64)) -> String {
    let first = &studies[0];
    let last = &studies[studies.len() - 1];
    let a_um = first.hertz_semi_axes_m[0] * 1e6;
    let mut text = format!(
        "# {}\n\n",
        scene.title.clone().unwrap_or_else(|| scene.name.clone())
    );
    if let Some(sweep) = &scene.sweep {
        text.push_str(&format!(
            "Scene `{}`: the coated body as its coating's thickness grows, {} steps from {} to {} (spaced geometrically) on the timeline `{}`, at the same load; a = {} µm is the coating's Hertz contact (the scene's scale).\n\n",
            scene.name,
            studies.len(),
            sweep.describe(0, scene),
            sweep.describe(studies.len() - 1, scene),
            sweep.parameter.key(),
            section::short(a_um),
        ));
    }
    text.push_str(&format!(
        "**Reading the views.** `section`: von Mises stress in MPa in the plane of sliding y = 0, depth downwards in µm; the white line is the interface z = h, the coating above it, the substrate below. Colours 0 to {} MPa at every step. The title gives where the largest value lies: in the substrate (a thin coating: nearly the substrate's own Hertz field), at the interface (where σxx jumps with the moduli) or inside the coating (a thick one: the coating's Hertz field). Charts: the largest von Mises stress in each material and the interface's shear against h; the depth of the overall maximum against h/a with the interface z = h dashed (on the line: at the interface; below it: in the coating). Hovering the map reads the value (the viewer calls it a \"Depth\" in m: ignore that line).\n\n",
        section::short(range.1)
    ));
    text.push_str(
        "Conventions: z points into the body, tension positive, q = μp acts in +x on the body.\n\n",
    );
    for (name, study) in [("first", first), ("last", last)] {
        let report = crate::report::coated::CoatedReport::new(study);
        let mut stepped = scene.clone();
        if let Some(coating) = &mut stepped.contact.coating {
            coating.thickness_m = study.spec.thickness_m;
        }
        text.push_str(&format!(
            "## The {name} step (`stressfield hertz`)\n\n```text\n{}```\n\n",
            report.text(&stepped, study)
        ));
    }
    text
}

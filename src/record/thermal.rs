//! Recordings of speed sweeps: scenes with `[thermal]` and `[sweep] parameter = "peclet"`
//! (issue 21). Draws what [`crate::study::thermal_sweep`] computed.
//!
//! ## Entities (steps on the timeline `peclet`, and at Pe × 100 on `Pe × 100`)
//! - `description`: the scene's `hertz` report and its heating at its own speed (`stressfield
//!   thermal`), the sweep, and how to read the views.
//! - `surface`: body 1's surface temperature rise (K) under its share of the heat, as a map
//!   view (see [`super::section`]): the field (values read on hover), the contact outlined, a
//!   title row with the step's Pe, V and body 1's share, and the labelled maximum (a line
//!   contact's, whose strip repeats one row, on `section`).
//! - `section`: body 1's temperature rise (K) in the xz section through the contact's centre
//!   (`y = 0`), depth downwards to `1.2a`, the contact's width marked on the surface; its
//!   title gives the step's colour range.
//! - Both views take each step's own colour range, 0 to its maximum rounded up (the maximum
//!   grows by orders of magnitude over a sweep of three decades, so one range would leave the
//!   slow steps black): their colour bars (`.../colorbar/...`) are logged at every step.
//! - `charts/max_temperature` (body 1's maximum against Pe on log axes, with the stationary
//!   and fast asymptotes), `charts/max_position` (where the maximum is, x/a, against Pe),
//!   `charts/share` (body 1's share of the heat, Blok's partition only): chart images of the
//!   steps so far, the current one marked.
//! - `series/peclet`, `series/sliding_speed_m_per_s`, `series/max_temperature_rise_k`,
//!   `series/mean_temperature_rise_k`, `series/max_x_over_a`, `series/body1_share`: scalars
//!   per step.
//! - `log`: one line per step.

use rerun::RecordingStream;

use super::layout::{Layout, Node, View, ViewKind};
use super::rough::{log_map_static, log_map_step, main_view_px, rerun_error};
use super::section::{self, Frame, When};
use super::{RecordError, Summary};
use crate::field::Axis;
use crate::figure::thermal::{asymptotes, map, surface_map};
use crate::render::chart::{Chart, Scale, Series, Style, PALETTE};
use crate::render::{ColorMap, Figure, Mark};
use crate::scene::Scene;
use crate::study::thermal_sweep::{speed_sweep, SpeedStep, SpeedSweep};
use crate::thermal::heating::Partition;

/// The timeline of the steps.
const TIMELINE: &str = "peclet";
/// The power of ten the Péclet numbers are scaled by on their own timeline (`Pe × 100`, which
/// the time panel opens on, so that it shows Pe, not the step): the smallest from 100 up that
/// keeps every step's value apart.
fn peclet_scale(steps: &[SpeedStep]) -> i32 {
    (2..=6)
        .find(|&k| {
            let mut values: Vec<i64> = steps
                .iter()
                .map(|s| (s.peclet * 10f64.powi(k)).round() as i64)
                .collect();
            values.sort_unstable();
            values.windows(2).all(|w| w[0] != w[1])
        })
        .unwrap_or(6)
}

/// The name of the Péclet numbers' timeline at scale `10^k`.
fn peclet_timeline(k: i32) -> String {
    format!("Pe × {}", 10i64.pow(k.unsigned_abs()))
}

/// Height shares of the surface map and of the section below it.
const SURFACE_SHARE: f32 = 2.0;
const SECTION_SHARE: f32 = 1.0;

/// Records a speed sweep (module doc); a `live` stream opens following the newest step. The
/// sweep is computed first (its steps share one grid), then sent step by step.
pub fn record(
    scene: &Scene,
    stream: &RecordingStream,
    live: bool,
    flush: &dyn Fn() -> Result<(), RecordError>,
) -> Result<Summary, RecordError> {
    let sweep_spec = scene
        .sweep
        .as_ref()
        .ok_or_else(|| rerun_error("a speed sweep needs [sweep]"))?;
    let spec = scene
        .thermal
        .ok_or_else(|| rerun_error("a speed sweep needs [thermal]"))?;
    let sweep = speed_sweep(scene, &sweep_spec.values, &mut |_, _| {})?;
    stream.log_static(
        "description",
        &rerun::TextDocument::from_markdown(describe(scene, &sweep)?),
    )?;
    let steps = sweep.steps.len();
    let a_um = sweep.half_width_m * 1e6;
    // The views' frames, from the first step (the axes do not change; the colour bars'
    // labels are allowed six characters).
    let (width, height) = main_view_px(steps > 1);
    let share = |s: f32| f64::from(s / (SURFACE_SHARE + SECTION_SHARE));
    let first = &sweep.steps[0];
    let surface0 = surface_figure(&sweep, first, String::new());
    let section0 = section_figure(&sweep, first, String::new());
    let shown_surface0 = section::displayed(&surface0, &surface0.panels[0]);
    let shown_section0 = section::displayed(&section0, &section0.panels[0]);
    let surface_frame = Frame::new(
        &shown_surface0,
        false,
        (width, height * share(SURFACE_SHARE)),
        6,
    );
    let section_frame = Frame::new(
        &shown_section0,
        false,
        (width, height * share(SECTION_SHARE)),
        6,
    );
    log_map_static(
        stream,
        "surface",
        &surface_frame,
        &surface0,
        &shown_surface0,
        None,
    )?;
    log_map_static(
        stream,
        "section",
        &section_frame,
        &section0,
        &shown_section0,
        None,
    )?;
    log_series_styles(stream)?;
    let blok = spec.partition == Partition::Blok;
    super::layout::send(
        stream,
        &plan_layout(
            &surface_frame,
            &section_frame,
            blok,
            (steps > 1).then(|| peclet_timeline(peclet_scale(&sweep.steps))),
        ),
        live,
    )?;
    flush()?;
    let pe_scale = peclet_scale(&sweep.steps);
    let pe_timeline = rerun::TimelineName::try_new(peclet_timeline(pe_scale))
        .map_err(|e| RecordError::Rerun(e.to_string()))?;
    for (k, step) in sweep.steps.iter().enumerate() {
        stream.set_time_sequence(TIMELINE, super::step_time(k));
        if steps > 1 {
            stream.set_time_sequence(
                pe_timeline,
                (step.peclet * 10f64.powi(pe_scale)).round() as i64,
            );
        }
        let text = sweep_spec.describe(k, scene);
        let max_k = step.body1.max_temperature_rise_k;
        let range = (0.0, super::round_up(1.03 * max_k).max(1e-9));
        let x_over_a = step.body1.max_at_m[0] / sweep.half_width_m;
        let colours = format!(
            "colours 0 to {} K (this step's range)",
            section::short(range.1)
        );
        let surface = surface_figure(&sweep, step, text.clone());
        let section = section_figure(&sweep, step, text.clone());
        let title = format!(
            "{}; body 1 takes {} % of the heat",
            super::step_text(k, steps, &text),
            section::short(100.0 * step.body1.share),
        );
        let section_title = format!(
            "xz section at y = 0 through the contact's centre (white: the contact, 2a = {} µm): {text}; {colours}",
            section::short(2.0 * a_um)
        );
        for (base, frame, figure, title) in [
            ("surface", &surface_frame, &surface, &title),
            ("section", &section_frame, &section, &section_title),
        ] {
            let shown = section::displayed(figure, &figure.panels[0]);
            section::log_colour_bar(
                stream,
                When::Step,
                base,
                frame,
                section::panel_colormap(figure, &shown),
                &section::panel_caption(figure, &shown),
                range,
            )?;
            log_map_step(
                stream,
                When::Step,
                base,
                frame,
                figure,
                &shown,
                range,
                title,
            )?;
        }
        stream.log(
            "log",
            &rerun::TextLog::new(format!(
                "{}: max {} K at x = {}a, mean over the contact {} K, body 1's share {}",
                super::step_text(k, steps, &text),
                section::short(max_k),
                section::short(x_over_a),
                section::short(step.body1.mean_temperature_rise_k),
                section::short(step.body1.share)
            )),
        )?;
        for (path, value) in [
            ("series/peclet", step.peclet),
            ("series/sliding_speed_m_per_s", step.sliding_speed_m_per_s),
            ("series/max_temperature_rise_k", max_k),
            (
                "series/mean_temperature_rise_k",
                step.body1.mean_temperature_rise_k,
            ),
            ("series/max_x_over_a", x_over_a),
            ("series/body1_share", step.body1.share),
        ] {
            stream.log(path, &rerun::Scalars::new([value]))?;
        }
        for (name, chart) in charts(&sweep, k, blok) {
            stream.log(
                format!("charts/{name}"),
                &rerun::EncodedImage::from_file_contents(super::chart_png_bytes(&chart)?),
            )?;
        }
        flush()?;
    }
    Ok(Summary {
        steps,
        panels: 2,
        volume_triangles: 0,
    })
}

/// Body 1's surface temperature map of a step, in µm, the contact outlined.
fn surface_figure(sweep: &SpeedSweep, step: &SpeedStep, subtitle: String) -> Figure {
    let surface = surface_map(
        &step.body1.temperature_k,
        &sweep.flux_per_speed,
        sweep.origin_m,
        sweep.spacing_m,
        sweep.half_width_m,
        sweep.line,
    );
    let mut figure = map(
        "body 1's surface temperature rise",
        subtitle,
        surface.x,
        surface.y,
        surface.values,
        "ΔT (K)",
        ColorMap::Inferno,
        false,
        surface.outlines,
    );
    // A line contact's strip repeats one row: its maximum is labelled on the section, where
    // it is one point.
    if sweep.line {
        figure.mark = Mark::None;
    }
    figure
}

/// Body 1's xz temperature section of a step through the contact's centre, in µm, depth
/// downwards, the contact's width drawn on the surface.
fn section_figure(sweep: &SpeedSweep, step: &SpeedStep, subtitle: String) -> Figure {
    let um = |m: f64| m * 1e6;
    let nx = sweep.shape[1];
    let x = Axis::new(um(sweep.x_m(0)), um(sweep.x_m(nx - 1)), nx);
    let depth = Axis::new(
        0.0,
        um(*sweep.depths_m.last().unwrap_or(&0.0)),
        sweep.depths_m.len(),
    );
    let a = um(sweep.half_width_m);
    let mut figure = map(
        "body 1's temperature rise under the contact",
        subtitle,
        x,
        depth,
        step.section_k.clone(),
        "ΔT (K)",
        ColorMap::Inferno,
        true,
        vec![vec![(-a, 0.0), (a, 0.0)]],
    );
    // Its maximum is the surface map's, labelled there (a label here would cover the heated
    // layer), except for a line contact's.
    if !sweep.line {
        figure.mark = Mark::None;
    }
    figure
}

/// The charts at step `current` (the steps so far, the current one marked), by entity name.
fn charts(sweep: &SpeedSweep, current: usize, blok: bool) -> Vec<(&'static str, Chart)> {
    let steps = &sweep.steps;
    let so_far = &steps[..=current];
    let (lo, hi) = (
        steps.iter().map(|s| s.peclet).fold(f64::INFINITY, f64::min),
        steps.iter().map(|s| s.peclet).fold(0.0, f64::max),
    );
    let x_range = Some((lo / 1.25, hi * 1.25));
    let up_to_now = |label: &str, colour: [u8; 3], f: &dyn Fn(&SpeedStep) -> f64| {
        vec![
            Series {
                label: label.to_string(),
                points: so_far.iter().map(|s| (s.peclet, f(s))).collect(),
                style: Style::Line,
                colour,
            },
            Series {
                label: String::new(),
                points: vec![(steps[current].peclet, f(&steps[current]))],
                style: Style::Markers,
                colour,
            },
        ]
    };
    // Against Pe on a log axis, 520 x 400 pixels.
    let against_pe = |title: &str, y_label: &str, y_range: (f64, f64)| {
        let mut chart = Chart::new(title, "Pe = V a / (2κ) of body 1", y_label);
        chart.x_scale = Scale::Log;
        chart.x_range = x_range;
        chart.y_range = Some(y_range);
        // The shape of the charts' panel in the default window (a third of its width, a bit
        // over half its height), so that the viewer fits the image without black bands.
        chart.width_px = 520;
        chart.height_px = 560;
        chart
    };
    // The maximum: body 1 under its share and, when that differs, with all the heat; the
    // asymptotes (of all the heat) where they fall inside the chart.
    let (y_lo, y_hi) = steps.iter().fold((f64::INFINITY, 0.0f64), |(a, b), s| {
        (
            a.min(s.body1.max_temperature_rise_k.min(s.whole_max_k)),
            b.max(s.body1.max_temperature_rise_k.max(s.whole_max_k)),
        )
    });
    let y_range = (0.5 * y_lo, 4.0 * y_hi);
    let mut maximum = against_pe(
        "body 1's maximum flash temperature against Pe",
        "ΔT max (K)",
        y_range,
    );
    maximum.y_scale = Scale::Log;
    for mut line in asymptotes(
        sweep.slow_per_peclet,
        sweep.fast_per_root_peclet,
        lo / 1.25,
        hi * 1.25,
    ) {
        line.points
            .retain(|&(_, t)| t >= y_range.0 && t <= y_range.1);
        maximum.series.push(line);
    }
    let shared = steps.iter().all(|s| s.body1.share == 1.0);
    if !shared {
        maximum
            .series
            .extend(up_to_now("all heat into body 1", PALETTE[0], &|s| {
                s.whole_max_k
            }));
    }
    maximum.series.extend(up_to_now(
        if shared {
            "body 1 (all the heat)"
        } else {
            "body 1 (its share)"
        },
        PALETTE[1],
        &|s| s.body1.max_temperature_rise_k,
    ));
    // Where the maximum is.
    let mut position = against_pe(
        "where body 1's hottest point is",
        "x of the maximum / a",
        (-1.3, 0.4),
    );
    position.hlines = vec![
        (0.0, "contact centre".into()),
        (-1.0, "trailing edge x = −a".into()),
    ];
    position.series.extend(up_to_now("", PALETTE[2], &|s| {
        s.body1.max_at_m[0] / sweep.half_width_m
    }));
    let mut out = vec![("max_temperature", maximum), ("max_position", position)];
    if blok {
        let mut share = against_pe(
            "body 1's share of the heat (Blok's partition)",
            "share of q = μ p V",
            (0.0, 1.0),
        );
        share
            .series
            .extend(up_to_now("", PALETTE[3], &|s| s.body1.share));
        out.push(("share", share));
    }
    out
}

/// The names and colours of the time series (static).
fn log_series_styles(stream: &RecordingStream) -> Result<(), RecordError> {
    for (path, name, colour) in [
        ("series/max_temperature_rise_k", "max ΔT (K)", PALETTE[1]),
        ("series/mean_temperature_rise_k", "mean ΔT (K)", PALETTE[0]),
        ("series/max_x_over_a", "x of the maximum / a", PALETTE[2]),
        ("series/body1_share", "body 1's share", PALETTE[3]),
        ("series/peclet", "Pe", PALETTE[6]),
        ("series/sliding_speed_m_per_s", "V (m/s)", PALETTE[4]),
    ] {
        stream.log_static(path, &super::series_line(name, colour))?;
    }
    Ok(())
}

/// The layout: the surface map over the section; beside them the charts against Pe and the
/// series by step, over the description and the steps.
fn plan_layout(surface: &Frame, section: &Frame, blok: bool, timeline: Option<String>) -> Layout {
    let view2d = |name: &str, origin: &str, frame: Option<&Frame>| {
        Node::View(View::new(
            ViewKind::Spatial2D(frame.map(|f| f.bounds)),
            name,
            origin,
        ))
    };
    let main = Node::Vertical(
        vec![
            view2d(
                "body 1's surface temperature rise (K) against Pe",
                "surface",
                Some(surface),
            ),
            view2d(
                "xz section through the contact's centre (K), depth down",
                "section",
                Some(section),
            ),
        ],
        vec![SURFACE_SHARE, SECTION_SHARE],
    );
    // Short tab names, so that every tab fits beside the others (issue 23, item 4).
    let mut plots = vec![
        view2d("max ΔT vs Pe", "charts/max_temperature", None),
        view2d("hottest x vs Pe", "charts/max_position", None),
    ];
    if blok {
        plots.push(view2d("share vs Pe", "charts/share", None));
    }
    // The temperatures against Pe (its timeline's linear axis; hover, zoom) beside the
    // documents, where the tabs fit.
    let by_step = Node::View(
        View::new(ViewKind::TimeSeries, "ΔT vs Pe", "series").with_contents(&[
            "$origin/max_temperature_rise_k",
            "$origin/mean_temperature_rise_k",
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
    Layout {
        root: Node::Horizontal(
            vec![
                main,
                Node::Vertical(vec![Node::Tabs(plots, 0), documents], vec![1.3, 1.0]),
            ],
            vec![super::MAIN_SHARE, super::SIDE_SHARE],
        ),
        timeline,
    }
}

/// The markdown description: the sweep, how to read the views, the scene's reports.
fn describe(scene: &Scene, sweep: &SpeedSweep) -> Result<String, RecordError> {
    let spec = scene
        .thermal
        .ok_or_else(|| rerun_error("a speed sweep needs [thermal]"))?;
    let Some(sweep_spec) = &scene.sweep else {
        return Err(rerun_error("a speed sweep needs [sweep]"));
    };
    let studied = crate::study::thermal::study(scene, None, &mut |_| {})?;
    let heating = crate::report::thermal::ThermalReport::new(&studied).text(&studied);
    let a_um = sweep.half_width_m * 1e6;
    let [ny, nx] = sweep.shape;
    let partition = match spec.partition {
        Partition::Body1 => "all of it into body 1 (the counter-face adiabatic)".to_string(),
        Partition::Fraction(f) => format!("a fixed fraction {f} into body 1"),
        Partition::Blok => "Blok's partition, recomputed at every speed (both bodies' mean surface temperatures over the contact equal)".to_string(),
    };
    let last = sweep_spec.values.len() - 1;
    Ok(format!(
        "# {title}\n\n\
         Scene `{name}`: body 1's flash temperature as the sliding speed rises, {n} steps from {first} to {final_} on the timeline `peclet` (the steps) and on `Pe × 100` (each step at its Pe times a hundred, or a larger power of ten where a hundred would merge two steps; the time panel opens on it).\n\n\
         The Péclet number is body 1's, Pe = V1 a / (2κ1): how far the contact moves over body 1 (a = {a} µm) while heat diffuses across it. Every speed of the scene is scaled by the same factor, so the frictional flux q = μ p V grows with V. Heat partition: {partition}.\n\n\
         **Reading the views.** The contact moves in +x over body 1: its material enters at the leading edge x = +a and leaves at the trailing edge x = −a, carrying heat behind. At Pe well below 1 the heat spreads in every direction before the contact moves on: the field is centred on the contact, deep and wide, and the temperature grows like V. At Pe well above 1 the heat has no time to spread ahead or down: it stays in a thin layer swept back into a wake, the hottest point moves towards the trailing edge, and the temperature grows only like √V (Jaeger 1942; Blok 1937).\n\n\
         - `surface`: body 1's surface temperature rise (K) under its share of the heat, the contact outlined in white, the maximum labelled.\n\
         - `section`: the same in the xz plane through the contact's centre (y = 0), depth downwards to 1.2a; the white line on the surface spans the contact.\n\
         - **Each step has its own colour range**, 0 to its maximum rounded up (on its colour bar and in the title): the maximum grows by orders of magnitude over the sweep. Compare steps by the labelled maxima and the charts, not by colour.\n\
         - Hovering a map shows `Val`, the temperature rise in K (the viewer also prints it as a \"Depth\" in m: ignore that line).\n\
         - Charts: body 1's maximum against Pe on log axes with the stationary (∝ Pe) and fast (∝ √Pe) asymptotes of all the heat in body 1; the x of the maximum in units of a; body 1's share (Blok). The series plot the same by step.\n\n\
         Grid: {nx} x {ny} cells of {dx} x {dy} µm over −4a ≤ x ≤ 2a{rows}, one grid for every step (cell Péclet number at most 2 at the largest Pe).\n\n\
         ## Contact (`stressfield hertz`)\n\n```text\n{hertz}```\n\n\
         ## Heating at the scene's own speed (`stressfield thermal`)\n\n```text\n{heating}```\n",
        title = scene.title.clone().unwrap_or_else(|| scene.name.clone()),
        name = scene.name,
        n = sweep_spec.values.len(),
        first = sweep_spec.describe(0, scene),
        final_ = sweep_spec.describe(last, scene),
        a = section::short(a_um),
        dx = section::short(sweep.spacing_m[0] * 1e6),
        dy = section::short(sweep.spacing_m[1] * 1e6),
        rows = if sweep.line {
            " (a line contact: one row, drawn as a strip of ±1.5a)"
        } else {
            ", |y| ≤ 2b"
        },
        hertz = crate::report::hertz(scene, &crate::study::assess::scene_maxima(scene)),
    ))
}

//! Recordings of Hertz and traction scenes: each panel's section at every step of a sweep
//! (or the one step), with the charts, the series, the material points' histories and the
//! layout of the views.

use super::*;

/// The size in pixels of each section view in the planned window.
pub(super) fn section_view_px(scene: &Scene) -> (f64, f64) {
    let width = WINDOW_PX.0 * f64::from(MAIN_SHARE / (MAIN_SHARE + SIDE_SHARE)) - 20.0;
    let chrome = if scene.sweep.is_some() { 130.0 } else { 90.0 };
    let mut height = (WINDOW_PX.1 - chrome) / scene.panels.len().max(1) as f64;
    if scene.volume.is_some() {
        height *= f64::from(SECTIONS_SHARE / (SECTIONS_SHARE + VOLUME_SHARE));
    }
    (width, height)
}

/// The coarse preview of a scene: at most 81 samples across.
pub(super) fn preview(scene: &Scene) -> Scene {
    let mut coarse = scene.clone();
    coarse.figure.resolution = scene.figure.resolution.min(81);
    coarse
}

pub(super) fn step_scene(scene: &Scene, step: usize) -> Result<Scene, RecordError> {
    study::at_step(scene, step).map_err(|e| RecordError::Step {
        step,
        message: e.to_string(),
    })
}

/// The swept parameter's axis label and the value shown on it.
pub(super) fn parameter_axis(scene: &Scene) -> Option<(String, Vec<f64>)> {
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
        SweepParameter::CoatingThickness => (
            "h (µm)".into(),
            sweep.values.iter().map(|v| v * 1e6).collect(),
        ),
        SweepParameter::EntrainmentSpeed => ("u (m/s)".into(), sweep.values.clone()),
    })
}

/// The recording of a section scene (line, point, elliptical, tractions).
pub(super) fn record_sections(
    scene: &Scene,
    stream: &RecordingStream,
    live: bool,
    on_row: &(dyn Fn() + Sync),
    flush: &dyn Fn() -> Result<(), RecordError>,
) -> Result<Summary, RecordError> {
    let steps = scene.sweep.as_ref().map_or(1, |s| s.values.len());
    let timeline = timeline(scene);
    let values = super::value_timeline(scene);
    let panels = scene.panels.len();
    stream.log_static(
        "description",
        &rerun::TextDocument::from_markdown(describe(scene)),
    )?;
    // The colour ranges from a coarse preview of every step.
    let coarse = preview(scene);
    let mut spans = vec![(f64::INFINITY, f64::NEG_INFINITY); panels];
    // Each step's own spans too: a sweep whose field grows by decades takes each step's range.
    let mut step_spans = Vec::with_capacity(steps);
    let mut volume_largest = 0.0f64;
    // The largest traction of the sweep: the strip above the map keeps one scale, so the
    // profiles grow with the load (issue 23, item 8).
    let mut traction_peak = 0.0f64;
    for step in 0..steps {
        let coarse_step = step_scene(&coarse, step)?;
        let figure = figure::build(&coarse_step, &study::panel_fields(&coarse_step, &|| {})?);
        let own: Vec<(f64, f64)> = figure.panels.iter().map(panel_span).collect();
        for ((span, own), panel) in spans.iter_mut().zip(&own).zip(&figure.panels) {
            *span = (span.0.min(own.0), span.1.max(own.1));
            for sample in &panel.traction {
                traction_peak = traction_peak.max(sample.p.abs()).max(sample.q.abs());
            }
        }
        step_spans.push(shared_scale(&figure.panels, own));
        if let Some(spec) = &scene.volume {
            let grid = study::volume::evaluate(&coarse_step, spec, (spec.points / 2).max(9))?;
            volume_largest = volume_largest.max(grid.largest());
        }
    }
    // The first step at full resolution: the frames of the views follow its axes.
    let first_scene = step_scene(scene, 0)?;
    let mut first = Some(figure::build(
        &first_scene,
        &study::panel_fields(&first_scene, on_row)?,
    ));
    let figure0 = first.as_ref().expect("just built");
    let range_of = |spans: &[(f64, f64)]| -> Vec<(f64, f64)> {
        figure0
            .panels
            .iter()
            .zip(spans)
            .map(|(panel, &(lo, hi))| {
                let map = section::panel_colormap(figure0, panel);
                colour_range(map, lo, hi, panel.scale.as_ref().and_then(|s| s.range))
            })
            .collect()
    };
    let ranges = range_of(&shared_scale(&figure0.panels, spans));
    // Decided on the preview; each step's range then comes from its own full-resolution field
    // (a coarse preview can miss a small contact's peak).
    let per_step = spans_decades(&step_spans);
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
            let has_strip = figure0.axes_of(panel).vertical_is_depth && !panel.traction.is_empty();
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
                // Per-step ranges: the colour bar is logged with each step.
                range: (!per_step).then_some(ranges[k]),
                surface: figure0.axes_of(panel).vertical_is_depth,
                material: &material,
            },
        )?;
    }
    log_series_styles(stream, scene, figure0)?;
    let volume_setup = match &scene.volume {
        Some(spec) => {
            volume::log_static(stream, scene, spec)?;
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
    for step in 0..steps {
        let step_scene = step_scene(scene, step)?;
        let figure = match first.take() {
            Some(figure) => figure,
            None => figure::build(&step_scene, &study::panel_fields(&step_scene, on_row)?),
        };
        stream.set_time_sequence(timeline, step_time(step));
        if let Some(values) = &values {
            stream.set_time_sequence(values.timeline()?, values.values[step]);
        }
        let mut title = String::new();
        if let Some(sweep) = &scene.sweep {
            let text = sweep.describe(step, scene);
            title = step_text(step, steps, &text);
            stream.log("log", &rerun::TextLog::new(title.clone()))?;
            stream.log(
                format!("series/{}", sweep.parameter.key()),
                &rerun::Scalars::new([sweep.values[step]]),
            )?;
        }
        let step_ranges: Option<Vec<(f64, f64)>> = per_step.then(|| {
            let own = figure.panels.iter().map(panel_span).collect();
            shared_scale(&figure.panels, own)
                .into_iter()
                .zip(&figure.panels)
                .map(|((lo, hi), panel)| {
                    let map = section::panel_colormap(&figure, panel);
                    colour_range(map, lo, hi, panel.scale.as_ref().and_then(|s| s.range))
                })
                .collect()
        });
        for (k, panel) in figure.panels.iter().enumerate() {
            let mut panel_title = step_title(scene, step, &title, &figure, panel);
            let shown = section::displayed(&figure, panel);
            let range = match &step_ranges {
                Some(step_ranges) => {
                    let range = step_ranges[k];
                    section::log_colour_bar(
                        stream,
                        section::When::Step,
                        &format!("sections/{k}"),
                        &frames[k],
                        section::panel_colormap(&figure, panel),
                        &section::panel_caption(&figure, panel),
                        range,
                    )?;
                    panel_title.push_str(&format!(
                        ",  colours {} to {} (this step's range)",
                        section::short(range.0),
                        section::short(range.1)
                    ));
                    range
                }
                None => ranges[k],
            };
            section::log_step(
                stream,
                section::When::Step,
                &format!("sections/{k}"),
                &frames[k],
                &figure,
                &shown,
                range,
                &section::Changing {
                    title: &panel_title,
                    notation: &section::Notation::of(&figure, panel),
                    mark: figure.mark,
                    material: &material,
                    values: true,
                    traction_peak: Some(traction_peak).filter(|&t| t > 0.0 && steps > 1),
                },
            )?;
            let (largest, smallest) = section::extremes(panel, figure.mark);
            let largest = largest.or_else(|| section::extremes(panel, Mark::Max).0);
            if let Some(e) = largest {
                stream.log(
                    format!("series/{k}/maximum"),
                    &rerun::Scalars::new([e.value]),
                )?;
                if figure.axes_of(panel).vertical_is_depth {
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
        }
        log_material_points(stream, &step_scene)?;
        if let Some((spec, levels, scale)) = &volume_setup {
            let grid = study::volume::evaluate(&step_scene, spec, spec.points)?;
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

/// A panel's smallest and largest finite values, its located peak included (a peak between
/// coarse samples, under a small contact, may be well above them).
fn panel_span(panel: &Panel) -> (f64, f64) {
    let peak = panel.peak.map(|p| p.value);
    panel
        .values
        .iter()
        .chain(peak.as_ref())
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        })
}

/// The spans of panels drawn on the figure's shared colour scale (`scale: None`) joined into
/// one, as the PNG figure draws them; a panel with a scale of its own keeps its span.
fn shared_scale(panels: &[Panel], spans: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    let joined = panels
        .iter()
        .zip(&spans)
        .filter(|(p, _)| p.scale.is_none())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), (_, s)| {
            (a.min(s.0), b.max(s.1))
        });
    panels
        .iter()
        .zip(spans)
        .map(|(p, s)| if p.scale.is_none() { joined } else { s })
        .collect()
}

/// Whether a sweep's field grows by a decade or more from step to step (the largest magnitude
/// of a panel's step spans, its largest against its smallest, over 10): then one colour range
/// would leave the first steps dark, and each step takes its own (said in its title).
fn spans_decades(step_spans: &[Vec<(f64, f64)>]) -> bool {
    let panels = step_spans.first().map_or(0, Vec::len);
    step_spans.len() > 1
        && (0..panels).any(|k| {
            let sizes: Vec<f64> = step_spans
                .iter()
                .map(|s| s[k].0.abs().max(s[k].1.abs()))
                .filter(|m| m.is_finite())
                .collect();
            let (lo, hi) = sizes
                .iter()
                .fold((f64::INFINITY, 0.0f64), |(a, b), &m| (a.min(m), b.max(m)));
            hi > 0.0 && hi > 10.0 * lo
        })
}

/// The title row of a panel at a step: the step and its parameter, then the rest of the
/// panel's subtitle (its groups are separated by two spaces, as in the PNG figure) without
/// repeating the parameter.
pub(super) fn step_title(
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

/// Whether a figure's marks (and so the plotted series) include the minimum; the maximum is
/// plotted always.
fn marks_minimum(mark: Mark) -> bool {
    matches!(mark, Mark::Min | Mark::Both)
}

/// Names and colours of the plotted series (static).
pub(super) fn log_series_styles(
    stream: &RecordingStream,
    scene: &Scene,
    figure: &Figure,
) -> Result<(), RecordError> {
    let symbol = scene.figure.quantity.symbol();
    for k in 0..figure.panels.len() {
        stream.log_static(
            format!("series/{k}/maximum"),
            &super::series_line(format!("max {symbol}"), PALETTE[1]),
        )?;
        // The minimum is plotted only where the figure marks it (a style without values
        // would be a view error).
        if marks_minimum(figure.mark) {
            stream.log_static(
                format!("series/{k}/minimum"),
                &super::series_line(format!("min {symbol}"), PALETTE[0]),
            )?;
        }
        stream.log_static(
            format!("series/{k}/maximum_depth"),
            &super::series_line(
                format!("depth of max {symbol}, {}", figure.z_label),
                PALETTE[2],
            ),
        )?;
    }
    if let Some(sweep) = &scene.sweep {
        stream.log_static(
            format!("series/{}", sweep.parameter.key()),
            &super::series_line(sweep.parameter.key().to_string(), PALETTE[6]),
        )?;
        for k in 0..figure.panels.len() {
            for j in 0..sweep.material_points.len() {
                for (c, (key, name)) in history_components(scene).into_iter().enumerate() {
                    stream.log_static(
                        format!("history/{k}/point{j}/{key}"),
                        &super::series_line(name, PALETTE[c % PALETTE.len()]),
                    )?;
                }
            }
        }
    }
    Ok(())
}

/// The stresses recorded at material points: `σxx`, `σzz`, `τxz`, the principal shear `τ1` of
/// the xz plane and `σvM` (what fatigue and yield criteria read), and the figure's quantity
/// when it is none of them, as `(key, symbol)`.
pub(super) fn history_components(scene: &Scene) -> Vec<(&'static str, String)> {
    let mut components = vec![
        ("sxx", "σxx".to_string()),
        ("szz", "σzz".to_string()),
        ("sxz", "τxz".to_string()),
        ("tau1", "τ1".to_string()),
        ("von_mises", "σvM".to_string()),
    ];
    let quantity = scene.figure.quantity;
    if !components.iter().any(|(key, _)| *key == quantity.key()) {
        components.push((quantity.key(), quantity.symbol().to_string()));
    }
    components
}

/// A chart drawn as PNG bytes, for an `EncodedImage`.
pub(super) fn chart_png_bytes(chart: &Chart) -> Result<Vec<u8>, RecordError> {
    let image = chart_png(chart).map_err(|e| RecordError::Rerun(e.to_string()))?;
    crate::render::encode_png(&image).map_err(|e| RecordError::Rerun(e.to_string()))
}

/// The viewer layout: the section maps (and the 3-D volume) take most of the window; beside
/// them, tabs of plots (against the swept parameter, by step, the stress histories) over tabs
/// of documents (the description, the raw values, the steps).
pub(super) fn plan_layout(
    scene: &Scene,
    figure: &Figure,
    frames: &[Frame],
    levels: &[f64],
) -> Layout {
    let section_name = |k: usize| {
        let mut name = format!(
            "{} · {} section",
            figure.value_label,
            scene.panels[k].section.key()
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
                        "volume: iso-surfaces of {} at {} (half box y ≤ 0, z down)",
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
    // The raw values in the map's colours and colour range, so the map's colour bar reads them
    // (the tensor view draws none of its own).
    for (k, panel) in figure.panels.iter().enumerate() {
        documents.push(Node::View(View::new(
            ViewKind::Tensor(super::rerun_colormap(section::panel_colormap(
                figure, panel,
            ))),
            format!("values {}", k + 1),
            format!("sections/{k}/values"),
        )));
    }
    // Beside the map, short tab names that all fit (issue 23, item 4): a moving load's stress
    // histories in one group, above the charts against the parameter (with the extremes by
    // step, which the viewer can hover and zoom), above the documents.
    let mut histories = Vec::new();
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
        let several = figure.panels.len() > 1;
        let panel_suffix = |k: usize| {
            if several {
                format!(", panel {}", k + 1)
            } else {
                String::new()
            }
        };
        for k in 0..figure.panels.len() {
            for j in 0..sweep.material_points.len() {
                histories.push(Node::View(View::new(
                    ViewKind::TimeSeries,
                    format!("point {j} {unit}{}", panel_suffix(k)),
                    format!("history/{k}/point{j}"),
                )));
            }
            // Native plots (hover, zoom) against the parameter's own timeline, which the time
            // panel opens on ([`super::value_timeline`]).
            // "max, min" only where both are plotted.
            let (extremes, contents): (&str, &[&str]) = if marks_minimum(figure.mark) {
                ("max, min", &["$origin/maximum", "$origin/minimum"])
            } else {
                ("max", &["$origin/maximum"])
            };
            plots.push(Node::View(
                View::new(
                    ViewKind::TimeSeries,
                    format!("{extremes} {unit} vs {parameter}{}", panel_suffix(k)),
                    format!("series/{k}"),
                )
                .with_contents(contents),
            ));
            if figure.axes_of(&figure.panels[k]).vertical_is_depth {
                plots.push(Node::View(
                    View::new(
                        ViewKind::TimeSeries,
                        format!("depth vs {parameter}{}", panel_suffix(k)),
                        format!("series/{k}"),
                    )
                    .with_contents(&["$origin/maximum_depth"]),
                ));
            }
        }
    }
    let documents = Node::Tabs(documents, 0);
    let side = match (histories.is_empty(), plots.is_empty()) {
        (_, true) => documents,
        (true, false) => Node::Vertical(vec![Node::Tabs(plots, 0), documents], vec![1.3, 1.0]),
        (false, false) => Node::Vertical(
            // The histories run over about 1.6 p0 (σzz to σvM): tall enough for the viewer to
            // label their axis every 0.1 p0, not only at 0.
            vec![Node::Tabs(histories, 0), Node::Tabs(plots, 0), documents],
            vec![1.6, 0.9, 0.6],
        ),
    };
    Layout {
        root: Node::Horizontal(vec![main, side], vec![MAIN_SHARE, SIDE_SHARE]),
        timeline: scene
            .sweep
            .as_ref()
            .filter(|s| s.values.len() > 1)
            .map(|_| {
                super::value_timeline(scene).map_or_else(|| timeline(scene).to_string(), |v| v.name)
            }),
    }
}

/// The iso-levels with their unit, innermost last: `0.198, 0.33, 0.46, 0.594 p0`.
pub(super) fn levels_text(scene: &Scene, levels: &[f64]) -> String {
    let values: Vec<String> = levels.iter().map(|&l| section::short(l)).collect();
    let unit = section::stress_text(scene, 1.0);
    let unit = unit.trim_start_matches(|c: char| !c.is_whitespace());
    format!("{}{unit}", values.join(", "))
}

/// Plots the stresses at the sweep's material points (body frame) as a moving load passes,
/// computed by [`study::panels::material_point_stresses`]: `σxx`, `σzz`, `τxz`, τ1, σvM and
/// the figure's quantity, in the figure's stress unit.
pub(super) fn log_material_points(
    stream: &RecordingStream,
    scene: &Scene,
) -> Result<(), RecordError> {
    let stresses = study::panels::material_point_stresses(scene).map_err(RecordError::Field)?;
    let stress_per_p0 = study::DisplayUnits::of(scene).stress_per_p0;
    let quantity = scene.figure.quantity;
    for (k, points) in stresses.iter().enumerate() {
        for (j, s) in points.iter().enumerate() {
            let base = format!("history/{k}/point{j}");
            for (key, _) in history_components(scene) {
                let value = match key {
                    "sxx" => s.xx,
                    "szz" => s.zz,
                    "sxz" => s.xz,
                    "tau1" => crate::stress::Quantity::Tau1.of(s),
                    "von_mises" => crate::stress::Quantity::VonMises.of(s),
                    _ => quantity.of(s),
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

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
        let figure = figure::build(&coarse_step, &study::panel_fields(&coarse_step, &|| {})?);
        for (span, panel) in spans.iter_mut().zip(&figure.panels) {
            for &v in panel.values.iter().filter(|v| v.is_finite()) {
                *span = (span.0.min(v), span.1.max(v));
            }
        }
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
                range: Some(ranges[k]),
                surface: figure0.axes_of(panel).vertical_is_depth,
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
            None => figure::build(&step_scene, &study::panel_fields(&step_scene, on_row)?),
        };
        stream.set_time_sequence(timeline, step_time(step));
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

/// Names and colours of the plotted series (static).
pub(super) fn log_series_styles(
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

/// The extremes of panel `k` and the depth of its maximum against the swept parameter, for the
/// steps so far (the current one marked), drawn as chart images. `history` holds (max, min,
/// depth of max) per step.
pub(super) fn log_charts(
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
    let axes = figure.axes_of(&figure.panels[k]);
    if axes.vertical_is_depth {
        let mut depth = Chart::new(
            &format!("depth of the maximum of {symbol}"),
            &x_label,
            axes.z_label,
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
    for k in 0..figure.panels.len() {
        documents.push(Node::View(View::new(
            ViewKind::Tensor,
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
            plots.push(Node::View(View::new(
                ViewKind::Spatial2D(None),
                format!("max, min vs {parameter}{}", panel_suffix(k)),
                format!("charts/{k}/maximum"),
            )));
            if figure.axes_of(&figure.panels[k]).vertical_is_depth {
                plots.push(Node::View(View::new(
                    ViewKind::Spatial2D(None),
                    format!("depth vs {parameter}{}", panel_suffix(k)),
                    format!("charts/{k}/depth"),
                )));
            }
            plots.push(Node::View(
                View::new(
                    ViewKind::TimeSeries,
                    format!("by step{}", panel_suffix(k)),
                    format!("series/{k}"),
                )
                .with_contents(&["$origin/maximum", "$origin/minimum"]),
            ));
        }
    }
    let documents = Node::Tabs(documents, 0);
    let side = match (histories.is_empty(), plots.is_empty()) {
        (_, true) => documents,
        (true, false) => Node::Vertical(vec![Node::Tabs(plots, 0), documents], vec![1.3, 1.0]),
        (false, false) => Node::Vertical(
            vec![Node::Tabs(histories, 0), Node::Tabs(plots, 0), documents],
            vec![1.1, 1.0, 0.9],
        ),
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
pub(super) fn levels_text(scene: &Scene, levels: &[f64]) -> String {
    let values: Vec<String> = levels.iter().map(|&l| section::short(l)).collect();
    let unit = section::stress_text(scene, 1.0);
    let unit = unit.trim_start_matches(|c: char| !c.is_whitespace());
    format!("{}{unit}", values.join(", "))
}

/// Stresses at the sweep's material points (body frame) as a moving load passes: `σxx`,
/// `σzz`, `τxz` and the figure's quantity, in the figure's stress unit.
pub(super) fn log_material_points(
    stream: &RecordingStream,
    scene: &Scene,
) -> Result<(), RecordError> {
    let Some(sweep) = &scene.sweep else {
        return Ok(());
    };
    if sweep.material_points.is_empty() {
        return Ok(());
    }
    let unit_over_a = scene.length_unit_over_a();
    let stress_per_p0 = study::DisplayUnits::of(scene).stress_per_p0;
    let quantity = scene.figure.quantity;
    for (k, panel) in scene.panels.iter().enumerate() {
        let solution = study::solution(scene, panel)
            .map_err(|e| RecordError::Field(FieldError::Numerical(e.to_string())))?;
        let y = match panel.section {
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
                    "tau1" => crate::stress::Quantity::Tau1.of(&s),
                    "von_mises" => crate::stress::Quantity::VonMises.of(&s),
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

//! One section panel in a 2-D view: the field as a depth image with a colour bar beside it
//! (ticks labelled in the figure's unit), the traction profiles above the surface, a title row
//! with the step's parameters, and the marked extremes, every label placed where it cannot
//! cover another.
//!
//! Coordinates are the figure's (x/a or mm to the right, depth downwards; the strip of the
//! tractions is above the surface, `z < 0`). The viewer draws a label centred below its point
//! at a fixed text size, so where labels go depends on the view's size in pixels: the layout
//! estimates it ([`Frame::new`]) and sets the view's visible area to the frame's bounds, so
//! that the estimate holds when the recording opens.

mod frame;
mod labels;
mod notation;
pub use frame::*;
pub use labels::*;
pub use notation::*;

use rerun::RecordingStream;

use super::{rerun_colormap, RecordError};
use crate::render::{ColorMap, Figure, Mark, Panel};
use crate::scene::Scene;

/// The colour map of a panel.
pub fn panel_colormap(figure: &Figure, panel: &Panel) -> ColorMap {
    panel.scale.as_ref().map_or(figure.colormap, |s| s.colormap)
}

/// The colour-bar caption of a panel (with its unit).
pub fn panel_caption(figure: &Figure, panel: &Panel) -> String {
    panel
        .scale
        .as_ref()
        .map_or(figure.value_label.clone(), |s| s.value_label.clone())
}

/// The longest colour-bar tick label of a range (for [`Frame::new`]).
pub fn longest_tick(range: (f64, f64)) -> usize {
    tick_texts(&nice_ticks(range.0, range.1, 8))
        .iter()
        .map(|t| t.chars().count())
        .max()
        .unwrap_or(4)
}

/// What stays from step to step in a map's view.
pub struct Fixed<'a> {
    pub map: ColorMap,
    /// The colour bar's caption, with its unit.
    pub caption: &'a str,
    /// The colour range of every step, or `None` when it changes from step to step (the
    /// caller then logs the bar at each step with [`log_colour_bar`]).
    pub range: Option<(f64, f64)>,
    /// A line along the surface (z = 0), for a section in depth.
    pub surface: bool,
    /// Material points (displayed coordinates), marked with a dot.
    pub material: &'a [(f64, f64)],
}

/// Logs what does not change from step to step: the field's placement, a thin border around
/// it, the colour bar with its ticks and caption (with a fixed range), the surface line, and
/// the material points.
pub fn log_static(
    stream: &RecordingStream,
    base: &str,
    frame: &Frame,
    panel: &Panel,
    fixed: &Fixed<'_>,
) -> Result<(), RecordError> {
    let (du, dv) = (step(&panel.x), step(&panel.z));
    // Pixel (i, j) covers [i, i + 1) x [j, j + 1): its centre i + 1/2 maps to sample i.
    stream.log_static(
        format!("{base}/field"),
        &rerun::Transform3D::from_translation_scale(
            [frame.u.0 as f32, frame.v.0 as f32, 0.0],
            [du as f32, dv as f32, 1.0],
        ),
    )?;
    let (u0, u1, v0, v1) = (
        frame.u.0 as f32,
        frame.u.1 as f32,
        frame.v.0 as f32,
        frame.v.1 as f32,
    );
    stream.log_static(
        format!("{base}/border"),
        &rerun::LineStrips2D::new([[[u0, v0], [u1, v0], [u1, v1], [u0, v1], [u0, v0]]])
            .with_colors([rerun::Color::from_rgb(110, 110, 110)])
            .with_radii([rerun::Radius::new_ui_points(0.5)]),
    )?;
    if let Some(range) = fixed.range {
        log_colour_bar(
            stream,
            When::Static,
            base,
            frame,
            fixed.map,
            fixed.caption,
            range,
        )?;
    }
    if fixed.surface {
        let surface = [[frame.u.0 as f32, 0.0], [frame.u.1 as f32, 0.0]];
        stream.log_static(
            format!("{base}/surface"),
            &rerun::LineStrips2D::new([surface])
                .with_colors([rerun::Color::from_rgb(170, 170, 170)])
                .with_radii([rerun::Radius::new_ui_points(1.0)]),
        )?;
    }
    if !fixed.material.is_empty() {
        let points: Vec<[f32; 2]> = fixed
            .material
            .iter()
            .map(|&(x, z)| [x as f32, z as f32])
            .collect();
        stream.log_static(
            format!("{base}/material_points"),
            &rerun::Points2D::new(points)
                .with_radii([rerun::Radius::new_ui_points(4.0)])
                .with_colors([rerun::Color::from_rgb(20, 20, 20)]),
        )?;
    }
    Ok(())
}

/// Logs a colour bar beside the field (statically, or at the current step when the range
/// changes from step to step): the colour map over `range` as an image, high values at the
/// top, its ticks and their labels, and `caption` (the quantity and its unit) above it.
pub fn log_colour_bar(
    stream: &RecordingStream,
    when: When,
    base: &str,
    frame: &Frame,
    map: ColorMap,
    caption: &str,
    range: (f64, f64),
) -> Result<(), RecordError> {
    // The colour bar: the same colour map and range as the field, high values at the top.
    const BAR_ROWS: usize = 256;
    let (lo, hi) = range;
    let bar = ndarray::Array2::from_shape_fn((BAR_ROWS, 1), |(row, _)| {
        (hi - (hi - lo) * (row as f64 + 0.5) / BAR_ROWS as f64) as f32
    });
    // The image is a child entity: the ticks and labels beside it are not scaled by its
    // placement.
    put(
        stream,
        when,
        format!("{base}/colorbar/image"),
        &rerun::Transform3D::from_translation_scale(
            [frame.bar.0 as f32, frame.v.0 as f32, 0.0],
            [
                (frame.bar.1 - frame.bar.0) as f32,
                ((frame.v.1 - frame.v.0) / BAR_ROWS as f64) as f32,
                1.0,
            ],
        ),
    )?;
    put(
        stream,
        when,
        format!("{base}/colorbar/image"),
        &rerun::DepthImage::try_from(bar)
            .map_err(|e| RecordError::Rerun(e.to_string()))?
            .with_meter(1.0)
            .with_colormap(rerun_colormap(map))
            .with_depth_range(colour_range(map, lo, hi)),
    )?;
    let to_v = |value: f64| frame.v.1 - (value - lo) / (hi - lo) * (frame.v.1 - frame.v.0);
    let bar_px = (frame.v.1 - frame.v.0) * frame.px;
    let most = ((bar_px / (2.0 * LABEL_PX)).floor() as usize).clamp(2, 8);
    let ticks = nice_ticks(lo, hi, most);
    let tick_length = 5.0 / frame.px;
    let strips: Vec<Vec<[f32; 2]>> = ticks
        .iter()
        .map(|&t| {
            let v = to_v(t) as f32;
            vec![
                [frame.bar.1 as f32, v],
                [(frame.bar.1 + tick_length) as f32, v],
            ]
        })
        .collect();
    put(
        stream,
        when,
        format!("{base}/colorbar/ticks"),
        &rerun::LineStrips2D::new(strips)
            .with_colors([rerun::Color::from_rgb(220, 220, 220)])
            .with_radii([rerun::Radius::new_ui_points(0.75)]),
    )?;
    let texts = tick_texts(&ticks);
    let longest = texts.iter().map(|t| t.chars().count()).max().unwrap_or(1);
    let label_u =
        frame.bar.1 + tick_length + (3.0 + 0.5 * (longest as f64 * CHAR_PX + 10.0)) / frame.px;
    let mut anchors: Vec<[f32; 2]> = ticks
        .iter()
        .map(|&t| frame.anchor(label_u, to_v(t)))
        .collect();
    let mut labels = texts;
    // The caption: the quantity and its unit, above the bar.
    anchors.push(frame.anchor(
        0.5 * (frame.bar.0 + frame.bar.1),
        frame.v.0 - 1.2 * frame.label_height(),
    ));
    labels.push(caption.to_string());
    put(
        stream,
        when,
        format!("{base}/colorbar/labels"),
        &rerun::Points2D::new(anchors)
            .with_radii([rerun::Radius::new_ui_points(0.0)])
            .with_colors([rerun::Color::from_rgb(230, 230, 230)])
            .with_labels(labels)
            .with_show_labels(true),
    )?;
    Ok(())
}

pub use crate::figure::{extremes, Extreme};

/// The range a map's colours run over, as Rerun reads it. Rerun's one diverging map
/// (Spectral) runs from red at the range's first end to blue at its second, the other way from
/// the figures' (tension, positive, red): a diverging map's range is given high end first, so
/// that positive values are red in the recordings too.
fn colour_range(map: ColorMap, lo: f64, hi: f64) -> rerun::components::ValueRange {
    match map {
        ColorMap::Diverging => rerun::components::ValueRange::new(hi, lo),
        _ => rerun::components::ValueRange::new(lo, hi),
    }
}

/// An extreme smaller than this fraction of the colour range's largest magnitude is not
/// marked: the far end of a lobe cut by the map's edge, or the flat remainder of a signed
/// field where the load has not arrived yet, is no feature worth a label (the charts still
/// plot it).
pub const NEGLIGIBLE: f64 = 0.05;

/// What changes from step to step in a map's view, besides the field.
pub struct Changing<'a> {
    /// The title row (the step's parameters).
    pub title: &'a str,
    pub notation: &'a Notation,
    /// Which extremes to mark.
    pub mark: Mark,
    /// Material points (displayed coordinates), labelled.
    pub material: &'a [(f64, f64)],
    /// Also log the raw values as a tensor (`<base>/values`).
    pub values: bool,
    /// The traction the strip's height stands for, fixed over a sweep (so the profiles grow
    /// with the load); `None`: the step's own largest traction.
    pub traction_peak: Option<f64>,
}

/// The panel (as [`displayed`]) at the current step, or statically: field, raw values,
/// tractions with their legend, the title row, outlines and the marked extremes.
#[allow(clippy::too_many_arguments)]
pub fn log_step(
    stream: &RecordingStream,
    when: When,
    base: &str,
    frame: &Frame,
    figure: &Figure,
    panel: &Panel,
    range: (f64, f64),
    changing: &Changing<'_>,
) -> Result<(), RecordError> {
    let values32 = panel.values.mapv(|v| v as f32);
    let map = panel_colormap(figure, panel);
    put(
        stream,
        when,
        format!("{base}/field"),
        &rerun::DepthImage::try_from(values32.clone())
            .map_err(|e| RecordError::Rerun(e.to_string()))?
            .with_meter(1.0)
            .with_colormap(rerun_colormap(map))
            .with_depth_range(colour_range(map, range.0, range.1)),
    )?;
    if changing.values {
        put(
            stream,
            when,
            format!("{base}/values"),
            // The map's colour range (its view's tab names the colour map): the colours read
            // on the map's colour bar.
            &rerun::Tensor::try_from(values32)
                .map_err(|e| RecordError::Rerun(e.to_string()))?
                .with_dim_names({
                    let axes = figure.axes_of(panel);
                    [axes.z_label.to_string(), axes.x_label.to_string()]
                })
                .with_value_range(colour_range(map, range.0, range.1)),
        )?;
    }
    let notation = changing.notation;
    let centre_u = 0.5 * (frame.u.0 + frame.u.1);
    let mut row_anchors = vec![frame.anchor(centre_u, frame.title_row)];
    let mut row_labels = vec![changing.title.to_string()];
    let mut row_colours = vec![rerun::Color::from_rgb(235, 235, 235)];
    if frame.strip > 0.0 {
        let peak = panel
            .traction
            .iter()
            .map(|s| s.p.abs().max(s.q.abs()))
            .fold(0.0f64, f64::max);
        if peak > 0.0 {
            let scale = frame.strip / changing.traction_peak.unwrap_or(peak).max(peak);
            let profile = |f: &dyn Fn(&crate::render::TractionSample) -> f64| -> Vec<[f32; 2]> {
                panel
                    .traction
                    .iter()
                    .map(|s| [s.x as f32, (-scale * f(s)) as f32])
                    .collect()
            };
            let p_peak = panel.traction.iter().map(|s| s.p).fold(0.0f64, f64::max);
            put(
                stream,
                when,
                format!("{base}/tractions/p"),
                &rerun::LineStrips2D::new([profile(&|s| s.p)])
                    .with_colors([colour(P_COLOUR)])
                    .with_radii([rerun::Radius::new_ui_points(1.5)]),
            )?;
            let width = frame.u.1 - frame.u.0;
            row_anchors.push(frame.anchor(frame.u.0 + 0.25 * width, frame.legend_row));
            row_labels.push(format!("p: peak {}", notation.value(p_peak)));
            row_colours.push(colour(P_COLOUR));
            let q_size = panel
                .traction
                .iter()
                .map(|s| s.q.abs())
                .fold(0.0f64, f64::max);
            if q_size > 0.0 {
                put(
                    stream,
                    when,
                    format!("{base}/tractions/q"),
                    &rerun::LineStrips2D::new([profile(&|s| s.q)])
                        .with_colors([colour(Q_COLOUR)])
                        .with_radii([rerun::Radius::new_ui_points(1.5)]),
                )?;
                row_anchors.push(frame.anchor(frame.u.0 + 0.75 * width, frame.legend_row));
                row_labels.push(format!("q: largest |q| {}", notation.value(q_size)));
                row_colours.push(colour(Q_COLOUR));
            } else {
                put(
                    stream,
                    when,
                    format!("{base}/tractions/q"),
                    &rerun::Clear::flat(),
                )?;
            }
        }
    }
    put(
        stream,
        when,
        format!("{base}/title"),
        &rerun::Points2D::new(row_anchors.clone())
            .with_radii([rerun::Radius::new_ui_points(0.0)])
            .with_colors(row_colours)
            .with_labels(row_labels.clone())
            .with_show_labels(true),
    )?;
    if !panel.outlines.is_empty() {
        let strips: Vec<Vec<[f32; 2]>> = panel
            .outlines
            .iter()
            .map(|line| line.iter().map(|&(u, v)| [u as f32, v as f32]).collect())
            .collect();
        put(
            stream,
            when,
            format!("{base}/outline"),
            &rerun::LineStrips2D::new(strips)
                .with_colors([rerun::Color::from_rgb(255, 255, 255)])
                .with_radii([rerun::Radius::new_ui_points(0.75)]),
        )?;
    }
    // The extremes worth marking and the material points, labelled without overlaps.
    let largest_magnitude = range.0.abs().max(range.1.abs());
    let worth = |e: Option<Extreme>| e.filter(|e| e.value.abs() >= NEGLIGIBLE * largest_magnitude);
    let (largest, smallest) = extremes(panel, changing.mark);
    let (largest, smallest) = (worth(largest), worth(smallest));
    let mut wanted: Vec<((f64, f64), String)> = Vec::new();
    // A label is wanted just below its point.
    let below = |(u, v): (f64, f64)| (u, v + 0.9 * frame.label_height());
    let mut marks = Vec::new();
    for (name, word, extreme) in [("maximum", "max", largest), ("minimum", "min", smallest)] {
        if let Some(e) = extreme {
            wanted.push((
                below((e.u, e.v)),
                format!(
                    "{word} {} = {} at {}",
                    notation.symbol,
                    notation.value(e.value),
                    notation.position(e.u, e.v)
                ),
            ));
            marks.push((name, e));
        }
    }
    for (j, &(x, z)) in changing.material.iter().enumerate() {
        wanted.push((
            below((x, z)),
            format!("point {j}: {}", notation.position(x, z)),
        ));
    }
    let requests: Vec<((f64, f64), &str)> = wanted
        .iter()
        .map(|(at, text)| (*at, text.as_str()))
        .collect();
    // Label centres of the title and legend rows (their anchors are half a label higher).
    let rows: Vec<((f64, f64), &str)> = row_anchors
        .iter()
        .zip(&row_labels)
        .map(|(a, text)| {
            (
                (
                    f64::from(a[0]),
                    f64::from(a[1]) + 0.5 * frame.label_height(),
                ),
                text.as_str(),
            )
        })
        .collect();
    let dots: Vec<(f64, f64)> = marks
        .iter()
        .map(|(_, e)| (e.u, e.v))
        .chain(changing.material.iter().copied())
        .collect();
    let lines: Vec<(f64, f64)> = panel.outlines.iter().flatten().copied().collect();
    let centres = place_labels(
        frame,
        &requests,
        &Avoid {
            labels: &rows,
            dots: &dots,
            lines: &lines,
        },
    );
    // Whether label `k` had to leave the place it was wanted at (it then gets a leader).
    let moved = |k: usize| {
        let ((cu, cv), (wu, wv)) = (centres[k], requests[k].0);
        (cu - wu).abs() > 1e-9 || (cv - wv).abs() > 1e-9
    };
    for name in ["maximum", "minimum"] {
        match marks.iter().position(|(n, _)| *n == name) {
            Some(index) => {
                let e = marks[index].1;
                let (cu, cv) = centres[index];
                put(
                    stream,
                    when,
                    format!("{base}/{name}"),
                    &rerun::Points2D::new([[e.u as f32, e.v as f32]])
                        .with_radii([rerun::Radius::new_ui_points(4.0)])
                        .with_colors([rerun::Color::from_rgb(255, 255, 255)]),
                )?;
                put(
                    stream,
                    when,
                    format!("{base}/{name}/label"),
                    &rerun::Points2D::new([frame.anchor(cu, cv)])
                        .with_radii([rerun::Radius::new_ui_points(0.0)])
                        .with_colors([rerun::Color::from_rgb(255, 255, 255)])
                        .with_labels([requests[index].1.to_string()])
                        .with_show_labels(true),
                )?;
                // A leader from the mark to a label that had to move.
                let moved = moved(index);
                let leader = [
                    [e.u as f32, e.v as f32],
                    frame.leader_end((cu, cv), (e.u, e.v)),
                ];
                put(
                    stream,
                    when,
                    format!("{base}/{name}/leader"),
                    &rerun::LineStrips2D::new(if moved { vec![leader] } else { Vec::new() })
                        .with_colors([rerun::Color::from_rgb(255, 255, 255)])
                        .with_radii([rerun::Radius::new_ui_points(0.5)]),
                )?;
            }
            None if when == When::Step => {
                stream.log(format!("{base}/{name}"), &rerun::Clear::recursive())?;
            }
            None => {}
        }
    }
    if !changing.material.is_empty() {
        let anchors: Vec<[f32; 2]> = centres[marks.len()..]
            .iter()
            .map(|&(u, v)| frame.anchor(u, v))
            .collect();
        let labels: Vec<String> = requests[marks.len()..]
            .iter()
            .map(|(_, text)| text.to_string())
            .collect();
        put(
            stream,
            when,
            format!("{base}/material_points/labels"),
            // White text on the viewer's dark label box, as the extremes' labels: readable on
            // the map and above the surface alike (dark text vanished there).
            &rerun::Points2D::new(anchors)
                .with_radii([rerun::Radius::new_ui_points(0.0)])
                .with_colors([rerun::Color::from_rgb(255, 255, 255)])
                .with_labels(labels)
                .with_show_labels(true),
        )?;
        // Leaders from the points to the labels that had to move.
        let leaders: Vec<[[f32; 2]; 2]> = changing
            .material
            .iter()
            .enumerate()
            .filter(|&(j, _)| moved(marks.len() + j))
            .map(|(j, &(x, z))| {
                let centre = centres[marks.len() + j];
                [[x as f32, z as f32], frame.leader_end(centre, (x, z))]
            })
            .collect();
        put(
            stream,
            when,
            format!("{base}/material_points/leaders"),
            &rerun::LineStrips2D::new(leaders)
                .with_colors([rerun::Color::from_rgb(128, 128, 128)])
                .with_radii([rerun::Radius::new_ui_points(0.5)]),
        )?;
    }
    Ok(())
}

#[cfg(test)]
mod tests;

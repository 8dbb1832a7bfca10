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

use rerun::RecordingStream;

use super::{rerun_colormap, RecordError};
use crate::render::{ColorMap, Figure, Mark, Panel};
use crate::scene::Scene;

/// Height of a label in pixels, and the width of one of its characters (the viewer's font).
const LABEL_PX: f64 = 18.0;
const CHAR_PX: f64 = 7.5;

/// The p profile: a light blue that reads on the dark background and beside every map.
pub const P_COLOUR: [u8; 3] = [86, 180, 233];
/// The q profile: orange.
pub const Q_COLOUR: [u8; 3] = [230, 159, 0];

fn colour([r, g, b]: [u8; 3]) -> rerun::Color {
    rerun::Color::from_rgb(r, g, b)
}

/// A number with three significant digits, or in exponent form when very small or large;
/// a typographic minus.
pub fn short(value: f64) -> String {
    if value == 0.0 || !value.is_finite() {
        return if value.is_finite() {
            "0".into()
        } else {
            value.to_string()
        };
    }
    let magnitude = value.abs();
    let text = if (1e-3..1e5).contains(&magnitude) {
        let decimals = (2 - magnitude.log10().floor() as i32).max(0) as usize;
        format!("{value:.decimals$}")
    } else {
        format!("{value:.2e}")
    };
    text.replace('-', "\u{2212}")
}

/// A stress with its unit: `0.557 p0`, `612 MPa`.
pub fn stress_text(scene: &Scene, value: f64) -> String {
    use crate::scene::StressUnit;
    let unit = match scene.figure.stress_unit {
        StressUnit::PeakPressure => " p0",
        StressUnit::Pascal => " Pa",
        StressUnit::MegaPascal => " MPa",
        StressUnit::GigaPascal => " GPa",
    };
    format!("{}{unit}", short(value))
}

/// A position in the section with its unit: `(x = −0.45a, z = 0.16a)`.
pub fn position_text(scene: &Scene, u: f64, v: f64) -> String {
    // Rounding noise of a grid through zero reads as zero.
    let snap = |c: f64| if c.abs() < 1e-9 { 0.0 } else { c };
    let (u, v) = (snap(u), snap(v));
    let (horizontal, vertical, _) = scene.figure.section.coordinates();
    let suffix = scene.figure.length_unit.suffix();
    format!(
        "{horizontal} = {}{suffix}, {vertical} = {}{suffix}",
        short(u),
        short(v)
    )
}

/// A point of the volume with its unit: `(x = 0a, y = 0a, z = 0.48a)`.
pub fn position_text_3d(scene: &Scene, [x, y, z]: [f32; 3]) -> String {
    let snap = |c: f32| if c.abs() < 1e-6 { 0.0 } else { c };
    let (x, y, z) = (snap(x), snap(y), snap(z));
    let suffix = scene.figure.length_unit.suffix();
    format!(
        "(x = {}{suffix}, y = {}{suffix}, z = {}{suffix})",
        short(f64::from(x)),
        short(f64::from(y)),
        short(f64::from(z))
    )
}

/// The geometry of a panel's view, in its coordinates.
#[derive(Clone, Debug)]
pub struct Frame {
    /// The field's extent (pixel edges).
    pub u: (f64, f64),
    pub v: (f64, f64),
    /// Height of the traction strip above the surface (0 without tractions).
    pub strip: f64,
    /// Pixels per unit (estimated from the view's size).
    pub px: f64,
    /// The colour bar's horizontal extent.
    pub bar: (f64, f64),
    /// Centres of the title row and of the legend row (above the strip).
    pub title_row: f64,
    pub legend_row: f64,
    /// What the view shows at first: `[u_min, u_max, v_min, v_max]`.
    pub bounds: [f64; 4],
}

impl Frame {
    /// The frame of `panel` in a view of about `view_px` pixels (width, height); `tick_chars`
    /// is the longest colour-bar label.
    pub fn new(panel: &Panel, has_strip: bool, view_px: (f64, f64), tick_chars: usize) -> Self {
        let (du, dv) = (step(&panel.x), step(&panel.z));
        let u = (panel.x.min - 0.5 * du, panel.x.max + 0.5 * du);
        let v = (panel.z.min - 0.5 * dv, panel.z.max + 0.5 * dv);
        let (width, depth) = (u.1 - u.0, v.1 - v.0);
        let strip = if has_strip { 0.2 * depth } else { 0.0 };
        // Two passes: the text's size in units depends on the scale, the scale on the bounds.
        let mut px = (view_px.0 / (1.3 * width)).min(view_px.1 / (1.5 * depth));
        let mut frame = None;
        for _ in 0..2 {
            let label = LABEL_PX / px;
            let gap = 8.0 / px;
            let bar = (u.1 + 0.03 * width, u.1 + 0.03 * width + 16.0 / px);
            let legend_row = v.0 - strip - 1.1 * label;
            let title_row = if has_strip {
                legend_row - 1.4 * label
            } else {
                v.0 - 1.1 * label
            };
            let right = bar.1 + gap + (tick_chars as f64 * CHAR_PX + 12.0) / px;
            let bounds = [u.0 - gap, right, title_row - 0.9 * label, v.1 + 2.5 * label];
            let fit =
                (view_px.0 / (bounds[1] - bounds[0])).min(view_px.1 / (bounds[3] - bounds[2]));
            frame = Some(Self {
                u,
                v,
                strip,
                px: fit,
                bar,
                title_row,
                legend_row,
                bounds,
            });
            px = fit;
        }
        frame.expect("two passes")
    }

    fn label_height(&self) -> f64 {
        LABEL_PX / self.px
    }

    /// The anchor point of a label whose text is centred at `(u, v)`.
    fn anchor(&self, u: f64, v: f64) -> [f32; 2] {
        [u as f32, (v - 0.5 * self.label_height()) as f32]
    }
}

fn step(axis: &crate::field::Axis) -> f64 {
    if axis.count > 1 {
        axis.step()
    } else {
        1.0
    }
}

/// A label's box in units, centred at `(u, v)`.
#[derive(Clone, Copy, Debug)]
struct LabelBox {
    u: f64,
    v: f64,
    half_width: f64,
    half_height: f64,
}

impl LabelBox {
    fn overlaps(&self, other: &LabelBox) -> bool {
        (self.u - other.u).abs() < self.half_width + other.half_width
            && (self.v - other.v).abs() < self.half_height + other.half_height
    }
}

/// Places labels at their preferred centres, moving each one that would cover an earlier one
/// down (then up) by label heights until it is clear. Returns the centres.
fn place_labels(frame: &Frame, wanted: &[((f64, f64), &str)]) -> Vec<(f64, f64)> {
    let height = frame.label_height();
    let mut placed: Vec<LabelBox> = Vec::new();
    let mut centres = Vec::new();
    for &((u, v), text) in wanted {
        let half_width = 0.5 * (text.chars().count() as f64 * CHAR_PX + 10.0) / frame.px;
        let candidate = |shift: f64| LabelBox {
            u,
            v: v + shift * height,
            half_width,
            half_height: 0.5 * height,
        };
        let shifts = (0..12).flat_map(|k| [f64::from(k), -f64::from(k)]);
        let chosen = shifts
            .map(candidate)
            .find(|b| placed.iter().all(|p| !b.overlaps(p)))
            .unwrap_or_else(|| candidate(0.0));
        centres.push((chosen.u, chosen.v));
        placed.push(chosen);
    }
    centres
}

/// Nice tick values within `[lo, hi]`: at most `most` of them, steps of 1, 2 or 5 x 10^k.
pub fn nice_ticks(lo: f64, hi: f64, most: usize) -> Vec<f64> {
    if !(lo.is_finite() && hi.is_finite()) || hi <= lo || most < 2 {
        return vec![lo, hi];
    }
    let raw = (hi - lo) / (most - 1) as f64;
    let magnitude = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * magnitude)
        .find(|s| (((hi - lo) / s).floor() as usize) < most)
        .unwrap_or(10.0 * magnitude);
    let first = (lo / step - 1e-9).ceil() as i64;
    let last = (hi / step + 1e-9).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

/// The colour map of a panel.
pub fn panel_colormap(figure: &Figure, panel: &Panel) -> ColorMap {
    panel.scale.as_ref().map_or(figure.colormap, |s| s.colormap)
}

/// Logs what does not change from step to step: the field's placement, the colour bar with
/// its ticks and caption, the surface line, and the material points.
pub fn log_static(
    stream: &RecordingStream,
    base: &str,
    frame: &Frame,
    figure: &Figure,
    panel: &Panel,
    range: (f64, f64),
    scene: &Scene,
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
    // The colour bar: the same colour map and range as the field, high values at the top.
    const BAR_ROWS: usize = 256;
    let (lo, hi) = range;
    let bar = ndarray::Array2::from_shape_fn((BAR_ROWS, 1), |(row, _)| {
        (hi - (hi - lo) * (row as f64 + 0.5) / BAR_ROWS as f64) as f32
    });
    let map = panel_colormap(figure, panel);
    // The image is a child entity: the ticks and labels beside it are not scaled by its
    // placement.
    stream.log_static(
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
    stream.log_static(
        format!("{base}/colorbar/image"),
        &rerun::DepthImage::try_from(bar)
            .map_err(|e| RecordError::Rerun(e.to_string()))?
            .with_meter(1.0)
            .with_colormap(rerun_colormap(map))
            .with_depth_range(rerun::components::ValueRange::new(lo, hi)),
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
    stream.log_static(
        format!("{base}/colorbar/ticks"),
        &rerun::LineStrips2D::new(strips)
            .with_colors([rerun::Color::from_rgb(220, 220, 220)])
            .with_radii([rerun::Radius::new_ui_points(0.75)]),
    )?;
    let texts: Vec<String> = ticks.iter().map(|&t| short(t)).collect();
    let longest = texts.iter().map(|t| t.chars().count()).max().unwrap_or(1);
    let label_u =
        frame.bar.1 + tick_length + (3.0 + 0.5 * (longest as f64 * CHAR_PX + 10.0)) / frame.px;
    let mut anchors: Vec<[f32; 2]> = ticks
        .iter()
        .map(|&t| frame.anchor(label_u, to_v(t)))
        .collect();
    let mut labels = texts;
    // The caption: the quantity and its unit, above the bar.
    let caption = panel
        .scale
        .as_ref()
        .map_or(figure.value_label.clone(), |s| s.value_label.clone());
    anchors.push(frame.anchor(
        0.5 * (frame.bar.0 + frame.bar.1),
        frame.v.0 - 1.2 * frame.label_height(),
    ));
    labels.push(caption);
    stream.log_static(
        format!("{base}/colorbar/labels"),
        &rerun::Points2D::new(anchors)
            .with_radii([rerun::Radius::new_ui_points(0.0)])
            .with_colors([rerun::Color::from_rgb(230, 230, 230)])
            .with_labels(labels)
            .with_show_labels(true),
    )?;
    if figure.vertical_is_depth {
        let surface = [[frame.u.0 as f32, 0.0], [frame.u.1 as f32, 0.0]];
        stream.log_static(
            format!("{base}/surface"),
            &rerun::LineStrips2D::new([surface])
                .with_colors([rerun::Color::from_rgb(170, 170, 170)])
                .with_radii([rerun::Radius::new_ui_points(1.0)]),
        )?;
    }
    if let Some(sweep) = &scene.sweep {
        if !sweep.material_points.is_empty() {
            let points: Vec<[f32; 2]> = sweep
                .material_points
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
    }
    Ok(())
}

/// One extreme of a map: its value and position (figure units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Extreme {
    pub value: f64,
    pub u: f64,
    pub v: f64,
}

/// The extremes the figure marks (its [`Mark`]): the largest and/or the smallest finite value.
pub fn extremes(panel: &Panel, mark: Mark) -> (Option<Extreme>, Option<Extreme>) {
    let finite = || panel.values.indexed_iter().filter(|(_, v)| v.is_finite());
    let at = |((row, column), &value): ((usize, usize), &f64)| Extreme {
        value,
        u: panel.x.value(column),
        v: panel.z.value(row),
    };
    let largest = finite().max_by(|a, b| a.1.total_cmp(b.1)).map(at);
    let smallest = finite().min_by(|a, b| a.1.total_cmp(b.1)).map(at);
    match mark {
        Mark::Max => (largest, None),
        Mark::Min => (None, smallest),
        Mark::Both => (largest, smallest),
        Mark::None => (None, None),
    }
}

/// The panel at the current step: field, raw values, tractions with their legend, the title
/// row, and the marked extremes.
#[allow(clippy::too_many_arguments)]
pub fn log_step(
    stream: &RecordingStream,
    base: &str,
    frame: &Frame,
    figure: &Figure,
    panel: &Panel,
    range: (f64, f64),
    scene: &Scene,
    title: &str,
) -> Result<(), RecordError> {
    let values32 = panel.values.mapv(|v| v as f32);
    let map = panel_colormap(figure, panel);
    stream.log(
        format!("{base}/field"),
        &rerun::DepthImage::try_from(values32.clone())
            .map_err(|e| RecordError::Rerun(e.to_string()))?
            .with_meter(1.0)
            .with_colormap(rerun_colormap(map))
            .with_depth_range(rerun::components::ValueRange::new(range.0, range.1)),
    )?;
    stream.log(
        format!("{base}/values"),
        &rerun::Tensor::try_from(values32)
            .map_err(|e| RecordError::Rerun(e.to_string()))?
            .with_dim_names([figure.z_label.clone(), figure.x_label.clone()]),
    )?;
    let centre_u = 0.5 * (frame.u.0 + frame.u.1);
    let mut row_anchors = vec![frame.anchor(centre_u, frame.title_row)];
    let mut row_labels = vec![title.to_string()];
    let mut row_colours = vec![rerun::Color::from_rgb(235, 235, 235)];
    if frame.strip > 0.0 {
        let peak = panel
            .traction
            .iter()
            .map(|s| s.p.abs().max(s.q.abs()))
            .fold(0.0f64, f64::max);
        if peak > 0.0 {
            let scale = frame.strip / peak;
            let profile = |f: &dyn Fn(&crate::render::TractionSample) -> f64| -> Vec<[f32; 2]> {
                panel
                    .traction
                    .iter()
                    .map(|s| [s.x as f32, (-scale * f(s)) as f32])
                    .collect()
            };
            let p_peak = panel.traction.iter().map(|s| s.p).fold(0.0f64, f64::max);
            stream.log(
                format!("{base}/tractions/p"),
                &rerun::LineStrips2D::new([profile(&|s| s.p)])
                    .with_colors([colour(P_COLOUR)])
                    .with_radii([rerun::Radius::new_ui_points(1.5)]),
            )?;
            let width = frame.u.1 - frame.u.0;
            row_anchors.push(frame.anchor(frame.u.0 + 0.25 * width, frame.legend_row));
            row_labels.push(format!("p: peak {}", stress_text(scene, p_peak)));
            row_colours.push(colour(P_COLOUR));
            let q_size = panel
                .traction
                .iter()
                .map(|s| s.q.abs())
                .fold(0.0f64, f64::max);
            if q_size > 0.0 {
                stream.log(
                    format!("{base}/tractions/q"),
                    &rerun::LineStrips2D::new([profile(&|s| s.q)])
                        .with_colors([colour(Q_COLOUR)])
                        .with_radii([rerun::Radius::new_ui_points(1.5)]),
                )?;
                row_anchors.push(frame.anchor(frame.u.0 + 0.75 * width, frame.legend_row));
                row_labels.push(format!("q: largest |q| {}", stress_text(scene, q_size)));
                row_colours.push(colour(Q_COLOUR));
            } else {
                stream.log(format!("{base}/tractions/q"), &rerun::Clear::flat())?;
            }
        }
    }
    stream.log(
        format!("{base}/title"),
        &rerun::Points2D::new(row_anchors)
            .with_radii([rerun::Radius::new_ui_points(0.0)])
            .with_colors(row_colours)
            .with_labels(row_labels)
            .with_show_labels(true),
    )?;
    if !panel.outlines.is_empty() {
        let strips: Vec<Vec<[f32; 2]>> = panel
            .outlines
            .iter()
            .map(|line| line.iter().map(|&(u, v)| [u as f32, v as f32]).collect())
            .collect();
        stream.log(
            format!("{base}/outline"),
            &rerun::LineStrips2D::new(strips).with_colors([rerun::Color::from_rgb(255, 255, 255)]),
        )?;
    }
    // The extremes and the material points, labelled without overlaps.
    let (largest, smallest) = extremes(panel, figure.mark);
    let symbol = scene.figure.quantity.symbol();
    let mut wanted: Vec<((f64, f64), String)> = Vec::new();
    let below = |e: &Extreme| (e.u, e.v + 0.9 * frame.label_height());
    let mut marks = Vec::new();
    if let Some(e) = largest {
        wanted.push((
            below(&e),
            format!(
                "max {symbol} = {} at {}",
                stress_text(scene, e.value),
                position_text(scene, e.u, e.v)
            ),
        ));
        marks.push(("maximum", e));
    }
    if let Some(e) = smallest {
        wanted.push((
            below(&e),
            format!(
                "min {symbol} = {} at {}",
                stress_text(scene, e.value),
                position_text(scene, e.u, e.v)
            ),
        ));
        marks.push(("minimum", e));
    }
    let material: Vec<(f64, f64)> = scene
        .sweep
        .as_ref()
        .map(|s| s.material_points.clone())
        .unwrap_or_default();
    for (j, &(x, z)) in material.iter().enumerate() {
        wanted.push(((x, z + 0.9 * frame.label_height()), format!("point {j}")));
    }
    let requests: Vec<((f64, f64), &str)> = wanted
        .iter()
        .map(|(at, text)| (*at, text.as_str()))
        .collect();
    let centres = place_labels(frame, &requests);
    for name in ["maximum", "minimum"] {
        match marks.iter().position(|(n, _)| *n == name) {
            Some(index) => {
                let e = marks[index].1;
                let (cu, cv) = centres[index];
                stream.log(
                    format!("{base}/{name}"),
                    &rerun::Points2D::new([[e.u as f32, e.v as f32]])
                        .with_radii([rerun::Radius::new_ui_points(4.0)])
                        .with_colors([rerun::Color::from_rgb(255, 255, 255)]),
                )?;
                stream.log(
                    format!("{base}/{name}/label"),
                    &rerun::Points2D::new([frame.anchor(cu, cv)])
                        .with_radii([rerun::Radius::new_ui_points(0.0)])
                        .with_colors([rerun::Color::from_rgb(255, 255, 255)])
                        .with_labels([requests[index].1.to_string()])
                        .with_show_labels(true),
                )?;
                // A leader from the mark to a label that had to move.
                let moved = (cv - below(&e).1).abs() > 1e-9;
                let leader = [
                    [e.u as f32, e.v as f32],
                    [cu as f32, (cv - 0.5 * frame.label_height()) as f32],
                ];
                stream.log(
                    format!("{base}/{name}/leader"),
                    &rerun::LineStrips2D::new(if moved { vec![leader] } else { Vec::new() })
                        .with_colors([rerun::Color::from_rgb(255, 255, 255)])
                        .with_radii([rerun::Radius::new_ui_points(0.5)]),
                )?;
            }
            None => {
                stream.log(format!("{base}/{name}"), &rerun::Clear::recursive())?;
            }
        }
    }
    if !material.is_empty() {
        let anchors: Vec<[f32; 2]> = centres[marks.len()..]
            .iter()
            .map(|&(u, v)| frame.anchor(u, v))
            .collect();
        let labels: Vec<String> = (0..material.len()).map(|j| format!("point {j}")).collect();
        stream.log(
            format!("{base}/material_points/labels"),
            &rerun::Points2D::new(anchors)
                .with_radii([rerun::Radius::new_ui_points(0.0)])
                .with_colors([rerun::Color::from_rgb(20, 20, 20)])
                .with_labels(labels)
                .with_show_labels(true),
        )?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_are_nice_and_inside() {
        let ticks = nice_ticks(0.0, 0.62, 5);
        assert_eq!(ticks.len(), 4);
        for (t, e) in ticks.iter().zip([0.0, 0.2, 0.4, 0.6]) {
            assert!((t - e).abs() < 1e-12, "{ticks:?}");
        }
        let ticks = nice_ticks(-0.3, 0.3, 7);
        assert_eq!(ticks.len(), 7);
        assert!((ticks[0] + 0.3).abs() < 1e-12 && (ticks[6] - 0.3).abs() < 1e-12);
        assert!(nice_ticks(0.0, 1250.0, 6).iter().all(|t| t % 250.0 == 0.0));
    }

    #[test]
    fn short_numbers_keep_three_digits() {
        assert_eq!(short(0.55724), "0.557");
        assert_eq!(short(-0.25), "\u{2212}0.250");
        assert_eq!(short(1234.5), "1234");
        assert_eq!(short(0.0), "0");
        assert_eq!(short(2.5e-6), "2.50e\u{2212}6");
    }

    fn frame() -> Frame {
        Frame {
            u: (-1.0, 1.0),
            v: (0.0, 1.0),
            strip: 0.2,
            px: 100.0,
            bar: (1.05, 1.2),
            title_row: -0.6,
            legend_row: -0.4,
            bounds: [-1.1, 1.6, -0.8, 1.1],
        }
    }

    #[test]
    fn labels_that_would_overlap_are_moved_apart() {
        let frame = frame();
        let wanted = [
            ((0.0, 0.5), "max σvM = 0.557 p0 at x = 0a, z = 0.700a"),
            ((0.05, 0.52), "min σvM = 0.001 p0 at x = 0.1a, z = 0.7a"),
            ((0.9, 0.1), "point 0"),
        ];
        let centres = place_labels(&frame, &wanted);
        assert_eq!(centres[0], (0.0, 0.5));
        // The second is moved a label height or more away; the third, far away, stays.
        assert!((centres[1].1 - 0.52).abs() >= LABEL_PX / frame.px - 1e-9);
        assert_eq!(centres[2], (0.9, 0.1));
        for i in 0..3 {
            for j in 0..i {
                let boxed = |k: usize| LabelBox {
                    u: centres[k].0,
                    v: centres[k].1,
                    half_width: 0.5 * (wanted[k].1.chars().count() as f64 * CHAR_PX + 10.0)
                        / frame.px,
                    half_height: 0.5 * LABEL_PX / frame.px,
                };
                assert!(!boxed(i).overlaps(&boxed(j)), "{i} covers {j}");
            }
        }
    }
}

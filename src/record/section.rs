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
const LABEL_PX: f64 = 21.0;
const CHAR_PX: f64 = 6.3;

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
    crate::io::text::significant(value, 3, 1e5, false)
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

/// A position in the section with its unit: `x = −0.45a, z = 0.16a`.
pub fn position_text(scene: &Scene, u: f64, v: f64) -> String {
    let (horizontal, vertical, _) = scene.figure.section.coordinates();
    let suffix = scene.figure.length_unit.suffix();
    format!(
        "{horizontal} = {}{suffix}, {vertical} = {}{suffix}",
        short(snap(u)),
        short(snap(v))
    )
}

/// Rounding noise of a grid through zero reads as zero.
fn snap(c: f64) -> f64 {
    if c.abs() < 1e-9 {
        0.0
    } else {
        c
    }
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

/// Splits an axis or colour-bar caption into its name and its unit as written after a number:
/// `σvM / p0` gives (`σvM`, ` p0`), `p (MPa)` gives (`p`, ` MPa`), `x/a` gives (`x`, `a`).
fn name_and_unit(label: &str) -> (String, String) {
    let label = label.trim();
    if let (Some(open), true) = (label.rfind(" ("), label.ends_with(')')) {
        let unit = &label[open + 2..label.len() - 1];
        return (label[..open].to_string(), format!(" {unit}"));
    }
    if let Some((name, unit)) = label.rsplit_once(" / ") {
        return (name.to_string(), format!(" {unit}"));
    }
    if let Some((name, unit)) = label.rsplit_once('/') {
        return (name.to_string(), unit.to_string());
    }
    (label.to_string(), String::new())
}

/// How a map's values and positions are written in its labels, from the figure's captions.
#[derive(Clone, Debug, PartialEq)]
pub struct Notation {
    /// The quantity's name, e.g. `σvM`, `p`.
    pub symbol: String,
    /// Its unit as written after a number, e.g. ` p0`, ` MPa`.
    pub unit: String,
    /// The horizontal and vertical coordinates' names and their unit (`x`, `z`, `a`).
    pub axes: (String, String),
    pub length: String,
    /// The map is drawn with its vertical coordinate negated (see [`displayed`]).
    pub flipped: bool,
}

impl Notation {
    /// The notation of a panel of `figure` (its own colour scale's caption if it has one).
    pub fn of(figure: &Figure, panel: &Panel) -> Self {
        let caption = panel
            .scale
            .as_ref()
            .map_or(figure.value_label.as_str(), |s| s.value_label.as_str());
        let (symbol, unit) = name_and_unit(caption);
        let (horizontal, length) = name_and_unit(&figure.x_label);
        let (vertical, _) = name_and_unit(&figure.z_label);
        Self {
            symbol,
            unit,
            axes: (horizontal, vertical),
            length,
            flipped: !figure.vertical_is_depth,
        }
    }

    /// A value with its unit: `0.557 p0`.
    pub fn value(&self, value: f64) -> String {
        format!("{}{}", short(value), self.unit)
    }

    /// A displayed position with its unit: `x = −0.45a, z = 0.16a`.
    pub fn position(&self, u: f64, v: f64) -> String {
        let v = if self.flipped { -v } else { v };
        format!(
            "{} = {}{length}, {} = {}{length}",
            self.axes.0,
            short(snap(u)),
            self.axes.1,
            short(snap(v)),
            length = self.length
        )
    }
}

/// The panel as drawn in a view, whose vertical axis points down: a depth as it is; a map
/// seen from above (y up in the figure) with its rows reversed and its vertical coordinate
/// negated, so that it reads as the PNG figure does. Labels undo the negation
/// ([`Notation::position`]).
pub fn displayed(figure: &Figure, panel: &Panel) -> Panel {
    let mut shown = panel.clone();
    if !figure.vertical_is_depth {
        let rows = panel.values.nrows();
        shown.values = ndarray::Array2::from_shape_fn(panel.values.dim(), |(row, column)| {
            panel.values[[rows - 1 - row, column]]
        });
        shown.z = crate::field::Axis::new(-panel.z.max, -panel.z.min, panel.z.count);
        for line in &mut shown.outlines {
            for point in line.iter_mut() {
                point.1 = -point.1;
            }
        }
    }
    shown
}

/// Whether a row is logged once for the whole recording or at the current step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum When {
    Static,
    Step,
}

/// Logs `archetype` at `path`, statically or at the current step.
pub fn put(
    stream: &RecordingStream,
    when: When,
    path: impl Into<rerun::EntityPath>,
    archetype: &impl rerun::AsComponents,
) -> Result<(), RecordError> {
    match when {
        When::Static => stream.log_static(path, archetype)?,
        When::Step => stream.log(path, archetype)?,
    }
    Ok(())
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

    /// Where a leader from `point` meets the label centred at `centre`: the middle of the
    /// label's top edge, or of its bottom edge for a label above the point.
    fn leader_end(&self, (cu, cv): (f64, f64), (_, v): (f64, f64)) -> [f32; 2] {
        let edge = if cv >= v { -0.5 } else { 0.5 };
        [cu as f32, (cv + edge * self.label_height()) as f32]
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

/// What labels must not cover, besides one another.
#[derive(Clone, Copy, Debug, Default)]
pub struct Avoid<'a> {
    /// Labels already in place (the title and legend rows): centre and text.
    pub labels: &'a [((f64, f64), &'a str)],
    /// Marked points (the extremes, the material points): no label covers one.
    pub dots: &'a [(f64, f64)],
    /// Points along drawn lines (the outlines): covered only where no other place is free.
    pub lines: &'a [(f64, f64)],
}

/// Half the size of the box kept free around a marked point (its dot is 4 points in radius).
const DOT_PX: f64 = 6.0;

/// Places labels at their preferred centres, kept inside the map's width (a label is
/// centred on its point, so one near a side would be cut by the view's edge). A label is wanted
/// just below its point; one that would cover an earlier label, a label of `avoid` or a
/// marked point goes just above it, else further down or up by label heights, and where
/// possible it covers no line either. Returns the centres.
fn place_labels(
    frame: &Frame,
    wanted: &[((f64, f64), &str)],
    avoid: &Avoid<'_>,
) -> Vec<(f64, f64)> {
    let height = frame.label_height();
    let boxed = |(u, v): (f64, f64), text: &str| LabelBox {
        u,
        v,
        half_width: 0.5 * (text.chars().count() as f64 * CHAR_PX + 10.0) / frame.px,
        half_height: 0.5 * height,
    };
    let point = |&(u, v): &(f64, f64), half: f64| LabelBox {
        u,
        v,
        half_width: half,
        half_height: half,
    };
    let dots: Vec<LabelBox> = avoid
        .dots
        .iter()
        .map(|p| point(p, DOT_PX / frame.px))
        .collect();
    let lines: Vec<LabelBox> = avoid.lines.iter().map(|p| point(p, 0.0)).collect();
    let mut placed: Vec<LabelBox> = avoid
        .labels
        .iter()
        .map(|&(at, text)| boxed(at, text))
        .collect();
    let mut centres = Vec::new();
    for &((u, v), text) in wanted {
        let half_width = boxed((u, v), text).half_width;
        let (left, right) = (frame.u.0 + half_width, frame.bar.0 - half_width);
        let u = if left <= right {
            u.clamp(left, right)
        } else {
            0.5 * (frame.u.0 + frame.bar.0)
        };
        // Below the point as wanted, then above it, then further down and up.
        let candidates: Vec<LabelBox> = std::iter::once(0.0)
            .chain((1..12).flat_map(|k| [-f64::from(k) - 0.8, f64::from(k)]))
            .map(|shift| boxed((u, v + shift * height), text))
            .collect();
        let clear = |b: &LabelBox, obstacles: &[&[LabelBox]]| {
            obstacles
                .iter()
                .all(|list| list.iter().all(|o| !b.overlaps(o)))
        };
        // Lines are given up first, then nothing else: a label may only land on another if
        // there is no room at all.
        let chosen = [
            &[&placed[..], &dots[..], &lines[..]][..],
            &[&placed[..], &dots[..]][..],
            &[&placed[..]][..],
        ]
        .iter()
        .find_map(|obstacles| candidates.iter().find(|b| clear(b, obstacles)))
        .copied()
        .unwrap_or(candidates[0]);
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

/// Tick labels with as many decimals as the tick step needs (`0.2`, `0.4`; `500`, `1000`),
/// or in exponent form for very small or large values.
pub fn tick_texts(ticks: &[f64]) -> Vec<String> {
    let largest = ticks.iter().fold(0.0f64, |m, t| m.max(t.abs()));
    let step = ticks
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .fold(f64::INFINITY, f64::min);
    if !(step.is_finite() && step > 0.0) || largest >= 1e5 || step < 1e-3 {
        return ticks.iter().map(|&t| short(t)).collect();
    }
    let decimals = (-(step.log10() + 1e-9).floor()).max(0.0) as usize;
    ticks
        .iter()
        .map(|&t| format!("{:.decimals$}", snap(t)).replace('-', "\u{2212}"))
        .collect()
}

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
            .with_depth_range(rerun::components::ValueRange::new(range.0, range.1)),
    )?;
    if changing.values {
        put(
            stream,
            when,
            format!("{base}/values"),
            &rerun::Tensor::try_from(values32)
                .map_err(|e| RecordError::Rerun(e.to_string()))?
                .with_dim_names([figure.z_label.clone(), figure.x_label.clone()]),
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
            let scale = frame.strip / peak;
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
        wanted.push((below((x, z)), format!("point {j}")));
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
            &rerun::Points2D::new(anchors)
                .with_radii([rerun::Radius::new_ui_points(0.0)])
                .with_colors([rerun::Color::from_rgb(20, 20, 20)])
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
                .with_colors([rerun::Color::from_rgb(20, 20, 20)])
                .with_radii([rerun::Radius::new_ui_points(0.5)]),
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
            px: 400.0,
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
        let centres = place_labels(&frame, &wanted, &Avoid::default());
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

    #[test]
    fn labels_never_cover_a_marked_point_and_stay_by_their_own() {
        // A moving load at x0 = 0 (issue 14): the labels of the two τxz lobes flank the axis,
        // where two material points sit one above the other. Pushed from below its dot, the
        // first point's label once landed on the second point's dot.
        let frame = frame();
        let h = LABEL_PX / frame.px;
        let (max_at, min_at) = ((-0.3, 0.5), (0.3, 0.5));
        let points = [(0.0, 0.5), (0.0, 0.58)];
        let below = |(u, v): (f64, f64)| (u, v + 0.9 * h);
        let wanted = [
            (
                below(max_at),
                "max τxz = 0.250 p0 at x = −0.860a, z = 0.500a",
            ),
            (
                below(min_at),
                "min τxz = −0.250 p0 at x = 0.860a, z = 0.500a",
            ),
            (below(points[0]), "point 0"),
            (below(points[1]), "point 1"),
        ];
        let dots = [max_at, min_at, points[0], points[1]];
        let avoid = Avoid {
            dots: &dots,
            ..Avoid::default()
        };
        let centres = place_labels(&frame, &wanted, &avoid);
        let boxed = |k: usize| LabelBox {
            u: centres[k].0,
            v: centres[k].1,
            half_width: 0.5 * (wanted[k].1.chars().count() as f64 * CHAR_PX + 10.0) / frame.px,
            half_height: 0.5 * h,
        };
        for k in 0..wanted.len() {
            for &(u, v) in &dots {
                let dot = LabelBox {
                    u,
                    v,
                    half_width: DOT_PX / frame.px,
                    half_height: DOT_PX / frame.px,
                };
                assert!(
                    !boxed(k).overlaps(&dot),
                    "label {k} covers the dot at ({u}, {v})"
                );
            }
            for j in 0..k {
                assert!(!boxed(k).overlaps(&boxed(j)), "{k} covers {j}");
            }
        }
        // Each point's label is nearer its own point than the other one.
        let distance = |(u, v): (f64, f64), (a, b): (f64, f64)| (u - a).hypot(v - b);
        for (j, own) in points.iter().enumerate() {
            let other = points[1 - j];
            assert!(
                distance(centres[2 + j], *own) < distance(centres[2 + j], other),
                "{centres:?}"
            );
        }
    }

    #[test]
    fn labels_keep_off_rows_and_lines_where_there_is_room() {
        let frame = frame();
        let h = LABEL_PX / frame.px;
        let text = "max p = 2125 MPa at x = 100 µm, y = 107 µm";
        let half_width = 0.5 * (text.chars().count() as f64 * CHAR_PX + 10.0) / frame.px;
        let clear_of = |centre: (f64, f64), (u, v): (f64, f64)| {
            (centre.0 - u).abs() >= half_width || (centre.1 - v).abs() >= 0.5 * h
        };
        // A title row where the label is wanted.
        let rows = [(
            (0.0, 0.5),
            "step 1 of 10: W = 0.05 N: 4 spots, 0.543 % in contact",
        )];
        let avoid = Avoid {
            labels: &rows,
            ..Avoid::default()
        };
        let centre = place_labels(&frame, &[((0.0, 0.5), text)], &avoid)[0];
        assert!((centre.1 - 0.5).abs() >= h - 1e-12, "{centre:?}");
        // An outline through the wanted place: the label moves off it.
        let outline: Vec<(f64, f64)> = (0..=40)
            .map(|i| (-1.0 + 0.05 * f64::from(i), 0.5))
            .collect();
        let avoid = Avoid {
            lines: &outline,
            ..Avoid::default()
        };
        let centre = place_labels(&frame, &[((0.0, 0.5), text)], &avoid)[0];
        assert!(outline.iter().all(|&p| clear_of(centre, p)), "{centre:?}");
        // Lines everywhere: the label stays where it is wanted.
        let everywhere: Vec<(f64, f64)> = (0..=400)
            .flat_map(|i| {
                (0..=40).map(move |j| (-1.0 + 0.005 * f64::from(i), -0.8 + 0.05 * f64::from(j)))
            })
            .collect();
        let avoid = Avoid {
            lines: &everywhere,
            ..Avoid::default()
        };
        assert_eq!(
            place_labels(&frame, &[((0.0, 0.5), text)], &avoid)[0],
            (0.0, 0.5)
        );
    }

    #[test]
    fn labels_near_a_side_stay_inside_the_map() {
        let frame = frame();
        let text = "max τxz = 0.113 p0 at x = −1.00a, z = 0.680a";
        let centres = place_labels(&frame, &[((frame.u.0, 0.5), text)], &Avoid::default());
        let half_width = 0.5 * (text.chars().count() as f64 * CHAR_PX + 10.0) / frame.px;
        assert!(
            (centres[0].0 - (frame.u.0 + half_width)).abs() < 1e-12,
            "{centres:?}"
        );
        let centres = place_labels(&frame, &[((frame.u.1, 0.5), text)], &Avoid::default());
        assert!(
            centres[0].0 + half_width <= frame.bar.0 + 1e-12,
            "{centres:?}"
        );
    }

    #[test]
    fn tick_labels_share_their_decimals() {
        assert_eq!(
            tick_texts(&[0.0, 0.2, 0.4, 0.6, 0.8, 1.0]),
            ["0.0", "0.2", "0.4", "0.6", "0.8", "1.0"]
        );
        assert_eq!(
            tick_texts(&[-0.2, -0.1, 0.0, 0.1, 0.2]),
            ["\u{2212}0.2", "\u{2212}0.1", "0.0", "0.1", "0.2"]
        );
        assert_eq!(tick_texts(&[0.0, 500.0, 1000.0]), ["0", "500", "1000"]);
        assert_eq!(tick_texts(&[0.0, 0.05, 0.1]), ["0.00", "0.05", "0.10"]);
    }

    #[test]
    fn captions_give_the_name_and_the_unit() {
        assert_eq!(name_and_unit("σvM / p0"), ("σvM".into(), " p0".into()));
        assert_eq!(name_and_unit("p (MPa)"), ("p".into(), " MPa".into()));
        assert_eq!(
            name_and_unit("height (µm)"),
            ("height".into(), " µm".into())
        );
        assert_eq!(name_and_unit("x/a"), ("x".into(), "a".into()));
        assert_eq!(name_and_unit("y (mm)"), ("y".into(), " mm".into()));
        assert_eq!(name_and_unit("spots"), ("spots".into(), String::new()));
    }

    fn map_figure(vertical_is_depth: bool) -> Figure {
        Figure {
            title: "map".into(),
            panels: vec![Panel {
                subtitle: String::new(),
                x: crate::field::Axis::new(0.0, 2.0, 3),
                z: crate::field::Axis::new(10.0, 30.0, 3),
                // Row k is at the vertical coordinate 10 + 10k.
                values: ndarray::Array2::from_shape_fn((3, 3), |(row, column)| {
                    (10 * row + column) as f64
                }),
                traction: Vec::new(),
                half_width: 0.0,
                outlines: vec![vec![(0.0, 10.0), (1.0, 20.0)]],
                scale: None,
            }],
            value_label: "p (MPa)".into(),
            x_label: "x (µm)".into(),
            z_label: "y (µm)".into(),
            vertical_is_depth,
            traction_label: String::new(),
            colormap: ColorMap::Inferno,
            levels: crate::render::Levels::Count(0),
            mark: Mark::Max,
            panel_width_px: 400,
        }
    }

    #[test]
    fn a_map_seen_from_above_is_drawn_with_y_up_and_labelled_in_its_own_coordinates() {
        let figure = map_figure(false);
        let shown = displayed(&figure, &figure.panels[0]);
        // The view's vertical axis points down: the largest y (row 2) is the top row, at −30.
        assert_eq!(shown.values[[0, 1]], 21.0);
        assert_eq!(shown.values[[2, 1]], 1.0);
        assert_eq!((shown.z.min, shown.z.max), (-30.0, -10.0));
        assert_eq!(shown.outlines[0], vec![(0.0, -10.0), (1.0, -20.0)]);
        // The maximum, found on the drawn map, is labelled where it is on the figure.
        let (largest, _) = extremes(&shown, Mark::Max);
        let e = largest.expect("a maximum");
        assert_eq!(e.value, 22.0);
        let notation = Notation::of(&figure, &figure.panels[0]);
        assert_eq!(notation.value(e.value), "22.0 MPa");
        assert_eq!(notation.position(e.u, e.v), "x = 2.00 µm, y = 30.0 µm");
        // A section in depth is drawn as it is.
        let depth = map_figure(true);
        let same = displayed(&depth, &depth.panels[0]);
        assert_eq!(same.values, depth.panels[0].values);
        assert_eq!(same.z, depth.panels[0].z);
    }
}

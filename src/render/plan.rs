//! Everything a figure shows, computed once in pixels before any drawing: the heat-map and
//! colour-bar bitmaps, contour polylines, the placed contour and extreme labels, and the
//! traction curves. PNG and SVG then draw the same plan.

use super::colormap::{self, ColorScale};
use super::contour::isolines_on;
use super::font;
use super::layout::{Layout, PanelLayout, Rect, TextSizes};
use super::scales::{scale_groups, ScaleGroup};
use super::ticks::{format_fixed, format_levels, format_significant};
use super::{ColorMap, Figure, Mark, Panel, RenderError};
use crate::field::Axis;

/// A box of text: the box (for the background) and where the text sits.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct TextBox {
    pub text: String,
    pub size: f64,
    /// `[x0, y0, x1, y1]` in pixels.
    pub bounds: [f64; 4],
    /// Start of the baseline.
    pub origin: (f64, f64),
}

impl TextBox {
    /// A box of `text` padded by `pad` pixels, its top-left corner at `corner`.
    fn new(text: String, size: f64, width: f64, pad: f64, corner: (f64, f64)) -> Self {
        let cap = font::cap_height(size);
        let bounds = [
            corner.0,
            corner.1,
            corner.0 + width + 2.0 * pad,
            corner.1 + cap + 2.0 * pad,
        ];
        Self {
            text,
            size,
            bounds,
            origin: (corner.0 + pad, corner.1 + pad + cap),
        }
    }

    fn w(&self) -> f64 {
        self.bounds[2] - self.bounds[0]
    }

    fn h(&self) -> f64 {
        self.bounds[3] - self.bounds[1]
    }

    fn moved_to(&self, corner: (f64, f64)) -> Self {
        let (dx, dy) = (corner.0 - self.bounds[0], corner.1 - self.bounds[1]);
        Self {
            text: self.text.clone(),
            size: self.size,
            bounds: [
                self.bounds[0] + dx,
                self.bounds[1] + dy,
                self.bounds[2] + dx,
                self.bounds[3] + dy,
            ],
            origin: (self.origin.0 + dx, self.origin.1 + dy),
        }
    }

    fn overlaps(&self, other: &[f64; 4], gap: f64) -> bool {
        let b = &self.bounds;
        b[0] < other[2] + gap
            && other[0] < b[2] + gap
            && b[1] < other[3] + gap
            && other[1] < b[3] + gap
    }

    fn inside(&self, rect: &Rect, inset: f64) -> bool {
        let b = &self.bounds;
        b[0] >= f64::from(rect.x) + inset
            && b[1] >= f64::from(rect.y) + inset
            && b[2] <= f64::from(rect.right()) - inset
            && b[3] <= f64::from(rect.bottom()) - inset
    }
}

/// A marked extreme of a panel.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Extreme {
    /// Pixel position of the marker.
    pub at: (f64, f64),
    pub label: TextBox,
}

/// What one panel shows.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PanelPlan {
    /// Contour polylines in pixels.
    pub contours: Vec<Vec<(f64, f64)>>,
    pub contour_labels: Vec<TextBox>,
    pub extremes: Vec<Extreme>,
    /// p(x) in strip pixels.
    pub pressure: Vec<(f64, f64)>,
    /// q(x) in strip pixels, when any q is not zero.
    pub shear: Option<Vec<(f64, f64)>>,
    /// Legend at the right end of the strip (else the left).
    pub legend_right: bool,
    /// Guide polylines (the contact outline) in pixels, cut to the map.
    pub outlines: Vec<Vec<(f64, f64)>>,
}

/// The drawing plan of a figure.
pub(crate) struct Plan<'f> {
    pub figure: &'f Figure,
    pub layout: Layout,
    /// The panels sharing each colour scale, left to right; `layout.colorbars` in the same
    /// order.
    pub groups: Vec<ScaleGroup<'f>>,
    pub panels: Vec<PanelPlan>,
    /// Bitmaps under everything else: one heat map per panel, then one colour bar per group.
    pub images: Vec<(Rect, Vec<u8>)>,
}

impl<'f> Plan<'f> {
    pub fn new(figure: &'f Figure) -> Result<Self, RenderError> {
        if figure.panels.is_empty() {
            return Err(RenderError::NoPanels);
        }
        for (i, panel) in figure.panels.iter().enumerate() {
            check_panel(i, panel)?;
        }
        font::ensure_registered()?;
        let groups = scale_groups(figure);
        let layout = Layout::new(figure, &groups)?;

        let mut images = Vec::with_capacity(figure.panels.len() + groups.len());
        let mut panels = Vec::with_capacity(figure.panels.len());
        for group in &groups {
            for index in group.panels.clone() {
                let (panel, panel_layout) = (&figure.panels[index], &layout.panels[index]);
                images.push((
                    panel_layout.map,
                    heat_map(panel, panel_layout, &group.scale),
                ));
                panels.push(plan_panel(
                    figure,
                    panel,
                    panel_layout,
                    &layout,
                    &group.levels,
                )?);
            }
        }
        for (group, bar) in groups.iter().zip(&layout.colorbars) {
            images.push((bar.rect, colorbar(group.colormap, bar.rect)));
        }
        Ok(Self {
            figure,
            layout,
            groups,
            panels,
            images,
        })
    }
}

fn check_panel(index: usize, panel: &Panel) -> Result<(), RenderError> {
    let n = index + 1;
    let axis_ok = |a: &crate::field::Axis| {
        a.count >= 2 && a.min.is_finite() && a.max.is_finite() && a.max > a.min
    };
    if !axis_ok(&panel.x) || !axis_ok(&panel.z) {
        return Err(RenderError::Draw(format!(
            "panel {n}: axes need at least 2 samples over a non-empty finite range, got x {:?} and z {:?}",
            panel.x, panel.z
        )));
    }
    if panel.values.dim() != (panel.z.count, panel.x.count) {
        let (rows, columns) = panel.values.dim();
        return Err(RenderError::Draw(format!(
            "panel {n}: values are {rows} x {columns} but the axes need {} x {} (z by x)",
            panel.z.count, panel.x.count
        )));
    }
    Ok(())
}

/// Bilinear value of a panel's field at data coordinates (clamped to the grid).
pub(crate) fn bilinear(panel: &Panel, x: f64, z: f64) -> f64 {
    let fx = ((x - panel.x.min) / panel.x.step()).clamp(0.0, (panel.x.count - 1) as f64);
    let fz = ((z - panel.z.min) / panel.z.step()).clamp(0.0, (panel.z.count - 1) as f64);
    let i = (fx.floor() as usize).min(panel.x.count - 2);
    let j = (fz.floor() as usize).min(panel.z.count - 2);
    let (tx, tz) = (fx - i as f64, fz - j as f64);
    let v = &panel.values;
    let top = v[[j, i]] * (1.0 - tx) + v[[j, i + 1]] * tx;
    let bottom = v[[j + 1, i]] * (1.0 - tx) + v[[j + 1, i + 1]] * tx;
    top * (1.0 - tz) + bottom * tz
}

/// The panel's field resampled to the map's pixels (pixel centres), as RGB rows.
fn heat_map(panel: &Panel, layout: &PanelLayout, scale: &ColorScale) -> Vec<u8> {
    let (w, h) = (layout.map.w.max(0) as usize, layout.map.h.max(0) as usize);
    let mut rgb = Vec::with_capacity(w * h * 3);
    let xs: Vec<f64> = (0..w)
        .map(|i| layout.data_x(f64::from(layout.map.x) + i as f64 + 0.5))
        .collect();
    for j in 0..h {
        let z = layout.data_z(f64::from(layout.map.y) + j as f64 + 0.5);
        for &x in &xs {
            rgb.extend_from_slice(&scale.rgb(bilinear(panel, x, z)));
        }
    }
    rgb
}

/// The colour bar: the colour map from the bottom (low) to the top (high).
fn colorbar(map: ColorMap, rect: Rect) -> Vec<u8> {
    let (w, h) = (rect.w.max(0) as usize, rect.h.max(0) as usize);
    let mut rgb = Vec::with_capacity(w * h * 3);
    for j in 0..h {
        let t = 1.0 - (j as f64 + 0.5) / h as f64;
        let color = colormap::eval(map, t);
        for _ in 0..w {
            rgb.extend_from_slice(&color);
        }
    }
    rgb
}

fn plan_panel(
    figure: &Figure,
    panel: &Panel,
    pl: &PanelLayout,
    layout: &Layout,
    levels: &[f64],
) -> Result<PanelPlan, RenderError> {
    let sizes = &layout.sizes;
    let to_px = |p: &[f64; 2]| (pl.px(p[0]), pl.pz(p[1]));

    // Contours, with their level, in pixels.
    let mut lines: Vec<(usize, Vec<(f64, f64)>)> = Vec::new();
    for (k, &level) in levels.iter().enumerate() {
        for line in isolines_on(panel.values.view(), &panel.x, &panel.z, level) {
            lines.push((k, line.points.iter().map(to_px).collect()));
        }
    }

    // Extremes first: contour labels keep clear of them.
    let mut taken: Vec<[f64; 4]> = Vec::new();
    let mut extremes = Vec::new();
    let wanted: &[bool] = match figure.mark {
        Mark::Max => &[true],
        Mark::Min => &[false],
        Mark::Both => &[true, false],
        Mark::None => &[],
    };
    // Every marker is known before any label is placed, so no label covers another marker.
    let r = marker_radius(sizes.tick);
    let markers: Vec<(bool, [f64; 4])> = wanted
        .iter()
        .filter_map(|&maximum| {
            let ((j, i), _) = sampled_extreme(panel, maximum)?;
            let at = (pl.px(panel.x.value(i)), pl.pz(panel.z.value(j)));
            Some((maximum, [at.0 - r, at.1 - r, at.0 + r, at.1 + r]))
        })
        .collect();
    for &maximum in wanted {
        let mut avoid = taken.clone();
        avoid.extend(
            markers
                .iter()
                .filter(|(m, _)| *m != maximum)
                .map(|(_, b)| *b),
        );
        if let Some(extreme) = plan_extreme(figure, panel, pl, sizes, maximum, &avoid)? {
            taken.push([
                extreme.at.0 - r,
                extreme.at.1 - r,
                extreme.at.0 + r,
                extreme.at.1 + r,
            ]);
            taken.push(extreme.label.bounds);
            extremes.push(extreme);
        }
    }

    let contour_labels = place_contour_labels(&lines, levels, pl, sizes.contour, &mut taken)?;

    // Traction curves within the map's x range.
    let inside = |x: f64| x >= pl.x_min && x <= pl.x_max;
    let samples: Vec<_> = panel
        .traction
        .iter()
        .filter(|s| inside(s.x) && s.p.is_finite() && s.q.is_finite())
        .collect();
    let pressure: Vec<(f64, f64)> = samples
        .iter()
        .map(|s| (pl.px(s.x), layout.strip_y(pl, s.p)))
        .collect();
    let peak = samples
        .iter()
        .map(|s| s.p.abs().max(s.q.abs()))
        .fold(0.0, f64::max);
    let has_shear = samples
        .iter()
        .any(|s| s.q.abs() > 1e-12 * peak.max(f64::MIN_POSITIVE));
    let shear = has_shear.then(|| {
        // Only where q acts (and one zero sample either side), not along the free surface.
        let first = samples
            .iter()
            .position(|s| s.q != 0.0)
            .unwrap_or(0)
            .saturating_sub(1);
        let last = samples
            .iter()
            .rposition(|s| s.q != 0.0)
            .map_or(samples.len(), |i| (i + 2).min(samples.len()));
        samples[first..last]
            .iter()
            .map(|s| (pl.px(s.x), layout.strip_y(pl, s.q)))
            .collect()
    });
    // The legend goes to the end where the tractions are lower.
    let end_load = |right: bool| {
        let span = 0.2 * (pl.x_max - pl.x_min);
        samples
            .iter()
            .filter(|s| {
                if right {
                    s.x >= pl.x_max - span
                } else {
                    s.x <= pl.x_min + span
                }
            })
            .map(|s| s.p.abs().max(s.q.abs()))
            .fold(0.0, f64::max)
    };
    let legend_right = end_load(true) <= end_load(false);
    let outlines = panel
        .outlines
        .iter()
        .flat_map(|line| runs_inside(line, pl))
        .collect();
    Ok(PanelPlan {
        outlines,
        contours: lines.into_iter().map(|(_, l)| l).collect(),
        contour_labels,
        extremes,
        pressure,
        shear,
        legend_right,
    })
}

/// The parts of a polyline (data units) that lie within the map, in pixels.
fn runs_inside(line: &[(f64, f64)], pl: &PanelLayout) -> Vec<Vec<(f64, f64)>> {
    let inside = |&(x, z): &(f64, f64)| {
        let (z_lo, z_hi) = (pl.z_min.min(pl.z_max), pl.z_min.max(pl.z_max));
        x >= pl.x_min && x <= pl.x_max && z >= z_lo && z <= z_hi
    };
    let mut runs = Vec::new();
    let mut run: Vec<(f64, f64)> = Vec::new();
    for point in line {
        if inside(point) {
            run.push((pl.px(point.0), pl.pz(point.1)));
        } else if !run.is_empty() {
            runs.push(std::mem::take(&mut run));
        }
    }
    if run.len() > 1 {
        runs.push(run);
    }
    runs.retain(|r| r.len() > 1);
    runs
}

/// The grid index `(row, column)` and value of the largest (or smallest) finite sample.
fn sampled_extreme(panel: &Panel, maximum: bool) -> Option<((usize, usize), f64)> {
    let sign = if maximum { 1.0 } else { -1.0 };
    let mut best: Option<((usize, usize), f64)> = None;
    for ((j, i), &v) in panel.values.indexed_iter() {
        if v.is_finite() && best.is_none_or(|(_, b)| sign * v > sign * b) {
            best = Some(((j, i), v));
        }
    }
    best
}

/// Radius of the extreme marker for a tick font size.
pub(crate) fn marker_radius(tick_size: f64) -> f64 {
    (0.28 * tick_size).max(3.5)
}

/// Decimal places for coordinates on an axis spanning `span`: two for a span of 1 to 10.
fn coordinate_decimals(span: f64) -> usize {
    (2 - span.abs().log10().floor() as i32).clamp(0, 6) as usize
}

/// One number of decimals for both coordinates of a marked sample: at least what each axis's
/// span asks ([`coordinate_decimals`]), more while a coordinate is off by more than a
/// hundredth of the finer sample spacing, but no more than shows that spacing to three digits.
fn marker_decimals(x: f64, z: f64, x_axis: &Axis, z_axis: &Axis) -> usize {
    let base = coordinate_decimals(x_axis.max - x_axis.min)
        .max(coordinate_decimals(z_axis.max - z_axis.min));
    let step = x_axis.step().abs().min(z_axis.step().abs());
    if !(step.is_finite() && step > 0.0) {
        return base;
    }
    let limit = ((2.0 - step.log10().floor()).max(0.0) as usize).clamp(base, 6);
    let exact = |value: f64, decimals: usize| {
        let scale = 10f64.powi(decimals as i32);
        ((value * scale).round() / scale - value).abs() <= 0.01 * step
    };
    (base..=limit)
        .find(|&d| exact(x, d) && exact(z, d))
        .unwrap_or(limit)
}

/// The label of a marked extreme, in the units of the figure's captions: `max 0.300 p0 at
/// x = 0.000a, z = 0.785a`, `max 1659 MPa at x = 109.500 µm, z = 0.375 µm` (both coordinates
/// with the same decimals, [`marker_decimals`]; a coordinate within 1e-9 of the span of zero
/// is 0).
fn marker_text(
    figure: &Figure,
    panel: &Panel,
    maximum: bool,
    value: f64,
    (x, z): (f64, f64),
) -> String {
    let caption = panel
        .scale
        .as_ref()
        .map_or(figure.value_label.as_str(), |s| s.value_label.as_str());
    let (_, unit) = super::name_and_unit(caption);
    let axes = figure.axes_of(panel);
    let (horizontal, length) = super::name_and_unit(axes.x_label);
    let (vertical, _) = super::name_and_unit(axes.z_label);
    let span = (panel.x.max - panel.x.min)
        .abs()
        .max((panel.z.max - panel.z.min).abs());
    let snap = |c: f64| if c.abs() <= 1e-9 * span { 0.0 } else { c };
    let (x, z) = (snap(x), snap(z));
    // A peak located off the grid: one decimal more than the axes' spans ask, up to three (as
    // the `hertz` report prints positions: 0.786a), not the digits that tell a sample apart.
    let decimals = if maximum && panel.peak.is_some() {
        let base = coordinate_decimals(panel.x.max - panel.x.min)
            .max(coordinate_decimals(panel.z.max - panel.z.min));
        base.max((base + 1).min(3))
    } else {
        marker_decimals(x, z, &panel.x, &panel.z)
    };
    format!(
        "{} {}{unit} at {horizontal} = {}{length}, {vertical} = {}{length}",
        if maximum { "max" } else { "min" },
        format_significant(value),
        format_fixed(x, decimals),
        format_fixed(z, decimals),
    )
}

/// Finds the largest (or smallest) sampled value of a panel and places its label.
fn plan_extreme(
    figure: &Figure,
    panel: &Panel,
    pl: &PanelLayout,
    sizes: &TextSizes,
    maximum: bool,
    taken: &[[f64; 4]],
) -> Result<Option<Extreme>, RenderError> {
    let Some(((j, i), v0)) = sampled_extreme(panel, maximum) else {
        return Ok(None);
    };
    // The sampled extreme, not an interpolated one: the maxima of contact fields often sit on
    // a kink (the contact edge, the surface), where a fitted parabola would overshoot. Where
    // the study located the maximum between the samples on the field itself, that one.
    let (value, x, z) = match panel.peak.filter(|_| maximum) {
        Some(peak) => (peak.value, peak.x, peak.z),
        None => (v0, panel.x.value(i), panel.z.value(j)),
    };

    let text = marker_text(figure, panel, maximum, value, (x, z));
    let at = (pl.px(x), pl.pz(z));
    let size = sizes.mark;
    let width = font::text_width(&text, size)?;
    let pad = 0.3 * size;
    let template = TextBox::new(text, size, width, pad, (0.0, 0.0));
    let (w, h) = (template.w(), template.h());
    let r = marker_radius(sizes.tick) + 0.35 * size;
    // Right, left, below, above, then the diagonals, then further below and above (clear of
    // a neighbouring label on the same row).
    let mut candidates = vec![
        (at.0 + r, at.1 - h / 2.0),
        (at.0 - r - w, at.1 - h / 2.0),
        (at.0 - w / 2.0, at.1 + r),
        (at.0 - w / 2.0, at.1 - r - h),
        (at.0 + r * 0.7, at.1 + r * 0.7),
        (at.0 - r * 0.7 - w, at.1 + r * 0.7),
        (at.0 + r * 0.7, at.1 - r * 0.7 - h),
        (at.0 - r * 0.7 - w, at.1 - r * 0.7 - h),
    ];
    for k in 1..=2 {
        let step = k as f64 * (h + 0.6 * size);
        candidates.push((at.0 - w / 2.0, at.1 + r + step));
        candidates.push((at.0 - w / 2.0, at.1 - r - h - step));
    }
    // The first candidate inside the map and clear of everything taken wins; failing that,
    // each candidate is pushed back inside the map and the first clear one, else the one
    // overlapping least, wins.
    let inset = 3.0;
    let map = &pl.map;
    let placed: Vec<TextBox> = candidates
        .iter()
        .map(|c| {
            let x =
                c.0.min(f64::from(map.right()) - inset - w)
                    .max(f64::from(map.x) + inset);
            let y =
                c.1.min(f64::from(map.bottom()) - inset - h)
                    .max(f64::from(map.y) + inset);
            template.moved_to((x, y))
        })
        .collect();
    let overlap = |b: &TextBox| -> f64 {
        taken
            .iter()
            .map(|t| {
                let g = 0.6 * size;
                let dx = (b.bounds[2].min(t[2] + g) - b.bounds[0].max(t[0] - g)).max(0.0);
                let dy = (b.bounds[3].min(t[3] + g) - b.bounds[1].max(t[1] - g)).max(0.0);
                dx * dy
            })
            .sum()
    };
    // Clamping may have pushed a label onto its own marker: such a place is never taken.
    let mr = marker_radius(sizes.tick);
    let own = [at.0 - mr, at.1 - mr, at.0 + mr, at.1 + mr];
    let placed: Vec<TextBox> = placed
        .into_iter()
        .filter(|b| !b.overlaps(&own, 0.0))
        .collect();
    let clear = |b: &&TextBox| !taken.iter().any(|t| b.overlaps(t, 0.6 * size));
    // Unmoved places first (in the order above), then the clamped ones.
    let unmoved = candidates
        .iter()
        .map(|c| template.moved_to(*c))
        .find(|b| b.inside(map, inset) && clear(&b));
    let label = unmoved
        .as_ref()
        .or_else(|| placed.iter().find(clear))
        .or_else(|| {
            placed
                .iter()
                .min_by(|a, b| overlap(a).total_cmp(&overlap(b)))
        })
        .cloned()
        .unwrap_or(template);
    Ok(Some(Extreme { at, label }))
}

/// Places one label on each long enough contour line (two on very long ones), longest lines
/// first: on a straight stretch, inside the map, clear of other labels, the extremes and the
/// lines of other levels.
fn place_contour_labels(
    lines: &[(usize, Vec<(f64, f64)>)],
    levels: &[f64],
    pl: &PanelLayout,
    size: f64,
    taken: &mut Vec<[f64; 4]>,
) -> Result<Vec<TextBox>, RenderError> {
    let map = pl.map;
    let (mw, mh) = (map.w.max(1) as usize, map.h.max(1) as usize);
    // Which level's line passes through each map pixel (0: none).
    let mut owner = vec![0u16; mw * mh];
    for (k, line) in lines {
        for pair in line.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let steps = ((b.0 - a.0).abs().max((b.1 - a.1).abs()).ceil() as usize).max(1);
            for s in 0..=steps {
                let t = s as f64 / steps as f64;
                let px = (a.0 + t * (b.0 - a.0)).floor() as i64 - i64::from(map.x);
                let py = (a.1 + t * (b.1 - a.1)).floor() as i64 - i64::from(map.y);
                if px >= 0 && py >= 0 && (px as usize) < mw && (py as usize) < mh {
                    owner[py as usize * mw + px as usize] = (*k + 1).min(u16::MAX as usize) as u16;
                }
            }
        }
    }
    let crosses_other = |b: &TextBox, k: usize| {
        let x0 = (b.bounds[0].floor() as i64 - i64::from(map.x)).max(0) as usize;
        let y0 = (b.bounds[1].floor() as i64 - i64::from(map.y)).max(0) as usize;
        let x1 = ((b.bounds[2].ceil() as i64 - i64::from(map.x)).max(0) as usize).min(mw);
        let y1 = ((b.bounds[3].ceil() as i64 - i64::from(map.y)).max(0) as usize).min(mh);
        (y0..y1).any(|y| {
            (x0..x1).any(|x| {
                let o = owner[y * mw + x];
                o != 0 && usize::from(o) != k + 1
            })
        })
    };

    let texts = format_levels(levels);
    let widths: Vec<f64> = texts
        .iter()
        .map(|t| font::text_width(t, size))
        .collect::<Result<_, _>>()?;
    let pad = 0.25 * size;

    let mut order: Vec<(f64, usize)> = lines
        .iter()
        .enumerate()
        .map(|(n, (_, l))| (path_length(l), n))
        .collect();
    order.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    let mut labels = Vec::new();
    for (length, n) in order {
        let (k, line) = &lines[n];
        let template = TextBox::new(texts[*k].clone(), size, widths[*k], pad, (0.0, 0.0));
        if length < 2.5 * template.w() {
            continue;
        }
        let wanted: &[&[f64]] = if length > 1.5 * f64::from(map.w) {
            &[&[0.25, 0.3, 0.2, 0.35, 0.15], &[0.75, 0.7, 0.8, 0.65, 0.85]]
        } else {
            &[&[0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.15, 0.85]]
        };
        for fractions in wanted {
            let found = fractions.iter().find_map(|f| {
                let centre = point_at(line, f * length)?;
                // A straight enough stretch under the label.
                let half = template.w() / 2.0;
                let before = point_at(line, f * length - half)?;
                let after = point_at(line, f * length + half)?;
                let chord = (after.0 - before.0).hypot(after.1 - before.1);
                if chord < 0.75 * template.w() {
                    return None;
                }
                let b = template.moved_to((centre.0 - half, centre.1 - template.h() / 2.0));
                let clear = b.inside(&map, 2.0)
                    && !taken.iter().any(|t| b.overlaps(t, 3.0))
                    && !crosses_other(&b, *k);
                clear.then_some(b)
            });
            if let Some(b) = found {
                taken.push(b.bounds);
                labels.push(b);
            }
        }
    }
    Ok(labels)
}

fn path_length(line: &[(f64, f64)]) -> f64 {
    line.windows(2)
        .map(|p| (p[1].0 - p[0].0).hypot(p[1].1 - p[0].1))
        .sum()
}

/// The point at arc length `s` along a polyline (`None` outside it).
fn point_at(line: &[(f64, f64)], s: f64) -> Option<(f64, f64)> {
    if s < 0.0 {
        return None;
    }
    let mut travelled = 0.0;
    for p in line.windows(2) {
        let length = (p[1].0 - p[0].0).hypot(p[1].1 - p[0].1);
        if travelled + length >= s && length > 0.0 {
            let t = (s - travelled) / length;
            return Some((
                p[0].0 + t * (p[1].0 - p[0].0),
                p[0].1 + t * (p[1].1 - p[0].1),
            ));
        }
        travelled += length;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::{ColorMap, Levels, PanelScale};
    use ndarray::Array2;

    fn figure(value_label: &str, x_label: &str, z_label: &str, x: Axis, z: Axis) -> Figure {
        Figure {
            title: String::new(),
            panels: vec![Panel {
                subtitle: String::new(),
                x,
                z,
                values: Array2::zeros((z.count, x.count)),
                traction: Vec::new(),
                half_width: 0.0,
                outlines: Vec::new(),
                scale: None,
                peak: None,
                axes: None,
            }],
            value_label: value_label.into(),
            x_label: x_label.into(),
            z_label: z_label.into(),
            vertical_is_depth: true,
            traction_label: String::new(),
            colormap: ColorMap::Viridis,
            levels: Levels::Count(0),
            mark: Mark::Max,
            panel_width_px: 300,
        }
    }

    #[test]
    fn marker_labels_carry_units_and_one_precision() {
        // A normalised section, 4a by 2a, 801 samples across: one decimals count for both.
        let f = figure(
            "τ1 / p0",
            "x/a",
            "z/a",
            Axis::new(-2.0, 2.0, 801),
            Axis::new(0.0, 2.0, 401),
        );
        let text = |f: &Figure, max: bool, v: f64, at: (f64, f64)| {
            marker_text(f, &f.panels[0], max, v, at)
        };
        assert_eq!(
            text(&f, true, 0.30028, (3e-13, 0.785)),
            "max 0.300 p0 at x = 0.000a, z = 0.785a"
        );
        assert_eq!(
            text(&f, true, 0.3, (0.18, 0.19)),
            "max 0.300 p0 at x = 0.18a, z = 0.19a"
        );
        assert_eq!(
            text(&f, false, -0.25, (-0.86, 0.5)),
            "min \u{2212}0.250 p0 at x = \u{2212}0.86a, z = 0.50a"
        );
        // A rough section in µm and MPa: depth samples 0.375 µm apart, 1 µm cells along x.
        let f = figure(
            "σvM (MPa)",
            "x (µm)",
            "z (µm)",
            Axis::new(45.5, 172.5, 128),
            Axis::new(0.0, 50.25, 135),
        );
        assert_eq!(
            text(&f, true, 1658.99, (109.5, 0.375)),
            "max 1659 MPa at x = 109.500 µm, z = 0.375 µm"
        );
        // A map seen from above: y, not z; its own scale's unit.
        let mut f = figure(
            "σvM (MPa)",
            "x (µm)",
            "y (µm)",
            Axis::new(0.5, 127.5, 128),
            Axis::new(0.5, 127.5, 128),
        );
        f.panels[0].scale = Some(PanelScale {
            value_label: "p (GPa)".into(),
            colormap: ColorMap::Inferno,
            levels: Levels::Count(0),
            range: None,
        });
        assert_eq!(
            text(&f, true, 2.9289, (100.5, 107.5)),
            "max 2.93 GPa at x = 100.5 µm, y = 107.5 µm"
        );
    }
}

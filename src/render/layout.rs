//! Where everything goes: text sizes, the rectangles of maps, traction strips and colour bars,
//! and the ticks of every axis, in pixels of the output image.
//!
//! The maps have equal aspect ratio: a map is `panel_width_px` wide and as tall as the depth
//! range needs at the same scale. Everything else is measured around them with the embedded
//! font, so nothing overlaps and nothing is clipped.
//!
//! A colour bar follows the last panel of each group of panels sharing a colour scale; a panel
//! after a bar starts clear of the bar's label, with room for its own axis numbers.

use super::font;
use super::scales::ScaleGroup;
use super::ticks::{choose_ticks, Ticks};
use super::{Figure, Panel, RenderError};

/// Largest side of an output image, in pixels.
const MAX_SIDE_PX: f64 = 16_384.0;

/// An axis-aligned rectangle of pixels `[x, x + w) x [y, y + h)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Rect {
    pub x: i32,
    pub y: i32,
    pub w: i32,
    pub h: i32,
}

impl Rect {
    pub fn right(&self) -> i32 {
        self.x + self.w
    }

    pub fn bottom(&self) -> i32 {
        self.y + self.h
    }

    pub fn center(&self) -> (f64, f64) {
        (
            f64::from(self.x) + f64::from(self.w) / 2.0,
            f64::from(self.y) + f64::from(self.h) / 2.0,
        )
    }
}

/// Font sizes (plotters sizes, see [`font`]) of the kinds of text.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct TextSizes {
    pub tick: f64,
    pub label: f64,
    pub title: f64,
    pub subtitle: f64,
    pub contour: f64,
    pub mark: f64,
    pub legend: f64,
}

impl TextSizes {
    /// Tick text grows with the figure so that it stays readable when the figure is scaled to
    /// the width of a page; the rest is proportional.
    fn for_width(estimated_width_px: f64) -> Self {
        // Even sizes: plotters places ab_glyph glyphs half a size below the anchor and
        // truncates; with an odd size glyph rows would jitter by a pixel.
        let even = |size: f64| 2.0 * (size / 2.0).round();
        let tick = even((8.0 + 0.009 * estimated_width_px).clamp(12.0, 32.0));
        Self {
            tick,
            label: even(1.25 * tick),
            title: even(1.7 * tick),
            subtitle: even(1.2 * tick),
            contour: even(0.85 * tick),
            mark: even(0.9 * tick),
            legend: even(0.9 * tick),
        }
    }
}

/// One panel: its map, traction strip and axes.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PanelLayout {
    /// The heat map (plotting area), exactly the data extent.
    pub map: Rect,
    /// The traction profile strip above the map, sharing its horizontal scale.
    pub strip: Rect,
    pub x_ticks: Ticks,
    pub z_ticks: Ticks,
    pub strip_ticks: Ticks,
    /// Horizontal centre of the rotated labels left of the leftmost panel's axes.
    pub rotated_label_x: f64,
    pub x_label_baseline: f64,
    pub x_min: f64,
    pub x_max: f64,
    pub z_min: f64,
    pub z_max: f64,
    /// Whether `z` grows downwards (a depth) or upwards.
    pub z_down: bool,
    /// Whether the panel draws its traction strip (a figure with strips: every panel but a
    /// plane parallel to the surface beside depth sections).
    pub strip_drawn: bool,
    /// Whether the vertical axis's caption (and the strip's) is drawn left of this panel: the
    /// first panel, and one whose vertical axis or strip differs from its left neighbour's
    /// (an xy section beside an xz one).
    pub new_axes: bool,
}

impl PanelLayout {
    /// Pixel column of the data abscissa `x`.
    pub fn px(&self, x: f64) -> f64 {
        f64::from(self.map.x) + (x - self.x_min) / (self.x_max - self.x_min) * f64::from(self.map.w)
    }

    /// Pixel row of the vertical coordinate `z` (a depth grows downwards, y upwards).
    pub fn pz(&self, z: f64) -> f64 {
        let f = (z - self.z_min) / (self.z_max - self.z_min);
        let f = if self.z_down { f } else { 1.0 - f };
        f64::from(self.map.y) + f * f64::from(self.map.h)
    }

    /// Data abscissa at a pixel column.
    pub fn data_x(&self, px: f64) -> f64 {
        self.x_min
            + (px - f64::from(self.map.x)) / f64::from(self.map.w) * (self.x_max - self.x_min)
    }

    /// Vertical coordinate at a pixel row.
    pub fn data_z(&self, pz: f64) -> f64 {
        let f = (pz - f64::from(self.map.y)) / f64::from(self.map.h);
        let f = if self.z_down { f } else { 1.0 - f };
        self.z_min + f * (self.z_max - self.z_min)
    }
}

/// A colour bar: the bar, its ticks (on its right) and the centre of its rotated label.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ColorbarLayout {
    pub rect: Rect,
    pub ticks: Ticks,
    /// Horizontal centre of the rotated caption right of the tick labels.
    pub label_x: f64,
}

impl ColorbarLayout {
    /// Right edge of the caption's line, in pixels.
    pub fn right(&self, label_line: f64) -> f64 {
        self.label_x + label_line / 2.0
    }
}

/// The whole figure.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Layout {
    pub width: u32,
    pub height: u32,
    pub sizes: TextSizes,
    pub tick_length: f64,
    /// Gap between a tick and its label.
    pub tick_gap: f64,
    pub title_baseline: f64,
    /// Horizontal centre of the title.
    pub title_x: f64,
    /// The title and the panels' subtitles as drawn: cut with an ellipsis where they would be
    /// wider than the figure could reasonably be (so no text makes an image huge).
    pub title: String,
    pub subtitles: Vec<String>,
    pub subtitle_baseline: f64,
    pub panels: Vec<PanelLayout>,
    /// One per scale group, in the order of the groups.
    pub colorbars: Vec<ColorbarLayout>,
    /// Height of a line of label text (a rotated label's width).
    pub label_line: f64,
    /// Whether the panels have traction strips above their maps.
    pub has_strips: bool,
    /// Traction axis range shared by all strips.
    pub traction_min: f64,
    pub traction_max: f64,
}

impl Layout {
    /// Pixel row of the traction value `t` in the strip of `panel`.
    pub fn strip_y(&self, panel: &PanelLayout, t: f64) -> f64 {
        let f = (t - self.traction_min) / (self.traction_max - self.traction_min);
        f64::from(panel.strip.bottom()) - f * f64::from(panel.strip.h)
    }

    /// Lays out `figure` with its scale `groups` (which cover its panels in order).
    pub fn new(figure: &Figure, groups: &[ScaleGroup<'_>]) -> Result<Self, RenderError> {
        let count = figure.panels.len();
        if count == 0 {
            return Err(RenderError::NoPanels);
        }
        let covered = groups.iter().try_fold(0, |next, g| {
            (g.panels.start == next && g.panels.end > next).then_some(g.panels.end)
        });
        if covered != Some(count) {
            return Err(RenderError::Draw(format!(
                "the colour-scale groups {:?} do not cover the {count} panels in order",
                groups.iter().map(|g| g.panels.clone()).collect::<Vec<_>>()
            )));
        }
        let map_w = f64::from(figure.panel_width_px.max(16));
        let map_heights: Vec<f64> = figure
            .panels
            .iter()
            .map(|p| {
                (map_w * (p.z.max - p.z.min) / (p.x.max - p.x.min))
                    .round()
                    .max(8.0)
            })
            .collect();
        if let Some(h) = map_heights.iter().find(|h| **h > MAX_SIDE_PX) {
            return Err(RenderError::Draw(format!(
                "a map {map_w} px wide would be {h} px tall at equal aspect; narrow the depth \
                 range or the panel width"
            )));
        }
        let tallest = map_heights.iter().copied().fold(0.0, f64::max);
        // Each colour bar after the first widens the figure by about as much as the first.
        let extra_bars = (groups.len() - 1) as f64;
        let sizes = TextSizes::for_width(count as f64 * map_w + 250.0 + 150.0 * extra_bars);
        let s = sizes.tick;
        let margin = (0.8 * s).round();
        let tick_length = (0.4 * s).round();
        let tick_gap = (0.35 * s).round();
        let tick_cap = font::cap_height(s);
        let label_line = font::ascent(sizes.label) + font::descent(sizes.label);

        // Tractions: one range for all strips, so panels compare at a glance. A figure whose
        // panels carry no traction profile (a plane parallel to the surface) has no strips.
        let has_strips = figure.panels.iter().any(|p| !p.traction.is_empty());
        // Panels cut in different planes (their maps differ in shape): each horizontal caption
        // under its own map, the colour bars as tall as their tallest map.
        let mixed = figure.panels.iter().any(|p| p.axes.is_some());
        let (t_min, t_max) = traction_range(&figure.panels);
        let (strip_h, strip_ticks) = if has_strips {
            let traction_label_w = font::text_width(&figure.traction_label, sizes.label)?;
            let strip_h = (0.22 * tallest)
                .max(90.0)
                .max(traction_label_w + 0.4 * s)
                .round();
            (strip_h, vertical_ticks(t_min, t_max, strip_h, tick_cap))
        } else {
            (0.0, Ticks::default())
        };

        // Which panels draw a strip, and which start new vertical axes (their captions drawn
        // left of them): panels cut in different planes may share a figure.
        let strip_drawn: Vec<bool> = figure
            .panels
            .iter()
            .map(|p| has_strips && (figure.axes_of(p).vertical_is_depth || !p.traction.is_empty()))
            .collect();
        let new_axes: Vec<bool> = (0..count)
            .map(|i| {
                i == 0
                    || figure.axes_of(&figure.panels[i]).z_label
                        != figure.axes_of(&figure.panels[i - 1]).z_label
                    || (strip_drawn[i] && !strip_drawn[i - 1])
            })
            .collect();

        // Per-panel ticks and the width of the axis text left of each map.
        let mut axes = Vec::with_capacity(count);
        for ((panel, &map_h), &strip) in figure.panels.iter().zip(&map_heights).zip(&strip_drawn) {
            let x_ticks = horizontal_ticks(panel.x.min, panel.x.max, map_w, s);
            let z_ticks = vertical_ticks(panel.z.min, panel.z.max, map_h, tick_cap);
            let mut widest = widest(&z_ticks.labels, s)?;
            if strip {
                widest = widest.max(self::widest(&strip_ticks.labels, s)?);
            }
            axes.push((x_ticks, z_ticks, widest));
        }
        let gutter = |widest: f64| tick_length + tick_gap + widest;
        let rotated_column = label_line + 0.5 * s;
        // Room for the captions of a panel that starts new axes after the first.
        let captions = |i: usize| {
            if i > 0 && new_axes[i] {
                rotated_column
            } else {
                0.0
            }
        };

        // A subtitle at most three times its map's width, a title twice the maps' width; each
        // at least about eighty characters' worth (an average glyph is about 0.6 em).
        let subtitle_budget = (3.0 * map_w).max(50.0 * sizes.subtitle);
        let subtitles: Vec<String> = figure
            .panels
            .iter()
            .map(|p| font::fit(&p.subtitle, sizes.subtitle, subtitle_budget))
            .collect::<Result<_, _>>()?;
        let title_budget = (2.0 * count as f64 * map_w).max(50.0 * sizes.title);
        let title = font::fit(&figure.title, sizes.title, title_budget)?;
        let subtitle_widths: Vec<f64> = subtitles
            .iter()
            .map(|text| font::text_width(text, sizes.subtitle))
            .collect::<Result<_, _>>()?;
        // Horizontal positions of the maps and of the colour bar after each group.
        let colorbar_w = (0.9 * s).clamp(12.0, 30.0).round();
        let mut map_x = Vec::with_capacity(count);
        let mut colorbars: Vec<ColorbarLayout> = Vec::with_capacity(groups.len());
        let mut x = margin + rotated_column + gutter(axes[0].2);
        // The first subtitle must not start left of the margin.
        x = x.max(margin + subtitle_widths[0] / 2.0 - map_w / 2.0);
        let mut maps_right = x + map_w;
        for group in groups {
            for i in group.panels.clone() {
                if i > 0 {
                    let mut gap = 1.3 * s + gutter(axes[i].2) + captions(i);
                    // Neighbouring subtitles keep a gap of one tick size.
                    let needed = (subtitle_widths[i - 1] + subtitle_widths[i]) / 2.0 + s - map_w;
                    gap = gap.max(needed);
                    x += map_w + gap;
                    // After a colour bar: a wider gap than between panels, so that the bar reads
                    // as part of the group on its left, then this panel's axis numbers.
                    if let Some(bar) = colorbars.last().filter(|_| i == group.panels.start) {
                        x = x
                            .max(bar.right(label_line) + 2.5 * s + gutter(axes[i].2) + captions(i));
                    }
                }
                map_x.push(x.round());
                maps_right = x + map_w;
            }
            let bar_x = (maps_right + 1.2 * s).round();
            // As tall as the group's first map; maps cut in different planes differ in shape,
            // and the bar then spans the tallest.
            let bar_h = if mixed {
                map_heights[group.panels.clone()]
                    .iter()
                    .copied()
                    .fold(0.0, f64::max)
            } else {
                map_heights[group.panels.start]
            };
            let ticks = vertical_ticks(group.scale.lo, group.scale.hi, bar_h, tick_cap);
            let text = widest(&ticks.labels, s)?;
            let label_x =
                bar_x + colorbar_w + tick_length + tick_gap + text + 0.5 * s + label_line / 2.0;
            // Moved down to the maps (and right with the title) below.
            colorbars.push(ColorbarLayout {
                rect: rect(bar_x, 0.0, colorbar_w, bar_h),
                ticks,
                label_x,
            });
        }
        let last_bar = colorbars.last().ok_or(RenderError::NoPanels)?;
        let mut width = last_bar.right(label_line) + margin;
        let last_subtitle_right = map_x[count - 1] + map_w / 2.0 + subtitle_widths[count - 1] / 2.0;
        width = width.max(last_subtitle_right + margin);

        // The title, centred over the maps unless it needs the whole width.
        let title_w = font::text_width(&title, sizes.title)?;
        let maps_centre = (map_x[0] + maps_right) / 2.0;
        let mut shift = 0.0;
        let mut title_x = maps_centre;
        if title_w > 0.0 {
            if title_x - title_w / 2.0 < margin || title_x + title_w / 2.0 > width - margin {
                title_x = width / 2.0;
            }
            if title_w + 2.0 * margin > width {
                shift = ((title_w + 2.0 * margin - width) / 2.0).round();
                width = title_w + 2.0 * margin;
                title_x = width / 2.0;
            }
        }

        // Vertical positions.
        let mut y = margin;
        let mut title_baseline = y;
        if !title.is_empty() {
            title_baseline = y + font::ascent(sizes.title);
            y = title_baseline + font::descent(sizes.title) + 0.6 * s;
        }
        let mut subtitle_baseline = y;
        if figure.panels.iter().any(|p| !p.subtitle.is_empty()) {
            subtitle_baseline = y + font::ascent(sizes.subtitle);
            y = subtitle_baseline + font::descent(sizes.subtitle) + 0.5 * s;
        }
        // Room for the top strip tick label, which is centred on its tick.
        y += tick_cap;
        let strip_y = y.round();
        let strip_gap = if has_strips { (1.1 * s).round() } else { 0.0 };
        let map_y = strip_y + strip_h + strip_gap;
        let label_baseline = |map_h: f64| {
            map_y + map_h + tick_length + tick_gap + tick_cap + 0.7 * s + font::ascent(sizes.label)
        };
        let x_label_baseline = label_baseline(tallest);
        let height = x_label_baseline + font::descent(sizes.label) + margin;
        if width > MAX_SIDE_PX || height > MAX_SIDE_PX {
            return Err(RenderError::Draw(format!(
                "the figure would be {width:.0} x {height:.0} px, more than {MAX_SIDE_PX} px; \
                 reduce the panel width or the number of panels"
            )));
        }

        let panels = figure
            .panels
            .iter()
            .zip(axes)
            .zip(map_x.iter().zip(&map_heights))
            .enumerate()
            .map(|(i, ((panel, (x_ticks, z_ticks, widest)), (&mx, &mh)))| {
                let mx = mx + shift;
                PanelLayout {
                    map: rect(mx, map_y, map_w, mh),
                    strip: rect(mx, strip_y, map_w, strip_h),
                    x_ticks,
                    z_ticks,
                    strip_ticks: strip_ticks.clone(),
                    rotated_label_x: mx - gutter(widest) - 0.5 * s - label_line / 2.0,
                    x_label_baseline: if mixed {
                        label_baseline(mh)
                    } else {
                        x_label_baseline
                    },
                    x_min: panel.x.min,
                    x_max: panel.x.max,
                    z_min: panel.z.min,
                    z_max: panel.z.max,
                    z_down: figure.axes_of(panel).vertical_is_depth,
                    strip_drawn: strip_drawn[i],
                    new_axes: new_axes[i],
                }
            })
            .collect();
        Ok(Layout {
            width: width.ceil() as u32,
            height: height.ceil() as u32,
            sizes,
            tick_length,
            tick_gap,
            title_baseline,
            title_x,
            title,
            subtitles,
            subtitle_baseline,
            panels,
            colorbars: colorbars
                .into_iter()
                .map(|bar| ColorbarLayout {
                    rect: Rect {
                        x: bar.rect.x + shift as i32,
                        y: map_y.round() as i32,
                        ..bar.rect
                    },
                    label_x: bar.label_x + shift,
                    ..bar
                })
                .collect(),
            label_line,
            has_strips,
            traction_min: t_min,
            traction_max: t_max,
        })
    }
}

fn rect(x: f64, y: f64, w: f64, h: f64) -> Rect {
    Rect {
        x: x.round() as i32,
        y: y.round() as i32,
        w: w.round() as i32,
        h: h.round() as i32,
    }
}

fn widest(labels: &[String], size: f64) -> Result<f64, RenderError> {
    labels
        .iter()
        .try_fold(0.0, |w: f64, l| Ok(w.max(font::text_width(l, size)?)))
}

/// Ticks along a horizontal axis `length` pixels long: labels at least a tick size apart.
fn horizontal_ticks(lo: f64, hi: f64, length: f64, size: f64) -> Ticks {
    // A label that cannot be measured counts as not fitting.
    choose_ticks(lo, hi, |step, labels| {
        let spacing = step / (hi - lo) * length;
        let widest = widest(labels, size).unwrap_or(f64::INFINITY);
        spacing >= widest + 1.2 * size && labels.len() <= 11
    })
}

/// Ticks along a vertical axis: label lines at least 2.4 cap heights apart, at most 8.
fn vertical_ticks(lo: f64, hi: f64, length: f64, cap: f64) -> Ticks {
    choose_ticks(lo, hi, |step, labels| {
        step / (hi - lo) * length >= 2.4 * cap && labels.len() <= 8
    })
}

/// Range of the traction axis: `[min(0, min q), 1.15 max(p, q)]`, never empty.
fn traction_range(panels: &[Panel]) -> (f64, f64) {
    let mut lo: f64 = 0.0;
    let mut hi: f64 = 0.0;
    for sample in panels.iter().flat_map(|p| &p.traction) {
        for v in [sample.p, sample.q] {
            if v.is_finite() {
                lo = lo.min(v);
                hi = hi.max(v);
            }
        }
    }
    if hi <= 0.0 && lo >= 0.0 {
        hi = 1.0;
    }
    let pad = 0.15 * (hi - lo);
    (
        if lo < 0.0 { lo - pad } else { 0.0 },
        hi + if hi > 0.0 { pad } else { 0.0 },
    )
}

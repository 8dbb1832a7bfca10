//! The one drawing routine behind PNG and SVG: it walks a [`Plan`] and paints it through a
//! [`Painter`] over any plotters backend.

use plotters::prelude::{DrawingBackend, RGBAColor};

use super::font;
use super::layout::{ColorbarLayout, Layout, PanelLayout};
use super::paint::{Align, Painter};
use super::plan::{marker_radius, PanelPlan, Plan, TextBox};
use super::scales::ScaleGroup;
use super::{AxesOf, Figure, Panel, RenderError};

const INK: RGBAColor = RGBAColor(0, 0, 0, 1.0);
const TEXT: RGBAColor = RGBAColor(20, 20, 20, 1.0);
const CONTOUR: RGBAColor = RGBAColor(0, 0, 0, 0.6);
const LABEL_BACKGROUND: RGBAColor = RGBAColor(255, 255, 255, 0.8);
const PRESSURE: RGBAColor = RGBAColor(25, 25, 25, 1.0);
const PRESSURE_FILL: RGBAColor = RGBAColor(0, 0, 0, 0.08);
const SHEAR: RGBAColor = RGBAColor(200, 70, 30, 1.0);
const GUIDE: RGBAColor = RGBAColor(0, 0, 0, 0.35);
const WHITE: RGBAColor = RGBAColor(255, 255, 255, 1.0);

/// Widths of lines, from the tick font size.
struct Pens {
    axis: f64,
    contour: f64,
    curve: f64,
}

impl Pens {
    fn new(tick: f64) -> Self {
        let axis = (tick / 15.0).clamp(1.0, 2.0);
        Self {
            axis,
            contour: (0.07 * tick).clamp(0.9, 2.0),
            curve: 1.6 * axis,
        }
    }
}

/// Paints the whole figure. The bitmaps come first (the raster target blits them; the vector
/// target leaves them to its caller, which puts them under everything).
pub(crate) fn draw<DB: DrawingBackend>(
    painter: &mut Painter<'_, DB>,
    plan: &Plan<'_>,
) -> Result<(), RenderError> {
    let figure = plan.figure;
    let layout = &plan.layout;
    let pens = Pens::new(layout.sizes.tick);
    for (rect, rgb) in &plan.images {
        painter.image(*rect, rgb)?;
    }
    for (index, ((panel, pl), pp)) in figure
        .panels
        .iter()
        .zip(&layout.panels)
        .zip(&plan.panels)
        .enumerate()
    {
        for line in &pp.contours {
            painter.stroke(line, pens.contour, CONTOUR)?;
        }
        for outline in &pp.outlines {
            // A white line under the black dashes: the outline stays visible on the dark end
            // of a colour map (inferno, magma) as on its light end.
            painter.stroke(outline, 2.5 * pens.contour, WHITE)?;
            painter.dashed(
                outline,
                pens.contour,
                5.0 * pens.contour,
                3.5 * pens.contour,
                INK,
            )?;
        }
        map_axes(painter, figure.axes_of(panel), layout, pl, &pens)?;
        if pl.strip_drawn {
            strip(painter, figure, layout, pl, pp, panel, &pens)?;
        }
        for label in &pp.contour_labels {
            text_box(painter, label)?;
        }
        let r = marker_radius(layout.sizes.tick);
        for extreme in &pp.extremes {
            painter.disc(extreme.at, r, WHITE, INK, 1.5 * pens.axis)?;
            text_box(painter, &extreme.label)?;
        }
        let (centre, _) = pl.map.center();
        let subtitle = &layout.subtitles[index];
        painter.text(
            subtitle,
            (centre, layout.subtitle_baseline),
            layout.sizes.subtitle,
            Align::Center,
            false,
            TEXT,
        )?;
    }
    for (group, bar) in plan.groups.iter().zip(&layout.colorbars) {
        colorbar(painter, layout, group, bar, &pens)?;
    }
    painter.text(
        &layout.title,
        (layout.title_x, layout.title_baseline),
        layout.sizes.title,
        Align::Center,
        false,
        TEXT,
    )
}

fn text_box<DB: DrawingBackend>(
    painter: &mut Painter<'_, DB>,
    label: &TextBox,
) -> Result<(), RenderError> {
    painter.fill_rect(label.bounds, LABEL_BACKGROUND)?;
    painter.text(
        &label.text,
        label.origin,
        label.size,
        Align::Left,
        false,
        TEXT,
    )
}

/// Baseline x of rotated text whose glyphs are centred on the column `centre`.
fn rotated_baseline(centre: f64, size: f64) -> f64 {
    centre + (font::ascent(size) - font::descent(size)) / 2.0
}

/// The frame, ticks, numbers and axis labels of a map (the vertical one where the panel starts
/// new axes).
fn map_axes<DB: DrawingBackend>(
    painter: &mut Painter<'_, DB>,
    axes: AxesOf<'_>,
    layout: &Layout,
    pl: &PanelLayout,
    pens: &Pens,
) -> Result<(), RenderError> {
    let s = layout.sizes.tick;
    let cap = font::cap_height(s);
    let map = pl.map;
    let (left, top) = (f64::from(map.x) - 0.5, f64::from(map.y) - 0.5);
    let (right, bottom) = (f64::from(map.right()) + 0.5, f64::from(map.bottom()) + 0.5);
    let frame = [
        (left, top),
        (right, top),
        (right, bottom),
        (left, bottom),
        (left, top),
    ];
    painter.stroke(&frame, pens.axis, INK)?;

    for (value, label) in pl.x_ticks.values.iter().zip(&pl.x_ticks.labels) {
        let x = pl.px(*value).clamp(left, right);
        painter.stroke(
            &[(x, bottom), (x, bottom + layout.tick_length)],
            pens.axis,
            INK,
        )?;
        let baseline = bottom + layout.tick_length + layout.tick_gap + cap;
        painter.text(label, (x, baseline), s, Align::Center, false, TEXT)?;
    }
    for (value, label) in pl.z_ticks.values.iter().zip(&pl.z_ticks.labels) {
        let z = pl.pz(*value).clamp(top, bottom);
        painter.stroke(&[(left - layout.tick_length, z), (left, z)], pens.axis, INK)?;
        let end = left - layout.tick_length - layout.tick_gap;
        painter.text(label, (end, z + cap / 2.0), s, Align::Right, false, TEXT)?;
    }
    let (centre_x, centre_z) = map.center();
    let size = layout.sizes.label;
    painter.text(
        axes.x_label,
        (centre_x, pl.x_label_baseline),
        size,
        Align::Center,
        false,
        TEXT,
    )?;
    if pl.new_axes {
        let at = (rotated_baseline(pl.rotated_label_x, size), centre_z);
        painter.text(axes.z_label, at, size, Align::Center, true, TEXT)?;
    }
    Ok(())
}

/// The traction strip above a map: p(x) (filled below), q(x) dashed, contact edges, its axis
/// and legend (and its caption where the panel starts new axes).
fn strip<DB: DrawingBackend>(
    painter: &mut Painter<'_, DB>,
    figure: &Figure,
    layout: &Layout,
    pl: &PanelLayout,
    pp: &PanelPlan,
    panel: &Panel,
    pens: &Pens,
) -> Result<(), RenderError> {
    let s = layout.sizes.tick;
    let cap = font::cap_height(s);
    let strip = pl.strip;
    let left = f64::from(strip.x) - 0.5;
    let zero = layout.strip_y(pl, 0.0);
    let surface = f64::from(pl.map.y) - 0.5;

    // Contact edges: thin guides from the strip's zero line down to the surface.
    for edge in [-panel.half_width, panel.half_width] {
        if panel.half_width > 0.0 && edge > pl.x_min && edge < pl.x_max {
            let x = pl.px(edge);
            painter.stroke(&[(x, zero), (x, surface)], 1.0, GUIDE)?;
        }
    }
    // Zero line across the strip.
    painter.stroke(
        &[(left, zero), (f64::from(strip.right()), zero)],
        pens.axis,
        GUIDE,
    )?;

    if let (Some(first_point), Some(last_point)) = (pp.pressure.first(), pp.pressure.last()) {
        let mut area = pp.pressure.clone();
        area.push((last_point.0, zero));
        area.push((first_point.0, zero));
        painter.fill_polygon(&area, PRESSURE_FILL)?;
    }
    if let Some(shear) = &pp.shear {
        painter.dashed(shear, pens.curve, 4.0 * pens.curve, 2.5 * pens.curve, SHEAR)?;
    }
    painter.stroke(&pp.pressure, pens.curve, PRESSURE)?;

    // Axis: spine, ticks, numbers.
    let (top, bottom) = (f64::from(strip.y), f64::from(strip.bottom()));
    painter.stroke(&[(left, top), (left, bottom)], pens.axis, INK)?;
    for (value, label) in pl.strip_ticks.values.iter().zip(&pl.strip_ticks.labels) {
        let y = layout.strip_y(pl, *value);
        painter.stroke(&[(left - layout.tick_length, y), (left, y)], pens.axis, INK)?;
        let end = left - layout.tick_length - layout.tick_gap;
        painter.text(label, (end, y + cap / 2.0), s, Align::Right, false, TEXT)?;
    }
    if pl.new_axes {
        let size = layout.sizes.label;
        let at = (rotated_baseline(pl.rotated_label_x, size), strip.center().1);
        painter.text(&figure.traction_label, at, size, Align::Center, true, TEXT)?;
    }
    legend(painter, layout, pl, pp, pens)
}

/// "— p  - - q" in a top corner of the strip.
fn legend<DB: DrawingBackend>(
    painter: &mut Painter<'_, DB>,
    layout: &Layout,
    pl: &PanelLayout,
    pp: &PanelPlan,
    pens: &Pens,
) -> Result<(), RenderError> {
    let size = layout.sizes.legend;
    let cap = font::cap_height(size);
    // Two dashes and a gap.
    let sample = 10.5 * pens.curve;
    let gap = 0.35 * size;
    let mut entries = vec![("p", false)];
    if pp.shear.is_some() {
        entries.push(("q", true));
    }
    let entry_widths: Vec<f64> = entries
        .iter()
        .map(|(name, _)| Ok(sample + gap + font::text_width(name, size)?))
        .collect::<Result<_, RenderError>>()?;
    let spacing = 1.0 * size;
    let total: f64 = entry_widths.iter().sum::<f64>() + spacing * (entries.len() - 1) as f64;
    let strip = pl.strip;
    let inset = 0.5 * layout.sizes.tick;
    let mut x = if pp.legend_right {
        f64::from(strip.right()) - inset - total
    } else {
        f64::from(strip.x) + inset
    };
    let baseline = f64::from(strip.y) + cap + 0.2 * size;
    let line_y = baseline - cap / 2.0;
    for ((name, dashed), width) in entries.iter().zip(&entry_widths) {
        let line = [(x, line_y), (x + sample, line_y)];
        if *dashed {
            painter.dashed(&line, pens.curve, 4.0 * pens.curve, 2.5 * pens.curve, SHEAR)?;
        } else {
            painter.stroke(&line, pens.curve, PRESSURE)?;
        }
        painter.text(
            name,
            (x + sample + gap, baseline),
            size,
            Align::Left,
            false,
            TEXT,
        )?;
        x += width + spacing;
    }
    Ok(())
}

/// A group's colour bar with its frame, ticks, contour levels and label.
fn colorbar<DB: DrawingBackend>(
    painter: &mut Painter<'_, DB>,
    layout: &Layout,
    group: &ScaleGroup<'_>,
    bar_layout: &ColorbarLayout,
    pens: &Pens,
) -> Result<(), RenderError> {
    let s = layout.sizes.tick;
    let cap = font::cap_height(s);
    let bar = bar_layout.rect;
    let scale = &group.scale;
    let (left, top) = (f64::from(bar.x) - 0.5, f64::from(bar.y) - 0.5);
    let (right, bottom) = (f64::from(bar.right()) + 0.5, f64::from(bar.bottom()) + 0.5);
    let y_of = |v: f64| f64::from(bar.bottom()) - scale.fraction(v) * f64::from(bar.h);
    for level in &group.levels {
        if *level > scale.lo && *level < scale.hi {
            let y = y_of(*level);
            painter.stroke(&[(left, y), (right, y)], pens.contour, CONTOUR)?;
        }
    }
    let frame = [
        (left, top),
        (right, top),
        (right, bottom),
        (left, bottom),
        (left, top),
    ];
    painter.stroke(&frame, pens.axis, INK)?;
    // Values beyond the colour range: a triangle in the end colour on that end.
    let height = 0.9 * (right - left);
    for (beyond, base, tip, value) in [
        (group.beyond[0], bottom, bottom + height, scale.lo),
        (group.beyond[1], top, top - height, scale.hi),
    ] {
        if beyond {
            let [r, g, b] = scale.rgb(value);
            let triangle = [(left, base), (right, base), (0.5 * (left + right), tip)];
            painter.fill_polygon(&triangle, RGBAColor(r, g, b, 1.0))?;
            let mut outline = triangle.to_vec();
            outline.push(triangle[0]);
            painter.stroke(&outline, pens.axis, INK)?;
        }
    }
    for (value, label) in bar_layout.ticks.values.iter().zip(&bar_layout.ticks.labels) {
        let y = y_of(*value).clamp(top, bottom);
        painter.stroke(
            &[(right, y), (right + layout.tick_length, y)],
            pens.axis,
            INK,
        )?;
        let start = right + layout.tick_length + layout.tick_gap;
        painter.text(label, (start, y + cap / 2.0), s, Align::Left, false, TEXT)?;
    }
    let size = layout.sizes.label;
    let at = (rotated_baseline(bar_layout.label_x, size), bar.center().1);
    painter.text(group.value_label, at, size, Align::Center, true, TEXT)
}

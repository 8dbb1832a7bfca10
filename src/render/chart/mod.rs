//! Charts (line, marker and histogram plots on linear or logarithmic axes) and sheets (a
//! title over rows of maps and charts), drawn with the same painter, font and colours as the
//! maps, into PNG pixels or SVG text.

use plotters::prelude::{BitMapBackend, DrawingBackend, SVGBackend};
use plotters::style::RGBAColor;

use super::font;
use super::layout::Rect;
use super::paint::{draw_error, Align, Painter, Target};
use super::table::{table_png, table_svg, Table};
use super::ticks::choose_ticks;
use super::{render_png, render_svg, Figure, RenderError};

/// A colour-blind-safe qualitative palette (Okabe & Ito 2008).
pub const PALETTE: [[u8; 3]; 7] = [
    [0, 114, 178],
    [213, 94, 0],
    [0, 158, 115],
    [204, 121, 167],
    [230, 159, 0],
    [86, 180, 233],
    [0, 0, 0],
];

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Style {
    Line,
    Dashed,
    Markers,
    /// A histogram: each point is a bin centre and height; bins are the points' spacing wide.
    Bars,
}

/// One series of points in data coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Legend text; empty for none.
    pub label: String,
    pub points: Vec<(f64, f64)>,
    pub style: Style,
    pub colour: [u8; 3],
}

/// Axis scale.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scale {
    Linear,
    Log,
}

/// A chart.
#[derive(Clone, Debug, PartialEq)]
pub struct Chart {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub x_scale: Scale,
    pub y_scale: Scale,
    /// Fixed ranges (else from the data).
    pub x_range: Option<(f64, f64)>,
    pub y_range: Option<(f64, f64)>,
    pub series: Vec<Series>,
    /// A shaded span of x, e.g. the band of a fit.
    pub x_band: Option<(f64, f64)>,
    /// Horizontal reference lines (dashed grey), with a label.
    pub hlines: Vec<(f64, String)>,
    pub width_px: u32,
    pub height_px: u32,
}

impl Chart {
    /// A chart with logarithmic axes in x and y (spectra, area against load).
    pub fn log_log(title: &str, x_label: &str, y_label: &str) -> Self {
        Self {
            x_scale: Scale::Log,
            y_scale: Scale::Log,
            ..Self::new(title, x_label, y_label)
        }
    }

    pub fn new(title: &str, x_label: &str, y_label: &str) -> Self {
        Self {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            x_range: None,
            y_range: None,
            series: Vec::new(),
            x_band: None,
            hlines: Vec::new(),
            width_px: 520,
            height_px: 380,
        }
    }
}

const TITLE_SIZE: f64 = 17.0;
const LABEL_SIZE: f64 = 15.0;
const TICK_SIZE: f64 = 13.0;

fn rgba(c: [u8; 3], alpha: f64) -> RGBAColor {
    RGBAColor(c[0], c[1], c[2], alpha)
}

const BLACK: RGBAColor = RGBAColor(0, 0, 0, 1.0);
const GRID: RGBAColor = RGBAColor(220, 220, 220, 1.0);

/// One axis: data range and scale, mapped onto a pixel span.
#[derive(Clone, Copy, Debug)]
struct AxisMap {
    lo: f64,
    hi: f64,
    scale: Scale,
    from: f64,
    to: f64,
}

impl AxisMap {
    fn t(&self, v: f64) -> f64 {
        match self.scale {
            Scale::Linear => v,
            Scale::Log => v.log10(),
        }
    }

    fn px(&self, v: f64) -> f64 {
        let (a, b) = (self.t(self.lo), self.t(self.hi));
        self.from + (self.t(v) - a) / (b - a) * (self.to - self.from)
    }
}

/// The data range of an axis from the values (positive only on a log axis), padded.
fn range(values: impl Iterator<Item = f64>, scale: Scale) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && (scale == Scale::Linear || *v > 0.0))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return match scale {
            Scale::Linear => (0.0, 1.0),
            Scale::Log => (1.0, 10.0),
        };
    }
    match scale {
        Scale::Linear => {
            let span = if hi > lo { hi - lo } else { lo.abs().max(1.0) };
            (lo - 0.05 * span, hi + 0.05 * span)
        }
        Scale::Log => {
            let (a, b) = (lo.log10(), hi.log10());
            let span = (b - a).max(1.0);
            (10f64.powf(a - 0.04 * span), 10f64.powf(b + 0.04 * span))
        }
    }
}

/// Superscript digits for decade labels: 10⁻³.
fn superscript(exponent: i32) -> String {
    exponent
        .to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            _ => '⁹',
        })
        .collect()
}

/// Ticks of a log axis: labelled decades and unlabelled minor ticks (2..9); within less than
/// two decades, also 2 and 5 times the decades, labelled.
fn log_ticks(lo: f64, hi: f64) -> (Vec<(f64, String)>, Vec<f64>) {
    let (a, b) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    let mut major = Vec::new();
    let mut minor = Vec::new();
    let few = (hi / lo).log10() < 2.0;
    for k in a..=b {
        let decade = 10f64.powi(k);
        for m in 1..10 {
            let v = m as f64 * decade;
            if v < lo * (1.0 - 1e-9) || v > hi * (1.0 + 1e-9) {
                continue;
            }
            if m == 1 {
                major.push((v, format!("10{}", superscript(k))));
            } else if few && (m == 2 || m == 5) {
                major.push((v, format!("{m}·10{}", superscript(k))));
            } else {
                minor.push(v);
            }
        }
    }
    (major, minor)
}

fn linear_ticks(lo: f64, hi: f64, pixels: f64) -> Vec<(f64, String)> {
    let ticks = choose_ticks(lo, hi, |step, labels| {
        let widest = labels
            .iter()
            .map(|l| font::text_width(l, TICK_SIZE).unwrap_or(40.0))
            .fold(0.0, f64::max);
        step / (hi - lo) * pixels >= (widest + 12.0).max(34.0)
    });
    ticks.values.into_iter().zip(ticks.labels).collect()
}

/// Draws `chart` with `painter` into the whole of its image.
fn draw_chart<DB: DrawingBackend>(
    painter: &mut Painter<'_, DB>,
    chart: &Chart,
) -> Result<(), RenderError> {
    let (w, h) = (f64::from(chart.width_px), f64::from(chart.height_px));
    painter.fill_rect([0.0, 0.0, w, h], RGBAColor(255, 255, 255, 1.0))?;
    let points = || chart.series.iter().flat_map(|s| s.points.iter().copied());
    let (x0, x1) = chart.x_range.unwrap_or_else(|| {
        range(
            points()
                .map(|p| p.0)
                .chain(chart.x_band.iter().flat_map(|b| [b.0, b.1])),
            chart.x_scale,
        )
    });
    let (y0, y1) = chart.y_range.unwrap_or_else(|| {
        range(
            points()
                .map(|p| p.1)
                .chain(chart.hlines.iter().map(|l| l.0)),
            chart.y_scale,
        )
    });
    let y_ticks_probe: Vec<(f64, String)> = match chart.y_scale {
        Scale::Linear => linear_ticks(y0, y1, h * 0.7),
        Scale::Log => log_ticks(y0, y1).0,
    };
    let widest = y_ticks_probe
        .iter()
        .map(|(_, l)| font::text_width(l, TICK_SIZE).unwrap_or(40.0))
        .fold(0.0, f64::max);
    let left = 14.0 + font::em(LABEL_SIZE) + 8.0 + widest + 8.0;
    let (top, right) = (14.0 + font::em(TITLE_SIZE) + 10.0, w - 18.0);
    let bottom = h - (10.0 + font::em(LABEL_SIZE) + 6.0 + font::em(TICK_SIZE) + 8.0);
    let x = AxisMap {
        lo: x0,
        hi: x1,
        scale: chart.x_scale,
        from: left,
        to: right,
    };
    let y = AxisMap {
        lo: y0,
        hi: y1,
        scale: chart.y_scale,
        from: bottom,
        to: top,
    };
    let inside = |px: f64, py: f64| {
        px >= left - 0.5 && px <= right + 0.5 && py >= top - 0.5 && py <= bottom + 0.5
    };

    // Title and axis labels.
    painter.text(
        &chart.title,
        ((left + right) / 2.0, 12.0 + font::ascent(TITLE_SIZE)),
        TITLE_SIZE,
        Align::Center,
        false,
        BLACK,
    )?;
    painter.text(
        &chart.x_label,
        ((left + right) / 2.0, h - 10.0 - font::descent(LABEL_SIZE)),
        LABEL_SIZE,
        Align::Center,
        false,
        BLACK,
    )?;
    painter.text(
        &chart.y_label,
        (12.0 + font::ascent(LABEL_SIZE), (top + bottom) / 2.0),
        LABEL_SIZE,
        Align::Center,
        true,
        BLACK,
    )?;

    // Band, grid, ticks.
    if let Some((b0, b1)) = chart.x_band {
        let (p0, p1) = (x.px(b0.max(x0)).max(left), x.px(b1.min(x1)).min(right));
        painter.fill_rect([p0, top, p1, bottom], RGBAColor(255, 232, 170, 1.0))?;
    }
    let x_ticks = match chart.x_scale {
        Scale::Linear => (linear_ticks(x0, x1, right - left), Vec::new()),
        Scale::Log => log_ticks(x0, x1),
    };
    let y_ticks = match chart.y_scale {
        Scale::Linear => (linear_ticks(y0, y1, bottom - top), Vec::new()),
        Scale::Log => log_ticks(y0, y1),
    };
    for (v, _) in &x_ticks.0 {
        let px = x.px(*v);
        painter.stroke(&[(px, top), (px, bottom)], 1.0, GRID)?;
    }
    for (v, _) in &y_ticks.0 {
        let py = y.px(*v);
        painter.stroke(&[(left, py), (right, py)], 1.0, GRID)?;
    }
    for (v, label) in &x_ticks.0 {
        let px = x.px(*v);
        painter.stroke(&[(px, bottom), (px, bottom + 5.0)], 1.0, BLACK)?;
        painter.text(
            label,
            (px, bottom + 7.0 + font::ascent(TICK_SIZE)),
            TICK_SIZE,
            Align::Center,
            false,
            BLACK,
        )?;
    }
    for v in &x_ticks.1 {
        let px = x.px(*v);
        painter.stroke(&[(px, bottom), (px, bottom + 3.0)], 1.0, BLACK)?;
    }
    for (v, label) in &y_ticks.0 {
        let py = y.px(*v);
        painter.stroke(&[(left - 5.0, py), (left, py)], 1.0, BLACK)?;
        painter.text(
            label,
            (left - 8.0, py + font::cap_height(TICK_SIZE) / 2.0),
            TICK_SIZE,
            Align::Right,
            false,
            BLACK,
        )?;
    }
    for v in &y_ticks.1 {
        let py = y.px(*v);
        painter.stroke(&[(left - 3.0, py), (left, py)], 1.0, BLACK)?;
    }

    // Reference lines and series.
    for (value, label) in &chart.hlines {
        let py = y.px(*value);
        if py.is_finite() && py >= top && py <= bottom {
            painter.dashed(
                &[(left, py), (right, py)],
                1.2,
                6.0,
                4.0,
                RGBAColor(110, 110, 110, 1.0),
            )?;
            painter.text(
                label,
                (right - 4.0, py - 4.0),
                TICK_SIZE,
                Align::Right,
                false,
                RGBAColor(80, 80, 80, 1.0),
            )?;
        }
    }
    let valid = |p: &(f64, f64)| {
        p.0.is_finite()
            && p.1.is_finite()
            && (chart.x_scale == Scale::Linear || p.0 > 0.0)
            && (chart.y_scale == Scale::Linear || p.1 > 0.0)
    };
    for series in &chart.series {
        let colour = rgba(series.colour, 1.0);
        let pixels: Vec<(f64, f64)> = series
            .points
            .iter()
            .filter(|p| valid(p))
            .map(|p| (x.px(p.0), y.px(p.1)))
            .collect();
        match series.style {
            Style::Line | Style::Dashed => {
                // Clip to the plot: keep runs of points inside (lines leave through the edge).
                let clipped: Vec<(f64, f64)> = pixels
                    .iter()
                    .map(|&(px, py)| (px.clamp(left, right), py.clamp(top, bottom)))
                    .collect();
                if series.style == Style::Line {
                    painter.stroke(&clipped, 2.0, colour)?;
                } else {
                    painter.dashed(&clipped, 2.0, 8.0, 5.0, colour)?;
                }
            }
            Style::Markers => {
                for &(px, py) in pixels.iter().filter(|p| inside(p.0, p.1)) {
                    painter.disc((px, py), 3.5, colour, BLACK, 0.8)?;
                }
            }
            Style::Bars => {
                let half = if series.points.len() > 1 {
                    0.5 * (series.points[1].0 - series.points[0].0)
                } else {
                    0.5
                };
                for p in series.points.iter().filter(|p| valid(p)) {
                    let (a, b) = (x.px(p.0 - half).max(left), x.px(p.0 + half).min(right));
                    let base = y
                        .px(if chart.y_scale == Scale::Log {
                            y0
                        } else {
                            0f64.max(y0)
                        })
                        .min(bottom);
                    let top_px = y.px(p.1).max(top);
                    painter.fill_rect([a, top_px, b, base], rgba(series.colour, 0.35))?;
                    painter.stroke(
                        &[(a, base), (a, top_px), (b, top_px), (b, base)],
                        1.0,
                        colour,
                    )?;
                }
            }
        }
    }
    // Frame.
    painter.stroke(
        &[
            (left, top),
            (right, top),
            (right, bottom),
            (left, bottom),
            (left, top),
        ],
        1.0,
        BLACK,
    )?;

    // Legend in the corner of the plot with the fewest points under it.
    let entries: Vec<&Series> = chart
        .series
        .iter()
        .filter(|s| !s.label.is_empty())
        .collect();
    if !entries.is_empty() {
        let line_height = font::em(TICK_SIZE) + 6.0;
        let text_w = entries
            .iter()
            .map(|s| font::text_width(&s.label, TICK_SIZE).unwrap_or(60.0))
            .fold(0.0, f64::max);
        let (bw, bh) = (text_w + 46.0, line_height * entries.len() as f64 + 8.0);
        let corners = [
            (right - bw - 6.0, top + 6.0),
            (left + 6.0, top + 6.0),
            (right - bw - 6.0, bottom - bh - 6.0),
            (left + 6.0, bottom - bh - 6.0),
        ];
        let covered = |(cx, cy): (f64, f64)| {
            chart
                .series
                .iter()
                .flat_map(|s| s.points.iter())
                .filter(|p| valid(p))
                .filter(|p| {
                    let (px, py) = (x.px(p.0), y.px(p.1));
                    px >= cx && px <= cx + bw && py >= cy && py <= cy + bh
                })
                .count()
        };
        let (bx, by) = corners
            .into_iter()
            .min_by_key(|c| covered(*c))
            .unwrap_or(corners[0]);
        painter.fill_rect([bx, by, bx + bw, by + bh], RGBAColor(255, 255, 255, 0.9))?;
        painter.stroke(
            &[
                (bx, by),
                (bx + bw, by),
                (bx + bw, by + bh),
                (bx, by + bh),
                (bx, by),
            ],
            1.0,
            RGBAColor(160, 160, 160, 1.0),
        )?;
        for (k, series) in entries.iter().enumerate() {
            let cy = by + 4.0 + line_height * (k as f64 + 0.5);
            let colour = rgba(series.colour, 1.0);
            match series.style {
                Style::Line => painter.stroke(&[(bx + 8.0, cy), (bx + 34.0, cy)], 2.0, colour)?,
                Style::Dashed => {
                    painter.dashed(&[(bx + 8.0, cy), (bx + 34.0, cy)], 2.0, 8.0, 5.0, colour)?
                }
                Style::Markers => painter.disc((bx + 21.0, cy), 3.5, colour, BLACK, 0.8)?,
                Style::Bars => painter.fill_rect(
                    [bx + 10.0, cy - 5.0, bx + 32.0, cy + 5.0],
                    rgba(series.colour, 0.5),
                )?,
            }
            painter.text(
                &series.label,
                (bx + 40.0, cy + font::cap_height(TICK_SIZE) / 2.0),
                TICK_SIZE,
                Align::Left,
                false,
                BLACK,
            )?;
        }
    }
    Ok(())
}

/// The chart as pixels.
pub fn chart_png(chart: &Chart) -> Result<image::RgbImage, RenderError> {
    font::ensure_registered()?;
    let (w, h) = (chart.width_px, chart.height_px);
    let mut pixels = vec![255u8; w as usize * h as usize * 3];
    {
        let mut backend = BitMapBackend::with_buffer(&mut pixels, (w, h));
        let mut painter = Painter::new(&mut backend, Target::Raster);
        draw_chart(&mut painter, chart)?;
        backend.present().map_err(draw_error)?;
    }
    image::RgbImage::from_raw(w, h, pixels)
        .ok_or_else(|| RenderError::Draw("chart buffer size".into()))
}

/// The chart as an SVG document.
pub fn chart_svg(chart: &Chart) -> Result<String, RenderError> {
    font::ensure_registered()?;
    let mut text = String::new();
    {
        let mut backend = SVGBackend::with_string(&mut text, (chart.width_px, chart.height_px));
        let mut painter = Painter::new(&mut backend, Target::Vector);
        draw_chart(&mut painter, chart)?;
        backend.present().map_err(draw_error)?;
    }
    Ok(text.replace(
        "font-family=\"sans-serif\"",
        "font-family=\"DejaVu Sans, sans-serif\"",
    ))
}

/// One cell of a sheet.
#[derive(Clone, Debug)]
pub enum Cell {
    Map(Figure),
    Chart(Chart),
    Table(Table),
}

/// A title over rows of maps and charts, with notes (warnings) under the title.
#[derive(Clone, Debug)]
pub struct Sheet {
    pub title: String,
    /// Lines under the title, in red: what the reader must know about the whole sheet.
    pub notes: Vec<String>,
    pub rows: Vec<Vec<Cell>>,
}

const GAP: u32 = 16;
const SHEET_TITLE: f64 = 22.0;
const SHEET_NOTE: f64 = 14.0;
const NOTE_COLOUR: RGBAColor = RGBAColor(178, 24, 43, 1.0);

/// The baseline of note `index` under the title.
fn note_baseline(index: usize) -> f64 {
    14.0 + font::em(SHEET_TITLE)
        + 6.0
        + index as f64 * (font::em(SHEET_NOTE) + 4.0)
        + font::ascent(SHEET_NOTE)
}

/// The notes wrapped at word boundaries into lines no wider than `width` pixels (less the
/// sheet's margins): a long warning stays on the sheet instead of running off both sides.
fn wrapped_notes(notes: &[String], width: u32) -> Result<Vec<String>, RenderError> {
    let room = f64::from(width.saturating_sub(2 * GAP)).max(100.0);
    let mut lines = Vec::new();
    for note in notes {
        let mut line = String::new();
        for word in note.split(' ') {
            let candidate = if line.is_empty() {
                word.to_string()
            } else {
                format!("{line} {word}")
            };
            if !line.is_empty() && font::text_width(&candidate, SHEET_NOTE)? > room {
                lines.push(std::mem::replace(&mut line, word.to_string()));
            } else {
                line = candidate;
            }
        }
        lines.push(line);
    }
    Ok(lines)
}

/// Cell images and their placement: `(x, y)` of each cell, row by row, and the sheet's size,
/// below the title and `notes` lines.
fn place(sizes: &[Vec<(u32, u32)>], notes: usize) -> (Vec<Vec<(u32, u32)>>, u32, u32) {
    let title = (14.0 + font::em(SHEET_TITLE) + 10.0) as u32;
    let notes = (notes as f64 * (font::em(SHEET_NOTE) + 4.0)).ceil() as u32;
    let mut y = title + notes;
    let mut width = 0;
    let mut places = Vec::new();
    for row in sizes {
        let mut x = GAP;
        let mut row_places = Vec::new();
        let mut height = 0;
        for &(w, h) in row {
            row_places.push((x, y));
            x += w + GAP;
            height = height.max(h);
        }
        width = width.max(x);
        y += height + GAP;
        places.push(row_places);
    }
    (places, width.max(200), y)
}

/// The sheet as pixels: each map and chart rendered and placed, the title on top.
pub fn sheet_png(sheet: &Sheet) -> Result<image::RgbImage, RenderError> {
    let images: Vec<Vec<image::RgbImage>> = sheet
        .rows
        .iter()
        .map(|row| {
            row.iter()
                .map(|cell| match cell {
                    Cell::Map(figure) => render_png(figure),
                    Cell::Chart(chart) => chart_png(chart),
                    Cell::Table(table) => table_png(table),
                })
                .collect::<Result<Vec<_>, _>>()
        })
        .collect::<Result<_, _>>()?;
    let sizes: Vec<Vec<(u32, u32)>> = images
        .iter()
        .map(|r| r.iter().map(|i| i.dimensions()).collect())
        .collect();
    let notes = wrapped_notes(&sheet.notes, place(&sizes, 0).1)?;
    let (places, width, height) = place(&sizes, notes.len());
    let mut pixels = vec![255u8; width as usize * height as usize * 3];
    {
        let mut backend = BitMapBackend::with_buffer(&mut pixels, (width, height));
        let mut painter = Painter::new(&mut backend, Target::Raster);
        painter.text(
            &sheet.title,
            (f64::from(width) / 2.0, 12.0 + font::ascent(SHEET_TITLE)),
            SHEET_TITLE,
            Align::Center,
            false,
            BLACK,
        )?;
        for (index, note) in notes.iter().enumerate() {
            painter.text(
                note,
                (f64::from(width) / 2.0, note_baseline(index)),
                SHEET_NOTE,
                Align::Center,
                false,
                NOTE_COLOUR,
            )?;
        }
        for (row, row_places) in images.iter().zip(&places) {
            for (image, &(x, y)) in row.iter().zip(row_places) {
                let rect = Rect {
                    x: x as i32,
                    y: y as i32,
                    w: image.width() as i32,
                    h: image.height() as i32,
                };
                painter.image(rect, image.as_raw())?;
            }
        }
        backend.present().map_err(draw_error)?;
    }
    image::RgbImage::from_raw(width, height, pixels)
        .ok_or_else(|| RenderError::Draw("sheet buffer size".into()))
}

/// The sheet as one SVG document: each cell's own SVG nested at its place.
pub fn sheet_svg(sheet: &Sheet) -> Result<String, RenderError> {
    let documents: Vec<Vec<(String, (u32, u32))>> = sheet
        .rows
        .iter()
        .map(|row| {
            row.iter()
                .map(|cell| -> Result<(String, (u32, u32)), RenderError> {
                    match cell {
                        Cell::Map(figure) => {
                            let size = render_png(figure)?.dimensions();
                            Ok((render_svg(figure)?, size))
                        }
                        Cell::Chart(chart) => {
                            Ok((chart_svg(chart)?, (chart.width_px, chart.height_px)))
                        }
                        Cell::Table(table) => {
                            Ok((table_svg(table)?, (table.width_px, table.height_px)))
                        }
                    }
                })
                .collect::<Result<Vec<_>, _>>()
        })
        .collect::<Result<_, _>>()?;
    let sizes: Vec<Vec<(u32, u32)>> = documents
        .iter()
        .map(|r| r.iter().map(|d| d.1).collect())
        .collect();
    let notes = wrapped_notes(&sheet.notes, place(&sizes, 0).1)?;
    let (places, width, height) = place(&sizes, notes.len());
    let mut out = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"{width}\" height=\"{height}\" viewBox=\"0 0 {width} {height}\">\n<rect x=\"0\" y=\"0\" width=\"{width}\" height=\"{height}\" fill=\"#FFFFFF\"/>\n<text x=\"{}\" y=\"{:.1}\" text-anchor=\"middle\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"{:.1}\">{}</text>\n",
        width / 2,
        12.0 + font::ascent(SHEET_TITLE),
        font::em(SHEET_TITLE),
        sheet.title.replace('&', "&amp;").replace('<', "&lt;")
    );
    for (index, note) in notes.iter().enumerate() {
        out.push_str(&format!(
            "<text x=\"{}\" y=\"{:.1}\" text-anchor=\"middle\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"{:.1}\" fill=\"#B2182B\">{}</text>\n",
            width / 2,
            note_baseline(index),
            font::em(SHEET_NOTE),
            note.replace('&', "&amp;").replace('<', "&lt;")
        ));
    }
    for (row, row_places) in documents.iter().zip(&places) {
        for ((document, (w, h)), &(x, y)) in row.iter().zip(row_places) {
            let body = document
                .find("<svg")
                .map_or(document.as_str(), |i| &document[i..]);
            // Place the nested document: its own <svg> gets the position.
            let placed = body.replacen(
                "<svg",
                &format!("<svg x=\"{x}\" y=\"{y}\" width=\"{w}\" height=\"{h}\""),
                1,
            );
            out.push_str(&dedupe_size(&placed));
            out.push('\n');
        }
    }
    out.push_str("</svg>\n");
    Ok(out)
}

/// Drops the second `width`/`height` attributes of a nested `<svg>` tag (the placement's come
/// first; XML forbids repeated attributes).
fn dedupe_size(document: &str) -> String {
    let Some(end) = document.find('>') else {
        return document.to_string();
    };
    let (tag, rest) = document.split_at(end);
    let mut seen = std::collections::HashSet::new();
    let mut kept = Vec::new();
    for part in split_attributes(tag) {
        let name = part.split('=').next().unwrap_or("").trim().to_string();
        if part.contains('=') && !seen.insert(name) {
            continue;
        }
        kept.push(part);
    }
    format!("{}{rest}", kept.join(" "))
}

/// Splits a tag's text at spaces outside quotes.
fn split_attributes(tag: &str) -> Vec<String> {
    let mut parts = Vec::new();
    let mut current = String::new();
    let mut quoted = false;
    for c in tag.chars() {
        match c {
            '"' => {
                quoted = !quoted;
                current.push(c);
            }
            c if c.is_whitespace() && !quoted => {
                if !current.is_empty() {
                    parts.push(std::mem::take(&mut current));
                }
            }
            c => current.push(c),
        }
    }
    if !current.is_empty() {
        parts.push(current);
    }
    parts
}

#[cfg(test)]
mod tests;

//! Tables of named values for sheets: a title, then rows of a symbol, a value with its unit and
//! what it means, with headings between groups. Drawn with the charts' painter and font, so a
//! sheet's table matches its charts in PNG and SVG.

use plotters::prelude::{BitMapBackend, DrawingBackend, SVGBackend};
use plotters::style::RGBAColor;

use super::font;
use super::paint::{draw_error, Align, Painter, Target};
use super::RenderError;

/// One line of a table.
#[derive(Clone, Debug, PartialEq)]
pub enum Row {
    /// A group heading.
    Heading(String),
    /// Symbol, value with its unit, meaning.
    Value(String, String, String),
}

/// A table cell of a sheet.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    pub title: String,
    pub rows: Vec<Row>,
    pub width_px: u32,
    pub height_px: u32,
}

const TITLE_SIZE: f64 = 17.0;
/// The largest text size; smaller when the rows would not fit.
const TEXT_SIZE: f64 = 14.0;
const MIN_TEXT_SIZE: f64 = 8.0;
const MARGIN: f64 = 18.0;
const COLUMN_GAP: f64 = 14.0;

const BLACK: RGBAColor = RGBAColor(0, 0, 0, 1.0);
const GREY: RGBAColor = RGBAColor(90, 90, 90, 1.0);
const RULE: RGBAColor = RGBAColor(200, 200, 200, 1.0);

/// Widths of the three columns at text size `size`.
fn columns(table: &Table, size: f64) -> Result<[f64; 3], RenderError> {
    let mut widths = [0.0f64; 3];
    for row in &table.rows {
        if let Row::Value(symbol, value, meaning) = row {
            for (width, text) in widths.iter_mut().zip([symbol, value, meaning]) {
                *width = width.max(font::text_width(text, size)?);
            }
        }
    }
    Ok(widths)
}

/// The text size at which every row fits the table's height (line height 1.5 em) and the
/// symbols and values its width; meanings too long for the rest are cut ([`fit_text`]).
fn fitting_size(table: &Table) -> Result<f64, RenderError> {
    let (w, h) = (f64::from(table.width_px), f64::from(table.height_px));
    let top = MARGIN + font::em(TITLE_SIZE) + 12.0;
    let lines = table.rows.len().max(1) as f64;
    let mut size = TEXT_SIZE;
    while size > MIN_TEXT_SIZE {
        let [a, b, _] = columns(table, size)?;
        let fits_width = 2.0 * MARGIN + a + b + 2.0 * COLUMN_GAP + 4.0 * size <= w;
        let fits_height = top + lines * 1.5 * font::em(size) + MARGIN <= h;
        if fits_width && fits_height {
            break;
        }
        size -= 0.5;
    }
    Ok(size)
}

/// `text`, or as much of it as fits `width` followed by an ellipsis.
fn fit_text(text: &str, size: f64, width: f64) -> Result<String, RenderError> {
    if font::text_width(text, size)? <= width {
        return Ok(text.to_string());
    }
    let mut cut: String = text.to_string();
    while !cut.is_empty() {
        cut.pop();
        let candidate = format!("{}…", cut.trim_end());
        if font::text_width(&candidate, size)? <= width {
            return Ok(candidate);
        }
    }
    Ok(String::new())
}

fn draw_table<DB: DrawingBackend>(
    painter: &mut Painter<'_, DB>,
    table: &Table,
) -> Result<(), RenderError> {
    let (w, h) = (f64::from(table.width_px), f64::from(table.height_px));
    painter.fill_rect([0.0, 0.0, w, h], RGBAColor(255, 255, 255, 1.0))?;
    painter.text(
        &table.title,
        (w / 2.0, MARGIN + font::ascent(TITLE_SIZE)),
        TITLE_SIZE,
        Align::Center,
        false,
        BLACK,
    )?;
    let size = fitting_size(table)?;
    let [symbol_w, value_w, _] = columns(table, size)?;
    let line = 1.5 * font::em(size);
    let value_right = MARGIN + symbol_w + COLUMN_GAP + value_w;
    let meaning_left = value_right + COLUMN_GAP;
    let mut y = MARGIN + font::em(TITLE_SIZE) + 12.0;
    for (index, row) in table.rows.iter().enumerate() {
        let baseline = y + font::ascent(size) + 0.25 * font::em(size);
        match row {
            Row::Heading(text) => {
                if index > 0 {
                    painter.stroke(&[(MARGIN, y + 1.0), (w - MARGIN, y + 1.0)], 1.0, RULE)?;
                }
                painter.text(text, (MARGIN, baseline), size, Align::Left, false, GREY)?;
            }
            Row::Value(symbol, value, meaning) => {
                painter.text(symbol, (MARGIN, baseline), size, Align::Left, false, BLACK)?;
                painter.text(
                    value,
                    (value_right, baseline),
                    size,
                    Align::Right,
                    false,
                    BLACK,
                )?;
                let meaning = fit_text(meaning, size, w - MARGIN - meaning_left)?;
                painter.text(
                    &meaning,
                    (meaning_left, baseline),
                    size,
                    Align::Left,
                    false,
                    GREY,
                )?;
            }
        }
        y += line;
    }
    Ok(())
}

/// The table as pixels.
pub fn table_png(table: &Table) -> Result<image::RgbImage, RenderError> {
    font::ensure_registered()?;
    let (w, h) = (table.width_px, table.height_px);
    let mut pixels = vec![255u8; w as usize * h as usize * 3];
    {
        let mut backend = BitMapBackend::with_buffer(&mut pixels, (w, h));
        let mut painter = Painter::new(&mut backend, Target::Raster);
        draw_table(&mut painter, table)?;
        backend.present().map_err(draw_error)?;
    }
    image::RgbImage::from_raw(w, h, pixels)
        .ok_or_else(|| RenderError::Draw("table buffer size".into()))
}

/// The table as an SVG document.
pub fn table_svg(table: &Table) -> Result<String, RenderError> {
    font::ensure_registered()?;
    let mut text = String::new();
    {
        let mut backend = SVGBackend::with_string(&mut text, (table.width_px, table.height_px));
        let mut painter = Painter::new(&mut backend, Target::Vector);
        draw_table(&mut painter, table)?;
        backend.present().map_err(draw_error)?;
    }
    Ok(text.replace(
        "font-family=\"sans-serif\"",
        "font-family=\"DejaVu Sans, sans-serif\"",
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(rows: usize, height_px: u32) -> Table {
        Table {
            title: "Parameters".into(),
            rows: (0..rows)
                .map(|k| {
                    if k % 5 == 0 {
                        Row::Heading(format!("group {k}"))
                    } else {
                        Row::Value(format!("S{k}"), format!("{k}.25 µm"), "a meaning".into())
                    }
                })
                .collect(),
            width_px: 420,
            height_px,
        }
    }

    #[test]
    fn rows_shrink_to_fit_and_both_targets_draw() {
        let roomy = table(10, 600);
        assert_eq!(fitting_size(&roomy).expect("size"), TEXT_SIZE);
        let crowded = table(40, 600);
        let size = fitting_size(&crowded).expect("size");
        assert!(size < TEXT_SIZE, "{size}");
        let top = MARGIN + font::em(TITLE_SIZE) + 12.0;
        assert!(top + 40.0 * 1.5 * font::em(size) + MARGIN <= 600.0);
        let image = table_png(&crowded).expect("png");
        assert_eq!(image.dimensions(), (420, 600));
        // Text was drawn: some dark pixels below the title.
        let dark = image
            .enumerate_pixels()
            .filter(|(_, y, p)| *y > 60 && p.0[0] < 100)
            .count();
        assert!(dark > 100, "{dark}");
        let svg = table_svg(&crowded).expect("svg");
        let long = "a meaning far too long for the narrow space that is left for it";
        let cut = fit_text(long, TEXT_SIZE, 120.0).expect("cut");
        assert!(cut.ends_with('…') && cut.len() < long.len(), "{cut}");
        assert!(font::text_width(&cut, TEXT_SIZE).expect("width") <= 120.0);
        assert_eq!(fit_text("short", TEXT_SIZE, 120.0).expect("kept"), "short");
        assert!(svg.contains("S39") && svg.contains("group 35"));
    }
}

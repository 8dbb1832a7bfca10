//! A thin painter over a plotters [`DrawingBackend`], the one place that knows whether the
//! output is a raster (PNG) or vector (SVG) image.
//!
//! Raster strokes and discs are anti-aliased here with sub-pixel coordinates (plotters' own
//! lines snap to whole pixels and overlap at the joints of translucent polylines); vector output
//! uses plotters' elements. Text goes through plotters in both cases, with the offsets that put
//! the baseline at the same place in PNG and SVG.

use plotters::prelude::{Color, DrawingBackend, FontTransform, IntoFont, RGBAColor, ShapeStyle};
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::font;
use super::layout::Rect;
use super::RenderError;

/// The kind of image drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Target {
    /// Pixels (bitmap backend): anti-aliased strokes by the painter, bitmaps blitted.
    Raster,
    /// SVG: plotters elements; bitmaps are placed by the caller (see `render_svg`).
    Vector,
}

/// Horizontal alignment of text along its baseline.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Align {
    Left,
    Center,
    Right,
}

/// An error of the backend, as text.
pub(crate) fn draw_error(error: impl std::fmt::Display) -> RenderError {
    RenderError::Draw(error.to_string())
}

pub(crate) struct Painter<'a, DB: DrawingBackend> {
    backend: &'a mut DB,
    target: Target,
    width: usize,
    height: usize,
    /// Raster only: coverage of the stroke being drawn, and the pixels it touched.
    coverage: Vec<f32>,
    touched: Vec<usize>,
}

impl<'a, DB: DrawingBackend> Painter<'a, DB> {
    pub fn new(backend: &'a mut DB, target: Target) -> Self {
        let (w, h) = backend.get_size();
        let (width, height) = (w as usize, h as usize);
        let coverage = match target {
            Target::Raster => vec![0.0; width * height],
            Target::Vector => Vec::new(),
        };
        Self {
            backend,
            target,
            width,
            height,
            coverage,
            touched: Vec::new(),
        }
    }

    /// Places an RGB bitmap (`rect.w * rect.h * 3` bytes, rows top down). Vector output leaves
    /// it to the caller, which embeds it as a PNG under everything else.
    pub fn image(&mut self, rect: Rect, rgb: &[u8]) -> Result<(), RenderError> {
        match self.target {
            Target::Raster => self
                .backend
                .blit_bitmap((rect.x, rect.y), (rect.w as u32, rect.h as u32), rgb)
                .map_err(draw_error),
            Target::Vector => Ok(()),
        }
    }

    /// Fills the pixel rectangle `[x0, x1) x [y0, y1)` (coordinates rounded to whole pixels).
    pub fn fill_rect(&mut self, corners: [f64; 4], color: RGBAColor) -> Result<(), RenderError> {
        let [x0, y0, x1, y1] = corners.map(|c| c.round() as i32);
        if x1 <= x0 || y1 <= y0 {
            return Ok(());
        }
        let style = ShapeStyle {
            color,
            filled: true,
            stroke_width: 0,
        };
        self.backend
            .draw_rect((x0, y0), (x1, y1), &style, true)
            .map_err(draw_error)
    }

    /// A polyline through pixel coordinates (pixel `(i, j)` covers `[i, i+1) x [j, j+1)`).
    pub fn stroke(
        &mut self,
        points: &[(f64, f64)],
        width: f64,
        color: RGBAColor,
    ) -> Result<(), RenderError> {
        if points.len() < 2 {
            return Ok(());
        }
        match self.target {
            Target::Raster => self.raster_stroke(points, width, color),
            Target::Vector => {
                let path: Vec<(i32, i32)> = points
                    .iter()
                    .map(|p| (p.0.round() as i32, p.1.round() as i32))
                    .collect();
                let style = ShapeStyle {
                    color,
                    filled: false,
                    stroke_width: width.round().max(1.0) as u32,
                };
                self.backend.draw_path(path, &style).map_err(draw_error)
            }
        }
    }

    /// A dashed polyline: `dash` pixels drawn, `gap` pixels skipped, along its length.
    pub fn dashed(
        &mut self,
        points: &[(f64, f64)],
        width: f64,
        dash: f64,
        gap: f64,
        color: RGBAColor,
    ) -> Result<(), RenderError> {
        for piece in dash_pieces(points, dash, gap) {
            self.stroke(&piece, width, color)?;
        }
        Ok(())
    }

    /// A filled polygon (edges not anti-aliased; stroke the outline for a smooth edge).
    pub fn fill_polygon(
        &mut self,
        points: &[(f64, f64)],
        color: RGBAColor,
    ) -> Result<(), RenderError> {
        if points.len() < 3 {
            return Ok(());
        }
        let vertices: Vec<(i32, i32)> = points
            .iter()
            .map(|p| (p.0.round() as i32, p.1.round() as i32))
            .collect();
        self.backend
            .fill_polygon(vertices, &color)
            .map_err(draw_error)
    }

    /// A filled disc with an outline.
    pub fn disc(
        &mut self,
        centre: (f64, f64),
        radius: f64,
        fill: RGBAColor,
        outline: RGBAColor,
        outline_width: f64,
    ) -> Result<(), RenderError> {
        match self.target {
            Target::Raster => {
                let (cx, cy) = centre;
                self.raster_shape(
                    centre,
                    radius + 1.0,
                    |px, py| {
                        let d = (px - cx).hypot(py - cy);
                        (radius + 0.5 - d).clamp(0.0, 1.0)
                    },
                    fill,
                )?;
                self.raster_shape(
                    centre,
                    radius + outline_width + 1.0,
                    |px, py| {
                        let d = (px - cx).hypot(py - cy);
                        (outline_width / 2.0 + 0.5 - (d - radius).abs()).clamp(0.0, 1.0)
                    },
                    outline,
                )
            }
            Target::Vector => {
                let c = (centre.0.round() as i32, centre.1.round() as i32);
                let r = radius.round().max(1.0) as u32;
                let fill_style = ShapeStyle {
                    color: fill,
                    filled: true,
                    stroke_width: 0,
                };
                self.backend
                    .draw_circle(c, r, &fill_style, true)
                    .map_err(draw_error)?;
                let stroke = ShapeStyle {
                    color: outline,
                    filled: false,
                    stroke_width: outline_width.round().max(1.0) as u32,
                };
                self.backend
                    .draw_circle(c, r, &stroke, false)
                    .map_err(draw_error)
            }
        }
    }

    /// Text with its baseline through `at`; `rotated` text reads upwards (baseline vertical,
    /// glyphs to its left) and `at.1` is then the position along the text.
    pub fn text(
        &mut self,
        text: &str,
        at: (f64, f64),
        size: f64,
        align: Align,
        rotated: bool,
        color: RGBAColor,
    ) -> Result<(), RenderError> {
        if text.is_empty() {
            return Ok(());
        }
        match self.target {
            Target::Raster => self.raster_text(text, at, size, align, rotated, color),
            Target::Vector => {
                // The SVG backend writes font-size = size / 1.24 and dy = 0.76 em for a top
                // anchor: ask for the em of the PNG and move the anchor up to the baseline.
                let em = font::em(size);
                let offset = 0.76 * em;
                let h_pos = match align {
                    Align::Left => HPos::Left,
                    Align::Center => HPos::Center,
                    Align::Right => HPos::Right,
                };
                let (pos, transform) = if rotated {
                    ((at.0 - offset, at.1), FontTransform::Rotate270)
                } else {
                    ((at.0, at.1 - offset), FontTransform::None)
                };
                let style = (font::FAMILY, 1.24 * em)
                    .into_font()
                    .transform(transform)
                    .color(&color)
                    .pos(Pos::new(h_pos, VPos::Top));
                // SVG collapses runs of spaces ("μ = 0,  ν = 0.3"): keep them as the PNG shows.
                let text = text.replace("  ", "\u{a0} ");
                self.backend
                    .draw_text(&text, &style, (pos.0.round() as i32, pos.1.round() as i32))
                    .map_err(draw_error)
            }
        }
    }

    /// Raster text, glyph by glyph: plotters' ab_glyph text ignores left side bearings and
    /// truncates pen positions, which spaces letters unevenly. Each glyph is rasterised by
    /// plotters alone and placed here by its advance and side bearing.
    fn raster_text(
        &mut self,
        text: &str,
        at: (f64, f64),
        size: f64,
        align: Align,
        rotated: bool,
        color: RGBAColor,
    ) -> Result<(), RenderError> {
        let font = (font::FAMILY, size).into_font();
        let total = font::text_width(text, size)?;
        let mut pen = match align {
            Align::Left => 0.0,
            Align::Center => -total / 2.0,
            Align::Right => -total,
        };
        // ab_glyph puts the baseline half a font size below the drawing origin.
        let half = (size / 2.0).round() as i32;
        let mut pixels: Vec<(i32, i32, f32)> = Vec::new();
        let mut utf8 = [0u8; 4];
        for c in text.chars() {
            let (advance, bearing) = font::glyph_metrics(c, size);
            pixels.clear();
            font.draw(c.encode_utf8(&mut utf8), (0, 0), |x, y, coverage| {
                pixels.push((x, y, coverage));
                Ok::<(), ()>(())
            })
            .map_err(|e| RenderError::Draw(format!("cannot draw `{c}`: {e}")))?
            .map_err(|()| RenderError::Draw(format!("cannot draw `{c}`")))?;
            let bearing = bearing.floor() as i32;
            for &(x, y, coverage) in &pixels {
                let across = y - half;
                let point = if rotated {
                    let origin = (at.1 - pen).round() as i32;
                    (at.0.round() as i32 + across, origin - bearing - x - 1)
                } else {
                    let origin = (at.0 + pen).round() as i32;
                    (origin + bearing + x, at.1.round() as i32 + across)
                };
                let inside = point.0 >= 0
                    && point.1 >= 0
                    && (point.0 as usize) < self.width
                    && (point.1 as usize) < self.height;
                if inside && coverage > 0.0 {
                    let ink = color.mix(f64::from(coverage.min(1.0))).to_backend_color();
                    self.backend.draw_pixel(point, ink).map_err(draw_error)?;
                }
            }
            pen += advance;
        }
        Ok(())
    }

    fn raster_stroke(
        &mut self,
        points: &[(f64, f64)],
        width: f64,
        color: RGBAColor,
    ) -> Result<(), RenderError> {
        let reach = width / 2.0 + 1.0;
        let strength = width.min(1.0) as f32;
        for segment in points.windows(2) {
            let (a, b) = (segment[0], segment[1]);
            let x0 = ((a.0.min(b.0) - reach).floor().max(0.0)) as usize;
            let y0 = ((a.1.min(b.1) - reach).floor().max(0.0)) as usize;
            let x1 = ((a.0.max(b.0) + reach).ceil().max(0.0) as usize).min(self.width);
            let y1 = ((a.1.max(b.1) + reach).ceil().max(0.0) as usize).min(self.height);
            for py in y0..y1 {
                for px in x0..x1 {
                    let d = distance_to_segment((px as f64 + 0.5, py as f64 + 0.5), a, b);
                    let c = (width / 2.0 + 0.5 - d).clamp(0.0, 1.0) as f32 * strength;
                    self.cover(px, py, c);
                }
            }
        }
        self.flush(color)
    }

    /// Fills pixels within `reach` of `centre` with the coverage `shape` gives a pixel centre.
    fn raster_shape(
        &mut self,
        centre: (f64, f64),
        reach: f64,
        shape: impl Fn(f64, f64) -> f64,
        color: RGBAColor,
    ) -> Result<(), RenderError> {
        let x0 = (centre.0 - reach).floor().max(0.0) as usize;
        let y0 = (centre.1 - reach).floor().max(0.0) as usize;
        let x1 = ((centre.0 + reach).ceil().max(0.0) as usize).min(self.width);
        let y1 = ((centre.1 + reach).ceil().max(0.0) as usize).min(self.height);
        for py in y0..y1 {
            for px in x0..x1 {
                let c = shape(px as f64 + 0.5, py as f64 + 0.5) as f32;
                self.cover(px, py, c);
            }
        }
        self.flush(color)
    }

    /// Raises the coverage of pixel `(px, py)` to at least `c` (remembering touched pixels).
    fn cover(&mut self, px: usize, py: usize, c: f32) {
        if c > 0.0 {
            let index = py * self.width + px;
            if self.coverage[index] == 0.0 {
                self.touched.push(index);
            }
            self.coverage[index] = self.coverage[index].max(c);
        }
    }

    /// Blends the accumulated coverage in `color` and clears it.
    fn flush(&mut self, color: RGBAColor) -> Result<(), RenderError> {
        let touched = std::mem::take(&mut self.touched);
        for &index in &touched {
            let c = f64::from(self.coverage[index]);
            self.coverage[index] = 0.0;
            let point = ((index % self.width) as i32, (index / self.width) as i32);
            self.backend
                .draw_pixel(point, color.mix(c).to_backend_color())
                .map_err(draw_error)?;
        }
        self.touched = touched;
        self.touched.clear();
        Ok(())
    }
}

fn distance_to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let length2 = dx * dx + dy * dy;
    let t = if length2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / length2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

/// Splits a polyline into dashes of length `dash` separated by `gap`.
fn dash_pieces(points: &[(f64, f64)], dash: f64, gap: f64) -> Vec<Vec<(f64, f64)>> {
    let mut pieces = Vec::new();
    if points.len() < 2 || dash <= 0.0 {
        return pieces;
    }
    let period = dash + gap.max(0.0);
    let mut phase = 0.0; // distance travelled within the current period
    let mut current: Vec<(f64, f64)> = vec![points[0]];
    for segment in points.windows(2) {
        let (a, b) = (segment[0], segment[1]);
        let length = (b.0 - a.0).hypot(b.1 - a.1);
        let mut done = 0.0;
        while done < length {
            let drawing = phase < dash;
            let boundary = if drawing { dash } else { period };
            let step = (boundary - phase).min(length - done);
            done += step;
            phase += step;
            let t = done / length;
            let p = (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
            if drawing {
                current.push(p);
            }
            if phase >= boundary - 1e-12 {
                if drawing {
                    if current.len() > 1 {
                        pieces.push(std::mem::take(&mut current));
                    }
                    current.clear();
                } else {
                    phase = 0.0;
                    current = vec![p];
                }
            }
        }
    }
    if current.len() > 1 {
        pieces.push(current);
    }
    pieces
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dashes_alternate_along_the_line() {
        let pieces = dash_pieces(&[(0.0, 0.0), (10.0, 0.0), (10.0, 10.0)], 4.0, 2.0);
        // 20 px long: dashes at 0-4, 6-10, 12-16, 18-20.
        assert_eq!(pieces.len(), 4);
        assert_eq!(pieces[0], vec![(0.0, 0.0), (4.0, 0.0)]);
        assert_eq!(pieces[1], vec![(6.0, 0.0), (10.0, 0.0)]);
        assert_eq!(pieces[2], vec![(10.0, 2.0), (10.0, 6.0)]);
        assert_eq!(pieces[3], vec![(10.0, 8.0), (10.0, 10.0)]);
    }

    #[test]
    fn distance_to_segment_clamps_to_the_ends() {
        assert!((distance_to_segment((5.0, 3.0), (0.0, 0.0), (10.0, 0.0)) - 3.0).abs() < 1e-12);
        assert!((distance_to_segment((13.0, 4.0), (0.0, 0.0), (10.0, 0.0)) - 5.0).abs() < 1e-12);
    }
}

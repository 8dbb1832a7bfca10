//! Figures: filled maps with labelled contours, colour bar, depth-down axes, surface traction
//! profiles and the extreme marked. Renderers draw into memory and return pixels or SVG text;
//! the caller writes files.
//!
//! Everything here is in display units: the caller has already converted coordinates (x/a or
//! mm) and values (multiples of p0, or MPa).

mod colormap;
mod contour;
mod draw;
mod font;
mod layout;
mod paint;
mod plan;
mod svg;
mod ticks;

use ndarray::Array2;
use plotters::prelude::{BitMapBackend, DrawingBackend, SVGBackend};

use crate::field::Axis;
use paint::{draw_error, Painter, Target};
use plan::Plan;

/// One figure: one or more panels side by side sharing a colour scale and a colour bar.
#[derive(Clone, Debug)]
pub struct Figure {
    /// Headline, e.g. "Hertz line contact (plane strain), ν = 0.3".
    pub title: String,
    pub panels: Vec<Panel>,
    /// Colour-bar caption with its unit, e.g. "τ1 / p0" or "σvM (MPa)".
    pub value_label: String,
    /// e.g. "x/a" or "x (mm)".
    pub x_label: String,
    /// Label of the vertical axis, e.g. "z/a" or "z (mm)" (depth, drawn downwards), or "y/a"
    /// for a plane parallel to the surface.
    pub z_label: String,
    /// Whether the vertical axis is the depth, drawn downwards (row 0 at the top); otherwise it
    /// points upwards (row 0 at the bottom), as for an xy section seen from above.
    pub vertical_is_depth: bool,
    /// Caption of the traction profile axis, e.g. "p, q / p0" or "p, q (MPa)".
    pub traction_label: String,
    pub colormap: ColorMap,
    pub levels: Levels,
    pub mark: Mark,
    /// Width in pixels of each panel's plotting area (the height follows from equal aspect).
    pub panel_width_px: u32,
}

/// One map.
#[derive(Clone, Debug)]
pub struct Panel {
    /// Caption above the panel, e.g. "μ = 0.2"; may be empty.
    pub subtitle: String,
    /// Horizontal axis (display units), `values` columns.
    pub x: Axis,
    /// Vertical axis (display units): the depth (`z.min >= 0`) or, for a plane parallel to the
    /// surface, y; `values` rows, row 0 is `z.min`.
    pub z: Axis,
    /// `[z.count, x.count]` values in display units.
    pub values: Array2<f64>,
    /// Surface tractions sampled along the horizontal axis (display units): drawn in a strip
    /// above the map. When no panel has any, the figure has no strips.
    pub traction: Vec<TractionSample>,
    /// Half-length of the contact along the horizontal axis of this section, in display units
    /// (the contact spans `-half_width..half_width`; 0 when the section misses it).
    pub half_width: f64,
    /// Polylines drawn as thin dashed guides over the map (display units), e.g. the contact
    /// outline on a plane parallel to the surface.
    pub outlines: Vec<Vec<(f64, f64)>>,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TractionSample {
    pub x: f64,
    /// Normal pressure, >= 0.
    pub p: f64,
    /// Tangential traction acting on the body in +x.
    pub q: f64,
}

/// Colour maps (all from `colorous`). Sequential maps span `[0, max]` for non-negative
/// quantities; `Diverging` is centred on zero, compression blue and tension red.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorMap {
    Viridis,
    Inferno,
    Magma,
    Plasma,
    Cividis,
    Turbo,
    Diverging,
}

impl ColorMap {
    pub const ALL: [ColorMap; 7] = [
        ColorMap::Viridis,
        ColorMap::Inferno,
        ColorMap::Magma,
        ColorMap::Plasma,
        ColorMap::Cividis,
        ColorMap::Turbo,
        ColorMap::Diverging,
    ];

    pub fn key(self) -> &'static str {
        match self {
            ColorMap::Viridis => "viridis",
            ColorMap::Inferno => "inferno",
            ColorMap::Magma => "magma",
            ColorMap::Plasma => "plasma",
            ColorMap::Cividis => "cividis",
            ColorMap::Turbo => "turbo",
            ColorMap::Diverging => "diverging",
        }
    }

    pub fn from_key(key: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|c| c.key() == key)
    }
}

/// Which contour lines to draw.
#[derive(Clone, Debug, PartialEq)]
pub enum Levels {
    /// About this many "nice" levels (steps of 1, 2 or 5 times a power of ten).
    Count(usize),
    /// Exactly these levels, in display units.
    Values(Vec<f64>),
}

/// Which extreme of the map to mark with a point and a label of its value and location.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mark {
    Max,
    Min,
    Both,
    None,
}

/// Errors of drawing.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    #[error("drawing failed: {0}")]
    Draw(String),
    #[error("figure has no panels")]
    NoPanels,
}

/// Draws `figure` into an RGB image: one row of panels (traction strip above each map, depth
/// downwards, equal aspect), labelled contours, the extremes marked, one colour bar.
///
/// The image size follows from `panel_width_px`, the axis extents and the text; the font is the
/// embedded DejaVu Sans, so the pixels do not depend on the machine.
pub fn render_png(figure: &Figure) -> Result<image::RgbImage, RenderError> {
    let plan = Plan::new(figure)?;
    let (width, height) = (plan.layout.width, plan.layout.height);
    let mut pixels = vec![255u8; width as usize * height as usize * 3];
    {
        let mut backend = BitMapBackend::with_buffer(&mut pixels, (width, height));
        let mut painter = Painter::new(&mut backend, Target::Raster);
        draw::draw(&mut painter, &plan)?;
        backend.present().map_err(draw_error)?;
    }
    image::RgbImage::from_raw(width, height, pixels)
        .ok_or_else(|| RenderError::Draw("pixel buffer does not match the image size".to_string()))
}

/// Draws `figure` as an SVG document, the same drawing as [`render_png`]: lines and text are
/// vector elements, the heat maps and the colour bar embedded PNG images at the PNG's
/// resolution.
pub fn render_svg(figure: &Figure) -> Result<String, RenderError> {
    let plan = Plan::new(figure)?;
    let size = (plan.layout.width, plan.layout.height);
    let mut text = String::new();
    {
        let mut backend = SVGBackend::with_string(&mut text, size);
        let mut painter = Painter::new(&mut backend, Target::Vector);
        draw::draw(&mut painter, &plan)?;
        backend.present().map_err(draw_error)?;
    }
    svg::finish(&text, &plan.images, size)
}

/// Encodes an image as PNG bytes, in memory.
pub fn encode_png(image: &image::RgbImage) -> Result<Vec<u8>, RenderError> {
    use image::ImageEncoder;
    let mut bytes = Vec::new();
    image::codecs::png::PngEncoder::new(&mut bytes)
        .write_image(
            image.as_raw(),
            image.width(),
            image.height(),
            image::ExtendedColorType::Rgb8,
        )
        .map_err(|e| RenderError::Draw(format!("PNG encoding failed: {e}")))?;
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A smooth bump centred at (`x0`, 0.8), the value 1 at its centre.
    fn bump(x0: f64) -> impl Fn(f64, f64) -> f64 {
        move |x, z| (-((x - x0).powi(2) + (z - 0.8).powi(2)) / 0.5).exp()
    }

    fn panel(subtitle: &str, f: impl Fn(f64, f64) -> f64) -> Panel {
        let (x, z) = (Axis::new(-2.0, 2.0, 161), Axis::new(0.0, 1.6, 65));
        let values =
            Array2::from_shape_fn((z.count, x.count), |(iz, ix)| f(x.value(ix), z.value(iz)));
        let traction = (0..=200)
            .map(|i| {
                let x = -2.0 + 4.0 * i as f64 / 200.0;
                let p = (1.0 - x * x).max(0.0).sqrt();
                TractionSample { x, p, q: 0.2 * p }
            })
            .collect();
        Panel {
            subtitle: subtitle.to_string(),
            x,
            z,
            values,
            traction,
            half_width: 1.0,
            outlines: Vec::new(),
        }
    }

    fn figure(levels: Levels, mark: Mark) -> Figure {
        Figure {
            title: "Test bumps τ1".to_string(),
            panels: vec![
                panel("left, μ = 0", bump(-0.5)),
                panel("right", |x, z| 0.5 * bump(0.5)(x, z)),
            ],
            value_label: "τ1 / p0".to_string(),
            x_label: "x/a".to_string(),
            z_label: "z/a".to_string(),
            vertical_is_depth: true,
            traction_label: "p, q / p0".to_string(),
            colormap: ColorMap::Viridis,
            levels,
            mark,
            panel_width_px: 300,
        }
    }

    fn expected_colour(map: ColorMap, t: f64) -> [u8; 3] {
        colormap::eval(map, t)
    }

    fn close(a: [u8; 3], b: [u8; 3], tolerance: u8) -> bool {
        a.iter().zip(b).all(|(x, y)| x.abs_diff(y) <= tolerance)
    }

    #[test]
    fn png_has_the_layout_size_and_equal_aspect_maps() {
        let figure = figure(Levels::Count(6), Mark::Max);
        let image = render_png(&figure).expect("render");
        let plan = Plan::new(&figure).expect("plan");
        let layout = &plan.layout;
        assert_eq!(image.dimensions(), (layout.width, layout.height));
        for panel in &layout.panels {
            assert_eq!(panel.map.w, 300);
            // 4 wide, 1.6 deep: 120 px.
            assert_eq!(panel.map.h, 120);
        }
        // Side by side, same row, strip directly above its map.
        let (a, b) = (&layout.panels[0], &layout.panels[1]);
        assert_eq!(a.map.y, b.map.y);
        assert!(a.map.right() < b.map.x);
        assert!(a.strip.bottom() < a.map.y && a.strip.x == a.map.x && a.strip.w == a.map.w);
        assert!(b.map.right() < layout.colorbar.x);
        assert!(layout.title_baseline < layout.subtitle_baseline);
        assert!(layout.subtitle_baseline < f64::from(a.strip.y));
    }

    #[test]
    fn margins_stay_white() {
        let image = render_png(&figure(Levels::Count(6), Mark::Both)).expect("render");
        let (w, h) = image.dimensions();
        let white = |x: u32, y: u32| image.get_pixel(x, y).0 == [255, 255, 255];
        for x in 0..w {
            assert!(
                white(x, 0) && white(x, h - 1),
                "ink at the top or bottom edge, x = {x}"
            );
        }
        for y in 0..h {
            assert!(
                white(0, y) && white(w - 1, y),
                "ink at the left or right edge, y = {y}"
            );
        }
    }

    #[test]
    fn map_pixels_have_the_colour_of_their_value() {
        // No contours and no marks: the map shows the colour scale alone.
        let figure = figure(Levels::Values(Vec::new()), Mark::None);
        let image = render_png(&figure).expect("render");
        let plan = Plan::new(&figure).expect("plan");
        // The scale spans [0, 1]: the left bump peaks at 1.
        for (panel, layout) in figure.panels.iter().zip(&plan.layout.panels) {
            for (fx, fz) in [(0.5, 0.5), (0.3, 0.7), (0.8, 0.2), (0.1, 0.9)] {
                let px = layout.map.x + (fx * f64::from(layout.map.w)) as i32;
                let pz = layout.map.y + (fz * f64::from(layout.map.h)) as i32;
                let x = layout.data_x(f64::from(px) + 0.5);
                let z = layout.data_z(f64::from(pz) + 0.5);
                let value = (panel.values[[0, 0]] * 0.0) + {
                    // The analytic field (the grid is fine enough for bilinear to agree).
                    let left = bump(-0.5)(x, z);
                    if std::ptr::eq(panel, &figure.panels[0]) {
                        left
                    } else {
                        0.5 * bump(0.5)(x, z)
                    }
                };
                let expected = expected_colour(ColorMap::Viridis, value);
                let got = image.get_pixel(px as u32, pz as u32).0;
                assert!(
                    close(got, expected, 6),
                    "({x:.2}, {z:.2}) = {value:.3}: {got:?} vs {expected:?}"
                );
            }
        }
    }

    #[test]
    fn contour_lines_darken_the_map_on_their_level() {
        let figure = Figure {
            panels: vec![panel("", bump(0.0))],
            ..figure(Levels::Values(vec![0.5]), Mark::None)
        };
        let image = render_png(&figure).expect("render");
        let plan = Plan::new(&figure).expect("plan");
        let layout = &plan.layout.panels[0];
        // exp(-r^2 / 0.5) = 0.5 on the circle r = sqrt(0.5 ln 2) around (0, 0.8).
        let r = (0.5 * 2f64.ln()).sqrt();
        let mut dark = 0;
        for k in 0..16 {
            let angle = std::f64::consts::TAU * k as f64 / 16.0;
            let (x, z) = (r * angle.cos(), 0.8 + r * angle.sin());
            let (px, pz) = (layout.px(x).floor() as u32, layout.pz(z).floor() as u32);
            let plain = expected_colour(ColorMap::Viridis, 0.5);
            let got = image.get_pixel(px, pz).0;
            if got
                .iter()
                .zip(plain)
                .all(|(g, p)| u16::from(*g) + 30 < u16::from(p) || p < 40)
            {
                dark += 1;
            }
        }
        // A label may cover a stretch of the line.
        assert!(
            dark >= 12,
            "only {dark} of 16 points on the isoline are dark"
        );
    }

    #[test]
    fn diverging_maps_show_compression_blue_and_zero_white() {
        let figure = Figure {
            panels: vec![panel("", |x, _| -x)],
            colormap: ColorMap::Diverging,
            ..figure(Levels::Values(Vec::new()), Mark::None)
        };
        let image = render_png(&figure).expect("render");
        let plan = Plan::new(&figure).expect("plan");
        let map = plan.layout.panels[0].map;
        let row = (map.y + map.h / 2) as u32;
        // x = 1.5: value -1.5 (compression) is blue; x = 0 white.
        let [r, g, b] = image.get_pixel((map.x + map.w * 7 / 8) as u32, row).0;
        assert!(b > 100 && b > r + 40 && b > g, "{:?}", [r, g, b]);
        let centre = image.get_pixel((map.x + map.w / 2) as u32, row).0;
        assert!(centre.iter().all(|c| *c > 235), "{centre:?}");
    }

    #[test]
    fn svg_shows_the_same_figure() {
        let figure = figure(Levels::Count(6), Mark::Max);
        let svg = render_svg(&figure).expect("svg");
        let image = render_png(&figure).expect("png");
        assert!(svg.starts_with("<svg"));
        assert!(svg.contains(&format!(
            "width=\"{}\" height=\"{}\"",
            image.width(),
            image.height()
        )));
        for text in [
            "Test bumps τ1",
            "left, μ = 0",
            "x/a",
            "z/a",
            "τ1 / p0",
            "p, q / p0",
            "max 1.00 at",
        ] {
            assert!(svg.contains(text), "no `{text}` in the SVG");
        }
        // Two heat maps and the colour bar, embedded once each.
        assert_eq!(svg.matches("<image").count(), 3);
        assert!(svg.len() < 2_000_000, "{} bytes", svg.len());
    }

    #[test]
    fn rendering_is_deterministic_and_png_round_trips() {
        let figure = figure(Levels::Count(8), Mark::Both);
        let a = render_png(&figure).expect("render");
        let b = render_png(&figure).expect("render");
        assert!(a == b);
        let bytes = encode_png(&a).expect("encode");
        assert!(bytes.starts_with(b"\x89PNG"));
        let decoded = image::load_from_memory(&bytes).expect("decode").to_rgb8();
        assert!(decoded == a);
    }

    #[test]
    fn bad_figures_are_errors() {
        let empty = Figure {
            panels: Vec::new(),
            ..figure(Levels::Count(5), Mark::Max)
        };
        assert!(matches!(render_png(&empty), Err(RenderError::NoPanels)));
        let mut wrong = figure(Levels::Count(5), Mark::Max);
        wrong.panels[1].values = Array2::zeros((3, 3));
        match render_svg(&wrong) {
            Err(RenderError::Draw(message)) => assert!(message.contains("panel 2"), "{message}"),
            other => panic!("expected an error, got {:?}", other.map(|s| s.len())),
        }
    }

    #[test]
    fn non_finite_values_do_not_break_the_figure() {
        let mut figure = figure(Levels::Count(5), Mark::Max);
        figure.panels[0].values[[10, 10]] = f64::NAN;
        figure.panels[1].values.fill(f64::NAN);
        let image = render_png(&figure).expect("render");
        assert!(image.width() > 0);
    }
}

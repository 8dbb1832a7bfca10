//! Figures: filled maps with labelled contours, colour bars, depth-down axes, surface traction
//! profiles and the extreme marked. Renderers draw into memory and return pixels or SVG text;
//! the caller writes files.
//!
//! Everything here is in display units: the caller has already converted coordinates (x/a or
//! mm) and values (multiples of p0, or MPa).
//!
//! Uses: [`crate::field`] (axes) only.

pub mod chart;
pub(crate) mod colormap;
mod contour;
mod draw;
mod font;
mod layout;
mod paint;
mod plan;
mod scales;
pub use scales::{name_and_unit, robust_top, ROBUST_QUANTILE};
mod svg;
pub mod table;
mod ticks;

use ndarray::Array2;
use plotters::prelude::{BitMapBackend, DrawingBackend, SVGBackend};

use crate::field::Axis;
use paint::{draw_error, Painter, Target};
use plan::Plan;

/// One figure: one or more panels side by side. By default they share one colour scale and one
/// colour bar at the right; a panel with its own [`PanelScale`] gets its own (see
/// [`Panel::scale`]).
#[derive(Clone, Debug)]
pub struct Figure {
    /// Headline, e.g. "Hertz line contact (plane strain), ν = 0.3".
    pub title: String,
    pub panels: Vec<Panel>,
    /// Colour-bar caption with its unit, e.g. "τ1 / p0" or "σvM (MPa)", of the shared scale
    /// (panels whose `scale` is `None`).
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
    /// Colour map of the shared scale.
    pub colormap: ColorMap,
    /// Contour levels of the shared scale.
    pub levels: Levels,
    /// Extremes marked in every panel, each panel its own.
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
    /// The colour scale of this panel: `None` for the figure's shared one
    /// (`Figure::value_label`, `colormap`, `levels`).
    ///
    /// Consecutive panels with the same scale (compared after resolving `None`) form a group:
    /// one colour range spanning the group's values, one set of contour levels, and one colour
    /// bar right after the group's last panel, e.g. `[A][B] |bar 1|  [A − B] |bar 2|` for a
    /// closed form and a numerical result on one scale and their difference on its own. Panels
    /// with the same scale that are not neighbours form separate groups, each with its own
    /// range and bar.
    pub scale: Option<PanelScale>,
    /// The panel's largest value found off the grid, where the field could be evaluated
    /// anywhere in the plane (display units): marked instead of the largest sample, so that a
    /// section through the `hertz` report's maximum marks the report's value and position.
    pub peak: Option<Peak>,
}

/// A maximum located between the samples of a panel (display units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peak {
    pub value: f64,
    pub x: f64,
    pub z: f64,
}

/// A colour scale of its own for a panel (see [`Panel::scale`]), e.g. for a difference between
/// two panels, much smaller than either and signed: `ColorMap::Diverging` centres it on zero.
#[derive(Clone, Debug, PartialEq)]
pub struct PanelScale {
    /// Colour-bar caption with its unit, e.g. "Δτ1 / p0".
    pub value_label: String,
    pub colormap: ColorMap,
    pub levels: Levels,
    /// The colour range `(min, max)`; values beyond take the end colours (say so in the
    /// subtitle). `None`: the range of the group's values.
    pub range: Option<(f64, f64)>,
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
/// downwards, equal aspect), labelled contours, the extremes marked, and one colour bar after
/// each group of panels sharing a scale (one for the whole figure unless panels have their
/// own [`PanelScale`]).
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
/// vector elements, the heat maps and the colour bars embedded PNG images at the PNG's
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

/// Isolines of `values` (`[rows, columns]` over the axes `x` (columns) and `z` (rows)) at
/// `level`, as polylines in the axes' coordinates (closed ones end where they start).
pub fn contour_lines(
    values: ndarray::ArrayView2<'_, f64>,
    x: &Axis,
    z: &Axis,
    level: f64,
) -> Vec<Vec<(f64, f64)>> {
    contour::isolines_on(values, x, z, level)
        .into_iter()
        .map(|line| {
            let mut points: Vec<(f64, f64)> = line.points.iter().map(|p| (p[0], p[1])).collect();
            if line.closed {
                if let Some(&first) = points.first() {
                    points.push(first);
                }
            }
            points
        })
        .collect()
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
            scale: None,
            peak: None,
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
        assert!(b.map.right() < layout.colorbars[0].rect.x);
        assert!(layout.title_baseline < layout.subtitle_baseline);
        assert!(layout.subtitle_baseline < f64::from(a.strip.y));
    }

    #[test]
    fn margins_stay_white() {
        assert_margins_white(&render_png(&figure(Levels::Count(6), Mark::Both)).expect("render"));
        assert_margins_white(&render_png(&compared(Mark::Both)).expect("render"));
    }

    fn assert_margins_white(image: &image::RgbImage) {
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
            "max 1.00 p0 at x = \u{2212}0.50a, z = 0.80a",
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

    /// The difference of [`compared`]: small and signed, 0 at x = 0.
    fn difference(x: f64, z: f64) -> f64 {
        0.01 * x * (1.0 + 0.2 * z)
    }

    /// The scale of the difference panel of [`compared`].
    fn difference_scale() -> PanelScale {
        PanelScale {
            value_label: "Δτ1 / p0".to_string(),
            colormap: ColorMap::Diverging,
            levels: Levels::Count(4),
            range: None,
        }
    }

    /// "closed form" and "numerical" on the shared scale, then "their difference" on its own.
    fn compared(mark: Mark) -> Figure {
        let exact = bump(-0.5);
        let numerical = move |x, z| exact(x, z) + difference(x, z);
        Figure {
            panels: vec![
                panel("closed form", bump(-0.5)),
                panel("numerical", numerical),
                Panel {
                    scale: Some(difference_scale()),
                    peak: None,
                    ..panel("numerical − closed form", difference)
                },
            ],
            ..figure(Levels::Count(6), mark)
        }
    }

    /// Whether the columns `x0..x1` are white over the rows `y0..y1`.
    fn white_columns(image: &image::RgbImage, x0: i32, x1: i32, y0: i32, y1: i32) -> bool {
        (x0..x1).all(|x| (y0..y1).all(|y| image.get_pixel(x as u32, y as u32).0 == [255; 3]))
    }

    #[test]
    fn a_clipped_colour_range_ends_its_bar_in_triangles_of_the_end_colours() {
        // The difference spans ±0.024 (0.01 x (1 + 0.2 z) at x = ±2, z = 1.6); colours to ±0.01.
        let mut figure = compared(Mark::None);
        figure.panels[2].scale = Some(PanelScale {
            range: Some((-0.01, 0.01)),
            ..difference_scale()
        });
        let plan = Plan::new(&figure).expect("plan");
        assert_eq!(plan.groups[0].beyond, [false, false]);
        assert_eq!(plan.groups[1].beyond, [true, true]);
        let image = render_png(&figure).expect("render");
        let bar = plan.layout.colorbars[1].rect;
        let centre = (bar.x + bar.w / 2) as u32;
        let (top, bottom) = (
            plan.groups[1].scale.rgb(0.01),
            plan.groups[1].scale.rgb(-0.01),
        );
        // Just outside the bar's ends, in the middle of the triangles.
        let above = image.get_pixel(centre, (bar.y - bar.w / 3) as u32).0;
        let below = image.get_pixel(centre, (bar.bottom() + bar.w / 3) as u32).0;
        assert_eq!((above, below), (top, bottom));
        // Unclipped: nothing drawn there.
        let unclipped = compared(Mark::None);
        let image = render_png(&unclipped).expect("render");
        let plan = Plan::new(&unclipped).expect("plan");
        let bar = plan.layout.colorbars[1].rect;
        let above = image
            .get_pixel((bar.x + bar.w / 2) as u32, (bar.y - bar.w / 3) as u32)
            .0;
        assert_eq!(above, [255; 3]);
    }

    #[test]
    fn a_panel_with_its_own_scale_gets_its_own_group_and_colour_bar() {
        let figure = compared(Mark::Max);
        let plan = Plan::new(&figure).expect("plan");
        let ranges: Vec<_> = plan.groups.iter().map(|g| g.panels.clone()).collect();
        assert_eq!(ranges, vec![0..2, 2..3]);
        assert_eq!(plan.layout.colorbars.len(), 2);
        assert_eq!(plan.groups[0].value_label, "τ1 / p0");
        assert_eq!(plan.groups[1].value_label, "Δτ1 / p0");

        // Each group's scale spans its own values: the shared one both bumps (the numerical
        // one dips a little below 0 at the left), the difference one ±max |difference|.
        let shared = &plan.groups[0].scale;
        let over = |panels: &[Panel], f: fn(f64, f64) -> f64, start: f64| {
            panels
                .iter()
                .flat_map(|p| p.values.iter())
                .fold(start, |m, v| f(m, *v))
        };
        let shared_panels = &figure.panels[..2];
        assert_eq!(shared.lo, over(shared_panels, f64::min, f64::MAX));
        assert_eq!(shared.hi, over(shared_panels, f64::max, f64::MIN));
        assert!(shared.lo < 0.0 && shared.hi >= 1.0, "{shared:?}");
        let own = &plan.groups[1].scale;
        let largest = difference(2.0, 1.6);
        assert!((own.hi - largest).abs() < 1e-12, "{} vs {largest}", own.hi);
        assert_eq!(own.lo, -own.hi);

        // Contour levels per group, within the group's range.
        let levels = &plan.groups[0].levels;
        assert!(levels.len() >= 4 && levels.iter().all(|l| *l > shared.lo && *l < shared.hi));
        assert!(levels.iter().any(|l| *l > 0.5), "{levels:?}");
        let small = &plan.groups[1].levels;
        assert!(
            small.len() >= 2 && small.iter().all(|l| l.abs() < largest),
            "{small:?}"
        );

        // The difference bar is labelled in its own, small numbers.
        let ticks = &plan.layout.colorbars[1].ticks;
        assert!(ticks.values.contains(&0.0), "{ticks:?}");
        assert!(
            ticks.values.iter().all(|v| v.abs() <= own.hi + 1e-12),
            "{ticks:?}"
        );
    }

    #[test]
    fn each_colour_bar_follows_its_group_and_clears_the_next_panel() {
        let figure = compared(Mark::Both);
        let image = render_png(&figure).expect("render");
        let plan = Plan::new(&figure).expect("plan");
        let layout = &plan.layout;
        assert_eq!(image.dimensions(), (layout.width, layout.height));
        let [a, b, c] = [0, 1, 2].map(|i| &layout.panels[i]);
        let [first, second] = [0, 1].map(|i| &layout.colorbars[i]);

        // Equal aspect, one row, the bars beside the maps of their group.
        for panel in [a, b, c] {
            assert_eq!((panel.map.w, panel.map.h), (300, 120));
            assert_eq!(panel.map.y, a.map.y);
        }
        for bar in [first, second] {
            assert_eq!((bar.rect.y, bar.rect.h), (a.map.y, a.map.h));
        }
        assert!(a.map.right() < b.map.x);
        assert!(b.map.right() < first.rect.x);
        assert!(first.right(layout.label_line) < f64::from(c.map.x));
        assert!(c.map.right() < second.rect.x);
        // A gap between panels of one group is narrower than the one after a bar.
        let within = b.map.x - a.map.right();
        let across = c.map.x - b.map.right();
        assert!(across > within + first.rect.w, "{within} vs {across}");

        // Between the first bar's caption and the next panel's axis numbers (strip and map),
        // nothing: white columns, at least a tick size of them; so no rotated axis label
        // either (only the first panel has one).
        let s = layout.sizes.tick;
        let (top, bottom) = (c.strip.y - 10, c.map.bottom() + 10);
        let numbers = c
            .z_ticks
            .labels
            .iter()
            .chain(&c.strip_ticks.labels)
            .map(|l| font::text_width(l, s).expect("width"))
            .fold(0.0, f64::max);
        let numbers_left = f64::from(c.map.x) - layout.tick_length - layout.tick_gap - numbers;
        let caption_right = first.right(layout.label_line);
        assert!(
            numbers_left - caption_right >= s,
            "{caption_right} .. {numbers_left}"
        );
        let band = (caption_right.ceil() as i32, numbers_left.floor() as i32 - 1);
        assert!(
            white_columns(&image, band.0, band.1, top, bottom),
            "{band:?}"
        );
        // The caption and the numbers are there, just outside the band.
        let ink_left = !white_columns(&image, first.rect.right(), band.0, top, bottom);
        let ink_right = !white_columns(&image, band.1, c.map.x - 1, top, bottom);
        assert!(ink_left && ink_right);

        // The bars show their maps: the shared one viridis (yellow on top), the other
        // diverging (red on top, white in the middle, blue at the bottom).
        let top_of = |bar: &layout::ColorbarLayout, j: i32| {
            image
                .get_pixel(
                    (bar.rect.x + bar.rect.w / 2) as u32,
                    (bar.rect.y + j) as u32,
                )
                .0
        };
        let yellow = top_of(first, 2);
        let t = 1.0 - 2.5 / f64::from(first.rect.h);
        assert!(
            close(yellow, colormap::eval(ColorMap::Viridis, t), 3),
            "{yellow:?}"
        );
        let [r, g, bl] = top_of(second, 2);
        assert!(r > 80 && r > g + 40 && r > bl + 40, "{:?}", [r, g, bl]);
        // (Just above the middle: the level 0 is marked across it.)
        let middle = top_of(second, second.rect.h / 2 - 3);
        assert!(middle.iter().all(|v| *v > 225), "{middle:?}");
    }

    #[test]
    fn the_difference_map_has_the_colour_of_its_own_scale() {
        let figure = Figure {
            levels: Levels::Values(Vec::new()),
            panels: compared(Mark::None)
                .panels
                .into_iter()
                .map(|p| Panel {
                    scale: p.scale.map(|s| PanelScale {
                        levels: Levels::Values(Vec::new()),
                        ..s
                    }),
                    ..p
                })
                .collect(),
            ..compared(Mark::None)
        };
        let image = render_png(&figure).expect("render");
        let plan = Plan::new(&figure).expect("plan");
        let layout = &plan.layout.panels[2];
        let largest = difference(2.0, 1.6);
        for (fx, fz) in [(0.1, 0.5), (0.3, 0.2), (0.7, 0.8), (0.95, 0.5)] {
            let px = layout.map.x + (fx * f64::from(layout.map.w)) as i32;
            let pz = layout.map.y + (fz * f64::from(layout.map.h)) as i32;
            let x = layout.data_x(f64::from(px) + 0.5);
            let z = layout.data_z(f64::from(pz) + 0.5);
            let t = 0.5 + 0.5 * difference(x, z) / largest;
            let expected = expected_colour(ColorMap::Diverging, t);
            let got = image.get_pixel(px as u32, pz as u32).0;
            assert!(
                close(got, expected, 6),
                "({x:.2}, {z:.2}): {got:?} vs {expected:?}"
            );
        }
    }

    #[test]
    fn panels_group_by_their_resolved_scale() {
        let base = compared(Mark::Max);
        let groups = |panels: Vec<Panel>| -> Vec<std::ops::Range<usize>> {
            let figure = Figure {
                panels,
                ..base.clone()
            };
            let plan = Plan::new(&figure).expect("plan");
            assert_eq!(plan.layout.colorbars.len(), plan.groups.len());
            plan.groups.iter().map(|g| g.panels.clone()).collect()
        };
        let [a, b, d] = [0, 1, 2].map(|i| base.panels[i].clone());
        // All shared: one group, as before panels had scales.
        assert_eq!(groups(vec![a.clone(), b.clone()]), vec![0..2]);
        // A panel's own scale equal to the shared one is the shared one.
        let same = Panel {
            scale: Some(PanelScale {
                value_label: base.value_label.clone(),
                colormap: base.colormap,
                levels: base.levels.clone(),
                range: None,
            }),
            ..b.clone()
        };
        assert_eq!(groups(vec![a.clone(), same]), vec![0..2]);
        // Only neighbours group: the shared scale on both sides of a difference is two groups.
        assert_eq!(
            groups(vec![a.clone(), d.clone(), b.clone()]),
            vec![0..1, 1..2, 2..3]
        );
        assert_eq!(groups(vec![d.clone(), d, a, b]), vec![0..2, 2..4]);
    }

    #[test]
    fn svg_shows_every_colour_bar() {
        let figure = compared(Mark::Max);
        let svg = render_svg(&figure).expect("svg");
        let image = render_png(&figure).expect("png");
        assert!(svg.contains(&format!(
            "width=\"{}\" height=\"{}\"",
            image.width(),
            image.height()
        )));
        for text in [
            "τ1 / p0",
            "Δτ1 / p0",
            "numerical − closed form",
            "closed form",
        ] {
            assert!(svg.contains(text), "no `{text}` in the SVG");
        }
        // Three heat maps and two colour bars.
        assert_eq!(svg.matches("<image").count(), 5);
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

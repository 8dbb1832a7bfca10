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
    /// e.g. "x/a" or "x (mm)" (of the panels without axes of their own, [`Panel::axes`]).
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
    /// The axes of a panel cut in another plane than the figure's (a yz section beside an xz
    /// one, a plane parallel to the surface beside a depth section): `None` for the figure's
    /// (`Figure::x_label`, `z_label`, `vertical_is_depth`). The panel keeps the colour scale
    /// it shares; its vertical caption is drawn left of it when it differs from its left
    /// neighbour's.
    pub axes: Option<PanelAxes>,
}

/// A maximum located between the samples of a panel (display units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peak {
    pub value: f64,
    pub x: f64,
    pub z: f64,
}

/// The axes of a panel (see [`Panel::axes`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PanelAxes {
    /// e.g. "y/a" or "y (mm)".
    pub x_label: String,
    /// e.g. "z/a" (a depth, drawn downwards) or "y/a".
    pub z_label: String,
    pub vertical_is_depth: bool,
}

/// The axes a panel is drawn with: its own or the figure's (see [`Figure::axes_of`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AxesOf<'a> {
    pub x_label: &'a str,
    pub z_label: &'a str,
    pub vertical_is_depth: bool,
}

impl Figure {
    /// The axes of `panel` (one of this figure's): its own ([`Panel::axes`]) or the figure's.
    pub fn axes_of<'a>(&'a self, panel: &'a Panel) -> AxesOf<'a> {
        match &panel.axes {
            Some(own) => AxesOf {
                x_label: &own.x_label,
                z_label: &own.z_label,
                vertical_is_depth: own.vertical_is_depth,
            },
            None => AxesOf {
                x_label: &self.x_label,
                z_label: &self.z_label,
                vertical_is_depth: self.vertical_is_depth,
            },
        }
    }
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
mod tests;

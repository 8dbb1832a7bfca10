//! Figures: filled maps with labelled contours, colour bar, depth-down axes, surface traction
//! profiles and the extreme marked. Renderers draw into memory and return pixels or SVG text;
//! the caller writes files.
//!
//! Everything here is in display units: the caller has already converted coordinates (x/a or
//! mm) and values (multiples of p0, or MPa).

use ndarray::Array2;

use crate::field::Axis;

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
    /// e.g. "z/a" or "z (mm)"; depth is drawn downwards.
    pub z_label: String,
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
    /// Depth axis (display units, `z.min >= 0`), `values` rows; row 0 is `z.min`.
    pub z: Axis,
    /// `[z.count, x.count]` values in display units.
    pub values: Array2<f64>,
    /// Surface tractions sampled along x (display units): drawn above the surface.
    pub traction: Vec<TractionSample>,
    /// Contact half-width in display units (the contact spans `-a..a`).
    pub half_width: f64,
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

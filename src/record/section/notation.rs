//! Texts of the map views: numbers, positions and stresses in the scene's units, and the
//! notation (names and units) of a map's values and axes; the traction colours.

use super::*;

/// Height of a label in pixels, and the width of one of its characters (the viewer's font).
pub(super) const LABEL_PX: f64 = 21.0;
pub(super) const CHAR_PX: f64 = 6.3;

/// The p profile: a light blue that reads on the dark background and beside every map.
pub const P_COLOUR: [u8; 3] = [86, 180, 233];
/// The q profile: orange.
pub const Q_COLOUR: [u8; 3] = [230, 159, 0];

pub(super) fn colour([r, g, b]: [u8; 3]) -> rerun::Color {
    rerun::Color::from_rgb(r, g, b)
}

/// A number with three significant digits, or in exponent form when very small or large;
/// a typographic minus.
pub fn short(value: f64) -> String {
    crate::io::text::significant(value, 3, 1e5, false)
}

/// A stress with its unit: `0.557 p0`, `612 MPa`.
pub fn stress_text(scene: &Scene, value: f64) -> String {
    use crate::scene::StressUnit;
    let unit = match scene.figure.stress_unit {
        StressUnit::PeakPressure => " p0",
        StressUnit::Pascal => " Pa",
        StressUnit::MegaPascal => " MPa",
        StressUnit::GigaPascal => " GPa",
    };
    format!("{}{unit}", short(value))
}

/// Rounding noise of a grid through zero reads as zero.
pub(super) fn snap(c: f64) -> f64 {
    if c.abs() < 1e-9 {
        0.0
    } else {
        c
    }
}

/// A point of the volume with its unit: `(x = 0a, y = 0a, z = 0.48a)`.
pub fn position_text_3d(scene: &Scene, [x, y, z]: [f32; 3]) -> String {
    let snap = |c: f32| if c.abs() < 1e-6 { 0.0 } else { c };
    let (x, y, z) = (snap(x), snap(y), snap(z));
    let suffix = scene.figure.length_unit.suffix();
    format!(
        "(x = {}{suffix}, y = {}{suffix}, z = {}{suffix})",
        short(f64::from(x)),
        short(f64::from(y)),
        short(f64::from(z))
    )
}

pub(super) use crate::render::name_and_unit;

/// How a map's values and positions are written in its labels, from the figure's captions.
#[derive(Clone, Debug, PartialEq)]
pub struct Notation {
    /// The quantity's name, e.g. `σvM`, `p`.
    pub symbol: String,
    /// Its unit as written after a number, e.g. ` p0`, ` MPa`.
    pub unit: String,
    /// The horizontal and vertical coordinates' names and their unit (`x`, `z`, `a`).
    pub axes: (String, String),
    pub length: String,
    /// The map is drawn with its vertical coordinate negated (see [`displayed`]).
    pub flipped: bool,
    /// A coordinate smaller than this (a millionth of the map's extent) is written as zero:
    /// a refined maximum on a symmetry plane lands there within rounding (`y = 5.59e-9 mm` on
    /// a 1 mm map), not off it.
    pub zero_below: f64,
}

impl Notation {
    /// The notation of a panel of `figure` (its own colour scale's caption if it has one).
    pub fn of(figure: &Figure, panel: &Panel) -> Self {
        let caption = panel
            .scale
            .as_ref()
            .map_or(figure.value_label.as_str(), |s| s.value_label.as_str());
        let (symbol, unit) = name_and_unit(caption);
        let axes = figure.axes_of(panel);
        let (horizontal, length) = name_and_unit(axes.x_label);
        let (vertical, _) = name_and_unit(axes.z_label);
        Self {
            symbol,
            unit,
            axes: (horizontal, vertical),
            length,
            flipped: !axes.vertical_is_depth,
            zero_below: 1e-6
                * [panel.x.min, panel.x.max, panel.z.min, panel.z.max]
                    .iter()
                    .fold(0.0f64, |m, c| m.max(c.abs())),
        }
    }

    /// A value with its unit: `0.557 p0`.
    pub fn value(&self, value: f64) -> String {
        format!("{}{}", short(value), self.unit)
    }

    /// A displayed position with its unit: `x = −0.45a, z = 0.16a`.
    pub fn position(&self, u: f64, v: f64) -> String {
        let v = if self.flipped { -v } else { v };
        let snap = |c: f64| {
            if c.abs() < self.zero_below {
                0.0
            } else {
                snap(c)
            }
        };
        format!(
            "{} = {}{length}, {} = {}{length}",
            self.axes.0,
            short(snap(u)),
            self.axes.1,
            short(snap(v)),
            length = self.length
        )
    }
}

//! The units a figure is drawn in: lengths (semi-widths or metric) and stresses.

/// Unit of lengths on a figure (and of `figure.x`, `figure.y`, `figure.z` and `figure.at`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LengthUnit {
    HalfWidth,
    Metre,
    Millimetre,
    Micrometre,
}

impl LengthUnit {
    pub(crate) fn from_key(key: &str) -> Option<Self> {
        match key {
            "a" => Some(Self::HalfWidth),
            "m" => Some(Self::Metre),
            "mm" => Some(Self::Millimetre),
            "um" | "µm" => Some(Self::Micrometre),
            _ => None,
        }
    }

    /// Size of one unit in m, given the half-width.
    pub fn metres(self, half_width_m: f64) -> f64 {
        match self {
            Self::HalfWidth => half_width_m,
            Self::Metre => 1.0,
            Self::Millimetre => 1e-3,
            Self::Micrometre => 1e-6,
        }
    }

    /// The unit after a number: `a`, ` m`, ` mm`, ` µm`.
    pub fn suffix(self) -> &'static str {
        match self {
            Self::HalfWidth => "a",
            Self::Metre => " m",
            Self::Millimetre => " mm",
            Self::Micrometre => " µm",
        }
    }

    /// Axis label for a coordinate, e.g. `x/a` or `x (mm)`.
    pub fn axis_label(self, coordinate: &str) -> String {
        match self {
            Self::HalfWidth => format!("{coordinate}/a"),
            Self::Metre => format!("{coordinate} (m)"),
            Self::Millimetre => format!("{coordinate} (mm)"),
            Self::Micrometre => format!("{coordinate} (µm)"),
        }
    }
}

/// Unit of stresses on a figure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StressUnit {
    PeakPressure,
    Pascal,
    MegaPascal,
    GigaPascal,
}

impl StressUnit {
    pub(crate) fn from_key(key: &str) -> Option<Self> {
        match key {
            "p0" => Some(Self::PeakPressure),
            "Pa" => Some(Self::Pascal),
            "MPa" => Some(Self::MegaPascal),
            "GPa" => Some(Self::GigaPascal),
            _ => None,
        }
    }

    /// Size of one unit in Pa, given the peak pressure.
    pub fn pascals(self, p0_pa: f64) -> f64 {
        match self {
            Self::PeakPressure => p0_pa,
            Self::Pascal => 1.0,
            Self::MegaPascal => 1e6,
            Self::GigaPascal => 1e9,
        }
    }

    /// The unit as written in a scene: `p0`, `Pa`, `MPa` or `GPa`.
    pub fn symbol(self) -> &'static str {
        match self {
            Self::PeakPressure => "p0",
            Self::Pascal => "Pa",
            Self::MegaPascal => "MPa",
            Self::GigaPascal => "GPa",
        }
    }

    /// Label of a value with this unit, e.g. `τ1 / p0` or `τ1 (MPa)`.
    pub fn label(self, symbol: &str) -> String {
        match self {
            Self::PeakPressure => format!("{symbol} / p0"),
            Self::Pascal => format!("{symbol} (Pa)"),
            Self::MegaPascal => format!("{symbol} (MPa)"),
            Self::GigaPascal => format!("{symbol} (GPa)"),
        }
    }
}

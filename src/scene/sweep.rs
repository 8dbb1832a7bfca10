//! Recording scenes: a `[sweep]` of friction, load, the load's position or the sliding speed
//! as a Péclet number (one step per time point of a recording), and a `[volume]` recorded as
//! 3-D iso-surfaces.

use super::{ContactKind, Scene, ThermalSpec};
use crate::contact::{ContactError, LineContact, PointContact};
use crate::stress::Quantity;

/// Most steps a sweep may have (each step evaluates every panel).
pub const MAX_STEPS: usize = 400;

/// What a sweep varies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SweepParameter {
    /// The coefficient of friction of every panel.
    Friction,
    /// The normal load (N/m for a line contact, N for a point contact), at fixed geometry.
    Load,
    /// The x position of the contact's centre on the body's surface: the field in a fixed body
    /// frame as the load passes.
    Position,
    /// The sliding speed, given as body 1's Péclet number `Pe = V1 a / (2κ1)` (scenes with
    /// `[thermal]`): every speed of the scene scaled by the same factor, so the frictional
    /// flux `q = μ p V` grows with it. Values from `from`/`to`/`steps` are spaced
    /// geometrically (Pe 0.1 to 100 is three decades).
    Peclet,
    /// The thickness of body 1's coating (m; coated scenes), at fixed load: the maximum
    /// travelling between the substrate, the interface and the layer. Values from
    /// `from`/`to`/`steps` (in the figure's length unit) are spaced geometrically.
    CoatingThickness,
    /// The lubricant's entrainment speed (m/s; lubricated line contacts): the numerical EHL
    /// solution at each speed, its pressure spike and the stress under it. Values from
    /// `from`/`to`/`steps` are spaced geometrically.
    EntrainmentSpeed,
}

impl SweepParameter {
    pub(crate) fn from_key(key: &str) -> Option<Self> {
        match key {
            "friction" => Some(Self::Friction),
            "load" => Some(Self::Load),
            "position" => Some(Self::Position),
            "peclet" => Some(Self::Peclet),
            "coating_thickness" => Some(Self::CoatingThickness),
            "entrainment_speed" => Some(Self::EntrainmentSpeed),
            _ => None,
        }
    }

    /// The name of the recording's timeline.
    pub fn key(self) -> &'static str {
        match self {
            Self::Friction => "friction",
            Self::Load => "load",
            Self::Position => "position",
            Self::Peclet => "peclet",
            Self::CoatingThickness => "coating_thickness",
            Self::EntrainmentSpeed => "entrainment_speed",
        }
    }
}

/// A validated `[sweep]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep {
    pub parameter: SweepParameter,
    /// Friction coefficients; loads in N/m (line) or N (point); positions in the figure's
    /// length unit; body 1's Péclet numbers; coating thicknesses in m; entrainment speeds in
    /// m/s.
    pub values: Vec<f64>,
    /// Material points `(x, z)` (figure length unit, body frame, in the plane of the section)
    /// whose stresses are recorded at every step: the stress history as the load passes.
    pub material_points: Vec<(f64, f64)>,
    /// The values were generated from `from`, `to` and `steps` (not listed in `values`).
    pub generated: bool,
}

/// The smallest Péclet number a speed sweep takes: below it the field is the stationary one
/// scaled with the speed.
pub const MIN_PECLET: f64 = 1e-3;

impl Sweep {
    /// The key that names step `k`'s value in an error: `sweep.values[k]`, or for generated
    /// values `sweep.from` (the first) and `sweep.to` (the others lie between the two).
    pub fn value_key(&self, k: usize) -> String {
        match (self.generated, k) {
            (false, _) => format!("sweep.values[{k}]"),
            (true, 0) => "sweep.from".into(),
            (true, _) => "sweep.to".into(),
        }
    }

    /// A text of step `k`'s value with its unit, e.g. `μ = 0.25`, `W = 500 N`, `x0 = 1.2a`,
    /// `Pe = 3.16 (V = 1.9 m/s)` (`V` the sliding speed).
    pub fn describe(&self, k: usize, scene: &Scene) -> String {
        let value = self.values[k];
        match self.parameter {
            SweepParameter::Friction => format!("μ = {}", compact(value)),
            SweepParameter::Load if scene.contact.kind == ContactKind::Line => {
                format!("P = {} kN/m", compact(value * 1e-3))
            }
            SweepParameter::Load => format!("W = {} N", compact(value)),
            SweepParameter::Position => {
                format!(
                    "x0 = {}{}",
                    compact(value),
                    scene.figure.length_unit.suffix()
                )
            }
            SweepParameter::CoatingThickness => {
                format!(
                    "h = {} µm",
                    crate::io::text::significant(value * 1e6, 3, 1e6, true)
                )
            }
            SweepParameter::EntrainmentSpeed => format!(
                "u = {} m/s",
                crate::io::text::significant(value, 3, 1e6, true)
            ),
            SweepParameter::Peclet => {
                let three = |v: f64| crate::io::text::significant(v, 3, 1e6, true);
                match &scene.thermal {
                    Some(spec) => {
                        let stepped = spec.at_body1_peclet(value, scene.contact.half_width_m());
                        format!(
                            "Pe = {} (V = {} m/s)",
                            three(value),
                            three(stepped.sliding_speed_m_per_s)
                        )
                    }
                    None => format!("Pe = {}", three(value)),
                }
            }
        }
    }
}

impl ThermalSpec {
    /// Body 1's Péclet number `Pe = V1 a / (2κ1)` for the length `a` (m): how far the contact
    /// moves over body 1 in the time heat diffuses across it (Carslaw & Jaeger 1959, §10.7;
    /// Jaeger 1942). 0 when body 1 carries the contact.
    pub fn body1_peclet(&self, half_width_m: f64) -> f64 {
        self.body1.speed_m_per_s * half_width_m / (2.0 * self.body1.properties.diffusivity_m2_per_s)
    }

    /// The same contact slid faster or slower, so that body 1's Péclet number is `peclet`:
    /// the sliding speed and both bodies' speeds scaled by one factor (their ratios kept).
    /// Body 1 must move (`body1_peclet > 0`); otherwise the speeds are left as they are.
    pub fn at_body1_peclet(&self, peclet: f64, half_width_m: f64) -> Self {
        let now = self.body1_peclet(half_width_m);
        if now <= 0.0 {
            return *self;
        }
        let factor = peclet / now;
        let mut stepped = *self;
        stepped.sliding_speed_m_per_s *= factor;
        stepped.body1.speed_m_per_s *= factor;
        if let Some(body2) = &mut stepped.body2 {
            body2.speed_m_per_s *= factor;
        }
        stepped
    }
}

/// A number with at most four significant digits and no trailing zeros (`0.15`, `800`,
/// `−0.866`), in exponent form when very small or large; a typographic minus.
pub fn compact(value: f64) -> String {
    crate::io::text::significant(value, 4, 1e6, true)
}

/// A validated `[volume]`: a box under a point contact recorded as nested iso-surfaces.
#[derive(Clone, Debug, PartialEq)]
pub struct VolumeSpec {
    pub quantity: Quantity,
    /// Ranges in the figure's length unit.
    pub x: (f64, f64),
    pub y: (f64, f64),
    pub z: (f64, f64),
    /// Samples along the longest side; the others follow with the same spacing.
    pub points: usize,
    /// The lowest iso-surface, as a fraction of the largest |value| (the others up to 90 %).
    pub threshold: f64,
}

impl super::Contact {
    /// The same bodies under another normal load (N/m for a line contact, N otherwise):
    /// the Hertz solution recomputed, its size and peak pressure with it.
    pub fn with_load(&self, load: f64) -> Result<Self, ContactError> {
        let Some(mut dimensional) = self.dimensional else {
            return Err(ContactError::InvalidParameter {
                name: "load sweep",
                requirement: "a dimensional contact (bodies and load)",
                value: load,
            });
        };
        dimensional.hertz = match dimensional.hertz {
            super::Hertz::Line(line) => super::Hertz::Line(LineContact::from_effective(
                load,
                line.effective_modulus_pa,
                line.effective_radius_m,
            )),
            super::Hertz::Point(point) => super::Hertz::Point(PointContact::from_effective(
                load,
                point.effective_modulus_pa,
                point.effective_radius_m,
            )),
            super::Hertz::Elliptical(ellipse) => super::Hertz::Elliptical(
                crate::contact::elliptic::EllipticalContact::from_curvatures(
                    ellipse.curvature,
                    ellipse.effective_modulus_pa,
                    load,
                )?,
            ),
        };
        Ok(Self {
            scale: Some(super::Scale {
                half_width_m: dimensional.hertz.half_width_m(),
                p0_pa: dimensional.hertz.p0_pa(),
            }),
            dimensional: Some(dimensional),
            ..*self
        })
    }
}

#[cfg(test)]
mod tests {
    use super::compact;

    #[test]
    fn compact_numbers_drop_trailing_zeros_and_noise() {
        assert_eq!(compact(0.15000000000000002), "0.15");
        assert_eq!(compact(800.0), "800");
        assert_eq!(compact(100.0), "100");
        assert_eq!(compact(-0.8660254037844386), "\u{2212}0.866");
        assert_eq!(compact(-3.0), "\u{2212}3");
        assert_eq!(compact(0.0), "0");
        assert_eq!(compact(2.5e-5), "2.5e\u{2212}5");
        assert_eq!(compact(1234.5678), "1235");
    }
}

//! Recording scenes: a `[sweep]` of friction, load or the load's position (one step per time
//! point of a recording), and a `[volume]` recorded as a 3-D point cloud.

use super::raw::{NumberOrText, RawSweep, RawVolume};
use super::units::{self, Dimension};
use super::{ContactKind, FigureSpec, LengthUnit, Method, PanelSpec, Scene, SceneError, Validator};
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
}

impl SweepParameter {
    fn from_key(key: &str) -> Option<Self> {
        match key {
            "friction" => Some(Self::Friction),
            "load" => Some(Self::Load),
            "position" => Some(Self::Position),
            _ => None,
        }
    }

    /// The name of the recording's timeline.
    pub fn key(self) -> &'static str {
        match self {
            Self::Friction => "friction",
            Self::Load => "load",
            Self::Position => "position",
        }
    }
}

/// A validated `[sweep]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep {
    pub parameter: SweepParameter,
    /// Friction coefficients; loads in N/m (line) or N (point); positions in the figure's
    /// length unit.
    pub values: Vec<f64>,
    /// Material points `(x, z)` (figure length unit, body frame, in the plane of the section)
    /// whose stresses are recorded at every step: the stress history as the load passes.
    pub material_points: Vec<(f64, f64)>,
}

impl Sweep {
    /// A text of step `k`'s value with its unit, e.g. `μ = 0.25`, `W = 500 N`, `x0 = 1.2a`.
    pub fn describe(&self, k: usize, scene: &Scene) -> String {
        let value = self.values[k];
        match self.parameter {
            SweepParameter::Friction => format!("μ = {value}"),
            SweepParameter::Load if scene.contact.kind == ContactKind::Line => {
                format!("P = {:.4} kN/m", value * 1e-3)
            }
            SweepParameter::Load => format!("W = {value:.4} N"),
            SweepParameter::Position => {
                format!("x0 = {value:.4}{}", scene.figure.length_unit.suffix())
            }
        }
    }
}

/// A validated `[volume]`: a box under a point contact recorded as a point cloud.
#[derive(Clone, Debug, PartialEq)]
pub struct VolumeSpec {
    pub quantity: Quantity,
    /// Ranges in the figure's length unit.
    pub x: (f64, f64),
    pub y: (f64, f64),
    pub z: (f64, f64),
    /// Samples along the longest side; the others follow with the same spacing.
    pub points: usize,
    /// Only points whose |value| is at least this fraction of the largest are kept.
    pub threshold: f64,
}

impl Scene {
    /// The scene at step `k` of its sweep (the scene itself when it has none).
    pub fn at_step(&self, k: usize) -> Result<Scene, ContactError> {
        let Some(sweep) = &self.sweep else {
            return Ok(self.clone());
        };
        let value = sweep.values[k];
        let mut scene = self.clone();
        match sweep.parameter {
            SweepParameter::Friction => {
                scene.contact.friction = value;
                for panel in &mut scene.panels {
                    panel.friction = value;
                }
            }
            SweepParameter::Load => scene.contact = self.contact.with_load(value)?,
            SweepParameter::Position => {
                scene.load_centre_over_a = value * self.length_unit_over_a();
            }
        }
        Ok(scene)
    }
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

impl Validator<'_> {
    /// `[sweep]`: `parameter`, and either `values` or `from`, `to`, `steps`.
    pub(super) fn sweep(&self, raw: &RawSweep, scene: &Scene) -> Result<Sweep, SceneError> {
        let parameter = SweepParameter::from_key(&raw.parameter).ok_or_else(|| {
            self.error(
                "sweep.parameter",
                format!("unknown sweep parameter `{}`", raw.parameter),
                Some("use \"friction\", \"load\" or \"position\""),
            )
        })?;
        let contact = &scene.contact;
        let values: Vec<f64> = match (&raw.values, raw.from, raw.to, raw.steps) {
            (Some(values), None, None, None) => {
                let mut numbers = Vec::with_capacity(values.len());
                for (i, value) in values.iter().enumerate() {
                    let key = format!("sweep.values[{i}]");
                    numbers.push(match (value, parameter) {
                        (NumberOrText::Number(v), _) => *v,
                        (NumberOrText::Text(text), SweepParameter::Load) => {
                            let dimension = if contact.kind == ContactKind::Line {
                                Dimension::ForcePerLength
                            } else {
                                Dimension::Force
                            };
                            units::parse(text, dimension).map_err(|m| self.error(&key, m, None))?
                        }
                        (NumberOrText::Text(text), _) => {
                            return Err(self.error(
                                &key,
                                format!("expected a number, got `{text}`"),
                                Some("friction and position values are plain numbers"),
                            ))
                        }
                    });
                }
                numbers
            }
            (None, Some(from), Some(to), Some(steps)) => {
                if !(2..=MAX_STEPS as i64).contains(&steps) {
                    return Err(self.error(
                        "sweep.steps",
                        format!("must lie in 2..={MAX_STEPS}, got {steps}"),
                        None,
                    ));
                }
                let n = steps as usize;
                (0..n)
                    .map(|k| from + (to - from) * k as f64 / (n - 1) as f64)
                    .collect()
            }
            _ => {
                return Err(self.error(
                    "sweep",
                    "give either `values` or all of `from`, `to` and `steps`",
                    Some("e.g. values = [0.0, 0.1, 0.2] or from = 0.0, to = 0.5, steps = 11"),
                ))
            }
        };
        if values.is_empty() || values.len() > MAX_STEPS {
            return Err(self.error(
                "sweep.values",
                format!("needs 1 to {MAX_STEPS} values, got {}", values.len()),
                None,
            ));
        }
        for (i, &value) in values.iter().enumerate() {
            let key = format!("sweep.values[{i}]");
            match parameter {
                SweepParameter::Friction => {
                    self.friction(&key, value)?;
                }
                SweepParameter::Load if !(value.is_finite() && value > 0.0) => {
                    return Err(self.error(
                        &key,
                        format!("a load must be positive and finite, got {value}"),
                        None,
                    ));
                }
                SweepParameter::Load | SweepParameter::Position if !value.is_finite() => {
                    return Err(self.error(&key, format!("must be finite, got {value}"), None));
                }
                _ => {}
            }
        }
        match parameter {
            SweepParameter::Friction if contact.kind == ContactKind::Tractions => {
                return Err(self.error(
                    "sweep.parameter",
                    "tractions from a file carry their own shear: there is no friction to sweep",
                    None,
                ))
            }
            SweepParameter::Friction if contact.tangential.is_some() => {
                return Err(self.error(
                    "sweep.parameter",
                    "a friction sweep of partial slip is not supported",
                    Some("sweep the friction of a sliding contact (no contact.tangential)"),
                ))
            }
            SweepParameter::Load if contact.dimensional.is_none() => {
                return Err(self.error(
                    "sweep.parameter",
                    "a load sweep needs a dimensional contact (bodies, materials and a load)",
                    Some("give contact.load and [contact.body1], [contact.body2]"),
                ))
            }
            SweepParameter::Load if scene.figure.length_unit == LengthUnit::HalfWidth => {
                return Err(self.error(
                    "figure.length_unit",
                    "in units of a and p0 every step of a load sweep shows the same field",
                    Some("draw it in physical units: figure.length_unit = \"mm\" and figure.stress_unit = \"MPa\""),
                ))
            }
            SweepParameter::Position => {
                let numerical_point = contact.kind != ContactKind::Line
                    && scene.panels.iter().any(|p: &PanelSpec| {
                        p.method != Method::ClosedForm
                            || contact.solution(p.friction, p.poisson).is_none()
                    });
                if numerical_point {
                    return Err(self.error(
                        "sweep.parameter",
                        "a moving load is recorded with the closed form only for point contacts (numerical panels off the traction grid would need direct summation at every point)",
                        Some("use method = \"closed_form\" for a moving sphere"),
                    ));
                }
            }
            _ => {}
        }
        // A recording holds every step's sections (to give each panel one colour range).
        let plane_bytes: usize = scene
            .panels
            .iter()
            .map(|p| {
                let plane = scene.plane(p);
                plane.u.count * plane.v.count * 8
            })
            .sum();
        let bytes = plane_bytes.saturating_mul(values.len());
        let limit = crate::field::memory_limit_bytes();
        if bytes > limit {
            return Err(self.error(
                "sweep",
                format!(
                    "{} steps of {} MiB of sections need {} MiB, more than the {} MiB this machine allows",
                    values.len(),
                    plane_bytes >> 20,
                    bytes >> 20,
                    limit >> 20
                ),
                Some("use fewer steps or a lower figure.resolution"),
            ));
        }
        let mut material_points = Vec::new();
        if let Some(points) = &raw.material_points {
            if parameter != SweepParameter::Position {
                return Err(self.error(
                    "sweep.material_points",
                    "material points follow a moving load: they need parameter = \"position\"",
                    None,
                ));
            }
            for (i, point) in points.iter().enumerate() {
                match point.as_slice() {
                    [x, z] if x.is_finite() && z.is_finite() && *z >= 0.0 => {
                        material_points.push((*x, *z))
                    }
                    _ => {
                        return Err(self.error(
                            &format!("sweep.material_points[{i}]"),
                            format!(
                            "needs [x, z] with z >= 0 (in the figure's length unit), got {point:?}"
                        ),
                            None,
                        ))
                    }
                }
            }
            if scene.figure.section != super::SectionKind::Xz {
                return Err(self.error(
                    "sweep.material_points",
                    "material points (x, z) lie in an xz section",
                    Some("use figure.section = \"xz\""),
                ));
            }
        }
        Ok(Sweep {
            parameter,
            values,
            material_points,
        })
    }

    /// `[volume]`: a box under a point contact, recorded as a point cloud.
    pub(super) fn volume(
        &self,
        raw: &RawVolume,
        contact: &super::Contact,
        figure: &FigureSpec,
    ) -> Result<VolumeSpec, SceneError> {
        if contact.kind == ContactKind::Line {
            return Err(self.error(
                "volume",
                "a line contact is the same in every xz plane: record a section instead",
                Some("remove [volume], or use kind = \"point\""),
            ));
        }
        if contact
            .solution(contact.friction, contact.poisson)
            .is_none()
        {
            return Err(self.error(
                "volume",
                "a volume is recorded from the closed form, which this contact has not (elliptical, partial slip or tractions from a file)",
                Some("record sections of it instead (figure.section = \"xz\", \"yz\" or \"xy\" with [[panel]] at = ...)"),
            ));
        }
        let quantity = match &raw.quantity {
            Some(key) => Quantity::from_key(key).ok_or_else(|| {
                let keys: Vec<_> = Quantity::ALL.iter().map(|q| q.key()).collect();
                self.error(
                    "volume.quantity",
                    format!("unknown quantity `{key}`"),
                    Some(&format!("use one of: {}", keys.join(", "))),
                )
            })?,
            None => figure.quantity,
        };
        let unit = figure.length_unit.metres(contact.half_width_m()) / contact.half_width_m();
        let default = |a: f64| a / unit;
        let x = self.range("volume.x", raw.x.as_ref(), (default(-2.0), default(2.0)))?;
        let y = self.range("volume.y", raw.y.as_ref(), (default(-2.0), default(2.0)))?;
        let z = self.range("volume.z", raw.z.as_ref(), (0.0, default(2.0)))?;
        if z.0 < 0.0 {
            return Err(self.error(
                "volume.z",
                format!("depths must be >= 0 (z points into the body), got {}", z.0),
                None,
            ));
        }
        let points = match raw.points {
            None => 48,
            Some(n) if (2..=256).contains(&n) => n as usize,
            Some(n) => {
                return Err(self.error(
                    "volume.points",
                    format!("must lie in 2..=256 (samples along the longest side), got {n}"),
                    Some("48 to 96 keeps the viewer responsive"),
                ))
            }
        };
        let threshold = match raw.threshold {
            None => 0.3,
            Some(t) if (0.0..1.0).contains(&t) => t,
            Some(t) => {
                return Err(self.error(
                    "volume.threshold",
                    format!("must lie in [0, 1) (a fraction of the largest |value|), got {t}"),
                    None,
                ))
            }
        };
        Ok(VolumeSpec {
            quantity,
            x,
            y,
            z,
            points,
            threshold,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_load_step_recomputes_hertz_at_fixed_geometry() {
        let text = "format = 1\n[contact]\nkind = \"point\"\nload = \"100 N\"\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"6.35 mm\"\nmaterial = \"steel\"\n[figure]\nlength_unit = \"mm\"\n[sweep]\nparameter = \"load\"\nvalues = [\"100 N\", \"800 N\"]\n";
        let scene = Scene::parse(text, "t", "t.toml").expect("valid");
        let (first, second) = (scene.at_step(0).expect("ok"), scene.at_step(1).expect("ok"));
        assert_eq!(first.contact, scene.contact);
        // Hertz (Johnson 1985, §4.2(a)): a and p0 grow as W^(1/3); 8 times the load, twice.
        let ratio = |f: fn(&super::super::Contact) -> f64| f(&second.contact) / f(&first.contact);
        assert!((ratio(|c| c.p0_pa()) - 2.0).abs() < 1e-12);
        assert!((ratio(|c| c.half_width_m()) - 2.0).abs() < 1e-12);
        let direct = PointContact::new(
            &scene.contact.dimensional.expect("dimensional").body1,
            &scene.contact.dimensional.expect("dimensional").body2,
            800.0,
        )
        .expect("valid");
        assert!((second.contact.p0_pa() - direct.p0_pa).abs() < 1e-6 * direct.p0_pa);
    }

    #[test]
    fn a_position_step_moves_the_solution() {
        let text = "format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"position\"\nvalues = [0.0, 1.5]\n";
        let scene = Scene::parse(text, "t", "t.toml").expect("valid");
        let moved = scene.at_step(1).expect("ok");
        let solution = moved.solution(&moved.panels[0]).expect("closed form");
        let centred = scene.solution(&scene.panels[0]).expect("closed form");
        let (a, b) = (
            solution.stress_over_p0(1.25, 0.0, 0.4),
            centred.stress_over_p0(-0.25, 0.0, 0.4),
        );
        assert_eq!(a, b);
        assert_eq!(solution.surface_traction_over_p0(1.5, 0.0), (1.0, 0.0));
    }
}

//! Hertz theory: two elastic bodies and a load give the contact size and pressure.
//!
//! All values are SI (m, Pa, N or N/m). A flat has an infinite radius; a concave body (the
//! outer ring of a bearing, an internal gear) has a negative radius and makes a conformal
//! contact, valid while the effective radius stays positive.
//!
//! Uses: [`crate::operator`] (the rough solver's FFT and elastic operator) and [`crate::io`];
//! its tests also use `solution` and `thermal` as second methods.

pub mod coated;
pub mod elliptic;
pub mod gear;
pub mod material;
pub mod partial_slip;
pub mod rough;

pub use material::Material;

use std::f64::consts::PI;

/// One of the two bodies in contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    /// Radius of curvature in the plane of the section, m (`f64::INFINITY` for a flat, negative
    /// for a concave surface).
    pub radius_m: f64,
    pub material: Material,
}

/// Errors of contact parameters; the scene layer adds the key path.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum ContactError {
    #[error(
        "the bodies do not close on each other: 1/R1 + 1/R2 = {curvature_per_m:.6} 1/m must be \
         positive (a concave body's radius must be larger in size than the convex one's)"
    )]
    NotConvex { curvature_per_m: f64 },
    #[error("both bodies are flat: Hertz theory needs at least one curved body")]
    BothFlat,
    #[error("{name} must be {requirement}, got {}", crate::io::text::number(*.value))]
    InvalidParameter {
        name: &'static str,
        requirement: &'static str,
        value: f64,
    },
    #[error(
        "the gap between the bodies must close in every direction: the smaller principal \
         relative curvature is {curvature_per_m:.6} 1/m (zero: the bodies touch along a line, \
         use a line contact; negative: a concave body's radius must be larger in size than the \
         convex one's)"
    )]
    OpenGap { curvature_per_m: f64 },
    #[error(
        "the tangential load {tangential_load_n} N exceeds the limit of friction mu P = \
         {limit_n} N: the contact slides as a whole (partial slip needs 0 <= Q <= mu P)"
    )]
    GrossSliding {
        tangential_load_n: f64,
        limit_n: f64,
    },
}

/// Effective (contact) modulus `E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)`.
///
/// ## Reference
/// Johnson, *Contact Mechanics* (1985), §4.2 (the same combination for line and point
/// contact; Hertz 1882).
pub fn effective_modulus(m1: &Material, m2: &Material) -> f64 {
    1.0 / ((1.0 - m1.poisson * m1.poisson) / m1.modulus_pa
        + (1.0 - m2.poisson * m2.poisson) / m2.modulus_pa)
}

/// Effective radius `R = 1 / (1/R1 + 1/R2)`, flats contributing nothing.
///
/// ## Reference
/// Johnson (1985), §4.1 (relative curvature of two surfaces).
pub fn effective_radius(r1_m: f64, r2_m: f64) -> Result<f64, ContactError> {
    let curvature_per_m = 1.0 / r1_m + 1.0 / r2_m;
    if r1_m.is_infinite() && r2_m.is_infinite() {
        return Err(ContactError::BothFlat);
    }
    if curvature_per_m <= 0.0 {
        return Err(ContactError::NotConvex { curvature_per_m });
    }
    Ok(1.0 / curvature_per_m)
}

/// Hertz line contact (two parallel cylinders, plane strain).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineContact {
    pub load_n_per_m: f64,
    pub effective_modulus_pa: f64,
    pub effective_radius_m: f64,
    /// Contact half-width `a = sqrt(4 P R / (pi E*))`.
    pub half_width_m: f64,
    /// Peak pressure `p0 = 2P / (pi a) = sqrt(P E* / (pi R))`.
    pub p0_pa: f64,
    /// Mean pressure `P / (2a) = pi p0 / 4`.
    pub mean_pressure_pa: f64,
}

impl LineContact {
    /// Hertz solution for a load `P` per unit length.
    ///
    /// `a = sqrt(4 P R / (pi E*))`, `p0 = 2 P / (pi a)`: Johnson (1985), §4.2(b)
    /// (Hertz 1882).
    pub fn new(body1: &Body, body2: &Body, load_n_per_m: f64) -> Result<Self, ContactError> {
        let effective_radius_m = effective_radius(body1.radius_m, body2.radius_m)?;
        let effective_modulus_pa = effective_modulus(&body1.material, &body2.material);
        Ok(Self::from_effective(
            load_n_per_m,
            effective_modulus_pa,
            effective_radius_m,
        ))
    }

    pub fn from_effective(load_n_per_m: f64, e_star_pa: f64, radius_m: f64) -> Self {
        let half_width_m = (4.0 * load_n_per_m * radius_m / (PI * e_star_pa)).sqrt();
        let p0_pa = 2.0 * load_n_per_m / (PI * half_width_m);
        Self {
            load_n_per_m,
            effective_modulus_pa: e_star_pa,
            effective_radius_m: radius_m,
            half_width_m,
            p0_pa,
            mean_pressure_pa: load_n_per_m / (2.0 * half_width_m),
        }
    }

    /// Load per unit length at which the peak pressure would be `p0_pa` (`P ∝ p0^2`).
    pub fn load_for_peak_pressure(&self, p0_pa: f64) -> f64 {
        self.load_n_per_m * (p0_pa / self.p0_pa).powi(2)
    }

    /// The normal approach of the axes of two cylinders (`body1`, `body2`, this contact's
    /// bodies), m: the sum over the bodies of
    /// `δ_i = P (1 - ν_i²) / (π E_i) (2 ln(4 R_i / a) - 1)`, `a` the half-width.
    /// `None` unless both bodies are convex cylinders: a plane problem defines the approach only
    /// relative to points at a finite distance, here the axes (a flat or concave body has none).
    ///
    /// ## Reference
    /// Johnson (1985), *Contact Mechanics*, ch. 5, the approach of the axes of two cylinders in
    /// line contact: each cylinder's centre moves towards the contact by the half-space strain
    /// under the Hertz pressure, integrated from the surface to the depth `R`, plus the
    /// correction of a disc compressed along a diameter (Timoshenko & Goodier, the disc under
    /// two opposite point loads), in which the Poisson terms cancel. The test derives it again by
    /// quadrature of the crate's Hertz stress field.
    pub fn approach_of_axes_m(&self, body1: &Body, body2: &Body) -> Option<f64> {
        let a = self.half_width_m;
        let one = |body: &Body| {
            let r = body.radius_m;
            (r.is_finite() && r > 0.0).then(|| {
                let m = &body.material;
                self.load_n_per_m * (1.0 - m.poisson * m.poisson) / (PI * m.modulus_pa)
                    * (2.0 * (4.0 * r / a).ln() - 1.0)
            })
        };
        Some(one(body1)? + one(body2)?)
    }
}

/// Hertz point contact (two spheres, or a sphere on a flat).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointContact {
    pub load_n: f64,
    pub effective_modulus_pa: f64,
    pub effective_radius_m: f64,
    /// Contact radius `a = (3 W R / (4 E*))^(1/3)`.
    pub radius_m: f64,
    /// Peak pressure `p0 = 3 W / (2 pi a^2)`.
    pub p0_pa: f64,
    /// Mean pressure `W / (pi a^2) = 2 p0 / 3`.
    pub mean_pressure_pa: f64,
    /// Approach of distant points `delta = a^2 / R`.
    pub approach_m: f64,
}

impl PointContact {
    /// Hertz solution for a load `W`.
    ///
    /// `a = (3 W R / (4 E*))^(1/3)`, `p0 = 3 W / (2 pi a^2)`, `delta = a^2 / R`: Johnson (1985), §4.2(a)
    /// (Hertz 1882).
    pub fn new(body1: &Body, body2: &Body, load_n: f64) -> Result<Self, ContactError> {
        let effective_radius_m = effective_radius(body1.radius_m, body2.radius_m)?;
        let effective_modulus_pa = effective_modulus(&body1.material, &body2.material);
        Ok(Self::from_effective(
            load_n,
            effective_modulus_pa,
            effective_radius_m,
        ))
    }

    pub fn from_effective(load_n: f64, e_star_pa: f64, radius_m: f64) -> Self {
        let a = (3.0 * load_n * radius_m / (4.0 * e_star_pa)).cbrt();
        Self {
            load_n,
            effective_modulus_pa: e_star_pa,
            effective_radius_m: radius_m,
            radius_m: a,
            p0_pa: 3.0 * load_n / (2.0 * PI * a * a),
            mean_pressure_pa: load_n / (PI * a * a),
            approach_m: a * a / radius_m,
        }
    }

    /// Load at which the peak pressure would be `p0_pa` (`W ∝ p0^3`).
    pub fn load_for_peak_pressure(&self, p0_pa: f64) -> f64 {
        self.load_n * (p0_pa / self.p0_pa).powi(3)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn steel() -> Material {
        Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        }
    }

    /// The approach of a cylinder's axis derived again: the plane-strain strain `ε_zz` on the
    /// axis under the Hertz pressure (the crate's closed-form field, McEwen) integrated by
    /// quadrature from the surface to the depth `R`, plus the difference between a disc
    /// compressed along a diameter by two opposite loads `P` (Timoshenko & Goodier: on the
    /// loaded diameter `σ_zz = -(2P/π)(1/r1 + 1/r2 - 1/(2R))`, `σ_xx = P/(πR)`) and the
    /// half-space under one (`σ_zz = -2P/(π r)`, `σ_xx = 0`), also by quadrature.
    #[test]
    fn cylinder_approach_from_the_strain_on_the_axis() {
        use crate::thermal::special::integrate;
        for (radius, nu) in [(0.017, 0.3), (0.034, 0.25), (0.002, 0.45)] {
            let cylinder = Body {
                radius_m: radius,
                material: Material {
                    modulus_pa: 210e9,
                    poisson: nu,
                },
            };
            let rigid_flat = Body {
                radius_m: f64::INFINITY,
                material: Material {
                    modulus_pa: 1e30,
                    poisson: 0.0,
                },
            };
            let line =
                LineContact::new(&cylinder, &rigid_flat, 40e3).expect("a cylinder on a flat");
            let (a, p0, p) = (line.half_width_m, line.p0_pa, line.load_n_per_m);
            let e = cylinder.material.modulus_pa;
            let strain = |sxx: f64, szz: f64| ((1.0 - nu * nu) * szz - nu * (1.0 + nu) * sxx) / e;
            // z = a sinh t spreads the logarithmic decay evenly.
            let half_space = integrate(
                |t| {
                    let z = t.sinh();
                    let s = crate::solution::line_hertz::stress_over_p0(0.0, z, 0.0, nu);
                    strain(s.xx * p0, s.zz * p0) * a * t.cosh()
                },
                0.0,
                (radius / a).asinh(),
                1e-13,
            );
            let disc = integrate(
                |r| {
                    let dszz = -2.0 * p / PI * (1.0 / (2.0 * radius - r) - 0.5 / radius);
                    strain(p / (PI * radius), dszz)
                },
                0.0,
                radius,
                1e-13,
            );
            let by_quadrature = -(half_space + disc);
            // Only the cylinder deforms: its own term of the formula.
            let formula = p * (1.0 - nu * nu) / (PI * e) * (2.0 * (4.0 * radius / a).ln() - 1.0);
            // The formula keeps the terms that survive R/a -> ∞; the rest is O((a/R)²) (here
            // R/a from 100 to 390: relative differences of 6e-6 to 3e-7).
            assert_relative_eq!(by_quadrature, formula, max_relative = 2e-5);
        }
        // Flats and concave bodies have no axis.
        let line = LineContact::from_effective(40e3, 115e9, 0.01);
        let flat = Body {
            radius_m: f64::INFINITY,
            material: steel(),
        };
        let cylinder = Body {
            radius_m: 0.01,
            material: steel(),
        };
        assert!(line.approach_of_axes_m(&cylinder, &flat).is_none());
        assert!(line.approach_of_axes_m(&cylinder, &cylinder).is_some());
    }

    #[test]
    fn line_contact_identities() {
        let c = LineContact::from_effective(40e3, 115e9, 0.0114);
        // P = (pi/2) a p0 (the integral of the elliptical pressure) and p0 = sqrt(P E*/(pi R)).
        assert_relative_eq!(
            PI / 2.0 * c.half_width_m * c.p0_pa,
            40e3,
            max_relative = 1e-14
        );
        assert_relative_eq!(
            c.p0_pa,
            (40e3 * 115e9 / (PI * 0.0114)).sqrt(),
            max_relative = 1e-14
        );
        assert_relative_eq!(c.mean_pressure_pa, PI / 4.0 * c.p0_pa, max_relative = 1e-14);
        assert_relative_eq!(
            c.load_for_peak_pressure(2.0 * c.p0_pa),
            4.0 * 40e3,
            max_relative = 1e-14
        );
    }

    #[test]
    fn point_contact_identities() {
        let body = Body {
            radius_m: 0.01,
            material: steel(),
        };
        let flat = Body {
            radius_m: f64::INFINITY,
            material: steel(),
        };
        let c = PointContact::new(&body, &flat, 100.0).expect("valid");
        // W = (2/3) pi a^2 p0 and p0 = (6 W E*^2 / (pi^3 R^2))^(1/3) (Johnson 1985, §4.2(a)).
        assert_relative_eq!(
            2.0 / 3.0 * PI * c.radius_m.powi(2) * c.p0_pa,
            100.0,
            max_relative = 1e-14
        );
        let e = c.effective_modulus_pa;
        assert_relative_eq!(
            c.p0_pa,
            (6.0 * 100.0 * e * e / (PI.powi(3) * 0.01f64.powi(2))).cbrt(),
            max_relative = 1e-13
        );
        // delta = (9 W^2 / (16 R E*^2))^(1/3).
        assert_relative_eq!(
            c.approach_m,
            (9.0 * 100.0f64.powi(2) / (16.0 * 0.01 * e * e)).cbrt(),
            max_relative = 1e-13
        );
    }

    #[test]
    fn load_at_a_given_peak_pressure_follows_hertz_scaling() {
        // Independent of the scaling rule used inside: recompute the contact at the new load.
        let body = Body {
            radius_m: 0.01,
            material: steel(),
        };
        let flat = Body {
            radius_m: f64::INFINITY,
            material: steel(),
        };
        let point = PointContact::new(&body, &flat, 100.0).expect("valid");
        let load = point.load_for_peak_pressure(1.5 * point.p0_pa);
        let again = PointContact::new(&body, &flat, load).expect("valid");
        assert_relative_eq!(again.p0_pa, 1.5 * point.p0_pa, max_relative = 1e-13);
        let line = LineContact::from_effective(40e3, 115e9, 0.0114);
        let load = line.load_for_peak_pressure(0.7 * line.p0_pa);
        let again = LineContact::from_effective(load, 115e9, 0.0114);
        assert_relative_eq!(again.p0_pa, 0.7 * line.p0_pa, max_relative = 1e-13);
    }

    #[test]
    fn effective_values() {
        assert_relative_eq!(
            effective_modulus(&steel(), &steel()),
            210e9 / (2.0 * 0.91),
            max_relative = 1e-15
        );
        assert_relative_eq!(effective_radius(0.02, f64::INFINITY).expect("flat"), 0.02);
        assert_relative_eq!(
            effective_radius(0.01, -0.03).expect("conformal"),
            0.015,
            max_relative = 1e-14
        );
        assert!(matches!(
            effective_radius(0.03, -0.01),
            Err(ContactError::NotConvex { .. })
        ));
        assert_eq!(
            effective_radius(f64::INFINITY, f64::INFINITY),
            Err(ContactError::BothFlat)
        );
    }
}

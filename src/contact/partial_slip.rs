//! Cattaneo–Mindlin partial slip: a Hertz sphere contact under a tangential force `Q < mu P`.
//!
//! A tangential force `Q` in +x, applied after the normal load `P` and increased
//! monotonically (no reversal), leaves a central circle of radius `c` stuck and an annulus
//! `c <= r <= a` slipping with `q = mu p`:
//!
//! ```text
//! c / a = (1 - Q / (mu P))^(1/3)
//! q(r) = mu p0 sqrt(1 - r^2/a^2)                                  c <= r <= a
//! q(r) = mu p0 [sqrt(1 - r^2/a^2) - (c/a) sqrt(1 - r^2/c^2)]      r < c
//! ```
//!
//! The traction acts on the body's surface in +x, as `q = mu p` does elsewhere in the crate.
//! Both bodies are taken to be elastically similar (or the coupling between normal and
//! tangential tractions is otherwise neglected), as in the classical solution.
//!
//! ## Reference
//! C. Cattaneo, Sul contatto di due corpi elastici: distribuzione locale degli sforzi, Rend.
//! Accad. Naz. Lincei 27 (1938) 342–348, 434–436, 474–478; R. D. Mindlin, Compliance of elastic
//! bodies in contact, J. Appl. Mech. 16 (1949) 259–268; both as presented in K. L. Johnson,
//! *Contact Mechanics* (1985), ch. 7 (tangential loading of non-conforming bodies).

use super::{ContactError, Material, PointContact};

/// The Cattaneo–Mindlin traction in units of the Hertz peak pressure `p0` and contact
/// radius `a`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CattaneoMindlin {
    /// Coefficient of friction `mu > 0`.
    pub friction: f64,
    /// `Q / (mu P)` in [0, 1].
    pub tangential_over_limit: f64,
    /// `c / a = (1 - Q/(mu P))^(1/3)`.
    pub stick_radius_over_a: f64,
}

impl CattaneoMindlin {
    /// Partial slip at `Q / (mu P) = tangential_over_limit` in [0, 1] (1: sliding as a whole,
    /// `c = 0`).
    pub fn new(friction: f64, tangential_over_limit: f64) -> Result<Self, ContactError> {
        check_friction(friction)?;
        Ok(Self {
            friction,
            tangential_over_limit,
            stick_radius_over_a: stick_radius_over_a(tangential_over_limit)?,
        })
    }

    /// Tangential traction `q / p0` (acting in +x) at `(x/a, y/a)`; zero outside the contact.
    ///
    /// Inside the stick circle the correction `(c/a) sqrt(1 - r^2/c^2)` is evaluated as
    /// `sqrt(c^2 - r^2) / a` (the same quantity, finite as `c -> 0`).
    pub fn traction_over_p0(&self, x_over_a: f64, y_over_a: f64) -> f64 {
        let r2 = x_over_a * x_over_a + y_over_a * y_over_a;
        if r2 >= 1.0 {
            return 0.0;
        }
        let c = self.stick_radius_over_a;
        let slip = (1.0 - r2).sqrt();
        let correction = if r2 < c * c { (c * c - r2).sqrt() } else { 0.0 };
        self.friction * (slip - correction)
    }
}

/// Stick radius over contact radius, `c/a = (1 - Q/(mu P))^(1/3)`, for `Q/(mu P)` in [0, 1].
pub fn stick_radius_over_a(tangential_over_limit: f64) -> Result<f64, ContactError> {
    if !(0.0..=1.0).contains(&tangential_over_limit) {
        return Err(ContactError::InvalidParameter {
            name: "tangential load over limit of friction Q/(mu P)",
            requirement: "in [0, 1]",
            value: tangential_over_limit,
        });
    }
    Ok((1.0 - tangential_over_limit).cbrt())
}

/// Cattaneo–Mindlin partial slip of a Hertz point contact, in SI units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PartialSlip {
    pub contact: PointContact,
    pub tangential_load_n: f64,
    pub traction: CattaneoMindlin,
    /// Stick radius `c`, m.
    pub stick_radius_m: f64,
}

impl PartialSlip {
    /// A tangential force `tangential_load_n` in +x, `0 <= Q <= mu P`, on `contact`.
    pub fn new(
        contact: &PointContact,
        friction: f64,
        tangential_load_n: f64,
    ) -> Result<Self, ContactError> {
        check_friction(friction)?;
        let limit_n = friction * contact.load_n;
        if tangential_load_n.is_nan() || tangential_load_n < 0.0 {
            return Err(ContactError::InvalidParameter {
                name: "tangential load (N)",
                requirement: "zero or positive (it acts in +x)",
                value: tangential_load_n,
            });
        }
        if tangential_load_n > limit_n {
            return Err(ContactError::GrossSliding {
                tangential_load_n,
                limit_n,
            });
        }
        let traction = CattaneoMindlin::new(friction, tangential_load_n / limit_n)?;
        Ok(Self {
            contact: *contact,
            tangential_load_n,
            traction,
            stick_radius_m: traction.stick_radius_over_a * contact.radius_m,
        })
    }

    /// Tangential traction at `(x, y)`, Pa, acting in +x.
    pub fn traction_pa(&self, x_m: f64, y_m: f64) -> f64 {
        let a = self.contact.radius_m;
        self.contact.p0_pa * self.traction.traction_over_p0(x_m / a, y_m / a)
    }

    /// Tangential displacement of one body relative to the other in x (the shift of the stick
    /// region), m:
    ///
    /// ```text
    /// delta_x = 3 mu P / (16 a) ((2 - nu1)/G1 + (2 - nu2)/G2) (1 - (1 - Q/(mu P))^(2/3))
    /// ```
    ///
    /// with `G = E / (2 (1 + nu))`; `Q = mu P` gives the displacement at the onset of sliding.
    ///
    /// ## Reference
    /// Mindlin (1949); Johnson (1985), ch. 7.
    pub fn tangential_displacement_m(&self, material1: &Material, material2: &Material) -> f64 {
        let compliance = |m: &Material| (2.0 - m.poisson) * 2.0 * (1.0 + m.poisson) / m.modulus_pa;
        let c_over_a = self.traction.stick_radius_over_a;
        3.0 * self.traction.friction * self.contact.load_n / (16.0 * self.contact.radius_m)
            * (compliance(material1) + compliance(material2))
            * (1.0 - c_over_a * c_over_a)
    }
}

fn check_friction(friction: f64) -> Result<(), ContactError> {
    if friction > 0.0 && friction.is_finite() {
        Ok(())
    } else {
        Err(ContactError::InvalidParameter {
            name: "coefficient of friction",
            requirement: "positive and finite",
            value: friction,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::Body;
    use approx::assert_relative_eq;
    use proptest::prelude::*;
    use quadrature::double_exponential;
    use std::f64::consts::{FRAC_PI_2, PI};

    fn steel() -> Material {
        Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        }
    }

    fn aluminium() -> Material {
        Material {
            modulus_pa: 70e9,
            poisson: 0.33,
        }
    }

    /// Steel ball of radius 10 mm on an aluminium flat under 100 N.
    fn contact() -> PointContact {
        let ball = Body {
            radius_m: 0.01,
            material: steel(),
        };
        let flat = Body {
            radius_m: f64::INFINITY,
            material: aluminium(),
        };
        PointContact::new(&ball, &flat, 100.0).expect("valid")
    }

    /// `integral f(x, y) dx dy` over the disc of radius `a`, nested double-exponential
    /// quadrature with the pieces split where the integrand has a kink (the stick circle `c`).
    fn over_disc(f: &dyn Fn(f64, f64) -> f64, a: f64, c: f64, tolerance: f64) -> f64 {
        let row = |y: f64| {
            let half = (a * a - y * y).max(0.0).sqrt();
            let stick = (c * c - y * y).max(0.0).sqrt();
            let mut ends = vec![-half, half];
            if stick > 0.0 {
                ends.extend([-stick, stick]);
            }
            ends.sort_by(f64::total_cmp);
            ends.windows(2)
                .map(|w| double_exponential::integrate(|x| f(x, y), w[0], w[1], tolerance).integral)
                .sum::<f64>()
        };
        let mut ends = vec![-a, a];
        if c > 0.0 {
            ends.extend([-c, c]);
        }
        ends.sort_by(f64::total_cmp);
        ends.windows(2)
            .map(|w| double_exponential::integrate(row, w[0], w[1], tolerance * a).integral)
            .sum()
    }

    #[test]
    fn traction_integrates_to_the_tangential_load() {
        let hertz = contact();
        let friction = 0.3;
        for fraction in [0.05, 0.3, 0.7, 0.95, 0.999, 1.0] {
            let q_n = fraction * friction * hertz.load_n;
            let slip = PartialSlip::new(&hertz, friction, q_n).expect("valid");
            let a = hertz.radius_m;
            let total = over_disc(
                &|x, y| slip.traction_pa(x, y),
                a,
                slip.stick_radius_m,
                1e-13 * hertz.p0_pa * a,
            );
            assert_relative_eq!(total, q_n, max_relative = 1e-9);
        }
    }

    #[test]
    fn no_tangential_load_sticks_everywhere_without_traction() {
        let slip = PartialSlip::new(&contact(), 0.3, 0.0).expect("valid");
        assert_eq!(slip.traction.stick_radius_over_a, 1.0);
        assert_eq!(slip.stick_radius_m, slip.contact.radius_m);
        let a = slip.contact.radius_m;
        for i in -10..=10 {
            for j in -10..=10 {
                let (x, y) = (0.1 * f64::from(i) * a, 0.1 * f64::from(j) * a);
                assert_eq!(slip.traction_pa(x, y), 0.0);
            }
        }
        // Small loads: c -> a as (1 - Q/(mu P))^(1/3) = 1 - Q/(3 mu P) + ...
        let law = CattaneoMindlin::new(0.3, 1e-9).expect("valid");
        assert_relative_eq!(
            law.stick_radius_over_a,
            1.0 - 1e-9 / 3.0,
            max_relative = 1e-15
        );
        assert!(law.traction_over_p0(0.0, 0.0) < 1e-4);
    }

    #[test]
    fn at_the_limit_of_friction_the_whole_contact_slides() {
        let hertz = contact();
        let slip = PartialSlip::new(&hertz, 0.4, 0.4 * hertz.load_n).expect("valid");
        assert_eq!(slip.stick_radius_m, 0.0);
        let a = hertz.radius_m;
        for i in -10..=10 {
            for j in -10..=10 {
                let (x, y) = (0.1 * f64::from(i) * a, 0.1 * f64::from(j) * a);
                let pressure = hertz.p0_pa * (1.0 - (x * x + y * y) / (a * a)).max(0.0).sqrt();
                assert_relative_eq!(
                    slip.traction_pa(x, y),
                    0.4 * pressure,
                    max_relative = 1e-14,
                    epsilon = 1e-14 * hertz.p0_pa
                );
            }
        }
    }

    #[test]
    fn traction_is_continuous_at_the_stick_circle() {
        for fraction in [0.1, 0.5, 0.9] {
            let law = CattaneoMindlin::new(0.5, fraction).expect("valid");
            let c = law.stick_radius_over_a;
            let on_circle = 0.5 * (1.0 - c * c).sqrt();
            for angle in [0.0, 0.7, 2.0, 4.0] {
                let (sin, cos) = f64::sin_cos(angle);
                let at = |r: f64| law.traction_over_p0(r * cos, r * sin);
                assert_relative_eq!(at(c), on_circle, max_relative = 1e-15);
                // The stick correction vanishes like sqrt(c^2 - r^2): within 2 c sqrt(2 eps).
                let epsilon = 1e-12;
                let jump = (at(c * (1.0 - epsilon)) - at(c * (1.0 + epsilon))).abs();
                assert!(
                    jump <= 0.5 * 2.0 * c * (2.0 * epsilon).sqrt(),
                    "jump {jump}"
                );
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]

        #[test]
        fn traction_never_exceeds_the_limit_of_friction(
            x in -1.2f64..1.2,
            y in -1.2f64..1.2,
            fraction in 0.0f64..=1.0,
            friction in 0.01f64..2.0,
        ) {
            let law = CattaneoMindlin::new(friction, fraction).expect("valid");
            let q = law.traction_over_p0(x, y);
            // The pressure with the same rounding as the traction (r^2 first), so that the
            // slip annulus can be checked for equality.
            let r2 = x * x + y * y;
            let limit = friction * (1.0 - r2).max(0.0).sqrt();
            prop_assert!(q >= 0.0);
            prop_assert!(q <= limit);
            // In the slip annulus the traction is at the limit; inside the stick circle below.
            let c = law.stick_radius_over_a;
            if r2 >= c * c || r2 >= 1.0 {
                prop_assert_eq!(q, limit);
            } else {
                prop_assert!(q < limit);
            }
        }
    }

    /// Relative tangential displacement at `(x0, y0)` (units of `a`) of the two surfaces under
    /// the traction, by quadrature of Cerruti's surface displacement for a tangential point
    /// force `Q` in x, `u_x = Q / (2 pi G) ((1 - nu)/rho + nu x^2/rho^3)` (the z = 0 limit of
    /// Johnson 1985, §3.2), summed over both bodies; polar coordinates about the point.
    fn displacement_by_quadrature(
        slip: &PartialSlip,
        m1: &Material,
        m2: &Material,
        x0: f64,
        y0: f64,
    ) -> f64 {
        let a = slip.contact.radius_m;
        let c = slip.traction.stick_radius_over_a;
        // Exit of the ray from a circle of radius `r` centred at the origin.
        let exit = |r: f64, cos: f64, sin: f64| {
            let along = x0 * cos + y0 * sin;
            -along + (along * along - x0 * x0 - y0 * y0 + r * r).sqrt()
        };
        // integral q ds along the ray, and its weights (1 - nu) + nu cos^2 per body.
        let ray = |phi: f64| {
            let (sin, cos) = phi.sin_cos();
            let q = |s: f64| slip.traction.traction_over_p0(x0 + s * cos, y0 + s * sin);
            let (s_c, s_a) = (exit(c, cos, sin), exit(1.0, cos, sin));
            let line = double_exponential::integrate(q, 0.0, s_c, 1e-14).integral
                + double_exponential::integrate(q, s_c, s_a, 1e-14).integral;
            let weight = |m: &Material| {
                let shear_pa = m.modulus_pa / (2.0 * (1.0 + m.poisson));
                ((1.0 - m.poisson) + m.poisson * cos * cos) / (2.0 * PI * shear_pa)
            };
            line * (weight(m1) + weight(m2))
        };
        let total: f64 = (0..4)
            .map(|k| {
                let from = f64::from(k) * FRAC_PI_2;
                double_exponential::integrate(ray, from, from + FRAC_PI_2, 1e-14 / 1e9).integral
            })
            .sum();
        // ds dphi in units of a, traction in units of p0.
        total * slip.contact.p0_pa * a
    }

    #[test]
    fn stick_region_shifts_rigidly_by_mindlins_displacement() {
        let hertz = contact();
        let (m1, m2) = (steel(), aluminium());
        for fraction in [0.2, 0.6, 0.9] {
            let slip = PartialSlip::new(&hertz, 0.3, fraction * 0.3 * hertz.load_n).expect("valid");
            let expected = slip.tangential_displacement_m(&m1, &m2);
            let c = slip.traction.stick_radius_over_a;
            for (x, y) in [
                (0.0, 0.0),
                (0.5 * c, 0.0),
                (0.3 * c, -0.6 * c),
                (0.0, 0.9 * c),
            ] {
                assert_relative_eq!(
                    displacement_by_quadrature(&slip, &m1, &m2, x, y),
                    expected,
                    max_relative = 1e-9
                );
            }
        }
        // At the onset of sliding: 3 mu P / (16 a) ((2 - nu1)/G1 + (2 - nu2)/G2).
        let full = PartialSlip::new(&hertz, 0.3, 0.3 * hertz.load_n).expect("valid");
        let compliance =
            |m: &Material| (2.0 - m.poisson) / (m.modulus_pa / (2.0 * (1.0 + m.poisson)));
        assert_relative_eq!(
            full.tangential_displacement_m(&m1, &m2),
            3.0 * 0.3 * hertz.load_n / (16.0 * hertz.radius_m)
                * (compliance(&m1) + compliance(&m2)),
            max_relative = 1e-15
        );
    }

    #[test]
    fn invalid_friction_and_tangential_load_are_refused() {
        let hertz = contact();
        for friction in [0.0, -0.1, f64::NAN, f64::INFINITY] {
            assert!(matches!(
                PartialSlip::new(&hertz, friction, 1.0),
                Err(ContactError::InvalidParameter { .. })
            ));
        }
        for q in [-1.0, f64::NAN] {
            assert!(matches!(
                PartialSlip::new(&hertz, 0.3, q),
                Err(ContactError::InvalidParameter { .. })
            ));
        }
        assert_eq!(
            PartialSlip::new(&hertz, 0.3, 31.0),
            Err(ContactError::GrossSliding {
                tangential_load_n: 31.0,
                limit_n: 0.3 * hertz.load_n
            })
        );
        for fraction in [-0.1, 1.1, f64::NAN] {
            assert!(stick_radius_over_a(fraction).is_err());
        }
    }
}

//! Viscosity of a lubricant: its rise with pressure (Barus, Roelands) and its fall with
//! temperature (Walther's relation, ASTM D341, through two reference viscosities), and the
//! ISO viscosity grades.
//!
//! SI throughout: dynamic viscosity in Pa s, kinematic viscosity in m²/s, pressure in Pa,
//! temperature in K.

/// Roelands' reference pressure `p_r = 1.96e8 Pa` (Roelands 1966; Hamrock, Schmid & Jacobson
/// 2004, the Roelands pressure-viscosity relation).
pub const ROELANDS_PRESSURE_PA: f64 = 1.96e8;

/// `-ln η∞` with `η∞ = 6.31e-5 Pa s`, the viscosity Roelands' relation tends to at zero
/// pressure for every oil (so that `ln η0 + 9.67 = ln(η0/η∞)`, `η0` in Pa s).
pub const ROELANDS_LN_LIMIT: f64 = 9.67;

/// The smallest inlet viscosity Roelands' relation accepts, Pa s: `η∞ = exp(-9.67)`; a
/// thinner fluid (a gas) has no Roelands pressure-viscosity index.
pub fn roelands_limit_pa_s() -> f64 {
    (-ROELANDS_LN_LIMIT).exp()
}

/// How the viscosity rises with pressure.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PressureViscosity {
    /// Barus (1893): `η = η0 exp(α p)`.
    Barus { alpha_per_pa: f64 },
    /// Roelands (1966): `η = η0 exp{(ln η0 + 9.67) [(1 + p/p_r)^Z - 1]}`, `p_r = 1.96e8 Pa`.
    Roelands { z: f64 },
}

impl PressureViscosity {
    /// `ln(η/η0)` and its derivative with respect to the pressure (1/Pa) at `pressure_pa`
    /// (negative pressures are taken as zero: a cavitated film is at ambient pressure), for the
    /// inlet viscosity `eta0_pa_s`.
    ///
    /// ## Reference
    /// C. Barus, Isothermals, isopiestics and isometrics relative to viscosity, Am. J. Sci. 45
    /// (1893) 87–96; C. J. A. Roelands, Correlational aspects of the viscosity-temperature-
    /// pressure relationship of lubricating oils, thesis, TH Delft (1966); both as written by
    /// Hamrock, Schmid & Jacobson, *Fundamentals of Fluid Film Lubrication* (2004), ch. 4, and
    /// by Venner & Lubrecht, *Multilevel Methods in Lubrication* (2000).
    pub fn log_ratio(&self, eta0_pa_s: f64, pressure_pa: f64) -> (f64, f64) {
        let p = pressure_pa.max(0.0);
        match *self {
            PressureViscosity::Barus { alpha_per_pa } => (alpha_per_pa * p, alpha_per_pa),
            PressureViscosity::Roelands { z } => {
                let a = eta0_pa_s.ln() + ROELANDS_LN_LIMIT;
                let base = 1.0 + p / ROELANDS_PRESSURE_PA;
                let power = base.powf(z);
                (
                    a * (power - 1.0),
                    a * z * power / base / ROELANDS_PRESSURE_PA,
                )
            }
        }
    }

    /// The viscosity at `pressure_pa`, Pa s.
    pub fn viscosity_pa_s(&self, eta0_pa_s: f64, pressure_pa: f64) -> f64 {
        eta0_pa_s * self.log_ratio(eta0_pa_s, pressure_pa).0.exp()
    }

    /// The pressure-viscosity coefficient at zero pressure, `d ln η / dp` at `p = 0`, 1/Pa: `α`
    /// of Barus, and `Z (ln η0 + 9.67) / p_r` of Roelands (the `α` the film formulas take).
    pub fn alpha_at_zero_per_pa(&self, eta0_pa_s: f64) -> f64 {
        self.log_ratio(eta0_pa_s, 0.0).1
    }
}

/// Roelands' pressure-viscosity index `Z` whose slope at zero pressure is `alpha_per_pa`:
/// `Z = α p_r / (ln η0 + 9.67)`. `None` when `η0 <= η∞` (no Roelands index).
pub fn roelands_z_from_alpha(alpha_per_pa: f64, eta0_pa_s: f64) -> Option<f64> {
    let a = eta0_pa_s.ln() + ROELANDS_LN_LIMIT;
    (a > 0.0).then(|| alpha_per_pa * ROELANDS_PRESSURE_PA / a)
}

/// Walther's viscosity-temperature relation as ASTM D341 writes it,
/// `log10 log10(ν + 0.7) = A - B log10 T` (`ν` in mm²/s, `T` in K), through two measured
/// kinematic viscosities.
///
/// Valid for `ν >= 2 mm²/s` (ASTM D341 adds correction terms below, not modelled here) and
/// between and near the two reference temperatures; extrapolation far beyond them is the
/// user's risk (ASTM D341 itself allows it within the oil's liquid range).
///
/// ## Reference
/// C. Walther, Über die Auswertung von Viskositätsangaben, Erdöl und Teer 7 (1931); ASTM D341,
/// Standard Practice for Viscosity-Temperature Equations and Charts for Liquid Petroleum or
/// Hydrocarbon Products.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Walther {
    pub a: f64,
    pub b: f64,
}

/// The smallest kinematic viscosity Walther's relation with the constant 0.7 covers, m²/s.
pub const WALTHER_MIN_M2_PER_S: f64 = 2e-6;

impl Walther {
    /// The line through two (temperature K, kinematic viscosity m²/s) points; `None` unless
    /// the temperatures differ, both viscosities are at least 2 mm²/s and the hotter oil is the
    /// thinner.
    pub fn through(points: [(f64, f64); 2]) -> Option<Self> {
        let [(t1, nu1), (t2, nu2)] = points;
        let loglog = |nu_m2_per_s: f64| (nu_m2_per_s * 1e6 + 0.7).log10().log10();
        let valid = t1 > 0.0
            && t2 > 0.0
            && t1 != t2
            && nu1 >= WALTHER_MIN_M2_PER_S
            && nu2 >= WALTHER_MIN_M2_PER_S
            && (t2 - t1) * (nu2 - nu1) < 0.0;
        if !valid {
            return None;
        }
        let b = (loglog(nu1) - loglog(nu2)) / (t2.log10() - t1.log10());
        Some(Self {
            a: loglog(nu1) + b * t1.log10(),
            b,
        })
    }

    /// The kinematic viscosity at `temperature_k`, m²/s.
    pub fn kinematic_m2_per_s(&self, temperature_k: f64) -> f64 {
        let exponent = self.a - self.b * temperature_k.log10();
        (10f64.powf(10f64.powf(exponent)) - 0.7) * 1e-6
    }
}

/// The ISO viscosity grades of ISO 3448: grade `VG n` has the mid-point kinematic viscosity
/// `n` mm²/s at 40 °C (within ±10 %).
pub const ISO_VG_GRADES: [u32; 20] = [
    2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680, 1000, 1500, 2200, 3200,
];

/// The mid-point kinematic viscosity at 40 °C of `grade` (e.g. 220 for ISO VG 220), m²/s;
/// `None` for a number that is not a grade.
///
/// ## Reference
/// ISO 3448, Industrial liquid lubricants — ISO viscosity classification.
pub fn iso_vg_at_40c_m2_per_s(grade: u32) -> Option<f64> {
    ISO_VG_GRADES
        .contains(&grade)
        .then(|| f64::from(grade) * 1e-6)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn roelands_slope_at_zero_is_alpha_and_lies_below_barus() {
        let eta0 = 0.04;
        let alpha = 2.2e-8;
        let z = roelands_z_from_alpha(alpha, eta0).expect("oil");
        // Z = α p_r / (ln η0 + 9.67) by hand: 2.2e-8 * 1.96e8 / (ln 0.04 + 9.67).
        assert_relative_eq!(z, 4.312 / (0.04f64.ln() + 9.67), max_relative = 1e-12);
        let roelands = PressureViscosity::Roelands { z };
        assert_relative_eq!(
            roelands.alpha_at_zero_per_pa(eta0),
            alpha,
            max_relative = 1e-12
        );
        // The derivative agrees with a central difference.
        for p in [1e7, 3e8, 1.5e9] {
            let (_, slope) = roelands.log_ratio(eta0, p);
            let h = 1e3;
            let numeric =
                (roelands.log_ratio(eta0, p + h).0 - roelands.log_ratio(eta0, p - h).0) / (2.0 * h);
            assert_relative_eq!(slope, numeric, max_relative = 1e-6);
        }
        // For Z < 1 the Roelands viscosity grows more slowly than Barus' at high pressure.
        let barus = PressureViscosity::Barus {
            alpha_per_pa: alpha,
        };
        assert!(roelands.viscosity_pa_s(eta0, 1e9) < barus.viscosity_pa_s(eta0, 1e9));
        assert_eq!(roelands.viscosity_pa_s(eta0, -1e8), eta0);
        assert!(roelands_z_from_alpha(alpha, 1e-5).is_none());
    }

    /// A Walther line through two points returns them, and one point computed by hand:
    /// through 220 mm²/s at 40 °C and 19 mm²/s at 100 °C, at 70 °C.
    #[test]
    fn walther_through_two_points() {
        let t40 = 313.15;
        let t100 = 373.15;
        let fit = Walther::through([(t40, 220e-6), (t100, 19e-6)]).expect("oil");
        assert_relative_eq!(fit.kinematic_m2_per_s(t40), 220e-6, max_relative = 1e-12);
        assert_relative_eq!(fit.kinematic_m2_per_s(t100), 19e-6, max_relative = 1e-12);
        // By hand: y1 = log10 log10 220.7 = 0.368604..., y2 = log10 log10 19.7 = 0.110573...,
        // B = (y1 - y2) / (log10 373.15 - log10 313.15), y(343.15) = y1 - B (log10 343.15 -
        // log10 313.15), ν = 10^10^y - 0.7.
        let y1 = 220.7f64.log10().log10();
        let y2 = 19.7f64.log10().log10();
        let b = (y1 - y2) / (373.15f64.log10() - 313.15f64.log10());
        let y = y1 - b * (343.15f64.log10() - 313.15f64.log10());
        let by_hand = 10f64.powf(10f64.powf(y)) - 0.7;
        assert_relative_eq!(
            fit.kinematic_m2_per_s(343.15) * 1e6,
            by_hand,
            max_relative = 1e-12
        );
        // 51.70 mm²/s (an ISO VG 220 oil of 19 mm²/s at 100 °C, at 70 °C).
        assert!((by_hand - 51.70).abs() < 0.01, "{by_hand}");
        assert!(Walther::through([(t40, 19e-6), (t100, 220e-6)]).is_none());
        assert!(Walther::through([(t40, 1e-6), (t100, 0.5e-6)]).is_none());
    }

    #[test]
    fn iso_grades() {
        assert_relative_eq!(iso_vg_at_40c_m2_per_s(220).expect("grade"), 220e-6);
        assert!(iso_vg_at_40c_m2_per_s(200).is_none());
    }
}

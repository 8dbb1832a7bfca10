//! Film thickness of an elastohydrodynamic contact from the standard regressions: Hamrock &
//! Dowson (1977) for point and elliptical contacts, Pan & Hamrock (1989) for line contacts,
//! and Moes' (1992) central film of a line contact over every regime (the numerical solver's
//! first guess, and a published reference for it).
//!
//! Hamrock's dimensionless groups: speed `U = η0 u / (E' Rx)`, materials `G = α E'`, load
//! `W = w / (E' Rx²)` (a point or elliptical contact, `w` in N) or `W' = w' / (E' Rx)` (a line
//! contact, `w'` in N/m), with `u = (u1 + u2)/2` the mean entrainment speed, `Rx` the
//! effective radius in the direction of entrainment and Hamrock's `E' = 2 E*` (twice the
//! contact modulus of [`crate::contact::effective_modulus`]). Moes' groups use the sum speed
//! `2u`: a line contact's `M = W' (2U)^(-1/2)`, `L = G (2U)^(1/4)`; a point contact's
//! `M = W (2U)^(-3/4)` and the same `L`.

/// The operating conditions a film formula needs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilmConditions {
    /// Dynamic viscosity at the inlet temperature and ambient pressure, Pa s.
    pub viscosity_pa_s: f64,
    /// Pressure-viscosity coefficient (the slope of `ln η` at zero pressure), 1/Pa.
    pub alpha_per_pa: f64,
    /// Hamrock's reduced modulus `E' = 2 E*`, Pa.
    pub reduced_modulus_pa: f64,
    /// Mean entrainment speed `u = (u1 + u2)/2`, m/s.
    pub entrainment_m_per_s: f64,
    /// Effective radius in the direction of entrainment, m.
    pub radius_x_m: f64,
}

impl FilmConditions {
    /// Hamrock's speed parameter `U = η0 u / (E' Rx)`.
    pub fn speed_parameter(&self) -> f64 {
        self.viscosity_pa_s * self.entrainment_m_per_s / (self.reduced_modulus_pa * self.radius_x_m)
    }

    /// Hamrock's materials parameter `G = α E'`.
    pub fn materials_parameter(&self) -> f64 {
        self.alpha_per_pa * self.reduced_modulus_pa
    }

    /// A line contact's load parameter `W' = w' / (E' Rx)`.
    pub fn line_load_parameter(&self, load_n_per_m: f64) -> f64 {
        load_n_per_m / (self.reduced_modulus_pa * self.radius_x_m)
    }

    /// A point contact's load parameter `W = w / (E' Rx²)`.
    pub fn point_load_parameter(&self, load_n: f64) -> f64 {
        load_n / (self.reduced_modulus_pa * self.radius_x_m * self.radius_x_m)
    }

    /// Moes' parameters `(M, L)` of a line contact under `load_n_per_m`:
    /// `M = W' (2U)^(-1/2)`, `L = G (2U)^(1/4)`.
    ///
    /// ## Reference
    /// H. Moes, Optimum similarity analysis with applications to elastohydrodynamic
    /// lubrication, Wear 159 (1992) 57–66; as used by Venner & Lubrecht, *Multilevel Methods in
    /// Lubrication* (2000).
    pub fn moes_line(&self, load_n_per_m: f64) -> (f64, f64) {
        let sum = 2.0 * self.speed_parameter();
        (
            self.line_load_parameter(load_n_per_m) / sum.sqrt(),
            self.materials_parameter() * sum.powf(0.25),
        )
    }

    /// Moes' parameters `(M, L)` of a point contact under `load_n`: `M = W (2U)^(-3/4)`,
    /// `L = G (2U)^(1/4)` (same reference as [`Self::moes_line`]).
    pub fn moes_point(&self, load_n: f64) -> (f64, f64) {
        let sum = 2.0 * self.speed_parameter();
        (
            self.point_load_parameter(load_n) * sum.powf(-0.75),
            self.materials_parameter() * sum.powf(0.25),
        )
    }
}

/// A central and a minimum film thickness, m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Films {
    pub central_m: f64,
    pub minimum_m: f64,
}

/// Pan & Hamrock's (1989) film of an isothermal, fully flooded line contact:
/// `h_min / Rx = 1.714 W'^(-0.128) U^0.694 G^0.568` and
/// `h_c / Rx = 2.922 W'^(-0.166) U^0.692 G^0.470`.
///
/// A curve fit to their numerical solutions of the elastic-piezoviscous regime (Roelands
/// viscosity, Dowson–Higginson density). The central film falls faster with load than the
/// minimum one, so beyond `W'` of about 1e-3 (at `U = 1e-11`, `G = 5000`) the formulas give
/// `h_c < h_min`; [`crate::lubrication::line_ehl`] solves the contact instead. Against that
/// solver (docs/lubrication.md) the minimum film agrees within 6 % and the central within 12 %
/// for Moes' `M` from 5 to 200 at `L = 10`.
///
/// ## Reference
/// P. Pan & B. J. Hamrock, Simple formulas for performance parameters used in
/// elastohydrodynamically lubricated line contacts, J. Tribol. 111 (1989) 246–251; also in
/// Hamrock, Schmid & Jacobson, *Fundamentals of Fluid Film Lubrication* (2004).
pub fn pan_hamrock(conditions: &FilmConditions, load_n_per_m: f64) -> Films {
    let u = conditions.speed_parameter();
    let g = conditions.materials_parameter();
    let w = conditions.line_load_parameter(load_n_per_m);
    let r = conditions.radius_x_m;
    Films {
        central_m: r * 2.922 * w.powf(-0.166) * u.powf(0.692) * g.powf(0.470),
        minimum_m: r * 1.714 * w.powf(-0.128) * u.powf(0.694) * g.powf(0.568),
    }
}

/// Hamrock & Dowson's (1977) film of an isothermal, fully flooded point or elliptical
/// contact: `h_c / Rx = 2.69 U^0.67 G^0.53 W^(-0.067) (1 - 0.61 e^(-0.73 k))` and
/// `h_min / Rx = 3.63 U^0.68 G^0.49 W^(-0.073) (1 - e^(-0.68 k))`, with `k` the ellipticity:
/// the contact's semi-axis across the entrainment over the one along it (1 for a sphere).
///
/// Fitted to their numerical solutions for `k` from 1 (a ball on a plate) to 8 (nearly a line
/// contact), the speed parameter over nearly two orders of magnitude and the load over one, for
/// steel, bronze and silicon nitride with mineral oils; entrainment along the short axis
/// (`k >= 1`). [`FilmValidity`] says when a contact leaves that range.
///
/// ## Reference
/// B. J. Hamrock & D. Dowson, Isothermal elastohydrodynamic lubrication of point contacts,
/// Part III — Fully flooded results, J. Lubr. Technol. 99 (1977) 264–276.
pub fn hamrock_dowson(conditions: &FilmConditions, load_n: f64, ellipticity: f64) -> Films {
    let u = conditions.speed_parameter();
    let g = conditions.materials_parameter();
    let w = conditions.point_load_parameter(load_n);
    let r = conditions.radius_x_m;
    let k = ellipticity;
    Films {
        central_m: r
            * 2.69
            * u.powf(0.67)
            * g.powf(0.53)
            * w.powf(-0.067)
            * (1.0 - 0.61 * (-0.73 * k).exp()),
        minimum_m: r
            * 3.63
            * u.powf(0.68)
            * g.powf(0.49)
            * w.powf(-0.073)
            * (1.0 - (-0.68 * k).exp()),
    }
}

/// The range of ellipticity Hamrock & Dowson's regression covers.
pub const HAMROCK_DOWSON_ELLIPTICITY: (f64, f64) = (1.0, 8.0);

/// Moes' central film of an isothermal line contact in Moes' dimensionless form
/// `H = (h_c / Rx) (2U)^(-1/2)`, joining the four asymptotes rigid-isoviscous `3 M^(-1)`,
/// elastic-isoviscous `2.621 M^(-1/5)`, rigid-piezoviscous `1.287 L^(2/3)` and
/// elastic-piezoviscous `1.311 M^(-1/8) L^(3/4)`:
/// `H = [(H_RI^(7/3) + H_EI^(7/3))^(3s/7) + (H_RP^(-7/2) + H_EP^(-7/2))^(-2s/7)]^(1/s)`,
/// `s = (7 + 8 exp(-2 H_EI/H_RI)) / 5`.
///
/// Fitted to numerical solutions with Barus viscosity and a constant density (the solver
/// here agrees within 4 % for `M` 5 to 100, `L = 10`: docs/lubrication.md); with Roelands
/// viscosity the film is thinner.
///
/// ## Reference
/// H. Moes, Optimum similarity analysis with applications to elastohydrodynamic lubrication,
/// Wear 159 (1992) 57–66; as given by C. H. Venner & A. A. Lubrecht, *Multilevel Methods in
/// Lubrication* (Elsevier, 2000), the line contact's film thickness formula.
pub fn moes_line_central(m: f64, l: f64) -> f64 {
    let rigid_isoviscous = 3.0 / m;
    let elastic_isoviscous = 2.621 * m.powf(-0.2);
    let rigid_piezoviscous = 1.287 * l.powf(2.0 / 3.0);
    let elastic_piezoviscous = 1.311 * m.powf(-0.125) * l.powf(0.75);
    let s = 0.2 * (7.0 + 8.0 * (-2.0 * elastic_isoviscous / rigid_isoviscous).exp());
    let isoviscous =
        (rigid_isoviscous.powf(7.0 / 3.0) + elastic_isoviscous.powf(7.0 / 3.0)).powf(3.0 * s / 7.0);
    let piezoviscous = if l > 0.0 {
        (rigid_piezoviscous.powf(-3.5) + elastic_piezoviscous.powf(-3.5)).powf(-2.0 * s / 7.0)
    } else {
        0.0
    };
    (isoviscous + piezoviscous).powf(1.0 / s)
}

/// Why a film formula's result is doubtful for a contact.
#[derive(Clone, Debug, PartialEq)]
pub enum FilmValidity {
    /// Within the regression's fitted range and the elastic-piezoviscous regime.
    Valid,
    /// The ellipticity lies outside Hamrock & Dowson's 1 to 8.
    Ellipticity { k: f64 },
    /// The film is thicker than the elastic flattening `a²/(2 Rx)` (the gap the Hertz pressure
    /// closes at the contact's edge): the surfaces barely deform, the contact runs in the rigid
    /// (hydrodynamic) regime, isoviscous-rigid unless the pressure-viscosity effect is strong,
    /// and the EHL formulas do not apply.
    Rigid { film_over_flattening: f64 },
}

/// Whether `films` of a contact with half-width (or semi-axis along the entrainment)
/// `half_width_m` lie in the formulas' regime, and for an elliptical contact whether its
/// ellipticity is covered.
pub fn validity(
    films: &Films,
    half_width_m: f64,
    radius_x_m: f64,
    ellipticity: Option<f64>,
) -> Vec<FilmValidity> {
    let mut doubts = Vec::new();
    if let Some(k) = ellipticity {
        let (lo, hi) = HAMROCK_DOWSON_ELLIPTICITY;
        if !(lo - 1e-9..=hi + 1e-9).contains(&k) {
            doubts.push(FilmValidity::Ellipticity { k });
        }
    }
    let flattening = half_width_m * half_width_m / (2.0 * radius_x_m);
    let ratio = films.central_m / flattening;
    if ratio > 1.0 {
        doubts.push(FilmValidity::Rigid {
            film_over_flattening: ratio,
        });
    }
    doubts
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Conditions with `U = 1e-11`, `G = 5000` and `Rx = 10 mm`.
    fn conditions() -> FilmConditions {
        let e = 2.3e11;
        FilmConditions {
            viscosity_pa_s: 0.05,
            alpha_per_pa: 5000.0 / e,
            reduced_modulus_pa: e,
            entrainment_m_per_s: 1e-11 * e * 0.01 / 0.05,
            radius_x_m: 0.01,
        }
    }

    /// Pan & Hamrock at `W' = 1e-4`, `U = 1e-11`, `G = 5000`, by hand:
    /// `h_min/Rx = 1.714 × 1e-4^-0.128 × 1e-11^0.694 × 5000^0.568 = 1.63315e-5` and
    /// `h_c/Rx = 2.922 × 1e-4^-0.166 × 1e-11^0.692 × 5000^0.470 = 1.80383e-5`.
    #[test]
    fn pan_hamrock_by_hand() {
        let c = conditions();
        assert_relative_eq!(c.speed_parameter(), 1e-11, max_relative = 1e-12);
        assert_relative_eq!(c.materials_parameter(), 5000.0, max_relative = 1e-12);
        let load = 1e-4 * c.reduced_modulus_pa * c.radius_x_m;
        let films = pan_hamrock(&c, load);
        assert_relative_eq!(films.minimum_m / 0.01, 1.63315e-5, max_relative = 1e-5);
        assert_relative_eq!(films.central_m / 0.01, 1.80383e-5, max_relative = 1e-5);
    }

    /// Hamrock & Dowson at `W = 1e-6`, `U = 1e-11`, `G = 5000`, by hand: a sphere (`k = 1`)
    /// `h_c/Rx = 2.69 × 1e-11^0.67 × 5000^0.53 × 1e-6^-0.067 × (1 - 0.61 e^-0.73) = 1.86652e-5`,
    /// `h_min/Rx = 3.63 × 1e-11^0.68 × 5000^0.49 × 1e-6^-0.073 × (1 - e^-0.68) = 1.05581e-5`;
    /// `k = 4`: 2.55669e-5 and 1.99897e-5.
    #[test]
    fn hamrock_dowson_by_hand() {
        let c = conditions();
        let load = 1e-6 * c.reduced_modulus_pa * c.radius_x_m * c.radius_x_m;
        let sphere = hamrock_dowson(&c, load, 1.0);
        assert_relative_eq!(sphere.central_m / 0.01, 1.86652e-5, max_relative = 1e-5);
        assert_relative_eq!(sphere.minimum_m / 0.01, 1.05581e-5, max_relative = 1e-5);
        let ellipse = hamrock_dowson(&c, load, 4.0);
        assert_relative_eq!(ellipse.central_m / 0.01, 2.55669e-5, max_relative = 1e-5);
        assert_relative_eq!(ellipse.minimum_m / 0.01, 1.99897e-5, max_relative = 1e-5);
    }

    #[test]
    fn moes_parameters_and_asymptotes() {
        let c = conditions();
        let load = 1e-4 * c.reduced_modulus_pa * c.radius_x_m;
        let (m, l) = c.moes_line(load);
        // M = 1e-4 / sqrt(2e-11), L = 5000 (2e-11)^(1/4).
        assert_relative_eq!(m, 1e-4 / 2e-11f64.sqrt(), max_relative = 1e-12);
        assert_relative_eq!(l, 5000.0 * 2e-11f64.powf(0.25), max_relative = 1e-12);
        // Far into each regime the formula is its asymptote: rigid-isoviscous at small M and
        // L = 0, elastic-piezoviscous at large M and L.
        assert_relative_eq!(
            moes_line_central(1e-3, 0.0),
            3.0 / 1e-3,
            max_relative = 1e-3
        );
        let (m, l) = (1e6, 1e3);
        assert_relative_eq!(
            moes_line_central(m, l),
            1.311 * m.powf(-0.125) * l.powf(0.75),
            max_relative = 1e-2
        );
    }

    #[test]
    fn validity_flags() {
        let films = Films {
            central_m: 2e-6,
            minimum_m: 1e-6,
        };
        // a²/(2R) = (0.1 mm)² / 20 mm = 0.5 µm < 2 µm: rigid.
        let doubts = validity(&films, 1e-4, 0.01, Some(10.0));
        assert!(doubts.contains(&FilmValidity::Ellipticity { k: 10.0 }));
        assert!(
            matches!(doubts[1], FilmValidity::Rigid { film_over_flattening } if (film_over_flattening - 4.0).abs() < 1e-12)
        );
        assert!(validity(&films, 1e-3, 0.01, Some(1.0)).is_empty());
    }
}

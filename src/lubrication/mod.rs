//! Lubricated contacts: the lubricant's viscosity and density, the film thickness of the
//! standard regressions, the λ ratio of film to roughness, and the numerical EHL solution of a
//! line contact. Pure functions of SI values: no I/O, no threads.
//!
//! Conventions: the lubricant is entrained in `+x` (inlet at `-x`); `u = (u1 + u2)/2` is the
//! mean entrainment (rolling) speed of the two surfaces relative to the contact; Hamrock's
//! reduced modulus `E' = 2 E*`.

pub mod density;
pub mod film;
pub mod line_ehl;
pub mod viscosity;

/// The lubrication regime by the λ ratio of the minimum film to the composite roughness.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Regime {
    /// `λ < 1`: the asperities carry most of the load.
    Boundary,
    /// `1 <= λ <= 3`: film and asperities share it.
    Mixed,
    /// `λ > 3`: a full film separates the surfaces.
    FullFilm,
}

impl Regime {
    /// The regime of `lambda`: boundary below 1, mixed from 1 to 3, full film above 3.
    ///
    /// ## Reference
    /// The usual bands, e.g. Hamrock, Schmid & Jacobson, *Fundamentals of Fluid Film
    /// Lubrication* (2004), ch. 1 (the film parameter Λ).
    pub fn of_lambda(lambda: f64) -> Self {
        if lambda < 1.0 {
            Regime::Boundary
        } else if lambda <= 3.0 {
            Regime::Mixed
        } else {
            Regime::FullFilm
        }
    }

    /// `boundary`, `mixed` or `full_film`.
    pub fn key(self) -> &'static str {
        match self {
            Regime::Boundary => "boundary",
            Regime::Mixed => "mixed",
            Regime::FullFilm => "full_film",
        }
    }
}

/// The composite rms roughness of two surfaces, `√(σ1² + σ2²)`, m.
pub fn composite_roughness_m(sigma1_m: f64, sigma2_m: f64) -> f64 {
    sigma1_m.hypot(sigma2_m)
}

/// `λ = h_min / σ`.
pub fn lambda_ratio(minimum_film_m: f64, composite_roughness_m: f64) -> f64 {
    minimum_film_m / composite_roughness_m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regimes_by_lambda() {
        assert_eq!(Regime::of_lambda(0.5), Regime::Boundary);
        assert_eq!(Regime::of_lambda(1.0), Regime::Mixed);
        assert_eq!(Regime::of_lambda(3.0), Regime::Mixed);
        assert_eq!(Regime::of_lambda(3.5), Regime::FullFilm);
        assert!((composite_roughness_m(0.3e-6, 0.4e-6) - 0.5e-6).abs() < 1e-20);
        assert!((lambda_ratio(1e-6, 0.5e-6) - 2.0).abs() < 1e-15);
    }
}

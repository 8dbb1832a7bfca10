//! J2 (von Mises) plasticity with linear isotropic hardening: the radial return of a trial
//! stress onto the yield surface.
//!
//! ## The model
//! The yield function is `f = σ_eq - (σY + h κ)`, with `σ_eq = √(3/2 s:s)` the von Mises
//! stress of the deviator `s`, `σY` the initial yield strength, `h` the plastic modulus
//! (the slope of the yield stress against the equivalent plastic strain; `h = 0` is perfectly
//! plastic) and `κ = ∫ √(2/3 dεp:dεp)` the accumulated equivalent plastic strain. The flow is
//! associative: `dεp = dκ (3/2) s / σ_eq`, deviatoric. Hardening is isotropic (the surface
//! grows, it does not move), so a reversed stress yields again once its von Mises stress
//! reaches `σY + h κ` (reverse yielding on unloading).
//!
//! ## The return mapping (backward Euler)
//! From the state at the start of a step (`εp_n`, `κ_n`) and the trial stress of the step's
//! total strain with the plastic strain frozen, `σ_tr`: if `f(σ_tr, κ_n) <= 0` the step is
//! elastic; otherwise `Δκ = f(σ_tr, κ_n) / (3μ + h)`, `Δεp = Δκ (3/2) s_tr / σ_eq,tr`, and
//! the stress `σ = σ_tr - 2μ Δεp` lies on the grown surface (the deviator shrinks radially;
//! the pressure is unchanged). Exact for linear hardening (Simo & Hughes 1998, §3.3.1, the
//! radial return of Wilkins 1964).
//!
//! Components in the order of [`crate::solution::dcfft::COMPONENTS`] (xx, yy, zz, yz, xz,
//! xy), tensor shears.
//!
//! ## References
//! - J. C. Simo, T. J. R. Hughes, *Computational Inelasticity*, Springer (1998), §3.3.
//! - M. L. Wilkins, Calculation of elastic-plastic flow, *Methods in Computational Physics* 3
//!   (1964).

/// The yield stress `σY + h κ`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hardening {
    /// `σY`, Pa.
    pub yield_strength_pa: f64,
    /// `h`, Pa: the plastic modulus (not the tangent modulus of a bilinear curve).
    pub plastic_modulus_pa: f64,
}

impl Hardening {
    /// The yield stress at the accumulated equivalent plastic strain `kappa`, Pa.
    pub fn yield_stress_pa(&self, kappa: f64) -> f64 {
        self.yield_strength_pa + self.plastic_modulus_pa * kappa
    }
}

/// The von Mises stress of a stress given as six components (tensor shears).
pub fn von_mises(stress: &[f64; 6]) -> f64 {
    let mean = (stress[0] + stress[1] + stress[2]) / 3.0;
    let (a, b, c) = (stress[0] - mean, stress[1] - mean, stress[2] - mean);
    let contracted = a * a
        + b * b
        + c * c
        + 2.0 * (stress[3] * stress[3] + stress[4] * stress[4] + stress[5] * stress[5]);
    (1.5 * contracted).sqrt()
}

/// The equivalent of a strain increment, `√(2/3 Δε:Δε)` (tensor shears).
pub fn equivalent_strain(strain: &[f64; 6]) -> f64 {
    let contracted = strain[0] * strain[0]
        + strain[1] * strain[1]
        + strain[2] * strain[2]
        + 2.0 * (strain[3] * strain[3] + strain[4] * strain[4] + strain[5] * strain[5]);
    (contracted * 2.0 / 3.0).sqrt()
}

/// The radial return of `trial` (Pa) from the accumulated plastic strain `kappa` in a
/// material of shear modulus `shear_modulus_pa`: `None` if the trial stress lies within the
/// yield surface, else the plastic strain increment and the increment of `κ`.
pub fn radial_return(
    trial: &[f64; 6],
    kappa: f64,
    hardening: &Hardening,
    shear_modulus_pa: f64,
) -> Option<([f64; 6], f64)> {
    let equivalent = von_mises(trial);
    let excess = equivalent - hardening.yield_stress_pa(kappa);
    if excess <= 0.0 {
        return None;
    }
    let increment = excess / (3.0 * shear_modulus_pa + hardening.plastic_modulus_pa);
    let mean = (trial[0] + trial[1] + trial[2]) / 3.0;
    let factor = 1.5 * increment / equivalent;
    let strain = [
        factor * (trial[0] - mean),
        factor * (trial[1] - mean),
        factor * (trial[2] - mean),
        factor * trial[3],
        factor * trial[4],
        factor * trial[5],
    ];
    Some((strain, increment))
}

#[cfg(test)]
mod tests {
    use super::*;

    const MU: f64 = 80e9;

    #[test]
    fn the_returned_stress_lies_on_the_grown_surface() {
        let hardening = Hardening {
            yield_strength_pa: 1e9,
            plastic_modulus_pa: 10e9,
        };
        let trial = [1.8e9, -0.3e9, 0.2e9, 0.4e9, -0.7e9, 0.5e9];
        let kappa = 0.01;
        let (strain, increment) = radial_return(&trial, kappa, &hardening, MU).expect("yields");
        let returned: Vec<f64> = trial
            .iter()
            .zip(&strain)
            .map(|(t, e)| t - 2.0 * MU * e)
            .collect();
        let returned: [f64; 6] = returned.try_into().expect("six");
        let surface = hardening.yield_stress_pa(kappa + increment);
        assert!((von_mises(&returned) / surface - 1.0).abs() < 1e-13);
        // Deviatoric flow, and κ grows by the equivalent of the increment.
        assert!((strain[0] + strain[1] + strain[2]).abs() < 1e-15);
        assert!((equivalent_strain(&strain) / increment - 1.0).abs() < 1e-13);
        // The pressure is unchanged and the deviator keeps its direction.
        let mean = |s: &[f64; 6]| (s[0] + s[1] + s[2]) / 3.0;
        assert!((mean(&returned) - mean(&trial)).abs() < 1e-3);
        let ratio = (returned[3]) / trial[3];
        for c in 3..6 {
            assert!((returned[c] / trial[c] - ratio).abs() < 1e-12);
        }
    }

    #[test]
    fn within_the_surface_nothing_flows_and_uniaxial_flow_matches_the_slope() {
        let hardening = Hardening {
            yield_strength_pa: 1e9,
            plastic_modulus_pa: 0.0,
        };
        assert!(radial_return(&[0.9e9, 0.0, 0.0, 0.0, 0.0, 0.0], 0.0, &hardening, MU).is_none());
        // Uniaxial trial σ: von Mises σ, so Δκ = (σ - σY)/(3μ).
        let (_, increment) =
            radial_return(&[1.3e9, 0.0, 0.0, 0.0, 0.0, 0.0], 0.0, &hardening, MU).expect("yields");
        assert!((increment / (0.3e9 / (3.0 * MU)) - 1.0).abs() < 1e-13);
    }
}

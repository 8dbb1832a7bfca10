//! The frictional heat and how it divides between the two bodies.
//!
//! Sliding at speed `V` under a pressure `p` with friction coefficient `μ` dissipates
//! `q = μ p V` (W/m²) at the interface (Blok 1937; Johnson 1985, §13.4). It enters the bodies
//! in shares `f` (body 1) and `1 - f` (body 2):
//! - all into body 1 (`f = 1`): the counter-face rigid and adiabatic, the upper bound on body
//!   1's heating that Liu & Wang (2001) use for a steel ball on a boron-carbide coated disc;
//! - a given fraction;
//! - Blok's partition: `f` such that both bodies' surfaces, each heated by its share moving
//!   over it at its own speed, reach the same mean temperature over the contact. Temperatures
//!   are linear in the flux, so with `T̄1`, `T̄2` the mean rises under the whole flux,
//!   `f T̄1 = (1 - f) T̄2` gives `f = T̄2 / (T̄1 + T̄2)`. At high Péclet numbers this tends to
//!   the ratio of effusivities `e1 / (e1 + e2)`, `e = √(K ρ c)` (each surface heated like a
//!   semi-infinite body for the same time, `T̄ ∝ 1/e`).
//!
//! ## References
//! - H. Blok, Theoretical study of temperature rise at surfaces of actual contact under
//!   oiliness lubricating conditions, *Proc. General Discussion on Lubrication*, IMechE (1937).
//! - K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985).
//! - S. Liu, Q. Wang, A three-dimensional thermomechanical model of contact between
//!   non-conforming rough surfaces, *ASME J. Tribol.* 123 (2001).

/// How the frictional heat divides between the bodies.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Partition {
    /// All of it into body 1: the counter-face is adiabatic.
    Body1,
    /// This fraction (0..=1) into body 1, the rest into body 2.
    Fraction(f64),
    /// Blok's: equal mean surface temperatures over the contact.
    Blok,
}

impl Partition {
    /// The share of body 1, given both bodies' mean surface temperature rises over the contact
    /// under the whole flux (only Blok's partition reads them).
    pub fn body1_share(self, mean_body1_k: f64, mean_body2_k: f64) -> f64 {
        match self {
            Partition::Body1 => 1.0,
            Partition::Fraction(f) => f,
            Partition::Blok => mean_body2_k / (mean_body1_k + mean_body2_k),
        }
    }

    /// Whether body 2's temperature is needed.
    pub fn needs_body2(self) -> bool {
        !matches!(self, Partition::Body1)
    }
}

/// The frictional flux `q = μ p V` (W/m²) of a pressure (Pa) at sliding speed `V` (m/s).
pub fn frictional_flux(friction: f64, pressure_pa: f64, sliding_speed_m_per_s: f64) -> f64 {
    friction * pressure_pa.max(0.0) * sliding_speed_m_per_s
}

//! Frictional heating: the steady temperature rise of bodies heated by a flux that moves over
//! their surfaces (flash temperature), and the thermoelastic stress it causes.
//!
//! - [`material`]: conductivity, diffusivity, expansion; the materials library.
//! - [`temperature`]: the 3-D moving (or stationary) source over gridded cells, by DC-FFT.
//! - [`line`]: the 2-D moving band (line contacts), Jaeger's line source over strips.
//! - [`line_stress`]: the 2-D (plane-strain) thermal stress of a moving band over strips.
//! - [`stress`]: thermoelastic stress and surface displacement of the half-space, from the
//!   frequency-response functions, turned into influence coefficients.
//! - [`heating`]: the frictional flux and its partition between the bodies (Blok).
//!
//! Conventions: the contact moves over body 1 in +x (the direction of the traction `q`), so in
//! the frame of the contact body 1's material flows in -x: it enters at the leading edge
//! `x = +a`, leaves at the trailing edge `x = -a`, and carries the heat behind.
//!
//! Uses: [`crate::operator`] (FFT) and [`crate::contact`]'s materials.

pub mod distortion;
pub mod heating;
pub mod kernel;
pub mod line;
pub mod line_stress;
pub mod material;
pub mod special;
pub mod stress;
pub mod temperature;

#[cfg(test)]
mod tests;

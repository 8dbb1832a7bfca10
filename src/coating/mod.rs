//! Coated bodies: a layer of thickness `h` perfectly bonded to an elastic half-space (the
//! substrate), loaded on its free surface.
//!
//! A coated body is not Hertzian. Everything here follows from the response of the layered
//! half-space to one surface-traction wave ([`response`]): its surface compliance gives the
//! contact's influence coefficients ([`kernel`], for the DC-FFT contact solver of
//! [`crate::contact::rough`]), and its stresses at depth the six components in the coating and
//! in the substrate ([`stress`]). [`reference`] is an independent check: the axisymmetric
//! contact of a rigid sphere on a coated half-space by Hankel transforms and quadrature.
//!
//! Conventions as everywhere: `z >= 0` into the body, the interface at `z = h`; tension
//! positive, `σzz(x, 0) = -p`; the traction `q` acts in `+x` on the surface,
//! `τxz(x, 0) = -q`. Across the interface `σzz`, `σxz`, `σyz` and the displacements are
//! continuous; `σxx`, `σyy`, `σxy` jump with the moduli ([`response::Side`] says which side a
//! point on the interface belongs to).
//!
//! Uses nothing of the crate above `contact::material`, `operator` and `stress`.

pub mod axisymmetric;
pub mod kernel;
pub mod line;
pub mod line_reference;
pub mod reference;
pub mod response;
pub mod stress;

pub use response::{Interlayers, Layer, Layered, Side, MAX_LAYERS};

#[cfg(test)]
mod tests;

#[cfg(test)]
mod stack_tests;

//! Operators on gridded surfaces that the contact solver, the stress layers, the thermal
//! operators and the surface statistics share: the parallel 2-D real FFT ([`transform`]) and
//! the elastic half-space's surface displacement under cells of pressure ([`elastic`]), and
//! stacks of layers transformed in parallel ([`layers`], the volumes of plastic strain). Uses
//! nothing of the crate above it.

pub mod elastic;
pub mod layers;
pub mod transform;

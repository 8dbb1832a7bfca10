//! Elastic-plastic contact (issue 51): the residual stress and surface displacement of plastic
//! strains in an elastic half-space, J2 plasticity, and the semi-analytical loop of load steps.
//! Pure: no I/O; threads only through the shared transform driver.

pub mod anderson;
pub mod column;
pub mod halfspace;
pub mod j2;
pub mod line;
pub mod loading;

#[cfg(test)]
mod tests;

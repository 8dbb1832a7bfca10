//! Stress solutions: pure functions from a point (in units of the contact half-width) to a
//! stress tensor (in units of the peak pressure). No I/O, no threads.
//!
//! Uses: [`crate::contact`] (pressure shapes, partial slip), [`crate::operator`],
//! [`crate::stress`].

pub mod dcfft;
pub mod line_hertz;
pub mod line_numerical;
pub mod patch;
pub mod point_numerical;
pub mod sphere_hertz;
pub mod strip;

use std::sync::Arc;

use crate::stress::Stress;
use line_numerical::StripTractions;
use point_numerical::{NumericalError, PointTractions};

/// A stress solution that can be evaluated anywhere in the body `z >= 0`.
#[derive(Clone, Debug, PartialEq)]
pub enum Solution {
    /// Sliding Hertzian line contact, plane strain, closed form (McEwen 1949).
    LineHertz { friction: f64, poisson: f64 },
    /// Line contact by numerical integration: the tractions as uniform strips, summed with the
    /// strips' exact influence coefficients (plane strain).
    LineNumerical {
        tractions: Arc<StripTractions>,
        friction: f64,
        poisson: f64,
    },
    /// Sliding Hertzian point contact (sphere), closed form (Hamilton 1983, Huber 1904).
    SphereHertz { friction: f64, poisson: f64 },
    /// Point contact by numerical integration: tractions on a grid of uniform cells, summed
    /// with the cells' exact influence coefficients (directly at points, by DC-FFT on grids).
    PointNumerical {
        tractions: Arc<PointTractions>,
        friction: f64,
        poisson: f64,
    },
    /// Another solution with the contact's centre moved to `x = centre_x_over_a` on the
    /// surface: `σ(x, y, z) = σ_inner(x - centre, y, z)`. A moving load seen in a fixed body
    /// frame (evaluated point by point, never by DC-FFT layers).
    Moved {
        inner: Arc<Solution>,
        centre_x_over_a: f64,
    },
}

impl Solution {
    /// This solution with the contact centred at `x = centre_x_over_a` (itself at 0).
    pub fn moved_to(self, centre_x_over_a: f64) -> Self {
        if centre_x_over_a == 0.0 {
            return self;
        }
        match self {
            Solution::Moved {
                inner,
                centre_x_over_a: centre,
            } => Solution::Moved {
                inner,
                centre_x_over_a: centre + centre_x_over_a,
            },
            solution => Solution::Moved {
                inner: Arc::new(solution),
                centre_x_over_a,
            },
        }
    }

    /// The Hertz line contact integrated numerically over `strips` uniform strips.
    pub fn line_numerical(friction: f64, poisson: f64, strips: usize) -> Self {
        let tractions = Arc::new(StripTractions::hertz(strips, friction));
        Solution::LineNumerical {
            tractions,
            friction,
            poisson,
        }
    }

    /// The Hertz sphere integrated numerically over `cells x cells` cells on
    /// `[-extent, extent]²` (units of a).
    pub fn sphere_numerical(
        friction: f64,
        poisson: f64,
        cells: usize,
        extent: f64,
    ) -> Result<Self, NumericalError> {
        let tractions = Arc::new(PointTractions::hertz_sphere(
            cells, extent, friction, poisson,
        )?);
        Ok(Solution::PointNumerical {
            tractions,
            friction,
            poisson,
        })
    }

    /// Stress in units of `p0` at a point in units of `a` (`y` is ignored by line contacts).
    #[inline]
    pub fn stress_over_p0(&self, x_over_a: f64, y_over_a: f64, z_over_a: f64) -> Stress {
        match self {
            Solution::LineHertz { friction, poisson } => {
                line_hertz::stress_over_p0(x_over_a, z_over_a, *friction, *poisson)
            }
            Solution::LineNumerical {
                tractions, poisson, ..
            } => tractions.stress_over_p0(x_over_a, z_over_a, *poisson),
            Solution::SphereHertz { friction, poisson } => {
                sphere_hertz::stress_over_p0(x_over_a, y_over_a, z_over_a, *friction, *poisson)
            }
            Solution::PointNumerical { tractions, .. } => {
                tractions.stress_over_p0(x_over_a, y_over_a, z_over_a)
            }
            Solution::Moved {
                inner,
                centre_x_over_a,
            } => inner.stress_over_p0(x_over_a - centre_x_over_a, y_over_a, z_over_a),
        }
    }

    /// [`Self::stress_over_p0`] for a point a user asks about (`probe`): the same, except on
    /// the surface exactly on a strip or cell edge of a numerical solution, where the
    /// discretised tractions jump and the exact value is infinite or undefined: there the mean
    /// of the values at the neighbouring strip or cell centres (see
    /// [`StripTractions::finite_stress_over_p0`], [`PointTractions::finite_stress_over_p0`]).
    /// Grids keep the exact values (a figure leaves those few samples blank).
    pub fn finite_stress_over_p0(&self, x_over_a: f64, y_over_a: f64, z_over_a: f64) -> Stress {
        match self {
            Solution::LineNumerical {
                tractions, poisson, ..
            } => tractions.finite_stress_over_p0(x_over_a, z_over_a, *poisson),
            Solution::PointNumerical { tractions, .. } => {
                tractions.finite_stress_over_p0(x_over_a, y_over_a, z_over_a)
            }
            Solution::Moved {
                inner,
                centre_x_over_a,
            } => inner.finite_stress_over_p0(x_over_a - centre_x_over_a, y_over_a, z_over_a),
            Solution::LineHertz { .. } | Solution::SphereHertz { .. } => {
                self.stress_over_p0(x_over_a, y_over_a, z_over_a)
            }
        }
    }

    /// Stresses along a row of points `(xs[i], y, z)`, written into `out` (same length).
    ///
    /// The match on the solution is hoisted out of the loop so the loop body can vectorise.
    pub fn stress_row_over_p0(&self, xs: &[f64], y_over_a: f64, z_over_a: f64, out: &mut [Stress]) {
        match self {
            Solution::LineHertz { friction, poisson } => {
                for (stress, &x) in out.iter_mut().zip(xs) {
                    *stress = line_hertz::stress_over_p0(x, z_over_a, *friction, *poisson);
                }
            }
            Solution::LineNumerical {
                tractions, poisson, ..
            } => {
                for (stress, &x) in out.iter_mut().zip(xs) {
                    *stress = tractions.stress_over_p0(x, z_over_a, *poisson);
                }
            }
            Solution::SphereHertz { friction, poisson } => {
                for (stress, &x) in out.iter_mut().zip(xs) {
                    *stress =
                        sphere_hertz::stress_over_p0(x, y_over_a, z_over_a, *friction, *poisson);
                }
            }
            Solution::PointNumerical { tractions, .. } => {
                for (stress, &x) in out.iter_mut().zip(xs) {
                    *stress = tractions.stress_over_p0(x, y_over_a, z_over_a);
                }
            }
            Solution::Moved {
                inner,
                centre_x_over_a,
            } => {
                let shifted: Vec<f64> = xs.iter().map(|x| x - centre_x_over_a).collect();
                inner.stress_row_over_p0(&shifted, y_over_a, z_over_a, out);
            }
        }
    }

    /// Surface pressure and tangential traction in +x `(p/p0, q/p0)` at `(x, y)` on the
    /// surface (for the numerical solution, the discretised tractions; line contacts ignore y).
    pub fn surface_traction_over_p0(&self, x_over_a: f64, y_over_a: f64) -> (f64, f64) {
        match self {
            Solution::LineHertz { friction, .. } => {
                line_hertz::surface_traction_over_p0(x_over_a, *friction)
            }
            Solution::LineNumerical { tractions, .. } => tractions.at(x_over_a),
            Solution::SphereHertz { friction, .. } => {
                sphere_hertz::surface_traction_over_p0(x_over_a, y_over_a, *friction)
            }
            Solution::PointNumerical { tractions, .. } => tractions.traction_at(x_over_a, y_over_a),
            Solution::Moved {
                inner,
                centre_x_over_a,
            } => inner.surface_traction_over_p0(x_over_a - centre_x_over_a, y_over_a),
        }
    }

    /// Whether the field depends on y (a point contact), or not (plane strain).
    pub fn is_three_dimensional(&self) -> bool {
        match self {
            Solution::LineHertz { .. } | Solution::LineNumerical { .. } => false,
            Solution::SphereHertz { .. } | Solution::PointNumerical { .. } => true,
            Solution::Moved { inner, .. } => inner.is_three_dimensional(),
        }
    }

    pub fn friction(&self) -> f64 {
        match self {
            Solution::LineHertz { friction, .. }
            | Solution::LineNumerical { friction, .. }
            | Solution::SphereHertz { friction, .. }
            | Solution::PointNumerical { friction, .. } => *friction,
            Solution::Moved { inner, .. } => inner.friction(),
        }
    }

    pub fn poisson(&self) -> f64 {
        match self {
            Solution::LineHertz { poisson, .. }
            | Solution::LineNumerical { poisson, .. }
            | Solution::SphereHertz { poisson, .. }
            | Solution::PointNumerical { poisson, .. } => *poisson,
            Solution::Moved { inner, .. } => inner.poisson(),
        }
    }
}

//! What a rough scene computes: the contact problem on its surface, the solved pressure as
//! surface tractions (`q = μ p` in +x), and the stress solution under them.
//!
//! The traction grid is in the rough scenes' reference units ([`REFERENCE_LENGTH_M`],
//! [`REFERENCE_PRESSURE_PA`]: 1 um and 1 MPa), the `a` and `p0` of their `Contact::scale`.

use std::sync::Arc;

use crate::contact::rough::{self, RoughContactError, RoughContactProblem, RoughSolution};
use crate::operator::elastic::Periodicity;
use crate::scene::{ContactKind, Scene};
use crate::solution::dcfft::TractionGrid;
use crate::solution::point_numerical::{NumericalError, PointTractions};
use crate::solution::Solution;

/// The length unit of a rough scene's tractions and sections (its `a`), m.
pub const REFERENCE_LENGTH_M: f64 = 1e-6;
/// The pressure unit of a rough scene's tractions (its `p0`), Pa.
pub const REFERENCE_PRESSURE_PA: f64 = 1e6;

/// Why a rough scene cannot be studied.
#[derive(Debug, thiserror::Error)]
pub enum RoughStudyError {
    #[error("the scene is not a rough contact with its surface and materials")]
    NotRough,
    #[error(transparent)]
    Contact(#[from] RoughContactError),
    #[error(transparent)]
    Numerical(#[from] NumericalError),
}

/// The contact problem of a rough scene (`None` if it is not one).
pub fn problem(scene: &Scene) -> Option<RoughContactProblem<'_>> {
    let spec = scene.contact.rough?;
    let surface = scene.surface.as_ref()?;
    Some(RoughContactProblem {
        heights_m: surface.heights.heights_m().view(),
        spacing_m: surface.heights.spacing_m(),
        e_star_pa: spec.e_star_pa?,
        periodicity: if spec.periodic {
            Periodicity::Periodic
        } else {
            Periodicity::NonPeriodic
        },
        control: spec.control?,
        hardness_pa: spec.hardness_pa,
        tolerance: spec.tolerance,
        max_iterations: spec.max_iterations,
        memory_limit_bytes: crate::field::memory_limit_bytes(),
    })
}

/// Solves the scene's contact; `progress(iteration, residual)` after each iteration.
pub fn solve(
    scene: &Scene,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<RoughSolution, RoughStudyError> {
    if scene.contact.kind != ContactKind::Rough {
        return Err(RoughStudyError::NotRough);
    }
    let problem = problem(scene).ok_or(RoughStudyError::NotRough)?;
    Ok(rough::solve(&problem, progress)?)
}

/// The solved pressure and `q = friction p` (in +x) as a traction grid in the reference units,
/// cell `[0, 0]` at the origin.
pub fn traction_grid(
    solution: &RoughSolution,
    friction: f64,
) -> Result<TractionGrid, NumericalError> {
    let [dx, dy] = solution.spacing_m;
    let pressure = solution.pressure_pa.mapv(|p| p / REFERENCE_PRESSURE_PA);
    let shear = (friction > 0.0).then(|| pressure.mapv(|p| friction * p));
    Ok(TractionGrid::new(
        [0.0, 0.0],
        [dx / REFERENCE_LENGTH_M, dy / REFERENCE_LENGTH_M],
        Some(pressure),
        shear,
        None,
    )?)
}

/// The solved tractions with their DC-FFT, periodic when the contact is.
pub fn tractions(
    solution: &RoughSolution,
    friction: f64,
    poisson: f64,
) -> Result<PointTractions, NumericalError> {
    let grid = traction_grid(solution, friction)?;
    Ok(match solution.periodicity {
        Periodicity::Periodic => PointTractions::periodic(grid, poisson)?,
        Periodicity::NonPeriodic => PointTractions::new(grid, poisson)?,
    })
}

/// The stress solution under the solved tractions (DC-FFT on the surface's grid; a periodic
/// contact's tractions repeat, with their images, so the field is periodic too).
pub fn stress_solution(
    solution: &RoughSolution,
    friction: f64,
    poisson: f64,
) -> Result<Solution, NumericalError> {
    let tractions = tractions(solution, friction, poisson)?;
    Ok(Solution::PointNumerical {
        tractions: Arc::new(tractions),
        friction,
        poisson,
    })
}

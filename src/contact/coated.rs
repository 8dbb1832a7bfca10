//! The contact of a coated body: the pressure solved by the conjugate gradients of
//! [`crate::contact::rough`] on the gridded gap (a Hertz pair's paraboloid, or a rough
//! surface), with the layered influence coefficients of [`crate::coating::kernel`] in place of
//! Love's. The layered kernels are built once per solve (per scene).
//!
//! The problem's `e_star_pa` is the far field's, `1/E* = (1 - ν_s²)/E_s + (1 - ν2²)/E2` (the
//! substrate's and the counter-body's), which is what a coated body's compliance tends to at
//! long wavelengths; the solver takes it only for its checks.

use crate::coating::kernel::{kernel_grid, MIN_THICKNESS_CELLS};
use crate::coating::Layered;
use crate::contact::rough::{
    solve_cached, OperatorCache, RoughContactError, RoughContactProblem, RoughSolution, Warm,
};
use crate::operator::elastic::ElasticOperator;

/// Why a coated contact cannot be solved on this grid.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CoatedContactError {
    #[error("the coating ({thickness_m:.3e} m) is thinner than the grid resolves: it needs cells of at most {needed_m:.3e} m (half its thickness), got {cell_m:.3e} m")]
    TooThin {
        thickness_m: f64,
        cell_m: f64,
        needed_m: f64,
    },
    #[error(transparent)]
    Contact(#[from] RoughContactError),
}

/// The largest cell (m) a coating of `thickness_m` allows.
pub fn largest_cell_m(thickness_m: f64) -> f64 {
    thickness_m / MIN_THICKNESS_CELLS
}

/// Solves `problem` on a coated body 1 (`layered`) against a counter-body of compliance
/// `counter_per_pa` (`(1 - ν2²)/E2`, 0 when rigid). `progress(iteration, residual)` after every
/// iteration.
pub fn solve(
    problem: &RoughContactProblem,
    layered: &Layered,
    counter_per_pa: f64,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<RoughSolution, CoatedContactError> {
    let cell = problem.spacing_m[0].max(problem.spacing_m[1]);
    if cell > largest_cell_m(layered.thickness_m) * (1.0 + 1e-12) {
        return Err(CoatedContactError::TooThin {
            thickness_m: layered.thickness_m,
            cell_m: cell,
            needed_m: largest_cell_m(layered.thickness_m),
        });
    }
    let (ny, nx) = problem.heights_m.dim();
    let grid = kernel_grid(
        layered,
        counter_per_pa,
        [ny, nx],
        problem.spacing_m,
        problem.periodicity,
    )
    .map_err(RoughContactError::from)?;
    let operator = ElasticOperator::from_kernel([ny, nx], problem.periodicity, &grid)
        .map_err(RoughContactError::from)?;
    let mut cache = OperatorCache::holding(problem, operator);
    Ok(solve_cached(
        problem,
        &Warm::default(),
        &mut cache,
        progress,
    )?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coating::reference::rigid_sphere;
    use crate::coating::response::plane_strain_modulus;
    use crate::contact::material::Material;
    use crate::contact::rough::{self, Control};
    use crate::operator::elastic::Periodicity;
    use crate::study::coupled::paraboloid;

    /// A rigid sphere (R = 10 mm) on the coated half-space at the load the reference carries
    /// with radius `a`, on cells of `a / cells_per_a` over ±`extent` a.
    fn gridded(
        layered: &Layered,
        load: f64,
        a: f64,
        cells_per_a: f64,
        extent: f64,
    ) -> RoughSolution {
        let radius = 10e-3;
        let d = a / cells_per_a;
        let n = (2.0 * extent * cells_per_a).round() as usize;
        let origin = -0.5 * n as f64 * d + 0.5 * d;
        let heights = paraboloid([n, n], [d, d], [origin, origin], [0.5 / radius; 2]);
        let e_far = plane_strain_modulus(&layered.substrate);
        let problem = RoughContactProblem {
            heights_m: heights.view(),
            spacing_m: [d, d],
            e_star_pa: e_far,
            periodicity: Periodicity::NonPeriodic,
            control: Control::Load { newtons: load },
            hardness_pa: None,
            tolerance: 1e-10,
            max_iterations: rough::DEFAULT_MAX_ITERATIONS,
            memory_limit_bytes: 1 << 30,
        };
        solve(&problem, layered, 0.0, &mut |_, _| {}).expect("coated solve")
    }

    #[test]
    fn equal_materials_give_the_homogeneous_solve_exactly_enough() {
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let layered = Layered {
            coating: steel,
            substrate: steel,
            thickness_m: 20e-6,
        };
        let a: f64 = 100e-6;
        let e = plane_strain_modulus(&steel);
        let load = 4.0 * e * a.powi(3) / (3.0 * 10e-3);
        let coated = gridded(&layered, load, a, 12.0, 1.5);
        // The homogeneous operator on the same grid.
        let d = a / 12.0;
        let heights = paraboloid([36, 36], [d, d], [-17.5 * d; 2], [50.0; 2]);
        let problem = RoughContactProblem {
            heights_m: heights.view(),
            spacing_m: [d, d],
            e_star_pa: e,
            periodicity: Periodicity::NonPeriodic,
            control: Control::Load { newtons: load },
            hardness_pa: None,
            tolerance: 1e-10,
            max_iterations: rough::DEFAULT_MAX_ITERATIONS,
            memory_limit_bytes: 1 << 30,
        };
        let plain = rough::solve(&problem, &mut |_, _| {}).expect("solve");
        let p0 = 3.0 * load / (2.0 * std::f64::consts::PI * a * a);
        let worst = (&coated.pressure_pa - &plain.pressure_pa)
            .iter()
            .fold(0.0f64, |m, v| m.max(v.abs()))
            / p0;
        eprintln!(
            "measured: equal moduli, coated contact against the homogeneous solve: {worst:.1e} p0"
        );
        assert!(worst < 1e-8, "{worst}");
    }

    #[test]
    fn rigid_sphere_on_a_coated_half_space_agrees_with_the_hankel_reference() {
        // Ec/Es = 2 and 0.5 on steel (ν = 0.3 both), h/a = 0.1 to 2: peak pressure and
        // contact radius (sqrt(area/π)) of the DC-FFT solve against the axisymmetric reference
        // at the reference's load, both over the coating's Hertz values.
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let radius = 10e-3;
        let a: f64 = 100e-6;
        let mut worst_p: f64 = 0.0;
        let mut worst_a: f64 = 0.0;
        for ratio in [2.0, 0.5] {
            let coating = Material {
                modulus_pa: ratio * 210e9,
                poisson: 0.3,
            };
            for h_over_a in [0.1, 0.5, 2.0] {
                let layered = Layered {
                    coating,
                    substrate: steel,
                    thickness_m: h_over_a * a,
                };
                let reference = rigid_sphere(&layered, radius, a, 8);
                let e1 = plane_strain_modulus(&coating);
                let a_hertz = (3.0 * reference.load_n * radius / (4.0 * e1)).cbrt();
                let p_hertz =
                    3.0 * reference.load_n / (2.0 * std::f64::consts::PI * a_hertz * a_hertz);
                let cells_per_a = (2.0 / h_over_a).max(20.0);
                let solved = gridded(&layered, reference.load_n, a, cells_per_a, 1.5);
                let d = a / cells_per_a;
                let cells = solved.pressure_pa.iter().filter(|&&p| p > 0.0).count();
                let radius_solved = (cells as f64 * d * d / std::f64::consts::PI).sqrt();
                let (ep, ea) = (
                    solved.max_pressure_pa / reference.max_pressure_pa - 1.0,
                    radius_solved / a - 1.0,
                );
                eprintln!(
                    "measured: Ec/Es = {ratio}, h/a = {h_over_a}: reference p/p0c = {:.4}, a/ac = {:.4} (residual {:.1e}); DC-FFT p/p0c = {:.4}, a/ac = {:.4}: errors {:+.2} %, {:+.2} %",
                    reference.max_pressure_pa / p_hertz,
                    a / a_hertz,
                    reference.residual,
                    solved.max_pressure_pa / p_hertz,
                    radius_solved / a_hertz,
                    100.0 * ep,
                    100.0 * ea
                );
                worst_p = worst_p.max(ep.abs());
                worst_a = worst_a.max(ea.abs());
            }
        }
        assert!(worst_p < 0.01, "peak pressure {worst_p}");
        assert!(worst_a < 0.02, "contact radius {worst_a}");
    }

    #[test]
    fn a_thin_coating_gives_the_substrates_contact() {
        // The reference at h/a = 0.002 (Ec/Es = 2 and 0.5) against the substrate's Hertz
        // contact under the same load.
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let (radius, a) = (10e-3, 100e-6);
        for ratio in [2.0, 0.5] {
            let layered = Layered {
                coating: Material {
                    modulus_pa: ratio * 210e9,
                    poisson: 0.3,
                },
                substrate: steel,
                thickness_m: 0.002 * a,
            };
            let reference = rigid_sphere(&layered, radius, a, 6);
            let e2 = plane_strain_modulus(&steel);
            let a_sub = (3.0 * reference.load_n * radius / (4.0 * e2)).cbrt();
            let p_sub = 3.0 * reference.load_n / (2.0 * std::f64::consts::PI * a_sub * a_sub);
            let (ea, ep) = (a / a_sub - 1.0, reference.max_pressure_pa / p_sub - 1.0);
            eprintln!(
                "measured: h/a = 0.002, Ec/Es = {ratio}: against the substrate's Hertz contact, radius {:+.3} %, peak pressure {:+.3} %",
                100.0 * ea,
                100.0 * ep
            );
            assert!(ea.abs() < 0.005 && ep.abs() < 0.01, "{ea} {ep}");
        }
    }

    #[test]
    fn a_coating_thinner_than_two_cells_is_refused() {
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let layered = Layered {
            coating: steel,
            substrate: steel,
            thickness_m: 1e-6,
        };
        let heights = paraboloid([16, 16], [1e-6, 1e-6], [-7.5e-6; 2], [50.0; 2]);
        let problem = RoughContactProblem {
            heights_m: heights.view(),
            spacing_m: [1e-6, 1e-6],
            e_star_pa: 1e11,
            periodicity: Periodicity::NonPeriodic,
            control: Control::Load { newtons: 0.01 },
            hardness_pa: None,
            tolerance: 1e-8,
            max_iterations: 100,
            memory_limit_bytes: 1 << 30,
        };
        let error = solve(&problem, &layered, 0.0, &mut |_, _| {}).expect_err("too thin");
        assert!(
            matches!(error, CoatedContactError::TooThin { .. }),
            "{error}"
        );
    }
}

//! The contact of a coated body: the pressure solved by the conjugate gradients of
//! [`crate::contact::rough`] on the gridded gap (a Hertz pair's paraboloid, or a rough
//! surface), with the layered influence coefficients of [`crate::coating::kernel`] in place of
//! Love's. The layered kernels are built once per solve (per scene).
//!
//! The problem's `e_star_pa` is the far field's, `1/E* = (1 - ν_s²)/E_s + (1 - ν2²)/E2` (the
//! substrate's and the counter-body's), which is what a coated body's compliance tends to at
//! long wavelengths; the solver takes it only for its checks.
//!
//! A coated **line** contact (plane strain) is solved on a 1-D grid by [`solve_line`]: the
//! influence coefficients of [`crate::coating::line`] (strips of uniform pressure on the
//! layered half-plane) in a dense system over the cells in contact, and an active set
//! (Kalker's: drop the cells of negative pressure, add the cells the surfaces would
//! interpenetrate, solve again), which for the smooth convex gap of two cylinders ends in a
//! few iterations. The load per unit length closes the system; the approach it returns is
//! relative (a plane problem's displacements are defined up to a constant).
//!
//! ## Reference
//! J. J. Kalker, *Three-Dimensional Elastic Bodies in Rolling Contact*, Kluwer (1990), ch. 2
//! (the active-set contact algorithm on influence coefficients).

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
    #[error("the coated line contact reaches the edge of its grid (cell {cell} of {cells}): the contact must lie inside it\nhint: raise numerical.extent")]
    LineAtEdge { cell: usize, cells: usize },
    #[error("the coated line contact's active set did not settle in {iterations} iterations")]
    LineNotConverged { iterations: usize },
}

/// A solved coated line contact.
#[derive(Clone, Debug, PartialEq)]
pub struct LineSolution {
    /// Pressure at the cell centres, Pa.
    pub pressure_pa: Vec<f64>,
    pub max_pressure_pa: f64,
    /// The contact's edges, m: from the first and last loaded cells, where `p²` (linear in the
    /// distance from a smooth contact's edge, `p ∝ sqrt(b - |x|)`) extrapolated from the two
    /// outermost loaded cells vanishes, kept within the cell beyond them.
    pub edges_m: [f64; 2],
    /// Half the distance between the edges, m.
    pub half_width_m: f64,
    /// The approach, m, relative to the influence coefficients' arbitrary constant.
    pub relative_approach_m: f64,
    /// Active-set iterations.
    pub iterations: usize,
}

/// The most active-set iterations of [`solve_line`].
const LINE_ITERATIONS: usize = 200;

/// Solves `A x = b` (row-major `n x n`) by Gaussian elimination with partial pivoting.
fn solve_dense_row_major(mut a: Vec<f64>, mut b: Vec<f64>) -> Vec<f64> {
    let n = b.len();
    for column in 0..n {
        let pivot = (column..n)
            .max_by(|&x, &y| a[x * n + column].abs().total_cmp(&a[y * n + column].abs()))
            .unwrap_or(column);
        if pivot != column {
            for j in 0..n {
                a.swap(column * n + j, pivot * n + j);
            }
            b.swap(column, pivot);
        }
        let (head, tail) = a.split_at_mut((column + 1) * n);
        let pivot_row = &head[column * n..];
        let diagonal = pivot_row[column];
        for (offset, row) in tail.chunks_exact_mut(n).enumerate() {
            let factor = row[column] / diagonal;
            if factor != 0.0 {
                for (target, source) in row[column..].iter_mut().zip(&pivot_row[column..]) {
                    *target -= factor * source;
                }
                b[column + 1 + offset] -= factor * b[column];
            }
        }
    }
    let mut x = vec![0.0; n];
    for row in (0..n).rev() {
        let sum: f64 = (row + 1..n).map(|j| a[row * n + j] * x[j]).sum();
        x[row] = (b[row] - sum) / a[row * n + row];
    }
    x
}

/// Solves the line contact of a coated body 1 (`layered`) against a counter-body of compliance
/// `counter_per_pa` (0 when rigid): the initial separation `gap_m` at the centres of cells
/// `spacing_m` wide starting at `origin_m` (the centre of the first), pressed together by
/// `load_n_per_m` (module doc).
pub fn solve_line(
    layered: &Layered,
    counter_per_pa: f64,
    gap_m: &[f64],
    spacing_m: f64,
    origin_m: f64,
    load_n_per_m: f64,
) -> Result<LineSolution, CoatedContactError> {
    let cells = gap_m.len();
    if spacing_m > largest_cell_m(layered.thickness_m) * (1.0 + 1e-12) {
        return Err(CoatedContactError::TooThin {
            thickness_m: layered.thickness_m,
            cell_m: spacing_m,
            needed_m: largest_cell_m(layered.thickness_m),
        });
    }
    if cells < 8 || load_n_per_m.is_nan() || load_n_per_m <= 0.0 {
        return Err(CoatedContactError::Contact(RoughContactError::Parameter {
            name: "the load per unit length",
            requirement: "must be positive on at least 8 cells",
            value: load_n_per_m,
        }));
    }
    let kernel = crate::coating::line::line_kernel(layered, counter_per_pa, cells, spacing_m)
        .map_err(RoughContactError::from)?;
    let (lowest, highest) = gap_m
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &g| {
            (l.min(g), h.max(g))
        });
    let span = (highest - lowest).max(f64::MIN_POSITIVE);
    let mut active: Vec<bool> = gap_m.iter().map(|&g| g <= lowest + 0.25 * span).collect();
    let scale = kernel[0];
    let tolerance = 1e-12 * span;
    for iteration in 1..=LINE_ITERATIONS {
        let set: Vec<usize> = (0..cells).filter(|&i| active[i]).collect();
        let n = set.len() + 1;
        let mut matrix = vec![0.0; n * n];
        let mut rhs = vec![0.0; n];
        for (r, &i) in set.iter().enumerate() {
            for (c, &j) in set.iter().enumerate() {
                matrix[r * n + c] = kernel[i.abs_diff(j)];
            }
            // The approach, in units of `scale` Pa.
            matrix[r * n + n - 1] = -scale;
            rhs[r] = -gap_m[i];
        }
        for c in 0..set.len() {
            matrix[(n - 1) * n + c] = scale;
        }
        rhs[n - 1] = scale * load_n_per_m / spacing_m;
        let x = solve_dense_row_major(matrix, rhs);
        let mut pressure = vec![0.0; cells];
        for (r, &i) in set.iter().enumerate() {
            pressure[i] = x[r];
        }
        let approach = x[n - 1] * scale;
        let mut changed = false;
        for &i in &set {
            if pressure[i] < 0.0 {
                active[i] = false;
                changed = true;
            }
        }
        if !changed {
            let outside: Vec<usize> = (0..cells).filter(|&i| !active[i]).collect();
            for i in outside {
                let displacement: f64 = set
                    .iter()
                    .map(|&j| kernel[i.abs_diff(j)] * pressure[j])
                    .sum();
                if gap_m[i] + displacement - approach < -tolerance {
                    active[i] = true;
                    changed = true;
                }
            }
        }
        if changed {
            continue;
        }
        let first = set.first().copied().unwrap_or(0);
        let last = set.last().copied().unwrap_or(0);
        if set.is_empty() || first == 0 || last == cells - 1 {
            return Err(CoatedContactError::LineAtEdge {
                cell: if first == 0 { 0 } else { last },
                cells,
            });
        }
        let x_of = |i: usize| origin_m + i as f64 * spacing_m;
        // p² linear towards the edge (doc of `edges_m`).
        let edge = |outer: usize, inner: usize, outward: f64| {
            let (p_outer, p_inner) = (pressure[outer].powi(2), pressure[inner].powi(2));
            let step = if p_inner > p_outer {
                (spacing_m * p_outer / (p_inner - p_outer)).min(spacing_m)
            } else {
                0.5 * spacing_m
            };
            x_of(outer) + outward * step
        };
        let left = if last > first {
            edge(first, first + 1, -1.0)
        } else {
            x_of(first) - 0.5 * spacing_m
        };
        let right = if last > first {
            edge(last, last - 1, 1.0)
        } else {
            x_of(last) + 0.5 * spacing_m
        };
        return Ok(LineSolution {
            max_pressure_pa: pressure.iter().copied().fold(0.0, f64::max),
            pressure_pa: pressure,
            edges_m: [left, right],
            half_width_m: 0.5 * (right - left),
            relative_approach_m: approach,
            iterations: iteration,
        });
    }
    Err(CoatedContactError::LineNotConverged {
        iterations: LINE_ITERATIONS,
    })
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
    let mut cache = operator_cache(problem, layered, counter_per_pa)?;
    Ok(solve_cached(
        problem,
        &Warm::default(),
        &mut cache,
        progress,
    )?)
}

/// The layered operator of `problem`'s grid, spacing and periodicity (built once; the solves
/// of problems on the same grid, e.g. at other loads, reuse it through
/// [`crate::contact::rough::solve_cached`]), refused on cells coarser than half the
/// coating's thickness.
pub fn operator_cache(
    problem: &RoughContactProblem,
    layered: &Layered,
    counter_per_pa: f64,
) -> Result<OperatorCache, CoatedContactError> {
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
    Ok(OperatorCache::holding(problem, operator))
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
            under: crate::coating::Interlayers::NONE,
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
                    under: crate::coating::Interlayers::NONE,
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
                under: crate::coating::Interlayers::NONE,
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

    /// A steel ball (R = 6.35 mm, 210 GPa, ν = 0.3) pressed with `load` on `layered`, on
    /// `cells`² cells over ±1.5 radii of the coating's own Hertz contact (of `material`'s in
    /// [`ball_over_hertz`]): the solved
    /// `(approach, peak pressure, sqrt(area/π))` over the coating's Hertz values.
    fn ball_over_coatings_hertz(layered: &Layered, load: f64, cells: usize) -> [f64; 3] {
        ball_over_hertz(layered, &layered.coating, load, cells)
    }

    /// As [`ball_over_coatings_hertz`], over the substrate's Hertz contact.
    fn ball_over_substrates_hertz(layered: &Layered, load: f64, cells: usize) -> [f64; 3] {
        ball_over_hertz(layered, &layered.substrate, load, cells)
    }

    fn ball_over_hertz(
        layered: &Layered,
        material: &Material,
        load: f64,
        cells: usize,
    ) -> [f64; 3] {
        let radius = 6.35e-3;
        let counter = (1.0 - 0.09) / 210e9;
        let e_star = 1.0 / (1.0 / plane_strain_modulus(material) + counter);
        let a = (3.0 * load * radius / (4.0 * e_star)).cbrt();
        let p0 = 3.0 * load / (2.0 * std::f64::consts::PI * a * a);
        let approach = a * a / radius;
        let d = 3.0 * a / cells as f64;
        let origin = -0.5 * cells as f64 * d + 0.5 * d;
        let heights = paraboloid([cells, cells], [d, d], [origin, origin], [0.5 / radius; 2]);
        let problem = RoughContactProblem {
            heights_m: heights.view(),
            spacing_m: [d, d],
            e_star_pa: e_star,
            periodicity: Periodicity::NonPeriodic,
            control: Control::Load { newtons: load },
            hardness_pa: None,
            tolerance: 1e-10,
            max_iterations: rough::DEFAULT_MAX_ITERATIONS,
            memory_limit_bytes: 1 << 30,
        };
        let solved = solve(&problem, layered, counter, &mut |_, _| {}).expect("coated solve");
        let cells_in = solved.pressure_pa.iter().filter(|&&p| p > 0.0).count();
        let radius_solved = (cells_in as f64 * d * d / std::f64::consts::PI).sqrt();
        [
            solved.approach_m / approach,
            solved.max_pressure_pa / p0,
            radius_solved / a,
        ]
    }

    #[test]
    fn a_very_thick_coating_gives_the_coatings_own_hertz_contact() {
        // Issue 50: 10 mm of TiN (600 GPa, ν = 0.25) on steel and a PEEK liner (3.6 GPa,
        // ν = 0.4) 100 mm thick under a steel ball, 5 N (contact radii 52 µm and 0.17 mm): the
        // approach, peak pressure and contact radius against the coating's own Hertz contact,
        // beside the same grid with the coating's material throughout (the grid's own error).
        // The substrate moves the approach by about W (1/E2' - 1/E1') / (π h), 0.1 % and
        // -0.07 % here (measured +0.11 % and -0.11 %). Before the layered kernel's low wavenumbers were transformed
        // radially (`coating::kernel`), the approach was 33 % too large and negative.
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let mut worst: f64 = 0.0;
        for (coating, thickness) in [((600e9, 0.25), 10e-3), ((3.6e9, 0.4), 100e-3)] {
            let coating = Material {
                modulus_pa: coating.0,
                poisson: coating.1,
            };
            let layered = Layered {
                coating,
                substrate: steel,
                thickness_m: thickness,
                under: crate::coating::Interlayers::NONE,
            };
            let alone = Layered {
                substrate: coating,
                ..layered
            };
            let got = ball_over_coatings_hertz(&layered, 5.0, 48);
            let grid = ball_over_coatings_hertz(&alone, 5.0, 48);
            eprintln!(
                "measured: E1 = {:.1} GPa, h = {thickness} m on steel, over the coating's Hertz contact: approach {:.4}, peak pressure {:.4}, radius {:.4} (the coating's material throughout on the same grid: {:.4}, {:.4}, {:.4})",
                coating.modulus_pa / 1e9,
                got[0],
                got[1],
                got[2],
                grid[0],
                grid[1],
                grid[2]
            );
            for (g, h) in got.iter().zip(&grid) {
                assert!(g.is_finite(), "{got:?}");
                worst = worst.max((g / h - 1.0).abs());
            }
            assert!((got[0] - 1.0).abs() < 0.01, "approach {}", got[0]);
        }
        assert!(worst < 0.002, "{worst}");
    }

    #[test]
    fn a_thinning_coating_tends_to_the_substrates_hertz_contact() {
        // Ec/Es = 2 and 0.5 on steel (ν = 0.3 both) under a steel ball, 5 N, h = 0.3, 0.15
        // and 0.075 of the substrate's Hertz radius on the same grid (84² cells over ±1.5
        // radii: the thinnest coating 2.1 cells): the approach, peak pressure and radius over
        // the substrate's Hertz values, each against the grid's own (the substrate's material
        // throughout). The coating's share falls in proportion to h: halving h halves the
        // largest (measured ratios 0.50 to 0.62; the radius counts whole cells), 2.4 % at
        // h = 0.075a (Ec/Es = 0.5, the radius; the approach 1.1 %).
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let load = 5.0;
        let radius = 6.35e-3;
        let counter = (1.0 - 0.09) / 210e9;
        let e_star = 1.0 / (1.0 / plane_strain_modulus(&steel) + counter);
        let a = (3.0 * load * radius / (4.0 * e_star)).cbrt();
        let cells = 84;
        let alone = Layered {
            coating: steel,
            substrate: steel,
            thickness_m: a,
            under: crate::coating::Interlayers::NONE,
        };
        let grid = ball_over_coatings_hertz(&alone, load, cells);
        for ratio in [2.0, 0.5] {
            let mut previous: Option<f64> = None;
            for h_over_a in [0.3, 0.15, 0.075] {
                let layered = Layered {
                    coating: Material {
                        modulus_pa: ratio * 210e9,
                        poisson: 0.3,
                    },
                    substrate: steel,
                    thickness_m: h_over_a * a,
                    under: crate::coating::Interlayers::NONE,
                };
                let got = ball_over_substrates_hertz(&layered, load, cells);
                let shares: Vec<f64> = got.iter().zip(&grid).map(|(g, h)| g / h - 1.0).collect();
                let largest = shares.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                eprintln!(
                    "measured: Ec/Es = {ratio}, h = {h_over_a} a: against the substrate's Hertz contact on the same grid, approach {:+.2} %, peak pressure {:+.2} %, radius {:+.2} %",
                    100.0 * shares[0],
                    100.0 * shares[1],
                    100.0 * shares[2]
                );
                if let Some(before) = previous {
                    let halved = largest / before;
                    assert!((0.4..0.65).contains(&halved), "{halved}");
                }
                previous = Some(largest);
            }
            assert!(previous.is_some_and(|p| p < 0.03), "{previous:?}");
        }
    }

    /// A cylinder (R = 10 mm) of compliance `counter` on the coated half-plane under `load`
    /// (N/m), on cells of `spacing` over ±`extent_m`.
    fn line_gridded(
        layered: &Layered,
        counter: f64,
        load: f64,
        spacing: f64,
        extent_m: f64,
    ) -> (LineSolution, Vec<f64>) {
        let radius = 10e-3;
        let n = (2.0 * extent_m / spacing).round() as usize;
        let origin = -0.5 * (n as f64 - 1.0) * spacing;
        let x: Vec<f64> = (0..n).map(|i| origin + i as f64 * spacing).collect();
        let gap: Vec<f64> = x.iter().map(|x| x * x / (2.0 * radius)).collect();
        let solved = solve_line(layered, counter, &gap, spacing, origin, load).expect("line solve");
        (solved, x)
    }

    #[test]
    fn equal_moduli_line_contact_gives_hertz() {
        // Johnson §4.2: b = sqrt(4WR/(πE*)), p = p0 sqrt(1 - x²/b²), p0 = 2W/(πb).
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let layered = Layered {
            coating: steel,
            substrate: steel,
            thickness_m: 20e-6,
            under: crate::coating::Interlayers::NONE,
        };
        let counter = 0.91 / 210e9;
        let e_star = 210e9 / (2.0 * 0.91);
        let b: f64 = 100e-6;
        let load = std::f64::consts::PI * e_star * b * b / (4.0 * 10e-3);
        let p0 = 2.0 * load / (std::f64::consts::PI * b);
        let (solved, x) = line_gridded(&layered, counter, load, b / 50.0, 1.5 * b);
        let profile = x
            .iter()
            .zip(&solved.pressure_pa)
            .map(|(x, p)| (p - p0 * (1.0 - (x / b).powi(2)).max(0.0).sqrt()).abs())
            .fold(0.0, f64::max)
            / p0;
        let (ep, eb) = (
            solved.max_pressure_pa / p0 - 1.0,
            solved.half_width_m / b - 1.0,
        );
        eprintln!("measured: equal moduli line contact (b/50 cells) against Hertz: peak pressure {:+.3} %, half-width {:+.3} %, profile {profile:.1e} p0 ({} iterations)", 100.0 * ep, 100.0 * eb, solved.iterations);
        assert!(
            ep.abs() < 2e-3 && eb.abs() < 5e-3 && profile < 2e-2,
            "{ep} {eb} {profile}"
        );
    }

    #[test]
    fn coated_line_contact_agrees_with_the_fourier_reference() {
        // Ec/Es = 2 and 0.5 on steel, h/b = 0.1, 0.5, 2, a rigid cylinder: peak pressure,
        // half-width and the pressure profile of the 1-D solve against the plane-strain
        // reference at the reference's load.
        use crate::coating::line_reference::cylinder;
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let (radius, b) = (10e-3, 100e-6);
        let (mut worst_p, mut worst_b, mut worst_profile) = (0.0f64, 0.0f64, 0.0f64);
        for ratio in [2.0, 0.5] {
            let coating = Material {
                modulus_pa: ratio * 210e9,
                poisson: 0.3,
            };
            for h_over_b in [0.1, 0.5, 2.0] {
                let layered = Layered {
                    coating,
                    substrate: steel,
                    thickness_m: h_over_b * b,
                    under: crate::coating::Interlayers::NONE,
                };
                let reference = cylinder(&layered, 0.0, radius, b, 8);
                let e1 = plane_strain_modulus(&coating);
                let b_hertz =
                    (4.0 * reference.load_n_per_m * radius / (std::f64::consts::PI * e1)).sqrt();
                let p_hertz = 2.0 * reference.load_n_per_m / (std::f64::consts::PI * b_hertz);
                let spacing = b / (2.0 / h_over_b).max(50.0);
                let (solved, x) =
                    line_gridded(&layered, 0.0, reference.load_n_per_m, spacing, 1.5 * b);
                let profile = x
                    .iter()
                    .zip(&solved.pressure_pa)
                    .map(|(x, p)| (p - reference.pressure_pa(*x)).abs())
                    .fold(0.0, f64::max)
                    / reference.max_pressure_pa;
                let (ep, eb) = (
                    solved.max_pressure_pa / reference.max_pressure_pa - 1.0,
                    solved.half_width_m / b - 1.0,
                );
                eprintln!(
                    "measured: line, Ec/Es = {ratio}, h/b = {h_over_b}: reference p/p0c = {:.4}, b/bc = {:.4} (residual {:.1e}); 1-D solve errors: peak {:+.3} %, half-width {:+.3} %, profile {profile:.1e} p",
                    reference.max_pressure_pa / p_hertz,
                    b / b_hertz,
                    reference.residual,
                    100.0 * ep,
                    100.0 * eb
                );
                worst_p = worst_p.max(ep.abs());
                worst_b = worst_b.max(eb.abs());
                worst_profile = worst_profile.max(profile);
            }
        }
        assert!(worst_p < 3e-3, "peak pressure {worst_p}");
        assert!(worst_b < 5e-3, "half-width {worst_b}");
        assert!(worst_profile < 2e-2, "profile {worst_profile}");
    }

    #[test]
    fn coated_line_contact_limits_are_the_coatings_and_the_substrates_hertz() {
        // h = 20 b: the coating's Hertz line contact (1-D solve); h/b = 0.002: the substrate's
        // (reference, the grid would need 1000 cells per b).
        use crate::coating::line_reference::cylinder;
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let radius = 10e-3;
        for ratio in [2.0, 0.5] {
            let coating = Material {
                modulus_pa: ratio * 210e9,
                poisson: 0.3,
            };
            let e1 = plane_strain_modulus(&coating);
            let b: f64 = 100e-6;
            let load = std::f64::consts::PI * e1 * b * b / (4.0 * radius);
            let thick = Layered {
                coating,
                substrate: steel,
                thickness_m: 20.0 * b,
                under: crate::coating::Interlayers::NONE,
            };
            let (solved, _) = line_gridded(&thick, 0.0, load, b / 50.0, 1.5 * b);
            let p0 = 2.0 * load / (std::f64::consts::PI * b);
            let (ep, eb) = (
                solved.max_pressure_pa / p0 - 1.0,
                solved.half_width_m / b - 1.0,
            );
            let thin = Layered {
                coating,
                substrate: steel,
                thickness_m: 0.002 * b,
                under: crate::coating::Interlayers::NONE,
            };
            let reference = cylinder(&thin, 0.0, radius, b, 6);
            let e2 = plane_strain_modulus(&steel);
            let b_sub =
                (4.0 * reference.load_n_per_m * radius / (std::f64::consts::PI * e2)).sqrt();
            let p_sub = 2.0 * reference.load_n_per_m / (std::f64::consts::PI * b_sub);
            let (tp, tb) = (reference.max_pressure_pa / p_sub - 1.0, b / b_sub - 1.0);
            eprintln!("measured: line, Ec/Es = {ratio}: h = 20b against the coating's Hertz: peak {:+.3} %, half-width {:+.3} %; h/b = 0.002 against the substrate's: peak {:+.3} %, half-width {:+.3} %", 100.0 * ep, 100.0 * eb, 100.0 * tp, 100.0 * tb);
            assert!(ep.abs() < 3e-3 && eb.abs() < 5e-3, "{ep} {eb}");
            assert!(tp.abs() < 5e-3 && tb.abs() < 5e-3, "{tp} {tb}");
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
            under: crate::coating::Interlayers::NONE,
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

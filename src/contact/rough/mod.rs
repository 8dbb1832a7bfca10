//! Rough contact: the pressure between a rough surface and a flat (or two rough surfaces),
//! solved on the grid of the heights by the conjugate-gradient method of Polonsky & Keer
//! (1999), with the elastic integral operator of [`crate::operator::elastic`] (non-periodic
//! DC-FFT or periodic).
//!
//! ## The problem
//! Heights `h` (m) point out of body 1 towards the counter-surface; for two rough bodies `h`
//! is the sum of both maps, acting on an equivalent body of combined modulus `E*`. The
//! separation of the undeformed surfaces when the highest point touches is `s = max h - h`.
//! Pressed together by the rigid approach `δ`, the surfaces open a gap
//! `g = s - δ + u(p)` with `u = K * p` the combined normal displacement. The solution has
//! `p >= 0`, `g >= 0` and `p g = 0` everywhere, and either its load `Σ p dx dy` or its
//! approach `δ` is given. With a hardness `H` the pressure is capped at `H` (perfectly
//! plastic asperities): cells at the cap may penetrate (the plastic flow absorbs it).
//!
//! ## The iteration (Polonsky & Keer 1999)
//! Load control: on the set `S` of loaded cells the gap's mean over `S` is the approach
//! (`g` is measured from it, so that it has zero mean over `S`), a conjugate direction `t` of
//! the gap on `S` and its response `r = K t` (also centred on `S`) give the step
//! `τ = Σ g t / Σ r t`; `p -= τ t` on `S`, negative pressures become zero, cells outside `S`
//! that penetrate (`g < 0`) are loaded by `-τ g` and restart the conjugation, and the pressure
//! is scaled to the load. Approach control: the same without centring and without scaling,
//! with `g = s - δ + u`.
//!
//! ## Convergence
//! After each iteration two relative measures are formed: the change of pressure
//! `Σ |p_k - p_(k-1)| / Σ p_k`, and the complementarity `Σ p |g| / (Σ p · Sq(s))` (the gap left
//! where pressure acts, relative to the rms of the separation). The solution has converged
//! when both are below the tolerance (default 1e-8); the residual reported is the larger.
//! Reaching the iteration cap first is an error that gives the residual reached.
//!
//! ## References
//! - I. A. Polonsky, L. M. Keer, A numerical method for solving rough contact problems based
//!   on the multi-level multi-summation and conjugate gradient techniques, *Wear* 231 (1999)
//!   206–219.
//! - V. Rey, G. Anciaux, J.-F. Molinari, Normal adhesive contact on rough surfaces: efficient
//!   algorithm for FFT-based BEM resolution, *Comput. Mech.* 60 (2017) 69–81 (the same
//!   iteration with FFT, as Tamaas implements it).

use std::ops::ControlFlow;

use ndarray::{Array2, ArrayView2, Zip};

use crate::operator::elastic::{ElasticOperator, Periodicity};
use crate::operator::transform::TransformError;

mod iteration;
mod load_search;

use iteration::{iterate, scale_to_mean, sum_active, Compliance, Settings, State, Target};

/// What fixes the solution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Control {
    /// The total normal load, N.
    Load { newtons: f64 },
    /// The load over the nominal area of the grid, Pa.
    MeanPressure { pa: f64 },
    /// The rigid-body approach from first contact, m (see [`RoughSolution::approach_m`]).
    Approach { m: f64 },
}

/// A rough contact problem on a grid.
#[derive(Clone, Debug)]
pub struct RoughContactProblem<'a> {
    /// Combined heights (m), `[ny, nx]`, row = y, out of body 1.
    pub heights_m: ArrayView2<'a, f64>,
    /// `[dx, dy]`, m.
    pub spacing_m: [f64; 2],
    /// Combined modulus `E*`, Pa.
    pub e_star_pa: f64,
    pub periodicity: Periodicity,
    pub control: Control,
    /// Pressure cap (perfect plasticity), Pa.
    pub hardness_pa: Option<f64>,
    /// Relative tolerance of both convergence measures.
    pub tolerance: f64,
    pub max_iterations: usize,
    /// The most memory the solve may take (estimated before anything is allocated).
    pub memory_limit_bytes: usize,
}

/// Default relative tolerance.
pub const DEFAULT_TOLERANCE: f64 = 1e-8;
/// Periodic and elastic, an approach within this fraction of the mean separation (or beyond
/// it) closes the gap everywhere: the mean gap is the mean separation less the approach, and
/// as it vanishes the pressure needed grows without bound (at it, any uniform pressure added
/// satisfies the contact conditions).
pub const FULL_CONTACT_MARGIN: f64 = 1e-6;

/// Default cap on iterations.
pub const DEFAULT_MAX_ITERATIONS: usize = 5000;

/// Why a rough contact has no solution here.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RoughContactError {
    #[error("{name} {requirement}, got {}", crate::io::text::number(*.value))]
    Parameter {
        name: &'static str,
        requirement: &'static str,
        value: f64,
    },
    #[error("the height at row {row}, column {column} is not finite ({value})")]
    NotFinite {
        row: usize,
        column: usize,
        value: f64,
    },
    #[error("a rough contact needs at least 2 x 2 cells, got {0} x {1}")]
    TooSmall(usize, usize),
    #[error("the surfaces are in contact everywhere (full contact): {what}; the gap is closed, so rough contact theory has nothing to solve")]
    FullContact { what: String },
    #[error("the solution did not converge in {iterations} iterations: residual {residual:.3e} > tolerance {tolerance:.1e}")]
    NotConverged {
        iterations: usize,
        residual: f64,
        tolerance: f64,
    },
    #[error("the pressure reaches the edge of the domain (row {row}, column {column}): an isolated contact must lie inside its grid; enlarge the domain (or solve it as a periodic surface)")]
    PressureAtEdge { row: usize, column: usize },
    #[error(
        "a {ny} x {nx} contact needs about {needed_mib} MiB, more than the {limit_mib} MiB allowed"
    )]
    TooLarge {
        ny: usize,
        nx: usize,
        needed_mib: usize,
        limit_mib: usize,
    },
    #[error("the load exceeds what the fully plastic surface can carry: a mean pressure of {mean_pa:.4e} Pa over the nominal area, while the hardness caps every cell at {hardness_pa:.4e} Pa; lower the load (contact.load or contact.mean_pressure) or check the hardness (contact.hardness)")]
    HardnessTooLow { hardness_pa: f64, mean_pa: f64 },
    #[error("the approach {approach_m:.4e} m does not bring the surfaces into contact: it must be positive")]
    NoContact { approach_m: f64 },
    /// The caller's progress asked to stop before the solution converged
    /// ([`solve_interruptible`]): there is no solution, only how far the solve got.
    #[error("the solve was interrupted after {iterations} iterations (residual {residual:.3e}, not converged): no solution")]
    Interrupted { iterations: usize, residual: f64 },
    #[error(transparent)]
    Transform(#[from] TransformError),
}

/// The solved contact.
#[derive(Clone, Debug, PartialEq)]
pub struct RoughSolution {
    /// Contact pressure, Pa, `[ny, nx]`.
    pub pressure_pa: Array2<f64>,
    /// Gap `s - δ + u` (m), zero in contact.
    pub gap_m: Array2<f64>,
    pub spacing_m: [f64; 2],
    pub periodicity: Periodicity,
    /// Rigid-body approach from first contact (m). Non-periodic: the displacement of the far
    /// field of one body relative to the other. Periodic: relative to the mean plane of the
    /// deformed surface (the operator's mean displacement is zero).
    pub approach_m: f64,
    /// `Σ p dx dy`, N.
    pub load_n: f64,
    /// Load over the nominal area `nx dx ny dy`, Pa.
    pub mean_pressure_pa: f64,
    pub max_pressure_pa: f64,
    /// Cells with `p > 0` over all cells.
    pub contact_fraction: f64,
    /// Connected contact spots (4-connected cells; across the period's edges when periodic).
    pub spots: usize,
    /// Cells of the largest spot.
    pub largest_spot_cells: usize,
    /// Cells at the hardness cap.
    pub plastic_cells: usize,
    /// The penetration (m, positive) of each cell at the hardness cap that penetrates, by
    /// `[row, column]`: the plastic flow the cap absorbs there (empty without a hardness).
    pub plastic_penetration_m: Vec<([usize; 2], f64)>,
    /// Mean of the gap over the grid, m.
    pub mean_gap_m: f64,
    pub iterations: usize,
    /// The larger of the two convergence measures at the end.
    pub residual: f64,
}

impl RoughContactProblem<'_> {
    /// Bytes a solve of this size takes (the operator and seven grids).
    pub fn memory_bytes(shape: [usize; 2], periodicity: Periodicity) -> usize {
        ElasticOperator::memory_bytes(shape, periodicity) + 7 * 8 * shape[0] * shape[1]
    }
}

fn parameter(name: &'static str, requirement: &'static str, value: f64) -> RoughContactError {
    RoughContactError::Parameter {
        name,
        requirement,
        value,
    }
}

/// What a solve may start from and add beyond the problem: a pressure to start from (a warm
/// start, e.g. the solution of a neighbouring problem), and a local compliance added to the
/// elastic one (the wear of a backward-Euler step, [`crate::wear`]).
#[derive(Clone, Debug, Default)]
pub struct Warm<'a> {
    /// The starting pressure (Pa, the heights' shape): clipped to `[0, H]`, and under a given
    /// load scaled to carry it. `None`: the mean pressure everywhere (or, under a given
    /// approach, each cell pressed by its own interference).
    pub pressure_pa: Option<ArrayView2<'a, f64>>,
    /// `c` (m/Pa): every cell's displacement grows by `c p` besides the elastic `K p`. Zero
    /// leaves the problem as it is.
    pub local_compliance_m_per_pa: f64,
}

/// Solves the problem. `progress(iteration, residual)` is called after every iteration.
pub fn solve(
    problem: &RoughContactProblem,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<RoughSolution, RoughContactError> {
    solve_warm(problem, &Warm::default(), progress)
}

/// Solves the problem from `warm`'s pressure with its local compliance added ([`Warm`]);
/// with [`Warm::default`] this is [`solve`], bit for bit.
pub fn solve_warm(
    problem: &RoughContactProblem,
    warm: &Warm,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<RoughSolution, RoughContactError> {
    solve_cached(problem, warm, &mut OperatorCache::default(), progress)
}

/// The elastic operator of one grid kept from solve to solve (the steps of a wear evolution):
/// built by the first solve, reused while the grid, spacing, `E*` and periodicity agree (the
/// same operator, so the same results bit for bit; its spectra cost about a quarter of a
/// warm-started solve).
#[derive(Default)]
pub struct OperatorCache {
    kept: Option<(ElasticOperator, OperatorKey)>,
}

/// What an elastic operator is built for: the grid's shape, its spacing (m), `E*` (Pa) and
/// the periodicity.
type OperatorKey = ([usize; 2], [f64; 2], f64, Periodicity);

impl OperatorCache {
    /// A cache holding `operator` for `problem`'s grid, spacing, `E*` and periodicity: the
    /// solves of `problem` use it instead of Love's (a coated body's operator,
    /// [`crate::coating::kernel`]; `E*` then names the one the problem states).
    pub fn holding(problem: &RoughContactProblem, operator: ElasticOperator) -> Self {
        let (ny, nx) = problem.heights_m.dim();
        let key = (
            [ny, nx],
            problem.spacing_m,
            problem.e_star_pa,
            problem.periodicity,
        );
        Self {
            kept: Some((operator, key)),
        }
    }

    /// The operator of `problem`'s grid: the kept one, or a new one, kept.
    fn operator(
        &mut self,
        problem: &RoughContactProblem,
    ) -> Result<&mut ElasticOperator, RoughContactError> {
        let (ny, nx) = problem.heights_m.dim();
        let key = (
            [ny, nx],
            problem.spacing_m,
            problem.e_star_pa,
            problem.periodicity,
        );
        let kept = match self.kept.take() {
            Some(kept) if kept.1 == key => kept,
            _ => (ElasticOperator::new(key.0, key.1, key.2, key.3)?, key),
        };
        Ok(&mut self.kept.insert(kept).0)
    }
}

/// [`solve_warm`] with the elastic operator taken from (or put into) `cache`.
pub fn solve_cached(
    problem: &RoughContactProblem,
    warm: &Warm,
    cache: &mut OperatorCache,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<RoughSolution, RoughContactError> {
    solve_interruptible(problem, warm, cache, &mut |iteration, residual| {
        progress(iteration, residual);
        ControlFlow::Continue(())
    })
}

/// [`solve_cached`] that can be stopped: `progress(iteration, residual)` after every
/// iteration returns whether to go on, and a [`ControlFlow::Break`] before the solution has
/// converged ends the solve with [`RoughContactError::Interrupted`] (never a result). The
/// Python package answers it with Python's pending signals, so that Ctrl-C stops a long solve
/// between two iterations; a progress that always continues is [`solve_cached`], bit for bit.
pub fn solve_interruptible(
    problem: &RoughContactProblem,
    warm: &Warm,
    cache: &mut OperatorCache,
    progress: &mut dyn FnMut(usize, f64) -> ControlFlow<()>,
) -> Result<RoughSolution, RoughContactError> {
    let (ny, nx) = problem.heights_m.dim();
    if nx < 2 || ny < 2 {
        return Err(RoughContactError::TooSmall(ny, nx));
    }
    let [dx, dy] = problem.spacing_m;
    if !(dx > 0.0 && dy > 0.0 && dx.is_finite() && dy.is_finite()) {
        return Err(parameter(
            "the spacing",
            "must be positive and finite",
            dx.min(dy),
        ));
    }
    if !(problem.e_star_pa > 0.0 && problem.e_star_pa.is_finite()) {
        return Err(parameter(
            "E*",
            "must be positive and finite",
            problem.e_star_pa,
        ));
    }
    if !(problem.tolerance > 0.0 && problem.tolerance < 1.0) {
        return Err(parameter(
            "the tolerance",
            "must lie in (0, 1)",
            problem.tolerance,
        ));
    }
    if let Some(((row, column), &value)) = problem
        .heights_m
        .indexed_iter()
        .find(|(_, v)| !v.is_finite())
    {
        return Err(RoughContactError::NotFinite { row, column, value });
    }
    let local = warm.local_compliance_m_per_pa;
    if !(local >= 0.0 && local.is_finite()) {
        return Err(parameter(
            "the local compliance",
            "must be non-negative and finite",
            local,
        ));
    }
    if let Some(start) = &warm.pressure_pa {
        if start.dim() != (ny, nx) {
            return Err(parameter(
                "the starting pressure",
                "must have the heights' shape",
                start.len() as f64,
            ));
        }
        if let Some(&value) = start.iter().find(|p| !(p.is_finite() && **p >= 0.0)) {
            return Err(parameter(
                "the starting pressure",
                "must be non-negative and finite",
                value,
            ));
        }
    }
    let aspect = crate::operator::elastic::period_aspect([ny, nx], problem.spacing_m);
    if problem.periodicity == Periodicity::Periodic
        && aspect > crate::operator::elastic::MAX_PERIODIC_ASPECT
    {
        return Err(parameter(
            "a periodic map's longer side over its shorter",
            "must be at most 64 (the periodic kernel's images reach 1.5 times the longer side)",
            aspect,
        ));
    }
    let needed = RoughContactProblem::memory_bytes([ny, nx], problem.periodicity);
    if needed > problem.memory_limit_bytes {
        return Err(RoughContactError::TooLarge {
            ny,
            nx,
            needed_mib: needed >> 20,
            limit_mib: problem.memory_limit_bytes >> 20,
        });
    }
    let cells = (nx * ny) as f64;
    let cell_area = dx * dy;
    let hardness = match problem.hardness_pa {
        Some(h) if h > 0.0 && h.is_finite() => h,
        Some(h) => return Err(parameter("the hardness", "must be positive and finite", h)),
        None => f64::INFINITY,
    };
    let target_mean = match problem.control {
        Control::Load { newtons } => Some(newtons / (cells * cell_area)),
        Control::MeanPressure { pa } => Some(pa),
        Control::Approach { .. } => None,
    };
    if let Some(mean) = target_mean {
        if !(mean > 0.0 && mean.is_finite()) {
            let name = match problem.control {
                Control::Load { .. } => "the load",
                _ => "the mean pressure",
            };
            let value = match problem.control {
                Control::Load { newtons } => newtons,
                _ => mean,
            };
            return Err(parameter(name, "must be positive and finite", value));
        }
        if mean >= hardness {
            return Err(RoughContactError::HardnessTooLow {
                hardness_pa: hardness,
                mean_pa: mean,
            });
        }
    }

    let top = problem
        .heights_m
        .iter()
        .fold(f64::NEG_INFINITY, |m, &v| m.max(v));
    let separation = problem.heights_m.mapv(|h| top - h);
    let separation_mean = separation.sum() / cells;
    let roughness = (separation
        .iter()
        .map(|s| (s - separation_mean).powi(2))
        .sum::<f64>()
        / cells)
        .sqrt();
    // A flat surface has no roughness scale: measure the gap against the cell size instead.
    let gap_scale = if roughness > 0.0 {
        roughness
    } else {
        dx.min(dy)
    };

    let mut operator = Compliance {
        elastic: cache.operator(problem)?,
        local_m_per_pa: local,
    };
    // Local stiffness: a cell's own displacement per unit pressure (Love's centre value, or a
    // coated body's), and the local compliance.
    let own_compliance = operator.elastic.own_m_per_pa() + local;

    let approach_given = match problem.control {
        Control::Approach { m } => Some(m),
        _ => None,
    };
    // Periodic and elastic, the operator's mean displacement is zero, so the mean gap is the
    // mean separation less the approach: at or beyond it the gap closes everywhere (beyond it no
    // pressure satisfies the contact conditions, and the iteration would only diverge).
    if let Some(approach) = approach_given {
        if problem.periodicity == Periodicity::Periodic
            && hardness.is_infinite()
            && approach >= separation_mean * (1.0 - FULL_CONTACT_MARGIN)
        {
            return Err(RoughContactError::FullContact {
                what: format!(
                    "an approach of {approach:.4e} m closes the whole gap (periodic: the mean gap is the mean separation {separation_mean:.4e} m less the approach)"
                ),
            });
        }
    }
    // Start: the mean pressure everywhere, or, under a given approach, each cell pressed by
    // its own interference alone.
    let mut pressure = match (target_mean, approach_given, &warm.pressure_pa) {
        (Some(mean), _, Some(start)) if start.sum() > 0.0 => {
            let mut start = start.mapv(|p| p.min(hardness));
            scale_to_mean(&mut start, mean * cells, hardness);
            start
        }
        (None, Some(_), Some(start)) => start.mapv(|p| p.min(hardness)),
        (Some(mean), _, _) => Array2::from_elem((ny, nx), mean),
        (None, approach, _) => {
            let approach = approach.unwrap_or(0.0);
            if !(approach > 0.0 && approach.is_finite()) {
                return Err(RoughContactError::NoContact {
                    approach_m: approach,
                });
            }
            separation.mapv(|s| ((approach - s) / own_compliance).clamp(0.0, hardness))
        }
    };

    let mut state = State::new([ny, nx]);
    let settings = Settings {
        hardness,
        gap_scale,
        tolerance: problem.tolerance,
        max_iterations: problem.max_iterations,
        own_compliance,
    };
    let (iterations, residual) = match (target_mean, approach_given) {
        // Elastic, or capped under a given approach: one iteration.
        (Some(mean), _) if hardness.is_infinite() => iterate(
            &mut operator,
            &separation,
            &mut pressure,
            &mut state,
            Target::MeanPressure(mean),
            &settings,
            progress,
        )?,
        (None, Some(approach)) => iterate(
            &mut operator,
            &separation,
            &mut pressure,
            &mut state,
            Target::Approach(approach),
            &settings,
            progress,
        )?,
        // Capped under a given load: the approach that carries it, by a safeguarded search.
        (Some(mean), _) => load_search::capped_under_load(
            &mut operator,
            &separation,
            &mut pressure,
            &mut state,
            mean,
            &settings,
            progress,
        )?,
        (None, None) => (0, f64::INFINITY),
    };
    let mut gap = state.gap;
    // The gap of the final pressure, and the approach it implies.
    operator.apply(pressure.view(), gap.view_mut())?;
    Zip::from(&mut gap)
        .and(&separation)
        .for_each(|g, &s| *g += s);
    let approach_m = match approach_given {
        Some(approach) => approach,
        None => {
            let (sum, count) = sum_active(&pressure, &gap, &|p, _| p > 0.0 && p < hardness);
            let (sum, count) = if count > 0 {
                (sum, count)
            } else {
                sum_active(&pressure, &gap, &|p, _| p > 0.0)
            };
            sum / count.max(1) as f64
        }
    };
    gap.mapv_inplace(|g| g - approach_m);
    let plastic_penetration_m: Vec<([usize; 2], f64)> = if hardness.is_finite() {
        Zip::indexed(&gap)
            .and(&pressure)
            .fold(Vec::new(), |mut cells, (row, column), &g, &p| {
                if p >= hardness && g < 0.0 {
                    cells.push(([row, column], -g));
                }
                cells
            })
    } else {
        Vec::new()
    };
    // In contact the gap is zero by definition (its rounding is the tolerance).
    Zip::from(&mut gap).and(&pressure).for_each(|g, &p| {
        if p > 0.0 {
            *g = 0.0
        }
    });

    if residual >= problem.tolerance {
        return Err(RoughContactError::NotConverged {
            iterations,
            residual,
            tolerance: problem.tolerance,
        });
    }
    let loaded = pressure.iter().filter(|&&p| p > 0.0).count();
    if loaded == 0 {
        return Err(RoughContactError::NoContact {
            approach_m: approach_given.unwrap_or(0.0),
        });
    }
    if loaded == nx * ny {
        let what = match problem.control {
            Control::Approach { m } => format!("an approach of {m:.4e} m closes the whole gap"),
            Control::Load { newtons } => {
                format!("a load of {newtons:.4e} N flattens the whole surface")
            }
            Control::MeanPressure { pa } => {
                format!("a mean pressure of {pa:.4e} Pa flattens the whole surface")
            }
        };
        return Err(RoughContactError::FullContact { what });
    }
    if problem.periodicity == Periodicity::NonPeriodic {
        if let Some((row, column)) = edge_contact(&pressure) {
            return Err(RoughContactError::PressureAtEdge { row, column });
        }
    }
    let load_n = pressure.sum() * cell_area;
    let plastic_cells = pressure.iter().filter(|&&p| p >= hardness).count();
    let sizes = spot_sizes(&pressure, problem.periodicity == Periodicity::Periodic);
    Ok(RoughSolution {
        max_pressure_pa: pressure.iter().fold(0.0f64, |m, &p| m.max(p)),
        contact_fraction: loaded as f64 / cells,
        spots: sizes.len(),
        largest_spot_cells: sizes.iter().copied().max().unwrap_or(0),
        mean_gap_m: gap.sum() / cells,
        mean_pressure_pa: load_n / (cells * cell_area),
        load_n,
        pressure_pa: pressure,
        gap_m: gap,
        spacing_m: problem.spacing_m,
        periodicity: problem.periodicity,
        approach_m,
        plastic_cells,
        plastic_penetration_m,
        iterations,
        residual,
    })
}

/// A loaded cell on the border of the grid, if any.
fn edge_contact(pressure: &Array2<f64>) -> Option<(usize, usize)> {
    let (ny, nx) = pressure.dim();
    pressure
        .indexed_iter()
        .find(|&((j, i), &p)| p > 0.0 && (j == 0 || i == 0 || j + 1 == ny || i + 1 == nx))
        .map(|(at, _)| at)
}

/// Connected groups of loaded cells (4-neighbours; wrapping around when `periodic`).
pub fn count_spots(pressure: &Array2<f64>, periodic: bool) -> usize {
    spot_sizes(pressure, periodic).len()
}

/// The number of cells of each contact spot (4-connected; wrapping when `periodic`).
pub fn spot_sizes(pressure: &Array2<f64>, periodic: bool) -> Vec<usize> {
    let (ny, nx) = pressure.dim();
    let mut seen = Array2::from_elem((ny, nx), false);
    let mut stack = Vec::new();
    let mut sizes = Vec::new();
    for ((j, i), &p) in pressure.indexed_iter() {
        if p <= 0.0 || seen[[j, i]] {
            continue;
        }
        let mut size = 0;
        seen[[j, i]] = true;
        stack.push((j, i));
        while let Some((b, a)) = stack.pop() {
            size += 1;
            let neighbours = [
                (b as i64 - 1, a as i64),
                (b as i64 + 1, a as i64),
                (b as i64, a as i64 - 1),
                (b as i64, a as i64 + 1),
            ];
            for (y, x) in neighbours {
                let (y, x) = if periodic {
                    (y.rem_euclid(ny as i64), x.rem_euclid(nx as i64))
                } else if y < 0 || x < 0 || y >= ny as i64 || x >= nx as i64 {
                    continue;
                } else {
                    (y, x)
                };
                let (y, x) = (y as usize, x as usize);
                if pressure[[y, x]] > 0.0 && !seen[[y, x]] {
                    seen[[y, x]] = true;
                    stack.push((y, x));
                }
            }
        }
        sizes.push(size);
    }
    sizes
}

#[cfg(test)]
mod tests;

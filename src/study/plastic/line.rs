//! The elastic-plastic line contact of a `[plasticity]` scene with `contact.kind = "line"`
//! (issue 51): a cylinder or a rigid roller pressed on body 1 in plane strain, in load steps,
//! then unloaded ([`crate::plasticity::line`]).
//!
//! The x–z volume is centred on the contact's axis: `grid_cells` columns over
//! `±extent_over_a` Hertz half-widths `b` (a column centred on the axis), `depth_cells` uniform
//! layers down to `depth_over_a` half-widths. What is reported is defined in
//! docs/plasticity.md: the keys of the point contact with `load_n_per_m`, `half_width_m` (half
//! the width of the cells in contact) and `plastic_area_m2` (the plastic zone's area in the
//! x–z section); `contact_area_m2` is the contact's area per metre of length (its width times
//! 1 m).

use ndarray::{Array3, Array4};

use super::{step_loads, PlasticStudyError, Unloaded, MAX_ITERATIONS};
use crate::contact::LineContact;
use crate::plasticity::column::DepthCells;
use crate::plasticity::j2::Hardening;
use crate::plasticity::line::{self, LineGrid, LinePlasticProblem};
use crate::plasticity::loading::{
    largest, von_mises_field, PlasticContactSolution, Progress, Snapshot, PLASTIC_ZONE_STRAIN,
};
use crate::scene::{Hertz, PlasticitySpec, Scene};

/// Differences kept by the Anderson acceleration of each step's fixed point.
pub const ACCELERATION: usize = 5;

/// The loaded state at the full load.
#[derive(Clone, Debug, PartialEq)]
pub struct LineLoaded {
    pub max_pressure_pa: f64,
    /// The load per unit length over the contact's width.
    pub mean_pressure_pa: f64,
    /// The contact's area per metre of length (m²: its width times 1 m).
    pub contact_area_m2: f64,
    /// Half the width of the cells in contact.
    pub half_width_m: f64,
    /// The approach of the points at the grid's depth below each surface on the axis
    /// ([`crate::plasticity::line`]).
    pub approach_m: f64,
    pub max_plastic_strain: f64,
    pub max_plastic_strain_depth_m: f64,
    pub plastic_zone_depth_m: f64,
    /// The plastic zone's area in the x–z section (m², the volume per metre of length).
    pub plastic_area_m2: f64,
    pub von_mises_max_pa: f64,
    pub von_mises_max_depth_m: f64,
    /// Hertz's peak pressure at the load (the elastic body).
    pub elastic_max_pressure_pa: f64,
}

/// Everything computed of a line `[plasticity]` scene.
#[derive(Clone, Debug)]
pub struct LinePlasticStudy {
    pub spec: PlasticitySpec,
    /// The elastic (Hertz) line contact at the scene's load.
    pub hertz: LineContact,
    pub friction: f64,
    pub grid: LineGrid,
    /// Cell centres (m): x (from the axis) and depth z.
    pub x_m: Vec<f64>,
    pub z_m: Vec<f64>,
    pub solution: PlasticContactSolution,
    pub loaded: LineLoaded,
    /// `residual_von_mises_max_r_m` is the distance from the axis, `|x|`.
    pub unloaded: Option<Unloaded>,
    pub converged: bool,
    pub iterations: usize,
    pub warnings: Vec<String>,
}

impl LinePlasticStudy {
    pub fn loaded_snapshot(&self) -> &Snapshot {
        &self.solution.snapshots[0]
    }

    pub fn unloaded_snapshot(&self) -> Option<&Snapshot> {
        self.unloaded.as_ref().and(self.solution.snapshots.get(1))
    }

    /// The equivalent plastic strain after the last step (`[nz, 1, nx]`).
    pub fn final_plastic_strain(&self) -> &Array3<f64> {
        let last = self.solution.snapshots.len() - 1;
        &self.solution.snapshots[last].equivalent_plastic_strain
    }

    /// The total stress of a state with its components last, `[nz, 1, nx, 6]`.
    pub fn components_last(stress: &Array4<f64>) -> Array4<f64> {
        super::components_last(stress)
    }
}

/// The x–z grid of `spec` about a contact of half-width `b_m`.
pub fn line_grid(spec: &PlasticitySpec, b_m: f64) -> Result<LineGrid, PlasticStudyError> {
    let depth = DepthCells::uniform(
        spec.depth_cells,
        spec.depth_over_a * b_m / spec.depth_cells as f64,
    )
    .map_err(|e| PlasticStudyError::Grid {
        key: "depth_cells",
        message: e.0,
    })?;
    Ok(LineGrid {
        cells: spec.grid_cells,
        spacing_m: 2.0 * spec.extent_over_a * b_m / spec.grid_cells as f64,
        depth,
    })
}

/// The study of a line `[plasticity]` scene; `progress(step, iteration, residual)` after every
/// iteration.
pub fn study(
    scene: &Scene,
    progress: &mut dyn FnMut(Progress),
) -> Result<LinePlasticStudy, PlasticStudyError> {
    let spec = scene.plasticity.ok_or(PlasticStudyError::NotPlastic)?;
    let Some(dimensional) = scene.contact.dimensional else {
        return Err(PlasticStudyError::NotPlastic);
    };
    let Hertz::Line(hertz) = dimensional.hertz else {
        return Err(PlasticStudyError::NotPlastic);
    };
    let body2 = dimensional.body2.material;
    let counter = body2
        .modulus_pa
        .is_finite()
        .then_some((body2.modulus_pa, body2.poisson));
    study_line(&spec, &hertz, counter, scene.contact.friction, progress)
}

/// The study of a cylinder pressed on an elastic-plastic body 1 (`hertz` its elastic
/// contact; `counter` body 2's modulus and Poisson's ratio, `None` when rigid).
pub fn study_line(
    spec: &PlasticitySpec,
    hertz: &LineContact,
    counter: Option<(f64, f64)>,
    friction: f64,
    progress: &mut dyn FnMut(Progress),
) -> Result<LinePlasticStudy, PlasticStudyError> {
    let b = hertz.half_width_m;
    let grid = line_grid(spec, b)?;
    let [nz, nx] = grid.dims();
    let dx = grid.spacing_m;
    let x_m = grid.x_m();
    let z_m = grid.depth.centres_m();
    let radius = hertz.effective_radius_m;
    let gap_m: Vec<f64> = x_m.iter().map(|x| x * x / (2.0 * radius)).collect();
    let loads = step_loads(spec, hertz.load_n_per_m);
    let loaded_step = spec.steps - 1;
    let mut snapshots = vec![loaded_step];
    if spec.unload {
        snapshots.push(loads.len() - 1);
    }
    let problem = LinePlasticProblem {
        gap_m,
        grid: grid.clone(),
        modulus_pa: spec.body1.modulus_pa,
        poisson: spec.body1.poisson,
        counter,
        e_star_pa: hertz.effective_modulus_pa,
        hardening: Hardening {
            yield_strength_pa: spec.yield_strength_pa,
            plastic_modulus_pa: spec.hardening_modulus_pa,
        },
        friction,
        loads_n_per_m: loads,
        snapshots,
        tolerance: spec.tolerance,
        max_iterations: MAX_ITERATIONS,
        acceleration: ACCELERATION,
    };
    let solution = line::solve(&problem, progress, None)?;
    let loaded_state = &solution.snapshots[0];
    let kappa = &loaded_state.equivalent_plastic_strain;
    let mut at_bottom = false;
    let mut at_side = false;
    for ((l, _, i), &k) in kappa.indexed_iter() {
        if k > PLASTIC_ZONE_STRAIN {
            at_bottom |= l + 1 == nz;
            at_side |= i == 0 || i + 1 == nx;
        }
    }
    if at_bottom {
        return Err(PlasticStudyError::Grid {
            key: "depth_over_a",
            message: format!(
                "the plastic zone reaches the volume grid's bottom ({:.3} b): the grid is too shallow for it\nhint: raise depth_over_a (e.g. to {:.1}) and depth_cells with it",
                spec.depth_over_a,
                spec.depth_over_a * 2.0
            ),
        });
    }
    if at_side {
        return Err(PlasticStudyError::Grid {
            key: "extent_over_a",
            message: format!(
                "the plastic zone reaches the volume grid's sides (±{:.3} b): the grid is too narrow for it\nhint: raise extent_over_a (e.g. to {:.1}) and grid_cells with it",
                spec.extent_over_a,
                spec.extent_over_a * 2.0
            ),
        });
    }
    let step = &solution.steps[loaded_step];
    let width_m = step.contact_cells as f64 * dx;
    let (max_plastic_strain, at_strain) = largest(kappa);
    let mut plastic_zone_depth_m: f64 = 0.0;
    let mut plastic_area_m2 = 0.0;
    for ((l, _, _), &k) in kappa.indexed_iter() {
        if k > PLASTIC_ZONE_STRAIN {
            plastic_zone_depth_m = plastic_zone_depth_m.max(z_m[l]);
            plastic_area_m2 += dx * grid.depth.thickness_m(l);
        }
    }
    let plastic = max_plastic_strain > PLASTIC_ZONE_STRAIN;
    let von_mises = von_mises_field(&loaded_state.stress_pa);
    let (von_mises_max_pa, at_von_mises) = largest(&von_mises);
    let loaded = LineLoaded {
        max_pressure_pa: step.max_pressure_pa,
        mean_pressure_pa: if width_m > 0.0 {
            hertz.load_n_per_m / width_m
        } else {
            0.0
        },
        contact_area_m2: width_m * 1.0,
        half_width_m: width_m / 2.0,
        approach_m: step.approach_m.unwrap_or(0.0),
        max_plastic_strain: if plastic { max_plastic_strain } else { 0.0 },
        max_plastic_strain_depth_m: if plastic { z_m[at_strain[0]] } else { 0.0 },
        plastic_zone_depth_m,
        plastic_area_m2,
        von_mises_max_pa,
        von_mises_max_depth_m: z_m[at_von_mises[0]],
        elastic_max_pressure_pa: hertz.p0_pa,
    };
    let unloaded = spec.unload.then(|| {
        let state = &solution.snapshots[1];
        let residual = von_mises_field(&state.stress_pa);
        let (value, [l, _, i]) = largest(&residual);
        let stressed = value > 0.0;
        Unloaded {
            residual_depth_m: state.plastic_displacement_m[[0, nx / 2]],
            residual_von_mises_max_pa: value,
            residual_von_mises_max_depth_m: if stressed { z_m[l] } else { 0.0 },
            residual_von_mises_max_r_m: if stressed { x_m[i].abs() } else { 0.0 },
        }
    });
    let converged = solution.steps.iter().all(|s| s.converged);
    let iterations = solution.steps.iter().map(|s| s.iterations).sum();
    let mut warnings = Vec::new();
    if !converged {
        let failed: Vec<String> = solution
            .steps
            .iter()
            .enumerate()
            .filter(|(_, s)| !s.converged)
            .map(|(i, s)| format!("{} (residual {:.1e})", i + 1, s.residual))
            .collect();
        warnings.push(format!(
            "steps {} did not converge to plasticity.tolerance = {:e} in {MAX_ITERATIONS} iterations",
            failed.join(", "),
            spec.tolerance
        ));
    }
    if loaded.mean_pressure_pa > 3.0 * spec.yield_strength_pa {
        warnings.push(format!(
            "the mean pressure {:.0} MPa exceeds 3 Y ({:.0} MPa), the fully plastic indentation of Tabor: small strains no longer hold",
            loaded.mean_pressure_pa / 1e6,
            3.0 * spec.yield_strength_pa / 1e6
        ));
    }
    Ok(LinePlasticStudy {
        spec: *spec,
        hertz: *hertz,
        friction,
        grid,
        x_m,
        z_m,
        solution,
        loaded,
        unloaded,
        converged,
        iterations,
        warnings,
    })
}

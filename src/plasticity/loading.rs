//! The semi-analytical method of elastic-plastic contact: load steps, each solved by a
//! fixed-point iteration between the contact, the stresses and the return mapping.
//!
//! ## One step
//! Body 1 is an elastic-plastic half-space with the plastic strain `εp` on a volume grid
//! ([`super::halfspace`]); body 2 is elastic or rigid. At the step's load `W`, from the state
//! at the start of the step (`εp_n`, `κ_n`), iterate:
//!
//! 1. the contact ([`crate::contact::rough`], with its elastic operator of `E*`) is solved
//!    under `W` on the gap opened by the surface displacement `u_p` of the current plastic
//!    strain: the heights less `u_p` (the plastic strain's surface moves into body 1 by `u_p`);
//! 2. the stress at every cell is the contact's elastic stress (DC-FFT of the pressure, and of
//!    `q = μ p` along x when sliding) plus the residual stress of the current plastic strain,
//!    both in one set of transforms ([`super::halfspace::HalfSpace::stress`]);
//! 3. the total strain so found, with the plastic strain of the start of the step, gives the
//!    trial stress `σ_tr = σ + C : (εp - εp_n)`, returned onto the yield surface from `κ_n`
//!    ([`super::j2::radial_return`]): the new plastic strain `εp_n + Δεp`;
//! 4. its surface displacement closes the loop.
//!
//! The step has converged when the plastic strain changes by less than `tolerance` times the
//! largest accumulated plastic strain (or the yield strain `σY/E` while that is smaller)
//! from one iteration to the next, anywhere, and the pressure by less than `tolerance` of its
//! sum (`Σ|Δp| / Σp`). This is the fixed point of Jacq et al. (2002) on the plastic strain,
//! with the contact solved inside it as Tamaas's EPIC does (Frérot et al. 2019).
//!
//! ## The steps
//! Each step starts from the converged state of the one before (backward Euler in the load:
//! the path of a growing contact is followed step by step). A step of zero load lifts the
//! indenter off: the pressure is zero and the stress is the residual stress, which may still
//! yield (reverse yielding); the iteration then has no contact to solve.
//!
//! ## The approach
//! The rough solver measures its approach from the first contact of the heights it is given;
//! those are the undeformed heights less `u_p`, so the approach from the first contact of the
//! undeformed bodies, with the far surface as the reference (`u_p` vanishes far from an
//! isolated plastic zone), is the solver's plus `max(h) - max(h - u_p)`.
//!
//! ## References
//! - C. Jacq, D. Nélias, G. Lormand, D. Girodin, Development of a three-dimensional
//!   semi-analytical elastic-plastic contact code, *J. Tribol.* 124 (2002) 653–667.
//! - L. Frérot, M. Bonnet, J.-F. Molinari, G. Anciaux, A Fourier-accelerated volume integral
//!   method for elastoplastic contact, *Comput. Methods Appl. Mech. Engrg.* 351 (2019)
//!   951–976.

use ndarray::{Array2, Array3, Array4, ArrayView2, Zip};

use super::anderson::Anderson;
use super::halfspace::{HalfSpace, HalfSpaceError, VolumeGrid};
use super::j2::{equivalent_strain, radial_return, von_mises, Hardening};
use crate::contact::rough::{
    solve_cached, Control, OperatorCache, RoughContactError, RoughContactProblem, Warm,
};

/// An elastic-plastic contact loaded step by step.
#[derive(Clone, Debug)]
pub struct PlasticContactProblem<'a> {
    /// The undeformed gap as heights out of body 1 (m, `[ny, nx]`: the convention of
    /// [`RoughContactProblem::heights_m`]).
    pub heights_m: ArrayView2<'a, f64>,
    /// The volume grid of the plastic strain; its shape is the heights'.
    pub grid: VolumeGrid,
    /// Body 1's Young's modulus and Poisson's ratio.
    pub modulus_pa: f64,
    pub poisson: f64,
    /// The contact's combined modulus.
    pub e_star_pa: f64,
    pub hardening: Hardening,
    /// `q = μ p` on body 1 along +x.
    pub friction: f64,
    /// The load of each step (N): loading, then unloading (0 lifts the indenter off).
    pub loads_n: Vec<f64>,
    /// The steps after which the whole state is kept ([`Snapshot`]).
    pub snapshots: Vec<usize>,
    /// The cell `[row, column]` on the contact's axis (the dent is read there).
    pub axis_cell: [usize; 2],
    /// Relative tolerance of the fixed point.
    pub tolerance: f64,
    /// Iterations allowed per step.
    pub max_iterations: usize,
    /// Differences kept by the Anderson acceleration of the fixed point (0: plain iteration).
    pub acceleration: usize,
    /// The contact solver's tolerance.
    pub contact_tolerance: f64,
    /// The most memory the contact solver may take.
    pub memory_limit_bytes: usize,
}

/// What a step ended with.
#[derive(Clone, Debug, PartialEq)]
pub struct StepResult {
    /// N (N/m for a plane volume).
    pub load_n: f64,
    /// The approach of the bodies from the first contact of the undeformed ones (m), with the
    /// far surface as reference; `None` when lifted off.
    pub approach_m: Option<f64>,
    pub max_pressure_pa: f64,
    pub contact_cells: usize,
    /// The plastic surface displacement on the axis (m, into body 1).
    pub axis_displacement_m: f64,
    pub max_plastic_strain: f64,
    pub plastic_cells: usize,
    pub iterations: usize,
    /// The larger of the two convergence measures at the end.
    pub residual: f64,
    pub converged: bool,
}

/// The whole state after a step.
#[derive(Clone, Debug)]
pub struct Snapshot {
    pub step: usize,
    /// N (N/m for a plane volume).
    pub load_n: f64,
    pub approach_m: Option<f64>,
    pub pressure_pa: Array2<f64>,
    /// The total stress at the cell centres (Pa, `[nz, 6, ny, nx]`): the contact's plus the
    /// residual stress.
    pub stress_pa: Array4<f64>,
    /// The accumulated equivalent plastic strain (`[nz, ny, nx]`).
    pub equivalent_plastic_strain: Array3<f64>,
    /// The plastic strain tensor (`[nz, 6, ny, nx]`).
    pub plastic_strain: Array4<f64>,
    /// The surface displacement of the plastic strain (m, into body 1, `[ny, nx]`).
    pub plastic_displacement_m: Array2<f64>,
}

/// The loading history.
#[derive(Clone, Debug)]
pub struct PlasticContactSolution {
    pub steps: Vec<StepResult>,
    pub snapshots: Vec<Snapshot>,
}

/// Progress reported after each iteration.
#[derive(Clone, Copy, Debug)]
pub struct Progress {
    pub step: usize,
    pub steps: usize,
    pub iteration: usize,
    pub residual: f64,
}

/// Why an elastic-plastic contact has no solution.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PlasticContactError {
    #[error("{0}")]
    Parameter(String),
    #[error("the contact at step {step} ({load_n:.4e} N): {source}")]
    Contact {
        step: usize,
        load_n: f64,
        source: RoughContactError,
    },
    #[error(transparent)]
    HalfSpace(#[from] HalfSpaceError),
    /// The line contact's solve (plane strain) at a step.
    #[error("the line contact at step {step} ({load_n_per_m:.4e} N/m): {message}")]
    LineContact {
        step: usize,
        load_n_per_m: f64,
        message: String,
    },
    /// The plane operator's transforms.
    #[error("the FFT of the plane operator: {0}")]
    Transform(String),
}

/// Bytes the solve of `grid` takes besides the snapshots: the operator, the strains and
/// stresses of the iteration, and the contact solver.
pub fn memory_bytes(grid: &VolumeGrid, with_shear: bool) -> usize {
    let cells = grid.depth.count() * grid.layer_cells();
    HalfSpace::memory_bytes(grid, 1 + usize::from(with_shear))
        + cells * 8 * (3 * 6 + 2)
        + RoughContactProblem::memory_bytes(grid.shape, grid.periodicity)
        + 6 * 8 * grid.layer_cells()
}

/// Bytes of one [`Snapshot`].
pub fn snapshot_bytes(grid: &VolumeGrid) -> usize {
    let cells = grid.depth.count() * grid.layer_cells();
    cells * 8 * 13 + 2 * 8 * grid.layer_cells()
}

/// The state at the end of a step, lent to the observer of [`solve_observed`] (the stress is
/// that of the step's final plastic strain and pressure, as a [`Snapshot`]'s).
#[derive(Clone, Copy, Debug)]
pub struct StepState<'a> {
    pub step: usize,
    pub result: &'a StepResult,
    pub pressure_pa: &'a Array2<f64>,
    /// `[nz, 6, ny, nx]`.
    pub stress_pa: &'a Array4<f64>,
    /// `[nz, ny, nx]`.
    pub equivalent_plastic_strain: &'a Array3<f64>,
    pub plastic_displacement_m: &'a Array2<f64>,
}

/// Solves the steps. `progress` is called after every iteration.
pub fn solve(
    problem: &PlasticContactProblem,
    progress: &mut dyn FnMut(Progress),
) -> Result<PlasticContactSolution, PlasticContactError> {
    solve_observed(problem, progress, None)
}

/// What the load-step loop ([`run`]) asks of a body: its eigenstrain operator (the residual
/// stress and the surface displacement of a plastic strain, plus the contact's stress) and its
/// contact solve. The 3-D half-space ([`VolumeBody`]) and the plane-strain x–z volume
/// ([`super::line`]) differ only here; arrays are `[nz, 6, ny, nx]`, `[nz, ny, nx]` and
/// `[ny, nx]` (one row for the plane volume).
pub trait PlasticBody {
    /// Takes the plastic strain `strain`, writes its normal surface displacement (m, into
    /// body 1) and keeps what [`PlasticBody::stress`] needs of it.
    fn set_strain(
        &mut self,
        strain: &Array4<f64>,
        displacement: &mut Array2<f64>,
    ) -> Result<(), PlasticContactError>;

    /// The total stress at the cell centres: the residual stress of the strain last given to
    /// [`PlasticBody::set_strain`] plus the contact's stress of `pressure_pa` and of the shear
    /// `friction` times it along +x. It may consume what `set_strain` kept: the loop calls
    /// `set_strain` again before the next use.
    fn stress(
        &mut self,
        pressure_pa: &Array2<f64>,
        friction: f64,
        stress: &mut Array4<f64>,
    ) -> Result<(), PlasticContactError>;

    /// The pressure carrying `load` on the undeformed gap opened by the plastic surface
    /// displacement `displacement`, starting from `previous` (the last iterate), and the
    /// approach the contact solve measures.
    fn contact(
        &mut self,
        step: usize,
        load: f64,
        displacement: &Array2<f64>,
        previous: &Array2<f64>,
    ) -> Result<(Array2<f64>, f64), PlasticContactError>;

    /// Whether [`PlasticBody::approach_m`] needs the stress of the step's final state.
    fn approach_needs_stress(&self) -> bool {
        false
    }

    /// The approach reported at the end of a loaded step: the contact solve's (`contact_m`)
    /// unless the body defines it from its final state (the total `stress` when
    /// [`PlasticBody::approach_needs_stress`], the plastic `strain` and the pressure).
    fn approach_m(
        &self,
        contact_m: f64,
        _stress: &Array4<f64>,
        _strain: &Array4<f64>,
        _pressure_pa: &Array2<f64>,
    ) -> f64 {
        contact_m
    }
}

/// What the load-step loop needs besides the body: the material, the loads and the control of
/// the fixed point.
#[derive(Clone, Debug)]
pub struct Steps<'a> {
    /// `[nz, ny, nx]` cells.
    pub dims: [usize; 3],
    /// Body 1's Young's modulus and Poisson's ratio.
    pub modulus_pa: f64,
    pub poisson: f64,
    pub hardening: Hardening,
    /// `q = μ p` on body 1 along +x.
    pub friction: f64,
    /// The load of each step (N, or N/m for a plane volume).
    pub loads: &'a [f64],
    pub snapshots: &'a [usize],
    /// The cell `[row, column]` on the contact's axis.
    pub axis_cell: [usize; 2],
    pub tolerance: f64,
    pub max_iterations: usize,
    pub acceleration: usize,
}

impl Steps<'_> {
    /// The checks common to every body (`what`: its name in the messages): the material and
    /// the tolerance. Callers check before they build the body's operator.
    pub fn validate(&self, what: &str) -> Result<(), PlasticContactError> {
        let hardening = self.hardening;
        if !(hardening.yield_strength_pa > 0.0 && hardening.yield_strength_pa.is_finite()) {
            return Err(PlasticContactError::Parameter(format!(
                "the yield strength must be positive, got {}",
                hardening.yield_strength_pa
            )));
        }
        if !(hardening.plastic_modulus_pa >= 0.0 && hardening.plastic_modulus_pa.is_finite()) {
            return Err(PlasticContactError::Parameter(format!(
                "the plastic modulus must be non-negative, got {}",
                hardening.plastic_modulus_pa
            )));
        }
        if !(self.poisson > -1.0 && self.poisson < 0.5) {
            return Err(PlasticContactError::Parameter(format!(
                "Poisson's ratio must lie in (-1, 0.5) for the plastic {what}, got {}",
                self.poisson
            )));
        }
        if !(self.tolerance > 0.0 && self.tolerance < 1.0) {
            return Err(PlasticContactError::Parameter(format!(
                "the tolerance must lie in (0, 1), got {}",
                self.tolerance
            )));
        }
        Ok(())
    }
}

/// The 3-D half-space of [`PlasticContactProblem`]: the DC-FFT eigenstrain operator
/// ([`HalfSpace`]) and the rough contact solver on the heights less the plastic displacement.
pub struct VolumeBody<'a, 'h> {
    problem: &'a PlasticContactProblem<'h>,
    operator: HalfSpace,
    heights: Array2<f64>,
    /// The highest undeformed height (the approach's reference, module doc).
    top: f64,
    cache: OperatorCache,
}

impl PlasticBody for VolumeBody<'_, '_> {
    fn set_strain(
        &mut self,
        strain: &Array4<f64>,
        displacement: &mut Array2<f64>,
    ) -> Result<(), PlasticContactError> {
        Ok(self
            .operator
            .set_strain(strain.view(), displacement.view_mut())?)
    }

    fn stress(
        &mut self,
        pressure_pa: &Array2<f64>,
        friction: f64,
        stress: &mut Array4<f64>,
    ) -> Result<(), PlasticContactError> {
        Ok(self
            .operator
            .stress(Some((pressure_pa.view(), friction)), stress.view_mut())?)
    }

    fn contact(
        &mut self,
        step: usize,
        load: f64,
        displacement: &Array2<f64>,
        previous: &Array2<f64>,
    ) -> Result<(Array2<f64>, f64), PlasticContactError> {
        let problem = self.problem;
        let grid = &problem.grid;
        Zip::from(&mut self.heights)
            .and(&problem.heights_m)
            .and(displacement)
            .for_each(|h, &h0, &u| *h = h0 - u);
        let contact = RoughContactProblem {
            heights_m: self.heights.view(),
            spacing_m: grid.spacing_m,
            e_star_pa: problem.e_star_pa,
            periodicity: grid.periodicity,
            control: Control::Load { newtons: load },
            hardness_pa: None,
            tolerance: problem.contact_tolerance,
            max_iterations: crate::contact::rough::DEFAULT_MAX_ITERATIONS,
            memory_limit_bytes: problem.memory_limit_bytes,
        };
        let warm = Warm {
            pressure_pa: (previous.sum() > 0.0).then(|| previous.view()),
            local_compliance_m_per_pa: 0.0,
        };
        let solution =
            solve_cached(&contact, &warm, &mut self.cache, &mut |_, _| {}).map_err(|source| {
                PlasticContactError::Contact {
                    step,
                    load_n: load,
                    source,
                }
            })?;
        let shifted = self
            .heights
            .iter()
            .fold(f64::NEG_INFINITY, |m, &h| m.max(h));
        Ok((
            solution.pressure_pa,
            solution.approach_m + self.top - shifted,
        ))
    }
}

/// [`solve`], lending the state at the end of every step to `observe` (a light record of each
/// step, e.g. a recording's section, without keeping whole [`Snapshot`]s); observing costs one
/// stress evaluation per step.
pub fn solve_observed(
    problem: &PlasticContactProblem,
    progress: &mut dyn FnMut(Progress),
    observe: Option<&mut dyn FnMut(&StepState)>,
) -> Result<PlasticContactSolution, PlasticContactError> {
    let grid = &problem.grid;
    let [_, ny, nx] = grid.dims();
    if problem.heights_m.dim() != (ny, nx) {
        return Err(PlasticContactError::Parameter(format!(
            "the heights ({} x {}) and the volume grid ({ny} x {nx}) differ",
            problem.heights_m.nrows(),
            problem.heights_m.ncols()
        )));
    }
    let steps = Steps {
        dims: grid.dims(),
        modulus_pa: problem.modulus_pa,
        poisson: problem.poisson,
        hardening: problem.hardening,
        friction: problem.friction,
        loads: &problem.loads_n,
        snapshots: &problem.snapshots,
        axis_cell: problem.axis_cell,
        tolerance: problem.tolerance,
        max_iterations: problem.max_iterations,
        acceleration: problem.acceleration,
    };
    steps.validate("half-space")?;
    let shear_modulus = problem.modulus_pa / (2.0 * (1.0 + problem.poisson));
    let operator = HalfSpace::new(grid.clone(), shear_modulus, problem.poisson)
        .with_contact(problem.poisson, problem.friction != 0.0)?;
    let mut body = VolumeBody {
        problem,
        operator,
        heights: problem.heights_m.to_owned(),
        top: problem
            .heights_m
            .iter()
            .fold(f64::NEG_INFINITY, |m, &h| m.max(h)),
        cache: OperatorCache::default(),
    };
    run(&mut body, &steps, progress, observe)
}

/// The load steps of the semi-analytical method (module doc) on any [`PlasticBody`]: the one
/// loop of the point, elliptical, rough and line (plane-strain) contacts. `control` is
/// checked by the caller ([`Steps::validate`]).
pub fn run(
    body: &mut dyn PlasticBody,
    control: &Steps,
    progress: &mut dyn FnMut(Progress),
    mut observe: Option<&mut dyn FnMut(&StepState)>,
) -> Result<PlasticContactSolution, PlasticContactError> {
    let [nz, ny, nx] = control.dims;
    let hardening = control.hardening;
    let shear_modulus = control.modulus_pa / (2.0 * (1.0 + control.poisson));
    let lambda = 2.0 * shear_modulus * control.poisson / (1.0 - 2.0 * control.poisson);
    let yield_strain = hardening.yield_strength_pa / control.modulus_pa;

    let mut strain = Array4::<f64>::zeros((nz, 6, ny, nx));
    let mut strain_start = strain.clone();
    let mut kappa = Array3::<f64>::zeros((nz, ny, nx));
    let mut kappa_start = kappa.clone();
    let mut stress = Array4::<f64>::zeros((nz, 6, ny, nx));
    let mut displacement = Array2::<f64>::zeros((ny, nx));
    body.set_strain(&strain, &mut displacement)?;
    let mut kept = true;
    let mut pressure = Array2::<f64>::zeros((ny, nx));
    let mut previous = Array2::<f64>::zeros((ny, nx));

    let mut steps = Vec::with_capacity(control.loads.len());
    let mut snapshots = Vec::new();
    let count = control.loads.len();
    let mut anderson = Anderson::new(control.acceleration);
    let mut active = Active::new(kappa.len());
    for (step, &load) in control.loads.iter().enumerate() {
        strain_start.assign(&strain);
        kappa_start.assign(&kappa);
        anderson.reset();
        active.clear();
        let mut approach = None;
        let mut contact_cells = 0;
        let mut residual = f64::INFINITY;
        let mut iterations = 0;
        let mut converged = false;
        while iterations < control.max_iterations {
            iterations += 1;
            if !kept {
                body.set_strain(&strain, &mut displacement)?;
            }
            // 1. The contact on the gap opened by the plastic surface displacement.
            previous.assign(&pressure);
            if load > 0.0 {
                let (solved, solved_approach) =
                    body.contact(step, load, &displacement, &previous)?;
                approach = Some(solved_approach);
                contact_cells = solved.iter().filter(|&&p| p > 0.0).count();
                pressure = solved;
            } else {
                pressure.fill(0.0);
                approach = None;
                contact_cells = 0;
            }
            // 2. The stresses: the contact's and the residual ones.
            body.stress(&pressure, control.friction, &mut stress)?;
            // 3. The return mapping from the start of the step.
            // The active cells' plastic strain before the mapping (x), then after (G(x)).
            gather(&strain, &active.cells, &mut active.x);
            let change = return_mapping(
                &stress,
                &mut strain,
                &strain_start,
                &mut kappa,
                &kappa_start,
                &hardening,
                [lambda, shear_modulus],
                &mut active,
            );
            gather(&strain, &active.cells, &mut active.g);
            // Cells that joined had x = G(x) at every earlier iterate (they did not flow).
            let joined = 6 * active.joined.len();
            if joined > 0 {
                let from = active.x.len() - joined;
                anderson.grow(&active.x[from..]);
            }
            // Accelerated: the next plastic strain of the active cells.
            anderson.next(&mut active.x, &active.g);
            scatter(&mut strain, &active.cells, &active.x);
            // 4. The surface displacement of the new plastic strain.
            body.set_strain(&strain, &mut displacement)?;
            kept = true;
            let largest = kappa.iter().fold(0.0f64, |m, &k| m.max(k));
            let strain_residual = change / largest.max(yield_strain);
            let total = pressure.sum();
            let pressure_residual = if total > 0.0 {
                Zip::from(&pressure)
                    .and(&previous)
                    .fold(0.0, |s, &a, &b| s + (a - b).abs())
                    / total
            } else {
                0.0
            };
            // The first iteration of a loaded step compares with the previous step's pressure.
            residual = strain_residual.max(if iterations > 1 {
                pressure_residual
            } else {
                1.0
            });
            if iterations == 1 && load == 0.0 {
                residual = strain_residual;
            }
            progress(Progress {
                step,
                steps: count,
                iteration: iterations,
                residual,
            });
            if residual < control.tolerance {
                converged = true;
                break;
            }
        }
        let snapshot = control.snapshots.contains(&step);
        let final_stress =
            snapshot || observe.is_some() || (approach.is_some() && body.approach_needs_stress());
        if final_stress {
            // The stress of the final plastic strain and pressure.
            body.stress(&pressure, control.friction, &mut stress)?;
            kept = false;
        }
        let approach =
            approach.map(|contact| body.approach_m(contact, &stress, &strain, &pressure));
        let max_plastic_strain = kappa.iter().fold(0.0f64, |m, &k| m.max(k));
        steps.push(StepResult {
            load_n: load,
            approach_m: approach,
            max_pressure_pa: pressure.iter().fold(0.0f64, |m, &p| m.max(p)),
            contact_cells,
            axis_displacement_m: displacement[control.axis_cell],
            max_plastic_strain,
            plastic_cells: kappa.iter().filter(|&&k| k > PLASTIC_ZONE_STRAIN).count(),
            iterations,
            residual,
            converged,
        });
        if let (Some(observe), Some(result)) = (observe.as_mut(), steps.last()) {
            observe(&StepState {
                step,
                result,
                pressure_pa: &pressure,
                stress_pa: &stress,
                equivalent_plastic_strain: &kappa,
                plastic_displacement_m: &displacement,
            });
        }
        if snapshot {
            snapshots.push(Snapshot {
                step,
                load_n: load,
                approach_m: approach,
                pressure_pa: pressure.clone(),
                stress_pa: stress.clone(),
                equivalent_plastic_strain: kappa.clone(),
                plastic_strain: strain.clone(),
                plastic_displacement_m: displacement.clone(),
            });
        }
    }
    Ok(PlasticContactSolution { steps, snapshots })
}

/// The cells that flow in a step (the accelerated unknowns), with their plastic strain before
/// and after a return mapping.
pub(crate) struct Active {
    /// Flat cell indices `l ny nx + j nx + i`.
    pub(crate) cells: Vec<usize>,
    member: Vec<bool>,
    pub(crate) x: Vec<f64>,
    pub(crate) g: Vec<f64>,
    /// Cells that joined during the last return mapping.
    pub(crate) joined: Vec<usize>,
}

impl Active {
    pub(crate) fn new(cells: usize) -> Self {
        Self {
            cells: Vec::new(),
            member: vec![false; cells],
            x: Vec::new(),
            g: Vec::new(),
            joined: Vec::new(),
        }
    }

    pub(crate) fn clear(&mut self) {
        for &cell in &self.cells {
            self.member[cell] = false;
        }
        self.cells.clear();
        self.joined.clear();
    }
}

/// The plastic strain of `cells` (flat indices), six values each, into `out`.
pub(crate) fn gather(strain: &Array4<f64>, cells: &[usize], out: &mut Vec<f64>) {
    let (_, _, ny, nx) = strain.dim();
    let layer = ny * nx;
    out.clear();
    let Some(values) = strain.as_slice() else {
        return;
    };
    for &cell in cells {
        let (l, at) = (cell / layer, cell % layer);
        for c in 0..6 {
            out.push(values[(6 * l + c) * layer + at]);
        }
    }
}

/// The inverse of [`gather`].
pub(crate) fn scatter(strain: &mut Array4<f64>, cells: &[usize], values: &[f64]) {
    let (_, _, ny, nx) = strain.dim();
    let layer = ny * nx;
    let Some(target) = strain.as_slice_mut() else {
        return;
    };
    for (&cell, chunk) in cells.iter().zip(values.chunks_exact(6)) {
        let (l, at) = (cell / layer, cell % layer);
        for (c, value) in chunk.iter().enumerate() {
            target[(6 * l + c) * layer + at] = *value;
        }
    }
}

/// Returns every cell's trial stress `σ + C : (εp - εp_n)` onto the yield surface from
/// `κ_n` (`strain_start`, `kappa_start`), writing the new plastic strain and `κ`; the largest
/// change of the plastic strain (its equivalent). `lame` is `[λ, μ]`. Cells that flow for the
/// first time in the step join `active` (their `x` appended: the strain of the step's
/// start).
#[allow(clippy::too_many_arguments)]
pub(crate) fn return_mapping(
    stress: &Array4<f64>,
    strain: &mut Array4<f64>,
    strain_start: &Array4<f64>,
    kappa: &mut Array3<f64>,
    kappa_start: &Array3<f64>,
    hardening: &Hardening,
    lame: [f64; 2],
    active: &mut Active,
) -> f64 {
    let (nz, _, ny, nx) = stress.dim();
    let layer = ny * nx;
    let [lambda, mu] = lame;
    let mut change: f64 = 0.0;
    active.joined.clear();
    let (Some(stress), Some(strain), Some(start), Some(kappa), Some(kappa_start)) = (
        stress.as_slice(),
        strain.as_slice_mut(),
        strain_start.as_slice(),
        kappa.as_slice_mut(),
        kappa_start.as_slice(),
    ) else {
        // Arrays made here in standard layout: always contiguous.
        return f64::INFINITY;
    };
    for l in 0..nz {
        let base = 6 * layer * l;
        for cell in 0..layer {
            let at = |c: usize| base + c * layer + cell;
            let current: [f64; 6] = std::array::from_fn(|c| strain[at(c)]);
            let first: [f64; 6] = std::array::from_fn(|c| start[at(c)]);
            let delta: [f64; 6] = std::array::from_fn(|c| current[c] - first[c]);
            let trace = (delta[0] + delta[1] + delta[2]) * lambda;
            let trial: [f64; 6] = std::array::from_fn(|c| {
                let normal = if c < 3 { trace } else { 0.0 };
                stress[at(c)] + normal + 2.0 * mu * delta[c]
            });
            let k0 = kappa_start[l * layer + cell];
            let (next, k) = match radial_return(&trial, k0, hardening, mu) {
                None => (first, k0),
                Some((increment, dk)) => {
                    let flat = l * layer + cell;
                    if !active.member[flat] {
                        active.member[flat] = true;
                        active.cells.push(flat);
                        active.joined.push(flat);
                        active.x.extend_from_slice(&current);
                    }
                    (std::array::from_fn(|c| first[c] + increment[c]), k0 + dk)
                }
            };
            let moved: [f64; 6] = std::array::from_fn(|c| next[c] - current[c]);
            change = change.max(equivalent_strain(&moved));
            for (c, value) in next.iter().enumerate() {
                strain[at(c)] = *value;
            }
            kappa[l * layer + cell] = k;
        }
    }
    change
}

/// The equivalent plastic strain above which a cell belongs to the plastic zone.
pub const PLASTIC_ZONE_STRAIN: f64 = 1e-5;

/// The von Mises stress of each cell of a `[nz, 6, ny, nx]` stress, `[nz, ny, nx]`.
pub fn von_mises_field(stress: &Array4<f64>) -> Array3<f64> {
    let (nz, _, ny, nx) = stress.dim();
    let mut out = Array3::zeros((nz, ny, nx));
    for ((l, j, i), value) in out.indexed_iter_mut() {
        let s: [f64; 6] = std::array::from_fn(|c| stress[[l, c, j, i]]);
        *value = von_mises(&s);
    }
    out
}

/// The largest value of a `[nz, ny, nx]` field and its cell `[l, j, i]`.
pub fn largest(field: &Array3<f64>) -> (f64, [usize; 3]) {
    field
        .indexed_iter()
        .fold((f64::NEG_INFINITY, [0, 0, 0]), |best, ((l, j, i), &v)| {
            if v > best.0 {
                (v, [l, j, i])
            } else {
                best
            }
        })
}

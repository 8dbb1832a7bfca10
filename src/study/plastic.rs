//! The elastic-plastic contact of a `[plasticity]` scene (issue 51), computed once for the
//! command line (`stressfield plastic`), its JSON and its fields: a ball pressed on body 1,
//! elastic-plastic, in load steps, then unloaded.
//!
//! The volume grid is centred on the contact's axis: `grid_cells` cells along x and y over
//! `±extent_over_a` Hertz radii (a cell centred on the axis), `depth_cells` uniform layers
//! down to `depth_over_a` radii; the contact's grid is the volume's top face. The half-space
//! is isolated (DC-FFT, zero padding). What is reported from it is defined in
//! docs/plasticity.md.

use ndarray::{Array2, Array3};

use crate::contact::elliptic::EllipticalContact;
use crate::contact::{LineContact, PointContact};
use crate::operator::elastic::Periodicity;
use crate::plasticity::column::DepthCells;
use crate::plasticity::halfspace::VolumeGrid;
use crate::plasticity::j2::Hardening;
use crate::plasticity::loading::{
    self, largest, von_mises_field, PlasticContactError, PlasticContactProblem,
    PlasticContactSolution, Progress, Snapshot, PLASTIC_ZONE_STRAIN,
};
use crate::scene::{Hertz, PlasticitySpec, Scene};

pub mod history;
use history::StepHistory;

/// Iterations allowed in one load step.
pub const MAX_ITERATIONS: usize = 500;
/// Differences kept by the Anderson acceleration of each step's fixed point.
pub const ACCELERATION: usize = 5;
/// The contact solver's tolerance inside the loop.
pub const CONTACT_TOLERANCE: f64 = 1e-10;
/// The most memory a plastic solve may take (bytes): 4 GiB, the limit of fields.
pub const MEMORY_LIMIT_BYTES: usize = 4 << 30;

/// The loaded state at the full load.
#[derive(Clone, Debug, PartialEq)]
pub struct Loaded {
    pub max_pressure_pa: f64,
    /// The load over the contact area.
    pub mean_pressure_pa: f64,
    /// The area of the cells in contact (a line's per metre of length: its width times 1 m).
    pub contact_area_m2: f64,
    /// `√(A/π)`; a line's half the width of the cells in contact.
    pub contact_radius_m: f64,
    /// The indenter's displacement relative to the far surface from first contact.
    pub approach_m: f64,
    pub max_plastic_strain: f64,
    pub max_plastic_strain_depth_m: f64,
    /// The centre depth of the deepest cell with `εp > 1e-5` (0 without one).
    pub plastic_zone_depth_m: f64,
    /// A line's per metre of length: the plastic zone's area in the x–z section.
    pub plastic_volume_m3: f64,
    /// The largest von Mises stress of the total stress over the volume's cells.
    pub von_mises_max_pa: f64,
    pub von_mises_max_depth_m: f64,
    /// Hertz's peak pressure at the load (the elastic body).
    pub elastic_max_pressure_pa: f64,
}

/// The state after full unloading.
#[derive(Clone, Debug, PartialEq)]
pub struct Unloaded {
    /// The permanent surface displacement on the axis (m, into body 1).
    pub residual_depth_m: f64,
    pub residual_von_mises_max_pa: f64,
    pub residual_von_mises_max_depth_m: f64,
    /// The distance of that maximum from the axis.
    pub residual_von_mises_max_r_m: f64,
}

/// Everything computed of a `[plasticity]` scene.
#[derive(Clone, Debug)]
pub struct PlasticStudy {
    pub spec: PlasticitySpec,
    /// The elastic (Hertz) contact at the scene's load: a ball's own; for an elliptical
    /// contact the circle of the same load, area and peak pressure (radius `√(ab)`); for a
    /// rough map the circle of the elastic rough contact's area at the load and its peak
    /// pressure ([`PlasticKind`] holds the contact itself); a line's own.
    pub hertz: ElasticHertz,
    /// The contact's kind and what it adds.
    pub kind: PlasticKind,
    pub friction: f64,
    /// A line's body 2 modulus and Poisson's ratio (its approach, [`history::elastic_approach_m`]);
    /// `None` when body 2 is rigid, and for the other kinds (their approach is the contact
    /// solver's).
    pub counter: Option<(f64, f64)>,
    /// The volume grid (a line's: one row 1 m wide in y, [`line::row_grid`]).
    pub grid: VolumeGrid,
    /// Cell centres (m): x, y (from the axis) and depth z.
    pub x_m: Vec<f64>,
    pub y_m: Vec<f64>,
    pub z_m: Vec<f64>,
    pub solution: PlasticContactSolution,
    pub loaded: Loaded,
    pub unloaded: Option<Unloaded>,
    /// Whether every step converged.
    pub converged: bool,
    /// Iterations over all steps.
    pub iterations: usize,
    pub warnings: Vec<String>,
    /// Every step's load, approach, pressures and contact radius, and its section on `y = 0`
    /// (the sheet's curves, the recording's steps).
    pub history: StepHistory,
}

impl PlasticStudy {
    /// The state at the full load.
    pub fn loaded_snapshot(&self) -> &Snapshot {
        &self.solution.snapshots[0]
    }

    /// The state after unloading, if unloaded.
    pub fn unloaded_snapshot(&self) -> Option<&Snapshot> {
        self.unloaded.as_ref().and(self.solution.snapshots.get(1))
    }
}

/// The elastic contact of Hertz a plastic study is compared with: a circle (point, elliptical
/// and rough contacts) or a line (plane strain, per metre of length).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ElasticHertz {
    Point(PointContact),
    Line(LineContact),
}

impl ElasticHertz {
    /// The load: N, or N/m for a line.
    pub fn load(&self) -> f64 {
        match self {
            Self::Point(c) => c.load_n,
            Self::Line(c) => c.load_n_per_m,
        }
    }

    /// The contact radius `a` or a line's half-width `b` (m): the length the grid is measured
    /// in.
    pub fn size_m(&self) -> f64 {
        match self {
            Self::Point(c) => c.radius_m,
            Self::Line(c) => c.half_width_m,
        }
    }

    pub fn p0_pa(&self) -> f64 {
        match self {
            Self::Point(c) => c.p0_pa,
            Self::Line(c) => c.p0_pa,
        }
    }

    pub fn effective_modulus_pa(&self) -> f64 {
        match self {
            Self::Point(c) => c.effective_modulus_pa,
            Self::Line(c) => c.effective_modulus_pa,
        }
    }

    pub fn effective_radius_m(&self) -> f64 {
        match self {
            Self::Point(c) => c.effective_radius_m,
            Self::Line(c) => c.effective_radius_m,
        }
    }

    /// The circle's contact, `None` for a line.
    pub fn point(&self) -> Option<&PointContact> {
        match self {
            Self::Point(c) => Some(c),
            Self::Line(_) => None,
        }
    }
}

/// The contact a plastic study pressed.
#[derive(Clone, Debug, PartialEq)]
pub enum PlasticKind {
    /// A ball on a flat: [`PlasticStudy::hertz`] is its Hertz contact.
    Point,
    /// An elliptical paraboloid (Hertz's ellipse: `a` along x, `b` along y).
    Elliptical(EllipticalContact),
    /// A rough map.
    Rough(RoughPlastic),
    /// A cylinder or a roller in plane strain ([`line`]): the grid one row 1 m wide in y, so
    /// the areas and volumes are per metre of length.
    Line,
}

/// What a rough map's plastic study adds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughPlastic {
    pub periodic: bool,
    /// The elastic rough contact at the load (no hardness cap), on the same map: its
    /// largest pressure, its contact area, and the equivalent radius `√(A/π)` of its largest
    /// contact spot (the length the grid's depth is measured in).
    pub elastic_max_pressure_pa: f64,
    pub elastic_contact_area_m2: f64,
    pub largest_spot_radius_m: f64,
    /// The hardness-capped contact of the scene on the same map, when it has a hardness: its
    /// largest pressure (the cap, or below it) and the area of the cells at the cap.
    pub capped_max_pressure_pa: Option<f64>,
    pub capped_area_m2: Option<f64>,
    /// At the full load: the area of the columns whose top cell has `εp > 1e-5` (the plastic
    /// surface layer), and of those with such a cell at any depth (the plastic zone's
    /// footprint).
    pub surface_plastic_area_m2: f64,
    pub plastic_footprint_m2: f64,
}

/// What `stressfield plastic` and Python's `Scene.plastic()` say of a scene (`file`, as the
/// user named it) without `[plasticity]`: one message for both.
pub fn not_plastic_message(file: &str) -> String {
    format!(
        "{file} has no [plasticity]\nhint: add [plasticity] with yield_strength = \"1 GPa\" to a point, elliptical, line or rough contact (body 1 the elastic-plastic one, body 2 material = \"rigid\" allowed); see docs/plasticity.md"
    )
}

/// Why a plastic study failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PlasticStudyError {
    #[error("the scene has no [plasticity]")]
    NotPlastic,
    #[error(transparent)]
    Solve(#[from] PlasticContactError),
    /// The plastic zone reaches the volume grid's edge: the key to change and how.
    #[error("plasticity.{key}: {message}")]
    Grid { key: &'static str, message: String },
    #[error("the volume grid needs {needed_bytes} bytes, more than the {limit_bytes} allowed")]
    Memory {
        needed_bytes: usize,
        limit_bytes: usize,
    },
}

/// The volume grid of `spec` about a contact of radius `a_m`.
pub fn volume_grid(spec: &PlasticitySpec, a_m: f64) -> Result<VolumeGrid, PlasticStudyError> {
    let n = spec.grid_cells;
    let dx = 2.0 * spec.extent_over_a * a_m / n as f64;
    let depth = DepthCells::uniform(
        spec.depth_cells,
        spec.depth_over_a * a_m / spec.depth_cells as f64,
    )
    .map_err(|e| PlasticStudyError::Grid {
        key: "depth_cells",
        message: e.0,
    })?;
    Ok(VolumeGrid {
        shape: [n, n],
        spacing_m: [dx, dx],
        depth,
        periodicity: Periodicity::NonPeriodic,
    })
}

/// The bytes a solve of `spec` takes about a contact of radius `a_m` (the operator, the
/// iteration's fields, the contact solver and two kept states).
pub fn memory_bytes(spec: &PlasticitySpec, a_m: f64, sliding: bool) -> usize {
    match volume_grid(spec, a_m) {
        Ok(grid) => loading::memory_bytes(&grid, sliding) + 2 * loading::snapshot_bytes(&grid),
        Err(_) => 0,
    }
}

/// CPU seconds per cell and iteration of the load loop, measured on the shipped scene (64² ×
/// 32 cells, 118 iterations in 8.1 s of CPU).
pub const CPU_SECONDS_PER_CELL_ITERATION: f64 = 5.2e-7;
/// Iterations a load step takes (the shipped scene: 118 over 8 load and 4 unload steps, the
/// unload steps 2 each).
pub const ITERATIONS_PER_LOAD_STEP: f64 = 14.0;

/// A rough estimate of the CPU time of `spec`'s solve, s: the cells, times the iterations of
/// the load steps (two per unload step), times the measured cost of one.
pub fn cpu_seconds(spec: &PlasticitySpec) -> f64 {
    let cells = (spec.grid_cells * spec.grid_cells * spec.depth_cells) as f64;
    let unload = if spec.unload { spec.unload_steps } else { 0 };
    let iterations = ITERATIONS_PER_LOAD_STEP * spec.steps as f64 + 2.0 * unload as f64;
    cells * iterations * CPU_SECONDS_PER_CELL_ITERATION
}

/// CPU seconds per cell and iteration of a line contact's load loop (plane strain, its x–z
/// cells): 3.1e-7 to 6.1e-7 measured on the roller scene at 64 x 24, 128 x 48, 256 x 96 and
/// 512 x 48 cells (docs/plasticity.md), 4.5e-7 their middle.
pub const LINE_CPU_SECONDS_PER_CELL_ITERATION: f64 = 4.5e-7;

/// The most CPU time `check` lets a plastic scene's estimate take, s (an hour).
pub const CPU_LIMIT_SECONDS: f64 = 3600.0;

/// What a plastic scene's solve will take, before it runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlasticPlan {
    /// `[nz, ny, nx]` cells of the volume.
    pub cells: [usize; 3],
    pub steps: usize,
    pub bytes: usize,
    /// The estimate of [`cpu_seconds`] for this many cells.
    pub cpu_seconds: f64,
}

impl PlasticPlan {
    /// Why the plan is beyond the limits ([`MEMORY_LIMIT_BYTES`], [`CPU_LIMIT_SECONDS`]),
    /// naming the size, or `None`.
    pub fn beyond_limits(&self) -> Option<String> {
        let [nz, ny, nx] = self.cells;
        if self.bytes > MEMORY_LIMIT_BYTES {
            return Some(format!(
                "plasticity: the volume of {nx} x {ny} x {nz} cells needs {} MB, more than the {} MB allowed\nhint: fewer cells (plasticity.grid_cells, plasticity.depth_cells, or a smaller map)",
                self.bytes >> 20,
                MEMORY_LIMIT_BYTES >> 20
            ));
        }
        if self.cpu_seconds > CPU_LIMIT_SECONDS {
            return Some(format!(
                "plasticity: the volume of {nx} x {ny} x {nz} cells over {} steps would take about {:.0} s of CPU, more than the {CPU_LIMIT_SECONDS:.0} s allowed\nhint: fewer cells or steps",
                self.steps, self.cpu_seconds
            ));
        }
        None
    }
}

/// The plan of a `[plasticity]` scene's solve (`None` without one): its volume grid's cells
/// (a rough map's own, with `depth_cells` layers; a line's x–z cells, one row), the memory and
/// the CPU time estimated.
pub fn plan(scene: &Scene) -> Option<PlasticPlan> {
    let spec = scene.plasticity?;
    let sliding = scene.contact.friction != 0.0;
    let unload = if spec.unload { spec.unload_steps } else { 0 };
    let iterations = ITERATIONS_PER_LOAD_STEP * spec.steps as f64 + 2.0 * unload as f64;
    if scene.contact.kind == crate::scene::ContactKind::Line {
        // The depth's thickness and the cells' width do not change the cost.
        let line_grid = crate::plasticity::line::LineGrid {
            cells: spec.grid_cells,
            spacing_m: 1.0,
            depth: DepthCells::uniform(spec.depth_cells, 1.0).ok()?,
        };
        let grid = line::row_grid(&line_grid);
        let cells = (spec.grid_cells * spec.depth_cells) as f64;
        return Some(PlasticPlan {
            cells: [spec.depth_cells, 1, spec.grid_cells],
            steps: spec.steps + unload,
            bytes: solve_bytes(&grid, Some(&line_grid), sliding),
            cpu_seconds: cells * iterations * LINE_CPU_SECONDS_PER_CELL_ITERATION,
        });
    }
    let (shape, periodicity) = match (&scene.surface, scene.contact.rough) {
        (Some(surface), Some(rough)) if scene.contact.kind == crate::scene::ContactKind::Rough => (
            surface.heights.shape(),
            if rough.periodic {
                Periodicity::Periodic
            } else {
                Periodicity::NonPeriodic
            },
        ),
        _ => ([spec.grid_cells, spec.grid_cells], Periodicity::NonPeriodic),
    };
    // The depth's thickness does not change the cost.
    let grid = VolumeGrid {
        shape,
        spacing_m: [1.0, 1.0],
        depth: DepthCells::uniform(spec.depth_cells, 1.0).ok()?,
        periodicity,
    };
    let bytes = loading::memory_bytes(&grid, sliding) + 2 * loading::snapshot_bytes(&grid);
    let cells = (shape[0] * shape[1] * spec.depth_cells) as f64;
    Some(PlasticPlan {
        cells: [spec.depth_cells, shape[0], shape[1]],
        steps: spec.steps + unload,
        bytes,
        cpu_seconds: cells * iterations * CPU_SECONDS_PER_CELL_ITERATION,
    })
}

/// The loads of the steps: `steps` equal increments up to `load_n`, then `unload_steps` down
/// to zero when unloading.
pub fn step_loads(spec: &PlasticitySpec, load_n: f64) -> Vec<f64> {
    let mut loads: Vec<f64> = (1..=spec.steps)
        .map(|i| load_n * i as f64 / spec.steps as f64)
        .collect();
    if spec.unload {
        loads.extend(
            (1..=spec.unload_steps)
                .map(|i| load_n * (1.0 - i as f64 / spec.unload_steps as f64).max(0.0)),
        );
    }
    loads
}

/// The study of a `[plasticity]` scene; `progress` after every iteration.
pub fn study(
    scene: &Scene,
    progress: &mut dyn FnMut(Progress),
) -> Result<PlasticStudy, PlasticStudyError> {
    let spec = scene.plasticity.ok_or(PlasticStudyError::NotPlastic)?;
    if scene.contact.kind == crate::scene::ContactKind::Rough {
        return rough::study_rough(scene, &spec, progress);
    }
    match scene.contact.dimensional.map(|d| d.hertz) {
        Some(Hertz::Point(hertz)) => study_point(&spec, &hertz, scene.contact.friction, progress),
        Some(Hertz::Elliptical(ellipse)) => {
            elliptic::study_elliptical(&spec, &ellipse, scene.contact.friction, progress)
        }
        Some(Hertz::Line(hertz)) => {
            let body2 = scene
                .contact
                .dimensional
                .map(|d| d.body2.material)
                .filter(|m| m.modulus_pa.is_finite())
                .map(|m| (m.modulus_pa, m.poisson));
            line::study_line(&spec, &hertz, body2, scene.contact.friction, progress)
        }
        _ => Err(PlasticStudyError::NotPlastic),
    }
}

/// The study of a ball pressed on an elastic-plastic body 1 (`hertz` its elastic contact).
pub fn study_point(
    spec: &PlasticitySpec,
    hertz: &PointContact,
    friction: f64,
    progress: &mut dyn FnMut(Progress),
) -> Result<PlasticStudy, PlasticStudyError> {
    let grid = volume_grid(spec, hertz.radius_m)?;
    let [_, ny, nx] = grid.dims();
    let [dx, dy] = grid.spacing_m;
    let x_m: Vec<f64> = (0..nx).map(|i| (i as f64 - (nx / 2) as f64) * dx).collect();
    let y_m: Vec<f64> = (0..ny).map(|j| (j as f64 - (ny / 2) as f64) * dy).collect();
    let radius = hertz.effective_radius_m;
    // The gap of a ball on a flat: heights out of body 1, highest on the axis.
    let heights = Array2::from_shape_fn((ny, nx), |(j, i)| {
        -(x_m[i] * x_m[i] + y_m[j] * y_m[j]) / (2.0 * radius)
    });
    let setup = Setup {
        hertz: ElasticHertz::Point(*hertz),
        kind: PlasticKind::Point,
        grid,
        x_m,
        y_m,
        body: SetupBody::Volume { heights },
        elastic_max_pressure_pa: hertz.p0_pa,
        edges: Edges::Bounded,
    };
    solve_setup(spec, setup, friction, progress)
}

/// Where the volume grid's sides are: keys to raise (a smooth contact's grid about the Hertz
/// ellipse), the edges of an isolated map (warned about: the map is the grid), or none
/// (periodic).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Edges {
    /// `extent_over_a` and `depth_over_a` size the grid.
    Bounded,
    /// The map's edges; `depth_over_a` sizes the depth.
    Map,
    /// A periodic map: no sides.
    Periodic,
}

/// A contact's undeformed gap on its volume grid, ready to be loaded.
#[derive(Clone, Debug)]
pub(crate) struct Setup {
    /// The Hertz contact reported beside the result ([`PlasticStudy::hertz`]).
    pub hertz: ElasticHertz,
    pub kind: PlasticKind,
    /// The volume grid (a line's: one row 1 m wide, [`line::row_grid`]).
    pub grid: VolumeGrid,
    /// Cell centres from the axis (the map's centre), m.
    pub x_m: Vec<f64>,
    pub y_m: Vec<f64>,
    pub body: SetupBody,
    pub elastic_max_pressure_pa: f64,
    pub edges: Edges,
}

/// What is pressed: a 3-D half-space under a gap, or a plane-strain x–z volume.
#[derive(Clone, Debug)]
pub(crate) enum SetupBody {
    /// The undeformed gap as heights out of body 1 (`[ny, nx]`).
    Volume { heights: Array2<f64> },
    /// The x–z grid, the undeformed gap (m, one per column) and body 2's modulus and
    /// Poisson's ratio (`None`: rigid).
    Line {
        grid: crate::plasticity::line::LineGrid,
        gap_m: Vec<f64>,
        counter: Option<(f64, f64)>,
    },
}

/// The bytes of a solve on `grid` (a line's one-row grid with `body`), two states kept.
fn solve_bytes(
    grid: &VolumeGrid,
    line: Option<&crate::plasticity::line::LineGrid>,
    sliding: bool,
) -> usize {
    let solver = match line {
        Some(line) => crate::plasticity::line::memory_bytes(line),
        None => loading::memory_bytes(grid, sliding),
    };
    solver + 2 * loading::snapshot_bytes(grid)
}

/// The study of `setup` loaded to `setup.hertz.load()` in `spec`'s steps.
pub(crate) fn solve_setup(
    spec: &PlasticitySpec,
    setup: Setup,
    friction: f64,
    progress: &mut dyn FnMut(Progress),
) -> Result<PlasticStudy, PlasticStudyError> {
    let Setup {
        hertz,
        kind,
        grid,
        x_m,
        y_m,
        body,
        elastic_max_pressure_pa,
        edges,
    } = setup;
    let line_grid = match &body {
        SetupBody::Line { grid, .. } => Some(grid),
        SetupBody::Volume { .. } => None,
    };
    let needed_bytes = solve_bytes(&grid, line_grid, friction != 0.0);
    if needed_bytes > MEMORY_LIMIT_BYTES {
        return Err(PlasticStudyError::Memory {
            needed_bytes,
            limit_bytes: MEMORY_LIMIT_BYTES,
        });
    }
    let [nz, ny, nx] = grid.dims();
    let [dx, dy] = grid.spacing_m;
    let z_m = grid.depth.centres_m();
    let loads = step_loads(spec, hertz.load());
    let axis_cell = [ny / 2, nx / 2];
    let loaded_step = spec.steps - 1;
    let mut snapshots = vec![loaded_step];
    if spec.unload {
        snapshots.push(loads.len() - 1);
    }
    let hardening = Hardening {
        yield_strength_pa: spec.yield_strength_pa,
        plastic_modulus_pa: spec.hardening_modulus_pa,
    };
    let is_line = line_grid.is_some();
    let counter = match &body {
        SetupBody::Line { counter, .. } => *counter,
        SetupBody::Volume { .. } => None,
    };
    let mut history = StepHistory::default();
    let mut observe = |state: &loading::StepState| history.push(state, dx * dy, ny / 2, is_line);
    let solution = match body {
        SetupBody::Volume { heights } => {
            let problem = PlasticContactProblem {
                heights_m: heights.view(),
                grid: grid.clone(),
                modulus_pa: spec.body1.modulus_pa,
                poisson: spec.body1.poisson,
                e_star_pa: hertz.effective_modulus_pa(),
                hardening,
                friction,
                loads_n: loads,
                snapshots,
                axis_cell,
                tolerance: spec.tolerance,
                max_iterations: MAX_ITERATIONS,
                acceleration: ACCELERATION,
                contact_tolerance: CONTACT_TOLERANCE,
                memory_limit_bytes: MEMORY_LIMIT_BYTES,
            };
            loading::solve_observed(&problem, progress, Some(&mut observe))?
        }
        SetupBody::Line {
            grid: line_grid,
            gap_m,
            counter,
        } => {
            let problem = crate::plasticity::line::LinePlasticProblem {
                gap_m,
                grid: line_grid,
                modulus_pa: spec.body1.modulus_pa,
                poisson: spec.body1.poisson,
                counter,
                e_star_pa: hertz.effective_modulus_pa(),
                hardening,
                friction,
                loads_n_per_m: loads,
                snapshots,
                tolerance: spec.tolerance,
                max_iterations: MAX_ITERATIONS,
                acceleration: ACCELERATION,
            };
            crate::plasticity::line::solve(&problem, progress, Some(&mut observe))?
        }
    };
    let loaded_state = &solution.snapshots[0];
    let kappa = &loaded_state.equivalent_plastic_strain;
    // The plastic zone must lie inside the grid: not in its deepest layer, nor on its sides.
    let mut at_bottom = false;
    let mut at_side = false;
    for ((l, j, i), &k) in kappa.indexed_iter() {
        if k > PLASTIC_ZONE_STRAIN {
            at_bottom |= l + 1 == nz;
            // A line's one row has no sides in y.
            at_side |= i == 0 || i + 1 == nx || (ny > 1 && (j == 0 || j + 1 == ny));
        }
    }
    // The length the grid is measured in: a line's half-width b, else a.
    let unit = if is_line { "b" } else { "a" };
    if at_bottom {
        return Err(PlasticStudyError::Grid {
            key: "depth_over_a",
            message: format!(
                "the plastic zone reaches the volume grid's bottom ({:.3} {unit}): the grid is too shallow for it\nhint: raise depth_over_a (e.g. to {:.1}) and depth_cells with it",
                spec.depth_over_a,
                spec.depth_over_a * 2.0
            ),
        });
    }
    let mut warnings = Vec::new();
    if at_side && edges == Edges::Map {
        warnings.push(
            "the plastic zone reaches the map's edge: the isolated map ends there, so the flow beyond it is not computed; crop the map about the contact, or solve it periodic (contact.periodic = true) if it tiles".to_string(),
        );
    }
    if at_side && edges == Edges::Bounded {
        return Err(PlasticStudyError::Grid {
            key: "extent_over_a",
            message: format!(
                "the plastic zone reaches the volume grid's sides (±{:.3} {unit}): the grid is too narrow for it\nhint: raise extent_over_a (e.g. to {:.1}) and grid_cells with it",
                spec.extent_over_a,
                spec.extent_over_a * 2.0
            ),
        });
    }
    let loaded_step_result = &solution.steps[loaded_step];
    let contact_area_m2 = loaded_step_result.contact_cells as f64 * dx * dy;
    let (max_plastic_strain, at_strain) = largest(kappa);
    let mut plastic_zone_depth_m: f64 = 0.0;
    let mut plastic_volume_m3 = 0.0;
    for ((l, _, _), &k) in kappa.indexed_iter() {
        if k > PLASTIC_ZONE_STRAIN {
            plastic_zone_depth_m = plastic_zone_depth_m.max(z_m[l]);
            plastic_volume_m3 += grid.cell_volume_m3(l);
        }
    }
    let plastic = max_plastic_strain > PLASTIC_ZONE_STRAIN;
    let von_mises = von_mises_field(&loaded_state.stress_pa);
    let (von_mises_max_pa, at_von_mises) = largest(&von_mises);
    let loaded = Loaded {
        max_pressure_pa: loaded_step_result.max_pressure_pa,
        mean_pressure_pa: if contact_area_m2 > 0.0 {
            hertz.load() / contact_area_m2
        } else {
            0.0
        },
        contact_area_m2,
        contact_radius_m: if is_line {
            contact_area_m2 / (2.0 * line::ROW_WIDTH_M)
        } else {
            (contact_area_m2 / std::f64::consts::PI).sqrt()
        },
        approach_m: loaded_step_result.approach_m.unwrap_or(0.0),
        max_plastic_strain: if plastic { max_plastic_strain } else { 0.0 },
        max_plastic_strain_depth_m: if plastic { z_m[at_strain[0]] } else { 0.0 },
        plastic_zone_depth_m,
        plastic_volume_m3,
        von_mises_max_pa,
        von_mises_max_depth_m: z_m[at_von_mises[0]],
        elastic_max_pressure_pa,
    };
    let unloaded = spec.unload.then(|| {
        let state = &solution.snapshots[1];
        let residual = von_mises_field(&state.stress_pa);
        let (value, [l, j, i]) = largest(&residual);
        // No residual stress (an elastic contact): no place of its maximum either.
        let stressed = value > 0.0;
        Unloaded {
            // A rough map has no axis: its largest permanent surface displacement.
            residual_depth_m: match kind {
                PlasticKind::Rough(_) => state
                    .plastic_displacement_m
                    .iter()
                    .fold(0.0f64, |m, &u| m.max(u)),
                _ => state.plastic_displacement_m[axis_cell],
            },
            residual_von_mises_max_pa: value,
            residual_von_mises_max_depth_m: if stressed { z_m[l] } else { 0.0 },
            residual_von_mises_max_r_m: if stressed { x_m[i].hypot(y_m[j]) } else { 0.0 },
        }
    });
    let converged = solution.steps.iter().all(|s| s.converged);
    let iterations = solution.steps.iter().map(|s| s.iterations).sum();
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
    if loaded.max_plastic_strain > LARGE_PLASTIC_STRAIN {
        warnings.push(large_strain_message(loaded.max_plastic_strain));
    }
    Ok(PlasticStudy {
        spec: *spec,
        hertz,
        kind,
        friction,
        counter,
        grid,
        x_m,
        y_m,
        z_m,
        solution,
        loaded,
        unloaded,
        converged,
        iterations,
        warnings,
        history,
    })
}

/// The equivalent plastic strain beyond which a warning says that small strains no longer
/// hold: at 5 % the engineering and the logarithmic strain differ by 2.5 % of the strain, and
/// the rotations of the material, of the same order, are no longer small against the elastic
/// strains at yield (Y/E ≈ 0.5 % for steel) that the half-space's influence functions assume.
pub const LARGE_PLASTIC_STRAIN: f64 = 0.05;

/// The warning for a largest equivalent plastic strain beyond [`LARGE_PLASTIC_STRAIN`].
pub fn large_strain_message(max_plastic_strain: f64) -> String {
    format!(
        "the largest plastic strain {max_plastic_strain:.3} exceeds {LARGE_PLASTIC_STRAIN}: small strains no longer hold there (a finite-strain model would be needed for its value; the loads and the contact stay close)"
    )
}

/// The equivalent plastic strain after the last step (`[nz, ny, nx]`).
pub fn final_plastic_strain(study: &PlasticStudy) -> &Array3<f64> {
    let last = study.solution.snapshots.len() - 1;
    &study.solution.snapshots[last].equivalent_plastic_strain
}

/// The surface displacement of the plastic strain after the last step (m, into body 1,
/// `[ny, nx]`): after unloading, the dent's profile.
pub fn final_surface_displacement(study: &PlasticStudy) -> &Array2<f64> {
    let last = study.solution.snapshots.len() - 1;
    &study.solution.snapshots[last].plastic_displacement_m
}

/// A state's stress `[nz, 6, ny, nx]` with its components last, `[nz, ny, nx, 6]` (xx, yy, zz,
/// yz, xz, xy): the order of the `--fields` archive and of the Python package.
pub fn components_last(stress: &ndarray::Array4<f64>) -> ndarray::Array4<f64> {
    let (nz, _, ny, nx) = stress.dim();
    ndarray::Array4::from_shape_fn((nz, ny, nx, 6), |(l, j, i, c)| stress[[l, c, j, i]])
}

pub mod elliptic;
pub mod line;
pub mod rough;

#[cfg(test)]
mod tests;

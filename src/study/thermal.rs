//! What a scene with `[thermal]` computes: the frictional flux on a grid (the Hertz pressure,
//! or the solved rough pressure), the bodies' flash temperatures and the heat partition, and
//! body 1's thermal stress added to the contact stress, searched over depth for the maxima.
//!
//! Grids: a Hertz contact is gridded over a [`Window`], here [`STUDY_WINDOW`]:
//! `-2.5a <= x <= 1.5a` (the wake lies behind, at -x) and `|y| <= 1.5b`, with cells of `a/20`
//! or finer, fine enough that the cell Péclet number `V dx / (2κ)` stays within
//! [`MAX_CELL_PECLET`] (the speed sweep, [`crate::study::thermal_sweep`], takes a wider
//! window); a line contact (plane problem) takes the same x range as a row of strips for the
//! temperature and the thermal stress (plane strain), and for the contact stress a band of
//! rows long enough in y (`|y| <= max(6a, 6 √(a/u))`, `u = V/(2κ)`) that the middle row sees
//! the band as endless (its contact stress is McEwen's closed form, so the band serves the
//! maps). A rough contact uses the surface's own grid, the window taken as the nominal
//! contact. The stresses and their maxima: [`crate::study::heated_stress`].

use ndarray::{Array2, Array3};

use crate::contact::rough::{self, Control, RoughContactProblem, RoughSolution};
use crate::operator::elastic::Periodicity;
use crate::operator::transform::TransformError;
use crate::scene::Hertz;
use crate::scene::{ContactKind, Scene, ThermalBody, ThermalSpec};
use crate::solution::dcfft::{DcFft, DcFftError, TractionGrid, TractionGridError};
use crate::solution::Solution;
use crate::study::coupled::{self, CoupledContact, CoupledError};
use crate::study::heated_stress::{
    HeatedStress, Parts, CONTACT_MAX_SHEAR, CONTACT_VON_MISES, DEPTH_TOLERANCE_OVER_A,
    THERMAL_VON_MISES, TOTAL_MAX_SHEAR, TOTAL_VON_MISES,
};
use crate::study::thermal_sections::SECTION_DEPTH_OVER_A;
use crate::thermal::heating::frictional_flux;
use crate::thermal::kernel::CellGrid;
use crate::thermal::line::LineTemperature;
use crate::thermal::line_stress::LineThermalStress;
use crate::thermal::stress::ThermalStressOperator;
use crate::thermal::temperature::{TemperatureOperator, MAX_CELL_PECLET};

/// Depths of the stress maxima search, in units of the half-width `a`.
pub const DEPTHS_OVER_A: [f64; 16] = [
    0.0, 0.005, 0.01, 0.02, 0.04, 0.07, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.3,
];

/// The depth, in cells, to which a rough contact's search computes the thermal layer at
/// every coarse depth (beyond it, at every other one: [`crate::study::heated_search`]).
pub const DENSE_CELLS: f64 = 5.0;

/// How many of the increasing `coarse` depths lie within [`DENSE_CELLS`] cells of `dz`: those
/// whose thermal layers a rough contact's search computes every one.
pub(crate) fn dense_depths(coarse: &[f64], dz: f64) -> usize {
    coarse
        .iter()
        .filter(|&&z| z <= DENSE_CELLS * dz * (1.0 + 1e-9))
        .count()
}

/// The most cells a Hertz contact's thermal grid takes along x.
pub const MAX_CELLS: usize = 640;

/// Why the heating of a scene cannot be computed.
#[derive(Debug, thiserror::Error)]
pub enum ThermalStudyError {
    #[error("the scene has no [thermal] table")]
    NoThermal,
    #[error("a spur-gear scene is heated along its path of contact (study::gear_heating), not at the pitch point, where the teeth roll")]
    GearScene,
    #[error("the scene is not a pair of running spur gears ([contact.gears] with [thermal] pinion_speed)")]
    NotGears,
    #[error("{key}: the cell Péclet number V dx / (2κ) of body {body} is {cell_peclet:.3}, more than {MAX_CELL_PECLET} the grid resolves (the heat penetrates less than a cell while the contact crosses one)\nhint: {hint}")]
    CellPeclet {
        key: &'static str,
        body: usize,
        cell_peclet: f64,
        hint: &'static str,
    },
    #[error("sweep.parameter: {message}\nhint: {hint}")]
    PecletSweep {
        message: &'static str,
        hint: &'static str,
    },
    #[error("thermal.coupled: the coupled solution of a {0} contact needs its bodies (radii and materials) and load\nhint: give contact.load with [contact.body1] and [contact.body2], or set coupled = false")]
    CoupledNeedsBodies(&'static str),
    #[error(transparent)]
    Coupled(#[from] CoupledError),
    #[error("the contact stress of the heated contact: {0}")]
    Contact(String),
    #[error(transparent)]
    Transform(#[from] TransformError),
    #[error(transparent)]
    DcFft(#[from] DcFftError),
    #[error(transparent)]
    Tractions(#[from] TractionGridError),
}

/// The heating of one body.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyHeating {
    /// `V a / (2κ)`.
    pub peclet: f64,
    /// Its share of the heat.
    pub share: f64,
    /// The surface temperature rise on the grid (K), `[ny, nx]`, under its share.
    pub temperature_k: Array2<f64>,
    pub max_temperature_rise_k: f64,
    /// The mean over the contact (cells with pressure).
    pub mean_temperature_rise_k: f64,
    /// Where the maximum is, m from the contact's centre.
    pub max_at_m: [f64; 2],
}

/// A stress maximum and where it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Maximum {
    pub value_pa: f64,
    pub x_m: f64,
    pub y_m: f64,
    pub depth_m: f64,
}

impl Maximum {
    pub(crate) const NONE: Maximum = Maximum {
        value_pa: f64::NEG_INFINITY,
        x_m: 0.0,
        y_m: 0.0,
        depth_m: 0.0,
    };
}

/// Everything a thermal scene computes.
#[derive(Clone, Debug, PartialEq)]
pub struct ThermalStudy {
    pub spec: ThermalSpec,
    /// The length `a` of the Péclet number (half-width, radius, semi-axis along x, or half the
    /// rough window), m.
    pub half_width_m: f64,
    /// The grid: `[ny, nx]`, `[dx, dy]` (m), and the centre of cell `[0, 0]` relative to the
    /// contact's centre (m).
    pub shape: [usize; 2],
    pub spacing_m: [f64; 2],
    pub origin_m: [f64; 2],
    /// The contact pressure (Pa) on the grid (the heated one when coupled) and the frictional
    /// flux (W/m²) it makes.
    pub pressure_pa: Array2<f64>,
    pub flux_w_per_m2: Array2<f64>,
    pub body1: BodyHeating,
    pub body2: Option<BodyHeating>,
    /// Largest von Mises stress of the thermal stress alone, of the contact stress alone, and
    /// of their sum, over the grid and [`DEPTHS_OVER_A`].
    pub thermal_von_mises: Maximum,
    pub contact_von_mises: Maximum,
    pub total_von_mises: Maximum,
    /// Largest maximum (Tresca) shear stress `(σ1 − σ3)/2` of the contact and of the total.
    pub contact_max_shear: Maximum,
    pub total_max_shear: Maximum,
    /// The coupled thermo-mechanical contact (`coupled = true`): the heating and stresses
    /// above are those of its heated pressure.
    pub coupled: Option<CoupledContact>,
    /// A line contact (plane problem): every row is the same.
    pub line: bool,
    /// Where the contact stress comes from.
    pub contact_model: ContactModel,
    /// The friction coefficient on body 1, negative when it acts in −x.
    pub signed_friction: f64,
    /// How the maxima were searched.
    pub search: Search,
    /// How deep the heating sheet's sections reach (m): 1.2a for a Hertz contact; for a rough
    /// one where its stresses live: four times the deepest maximum, at least 16 cells, at most
    /// twice `contact`'s search depth.
    pub section_depth_m: f64,
}

/// Where a heating study's contact stress comes from ([`crate::study::heated_stress`]).
#[derive(Clone, Debug, PartialEq)]
pub enum ContactModel {
    /// The exact closed form (line, sphere) in units of `p0` and `a`, with the heating's
    /// traction.
    ClosedForm { solution: Solution, p0_pa: f64 },
    /// DC-FFT layers of the gridded pressure (elliptical contacts, a coupled contact's heated
    /// pressure).
    Gridded,
    /// A rough contact's tractions, periodic when the contact is (as `contact`'s).
    Rough { periodic: bool },
}

/// How a heating study searched its maxima: cell centres of layers at `coarse_depths`
/// depths down to `depth_m`, refined in depth to `tolerance_m`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Search {
    pub coarse_depths: usize,
    pub depth_m: f64,
    pub tolerance_m: f64,
}

/// What the study reports while it works.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Progress {
    /// A coupled iteration done, with its relative change of pressure.
    Coupled { iteration: usize, change: f64 },
    /// Depths of the stress search done, of `total`.
    Depth { done: usize, total: usize },
    /// Points of a gear's path of contact done, of `total`.
    Path { done: usize, total: usize },
}

/// `u = V / (2κ)` of a body.
pub(crate) fn inverse_length(body: &ThermalBody) -> f64 {
    body.speed_m_per_s / (2.0 * body.properties.diffusivity_m2_per_s)
}

/// The grid and pressure of a scene.
pub(super) struct Gridded {
    pub(super) shape: [usize; 2],
    pub(super) spacing_m: [f64; 2],
    pub(super) origin_m: [f64; 2],
    pub(super) pressure_pa: Array2<f64>,
    pub(super) half_width_m: f64,
    pub(super) line: bool,
}

/// Where and how finely a Hertz contact is gridded.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Window {
    /// The x range in units of `a` (the wake trails at -x).
    pub(super) x_over_a: [f64; 2],
    /// `|y| <=` this times `b` (point and elliptical contacts).
    pub(super) y_over_b: f64,
    /// The most cells along x.
    pub(super) max_cells: usize,
    /// An odd number of rows, the middle one centred on `y = 0` (point and elliptical).
    pub(super) centre_row: bool,
    /// The key a too high speed is reported under, and the fix.
    pub(super) key: &'static str,
    pub(super) hint: &'static str,
}

/// The study's window: `-2.5a <= x <= 1.5a`, `|y| <= 1.5b`, at most [`MAX_CELLS`] cells, a
/// row on `y = 0` (where the closed form's maxima lie, so that the sheet's sections through
/// them pass through the contact's plane of symmetry).
pub(crate) const STUDY_WINDOW: Window = Window {
    x_over_a: [-2.5, 1.5],
    y_over_b: 1.5,
    max_cells: MAX_CELLS,
    centre_row: true,
    key: "thermal.speed",
    hint: "the Péclet number is beyond what a grid of at most 640 cells across 4a resolves (Pe up to 320); lower the speed (beyond, the flash temperature follows the fast limit of Jaeger and Blok, growing as √Pe)",
};

/// Where the cells of a Hertz contact's thermal grid lie: `[ny, nx]`, `[dx, dy]` (m), and the
/// centre of cell `[0, 0]` (m from the contact's centre).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Layout {
    pub(crate) shape: [usize; 2],
    pub(crate) spacing_m: [f64; 2],
    pub(crate) origin_m: [f64; 2],
}

/// The grid of `scene` on `window` (see [`hertz_grid`]), without computing anything: what the
/// admission of a scene ([`plan`]) and the study share.
pub(crate) fn hertz_layout(
    scene: &Scene,
    spec: &ThermalSpec,
    window: &Window,
) -> Result<Layout, ThermalStudyError> {
    let contact = &scene.contact;
    let a = contact.half_width_m();
    let line = contact.kind == ContactKind::Line;
    let b = a * contact.aspect;
    let u = std::iter::once(&spec.body1)
        .chain(spec.body2.iter())
        .map(inverse_length)
        .fold(0.0, f64::max);
    let width = (window.x_over_a[1] - window.x_over_a[0]) * a;
    let mut dx = a / 20.0;
    if u * dx > 1.0 {
        dx = 1.0 / u;
    }
    let mut nx = (width / dx).ceil() as usize;
    if nx > window.max_cells {
        nx = window.max_cells;
        let cell_peclet = u * width / nx as f64;
        if cell_peclet > MAX_CELL_PECLET {
            let body = if inverse_length(&spec.body1) >= u {
                1
            } else {
                2
            };
            return Err(ThermalStudyError::CellPeclet {
                key: speed_key(spec, body, window),
                body,
                cell_peclet,
                hint: window.hint,
            });
        }
    }
    let dx = width / nx as f64;
    let x0 = window.x_over_a[0] * a + 0.5 * dx;
    let (ny, dy, y0) = if line {
        let u1 = inverse_length(&spec.body1);
        let half = (6.0 * a).max(6.0 * (a / u1).sqrt()).min(40.0 * a);
        // An odd number of rows, one centred on y = 0, each at least a cell wide.
        let dy = (half / 24.0).max(dx);
        let rows = 2 * (half / dy).ceil() as usize + 1;
        (rows, dy, -((rows / 2) as f64) * dy)
    } else {
        // Cells of the contact's aspect: as many across the window's height in b as across
        // its width in a.
        let height = 2.0 * window.y_over_b * b;
        let dy = dx * b / a;
        let mut ny = (height / dy).ceil() as usize;
        if window.centre_row && ny.is_multiple_of(2) {
            ny += 1;
        }
        let dy = height / ny as f64;
        // With a centre row, its y is exactly 0.
        let y0 = if window.centre_row {
            -((ny / 2) as f64) * dy
        } else {
            -window.y_over_b * b + 0.5 * dy
        };
        (ny, dy, y0)
    };
    Ok(Layout {
        shape: [ny, nx],
        spacing_m: [dx, dy],
        origin_m: [x0, y0],
    })
}

/// The key a speed too high for `window` is refused under: the window's own (a speed sweep's
/// `sweep.parameter`), or the scene key that set body `body`'s speed.
fn speed_key(spec: &ThermalSpec, body: usize, window: &Window) -> &'static str {
    if window.key == STUDY_WINDOW.key {
        spec.speed_keys[body.clamp(1, 2) - 1]
    } else {
        window.key
    }
}

/// The Hertz pressure of `scene` on `window`, with cells of `a/20`, or finer so that every
/// heated body of `spec` has a cell Péclet number of at most 1, or (at most
/// `window.max_cells` cells along x) at most [`MAX_CELL_PECLET`].
pub(super) fn hertz_grid(
    scene: &Scene,
    spec: &ThermalSpec,
    window: &Window,
) -> Result<Gridded, ThermalStudyError> {
    let contact = &scene.contact;
    let a = contact.half_width_m();
    let p0 = contact.p0_pa();
    let line = contact.kind == ContactKind::Line;
    let b = a * contact.aspect;
    let Layout {
        shape: [ny, nx],
        spacing_m: [dx, dy],
        origin_m: [x0, y0],
    } = hertz_layout(scene, spec, window)?;
    let pressure = Array2::from_shape_fn((ny, nx), |(row, column)| {
        let x = x0 + column as f64 * dx;
        let y = y0 + row as f64 * dy;
        let r2 = if line {
            (x / a).powi(2)
        } else {
            (x / a).powi(2) + (y / b).powi(2)
        };
        p0 * (1.0 - r2).max(0.0).sqrt()
    });
    Ok(Gridded {
        shape: [ny, nx],
        spacing_m: [dx, dy],
        origin_m: [x0, y0],
        pressure_pa: pressure,
        half_width_m: a,
        line,
    })
}

fn rough_grid(solution: &RoughSolution) -> Gridded {
    let [ny, nx] = [solution.pressure_pa.nrows(), solution.pressure_pa.ncols()];
    let [dx, dy] = solution.spacing_m;
    Gridded {
        shape: [ny, nx],
        spacing_m: [dx, dy],
        origin_m: [-0.5 * (nx as f64 - 1.0) * dx, -0.5 * (ny as f64 - 1.0) * dy],
        pressure_pa: solution.pressure_pa.clone(),
        half_width_m: 0.5 * nx as f64 * dx,
        line: false,
    }
}

/// The heating of one body under `flux` (its whole), scaled to `share` later.
pub(super) fn body_temperature(
    gridded: &Gridded,
    body: &ThermalBody,
    flux: &Array2<f64>,
) -> Result<Array2<f64>, ThermalStudyError> {
    let u = inverse_length(body);
    let k = body.properties.conductivity_w_per_m_k;
    let grid = CellGrid {
        shape: gridded.shape,
        spacing_m: gridded.spacing_m,
    };
    Ok(if gridded.line {
        // The plane problem: one row of strips, the same on every row.
        let middle = gridded.shape[0] / 2;
        let row: Vec<f64> = flux.row(middle).to_vec();
        let line = LineTemperature::new(row.len(), gridded.spacing_m[0], 0.0, u, k);
        let t = line.apply(&row);
        Array2::from_shape_fn(gridded.shape, |(_, c)| t[c])
    } else {
        TemperatureOperator::new(&grid, 0.0, u, k)?.apply(flux.view())?
    })
}

pub(super) fn heating(
    gridded: &Gridded,
    temperature: &Array2<f64>,
    share: f64,
    peclet: f64,
) -> BodyHeating {
    let t = temperature.mapv(|v| v * share);
    let mut best = (f64::NEG_INFINITY, 0, 0);
    let (mut sum, mut count) = (0.0, 0usize);
    let rows: Vec<usize> = if gridded.line {
        vec![gridded.shape[0] / 2]
    } else {
        (0..gridded.shape[0]).collect()
    };
    for &row in &rows {
        for column in 0..gridded.shape[1] {
            let value = t[[row, column]];
            if value > best.0 {
                best = (value, row, column);
            }
            if gridded.pressure_pa[[row, column]] > 0.0 {
                sum += value;
                count += 1;
            }
        }
    }
    BodyHeating {
        peclet,
        share,
        max_temperature_rise_k: best.0,
        mean_temperature_rise_k: if count > 0 { sum / count as f64 } else { 0.0 },
        max_at_m: [
            gridded.origin_m[0] + best.2 as f64 * gridded.spacing_m[0],
            gridded.origin_m[1] + best.1 as f64 * gridded.spacing_m[1],
        ],
        temperature_k: t,
    }
}

/// Body 1's thermal stress `[6, ny, nx]` (Pa) at depth `z` under `flux` (W/m²): a line
/// contact's plane strain from its middle row ([`LineThermalStress`], the same on every row),
/// otherwise the 3-D operator.
pub(crate) fn thermal_stress_layer(
    grid: &CellGrid,
    line: bool,
    z: f64,
    u: f64,
    poisson: f64,
    e_alpha_over_k: f64,
    flux: &Array2<f64>,
) -> Result<Array3<f64>, ThermalStudyError> {
    let [ny, nx] = grid.shape;
    Ok(if line {
        let row: Vec<f64> = flux.row(ny / 2).to_vec();
        let layer = LineThermalStress::new(nx, grid.spacing_m[0], z, u, poisson, e_alpha_over_k)
            .apply(&row);
        Array3::from_shape_fn((layer.nrows(), ny, nx), |(c, _, i)| layer[[c, i]])
    } else {
        ThermalStressOperator::new(grid, z, u, poisson, e_alpha_over_k)?.apply(flux.view())?
    })
}

/// The DC-FFT layers of the contact tractions on the thermal grid: the pressure and `q = μ p`
/// in +x (a negative `friction`: in -x), lengths in units of `a`.
pub(crate) fn contact_operator(
    pressure_pa: &Array2<f64>,
    spacing_m: [f64; 2],
    a: f64,
    friction: f64,
    poisson: f64,
) -> Result<DcFft, ThermalStudyError> {
    let traction_grid = TractionGrid::new(
        [0.0, 0.0],
        [spacing_m[0] / a, spacing_m[1] / a],
        Some(pressure_pa.clone()),
        Some(pressure_pa.mapv(|p| friction * p)),
        None,
    )?;
    Ok(DcFft::new(&traction_grid, poisson)?)
}

/// `E α / K` of a body: the thermal stress per unit flux scale (Pa m/W).
pub(crate) fn e_alpha_over_k(body: &ThermalBody) -> f64 {
    body.material.modulus_pa * body.properties.expansion_per_k
        / body.properties.conductivity_w_per_m_k
}

/// The flux and the bodies' flash temperatures on a grid.
struct Heated {
    flux: Array2<f64>,
    body1: BodyHeating,
    body2: Option<BodyHeating>,
}

/// The frictional flux `μ p V` on `gridded` and each body's temperature under its share (the
/// partition of `spec`; Blok's found from the bodies' mean temperatures under the whole flux).
fn heat(gridded: &Gridded, spec: &ThermalSpec, friction: f64) -> Result<Heated, ThermalStudyError> {
    let flux = gridded
        .pressure_pa
        .mapv(|p| frictional_flux(friction, p, spec.sliding_speed_m_per_s));
    for (index, body) in std::iter::once(&spec.body1)
        .chain(spec.body2.iter())
        .enumerate()
    {
        let cell_peclet = inverse_length(body) * gridded.spacing_m[0];
        if cell_peclet > MAX_CELL_PECLET * (1.0 + 1e-9) {
            return Err(ThermalStudyError::CellPeclet {
                key: spec.speed_keys[index.min(1)],
                body: index + 1,
                cell_peclet,
                hint: "a rough surface's grid is fixed by its samples: lower the speed, or resample the surface more finely",
            });
        }
    }
    let a = gridded.half_width_m;
    let peclet = |body: &ThermalBody| inverse_length(body) * a;
    let t1 = body_temperature(gridded, &spec.body1, &flux)?;
    let whole1 = heating(gridded, &t1, 1.0, peclet(&spec.body1));
    let (share, body2) = match &spec.body2 {
        Some(b2) => {
            let t2 = body_temperature(gridded, b2, &flux)?;
            let whole2 = heating(gridded, &t2, 1.0, peclet(b2));
            let share = spec.partition.body1_share(
                whole1.mean_temperature_rise_k,
                whole2.mean_temperature_rise_k,
            );
            (share, Some(heating(gridded, &t2, 1.0 - share, peclet(b2))))
        }
        None => (spec.partition.body1_share(1.0, 0.0), None),
    };
    let body1 = heating(gridded, &t1, share, peclet(&spec.body1));
    Ok(Heated { flux, body1, body2 })
}

/// The flash temperatures of a Hertz scene (line, point or elliptical, with `[thermal]`) on
/// the study's grid, without the stresses: `(half-width, body 1, body 2)`.
pub fn hertz_flash(
    scene: &Scene,
    spec: &ThermalSpec,
) -> Result<(f64, BodyHeating, Option<BodyHeating>), ThermalStudyError> {
    let gridded = hertz_grid(scene, spec, &STUDY_WINDOW)?;
    let heated = heat(&gridded, spec, scene.contact.friction)?;
    Ok((gridded.half_width_m, heated.body1, heated.body2))
}

/// A rough contact's own subsurface maxima, as `contact` found them
/// ([`crate::study::rough::subsurface_maxima`]: reference units), with the friction (on body
/// 1, in +x when positive) and Poisson ratio they were found for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactMaxima<'a> {
    pub maxima: &'a crate::study::assess::StressMaxima,
    pub friction: f64,
    pub poisson: f64,
}

/// Computes the heating of `scene` (with `[thermal]`); `rough` is the solved contact of a
/// rough scene. `progress(done, total)` after each depth of the stress search.
pub fn study(
    scene: &Scene,
    rough: Option<&RoughSolution>,
    progress: &mut dyn FnMut(Progress),
) -> Result<ThermalStudy, ThermalStudyError> {
    study_with(scene, rough, None, progress)
}

/// [`study`], given `contact`'s own maxima of the rough contact `rough` (its findings, so
/// that they are not searched again): used when they were found for the heating's friction
/// and Poisson ratio on the same (not a coupled, heated) pressure; otherwise searched.
pub fn study_with(
    scene: &Scene,
    rough: Option<&RoughSolution>,
    known: Option<ContactMaxima>,
    progress: &mut dyn FnMut(Progress),
) -> Result<ThermalStudy, ThermalStudyError> {
    let spec = scene.thermal.ok_or(ThermalStudyError::NoThermal)?;
    if spec.gear.is_some() {
        return Err(ThermalStudyError::GearScene);
    }
    let friction = scene.contact.friction;
    let mut on_coupled =
        |iteration: usize, change: f64| progress(Progress::Coupled { iteration, change });
    let (gridded, coupled) = match (rough, spec.coupled) {
        (Some(solution), false) => (rough_grid(solution), None),
        (None, false) => (hertz_grid(scene, &spec, &STUDY_WINDOW)?, None),
        (Some(solution), true) => {
            let problem = crate::study::rough::problem(scene)
                .ok_or(ThermalStudyError::CoupledNeedsBodies("rough"))?;
            let solved =
                coupled::solve(&problem, solution.clone(), &spec, friction, &mut on_coupled)?;
            (rough_grid(&solved.heated), Some(solved))
        }
        (None, true) => {
            let mut gridded = hertz_grid(scene, &spec, &STUDY_WINDOW)?;
            let (curvature, e_star, load) = match scene.contact.dimensional.map(|d| d.hertz) {
                Some(Hertz::Point(point)) => {
                    let c = 0.5 / point.effective_radius_m;
                    ([c, c], point.effective_modulus_pa, point.load_n)
                }
                Some(Hertz::Elliptical(e)) => (
                    [
                        e.curvature.half_curvature_x_per_m,
                        e.curvature.half_curvature_y_per_m,
                    ],
                    e.effective_modulus_pa,
                    e.load_n,
                ),
                Some(Hertz::Line(_)) => return Err(ThermalStudyError::CoupledNeedsBodies("line")),
                None => return Err(ThermalStudyError::CoupledNeedsBodies("Hertz")),
            };
            let heights = coupled::paraboloid(
                gridded.shape,
                gridded.spacing_m,
                gridded.origin_m,
                curvature,
            );
            let problem = RoughContactProblem {
                heights_m: heights.view(),
                spacing_m: gridded.spacing_m,
                e_star_pa: e_star,
                periodicity: Periodicity::NonPeriodic,
                control: Control::Load { newtons: load },
                hardness_pa: None,
                tolerance: rough::DEFAULT_TOLERANCE,
                max_iterations: rough::DEFAULT_MAX_ITERATIONS,
                memory_limit_bytes: crate::field::memory_limit_bytes(),
            };
            let isothermal = rough::solve(&problem, &mut |_, _| {}).map_err(CoupledError::from)?;
            let solved = coupled::solve(&problem, isothermal, &spec, friction, &mut on_coupled)?;
            gridded.pressure_pa = solved.heated.pressure_pa.clone();
            (gridded, Some(solved))
        }
    };
    let poisson = spec.body1.material.poisson;
    let Heated { flux, body1, body2 } = heat(&gridded, &spec, friction)?;
    let share = body1.share;
    let a = gridded.half_width_m;
    // Friction on body 1 acts the way body 2 slides over it ([`crate::scene::TractionDirection`]).
    let signed_friction = friction * spec.traction.sign();
    let heated_rough = rough.map(|r| coupled.as_ref().map_or(r, |c| &c.heated));
    let model = match heated_rough {
        Some(solution) => ContactModel::Rough {
            periodic: solution.periodicity == Periodicity::Periodic,
        },
        None if coupled.is_none() => {
            crate::study::closed_form_solution(&scene.contact, signed_friction, poisson).map_or(
                ContactModel::Gridded,
                |solution| ContactModel::ClosedForm {
                    solution,
                    p0_pa: scene.contact.p0_pa(),
                },
            )
        }
        None => ContactModel::Gridded,
    };
    let stress = HeatedStress::new(
        &Parts {
            shape: gridded.shape,
            spacing_m: gridded.spacing_m,
            origin_m: gridded.origin_m,
            half_width_m: a,
            line: gridded.line,
            pressure_pa: &gridded.pressure_pa,
            flux_w_per_m2: &flux,
            share,
        },
        &spec,
        &model,
        signed_friction,
    )?;
    // The depths: a Hertz contact's [`DEPTHS_OVER_A`], a rough contact's those of
    // `contact`'s search ([`crate::study::rough::search_depth_m`]).
    // A rough contact's thermal layers are computed at every depth to `DENSE_CELLS` cells,
    // then at every other one ([`crate::study::heated_search`]).
    let (coarse, dense, tolerance_m, search_depth_m) = match heated_rough {
        Some(solution) => {
            let depth = crate::study::rough::search_depth_m(solution);
            let dz = gridded.spacing_m[0].min(gridded.spacing_m[1]);
            let coarse = crate::study::assess::search_depths(dz, depth);
            let dense = dense_depths(&coarse, dz);
            (coarse, dense, dz / 16.0, depth)
        }
        None => (
            DEPTHS_OVER_A.iter().map(|d| d * a).collect::<Vec<f64>>(),
            DEPTHS_OVER_A.len(),
            DEPTH_TOLERANCE_OVER_A * a,
            DEPTHS_OVER_A[DEPTHS_OVER_A.len() - 1] * a,
        ),
    };
    let total = coarse.len();
    let mut maxima = stress.maxima(&coarse, dense, tolerance_m, &mut |done| {
        progress(Progress::Depth { done, total })
    })?;
    // The contact alone: `hertz`'s closed-form maxima, or `contact`'s search of a rough
    // contact, with the heating's traction.
    match (&model, heated_rough) {
        (ContactModel::ClosedForm { solution, p0_pa }, _) => {
            let to_max = |e: crate::study::assess::Extreme| Maximum {
                value_pa: e.value_over_p0 * p0_pa,
                x_m: e.x_over_a * a,
                y_m: e.y_over_a * a,
                depth_m: e.z_over_a * a,
            };
            let found = crate::study::assess::StressMaxima::of(solution);
            maxima[CONTACT_VON_MISES] = to_max(found.von_mises);
            maxima[CONTACT_MAX_SHEAR] = to_max(found.max_shear);
        }
        (ContactModel::Rough { .. }, Some(solution)) => {
            let reference = crate::study::rough::REFERENCE_LENGTH_M;
            let reusable = known.filter(|k| {
                coupled.is_none() && k.friction == signed_friction && k.poisson == poisson
            });
            let found = match reusable {
                Some(k) => *k.maxima,
                None => {
                    let tractions =
                        crate::study::rough::tractions(solution, signed_friction, poisson)
                            .map_err(|e| ThermalStudyError::Contact(e.to_string()))?;
                    crate::study::assess::grid_maxima_to_depth(
                        &tractions,
                        search_depth_m / reference,
                    )?
                }
            };
            let [dx, dy] = gridded.spacing_m;
            let to_max = |e: crate::study::assess::Extreme| Maximum {
                value_pa: e.value_over_p0 * crate::study::rough::REFERENCE_PRESSURE_PA,
                // Cell centres from the map's corner, to the study's frame (from its centre).
                x_m: e.x_over_a * reference + gridded.origin_m[0] - 0.5 * dx,
                y_m: e.y_over_a * reference + gridded.origin_m[1] - 0.5 * dy,
                depth_m: e.z_over_a * reference,
            };
            maxima[CONTACT_VON_MISES] = to_max(found.von_mises);
            maxima[CONTACT_MAX_SHEAR] = to_max(found.max_shear);
        }
        _ => {}
    }
    let section_depth_m = match heated_rough {
        // Where a rough contact's stresses live: four times the deepest of the maxima, at
        // least 16 cells, at most twice `contact`'s search depth (as its sheet).
        Some(_) => {
            let deepest = [
                maxima[TOTAL_VON_MISES],
                maxima[CONTACT_VON_MISES],
                maxima[TOTAL_MAX_SHEAR],
                maxima[CONTACT_MAX_SHEAR],
            ]
            .iter()
            .fold(0.0f64, |d, m| d.max(m.depth_m));
            let cell = gridded.spacing_m[0].min(gridded.spacing_m[1]);
            (4.0 * deepest)
                .max(16.0 * cell)
                .min(2.0 * search_depth_m)
                .max(deepest)
        }
        None => SECTION_DEPTH_OVER_A * a,
    };
    Ok(ThermalStudy {
        spec,
        half_width_m: a,
        shape: gridded.shape,
        spacing_m: gridded.spacing_m,
        origin_m: gridded.origin_m,
        pressure_pa: gridded.pressure_pa,
        flux_w_per_m2: flux,
        body1,
        body2,
        thermal_von_mises: maxima[THERMAL_VON_MISES],
        contact_von_mises: maxima[CONTACT_VON_MISES],
        total_von_mises: maxima[TOTAL_VON_MISES],
        contact_max_shear: maxima[CONTACT_MAX_SHEAR],
        total_max_shear: maxima[TOTAL_MAX_SHEAR],
        coupled,
        line: gridded.line,
        contact_model: model,
        signed_friction,
        search: Search {
            coarse_depths: total,
            depth_m: search_depth_m,
            tolerance_m,
        },
        section_depth_m,
    })
}

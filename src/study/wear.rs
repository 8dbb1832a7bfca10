//! What a wear scene computes, once for every sink: the contact at every step of its sliding
//! distance (Archard wear simulated by [`crate::wear::Evolution`], or a measured series
//! solved map by map, each warm-started from the pressure before), the worn surface, and under
//! each step the subsurface maxima and, with `[thermal]`, the largest flash temperature.
//!
//! With `[thermal] coupled = true` each step is the coupled thermo-mechanical contact of its
//! surface ([`crate::study::coupled`]): the frictional bulge is added to the heights of the
//! step's solves, the wear follows the heated pressure, and the bulge (transient: it goes with
//! the heat) never enters the worn surface.

use std::sync::Arc;

use ndarray::Array2;

use crate::contact::rough::{self, RoughContactError, RoughSolution};
use crate::scene::{Scene, ThermalSpec, WearSpec};
use crate::solution::point_numerical::NumericalError;
use crate::study::assess::StressMaxima;
use crate::study::coupled::{self, CoupledError};
use crate::thermal::heating::frictional_flux;
use crate::thermal::kernel::CellGrid;
use crate::thermal::temperature::{TemperatureOperator, MAX_CELL_PECLET};
use crate::wear::{self, Archard, Evolution, Schedule, WearError};

/// Why a wear scene cannot be studied.
#[derive(Debug, thiserror::Error)]
pub enum WearStudyError {
    #[error("the scene has no [wear] or [[series]]")]
    NoWear,
    #[error("wear: {0}")]
    Wear(#[from] WearError),
    #[error("series[{index}] ({source_name}), at {distance_m} m: {error}")]
    Series {
        index: usize,
        source_name: String,
        distance_m: f64,
        error: RoughContactError,
    },
    #[error("the subsurface maxima at step {step}: {error}")]
    Maxima { step: usize, error: NumericalError },
    #[error("thermal.speed: the cell Péclet number V dx / (2κ) of body {body} is {cell_peclet:.3}, more than {MAX_CELL_PECLET} the surface's grid resolves\nhint: lower thermal.speed, or resample the surface more finely")]
    CellPeclet { body: usize, cell_peclet: f64 },
    #[error("step {step}: {error}")]
    Coupled { step: usize, error: CoupledError },
    #[error("the section of step {step}: {message}")]
    Section { step: usize, message: String },
    #[error(transparent)]
    Transform(#[from] crate::operator::transform::TransformError),
}

/// How the surface evolves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WearKind {
    /// Archard's law with coefficient `k` (m²/N) over `distance_m` in `steps` steps.
    Archard {
        coefficient_m2_per_n: f64,
        distance_m: f64,
        steps: usize,
    },
    /// Measured topographies.
    Series,
}

/// One step: the contact at its sliding distance, the surface it left, and what lies under it.
#[derive(Clone, Debug, PartialEq)]
pub struct WearStudyStep {
    pub sliding_distance_m: f64,
    /// The measured file of a series' step.
    pub source: Option<String>,
    /// The contact (the heated one when coupled).
    pub solution: RoughSolution,
    /// The worn combined heights at the step's end (m, out of body 1; a series' map as read).
    pub heights_m: Arc<Array2<f64>>,
    /// The wear depth so far (m): Archard's, or a series' difference from its first map.
    pub wear_depth_m: Array2<f64>,
    /// The worn volume so far, m³ (Archard's `k W s`; a series: the volume its maps lack).
    pub worn_volume_m3: f64,
    pub max_wear_depth_m: f64,
    /// The plastic flattening so far (simulated wear with a hardness), m³.
    pub plastic_volume_m3: f64,
    /// Subsurface maxima (in the rough scenes' reference units: µm and MPa).
    pub maxima: StressMaxima,
    pub search_depth_m: f64,
    /// Body 1's largest flash temperature rise (with `[thermal]`), K.
    pub max_temperature_rise_k: Option<f64>,
}

impl WearStudyStep {
    /// The real contact area, m².
    pub fn contact_area_m2(&self) -> f64 {
        let [dx, dy] = self.solution.spacing_m;
        self.solution
            .pressure_pa
            .iter()
            .filter(|&&p| p > 0.0)
            .count() as f64
            * dx
            * dy
    }

    /// The plastic area: the cells at the hardness cap times the cell area, m².
    pub fn plastic_area_m2(&self) -> f64 {
        let [dx, dy] = self.solution.spacing_m;
        self.solution.plastic_cells as f64 * dx * dy
    }

    /// The worn scar: the area whose wear depth exceeds a thousandth of the deepest (m²; zero
    /// before any wear). It grows with the distance while the real contact may not.
    pub fn scar_area_m2(&self) -> f64 {
        let [dx, dy] = self.solution.spacing_m;
        if self.max_wear_depth_m <= 0.0 {
            return 0.0;
        }
        let threshold = 1e-3 * self.max_wear_depth_m;
        self.wear_depth_m.iter().filter(|&&w| w > threshold).count() as f64 * dx * dy
    }

    /// The load over the real contact area, Pa.
    pub fn mean_contact_pressure_pa(&self) -> f64 {
        self.solution.load_n / self.contact_area_m2()
    }
}

/// Everything a wear scene computes.
#[derive(Clone, Debug, PartialEq)]
pub struct WearStudy {
    pub kind: WearKind,
    /// The load that presses the surface, N.
    pub load_n: f64,
    pub hardness_pa: Option<f64>,
    pub e_star_pa: f64,
    pub friction: f64,
    pub poisson: f64,
    /// The steps, the unworn contact first (distance 0, or a series' first map).
    pub steps: Vec<WearStudyStep>,
    /// Whether each step's contact is the coupled thermo-mechanical one.
    pub coupled: bool,
    /// How many steps' maxima were searched in full (the others warm: [`MaximaSearch`]).
    pub full_maxima_searches: usize,
    /// What the reader should be told, in words: a series' map that stands higher than the
    /// first (material added, or another datum), which is not wear.
    pub warnings: Vec<String>,
}

/// What the study reports while it works.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WearProgress {
    /// Step `step` of `total` (0-based) is being solved: iteration and residual.
    Solving {
        step: usize,
        total: usize,
        iteration: usize,
        residual: f64,
    },
    /// Step `step`'s subsurface maxima are being searched.
    Maxima { step: usize, total: usize },
}

/// Bytes the study keeps per step of a `[ny, nx]` map (pressure, gap, worn heights, wear
/// depth), for the estimate before computing ([`crate::study::admit`]).
pub fn bytes_per_step(shape: [usize; 2]) -> usize {
    4 * 8 * shape[0] * shape[1]
}

/// The number of steps of a scene's evolution, the unworn contact included.
pub fn step_count(spec: &WearSpec) -> usize {
    match spec {
        WearSpec::Archard { steps, .. } => steps + 1,
        WearSpec::Series(entries) => entries.len(),
    }
}

/// Body 1's flash temperature under a pressure, with the operators built once.
struct Heating {
    spec: ThermalSpec,
    friction: f64,
    body1: TemperatureOperator,
    /// Body 2's, when the partition needs it.
    body2: Option<TemperatureOperator>,
}

impl Heating {
    fn new(
        spec: &ThermalSpec,
        friction: f64,
        shape: [usize; 2],
        spacing_m: [f64; 2],
    ) -> Result<Self, WearStudyError> {
        let grid = CellGrid { shape, spacing_m };
        let mut bodies = vec![&spec.body1];
        if spec.partition.needs_body2() {
            bodies.extend(spec.body2.iter());
        }
        for (index, body) in bodies.iter().enumerate() {
            let cell_peclet = crate::study::thermal::inverse_length(body) * spacing_m[0];
            if cell_peclet > MAX_CELL_PECLET {
                return Err(WearStudyError::CellPeclet {
                    body: index + 1,
                    cell_peclet,
                });
            }
        }
        let operator = |body: &crate::scene::ThermalBody| {
            TemperatureOperator::new(
                &grid,
                0.0,
                crate::study::thermal::inverse_length(body),
                body.properties.conductivity_w_per_m_k,
            )
        };
        Ok(Self {
            spec: *spec,
            friction,
            body1: operator(&spec.body1)?,
            body2: match (&spec.body2, spec.partition.needs_body2()) {
                (Some(body), true) => Some(operator(body)?),
                _ => None,
            },
        })
    }

    /// Body 1's largest temperature rise (K) under `pressure`, its share of the flux as the
    /// heating study divides it (Blok's from the mean rises over the contact).
    fn max_rise(&mut self, pressure: &Array2<f64>) -> Result<f64, WearStudyError> {
        let flux =
            pressure.mapv(|p| frictional_flux(self.friction, p, self.spec.sliding_speed_m_per_s));
        let t1 = self.body1.apply(flux.view())?;
        let mean_over_contact = |t: &Array2<f64>| {
            let (mut sum, mut count) = (0.0, 0usize);
            for (&value, &p) in t.iter().zip(pressure.iter()) {
                if p > 0.0 {
                    sum += value;
                    count += 1;
                }
            }
            sum / count.max(1) as f64
        };
        let share = match self.body2.as_mut() {
            Some(operator) => {
                let t2 = operator.apply(flux.view())?;
                self.spec
                    .partition
                    .body1_share(mean_over_contact(&t1), mean_over_contact(&t2))
            }
            None => self.spec.partition.body1_share(1.0, 0.0),
        };
        Ok(share * t1.iter().fold(f64::NEG_INFINITY, |m, &t| m.max(t)))
    }
}

/// How each step's subsurface maxima are searched.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MaximaSearch {
    /// The full search of `contact` at every step ([`crate::study::rough::subsurface_maxima`]).
    Full,
    /// Near the previous step's maxima where the pressure changed little since the last full
    /// search ([`Searcher`]); the full search elsewhere. The default.
    Warm,
}

/// The relative change of the pressure from the step before, `‖p − p_before‖₂ / ‖p‖₂`, beyond
/// which a step's maxima are searched in full: a field that changed that much may have peaks
/// the step before did not have (the von Mises stress is a seminorm of the stress, which is
/// linear in the tractions: the stress of the change bounds how far any maximum can have
/// risen where the warm search does not look). A smooth ball's wear changes its pressure by
/// 0.1 to 0.4 a step (the scar's edge moving); the instantaneous contact under a sliding rough
/// counter-surface by more than 1 (its asperities moved).
pub const WARM_CHANGE_LIMIT: f64 = 0.5;

/// At most this many steps in a row are searched warm; the next is searched in full.
pub const WARM_STEPS: usize = 9;

/// How far a warm maximum may lie from the full search's (relative), as tested on the
/// evolutions of `tests/wear.rs`.
pub const WARM_TOLERANCE: f64 = 2e-3;

/// The subsurface maxima of an evolution's steps, each searched near the peaks of the one
/// before ([`crate::study::assess::grid_maxima_warm`]) while the pressure stays within
/// [`WARM_CHANGE_LIMIT`] of the last pressure searched in full, for at most [`WARM_STEPS`]
/// steps in a row; in full otherwise.
struct Searcher {
    search: MaximaSearch,
    friction: f64,
    poisson: f64,
    /// The peaks in depth of the step before, its pressure, and the steps searched warm since
    /// the last full search.
    previous: Option<(Vec<f64>, Array2<f64>, usize)>,
    /// How many steps were searched in full.
    full_searches: usize,
}

impl Searcher {
    fn maxima(
        &mut self,
        index: usize,
        solution: &RoughSolution,
    ) -> Result<(StressMaxima, f64), WearStudyError> {
        let error = |error| WearStudyError::Maxima { step: index, error };
        let pressure = &solution.pressure_pa;
        if let (MaximaSearch::Warm, Some((peaks, before, warm_steps))) =
            (self.search, self.previous.as_mut())
        {
            if *warm_steps < WARM_STEPS
                && before.dim() == pressure.dim()
                && relative_change(before, pressure) <= WARM_CHANGE_LIMIT
            {
                if let Some((maxima, depth_m, moved)) = crate::study::rough::subsurface_maxima_warm(
                    solution,
                    self.friction,
                    self.poisson,
                    peaks,
                )
                .map_err(error)?
                {
                    *peaks = moved;
                    before.assign(pressure);
                    *warm_steps += 1;
                    return Ok((maxima, depth_m));
                }
            }
        }
        let (maxima, depth_m, peaks) =
            crate::study::rough::subsurface_maxima_and_peaks(solution, self.friction, self.poisson)
                .map_err(error)?;
        self.full_searches += 1;
        self.previous = Some((peaks, pressure.clone(), 0));
        Ok((maxima, depth_m))
    }
}

/// `‖now − before‖₂ / ‖now‖₂` (infinite for a zero `now`).
fn relative_change(before: &Array2<f64>, now: &Array2<f64>) -> f64 {
    let (mut change, mut norm) = (0.0, 0.0);
    for (&b, &n) in before.iter().zip(now.iter()) {
        change += (n - b) * (n - b);
        norm += n * n;
    }
    if norm > 0.0 {
        (change / norm).sqrt()
    } else {
        f64::INFINITY
    }
}

/// Solves every step of `scene`'s evolution ([`WearSpec`]), with the subsurface maxima and
/// flash temperature of each (the maxima warm-started: [`MaximaSearch::Warm`]).
pub fn study(
    scene: &Scene,
    progress: &mut dyn FnMut(WearProgress),
) -> Result<WearStudy, WearStudyError> {
    study_with(scene, MaximaSearch::Warm, progress)
}

/// [`study`] with the maxima searched as `search` says.
pub fn study_with(
    scene: &Scene,
    search: MaximaSearch,
    progress: &mut dyn FnMut(WearProgress),
) -> Result<WearStudy, WearStudyError> {
    let spec = scene.wear.as_ref().ok_or(WearStudyError::NoWear)?;
    let problem = crate::study::rough::problem(scene).ok_or(WearStudyError::NoWear)?;
    let (friction, poisson) = (scene.contact.friction, scene.contact.poisson);
    let total = step_count(spec);
    let (ny, nx) = problem.heights_m.dim();
    let mut heating = match &scene.thermal {
        Some(thermal) => Some(Heating::new(
            thermal,
            friction,
            [ny, nx],
            problem.spacing_m,
        )?),
        None => None,
    };
    let coupled = scene.thermal.is_some_and(|t| t.coupled);
    let load_n = wear::nominal_load_n(&problem);
    let mut steps: Vec<WearStudyStep> = Vec::with_capacity(total);
    let mut warnings = Vec::new();
    let mut searcher = Searcher {
        search,
        friction,
        poisson,
        previous: None,
        full_searches: 0,
    };
    // The maxima and flash temperature under a solved step.
    let mut finish = |index: usize,
                      solution: &RoughSolution,
                      heating: &mut Option<Heating>,
                      progress: &mut dyn FnMut(WearProgress)|
     -> Result<_, WearStudyError> {
        progress(WearProgress::Maxima { step: index, total });
        let (maxima, search_depth_m) = searcher.maxima(index, solution)?;
        let temperature = match heating.as_mut() {
            Some(h) => Some(h.max_rise(&solution.pressure_pa)?),
            None => None,
        };
        Ok((maxima, search_depth_m, temperature))
    };
    let kind = match spec {
        WearSpec::Archard {
            coefficient_m2_per_n,
            distance_m,
            steps: count,
        } => {
            let law = Archard {
                coefficient_m2_per_n: *coefficient_m2_per_n,
            };
            let schedule = Schedule {
                distance_m: *distance_m,
                steps: *count,
            };
            // The worn body is body 1; a rough body 2 slides over it and does not wear.
            let surface = scene.surface.as_ref().ok_or(WearStudyError::NoWear)?;
            let worn_problem = rough::RoughContactProblem {
                heights_m: surface.body1.heights_m().view(),
                ..problem.clone()
            };
            let mut evolution = Evolution::new(&worn_problem, law, schedule)?;
            if let Some(counter) = &surface.counter {
                evolution = evolution.sliding_against(counter.heights_m().clone());
            }
            loop {
                let index = steps.len();
                let mut on_iteration = |iteration: usize, residual: f64| {
                    progress(WearProgress::Solving {
                        step: index,
                        total,
                        iteration,
                        residual,
                    })
                };
                let step = if coupled {
                    let thermal = scene.thermal.as_ref().ok_or(WearStudyError::NoWear)?;
                    let Some(solution) =
                        coupled_step(&evolution, &problem, thermal, friction, index)?
                    else {
                        break;
                    };
                    let mut taken = evolution.commit(solution)?;
                    if let Some(sliding) =
                        evolution.sliding_contact(&mut on_iteration).map_err(|e| {
                            WearStudyError::Coupled {
                                step: index,
                                error: CoupledError::Contact(e),
                            }
                        })?
                    {
                        taken.solution = sliding;
                    }
                    taken
                } else {
                    match evolution.step(&mut on_iteration)? {
                        Some(step) => step,
                        None => break,
                    }
                };
                let (maxima, search_depth_m, max_temperature_rise_k) =
                    finish(index, &step.solution, &mut heating, progress)?;
                steps.push(WearStudyStep {
                    sliding_distance_m: step.sliding_distance_m,
                    source: None,
                    solution: step.solution,
                    heights_m: Arc::new(evolution.heights_m().clone()),
                    wear_depth_m: evolution.wear_depth_m().clone(),
                    worn_volume_m3: step.worn_volume_m3,
                    max_wear_depth_m: step.max_wear_depth_m,
                    plastic_volume_m3: step.plastic_volume_m3,
                    maxima,
                    search_depth_m,
                    max_temperature_rise_k,
                });
            }
            WearKind::Archard {
                coefficient_m2_per_n: *coefficient_m2_per_n,
                distance_m: *distance_m,
                steps: *count,
            }
        }
        WearSpec::Series(entries) => {
            let [dx, dy] = problem.spacing_m;
            let first = entries.first().map(|e| e.heights.heights_m().clone());
            let counter = scene.surface.as_ref().and_then(|s| s.counter.clone());
            for (index, entry) in entries.iter().enumerate() {
                let heights = entry.heights.heights_m();
                // A rough counter-surface slides over the measured body (module doc).
                let combined = counter
                    .as_ref()
                    .map(|c| heights + &wear::slid(c.heights_m(), entry.distance_m, dx));
                let step_problem = rough::RoughContactProblem {
                    heights_m: combined.as_ref().unwrap_or(heights).view(),
                    ..problem.clone()
                };
                let previous = steps.last().map(|s| s.solution.pressure_pa.view());
                let series_error = |error| WearStudyError::Series {
                    index,
                    source_name: entry.source.clone(),
                    distance_m: entry.distance_m,
                    error,
                };
                let isothermal = rough::solve_warm(
                    &step_problem,
                    &rough::Warm {
                        pressure_pa: previous,
                        local_compliance_m_per_pa: 0.0,
                    },
                    &mut |iteration, residual| {
                        progress(WearProgress::Solving {
                            step: index,
                            total,
                            iteration,
                            residual,
                        })
                    },
                )
                .map_err(series_error)?;
                let solution = if coupled {
                    let thermal = scene.thermal.as_ref().ok_or(WearStudyError::NoWear)?;
                    coupled::solve(&step_problem, isothermal, thermal, friction, &mut |_, _| {})
                        .map_err(|error| WearStudyError::Coupled { step: index, error })?
                        .heated
                } else {
                    isothermal
                };
                let wear_depth_m = match &first {
                    Some(first) if index > 0 => {
                        let change = wear::measured_change(first, heights);
                        if change.stands_higher() {
                            warnings.push(standing_higher(index, entry, &change, dx * dy));
                        }
                        change.depth_m
                    }
                    _ => Array2::zeros(heights.raw_dim()),
                };
                let worn_volume_m3 = wear_depth_m.sum() * dx * dy;
                let max_wear_depth_m = wear_depth_m.iter().fold(0.0f64, |m, &w| m.max(w));
                let (maxima, search_depth_m, max_temperature_rise_k) =
                    finish(index, &solution, &mut heating, progress)?;
                steps.push(WearStudyStep {
                    sliding_distance_m: entry.distance_m,
                    source: Some(entry.source.clone()),
                    solution,
                    heights_m: Arc::new(heights.clone()),
                    wear_depth_m,
                    worn_volume_m3,
                    max_wear_depth_m,
                    plastic_volume_m3: 0.0,
                    maxima,
                    search_depth_m,
                    max_temperature_rise_k,
                });
            }
            WearKind::Series
        }
    };
    Ok(WearStudy {
        kind,
        load_n,
        hardness_pa: problem.hardness_pa,
        e_star_pa: problem.e_star_pa,
        friction,
        poisson,
        steps,
        coupled,
        full_maxima_searches: searcher.full_searches,
        warnings,
    })
}

/// The warning for series map `index` (`entry`) that stands higher than the first somewhere
/// ([`wear::MeasuredChange::stands_higher`]), cells of `cell_m2`.
fn standing_higher(
    index: usize,
    entry: &crate::scene::SeriesEntry,
    change: &wear::MeasuredChange,
    cell_m2: f64,
) -> String {
    format!(
        "series[{index}] ({}) stands up to {:.4} µm higher than the first map over {:.5} mm² (material added, such as a transfer film or pile-up, or a datum that differs between the maps): that is not wear, and the wear reported is only where the map lacks",
        entry.source,
        change.higher_m * 1e6,
        change.higher_cells as f64 * cell_m2 * 1e6
    )
}

/// The next step of a coupled evolution, not yet taken: the coupled contact of the worn
/// surface with the step's wear compliance ([`coupled::iterate`]); `None` after the last.
fn coupled_step(
    evolution: &Evolution,
    problem: &rough::RoughContactProblem,
    thermal: &ThermalSpec,
    friction: f64,
    index: usize,
) -> Result<Option<RoughSolution>, WearStudyError> {
    if evolution.finished() {
        return Ok(None);
    }
    let coupled_error = |error| WearStudyError::Coupled { step: index, error };
    let isothermal = evolution
        .solve_next(None, None, &mut |_, _| {})
        .map_err(|e| coupled_error(CoupledError::Contact(e)))?;
    let (ny, nx) = problem.heights_m.dim();
    let grid = CellGrid {
        shape: [ny, nx],
        spacing_m: problem.spacing_m,
    };
    let solved =
        coupled::iterate(
            &grid,
            isothermal,
            thermal,
            friction,
            &mut |_, _| {},
            &mut |distortion, start| {
                Ok(evolution.solve_next(
                    Some(distortion.view()),
                    Some(start.view()),
                    &mut |_, _| {},
                )?)
            },
        )
        .map_err(coupled_error)?;
    Ok(Some(solved.heated))
}

/// The xz section of one step through its largest von Mises stress, for the recording.
#[derive(Clone, Debug, PartialEq)]
pub struct StepSection {
    /// The plane in the reference length (µm): along x over the map's cell centres, in depth
    /// from the surface.
    pub plane: crate::field::Plane,
    /// Von Mises stress on `plane`, Pa, `[z, x]`.
    pub values_pa: Array2<f64>,
}

/// Rows of a step's section in depth.
const SECTION_ROWS: usize = 40;

/// The depth of the steps' sections, µm: three times the deepest von Mises maximum of any step,
/// at least four cells and an eighth of the map's width (a section across the whole map no
/// thinner than that), at most a sixth of it, the same for every step so that the recording's
/// view keeps its frame.
pub fn section_depth_um(study: &WearStudy) -> f64 {
    let first = &study.steps[0].solution;
    let (_, nx) = first.pressure_pa.dim();
    let [dx, _] = first.spacing_m;
    let cell_um = dx * 1e6;
    let deepest = study
        .steps
        .iter()
        .map(|s| s.maxima.von_mises.z_over_a * REFERENCE_UM)
        .fold(0.0f64, f64::max);
    let width = nx as f64 * cell_um;
    (3.0 * deepest)
        .max(4.0 * cell_um)
        .max(width / 8.0)
        .min(width / 6.0)
        .max(cell_um)
}

/// µm per unit of the rough scenes' reference length.
const REFERENCE_UM: f64 = crate::study::rough::REFERENCE_LENGTH_M * 1e6;

/// Each step's xz section through the row of its largest von Mises stress, to
/// [`section_depth_um`] in [`SECTION_ROWS`] rows; `on_step(k)` after each.
pub fn sections(
    study: &WearStudy,
    on_step: &mut dyn FnMut(usize),
) -> Result<Vec<StepSection>, WearStudyError> {
    let depth = section_depth_um(study);
    let mut out = Vec::with_capacity(study.steps.len());
    for (k, step) in study.steps.iter().enumerate() {
        let solution = &step.solution;
        let (ny, nx) = solution.pressure_pa.dim();
        let [dx, dy] = solution.spacing_m;
        let (ax, ay) = (dx * 1e6 / REFERENCE_UM, dy * 1e6 / REFERENCE_UM);
        let row = crate::study::map_roll::cell_of(step.maxima.von_mises.y_over_a, ay, ny);
        let plane = crate::field::Plane {
            section: crate::field::Section::Xz {
                y: (row as f64 + 0.5) * ay,
            },
            u: crate::field::Axis::new(0.5 * ax, (nx as f64 - 0.5) * ax, nx),
            v: crate::field::Axis::new(0.0, depth / REFERENCE_UM, SECTION_ROWS),
        };
        let stresses =
            crate::study::rough::stress_solution(solution, study.friction, study.poisson)
                .map_err(|error| WearStudyError::Maxima { step: k, error })?;
        let values_pa = crate::field::evaluate(
            &stresses,
            &plane,
            &[crate::stress::Quantity::VonMises],
            &|| {},
        )
        .map_err(|e| WearStudyError::Section {
            step: k,
            message: e.to_string(),
        })?
        .values
        .index_axis(ndarray::Axis(1), 0)
        .mapv(|v| v * crate::study::rough::REFERENCE_PRESSURE_PA);
        out.push(StepSection { plane, values_pa });
        on_step(k);
    }
    Ok(out)
}

//! What a rough scene computes: the contact problem on its surface, the solved pressure as
//! surface tractions (`q = μ p` in +x), and the stress solution under them.
//!
//! The traction grid is in the rough scenes' reference units ([`REFERENCE_LENGTH_M`],
//! [`REFERENCE_PRESSURE_PA`]: 1 um and 1 MPa), the `a` and `p0` of their `Contact::scale`.

use std::ops::ControlFlow;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

use std::f64::consts::PI;

use crate::contact::rough::{self, RoughContactError, RoughContactProblem, RoughSolution};
use crate::operator::elastic::Periodicity;
use crate::scene::{ContactKind, Scene};
use crate::solution::dcfft::TractionGrid;
use crate::solution::point_numerical::{NumericalError, PointTractions};
use crate::solution::Solution;
use crate::study::assess::{
    grid_maxima_and_peaks, grid_maxima_to_depth, grid_maxima_warm, StressMaxima,
};
use crate::surface::stats::{self, FormRemoval, Options};

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
    #[error(transparent)]
    Coated(#[from] crate::contact::coated::CoatedContactError),
    #[error(transparent)]
    Transform(#[from] crate::operator::transform::TransformError),
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

/// How many times this process has solved a scene's own contact ([`solve`]): a command should
/// solve it once, whatever it draws, reports or records (the binary prints it when
/// `STRESSFIELD_COUNT_SOLVES` is set; the tests count with it).
static SCENE_SOLVES: AtomicUsize = AtomicUsize::new(0);

/// The number of [`solve`] calls so far in this process.
pub fn scene_solves() -> usize {
    SCENE_SOLVES.load(Ordering::Relaxed)
}

/// Solves the scene's contact; `progress(iteration, residual)` after each iteration. A coated
/// body 1 (`[contact.body1.coating]`) takes the layered influence coefficients
/// ([`crate::contact::coated`]), periodic or isolated as the scene says.
pub fn solve(
    scene: &Scene,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<RoughSolution, RoughStudyError> {
    solve_interruptible(scene, &mut |iteration, residual| {
        progress(iteration, residual);
        ControlFlow::Continue(())
    })
}

/// [`solve`] that can be stopped between iterations: `progress(iteration, residual)` returns
/// whether to go on ([`rough::solve_interruptible`]; a stop is
/// [`RoughContactError::Interrupted`]), the same solution as [`solve`] to the last bit
/// otherwise. A coated body's solve ([`crate::contact::coated::solve`]) has no stop yet: its
/// progress is reported and its answer to stop is not heard.
pub fn solve_interruptible(
    scene: &Scene,
    progress: &mut dyn FnMut(usize, f64) -> ControlFlow<()>,
) -> Result<RoughSolution, RoughStudyError> {
    if scene.contact.kind != ContactKind::Rough {
        return Err(RoughStudyError::NotRough);
    }
    let problem = problem(scene).ok_or(RoughStudyError::NotRough)?;
    SCENE_SOLVES.fetch_add(1, Ordering::Relaxed);
    // A coated body's layered operator, built once, or Love's: either solve hears the stop.
    let mut cache = match &scene.contact.coating {
        Some(coating) => crate::contact::coated::operator_cache(
            &problem,
            &coating.layered(),
            coating.counter_per_pa,
        )?,
        None => rough::OperatorCache::default(),
    };
    Ok(rough::solve_interruptible(
        &problem,
        &rough::Warm::default(),
        &mut cache,
        progress,
    )?)
}

/// The factors of the scene's mean pressure at which [`area_curve`] solves the contact again.
pub const AREA_CURVE_FACTORS: [f64; 4] = [0.25, 0.5, 2.0, 4.0];

/// Real area against load: `(p̄ / E*, A / A0)` of the contact solved at
/// [`AREA_CURVE_FACTORS`] times the mean pressure of `solution` (the scene's own, included),
/// in order of pressure. A factor at which the contact becomes full, reaches the edge or
/// cannot carry the load under the hardness ends the series there.
pub fn area_curve(
    scene: &Scene,
    solution: &RoughSolution,
) -> Result<Vec<(f64, f64)>, RoughStudyError> {
    let problem = problem(scene).ok_or(RoughStudyError::NotRough)?;
    let e_star = problem.e_star_pa;
    // One operator for every load: a coated body's layered one, built once, or Love's.
    let mut cache = match &scene.contact.coating {
        Some(coating) => crate::contact::coated::operator_cache(
            &problem,
            &coating.layered(),
            coating.counter_per_pa,
        )?,
        None => rough::OperatorCache::default(),
    };
    let mut solved = Vec::new();
    for factor in AREA_CURVE_FACTORS {
        let mut scaled = problem.clone();
        scaled.control = rough::Control::MeanPressure {
            pa: factor * solution.mean_pressure_pa,
        };
        match rough::solve_cached(&scaled, &rough::Warm::default(), &mut cache, &mut |_, _| {}) {
            Ok(s) => solved.push((s.mean_pressure_pa / e_star, s.contact_fraction)),
            Err(
                RoughContactError::FullContact { .. }
                | RoughContactError::PressureAtEdge { .. }
                | RoughContactError::HardnessTooLow { .. },
            ) => {}
            Err(e) => return Err(e.into()),
        }
    }
    solved.push((
        solution.mean_pressure_pa / e_star,
        solution.contact_fraction,
    ));
    solved.sort_by(|a, b| a.0.total_cmp(&b.0));
    Ok(solved)
}

/// The solved pressure and `q = friction p` (in +x) as a traction grid in the reference units,
/// cell `[0, 0]` at the origin.
pub fn traction_grid(
    solution: &RoughSolution,
    friction: f64,
) -> Result<TractionGrid, NumericalError> {
    let [dx, dy] = solution.spacing_m;
    let pressure = solution.pressure_pa.mapv(|p| p / REFERENCE_PRESSURE_PA);
    let shear = (friction != 0.0).then(|| pressure.mapv(|p| friction * p));
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

/// How deep to search the maxima (m): the subsurface maximum under a spot of radius `r` lies
/// near `0.5 r` (Hertz: 0.48a), under a cluster of spots forming one macro-contact near half
/// its radius. The search goes to 2.5 times the radius of the largest spot, and for an
/// isolated contact also to the radius of the loaded cells' bounding box; never beyond half
/// the grid.
pub fn search_depth_m(solution: &RoughSolution) -> f64 {
    let [dx, dy] = solution.spacing_m;
    let spot_radius = (solution.largest_spot_cells as f64 * dx * dy / PI).sqrt();
    let mut depth = 2.5 * spot_radius;
    if solution.periodicity == crate::operator::elastic::Periodicity::NonPeriodic {
        let (mut x0, mut x1, mut y0, mut y1) = (usize::MAX, 0, usize::MAX, 0);
        for ((j, i), &p) in solution.pressure_pa.indexed_iter() {
            if p > 0.0 {
                (x0, x1, y0, y1) = (x0.min(i), x1.max(i), y0.min(j), y1.max(j));
            }
        }
        if x0 <= x1 {
            let extent = ((x1 - x0 + 1) as f64 * dx).max((y1 - y0 + 1) as f64 * dy);
            depth = depth.max(0.5 * extent);
        }
    }
    let (ny, nx) = solution.pressure_pa.dim();
    depth
        .min(0.5 * (nx as f64 * dx).min(ny as f64 * dy))
        .max(dx.min(dy))
}

/// The subsurface maxima under the solved pressure (and `q = μ p`; periodic when the contact
/// is), from DC-FFT layers at the cell centres, one cell apart near the surface and a fifth of
/// their depth below, refined by bisection to a sixteenth of a cell around the best
/// ([`grid_maxima_to_depth`]), down to [`search_depth_m`].
pub fn subsurface_maxima(
    solution: &RoughSolution,
    friction: f64,
    poisson: f64,
) -> Result<(StressMaxima, f64), NumericalError> {
    let tractions = tractions(solution, friction, poisson)?;
    let depth_m = search_depth_m(solution);
    let maxima = grid_maxima_to_depth(&tractions, depth_m / REFERENCE_LENGTH_M)?;
    Ok((maxima, depth_m))
}

/// [`subsurface_maxima`] and the depths of its peaks in depth (reference units), for a warm
/// search of a nearby solution ([`subsurface_maxima_warm`]).
pub fn subsurface_maxima_and_peaks(
    solution: &RoughSolution,
    friction: f64,
    poisson: f64,
) -> Result<(StressMaxima, f64, Vec<f64>), NumericalError> {
    let tractions = tractions(solution, friction, poisson)?;
    let depth_m = search_depth_m(solution);
    let (maxima, peaks) = grid_maxima_and_peaks(&tractions, depth_m / REFERENCE_LENGTH_M)?;
    Ok((maxima, depth_m, peaks))
}

/// [`subsurface_maxima`] searched near `peaks`, the depths of a nearby solution's peaks (the
/// step before, in an evolution), to the same [`search_depth_m`] ([`grid_maxima_warm`]):
/// the maxima, the search depth and the peaks' new depths, or `None` where only the full
/// search will do.
pub fn subsurface_maxima_warm(
    solution: &RoughSolution,
    friction: f64,
    poisson: f64,
    peaks: &[f64],
) -> Result<Option<(StressMaxima, f64, Vec<f64>)>, NumericalError> {
    let tractions = tractions(solution, friction, poisson)?;
    let depth_m = search_depth_m(solution);
    let found = grid_maxima_warm(&tractions, depth_m / REFERENCE_LENGTH_M, peaks)?;
    Ok(found.map(|(maxima, peaks)| (maxima, depth_m, peaks)))
}

/// What the contact report states beyond the solution itself: the subsurface maxima with the
/// depth they were searched to, the plasticity index of the surface (with a hardness), and
/// the warnings about the solution ([`warnings`]).
#[derive(Clone, Debug, PartialEq)]
pub struct ContactFindings {
    pub maxima: StressMaxima,
    /// A coated body's maxima in the coating, on the interface and in the substrate
    /// ([`super::coated_rough::maxima`]; `maxima` is drawn from them).
    pub coating: Option<super::coated_rough::CoatingMaxima>,
    pub search_depth_m: f64,
    pub plasticity_index: Option<f64>,
    pub warnings: Vec<String>,
}

/// Fewer cells in contact than this and the contact is not resolved by the grid (a Hertz
/// contact needs about ten cells across its radius for a peak pressure within 0.05 %: the
/// grid convergence of `tests/rough_contact.rs`; below ten cells in all, a spot is one or two
/// cells wide and its pressure is the grid's, not the surface's).
pub const FEW_CONTACT_CELLS: usize = 10;

/// The peak pressure beyond which no material carries the load, as a fraction of E*: the
/// ideal (theoretical) strength of a perfect crystal is of order E/10 (Kelly & Macmillan 1986,
/// ch. 1; for steel about 20 GPa), an upper bound of any real solid's strength, and E* is E
/// or a little more (E/(1 − ν²) against a rigid body, E/(2(1 − ν²)) between equal bodies).
///
/// ## Reference
/// A. Kelly, N. H. Macmillan, *Strong Solids*, 3rd ed., Clarendon Press, Oxford (1986).
pub const IDEAL_STRENGTH_OVER_E_STAR: f64 = 0.1;

/// What a reader of the solved contact should be told, in words: a contact resolved by fewer
/// than [`FEW_CONTACT_CELLS`] cells, and a peak pressure beyond any material's strength
/// ([`IDEAL_STRENGTH_OVER_E_STAR`] times E*, without a hardness to cap it), and a measured
/// map's seam under a periodic contact ([`seam_warning`]). Warnings, not errors: the solution
/// is the elastic one of the map as given.
pub fn warnings(scene: &Scene, solution: &RoughSolution) -> Vec<String> {
    let rough = scene.contact.rough;
    let mut warnings = warnings_of(
        solution,
        rough.and_then(|r| r.e_star_pa),
        rough.and_then(|r| r.hardness_pa),
    );
    warnings.extend(scene_seam_warning(scene, solution));
    warnings
}

/// The warnings of a scene's measured map solved periodically (none for a generated map,
/// which tiles by construction, or an isolated contact): a form removed on request
/// ([`levelled_seam_warning`]) and a seam the contact touches ([`seam_warning`]).
fn scene_seam_warning(scene: &Scene, solution: &RoughSolution) -> Vec<String> {
    let periodic = scene.contact.rough.is_some_and(|r| r.periodic);
    let Some(surface) = scene.surface.as_ref().filter(|s| periodic && !s.generated) else {
        return Vec::new();
    };
    let mut warnings = Vec::new();
    if let Some(crate::scene::Levelling::Removed(datum)) = surface.levelling {
        warnings.extend(levelled_seam_warning(&surface.body1, datum));
    }
    warnings.extend(seam_warning(
        surface.heights.heights_m().view(),
        &solution.pressure_pa,
    ));
    warnings
}

/// The warning for a periodic map levelled by a plane (or a quadratic) on request: the form
/// removed is not periodic, so it steps the map at the seam by its rise across the period,
/// `|c1| Lx` along x and `|c2| Ly` along y (issue 50). Given when that step exceeds the rms
/// step between neighbouring samples of the levelled map `levelled`, where it shows.
pub fn levelled_seam_warning(
    levelled: &crate::surface::HeightMap,
    datum: crate::surface::stats::Datum,
) -> Option<String> {
    let [lx, ly] = levelled.size_m();
    let [_, slope_x, slope_y] = datum.plane_m;
    let [(_, inner_x), (_, inner_y)] = levelled.seam_steps_m();
    let rise = [
        (slope_x.abs() * lx, inner_x, "x"),
        (slope_y.abs() * ly, inner_y, "y"),
    ];
    let shown: Vec<String> = rise
        .iter()
        .filter(|(rise, inner, _)| rise > inner)
        .map(|(rise, inner, axis)| {
            format!(
                "{:.3} µm along {axis} (neighbouring samples: {:.3} µm rms)",
                rise * 1e6,
                inner * 1e6
            )
        })
        .collect();
    if shown.is_empty() {
        return None;
    }
    Some(format!(
        "level = \"{}\" on a periodic map: the removed form is not periodic, its plane alone steps the repeated map at the seam by {}; level = \"mean\" (the default of a periodic contact) keeps the map as given",
        match datum.form() {
            crate::surface::stats::FormRemoval::Plane => "plane",
            crate::surface::stats::FormRemoval::Quadratic => "quadratic",
        },
        shown.join(" and ")
    ))
}

/// [`warnings`] of a contact solved with `e_star_pa` and `hardness_pa` (Pa).
pub fn warnings_of(
    solution: &RoughSolution,
    e_star_pa: Option<f64>,
    hardness_pa: Option<f64>,
) -> Vec<String> {
    let mut warnings = Vec::new();
    let cells = solution.pressure_pa.iter().filter(|&&p| p > 0.0).count();
    if cells < FEW_CONTACT_CELLS {
        warnings.push(format!(
            "the contact is resolved by only {cells} cell{}; refine the grid (surface samples) or raise the load",
            if cells == 1 { "" } else { "s" }
        ));
    }
    if let (Some(e_star_pa), None) = (e_star_pa, hardness_pa) {
        let limit_pa = IDEAL_STRENGTH_OVER_E_STAR * e_star_pa;
        if solution.max_pressure_pa > limit_pa {
            warnings.push(format!(
                "the peak pressure {} GPa is beyond any material: above E*/10 = {} GPa, the order of a perfect crystal's ideal strength; give contact.hardness (e.g. \"300 HV\") to cap the asperities' pressure",
                crate::io::text::significant(solution.max_pressure_pa * 1e-9, 3, 1e6, true),
                crate::io::text::significant(limit_pa * 1e-9, 3, 1e6, true)
            ));
        }
    }
    warnings
}

/// How many times the steps between neighbouring samples a seam's step may be before a
/// periodic solve of a measured map is warned about: a map that tiles (a generated one, a
/// measured one cut to a period) has seam steps like its neighbours'.
pub const SEAM_STEP_RATIO: f64 = 3.0;

/// The warning for a measured map solved periodically whose opposite edges do not meet
/// (a seam step more than [`SEAM_STEP_RATIO`] times the neighbours', rms) and whose contact
/// touches that seam (pressure on its first or last column, or row): the periodic solve
/// repeats the map, and the step at the seam is a ridge the counter-surface may touch
/// first. A seam the contact stays away from changes nothing and is not warned about.
pub fn seam_warning(
    heights: ndarray::ArrayView2<f64>,
    pressure_pa: &ndarray::Array2<f64>,
) -> Option<String> {
    let steps = crate::surface::seam_steps_m(heights);
    let (ny, nx) = pressure_pa.dim();
    let on_seam = |axis: usize| -> usize {
        if axis == 0 {
            (0..ny)
                .filter(|&j| pressure_pa[[j, 0]] > 0.0 || pressure_pa[[j, nx - 1]] > 0.0)
                .count()
        } else {
            (0..nx)
                .filter(|&i| pressure_pa[[0, i]] > 0.0 || pressure_pa[[ny - 1, i]] > 0.0)
                .count()
        }
    };
    let worst = steps
        .iter()
        .enumerate()
        .filter(|(_, (seam, inner))| *seam > SEAM_STEP_RATIO * *inner)
        .map(|(axis, &steps)| (axis, steps, on_seam(axis)))
        .filter(|&(_, _, cells)| cells > 0)
        .max_by(|a, b| (a.1 .0 / a.1 .1).total_cmp(&(b.1 .0 / b.1 .1)))?;
    let (axis, (seam, inner), cells) = worst;
    let (axis, lines) = if axis == 0 {
        ("x", "columns")
    } else {
        ("y", "rows")
    };
    Some(format!(
        "the map's opposite edges do not meet: repeated periodically it steps by {:.3} µm rms at the seam along {axis} (against {:.3} µm between neighbouring samples), and the contact touches the seam ({cells} contact lines on its first or last {lines}); the ridge may carry contact the measured surface does not have: solve with contact.periodic = false if the contact lies inside the map, or crop the map to a period",
        seam * 1e6,
        inner * 1e6
    ))
}

/// The report's maxima under the scene's solved contact: [`subsurface_maxima`], or a coated
/// body's ([`super::coated_rough::maxima`]) with them.
pub fn scene_maxima(
    scene: &Scene,
    solution: &RoughSolution,
) -> Result<(StressMaxima, Option<super::coated_rough::CoatingMaxima>), RoughStudyError> {
    match &scene.contact.coating {
        Some(coating) => {
            let found = super::coated_rough::maxima(solution, coating, scene.contact.friction)?;
            Ok((found.stress_maxima(), Some(found)))
        }
        None => Ok((
            subsurface_maxima(solution, scene.contact.friction, scene.contact.poisson)?.0,
            None,
        )),
    }
}

/// The findings under the scene's solved contact ([`subsurface_maxima`], or a coated body's
/// [`super::coated_rough::maxima`]; the plasticity index of Greenwood & Williamson from the
/// levelled surface's summits, with a hardness).
pub fn findings(
    scene: &Scene,
    solution: &RoughSolution,
) -> Result<ContactFindings, RoughStudyError> {
    if let Some(coating) = &scene.contact.coating {
        let found = super::coated_rough::maxima(solution, coating, scene.contact.friction)?;
        let rough = scene.contact.rough;
        let mut warnings = warnings_of(solution, rough.and_then(|r| r.e_star_pa), None);
        warnings.extend(scene_seam_warning(scene, solution));
        return Ok(ContactFindings {
            maxima: found.stress_maxima(),
            coating: Some(found),
            search_depth_m: found.search_depth_m,
            plasticity_index: None,
            warnings,
        });
    }
    let rough = scene.contact.rough;
    let mut findings = findings_of(
        solution,
        &RoughMaterials {
            friction: scene.contact.friction,
            poisson: scene.contact.poisson,
            e_star_pa: rough.and_then(|r| r.e_star_pa),
            hardness_pa: rough.and_then(|r| r.hardness_pa),
        },
        scene
            .surface
            .as_ref()
            .map(|surface| (surface.heights.as_ref(), surface.generated)),
    )?;
    findings
        .warnings
        .extend(scene_seam_warning(scene, solution));
    Ok(findings)
}

/// What [`findings_of`] needs of a rough contact besides its solution: body 1's friction
/// (`q = μ p` in +x) and Poisson ratio, `E*` and the hardness (Pa).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughMaterials {
    pub friction: f64,
    pub poisson: f64,
    pub e_star_pa: Option<f64>,
    pub hardness_pa: Option<f64>,
}

/// [`findings`] of a contact solved on `surface` (its heights, and whether they were
/// generated, i.e. periodic and not windowed for the summits), without a scene: the Python
/// package's `contact` on a height array. The plasticity index needs the surface and a
/// hardness.
pub fn findings_of(
    solution: &RoughSolution,
    materials: &RoughMaterials,
    surface: Option<(&crate::surface::HeightMap, bool)>,
) -> Result<ContactFindings, NumericalError> {
    let (maxima, search_depth_m) =
        subsurface_maxima(solution, materials.friction, materials.poisson)?;
    let e_star_pa = materials.e_star_pa.unwrap_or(f64::NAN);
    let plasticity_index = match (materials.hardness_pa, surface) {
        (Some(hardness), Some((heights, generated))) => {
            let options = Options {
                form: FormRemoval::Plane,
                band_m: None,
                window: !generated,
            };
            stats::characterise(heights, &options).ok().map(|c| {
                crate::surface::gw::plasticity_index(
                    e_star_pa,
                    hardness,
                    c.summits.height_std_m,
                    c.summits.radius_m,
                )
                .0
            })
        }
        _ => None,
    };
    Ok(ContactFindings {
        maxima,
        coating: None,
        search_depth_m,
        plasticity_index,
        warnings: warnings_of(solution, materials.e_star_pa, materials.hardness_pa),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::rough::{Control, DEFAULT_TOLERANCE};

    /// The ideal-strength warning prints both pressures to three significant digits: a soft
    /// E* of 1 GPa gives "E*/10 = 0.1 GPa", not a rounded "0 GPa".
    #[test]
    fn the_ideal_strength_warning_prints_small_pressures_readably() {
        let n = 16;
        let d = 1e-6;
        let heights = ndarray::Array2::from_shape_fn((n, n), |(i, j)| {
            let (y, x) = ((i as f64 - 7.5) * d, (j as f64 - 7.5) * d);
            -(x * x + y * y) / (2.0 * 1e-5)
        });
        let problem = RoughContactProblem {
            heights_m: heights.view(),
            spacing_m: [d, d],
            e_star_pa: 1e9,
            periodicity: Periodicity::NonPeriodic,
            control: Control::Load { newtons: 1e-3 },
            hardness_pa: None,
            tolerance: DEFAULT_TOLERANCE,
            max_iterations: rough::DEFAULT_MAX_ITERATIONS,
            memory_limit_bytes: 1 << 30,
        };
        let solution = rough::solve(&problem, &mut |_, _| {}).expect("solves");
        assert!(
            solution.max_pressure_pa > 1e8,
            "{}",
            solution.max_pressure_pa
        );
        let warnings = warnings_of(&solution, Some(1e9), None);
        let warning = warnings
            .iter()
            .find(|w| w.contains("beyond any material"))
            .expect("the ideal-strength warning");
        assert!(warning.contains("E*/10 = 0.1 GPa"), "{warning}");
        let peak = crate::io::text::significant(solution.max_pressure_pa * 1e-9, 3, 1e6, true);
        assert!(peak != "0", "{warning}");
        assert!(
            warning.contains(&format!("peak pressure {peak} GPa")),
            "{warning}"
        );
    }
}

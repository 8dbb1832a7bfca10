//! A coated scene computed once for every sink: the contact of the gridded paraboloid solved
//! with the layered influence coefficients ([`crate::contact::coated`]), then the stresses in
//! the plane of sliding `y = 0` (the plane of symmetry of the Hertz pair) at depths through
//! the coating, on both sides of the interface and into the substrate
//! ([`crate::coating::stress`]), and their maxima.
//!
//! ## The grid
//! The scene's `[numerical]` grid: `cells` per side over ±`extent` semi-axes of the coating's
//! Hertz contact (the contact of a half-space of the coating's material, which sets the
//! scene's `a` and `p0`). Its cells must be at most half the coating's thickness
//! ([`crate::coating::kernel::MIN_THICKNESS_CELLS`]); a coarser grid is refused under
//! `numerical.cells` with the count needed. The pressure must stay inside the grid (a hard
//! coating on a soft substrate spreads the contact up to `(E1'/E2')^(1/3)` times the coating's
//! Hertz radius), or the solver's "enlarge the domain" error names the edge.
//!
//! ## The depths
//! In the coating `2 min(h, 2.5a)/dx` depths (12 to 60) from the surface to `min(h, 2.5a)`;
//! in a coating thicker than that 24 more whose steps grow geometrically to the interface (its
//! coating side: a thick coating's maximum lies at the contact's depth, not spread over `h`);
//! then the interface's substrate side, then 72 depths to `max(2.5 a, h + 1.5 a)`. The maxima
//! are the largest samples (no refinement between them): their places are good to the
//! sampling, a cell along `x` and the depth step. The surface's `σxx` peaks at the contact's
//! edge, a kink between two cells where the pressure falls as `√(a - r)`: it is also taken at
//! the edges, extrapolated from the free surface outside
//! ([`crate::coating::stress::surface_edge_values`]; against Love's strain-function
//! reference within 1.2 % on the default grid, where the largest cell sample was up to 7.3 %
//! low).

use ndarray::Array2;
use rayon::prelude::*;

use crate::coating::line::LineStress;
use crate::coating::stress::LayeredStress;
use crate::coating::{Layered, Side};
use crate::contact::coated::{self, CoatedContactError, LineSolution};
use crate::contact::rough::RoughContactError;
use crate::contact::rough::{self, Control, RoughContactProblem, RoughSolution};
use crate::operator::elastic::Periodicity;
use crate::scene::{CoatingSpec, Hertz};
use crate::scene::{ContactKind, Scene};
use crate::stress::Stress;

/// The most cells per side a coated scene takes (its kernel is built on a grid four times as
/// wide: 1024 cells need about 0.6 GB).
pub const MAX_CELLS: usize = 1024;

/// The most strips a coated line contact takes (its active set solves a dense system over the
/// strips in contact: 4096 strips over ±2b, about 2048 in contact, take some seconds).
pub const MAX_LINE_CELLS: usize = 4096;

/// Why a coated scene cannot be computed.
#[derive(Debug, thiserror::Error)]
pub enum CoatedStudyError {
    /// The scene's grid cannot carry this coating ([`admit_grid`]).
    #[error("{0}")]
    Grid(GridRefusal),
    /// The pressure reaches the grid's edge: the window `numerical.extent` is too narrow.
    #[error("numerical.extent: the coated contact's pressure reaches the edge of its grid (±{extent} semi-axes of the coating's Hertz contact), at {place}: the contact must lie inside the grid\nhint: raise numerical.extent (a hard coating on a soft substrate spreads the contact up to (E_coating'/E_substrate')^(1/3) times the coating's Hertz radius), and numerical.cells in proportion to keep the cells' size")]
    ExtentTooSmall { extent: String, place: String },
    #[error("a coated scene needs a line, point or elliptical contact with bodies and a load")]
    NotDimensional,
    #[error(transparent)]
    Contact(#[from] CoatedContactError),
    #[error(transparent)]
    Transform(#[from] crate::operator::transform::TransformError),
    #[error("sweep step {step}: {message}")]
    Step { step: usize, message: String },
}

/// A stress value and its place (m; `y` is 0: the plane of sliding).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Located {
    pub value_pa: f64,
    pub x_m: f64,
    pub z_m: f64,
}

impl Located {
    pub(super) const NONE: Located = Located {
        value_pa: f64::NEG_INFINITY,
        x_m: 0.0,
        z_m: 0.0,
    };

    pub(super) fn keep_larger(&mut self, value: f64, x: f64, z: f64) {
        if value > self.value_pa {
            *self = Located {
                value_pa: value,
                x_m: x,
                z_m: z,
            };
        }
    }
}

/// The maxima of a coated body's stresses in the plane of sliding.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoatedMaxima {
    /// Von Mises anywhere (coating or substrate).
    pub von_mises: Located,
    pub coating_von_mises: Located,
    pub coating_tresca: Located,
    pub substrate_von_mises: Located,
    pub substrate_tresca: Located,
    /// The interface's shear traction `sqrt(σxz² + σyz²)` at `z = h`.
    pub interface_shear: Located,
    /// The interface's normal stress `σzz` at `z = h`: most compressive (a value, negative)
    /// and most tensile.
    pub interface_normal_min: Located,
    pub interface_normal_max: Located,
    /// The largest `σxx` on the surface (with friction, at the trailing edge).
    pub surface_tension: Located,
}

/// The section `y = 0` the figure draws: von Mises at each depth (rows) and cell (columns).
#[derive(Clone, Debug, PartialEq)]
pub struct CoatedSection {
    /// Cell centres along x, m.
    pub x_m: Vec<f64>,
    /// Depths of the rows, m (increasing; the interface appears twice, coating side first).
    pub z_m: Vec<f64>,
    /// Which side of the interface each row belongs to.
    pub sides: Vec<Side>,
    /// `[row, column]`, Pa.
    pub von_mises_pa: Array2<f64>,
    /// The surface pressure along the section, Pa.
    pub pressure_pa: Vec<f64>,
}

/// The solved contact of a coated scene.
#[derive(Clone, Debug)]
pub enum CoatedSolution {
    /// Point and elliptical contacts: the 2-D grid of the DC-FFT solver.
    Surface(RoughSolution),
    /// Line contacts: the 1-D grid of [`crate::contact::coated::solve_line`].
    Line(LineSolution),
}

impl CoatedSolution {
    pub fn max_pressure_pa(&self) -> f64 {
        match self {
            Self::Surface(s) => s.max_pressure_pa,
            Self::Line(l) => l.max_pressure_pa,
        }
    }

    /// The approach of distant points of the bodies, m; `None` for a line contact (a plane
    /// problem's displacements are defined up to a constant).
    pub fn approach_m(&self) -> Option<f64> {
        match self {
            Self::Surface(s) => Some(s.approach_m),
            Self::Line(_) => None,
        }
    }

    /// `[nx, ny]` cells (`ny = 1` for a line contact).
    pub fn grid(&self) -> [usize; 2] {
        match self {
            Self::Surface(s) => [s.pressure_pa.dim().1, s.pressure_pa.dim().0],
            Self::Line(l) => [l.pressure_pa.len(), 1],
        }
    }
}

/// A coated scene, computed.
#[derive(Clone, Debug)]
pub struct CoatedStudy {
    pub spec: CoatingSpec,
    pub kind: ContactKind,
    pub friction: f64,
    /// N (point, elliptical) or N/m (line).
    pub load_n: f64,
    /// The coating's Hertz contact: semi-axes along x and y (a line contact's half-width
    /// twice), peak pressure.
    pub hertz_semi_axes_m: [f64; 2],
    pub hertz_p0_pa: f64,
    /// Cell sides along x and y (a line contact's strips: the width twice).
    pub spacing_m: [f64; 2],
    pub solution: CoatedSolution,
    /// Point and elliptical contacts: the loaded cells' area, m² (0 for a line contact).
    pub contact_area_m2: f64,
    /// `sqrt(area / π)` (0 for a line contact).
    pub contact_radius_m: f64,
    /// Half the contact's extent along x and along y through the centre, m (a line contact:
    /// its half-width, from the refined edges of [`LineSolution::edges_m`], twice).
    pub semi_axes_m: [f64; 2],
    pub maxima: CoatedMaxima,
    /// Per layer, top first: its maxima and those of the interface under it
    /// ([`super::coated_layers`]; with one coating, the coating's).
    pub layers: Vec<super::coated_layers::LayerMaxima>,
    /// The load at which the first given strength is reached (filled by
    /// [`crate::study::commands::hertz`] when strengths are given: it solves the contact again
    /// at other loads).
    pub first_failure: Option<super::coated_layers::FirstFailure>,
    pub section: CoatedSection,
    /// Wall-clock seconds of the contact solve and of the stresses.
    pub solve_seconds: f64,
    pub stress_seconds: f64,
}

/// Why a coated scene's grid is refused: the key to change, what is wrong, and how to fix it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GridRefusal {
    pub key: &'static str,
    pub message: String,
    pub hint: String,
}

impl std::fmt::Display for GridRefusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}\nhint: {}", self.key, self.message, self.hint)
    }
}

/// The grid of a coated scene: `cells` over ±`extent` semi-axes `semi_axis_m` (the larger),
/// refused beyond `max_cells` or when coarser than the coating allows (module doc). Returns
/// the cell's side, m.
fn check_grid(
    spec: &CoatingSpec,
    cells: usize,
    extent: f64,
    semi_axis_m: f64,
    max_cells: usize,
    line: bool,
) -> Result<f64, GridRefusal> {
    let unit = if line { "strips" } else { "cells a side" };
    let what = if line {
        "a coated line contact"
    } else {
        "a coated point or elliptical contact"
    };
    if cells > max_cells {
        return Err(GridRefusal {
            key: "numerical.cells",
            message: format!("{what} takes at most {max_cells} {unit}, got {cells}"),
            hint: if line {
                format!("set numerical.cells to {max_cells} or fewer (the active set solves a dense system over the strips in contact)")
            } else {
                format!("set numerical.cells to {max_cells} or fewer (the layered kernel lives on a grid four times as wide: {max_cells} cells take about {} already)", crate::io::text::bytes(cost(false, max_cells).0 as u64))
            },
        });
    }
    let spacing = 2.0 * extent * semi_axis_m / cells as f64;
    let h = spec.thickness_m;
    let largest = coated::largest_cell_m(h);
    let um = |m: f64| crate::io::text::approx(m * 1e6);
    if spacing > largest * (1.0 + 1e-12) {
        let needed = (2.0 * extent * semi_axis_m / largest).ceil() as usize;
        if needed > max_cells {
            // A larger load widens the contact and needs more cells, not fewer.
            return Err(GridRefusal {
                key: "numerical.cells",
                message: format!(
                    "the coating ({} µm) needs cells of at most {} µm (half its thickness): over ±{} semi-axes of {} µm that is {needed} {unit}, more than the {max_cells} {what} takes",
                    um(h),
                    um(largest),
                    crate::io::text::approx(extent),
                    um(semi_axis_m),
                ),
                hint: {
                    // The extent that fits, if the contact (about ±1.1 a) still fits in it;
                    // otherwise the load that does (cells ∝ a ∝ W^(1/3) for a point, W^(1/2)
                    // for a line).
                    let fit = extent * max_cells as f64 / needed as f64;
                    let tail = format!(
                        "at h/a = {} the coating barely changes the contact: the uncoated scene gives its pressure",
                        crate::io::text::significant(h / semi_axis_m, 2, 1e6, true)
                    );
                    if fit >= 1.25 {
                        format!("set numerical.extent to {} or less (the contact must stay inside the grid); {tail}", crate::io::text::significant((fit * 20.0).floor() / 20.0, 3, 1e6, true))
                    } else {
                        let ratio = 1.25 / fit;
                        let load = if line { ratio.powi(-2) } else { ratio.powi(-3) };
                        format!("even at numerical.extent = 1.25 it needs {} {unit}: the load would have to be below {} % of this one (a smaller contact needs fewer {unit}); {tail}", (needed as f64 * 1.25 / extent).ceil(), crate::io::text::significant(100.0 * load, 2, 1e6, true))
                    }
                },
            });
        }
        return Err(GridRefusal {
            key: "numerical.cells",
            message: format!(
                "the coating ({} µm) needs cells of at most {} µm (half its thickness), the grid of {cells} {unit} over ±{} semi-axes has {} µm",
                um(h),
                um(largest),
                crate::io::text::approx(extent),
                um(spacing)
            ),
            hint: format!(
                "set numerical.cells to at least {needed} (or numerical.extent lower, or a thicker contact.body1.coating.thickness)"
            ),
        });
    }
    Ok(spacing)
}

/// The coated scene's grid refused, or its estimated cost: `(bytes, cpu_seconds)` of the
/// largest step (a thickness sweep checks every step's grid). Run by [`super::admit`] before
/// anything is computed, so `check` refuses what `hertz` would.
pub fn admit_grid(scene: &Scene) -> Result<Option<(usize, f64)>, GridRefusal> {
    let (Some(_), Some(_)) = (scene.contact.coating, scene.contact.dimensional) else {
        return Ok(None);
    };
    if scene.contact.kind == ContactKind::Rough {
        return Ok(None);
    }
    let steps = scene.sweep.as_ref().map_or(1, |s| s.values.len());
    let line = scene.contact.kind == ContactKind::Line;
    for k in 0..steps {
        let Ok(stepped) = super::at_step(scene, k) else {
            continue;
        };
        let (Some(spec), Some(dimensional)) =
            (stepped.contact.coating, stepped.contact.dimensional)
        else {
            continue;
        };
        let semi_axis = match dimensional.hertz {
            Hertz::Point(point) => point.radius_m,
            Hertz::Elliptical(e) => e.semi_axis_x_m.max(e.semi_axis_y_m),
            Hertz::Line(line) => line.half_width_m,
        };
        let max = if line { MAX_LINE_CELLS } else { MAX_CELLS };
        check_grid(
            &spec,
            stepped.numerical.cells,
            stepped.numerical.extent_over_a,
            semi_axis,
            max,
            line,
        )
        .map_err(|mut refusal| {
            if steps > 1 {
                refusal.message = format!("sweep step {}: {}", k + 1, refusal.message);
            }
            refusal
        })?;
    }
    let (bytes, seconds) = cost(line, scene.numerical.cells);
    Ok(Some((bytes, seconds * steps as f64)))
}

/// The estimated peak memory (bytes) and CPU time (s) of one coated solve and its stresses on
/// `cells` cells a side (a line contact: strips), fitted to the runs measured with
/// `/usr/bin/time` in `docs/coatings.md` ("What `check` estimates"): a point contact's
/// within 30 % from 64² to 512², a line's within a factor of two (its active set takes a
/// number of dense solves that varies with the grid).
pub fn cost(line: bool, cells: usize) -> (usize, f64) {
    let n = cells as f64;
    if line {
        // The strips in contact (about half) solve dense systems of their count squared.
        let bytes = 12.0 * 1024.0 * 1024.0 + 12.0e3 * n;
        let seconds = 0.05 + 1.6e-13 * n.powi(4);
        return (bytes as usize, seconds);
    }
    // The layered kernel on a grid four times as wide, the solver's transforms.
    let bytes = 11.3e6 + 472.0 * n * n;
    let seconds = 0.05 + 4.0e-6 * n * n * n.log2();
    (bytes as usize, seconds)
}

/// What the contact solve hands the stresses: the solution, the section's cell centres, the
/// pressure along it, the loaded area and the contact's semi-axes.
struct Solved {
    solution: CoatedSolution,
    spacing_m: [f64; 2],
    x_m: Vec<f64>,
    pressure_pa: Vec<f64>,
    contact_area_m2: f64,
    semi_axes_m: [f64; 2],
    rows: Vec<Array2<f64>>,
}

/// The coated contact and its stresses (module doc).
pub fn solve(scene: &Scene) -> Result<CoatedStudy, CoatedStudyError> {
    let spec = scene
        .contact
        .coating
        .ok_or(CoatedStudyError::NotDimensional)?;
    let dimensional = scene
        .contact
        .dimensional
        .ok_or(CoatedStudyError::NotDimensional)?;
    let friction = scene.contact.friction;
    let layered = spec.layered();
    let cells = scene.numerical.cells;
    let extent = scene.numerical.extent_over_a;
    let (semi_axes, p0, load) = match dimensional.hertz {
        Hertz::Point(point) => ([point.radius_m; 2], point.p0_pa, point.load_n),
        Hertz::Elliptical(e) => ([e.semi_axis_x_m, e.semi_axis_y_m], e.p0_pa, e.load_n),
        Hertz::Line(line) => ([line.half_width_m; 2], line.p0_pa, line.load_n_per_m),
    };
    let depths = |spacing: f64| depths(&layered, spacing, semi_axes[0].max(semi_axes[1]));
    let solve_started = std::time::Instant::now();
    let (solved, depths, mut stress_seconds) = match dimensional.hertz {
        Hertz::Line(line) => {
            let d = check_grid(&spec, cells, extent, semi_axes[0], MAX_LINE_CELLS, true)
                .map_err(CoatedStudyError::Grid)?;
            let origin = -extent * semi_axes[0] + 0.5 * d;
            let x_m: Vec<f64> = (0..cells).map(|i| origin + i as f64 * d).collect();
            let gap: Vec<f64> = x_m
                .iter()
                .map(|x| x * x / (2.0 * line.effective_radius_m))
                .collect();
            let solution =
                coated::solve_line(&layered, spec.counter_per_pa, &gap, d, origin, load)?;
            let started = std::time::Instant::now();
            let shear: Vec<f64> = solution.pressure_pa.iter().map(|p| friction * p).collect();
            let field = LineStress::new(
                layered,
                &solution.pressure_pa,
                (friction != 0.0).then_some(&shear[..]),
                d,
            )?;
            let depths = depths(d);
            let rows = depths
                .par_iter()
                .map(|&(z, side)| field.at_depth(z, side))
                .collect::<Result<Vec<_>, _>>()?;
            let stress_seconds = started.elapsed().as_secs_f64();
            let half_width = solution.half_width_m;
            (
                Solved {
                    pressure_pa: solution.pressure_pa.clone(),
                    solution: CoatedSolution::Line(solution),
                    spacing_m: [d, d],
                    x_m,
                    contact_area_m2: 0.0,
                    semi_axes_m: [half_width; 2],
                    rows,
                },
                depths,
                stress_seconds,
            )
        }
        Hertz::Point(_) | Hertz::Elliptical(_) => {
            let curvature = match dimensional.hertz {
                Hertz::Elliptical(e) => [
                    e.curvature.half_curvature_x_per_m,
                    e.curvature.half_curvature_y_per_m,
                ],
                Hertz::Point(point) => [0.5 / point.effective_radius_m; 2],
                Hertz::Line(_) => return Err(CoatedStudyError::NotDimensional),
            };
            check_grid(
                &spec,
                cells,
                extent,
                semi_axes[0].max(semi_axes[1]),
                MAX_CELLS,
                false,
            )
            .map_err(CoatedStudyError::Grid)?;
            let spacing = semi_axes.map(|s| 2.0 * extent * s / cells as f64);
            let shape = [cells, cells];
            let origin = [
                -extent * semi_axes[0] + 0.5 * spacing[0],
                -extent * semi_axes[1] + 0.5 * spacing[1],
            ];
            let heights = super::coupled::paraboloid(shape, spacing, origin, curvature);
            let e_far = 1.0
                / ((1.0 - spec.substrate.poisson.powi(2)) / spec.substrate.modulus_pa
                    + spec.counter_per_pa);
            let problem = RoughContactProblem {
                heights_m: heights.view(),
                spacing_m: spacing,
                e_star_pa: e_far,
                periodicity: Periodicity::NonPeriodic,
                control: Control::Load { newtons: load },
                hardness_pa: None,
                tolerance: rough::DEFAULT_TOLERANCE,
                max_iterations: rough::DEFAULT_MAX_ITERATIONS,
                memory_limit_bytes: crate::field::memory_limit_bytes(),
            };
            let solution = coated::solve(&problem, &layered, spec.counter_per_pa, &mut |_, _| {})
                .map_err(|e| match e {
                // The grid is the scene's window, not a map: name its extent.
                CoatedContactError::Contact(RoughContactError::PressureAtEdge { row, column }) => {
                    CoatedStudyError::ExtentTooSmall {
                        extent: crate::io::text::approx(extent),
                        place: format!(
                            "x = {} µm, y = {} µm",
                            crate::io::text::approx((origin[0] + column as f64 * spacing[0]) * 1e6),
                            crate::io::text::approx((origin[1] + row as f64 * spacing[1]) * 1e6)
                        ),
                    }
                }
                other => other.into(),
            })?;
            let started = std::time::Instant::now();
            let pressure = &solution.pressure_pa;
            let shear = pressure.mapv(|p| friction * p);
            let layers = LayeredStress::new(
                layered,
                pressure.view(),
                (friction != 0.0).then_some(shear.view()),
                spacing,
                false,
            )?;
            let depths = depths(spacing[0]);
            let centre_row = cells / 2;
            let rows: Vec<Array2<f64>> = depths
                .par_iter()
                .map(|&(z, side)| layers.row(centre_row, z, side))
                .collect();
            let stress_seconds = started.elapsed().as_secs_f64();
            let x_m: Vec<f64> = (0..cells)
                .map(|i| origin[0] + i as f64 * spacing[0])
                .collect();
            let contact_cells = pressure.iter().filter(|&&p| p > 0.0).count();
            let extent_along = |line: Vec<f64>, d: f64| {
                let count = line.iter().filter(|&&p| p > 0.0).count();
                0.5 * count as f64 * d
            };
            let semi_axes_m = [
                extent_along(pressure.row(centre_row).to_vec(), spacing[0]),
                extent_along(pressure.column(cells / 2).to_vec(), spacing[1]),
            ];
            (
                Solved {
                    pressure_pa: pressure.row(centre_row).to_vec(),
                    contact_area_m2: contact_cells as f64 * spacing[0] * spacing[1],
                    solution: CoatedSolution::Surface(solution),
                    spacing_m: spacing,
                    x_m,
                    semi_axes_m,
                    rows,
                },
                depths,
                stress_seconds,
            )
        }
    };
    let solve_seconds = solve_started.elapsed().as_secs_f64() - stress_seconds;
    let started = std::time::Instant::now();
    let (maxima, von_mises) = maxima_of(
        &layered,
        &depths,
        &solved.rows,
        &solved.x_m,
        &solved.pressure_pa,
    );
    let layers = super::coated_layers::layer_maxima(&layered, &depths, &solved.rows, &solved.x_m);
    stress_seconds += started.elapsed().as_secs_f64();
    Ok(CoatedStudy {
        spec,
        kind: scene.contact.kind,
        friction,
        load_n: load,
        hertz_semi_axes_m: semi_axes,
        hertz_p0_pa: p0,
        spacing_m: solved.spacing_m,
        contact_area_m2: solved.contact_area_m2,
        contact_radius_m: (solved.contact_area_m2 / std::f64::consts::PI).sqrt(),
        semi_axes_m: solved.semi_axes_m,
        maxima,
        layers,
        first_failure: None,
        section: CoatedSection {
            x_m: solved.x_m,
            z_m: depths.iter().map(|d| d.0).collect(),
            sides: depths.iter().map(|d| d.1).collect(),
            von_mises_pa: von_mises,
            pressure_pa: solved.pressure_pa,
        },
        solution: solved.solution,
        solve_seconds,
        stress_seconds,
    })
}

/// Every step of a coated scene's sweep (`[sweep] parameter = "coating_thickness"`), each
/// solved as [`solve`] does (the layered kernels depend on the thickness: built once per
/// step); the scene itself as one step without a sweep. `on_step(done, total)` after each.
pub fn sweep(
    scene: &Scene,
    on_step: &mut dyn FnMut(usize, usize),
) -> Result<Vec<CoatedStudy>, CoatedStudyError> {
    let steps = scene.sweep.as_ref().map_or(1, |s| s.values.len());
    let mut out = Vec::with_capacity(steps);
    for k in 0..steps {
        let stepped = super::at_step(scene, k).map_err(|e| CoatedStudyError::Step {
            step: k + 1,
            message: e.to_string(),
        })?;
        out.push(solve(&stepped).map_err(|e| CoatedStudyError::Step {
            step: k + 1,
            message: e.to_string(),
        })?);
        on_step(k + 1, steps);
    }
    Ok(out)
}

/// The maxima of the rows (`[component, x]` at each of `depths`) and the von Mises section;
/// the surface's `σxx` also at the contact's edges along the row (`pressure_pa`), between the
/// cells ([`crate::coating::stress::surface_edge_values`]).
fn maxima_of(
    layered: &Layered,
    depths: &[(f64, Side)],
    rows: &[Array2<f64>],
    x_m: &[f64],
    pressure_pa: &[f64],
) -> (CoatedMaxima, Array2<f64>) {
    // The interface over the substrate (a stack's deepest).
    let h = layered.total_thickness_m();
    let mut maxima = CoatedMaxima {
        von_mises: Located::NONE,
        coating_von_mises: Located::NONE,
        coating_tresca: Located::NONE,
        substrate_von_mises: Located::NONE,
        substrate_tresca: Located::NONE,
        interface_shear: Located::NONE,
        interface_normal_min: Located::NONE,
        interface_normal_max: Located::NONE,
        surface_tension: Located::NONE,
    };
    let mut von_mises = Array2::zeros((depths.len(), x_m.len()));
    for (r, ((z, side), row)) in depths.iter().zip(rows).enumerate() {
        for (i, &x) in x_m.iter().enumerate() {
            let s = Stress {
                xx: row[[0, i]],
                yy: row[[1, i]],
                zz: row[[2, i]],
                yz: row[[3, i]],
                xz: row[[4, i]],
                xy: row[[5, i]],
            };
            let vm = s.von_mises();
            let tresca = s.max_shear();
            von_mises[[r, i]] = vm;
            maxima.von_mises.keep_larger(vm, x, *z);
            match layered.layer_at(*z, *side) {
                Some(_) => {
                    maxima.coating_von_mises.keep_larger(vm, x, *z);
                    maxima.coating_tresca.keep_larger(tresca, x, *z);
                }
                None => {
                    maxima.substrate_von_mises.keep_larger(vm, x, *z);
                    maxima.substrate_tresca.keep_larger(tresca, x, *z);
                }
            }
            if *z == h && *side == Side::Coating {
                maxima.interface_shear.keep_larger(s.xz.hypot(s.yz), x, *z);
                maxima.interface_normal_max.keep_larger(s.zz, x, *z);
                // The most compressive: the largest of -σzz, stored with its sign.
                if -s.zz > -maxima.interface_normal_min.value_pa
                    || maxima.interface_normal_min.value_pa == f64::NEG_INFINITY
                {
                    maxima.interface_normal_min = Located {
                        value_pa: s.zz,
                        x_m: x,
                        z_m: *z,
                    };
                }
            }
            if *z == 0.0 {
                maxima.surface_tension.keep_larger(s.xx, x, 0.0);
            }
        }
        if *z == 0.0 {
            let sxx = row.row(0).to_vec();
            for (x, value) in crate::coating::stress::surface_edge_values(x_m, pressure_pa, &sxx) {
                maxima.surface_tension.keep_larger(value, x, 0.0);
            }
        }
    }
    (maxima, von_mises)
}

/// The depths sampled (module doc), with their side of the interface.
fn depths(layered: &Layered, cell_m: f64, semi_axis_m: f64) -> Vec<(f64, Side)> {
    if !layered.under.is_empty() {
        return super::coated_layers::stack_depths(layered, cell_m, semi_axis_m);
    }
    let h = layered.thickness_m;
    // The contact's own depths: uniform down to `min(h, 2.5 a)`; below them, in a coating
    // thicker than that, steps growing geometrically to the interface (the contact's field
    // has decayed there; the interface's own terms are sampled on both of its sides).
    let near = h.min(2.5 * semi_axis_m);
    let in_near = ((2.0 * near / cell_m).ceil() as usize).clamp(12, 60);
    let mut out: Vec<(f64, Side)> = (0..=in_near)
        .map(|i| {
            let z = if i == in_near {
                near
            } else {
                near * i as f64 / in_near as f64
            };
            (z, Side::Coating)
        })
        .collect();
    if h > near {
        let deeper = 24;
        let ratio = (h / near).powf(1.0 / deeper as f64);
        for i in 1..=deeper {
            let z = if i == deeper { h } else { near * ratio.powi(i) };
            out.push((z, Side::Coating));
        }
    }
    out.push((h, Side::Substrate));
    let end = (2.5 * semi_axis_m).max(h + 1.5 * semi_axis_m);
    let below = 72;
    for i in 1..=below {
        out.push((h + (end - h) * i as f64 / below as f64, Side::Substrate));
    }
    out
}

#[cfg(test)]
#[path = "coated_tests.rs"]
mod tests;

//! The coupled thermo-mechanical contact (`[thermal] coupled = true`): the frictional heat
//! bulges the surfaces, the bulge changes the contact, the new pressure changes the heat,
//! until pressure and distortion agree (Liu & Wang 2001).
//!
//! ## The iteration
//! Start from the isothermal pressure `p0`. At step `k` the flux `q = μ p(k-1) V` is divided
//! between the bodies (their shares as in the thermal study; Blok's partition from the mean
//! temperatures under the current flux), each body's outward thermal displacement
//! ([`crate::thermal::distortion`], for the speed of the contact over it) is computed, and
//! their sum `w` is added to the combined heights: a bulge of either surface closes the gap
//! like a higher asperity. The contact is solved again under the same load on `h + w(k)`,
//! with `w(k) = w(k-1) + ω (w(p(k-1)) - w(k-1))`: `ω = 1` while the pressure change falls, and
//! halved (down to 1/16) when it grows, since strong heating can make the plain iteration
//! oscillate. Converged when the change of pressure `Σ |p(k) - p(k-1)| / Σ p(k)` is below
//! [`TOLERANCE`] (each contact solve converges to its own tolerance, 1e-8 by default). Without
//! heating (`α = 0` for both bodies) `w = 0` and the first solve is the isothermal one, bit for
//! bit.
//!
//! ## Runaway
//! Strong heating can make the feedback run away: the bulge lifts the surfaces outside the
//! hottest region, the contact shrinks, the flux concentrates and the bulge grows, until the
//! heat and not the elasticity decides the contact (a thermal asperity; thermoelastic
//! instability, Barber 1969). A fixed point of the iteration may then exist on the grid, but it
//! is not a state the model describes: every iterate (the isothermal contact included) is
//! checked, and the iteration stops with [`CoupledError::Runaway`], naming the last state that
//! passed, when the contact
//! - keeps less than [`MIN_AREA_FRACTION`] of its isothermal area (it ran away),
//! - falls below [`MIN_RESOLVED_CELLS`] cells (and to less than half its isothermal cells):
//!   less than about four cells across, which the grid does not resolve,
//! - or heats a body by more than [`MAX_FLASH_TEMPERATURE_RISE_K`], beyond any solid.
//!
//! Only a given load (or mean pressure) is coupled: the bulge of a stationary source is defined
//! up to a constant (see [`crate::thermal::distortion`]), which a given load absorbs into the
//! approach and a given approach would not.
//!
//! ## References
//! - S. Liu, Q. Wang, A three-dimensional thermomechanical model of contact between
//!   non-conforming rough surfaces, *ASME J. Tribol.* 123 (2001) 17–26.
//! - J. R. Barber, Thermoelastic instabilities in the sliding of conforming solids, *Proc.
//!   R. Soc. Lond. A* 312 (1969) 381–394.

use ndarray::{Array2, Zip};

use crate::contact::rough::{self, Control, RoughContactError, RoughContactProblem, RoughSolution};
use crate::operator::transform::TransformError;
use crate::scene::{ThermalBody, ThermalSpec};
use crate::thermal::distortion::DisplacementOperator;
use crate::thermal::heating::{frictional_flux, Partition};
use crate::thermal::kernel::CellGrid;
use crate::thermal::temperature::TemperatureOperator;

/// Convergence of the coupled iteration: relative change of pressure.
pub const TOLERANCE: f64 = 1e-6;
/// The most coupled iterations (each a contact solve).
pub const MAX_ITERATIONS: usize = 60;
/// A heated contact that keeps less than this fraction of its isothermal area has run away
/// (module doc): the heat, not the elasticity, decides it.
pub const MIN_AREA_FRACTION: f64 = 0.1;
/// Fewer contact cells than this (less than about four cells across) are not resolved by the
/// grid (unless the isothermal contact had hardly more).
pub const MIN_RESOLVED_CELLS: usize = 16;
/// A flash temperature rise beyond any solid: the highest melting points known, of hafnium
/// and tantalum carbides, are about 4200 K (CRC Handbook of Chemistry and Physics), so no
/// surface survives a rise of 4000 K above room temperature.
pub const MAX_FLASH_TEMPERATURE_RISE_K: f64 = 4000.0;

/// The coupled contact at one iterate, for the runaway checks and their messages.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoupledState {
    /// 0 for the isothermal contact.
    pub iteration: usize,
    pub contact_cells: usize,
    /// The contact's area over the isothermal one.
    pub area_fraction: f64,
    pub max_pressure_pa: f64,
    /// The largest flash temperature rise of either body under its share, K.
    pub max_temperature_rise_k: f64,
}

impl std::fmt::Display for CoupledState {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} contact cells ({:.1} % of the isothermal area), peak pressure {:.0} MPa, flash temperature rise {:.0} K",
            self.contact_cells,
            100.0 * self.area_fraction,
            self.max_pressure_pa * 1e-6,
            self.max_temperature_rise_k
        )
    }
}

/// A coupled iteration that ran away (module doc): what happened, at which iterate, the last
/// iterate that passed the checks, and the isothermal contact.
#[derive(Clone, Debug, PartialEq)]
pub struct Runaway {
    pub cause: String,
    pub at: CoupledState,
    pub last: CoupledState,
    pub isothermal: CoupledState,
}

/// How the contact is solved again at each coupled iteration: `solve(distortion, pressure)`
/// ([`iterate`]).
pub type ContactSolve<'a> =
    dyn FnMut(&Array2<f64>, &Array2<f64>) -> Result<RoughSolution, CoupledError> + 'a;

/// The message of a runaway (module doc).
fn runaway_message(
    cause: &str,
    at: &CoupledState,
    last: &CoupledState,
    isothermal: &CoupledState,
) -> String {
    let last = if last.iteration == 0 {
        "the isothermal contact itself".to_string()
    } else {
        format!("iteration {}: {last}", last.iteration)
    };
    format!(
        "the thermoelastic feedback runs away ({cause}) at iteration {}: {at}. This is thermoelastic instability: the heat, not the elasticity, decides the contact, and no steady coupled state exists for these conditions. The last resolved state was {last}; the isothermal contact: {} cells, peak pressure {:.0} MPa, flash temperature rise {:.0} K",
        at.iteration,
        isothermal.contact_cells,
        isothermal.max_pressure_pa * 1e-6,
        isothermal.max_temperature_rise_k
    )
}

/// Why the coupled contact has no solution.
#[derive(Debug, thiserror::Error)]
pub enum CoupledError {
    #[error("thermal.coupled: the coupled solution needs a given load or mean pressure, not an approach (the bulge of a stationary source is defined only up to a constant)\nhint: give contact.load (or contact.mean_pressure) instead of contact.approach, or set coupled = false")]
    ApproachControl,
    #[error("thermal.coupled: the thermoelastic feedback did not settle in {iterations} iterations (pressure change {change:.2e}, tolerance {TOLERANCE:.0e}); the last iterate: {last}\nhint: the heating may be beyond thermoelastic stability: lower thermal.speed or contact.friction, or set coupled = false")]
    NotConverged {
        iterations: usize,
        change: f64,
        last: CoupledState,
    },
    #[error("thermal.coupled: the isothermal pressure already heats the surface by {:.0} K, more than the {MAX_FLASH_TEMPERATURE_RISE_K:.0} K no solid survives ({}): the coupled feedback, which concentrates the heat further, describes no state there\nhint: lower the heat (thermal.speed, contact.friction or the load), or take bodies that conduct more; coupled = false reports the linear heating as it stands", .isothermal.max_temperature_rise_k, .isothermal)]
    BeyondAnySolid { isothermal: CoupledState },
    #[error("thermal.coupled: {}\nhint: lower the heat (thermal.speed, contact.friction or the load), or take bodies that conduct more or expand less; coupled = false gives the heating on the isothermal pressure (a bound that ignores the feedback)", runaway_message(&.0.cause, &.0.at, &.0.last, &.0.isothermal))]
    Runaway(Box<Runaway>),
    #[error(transparent)]
    Contact(#[from] RoughContactError),
    #[error(transparent)]
    Transform(#[from] TransformError),
}

/// The coupled solution next to the isothermal one.
#[derive(Clone, Debug, PartialEq)]
pub struct CoupledContact {
    pub isothermal: RoughSolution,
    pub heated: RoughSolution,
    /// The sum of both bodies' outward thermal displacements added to the heights (m), `[ny,
    /// nx]`, at the converged pressure.
    pub distortion_m: Array2<f64>,
    /// Body 1's share of the heat at convergence.
    pub body1_share: f64,
    /// Contact solves after the isothermal one.
    pub iterations: usize,
    /// The pressure change after each of them.
    pub changes: Vec<f64>,
}

/// One heated body: its distortion operator (none when it does not expand) and its
/// temperature operator (Blok's partition, and the runaway checks).
struct Body {
    distortion: Option<DisplacementOperator>,
    temperature: Option<TemperatureOperator>,
}

impl Body {
    fn new(grid: &CellGrid, body: &ThermalBody, heated: bool) -> Result<Self, TransformError> {
        let properties = &body.properties;
        let u = super::thermal::inverse_length(body);
        let k = properties.conductivity_w_per_m_k;
        let scale = (1.0 + body.material.poisson) * properties.expansion_per_k / k;
        Ok(Self {
            distortion: if scale > 0.0 {
                Some(DisplacementOperator::new(grid, u, scale)?)
            } else {
                None
            },
            temperature: if heated {
                Some(TemperatureOperator::new(grid, 0.0, u, k)?)
            } else {
                None
            },
        })
    }

    /// The mean temperature rise over the loaded cells under the whole `flux`.
    fn mean_temperature(
        &mut self,
        flux: &Array2<f64>,
        pressure: &Array2<f64>,
    ) -> Result<f64, TransformError> {
        let Some(operator) = self.temperature.as_mut() else {
            return Ok(0.0);
        };
        let t = operator.apply(flux.view())?;
        let (mut sum, mut count) = (0.0, 0usize);
        Zip::from(&t).and(pressure).for_each(|&t, &p| {
            if p > 0.0 {
                sum += t;
                count += 1;
            }
        });
        Ok(sum / count.max(1) as f64)
    }

    /// The largest temperature rise under `flux` (its share).
    fn max_temperature(&mut self, flux: &Array2<f64>) -> Result<f64, TransformError> {
        let Some(operator) = self.temperature.as_mut() else {
            return Ok(0.0);
        };
        let t = operator.apply(flux.view())?;
        Ok(t.iter().fold(0.0f64, |m, &v| m.max(v)))
    }
}

/// Solves the coupled contact of `problem` from its isothermal solution, heated by `spec` with
/// friction `friction`. `progress(iteration, change)` after each coupled iteration.
pub fn solve(
    problem: &RoughContactProblem,
    isothermal: RoughSolution,
    spec: &ThermalSpec,
    friction: f64,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<CoupledContact, CoupledError> {
    if matches!(problem.control, Control::Approach { .. }) {
        return Err(CoupledError::ApproachControl);
    }
    let (ny, nx) = problem.heights_m.dim();
    let grid = CellGrid {
        shape: [ny, nx],
        spacing_m: problem.spacing_m,
    };
    iterate(
        &grid,
        isothermal,
        spec,
        friction,
        progress,
        &mut |distortion, _| {
            let heights = &problem.heights_m + distortion;
            let step = RoughContactProblem {
                heights_m: heights.view(),
                ..problem.clone()
            };
            Ok(rough::solve(&step, &mut |_, _| {})?)
        },
    )
}

/// The coupled iteration (module doc) on `grid` from the isothermal solution, whatever solves
/// the contact: `solve(distortion, pressure)` solves the contact with the heights raised by
/// `distortion` (m), from `pressure` if it wishes (a worn surface's step solves it with its
/// wear compliance, [`crate::study::wear`]).
pub fn iterate(
    grid: &CellGrid,
    isothermal: RoughSolution,
    spec: &ThermalSpec,
    friction: f64,
    progress: &mut dyn FnMut(usize, f64),
    solve: &mut ContactSolve,
) -> Result<CoupledContact, CoupledError> {
    let [ny, nx] = grid.shape;
    let blok = spec.partition == Partition::Blok;
    let mut body1 = Body::new(
        grid,
        &spec.body1,
        spec.partition != Partition::Fraction(0.0),
    )?;
    let mut body2 = match &spec.body2 {
        Some(b) if spec.partition.needs_body2() => Some(Body::new(grid, b, true)?),
        _ => None,
    };
    // The runaway checks (module doc): each iterate's contact and flash temperature.
    let cells = |p: &Array2<f64>| p.iter().filter(|&&v| v > 0.0).count();
    let isothermal_cells = cells(&isothermal.pressure_pa);
    let state = |iteration: usize,
                 pressure: &Array2<f64>,
                 share: f64,
                 body1: &mut Body,
                 body2: Option<&mut Body>|
     -> Result<CoupledState, TransformError> {
        let flux = pressure.mapv(|p| frictional_flux(friction, p, spec.sliding_speed_m_per_s));
        let mut hottest = 0.0f64;
        if share > 0.0 {
            hottest = hottest.max(body1.max_temperature(&flux.mapv(|q| q * share))?);
        }
        if let (Some(b2), true) = (body2, share < 1.0) {
            hottest = hottest.max(b2.max_temperature(&flux.mapv(|q| q * (1.0 - share)))?);
        }
        let contact_cells = cells(pressure);
        Ok(CoupledState {
            iteration,
            contact_cells,
            area_fraction: contact_cells as f64 / isothermal_cells.max(1) as f64,
            max_pressure_pa: pressure.iter().fold(0.0f64, |m, &v| m.max(v)),
            max_temperature_rise_k: hottest,
        })
    };
    let runaway = |at: &CoupledState| -> Option<String> {
        if at.max_temperature_rise_k > MAX_FLASH_TEMPERATURE_RISE_K {
            Some(format!(
                "a flash temperature rise of {:.0} K, more than the {MAX_FLASH_TEMPERATURE_RISE_K:.0} K no solid survives",
                at.max_temperature_rise_k
            ))
        } else if at.iteration > 0
            && at.contact_cells < MIN_RESOLVED_CELLS
            && 2 * at.contact_cells < isothermal_cells
        {
            Some(format!(
                "the contact shrinks to {} cells, fewer than the {MIN_RESOLVED_CELLS} the grid resolves",
                at.contact_cells
            ))
        } else if at.area_fraction < MIN_AREA_FRACTION {
            Some(format!(
                "the contact shrinks to less than {:.0} % of its isothermal area",
                100.0 * MIN_AREA_FRACTION
            ))
        } else {
            None
        }
    };
    let first_share = if blok {
        let flux = isothermal
            .pressure_pa
            .mapv(|p| frictional_flux(friction, p, spec.sliding_speed_m_per_s));
        let t1 = body1.mean_temperature(&flux, &isothermal.pressure_pa)?;
        let t2 = match body2.as_mut() {
            Some(b) => b.mean_temperature(&flux, &isothermal.pressure_pa)?,
            None => 0.0,
        };
        spec.partition.body1_share(t1, t2)
    } else {
        spec.partition.body1_share(1.0, 0.0)
    };
    let start = state(
        0,
        &isothermal.pressure_pa,
        first_share,
        &mut body1,
        body2.as_mut(),
    )?;
    if start.max_temperature_rise_k > MAX_FLASH_TEMPERATURE_RISE_K {
        return Err(CoupledError::BeyondAnySolid { isothermal: start });
    }
    let mut last = start;
    let mut pressure = isothermal.pressure_pa.clone();
    let mut distortion = Array2::<f64>::zeros((ny, nx));
    let mut changes = Vec::new();
    let mut relaxation = 1.0;
    for iteration in 1..=MAX_ITERATIONS {
        let flux = pressure.mapv(|p| frictional_flux(friction, p, spec.sliding_speed_m_per_s));
        let share = if blok {
            let t1 = body1.mean_temperature(&flux, &pressure)?;
            let t2 = match body2.as_mut() {
                Some(b) => b.mean_temperature(&flux, &pressure)?,
                None => 0.0,
            };
            spec.partition.body1_share(t1, t2)
        } else {
            spec.partition.body1_share(1.0, 0.0)
        };
        let mut target = Array2::<f64>::zeros((ny, nx));
        for (body, fraction) in [(Some(&mut body1), share), (body2.as_mut(), 1.0 - share)] {
            if let Some(operator) = body.and_then(|b| b.distortion.as_mut()) {
                if fraction > 0.0 {
                    target += &operator.apply(flux.mapv(|q| q * fraction).view())?;
                }
            }
        }
        Zip::from(&mut distortion)
            .and(&target)
            .for_each(|w, &t| *w += relaxation * (t - *w));
        let heated = solve(&distortion, &pressure)?;
        let total: f64 = heated.pressure_pa.sum();
        let moved: f64 = Zip::from(&heated.pressure_pa)
            .and(&pressure)
            .fold(0.0, |s, &a, &b| s + (a - b).abs());
        let change = if total > 0.0 { moved / total } else { 0.0 };
        progress(iteration, change);
        if changes.last().is_some_and(|&last| change > last) {
            relaxation = (relaxation * 0.5).max(1.0 / 16.0);
        }
        changes.push(change);
        pressure.assign(&heated.pressure_pa);
        let now = state(iteration, &pressure, share, &mut body1, body2.as_mut())?;
        if let Some(cause) = runaway(&now) {
            return Err(CoupledError::Runaway(Box::new(Runaway {
                cause,
                at: now,
                last,
                isothermal: start,
            })));
        }
        last = now;
        if change < TOLERANCE {
            return Ok(CoupledContact {
                isothermal,
                heated,
                distortion_m: distortion,
                body1_share: share,
                iterations: iteration,
                changes,
            });
        }
    }
    Err(CoupledError::NotConverged {
        iterations: MAX_ITERATIONS,
        change: changes.last().copied().unwrap_or(f64::INFINITY),
        last,
    })
}

/// The gap between a Hertz pair's undeformed surfaces on a grid as heights out of body 1:
/// `h = -(A x² + B y²)` with the relative half-curvatures `A`, `B` (m⁻¹), cell `[0, 0]` centred
/// at `origin_m`.
pub fn paraboloid(
    shape: [usize; 2],
    spacing_m: [f64; 2],
    origin_m: [f64; 2],
    half_curvature_per_m: [f64; 2],
) -> Array2<f64> {
    Array2::from_shape_fn((shape[0], shape[1]), |(row, column)| {
        let x = origin_m[0] + column as f64 * spacing_m[0];
        let y = origin_m[1] + row as f64 * spacing_m[1];
        -(half_curvature_per_m[0] * x * x + half_curvature_per_m[1] * y * y)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::material::Material;
    use crate::operator::elastic::Periodicity;
    use crate::thermal::material::thermal_preset;

    const STEEL: Material = Material {
        modulus_pa: 210e9,
        poisson: 0.3,
    };

    /// A steel ball of radius 20 mm on a steel flat under 500 N (a ≈ 0.40 mm), gridded at
    /// a/12 over [-2.5a, 1.5a] x [-1.5a, 1.5a], heated by μ = 0.1 at `speed` with all heat into
    /// the flat, whose expansion is scaled by `expansion_factor`.
    fn sphere(speed: f64, expansion_factor: f64) -> Result<CoupledContact, CoupledError> {
        let e_star = STEEL.modulus_pa / (2.0 * (1.0 - 0.09));
        let (radius, load) = (0.02, 500.0);
        let a = (3.0 * load * radius / (4.0 * e_star)).cbrt();
        let d = a / 12.0;
        let shape = [36, 48];
        let heights = paraboloid(
            shape,
            [d, d],
            [-2.5 * a + 0.5 * d, -1.5 * a + 0.5 * d],
            [0.5 / radius; 2],
        );
        let problem = RoughContactProblem {
            heights_m: heights.view(),
            spacing_m: [d, d],
            e_star_pa: e_star,
            periodicity: Periodicity::NonPeriodic,
            control: Control::Load { newtons: load },
            hardness_pa: None,
            tolerance: rough::DEFAULT_TOLERANCE,
            max_iterations: rough::DEFAULT_MAX_ITERATIONS,
            memory_limit_bytes: 1 << 30,
        };
        let mut properties = thermal_preset("steel").expect("steel");
        properties.expansion_per_k *= expansion_factor;
        let spec = ThermalSpec {
            sliding_speed_m_per_s: speed,
            traction: crate::scene::TractionDirection::PlusX,
            speed_keys: ["thermal.speed", "thermal.body2_speed"],
            partition: Partition::Body1,
            coupled: true,
            body1: ThermalBody {
                properties,
                material: STEEL,
                speed_m_per_s: speed,
            },
            body2: None,
            gear: None,
        };
        let isothermal = rough::solve(&problem, &mut |_, _| {})?;
        solve(&problem, isothermal, &spec, 0.1, &mut |_, _| {})
    }

    #[test]
    fn without_expansion_the_coupled_contact_is_the_isothermal_one_exactly() {
        let c = sphere(2.0, 0.0).expect("coupled");
        assert_eq!(c.iterations, 1);
        assert_eq!(c.heated, c.isothermal);
        assert!(c.distortion_m.iter().all(|&w| w == 0.0));
    }

    #[test]
    fn heating_shrinks_the_contact_and_raises_the_peak_linearly_when_weak() {
        // Liu & Wang (2001) report a smaller contact and a higher peak pressure as frictional
        // heating grows. Checks: load carried (1e-9); area down and peak up, more at a higher
        // speed (the area by whole cells: at or below); the fixed point (the distortion of
        // the final pressure, computed again by a new operator, is the one the contact was
        // solved on within 1e-5 of its range); weak heating is linear: the peak's rise at α/20
        // is half that at α/10 within 3 %.
        let slow = sphere(0.5, 1.0).expect("0.5 m/s");
        let fast = sphere(2.0, 1.0).expect("2 m/s");
        for c in [&slow, &fast] {
            assert!((c.heated.load_n / 500.0 - 1.0).abs() < 1e-9);
            assert!(c.heated.contact_fraction < c.isothermal.contact_fraction);
            assert!(c.heated.max_pressure_pa > c.isothermal.max_pressure_pa);
        }
        let steel = thermal_preset("steel").expect("steel");
        let u = 2.0 / (2.0 * steel.diffusivity_m2_per_s);
        let (ny, nx) = fast.distortion_m.dim();
        let grid = CellGrid {
            shape: [ny, nx],
            spacing_m: fast.heated.spacing_m,
        };
        let again = DisplacementOperator::new(
            &grid,
            u,
            1.3 * steel.expansion_per_k / steel.conductivity_w_per_m_k,
        )
        .expect("operator")
        .apply(fast.heated.pressure_pa.mapv(|p| 0.1 * p * 2.0).view())
        .expect("apply");
        let range = fast.distortion_m.iter().fold(0.0f64, |m, w| m.max(w.abs()));
        let worst = (&again - &fast.distortion_m)
            .iter()
            .fold(0.0f64, |m, w| m.max(w.abs()));
        eprintln!("measured: coupled fixed point: {:.1e}", worst / range);
        assert!(worst < 1e-5 * range);
        let rise =
            |c: &CoupledContact| c.heated.max_pressure_pa / c.isothermal.max_pressure_pa - 1.0;
        eprintln!(
            "measured: coupled sphere: peak +{:.2} % at 0.5 m/s, +{:.2} % at 2 m/s; area {:.2} %, {:.2} %",
            100.0 * rise(&slow),
            100.0 * rise(&fast),
            100.0 * (slow.heated.contact_fraction / slow.isothermal.contact_fraction - 1.0),
            100.0 * (fast.heated.contact_fraction / fast.isothermal.contact_fraction - 1.0)
        );
        assert!(fast.heated.contact_fraction <= slow.heated.contact_fraction);
        assert!(fast.heated.max_pressure_pa > slow.heated.max_pressure_pa);
        let tenth = sphere(2.0, 0.1).expect("α/10");
        let twentieth = sphere(2.0, 0.05).expect("α/20");
        let ratio = rise(&tenth) / rise(&twentieth);
        eprintln!("measured: coupled sphere, weak heating: rise ratio {ratio:.4} (2 expected)");
        assert!((ratio / 2.0 - 1.0).abs() < 0.03, "ratio {ratio}");
    }
}

//! A load-controlled rough contact under a pressure cap: the approach that carries the load,
//! found by a safeguarded root search on the load of capped approach-controlled solutions.
//!
//! ## Why a search on the approach
//! Under a given approach `δ` the capped problem is Polonsky & Keer's iteration with the
//! pressure clipped to `[0, H]` ([`super::iterate`]); its load `W(δ) = Σ p dx dy` is continuous
//! and non-decreasing in `δ` (pressing further never unloads the surface). Two approaches
//! bracket any load below the fully plastic one without solving anything:
//! - `δ = 0` carries nothing (the highest point just touches);
//! - `δ_full = max(s + u(H))`, with `u(H)` the displacement of the whole grid at the cap,
//!   carries `H × A`: there every cell penetrates under `p = H`, which is then the solution
//!   (a cell at the cap may penetrate). Periodic, `u(H) = 0` (the mean mode carries no
//!   displacement) and `δ_full = max s`.
//!
//! An elastic solution (under the same load) that stays below the cap everywhere is already
//! the capped one and ends the search before it starts. A load `W ≥ H A` has no solution
//! (refused before the search). Inside the bracket the
//! search is Brent's method (inverse quadratic interpolation or secant, with a bisection
//! whenever they would stall), first trying the approach of the elastic solution under the
//! same load. Each approach-controlled run starts from the pressure of the previous one. The
//! search ends when a run has converged (both measures of the module [`super`] below the
//! tolerance) and carries the load to the tolerance; its free pressures (below the cap) are
//! then scaled to carry the load exactly, a change smaller than the tolerance.
//!
//! ## Reference
//! R. P. Brent, *Algorithms for Minimization without Derivatives*, Prentice-Hall (1973),
//! chapter 4 (the zero finder `zero`); W. H. Press et al., *Numerical Recipes*, 3rd ed. (2007),
//! §9.3 (the same algorithm, `zbrent`).

use std::ops::ControlFlow;

use ndarray::{Array2, Zip};

use super::{
    iterate, scale_to_mean, sum_active, Compliance, RoughContactError, Settings, State, Target,
};

/// The capped load-controlled solve: `pressure` ends as the solution carrying
/// `mean` × cells; returns the iterations made (all runs) and the residual (the larger of the
/// last run's and the relative load error before the final scaling).
pub(super) fn capped_under_load(
    operator: &mut Compliance<'_>,
    separation: &Array2<f64>,
    pressure: &mut Array2<f64>,
    state: &mut State,
    mean: f64,
    settings: &Settings,
    progress: &mut dyn FnMut(usize, f64) -> ControlFlow<()>,
) -> Result<(usize, f64), RoughContactError> {
    let cells = pressure.len() as f64;
    let hardness = settings.hardness;
    if mean >= hardness {
        return Err(RoughContactError::HardnessTooLow {
            hardness_pa: hardness,
            mean_pa: mean,
        });
    }
    let mut total_iterations = 0usize;

    // A first guess: the approach of the elastic solution under the same load, and its
    // pressure, capped, as the start.
    let mut elastic = pressure.clone();
    let uncapped = Settings {
        hardness: f64::INFINITY,
        ..*settings
    };
    let (iterations, elastic_residual) = iterate(
        operator,
        separation,
        &mut elastic,
        state,
        Target::MeanPressure(mean),
        &uncapped,
        progress,
    )?;
    total_iterations += iterations;
    // An elastic solution below the cap everywhere is the capped one (a warm-started step of a
    // worn surface often is): nothing left to search.
    if elastic_residual < settings.tolerance && elastic.iter().all(|&p| p < hardness) {
        pressure.assign(&elastic);
        return Ok((total_iterations, elastic_residual));
    }
    let guess = elastic_approach(operator, separation, &elastic, state)?;

    // The bracket: δ = 0 carries nothing, δ_full the whole grid at the cap.
    let mut low = (0.0, -mean);
    let full_approach = {
        let at_cap = Array2::from_elem(pressure.dim(), hardness);
        operator.apply(at_cap.view(), state.gap.view_mut())?;
        Zip::from(&state.gap)
            .and(separation)
            .fold(f64::NEG_INFINITY, |m, &u, &s| m.max(s + u))
    };
    let mut high = (full_approach, hardness - mean);
    pressure.assign(&elastic.mapv(|p| p.min(hardness)));
    drop(elastic);

    // One approach-controlled run, from the current pressure: the mean pressure's excess
    // over the target, and the run's residual.
    let mut run = |approach: f64,
                   pressure: &mut Array2<f64>,
                   state: &mut State,
                   total_iterations: &mut usize|
     -> Result<(f64, f64), RoughContactError> {
        let budget = Settings {
            max_iterations: settings.max_iterations.saturating_sub(*total_iterations),
            ..*settings
        };
        let (iterations, residual) = if budget.max_iterations == 0 {
            (0, f64::INFINITY)
        } else {
            iterate(
                operator,
                separation,
                pressure,
                state,
                Target::Approach(approach),
                &budget,
                progress,
            )?
        };
        *total_iterations += iterations;
        if residual >= settings.tolerance {
            return Err(RoughContactError::NotConverged {
                iterations: *total_iterations,
                residual,
                tolerance: settings.tolerance,
            });
        }
        Ok((pressure.sum() / cells - mean, residual))
    };
    let accept = |excess: f64| (excess / mean).abs() < settings.tolerance;

    let mut last = (f64::NAN, f64::NAN, f64::INFINITY);
    if guess > low.0 && guess < high.0 {
        let (excess, residual) = run(guess, pressure, state, &mut total_iterations)?;
        last = (guess, excess, residual);
        if excess < 0.0 {
            low = (guess, excess);
        } else {
            high = (guess, excess);
        }
    }
    if !accept(last.1) {
        last = brent(low, high, &mut |approach| {
            let (excess, residual) = run(approach, pressure, state, &mut total_iterations)?;
            Ok(((excess, residual), accept(excess)))
        })
        .map_err(|error| match error {
            SearchError::Run(error) => error,
            SearchError::Stalled { excess } => RoughContactError::NotConverged {
                iterations: total_iterations,
                residual: (excess / mean).abs(),
                tolerance: settings.tolerance,
            },
        })?;
    }
    let (_, excess, residual) = last;
    // The free pressures carry the rest of the load exactly.
    scale_to_mean(pressure, mean * cells, hardness);
    Ok((total_iterations, residual.max((excess / mean).abs())))
}

/// Why the search ended without an answer.
enum SearchError {
    /// A run failed (not converged, or a transform error).
    Run(RoughContactError),
    /// The bracket shrank to rounding without a run carrying the load (the load against the
    /// approach jumps there: the runs are not accurate enough).
    Stalled { excess: f64 },
}

impl From<RoughContactError> for SearchError {
    fn from(error: RoughContactError) -> Self {
        Self::Run(error)
    }
}

/// Brent's zero finder on `[low.0, high.0]` with `low.1 < 0 <= high.1` (Brent 1973, ch. 4;
/// Press et al. 2007, §9.3). `evaluate(x)` returns `((f, residual), done)`; the search ends at
/// the first evaluation that is `done`, with `(x, f, residual)` of that evaluation (so the
/// caller's state is the one of the answer).
fn brent(
    low: (f64, f64),
    high: (f64, f64),
    evaluate: &mut dyn FnMut(f64) -> Result<((f64, f64), bool), RoughContactError>,
) -> Result<(f64, f64, f64), SearchError> {
    let (mut a, mut fa) = low;
    let (mut b, mut fb) = high;
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    loop {
        if (fb > 0.0 && fc > 0.0) || (fb < 0.0 && fc < 0.0) {
            (c, fc) = (a, fa);
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, fa) = (b, fb);
            (b, fb) = (c, fc);
            (c, fc) = (a, fa);
        }
        let tol1 = 2.0 * f64::EPSILON * b.abs();
        let xm = 0.5 * (c - b);
        if xm.abs() <= tol1 {
            return Err(SearchError::Stalled { excess: fb });
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            // Inverse quadratic interpolation (secant when only two points differ).
            let s = fb / fa;
            let (mut p, mut q) = if a == c {
                (2.0 * xm * s, 1.0 - s)
            } else {
                let q = fa / fc;
                let r = fb / fc;
                (
                    s * (2.0 * xm * q * (q - r) - (b - a) * (r - 1.0)),
                    (q - 1.0) * (r - 1.0) * (s - 1.0),
                )
            };
            if p > 0.0 {
                q = -q;
            }
            p = p.abs();
            let min1 = 3.0 * xm * q - (tol1 * q).abs();
            let min2 = (e * q).abs();
            if 2.0 * p < min1.min(min2) {
                e = d;
                d = p / q;
            } else {
                d = xm;
                e = d;
            }
        } else {
            d = xm;
            e = d;
        }
        (a, fa) = (b, fb);
        b += if d.abs() > tol1 { d } else { tol1.copysign(xm) };
        let ((f, residual), done) = evaluate(b)?;
        fb = f;
        if done {
            return Ok((b, f, residual));
        }
    }
}

/// The approach of a converged load-controlled pressure: the mean gap over the loaded cells.
fn elastic_approach(
    operator: &mut Compliance<'_>,
    separation: &Array2<f64>,
    pressure: &Array2<f64>,
    state: &mut State,
) -> Result<f64, RoughContactError> {
    operator.apply(pressure.view(), state.gap.view_mut())?;
    Zip::from(&mut state.gap)
        .and(separation)
        .for_each(|g, &s| *g += s);
    let (sum, count) = sum_active(pressure, &state.gap, &|p, _| p > 0.0);
    Ok(sum / count.max(1) as f64)
}

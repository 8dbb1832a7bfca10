//! Polonsky & Keer's iteration (module doc of [`super`]): the work arrays, the settings and
//! the loop, apart from the problem's checks and the solution's summary in `mod.rs`.
//!
//! ## Passes over the grid
//! Besides its two applications of the operator (a forward and an inverse transform each),
//! an iteration sweeps the grid in as few passes as the data flow allows: the gap's sum over
//! the active cells with its separation added; its centring with the complementarity and the
//! gap's norm; the conjugate direction; the response's sum, then its centring with the step's
//! numerator and denominator; the pressure step with the penetrating cells' loading and the
//! sums of capped and free pressure; the scaling to the load with the change of pressure. Each
//! sum is formed in the same (row-major) order as when each had a pass of its own, so the
//! iterates are the same to the last bit.

use std::ops::ControlFlow;

use ndarray::{Array2, ArrayView2, ArrayViewMut2, Zip};

use super::RoughContactError;
use crate::operator::elastic::ElasticOperator;
use crate::operator::transform::TransformError;

/// The displacement per pressure the iteration works with: the elastic half-space's `K`
/// plus a local compliance `c` (zero unless [`Warm`] gives one): `u = K p + c p`.
pub(super) struct Compliance<'a> {
    pub(super) elastic: &'a mut ElasticOperator,
    pub(super) local_m_per_pa: f64,
}

impl Compliance<'_> {
    /// `displacement = K pressure + c pressure`; allocates nothing.
    pub(super) fn apply(
        &mut self,
        pressure: ArrayView2<f64>,
        mut displacement: ArrayViewMut2<f64>,
    ) -> Result<(), TransformError> {
        self.elastic
            .apply(pressure.view(), displacement.view_mut())?;
        if self.local_m_per_pa != 0.0 {
            let c = self.local_m_per_pa;
            Zip::from(&mut displacement)
                .and(&pressure)
                .for_each(|u, &p| *u += c * p);
        }
        Ok(())
    }
}

/// Work arrays of the iteration.
pub(super) struct State {
    pub(super) gap: Array2<f64>,
    direction: Array2<f64>,
    response: Array2<f64>,
    previous: Array2<f64>,
}

impl State {
    pub(super) fn new([ny, nx]: [usize; 2]) -> Self {
        Self {
            gap: Array2::zeros((ny, nx)),
            direction: Array2::zeros((ny, nx)),
            response: Array2::zeros((ny, nx)),
            previous: Array2::zeros((ny, nx)),
        }
    }
}

#[derive(Clone, Copy)]
pub(super) struct Settings {
    pub(super) hardness: f64,
    pub(super) gap_scale: f64,
    pub(super) tolerance: f64,
    pub(super) max_iterations: usize,
    /// A cell's own displacement per unit pressure (m/Pa): the stiffness with which cells
    /// that penetrate are loaded when no cell takes a conjugate-gradient step.
    pub(super) own_compliance: f64,
}

/// What one run of the iteration holds fixed.
#[derive(Clone, Copy)]
pub(super) enum Target {
    Approach(f64),
    MeanPressure(f64),
}

/// Polonsky & Keer's iteration from the given pressure until converged or the cap is
/// reached: returns the iterations made and the residual (module doc). `progress(iteration,
/// residual)` after every iteration says whether to go on: a break before convergence ends the
/// run with [`RoughContactError::Interrupted`].
pub(super) fn iterate(
    operator: &mut Compliance<'_>,
    separation: &Array2<f64>,
    pressure: &mut Array2<f64>,
    state: &mut State,
    target: Target,
    settings: &Settings,
    progress: &mut dyn FnMut(usize, f64) -> ControlFlow<()>,
) -> Result<(usize, f64), RoughContactError> {
    let State {
        gap,
        direction,
        response,
        previous,
    } = state;
    let Settings {
        hardness,
        gap_scale,
        tolerance,
        max_iterations,
        own_compliance,
    } = *settings;
    let (approach_given, target_mean) = match target {
        Target::Approach(m) => (Some(m), None),
        Target::MeanPressure(pa) => (None, Some(pa)),
    };
    let cells = pressure.len() as f64;
    let mut conjugate = false;
    let mut gap_norm_old = 1.0;
    let mut iterations = 0;
    let mut residual = f64::INFINITY;
    // A cell takes part in the conjugate-gradient step when loaded below the cap, or at the
    // cap but opening (then it may unload).
    let active = |p: f64, g: f64| p > 0.0 && (p < hardness || g > 0.0);

    while iterations < max_iterations {
        iterations += 1;
        operator.apply(pressure.view(), gap.view_mut())?;
        // The gap, and (under a given load) its sum over the active cells.
        let (sum, count) = Zip::from(&mut *gap).and(separation).and(&*pressure).fold(
            (0.0, 0usize),
            |(sum, count), g, &s, &p| {
                *g += s;
                if approach_given.is_none() && active(p, *g) {
                    (sum + *g, count + 1)
                } else {
                    (sum, count)
                }
            },
        );
        let shift = match approach_given {
            Some(approach) => approach,
            None if count == 0 => break,
            None => sum / count as f64,
        };
        // The gap measured from the approach (or centred on the active cells), with the
        // complementarity of the current pressure and its gap (at the cap a cell may
        // penetrate: only an opening gap counts there) and the gap's norm on the active cells.
        let mut unloaded = true;
        let mut open_everywhere = true;
        let (pg, p_sum, gap_norm) =
            Zip::from(&mut *gap)
                .and(&*pressure)
                .fold((0.0, 0.0, 0.0), |(a, b, norm), g, &p| {
                    *g -= shift;
                    let g = *g;
                    unloaded &= p == 0.0;
                    open_everywhere &= g >= 0.0;
                    let open = if p >= hardness { g.max(0.0) } else { g.abs() };
                    let norm = if active(p, g) { norm + g * g } else { norm };
                    (a + p * open, b + p, norm)
                });
        // Under a given approach, no pressure and no cell penetrating is the solution (the
        // approach does not reach the surface).
        if approach_given.is_some() && unloaded && open_everywhere {
            return Ok((iterations, 0.0));
        }
        let complementarity = if p_sum > 0.0 {
            pg / (p_sum * gap_scale)
        } else {
            f64::INFINITY
        };
        let ratio = if conjugate {
            gap_norm / gap_norm_old
        } else {
            0.0
        };
        Zip::from(&mut *direction)
            .and(&*pressure)
            .and(&*gap)
            .for_each(|t, &p, &g| *t = if active(p, g) { g + ratio * *t } else { 0.0 });
        gap_norm_old = gap_norm;
        operator.apply(direction.view(), response.view_mut())?;
        // Under a given load the response is centred on the same set as the gap.
        let centre = if approach_given.is_none() {
            let (sum, count) = Zip::from(&*pressure).and(&*gap).and(&*response).fold(
                (0.0, 0usize),
                |(s, c), &p, &g, &r| if active(p, g) { (s + r, c + 1) } else { (s, c) },
            );
            (count > 0).then(|| sum / count as f64)
        } else {
            None
        };
        let (numerator, denominator) = Zip::from(&*pressure)
            .and(&*gap)
            .and(&*direction)
            .and(&mut *response)
            .fold((0.0, 0.0), |(a, b), &p, &g, &t, r| {
                if let Some(mean) = centre {
                    *r -= mean;
                }
                if active(p, g) {
                    (a + g * t, b + *r * t)
                } else {
                    (a, b)
                }
            });
        let step = if denominator != 0.0 {
            numerator / denominator
        } else {
            0.0
        };
        // Cells out of contact that penetrate are loaded, and the conjugation restarts.
        // Cells reaching or leaving the cap change the set too. With no cell in the
        // conjugate-gradient step (all at the cap and penetrating) the step is zero: the
        // penetrating cells are then loaded with their own stiffness, else they would never
        // enter and the iteration would stop with them penetrating.
        let load_stiffness = if step != 0.0 {
            step.abs()
        } else {
            1.0 / own_compliance
        };
        let mut overlap = false;
        let mut cap_changed = false;
        // The step, the penetrating cells loaded, and the sums of capped and free pressure
        // that the scaling to the load needs ([`scale_to_mean`]).
        let (capped, free) = Zip::from(&mut *pressure)
            .and(&mut *previous)
            .and(&*gap)
            .and(&*direction)
            .fold((0.0, 0.0), |(c, f), p, old, &g, &t| {
                *old = *p;
                if active(*p, g) {
                    *p -= step * t;
                }
                if *p <= 0.0 {
                    *p = 0.0;
                }
                if *p == 0.0 && g < 0.0 {
                    *p = -load_stiffness * g;
                    overlap = true;
                }
                if *p > hardness {
                    *p = hardness;
                }
                if (*p >= hardness) != (*old >= hardness) {
                    cap_changed = true;
                }
                if *p >= hardness {
                    (c + *p, f)
                } else {
                    (c, f + *p)
                }
            });
        conjugate = !overlap && !cap_changed;
        // Scaled to the load (the pressures below the cap, as [`scale_to_mean`] does), with
        // the change of pressure.
        let factor = match target_mean {
            Some(mean) if free > 0.0 => Some(((mean * cells - capped) / free).max(0.0)),
            _ => None,
        };
        let change = Zip::from(&mut *pressure)
            .and(&*previous)
            .fold(0.0, |acc, p, &old| {
                if let Some(factor) = factor {
                    if *p < hardness {
                        *p = (*p * factor).min(hardness);
                    }
                }
                acc + (*p - old).abs()
            });
        let total = pressure.sum();
        let pressure_change = if total > 0.0 {
            change / total
        } else {
            f64::INFINITY
        };
        residual = pressure_change.max(complementarity);
        let asked = progress(iterations, residual);
        if residual < tolerance {
            break;
        }
        if asked.is_break() {
            return Err(RoughContactError::Interrupted {
                iterations,
                residual,
            });
        }
        if total == 0.0 && approach_given.is_some() {
            break;
        }
    }
    Ok((iterations, residual))
}

/// `Σ values` and the count over the cells where `select(p, g)` holds (`g` = `values`).
pub(super) fn sum_active(
    pressure: &Array2<f64>,
    values: &Array2<f64>,
    select: &dyn Fn(f64, f64) -> bool,
) -> (f64, usize) {
    Zip::from(pressure)
        .and(values)
        .fold((0.0, 0usize), |(s, c), &p, &v| {
            if select(p, v) {
                (s + v, c + 1)
            } else {
                (s, c)
            }
        })
}

/// Scales the pressures below the cap so that the sum is `total` (cells at the cap stay).
pub(super) fn scale_to_mean(pressure: &mut Array2<f64>, total: f64, hardness: f64) {
    let (capped, free) = pressure.iter().fold((0.0, 0.0), |(c, f), &p| {
        if p >= hardness {
            (c + p, f)
        } else {
            (c, f + p)
        }
    });
    if free > 0.0 {
        let factor = ((total - capped) / free).max(0.0);
        pressure.mapv_inplace(|p| {
            if p < hardness {
                (p * factor).min(hardness)
            } else {
                p
            }
        });
    }
}

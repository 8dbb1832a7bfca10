//! Wear of a rough contact with sliding distance: Archard's law applied cell by cell to the
//! solved pressure, stepped by backward Euler, and the wear read off a measured series of
//! topographies.
//!
//! ## Archard's law, locally
//! Archard's law `V = k W s` (worn volume `V`, normal load `W`, sliding distance `s`, the
//! dimensional wear coefficient `k` in m³/(N m) = m²/N) holds at every point of the surface
//! as `dh/ds = k p`: the local wear depth grows with the local pressure (Archard 1953, in the
//! local form used for simulated wear by Põdra & Andersson 1999). Summed over the surface the
//! worn volume grows by `k ds Σ p dA = k W ds` at every step, whatever the pressure.
//!
//! ## The step: backward Euler
//! Explicit stepping (the wear `k ds p` of the pressure before the step) is stiff: the stable
//! step shrinks with the cell size (about `dx / (E* k)`) and beyond it the pressure jumps from
//! cell to cell. Here each step takes the wear of the pressure *at its end*: with the
//! separation `s` of the surface before the step, the gap at its end is
//!
//! `g = s + k ds p - δ + K p = s - δ + (K + k ds I) p`,
//!
//! so the wear acts inside the contact solver as a local compliance `k ds` added to the elastic
//! one (still symmetric and positive definite: Polonsky & Keer's iteration applies unchanged).
//! The step is unconditionally stable (the implicit Euler method is A-stable), and its
//! pressure is the static contact of the worn surface at the step's end: a series of the worn
//! surfaces, solved one by one, gives the same pressures.
//!
//! ## Plastic flattening
//! With a hardness `H`, the cells at the cap penetrate the counter-surface. Their penetration
//! is made permanent: the worn surface is lowered by it at the step's end, as ContactMechanics
//! keeps a plastic displacement. A perfectly plastic asperity that has flowed does not spring
//! back; left as it was, the same asperity would be flattened again at every step and counted
//! as new plastic flow each time. The flattened material is displaced, not removed: it is
//! reported as its own volume, apart from the Archard wear (which stays `k W s` exactly).
//!
//! ## A rough counter-surface
//! A rough body 2 that does not wear (a hard coating) slides over the worn body along +x: at
//! sliding distance `s` its asperities stand where they stood at 0 shifted by `s` ([`slid`],
//! whole cells, around its period). Within one step they pass over the worn body many times,
//! so the worn body wears under their mean effect: the pressure against the counter's mean
//! plane (to first order in the roughness: the macroscopic pressure of a rough contact is the
//! smooth one where the roughness is small against the bulk deformation, Greenwood & Tripp
//! 1967). The contact reported at each step is the instantaneous one, the worn body against
//! the counter at that distance: through the counter's asperities, with the real and plastic
//! areas that the load (not the growing scar) sets, as Greenwood & Williamson's model has it.
//! Its plastic penetration is ploughing, material moved aside by the hard asperities (which
//! this model cannot place), and is not kept.
//!
//! ## A measured series
//! The wear between two measured topographies of one surface is what the later one lacks: the
//! difference of heights, less the two measurements' offset of datum (the difference the
//! unworn cells share: the most common one), counted where positive ([`measured_wear`]).
//!
//! ## References
//! - J. F. Archard, Contact and rubbing of flat surfaces, *J. Appl. Phys.* 24 (1953) 981–988.
//! - P. Põdra, S. Andersson, Simulating sliding wear with finite element method, *Tribol.
//!   Int.* 32 (1999) 71–81.
//! - M. T. Siniawski, S. J. Harris, Q. Wang, S. Liu, Wear initiation of steel sliding against
//!   a thin boron carbide coating, *Tribol. Lett.* 15 (1) (2003) (the evolution of a steel
//!   ball's wear scar, its pressure and its plastic area with sliding distance).
//! - J. A. Greenwood, J. H. Tripp, The elastic contact of rough spheres, *J. Appl. Mech.* 34
//!   (1967) 153–159.
//! - E. Hairer, G. Wanner, *Solving Ordinary Differential Equations II*, 2nd ed., Springer
//!   (1996), ch. IV (the implicit Euler method's stability).

use ndarray::{Array2, ArrayView2, Zip};

use crate::contact::rough::{self, RoughContactError, RoughContactProblem, RoughSolution};

/// Archard's wear law with its dimensional coefficient.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Archard {
    /// `k`, m²/N (m³ worn per N of load and m of sliding).
    pub coefficient_m2_per_n: f64,
}

/// The sliding distance and its uniform steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Schedule {
    /// The total sliding distance, m.
    pub distance_m: f64,
    /// Steps after the unworn contact.
    pub steps: usize,
}

impl Schedule {
    /// The sliding distance at the end of step `k` (0: the unworn contact), m.
    pub fn distance_at(&self, k: usize) -> f64 {
        if k >= self.steps {
            self.distance_m
        } else {
            self.distance_m * k as f64 / self.steps as f64
        }
    }
}

/// Why an evolution stops.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WearError {
    #[error("{name} {requirement}, got {}", crate::io::text::number(*.value))]
    Parameter {
        name: &'static str,
        requirement: &'static str,
        value: f64,
    },
    #[error("at a sliding distance of {distance_m:.4e} m (step {step}) the wear depth reaches {depth_m:.4e} m, more than the surface's height range {range_m:.4e} m: the worn body would be worn through the map")]
    WornThrough {
        step: usize,
        distance_m: f64,
        depth_m: f64,
        range_m: f64,
    },
    #[error("the wear k W s = {wear_m3:.4e} m³ over the sliding distance is more than the map holds above its lowest point, {capacity_m3:.4e} m³: the worn body would be worn through the map")]
    TooMuchWear { wear_m3: f64, capacity_m3: f64 },
    #[error("at a sliding distance of {distance_m:.4e} m (step {step}) the worn contact reaches the edge of the map (row {row}, column {column}): an isolated contact must lie inside its grid\nhint: shorten wear.distance (or lower wear.coefficient), or give a larger map")]
    ScarAtEdge {
        step: usize,
        distance_m: f64,
        row: usize,
        column: usize,
    },
    #[error("at a sliding distance of {distance_m:.4e} m (step {step}): {source}")]
    Contact {
        step: usize,
        distance_m: f64,
        source: RoughContactError,
    },
}

/// One step of an evolution: the contact at the end of it and the surface it left.
#[derive(Clone, Debug, PartialEq)]
pub struct WearStep {
    /// 0 for the unworn contact.
    pub index: usize,
    pub sliding_distance_m: f64,
    /// The contact at the end of the step (the worn surface's static contact).
    pub solution: RoughSolution,
    /// The Archard wear so far, `Σ k ds p dA`, m³.
    pub worn_volume_m3: f64,
    /// The deepest wear so far, m.
    pub max_wear_depth_m: f64,
    /// The plastic flattening so far (displaced, not removed), m³.
    pub plastic_volume_m3: f64,
}

/// A worn surface stepped along the sliding distance (module doc): each [`Evolution::step`]
/// solves the next contact, warm-started from the last pressure.
pub struct Evolution<'p> {
    problem: RoughContactProblem<'p>,
    law: Archard,
    schedule: Schedule,
    /// The worn heights, m, out of body 1 (the worn body).
    heights_m: Array2<f64>,
    /// A rough counter-surface that slides over the worn body and does not wear (m, out of
    /// body 2 towards body 1), shifted by the sliding distance at each step.
    counter_m: Option<Array2<f64>>,
    wear_depth_m: Array2<f64>,
    plastic_depth_m: Array2<f64>,
    /// The height range of the unworn map: wear beyond it is refused.
    range_m: f64,
    next: usize,
    last_pressure_pa: Option<Array2<f64>>,
    /// The pressure of the step before the last, for the predictor.
    earlier_pressure_pa: Option<Array2<f64>>,
    /// The elastic operator, built once for every step.
    cache: std::cell::RefCell<rough::OperatorCache>,
    /// The last contact against the sliding counter-surface, to start the next from.
    last_sliding_pressure_pa: Option<Array2<f64>>,
    worn_volume_m3: f64,
    plastic_volume_m3: f64,
}

fn parameter(name: &'static str, requirement: &'static str, value: f64) -> WearError {
    WearError::Parameter {
        name,
        requirement,
        value,
    }
}

impl<'p> Evolution<'p> {
    /// An evolution of `problem`'s surface under Archard's law: `problem` gives the unworn
    /// heights, the load (or mean pressure), the hardness and the solver's settings.
    pub fn new(
        problem: &RoughContactProblem<'p>,
        law: Archard,
        schedule: Schedule,
    ) -> Result<Self, WearError> {
        let k = law.coefficient_m2_per_n;
        if !(k > 0.0 && k.is_finite()) {
            return Err(parameter(
                "the wear coefficient",
                "must be positive and finite",
                k,
            ));
        }
        if !(schedule.distance_m > 0.0 && schedule.distance_m.is_finite()) {
            return Err(parameter(
                "the sliding distance",
                "must be positive and finite",
                schedule.distance_m,
            ));
        }
        if schedule.steps == 0 {
            return Err(parameter("the number of steps", "must be at least 1", 0.0));
        }
        if matches!(problem.control, rough::Control::Approach { .. }) {
            return Err(parameter(
                "the contact",
                "must be pressed by a load or a mean pressure (under a fixed approach the worn surface would run out of contact)",
                f64::NAN,
            ));
        }
        let heights_m = problem.heights_m.to_owned();
        let (low, high) = heights_m
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &h| {
                (lo.min(h), hi.max(h))
            });
        let wear_m3 = k * nominal_load_n(problem) * schedule.distance_m;
        let capacity_m3 = capacity_m3(&heights_m, problem.spacing_m);
        if wear_m3 > capacity_m3 {
            return Err(WearError::TooMuchWear {
                wear_m3,
                capacity_m3,
            });
        }
        let shape = heights_m.raw_dim();
        Ok(Self {
            problem: problem.clone(),
            law,
            schedule,
            heights_m,
            counter_m: None,
            wear_depth_m: Array2::zeros(shape),
            plastic_depth_m: Array2::zeros(shape),
            range_m: high - low,
            next: 0,
            last_pressure_pa: None,
            earlier_pressure_pa: None,
            cache: std::cell::RefCell::new(rough::OperatorCache::default()),
            last_sliding_pressure_pa: None,
            worn_volume_m3: 0.0,
            plastic_volume_m3: 0.0,
        })
    }

    /// The worn body's heights (`problem`'s) pressed by a rough counter-surface `counter_m`
    /// (m, the same grid, heights out of body 2 towards body 1) that slides over it along +x
    /// and does not wear: at sliding distance `s` the contact sees the worn heights plus the
    /// counter-surface shifted by `s` ([`slid`]; the counter is taken as periodic, as a
    /// generated surface is). Only the worn body loses material.
    pub fn sliding_against(mut self, counter_m: Array2<f64>) -> Self {
        self.counter_m = Some(counter_m);
        self
    }

    /// The worn heights after the last step (m, `[ny, nx]`, out of body 1).
    pub fn heights_m(&self) -> &Array2<f64> {
        &self.heights_m
    }

    /// The Archard wear depth so far (m, `[ny, nx]`).
    pub fn wear_depth_m(&self) -> &Array2<f64> {
        &self.wear_depth_m
    }

    /// The plastic flattening so far (m, `[ny, nx]`).
    pub fn plastic_depth_m(&self) -> &Array2<f64> {
        &self.plastic_depth_m
    }

    /// Steps in all, the unworn contact included.
    pub fn len(&self) -> usize {
        self.schedule.steps + 1
    }

    /// Never empty (the unworn contact is a step).
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Whether every step has been taken.
    pub fn finished(&self) -> bool {
        self.next > self.schedule.steps
    }

    /// The index and sliding distance of the next step, and the local compliance of its wear
    /// (`k ds`, m/Pa; zero for the unworn contact).
    fn next_step(&self) -> (usize, f64, f64) {
        let index = self.next;
        let distance_m = self.schedule.distance_at(index);
        let ds = if index == 0 {
            0.0
        } else {
            distance_m - self.schedule.distance_at(index - 1)
        };
        (index, distance_m, self.law.coefficient_m2_per_n * ds)
    }

    /// The contact of the next step, not yet taken, that wears the surface: the worn surface
    /// plus `offset` (m, a transient bulge such as the thermal distortion, which wears
    /// nothing) against a smooth counter-surface, with the step's wear compliance, started from
    /// `start` (else the last step's pressure). Step 0 is the unworn contact, solved as
    /// [`rough::solve`] solves it (bit for bit). A rough counter-surface is not in it: its
    /// asperities pass over the worn body many times within a step, so the worn body wears
    /// under their mean, the pressure against the counter's mean plane (module doc).
    pub fn solve_next(
        &self,
        offset: Option<ArrayView2<f64>>,
        start: Option<ArrayView2<f64>>,
        progress: &mut dyn FnMut(usize, f64),
    ) -> Result<RoughSolution, RoughContactError> {
        let (index, _, compliance) = self.next_step();
        let shifted = offset.map(|w| &self.heights_m + &w);
        let problem = RoughContactProblem {
            heights_m: shifted.as_ref().unwrap_or(&self.heights_m).view(),
            ..self.problem.clone()
        };
        // The predictor: the pressure extrapolated linearly from the last two steps (uniform
        // steps: 2 p(n-1) - p(n-2)), clipped at zero; the solver clips it to the cap and scales
        // it to the load.
        let predicted = match (&self.last_pressure_pa, &self.earlier_pressure_pa) {
            (Some(last), Some(earlier)) if start.is_none() && index >= 2 => {
                let ratio = (self.schedule.distance_at(index)
                    - self.schedule.distance_at(index - 1))
                    / (self.schedule.distance_at(index - 1) - self.schedule.distance_at(index - 2));
                let mut p = last.clone();
                Zip::from(&mut p)
                    .and(earlier)
                    .for_each(|p, &e| *p = (*p + ratio * (*p - e)).max(0.0));
                Some(p)
            }
            _ => None,
        };
        let pressure = match (&start, &predicted) {
            (Some(given), _) => Some(given.view()),
            (None, Some(p)) => Some(p.view()),
            (None, None) => self.last_pressure_pa.as_ref().map(|p| p.view()),
        };
        let warm = rough::Warm {
            pressure_pa: pressure,
            local_compliance_m_per_pa: compliance,
        };
        rough::solve_cached(&problem, &warm, &mut self.cache.borrow_mut(), progress)
    }

    /// With a rough counter-surface ([`Evolution::sliding_against`]), the contact at the end of
    /// the last step taken: the worn surface against the counter slid to that distance, static
    /// (its plastic penetration is ploughing by the counter's asperities, which moves material
    /// aside and is not kept); `None` without a counter.
    pub fn sliding_contact(
        &mut self,
        progress: &mut dyn FnMut(usize, f64),
    ) -> Result<Option<RoughSolution>, RoughContactError> {
        let Some(counter) = &self.counter_m else {
            return Ok(None);
        };
        let distance_m = self.schedule.distance_at(self.next.saturating_sub(1));
        let combined = &self.heights_m + &slid(counter, distance_m, self.problem.spacing_m[0]);
        let problem = RoughContactProblem {
            heights_m: combined.view(),
            ..self.problem.clone()
        };
        let warm = rough::Warm {
            pressure_pa: self.last_sliding_pressure_pa.as_ref().map(|p| p.view()),
            local_compliance_m_per_pa: 0.0,
        };
        let solution =
            rough::solve_cached(&problem, &warm, &mut self.cache.borrow_mut(), progress)?;
        self.last_sliding_pressure_pa = Some(solution.pressure_pa.clone());
        Ok(Some(solution))
    }

    /// Takes the next step with `solution`, the contact [`Evolution::solve_next`] found for
    /// it: the wear `k ds p` and the plastic penetration at the cap are removed from the
    /// surface.
    pub fn commit(&mut self, solution: RoughSolution) -> Result<WearStep, WearError> {
        let (index, distance_m, compliance) = self.next_step();
        let cell_area = self.problem.spacing_m[0] * self.problem.spacing_m[1];
        if compliance > 0.0 {
            Zip::from(&mut self.heights_m)
                .and(&mut self.wear_depth_m)
                .and(&solution.pressure_pa)
                .for_each(|h, w, &p| {
                    let worn = compliance * p;
                    *h -= worn;
                    *w += worn;
                });
            self.worn_volume_m3 += compliance * solution.pressure_pa.sum() * cell_area;
        }
        // Plastic flattening: the penetration of the cells at the cap, kept.
        for &([row, column], depth) in &solution.plastic_penetration_m {
            self.heights_m[[row, column]] -= depth;
            self.plastic_depth_m[[row, column]] += depth;
            self.plastic_volume_m3 += depth * cell_area;
        }
        let max_wear_depth_m = self.wear_depth_m.iter().fold(0.0f64, |m, &w| m.max(w));
        if max_wear_depth_m > self.range_m {
            return Err(WearError::WornThrough {
                step: index,
                distance_m,
                depth_m: max_wear_depth_m,
                range_m: self.range_m,
            });
        }
        self.earlier_pressure_pa = self.last_pressure_pa.take();
        self.last_pressure_pa = Some(solution.pressure_pa.clone());
        self.next += 1;
        Ok(WearStep {
            index,
            sliding_distance_m: distance_m,
            solution,
            worn_volume_m3: self.worn_volume_m3,
            max_wear_depth_m,
            plastic_volume_m3: self.plastic_volume_m3,
        })
    }

    /// The next step solved and taken, `None` after the last: each step after the unworn
    /// contact wears the surface over its distance by backward Euler, warm-started from the
    /// pressure before; with a rough counter-surface, the step's contact is then the one
    /// against the counter slid to the step's distance ([`Evolution::sliding_contact`]).
    /// `progress(iteration, residual)` follows the contact solver.
    pub fn step(
        &mut self,
        progress: &mut dyn FnMut(usize, f64),
    ) -> Result<Option<WearStep>, WearError> {
        if self.finished() {
            return Ok(None);
        }
        let (step, distance_m, _) = self.next_step();
        // At step 0 nothing is worn: a contact at the edge is the unworn contact's own, with its
        // own hint (a larger map or a periodic solve), not a shorter sliding distance.
        let contact_error = |source| match source {
            RoughContactError::PressureAtEdge { row, column } if step > 0 => {
                WearError::ScarAtEdge {
                    step,
                    distance_m,
                    row,
                    column,
                }
            }
            source => WearError::Contact {
                step,
                distance_m,
                source,
            },
        };
        let solution = self
            .solve_next(None, None, progress)
            .map_err(contact_error)?;
        let mut taken = self.commit(solution)?;
        if let Some(sliding) = self.sliding_contact(progress).map_err(contact_error)? {
            taken.solution = sliding;
        }
        Ok(Some(taken))
    }
}

/// A counter-surface (`[ny, nx]`, periodic) slid by `distance_m` along +x over cells `dx` wide:
/// the point at `x` moves to `x + s`, rounded to whole cells and wrapped around the period.
pub fn slid(counter: &Array2<f64>, distance_m: f64, dx: f64) -> Array2<f64> {
    let nx = counter.ncols();
    let shift = (distance_m / dx).round().rem_euclid(nx as f64) as usize % nx.max(1);
    if shift == 0 {
        return counter.clone();
    }
    Array2::from_shape_fn(counter.raw_dim(), |(j, i)| {
        counter[[j, (i + nx - shift) % nx]]
    })
}

/// The load that presses `problem`'s surface: given, or the mean pressure over the map, N
/// (zero under a given approach).
pub fn nominal_load_n(problem: &RoughContactProblem) -> f64 {
    let (ny, nx) = problem.heights_m.dim();
    match problem.control {
        rough::Control::Load { newtons } => newtons,
        rough::Control::MeanPressure { pa } => {
            pa * nx as f64 * ny as f64 * problem.spacing_m[0] * problem.spacing_m[1]
        }
        rough::Control::Approach { .. } => 0.0,
    }
}

/// The volume of a map above its lowest point, `Σ (h - min h) dx dy` (m³): the most wear it
/// can take.
pub fn capacity_m3(heights_m: &Array2<f64>, spacing_m: [f64; 2]) -> f64 {
    let low = heights_m.iter().fold(f64::INFINITY, |m, &h| m.min(h));
    heights_m.iter().map(|&h| h - low).sum::<f64>() * spacing_m[0] * spacing_m[1]
}

/// The wear a later measurement `now` of a surface shows against the first, `first` (both m,
/// the same grid): the depth `max(first - now - offset, 0)` with `offset` the two
/// measurements' offset of datum, read where the difference is most common: the unworn part
/// of the map keeps its heights, so all its cells differ by the offset alone, while the worn
/// cells spread over the wear depths ([`datum_offset`]). Returns the depth map and the offset.
pub fn measured_wear(first: &Array2<f64>, now: &Array2<f64>) -> (Array2<f64>, f64) {
    let found = measured_change(first, now);
    (found.depth_m, found.offset_m)
}

/// What a later measurement of a surface shows against the first ([`measured_change`]).
#[derive(Clone, Debug, PartialEq)]
pub struct MeasuredChange {
    /// The wear depth, `max(first - now - offset, 0)` (m).
    pub depth_m: Array2<f64>,
    /// The two measurements' offset of datum (m, [`datum_offset`]).
    pub offset_m: f64,
    /// The most the later map stands above the first, `max(now - first + offset, 0)` (m):
    /// material added (a transfer film, pile-up at a scar's rim) or a datum that differs,
    /// which is not wear.
    pub higher_m: f64,
    /// The cells standing higher by more than a tenth of `higher_m` and than the unworn
    /// cells' spread (the densest window's width).
    pub higher_cells: usize,
    /// The differences' range, `max - min` of `first - now` (m).
    pub range_m: f64,
}

impl MeasuredChange {
    /// Whether the later map stands notably higher than the first somewhere: by more than a
    /// hundredth of the differences' range (ten times the window the datum offset is read in,
    /// above the unworn cells' own scatter).
    pub fn stands_higher(&self) -> bool {
        self.higher_m > 1e-2 * self.range_m && self.higher_cells > 0
    }
}

/// [`measured_wear`] with what the later map adds: where it stands higher than the first.
pub fn measured_change(first: &Array2<f64>, now: &Array2<f64>) -> MeasuredChange {
    let difference = first - now;
    let (offset_m, window_m) = datum_offset_and_window(difference.iter().copied().collect());
    let (low, high) = difference
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &d| {
            (l.min(d), h.max(d))
        });
    let higher_m = (offset_m - low).max(0.0);
    let floor = window_m.max(0.1 * higher_m);
    let higher_cells = difference.iter().filter(|&&d| offset_m - d > floor).count();
    MeasuredChange {
        depth_m: difference.mapv(|d| (d - offset_m).max(0.0)),
        offset_m,
        higher_m,
        higher_cells,
        range_m: if high >= low { high - low } else { 0.0 },
    }
}

/// The value the most differences share: the centre (median) of the densest window of the
/// sorted differences, the window a thousandth of their range wide. The unworn cells may be
/// fewer than half the map (a scar over most of it): the median of all would then lie in the
/// scar, the densest window still on the unworn cells.
pub fn datum_offset(differences: Vec<f64>) -> f64 {
    datum_offset_and_window(differences).0
}

/// [`datum_offset`] and the width of the window it was read in (a thousandth of the
/// differences' range).
fn datum_offset_and_window(mut differences: Vec<f64>) -> (f64, f64) {
    differences.retain(|d| d.is_finite());
    if differences.is_empty() {
        return (0.0, 0.0);
    }
    differences.sort_by(f64::total_cmp);
    let n = differences.len();
    let range = differences[n - 1] - differences[0];
    let width = 1e-3 * range;
    let (mut best, mut best_start) = (0usize, 0usize);
    let mut start = 0;
    for end in 0..n {
        while differences[end] - differences[start] > width {
            start += 1;
        }
        if end + 1 - start > best {
            best = end + 1 - start;
            best_start = start;
        }
    }
    let window = &differences[best_start..best_start + best];
    let m = window.len();
    let offset = if m % 2 == 1 {
        window[m / 2]
    } else {
        0.5 * (window[m / 2 - 1] + window[m / 2])
    };
    (offset, width)
}

#[cfg(test)]
mod tests;

//! The numerical EHL solution of a lubricated line contact (`ehl SCENE`) and the stresses in
//! body 1 under its pressure, beside the dry Hertz contact's.
//!
//! The solved pressure (piecewise linear between the solver's nodes) is applied to the
//! half-plane as uniform strips, one per element, each carrying the element's mean pressure
//! (so the load is kept exactly) and `q = μ p` in +x on body 1 (the scene's friction, as every
//! figure of the scene takes it): [`crate::solution::line_numerical::StripTractions`], the
//! closed-form strip solutions of plane strain. The dry contact is Hertz's closed form
//! (McEwen) under the same load.

use std::sync::Arc;

use ndarray::Array2;
use rayon::prelude::*;

use crate::contact::effective_modulus;
use crate::field::{Axis, FieldError, Plane};
use crate::lubrication::line_ehl::{self, LineEhl, LineEhlError, LineEhlOptions, LineEhlProblem};
use crate::scene::{Hertz, Scene};
use crate::solution::line_numerical::StripTractions;
use crate::solution::Solution;
use crate::stress::Quantity;
use crate::study::assess::{self, Extreme};

/// Why a scene has no EHL solution.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum EhlError {
    #[error("the scene has no [lubricant] table\nhint: add [lubricant] with viscosity, pressure_viscosity and entrainment_speed (docs/lubrication.md)")]
    NoLubricant,
    #[error("the numerical EHL solution is computed for line contacts (and spur gears at the pitch point), not for a {kind} contact\nhint: `stressfield hertz` reports its film and λ from Hamrock & Dowson's formulas")]
    NotLine { kind: &'static str },
    #[error("{0}")]
    Solver(#[from] LineEhlError),
    #[error("{0}")]
    Field(#[from] FieldError),
    #[error("the EHL solution at an entrainment speed of {speed_m_per_s} m/s did not converge after {iterations} Newton iterations: no step recorded\nhint: the solver is checked for Moes' M from 0.2 to 2000 and L up to 46 (docs/lubrication.md); narrow the sweep's speeds")]
    NotConverged {
        speed_m_per_s: f64,
        iterations: usize,
    },
}

/// The solved contact and the stresses under it.
#[derive(Clone, Debug)]
pub struct EhlStudy {
    pub solution: LineEhl,
    /// The EHL pressure and `q = μ p` as strips, in units of the Hertz half-width `b` and peak
    /// pressure `p_h` (only the strips that carry pressure).
    pub tractions: Arc<StripTractions>,
    pub friction: f64,
    /// Body 1's Poisson ratio.
    pub poisson: f64,
    /// The largest von Mises stress in body 1 under the EHL pressure and under the dry Hertz
    /// contact (units of `p_h` and `b`).
    pub von_mises: Extreme,
    pub dry_von_mises: Extreme,
}

impl EhlStudy {
    /// The stress solution under the EHL pressure (units of b and p_h).
    pub fn lubricated(&self) -> Solution {
        Solution::LineNumerical {
            tractions: Arc::clone(&self.tractions),
            friction: self.friction,
            poisson: self.poisson,
        }
    }

    /// The dry contact's closed form.
    pub fn dry(&self) -> Solution {
        Solution::LineHertz {
            friction: self.friction,
            poisson: self.poisson,
        }
    }
}

/// The line contact of a lubricated scene as an EHL problem.
pub fn problem(scene: &Scene) -> Result<LineEhlProblem, EhlError> {
    let lubricant = scene.lubricant.ok_or(EhlError::NoLubricant)?;
    let dimensional = scene.contact.dimensional.ok_or(EhlError::NoLubricant)?;
    let line = match dimensional.hertz {
        Hertz::Line(line) => line,
        Hertz::Point(_) => return Err(EhlError::NotLine { kind: "point" }),
        Hertz::Elliptical(_) => return Err(EhlError::NotLine { kind: "elliptical" }),
    };
    Ok(LineEhlProblem {
        load_n_per_m: line.load_n_per_m,
        radius_m: line.effective_radius_m,
        reduced_modulus_pa: 2.0
            * effective_modulus(&dimensional.body1.material, &dimensional.body2.material),
        viscosity_pa_s: lubricant.viscosity_pa_s,
        entrainment_m_per_s: lubricant.entrainment_m_per_s,
        pressure_viscosity: lubricant.pressure_viscosity,
        compressibility: lubricant.compressibility,
    })
}

/// Solves `scene`'s lubricated line contact and the stresses under it.
pub fn solve(scene: &Scene) -> Result<EhlStudy, EhlError> {
    let problem = problem(scene)?;
    solve_problem(
        &problem,
        scene.contact.friction,
        scene.contact.poisson,
        &LineEhlOptions::default(),
    )
}

/// Solves `problem` and the stresses under it with friction `friction` (`q = μ p` in +x on
/// body 1) and body 1's Poisson ratio `poisson`.
pub fn solve_problem(
    problem: &LineEhlProblem,
    friction: f64,
    poisson: f64,
    options: &LineEhlOptions,
) -> Result<EhlStudy, EhlError> {
    let solution = line_ehl::solve(problem, options)?;
    let tractions = Arc::new(strips(&solution, friction));
    let lubricated = Solution::LineNumerical {
        tractions: Arc::clone(&tractions),
        friction,
        poisson,
    };
    let b = solution.half_width_m;
    let span = (
        solution
            .x_m
            .iter()
            .zip(&solution.pressure_pa)
            .find(|(_, p)| **p > 0.0)
            .map_or(-1.0, |(x, _)| x / b),
        solution.cavitation_x_m / b,
    );
    // With friction the strips' surface stress has logarithmic peaks at their edges: the
    // search stays half a strip below the surface.
    let min_depth = if friction > 0.0 {
        0.5 * solution.spacing_over_b
    } else {
        0.0
    };
    let von_mises = maximum(&lubricated, Quantity::VonMises, span, min_depth);
    let dry_von_mises = assess::maximum(
        &Solution::LineHertz { friction, poisson },
        Quantity::VonMises,
        false,
    );
    Ok(EhlStudy {
        solution,
        tractions,
        friction,
        poisson,
        von_mises,
        dry_von_mises,
    })
}

/// The solved pressure as strips in units of b and p_h: one per element that carries
/// pressure, with the element's mean pressure (the load of the piecewise-linear pressure kept
/// exactly) and `q = μ p`.
pub fn strips(solution: &LineEhl, friction: f64) -> StripTractions {
    let b = solution.half_width_m;
    let ph = solution.hertz_p0_pa;
    let mut edges = Vec::new();
    let mut pressure = Vec::new();
    for k in 0..solution.x_m.len().saturating_sub(1) {
        let mean = 0.5 * (solution.pressure_pa[k] + solution.pressure_pa[k + 1]) / ph;
        if mean <= 0.0 {
            continue;
        }
        let (left, right) = (solution.x_m[k] / b, solution.x_m[k + 1] / b);
        if edges.last() != Some(&left) {
            if !edges.is_empty() {
                // A gap between loaded elements: an unloaded strip keeps the edges contiguous.
                pressure.push(0.0);
            }
            edges.push(left);
        }
        edges.push(right);
        pressure.push(mean);
    }
    if edges.is_empty() {
        edges = vec![-1.0, 1.0];
        pressure = vec![0.0];
    }
    let shear = pressure.iter().map(|p| friction * p).collect();
    StripTractions {
        edges,
        pressure,
        shear,
    }
}

/// The largest `quantity` of `solution` over `x` in the loaded span `(from, to)` widened by
/// half a half-width each way and `min_depth <= z <= 2` (units of b): a scan at a step of
/// 0.02 b (rows in parallel), then a compass search from its best point.
fn maximum(
    solution: &Solution,
    quantity: Quantity,
    (from, to): (f64, f64),
    min_depth: f64,
) -> Extreme {
    let step = 0.02;
    let (x0, x1) = (from - 0.5, to + 0.5);
    let nx = ((x1 - x0) / step).ceil() as usize;
    let nz = (2.0 / step).ceil() as usize;
    let best = (0..=nz)
        .into_par_iter()
        .map(|iz| {
            let z = (min_depth + step * iz as f64).min(2.0);
            let mut best = ([x0, z], f64::NEG_INFINITY);
            for ix in 0..=nx {
                let x = x0 + step * ix as f64;
                let v = quantity.of(&solution.stress_over_p0(x, 0.0, z));
                if v > best.1 {
                    best = ([x, z], v);
                }
            }
            best
        })
        .reduce(
            || ([x0, 0.0], f64::NEG_INFINITY),
            |a, b| if b.1 > a.1 { b } else { a },
        );
    let value = |p: [f64; 2]| quantity.of(&solution.stress_over_p0(p[0], 0.0, p[1]));
    let (at, value) = super::compass::compass_maximum(
        value,
        best.0,
        best.1,
        [step, step],
        [(x0, x1), (min_depth, 2.0)],
    );
    Extreme {
        value_over_p0: value,
        x_over_a: at[0],
        y_over_a: 0.0,
        z_over_a: at[1],
        mirrored_in_y: false,
    }
}

/// The solution as `ehl --pressure` writes it and `Scene.ehl()` returns it: `(n, 3)`, columns
/// x (m, entrainment in +x), pressure (Pa), film (m).
pub fn solution_array(solution: &LineEhl) -> Array2<f64> {
    let mut array = Array2::zeros((solution.x_m.len(), 3));
    for (i, mut row) in array.rows_mut().into_iter().enumerate() {
        row[0] = solution.x_m[i];
        row[1] = solution.pressure_pa[i];
        row[2] = solution.film_m[i];
    }
    array
}

/// The sections a sheet or a recording draws: von Mises in body 1 under the EHL pressure and
/// under the dry Hertz contact, on one xz grid in units of b.
#[derive(Clone, Debug)]
pub struct EhlSections {
    /// The grid (units of b): x across the contact, z depth.
    pub plane: Plane,
    /// `[z, x]` von Mises over `p_h`: under the EHL pressure, and the dry contact's.
    pub lubricated_von_mises_over_p0: Array2<f64>,
    pub dry_von_mises_over_p0: Array2<f64>,
}

/// The drawn window: `x` from −2 b (the inlet's pressure build-up) to 1.5 b (past the spike),
/// `z` from the surface to 1.2 b (below the largest von Mises, 0.7 b for μ = 0).
pub const SECTION_X_OVER_B: (f64, f64) = (-2.0, 1.5);
pub const SECTION_Z_OVER_B: f64 = 1.2;

/// [`EhlSections`] of `study` on `columns` × `rows` samples (rows in parallel, by
/// [`crate::field::evaluate`]).
pub fn sections(study: &EhlStudy, columns: usize, rows: usize) -> Result<EhlSections, FieldError> {
    let plane = Plane::xz(
        Axis::new(SECTION_X_OVER_B.0, SECTION_X_OVER_B.1, columns),
        Axis::new(0.0, SECTION_Z_OVER_B, rows),
    );
    let map = |solution: &Solution| -> Result<Array2<f64>, FieldError> {
        let field = crate::field::evaluate(solution, &plane, &[Quantity::VonMises], &|| {})?;
        Ok(field
            .map(Quantity::VonMises)
            .map(|m| m.to_owned())
            .unwrap_or_else(|| Array2::zeros((rows, columns))))
    };
    Ok(EhlSections {
        plane,
        lubricated_von_mises_over_p0: map(&study.lubricated())?,
        dry_von_mises_over_p0: map(&study.dry())?,
    })
}

/// The depth (units of b) above which the sweep's near-surface maximum is taken: the layer the
/// pressure spike stresses, above the Hertzian maximum at 0.7 b.
pub const NEAR_SURFACE_DEPTH_OVER_B: f64 = 0.25;

/// A sweep's sections (its table and its recording): samples across (−2 b to 1.5 b) and in
/// depth (0 to 1.2 b), 0.02 b apart (each step's two maps cost a strip sum per sample).
pub const SWEEP_COLUMNS: usize = 176;
pub const SWEEP_ROWS: usize = 61;

/// The sheet's sections (`render`): 0.0125 b apart.
pub const SHEET_COLUMNS: usize = 281;
pub const SHEET_ROWS: usize = 97;

/// One step of an entrainment-speed sweep (`[sweep] parameter = "entrainment_speed"`).
#[derive(Clone, Debug)]
pub struct EhlStep {
    pub entrainment_m_per_s: f64,
    pub study: EhlStudy,
    pub sections: EhlSections,
    /// The largest von Mises under the EHL pressure at depths up to
    /// [`NEAR_SURFACE_DEPTH_OVER_B`], over the section's samples (0.02 b apart; units of p_h
    /// and b).
    pub near_surface_von_mises: Extreme,
}

/// The lubricated line contact of `scene` solved at each entrainment speed of `speeds` (m/s),
/// steps in parallel, with the sections on `columns` × `rows` samples. A step that does not
/// converge is an error: a sweep never draws an unconverged film.
pub fn speed_sweep(
    scene: &Scene,
    speeds: &[f64],
    columns: usize,
    rows: usize,
) -> Result<Vec<EhlStep>, EhlError> {
    let base = problem(scene)?;
    speeds
        .par_iter()
        .map(|&speed| {
            let problem = LineEhlProblem {
                entrainment_m_per_s: speed,
                ..base
            };
            let study = solve_problem(
                &problem,
                scene.contact.friction,
                scene.contact.poisson,
                &LineEhlOptions::default(),
            )?;
            if !study.solution.converged {
                return Err(EhlError::NotConverged {
                    speed_m_per_s: speed,
                    iterations: study.solution.iterations,
                });
            }
            let sections = sections(&study, columns, rows)?;
            let near_surface_von_mises = near_surface_maximum(&sections);
            Ok(EhlStep {
                entrainment_m_per_s: speed,
                study,
                sections,
                near_surface_von_mises,
            })
        })
        .collect()
}

/// The largest sample of the EHL section's von Mises at depths up to
/// [`NEAR_SURFACE_DEPTH_OVER_B`].
pub fn near_surface_maximum(sections: &EhlSections) -> Extreme {
    let plane = &sections.plane;
    let mut best = (0.0, 0.0, f64::NEG_INFINITY);
    for iz in 0..plane.v.count {
        let z = plane.v.value(iz);
        if z > NEAR_SURFACE_DEPTH_OVER_B + 1e-12 {
            break;
        }
        for ix in 0..plane.u.count {
            let v = sections.lubricated_von_mises_over_p0[[iz, ix]];
            if v > best.2 {
                best = (plane.u.value(ix), z, v);
            }
        }
    }
    Extreme {
        value_over_p0: best.2,
        x_over_a: best.0,
        y_over_a: 0.0,
        z_over_a: best.1,
        mirrored_in_y: false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lubrication::density::Compressibility;
    use crate::lubrication::viscosity::PressureViscosity;
    use std::f64::consts::PI;

    fn problem() -> LineEhlProblem {
        // A steel roller, M about 20, L about 10.
        let e = 2.3e11;
        let r = 0.01;
        let u: f64 = 1e-11;
        LineEhlProblem {
            load_n_per_m: 20.0 * (2.0 * u).sqrt() * e * r,
            radius_m: r,
            reduced_modulus_pa: e,
            viscosity_pa_s: 0.04,
            entrainment_m_per_s: u * e * r / 0.04,
            pressure_viscosity: PressureViscosity::Roelands { z: 0.67 },
            compressibility: Compressibility::DowsonHigginson,
        }
    }

    /// The stress under the solved pressure equals an independent quadrature of Flamant's
    /// line-load solution over the same (piecewise-linear) pressure: `σxx = -(2/π) ∫ p X² z / r⁴`,
    /// `σzz = -(2/π) ∫ p z³ / r⁴`, `σxz = -(2/π) ∫ p X z² / r⁴` (Johnson 1985, §2.2), by
    /// adaptive quadrature element by element, at depths from 0.1 b.
    #[test]
    fn stress_under_the_ehl_pressure_is_flamant_s() {
        let study =
            solve_problem(&problem(), 0.0, 0.3, &LineEhlOptions::default()).expect("solved");
        let s = &study.solution;
        let (b, ph) = (s.half_width_m, s.hertz_p0_pa);
        let solution = study.lubricated();
        for &(x, z) in &[
            (-0.5, 0.1),
            (0.0, 0.3),
            (0.8, 0.15),
            (0.95, 0.1),
            (0.3, 0.7),
            (1.5, 0.5),
        ] {
            let mut sums = [0.0; 3];
            for k in 0..s.x_m.len() - 1 {
                let (p0, p1) = (s.pressure_pa[k] / ph, s.pressure_pa[k + 1] / ph);
                if p0 <= 0.0 && p1 <= 0.0 {
                    continue;
                }
                let (a, c) = (s.x_m[k] / b, s.x_m[k + 1] / b);
                for (component, sum) in sums.iter_mut().enumerate() {
                    let integrand = |t: f64| {
                        let p = p0 + (p1 - p0) * (t - a) / (c - a);
                        let dx = x - t;
                        let r2 = dx * dx + z * z;
                        let kernel = match component {
                            0 => dx * dx * z,
                            1 => z * z * z,
                            _ => dx * z * z,
                        };
                        -2.0 / PI * p * kernel / (r2 * r2)
                    };
                    *sum += quadrature::integrate(integrand, a, c, 1e-13).integral;
                }
            }
            let strips = solution.stress_over_p0(x, 0.0, z);
            let worst = [strips.xx, strips.zz, strips.xz]
                .iter()
                .zip(sums)
                .map(|(n, e)| (n - e).abs())
                .fold(0.0, f64::max);
            println!("Flamant at ({x}, {z}) b: largest difference {worst:.2e} p_h");
            for (numeric, exact) in [strips.xx, strips.zz, strips.xz].iter().zip(sums) {
                // The strips carry each element's mean pressure: they differ from the linear
                // pressure by its curvature within an element, O(spacing²).
                assert!(
                    (numeric - exact).abs() < 2e-4,
                    "({x}, {z}): {numeric} vs {exact}"
                );
            }
        }
    }

    /// The dry maximum is Hertz's (0.5575 p0 at 0.7043 b for ν = 0.3, μ = 0: the closed form
    /// on the axis, maximised to 1e-5 b), and the EHL pressure's lies near it.
    #[test]
    fn maxima_beside_the_dry_ones() {
        let study =
            solve_problem(&problem(), 0.0, 0.3, &LineEhlOptions::default()).expect("solved");
        assert!((study.dry_von_mises.value_over_p0 - 0.5575).abs() < 1e-4);
        assert!((study.dry_von_mises.z_over_a - 0.7043).abs() < 1e-3);
        let ehl = study.von_mises;
        assert!(
            (ehl.value_over_p0 / study.dry_von_mises.value_over_p0 - 1.0).abs() < 0.1,
            "{ehl:?}"
        );
        // The strips carry the load exactly.
        assert!((study.tractions.load() - PI / 2.0).abs() < 1e-9);
    }
}

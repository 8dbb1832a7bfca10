//! The isothermal, steady elastohydrodynamic lubrication (EHL) of a line contact, solved
//! numerically: the pressure `p(x)` and the film `h(x)` of two elastic cylinders entraining a
//! lubricant in `+x` (inlet at `-x`, outlet at `+x`).
//!
//! ## The equations
//! In Hertz's units (`X = x/b`, `b` the Hertz half-width; `P = p/p_h`, `p_h` the Hertz peak
//! pressure; `H = h R / b²`; `ρ̄ = ρ/ρ0`; `η̄ = η/η0`), after Venner & Lubrecht (2000):
//!
//! - Reynolds' equation, steady: `d/dX(ε dP/dX) - d(ρ̄ H)/dX = 0`, `ε = ρ̄ H³ / (η̄ λ̄)`,
//!   `λ̄ = 12 η0 u R² / (b³ p_h)`, `u = (u1 + u2)/2`;
//! - the film: `H(X) = H0 + X²/2 - (1/π) ∫ ln|X - S| P(S) dS` (the rigid gap and the elastic
//!   deflection of both bodies, plane strain, Hamrock's `E' = 2 E*` in `p_h = E' b / (4R)`);
//! - the load: `∫ P dX = π/2` (the load per unit length `w`, as `p_h = 2w / (π b)`);
//! - cavitation by Reynolds' condition: `P >= 0` everywhere, Reynolds' equation where
//!   `P > 0`, and where the film cavitates `P = 0` with a diverging gap (so `dP/dX = 0` where
//!   the film breaks), a complementarity condition;
//! - the viscosity of Roelands or Barus ([`PressureViscosity`]) and the density of
//!   Dowson & Higginson or a constant one ([`Compressibility`]).
//!
//! ## The method
//! Newton–Raphson on the whole coupled system (Okamura 1982; Houpert & Hamrock 1986): the
//! unknowns are the nodal pressures and `H0`, the Jacobian is dense (the deflection couples
//! every node), and the linear systems are solved by LU decomposition with partial pivoting.
//! The pressure is piecewise linear on a graded grid, finest where the film constricts at the
//! inlet and the outlet; its deflection is integrated exactly over each element; Reynolds'
//! equation is a finite volume with the Poiseuille flow centred and the Couette flow upwind to
//! second order (a linear extrapolation from the two upstream nodes, after Venner & Lubrecht).
//! The cavitated nodes form an active set updated after each step: a node whose pressure would
//! fall below zero cavitates, and a cavitated node where the film would need pressure is freed
//! with a few downstream neighbours, so the film's end moves several nodes per step. Each
//! Newton step is damped by backtracking until the film stays open and the residual falls.
//! The problem is solved first on a coarse grid from the Hertz pressure, then on finer grids
//! from the coarser solution (grid sequencing). Convergence: a full Newton step that changes no
//! pressure by more than 1e-8 of the largest, with no change of the cavitated set.
//!
//! ## Reference
//! C. H. Venner & A. A. Lubrecht, *Multilevel Methods in Lubrication* (Elsevier, 2000), the
//! line contact's equations and dimensionless form; K. Okamura, A contribution to the
//! numerical analysis of isothermal elastohydrodynamic lubrication, Proc. 9th Leeds-Lyon
//! Symposium (1982) 313–320; L. G. Houpert & B. J. Hamrock, Fast approach for calculating film
//! thicknesses and pressures in elastohydrodynamically lubricated contacts at high loads,
//! J. Tribol. 108 (1986) 411–420.

use std::f64::consts::PI;

use super::density::Compressibility;
use super::film::{moes_line_central, FilmConditions};
use super::viscosity::PressureViscosity;

/// The contact to solve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineEhlProblem {
    pub load_n_per_m: f64,
    /// Effective radius in the direction of entrainment, m.
    pub radius_m: f64,
    /// Hamrock's reduced modulus `E' = 2 E*`, Pa.
    pub reduced_modulus_pa: f64,
    /// Dynamic viscosity at the inlet temperature and ambient pressure, Pa s.
    pub viscosity_pa_s: f64,
    /// Mean entrainment speed `u = (u1 + u2)/2`, m/s.
    pub entrainment_m_per_s: f64,
    pub pressure_viscosity: PressureViscosity,
    pub compressibility: Compressibility,
}

impl LineEhlProblem {
    /// Hertz's half-width `b = √(8 w R / (π E'))`, m.
    pub fn half_width_m(&self) -> f64 {
        (8.0 * self.load_n_per_m * self.radius_m / (PI * self.reduced_modulus_pa)).sqrt()
    }

    /// Hertz's peak pressure `p_h = 2 w / (π b)`, Pa.
    pub fn hertz_p0_pa(&self) -> f64 {
        2.0 * self.load_n_per_m / (PI * self.half_width_m())
    }

    /// The conditions of the film formulas (`α` the viscosity's slope at zero pressure).
    pub fn conditions(&self) -> FilmConditions {
        FilmConditions {
            viscosity_pa_s: self.viscosity_pa_s,
            alpha_per_pa: self
                .pressure_viscosity
                .alpha_at_zero_per_pa(self.viscosity_pa_s),
            reduced_modulus_pa: self.reduced_modulus_pa,
            entrainment_m_per_s: self.entrainment_m_per_s,
            radius_x_m: self.radius_m,
        }
    }

    /// Moes' `(M, L)`.
    pub fn moes(&self) -> (f64, f64) {
        self.conditions().moes_line(self.load_n_per_m)
    }

    fn check(&self) -> Result<(), LineEhlError> {
        let positive = [
            ("load", self.load_n_per_m),
            ("radius", self.radius_m),
            ("reduced modulus", self.reduced_modulus_pa),
            ("viscosity", self.viscosity_pa_s),
            ("entrainment speed", self.entrainment_m_per_s),
        ];
        for (name, value) in positive {
            if !(value > 0.0 && value.is_finite()) {
                return Err(LineEhlError::Invalid(format!(
                    "the {name} must be positive and finite, got {value}"
                )));
            }
        }
        match self.pressure_viscosity {
            PressureViscosity::Barus { alpha_per_pa } if !(alpha_per_pa >= 0.0 && alpha_per_pa.is_finite()) => {
                return Err(LineEhlError::Invalid(format!(
                    "the pressure-viscosity coefficient must be zero or positive, got {alpha_per_pa}"
                )))
            }
            PressureViscosity::Roelands { z } if !(z >= 0.0 && z.is_finite()) => {
                return Err(LineEhlError::Invalid(format!(
                    "Roelands' pressure-viscosity index must be zero or positive, got {z}"
                )))
            }
            PressureViscosity::Roelands { .. }
                if self.viscosity_pa_s <= super::viscosity::roelands_limit_pa_s() =>
            {
                return Err(LineEhlError::Invalid(format!(
                    "Roelands' relation needs a viscosity above 6.3e-5 Pa s, got {}",
                    self.viscosity_pa_s
                )))
            }
            _ => {}
        }
        Ok(())
    }
}

/// How fine the grid is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineEhlOptions {
    /// The finest node spacing, in Hertz half-widths; `None`: [`default_spacing`] of the
    /// contact's Moes `M`.
    pub spacing_over_b: Option<f64>,
    /// Newton iterations allowed on each grid.
    pub max_iterations: usize,
}

impl Default for LineEhlOptions {
    fn default() -> Self {
        Self {
            spacing_over_b: None,
            max_iterations: 60,
        }
    }
}

/// The default finest spacing (units of b) for Moes' `M`: `0.01` up to `M = 50`, then
/// `0.5/M` (the film's constriction at the outlet narrows as the load grows); halving it
/// changes the minimum film by less than 1 % (docs/lubrication.md).
pub fn default_spacing(moes_m: f64) -> f64 {
    (0.4 / moes_m).clamp(1e-4, 0.008)
}

/// Why a contact cannot be solved.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum LineEhlError {
    #[error("{0}")]
    Invalid(String),
}

/// A solved line contact, SI units; `x` from the centre of the Hertz contact, the entrainment
/// in `+x`.
#[derive(Clone, Debug, PartialEq)]
pub struct LineEhl {
    pub x_m: Vec<f64>,
    pub pressure_pa: Vec<f64>,
    pub film_m: Vec<f64>,
    /// Hertz's half-width `b` and peak pressure `p_h` of the dry contact under the same load.
    pub half_width_m: f64,
    pub hertz_p0_pa: f64,
    /// The film at the centre `x = 0`.
    pub central_film_m: f64,
    /// The smallest film where the lubricant carries pressure (before it cavitates), and where.
    pub minimum_film_m: f64,
    pub minimum_film_x_m: f64,
    pub max_pressure_pa: f64,
    pub max_pressure_x_m: f64,
    /// The pressure spike: the most downstream local maximum of the pressure at `x > 0`, and
    /// its pressure (`None` without such a maximum).
    pub spike_x_m: Option<f64>,
    pub spike_pressure_pa: Option<f64>,
    /// Where the film cavitates (the first node downstream of the pressure with zero pressure).
    pub cavitation_x_m: f64,
    pub moes_m: f64,
    pub moes_l: f64,
    /// Newton iterations over all grids.
    pub iterations: usize,
    pub converged: bool,
    /// `|∫p dx / w - 1|`.
    pub load_error: f64,
    /// The mass flow per unit length `ρ̄ (h u - h³/(12 η) dp/dx)` (with `ρ0 = 1`), m²/s, at
    /// each node; constant where the film is full.
    pub flow_m2_per_s: Vec<f64>,
    /// The finest spacing used, units of b, and the nodes.
    pub spacing_over_b: f64,
}

impl LineEhl {
    /// The largest relative departure of the mass flow from its mean over the nodes with
    /// pressure above `fraction` of the largest (where the film is full and away from its
    /// ends), by central differences: the discretisation's error, not its conservation (the
    /// finite volumes conserve their own flux exactly).
    pub fn flow_variation(&self, fraction: f64) -> f64 {
        let threshold = fraction * self.max_pressure_pa;
        let flows: Vec<f64> = self
            .flow_m2_per_s
            .iter()
            .zip(&self.pressure_pa)
            .filter(|(_, p)| **p > threshold)
            .map(|(q, _)| *q)
            .collect();
        if flows.is_empty() {
            return 0.0;
        }
        let mean = flows.iter().sum::<f64>() / flows.len() as f64;
        flows
            .iter()
            .map(|q| (q / mean - 1.0).abs())
            .fold(0.0, f64::max)
    }
}

/// Solves `problem`.
pub fn solve(problem: &LineEhlProblem, options: &LineEhlOptions) -> Result<LineEhl, LineEhlError> {
    problem.check()?;
    let b = problem.half_width_m();
    let ph = problem.hertz_p0_pa();
    let (moes_m, moes_l) = problem.moes();
    let lambda =
        12.0 * problem.viscosity_pa_s * problem.entrainment_m_per_s * problem.radius_m.powi(2)
            / (b.powi(3) * ph);
    // A first guess of the central film (Moes, Barus: thicker than Roelands'), H = h R / b².
    let hc_guess = moes_line_central(moes_m, moes_l)
        * (2.0 * problem.conditions().speed_parameter()).sqrt()
        * problem.radius_m
        * problem.radius_m
        / (b * b);
    let finest = options
        .spacing_over_b
        .unwrap_or_else(|| default_spacing(moes_m))
        .clamp(1e-5, 0.05);
    let physics = Physics {
        problem: *problem,
        ph,
        lambda,
    };
    let mut extent = Extent::for_film(hc_guess);
    let mut attempts = 0;
    loop {
        let result = sequence(
            &physics,
            extent,
            finest,
            moes_m,
            hc_guess,
            options.max_iterations,
        );
        attempts += 1;
        // A domain too short for the solution: pressure left at the outlet's end (the film
        // has not cavitated) or at the inlet's (not fully flooded). Lengthen it and solve again.
        let ends_clear = result.outlet_clear && result.inlet_clear;
        if ends_clear || !result.converged || attempts >= 3 {
            return Ok(result.into_solution(problem, moes_m, moes_l, finest, ends_clear));
        }
        extent = Extent {
            inlet: if result.inlet_clear {
                extent.inlet
            } else {
                1.6 * extent.inlet
            },
            outlet: if result.outlet_clear {
                extent.outlet
            } else {
                1.6 * extent.outlet
            },
        };
    }
}

/// The domain `[-inlet, outlet]`, units of b.
#[derive(Clone, Copy, Debug)]
struct Extent {
    inlet: f64,
    outlet: f64,
}

impl Extent {
    /// Long enough that the rigid gap at the inlet is 40 central films, and that the outlet
    /// reaches past where a film of about that thickness cavitates.
    fn for_film(hc: f64) -> Self {
        Self {
            inlet: 4.5f64.max((80.0 * hc).sqrt()),
            outlet: 1.6f64.max(1.0 + (2.0 * hc).sqrt()),
        }
    }
}

struct Physics {
    problem: LineEhlProblem,
    ph: f64,
    lambda: f64,
}

impl Physics {
    /// `(ln η̄, d ln η̄/dP, ρ̄, dρ̄/dP)` at `P`.
    #[inline]
    fn at(&self, p: f64) -> (f64, f64, f64, f64) {
        let pressure = p * self.ph;
        let (ln_eta, d_ln_eta) = self
            .problem
            .pressure_viscosity
            .log_ratio(self.problem.viscosity_pa_s, pressure);
        let (rho, d_rho) = self.problem.compressibility.density_ratio(pressure);
        (ln_eta, d_ln_eta * self.ph, rho, d_rho * self.ph)
    }
}

/// A graded grid on `[-extent.inlet, extent.outlet]` (units of b): spacing `fine` where the
/// film constricts, at the inlet's edge `|X + 1| <= w` and at the outlet `1 - 2w <= X <= 1 + w`
/// (`w` narrowing with Moes' M), at most `max(fine, 0.01)` elsewhere within `|X| <= 1.2`, and
/// growing by 5 % per node away from those zones, to at most 0.1.
fn graded_grid(extent: Extent, fine: f64, moes_m: f64, scale: f64) -> Vec<f64> {
    let w = (15.0 / moes_m).clamp(0.03, 0.35);
    let zones = [(-1.0 - w, -1.0 + w), (1.0 - 2.0 * w, 1.0 + w)];
    let growth = 0.05;
    let centre = fine.max(0.01);
    let spacing = |x: f64| {
        let distance = zones
            .iter()
            .map(|&(lo, hi)| (lo - x).max(x - hi).max(0.0))
            .fold(f64::INFINITY, f64::min);
        let cap = (centre + growth * (x.abs() - 1.2).max(0.0)).min(0.1);
        scale * (fine + growth * distance).min(cap).max(fine)
    };
    let (start, end) = (-extent.inlet, extent.outlet);
    let mut x = vec![start];
    let mut at = start;
    loop {
        let step = spacing(at / scale);
        if at + 1.5 * step >= end {
            x.push(end);
            break;
        }
        at += step;
        x.push(at);
    }
    x
}

/// The grid's elastic influence coefficients: `K[i][j] = ∫ φ_j(S) ln|X_i - S| dS` for the hat
/// function `φ_j` of each interior node, exactly (`∫ ln|u| du = u ln|u| - u`,
/// `∫ u ln|u| du = u²/2 ln|u| - u²/4`), row-major.
fn influence(x: &[f64]) -> Vec<f64> {
    let g0 = |u: f64| if u == 0.0 { 0.0 } else { u * u.abs().ln() - u };
    let g1 = |u: f64| {
        if u == 0.0 {
            0.0
        } else {
            0.5 * u * u * u.abs().ln() - 0.25 * u * u
        }
    };
    let nodes = x.len();
    let mut k = vec![0.0; nodes * nodes];
    for (i, &xi) in x.iter().enumerate() {
        // ∫ over each element of its rising and falling halves.
        let mut rising = vec![0.0; nodes];
        let mut falling = vec![0.0; nodes];
        for e in 0..nodes - 1 {
            let (a, b) = (x[e], x[e + 1]);
            let i0 = g0(b - xi) - g0(a - xi);
            let i1 = g1(b - xi) - g1(a - xi);
            let up = (i1 + (xi - a) * i0) / (b - a);
            rising[e + 1] = up;
            falling[e] = i0 - up;
        }
        let row = &mut k[i * nodes..(i + 1) * nodes];
        for j in 1..nodes - 1 {
            row[j] = rising[j] + falling[j];
        }
    }
    k
}

/// Solves `a x = b` in place by LU decomposition with partial pivoting (`a` row-major
/// `n x n`); `false` if `a` is singular.
fn lu_solve(a: &mut [f64], b: &mut [f64], n: usize) -> bool {
    for col in 0..n {
        let mut pivot = col;
        let mut best = a[col * n + col].abs();
        for r in col + 1..n {
            let v = a[r * n + col].abs();
            if v > best {
                best = v;
                pivot = r;
            }
        }
        if !(best > 0.0 && best.is_finite()) {
            return false;
        }
        if pivot != col {
            for c in 0..n {
                a.swap(col * n + c, pivot * n + c);
            }
            b.swap(col, pivot);
        }
        let diagonal = a[col * n + col];
        let (top, bottom) = a.split_at_mut((col + 1) * n);
        let pivot_row = &top[col * n + col + 1..col * n + n];
        let b_col = b[col];
        for (r, row) in bottom.chunks_exact_mut(n).enumerate() {
            let factor = row[col] / diagonal;
            if factor != 0.0 {
                for (v, p) in row[col + 1..].iter_mut().zip(pivot_row) {
                    *v -= factor * p;
                }
                b[col + 1 + r] -= factor * b_col;
            }
        }
    }
    for r in (0..n).rev() {
        let row = &a[r * n..(r + 1) * n];
        let sum: f64 = row[r + 1..]
            .iter()
            .zip(&b[r + 1..])
            .map(|(x, y)| x * y)
            .sum();
        b[r] = (b[r] - sum) / row[r];
    }
    true
}

/// The discrete system on one grid.
struct System<'a> {
    physics: &'a Physics,
    x: Vec<f64>,
    kernel: Vec<f64>,
    /// Second-order upwind weights: the Couette flux through the face `k+1/2` is
    /// `g_k + theta_k (g_k - g_{k-1})`.
    theta: Vec<f64>,
    /// Trapezoidal weights of the load.
    weights: Vec<f64>,
}

/// Node values derived from the pressure and the film.
struct Nodes {
    eps: Vec<f64>,
    eps_dp: Vec<f64>,
    eps_dh: Vec<f64>,
    g: Vec<f64>,
    g_dp: Vec<f64>,
    g_dh: Vec<f64>,
}

impl<'a> System<'a> {
    fn new(physics: &'a Physics, x: Vec<f64>) -> Self {
        let n = x.len() - 1;
        let theta = (0..=n)
            .map(|k| {
                if k == 0 || k == n {
                    0.0
                } else {
                    0.5 * (x[k + 1] - x[k]) / (x[k] - x[k - 1])
                }
            })
            .collect();
        let weights = (0..=n)
            .map(|j| {
                if j == 0 || j == n {
                    0.0
                } else {
                    0.5 * (x[j + 1] - x[j - 1])
                }
            })
            .collect();
        Self {
            physics,
            kernel: influence(&x),
            x,
            theta,
            weights,
        }
    }

    fn last(&self) -> usize {
        self.x.len() - 1
    }

    fn film(&self, p: &[f64], h0: f64) -> Vec<f64> {
        let nodes = self.x.len();
        let n = nodes - 1;
        (0..nodes)
            .map(|i| {
                let row = &self.kernel[i * nodes + 1..i * nodes + n];
                let deflection: f64 = row.iter().zip(&p[1..n]).map(|(k, p)| k * p).sum();
                h0 + 0.5 * self.x[i] * self.x[i] - deflection / PI
            })
            .collect()
    }

    fn nodes(&self, p: &[f64], h: &[f64]) -> Nodes {
        let count = p.len();
        let mut nodes = Nodes {
            eps: vec![0.0; count],
            eps_dp: vec![0.0; count],
            eps_dh: vec![0.0; count],
            g: vec![0.0; count],
            g_dp: vec![0.0; count],
            g_dh: vec![0.0; count],
        };
        for k in 0..count {
            let (ln_eta, d_ln_eta, rho, d_rho) = self.physics.at(p[k]);
            let hk = h[k].max(1e-300);
            let eps = rho * hk * hk * hk * (-ln_eta).exp() / self.physics.lambda;
            nodes.eps[k] = eps;
            nodes.eps_dp[k] = eps * (d_rho / rho - d_ln_eta);
            nodes.eps_dh[k] = 3.0 * eps / hk;
            nodes.g[k] = rho * hk;
            nodes.g_dp[k] = d_rho * hk;
            nodes.g_dh[k] = rho;
        }
        nodes
    }

    fn couette(&self, nodes: &Nodes, k: usize) -> f64 {
        let upstream = if k > 0 { nodes.g[k - 1] } else { 0.0 };
        nodes.g[k] + self.theta[k] * (nodes.g[k] - upstream)
    }

    /// Reynolds' residual at interior node `i`: the flux into its finite volume minus the flux
    /// out.
    fn reynolds(&self, nodes: &Nodes, p: &[f64], i: usize) -> f64 {
        let x = &self.x;
        let east = 0.5 * (nodes.eps[i] + nodes.eps[i + 1]);
        let west = 0.5 * (nodes.eps[i - 1] + nodes.eps[i]);
        east * (p[i + 1] - p[i]) / (x[i + 1] - x[i])
            - west * (p[i] - p[i - 1]) / (x[i] - x[i - 1])
            - (self.couette(nodes, i) - self.couette(nodes, i - 1))
    }

    /// The residuals (interior nodes, then the load) and their sum of squares.
    fn residual(&self, p: &[f64], h0: f64, cavitated: &[bool]) -> (Vec<f64>, f64) {
        let n = self.last();
        let h = self.film(p, h0);
        let nodes = self.nodes(p, &h);
        let mut r = vec![0.0; n];
        for i in 1..n {
            r[i - 1] = if cavitated[i] {
                p[i]
            } else {
                self.reynolds(&nodes, p, i)
            };
        }
        r[n - 1] = self.load(p) - PI / 2.0;
        let merit = r.iter().map(|v| v * v).sum();
        (r, merit)
    }

    fn load(&self, p: &[f64]) -> f64 {
        self.weights.iter().zip(p).map(|(w, p)| w * p).sum()
    }

    /// The Jacobian of [`Self::residual`] with respect to the interior pressures and `H0`,
    /// row-major `n x n`.
    fn jacobian(&self, p: &[f64], h0: f64, cavitated: &[bool]) -> Vec<f64> {
        let nodes_count = self.x.len();
        let n = nodes_count - 1;
        let x = &self.x;
        let h = self.film(p, h0);
        let nodes = self.nodes(p, &h);
        let theta = &self.theta;
        let mut jacobian = vec![0.0; n * n];
        let column = |k: usize| (k >= 1 && k < n).then(|| k - 1);
        for i in 1..n {
            let row = &mut jacobian[(i - 1) * n..i * n];
            if cavitated[i] {
                row[i - 1] = 1.0;
                continue;
            }
            let (de, dw) = (x[i + 1] - x[i], x[i] - x[i - 1]);
            let east = 0.5 * (nodes.eps[i] + nodes.eps[i + 1]);
            let west = 0.5 * (nodes.eps[i - 1] + nodes.eps[i]);
            // ∂R/∂ε_k and ∂R/∂g_k, and the direct pressure terms.
            let by_eps = [
                (i - 1, -0.5 * (p[i] - p[i - 1]) / dw),
                (
                    i,
                    0.5 * (p[i + 1] - p[i]) / de - 0.5 * (p[i] - p[i - 1]) / dw,
                ),
                (i + 1, 0.5 * (p[i + 1] - p[i]) / de),
            ];
            let by_g = [
                (i, -(1.0 + theta[i])),
                (i - 1, theta[i] + 1.0 + theta[i - 1]),
                (
                    i.saturating_sub(2),
                    if i >= 2 { -theta[i - 1] } else { 0.0 },
                ),
            ];
            let direct = [
                (i - 1, west / dw),
                (i, -east / de - west / dw),
                (i + 1, east / de),
            ];
            for (k, v) in direct {
                if let Some(c) = column(k) {
                    row[c] += v;
                }
            }
            for (k, v) in by_eps {
                if let Some(c) = column(k) {
                    row[c] += v * nodes.eps_dp[k];
                }
            }
            for (k, v) in by_g {
                if let Some(c) = column(k) {
                    row[c] += v * nodes.g_dp[k];
                }
            }
            // Through the film: ∂H_k/∂P_j = -K_kj/π, ∂H_k/∂H0 = 1.
            let by_film = by_eps
                .iter()
                .map(|&(k, v)| (k, v * nodes.eps_dh[k]))
                .chain(by_g.iter().map(|&(k, v)| (k, v * nodes.g_dh[k])));
            let mut by_h0 = 0.0;
            for (k, c) in by_film {
                if c == 0.0 {
                    continue;
                }
                by_h0 += c;
                let kernel_row = &self.kernel[k * nodes_count + 1..k * nodes_count + n];
                let factor = -c / PI;
                for (v, kv) in row[..n - 1].iter_mut().zip(kernel_row) {
                    *v += factor * kv;
                }
            }
            row[n - 1] += by_h0;
        }
        let load_row = &mut jacobian[(n - 1) * n..n * n];
        load_row[..n - 1].copy_from_slice(&self.weights[1..n]);
        jacobian
    }
}

/// A state on one grid.
struct State {
    p: Vec<f64>,
    h0: f64,
    cavitated: Vec<bool>,
}

/// The outcome of Newton's method on one grid.
struct Outcome {
    iterations: usize,
    converged: bool,
}

/// Newton's method on `system` from `state`.
fn newton(system: &System, state: &mut State, max_iterations: usize) -> Outcome {
    let n = system.last();
    let mut release = 16usize;
    let mut optimistic: Vec<usize> = Vec::new();
    let mut released_any = false;
    for iteration in 0..max_iterations {
        let (residual, merit) = system.residual(&state.p, state.h0, &state.cavitated);
        let mut jacobian = system.jacobian(&state.p, state.h0, &state.cavitated);
        let mut step: Vec<f64> = residual.iter().map(|v| -v).collect();
        if !lu_solve(&mut jacobian, &mut step, n) || step.iter().any(|v| !v.is_finite()) {
            return Outcome {
                iterations: iteration + 1,
                converged: false,
            };
        }
        // Backtracking: the film must stay open and the residual fall (after a few halvings
        // the step is taken anyway, to leave a plateau).
        let mut omega = 1.0;
        for tries in 0.. {
            let trial: Vec<f64> = (0..=n)
                .map(|i| {
                    if i == 0 || i == n {
                        0.0
                    } else {
                        (state.p[i] + omega * step[i - 1]).max(0.0)
                    }
                })
                .collect();
            let h0 = state.h0 + omega * step[n - 1];
            let open = system.film(&trial, h0).iter().all(|&h| h > 0.0);
            let accept = open
                && (tries >= 8
                    || system.residual(&trial, h0, &state.cavitated).1
                        <= (1.0 - 1e-4 * omega) * merit);
            if accept || tries >= 12 {
                state.p = trial;
                state.h0 = h0;
                break;
            }
            omega *= 0.5;
        }
        // The cavitated set: negative pressures cavitate; a cavitated node whose film would
        // need pressure is freed, with up to `release` downstream neighbours when it borders
        // the pressurised film (halved when that overshoots, doubled when it does not).
        let h = system.film(&state.p, state.h0);
        let nodes = system.nodes(&state.p, &h);
        let mut changed = 0;
        if optimistic.iter().any(|&i| state.p[i] <= 0.0) {
            release = (release / 2).max(1);
        } else if released_any {
            release = (release * 2).min(64);
        }
        optimistic.clear();
        released_any = false;
        for i in 1..n {
            if state.p[i] <= 0.0 && !state.cavitated[i] {
                state.cavitated[i] = true;
                changed += 1;
            }
        }
        let mut i = 1;
        while i < n {
            if state.cavitated[i] && system.reynolds(&nodes, &state.p, i) > 0.0 {
                state.cavitated[i] = false;
                changed += 1;
                released_any = true;
                if !state.cavitated[i - 1] && state.p[i - 1] > 0.0 {
                    let mut k = i + 1;
                    while k < n && k < i + release && state.cavitated[k] {
                        state.cavitated[k] = false;
                        optimistic.push(k);
                        k += 1;
                    }
                    i = k;
                    continue;
                }
            }
            i += 1;
        }
        let largest = state.p.iter().copied().fold(0.0, f64::max);
        let change = step[..n - 1].iter().fold(0.0f64, |m, v| m.max(v.abs()));
        if change <= 1e-8 * largest && changed == 0 {
            return Outcome {
                iterations: iteration + 1,
                converged: true,
            };
        }
    }
    Outcome {
        iterations: max_iterations,
        converged: false,
    }
}

/// The solution on the finest grid, in Hertz's units.
struct Sequenced {
    x: Vec<f64>,
    p: Vec<f64>,
    h: Vec<f64>,
    iterations: usize,
    converged: bool,
    load: f64,
    inlet_clear: bool,
    outlet_clear: bool,
    lambda: f64,
    physics_ph: f64,
}

/// Grid sequencing: solves on grids of spacing `finest · 2^k` from the coarsest (at least
/// 0.02 b) to `finest`, each from the one before, the first from the Hertz pressure.
fn sequence(
    physics: &Physics,
    extent: Extent,
    finest: f64,
    moes_m: f64,
    hc_guess: f64,
    max_iterations: usize,
) -> Sequenced {
    // The coarsest grid still resolves the film: its deflection's discretisation error, of
    // the order of the spacing squared, stays well below the central film.
    let coarsest = (hc_guess.sqrt() / 8.0).clamp(finest, 0.02);
    let mut spacings = vec![finest];
    while *spacings.last().unwrap_or(&finest) * 2.0 <= coarsest * 1.0001 {
        let next = 2.0 * spacings.last().copied().unwrap_or(finest);
        spacings.push(next);
    }
    spacings.reverse();
    let mut iterations = 0;
    let mut previous: Option<(Vec<f64>, State)> = None;
    let mut converged = false;
    let mut last = None;
    for spacing in spacings {
        let system = System::new(
            physics,
            graded_grid(extent, spacing, moes_m, (2.0 * hc_guess).sqrt().max(1.0)),
        );
        let x = &system.x;
        let mut state = match previous.take() {
            None => {
                let p: Vec<f64> = x
                    .iter()
                    .enumerate()
                    .map(|(i, &v)| {
                        if i == 0 || i == x.len() - 1 {
                            0.0
                        } else {
                            (1.0 - v * v).max(0.0).sqrt()
                        }
                    })
                    .collect();
                State {
                    cavitated: vec![false; x.len()],
                    p,
                    // Under the Hertz pressure the film is H0 + 1/4 + ln 2 / 2 across the contact.
                    h0: hc_guess - 0.25 - 0.5 * 2f64.ln(),
                }
            }
            Some((coarse_x, coarse)) => {
                let p = interpolate(&coarse_x, &coarse.p, x);
                // Downstream of the pressure the film stays cavitated.
                let peak = p
                    .iter()
                    .enumerate()
                    .fold(
                        (0, 0.0),
                        |best, (i, &v)| if v > best.1 { (i, v) } else { best },
                    )
                    .0;
                let cavitated = p
                    .iter()
                    .enumerate()
                    .map(|(i, &v)| i > peak && v <= 0.0)
                    .collect();
                State {
                    p,
                    h0: coarse.h0,
                    cavitated,
                }
            }
        };
        let outcome = newton(&system, &mut state, max_iterations);
        iterations += outcome.iterations;
        converged = outcome.converged;
        let h = system.film(&state.p, state.h0);
        let load = system.load(&state.p);
        last = Some((system.x.clone(), state.p.clone(), h, load));
        previous = Some((system.x.clone(), state));
    }
    let (x, p, h, load) = last.unwrap_or_default();
    let largest = p.iter().copied().fold(0.0, f64::max);
    // The pressure must have ended (three zero nodes) before the outlet's end, and be
    // negligible over the inlet's first tenth.
    let n = p.len();
    let outlet_clear = n > 4 && p[n - 4..].iter().all(|&v| v == 0.0);
    let inlet_end = x.first().copied().unwrap_or(0.0) * 0.9;
    let inlet_clear = x
        .iter()
        .zip(&p)
        .filter(|(x, _)| **x < inlet_end)
        .all(|(_, &v)| v <= 1e-3 * largest);
    Sequenced {
        x,
        p,
        h,
        iterations,
        converged,
        load,
        inlet_clear,
        outlet_clear,
        lambda: physics.lambda,
        physics_ph: physics.ph,
    }
}

/// Linear interpolation of `(x, values)` at `at` (zero outside).
fn interpolate(x: &[f64], values: &[f64], at: &[f64]) -> Vec<f64> {
    at.iter()
        .map(|&v| {
            let k = x.partition_point(|&xi| xi <= v);
            if k == 0 || k >= x.len() {
                return if k > 0 && v == x[x.len() - 1] {
                    values[x.len() - 1]
                } else {
                    0.0
                };
            }
            let t = (v - x[k - 1]) / (x[k] - x[k - 1]);
            values[k - 1] + t * (values[k] - values[k - 1])
        })
        .collect()
}

impl Sequenced {
    fn into_solution(
        self,
        problem: &LineEhlProblem,
        moes_m: f64,
        moes_l: f64,
        spacing: f64,
        ends_clear: bool,
    ) -> LineEhl {
        let b = problem.half_width_m();
        let ph = self.physics_ph;
        let film_scale = b * b / problem.radius_m;
        let n = self.x.len();
        let physics = Physics {
            problem: *problem,
            ph,
            lambda: self.lambda,
        };
        // The centre's film, interpolated at X = 0.
        let central = interpolate(&self.x, &self.h, &[0.0])[0];
        let pressurised: Vec<usize> = (0..n).filter(|&i| self.p[i] > 0.0).collect();
        let first = pressurised.first().copied().unwrap_or(0);
        let last = pressurised.last().copied().unwrap_or(n - 1);
        let (min_i, _) = (first..=last).fold((first, f64::INFINITY), |best, i| {
            if self.h[i] < best.1 {
                (i, self.h[i])
            } else {
                best
            }
        });
        let (max_i, _) = (0..n).fold((0, f64::NEG_INFINITY), |best, i| {
            if self.p[i] > best.1 {
                (i, self.p[i])
            } else {
                best
            }
        });
        let spike = (1..n - 1).rev().find(|&i| {
            self.x[i] > 0.0
                && self.p[i] > self.p[i - 1]
                && self.p[i] >= self.p[i + 1]
                && self.p[i] > 0.0
        });
        // Mass flow ρ̄ (H - ε dP/dX) in Hertz's units, by central differences, times u b²/R.
        let flow = (0..n)
            .map(|i| {
                if i == 0 || i == n - 1 {
                    return f64::NAN;
                }
                let (ln_eta, _, rho, _) = physics.at(self.p[i]);
                let eps = rho * self.h[i].powi(3) * (-ln_eta).exp() / physics.lambda;
                let slope = (self.p[i + 1] - self.p[i - 1]) / (self.x[i + 1] - self.x[i - 1]);
                (rho * self.h[i] - eps * slope) * problem.entrainment_m_per_s * film_scale
            })
            .collect();
        LineEhl {
            x_m: self.x.iter().map(|x| x * b).collect(),
            pressure_pa: self.p.iter().map(|p| p * ph).collect(),
            film_m: self.h.iter().map(|h| h * film_scale).collect(),
            half_width_m: b,
            hertz_p0_pa: ph,
            central_film_m: central * film_scale,
            minimum_film_m: self.h[min_i] * film_scale,
            minimum_film_x_m: self.x[min_i] * b,
            max_pressure_pa: self.p[max_i] * ph,
            max_pressure_x_m: self.x[max_i] * b,
            spike_x_m: spike.map(|i| self.x[i] * b),
            spike_pressure_pa: spike.map(|i| self.p[i] * ph),
            cavitation_x_m: self.x[(last + 1).min(n - 1)] * b,
            moes_m,
            moes_l,
            iterations: self.iterations,
            converged: self.converged && ends_clear,
            load_error: (self.load / (PI / 2.0) - 1.0).abs(),
            flow_m2_per_s: flow,
            spacing_over_b: spacing,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lubrication::film::pan_hamrock;
    use crate::lubrication::viscosity::roelands_z_from_alpha;
    use approx::assert_relative_eq;

    /// A steel line contact with Hamrock's `G`, `U` and Moes' `M`: `E' = 230 GPa`, `R = 10 mm`,
    /// `η0 = 0.04 Pa s`, Roelands (with `α = G/E'`) and Dowson–Higginson, or Barus and a
    /// constant density.
    fn contact(g: f64, u: f64, m: f64, roelands: bool) -> LineEhlProblem {
        let e = 2.3e11;
        let r = 0.01;
        let eta0 = 0.04;
        let alpha = g / e;
        LineEhlProblem {
            load_n_per_m: m * (2.0 * u).sqrt() * e * r,
            radius_m: r,
            reduced_modulus_pa: e,
            viscosity_pa_s: eta0,
            entrainment_m_per_s: u * e * r / eta0,
            pressure_viscosity: if roelands {
                PressureViscosity::Roelands {
                    z: roelands_z_from_alpha(alpha, eta0).expect("oil"),
                }
            } else {
                PressureViscosity::Barus {
                    alpha_per_pa: alpha,
                }
            },
            compressibility: if roelands {
                Compressibility::DowsonHigginson
            } else {
                Compressibility::Incompressible
            },
        }
    }

    fn solved(problem: &LineEhlProblem) -> LineEhl {
        let solution = solve(problem, &LineEhlOptions::default()).expect("valid");
        assert!(solution.converged, "{problem:?}");
        solution
    }

    /// Under the Hertz pressure the film is flat across the contact: the influence
    /// coefficients integrate `ln|X - S| √(1 - S²)` to `(π/2)(X² - 1/2 - ln 2)` inside.
    #[test]
    fn the_hertz_pressure_flattens_the_gap() {
        let x: Vec<f64> = (0..=800)
            .map(|i| -2.0 + 4.0 * f64::from(i) / 800.0)
            .collect();
        let k = influence(&x);
        let nodes = x.len();
        let p: Vec<f64> = x.iter().map(|&v| (1.0 - v * v).max(0.0).sqrt()).collect();
        for (i, &xi) in x.iter().enumerate() {
            if xi.abs() > 0.9 {
                continue;
            }
            let integral: f64 = (1..nodes - 1).map(|j| k[i * nodes + j] * p[j]).sum();
            let exact = 0.5 * PI * (xi * xi - 0.5 - 2f64.ln());
            assert!(
                (integral - exact).abs() < 2e-4,
                "X = {xi}: {integral} vs {exact}"
            );
        }
    }

    #[test]
    fn lu_solves_a_system() {
        let n = 5;
        let a: Vec<f64> = (0..n * n)
            .map(|k| {
                if k % (n + 1) == 0 {
                    0.1
                } else {
                    ((k * 7) % 11) as f64 - 5.0
                }
            })
            .collect();
        let x: Vec<f64> = (0..n).map(|i| i as f64 - 1.5).collect();
        let mut b: Vec<f64> = (0..n)
            .map(|r| (0..n).map(|c| a[r * n + c] * x[c]).sum())
            .collect();
        let mut lu = a.clone();
        assert!(lu_solve(&mut lu, &mut b, n));
        for (solved, expected) in b.iter().zip(&x) {
            assert!((solved - expected).abs() < 1e-12);
        }
        let mut singular = vec![1.0; 4];
        assert!(!lu_solve(&mut singular, &mut [1.0, 2.0], 2));
    }

    /// Pan & Hamrock's films within 10 % at four loads, `M` 10 to 100, for a steel contact
    /// with `G = 4600` (`α = 20 GPa⁻¹`) at `U = 5e-12` (`L = 8.2`).
    #[test]
    fn films_agree_with_pan_hamrock() {
        for m in [10.0, 20.0, 50.0, 100.0] {
            let problem = contact(4600.0, 5e-12, m, true);
            let solution = solved(&problem);
            let formula = pan_hamrock(&problem.conditions(), problem.load_n_per_m);
            let central = solution.central_film_m / formula.central_m - 1.0;
            let minimum = solution.minimum_film_m / formula.minimum_m - 1.0;
            // The measured errors (docs/lubrication.md quotes them: --nocapture).
            println!(
                "Pan-Hamrock M {m} L {:.2}: central {central:+.4}, minimum {minimum:+.4}",
                solution.moes_l
            );
            assert!(central.abs() < 0.10, "M {m}: central {central:+.3}");
            assert!(minimum.abs() < 0.10, "M {m}: minimum {minimum:+.3}");
            // The load is carried.
            assert!(solution.load_error < 1e-9, "{}", solution.load_error);
        }
    }

    /// Moes' central film (a fit to numerical solutions with Barus viscosity and constant
    /// density) within 4 %, `M` 5 to 100 at `L = 10`.
    #[test]
    fn central_film_agrees_with_moes() {
        for m in [5.0, 20.0, 100.0] {
            let problem = contact(5000.0, (10.0f64 / 5000.0).powi(4) / 2.0, m, false);
            let solution = solved(&problem);
            let (mm, ll) = problem.moes();
            assert_relative_eq!(ll, 10.0, max_relative = 1e-9);
            let u = problem.conditions().speed_parameter();
            let moes = moes_line_central(mm, ll) * (2.0 * u).sqrt() * problem.radius_m;
            let error = solution.central_film_m / moes - 1.0;
            println!("Moes M {m} L 10: central {error:+.4}");
            assert!(error.abs() < 0.04, "M {m}: {error:+.4}");
        }
    }

    /// The film's shape: the minimum at the outlet, the spike just upstream of it, the film
    /// cavitating just beyond; the mass flow constant from the inlet to the spike.
    #[test]
    fn the_spike_and_the_minimum_film_sit_at_the_outlet() {
        let problem = contact(5000.0, 1e-11, 50.0, true);
        let solution = solved(&problem);
        let b = solution.half_width_m;
        let spike = solution.spike_x_m.expect("a spike") / b;
        let minimum = solution.minimum_film_x_m / b;
        assert!((0.85..1.0).contains(&spike), "spike at {spike} b");
        assert!(spike < minimum && minimum < 1.05, "minimum at {minimum} b");
        assert!(solution.cavitation_x_m / b > minimum);
        assert!(solution.minimum_film_m < solution.central_film_m);
        // The spike stands above the Hertz pressure there.
        let spike_p = solution.spike_pressure_pa.expect("a spike") / solution.hertz_p0_pa;
        assert!(spike_p > (1.0 - spike * spike).sqrt() + 0.05, "{spike_p}");
        // Mass flow: constant within 1 % from where the pressure rises to two nodes before
        // the spike (the pressure's gradient jumps at the spike, which central differences
        // do not resolve).
        let threshold = 0.05 * solution.max_pressure_pa;
        let before_spike = spike * b - 2.0 * solution.spacing_over_b * b;
        let flows: Vec<f64> = (0..solution.x_m.len())
            .filter(|&i| solution.pressure_pa[i] > threshold && solution.x_m[i] < before_spike)
            .map(|i| solution.flow_m2_per_s[i])
            .collect();
        let mean = flows.iter().sum::<f64>() / flows.len() as f64;
        let worst = flows
            .iter()
            .map(|q| (q / mean - 1.0).abs())
            .fold(0.0, f64::max);
        println!(
            "M 50: spike at {spike:.4} b ({spike_p:.4} p_h), minimum film at {minimum:.4} b, flow constant to {worst:.2e}"
        );
        assert!(worst < 0.01, "{worst}");
    }

    /// Halving the spacing changes the minimum film by less than 1 %.
    #[test]
    fn grid_independence() {
        let problem = contact(5000.0, 1e-11, 50.0, true);
        let default = solved(&problem);
        let finer = solve(
            &problem,
            &LineEhlOptions {
                spacing_over_b: Some(0.5 * default.spacing_over_b),
                ..LineEhlOptions::default()
            },
        )
        .expect("valid");
        assert!(finer.converged);
        let change = finer.minimum_film_m / default.minimum_film_m - 1.0;
        println!(
            "grid: spacing {} b -> {} b changes h_min by {change:+.5}",
            default.spacing_over_b, finer.spacing_over_b
        );
        assert!(change.abs() < 0.01, "{change}");
    }

    /// As the load grows (Moes' M), the pressure tends to Hertz's.
    #[test]
    fn heavy_loads_tend_to_the_hertz_pressure() {
        let departure = |m: f64| {
            let solution = solved(&contact(5000.0, 1e-11, m, true));
            let b = solution.half_width_m;
            solution
                .x_m
                .iter()
                .zip(&solution.pressure_pa)
                .filter(|(x, _)| (*x / b).abs() < 0.9)
                .map(|(x, p)| (p / solution.hertz_p0_pa - (1.0 - (x / b).powi(2)).sqrt()).abs())
                .fold(0.0, f64::max)
        };
        let (light, heavy) = (departure(10.0), departure(100.0));
        println!("largest |p/p_h - Hertz| over |x| < 0.9 b: M 10 {light:.4}, M 100 {heavy:.4}");
        assert!(heavy < 0.015 && heavy < light / 3.0, "{light} -> {heavy}");
    }

    #[test]
    fn non_convergence_and_bad_input_are_reported() {
        let problem = contact(5000.0, 1e-11, 20.0, true);
        let cut_short = solve(
            &problem,
            &LineEhlOptions {
                max_iterations: 2,
                ..LineEhlOptions::default()
            },
        )
        .expect("valid");
        assert!(!cut_short.converged);
        let mut bad = problem;
        bad.viscosity_pa_s = 0.0;
        assert!(solve(&bad, &LineEhlOptions::default()).is_err());
        bad = problem;
        bad.pressure_viscosity = PressureViscosity::Barus {
            alpha_per_pa: -1e-8,
        };
        assert!(solve(&bad, &LineEhlOptions::default()).is_err());
    }
}

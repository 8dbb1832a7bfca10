//! What the thermal figure draws, computed from a [`ThermalStudy`]: the xz sections under body
//! 1's hottest point (temperature; thermal, contact and total von Mises stress) at evenly
//! spaced depths, and body 1's maximum flash temperature against the Péclet number with its
//! two asymptotes.
//!
//! Asymptotes of the maximum temperature under the scene's pressure, `q = μ p V`:
//! - slow (`Pe -> 0`, point and elliptical contacts): the stationary temperature, linear in
//!   `V` (Carslaw & Jaeger 1959); a plane problem has none;
//! - fast (`Pe -> ∞`): each streamline heated like a semi-infinite body for its time under the
//!   contact (Jaeger 1942; Blok 1937), `θ(x) = (1/K) √(κ / (π V)) ∫_x^∞ q(x') / √(x' - x) dx'`
//!   along the rows (material enters at the leading edge, +x), growing as `√V`; integrated
//!   exactly over each cell.

use ndarray::Array2;

use super::thermal::{ThermalStudy, ThermalStudyError};
use crate::solution::dcfft::layer_stress;
use crate::thermal::kernel::CellGrid;
use crate::thermal::line::LineTemperature;
use crate::thermal::temperature::{TemperatureOperator, MAX_CELL_PECLET};

/// Depths of the sections: `0..=SECTION_DEPTH_OVER_A a` in this many steps.
pub const SECTION_STEPS: usize = 24;
/// The sections' depth, in units of `a`.
pub const SECTION_DEPTH_OVER_A: f64 = 1.2;

/// The figure's data.
#[derive(Clone, Debug, PartialEq)]
pub struct ThermalSections {
    /// The row of the sections (that of body 1's hottest point) and its y (m).
    pub row: usize,
    pub y_m: f64,
    /// Section depths (m), evenly spaced from 0.
    pub depths_m: Vec<f64>,
    /// `[depths, columns]`: body 1's temperature rise (K) under its share, the von Mises
    /// stress (Pa) of the thermal, contact and total stress, and their Tresca stress
    /// `σ1 - σ3` (Pa).
    pub temperature_k: Array2<f64>,
    pub thermal_von_mises_pa: Array2<f64>,
    pub contact_von_mises_pa: Array2<f64>,
    pub total_von_mises_pa: Array2<f64>,
    pub thermal_tresca_pa: Array2<f64>,
    pub contact_tresca_pa: Array2<f64>,
    pub total_tresca_pa: Array2<f64>,
    /// Body 1's maximum temperature rise (K) under the whole flux at the scene's pressure, at
    /// `(Pe, θ)` of body 1 for speeds around the scene's.
    pub sweep: Vec<(f64, f64)>,
    /// The slow asymptote's `θ / Pe` (None for a line contact) and the fast one's `θ / √Pe`.
    pub slow_per_peclet: Option<f64>,
    pub fast_per_root_peclet: f64,
}

/// Body 1's temperature under `flux` at depth `z` for `u = V/(2κ)`, on the study's grid.
fn temperature(
    study: &ThermalStudy,
    flux: &Array2<f64>,
    z: f64,
    u: f64,
) -> Result<Array2<f64>, ThermalStudyError> {
    let k = study.spec.body1.properties.conductivity_w_per_m_k;
    let [ny, nx] = study.shape;
    if study.line {
        let row: Vec<f64> = flux.row(ny / 2).to_vec();
        let t = LineTemperature::new(nx, study.spacing_m[0], z, u, k).apply(&row);
        Ok(Array2::from_shape_fn((ny, nx), |(_, c)| t[c]))
    } else {
        let grid = CellGrid {
            shape: study.shape,
            spacing_m: study.spacing_m,
        };
        Ok(TemperatureOperator::new(&grid, z, u, k)?.apply(flux.view())?)
    }
}

/// The fast asymptote's largest temperature per `1/√u` (K m^-1/2) of a body of conductivity
/// `K` under `flux` on cells `dx` long in x: `max over the grid of (1/K) √(1/(2π)) Σ q ∫
/// dx'/√(x' - x)`, so that `θ = value / √u`.
pub(super) fn fast_limit(flux: &Array2<f64>, dx: f64, conductivity_w_per_m_k: f64) -> f64 {
    let k = conductivity_w_per_m_k;
    let mut best: f64 = 0.0;
    for row in flux.rows() {
        for i in 0..row.len() {
            // Cell i from its centre forwards, then the cells ahead.
            let mut sum = row[i] * 2.0 * (0.5 * dx).sqrt();
            for (j, &q) in row.iter().enumerate().skip(i + 1) {
                if q != 0.0 {
                    let (x0, x1) = (
                        (j - i) as f64 * dx - 0.5 * dx,
                        (j - i) as f64 * dx + 0.5 * dx,
                    );
                    sum += q * 2.0 * (x1.sqrt() - x0.sqrt());
                }
            }
            best = best.max(sum);
        }
    }
    best / (k * (2.0 * std::f64::consts::PI).sqrt())
}

/// The sections and the speed sweep of `study` (`friction`, `poisson` of body 1; the
/// traction acts in the study's direction, [`crate::scene::TractionDirection`]).
/// `progress(done, total)` after each depth.
pub fn sections(
    study: &ThermalStudy,
    friction: f64,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<ThermalSections, ThermalStudyError> {
    let a = study.half_width_m;
    let [ny, nx] = study.shape;
    let [dx, dy] = study.spacing_m;
    let row = if study.line {
        ny / 2
    } else {
        ((study.body1.max_at_m[1] - study.origin_m[1]) / dy)
            .round()
            .clamp(0.0, (ny - 1) as f64) as usize
    };
    let body1 = &study.spec.body1;
    let u1 = super::thermal::inverse_length(body1);
    let share = study.body1.share;
    let flux1 = study.flux_w_per_m2.mapv(|q| q * share);
    let speed = study.spec.sliding_speed_m_per_s;
    let poisson = body1.material.poisson;
    let contact_operator = super::thermal::contact_operator(
        &study.pressure_pa,
        study.spacing_m,
        a,
        friction * study.spec.traction.sign(),
        poisson,
    )?;
    let grid = CellGrid {
        shape: study.shape,
        spacing_m: study.spacing_m,
    };
    let e_alpha_over_k = super::thermal::e_alpha_over_k(body1);
    let depths_m: Vec<f64> = (0..=SECTION_STEPS)
        .map(|k| SECTION_DEPTH_OVER_A * a * k as f64 / SECTION_STEPS as f64)
        .collect();
    let rows = depths_m.len();
    let mut out = [
        Array2::zeros((rows, nx)),
        Array2::zeros((rows, nx)),
        Array2::zeros((rows, nx)),
        Array2::zeros((rows, nx)),
        Array2::zeros((rows, nx)),
        Array2::zeros((rows, nx)),
        Array2::zeros((rows, nx)),
    ];
    for (k, &z) in depths_m.iter().enumerate() {
        let t = temperature(study, &flux1, z, u1)?;
        let thermal = super::thermal::thermal_stress_layer(
            &grid,
            study.line,
            z,
            u1,
            poisson,
            e_alpha_over_k,
            &flux1,
        )?;
        let contact = contact_operator.layer(z / a)?;
        for column in 0..nx {
            let th = layer_stress(&thermal.view(), row, column);
            let co = layer_stress(&contact.view(), row, column);
            out[0][[k, column]] = t[[row, column]];
            out[1][[k, column]] = th.von_mises();
            out[2][[k, column]] = co.von_mises();
            let total = th + co;
            out[3][[k, column]] = total.von_mises();
            out[4][[k, column]] = 2.0 * th.max_shear();
            out[5][[k, column]] = 2.0 * co.max_shear();
            out[6][[k, column]] = 2.0 * total.max_shear();
        }
        progress(k + 1, rows);
    }
    // The speed sweep: Pe of body 1 from 0.1 to 100 (as far as the grid resolves), the flux
    // scaled with the speed.
    let diffusivity = body1.properties.diffusivity_m2_per_s;
    let whole = &study.flux_w_per_m2;
    let max_peclet = (MAX_CELL_PECLET * a / dx).min(100.0);
    let mut sweep = Vec::new();
    let mut pe: f64 = 0.1;
    while pe <= max_peclet * (1.0 + 1e-9) {
        let u = pe / a;
        let v = 2.0 * diffusivity * u;
        let flux = whole.mapv(|q| q * v / speed);
        let t = temperature(study, &flux, 0.0, u)?;
        let max = t.iter().fold(f64::NEG_INFINITY, |m, &v| m.max(v));
        sweep.push((pe, max));
        pe *= 10f64.powf(0.25);
    }
    // Asymptotes per unit Pe (slow) and per √Pe (fast), with q ∝ V = 2κ Pe / a.
    let per_speed = |pe: f64| 2.0 * diffusivity * pe / a / speed;
    let slow_per_peclet = if study.line {
        None
    } else {
        let t = temperature(study, whole, 0.0, 0.0)?;
        Some(t.iter().fold(f64::NEG_INFINITY, |m, &v| m.max(v)) * per_speed(1.0))
    };
    // θ_fast = fast_limit(q) / √u with q scaled by V/speed: per √Pe, u = Pe/a.
    let fast_per_root_peclet = fast_limit(
        &study.flux_w_per_m2,
        dx,
        body1.properties.conductivity_w_per_m_k,
    ) * per_speed(1.0)
        * a.sqrt();
    Ok(ThermalSections {
        row,
        y_m: study.origin_m[1] + row as f64 * dy,
        depths_m,
        temperature_k: out[0].clone(),
        thermal_von_mises_pa: out[1].clone(),
        contact_von_mises_pa: out[2].clone(),
        total_von_mises_pa: out[3].clone(),
        thermal_tresca_pa: out[4].clone(),
        contact_tresca_pa: out[5].clone(),
        total_tresca_pa: out[6].clone(),
        sweep,
        slow_per_peclet,
        fast_per_root_peclet,
    })
}

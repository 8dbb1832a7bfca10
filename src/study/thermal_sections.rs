//! What the heating sheet draws, computed from a [`ThermalStudy`]: the xz section of the
//! temperature under body 1's hottest point, the sections of the thermal, contact and total
//! von Mises stress and maximum shear through the report's total von Mises maximum (its row,
//! and its depth among the section's depths), evaluated by the study's own
//! [`HeatedStress`], and body 1's maximum flash temperature against its Péclet number under
//! the scene's flux, with two asymptotes.
//!
//! Asymptotes of the maximum temperature under the scene's flux `q = μ p Vs` (fixed) as body
//! 1's speed, so its Péclet number, varies:
//! - slow (`Pe -> 0`, point and elliptical contacts): the stationary temperature (Carslaw &
//!   Jaeger 1959), a constant; a plane problem has none;
//! - fast (`Pe -> ∞`): each streamline heated like a semi-infinite body for its time under the
//!   contact (Jaeger 1942; Blok 1937), `θ(x) = (1/K) √(κ / (π V)) ∫_x^∞ q(x') / √(x' - x) dx'`
//!   along the rows (material enters at the leading edge, +x), falling as `1/√Pe`; integrated
//!   exactly over each cell.

use ndarray::Array2;

use super::heated_stress::{
    HeatedStress, CONTACT_MAX_SHEAR, CONTACT_VON_MISES, THERMAL_VON_MISES, TOTAL_MAX_SHEAR,
    TOTAL_VON_MISES,
};
use super::thermal::{ThermalStudy, ThermalStudyError};
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
    /// The row of the stress sections (that of the total von Mises maximum) and its y (m).
    pub row: usize,
    pub y_m: f64,
    /// The row of the temperature section (body 1's hottest point) and its y (m).
    pub temperature_row: usize,
    pub temperature_y_m: f64,
    /// Section depths (m), evenly spaced from 0.
    pub depths_m: Vec<f64>,
    /// The grid column of the sections' first sample, and the x (m) of their first and last
    /// (the whole grid, or a window four times as wide as the sections are deep, centred on
    /// the total's maximum, where they are shallow against it: a rough contact's).
    pub first_column: usize,
    pub x_m: [f64; 2],
    /// `[depths, columns]`: body 1's temperature rise (K) under its share, the von Mises
    /// stress (Pa) of the thermal, contact and total stress, and their maximum (Tresca) shear
    /// `(σ1 − σ3)/2` (Pa).
    pub temperature_k: Array2<f64>,
    pub thermal_von_mises_pa: Array2<f64>,
    pub contact_von_mises_pa: Array2<f64>,
    pub total_von_mises_pa: Array2<f64>,
    pub thermal_max_shear_pa: Array2<f64>,
    pub contact_max_shear_pa: Array2<f64>,
    pub total_max_shear_pa: Array2<f64>,
    /// Body 1's maximum temperature rise (K) under the scene's whole flux (`q = μ p Vs` at
    /// its sliding speed, all into body 1) as `(Pe, θ)` for body 1's Péclet number from 0.1
    /// to 100.
    pub sweep: Vec<(f64, f64)>,
    /// The asymptotes under the same flux: the stationary temperature (K; none for a line
    /// contact) and the fast limit's `θ √Pe` (K).
    pub stationary_k: Option<f64>,
    pub fast_times_root_peclet: f64,
    /// The scene's body 1 under the whole flux (its maximum over its share; None when it
    /// takes none), at its Péclet number (0: a stationary source, the stationary limit).
    pub scene_k: Option<f64>,
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

/// The depths of the sections: from 0 to `depth` in about [`SECTION_STEPS`] even steps, the
/// step chosen so that `exact` (the reported maximum's depth) is one of them when it lies in
/// `(0, depth]`.
pub(crate) fn section_depths(depth: f64, exact: f64) -> Vec<f64> {
    let nominal = depth / SECTION_STEPS as f64;
    let step = if exact > 0.0 && exact <= depth {
        exact / (exact / nominal).round().max(1.0)
    } else {
        nominal
    };
    let count = (depth / step - 1e-9).ceil().max(1.0) as usize;
    (0..=count).map(|k| k as f64 * step).collect()
}

/// The sections and the speed sweep of `study`, through the report's maxima: the stress
/// sections in the row of the total von Mises maximum, at depths that include its depth
/// ([`section_depths`]), evaluated by the study's own [`HeatedStress`] (so every value the
/// report states at a point of the section is the section's); the temperature section under
/// body 1's hottest point. `progress(done, total)` after each depth.
pub fn sections(
    study: &ThermalStudy,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<ThermalSections, ThermalStudyError> {
    let a = study.half_width_m;
    let [ny, nx] = study.shape;
    let [dx, dy] = study.spacing_m;
    let hot_row = if study.line {
        ny / 2
    } else {
        ((study.body1.max_at_m[1] - study.origin_m[1]) / dy)
            .round()
            .clamp(0.0, (ny - 1) as f64) as usize
    };
    let stress = HeatedStress::of_study(study)?;
    let row = stress.row_of(study.total_von_mises.y_m);
    let body1 = &study.spec.body1;
    let u1 = super::thermal::inverse_length(body1);
    let share = study.body1.share;
    let flux1 = study.flux_w_per_m2.mapv(|q| q * share);
    let depths_m = section_depths(study.section_depth_m, study.total_von_mises.depth_m);
    let rows = depths_m.len();
    // Along x: the whole grid, or, where the sections are shallow against it (a rough
    // contact's), a window four times as wide as deep centred on the total's maximum.
    let count = ((4.0 * study.section_depth_m / dx).round() as usize).clamp(1, nx);
    let centre = ((study.total_von_mises.x_m - study.origin_m[0]) / dx).round() as isize;
    let first_column = (centre - (count / 2) as isize).clamp(0, (nx - count) as isize) as usize;
    let mut out: [Array2<f64>; 7] = std::array::from_fn(|_| Array2::zeros((rows, count)));
    for (k, &z) in depths_m.iter().enumerate() {
        let t = temperature(study, &flux1, z, u1)?;
        let layer = stress.layer(z)?;
        let values = stress.row_values(&layer, row);
        let thermal_shear = stress.thermal_max_shear_row(&layer, row);
        for i in 0..count {
            let column = first_column + i;
            out[0][[k, i]] = t[[hot_row, column]];
            out[1][[k, i]] = values[THERMAL_VON_MISES][column];
            out[2][[k, i]] = values[CONTACT_VON_MISES][column];
            out[3][[k, i]] = values[TOTAL_VON_MISES][column];
            out[4][[k, i]] = thermal_shear[column];
            out[5][[k, i]] = values[CONTACT_MAX_SHEAR][column];
            out[6][[k, i]] = values[TOTAL_MAX_SHEAR][column];
        }
        progress(k + 1, rows);
    }
    let y_m = stress.y_m(row);
    // The speed sweep: body 1's Péclet number from 0.1 to 100 (as far as the grid resolves)
    // under the scene's own flux (q = μ p Vs at the scene's sliding speed), all into body 1:
    // the scene's body 1 lies on it at its own Pe, whatever the sliding speed.
    let whole = &study.flux_w_per_m2;
    let max_peclet = (MAX_CELL_PECLET * a / dx).min(100.0);
    let mut sweep = Vec::new();
    let mut pe: f64 = 0.1;
    while pe <= max_peclet * (1.0 + 1e-9) {
        let t = temperature(study, whole, 0.0, pe / a)?;
        let max = t.iter().fold(f64::NEG_INFINITY, |m, &v| m.max(v));
        sweep.push((pe, max));
        pe *= 10f64.powf(0.25);
    }
    let stationary_k = if study.line {
        None
    } else {
        let t = temperature(study, whole, 0.0, 0.0)?;
        Some(t.iter().fold(f64::NEG_INFINITY, |m, &v| m.max(v)))
    };
    // θ_fast = fast_limit(q) / √u, u = Pe/a.
    let fast_times_root_peclet =
        fast_limit(whole, dx, body1.properties.conductivity_w_per_m_k) * a.sqrt();
    // The scene's body 1 under the whole flux (its share undone).
    let scene_k =
        (study.body1.share > 0.0).then(|| study.body1.max_temperature_rise_k / study.body1.share);
    Ok(ThermalSections {
        row,
        y_m,
        temperature_row: hot_row,
        temperature_y_m: if study.line {
            0.0
        } else {
            study.origin_m[1] + hot_row as f64 * dy
        },
        depths_m,
        first_column,
        x_m: [
            study.origin_m[0] + first_column as f64 * dx,
            study.origin_m[0] + (first_column + count - 1) as f64 * dx,
        ],
        temperature_k: out[0].clone(),
        thermal_von_mises_pa: out[1].clone(),
        contact_von_mises_pa: out[2].clone(),
        total_von_mises_pa: out[3].clone(),
        thermal_max_shear_pa: out[4].clone(),
        contact_max_shear_pa: out[5].clone(),
        total_max_shear_pa: out[6].clone(),
        sweep,
        stationary_k,
        fast_times_root_peclet,
        scene_k,
    })
}

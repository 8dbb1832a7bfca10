//! The history of a `[plasticity]` point contact, step by step: the curves a sheet and a
//! recording draw (load, approach, pressures, contact radius) and a light section of each
//! step through the axis (the pressure, the plastic strain and von Mises on `y = 0`), kept
//! while solving instead of whole 3-D snapshots.

use ndarray::{Array2, Array3, Array4};

use crate::contact::PointContact;
use crate::plasticity::j2::von_mises;
use crate::plasticity::loading::StepState;

/// One step of the loading history.
#[derive(Clone, Debug, PartialEq)]
pub struct StepPoint {
    pub load_n: f64,
    /// From the first contact of the undeformed bodies; `None` when lifted off.
    pub approach_m: Option<f64>,
    pub max_pressure_pa: f64,
    /// The load over the contact area (0 without contact).
    pub mean_pressure_pa: f64,
    /// `√(A/π)`, `A` the area of the cells in contact; a line's half-width (`A` its width
    /// times 1 m).
    pub contact_radius_m: f64,
    pub max_plastic_strain: f64,
    /// The plastic surface displacement on the axis (m, into body 1).
    pub axis_displacement_m: f64,
    /// Whether the step lowers the load (the unloading).
    pub unloading: bool,
}

/// A step's xz section through the axis (`y = 0`, the volume's middle row of cells).
#[derive(Clone, Debug, PartialEq)]
pub struct StepSection {
    /// The pressure along x (Pa, `nx`).
    pub pressure_pa: Vec<f64>,
    /// The equivalent plastic strain (`[nz, nx]`).
    pub plastic_strain: Array2<f64>,
    /// The von Mises stress of the total stress (Pa, `[nz, nx]`).
    pub von_mises_pa: Array2<f64>,
}

/// Every step's point and section, in the order solved.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StepHistory {
    pub points: Vec<StepPoint>,
    pub sections: Vec<StepSection>,
}

impl StepHistory {
    /// Records the state at the end of a step; `cell_area_m2` the area of a surface cell,
    /// `row` the volume's row on the axis (`y = 0`), `line` whether the contact is a line
    /// (one row 1 m wide).
    pub fn push(&mut self, state: &StepState, cell_area_m2: f64, row: usize, line: bool) {
        let result = state.result;
        let area = result.contact_cells as f64 * cell_area_m2;
        let unloading = self
            .points
            .last()
            .is_some_and(|previous| result.load_n < previous.load_n);
        self.points.push(StepPoint {
            load_n: result.load_n,
            approach_m: result.approach_m,
            max_pressure_pa: result.max_pressure_pa,
            mean_pressure_pa: if area > 0.0 {
                result.load_n / area
            } else {
                0.0
            },
            contact_radius_m: if line {
                area / (2.0 * super::line::ROW_WIDTH_M)
            } else {
                (area / std::f64::consts::PI).sqrt()
            },
            max_plastic_strain: result.max_plastic_strain,
            axis_displacement_m: result.axis_displacement_m,
            unloading,
        });
        self.sections.push(section(
            state.pressure_pa,
            state.stress_pa,
            state.equivalent_plastic_strain,
            row,
        ));
    }
}

/// The section on row `row` of a state's pressure (`[ny, nx]`), stress (`[nz, 6, ny, nx]`)
/// and equivalent plastic strain (`[nz, ny, nx]`).
pub fn section(
    pressure_pa: &Array2<f64>,
    stress_pa: &Array4<f64>,
    plastic_strain: &Array3<f64>,
    row: usize,
) -> StepSection {
    let (nz, _, _, nx) = stress_pa.dim();
    StepSection {
        pressure_pa: pressure_pa.row(row).to_vec(),
        plastic_strain: Array2::from_shape_fn((nz, nx), |(l, i)| plastic_strain[[l, row, i]]),
        von_mises_pa: Array2::from_shape_fn((nz, nx), |(l, i)| {
            let s: [f64; 6] = std::array::from_fn(|c| stress_pa[[l, c, row, i]]);
            von_mises(&s)
        }),
    }
}

/// What the sheet draws in the section `y = 0`, from the loaded and unloaded snapshots.
#[derive(Clone, Debug, PartialEq)]
pub struct SheetSections {
    /// At full load: pressure, plastic strain, von Mises of the total stress.
    pub loaded: StepSection,
    /// The current yield stress `Y + h εp` at full load (Pa, `[nz, nx]`).
    pub loaded_yield_stress_pa: Array2<f64>,
    /// After unloading: the pressure (zero), the accumulated plastic strain and von Mises of
    /// the residual stress; `None` without unloading.
    pub unloaded: Option<StepSection>,
    /// The residual `σxx` (radial on `y = 0`) and `σyy` (hoop) after unloading (Pa, `[nz, nx]`).
    pub residual_xx_pa: Option<Array2<f64>>,
    pub residual_yy_pa: Option<Array2<f64>>,
}

/// The sheet's sections of `study` (module doc).
pub fn sheet_sections(study: &super::PlasticStudy) -> SheetSections {
    let row = study.y_m.len() / 2;
    let loaded_state = study.loaded_snapshot();
    let loaded = section(
        &loaded_state.pressure_pa,
        &loaded_state.stress_pa,
        &loaded_state.equivalent_plastic_strain,
        row,
    );
    let h = study.spec.hardening_modulus_pa;
    let loaded_yield_stress_pa = loaded
        .plastic_strain
        .mapv(|k| study.spec.yield_strength_pa + h * k);
    let unloaded_state = study.unloaded_snapshot();
    SheetSections {
        loaded,
        loaded_yield_stress_pa,
        unloaded: unloaded_state.map(|s| {
            section(
                &s.pressure_pa,
                &s.stress_pa,
                &s.equivalent_plastic_strain,
                row,
            )
        }),
        residual_xx_pa: unloaded_state.map(|s| component_section(&s.stress_pa, 0, row)),
        residual_yy_pa: unloaded_state.map(|s| component_section(&s.stress_pa, 1, row)),
    }
}

/// One stress component (`0..6`: xx, yy, zz, yz, xz, xy as stored) of a `[nz, 6, ny, nx]`
/// stress on row `row`, `[nz, nx]`.
pub fn component_section(stress_pa: &Array4<f64>, component: usize, row: usize) -> Array2<f64> {
    let (nz, _, _, nx) = stress_pa.dim();
    Array2::from_shape_fn((nz, nx), |(l, i)| stress_pa[[l, component, row, i]])
}

/// The largest von Mises stress over `p0` on the axis of Hertz's sphere for Poisson's ratio
/// `nu` (Hamilton's closed form sampled every 1e-4 a from 0.2 a to 0.8 a, where the maximum
/// lies for `0 <= ν <= 0.5`): 0.6200 for ν = 0.3, the `hertz` report's value.
///
/// ## Reference
/// G. M. Hamilton, Explicit equations for the stresses beneath a sliding spherical contact,
/// *Proc. Instn Mech. Engrs* 197C (1983) 53–59; Johnson (1985) §6.2 (p0 = 1.60 Y at first
/// yield for ν = 0.3).
pub fn axis_von_mises_max_over_p0(nu: f64) -> f64 {
    (2000..=8000)
        .map(|k| {
            crate::solution::sphere_hertz::stress_over_p0(0.0, 0.0, k as f64 * 1e-4, 0.0, nu)
                .von_mises()
        })
        .fold(0.0, f64::max)
}

/// The load (N) at which the elastic contact `hertz` first yields in body 1 (Poisson's ratio
/// `nu`, yield strength `yield_pa`): Hertz's `p0` reaches `Y / (σvM,max / p0)`, and the load
/// scales as `p0³`.
pub fn first_yield_load_n(hertz: &PointContact, nu: f64, yield_pa: f64) -> f64 {
    hertz.load_for_peak_pressure(yield_pa / axis_von_mises_max_over_p0(nu))
}

/// The largest von Mises stress over `p0` on the axis of Hertz's line contact in plane strain
/// for Poisson's ratio `nu`: on the axis `σxx = -p0 ((1 + 2ζ²)/√(1 + ζ²) - 2ζ)`,
/// `σzz = -p0/√(1 + ζ²)`, `σyy = ν (σxx + σzz)`, no shear (`ζ = z/b`; McEwen's field, Johnson
/// 1985 eq. 4.50 with §7.2's plane strain), sampled every 1e-4 b from 0.3 b to 1.2 b: 0.5575
/// at 0.70 b for ν = 0.3 (Johnson 1985 §6.2).
pub fn line_axis_von_mises_max_over_p0(nu: f64) -> f64 {
    (3000..=12000)
        .map(|k| {
            let zeta = k as f64 * 1e-4;
            let root = (1.0 + zeta * zeta).sqrt();
            let xx = -((1.0 + 2.0 * zeta * zeta) / root - 2.0 * zeta);
            let zz = -1.0 / root;
            let yy = nu * (xx + zz);
            von_mises(&[xx, yy, zz, 0.0, 0.0, 0.0])
        })
        .fold(0.0, f64::max)
}

/// The load and approach of the elastic contact of a plastic study at first yield of body 1
/// (`W_Y`, `δ_Y`): a point contact's `p0 = Y / 0.620` (ν = 0.3; [`first_yield_load_n`]),
/// a line's `p0 = Y / 0.5575` ([`line_axis_von_mises_max_over_p0`]; the load scales as
/// `p0²`), the approach from [`elastic_approach_m`].
pub fn first_yield(study: &super::PlasticStudy) -> (f64, f64) {
    let nu = study.spec.body1.poisson;
    let y = study.spec.yield_strength_pa;
    let load = match &study.hertz {
        super::ElasticHertz::Point(hertz) => first_yield_load_n(hertz, nu, y),
        super::ElasticHertz::Line(hertz) => {
            let p0 = y / line_axis_von_mises_max_over_p0(nu);
            hertz.load_n_per_m * (p0 / hertz.p0_pa).powi(2)
        }
    };
    (load, elastic_approach_m(study, load))
}

/// The approach of the elastic (Hertz) contact of a plastic study at the load `load` (N, or
/// N/m for a line): a circle's `δ_H (W/W_H)^(2/3)` (Johnson 1985 §4.2); a line's the approach
/// the line study reports, that of the points at the grid's depth `D` below each surface on
/// the axis, `(p0/E) [(1 - ν²) b asinh(D/b) - ν(1 + ν)(D √(b² + D²) - D²)/b]` for each elastic
/// body (the axis stresses of McEwen's field integrated, [`crate::plasticity::line`]), with
/// `b` and `p0` growing as `√W`.
pub fn elastic_approach_m(study: &super::PlasticStudy, load: f64) -> f64 {
    match &study.hertz {
        super::ElasticHertz::Point(hertz) => {
            hertz.approach_m * (load / hertz.load_n).powf(2.0 / 3.0)
        }
        super::ElasticHertz::Line(hertz) => {
            let scale = (load / hertz.load_n_per_m).max(0.0).sqrt();
            let (b, p0) = (hertz.half_width_m * scale, hertz.p0_pa * scale);
            if b <= 0.0 {
                return 0.0;
            }
            let d = study.grid.depth.depth_m();
            let body = |modulus: f64, nu: f64| {
                p0 / modulus
                    * ((1.0 - nu * nu) * b * (d / b).asinh()
                        - nu * (1.0 + nu) * (d * (b * b + d * d).sqrt() - d * d) / b)
            };
            let body1 = study.spec.body1;
            let mut approach = body(body1.modulus_pa, body1.poisson);
            if let Some((modulus, nu)) = study.counter {
                approach += body(modulus, nu);
            }
            approach
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_line_axis_maximum_is_johnson_s_0_5575_for_nu_0_3() {
        let ratio = line_axis_von_mises_max_over_p0(0.3);
        assert!((ratio - 0.5575).abs() < 1e-4, "{ratio}");
    }

    #[test]
    fn the_axis_maximum_is_johnson_s_0_62_for_nu_0_3() {
        // Johnson (1985) §6.2: 0.62 p0 at 0.48 a for ν = 0.3 (to its printed digits).
        let ratio = axis_von_mises_max_over_p0(0.3);
        assert!((ratio - 0.62).abs() < 5e-4, "{ratio}");
    }
}

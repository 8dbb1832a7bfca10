//! The stress in body 1 of a heated contact, and its maxima, computed once for the heating
//! report and the heating sheet: the thermal stress of body 1's share of the flux (on the
//! study's cells, [`super::thermal::thermal_stress_layer`]) plus the contact stress.
//!
//! The contact stress is the exact closed form where there is one (a Hertz line contact:
//! McEwen 1949; a sphere: Hamilton 1983), scaled by `p0` and `a`, so that the heating's
//! "contact alone" is `hertz`'s and the total's contact part carries no discretisation
//! error; otherwise (elliptical contacts, a coupled contact's heated pressure, rough
//! contacts) the DC-FFT layers of the gridded pressure (a rough contact: the tractions of
//! `contact`, periodic when the contact is, [`super::rough::tractions`]).
//!
//! ## The search
//! The maxima are searched over the cell centres of layers at coarse depths and refined in
//! depth: [`super::heated_search`].
//!
//! ## References
//! - E. McEwen, *Phil. Mag.* 40 (1949) 454–459; G. M. Hamilton, *Proc. Instn Mech. Engrs*
//!   197C (1983) 53–59 (the closed forms, [`crate::solution`]).
//! - E. Catmull, R. Rom, in *Computer Aided Geometric Design*, Academic Press (1974)
//!   317–326 (the interpolating cubic).

use ndarray::{Array2, Array3};
use rayon::prelude::*;

use super::rough::{REFERENCE_LENGTH_M, REFERENCE_PRESSURE_PA};
use super::thermal::{ContactModel, ThermalStudy, ThermalStudyError};
use crate::scene::ThermalSpec;
use crate::solution::dcfft::{layer_stress, DcFft, TractionGrid};
use crate::solution::point_numerical::PointTractions;
use crate::solution::Solution;
use crate::stress::Stress;
use crate::thermal::kernel::CellGrid;

/// One row's part of [`HeatedStress::layer_best`]'s scan: its von Mises bests and cells.
struct RowScan {
    best: [(f64, usize, usize); QUANTITIES],
    total_cells: Vec<(f64, usize, usize)>,
    contact_cells: Vec<(f64, usize, usize)>,
}

/// The depth tolerance of the refined maxima of a Hertz contact, in units of `a`.
pub const DEPTH_TOLERANCE_OVER_A: f64 = 1.0 / 400.0;

/// The contact stress of a heating study.
pub(crate) enum ContactPart {
    /// A closed form (units of `p0` and `a`), scaled to Pa and m; `y` of the grid measured
    /// from the contact's centre.
    ClosedForm {
        solution: Solution,
        p0_pa: f64,
        half_width_m: f64,
    },
    /// DC-FFT layers on the study's cells, in units of `length_m` (depth) and `pressure_pa`.
    Layers {
        fft: Layers,
        length_m: f64,
        pressure_pa: f64,
    },
}

/// The DC-FFT operator of a gridded contact: its own, or a rough contact's tractions'.
pub(crate) enum Layers {
    Own(Box<DcFft>),
    Tractions(Box<PointTractions>),
}

impl Layers {
    fn fft(&self) -> &DcFft {
        match self {
            Layers::Own(fft) => fft,
            Layers::Tractions(tractions) => tractions.dcfft(),
        }
    }
}

/// Body 1's stress under a heated contact.
pub(crate) struct HeatedStress {
    pub(crate) grid: CellGrid,
    /// The centre of cell `[0, 0]`, m from the contact's centre.
    pub(crate) origin_m: [f64; 2],
    /// A line contact: every row is the middle one.
    pub(crate) line: bool,
    pub(crate) u1: f64,
    pub(crate) poisson: f64,
    pub(crate) e_alpha_over_k: f64,
    /// Body 1's share of the flux, W/m².
    pub(crate) body1_flux: Array2<f64>,
    pub(crate) contact: ContactPart,
}

/// One depth of [`HeatedStress`]: the thermal stress `[6, ny, nx]` (Pa) and, unless the
/// contact is a closed form, the contact's layer (in its units).
pub(crate) struct StressLayer {
    pub(crate) depth_m: f64,
    pub(crate) thermal: Array3<f64>,
    pub(crate) contact: Option<Array3<f64>>,
}

/// The quantities searched, in this order.
pub(crate) const THERMAL_VON_MISES: usize = 0;
pub(crate) const CONTACT_VON_MISES: usize = 1;
pub(crate) const TOTAL_VON_MISES: usize = 2;
pub(crate) const CONTACT_MAX_SHEAR: usize = 3;
pub(crate) const TOTAL_MAX_SHEAR: usize = 4;
pub(crate) const QUANTITIES: usize = 5;

/// The value of quantity `k` from the thermal and the contact stress.
pub(crate) fn measure(k: usize, thermal: &Stress, contact: &Stress) -> f64 {
    match k {
        THERMAL_VON_MISES => thermal.von_mises(),
        CONTACT_VON_MISES => contact.von_mises(),
        TOTAL_VON_MISES => (*thermal + *contact).von_mises(),
        CONTACT_MAX_SHEAR => contact.max_shear(),
        _ => (*thermal + *contact).max_shear(),
    }
}

/// What [`HeatedStress::new`] is built from (a study's grid and heat).
pub(crate) struct Parts<'a> {
    pub(crate) shape: [usize; 2],
    pub(crate) spacing_m: [f64; 2],
    pub(crate) origin_m: [f64; 2],
    pub(crate) half_width_m: f64,
    pub(crate) line: bool,
    pub(crate) pressure_pa: &'a Array2<f64>,
    /// The whole frictional flux (W/m²) and body 1's share of it.
    pub(crate) flux_w_per_m2: &'a Array2<f64>,
    pub(crate) share: f64,
}

impl HeatedStress {
    /// Body 1's stress of a heated contact: the thermal stress of its share of the flux, the
    /// contact stress of `model` with `signed_friction` (negative: in −x).
    pub(crate) fn new(
        parts: &Parts,
        spec: &ThermalSpec,
        model: &ContactModel,
        signed_friction: f64,
    ) -> Result<Self, ThermalStudyError> {
        let poisson = spec.body1.material.poisson;
        let a = parts.half_width_m;
        let contact = match model {
            ContactModel::ClosedForm { solution, p0_pa } => ContactPart::ClosedForm {
                solution: solution.clone(),
                p0_pa: *p0_pa,
                half_width_m: a,
            },
            ContactModel::Gridded => ContactPart::Layers {
                fft: Layers::Own(Box::new(super::thermal::contact_operator(
                    parts.pressure_pa,
                    parts.spacing_m,
                    a,
                    signed_friction,
                    poisson,
                )?)),
                length_m: a,
                pressure_pa: 1.0,
            },
            ContactModel::Rough { periodic } => {
                // `contact`'s tractions ([`crate::study::rough::traction_grid`]): reference
                // units, periodic when the contact is.
                let (length, pressure) = (REFERENCE_LENGTH_M, REFERENCE_PRESSURE_PA);
                let p = parts.pressure_pa.mapv(|p| p / pressure);
                let grid = TractionGrid::new(
                    [0.0, 0.0],
                    [parts.spacing_m[0] / length, parts.spacing_m[1] / length],
                    Some(p.clone()),
                    (signed_friction != 0.0).then(|| p.mapv(|p| signed_friction * p)),
                    None,
                )?;
                let tractions = if *periodic {
                    PointTractions::periodic(grid, poisson)
                } else {
                    PointTractions::new(grid, poisson)
                }
                .map_err(|e| ThermalStudyError::Contact(e.to_string()))?;
                ContactPart::Layers {
                    fft: Layers::Tractions(Box::new(tractions)),
                    length_m: length,
                    pressure_pa: pressure,
                }
            }
        };
        Ok(Self {
            grid: CellGrid {
                shape: parts.shape,
                spacing_m: parts.spacing_m,
            },
            origin_m: parts.origin_m,
            line: parts.line,
            u1: super::thermal::inverse_length(&spec.body1),
            poisson,
            e_alpha_over_k: super::thermal::e_alpha_over_k(&spec.body1),
            body1_flux: parts.flux_w_per_m2.mapv(|q| q * parts.share),
            contact,
        })
    }

    /// The stress of `study` (its own grid, heat and contact model).
    pub(crate) fn of_study(study: &ThermalStudy) -> Result<Self, ThermalStudyError> {
        Self::new(
            &Parts {
                shape: study.shape,
                spacing_m: study.spacing_m,
                origin_m: study.origin_m,
                half_width_m: study.half_width_m,
                line: study.line,
                pressure_pa: &study.pressure_pa,
                flux_w_per_m2: &study.flux_w_per_m2,
                share: study.body1.share,
            },
            &study.spec,
            &study.contact_model,
            study.signed_friction,
        )
    }

    pub(crate) fn closed_form(&self) -> bool {
        matches!(self.contact, ContactPart::ClosedForm { .. })
    }

    /// The rows searched: a line contact's middle one, otherwise all.
    pub(crate) fn rows(&self) -> Vec<usize> {
        if self.line {
            vec![self.grid.shape[0] / 2]
        } else {
            (0..self.grid.shape[0]).collect()
        }
    }

    pub(crate) fn x_m(&self, column: usize) -> f64 {
        self.origin_m[0] + column as f64 * self.grid.spacing_m[0]
    }

    pub(crate) fn y_m(&self, row: usize) -> f64 {
        if self.line {
            0.0
        } else {
            self.origin_m[1] + row as f64 * self.grid.spacing_m[1]
        }
    }

    /// The row nearest to `y_m`.
    pub(crate) fn row_of(&self, y_m: f64) -> usize {
        let ny = self.grid.shape[0];
        if self.line {
            return ny / 2;
        }
        ((y_m - self.origin_m[1]) / self.grid.spacing_m[1])
            .round()
            .clamp(0.0, (ny - 1) as f64) as usize
    }

    /// The layer at depth `z` (m).
    pub(crate) fn layer(&self, z: f64) -> Result<StressLayer, ThermalStudyError> {
        let thermal = self.thermal_layer(z)?;
        self.with_thermal(z, thermal)
    }

    /// Body 1's thermal stress `[6, ny, nx]` (Pa) at depth `z` (m).
    pub(crate) fn thermal_layer(&self, z: f64) -> Result<Array3<f64>, ThermalStudyError> {
        super::thermal::thermal_stress_layer(
            &self.grid,
            self.line,
            z,
            self.u1,
            self.poisson,
            self.e_alpha_over_k,
            &self.body1_flux,
        )
    }

    /// The layer at depth `z` (m) with the thermal stress `thermal` given (computed, or
    /// interpolated in depth by the search, [`super::heated_search`]) and the contact's own.
    pub(crate) fn with_thermal(
        &self,
        z: f64,
        thermal: Array3<f64>,
    ) -> Result<StressLayer, ThermalStudyError> {
        let contact = match &self.contact {
            ContactPart::ClosedForm { .. } => None,
            ContactPart::Layers { fft, length_m, .. } => Some(fft.fft().layer(z / length_m)?),
        };
        Ok(StressLayer {
            depth_m: z,
            thermal,
            contact,
        })
    }

    /// The closed-form contact stress (Pa) at `(x, y, z)` (m); zero for gridded contacts.
    fn contact_at(&self, x: f64, y: f64, z: f64) -> Stress {
        match &self.contact {
            ContactPart::ClosedForm {
                solution,
                p0_pa,
                half_width_m: a,
            } => solution.stress_over_p0(x / a, y / a, z / a).scaled(*p0_pa),
            ContactPart::Layers { .. } => Stress::default(),
        }
    }

    /// The thermal and the contact stress (Pa) at the centre of cell `[row, column]`.
    pub(crate) fn at(&self, layer: &StressLayer, row: usize, column: usize) -> (Stress, Stress) {
        let thermal = layer_stress(&layer.thermal.view(), row, column);
        let contact = match (&layer.contact, &self.contact) {
            (Some(c), ContactPart::Layers { pressure_pa, .. }) => {
                layer_stress(&c.view(), row, column).scaled(*pressure_pa)
            }
            _ => self.contact_at(self.x_m(column), self.y_m(row), layer.depth_m),
        };
        (thermal, contact)
    }

    /// The thermal stress along `row` at `x` (m) between the cell centres, by the
    /// Catmull–Rom cubic through the four nearest (exact at a centre), and the closed-form
    /// contact stress there.
    pub(crate) fn between(&self, layer: &StressLayer, row: usize, x: f64) -> (Stress, Stress) {
        let nx = self.grid.shape[1];
        let f = ((x - self.origin_m[0]) / self.grid.spacing_m[0]).clamp(0.0, (nx - 1) as f64);
        let j = (f.floor() as usize).min(nx.saturating_sub(2));
        let t = f - j as f64;
        let at = |c: isize| {
            let c = c.clamp(0, nx as isize - 1) as usize;
            layer_stress(&layer.thermal.view(), row, c)
        };
        let j = j as isize;
        let (p0, p1, p2, p3) = (at(j - 1), at(j), at(j + 1), at(j + 2));
        // Catmull–Rom: p1 + t(p2 - p0)/2 + t²(2p0 - 5p1 + 4p2 - p3)/2 + t³(3p1 - p0 - 3p2 + p3)/2.
        let w0 = 0.5 * (-t + 2.0 * t * t - t * t * t);
        let w1 = 0.5 * (2.0 - 5.0 * t * t + 3.0 * t * t * t);
        let w2 = 0.5 * (t + 4.0 * t * t - 3.0 * t * t * t);
        let w3 = 0.5 * (-t * t + t * t * t);
        let thermal = p0.scaled(w0) + p1.scaled(w1) + p2.scaled(w2) + p3.scaled(w3);
        (thermal, self.contact_at(x, self.y_m(row), layer.depth_m))
    }

    /// Whether the contact's maxima come from elsewhere: the closed form, or a rough
    /// contact's own search ([`super::thermal::study`]).
    pub(crate) fn contact_elsewhere(&self) -> bool {
        self.closed_form()
            || matches!(
                self.contact,
                ContactPart::Layers {
                    fft: Layers::Tractions(_),
                    ..
                }
            )
    }

    /// Each quantity's largest value over the layer's cells: `(value, row, column)` (the
    /// contact's alone are left unsearched when they come from elsewhere; of equal values the
    /// first cell in row order). A maximum shear is computed (its principal stresses are most
    /// of the time) only where the von Mises bound `τ <= σvM/√3` could beat the best so far,
    /// as `contact`'s search does: the cells are taken in decreasing von Mises stress, so
    /// that the search stops at the first cell whose bound is below the best.
    pub(crate) fn layer_best(&self, layer: &StressLayer) -> [(f64, usize, usize); QUANTITIES] {
        let contact_too = !self.contact_elsewhere();
        let mut best = [(f64::NEG_INFINITY, 0, 0); QUANTITIES];
        fn offer(best: &mut [(f64, usize, usize)], k: usize, v: f64, row: usize, column: usize) {
            if v > best[k].0 {
                best[k] = (v, row, column);
            }
        }
        // The von Mises stress of the total and of the contact at each cell, for the shears:
        // the rows in parallel, their bests and cells then taken in row order (a later row's
        // best only where strictly larger), as one scan in row order finds them.
        let per_row: Vec<RowScan> = self
            .rows()
            .into_par_iter()
            .map(|row| {
                let mut scan = RowScan {
                    best: [(f64::NEG_INFINITY, 0, 0); QUANTITIES],
                    total_cells: Vec::with_capacity(self.grid.shape[1]),
                    contact_cells: Vec::new(),
                };
                for column in 0..self.grid.shape[1] {
                    let (thermal, contact) = self.at(layer, row, column);
                    offer(
                        &mut scan.best,
                        THERMAL_VON_MISES,
                        thermal.von_mises(),
                        row,
                        column,
                    );
                    let total_von_mises = (thermal + contact).von_mises();
                    offer(
                        &mut scan.best,
                        TOTAL_VON_MISES,
                        total_von_mises,
                        row,
                        column,
                    );
                    scan.total_cells.push((total_von_mises, row, column));
                    if contact_too {
                        let contact_von_mises = contact.von_mises();
                        offer(
                            &mut scan.best,
                            CONTACT_VON_MISES,
                            contact_von_mises,
                            row,
                            column,
                        );
                        scan.contact_cells.push((contact_von_mises, row, column));
                    }
                }
                scan
            })
            .collect();
        let mut total_cells: Vec<(f64, usize, usize)> = Vec::new();
        let mut contact_cells: Vec<(f64, usize, usize)> = Vec::new();
        for scan in per_row {
            for k in [THERMAL_VON_MISES, TOTAL_VON_MISES, CONTACT_VON_MISES] {
                let (v, row, column) = scan.best[k];
                offer(&mut best, k, v, row, column);
            }
            total_cells.extend(scan.total_cells);
            contact_cells.extend(scan.contact_cells);
        }
        let bound = super::assess::TRESCA_PER_VON_MISES;
        for (k, cells) in [
            (TOTAL_MAX_SHEAR, total_cells),
            (CONTACT_MAX_SHEAR, contact_cells),
        ] {
            // τ >= σvM/2 at every cell (`TRESCA_PER_VON_MISES`), so the largest shear is at
            // least half the largest von Mises stress: only cells whose bound reaches that
            // (less a margin for rounding) are candidates.
            let largest = cells.iter().fold(f64::NEG_INFINITY, |m, c| m.max(c.0));
            let floor = 0.5 * largest * (1.0 - 1e-9);
            let mut cells: Vec<(f64, usize, usize)> =
                cells.into_iter().filter(|c| c.0 * bound >= floor).collect();
            cells.sort_unstable_by(|a, b| b.0.total_cmp(&a.0));
            for (von_mises, row, column) in cells {
                if von_mises * bound < best[k].0 {
                    break;
                }
                let (thermal, contact) = self.at(layer, row, column);
                let shear = if k == TOTAL_MAX_SHEAR {
                    (thermal + contact).max_shear()
                } else {
                    contact.max_shear()
                };
                // Of equal shears the first cell in row order, as a scan in that order keeps.
                if shear > best[k].0
                    || (shear == best[k].0 && (row, column) < (best[k].1, best[k].2))
                {
                    best[k] = (shear, row, column);
                }
            }
        }
        best
    }

    /// The five quantities at every cell centre of `row` in `layer`:
    /// `[quantity][column]` (Pa).
    pub(crate) fn row_values(&self, layer: &StressLayer, row: usize) -> [Vec<f64>; QUANTITIES] {
        let nx = self.grid.shape[1];
        let mut out: [Vec<f64>; QUANTITIES] = std::array::from_fn(|_| vec![0.0; nx]);
        for column in 0..nx {
            let (thermal, contact) = self.at(layer, row, column);
            for (k, values) in out.iter_mut().enumerate() {
                values[column] = measure(k, &thermal, &contact);
            }
        }
        out
    }

    /// The thermal maximum shear at every cell centre of `row` in `layer` (Pa).
    pub(crate) fn thermal_max_shear_row(&self, layer: &StressLayer, row: usize) -> Vec<f64> {
        (0..self.grid.shape[1])
            .map(|column| layer_stress(&layer.thermal.view(), row, column).max_shear())
            .collect()
    }
}

/// A searched depth (m) and, per quantity, its largest value there with its cell `(value,
/// row, column)`.
pub(crate) type DepthBest = (f64, [(f64, usize, usize); QUANTITIES]);

//! The stresses in a coated body under tractions given on a grid: all six components at any
//! depth, in the coating and in the substrate, from the layered response of each traction
//! wave ([`super::response`]).
//!
//! ## The tractions as waves
//! The pressure `p` and the shear `qx` (and `qy`) are given at the centres of a `[ny, nx]`
//! grid. Zero-padded to `[2ny, 2nx]` (an isolated contact; a periodic one is taken as its
//! own period) they are taken as the band-limited functions through their samples: each
//! wavenumber of the discrete transform is one surface wave, whose stress at depth `z` follows
//! in closed form, and one inverse transform per component gives the field at the cell
//! centres. On the surface the samples come back exactly (`σzz = -p`, `σxz = -qx`,
//! `σyz = -qy` at every centre, to round-off); the Nyquist waves, which a real grid cannot
//! carry with their sign, are left out. The mean traction stresses the body uniformly
//! (`σzz = -p̄`, `τxz = -q̄x`, `τyz = -q̄y`, as for the homogeneous layers of
//! [`crate::solution::dcfft`]); for an isolated contact the mean wave stands for all the
//! wavenumbers within half a grid step of zero, in every direction, so its in-plane stress is
//! the waves' `k -> 0` limit averaged over direction, `σxx = σyy = (σss + σtt)/2` (for a
//! homogeneous body `-(1 + 2ν) p̄ / 2`); leaving it out shifted σxx and σyy by about
//! `0.8 p̄`, 0.027 p0 on a Hertz contact padded to ±4a. Unlike the cell-based layers of a homogeneous body, no
//! influence coefficients exist here in closed form: the waves are exact for the band-limited
//! tractions, which differ from uniform cells by the cells' form factor (a smoothing on the
//! scale of a cell).
//!
//! An isolated contact's field is that of its periodic images two grid lengths apart; near
//! the contact their stresses largely cancel (the in-plane surface stress of a Boussinesq load
//! is traceless), and the check against the Hertz closed form measures what is left
//! ([`crate::coating`] tests, `docs/coatings.md`).

use std::f64::consts::PI;

use ndarray::{Array2, Array3, ArrayView2, Axis};
use rustfft::num_complex::Complex;

use super::response::{Layered, Side, WaveResponse};
use crate::operator::transform::{signed_index, RealFft2, TransformError};

/// The stress layers of one set of tractions on a coated body.
pub struct LayeredStress {
    layered: Layered,
    shape: [usize; 2],
    plan: RealFft2,
    /// `(load, spectrum)`: load 0 the pressure, 1 `qx`, 2 `qy`; only the loads present.
    loads: Vec<(usize, Array2<Complex<f64>>)>,
    /// Per spectrum entry `[kx, ky]`: the wave vector `(kx, ky)`, `|k|` and the wave's
    /// constants (`None` for the mean and the Nyquist waves).
    waves: Array2<Option<([f64; 3], WaveResponse)>>,
    /// An isolated contact (zero-padded) rather than a period.
    isolated: bool,
    /// The padded grid's longer side, m.
    length_m: f64,
}

impl LayeredStress {
    /// Transforms the tractions (Pa, `[ny, nx]`, cells `spacing_m`): `pressure`, and `shear_x`
    /// (`qx`, acting in +x on the body) when given.
    pub fn new<'a>(
        layered: Layered,
        pressure: ArrayView2<'a, f64>,
        shear_x: Option<ArrayView2<'a, f64>>,
        spacing_m: [f64; 2],
        periodic: bool,
    ) -> Result<Self, TransformError> {
        let (ny, nx) = pressure.dim();
        let plan_shape = if periodic { [ny, nx] } else { [2 * ny, 2 * nx] };
        let plan = RealFft2::new(plan_shape);
        let mut work = plan.work();
        let mut loads = Vec::new();
        for (load, array) in [(0, Some(pressure)), (1, shear_x)] {
            let Some(array) = array else { continue };
            let mut spectrum = plan.new_spectrum();
            plan.forward(array, &mut spectrum, &mut work)?;
            loads.push((load, spectrum));
        }
        let [py, px] = plan_shape;
        let (lx, ly) = (px as f64 * spacing_m[0], py as f64 * spacing_m[1]);
        let [width, height] = plan.spectrum_shape();
        let h = layered.thickness_m;
        let waves = Array2::from_shape_fn((width, height), |(ix, iy)| {
            let (sx, sy) = (signed_index(ix, px), signed_index(iy, py));
            let nyquist =
                (px % 2 == 0 && sx == (px / 2) as i64) || (py % 2 == 0 && sy == (py / 2) as i64);
            if (sx == 0 && sy == 0) || nyquist {
                return None;
            }
            let (kx, ky) = (2.0 * PI * sx as f64 / lx, 2.0 * PI * sy as f64 / ly);
            let k = kx.hypot(ky);
            Some(([kx, ky, k], layered.wave(k * h)))
        });
        Ok(Self {
            layered,
            shape: [ny, nx],
            plan,
            loads,
            waves,
            isolated: !periodic,
            length_m: lx.max(ly),
        })
    }

    /// The coated body.
    pub fn layered(&self) -> &Layered {
        &self.layered
    }

    /// The tractions' grid `[ny, nx]`.
    pub fn shape(&self) -> [usize; 2] {
        self.shape
    }

    /// The stresses (Pa) at depth `z_m` along grid row `row` (e.g. the centre row, the plane of
    /// symmetry of a contact centred on the grid), `[component, x]` at the `nx` cell centres:
    /// each component's waves summed over `ky` with the row's phase, then one transform along
    /// `x` (no 2-D transforms: a row costs `O(nx ny)`).
    pub fn row(&self, row: usize, z_m: f64, side: Side) -> Array2<f64> {
        let nx = self.shape[1];
        let [width, height] = self.plan.spectrum_shape();
        let [py, px] = self.plan.shape();
        let mut columns = vec![[Complex::new(0.0, 0.0); 6]; width];
        for ix in 0..width {
            for iy in 0..height {
                let Some(([kx, ky, k], response)) = &self.waves[[ix, iy]] else {
                    continue;
                };
                let at = response.at(k * z_m, side, &self.layered);
                let factors = at.stress([kx / k, ky / k]);
                let angle = 2.0 * PI * (signed_index(iy, py) * row as i64) as f64 / py as f64;
                let phase = Complex::from_polar(1.0, angle);
                for (c, column) in columns[ix].iter_mut().enumerate() {
                    for (load, traction) in &self.loads {
                        let [re, im] = factors[c][*load];
                        *column += Complex::new(re, im) * traction[[ix, iy]] * phase;
                    }
                }
            }
        }
        let in_plane = self.mean_in_plane(z_m, side);
        for (load, traction) in &self.loads {
            let mean = traction[[0, 0]];
            if *load == 0 {
                columns[0][2] -= mean;
                if let Some(factor) = in_plane {
                    columns[0][0] += mean * factor;
                    columns[0][1] += mean * factor;
                }
            } else {
                columns[0][4] -= mean;
            }
        }
        let mut planner = realfft::RealFftPlanner::<f64>::new();
        let inverse = planner.plan_fft_inverse(px);
        let mut out = Array2::zeros((6, nx));
        let mut line = vec![0.0; px];
        for c in 0..6 {
            let mut spectrum: Vec<Complex<f64>> = columns.iter().map(|v| v[c]).collect();
            // The mean's and (zeroed) Nyquist's imaginary parts are rounding: a real grid.
            spectrum[0].im = 0.0;
            if px % 2 == 0 {
                spectrum[width - 1].im = 0.0;
            }
            if inverse.process(&mut spectrum, &mut line).is_err() {
                // Lengths are fixed above; a failure here is a bug in the layout.
                continue;
            }
            let scale = 1.0 / (px * py) as f64;
            for i in 0..nx {
                out[[c, i]] = line[i] * scale;
            }
        }
        out
    }

    /// `σxx = σyy` per unit mean pressure at depth `z` of an isolated contact's mean wave:
    /// the waves' limit as `k -> 0` averaged over their directions, `(σss + σtt) / 2` (the
    /// mean mode stands for the wavenumbers within half a grid step of zero, of every
    /// direction); `None` for a periodic contact, whose mean leaves the in-plane stresses
    /// unloaded as the homogeneous layers do.
    fn mean_in_plane(&self, z_m: f64, side: Side) -> Option<f64> {
        if !self.isolated {
            return None;
        }
        let h = self.layered.thickness_m;
        // A wavelength far beyond the layer, the depth and the grid.
        let k = 1e-6 / (h + z_m + self.length_m);
        let at = self.layered.wave(k * h).at(k * z_m, side, &self.layered);
        let ss = at.pressure[2];
        let tt = at.poisson * (at.pressure[2] - at.pressure[0]);
        Some(0.5 * (ss + tt))
    }

    /// The stresses (Pa) at depth `z_m` at every cell centre, `[component, y, x]` with the
    /// components `[xx, yy, zz, yz, xz, xy]`; at `z = h`, those of `side`.
    pub fn layer(&self, z_m: f64, side: Side) -> Result<Array3<f64>, TransformError> {
        let [ny, nx] = self.shape;
        let mut spectra: Vec<Array2<Complex<f64>>> =
            (0..6).map(|_| self.plan.new_spectrum()).collect();
        for ((ix, iy), wave) in self.waves.indexed_iter() {
            let Some(([kx, ky, k], response)) = wave else {
                continue;
            };
            let at = response.at(k * z_m, side, &self.layered);
            let factors = at.stress([kx / k, ky / k]);
            for (c, spectrum) in spectra.iter_mut().enumerate() {
                let mut sum = Complex::new(0.0, 0.0);
                for (load, traction) in &self.loads {
                    let [re, im] = factors[c][*load];
                    sum += Complex::new(re, im) * traction[[ix, iy]];
                }
                spectrum[[ix, iy]] = sum;
            }
        }
        // The mean traction (module doc).
        let in_plane = self.mean_in_plane(z_m, side);
        for (load, traction) in &self.loads {
            let mean = traction[[0, 0]];
            if *load == 0 {
                spectra[2][[0, 0]] -= mean;
                if let Some(factor) = in_plane {
                    spectra[0][[0, 0]] += mean * factor;
                    spectra[1][[0, 0]] += mean * factor;
                }
            } else {
                spectra[4][[0, 0]] -= mean;
            }
        }
        let mut out = Array3::zeros((6, ny, nx));
        let mut work = self.plan.work();
        for (c, spectrum) in spectra.iter_mut().enumerate() {
            self.plan
                .inverse(spectrum, out.index_axis_mut(Axis(0), c), &mut work)?;
        }
        Ok(out)
    }
}

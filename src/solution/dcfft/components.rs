//! The stress components of a layer from its influence coefficients: row transforms of the
//! coefficients, column transforms in chunks with the products by the tractions' spectra,
//! inverse transforms ([`DcFft::component_into`]).

use ndarray::ArrayViewMut2;
use rustfft::num_complex::Complex;

use super::*;

impl DcFft {
    /// Fresh working memory for [`DcFft::layer_into`].
    pub fn workspace(&self) -> Workspace {
        Workspace {
            quadrant: Vec::new(),
            component: None,
            spectral: None,
        }
    }

    /// The bytes one worker of [`DcFft::layer_into`] holds for a cell-based layer: the
    /// influence coefficients (six arrays per load present, `48 L nx ny` for `L` loads), a
    /// component's row spectra (`16 nx ny`: one array with friction along x, else one per
    /// load) and the layer (`48 nx ny`); on a periodic square grid, while the coefficients are
    /// filled, those of each turned shear that is not a load (`24 nx ny`,
    /// [`DcFft::periodic_turns_about_diagonal`]).
    pub fn worker_bytes(&self) -> usize {
        let [ny, nx] = self.shape;
        let loads = self.tractions.len();
        let unpaired = if self.periodic_turns_about_diagonal() {
            let present: Vec<Load> = self.tractions.iter().map(|(load, _)| *load).collect();
            present
                .iter()
                .filter(|load| !present.contains(&load.turned()))
                .count()
        } else {
            0
        };
        (48 * loads + 16 * self.row_spectra_per_component() + 48) * nx * ny
            + 48 * unpaired * (ny / 2 + 1) * nx
    }

    /// Fresh working memory for [`DcFft::component_into`].
    pub fn component_workspace(&self) -> ComponentWorkspace {
        let [ny, _] = self.shape;
        let zero = Complex::new(0.0, 0.0);
        let rows = self.plans.rows_len();
        ComponentWorkspace {
            rows: vec![vec![zero; rows]; self.row_spectra_per_component()],
            chunk: vec![zero; COLUMN_CHUNK * 2 * ny],
            sum: vec![zero; COLUMN_CHUNK * 2 * ny],
            buffers: FftBuffers::new(&self.plans),
        }
    }

    /// Arrays of row spectra per component: one where the loads pack ([`Packed`]), else one
    /// per load present.
    fn row_spectra_per_component(&self) -> usize {
        (0..6)
            .map(|c| match Packed::of(&self.tractions, c) {
                Some(_) => 1,
                None => self.tractions.len(),
            })
            .max()
            .unwrap_or(1)
    }

    /// One stress component (`c` in the order of [`COMPONENTS`]) of a layer whose influence
    /// coefficients are in `quadrant` ([`DcFft::influence_into`]), `[y, x]`: the row
    /// transforms of its coefficients, then chunk by chunk of columns their forward
    /// transforms, the products with the tractions' spectra and the inverse transforms, then
    /// the inverse row transforms. The six components of a layer are independent, so callers
    /// may compute them on different threads, each with its own [`ComponentWorkspace`].
    ///
    /// # Panics
    /// If `out` is not `[ny, nx]` or `c >= 6`.
    pub fn component_into(
        &self,
        quadrant: &[f64],
        c: usize,
        workspace: &mut ComponentWorkspace,
        mut out: ArrayViewMut2<f64>,
    ) -> Result<(), DcFftError> {
        let [ny, nx] = self.shape;
        assert!(c < 6, "stress component index {c} out of 0..6");
        assert_eq!(out.shape(), [ny, nx], "component output must be [ny, nx]");
        let ComponentWorkspace {
            rows,
            chunk,
            sum,
            buffers,
        } = workspace;
        self.coefficient_rows(quadrant, c, rows, buffers)?;
        let height = 2 * ny;
        for start in (0..=nx).step_by(COLUMN_CHUNK) {
            let length = COLUMN_CHUNK.min(nx + 1 - start) * height;
            let (chunk, sum) = (&mut chunk[..length], &mut sum[..length]);
            self.product_columns(c, rows, start, chunk, sum, &mut buffers.scratch);
        }
        let scale = 1.0 / (4 * nx * ny) as f64;
        self.plans
            .inverse_rows(&mut rows[0], scale, buffers, out.view_mut())?;
        let uniform = uniform_stress(self.mean, c);
        if uniform != 0.0 {
            out.mapv_inplace(|v| v + uniform);
        }
        Ok(())
    }

    /// Row transforms of component `c`'s coefficients into `rows`: one array for the loads
    /// that pack ([`Packed`]), else one per load.
    fn coefficient_rows(
        &self,
        quadrant: &[f64],
        c: usize,
        rows: &mut [Vec<Complex<f64>>],
        buffers: &mut FftBuffers,
    ) -> Result<(), DcFftError> {
        let [ny, nx] = self.shape;
        let cells = nx * ny;
        let periodic = self.periodicity == Periodicity::Periodic;
        let fill = |slot: usize, b: usize, line: &mut [f64], add: bool| {
            let (parity_x, parity_y) = self.tractions[slot].0.parity(c);
            let offset = (slot * 6 + c) * cells;
            let coefficients = &quadrant[offset..offset + cells];
            // Row b of the wrap-around grid: offsets 0..nx, a zero, then the mirror.
            // Periodic rows beyond ny/2 are the mirror of row ny - b.
            let (b, sign) = if periodic && 2 * b > ny {
                (ny - b, parity_y)
            } else {
                (b, 1.0)
            };
            let source = &coefficients[b * nx..(b + 1) * nx];
            let put = |target: &mut f64, value: f64| {
                if add {
                    *target += value;
                } else {
                    *target = value;
                }
            };
            for (target, value) in line[..nx].iter_mut().zip(source) {
                put(target, sign * value);
            }
            line[nx] = 0.0;
            for (target, value) in line[nx + 1..].iter_mut().rev().zip(&source[1..]) {
                put(target, sign * parity_x * value);
            }
        };
        match Packed::of(&self.tractions, c) {
            Some(Packed { even, odd, .. }) => {
                let fill_row = |b: usize, line: &mut [f64]| {
                    fill(even, b, line, false);
                    fill(odd, b, line, true);
                };
                self.plans.row_spectra(fill_row, buffers, &mut rows[0])?;
            }
            None => {
                for (slot, load_rows) in rows.iter_mut().enumerate().take(self.tractions.len()) {
                    let fill_row = |b: usize, line: &mut [f64]| fill(slot, b, line, false);
                    self.plans.row_spectra(fill_row, buffers, load_rows)?;
                }
            }
        }
        Ok(())
    }

    /// The columns `start..` (as many as `chunk` holds) of component `c`: forward column
    /// transforms of its coefficients' row spectra `rows`, products with the tractions'
    /// spectra summed over the loads, inverse column transforms, written into the same
    /// columns of `rows[0]` (whose values there have been read).
    fn product_columns(
        &self,
        c: usize,
        rows: &mut [Vec<Complex<f64>>],
        start: usize,
        chunk: &mut [Complex<f64>],
        sum: &mut [Complex<f64>],
        scratch: &mut [Complex<f64>],
    ) {
        let height = 2 * self.shape[0];
        let length = chunk.len();
        let window = |slot: usize| &self.tractions[slot].1[start * height..start * height + length];
        if let Some(Packed {
            even,
            odd,
            parity_y,
        }) = Packed::of(&self.tractions, c)
        {
            let more = Rows::Mirrored { parity: parity_y };
            self.plans
                .column_chunk(&rows[0], more, start, chunk, scratch);
            let (t_even, t_odd) = (window(even), window(odd));
            let terms = sum.iter_mut().zip(&*chunk).zip(t_even.iter().zip(t_odd));
            // With parity +1 in y, Ê = Re r and iÔ = i Im r; with −1, Ê = i Im r and
            // iÔ = Re r ([`Packed`]).
            if parity_y > 0.0 {
                for ((total, r), (te, to)) in terms {
                    *total = te * r.re + Complex::new(-to.im, to.re) * r.im;
                }
            } else {
                for ((total, r), (te, to)) in terms {
                    *total = Complex::new(-te.im, te.re) * r.im + to * r.re;
                }
            }
        } else {
            for (slot, ((load, _), load_rows)) in self.tractions.iter().zip(rows.iter()).enumerate()
            {
                let more = Rows::Mirrored {
                    parity: load.parity(c).1,
                };
                self.plans
                    .column_chunk(load_rows, more, start, chunk, scratch);
                let terms = sum.iter_mut().zip(&*chunk).zip(window(slot));
                if slot == 0 {
                    terms.for_each(|((total, k), t)| *total = k * t);
                } else {
                    terms.for_each(|((total, k), t)| *total += k * t);
                }
            }
        }
        self.plans
            .inverse_column_chunk(sum, start, &mut rows[0], scratch);
    }
}

/// Two loads whose coefficients of one component have opposite parity in x, transformed
/// together: the pressure and the shear along x (each component is even in x for one of them
/// and odd for the other, with the same parity in y). The rows of a real sequence even in x
/// transform to real spectra, those of an odd one to imaginary spectra, so the real transform
/// of their sum holds both: `E + iO`, with `E` the even load's and `iO` the odd load's. Along
/// the columns both are real (or, with parity −1 in y, imaginary) sequences of the same
/// parity, so the complex transform `r` of `E + iO` holds both again: with `Ê`, `Ô` the column
/// transforms of `E`, `O`, `r = Ê + iÔ`, and the odd load's spectrum is `iÔ`. Parity +1 in y:
/// `Ê`, `Ô` real, so `Ê = Re r`, `iÔ = i Im r`. Parity −1: both imaginary, `Ê = i Im r`,
/// `iÔ = Re r`.
/// Half the forward transforms of a layer with friction. (The two-real-sequences-in-one
/// transform of Press, Teukolsky, Vetterling & Flannery, *Numerical Recipes*, 3rd ed.,
/// Cambridge University Press (2007), §12.3, here with the parities doing the separation.)
#[derive(Clone, Copy, Debug)]
struct Packed {
    /// The slots of the loads even and odd in x.
    even: usize,
    odd: usize,
    /// Their common parity in y.
    parity_y: f64,
}

impl Packed {
    /// The packing of component `c` of `tractions`: two loads of opposite parity in x and the
    /// same in y, or `None`.
    fn of(tractions: &[(Load, Vec<Complex<f64>>)], c: usize) -> Option<Self> {
        let [(first, _), (second, _)] = tractions else {
            return None;
        };
        let ((x1, y1), (x2, y2)) = (first.parity(c), second.parity(c));
        if x1 == x2 || y1 != y2 {
            return None;
        }
        let (even, odd) = if x1 > 0.0 { (0, 1) } else { (1, 0) };
        Some(Self {
            even,
            odd,
            parity_y: y1,
        })
    }
}

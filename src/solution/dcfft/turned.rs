//! The influence coefficients of a grid that turns about its diagonal
//! ([`DcFft::turns_about_diagonal`]), filled band of rows by band of rows, on one thread or
//! split over several.

use rayon::prelude::*;

use super::*;
use crate::solution::patch::RowSums;

/// The component with x and y exchanged, in the order of [`COMPONENTS`]: `xx <-> yy`,
/// `yz <-> xz`.
pub(super) const EXCHANGED: [usize; 6] = [1, 0, 2, 4, 3, 5];

/// Rows of influence coefficients whose turned values are held before they are written as
/// columns, on one thread: eight values of a column fill a cache line.
const TURNED_BAND: usize = 8;

/// The same, split over threads: each thread's part of a band evaluates one row of corners
/// more (one in 32 here, for two threads).
const PARALLEL_BAND: usize = 64;

/// The loads present and the components, in the order of the arrays of coefficients.
fn arrays_of(loads: &[Load]) -> impl Iterator<Item = (Load, usize)> + '_ {
    loads
        .iter()
        .flat_map(|&load| (0..6).map(move |c| (load, c)))
}

/// Component `c` of `load` of a row of cells (the offsets `a >= b` of row `b`) into `direct`,
/// and for a shear its turned values into `turned`: component `c` of the turned load is the
/// exchanged component of this one (the diagonal cell `a = b` is written but not used).
fn write_row(
    load: Load,
    c: usize,
    nu: f64,
    sums: &RowSums,
    direct: &mut [f64],
    turned: &mut [f64],
) {
    sums.component(load, c, nu, direct);
    if load != Load::Pressure {
        sums.component(load.turned(), EXCHANGED[c], nu, turned);
    }
}

/// One thread's rows of a band: the rows `b` (the offsets `a >= b`) of each array, and the
/// turned values of the same rows.
struct Part<'q> {
    rows: std::ops::Range<usize>,
    arrays: Vec<&'q mut [f64]>,
    turned: Vec<&'q mut [f64]>,
}

impl DcFft {
    /// [`DcFft::influence_into`] on a grid that [turns about its
    /// diagonal](DcFft::turns_about_diagonal), over `parts` threads (1: on the calling
    /// thread): each offset `(a, b)` with `a >= b` is evaluated once ([`offset_sums`]) and
    /// gives the coefficients of both `(a, b)` and `(b, a)`. Turned about `x = y`, a load on
    /// the cell at `(a, b)` seen from the origin is the turned load ([`Load::turned`]: the
    /// pressure, or the other shear) at `(b, a)`, and its stresses have x and y exchanged
    /// (`xx <-> yy`, `xz <-> yz`; `zz`, `xy` stay), the symmetry of the formulas of
    /// [`super::patch::uniform_patch`]. About half the corner terms of the row by row
    /// evaluation.
    ///
    /// Band by band of rows: the rows' offsets `a >= b` (split over the threads, each part
    /// starting from its own row of corners, which gives the same values), with the shears'
    /// turned values held aside; then the columns `b` of the band in every row below it
    /// (`a > b`), the shears' from their turned values and the pressure's from its exchanged
    /// components. The coefficients are the same to the last bit whatever `parts`.
    pub(super) fn fill_turned_influence(&self, z: f64, quadrant: &mut Vec<f64>, parts: usize) {
        let n = self.shape[1];
        let cells = n * n;
        let loads: Vec<Load> = self.tractions.iter().map(|(load, _)| *load).collect();
        let arrays = 6 * loads.len();
        quadrant.resize(arrays * cells, 0.0);
        let nu = self.poisson;
        if parts > 1 {
            // `[array][b - first][a]`: the turned values of the shears (the pressure's
            // arrays are left unused).
            let mut turned = vec![0.0; arrays * PARALLEL_BAND * n];
            for first in (0..n).step_by(PARALLEL_BAND) {
                let band = first..(first + PARALLEL_BAND).min(n);
                self.turned_band_rows(z, quadrant, &mut turned, band.clone(), &loads, parts);
                self.turned_band_columns(quadrant, &turned, band, &loads, parts);
            }
            return;
        }
        // On one thread, the rows of corners run on from band to band.
        let mut turned = vec![0.0; arrays * TURNED_BAND * n];
        let mut first = 0;
        offset_sums(self.cell, z, n, 0..n, true, |b, sums| {
            if b == first + TURNED_BAND {
                self.turned_band_columns(quadrant, &turned, first..b, &loads, 1);
                first = b;
            }
            for (array, (load, c)) in arrays_of(&loads).enumerate() {
                let row = b * n + b..(b + 1) * n;
                let band_row = (array * TURNED_BAND + b - first) * n;
                let (direct, turned) = (
                    &mut quadrant[array * cells..][row],
                    &mut turned[band_row + b..band_row + n],
                );
                write_row(load, c, nu, sums, direct, turned);
            }
        });
        self.turned_band_columns(quadrant, &turned, first..n, &loads, 1);
    }

    /// The rows `band` of every array, offsets `a >= b`, and the shears' turned values of the
    /// same offsets into `turned`, the band split into `parts` parts of rows.
    fn turned_band_rows(
        &self,
        z: f64,
        quadrant: &mut [f64],
        turned: &mut [f64],
        band: std::ops::Range<usize>,
        loads: &[Load],
        parts: usize,
    ) {
        let n = self.shape[1];
        let height = turned.len() / (6 * loads.len() * n);
        let per_part = band.len().div_ceil(parts);
        let mut split: Vec<Part<'_>> = band
            .clone()
            .step_by(per_part)
            .map(|start| Part {
                rows: start..(start + per_part).min(band.end),
                arrays: Vec::new(),
                turned: Vec::new(),
            })
            .collect();
        for (array, values) in quadrant
            .chunks_exact_mut(n * n)
            .zip(turned.chunks_exact_mut(height * n))
        {
            let rows = array[band.start * n..band.end * n].chunks_mut(per_part * n);
            let values = values[..band.len() * n].chunks_mut(per_part * n);
            for (part, (rows, values)) in split.iter_mut().zip(rows.zip(values)) {
                part.arrays.push(rows);
                part.turned.push(values);
            }
        }
        let nu = self.poisson;
        let fill = |part: Part<'_>| {
            let Part {
                rows,
                mut arrays,
                mut turned,
            } = part;
            let start = rows.start;
            offset_sums(self.cell, z, n, rows, true, |b, sums| {
                let row = (b - start) * n + b..(b - start + 1) * n;
                for (array, (load, c)) in arrays_of(loads).enumerate() {
                    let (direct, turned) = (&mut arrays[array], &mut turned[array]);
                    write_row(
                        load,
                        c,
                        nu,
                        sums,
                        &mut direct[row.clone()],
                        &mut turned[row.clone()],
                    );
                }
            });
        };
        if split.len() == 1 {
            split.into_iter().for_each(fill);
        } else {
            split.into_par_iter().for_each(fill);
        }
    }

    /// The columns `band` of every row `a` below the band's first (`b < a`): the shears' from
    /// their turned values, the pressure's from its exchanged components in the band's rows.
    /// The rows below the band are split into parts over the threads.
    fn turned_band_columns(
        &self,
        quadrant: &mut [f64],
        turned: &[f64],
        band: std::ops::Range<usize>,
        loads: &[Load],
        parts: usize,
    ) {
        let n = self.shape[1];
        let cells = n * n;
        let height = turned.len() / (6 * loads.len() * n);
        let pressure = |array: usize| loads[array / 6] == Load::Pressure;
        let source = |array: usize| array - array % 6 + EXCHANGED[array % 6];
        // The rows within the band (a small triangle), here.
        for array in 0..6 * loads.len() {
            for a in band.start + 1..band.end {
                for b in band.start..a {
                    quadrant[array * cells + a * n + b] = if pressure(array) {
                        quadrant[source(array) * cells + b * n + a]
                    } else {
                        turned[(array * height + b - band.start) * n + a]
                    };
                }
            }
        }
        if band.end == n {
            return;
        }
        // The rows below it, in parts, reading the band's rows.
        let below = n - band.end;
        let chunks = if parts > 1 { 4 * parts } else { 1 };
        let per_chunk = below.div_ceil(chunks);
        let mut heads = Vec::with_capacity(6 * loads.len());
        let mut split: Vec<(usize, Vec<&mut [f64]>)> = (band.end..n)
            .step_by(per_chunk)
            .map(|start| (start, Vec::new()))
            .collect();
        for array in quadrant.chunks_exact_mut(cells) {
            let (head, tail) = array.split_at_mut(band.end * n);
            heads.push(&*head);
            for ((_, rows), chunk) in split.iter_mut().zip(tail.chunks_mut(per_chunk * n)) {
                rows.push(chunk);
            }
        }
        let write = |(start, mut rows): (usize, Vec<&mut [f64]>)| {
            for (array, rows) in rows.iter_mut().enumerate() {
                // The band's rows of the values read: `[b - first][a]`.
                let values = if pressure(array) {
                    &heads[source(array)][band.start * n..band.end * n]
                } else {
                    &turned[array * height * n..(array * height + band.len()) * n]
                };
                for (k, row) in rows.chunks_exact_mut(n).enumerate() {
                    let a = start + k;
                    for (target, column) in row[band.clone()].iter_mut().zip(values.chunks_exact(n))
                    {
                        *target = column[a];
                    }
                }
            }
        };
        if split.len() == 1 {
            split.into_iter().for_each(write);
        } else {
            split.into_par_iter().for_each(write);
        }
    }
}

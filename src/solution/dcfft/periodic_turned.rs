//! The periodic influence coefficients of a square grid of square cells
//! ([`DcFft::periodic_turns_about_diagonal`]): the offsets on one side of the diagonal, the
//! others turned, block of rows by block of rows over the threads.

use rayon::prelude::*;

use super::turned::EXCHANGED;
use super::*;
use crate::solution::patch::offset_sums_in;

/// The blocks of rows per thread when the rows are split over threads: their work is
/// balanced, so a few per thread are enough for threads that start late.
const BLOCKS_PER_THREAD: usize = 4;

impl DcFft {
    /// Whether the periodic coefficients of the offsets `a < b` are those of `(b, a)` turned
    /// about the diagonal `x = y`: a periodic square grid of square cells (`nx = ny`,
    /// `dx = dy`). Its coefficients are filled by [`DcFft::influence_into`] from those of
    /// `b <= a <= n/2` ([`DcFft::fill_periodic_turned_influence`]); the blocks of
    /// [`DcFft::influence_blocks`] fill them all, which callers should not use instead: the
    /// layers would differ in the last bits.
    pub fn periodic_turns_about_diagonal(&self) -> bool {
        let ([ny, nx], [dx, dy]) = (self.shape, self.cell);
        self.periodicity == Periodicity::Periodic && nx == ny && dx == dy
    }

    /// [`DcFft::influence_into`] of a grid that [turns about its
    /// diagonal](DcFft::periodic_turns_about_diagonal) and repeats, over `parts` threads (1:
    /// on the calling thread).
    ///
    /// ## Method
    /// The periodic coefficient of the circular offset `(a, b)` is the sum over the window of
    /// images (module doc) `C_per(a, b) = Σ w(x) w(y) C(x, y)` over `x ≡ a`, `y ≡ b` (mod `n`),
    /// plus the far images `F(a, b)` ([`far_images`] at the nearest image). Three exact
    /// symmetries leave an eighth of the offsets to evaluate:
    /// - *in y*: `C(x, -y) = p_y C(x, y)` (the parity of the component, [`Load::parity`]) and
    ///   the window is symmetric, so the rows `b > n/2` are not needed (they are read as the
    ///   mirror of `n - b` by [`DcFft::component_into`], as for any periodic grid);
    /// - *in x*: likewise `C_per(n - a, b) = p_x C_per(a, b)`, and `F` has the same parity
    ///   (the window rectangle is symmetric): the columns `a > n/2` are the mirror of
    ///   `n - a`;
    /// - *about the diagonal*: turned about `x = y`, a load on the cell at `(x, y)` is the
    ///   turned load ([`Load::turned`]) on the cell at `(y, x)`, with x and y exchanged in the
    ///   stresses (`xx <-> yy`, `xz <-> yz`): `C_L(x, y)[c] = C_L'(y, x)[c']`, the symmetry of
    ///   the formulas of [`super::patch::uniform_patch`] on a square cell, which
    ///   [`DcFft::fill_turned_influence`] uses for isolated grids. With `nx = ny` the window
    ///   `|x|, |y| <= (M + 1/2) n` and its weights are the same along x and y, and with
    ///   `dx = dy` the far images' window is a square and their nearest images are the same
    ///   along both axes, so the sums turn too: `C_per,L(a, b)[c] = C_per,L'(b, a)[c']`.
    ///
    /// So only `b <= a <= n/2` is summed, and only from the images `x` whose column folds
    /// into it (`b <= min(x mod n, n - x mod n)`): about half the corner terms of
    /// [`DcFft::fill_influence`], which sums every image for every column, and an eighth of
    /// its far images. The shears' coefficients need those of the turned shear, which are
    /// summed too where that shear is not among the loads. The columns `a < b` are then
    /// turned from the row `a`, and the columns `a > n/2` mirrored.
    ///
    /// Each coefficient of `b <= a <= n/2` is summed image by image in the order of
    /// [`DcFft::fill_influence`] (the same value to the last bit), whatever `parts`: the
    /// coefficients are the same to the last bit on one thread or several.
    pub(super) fn fill_periodic_turned_influence(
        &self,
        z: f64,
        quadrant: &mut Vec<f64>,
        parts: usize,
    ) {
        let n = self.shape[1];
        let half = n / 2;
        let loads: Vec<Load> = self.tractions.iter().map(|(load, _)| *load).collect();
        // The loads summed: those present, then the turned shears that are not.
        let mut summed = loads.clone();
        for load in &loads {
            if !summed.contains(&load.turned()) {
                summed.push(load.turned());
            }
        }
        quadrant.resize(6 * loads.len() * n * n, 0.0);
        // The rows b <= n/2 of the turned shears' coefficients that are not among the loads.
        let mut spare = vec![0.0; 6 * (summed.len() - loads.len()) * (half + 1) * n];
        let blocks = if parts > 1 {
            BLOCKS_PER_THREAD * parts
        } else {
            1
        };
        let bounds = balanced_blocks(half + 1, blocks);
        let mut split: Vec<(std::ops::Range<usize>, Vec<&mut [f64]>)> = bounds
            .windows(2)
            .map(|w| (w[0]..w[1], Vec::with_capacity(6 * summed.len())))
            .collect();
        for array in quadrant
            .chunks_exact_mut(n * n)
            .chain(spare.chunks_exact_mut((half + 1) * n))
        {
            let mut rest = &mut array[..(half + 1) * n];
            for (rows, arrays) in &mut split {
                let (head, tail) = std::mem::take(&mut rest).split_at_mut(rows.len() * n);
                arrays.push(head);
                rest = tail;
            }
        }
        let fill = |(rows, arrays): (std::ops::Range<usize>, Vec<&mut [f64]>)| {
            self.fill_periodic_fundamental(z, rows, arrays, &summed);
        };
        if split.len() == 1 {
            split.into_iter().for_each(fill);
        } else {
            split.into_par_iter().for_each(fill);
        }
        self.turn_and_mirror_periodic(quadrant, &spare, &loads, &summed);
    }

    /// The coefficients `b <= a <= n/2` of the rows `b` in `rows` of each load in `summed`:
    /// `arrays[6 * slot + c]` holds the rows `rows` (all `n` columns; the others are left at
    /// zero). The images of each row `y ≡ b` in the window, period by period in the order of
    /// [`DcFft::fill_influence`], then the far images.
    fn fill_periodic_fundamental(
        &self,
        z: f64,
        rows: std::ops::Range<usize>,
        mut arrays: Vec<&mut [f64]>,
        summed: &[Load],
    ) {
        let n = self.shape[1];
        let half = n / 2;
        let images = PERIODIC_IMAGES;
        for array in &mut arrays {
            array.fill(0.0);
        }
        let reach = (2 * images + 1) * n / 2;
        let weights: Vec<f64> = (0..=reach).map(|a| window_weight(a, n, images)).collect();
        // The columns that `x = a` and `x = -a` fold into, where they fold into `0..=n/2` (`n`:
        // nowhere); a column of `folding_columns(b)` folds into `b..=n/2`.
        let folds: Vec<[usize; 2]> = (0..=reach)
            .map(|a| {
                let (plus, minus) = (a % n, (n - a % n) % n);
                [
                    if 2 * plus <= n { plus } else { n },
                    if a > 0 && 2 * minus <= n { minus } else { n },
                ]
            })
            .collect();
        let nu = self.poisson;
        let mut values = vec![0.0; reach + 1];
        let periods = images as i64 + 1;
        for period in -periods..=periods {
            // The images y = b + period n of the rows b, as |y| (a contiguous range): rising
            // with b for period >= 0; for period < 0, y < 0, mirrored by the parity in y, and
            // |y| falls as b rises, so that row is taken first (the cells of a row of images
            // lie among those of the row before it: they shrink as b rises).
            let shift = period.unsigned_abs() as usize * n;
            let (start, end, mirrored) = if period >= 0 {
                (rows.start + shift, rows.end + shift, false)
            } else {
                (shift + 1 - rows.end, shift + 1 - rows.start, true)
            };
            let end = end.min(reach + 1);
            if start >= end {
                continue;
            }
            let row_of = |s: usize| if mirrored { shift - s } else { s - shift };
            offset_sums_in(
                self.cell,
                z,
                reach + 1,
                start..end,
                mirrored,
                |s| folding_columns(n, reach, row_of(s)),
                |s, sums| {
                    let b = row_of(s);
                    let weight_y = weights[s];
                    let row = (b - rows.start) * n;
                    for (slot, &load) in summed.iter().enumerate() {
                        for c in 0..6 {
                            let (parity_x, parity_y) = load.parity(c);
                            let sign = if mirrored { parity_y } else { 1.0 };
                            let target = &mut arrays[6 * slot + c][row..row + n];
                            for range in sums.cells() {
                                let values = &mut values[..range.len()];
                                sums.component_in(load, c, nu, range.clone(), values);
                                for (a, &v) in range.clone().zip(values.iter()) {
                                    let value = weights[a] * weight_y * sign * v;
                                    let [plus, minus] = folds[a];
                                    debug_assert!(plus >= b && minus >= b);
                                    if plus < n {
                                        target[plus] += value;
                                    }
                                    if minus < n {
                                        target[minus] += parity_x * value;
                                    }
                                }
                            }
                        }
                    }
                },
            );
        }
        // The images beyond the window, on `b <= a <= n/2` only.
        self.add_far_images(z, rows, &mut arrays, summed, |b| b..half + 1);
    }

    /// The columns `a < b` of the rows `b <= n/2`, turned from row `a`, column `b`; then the
    /// columns `a > n/2`, mirrored from `n - a` ([`DcFft::fill_periodic_turned_influence`]).
    fn turn_and_mirror_periodic(
        &self,
        quadrant: &mut [f64],
        spare: &[f64],
        loads: &[Load],
        summed: &[Load],
    ) {
        let n = self.shape[1];
        let half = n / 2;
        for (slot, &load) in loads.iter().enumerate() {
            let source = summed
                .iter()
                .position(|&l| l == load.turned())
                .unwrap_or(slot);
            for (c, exchanged) in EXCHANGED.iter().enumerate() {
                let array = (6 * slot + c) * n * n;
                let from = 6 * source + exchanged;
                for b in 1..=half {
                    for a in 0..b {
                        quadrant[array + b * n + a] = if source < loads.len() {
                            quadrant[from * n * n + a * n + b]
                        } else {
                            spare[(from - 6 * loads.len()) * (half + 1) * n + a * n + b]
                        };
                    }
                }
                let parity_x = load.parity(c).0;
                for b in 0..=half {
                    let row = &mut quadrant[array + b * n..array + (b + 1) * n];
                    for a in half + 1..n {
                        row[a] = parity_x * row[n - a];
                    }
                }
            }
        }
    }
}

/// The columns `x` of the window (`0 <= x <= reach`) that fold into the columns
/// `b <= a <= n/2` of row `b`: `b <= x mod n <= n - b`, as disjoint increasing ranges.
fn folding_columns(n: usize, reach: usize, b: usize) -> Vec<std::ops::Range<usize>> {
    let mut ranges: Vec<std::ops::Range<usize>> = Vec::new();
    let mut period = 0;
    while period * n + b <= reach {
        let start = period * n + b;
        let end = (period * n + n - b + 1).min(reach + 1);
        match ranges.last_mut() {
            Some(last) if last.end >= start => last.end = end.max(last.end),
            _ => ranges.push(start..end),
        }
        period += 1;
    }
    ranges
}

/// Bounds `0 = r_0 < r_1 < ... = rows` of at most `blocks` blocks of the rows `b` of
/// [`DcFft::fill_periodic_turned_influence`] of about equal work: row `b` sums about
/// `n/2 + 1 - b` columns of each row of images.
fn balanced_blocks(rows: usize, blocks: usize) -> Vec<usize> {
    let work = |b: usize| (rows - b) as f64;
    let total: f64 = (0..rows).map(work).sum();
    let per_block = total / blocks.max(1) as f64;
    let mut bounds = vec![0];
    let mut done = 0.0;
    for b in 0..rows {
        done += work(b);
        if done >= per_block * bounds.len() as f64 && b + 1 < rows {
            bounds.push(b + 1);
        }
    }
    bounds.push(rows);
    bounds
}

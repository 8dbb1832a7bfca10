//! Influence coefficients of a three-dimensional half-space: the stresses under a uniform
//! pressure and uniform tangential tractions on a rectangle of the surface.
//!
//! These are the building blocks of the numerical point-contact solutions: any surface traction
//! discretised into uniform rectangular cells is summed from them, directly or by DC-FFT
//! ([`super::dcfft`]).

mod atan;

use std::f64::consts::PI;

use atan::{atan2_right, atan2_right_in_place};

use crate::stress::Stress;

/// The three unit loads of a rectangle, in the order of [`PatchStresses`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Load {
    Pressure = 0,
    ShearX = 1,
    ShearY = 2,
}

impl Load {
    /// The load that this one becomes when the half-space is turned about the diagonal
    /// `x = y` (x and y exchanged): the pressure stays, the shears along x and y exchange.
    pub(crate) fn turned(self) -> Self {
        match self {
            Load::Pressure => Load::Pressure,
            Load::ShearX => Load::ShearY,
            Load::ShearY => Load::ShearX,
        }
    }
}

/// A rectangle `x1 <= x <= x2`, `y1 <= y <= y2` of the surface (`x1 < x2`, `y1 < y2`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rectangle {
    pub x1: f64,
    pub x2: f64,
    pub y1: f64,
    pub y2: f64,
}

impl Rectangle {
    /// The rectangle of half-widths `half_x`, `half_y` centred on `(x, y)`.
    pub fn centred(x: f64, y: f64, half_x: f64, half_y: f64) -> Self {
        Self {
            x1: x - half_x,
            x2: x + half_x,
            y1: y - half_y,
            y2: y + half_y,
        }
    }

    /// Area `(x2 - x1)(y2 - y1)`.
    pub fn area(&self) -> f64 {
        (self.x2 - self.x1) * (self.y2 - self.y1)
    }
}

/// The stresses of the three unit loads on one rectangle, in units of the traction.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PatchStresses {
    /// Uniform pressure `p = 1` pushing on the surface (into the body, +z).
    pub pressure: Stress,
    /// Uniform tangential traction `qx = 1` acting on the body in +x.
    pub shear_x: Stress,
    /// Uniform tangential traction `qy = 1` acting on the body in +y.
    pub shear_y: Stress,
}

/// Stresses at `(x, y, z)` due to a uniform pressure `p = 1`, a uniform traction `qx = 1` and a
/// uniform traction `qy = 1`, each acting alone on the rectangle `rect` of the surface of an
/// elastic half-space with Poisson's ratio `nu` (the three results are independent; scale and
/// add them for a combined load).
///
/// Conventions: `z >= 0` points into the body; tension positive; under the rectangle on the
/// surface `szz = -p`, `sxz = -qx`, `syz = -qy`.
///
/// ## Derivation
/// Love's potentials (Johnson, *Contact Mechanics*, 1985, §3.2) give the stresses of the
/// Boussinesq and Cerruti point forces as linear combinations of third and fourth derivatives
/// of `Omega = z ln(R + z) - R`, `R² = X² + Y² + z²` (`X = x - ξ`, `Y = y - η` from the loaded
/// point), with coefficients polynomial in `z` and `nu`. (That these reproduce the point-force
/// solutions in this crate's convention was checked by computer algebra, and the results below
/// against quadrature of those solutions in the tests.) For a uniform load on the rectangle,
/// `Omega` is replaced by its integral over the rectangle, `Σ W(X, Y)` with
/// `∂²W/∂X∂Y = Omega` and the corner sum
///
/// ```text
/// Σ f = f(x - x1, y - y1) - f(x - x2, y - y1) - f(x - x1, y - y2) + f(x - x2, y - y2).
/// ```
///
/// Every derivative that contains `∂/∂X` and `∂/∂Y` is a derivative of `Omega` itself; the
/// others need one integration, done in closed form with `∇²Omega = 0` (functions of `X` alone
/// or `Y` alone cancel in the corner sum, so any antiderivative serves). With
///
/// ```text
/// Tx = atan[X Y (X² + Y²) / ((R + z)(X² R + z Y²))]    (∂Tx/∂Y = X / (R (R + z)))
/// Ty = Tx with X and Y exchanged                        (Tx + Ty ≡ atan[X Y / (z R)])
/// Ax = z X / (R (R + Y)),  Bx = z² / (R (R + Y)),  Ay, By the same with X and Y exchanged,
/// U1 = X / (R + z),  U2 = z X / (R (R + z)),  V1 = Y / (R + z),  V2 = z Y / (R (R + z)),
/// W = z / R,  LX = ln(R + X),  LY = ln(R + Y),  LZ = ln(R + z),
/// ```
///
/// and `k = 1 / (2 pi)`, the three loads give
///
/// ```text
/// pressure  sxx = -k Σ(Tx + 2nu Ty + Ax)       syy = -k Σ(Ty + 2nu Tx + Ay)
///           szz = -k Σ(Tx + Ty - Ax - Ay)      syz = -k Σ By,   sxz = -k Σ Bx
///           sxy =  k Σ((2nu - 1) LZ - W)
/// qx        sxx =  k Σ(2 LY + 2nu V1 + Bx + V2)   syy = k Σ(2nu LY - 2nu V1 - V2)
///           szz = -k Σ Bx,   syz = -k Σ W,   sxz = -k Σ(Tx + Ty + Ax)
///           sxy =  k Σ(LX - U2 - 2nu U1)
/// ```
///
/// and `qy` the same as `qx` with the roles of x and y exchanged (`Tx <-> Ty`, `Ax <-> Ay`,
/// `Bx <-> By`, `U <-> V`, `LX <-> LY`; `sxx <-> syy`, `sxz <-> syz`), which by symmetry of the
/// half-space is the Cerruti solution turned by a right angle. The pressure's result solves
/// the problem of Love (1929), here derived afresh rather than transcribed; the tangential
/// ones are the corresponding integrals of Cerruti's solution (for the same problem see
/// Johnson 1985, ch. 3, and Liu & Wang 2002).
///
/// ## Evaluation
/// - Each corner is evaluated in the dimensionless variables `X/R`, `Y/R`, `z/R`; apart from
///   forming `R` and `sqrt(X² + z²)` (guarded against overflow and underflow), nothing is
///   squared but numbers of modulus at most one.
/// - `R + Y` (and `R + X`) cancel when `Y < 0`; there `1/(R + Y) = (R - Y)/(X² + z²)`.
/// - The logarithms enter only with constant coefficients, so they are summed as differences
///   along an edge, `ln(R1 + Y1) - ln(R2 + Y2)`, each formed with `ln_1p` of the exact
///   difference of its arguments (`Y1 - Y2` times a factor without cancellation), and, where
///   the edge crosses `Y = 0`, as `ln(R1 + Y1) + ln(R2 - Y2) - 2 ln sqrt(X² + z²)`. This keeps
///   the results finite on the surface on the extensions of the edges outside the rectangle,
///   where the corner terms are singular but their differences are not.
/// - `Tx` and `Ty` are arc tangents of a fraction with a denominator `>= 0`, evaluated by
///   `atan::atan2_right` (within 1.4 units in the last place; on a row of corners, on vector
///   registers).
/// - `Tx` is taken as 0 where its fraction is `0/0` (a corner exactly above the point, or on
///   the surface at `X = 0`, the mean of the values on the two sides).
///
/// ## Validity and accuracy
/// Any `z >= 0`, any point. For `z > 0` every result is finite. On the surface `z = 0` the
/// results are the surface tractions' stresses: `szz = -p`, `sxz = -qx`, `syz = -qy` strictly
/// inside the rectangle and 0 outside (half of that on an edge, a quarter at a corner, the mean
/// of the two sides). Some surface components are logarithmically singular at the rectangle's
/// edges and are returned as infinite exactly there, and only there: `sxx` and `syy` of `qx` on
/// the edges `x = x1`, `x = x2` (with `y1 <= y <= y2`), `sxy` of `qx` on the edges `y = y1`,
/// `y = y2`, the same with x and y exchanged for `qy`, and the pressure's `sxy` at the corners.
///
/// Absolute accuracy, in units of the traction, is a few ulps of the corner terms, which are
/// of order one (the logarithms grow like the logarithm of the distance). Far from the
/// rectangle the result falls like `(size/distance)²` while the corner terms do not, so its
/// relative accuracy degrades like `eps (distance/size)²`: measured (tests/patch.rs) about
/// `50 eps (distance/size)²`, i.e. 1e-10 at a hundred sizes. For sums over many cells, as in
/// [`super::dcfft`], the absolute accuracy is what counts. Lengths must lie between about
/// 1e-150 and 1e150 (in any unit).
///
/// ## References
/// - A. E. H. Love, The stress produced in a semi-infinite solid by pressure on part of the
///   boundary, *Phil. Trans. R. Soc. A* 228 (1929).
/// - K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §3.2 (Love's
///   potentials, Boussinesq and Cerruti).
/// - S. Liu, Q. Wang, Studying contact stress fields caused by surface tractions with a discrete
///   convolution and fast Fourier transform algorithm, *ASME J. Tribol.* 124 (2002) 36–45.
#[inline]
pub fn uniform_patch(x: f64, y: f64, z: f64, rect: Rectangle, nu: f64) -> PatchStresses {
    // -0.0 -> +0.0, so that no denominator below is a negative zero.
    let z = z + 0.0;
    let columns = [Edge::new(x - rect.x1, z), Edge::new(x - rect.x2, z)];
    let rows = [Edge::new(y - rect.y1, z), Edge::new(y - rect.y2, z)];
    let corner = |i: usize, j: usize| Corner::new(columns[i], rows[j], z);
    let corners = [[corner(0, 0), corner(0, 1)], [corner(1, 0), corner(1, 1)]];
    // Σ ln(R + Y) = D(X1) - D(X2) with D(X) = ln(R + Y1) - ln(R + Y2) along the column X.
    let ln_y =
        [0, 1].map(|i| log_difference(rows, columns[i].rho, corners[i][0].r, corners[i][1].r));
    let ln_x =
        [0, 1].map(|j| log_difference(columns, rows[j].rho, corners[0][j].r, corners[1][j].r));
    let sums = CornerSums::new(&corners, ln_x[0] - ln_x[1], ln_y[0] - ln_y[1]);
    sums.stresses(nu)
}

/// [`uniform_patch`] for the rectangle `dx x dy` centred on the origin (one cell of a grid),
/// at every offset `(a dx, b dy, z)`, `0 <= a < nx`, `0 <= b < ny`: calls `f(a, b, stresses)`
/// row by row (`b` outer).
///
/// The same formulas as [`uniform_patch`], but each corner term is evaluated once for the four
/// cells that share the corner, and each logarithm difference once for the two cells that
/// share the edge: about a quarter of the transcendental functions. The corners lie at
/// `((k - 1/2) dx, (l - 1/2) dy)`; the results agree with [`uniform_patch`] to rounding.
pub fn uniform_patch_offsets(
    cell: [f64; 2],
    z: f64,
    counts: [usize; 2],
    nu: f64,
    f: impl FnMut(usize, usize, &PatchStresses),
) {
    uniform_patch_offset_rows(cell, z, counts[0], 0..counts[1], nu, f);
}

/// [`uniform_patch_offsets`] for the rows `b` in `rows` only (and `0 <= a < nx`), so that
/// disjoint blocks of rows can be computed independently; each block evaluates one row of
/// corners more than its share.
pub fn uniform_patch_offset_rows(
    cell: [f64; 2],
    z: f64,
    nx: usize,
    rows: std::ops::Range<usize>,
    nu: f64,
    mut f: impl FnMut(usize, usize, &PatchStresses),
) {
    offset_sums(cell, z, nx, rows, false, |b, sums| {
        for a in sums.columns() {
            f(a, b, &sums.at(a).stresses(nu));
        }
    });
}

/// The corner sums of [`uniform_patch_offset_rows`], a row of offsets at a time: calls
/// `f(b, sums)` with the sums of the cells `a` in `sums.columns()` of row `b` (from which
/// [`RowSums::component`] gives each load's stresses along the row). With `diagonal`, only the
/// cells `a >= b`: on a grid of square cells the others are those cells turned about the
/// diagonal `x = y` (the pressure's stresses with x and y exchanged, the shear along x's those
/// of the shear along y; see [`uniform_patch`]), and their corners are not evaluated (about
/// half of them).
///
/// Each term is held as an array along the row: the corners' terms, their differences along
/// the row of corners (shared by the cells below and above it), and the cells' sums, the
/// difference of two such rows.
pub(crate) fn offset_sums(
    cell: [f64; 2],
    z: f64,
    nx: usize,
    rows: std::ops::Range<usize>,
    diagonal: bool,
    f: impl FnMut(usize, &RowSums),
) {
    // The first column of row b (and of the corners below and above it).
    let first = move |b: usize| if diagonal { b.min(nx) } else { 0 };
    // One range of cells a row.
    let cells = |b: usize| std::iter::once(first(b)..nx).collect();
    offset_sums_in(cell, z, nx, rows, false, cells, f);
}

/// [`offset_sums`] over chosen cells of each row: calls `f(b, sums)` for each row `b` of
/// `rows`, rising or (with `falling`) falling, with the sums of the cells `a` in the ranges
/// `cells(b)` (disjoint, increasing, within `0..nx`; [`RowSums::cells`]). The row of corners
/// that a row shares with the next one is evaluated once, for the cells of the first: the
/// cells of each row must lie among those of the row before it. Each cell's sums are those
/// of [`offset_sums`] to the last bit, whichever cells are taken with it.
pub(crate) fn offset_sums_in(
    cell: [f64; 2],
    z: f64,
    nx: usize,
    rows: std::ops::Range<usize>,
    falling: bool,
    mut cells: impl FnMut(usize) -> Vec<std::ops::Range<usize>>,
    mut f: impl FnMut(usize, &RowSums),
) {
    let z = z + 0.0;
    let [dx, dy] = cell;
    let columns: Vec<Edge> = (0..=nx)
        .map(|k| Edge::new((k as f64 - 0.5) * dx, z))
        .collect();
    // The row of corners k, between the rows of cells k - 1 and k.
    let corner_row = |k: usize| Edge::new((k as f64 - 0.5) * dy, z);
    let mut terms: [Vec<f64>; CORNER_TERMS] = std::array::from_fn(|_| vec![0.0; nx + 1]);
    // `shared`: the row of corners the previous row of cells shares with this one.
    let (mut shared, mut next) = (CornerRow::new(nx), CornerRow::new(nx));
    let mut sums = RowSums::new(nx);
    let mut ln_y = vec![0.0; nx + 1];
    let order: Box<dyn Iterator<Item = usize>> = if falling {
        Box::new(rows.clone().rev())
    } else {
        Box::new(rows.clone())
    };
    let mut shared_row = None;
    for b in order {
        sums.cells = cells(b);
        let (near, far) = if falling { (b + 1, b) } else { (b, b + 1) };
        let near_row = match shared_row {
            Some(row) => row,
            None => {
                let row = corner_row(near);
                shared.evaluate(&sums.cells, &columns, row, z, &mut terms);
                row
            }
        };
        let far_row = corner_row(far);
        next.evaluate(&sums.cells, &columns, far_row, z, &mut terms);
        let ((above, row_above), (below, row_below)) = if falling {
            ((&shared, near_row), (&next, far_row))
        } else {
            ((&next, far_row), (&shared, near_row))
        };
        for range in &sums.cells {
            let (from, to) = (range.start, range.end);
            for (sum, (up, down)) in sums.terms[..CORNER_TERMS]
                .iter_mut()
                .zip(above.steps.iter().zip(&below.steps))
            {
                for (s, (u, d)) in sum[from..to]
                    .iter_mut()
                    .zip(up[from..to].iter().zip(&down[from..to]))
                {
                    *s = u - d;
                }
            }
            // Σ ln(R + X) = E(Y_(b+1)) - E(Y_b), with E(Y) = ln(R + X_(a+1)) - ln(R + X_a).
            for (s, (u, d)) in sums.terms[LX][from..to]
                .iter_mut()
                .zip(above.ln_x[from..to].iter().zip(&below.ln_x[from..to]))
            {
                *s = u - d;
            }
            // Σ ln(R + Y) = D(X_(a+1)) - D(X_a), with D(X) = ln(R + Y_(b+1)) - ln(R + Y_b)
            // along each column of corners.
            for k in from..=to {
                ln_y[k] = log_difference(
                    [row_above, row_below],
                    columns[k].rho,
                    above.r[k],
                    below.r[k],
                );
            }
            for a in from..to {
                sums.terms[LY][a] = ln_y[a + 1] - ln_y[a];
            }
        }
        f(b, &sums);
        std::mem::swap(&mut shared, &mut next);
        shared_row = Some(far_row);
    }
}

/// The number of [`Corner`] terms, and the indices of all terms of [`CornerSums`].
const CORNER_TERMS: usize = 12;
const TERMS: usize = 14;
const TX: usize = 0;
const TY: usize = 1;
const AX: usize = 2;
const BX: usize = 3;
const AY: usize = 4;
const BY: usize = 5;
const U1: usize = 6;
const U2: usize = 7;
const V1: usize = 8;
const V2: usize = 9;
const W: usize = 10;
const LZ: usize = 11;
const LX: usize = 12;
const LY: usize = 13;

/// One row of corners `k = 0..=nx` (from some first column on): the distances `R`, the
/// differences of each corner term between neighbours, `steps[t][k] = t(k + 1) - t(k)`, and
/// `ln_x[k] = ln(R + X_(k+1)) - ln(R + X_k)`.
struct CornerRow {
    r: Vec<f64>,
    steps: [Vec<f64>; CORNER_TERMS],
    ln_x: Vec<f64>,
    /// The second arguments of the arc tangents `Tx`, `Ty`.
    denominators: [Vec<f64>; 2],
}

impl CornerRow {
    fn new(nx: usize) -> Self {
        Self {
            r: vec![0.0; nx + 1],
            steps: std::array::from_fn(|_| vec![0.0; nx + 1]),
            ln_x: vec![0.0; nx + 1],
            denominators: [vec![0.0; nx + 1], vec![0.0; nx + 1]],
        }
    }

    /// Evaluates the corners `(X_k, Y)` of the row `row` at both ends of the cells `a` in
    /// `cells` (`start <= k <= end` for each range), holding their terms in `terms` before
    /// they are differenced.
    fn evaluate(
        &mut self,
        cells: &[std::ops::Range<usize>],
        columns: &[Edge],
        row: Edge,
        z: f64,
        terms: &mut [Vec<f64>; CORNER_TERMS],
    ) {
        for range in cells {
            let (from, to) = (range.start, range.end);
            for (k, &column) in columns.iter().enumerate().take(to + 1).skip(from) {
                let (corner, [x, y]) = Corner::before_arc_tangents(column, row, z);
                self.r[k] = corner.r;
                for (term, value) in terms.iter_mut().zip(corner.terms) {
                    term[k] = value;
                }
                self.denominators[0][k] = x;
                self.denominators[1][k] = y;
            }
            let [x, y] = &self.denominators;
            atan2_right_in_place(&mut terms[TX][from..=to], &x[from..=to]);
            atan2_right_in_place(&mut terms[TY][from..=to], &y[from..=to]);
            for (steps, terms) in self.steps.iter_mut().zip(terms.iter()) {
                for k in from..to {
                    steps[k] = terms[k + 1] - terms[k];
                }
            }
            for k in from..to {
                let pair = [columns[k + 1], columns[k]];
                self.ln_x[k] = log_difference(pair, row.rho, self.r[k + 1], self.r[k]);
            }
        }
    }
}

/// The corner sums of one row of cells `b` ([`offset_sums`]): `terms[t][a]` for the cells `a`
/// in [`RowSums::columns`].
pub(crate) struct RowSums {
    cells: Vec<std::ops::Range<usize>>,
    terms: [Vec<f64>; TERMS],
}

impl RowSums {
    fn new(nx: usize) -> Self {
        Self {
            cells: Vec::new(),
            terms: std::array::from_fn(|_| vec![0.0; nx + 1]),
        }
    }

    /// The cells `a` of the row, of [`offset_sums`] (one range).
    pub(crate) fn columns(&self) -> std::ops::Range<usize> {
        self.cells[0].clone()
    }

    /// The ranges of cells `a` of the row, of [`offset_sums_in`].
    pub(crate) fn cells(&self) -> &[std::ops::Range<usize>] {
        &self.cells
    }

    /// The sums of cell `a`.
    pub(crate) fn at(&self, a: usize) -> CornerSums {
        CornerSums(std::array::from_fn(|t| self.terms[t][a]))
    }

    /// Component `c` (in the order `xx, yy, zz, yz, xz, xy`) of the stresses of `load` along
    /// the row: `out[i]` for the cell `a = columns().start + i`.
    pub(crate) fn component(&self, load: Load, c: usize, nu: f64, out: &mut [f64]) {
        self.component_in(load, c, nu, self.columns(), out);
    }

    /// [`RowSums::component`] of the cells `a` in `range` (one of [`RowSums::cells`] or
    /// part of one): `out[i]` for the cell `a = range.start + i`.
    pub(crate) fn component_in(
        &self,
        load: Load,
        c: usize,
        nu: f64,
        range: std::ops::Range<usize>,
        out: &mut [f64],
    ) {
        let [(t0, k0), (t1, k1), (t2, k2), (t3, k3)] = formula(load, c, nu);
        let term = |t: usize| &self.terms[t][range.clone()];
        // The terms used come first; the rest have coefficient 0 on the finite `Tx`, so
        // leaving them out changes nothing but the sign of a zero. Counted at a Poisson
        // ratio where no used coefficient vanishes (at 0 or 0.5 some do).
        let used = formula(load, c, 0.3)
            .iter()
            .filter(|(_, k)| *k != 0.0)
            .count();
        match used {
            0 | 1 => {
                for (o, v0) in out.iter_mut().zip(term(t0)) {
                    *o = k0 * v0;
                }
            }
            2 => {
                for ((o, v0), v1) in out.iter_mut().zip(term(t0)).zip(term(t1)) {
                    *o = k0 * v0 + k1 * v1;
                }
            }
            3 => {
                for (((o, v0), v1), v2) in out.iter_mut().zip(term(t0)).zip(term(t1)).zip(term(t2))
                {
                    *o = k0 * v0 + k1 * v1 + k2 * v2;
                }
            }
            _ => {
                for ((((o, v0), v1), v2), v3) in out
                    .iter_mut()
                    .zip(term(t0))
                    .zip(term(t1))
                    .zip(term(t2))
                    .zip(term(t3))
                {
                    *o = k0 * v0 + k1 * v1 + k2 * v2 + k3 * v3;
                }
            }
        }
    }
}

/// The stresses of the unit `load` as a linear combination of the corner sums (the formulas
/// of [`uniform_patch`]): component `c` is `Σ coefficient × term` over the four pairs
/// `(term, coefficient)` (unused pairs have coefficient 0 on the always finite `Tx`).
fn formula(load: Load, c: usize, nu: f64) -> [(usize, f64); 4] {
    let k = 0.5 / PI;
    let n = 2.0 * nu * k;
    let none = (TX, 0.0);
    match (load, c) {
        (Load::Pressure, 0) => [(TX, -k), (TY, -n), (AX, -k), none],
        (Load::Pressure, 1) => [(TY, -k), (TX, -n), (AY, -k), none],
        (Load::Pressure, 2) => [(TX, -k), (TY, -k), (AX, k), (AY, k)],
        (Load::Pressure, 3) => [(BY, -k), none, none, none],
        (Load::Pressure, 4) => [(BX, -k), none, none, none],
        (Load::Pressure, _) => [(LZ, n - k), (W, -k), none, none],
        (Load::ShearX, 0) => [(LY, 2.0 * k), (V1, n), (BX, k), (V2, k)],
        (Load::ShearX, 1) => [(LY, n), (V1, -n), (V2, -k), none],
        (Load::ShearX, 2) => [(BX, -k), none, none, none],
        (Load::ShearX, 3) => [(W, -k), none, none, none],
        (Load::ShearX, 4) => [(TX, -k), (TY, -k), (AX, -k), none],
        (Load::ShearX, _) => [(LX, k), (U2, -k), (U1, -n), none],
        (Load::ShearY, 0) => [(LX, n), (U1, -n), (U2, -k), none],
        (Load::ShearY, 1) => [(LX, 2.0 * k), (U1, n), (BY, k), (U2, k)],
        (Load::ShearY, 2) => [(BY, -k), none, none, none],
        (Load::ShearY, 3) => [(TX, -k), (TY, -k), (AY, -k), none],
        (Load::ShearY, 4) => [(W, -k), none, none, none],
        (Load::ShearY, _) => [(LY, k), (V2, -k), (V1, -n), none],
    }
}

/// One edge line of the rectangle seen from the point: the offset `X = x - x_i` (or
/// `Y = y - y_j`) and the distance `sqrt(X² + z²)` from the point to the line.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Edge {
    pub(crate) offset: f64,
    pub(crate) rho: f64,
}

impl Edge {
    #[inline]
    pub(crate) fn new(offset: f64, z: f64) -> Self {
        Self {
            offset,
            rho: norm2(offset, z),
        }
    }
}

/// The corner terms of [`uniform_patch`] at one corner `(X, Y)` (all but the logarithms of
/// `R + X` and `R + Y`, which are formed as differences along the edges).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Corner {
    pub(crate) r: f64,
    /// `Tx, Ty, Ax, Bx, Ay, By, U1, U2, V1, V2, W, LZ` (indexed by [`TX`] ... [`LZ`]).
    terms: [f64; CORNER_TERMS],
}

impl Corner {
    /// The corner `(X, Y)` of the column `X` and the row `Y`, at depth `z`.
    #[inline]
    pub(crate) fn new(column: Edge, row: Edge, z: f64) -> Self {
        let (mut corner, [x, y]) = Self::before_arc_tangents(column, row, z);
        corner.terms[TX] = atan2_right(corner.terms[TX], x);
        corner.terms[TY] = atan2_right(corner.terms[TY], y);
        corner
    }

    /// [`Corner::new`] but for the arc tangents: `Tx` and `Ty` hold the first arguments of
    /// theirs, the second ones are returned (`Tx = atan2_right(terms[TX], x)`, the same for
    /// `Ty`), so that a row of corners takes its arc tangents in one loop.
    #[inline]
    fn before_arc_tangents(column: Edge, row: Edge, z: f64) -> (Self, [f64; 2]) {
        let (x, y, rho_x, rho_y) = (column.offset, row.offset, column.rho, row.rho);
        let r = norm3(x, y, z);
        if r == 0.0 {
            // The corner itself, on the surface: only ln(R + z) is singular; every bounded
            // term is taken as 0 (the arc tangents of 0 over 0 are 0).
            let mut terms = [0.0; CORNER_TERMS];
            terms[LZ] = f64::NEG_INFINITY;
            return (Self { r, terms }, [0.0; 2]);
        }
        let inverse_r = 1.0 / r;
        let (u, v, w) = (x * inverse_r, y * inverse_r, z * inverse_r);
        let (uu, vv) = (u * u, v * v);
        let one_plus_w = 1.0 + w;
        let numerator = u * v * (uu + vv);
        // Denominators are >= 0; atan2(0, 0) = 0 is the mean of the two sides.
        let (tx, ty) = (numerator, numerator);
        let denominators = [one_plus_w * (uu + w * vv), one_plus_w * (vv + w * uu)];
        // (z X, z²) / (R (R + Y)), dimensionless: (w u, w²) / (1 + v); `across` is X.
        let over_r_plus = |along: f64, across: f64, across_over_r: f64, rho: f64| {
            if along >= 0.0 {
                let k = w / (1.0 + along);
                (k * across_over_r, k * w)
            } else if rho > 0.0 {
                // 1 + v = (rho / R)² / (1 - v) with rho² = X² + z², so
                // w u / (1 + v) = (z / rho)(X / rho)(1 - v).
                let inverse_rho = 1.0 / rho;
                let (z_rho, across_rho) = (z * inverse_rho, across * inverse_rho);
                (
                    z_rho * across_rho * (1.0 - along),
                    z_rho * z_rho * (1.0 - along),
                )
            } else {
                (0.0, 0.0)
            }
        };
        let (ax, bx) = over_r_plus(v, x, u, rho_x);
        let (ay, by) = over_r_plus(u, y, v, rho_y);
        let inverse_one_plus_w = 1.0 / one_plus_w;
        let terms = [
            tx,
            ty,
            ax,
            bx,
            ay,
            by,
            u * inverse_one_plus_w,
            w * u * inverse_one_plus_w,
            v * inverse_one_plus_w,
            w * v * inverse_one_plus_w,
            w,
            (r + z).ln(),
        ];
        (Self { r, terms }, denominators)
    }
}

/// `ln(r1 + a1) - ln(r2 + a2)` for the offsets `a1 > a2` of the two edges `[near, far]`, with
/// `r_i = sqrt(a_i² + rho²)`, without cancellation.
///
/// The difference of the arguments is `(a1 - a2)(1 + (a1 + a2)/(r1 + r2))`, exactly, and for
/// `a <= 0` the argument is `rho² / (r - a)`. Infinite (`+inf`) only where the segment
/// `a2..a1` contains 0 and `rho = 0`: on a loaded edge at the surface.
#[inline]
pub(crate) fn log_difference(edges: [Edge; 2], rho: f64, r1: f64, r2: f64) -> f64 {
    let (a1, a2) = (edges[0].offset, edges[1].offset);
    let width = a1 - a2;
    let ratio = (a1 + a2) / (r1 + r2);
    if a2 >= 0.0 {
        (width * (1.0 + ratio) / (r2 + a2)).ln_1p()
    } else if a1 <= 0.0 {
        // ln(r + a) = ln(rho²) - ln(r - a); the rho terms cancel.
        (width * (1.0 - ratio) / (r1 - a1)).ln_1p()
    } else if rho > 0.0 {
        (r1 + a1).ln() + (r2 - a2).ln() - 2.0 * rho.ln()
    } else {
        f64::INFINITY
    }
}

/// The corner sums of every term of [`uniform_patch`], indexed by [`TX`] ... [`LY`].
#[derive(Clone, Copy, Debug)]
pub(crate) struct CornerSums([f64; TERMS]);

impl CornerSums {
    /// `corners[i][j]` at `(x - x_{i+1}, y - y_{j+1})`; `lx = Σ ln(R + X)`, `ly = Σ ln(R + Y)`.
    #[inline]
    pub(crate) fn new(corners: &[[Corner; 2]; 2], lx: f64, ly: f64) -> Self {
        let [[c11, c12], [c21, c22]] = corners;
        let mut terms = [0.0; TERMS];
        for (t, sum) in terms[..CORNER_TERMS].iter_mut().enumerate() {
            *sum = (c11.terms[t] - c21.terms[t]) - (c12.terms[t] - c22.terms[t]);
        }
        terms[LX] = lx;
        terms[LY] = ly;
        Self(terms)
    }

    /// The stresses of the three unit loads.
    #[inline]
    pub(crate) fn stresses(&self, nu: f64) -> PatchStresses {
        PatchStresses {
            pressure: self.load(Load::Pressure, nu),
            shear_x: self.load(Load::ShearX, nu),
            shear_y: self.load(Load::ShearY, nu),
        }
    }

    /// The stresses of one unit load ([`formula`]).
    #[inline]
    pub(crate) fn load(&self, load: Load, nu: f64) -> Stress {
        let c = |c: usize| {
            formula(load, c, nu)
                .iter()
                .map(|&(t, k)| k * self.0[t])
                .sum::<f64>()
        };
        Stress {
            xx: c(0),
            yy: c(1),
            zz: c(2),
            yz: c(3),
            xz: c(4),
            xy: c(5),
        }
    }
}

/// `sqrt(a² + b²)` without overflow or underflow of the squares.
#[inline]
fn norm2(a: f64, b: f64) -> f64 {
    let s = a * a + b * b;
    if (1e-290..=1e290).contains(&s) {
        s.sqrt()
    } else {
        a.hypot(b)
    }
}

/// `sqrt(a² + b² + c²)` without overflow or underflow of the squares.
#[inline]
fn norm3(a: f64, b: f64, c: f64) -> f64 {
    let s = a * a + b * b + c * c;
    if (1e-290..=1e290).contains(&s) {
        s.sqrt()
    } else {
        a.hypot(b).hypot(c)
    }
}

#[cfg(test)]
mod tests;

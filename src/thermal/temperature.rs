//! Steady temperature rise of a half-space whose surface is heated by a flux that moves over
//! it: the moving point source of Carslaw & Jaeger integrated over uniformly heated cells.
//!
//! ## The point source
//! A heat source `Q` (W) moving at speed `V` in +x over the adiabatic surface of a half-space
//! (conductivity `K`, diffusivity `κ`) raises the steady temperature, in the frame of the source,
//! by (Carslaw & Jaeger 1959, §10.7; Jaeger 1942)
//!
//! ```text
//! θ(x, y, z) = Q / (2π K R) · exp(-u (R + x)),   R = √(x² + y² + z²),   u = V / (2κ),
//! ```
//!
//! `x` the distance ahead of the source: ahead (`x > 0`) the body is still cold, behind it the
//! heat is swept into a wake. `u = 0` is the stationary source `Q / (2π K R)` (a body that
//! carries the contact with it, a pin).
//!
//! ## Cells
//! A unit flux on the cell centred at offset `(X, Y)` gives, at depth `z`, `K θ = ∫∫ G` with
//! `G = exp(-u (R + x)) / (2π R)`, split as `1/(2π R)` plus the bounded remainder
//! `expm1(-u (R + x)) / (2π R)` (at most `u / π` in size). The first is integrated in closed
//! form: `∫∫ dx dy / R` over a rectangle is the sum over its corners, with alternating signs,
//! of
//!
//! ```text
//! F(X, Y) = X asinh(Y / √(X² + z²)) + Y asinh(X / √(Y² + z²)) - z atan(X Y / (z R))
//! ```
//!
//! (Love 1929 at `z = 0`; differentiate to check `∂²F/∂X∂Y = 1/R`). The remainder is
//! integrated by Gauss–Legendre: 6 x 6 points per cell within 16 cells of the source, 4 x 4
//! beyond, and 4 x 4 sub-cells of 8 x 8 points within two cells (where `G`'s direction-dependent
//! limit at `R = 0` lies on a sub-cell corner). While the cell Péclet number `u dx` is at most
//! [`MAX_CELL_PECLET`] the remainder changes by at most `e^-4` across a cell and these rules
//! resolve it to better than 1e-4 of the temperature.
//!
//! ## References
//! - H. S. Carslaw, J. C. Jaeger, *Conduction of Heat in Solids*, 2nd ed., Oxford (1959).
//! - J. C. Jaeger, Moving sources of heat and the temperature at sliding contacts, *Proc. R.
//!   Soc. N. S. W.* 76 (1942).
//! - A. E. H. Love, *Phil. Trans. R. Soc. A* 228 (1929).

use std::f64::consts::PI;

use ndarray::{Array2, ArrayView2};

use super::kernel::{CellGrid, Convolution};
use super::special::gauss_legendre;
use crate::operator::transform::TransformError;

/// The largest cell Péclet number `u dx = V dx / (2κ)` that the cell rules resolve: a finer
/// grid is needed beyond it (the heat penetrates less than a cell in the time the contact
/// crosses one).
pub const MAX_CELL_PECLET: f64 = 2.0;

/// `F(X, Y)` of the module doc at depth `z`; a term is 0 where its factor is 0.
#[inline]
fn corner(x: f64, y: f64, z: f64) -> f64 {
    let first = if x == 0.0 {
        0.0
    } else {
        x * (y / x.hypot(z)).asinh()
    };
    let second = if y == 0.0 {
        0.0
    } else {
        y * (x / y.hypot(z)).asinh()
    };
    let third = if z == 0.0 || x == 0.0 || y == 0.0 {
        0.0
    } else {
        let r = (x * x + y * y + z * z).sqrt();
        z * (x * y / (z * r)).atan()
    };
    first + second - third
}

/// `∫∫ dx dy / (2π R)` over the rectangle `[x0, x1] x [y0, y1]` at depth `z`.
pub fn stationary_rectangle(x0: f64, x1: f64, y0: f64, y1: f64, z: f64) -> f64 {
    (corner(x1, y1, z) - corner(x1, y0, z) - corner(x0, y1, z) + corner(x0, y0, z)) / (2.0 * PI)
}

/// `K θ` per unit flux: the temperature rise times the conductivity at `(0, 0, z)` from a unit
/// flux on the rectangle `[x0, x1] x [y0, y1]` moving with `u = V / (2κ)` (1/m), by the
/// module doc's split with a Gauss–Legendre rule of `n x n` points on `sub x sub` sub-cells.
fn rectangle(x0: f64, x1: f64, y0: f64, y1: f64, z: f64, u: f64, rule: &Rule) -> f64 {
    let mut total = stationary_rectangle(x0, x1, y0, y1, z);
    if u == 0.0 {
        return total;
    }
    let (sx, sy) = ((x1 - x0) / rule.sub as f64, (y1 - y0) / rule.sub as f64);
    let mut sum = 0.0;
    for a in 0..rule.sub {
        for b in 0..rule.sub {
            let (cx, cy) = (x0 + (a as f64 + 0.5) * sx, y0 + (b as f64 + 0.5) * sy);
            for (tx, wx) in rule.nodes.iter().zip(&rule.weights) {
                let x = cx + 0.5 * sx * tx;
                for (ty, wy) in rule.nodes.iter().zip(&rule.weights) {
                    let y = cy + 0.5 * sy * ty;
                    let r = (x * x + y * y + z * z).sqrt();
                    sum += wx * wy * (-u * (r + x)).exp_m1() / r;
                }
            }
        }
    }
    total += sum * 0.25 * sx * sy / (2.0 * PI);
    total
}

/// A Gauss–Legendre product rule on sub-cells.
struct Rule {
    sub: usize,
    nodes: Vec<f64>,
    weights: Vec<f64>,
}

impl Rule {
    fn new(sub: usize, points: usize) -> Self {
        let (nodes, weights) = gauss_legendre(points);
        Self {
            sub,
            nodes,
            weights,
        }
    }
}

/// The three rules of the module doc, by distance from the source.
struct Rules {
    near: Rule,
    middle: Rule,
    far: Rule,
}

impl Rules {
    fn new() -> Self {
        Self {
            near: Rule::new(4, 8),
            middle: Rule::new(1, 6),
            far: Rule::new(1, 4),
        }
    }

    fn for_offset(&self, i: i64, j: i64) -> &Rule {
        match i.abs().max(j.abs()) {
            0..=2 => &self.near,
            3..=16 => &self.middle,
            _ => &self.far,
        }
    }
}

/// `K θ` per unit flux at depth `z` below the centre of the cell offset by `(i, j)` cells from a
/// heated cell of the grid (the influence coefficient), for `u = V / (2κ)`.
pub fn cell_temperature(grid: &CellGrid, i: i64, j: i64, z: f64, u: f64) -> f64 {
    cell_temperature_with(grid, i, j, z, u, &Rules::new())
}

fn cell_temperature_with(grid: &CellGrid, i: i64, j: i64, z: f64, u: f64, rules: &Rules) -> f64 {
    let [dx, dy] = grid.spacing_m;
    let (x, y) = (i as f64 * dx, j as f64 * dy);
    rectangle(
        x - 0.5 * dx,
        x + 0.5 * dx,
        y - 0.5 * dy,
        y + 0.5 * dy,
        z,
        u,
        rules.for_offset(i, j),
    )
}

/// The temperature rise at depth `z` of a half-space of conductivity `K` under a gridded flux
/// moving with `u = V / (2κ)`: `θ = (1/K) C * q` by DC-FFT.
pub struct TemperatureOperator {
    convolution: Convolution,
    scale: f64,
}

impl TemperatureOperator {
    /// The operator at depth `z` (m) for `u = V / (2κ)` (1/m, 0 for a stationary source) and
    /// conductivity `K` (W/(m K)).
    pub fn new(
        grid: &CellGrid,
        z: f64,
        u: f64,
        conductivity_w_per_m_k: f64,
    ) -> Result<Self, TransformError> {
        let rules = Rules::new();
        let lattice = grid.offset_lattice(|i, j| cell_temperature_with(grid, i, j, z, u, &rules));
        Ok(Self {
            convolution: Convolution::new(grid.shape, lattice.view())?,
            scale: 1.0 / conductivity_w_per_m_k,
        })
    }

    /// The temperature rise (K) on the grid under `flux` (W/m², `[ny, nx]`).
    pub fn apply(&mut self, flux: ArrayView2<f64>) -> Result<Array2<f64>, TransformError> {
        let mut out = Array2::zeros(self.convolution.shape());
        self.convolution.apply(flux, out.view_mut())?;
        out.mapv_inplace(|t| t * self.scale);
        Ok(out)
    }
}

/// The temperature rise (K) along row `row` of the grid at depth `z` under `flux` (W/m²,
/// `[ny, nx]`) moving with `u = V / (2κ)`, for conductivity `K`: row `row` of
/// [`TemperatureOperator`]'s result, summed directly, `θ_i = (1/K) Σ q_jc C(i - c, row - j)`.
/// Only the influence coefficients of the offsets from the rows that carry flux are computed,
/// once for `±j` (a cell's coefficient is even in `y`), so a section through a contact (one
/// row at many depths) costs a few percent of the whole grid's lattice.
pub fn row_temperature(
    grid: &CellGrid,
    flux: ArrayView2<f64>,
    row: usize,
    z: f64,
    u: f64,
    conductivity_w_per_m_k: f64,
) -> Vec<f64> {
    let [ny, nx] = grid.shape;
    let heated: Vec<usize> = (0..ny)
        .filter(|&j| flux.row(j).iter().any(|&q| q != 0.0))
        .collect();
    let distance = |j: usize| (j as i64 - row as i64).abs();
    let mut offsets: Vec<i64> = heated.iter().map(|&j| distance(j)).collect();
    offsets.sort_unstable();
    offsets.dedup();
    // The lattice row of each offset.
    let mut index = vec![0; ny];
    for (k, &d) in offsets.iter().enumerate() {
        index[d as usize] = k;
    }
    let rules = Rules::new();
    let lattice = grid.offset_rows(&offsets, |i, j| {
        cell_temperature_with(grid, i, j, z, u, &rules)
    });
    let mut out = vec![0.0; nx];
    for &j in &heated {
        let line = lattice.row(index[distance(j) as usize]);
        for (c, &q) in flux.row(j).iter().enumerate() {
            if q == 0.0 {
                continue;
            }
            // Target column i sees the source column c at offset i - c, stored at i - c + nx - 1.
            for (i, slot) in out.iter_mut().enumerate() {
                *slot += q * line[i + nx - 1 - c];
            }
        }
    }
    let scale = 1.0 / conductivity_w_per_m_k;
    out.iter_mut().for_each(|t| *t *= scale);
    out
}

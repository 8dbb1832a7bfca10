//! Thermoelastic stress in a half-space heated at its surface by a flux moving over it
//! (quasi-static, uncoupled), as influence coefficients of uniformly heated cells.
//!
//! ## Frequency-response functions
//! Transform in the surface, `f(x, y) = (1/4π²) ∫∫ f̂(ξ, η) exp(i(ξx + ηy)) dξ dη`, `k² = ξ² +
//! η²`. In the frame of a flux moving at `V` in +x the heat equation `κ ∇²T = -V ∂T/∂x` with
//! `-K ∂T/∂z = q` at `z = 0` gives `T̂ = q̂ exp(-γz) / (K γ)`, `γ² = k² - i V ξ / κ`, `Re γ > 0`
//! (Carslaw & Jaeger 1959; Liu & Wang 2001). The thermoelastic field is Goodier's potential
//! `φ`, `∇²φ = m T`, `m = (1 + ν) α / (1 - ν)`, `u = ∇φ`, `σij = 2G (φ,ij - δij ∇²φ)`, taken as
//! `φ̂ = m T̂0 (e^(-γz) - e^(-kz)) / (γ² - k²)` (regular as `γ -> k`), plus Papkovich–Neuber
//! solutions A (`φ_A`) and B (`ω`) of Barber (*Elasticity*, 2010, ch. 20) with harmonic
//! `exp(-kz)` that cancel the shear traction Goodier's potential leaves on the surface (its
//! normal traction vanishes already). With `E(z) = (e^(-γz) - e^(-kz)) / (γ² - k²)` and
//! `B = 1 / (γ + k)`, per `E α T̂0 / (1 - ν)` (derived here):
//!
//! ```text
//! σzz = k² E + z k² e^(-kz) B
//! σxz = i ξ [E' + (1 - k z) e^(-kz) B],   σyz = i η [ ... ]
//! σxx = -(ξ² E + e^(-γz)) + [2 (1 - ν) ξ²/k - ξ² z + 2 ν k] e^(-kz) B   (σyy: ξ <-> η)
//! σxy = -ξ η [E + (z - 2 (1 - ν)/k) e^(-kz) B]
//! ```
//!
//! The surface is free of traction (`σzz = σxz = σyz = 0` at `z = 0`); for a stationary source
//! (`γ = k`) `σzz = σxz = σyz = 0` everywhere (Sternberg & McDowell 1957) and
//! `σ̂xx = -E α q̂ η² e^(-kz) / (K k³)`; at high Péclet numbers (`|γ| >> k`) the surface stress
//! tends to `σxx = σyy = -E α T / (1 - ν)`. `E` and `E'` are evaluated as
//! `-z e^(-kz) φ1(-δz) B` and `(γ z φ1(-δz) - 1) e^(-kz) B` with `δ = γ - k = -iVξ/(κ (γ + k))`
//! and `φ1(w) = (e^w - 1)/w`, free of cancellation.
//!
//! ## Influence coefficients
//! The stress at offset `(x, y)` from a cell `dx x dy` of unit flux is the inverse transform of
//! `H(ξ, η) S(ξ, η)`, `S = dx dy sinc(ξ dx/2) sinc(η dy/2)`. Sampling it on the periodic
//! lattice of the DC-FFT grid would fold the `1/k` singularity at `k = 0` (the far field
//! `1/R` of every stress) into a wrong constant, so `H` is split in three:
//! - the stationary part `H_s` (zero for `σzz`, `σxz`, `σyz`), integrated over the cell in
//!   closed form: with `f = (z ln(R + z) - R) / (2π)`, the inverse of `e^(-kz)/k³`, the
//!   stresses per `E α / K` are `σxx = ∂²f/∂y²`, `σyy = ∂²f/∂x²`, `σxy = -∂²f/∂x∂y`, whose cell
//!   integrals are corner sums of
//!   `Fxx = [-Y asinh(X/√(Y² + z²)) + z atan(X Y (R - z) / (Y² R + X² z))] / (2π)`,
//!   `Fyy(X, Y) = Fxx(Y, X)` and `Fxy = -f`;
//! - near `k = 0`, `W (H - H_s)` with `W = exp(-k²/kw²)`, `kw = 8π / min(2 nx dx, 2 ny dy)`,
//!   integrated directly by a Gauss–Legendre product rule graded towards `ξ = 0` and `η = 0`
//!   on `|ξ|, |η| <= 5 kw` (where `W < 2e-11`);
//! - `(1 - W)(H - H_s)`, free of the singularity, sampled at the discrete wavenumbers of a
//!   periodic lattice four times longer in x than the kernel's (the wake behind a fast source
//!   is long and narrow, so its part above `kw` reaches far behind; not oversampled, or
//!   twice, for a source slow on the lattice's scale, `u <= kw/4` or `u <= kw`), with its
//!   aliases (1 each way within two cells of the surface; none at a cell Péclet
//!   number `u dx <= 0.05`, where the moving part beyond the Nyquist wavenumber is
//!   `O(u dx)` of the exact stationary one), and inverse-transformed by FFT.
//!
//! Against the polar inverse transform of a Gaussian flux (test) the lattice is within 0.06 %
//! for a stationary source and 0.3 % at `u s = 3`; `kw` twice smaller or no oversampling
//! leaves 1 to 3 % (measured).
//!
//! ## References
//! - H. S. Carslaw, J. C. Jaeger, *Conduction of Heat in Solids*, Oxford (1959).
//! - J. N. Goodier, On the integration of the thermo-elastic equations, *Phil. Mag.* 23 (1937).
//! - E. Sternberg, E. L. McDowell, On the steady-state thermoelastic problem for the half-space,
//!   *Q. Appl. Math.* 14 (1957).
//! - J. R. Barber, *Elasticity*, 3rd ed., Springer (2010).
//! - S. Liu, Q. Wang, A three-dimensional thermomechanical model of contact between
//!   non-conforming rough surfaces, *ASME J. Tribol.* 123 (2001).

use std::f64::consts::PI;

use ndarray::{Array2, Array3, ArrayView2, ArrayViewMut2, Axis};
use rayon::prelude::*;
use rustfft::num_complex::Complex;

use super::kernel::{signed, CellGrid};
use super::special::gauss_legendre;
use crate::operator::transform::{signed_index, RealFft2, TransformError};

type C64 = Complex<f64>;

/// The six stress components in [`crate::stress::Stress`] order: xx, yy, zz, yz, xz, xy.
pub const COMPONENTS: usize = 6;

/// The parity of each component's response in `η` (and of its lattice in `y`): `σyz` and
/// `σxy` carry a factor `η`, the others are even.
const PARITY: [f64; COMPONENTS] = [1.0, 1.0, 1.0, -1.0, 1.0, -1.0];

/// How many times longer in x than the kernel's own lattice the periodic lattice of the smooth
/// part is: the narrow wake behind a fast source is long, and its images must lie beyond it.
const SMOOTH_OVERSAMPLING: usize = 4;

/// Below this `u / kw` (a slow source for the lattice: `u (2 nx dx) <= 2π`) the smooth part
/// has no long wake and its lattice is not oversampled; up to `kw`, twice.
const SLOW_OVER_WINDOW: f64 = 0.25;

/// Below this cell Péclet number `u max(dx, dy)` the smooth part takes no aliases.
const ALIAS_FREE_CELL_PECLET: f64 = 0.05;

/// The smooth part's oversampling in x for `u` and the window's `kw` (module doc). The
/// smooth part `(1 - W)(H - H_s)` of a source slow on the lattice's scale is concentrated
/// within a few `1/kw` of the cell (its kernel falls as `1/r³`), so its images `2 nx dx`
/// away are negligible: on the rough ball of `benches/thermal.rs` (`u/kw = 0.2`) the
/// thermal von Mises maximum moved by 4e-5 of itself without oversampling (measured).
pub(crate) fn smooth_oversampling(u: f64, kw: f64) -> usize {
    if u <= SLOW_OVER_WINDOW * kw {
        1
    } else if u <= kw {
        2
    } else {
        SMOOTH_OVERSAMPLING
    }
}

/// [`smooth_oversampling`] on a grid of `shape` and cells `spacing_m` (its window's `kw`).
pub fn smooth_oversampling_of(shape: [usize; 2], spacing_m: [f64; 2], u: f64) -> usize {
    smooth_oversampling(u, window_wavenumber(shape, spacing_m))
}

/// `kw = 8π / min(2 nx dx, 2 ny dy)` of the window (module doc).
fn window_wavenumber(shape: [usize; 2], spacing_m: [f64; 2]) -> f64 {
    let [ny, nx] = shape;
    let [dx, dy] = spacing_m;
    8.0 * PI / (2.0 * nx as f64 * dx).min(2.0 * ny as f64 * dy)
}

/// The aliases each way of the smooth part at depth `z` (module doc): 1 within two cells of
/// the surface, none deeper (`e^(-kz)` then damps them); none either at a cell Péclet number
/// `u dx` below [`ALIAS_FREE_CELL_PECLET`]: beyond the lattice's Nyquist wavenumber
/// `γ = k - i u ξ / k + O(u²)`, so `H - H_s` is `O(u/k)`, at most `u dx / π`, of the
/// stationary response there (whose cell integral is exact); on the rough ball of
/// `benches/thermal.rs` (`u dx = 0.02`) they moved the thermal maximum by 1e-6 (measured).
/// On the surface, against 6 aliases, under a Hertzian flux on 96² cells (a throw-away
/// sweep, 2026-11-28): 1 alias leaves 4e-6, 2e-5 and 9e-5 of the largest stress component
/// at `u dx` = 0.3, 1 and 3 (3 aliases: 5e-7, 3e-6, 1e-5; none: 5e-5, 2e-4, 9e-4), against
/// the lattice's own 1.6e-3 from the polar inverse transform (`thermal::tests`).
fn smooth_aliases(z: f64, u: f64, dx: f64, dy: f64) -> i64 {
    if u * dx.max(dy) <= ALIAS_FREE_CELL_PECLET || z >= 2.0 * dx.min(dy) {
        0
    } else {
        1
    }
}

/// `(e^w - 1) / w` from `e^w` (given), accurate near `w = 0` (its Taylor series there).
fn phi1(w: C64, exp_w: C64) -> C64 {
    if w.norm() < 1e-3 {
        C64::new(1.0, 0.0) + w * (0.5 + w * (1.0 / 6.0 + w / 24.0))
    } else {
        (exp_w - 1.0) / w
    }
}

/// The principal square root of `re + i im` with `re > 0` (so `Re > 0`), without the polar
/// form (no arc tangent, sine or cosine): `s + i im / (2s)` with `s = √((|w| + re)/2)`, whose
/// square is `s² − im²/(4s²) + i im = re + i im` since `4s²(s² − re) = im²` (derived here).
fn principal_sqrt(re: f64, im: f64) -> C64 {
    let modulus = (re * re + im * im).sqrt();
    let real = (0.5 * (modulus + re)).sqrt();
    C64::new(real, 0.5 * im / real)
}

/// `H(ξ, η; z)` of the six stresses per unit flux, `K = 1`, per `E α` (module doc); `two_u` is
/// `V / κ` (1/m). `k` must be positive.
pub fn response(xi: f64, eta: f64, z: f64, two_u: f64, nu: f64) -> [C64; COMPONENTS] {
    let k = (xi * xi + eta * eta).sqrt();
    response_with(xi, eta, k, (-k * z).exp(), z, two_u, nu)
}

/// [`response`] given `k = √(ξ² + η²)` and `e^(-kz)`: `e^(-γz) = e^(-kz) e^(-δz)`, and
/// `φ1(-δz)` from the same exponential.
fn response_with(
    xi: f64,
    eta: f64,
    k: f64,
    ez: f64,
    z: f64,
    two_u: f64,
    nu: f64,
) -> [C64; COMPONENTS] {
    // (No overflow: wavenumbers are far below 1e150.)
    let gamma = principal_sqrt(k * k, -two_u * xi);
    let b = 1.0 / (gamma + k);
    let delta = C64::new(0.0, -two_u * xi) * b;
    let w = -delta * z;
    let exp_w = if z == 0.0 {
        C64::new(1.0, 0.0)
    } else {
        w.exp()
    };
    let p = phi1(w, exp_w);
    let e = -z * ez * p * b;
    let e_prime = (gamma * z * p - 1.0) * ez * b;
    let eg = ez * exp_w;
    let i = C64::new(0.0, 1.0);
    let shear = e_prime + (1.0 - k * z) * ez * b;
    let zz = k * k * e + z * k * k * ez * b;
    let xx = -(xi * xi * e + eg)
        + (2.0 * (1.0 - nu) * xi * xi / k - xi * xi * z + 2.0 * nu * k) * ez * b;
    let yy = -(eta * eta * e + eg)
        + (2.0 * (1.0 - nu) * eta * eta / k - eta * eta * z + 2.0 * nu * k) * ez * b;
    let xy = -xi * eta * (e + (z - 2.0 * (1.0 - nu) / k) * ez * b);
    // Per E α T̂0 / (1 - ν) above; T̂0 = 1 / γ per unit flux with K = 1.
    let scale = 1.0 / ((1.0 - nu) * gamma);
    [
        xx * scale,
        yy * scale,
        zz * scale,
        i * eta * shear * scale,
        i * xi * shear * scale,
        xy * scale,
    ]
}

/// The stationary part `H_s` of [`response`] (zero for zz, yz, xz).
pub fn stationary_response(xi: f64, eta: f64, z: f64) -> [f64; COMPONENTS] {
    let k = (xi * xi + eta * eta).sqrt();
    stationary_with(xi, eta, k, (-k * z).exp())
}

/// [`stationary_response`] given `k` and `e^(-kz)`.
fn stationary_with(xi: f64, eta: f64, k: f64, ez: f64) -> [f64; COMPONENTS] {
    let c = ez / (k * k * k);
    [-eta * eta * c, -xi * xi * c, 0.0, 0.0, 0.0, xi * eta * c]
}

/// `H - H_s`, the moving part.
fn remainder(xi: f64, eta: f64, z: f64, two_u: f64, nu: f64) -> [C64; COMPONENTS] {
    if two_u == 0.0 {
        return [C64::new(0.0, 0.0); COMPONENTS];
    }
    let k = (xi * xi + eta * eta).sqrt();
    let ez = (-k * z).exp();
    let mut h = response_with(xi, eta, k, ez, z, two_u, nu);
    for (value, s) in h.iter_mut().zip(stationary_with(xi, eta, k, ez)) {
        *value -= s;
    }
    h
}

/// `Fxx` of the module doc (without the 1/(2π)).
fn corner_xx(x: f64, y: f64, z: f64) -> f64 {
    let first = if y == 0.0 {
        0.0
    } else {
        -y * (x / (y * y + z * z).sqrt()).asinh()
    };
    let second = if z == 0.0 || x == 0.0 || y == 0.0 {
        0.0
    } else {
        let r = (x * x + y * y + z * z).sqrt();
        z * (x * y * (r - z) / (y * y * r + x * x * z)).atan()
    };
    first + second
}

/// `Fxy` of the module doc (without the 1/(2π)).
fn corner_xy(x: f64, y: f64, z: f64) -> f64 {
    let r = (x * x + y * y + z * z).sqrt();
    let log = if z == 0.0 { 0.0 } else { z * (r + z).ln() };
    -(log - r)
}

/// `[Fxx, Fyy, Fxy]` (without the 1/(2π)) at the corners `((m + 1/2) dx, (l + 1/2) dy)`,
/// `0 <= m <= nx`, `0 <= l <= ny`: row-major, `nx + 1` a row. These are all the corners of
/// the cells of offsets `-n <= i, j < n` up to sign: `Fxx` and `Fyy` are odd in `x` and in
/// `y`, `Fxy` is even in both ([`StationaryCorners::fold`]).
struct StationaryCorners {
    values: Vec<[f64; 3]>,
}

impl StationaryCorners {
    fn new(grid: &CellGrid, z: f64) -> Self {
        let [ny, nx] = grid.shape;
        let [dx, dy] = grid.spacing_m;
        let width = nx + 1;
        let mut values = vec![[0.0; 3]; (ny + 1) * width];
        values
            .par_chunks_mut(width)
            .enumerate()
            .for_each(|(l, line)| {
                let y = (l as f64 + 0.5) * dy;
                for (m, slot) in line.iter_mut().enumerate() {
                    let x = (m as f64 + 0.5) * dx;
                    *slot = [corner_xx(x, y, z), corner_xx(y, x, z), corner_xy(x, y, z)];
                }
            });
        Self { values }
    }

    /// The corner `c` (`0 <= c <= 2n`) of an axis of `n` cells each way lies at
    /// `(c - n - 1/2)` cells: `(|m|, sign)` with the corner at `sign (m + 1/2)`.
    fn fold(c: usize, n: usize) -> (usize, f64) {
        if c > n {
            (c - n - 1, 1.0)
        } else {
            (n - c, -1.0)
        }
    }
}

/// The stationary cell integrals per `E α / K` of xx, yy, xy over `[x0, x1] x [y0, y1]`.
pub fn stationary_rectangle(x0: f64, x1: f64, y0: f64, y1: f64, z: f64) -> [f64; 3] {
    let sum =
        |f: &dyn Fn(f64, f64) -> f64| (f(x1, y1) - f(x1, y0) - f(x0, y1) + f(x0, y0)) / (2.0 * PI);
    [
        sum(&|x, y| corner_xx(x, y, z)),
        sum(&|x, y| corner_xx(y, x, z)),
        sum(&|x, y| corner_xy(x, y, z)),
    ]
}

pub(super) fn sinc(t: f64) -> f64 {
    if t.abs() < 1e-4 {
        1.0 - t * t / 6.0
    } else {
        t.sin() / t
    }
}

/// Nodes and weights on `[0, cut]`: panels graded by 4 towards 0 below `cut / 8`, uniform
/// panels of `7 cut / 128` above, 6 Gauss–Legendre points each.
pub(super) fn band_rule(cut: f64) -> (Vec<f64>, Vec<f64>) {
    let (nodes, weights) = gauss_legendre(6);
    let mut edges = vec![0.0];
    let mut edge = cut / 8.0 / 4f64.powi(6);
    while edge < cut / 8.0 * 0.999 {
        edges.push(edge);
        edge *= 4.0;
    }
    let uniform = 16;
    for k in 0..=uniform {
        edges.push(cut / 8.0 + (cut - cut / 8.0) * k as f64 / uniform as f64);
    }
    let mut xs = Vec::new();
    let mut ws = Vec::new();
    for pair in edges.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        for (t, w) in nodes.iter().zip(&weights) {
            xs.push(0.5 * (a + b) + 0.5 * (b - a) * t);
            ws.push(0.5 * (b - a) * w);
        }
    }
    (xs, ws)
}

impl StationaryCorners {
    /// Writes the stationary lattice of `slot` (0, 1, 2: xx, yy, xy) into `out` (`[2 ny, 2 nx]`,
    /// wrap-around order): each cell's corner sum.
    fn lattice_into(&self, grid: &CellGrid, slot: usize, mut out: ArrayViewMut2<f64>) {
        let [ny, nx] = grid.shape;
        // Each lattice column's two corners (offset + n and the next), folded.
        let column_corners: Vec<[(usize, f64); 2]> = (0..2 * nx)
            .map(|column| {
                let i = (signed(column, 2 * nx) + nx as i64) as usize;
                [
                    StationaryCorners::fold(i, nx),
                    StationaryCorners::fold(i + 1, nx),
                ]
            })
            .collect();
        // Fxx and Fyy are odd in x and y, Fxy even.
        let odd = slot < 2;
        out.axis_iter_mut(Axis(0))
            .into_par_iter()
            .enumerate()
            .for_each(|(row, mut line)| {
                // Cell offset j spans the corners j and j + 1 of the corner grid (offset + n).
                let j = (signed(row, 2 * ny) + ny as i64) as usize;
                let rows = [
                    StationaryCorners::fold(j, ny),
                    StationaryCorners::fold(j + 1, ny),
                ];
                let value = |(l, sy): (usize, f64), (m, sx): (usize, f64)| {
                    let v = self.values[l * (nx + 1) + m][slot];
                    if odd {
                        sx * sy * v
                    } else {
                        v
                    }
                };
                for (slot_value, [c0, c1]) in line.iter_mut().zip(&column_corners) {
                    *slot_value = (value(rows[1], *c1) - value(rows[0], *c1) - value(rows[1], *c0)
                        + value(rows[0], *c0))
                        / (2.0 * PI);
                }
            });
    }
}

/// The components with a stationary part, in the order of [`StationaryCorners`]' values.
const STATIONARY: [usize; 3] = [0, 1, 5];

/// What the six influence-coefficient lattices of the thermal stress per `E α / K` at one
/// depth are built from (module doc): the stationary part's corner values and, for a moving
/// source, the band's weighted values and the smooth part's spectrum, each computed once for
/// the six components. [`InfluenceParts::lattice`] builds one component's lattice at a time,
/// so that the six need not be held together.
pub struct InfluenceParts {
    grid: CellGrid,
    corners: StationaryCorners,
    moving: Option<(Band<COMPONENTS>, Smooth<COMPONENTS>)>,
}

impl InfluenceParts {
    /// At depth `z` for `u = V / (2κ)` and Poisson's ratio `nu`.
    pub fn new(grid: &CellGrid, z: f64, u: f64, nu: f64) -> Self {
        let [dx, dy] = grid.spacing_m;
        // Stationary part: the corner sums of the cells, each corner's three values computed
        // once.
        let corners = StationaryCorners::new(grid, z);
        if u == 0.0 {
            return Self {
                grid: *grid,
                corners,
                moving: None,
            };
        }
        let two_u = 2.0 * u;
        let kw = window_wavenumber(grid.shape, grid.spacing_m);
        // Beyond `k = 6.1 kw`, `W < 2^-53`: `1 - W` is 1 and `W` times a value is below its
        // last digit, so it is not evaluated there.
        let window = |k: f64| {
            if k > 6.1 * kw {
                0.0
            } else {
                (-(k / kw).powi(2)).exp()
            }
        };
        let cell = |xi: f64, eta: f64| dx * dy * sinc(0.5 * xi * dx) * sinc(0.5 * eta * dy);
        let band = Band::new(grid, kw * 5.0, &|xi, eta| {
            let mut h = remainder(xi, eta, z, two_u, nu);
            let s = window((xi * xi + eta * eta).sqrt()) * cell(xi, eta);
            for v in h.iter_mut() {
                *v *= s;
            }
            h
        });
        let aliases = smooth_aliases(z, u, dx, dy);
        let oversampling = smooth_oversampling(u, kw);
        let smooth = Smooth::new(grid, aliases, oversampling, &|xi, eta, form| {
            let k = (xi * xi + eta * eta).sqrt();
            if k == 0.0 {
                return [C64::new(0.0, 0.0); COMPONENTS];
            }
            let mut h = remainder(xi, eta, z, two_u, nu);
            let s = (1.0 - window(k)) * form;
            for v in h.iter_mut() {
                *v *= s;
            }
            h
        });
        Self {
            grid: *grid,
            corners,
            moving: Some((band, smooth)),
        }
    }

    /// The influence-coefficient lattice (`[2 ny, 2 nx]`, wrap-around order) of `component`
    /// ([`COMPONENTS`] order): its stationary part, plus the band's, plus the smooth part's.
    pub fn lattice(&self, component: usize) -> Result<Array2<f64>, TransformError> {
        let [ny, nx] = self.grid.shape;
        let mut out = Array2::zeros((2 * ny, 2 * nx));
        if let Some(slot) = STATIONARY.iter().position(|&c| c == component) {
            self.corners.lattice_into(&self.grid, slot, out.view_mut());
        }
        if let Some((band, smooth)) = &self.moving {
            band.add_to(component, PARITY[component], out.view_mut());
            smooth.add_to(component, PARITY[component], out.view_mut())?;
        }
        Ok(out)
    }
}

/// The six influence-coefficient lattices (`[6, 2 ny, 2 nx]`, wrap-around order) of the
/// thermal stress per `E α / K` at depth `z` for `u = V / (2κ)` (module doc): the six
/// [`InfluenceParts::lattice`]s.
pub fn influence_lattices(
    grid: &CellGrid,
    z: f64,
    u: f64,
    nu: f64,
) -> Result<Array3<f64>, TransformError> {
    let [ny, nx] = grid.shape;
    let parts = InfluenceParts::new(grid, z, u, nu);
    let mut out = Array3::zeros((COMPONENTS, 2 * ny, 2 * nx));
    for component in 0..COMPONENTS {
        out.index_axis_mut(Axis(0), component)
            .assign(&parts.lattice(component)?);
    }
    Ok(out)
}

/// Adds `(1/4π²) ∫∫ F e^(i(ξx + ηy))` over `|ξ|, |η| <= cut` at every lattice offset, for a
/// Hermitian `F` (`F(-ξ, -η) = conj F(ξ, η)`): [`Band`] for each component.
pub(super) fn add_band<const N: usize>(
    out: &mut Array3<f64>,
    grid: &CellGrid,
    cut: f64,
    parity: [f64; N],
    f: &(dyn Fn(f64, f64) -> [C64; N] + Sync),
) {
    let band = Band::new(grid, cut, f);
    for (component, &sign) in parity.iter().enumerate() {
        band.add_to(component, sign, out.index_axis_mut(Axis(0), component));
    }
}

/// `(1/4π²) ∫∫ F e^(i(ξx + ηy))` over `|ξ|, |η| <= cut` at every lattice offset, for a
/// Hermitian `F` (`F(-ξ, -η) = conj F(ξ, η)`): twice the real part of the `ξ > 0` half.
/// Component `c` of `F` has a parity (`+1` even, `-1` odd) in `η`, and so its lattice in `y`:
/// only `η > 0` is evaluated (`e^(iηy) ± e^(-iηy)` is `2 cos ηy` or `2i sin ηy`), the rows
/// `y >= 0` are summed and the rows `y < 0` mirrored, and each sum over `ξ` serves `x` and
/// `-x` (its cosine and sine parts): a quarter of the direct sum's work. `F` is evaluated once
/// for all components ([`Band::new`]), each component's lattice summed when asked
/// ([`Band::add_to`]).
///
/// The product rule's sums are matrix products (ndarray's `dot`, the cache-blocked kernels
/// of `matrixmultiply`): with `A` the weighted values `[ξ, η]` of a component, `C_η` its
/// cosines (or sines) `[η, row]` and `C_ξ`, `S_ξ` the cosines and sines `[ξ, column]`, the
/// sums over `η` are `R = A C_η` (`[ξ, row]`) and the lattice at `±x` is
/// `Re(R)ᵀ C_ξ ∓ Im(R)ᵀ S_ξ` (`[row, column]`): the product rule's double sum, ordered
/// (derived here).
pub(super) struct Band<const N: usize> {
    shape: [usize; 2],
    /// cos ηy and sin ηy for every η > 0 and row (`[η, row]`).
    eta_cos: Array2<f64>,
    eta_sin: Array2<f64>,
    /// cos ξx and sin ξx for every ξ > 0 and column (`[ξ, column]`).
    xi_cos: Array2<f64>,
    xi_sin: Array2<f64>,
    /// The weighted values `2 w_ξ w_η F(ξ, η)`, `[ξ][η]`.
    values: Vec<Vec<[C64; N]>>,
}

impl<const N: usize> Band<N> {
    pub(super) fn new(
        grid: &CellGrid,
        cut: f64,
        f: &(dyn Fn(f64, f64) -> [C64; N] + Sync),
    ) -> Self {
        let [ny, nx] = grid.shape;
        let [dx, dy] = grid.spacing_m;
        let (half, half_weights) = band_rule(cut);
        let m = half.len();
        // Rows y = j dy and columns x = i dx for 0 <= j <= ny, 0 <= i <= nx (the lattice's -ny
        // and -nx mirrored from +ny and +nx).
        let trig = |step: f64, count: usize| {
            let cosines =
                Array2::from_shape_fn((m, count), |(n, i)| (half[n] * i as f64 * step).cos());
            let sines =
                Array2::from_shape_fn((m, count), |(n, i)| (half[n] * i as f64 * step).sin());
            (cosines, sines)
        };
        let (eta_cos, eta_sin) = trig(dy, ny + 1);
        let (xi_cos, xi_sin) = trig(dx, nx + 1);
        let values: Vec<Vec<[C64; N]>> = half
            .par_iter()
            .zip(&half_weights)
            .map(|(&xi, &w_xi)| {
                half.iter()
                    .zip(&half_weights)
                    .map(|(&eta, &w)| {
                        let mut v = f(xi, eta);
                        for c in v.iter_mut() {
                            *c *= 2.0 * w * w_xi;
                        }
                        v
                    })
                    .collect()
            })
            .collect();
        Self {
            shape: grid.shape,
            eta_cos,
            eta_sin,
            xi_cos,
            xi_sin,
            values,
        }
    }

    /// Adds the sum of `component`, of parity `parity` in `η`, to its lattice `layer`
    /// (`[2 ny, 2 nx]`, wrap-around order).
    pub(super) fn add_to(&self, component: usize, parity: f64, mut layer: ArrayViewMut2<f64>) {
        let [ny, nx] = self.shape;
        let m = self.values.len();
        let rows = ny + 1;
        let scale = 2.0 / (4.0 * PI * PI);
        let values = &self.values;
        let even = parity > 0.0;
        let real = Array2::from_shape_fn((m, m), |(n, e)| values[n][e][component].re);
        let imaginary = Array2::from_shape_fn((m, m), |(n, e)| values[n][e][component].im);
        let table = if even { &self.eta_cos } else { &self.eta_sin };
        // Over η: `[ξ, row]`; the odd part's `2i sin ηy` turns (re, im) into (-im, re).
        let (row_re, row_im) = rayon::join(|| real.dot(table), || imaginary.dot(table));
        let (row_re, row_im) = if even {
            (row_re, row_im)
        } else {
            (row_im.mapv(|v| -v), row_re)
        };
        // Over ξ: P = Σ re cos ξx and Q = Σ im sin ξx, `[row, column]` for x >= 0: (P - Q) at
        // x, (P + Q) at -x.
        let (p, q) = rayon::join(
            || row_re.t().dot(&self.xi_cos),
            || row_im.t().dot(&self.xi_sin),
        );
        for j in 0..rows {
            let (p_row, q_row) = (p.row(j), q.row(j));
            let value = |column: usize| {
                let i = signed(column, 2 * nx);
                let at = i.unsigned_abs() as usize;
                scale
                    * if i >= 0 {
                        p_row[at] - q_row[at]
                    } else {
                        p_row[at] + q_row[at]
                    }
            };
            // Row +j (j < ny), and -j (1 <= j <= ny) at lattice row 2ny - j.
            if j < ny {
                for (column, slot) in layer.row_mut(j).iter_mut().enumerate() {
                    *slot += value(column);
                }
            }
            if j >= 1 {
                for (column, slot) in layer.row_mut(2 * ny - j).iter_mut().enumerate() {
                    *slot += parity * value(column);
                }
            }
        }
    }
}

/// Adds the lattice samples of the inverse transform of `F` (free of a singularity at `k = 0`)
/// from its values at the lattice's discrete wavenumbers and `aliases` aliases each way:
/// [`Smooth`] for each component. (A failure of the transform is a planning bug; the lattice
/// then keeps its other parts.)
pub(super) fn add_smooth<const N: usize>(
    out: &mut Array3<f64>,
    grid: &CellGrid,
    aliases: i64,
    over: usize,
    parity: [f64; N],
    f: &(dyn Fn(f64, f64, f64) -> [C64; N] + Sync),
) {
    let smooth = Smooth::new(grid, aliases, over, f);
    for (component, &sign) in parity.iter().enumerate() {
        if smooth
            .add_to(component, sign, out.index_axis_mut(Axis(0), component))
            .is_err()
        {
            break;
        }
    }
}

/// The lattice samples of the inverse transform of `F` (free of a singularity at `k = 0`)
/// from its values at the discrete wavenumbers of a periodic lattice `over` times longer in x
/// than the kernel's (images farther) and `aliases` aliases each way. `F` is given `(ξ, η)`
/// and the cell's form factor there, `dx dy sinc(ξ dx/2) sinc(η dy/2)`, whose two sines are
/// computed once a column and a row; it is evaluated once for all components
/// ([`Smooth::new`]: 16 bytes a component a value of half the periodic lattice's spectrum),
/// each component transformed when asked ([`Smooth::add_to`]). A component with the parity
/// `±1` in `η` has its values at `η < 0` from those at `-η`, so only `η >= 0` is evaluated.
pub(super) struct Smooth<const N: usize> {
    shape: [usize; 2],
    spacing_m: [f64; 2],
    /// The periodic lattice's transforms, `[2 ny, 2 nx over]`.
    plan: RealFft2,
    /// Each column's values for `0 <= ky <= my/2` (`η >= 0`).
    columns: Vec<Vec<[C64; N]>>,
}

impl<const N: usize> Smooth<N> {
    pub(super) fn new(
        grid: &CellGrid,
        aliases: i64,
        over: usize,
        f: &(dyn Fn(f64, f64, f64) -> [C64; N] + Sync),
    ) -> Self {
        let [ny, nx] = grid.shape;
        let [dx, dy] = grid.spacing_m;
        let (mx, my) = (2 * nx * over, 2 * ny);
        let plan = RealFft2::new([my, mx]);
        let [kxs, _] = plan.spectrum_shape();
        let (px, py) = (mx as f64 * dx, my as f64 * dy);
        let half_rows = my / 2 + 1;
        // Each wavenumber with its aliases, `(value, sinc(value d/2))`.
        let with_aliases = |base: f64, d: f64| -> Vec<(f64, f64)> {
            (-aliases..=aliases)
                .map(|a| {
                    let value = base + 2.0 * PI * a as f64 / d;
                    (value, sinc(0.5 * value * d))
                })
                .collect()
        };
        let etas: Vec<Vec<(f64, f64)>> = (0..half_rows)
            .map(|ky| with_aliases(2.0 * PI * signed_index(ky, my) as f64 / py, dy))
            .collect();
        let columns: Vec<Vec<[C64; N]>> = (0..kxs)
            .into_par_iter()
            .map(|kx| {
                let xis = with_aliases(2.0 * PI * kx as f64 / px, dx);
                etas.iter()
                    .map(|eta_aliases| {
                        let mut sum = [C64::new(0.0, 0.0); N];
                        for &(xi, sinc_xi) in &xis {
                            for &(eta, sinc_eta) in eta_aliases {
                                for (s, v) in
                                    sum.iter_mut().zip(f(xi, eta, dx * dy * sinc_xi * sinc_eta))
                                {
                                    *s += v;
                                }
                            }
                        }
                        sum
                    })
                    .collect()
            })
            .collect();
        Self {
            shape: grid.shape,
            spacing_m: grid.spacing_m,
            plan,
            columns,
        }
    }

    /// Adds the samples of `component`, of parity `parity` in `η` (the rows `my/2 < ky < my`,
    /// `η < 0`, are `parity` times those of `my - ky`: the aliases of `-η0` are those of `η0`
    /// mirrored), to its lattice `layer` (`[2 ny, 2 nx]`, wrap-around order): the periodic
    /// lattice's offsets `-nx <= i < nx`, transformed straight into it.
    pub(super) fn add_to(
        &self,
        component: usize,
        parity: f64,
        layer: ArrayViewMut2<f64>,
    ) -> Result<(), TransformError> {
        let nx = self.shape[1];
        let [dx, dy] = self.spacing_m;
        let [my, mx] = self.plan.shape();
        let half_rows = my / 2 + 1;
        let value = |kx: usize, ky: usize| {
            if ky < half_rows {
                self.columns[kx][ky][component]
            } else {
                self.columns[kx][my - ky][component] * parity
            }
        };
        let mut spectrum = self.plan.new_spectrum();
        for ((kx, ky), slot) in spectrum.indexed_iter_mut() {
            *slot = value(kx, ky) / (dx * dy);
        }
        // The periodic lattice's column of each lattice column.
        let sources: Vec<usize> = (0..2 * nx)
            .map(|column| {
                let i = signed(column, 2 * nx);
                if i >= 0 {
                    i as usize
                } else {
                    (mx as i64 + i) as usize
                }
            })
            .collect();
        let mut work = self.plan.work();
        self.plan
            .inverse_add_columns(&mut spectrum, layer, &sources, &mut work)
    }
}

/// The thermal stress (Pa) of body 1 at one depth under a gridded flux: six DC-FFT
/// convolutions. It keeps what the six lattices are built from ([`InfluenceParts`]), not the
/// lattices: each lattice is built when applied, transformed and dropped, one at a time (a
/// layer is applied once; the six lattices held at once took 192 bytes a cell, their spectra
/// as much again).
pub struct ThermalStressOperator {
    shape: [usize; 2],
    parts: InfluenceParts,
    scale: f64,
}

impl ThermalStressOperator {
    /// At depth `z` (m) for `u = V / (2κ)` (1/m), Poisson's ratio `ν`, and `E α / K` (Pa m/W).
    pub fn new(
        grid: &CellGrid,
        z: f64,
        u: f64,
        nu: f64,
        modulus_expansion_over_conductivity: f64,
    ) -> Result<Self, TransformError> {
        let parts = InfluenceParts::new(grid, z, u, nu);
        Ok(Self {
            shape: grid.shape,
            parts,
            scale: modulus_expansion_over_conductivity,
        })
    }

    /// Bytes held while a layer of `shape` is computed with the smooth part's lattice
    /// oversampled `over` times in x ([`smooth_oversampling`], 0 for a stationary source): the
    /// stationary part's corners (24 bytes a corner), the smooth part's values (96 bytes a
    /// value of `[nx over + 1, ny + 1]`), one lattice `[2 ny, 2 nx]` (8 bytes a value) and the
    /// larger of its smooth part's spectrum (16 bytes a value of `[nx over + 1, 2 ny]`) and its
    /// own with the transform's rows (twice 16 bytes a value of `[nx + 1, 2 ny]`), the flux's
    /// spectrum and the layer `[6, ny, nx]` (8 bytes a value).
    pub fn memory_bytes(shape: [usize; 2], over: usize) -> usize {
        let [ny, nx] = shape;
        let spectrum = (nx + 1) * 2 * ny * 16;
        let smooth_spectrum = (nx * over + 1) * 2 * ny * 16;
        (ny + 1) * (nx + 1) * 24
            + (nx * over + 1) * (ny + 1) * 96
            + 4 * ny * nx * 8
            + smooth_spectrum.max(2 * spectrum)
            + spectrum
            + COMPONENTS * ny * nx * 8
    }

    /// `[6, ny, nx]`: xx, yy, zz, yz, xz, xy (Pa) under `flux` (W/m²).
    pub fn apply(&mut self, flux: ArrayView2<f64>) -> Result<Array3<f64>, TransformError> {
        let [ny, nx] = self.shape;
        let plan = RealFft2::new([2 * ny, 2 * nx]);
        let mut out = Array3::zeros((COMPONENTS, ny, nx));
        // One transform of the flux for the six kernels.
        let mut flux_spectrum = plan.new_spectrum();
        plan.forward(flux, &mut flux_spectrum, &mut plan.work())?;
        for component in 0..COMPONENTS {
            // The lattice first, then the buffers of its transform: the smooth part's
            // transform and this one are never held together.
            let lattice = self.parts.lattice(component)?;
            let mut work = plan.work();
            let mut spectrum = plan.new_spectrum();
            plan.forward(lattice.view(), &mut spectrum, &mut work)?;
            drop(lattice);
            spectrum.zip_mut_with(&flux_spectrum, |value, &q| *value *= q);
            let mut layer = out.index_axis_mut(Axis(0), component);
            plan.inverse(&mut spectrum, layer.view_mut(), &mut work)?;
            layer.mapv_inplace(|s| s * self.scale);
        }
        Ok(out)
    }
}

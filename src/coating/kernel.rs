//! The influence coefficients of a coated body in contact: the normal surface displacement of
//! cells of uniform pressure on a layered half-space (plus the counter-body's), laid out for
//! the contact solver's integral operator ([`crate::operator::elastic::ElasticOperator`]),
//! non-periodic (DC-FFT) or periodic.
//!
//! ## The split
//! The layered compliance `G(k) = C(kh) / k` ([`super::response`]) behaves as `2 / (E1' k)`
//! (the coating's half-space) at large `k` and as `2 / (E2' k)` (the substrate's) as `k -> 0`;
//! neither singular part can be sampled on a grid. It is split as
//!
//! ```text
//! G(k) + 2/(Eb' k) = 2/(E*top k) + (2/k)(1/E2' - 1/E1') e^(-kc) + R(k)
//! 1/E*top = 1/E1' + 1/Eb',   R(k) = [C(kh) - 2/E1' - 2 (1/E2' - 1/E1') e^(-kc)] / k
//! ```
//!
//! (`Eb'` the counter-body's plane-strain modulus, infinite when rigid; `c = h`). The first
//! term is Love's uniformly loaded rectangle ([`crate::operator::elastic`]); the second, in
//! real space `1 / (π E sqrt(r² + c²))` (the transform pair `2π e^(-kc)/k <->
//! 1/sqrt(r² + c²)`), integrated over a cell in closed form,
//!
//! ```text
//! ∫∫ dx dy / sqrt(x² + y² + c²) = [x asinh(y/sqrt(x² + c²)) + y asinh(x/sqrt(y² + c²))
//!                                  - c atan(xy / (c R))] at the four corners
//! ```
//!
//! (derived here; it reduces to Love's corner function at `c = 0`; tested against quadrature).
//! The rest `R(k)` is finite at `k = 0` (the `1/k` parts cancel there) and decays as
//! `e^(-kh)`: a smooth function in real space, of width `h`. It is split by a window
//! (as [`super::stress`] splits the stress waves; derived here):
//!
//! ```text
//! R = R (1 - w) + R w,     w = (1 + s) e^(-s),   s = (k / k_w)²,   k_w = α / L
//! ```
//!
//! (`L` the larger side of the extended grid below, `α` = [`SPLIT`]).
//! - `R (1 - w)` is sampled spectrally with the cells' form factor `sinc(kx dx/2)
//!   sinc(ky dy/2)` on a grid twice the padded one and transformed back. `1 - w` vanishes as
//!   `k⁴` at `k = 0`, so its real-space kernel is `R` less `R` smoothed by a bump of width
//!   `L/α` with no second moments: it falls beyond `max(h, L/α)` as `(L / α h)⁴` of `R`, and
//!   its periodic images (at least three grid lengths away) are negligible however thick the
//!   coating. The aliases of the form factor are left out: with `h >= 2` cells they weigh at
//!   most `e^(-2π)` of `R` near the Nyquist wavenumber ([`MIN_THICKNESS_CELLS`]).
//! - `R w` (nothing beyond `k = 6 k_w`, where `w < 1e-14`) is the Hankel transform
//!   `dx dy (1/2π) ∫ R w F̄ J0(kr) k dk` (`F̄` the form factor averaged over direction, 8
//!   Gauss points), by Gauss–Legendre quadrature on panels fine enough for both `R`, which
//!   bends over `Δk ~ 1/h`, and `J0(kr)` across the grid; it is smooth over `L/α` (many
//!   cells), so tabulated in `r` every `1/(2 · 6 k_w)` and interpolated by cubics.
//!
//! Without the split (the whole of `R` on the lattice of the extended grid) a coating much
//! thicker than the grid put all of `R`'s low wavenumbers, which bend over `1/h`, into the
//! mean mode `R(0)`: a constant added to every coefficient, `R(0) / L²` instead of about
//! `R(0) / h²` (the approach of 10 mm of TiN on steel 33 % too large, of a 100 mm PEEK liner
//! negative). With it, the thick limit is the coating's own Hertz contact, approach included
//! (`crate::coating::tests`).
//!
//! A periodic contact takes Love's periodic kernel with `E*top` and adds
//! `[C(kh) - 2/E1'] / k` times the form factor at every wavenumber but the mean (which a
//! periodic operator drops).

use std::f64::consts::PI;

use ndarray::Array2;

use super::response::{plane_strain_modulus, Layered};
use crate::operator::elastic::{uniform_patch_displacement, Periodicity};
use crate::operator::transform::{signed_index, RealFft2, TransformError};

/// The thinnest coating a grid resolves, in cells (the larger cell side): below it the
/// neglected aliases of the remainder `R` (module doc) and of the stress waves exceed
/// `e^(-2π)`, and a coating thinner than two cells has no stress samples inside it.
pub const MIN_THICKNESS_CELLS: f64 = 2.0;

/// `∫∫ dx dy / sqrt(x² + y² + c²)` up to terms of `x` or `y` alone (module doc).
fn smoothed_corner(x: f64, y: f64, c: f64) -> f64 {
    let r = (x * x + y * y + c * c).sqrt();
    let first = if x == 0.0 {
        0.0
    } else {
        x * (y / (x * x + c * c).sqrt()).asinh()
    };
    let second = if y == 0.0 {
        0.0
    } else {
        y * (x / (y * y + c * c).sqrt()).asinh()
    };
    let third = if c == 0.0 || r == 0.0 {
        0.0
    } else {
        c * (x * y / (c * r)).atan()
    };
    first + second - third
}

/// `∫∫ dA / sqrt((x - x')² + (y - y')² + c²)` over the rectangle `|x'| <= half_x`,
/// `|y'| <= half_y`.
pub fn smoothed_patch(x: f64, y: f64, half_x: f64, half_y: f64, c: f64) -> f64 {
    smoothed_corner(x + half_x, y + half_y, c)
        - smoothed_corner(x + half_x, y - half_y, c)
        - smoothed_corner(x - half_x, y + half_y, c)
        + smoothed_corner(x - half_x, y - half_y, c)
}

fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-8 {
        1.0 - x * x / 6.0
    } else {
        x.sin() / x
    }
}

/// The remainder `R(k)` of the module doc, m/Pa per m² (`k` in 1/m), with `c = h`; the
/// line contact's kernel ([`super::line`]) takes the same function of `k` (its module doc).
pub(super) fn remainder(layered: &Layered, k: f64) -> f64 {
    let h = layered.thickness_m;
    let (e1, e2) = (
        plane_strain_modulus(&layered.coating),
        plane_strain_modulus(&layered.substrate),
    );
    let at = |k: f64| {
        (layered.normal_compliance_times_k(k * h)
            - 2.0 / e1
            - 2.0 * (1.0 / e2 - 1.0 / e1) * (-k * h).exp())
            / k
    };
    if k * h < 1e-3 {
        // Finite at k = 0: linear extrapolation from two small wavenumbers (R = β + γ k + ...).
        let k1 = 1e-3 / h;
        let (r1, r2) = (at(k1), at(2.0 * k1));
        r1 + (r1 - r2) * (k1 - k) / k1
    } else {
        at(k)
    }
}

/// The remainder `R(k)` tabulated in `K = kh`: `R` depends on `|k|` only (an isotropic
/// layer), so one table serves every wavenumber of a grid, in place of one six-by-six wave
/// solve per distinct `(|kx|, |ky|)` (261 000 of them on the extended grid of 255² cells).
///
/// Nodes every [`Self::STEP`] in `K` from `STEP/2` to [`Self::K_MAX`], each `R` by
/// [`remainder`] (off `K = 0`, where `R` is a limit: below the first node, and at the mean
/// mode `k = 0`, the cubic through the first four nodes extrapolates it);
/// between them the cubic through the four nearest nodes (Lagrange), whose error is at most
/// `max |d⁴R/dK⁴| ΔK⁴ / 24` times the largest `|u (u - 1)(u - 2)(u - 3)|` over the interval
/// used (`u` in [1, 2] away from the ends: 9/16; Abramowitz & Stegun 25.2.13 and 25.2.14):
/// measured 4.5e-10 of `max |R|` against [`remainder`] for `K >= 0.1` and 1.9e-9 below
/// (B4C on steel; `the_radial_table_is_the_remainder_to_its_stated_error`). Beyond `K_MAX` the layer's
/// influence on the surface has decayed as `e^(-2K)` and the far term's as `e^(-K)`: `k R` is
/// below `4e-18 |2/E2' - 2/E1'|`, less than the rounding of `C(kh)` itself (about 1e-16 of
/// `2/E1'`), and is taken as 0.
///
/// ## Reference
/// M. Abramowitz, I. A. Stegun, *Handbook of Mathematical Functions* (1964), 25.2.13–14
/// (Lagrange interpolation and its remainder).
pub(crate) struct RemainderTable {
    thickness_m: f64,
    /// The node spacing in `K`: [`Self::STEP`], or for a stack thicker than its top layer
    /// `STEP` times `h / H` (`H` the stack's thickness, over which `R` bends at small `K`).
    step: f64,
    /// `R(K_j / h) / h` at `K_j = (j + 1/2) step`, Pa⁻¹.
    values: Vec<f64>,
}

impl RemainderTable {
    /// The node spacing in `K = kh`.
    pub(crate) const STEP: f64 = 0.0025;
    /// The largest `K` tabulated; `R = 0` beyond.
    pub(crate) const K_MAX: f64 = 40.0;

    pub(crate) fn new(layered: &Layered) -> Self {
        let h = layered.thickness_m;
        let step = Self::STEP * (h / layered.total_thickness_m()).min(1.0);
        let nodes = (Self::K_MAX / step).round() as usize + 1;
        Self {
            thickness_m: h,
            step,
            values: (0..nodes)
                .map(|j| remainder(layered, (j as f64 + 0.5) * step / h) / h)
                .collect(),
        }
    }

    /// `R(k)`, m/Pa per m² (`k` in 1/m, `k >= 0`).
    pub(crate) fn at(&self, k: f64) -> f64 {
        let big_k = k * self.thickness_m;
        if big_k.is_nan() || big_k >= Self::K_MAX {
            return 0.0;
        }
        // Position in nodes; below the first node (K < STEP/2) the first four extrapolate.
        let t = big_k / self.step - 0.5;
        let n = self.values.len();
        let first = if t < 1.0 {
            0
        } else {
            (t.floor() as usize - 1).min(n - 4)
        };
        let u = t - first as f64;
        let v = &self.values[first..first + 4];
        let weights = [
            -(u - 1.0) * (u - 2.0) * (u - 3.0) / 6.0,
            u * (u - 2.0) * (u - 3.0) / 2.0,
            -u * (u - 1.0) * (u - 3.0) / 2.0,
            u * (u - 1.0) * (u - 2.0) / 6.0,
        ];
        self.thickness_m * weights.iter().zip(v).map(|(w, f)| w * f).sum::<f64>()
    }
}

/// `α` of the split (module doc): the window's width `k_w = α / L`.
pub const SPLIT: f64 = 24.0;

/// The largest `s = (k / k_w)²` of the window: beyond, `w = (1 + s) e^(-s) < 1e-14`.
const WINDOW_CUTOFF: f64 = 36.0;

/// The window `w(k)` of the split (module doc).
fn window(k: f64, k_w: f64) -> f64 {
    let s = (k / k_w).powi(2);
    if s > WINDOW_CUTOFF {
        0.0
    } else {
        (1.0 + s) * (-s).exp()
    }
}

/// The real-space kernel (m/Pa) of the windowed remainder `R w` (module doc) at the distance
/// `r` from a cell `spacing_m`: `dx dy (1/2π) ∫ R w F̄ J0(kr) k dk`, tabulated in `r` to
/// `reach_m` and interpolated by cubics.
struct WindowedRemainder {
    step_m: f64,
    /// The kernel at `r = (j - 1) step` (`j = 0` mirrors `j = 2`: the kernel is even in `r`).
    values: Vec<f64>,
}

impl WindowedRemainder {
    fn new(table: &RemainderTable, k_w: f64, spacing_m: [f64; 2], reach_m: f64) -> Self {
        let [dx, dy] = spacing_m;
        let h = table.thickness_m;
        let k_max = WINDOW_CUTOFF.sqrt() * k_w;
        // Panels: at most 0.25/h wide where R bends (K = kh < 40), and narrow enough for
        // J0(k r) across the grid (k reach <= 2 per panel).
        let bent = (RemainderTable::K_MAX / h).min(k_max);
        let mut edges = vec![0.0];
        let coarse_width = (2.0 / reach_m).min(k_max / 48.0);
        let fine = (bent * h / 0.25).max(bent / coarse_width).ceil().max(1.0) as usize;
        for i in 1..=fine {
            edges.push(bent * i as f64 / fine as f64);
        }
        let rest = ((k_max - bent) / coarse_width).ceil() as usize;
        for i in 1..=rest {
            edges.push(bent + (k_max - bent) * i as f64 / rest as f64);
        }
        let (points, weights) = crate::thermal::special::gauss_legendre(8);
        let (angles, angle_weights) = crate::thermal::special::gauss_legendre(8);
        let mut nodes = Vec::with_capacity(8 * edges.len());
        for pair in edges.windows(2) {
            let (lo, hi) = (pair[0], pair[1]);
            for (t, w) in points.iter().zip(&weights) {
                let k = 0.5 * (lo + hi) + 0.5 * (hi - lo) * t;
                // F̄: sinc(kx dx/2) sinc(ky dy/2) averaged over θ in [0, π/2].
                let form: f64 = angles
                    .iter()
                    .zip(&angle_weights)
                    .map(|(u, v)| {
                        let theta = 0.25 * PI * (u + 1.0);
                        0.5 * v
                            * sinc(0.5 * k * theta.cos() * dx)
                            * sinc(0.5 * k * theta.sin() * dy)
                    })
                    .sum();
                let weight = 0.5 * (hi - lo) * w;
                nodes.push((k, weight * table.at(k) * window(k, k_w) * form * k));
            }
        }
        let step_m = 1.0 / (2.0 * k_max);
        let count = (reach_m / step_m).ceil() as usize + 4;
        let scale = dx * dy / (2.0 * PI);
        let values = (0..count)
            .map(|j| {
                let r = (j as f64 - 1.0).abs() * step_m;
                scale
                    * nodes
                        .iter()
                        .map(|(k, v)| v * super::reference::bessel_j0(k * r))
                        .sum::<f64>()
            })
            .collect();
        Self { step_m, values }
    }

    /// The kernel at `r_m` (`0 <= r_m <=` the reach it was built for).
    fn at(&self, r_m: f64) -> f64 {
        let position = r_m / self.step_m + 1.0;
        let first = (position.floor() as usize)
            .saturating_sub(1)
            .min(self.values.len() - 4);
        let u = position - first as f64;
        let weights = [
            -(u - 1.0) * (u - 2.0) * (u - 3.0) / 6.0,
            u * (u - 2.0) * (u - 3.0) / 2.0,
            -u * (u - 1.0) * (u - 3.0) / 2.0,
            u * (u - 1.0) * (u - 2.0) / 6.0,
        ];
        weights
            .iter()
            .zip(&self.values[first..first + 4])
            .map(|(w, v)| w * v)
            .sum()
    }
}

/// The counter-body's `(1 - ν²)/E`, Pa⁻¹ (0 for a rigid one).
pub type CounterCompliance = f64;

/// The real-space kernel (m/Pa) of a coated body (and the counter-body of compliance
/// `counter_per_pa`) on cells `spacing_m` of a `[ny, nx]` grid, laid out for
/// [`crate::operator::elastic::ElasticOperator::from_kernel`]: wrap-around order on the
/// `[2ny, 2nx]` grid (non-periodic) or the `[ny, nx]` period.
pub fn kernel_grid(
    layered: &Layered,
    counter_per_pa: CounterCompliance,
    shape: [usize; 2],
    spacing_m: [f64; 2],
    periodicity: Periodicity,
) -> Result<Array2<f64>, TransformError> {
    let [ny, nx] = shape;
    let [dx, dy] = spacing_m;
    let e1 = plane_strain_modulus(&layered.coating);
    let e2 = plane_strain_modulus(&layered.substrate);
    let top = 1.0 / e1 + counter_per_pa;
    let h = layered.thickness_m;
    match periodicity {
        Periodicity::NonPeriodic => {
            let plan_shape = [2 * ny, 2 * nx];
            let mut grid = Array2::zeros((plan_shape[0], plan_shape[1]));
            // The remainder on a grid twice the padded one, less its low wavenumbers, which
            // are transformed radially (module doc).
            let extended = [4 * ny, 4 * nx];
            let table = RemainderTable::new(layered);
            let k_w = SPLIT / (4.0 * (nx as f64 * dx).max(ny as f64 * dy));
            let rest = spectral_real_space(
                extended,
                spacing_m,
                |k| table.at(k) * (1.0 - window(k, k_w)),
                true,
            )?;
            let reach = (nx as f64 * dx).hypot(ny as f64 * dy);
            let low = WindowedRemainder::new(&table, k_w, spacing_m, reach);
            let far = (1.0 / e2 - 1.0 / e1) / PI;
            for j in 0..ny {
                for i in 0..nx {
                    let (ox, oy) = (i as f64 * dx, j as f64 * dy);
                    let love = uniform_patch_displacement(ox, oy, dx / 2.0, dy / 2.0) * top / PI;
                    let smooth = far * smoothed_patch(ox, oy, dx / 2.0, dy / 2.0, h);
                    let value = love + smooth + low.at(ox.hypot(oy));
                    let (jm, im) = ((2 * ny - j) % (2 * ny), (2 * nx - i) % (2 * nx));
                    let (ej, ei) = ((4 * ny - j) % (4 * ny), (4 * nx - i) % (4 * nx));
                    for ((a, b), (c, d)) in [
                        ((j, i), (j, i)),
                        ((jm, i), (ej, i)),
                        ((j, im), (j, ei)),
                        ((jm, im), (ej, ei)),
                    ] {
                        grid[[a, b]] = value + rest[[c, d]];
                    }
                }
            }
            Ok(grid)
        }
        Periodicity::Periodic => {
            let love = crate::operator::elastic::periodic_love_kernel(shape, spacing_m);
            // [C(kh) - 2/E1'] / k = R(k) + (2/k)(1/E2' - 1/E1') e^(-kh) (module doc).
            let table = RemainderTable::new(layered);
            let far = 2.0 * (1.0 / e2 - 1.0 / e1);
            let rest = spectral_real_space(
                shape,
                spacing_m,
                |k| table.at(k) + far * (-k * h).exp() / k,
                false,
            )?;
            Ok(love * (top / PI) + rest)
        }
    }
}

/// The real-space kernel of the radial spectrum `value(|k|)` times the cells' form factor on
/// the `[ny, nx]` grid of cells `spacing_m`, wrap-around order; the mean mode `value(0)` when
/// `with_mean`, else zero.
fn spectral_real_space(
    shape: [usize; 2],
    spacing_m: [f64; 2],
    value: impl Fn(f64) -> f64,
    with_mean: bool,
) -> Result<Array2<f64>, TransformError> {
    let [ny, nx] = shape;
    let [dx, dy] = spacing_m;
    let plan = RealFft2::new(shape);
    let mut spectrum = plan.new_spectrum();
    let (lx, ly) = (nx as f64 * dx, ny as f64 * dy);
    // The spectrum depends on |k| only: one value per distinct (|ix|, |iy|).
    let columns = nx / 2 + 1;
    let rows = ny / 2 + 1;
    let mut table = Array2::zeros((rows, columns));
    for ((iy, ix), slot) in table.indexed_iter_mut() {
        let (kx, ky) = (2.0 * PI * ix as f64 / lx, 2.0 * PI * iy as f64 / ly);
        let k = kx.hypot(ky);
        let form = sinc(0.5 * kx * dx) * sinc(0.5 * ky * dy);
        *slot = if k == 0.0 {
            if with_mean {
                value(0.0)
            } else {
                0.0
            }
        } else {
            value(k) * form
        };
    }
    for ((ix, iy), slot) in spectrum.indexed_iter_mut() {
        let sy = signed_index(iy, ny).unsigned_abs() as usize;
        *slot = table[[sy, ix]].into();
    }
    let mut out = Array2::zeros((ny, nx));
    let mut work = plan.work();
    plan.inverse(&mut spectrum, out.view_mut(), &mut work)?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::material::Material;

    #[test]
    fn smoothed_patch_is_the_integral_of_its_kernel() {
        // Gauss-Legendre quadrature of 1/sqrt(r² + c²) over the cell, near and far.
        let (nodes, weights) = crate::thermal::special::gauss_legendre(40);
        let (hx, hy) = (1.0, 0.6);
        for &(x, y, c) in &[
            (0.0, 0.0, 0.5),
            (0.3, -0.2, 2.0),
            (2.5, 1.0, 0.8),
            (-7.0, 3.0, 3.0),
        ] {
            let mut sum = 0.0;
            for (u, wu) in nodes.iter().zip(&weights) {
                for (v, wv) in nodes.iter().zip(&weights) {
                    let (px, py) = (u * hx, v * hy);
                    let r2 = (x - px) * (x - px) + (y - py) * (y - py) + c * c;
                    sum += wu * wv * hx * hy / r2.sqrt();
                }
            }
            let closed = smoothed_patch(x, y, hx, hy, c);
            assert!(
                (closed / sum - 1.0).abs() < 1e-10,
                "({x}, {y}, {c}): {closed} vs {sum}"
            );
        }
        // c = 0 is Love's rectangle.
        let love = uniform_patch_displacement(0.4, 1.3, hx, hy);
        assert!((smoothed_patch(0.4, 1.3, hx, hy, 0.0) / love - 1.0).abs() < 1e-14);
    }

    #[test]
    fn the_radial_table_is_the_remainder_to_its_stated_error() {
        // B4C on steel and a soft layer on steel: the table against `remainder` itself off the
        // nodes, relative to the largest |R|: for K >= 0.1 the interpolation's error; below,
        // where R bends most, the same interpolation error larger. Then the whole kernel of
        // 40² cells of h/2 built from the table against the one built from `remainder` at
        // every wavenumber, relative to the kernel's largest coefficient.
        for (coating, substrate) in [((450e9, 0.17), (210e9, 0.3)), ((52e9, 0.33), (210e9, 0.3))] {
            let layered = Layered {
                coating: Material {
                    modulus_pa: coating.0,
                    poisson: coating.1,
                },
                substrate: Material {
                    modulus_pa: substrate.0,
                    poisson: substrate.1,
                },
                thickness_m: 7e-6,
                under: crate::coating::Interlayers::NONE,
            };
            let table = RemainderTable::new(&layered);
            let h = layered.thickness_m;
            let samples: Vec<f64> = (1..9000).map(|i| i as f64 * 0.005_003_7).collect();
            let largest = samples
                .iter()
                .map(|&big_k| remainder(&layered, big_k / h).abs())
                .fold(0.0, f64::max);
            let worst = |range: std::ops::Range<f64>| {
                samples
                    .iter()
                    .filter(|&&k| range.contains(&k))
                    .map(|&big_k| (table.at(big_k / h) - remainder(&layered, big_k / h)).abs())
                    .fold(0.0, f64::max)
                    / largest
            };
            let (far, near) = (worst(0.1..f64::INFINITY), worst(0.0..0.1));
            let (shape, spacing) = ([40, 40], [3.5e-6, 3.5e-6]);
            let direct = spectral_real_space([160, 160], spacing, |k| remainder(&layered, k), true)
                .expect("direct");
            let tabled =
                spectral_real_space([160, 160], spacing, |k| table.at(k), true).expect("tabled");
            let grid = kernel_grid(&layered, 0.0, shape, spacing, Periodicity::NonPeriodic)
                .expect("kernel");
            let scale = grid.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let kernel = (&direct - &tabled)
                .iter()
                .fold(0.0f64, |m, v| m.max(v.abs()))
                / scale;
            eprintln!(
                "measured: radial table of R against the direct evaluation, E1/E2 = {:.2}: {far:.1e} of max |R| for K >= 0.1, {near:.1e} below; kernel {kernel:.1e} of its largest coefficient",
                coating.0 / substrate.0
            );
            assert!(far < 2e-9, "{far}");
            assert!(near < 1e-8, "{near}");
            // The kernels differ mostly by their mean mode: the direct path extrapolates R(0)
            // linearly from K = 1e-3 and 2e-3, the table by the cubic through its first nodes
            // (a uniform shift of every coefficient, which the approach absorbs).
            assert!(kernel < 1e-8, "{kernel}");
        }
    }

    #[test]
    fn equal_materials_give_loves_coefficients() {
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let layered = Layered {
            coating: steel,
            substrate: steel,
            thickness_m: 3e-6,
            under: crate::coating::Interlayers::NONE,
        };
        let (shape, spacing) = ([12, 16], [1e-6, 1.3e-6]);
        let counter = (1.0 - 0.09) / 210e9;
        let grid = kernel_grid(&layered, counter, shape, spacing, Periodicity::NonPeriodic)
            .expect("kernel");
        let e_star = 210e9 / (2.0 * 0.91);
        let mut worst: f64 = 0.0;
        for j in 0..12 {
            for i in 0..16 {
                let love = uniform_patch_displacement(
                    i as f64 * spacing[0],
                    j as f64 * spacing[1],
                    0.5e-6,
                    0.65e-6,
                ) / (PI * e_star);
                worst = worst.max((grid[[j, i]] - love).abs() / love);
            }
        }
        eprintln!(
            "measured: equal moduli, layered influence coefficients against Love's: {worst:.1e}"
        );
        assert!(worst < 1e-12, "{worst}");
    }

    #[test]
    fn the_kernel_is_the_hankel_transform_of_the_layered_compliance_at_any_thickness() {
        // Off the coating's own Love coefficients, the kernel is smooth over a cell when the
        // coating is many cells thick: it is then dx dy (1/2π) ∫ (C(kh) - 2/E1') J0(kr) dk
        // (the layered compliance less the coating's half-space; `C - 2/E1'` falls as
        // e^(-2kh)), integrated here directly by Gauss–Legendre on panels of 1/8 in kh to
        // kh = 40, independently of the split. TiN (600 GPa, ν = 0.25) and PEEK (3.6 GPa,
        // ν = 0.4) on steel, 24² cells, h = 8 cells (about the grid's half-width) to 10⁴
        // cells (a coating far thicker than the grid, where the lattice alone failed),
        // relative to the kernel's coefficient at the centre.
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let (shape, spacing) = ([24, 24], [1e-6, 1e-6]);
        let (points, weights) = crate::thermal::special::gauss_legendre(8);
        let mut worst: f64 = 0.0;
        for coating in [(600e9, 0.25), (3.6e9, 0.4)] {
            let coating = Material {
                modulus_pa: coating.0,
                poisson: coating.1,
            };
            let e1 = plane_strain_modulus(&coating);
            for cells in [8.0, 40.0, 1e4] {
                let layered = Layered {
                    coating,
                    substrate: steel,
                    thickness_m: cells * spacing[0],
                    under: crate::coating::Interlayers::NONE,
                };
                let h = layered.thickness_m;
                let grid = kernel_grid(&layered, 0.0, shape, spacing, Periodicity::NonPeriodic)
                    .expect("kernel");
                let mut nodes = Vec::new();
                for panel in 0..320 {
                    for (t, w) in points.iter().zip(&weights) {
                        let big_k = 0.125 * (panel as f64 + 0.5 + 0.5 * t);
                        let excess = layered.normal_compliance_times_k(big_k) - 2.0 / e1;
                        nodes.push((big_k / h, 0.0625 * w / h * excess));
                    }
                }
                let centre = grid[[0, 0]];
                let mut case: f64 = 0.0;
                for (j, i) in [(0, 0), (0, 5), (3, 7), (11, 2), (23, 23), (17, 0)] {
                    let (x, y) = (i as f64 * spacing[0], j as f64 * spacing[1]);
                    let r = x.hypot(y);
                    let love = uniform_patch_displacement(x, y, 0.5e-6, 0.5e-6) / (PI * e1);
                    let smooth: f64 = nodes
                        .iter()
                        .map(|(k, v)| v * crate::coating::reference::bessel_j0(k * r))
                        .sum::<f64>()
                        * spacing[0]
                        * spacing[1]
                        / (2.0 * PI);
                    let error = (grid[[j, i]] - love - smooth).abs() / centre;
                    assert!(error.is_finite(), "({j}, {i}): {}", grid[[j, i]]);
                    case = case.max(error);
                }
                eprintln!(
                    "measured: E1 = {:.1} GPa on steel, h = {cells} cells: kernel against the direct Hankel transform, {case:.1e} of the centre's coefficient",
                    coating.modulus_pa / 1e9
                );
                worst = worst.max(case);
            }
        }
        assert!(worst < 1e-4, "{worst}");
    }

    #[test]
    fn the_windowed_remainder_is_its_lattice_sum_where_the_lattice_suffices() {
        // A coating of 2 and 6 cells on 96² cells, where a lattice holds R to its images: R w
        // by the radial transform against R w summed on a lattice three times the extended
        // grid (its images 12 grid lengths apart), at every offset of the kernel, relative
        // to the largest coefficient of R's kernel. B4C and a soft layer on steel. Measured
        // 2.8e-6 at most; on the extended grid itself 7.5e-5 (its images: the kernel's
        // lattice sums only R (1 - w), whose images are smaller by (4/α)⁴).
        let steel = Material {
            modulus_pa: 210e9,
            poisson: 0.3,
        };
        let (n, d) = (96, 1e-6);
        let mut worst: f64 = 0.0;
        for coating in [(450e9, 0.17), (52e9, 0.33)] {
            for cells in [2.0, 6.0] {
                let layered = Layered {
                    coating: Material {
                        modulus_pa: coating.0,
                        poisson: coating.1,
                    },
                    substrate: steel,
                    thickness_m: cells * d,
                    under: crate::coating::Interlayers::NONE,
                };
                let table = RemainderTable::new(&layered);
                let k_w = SPLIT / (4.0 * n as f64 * d);
                let lattice = spectral_real_space(
                    [12 * n, 12 * n],
                    [d, d],
                    |k| table.at(k) * window(k, k_w),
                    true,
                )
                .expect("lattice");
                let whole = spectral_real_space([4 * n, 4 * n], [d, d], |k| table.at(k), true)
                    .expect("whole");
                let scale = whole.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                let reach = (n as f64 * d).hypot(n as f64 * d);
                let low = WindowedRemainder::new(&table, k_w, [d, d], reach);
                let mut case: f64 = 0.0;
                for j in 0..n {
                    for i in 0..n {
                        let r = (i as f64 * d).hypot(j as f64 * d);
                        case = case.max((low.at(r) - lattice[[j, i]]).abs() / scale);
                    }
                }
                eprintln!(
                    "measured: E1 = {:.0} GPa, h = {cells} cells on 96² cells: the windowed remainder's radial transform against its lattice sum, {case:.1e} of R's largest coefficient",
                    coating.0 / 1e9
                );
                worst = worst.max(case);
            }
        }
        assert!(worst < 1e-5, "{worst}");
    }
}

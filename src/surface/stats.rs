//! Characterisation of a height map: levelling, the ISO 25178-2 areal parameters, the ISO 4287
//! profile parameters, power spectra with the Hurst exponent, the autocorrelation, the height
//! distribution, spectral moments, summits and their Greenwood–Williamson parameters measured
//! and from McCool's spectral formulas, and the highest asperity (the lecture notes' homework).
//!
//! Every statistic is computed on the levelled map: the least-squares mean plane is always
//! removed first (and a second-order form on request), so heights have zero mean.
//!
//! ## Definitions (discrete, on `nx x ny` samples `z` spaced `dx`, `dy`)
//! - Height (ISO 25178-2:2012, §4.1): `Sa = mean |z|`, `Sq = sqrt(mean z²)`,
//!   `Ssk = mean z³ / Sq³`, `Sku = mean z⁴ / Sq⁴`, `Sp = max z`, `Sv = -min z` (a positive
//!   depth), `Sz = Sp + Sv`.
//! - Hybrid (§4.3), on each of the `(nx - 1)(ny - 1)` cells between four samples, with the cell
//!   slopes `zx`, `zy` the means of the differences along its two edges in each direction
//!   (Leach, *Characterisation of Areal Surface Texture*, 2013, ch. 2):
//!   `Sdq = sqrt(mean (zx² + zy²))`, `Sdr = mean (sqrt(1 + zx² + zy²) - 1)` (a fraction).
//! - Spatial (§4.2): the areal autocorrelation `f(τ) = Σ z(r) z(r + τ) / Σ z²`, computed as the
//!   circular autocorrelation by FFT (Wiener–Khinchin; exact for a periodic map, and for lags
//!   small against the map size otherwise). Along 360 directions the first lag where it falls
//!   to `s = 0.2` is found (linear interpolation between samples, bilinear in the plane);
//!   `Sal` is the shortest of them, `Str` the shortest over the longest. Where it does not
//!   fall to 0.2 within half the map in some direction, that direction's length is unknown:
//!   `Str` is then an upper bound taken with the half-map length ([`Spatial::str_bounded`]).
//! - Profile (ISO 4287:1997, §4.2): each row along x with its least-squares line removed,
//!   `Ra`, `Rq`, `Rsk`, `Rku` as above, averaged over the rows (no filter: the evaluation
//!   length is the map's width).
//! - Power spectral density (Jacobs, Junge & Pastewka 2017): `C(q) = dx dy / (nx ny) |Z(q)|²`
//!   with `Z` the discrete Fourier transform of the (optionally Hann-windowed, power-corrected)
//!   heights, so that `Σ_q C(q) Δqx Δqy / (2π)² = Sq²`; radially averaged over rings of width
//!   `2π / min(Lx, Ly)`. The 1-D PSD along x, `C1(qx) = dx / nx |Z_row(qx)|²` averaged over
//!   rows, has `Σ C1 Δq / 2π = Rq²`. The Hurst exponent comes from a least-squares line
//!   through `log C` against `log q` over a band of wavelengths, `C ∝ q^(-2(1+H))`; the
//!   fractal dimension is `D = 3 - H`.
//! - Spectral moments of profiles (Nayak 1971; McCool 1986), by finite differences and the
//!   mean of the x and y directions: `m0 = Sq²`, `m2 = mean (Δz/Δx)²`,
//!   `m4 = mean (Δ²z/Δx²)²`; Nayak's bandwidth `α = m0 m4 / m2²`.
//! - Summits: samples higher than their eight neighbours (the border is left out). Their
//!   curvature is the lecture notes' finite difference `1/R = (2 z_i - z_(i-1) - z_(i+1)) / Δ²`
//!   along x and along y, averaged; the summit radius is the reciprocal of the mean curvature
//!   (Greenwood & Williamson give every summit one radius β); the summit heights' standard
//!   deviation `σs` and mean. McCool's spectral estimates (McCool 1986, for isotropic
//!   Gaussian surfaces): density `m4 / (6π√3 m2)`, mean curvature `(8/3) sqrt(m4/π)`,
//!   `σs = sqrt(1 - 0.8968/α) sqrt(m0)`, mean summit height `4 sqrt(m0 / (π α))`.
//!
//! ## References
//! - ISO 25178-2:2012, Geometrical product specifications (GPS) — Surface texture: Areal —
//!   Part 2: Terms, definitions and surface texture parameters.
//! - ISO 4287:1997, GPS — Surface texture: Profile method — Terms, definitions and surface
//!   texture parameters.
//! - R. Leach (ed.), *Characterisation of Areal Surface Texture*, Springer (2013).
//! - T. D. B. Jacobs, T. Junge, L. Pastewka, Quantitative characterization of surface
//!   topography using spectral analysis, *Surf. Topogr.: Metrol. Prop.* 5 (2017) 013001.
//! - P. R. Nayak, Random process model of rough surfaces, *J. Lubr. Technol.* 93 (1971) 398.
//! - J. I. McCool, Comparison of models for the contact of rough surfaces, *Wear* 107 (1986)
//!   37–60.

use std::f64::consts::PI;

use ndarray::{Array2, Axis, Zip};
use rayon::prelude::*;

use super::HeightMap;
use crate::operator::transform::{signed_index, RealFft2, TransformError};

/// What is removed before the statistics: always the least-squares mean plane.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum FormRemoval {
    /// The mean plane only.
    #[default]
    Plane,
    /// A least-squares second-order polynomial (a ball's or a cylinder's form, to second order).
    Quadratic,
}

impl FormRemoval {
    pub fn describe(self) -> &'static str {
        match self {
            FormRemoval::Plane => "least-squares mean plane removed",
            FormRemoval::Quadratic => "least-squares second-order form removed",
        }
    }
}

/// Options of [`characterise`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    pub form: FormRemoval,
    /// Band of wavelengths `(shortest, longest)` in m for the Hurst fit; `None`: from 4
    /// samples to a quarter of the map's shorter side (a decade or more from 160 samples on;
    /// the range of a generated surface's power law, whose cutoff is 4 samples and roll-off
    /// a quarter of the map by default). Set it for measured maps whose shortest wavelengths
    /// carry the instrument's response.
    pub band_m: Option<(f64, f64)>,
    /// Hann window before the spectra (measured, non-periodic maps).
    pub window: bool,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            form: FormRemoval::Plane,
            band_m: None,
            window: true,
        }
    }
}

/// Why a map cannot be characterised.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StatsError {
    #[error("a map of {0} x {1} samples is too small to characterise: it needs at least 8 x 8")]
    TooSmall(usize, usize),
    #[error("the surface is flat after levelling: its statistics are all zero")]
    Flat,
    #[error("the Hurst band {shortest_m:.3e} .. {longest_m:.3e} m holds fewer than 3 rings of the spectrum; widen it (the map resolves {min_m:.3e} .. {max_m:.3e} m)")]
    Band {
        shortest_m: f64,
        longest_m: f64,
        min_m: f64,
        max_m: f64,
    },
    #[error(transparent)]
    Transform(#[from] TransformError),
}

/// The ISO 25178-2 height parameters (m; skewness and kurtosis dimensionless).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeightParameters {
    pub sa: f64,
    pub sq: f64,
    pub ssk: f64,
    pub sku: f64,
    pub sp: f64,
    pub sv: f64,
    pub sz: f64,
}

/// ISO 4287 profile parameters along x, averaged over rows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProfileParameters {
    pub ra: f64,
    pub rq: f64,
    pub rsk: f64,
    pub rku: f64,
}

/// The spatial parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spatial {
    /// Autocorrelation length (m); `None` when the autocorrelation stays above 0.2 within half
    /// the map in every direction.
    pub sal_m: Option<f64>,
    /// Texture aspect ratio in [0, 1].
    pub str_ratio: Option<f64>,
    /// Whether some direction never decayed to 0.2, so `Str` is an upper bound.
    pub str_bounded: bool,
}

/// Spectral moments of profiles and Nayak's bandwidth.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Moments {
    pub m0: f64,
    pub m2: f64,
    pub m4: f64,
    pub nayak_alpha: f64,
}

/// Greenwood–Williamson summit parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SummitParameters {
    pub count: usize,
    pub density_per_m2: f64,
    /// The reciprocal of the mean summit curvature (m).
    pub radius_m: f64,
    pub height_std_m: f64,
    /// Mean summit height above the mean plane (m).
    pub mean_height_m: f64,
}

/// The spectra and the Hurst fit.
#[derive(Clone, Debug, PartialEq)]
pub struct Spectra {
    /// Radially averaged 2-D PSD: `(q in rad/m, C in m⁴)`.
    pub radial: Vec<(f64, f64)>,
    /// 1-D PSD along x: `(q, C1 in m³)`, q > 0.
    pub profile: Vec<(f64, f64)>,
    /// `None` when the band holds fewer than three rings of the spectrum.
    pub hurst: Option<f64>,
    pub fractal_dimension: Option<f64>,
    /// The band of the fit, wavenumbers (rad/m).
    pub band_q: (f64, f64),
    /// The fitted line `log10 C = intercept + slope log10 q`.
    pub fit_slope: f64,
    pub fit_intercept: f64,
}

/// The highest asperity, its profile and the Hertz contact of the homework.
#[derive(Clone, Debug, PartialEq)]
pub struct Asperity {
    /// `[row, column]` of the highest sample.
    pub at: [usize; 2],
    /// Its height above the mean plane (m).
    pub height_m: f64,
    /// Tip radii by the finite difference along x and along y (m); `None` when not convex.
    pub radius_x_m: Option<f64>,
    pub radius_y_m: Option<f64>,
    /// The profile along x through it: `(x, z)` in m, x from the map's left edge.
    pub profile_x: Vec<(f64, f64)>,
}

/// Everything [`characterise`] finds.
#[derive(Clone, Debug, PartialEq)]
pub struct Characterisation {
    pub options: Options,
    pub shape: [usize; 2],
    pub spacing_m: [f64; 2],
    /// The removed plane `z = c0 + c1 x + c2 y` (m, x and y in m from the first sample).
    pub plane: [f64; 3],
    pub height: HeightParameters,
    pub sdq: f64,
    pub sdr: f64,
    pub spatial: Spatial,
    pub profile: ProfileParameters,
    pub spectra: Spectra,
    /// The autocorrelation along x and along y: `(lag in m, value)` up to half the map.
    pub acf_x: Vec<(f64, f64)>,
    pub acf_y: Vec<(f64, f64)>,
    /// Height histogram: `(bin centre in m, probability density in 1/m)`.
    pub histogram: Vec<(f64, f64)>,
    pub moments: Moments,
    pub summits: SummitParameters,
    pub mccool: SummitParameters,
    pub asperity: Asperity,
}

/// Per-row values `f(j)` of the rows `0..rows`, computed in parallel and returned in row
/// order: sums folded from them in that order have the same bits on any number of threads.
fn per_row<T: Send>(rows: usize, f: impl Fn(usize) -> T + Sync + Send) -> Vec<T> {
    (0..rows).into_par_iter().map(f).collect()
}

/// Least-squares fit of `z` by `K` basis functions of the sample indices `(i, j)`, by the
/// normal equations (solved by Gaussian elimination with partial pivoting).
fn least_squares<const K: usize>(
    map: &Array2<f64>,
    basis: &(dyn Fn(usize, usize) -> [f64; K] + Sync),
) -> [f64; K] {
    let ny = map.nrows();
    let rows = per_row(ny, |j| {
        let (mut a, mut r) = ([[0.0; K]; K], [0.0; K]);
        for (i, &z) in map.row(j).iter().enumerate() {
            let b = basis(i, j);
            for p in 0..K {
                for q in 0..K {
                    a[p][q] += b[p] * b[q];
                }
                r[p] += b[p] * z;
            }
        }
        (a, r)
    });
    let (mut a, mut r) = ([[0.0; K]; K], [0.0; K]);
    for (row_a, row_r) in &rows {
        for (sum, row) in a.iter_mut().zip(row_a) {
            for (sum, value) in sum.iter_mut().zip(row) {
                *sum += value;
            }
        }
        for (sum, value) in r.iter_mut().zip(row_r) {
            *sum += value;
        }
    }
    for col in 0..K {
        let pivot = (col..K)
            .max_by(|&p, &q| a[p][col].abs().total_cmp(&a[q][col].abs()))
            .unwrap_or(col);
        a.swap(col, pivot);
        r.swap(col, pivot);
        let d = a[col][col];
        if d == 0.0 {
            continue;
        }
        let (pivot_row, pivot_rhs) = (a[col], r[col]);
        for row in 0..K {
            if row != col {
                let f = a[row][col] / d;
                for c in col..K {
                    a[row][c] -= f * pivot_row[c];
                }
                r[row] -= f * pivot_rhs;
            }
        }
    }
    std::array::from_fn(|k| if a[k][k] == 0.0 { 0.0 } else { r[k] / a[k][k] })
}

/// The levelled heights and the removed plane's coefficients `[c0, c1, c2]`.
pub fn level(map: &HeightMap, form: FormRemoval) -> (Array2<f64>, [f64; 3]) {
    let heights = map.heights_m();
    let spacing = map.spacing_m();
    let [ny, nx] = map.shape();
    // Centred, scaled coordinates u = (x - cx)/sx in [-1, 1] (for conditioning).
    let (ci, cj) = (0.5 * (nx - 1) as f64, 0.5 * (ny - 1) as f64);
    let (si, sj) = (ci.max(f64::MIN_POSITIVE), cj.max(f64::MIN_POSITIVE));
    let uv = move |i: usize, j: usize| ((i as f64 - ci) / si, (j as f64 - cj) / sj);
    let plane_basis = move |i: usize, j: usize| {
        let (u, v) = uv(i, j);
        [1.0, u, v]
    };
    let quadratic_basis = move |i: usize, j: usize| {
        let (u, v) = uv(i, j);
        [1.0, u, v, u * u, u * v, v * v]
    };
    let plane = least_squares(heights, &plane_basis);
    let mut levelled = heights.clone();
    match form {
        FormRemoval::Plane => Zip::indexed(&mut levelled).par_for_each(|(j, i), z| {
            let b = plane_basis(i, j);
            *z -= b[0] * plane[0] + b[1] * plane[1] + b[2] * plane[2];
        }),
        FormRemoval::Quadratic => {
            let c = least_squares(heights, &quadratic_basis);
            Zip::indexed(&mut levelled).par_for_each(|(j, i), z| {
                let b = quadratic_basis(i, j);
                *z -= b.iter().zip(&c).map(|(b, c)| b * c).sum::<f64>();
            })
        }
    }
    // The plane in physical coordinates: c0 + c1 x + c2 y.
    let [dx, dy] = spacing;
    let (cx, cy) = (ci * dx, cj * dy);
    let (p0, p1, p2) = (plane[0], plane[1] / (si * dx), plane[2] / (sj * dy));
    (levelled, [p0 - p1 * cx - p2 * cy, p1, p2])
}

/// Mean, rms, skewness and kurtosis of zero-mean-ish values (about their mean).
fn moments_of(values: impl Iterator<Item = f64> + Clone) -> (f64, f64, f64, f64) {
    let (n, sum) = values
        .clone()
        .fold((0usize, 0.0), |(n, s), v| (n + 1, s + v));
    let mean = sum / n.max(1) as f64;
    let (mut m1, mut m2, mut m3, mut m4) = (0.0, 0.0, 0.0, 0.0);
    for v in values {
        let d = v - mean;
        m1 += d.abs();
        m2 += d * d;
        m3 += d * d * d;
        m4 += d * d * d * d;
    }
    let n = n.max(1) as f64;
    let rms = (m2 / n).sqrt();
    let (skew, kurt) = if rms > 0.0 {
        (m3 / n / rms.powi(3), m4 / n / rms.powi(4))
    } else {
        (0.0, 0.0)
    };
    (m1 / n, rms, skew, kurt)
}

/// ISO 25178-2 height parameters of levelled heights.
pub fn height_parameters(z: &Array2<f64>) -> HeightParameters {
    let (ny, nx) = z.dim();
    let n = (nx * ny).max(1) as f64;
    let mean = per_row(ny, |j| z.row(j).sum()).iter().sum::<f64>() / n;
    let rows = per_row(ny, |j| {
        let (mut m, mut low, mut high) = ([0.0; 4], f64::INFINITY, f64::NEG_INFINITY);
        for &v in z.row(j) {
            let d = v - mean;
            let d2 = d * d;
            m[0] += d.abs();
            m[1] += d2;
            m[2] += d2 * d;
            m[3] += d2 * d2;
            low = low.min(v);
            high = high.max(v);
        }
        (m, low, high)
    });
    let (mut m, mut low, mut high) = ([0.0; 4], f64::INFINITY, f64::NEG_INFINITY);
    for (row, l, h) in &rows {
        for (sum, value) in m.iter_mut().zip(row) {
            *sum += value;
        }
        low = low.min(*l);
        high = high.max(*h);
    }
    let sq = (m[1] / n).sqrt();
    let (ssk, sku) = if sq > 0.0 {
        (m[2] / n / sq.powi(3), m[3] / n / sq.powi(4))
    } else {
        (0.0, 0.0)
    };
    HeightParameters {
        sa: m[0] / n,
        sq,
        ssk,
        sku,
        sp: high,
        sv: -low,
        sz: high - low,
    }
}

/// `(Sdq, Sdr)` from the cell slopes (module doc).
pub fn hybrid_parameters(z: &Array2<f64>, spacing: [f64; 2]) -> (f64, f64) {
    let (ny, nx) = z.dim();
    let [dx, dy] = spacing;
    let rows = per_row(ny - 1, |j| {
        let (mut slope2, mut area) = (0.0, 0.0);
        let (lower, upper) = (z.row(j), z.row(j + 1));
        for i in 0..nx - 1 {
            let zx = (lower[i + 1] - lower[i] + upper[i + 1] - upper[i]) / (2.0 * dx);
            let zy = (upper[i] - lower[i] + upper[i + 1] - lower[i + 1]) / (2.0 * dy);
            let s = zx * zx + zy * zy;
            slope2 += s;
            // sqrt(1 + s) - 1 without cancellation.
            area += s / ((1.0 + s).sqrt() + 1.0);
        }
        (slope2, area)
    });
    let (slope2, area) = rows
        .iter()
        .fold((0.0, 0.0), |(a, b), (s, r)| (a + s, b + r));
    let cells = ((nx - 1) * (ny - 1)) as f64;
    ((slope2 / cells).sqrt(), area / cells)
}

/// ISO 4287 parameters of the rows, each with its least-squares line removed, averaged.
pub fn profile_parameters(z: &Array2<f64>) -> ProfileParameters {
    let (ny, nx) = z.dim();
    let xs: Vec<f64> = (0..nx).map(|i| i as f64 - 0.5 * (nx - 1) as f64).collect();
    let sxx: f64 = xs.iter().map(|x| x * x).sum();
    let rows = per_row(ny, |j| {
        let row = z.row(j);
        let mean = row.sum() / nx as f64;
        let slope = if sxx > 0.0 {
            row.iter().zip(&xs).map(|(v, x)| v * x).sum::<f64>() / sxx
        } else {
            0.0
        };
        let residual = row.iter().zip(&xs).map(move |(v, x)| v - mean - slope * x);
        moments_of(residual)
    });
    let mut sums = [0.0; 4];
    for (ra, rq, rsk, rku) in &rows {
        for (s, v) in sums.iter_mut().zip([ra, rq, rsk, rku]) {
            *s += v;
        }
    }
    let n = ny as f64;
    ProfileParameters {
        ra: sums[0] / n,
        rq: sums[1] / n,
        rsk: sums[2] / n,
        rku: sums[3] / n,
    }
}

/// Profile moments `(m0, m2, m4)` by finite differences, mean of x and y (module doc).
pub fn spectral_moments(z: &Array2<f64>, spacing: [f64; 2]) -> Moments {
    let (ny, nx) = z.dim();
    let [dx, dy] = spacing;
    // Per row j: Σ z², the x differences of row j, and the y differences from row j up.
    let rows = per_row(ny, |j| {
        let row = z.row(j);
        let mut sums = [0.0; 5];
        for i in 0..nx {
            sums[0] += row[i] * row[i];
            if i + 1 < nx {
                sums[1] += ((row[i + 1] - row[i]) / dx).powi(2);
            }
            if i >= 1 && i + 1 < nx {
                sums[2] += ((row[i + 1] - 2.0 * row[i] + row[i - 1]) / (dx * dx)).powi(2);
            }
        }
        if j + 1 < ny {
            let up = z.row(j + 1);
            sums[3] += row
                .iter()
                .zip(up.iter())
                .map(|(a, b)| ((b - a) / dy).powi(2))
                .sum::<f64>();
        }
        if j >= 1 && j + 1 < ny {
            let (down, up) = (z.row(j - 1), z.row(j + 1));
            for i in 0..nx {
                sums[4] += ((up[i] - 2.0 * row[i] + down[i]) / (dy * dy)).powi(2);
            }
        }
        sums
    });
    let mut s = [0.0; 5];
    for row in &rows {
        for (total, value) in s.iter_mut().zip(row) {
            *total += value;
        }
    }
    let [sum_z2, m2x, m4x, m2y, m4y] = s;
    let m0 = sum_z2 / z.len() as f64;
    let m2 = 0.5 * (m2x / ((nx - 1) * ny) as f64 + m2y / (nx * (ny - 1)) as f64);
    let m4 = 0.5 * (m4x / ((nx - 2) * ny) as f64 + m4y / (nx * (ny - 2)) as f64);
    Moments {
        m0,
        m2,
        m4,
        nayak_alpha: if m2 > 0.0 {
            m0 * m4 / (m2 * m2)
        } else {
            f64::INFINITY
        },
    }
}

/// Summits (strict 8-neighbour maxima off the border) and their parameters (module doc).
pub fn summits(z: &Array2<f64>, spacing: [f64; 2]) -> SummitParameters {
    let (ny, nx) = z.dim();
    let [dx, dy] = spacing;
    let rows = per_row(ny.saturating_sub(2), |r| {
        let j = r + 1;
        let (down, row, up) = (z.row(j - 1), z.row(j), z.row(j + 1));
        let mut heights = Vec::new();
        let mut curvature_sum = 0.0;
        for i in 1..nx - 1 {
            let v = row[i];
            let higher = v > row[i - 1]
                && v > row[i + 1]
                && (i - 1..=i + 1).all(|k| v > down[k] && v > up[k]);
            if higher {
                let kx = (2.0 * v - row[i - 1] - row[i + 1]) / (dx * dx);
                let ky = (2.0 * v - down[i] - up[i]) / (dy * dy);
                curvature_sum += 0.5 * (kx + ky);
                heights.push(v);
            }
        }
        (heights, curvature_sum)
    });
    let heights: Vec<f64> = rows.iter().flat_map(|(h, _)| h.iter().copied()).collect();
    let curvature_sum: f64 = rows.iter().map(|(_, c)| c).sum();
    let count = heights.len();
    let area = ((nx - 2) * (ny - 2)) as f64 * dx * dy;
    let mean = heights.iter().sum::<f64>() / count.max(1) as f64;
    let std =
        (heights.iter().map(|h| (h - mean).powi(2)).sum::<f64>() / count.max(1) as f64).sqrt();
    SummitParameters {
        count,
        density_per_m2: count as f64 / area,
        radius_m: if curvature_sum > 0.0 {
            count as f64 / curvature_sum
        } else {
            f64::INFINITY
        },
        height_std_m: std,
        mean_height_m: mean,
    }
}

/// McCool's spectral estimates of the summit parameters (module doc), for an area `area_m2`.
pub fn mccool(moments: &Moments, area_m2: f64) -> SummitParameters {
    let Moments {
        m0,
        m2,
        m4,
        nayak_alpha,
    } = *moments;
    let density = m4 / (6.0 * PI * 3f64.sqrt() * m2);
    let curvature = 8.0 / 3.0 * (m4 / PI).sqrt();
    SummitParameters {
        count: (density * area_m2).round() as usize,
        density_per_m2: density,
        radius_m: 1.0 / curvature,
        height_std_m: ((1.0 - 0.8968 / nayak_alpha).max(0.0) * m0).sqrt(),
        mean_height_m: 4.0 * (m0 / (PI * nayak_alpha)).sqrt(),
    }
}

/// Spectrum columns (kx) per parallel block of the radial average.
const RING_BLOCK: usize = 16;

/// The characterisation of `map` (module doc).
pub fn characterise(map: &HeightMap, options: &Options) -> Result<Characterisation, StatsError> {
    let [ny, nx] = map.shape();
    if nx < 8 || ny < 8 {
        return Err(StatsError::TooSmall(ny, nx));
    }
    let spacing = map.spacing_m();
    let [dx, dy] = spacing;
    let (z, plane) = level(map, options.form);
    let height = height_parameters(&z);
    let scale = map
        .heights_m()
        .par_iter()
        .fold(|| 0.0f64, |m, v| m.max(v.abs()))
        .reduce(|| 0.0, f64::max);
    if height.sq <= 1e-12 * scale {
        return Err(StatsError::Flat);
    }
    let (sdq, sdr) = hybrid_parameters(&z, spacing);
    let profile = profile_parameters(&z);
    let moments = spectral_moments(&z, spacing);
    let summit_parameters = summits(&z, spacing);
    let area = nx as f64 * dx * ny as f64 * dy;
    let mccool_parameters = mccool(&moments, area);

    // Spectra: one 2-D transform of the (windowed) heights.
    let plan = RealFft2::new([ny, nx]);
    let mut work = plan.work();
    let mut spectrum = plan.new_spectrum();
    let windowed;
    let source = if options.window {
        windowed = hann(&z);
        &windowed
    } else {
        &z
    };
    plan.forward(source.view(), &mut spectrum, &mut work)?;
    let (lx, ly) = (nx as f64 * dx, ny as f64 * dy);
    let ring = 2.0 * PI / lx.min(ly);
    let rings = ((PI / dx.max(dy)) / ring).floor() as usize + 1;
    // Per ring: Σ C, Σ q, count (the ring's wavenumber is the mean of its samples'). In
    // parallel over fixed blocks of kx, merged in kx order (the same bits on any thread count).
    let psd_factor = dx * dy / (nx * ny) as f64;
    let blocks: Vec<Vec<(f64, f64, usize)>> = spectrum
        .axis_chunks_iter(Axis(0), RING_BLOCK)
        .into_par_iter()
        .enumerate()
        .map(|(b, block)| {
            let mut radial = vec![(0.0, 0.0, 0usize); rings + 1];
            for ((k, ky), value) in block.indexed_iter() {
                let qx = 2.0 * PI * (b * RING_BLOCK + k) as f64 / lx;
                let qy = 2.0 * PI * signed_index(ky, ny) as f64 / ly;
                let q = (qx * qx + qy * qy).sqrt();
                let r = (q / ring).round() as usize;
                if r == 0 || r > rings {
                    continue;
                }
                radial[r].0 += psd_factor * value.norm_sqr();
                radial[r].1 += q;
                radial[r].2 += 1;
            }
            radial
        })
        .collect();
    let mut radial = vec![(0.0, 0.0, 0usize); rings + 1];
    for block in &blocks {
        for (total, part) in radial.iter_mut().zip(block) {
            total.0 += part.0;
            total.1 += part.1;
            total.2 += part.2;
        }
    }
    let radial: Vec<(f64, f64)> = radial
        .iter()
        .filter(|(_, _, count)| *count > 0)
        .map(|(sum, q, count)| (q / *count as f64, sum / *count as f64))
        .collect();
    // 1-D PSD along x: |Z(kx, ky)|² summed over ky is ny Σ_rows |Z_row(kx)|² (Parseval along
    // the columns), so the row average needs no transform of its own.
    let profile_psd: Vec<f64> = spectrum
        .axis_iter(Axis(0))
        .into_par_iter()
        .map(|column| column.iter().map(|v| v.norm_sqr()).sum())
        .collect();
    let profile_spectrum: Vec<(f64, f64)> = profile_psd
        .iter()
        .enumerate()
        .skip(1)
        .map(|(kx, sum)| {
            (
                2.0 * PI * kx as f64 / lx,
                dx / nx as f64 * sum / (ny * ny) as f64,
            )
        })
        .collect();
    // Default band: 4 samples to a quarter of the map; a small map takes what it resolves.
    let resolved = (2.0 * dx.max(dy), lx.min(ly));
    let (shortest, longest) = options.band_m.unwrap_or_else(|| {
        let (short, long) = (4.0 * dx.max(dy), lx.min(ly) / 4.0);
        if long >= 2.0 * short {
            (short, long)
        } else {
            (resolved.0, resolved.1 / 2.0)
        }
    });
    let band_q = (2.0 * PI / longest, 2.0 * PI / shortest);
    let points: Vec<(f64, f64)> = radial
        .iter()
        .filter(|(q, c)| *q >= band_q.0 * (1.0 - 1e-9) && *q <= band_q.1 * (1.0 + 1e-9) && *c > 0.0)
        .map(|(q, c)| (q.log10(), c.log10()))
        .collect();
    if points.len() < 3 && options.band_m.is_some() {
        return Err(StatsError::Band {
            shortest_m: shortest,
            longest_m: longest,
            min_m: resolved.0,
            max_m: resolved.1,
        });
    }
    let (slope, intercept) = if points.len() >= 3 {
        let m = points.len() as f64;
        let (mx, my) = points
            .iter()
            .fold((0.0, 0.0), |(a, b), p| (a + p.0 / m, b + p.1 / m));
        let slope = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum::<f64>()
            / points.iter().map(|p| (p.0 - mx).powi(2)).sum::<f64>();
        (slope, my - slope * mx)
    } else {
        (f64::NAN, f64::NAN)
    };
    let hurst = slope.is_finite().then(|| -slope / 2.0 - 1.0);
    let spectra = Spectra {
        radial,
        profile: profile_spectrum,
        hurst,
        fractal_dimension: hurst.map(|h| 3.0 - h),
        band_q,
        fit_slope: slope,
        fit_intercept: intercept,
    };

    // Autocorrelation: inverse transform of |Z|² of the unwindowed heights.
    plan.forward(z.view(), &mut spectrum, &mut work)?;
    spectrum.par_mapv_inplace(|v| rustfft::num_complex::Complex::new(v.norm_sqr(), 0.0));
    let mut acf = Array2::zeros((ny, nx));
    plan.inverse(&mut spectrum, acf.view_mut(), &mut work)?;
    let zero = acf[[0, 0]];
    acf.par_mapv_inplace(|v| v / zero);
    let spatial = spatial_parameters(&acf, spacing);
    let acf_x = (0..=nx / 2).map(|i| (i as f64 * dx, acf[[0, i]])).collect();
    let acf_y = (0..=ny / 2).map(|j| (j as f64 * dy, acf[[j, 0]])).collect();

    Ok(Characterisation {
        options: *options,
        shape: [ny, nx],
        spacing_m: spacing,
        plane,
        height,
        sdq,
        sdr,
        spatial,
        profile,
        spectra,
        acf_x,
        acf_y,
        histogram: histogram(&z, height.sq),
        moments,
        summits: summit_parameters,
        mccool: mccool_parameters,
        asperity: highest_asperity(&z, spacing),
    })
}

/// The heights times a 2-D Hann window, scaled so that the mean square is kept (so the PSD
/// keeps `Σ C Δq²/(2π)² = Sq²` on average).
fn hann(z: &Array2<f64>) -> Array2<f64> {
    let (ny, nx) = z.dim();
    let w = |k: usize, n: usize| (PI * (k as f64 + 0.5) / n as f64).sin().powi(2);
    let (wx, wy): (Vec<f64>, Vec<f64>) = (
        (0..nx).map(|i| w(i, nx)).collect(),
        (0..ny).map(|j| w(j, ny)).collect(),
    );
    let mut out = z.clone();
    Zip::indexed(&mut out).par_for_each(|(j, i), v| *v *= wx[i] * wy[j]);
    let square_sum = |a: &Array2<f64>| -> f64 {
        per_row(a.nrows(), |j| a.row(j).iter().map(|v| v * v).sum::<f64>())
            .iter()
            .sum()
    };
    let (before, after) = (square_sum(z), square_sum(&out));
    if after > 0.0 {
        let scale = (before / after).sqrt();
        out.par_mapv_inplace(|v| v * scale);
    }
    out
}

/// `Sal` and `Str` from the normalised circular autocorrelation (module doc).
fn spatial_parameters(acf: &Array2<f64>, spacing: [f64; 2]) -> Spatial {
    let (ny, nx) = acf.dim();
    let [dx, dy] = spacing;
    // Bilinear interpolation at a lag (x, y) in samples (wrapped: the ACF is circular).
    let at = |x: f64, y: f64| {
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let value = |i: f64, j: f64| {
            acf[[
                (j as i64).rem_euclid(ny as i64) as usize,
                (i as i64).rem_euclid(nx as i64) as usize,
            ]]
        };
        (1.0 - fx) * (1.0 - fy) * value(x0, y0)
            + fx * (1.0 - fy) * value(x0 + 1.0, y0)
            + (1.0 - fx) * fy * value(x0, y0 + 1.0)
            + fx * fy * value(x0 + 1.0, y0 + 1.0)
    };
    let reach = 0.5 * (nx as f64 * dx).min(ny as f64 * dy);
    let step = 0.25 * dx.min(dy);
    let directions: Vec<Option<f64>> = (0..360)
        .into_par_iter()
        .map(|k| {
            let theta = PI * k as f64 / 360.0;
            let (c, s) = (theta.cos(), theta.sin());
            let mut previous = (0.0, 1.0);
            let mut found = None;
            let mut r = step;
            while r <= reach {
                let value = at(r * c / dx, r * s / dy);
                if value <= 0.2 {
                    let (r0, v0) = previous;
                    found = Some(r0 + (r - r0) * (v0 - 0.2) / (v0 - value));
                    break;
                }
                previous = (r, value);
                r += step;
            }
            found
        })
        .collect();
    let lengths: Vec<f64> = directions.iter().flatten().copied().collect();
    let bounded = directions.iter().any(Option::is_none);
    let shortest = lengths.iter().copied().fold(f64::INFINITY, f64::min);
    let longest = if bounded {
        reach
    } else {
        lengths.iter().copied().fold(0.0, f64::max)
    };
    let sal_m = shortest.is_finite().then_some(shortest);
    Spatial {
        sal_m,
        str_ratio: sal_m.map(|s| s / longest),
        str_bounded: bounded,
    }
}

/// Histogram of the heights as a probability density (Freedman–Diaconis-like bins: about
/// `sqrt(N)`, at most 100).
fn histogram(z: &Array2<f64>, sq: f64) -> Vec<(f64, f64)> {
    let (low, high) = z
        .par_iter()
        .fold(
            || (f64::INFINITY, f64::NEG_INFINITY),
            |(a, b), &v| (a.min(v), b.max(v)),
        )
        .reduce(
            || (f64::INFINITY, f64::NEG_INFINITY),
            |(a, b), (c, d)| (a.min(c), b.max(d)),
        );
    let bins = ((z.len() as f64).sqrt() as usize).clamp(10, 100);
    let width = ((high - low) / bins as f64).max(sq * 1e-9);
    let counts = z
        .par_iter()
        .fold(
            || vec![0usize; bins],
            |mut counts, &v| {
                counts[(((v - low) / width) as usize).min(bins - 1)] += 1;
                counts
            },
        )
        .reduce(
            || vec![0usize; bins],
            |mut a, b| {
                a.iter_mut().zip(&b).for_each(|(a, b)| *a += b);
                a
            },
        );
    let n = z.len() as f64;
    counts
        .iter()
        .enumerate()
        .map(|(k, &c)| (low + (k as f64 + 0.5) * width, c as f64 / (n * width)))
        .collect()
}

/// The highest sample, its profiles and tip radii (the lecture notes' homework).
fn highest_asperity(z: &Array2<f64>, spacing: [f64; 2]) -> Asperity {
    let (ny, nx) = z.dim();
    let [dx, dy] = spacing;
    // Off the border, so that both finite differences exist.
    // Each row's first highest interior sample, then the first highest row: the first in
    // row-major order, as a sequential scan finds it.
    let rows = per_row(ny, |j| {
        let interior = j > 0 && j + 1 < ny;
        z.row(j)
            .iter()
            .enumerate()
            .filter(|&(i, _)| interior && i > 0 && i + 1 < nx)
            .fold(((j, 0), f64::NEG_INFINITY), |best, (i, &v)| {
                if v > best.1 {
                    ((j, i), v)
                } else {
                    best
                }
            })
    });
    let (at, height) = rows
        .into_iter()
        .fold(((0, 0), f64::NEG_INFINITY), |best, row| {
            if row.1 > best.1 {
                row
            } else {
                best
            }
        });
    let (j, i) = at;
    let radius = |left: Option<f64>, right: Option<f64>, step: f64| {
        let (l, r) = (left?, right?);
        let curvature = (2.0 * height - l - r) / (step * step);
        (curvature > 0.0).then(|| 1.0 / curvature)
    };
    let get = |j: i64, i: i64| {
        (j >= 0 && i >= 0 && (j as usize) < ny && (i as usize) < nx)
            .then(|| z[[j as usize, i as usize]])
    };
    let (ji, ii) = (j as i64, i as i64);
    Asperity {
        at: [j, i],
        height_m: height,
        radius_x_m: radius(get(ji, ii - 1), get(ji, ii + 1), dx),
        radius_y_m: radius(get(ji - 1, ii), get(ji + 1, ii), dy),
        profile_x: (0..nx).map(|k| (k as f64 * dx, z[[j, k]])).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map(ny: usize, nx: usize, dx: f64, f: impl Fn(f64, f64) -> f64) -> HeightMap {
        HeightMap::new(
            Array2::from_shape_fn((ny, nx), |(j, i)| f(i as f64 * dx, j as f64 * dx)),
            [dx, dx],
        )
        .expect("map")
    }

    #[test]
    fn a_sampled_sinusoid_has_the_closed_form_height_parameters() {
        // A cos(2π(x - xc)/λ) about the map's centre, λ dividing the map: Sq = A/√2,
        // Sa = 2A/π, Ssk = 0, Sku = 1.5 (the sample means of cos^k over whole periods are
        // exact); being even about the centre it has no least-squares plane to remove.
        let (a, lambda, n) = (1e-6, 32.0, 128);
        let centre = 0.5 * (n - 1) as f64;
        let sine = map(16, n, 1.0, |x, _| {
            a * (2.0 * PI * (x - centre) / lambda).cos()
        });
        let c = characterise(
            &sine,
            &Options {
                window: false,
                ..Options::default()
            },
        )
        .expect("ok");
        let h = c.height;
        assert!(
            (h.sq / (a / 2f64.sqrt()) - 1.0).abs() < 1e-12,
            "Sq {}",
            h.sq
        );
        // Sa of samples of a sine at 32 points per period: 2A/π to the sampling (1e-3).
        assert!((h.sa / (2.0 * a / PI) - 1.0).abs() < 2e-3, "Sa {}", h.sa);
        assert!(h.ssk.abs() < 1e-12, "Ssk {}", h.ssk);
        assert!((h.sku - 1.5).abs() < 1e-12, "Sku {}", h.sku);
        assert!((h.sp - a).abs() < 0.01 * a && (h.sv - a).abs() < 0.01 * a);
        // Profile values equal the areal ones for a surface uniform in y.
        assert!((c.profile.rq / h.sq - 1.0).abs() < 1e-3);
        // Sdq = A 2π/λ /√2 to the finite difference, (2 sin(π/λ)) A /√2, over whole periods;
        // the map's 127 cells miss one difference of the 128 of four periods (< 1 %).
        let sdq = 2.0 * (PI / lambda).sin() * a / 2f64.sqrt();
        assert!((c.sdq / sdq - 1.0).abs() < 0.01, "Sdq {} vs {sdq}", c.sdq);
        // Sal: the ACF cos(2πτ/λ) falls to 0.2 at λ acos(0.2)/(2π) along x, never along y.
        let sal = lambda * 0.2f64.acos() / (2.0 * PI);
        let measured = c.spatial.sal_m.expect("decays along x");
        assert!((measured - sal).abs() < 0.05, "Sal {measured} vs {sal}");
        assert!(c.spatial.str_bounded);
    }

    #[test]
    fn a_tilted_plane_is_all_zero_after_levelling() {
        let plane = map(20, 30, 1e-6, |x, y| 3e-6 + 0.01 * x - 0.02 * y);
        let (z, coefficients) = level(&plane, FormRemoval::Plane);
        assert!(
            z.iter().all(|v| v.abs() < 1e-18),
            "{}",
            z.iter().fold(0.0f64, |m, v| m.max(v.abs()))
        );
        assert!((coefficients[1] - 0.01).abs() < 1e-12 && (coefficients[2] + 0.02).abs() < 1e-12);
        assert!((coefficients[0] - 3e-6).abs() < 1e-18);
        let h = height_parameters(&z);
        for value in [h.sa, h.sq, h.sp, h.sv, h.sz] {
            assert!(value < 1e-18);
        }
        assert_eq!(
            characterise(&plane, &Options::default()),
            Err(StatsError::Flat)
        );
    }

    #[test]
    fn a_sampled_sphere_has_its_radius_as_summit_radius() {
        // One summit at the top of a sphere of radius R = 5 mm sampled every 1 um; with a
        // quadratic form removed nothing remains, so summits are measured on the raw cap.
        let radius = 5e-3;
        let cap = map(41, 41, 1e-6, |x, y| {
            let r2 = (x - 20e-6).powi(2) + (y - 20e-6).powi(2);
            (radius * radius - r2).sqrt() - radius
        });
        let s = summits(cap.heights_m(), cap.spacing_m());
        assert_eq!(s.count, 1);
        assert!((s.radius_m / radius - 1.0).abs() < 1e-6, "{}", s.radius_m);
        let (levelled, _) = level(&cap, FormRemoval::Plane);
        let asperity = highest_asperity(&levelled, cap.spacing_m());
        assert_eq!(asperity.at, [20, 20]);
        let rx = asperity.radius_x_m.expect("convex");
        assert!((rx / radius - 1.0).abs() < 1e-6, "{rx}");
    }

    #[test]
    fn summit_density_of_an_egg_box() {
        // cos(2πx/λ) cos(2πy/λ): maxima where both are 1 or both -1, two per λ² cell.
        let lambda = 16.0;
        let egg = map(128, 128, 1.0, |x, y| {
            (2.0 * PI * x / lambda).cos() * (2.0 * PI * y / lambda).cos()
        });
        let s = summits(egg.heights_m(), egg.spacing_m());
        let expected = 2.0 / (lambda * lambda);
        assert!(
            (s.density_per_m2 / expected - 1.0).abs() < 0.1,
            "{} vs {expected}",
            s.density_per_m2
        );
    }

    #[test]
    fn psd_normalisation_keeps_the_variance() {
        // White-ish noise from a small LCG: Σ C Δq²/(2π)² = Sq², Σ C1 Δq/2π = Rq² (no window).
        let mut state = 12345u64;
        let mut noise = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64 / (1u64 << 53) as f64) - 0.5
        };
        let (n, dx) = (64, 2e-6);
        let heights = Array2::from_shape_simple_fn((n, n), || 1e-6 * noise());
        let m = HeightMap::new(heights, [dx, dx]).expect("map");
        let (z, _) = level(&m, FormRemoval::Plane);
        let plan = RealFft2::new([n, n]);
        let mut work = plan.work();
        let mut spectrum = plan.new_spectrum();
        plan.forward(z.view(), &mut spectrum, &mut work)
            .expect("fft");
        let l = n as f64 * dx;
        let factor = dx * dx / (n * n) as f64;
        let mut total = 0.0;
        for ((kx, _), v) in spectrum.indexed_iter() {
            let weight = if kx == 0 || kx == n / 2 { 1.0 } else { 2.0 };
            total += weight * factor * v.norm_sqr();
        }
        let dq = 2.0 * PI / l;
        let variance = z.iter().map(|v| v * v).sum::<f64>() / (n * n) as f64;
        assert!((total * dq * dq / (4.0 * PI * PI) / variance - 1.0).abs() < 1e-12);
        let c = characterise(
            &m,
            &Options {
                window: false,
                ..Options::default()
            },
        )
        .expect("ok");
        // The 1-D PSD: two-sided sum over ±qx (and qx = 0) equals the mean row variance.
        let mut one_d = 0.0;
        for (k, (_, value)) in c.spectra.profile.iter().enumerate() {
            one_d += if k + 1 == n / 2 { 1.0 } else { 2.0 } * value;
        }
        let row_dc: f64 = z
            .rows()
            .into_iter()
            .map(|r| (r.sum() / n as f64).powi(2))
            .sum::<f64>()
            / n as f64;
        let expected = variance - row_dc;
        assert!(
            (one_d * dq / (2.0 * PI) / expected - 1.0).abs() < 1e-10,
            "{one_d}"
        );
    }
}

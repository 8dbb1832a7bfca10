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

mod heights;
mod spectra;
mod summits;
pub use heights::*;
pub use spectra::*;
pub use summits::*;

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
    #[error("a map of {ny} x {nx} samples needs about {} to characterise ({BYTES_PER_SAMPLE} bytes a sample), more than the {} allowed here (at most 4 GiB, and 3/4 of the memory available); crop or resample the surface (half the samples a side needs a quarter)", crate::io::text::bytes(*needed), crate::io::text::bytes(*limit))]
    TooLarge {
        ny: usize,
        nx: usize,
        needed: u64,
        limit: u64,
    },
    #[error(transparent)]
    Transform(#[from] TransformError),
}

/// The memory a characterisation takes, per sample of the map, the map included: the peak
/// resident size of `stressfield surface` on x3p maps of 1024², 2048² and 4096² random heights
/// grows by 48 bytes a sample (62, 212 and 816 MB; about 11 MB of it is the program). The
/// levelled copy, the windowed copy, the spectrum and its work buffers, the autocorrelation
/// and the summit search each hold a map-sized array at the peak.
pub const BYTES_PER_SAMPLE: u64 = 48;

/// Refuses a map whose characterisation would take more than `limit` bytes (estimated with
/// [`BYTES_PER_SAMPLE`] before anything is allocated; the x3p reader asks before unpacking).
pub(crate) fn check_memory([ny, nx]: [usize; 2], limit: u64) -> Result<(), StatsError> {
    let needed = (ny as u64)
        .saturating_mul(nx as u64)
        .saturating_mul(BYTES_PER_SAMPLE);
    if needed > limit {
        return Err(StatsError::TooLarge {
            ny,
            nx,
            needed,
            limit,
        });
    }
    Ok(())
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
    /// `None` when some row is flat to rounding ([`heights::ROUNDING_FLAT`]): its skewness and
    /// kurtosis would be those of the rounding noise.
    pub rsk: Option<f64>,
    pub rku: Option<f64>,
    /// The rows flat to rounding.
    pub flat_rows: usize,
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
    /// `None` when the band holds fewer than three rings of the spectrum, or when the fitted
    /// slope gives an exponent outside (0, 1] (a fractal dimension outside [2, 3)): the
    /// spectrum is then not self-affine over the band and the number means nothing.
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

/// Spectrum columns (kx) per parallel block of the radial average.
const RING_BLOCK: usize = 16;

/// The characterisation of `map` (module doc).
pub fn characterise(map: &HeightMap, options: &Options) -> Result<Characterisation, StatsError> {
    let [ny, nx] = map.shape();
    if nx < 8 || ny < 8 {
        return Err(StatsError::TooSmall(ny, nx));
    }
    check_memory([ny, nx], crate::field::memory_limit_bytes() as u64)?;
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
    let hurst = Some(-slope / 2.0 - 1.0).filter(|h| *h > 0.0 && *h <= 1.0);
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

#[cfg(test)]
mod tests;

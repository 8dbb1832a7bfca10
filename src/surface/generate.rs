//! Gaussian random rough surfaces by Fourier filtering of white noise (Hu & Tonder 1992):
//! periodic by construction, seeded, and bit-for-bit the same on every machine.
//!
//! ## Method
//! 1. White noise: independent standard normal samples, one per grid point, from the ChaCha8
//!    stream cipher (`rand_chacha::ChaCha8Rng::seed_from_u64(seed)`, a portable generator)
//!    turned into normal deviates by the Box–Muller transform, `sqrt(-2 ln u1) cos(2π u2)` and
//!    `sqrt(-2 ln u1) sin(2π u2)`, with `u = (k + 1) 2⁻⁵³` from the top 53 bits `k` of each
//!    64-bit output (so `u` lies in (0, 1]).
//! 2. Its 2-D discrete Fourier transform ([`crate::operator::transform::RealFft2`]) is multiplied by the
//!    square root of the target isotropic power spectrum `C(q)`, at `q = |(qx, qy)|`,
//!    `qx = 2π kx / Lx`, `qy = 2π ky / Ly` with signed FFT indices and the periods `Lx = nx dx`,
//!    `Ly = ny dy`. The mean (q = 0) and the Nyquist rows and columns are set to zero, so the
//!    heights are the samples of a real trigonometric polynomial with zero mean.
//! 3. The spectrum is scaled so that the rms height of the samples, or the rms slope of the
//!    trigonometric polynomial, is exactly the one asked (both by Parseval's theorem, from the
//!    spectrum), then transformed back.
//!
//! Spectra: a **self-affine** surface has `C(q) = C0` below the roll-off wavenumber `qr`,
//! `C0 (q / qr)^(-2(1 + H))` between `qr` and the short-wavelength cutoff `qs`, and zero
//! beyond (Persson et al. 2005; Jacobs, Junge & Pastewka 2017, §2); `H` is the Hurst exponent,
//! the fractal dimension `D = 3 - H`. A **Gaussian autocorrelation** `R(r) = Sq² exp(-(r/ℓ)²)`
//! (ℓ: the distance at which the correlation falls to 1/e) has the power spectrum
//! `C(q) ∝ exp(-q² ℓ² / 4)`.
//!
//! ## References
//! - Y. Z. Hu, K. Tonder, Simulation of 3-D random rough surface by 2-D digital filter and
//!   Fourier analysis, *Int. J. Mach. Tools Manufact.* 32 (1992) 83–90.
//! - B. N. J. Persson, O. Albohr, U. Tartaglino, A. I. Volokitin, E. Tosatti, On the nature of
//!   surface roughness with application to contact mechanics, sealing, rubber friction and
//!   adhesion, *J. Phys.: Condens. Matter* 17 (2005) R1.
//! - T. D. B. Jacobs, T. Junge, L. Pastewka, Quantitative characterization of surface
//!   topography using spectral analysis, *Surf. Topogr.: Metrol. Prop.* 5 (2017) 013001.

use std::f64::consts::PI;

use ndarray::{Array2, Axis, Zip};
use rand_chacha::ChaCha8Rng;
use rand_core::{RngCore, SeedableRng};
use rayon::prelude::*;
use rustfft::num_complex::Complex;

use super::{HeightMap, SurfaceError};
use crate::operator::transform::{signed_index, RealFft2, TransformError};

/// The power spectrum of a generated surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Spectrum {
    /// Flat below the roll-off wavelength, `q^(-2(1+H))` from there to the cutoff, zero beyond.
    SelfAffine {
        /// Hurst exponent `H` in (0, 1].
        hurst: f64,
        /// The longest wavelength of the power law (the roll-off), `2π / qr`.
        rolloff_wavelength_m: f64,
        /// The shortest wavelength of the surface, `2π / qs`.
        cutoff_wavelength_m: f64,
    },
    /// A Gaussian autocorrelation `exp(-(r/ℓ)²)`.
    Gaussian { correlation_length_m: f64 },
}

/// How large the roughness is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Amplitude {
    /// Root mean square of the sampled heights (m).
    RmsHeight(f64),
    /// Root mean square of `|∇h|` of the periodic trigonometric interpolant (the spectral
    /// slope, the convention of contact mechanics codes; dimensionless).
    RmsSlope(f64),
}

/// A shape superposed on the roughness (heights out of the body: the top is highest).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Form {
    None,
    /// A sphere of this radius about the map's centre: `sqrt(R² - r²) - R` (a rough ball).
    Sphere {
        radius_m: f64,
    },
    /// A cylinder with its axis along y through the map's centre: `sqrt(R² - x²) - R`.
    Cylinder {
        radius_m: f64,
    },
}

/// What to generate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Generator {
    /// `[ny, nx]` samples.
    pub shape: [usize; 2],
    /// `[dx, dy]` in m.
    pub spacing_m: [f64; 2],
    pub spectrum: Spectrum,
    pub amplitude: Amplitude,
    pub form: Form,
    pub seed: u64,
}

/// Parameters that cannot make a surface.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GenerateError {
    #[error("{name} {requirement}, got {}", crate::io::text::number(*.value))]
    Parameter {
        name: &'static str,
        requirement: &'static str,
        value: f64,
    },
    #[error("a generated surface needs at least 4 x 4 samples, got {0} x {1}")]
    TooSmall(usize, usize),
    #[error("no wavelength of the spectrum fits between the cutoff and the map's size: the surface would be flat")]
    Empty,
    #[error(
        "the sphere or cylinder radius {radius_m} m is smaller than half the map ({half_m} m)"
    )]
    FormTooSmall { radius_m: f64, half_m: f64 },
    #[error(transparent)]
    Surface(#[from] SurfaceError),
    #[error(transparent)]
    Transform(#[from] TransformError),
}

fn positive(name: &'static str, value: f64) -> Result<f64, GenerateError> {
    if value > 0.0 && value.is_finite() {
        Ok(value)
    } else {
        Err(GenerateError::Parameter {
            name,
            requirement: "must be positive and finite",
            value,
        })
    }
}

impl Spectrum {
    /// Checks the parameters.
    fn check(&self) -> Result<(), GenerateError> {
        match *self {
            Spectrum::SelfAffine {
                hurst,
                rolloff_wavelength_m,
                cutoff_wavelength_m,
            } => {
                if !(hurst > 0.0 && hurst <= 1.0) {
                    return Err(GenerateError::Parameter {
                        name: "hurst",
                        requirement: "must lie in (0, 1]",
                        value: hurst,
                    });
                }
                positive("rolloff wavelength", rolloff_wavelength_m)?;
                positive("cutoff wavelength", cutoff_wavelength_m)?;
                if cutoff_wavelength_m > rolloff_wavelength_m {
                    return Err(GenerateError::Parameter {
                        name: "cutoff wavelength",
                        requirement: "must not exceed the roll-off wavelength",
                        value: cutoff_wavelength_m,
                    });
                }
            }
            Spectrum::Gaussian {
                correlation_length_m,
            } => {
                positive("correlation length", correlation_length_m)?;
            }
        }
        Ok(())
    }

    /// The square root of the (unnormalised) power spectrum at the wavenumber `q` (rad/m).
    pub fn filter(&self, q: f64) -> f64 {
        match *self {
            Spectrum::SelfAffine {
                hurst,
                rolloff_wavelength_m,
                cutoff_wavelength_m,
            } => {
                let (qr, qs) = (
                    2.0 * PI / rolloff_wavelength_m,
                    2.0 * PI / cutoff_wavelength_m,
                );
                if q > qs * (1.0 + 1e-12) {
                    0.0
                } else if q <= qr {
                    1.0
                } else {
                    (q / qr).powf(-(1.0 + hurst))
                }
            }
            Spectrum::Gaussian {
                correlation_length_m,
            } => (-(q * correlation_length_m).powi(2) / 8.0).exp(),
        }
    }
}

/// Standard normal deviates from a seeded ChaCha8 stream (Box–Muller, see the module doc).
struct Normal {
    rng: ChaCha8Rng,
    spare: Option<f64>,
}

impl Normal {
    fn new(seed: u64) -> Self {
        Self {
            rng: ChaCha8Rng::seed_from_u64(seed),
            spare: None,
        }
    }

    /// The stream of `seed` from its deviate number `index` on: deviates `2k` and `2k + 1`
    /// come from the 64-bit outputs `2k` and `2k + 1`, that is the 32-bit words `4k..4k + 4`,
    /// so any position can be reached without drawing what comes before it.
    fn at(seed: u64, index: usize) -> Self {
        let mut normal = Self::new(seed);
        normal.rng.set_word_pos(4 * (index / 2) as u128);
        if index % 2 == 1 {
            normal.sample();
        }
        normal
    }

    fn uniform(&mut self) -> f64 {
        ((self.rng.next_u64() >> 11) + 1) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    fn sample(&mut self) -> f64 {
        if let Some(value) = self.spare.take() {
            return value;
        }
        let radius = (-2.0 * self.uniform().ln()).sqrt();
        let angle = 2.0 * PI * self.uniform();
        self.spare = Some(radius * angle.sin());
        radius * angle.cos()
    }
}

/// Deviates per parallel chunk of [`white_noise`] (a fixed count, so the chunks, and with them
/// the bits, do not depend on the number of threads).
const NOISE_CHUNK: usize = 1 << 15;

/// `[ny, nx]` standard normal deviates of `seed` in row-major order: the sequence of
/// [`Normal::new`]`(seed)`, drawn in parallel chunks that each start at their own position.
fn white_noise(seed: u64, [ny, nx]: [usize; 2]) -> Array2<f64> {
    let mut noise = Array2::zeros((ny, nx));
    let values = noise
        .as_slice_mut()
        .expect("a new array is contiguous in standard order");
    values
        .par_chunks_mut(NOISE_CHUNK)
        .enumerate()
        .for_each(|(chunk, values)| {
            let mut normal = Normal::at(seed, chunk * NOISE_CHUNK);
            for value in values {
                *value = normal.sample();
            }
        });
    noise
}

/// The wavenumbers `(qx, qy)` (rad/m) of the stored spectrum entry `[kx, ky]`, or `None` on a
/// Nyquist row or column (an even count's `n/2`), whose direction is ambiguous.
fn wavenumbers(kx: usize, ky: usize, shape: [usize; 2], period_m: [f64; 2]) -> Option<(f64, f64)> {
    let [ny, nx] = shape;
    let nyquist = |k: usize, n: usize| n.is_multiple_of(2) && k == n / 2;
    if nyquist(kx, nx) || nyquist(ky, ny) {
        return None;
    }
    Some((
        2.0 * PI * kx as f64 / period_m[0],
        2.0 * PI * signed_index(ky, ny) as f64 / period_m[1],
    ))
}

/// Generates the surface.
pub fn generate(generator: &Generator) -> Result<HeightMap, GenerateError> {
    let [ny, nx] = generator.shape;
    if nx < 4 || ny < 4 {
        return Err(GenerateError::TooSmall(ny, nx));
    }
    let [dx, dy] = generator.spacing_m;
    positive("dx", dx)?;
    positive("dy", dy)?;
    generator.spectrum.check()?;
    match generator.amplitude {
        Amplitude::RmsHeight(value) => positive("rms height", value)?,
        Amplitude::RmsSlope(value) => positive("rms slope", value)?,
    };
    let period_m = [nx as f64 * dx, ny as f64 * dy];

    let mut noise = white_noise(generator.seed, [ny, nx]);
    let plan = RealFft2::new([ny, nx]);
    let mut work = plan.work();
    let mut spectrum = plan.new_spectrum();
    plan.forward(noise.view(), &mut spectrum, &mut work)?;

    // Filter, and accumulate Σ|H|² and Σ|H|² q² over the full spectrum (columns kx > 0 of the
    // stored half stand for their conjugates too, except a Nyquist column). In parallel over
    // kx, each kx summed on its own and the sums added in kx order: the same bits on any
    // number of threads.
    let spectral = &generator.spectrum;
    let sums: Vec<(f64, f64)> = spectrum
        .axis_iter_mut(Axis(0))
        .into_par_iter()
        .enumerate()
        .map(|(kx, mut column)| {
            let (mut power, mut slope_power) = (0.0, 0.0);
            let weight = if kx == 0 { 1.0 } else { 2.0 };
            for (ky, value) in column.iter_mut().enumerate() {
                let Some((qx, qy)) = wavenumbers(kx, ky, [ny, nx], period_m) else {
                    *value = Complex::new(0.0, 0.0);
                    continue;
                };
                let q2 = qx * qx + qy * qy;
                if q2 == 0.0 {
                    *value = Complex::new(0.0, 0.0);
                    continue;
                }
                *value *= spectral.filter(q2.sqrt());
                let norm = value.norm_sqr();
                power += weight * norm;
                slope_power += weight * norm * q2;
            }
            (power, slope_power)
        })
        .collect();
    let (power, slope_power) = sums
        .iter()
        .fold((0.0, 0.0), |(a, b), (p, s)| (a + p, b + s));
    if power == 0.0 {
        return Err(GenerateError::Empty);
    }
    // Parseval: mean(h²) = Σ|H|² / N², mean(|∇h|²) = Σ|H|² q² / N².
    let count = (nx * ny) as f64;
    let scale = match generator.amplitude {
        Amplitude::RmsHeight(rms) => rms / (power.sqrt() / count),
        Amplitude::RmsSlope(rms) => rms / (slope_power.sqrt() / count),
    };
    spectrum.par_mapv_inplace(|v| v * scale);
    // The noise's memory takes the heights.
    plan.inverse(&mut spectrum, noise.view_mut(), &mut work)?;
    let mut heights = noise;

    match generator.form {
        Form::None => {}
        Form::Sphere { radius_m } | Form::Cylinder { radius_m } => {
            positive("form radius", radius_m)?;
            let along_y = matches!(generator.form, Form::Sphere { .. });
            let half_m = 0.5
                * if along_y {
                    period_m[0].hypot(period_m[1])
                } else {
                    period_m[0]
                };
            if radius_m <= half_m {
                return Err(GenerateError::FormTooSmall { radius_m, half_m });
            }
            let (cx, cy) = (0.5 * (nx - 1) as f64 * dx, 0.5 * (ny - 1) as f64 * dy);
            Zip::indexed(&mut heights).par_for_each(|(j, i), h| {
                let x = i as f64 * dx - cx;
                let y = if along_y { j as f64 * dy - cy } else { 0.0 };
                let r2 = x * x + y * y;
                // sqrt(R² - r²) - R without cancellation.
                *h -= r2 / (radius_m + (radius_m * radius_m - r2).sqrt());
            });
        }
    }
    Ok(HeightMap::new(heights, generator.spacing_m)?)
}

/// The rms slope of a periodic map: the root mean square of `|∇h|` of its trigonometric
/// interpolant, from the spectrum (Nyquist rows and columns left out, as [`generate`] does).
pub fn spectral_rms_slope(map: &HeightMap) -> Result<f64, TransformError> {
    let [ny, nx] = map.shape();
    let plan = RealFft2::new([ny, nx]);
    let mut work = plan.work();
    let mut spectrum = plan.new_spectrum();
    plan.forward(map.heights_m().view(), &mut spectrum, &mut work)?;
    let period_m = map.size_m();
    let mut slope_power = 0.0;
    for ((kx, ky), value) in spectrum.indexed_iter() {
        if let Some((qx, qy)) = wavenumbers(kx, ky, [ny, nx], period_m) {
            let weight = if kx == 0 { 1.0 } else { 2.0 };
            slope_power += weight * value.norm_sqr() * (qx * qx + qy * qy);
        }
    }
    Ok(slope_power.sqrt() / (nx * ny) as f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn self_affine(n: usize, amplitude: Amplitude, seed: u64) -> Generator {
        Generator {
            shape: [n, n],
            spacing_m: [1e-6, 1e-6],
            spectrum: Spectrum::SelfAffine {
                hurst: 0.8,
                rolloff_wavelength_m: n as f64 * 1e-6 / 4.0,
                cutoff_wavelength_m: 4e-6,
            },
            amplitude,
            form: Form::None,
            seed,
        }
    }

    fn moments(map: &HeightMap) -> (f64, f64, f64, f64) {
        let h = map.heights_m();
        let n = h.len() as f64;
        let mean = h.sum() / n;
        let m2 = h.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n;
        let m3 = h.iter().map(|v| (v - mean).powi(3)).sum::<f64>() / n;
        let m4 = h.iter().map(|v| (v - mean).powi(4)).sum::<f64>() / n;
        (mean, m2.sqrt(), m3 / m2.powf(1.5), m4 / (m2 * m2))
    }

    #[test]
    fn rms_height_and_rms_slope_are_as_asked() {
        let map = generate(&self_affine(128, Amplitude::RmsHeight(0.5e-6), 3)).expect("ok");
        let (mean, rms, _, _) = moments(&map);
        assert!(mean.abs() < 1e-12 * 0.5e-6, "zero mean: {mean}");
        assert!((rms / 0.5e-6 - 1.0).abs() < 1e-12, "{rms}");
        let map = generate(&self_affine(96, Amplitude::RmsSlope(0.2), 4)).expect("ok");
        let slope = spectral_rms_slope(&map).expect("fft");
        assert!((slope / 0.2 - 1.0).abs() < 1e-12, "{slope}");
        // Finite differences of a well-resolved surface (cutoff 4 samples) are close to it.
        let h = map.heights_m();
        let mut sum = 0.0;
        for ((j, i), v) in h.indexed_iter() {
            let dx = (h[[j, (i + 1) % 96]] - v) / 1e-6;
            let dy = (h[[(j + 1) % 96, i]] - v) / 1e-6;
            sum += dx * dx + dy * dy;
        }
        let finite_difference = (sum / h.len() as f64).sqrt();
        assert!(
            (finite_difference / 0.2 - 1.0).abs() < 0.15,
            "{finite_difference}"
        );
    }

    #[test]
    fn the_same_seed_gives_the_same_bits() {
        let a = generate(&self_affine(32, Amplitude::RmsHeight(1e-6), 7)).expect("ok");
        let b = generate(&self_affine(32, Amplitude::RmsHeight(1e-6), 7)).expect("ok");
        let c = generate(&self_affine(32, Amplitude::RmsHeight(1e-6), 8)).expect("ok");
        assert_eq!(a, b);
        assert_ne!(a, c);
        // The stream itself is fixed: the first normal deviates of seed 0 (ChaCha8 + Box-Muller).
        // A change of the generator crate or of this code shows here.
        let mut normal = Normal::new(0);
        let first: Vec<f64> = (0..4).map(|_| normal.sample()).collect();
        let mut again = Normal::new(0);
        assert_eq!(first, (0..4).map(|_| again.sample()).collect::<Vec<_>>());
        let mut rng = ChaCha8Rng::seed_from_u64(0);
        let word = rng.next_u64();
        let u1 = ((word >> 11) + 1) as f64 / (1u64 << 53) as f64;
        let u2 = ((rng.next_u64() >> 11) + 1) as f64 / (1u64 << 53) as f64;
        let expected = (-2.0 * u1.ln()).sqrt() * (2.0 * PI * u2).cos();
        assert_eq!(first[0], expected);
        assert_eq!(word, 0xb585f767a79a3b6c, "ChaCha8 stream of seed 0");
    }

    #[test]
    fn parallel_noise_is_the_sequential_stream() {
        // Two chunks (the second starts inside a row of 1001), and starts at odd positions
        // (the second deviate of a Box-Muller pair) directly.
        let shape = [40, 1001];
        let noise = white_noise(5, shape);
        let mut normal = Normal::new(5);
        let sequential: Vec<f64> = (0..shape[0] * shape[1]).map(|_| normal.sample()).collect();
        assert_eq!(noise.as_slice().expect("contiguous"), &sequential[..]);
        for index in [0, 1, 2, 7, 32768, 32769] {
            assert_eq!(Normal::at(5, index).sample(), sequential[index], "{index}");
        }
    }

    #[test]
    fn heights_are_gaussian_within_the_sampling_error() {
        // Skewness and kurtosis of a correlated Gaussian field: with about (L/λr)² = 16 x 16
        // independent patches at the roll-off... use a short roll-off so there are many.
        let mut generator = self_affine(256, Amplitude::RmsHeight(1e-6), 11);
        generator.spectrum = Spectrum::SelfAffine {
            hurst: 0.8,
            rolloff_wavelength_m: 16e-6,
            cutoff_wavelength_m: 4e-6,
        };
        let map = generate(&generator).expect("ok");
        let (_, _, skew, kurtosis) = moments(&map);
        // About 256 independent wavelength-16 patches per side squared: 4096 samples' worth,
        // standard errors sqrt(6/4096) = 0.04 and sqrt(24/4096) = 0.08; allow 3 of them.
        assert!(skew.abs() < 0.12, "Ssk {skew}");
        assert!((kurtosis - 3.0).abs() < 0.24, "Sku {kurtosis}");
    }

    #[test]
    fn the_spectrum_follows_the_power_law() {
        // Radially averaged |H(q)|² of one 256² realisation between roll-off and cutoff: the
        // log-log slope is -2(1 + H) = -3.6 within the scatter of one realisation.
        let n = 256;
        let map = generate(&self_affine(n, Amplitude::RmsHeight(1e-6), 5)).expect("ok");
        let plan = RealFft2::new([n, n]);
        let mut work = plan.work();
        let mut spectrum = plan.new_spectrum();
        plan.forward(map.heights_m().view(), &mut spectrum, &mut work)
            .expect("fft");
        let period = map.size_m();
        let mut bins = vec![(0.0, 0usize); n];
        for ((kx, ky), v) in spectrum.indexed_iter() {
            if let Some((qx, qy)) = wavenumbers(kx, ky, [n, n], period) {
                let k = (qx.hypot(qy) * period[0] / (2.0 * PI)).round() as usize;
                if k < n {
                    bins[k].0 += v.norm_sqr();
                    bins[k].1 += 1;
                }
            }
        }
        // Rings k = 8 (roll-off at k = 4, so above it) .. 56 (cutoff at k = 64).
        let points: Vec<(f64, f64)> = (8..=56)
            .map(|k| ((k as f64).ln(), (bins[k].0 / bins[k].1 as f64).ln()))
            .collect();
        let m = points.len() as f64;
        let (sx, sy) = points
            .iter()
            .fold((0.0, 0.0), |(a, b), p| (a + p.0, b + p.1));
        let (mx, my) = (sx / m, sy / m);
        let slope = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum::<f64>()
            / points.iter().map(|p| (p.0 - mx).powi(2)).sum::<f64>();
        assert!((slope + 3.6).abs() < 0.15, "slope {slope}");
        // Nothing beyond the cutoff (k = 64), but rounding of a few energies near it.
        let total: f64 = bins.iter().map(|b| b.0).sum();
        let beyond: f64 = bins[66..].iter().map(|b| b.0).sum();
        assert!(beyond < 1e-20 * total, "{beyond} of {total}");
    }

    #[test]
    fn gaussian_autocorrelation_falls_to_1_over_e_at_the_correlation_length() {
        let n = 256;
        let ell = 8e-6;
        let generator = Generator {
            shape: [n, n],
            spacing_m: [1e-6, 1e-6],
            spectrum: Spectrum::Gaussian {
                correlation_length_m: ell,
            },
            amplitude: Amplitude::RmsHeight(1e-6),
            form: Form::None,
            seed: 2,
        };
        let map = generate(&generator).expect("ok");
        let h = map.heights_m();
        let correlation = |lag: usize| {
            let mut sum = 0.0;
            for ((j, i), v) in h.indexed_iter() {
                sum += v * (h[[j, (i + lag) % n]] + h[[(j + lag) % n, i]]) / 2.0;
            }
            sum / h.len() as f64 / 1e-12
        };
        let at_ell = correlation(8);
        // One realisation of 32 x 32 correlation areas: sampling error of a few percent.
        assert!((at_ell - (-1.0f64).exp()).abs() < 0.06, "{at_ell}");
        assert!((correlation(4) - (-0.25f64).exp()).abs() < 0.06);
    }

    #[test]
    fn a_sphere_form_makes_a_rough_ball_with_its_top_highest() {
        let mut generator = self_affine(64, Amplitude::RmsHeight(1e-9), 1);
        generator.form = Form::Sphere { radius_m: 1e-3 };
        let map = generate(&generator).expect("ok");
        let h = map.heights_m();
        let (max_at, _) =
            h.indexed_iter().fold(
                ((0, 0), f64::MIN),
                |best, (at, &v)| if v > best.1 { (at, v) } else { best },
            );
        assert!(
            max_at.0.abs_diff(31) <= 1 && max_at.1.abs_diff(31) <= 1,
            "top at {max_at:?}"
        );
        // Curvature 1/R along x about the centre x = 31.5 samples (roughness 1 nm beside the
        // 0.2 um drop): h(31.5 - d) - h(31.5 - d - 20) = ((d + 20)² - d²) dx² / (2R).
        let drop = h[[31, 31]] - h[[31, 11]];
        let radius = (20.5f64.powi(2) - 0.5f64.powi(2)) * 1e-12 / (2.0 * drop);
        assert!((radius / 1e-3 - 1.0).abs() < 0.02, "{radius}");
        let mut cylinder = generator;
        cylinder.form = Form::Cylinder { radius_m: 1e-3 };
        let map = generate(&cylinder).expect("ok");
        let h = map.heights_m();
        assert!((h[[0, 31]] - h[[63, 31]]).abs() < 1e-8, "constant along y");
    }

    #[test]
    fn bad_parameters_name_themselves() {
        let mut generator = self_affine(32, Amplitude::RmsHeight(1e-6), 1);
        generator.spectrum = Spectrum::SelfAffine {
            hurst: 1.5,
            rolloff_wavelength_m: 1e-5,
            cutoff_wavelength_m: 1e-6,
        };
        let error = generate(&generator).expect_err("hurst");
        assert!(error.to_string().contains("hurst"), "{error}");
        generator.spectrum = Spectrum::SelfAffine {
            hurst: 0.8,
            rolloff_wavelength_m: 1e-6,
            cutoff_wavelength_m: 1e-5,
        };
        assert!(generate(&generator).is_err());
        let mut tiny = self_affine(32, Amplitude::RmsHeight(0.0), 1);
        assert!(generate(&tiny).is_err());
        tiny.amplitude = Amplitude::RmsHeight(1e-6);
        // Every wavelength longer than the map: nothing fits.
        tiny.spectrum = Spectrum::SelfAffine {
            hurst: 0.8,
            rolloff_wavelength_m: 1.0,
            cutoff_wavelength_m: 1e-3,
        };
        assert_eq!(generate(&tiny), Err(GenerateError::Empty));
        let mut ball = self_affine(32, Amplitude::RmsHeight(1e-6), 1);
        ball.form = Form::Sphere { radius_m: 1e-6 };
        assert!(matches!(
            generate(&ball),
            Err(GenerateError::FormTooSmall { .. })
        ));
    }
}

//! The normal surface displacement of an elastic half-space under a pressure given on a grid of
//! uniformly loaded rectangular cells, as an integral operator applied by FFT: non-periodic
//! (an isolated contact; linear convolution by DC-FFT with zero padding) or periodic (a
//! periodic surface; every periodic image of every cell included).
//!
//! This is the operator of the rough-contact solver ([`crate::contact::rough`]); like Tamaas's
//! integral operators, one solver receives either kind.
//!
//! ## Influence coefficients
//! A pressure `p` uniform on the rectangle `|x| <= a`, `|y| <= b` of the surface of a
//! half-space displaces the surface, into the body, by (Love 1929; Johnson 1985, §3.2)
//!
//! ```text
//! u(x, y) = p / (π E*) [g(x + a, y + b) - g(x + a, y - b) - g(x - a, y + b) + g(x - a, y - b)]
//! g(X, Y) = X asinh(Y / |X|) + Y asinh(X / |Y|)        (a term is 0 where its factor is 0)
//! ```
//!
//! for two bodies in contact, `1/E* = (1 - ν1²)/E1 + (1 - ν2²)/E2` gives their combined
//! approach (each body's displacement is that of its own `(1 - ν²)/E`). Love's logarithms
//! `X ln(Y + R)` are written with `asinh(Y/|X|) = ln((Y + R)/|X|)`; the `X ln|X|` left over
//! cancels between the two corners that share `X`. At the centre of a square of side `h`,
//! `u = 4 h ln(1 + √2) p / (π E*)`.
//!
//! The coefficient `K(i, j)` is `u` at the centre of the cell offset by `(i dx, j dy)` from a
//! unit-loaded cell; it is evaluated on the lattice of cell corners, each corner term once.
//!
//! ## Non-periodic operator
//! `u = K * p` over the `ny x nx` grid is a linear convolution: DC-FFT (Liu, Wang & Liu 2000)
//! lays out `K` for the offsets `-n < i < n` in wrap-around order on a `2n` grid, zero-pads `p`
//! to it, and keeps the first `n` values of the cyclic convolution, which equal the linear one
//! exactly. `K` is even in `i` and in `j`, so its transform is real.
//!
//! ## Periodic operator
//! A periodic pressure of period `Lx = nx dx`, `Ly = ny dy` loads every image of every cell:
//! `K_per(d) = Σ_m K(d + m L)`. That sum diverges (a pressure of non-zero mean displaces a
//! half-space without bound) by a constant, which is dropped: the mean (zero-wavenumber) mode
//! of the operator is set to zero, so `u` has zero mean and the rigid approach of a periodic
//! contact is measured from the mean plane of the deformed surface. The images with
//! `|mx|, |my| <= 1` are summed exactly; the others, seen from the nine central periods, act as
//! point loads of the cell's resultant spread over the plane (density `1 / (Lx Ly)`), whose
//! potential outside the rectangle `|x| < 1.5 Lx`, `|y| < 1.5 Ly` differs from its value at
//! `d = 0` by the quadrupole term
//!
//! ```text
//! δ(d) = dx dy / (π E*) · 1/(2 Lx Ly) · (dₓ² J1 + d_y² J2),
//! J1 = ∫_out (2x² - y²)/r⁵ dA = 4 [(2s - s³)/A - (c - c³)/B],
//! J2 = ∫_out (2y² - x²)/r⁵ dA = 4 [(2c - c³)/B - (s - s³)/A],
//! ```
//!
//! with `A = 1.5 Lx`, `B = 1.5 Ly`, `s = sin φ`, `c = cos φ`, `tan φ = B / A` (the integrals in
//! polar coordinates, derived here). The next term falls like `(d / 1.5L)⁴`; the test compares
//! with five images each way.
//!
//! ## References
//! - A. E. H. Love, The stress produced in a semi-infinite solid by pressure on part of the
//!   boundary, *Phil. Trans. R. Soc. A* 228 (1929).
//! - K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §3.2.
//! - S. Liu, Q. Wang, G. Liu, A versatile method of discrete convolution and FFT (DC-FFT) for
//!   contact analyses, *Wear* 243 (2000).

use std::f64::consts::PI;

use ndarray::{Array2, ArrayView2, ArrayViewMut2};
use rustfft::num_complex::Complex;

use crate::operator::transform::{Fft2Work, RealFft2, TransformError};

/// `g(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|)`, a term 0 where its factor is 0.
#[inline]
fn love_corner(x: f64, y: f64) -> f64 {
    let first = if x == 0.0 {
        0.0
    } else {
        x * (y / x.abs()).asinh()
    };
    let second = if y == 0.0 {
        0.0
    } else {
        y * (x / y.abs()).asinh()
    };
    first + second
}

/// Normal surface displacement, times `π E* / p`, at `(x, y)` from a pressure `p` uniform on
/// the rectangle `|x| <= half_x`, `|y| <= half_y` (metres in, metres out; see the module doc).
pub fn uniform_patch_displacement(x: f64, y: f64, half_x: f64, half_y: f64) -> f64 {
    love_corner(x + half_x, y + half_y)
        - love_corner(x + half_x, y - half_y)
        - love_corner(x - half_x, y + half_y)
        + love_corner(x - half_x, y - half_y)
}

/// `K(i, j) π E*` for the offsets `first_x <= i < first_x + count_x` (and the same in y) of
/// cells `dx x dy`, from one row of corner terms to the next: `[count_y, count_x]`.
fn coefficients(spacing_m: [f64; 2], first: [i64; 2], count: [usize; 2]) -> Array2<f64> {
    let mut out = Array2::zeros((count[1], count[0]));
    coefficient_rows(spacing_m, first, count, |l, row| {
        out.row_mut(l).assign(&ndarray::ArrayView1::from(row));
    });
    out
}

/// The rows of [`coefficients`], one at a time (`visit(l, row)`), so that a sum over many
/// periodic images holds two rows of corner terms instead of every coefficient.
fn coefficient_rows(
    spacing_m: [f64; 2],
    first: [i64; 2],
    count: [usize; 2],
    mut visit: impl FnMut(usize, &[f64]),
) {
    let [dx, dy] = spacing_m;
    let [first_x, first_y] = first;
    let [count_x, count_y] = count;
    // Corner k of the row sits at x = (first_x + k - 1/2) dx.
    let corner_x: Vec<f64> = (0..=count_x)
        .map(|k| (first_x as f64 + k as f64 - 0.5) * dx)
        .collect();
    let fill = |l: usize, row: &mut Vec<f64>| {
        let y = (first_y as f64 + l as f64 - 0.5) * dy;
        row.clear();
        row.extend(corner_x.iter().map(|&x| love_corner(x, y)));
    };
    let (mut below, mut above) = (Vec::new(), Vec::new());
    let mut out = vec![0.0; count_x];
    fill(0, &mut below);
    for l in 0..count_y {
        fill(l + 1, &mut above);
        for i in 0..count_x {
            // Offset (X, Y) = (i, l) cells: X + a is corner i + 1, X - a corner i; Y + b the
            // row above, Y - b the row below.
            out[i] = above[i + 1] - below[i + 1] - above[i] + below[i];
        }
        visit(l, &out);
        std::mem::swap(&mut below, &mut above);
    }
}

/// The longest period a periodic operator takes, in lengths of the shorter: its kernel sums
/// the images out to 1.5 times the longer period each way (see [`periodic_kernel`]), about
/// `9 x aspect` corner terms a cell, so a map 1024 times longer than wide took minutes; 64
/// keeps it within about 600 terms a cell (2.5 s at 65,536 cells).
pub const MAX_PERIODIC_ASPECT: f64 = 64.0;

/// The longer period over the shorter of a `[ny, nx]` grid of cells `[dx, dy]`.
pub fn period_aspect(shape: [usize; 2], spacing_m: [f64; 2]) -> f64 {
    let (lx, ly) = (
        shape[1] as f64 * spacing_m[0],
        shape[0] as f64 * spacing_m[1],
    );
    lx.max(ly) / lx.min(ly)
}

/// Which convolution the operator makes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Periodicity {
    /// An isolated contact: zero pressure beyond the grid (DC-FFT, zero padding).
    NonPeriodic,
    /// A periodic surface: the grid is one period.
    Periodic,
}

/// The operator `p -> u` on one grid, with its FFT plans, kernel spectrum and work buffers.
pub struct ElasticOperator {
    shape: [usize; 2],
    periodicity: Periodicity,
    /// The kernel at offset zero, m/Pa.
    own_m_per_pa: f64,
    plan: RealFft2,
    /// The real transform of the kernel (even in x and y), in m/Pa.
    kernel: Array2<f64>,
    spectrum: Array2<Complex<f64>>,
    work: Fft2Work,
}

impl ElasticOperator {
    /// Bytes the operator holds for a `[ny, nx]` grid (kernel and pressure spectra, FFT row
    /// buffers), for a memory estimate before building it.
    pub fn memory_bytes(shape: [usize; 2], periodicity: Periodicity) -> usize {
        let factor = match periodicity {
            Periodicity::NonPeriodic => 2,
            Periodicity::Periodic => 1,
        };
        let (ny, nx) = (factor * shape[0], factor * shape[1]);
        let half = (nx / 2 + 1) * ny;
        // Kernel (f64) + spectrum (complex) + FFT row spectra (complex) + the corner rows.
        half * (8 + 16 + 16) + 64 * (nx + ny)
    }

    /// Plans the transforms and computes the kernel spectrum for cells `[dx, dy]` (m) and the
    /// combined modulus `E*` (Pa).
    pub fn new(
        shape: [usize; 2],
        spacing_m: [f64; 2],
        e_star_pa: f64,
        periodicity: Periodicity,
    ) -> Result<Self, TransformError> {
        let [ny, nx] = shape;
        let scale = 1.0 / (PI * e_star_pa);
        let (plan_shape, kernel_grid) = match periodicity {
            Periodicity::NonPeriodic => {
                // Offsets 0..n on the first quadrant, mirrored into wrap-around order.
                let quadrant = coefficients(spacing_m, [0, 0], [nx, ny]);
                let mut grid = Array2::zeros((2 * ny, 2 * nx));
                for ((j, i), &k) in quadrant.indexed_iter() {
                    let (jm, im) = ((2 * ny - j) % (2 * ny), (2 * nx - i) % (2 * nx));
                    for (a, b) in [(j, i), (jm, i), (j, im), (jm, im)] {
                        grid[[a, b]] = k * scale;
                    }
                }
                ([2 * ny, 2 * nx], grid)
            }
            Periodicity::Periodic => ([ny, nx], periodic_kernel(shape, spacing_m) * scale),
        };
        let plan = RealFft2::new(plan_shape);
        let mut work = plan.work();
        let mut spectrum = plan.new_spectrum();
        plan.forward(kernel_grid.view(), &mut spectrum, &mut work)?;
        let mut kernel = spectrum.mapv(|c| c.re);
        if periodicity == Periodicity::Periodic {
            // The mean mode: a constant displacement, absorbed in the approach (module doc).
            kernel[[0, 0]] = 0.0;
        }
        Ok(Self {
            shape,
            periodicity,
            own_m_per_pa: uniform_patch_displacement(
                0.0,
                0.0,
                spacing_m[0] / 2.0,
                spacing_m[1] / 2.0,
            ) / (PI * e_star_pa),
            plan,
            kernel,
            spectrum,
            work,
        })
    }

    /// The operator of any kernel given in real space (m/Pa, even in x and y): on the
    /// `[2ny, 2nx]` grid in wrap-around order (non-periodic) or on the `[ny, nx]` period
    /// (periodic; its mean mode is dropped), e.g. a coated body's
    /// ([`crate::coating::kernel::kernel_grid`]).
    pub fn from_kernel(
        shape: [usize; 2],
        periodicity: Periodicity,
        kernel_grid: &Array2<f64>,
    ) -> Result<Self, TransformError> {
        let [ny, nx] = shape;
        let plan_shape = match periodicity {
            Periodicity::NonPeriodic => [2 * ny, 2 * nx],
            Periodicity::Periodic => [ny, nx],
        };
        assert_eq!(
            kernel_grid.dim(),
            (plan_shape[0], plan_shape[1]),
            "the kernel grid must have the plan's shape"
        );
        let plan = RealFft2::new(plan_shape);
        let mut work = plan.work();
        let mut spectrum = plan.new_spectrum();
        plan.forward(kernel_grid.view(), &mut spectrum, &mut work)?;
        let mut kernel = spectrum.mapv(|c| c.re);
        if periodicity == Periodicity::Periodic {
            kernel[[0, 0]] = 0.0;
        }
        Ok(Self {
            shape,
            periodicity,
            own_m_per_pa: match periodicity {
                Periodicity::NonPeriodic => kernel_grid[[0, 0]],
                // Relative to the mean displacement, which the dropped mean mode removes.
                Periodicity::Periodic => kernel_grid[[0, 0]] - kernel_grid.mean().unwrap_or(0.0),
            },
            plan,
            kernel,
            spectrum,
            work,
        })
    }

    pub fn shape(&self) -> [usize; 2] {
        self.shape
    }

    /// A cell's displacement under its own unit pressure, m/Pa (the solver's local
    /// stiffness).
    pub fn own_m_per_pa(&self) -> f64 {
        self.own_m_per_pa
    }

    pub fn periodicity(&self) -> Periodicity {
        self.periodicity
    }

    /// `displacement = K * pressure` (m, into the bodies; Pa in), both `[ny, nx]`; allocates
    /// nothing.
    pub fn apply(
        &mut self,
        pressure: ArrayView2<f64>,
        displacement: ArrayViewMut2<f64>,
    ) -> Result<(), TransformError> {
        self.plan
            .forward(pressure, &mut self.spectrum, &mut self.work)?;
        self.spectrum
            .zip_mut_with(&self.kernel, |value, &k| *value *= k);
        self.plan
            .inverse(&mut self.spectrum, displacement, &mut self.work)
    }
}

/// `K_per π E*` on the `[ny, nx]` grid of signed offsets in wrap-around order (module doc),
/// for the layered kernels of [`crate::coating::kernel`].
pub fn periodic_love_kernel(shape: [usize; 2], spacing_m: [f64; 2]) -> Array2<f64> {
    periodic_kernel(shape, spacing_m)
}

/// `K_per π E*` on the `[ny, nx]` grid of signed offsets in wrap-around order (module doc).
fn periodic_kernel(shape: [usize; 2], spacing_m: [f64; 2]) -> Array2<f64> {
    // Images out to 1.5 times the longer period each way, so that the images left to the
    // continuum lie outside a nearly square region (a long, narrow period would otherwise
    // leave rows of nearby images to it).
    let (lx, ly) = (
        shape[1] as f64 * spacing_m[0],
        shape[0] as f64 * spacing_m[1],
    );
    let reach = 1.5 * lx.max(ly);
    let images = |period: f64| (reach / period - 0.5).ceil().max(1.0) as usize;
    periodic_kernel_with_images(shape, spacing_m, [images(lx), images(ly)], true)
}

/// The periodic kernel from the images `|mx| <= images[0]`, `|my| <= images[1]` summed
/// exactly, with or without the far-field quadrupole correction.
fn periodic_kernel_with_images(
    shape: [usize; 2],
    spacing_m: [f64; 2],
    images: [usize; 2],
    corrected: bool,
) -> Array2<f64> {
    let [ny, nx] = shape;
    let [dx, dy] = spacing_m;
    let [images_x, images_y] = images;
    // Offsets from -(images) periods - n/2 .. : every offset d + m L with d in [-n/2, n/2).
    let (half_x, half_y) = ((nx / 2) as i64, (ny / 2) as i64);
    let first = [
        -(images_x as i64) * nx as i64 - half_x,
        -(images_y as i64) * ny as i64 - half_y,
    ];
    let mut kernel = Array2::zeros((ny, nx));
    // Each row folded into one period as it is made (the rows of all images at once took
    // memory growing with the square of the longer period).
    coefficient_rows(
        spacing_m,
        first,
        [(2 * images_x + 1) * nx, (2 * images_y + 1) * ny],
        |l, row| {
            let fj = (first[1] + l as i64).rem_euclid(ny as i64) as usize;
            let mut folded = kernel.row_mut(fj);
            for (i, &k) in row.iter().enumerate() {
                let fi = (first[0] + i as i64).rem_euclid(nx as i64) as usize;
                folded[fi] += k;
            }
        },
    );
    if corrected {
        let (lx, ly) = (nx as f64 * dx, ny as f64 * dy);
        let (a, b) = ((images_x as f64 + 0.5) * lx, (images_y as f64 + 0.5) * ly);
        let phi = b.atan2(a);
        let (s, c) = (phi.sin(), phi.cos());
        let j1 = 4.0 * ((2.0 * s - s.powi(3)) / a - (c - c.powi(3)) / b);
        let j2 = 4.0 * ((2.0 * c - c.powi(3)) / b - (s - s.powi(3)) / a);
        let factor = dx * dy / (2.0 * lx * ly);
        for ((j, i), k) in kernel.indexed_iter_mut() {
            let ox = crate::operator::transform::signed_index(i, nx) as f64 * dx;
            let oy = crate::operator::transform::signed_index(j, ny) as f64 * dy;
            *k += factor * (ox * ox * j1 + oy * oy * j2);
        }
    }
    kernel
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn centre_of_a_loaded_square_and_the_far_field() {
        // Johnson §3.2: 4 h ln(1 + √2) at the centre of a square of side h.
        let h = 2e-6;
        let centre = uniform_patch_displacement(0.0, 0.0, h / 2.0, h / 2.0);
        assert!((centre / (4.0 * h * (1.0 + 2f64.sqrt()).ln()) - 1.0).abs() < 1e-14);
        // Far away a cell acts as a point load: u π E* = area / r (Boussinesq).
        let (x, y) = (300e-6, 400e-6);
        let far = uniform_patch_displacement(x, y, h / 2.0, 0.7 * h / 2.0);
        let point = h * 0.7 * h / x.hypot(y);
        assert!((far / point - 1.0).abs() < 1e-5, "{far} vs {point}");
        // Corner terms on the lattice equal the direct formula.
        let table = coefficients([h, 0.7 * h], [-3, -2], [7, 5]);
        for ((l, i), &k) in table.indexed_iter() {
            let (ox, oy) = ((i as f64 - 3.0) * h, (l as f64 - 2.0) * 0.7 * h);
            let direct = uniform_patch_displacement(ox, oy, h / 2.0, 0.35 * h);
            assert!((k - direct).abs() < 1e-13 * h, "({i}, {l})");
        }
    }

    #[test]
    fn non_periodic_operator_equals_direct_summation() {
        let (shape, spacing, e_star) = ([5, 7], [1e-6, 1.5e-6], 100e9);
        let pressure = Array2::from_shape_fn((5, 7), |(j, i)| ((i * 3 + j * 5) % 7) as f64 * 1e6);
        let mut operator =
            ElasticOperator::new(shape, spacing, e_star, Periodicity::NonPeriodic).expect("plan");
        let mut u = Array2::zeros((5, 7));
        operator
            .apply(pressure.view(), u.view_mut())
            .expect("apply");
        for ((j, i), &got) in u.indexed_iter() {
            let mut sum = 0.0;
            for ((l, k), &p) in pressure.indexed_iter() {
                let (ox, oy) = (
                    (i as f64 - k as f64) * spacing[0],
                    (j as f64 - l as f64) * spacing[1],
                );
                sum += p * uniform_patch_displacement(ox, oy, 0.5e-6, 0.75e-6);
            }
            sum /= PI * e_star;
            assert!(
                (got - sum).abs() < 1e-12 * sum.abs(),
                "({j}, {i}): {got} vs {sum}"
            );
        }
    }

    #[test]
    fn periodic_kernel_converges_with_the_images_and_matches_love_near_the_load() {
        let (shape, spacing) = ([32, 48], [1.0, 1.25]);
        let reference = periodic_kernel_with_images(shape, spacing, [5, 5], true);
        let corrected = periodic_kernel(shape, spacing);
        let plain = periodic_kernel_with_images(shape, spacing, [1, 1], false);
        // Up to a constant (the dropped mean mode): compare after removing the means.
        let centred = |k: &Array2<f64>| {
            let mean = k.mean().unwrap_or(0.0);
            k.mapv(|v| v - mean)
        };
        let (r, c, p) = (centred(&reference), centred(&corrected), centred(&plain));
        let scale = r.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let error = |k: &Array2<f64>| {
            k.iter()
                .zip(&r)
                .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
                / scale
        };
        assert!(error(&c) < 2e-4, "corrected: {}", error(&c));
        assert!(
            error(&p) > 10.0 * error(&c),
            "the correction matters: {}",
            error(&p)
        );
        // Near the loaded cell, the periodic kernel differs from Love's by a smooth function:
        // differences of neighbours agree to well below the kernel's own variation.
        let love =
            |i: i64, j: i64| uniform_patch_displacement(i as f64, 1.25 * j as f64, 0.5, 0.625);
        let at = |i: i64, j: i64| reference[[j.rem_euclid(32) as usize, i.rem_euclid(48) as usize]];
        for (i, j) in [(1, 0), (0, 1), (2, 2), (-3, 1)] {
            let periodic = at(i, j) - at(0, 0);
            let isolated = love(i, j) - love(0, 0);
            assert!(
                (periodic - isolated).abs() < 0.01 * isolated.abs(),
                "({i}, {j}): {periodic} vs {isolated}"
            );
        }
    }

    #[test]
    fn periodic_operator_of_a_sinusoid_is_its_spectral_response() {
        // p = cos(2π x / L): u = 2 p / (E* q) times the cell factor and aliases; for a long
        // wavelength (16 cells) the cell-based result lies within 1 % of 2/(E* q).
        let (nx, ny, dx, e_star) = (64, 8, 1e-6, 1e11);
        let period = nx as f64 * dx / 4.0;
        let pressure = Array2::from_shape_fn((ny, nx), |(_, i)| {
            (2.0 * PI * (i as f64 * dx) / period).cos()
        });
        let mut operator =
            ElasticOperator::new([ny, nx], [dx, dx], e_star, Periodicity::Periodic).expect("plan");
        let mut u = Array2::zeros((ny, nx));
        operator
            .apply(pressure.view(), u.view_mut())
            .expect("apply");
        let q = 2.0 * PI / period;
        let amplitude = 2.0 / (e_star * q);
        for ((_, i), &value) in u.indexed_iter() {
            let expected = amplitude * pressure[[0, i]];
            assert!(
                (value - expected).abs() < 0.01 * amplitude,
                "{i}: {value} vs {expected}"
            );
        }
        // Uniform in y and exactly proportional to the pressure (one mode).
        let ratio = u[[3, 0]] / pressure[[3, 0]];
        for ((j, i), &value) in u.indexed_iter() {
            assert!((value - ratio * pressure[[j, i]]).abs() < 1e-12 * amplitude);
        }
        // A uniform pressure: zero displacement (the mean mode is dropped).
        let uniform = Array2::from_elem((ny, nx), 1e6);
        operator.apply(uniform.view(), u.view_mut()).expect("apply");
        assert!(u.iter().all(|v| v.abs() < 1e-20), "{}", u[[0, 0]]);
    }
}

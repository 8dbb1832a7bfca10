//! Numerical helpers of the thermal module: Gauss–Legendre rules, adaptive Gauss–Kronrod
//! quadrature and the modified Bessel function `K0` (scaled by `e^x`).

use std::f64::consts::PI;

/// The `n`-point Gauss–Legendre rule on `[-1, 1]`: nodes and weights, by Newton's iteration on
/// the Legendre recurrence (Abramowitz & Stegun 1964, §25.4.29; Golub & Welsch give the same
/// nodes). Accurate to rounding for `n <= 64`.
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut nodes = vec![0.0; n];
    let mut weights = vec![0.0; n];
    for i in 0..n.div_ceil(2) {
        // Tricomi's first guess of the i-th largest root.
        let mut x = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut derivative = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=n {
                let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            let value = if n == 0 { 1.0 } else { p1 };
            let previous = if n == 1 { 1.0 } else { p0 };
            derivative = n as f64 * (x * value - previous) / (x * x - 1.0);
            let step = value / derivative;
            x -= step;
            if step.abs() < 1e-16 {
                break;
            }
        }
        let w = 2.0 / ((1.0 - x * x) * derivative * derivative);
        nodes[i] = -x;
        nodes[n - 1 - i] = x;
        weights[i] = w;
        weights[n - 1 - i] = w;
    }
    (nodes, weights)
}

/// Gauss–Kronrod 7/15 nodes (non-negative half) and weights (Piessens et al., QUADPACK 1983).
const KRONROD_NODES: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
const KRONROD_WEIGHTS: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
const GAUSS_WEIGHTS: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];

/// One Gauss–Kronrod 7/15 panel: the Kronrod estimate and its difference from Gauss's.
fn kronrod_panel(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    let (centre, half) = (0.5 * (a + b), 0.5 * (b - a));
    let middle = f(centre);
    let mut kronrod = KRONROD_WEIGHTS[7] * middle;
    let mut gauss = GAUSS_WEIGHTS[3] * middle;
    for k in 0..7 {
        let d = half * KRONROD_NODES[k];
        let sum = f(centre - d) + f(centre + d);
        kronrod += KRONROD_WEIGHTS[k] * sum;
        if k % 2 == 1 {
            gauss += GAUSS_WEIGHTS[k / 2] * sum;
        }
    }
    (kronrod * half, (kronrod - gauss).abs() * half)
}

/// `∫_a^b f` by globally adaptive Gauss–Kronrod 7/15 bisection until the summed error
/// estimate is below `tolerance` (absolute), or 4000 panels. Integrable end-point
/// singularities (logarithmic, inverse square root) converge by bisection.
pub fn integrate(f: impl Fn(f64) -> f64, a: f64, b: f64, tolerance: f64) -> f64 {
    if a == b {
        return 0.0;
    }
    let (value, error) = kronrod_panel(&f, a, b);
    let mut panels = vec![(a, b, value, error)];
    let mut total_error = error;
    while total_error > tolerance && panels.len() < 4000 {
        // The panel with the largest error is halved.
        let worst = panels
            .iter()
            .enumerate()
            .max_by(|p, q| p.1 .3.total_cmp(&q.1 .3))
            .map_or(0, |(i, _)| i);
        let (pa, pb, _, pe) = panels.swap_remove(worst);
        let middle = 0.5 * (pa + pb);
        if middle <= pa || middle >= pb {
            panels.push((pa, pb, 0.0, 0.0));
            total_error -= pe;
            continue;
        }
        let left = kronrod_panel(&f, pa, middle);
        let right = kronrod_panel(&f, middle, pb);
        total_error += left.1 + right.1 - pe;
        panels.push((pa, middle, left.0, left.1));
        panels.push((middle, pb, right.0, right.1));
    }
    panels.iter().map(|p| p.2).sum()
}

/// `e^x K0(x)` for `x > 0`: the modified Bessel function of the second kind, scaled so that it
/// stays finite where `K0` underflows. Polynomial approximations of Abramowitz & Stegun (1964)
/// 9.8.1 (`I0`), 9.8.5 (`K0`, `x <= 2`) and 9.8.6 (`√x e^x K0`, `x >= 2`); absolute error below
/// 2e-7 relative to the leading term.
pub fn bessel_k0_scaled(x: f64) -> f64 {
    if x <= 2.0 {
        let t = (x / 3.75).powi(2);
        let i0 = 1.0
            + t * (3.515_622_9
                + t * (3.089_942_4
                    + t * (1.206_749_2 + t * (0.265_973_2 + t * (0.036_076_8 + t * 0.004_581_3)))));
        let s = (x / 2.0).powi(2);
        let k0 = -(x / 2.0).ln() * i0 - 0.577_215_66
            + s * (0.422_784_20
                + s * (0.230_697_56
                    + s * (0.034_885_90
                        + s * (0.002_626_98 + s * (0.000_107_50 + s * 0.000_007_40)))));
        k0 * x.exp()
    } else {
        let t = 2.0 / x;
        (1.253_314_14
            + t * (-0.078_323_58
                + t * (0.021_895_68
                    + t * (-0.010_624_46
                        + t * (0.005_878_72 + t * (-0.002_515_40 + t * 0.000_532_08))))))
            / x.sqrt()
    }
}

/// Euler's constant γ.
pub const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// `Σ_(n>=1) (-x)^n / (n n!)`, so that `E1(x) = -γ - ln x - series(x)` (Abramowitz & Stegun
/// 1964, 5.1.11); used for `x <= 1`.
pub fn exponential_integral_series(x: f64) -> f64 {
    let (mut sum, mut term) = (0.0, 1.0);
    for n in 1..60 {
        term *= -x / n as f64;
        let add = term / n as f64;
        sum += add;
        if add.abs() < 1e-17 * sum.abs().max(1e-300) {
            break;
        }
    }
    sum
}

/// The exponential integral `E1(x) = ∫_x^∞ e^(-t)/t dt` for `x > 0`: the series of
/// Abramowitz & Stegun (1964) 5.1.11 for `x <= 1`, their continued fraction 5.1.22 (evaluated
/// by Lentz's method) above; relative error near rounding.
pub fn exponential_integral_e1(x: f64) -> f64 {
    if x <= 1.0 {
        return -EULER_GAMMA - x.ln() - exponential_integral_series(x);
    }
    if x > 740.0 {
        return 0.0;
    }
    // E1(x) = e^(-x) / (x + 1 - 1² / (x + 3 - 2² / (x + 5 - ...))).
    let tiny = 1e-300;
    let mut b = x + 1.0;
    let mut c = 1.0 / tiny;
    let mut d = 1.0 / b;
    let mut h = d;
    for i in 1..200 {
        let a = -((i * i) as f64);
        b += 2.0;
        d = 1.0 / (a * d + b);
        c = b + a / c;
        let delta = c * d;
        h *= delta;
        if (delta - 1.0).abs() < 1e-16 {
            break;
        }
    }
    h * (-x).exp()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_integrates_polynomials_exactly() {
        for n in [1, 2, 5, 8, 16, 33] {
            let (x, w) = gauss_legendre(n);
            for degree in 0..2 * n {
                let sum: f64 = x
                    .iter()
                    .zip(&w)
                    .map(|(x, w)| w * x.powi(degree as i32))
                    .sum();
                let exact = if degree % 2 == 1 {
                    0.0
                } else {
                    2.0 / (degree as f64 + 1.0)
                };
                assert!((sum - exact).abs() < 1e-13, "n {n} degree {degree}: {sum}");
            }
        }
    }

    #[test]
    fn adaptive_quadrature_handles_end_point_singularities() {
        // ∫_0^1 ln x dx = -1; ∫_0^1 x^(-1/2) dx = 2.
        assert!((integrate(|x: f64| x.ln(), 0.0, 1.0, 1e-12) + 1.0).abs() < 1e-10);
        assert!((integrate(|x: f64| 1.0 / x.sqrt(), 0.0, 1.0, 1e-12) - 2.0).abs() < 1e-9);
    }

    #[test]
    fn k0_matches_reference_values() {
        // K0 from mpmath (besselk(0, x)) to 12 digits.
        for (x, k0) in [
            (0.01, 4.721_244_730_161),
            (0.5, 0.924_419_071_227_7),
            (1.0, 0.421_024_438_240_7),
            (2.0, 0.113_893_872_749_5),
            (5.0, 0.003_691_098_334_043),
            (20.0, 5.741_237_815_336e-10),
        ] {
            let value = bessel_k0_scaled(x) * (-x).exp();
            assert!(
                ((value - k0) / k0).abs() < 2e-6,
                "K0({x}) = {value}, reference {k0}"
            );
        }
    }

    #[test]
    fn e1_matches_reference_values() {
        // E1 from mpmath (e1(x)) to 15 digits.
        for (x, e1) in [
            (1e-3, 6.331_539_364_136_15),
            (0.5, 0.559_773_594_776_160_8),
            (1.0, 0.219_383_934_395_520_3),
            (2.0, 0.048_900_510_708_061_12),
            (5.0, 0.001_148_295_591_275_326),
            (30.0, 3.021_552_010_688_81e-15),
        ] {
            let value = exponential_integral_e1(x);
            assert!(
                ((value - e1) / e1).abs() < 1e-12,
                "E1({x}) = {value}, reference {e1}"
            );
        }
    }
}

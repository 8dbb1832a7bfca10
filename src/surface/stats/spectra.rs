//! Spectral statistics: the spectral moments, the Hann window, and the spatial parameters
//! from the autocorrelation.

use super::*;

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

/// The heights times a 2-D Hann window, scaled so that the mean square is kept (so the PSD
/// keeps `Σ C Δq²/(2π)² = Sq²` on average).
pub(super) fn hann(z: &Array2<f64>) -> Array2<f64> {
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
pub(super) fn spatial_parameters(acf: &Array2<f64>, spacing: [f64; 2]) -> Spatial {
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

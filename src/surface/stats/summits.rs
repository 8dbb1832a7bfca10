//! Summits: counted on the grid (8-neighbour maxima), McCool's estimates from the spectral
//! moments, and the highest asperity with its tip radius.

use super::*;

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

/// Samples an asperity keeps from every edge of the map: its eight neighbours and the ring
/// the topography draws around it (three samples) lie inside the map, so that it is known to
/// be a summit and its circle is whole.
pub const ASPERITY_MARGIN: usize = 3;

/// The highest asperity: the highest summit (a sample no lower than its eight neighbours, as
/// the summits are counted) at least [`ASPERITY_MARGIN`] samples from every edge (less on a
/// map too small for it), or the highest sample there when no summit is (a map flat along a
/// direction); its profiles and tip radii by central differences.
pub(super) fn highest_asperity(z: &Array2<f64>, spacing: [f64; 2]) -> Asperity {
    let (ny, nx) = z.dim();
    let [dx, dy] = spacing;
    let margin = |n: usize| ASPERITY_MARGIN.min(n.saturating_sub(1) / 2).max(1);
    let (my, mx) = (margin(ny), margin(nx));
    let inside = |j: usize, i: usize| j >= my && j + my < ny && i >= mx && i + mx < nx;
    let summit = |j: usize, i: usize| {
        let v = z[[j, i]];
        (j - 1..=j + 1).all(|b| (i - 1..=i + 1).all(|a| z[[b, a]] <= v))
    };
    // Each row's first highest candidate, then the first highest row: the first in row-major
    // order, as a sequential scan finds it; summits first, any sample if there is none.
    let best = |only_summits: bool| {
        let rows = per_row(ny, |j| {
            z.row(j)
                .iter()
                .enumerate()
                .filter(|&(i, _)| inside(j, i) && (!only_summits || summit(j, i)))
                .fold(((j, 0), f64::NEG_INFINITY), |best, (i, &v)| {
                    if v > best.1 {
                        ((j, i), v)
                    } else {
                        best
                    }
                })
        });
        rows.into_iter()
            .fold(((0, 0), f64::NEG_INFINITY), |best, row| {
                if row.1 > best.1 {
                    row
                } else {
                    best
                }
            })
    };
    let found = best(true);
    let (at, height) = if found.1.is_finite() {
        found
    } else {
        best(false)
    };
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

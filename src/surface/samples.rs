//! What the surface readers ([`super::read`], [`super::x3p`]) share: their error, and what to
//! do with missing points, harmonic interpolation from the valid neighbours: the discrete
//! Laplace equation (each missing height the mean of its grid neighbours, three at an edge and
//! two at a corner) with the valid heights fixed, solved by Jacobi-preconditioned conjugate
//! gradients (Saad, *Iterative Methods for Sparse Linear Systems*, 2nd ed., 2003, Alg. 9.1);
//! the system is symmetric and positive definite because every connected patch of missing
//! points touches a valid one.

use ndarray::Array2;

use super::SurfaceError;

/// What to do with missing points.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Fill {
    /// Refuse the file, naming the first missing point.
    #[default]
    Refuse,
    /// Harmonic interpolation from the valid neighbours.
    Interpolate,
}

/// Why a surface file cannot be used.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    #[error("cannot read {path}: {source}")]
    Io {
        path: String,
        #[source]
        source: std::io::Error,
    },
    #[error("{path}: {message}")]
    Format { path: String, message: String },
    #[error("{path}: line {line}, column {column}: {message}")]
    At {
        path: String,
        line: usize,
        column: usize,
        message: String,
    },
    #[error("{path}: {size_mib} MiB is more than the {limit_mib} MiB a surface file may have here (its heights would need about {needed_mib} MiB)")]
    TooLarge {
        path: String,
        size_mib: u64,
        limit_mib: u64,
        needed_mib: u64,
    },
    #[error(transparent)]
    Archive(#[from] crate::io::archive::ArchiveError),
    #[error("{path}: {source}")]
    Surface {
        path: String,
        #[source]
        source: SurfaceError,
    },
}

/// Fills non-finite heights by harmonic interpolation from the finite ones (module doc).
///
/// Conjugate gradients need about as many iterations as the largest missing patch is wide (a
/// Gauss–Seidel relaxation needed its square: a mostly missing 256² map ran 50 s and did not
/// settle), each over the missing points only.
pub fn interpolate_missing(heights: &mut Array2<f64>) -> Result<(), String> {
    let (ny, nx) = heights.dim();
    let missing: Vec<(usize, usize)> = heights
        .indexed_iter()
        .filter(|(_, v)| !v.is_finite())
        .map(|(at, _)| at)
        .collect();
    if missing.is_empty() {
        return Ok(());
    }
    if missing.len() == heights.len() {
        return Err("every height is missing: there is nothing to interpolate from".to_string());
    }
    // The unknowns' numbers on the grid (usize::MAX for a valid height).
    let mut number = Array2::from_elem((ny, nx), usize::MAX);
    for (k, &at) in missing.iter().enumerate() {
        number[at] = k;
    }
    let neighbours = |j: usize, i: usize| {
        [(-1i64, 0i64), (1, 0), (0, -1), (0, 1)]
            .into_iter()
            .filter_map(move |(dj, di)| {
                let (y, x) = (j as i64 + dj, i as i64 + di);
                (y >= 0 && x >= 0 && (y as usize) < ny && (x as usize) < nx)
                    .then_some((y as usize, x as usize))
            })
    };
    // A x = b: (count) h_m - sum of missing neighbours = sum of valid neighbours.
    let diagonal: Vec<f64> = missing
        .iter()
        .map(|&(j, i)| neighbours(j, i).count() as f64)
        .collect();
    let b: Vec<f64> = missing
        .iter()
        .map(|&(j, i)| {
            neighbours(j, i)
                .filter(|&at| number[at] == usize::MAX)
                .map(|at| heights[at])
                .sum()
        })
        .collect();
    let apply = |x: &[f64], out: &mut [f64]| {
        for (k, &(j, i)) in missing.iter().enumerate() {
            let off: f64 = neighbours(j, i).filter_map(|at| x.get(number[at])).sum();
            out[k] = diagonal[k] * x[k] - off;
        }
    };
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let m = missing.len();
    // Start from the mean of the valid heights.
    let mean = heights.iter().filter(|v| v.is_finite()).sum::<f64>() / (heights.len() - m) as f64;
    let mut x = vec![mean; m];
    let mut r = vec![0.0; m];
    apply(&x, &mut r);
    for (r, b) in r.iter_mut().zip(&b) {
        *r = b - *r;
    }
    let mut z: Vec<f64> = r.iter().zip(&diagonal).map(|(r, d)| r / d).collect();
    let mut p = z.clone();
    let mut q = vec![0.0; m];
    let mut rz = dot(&r, &z);
    let b_norm = dot(&b, &b).sqrt().max(mean.abs() * (m as f64).sqrt());
    let tolerance = 1e-13 * b_norm.max(f64::MIN_POSITIVE);
    // In exact arithmetic CG ends within m steps; rounding may take a few more.
    let mut settled = false;
    for _ in 0..(2 * m + 100) {
        if dot(&r, &r).sqrt() <= tolerance {
            settled = true;
            break;
        }
        apply(&p, &mut q);
        let alpha = rz / dot(&p, &q);
        for k in 0..m {
            x[k] += alpha * p[k];
            r[k] -= alpha * q[k];
            z[k] = r[k] / diagonal[k];
        }
        let rz_new = dot(&r, &z);
        let beta = rz_new / rz;
        rz = rz_new;
        for k in 0..m {
            p[k] = z[k] + beta * p[k];
        }
    }
    if !settled {
        return Err("the interpolation of the missing points did not settle".to_string());
    }
    for (&at, value) in missing.iter().zip(x) {
        heights[at] = value;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A bilinear height a + b x + c y + d x y is discretely harmonic: with the map's edge and
    /// 3 % of its inside given, the 97 % missing inside is that surface again (to 1e-9 of its
    /// range). Gauss–Seidel did not settle on such a map.
    #[test]
    fn a_mostly_missing_map_is_filled_harmonically() {
        let n = 200;
        let exact = |j: usize, i: usize| {
            let (x, y) = (i as f64, j as f64);
            1e-6 * (0.3 + 0.002 * x - 0.001 * y + 1e-5 * x * y)
        };
        let mut state = 12345u64;
        let mut heights = Array2::from_shape_fn((n, n), |(j, i)| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let keep = (state >> 33) % 100 < 3;
            let edge = j == 0 || i == 0 || j == n - 1 || i == n - 1;
            if edge || keep {
                exact(j, i)
            } else {
                f64::NAN
            }
        });
        let missing = heights.iter().filter(|v| v.is_nan()).count();
        assert!(missing as f64 > 0.9 * (n * n) as f64);
        interpolate_missing(&mut heights).expect("settles");
        let range = 1e-6 * (0.002 + 0.001 + 1e-5 * 200.0) * 200.0;
        let worst = heights
            .indexed_iter()
            .map(|((j, i), v)| (v - exact(j, i)).abs())
            .fold(0.0f64, f64::max);
        assert!(worst < 1e-9 * range, "{worst:e} of {range:e}");
    }

    /// Each filled point is the mean of its neighbours (three at an edge): a single valid
    /// point fills everything with its height; an isolated hole in a corner is the mean of
    /// its two neighbours.
    #[test]
    fn filled_points_are_means_of_their_neighbours() {
        let mut one = Array2::from_elem((5, 7), f64::NAN);
        one[[2, 3]] = 4.0;
        interpolate_missing(&mut one).expect("settles");
        assert!(one.iter().all(|&v| (v - 4.0).abs() < 1e-12), "{one:?}");
        let mut corner = Array2::from_shape_fn((3, 3), |(j, i)| (j * 3 + i) as f64);
        corner[[0, 0]] = f64::NAN;
        interpolate_missing(&mut corner).expect("settles");
        assert!((corner[[0, 0]] - 2.0).abs() < 1e-12);
        let mut none = Array2::from_elem((2, 2), f64::NAN);
        assert!(interpolate_missing(&mut none).is_err());
    }
}

//! What the surface readers ([`super::read`], [`super::x3p`]) share: their error, and what to
//! do with missing points, harmonic interpolation from the valid neighbours (Gauss–Seidel
//! relaxation of Laplace's equation with the valid heights fixed, until the largest change is
//! below 1e-9 of the height range).

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
pub fn interpolate_missing(heights: &mut Array2<f64>) -> Result<(), String> {
    let (ny, nx) = heights.dim();
    let missing: Vec<(usize, usize)> = heights
        .indexed_iter()
        .filter(|(_, v)| !v.is_finite())
        .map(|(at, _)| at)
        .collect();
    if missing.len() == heights.len() {
        return Err("every height is missing: there is nothing to interpolate from".to_string());
    }
    let (low, high) = heights
        .iter()
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let mean = heights.iter().filter(|v| v.is_finite()).sum::<f64>()
        / (heights.len() - missing.len()) as f64;
    for &at in &missing {
        heights[at] = mean;
    }
    let tolerance = 1e-9 * (high - low).max(f64::MIN_POSITIVE);
    for _ in 0..100_000 {
        let mut change = 0.0f64;
        for &(j, i) in &missing {
            let mut sum = 0.0;
            let mut count = 0;
            for (dj, di) in [(-1i64, 0i64), (1, 0), (0, -1), (0, 1)] {
                let (y, x) = (j as i64 + dj, i as i64 + di);
                if y >= 0 && x >= 0 && (y as usize) < ny && (x as usize) < nx {
                    sum += heights[[y as usize, x as usize]];
                    count += 1;
                }
            }
            let value = sum / count as f64;
            change = change.max((value - heights[[j, i]]).abs());
            heights[[j, i]] = value;
        }
        if change <= tolerance {
            return Ok(());
        }
    }
    Err("the interpolation of the missing points did not settle".to_string())
}

//! Height statistics: levelling (form removal by least squares), the ISO 25178 height and
//! hybrid parameters, profile parameters along rows, and the height histogram.

use super::*;

/// Per-row values `f(j)` of the rows `0..rows`, computed in parallel and returned in row
/// order: sums folded from them in that order have the same bits on any number of threads.
pub(super) fn per_row<T: Send>(rows: usize, f: impl Fn(usize) -> T + Sync + Send) -> Vec<T> {
    (0..rows).into_par_iter().map(f).collect()
}

/// Least-squares fit of `z` by `K` basis functions of the sample indices `(i, j)`, over the
/// samples of `region` (all for `None`), by the normal equations (solved by Gaussian
/// elimination with partial pivoting).
fn least_squares<const K: usize>(
    map: &Array2<f64>,
    basis: &(dyn Fn(usize, usize) -> [f64; K] + Sync),
    region: Option<&SampleRegion>,
) -> [f64; K] {
    let ny = map.nrows();
    let rows = per_row(ny, |j| {
        let (mut a, mut r) = ([[0.0; K]; K], [0.0; K]);
        if region.is_some_and(|region| !region.rows.contains(&j)) {
            return (a, r);
        }
        for (i, &z) in map.row(j).iter().enumerate() {
            if region.is_some_and(|region| !region.columns.contains(&i)) {
                continue;
            }
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
    let datum = Datum::fitted(map, form, None);
    (datum.remove_from(map.heights_m()), datum.plane_m)
}

/// The samples `columns` x `rows` of a map (index ranges): where a datum is fitted.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SampleRegion {
    pub columns: std::ops::Range<usize>,
    pub rows: std::ops::Range<usize>,
}

/// A least-squares form fitted to a height map, over all its samples or a region of them, to
/// be removed from that map or from another on the same grid: a measured series levelled by
/// one datum (its first map's plane removed from every map, or each map's plane fitted on a
/// region that does not wear), so that what differs between its maps is the surface's change
/// and not a levelling of its own (issue 50).
///
/// The form is fitted in centred, scaled sample coordinates `u = (i - ci)/ci`,
/// `v = (j - cj)/cj` in [-1, 1] (for conditioning); a region's fit is the same least-squares
/// problem restricted to its samples, extrapolated over the whole map.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Datum {
    form: FormRemoval,
    /// The map's `[rows, columns]`, which the form's coordinates are scaled by.
    shape: [usize; 2],
    /// The plane's coefficients in the scaled coordinates.
    plane: [f64; 3],
    /// The quadratic's coefficients in the scaled coordinates (zero for a plane).
    quadratic: [f64; 6],
    /// The plane `c0 + c1 x + c2 y` in physical coordinates (m, m/m, m/m; x and y from the
    /// first sample): the fitted samples' least-squares plane, whatever the form.
    pub plane_m: [f64; 3],
}

impl Datum {
    /// The least-squares `form` of `map`'s samples (of `region` only, when given).
    pub fn fitted(map: &HeightMap, form: FormRemoval, region: Option<&SampleRegion>) -> Self {
        let heights = map.heights_m();
        let spacing = map.spacing_m();
        let shape = map.shape();
        let plane = least_squares(heights, &|i, j| plane_basis(shape, i, j), region);
        let quadratic = match form {
            FormRemoval::Plane => [0.0; 6],
            FormRemoval::Quadratic => {
                least_squares(heights, &|i, j| quadratic_basis(shape, i, j), region)
            }
        };
        // The plane in physical coordinates: c0 + c1 x + c2 y.
        let (ci, cj, si, sj) = centring(shape);
        let [dx, dy] = spacing;
        let (cx, cy) = (ci * dx, cj * dy);
        let (p0, p1, p2) = (plane[0], plane[1] / (si * dx), plane[2] / (sj * dy));
        Self {
            form,
            shape,
            plane,
            quadratic,
            plane_m: [p0 - p1 * cx - p2 * cy, p1, p2],
        }
    }

    /// What is removed.
    pub fn form(&self) -> FormRemoval {
        self.form
    }

    /// `heights` (on the grid the datum was fitted on) less the fitted form.
    ///
    /// # Panics
    /// When `heights` is not on that grid (a caller's error: a series' maps are checked to
    /// share the first one's grid before they are levelled).
    pub fn remove_from(&self, heights: &Array2<f64>) -> Array2<f64> {
        assert_eq!(heights.dim(), (self.shape[0], self.shape[1]), "datum grid");
        let shape = self.shape;
        let mut levelled = heights.clone();
        match self.form {
            FormRemoval::Plane => Zip::indexed(&mut levelled).par_for_each(|(j, i), z| {
                let b = plane_basis(shape, i, j);
                *z -= b[0] * self.plane[0] + b[1] * self.plane[1] + b[2] * self.plane[2];
            }),
            FormRemoval::Quadratic => Zip::indexed(&mut levelled).par_for_each(|(j, i), z| {
                let b = quadratic_basis(shape, i, j);
                *z -= b
                    .iter()
                    .zip(&self.quadratic)
                    .map(|(b, c)| b * c)
                    .sum::<f64>();
            }),
        }
        levelled
    }
}

/// The centre `(ci, cj)` of a `[rows, columns]` grid in samples and the scales `(si, sj)` of
/// its coordinates `u = (i - ci)/si`, `v = (j - cj)/sj` in [-1, 1].
fn centring(shape: [usize; 2]) -> (f64, f64, f64, f64) {
    let [ny, nx] = shape;
    let (ci, cj) = (0.5 * (nx - 1) as f64, 0.5 * (ny - 1) as f64);
    (ci, cj, ci.max(f64::MIN_POSITIVE), cj.max(f64::MIN_POSITIVE))
}

/// The plane's basis `[1, u, v]` at sample `(i, j)` ([`centring`]).
fn plane_basis(shape: [usize; 2], i: usize, j: usize) -> [f64; 3] {
    let (ci, cj, si, sj) = centring(shape);
    [1.0, (i as f64 - ci) / si, (j as f64 - cj) / sj]
}

/// The quadratic's basis `[1, u, v, u², uv, v²]` at sample `(i, j)` ([`centring`]).
fn quadratic_basis(shape: [usize; 2], i: usize, j: usize) -> [f64; 6] {
    let [_, u, v] = plane_basis(shape, i, j);
    [1.0, u, v, u * u, u * v, v * v]
}

/// Mean, rms, skewness and kurtosis of zero-mean-ish values (about their mean).
pub(super) fn moments_of(values: impl Iterator<Item = f64> + Clone) -> (f64, f64, f64, f64) {
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

/// A row whose rms residual (after its line is removed) is at most this fraction of its
/// largest height is flat to rounding: removing a line from doubles leaves noise of a few
/// 1e-16 of the values (times the square root of the count), so 1e-10 is a margin of about a
/// million over that noise, and far below any measured roughness (a 1 nm rms on a 10 mm form
/// is 1e-7). Its skewness and kurtosis would be the noise's.
pub(super) const ROUNDING_FLAT: f64 = 1e-10;

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
        let largest = row.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let moments = moments_of(residual);
        (moments, moments.1 <= ROUNDING_FLAT * largest)
    });
    let mut sums = [0.0; 4];
    for ((ra, rq, rsk, rku), _) in &rows {
        for (s, v) in sums.iter_mut().zip([ra, rq, rsk, rku]) {
            *s += v;
        }
    }
    let n = ny as f64;
    let flat_rows = rows.iter().filter(|(_, flat)| *flat).count();
    let shape = (flat_rows == 0).then_some((sums[2] / n, sums[3] / n));
    ProfileParameters {
        ra: sums[0] / n,
        rq: sums[1] / n,
        rsk: shape.map(|s| s.0),
        rku: shape.map(|s| s.1),
        flat_rows,
    }
}

/// Histogram of the heights as a probability density (Freedman–Diaconis-like bins: about
/// `sqrt(N)`, at most 100).
pub(super) fn histogram(z: &Array2<f64>, sq: f64) -> Vec<(f64, f64)> {
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

//! Grids of points in the body and the one place where they are evaluated in parallel.
//!
//! Coordinates are in units of the contact half-width `a` and values in units of `p0`; the
//! caller converts to display units. Only the requested quantities are stored.

use ndarray::{Array3, ArrayView2, Axis as NdAxis};
use rayon::prelude::*;

use crate::solution::Solution;
use crate::stress::{Quantity, Stress};

/// Evenly spaced samples `min..=max` (`count >= 2`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Axis {
    pub min: f64,
    pub max: f64,
    pub count: usize,
}

impl Axis {
    pub fn new(min: f64, max: f64, count: usize) -> Self {
        Self { min, max, count }
    }

    /// The i-th sample; the last one is exactly `max`.
    #[inline]
    pub fn value(&self, i: usize) -> f64 {
        if i + 1 == self.count {
            self.max
        } else {
            self.min + (self.max - self.min) * (i as f64) / ((self.count - 1) as f64)
        }
    }

    pub fn step(&self) -> f64 {
        (self.max - self.min) / ((self.count - 1) as f64)
    }

    pub fn values(&self) -> impl Iterator<Item = f64> + '_ {
        (0..self.count).map(|i| self.value(i))
    }
}

/// A section of the body. For a line contact (plane strain) the xz plane is the whole story.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// Along the surface, in units of `a`.
    pub x: Axis,
    /// Depth below the surface (`>= 0`), in units of `a`.
    pub z: Axis,
}

impl Plane {
    pub fn points(&self) -> usize {
        self.x.count * self.z.count
    }
}

/// Largest grid (in bytes of stored values) that [`evaluate`] accepts.
pub const MAX_FIELD_BYTES: usize = 4 << 30;

/// Errors of grid evaluation.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum FieldError {
    #[error(
        "the grid of {nx} x {nz} points with {quantities} quantities needs {needed_mib} MiB, more \
         than the {limit_mib} MiB allowed\nhint: lower figure.resolution or draw fewer panels"
    )]
    TooLarge {
        nx: usize,
        nz: usize,
        quantities: usize,
        needed_mib: usize,
        limit_mib: usize,
    },
}

/// Values of several quantities on a plane: `values[[iz, k, ix]]` is quantity `k` at
/// `(x[ix], z[iz])`.
#[derive(Clone, Debug)]
pub struct Field {
    pub plane: Plane,
    pub quantities: Vec<Quantity>,
    pub values: Array3<f64>,
}

impl Field {
    /// The `[nz, nx]` map of one of the stored quantities.
    pub fn map(&self, quantity: Quantity) -> Option<ArrayView2<'_, f64>> {
        let k = self.quantities.iter().position(|&q| q == quantity)?;
        Some(self.values.index_axis(NdAxis(1), k))
    }
}

/// Checks the memory a field would take before allocating it.
pub fn check_size(plane: &Plane, quantities: usize) -> Result<(), FieldError> {
    let bytes = plane
        .points()
        .saturating_mul(quantities.max(1))
        .saturating_mul(std::mem::size_of::<f64>());
    if bytes > MAX_FIELD_BYTES {
        return Err(FieldError::TooLarge {
            nx: plane.x.count,
            nz: plane.z.count,
            quantities,
            needed_mib: bytes >> 20,
            limit_mib: MAX_FIELD_BYTES >> 20,
        });
    }
    Ok(())
}

/// Evaluates `quantities` of `solution` on `plane`, rows in parallel (rayon).
///
/// `on_row` is called once per finished row (from worker threads), for progress reporting.
pub fn evaluate(
    solution: &Solution,
    plane: &Plane,
    quantities: &[Quantity],
    on_row: &(dyn Fn() + Sync),
) -> Result<Field, FieldError> {
    check_size(plane, quantities.len())?;
    let mut values = Array3::zeros((plane.z.count, quantities.len(), plane.x.count));
    values
        .axis_iter_mut(NdAxis(0))
        .into_par_iter()
        .enumerate()
        .for_each(|(iz, mut row)| {
            fill_row(solution, plane, quantities, iz, &mut row);
            on_row();
        });
    Ok(Field {
        plane: *plane,
        quantities: quantities.to_vec(),
        values,
    })
}

/// The same as [`evaluate`] on the calling thread only (for benchmarks and comparisons).
pub fn evaluate_sequential(
    solution: &Solution,
    plane: &Plane,
    quantities: &[Quantity],
) -> Result<Field, FieldError> {
    check_size(plane, quantities.len())?;
    let mut values = Array3::zeros((plane.z.count, quantities.len(), plane.x.count));
    for (iz, mut row) in values.axis_iter_mut(NdAxis(0)).enumerate() {
        fill_row(solution, plane, quantities, iz, &mut row);
    }
    Ok(Field {
        plane: *plane,
        quantities: quantities.to_vec(),
        values,
    })
}

fn fill_row(
    solution: &Solution,
    plane: &Plane,
    quantities: &[Quantity],
    iz: usize,
    row: &mut ndarray::ArrayViewMut2<'_, f64>,
) {
    let z = plane.z.value(iz);
    let xs: Vec<f64> = plane.x.values().collect();
    let mut stresses = vec![Stress::default(); xs.len()];
    solution.stress_row_over_p0(&xs, 0.0, z, &mut stresses);
    for (k, &quantity) in quantities.iter().enumerate() {
        let mut out = row.index_axis_mut(NdAxis(0), k);
        match out.as_slice_mut() {
            Some(out) => fill_quantity(quantity, &stresses, out),
            None => out
                .iter_mut()
                .zip(&stresses)
                .for_each(|(o, s)| *o = quantity.of(s)),
        }
    }
}

/// `out[i] = quantity(stresses[i])`, with the match outside the loops.
fn fill_quantity(quantity: Quantity, stresses: &[Stress], out: &mut [f64]) {
    fn each(stresses: &[Stress], out: &mut [f64], f: impl Fn(&Stress) -> f64) {
        out.iter_mut().zip(stresses).for_each(|(o, s)| *o = f(s));
    }
    match quantity {
        Quantity::VonMises => each(stresses, out, Stress::von_mises),
        Quantity::Tau1 => each(stresses, out, Stress::principal_shear_xz),
        Quantity::Sxx => each(stresses, out, |s| s.xx),
        Quantity::Szz => each(stresses, out, |s| s.zz),
        Quantity::Sxz | Quantity::OrthogonalShear => each(stresses, out, |s| s.xz),
        other => each(stresses, out, |s| other.of(s)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parallel_and_sequential_agree_bitwise() {
        let solution = Solution::LineHertz {
            friction: 0.3,
            poisson: 0.3,
        };
        let plane = Plane {
            x: Axis::new(-2.0, 2.0, 41),
            z: Axis::new(0.0, 2.0, 21),
        };
        let quantities = [Quantity::VonMises, Quantity::Sxx];
        let parallel = evaluate(&solution, &plane, &quantities, &|| {}).expect("small grid");
        let sequential = evaluate_sequential(&solution, &plane, &quantities).expect("small grid");
        assert_eq!(parallel.values, sequential.values);
        let map = parallel.map(Quantity::Sxx).expect("stored");
        // Row 0 is the surface; x = -1 is sample 10: trailing edge tension 2 mu p0.
        assert!((map[[0, 10]] - 0.6).abs() < 1e-12);
    }

    #[test]
    fn oversized_grid_is_refused_before_allocation() {
        let plane = Plane {
            x: Axis::new(-1.0, 1.0, 100_000),
            z: Axis::new(0.0, 1.0, 100_000),
        };
        let err = check_size(&plane, 2).expect_err("80 GB grid");
        assert!(err.to_string().contains("MiB"), "{err}");
    }

    #[test]
    fn axis_ends_are_exact() {
        let axis = Axis::new(-2.0, 3.0, 7);
        assert_eq!(axis.value(0), -2.0);
        assert_eq!(axis.value(6), 3.0);
    }
}

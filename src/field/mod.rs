//! Grids of points in the body and the one place where they are evaluated in parallel.
//!
//! Coordinates are in units of the contact half-width `a` and values in units of `p0`; the
//! caller converts to display units. Only the requested quantities are stored.

use ndarray::{Array3, Array4, ArrayView2, ArrayView3, Axis as NdAxis};
use rayon::prelude::*;

use crate::solution::point_numerical::PointTractions;
use crate::solution::Solution;
use crate::stress::{Quantity, Stress};

mod dcfft_layers;
pub use dcfft_layers::{for_each_dcfft_layer, kept_layers_bytes};

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

/// Which plane of the body a section lies in (coordinates in units of `a`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Section {
    /// The xz plane at a given y: horizontal axis x, vertical axis z (depth).
    Xz { y: f64 },
    /// The yz plane at a given x: horizontal axis y, vertical axis z (depth).
    Yz { x: f64 },
    /// A plane parallel to the surface at depth z: horizontal axis x, vertical axis y.
    Xy { z: f64 },
}

/// A section of the body: a plane and the two axes that span it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    pub section: Section,
    /// Horizontal axis: x for xz and xy sections, y for yz sections (units of `a`).
    pub u: Axis,
    /// Vertical axis: z (depth, `>= 0`) for xz and yz sections, y for xy sections.
    pub v: Axis,
}

impl Plane {
    /// The xz section at y = 0, the whole story for a line contact (plane strain).
    pub fn xz(x: Axis, z: Axis) -> Self {
        Self {
            section: Section::Xz { y: 0.0 },
            u: x,
            v: z,
        }
    }

    pub fn points(&self) -> usize {
        self.u.count * self.v.count
    }

    /// The point `(x, y, z)` at horizontal sample `iu` and vertical sample `iv`.
    #[inline]
    pub fn point(&self, iu: usize, iv: usize) -> (f64, f64, f64) {
        let (u, v) = (self.u.value(iu), self.v.value(iv));
        match self.section {
            Section::Xz { y } => (u, y, v),
            Section::Yz { x } => (x, u, v),
            Section::Xy { z } => (u, v, z),
        }
    }
}

/// A box of points, `x` by `y` by `z` (units of `a`, `z >= 0`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Volume {
    pub x: Axis,
    pub y: Axis,
    pub z: Axis,
}

impl Volume {
    pub fn points(&self) -> usize {
        self.x.count * self.y.count * self.z.count
    }
}

/// Storage precision of evaluated values: `f64`, or `f32` to halve the memory of large grids.
pub trait Precision: Copy + Default + Send + Sync + 'static {
    fn from_f64(value: f64) -> Self;
}

impl Precision for f64 {
    #[inline]
    fn from_f64(value: f64) -> Self {
        value
    }
}

impl Precision for f32 {
    #[inline]
    fn from_f64(value: f64) -> Self {
        value as f32
    }
}

pub use crate::io::input::MAX_FIELD_BYTES;

/// The largest grid this machine should hold: [`MAX_FIELD_BYTES`], or three quarters of the
/// memory available now (`MemAvailable` of `/proc/meminfo` on Linux) when that is smaller.
pub fn memory_limit_bytes() -> usize {
    let available = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|text| {
            let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
            let kib: usize = line.split_whitespace().nth(1)?.parse().ok()?;
            Some(kib.saturating_mul(1024))
        });
    match available {
        Some(bytes) => MAX_FIELD_BYTES.min(bytes / 4 * 3),
        None => MAX_FIELD_BYTES,
    }
}

/// Errors of grid evaluation.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum FieldError {
    #[error(
        "the grid of {points} points with {quantities} quantities needs {needed_mib} MiB, more \
         than the {limit_mib} MiB allowed (at most 4096 MiB, and 3/4 of the memory available)\n\
         hint: lower the resolution, store f32, or keep fewer quantities"
    )]
    TooLarge {
        points: usize,
        quantities: usize,
        needed_mib: usize,
        limit_mib: usize,
    },
    #[error("numerical integration failed: {0}")]
    Numerical(String),
}

/// Values of several quantities on a plane: `values[[iv, k, iu]]` is quantity `k` at the
/// horizontal sample `iu` and vertical sample `iv` (for an xz section: `(x[iu], z[iv])`).
#[derive(Clone, Debug)]
pub struct Field<T = f64> {
    pub plane: Plane,
    pub quantities: Vec<Quantity>,
    pub values: Array3<T>,
}

impl<T> Field<T> {
    /// The `[nv, nu]` map of one of the stored quantities.
    pub fn map(&self, quantity: Quantity) -> Option<ArrayView2<'_, T>> {
        let k = self.quantities.iter().position(|&q| q == quantity)?;
        Some(self.values.index_axis(NdAxis(1), k))
    }
}

/// Values of several quantities in a volume: `values[[iz, k, iy, ix]]` is quantity `k` at
/// `(x[ix], y[iy], z[iz])`.
#[derive(Clone, Debug)]
pub struct VolumeField<T = f64> {
    pub volume: Volume,
    pub quantities: Vec<Quantity>,
    pub values: Array4<T>,
}

impl<T> VolumeField<T> {
    /// The `[nz, ny, nx]` block of one of the stored quantities.
    pub fn block(&self, quantity: Quantity) -> Option<ArrayView3<'_, T>> {
        let k = self.quantities.iter().position(|&q| q == quantity)?;
        Some(self.values.index_axis(NdAxis(1), k))
    }
}

/// Checks the memory `points` values of `quantities` quantities of `bytes_per_value` bytes
/// would take against [`memory_limit_bytes`], before allocating them.
pub fn check_size(
    points: usize,
    quantities: usize,
    bytes_per_value: usize,
) -> Result<(), FieldError> {
    check_size_within(points, quantities, bytes_per_value, memory_limit_bytes())
}

/// [`check_size`] against a given limit in bytes.
pub fn check_size_within(
    points: usize,
    quantities: usize,
    bytes_per_value: usize,
    limit_bytes: usize,
) -> Result<(), FieldError> {
    let bytes = points
        .saturating_mul(quantities.max(1))
        .saturating_mul(bytes_per_value);
    if bytes > limit_bytes {
        return Err(FieldError::TooLarge {
            points,
            quantities,
            needed_mib: bytes >> 20,
            limit_mib: limit_bytes >> 20,
        });
    }
    Ok(())
}

/// Evaluates `quantities` of `solution` on `plane`, rows in parallel (rayon), stored as `f64`.
///
/// `on_row` is called once per finished row (from worker threads), for progress reporting.
pub fn evaluate(
    solution: &Solution,
    plane: &Plane,
    quantities: &[Quantity],
    on_row: &(dyn Fn() + Sync),
) -> Result<Field, FieldError> {
    evaluate_as::<f64>(solution, plane, quantities, on_row)
}

/// As [`evaluate`], storing values in the chosen precision (`f32` halves the memory).
pub fn evaluate_as<T: Precision>(
    solution: &Solution,
    plane: &Plane,
    quantities: &[Quantity],
    on_row: &(dyn Fn() + Sync),
) -> Result<Field<T>, FieldError> {
    check_size(plane.points(), quantities.len(), std::mem::size_of::<T>())?;
    if let Solution::PointNumerical { tractions, .. } = solution {
        if let Some(layout) = GridLayout::of(tractions, plane) {
            let values = evaluate_layers(tractions, plane, &layout, quantities, on_row)?;
            return Ok(Field {
                plane: *plane,
                quantities: quantities.to_vec(),
                values,
            });
        }
    }
    let mut values = Array3::default((plane.v.count, quantities.len(), plane.u.count));
    values
        .axis_iter_mut(NdAxis(0))
        .into_par_iter()
        .enumerate()
        .for_each_init(RowBuffers::default, |buffers, (iv, mut row)| {
            fill_plane_row(solution, plane, quantities, iv, &mut row, buffers);
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
    check_size(plane.points(), quantities.len(), std::mem::size_of::<f64>())?;
    let mut values = Array3::zeros((plane.v.count, quantities.len(), plane.u.count));
    let mut buffers = RowBuffers::default();
    for (iv, mut row) in values.axis_iter_mut(NdAxis(0)).enumerate() {
        fill_plane_row(solution, plane, quantities, iv, &mut row, &mut buffers);
    }
    Ok(Field {
        plane: *plane,
        quantities: quantities.to_vec(),
        values,
    })
}

/// Evaluates `quantities` in a volume, in parallel over (z, y) rows, in the chosen precision.
/// `on_layer` is called once per finished depth layer.
pub fn evaluate_volume<T: Precision>(
    solution: &Solution,
    volume: &Volume,
    quantities: &[Quantity],
    on_layer: &(dyn Fn() + Sync),
) -> Result<VolumeField<T>, FieldError> {
    check_size(volume.points(), quantities.len(), std::mem::size_of::<T>())?;
    let shape = (
        volume.z.count,
        quantities.len(),
        volume.y.count,
        volume.x.count,
    );
    let mut values = Array4::default(shape);
    values
        .axis_iter_mut(NdAxis(0))
        .into_par_iter()
        .enumerate()
        .for_each(|(iz, mut layer)| {
            let plane = Plane {
                section: Section::Xy {
                    z: volume.z.value(iz),
                },
                u: volume.x,
                v: volume.y,
            };
            // Layers are independent; rows within a layer go to other threads too.
            layer
                .axis_iter_mut(NdAxis(1))
                .into_par_iter()
                .enumerate()
                .for_each_init(RowBuffers::default, |buffers, (iy, mut row)| {
                    fill_plane_row(solution, &plane, quantities, iy, &mut row, buffers);
                });
            on_layer();
        });
    Ok(VolumeField {
        volume: *volume,
        quantities: quantities.to_vec(),
        values,
    })
}

/// Where a plane's samples lie among the cell centres of a numerical solution's traction grid:
/// the index of the first sample's column (x) and row (y). A plane whose samples are all cell
/// centres (any depths) is evaluated by DC-FFT, layer by layer.
struct GridLayout {
    first_column: usize,
    first_row: usize,
}

impl GridLayout {
    fn of(tractions: &PointTractions, plane: &Plane) -> Option<Self> {
        let [ny, nx] = tractions.grid().shape();
        let cell = tractions.grid().cell();
        // The samples of `axis` are the centres first..first + count along grid axis `k`.
        let along = |axis: &Axis, k: usize, n: usize| -> Option<usize> {
            let first = tractions.nearest_centre(axis.min, k);
            let last = first + axis.count - 1;
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * cell[k];
            (last < n
                && close(axis.min, tractions.centre(first, k))
                && close(axis.max, tractions.centre(last, k)))
            .then_some(first)
        };
        let single = |value: f64, k: usize, n: usize| along(&Axis::new(value, value, 1), k, n);
        let (first_column, first_row) = match plane.section {
            Section::Xz { y } => (along(&plane.u, 0, nx)?, single(y, 1, ny)?),
            Section::Yz { x } => (single(x, 0, nx)?, along(&plane.u, 1, ny)?),
            Section::Xy { .. } => (along(&plane.u, 0, nx)?, along(&plane.v, 1, ny)?),
        };
        Some(Self {
            first_column,
            first_row,
        })
    }
}

/// Evaluates a plane lying on the traction grid by DC-FFT: one layer per depth row (xz, yz)
/// or one layer (xy), in parallel over the layers, each layer's working set held by one worker.
fn evaluate_layers<T: Precision>(
    tractions: &PointTractions,
    plane: &Plane,
    layout: &GridLayout,
    quantities: &[Quantity],
    on_row: &(dyn Fn() + Sync),
) -> Result<Array3<T>, FieldError> {
    let (nu, nv) = (plane.u.count, plane.v.count);
    let values = std::sync::Mutex::new(Array3::default((nv, quantities.len(), nu)));
    let depths: Vec<f64> = match plane.section {
        Section::Xz { .. } | Section::Yz { .. } => plane.v.values().collect(),
        Section::Xy { z } => vec![z],
    };
    let stress = crate::solution::dcfft::layer_stress;
    let (c0, r0) = (layout.first_column, layout.first_row);
    // Copies what a finished layer (`[component, y, x]`) contributes to the plane.
    let take = |index: usize, layer: ndarray::ArrayView3<f64>| {
        // The rows of the plane this layer fills, and the stresses along u of each.
        let rows: Vec<usize> = match plane.section {
            Section::Xz { .. } | Section::Yz { .. } => vec![index],
            Section::Xy { .. } => (0..nv).collect(),
        };
        let stresses_of = |iv: usize| -> Vec<Stress> {
            match plane.section {
                Section::Xz { .. } => (0..nu).map(|iu| stress(&layer, r0, c0 + iu)).collect(),
                Section::Yz { .. } => (0..nu).map(|iu| stress(&layer, r0 + iu, c0)).collect(),
                Section::Xy { .. } => (0..nu).map(|iu| stress(&layer, r0 + iv, c0 + iu)).collect(),
            }
        };
        // The quantities of each row (in parallel: an xy section has all its rows here).
        let computed: Vec<(usize, Vec<Vec<T>>)> = rows
            .into_par_iter()
            .map_init(
                || vec![0.0; nu],
                |buffer, iv| {
                    let stresses = stresses_of(iv);
                    let mut computed = Vec::with_capacity(quantities.len());
                    for &quantity in quantities {
                        fill_quantity(quantity, &stresses, buffer);
                        computed.push(buffer.iter().map(|&v| T::from_f64(v)).collect());
                    }
                    (iv, computed)
                },
            )
            .collect();
        for (iv, computed) in computed {
            // A poisoned lock only means another worker panicked; the panic propagates.
            let mut values = values.lock().unwrap_or_else(|e| e.into_inner());
            for (k, row) in computed.into_iter().enumerate() {
                for (iu, v) in row.into_iter().enumerate() {
                    values[[iv, k, iu]] = v;
                }
            }
            drop(values);
            on_row();
        }
    };
    for_each_dcfft_layer(tractions.dcfft(), &depths, |index, _, layer| {
        take(index, layer)
    })
    .map_err(|e| FieldError::Numerical(e.to_string()))?;
    Ok(values.into_inner().unwrap_or_else(|e| e.into_inner()))
}

/// Scratch space reused from row to row by one worker.
#[derive(Default)]
struct RowBuffers {
    xs: Vec<f64>,
    stresses: Vec<Stress>,
    values: Vec<f64>,
}

/// Fills row `iv` (`[quantity, iu]`) of a plane.
fn fill_plane_row<T: Precision>(
    solution: &Solution,
    plane: &Plane,
    quantities: &[Quantity],
    iv: usize,
    row: &mut ndarray::ArrayViewMut2<'_, T>,
    buffers: &mut RowBuffers,
) {
    let n = plane.u.count;
    buffers.stresses.resize(n, Stress::default());
    buffers.values.resize(n, 0.0);
    match plane.section {
        // Rows along x: the solution's vectorisable row kernel.
        Section::Xz { .. } | Section::Xy { .. } => {
            let (_, y, z) = plane.point(0, iv);
            buffers.xs.clear();
            buffers.xs.extend(plane.u.values());
            solution.stress_row_over_p0(&buffers.xs, y, z, &mut buffers.stresses);
        }
        Section::Yz { .. } => {
            for (iu, stress) in buffers.stresses.iter_mut().enumerate() {
                let (x, y, z) = plane.point(iu, iv);
                *stress = solution.stress_over_p0(x, y, z);
            }
        }
    }
    for (k, &quantity) in quantities.iter().enumerate() {
        fill_quantity(quantity, &buffers.stresses, &mut buffers.values);
        row.index_axis_mut(NdAxis(0), k)
            .iter_mut()
            .zip(&buffers.values)
            .for_each(|(out, &v)| *out = T::from_f64(v));
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
        let plane = Plane::xz(Axis::new(-2.0, 2.0, 41), Axis::new(0.0, 2.0, 21));
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
        let plane = Plane::xz(Axis::new(-1.0, 1.0, 100_000), Axis::new(0.0, 1.0, 100_000));
        let err = check_size(plane.points(), 2, 8).expect_err("160 GB grid");
        assert!(err.to_string().contains("MiB"), "{err}");
    }

    #[test]
    fn sections_place_their_points_in_the_right_plane() {
        // The line contact does not depend on y: a yz section at x is constant along y and
        // equals the xz section's column at x; an xy section at z equals its row at z.
        let solution = Solution::LineHertz {
            friction: 0.25,
            poisson: 0.3,
        };
        let q = [Quantity::Sxx, Quantity::VonMises];
        let xz = Plane::xz(Axis::new(-2.0, 2.0, 9), Axis::new(0.0, 2.0, 5));
        let xz = evaluate(&solution, &xz, &q, &|| {}).expect("small");
        let yz = Plane {
            section: Section::Yz { x: 0.5 },
            u: Axis::new(-1.0, 1.0, 7),
            v: Axis::new(0.0, 2.0, 5),
        };
        let yz = evaluate(&solution, &yz, &q, &|| {}).expect("small");
        let xy = Plane {
            section: Section::Xy { z: 1.5 },
            u: Axis::new(-2.0, 2.0, 9),
            v: Axis::new(-1.0, 1.0, 3),
        };
        let xy = evaluate(&solution, &xy, &q, &|| {}).expect("small");
        for k in 0..2 {
            for iz in 0..5 {
                for iy in 0..7 {
                    assert_eq!(yz.values[[iz, k, iy]], xz.values[[iz, k, 5]]); // x = 0.5
                }
            }
            for iy in 0..3 {
                for ix in 0..9 {
                    assert_eq!(xy.values[[iy, k, ix]], xz.values[[3, k, ix]]); // z = 1.5
                }
            }
        }
    }

    #[test]
    fn sphere_sections_cross_where_they_should() {
        // A point contact depends on y: the xz section at y = 0.4 and the yz section at
        // x = -0.5 share the line (-0.5, 0.4, z); the xy section at z = 0.5 shares a row with
        // the xz section; and the volume's layers, kept in f32, are the f64 sections rounded.
        let solution = Solution::SphereHertz {
            friction: 0.3,
            poisson: 0.3,
        };
        let q = [Quantity::Sxz, Quantity::VonMises, Quantity::Syz];
        let x = Axis::new(-2.0, 2.0, 9); // x = -0.5 is sample 3
        let y = Axis::new(-1.2, 1.2, 7); // y = 0.4 is sample 4
        let z = Axis::new(0.0, 2.0, 5); // z = 0.5 is sample 1
        let xz = Plane {
            section: Section::Xz { y: 0.4 },
            u: x,
            v: z,
        };
        let yz = Plane {
            section: Section::Yz { x: -0.5 },
            u: y,
            v: z,
        };
        let xy = Plane {
            section: Section::Xy { z: 0.5 },
            u: x,
            v: y,
        };
        let [xz, yz, xy] =
            [xz, yz, xy].map(|p| evaluate(&solution, &p, &q, &|| {}).expect("small"));
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-14;
        let narrow =
            evaluate_volume::<f32>(&solution, &Volume { x, y, z }, &q, &|| {}).expect("small");
        for k in 0..3 {
            for iz in 0..5 {
                assert!(
                    close(xz.values[[iz, k, 3]], yz.values[[iz, k, 4]]),
                    "k {k} iz {iz}"
                );
            }
            for ix in 0..9 {
                assert!(
                    close(xz.values[[1, k, ix]], xy.values[[4, k, ix]]),
                    "k {k} ix {ix}"
                );
                for iy in 0..7 {
                    assert_eq!(narrow.values[[1, k, iy, ix]], xy.values[[iy, k, ix]] as f32);
                }
            }
        }
        // Symmetry in y of the sliding sphere: syz is odd, von Mises even.
        for ix in 0..9 {
            assert!(close(xy.values[[0, 1, ix]], xy.values[[6, 1, ix]]));
            assert!(close(xy.values[[0, 2, ix]], -xy.values[[6, 2, ix]]));
        }
    }

    #[test]
    fn numerical_planes_on_the_grid_use_dc_fft_and_agree_with_direct_summation() {
        // 15 cells over [-1.5, 1.5]²: centres at multiples of 0.2; sections through centres
        // go through DC-FFT layers, and must equal the direct sums at the same points.
        let solution = Solution::sphere_numerical(0.3, 0.3, 15, 1.5).expect("grid");
        let Solution::PointNumerical { tractions, .. } = &solution else {
            unreachable!("a numerical solution")
        };
        let q = [Quantity::Sxx, Quantity::Syz, Quantity::VonMises];
        let planes = [
            Plane {
                section: Section::Xz { y: 0.2 },
                u: Axis::new(-1.0, 1.0, 11),
                v: Axis::new(0.0, 1.0, 6),
            },
            Plane {
                section: Section::Yz { x: -0.4 },
                u: Axis::new(-1.4, 1.4, 15),
                v: Axis::new(0.05, 0.85, 5),
            },
            Plane {
                section: Section::Xy { z: 0.3 },
                u: Axis::new(-0.6, 1.0, 9),
                v: Axis::new(-1.0, 0.2, 7),
            },
        ];
        for plane in planes {
            assert!(
                GridLayout::of(tractions, &plane).is_some(),
                "{plane:?} is on the grid"
            );
            let field = evaluate(&solution, &plane, &q, &|| {}).expect("small");
            for iv in 0..plane.v.count {
                for iu in 0..plane.u.count {
                    let (x, y, z) = plane.point(iu, iv);
                    let direct = solution.stress_over_p0(x, y, z);
                    for (k, quantity) in q.iter().enumerate() {
                        let v = field.values[[iv, k, iu]];
                        assert!(
                            (v - quantity.of(&direct)).abs() < 1e-10,
                            "{plane:?} ({x}, {y}, {z}) {quantity:?}: {v} vs {}",
                            quantity.of(&direct)
                        );
                    }
                }
            }
        }
        // Off the grid: evaluated point by point (still correct, only slower).
        let off = Plane {
            section: Section::Xz { y: 0.25 },
            u: Axis::new(-1.0, 1.0, 5),
            v: Axis::new(0.1, 0.5, 2),
        };
        assert!(GridLayout::of(tractions, &off).is_none());
    }

    #[test]
    fn volume_layers_match_sections_and_f32_rounds_f64() {
        let solution = Solution::LineHertz {
            friction: 0.1,
            poisson: 0.28,
        };
        let volume = Volume {
            x: Axis::new(-2.0, 2.0, 11),
            y: Axis::new(-1.0, 1.0, 4),
            z: Axis::new(0.0, 1.0, 6),
        };
        let q = [Quantity::VonMises, Quantity::Szz];
        let wide = evaluate_volume::<f64>(&solution, &volume, &q, &|| {}).expect("small");
        let narrow = evaluate_volume::<f32>(&solution, &volume, &q, &|| {}).expect("small");
        for iz in 0..6 {
            let layer = Plane {
                section: Section::Xy {
                    z: volume.z.value(iz),
                },
                u: volume.x,
                v: volume.y,
            };
            let layer = evaluate(&solution, &layer, &q, &|| {}).expect("small");
            for k in 0..2 {
                for iy in 0..4 {
                    for ix in 0..11 {
                        let v = wide.values[[iz, k, iy, ix]];
                        assert_eq!(v, layer.values[[iy, k, ix]]);
                        assert_eq!(narrow.values[[iz, k, iy, ix]], v as f32);
                    }
                }
            }
        }
        assert_eq!(wide.block(Quantity::Szz).expect("stored").dim(), (6, 4, 11));
        // Memory: f32 halves the estimate, so a grid twice the limit in f64 is still refused
        // in f64 but its half fits in f32.
        let points = MAX_FIELD_BYTES / 8 + 1;
        assert!(check_size_within(points, 1, 8, MAX_FIELD_BYTES).is_err());
        assert!(check_size_within(points, 1, 4, MAX_FIELD_BYTES).is_ok());
        // The machine's limit never exceeds the fixed one.
        assert!(memory_limit_bytes() <= MAX_FIELD_BYTES);
    }

    #[test]
    fn axis_ends_are_exact() {
        let axis = Axis::new(-2.0, 3.0, 7);
        assert_eq!(axis.value(0), -2.0);
        assert_eq!(axis.value(6), 3.0);
    }
}

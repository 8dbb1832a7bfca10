//! The traction grid: cells, their loads, and the layout of a layer's stresses.

use ndarray::{Array2, Array3};

use super::*;
use crate::solution::patch::{uniform_patch, PatchStresses, Rectangle};
use crate::stress::Stress;

/// The order of the stress components in a layer: `xx, yy, zz, yz, xz, xy`.
pub const COMPONENTS: [&str; 6] = ["xx", "yy", "zz", "yz", "xz", "xy"];

/// The stress at cell `[row, column]` of a layer (`[component, y, x]`, components in the order
/// of [`COMPONENTS`]).
#[inline]
pub fn layer_stress(layer: &ndarray::ArrayView3<f64>, row: usize, column: usize) -> Stress {
    Stress {
        xx: layer[[0, row, column]],
        yy: layer[[1, row, column]],
        zz: layer[[2, row, column]],
        yz: layer[[3, row, column]],
        xz: layer[[4, row, column]],
        xy: layer[[5, row, column]],
    }
}

/// Invalid traction grids.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TractionGridError {
    #[error("a traction grid needs at least one of pressure, shear_x, shear_y")]
    NoTraction,
    #[error("a traction grid needs at least one cell, got shape {0:?}")]
    Empty([usize; 2]),
    #[error(
        "{name} has shape {got:?} but {first} has {expected:?}; give every traction as [ny, nx]"
    )]
    ShapeMismatch {
        name: &'static str,
        got: [usize; 2],
        first: &'static str,
        expected: [usize; 2],
    },
    #[error("the cell size must be positive and finite, got dx = {dx}, dy = {dy}")]
    CellSize { dx: f64, dy: f64 },
    #[error("the grid origin must be finite, got ({0}, {1})")]
    Origin(f64, f64),
    #[error("{name}[{row}, {column}] is not finite ({value})")]
    NotFinite {
        name: &'static str,
        row: usize,
        column: usize,
        value: f64,
    },
}

/// Failures of the FFT library (lengths are fixed at planning, so these indicate a bug).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("DC-FFT: the real FFT failed: {0}")]
pub struct DcFftError(String);

impl From<realfft::FftError> for DcFftError {
    fn from(error: realfft::FftError) -> Self {
        Self(error.to_string())
    }
}

impl From<crate::operator::transform::TransformError> for DcFftError {
    fn from(error: crate::operator::transform::TransformError) -> Self {
        Self(error.to_string())
    }
}

// The three kinds of surface traction (the discriminant indexes stored coefficients).
pub(crate) use crate::solution::patch::Load;

impl Load {
    pub(super) fn stress(self, s: &PatchStresses) -> &Stress {
        match self {
            Load::Pressure => &s.pressure,
            Load::ShearX => &s.shear_x,
            Load::ShearY => &s.shear_y,
        }
    }

    /// Parity `(in x, in y)` of each component's influence coefficient about the loaded cell:
    /// the pressure is symmetric in x and y, so a component is odd in x when it has an odd
    /// number of x indices (`xz`, `xy`); `qx` reverses under x -> -x, `qy` under y -> -y.
    pub(super) fn parity(self, component: usize) -> (f64, f64) {
        const PRESSURE: [(f64, f64); 6] = [
            (1.0, 1.0),
            (1.0, 1.0),
            (1.0, 1.0),
            (1.0, -1.0),
            (-1.0, 1.0),
            (-1.0, -1.0),
        ];
        let (x, y) = PRESSURE[component];
        match self {
            Load::Pressure => (x, y),
            Load::ShearX => (-x, y),
            Load::ShearY => (x, -y),
        }
    }
}

pub(super) fn component(s: &Stress, index: usize) -> f64 {
    [s.xx, s.yy, s.zz, s.yz, s.xz, s.xy][index]
}

/// Surface tractions, uniform on each cell of a regular grid.
///
/// Cell `[j, i]` (row `j` along y, column `i` along x) covers
/// `x0 + i dx <= x <= x0 + (i + 1) dx`, `y0 + j dy <= y <= y0 + (j + 1) dy`. Each traction is
/// optional (absent means zero): the pressure `p` pushes on the body (+z), `shear_x` and
/// `shear_y` act on the body in +x and +y.
#[derive(Clone, Debug, PartialEq)]
pub struct TractionGrid {
    pub(super) origin: [f64; 2],
    pub(super) cell: [f64; 2],
    pub(super) shape: [usize; 2],
    pub(super) pressure: Option<Array2<f64>>,
    pub(super) shear_x: Option<Array2<f64>>,
    pub(super) shear_y: Option<Array2<f64>>,
}

impl TractionGrid {
    /// Checks the arrays (same shape `[ny, nx]`, at least one cell, finite values) and the
    /// geometry (`origin = [x0, y0]` finite, `cell = [dx, dy]` positive and finite).
    pub fn new(
        origin: [f64; 2],
        cell: [f64; 2],
        pressure: Option<Array2<f64>>,
        shear_x: Option<Array2<f64>>,
        shear_y: Option<Array2<f64>>,
    ) -> Result<Self, TractionGridError> {
        let [dx, dy] = cell;
        if !(dx > 0.0 && dy > 0.0 && dx.is_finite() && dy.is_finite()) {
            return Err(TractionGridError::CellSize { dx, dy });
        }
        if !(origin[0].is_finite() && origin[1].is_finite()) {
            return Err(TractionGridError::Origin(origin[0], origin[1]));
        }
        let named = [
            ("pressure", &pressure),
            ("shear_x", &shear_x),
            ("shear_y", &shear_y),
        ];
        let mut first: Option<(&'static str, [usize; 2])> = None;
        for (name, array) in named {
            let Some(array) = array else { continue };
            let got = [array.nrows(), array.ncols()];
            match first {
                None => first = Some((name, got)),
                Some((first_name, expected)) if expected != got => {
                    return Err(TractionGridError::ShapeMismatch {
                        name,
                        got,
                        first: first_name,
                        expected,
                    })
                }
                Some(_) => {}
            }
            if let Some(((row, column), &value)) =
                array.indexed_iter().find(|(_, v)| !v.is_finite())
            {
                return Err(TractionGridError::NotFinite {
                    name,
                    row,
                    column,
                    value,
                });
            }
        }
        let Some((_, shape)) = first else {
            return Err(TractionGridError::NoTraction);
        };
        if shape[0] == 0 || shape[1] == 0 {
            return Err(TractionGridError::Empty(shape));
        }
        Ok(Self {
            origin,
            cell,
            shape,
            pressure,
            shear_x,
            shear_y,
        })
    }

    /// `[ny, nx]`.
    pub fn shape(&self) -> [usize; 2] {
        self.shape
    }

    /// `[dx, dy]`.
    pub fn cell(&self) -> [f64; 2] {
        self.cell
    }

    /// `[x0, y0]`, the corner of cell `[0, 0]` with the smallest coordinates.
    pub fn origin(&self) -> [f64; 2] {
        self.origin
    }

    /// The centre `(x, y)` of cell `[row, column]`.
    pub fn cell_centre(&self, row: usize, column: usize) -> (f64, f64) {
        (
            self.origin[0] + (column as f64 + 0.5) * self.cell[0],
            self.origin[1] + (row as f64 + 0.5) * self.cell[1],
        )
    }

    /// The rectangle of cell `[row, column]`.
    pub fn cell_rectangle(&self, row: usize, column: usize) -> Rectangle {
        let [x0, y0] = self.origin;
        let [dx, dy] = self.cell;
        Rectangle {
            x1: x0 + column as f64 * dx,
            x2: x0 + (column + 1) as f64 * dx,
            y1: y0 + row as f64 * dy,
            y2: y0 + (row + 1) as f64 * dy,
        }
    }

    /// The tractions `(p, qx, qy)` of cell `[row, column]`.
    pub fn traction(&self, row: usize, column: usize) -> (f64, f64, f64) {
        let at = |array: &Option<Array2<f64>>| array.as_ref().map_or(0.0, |a| a[[row, column]]);
        (at(&self.pressure), at(&self.shear_x), at(&self.shear_y))
    }

    /// The present tractions, each with its kind.
    pub(super) fn loads(&self) -> impl Iterator<Item = (Load, &Array2<f64>)> {
        [
            (Load::Pressure, &self.pressure),
            (Load::ShearX, &self.shear_x),
            (Load::ShearY, &self.shear_y),
        ]
        .into_iter()
        .filter_map(|(load, array)| array.as_ref().map(|a| (load, a)))
    }

    /// Stress at any point `(x, y, z)`, `z >= 0`, by direct summation over the cells of
    /// [`uniform_patch`] times each cell's tractions (cells without traction are skipped).
    ///
    /// Cost: one patch evaluation per loaded cell. Exact for the piecewise-constant tractions,
    /// up to rounding (see [`uniform_patch`] for the accuracy and for the surface `z = 0`).
    pub fn stress_at(&self, x: f64, y: f64, z: f64, nu: f64) -> Stress {
        let [ny, nx] = self.shape;
        let mut sum = Stress::default();
        for row in 0..ny {
            for column in 0..nx {
                let (p, qx, qy) = self.traction(row, column);
                if p == 0.0 && qx == 0.0 && qy == 0.0 {
                    continue;
                }
                let s = uniform_patch(x, y, z, self.cell_rectangle(row, column), nu);
                sum = sum + s.pressure.scaled(p) + s.shear_x.scaled(qx) + s.shear_y.scaled(qy);
            }
        }
        sum
    }

    /// Stresses at every cell centre at depth `z` by direct summation, `[component, y, x]`.
    ///
    /// `O((nx ny)²)`: for small grids and for checking [`DcFft`].
    pub fn direct_layer(&self, z: f64, nu: f64) -> Array3<f64> {
        self.direct_layer_with(z, |x, y| self.stress_at(x, y, z, nu))
    }

    pub(super) fn direct_layer_with(
        &self,
        _z: f64,
        stress: impl Fn(f64, f64) -> Stress,
    ) -> Array3<f64> {
        let [ny, nx] = self.shape;
        let mut out = Array3::zeros((6, ny, nx));
        for row in 0..ny {
            for column in 0..nx {
                let (x, y) = self.cell_centre(row, column);
                let s = stress(x, y);
                for c in 0..6 {
                    out[[c, row, column]] = component(&s, c);
                }
            }
        }
        out
    }

    /// The mean tractions `[p̄, q̄x, q̄y]` over the grid.
    pub fn mean_tractions(&self) -> [f64; 3] {
        let cells = (self.shape[0] * self.shape[1]) as f64;
        let mean = |array: &Option<Array2<f64>>| array.as_ref().map_or(0.0, |a| a.sum() / cells);
        [
            mean(&self.pressure),
            mean(&self.shear_x),
            mean(&self.shear_y),
        ]
    }

    /// Stress at `(x, y, z)` when the grid is one period of tractions repeating in x and y, by
    /// direct summation over the cells and their images in the window of [`PERIODIC_IMAGES`]
    /// periods (module doc). Cost: `(2M + 1)²` patch evaluations per cell.
    pub fn periodic_stress_at(&self, x: f64, y: f64, z: f64, nu: f64) -> Stress {
        self.periodic_stress_with_images(x, y, z, nu, PERIODIC_IMAGES)
    }

    /// [`TractionGrid::periodic_stress_at`] with a window of `images` periods on each side.
    pub fn periodic_stress_with_images(
        &self,
        x: f64,
        y: f64,
        z: f64,
        nu: f64,
        images: usize,
    ) -> Stress {
        let [ny, nx] = self.shape;
        let [dx, dy] = self.cell;
        let (period_x, period_y) = (nx as f64 * dx, ny as f64 * dy);
        let mean = self.mean_tractions();
        let cell = Rectangle {
            x1: -0.5 * dx,
            x2: 0.5 * dx,
            y1: -0.5 * dy,
            y2: 0.5 * dy,
        };
        let mut sum = Stress::default();
        for row in 0..ny {
            for column in 0..nx {
                let (p, qx, qy) = self.traction(row, column);
                let (p, qx, qy) = (p - mean[0], qx - mean[1], qy - mean[2]);
                if p == 0.0 && qx == 0.0 && qy == 0.0 {
                    continue;
                }
                let (xc, yc) = self.cell_centre(row, column);
                let of = |s: &PatchStresses| {
                    s.pressure.scaled(p) + s.shear_x.scaled(qx) + s.shear_y.scaled(qy)
                };
                for (sy, wy) in image_offsets(y - yc, period_y, images) {
                    for (sx, wx) in image_offsets(x - xc, period_x, images) {
                        let s = uniform_patch(sx, sy, z, cell, nu);
                        sum = sum + of(&s).scaled(wx * wy);
                    }
                }
                for (sy, wy) in centred_offsets(y - yc, period_y) {
                    for (sx, wx) in centred_offsets(x - xc, period_x) {
                        let s =
                            far_images([sx, sy], z, self.cell, [period_x, period_y], images, nu);
                        sum = sum + of(&s).scaled(wx * wy);
                    }
                }
            }
        }
        Stress {
            zz: sum.zz + uniform_stress(mean, 2),
            yz: sum.yz + uniform_stress(mean, 3),
            xz: sum.xz + uniform_stress(mean, 4),
            ..sum
        }
    }

    /// [`TractionGrid::direct_layer`] for periodic tractions
    /// ([`TractionGrid::periodic_stress_at`]).
    pub fn periodic_direct_layer(&self, z: f64, nu: f64) -> Array3<f64> {
        self.direct_layer_with(z, |x, y| self.periodic_stress_at(x, y, z, nu))
    }
}

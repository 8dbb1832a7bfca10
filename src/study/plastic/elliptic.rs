//! An elliptical contact on an elastic-plastic body 1 (issue 51): the gap of two elliptical
//! paraboloids, `h = A x² + B y²` in the contact's principal axes (Johnson 1985, §4.1), on a
//! volume grid sized on Hertz's ellipse.
//!
//! ## The grid
//! `grid_cells` cells along x over `±extent_over_a` semi-axes `a` (the ellipse's along x) and
//! as many along y over `±extent_over_a` semi-axes `b` (along y): the cells are rectangles
//! `dx/dy = a/b`, with as many across each semi-axis as a ball's grid has across its radius
//! (the contact solver and the eigenstrain operator take any `dx`, `dy`). The depth is
//! `depth_over_a` times the smaller semi-axis in `depth_cells` uniform layers: the von Mises
//! maximum of the ellipse lies between `0.48 b` (a circle) and `0.78 b` (`b/a → 0`, the line
//! contact) below the surface, `b` the smaller semi-axis (Johnson 1985, §4.2 and §6.2), so
//! the depth scales with it, as a ball's does with its radius.

use ndarray::Array2;

use super::{solve_setup, Edges, PlasticKind, PlasticStudy, PlasticStudyError, Setup};
use crate::contact::elliptic::EllipticalContact;
use crate::contact::PointContact;
use crate::operator::elastic::Periodicity;
use crate::plasticity::column::DepthCells;
use crate::plasticity::halfspace::VolumeGrid;
use crate::plasticity::loading::Progress;
use crate::scene::PlasticitySpec;

/// The volume grid of `spec` about Hertz's ellipse (semi-axes `a` along x, `b` along y).
pub fn volume_grid(
    spec: &PlasticitySpec,
    ellipse: &EllipticalContact,
) -> Result<VolumeGrid, PlasticStudyError> {
    let n = spec.grid_cells;
    let (a, b) = (ellipse.semi_axis_x_m, ellipse.semi_axis_y_m);
    let dx = 2.0 * spec.extent_over_a * a / n as f64;
    let dy = 2.0 * spec.extent_over_a * b / n as f64;
    let depth = DepthCells::uniform(
        spec.depth_cells,
        spec.depth_over_a * ellipse.semi_minor_m() / spec.depth_cells as f64,
    )
    .map_err(|e| PlasticStudyError::Grid {
        key: "depth_cells",
        message: e.0,
    })?;
    Ok(VolumeGrid {
        shape: [n, n],
        spacing_m: [dx, dy],
        depth,
        periodicity: Periodicity::NonPeriodic,
    })
}

/// The circle of the ellipse's load, area and peak pressure: radius `c = √(ab)`, `p0` the
/// ellipse's, and the radius `R = 4 E* c³ / (3 W)` that gives it by Hertz's sphere
/// (`c³ = 3 W R / (4 E*)`, Johnson 1985, §4.2(a)); reported beside the ellipse's own values.
pub fn equivalent_circle(ellipse: &EllipticalContact) -> PointContact {
    let c = (ellipse.semi_axis_x_m * ellipse.semi_axis_y_m).sqrt();
    let e_star = ellipse.effective_modulus_pa;
    let radius = 4.0 * e_star * c.powi(3) / (3.0 * ellipse.load_n);
    PointContact::from_effective(ellipse.load_n, e_star, radius)
}

/// The study of an elliptical paraboloid pressed on an elastic-plastic body 1 (`ellipse` its
/// elastic Hertz contact, in its principal axes).
pub fn study_elliptical(
    spec: &PlasticitySpec,
    ellipse: &EllipticalContact,
    friction: f64,
    progress: &mut dyn FnMut(Progress),
) -> Result<PlasticStudy, PlasticStudyError> {
    let grid = volume_grid(spec, ellipse)?;
    let [_, ny, nx] = grid.dims();
    let [dx, dy] = grid.spacing_m;
    let x_m: Vec<f64> = (0..nx).map(|i| (i as f64 - (nx / 2) as f64) * dx).collect();
    let y_m: Vec<f64> = (0..ny).map(|j| (j as f64 - (ny / 2) as f64) * dy).collect();
    let curvature = ellipse.curvature;
    // The gap of the two paraboloids: heights out of body 1, highest on the axis.
    let heights = Array2::from_shape_fn((ny, nx), |(j, i)| {
        -(curvature.half_curvature_x_per_m * x_m[i] * x_m[i]
            + curvature.half_curvature_y_per_m * y_m[j] * y_m[j])
    });
    let setup = Setup {
        hertz: super::ElasticHertz::Point(equivalent_circle(ellipse)),
        kind: PlasticKind::Elliptical(*ellipse),
        grid,
        x_m,
        y_m,
        body: super::SetupBody::Volume { heights },
        elastic_max_pressure_pa: ellipse.p0_pa,
        edges: Edges::Bounded,
    };
    solve_setup(spec, setup, friction, progress)
}

#[cfg(test)]
mod tests;

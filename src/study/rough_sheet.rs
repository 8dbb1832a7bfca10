//! What a rough scene's sheet draws, computed once here from the solved contact: the stress
//! in the xz section through the highest pressure (down to twice the search depth), the stress
//! in the xy plane at the depth of that section's maximum, and, for a nominally flat surface,
//! the real area against load ([`super::rough::area_curve`]). The sheet
//! ([`crate::figure::rough`]) only converts units and draws.

use ndarray::Array2;

use super::rough::{self, search_depth_m, RoughStudyError, REFERENCE_LENGTH_M};
use super::surface::SurfaceStudyError;
use crate::contact::rough::RoughSolution;
use crate::field::{self, Axis, FieldError, Plane, Section};
use crate::scene::Scene;
use crate::surface::generate::Form;
use crate::surface::stats::Characterisation;

/// The fields of a rough scene's sheet.
#[derive(Clone, Debug)]
pub struct RoughSheetFields {
    /// The row of the highest pressure (the xz section's `y` is its centre).
    pub peak_row: usize,
    /// The xz section, over the cell centres along x and from the surface down, in the
    /// reference length (µm).
    pub xz: Plane,
    /// The scene's quantity on `xz`, Pa, `[z, x]`.
    pub xz_pa: Array2<f64>,
    /// The depth of the largest value in the xz section, µm: the depth of the xy plane.
    pub max_depth: f64,
    /// The xy plane at `max_depth`, over the cell centres.
    pub xy: Plane,
    /// The scene's quantity on `xy`, Pa, `[y, x]`.
    pub xy_pa: Array2<f64>,
    /// Real area against load `(p̄ / E*, A / A0)` of a nominally flat surface (`None` for a
    /// rough ball or cylinder, whose sheet compares its pressure with Hertz's).
    pub area_curve: Option<Vec<(f64, f64)>>,
    /// The surface's characterisation, whose summits give the Greenwood-Williamson prediction
    /// beside the area curve (with it, or `None`).
    pub characterisation: Option<Characterisation>,
}

/// Why the sheet's fields cannot be computed.
#[derive(Debug, thiserror::Error)]
pub enum RoughSheetError {
    #[error(transparent)]
    Field(#[from] FieldError),
    #[error(transparent)]
    Study(#[from] RoughStudyError),
    #[error(transparent)]
    Surface(#[from] SurfaceStudyError),
}

/// The sheet's fields of rough `scene` under its `solution`; `on_row` is called per evaluated
/// grid row.
pub fn sheet_fields(
    scene: &Scene,
    solution: &RoughSolution,
    on_row: &(dyn Fn() + Sync),
) -> Result<RoughSheetFields, RoughSheetError> {
    let surface = scene.surface.as_ref().ok_or(RoughStudyError::NotRough)?;
    let [ny, nx] = surface.heights.shape();
    let [dx, dy] = surface.heights.spacing_m();
    // The stress field under the solved tractions, in the reference units (1 um, 1 MPa).
    let (friction, poisson) = (scene.contact.friction, scene.contact.poisson);
    let stresses = rough::stress_solution(solution, friction, poisson)
        .map_err(|e| FieldError::Numerical(e.to_string()))?;
    let quantity = scene.figure.quantity;
    let ((peak_row, _), _) =
        solution
            .pressure_pa
            .indexed_iter()
            .fold(((0, 0), f64::NEG_INFINITY), |best, (at, &p)| {
                if p > best.1 {
                    (at, p)
                } else {
                    best
                }
            });
    let (ax, ay) = (dx / REFERENCE_LENGTH_M, dy / REFERENCE_LENGTH_M);
    let cell = ax.min(ay);
    let depth_m = (2.0 * search_depth_m(solution)).min(0.5 * (nx as f64 * dx).min(ny as f64 * dy));
    let layers = ((depth_m / REFERENCE_LENGTH_M) / cell).ceil().max(4.0) as usize + 1;
    let centres_x = Axis::new(0.5 * ax, (nx as f64 - 0.5) * ax, nx);
    let xz = Plane {
        section: Section::Xz {
            y: (peak_row as f64 + 0.5) * ay,
        },
        u: centres_x,
        v: Axis::new(0.0, (layers - 1) as f64 * cell, layers),
    };
    let xz_pa = field::evaluate(&stresses, &xz, &[quantity], on_row)?
        .values
        .index_axis(ndarray::Axis(1), 0)
        .mapv(|v| v * 1e6);
    // Depth of the largest value in the section: the xy section is taken there.
    let ((deepest_row, _), _) =
        xz_pa
            .indexed_iter()
            .fold(((0, 0), f64::NEG_INFINITY), |best, (at, &v)| {
                if v > best.1 {
                    (at, v)
                } else {
                    best
                }
            });
    let max_depth = xz.v.value(deepest_row);
    let xy = Plane {
        section: Section::Xy { z: max_depth },
        u: centres_x,
        v: Axis::new(0.5 * ay, (ny as f64 - 0.5) * ay, ny),
    };
    let xy_pa = field::evaluate(&stresses, &xy, &[quantity], on_row)?
        .values
        .index_axis(ndarray::Axis(1), 0)
        .mapv(|v| v * 1e6);
    let (area_curve, characterisation) = match surface.shape {
        Form::None => (
            Some(rough::area_curve(scene, solution)?),
            Some(super::surface::characterise(scene)?),
        ),
        _ => (None, None),
    };
    Ok(RoughSheetFields {
        peak_row,
        xz,
        xz_pa,
        max_depth,
        xy,
        xy_pa,
        area_curve,
        characterisation,
    })
}

/// The scene's quantity in planes parallel to the surface, from the surface down to the
/// search depth ([`search_depth_m`]), for a recording's depth timeline: `(z, values)` with `z`
/// in the reference length (µm) and the values in Pa, `[y, x]` over the cell centres; at most
/// 25 planes, evenly spaced and at least a cell apart.
pub fn depth_layers(
    scene: &Scene,
    solution: &RoughSolution,
    on_row: &(dyn Fn() + Sync),
) -> Result<Vec<(f64, Array2<f64>)>, RoughSheetError> {
    let stresses = rough::stress_solution(solution, scene.contact.friction, scene.contact.poisson)
        .map_err(|e| FieldError::Numerical(e.to_string()))?;
    let [dx, dy] = solution.spacing_m;
    let (ny, nx) = solution.pressure_pa.dim();
    let (ax, ay) = (dx / REFERENCE_LENGTH_M, dy / REFERENCE_LENGTH_M);
    let cell = ax.min(ay);
    let deepest = search_depth_m(solution) / REFERENCE_LENGTH_M;
    let layers = ((deepest / cell).ceil() as usize).clamp(1, 24);
    let step = (deepest / layers as f64).max(cell);
    let quantity = scene.figure.quantity;
    let mut maps = Vec::with_capacity(layers + 1);
    for k in 0..=layers {
        let z = k as f64 * step;
        let plane = Plane {
            section: Section::Xy { z },
            u: Axis::new(0.5 * ax, (nx as f64 - 0.5) * ax, nx),
            v: Axis::new(0.5 * ay, (ny as f64 - 0.5) * ay, ny),
        };
        let values = field::evaluate(&stresses, &plane, &[quantity], on_row)?;
        maps.push((
            z,
            values
                .values
                .index_axis(ndarray::Axis(1), 0)
                .mapv(|v| v * 1e6),
        ));
    }
    Ok(maps)
}

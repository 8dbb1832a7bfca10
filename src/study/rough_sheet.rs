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
use crate::stress::Quantity;
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

/// Planes of a recording's depth timeline below the surface (the first at `z = 0`).
const DEPTH_LAYERS: usize = 24;

/// Each gap between depth layers is this many times the one above it: fine near the surface,
/// where the spots' own fields change fastest, coarse deep ([`depth_planes`]).
const DEPTH_GROWTH: f64 = 1.12;

/// One plane parallel to the surface of a recording's depth timeline.
#[derive(Clone, Debug)]
pub struct DepthLayer {
    /// Depth in the reference length (µm).
    pub z: f64,
    /// The scene's quantity, Pa, `[y, x]` over the cell centres.
    pub values_pa: Array2<f64>,
    /// The largest von Mises stress in the plane, Pa.
    pub max_von_mises_pa: f64,
    /// The largest Tresca shear stress `(σ1 − σ3)/2` in the plane, Pa.
    pub max_tresca_pa: f64,
}

/// The depths of [`DEPTH_LAYERS`] planes from the surface to `deepest` in a geometric
/// progression (each gap [`DEPTH_GROWTH`] times the one above), with `exact` (the depth of the
/// reported maximum) inserted unless a plane already lies there; in increasing order.
fn depth_planes(deepest: f64, exact: f64) -> Vec<f64> {
    let n = DEPTH_LAYERS as i32;
    let first = deepest * (DEPTH_GROWTH - 1.0) / (DEPTH_GROWTH.powi(n) - 1.0);
    let mut depths: Vec<f64> = (0..=n)
        .map(|k| first * (DEPTH_GROWTH.powi(k) - 1.0) / (DEPTH_GROWTH - 1.0))
        .collect();
    depths[DEPTH_LAYERS] = deepest;
    let near = |z: f64| {
        depths
            .iter()
            .any(|&d| (d - z).abs() <= 1e-12 * deepest.max(1.0))
    };
    if exact.is_finite() && exact >= 0.0 && !near(exact) {
        depths.push(exact);
        depths.sort_by(f64::total_cmp);
    }
    depths
}

/// The scene's quantity in planes parallel to the surface, from the surface down to the
/// search depth ([`search_depth_m`]) at the depths of [`depth_planes`], for a recording's
/// depth timeline, with each plane's largest von Mises and Tresca stresses; `exact_z` (in the
/// reference length) is the depth of the report's maximum
/// ([`super::rough::findings`]`.maxima.von_mises.z_over_a`), included exactly so that the
/// layer there shows the report's value.
pub fn depth_layers(
    scene: &Scene,
    solution: &RoughSolution,
    exact_z: f64,
    on_row: &(dyn Fn() + Sync),
) -> Result<Vec<DepthLayer>, RoughSheetError> {
    let stresses = rough::stress_solution(solution, scene.contact.friction, scene.contact.poisson)
        .map_err(|e| FieldError::Numerical(e.to_string()))?;
    let [dx, dy] = solution.spacing_m;
    let (ny, nx) = solution.pressure_pa.dim();
    let (ax, ay) = (dx / REFERENCE_LENGTH_M, dy / REFERENCE_LENGTH_M);
    let deepest = search_depth_m(solution) / REFERENCE_LENGTH_M;
    let quantities = [
        scene.figure.quantity,
        Quantity::VonMises,
        Quantity::MaxShear,
    ];
    let largest = |values: &Array2<f64>| {
        values
            .iter()
            .copied()
            .filter(|v| v.is_finite())
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let mut layers = Vec::with_capacity(DEPTH_LAYERS + 2);
    for z in depth_planes(deepest, exact_z) {
        let plane = Plane {
            section: Section::Xy { z },
            u: Axis::new(0.5 * ax, (nx as f64 - 0.5) * ax, nx),
            v: Axis::new(0.5 * ay, (ny as f64 - 0.5) * ay, ny),
        };
        let field = field::evaluate(&stresses, &plane, &quantities, on_row)?;
        let of = |k: usize| {
            field
                .values
                .index_axis(ndarray::Axis(1), k)
                .mapv(|v| v * 1e6)
        };
        layers.push(DepthLayer {
            z,
            values_pa: of(0),
            max_von_mises_pa: largest(&of(1)),
            max_tresca_pa: largest(&of(2)),
        });
    }
    Ok(layers)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn depth_planes_grow_geometrically_and_hold_the_exact_depth() {
        let depths = depth_planes(10.0, 0.375);
        assert_eq!(depths.len(), DEPTH_LAYERS + 2);
        assert_eq!(depths[0], 0.0);
        assert_eq!(*depths.last().expect("planes"), 10.0);
        assert!(depths.contains(&0.375));
        assert!(depths.windows(2).all(|w| w[1] > w[0]), "{depths:?}");
        // Fine near the surface, coarse deep.
        assert!(depths[1] < 0.1 && depths[DEPTH_LAYERS + 1] - depths[DEPTH_LAYERS] > 1.0);
        // A depth already on a plane is not repeated.
        assert_eq!(depth_planes(10.0, 0.0).len(), DEPTH_LAYERS + 1);
        assert_eq!(depth_planes(10.0, 10.0).len(), DEPTH_LAYERS + 1);
    }
}

//! The `[volume]` of a scene, computed once here for the recording's 3-D view
//! (`crate::record`): the scene's quantity on the half box `y >= 0` (the view cuts the box
//! at `y = 0` so that the nested iso-surfaces show), from the closed form where there is one.

use ndarray::Array3;

use crate::field::{self, Axis, FieldError, Volume};
use crate::scene::{Scene, VolumeSpec};

/// The quantity on the half box (figure units), indexed `[z, y, x]`.
pub struct Grid {
    pub values: Array3<f32>,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub z: Vec<f64>,
}

impl Grid {
    /// The largest |value|.
    pub fn largest(&self) -> f64 {
        self.values
            .iter()
            .filter(|v| v.is_finite())
            .fold(0.0f64, |m, v| m.max(f64::from(v.abs())))
    }
}

/// The half box `y <= 0` of the scene's volume (all of it if it lies on one side): seen from
/// `y > 0` with z down, +x runs to the right, as in the xz section.
pub fn half(spec: &VolumeSpec) -> (f64, f64) {
    if spec.y.0 < 0.0 && spec.y.1 > 0.0 {
        (spec.y.0, 0.0)
    } else {
        spec.y
    }
}

/// Evaluates the quantity on the half box with `points` samples along the box's longest side.
pub fn evaluate(scene: &Scene, spec: &VolumeSpec, points: usize) -> Result<Grid, FieldError> {
    let unit_over_a = scene.length_unit_over_a();
    let longest = (spec.x.1 - spec.x.0)
        .max(spec.y.1 - spec.y.0)
        .max(spec.z.1 - spec.z.0);
    let spacing = longest / (points.max(2) - 1) as f64;
    let axis = |(lo, hi): (f64, f64)| {
        let count = (((hi - lo) / spacing).round() as usize + 1).max(2);
        Axis::new(lo * unit_over_a, hi * unit_over_a, count)
    };
    let volume = Volume {
        x: axis(spec.x),
        y: axis(half(spec)),
        z: axis(spec.z),
    };
    // The closed form where there is one (a numerical volume would take direct summation at
    // every point).
    let panel = &scene.panels[0];
    let solution = match super::closed_form(scene, panel) {
        Some(solution) => solution,
        None => super::solution(scene, panel).map_err(|e| FieldError::Numerical(e.to_string()))?,
    };
    let field = field::evaluate_volume::<f32>(&solution, &volume, &[spec.quantity], &|| {})?;
    let block = field
        .block(spec.quantity)
        .ok_or_else(|| FieldError::Numerical("the volume's quantity was not evaluated".into()))?;
    let stress_per_p0 = super::DisplayUnits::of(scene).stress_per_p0 as f32;
    let to_unit = |axis: &Axis| axis.values().map(|v| v / unit_over_a).collect::<Vec<f64>>();
    Ok(Grid {
        values: block.mapv(|v| v * stress_per_p0),
        x: to_unit(&volume.x),
        y: to_unit(&volume.y),
        z: to_unit(&volume.z),
    })
}

/// The largest value of the volume's quantity and where it is (the figure's stress unit and
/// length unit), the one the `hertz` report gives: for von Mises and Tresca the report's
/// refined maximum ([`super::assess::scene_maxima`]) where it lies in the half box, otherwise
/// the grid's largest sample. One maximum then has one position in the 3-D view, the report
/// and the closing note.
pub fn maximum(scene: &Scene, spec: &VolumeSpec, grid: &Grid) -> Option<(f64, [f64; 3])> {
    use crate::stress::Quantity;
    let unit_over_a = scene.length_unit_over_a();
    let stress_per_p0 = super::DisplayUnits::of(scene).stress_per_p0;
    let reported = match spec.quantity {
        Quantity::VonMises | Quantity::MaxShear => {
            super::assess::scene_maxima(scene).maxima.ok().map(|m| {
                if spec.quantity == Quantity::VonMises {
                    m.von_mises
                } else {
                    m.max_shear
                }
            })
        }
        _ => None,
    };
    let (y0, y1) = half(spec);
    let inside = |[x, y, z]: [f64; 3]| {
        (spec.x.0..=spec.x.1).contains(&x)
            && (y0..=y1).contains(&y)
            && (spec.z.0..=spec.z.1).contains(&z)
    };
    if let Some(e) = reported {
        // The report searches y >= 0; its mirror at -y is the same maximum.
        let y = if y1 <= 0.0 { -e.y_over_a } else { e.y_over_a };
        let at = [e.x_over_a, y, e.z_over_a].map(|c| c / unit_over_a);
        if inside(at) {
            return Some((e.value_over_p0 * stress_per_p0, at));
        }
    }
    grid.values
        .indexed_iter()
        .filter(|(_, v)| v.is_finite())
        .max_by(|a, b| a.1.total_cmp(b.1))
        .map(|((k, j, i), &v)| (f64::from(v), [grid.x[i], grid.y[j], grid.z[k]]))
}

//! What a rough scene's sheet draws, computed once here from the solved contact and the
//! report's maxima ([`super::rough::findings`]): the stress in the xz section through the
//! report's largest value (its row, centred on it when the contact is periodic, from the
//! surface down to twice the search depth or the scene's `[figure] z`, never thinner than a
//! quarter of its width), the stress in the xy plane at the depth of that maximum, and, for a
//! nominally flat surface, the real area against load ([`super::rough::area_curve`]); and how
//! the maps are shown ([`display_roll`]: a periodic contact's centred on that maximum, so that a
//! contact on the periodic seam is drawn whole). The sheet ([`crate::figure::rough`]) only
//! converts units, rolls its maps by that and draws.

use ndarray::Array2;

use super::assess::{Extreme, StressMaxima};
use super::coated_rough;
use super::map_roll::{self, Roll};
use super::rough::{self, search_depth_m, RoughStudyError, REFERENCE_LENGTH_M};
use super::surface::SurfaceStudyError;
use crate::contact::rough::RoughSolution;
use crate::field::{self, Axis, FieldError, Plane, Section};
use crate::operator::elastic::Periodicity;
use crate::scene::{Scene, ROUGH_SECTION_MIN_CELLS, ROUGH_SECTION_MIN_DEPTH_OVER_WIDTH};
use crate::stress::Quantity;
use crate::surface::generate::Form;
use crate::surface::stats::Characterisation;

/// The report's maximum the xz section passes through.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReportedMaximum {
    /// [`Quantity::VonMises`] or [`Quantity::MaxShear`]: the figure's quantity when the report
    /// states its maximum, else von Mises.
    pub quantity: Quantity,
    /// Its value (MPa, the reference pressure) and place (µm, the reference length), as the
    /// `contact` report states them.
    pub extreme: Extreme,
}

impl ReportedMaximum {
    /// The report's maximum of `quantity` in `maxima` (von Mises for a quantity the report
    /// does not search).
    pub fn of(maxima: &StressMaxima, quantity: Quantity) -> Self {
        match quantity {
            Quantity::MaxShear => Self {
                quantity,
                extreme: maxima.max_shear,
            },
            _ => Self {
                quantity: Quantity::VonMises,
                extreme: maxima.von_mises,
            },
        }
    }
}

/// The largest sample of a drawn section: value (Pa) and place (µm).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampledMaximum {
    pub value_pa: f64,
    pub x: f64,
    pub z: f64,
}

/// The fields of a rough scene's sheet.
#[derive(Clone, Debug)]
pub struct RoughSheetFields {
    /// The report's maximum the section passes through.
    pub reported: ReportedMaximum,
    /// The map row of the section (the reported maximum's; the section's `y` is its centre).
    pub row: usize,
    /// The map column under each sample of the section along x (a periodic contact's section
    /// may run across the map's edge: its columns wrap around).
    pub columns: Vec<usize>,
    /// Whether the section is centred on the reported maximum across the periodic map's
    /// edges (its x then runs beyond the map where the field repeats).
    pub centred: bool,
    /// The xz section drawn, in the reference length (µm): along x over cell centres (a
    /// window of the row, see [`section_window`]), in depth from the depth range's top.
    pub xz: Plane,
    /// The scene's quantity on `xz`, Pa, `[z, x]`.
    pub xz_pa: Array2<f64>,
    /// The largest value in `xz_pa` and where it is.
    pub xz_largest: SampledMaximum,
    /// The depth range was the scene's (`[figure] z`), not the default.
    pub depth_given: bool,
    /// How the sheet's maps (topography, pressure, `xy`) are shown: a periodic contact's
    /// centred on the reported maximum ([`display_roll`]), an isolated one's as stored. The
    /// section's window lies within the rolled maps' x range.
    pub roll: Roll,
    /// The depth of the xy plane, µm: the reported maximum's.
    pub xy_depth: f64,
    /// The xy plane at `xy_depth`, over the cell centres as stored (drawn rolled by `roll`).
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

/// How a rough contact's maps are shown beside the section through `maximum` (the report's,
/// [`ReportedMaximum::extreme`], in µm): a periodic contact's rolled by whole cells so that
/// the maximum's cell is the map's centre cell (the contact around it drawn whole, not split
/// across the seam; the maximum keeps its coordinates, the axes run on past the period), an
/// isolated contact's as stored. Apply it with [`Roll::apply`] and [`Roll::axes`] (spacing in
/// µm).
///
/// The maximum, not the pressure's centroid on the torus, because the section goes through it
/// and both the section and the depth map mark it; and a rough surface's spots spread over the
/// whole period have no meaningful centroid.
pub fn display_roll(solution: &RoughSolution, maximum: &Extreme) -> Roll {
    let (ny, nx) = solution.pressure_pa.dim();
    let [dx, dy] = solution.spacing_m;
    let cell = [
        map_roll::cell_of(maximum.y_over_a, dy / REFERENCE_LENGTH_M, ny),
        map_roll::cell_of(maximum.x_over_a, dx / REFERENCE_LENGTH_M, nx),
    ];
    map_roll::centring(solution.periodicity, cell, [ny, nx])
}

/// At most this many depth rows: each is a DC-FFT layer of the whole map.
const MAX_SECTION_ROWS: usize = 4096;

/// How many of a row's `nx` cells (each `ax` wide) a section `span` deep shows: enough that
/// the section is no thinner than [`ROUGH_SECTION_MIN_DEPTH_OVER_WIDTH`] of its width (four times its depth),
/// at least [`ROUGH_SECTION_MIN_CELLS`], at most the row.
pub fn section_window(span: f64, ax: f64, nx: usize) -> usize {
    let wanted = (span / ROUGH_SECTION_MIN_DEPTH_OVER_WIDTH / ax).ceil();
    let wanted = if wanted.is_finite() && wanted > 0.0 {
        wanted.min(nx as f64) as usize
    } else {
        nx
    };
    wanted.max(ROUGH_SECTION_MIN_CELLS.min(nx)).min(nx)
}

/// The depth samples from `z0` to (at least) `z1`, evenly spaced at most `step` apart, with
/// `exact` among them when it lies in `(z0, z1]` (the reported maximum's depth, so that the
/// section samples the report's point). The last sample may lie up to one step below `z1`.
fn depth_axis(z0: f64, z1: f64, step: f64, exact: f64) -> Axis {
    let span = z1 - z0;
    let rows = |h: f64| ((span / h) - 1e-9).ceil().max(2.0) as usize;
    if exact > z0 && exact <= z1 {
        let k = (((exact - z0) / step) - 1e-9).ceil().max(1.0);
        let h = (exact - z0) / k;
        let m = rows(h);
        if m <= MAX_SECTION_ROWS {
            return Axis::new(z0, z0 + m as f64 * h, m + 1);
        }
    }
    let m = rows(step);
    Axis::new(z0, z0 + m as f64 * step, m + 1)
}

/// The sheet's fields of rough `scene` under its `solution`, the xz section through the
/// report's maximum in `maxima` (from [`super::rough::findings`]); `on_row` is called per
/// evaluated grid row.
pub fn sheet_fields(
    scene: &Scene,
    solution: &RoughSolution,
    maxima: &StressMaxima,
    on_row: &(dyn Fn() + Sync),
) -> Result<RoughSheetFields, RoughSheetError> {
    let surface = scene.surface.as_ref().ok_or(RoughStudyError::NotRough)?;
    let [ny, nx] = surface.heights.shape();
    let [dx, dy] = surface.heights.spacing_m();
    // The stress field under the solved tractions, in the reference units (1 um, 1 MPa): a
    // coated body's layered waves, or the homogeneous DC-FFT solution.
    let (friction, poisson) = (scene.contact.friction, scene.contact.poisson);
    let stresses = match &scene.contact.coating {
        Some(coating) => {
            let layers = coated_rough::layered_stress(solution, coating, friction)
                .map_err(|e| FieldError::Numerical(e.to_string()))?;
            let reported = ReportedMaximum::of(maxima, scene.figure.quantity);
            let side = coated_rough::reported_side(
                &layers,
                &reported.extreme,
                reported.quantity,
                solution.spacing_m,
            );
            Stresses::Layered(Box::new(layers), side)
        }
        None => Stresses::Homogeneous(
            rough::stress_solution(solution, friction, poisson)
                .map_err(|e| FieldError::Numerical(e.to_string()))?,
        ),
    };
    let quantity = scene.figure.quantity;
    let reported = ReportedMaximum::of(maxima, quantity);
    let (ax, ay) = (dx / REFERENCE_LENGTH_M, dy / REFERENCE_LENGTH_M);
    let cell = ax.min(ay);
    let row = map_roll::cell_of(reported.extreme.y_over_a, ay, ny);
    let column = map_roll::cell_of(reported.extreme.x_over_a, ax, nx);

    // The depth range: the scene's, or down to twice the search depth (within half the map),
    // never thinner than a quarter of the section's width.
    let default_depth = (2.0 * search_depth_m(solution))
        .min(0.5 * (nx as f64 * dx).min(ny as f64 * dy))
        / REFERENCE_LENGTH_M;
    let given = scene.figure.depth_given.then(|| {
        let per_unit = scene.figure.length_unit.metres(REFERENCE_LENGTH_M) / REFERENCE_LENGTH_M;
        (scene.figure.z.0 * per_unit, scene.figure.z.1 * per_unit)
    });
    let span = given.map_or(default_depth, |(z0, z1)| z1 - z0);
    let window = section_window(span, ax, nx);
    let (z0, z1) = given.unwrap_or_else(|| {
        let width = window as f64 * ax;
        (
            0.0,
            default_depth
                .max(ROUGH_SECTION_MIN_DEPTH_OVER_WIDTH * width)
                .max(4.0 * cell),
        )
    });
    let step = cell.min((z1 - z0) / 32.0).max((z1 - z0) / 512.0);
    let depths = depth_axis(z0, z1, step, reported.extreme.z_over_a);

    // The window along the row: centred on the maximum (across the edges of a periodic map,
    // whose field repeats; within an isolated one).
    let periodic = solution.periodicity == Periodicity::Periodic;
    let half = (window / 2) as isize;
    let first = if periodic {
        column as isize - half
    } else {
        (column as isize - half).clamp(0, (nx - window) as isize)
    };
    let centred = periodic;
    let columns: Vec<usize> = (0..window)
        .map(|k| (first + k as isize).rem_euclid(nx as isize) as usize)
        .collect();
    let x_of = |k: usize| (first as f64 + k as f64 + 0.5) * ax;
    let centres_x = Axis::new(0.5 * ax, (nx as f64 - 0.5) * ax, nx);
    let y = (row as f64 + 0.5) * ay;
    let whole_row = Plane {
        section: Section::Xz { y },
        u: centres_x,
        v: depths,
    };
    let row_pa = stresses.plane(&whole_row, row, quantity, on_row)?;
    let xz_pa = Array2::from_shape_fn((depths.count, window), |(j, k)| row_pa[[j, columns[k]]]);
    let xz = Plane {
        section: Section::Xz { y },
        u: Axis::new(x_of(0), x_of(window - 1), window),
        v: depths,
    };
    let ((best_row, best_column), best) =
        xz_pa
            .indexed_iter()
            .fold(((0, 0), f64::NEG_INFINITY), |best, (at, &v)| {
                if v > best.1 {
                    (at, v)
                } else {
                    best
                }
            });
    let xz_largest = SampledMaximum {
        value_pa: best,
        x: xz.u.value(best_column),
        z: xz.v.value(best_row),
    };
    let xy_depth = reported.extreme.z_over_a;
    let xy = Plane {
        section: Section::Xy { z: xy_depth },
        u: centres_x,
        v: Axis::new(0.5 * ay, (ny as f64 - 0.5) * ay, ny),
    };
    let xy_pa = stresses.plane(&xy, row, quantity, on_row)?;
    let (area_curve, characterisation) = match surface.shape {
        Form::None => (
            Some(rough::area_curve(scene, solution)?),
            Some(super::surface::characterise(scene)?),
        ),
        _ => (None, None),
    };
    Ok(RoughSheetFields {
        reported,
        row,
        columns,
        centred,
        roll: display_roll(solution, &reported.extreme),
        xz,
        xz_pa,
        xz_largest,
        depth_given: given.is_some(),
        xy_depth,
        xy,
        xy_pa,
        area_curve,
        characterisation,
    })
}

/// The stresses a sheet is drawn from: the homogeneous DC-FFT solution, or a coated body's
/// layered waves with the side of the interface its report's maximum lies on.
enum Stresses {
    Homogeneous(crate::solution::Solution),
    Layered(
        Box<crate::coating::stress::LayeredStress>,
        crate::coating::Side,
    ),
}

impl Stresses {
    /// `quantity` on `plane` (reference units, a section `xz` through map row `row`, or a
    /// plane `xy` over the cell centres), Pa, `[v, u]`.
    fn plane(
        &self,
        plane: &Plane,
        row: usize,
        quantity: Quantity,
        on_row: &(dyn Fn() + Sync),
    ) -> Result<Array2<f64>, FieldError> {
        match self {
            Stresses::Homogeneous(solution) => {
                Ok(field::evaluate(solution, plane, &[quantity], on_row)?
                    .values
                    .index_axis(ndarray::Axis(1), 0)
                    .mapv(|v| v * 1e6))
            }
            Stresses::Layered(layers, side) => match plane.section {
                Section::Xz { .. } => {
                    let depths: Vec<f64> = (0..plane.v.count)
                        .map(|k| plane.v.value(k) * REFERENCE_LENGTH_M)
                        .collect();
                    Ok(coated_rough::row_section(
                        layers, row, &depths, *side, quantity,
                    ))
                }
                Section::Xy { z } => {
                    let z_m = z * REFERENCE_LENGTH_M;
                    let h = layers.layered().thickness_m;
                    let field = layers
                        .layer(z_m, coated_rough::side_at(z_m, h, *side))
                        .map_err(|e| FieldError::Numerical(e.to_string()))?;
                    let (_, ny, nx) = field.dim();
                    Ok(Array2::from_shape_fn((ny, nx), |(j, i)| {
                        quantity.of(&coated_rough::stress_at(&field, j, i))
                    }))
                }
                _ => Err(FieldError::Numerical(
                    "a coated rough sheet draws xz and xy planes only".into(),
                )),
            },
        }
    }
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
    if scene.contact.coating.is_some() {
        return Err(FieldError::Numerical(
            "contact.body1.coating: a coated rough contact has no depth timeline (its planes would be the homogeneous body's)".into(),
        )
        .into());
    }
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
    fn the_depth_axis_holds_the_reported_depth_and_reaches_the_range() {
        // The worn scene: cells of 1 µm, the report's maximum at 0.375 µm, 50 µm deep.
        let axis = depth_axis(0.0, 50.3, 1.0, 0.375);
        assert_eq!(axis.min, 0.0);
        assert!(axis.max >= 50.3 && axis.max < 50.3 + axis.step());
        assert!((axis.step() - 0.375).abs() < 1e-15);
        assert!((axis.value(1) - 0.375).abs() < 1e-15);
        // A depth of several steps: the step shrinks to divide it, at most the one asked.
        let axis = depth_axis(0.0, 10.0, 1.0, 3.125);
        assert!(axis.step() <= 1.0 && axis.step() > 0.5);
        let k = (3.125 / axis.step()).round() as usize;
        assert!((axis.value(k) - 3.125).abs() < 1e-12, "{axis:?}");
        // Outside the range, or at its top, the step is the one asked.
        for exact in [0.0, 12.0, f64::NAN] {
            let axis = depth_axis(0.0, 10.0, 0.5, exact);
            assert_eq!((axis.count, axis.max), (21, 10.0), "{exact}");
        }
        // From a depth below the surface.
        let axis = depth_axis(2.0, 4.0, 0.25, 2.3);
        assert!(
            (axis.value(2) - 2.3).abs() < 1e-12 && axis.max >= 4.0,
            "{axis:?}"
        );
    }

    #[test]
    fn a_section_window_is_four_times_as_wide_as_deep_within_the_row() {
        assert_eq!(section_window(50.0, 1.0, 128), 128);
        assert_eq!(section_window(0.6, 0.15625, 64), 16);
        assert_eq!(section_window(0.01, 0.15625, 64), ROUGH_SECTION_MIN_CELLS);
        assert_eq!(section_window(0.01, 0.15625, 5), 5);
        assert_eq!(section_window(f64::NAN, 1.0, 32), 32);
    }

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

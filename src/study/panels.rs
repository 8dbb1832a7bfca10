//! The fields a figure's panels draw, computed once here: each panel's stress solution
//! evaluated on its grid plane (the numerical minus the closed form for a difference panel),
//! and the tractions along the line where the plane meets the surface. In units of `a` and
//! `p0`; the figure ([`crate::figure::build`]) converts them to its display units and draws.

use ndarray::Array2;

use crate::field::{self, Axis, FieldError, Plane, Section};
use crate::scene::{ContactKind, Method, Scene};
use crate::solution::Solution;
use crate::stress::Quantity;

/// Number of samples of the traction profile across a panel.
const TRACTION_SAMPLES: usize = 601;

/// One panel's computed field.
#[derive(Clone, Debug)]
pub struct PanelField {
    /// The grid plane, in units of a.
    pub plane: Plane,
    /// The scene's quantity on the plane, over `p0`, `[v, u]`; values below `1e-12` of the
    /// largest are exactly zero.
    pub values_over_p0: Array2<f64>,
    /// `(u, p, q)` along the line where the plane meets the surface (over `a` and `p0`), with
    /// the contact's edges on it included exactly; empty for a plane parallel to the surface.
    pub traction: Vec<(f64, f64, f64)>,
    /// Half the contact's chord on that line, over `a` (0 when the contact has no outline).
    pub half_width_over_a: f64,
    /// The plane's largest value of the quantity and where it is, `[value / p0, u / a, v / a]`,
    /// refined between the samples ([`refined_peak`]) for a closed form and a quantity whose
    /// maximum the `hertz` report gives; `None` otherwise (the largest sample is marked).
    pub peak_over_p0: Option<[f64; 3]>,
    /// The body's maximum of the quantity under this panel's contact, as the `hertz` report
    /// finds it ([`super::assess::maximum`]), `[value / p0, x / a, y / a, z / a]`, when this
    /// plane misses it (its largest value is more than 1e-4 p0 below): the figure says where
    /// the body's maximum is.
    pub elsewhere_over_p0: Option<[f64; 4]>,
}

/// Evaluates every panel of `scene` (in parallel within each panel), after checking that the
/// whole figure fits the memory allowed. `on_row` is called once per evaluated grid row.
pub fn panel_fields(
    scene: &Scene,
    on_row: &(dyn Fn() + Sync),
) -> Result<Vec<PanelField>, FieldError> {
    // The whole figure, before the first panel is allocated.
    let needed = super::memory::figure_bytes(scene);
    let limit = field::memory_limit_bytes();
    if needed > limit {
        let points = scene
            .panels
            .iter()
            .map(|p| super::plane(scene, p).points())
            .sum();
        return Err(FieldError::TooLarge {
            points,
            quantities: 1,
            needed_mib: needed >> 20,
            limit_mib: limit >> 20,
        });
    }
    let quantity = scene.figure.quantity;
    let mut fields = Vec::with_capacity(scene.panels.len());
    for panel in &scene.panels {
        let plane = super::plane(scene, panel);
        let solution =
            super::solution(scene, panel).map_err(|e| FieldError::Numerical(e.to_string()))?;
        let field = field::evaluate(&solution, &plane, &[quantity], on_row)?;
        let mut values = field.values.index_axis(ndarray::Axis(1), 0).to_owned();
        if panel.method == Method::Difference {
            let exact = super::closed_form(scene, panel).ok_or_else(|| {
                FieldError::Numerical("this contact has no closed form to compare with".into())
            })?;
            let exact = field::evaluate(&exact, &plane, &[quantity], on_row)?;
            values -= &exact.values.index_axis(ndarray::Axis(1), 0);
        }
        // Rounding noise around an exact zero (a free surface, a symmetry plane) would draw
        // a tangle of zero contours: values below 1e-12 of the largest are zero.
        let largest = values
            .iter()
            .filter(|v| v.is_finite())
            .fold(0.0f64, |m, v| m.max(v.abs()));
        values.mapv_inplace(|v| if v.abs() <= 1e-12 * largest { 0.0 } else { v });
        let (traction, half_width_over_a) = surface_line(scene, &plane, &solution);
        let reported = matches!(
            quantity,
            Quantity::VonMises | Quantity::MaxShear | Quantity::Tau1
        );
        let peak_over_p0 = (panel.method == Method::ClosedForm && reported)
            .then(|| refined_peak(&solution, &plane, &values, quantity))
            .flatten();
        // The body's maximum under this panel's contact (its friction and Poisson's ratio),
        // found as the `hertz` report finds it.
        let elsewhere_over_p0 = peak_over_p0.and_then(|[peak, ..]| {
            let extreme = super::assess::maximum(&solution, quantity, false);
            (peak < extreme.value_over_p0 - 1e-4).then_some([
                extreme.value_over_p0,
                extreme.x_over_a,
                extreme.y_over_a,
                extreme.z_over_a,
            ])
        });
        fields.push(PanelField {
            plane,
            values_over_p0: values,
            traction,
            half_width_over_a,
            peak_over_p0,
            elsewhere_over_p0,
        });
    }
    Ok(fields)
}

/// The largest value of `quantity` in `plane`, `[value / p0, u / a, v / a]`: from the
/// largest sample of `values`, a compass search in the plane (the pattern search of
/// Hooke & Jeeves, *J. ACM* 8, 1961, with the step halved down to 1e-9 a), the search that
/// finds the `hertz` report's maxima in the volume ([`super::assess::maximum`]). A section
/// through the report's maximum so marks the report's value at the report's position, where
/// the largest sample would be up to half a grid step off. The search stays in the panel and
/// below the surface; a peak found more than one grid step from its sample (a ridge leading
/// elsewhere) is not used.
pub fn refined_peak(
    solution: &Solution,
    plane: &Plane,
    values: &Array2<f64>,
    quantity: Quantity,
) -> Option<[f64; 3]> {
    let ((iv, iu), _) = values
        .indexed_iter()
        .filter(|(_, v)| v.is_finite())
        .max_by(|a, b| a.1.total_cmp(b.1))?;
    let (du, dv) = (plane.u.step().abs(), plane.v.step().abs());
    if !(du.is_finite() && dv.is_finite() && du > 0.0 && dv > 0.0) {
        return None;
    }
    let depth = !matches!(plane.section, Section::Xy { .. });
    let (u_lo, u_hi) = (plane.u.min.min(plane.u.max), plane.u.min.max(plane.u.max));
    let (mut v_lo, v_hi) = (plane.v.min.min(plane.v.max), plane.v.min.max(plane.v.max));
    if depth {
        v_lo = v_lo.max(0.0);
    }
    let value = |u: f64, v: f64| {
        let (x, y, z) = match plane.section {
            Section::Xz { y } => (u, y, v),
            Section::Yz { x } => (x, u, v),
            Section::Xy { z } => (u, v, z),
        };
        quantity.of(&solution.stress_over_p0(x, y, z))
    };
    let start = (plane.u.value(iu), plane.v.value(iv));
    let at_start = value(start.0, start.1);
    if !at_start.is_finite() {
        return None;
    }
    let ([u, v], best) = super::compass::compass_maximum(
        |[u, v]| value(u, v),
        [start.0, start.1],
        at_start,
        [du, dv],
        [(u_lo, u_hi), (v_lo, v_hi)],
    );
    // A coordinate the search left a hair off zero (a symmetry plane) is zero.
    let snap = |c: f64, d: f64| if c.abs() <= 1e-6 * d { 0.0 } else { c };
    let at = (snap(u, du), snap(v, dv));
    ((at.0 - start.0).abs() <= du && (at.1 - start.1).abs() <= dv).then_some([best, at.0, at.1])
}

/// Where `plane` meets the surface: the tractions along that line and the contact's extent on
/// it (a chord of the contact ellipse for a point or elliptical contact).
fn surface_line(scene: &Scene, plane: &Plane, solution: &Solution) -> (Vec<(f64, f64, f64)>, f64) {
    let aspect = scene.contact.aspect;
    let chord = |offset: f64, along_y: bool| match scene.contact.kind {
        ContactKind::Line => 1.0,
        // Tractions from a file, solved rough contact: no single contact outline.
        ContactKind::Tractions | ContactKind::Rough | ContactKind::Surface => 0.0,
        // The ellipse x² + (y/aspect)² = 1 (a circle for a sphere) cut at y or at x.
        ContactKind::Point | ContactKind::Elliptical if along_y => {
            aspect * (1.0 - offset * offset).max(0.0).sqrt()
        }
        ContactKind::Point | ContactKind::Elliptical => {
            (1.0 - (offset / aspect).powi(2)).max(0.0).sqrt()
        }
    };
    match plane.section {
        Section::Xz { y } => (
            traction_samples(&plane.u, chord(y, false), |x| {
                solution.surface_traction_over_p0(x, y)
            }),
            chord(y, false),
        ),
        Section::Yz { x } => (
            traction_samples(&plane.u, chord(x, true), |y| {
                solution.surface_traction_over_p0(x, y)
            }),
            chord(x, true),
        ),
        Section::Xy { .. } => (Vec::new(), 0.0),
    }
}

/// Samples `(u, p, q)` along a surface line, with the contact edges `u = ±half_width`
/// included exactly so the profile closes on the surface.
fn traction_samples(
    u: &Axis,
    half_width: f64,
    traction: impl Fn(f64) -> (f64, f64),
) -> Vec<(f64, f64, f64)> {
    let mut us: Vec<f64> = Axis::new(u.min, u.max, TRACTION_SAMPLES).values().collect();
    if half_width > 0.0 {
        us.extend(
            [-half_width, half_width]
                .into_iter()
                .filter(|e| *e > u.min && *e < u.max),
        );
    }
    us.sort_by(f64::total_cmp);
    us.into_iter()
        .map(|u| {
            let (p, q) = traction(u);
            (u, p, q)
        })
        .collect()
}

/// The stress tensor (over `p0`) at each of a moving load's material points (the sweep's
/// `material_points`, body frame, in the figure's length unit) under each panel's contact at
/// this step, `[panel][point]`; empty without a sweep or its points. On the surface, on a strip
/// or cell edge, the mean of the neighbours ([`Solution::finite_stress_over_p0`]). Computed
/// here once per step; the recording only plots them.
pub fn material_point_stresses(
    scene: &Scene,
) -> Result<Vec<Vec<crate::stress::Stress>>, FieldError> {
    let Some(sweep) = scene
        .sweep
        .as_ref()
        .filter(|s| !s.material_points.is_empty())
    else {
        return Ok(Vec::new());
    };
    let unit_over_a = scene.length_unit_over_a();
    scene
        .panels
        .iter()
        .map(|panel| {
            let solution =
                super::solution(scene, panel).map_err(|e| FieldError::Numerical(e.to_string()))?;
            let y = match panel.section {
                crate::scene::SectionKind::Xz => panel.at * unit_over_a,
                _ => 0.0,
            };
            Ok(sweep
                .material_points
                .iter()
                .map(|&(x, z)| solution.finite_stress_over_p0(x * unit_over_a, y, z * unit_over_a))
                .collect())
        })
        .collect()
}

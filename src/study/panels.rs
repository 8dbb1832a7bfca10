//! The fields a figure's panels draw, computed once here: each panel's stress solution
//! evaluated on its grid plane (the numerical minus the closed form for a difference panel),
//! and the tractions along the line where the plane meets the surface. In units of `a` and
//! `p0`; the figure ([`crate::figure::build`]) converts them to its display units and draws.

use ndarray::Array2;

use crate::field::{self, Axis, FieldError, Plane, Section};
use crate::scene::{ContactKind, Method, Scene};
use crate::solution::Solution;

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
        fields.push(PanelField {
            plane,
            values_over_p0: values,
            traction,
            half_width_over_a,
        });
    }
    Ok(fields)
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

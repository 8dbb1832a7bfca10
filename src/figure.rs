//! From a scene to a drawable figure: evaluates each panel's field on the grid and converts
//! everything to the figure's display units.

use crate::field::{self, Axis, FieldError};
use crate::render::{Figure, Mark, Panel, TractionSample};
use crate::scene::{ContactKind, LengthUnit, PanelSpec, Scene, StressUnit};

/// Number of samples of the traction profile across the figure.
const TRACTION_SAMPLES: usize = 601;

/// Evaluates every panel of `scene` (in parallel within each panel) and assembles the figure.
/// `on_row` is called once per evaluated grid row, for progress reporting.
pub fn build(scene: &Scene, on_row: &(dyn Fn() + Sync)) -> Result<Figure, FieldError> {
    let spec = &scene.figure;
    let plane = scene.plane();
    let a_m = scene.contact.half_width_m();
    let p0_pa = scene.contact.p0_pa();
    let length_per_a = a_m / spec.length_unit.metres(a_m);
    let stress_per_p0 = p0_pa / spec.stress_unit.pascals(p0_pa);
    let to_display =
        |axis: Axis| Axis::new(axis.min * length_per_a, axis.max * length_per_a, axis.count);

    let mut panels = Vec::with_capacity(scene.panels.len());
    for panel in &scene.panels {
        let solution = scene.solution(panel);
        let field = field::evaluate(&solution, &plane, &[spec.quantity], on_row)?;
        let values = field
            .values
            .index_axis(ndarray::Axis(1), 0)
            .mapv(|v| v * stress_per_p0);
        let traction = traction_samples(&plane.u, |x| solution.surface_traction_over_p0(x))
            .map(|(x, p, q)| TractionSample {
                x: x * length_per_a,
                p: p * stress_per_p0,
                q: q * stress_per_p0,
            })
            .collect();
        panels.push(Panel {
            subtitle: subtitle(scene, panel),
            x: to_display(plane.u),
            z: to_display(plane.v),
            values,
            traction,
            half_width: length_per_a,
        });
    }
    let mark = spec.mark.unwrap_or_else(|| auto_mark(&panels));
    let any_friction = scene.panels.iter().any(|p| p.friction != 0.0);
    Ok(Figure {
        title: title(scene),
        panels,
        value_label: spec.stress_unit.label(spec.quantity.symbol()),
        x_label: spec.length_unit.axis_label("x"),
        z_label: spec.length_unit.axis_label("z"),
        traction_label: spec
            .stress_unit
            .label(if any_friction { "p, q" } else { "p" }),
        colormap: spec.colormap,
        levels: spec.levels.clone(),
        mark,
        panel_width_px: spec.width_px,
    })
}

/// The extremes worth marking: those whose size is at least 5 % of the larger one (so an
/// all-compressive map marks its minimum only, and σxx under friction both its tension peak and
/// its compression peak).
pub fn auto_mark(panels: &[Panel]) -> Mark {
    let values = panels
        .iter()
        .flat_map(|p| p.values.iter().copied())
        .filter(|v| v.is_finite());
    let (lo, hi) = values.fold((0.0f64, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    let size = hi.max(-lo);
    match (
        hi >= 0.05 * size && hi > 0.0,
        -lo >= 0.05 * size && lo < 0.0,
    ) {
        (true, true) => Mark::Both,
        (false, true) => Mark::Min,
        (true, false) => Mark::Max,
        (false, false) => Mark::None,
    }
}

/// Samples `(x, p, q)` across the axis, with the contact edges `x = ±1` included exactly so the
/// profile closes on the surface.
fn traction_samples(
    x: &Axis,
    traction: impl Fn(f64) -> (f64, f64),
) -> impl Iterator<Item = (f64, f64, f64)> {
    let mut xs: Vec<f64> = Axis::new(x.min, x.max, TRACTION_SAMPLES).values().collect();
    xs.extend([-1.0, 1.0].into_iter().filter(|e| *e > x.min && *e < x.max));
    xs.sort_by(f64::total_cmp);
    xs.into_iter().map(move |x| {
        let (p, q) = traction(x);
        (x, p, q)
    })
}

fn title(scene: &Scene) -> String {
    if let Some(title) = &scene.title {
        return title.clone();
    }
    let quantity = scene.figure.quantity.description();
    let mut title = format!("{}{}", quantity[..1].to_uppercase(), &quantity[1..]);
    match scene.contact.kind {
        ContactKind::Line => title.push_str(" — Hertz line contact"),
    }
    title
}

/// The panel caption: friction and Poisson ratio, and for dimensional scenes a and p0.
fn subtitle(scene: &Scene, panel: &PanelSpec) -> String {
    if let Some(subtitle) = &panel.subtitle {
        return subtitle.clone();
    }
    let mut parts = vec![
        format!("μ = {}", panel.friction),
        format!("ν = {}", panel.poisson),
    ];
    if let Some(scale) = scene.contact.scale {
        let a = scale.half_width_m;
        let a_text = match scene.figure.length_unit {
            LengthUnit::Micrometre | LengthUnit::HalfWidth => format!("a = {:.1} µm", a * 1e6),
            LengthUnit::Millimetre => format!("a = {:.4} mm", a * 1e3),
            LengthUnit::Metre => format!("a = {a:.3e} m"),
        };
        parts.push(a_text);
        let p0 = scale.p0_pa;
        parts.push(match scene.figure.stress_unit {
            StressUnit::GigaPascal => format!("p0 = {:.3} GPa", p0 * 1e-9),
            _ => format!("p0 = {:.0} MPa", p0 * 1e-6),
        });
    }
    parts.join(",  ")
}

#[cfg(test)]
mod tests {
    use super::*;
    use ndarray::Array2;

    fn panel(values: &[f64]) -> Panel {
        Panel {
            subtitle: String::new(),
            x: Axis::new(0.0, 1.0, values.len()),
            z: Axis::new(0.0, 1.0, 2),
            values: Array2::from_shape_fn((2, values.len()), |(_, i)| values[i]),
            traction: Vec::new(),
            half_width: 1.0,
        }
    }

    #[test]
    fn auto_mark_picks_the_meaningful_extremes() {
        assert_eq!(auto_mark(&[panel(&[0.0, 0.3, 0.1])]), Mark::Max);
        assert_eq!(auto_mark(&[panel(&[-1.2, -0.4, 0.0])]), Mark::Min);
        assert_eq!(
            auto_mark(&[panel(&[-1.2, 0.0]), panel(&[0.0, 0.6])]),
            Mark::Both
        );
        assert_eq!(auto_mark(&[panel(&[-1.0, 0.01])]), Mark::Min);
        assert_eq!(auto_mark(&[panel(&[0.0, 0.0])]), Mark::None);
    }
}

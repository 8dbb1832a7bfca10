//! From a scene's computed fields to a drawable figure: the panels' fields (computed once by
//! [`crate::study::panels`]) converted to the figure's display units, with titles, traction
//! profiles, outlines and marks.
//!
//! Uses: [`crate::study`] (what is computed), [`crate::field`], [`crate::render`] (the
//! figure and sheet types), [`crate::report`] (the tables of a sheet), [`crate::io`].

pub mod coated;
pub mod ehl;
pub mod plastic;
pub mod rough;
pub mod surface;
pub mod thermal;
pub mod wear;

use crate::field::{FieldError, Plane, Section};
use crate::io::text;
use crate::render::{ColorMap, Figure, Levels, Mark, Panel, PanelAxes, PanelScale, TractionSample};
use crate::scene::{ContactKind, LengthUnit, Method, PanelSpec, Scene, SectionKind, StressUnit};
use crate::study;

/// Number of segments of the contact circle drawn on planes parallel to the surface.
const OUTLINE_SEGMENTS: usize = 256;

/// What a scene draws: a figure of stress maps, or a sheet of maps and charts (surface and
/// rough scenes).
#[derive(Clone, Debug)]
pub enum Drawing {
    Figure(Figure),
    Sheet(crate::render::chart::Sheet),
}

impl Drawing {
    pub fn png(&self) -> Result<image::RgbImage, crate::render::RenderError> {
        match self {
            Drawing::Figure(figure) => crate::render::render_png(figure),
            Drawing::Sheet(sheet) => crate::render::chart::sheet_png(sheet),
        }
    }

    pub fn svg(&self) -> Result<String, crate::render::RenderError> {
        match self {
            Drawing::Figure(figure) => crate::render::render_svg(figure),
            Drawing::Sheet(sheet) => crate::render::chart::sheet_svg(sheet),
        }
    }
}

/// Why a scene cannot be drawn.
#[derive(Debug, thiserror::Error)]
pub enum DrawError {
    #[error(transparent)]
    Field(#[from] FieldError),
    #[error(transparent)]
    Sheet(#[from] crate::figure::rough::SheetError),
    #[error(transparent)]
    Inputs(#[from] study::drawing::DrawingError),
    #[error(
        "the drawing's inputs are not this scene's kind: compute them with study::drawing::inputs"
    )]
    Mismatch,
}

/// Draws any scene from what the study computed for it ([`study::drawing::inputs`]): a
/// figure ([`build`]), a coated body's section, or the sheet of a surface or rough scene (a
/// rough scene's contact as solved, `rough`). Computes nothing itself.
pub fn draw(
    scene: &Scene,
    rough: Option<&crate::contact::rough::RoughSolution>,
    inputs: &study::drawing::DrawingInputs,
) -> Result<Drawing, DrawError> {
    use study::drawing::DrawingInputs;
    Ok(match inputs {
        DrawingInputs::Coated(study) => {
            Drawing::Figure(crate::figure::coated::coated_figure(scene, study))
        }
        DrawingInputs::Rough { fields, .. } => {
            let solution = rough.ok_or(study::drawing::DrawingError::Unsolved)?;
            Drawing::Sheet(crate::figure::rough::rough_sheet(scene, solution, fields)?)
        }
        DrawingInputs::Surface(characterisation) => Drawing::Sheet(
            crate::figure::surface::surface_sheet(scene, characterisation)?,
        ),
        DrawingInputs::Panels(fields) => {
            if matches!(
                scene.contact.kind,
                ContactKind::Rough | ContactKind::Surface
            ) {
                return Err(DrawError::Mismatch);
            }
            Drawing::Figure(build(scene, fields))
        }
    })
}

/// Computes what `scene`'s drawing needs ([`study::drawing::inputs`]) and draws it: for the
/// callers that compute and draw in one step (the `render` command, the tests).
pub fn compute_and_draw(
    scene: &Scene,
    rough: Option<&crate::contact::rough::RoughSolution>,
    on_row: &(dyn Fn() + Sync),
) -> Result<Drawing, DrawError> {
    let inputs = study::drawing::inputs(scene, rough, on_row)?;
    draw(scene, rough, &inputs)
}

/// Assembles the figure of `scene` from its panels' fields (computed by
/// [`study::panel_fields`]), in the figure's display units.
pub fn build(scene: &Scene, fields: &[study::panels::PanelField]) -> Figure {
    let spec = &scene.figure;
    let units = study::DisplayUnits::of(scene);
    let (length_per_a, stress_per_p0) = (units.length_per_a, units.stress_per_p0);
    // The figure's axes are the first panel's; a panel in another plane brings its own.
    let first_section = scene.panels.first().map_or(spec.section, |p| p.section);

    let mut panels = Vec::with_capacity(scene.panels.len());
    for (panel, computed) in scene.panels.iter().zip(fields) {
        let plane = &computed.plane;
        let values = computed.values_over_p0.mapv(|v| v * stress_per_p0);
        let (traction, half_width_over_a) = (&computed.traction, computed.half_width_over_a);
        let outlines = match plane.section {
            Section::Xz { .. } | Section::Yz { .. } => Vec::new(),
            Section::Xy { .. } => {
                let aspect = scene.contact.aspect;
                let mut lines = vec![contact_outline(scene.contact.kind, aspect)];
                // Partial slip: the stick circle c = a (1 - Q/(mu P))^(1/3) too.
                if let Some(ratio) = scene.contact.tangential {
                    let c = (1.0 - ratio).cbrt();
                    if c > 0.0 {
                        let circle = contact_outline(ContactKind::Point, 1.0);
                        lines.push(circle.into_iter().map(|(x, y)| (c * x, c * y)).collect());
                    }
                }
                lines
            }
        };
        let clip = clipped_range(&values);
        let (x, z) = (units.axis(plane.u), units.axis(plane.v));
        let mut subtitle = subtitle(scene, panel, plane);
        // A difference's colours span the bulk of it, not its spikes: say how far (the bar's
        // triangles show that values go beyond, the marked extremes how far).
        if let (Method::Difference, Some((_, limit))) = (panel.method, clip) {
            subtitle.push_str(&format!(
                "{}colours ±{} {} (98 %)",
                if panel.subtitle.is_some() { "; " } else { ", " },
                text::significant(limit, 2, 1e5, true),
                spec.stress_unit.symbol(),
            ));
        }
        // A section that misses the body's maximum (the `hertz` report's) says where it is:
        // `body's max 1671 MPa at x = 0.026, z = 0.110 mm`, `… at x = 0.319a, y = ±0.2a, …`.
        if let Some([value, x, y, z]) = computed.elsewhere_over_p0 {
            let unit = spec.length_unit.suffix();
            let each = unit == "a";
            let at = |c: f64, last: bool| {
                if c.abs() <= 1e-6 {
                    return "0".to_string();
                }
                let number = text::fixed(c * length_per_a, 3);
                if each || last {
                    format!("{number}{unit}")
                } else {
                    number
                }
            };
            let y = match scene.contact.kind {
                ContactKind::Line => String::new(),
                _ if y.abs() <= 1e-6 => String::new(),
                _ => format!("y = ±{}, ", at(y, false)),
            };
            subtitle.push_str(&format!(
                "; body's max {} {} at x = {}, {y}z = {}",
                text::significant(value * stress_per_p0, 3, 1e5, false),
                spec.stress_unit.symbol(),
                at(x, false),
                at(z, true)
            ));
        }
        let mut outlines = outlines;
        // First yield: the line where the drawn stress reaches it, dashed, with the region
        // inside named; or that the section stays below it.
        let per_pa = scene
            .contact
            .scale
            .map_or(f64::NAN, |s| stress_per_p0 / s.p0_pa);
        if let (Some(level), false) = (
            yield_level(scene, per_pa),
            panel.method == Method::Difference,
        ) {
            let (lines, note) = level.mark(spec.quantity, &values, &x, &z);
            outlines.extend(lines.into_iter().map(|line| {
                line.into_iter()
                    .map(|(u, v)| (u / length_per_a, v / length_per_a))
                    .collect()
            }));
            subtitle.push_str(&format!("; {note}"));
        }
        panels.push(Panel {
            subtitle,
            x,
            z,
            values,
            traction: traction
                .iter()
                .map(|&(u, p, q)| TractionSample {
                    x: u * length_per_a,
                    p: p * stress_per_p0,
                    q: q * stress_per_p0,
                })
                .collect(),
            half_width: half_width_over_a * length_per_a,
            outlines: outlines
                .into_iter()
                .map(|line| {
                    line.into_iter()
                        .map(|(u, v)| (u * length_per_a, v * length_per_a))
                        .collect()
                })
                .collect(),
            // A difference is far smaller than the field: its own diverging scale.
            scale: (panel.method == Method::Difference).then(|| PanelScale {
                value_label: spec
                    .stress_unit
                    .label(&format!("Δ{}", spec.quantity.symbol())),
                colormap: ColorMap::Diverging,
                levels: Levels::Count(8),
                range: clip,
            }),
            peak: computed
                .peak_over_p0
                .map(|[value, u, v]| crate::render::Peak {
                    value: value * stress_per_p0,
                    x: u * length_per_a,
                    z: v * length_per_a,
                }),
            // A panel cut in another plane than the first keeps the colour scale, with its own
            // axes.
            axes: (panel.section != first_section).then(|| axes(spec.length_unit, panel.section)),
        });
    }
    let mark = spec.mark.unwrap_or_else(|| auto_mark(&panels));
    let any_friction = panels.iter().flat_map(|p| &p.traction).any(|s| s.q != 0.0);
    let PanelAxes {
        x_label,
        z_label,
        vertical_is_depth,
    } = axes(spec.length_unit, first_section);
    Figure {
        title: title(scene),
        panels,
        value_label: spec.stress_unit.label(spec.quantity.symbol()),
        x_label,
        z_label,
        vertical_is_depth,
        traction_label: spec
            .stress_unit
            .label(if any_friction { "p, q" } else { "p" }),
        colormap: spec.colormap,
        levels: spec.levels.clone(),
        mark,
        panel_width_px: spec.width_px,
    }
}

/// The axes of a section drawn in `unit`: `x/a` and `z/a` (depth down) for xz, `y/a` and
/// `z/a` for yz, `x/a` and `y/a` (y up) for xy.
fn axes(unit: LengthUnit, section: SectionKind) -> PanelAxes {
    let (horizontal, vertical, _) = section.coordinates();
    PanelAxes {
        x_label: unit.axis_label(horizontal),
        z_label: unit.axis_label(vertical),
        vertical_is_depth: section.vertical_is_depth(),
    }
}

/// Where the figure's quantity reaches first yield, in the figure's stress unit: von Mises at
/// the yield strength Y, the Tresca shear `(σ1 − σ3)/2` at `Y/2` (the criteria of the `hertz`
/// report's yield check; e.g. Johnson 1985, §6.2).
pub(crate) struct YieldLevel {
    value: f64,
    /// `Y = 1500 MPa`, `Y/2 = 750 MPa`.
    text: String,
}

/// The yield level of `scene`'s figure quantity, values being `stress_per_pa` display units
/// per Pa; `None` without a yield strength (or hardness) or for another quantity.
pub(crate) fn yield_level(scene: &Scene, stress_per_pa: f64) -> Option<YieldLevel> {
    use crate::stress::Quantity;
    let y = scene.yield_strength()?;
    let (factor, name) = match scene.figure.quantity {
        Quantity::VonMises => (1.0, "Y"),
        Quantity::MaxShear => (0.5, "Y/2"),
        _ => return None,
    };
    let value = factor * y.pa * stress_per_pa;
    value.is_finite().then(|| YieldLevel {
        value,
        // In whole MPa, as the `hertz` report writes Y.
        text: format!("{name} = {:.0} MPa", factor * y.pa * 1e-6),
    })
}

impl YieldLevel {
    /// The top of a robust colour range (`top`, the quantile) of a field whose largest value is
    /// `largest`, that does not hide this level: where the field reaches it, the top rises to
    /// a quarter beyond the level (or to the largest value, if lower), so that the level's
    /// line lies inside the colours and the region beyond it shows. Returns the top and
    /// whether values lie above it.
    pub(crate) fn colour_top(&self, top: f64, largest: f64) -> (f64, bool) {
        let top = if largest >= self.value {
            top.max(largest.min(1.25 * self.value))
        } else {
            top
        };
        (top, top < largest)
    }

    /// The lines where `values` (over `x`, `z`, display units) reach the level, and the
    /// caption's note: `dashed: σvM = Y = 1500 MPa, yielding inside`, or, when the map stays
    /// below, `σvM < Y = 1800 MPa here (max 0.925 of it)`.
    pub(crate) fn mark(
        &self,
        quantity: crate::stress::Quantity,
        values: &ndarray::Array2<f64>,
        x: &crate::field::Axis,
        z: &crate::field::Axis,
    ) -> (Vec<Vec<(f64, f64)>>, String) {
        let largest = values
            .iter()
            .copied()
            .filter(|v| v.is_finite())
            .fold(f64::NEG_INFINITY, f64::max);
        let symbol = quantity.symbol();
        if largest >= self.value {
            (
                crate::render::contour_lines(values.view(), x, z, self.value),
                format!("dashed: {symbol} = {}, yielding inside", self.text),
            )
        } else {
            (
                Vec::new(),
                format!(
                    "{symbol} < {} here (max {} of it)",
                    self.text,
                    text::approx((largest / self.value * 1e3).round() / 1e3)
                ),
            )
        }
    }
}

/// The colour range of a difference map: `±` the 98th percentile of `|Δ|`, so that the
/// spikes of the stepped tractions at the surface and the contact edges (a few cells) do not
/// wash out the error below them; those take the end colours. `None` for an all-zero map.
fn clipped_range(values: &ndarray::Array2<f64>) -> Option<(f64, f64)> {
    let mut sizes: Vec<f64> = values
        .iter()
        .filter(|v| v.is_finite())
        .map(|v| v.abs())
        .collect();
    if sizes.is_empty() {
        return None;
    }
    sizes.sort_by(f64::total_cmp);
    let index = ((sizes.len() - 1) as f64 * 0.98).round() as usize;
    let limit = sizes[index];
    (limit > 0.0).then_some((-limit, limit))
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

/// The contact's outline on a plane parallel to the surface, in units of a: the circle
/// `r = a` of a point contact or the ellipse with semi-axes 1 and `aspect` of an elliptical one.
fn contact_outline(kind: ContactKind, aspect: f64) -> Vec<(f64, f64)> {
    match kind {
        ContactKind::Point | ContactKind::Elliptical => (0..=OUTLINE_SEGMENTS)
            .map(|i| {
                let angle = std::f64::consts::TAU * i as f64 / OUTLINE_SEGMENTS as f64;
                (angle.cos(), aspect * angle.sin())
            })
            .collect(),
        // A line contact has only xz sections; a traction file has no known outline.
        ContactKind::Line | ContactKind::Tractions | ContactKind::Rough | ContactKind::Surface => {
            Vec::new()
        }
    }
}

/// Which plane a panel shows, for point contacts (a line contact is the same in every xz
/// plane, so its panels need no such label): e.g. "xz plane, y = 0.5a" or "surface z = 0".
fn section_label(scene: &Scene, panel: &PanelSpec, plane: &Plane) -> Option<String> {
    if scene.contact.kind == ContactKind::Line {
        return None;
    }
    let section = panel.section;
    let (_, _, normal) = section.coordinates();
    // The plane's own position (a numerical panel lies on the nearest row of cell centres).
    let at_over_a = match plane.section {
        Section::Xz { y } => y,
        Section::Yz { x } => x,
        Section::Xy { z } => z,
    };
    let at = at_over_a / scene.length_unit_over_a();
    // A row of cell centres through the axis may miss 0 by a rounding error.
    let at = if at.abs() < 1e-12 { 0.0 } else { at };
    let value = match scene.figure.length_unit {
        _ if at == 0.0 => "0".to_string(),
        LengthUnit::HalfWidth => format!("{}a", trim(at)),
        LengthUnit::Millimetre => format!("{} mm", trim(at)),
        LengthUnit::Micrometre => format!("{} µm", trim(at)),
        LengthUnit::Metre => format!("{at:e} m"),
    };
    Some(match section {
        SectionKind::Xy if at == 0.0 => "surface z = 0".to_string(),
        _ => format!("{} plane, {normal} = {value}", section.key()),
    })
}

/// A short decimal: at most four decimals, trailing zeros dropped.
fn trim(value: f64) -> String {
    let text = format!("{value:.4}");
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

fn title(scene: &Scene) -> String {
    if let Some(title) = &scene.title {
        return title.clone();
    }
    let quantity = scene.figure.quantity.description();
    let mut title = format!("{}{}", quantity[..1].to_uppercase(), &quantity[1..]);
    match scene.contact.kind {
        ContactKind::Line => title.push_str(" — Hertz line contact"),
        ContactKind::Point if scene.contact.tangential.is_some() => {
            title.push_str(" — sphere in partial slip (Cattaneo–Mindlin)")
        }
        ContactKind::Point => title.push_str(" — Hertz point contact (sphere)"),
        ContactKind::Elliptical => title.push_str(" — elliptical Hertz contact"),
        ContactKind::Tractions => title.push_str(" — surface tractions from a file"),
        ContactKind::Rough => title.push_str(" — rough contact"),
        ContactKind::Surface => title.push_str(" — rough surface"),
    }
    title
}

/// The panel caption: the method when the figure uses more than one, the section, friction
/// and Poisson ratio, and for dimensional scenes a and p0.
fn subtitle(scene: &Scene, panel: &PanelSpec, plane: &Plane) -> String {
    if let Some(subtitle) = &panel.subtitle {
        return subtitle.clone();
    }
    let mixed = scene.panels.iter().any(|p| p.method != panel.method);
    let mut parts: Vec<String> = Vec::new();
    let cells = scene.numerical.cells;
    match (panel.method, scene.contact.kind) {
        (Method::ClosedForm, _) if mixed => parts.push("closed form".into()),
        (Method::ClosedForm, _) => {}
        (Method::Numerical, ContactKind::Line) => parts.push(format!("numerical, {cells} strips")),
        (Method::Numerical, ContactKind::Point | ContactKind::Elliptical) => {
            parts.push(format!("numerical, {cells}² cells"))
        }
        (Method::Numerical, ContactKind::Rough | ContactKind::Surface) => {
            parts.push("numerical, on the surface's grid".into())
        }
        (Method::Numerical, ContactKind::Tractions) => {
            if let Some(grid) = &scene.tractions {
                let [ny, nx] = grid.shape();
                parts.push(format!("numerical, {nx} x {ny} cells"));
            }
        }
        (Method::Difference, _) => parts.push("numerical − closed form".into()),
    }
    parts.extend(section_label(scene, panel, plane));
    // Tractions from a file carry their own shear, and a and p0 are only the figure's units.
    let from_file = scene.contact.kind == ContactKind::Tractions;
    if !from_file {
        parts.push(format!("μ = {}", text::number(panel.friction)));
    }
    parts.push(format!("ν = {}", text::number(panel.poisson)));
    if let (Some(scale), false) = (scene.contact.scale, from_file) {
        let a = scale.half_width_m;
        let a_text = match scene.figure.length_unit {
            LengthUnit::Micrometre | LengthUnit::HalfWidth => {
                format!("a = {} µm", text::fixed(a * 1e6, 1))
            }
            LengthUnit::Millimetre => format!("a = {} mm", text::fixed(a * 1e3, 4)),
            LengthUnit::Metre => format!("a = {a:.3e} m"),
        };
        parts.push(a_text);
        let p0 = scale.p0_pa;
        parts.push(match scene.figure.stress_unit {
            StressUnit::GigaPascal => format!("p0 = {} GPa", text::fixed(p0 * 1e-9, 3)),
            _ => format!("p0 = {} MPa", text::fixed(p0 * 1e-6, 0)),
        });
    }
    parts.join(",  ")
}

/// One extreme of a map: its value and position (figure units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Extreme {
    pub value: f64,
    pub u: f64,
    pub v: f64,
}

/// The extremes the figure marks (its [`Mark`]), as the PNG marks them and the recordings and sweep tables chart them: the largest (its [`Panel::peak`] where the
/// study located it between the samples) and/or the smallest finite value.
pub fn extremes(panel: &Panel, mark: Mark) -> (Option<Extreme>, Option<Extreme>) {
    let finite = || panel.values.indexed_iter().filter(|(_, v)| v.is_finite());
    let at = |((row, column), &value): ((usize, usize), &f64)| Extreme {
        value,
        u: panel.x.value(column),
        v: panel.z.value(row),
    };
    // The maximum the study located between the samples, as the PNG figure marks it.
    let largest = match panel.peak {
        Some(peak) => Some(Extreme {
            value: peak.value,
            u: peak.x,
            v: peak.z,
        }),
        None => finite().max_by(|a, b| a.1.total_cmp(b.1)).map(at),
    };
    let smallest = finite().min_by(|a, b| a.1.total_cmp(b.1)).map(at);
    match mark {
        Mark::Max => (largest, None),
        Mark::Min => (None, smallest),
        Mark::Both => (largest, smallest),
        Mark::None => (None, None),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::Axis;
    use ndarray::Array2;

    fn panel(values: &[f64]) -> Panel {
        Panel {
            subtitle: String::new(),
            x: Axis::new(0.0, 1.0, values.len()),
            z: Axis::new(0.0, 1.0, 2),
            values: Array2::from_shape_fn((2, values.len()), |(_, i)| values[i]),
            traction: Vec::new(),
            half_width: 1.0,
            outlines: Vec::new(),
            scale: None,
            peak: None,
            axes: None,
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

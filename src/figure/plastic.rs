//! The sheet of an elastic-plastic point contact (`[plasticity]`), in the spirit of Johnson,
//! *Contact Mechanics* (1985), ch. 6, on axes normalised by Hertz's contact radius `a_H` and
//! the yield strength `Y`:
//!
//! - the pressure at full load on `y = 0` beside Hertz's elastic pressure;
//! - the load against the approach, loading and unloading step by step, beside Hertz's
//!   elastic curve `δ = (9 W² / (16 R E*²))^(1/3)` (Johnson 1985 §4.2), both over the load
//!   `W_Y` and approach `δ_Y` of first yield (Hertz's `p0 = Y / (σvM,max/p0)`, Hamilton's
//!   closed form's axis maximum, 0.620 for ν = 0.3: Johnson §6.2);
//! - the mean pressure `p_m / Y` against `E* a / (Y R)` over the load steps (`a = √(A/π)` of
//!   each step's contact area), with Hertz's elastic line `p_m / Y = (4 / 3π) E* a / (Y R)`,
//!   the expanding-cavity model `p_m / Y = (2/3)(1 + ln(E a / (3 Y R)))` (Johnson 1985 §6.3,
//!   Johnson's cavity model with `tan β` of a cone replaced by `a / R` of a sphere; `E` is
//!   body 1's Young's modulus) and Tabor's fully plastic `p_m ≈ 3 Y` (Tabor 1951);
//! - in the section `y = 0` (depth drawn downwards): the equivalent plastic strain at full
//!   load with the plastic zone's boundary (`εp = 1e-5`), von Mises of the total stress at
//!   full load with the yield line (`σvM = Y + h εp`), and after unloading von Mises of the
//!   residual stress, its `σxx` (on `y = 0` the radial stress) and `σyy` (the hoop stress),
//!   each with the plastic zone outlined.
//!
//! A line contact (plane strain) draws the same sheet on axes over Hertz's half-width `b`:
//! the pressure beside Hertz's line `p0 √(1 - x²/b²)`; the load per unit length against the
//! approach (of the points at the grid's depth below each surface, as the study reports it)
//! beside the elastic line contact's ([`crate::study::plastic::history::elastic_approach_m`])
//! over first yield's (`p0 = Y / 0.5575` for ν = 0.3, McEwen's axis maximum); the residual
//! `σyy` is the out-of-plane stress. It has no mean-pressure panel: Johnson's cavity model and
//! Tabor's 3 Y are results of axisymmetric indentation, and the plane-strain limit (Prandtl's
//! `(2 + π) k` of a flat punch) is not that of a cylinder at small strains, so the panel would
//! have no reference to read the steps against.
//!
//! Draws what [`crate::study::plastic`] computed; solves nothing.
//!
//! ## References
//! - K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §4.2, §6.2, §6.3.
//! - D. Tabor, *The Hardness of Metals*, Clarendon Press, Oxford (1951).

use ndarray::Array2;

use crate::field::Axis;
use crate::plasticity::loading::PLASTIC_ZONE_STRAIN;
use crate::render::chart::{Cell, Chart, Scale, Series, Sheet, Style, PALETTE};
use crate::render::{
    contour_lines, ColorMap, Figure, Levels, Mark, Panel, PanelScale, TractionSample,
};
use crate::study::plastic::history::{elastic_approach_m, first_yield, SheetSections};
use crate::study::plastic::{PlasticKind, PlasticStudy};

const MAP_WIDTH: u32 = 380;
const CHART_WIDTH: u32 = 520;
const GREY: [u8; 3] = [90, 90, 90];
const RED: [u8; 3] = [214, 39, 40];
/// The fraction of the current yield stress at which the yield line is drawn: the plastic
/// cells sit on the yield surface to the solver's tolerance, so a line at exactly 1 would
/// wander through them; 0.995 follows the zone's edge from the elastic side.
pub const YIELD_LINE_FRACTION: f64 = 0.995;

/// The length the axes are measured in: Hertz's contact radius `a_H`, a line's half-width `b`.
pub fn length_unit(study: &PlasticStudy) -> &'static str {
    if study.kind == PlasticKind::Line {
        "b"
    } else {
        "a_H"
    }
}

/// The sections' axes over `a_H` (a line's `b`): cell centres along x and in depth.
pub fn axes(study: &PlasticStudy) -> (Axis, Axis) {
    let a = study.hertz.size_m();
    let (x, z) = (&study.x_m, &study.z_m);
    (
        Axis::new(x[0] / a, x[x.len() - 1] / a, x.len()),
        Axis::new(z[0] / a, z[z.len() - 1] / a, z.len()),
    )
}

/// The isolines of `values` at `level` as outlines (over `a_H`).
pub fn outline(values: &Array2<f64>, x: &Axis, z: &Axis, level: f64) -> Vec<Vec<(f64, f64)>> {
    contour_lines(values.view(), x, z, level)
}

/// One map of the section.
#[allow(clippy::too_many_arguments)]
fn map(
    study: &PlasticStudy,
    title: &str,
    subtitle: String,
    values: Array2<f64>,
    scale: PanelScale,
    outlines: Vec<Vec<(f64, f64)>>,
    traction: Vec<TractionSample>,
    mark: Mark,
) -> Figure {
    let (x, z) = axes(study);
    let half_width = study.loaded.contact_radius_m / study.hertz.size_m();
    let unit = length_unit(study);
    Figure {
        title: title.into(),
        panels: vec![Panel {
            subtitle,
            x,
            z,
            values,
            traction,
            half_width,
            outlines,
            scale: Some(scale.clone()),
            peak: None,
            axes: None,
        }],
        value_label: scale.value_label,
        x_label: format!("x/{unit}"),
        z_label: format!("z/{unit}"),
        vertical_is_depth: true,
        traction_label: "p/Y".into(),
        colormap: scale.colormap,
        levels: scale.levels,
        mark,
        panel_width_px: MAP_WIDTH,
    }
}

/// The largest magnitude of `values`, for a diverging scale centred on zero.
fn magnitude(values: &Array2<f64>) -> f64 {
    values
        .iter()
        .fold(0.0, |m: f64, v| m.max(v.abs()))
        .max(1e-12)
}

/// The pressure on `y = 0` (`pressure_pa` along x) beside Hertz's at the full load.
pub fn pressure_chart(study: &PlasticStudy, pressure_pa: &[f64], title: &str) -> Chart {
    let y = study.spec.yield_strength_pa;
    let hertz = &study.hertz;
    let a = hertz.size_m();
    let (x_axis, _) = axes(study);
    let p0_over_y = hertz.p0_pa() / y;
    let largest = pressure_pa.iter().fold(0.0, |m: f64, &p| m.max(p));
    let mut pressure = Chart::new(title, &format!("x/{}", length_unit(study)), "p/Y");
    pressure.width_px = CHART_WIDTH;
    pressure.x_range = Some((x_axis.min, x_axis.max));
    let top = p0_over_y.max(study.loaded.max_pressure_pa / y);
    pressure.y_range = Some((0.0, 1.45 * top));
    pressure.series.push(Series {
        label: format!("elastic-plastic, max {:.2} Y", largest / y),
        points: study
            .x_m
            .iter()
            .zip(pressure_pa)
            .map(|(&x, &p)| (x / a, p / y))
            .collect(),
        style: Style::Line,
        colour: PALETTE[0],
    });
    let samples = 241;
    pressure.series.push(Series {
        label: format!("Hertz (elastic) at full load, p0 = {p0_over_y:.2} Y"),
        points: (0..samples)
            .map(|k| {
                let x = x_axis.min + (x_axis.max - x_axis.min) * k as f64 / (samples - 1) as f64;
                (x, p0_over_y * (1.0 - x * x).max(0.0).sqrt())
            })
            .collect(),
        style: Style::Dashed,
        colour: GREY,
    });
    pressure
}

/// The load against the approach over first yield's (module doc), the first `shown` steps
/// drawn, on the axes of all of them.
pub fn load_approach_chart(study: &PlasticStudy, shown: usize) -> Chart {
    let (load_y, approach_y) = first_yield(study);
    let points = &study.history.points;
    let at = |point: &crate::study::plastic::history::StepPoint| {
        // Lifted off: the indenter leaves the dent (the permanent displacement on the axis).
        let approach = point.approach_m.unwrap_or(point.axis_displacement_m);
        (approach / approach_y, point.load_n / load_y)
    };
    let mut loading = vec![(0.0, 0.0)];
    let mut unloading = Vec::new();
    for (k, point) in points.iter().enumerate().take(shown) {
        if point.unloading {
            if unloading.is_empty() && k > 0 {
                unloading.push(at(&points[k - 1]));
            }
            unloading.push(at(point));
        } else {
            loading.push(at(point));
        }
    }
    let mut curve = Chart::new(
        "Load against approach",
        if study.kind == PlasticKind::Line {
            "δ/δ_Y (approach to the grid's depth over first yield's)"
        } else {
            "δ/δ_Y (approach over first yield's)"
        },
        "W/W_Y",
    );
    curve.width_px = CHART_WIDTH;
    let largest_load = points.iter().fold(0.0, |m: f64, p| m.max(p.load_n)) / load_y;
    let largest_approach = points.iter().map(at).fold(1.0, |m: f64, p| m.max(p.0));
    curve.x_range = Some((0.0, 1.1 * largest_approach));
    curve.y_range = Some((0.0, 1.35 * largest_load.max(1.0)));
    // Hertz's elastic curve, sampled in the load up to the chart's top.
    let load_top = 1.35 * largest_load.max(1.0) * load_y;
    curve.series.push(Series {
        label: "Hertz (elastic)".into(),
        points: (0..=120)
            .map(|k| {
                let load = load_top * k as f64 / 120.0;
                (elastic_approach_m(study, load) / approach_y, load / load_y)
            })
            .filter(|&(d, _)| d <= 1.1 * largest_approach)
            .collect(),
        style: Style::Dashed,
        colour: GREY,
    });
    for (label, series, colour) in [
        ("loading", &loading, PALETTE[0]),
        ("unloading", &unloading, PALETTE[1]),
    ] {
        if series.len() < 2 {
            continue;
        }
        curve.series.push(Series {
            label: String::new(),
            points: series.clone(),
            style: Style::Line,
            colour,
        });
        curve.series.push(Series {
            label: match series.len() - 1 {
                1 => format!("{label} (1 step)"),
                n => format!("{label} ({n} steps)"),
            },
            points: series[1..].to_vec(),
            style: Style::Markers,
            colour,
        });
    }
    curve.series.push(Series {
        label: if study.kind == PlasticKind::Line {
            format!(
                "first yield: W_Y = {:.1} kN/m, δ_Y = {:.3} µm",
                load_y * 1e-3,
                approach_y * 1e6
            )
        } else {
            format!(
                "first yield: W_Y = {:.2} N, δ_Y = {:.3} µm",
                load_y,
                approach_y * 1e6
            )
        },
        points: vec![(1.0, 1.0)],
        style: Style::Markers,
        colour: RED,
    });
    curve
}

/// The mean pressure against `E* a / (Y R)` over the first `shown` steps' loading ones, with
/// Hertz's line, the cavity model and Tabor's 3 Y (module doc).
pub fn mean_pressure_chart(study: &PlasticStudy, shown: usize) -> Chart {
    let y = study.spec.yield_strength_pa;
    let hertz = &study.hertz;
    let e_star = hertz.effective_modulus_pa();
    let radius = hertz.effective_radius_m();
    let parameter = |a_m: f64| e_star * a_m / (y * radius);
    let modulus_ratio = study.spec.body1.modulus_pa / e_star;
    let mut mean = Chart::new("Mean pressure over the load steps", "E* a/(Y R)", "p_m/Y");
    mean.x_scale = Scale::Log;
    mean.width_px = CHART_WIDTH;
    let steps: Vec<(f64, f64)> = study
        .history
        .points
        .iter()
        .take(shown)
        .filter(|p| !p.unloading && p.contact_radius_m > 0.0)
        .map(|p| (parameter(p.contact_radius_m), p.mean_pressure_pa / y))
        .collect();
    let (x0, x1) = (0.5, 300.0);
    mean.x_range = Some((x0, x1));
    mean.y_range = Some((0.0, 3.6));
    let log_samples = |f: &dyn Fn(f64) -> f64| -> Vec<(f64, f64)> {
        (0..=160)
            .map(|k| {
                let x = x0 * (x1 / x0).powf(k as f64 / 160.0);
                (x, f(x))
            })
            .filter(|p| p.1 >= 0.0 && p.1 <= 3.6)
            .collect()
    };
    mean.series.push(Series {
        label: "Hertz: (4/3π) E* a/(Y R)".into(),
        points: log_samples(&|x| 4.0 / (3.0 * std::f64::consts::PI) * x),
        style: Style::Dashed,
        colour: GREY,
    });
    mean.series.push(Series {
        label: "cavity model: (2/3)(1 + ln(E a/(3 Y R)))".into(),
        points: log_samples(&|x| 2.0 / 3.0 * (1.0 + (modulus_ratio * x / 3.0).ln())),
        style: Style::Dashed,
        colour: PALETTE[2],
    });
    mean.series.push(Series {
        label: format!("elastic-plastic ({} load steps)", steps.len()),
        points: steps,
        style: Style::Markers,
        colour: PALETTE[0],
    });
    mean.hlines.push((3.0, "Tabor: p_m ≈ 3 Y".into()));
    mean
}

/// The sheet (module doc) of `study`, titled `title`.
pub fn plastic_sheet(title: &str, study: &PlasticStudy, sections: &SheetSections) -> Sheet {
    let y = study.spec.yield_strength_pa;
    let h = study.spec.hardening_modulus_pa;
    let a = study.hertz.size_m();
    let unit = length_unit(study);
    let line = study.kind == PlasticKind::Line;
    let (x_axis, z_axis) = axes(study);
    let over_a: Vec<f64> = study.x_m.iter().map(|x| x / a).collect();
    let mu = study.friction;

    let pressure = pressure_chart(
        study,
        &sections.loaded.pressure_pa,
        if line {
            "Pressure at full load"
        } else {
            "Pressure at full load, y = 0"
        },
    );
    let curve = load_approach_chart(study, study.history.points.len());

    // The maps of the section.
    let strain_outline =
        |strain: &Array2<f64>| outline(strain, &x_axis, &z_axis, PLASTIC_ZONE_STRAIN);
    let loaded = &sections.loaded;
    let zone = strain_outline(&loaded.plastic_strain);
    let traction: Vec<TractionSample> = over_a
        .iter()
        .zip(&loaded.pressure_pa)
        .map(|(&x, &p)| TractionSample {
            x,
            p: p / y,
            q: mu * p / y,
        })
        .collect();
    let strain_map = map(
        study,
        "Equivalent plastic strain at full load",
        format!(
            "max {:.2e} at z = {:.2} {unit}; dashed: εp = 1e-5",
            study.loaded.max_plastic_strain,
            study.loaded.max_plastic_strain_depth_m / a
        ),
        loaded.plastic_strain.clone(),
        PanelScale {
            value_label: "εp".into(),
            colormap: ColorMap::Viridis,
            levels: Levels::Count(5),
            range: None,
        },
        zone.clone(),
        traction.clone(),
        Mark::Max,
    );
    let ratio = &loaded.von_mises_pa / &sections.loaded_yield_stress_pa;
    let yield_line = outline(&ratio, &x_axis, &z_axis, YIELD_LINE_FRACTION);
    let von_mises_map = map(
        study,
        "von Mises at full load (total stress)",
        if h > 0.0 {
            "dashed: the yield line σvM = Y + h εp".into()
        } else {
            "dashed: the yield line σvM = Y".into()
        },
        loaded.von_mises_pa.mapv(|v| v / y),
        PanelScale {
            value_label: "σvM/Y".into(),
            colormap: ColorMap::Magma,
            levels: Levels::Count(8),
            range: Some((
                0.0,
                loaded.von_mises_pa.iter().fold(0.0, |m: f64, &v| m.max(v)) / y,
            )),
        },
        yield_line,
        traction,
        Mark::Max,
    );
    let mut charts = vec![Cell::Chart(pressure), Cell::Chart(curve)];
    if !line {
        charts.push(Cell::Chart(mean_pressure_chart(
            study,
            study.history.points.len(),
        )));
    }
    let mut rows = vec![
        charts,
        vec![Cell::Map(strain_map), Cell::Map(von_mises_map)],
    ];
    if let (Some(unloaded), Some(xx), Some(yy), Some(state)) = (
        &sections.unloaded,
        &sections.residual_xx_pa,
        &sections.residual_yy_pa,
        &study.unloaded,
    ) {
        let zone = strain_outline(&unloaded.plastic_strain);
        let residual = map(
            study,
            "Residual von Mises after unloading",
            format!(
                "max {:.3} Y at z = {:.2} {unit}, {} = {:.2} {unit}; dashed: plastic zone",
                state.residual_von_mises_max_pa / y,
                state.residual_von_mises_max_depth_m / a,
                if line { "|x|" } else { "r" },
                state.residual_von_mises_max_r_m / a
            ),
            unloaded.von_mises_pa.mapv(|v| v / y),
            PanelScale {
                value_label: "σvM/Y".into(),
                colormap: ColorMap::Magma,
                levels: Levels::Count(6),
                range: None,
            },
            zone.clone(),
            Vec::new(),
            Mark::Max,
        );
        let signed = |title: &str, subtitle: &str, label: &str, values: &Array2<f64>| {
            let top = magnitude(values) / y;
            map(
                study,
                title,
                subtitle.into(),
                values.mapv(|v| v / y),
                PanelScale {
                    value_label: label.into(),
                    colormap: ColorMap::Diverging,
                    levels: Levels::Count(8),
                    range: Some((-top, top)),
                },
                zone.clone(),
                Vec::new(),
                Mark::Both,
            )
        };
        rows.push(vec![
            Cell::Map(residual),
            Cell::Map(signed(
                if line {
                    "Residual σxx"
                } else {
                    "Residual σxx (radial on y = 0)"
                },
                "tension positive; dashed: plastic zone",
                "σxx/Y",
                xx,
            )),
            Cell::Map(signed(
                if line {
                    "Residual σyy (out of plane, ε_yy = 0)"
                } else {
                    "Residual σyy (hoop on y = 0)"
                },
                "tension positive; dashed: plastic zone",
                "σyy/Y",
                yy,
            )),
        ]);
    }
    let steps = format!(
        "{} load{} steps",
        study.spec.steps,
        if study.spec.unload {
            format!(" and {} unload", study.spec.unload_steps)
        } else {
            String::new()
        }
    );
    let mut notes = Vec::new();
    if !study.converged {
        notes.push("not converged: some steps did not reach plasticity.tolerance (see `stressfield plastic`)".to_string());
    }
    notes.extend(study.warnings.iter().cloned());
    let title = if line {
        format!(
            "{title}: Y = {:.0} MPa, h = {:.0} MPa, b = {:.1} µm, μ = {mu}, plane strain; {steps}, {} x {} cells (x, z)",
            y * 1e-6,
            h * 1e-6,
            a * 1e6,
            study.x_m.len(),
            study.z_m.len()
        )
    } else {
        format!(
            "{title}: Y = {:.0} MPa, h = {:.0} MPa, a_H = {:.1} µm, μ = {mu}; {steps}, {} x {} x {} cells",
            y * 1e-6,
            h * 1e-6,
            a * 1e6,
            study.x_m.len(),
            study.y_m.len(),
            study.z_m.len()
        )
    };
    Sheet { title, notes, rows }
}

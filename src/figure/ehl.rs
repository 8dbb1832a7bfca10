//! The sheet of a lubricated line contact's numerical EHL solution: the pressure against x
//! with Hertz's dashed and the spike marked, the film against x with its minimum marked and the
//! central film, and von Mises in body 1 under the EHL pressure beside the dry contact's on one
//! colour scale, each maximum marked and labelled. Draws what [`crate::study::ehl`] computed;
//! solves nothing.

use crate::field::Axis;
use crate::render::chart::{Cell, Chart, Series, Sheet, Style};
use crate::render::{ColorMap, Figure, Levels, Mark, Panel, PanelScale, Peak, TractionSample};
use crate::study::assess::Extreme;
use crate::study::ehl::{EhlSections, EhlStudy};

const WIDTH_PX: u32 = 560;
const BLUE: [u8; 3] = [31, 119, 180];
const GREY: [u8; 3] = [90, 90, 90];
const RED: [u8; 3] = [214, 39, 40];

/// Hertz's pressure `p_h √(1 − (x/b)²)` at `x` (m).
fn hertz_pressure_pa(study: &EhlStudy, x_m: f64) -> f64 {
    let s = &study.solution;
    let t = x_m / s.half_width_m;
    if t.abs() < 1.0 {
        s.hertz_p0_pa * (1.0 - t * t).sqrt()
    } else {
        0.0
    }
}

/// A von Mises map in µm and MPa with the tractions above and the maximum marked.
#[allow(clippy::too_many_arguments)]
fn stress_map(
    title: &str,
    subtitle: String,
    sections: &EhlSections,
    values_over_p0: &ndarray::Array2<f64>,
    traction: Vec<TractionSample>,
    peak: &Extreme,
    study: &EhlStudy,
    range_mpa: (f64, f64),
) -> Figure {
    let s = &study.solution;
    let (b_um, ph_mpa) = (s.half_width_m * 1e6, s.hertz_p0_pa * 1e-6);
    let scale = |axis: Axis| Axis::new(axis.min * b_um, axis.max * b_um, axis.count);
    Figure {
        title: title.into(),
        panels: vec![Panel {
            subtitle,
            x: scale(sections.plane.u),
            z: scale(sections.plane.v),
            values: values_over_p0.mapv(|v| v * ph_mpa),
            traction,
            half_width: b_um,
            outlines: Vec::new(),
            scale: Some(PanelScale {
                value_label: "σvM (MPa)".into(),
                colormap: ColorMap::Magma,
                levels: Levels::Count(10),
                range: Some(range_mpa),
            }),
            peak: Some(Peak {
                value: peak.value_over_p0 * ph_mpa,
                x: peak.x_over_a * b_um,
                z: peak.z_over_a * b_um,
            }),
            axes: None,
        }],
        value_label: "σvM (MPa)".into(),
        x_label: "x (µm)".into(),
        z_label: "z (µm)".into(),
        vertical_is_depth: true,
        traction_label: "p, q (MPa)".into(),
        colormap: ColorMap::Magma,
        levels: Levels::Count(10),
        mark: Mark::Max,
        panel_width_px: WIDTH_PX,
    }
}

/// Fixed ranges for the steps of a sweep, so that they compare: the pressure's (GPa) and the
/// von Mises maps' (MPa) upper ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SheetRanges {
    pub pressure_gpa: f64,
    pub von_mises_mpa: f64,
}

/// The sheet (module doc) of `study`, titled `title`.
pub fn ehl_sheet(title: &str, study: &EhlStudy, sections: &EhlSections) -> Sheet {
    ehl_sheet_in(title, study, sections, None)
}

/// [`ehl_sheet`] with the ranges `ranges` (a sweep's), else each chart's and map's own.
pub fn ehl_sheet_in(
    title: &str,
    study: &EhlStudy,
    sections: &EhlSections,
    ranges: Option<SheetRanges>,
) -> Sheet {
    let s = &study.solution;
    let b = s.half_width_m;
    let um = |x: f64| x * 1e6;
    let (x0, x1) = (sections.plane.u.min * b, sections.plane.u.max * b);
    let window: Vec<usize> = (0..s.x_m.len())
        .filter(|&i| s.x_m[i] >= x0 && s.x_m[i] <= x1)
        .collect();
    // Pressure in GPa.
    let mut pressure = Chart::new(
        "Pressure: EHL (solid) and dry Hertz (dashed)",
        "x (µm), entrainment in +x",
        "p (GPa)",
    );
    pressure.width_px = WIDTH_PX;
    pressure.x_range = Some((um(x0), um(x1)));
    // Headroom above the larger peak keeps the top corners free for the legend (a broad
    // hydrodynamic hump fills every corner of a tight range).
    let peak_gpa = s.max_pressure_pa.max(s.hertz_p0_pa) * 1e-9;
    pressure.y_range = Some(ranges.map_or((0.0, 1.5 * peak_gpa), |r| (0.0, r.pressure_gpa)));
    pressure.series.push(Series {
        label: format!("EHL, max {:.2} GPa", s.max_pressure_pa * 1e-9),
        points: window
            .iter()
            .map(|&i| (um(s.x_m[i]), s.pressure_pa[i] * 1e-9))
            .collect(),
        style: Style::Line,
        colour: BLUE,
    });
    let hertz_samples = 241;
    pressure.series.push(Series {
        label: format!("Hertz, p_h = {:.2} GPa", s.hertz_p0_pa * 1e-9),
        points: (0..hertz_samples)
            .map(|k| {
                let x = x0 + (x1 - x0) * k as f64 / (hertz_samples - 1) as f64;
                (um(x), hertz_pressure_pa(study, x) * 1e-9)
            })
            .collect(),
        style: Style::Dashed,
        colour: GREY,
    });
    if let (Some(x), Some(p)) = (s.spike_x_m, s.spike_pressure_pa) {
        // A spike stands near the outlet, apart from the central pressure (it may be the
        // largest pressure at high speeds); at light loads (low M) one maximum near the centre
        // is all there is, and is called so.
        let label = if x == s.max_pressure_x_m && x < 0.5 * b {
            format!("maximum at x = {:.2} b (no separate spike)", x / b)
        } else {
            format!("spike {:.2} GPa at x = {:.2} b", p * 1e-9, x / b)
        };
        pressure.series.push(Series {
            label,
            points: vec![(um(x), p * 1e-9)],
            style: Style::Markers,
            colour: RED,
        });
    }
    // Film in µm, drawn up to four central films (the inlet's wedge rises far above).
    let top_um = 4.0 * um(s.central_film_m);
    let mut film = Chart::new("Film thickness h(x)", "x (µm), entrainment in +x", "h (µm)");
    film.width_px = WIDTH_PX;
    film.x_range = Some((um(x0), um(x1)));
    film.y_range = Some((0.0, top_um));
    film.series.push(Series {
        label: String::new(),
        points: window
            .iter()
            .map(|&i| (um(s.x_m[i]), um(s.film_m[i])))
            .filter(|&(_, h)| h <= top_um)
            .collect(),
        style: Style::Line,
        colour: BLUE,
    });
    film.series.push(Series {
        label: format!(
            "h_min {:.3} µm at x = {:.2} b",
            um(s.minimum_film_m),
            s.minimum_film_x_m / b
        ),
        points: vec![(um(s.minimum_film_x_m), um(s.minimum_film_m))],
        style: Style::Markers,
        colour: RED,
    });
    film.hlines.push((
        um(s.central_film_m),
        format!("h_c = {:.3} µm", um(s.central_film_m)),
    ));
    // The maps on one scale: the larger of the two maxima.
    let ph_mpa = s.hertz_p0_pa * 1e-6;
    let top = study
        .von_mises
        .value_over_p0
        .max(study.dry_von_mises.value_over_p0)
        .max(
            sections
                .lubricated_von_mises_over_p0
                .iter()
                .chain(sections.dry_von_mises_over_p0.iter())
                .fold(0.0, |a: f64, &v| a.max(v)),
        )
        * ph_mpa;
    let top = ranges.map_or(top, |r| r.von_mises_mpa);
    let mu = study.friction;
    let lubricated_traction = window
        .iter()
        .map(|&i| TractionSample {
            x: um(s.x_m[i]),
            p: s.pressure_pa[i] * 1e-6,
            q: mu * s.pressure_pa[i] * 1e-6,
        })
        .collect();
    let dry_traction = (0..hertz_samples)
        .map(|k| {
            let x = x0 + (x1 - x0) * k as f64 / (hertz_samples - 1) as f64;
            let p = hertz_pressure_pa(study, x) * 1e-6;
            TractionSample {
                x: um(x),
                p,
                q: mu * p,
            }
        })
        .collect();
    let label = |e: &Extreme| {
        format!(
            "max {:.0} MPa ({:.3} p_h) at z = {:.2} b, x = {:.2} b",
            e.value_over_p0 * ph_mpa,
            e.value_over_p0,
            e.z_over_a,
            e.x_over_a
        )
    };
    let lubricated = stress_map(
        "von Mises under the EHL pressure",
        label(&study.von_mises),
        sections,
        &sections.lubricated_von_mises_over_p0,
        lubricated_traction,
        &study.von_mises,
        study,
        (0.0, top),
    );
    let dry = stress_map(
        "von Mises under the dry Hertz contact",
        label(&study.dry_von_mises),
        sections,
        &sections.dry_von_mises_over_p0,
        dry_traction,
        &study.dry_von_mises,
        study,
        (0.0, top),
    );
    Sheet {
        title: format!(
            "{title}: EHL film and stress (Moes M = {:.3}, L = {:.3}; b = {:.1} µm; μ = {mu})",
            s.moes_m,
            s.moes_l,
            um(b)
        ),
        notes: Vec::new(),
        rows: vec![
            vec![Cell::Chart(pressure), Cell::Chart(film)],
            vec![Cell::Map(lubricated), Cell::Map(dry)],
        ],
    }
}

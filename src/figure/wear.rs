//! The sheet of a wear scene, in the spirit of Siniawski et al. (2003), Figs. 53–55: the worn
//! topography at six sliding distances (the scar outlined), the contact pressure at the same
//! distances (the cells at the hardness cap outlined), and two charts against the sliding
//! distance: the real contact, plastic and scar areas, and the worn volume beside Archard's
//! straight line `V = k W s`.
//!
//! ## Reference
//! M. T. Siniawski, S. J. Harris, Q. Wang, S. Liu, Wear initiation of steel sliding against a
//! thin boron carbide coating, *Tribol. Lett.* 15 (1) (2003).

use ndarray::Array2;

use crate::field::Axis;
use crate::render::chart::{Cell, Chart, Scale, Series, Sheet, Style, PALETTE};
use crate::render::{ColorMap, Figure, Levels, Mark, Panel, PanelScale};
use crate::scene::Scene;
use crate::study::wear::{WearKind, WearStudy, WearStudyStep};

/// Maps drawn side by side in a row, and their width.
const PER_ROW: usize = 3;
const MAP_WIDTH: u32 = 300;

/// The steps the sheet shows: six spread evenly over the evolution (all of a shorter one),
/// the first and the last included.
pub fn shown_steps(count: usize) -> Vec<usize> {
    if count <= 6 {
        return (0..count).collect();
    }
    let mut steps: Vec<usize> = (0..6)
        .map(|k| ((k as f64) * (count - 1) as f64 / 5.0).round() as usize)
        .collect();
    steps.dedup();
    steps
}

/// The cells `[row0, row1) x [col0, col1)` the maps show: around every cell that carried
/// pressure or wore in the shown steps, with a margin of a fifth of that box (at least four
/// cells), the whole map when that covers most of it.
fn window(study: &WearStudy, shown: &[usize]) -> [usize; 4] {
    let (ny, nx) = study.steps[0].solution.pressure_pa.dim();
    let (mut r0, mut r1, mut c0, mut c1) = (usize::MAX, 0, usize::MAX, 0);
    for &k in shown {
        let step = &study.steps[k];
        let threshold = 1e-3 * step.max_wear_depth_m;
        for ((j, i), &p) in step.solution.pressure_pa.indexed_iter() {
            if p > 0.0 || (step.max_wear_depth_m > 0.0 && step.wear_depth_m[[j, i]] > threshold) {
                (r0, r1, c0, c1) = (r0.min(j), r1.max(j + 1), c0.min(i), c1.max(i + 1));
            }
        }
    }
    if r0 >= r1 {
        return [0, ny, 0, nx];
    }
    let margin = ((r1 - r0).max(c1 - c0) / 5).max(4);
    let (r0, r1) = (r0.saturating_sub(margin), (r1 + margin).min(ny));
    let (c0, c1) = (c0.saturating_sub(margin), (c1 + margin).min(nx));
    if (r1 - r0) * (c1 - c0) * 10 > 8 * nx * ny {
        [0, ny, 0, nx]
    } else {
        [r0, r1, c0, c1]
    }
}

/// The distance of a step as its maps' subtitles say it.
fn distance_text(step: &WearStudyStep) -> String {
    let s = step.sliding_distance_m;
    if s == 0.0 {
        "s = 0 (unworn)".to_string()
    } else if s >= 1.0 {
        format!("s = {} m", crate::io::text::approx(s))
    } else {
        format!("s = {} mm", crate::io::text::approx(s * 1e3))
    }
}

/// A row of maps (one figure of several panels on one colour scale).
fn map_row(
    title: &str,
    panels: Vec<Panel>,
    value_label: &str,
    colormap: ColorMap,
    mark: Mark,
) -> Figure {
    Figure {
        title: title.into(),
        panels,
        value_label: value_label.into(),
        x_label: "x (µm)".into(),
        z_label: "y (µm)".into(),
        vertical_is_depth: false,
        traction_label: String::new(),
        colormap,
        levels: Levels::Count(0),
        mark,
        panel_width_px: MAP_WIDTH,
    }
}

/// The sheet of a wear scene's study (module doc).
pub fn wear_sheet(scene: &Scene, study: &WearStudy) -> Sheet {
    let shown = shown_steps(study.steps.len());
    let [r0, r1, c0, c1] = window(study, &shown);
    let first = &study.steps[0];
    let [dx, dy] = first.solution.spacing_m;
    let x = Axis::new(
        (c0 as f64 + 0.5) * dx * 1e6,
        (c1 as f64 - 0.5) * dx * 1e6,
        c1 - c0,
    );
    let y = Axis::new(
        (r0 as f64 + 0.5) * dy * 1e6,
        (r1 as f64 - 0.5) * dy * 1e6,
        r1 - r0,
    );
    let crop =
        |a: &Array2<f64>| Array2::from_shape_fn((r1 - r0, c1 - c0), |(j, i)| a[[r0 + j, c0 + i]]);
    let top = first
        .heights_m
        .iter()
        .fold(f64::NEG_INFINITY, |m, &h| m.max(h));

    // The worn topography: heights below the unworn top (µm) on one scale, the scar outlined.
    let heights: Vec<Array2<f64>> = shown
        .iter()
        .map(|&k| crop(&study.steps[k].heights_m).mapv(|h| (h - top) * 1e6))
        .collect();
    let (lo, hi) = heights
        .iter()
        .flat_map(|a| a.iter())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let height_scale = PanelScale {
        value_label: "height below the unworn top (µm)".into(),
        colormap: ColorMap::Viridis,
        levels: Levels::Count(0),
        range: Some((lo, if hi > lo { hi } else { lo + 1e-9 })),
    };
    let topography_panels: Vec<Panel> = shown
        .iter()
        .zip(heights)
        .map(|(&k, values)| {
            let step = &study.steps[k];
            let mut outlines = Vec::new();
            if step.max_wear_depth_m > 0.0 {
                let threshold = 1e-3 * step.max_wear_depth_m;
                let scar = crop(&step.wear_depth_m).mapv(|w| if w > threshold { 1.0 } else { 0.0 });
                outlines = crate::render::contour_lines(scar.view(), &x, &y, 0.5);
            }
            Panel {
                subtitle: format!(
                    "{}; wear depth {} µm",
                    distance_text(step),
                    crate::io::text::approx(step.max_wear_depth_m * 1e6)
                ),
                x,
                z: y,
                values,
                traction: Vec::new(),
                half_width: 0.0,
                outlines,
                scale: Some(height_scale.clone()),
                peak: None,
                axes: None,
            }
        })
        .collect();

    // The pressure on one scale (to the robust top of all shown steps), the cells at the cap
    // outlined.
    let pressures: Vec<Array2<f64>> = shown
        .iter()
        .map(|&k| crop(&study.steps[k].solution.pressure_pa).mapv(|p| p * 1e-6))
        .collect();
    let all: Vec<f64> = pressures.iter().flat_map(|a| a.iter().copied()).collect();
    let (robust, _) = crate::render::robust_top(&all);
    let largest = all.iter().fold(0.0f64, |m, &v| m.max(v));
    let pressure_top = match study.hardness_pa {
        // The cap is the top colour when reached: the capped cells read as such.
        Some(h) if largest >= h * 1e-6 * (1.0 - 1e-12) => h * 1e-6,
        _ => robust.max(1e-9),
    };
    // One scale while the peaks stay within a decade of each other; beyond, each map its own
    // (a worn scar's pressure falls far below the unworn peak, and would be one dark colour).
    let peaks: Vec<f64> = pressures
        .iter()
        .map(|a| a.iter().fold(0.0f64, |m, &v| m.max(v)))
        .collect();
    let lowest_peak = peaks.iter().copied().fold(f64::INFINITY, f64::min);
    let own_scales = lowest_peak > 0.0 && largest / lowest_peak > 10.0;
    let scale_for = |values: &Array2<f64>| {
        let top = if own_scales {
            values.iter().fold(0.0f64, |m, &v| m.max(v)).max(1e-9)
        } else {
            pressure_top
        };
        PanelScale {
            value_label: "p (MPa)".into(),
            colormap: ColorMap::Inferno,
            levels: Levels::Count(0),
            range: Some((0.0, top)),
        }
    };
    let hardness = study.hardness_pa;
    let pressure_panels: Vec<Panel> = shown
        .iter()
        .zip(pressures)
        .map(|(&k, values)| {
            let step = &study.steps[k];
            let mut outlines = Vec::new();
            let mut subtitle = format!(
                "{}; max {} MPa",
                distance_text(step),
                crate::io::text::approx(step.solution.max_pressure_pa * 1e-6)
            );
            if let Some(h) = hardness {
                let capped = values.mapv(|p| {
                    if p >= h * 1e-6 * (1.0 - 1e-12) {
                        1.0
                    } else {
                        0.0
                    }
                });
                outlines = crate::render::contour_lines(capped.view(), &x, &y, 0.5);
                subtitle.push_str(&format!("; {} cells at H", step.solution.plastic_cells));
            }
            Panel {
                subtitle,
                x,
                z: y,
                scale: Some(scale_for(&values)),
                values,
                traction: Vec::new(),
                half_width: 0.0,
                outlines,
                peak: None,
                axes: None,
            }
        })
        .collect();

    let mut rows: Vec<Vec<Cell>> = Vec::new();
    let chunks = |panels: Vec<Panel>| -> Vec<Vec<Panel>> {
        let mut out = Vec::new();
        let mut current = Vec::new();
        for panel in panels {
            current.push(panel);
            if current.len() == PER_ROW {
                out.push(std::mem::take(&mut current));
            }
        }
        if !current.is_empty() {
            out.push(current);
        }
        out
    };
    for (k, panels) in chunks(topography_panels).into_iter().enumerate() {
        let title = if k == 0 {
            "Worn topography (the scar outlined)"
        } else {
            "Worn topography, continued"
        };
        let mut map = map_row(
            title,
            panels,
            "height below the unworn top (µm)",
            ColorMap::Viridis,
            Mark::None,
        );
        map.levels = Levels::Count(0);
        rows.push(vec![Cell::Map(map)]);
    }
    let cap_note = match hardness {
        Some(h) => format!(
            "cells at H = {} MPa outlined",
            crate::io::text::approx(h * 1e-6)
        ),
        None => "no hardness cap".into(),
    };
    for (k, panels) in chunks(pressure_panels).into_iter().enumerate() {
        let title = if k == 0 {
            if own_scales {
                format!("Contact pressure, each map on its own scale ({cap_note})")
            } else {
                format!("Contact pressure ({cap_note})")
            }
        } else {
            "Contact pressure, continued".to_string()
        };
        rows.push(vec![Cell::Map(map_row(
            &title,
            panels,
            "p (MPa)",
            ColorMap::Inferno,
            Mark::None,
        ))]);
    }
    rows.push(vec![
        Cell::Chart(area_chart(study)),
        Cell::Chart(volume_chart(study)),
    ]);
    let title = scene.title.clone().unwrap_or_else(|| match study.kind {
        WearKind::Archard { .. } => format!("Wear of {}", scene.name),
        WearKind::Series => format!("Measured wear series of {}", scene.name),
    });
    Sheet {
        title,
        notes: Vec::new(),
        rows,
    }
}

/// The real contact area, the plastic area and the worn scar against the sliding distance, on
/// a logarithmic area axis (mm²).
fn area_chart(study: &WearStudy) -> Chart {
    let mut chart = Chart::new(
        "Contact, plastic and scar area against sliding distance",
        "sliding distance s (m)",
        "area (mm²)",
    );
    chart.y_scale = Scale::Log;
    let series = |f: &dyn Fn(&WearStudyStep) -> f64| -> Vec<(f64, f64)> {
        study
            .steps
            .iter()
            .map(|s| (s.sliding_distance_m, f(s) * 1e6))
            .filter(|p| p.1 > 0.0)
            .collect()
    };
    chart.series.push(Series {
        label: "scar (area worn so far)".into(),
        points: series(&|s| s.scar_area_m2()),
        style: Style::Line,
        colour: PALETTE[2],
    });
    chart.series.push(Series {
        label: "real contact area".into(),
        points: series(&|s| s.contact_area_m2()),
        style: Style::Line,
        colour: PALETTE[0],
    });
    let plastic = series(&|s| s.plastic_area_m2());
    let plastic_label = match study.hardness_pa {
        Some(_) if plastic.is_empty() => "plastic area: no cell at the hardness cap".to_string(),
        Some(_) => "plastic area (cells at the hardness cap)".to_string(),
        None => "plastic area: no hardness given".to_string(),
    };
    chart.series.push(Series {
        label: plastic_label,
        points: plastic,
        style: Style::Markers,
        colour: PALETTE[1],
    });
    if let Some(h) = study.hardness_pa {
        chart.hlines.push((
            study.load_n / h * 1e6,
            "W/H: the most the cap can carry".into(),
        ));
    }
    chart
}

/// The worn volume against the sliding distance, with Archard's `V = k W s` (simulated wear).
fn volume_chart(study: &WearStudy) -> Chart {
    let largest = study
        .steps
        .iter()
        .fold(0.0f64, |m, s| m.max(s.worn_volume_m3 * 1e18));
    // Volumes in µm³, or in thousands of them when they run to five digits and more.
    let (unit, per_m3) = if largest >= 1e4 {
        ("10³ µm³", 1e15)
    } else {
        ("µm³", 1e18)
    };
    let mut chart = Chart::new(
        "Worn volume against sliding distance",
        "sliding distance s (m)",
        &format!("worn volume ({unit})"),
    );
    chart.series.push(Series {
        label: match study.kind {
            WearKind::Archard { .. } => "worn (the simulation's Σ k ds p dA)".into(),
            WearKind::Series => "lost against the first map".into(),
        },
        points: study
            .steps
            .iter()
            .map(|s| (s.sliding_distance_m, s.worn_volume_m3 * per_m3))
            .collect(),
        style: Style::Markers,
        colour: PALETTE[0],
    });
    if let WearKind::Archard {
        coefficient_m2_per_n,
        distance_m,
        ..
    } = study.kind
    {
        chart.series.push(Series {
            label: format!(
                "Archard V = k W s, k = {} mm³/(N m), W = {} N",
                crate::io::text::approx(coefficient_m2_per_n * 1e9),
                crate::io::text::approx(study.load_n)
            ),
            points: vec![
                (0.0, 0.0),
                (
                    distance_m,
                    coefficient_m2_per_n * study.load_n * distance_m * per_m3,
                ),
            ],
            style: Style::Dashed,
            colour: PALETTE[1],
        });
    }
    chart
}

//! Recordings of entrainment-speed sweeps: lubricated line contacts with `[sweep] parameter =
//! "entrainment_speed"` (issue 52). Draws what [`crate::study::ehl::speed_sweep`] computed.
//!
//! ## Entities (steps on the timeline `entrainment_speed`)
//! - `description`: the scene, the sweep and how to read the views.
//! - `sheet`: the step's EHL sheet ([`crate::figure::ehl`]): the pressure against x with
//!   Hertz's dashed and the spike marked, the film with its minimum, and von Mises under the
//!   EHL pressure beside the dry contact's. The pressure axis and the maps' colour range are
//!   the whole sweep's, so that the spike and the near-surface stress are seen to grow.
//! - `charts/films` (central and minimum film against u, log axes, with Pan & Hamrock's
//!   formula) and `charts/stress` (the spike's pressure and the near-surface von Mises against
//!   u): chart images of the steps so far, the current one marked.
//! - `series/entrainment_speed_m_per_s`, `series/central_film_um`, `series/minimum_film_um`,
//!   `series/spike_pressure_over_ph`, `series/near_surface_von_mises_over_ph`,
//!   `series/von_mises_max_over_ph`: scalars per step.
//! - `log`: one line per step.

use rerun::RecordingStream;

use super::layout::{Layout, Node, View, ViewKind};
use super::rough::rerun_error;
use super::{RecordError, Summary};
use crate::figure::ehl::{ehl_sheet_in, SheetRanges};
use crate::lubrication::film::{pan_hamrock, FilmConditions};
use crate::render::chart::{Chart, Scale, Series, Style};
use crate::scene::Scene;
use crate::study::ehl::{self, EhlStep, NEAR_SURFACE_DEPTH_OVER_B};

/// The timeline of the steps.
pub const TIMELINE: &str = "entrainment_speed";

/// Records an entrainment-speed sweep (module doc); a `live` stream opens following the newest
/// step. The steps are solved first (in parallel), then sent one by one.
pub fn record(
    scene: &Scene,
    stream: &RecordingStream,
    live: bool,
    flush: &dyn Fn() -> Result<(), RecordError>,
) -> Result<Summary, RecordError> {
    let sweep = scene
        .sweep
        .as_ref()
        .ok_or_else(|| rerun_error("an entrainment-speed sweep needs [sweep]"))?;
    let steps = ehl::speed_sweep(scene, &sweep.values, ehl::SWEEP_COLUMNS, ehl::SWEEP_ROWS)
        .map_err(rerun_error)?;
    let problem = ehl::problem(scene).map_err(rerun_error)?;
    let alpha_per_pa = scene.lubricant.map_or(0.0, |l| l.alpha_per_pa);
    stream.log_static(
        "description",
        &rerun::TextDocument::from_markdown(describe(scene, &steps)),
    )?;
    let ranges = SheetRanges {
        pressure_gpa: super::round_up(
            1.05 * steps
                .iter()
                .map(|s| s.study.solution.max_pressure_pa)
                .fold(0.0, f64::max)
                * 1e-9,
        ),
        von_mises_mpa: super::round_up(
            steps
                .iter()
                .map(|s| {
                    let ph = s.study.solution.hertz_p0_pa * 1e-6;
                    s.study
                        .von_mises
                        .value_over_p0
                        .max(s.study.dry_von_mises.value_over_p0)
                        .max(
                            s.sections
                                .lubricated_von_mises_over_p0
                                .iter()
                                .fold(0.0, |a: f64, &v| a.max(v)),
                        )
                        * ph
                })
                .fold(0.0, f64::max),
        ),
    };
    super::layout::send(stream, &plan_layout(), live)?;
    let title = scene.title.clone().unwrap_or_else(|| scene.name.clone());
    let count = steps.len();
    for (k, step) in steps.iter().enumerate() {
        stream.set_time_sequence(TIMELINE, super::step_time(k));
        let text = sweep.describe(k, scene);
        let sheet = ehl_sheet_in(
            &format!("{title}, {text}"),
            &step.study,
            &step.sections,
            Some(ranges),
        );
        let image = crate::render::chart::sheet_png(&sheet).map_err(rerun_error)?;
        let png = crate::render::encode_png(&image).map_err(rerun_error)?;
        stream.log("sheet", &rerun::EncodedImage::from_file_contents(png))?;
        for (name, chart) in charts(&steps, k, &problem, alpha_per_pa) {
            stream.log(
                format!("charts/{name}"),
                &rerun::EncodedImage::from_file_contents(super::chart_png_bytes(&chart)?),
            )?;
        }
        let s = &step.study.solution;
        let spike = s.spike_pressure_pa.map_or(f64::NAN, |p| p / s.hertz_p0_pa);
        stream.log(
            "log",
            &rerun::TextLog::new(format!(
                "{}: M = {:.3}, L = {:.3}; h_c = {:.4} µm, h_min = {:.4} µm; spike {}; von Mises max {:.4} p_h at z = {:.3} b, above z = {NEAR_SURFACE_DEPTH_OVER_B} b {:.4} p_h",
                super::step_text(k, count, &text),
                s.moes_m,
                s.moes_l,
                s.central_film_m * 1e6,
                s.minimum_film_m * 1e6,
                s.spike_x_m.map_or_else(
                    || "none".to_string(),
                    |x| format!("{spike:.4} p_h at x = {:.3} b", x / s.half_width_m)
                ),
                step.study.von_mises.value_over_p0,
                step.study.von_mises.z_over_a,
                step.near_surface_von_mises.value_over_p0,
            )),
        )?;
        for (path, value) in [
            ("series/entrainment_speed_m_per_s", step.entrainment_m_per_s),
            ("series/central_film_um", s.central_film_m * 1e6),
            ("series/minimum_film_um", s.minimum_film_m * 1e6),
            ("series/spike_pressure_over_ph", spike),
            (
                "series/near_surface_von_mises_over_ph",
                step.near_surface_von_mises.value_over_p0,
            ),
            (
                "series/von_mises_max_over_ph",
                step.study.von_mises.value_over_p0,
            ),
        ] {
            if value.is_finite() {
                stream.log(path, &rerun::Scalars::new([value]))?;
            }
        }
        flush()?;
    }
    Ok(Summary {
        steps: count,
        panels: 2,
        volume_triangles: 0,
    })
}

/// The viewer layout: the sheet takes most of the window; beside it the charts (tabs) above
/// the documents and the scalars against the step.
fn plan_layout() -> Layout {
    let view2d =
        |name: &str, origin: &str| Node::View(View::new(ViewKind::Spatial2D(None), name, origin));
    let charts = Node::Tabs(
        vec![
            view2d("films vs u", "charts/films"),
            view2d("spike, stress vs u", "charts/stress"),
        ],
        0,
    );
    let documents = Node::Tabs(
        vec![
            Node::View(View::new(ViewKind::TextDocument, "scene", "description")),
            Node::View(View::new(ViewKind::TextLog, "steps", "log")),
            Node::View(
                View::new(ViewKind::TimeSeries, "over p_h vs step", "series").with_contents(&[
                    "$origin/spike_pressure_over_ph",
                    "$origin/near_surface_von_mises_over_ph",
                    "$origin/von_mises_max_over_ph",
                ]),
            ),
        ],
        0,
    );
    Layout {
        root: Node::Horizontal(
            vec![
                view2d("EHL sheet at this speed", "sheet"),
                Node::Vertical(vec![charts, documents], vec![1.3, 1.0]),
            ],
            vec![super::MAIN_SHARE, super::SIDE_SHARE],
        ),
        timeline: Some(TIMELINE.to_string()),
    }
}

/// The charts at step `current` (the steps so far, the current one marked), by entity name.
fn charts(
    steps: &[EhlStep],
    current: usize,
    problem: &crate::lubrication::line_ehl::LineEhlProblem,
    alpha_per_pa: f64,
) -> Vec<(&'static str, Chart)> {
    let so_far = &steps[..=current];
    let (lo, hi) = (
        steps
            .iter()
            .map(|s| s.entrainment_m_per_s)
            .fold(f64::INFINITY, f64::min),
        steps
            .iter()
            .map(|s| s.entrainment_m_per_s)
            .fold(0.0, f64::max),
    );
    let x_range = Some((lo / 1.25, hi * 1.25));
    let line = |label: &str, colour: [u8; 3], f: &dyn Fn(&EhlStep) -> f64| {
        vec![
            Series {
                label: label.to_string(),
                points: so_far
                    .iter()
                    .map(|s| (s.entrainment_m_per_s, f(s)))
                    .filter(|p| p.1.is_finite())
                    .collect(),
                style: Style::Line,
                colour,
            },
            Series {
                label: String::new(),
                points: [(steps[current].entrainment_m_per_s, f(&steps[current]))]
                    .into_iter()
                    .filter(|p| p.1.is_finite())
                    .collect(),
                style: Style::Markers,
                colour,
            },
        ]
    };
    let mut films = Chart::log_log(
        "Film thickness against the entrainment speed",
        "u (m/s)",
        "h (µm)",
    );
    films.x_range = x_range;
    films
        .series
        .extend(line("central (numerical)", [31, 119, 180], &|s| {
            s.study.solution.central_film_m * 1e6
        }));
    films
        .series
        .extend(line("minimum (numerical)", [214, 39, 40], &|s| {
            s.study.solution.minimum_film_m * 1e6
        }));
    let formula = |speed: f64| {
        pan_hamrock(
            &FilmConditions {
                viscosity_pa_s: problem.viscosity_pa_s,
                alpha_per_pa,
                reduced_modulus_pa: problem.reduced_modulus_pa,
                entrainment_m_per_s: speed,
                radius_x_m: problem.radius_m,
            },
            problem.load_n_per_m,
        )
    };
    let samples = 40;
    let along = |f: &dyn Fn(f64) -> f64| -> Vec<(f64, f64)> {
        (0..samples)
            .map(|i| {
                let u = lo * (hi / lo).powf(f64::from(i) / f64::from(samples - 1));
                (u, f(u))
            })
            .collect()
    };
    films.series.push(Series {
        label: "Pan & Hamrock, central".into(),
        points: along(&|u| formula(u).central_m * 1e6),
        style: Style::Dashed,
        colour: [31, 119, 180],
    });
    films.series.push(Series {
        label: "Pan & Hamrock, minimum".into(),
        points: along(&|u| formula(u).minimum_m * 1e6),
        style: Style::Dashed,
        colour: [214, 39, 40],
    });
    let mut stress = Chart::new(
        "Spike pressure and near-surface stress against u",
        "u (m/s)",
        "over the Hertz pressure p_h",
    );
    stress.x_scale = Scale::Log;
    stress.x_range = x_range;
    stress.y_range = Some((0.0, {
        let top = steps
            .iter()
            .map(|s| {
                let sol = &s.study.solution;
                sol.spike_pressure_pa
                    .map_or(0.0, |p| p / sol.hertz_p0_pa)
                    .max(s.near_surface_von_mises.value_over_p0)
            })
            .fold(1.0, f64::max);
        1.1 * top
    }));
    stress
        .series
        .extend(line("spike pressure", [214, 39, 40], &|s| {
            let sol = &s.study.solution;
            sol.spike_pressure_pa
                .map_or(f64::NAN, |p| p / sol.hertz_p0_pa)
        }));
    stress.series.extend(line(
        &format!("von Mises max above z = {NEAR_SURFACE_DEPTH_OVER_B} b"),
        [31, 119, 180],
        &|s| s.near_surface_von_mises.value_over_p0,
    ));
    stress.series.extend(line("von Mises max", [0, 0, 0], &|s| {
        s.study.von_mises.value_over_p0
    }));
    vec![("films", films), ("stress", stress)]
}

/// The description: the scene, the sweep and how to read the views.
fn describe(scene: &Scene, steps: &[EhlStep]) -> String {
    let mut text = format!(
        "# {}\n\nThe numerical EHL solution of a lubricated line contact (isothermal, Reynolds with the elastic film and the load balance, Newton–Raphson; docs/lubrication.md) at {} entrainment speeds, one per step on the timeline `{TIMELINE}`.\n\n",
        scene.title.as_deref().unwrap_or(&scene.name),
        steps.len()
    );
    text.push_str("- `sheet`: the step's pressure (Hertz's dashed, the spike marked), film (minimum marked, central dashed) and von Mises in body 1 under the EHL pressure beside the dry contact's; the pressure axis and the maps' colours are the whole sweep's.\n");
    text.push_str("- `charts/films`: the central and minimum films against u (log axes) with Pan & Hamrock's formula (dashed); `charts/stress`: the spike's pressure and the largest von Mises (near the surface and overall) over p_h.\n");
    text.push_str(&format!("- The near-surface maximum is the section's largest sample above z = {NEAR_SURFACE_DEPTH_OVER_B} b (grid 0.02 b).\n\n| step | u (m/s) | M | L | h_min (µm) | spike / p_h |\n|---|---|---|---|---|---|\n"));
    for (k, step) in steps.iter().enumerate() {
        let s = &step.study.solution;
        text.push_str(&format!(
            "| {} | {:.3} | {:.3} | {:.3} | {:.4} | {} |\n",
            k + 1,
            step.entrainment_m_per_s,
            s.moes_m,
            s.moes_l,
            s.minimum_film_m * 1e6,
            s.spike_pressure_pa
                .map_or_else(|| "none".into(), |p| format!("{:.3}", p / s.hertz_p0_pa))
        ));
    }
    text
}

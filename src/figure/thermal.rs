//! The frictional-heating sheet: body 1's surface temperature with the contact outlined, the
//! xz section of the temperature under its hottest point, the von Mises and Tresca sections
//! of the thermal, contact and total stress there, and the maximum flash temperature against
//! the Péclet number with its asymptotes. Draws what [`crate::study::thermal`] and [`crate::study::thermal_sections`]
//! computed; computes nothing itself.

use ndarray::Array2;

use crate::thermal::heating::Partition;

use crate::field::Axis;
use crate::render::chart::{Cell, Chart, Scale, Series, Sheet, Style};
use crate::render::{ColorMap, Figure, Levels, Mark, Panel, Peak};
use crate::study::gear_heating::{GearHeating, PathPoint};
use crate::study::thermal::{ContactModel, Maximum, ThermalStudy};
use crate::study::thermal_sections::ThermalSections;

const MAP_WIDTH: u32 = 520;

/// A map in µm (x across, y or depth down), values already in display units.
#[allow(clippy::too_many_arguments)]
pub(crate) fn map(
    title: &str,
    subtitle: String,
    x: Axis,
    z: Axis,
    values: Array2<f64>,
    value_label: &str,
    colormap: ColorMap,
    depth: bool,
    outlines: Vec<Vec<(f64, f64)>>,
) -> Figure {
    Figure {
        title: title.into(),
        panels: vec![Panel {
            subtitle,
            x,
            z,
            values,
            traction: Vec::new(),
            half_width: 0.0,
            outlines,
            scale: None,
            peak: None,
            axes: None,
        }],
        value_label: value_label.into(),
        x_label: "x (µm)".into(),
        z_label: if depth { "z (µm)" } else { "y (µm)" }.into(),
        vertical_is_depth: depth,
        traction_label: String::new(),
        colormap,
        levels: Levels::Count(8),
        mark: Mark::Max,
        panel_width_px: MAP_WIDTH,
    }
}

/// A surface temperature map as drawn, in µm.
pub(crate) struct SurfaceMap {
    pub(crate) x: Axis,
    pub(crate) y: Axis,
    /// `[rows, columns]`, K.
    pub(crate) values: Array2<f64>,
    /// The contact's outline.
    pub(crate) outlines: Vec<Vec<(f64, f64)>>,
}

/// A surface temperature map as drawn, in µm: the x axis, the y axis, the values (K) and the
/// contact's outline. `temperature` and `flux` are on cells `spacing_m` apart from `origin_m`
/// (the centre of cell `[0, 0]`); a line contact's band of identical rows is shown as a strip
/// of ±1.5a with the edges x = ±a drawn, a gridded contact with the isoline where the flux (so
/// the pressure) falls to zero, at a level just above it.
pub(crate) fn surface_map(
    temperature: &Array2<f64>,
    flux: &Array2<f64>,
    origin_m: [f64; 2],
    spacing_m: [f64; 2],
    half_width_m: f64,
    line: bool,
) -> SurfaceMap {
    let (ny, nx) = temperature.dim();
    let um = |v: f64| v * 1e6;
    let x = Axis::new(
        um(origin_m[0]),
        um(origin_m[0] + (nx - 1) as f64 * spacing_m[0]),
        nx,
    );
    if line {
        let rows = 31;
        let (a, half) = (um(half_width_m), 1.5 * um(half_width_m));
        let row = temperature.row(ny / 2).to_owned();
        return SurfaceMap {
            x,
            y: Axis::new(-half, half, rows),
            values: Array2::from_shape_fn((rows, nx), |(_, c)| row[c]),
            outlines: vec![vec![(-a, -half), (-a, half)], vec![(a, -half), (a, half)]],
        };
    }
    let y = Axis::new(
        um(origin_m[1]),
        um(origin_m[1] + (ny - 1) as f64 * spacing_m[1]),
        ny,
    );
    let max = flux.iter().fold(0.0f64, |m, &q| m.max(q));
    let outlines = crate::render::contour_lines(flux.view(), &x, &y, 1e-6 * max);
    SurfaceMap {
        x,
        y,
        values: temperature.clone(),
        outlines,
    }
}

/// The two asymptotes of body 1's maximum flash temperature against the Péclet number from
/// `lo` to `hi`, dashed: stationary `θ = slow Pe` (none for a line contact) and fast
/// `θ = fast √Pe` (Jaeger 1942; Blok 1937; see [`crate::study::thermal_sections`]). Used by
/// the speed sweep's recording alone (the sheet's chart has its own since issue 38).
#[cfg(feature = "rerun")]
pub(crate) fn asymptotes(slow: Option<f64>, fast: f64, lo: f64, hi: f64) -> Vec<Series> {
    let line = |f: &dyn Fn(f64) -> f64| -> Vec<(f64, f64)> {
        (0..=40)
            .map(|k| {
                let pe = lo * (hi / lo).powf(k as f64 / 40.0);
                (pe, f(pe))
            })
            .collect()
    };
    let mut series = Vec::new();
    if let Some(slow) = slow {
        series.push(Series {
            label: "stationary limit ∝ Pe".into(),
            points: line(&|pe| slow * pe),
            style: Style::Dashed,
            colour: [44, 160, 44],
        });
    }
    series.push(Series {
        label: "fast limit ∝ √Pe (Jaeger, Blok)".into(),
        points: line(&|pe| fast * pe.sqrt()),
        style: Style::Dashed,
        colour: [214, 39, 40],
    });
    series
}

/// The asymptotes of body 1's maximum flash temperature under a fixed flux against its
/// Péclet number from `lo` to `hi`, dashed: the stationary temperature (a constant; none for
/// a line contact) and the fast limit `θ = fast / √Pe` (Jaeger 1942; Blok 1937; see
/// [`crate::study::thermal_sections`]). `stationary_scene`: the scene is a stationary source
/// with this temperature (K), which the stationary limit's label states.
fn flux_asymptotes(
    stationary: Option<f64>,
    fast: f64,
    lo: f64,
    hi: f64,
    stationary_scene: Option<f64>,
) -> Vec<Series> {
    let line = |f: &dyn Fn(f64) -> f64| -> Vec<(f64, f64)> {
        (0..=40)
            .map(|k| {
                let pe = lo * (hi / lo).powf(k as f64 / 40.0);
                (pe, f(pe))
            })
            .collect()
    };
    let mut series = Vec::new();
    if let Some(stationary) = stationary {
        series.push(Series {
            label: match stationary_scene {
                Some(t) => format!(
                    "stationary limit: this scene (body 1 carries the contact, Pe = 0): {t:.1} K"
                ),
                None => "stationary limit (Pe → 0)".into(),
            },
            points: line(&|_| stationary),
            style: Style::Dashed,
            colour: [44, 160, 44],
        });
    }
    series.push(Series {
        label: "fast limit ∝ 1/√Pe (Jaeger, Blok)".into(),
        points: line(&|pe| fast / pe.sqrt()),
        style: Style::Dashed,
        colour: [214, 39, 40],
    });
    series
}

/// The sheet of a scene's heating; running gears (`gear`) add the flash temperatures along the path of contact,
/// and the maps and sections are then those of its hottest point.
pub fn thermal_sheet(
    name: &str,
    study: &ThermalStudy,
    sections: &ThermalSections,
    gear: Option<&GearHeating>,
) -> Sheet {
    let um = |v: f64| v * 1e6;
    let SurfaceMap {
        x: x_axis,
        y: y_axis,
        values: surface_values,
        outlines: outline,
    } = surface_map(
        &study.body1.temperature_k,
        &study.flux_w_per_m2,
        study.origin_m,
        study.spacing_m,
        study.half_width_m,
        study.line,
    );
    let pe = study.body1.peclet;
    let peclet_text = format!(
        "Pe = {pe:.2}, V = {} m/s{}",
        crate::io::text::significant(study.spec.sliding_speed_m_per_s, 4, 1e6, true),
        gear.map_or(String::new(), |g| format!(
            " at s = {:.2} mm on the path",
            g.points[g.hottest].s_m * 1e3
        ))
    );
    let mut surface = map(
        "Body 1's surface temperature rise (contact outlined)",
        if pe > 0.0 {
            format!("{peclet_text}; the contact moves in +x, the wake trails at −x")
        } else {
            format!("{peclet_text}; a stationary source: body 1 carries the contact")
        },
        x_axis,
        y_axis,
        surface_values,
        "ΔT (K)",
        ColorMap::Inferno,
        false,
        outline,
    );
    // The report's hottest point (a line contact's: y = 0, every row being the same).
    surface.panels[0].peak = Some(Peak {
        value: study.body1.max_temperature_rise_k,
        x: um(study.body1.max_at_m[0]),
        z: um(study.body1.max_at_m[1]),
    });
    let depth = Axis::new(
        0.0,
        um(*sections.depths_m.last().unwrap_or(&0.0)),
        sections.depths_m.len(),
    );
    let section_x = Axis::new(
        um(sections.x_m[0]),
        um(sections.x_m[1]),
        sections.temperature_k.ncols(),
    );
    let at_hot_row = format!("y = {:.1} µm", um(sections.temperature_y_m));
    let temperature = map(
        "Temperature rise under the hottest point",
        format!("xz section at {at_hot_row}; {peclet_text}"),
        section_x,
        depth,
        sections.temperature_k.clone(),
        "ΔT (K)",
        ColorMap::Inferno,
        true,
        Vec::new(),
    );
    let at_row = format!("y = {:.1} µm", um(sections.y_m));
    let mpa = |a: &Array2<f64>| a.mapv(|v| v * 1e-6);
    // A report's maximum marked where it lies in the section (its row and depth range);
    // otherwise the section's largest sample.
    let deepest = *sections.depths_m.last().unwrap_or(&0.0);
    let peak_of = |m: &Maximum| {
        // A closed form's maximum is located to about 1e-8 a (off y = 0 by as much).
        let in_row = (m.y_m - sections.y_m).abs() <= 1e-6 * study.half_width_m;
        let [x0, x1] = sections.x_m;
        let in_window = m.x_m >= x0 - 1e-12 * x0.abs() && m.x_m <= x1 + 1e-12 * x1.abs();
        (in_row && in_window && m.depth_m <= deepest * (1.0 + 1e-12)).then(|| Peak {
            value: m.value_pa * 1e-6,
            x: um(m.x_m),
            z: um(m.depth_m),
        })
    };
    let section =
        |title: &str, subtitle: String, values: &Array2<f64>, label: &str, m: Option<&Maximum>| {
            let mut figure = map(
                title,
                subtitle,
                section_x,
                depth,
                mpa(values),
                label,
                ColorMap::Magma,
                true,
                Vec::new(),
            );
            figure.panels[0].peak = m.and_then(peak_of);
            figure
        };
    // Friction on body 1 acts the way body 2 slides over it.
    let source = match study.contact_model {
        ContactModel::ClosedForm { .. } => "closed form",
        ContactModel::Gridded | ContactModel::Rough { .. } => "DC-FFT",
    };
    let traction = match study.spec.traction {
        crate::scene::TractionDirection::PlusX => {
            format!("{at_row}; p and q = μ p in +x ({source})")
        }
        crate::scene::TractionDirection::MinusX => {
            format!("{at_row}; p and q = μ p in −x, body 2 the faster ({source})")
        }
    };
    let e_alpha = format!(
        "{at_row}; E α = {:.3} MPa/K",
        study.spec.body1.material.modulus_pa * study.spec.body1.properties.expansion_per_k * 1e-6
    );
    let shear_label = "(σ1 − σ3)/2 (MPa)";
    let stresses = [
        [
            section(
                "Thermal stress alone: von Mises",
                e_alpha.clone(),
                &sections.thermal_von_mises_pa,
                "σvM (MPa)",
                Some(&study.thermal_von_mises),
            ),
            section(
                "Thermal stress alone: maximum shear (σ1 − σ3)/2",
                e_alpha,
                &sections.thermal_max_shear_pa,
                shear_label,
                None,
            ),
        ],
        [
            section(
                "Contact stress alone: von Mises",
                traction.clone(),
                &sections.contact_von_mises_pa,
                "σvM (MPa)",
                Some(&study.contact_von_mises),
            ),
            section(
                "Contact stress alone: maximum shear (σ1 − σ3)/2",
                traction.clone(),
                &sections.contact_max_shear_pa,
                shear_label,
                Some(&study.contact_max_shear),
            ),
        ],
        [
            section(
                "Contact + thermal stress: von Mises",
                format!(
                    "{at_row}; contact alone peaks at {:.1} MPa",
                    study.contact_von_mises.value_pa * 1e-6
                ),
                &sections.total_von_mises_pa,
                "σvM (MPa)",
                Some(&study.total_von_mises),
            ),
            section(
                "Contact + thermal stress: maximum shear (σ1 − σ3)/2",
                format!(
                    "{at_row}; contact alone peaks at {:.1} MPa",
                    study.contact_max_shear.value_pa * 1e-6
                ),
                &sections.total_max_shear_pa,
                shear_label,
                Some(&study.total_max_shear),
            ),
        ],
    ];
    let mut chart = Chart::new(
        "Maximum flash temperature of body 1 against Pe",
        "Péclet number of body 1, V1 a / (2κ1)",
        "ΔT max (K), all heat into body 1",
    );
    chart.x_scale = Scale::Log;
    chart.y_scale = Scale::Log;
    let (lo, hi) = (
        sections.sweep.first().map_or(0.1, |p| p.0),
        sections.sweep.last().map_or(100.0, |p| p.0),
    );
    chart.series.push(Series {
        label: if study.line {
            "computed (strips, q = μ p Vs fixed)".into()
        } else {
            "computed (cells by DC-FFT, q = μ p Vs fixed)".into()
        },
        points: sections.sweep.clone(),
        style: Style::Markers,
        colour: [31, 119, 180],
    });
    chart.series.extend(flux_asymptotes(
        sections.stationary_k,
        sections.fast_times_root_peclet,
        lo,
        hi,
        (pe == 0.0).then_some(()).and(sections.scene_k),
    ));
    if let (Some(scene_k), true) = (sections.scene_k, pe >= lo && pe <= hi) {
        chart.series.push(Series {
            label: format!("this scene (Pe = {pe:.2}: {scene_k:.1} K)"),
            points: vec![(pe, scene_k)],
            style: Style::Markers,
            colour: [0, 0, 0],
        });
    }
    let mut rows = vec![vec![Cell::Map(surface), Cell::Map(temperature)]];
    for [von_mises, tresca] in stresses {
        rows.push(vec![Cell::Map(von_mises), Cell::Map(tresca)]);
    }
    rows.push(vec![Cell::Chart(chart)]);
    if let Some(gear) = gear {
        rows.insert(0, gear_charts(gear));
    }
    Sheet {
        title: format!("{name}: frictional heating"),
        notes: Vec::new(),
        rows,
    }
}

/// Blok's flash temperature as the gears' partition computes it (the two-body formula only
/// for Blok's partition; see [`crate::study::gear_heating`]).
pub fn blok_formula(partition: Partition) -> &'static str {
    match partition {
        Partition::Blok => "Blok 1.11 μ w Vs / (√(2a) (β1 √V1 + β2 √V2))",
        Partition::Fraction(_) => "Blok f 1.11 μ w Vs / (√(2a) β1 √V1)",
        Partition::Body1 => "Blok 1.11 μ w Vs / (√(2a) β1 √V1)",
    }
}

/// Running gears: the flash temperatures along the path of contact (each body's, and Blok's
/// formula), and the sliding speed with the load per unit width.
fn gear_charts(gear: &GearHeating) -> Vec<Cell> {
    let mm = |p: &PathPoint| p.s_m * 1e3;
    let series = |label: &str, f: &dyn Fn(&PathPoint) -> f64, style, colour| Series {
        label: label.into(),
        points: gear.points.iter().map(|p| (mm(p), f(p))).collect(),
        style,
        colour,
    };
    let rpm = gear.mesh.pinion_rad_per_s * 30.0 / std::f64::consts::PI;
    let mut temperature = Chart::new(
        &format!(
            "Flash temperature along the path ({rpm:.0} rpm, μ = {})",
            gear.mesh.friction
        ),
        "s from the pitch point (mm), + towards the pinion's tip",
        "ΔT max (K)",
    );
    temperature.series = vec![
        series(
            "pinion (body 1)",
            &|p| p.max_temperature_rise_k[0],
            Style::Line,
            [31, 119, 180],
        ),
        series(
            "gear (body 2)",
            &|p| p.max_temperature_rise_k[1],
            Style::Line,
            [255, 127, 14],
        ),
        series(
            blok_formula(gear.study.spec.partition),
            &|p| p.blok_k,
            Style::Dashed,
            [120, 120, 120],
        ),
    ];
    let mut kinematics = Chart::new(
        &format!(
            "Sliding speed and load per pair (contact ratio {:.3})",
            gear.contact_ratio
        ),
        "s from the pitch point (mm), + towards the pinion's tip",
        "Vs (m/s); w (10 N/mm)",
    );
    kinematics.series = vec![
        series(
            "sliding speed Vs (m/s)",
            &|p| p.sliding_speed_m_per_s,
            Style::Line,
            [214, 39, 40],
        ),
        series(
            "load per pair w (10 N/mm)",
            &|p| p.load_n_per_m * 1e-4,
            Style::Line,
            [44, 160, 44],
        ),
    ];
    vec![Cell::Chart(temperature), Cell::Chart(kinematics)]
}

//! The figures of rough scenes, as sheets of maps and charts (a surface scene's sheet is in
//! [`super::surface`]).
//!
//! A **rough** scene: the topography with the contact spots outlined, the pressure map, the
//! chosen stress quantity in the xz section through the `contact` report's maximum, marking
//! the report's value or saying how it differs (the pressure and traction profile along that
//! line above it), the xy section at the depth of that maximum, and the real area against load: solved at several loads, beside the GW prediction
//! and the linear law `A/A0 = κ p / (E* h'rms)` with `κ = sqrt(8/π)` (Persson 2001; h'rms =
//! Sdq here).
//!
//! ## References
//! - B. N. J. Persson, Theory of rubber friction and contact mechanics, *J. Chem. Phys.* 115
//!   (2001) 3840 (the linear area-load law and its κ).
//! - J. A. Greenwood, J. B. P. Williamson (1966), see [`crate::surface::gw`].

use std::f64::consts::PI;

use ndarray::Array2;

use crate::contact::rough::RoughSolution;
use crate::field::{Axis, FieldError};
use crate::operator::elastic::Periodicity;
use crate::render::chart::{Cell, Chart, Series, Sheet, Style, PALETTE};
use crate::render::{ColorMap, Figure, Levels, Mark, Panel, PanelScale, TractionSample};
use crate::scene::{ContactKind, Scene};
use crate::study::map_roll::Roll;
use crate::study::rough::{self as rough_study, RoughStudyError};
use crate::study::rough_sheet::RoughSheetFields;
use crate::surface::generate::Form;
use crate::surface::gw::GreenwoodWilliamson;
use crate::surface::stats::Characterisation;
use crate::surface::HeightMap;

/// What can go wrong building these figures.
#[derive(Debug, thiserror::Error)]
pub enum SheetError {
    #[error(transparent)]
    Study(#[from] RoughStudyError),
    #[error(transparent)]
    Surface(#[from] crate::study::surface::SurfaceStudyError),
    #[error(transparent)]
    Field(#[from] FieldError),
    #[error(transparent)]
    Fields(#[from] crate::study::rough_sheet::RoughSheetError),
    #[error("this scene has no surface")]
    NoSurface,
}

pub(super) const MAP_WIDTH: u32 = 420;

/// The axes `(x, y)` in µm of the cell centres of `map` shown rolled by `roll` (as stored:
/// [`Roll::NONE`]).
pub(super) fn map_axes_um(map: &HeightMap, roll: Roll) -> (Axis, Axis) {
    let [dx, dy] = map.spacing_m();
    roll.axes(map.shape(), [dx * 1e6, dy * 1e6])
}

/// A map of `values` (`[ny, nx]`, display units) over the surface's plane, on `axes` `(x, y)`
/// in µm.
pub(super) fn xy_map(
    title: &str,
    subtitle: &str,
    axes: (Axis, Axis),
    values: Array2<f64>,
    value_label: &str,
    colormap: ColorMap,
    outlines: Vec<Vec<(f64, f64)>>,
) -> Figure {
    let (x, z) = axes;
    let finite = values.iter().filter(|v| v.is_finite());
    let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
        (a.min(v), b.max(v))
    });
    Figure {
        title: title.into(),
        panels: vec![Panel {
            subtitle: subtitle.into(),
            x,
            z,
            values,
            traction: Vec::new(),
            half_width: 0.0,
            outlines,
            scale: Some(PanelScale {
                value_label: value_label.into(),
                colormap,
                levels: Levels::Count(0),
                range: Some((lo, hi)),
            }),
            peak: None,
            axes: None,
        }],
        value_label: value_label.into(),
        x_label: "x (µm)".into(),
        z_label: "y (µm)".into(),
        vertical_is_depth: false,
        traction_label: String::new(),
        colormap,
        levels: Levels::Count(0),
        mark: Mark::Max,
        panel_width_px: MAP_WIDTH,
    }
}

/// Sets a map of non-negative values (a pressure, a von Mises stress) to colours up to the
/// 99.5 % quantile of its positive values ([`crate::render::robust_top`]): a few cells' spikes
/// no longer darken the rest; values beyond take the top colour (the bar's triangle), and the
/// marked maximum keeps its true value.
fn robust_colours(map: &mut Figure) {
    for panel in &mut map.panels {
        let (top, clipped) = crate::render::robust_top(panel.values.as_slice().unwrap_or(&[]));
        if let (Some(scale), true) = (panel.scale.as_mut(), clipped) {
            if scale.range.is_some_and(|(lo, _)| lo >= 0.0) {
                scale.range = Some((0.0, top));
            }
        }
    }
}

/// The GW model of a characterised surface with measured summits.
pub fn gw_model(c: &Characterisation, e_star_pa: f64) -> GreenwoodWilliamson {
    GreenwoodWilliamson {
        density_per_m2: c.summits.density_per_m2,
        radius_m: c.summits.radius_m,
        height_std_m: c.summits.height_std_m,
        mean_height_m: c.summits.mean_height_m,
        e_star_pa,
    }
}

/// The outlines of the contact spots on the map shown rolled by `roll`: isolines of the
/// loaded-cell indicator at 1/2, in um.
fn spot_outlines(solution: &RoughSolution, roll: Roll) -> Vec<Vec<(f64, f64)>> {
    let indicator = roll.apply(
        solution
            .pressure_pa
            .mapv(|p| if p > 0.0 { 1.0 } else { 0.0 })
            .view(),
    );
    let [dx, dy] = solution.spacing_m;
    let (x, y) = roll.axes([indicator.nrows(), indicator.ncols()], [dx * 1e6, dy * 1e6]);
    crate::render::contour_lines(indicator.view(), &x, &y, 0.5)
}

/// The rough scene's sheet of its solved contact (`solution`, solved by the study; the area
/// against load, of a nominally flat surface, solved by [`rough_study::area_curve`]), its xz
/// section through the report's maximum, all from `fields`, which the study computed through
/// the report's maxima ([`crate::study::drawing::inputs`]). Draws; computes no field.
pub fn rough_sheet(
    scene: &Scene,
    solution: &RoughSolution,
    fields: &RoughSheetFields,
) -> Result<Sheet, SheetError> {
    if scene.contact.kind != ContactKind::Rough {
        return Err(SheetError::NoSurface);
    }
    let surface = scene.surface.as_ref().ok_or(SheetError::NoSurface)?;
    let stress_per_pa = 1.0 / scene.figure.stress_unit.pascals(1.0);
    let unit = scene.figure.stress_unit.label("");
    let unit = unit.trim();
    // The fields under the solved contact, computed by the study
    // ([`crate::study::rough_sheet::sheet_fields`]), and how the maps are shown: a periodic
    // contact's centred on the report's maximum (a contact on the seam whole).
    let roll = fields.roll;
    let axes = map_axes_um(&surface.heights, roll);
    let outlines = spot_outlines(solution, roll);
    let top = surface
        .heights
        .heights_m()
        .iter()
        .fold(f64::NEG_INFINITY, |m, &h| m.max(h));
    let mut spots = format!(
        "{} spots, {:.2} % of the area in contact",
        solution.spots,
        100.0 * solution.contact_fraction
    );
    if solution.periodicity == Periodicity::Periodic {
        spots.push_str("; periodic, centred on the maximum");
    }
    let mut topography = xy_map(
        "Topography and contact spots",
        &spots,
        axes,
        roll.apply(surface.heights.heights_m().mapv(|h| (h - top) * 1e6).view()),
        "height below the top (µm)",
        ColorMap::Viridis,
        outlines.clone(),
    );
    topography.mark = Mark::None;
    let mut pressure = xy_map(
        "Contact pressure",
        &format!(
            "mean {:.1} MPa, max {:.0} MPa",
            solution.mean_pressure_pa * 1e-6,
            solution.max_pressure_pa * 1e-6
        ),
        axes,
        roll.apply(solution.pressure_pa.mapv(|p| p * stress_per_pa).view()),
        &format!("p {unit}"),
        ColorMap::Inferno,
        Vec::new(),
    );
    robust_colours(&mut pressure);

    let section_map = section_figure(scene, solution, fields);
    let quantity = scene.figure.quantity;
    let quantity_label = scene.figure.stress_unit.label(quantity.symbol());
    let values_xy = roll.apply(fields.xy_pa.mapv(|v| v * stress_per_pa).view());
    let mut depth_map = xy_map(
        &format!(
            "{} at the depth of the report's largest {}",
            quantity.description(),
            fields.reported.quantity.symbol()
        ),
        &format!(
            "z = {} µm; spots outlined",
            crate::io::text::approx(fields.xy_depth)
        ),
        axes,
        values_xy,
        &quantity_label,
        scene.figure.colormap,
        outlines,
    );
    if quantity.kind() == crate::stress::QuantityKind::NonNegative {
        robust_colours(&mut depth_map);
    }
    depth_map.levels = scene.figure.levels.clone();
    if let Some(scale) = depth_map.panels[0].scale.as_mut() {
        scale.levels = scene.figure.levels.clone();
    }

    // A rough ball or cylinder: its pressure against the smooth body's (Hertz); a nominally
    // flat surface: its real area against load.
    let area_chart = match (&fields.area_curve, &fields.characterisation, surface.shape) {
        (Some(curve), Some(c), _) => {
            let e_star = rough_study::problem(scene)
                .ok_or(SheetError::NoSurface)?
                .e_star_pa;
            area_against_load(curve.clone(), c, e_star)
        }
        (_, _, shape) => pressure_against_hertz(scene, solution, shape)?,
    };
    let sheet = Sheet {
        notes: rough_study::warnings(scene, solution)
            .into_iter()
            .map(|warning| format!("warning: {warning}"))
            .collect(),
        title: scene
            .title
            .clone()
            .unwrap_or_else(|| format!("Rough contact: {}", surface.source)),
        rows: vec![
            vec![Cell::Map(topography), Cell::Map(pressure)],
            vec![Cell::Map(section_map)],
            vec![Cell::Map(depth_map), Cell::Chart(area_chart)],
        ],
    };
    Ok(sheet)
}

/// The xz section through the report's maximum (`fields`, from
/// [`crate::study::rough_sheet::sheet_fields`]) with the tractions along it above, its subtitle
/// saying where it is and how its marked maximum compares with the report's.
fn section_figure(scene: &Scene, solution: &RoughSolution, fields: &RoughSheetFields) -> Figure {
    let stress_per_pa = 1.0 / scene.figure.stress_unit.pascals(1.0);
    let (friction, poisson) = (scene.contact.friction, scene.contact.poisson);
    let quantity = scene.figure.quantity;
    let xz = &fields.xz;
    let traction: Vec<TractionSample> = fields
        .columns
        .iter()
        .enumerate()
        .map(|(k, &column)| {
            let p = solution.pressure_pa[[fields.row, column]] * stress_per_pa;
            TractionSample {
                x: xz.u.value(k),
                p,
                q: friction * p,
            }
        })
        .collect();
    let y = match xz.section {
        crate::field::Section::Xz { y } => y,
        _ => f64::NAN,
    };
    let reported = &fields.reported;
    let symbol = reported.quantity.symbol();
    let mut subtitle = format!("y = {} µm", crate::io::text::approx(y));
    if fields.centred {
        subtitle.push_str(", centred on the maximum (periodic)");
    }
    subtitle.push_str(&format!("; μ = {friction}, ν = {poisson}; "));
    subtitle.push_str(&section_agreement(scene, fields));
    let values = fields.xz_pa.mapv(|v| v * stress_per_pa);
    let mut outlines = Vec::new();
    let level = crate::figure::yield_level(scene, stress_per_pa);
    if let Some(level) = &level {
        let (lines, note) = level.mark(quantity, &values, &xz.u, &xz.v);
        outlines = lines;
        subtitle.push_str(&format!("; {note}"));
    }
    // A coated body: the interface dashed across the section, both materials named.
    if let Some(coating) = &scene.contact.coating {
        let h = coating.thickness_m / rough_study::REFERENCE_LENGTH_M;
        if h > xz.v.min && h < xz.v.max {
            outlines.push(vec![(xz.u.min, h), (xz.u.max, h)]);
        }
        subtitle = format!(
            "coating {} µm ({}) above the dashed interface, substrate ({}) below; {subtitle}",
            crate::scene::compact(h),
            super::coated::material_name(&coating.material),
            super::coated::material_name(&coating.substrate),
        );
    }
    let quantity_label = scene.figure.stress_unit.label(quantity.symbol());
    // A non-negative quantity's colours to the 99.5 % quantile of the section (a single
    // cell's spike would darken the rest); beyond in the top colour, the maximum labelled.
    // The range never hides the yield line the subtitle promises: where the field reaches
    // the yield level, the top rises to show it and the region beyond.
    let (top, clipped) = crate::render::robust_top(values.as_slice().unwrap_or(&[]));
    let (top, clipped) = match &level {
        Some(level) => level.colour_top(top, values.iter().fold(0.0f64, |m, &v| m.max(v))),
        None => (top, clipped),
    };
    let scale =
        (quantity.kind() == crate::stress::QuantityKind::NonNegative && clipped).then(|| {
            PanelScale {
                value_label: quantity_label.clone(),
                colormap: scene.figure.colormap,
                levels: scene.figure.levels.clone(),
                range: Some((0.0, top)),
            }
        });
    Figure {
        title: format!(
            "{} in the xz section through the report's largest {symbol}",
            quantity.description()
        ),
        panels: vec![Panel {
            subtitle,
            x: xz.u,
            z: xz.v,
            values,
            traction,
            half_width: 0.0,
            outlines,
            scale,
            peak: None,
            axes: None,
        }],
        value_label: quantity_label,
        x_label: "x (µm)".into(),
        z_label: "z (µm)".into(),
        vertical_is_depth: true,
        traction_label: scene
            .figure
            .stress_unit
            .label(if friction > 0.0 { "p, q" } else { "p" }),
        colormap: scene.figure.colormap,
        levels: scene.figure.levels.clone(),
        mark: scene.figure.mark.unwrap_or(Mark::Max),
        panel_width_px: 2 * MAP_WIDTH,
    }
}

/// How the section's marked maximum compares with the report's: the same (to 1e-9 of it), or
/// the difference stated (a sample above the report's, which refines depth only around its
/// best layer; the report's point outside the depth range drawn); for a quantity the report
/// does not search, where the report's von Mises maximum is.
fn section_agreement(scene: &Scene, fields: &RoughSheetFields) -> String {
    let reported = &fields.reported;
    let symbol = reported.quantity.symbol();
    let stress_per_pa = 1.0 / scene.figure.stress_unit.pascals(1.0);
    let unit = scene.figure.stress_unit.symbol();
    let value = |pa: f64| format!("{} {unit}", crate::io::text::approx(pa * stress_per_pa));
    let reported_pa = reported.extreme.value_over_p0 * rough_study::REFERENCE_PRESSURE_PA;
    let at = format!(
        "x = {} µm, z = {} µm",
        crate::io::text::approx(reported.extreme.x_over_a),
        crate::io::text::approx(reported.extreme.z_over_a)
    );
    if scene.figure.quantity != reported.quantity {
        return format!(
            "the report's largest {symbol}, {}, at {at}",
            value(reported_pa)
        );
    }
    let (z0, z1) = (fields.xz.v.min, fields.xz.v.max);
    let z = reported.extreme.z_over_a;
    if !(z >= z0 - 1e-9 * z1.abs() && z <= z1 + 1e-9 * z1.abs()) {
        return format!(
            "the report's largest {symbol}, {}, lies at z = {} µm, outside the depths drawn",
            value(reported_pa),
            crate::io::text::approx(z)
        );
    }
    let largest = fields.xz_largest.value_pa;
    if (largest - reported_pa).abs() <= 1e-9 * reported_pa.abs() {
        return format!("max = the report's {symbol}");
    }
    format!(
        "the marked max differs from the report's largest {symbol}, {} at {at}, by {:+.2} %",
        value(reported_pa),
        100.0 * (largest - reported_pa) / reported_pa
    )
}

/// Real area against mean pressure: the solver at fractions and multiples of the scene's mean
/// pressure, the GW prediction and the linear law.
fn area_against_load(solved: Vec<(f64, f64)>, c: &Characterisation, e_star: f64) -> Chart {
    let mut chart = Chart::log_log(
        "Real area against load",
        "mean pressure p / E*",
        "real area A/A0",
    );
    chart.series.push(Series {
        label: "solved (this surface)".into(),
        points: solved.clone(),
        style: Style::Markers,
        colour: PALETTE[0],
    });
    let gw = gw_model(c, e_star);
    let (lo, hi) = (solved[0].0 / 2.0, solved[solved.len() - 1].0 * 2.0);
    let pressures: Vec<f64> = (0..=30)
        .map(|k| lo * (hi / lo).powf(k as f64 / 30.0))
        .collect();
    chart.series.push(Series {
        label: "Greenwood–Williamson".into(),
        points: pressures
            .iter()
            .map(|&p| (p, gw.area_at_pressure(p * e_star).area_fraction))
            .collect(),
        style: Style::Line,
        colour: PALETTE[2],
    });
    let kappa = (8.0 / PI).sqrt();
    chart.series.push(Series {
        label: format!("κ p/(E* h'rms), κ = {kappa:.2}, h'rms = Sdq = {:.3}", c.sdq),
        points: pressures
            .iter()
            .map(|&p| (p, kappa * p / c.sdq))
            .filter(|p| p.1 < 1.0)
            .collect(),
        style: Style::Dashed,
        colour: PALETTE[1],
    });
    chart
}

/// The pressure under a rough ball (or cylinder) against the Hertz pressure of the smooth one
/// under the same load: around the centre of pressure, the mean over rings a fifteenth of the
/// Hertz radius wide (a cylinder: over strips along its axis y) and the largest in each, and Hertz's
/// `p0 sqrt(1 - r²/a²)` with `a = (3WR/(4E*))^(1/3)`, `p0 = 3W/(2πa²)` (a cylinder: `b` and
/// `p0 = 2W'/(πb)` of the load per unit length `W' = W/Ly`, `b = sqrt(4W'R/(πE*))`; Johnson
/// 1985, §4.2). Roughness spreads the load wider and lower on average while the asperities'
/// peaks exceed p0 (Greenwood & Tripp 1967).
fn pressure_against_hertz(
    scene: &Scene,
    solution: &RoughSolution,
    shape: Form,
) -> Result<Chart, SheetError> {
    let problem = rough_study::problem(scene).ok_or(SheetError::NoSurface)?;
    let e_star = problem.e_star_pa;
    let stress_per_pa = 1.0 / scene.figure.stress_unit.pascals(1.0);
    let unit = scene.figure.stress_unit.label("");
    let ny = solution.pressure_pa.nrows();
    let [dx, dy] = solution.spacing_m;
    let load = solution.load_n;
    let total: f64 = solution.pressure_pa.sum();
    let (mut cx, mut cy) = (0.0, 0.0);
    for ((j, i), &p) in solution.pressure_pa.indexed_iter() {
        cx += p * (i as f64 + 0.5) * dx;
        cy += p * (j as f64 + 0.5) * dy;
    }
    let (cx, cy) = (cx / total, cy / total);
    let (radius_m, cylinder) = match shape {
        Form::Sphere { radius_m } => (radius_m, false),
        Form::Cylinder { radius_m } => (radius_m, true),
        Form::None => return Err(SheetError::NoSurface),
    };
    let (half_width, p0) = if cylinder {
        let per_length = load / (ny as f64 * dy);
        let b = (4.0 * per_length * radius_m / (PI * e_star)).sqrt();
        (b, 2.0 * per_length / (PI * b))
    } else {
        let a = (3.0 * load * radius_m / (4.0 * e_star)).cbrt();
        (a, 3.0 * load / (2.0 * PI * a * a))
    };
    // Rings (strips) a fifteenth of the Hertz radius wide (at least a cell), out to twice it.
    let width = (half_width / 15.0).max(if cylinder { dx } else { dx.max(dy) });
    let bins = ((2.0 * half_width / width).ceil() as usize).max(4);
    let mut sums = vec![(0.0f64, 0usize, 0.0f64); bins];
    for ((j, i), &p) in solution.pressure_pa.indexed_iter() {
        let x = (i as f64 + 0.5) * dx - cx;
        let y = (j as f64 + 0.5) * dy - cy;
        let r = if cylinder { x.abs() } else { x.hypot(y) };
        let bin = (r / width) as usize;
        if let Some(entry) = sums.get_mut(bin) {
            entry.0 += p;
            entry.1 += 1;
            entry.2 = entry.2.max(p);
        }
    }
    let at = |k: usize| (k as f64 + 0.5) * width * 1e6;
    let mean: Vec<(f64, f64)> = sums
        .iter()
        .enumerate()
        .filter(|(_, e)| e.1 > 0)
        .map(|(k, e)| (at(k), e.0 / e.1 as f64 * stress_per_pa))
        .collect();
    let largest: Vec<(f64, f64)> = sums
        .iter()
        .enumerate()
        .filter(|(_, e)| e.1 > 0 && e.2 > 0.0)
        .map(|(k, e)| (at(k), e.2 * stress_per_pa))
        .collect();
    let hertz: Vec<(f64, f64)> = (0..=200)
        .map(|k| {
            let r = 2.0 * half_width * k as f64 / 200.0;
            let p = p0 * (1.0 - (r / half_width).powi(2)).max(0.0).sqrt();
            (r * 1e6, p * stress_per_pa)
        })
        .collect();
    let (axis, ring) = if cylinder {
        ("distance from the centre line |x| (µm)", "strip")
    } else {
        ("radius r from the centre of pressure (µm)", "ring")
    };
    let mut chart = Chart::new(
        &format!(
            "Pressure against the smooth {} (Hertz)",
            if cylinder { "cylinder" } else { "ball" }
        ),
        axis,
        &format!("p {}", unit.trim()),
    );
    chart.series.push(Series {
        label: format!("largest in each {ring}"),
        points: largest,
        style: Style::Markers,
        colour: PALETTE[3],
    });
    chart.series.push(Series {
        label: format!("mean over each {ring}"),
        points: mean,
        style: Style::Line,
        colour: PALETTE[0],
    });
    chart.series.push(Series {
        label: format!(
            "Hertz, smooth{}: {} = {:.1} µm, p0 = {:.0} MPa",
            if scene.contact.coating.is_some() {
                ", uncoated"
            } else {
                ""
            },
            if cylinder { "b" } else { "a" },
            half_width * 1e6,
            p0 * 1e-6
        ),
        points: hertz,
        style: Style::Dashed,
        colour: PALETTE[1],
    });
    chart.x_range = Some((0.0, 2.0 * half_width * 1e6));
    // Head room for the legend above the highest peak.
    let highest = chart
        .series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .fold(0.0, f64::max);
    chart.y_range = Some((0.0, 1.3 * highest));
    Ok(chart)
}

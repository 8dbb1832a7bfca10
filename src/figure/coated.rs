//! The figure of a coated scene: von Mises stress in the plane of sliding (y = 0) through the
//! coating and the substrate, in µm and MPa, with the interface drawn as a dashed line across
//! the map, both materials named in the subtitle, the surface tractions above and the largest
//! value marked. Draws what [`crate::study::coated`] computed; solves nothing.

use ndarray::Array2;

use crate::coating::Side;
use crate::field::Axis;
use crate::render::{ColorMap, Figure, Levels, Mark, Panel, Peak, TractionSample};
use crate::scene::Scene;
use crate::study::coated::CoatedStudy;

/// Rows of the drawn map (depth samples, resampled from the study's rows).
const ROWS: usize = 241;

/// The value at depth `z` on the side of the interface it lies on, interpolated linearly in
/// depth between the study's rows of that side.
fn at_depth(study: &CoatedStudy, z: f64, column: usize) -> f64 {
    let section = &study.section;
    let h = study.spec.thickness_m;
    let side = if z <= h {
        Side::Coating
    } else {
        Side::Substrate
    };
    let rows: Vec<usize> = (0..section.z_m.len())
        .filter(|&r| section.sides[r] == side)
        .collect();
    let mut previous = rows[0];
    for &r in &rows {
        if section.z_m[r] >= z {
            let (z0, z1) = (section.z_m[previous], section.z_m[r]);
            let (v0, v1) = (
                section.von_mises_pa[[previous, column]],
                section.von_mises_pa[[r, column]],
            );
            if z1 <= z0 {
                return v1;
            }
            let t = (z - z0) / (z1 - z0);
            return v0 + t * (v1 - v0);
        }
        previous = r;
    }
    section.von_mises_pa[[previous, column]]
}

/// A material's name for the subtitle: the preset whose constants it has, else its modulus.
pub(super) fn material_name(material: &crate::contact::material::Material) -> String {
    let preset = crate::contact::material::PRESETS
        .iter()
        .chain(crate::contact::material::COATING_PRESETS.iter())
        .find(|p| p.material == *material)
        .map(|p| p.name.replace('_', " "));
    match preset {
        Some(name) => format!("{name}, E = {:.0} GPa", material.modulus_pa * 1e-9),
        None => format!(
            "E = {:.0} GPa, ν = {}",
            material.modulus_pa * 1e-9,
            material.poisson
        ),
    }
}

/// The depth the figure of `study` draws to, m: `max(2a, h + a)`.
pub fn drawn_depth_m(study: &CoatedStudy) -> f64 {
    let a = study.hertz_semi_axes_m[0];
    (2.0 * a).max(study.spec.thickness_m + a)
}

/// The figure (module doc).
pub fn coated_figure(scene: &Scene, study: &CoatedStudy) -> Figure {
    coated_figure_to_depth(scene, study, drawn_depth_m(study))
}

/// The figure drawn to the depth `z_end_m` (a sweep's steps share one frame).
pub fn coated_figure_to_depth(scene: &Scene, study: &CoatedStudy, z_end_m: f64) -> Figure {
    let section = &study.section;
    let a = study.hertz_semi_axes_m[0];
    let h = study.spec.thickness_m;
    let um = 1e6;
    let (x_min, x_max) = (-2.0 * a, 2.0 * a);
    let columns: Vec<usize> = (0..section.x_m.len())
        .filter(|&i| section.x_m[i] >= x_min && section.x_m[i] <= x_max)
        .collect();
    let z_end = z_end_m;
    let mut values = Array2::zeros((ROWS, columns.len()));
    for r in 0..ROWS {
        let z = z_end * r as f64 / (ROWS - 1) as f64;
        for (c, &column) in columns.iter().enumerate() {
            values[[r, c]] = at_depth(study, z, column) * 1e-6;
        }
    }
    let first = section.x_m[columns[0]];
    let last = section.x_m[columns[columns.len() - 1]];
    let traction = columns
        .iter()
        .map(|&i| TractionSample {
            x: section.x_m[i] * um,
            p: section.pressure_pa[i] * 1e-6,
            q: study.friction * section.pressure_pa[i] * 1e-6,
        })
        .collect();
    let m = &study.maxima;
    let subtitle = format!(
        "coating {} µm ({}) above the dashed interface; substrate below ({}); max {:.0} MPa in the {}",
        crate::scene::compact(h * um),
        material_name(&study.spec.material),
        material_name(&study.spec.substrate),
        m.von_mises.value_pa * 1e-6,
        if m.von_mises == m.coating_von_mises {
            "coating"
        } else {
            "substrate"
        }
    );
    Figure {
        title: scene
            .title
            .clone()
            .unwrap_or_else(|| format!("Coated body: von Mises stress, {}", scene.name)),
        panels: vec![Panel {
            subtitle,
            x: Axis::new(first * um, last * um, columns.len()),
            z: Axis::new(0.0, z_end * um, ROWS),
            values,
            traction,
            half_width: study.semi_axes_m[0] * um,
            outlines: vec![vec![(first * um, h * um), (last * um, h * um)]],
            scale: None,
            peak: Some(Peak {
                value: m.von_mises.value_pa * 1e-6,
                x: m.von_mises.x_m * um,
                z: m.von_mises.z_m * um,
            }),
            axes: None,
        }],
        value_label: "σvM (MPa)".to_string(),
        x_label: "x (µm)".to_string(),
        z_label: "z (µm)".to_string(),
        vertical_is_depth: true,
        traction_label: "p, q (MPa)".to_string(),
        colormap: ColorMap::Magma,
        levels: Levels::Count(10),
        mark: Mark::Max,
        panel_width_px: 840,
    }
}

//! The report of a coated scene (`stressfield hertz` of a scene with
//! `[contact.body1.coating]`): a readable table, and the values of the JSON contract.
//!
//! JSON (SI; [`CoatedReport::json_fields`] for the keys of `hertz --json`):
//! `"max_pressure_pa"`, `"contact_radius_m"` (point: `sqrt(area/π)`) or `"half_width_m"`
//! (line), `"contact_area_m2"` (point and elliptical), `"approach_m"` (`null` for a line
//! contact, whose displacements a plane problem defines only up to a constant),
//! `"von_mises_max_pa"`, `"von_mises_max_depth_m"`, and `"coating"`
//! ([`CoatingJson`], [`CoatedReport::json`]): `{"thickness_m", "von_mises_max_pa",
//! "interface_shear_max_pa", "interface_normal_min_pa", "substrate_von_mises_max_pa"}`.

use std::fmt::Write as _;

use serde::Serialize;

use crate::scene::{ContactKind, Scene};
use crate::study::coated::{CoatedStudy, Located};
use crate::study::coated_layers::utilisation;

/// The `"coating"` object of `hertz --json` for a coated scene.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct CoatingJson {
    pub thickness_m: f64,
    /// The largest von Mises stress in the coating (interface included, its coating side).
    pub von_mises_max_pa: f64,
    /// The largest shear traction on the interface, `sqrt(σxz² + σyz²)` at `z = h`.
    pub interface_shear_max_pa: f64,
    /// The most compressive normal stress on the interface, `σzz` at `z = h` (negative).
    pub interface_normal_min_pa: f64,
    pub substrate_von_mises_max_pa: f64,
}

/// The keys of `hertz --json` for a coated scene (with `"coating"` nested).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CoatedJson {
    pub max_pressure_pa: f64,
    /// Point contacts: `sqrt(area / π)`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contact_radius_m: Option<f64>,
    /// Line contacts: half the distance between the refined edges.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub half_width_m: Option<f64>,
    /// Point and elliptical contacts.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contact_area_m2: Option<f64>,
    /// `null` for a line contact.
    pub approach_m: Option<f64>,
    pub von_mises_max_pa: f64,
    pub von_mises_max_depth_m: f64,
    /// `[contact.body1.coating]` scenes.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub coating: Option<CoatingJson>,
    /// `[[contact.body1.layers]]` scenes: one object per layer, top first.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub layers: Option<Vec<LayerJson>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub substrate_von_mises_max_pa: Option<f64>,
    /// With strengths given: each governing stress over its strength.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub utilisation: Option<Vec<UtilisationJson>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub first_failure: Option<FirstFailureJson>,
}

/// One layer of `"layers"` (the interface under it).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct LayerJson {
    pub thickness_m: f64,
    pub von_mises_max_pa: f64,
    /// The largest principal stress (tension positive).
    pub max_tension_pa: f64,
    pub interface_shear_max_pa: f64,
    pub interface_normal_min_pa: f64,
}

/// One entry of `"utilisation"`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct UtilisationJson {
    #[serde(rename = "where")]
    pub place: String,
    pub mode: &'static str,
    pub value: f64,
    pub x_m: f64,
    pub z_m: f64,
}

/// `"first_failure"`: `"load_n"` for point and elliptical contacts, `"load_n_per_m"` for
/// lines.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FirstFailureJson {
    #[serde(rename = "where")]
    pub place: String,
    pub mode: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_n: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_n_per_m: Option<f64>,
}

/// What the report says.
#[derive(Clone, Debug, PartialEq)]
pub struct CoatedReport {
    pub fields: CoatedJson,
}

impl CoatedReport {
    pub fn new(study: &CoatedStudy) -> Self {
        let m = &study.maxima;
        Self {
            fields: CoatedJson {
                max_pressure_pa: study.solution.max_pressure_pa(),
                contact_radius_m: (study.kind == ContactKind::Point)
                    .then_some(study.contact_radius_m),
                half_width_m: (study.kind == ContactKind::Line).then_some(study.semi_axes_m[0]),
                contact_area_m2: (study.kind != ContactKind::Line).then_some(study.contact_area_m2),
                approach_m: study.solution.approach_m(),
                von_mises_max_pa: m.von_mises.value_pa,
                von_mises_max_depth_m: m.von_mises.z_m,
                coating: (!study.spec.stacked).then_some(CoatingJson {
                    thickness_m: study.spec.thickness_m,
                    von_mises_max_pa: m.coating_von_mises.value_pa,
                    interface_shear_max_pa: m.interface_shear.value_pa,
                    interface_normal_min_pa: m.interface_normal_min.value_pa,
                    substrate_von_mises_max_pa: m.substrate_von_mises.value_pa,
                }),
                layers: study.spec.stacked.then(|| {
                    study
                        .layers
                        .iter()
                        .map(|l| LayerJson {
                            thickness_m: l.thickness_m,
                            von_mises_max_pa: l.von_mises.value_pa,
                            max_tension_pa: l.max_tension.value_pa,
                            interface_shear_max_pa: l.interface_shear.value_pa,
                            interface_normal_min_pa: l.interface_normal_min.value_pa,
                        })
                        .collect()
                }),
                substrate_von_mises_max_pa: study
                    .spec
                    .stacked
                    .then_some(m.substrate_von_mises.value_pa),
                utilisation: study.spec.strengths.any().then(|| {
                    utilisation(study)
                        .into_iter()
                        .map(|u| UtilisationJson {
                            place: u.place,
                            mode: u.mode.key(),
                            value: u.value,
                            x_m: u.x_m,
                            z_m: u.z_m,
                        })
                        .collect()
                }),
                first_failure: study.first_failure.as_ref().map(|f| {
                    let line = study.kind == ContactKind::Line;
                    FirstFailureJson {
                        place: f.place.clone(),
                        mode: f.mode.key(),
                        load_n: (!line).then_some(f.load_n),
                        load_n_per_m: line.then_some(f.load_n),
                    }
                }),
            },
        }
    }

    /// The `"coating"` object, to be nested in `hertz --json` (`null` for a stack, which
    /// gives `"layers"`).
    pub fn json(&self) -> serde_json::Value {
        serde_json::to_value(self.fields.coating).unwrap_or(serde_json::Value::Null)
    }

    /// Every key of `hertz --json` for the coated scene, `"coating"` included.
    pub fn json_fields(&self) -> serde_json::Value {
        serde_json::to_value(&self.fields).unwrap_or(serde_json::Value::Null)
    }

    /// The readable table.
    pub fn text(&self, scene: &Scene, study: &CoatedStudy) -> String {
        let mut out = String::new();
        let spec = &study.spec;
        let a = study.hertz_semi_axes_m[0];
        let p0 = study.hertz_p0_pa;
        let mpa = |pa: f64| pa * 1e-6;
        let place = |l: &Located| {
            format!(
                "at x = {:.4} mm, z = {:.4} mm (x = {:.3} a, z = {:.3} a, z = {:.3} h)",
                l.x_m * 1e3,
                l.z_m * 1e3,
                l.x_m / a,
                l.z_m / a,
                l.z_m / spec.thickness_m
            )
        };
        let _ = writeln!(out, "scene {}", scene.name);
        let _ = writeln!(
            out,
            "coated body 1: {:.3} µm of E = {:.0} GPa, ν = {} on E = {:.0} GPa, ν = {}; counter-body {}",
            spec.thickness_m * 1e6,
            spec.material.modulus_pa * 1e-9,
            spec.material.poisson,
            spec.substrate.modulus_pa * 1e-9,
            spec.substrate.poisson,
            if spec.counter_rigid {
                "rigid".to_string()
            } else {
                format!("(1 - ν²)/E = {:.4e} 1/Pa", spec.counter_per_pa)
            }
        );
        let line = study.kind == ContactKind::Line;
        let _ = writeln!(
            out,
            "load                         W  = {} {}, friction μ = {}",
            crate::io::text::approx(study.load_n),
            if line { "N/m" } else { "N" },
            study.friction
        );
        let _ = writeln!(
            out,
            "the coating's Hertz contact  a  = {:.3} µm{}, p0 = {:.2} MPa (the scene's units)",
            a * 1e6,
            if study.kind == ContactKind::Elliptical {
                format!(", b = {:.3} µm", study.hertz_semi_axes_m[1] * 1e6)
            } else {
                String::new()
            },
            mpa(p0)
        );
        let _ = writeln!(
            out,
            "h / a                        {:.4}",
            spec.thickness_m / a
        );
        let [nx, ny] = study.solution.grid();
        if line {
            let _ = writeln!(
                out,
                "coated line contact (plane strain, {nx} strips of {:.3} µm, layered influence coefficients, active set):",
                study.spacing_m[0] * 1e6
            );
        } else {
            let _ = writeln!(
                out,
                "coated contact (DC-FFT, {nx} x {ny} cells of {:.3} µm, layered influence coefficients):",
                study.spacing_m[0] * 1e6
            );
        }
        let peak = study.solution.max_pressure_pa();
        let _ = writeln!(
            out,
            "  peak pressure              {:.2} MPa ({:.4} p0)",
            mpa(peak),
            peak / p0
        );
        if line {
            let _ = writeln!(
                out,
                "  half-width                 {:.3} µm ({:.4} a)",
                study.semi_axes_m[0] * 1e6,
                study.semi_axes_m[0] / a
            );
        } else if study.kind == ContactKind::Point {
            let _ = writeln!(
                out,
                "  contact radius sqrt(A/π)   {:.3} µm ({:.4} a)",
                study.contact_radius_m * 1e6,
                study.contact_radius_m / a
            );
        } else {
            let _ = writeln!(
                out,
                "  semi-axes through centre   {:.3} µm along x, {:.3} µm along y",
                study.semi_axes_m[0] * 1e6,
                study.semi_axes_m[1] * 1e6
            );
        }
        if !line {
            let _ = writeln!(
                out,
                "  contact area               {:.4e} mm²",
                study.contact_area_m2 * 1e6
            );
        }
        if let Some(approach) = study.solution.approach_m() {
            let _ = writeln!(out, "  approach                   {:.4} µm", approach * 1e6);
        }
        let m = &study.maxima;
        let _ = writeln!(out, "stress maxima in the plane of sliding (y = 0):");
        let rows = [
            ("von Mises, anywhere", &m.von_mises),
            ("von Mises in the coating", &m.coating_von_mises),
            ("Tresca (σ1 − σ3)/2, coating", &m.coating_tresca),
            ("von Mises in the substrate", &m.substrate_von_mises),
            ("Tresca, substrate", &m.substrate_tresca),
            ("interface shear", &m.interface_shear),
            ("interface σzz, most compressive", &m.interface_normal_min),
            ("interface σzz, most tensile", &m.interface_normal_max),
            ("surface σxx, most tensile", &m.surface_tension),
        ];
        for (name, located) in rows {
            let _ = writeln!(
                out,
                "  {:<32} {:>9.1} MPa ({:.4} p0) {}",
                name,
                mpa(located.value_pa),
                located.value_pa / p0,
                place(located)
            );
        }
        if spec.stacked {
            let _ = writeln!(out, "per layer, top first (the interface under each):");
            let depths = spec.layered().interface_depths_m();
            for (i, l) in study.layers.iter().enumerate() {
                let _ = writeln!(
                    out,
                    "  layer {} ({:.3} µm, to z = {:.3} µm): von Mises {:.1} MPa {}; largest principal {:.1} MPa {}",
                    i + 1,
                    l.thickness_m * 1e6,
                    depths[i] * 1e6,
                    mpa(l.von_mises.value_pa),
                    place(&l.von_mises),
                    mpa(l.max_tension.value_pa),
                    place(&l.max_tension)
                );
                let _ = writeln!(
                    out,
                    "  interface {}: shear {:.1} MPa {}; σzz most compressive {:.1} MPa",
                    i + 1,
                    mpa(l.interface_shear.value_pa),
                    place(&l.interface_shear),
                    mpa(l.interface_normal_min.value_pa)
                );
            }
            let _ = writeln!(
                out,
                "  substrate: von Mises {:.1} MPa {}",
                mpa(m.substrate_von_mises.value_pa),
                place(&m.substrate_von_mises)
            );
        }
        if spec.strengths.any() {
            let _ = writeln!(out, "strength check (stress over strength at this load):");
            for u in utilisation(study) {
                let _ = writeln!(
                    out,
                    "  {:<12} {:<13} {:.3} at x = {:.4} mm, z = {:.4} mm",
                    u.place,
                    u.mode.key(),
                    u.value,
                    u.x_m * 1e3,
                    u.z_m * 1e3
                );
            }
            match &study.first_failure {
                Some(f) => {
                    let _ = writeln!(
                        out,
                        "first failure: {} ({}) at W = {} {} ({} coated solves; the solve there gives {:.4}; a coated contact is not linear in the load)",
                        f.place,
                        f.mode.key(),
                        crate::io::text::approx(f.load_n),
                        if line { "N/m" } else { "N" },
                        f.solves,
                        f.check
                    );
                }
                None => {
                    let _ = writeln!(
                        out,
                        "first failure: none found (no governing stress is positive)"
                    );
                }
            }
        }
        let layer = if m.von_mises.z_m < spec.thickness_m || (m.von_mises == m.coating_von_mises) {
            "in the coating"
        } else {
            "in the substrate"
        };
        let _ = writeln!(
            out,
            "the largest von Mises stress lies {layer}; the interface carries {:.1} MPa of shear",
            mpa(m.interface_shear.value_pa)
        );
        if std::env::var_os("STRESSFIELD_TIMINGS").is_some() {
            let _ = writeln!(
                out,
                "timings: contact {:.2} s, stresses {:.2} s",
                study.solve_seconds, study.stress_seconds
            );
        }
        out
    }
}

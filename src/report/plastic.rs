//! The report of a `[plasticity]` scene (`stressfield plastic`): readable text, or one JSON
//! object with SI values.
//!
//! JSON keys (the output contract of issue 51, all SI): `load_n`, `yield_strength_pa`,
//! `hardening_modulus_pa`, `converged`, `iterations` (over all steps), `loaded`:
//! {`max_pressure_pa`, `mean_pressure_pa`, `contact_area_m2`, `contact_radius_m` (√(A/π)),
//! `approach_m`, `max_plastic_strain`, `max_plastic_strain_depth_m`, `plastic_zone_depth_m`
//! (the deepest cell with εp > 1e-5), `plastic_volume_m3`, `von_mises_max_pa`,
//! `von_mises_max_depth_m`, `elastic_max_pressure_pa`} and, when unloaded, `unloaded`:
//! {`residual_depth_m`, `residual_von_mises_max_pa`, `residual_von_mises_max_depth_m`,
//! `residual_von_mises_max_r_m`}. A line contact (plane strain) says `load_n_per_m` for
//! `load_n`, `half_width_m` (half the width of the cells in contact) for `contact_radius_m`
//! and `plastic_area_m2` (the plastic zone's area in the x–z section) for `plastic_volume_m3`;
//! its `contact_area_m2` is per metre of length (the width times 1 m), its `approach_m` that of
//! the points at the grid's depth below each surface on the axis, its
//! `residual_von_mises_max_r_m` the distance `|x|`. Definitions in docs/plasticity.md.

use std::fmt::Write as _;

use serde::Serialize;

use crate::study::plastic::{Loaded, PlasticKind, PlasticStudy, Unloaded};

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LoadedReport {
    pub max_pressure_pa: f64,
    pub mean_pressure_pa: f64,
    pub contact_area_m2: f64,
    /// A point contact's (and elliptical, rough); a line's is `half_width_m`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contact_radius_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub half_width_m: Option<f64>,
    pub approach_m: f64,
    pub max_plastic_strain: f64,
    pub max_plastic_strain_depth_m: f64,
    pub plastic_zone_depth_m: f64,
    /// A volume's; a line's is `plastic_area_m2`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_volume_m3: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_area_m2: Option<f64>,
    pub von_mises_max_pa: f64,
    pub von_mises_max_depth_m: f64,
    pub elastic_max_pressure_pa: f64,
}

impl LoadedReport {
    fn of(loaded: &Loaded, line: bool) -> Self {
        let (volume, line) = if line {
            (None, Some(()))
        } else {
            (Some(()), None)
        };
        Self {
            max_pressure_pa: loaded.max_pressure_pa,
            mean_pressure_pa: loaded.mean_pressure_pa,
            contact_area_m2: loaded.contact_area_m2,
            contact_radius_m: volume.map(|_| loaded.contact_radius_m),
            half_width_m: line.map(|_| loaded.contact_radius_m),
            approach_m: loaded.approach_m,
            max_plastic_strain: loaded.max_plastic_strain,
            max_plastic_strain_depth_m: loaded.max_plastic_strain_depth_m,
            plastic_zone_depth_m: loaded.plastic_zone_depth_m,
            plastic_volume_m3: volume.map(|_| loaded.plastic_volume_m3),
            plastic_area_m2: line.map(|_| loaded.plastic_volume_m3),
            von_mises_max_pa: loaded.von_mises_max_pa,
            von_mises_max_depth_m: loaded.von_mises_max_depth_m,
            elastic_max_pressure_pa: loaded.elastic_max_pressure_pa,
        }
    }
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct UnloadedReport {
    pub residual_depth_m: f64,
    pub residual_von_mises_max_pa: f64,
    pub residual_von_mises_max_depth_m: f64,
    pub residual_von_mises_max_r_m: f64,
}

impl UnloadedReport {
    pub(crate) fn of(unloaded: &Unloaded) -> Self {
        Self {
            residual_depth_m: unloaded.residual_depth_m,
            residual_von_mises_max_pa: unloaded.residual_von_mises_max_pa,
            residual_von_mises_max_depth_m: unloaded.residual_von_mises_max_depth_m,
            residual_von_mises_max_r_m: unloaded.residual_von_mises_max_r_m,
        }
    }
}

/// The report of a plastic study.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PlasticReport {
    /// N; a line's is `load_n_per_m`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_n: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_n_per_m: Option<f64>,
    pub yield_strength_pa: f64,
    pub hardening_modulus_pa: f64,
    pub converged: bool,
    pub iterations: usize,
    pub loaded: LoadedReport,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub unloaded: Option<UnloadedReport>,
}

impl PlasticReport {
    pub fn new(study: &PlasticStudy) -> Self {
        let line = study.kind == PlasticKind::Line;
        let load = study.hertz.load();
        Self {
            load_n: (!line).then_some(load),
            load_n_per_m: line.then_some(load),
            yield_strength_pa: study.spec.yield_strength_pa,
            hardening_modulus_pa: study.spec.hardening_modulus_pa,
            converged: study.converged,
            iterations: study.iterations,
            loaded: LoadedReport::of(&study.loaded, line),
            unloaded: study.unloaded.as_ref().map(UnloadedReport::of),
        }
    }

    /// One JSON object.
    pub fn json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// The readable report.
    pub fn text(&self, study: &PlasticStudy) -> String {
        let mut out = String::new();
        let _ = self.write_text(&mut out, study);
        out
    }

    fn write_text(&self, out: &mut String, study: &PlasticStudy) -> std::fmt::Result {
        let y = self.yield_strength_pa;
        let a = study.hertz.size_m();
        let load = study.hertz.load();
        let mpa = |v: f64| v / 1e6;
        let um = |v: f64| v * 1e6;
        let [nz, ny, nx] = study.grid.dims();
        let steps = format!(
            "{} load and {} unload steps; {} iterations, {}",
            study.spec.steps,
            if study.spec.unload {
                study.spec.unload_steps
            } else {
                0
            },
            self.iterations,
            if self.converged {
                "converged"
            } else {
                "NOT converged"
            }
        );
        match &study.kind {
            PlasticKind::Point => {
                writeln!(
                    out,
                    "elastic-plastic point contact (J2, linear hardening; SAM, docs/plasticity.md)"
                )?;
                writeln!(
                    out,
                    "  load {:.4} N, Y = {:.0} MPa, h = {:.0} MPa; Hertz: p0 = {:.0} MPa = {:.3} Y, a = {:.2} µm",
                    load,
                    mpa(y),
                    mpa(self.hardening_modulus_pa),
                    mpa(study.hertz.p0_pa()),
                    study.hertz.p0_pa() / y,
                    um(a)
                )?;
                writeln!(
                    out,
                    "  grid {nx} x {ny} x {nz} cells over ±{} a and {} a deep; {steps}",
                    study.spec.extent_over_a, study.spec.depth_over_a,
                )?;
            }
            PlasticKind::Elliptical(ellipse) => {
                writeln!(
                    out,
                    "elastic-plastic elliptical contact (J2, linear hardening; SAM, docs/plasticity.md)"
                )?;
                writeln!(
                    out,
                    "  load {:.4} N, Y = {:.0} MPa, h = {:.0} MPa; Hertz: p0 = {:.0} MPa = {:.3} Y, a = {:.2} µm (x), b = {:.2} µm (y), √(ab) = {:.2} µm",
                    load,
                    mpa(y),
                    mpa(self.hardening_modulus_pa),
                    mpa(ellipse.p0_pa),
                    ellipse.p0_pa / y,
                    um(ellipse.semi_axis_x_m),
                    um(ellipse.semi_axis_y_m),
                    um(a)
                )?;
                writeln!(
                    out,
                    "  grid {nx} x {ny} x {nz} cells over ±{} a and ±{} b, {} {} deep ({:.2} µm); {steps}",
                    study.spec.extent_over_a,
                    study.spec.extent_over_a,
                    study.spec.depth_over_a,
                    if ellipse.semi_axis_x_m <= ellipse.semi_axis_y_m { "a" } else { "b" },
                    um(study.spec.depth_over_a * ellipse.semi_minor_m()),
                )?;
            }
            PlasticKind::Rough(rough) => {
                writeln!(
                    out,
                    "elastic-plastic rough contact, {} (J2, linear hardening; SAM, docs/plasticity.md)",
                    if rough.periodic { "periodic" } else { "isolated" }
                )?;
                writeln!(
                    out,
                    "  load {:.4} N, Y = {:.0} MPa, h = {:.0} MPa; elastic contact: p_max = {:.0} MPa = {:.3} Y, A = {:.4e} m², largest spot c = {:.3} µm",
                    load,
                    mpa(y),
                    mpa(self.hardening_modulus_pa),
                    mpa(rough.elastic_max_pressure_pa),
                    rough.elastic_max_pressure_pa / y,
                    rough.elastic_contact_area_m2,
                    um(rough.largest_spot_radius_m)
                )?;
                writeln!(
                    out,
                    "  grid {nx} x {ny} x {nz} cells (the map's), {:.3} µm deep ({} c); {steps}",
                    um(study.grid.depth.depth_m()),
                    study.spec.depth_over_a,
                )?;
            }
            PlasticKind::Line => {
                writeln!(
                    out,
                    "elastic-plastic line contact, plane strain (J2, linear hardening; SAM, docs/plasticity.md)"
                )?;
                writeln!(
                    out,
                    "  load {:.4} kN/m, Y = {:.0} MPa, h = {:.0} MPa, mu = {}; Hertz: p0 = {:.0} MPa = {:.3} Y, b = {:.2} µm",
                    load / 1e3,
                    mpa(y),
                    mpa(self.hardening_modulus_pa),
                    study.friction,
                    mpa(study.hertz.p0_pa()),
                    study.hertz.p0_pa() / y,
                    um(a)
                )?;
                writeln!(
                    out,
                    "  grid {nx} x {nz} cells (x, z) over ±{} b and {} b deep; {steps}",
                    study.spec.extent_over_a, study.spec.depth_over_a,
                )?;
            }
        }
        let l = &self.loaded;
        writeln!(out, "loaded")?;
        writeln!(
            out,
            "  max pressure      {:>10.1} MPa ({:.3} Y; elastic {:.1} MPa)",
            mpa(l.max_pressure_pa),
            l.max_pressure_pa / y,
            mpa(l.elastic_max_pressure_pa)
        )?;
        writeln!(
            out,
            "  mean pressure     {:>10.1} MPa ({:.3} Y)",
            mpa(l.mean_pressure_pa),
            l.mean_pressure_pa / y
        )?;
        let unit = match study.kind {
            PlasticKind::Point => "a",
            PlasticKind::Elliptical(_) => "√(ab)",
            PlasticKind::Rough(_) => "elastic",
            PlasticKind::Line => "b",
        };
        let line = study.kind == PlasticKind::Line;
        if let Some(half_width) = l.half_width_m {
            writeln!(
                out,
                "  half-width        {:>10.3} µm ({:.4} b)",
                um(half_width),
                half_width / a
            )?;
        }
        if let Some(radius) = l.contact_radius_m {
            writeln!(
                out,
                "  contact radius    {:>10.3} µm ({:.4} {unit}; √(A/π))",
                um(radius),
                radius / a
            )?;
        }
        if line {
            writeln!(
                out,
                "  approach          {:>10.4} µm (of the points {:.3} µm below the surfaces)",
                um(l.approach_m),
                um(study.grid.depth.depth_m())
            )?;
        } else {
            writeln!(out, "  approach          {:>10.4} µm", um(l.approach_m))?;
        }
        let (zone, zone_unit) = match (l.plastic_volume_m3, l.plastic_area_m2) {
            (Some(volume), _) => (volume, "m³"),
            (None, Some(area)) => (area, "m² in the section"),
            (None, None) => (0.0, "m³"),
        };
        writeln!(
            out,
            "  max plastic strain{:>10.3e} at z = {:.3} µm; plastic zone to z = {:.3} µm, {:.4e} {zone_unit}",
            l.max_plastic_strain,
            um(l.max_plastic_strain_depth_m),
            um(l.plastic_zone_depth_m),
            zone
        )?;
        writeln!(
            out,
            "  von Mises max     {:>10.1} MPa at z = {:.3} µm",
            mpa(l.von_mises_max_pa),
            um(l.von_mises_max_depth_m)
        )?;
        if let PlasticKind::Rough(rough) = &study.kind {
            writeln!(
                out,
                "  plastic areas     surface layer {:.4e} m², footprint {:.4e} m² (of {:.4e} m² in contact)",
                rough.surface_plastic_area_m2, rough.plastic_footprint_m2, l.contact_area_m2
            )?;
            if let (Some(p), Some(area)) = (rough.capped_max_pressure_pa, rough.capped_area_m2) {
                writeln!(
                    out,
                    "  hardness cap      max pressure {:.1} MPa, {:.4e} m² at the cap (the scene's contact.hardness, same map)",
                    mpa(p),
                    area
                )?;
            }
        }
        if let Some(u) = &self.unloaded {
            writeln!(out, "unloaded")?;
            let dent = match study.kind {
                PlasticKind::Rough(_) => "largest dent",
                _ => "dent",
            };
            writeln!(out, "  {dent:<18}{:>10.4} µm", um(u.residual_depth_m))?;
            let r = if line { "|x|" } else { "r" };
            writeln!(
                out,
                "  residual von Mises{:>10.1} MPa at z = {:.3} µm, {r} = {:.3} µm ({:.3} {unit})",
                mpa(u.residual_von_mises_max_pa),
                um(u.residual_von_mises_max_depth_m),
                um(u.residual_von_mises_max_r_m),
                u.residual_von_mises_max_r_m / a
            )?;
        }
        for warning in &study.warnings {
            writeln!(out, "warning: {warning}")?;
        }
        Ok(())
    }
}

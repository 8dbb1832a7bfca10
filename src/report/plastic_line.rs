//! The report of a line `[plasticity]` scene (`stressfield plastic` of a line contact, plane
//! strain): readable text, or one JSON object with SI values.
//!
//! JSON keys (the output contract of issue 51 for lines): `load_n_per_m`,
//! `yield_strength_pa`, `hardening_modulus_pa`, `converged`, `iterations`, `loaded`:
//! {`max_pressure_pa`, `mean_pressure_pa`, `contact_area_m2` (per metre of length: the
//! contact's width times 1 m), `half_width_m`, `approach_m` (of the points at the grid's depth
//! below each surface on the axis), `max_plastic_strain`, `max_plastic_strain_depth_m`,
//! `plastic_zone_depth_m`, `plastic_area_m2` (the zone's area in the x–z section),
//! `von_mises_max_pa`, `von_mises_max_depth_m`, `elastic_max_pressure_pa`} and, when unloaded,
//! `unloaded`: the point contact's keys ([`super::plastic::UnloadedReport`]), `r` being `|x|`.
//! Definitions in docs/plasticity.md.

use std::fmt::Write as _;

use serde::Serialize;

use super::plastic::UnloadedReport;
use crate::study::plastic::line::{LineLoaded, LinePlasticStudy};

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LineLoadedReport {
    pub max_pressure_pa: f64,
    pub mean_pressure_pa: f64,
    pub contact_area_m2: f64,
    pub half_width_m: f64,
    pub approach_m: f64,
    pub max_plastic_strain: f64,
    pub max_plastic_strain_depth_m: f64,
    pub plastic_zone_depth_m: f64,
    pub plastic_area_m2: f64,
    pub von_mises_max_pa: f64,
    pub von_mises_max_depth_m: f64,
    pub elastic_max_pressure_pa: f64,
}

impl LineLoadedReport {
    fn of(loaded: &LineLoaded) -> Self {
        Self {
            max_pressure_pa: loaded.max_pressure_pa,
            mean_pressure_pa: loaded.mean_pressure_pa,
            contact_area_m2: loaded.contact_area_m2,
            half_width_m: loaded.half_width_m,
            approach_m: loaded.approach_m,
            max_plastic_strain: loaded.max_plastic_strain,
            max_plastic_strain_depth_m: loaded.max_plastic_strain_depth_m,
            plastic_zone_depth_m: loaded.plastic_zone_depth_m,
            plastic_area_m2: loaded.plastic_area_m2,
            von_mises_max_pa: loaded.von_mises_max_pa,
            von_mises_max_depth_m: loaded.von_mises_max_depth_m,
            elastic_max_pressure_pa: loaded.elastic_max_pressure_pa,
        }
    }
}

/// The report of a line plastic study.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LinePlasticReport {
    pub load_n_per_m: f64,
    pub yield_strength_pa: f64,
    pub hardening_modulus_pa: f64,
    pub converged: bool,
    pub iterations: usize,
    pub loaded: LineLoadedReport,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub unloaded: Option<UnloadedReport>,
}

impl LinePlasticReport {
    pub fn new(study: &LinePlasticStudy) -> Self {
        Self {
            load_n_per_m: study.hertz.load_n_per_m,
            yield_strength_pa: study.spec.yield_strength_pa,
            hardening_modulus_pa: study.spec.hardening_modulus_pa,
            converged: study.converged,
            iterations: study.iterations,
            loaded: LineLoadedReport::of(&study.loaded),
            unloaded: study.unloaded.as_ref().map(UnloadedReport::of),
        }
    }

    /// One JSON object.
    pub fn json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// The readable report.
    pub fn text(&self, study: &LinePlasticStudy) -> String {
        let mut out = String::new();
        let _ = self.write_text(&mut out, study);
        out
    }

    fn write_text(&self, out: &mut String, study: &LinePlasticStudy) -> std::fmt::Result {
        let y = self.yield_strength_pa;
        let b = study.hertz.half_width_m;
        let mpa = |v: f64| v / 1e6;
        let um = |v: f64| v * 1e6;
        let [nz, nx] = study.grid.dims();
        writeln!(
            out,
            "elastic-plastic line contact, plane strain (J2, linear hardening; SAM, docs/plasticity.md)"
        )?;
        writeln!(
            out,
            "  load {:.4} kN/m, Y = {:.0} MPa, h = {:.0} MPa, mu = {}; Hertz: p0 = {:.0} MPa = {:.3} Y, b = {:.2} µm",
            self.load_n_per_m / 1e3,
            mpa(y),
            mpa(self.hardening_modulus_pa),
            study.friction,
            mpa(study.hertz.p0_pa),
            study.hertz.p0_pa / y,
            um(b)
        )?;
        writeln!(
            out,
            "  grid {nx} x {nz} cells (x, z) over ±{} b and {} b deep; {} load and {} unload steps; {} iterations, {}",
            study.spec.extent_over_a,
            study.spec.depth_over_a,
            study.spec.steps,
            if study.spec.unload { study.spec.unload_steps } else { 0 },
            self.iterations,
            if self.converged { "converged" } else { "NOT converged" }
        )?;
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
        writeln!(
            out,
            "  half-width        {:>10.3} µm ({:.4} b)",
            um(l.half_width_m),
            l.half_width_m / b
        )?;
        writeln!(
            out,
            "  approach          {:>10.4} µm (of the points {:.3} µm below the surfaces)",
            um(l.approach_m),
            um(study.grid.depth.depth_m())
        )?;
        writeln!(
            out,
            "  max plastic strain{:>10.3e} at z = {:.3} µm; plastic zone to z = {:.3} µm, {:.4e} m² in the section",
            l.max_plastic_strain,
            um(l.max_plastic_strain_depth_m),
            um(l.plastic_zone_depth_m),
            l.plastic_area_m2
        )?;
        writeln!(
            out,
            "  von Mises max     {:>10.1} MPa at z = {:.3} µm",
            mpa(l.von_mises_max_pa),
            um(l.von_mises_max_depth_m)
        )?;
        if let Some(u) = &self.unloaded {
            writeln!(out, "unloaded")?;
            writeln!(
                out,
                "  dent              {:>10.4} µm",
                um(u.residual_depth_m)
            )?;
            writeln!(
                out,
                "  residual von Mises{:>10.1} MPa at z = {:.3} µm, |x| = {:.3} µm ({:.3} b)",
                mpa(u.residual_von_mises_max_pa),
                um(u.residual_von_mises_max_depth_m),
                um(u.residual_von_mises_max_r_m),
                u.residual_von_mises_max_r_m / b
            )?;
        }
        for warning in &study.warnings {
            writeln!(out, "warning: {warning}")?;
        }
        Ok(())
    }
}

//! The report of a wear scene (`stressfield wear`): a readable table, one row per step, or one
//! JSON object with SI values.
//!
//! JSON keys (the output contract, all SI): `load_n`, `hardness_pa` (null without a hardness),
//! `coefficient_m2_per_n` (null for a measured series), and `steps`, an array whose first
//! entry is the unworn contact (distance 0, or a series' first map), each with
//! `sliding_distance_m`, `contact_area_m2`, `plastic_area_m2` (cells at the hardness cap
//! times the cell area), `spots`, `max_pressure_pa`, `mean_pressure_pa` (the load over the
//! nominal area, as `contact` reports it), `worn_volume_m3`, `max_wear_depth_m`,
//! `von_mises_max_pa`, `von_mises_max_depth_m`, `iterations`, and with `[thermal]`
//! `max_temperature_rise_k`. Also, per step: `mean_contact_pressure_pa` (the load over the real
//! contact area), `plastic_volume_m3` (the plastic flattening so far, displaced and not worn),
//! `max_shear_max_pa` and `max_shear_max_depth_m` (Tresca, (σ1 − σ3)/2), `scar_area_m2` (the
//! area worn so far: wear depth above a thousandth of the deepest), `file` (a series'
//! map); and at the top `kind` (`"archard"` or `"series"`), `distance_m`, `scheme`,
//! `e_star_pa`, `friction`, `poisson`, `periodic`, `rows`, `columns`, `spacing_m`, `coupled`,
//! `warnings` (an array of sentences, empty when there is nothing to say: a series' map that
//! stands higher than the first, which is not wear).

use std::fmt::Write as _;

use serde::Serialize;

use crate::scene::Scene;
use crate::study::rough::{REFERENCE_LENGTH_M, REFERENCE_PRESSURE_PA};
use crate::study::wear::{WearKind, WearStudy, WearStudyStep};

/// One step of the report.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct StepReport {
    pub sliding_distance_m: f64,
    pub contact_area_m2: f64,
    pub plastic_area_m2: f64,
    pub scar_area_m2: f64,
    pub spots: usize,
    pub max_pressure_pa: f64,
    pub mean_pressure_pa: f64,
    pub mean_contact_pressure_pa: f64,
    pub worn_volume_m3: f64,
    pub max_wear_depth_m: f64,
    pub plastic_volume_m3: f64,
    pub von_mises_max_pa: f64,
    pub von_mises_max_depth_m: f64,
    pub max_shear_max_pa: f64,
    pub max_shear_max_depth_m: f64,
    pub iterations: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_temperature_rise_k: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub file: Option<String>,
}

impl StepReport {
    /// The report of one step.
    pub fn of(step: &WearStudyStep) -> Self {
        let maxima = &step.maxima;
        Self {
            sliding_distance_m: step.sliding_distance_m,
            contact_area_m2: step.contact_area_m2(),
            plastic_area_m2: step.plastic_area_m2(),
            scar_area_m2: step.scar_area_m2(),
            spots: step.solution.spots,
            max_pressure_pa: step.solution.max_pressure_pa,
            mean_pressure_pa: step.solution.mean_pressure_pa,
            mean_contact_pressure_pa: step.mean_contact_pressure_pa(),
            worn_volume_m3: step.worn_volume_m3,
            max_wear_depth_m: step.max_wear_depth_m,
            plastic_volume_m3: step.plastic_volume_m3,
            von_mises_max_pa: maxima.von_mises.value_over_p0 * REFERENCE_PRESSURE_PA,
            von_mises_max_depth_m: maxima.von_mises.z_over_a * REFERENCE_LENGTH_M,
            max_shear_max_pa: maxima.max_shear.value_over_p0 * REFERENCE_PRESSURE_PA,
            max_shear_max_depth_m: maxima.max_shear.z_over_a * REFERENCE_LENGTH_M,
            iterations: step.solution.iterations,
            max_temperature_rise_k: step.max_temperature_rise_k,
            file: step.source.clone(),
        }
    }
}

/// What the report says.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct WearReport {
    pub kind: &'static str,
    pub load_n: f64,
    pub hardness_pa: Option<f64>,
    pub coefficient_m2_per_n: Option<f64>,
    /// The total sliding distance (the last step's).
    pub distance_m: f64,
    pub scheme: &'static str,
    pub e_star_pa: f64,
    pub friction: f64,
    pub poisson: f64,
    pub periodic: bool,
    pub rows: usize,
    pub columns: usize,
    pub spacing_m: [f64; 2],
    pub coupled: bool,
    pub steps: Vec<StepReport>,
    /// Sentences the reader should be told (a series' map standing higher than the first).
    pub warnings: Vec<String>,
}

impl WearReport {
    pub fn new(study: &WearStudy) -> Self {
        let (rows, columns) = study
            .steps
            .first()
            .map_or((0, 0), |s| s.solution.pressure_pa.dim());
        let (kind, coefficient, scheme) = match study.kind {
            WearKind::Archard {
                coefficient_m2_per_n,
                ..
            } => (
                "archard",
                Some(coefficient_m2_per_n),
                "Archard's law, backward Euler (the wear of each step from the pressure at its end); plastic penetration at the cap kept as flattening",
            ),
            WearKind::Series => (
                "series",
                None,
                "measured topographies, each solved as a static contact; wear = the first map less each map, less the offset the unworn cells share",
            ),
        };
        let first = study.steps.first();
        Self {
            kind,
            load_n: study.load_n,
            hardness_pa: study.hardness_pa,
            coefficient_m2_per_n: coefficient,
            distance_m: study.steps.last().map_or(0.0, |s| s.sliding_distance_m),
            scheme,
            e_star_pa: study.e_star_pa,
            friction: study.friction,
            poisson: study.poisson,
            periodic: first.is_some_and(|s| {
                s.solution.periodicity == crate::operator::elastic::Periodicity::Periodic
            }),
            rows,
            columns,
            spacing_m: first.map_or([0.0; 2], |s| s.solution.spacing_m),
            coupled: study.coupled,
            steps: study.steps.iter().map(StepReport::of).collect(),
            warnings: study.warnings.clone(),
        }
    }

    /// One JSON object.
    pub fn json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// The readable table.
    pub fn text(&self, scene: &Scene) -> String {
        let mut out = String::new();
        let _ = self.write_text(&mut out, scene);
        out
    }

    fn write_text(&self, out: &mut String, scene: &Scene) -> std::fmt::Result {
        writeln!(out, "scene {}", scene.name)?;
        if let Some(surface) = &scene.surface {
            let [dx, dy] = self.spacing_m;
            writeln!(
                out,
                "surface: {} ({} x {} samples, {:.4} x {:.4} µm each)",
                surface.source,
                self.columns,
                self.rows,
                dx * 1e6,
                dy * 1e6
            )?;
        }
        writeln!(
            out,
            "contact: {}, load {} N, E* = {:.2} GPa, friction {}, body 1 Poisson ratio {}{}",
            if self.periodic {
                "periodic"
            } else {
                "isolated (non-periodic, DC-FFT)"
            },
            crate::scene::compact(self.load_n),
            self.e_star_pa * 1e-9,
            self.friction,
            self.poisson,
            match self.hardness_pa {
                Some(h) => format!(", hardness cap {:.1} MPa", h * 1e-6),
                None => String::new(),
            }
        )?;
        match self.coefficient_m2_per_n {
            Some(k) => writeln!(
                out,
                "wear: Archard, k = {:.4e} mm³/(N m), {} m in {} steps; backward Euler; plastic penetration at the cap kept as flattening",
                k * 1e9,
                crate::scene::compact(self.distance_m),
                self.steps.len().saturating_sub(1)
            )?,
            None => writeln!(
                out,
                "wear: a measured series of {} topographies, each solved as a static contact; the wear is the first map less each, less the offset of datum the unworn cells share; {}",
                self.steps.len(),
                series_levelling(scene)
            )?,
        }
        if self.coupled {
            writeln!(out, "heating: coupled (each step's contact is the thermo-mechanical one; the bulge wears nothing)")?;
        }
        writeln!(out)?;
        let thermal = self
            .steps
            .iter()
            .any(|s| s.max_temperature_rise_k.is_some());
        let mut header = String::from(
            "  distance (m)  area (mm²)  plastic (µm²)  scar (mm²)  spots  p max (MPa)  p mean (MPa)  worn (µm³)  depth (µm)  σvM max (MPa) at z (µm)  Tresca max (MPa) at z (µm)",
        );
        if thermal {
            header.push_str("  ΔT max (K)");
        }
        header.push_str("  iterations");
        writeln!(out, "{header}")?;
        for step in &self.steps {
            let mut row = format!(
                "  {:>12}  {:>10.5}  {:>13.2}  {:>10.5}  {:>5}  {:>11.1}  {:>12.1}  {:>10.2}  {:>10.4}  {:>13.1} at {:>6.2}  {:>16.1} at {:>6.2}",
                crate::scene::compact(step.sliding_distance_m),
                step.contact_area_m2 * 1e6,
                step.plastic_area_m2 * 1e12,
                step.scar_area_m2 * 1e6,
                step.spots,
                step.max_pressure_pa * 1e-6,
                step.mean_contact_pressure_pa * 1e-6,
                step.worn_volume_m3 * 1e18,
                step.max_wear_depth_m * 1e6,
                step.von_mises_max_pa * 1e-6,
                step.von_mises_max_depth_m * 1e6,
                step.max_shear_max_pa * 1e-6,
                step.max_shear_max_depth_m * 1e6,
            );
            if let Some(t) = step.max_temperature_rise_k {
                row.push_str(&format!("  {t:>10.1}"));
            }
            row.push_str(&format!("  {:>10}", step.iterations));
            if let Some(file) = &step.file {
                row.push_str(&format!("  {file}"));
            }
            writeln!(out, "{row}")?;
        }
        writeln!(
            out,
            "(area: the real contact area; scar: the area worn so far; p mean: the load over the real contact area; worn: the worn volume so far, Archard's k W s for simulated wear; depth: the deepest wear so far; maxima of DC-FFT layers under each step, as `contact` searches them)"
        )?;
        for warning in &self.warnings {
            writeln!(out, "warning: {warning}")?;
        }
        Ok(())
    }
}

/// How a series' maps were levelled, in words (issue 50: one datum for the specimen).
fn series_levelling(scene: &Scene) -> String {
    use crate::scene::{Levelling, SeriesDatum};
    let Some(surface) = &scene.surface else {
        return String::new();
    };
    let what = match surface.levelling {
        None | Some(Levelling::Raw) => {
            return "the maps solved as measured (level = \"none\")".into()
        }
        Some(Levelling::Mean { .. }) => "mean height",
        Some(Levelling::Removed(datum)) => match datum.form() {
            crate::surface::stats::FormRemoval::Plane => "least-squares plane",
            crate::surface::stats::FormRemoval::Quadratic => "least-squares second-order form",
        },
    };
    match &surface.series_datum {
        Some(SeriesDatum::Each) => format!("each map levelled by its own {what} (datum = \"each\")"),
        Some(SeriesDatum::Region { x_m, y_m }) => format!(
            "each map levelled by its {what} over x {:.1} to {:.1} µm, y {:.1} to {:.1} µm (datum_region)",
            x_m[0] * 1e6,
            x_m[1] * 1e6,
            y_m[0] * 1e6,
            y_m[1] * 1e6
        ),
        Some(SeriesDatum::First) | None => {
            format!("every map levelled by the first map's {what} (one datum for the specimen)")
        }
    }
}

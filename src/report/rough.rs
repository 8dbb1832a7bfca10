//! The report of a solved rough contact (`stressfield contact`, and `hertz` of a rough scene):
//! a readable table or one JSON object with SI values.
//!
//! JSON keys (the output contract, all SI): `contact_fraction`, `spots`, `load_n`,
//! `mean_pressure_pa`, `max_pressure_pa`, `approach_m`, `mean_gap_m`, `iterations`, `residual`,
//! `von_mises_max_pa`, `von_mises_max_depth_m`, and also `largest_spot_cells`,
//! `max_shear_max_pa`, `max_shear_max_depth_m`, `plastic_cells`, `plasticity_index` (null
//! without a hardness), `e_star_pa`, `hardness_pa`, `friction`, `poisson`, `periodic`,
//! `rows`, `columns`, `spacing_m`, `tolerance`, `search_depth_m`, `warnings` (an array of
//! sentences, empty when the solution gives no cause: [`crate::study::rough::warnings`]),
//! `levelling` (null for a generated map, else `{"removed": "plane" | "quadratic" | "mean" |
//! "none", "plane_m": [c0, c1, c2]}`: what was removed from the measured map before solving
//! ("mean": only its mean height, the default of a periodic contact), and its least-squares
//! plane c0 + c1 x + c2 y in m and m/m, x and y from its first sample, removed or kept; null
//! `plane_m` when nothing was removed), and for a coated body 1 `coating` (absent otherwise):
//! `{"thickness_m", "von_mises_max_pa", "interface_shear_max_pa", "interface_normal_min_pa",
//! "substrate_von_mises_max_pa"}`, the same object as `hertz --json` of a coated point or line
//! scene ([`crate::report::coated::CoatingJson`]).

use std::fmt::Write as _;

use serde::Serialize;

use crate::contact::rough::RoughSolution;
use crate::scene::Scene;
use crate::study::rough::{ContactFindings, REFERENCE_LENGTH_M, REFERENCE_PRESSURE_PA};

/// What the report says.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ContactReport {
    pub contact_fraction: f64,
    pub spots: usize,
    pub largest_spot_cells: usize,
    pub load_n: f64,
    pub mean_pressure_pa: f64,
    pub max_pressure_pa: f64,
    pub approach_m: f64,
    pub mean_gap_m: f64,
    pub iterations: usize,
    pub residual: f64,
    pub tolerance: f64,
    pub von_mises_max_pa: f64,
    pub von_mises_max_depth_m: f64,
    pub max_shear_max_pa: f64,
    pub max_shear_max_depth_m: f64,
    /// How deep the maxima were searched.
    pub search_depth_m: f64,
    pub plastic_cells: usize,
    pub plasticity_index: Option<f64>,
    pub e_star_pa: f64,
    pub hardness_pa: Option<f64>,
    pub friction: f64,
    pub poisson: f64,
    pub periodic: bool,
    pub rows: usize,
    pub columns: usize,
    pub spacing_m: [f64; 2],
    /// What the reader should be told about the solution (few cells, an impossible peak).
    pub warnings: Vec<String>,
    /// What was removed from a measured map before solving (`None` for a generated map).
    pub levelling: Option<LevellingReport>,
    /// A coated body's maxima in the coating, on the interface and in the substrate.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub coating: Option<super::coated::CoatingJson>,
    /// Where the coated maxima lie, for the readable table (not in the JSON).
    #[serde(skip)]
    pub coating_places: Option<crate::study::coated_rough::CoatingMaxima>,
}

/// What was removed from a measured map before its contact was solved.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LevellingReport {
    /// "plane", "quadratic", "mean" or "none".
    pub removed: &'static str,
    /// The map's least-squares plane `[c0, c1, c2]` (m, m/m, m/m), removed or kept (null as measured).
    pub plane_m: Option<[f64; 3]>,
}

impl LevellingReport {
    pub fn of(levelling: crate::scene::Levelling) -> Self {
        Self {
            removed: levelling.removed(),
            plane_m: levelling.plane_m(),
        }
    }

    /// One line for the readable report.
    pub fn sentence(&self) -> String {
        match (self.removed, self.plane_m) {
            (_, None) => "heights solved as measured (level = \"none\": no plane removed)".into(),
            ("mean", Some([_, sx, sy])) => format!(
                "a periodic map: only its mean height removed before solving (a plane is not periodic; its slopes {sx:.3e} along x, {sy:.3e} along y kept; level = \"plane\" removes them and steps the seam)"
            ),
            (form, Some([_, sx, sy])) => format!(
                "levelled before solving: the least-squares {} removed (the measured map's slopes {:.3e} along x, {:.3e} along y; level = \"none\" keeps them)",
                if form == "quadratic" { "second-order form" } else { "mean plane" },
                sx,
                sy
            ),
        }
    }
}

impl ContactReport {
    /// The report of `solution`, the scene's solved contact, with what the study found under
    /// it ([`crate::study::rough::findings`]).
    pub fn new(scene: &Scene, solution: &RoughSolution, findings: &ContactFindings) -> Self {
        let spec = scene.contact.rough.unwrap_or(crate::scene::RoughSpec {
            control: None,
            periodic: false,
            e_star_pa: None,
            hardness_pa: None,
            tolerance: crate::contact::rough::DEFAULT_TOLERANCE,
            max_iterations: crate::contact::rough::DEFAULT_MAX_ITERATIONS,
        });
        Self {
            levelling: scene
                .surface
                .as_ref()
                .and_then(|s| s.levelling)
                .map(LevellingReport::of),
            ..Self::of(
                &spec,
                scene.contact.friction,
                scene.contact.poisson,
                solution,
                findings,
            )
        }
    }

    /// The report of `solution`, solved as `spec` says, under body 1's `friction` and
    /// `poisson` (without a scene: the Python package's `contact` on a height array).
    pub fn of(
        spec: &crate::scene::RoughSpec,
        friction: f64,
        poisson: f64,
        solution: &RoughSolution,
        findings: &ContactFindings,
    ) -> Self {
        let maxima = &findings.maxima;
        let search_depth_m = findings.search_depth_m;
        let plasticity_index = findings.plasticity_index;
        let e_star_pa = spec.e_star_pa.unwrap_or(f64::NAN);
        let (rows, columns) = solution.pressure_pa.dim();
        Self {
            contact_fraction: solution.contact_fraction,
            spots: solution.spots,
            largest_spot_cells: solution.largest_spot_cells,
            load_n: solution.load_n,
            mean_pressure_pa: solution.mean_pressure_pa,
            max_pressure_pa: solution.max_pressure_pa,
            approach_m: solution.approach_m,
            mean_gap_m: solution.mean_gap_m,
            iterations: solution.iterations,
            residual: solution.residual,
            tolerance: spec.tolerance,
            von_mises_max_pa: maxima.von_mises.value_over_p0 * REFERENCE_PRESSURE_PA,
            von_mises_max_depth_m: maxima.von_mises.z_over_a * REFERENCE_LENGTH_M,
            max_shear_max_pa: maxima.max_shear.value_over_p0 * REFERENCE_PRESSURE_PA,
            max_shear_max_depth_m: maxima.max_shear.z_over_a * REFERENCE_LENGTH_M,
            search_depth_m,
            plastic_cells: solution.plastic_cells,
            plasticity_index,
            e_star_pa,
            hardness_pa: spec.hardness_pa,
            friction,
            poisson,
            periodic: spec.periodic,
            rows,
            columns,
            spacing_m: solution.spacing_m,
            warnings: findings.warnings.clone(),
            // Heights given as an array (no scene): solved as given.
            levelling: Some(LevellingReport {
                removed: "none",
                plane_m: None,
            }),
            coating: findings.coating.map(|c| super::coated::CoatingJson {
                thickness_m: c.thickness_m,
                von_mises_max_pa: c.coating_von_mises.value_pa,
                interface_shear_max_pa: c.interface_shear.value_pa,
                interface_normal_min_pa: c.interface_normal_min.value_pa,
                substrate_von_mises_max_pa: c.substrate_von_mises.value_pa,
            }),
            coating_places: findings.coating,
        }
    }

    /// One JSON object.
    pub fn json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// One JSON object with the heating's (`thermal --json`) as the key `thermal`, after the
    /// contact's, when there is one.
    pub fn json_with(&self, thermal: Option<&super::thermal::ThermalReport>) -> String {
        super::with_thermal(self.json(), thermal)
    }

    /// The readable table.
    pub fn text(&self, scene: &Scene) -> String {
        let mut out = String::new();
        let _ = self.write_text(&mut out, scene);
        out
    }

    fn write_text(&self, out: &mut String, scene: &Scene) -> std::fmt::Result {
        let um = |m: f64| m * 1e6;
        let mpa = |pa: f64| pa * 1e-6;
        writeln!(out, "scene {}", scene.name)?;
        if let Some(surface) = &scene.surface {
            let [ny, nx] = surface.heights.shape();
            let [dx, dy] = surface.heights.spacing_m();
            writeln!(
                out,
                "surface: {} ({nx} x {ny} samples, {:.4} x {:.4} µm each{})",
                surface.source,
                um(dx),
                um(dy),
                if surface.counter.is_some() {
                    "; both bodies rough, heights summed"
                } else {
                    ""
                }
            )?;
            if let Some(levelling) = &self.levelling {
                writeln!(out, "{}", levelling.sentence())?;
            }
        }
        writeln!(
            out,
            "contact: {}, E* = {:.2} GPa, friction {}, body 1 Poisson ratio {}",
            if self.periodic {
                "periodic"
            } else {
                "isolated (non-periodic, DC-FFT)"
            },
            self.e_star_pa * 1e-9,
            self.friction,
            self.poisson
        )?;
        if let Some(coating) = &scene.contact.coating {
            writeln!(
                out,
                "coated body 1: {} µm of E = {:.0} GPa, ν = {} on E = {:.0} GPa, ν = {} (E* above: the substrate's with the counter-body, the long waves')",
                crate::scene::compact(coating.thickness_m * 1e6),
                coating.material.modulus_pa * 1e-9,
                coating.material.poisson,
                coating.substrate.modulus_pa * 1e-9,
                coating.substrate.poisson
            )?;
        }
        writeln!(
            out,
            "solver: Polonsky-Keer conjugate gradients{}, {} iterations, residual {:.2e} (tolerance {:.0e})",
            if scene.contact.coating.is_some() {
                " on the layered influence coefficients"
            } else {
                ""
            },
            self.iterations,
            self.residual,
            self.tolerance
        )?;
        writeln!(out)?;
        writeln!(
            out,
            "  load                 {} N",
            crate::scene::compact(self.load_n)
        )?;
        writeln!(
            out,
            "  mean pressure        {:.4} MPa (over the nominal area)",
            mpa(self.mean_pressure_pa)
        )?;
        writeln!(
            out,
            "  max pressure         {:.4} MPa",
            mpa(self.max_pressure_pa)
        )?;
        writeln!(
            out,
            "  real contact area    {:.4} % of the nominal area",
            100.0 * self.contact_fraction
        )?;
        writeln!(
            out,
            "  contact spots        {} (largest {} cells)",
            self.spots, self.largest_spot_cells
        )?;
        writeln!(out, "  approach             {:.5} µm", um(self.approach_m))?;
        writeln!(out, "  mean gap             {:.5} µm", um(self.mean_gap_m))?;
        if let Some(h) = self.hardness_pa {
            writeln!(
                out,
                "  hardness cap         {:.1} MPa, {} cells at the cap",
                mpa(h),
                self.plastic_cells
            )?;
        }
        if let Some(psi) = self.plasticity_index {
            let reading = crate::surface::gw::plasticity_reading(psi);
            writeln!(out, "  plasticity index     {psi:.3} ({reading})")?;
        }
        writeln!(
            out,
            "  von Mises max        {:.4} MPa at depth {:.4} µm",
            mpa(self.von_mises_max_pa),
            um(self.von_mises_max_depth_m)
        )?;
        writeln!(
            out,
            "  max shear (Tresca)   {:.4} MPa at depth {:.4} µm",
            mpa(self.max_shear_max_pa),
            um(self.max_shear_max_depth_m)
        )?;
        let repeat = if self.periodic {
            "; the tractions repeat with the surface"
        } else {
            ""
        };
        if let Some(c) = &self.coating_places {
            let place = |p: &crate::study::coated_rough::Place| {
                format!(
                    "{:.4} MPa at x = {:.3} µm, y = {:.3} µm, z = {:.4} µm",
                    mpa(p.value_pa),
                    um(p.x_m),
                    um(p.y_m),
                    um(p.z_m)
                )
            };
            writeln!(
                out,
                "  von Mises, coating   {}",
                place(&c.coating_von_mises)
            )?;
            writeln!(
                out,
                "  von Mises, substrate {}",
                place(&c.substrate_von_mises)
            )?;
            writeln!(out, "  interface shear      {}", place(&c.interface_shear))?;
            writeln!(
                out,
                "  interface σzz, min   {}",
                place(&c.interface_normal_min)
            )?;
            writeln!(
                out,
                "  (maxima at cell centres of planes of the tractions' layered waves: the first cell's quarters, 12 to 48 depths through the coating, both sides of the interface, then cells and a fifth of their depth below it, refined to a sixteenth of a cell; searched to {:.3} µm{repeat})",
                um(self.search_depth_m),
            )?;
        } else {
            writeln!(
                out,
                "  (maxima at cell centres of DC-FFT layers: quarters of the first cell, then one cell apart to five cells and a fifth of their depth below, refined to a sixteenth of a cell; searched to {:.3} µm{repeat})",
                um(self.search_depth_m),
            )?;
        }
        for warning in &self.warnings {
            writeln!(out, "warning: {warning}")?;
        }
        Ok(())
    }
}

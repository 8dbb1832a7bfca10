//! The lubrication reports: the film and λ block of `hertz` (text, and the `lubrication`
//! object of `hertz --json`), and `ehl`'s numerical solution of a line contact.
//!
//! `hertz --json`'s `lubrication` object (the output contract; SI units):
//! `entrainment_speed_m_per_s`, `central_film_m`, `minimum_film_m`, `film_formula`
//! (`pan_hamrock_1989` or `hamrock_dowson_1977`), `composite_roughness_m` (or `null`),
//! `lambda` (or `null`), `regime` (`boundary`, `mixed`, `full_film`; `null` without a
//! roughness); and besides them `viscosity_pa_s`, `pressure_viscosity_per_pa`, `moes_m`,
//! `moes_l`, `ellipticity` (point and elliptical contacts, else `null`), `warnings` (the
//! formula's doubts, in words) and for spur gears with a pinion speed `gear_path` (per point
//! of the path of contact: `s_m`, `entrainment_speed_m_per_s`, `load_n_per_m`,
//! `central_film_m`, `minimum_film_m`, `lambda`).
//!
//! `ehl --json` (the output contract): `central_film_m`, `minimum_film_m`,
//! `minimum_film_x_m`, `max_pressure_pa`, `hertz_max_pressure_pa`, `half_width_m` (Hertz's),
//! `spike_x_m` (or `null`), `von_mises_max_pa`, `von_mises_max_depth_m`, `moes_m`, `moes_l`,
//! `iterations`, `converged`; and besides them `scene`, `max_pressure_x_m`, `spike_pressure_pa`,
//! `cavitation_x_m`, `von_mises_max_x_m`, `dry_von_mises_max_pa`,
//! `dry_von_mises_max_depth_m`, `load_error`, `grid_spacing_m`, `nodes`, `friction`,
//! `pressure_viscosity_law`, `compressibility`.

use std::fmt::Write;

use serde::Serialize;

use crate::io::text;
use crate::lubrication::density::Compressibility;
use crate::lubrication::film::FilmValidity;
use crate::lubrication::viscosity::PressureViscosity;
use crate::scene::Scene;
use crate::study::ehl::EhlStudy;
use crate::study::lubrication::Lubrication;

/// One point of a gear's path in `hertz --json`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PathPoint {
    pub s_m: f64,
    pub entrainment_speed_m_per_s: f64,
    pub load_n_per_m: f64,
    pub central_film_m: f64,
    pub minimum_film_m: f64,
    pub lambda: Option<f64>,
}

/// `hertz --json`'s `lubrication` object (see the module's key list).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LubricationReport {
    pub entrainment_speed_m_per_s: f64,
    pub central_film_m: f64,
    pub minimum_film_m: f64,
    pub film_formula: &'static str,
    pub composite_roughness_m: Option<f64>,
    pub lambda: Option<f64>,
    pub regime: Option<&'static str>,
    pub viscosity_pa_s: f64,
    pub pressure_viscosity_per_pa: f64,
    pub moes_m: f64,
    pub moes_l: f64,
    pub ellipticity: Option<f64>,
    pub warnings: Vec<String>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub gear_path: Vec<PathPoint>,
}

/// A doubt in words.
fn warning(doubt: &FilmValidity) -> String {
    match doubt {
        FilmValidity::Valid => String::new(),
        FilmValidity::Ellipticity { k } => format!(
            "the ellipticity k = {} lies outside the 1 to 8 of Hamrock & Dowson's fit{}",
            text::significant(*k, 4, 1e6, true),
            if *k < 1.0 {
                " (entrainment along the contact's long axis)"
            } else {
                ""
            }
        ),
        FilmValidity::Rigid {
            film_over_flattening,
        } => format!(
            "the film is {} times the elastic flattening a²/(2Rx): the elastic deflection is small against the film, and the contact leaves the elastohydrodynamic regime for the rigid one (isoviscous-rigid where the pressure raises the viscosity little), where the formula, a fit to elastic-piezoviscous solutions, is not checked; a line contact's film is solved numerically by `stressfield ehl`",
            text::significant(*film_over_flattening, 3, 1e6, true)
        ),
    }
}

impl LubricationReport {
    pub fn new(lubrication: &Lubrication) -> Self {
        Self {
            entrainment_speed_m_per_s: lubrication.lubricant.entrainment_m_per_s,
            central_film_m: lubrication.films.central_m,
            minimum_film_m: lubrication.films.minimum_m,
            film_formula: lubrication.formula.key(),
            composite_roughness_m: lubrication.lubricant.roughness_m,
            lambda: lubrication.lambda,
            regime: lubrication.regime.map(|r| r.key()),
            viscosity_pa_s: lubrication.lubricant.viscosity_pa_s,
            pressure_viscosity_per_pa: lubrication.lubricant.alpha_per_pa,
            moes_m: lubrication.moes.0,
            moes_l: lubrication.moes.1,
            ellipticity: lubrication.ellipticity,
            warnings: lubrication.doubts.iter().map(warning).collect(),
            gear_path: lubrication
                .path
                .iter()
                .map(|p| PathPoint {
                    s_m: p.s_m,
                    entrainment_speed_m_per_s: p.entrainment_m_per_s,
                    load_n_per_m: p.load_n_per_m,
                    central_film_m: p.films.central_m,
                    minimum_film_m: p.films.minimum_m,
                    lambda: p.lambda,
                })
                .collect(),
        }
    }
}

fn um(m: f64) -> String {
    format!("{} µm", text::significant(m * 1e6, 4, 1e6, true))
}

/// `hertz`'s lubrication block, as text.
pub fn text(lubrication: &Lubrication) -> String {
    let mut out = String::new();
    // Writing into a String cannot fail.
    let _ = write_text(&mut out, lubrication);
    out
}

fn write_text(out: &mut String, l: &Lubrication) -> std::fmt::Result {
    let lubricant = &l.lubricant;
    writeln!(out, "lubrication ({}):", l.formula.citation())?;
    if let Some(oil) = lubricant.oil {
        let grade = oil
            .grade
            .map_or_else(String::new, |g| format!("ISO VG {g}, "));
        writeln!(
            out,
            "  lubricant                    {grade}{} mm²/s at 40 °C, {} mm²/s at 100 °C (Walther, ASTM D341): {} mm²/s at {} °C, density {} kg/m³",
            text::significant(oil.kinematic_40c_m2_per_s * 1e6, 4, 1e6, true),
            text::significant(oil.kinematic_100c_m2_per_s * 1e6, 4, 1e6, true),
            text::significant(oil.kinematic_m2_per_s * 1e6, 4, 1e6, true),
            text::fixed(oil.temperature_k - 273.15, 1),
            text::significant(oil.density_kg_per_m3, 4, 1e6, true)
        )?;
    }
    writeln!(
        out,
        "  inlet viscosity              η0 = {} Pa s",
        text::significant(lubricant.viscosity_pa_s, 4, 1e6, true)
    )?;
    writeln!(
        out,
        "  pressure-viscosity           α  = {} GPa⁻¹",
        text::significant(lubricant.alpha_per_pa * 1e9, 4, 1e6, true)
    )?;
    writeln!(
        out,
        "  entrainment speed            u  = {} m/s (u = (u1 + u2)/2, from {})",
        text::significant(lubricant.entrainment_m_per_s, 4, 1e6, true),
        lubricant.entrainment_source
    )?;
    let c = &l.conditions;
    writeln!(
        out,
        "  Hamrock's groups             U = {}, G = {}; Moes M = {}, L = {}",
        text::significant(c.speed_parameter(), 4, 1e3, true),
        text::significant(c.materials_parameter(), 4, 1e6, true),
        text::significant(l.moes.0, 4, 1e6, true),
        text::significant(l.moes.1, 4, 1e6, true)
    )?;
    if let Some(k) = l.ellipticity {
        writeln!(
            out,
            "  ellipticity                  k  = {} (across / along the entrainment)",
            text::significant(k, 4, 1e6, true)
        )?;
    }
    let at = if l.path.is_empty() {
        ""
    } else {
        " (at the pitch point)"
    };
    writeln!(
        out,
        "  central film                 hc = {}{at}",
        um(l.films.central_m)
    )?;
    writeln!(
        out,
        "  minimum film                 hmin = {}{at}",
        um(l.films.minimum_m)
    )?;
    match (lubricant.roughness_m, l.lambda, l.regime) {
        (Some(sigma), Some(lambda), Some(regime)) => {
            writeln!(out, "  composite roughness          σ  = {}", um(sigma))?;
            let words = match regime {
                crate::lubrication::Regime::Boundary => "boundary lubrication (λ < 1)",
                crate::lubrication::Regime::Mixed => "mixed lubrication (1 ≤ λ ≤ 3)",
                crate::lubrication::Regime::FullFilm => "full film (λ > 3)",
            };
            writeln!(
                out,
                "  λ = hmin / σ                 {}: {words}",
                text::significant(lambda, 3, 1e6, true)
            )?;
        }
        _ => writeln!(out, "  λ                            not computed: give lubricant.roughness (the surfaces' composite rms roughness, or both as a list)")?,
    }
    if let Some(thinnest) = l.thinnest_on_path() {
        writeln!(
            out,
            "  along the path of contact    {} points from s = {} to {} mm; thinnest hmin = {} at s = {} mm (u = {} m/s{})",
            l.path.len(),
            text::fixed(l.path[0].s_m * 1e3, 3),
            text::fixed(l.path[l.path.len() - 1].s_m * 1e3, 3),
            um(thinnest.films.minimum_m),
            text::fixed(thinnest.s_m * 1e3, 3),
            text::significant(thinnest.entrainment_m_per_s, 4, 1e6, true),
            thinnest
                .lambda
                .map_or_else(String::new, |lambda| format!(", λ = {}", text::significant(lambda, 3, 1e6, true)))
        )?;
    }
    for doubt in &l.doubts {
        writeln!(out, "  warning: {}", warning(doubt))?;
    }
    Ok(())
}

/// What `ehl --json` says (see the module's key list).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct EhlReport {
    pub scene: String,
    pub central_film_m: f64,
    pub minimum_film_m: f64,
    pub minimum_film_x_m: f64,
    pub max_pressure_pa: f64,
    pub max_pressure_x_m: f64,
    pub hertz_max_pressure_pa: f64,
    pub half_width_m: f64,
    pub spike_x_m: Option<f64>,
    pub spike_pressure_pa: Option<f64>,
    pub cavitation_x_m: f64,
    pub von_mises_max_pa: f64,
    pub von_mises_max_depth_m: f64,
    pub von_mises_max_x_m: f64,
    pub dry_von_mises_max_pa: f64,
    pub dry_von_mises_max_depth_m: f64,
    pub moes_m: f64,
    pub moes_l: f64,
    pub iterations: usize,
    pub converged: bool,
    pub load_error: f64,
    pub grid_spacing_m: f64,
    pub nodes: usize,
    pub friction: f64,
    pub pressure_viscosity_law: &'static str,
    pub compressibility: &'static str,
}

impl EhlReport {
    pub fn new(scene: &Scene, study: &EhlStudy) -> Self {
        let s = &study.solution;
        let (b, ph) = (s.half_width_m, s.hertz_p0_pa);
        Self {
            scene: scene.name.clone(),
            central_film_m: s.central_film_m,
            minimum_film_m: s.minimum_film_m,
            minimum_film_x_m: s.minimum_film_x_m,
            max_pressure_pa: s.max_pressure_pa,
            max_pressure_x_m: s.max_pressure_x_m,
            hertz_max_pressure_pa: ph,
            half_width_m: b,
            spike_x_m: s.spike_x_m,
            spike_pressure_pa: s.spike_pressure_pa,
            cavitation_x_m: s.cavitation_x_m,
            von_mises_max_pa: study.von_mises.value_over_p0 * ph,
            von_mises_max_depth_m: study.von_mises.z_over_a * b,
            von_mises_max_x_m: study.von_mises.x_over_a * b,
            dry_von_mises_max_pa: study.dry_von_mises.value_over_p0 * ph,
            dry_von_mises_max_depth_m: study.dry_von_mises.z_over_a * b,
            moes_m: s.moes_m,
            moes_l: s.moes_l,
            iterations: s.iterations,
            converged: s.converged,
            load_error: s.load_error,
            grid_spacing_m: s.spacing_over_b * b,
            nodes: s.x_m.len(),
            friction: study.friction,
            pressure_viscosity_law: match scene.lubricant.map(|l| l.pressure_viscosity) {
                Some(PressureViscosity::Barus { .. }) => "barus",
                _ => "roelands",
            },
            compressibility: match scene.lubricant.map(|l| l.compressibility) {
                Some(Compressibility::Incompressible) => "constant",
                _ => "dowson_higginson",
            },
        }
    }

    /// One JSON object.
    pub fn json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// The report as text.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let _ = self.write_text(&mut out);
        out
    }

    fn write_text(&self, out: &mut String) -> std::fmt::Result {
        let b = self.half_width_m;
        let mpa = |pa: f64| format!("{} MPa", text::fixed(pa * 1e-6, 1));
        let at = |x: f64| {
            format!(
                "x = {} b ({} mm)",
                text::fixed(x / b, 3),
                text::fixed(x * 1e3, 4)
            )
        };
        writeln!(out, "scene {}", self.scene)?;
        writeln!(
            out,
            "numerical EHL of a line contact: isothermal, steady; Reynolds (cavitation by Reynolds' condition), elastic film, load balance; {} viscosity, {} density; Newton–Raphson on a graded grid (docs/lubrication.md)",
            if self.pressure_viscosity_law == "barus" { "Barus" } else { "Roelands" },
            if self.compressibility == "constant" { "constant" } else { "Dowson–Higginson" }
        )?;
        writeln!(
            out,
            "entrainment in +x: inlet at -x, outlet at +x; lengths in the Hertz half-width b = {} µm",
            text::fixed(b * 1e6, 3)
        )?;
        writeln!(
            out,
            "Moes' parameters             M = {}, L = {}",
            text::significant(self.moes_m, 4, 1e6, true),
            text::significant(self.moes_l, 4, 1e6, true)
        )?;
        writeln!(
            out,
            "central film                 hc = {} µm (x = 0)",
            text::significant(self.central_film_m * 1e6, 4, 1e6, true)
        )?;
        writeln!(
            out,
            "minimum film                 hmin = {} µm at {}",
            text::significant(self.minimum_film_m * 1e6, 4, 1e6, true),
            at(self.minimum_film_x_m)
        )?;
        writeln!(
            out,
            "largest pressure             {} at x = {} b (Hertz p0 = {})",
            mpa(self.max_pressure_pa),
            text::fixed(self.max_pressure_x_m / b, 3),
            mpa(self.hertz_max_pressure_pa)
        )?;
        match (self.spike_x_m, self.spike_pressure_pa) {
            (Some(x), Some(p)) => {
                writeln!(out, "pressure spike               {} at {}", mpa(p), at(x))?
            }
            _ => writeln!(
                out,
                "pressure spike               none (no pressure maximum downstream of the centre)"
            )?,
        }
        writeln!(
            out,
            "film cavitates at            {}",
            at(self.cavitation_x_m)
        )?;
        writeln!(
            out,
            "von Mises under the EHL pressure  {} at x = {} b, z = {} b ({} mm deep); dry Hertz: {} at z = {} b (μ = {})",
            mpa(self.von_mises_max_pa),
            text::fixed(self.von_mises_max_x_m / b, 3),
            text::fixed(self.von_mises_max_depth_m / b, 3),
            text::fixed(self.von_mises_max_depth_m * 1e3, 4),
            mpa(self.dry_von_mises_max_pa),
            text::fixed(self.dry_von_mises_max_depth_m / b, 3),
            text::number(self.friction)
        )?;
        writeln!(
            out,
            "solver                       {} after {} Newton iterations; {} nodes, finest spacing {} b; load carried to {:.1e}",
            if self.converged { "converged" } else { "NOT CONVERGED" },
            self.iterations,
            self.nodes,
            text::significant(self.grid_spacing_m / b, 3, 1e6, true),
            self.load_error
        )?;
        Ok(())
    }
}

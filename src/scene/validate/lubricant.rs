//! The `[lubricant]` table: the oil's viscosity (given, or an ISO VG grade with its kinematic
//! viscosities and the inlet temperature), its pressure-viscosity coefficient and laws, the
//! entrainment speed (given, from the bodies' speeds of `[thermal]`, or from the pinion's speed
//! of spur gears), the surfaces' roughness.

#[allow(clippy::wildcard_imports)]
use super::*;
use crate::lubrication::density::Compressibility;
use crate::lubrication::viscosity::{
    iso_vg_at_40c_m2_per_s, roelands_limit_pa_s, roelands_z_from_alpha, PressureViscosity, Walther,
    ISO_VG_GRADES, ROELANDS_LN_LIMIT, ROELANDS_PRESSURE_PA,
};
use crate::scene::raw::RawLubricant;
use crate::scene::spec::{LubricantSpec, OilSpec, ThermalSpec};

/// Dynamic viscosities, Pa s.
const VISCOSITY_BOUNDS: Bounds = Bounds {
    lo: 1e-5,
    hi: 1e4,
    why: "from a gas (1e-5 Pa s) through water (1e-3) and gear oils (0.01 to 1) to a bitumen (1e4)",
};
/// Kinematic viscosities, m²/s.
const KINEMATIC_BOUNDS: Bounds = Bounds {
    lo: 2e-6,
    hi: 0.1,
    why: "Walther's relation (ASTM D341) holds from 2 mm^2/s; the heaviest gear oils reach a few thousand",
};
/// Pressure-viscosity coefficients, 1/Pa.
const ALPHA_BOUNDS: Bounds = Bounds {
    lo: 1e-10,
    hi: 2e-7,
    why: "from water (0.1 GPa^-1) through mineral oils (15 to 35 GPa^-1) to 200 GPa^-1",
};
/// Densities of a lubricant, kg/m³.
const OIL_DENSITY_BOUNDS: Bounds = Bounds {
    lo: 500.0,
    hi: 2500.0,
    why: "mineral and synthetic oils weigh 800 to 1000 kg/m^3, perfluorinated ones up to 2000",
};
/// Entrainment speeds, m/s.
const ENTRAINMENT_BOUNDS: Bounds = Bounds {
    lo: 1e-6,
    hi: 1e3,
    why: "from a creeping contact (µm/s) to beyond the fastest bearings (a few hundred m/s)",
};
/// Pinion speeds, rad/s.
const PINION_SPEED_BOUNDS: Bounds = Bounds {
    lo: 1e-3,
    hi: 1e5,
    why: "from a creeping drive (0.01 rpm) to beyond turbine gears (1e6 rpm)",
};
/// The rms roughness of a surface, or the composite one, m.
const ROUGHNESS_BOUNDS: Bounds = Bounds {
    lo: 1e-10,
    hi: 1e-3,
    why: "from a polished crystal (0.1 nm) to a cast surface (1 mm)",
};
/// Inlet temperatures, K.
const TEMPERATURE_K: (f64, f64) = (213.15, 673.15);

const SPEED_HINT: &str = "add entrainment_speed = \"2 m/s\" to [lubricant]: the mean u = (u1 + u2)/2 of the two surfaces' speeds relative to the contact (or give the bodies' speeds in [thermal])";

impl Validator<'_> {
    /// With `[lubricant]`, a rigid body is refused before the contact is read: the film
    /// formulas and the EHL solution need both bodies' elasticity (`E' = 2 E*`).
    pub(super) fn lubricated_bodies(&self, raw: &RawScene) -> Result<(), SceneError> {
        if raw.lubricant.is_none() {
            return Ok(());
        }
        for (key, body) in [
            ("contact.body1", &raw.contact.body1),
            ("contact.body2", &raw.contact.body2),
        ] {
            if body
                .as_ref()
                .and_then(|b| b.material.as_deref())
                .is_some_and(|m| m.trim() == "rigid")
            {
                return Err(self.error(
                    &format!("{key}.material"),
                    "a rigid body has no elastic modulus, so the reduced modulus E' = 2 E* of the film formulas and the elastic deflection of the EHL film are undefined",
                    Some("give the body's material (e.g. material = \"steel\") or its modulus and poisson"),
                ));
            }
        }
        Ok(())
    }

    /// `[lubricant]` of a line, point, elliptical or gear scene, or `None` without the table.
    pub(super) fn lubricant(
        &self,
        raw: &RawScene,
        contact: &Contact,
        thermal: Option<&ThermalSpec>,
    ) -> Result<Option<LubricantSpec>, SceneError> {
        let Some(table) = &raw.lubricant else {
            return Ok(None);
        };
        match contact.kind {
            ContactKind::Line | ContactKind::Point | ContactKind::Elliptical => {}
            ContactKind::Tractions => {
                return Err(self.error(
                    "lubricant",
                    "a traction grid from a file has no contact geometry for a film",
                    Some("remove [lubricant]; the film belongs to line, point, elliptical and gear scenes with bodies and a load"),
                ))
            }
            ContactKind::Rough | ContactKind::Surface => {
                return Err(self.error(
                    "lubricant",
                    "the film of a rough contact is not computed",
                    Some("remove [lubricant]; give the rough surfaces' smooth counterpart (a line, point or elliptical scene) with lubricant.roughness set to their composite Sq"),
                ))
            }
        }
        if contact.dimensional.is_none() {
            let given = if contact.scale.is_some() {
                "this contact is given by its size (contact.a, contact.p0)"
            } else {
                "this contact is normalised (a = 1, p0 = 1)"
            };
            return Err(self.error(
                "lubricant",
                format!("the film needs the bodies' radii and elasticity and the load; {given}"),
                Some("give contact.load and [contact.body1] and [contact.body2], each with its radius and material"),
            ));
        }
        if contact.coating.is_some() {
            return Err(self.error(
                "lubricant",
                "the film of a coated body is not computed (the film formulas take homogeneous bodies)",
                Some("remove [lubricant], or the coating"),
            ));
        }
        let (viscosity_pa_s, oil) = self.inlet_viscosity(table)?;
        let law = match table.pressure_viscosity_law.as_deref().map(str::trim) {
            None | Some("roelands") => true,
            Some("barus") => false,
            Some(other) => {
                return Err(self.error(
                    "lubricant.pressure_viscosity_law",
                    format!("unknown law `{}`", crate::io::text::cut(other, 40)),
                    Some("use \"roelands\" (the default) or \"barus\""),
                ))
            }
        };
        let (alpha_per_pa, pressure_viscosity) =
            self.pressure_viscosity(table, viscosity_pa_s, law)?;
        let compressibility = match table.compressibility.as_deref().map(str::trim) {
            None | Some("dowson_higginson") => Compressibility::DowsonHigginson,
            Some("constant") => Compressibility::Incompressible,
            Some(other) => {
                return Err(self.error(
                    "lubricant.compressibility",
                    format!("unknown density law `{}`", crate::io::text::cut(other, 40)),
                    Some("use \"dowson_higginson\" (the default) or \"constant\""),
                ))
            }
        };
        let (entrainment_m_per_s, entrainment_source, pinion_rad_per_s) =
            self.entrainment(raw, table, contact, thermal)?;
        let roughness_m = self.roughness(table)?;
        Ok(Some(LubricantSpec {
            viscosity_pa_s,
            oil,
            alpha_per_pa,
            pressure_viscosity,
            compressibility,
            entrainment_m_per_s,
            entrainment_source,
            pinion_rad_per_s,
            roughness_m,
        }))
    }

    /// The dynamic viscosity at the inlet: `viscosity`, or `η = ρ ν(T)` with `ν(T)` on
    /// Walther's line through the kinematic viscosities at 40 °C (or the grade's) and 100 °C.
    fn inlet_viscosity(&self, table: &RawLubricant) -> Result<(f64, Option<OilSpec>), SceneError> {
        let kinematic_keys = [
            ("lubricant.grade", table.grade.is_some()),
            ("lubricant.viscosity_40c", table.viscosity_40c.is_some()),
            ("lubricant.viscosity_100c", table.viscosity_100c.is_some()),
            ("lubricant.temperature", table.temperature.is_some()),
            ("lubricant.density", table.density.is_some()),
        ];
        if let Some(text) = &table.viscosity {
            if let Some((key, _)) = kinematic_keys.iter().find(|(_, given)| *given) {
                return Err(self.error(
                    key,
                    "the viscosity is given twice: lubricant.viscosity is already the dynamic viscosity at the inlet",
                    Some("give either viscosity (dynamic, at the inlet temperature) or the oil's grade (or viscosity_40c), viscosity_100c, temperature and density"),
                ));
            }
            let value = self.positive("lubricant.viscosity", text, Dimension::DynamicViscosity)?;
            let value = self.within(
                "lubricant.viscosity",
                value,
                text,
                Dimension::DynamicViscosity,
                VISCOSITY_BOUNDS,
            )?;
            return Ok((value, None));
        }
        if kinematic_keys.iter().all(|(_, given)| !given) {
            return Err(self.error(
                "lubricant.viscosity",
                "missing the lubricant's viscosity",
                Some("add viscosity = \"0.05 Pa s\" (dynamic, at the inlet temperature), or grade = \"ISO VG 220\" with viscosity_100c, temperature and density"),
            ));
        }
        let (grade, nu40) = match (&table.grade, &table.viscosity_40c) {
            (Some(_), Some(_)) => {
                return Err(self.error(
                    "lubricant.viscosity_40c",
                    "the viscosity at 40 °C is given twice: an ISO VG grade is its mid-point",
                    Some("give either grade or viscosity_40c"),
                ))
            }
            (Some(grade), None) => {
                let number = self.grade(grade)?;
                let nu40 = iso_vg_at_40c_m2_per_s(number).ok_or_else(|| {
                    let grades: Vec<String> = ISO_VG_GRADES.iter().map(u32::to_string).collect();
                    self.error(
                        "lubricant.grade",
                        format!("{number} is not an ISO VG grade"),
                        Some(&format!("ISO 3448's grades: {}", grades.join(", "))),
                    )
                })?;
                (Some(number), nu40)
            }
            (None, Some(text)) => (
                None,
                self.bounded(
                    "lubricant.viscosity_40c",
                    text,
                    Dimension::KinematicViscosity,
                    KINEMATIC_BOUNDS,
                )?,
            ),
            (None, None) => {
                return Err(self.error(
                    "lubricant.grade",
                    "missing the oil's viscosity at 40 °C",
                    Some("add grade = \"ISO VG 220\" (or viscosity_40c = \"220 mm^2/s\"), or give the dynamic viscosity at the inlet as viscosity = \"0.05 Pa s\""),
                ))
            }
        };
        let nu100_text = table.viscosity_100c.as_ref().ok_or_else(|| {
            self.error(
                "lubricant.viscosity_100c",
                "missing the oil's kinematic viscosity at 100 °C: a grade fixes only the one at 40 °C, and the viscosity at the inlet temperature follows from the two (Walther, ASTM D341)",
                Some("add viscosity_100c from the oil's data sheet, e.g. \"19 mm^2/s\" (a mineral ISO VG 220 gear oil of viscosity index about 95)"),
            )
        })?;
        let nu100 = self.bounded(
            "lubricant.viscosity_100c",
            nu100_text,
            Dimension::KinematicViscosity,
            KINEMATIC_BOUNDS,
        )?;
        let temperature_text = table.temperature.as_ref().ok_or_else(|| {
            self.error(
                "lubricant.temperature",
                "missing the inlet temperature at which the viscosity is taken",
                Some("add temperature = \"70 C\" (the oil's temperature entering the contact)"),
            )
        })?;
        let temperature_k = self.temperature("lubricant.temperature", temperature_text)?;
        let density_text = table.density.as_ref().ok_or_else(|| {
            self.error(
                "lubricant.density",
                "missing the oil's density: the dynamic viscosity is η = ρ ν",
                Some("add density = \"870 kg/m^3\" (the density at the inlet temperature; mineral gear oils: about 850 to 900 kg/m^3)"),
            )
        })?;
        let density = self.bounded(
            "lubricant.density",
            density_text,
            Dimension::Density,
            OIL_DENSITY_BOUNDS,
        )?;
        let walther = Walther::through([(313.15, nu40), (373.15, nu100)]).ok_or_else(|| {
            self.error(
                "lubricant.viscosity_100c",
                format!(
                    "the oil must be thinner at 100 °C than at 40 °C, got {} mm^2/s at 100 °C and {} mm^2/s at 40 °C",
                    crate::io::text::number(nu100 * 1e6),
                    crate::io::text::number(nu40 * 1e6)
                ),
                Some("check viscosity_100c against the oil's data sheet"),
            )
        })?;
        let kinematic = walther.kinematic_m2_per_s(temperature_k);
        if !(kinematic >= KINEMATIC_BOUNDS.lo && kinematic.is_finite()) {
            return Err(self.error(
                "lubricant.temperature",
                format!(
                    "at {} the oil's viscosity falls below 2 mm^2/s, where Walther's relation (ASTM D341) no longer holds",
                    crate::io::text::cut(temperature_text.trim(), 20)
                ),
                Some("give the dynamic viscosity at the inlet directly, as viscosity = \"...\""),
            ));
        }
        let viscosity = density * kinematic;
        let viscosity = self.within(
            "lubricant.temperature",
            viscosity,
            temperature_text,
            Dimension::DynamicViscosity,
            VISCOSITY_BOUNDS,
        )?;
        Ok((
            viscosity,
            Some(OilSpec {
                grade,
                kinematic_40c_m2_per_s: nu40,
                kinematic_100c_m2_per_s: nu100,
                temperature_k,
                density_kg_per_m3: density,
                kinematic_m2_per_s: kinematic,
            }),
        ))
    }

    /// An ISO VG grade: `220`, `"220"`, `"VG 220"` or `"ISO VG 220"`.
    fn grade(&self, value: &NumberOrText) -> Result<u32, SceneError> {
        let text = match value {
            NumberOrText::Number(n) => crate::io::text::number(*n),
            NumberOrText::Text(t) => t.clone(),
        };
        let digits = text
            .trim()
            .trim_start_matches("ISO")
            .trim()
            .trim_start_matches("VG")
            .trim()
            .to_string();
        digits.parse::<u32>().map_err(|_| {
            self.error(
                "lubricant.grade",
                format!(
                    "`{}` is not an ISO VG grade",
                    crate::io::text::cut(text.trim(), 40)
                ),
                Some("write e.g. grade = \"ISO VG 220\""),
            )
        })
    }

    /// A temperature in °C (`"70 C"`, `"70 °C"`, `"70 degC"`) or K (`"343 K"`), as K.
    fn temperature(&self, key: &str, text: &str) -> Result<f64, SceneError> {
        let trimmed = text.trim();
        let (number, offset) = [("°C", 273.15), ("degC", 273.15), ("C", 273.15), ("K", 0.0)]
            .iter()
            .find_map(|(unit, offset)| {
                trimmed
                    .strip_suffix(unit)
                    .map(|number| (number.trim(), *offset))
            })
            .ok_or_else(|| {
                self.error(
                    key,
                    format!(
                        "`{}` is not a temperature",
                        crate::io::text::cut(trimmed, 40)
                    ),
                    Some("write it with its unit, e.g. \"70 C\" or \"343.15 K\""),
                )
            })?;
        let value: f64 = number.parse().map_err(|_| {
            self.error(
                key,
                format!(
                    "`{}` does not start with a number",
                    crate::io::text::cut(trimmed, 40)
                ),
                Some("write e.g. \"70 C\""),
            )
        })?;
        let kelvin = value + offset;
        if !(kelvin >= TEMPERATURE_K.0 && kelvin <= TEMPERATURE_K.1) {
            return Err(self.error(
                key,
                format!(
                    "must lie between -60 C and 400 C, got `{}`",
                    crate::io::text::cut(trimmed, 40)
                ),
                Some("a lubricant's working range; beyond it oils freeze or decompose"),
            ));
        }
        Ok(kelvin)
    }

    /// A value that must be positive, parsed, with a message naming the sign.
    fn positive(&self, key: &str, text: &str, dimension: Dimension) -> Result<f64, SceneError> {
        let value = units::parse(text, dimension).map_err(|m| self.error(key, m, None))?;
        if value <= 0.0 {
            return Err(self.error(
                key,
                format!(
                    "must be positive, got `{}`",
                    crate::io::text::cut(text.trim(), 40)
                ),
                Some(match dimension {
                    Dimension::DynamicViscosity => "a lubricant's viscosity is positive: a gear oil at 70 C is about 0.05 Pa s",
                    Dimension::InversePressure => "a lubricant's viscosity rises with pressure: mineral oils have 15 to 35 GPa^-1",
                    _ => "give a positive value",
                }),
            ));
        }
        Ok(value)
    }

    /// α for the film formulas and the law of the numerical solution: `pressure_viscosity`,
    /// `roelands_z`, or both (α for the formulas, Z for the solution).
    fn pressure_viscosity(
        &self,
        table: &RawLubricant,
        viscosity_pa_s: f64,
        roelands: bool,
    ) -> Result<(f64, PressureViscosity), SceneError> {
        let alpha = match &table.pressure_viscosity {
            Some(text) => {
                let value = self.positive(
                    "lubricant.pressure_viscosity",
                    text,
                    Dimension::InversePressure,
                )?;
                Some(self.within(
                    "lubricant.pressure_viscosity",
                    value,
                    text,
                    Dimension::InversePressure,
                    ALPHA_BOUNDS,
                )?)
            }
            None => None,
        };
        let z = match table.roelands_z {
            Some(z) if !roelands => {
                let _ = z;
                return Err(self.error(
                    "lubricant.roelands_z",
                    "Roelands' index is given, but the numerical solution uses Barus' law",
                    Some("remove roelands_z, or pressure_viscosity_law = \"barus\""),
                ));
            }
            Some(z) if z > 0.0 && z <= 3.0 => Some(z),
            Some(z) => {
                return Err(self.error(
                    "lubricant.roelands_z",
                    format!(
                        "Roelands' pressure-viscosity index must lie in (0, 3], got {}",
                        crate::io::text::number(z)
                    ),
                    Some("mineral oils have Z of about 0.5 to 0.8"),
                ))
            }
            None => None,
        };
        let roelands_possible = viscosity_pa_s > roelands_limit_pa_s();
        if roelands && !roelands_possible {
            return Err(self.error(
                "lubricant.pressure_viscosity_law",
                format!(
                    "Roelands' relation needs a viscosity above 6.3e-5 Pa s (its limit η∞), got {} Pa s",
                    crate::io::text::number(viscosity_pa_s)
                ),
                Some("set pressure_viscosity_law = \"barus\" for so thin a fluid"),
            ));
        }
        match (alpha, z) {
            (Some(alpha), _) if !roelands => Ok((alpha, PressureViscosity::Barus { alpha_per_pa: alpha })),
            (Some(alpha), Some(z)) => Ok((alpha, PressureViscosity::Roelands { z })),
            (Some(alpha), None) => {
                let z = roelands_z_from_alpha(alpha, viscosity_pa_s).ok_or_else(|| {
                    self.error("lubricant.pressure_viscosity_law", "no Roelands index for this viscosity", None)
                })?;
                Ok((alpha, PressureViscosity::Roelands { z }))
            }
            (None, Some(z)) => {
                let alpha = z * (viscosity_pa_s.ln() + ROELANDS_LN_LIMIT) / ROELANDS_PRESSURE_PA;
                Ok((alpha, PressureViscosity::Roelands { z }))
            }
            (None, None) => Err(self.error(
                "lubricant.pressure_viscosity",
                "missing the pressure-viscosity coefficient α",
                Some("add pressure_viscosity = \"20 GPa^-1\" (mineral oils: 15 to 35 GPa^-1; the oil's data or Hamrock's tables)"),
            )),
        }
    }

    /// The entrainment speed, the key it comes from, and the pinion's speed of gears.
    fn entrainment(
        &self,
        raw: &RawScene,
        table: &RawLubricant,
        contact: &Contact,
        thermal: Option<&ThermalSpec>,
    ) -> Result<(f64, &'static str, Option<f64>), SceneError> {
        let gears = contact.dimensional.and_then(|d| d.gears);
        let thermal_pinion = thermal.and_then(|t| t.gear).map(|g| g.pinion_rad_per_s);
        let own_pinion =
            match &table.pinion_speed {
                Some(_) if gears.is_none() => {
                    return Err(self.error(
                        "lubricant.pinion_speed",
                        "a pinion speed belongs to gear scenes",
                        Some(SPEED_HINT),
                    ))
                }
                Some(_) if thermal_pinion.is_some() => return Err(self.error(
                    "lubricant.pinion_speed",
                    "the pinion's speed is given twice: [thermal] pinion_speed already gives it",
                    Some("remove lubricant.pinion_speed"),
                )),
                Some(text) => Some(self.bounded(
                    "lubricant.pinion_speed",
                    text,
                    Dimension::RotationalSpeed,
                    PINION_SPEED_BOUNDS,
                )?),
                None => None,
            };
        let pinion = own_pinion.or(thermal_pinion);
        if let Some(text) = &table.entrainment_speed {
            if pinion.is_some() {
                return Err(self.error(
                    "lubricant.entrainment_speed",
                    "the entrainment speed of gears follows from the pinion's speed along the path of contact",
                    Some("remove entrainment_speed (the pinion's speed gives it at every point of the path), or the pinion's speed"),
                ));
            }
            let value = self.positive("lubricant.entrainment_speed", text, Dimension::Speed)?;
            let value = self.within(
                "lubricant.entrainment_speed",
                value,
                text,
                Dimension::Speed,
                ENTRAINMENT_BOUNDS,
            )?;
            return Ok((value, "lubricant.entrainment_speed", None));
        }
        if let (Some(pair), Some(rad_per_s)) = (gears, pinion) {
            let [v1, v2] = pair.flank_speeds_m_per_s(0.0, rad_per_s);
            let key = if own_pinion.is_some() {
                "lubricant.pinion_speed"
            } else {
                "thermal.pinion_speed"
            };
            return Ok((0.5 * (v1 + v2), key, Some(rad_per_s)));
        }
        if let (Some(table), false) = (&raw.thermal, gears.is_some()) {
            let speeds = self.speeds(table)?;
            let u = 0.5 * (speeds.body1 + speeds.body2);
            if u < ENTRAINMENT_BOUNDS.lo {
                return Err(self.error(
                    "lubricant.entrainment_speed",
                    "the bodies' speeds of [thermal] entrain no lubricant (u = (u1 + u2)/2 = 0)",
                    Some(SPEED_HINT),
                ));
            }
            return Ok((u, "thermal (the bodies' speeds)", None));
        }
        Err(self.error(
            "lubricant.entrainment_speed",
            "missing the entrainment speed: the film grows with the speed at which the surfaces drag the lubricant into the contact",
            Some(if gears.is_some() {
                "add pinion_speed = \"1500 rpm\" to [lubricant] (the flanks' speeds follow along the path of contact), or entrainment_speed for the pitch point alone"
            } else {
                SPEED_HINT
            }),
        ))
    }

    /// The composite rms roughness: one value, or the two surfaces' (`√(σ1² + σ2²)`).
    fn roughness(&self, table: &RawLubricant) -> Result<Option<f64>, SceneError> {
        let key = "lubricant.roughness";
        match &table.roughness {
            None => Ok(None),
            Some(TextOrList::Text(text)) => {
                let value = self.positive(key, text, Dimension::Length)?;
                Ok(Some(self.within(key, value, text, Dimension::Length, ROUGHNESS_BOUNDS)?))
            }
            Some(TextOrList::List(list)) => match list.as_slice() {
                [first, second] => {
                    let mut sigmas = [0.0; 2];
                    for (sigma, text) in sigmas.iter_mut().zip([first, second]) {
                        let value = self.positive(key, text, Dimension::Length)?;
                        *sigma =
                            self.within(key, value, text, Dimension::Length, ROUGHNESS_BOUNDS)?;
                    }
                    Ok(Some(crate::lubrication::composite_roughness_m(
                        sigmas[0], sigmas[1],
                    )))
                }
                _ => Err(self.error(
                    key,
                    format!("needs one rms roughness or two (one per surface), got {} values", list.len()),
                    Some("write roughness = \"0.1 um\" (composite) or roughness = [\"0.1 um\", \"0.2 um\"]"),
                )),
            },
        }
    }
}

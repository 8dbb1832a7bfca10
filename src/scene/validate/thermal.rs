//! The `[thermal]` table and the bodies' thermal properties (`[contact.bodyN]`).

#[allow(clippy::wildcard_imports)]
use super::*;
use crate::scene::raw::RawThermal;
use crate::scene::spec::{GearMesh, ThermalBody, ThermalSpec, TractionDirection};
use crate::thermal::heating::Partition;
use crate::thermal::material::{thermal_preset, ThermalProperties, THERMAL_PRESETS};

/// Sliding and body speeds, m/s.
const SPEED_BOUNDS: Bounds = Bounds {
    lo: 1e-9,
    hi: 1e4,
    why: "from creep (nm/s) to beyond any sliding contact (10 km/s)",
};
/// Pinion speeds, rad/s.
const PINION_SPEED_BOUNDS: Bounds = Bounds {
    lo: 1e-3,
    hi: 1e5,
    why: "from a creeping drive (0.01 rpm) to beyond turbine gears (1e6 rpm)",
};
/// Friction coefficients of a gear mesh.
const MAX_FRICTION: f64 = 1.0;
/// Conductivities, W/(m K).
const CONDUCTIVITY_BOUNDS: Bounds = Bounds {
    lo: 1e-3,
    hi: 1e4,
    why: "from aerogels to five times diamond",
};
/// Diffusivities, m²/s.
const DIFFUSIVITY_BOUNDS: Bounds = Bounds {
    lo: 1e-9,
    hi: 1e-2,
    why: "from polymers (1e-7) to ten times diamond (1e-3)",
};
/// Densities, kg/m³.
const DENSITY_BOUNDS: Bounds = Bounds {
    lo: 1.0,
    hi: 1e5,
    why: "from foams to five times osmium",
};
/// Specific heats, J/(kg K).
const SPECIFIC_HEAT_BOUNDS: Bounds = Bounds {
    lo: 1.0,
    hi: 1e5,
    why: "from lead (130) to ten times water",
};
/// Expansion coefficients, 1/K (0: no thermal stress).
const EXPANSION_BOUNDS: Bounds = Bounds {
    lo: 0.0,
    hi: 1e-3,
    why: "from Invar (1e-6) to five times soft polymers",
};

/// How a Hertz contact with `[thermal]` gets what heating needs.
const HEATED_CONTACT_HINT: &str = "give contact.load (instead of contact.a and contact.p0) and [contact.body1] and [contact.body2], each with its radius and material (e.g. material = \"steel\"): a and p0 then follow from the bodies, and the heating takes their thermal properties";

/// The speeds of the contact over the bodies and the sliding speed, m/s, with the keys that
/// set the bodies' speeds.
pub(super) struct Speeds {
    pub(super) body1: f64,
    pub(super) body2: f64,
    sliding: f64,
    keys: [&'static str; 2],
}

impl Validator<'_> {
    /// A Hertz contact (line, point, elliptical) with `[thermal]` needs a load and two
    /// bodies: said once, before the contact's own keys are read (issue 42, class 11), so
    /// that a contact given by `a` and `p0` is not first sent to add bodies, then told that
    /// `a` and `p0` follow from them.
    pub(super) fn heated_contact_keys(&self, raw: &RawScene) -> Result<(), SceneError> {
        let contact = &raw.contact;
        let hertz = matches!(contact.kind.trim(), "line" | "point" | "elliptical");
        if raw.thermal.is_none() || !hertz {
            return Ok(());
        }
        let sized = contact.a.is_some() || contact.p0.is_some() || contact.aspect.is_some();
        if contact.load.is_some() && !sized {
            return Ok(());
        }
        let given = if sized {
            let keys: Vec<&str> = [
                ("contact.a", contact.a.is_some()),
                ("contact.p0", contact.p0.is_some()),
                ("contact.aspect", contact.aspect.is_some()),
            ]
            .into_iter()
            .filter_map(|(key, given)| given.then_some(key))
            .collect();
            format!("this contact is given by its size ({})", keys.join(", "))
        } else {
            "this contact has no load".to_string()
        };
        Err(self.error(
            "thermal",
            format!("frictional heating needs a load and two bodies; {given}"),
            Some(HEATED_CONTACT_HINT),
        ))
    }

    /// `[thermal]` with the bodies' properties, or `None` without the table.
    pub(super) fn thermal(
        &self,
        raw: &RawScene,
        contact: &Contact,
    ) -> Result<Option<ThermalSpec>, SceneError> {
        let Some(table) = &raw.thermal else {
            return Ok(None);
        };
        match contact.kind {
            ContactKind::Line | ContactKind::Point | ContactKind::Elliptical => {
                // One requirement, said once (issue 42, class 11): the heat is made by the load
                // and shared by the bodies, whose thermal and elastic properties it needs; a
                // contact given by its a and p0 has neither.
                if contact.dimensional.is_none() {
                    let given = if contact.scale.is_some() {
                        "this contact is given by its size (contact.a, contact.p0)"
                    } else {
                        "this contact is normalised (a = 1, p0 = 1)"
                    };
                    return Err(self.error(
                        "thermal",
                        format!("frictional heating needs a load and two bodies; {given}"),
                        Some(HEATED_CONTACT_HINT),
                    ));
                }
                if contact.tangential.is_some() {
                    return Err(self.error(
                        "thermal",
                        "frictional heating is computed for full sliding",
                        Some("remove contact.tangential (partial slip), or remove [thermal]"),
                    ));
                }
            }
            ContactKind::Rough => {}
            ContactKind::Tractions | ContactKind::Surface => {
                return Err(self.error(
                    "thermal",
                    "frictional heating belongs to line, point, elliptical and rough scenes",
                    Some("remove [thermal]"),
                ))
            }
        }
        let gears = contact.dimensional.and_then(|d| d.gears);
        let friction = match (gears, table.friction) {
            (Some(_), Some(f)) if f > 0.0 && f <= MAX_FRICTION => f,
            (Some(_), Some(f)) => {
                return Err(self.error(
                    "thermal.friction",
                    format!(
                        "the mesh's friction coefficient must lie in (0, {MAX_FRICTION}], got {}",
                        crate::io::text::number(f)
                    ),
                    Some("gears run with about 0.03 to 0.08 when lubricated"),
                ))
            }
            (None, Some(_)) => {
                return Err(self.error(
                    "thermal.friction",
                    "a separate friction coefficient for the heat belongs to gear scenes",
                    Some("set contact.friction, which makes both the traction and the heat"),
                ))
            }
            (_, None) => contact.friction,
        };
        if friction <= 0.0 {
            return Err(self.error(
                if gears.is_some() { "thermal.friction" } else { "contact.friction" },
                "frictional heating needs friction: with friction = 0 no heat is made",
                Some(if gears.is_some() {
                    "give thermal.friction > 0 (the mesh's friction along the path; the pitch point itself rolls), or remove [thermal]"
                } else {
                    "give contact.friction > 0, or remove [thermal]"
                }),
            ));
        }
        let gear = match gears {
            Some(pair) => Some(self.gear_mesh(table, &pair, friction)?),
            None => {
                if table.pinion_speed.is_some() {
                    return Err(self.error(
                        "thermal.pinion_speed",
                        "a pinion speed belongs to gear scenes",
                        Some("add [contact.gears], or give the sliding speed as thermal.speed"),
                    ));
                }
                None
            }
        };
        let speeds = match (&gear, gears) {
            // At the pitch point the teeth roll: the path's sliding speeds are computed from
            // the pinion's speed.
            (Some(mesh), Some(pair)) => {
                let [v1, v2] = pair.flank_speeds_m_per_s(0.0, mesh.pinion_rad_per_s);
                Speeds {
                    body1: v1,
                    body2: v2,
                    sliding: 0.0,
                    keys: ["thermal.pinion_speed"; 2],
                }
            }
            _ => self.speeds(table)?,
        };
        let (body1_speed, body2_speed, sliding) = (speeds.body1, speeds.body2, speeds.sliding);
        let partition = self.partition(table)?;
        let coupled = table.coupled.unwrap_or(false);
        if coupled && contact.kind == ContactKind::Line {
            return Err(self.error(
                "thermal.coupled",
                "the coupled thermo-mechanical solution is computed on a gridded contact (point, elliptical or rough), not on a line contact's plane problem",
                Some("set coupled = false: the heating is then computed on the Hertz pressure"),
            ));
        }
        if coupled && contact.kind != ContactKind::Rough && contact.dimensional.is_none() {
            return Err(self.error(
                "thermal.coupled",
                "the coupled solution solves the contact again, which needs the bodies' radii, materials and the load",
                Some("give contact.load with [contact.body1] and [contact.body2], or set coupled = false"),
            ));
        }
        if coupled
            && matches!(
                contact.rough.and_then(|r| r.control),
                Some(crate::contact::rough::Control::Approach { .. })
            )
        {
            return Err(self.error(
                "thermal.coupled",
                "the coupled solution needs a given load or mean pressure, not an approach (the bulge of a stationary source is defined only up to a constant)",
                Some("give contact.load (or contact.mean_pressure) instead of contact.approach, or set coupled = false"),
            ));
        }
        let default_body = RawBody::default();
        let raw1 = raw.contact.body1.as_ref().unwrap_or(&default_body);
        let body1 = self
            .thermal_body("contact.body1", raw1, body1_speed, true)?
            .ok_or_else(|| self.error("contact.body1", "missing", None))?;
        let raw2 = raw.contact.body2.as_ref();
        let needs_body2 = partition.needs_body2();
        let body2 = match raw2 {
            Some(raw2) => self.thermal_body("contact.body2", raw2, body2_speed, needs_body2)?,
            None if needs_body2 => {
                return Err(self.error(
                    "contact.body2",
                    "the heat partition needs body 2's thermal properties",
                    Some("add [contact.body2] with material = \"steel\" (or conductivity, diffusivity, expansion), or set thermal.partition = \"body1\""),
                ))
            }
            None => None,
        };
        if contact.kind == ContactKind::Line {
            if body1.speed_m_per_s == 0.0 {
                return Err(self.error(
                    "thermal.body1_speed",
                    "a line contact that stays on body 1 (speed 0) has no steady temperature: a stationary band heats a plane problem without bound",
                    Some("give body 1 a positive speed"),
                ));
            }
            if let Some(b2) = &body2 {
                if needs_body2 && b2.speed_m_per_s == 0.0 {
                    return Err(self.error(
                        "thermal.body2_speed",
                        "a line contact that stays on body 2 (speed 0, the default) has no steady temperature, so its share cannot be found",
                        Some("give thermal.body2_speed (e.g. the pinion's rolling speed), or set thermal.partition = \"body1\""),
                    ));
                }
            }
        }
        Ok(Some(ThermalSpec {
            sliding_speed_m_per_s: sliding,
            traction: TractionDirection::of_speeds(body1_speed, body2_speed),
            speed_keys: speeds.keys,
            partition,
            coupled,
            body1,
            body2,
            gear,
        }))
    }

    /// The speeds of a sliding (not geared) contact: `V1` over body 1 (`body1_speed`, by
    /// default `speed`), `V2` over body 2 (`body2_speed`, by default 0: body 2 carries the
    /// contact), and the sliding speed `|V1 - V2|`: derived from them, or `speed` when it
    /// agrees (a `speed` that disagrees is refused, naming the keys).
    pub(super) fn speeds(&self, table: &RawThermal) -> Result<Speeds, SceneError> {
        let number = |v: f64| crate::io::text::significant(v, 6, 1e6, true);
        let sliding_given = match &table.speed {
            None => None,
            Some(text) => Some(
                self.bounded("thermal.speed", text, Dimension::Speed, SPEED_BOUNDS)
                    .map_err(|mut e| {
                        e.hint = Some(format!(
                            "the sliding speed must be positive (a contact that does not slide makes no frictional heat); {}",
                            e.hint.unwrap_or_default()
                        ));
                        e
                    })?,
            ),
        };
        let body_speed = |key: &str, text: &str| -> Result<f64, SceneError> {
            let value =
                units::parse(text, Dimension::Speed).map_err(|m| self.error(key, m, None))?;
            if value == 0.0 {
                Ok(0.0)
            } else {
                self.within(key, value, text, Dimension::Speed, SPEED_BOUNDS)
            }
        };
        let (v1, key1) = match (&table.body1_speed, sliding_given) {
            (Some(text), _) => (body_speed("thermal.body1_speed", text)?, "thermal.body1_speed"),
            (None, Some(v)) => (v, "thermal.speed"),
            (None, None) if table.body2_speed.is_some() => {
                return Err(self.error(
                    "thermal.body1_speed",
                    "missing the speed of the contact over body 1 (the surfaces slide at |V1 - V2|)",
                    Some("add body1_speed = \"2 m/s\" to [thermal] (or speed, the sliding speed, when body 1's surface is the one that moves)"),
                ))
            }
            (None, None) => {
                return Err(self.error(
                    "thermal.speed",
                    "missing the sliding speed",
                    Some("add speed = \"2 m/s\" to [thermal] (the speed of the contact over body 1), or the bodies' speeds body1_speed and body2_speed"),
                ))
            }
        };
        let (v2, key2) = match &table.body2_speed {
            Some(text) => (
                body_speed("thermal.body2_speed", text)?,
                "thermal.body2_speed",
            ),
            None => (0.0, "thermal.body2_speed"),
        };
        let sliding = (v1 - v2).abs();
        // How each body's speed was set, for the messages below.
        let origin = |key: &str, given: bool| {
            if given {
                key.to_string()
            } else if key == "thermal.speed" {
                "thermal.speed, as body1_speed is not given".to_string()
            } else {
                "the default, as body2_speed is not given".to_string()
            }
        };
        let described = format!(
            "the contact moves over body 1 at {} m/s ({}) and over body 2 at {} m/s ({})",
            number(v1),
            origin(key1, key1 == "thermal.body1_speed"),
            number(v2),
            origin(key2, table.body2_speed.is_some())
        );
        if let (Some(given), Some(text)) = (sliding_given, &table.speed) {
            if (given - sliding).abs() > 1e-9 * given.max(v1).max(v2) {
                return Err(self.error(
                    "thermal.speed",
                    format!(
                        "speed = \"{}\" disagrees with the bodies' speeds: {described}, so the surfaces slide at |V1 - V2| = {} m/s",
                        crate::io::text::cut(text, 40),
                        number(sliding)
                    ),
                    Some("the sliding speed is |body1_speed - body2_speed|: remove thermal.speed (it then follows from the bodies' speeds), or correct body1_speed and body2_speed"),
                ));
            }
        }
        if sliding < SPEED_BOUNDS.lo {
            let key = if table.body2_speed.is_some() {
                "thermal.body2_speed"
            } else {
                key1
            };
            return Err(self.error(
                key,
                format!(
                    "the surfaces do not slide: {described}, so |V1 - V2| = {} m/s (rolling without sliding makes no frictional heat)",
                    number(sliding)
                ),
                Some("give the bodies different speeds (the sliding speed is |body1_speed - body2_speed|), or remove [thermal]"),
            ));
        }
        Ok(Speeds {
            body1: v1,
            body2: v2,
            sliding,
            keys: [key1, key2],
        })
    }

    /// The running gears: the pinion's speed, and a path of contact that the teeth can run.
    fn gear_mesh(
        &self,
        table: &RawThermal,
        pair: &crate::contact::gear::SpurGearPair,
        friction: f64,
    ) -> Result<GearMesh, SceneError> {
        for (key, given) in [
            ("thermal.speed", table.speed.is_some()),
            ("thermal.body1_speed", table.body1_speed.is_some()),
            ("thermal.body2_speed", table.body2_speed.is_some()),
        ] {
            if given {
                return Err(self.error(
                    key,
                    "the speeds of gears follow from the pinion's speed along the path of contact (no sliding at the pitch point)",
                    Some("remove it and give thermal.pinion_speed, e.g. \"1500 rpm\""),
                ));
            }
        }
        let text = table.pinion_speed.as_ref().ok_or_else(|| {
            self.error(
                "thermal.pinion_speed",
                "gears need the pinion's speed: the sliding and rolling speeds along the path of contact follow from it",
                Some("add pinion_speed = \"1500 rpm\" to [thermal]"),
            )
        })?;
        let pinion_rad_per_s = self.bounded(
            "thermal.pinion_speed",
            text,
            Dimension::RotationalSpeed,
            PINION_SPEED_BOUNDS,
        )?;
        // Pointed or interfering teeth are refused with [contact.gears] itself.
        let ratio = pair.contact_ratio();
        if ratio < 1.0 {
            return Err(self.error(
                "contact.gears",
                format!(
                    "the contact ratio is {}: one pair of teeth leaves contact before the next engages",
                    crate::io::text::approx(ratio)
                ),
                Some("give more teeth or a smaller pressure_angle"),
            ));
        }
        Ok(GearMesh {
            pinion_rad_per_s,
            friction,
        })
    }

    /// `thermal.partition`: `"body1"`, `"blok"` (any case) or body 1's fraction (a number, or
    /// a number in quotes). Equivalent spellings mean the same: the fraction 1 is `"body1"`
    /// (all heat into body 1; body 2's properties and speed are then not needed).
    fn partition(&self, table: &RawThermal) -> Result<Partition, SceneError> {
        let key = "thermal.partition";
        let hint = Some("use partition = \"body1\" (all heat into body 1), \"blok\" (equal mean flash temperatures) or body 1's fraction, e.g. 0.5");
        let fraction = |f: f64| {
            if !(0.0..=1.0).contains(&f) {
                Err(self.error(
                    key,
                    format!(
                        "body 1's fraction must lie in [0, 1], got {}",
                        crate::io::text::number(f)
                    ),
                    hint,
                ))
            } else if f == 1.0 {
                Ok(Partition::Body1)
            } else {
                Ok(Partition::Fraction(f))
            }
        };
        match &table.partition {
            None => Ok(Partition::Body1),
            Some(NumberOrText::Text(text)) => {
                let word = text.trim().to_ascii_lowercase();
                match word.as_str() {
                    "body1" => Ok(Partition::Body1),
                    "blok" => Ok(Partition::Blok),
                    other => match other.parse::<f64>() {
                        Ok(f) => fraction(f),
                        Err(_) => Err(self.error(
                            key,
                            format!("unknown partition `{}`", crate::io::text::cut(text, 40)),
                            hint,
                        )),
                    },
                }
            }
            Some(NumberOrText::Number(f)) => fraction(*f),
        }
    }

    /// A body's thermal and elastic properties: each key, or the material's value. `None` when
    /// the body names none of them and `required` is false.
    fn thermal_body(
        &self,
        key: &str,
        raw: &RawBody,
        speed_m_per_s: f64,
        required: bool,
    ) -> Result<Option<ThermalBody>, SceneError> {
        let preset = match &raw.material {
            Some(name) => match thermal_preset(name) {
                Some(p) => Some(p),
                None => {
                    let names: Vec<_> = THERMAL_PRESETS.iter().map(|p| p.name).collect();
                    return Err(self.error(
                        &format!("{key}.material"),
                        format!("unknown material `{}`", crate::io::text::cut(name, 40)),
                        Some(&format!("use one of: {}", names.join(", "))),
                    ));
                }
            },
            None => None,
        };
        let given =
            raw.conductivity.is_some() || raw.diffusivity.is_some() || raw.expansion.is_some();
        if preset.is_none() && !given && !required {
            return Ok(None);
        }
        let value = |name: &str,
                     text: &Option<String>,
                     dimension,
                     bounds|
         -> Result<Option<f64>, SceneError> {
            text.as_ref()
                .map(|t| self.bounded(&format!("{key}.{name}"), t, dimension, bounds))
                .transpose()
        };
        let missing = |name: &str, example: &str| {
            self.error(
                &format!("{key}.{name}"),
                format!("missing thermal property `{name}`"),
                Some(&format!("add {name} = {example}, or material = \"steel\" (docs/reference.md lists the materials)")),
            )
        };
        let conductivity = value(
            "conductivity",
            &raw.conductivity,
            Dimension::Conductivity,
            CONDUCTIVITY_BOUNDS,
        )?
        .or(preset.map(|p| p.conductivity_w_per_m_k))
        .ok_or_else(|| missing("conductivity", "\"50 W/(m K)\""))?;
        let diffusivity = match (&raw.diffusivity, &raw.density, &raw.specific_heat) {
            (Some(_), Some(_), _) | (Some(_), _, Some(_)) => {
                return Err(self.error(
                    &format!("{key}.diffusivity"),
                    "give the diffusivity, or the density and specific heat, not both",
                    Some("remove one of them"),
                ))
            }
            (Some(_), None, None) => value(
                "diffusivity",
                &raw.diffusivity,
                Dimension::Diffusivity,
                DIFFUSIVITY_BOUNDS,
            )?
            .unwrap_or(f64::NAN),
            (None, Some(_), Some(_)) => {
                let rho = value("density", &raw.density, Dimension::Density, DENSITY_BOUNDS)?
                    .unwrap_or(f64::NAN);
                let c = value(
                    "specific_heat",
                    &raw.specific_heat,
                    Dimension::SpecificHeat,
                    SPECIFIC_HEAT_BOUNDS,
                )?
                .unwrap_or(f64::NAN);
                conductivity / (rho * c)
            }
            (None, Some(_), None) => return Err(missing("specific_heat", "\"475 J/(kg K)\"")),
            (None, None, Some(_)) => return Err(missing("density", "\"7850 kg/m^3\"")),
            (None, None, None) => match preset {
                Some(p) => p.diffusivity_m2_per_s,
                None => {
                    return Err(missing(
                        "diffusivity",
                        "\"1.4e-5 m^2/s\" (or density and specific_heat)",
                    ))
                }
            },
        };
        let expansion = value(
            "expansion",
            &raw.expansion,
            Dimension::Expansion,
            EXPANSION_BOUNDS,
        )?
        .or(preset.map(|p| p.expansion_per_k))
        .ok_or_else(|| missing("expansion", "\"11.5e-6 /K\""))?;
        let material = self.elastic(
            key,
            raw,
            "missing elastic modulus (the thermal stress is E α times the temperature)",
        )?;
        Ok(Some(ThermalBody {
            properties: ThermalProperties {
                conductivity_w_per_m_k: conductivity,
                diffusivity_m2_per_s: diffusivity,
                expansion_per_k: expansion,
            },
            material,
            speed_m_per_s,
        }))
    }
}

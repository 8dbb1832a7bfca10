//! The `[contact]` of rough and surface scenes (`kind = "rough"` or `"surface"`): what fixes
//! the solution (load, mean pressure or approach), bodies that may be rigid, the hardness, and
//! what their `[figure]` and `[numerical]` may say.

#[allow(clippy::wildcard_imports)]
use super::*;
use crate::contact::rough::{Control, DEFAULT_MAX_ITERATIONS, DEFAULT_TOLERANCE};

/// The reference units of rough and surface scenes: lengths in units of 1 um and pressures
/// in units of 1 MPa (their figures are drawn in um and MPa).
pub(super) const ROUGH_SCALE: Scale = Scale {
    half_width_m: 1e-6,
    p0_pa: 1e6,
};

impl Validator<'_> {
    /// The `[contact]` of a rough (`rough = true`) or surface scene.
    pub(super) fn rough_contact(
        &self,
        raw: &RawContact,
        kind: ContactKind,
    ) -> Result<Contact, SceneError> {
        let rough = kind == ContactKind::Rough;
        let what = if rough {
            "a rough contact"
        } else {
            "a surface scene"
        };
        let forbidden = [
            (
                "contact.a",
                raw.a.is_some(),
                "the scale follows from the surface",
            ),
            ("contact.p0", raw.p0.is_some(), "the pressure is solved for"),
            (
                "contact.aspect",
                raw.aspect.is_some(),
                "the geometry is the surface's",
            ),
            (
                "contact.tangential",
                raw.tangential.is_some(),
                "the traction is q = mu p on the solved pressure",
            ),
            (
                "contact.gears",
                raw.gears.is_some(),
                "the geometry is the surface's",
            ),
            (
                "contact.method",
                raw.method.is_some(),
                "the stresses are integrated numerically",
            ),
            (
                "contact.poisson",
                raw.poisson.is_some(),
                "Poisson's ratio is body 1's: give [contact.body1]",
            ),
        ];
        if let Some((key, _, why)) = forbidden.iter().find(|(_, given, _)| *given) {
            return Err(self.error(
                key,
                format!("{what} has no {key}: {why}"),
                Some("remove it"),
            ));
        }
        if !rough {
            let given = [
                ("contact.load", raw.load.is_some()),
                ("contact.mean_pressure", raw.mean_pressure.is_some()),
                ("contact.approach", raw.approach.is_some()),
                ("contact.friction", raw.friction.is_some()),
                ("contact.periodic", raw.periodic.is_some()),
            ];
            if let Some((key, _)) = given.iter().find(|(_, g)| *g) {
                return Err(self.error(
                    key,
                    "a surface scene characterises the surface; it solves no contact",
                    Some("use kind = \"rough\" to press it on a flat"),
                ));
            }
        }
        let controls = [
            ("contact.load", &raw.load),
            ("contact.mean_pressure", &raw.mean_pressure),
            ("contact.approach", &raw.approach),
        ];
        let given: Vec<_> = controls.iter().filter(|(_, v)| v.is_some()).collect();
        let control = if rough {
            match given.as_slice() {
                [] => {
                    return Err(self.error(
                        "contact.load",
                        "a rough contact needs what presses the surfaces together",
                        Some("give one of load = \"2 N\", mean_pressure = \"10 MPa\" or approach = \"0.5 um\""),
                    ))
                }
                [(key, Some(text))] => Some(match *key {
                    "contact.load" => Control::Load {
                        newtons: self.bounded(key, text, Dimension::Force, LOAD_BOUNDS)?,
                    },
                    "contact.mean_pressure" => Control::MeanPressure {
                        pa: self.bounded(key, text, Dimension::Pressure, STRESS_BOUNDS)?,
                    },
                    _ => Control::Approach {
                        m: self.bounded(key, text, Dimension::Length, APPROACH_BOUNDS)?,
                    },
                }),
                _ => {
                    return Err(self.error(
                        given[1].0,
                        "give one of load, mean_pressure and approach, not several",
                        None,
                    ))
                }
            }
        } else {
            None
        };
        let friction = self.friction("contact.friction", raw.friction.unwrap_or(0.0))?;
        {
            let empty = RawBody::default();
            let raw1 = raw.body1.as_ref().unwrap_or(&empty);
            self.coating_placement(raw1, raw.body2.as_ref().unwrap_or(&empty))?;
            if raw1.coating.is_some() {
                if !rough {
                    return Err(self.error(
                        "contact.body1.coating",
                        "a surface scene characterises the surface; it solves no contact, coated or not",
                        Some("use kind = \"rough\" to press the surface on a coated flat"),
                    ));
                }
                // The pressure cap of a plastic surface is one number for one material; a
                // coated surface's indentation hardness is a composite of the coating's and
                // the substrate's that depends on how deep the asperities press relative to
                // the thickness, which no single cap states.
                for (key, given) in [
                    ("contact.hardness", raw.hardness.is_some()),
                    ("contact.yield_strength", raw.yield_strength.is_some()),
                ] {
                    if given {
                        return Err(self.error(
                            key,
                            "a hardness cap on a coated rough surface is not computed: the indentation hardness of a coated surface is a composite of the coating's and the substrate's, set by how deep the asperities press relative to the coating's thickness, which one pressure cap cannot state",
                            Some(&format!("remove {key}: the coated contact is solved elastic, and its report gives the stresses in the coating, on the interface and in the substrate to compare with each material's strength")),
                        ));
                    }
                }
            }
        }
        let bodies = match (&raw.body1, &raw.body2) {
            (Some(b1), Some(b2)) => Some((
                self.rough_body("contact.body1", b1)?,
                self.rough_body("contact.body2", b2)?,
            )),
            (None, None) if !rough => None,
            (None, _) => {
                return Err(self.error(
                    "contact.body1",
                    "the materials of both bodies are needed",
                    Some("add [contact.body1] and [contact.body2] with material = \"steel\" (or \"rigid\"), or modulus and poisson"),
                ))
            }
            (Some(_), None) => {
                return Err(self.error(
                    "contact.body2",
                    "the materials of both bodies are needed",
                    Some("add [contact.body2] with material = \"steel\" or \"rigid\""),
                ))
            }
        };
        let e_star_pa = match bodies {
            Some((m1, m2)) => {
                if m1.modulus_pa.is_infinite() && m2.modulus_pa.is_infinite() {
                    return Err(self.error(
                        "contact.body2.material",
                        "both bodies are rigid: nothing deforms",
                        Some("make one of them elastic, e.g. material = \"steel\""),
                    ));
                }
                Some(crate::contact::effective_modulus(&m1, &m2))
            }
            None => None,
        };
        let coating = match (&raw.body1, bodies) {
            (Some(raw1), Some((substrate, counter))) => match &raw1.coating {
                Some(raw_coating) => {
                    if substrate.modulus_pa.is_infinite() {
                        return Err(self.error(
                            "contact.body1.material",
                            "a coated body's substrate must be elastic: the layer is bonded to body 1's own material",
                            Some("give body 1 an elastic material under the coating (e.g. material = \"steel\"); the counter-body, body 2, may be rigid"),
                        ));
                    }
                    let counter = counter.modulus_pa.is_finite().then_some(counter);
                    Some(self.coating(kind, raw_coating, substrate, counter)?)
                }
                None => None,
            },
            _ => None,
        };
        let yield_strength = self.yield_strength(raw)?;
        let hardness_pa = yield_strength.map(|y| match y.from_hardness {
            Some(number) => number * 9.80665e6,
            None => 3.0 * y.pa,
        });
        Ok(Contact {
            kind,
            friction,
            poisson: bodies.map_or(0.3, |(m1, _)| m1.poisson),
            scale: Some(ROUGH_SCALE),
            dimensional: None,
            yield_strength,
            aspect: 1.0,
            tangential: None,
            coating,
            rough: Some(RoughSpec {
                control,
                periodic: raw.periodic.unwrap_or(false),
                e_star_pa,
                hardness_pa,
                tolerance: DEFAULT_TOLERANCE,
                max_iterations: DEFAULT_MAX_ITERATIONS,
            }),
        })
    }

    /// A body of a rough contact: its material only (`"rigid"` allowed); its shape is the
    /// surface's.
    pub(super) fn rough_body(&self, key: &str, raw: &RawBody) -> Result<Material, SceneError> {
        if let Some((name, _)) = [
            ("radius", &raw.radius),
            ("radius_x", &raw.radius_x),
            ("radius_y", &raw.radius_y),
        ]
        .iter()
        .find(|(_, v)| v.is_some())
        {
            return Err(self.error(
                &format!("{key}.{name}"),
                "the bodies of a rough contact take their shape from the surface",
                Some("remove it; a rough ball is [surface.generate] sphere_radius = \"5 mm\""),
            ));
        }
        let rigid = raw.material.as_deref() == Some("rigid");
        if rigid {
            // A rigid body has no elastic constants; body 1's Poisson ratio alone is read (the
            // stresses drawn in it), body 2's would be silently ignored: refused, as a coated
            // scene's rigid counter-body refuses it (issue 50).
            for (name, given) in [
                ("modulus", raw.modulus.is_some()),
                ("poisson", raw.poisson.is_some() && key == "contact.body2"),
            ] {
                if given {
                    return Err(self.error(
                        &format!("{key}.{name}"),
                        "a rigid body has no elastic constants",
                        Some("remove it, or replace material = \"rigid\" by the body's material"),
                    ));
                }
            }
            let poisson = match raw.poisson {
                Some(nu) => self.poisson(&format!("{key}.poisson"), nu)?,
                None => 0.3,
            };
            return Ok(Material {
                modulus_pa: f64::INFINITY,
                poisson,
            });
        }
        // The material keys as for any body, with a radius that is not used.
        let mut with_radius = RawBody {
            radius: Some("flat".into()),
            material: raw.material.clone(),
            modulus: raw.modulus.clone(),
            poisson: raw.poisson,
            ..RawBody::default()
        };
        with_radius.radius_x = None;
        Ok(self.body(key, &with_radius, false, false)?.material)
    }
}

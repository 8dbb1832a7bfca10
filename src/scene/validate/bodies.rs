//! The `[contact.body1]` and `[contact.body2]` tables: radii and materials.

#[allow(clippy::wildcard_imports)]
use super::*;

impl Validator<'_> {
    /// A radius: `"flat"` or a non-zero length.
    pub(super) fn radius(&self, key: &str, text: &str) -> Result<f64, SceneError> {
        match text.trim() {
            "flat" | "inf" | "infinite" => Ok(f64::INFINITY),
            _ => {
                let r =
                    units::parse(text, Dimension::Length).map_err(|m| self.error(key, m, None))?;
                // In size: a concave body's radius is negative.
                self.within(key, r.abs(), text, Dimension::Length, RADIUS_BOUNDS)?;
                Ok(r)
            }
        }
    }

    /// The principal radii of a body in the xz and yz planes (elliptical contact): `radius_x`
    /// and `radius_y`, each defaulting to `radius`.
    pub(super) fn principal_radii(
        &self,
        key: &str,
        raw: &RawBody,
    ) -> Result<PrincipalRadii, SceneError> {
        let one = |name: &str, own: &Option<String>| {
            match (own, &raw.radius) {
            (Some(text), _) => self.radius(&format!("{key}.{name}"), text),
            (None, Some(text)) => self.radius(&format!("{key}.radius"), text),
            (None, None) => Err(self.error(&format!("{key}.{name}"), "missing radius", Some("give radius_x (in the xz plane, along the sliding direction) and radius_y (in the yz plane), or radius for both; \"flat\" for a plane, negative for a concave surface"))),
        }
        };
        Ok(PrincipalRadii {
            first_m: one("radius_x", &raw.radius_x)?,
            second_m: one("radius_y", &raw.radius_y)?,
        })
    }

    pub(super) fn body(
        &self,
        key: &str,
        raw: &RawBody,
        radius_from_gears: bool,
        elliptical: bool,
    ) -> Result<Body, SceneError> {
        if !elliptical {
            if let Some(name) = [("radius_x", &raw.radius_x), ("radius_y", &raw.radius_y)]
                .iter()
                .find_map(|(n, v)| v.is_some().then_some(*n))
            {
                return Err(self.error(
                    &format!("{key}.{name}"),
                    "two principal radii make an elliptical contact",
                    Some("use kind = \"elliptical\", or give one radius"),
                ));
            }
        }
        let radius_m = match (&raw.radius, radius_from_gears || elliptical) {
            (_, true) if elliptical => f64::NAN,
            (Some(_), true) => {
                return Err(self.error(&format!("{key}.radius"), "the radius follows from [contact.gears]", Some("remove it, or remove [contact.gears]")))
            }
            (None, true) => f64::NAN,
            (None, false) => {
                return Err(self.error(&format!("{key}.radius"), "missing radius", Some("e.g. radius = \"20 mm\", radius = \"flat\", or a negative radius for a concave body")))
            }
            (Some(text), false) => self.radius(&format!("{key}.radius"), text)?,
        };
        let material = self.elastic(key, raw, "missing elastic modulus")?;
        Ok(Body { radius_m, material })
    }

    /// A body's elastic constants: `modulus` and `poisson`, or its `material`'s; `missing` is
    /// the message when neither gives the modulus.
    pub(super) fn elastic(
        &self,
        key: &str,
        raw: &RawBody,
        missing: &str,
    ) -> Result<Material, SceneError> {
        let preset = match &raw.material {
            Some(name) if name.trim() == "rigid" && self.rigid_counter && key == "contact.body2" => {
                // A rigid indenter on an elastic-plastic body 1: it adds nothing to
                // 1/E* = (1 - ν1²)/E1 + (1 - ν2²)/E2.
                return Ok(Material {
                    modulus_pa: f64::INFINITY,
                    poisson: 0.0,
                });
            }
            Some(name) if name.trim() == "rigid" => {
                return Err(self.error(
                    &format!("{key}.material"),
                    "a rigid body is for rough contacts only: Hertz theory (line, point, elliptical contacts) takes both bodies' modulus and Poisson's ratio",
                    Some("give the stiffer body its own material or modulus and poisson (a body far stiffer than the other barely changes E*: 1/E* = (1 - ν1²)/E1 + (1 - ν2²)/E2), e.g. material = \"tungsten_carbide\""),
                ))
            }
            Some(name) => Some(material::preset(name).ok_or_else(|| {
                let names: Vec<_> = material::PRESETS
                    .iter()
                    .chain(material::COATING_PRESETS.iter())
                    .map(|p| p.name)
                    .collect();
                self.error(
                    &format!("{key}.material"),
                    format!("unknown material `{name}`"),
                    Some(&format!(
                        "use one of: {}; or give modulus and poisson",
                        names.join(", ")
                    )),
                )
            })?),
            None => None,
        };
        let modulus_pa = match (&raw.modulus, preset) {
            (Some(text), _) => self.bounded(
                &format!("{key}.modulus"),
                text,
                Dimension::Pressure,
                MODULUS_BOUNDS,
            )?,
            (None, Some(p)) => p.material.modulus_pa,
            (None, None) => {
                return Err(self.error(
                    &format!("{key}.modulus"),
                    missing,
                    Some("add modulus = \"210 GPa\" or material = \"steel\""),
                ))
            }
        };
        let poisson = match (raw.poisson, preset) {
            (Some(nu), _) => self.poisson(&format!("{key}.poisson"), nu)?,
            (None, Some(p)) => p.material.poisson,
            (None, None) => {
                return Err(self.error(
                    &format!("{key}.poisson"),
                    "missing Poisson's ratio",
                    Some("add poisson = 0.3 or material = \"steel\""),
                ))
            }
        };
        Ok(Material {
            modulus_pa,
            poisson,
        })
    }
}

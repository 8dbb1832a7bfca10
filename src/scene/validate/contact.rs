//! The `[contact]` table: kind, friction, scale or load, yield strength (the gears: `gears.rs`).

#[allow(clippy::wildcard_imports)]
use super::*;

/// The range of an elliptical contact's semi-axis ratio b/a, given or derived from the radii.
const MIN_ASPECT: f64 = 0.01;
const MAX_ASPECT: f64 = 100.0;

impl Validator<'_> {
    pub(super) fn contact(&self, raw: &RawContact) -> Result<Contact, SceneError> {
        let kind = match raw.kind.as_str() {
            "line" => ContactKind::Line,
            "point" => ContactKind::Point,
            "elliptical" => ContactKind::Elliptical,
            "tractions" => ContactKind::Tractions,
            "rough" => return self.rough_contact(raw, ContactKind::Rough),
            "surface" => return self.rough_contact(raw, ContactKind::Surface),
            other => {
                return Err(self.error(
                    "contact.kind",
                    format!("unknown contact kind `{other}`"),
                    Some("use \"line\" (cylinders, plane strain), \"point\" (spheres), \"elliptical\" (two principal radii per body), \"tractions\" (from a file), \"rough\" (a rough surface pressed on a flat) or \"surface\" (a rough surface characterised)"),
                ))
            }
        };
        for (key, given) in [
            ("contact.mean_pressure", raw.mean_pressure.is_some()),
            ("contact.approach", raw.approach.is_some()),
            ("contact.periodic", raw.periodic.is_some()),
        ] {
            if given {
                return Err(self.error(
                    key,
                    "only a rough contact is pressed by a mean pressure or an approach, or is periodic",
                    Some("use kind = \"rough\", or give load"),
                ));
            }
        }
        let tangential = match (raw.tangential, kind) {
            (None, _) => None,
            (
                Some(_),
                ContactKind::Line
                | ContactKind::Elliptical
                | ContactKind::Tractions
                | ContactKind::Rough
                | ContactKind::Surface,
            ) => {
                return Err(self.error(
                    "contact.tangential",
                    "partial slip (Cattaneo-Mindlin) is available for a sphere only",
                    Some("use kind = \"point\", or remove it for full sliding (q = mu p)"),
                ))
            }
            (Some(ratio), ContactKind::Point) if ratio > 0.0 && ratio <= 1.0 => Some(ratio),
            (Some(ratio), ContactKind::Point) => {
                return Err(self.error(
                    "contact.tangential",
                    format!(
                        "the tangential force over mu P must lie in (0, 1], got {}",
                        crate::io::text::number(ratio)
                    ),
                    Some("1 is full sliding; 0.5 leaves a stick circle of radius 0.79a"),
                ))
            }
        };
        if tangential.is_some() && raw.friction.is_none_or(|mu| mu <= 0.0) {
            return Err(self.error(
                "contact.friction",
                "partial slip needs a friction coefficient > 0",
                Some("add e.g. friction = 0.5"),
            ));
        }
        if kind == ContactKind::Tractions {
            if raw.friction.is_some() {
                return Err(self.error(
                    "contact.friction",
                    "the tangential tractions of a traction scene come from the file",
                    Some("remove it; give qx (and qy) columns in the CSV file instead"),
                ));
            }
            let key = [
                ("contact.load", raw.load.is_some()),
                ("contact.body1", raw.body1.is_some()),
                ("contact.body2", raw.body2.is_some()),
                ("contact.gears", raw.gears.is_some()),
            ]
            .into_iter()
            .find_map(|(key, given)| given.then_some(key));
            if let Some(key) = key {
                return Err(self.error(
                    key,
                    "a traction scene has no bodies or load: the file gives the tractions",
                    Some("remove it; contact.a and contact.p0 set the figures' units"),
                ));
            }
        }
        if kind != ContactKind::Line && raw.gears.is_some() {
            return Err(self.error(
                "contact.gears",
                "spur gears make a line contact",
                Some("use kind = \"line\" with [contact.gears], or give sphere radii in [contact.body1] and [contact.body2]"),
            ));
        }
        let friction = self.friction("contact.friction", raw.friction.unwrap_or(0.0))?;
        let mut aspect = match (raw.aspect, kind) {
            (None, _) => 1.0,
            (
                Some(_),
                ContactKind::Line
                | ContactKind::Point
                | ContactKind::Tractions
                | ContactKind::Rough
                | ContactKind::Surface,
            ) => {
                return Err(self.error(
                    "contact.aspect",
                    "the aspect ratio b/a is for an elliptical contact",
                    Some("use kind = \"elliptical\", or remove it"),
                ))
            }
            (Some(ratio), ContactKind::Elliptical)
                if (MIN_ASPECT..=MAX_ASPECT).contains(&ratio) =>
            {
                ratio
            }
            (Some(ratio), ContactKind::Elliptical) => {
                return Err(self.error(
                    "contact.aspect",
                    format!(
                        "the semi-axis ratio b/a must lie in {MIN_ASPECT}..={MAX_ASPECT}, got {}",
                        crate::io::text::number(ratio)
                    ),
                    Some("b is the semi-axis along y, a along x (the sliding direction)"),
                ))
            }
        };
        let dimensional_keys =
            raw.load.is_some() || raw.body1.is_some() || raw.body2.is_some() || raw.gears.is_some();
        let yield_strength = self.yield_strength(raw)?;
        let scale = self.scale(raw)?;
        if !dimensional_keys && scale.is_none() && yield_strength.is_some() {
            let key = if raw.hardness.is_some() {
                "contact.hardness"
            } else {
                "contact.yield_strength"
            };
            return Err(self.error(
                key,
                "a yield check needs a dimensional contact; this scene is normalised (a = 1, p0 = 1)",
                Some("give a and p0 with units, or load and bodies; `stressfield hertz` reports p0 at first yield in units of Y anyway"),
            ));
        }
        if !dimensional_keys {
            if kind == ContactKind::Elliptical && raw.aspect.is_none() {
                return Err(self.error(
                    "contact.aspect",
                    "a normalised elliptical contact needs its semi-axis ratio b/a",
                    Some("add e.g. aspect = 0.3 (b along y over a along x), or give load and bodies with radius_x and radius_y"),
                ));
            }
            let poisson = self.poisson("contact.poisson", raw.poisson.unwrap_or(0.3))?;
            return Ok(Contact {
                kind,
                friction,
                poisson,
                scale,
                dimensional: None,
                yield_strength,
                aspect,
                tangential,
                rough: None,
                coating: None,
            });
        }
        if raw.aspect.is_some() {
            return Err(self.error(
                "contact.aspect",
                "the semi-axis ratio follows from the load and the bodies",
                Some("remove it, or remove the load and bodies for a normalised scene"),
            ));
        }
        if raw.a.is_some() || raw.p0.is_some() {
            let key = if raw.a.is_some() {
                "contact.a"
            } else {
                "contact.p0"
            };
            return Err(self.error(
                key,
                "a and p0 follow from the load and the bodies",
                Some("give either a and p0, or load with [contact.body1] and [contact.body2]"),
            ));
        }
        if raw.poisson.is_some() {
            return Err(self.error(
                "contact.poisson",
                "a dimensional scene takes Poisson's ratio from each body",
                Some("move it to [contact.body1] and [contact.body2] (or use a material preset)"),
            ));
        }
        let (load_dimension, load_hint) = match kind {
            ContactKind::Line => (
                Dimension::ForcePerLength,
                "add e.g. load = \"40 kN/m\" (force per unit length for a line contact)",
            ),
            ContactKind::Point
            | ContactKind::Elliptical
            | ContactKind::Tractions
            | ContactKind::Rough
            | ContactKind::Surface => (
                Dimension::Force,
                "add e.g. load = \"500 N\" (the total force for a point contact)",
            ),
        };
        let load_text = raw.load.as_deref().ok_or_else(|| {
            self.error(
                "contact.load",
                "a dimensional scene needs the load",
                Some(load_hint),
            )
        })?;
        let load = self.bounded("contact.load", load_text, load_dimension, LOAD_BOUNDS)?;
        let gears = raw.gears.as_ref().map(|g| self.gears(g)).transpose()?;
        let empty = RawBody::default();
        let elliptical = kind == ContactKind::Elliptical;
        let raw1 = raw.body1.as_ref().unwrap_or(&empty);
        let raw2 = raw.body2.as_ref().unwrap_or(&empty);
        self.coating_placement(raw1, raw2)?;
        let coated = raw1.coating.is_some() || raw1.layers.is_some();
        let rigid2 = coated && raw2.material.as_deref().map(str::trim) == Some("rigid");
        let mut body1 = self.body("contact.body1", raw1, gears.is_some(), elliptical)?;
        let mut body2 = if rigid2 {
            self.rigid_counter_body(raw2, elliptical)?
        } else {
            self.body("contact.body2", raw2, gears.is_some(), elliptical)?
        };
        let coating = match (&raw1.coating, &raw1.layers) {
            (None, None) => None,
            (raw_coating, raw_layers) => {
                // One yield strength cannot assess two materials: the coated study gives the
                // coating's and the substrate's maxima apart (issue 50: it was ignored).
                for (key, given) in [
                    ("contact.hardness", raw.hardness.is_some()),
                    ("contact.yield_strength", raw.yield_strength.is_some()),
                ] {
                    if given {
                        return Err(self.error(
                            key,
                            "a coated body is two materials, and one yield strength cannot assess both: the coating's and the substrate's stresses peak in different places",
                            Some(&format!("remove {key}: `stressfield hertz` of a coated scene reports the largest von Mises and Tresca stresses in the coating, on the interface and in the substrate, with their places, to compare with each material's strength")),
                        ));
                    }
                }
                let counter = (!rigid2).then_some(body2.material);
                let spec = match raw_coating {
                    Some(raw_coating) => {
                        self.coating(kind, raw_coating, body1.material, counter)?
                    }
                    None => self.layers(
                        kind,
                        raw_layers.as_deref().unwrap_or_default(),
                        raw1.yield_strength.as_deref(),
                        body1.material,
                        counter,
                    )?,
                };
                // The scene's scale (a, p0) is the (top) coating's Hertz contact.
                body1.material = spec.material;
                Some(spec)
            }
        };
        if let Some(pair) = gears {
            body1.radius_m = pair.curvature_radius_at_pitch_point_m(0);
            body2.radius_m = pair.curvature_radius_at_pitch_point_m(1);
            for (name, radius) in [("pinion", body1.radius_m), ("gear", body2.radius_m)] {
                if !(RADIUS_BOUNDS.lo..=RADIUS_BOUNDS.hi).contains(&radius.abs()) {
                    return Err(self.error(
                        "contact.gears",
                        format!(
                            "the {name}'s radius of curvature at the pitch point is {} m, outside {} m to {} m",
                            crate::io::text::approx(radius),
                            crate::io::text::compact(RADIUS_BOUNDS.lo),
                            crate::io::text::compact(RADIUS_BOUNDS.hi)
                        ),
                        Some("check module, teeth and pressure_angle (20 deg is standard)"),
                    ));
                }
            }
            if let Some(raw_gears) = &raw.gears {
                self.gear_teeth(raw_gears, &pair)?;
            }
        }
        let radius_error = |e: crate::contact::ContactError| {
            self.error("contact.body2.radius", e.to_string(), Some("a flat is radius = \"flat\"; a concave body has a negative radius larger in size than the convex one's"))
        };
        let hertz = match kind {
            ContactKind::Line => {
                Hertz::Line(LineContact::new(&body1, &body2, load).map_err(radius_error)?)
            }
            ContactKind::Point => {
                Hertz::Point(PointContact::new(&body1, &body2, load).map_err(radius_error)?)
            }
            ContactKind::Elliptical => {
                let curved = |radii, body: &Body| CurvedBody {
                    radii,
                    material: body.material,
                };
                let first = curved(self.principal_radii("contact.body1", raw1)?, &body1);
                let second = curved(self.principal_radii("contact.body2", raw2)?, &body2);
                let ellipse = EllipticalContact::new(&first, &second, 0.0, load).map_err(|e| {
                    self.error("contact.body2.radius_y", e.to_string(), Some("each principal relative curvature must be positive: a concave radius must be larger in size than the convex one's in the same plane"))
                })?;
                aspect = ellipse.semi_axis_y_m / ellipse.semi_axis_x_m;
                if !(MIN_ASPECT..=MAX_ASPECT).contains(&aspect) {
                    return Err(self.error(
                        "contact.body2.radius_y",
                        format!(
                            "the radii give an ellipse with b/a = {} (b = {} m along y, a = {} m along x); b/a must lie in {MIN_ASPECT}..={MAX_ASPECT}",
                            crate::io::text::approx(aspect),
                            crate::io::text::approx(ellipse.semi_axis_y_m),
                            crate::io::text::approx(ellipse.semi_axis_x_m)
                        ),
                        Some("the relative curvatures in x and y (1/radius_x and 1/radius_y of both bodies, added) must not differ by more than about 1000; a nearly conforming groove gives a very long ellipse: check radius_y"),
                    ));
                }
                Hertz::Elliptical(ellipse)
            }
            ContactKind::Tractions | ContactKind::Rough | ContactKind::Surface => {
                return Err(self.error(
                    "contact.load",
                    "a traction scene has no bodies or load",
                    None,
                ))
            }
        };
        self.hertz_values(&hertz, yield_strength)?;
        Ok(Contact {
            kind,
            friction,
            poisson: body1.material.poisson,
            scale: Some(Scale {
                half_width_m: hertz.half_width_m(),
                p0_pa: hertz.p0_pa(),
            }),
            dimensional: Some(Dimensional {
                body1,
                body2,
                gears,
                hertz,
            }),
            yield_strength,
            aspect,
            tangential,
            rough: None,
            coating,
        })
    }

    /// A rigid counter-body of a coated scene (`material = "rigid"`): its radius (or radii), an
    /// infinite modulus (it adds nothing to the compliance).
    fn rigid_counter_body(&self, raw: &RawBody, elliptical: bool) -> Result<Body, SceneError> {
        for (name, given) in [
            ("modulus", raw.modulus.is_some()),
            ("poisson", raw.poisson.is_some()),
        ] {
            if given {
                return Err(self.error(
                    &format!("contact.body2.{name}"),
                    "a rigid body has no elastic constants",
                    Some("remove it, or replace material = \"rigid\" by the body's material"),
                ));
            }
        }
        let stand_in = RawBody {
            radius: raw.radius.clone(),
            radius_x: raw.radius_x.clone(),
            radius_y: raw.radius_y.clone(),
            material: Some("steel".to_string()),
            ..RawBody::default()
        };
        let mut body = self.body("contact.body2", &stand_in, false, elliptical)?;
        body.material = Material {
            modulus_pa: f64::INFINITY,
            poisson: 0.0,
        };
        Ok(body)
    }

    /// Every value derived from the load, the radii and the moduli (E*, R, a, b, p0, the mean
    /// pressure, the approach, and the load at which p0 reaches the yield strength) finite and
    /// positive: a safety net behind the bounds on each input, which keep them so.
    pub(super) fn hertz_values(
        &self,
        hertz: &Hertz,
        yield_strength: Option<YieldStrength>,
    ) -> Result<(), SceneError> {
        let values: Vec<(&str, f64)> = match hertz {
            Hertz::Line(line) => vec![
                ("the effective modulus E* (Pa)", line.effective_modulus_pa),
                ("the effective radius R (m)", line.effective_radius_m),
                ("the half-width a (m)", line.half_width_m),
                ("the peak pressure p0 (Pa)", line.p0_pa),
                ("the mean pressure (Pa)", line.mean_pressure_pa),
            ],
            Hertz::Point(point) => vec![
                ("the effective modulus E* (Pa)", point.effective_modulus_pa),
                ("the effective radius R (m)", point.effective_radius_m),
                ("the contact radius a (m)", point.radius_m),
                ("the peak pressure p0 (Pa)", point.p0_pa),
                ("the mean pressure (Pa)", point.mean_pressure_pa),
                ("the approach (m)", point.approach_m),
            ],
            Hertz::Elliptical(ellipse) => vec![
                (
                    "the effective modulus E* (Pa)",
                    ellipse.effective_modulus_pa,
                ),
                ("the semi-axis a (m)", ellipse.semi_axis_x_m),
                ("the semi-axis b (m)", ellipse.semi_axis_y_m),
                ("the peak pressure p0 (Pa)", ellipse.p0_pa),
                ("the mean pressure (Pa)", ellipse.mean_pressure_pa),
                ("the approach (m)", ellipse.approach_m),
            ],
        };
        let yield_load = yield_strength.map(|y| hertz.load_for_peak_pressure(y.pa));
        let values = values.into_iter().chain(
            yield_load.map(|load| ("the load at which p0 reaches the yield strength", load)),
        );
        for (name, value) in values {
            if !(value.is_finite() && value > 0.0) {
                return Err(self.error(
                    "contact.load",
                    format!(
                        "with these bodies the load gives {name} = {}: every Hertz value must be finite and positive",
                        crate::io::text::approx(value)
                    ),
                    Some("check the load, the radii and the moduli (and their units)"),
                ));
            }
        }
        Ok(())
    }

    /// `a` and `p0` given directly: both bare 1 (normalised, the default) or both with units.
    pub(super) fn scale(&self, raw: &RawContact) -> Result<Option<Scale>, SceneError> {
        let value = |key: &str, value: &NumberOrText, dimension: Dimension, bounds| match value {
            NumberOrText::Number(n) if *n == 1.0 => Ok(None),
            NumberOrText::Number(n) => Err(self.error(
                key,
                format!(
                    "a bare number means normalised units and must be 1, got {}",
                    crate::io::text::number(*n)
                ),
                Some(&format!(
                    "write it with a unit for a dimensional scale, e.g. {}",
                    dimension.example()
                )),
            )),
            NumberOrText::Text(text) => self.bounded(key, text, dimension, bounds).map(Some),
        };
        let a = raw
            .a
            .as_ref()
            .map(|v| value("contact.a", v, Dimension::Length, HALF_WIDTH_BOUNDS))
            .transpose()?
            .flatten();
        let p0 = raw
            .p0
            .as_ref()
            .map(|v| value("contact.p0", v, Dimension::Pressure, STRESS_BOUNDS))
            .transpose()?
            .flatten();
        match (a, p0) {
            (Some(half_width_m), Some(p0_pa)) => Ok(Some(Scale {
                half_width_m,
                p0_pa,
            })),
            (None, None) => Ok(None),
            (Some(_), None) => Err(self.error(
                "contact.p0",
                "a dimensional half-width needs a dimensional peak pressure",
                Some("add e.g. p0 = \"1.2 GPa\""),
            )),
            (None, Some(_)) => Err(self.error(
                "contact.a",
                "a dimensional peak pressure needs a dimensional half-width",
                Some("add e.g. a = \"0.2 mm\""),
            )),
        }
    }

    pub(super) fn yield_strength(
        &self,
        raw: &RawContact,
    ) -> Result<Option<YieldStrength>, SceneError> {
        match (&raw.yield_strength, &raw.hardness) {
            (Some(_), Some(_)) => Err(self.error(
                "contact.hardness",
                "give either yield_strength or hardness, not both",
                None,
            )),
            (Some(text), None) => Ok(Some(YieldStrength {
                pa: self.bounded(
                    "contact.yield_strength",
                    text,
                    Dimension::Pressure,
                    STRESS_BOUNDS,
                )?,
                from_hardness: None,
                hardness_scale: "",
            })),
            (None, Some(text)) => {
                let number = self.bounded(
                    "contact.hardness",
                    text,
                    Dimension::Hardness,
                    HARDNESS_BOUNDS,
                )?;
                Ok(Some(YieldStrength {
                    pa: yield_strength_from_hardness_pa(number),
                    from_hardness: Some(number),
                    hardness_scale: units::scale_of(text, Dimension::Hardness).unwrap_or("HB"),
                }))
            }
            (None, None) => Ok(None),
        }
    }
}

//! The `[sweep]` table of a recording scene.

#[allow(clippy::wildcard_imports)]
use super::*;

impl Validator<'_> {
    pub(super) fn sweep(&self, raw: &RawSweep, scene: &Scene) -> Result<Sweep, SceneError> {
        let parameter = SweepParameter::from_key(&raw.parameter).ok_or_else(|| {
            self.error(
                "sweep.parameter",
                format!("unknown sweep parameter `{}`", raw.parameter),
                Some(
                    "use \"friction\", \"load\", \"position\", \"peclet\", \"coating_thickness\" or \"entrainment_speed\"",
                ),
            )
        })?;
        let contact = &scene.contact;
        if parameter == SweepParameter::CoatingThickness && contact.coating.is_none() {
            return Err(self.error(
                "sweep.parameter",
                "a coating-thickness sweep needs a coated body",
                Some("add [contact.body1.coating] with thickness and material, or sweep another parameter"),
            ));
        }
        if parameter == SweepParameter::EntrainmentSpeed {
            let line = matches!(
                contact.dimensional.map(|d| d.hertz),
                Some(crate::scene::Hertz::Line(_))
            );
            if scene.lubricant.is_none() || !line {
                return Err(self.error(
                    "sweep.parameter",
                    "an entrainment-speed sweep records the numerical EHL solution of a lubricated line contact",
                    Some("give a line contact with bodies and a load, and [lubricant] (docs/lubrication.md), or sweep another parameter"),
                ));
            }
        }
        // A coating's thickness given as a plain number is in the figure's length unit.
        let unit_m = scene.figure.length_unit.metres(contact.half_width_m());
        let values: Vec<f64> = match (&raw.values, raw.from, raw.to, raw.steps) {
            (Some(values), None, None, None) => {
                let mut numbers = Vec::with_capacity(values.len());
                for (i, value) in values.iter().enumerate() {
                    let key = format!("sweep.values[{i}]");
                    numbers.push(match (value, parameter) {
                        (NumberOrText::Number(v), SweepParameter::CoatingThickness) => v * unit_m,
                        (NumberOrText::Text(text), SweepParameter::EntrainmentSpeed) => {
                            units::parse(text, Dimension::Speed)
                                .map_err(|m| self.error(&key, m, None))?
                        }
                        (NumberOrText::Number(v), _) => *v,
                        (NumberOrText::Text(text), SweepParameter::CoatingThickness) => {
                            units::parse(text, Dimension::Length)
                                .map_err(|m| self.error(&key, m, None))?
                        }
                        (NumberOrText::Text(text), SweepParameter::Load) => {
                            let dimension = if contact.kind == ContactKind::Line {
                                Dimension::ForcePerLength
                            } else {
                                Dimension::Force
                            };
                            units::parse(text, dimension).map_err(|m| self.error(&key, m, None))?
                        }
                        (NumberOrText::Text(text), _) => {
                            return Err(self.error(
                                &key,
                                format!("expected a number, got `{text}`"),
                                Some("friction, position and Péclet values are plain numbers; loads and coating thicknesses may carry units"),
                            ))
                        }
                    });
                }
                numbers
            }
            (None, Some(from), Some(to), Some(steps)) => {
                for (key, value) in [("sweep.from", from), ("sweep.to", to)] {
                    if !value.is_finite() {
                        return Err(self.error(
                            key,
                            format!(
                                "must be a finite number, got {}",
                                crate::io::text::number(value)
                            ),
                            None,
                        ));
                    }
                }
                if !(to - from).is_finite() {
                    return Err(self.error(
                        "sweep.to",
                        format!(
                            "the span from {} to {} is beyond double precision",
                            crate::io::text::number(from),
                            crate::io::text::number(to)
                        ),
                        Some("give a sweep of sizes a user could mean"),
                    ));
                }
                if !(2..=MAX_STEPS as i64).contains(&steps) {
                    return Err(self.error(
                        "sweep.steps",
                        format!("must lie in 2..={MAX_STEPS}, got {steps}"),
                        None,
                    ));
                }
                let n = steps as usize;
                if parameter == SweepParameter::CoatingThickness {
                    // Geometric steps in the figure's length unit: 1 µm to 100 µm is two decades.
                    for (key, value) in [("sweep.from", from), ("sweep.to", to)] {
                        if value <= 0.0 {
                            return Err(self.error(
                                key,
                                format!(
                                    "coating thicknesses are spaced geometrically from `from` to `to` (in the figure's length unit), so both must be positive, got {}",
                                    crate::io::text::number(value)
                                ),
                                Some("e.g. from = 2, to = 128, steps = 7 with figure.length_unit = \"um\""),
                            ));
                        }
                    }
                    (0..n)
                        .map(|k| unit_m * from * (to / from).powf(k as f64 / (n - 1) as f64))
                        .collect()
                } else if parameter == SweepParameter::EntrainmentSpeed {
                    // Geometric steps in m/s: 0.1 to 10 m/s is two decades.
                    for (key, value) in [("sweep.from", from), ("sweep.to", to)] {
                        if value <= 0.0 {
                            return Err(self.error(
                                key,
                                format!(
                                    "entrainment speeds (m/s) are spaced geometrically from `from` to `to`, so both must be positive, got {}",
                                    crate::io::text::number(value)
                                ),
                                Some("e.g. from = 0.2, to = 20, steps = 10"),
                            ));
                        }
                    }
                    (0..n)
                        .map(|k| from * (to / from).powf(k as f64 / (n - 1) as f64))
                        .collect()
                } else if parameter == SweepParameter::Peclet {
                    // Geometric steps: Pe 0.1 to 100 is three decades.
                    for (key, value) in [("sweep.from", from), ("sweep.to", to)] {
                        if value <= 0.0 {
                            return Err(self.error(
                                key,
                                format!(
                                    "Péclet numbers are spaced geometrically from `from` to `to` (Pe 0.1 to 100 is three decades), so both must be positive, got {}",
                                    crate::io::text::number(value)
                                ),
                                Some("e.g. from = 0.1, to = 100, steps = 13 (four steps a decade)"),
                            ));
                        }
                    }
                    (0..n)
                        .map(|k| from * (to / from).powf(k as f64 / (n - 1) as f64))
                        .collect()
                } else {
                    (0..n)
                        .map(|k| from + (to - from) * k as f64 / (n - 1) as f64)
                        .collect()
                }
            }
            _ => {
                return Err(self.error(
                    "sweep",
                    "give either `values` or all of `from`, `to` and `steps`",
                    Some("e.g. values = [0.0, 0.1, 0.2] or from = 0.0, to = 0.5, steps = 11"),
                ))
            }
        };
        if values.is_empty() || values.len() > MAX_STEPS {
            return Err(self.error(
                "sweep.values",
                format!("needs 1 to {MAX_STEPS} values, got {}", values.len()),
                None,
            ));
        }
        // Each step its own point of the recording (issue 42, class 9): a repeated value (or
        // from = to) would put several steps at one point of the value's timeline and charts.
        if raw.values.is_none() && values.len() > 1 && values.first() == values.last() {
            return Err(self.error(
                "sweep.to",
                format!(
                    "from and to are both {}: every step would record the same value",
                    crate::io::text::number(values[0])
                ),
                Some("give a range (from < to, or from > to), or a single value as values = [...]"),
            ));
        }
        if raw.values.is_some() {
            for (j, value) in values.iter().enumerate() {
                if let Some(i) = values[..j].iter().position(|v| v == value) {
                    return Err(self.error(
                        &format!("sweep.values[{j}]"),
                        format!(
                            "repeats sweep.values[{i}] ({}): two steps would record the same value at one point of the recording",
                            crate::io::text::number(*value)
                        ),
                        Some("give each value once"),
                    ));
                }
            }
        }
        // A recording of a friction, load or position sweep records the isothermal field:
        // [thermal] would be ignored (issue 42, class 9).
        if scene.thermal.is_some() && parameter != SweepParameter::Peclet {
            return Err(self.error(
                "thermal",
                format!(
                    "a {} sweep records the contact's stress field without heating: [thermal] would be ignored",
                    raw.parameter.trim()
                ),
                Some("record the heating as the speed rises with sweep.parameter = \"peclet\", or remove [thermal] (`stressfield thermal SCENE` reports the heating of one state)"),
            ));
        }
        // Each value as the user wrote it, named by its key. Generated values lie between
        // `from` and `to` (every bound below is an interval, and a, p0 and the other Hertz
        // values change monotonically with the load), so those two are checked, by their keys.
        let checked: Vec<(String, f64, Option<&str>)> = match (&raw.values, raw.from, raw.to) {
            (Some(written), _, _) => values
                .iter()
                .zip(written)
                .enumerate()
                .map(|(i, (&value, text))| {
                    let text = match text {
                        NumberOrText::Text(text) => Some(text.as_str()),
                        NumberOrText::Number(_) => None,
                    };
                    (format!("sweep.values[{i}]"), value, text)
                })
                .collect(),
            // A coating's thicknesses in m (from and to were in the figure's length unit).
            (None, Some(_), Some(_)) if parameter == SweepParameter::CoatingThickness => vec![
                ("sweep.from".to_string(), values[0], None),
                ("sweep.to".to_string(), values[values.len() - 1], None),
            ],
            (None, Some(from), Some(to)) => vec![
                ("sweep.from".to_string(), from, None),
                ("sweep.to".to_string(), to, None),
            ],
            _ => Vec::new(),
        };
        for (key, value, text) in checked {
            let key = key.as_str();
            let written = text.map_or_else(|| crate::io::text::number(value), str::to_string);
            match parameter {
                SweepParameter::Friction => {
                    self.friction(key, value)?;
                }
                SweepParameter::Load => {
                    let (dimension, unit) = if contact.kind == ContactKind::Line {
                        (Dimension::ForcePerLength, "N/m")
                    } else {
                        (Dimension::Force, "N")
                    };
                    let written = match text {
                        Some(_) => written,
                        None => format!("{written} {unit}"),
                    };
                    self.within(key, value, &written, dimension, LOAD_BOUNDS)?;
                    if contact.dimensional.is_some() {
                        let stepped = contact
                            .with_load(value)
                            .map_err(|e| self.error(key, e.to_string(), None))?;
                        if let Some(d) = stepped.dimensional {
                            self.hertz_values(&d.hertz, contact.yield_strength)
                                .map_err(|e| SceneError {
                                    key: Some(key.to_string()),
                                    ..e
                                })?;
                        }
                    }
                }
                SweepParameter::Peclet => self.peclet(key, value)?,
                SweepParameter::CoatingThickness => self.swept_thickness(key, value, scene)?,
                SweepParameter::EntrainmentSpeed => {
                    if !(value.is_finite() && value > 0.0) {
                        return Err(self.error(
                            key,
                            format!("an entrainment speed must be positive, got {written} m/s"),
                            Some("the oil is drawn into the contact at u = (u1 + u2)/2 > 0"),
                        ));
                    }
                }
                SweepParameter::Position => {
                    // In units of a, like every figure range.
                    let over_a = value * scene.length_unit_over_a();
                    let written = format!("{written}{}", unit_after(scene.figure.length_unit));
                    self.within_reach(key, over_a, &written)?;
                }
            }
        }
        match parameter {
            SweepParameter::Friction if contact.kind == ContactKind::Tractions => {
                return Err(self.error(
                    "sweep.parameter",
                    "tractions from a file carry their own shear: there is no friction to sweep",
                    None,
                ))
            }
            SweepParameter::Friction if contact.tangential.is_some() => {
                return Err(self.error(
                    "sweep.parameter",
                    "a friction sweep of partial slip is not supported",
                    Some("sweep the friction of a sliding contact (no contact.tangential)"),
                ))
            }
            SweepParameter::Friction | SweepParameter::Position
                if contact.kind == ContactKind::Rough =>
            {
                return Err(self.error(
                    "sweep.parameter",
                    "a rough contact records a load sweep (the spots appearing and merging)",
                    Some("use parameter = \"load\" with values in N"),
                ))
            }
            SweepParameter::Load if contact.kind == ContactKind::Rough => {}
            SweepParameter::Load if contact.dimensional.is_none() => {
                return Err(self.error(
                    "sweep.parameter",
                    "a load sweep needs a dimensional contact (bodies, materials and a load)",
                    Some("give contact.load and [contact.body1], [contact.body2]"),
                ))
            }
            SweepParameter::Load if scene.figure.length_unit == LengthUnit::HalfWidth => {
                return Err(self.error(
                    "figure.length_unit",
                    "in units of a and p0 every step of a load sweep shows the same field",
                    Some("draw it in physical units: figure.length_unit = \"mm\" and figure.stress_unit = \"MPa\""),
                ))
            }
            SweepParameter::Position => {
                let numerical_point = contact.kind != ContactKind::Line
                    && scene.panels.iter().any(|p: &PanelSpec| {
                        p.method != Method::ClosedForm
                            || !contact.has_closed_form()
                    });
                if numerical_point {
                    return Err(self.error(
                        "sweep.parameter",
                        "a moving load is recorded with the closed form only for point contacts (numerical panels off the traction grid would need direct summation at every point)",
                        Some("use method = \"closed_form\" for a moving sphere"),
                    ));
                }
            }
            _ => {}
        }
        let mut material_points = Vec::new();
        if let Some(points) = &raw.material_points {
            if parameter != SweepParameter::Position {
                return Err(self.error(
                    "sweep.material_points",
                    "material points follow a moving load: they need parameter = \"position\"",
                    None,
                ));
            }
            for (i, point) in points.iter().enumerate() {
                match point.as_slice() {
                    [x, z] if x.is_finite() && z.is_finite() && *z >= 0.0 => {
                        let key = format!("sweep.material_points[{i}]");
                        let unit_over_a = scene.length_unit_over_a();
                        let suffix = unit_after(scene.figure.length_unit);
                        for value in [*x, *z] {
                            let written = format!("{}{suffix}", crate::io::text::number(value));
                            self.within_reach(&key, value * unit_over_a, &written)?;
                        }
                        material_points.push((*x, *z));
                    }
                    _ => {
                        return Err(self.error(
                            &format!("sweep.material_points[{i}]"),
                            format!(
                            "needs [x, z] with z >= 0 (in the figure's length unit), got {point:?}"
                        ),
                            None,
                        ))
                    }
                }
            }
            if scene.figure.section != super::SectionKind::Xz {
                return Err(self.error(
                    "sweep.material_points",
                    "material points (x, z) lie in an xz section",
                    Some("use figure.section = \"xz\""),
                ));
            }
            if let Some(i) = scene
                .panels
                .iter()
                .position(|p| p.section != super::SectionKind::Xz)
            {
                return Err(self.error(
                    &format!("panel[{i}].section"),
                    format!(
                        "material points (x, z) lie in xz sections: this panel's {} section has none to follow",
                        scene.panels[i].section.key()
                    ),
                    Some(&format!(
                        "remove panel[{i}].section, or record the material points in a scene of xz sections"
                    )),
                ));
            }
        }
        Ok(Sweep {
            parameter,
            values,
            material_points,
            generated: raw.values.is_none(),
        })
    }

    /// A coating thickness of a sweep (m): positive, within the coating's bounds, and resolved
    /// by the scene's grid (cells of at most half of it).
    fn swept_thickness(&self, key: &str, value: f64, scene: &Scene) -> Result<(), SceneError> {
        let written = format!("{} m", crate::io::text::number(value));
        if !(value.is_finite() && (1e-9..=1.0).contains(&value)) {
            return Err(self.error(
                key,
                format!("a coating thickness must lie in 1 nm..=1 m, got {written}"),
                Some("give thicknesses in the figure's length unit, e.g. from = 2, to = 128 with figure.length_unit = \"um\""),
            ));
        }
        let contact = &scene.contact;
        let semi_axis = contact.half_width_m() * contact.aspect.max(1.0);
        let (cells, extent) = (scene.numerical.cells, scene.numerical.extent_over_a);
        let cell = 2.0 * extent * semi_axis / cells as f64;
        let largest = crate::contact::coated::largest_cell_m(value);
        if cell > largest * (1.0 + 1e-12) {
            let needed = (2.0 * extent * semi_axis / largest).ceil() as usize;
            return Err(self.error(
                key,
                format!(
                    "the grid's cells ({} µm: numerical.cells = {cells} over ±{} semi-axes) are coarser than half this coating ({} µm)",
                    crate::io::text::approx(cell * 1e6),
                    crate::io::text::approx(extent),
                    crate::io::text::approx(value * 1e6)
                ),
                Some(&format!("set numerical.cells to at least {needed}, or start the sweep at a thicker coating")),
            ));
        }
        Ok(())
    }

    /// A Péclet number of a speed sweep: at least [`MIN_PECLET`]. Whether the sweep's grid
    /// resolves it is the study's to say ([`crate::study::admit`]).
    fn peclet(&self, key: &str, value: f64) -> Result<(), SceneError> {
        let written = crate::io::text::number(value);
        if !(value.is_finite() && value >= MIN_PECLET) {
            return Err(self.error(
                key,
                format!("a Péclet number must be at least {MIN_PECLET}, got {written}"),
                Some("below it the temperature is the stationary one, scaled with the speed; sweep e.g. from 0.1 to 100"),
            ));
        }
        Ok(())
    }
}

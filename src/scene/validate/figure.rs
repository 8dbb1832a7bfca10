//! The `[figure]` table and the position of each `[[panel]]`'s section.

#[allow(clippy::wildcard_imports)]
use super::*;

/// How far from the contact's centre a figure range, a section, a volume, a moving load or a
/// material point may reach, in units of a. There the stresses have fallen below 1e-4 p0
/// (line contact, as 1/r) or 1e-8 p0 (point contact, as 1/r²); farther, a figure shows
/// nothing and its numbers lose their meaning.
pub(crate) const REACH_OVER_A: f64 = 1e4;

/// The smallest span of a figure range, in units of a.
pub(crate) const MIN_SPAN_OVER_A: f64 = 1e-6;

/// The largest ratio of a section's height to its width, and of its width to its height: at
/// equal scale the map is drawn this much taller (or shorter) than it is wide.
pub(crate) const MAX_ASPECT: f64 = 50.0;

/// The tallest map, in pixels (the renderer's limit on a side of an image).
pub(crate) const MAX_MAP_PX: f64 = 16_384.0;

impl Validator<'_> {
    /// `value_over_a` (a position in units of a, which the user wrote as `written`) within
    /// [`REACH_OVER_A`] of the contact.
    pub(super) fn within_reach(
        &self,
        key: &str,
        value_over_a: f64,
        written: &str,
    ) -> Result<f64, SceneError> {
        if value_over_a.is_nan() || value_over_a.abs() > REACH_OVER_A {
            return Err(self.error(
                key,
                format!(
                    "`{}` lies more than {} a from the contact, as far as figures, sections and points may reach",
                    crate::io::text::cut(written, 40),
                    crate::io::text::compact(REACH_OVER_A)
                ),
                Some("there the stresses have fallen below 1e-4 p0 (line contact) or 1e-8 p0 (point contact): draw nearer to the contact"),
            ));
        }
        Ok(value_over_a)
    }

    /// A figure's or volume's range `(lo, hi)` in the figure's unit (`unit_over_a` a each):
    /// both ends within reach, and a span of at least [`MIN_SPAN_OVER_A`].
    pub(super) fn range_within_reach(
        &self,
        key: &str,
        (lo, hi): (f64, f64),
        unit_over_a: f64,
        suffix: &str,
    ) -> Result<(), SceneError> {
        for end in [lo, hi] {
            let written = format!("{}{suffix}", crate::io::text::number(end));
            self.within_reach(key, end * unit_over_a, &written)?;
        }
        if (hi - lo) * unit_over_a < MIN_SPAN_OVER_A {
            return Err(self.error(
                key,
                format!(
                    "the range [{}, {}] spans {} a, less than the {} a a figure can resolve",
                    crate::io::text::number(lo),
                    crate::io::text::number(hi),
                    crate::io::text::number((hi - lo) * unit_over_a),
                    crate::io::text::compact(MIN_SPAN_OVER_A)
                ),
                Some("widen the range"),
            ));
        }
        Ok(())
    }

    /// A section plane written as `key = "xz"`, `"yz"` or `"xy"`.
    pub(super) fn section_kind(&self, key: &str, text: &str) -> Result<SectionKind, SceneError> {
        SectionKind::from_key(text).ok_or_else(|| {
            self.error(
                key,
                format!("unknown section `{}`", crate::io::text::cut(text, 40)),
                Some("use \"xz\" (depth below the sliding direction), \"yz\" (depth across it) or \"xy\" (a plane at a depth, 0 for the surface)"),
            )
        })
    }

    /// The position of a `section` of `figure` along its normal: any y or x, a depth z >= 0;
    /// only 0 for a line contact (its field does not depend on y).
    pub(super) fn section_position(
        &self,
        key: &str,
        value: Option<f64>,
        contact: &Contact,
        figure: &FigureSpec,
        section: SectionKind,
    ) -> Result<f64, SceneError> {
        let Some(at) = value else {
            return Ok(0.0);
        };
        let (_, _, normal) = section.coordinates();
        if !at.is_finite() {
            return Err(self.error(
                key,
                format!(
                    "must be a finite {normal}, got {}",
                    crate::io::text::number(at)
                ),
                None,
            ));
        }
        let unit_over_a =
            figure.length_unit.metres(contact.half_width_m()) / contact.half_width_m();
        let written = format!(
            "{}{}",
            crate::io::text::number(at),
            unit_after(figure.length_unit)
        );
        self.within_reach(key, at * unit_over_a, &written)?;
        if contact.kind == ContactKind::Line && at != 0.0 {
            return Err(self.error(
                key,
                "a line contact is the same in every xz plane (plane strain)",
                Some("remove it; sections at other y are for point contacts"),
            ));
        }
        if section == SectionKind::Xy && at < 0.0 {
            return Err(self.error(
                key,
                format!(
                    "the depth of an xy section must be >= 0 (z points into the body), got {}",
                    crate::io::text::number(at)
                ),
                Some("0 is the surface"),
            ));
        }
        Ok(at)
    }

    /// The `[figure]` table; `own_sections` are the sections the `[[panel]]` tables choose
    /// (`None` for the figure's), so that every range is checked against the planes drawn.
    pub(super) fn figure(
        &self,
        raw: &RawFigure,
        contact: &Contact,
        own_sections: &[Option<SectionKind>],
    ) -> Result<FigureSpec, SceneError> {
        let quantity = match &raw.quantity {
            Some(key) => Quantity::from_key(key).ok_or_else(|| {
                let keys: Vec<_> = Quantity::ALL.iter().map(|q| q.key()).collect();
                self.error(
                    "figure.quantity",
                    format!("unknown quantity `{key}`"),
                    Some(&format!("use one of: {}", keys.join(", "))),
                )
            })?,
            None => Quantity::VonMises,
        };
        let dimensional = contact.scale.is_some();
        let length_unit = match &raw.length_unit {
            Some(key) => LengthUnit::from_key(key).ok_or_else(|| {
                self.error(
                    "figure.length_unit",
                    format!("unknown length unit `{key}`"),
                    Some("use \"a\", \"mm\", \"um\" or \"m\""),
                )
            })?,
            None if matches!(contact.kind, ContactKind::Rough | ContactKind::Surface) => {
                LengthUnit::Micrometre
            }
            None if dimensional => LengthUnit::Millimetre,
            None => LengthUnit::HalfWidth,
        };
        let stress_unit = match &raw.stress_unit {
            Some(key) => StressUnit::from_key(key).ok_or_else(|| {
                self.error(
                    "figure.stress_unit",
                    format!("unknown stress unit `{key}`"),
                    Some("use \"p0\", \"MPa\", \"GPa\" or \"Pa\""),
                )
            })?,
            None if dimensional => StressUnit::MegaPascal,
            None => StressUnit::PeakPressure,
        };
        if !dimensional && length_unit != LengthUnit::HalfWidth {
            return Err(self.error(
                "figure.length_unit",
                "a normalised scene (no load or bodies) is drawn in units of a",
                Some("use length_unit = \"a\", or give contact.load and the bodies"),
            ));
        }
        if !dimensional && stress_unit != StressUnit::PeakPressure {
            return Err(self.error(
                "figure.stress_unit",
                "a normalised scene (no load or bodies) is drawn in units of p0",
                Some("use stress_unit = \"p0\", or give contact.load and the bodies"),
            ));
        }
        let section = match &raw.section {
            Some(key) => self.section_kind("figure.section", key)?,
            None => SectionKind::Xz,
        };
        // The sections the panels draw, each with the key that chose it (the figure's first).
        let mut drawn: Vec<(SectionKind, String)> = Vec::new();
        if own_sections.iter().any(Option::is_none) || own_sections.is_empty() {
            drawn.push((section, "figure.section".to_string()));
        }
        for (i, own) in own_sections.iter().enumerate() {
            if let Some(kind) = *own {
                if drawn.iter().all(|(k, _)| *k != kind) {
                    drawn.push((kind, format!("panel[{i}].section")));
                }
            }
        }
        if contact.kind == ContactKind::Line {
            if let Some((kind, key)) = drawn.iter().find(|(k, _)| *k != SectionKind::Xz) {
                return Err(self.error(
                    key,
                    format!(
                        "a line contact is plane strain: its {} sections only repeat the xz field",
                        kind.key()
                    ),
                    Some("use section = \"xz\" (the default), or kind = \"point\""),
                ));
            }
        }
        let ranges = [
            ("x", raw.x.as_ref()),
            ("y", raw.y.as_ref()),
            ("z", raw.z.as_ref()),
        ];
        // A range no section draws (along the normal of every panel's plane) is an error, not
        // ignored.
        for (name, range) in ranges {
            let drawn_by = |kind: &SectionKind| {
                let (h, v, _) = kind.coordinates();
                h == name || v == name
            };
            if range.is_some() && !drawn.iter().any(|(kind, _)| drawn_by(kind)) {
                let (kind, _) = &drawn[0];
                let (horizontal_name, vertical_name, normal_name) = kind.coordinates();
                let at_key = if drawn[0].1 == "figure.section" {
                    "figure.at".to_string()
                } else {
                    drawn[0].1.replace(".section", ".at")
                };
                return Err(self.error(
                    &format!("figure.{name}"),
                    format!(
                        "an {} section has no {name} range: {name} is fixed by {at_key}",
                        kind.key()
                    ),
                    Some(&format!("give figure.{horizontal_name} and figure.{vertical_name}, and the section's {normal_name} as {at_key}; a panel in another plane takes its own ([[panel]] section = ...)")),
                ));
            }
        }
        let range_of = |name: &str| {
            ranges
                .iter()
                .find(|(n, _)| *n == name)
                .and_then(|(_, range)| *range)
        };
        let a_in_unit = contact.half_width_m() / length_unit.metres(contact.half_width_m());
        // Defaults: twice the semi-axis along x (b = aspect a along y; 2.5a for a line
        // contact), depth 0 to twice the smaller semi-axis.
        let default_x = if contact.kind == ContactKind::Line {
            2.5
        } else {
            2.0
        };
        let default_y = match contact.kind {
            ContactKind::Line => 2.5,
            ContactKind::Elliptical => 2.0 * contact.aspect,
            _ => 2.0,
        };
        let x = self.range(
            "figure.x",
            range_of("x"),
            (-default_x * a_in_unit, default_x * a_in_unit),
        )?;
        let y = self.range(
            "figure.y",
            range_of("y"),
            (-default_y * a_in_unit, default_y * a_in_unit),
        )?;
        let z = self.range(
            "figure.z",
            range_of("z"),
            (0.0, 2.0 * a_in_unit * contact.aspect.min(1.0)),
        )?;
        if z.0 < 0.0 {
            return Err(self.error(
                "figure.z",
                format!(
                    "depth must be >= 0 (z points into the body), got {}",
                    crate::io::text::number(z.0)
                ),
                Some("start the range at 0 for the surface"),
            ));
        }
        let unit_over_a = 1.0 / a_in_unit;
        let suffix = unit_after(length_unit);
        let spec_ranges = |kind: SectionKind| match kind {
            SectionKind::Xz => (x, z),
            SectionKind::Yz => (y, z),
            SectionKind::Xy => (x, y),
        };
        for (kind, _) in &drawn {
            let (horizontal_name, vertical_name, _) = kind.coordinates();
            let (horizontal, vertical) = spec_ranges(*kind);
            for (name, range) in [(horizontal_name, horizontal), (vertical_name, vertical)] {
                self.range_within_reach(&format!("figure.{name}"), range, unit_over_a, suffix)?;
            }
        }
        // At equal scale: neither a sliver nor a tower. (A rough scene's section is as wide
        // as its map, checked with the map: `rough_section_depth`.)
        let sheet = matches!(contact.kind, ContactKind::Rough | ContactKind::Surface);
        let mut tallest = 0.0f64;
        for (kind, _) in &drawn {
            let (horizontal_name, vertical_name, _) = kind.coordinates();
            let (horizontal, vertical) = spec_ranges(*kind);
            let aspect = (vertical.1 - vertical.0) / (horizontal.1 - horizontal.0);
            tallest = tallest.max(aspect);
            if !sheet && !(1.0 / MAX_ASPECT..=MAX_ASPECT).contains(&aspect) {
                let key =
                    if range_of(vertical_name).is_some() || range_of(horizontal_name).is_none() {
                        vertical_name
                    } else {
                        horizontal_name
                    };
                let which = if drawn.len() > 1 {
                    format!("the {} section", kind.key())
                } else {
                    "the section".to_string()
                };
                return Err(self.error(
                    &format!("figure.{key}"),
                    format!(
                        "at equal scale {which} would be drawn {} times as tall as it is wide ({} by {}{suffix}); keep the ratio between 1/{MAX_ASPECT} and {MAX_ASPECT}",
                        crate::io::text::number((aspect * 1000.0).round() / 1000.0),
                        crate::io::text::number(horizontal.1 - horizontal.0),
                        crate::io::text::number(vertical.1 - vertical.0),
                    ),
                    Some(&format!(
                        "adjust figure.{horizontal_name} or figure.{vertical_name}, or split the section into several panels"
                    )),
                ));
            }
        }
        let resolution = match raw.resolution {
            None => 801,
            Some(n) if (16..=20_000).contains(&n) => n as usize,
            Some(n) => {
                return Err(self.error(
                    "figure.resolution",
                    format!("must lie in 16..=20000 samples along x, got {n}"),
                    Some("600 to 1200 is plenty for a figure"),
                ))
            }
        };
        let levels = match (raw.contours, &raw.levels) {
            (Some(_), Some(_)) => {
                return Err(self.error(
                    "figure.levels",
                    "give either contours (a count) or levels (values), not both",
                    None,
                ))
            }
            (Some(n), None) if (0..=100).contains(&n) => Levels::Count(n as usize),
            (Some(n), None) => {
                return Err(self.error(
                    "figure.contours",
                    format!("must lie in 0..=100, got {n}"),
                    None,
                ))
            }
            (None, Some(values)) if values.iter().all(|v| v.is_finite()) => {
                Levels::Values(values.clone())
            }
            (None, Some(_)) => {
                return Err(self.error("figure.levels", "levels must be finite numbers", None))
            }
            (None, None) => Levels::Count(10),
        };
        let colormap = match &raw.colormap {
            Some(key) => ColorMap::from_key(key).ok_or_else(|| {
                let keys: Vec<_> = ColorMap::ALL.iter().map(|c| c.key()).collect();
                self.error(
                    "figure.colormap",
                    format!("unknown colour map `{key}`"),
                    Some(&format!("use one of: {}", keys.join(", "))),
                )
            })?,
            None => match quantity.kind() {
                QuantityKind::NonNegative => ColorMap::Viridis,
                QuantityKind::Signed => ColorMap::Diverging,
            },
        };
        let mark = match raw.mark.as_deref() {
            None | Some("auto") => None,
            Some("max") => Some(Mark::Max),
            Some("min") => Some(Mark::Min),
            Some("both") => Some(Mark::Both),
            Some("none") => Some(Mark::None),
            Some(other) => {
                return Err(self.error(
                    "figure.mark",
                    format!("unknown mark `{other}`"),
                    Some("use \"auto\", \"max\", \"min\", \"both\" or \"none\""),
                ))
            }
        };
        let width_px = match raw.width {
            None => 560,
            Some(w) if (200..=4000).contains(&w) => w as u32,
            Some(w) => {
                return Err(self.error(
                    "figure.width",
                    format!("panel width must lie in 200..=4000 px, got {w}"),
                    None,
                ))
            }
        };
        let map_px = f64::from(width_px) * tallest;
        if !sheet && map_px > MAX_MAP_PX {
            return Err(self.error(
                "figure.width",
                format!(
                    "a map {width_px} px wide would be {} px tall at equal scale, more than the {MAX_MAP_PX} px of an image",
                    map_px.round()
                ),
                Some("narrow the panels (figure.width) or the depth range"),
            ));
        }
        Ok(FigureSpec {
            quantity,
            section,
            x,
            y,
            z,
            depth_given: range_of("z").is_some(),
            length_unit,
            stress_unit,
            resolution,
            levels,
            colormap,
            mark,
            width_px,
            svg: raw.svg.unwrap_or(false),
        })
    }
}

//! The `[volume]` table of a recording scene.

#[allow(clippy::wildcard_imports)]
use super::*;

impl Validator<'_> {
    /// `[volume]`: a box under a point contact, recorded as a point cloud.
    pub(super) fn volume(
        &self,
        raw: &RawVolume,
        contact: &super::Contact,
        figure: &FigureSpec,
    ) -> Result<VolumeSpec, SceneError> {
        if contact.kind == ContactKind::Line {
            return Err(self.error(
                "volume",
                "a line contact is the same in every xz plane: record a section instead",
                Some("remove [volume], or use kind = \"point\""),
            ));
        }
        if !contact.has_closed_form() {
            return Err(self.error(
                "volume",
                "a volume is recorded from the closed form, which this contact has not (elliptical, partial slip or tractions from a file)",
                Some("record sections of it instead (figure.section, or each [[panel]]'s section = \"xz\", \"yz\" or \"xy\", with at = ...)"),
            ));
        }
        let quantity = match &raw.quantity {
            Some(key) => Quantity::from_key(key).ok_or_else(|| {
                let keys: Vec<_> = Quantity::ALL.iter().map(|q| q.key()).collect();
                self.error(
                    "volume.quantity",
                    format!("unknown quantity `{key}`"),
                    Some(&format!("use one of: {}", keys.join(", "))),
                )
            })?,
            None => figure.quantity,
        };
        let unit = figure.length_unit.metres(contact.half_width_m()) / contact.half_width_m();
        let default = |a: f64| a / unit;
        let x = self.range("volume.x", raw.x.as_ref(), (default(-2.0), default(2.0)))?;
        let y = self.range("volume.y", raw.y.as_ref(), (default(-2.0), default(2.0)))?;
        let z = self.range("volume.z", raw.z.as_ref(), (0.0, default(2.0)))?;
        for (key, range) in [("volume.x", x), ("volume.y", y), ("volume.z", z)] {
            self.range_within_reach(key, range, unit, unit_after(figure.length_unit))?;
        }
        if z.0 < 0.0 {
            return Err(self.error(
                "volume.z",
                format!(
                    "depths must be >= 0 (z points into the body), got {}",
                    crate::io::text::number(z.0)
                ),
                None,
            ));
        }
        let points = match raw.points {
            None => 48,
            Some(n) if (2..=256).contains(&n) => n as usize,
            Some(n) => {
                return Err(self.error(
                    "volume.points",
                    format!("must lie in 2..=256 (samples along the longest side), got {n}"),
                    Some("48 to 96 keeps the viewer responsive"),
                ))
            }
        };
        let threshold = match raw.threshold {
            None => 0.3,
            Some(t) if (0.0..1.0).contains(&t) => t,
            Some(t) => {
                return Err(self.error(
                    "volume.threshold",
                    format!(
                        "must lie in [0, 1) (a fraction of the largest |value|), got {}",
                        crate::io::text::number(t)
                    ),
                    None,
                ))
            }
        };
        Ok(VolumeSpec {
            quantity,
            x,
            y,
            z,
            points,
            threshold,
        })
    }
}

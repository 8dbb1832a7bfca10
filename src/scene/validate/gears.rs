//! The spur gears of a `[contact.gears]` table: module, teeth, pressure angle, speeds.

#[allow(clippy::wildcard_imports)]
use super::*;

impl Validator<'_> {
    pub(super) fn gears(&self, raw: &raw::RawGears) -> Result<SpurGearPair, SceneError> {
        let module_m = self.bounded(
            "contact.gears.module",
            &raw.module,
            Dimension::Length,
            MODULE_BOUNDS,
        )?;
        let angle = units::parse(&raw.pressure_angle, Dimension::Angle)
            .map_err(|m| self.error("contact.gears.pressure_angle", m, None))?;
        if !(angle > 0.0 && angle < std::f64::consts::FRAC_PI_2) {
            return Err(self.error(
                "contact.gears.pressure_angle",
                format!(
                    "must lie between 0 and 90 deg, got `{}`",
                    raw.pressure_angle
                ),
                Some("20 deg is standard"),
            ));
        }
        let teeth: [u32; 2] = match raw.teeth.as_slice() {
            [a, b] if *a >= 6 && *b >= 6 && *a <= 100_000 && *b <= 100_000 => {
                [*a as u32, *b as u32]
            }
            _ => {
                return Err(self.error(
                    "contact.gears.teeth",
                    format!("needs two tooth counts of at least 6, got {:?}", raw.teeth),
                    Some("e.g. teeth = [20, 40] (pinion = body1, gear = body2)"),
                ))
            }
        };
        Ok(SpurGearPair {
            module_m,
            teeth,
            pressure_angle_rad: angle,
        })
    }

    /// Teeth that can mesh (issue 42, class 7): standard teeth (addendum one module) neither
    /// pointed (the flanks meeting below the tip circle) nor interfering (a tip reaching below
    /// the mate's base circle), each refused with the key and the limit for these teeth.
    pub(super) fn gear_teeth(
        &self,
        raw: &raw::RawGears,
        pair: &SpurGearPair,
    ) -> Result<(), SceneError> {
        let degrees = |rad: f64| crate::io::text::fixed(rad.to_degrees(), 1);
        let at = |angle: f64| SpurGearPair {
            pressure_angle_rad: angle,
            ..*pair
        };
        let pointed = |p: &SpurGearPair| (0..2).find(|&i| p.tip_thickness_m(i) <= 0.0);
        let name = |i: usize| if i == 0 { "pinion" } else { "gear" };
        if let Some(i) = pointed(pair) {
            // The tip land shrinks as the angle grows: the largest angle with a land.
            let (mut lo, mut hi) = (1e-3, pair.pressure_angle_rad);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if pointed(&at(mid)).is_some() {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            return Err(self.error(
                "contact.gears.pressure_angle",
                format!(
                    "the {}'s teeth ({}) are pointed at `{}`: standard teeth (addendum one module) would have a tip thickness of {} mm, their flanks meeting below the tip circle",
                    name(i),
                    pair.teeth[i],
                    crate::io::text::cut(&raw.pressure_angle, 20),
                    crate::io::text::significant(pair.tip_thickness_m(i) * 1e3, 4, 1e6, true)
                ),
                Some(&format!(
                    "with {} and {} teeth the pressure angle must be below {} deg (20 deg is standard, 25 deg for stronger teeth)",
                    pair.teeth[0],
                    pair.teeth[1],
                    degrees(lo)
                )),
            ));
        }
        if let Some(i) = pair.undercut() {
            let other = 1 - i;
            // The fewest teeth of the undercut member that clear the mate's tip, the mate's
            // kept; and the smallest pressure angle that clears it (if any below pointed teeth).
            let fewest = (pair.teeth[i]..=100_000).find(|&n| {
                let mut teeth = pair.teeth;
                teeth[i] = n;
                SpurGearPair { teeth, ..*pair }.undercut().is_none()
            });
            let (mut lo, mut hi) = (pair.pressure_angle_rad, 89.0f64.to_radians());
            let clears = at(hi).undercut().is_none();
            if clears {
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if at(mid).undercut().is_none() {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
            }
            let mut fixes = Vec::new();
            if let Some(n) = fewest {
                fixes.push(format!(
                    "give the {} at least {n} teeth (with the {}'s {})",
                    name(i),
                    name(other),
                    pair.teeth[other]
                ));
            }
            if clears && pointed(&at(hi)).is_none() {
                fixes.push(format!("a pressure angle of at least {} deg", degrees(hi)));
            }
            let key = if fewest.is_some() {
                "contact.gears.teeth"
            } else {
                "contact.gears.pressure_angle"
            };
            return Err(self.error(
                key,
                format!(
                    "the teeth interfere: the {}'s tip reaches inside the {}'s base circle ({} and {} teeth at {} deg), so the {} would be undercut and the path of contact is not involute throughout",
                    name(other),
                    name(i),
                    pair.teeth[0],
                    pair.teeth[1],
                    degrees(pair.pressure_angle_rad),
                    name(i)
                ),
                Some(&format!("{} (standard teeth: at least 17 on a pinion at 20 deg)", fixes.join(", or "))),
            ));
        }
        Ok(())
    }
}

//! Dimensional values written with their unit, such as `"210 GPa"`, `"40 kN/m"` or `"20 mm"`.

/// The physical dimension a scene key expects.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dimension {
    Length,
    Pressure,
    Force,
    ForcePerLength,
    Angle,
    Hardness,
    Speed,
    Conductivity,
    Diffusivity,
    Density,
    SpecificHeat,
    Expansion,
    /// Rotational speed (rad/s).
    RotationalSpeed,
}

impl Dimension {
    /// Units accepted for the dimension with their factor to SI (radians for angles, the
    /// hardness number itself for hardness).
    fn units(self) -> &'static [(&'static str, f64)] {
        match self {
            Dimension::Length => &[
                ("m", 1.0),
                ("cm", 1e-2),
                ("mm", 1e-3),
                ("um", 1e-6),
                ("µm", 1e-6),
                ("nm", 1e-9),
                ("in", 0.0254),
            ],
            Dimension::Pressure => &[
                ("Pa", 1.0),
                ("kPa", 1e3),
                ("MPa", 1e6),
                ("GPa", 1e9),
                ("N/mm^2", 1e6),
                ("N/mm2", 1e6),
                ("psi", 6_894.757_293_168_361),
                ("ksi", 6_894_757.293_168_361),
            ],
            Dimension::Force => &[
                ("N", 1.0),
                ("kN", 1e3),
                ("MN", 1e6),
                ("lbf", 4.448_221_615_260_5),
            ],
            Dimension::ForcePerLength => &[
                ("N/m", 1.0),
                ("kN/m", 1e3),
                ("MN/m", 1e6),
                ("N/mm", 1e3),
                ("kN/mm", 1e6),
                ("lbf/in", 175.126_835_246_476_4),
            ],
            Dimension::Angle => &[("deg", std::f64::consts::PI / 180.0), ("rad", 1.0)],
            Dimension::Hardness => &[("HB", 1.0), ("BHN", 1.0), ("HBW", 1.0), ("HV", 1.0)],
            Dimension::Speed => &[
                ("m/s", 1.0),
                ("mm/s", 1e-3),
                ("km/h", 1.0 / 3.6),
                ("m/min", 1.0 / 60.0),
            ],
            Dimension::Conductivity => &[
                ("W/(m K)", 1.0),
                ("W/(m*K)", 1.0),
                ("W/mK", 1.0),
                ("W/m/K", 1.0),
            ],
            Dimension::Diffusivity => &[("m^2/s", 1.0), ("mm^2/s", 1e-6), ("m2/s", 1.0)],
            Dimension::Density => &[("kg/m^3", 1.0), ("kg/m3", 1.0), ("g/cm^3", 1e3)],
            Dimension::SpecificHeat => &[
                ("J/(kg K)", 1.0),
                ("J/(kg*K)", 1.0),
                ("J/kgK", 1.0),
                ("J/kg/K", 1.0),
            ],
            Dimension::Expansion => &[("/K", 1.0), ("1/K", 1.0), ("/degC", 1.0)],
            Dimension::RotationalSpeed => &[
                ("rpm", std::f64::consts::PI / 30.0),
                ("1/min", std::f64::consts::PI / 30.0),
                ("rad/s", 1.0),
                ("rev/s", 2.0 * std::f64::consts::PI),
            ],
        }
    }

    /// An example for error messages.
    pub fn example(self) -> &'static str {
        match self {
            Dimension::Length => "\"20 mm\"",
            Dimension::Pressure => "\"210 GPa\"",
            Dimension::Force => "\"1.5 kN\"",
            Dimension::ForcePerLength => "\"40 kN/m\"",
            Dimension::Angle => "\"20 deg\"",
            Dimension::Hardness => "\"300 HB\"",
            Dimension::Speed => "\"2 m/s\"",
            Dimension::Conductivity => "\"50 W/(m K)\"",
            Dimension::Diffusivity => "\"1.4e-5 m^2/s\"",
            Dimension::Density => "\"7850 kg/m^3\"",
            Dimension::SpecificHeat => "\"475 J/(kg K)\"",
            Dimension::Expansion => "\"11.5e-6 /K\"",
            Dimension::RotationalSpeed => "\"1500 rpm\"",
        }
    }

    /// The SI unit values are converted to (the hardness number for hardness).
    pub fn si_unit(self) -> &'static str {
        match self {
            Dimension::Length => "m",
            Dimension::Pressure => "Pa",
            Dimension::Force => "N",
            Dimension::ForcePerLength => "N/m",
            Dimension::Angle => "rad",
            Dimension::Hardness => "HB",
            Dimension::Speed => "m/s",
            Dimension::Conductivity => "W/(m K)",
            Dimension::Diffusivity => "m^2/s",
            Dimension::Density => "kg/m^3",
            Dimension::SpecificHeat => "J/(kg K)",
            Dimension::Expansion => "/K",
            Dimension::RotationalSpeed => "rad/s",
        }
    }

    pub fn unit_list(self) -> String {
        self.units()
            .iter()
            .map(|(u, _)| *u)
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// Parses `"<number> <unit>"` (the space is optional) into SI.
pub fn parse(text: &str, dimension: Dimension) -> Result<f64, String> {
    let text = text.trim();
    let bytes = text.as_bytes();
    let mut split = 0;
    while split < bytes.len() {
        let c = bytes[split];
        let exponent = (c == b'e' || c == b'E')
            && bytes
                .get(split + 1)
                .is_some_and(|n| n.is_ascii_digit() || *n == b'-' || *n == b'+');
        if c.is_ascii_digit() || c == b'.' || c == b'+' || c == b'-' || exponent {
            split += 1;
        } else {
            break;
        }
    }
    let (number, unit) = text.split_at(split);
    let number = number.trim();
    let unit = unit.trim();
    if unit.is_empty() {
        return Err(format!(
            "`{text}` has no unit; write it with one, e.g. {} (units: {})",
            dimension.example(),
            dimension.unit_list()
        ));
    }
    let value: f64 = number.parse().map_err(|_| {
        format!(
            "`{text}` does not start with a number; write e.g. {}",
            dimension.example()
        )
    })?;
    let factor = dimension
        .units()
        .iter()
        .find(|(u, _)| *u == unit)
        .map(|(_, f)| *f)
        .ok_or_else(|| {
            format!(
                "unknown unit `{unit}` in `{text}`; use one of: {}",
                dimension.unit_list()
            )
        })?;
    Ok(value * factor)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn parses_common_units() {
        assert_relative_eq!(parse("210 GPa", Dimension::Pressure).expect("ok"), 210e9);
        assert_relative_eq!(
            parse("40 kN/m", Dimension::ForcePerLength).expect("ok"),
            40e3
        );
        assert_relative_eq!(parse("20mm", Dimension::Length).expect("ok"), 0.02);
        assert_relative_eq!(parse("1.5e3 N", Dimension::Force).expect("ok"), 1500.0);
        assert_relative_eq!(
            parse("20 deg", Dimension::Angle).expect("ok"),
            20f64.to_radians()
        );
        assert_relative_eq!(parse("-3 mm", Dimension::Length).expect("ok"), -0.003);
        assert_relative_eq!(parse("300 HB", Dimension::Hardness).expect("ok"), 300.0);
        assert_relative_eq!(parse("2 m/s", Dimension::Speed).expect("ok"), 2.0);
        assert_relative_eq!(
            parse("50 W/(m K)", Dimension::Conductivity).expect("ok"),
            50.0
        );
        assert_relative_eq!(
            parse("1.4e-5 m^2/s", Dimension::Diffusivity).expect("ok"),
            1.4e-5
        );
        assert_relative_eq!(
            parse("11.5e-6 /K", Dimension::Expansion).expect("ok"),
            11.5e-6
        );
        assert_relative_eq!(
            parse("475 J/(kg K)", Dimension::SpecificHeat).expect("ok"),
            475.0
        );
    }

    #[test]
    fn rejects_missing_or_wrong_units() {
        assert!(parse("210", Dimension::Pressure)
            .expect_err("no unit")
            .contains("no unit"));
        assert!(parse("40 kN", Dimension::ForcePerLength)
            .expect_err("force")
            .contains("unknown unit `kN`"));
        assert!(parse("abc MPa", Dimension::Pressure)
            .expect_err("nan")
            .contains("number"));
    }
}

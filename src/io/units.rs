//! Dimensional values written with their unit, such as `"210 GPa"`, `"40 kN/m"` or `"20 mm"`:
//! the one number-and-unit parser of scenes, command-line flags (`--spacing 1e-6m`,
//! `--e-star 1.15e11Pa`) and the headers of surface files (`# Width: 1.6e-5 m`). The number
//! may use exponent notation (`1.6e-5`, `2E3`); the unit follows, with or without a space.

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
    /// Archard's dimensional wear coefficient: volume worn per load and sliding distance
    /// (m³/(N m) = m²/N).
    WearCoefficient,
    /// Dynamic viscosity (Pa s).
    DynamicViscosity,
    /// Kinematic viscosity (m²/s).
    KinematicViscosity,
    /// The inverse of a pressure (1/Pa): a pressure-viscosity coefficient.
    InversePressure,
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
                // The micro sign (U+00B5) and the Greek mu (U+03BC): keyboards give either.
                ("µm", 1e-6),
                ("μm", 1e-6),
                ("nm", 1e-9),
                ("pm", 1e-12),
                ("in", 0.0254),
                ("km", 1e3),
            ],
            Dimension::Pressure => &[
                ("Pa", 1.0),
                ("kPa", 1e3),
                ("MPa", 1e6),
                ("GPa", 1e9),
                ("TPa", 1e12),
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
            Dimension::WearCoefficient => &[
                ("mm^3/(N m)", 1e-9),
                ("mm^3/(N*m)", 1e-9),
                ("mm^3/Nm", 1e-9),
                ("mm3/(N m)", 1e-9),
                ("mm3/Nm", 1e-9),
                ("m^3/(N m)", 1.0),
                ("m^3/(N*m)", 1.0),
                ("m3/(N m)", 1.0),
                ("m^2/N", 1.0),
                ("m2/N", 1.0),
            ],
            Dimension::DynamicViscosity => &[
                ("Pa s", 1.0),
                ("Pa*s", 1.0),
                ("Pa.s", 1.0),
                ("mPa s", 1e-3),
                ("mPa*s", 1e-3),
                ("mPa.s", 1e-3),
                ("cP", 1e-3),
                ("N s/m^2", 1.0),
            ],
            Dimension::KinematicViscosity => &[
                ("mm^2/s", 1e-6),
                ("mm2/s", 1e-6),
                ("cSt", 1e-6),
                ("m^2/s", 1.0),
                ("m2/s", 1.0),
            ],
            Dimension::InversePressure => &[
                ("1/Pa", 1.0),
                ("/Pa", 1.0),
                ("Pa^-1", 1.0),
                ("1/MPa", 1e-6),
                ("/MPa", 1e-6),
                ("MPa^-1", 1e-6),
                ("1/GPa", 1e-9),
                ("/GPa", 1e-9),
                ("GPa^-1", 1e-9),
                ("m^2/N", 1.0),
                ("mm^2/N", 1e-6),
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
            Dimension::WearCoefficient => "\"2e-6 mm^3/(N m)\"",
            Dimension::DynamicViscosity => "\"0.05 Pa s\"",
            Dimension::KinematicViscosity => "\"220 mm^2/s\"",
            Dimension::InversePressure => "\"20 GPa^-1\"",
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
            Dimension::WearCoefficient => "m^2/N",
            Dimension::DynamicViscosity => "Pa s",
            Dimension::KinematicViscosity => "m^2/s",
            Dimension::InversePressure => "1/Pa",
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

/// The factor to SI of `unit` of `dimension` (`"um"` of a length is 1e-6), if it is one.
pub fn factor(unit: &str, dimension: Dimension) -> Option<f64> {
    let unit = unit.trim();
    dimension
        .units()
        .iter()
        .find(|(u, _)| *u == unit)
        .map(|(_, f)| *f)
}

/// The unit of `text` as `dimension` spells it (`"700 HV"` gives `HV`), if it is one.
pub fn scale_of(text: &str, dimension: Dimension) -> Option<&'static str> {
    let (_, unit) = split_number(text.trim());
    dimension
        .units()
        .iter()
        .find(|(u, _)| *u == unit)
        .map(|(u, _)| *u)
}

/// `text` split into its number and its unit: the longest start that reads as a number
/// (sign, digits, a point, an exponent `e`/`E` only where digits follow it), so that
/// `1e-6m` is `1e-6` and `m`, and `1 em` would be `1` and `em`.
fn split_number(text: &str) -> (&str, &str) {
    let bytes = text.as_bytes();
    let mut split = 0;
    let mut seen_exponent = false;
    while split < bytes.len() {
        let c = bytes[split];
        let sign =
            (c == b'+' || c == b'-') && (split == 0 || matches!(bytes[split - 1], b'e' | b'E'));
        let exponent = (c == b'e' || c == b'E')
            && !seen_exponent
            && split > 0
            && match bytes.get(split + 1) {
                Some(n) if n.is_ascii_digit() => true,
                Some(b'+' | b'-') => bytes.get(split + 2).is_some_and(u8::is_ascii_digit),
                _ => false,
            };
        seen_exponent |= exponent;
        if c.is_ascii_digit() || c == b'.' || sign || exponent {
            split += 1;
        } else {
            break;
        }
    }
    let (number, unit) = text.split_at(split);
    (number.trim(), unit.trim())
}

/// Parses `"<number> <unit>"` (the space is optional) into SI. The number must be finite
/// (`1e400` is out of range).
pub fn parse(text: &str, dimension: Dimension) -> Result<f64, String> {
    let text = text.trim();
    let shown = super::text::cut(text, 40);
    let (number, unit) = split_number(text);
    if unit.is_empty() {
        return Err(format!(
            "`{shown}` has no unit; write it with one, e.g. {} (units: {})",
            dimension.example(),
            dimension.unit_list()
        ));
    }
    let value: f64 = number.parse().map_err(|_| {
        format!(
            "`{shown}` does not start with a number; write e.g. {}",
            dimension.example()
        )
    })?;
    if !value.is_finite() {
        return Err(format!(
            "`{shown}` is out of range (at most 1.8e308 in size); write e.g. {}",
            dimension.example()
        ));
    }
    let factor = factor(unit, dimension).ok_or_else(|| {
        if let Some(why) = wrong_kind(unit, dimension) {
            return format!("`{shown}`: {why}");
        }
        format!(
            "unknown unit `{}` in `{shown}`; use one of: {}",
            super::text::cut(unit, 20),
            dimension.unit_list()
        )
    })?;
    Ok(value * factor)
}

/// Why `unit`, not one of `dimension`'s, is a mistake a user makes, with the fix: a force for a
/// line contact's load (per unit length), a Rockwell hardness (no factor converts it), a
/// hardness or a force given for a pressure or modulus.
fn wrong_kind(unit: &str, dimension: Dimension) -> Option<String> {
    let rockwell = unit.len() >= 3 && unit.starts_with("HR") && unit.is_ascii();
    match dimension {
        Dimension::ForcePerLength if factor(unit, Dimension::Force).is_some() => Some(format!(
            "a line contact's load is a force per unit length of the contact (N/m), not a force; write e.g. \"1000 N/mm\" for 1000 N on each millimetre of length (units: {})",
            dimension.unit_list()
        )),
        Dimension::Hardness if rockwell => Some(format!(
            "a Rockwell hardness ({unit}) has no factor to Vickers or Brinell: convert it with a table (ASTM E140; 60 HRC is about 700 HV) and give the HV or HB value, e.g. \"700 HV\""
        )),
        Dimension::Pressure if factor(unit, Dimension::Hardness).is_some() || rockwell => {
            Some(format!(
                "a hardness is not a modulus or a stress; give a pressure, e.g. {} (units: {})",
                dimension.example(),
                dimension.unit_list()
            ))
        }
        _ => None,
    }
}

/// A hardness as a pressure: a pressure (`3 GPa`) or a hardness number (`300 HV`, `1e3HV`,
/// kgf/mm², times 9.80665 MPa).
pub fn hardness_pa(text: &str) -> Result<f64, String> {
    let (_, unit) = split_number(text.trim());
    if factor(unit, Dimension::Hardness).is_some() || unit.starts_with("HR") {
        Ok(parse(text, Dimension::Hardness)? * 9.80665e6)
    } else {
        parse(text, Dimension::Pressure).map_err(|m| {
            format!(
                "{m}, or a hardness number ({})",
                Dimension::Hardness.unit_list()
            )
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Issue 24, classes 18 to 20: a force for a line load, a Rockwell hardness, a hardness for a
    /// modulus are refused saying why; TPa, which the README's bounds use, is a unit.
    #[test]
    fn wrong_kinds_of_unit_say_why() {
        let line = parse("1000 N", Dimension::ForcePerLength).expect_err("force");
        assert!(
            line.contains("per unit length") && line.contains("1000 N/mm"),
            "{line}"
        );
        assert_relative_eq!(
            parse("1000 N/mm", Dimension::ForcePerLength).expect("ok"),
            1e6
        );
        for text in ["60 HRC", "60HRC"] {
            let rockwell = parse(text, Dimension::Hardness).expect_err("HRC");
            assert!(
                rockwell.contains("ASTM E140") && rockwell.contains("HV"),
                "{rockwell}"
            );
            let rockwell = hardness_pa(text).expect_err("HRC");
            assert!(rockwell.contains("ASTM E140"), "{rockwell}");
        }
        let modulus = parse("300HV", Dimension::Pressure).expect_err("hardness");
        assert!(modulus.contains("a hardness is not a modulus"), "{modulus}");
        assert_relative_eq!(parse("10 TPa", Dimension::Pressure).expect("ok"), 1e13);
    }

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

    /// The lubricant's units (issue 52): viscosities and a pressure-viscosity coefficient.
    #[test]
    fn lubricant_units() {
        assert_relative_eq!(
            parse("0.05 Pa s", Dimension::DynamicViscosity).expect("ok"),
            0.05
        );
        assert_relative_eq!(
            parse("50 cP", Dimension::DynamicViscosity).expect("ok"),
            0.05
        );
        assert_relative_eq!(
            parse("220 mm^2/s", Dimension::KinematicViscosity).expect("ok"),
            220e-6
        );
        assert_relative_eq!(
            parse("19 cSt", Dimension::KinematicViscosity).expect("ok"),
            19e-6
        );
        assert_relative_eq!(
            parse("20 GPa^-1", Dimension::InversePressure).expect("ok"),
            2e-8
        );
        assert_relative_eq!(
            parse("2e-8 1/Pa", Dimension::InversePressure).expect("ok"),
            2e-8
        );
        assert_relative_eq!(
            parse("20 /GPa", Dimension::InversePressure).expect("ok"),
            2e-8
        );
    }

    #[test]
    fn rejects_missing_or_wrong_units() {
        assert!(parse("210", Dimension::Pressure)
            .expect_err("no unit")
            .contains("no unit"));
        assert!(parse("40 kN", Dimension::ForcePerLength)
            .expect_err("force")
            .contains("per unit length"));
        assert!(parse("abc MPa", Dimension::Pressure)
            .expect_err("nan")
            .contains("number"));
    }

    /// Issue 24, class 9: exponent notation before a unit, with or without a space; class 16:
    /// the lengths of files and flags (`pm`, `μm`) in scenes too.
    #[test]
    fn exponents_and_every_length_unit() {
        assert_relative_eq!(parse("1.6e-5 m", Dimension::Length).expect("ok"), 1.6e-5);
        assert_relative_eq!(parse("1e-6m", Dimension::Length).expect("ok"), 1e-6);
        assert_relative_eq!(
            parse("1.15e11Pa", Dimension::Pressure).expect("ok"),
            1.15e11
        );
        assert_relative_eq!(parse("1e3HV", Dimension::Hardness).expect("ok"), 1e3);
        assert_relative_eq!(parse("2E3 N", Dimension::Force).expect("ok"), 2e3);
        assert_relative_eq!(parse("2E+3N", Dimension::Force).expect("ok"), 2e3);
        assert_relative_eq!(parse("5 pm", Dimension::Length).expect("ok"), 5e-12);
        assert_relative_eq!(parse("2 μm", Dimension::Length).expect("ok"), 2e-6);
        assert_relative_eq!(parse("2µm", Dimension::Length).expect("ok"), 2e-6);
        assert_relative_eq!(hardness_pa("1e3HV").expect("ok"), 9.80665e9);
        assert_relative_eq!(hardness_pa("3GPa").expect("ok"), 3e9);
        assert!(hardness_pa("3 N").expect_err("force").contains("HV"));
        // An overflowing number is out of range, not infinite.
        assert!(parse("1e400 m", Dimension::Length)
            .expect_err("overflow")
            .contains("out of range"));
        // A long value is echoed cut.
        let long = format!("1 {}", "x".repeat(100_000));
        let error = parse(&long, Dimension::Length).expect_err("long");
        assert!(error.len() < 400, "{} characters", error.len());
    }
}

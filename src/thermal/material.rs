//! Thermal properties of a body and a small library of materials.

/// Conductivity, diffusivity and linear expansion of an isotropic body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThermalProperties {
    /// Thermal conductivity `K`, W/(m K).
    pub conductivity_w_per_m_k: f64,
    /// Thermal diffusivity `κ = K / (ρ c)`, m²/s.
    pub diffusivity_m2_per_s: f64,
    /// Linear thermal expansion coefficient `α`, 1/K.
    pub expansion_per_k: f64,
}

impl ThermalProperties {
    /// Thermal effusivity `K / √κ = √(K ρ c)`, W s^½/(m² K): which body takes more of the heat
    /// at high Péclet numbers (Blok's partition tends to `e1 / (e1 + e2)`).
    pub fn effusivity(&self) -> f64 {
        self.conductivity_w_per_m_k / self.diffusivity_m2_per_s.sqrt()
    }
}

/// A named material's thermal properties.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThermalPreset {
    pub name: &'static str,
    pub properties: ThermalProperties,
    pub source: &'static str,
}

const fn preset(
    name: &'static str,
    conductivity: f64,
    density: f64,
    specific_heat: f64,
    expansion: f64,
    source: &'static str,
) -> ThermalPreset {
    ThermalPreset {
        name,
        properties: ThermalProperties {
            conductivity_w_per_m_k: conductivity,
            diffusivity_m2_per_s: conductivity / (density * specific_heat),
            expansion_per_k: expansion,
        },
        source,
    }
}

/// Room-temperature values of the materials that `material = "..."` names (the same names as
/// the elastic presets of [`crate::contact::material::PRESETS`]). Typical values, not those of
/// a particular grade: give `conductivity`, `diffusivity` and `expansion` for design work.
///
/// ## Sources
/// - Steel's conductivity 46.6 W/(m K) and boron carbide's 92 W/(m K): Siniawski, Harris, Wang
///   & Liu, Wear initiation of steel sliding against a thin boron carbide coating, *Tribology
///   Letters* 15 (2003), as quoted in the lecture notes (`../shared/seed`).
/// - Densities, specific heats, expansion and the other conductivities: typical handbook values
///   (F. P. Incropera et al., *Fundamentals of Heat and Mass Transfer*, appendix A; ASM
///   Handbook vol. 2 for the aluminium and titanium alloys; manufacturers' data sheets for the
///   ceramics and cemented carbide).
pub const THERMAL_PRESETS: [ThermalPreset; 8] = [
    preset(
        "steel",
        46.6,
        7850.0,
        475.0,
        11.5e-6,
        "Siniawski et al. 2003 (K); handbook",
    ),
    preset(
        "bearing_steel",
        46.6,
        7810.0,
        458.0,
        11.9e-6,
        "AISI 52100; handbook",
    ),
    preset(
        "cast_iron",
        52.0,
        7200.0,
        460.0,
        10.5e-6,
        "grey cast iron; handbook",
    ),
    preset(
        "aluminium",
        167.0,
        2700.0,
        896.0,
        23.6e-6,
        "6061-T6; ASM handbook",
    ),
    preset(
        "titanium",
        6.7,
        4430.0,
        526.0,
        8.6e-6,
        "Ti-6Al-4V; ASM handbook",
    ),
    preset(
        "silicon_nitride",
        30.0,
        3200.0,
        690.0,
        3.2e-6,
        "bearing-grade Si3N4; data sheets",
    ),
    preset(
        "tungsten_carbide",
        84.0,
        15_600.0,
        203.0,
        5.2e-6,
        "WC-6Co; data sheets",
    ),
    preset(
        "boron_carbide",
        92.0,
        2520.0,
        950.0,
        5.0e-6,
        "Siniawski et al. 2003 (K); data sheets",
    ),
];

/// The thermal preset of this name.
pub fn thermal_preset(name: &str) -> Option<ThermalProperties> {
    THERMAL_PRESETS
        .iter()
        .find(|preset| preset.name == name)
        .map(|preset| preset.properties)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::material::PRESETS;

    #[test]
    fn every_elastic_preset_has_thermal_properties_and_back() {
        for preset in PRESETS {
            assert!(thermal_preset(preset.name).is_some(), "{}", preset.name);
        }
        for preset in THERMAL_PRESETS {
            assert!(
                PRESETS.iter().any(|p| p.name == preset.name),
                "{}",
                preset.name
            );
            let p = preset.properties;
            // Diffusivities of metals and ceramics lie between 1e-6 and 1e-4 m²/s.
            assert!(
                (1e-6..1e-4).contains(&p.diffusivity_m2_per_s),
                "{}",
                preset.name
            );
        }
        let steel = thermal_preset("steel").expect("steel");
        assert!((steel.diffusivity_m2_per_s - 46.6 / (7850.0 * 475.0)).abs() < 1e-12);
    }
}

//! Elastic constants and yield strength of a body's material.

/// Isotropic linear-elastic constants.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Young's modulus, Pa.
    pub modulus_pa: f64,
    /// Poisson's ratio, in (-1, 0.5].
    pub poisson: f64,
}

/// A named material with typical handbook constants (room temperature).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Preset {
    pub name: &'static str,
    pub material: Material,
    pub description: &'static str,
}

/// Presets usable as `material = "steel"` in scenes. Values are typical, not guaranteed for a
/// particular grade: give `modulus` and `poisson` explicitly for design work.
pub const PRESETS: [Preset; 8] = [
    Preset {
        name: "steel",
        material: Material {
            modulus_pa: 210e9,
            poisson: 0.30,
        },
        description: "carbon and alloy steel",
    },
    Preset {
        name: "bearing_steel",
        material: Material {
            modulus_pa: 208e9,
            poisson: 0.30,
        },
        description: "through-hardened bearing steel (AISI 52100)",
    },
    Preset {
        name: "cast_iron",
        material: Material {
            modulus_pa: 120e9,
            poisson: 0.26,
        },
        description: "grey cast iron",
    },
    Preset {
        name: "aluminium",
        material: Material {
            modulus_pa: 70e9,
            poisson: 0.33,
        },
        description: "aluminium alloy",
    },
    Preset {
        name: "titanium",
        material: Material {
            modulus_pa: 114e9,
            poisson: 0.34,
        },
        description: "Ti-6Al-4V",
    },
    Preset {
        name: "silicon_nitride",
        material: Material {
            modulus_pa: 310e9,
            poisson: 0.27,
        },
        description: "Si3N4 (hybrid bearing balls)",
    },
    Preset {
        name: "tungsten_carbide",
        material: Material {
            modulus_pa: 600e9,
            poisson: 0.22,
        },
        description: "cemented WC-Co",
    },
    Preset {
        name: "boron_carbide",
        material: Material {
            modulus_pa: 450e9,
            poisson: 0.17,
        },
        description: "B4C (boron carbide, a hard coating)",
    },
];

/// Looks up a preset by name.
pub fn preset(name: &str) -> Option<&'static Preset> {
    PRESETS.iter().find(|p| p.name == name)
}

/// Conversion of a Brinell or Vickers hardness number to a yield strength.
///
/// The hardness number (kgf/mm²) is converted to a pressure `H` (×9.80665 MPa) and Tabor's
/// relation `H ≈ 3 Y` for the mean pressure under a fully plastic indentation gives `Y = H/3`.
///
/// ## Reference
/// D. Tabor, *The Hardness of Metals*, Oxford (1951); Johnson, *Contact Mechanics* (1985),
/// ch. 6 (fully plastic indentation, `p_m ≈ 3Y`).
pub fn yield_strength_from_hardness_pa(hardness_number_kgf_per_mm2: f64) -> f64 {
    hardness_number_kgf_per_mm2 * 9.80665e6 / 3.0
}

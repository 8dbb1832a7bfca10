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

const fn coating(
    name: &'static str,
    modulus_pa: f64,
    poisson: f64,
    description: &'static str,
) -> Preset {
    Preset {
        name,
        material: Material {
            modulus_pa,
            poisson,
        },
        description,
    }
}

/// Presets for coatings, interlayers and liners (usable for any body; elastic constants only,
/// no thermal properties). Typical values of the material as deposited or moulded: a
/// coating's modulus varies with the process by tens of per cent (a plasma-sprayed alumina is
/// half the sintered one's), so give `modulus` and `poisson` measured on the coating for
/// design work. Sources (values typical of the ranges they give; no table number checked):
/// K. Holmberg, A. Matthews, *Coatings Tribology*, 2nd ed., Elsevier (2009), ch. 2 and 5
/// (TiN, CrN, DLC, Al2O3, WC-Co, B4C); J. Robertson, Diamond-like amorphous carbon, *Mater.
/// Sci. Eng. R* 37 (2002) 129–281 (a-C:H: E about 100–200 GPa); *CRC Handbook of Chemistry
/// and Physics* (elastic constants of the elements: Cr); ASM Handbook vol. 18, *Friction,
/// Lubrication and Wear Technology* (1992) (babbitt); manufacturers' data sheets as collected
/// in ASM Handbook vol. 21 and polymer handbooks (PTFE, PEEK, UHMWPE).
pub const COATING_PRESETS: [Preset; 11] = [
    coating("tin", 450e9, 0.25, "TiN (PVD titanium nitride coating)"),
    coating("crn", 300e9, 0.28, "CrN (PVD chromium nitride coating)"),
    coating(
        "dlc",
        150e9,
        0.2,
        "DLC a-C:H (hydrogenated amorphous carbon coating)",
    ),
    coating(
        "alumina",
        380e9,
        0.22,
        "Al2O3 (dense alumina; a plasma-sprayed layer is much more compliant)",
    ),
    coating(
        "wc_co",
        600e9,
        0.22,
        "WC-Co (cemented tungsten carbide, as tungsten_carbide)",
    ),
    coating("b4c", 450e9, 0.17, "B4C (as boron_carbide)"),
    coating(
        "chromium",
        279e9,
        0.21,
        "Cr (an interlayer under DLC or nitrides)",
    ),
    coating(
        "babbitt",
        52e9,
        0.33,
        "tin babbitt (white metal bearing lining)",
    ),
    coating("ptfe", 0.5e9, 0.46, "PTFE"),
    coating("peek", 3.6e9, 0.38, "PEEK"),
    coating("uhmwpe", 0.8e9, 0.46, "UHMWPE"),
];

/// Looks up a preset by name (the bodies' presets, then the coatings').
pub fn preset(name: &str) -> Option<&'static Preset> {
    PRESETS
        .iter()
        .chain(COATING_PRESETS.iter())
        .find(|p| p.name == name)
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

#[cfg(test)]
mod coating_preset_tests {
    use super::*;

    #[test]
    fn coating_presets_are_found_and_leave_the_bodies_presets_alone() {
        assert_eq!(preset("steel").map(|p| p.material.modulus_pa), Some(210e9));
        assert_eq!(preset("dlc").map(|p| p.material.modulus_pa), Some(150e9));
        // The aliases carry the bodies' constants.
        assert_eq!(
            preset("b4c").map(|p| p.material),
            preset("boron_carbide").map(|p| p.material)
        );
        assert_eq!(
            preset("wc_co").map(|p| p.material),
            preset("tungsten_carbide").map(|p| p.material)
        );
        for p in COATING_PRESETS {
            assert!(PRESETS.iter().all(|b| b.name != p.name), "{}", p.name);
            assert!(p.material.modulus_pa > 1e8 && (0.0..0.5).contains(&p.material.poisson));
        }
    }
}

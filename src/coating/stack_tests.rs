//! The stack of several layers ([`Layered::stack_wave`]) against the single coating and the
//! homogeneous half-space, and its interface and surface conditions.

use super::response::{Layer, Layered, Side, WaveAtDepth};
use super::Interlayers;
use crate::contact::material::Material;

const STEEL: Material = Material {
    modulus_pa: 210e9,
    poisson: 0.3,
};
const CHROMIUM: Material = Material {
    modulus_pa: 279e9,
    poisson: 0.21,
};
const DLC: Material = Material {
    modulus_pa: 150e9,
    poisson: 0.2,
};
const TIN: Material = Material {
    modulus_pa: 450e9,
    poisson: 0.25,
};
const ALUMINIUM: Material = Material {
    modulus_pa: 70e9,
    poisson: 0.33,
};

fn stack(top: (Material, f64), under: &[(Material, f64)], substrate: Material) -> Layered {
    let layers: Vec<Layer> = under
        .iter()
        .map(|&(material, thickness_m)| Layer {
            material,
            thickness_m,
        })
        .collect();
    Layered {
        coating: top.0,
        substrate,
        thickness_m: top.1,
        under: Interlayers::of(&layers).expect("few layers"),
    }
}

fn single(coating: Material, thickness_m: f64, substrate: Material) -> Layered {
    stack((coating, thickness_m), &[], substrate)
}

/// The fields of the wave `k` at depth `z` on `side`: the stresses along `n` per unit load,
/// the plane displacements and the anti-plane `U` (scaled by the top layer's `G1`, so
/// rescaled here by `G1` to compare stacks with different top layers).
fn fields(layered: &Layered, k: f64, z: f64, side: Side) -> Vec<f64> {
    let at: WaveAtDepth = layered
        .wave(k * layered.thickness_m)
        .at(k * z, side, layered);
    let g1 = layered.coating.modulus_pa / (2.0 * (1.0 + layered.coating.poisson));
    let mut out: Vec<f64> = at
        .stress([0.6, 0.8])
        .iter()
        .flat_map(|c| c.iter().flat_map(|l| l.iter().copied()))
        .collect();
    // 2 G1 k u: divide by G1 to compare stacks with different top layers.
    for d in at.plane_displacements().iter().flatten() {
        out.push(d / g1 * 1e9);
    }
    out.push(at.antiplane[0] / g1 * 1e9);
    out
}

/// The largest difference of two field vectors over the largest value of the first.
fn relative(a: &[f64], b: &[f64]) -> f64 {
    let scale = a.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    a.iter()
        .zip(b)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
        / scale
}

const WAVES_PER_M: [f64; 7] = [1e2, 1e4, 1e5, 3e5, 1e6, 1e7, 1e9];

#[test]
fn one_layer_by_the_stack_is_the_single_coating() {
    let layered = single(TIN, 2e-6, STEEL);
    let mut worst = 0.0_f64;
    for k_h in [1e-4, 1e-2, 0.3, 1.0, 4.0, 40.0, 1e3, 1e5] {
        let (a, b) = (layered.wave(k_h), layered.stack_wave(k_h));
        let mut da: Vec<f64> = a.pressure.to_vec();
        da.extend(a.shear);
        da.extend(a.antiplane);
        let mut db: Vec<f64> = b.pressure.to_vec();
        db.extend(b.shear);
        db.extend(b.antiplane);
        worst = worst.max(relative(&da, &db));
    }
    eprintln!("one layer, stack against single: {worst:.2e}");
    assert!(worst < 1e-13, "{worst}");
}

#[test]
fn two_layers_of_one_material_are_one_coating_of_their_thickness() {
    let (h1, h2) = (1.5e-6, 4e-6);
    let two = stack((TIN, h1), &[(TIN, h2)], STEEL);
    let one = single(TIN, h1 + h2, STEEL);
    let mut worst = 0.0_f64;
    for k in WAVES_PER_M {
        for z in [0.0, 0.7e-6, h1, 3e-6, h1 + h2, 8e-6, 30e-6] {
            for side in [Side::Coating, Side::Substrate] {
                let (a, b) = (fields(&one, k, z, side), fields(&two, k, z, side));
                worst = worst.max(relative(&a, &b));
            }
        }
        let (ca, cb) = (
            one.normal_compliance_times_k(k * one.thickness_m),
            two.normal_compliance_times_k(k * two.thickness_m),
        );
        worst = worst.max((ca - cb).abs() / ca);
    }
    eprintln!("two layers of TiN against one coating: {worst:.2e}");
    assert!(worst < 1e-12, "{worst}");
}

#[test]
fn a_layer_of_the_substrates_material_is_the_substrate() {
    // DLC on a layer of steel on steel: the single DLC coating; and a top layer of the
    // coating's material on the coating is that coating thickened (the test above).
    let h = 2e-6;
    let buried = stack((DLC, h), &[(STEEL, 3e-6)], STEEL);
    let one = single(DLC, h, STEEL);
    let mut worst = 0.0_f64;
    for k in WAVES_PER_M {
        for z in [0.0, 1e-6, h, 3.5e-6, 5e-6, 12e-6] {
            for side in [Side::Coating, Side::Substrate] {
                worst = worst.max(relative(
                    &fields(&one, k, z, side),
                    &fields(&buried, k, z, side),
                ));
            }
        }
    }
    eprintln!("a steel layer on steel under DLC against the DLC coating: {worst:.2e}");
    assert!(worst < 1e-12, "{worst}");
}

#[test]
fn equal_moduli_everywhere_are_the_homogeneous_half_space() {
    let layered = stack((STEEL, 1e-6), &[(STEEL, 2e-6), (STEEL, 0.5e-6)], STEEL);
    let mut worst = 0.0_f64;
    for k_h in [1e-3, 0.1, 1.0, 7.0, 60.0] {
        let wave = layered.wave(k_h);
        for zeta in [0.0, 0.3, k_h, 2.5 * k_h, 3.2 * k_h, 3.5 * k_h, 5.0 * k_h] {
            let at = wave.at(zeta, Side::Substrate, &layered);
            let decay = (-zeta).exp();
            // Johnson (1985) §2.8: F_p = (1 + ζ) e^(-ζ), F_q = ζ e^(-ζ), U = e^(-ζ).
            let expected_p = [(1.0 + zeta) * decay, -zeta * decay, (zeta - 1.0) * decay];
            let expected_q = [zeta * decay, (1.0 - zeta) * decay, (zeta - 2.0) * decay];
            for d in 0..3 {
                worst = worst.max((at.pressure[d] - expected_p[d]).abs());
                worst = worst.max((at.shear[d] - expected_q[d]).abs());
            }
            worst = worst.max((at.antiplane[0] - decay).abs());
        }
        let e_prime = STEEL.modulus_pa / (1.0 - STEEL.poisson * STEEL.poisson);
        let c = layered.normal_compliance_times_k(k_h);
        worst = worst.max((c * e_prime / 2.0 - 1.0).abs());
    }
    eprintln!("three layers of steel on steel against the homogeneous waves: {worst:.2e}");
    assert!(worst < 1e-12, "{worst}");
}

#[test]
fn a_stack_is_continuous_at_every_interface_and_free_on_its_surface() {
    // TiN on Cr on DLC on aluminium, a soft layer in the middle.
    let layered = stack((TIN, 1e-6), &[(CHROMIUM, 0.3e-6), (DLC, 2e-6)], ALUMINIUM);
    let interfaces = layered.interface_depths_m();
    assert_eq!(interfaces.len(), 3);
    let (mut worst_continuity, mut smallest_jump, mut worst_surface) = (0.0_f64, f64::MAX, 0.0_f64);
    for k in WAVES_PER_M {
        let wave = layered.wave(k * layered.thickness_m);
        let surface = wave.at(0.0, Side::Coating, &layered).stress([0.6, 0.8]);
        // σzz = -p, σxz = -qx, σyz = -qy on the surface (components [xx, yy, zz, yz, xz, xy],
        // loads [p, qx, qy], (re, im)).
        let expected = [(2, 0, -1.0), (4, 1, -1.0), (3, 2, -1.0)];
        for component in [2, 3, 4] {
            for (load, factor) in surface[component].iter().enumerate() {
                let want = expected
                    .iter()
                    .find(|e| e.0 == component && e.1 == load)
                    .map_or(0.0, |e| e.2);
                worst_surface = worst_surface.max((factor[0] - want).abs());
                worst_surface = worst_surface.max(factor[1].abs());
            }
        }
        for &depth in &interfaces {
            let above = wave.at(k * depth, Side::Coating, &layered);
            let below = wave.at(k * depth, Side::Substrate, &layered);
            let (sa, sb) = (above.stress([0.6, 0.8]), below.stress([0.6, 0.8]));
            let scale = sa
                .iter()
                .flatten()
                .flatten()
                .fold(1e-300_f64, |m, v| m.max(v.abs()));
            for component in [2, 3, 4] {
                for load in 0..3 {
                    for part in 0..2 {
                        worst_continuity = worst_continuity.max(
                            (sa[component][load][part] - sb[component][load][part]).abs() / scale,
                        );
                    }
                }
            }
            let jump = (sa[0][0][0] - sb[0][0][0]).abs() / scale;
            if scale > 1e-8 {
                smallest_jump = smallest_jump.min(jump);
            }
            let (da, db) = (above.plane_displacements(), below.plane_displacements());
            let dscale = da.iter().flatten().fold(1e-300_f64, |m, v| m.max(v.abs()));
            for (x, y) in da.iter().flatten().zip(db.iter().flatten()) {
                worst_continuity = worst_continuity.max((x - y).abs() / dscale);
            }
            let (ua, ub) = (above.antiplane, below.antiplane);
            worst_continuity =
                worst_continuity.max((ua[0] - ub[0]).abs() / ua[0].abs().max(1e-300));
            // The anti-plane traction σtz = (G/G1) U'.
            worst_continuity = worst_continuity.max(
                (above.shear_ratio * ua[1] - below.shear_ratio * ub[1]).abs()
                    / (above.shear_ratio * ua[1]).abs().max(1e-300),
            );
        }
    }
    eprintln!(
        "stack TiN/Cr/DLC/Al: continuity {worst_continuity:.2e}, surface {worst_surface:.2e}, smallest σxx jump {smallest_jump:.3}"
    );
    assert!(worst_continuity < 1e-12, "{worst_continuity}");
    assert!(worst_surface < 1e-12, "{worst_surface}");
    assert!(smallest_jump > 1e-3, "{smallest_jump}");
}

#[test]
fn a_thick_stack_neither_overflows_nor_forgets_its_top() {
    let layered = stack((TIN, 1e-6), &[(CHROMIUM, 1e-6)], STEEL);
    let e_top = TIN.modulus_pa / (1.0 - TIN.poisson * TIN.poisson);
    let e_sub = STEEL.modulus_pa / (1.0 - STEEL.poisson * STEEL.poisson);
    for k_h in [1e2, 1e4, 1e7] {
        let c = layered.normal_compliance_times_k(k_h);
        assert!((c * e_top / 2.0 - 1.0).abs() < 1e-12, "{k_h}: {c}");
        let at = layered.wave(k_h).at(1.5 * k_h, Side::Coating, &layered);
        assert!(at.pressure.iter().all(|v| v.is_finite()));
    }
    let c = layered.normal_compliance_times_k(1e-7);
    assert!((c * e_sub / 2.0 - 1.0).abs() < 1e-5, "{c}");
}

#[test]
fn depths_name_their_layer_and_side() {
    let layered = stack((DLC, 2e-6), &[(CHROMIUM, 0.3e-6)], STEEL);
    assert_eq!(layered.layer_at(1e-6, Side::Substrate), Some(0));
    assert_eq!(layered.layer_at(2e-6, Side::Coating), Some(0));
    assert_eq!(layered.layer_at(2e-6, Side::Substrate), Some(1));
    assert_eq!(layered.layer_at(2.3e-6, Side::Coating), Some(1));
    assert_eq!(layered.layer_at(2.3e-6, Side::Substrate), None);
    assert_eq!(layered.material_at(2.2e-6, Side::Coating), CHROMIUM);
    assert_eq!(layered.material_at(9e-6, Side::Coating), STEEL);
    assert!(Interlayers::of(
        &[Layer {
            material: DLC,
            thickness_m: 1e-6
        }; 6]
    )
    .is_none());
}

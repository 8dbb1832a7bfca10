//! Checks of the elastic-plastic contact against closed forms and limits (docs/plasticity.md
//! states each tolerance with the measured error).

use super::*;
use crate::contact::material::Material;
use crate::contact::rough::{self, Control, RoughContactProblem};

const MODULUS: f64 = 210e9;
const POISSON: f64 = 0.3;
const YIELD: f64 = 1e9;
const RADIUS: f64 = 10e-3;

fn spec(steps: usize, unload_steps: usize, cells: usize, depth_cells: usize) -> PlasticitySpec {
    PlasticitySpec {
        yield_strength_pa: YIELD,
        hardening_modulus_pa: 0.0,
        unload: unload_steps > 0,
        steps,
        unload_steps: unload_steps.max(1),
        grid_cells: cells,
        depth_cells,
        extent_over_a: 1.5,
        depth_over_a: 1.5,
        tolerance: 1e-7,
        body1: Material {
            modulus_pa: MODULUS,
            poisson: POISSON,
        },
        counter_rigid: true,
    }
}

/// A rigid ball on the steel flat at Hertz's peak pressure `p0_over_y` Y.
fn hertz(p0_over_y: f64) -> PointContact {
    let e_star = MODULUS / (1.0 - POISSON * POISSON);
    let p0 = p0_over_y * YIELD;
    let load = (p0 * std::f64::consts::PI).powi(3) * RADIUS * RADIUS / (6.0 * e_star * e_star);
    PointContact::from_effective(load, e_star, RADIUS)
}

/// The largest von Mises stress over p0 on the axis of Hertz's sphere, by the closed form
/// (Hamilton 1983) sampled every 1e-4 a.
fn closed_form_axis_maximum(nu: f64) -> f64 {
    (1..20_000)
        .map(|k| crate::solution::sphere_hertz::stress_over_p0(0.0, 0.0, k as f64 * 1e-4, 0.0, nu).von_mises())
        .fold(0.0, f64::max)
}

#[test]
fn below_first_yield_the_contact_is_elastic_and_unloading_leaves_nothing() {
    let spec = spec(1, 1, 32, 12);
    let hertz = hertz(1.2);
    let study = study_point(&spec, &hertz, 0.0, &mut |_| {}).expect("solves");
    assert_eq!(study.loaded.max_plastic_strain, 0.0);
    assert_eq!(study.loaded.plastic_volume_m3, 0.0);
    // The same contact solved by the rough solver alone, on the same grid.
    let grid = &study.grid;
    let heights = Array2::from_shape_fn((32, 32), |(j, i)| {
        -(study.x_m[i].powi(2) + study.y_m[j].powi(2)) / (2.0 * RADIUS)
    });
    let elastic = rough::solve(
        &RoughContactProblem {
            heights_m: heights.view(),
            spacing_m: grid.spacing_m,
            e_star_pa: hertz.effective_modulus_pa,
            periodicity: Periodicity::NonPeriodic,
            control: Control::Load {
                newtons: hertz.load_n,
            },
            hardness_pa: None,
            tolerance: CONTACT_TOLERANCE,
            max_iterations: rough::DEFAULT_MAX_ITERATIONS,
            memory_limit_bytes: MEMORY_LIMIT_BYTES,
        },
        &mut |_, _| {},
    )
    .expect("elastic");
    let elastic_max = elastic.pressure_pa.iter().fold(0.0f64, |m, &p| m.max(p));
    let relative = (study.loaded.max_pressure_pa / elastic_max - 1.0).abs();
    assert!(relative < 1e-9, "peak pressure against the contact solver: {relative:e}");
    assert!((study.loaded.approach_m / elastic.approach_m - 1.0).abs() < 1e-9);
    // And Hertz's, to the grid's discretisation (16 cells across the diameter's half).
    let hertz_error = (study.loaded.max_pressure_pa / hertz.p0_pa - 1.0).abs();
    assert!(hertz_error < 0.02, "against Hertz: {hertz_error:e}");
    let approach_error = (study.loaded.approach_m / hertz.approach_m - 1.0).abs();
    assert!(approach_error < 0.02, "approach against Hertz: {approach_error:e}");
    // Unloaded: no dent, no residual stress.
    let unloaded = study.unloaded.as_ref().expect("unloaded");
    assert_eq!(unloaded.residual_depth_m, 0.0);
    assert_eq!(unloaded.residual_von_mises_max_pa, 0.0);
}

#[test]
fn first_yield_is_at_the_closed_form_load() {
    // Johnson (1985) §6.2: von Mises first yield at p0 = Y / 0.620 for ν = 0.3 (checked here
    // against the closed form to its three digits).
    let ratio = closed_form_axis_maximum(POISSON);
    assert!((ratio / 0.620 - 1.0).abs() < 0.5e-2 / 3.0, "closed form: {ratio}");
    // The grid: cells of a/20 across, layers of a/20 from the surface (the maximum's depth,
    // 0.48 a, is a cell's centre within a/40).
    let mut below = spec(1, 0, 48, 18);
    below.extent_over_a = 1.2;
    below.depth_over_a = 0.9;
    let first_yield = 1.0 / ratio;
    for (factor, plastic) in [(0.995, false), (1.005, true)] {
        let study = study_point(&below, &hertz(factor * first_yield), 0.0, &mut |_| {})
            .expect("solves");
        let strain = largest(&study.loaded_snapshot().equivalent_plastic_strain).0;
        assert_eq!(strain > 0.0, plastic, "at {factor} of the first yield: {strain:e}");
    }
}

#[test]
fn the_residual_field_is_self_equilibrated_and_free_at_the_surface() {
    let spec = spec(4, 2, 32, 16);
    let study = study_point(&spec, &hertz(2.5), 0.0, &mut |_| {}).expect("solves");
    assert!(study.converged);
    let state = study.unloaded_snapshot().expect("unloaded");
    let stress = &state.stress_pa;
    let (nz, _, ny, nx) = stress.dim();
    let scale = study.unloaded.as_ref().expect("unloaded").residual_von_mises_max_pa;
    assert!(scale > 0.1 * YIELD, "a residual stress: {scale:e}");
    // Force balance of the body above each plane z = const: the plane's net normal and shear
    // forces vanish (no load on the surface), relative to the plane's largest stress.
    let mut worst: f64 = 0.0;
    for l in 0..nz {
        for c in [2, 3, 4] {
            let (mut sum, mut largest_value) = (0.0, 0.0f64);
            for j in 0..ny {
                for i in 0..nx {
                    let value = stress[[l, c, j, i]];
                    sum += value;
                    largest_value = largest_value.max(value.abs());
                }
            }
            worst = worst.max(sum.abs() / (largest_value * (nx * ny) as f64));
        }
    }
    assert!(worst < 1e-3, "net force over a plane: {worst:e} of its largest stress x area");
    // Traction-free: the top layer's σzz, σxz, σyz (at a/21 depth) are small beside the
    // residual stress.
    let top = (0..ny)
        .flat_map(|j| (0..nx).map(move |i| (j, i)))
        .map(|(j, i)| {
            [2, 3, 4]
                .iter()
                .map(|&c| stress[[0, c, j, i]].abs())
                .fold(0.0, f64::max)
        })
        .fold(0.0, f64::max);
    assert!(top < 0.1 * scale, "traction at the top layer: {:.3} of the residual", top / scale);
    // A dent, and plastic strain left where it flowed.
    assert!(study.unloaded.as_ref().expect("unloaded").residual_depth_m > 0.0);
}

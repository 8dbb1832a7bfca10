//! Checks of volume plasticity under a rough map: a smooth ball given as a map is the ball,
//! a large period is isolated, and below yield the rough contact solver alone
//! (docs/plasticity.md states each tolerance with the measured error).

use super::*;
use crate::contact::material::Material;
use crate::study::plastic::{study_point, MEMORY_LIMIT_BYTES};
use ndarray::Array2;

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

fn e_star() -> f64 {
    MODULUS / (1.0 - POISSON * POISSON)
}

/// A rigid ball on the steel flat at Hertz's peak pressure `p0_over_y` Y.
fn hertz(p0_over_y: f64) -> PointContact {
    let p0 = p0_over_y * YIELD;
    let load = (p0 * std::f64::consts::PI).powi(3) * RADIUS * RADIUS / (6.0 * e_star() * e_star());
    PointContact::from_effective(load, e_star(), RADIUS)
}

/// The ball's heights on `cells²` cells of `dx`, the axis on cell `[cells/2, cells/2]`.
fn ball_map(cells: usize, dx: f64) -> Array2<f64> {
    let c = (cells / 2) as f64;
    Array2::from_shape_fn((cells, cells), |(j, i)| {
        let (x, y) = ((i as f64 - c) * dx, (j as f64 - c) * dx);
        -(x * x + y * y) / (2.0 * RADIUS)
    })
}

fn problem(
    heights: &Array2<f64>,
    dx: f64,
    load: f64,
    periodicity: Periodicity,
) -> RoughContactProblem<'_> {
    RoughContactProblem {
        heights_m: heights.view(),
        spacing_m: [dx, dx],
        e_star_pa: e_star(),
        periodicity,
        control: Control::Load { newtons: load },
        hardness_pa: None,
        tolerance: crate::study::plastic::CONTACT_TOLERANCE,
        max_iterations: rough::DEFAULT_MAX_ITERATIONS,
        memory_limit_bytes: MEMORY_LIMIT_BYTES,
    }
}

#[test]
fn a_smooth_ball_given_as_a_map_is_the_ball() {
    let ball = hertz(2.5);
    let point_spec = spec(2, 1, 24, 10);
    let point = study_point(&point_spec, &ball, 0.0, &mut |_| {}).expect("solves");
    let dx = point.grid.spacing_m[0];
    let heights = ball_map(24, dx);
    let map = problem(&heights, dx, ball.load_n, Periodicity::NonPeriodic);
    // The same depth: the map's is measured in radii of its largest spot.
    let elastic = rough::solve(&map, &mut |_, _| {}).expect("elastic");
    let spot = (elastic.largest_spot_cells as f64 * dx * dx / std::f64::consts::PI).sqrt();
    let mut map_spec = point_spec;
    map_spec.depth_over_a = point_spec.depth_over_a * ball.radius_m / spot;
    let rough = study_map(&map, &map_spec, 0.0, &mut |_| {}).expect("solves");
    let (r, p) = (&rough.loaded, &point.loaded);
    assert!(
        p.max_plastic_strain > 1e-4,
        "plastic: {}",
        p.max_plastic_strain
    );
    for (what, x, y) in [
        ("peak pressure", r.max_pressure_pa, p.max_pressure_pa),
        ("area", r.contact_area_m2, p.contact_area_m2),
        ("approach", r.approach_m, p.approach_m),
        (
            "max plastic strain",
            r.max_plastic_strain,
            p.max_plastic_strain,
        ),
        ("plastic volume", r.plastic_volume_m3, p.plastic_volume_m3),
        ("von Mises max", r.von_mises_max_pa, p.von_mises_max_pa),
        (
            "dent",
            rough.unloaded.as_ref().expect("unloaded").residual_depth_m,
            point.unloaded.as_ref().expect("unloaded").residual_depth_m,
        ),
    ] {
        assert!((x / y - 1.0).abs() < 1e-6, "{what}: {x} vs {y}");
    }
    let PlasticKind::Rough(found) = rough.kind else {
        panic!("a rough study")
    };
    assert!(
        found.surface_plastic_area_m2 == 0.0,
        "the zone is below the surface at 2.5 Y"
    );
    assert!(found.plastic_footprint_m2 > 0.0);
}

/// The relative differences (peak pressure, area, largest plastic strain, plastic volume)
/// between a periodic and an isolated map of a ball at 2.5 Y, `half_periods` contact radii
/// each side of the axis, cells of a/6.
fn periodic_against_isolated(half_periods: usize) -> [f64; 4] {
    let ball = hertz(2.5);
    let cells = 12 * half_periods;
    let dx = ball.radius_m / 6.0;
    let heights = ball_map(cells, dx);
    let spec = spec(2, 0, cells, 10);
    let mut results = Vec::new();
    for periodicity in [Periodicity::NonPeriodic, Periodicity::Periodic] {
        let map = problem(&heights, dx, ball.load_n, periodicity);
        let study = study_map(&map, &spec, 0.0, &mut |_| {}).expect("solves");
        let expected = match periodicity {
            Periodicity::Periodic => [cells, cells],
            Periodicity::NonPeriodic => [2 * cells, 2 * cells],
        };
        assert_eq!(study.grid.plan_shape(), expected);
        results.push(study.loaded);
    }
    let (isolated, periodic) = (&results[0], &results[1]);
    [
        periodic.max_pressure_pa / isolated.max_pressure_pa - 1.0,
        periodic.contact_area_m2 / isolated.contact_area_m2 - 1.0,
        periodic.max_plastic_strain / isolated.max_plastic_strain - 1.0,
        periodic.plastic_volume_m3 / isolated.plastic_volume_m3 - 1.0,
    ]
}

#[test]
fn a_large_period_isolates_the_contact() {
    // A periodic map is a lattice of contacts: its mean pressure W/L² is a uniform σzz at every
    // depth and the images' stress adds to it, so the difference falls as (a/L)² (measured:
    // the peak pressure -4.5 % at a period of 6 a, -1.4 % at 12 a; the largest plastic strain
    // +14 %, +3.5 %; the plastic volume +12 %, +3.3 %).
    let near = periodic_against_isolated(3);
    let far = periodic_against_isolated(6);
    assert!(far[0].abs() < 0.02, "peak pressure at 12 a: {:e}", far[0]);
    assert!(
        far[2].abs() < 0.05,
        "largest plastic strain at 12 a: {:e}",
        far[2]
    );
    assert!(far[3].abs() < 0.05, "plastic volume at 12 a: {:e}", far[3]);
    for k in [0, 2, 3] {
        assert!(
            far[k].abs() < near[k].abs() / 2.5,
            "quantity {k}: the difference falls as the period grows: {} then {}",
            near[k],
            far[k]
        );
    }
}

#[test]
fn below_yield_the_map_is_the_rough_contact_solver_s() {
    // Bumps of 0.2 µm every 16 µm on a ball of 2 mm, 32² cells of 2 µm: a few spots, none
    // at the map's edge.
    let cells = 32;
    let dx = 2e-6;
    let k = 2.0 * std::f64::consts::PI / (8.0 * dx);
    let heights = Array2::from_shape_fn((cells, cells), |(j, i)| {
        let (x, y) = ((i as f64 - 16.0) * dx, (j as f64 - 16.0) * dx);
        0.2e-6 * (k * x).cos() * (k * y).cos() - (x * x + y * y) / (2.0 * 2e-3)
    });
    let mut spec = spec(1, 1, cells, 8);
    // A strength no cell reaches.
    spec.yield_strength_pa = 1e12;
    for periodicity in [Periodicity::NonPeriodic, Periodicity::Periodic] {
        let map = problem(&heights, dx, 0.05, periodicity);
        let elastic = rough::solve(&map, &mut |_, _| {}).expect("elastic");
        let study = study_map(&map, &spec, 0.0, &mut |_| {}).expect("solves");
        assert_eq!(study.loaded.max_plastic_strain, 0.0);
        let pressure = &study.loaded_snapshot().pressure_pa;
        let difference = (pressure - &elastic.pressure_pa).mapv(f64::abs).sum();
        assert!(
            difference <= 1e-9 * elastic.pressure_pa.sum(),
            "{periodicity:?}: Σ|Δp| / Σp = {:e}",
            difference / elastic.pressure_pa.sum()
        );
        assert!(
            (study.loaded.approach_m / elastic.approach_m - 1.0).abs() < 1e-9,
            "{periodicity:?}: approach {} vs {}",
            study.loaded.approach_m,
            elastic.approach_m
        );
        assert!(
            elastic.spots > 1,
            "{periodicity:?}: {} spots",
            elastic.spots
        );
        assert_eq!(study.unloaded.expect("unloaded").residual_depth_m, 0.0);
    }
}

#[test]
fn the_graded_layers_reach_the_depth_from_cells_as_thin_as_the_map_s() {
    let cell = 0.5e-6;
    // Deep: graded, the top layer a map cell thick (16 layers), the bottom face at the depth.
    let graded = depth_layers(16, cell, 20e-6).expect("layers");
    assert_eq!(graded.count(), 16);
    assert!((graded.thickness_m(0) / cell - 1.0).abs() < 1e-12);
    assert!(
        (graded.depth_m() / 20e-6 - 1.0).abs() < 1e-9,
        "{}",
        graded.depth_m()
    );
    let growth = graded.thickness_m(1) / graded.thickness_m(0);
    assert!(growth > 1.0);
    assert!((graded.thickness_m(15) / graded.thickness_m(14) / growth - 1.0).abs() < 1e-9);
    // Doubling the layers halves the top one.
    let finer = depth_layers(32, cell, 20e-6).expect("layers");
    assert!((finer.thickness_m(0) / (cell / 2.0) - 1.0).abs() < 1e-12);
    // Shallow: uniform.
    let uniform = depth_layers(16, cell, 4e-6).expect("layers");
    assert!((uniform.thickness_m(0) - 0.25e-6).abs() < 1e-18);
    assert!((uniform.thickness_m(15) - 0.25e-6).abs() < 1e-18);
}

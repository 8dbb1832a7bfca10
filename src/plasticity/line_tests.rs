//! The plane-strain elastic-plastic contact: the operator's plane-strain identities, Hertz's
//! line contact below first yield, first yield at Johnson's load, the residual field.

use ndarray::Array4;

use super::*;
use crate::contact::LineContact;
use crate::solution::line_hertz;

const MODULUS: f64 = 210e9;
const POISSON: f64 = 0.3;
const YIELD: f64 = 1e9;
const RADIUS: f64 = 10e-3;

/// A rigid roller on a steel flat at the peak Hertz pressure `p0_over_y` Y, loaded in `steps`
/// and (when `unload`) unloaded in one step.
fn roller(
    p0_over_y: f64,
    cells: usize,
    extent: f64,
    depth_cells: usize,
    depth: f64,
    steps: usize,
    unload: bool,
) -> (LineContact, LinePlasticProblem) {
    let e_star = MODULUS / (1.0 - POISSON * POISSON);
    let p0 = p0_over_y * YIELD;
    // p0 = sqrt(P E* / (π R)).
    let load = p0 * p0 * PI * RADIUS / e_star;
    let hertz = LineContact::from_effective(load, e_star, RADIUS);
    let b = hertz.half_width_m;
    let grid = LineGrid {
        cells,
        spacing_m: 2.0 * extent * b / cells as f64,
        depth: DepthCells::uniform(depth_cells, depth * b / depth_cells as f64).expect("depth"),
    };
    let gap_m = grid.x_m().iter().map(|x| x * x / (2.0 * RADIUS)).collect();
    let mut loads: Vec<f64> = (1..=steps)
        .map(|i| load * i as f64 / steps as f64)
        .collect();
    let mut snapshots = vec![steps - 1];
    if unload {
        loads.push(0.0);
        snapshots.push(steps);
    }
    let problem = LinePlasticProblem {
        gap_m,
        grid,
        modulus_pa: MODULUS,
        poisson: POISSON,
        counter: None,
        e_star_pa: e_star,
        hardening: Hardening {
            yield_strength_pa: YIELD,
            plastic_modulus_pa: 0.0,
        },
        friction: 0.0,
        loads_n_per_m: loads,
        snapshots,
        tolerance: 1e-7,
        max_iterations: 500,
        acceleration: 5,
    };
    (hertz, problem)
}

#[test]
fn the_operator_keeps_plane_strain_and_the_planes_free() {
    // A deviatoric plastic strain in a patch of cells, with the in-plane components of J2 flow.
    let grid = LineGrid {
        cells: 64,
        spacing_m: 1e-5,
        depth: DepthCells::uniform(12, 1e-5).expect("depth"),
    };
    let operator = PlaneStrainSpace::new(grid.clone(), MODULUS, POISSON);
    let mut strain = Array4::<f64>::zeros((12, 6, 1, 64));
    for l in 2..6 {
        for i in 28..35 {
            let (a, b) = (1e-3 * (1.0 + 0.1 * l as f64), 4e-4 * (i as f64 - 31.0));
            strain[[l, XX, 0, i]] = a;
            strain[[l, ZZ, 0, i]] = -0.6 * a - b;
            strain[[l, YY, 0, i]] = -0.4 * a + b;
            strain[[l, XZ, 0, i]] = 0.3 * b;
        }
    }
    let mut stress = Array4::<f64>::zeros((12, 6, 1, 64));
    let mut surface = vec![0.0; 64];
    operator
        .residual(&strain, &mut stress, &mut surface)
        .expect("operator");
    let largest = stress.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    // ε_yy = 0: σyy = ν(σxx + σzz) - E ε*_yy in every cell; no anti-plane stress.
    let mut worst: f64 = 0.0;
    for l in 0..12 {
        for i in 0..64 {
            let s = |c: usize| stress[[l, c, 0, i]];
            let expected = POISSON * (s(XX) + s(ZZ)) - MODULUS * strain[[l, YY, 0, i]];
            worst = worst.max((s(YY) - expected).abs());
            worst = worst.max(s(3).abs()).max(s(5).abs());
        }
    }
    assert!(
        worst < 1e-10 * largest,
        "plane strain: {worst:e} of {largest:e}"
    );
    // Each plane z = const carries no net σzz, σxz: exactly on the padded period (the mean
    // wave), here over the grid, which holds most of the field (relative to the layer that
    // carries the most).
    let dx = grid.spacing_m;
    let sums: Vec<[f64; 3]> = (0..12)
        .map(|l| {
            let sum = |f: &dyn Fn(usize) -> f64| (0..64).map(|i| f(i) * dx).sum::<f64>();
            [
                sum(&|i| stress[[l, ZZ, 0, i]]),
                sum(&|i| stress[[l, XZ, 0, i]]),
                sum(&|i| stress[[l, ZZ, 0, i]].abs() + stress[[l, XZ, 0, i]].abs()),
            ]
        })
        .collect();
    let scale = sums.iter().fold(0.0f64, |m, s| m.max(s[2]));
    let worst = sums
        .iter()
        .fold(0.0f64, |m, s| m.max(s[0].abs()).max(s[1].abs()));
    eprintln!(
        "plane strain {:.2e}; planes' net force {:.2e}",
        worst_plane(&stress, &strain),
        worst / scale
    );
    assert!(worst < 0.02 * scale, "planes: {worst:e} of {scale:e}");
}

/// The largest departure from `σyy = ν(σxx + σzz) - E ε*_yy` over the cells, relative.
fn worst_plane(stress: &Array4<f64>, strain: &Array4<f64>) -> f64 {
    let largest = stress.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let (nz, _, _, nx) = stress.dim();
    let mut worst: f64 = 0.0;
    for l in 0..nz {
        for i in 0..nx {
            let s = |c: usize| stress[[l, c, 0, i]];
            let expected = POISSON * (s(XX) + s(ZZ)) - MODULUS * strain[[l, YY, 0, i]];
            worst = worst.max((s(YY) - expected).abs());
        }
    }
    worst / largest
}

#[test]
fn below_first_yield_the_roller_is_hertz_and_unloading_leaves_nothing() {
    let (hertz, problem) = roller(1.2, 128, 2.0, 32, 4.0, 2, true);
    let solution = solve(&problem, &mut |_| {}, None).expect("solve");
    let loaded = &solution.steps[1];
    assert!(loaded.converged && loaded.max_plastic_strain == 0.0);
    let p_error = loaded.max_pressure_pa / hertz.p0_pa - 1.0;
    eprintln!("elastic roller: p0 {p_error:.2e}");
    assert!(p_error.abs() < 2e-3, "p0: {p_error:e}");
    let b = hertz.half_width_m;
    let width = loaded.contact_cells as f64 * problem.grid.spacing_m / 2.0;
    // Whole cells: the half-width within a cell.
    assert!(
        (width - b).abs() <= problem.grid.spacing_m,
        "b {width:e} vs {b:e}"
    );
    // The approach to the grid's depth D against the closed form (module doc).
    let d = problem.grid.depth.depth_m();
    let expected = hertz.p0_pa / MODULUS
        * ((1.0 - POISSON * POISSON) * b * (d / b).asinh()
            - POISSON * (1.0 + POISSON) * (d * (b * b + d * d).sqrt() - d * d) / b);
    let approach = loaded.approach_m.expect("loaded");
    eprintln!("elastic roller: approach {:.2e}", approach / expected - 1.0);
    assert!(
        (approach / expected - 1.0).abs() < 3e-3,
        "approach {approach:e} vs {expected:e}"
    );
    // The loaded stress is McEwen's field of Hertz's pressure on the axis.
    let state = &solution.snapshots[0];
    let axis = problem.grid.cells / 2;
    for l in [4, 11, 20] {
        let z = problem.grid.depth.centre_m(l);
        let exact = line_hertz::stress_over_p0(0.0, z / b, 0.0, POISSON);
        let zz = state.stress_pa[[l, ZZ, 0, axis]] / hertz.p0_pa;
        assert!(
            (zz - exact.zz).abs() < 3e-3,
            "σzz at {l}: {zz} vs {}",
            exact.zz
        );
    }
    let unloaded = &solution.snapshots[1];
    assert!(unloaded.stress_pa.iter().all(|&v| v == 0.0));
    assert!(unloaded.plastic_displacement_m.iter().all(|&v| v == 0.0));
}

#[test]
fn first_yield_of_the_line_contact_is_johnsons() {
    // The largest von Mises stress on the axis of McEwen's field (plane strain, ν = 0.3):
    // Johnson (1985) §6.2 gives 0.5575 p0 at 0.70 b (Tresca: 0.300 p0 at 0.78 b).
    let (mut peak, mut at) = (0.0f64, 0.0);
    for k in 1..=4000 {
        let z = k as f64 * 5e-4;
        let s = line_hertz::stress_over_p0(0.0, z, 0.0, POISSON);
        let v = s.von_mises();
        if v > peak {
            (peak, at) = (v, z);
        }
    }
    assert!((peak / 0.5575 - 1.0).abs() < 2e-4, "{peak} at {at}");
    assert!((at - 0.70).abs() < 0.01, "{peak} at {at}");
    let first_yield = 1.0 / peak;
    for (factor, yields) in [(0.995, false), (1.005, true)] {
        let (_, problem) = roller(first_yield * factor, 192, 1.5, 40, 1.25, 1, false);
        let solution = solve(&problem, &mut |_| {}, None).expect("solve");
        let step = &solution.steps[0];
        assert!(step.converged);
        assert_eq!(
            step.max_plastic_strain > 0.0,
            yields,
            "at {factor} of first yield: {:e}",
            step.max_plastic_strain
        );
    }
}

#[test]
fn the_residual_field_is_free_and_balanced() {
    let (hertz, mut problem) = roller(2.0, 192, 6.0, 24, 2.0, 4, true);
    // A thin top cell (1/100 of the others) to read the surface's tractions.
    let dz = problem.grid.depth.thickness_m(0);
    let mut faces = vec![0.0, dz / 100.0];
    faces.extend((1..=24).map(|j| j as f64 * dz));
    problem.grid.depth = DepthCells::new(faces).expect("faces");
    let solution = solve(&problem, &mut |_| {}, None).expect("solve");
    assert!(solution.steps.iter().all(|s| s.converged));
    let residual = &solution.snapshots[1].stress_pa;
    let kappa = &solution.snapshots[1].equivalent_plastic_strain;
    assert!(kappa.iter().any(|&k| k > 1e-4));
    let largest = residual.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    // The thin top cell's centre (b/1200 deep): σzz and σxz against the field's largest.
    let nx = problem.grid.cells;
    let top = (0..nx).fold(0.0f64, |m, i| {
        m.max(residual[[0, ZZ, 0, i]].abs())
            .max(residual[[0, XZ, 0, i]].abs())
    });
    eprintln!(
        "residual: surface tractions {:.2e} of the largest",
        top / largest
    );
    assert!(top < 0.01 * largest, "surface: {top:e} of {largest:e}");
    // Each plane z = const carries no net σzz and σxz (over the grid: relative to the layer
    // that carries the most; the deep layers' field spreads past the grid's sides).
    let dx = problem.grid.spacing_m;
    let layers = problem.grid.depth.count();
    let sums: Vec<[f64; 3]> = (0..layers)
        .map(|l| {
            let sum = |f: &dyn Fn(usize) -> f64| (0..nx).map(|i| f(i) * dx).sum::<f64>();
            [
                sum(&|i| residual[[l, ZZ, 0, i]]),
                sum(&|i| residual[[l, XZ, 0, i]]),
                sum(&|i| residual[[l, ZZ, 0, i]].abs() + residual[[l, XZ, 0, i]].abs()),
            ]
        })
        .collect();
    let scale = sums.iter().fold(0.0f64, |m, s| m.max(s[2]));
    let worst = sums
        .iter()
        .fold(0.0f64, |m, s| m.max(s[0].abs()).max(s[1].abs()));
    eprintln!(
        "residual: planes' net force {:.2e} (p0 {:.3e})",
        worst / scale,
        hertz.p0_pa
    );
    assert!(worst < 0.03 * scale, "planes: {worst:e} of {scale:e}");
}

//! The semi-analytical loop on a rigid sphere pressed into an elastic-plastic half-space.

use ndarray::Array2;

use super::column::DepthCells;
use super::halfspace::VolumeGrid;
use super::j2::Hardening;
use super::loading::{solve, PlasticContactProblem, PlasticContactSolution};
use crate::contact::PointContact;
use crate::operator::elastic::Periodicity;

const MODULUS: f64 = 210e9;
const POISSON: f64 = 0.3;
const YIELD: f64 = 1e9;
const RADIUS: f64 = 10e-3;

/// A rigid ball on a steel flat at the peak Hertz pressure `p0_over_y` Y.
pub(super) struct Sphere {
    pub hertz: PointContact,
    pub heights: Array2<f64>,
    pub grid: VolumeGrid,
    pub axis: [usize; 2],
}

pub(super) fn sphere(
    p0_over_y: f64,
    cells: usize,
    depth_cells: usize,
    extent: f64,
    depth: f64,
) -> Sphere {
    let e_star = MODULUS / (1.0 - POISSON * POISSON);
    let p0 = p0_over_y * YIELD;
    let load =
        p0.powi(3) * std::f64::consts::PI.powi(3) * RADIUS * RADIUS / (6.0 * e_star * e_star);
    let hertz = PointContact::from_effective(load, e_star, RADIUS);
    let a = hertz.radius_m;
    let dx = 2.0 * extent * a / cells as f64;
    let centre = cells / 2;
    let heights = Array2::from_shape_fn((cells, cells), |(j, i)| {
        let (x, y) = (
            (i as f64 - centre as f64) * dx,
            (j as f64 - centre as f64) * dx,
        );
        -(x * x + y * y) / (2.0 * RADIUS)
    });
    let grid = VolumeGrid {
        shape: [cells, cells],
        spacing_m: [dx, dx],
        depth: DepthCells::uniform(depth_cells, depth * a / depth_cells as f64).expect("depth"),
        periodicity: Periodicity::NonPeriodic,
    };
    Sphere {
        hertz,
        heights,
        grid,
        axis: [centre, centre],
    }
}

pub(super) fn run(
    sphere: &Sphere,
    loads: Vec<f64>,
    hardening_pa: f64,
    tolerance: f64,
) -> PlasticContactSolution {
    let last = loads.len() - 1;
    let loaded = loads
        .iter()
        .enumerate()
        .fold(
            (0, 0.0),
            |best, (i, &w)| if w > best.1 { (i, w) } else { best },
        )
        .0;
    let problem = PlasticContactProblem {
        heights_m: sphere.heights.view(),
        grid: sphere.grid.clone(),
        modulus_pa: MODULUS,
        poisson: POISSON,
        e_star_pa: sphere.hertz.effective_modulus_pa,
        hardening: Hardening {
            yield_strength_pa: YIELD,
            plastic_modulus_pa: hardening_pa,
        },
        friction: 0.0,
        loads_n: loads,
        snapshots: vec![loaded, last],
        axis_cell: sphere.axis,
        tolerance,
        max_iterations: 500,
        acceleration: 5,
        contact_tolerance: 1e-10,
        memory_limit_bytes: 1 << 32,
    };
    solve(&problem, &mut |_| {}).expect("solve")
}

fn ramp(load: f64, up: usize, down: usize) -> Vec<f64> {
    let mut loads: Vec<f64> = (1..=up).map(|i| load * i as f64 / up as f64).collect();
    loads.extend((1..=down).map(|i| load * (1.0 - i as f64 / down as f64)));
    loads
}

#[test]
#[ignore]
fn probe_sphere() {
    let cases: Vec<(f64, usize)> = match std::env::var("PROBE").as_deref() {
        Ok("quick") => vec![(2.5, 3)],
        _ => vec![(2.5, 8), (4.0, 8)],
    };
    for (p0, steps) in cases {
        let s = sphere(p0, 64, 32, 2.0, 2.0);
        let started = std::time::Instant::now();
        let solution = run(&s, ramp(s.hertz.load_n, steps, 4), 0.0, 1e-6);
        eprintln!(
            "p0 = {p0} Y, a = {:.4e}, took {:?}",
            s.hertz.radius_m,
            started.elapsed()
        );
        for step in &solution.steps {
            eprintln!(
                "  W {:.4e} it {} res {:.2e} pmax/Y {:.4} cells {} kmax {:.4e} dent {:.4e} delta {:?}",
                step.load_n, step.iterations, step.residual, step.max_pressure_pa / YIELD,
                step.contact_cells, step.max_plastic_strain, step.axis_displacement_m, step.approach_m
            );
        }
    }
}

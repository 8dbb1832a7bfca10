//! A coated point contact at the default grid (issue 40, speed): the steel ball on 10 µm of
//! B4C (`scenes/coated_ball_on_b4c_10um.toml`, 255 x 255 cells) solved with the layered
//! influence coefficients (kernels built in every iteration: once per scene), beside the same
//! gridded paraboloid on a homogeneous body solved with Love's coefficients; then the coated
//! scene's whole study (contact and the stresses of the section y = 0) and a coated line
//! contact (400 strips). Target: the coated solve within twice the homogeneous one.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use stressfield::contact::rough::{self, Control, RoughContactProblem};
use stressfield::operator::elastic::Periodicity;
use stressfield::scene::{Hertz, Scene};

fn scene(path: &str) -> Scene {
    Scene::load(std::path::Path::new(path)).expect("the shipped scene")
}

fn coated_point(c: &mut Criterion) {
    let mut group = c.benchmark_group("coated_point_contact");
    group.sample_size(10);
    let scene = scene("scenes/coated_ball_on_b4c_10um.toml");
    let spec = scene.contact.coating.expect("coated");
    let Some(Hertz::Point(point)) = scene.contact.dimensional.map(|d| d.hertz) else {
        panic!("a point contact");
    };
    let cells = scene.numerical.cells;
    let extent = scene.numerical.extent_over_a;
    let d = 2.0 * extent * point.radius_m / cells as f64;
    let origin = -extent * point.radius_m + 0.5 * d;
    let curvature = 0.5 / point.effective_radius_m;
    let heights = stressfield::study::coupled::paraboloid(
        [cells, cells],
        [d, d],
        [origin, origin],
        [curvature, curvature],
    );
    let problem = RoughContactProblem {
        heights_m: heights.view(),
        spacing_m: [d, d],
        e_star_pa: point.effective_modulus_pa,
        periodicity: Periodicity::NonPeriodic,
        control: Control::Load {
            newtons: point.load_n,
        },
        hardness_pa: None,
        tolerance: rough::DEFAULT_TOLERANCE,
        max_iterations: rough::DEFAULT_MAX_ITERATIONS,
        memory_limit_bytes: 1 << 31,
    };
    let label = format!("{cells}x{cells}");
    group.bench_with_input(
        BenchmarkId::new("homogeneous_solve", &label),
        &problem,
        |b, problem| b.iter(|| rough::solve(problem, &mut |_, _| {}).expect("solve")),
    );
    let layered = spec.layered();
    group.bench_with_input(
        BenchmarkId::new("coated_solve", &label),
        &problem,
        |b, problem| {
            b.iter(|| {
                stressfield::contact::coated::solve(
                    problem,
                    &layered,
                    spec.counter_per_pa,
                    &mut |_, _| {},
                )
                .expect("solve")
            })
        },
    );
    group.bench_with_input(
        BenchmarkId::new("coated_study", &label),
        &scene,
        |b, scene| b.iter(|| stressfield::study::coated::solve(scene).expect("study")),
    );
    let line = self::scene("scenes/coated_roller_babbitt_on_steel.toml");
    group.bench_with_input(
        BenchmarkId::new("coated_line_study", line.numerical.cells),
        &line,
        |b, scene| b.iter(|| stressfield::study::coated::solve(scene).expect("study")),
    );
    group.finish();
}

criterion_group!(benches, coated_point);
criterion_main!(benches);

//! The numerical EHL of a line contact (issue 52): one solution on the default grid (target:
//! under a second), the stresses under it, and a sweep of ten entrainment speeds (target:
//! under ten seconds): the solves alone, one after the other, and the shipped recording's
//! sweep as it is computed (in parallel, with the sections).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use stressfield::lubrication::line_ehl::{self, LineEhlOptions, LineEhlProblem};
use stressfield::study;

/// The shipped roller bearing's contact (M = 15.6, L = 18.1), and one at `M = 100, L = 10`.
fn problems() -> Vec<(&'static str, LineEhlProblem)> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/lubricated_roller_bearing.toml"
    );
    let scene = stressfield::scene::Scene::load(std::path::Path::new(path)).expect("shipped");
    let roller = study::ehl::problem(&scene).expect("a line contact");
    let heavy = {
        let u: f64 = (10.0f64 / 4600.0).powi(4) / 2.0;
        let (e, r, eta) = (2.3e11, 0.01, 0.04);
        LineEhlProblem {
            load_n_per_m: 100.0 * (2.0 * u).sqrt() * e * r,
            radius_m: r,
            reduced_modulus_pa: e,
            viscosity_pa_s: eta,
            entrainment_m_per_s: u * e * r / eta,
            ..roller
        }
    };
    vec![("roller_M16_L18", roller), ("M100_L10", heavy)]
}

fn line_ehl(c: &mut Criterion) {
    let mut group = c.benchmark_group("line_ehl");
    group.sample_size(10);
    for (name, problem) in problems() {
        group.bench_with_input(BenchmarkId::new("solve", name), &problem, |b, problem| {
            b.iter(|| line_ehl::solve(problem, &LineEhlOptions::default()))
        });
        group.bench_with_input(
            BenchmarkId::new("solve_and_stress", name),
            &problem,
            |b, problem| {
                b.iter(|| study::ehl::solve_problem(problem, 0.0, 0.3, &LineEhlOptions::default()))
            },
        );
    }
    // Ten entrainment speeds from 0.5 to 20 m/s (geometric) of the roller.
    let (_, roller) = problems().remove(0);
    group.bench_function("speed_sweep_10_steps", |b| {
        b.iter(|| {
            (0..10)
                .map(|k| {
                    let speed = 0.5 * 40f64.powf(f64::from(k) / 9.0);
                    let problem = LineEhlProblem {
                        entrainment_m_per_s: speed,
                        ..roller
                    };
                    line_ehl::solve(&problem, &LineEhlOptions::default()).map(|s| s.minimum_film_m)
                })
                .collect::<Vec<_>>()
        })
    });
    // The shipped recording's sweep as `record` and `sweep` compute it: ten speeds solved in
    // parallel, each with its two sections (0.02 b) and the maxima.
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/record_lubricated_speed_sweep.toml"
    );
    let scene = stressfield::scene::Scene::load(std::path::Path::new(path)).expect("shipped");
    let speeds = scene.sweep.as_ref().expect("a sweep").values.clone();
    group.bench_function("speed_sweep_10_steps_with_sections", |b| {
        b.iter(|| {
            study::ehl::speed_sweep(
                &scene,
                &speeds,
                study::ehl::SWEEP_COLUMNS,
                study::ehl::SWEEP_ROWS,
            )
            .map(|steps| steps.len())
        })
    });
    group.finish();
}

criterion_group!(benches, line_ehl);
criterion_main!(benches);

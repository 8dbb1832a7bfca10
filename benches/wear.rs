//! Contact evolution with sliding (issue 37): a rough steel ball (R = 6.35 mm, Sq 0.02 µm on
//! 2.6 µm cells at 256², 1.3 µm at 512²: the same 666 µm map) worn by Archard's law under 20 N
//! over 20 m (k = 2e-6 mm³/(N m)) in 50 backward-Euler steps, each warm-started from the
//! pressure before, side by side with one cold solve of the unworn contact (the target: the 50
//! steps in under ten cold solves at 256², under a minute at 512²). Also the same evolution
//! under a rough counter-surface sliding over the ball (two solves a step: the wear against its
//! mean plane, the instantaneous contact through its asperities), and what `stressfield wear`
//! adds per step: the subsurface maxima of every step (10 steps at 256²).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use stressfield::contact::rough::{solve, Control, RoughContactProblem, DEFAULT_TOLERANCE};
use stressfield::operator::elastic::Periodicity;
use stressfield::study::rough::subsurface_maxima;
use stressfield::surface::generate::{generate, Amplitude, Form, Generator, Spectrum};
use stressfield::surface::HeightMap;
use stressfield::wear::{Archard, Evolution, Schedule};

/// A steel ball on a B4C-coated disc: E* of steel (210 GPa, 0.3) and B4C (450 GPa, 0.17).
const E_STAR: f64 = 154.05e9;
const MAP_M: f64 = 666e-6;

fn map(n: usize, rms_m: f64, form: Form, seed: u64) -> HeightMap {
    let spacing = MAP_M / n as f64;
    generate(&Generator {
        shape: [n, n],
        spacing_m: [spacing, spacing],
        spectrum: Spectrum::SelfAffine {
            hurst: 0.8,
            rolloff_wavelength_m: 40e-6,
            cutoff_wavelength_m: 10e-6_f64.max(4.0 * spacing),
        },
        amplitude: Amplitude::RmsHeight(rms_m),
        form,
        seed,
    })
    .expect("surface")
}

fn problem(ball: &HeightMap) -> RoughContactProblem<'_> {
    RoughContactProblem {
        heights_m: ball.heights_m().view(),
        spacing_m: ball.spacing_m(),
        e_star_pa: E_STAR,
        periodicity: Periodicity::NonPeriodic,
        control: Control::Load { newtons: 20.0 },
        hardness_pa: Some(6.86e9),
        tolerance: DEFAULT_TOLERANCE,
        max_iterations: 5000,
        memory_limit_bytes: 8 << 30,
    }
}

const LAW: Archard = Archard {
    coefficient_m2_per_n: 2e-15,
};

fn evolve(problem: &RoughContactProblem, counter: Option<&HeightMap>, steps: usize) -> usize {
    let mut evolution = Evolution::new(
        problem,
        LAW,
        Schedule {
            distance_m: 20.0,
            steps,
        },
    )
    .expect("evolution");
    if let Some(counter) = counter {
        evolution = evolution.sliding_against(counter.heights_m().clone());
    }
    let mut iterations = 0;
    while let Some(step) = evolution.step(&mut |_, _| {}).expect("step") {
        iterations += step.solution.iterations;
    }
    iterations
}

fn wear(c: &mut Criterion) {
    let mut group = c.benchmark_group("wear");
    group.sample_size(10);
    for n in [256, 512] {
        let ball = map(n, 0.02e-6, Form::Sphere { radius_m: 6.35e-3 }, 5);
        let counter = map(n, 0.5e-6, Form::None, 11);
        let problem = problem(&ball);
        let cold = solve(&problem, &mut |_, _| {}).expect("solves");
        let iterations = evolve(&problem, None, 50);
        eprintln!(
            "wear {n}²: one cold solve {} iterations; 50 steps {iterations} iterations in all",
            cold.iterations
        );
        group.bench_with_input(BenchmarkId::new("cold_solve", n), &problem, |b, problem| {
            b.iter(|| solve(problem, &mut |_, _| {}))
        });
        group.bench_with_input(
            BenchmarkId::new("evolution_50_steps", n),
            &problem,
            |b, problem| b.iter(|| evolve(problem, None, 50)),
        );
        if n == 256 {
            group.bench_with_input(
                BenchmarkId::new("evolution_50_steps_sliding_counter", n),
                &problem,
                |b, problem| b.iter(|| evolve(problem, Some(&counter), 50)),
            );
            group.bench_with_input(
                BenchmarkId::new("maxima_of_10_steps", n),
                &problem,
                |b, problem| {
                    b.iter(|| {
                        let mut evolution = Evolution::new(
                            problem,
                            LAW,
                            Schedule {
                                distance_m: 20.0,
                                steps: 9,
                            },
                        )
                        .expect("evolution");
                        while let Some(step) = evolution.step(&mut |_, _| {}).expect("step") {
                            subsurface_maxima(&step.solution, 0.2, 0.3).expect("maxima");
                        }
                    })
                },
            );
        }
    }
    group.finish();
}

criterion_group!(benches, wear);
criterion_main!(benches);

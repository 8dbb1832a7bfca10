//! Contact evolution with sliding (issue 37): a rough steel ball (R = 6.35 mm, Sq 0.02 µm on
//! 2.6 µm cells at 256², 1.3 µm at 512²: the same 666 µm map) worn by Archard's law under 20 N
//! over 20 m (k = 2e-6 mm³/(N m)) in 50 backward-Euler steps, each warm-started from the
//! pressure before, side by side with one cold solve of the unworn contact (the target: the 50
//! steps in under ten cold solves at 256², under a minute at 512²). Also the same evolution
//! under a rough counter-surface sliding over the ball (two solves a step: the wear against its
//! mean plane, the instantaneous contact through its asperities), and what `stressfield wear`
//! adds per step: the subsurface maxima of every step (10 steps at 256²). Last, whole studies
//! side by side as the command runs them (issue 54): one `contact` of a smooth ball at 256²
//! (the solve and its subsurface maxima) against the wear study of 50 steps, with the maxima
//! warm-started (the default) and searched in full at every step.

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

/// The smooth ball of `docs/wear.md`'s timings: 256² cells of 2.6 µm, 20 N, 20 m in 50 steps.
const SMOOTH_BALL: &str = "format = 1
[contact]
kind = \"rough\"
load = \"20 N\"
friction = 0.2
hardness = \"700 HV\"
[contact.body1]
material = \"steel\"
[contact.body2]
material = \"boron_carbide\"
[surface.generate]
samples = 256
spacing = \"2.6 um\"
hurst = 0.8
rolloff = \"40 um\"
cutoff = \"10.4 um\"
rms_height = \"0.001 nm\"
sphere_radius = \"6.35 mm\"
seed = 5
[wear]
coefficient = \"2e-6 mm^3/(N m)\"
distance = \"20 m\"
steps = 50
";

fn wear_study(c: &mut Criterion) {
    use stressfield::study::wear::{study_with, MaximaSearch};
    let scene = stressfield::scene::Scene::parse(SMOOTH_BALL, "smooth_ball", "smooth_ball.toml")
        .expect("scene");
    let problem = stressfield::study::rough::problem(&scene).expect("a rough scene");
    let mut group = c.benchmark_group("wear_study_256");
    group.sample_size(10);
    group.bench_function("one_contact_with_maxima", |b| {
        b.iter(|| {
            let solution = solve(&problem, &mut |_, _| {}).expect("solves");
            subsurface_maxima(&solution, 0.2, 0.3).expect("maxima")
        })
    });
    for (name, search) in [
        ("wear_50_steps_warm_maxima", MaximaSearch::Warm),
        ("wear_50_steps_full_maxima", MaximaSearch::Full),
    ] {
        group.bench_function(name, |b| {
            b.iter(|| study_with(&scene, search, &mut |_| {}).expect("study"))
        });
    }
    group.finish();
}

criterion_group!(benches, wear, wear_study);
criterion_main!(benches);

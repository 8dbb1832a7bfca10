//! Rough contact (issue 12): Polonsky-Keer conjugate gradients on a self-affine surface (Hurst
//! 0.8, rms slope 1, roll-off at a quarter of the period, cutoff at 4 samples) pressed to a mean
//! pressure of 0.01 E*, tolerance 1e-8; 512² and 1024², periodic and non-periodic. The
//! reference is Tamaas 2.9's PolonskyKeerRey on the same problem (README, Rough contact).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use stressfield::contact::rough::{solve, Control, RoughContactProblem, DEFAULT_TOLERANCE};
use stressfield::solution::elastic::Periodicity;
use stressfield::surface::generate::{generate, Amplitude, Form, Generator, Spectrum};
use stressfield::surface::HeightMap;

const E_STAR: f64 = 1e9;

/// The benchmark surface: n x n samples over 1 mm.
pub fn surface(n: usize) -> HeightMap {
    let spacing = 1e-3 / n as f64;
    generate(&Generator {
        shape: [n, n],
        spacing_m: [spacing, spacing],
        spectrum: Spectrum::SelfAffine {
            hurst: 0.8,
            rolloff_wavelength_m: 1e-3 / 4.0,
            cutoff_wavelength_m: 4.0 * spacing,
        },
        amplitude: Amplitude::RmsSlope(1.0),
        form: Form::None,
        seed: 1,
    })
    .expect("surface")
}

fn rough_contact(c: &mut Criterion) {
    let mut group = c.benchmark_group("rough_contact");
    group.sample_size(10);
    for n in [512, 1024] {
        let map = surface(n);
        for (name, periodicity) in [
            ("periodic", Periodicity::Periodic),
            ("non_periodic", Periodicity::NonPeriodic),
        ] {
            let problem = RoughContactProblem {
                heights_m: map.heights_m().view(),
                spacing_m: map.spacing_m(),
                e_star_pa: E_STAR,
                periodicity,
                control: Control::MeanPressure { pa: 0.01 * E_STAR },
                hardness_pa: None,
                tolerance: DEFAULT_TOLERANCE,
                max_iterations: 5000,
                memory_limit_bytes: 8 << 30,
            };
            group.bench_with_input(BenchmarkId::new(name, n), &problem, |b, problem| {
                b.iter(|| solve(problem, &mut |_, _| {}))
            });
        }
    }
    group.finish();
}

criterion_group!(benches, rough_contact);
criterion_main!(benches);

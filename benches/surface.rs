//! Surfaces (issue 11): generation of a 4096² self-affine surface (target under 1 s on two
//! cores) and its full characterisation (levelling, ISO 25178 parameters, spectra with the
//! Hurst fit, autocorrelation, summits; target under 2 s).

use criterion::{criterion_group, criterion_main, Criterion};
use stressfield::surface::generate::{generate, Amplitude, Form, Generator, Spectrum};
use stressfield::surface::stats::{characterise, Options};

fn generator(n: usize) -> Generator {
    Generator {
        shape: [n, n],
        spacing_m: [1e-6, 1e-6],
        spectrum: Spectrum::SelfAffine {
            hurst: 0.8,
            rolloff_wavelength_m: n as f64 * 1e-6 / 4.0,
            cutoff_wavelength_m: 4e-6,
        },
        amplitude: Amplitude::RmsHeight(1e-6),
        form: Form::None,
        seed: 1,
    }
}

fn surfaces(c: &mut Criterion) {
    let mut group = c.benchmark_group("surface");
    group.sample_size(10);
    let spec = generator(4096);
    group.bench_function("generate_4096", |b| {
        b.iter(|| generate(&spec).expect("surface"))
    });
    let map = generate(&spec).expect("surface");
    let options = Options::default();
    group.bench_function("characterise_4096", |b| {
        b.iter(|| characterise(&map, &options).expect("statistics"))
    });
    group.finish();
}

criterion_group!(benches, surfaces);
criterion_main!(benches);

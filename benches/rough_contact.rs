//! Rough contact (issue 12): Polonsky-Keer conjugate gradients on a self-affine surface (Hurst
//! 0.8, rms slope 1, roll-off at a quarter of the period, cutoff at 4 samples, over 1 mm),
//! tolerance 1e-8, on 512² and 1024²:
//! - periodic: pressed to a mean pressure of 0.01 E* (the problem Tamaas was timed on, README);
//! - non-periodic: the same roughness on a ball of radius 1 mm under 5 N (E* = 1 GPa), so that
//!   the isolated contact stays inside the grid.
//!
//! And (issue 22) what `stressfield contact` computes after reading the heights: the periodic
//! solve followed by the subsurface maxima search of its report (`with_maxima`), on the same
//! surfaces. Tamaas's solve alone is the target (README, speed section).
//!
//! And (issue 41) Tamaas itself, side by side in the same run: with
//! `STRESSFIELD_TAMAAS_PYTHON=/path/to/python` (a Python with `tamaas` and `numpy`), the
//! periodic heights are written as .npy and `benches/peers/tamaas_solve.py` times
//! `PolonskyKeerRey.solve` alone on them (same mean pressure, tolerance 1e-8), with one and
//! two OpenMP threads (`tamaas_1_thread`, `tamaas_2_threads`). Without the variable the bench
//! runs as before; no test needs Python.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use stressfield::contact::rough::{solve, Control, RoughContactProblem, DEFAULT_TOLERANCE};
use stressfield::operator::elastic::Periodicity;
use stressfield::study::rough::subsurface_maxima;
use stressfield::surface::generate::{generate, Amplitude, Form, Generator, Spectrum};
use stressfield::surface::HeightMap;

const E_STAR: f64 = 1e9;

fn surface(n: usize, form: Form) -> HeightMap {
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
        form,
        seed: 1,
    })
    .expect("surface")
}

fn rough_contact(c: &mut Criterion) {
    let mut group = c.benchmark_group("rough_contact");
    group.sample_size(10);
    for n in [512, 1024] {
        let cases = [
            (
                "periodic",
                surface(n, Form::None),
                Periodicity::Periodic,
                Control::MeanPressure { pa: 0.01 * E_STAR },
            ),
            (
                "non_periodic",
                surface(n, Form::Sphere { radius_m: 1e-3 }),
                Periodicity::NonPeriodic,
                Control::Load { newtons: 5.0 },
            ),
        ];
        for (name, map, periodicity, control) in &cases {
            let problem = RoughContactProblem {
                heights_m: map.heights_m().view(),
                spacing_m: map.spacing_m(),
                e_star_pa: E_STAR,
                periodicity: *periodicity,
                control: *control,
                hardness_pa: None,
                tolerance: DEFAULT_TOLERANCE,
                max_iterations: 5000,
                memory_limit_bytes: 8 << 30,
            };
            // A failing solve would time nothing useful.
            solve(&problem, &mut |_, _| {}).expect("the benchmark problem solves");
            group.bench_with_input(BenchmarkId::new(*name, n), &problem, |b, problem| {
                b.iter(|| solve(problem, &mut |_, _| {}))
            });
            if *periodicity == Periodicity::Periodic {
                if let Some(python) = std::env::var_os("STRESSFIELD_TAMAAS_PYTHON") {
                    tamaas_cases(&mut group, Path::new(&python), map, n);
                }
                group.bench_with_input(
                    BenchmarkId::new("periodic_with_maxima", n),
                    &problem,
                    |b, problem| {
                        b.iter(|| {
                            let solution = solve(problem, &mut |_, _| {}).expect("solved");
                            subsurface_maxima(&solution, 0.0, 0.3).expect("searched")
                        })
                    },
                );
            }
        }
    }
    group.finish();
}

/// Tamaas's `PolonskyKeerRey.solve` on the heights of `map`, pressed to 0.01 E* with tolerance
/// 1e-8, timed by `benches/peers/tamaas_solve.py` (the solve alone, model and solver built
/// outside the timing), with one and two OpenMP threads.
fn tamaas_cases(
    group: &mut criterion::BenchmarkGroup<criterion::measurement::WallTime>,
    python: &Path,
    map: &HeightMap,
    n: usize,
) {
    let heights = std::env::temp_dir().join(format!("stressfield-bench-heights-{n}.npy"));
    ndarray_npy::write_npy(&heights, map.heights_m()).expect("heights written");
    let script = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("benches/peers/tamaas_solve.py");
    let spacing = map.spacing_m()[0];
    for (name, threads) in [("tamaas_1_thread", 1), ("tamaas_2_threads", 2)] {
        group.bench_function(BenchmarkId::new(name, n), |b| {
            b.iter_custom(|repeats| {
                let output = Command::new(python)
                    .arg(&script)
                    .arg(&heights)
                    .arg(spacing.to_string())
                    .arg("0.01")
                    .arg(DEFAULT_TOLERANCE.to_string())
                    .arg(repeats.to_string())
                    .env("OMP_NUM_THREADS", threads.to_string())
                    .output()
                    .expect("the Tamaas script runs");
                assert!(
                    output.status.success(),
                    "tamaas_solve.py failed: {}",
                    String::from_utf8_lossy(&output.stderr)
                );
                let report: serde_json::Value =
                    serde_json::from_slice(&output.stdout).expect("the script prints JSON");
                let seconds: f64 = report["seconds"]
                    .as_array()
                    .expect("a list of seconds")
                    .iter()
                    .filter_map(serde_json::Value::as_f64)
                    .sum();
                Duration::from_secs_f64(seconds)
            })
        });
    }
}

criterion_group!(benches, rough_contact);
criterion_main!(benches);

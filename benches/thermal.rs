//! Frictional heating (issue 21): the flash temperature of a 512² gridded flux at Pe = 1 and
//! 100 (the operator built and applied: influence coefficients, then one DC-FFT), and one
//! coupled thermo-mechanical rough solve (isothermal solve, then the coupled iteration) at 256²
//! and 512². Compare with the isothermal solve of `rough_contact` (512²).
//!
//! Temperature: a Hertzian flux `q0 √(1 - r²/a²)` over a grid of `4a` square (cells of
//! `a/128`), `u = Pe / a`. Coupled: the self-affine roughness of `rough_contact` (Hurst 0.8,
//! rms slope 1) scaled to Sq 0.05 um on a steel ball of radius 2 mm (the `rough_ball_on_flat`
//! scene's kind, cells of 0.5 um at 256²; 0.25 um at 512²) on a steel flat under 0.5 N,
//! μ = 0.1 at 1 m/s, all heat into the flat.
//!
//! Also: the rough scene of issue 41 by `contact` with and without `[thermal]`, and `thermal`
//! of each shipped Hertz scene with `[thermal]` (run from the repository's root, as `cargo
//! bench` does).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use ndarray::Array2;
use stressfield::contact::material::Material;
use stressfield::contact::rough::{self, Control, RoughContactProblem, DEFAULT_TOLERANCE};
use stressfield::operator::elastic::Periodicity;
use stressfield::report::thermal::ThermalReport;
use stressfield::scene::{ThermalBody, ThermalSpec, TractionDirection};
use stressfield::study::coupled;
use stressfield::surface::generate::{generate, Amplitude, Form, Generator, Spectrum};
use stressfield::thermal::heating::Partition;
use stressfield::thermal::kernel::CellGrid;
use stressfield::thermal::material::thermal_preset;
use stressfield::thermal::temperature::TemperatureOperator;

const STEEL: Material = Material {
    modulus_pa: 210e9,
    poisson: 0.3,
};

fn temperature(c: &mut Criterion) {
    let mut group = c.benchmark_group("thermal_temperature");
    group.sample_size(10);
    let n = 512;
    let a = 1e-4;
    let d = 4.0 * a / n as f64;
    let grid = CellGrid {
        shape: [n, n],
        spacing_m: [d, d],
    };
    let flux = Array2::from_shape_fn((n, n), |(row, column)| {
        let x = (column as f64 + 0.5) * d - 2.0 * a;
        let y = (row as f64 + 0.5) * d - 2.0 * a;
        1e8 * (1.0 - (x * x + y * y) / (a * a)).max(0.0).sqrt()
    });
    for peclet in [1.0, 100.0] {
        group.bench_with_input(BenchmarkId::new("512", peclet), &peclet, |b, &peclet| {
            b.iter(|| {
                let mut operator =
                    TemperatureOperator::new(&grid, 0.0, peclet / a, 50.0).expect("operator");
                operator.apply(flux.view()).expect("apply")
            })
        });
    }
    group.finish();
}

fn coupled_solve(c: &mut Criterion) {
    let mut group = c.benchmark_group("thermal_coupled");
    group.sample_size(10);
    let steel = thermal_preset("steel").expect("steel");
    let spec = ThermalSpec {
        sliding_speed_m_per_s: 1.0,
        traction: TractionDirection::PlusX,
        speed_keys: ["thermal.speed", "thermal.body2_speed"],
        partition: Partition::Body1,
        coupled: true,
        body1: ThermalBody {
            properties: steel,
            material: STEEL,
            speed_m_per_s: 1.0,
        },
        body2: None,
        gear: None,
    };
    let e_star = STEEL.modulus_pa / (2.0 * (1.0 - STEEL.poisson * STEEL.poisson));
    for n in [256, 512] {
        let spacing = 128e-6 / n as f64;
        let map = generate(&Generator {
            shape: [n, n],
            spacing_m: [spacing, spacing],
            spectrum: Spectrum::SelfAffine {
                hurst: 0.8,
                rolloff_wavelength_m: 32e-6,
                cutoff_wavelength_m: 4.0 * spacing,
            },
            amplitude: Amplitude::RmsHeight(0.05e-6),
            form: Form::Sphere { radius_m: 2e-3 },
            seed: 3,
        })
        .expect("surface");
        let problem = RoughContactProblem {
            heights_m: map.heights_m().view(),
            spacing_m: map.spacing_m(),
            e_star_pa: e_star,
            periodicity: Periodicity::NonPeriodic,
            control: Control::Load { newtons: 0.5 },
            hardness_pa: None,
            tolerance: DEFAULT_TOLERANCE,
            max_iterations: 5000,
            memory_limit_bytes: 4 << 30,
        };
        group.bench_with_input(BenchmarkId::new("rough_ball", n), &n, |b, _| {
            b.iter(|| {
                let isothermal = rough::solve(&problem, &mut |_, _| {}).expect("isothermal");
                coupled::solve(&problem, isothermal, &spec, 0.1, &mut |_, _| {}).expect("coupled")
            })
        });
    }
    group.finish();
}

/// A rough steel ball (R = 2 mm, Sq 0.05 µm, seed 3) on a steel flat under 0.5 N, μ = 0.1, over a
/// 128 µm window (isolated), or the same roughness without the ball pressed to 0.5 GPa
/// (periodic), with `[thermal]` sliding at 0.5 m/s (Pe about 1.3, Blok's partition): the scene
/// of issue 41.
fn rough_scene(samples: usize, periodic: bool, heated: bool) -> stressfield::scene::Scene {
    let spacing_um = 128.0 / samples as f64;
    let (control, form) = if periodic {
        ("mean_pressure = \"0.5 GPa\"\nperiodic = true", "")
    } else {
        ("load = \"0.5 N\"", "sphere_radius = \"2 mm\"\n")
    };
    let thermal = if heated {
        "[thermal]\nspeed = \"0.5 m/s\"\npartition = \"blok\"\n"
    } else {
        ""
    };
    let text = format!(
        "format = 1\n[contact]\nkind = \"rough\"\n{control}\nfriction = 0.1\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n[surface.generate]\nsamples = {samples}\nspacing = \"{spacing_um} um\"\nhurst = 0.8\nrolloff = \"32 um\"\ncutoff = \"2 um\"\nrms_height = \"0.05 um\"\n{form}seed = 3\n{thermal}"
    );
    stressfield::scene::Scene::parse(&text, "bench", "bench.toml").expect("the bench scene")
}

/// What `stressfield contact` computes of a rough scene, without and with `[thermal]`, side by
/// side: the solve and the subsurface maxima, and then the heating study (issue 41's target:
/// at most twice the time). `STRESSFIELD_BENCH_SIZES` (e.g. `256,512,1024`) chooses the grids
/// (default 256).
fn rough_heating(c: &mut Criterion) {
    let mut group = c.benchmark_group("thermal_rough");
    group.sample_size(10);
    let sizes: Vec<usize> = std::env::var("STRESSFIELD_BENCH_SIZES")
        .ok()
        .map(|v| v.split(',').filter_map(|s| s.trim().parse().ok()).collect())
        .unwrap_or_else(|| vec![256]);
    for n in sizes {
        for periodic in [false, true] {
            let kind = if periodic { "periodic" } else { "isolated" };
            for heated in [false, true] {
                let scene = rough_scene(n, periodic, heated);
                let name = format!("{kind}_{}", if heated { "thermal" } else { "contact" });
                group.bench_with_input(BenchmarkId::new(name, n), &scene, |b, scene| {
                    b.iter(|| {
                        let solution = stressfield::study::rough::solve(scene, &mut |_, _| {})
                            .expect("solved");
                        let findings =
                            stressfield::study::rough::findings(scene, &solution).expect("maxima");
                        // As `stressfield contact` does: the heating reuses the maxima found.
                        let known = stressfield::study::thermal::ContactMaxima {
                            maxima: &findings.maxima,
                            friction: scene.contact.friction,
                            poisson: scene.contact.poisson,
                        };
                        let heating = scene.thermal.map(|_| {
                            stressfield::study::thermal::study_with(
                                scene,
                                Some(&solution),
                                Some(known),
                                &mut |_| {},
                            )
                            .expect("heated")
                        });
                        (findings, heating)
                    })
                });
            }
        }
    }
    group.finish();
}

/// `stressfield thermal` of each shipped Hertz scene with `[thermal]` (issue 41's target: under
/// one second each): the heating study and its report, as the command computes them (the
/// gears along their path of contact), reading the scene included; printing left out.
fn hertz_scenes(c: &mut Criterion) {
    let mut group = c.benchmark_group("thermal_hertz_scenes");
    group.sample_size(10);
    for name in [
        "thermal_sliding_sphere",
        "thermal_ball_on_disc",
        "gear_pitch_point",
        "record_thermal_speed_sweep",
    ] {
        let path = std::path::PathBuf::from(format!("scenes/{name}.toml"));
        group.bench_function(name, |b| {
            b.iter(|| {
                let scene = stressfield::study::load_scene(&path).expect("a shipped scene");
                if scene.thermal.and_then(|t| t.gear).is_some() {
                    let gear = stressfield::study::gear_heating::gear_heating(&scene, &mut |_| {})
                        .expect("heated");
                    ThermalReport::for_gears(&gear)
                } else {
                    let study = stressfield::study::thermal::study(&scene, None, &mut |_| {})
                        .expect("heated");
                    ThermalReport::new(&study)
                }
            })
        });
    }
    group.finish();
}

criterion_group!(
    benches,
    temperature,
    coupled_solve,
    rough_heating,
    hertz_scenes
);
criterion_main!(benches);

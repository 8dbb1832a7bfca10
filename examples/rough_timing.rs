use std::time::Instant;
use stressfield::contact::rough::{solve, Control, RoughContactProblem};
use stressfield::solution::elastic::Periodicity;
use stressfield::surface::generate::{generate, Amplitude, Form, Generator, Spectrum};
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args[1].parse().unwrap();
    let periodic = args[2] == "p";
    let tol: f64 = args.get(3).map(|s| s.parse().unwrap()).unwrap_or(1e-8);
    let spacing = 1e-3 / n as f64;
    let t = Instant::now();
    let map = generate(&Generator {
        shape: [n, n],
        spacing_m: [spacing, spacing],
        spectrum: Spectrum::SelfAffine {
            hurst: 0.8,
            rolloff_wavelength_m: 1e-3 / 4.0,
            cutoff_wavelength_m: 4.0 * spacing,
        },
        amplitude: Amplitude::RmsSlope(1.0),
        form: if periodic {
            Form::None
        } else {
            Form::Sphere { radius_m: 1e-3 }
        },
        seed: 1,
    })
    .unwrap();
    eprintln!("generate {:.3} s", t.elapsed().as_secs_f64());
    let e = 1e9;
    let control = if periodic {
        Control::MeanPressure { pa: 0.01 * e }
    } else {
        Control::Load { newtons: 5.0 }
    };
    let p = RoughContactProblem {
        heights_m: map.heights_m().view(),
        spacing_m: map.spacing_m(),
        e_star_pa: e,
        periodicity: if periodic {
            Periodicity::Periodic
        } else {
            Periodicity::NonPeriodic
        },
        control,
        hardness_pa: None,
        tolerance: tol,
        max_iterations: 5000,
        memory_limit_bytes: 8 << 30,
    };
    let t = Instant::now();
    let s = solve(&p, &mut |_, _| {});
    let el = t.elapsed().as_secs_f64();
    if let (Some(path), Ok(sol)) = (args.get(4), &s) {
        ndarray_npy::write_npy(format!("{path}-heights.npy"), map.heights_m()).unwrap();
        ndarray_npy::write_npy(format!("{path}-pressure.npy"), &sol.pressure_pa).unwrap();
    }
    match s { Ok(s) => eprintln!("n {n} periodic {periodic}: {el:.3} s, {} it, residual {:.2e}, fraction {:.4}, spots {}, max p/E* {:.4}", s.iterations, s.residual, s.contact_fraction, s.spots, s.max_pressure_pa / e),
      Err(err) => eprintln!("n {n}: {el:.3} s error {err}") }
}

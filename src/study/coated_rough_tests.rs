//! Checks of the coated rough contact against independent references: the homogeneous rough
//! solver (equal moduli; a very thick and a very thin coating), the coated point study (a
//! smooth ball given as a map), equilibrium and the interface conditions.

use std::f64::consts::PI;

use ndarray::Array2;

use super::*;
use crate::coating::response::plane_strain_modulus;
use crate::contact::coated;
use crate::contact::material::Material;
use crate::contact::rough::{self, Control, RoughContactProblem};
use crate::scene::Scene;

const STEEL: Material = Material {
    modulus_pa: 210e9,
    poisson: 0.3,
};
const B4C: Material = Material {
    modulus_pa: 450e9,
    poisson: 0.17,
};

/// A coating of `material`, `thickness_m` thick on steel, against a steel counter-body.
fn spec(material: Material, thickness_m: f64) -> CoatingSpec {
    CoatingSpec {
        thickness_m,
        material,
        substrate: STEEL,
        counter_per_pa: (1.0 - 0.09) / 210e9,
        counter_rigid: false,
        under: crate::coating::Interlayers::NONE,
        stacked: false,
        strengths: crate::scene::Strengths::default(),
    }
}

/// A wavy map of `n` cells of 0.5 µm: a periodic surface of a few sinusoids (integer waves per
/// period), with a ball of radius 2 mm on it when isolated.
fn wavy(n: usize, periodic: bool) -> Array2<f64> {
    let d = 0.5e-6;
    let length = n as f64 * d;
    Array2::from_shape_fn((n, n), |(j, i)| {
        let (x, y) = ((i as f64 + 0.5) * d, (j as f64 + 0.5) * d);
        let k = 2.0 * PI / length;
        let rough = 0.05e-6
            * ((3.0 * k * x).sin() * (2.0 * k * y).cos()
                + 0.6 * (7.0 * k * x + 1.0).cos() * (5.0 * k * y).sin()
                + 0.3 * (13.0 * k * (x + y)).sin());
        if periodic {
            rough
        } else {
            let (cx, cy) = (x - 0.5 * length, y - 0.5 * length);
            rough - (cx * cx + cy * cy) / (2.0 * 2e-3)
        }
    })
}

fn problem(heights: &Array2<f64>, periodic: bool, e_star_pa: f64) -> RoughContactProblem<'_> {
    RoughContactProblem {
        heights_m: heights.view(),
        spacing_m: [0.5e-6; 2],
        e_star_pa,
        periodicity: if periodic {
            Periodicity::Periodic
        } else {
            Periodicity::NonPeriodic
        },
        control: if periodic {
            Control::MeanPressure { pa: 100e6 }
        } else {
            Control::Load { newtons: 0.05 }
        },
        hardness_pa: None,
        tolerance: 1e-12,
        max_iterations: rough::DEFAULT_MAX_ITERATIONS,
        memory_limit_bytes: 1 << 30,
    }
}

fn coated_solve(heights: &Array2<f64>, periodic: bool, spec: &CoatingSpec) -> RoughSolution {
    let e_far = 1.0 / ((1.0 - 0.09) / 210e9 + spec.counter_per_pa);
    coated::solve(
        &problem(heights, periodic, e_far),
        &spec.layered(),
        spec.counter_per_pa,
        &mut |_, _| {},
    )
    .expect("coated rough solve")
}

/// The homogeneous rough solve of a body of `material` against the steel counter-body.
fn homogeneous_solve(heights: &Array2<f64>, periodic: bool, material: Material) -> RoughSolution {
    let e_star = 1.0 / (1.0 / plane_strain_modulus(&material) + (1.0 - 0.09) / 210e9);
    rough::solve(&problem(heights, periodic, e_star), &mut |_, _| {}).expect("rough solve")
}

/// The largest pressure difference over the larger peak pressure.
fn pressure_difference(a: &RoughSolution, b: &RoughSolution) -> f64 {
    let peak = a.max_pressure_pa.max(b.max_pressure_pa);
    (&a.pressure_pa - &b.pressure_pa)
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()))
        / peak
}

#[test]
fn depths_run_through_the_coating_and_on_both_sides_of_the_interface() {
    let d = depths(4.0, 0.5, 20.0);
    assert_eq!(d[0], (0.0, Side::Coating));
    let at_interface: Vec<_> = d.iter().filter(|p| p.0 == 4.0).collect();
    assert_eq!(at_interface.len(), 2);
    assert!(d.windows(2).all(|w| w[1].0 >= w[0].0));
    // The substrate's schedule ends within half a step (a tenth of the depth) of the end.
    assert!(d.last().is_some_and(|p| p.0 > 18.0 && p.0 <= 20.0), "{d:?}");
}

#[test]
fn equal_moduli_give_the_homogeneous_rough_solution() {
    // The coating of steel on steel, 2 µm: the layered kernels reduce to Love's and the
    // pressure to the homogeneous solver's on the same map, periodic and isolated.
    let mut worst: f64 = 0.0;
    for periodic in [true, false] {
        let heights = wavy(64, periodic);
        let coated = coated_solve(&heights, periodic, &spec(STEEL, 2e-6));
        let plain = homogeneous_solve(&heights, periodic, STEEL);
        let difference = pressure_difference(&coated, &plain);
        eprintln!(
            "measured: equal moduli, coated rough against homogeneous rough ({}): pressure {difference:.1e} of the peak, load {:.1e}",
            if periodic { "periodic" } else { "isolated" },
            (coated.load_n / plain.load_n - 1.0).abs()
        );
        worst = worst.max(difference);
    }
    assert!(worst < 1e-10, "{worst}");
}

#[test]
fn a_thick_coating_gives_the_coatings_rough_solution_and_a_thin_one_the_substrates() {
    // B4C on steel. Thick (h = 1 m, twenty thousand times the map): the coating's homogeneous
    // rough contact. Thin (h = 2 and 4 cells): the substrate's, the difference of the order
    // of h over the spots' size, halving as h halves.
    let mut thick_worst: f64 = 0.0;
    for periodic in [true, false] {
        let heights = wavy(64, periodic);
        let thick = coated_solve(&heights, periodic, &spec(B4C, 1.0));
        let coating = homogeneous_solve(&heights, periodic, B4C);
        let difference = pressure_difference(&thick, &coating);
        eprintln!(
            "measured: h = 1 m, coated rough against the coating's homogeneous rough ({}): pressure {difference:.1e} of the peak",
            if periodic { "periodic" } else { "isolated" }
        );
        thick_worst = thick_worst.max(difference);
    }
    assert!(thick_worst < 1e-6, "{thick_worst}");
    // One long wave (64 µm) pressed to patches about 30 cells across: h of 2 and 4 cells is
    // thin against them.
    let d = 0.5e-6;
    let k = 2.0 * PI / (128.0 * d);
    let heights = Array2::from_shape_fn((128, 128), |(j, i)| {
        0.05e-6 * (k * (i as f64 + 0.5) * d).cos() * (k * (j as f64 + 0.5) * d).cos()
    });
    let substrate = homogeneous_solve(&heights, true, STEEL);
    let errors: Vec<f64> = [1e-6, 2e-6]
        .iter()
        .map(|&h| pressure_difference(&coated_solve(&heights, true, &spec(B4C, h)), &substrate))
        .collect();
    let coating_apart = pressure_difference(&homogeneous_solve(&heights, true, B4C), &substrate);
    eprintln!(
        "measured: thin B4C on steel (periodic), against the substrate's rough solution: h = 2 cells {:.3}, 4 cells {:.3} of the peak (the coating's own solution is {coating_apart:.3} apart)",
        errors[0], errors[1]
    );
    // Closer to the substrate's as the coating thins (about as h^0.8 here), and at two cells
    // within a third of the way from the substrate's solution to the coating's.
    assert!(errors[0] < 0.7 * errors[1], "{errors:?}");
    assert!(
        errors[0] < 0.3 * coating_apart,
        "{errors:?} {coating_apart}"
    );
}

#[test]
fn the_layered_field_is_in_equilibrium_and_continuous_across_the_interface() {
    // Periodic B4C on steel, 2 µm, μ = 0.2: the mean σzz and σxz of every plane are -p̄ and
    // -q̄ (the tractions carried down through both materials); at the interface σzz, σyz, σxz
    // are continuous and σxx jumps.
    let heights = wavy(64, true);
    let coating = spec(B4C, 2e-6);
    let solution = coated_solve(&heights, true, &coating);
    let mean_p = solution.pressure_pa.mean().unwrap_or(0.0);
    let load = solution.pressure_pa.sum() * 0.25e-12;
    eprintln!(
        "measured: pressure integrates to the load: {:.1e}",
        (load / solution.load_n - 1.0).abs()
    );
    assert!((load / solution.load_n - 1.0).abs() < 1e-12);
    let layers = layered_stress(&solution, &coating, 0.2).expect("layers");
    let peak = solution.max_pressure_pa;
    let mut worst_mean: f64 = 0.0;
    for (z, side) in [
        (0.3e-6, Side::Coating),
        (2e-6, Side::Coating),
        (2e-6, Side::Substrate),
        (7e-6, Side::Substrate),
    ] {
        let field = layers.layer(z, side).expect("layer");
        let mean = |c: usize| field.index_axis(ndarray::Axis(0), c).mean().unwrap_or(0.0);
        worst_mean = worst_mean
            .max((mean(2) + mean_p).abs() / mean_p)
            .max((mean(4) + 0.2 * mean_p).abs() / mean_p);
    }
    let above = layers.layer(2e-6, Side::Coating).expect("layer");
    let below = layers.layer(2e-6, Side::Substrate).expect("layer");
    let jump = |c: usize| {
        (&above.index_axis(ndarray::Axis(0), c) - &below.index_axis(ndarray::Axis(0), c))
            .iter()
            .fold(0.0f64, |m, v| m.max(v.abs()))
            / peak
    };
    let continuous = jump(2).max(jump(3)).max(jump(4));
    eprintln!(
        "measured: mean σzz, σxz of the planes against -p̄, -q̄: {worst_mean:.1e} p̄; interface σzz, σyz, σxz continuous to {continuous:.1e} of the peak, σxx jumps by {:.3}",
        jump(0)
    );
    assert!(worst_mean < 1e-10, "{worst_mean}");
    assert!(continuous < 1e-12, "{continuous}");
    // B4C on steel: σxx jumps with the moduli, by a visible fraction of the peak.
    assert!(jump(0) > 0.01 && jump(0) > 1e10 * continuous, "{}", jump(0));
}

#[test]
fn a_smooth_ball_given_as_a_map_agrees_with_the_coated_point_study() {
    // The lecture notes' ball (6.35 mm steel, 5 N, μ = 0.1) on 10 µm of B4C on steel: the
    // coated point study (96 cells over ±2a), and the same gridded paraboloid solved as a
    // rough map with its maxima searched in full planes. The pressures are the same solve;
    // the maxima differ by the sampling: the point study's largest samples of the plane y = 0,
    // the rough search's planes refined in depth.
    let text = "format = 1\n[contact]\nkind = \"point\"\nload = \"5 N\"\nfriction = 0.1\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body1.coating]\nthickness = \"10 um\"\nmaterial = \"boron_carbide\"\n[contact.body2]\nradius = \"6.35 mm\"\nmaterial = \"steel\"\n[numerical]\ncells = 96\n";
    let scene = Scene::parse(text, "test", "test.toml").expect("valid");
    let point = crate::study::coated::solve(&scene).expect("coated point study");
    let coating = scene.contact.coating.expect("coated");
    let crate::study::coated::CoatedSolution::Surface(solved) = &point.solution else {
        panic!("a point contact");
    };
    let found = maxima(solved, &coating, 0.1).expect("maxima");
    let m = &point.maxima;
    let pairs = [
        (
            "coating von Mises",
            m.coating_von_mises.value_pa,
            found.coating_von_mises.value_pa,
        ),
        (
            "substrate von Mises",
            m.substrate_von_mises.value_pa,
            found.substrate_von_mises.value_pa,
        ),
        (
            "interface shear",
            m.interface_shear.value_pa,
            found.interface_shear.value_pa,
        ),
        (
            "interface σzz",
            m.interface_normal_min.value_pa,
            found.interface_normal_min.value_pa,
        ),
    ];
    let mut errors = Vec::new();
    for (name, study, rough) in pairs {
        let error = rough / study - 1.0;
        eprintln!(
            "measured: smooth ball as a map against the coated point study, {name}: {:.1} against {:.1} MPa, {:+.2} %",
            rough * 1e-6,
            study * 1e-6,
            100.0 * error
        );
        errors.push(error);
    }
    // The interface and the substrate: the same values. The coating's largest von Mises
    // stress lies on the surface at the contact's trailing edge, where the gridded circle's
    // edge cells differ from row to row: the full planes find a larger one off y = 0, never a
    // smaller one.
    eprintln!(
        "  the coating's maximum of the map at x = {:.1} µm, y = {:.1} µm from the centre, z = {:.2} µm",
        (found.coating_von_mises.x_m - 48.0 * solved.spacing_m[0]) * 1e6,
        (found.coating_von_mises.y_m - 48.0 * solved.spacing_m[1]) * 1e6,
        found.coating_von_mises.z_m * 1e6
    );
    assert!(errors[1..].iter().all(|e| e.abs() < 5e-3), "{errors:?}");
    assert!(errors[0] > -5e-3 && errors[0] < 0.02, "{errors:?}");
}

#[test]
fn a_coated_rough_scene_reports_its_coating_and_refuses_what_it_cannot_compute() {
    let scene_text = |extra: &str, thickness: &str| {
        format!(
            "format = 1\n[contact]\nkind = \"rough\"\nload = \"0.05 N\"\nfriction = 0.1\n{extra}\n[contact.body1]\nmaterial = \"steel\"\n[contact.body1.coating]\nthickness = \"{thickness}\"\nmaterial = \"boron_carbide\"\n[contact.body2]\nmaterial = \"steel\"\n[surface.generate]\nsamples = 64\nspacing = \"0.5 um\"\nhurst = 0.8\nrolloff = \"8 um\"\nrms_height = \"0.05 um\"\nsphere_radius = \"2 mm\"\nseed = 3\n"
        )
    };
    let scene = Scene::parse(&scene_text("", "2 um"), "test", "test.toml").expect("valid");
    let solution = crate::study::rough::solve(&scene, &mut |_, _| {}).expect("solve");
    let findings = crate::study::rough::findings(&scene, &solution).expect("findings");
    let report = crate::report::rough::ContactReport::new(&scene, &solution, &findings);
    let json: serde_json::Value = serde_json::from_str(&report.json()).expect("json");
    let coating = &json["coating"];
    for key in [
        "thickness_m",
        "von_mises_max_pa",
        "interface_shear_max_pa",
        "interface_normal_min_pa",
        "substrate_von_mises_max_pa",
    ] {
        assert!(coating[key].as_f64().is_some_and(f64::is_finite), "{key}");
    }
    assert_eq!(coating.as_object().map(|o| o.len()), Some(5));
    assert_eq!(coating["thickness_m"].as_f64(), Some(2e-6));
    assert!(coating["interface_normal_min_pa"].as_f64() < Some(0.0));
    let vm = json["von_mises_max_pa"].as_f64().unwrap_or(f64::NAN);
    let largest = coating["von_mises_max_pa"]
        .as_f64()
        .unwrap_or(f64::NAN)
        .max(
            coating["substrate_von_mises_max_pa"]
                .as_f64()
                .unwrap_or(f64::NAN),
        );
    assert_eq!(vm, largest);
    // Refused, by key.
    for (text, key) in [
        (
            scene_text("hardness = \"300 HV\"", "2 um"),
            "contact.hardness",
        ),
        (
            scene_text("yield_strength = \"1 GPa\"", "2 um"),
            "contact.yield_strength",
        ),
        (scene_text("", "0.8 um"), "contact.body1.coating.thickness"),
        (
            scene_text("", "2 um") + "[thermal]\nspeed = \"1 m/s\"\n",
            "thermal",
        ),
        (
            scene_text("", "2 um")
                + "[sweep]\nparameter = \"load\"\nvalues = [\"0.01 N\", \"0.02 N\"]\n",
            "sweep",
        ),
    ] {
        let message = match Scene::parse(&text, "test", "test.toml") {
            Ok(_) => panic!("accepted: {key}"),
            Err(e) => e.to_string(),
        };
        assert!(message.contains(key), "{key}: {message}");
    }
    let message = Scene::parse(&scene_text("", "0.8 um"), "test", "test.toml")
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(message.contains("surface.generate.spacing"), "{message}");
}

/// Issue 50 §2: a coated rough solve hears a stop between iterations (Ctrl-C in Python), as
/// the uncoated one does: a break before convergence is `Interrupted`, never a result, and a
/// progress that always goes on gives [`crate::study::rough::solve`]'s solution bit for bit.
#[test]
fn a_coated_rough_solve_stops_when_asked() {
    let text = "format = 1\n[contact]\nkind = \"rough\"\nload = \"0.05 N\"\n[contact.body1]\nmaterial = \"steel\"\n[contact.body1.coating]\nthickness = \"2 um\"\nmaterial = \"boron_carbide\"\n[contact.body2]\nmaterial = \"steel\"\n[surface.generate]\nsamples = 64\nspacing = \"0.5 um\"\nhurst = 0.8\nrolloff = \"8 um\"\nrms_height = \"0.05 um\"\nsphere_radius = \"2 mm\"\nseed = 3\n";
    let scene = Scene::parse(text, "test", "test.toml").expect("valid");
    let mut heard = 0;
    let stopped = crate::study::rough::solve_interruptible(&scene, &mut |_, _| {
        heard += 1;
        std::ops::ControlFlow::Break(())
    });
    assert_eq!(heard, 1);
    assert!(
        matches!(
            stopped,
            Err(crate::study::rough::RoughStudyError::Contact(
                rough::RoughContactError::Interrupted { iterations: 1, .. }
            ))
        ),
        "{stopped:?}"
    );
    let went_on = crate::study::rough::solve_interruptible(&scene, &mut |_, _| {
        std::ops::ControlFlow::Continue(())
    })
    .expect("solved");
    let plain = crate::study::rough::solve(&scene, &mut |_, _| {}).expect("solved");
    assert_eq!(went_on.pressure_pa, plain.pressure_pa);
    assert_eq!(went_on.iterations, plain.iterations);
}

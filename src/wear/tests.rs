//! Checks of the worn contact against independent references: Archard's volume, the rigid
//! flat-scar law of a worn ball with its uniform pressure and elastic crown, the first step
//! against the static contact, halving the step, the plastic area's bound, and the worn
//! surfaces solved again one by one.

use std::f64::consts::PI;

use ndarray::Array2;

use super::*;
use crate::contact::rough::{Control, DEFAULT_MAX_ITERATIONS, DEFAULT_TOLERANCE};
use crate::operator::elastic::Periodicity;

/// A steel ball (E* against a rigid flat: 210 GPa / (1 − 0.3²)).
const E_STAR: f64 = 210e9 / (1.0 - 0.09);

/// A smooth ball of radius `radius` on `n`² cells of `d` (m), centred.
fn ball(n: usize, d: f64, radius: f64) -> Array2<f64> {
    let centre = 0.5 * n as f64 * d;
    Array2::from_shape_fn((n, n), |(j, i)| {
        let x = (i as f64 + 0.5) * d - centre;
        let y = (j as f64 + 0.5) * d - centre;
        -(x * x + y * y) / (2.0 * radius)
    })
}

fn problem(
    heights: &Array2<f64>,
    d: f64,
    load: f64,
    hardness: Option<f64>,
) -> RoughContactProblem<'_> {
    RoughContactProblem {
        heights_m: heights.view(),
        spacing_m: [d, d],
        e_star_pa: E_STAR,
        periodicity: Periodicity::NonPeriodic,
        control: Control::Load { newtons: load },
        hardness_pa: hardness,
        tolerance: DEFAULT_TOLERANCE,
        max_iterations: DEFAULT_MAX_ITERATIONS,
        memory_limit_bytes: 1 << 30,
    }
}

/// Every step of an evolution, with the worn heights after each.
fn run(
    problem: &RoughContactProblem,
    law: Archard,
    schedule: Schedule,
) -> Vec<(WearStep, Array2<f64>)> {
    let mut evolution = Evolution::new(problem, law, schedule).expect("evolution");
    let mut steps = Vec::new();
    while let Some(step) = evolution.step(&mut |_, _| {}).expect("step") {
        steps.push((step, evolution.heights_m().clone()));
    }
    steps
}

/// A seeded rough surface: a sum of a few cosines with random phases (no generator needed).
fn rough_ball(n: usize, d: f64, radius: f64, amplitude: f64) -> Array2<f64> {
    let mut heights = ball(n, d, radius);
    let waves = [
        (3.0, 5.0, 0.3),
        (7.0, 2.0, 1.1),
        (11.0, 13.0, 2.0),
        (17.0, 4.0, 0.7),
    ];
    let size = n as f64 * d;
    for ((j, i), h) in heights.indexed_iter_mut() {
        let (x, y) = ((i as f64 + 0.5) * d, (j as f64 + 0.5) * d);
        for (kx, ky, phase) in waves {
            *h += amplitude * (2.0 * PI * (kx * x + ky * y) / size + phase).cos()
                / waves.len() as f64;
        }
    }
    heights
}

#[test]
fn the_worn_volume_is_archards_k_w_s_at_every_step() {
    // Whatever the pressure, Σ k ds p dA = k W ds: the worn volume after each step is k W s
    // to 1e-9 (relative), on a rough ball with and without a hardness cap.
    let (n, d, radius, load) = (64, 1.5e-6, 2e-3, 0.3);
    let heights = rough_ball(n, d, radius, 0.05e-6);
    let k = 1e-14;
    for hardness in [None, Some(6e9)] {
        let p = problem(&heights, d, load, hardness);
        let schedule = Schedule {
            distance_m: 0.05,
            steps: 8,
        };
        let mut worst = 0.0f64;
        for (step, _) in run(
            &p,
            Archard {
                coefficient_m2_per_n: k,
            },
            schedule,
        ) {
            let expected = k * load * step.sliding_distance_m;
            if step.index == 0 {
                assert_eq!(step.worn_volume_m3, 0.0);
                continue;
            }
            worst = worst.max((step.worn_volume_m3 / expected - 1.0).abs());
        }
        eprintln!(
            "measured: Archard volume, hardness {hardness:?}: largest relative error {worst:.1e}"
        );
        assert!(worst < 1e-9, "{worst}");
    }
}

#[test]
fn the_first_step_is_the_static_contact_bit_for_bit() {
    let (n, d) = (48, 2e-6);
    let heights = rough_ball(n, d, 2e-3, 0.1e-6);
    let p = problem(&heights, d, 0.2, Some(5e9));
    let static_contact = rough::solve(&p, &mut |_, _| {}).expect("static");
    let mut evolution = Evolution::new(
        &p,
        Archard {
            coefficient_m2_per_n: 1e-14,
        },
        Schedule {
            distance_m: 1.0,
            steps: 4,
        },
    )
    .expect("evolution");
    let first = evolution
        .step(&mut |_, _| {})
        .expect("step")
        .expect("first");
    assert_eq!(first.index, 0);
    assert_eq!(first.sliding_distance_m, 0.0);
    assert_eq!(first.solution, static_contact);
}

/// The contact radius `sqrt(A / π)` of a solution, m.
fn contact_radius(solution: &RoughSolution) -> f64 {
    let [dx, dy] = solution.spacing_m;
    let cells = solution.pressure_pa.iter().filter(|&&p| p > 0.0).count();
    (cells as f64 * dx * dy / PI).sqrt()
}

#[test]
fn a_smooth_ball_wears_to_the_rigid_flat_scar_with_a_uniform_pressure_and_its_elastic_crown() {
    // A smooth steel ball (R = 2 mm, 0.5 N) on a rigid flat: the Hertz radius is 14.8 µm. Worn
    // until the scar volume k W s makes a flat scar of radius a = (4 R k W s / π)^(1/4) = 3.3
    // times it, the scar radius (from the contact area) tends to that law, the pressure over the
    // inner scar to W / (π a²), and the unloaded scar keeps a crown u(0) − u(a) = (2 − 4/π) p a
    // / E* (the elastic displacement of a uniform pressure; Johnson 1985, §3.4) between its
    // centre and its edge.
    let (n, d, radius, load) = (112, 1.25e-6, 2e-3, 0.5);
    let heights = ball(n, d, radius);
    let hertz = (3.0 * load * radius / (4.0 * E_STAR)).cbrt();
    let k = 1e-14;
    let distance = 0.4;
    let p = problem(&heights, d, load, None);
    let steps = run(
        &p,
        Archard {
            coefficient_m2_per_n: k,
        },
        Schedule {
            distance_m: distance,
            steps: 40,
        },
    );
    let (last, worn) = steps.last().expect("steps");
    let law = (4.0 * radius * k * load * distance / PI).powf(0.25);
    let a = contact_radius(&last.solution);
    eprintln!(
        "measured: worn ball: scar radius {:.3} µm against the rigid law's {:.3} µm ({:+.2} %), Hertz {:.2} µm",
        a * 1e6,
        law * 1e6,
        100.0 * (a / law - 1.0),
        hertz * 1e6
    );
    assert!(law > 3.0 * hertz);
    assert!((a / law - 1.0).abs() < 0.02, "{a} against {law}");

    let uniform = load / (PI * a * a);
    let centre = 0.5 * n as f64 * d;
    let (mut sum, mut count, mut largest) = (0.0, 0usize, 0.0f64);
    for ((j, i), &pressure) in last.solution.pressure_pa.indexed_iter() {
        let r = ((i as f64 + 0.5) * d - centre).hypot((j as f64 + 0.5) * d - centre);
        if r < 0.8 * a {
            sum += pressure;
            count += 1;
            largest = largest.max(pressure);
        }
    }
    let inner_mean = sum / count as f64;
    eprintln!(
        "measured: worn ball: inner-scar pressure mean {:.2} MPa, max {:.2} MPa, uniform W/(πa²) {:.2} MPa",
        inner_mean * 1e-6,
        largest * 1e-6,
        uniform * 1e-6
    );
    assert!((inner_mean / uniform - 1.0).abs() < 0.03);
    assert!(largest / uniform < 1.1);

    // The crown: the unloaded worn heights at the centre above those at 0.7a, inside the scar
    // (at its edge the ball's slope a/R would swamp a few nanometres), against the elastic
    // displacement of a uniform pressure, u(r) = 4 p a E(r/a) / (π E*) (Johnson 1985, §3.4;
    // E the complete elliptic integral of the second kind): u(0) − u(0.7a). The crown to the
    // edge, (2 − 4/π) p a / E*, follows from the same formula at r = a.
    let ring = |r_target: f64| {
        let (mut s, mut c) = (0.0, 0usize);
        for ((j, i), &h) in worn.indexed_iter() {
            let r = ((i as f64 + 0.5) * d - centre).hypot((j as f64 + 0.5) * d - centre);
            if (r - r_target).abs() < 0.5 * d {
                s += h;
                c += 1;
            }
        }
        s / c as f64
    };
    let centre_height = {
        let (mut s, mut c) = (0.0, 0usize);
        for ((j, i), &h) in worn.indexed_iter() {
            let r = ((i as f64 + 0.5) * d - centre).hypot((j as f64 + 0.5) * d - centre);
            if r < 1.5 * d {
                // The crown is flat near the centre to second order: a small disc's mean.
                s += h;
                c += 1;
            }
        }
        s / c as f64
    };
    let u = |r: f64| {
        4.0 * uniform * a * crate::contact::elliptic::complete_elliptic_integrals(r / a).second_kind
            / (PI * E_STAR)
    };
    let crown = centre_height - ring(0.7 * a);
    let expected = u(0.0) - u(0.7 * a);
    eprintln!(
        "measured: worn ball: crown to 0.7a {:.3} nm against u(0) − u(0.7a) = {:.3} nm of a uniform pressure ({:+.1} %); to the edge (2 − 4/π) p a / E* = {:.2} nm",
        crown * 1e9,
        expected * 1e9,
        100.0 * (crown / expected - 1.0),
        (2.0 - 4.0 / PI) * uniform * a / E_STAR * 1e9
    );
    assert!((crown / expected - 1.0).abs() < 0.1);
}

#[test]
fn halving_the_step_changes_the_scar_by_less_than_one_percent_and_half_as_much_again() {
    // Backward Euler is first order: 20, 40 and 80 steps over the same distance give scar
    // radii, peak pressures and deepest wear within 1 % of each other, the change from 40 to
    // 80 steps about half that from 20 to 40 (a ratio in 1.5..3 where the change is above
    // 1e-4), and the same worn volume to 1e-9.
    let (n, d, radius, load) = (80, 1.25e-6, 2e-3, 0.5);
    let heights = ball(n, d, radius);
    let p = problem(&heights, d, load, None);
    let law = Archard {
        coefficient_m2_per_n: 1e-14,
    };
    let last = |steps: usize| {
        run(
            &p,
            law,
            Schedule {
                distance_m: 0.15,
                steps,
            },
        )
        .pop()
        .expect("steps")
        .0
    };
    let runs = [last(20), last(40), last(80)];
    let measures = |s: &WearStep| {
        [
            contact_radius(&s.solution),
            s.solution.max_pressure_pa,
            s.max_wear_depth_m,
        ]
    };
    let [coarse, middle, fine] = [measures(&runs[0]), measures(&runs[1]), measures(&runs[2])];
    for (k, name) in ["scar radius", "peak pressure", "deepest wear"]
        .iter()
        .enumerate()
    {
        let first = coarse[k] / middle[k] - 1.0;
        let second = middle[k] / fine[k] - 1.0;
        eprintln!(
            "measured: {name}: 20 -> 40 steps {:+.3} %, 40 -> 80 steps {:+.3} %",
            100.0 * first,
            100.0 * second
        );
        assert!(first.abs() < 0.01 && second.abs() < 0.01, "{name}");
        if first.abs() > 1e-4 {
            let ratio = first / second;
            assert!((1.5..3.0).contains(&ratio), "{name}: ratio {ratio}");
        }
    }
    for run in &runs[..2] {
        assert!((run.worn_volume_m3 / runs[2].worn_volume_m3 - 1.0).abs() < 1e-9);
    }
}

#[test]
fn the_plastic_area_never_exceeds_the_load_over_the_hardness() {
    let (n, d, load, hardness) = (64, 1.5e-6, 0.3, 4e9);
    let heights = rough_ball(n, d, 2e-3, 0.15e-6);
    let p = problem(&heights, d, load, Some(hardness));
    let mut plastic_seen = false;
    for (step, _) in run(
        &p,
        Archard {
            coefficient_m2_per_n: 1e-14,
        },
        Schedule {
            distance_m: 0.05,
            steps: 6,
        },
    ) {
        let area = step.solution.plastic_cells as f64 * d * d;
        assert!(area <= load / hardness * (1.0 + 1e-12), "{area}");
        plastic_seen |= step.solution.plastic_cells > 0;
        assert!(step.plastic_volume_m3 >= 0.0);
    }
    assert!(plastic_seen, "the case should reach the cap");
}

#[test]
fn the_worn_surfaces_solved_again_give_the_same_pressures() {
    // Each step's pressure is the static contact of the surface it leaves (module doc): the
    // worn heights solved cold, one by one, give the same pressure within 1e-6 of its peak
    // (the solver's tolerance is 1e-8 on the pressure's change and the complementarity).
    let (n, d, load) = (64, 1.5e-6, 0.3);
    let heights = rough_ball(n, d, 2e-3, 0.1e-6);
    for hardness in [None, Some(4e9)] {
        let p = problem(&heights, d, load, hardness);
        let mut worst = 0.0f64;
        for (step, worn) in run(
            &p,
            Archard {
                coefficient_m2_per_n: 1e-14,
            },
            Schedule {
                distance_m: 0.05,
                steps: 5,
            },
        ) {
            let again = rough::solve(
                &RoughContactProblem {
                    heights_m: worn.view(),
                    ..p.clone()
                },
                &mut |_, _| {},
            )
            .expect("again");
            let peak = step.solution.max_pressure_pa;
            let difference = (&again.pressure_pa - &step.solution.pressure_pa)
                .iter()
                .fold(0.0f64, |m, v| m.max(v.abs()));
            worst = worst.max(difference / peak);
        }
        eprintln!("measured: worn surfaces solved again, hardness {hardness:?}: largest pressure difference {worst:.1e} of the peak");
        assert!(worst < 1e-6, "{worst}");
    }
}

#[test]
fn measured_wear_is_the_difference_less_the_unworn_cells_offset() {
    let first = Array2::from_shape_fn((10, 10), |(j, i)| (i as f64 - j as f64) * 1e-7);
    let mut now = first.mapv(|h| h + 3e-8);
    now[[4, 4]] -= 2e-7;
    now[[4, 5]] -= 1e-7;
    let (depth, offset) = measured_wear(&first, &now);
    assert!((offset + 3e-8).abs() < 1e-20);
    assert!((depth[[4, 4]] - 2e-7).abs() < 1e-20);
    assert!((depth[[4, 5]] - 1e-7).abs() < 1e-20);
    // Elsewhere only the rounding of the difference remains.
    assert_eq!(depth.iter().filter(|&&w| w > 1e-15).count(), 2);
    // A scar over 70 % of the map: the offset is still the unworn cells' (the median of all
    // differences would lie in the scar).
    let mut scarred = first.mapv(|h| h - 5e-8);
    for ((j, i), h) in scarred.indexed_iter_mut() {
        if j < 7 {
            *h -= 1e-7 * (1.0 + (i + j) as f64 / 20.0);
        }
    }
    let (depth, offset) = measured_wear(&first, &scarred);
    assert!((offset - 5e-8).abs() < 1e-15, "{offset}");
    assert!((depth[[0, 0]] - 1e-7).abs() < 1e-15);
    assert!(depth[[8, 3]] < 1e-15);
}

#[test]
fn bad_input_is_refused_naming_it() {
    let heights = ball(16, 1e-6, 1e-3);
    let p = problem(&heights, 1e-6, 0.1, None);
    let schedule = Schedule {
        distance_m: 1.0,
        steps: 2,
    };
    for k in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let error = Evolution::new(
            &p,
            Archard {
                coefficient_m2_per_n: k,
            },
            schedule,
        )
        .err()
        .expect("refused");
        assert!(error.to_string().contains("wear coefficient"), "{error}");
    }
    let law = Archard {
        coefficient_m2_per_n: 1e-14,
    };
    for distance in [0.0, -1.0] {
        let error = Evolution::new(
            &p,
            law,
            Schedule {
                distance_m: distance,
                steps: 2,
            },
        )
        .err()
        .expect("refused");
        assert!(error.to_string().contains("sliding distance"), "{error}");
    }
    // Worn through: a coefficient that removes more than the map holds above its lowest point.
    let error = Evolution::new(
        &p,
        Archard {
            coefficient_m2_per_n: 1e-3,
        },
        schedule,
    )
    .err()
    .expect("refused");
    assert!(matches!(error, WearError::TooMuchWear { .. }), "{error}");
    let capacity = capacity_m3(&heights, [1e-6, 1e-6]);
    // Just below the capacity is accepted, just above refused.
    for (factor, accepted) in [(0.99, true), (1.01, false)] {
        let k = factor * capacity / (0.1 * schedule.distance_m);
        let outcome = Evolution::new(
            &p,
            Archard {
                coefficient_m2_per_n: k,
            },
            schedule,
        );
        assert_eq!(outcome.is_ok(), accepted, "factor {factor}");
    }
}

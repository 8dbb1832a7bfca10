//! Tests of [`super`].

use super::*;

#[test]
fn spots_are_4_connected_and_wrap_when_periodic() {
    let mut p = Array2::zeros((5, 6));
    for at in [[0, 0], [0, 1], [1, 1], [3, 3], [4, 4], [2, 5]] {
        p[at] = 1.0;
    }
    // {00, 01, 11}, {33}, {44}, {25}: four; periodic: 25 touches 20? no (0 at [2,0]);
    // 44 wraps to 04? no; 00 wraps to 05 and 40: not loaded. Still four.
    assert_eq!(count_spots(&p, false), 4);
    assert_eq!(count_spots(&p, true), 4);
    p[[2, 0]] = 1.0;
    assert_eq!(count_spots(&p, false), 5);
    assert_eq!(
        count_spots(&p, true),
        4,
        "[2, 0] joins [2, 5] across the edge"
    );
}

/// A 32² periodic base (a gentle cosine bump, 4 nm) with one tall single-cell spike (30 nm),
/// 40 nm cells, steel on a rigid flat: the spike is the highest point.
fn spike_on_bump() -> Array2<f64> {
    let n = 32;
    let mut heights = Array2::from_shape_fn((n, n), |(j, i)| {
        let phase = 2.0 * std::f64::consts::PI / n as f64;
        2e-9 * ((phase * i as f64).cos() + (phase * j as f64).cos())
    });
    heights[[5, 7]] += 30e-9;
    heights
}

const SPIKE_E_STAR: f64 = 230.77e9;
const SPIKE_SPACING: f64 = 40e-9;

/// The iteration's settings for [`spike_on_bump`] under a cap.
fn spike_settings(heights: &Array2<f64>, hardness: f64) -> Settings {
    let separation_rms = {
        let mean = heights.mean().unwrap_or(0.0);
        (heights.mapv(|h| (h - mean).powi(2)).mean().unwrap_or(0.0)).sqrt()
    };
    Settings {
        hardness,
        gap_scale: separation_rms,
        tolerance: DEFAULT_TOLERANCE,
        max_iterations: 2000,
        own_compliance: crate::operator::elastic::uniform_patch_displacement(
            0.0,
            0.0,
            SPIKE_SPACING / 2.0,
            SPIKE_SPACING / 2.0,
        ) / (std::f64::consts::PI * SPIKE_E_STAR),
    }
}

/// Issue 22: an approach that reaches no cell, started from zero pressure, is solved by zero
/// pressure with residual 0 (it used to end with residual infinity, which broke the search).
#[test]
fn an_approach_that_reaches_no_cell_has_zero_pressure_and_residual() {
    let heights = spike_on_bump();
    let top = heights.iter().fold(f64::NEG_INFINITY, |m, &h| m.max(h));
    let separation = heights.mapv(|h| top - h);
    let mut elastic = ElasticOperator::new(
        [32, 32],
        [SPIKE_SPACING; 2],
        SPIKE_E_STAR,
        Periodicity::Periodic,
    )
    .expect("operator");
    let mut operator = Compliance {
        elastic: &mut elastic,
        local_m_per_pa: 0.0,
    };
    let mut pressure = Array2::zeros((32, 32));
    let mut state = State::new([32, 32]);
    let (_, residual) = iterate(
        &mut operator,
        &separation,
        &mut pressure,
        &mut state,
        Target::Approach(-1e-9),
        &spike_settings(&heights, 1e9),
        &mut |_, _| ControlFlow::Continue(()),
    )
    .expect("iterates");
    assert_eq!(residual, 0.0);
    assert!(pressure.iter().all(|&p| p == 0.0));
}

/// Issue 22, the cause: started from a pressure whose only loaded cell is at the cap and
/// penetrates while other cells penetrate unloaded, no cell takes a conjugate-gradient step.
/// The penetrating cells must still be loaded: the run ends where a run from the usual start
/// ends (it used to stop at once with residual 0, the spike alone carrying the load).
#[test]
fn cells_that_penetrate_enter_when_every_loaded_cell_is_at_the_cap() {
    let heights = spike_on_bump();
    let hardness = 2e9;
    // Deep enough to bring the bump's top (28 nm below the spike) into contact.
    let approach = 31e-9;
    let problem = RoughContactProblem {
        heights_m: heights.view(),
        spacing_m: [SPIKE_SPACING; 2],
        e_star_pa: SPIKE_E_STAR,
        periodicity: Periodicity::Periodic,
        control: Control::Approach { m: approach },
        hardness_pa: Some(hardness),
        tolerance: DEFAULT_TOLERANCE,
        max_iterations: 2000,
        memory_limit_bytes: 1 << 30,
    };
    let reference = solve(&problem, &mut |_, _| {}).expect("solves from its own start");
    assert!(
        reference.contact_fraction * 1024.0 > 5.0,
        "the bump is reached"
    );

    let top = heights.iter().fold(f64::NEG_INFINITY, |m, &h| m.max(h));
    let separation = heights.mapv(|h| top - h);
    let mut elastic = ElasticOperator::new(
        [32, 32],
        [SPIKE_SPACING; 2],
        SPIKE_E_STAR,
        Periodicity::Periodic,
    )
    .expect("operator");
    let mut operator = Compliance {
        elastic: &mut elastic,
        local_m_per_pa: 0.0,
    };
    let mut pressure = Array2::zeros((32, 32));
    pressure[[5, 7]] = hardness;
    let mut state = State::new([32, 32]);
    let (iterations, residual) = iterate(
        &mut operator,
        &separation,
        &mut pressure,
        &mut state,
        Target::Approach(approach),
        &spike_settings(&heights, hardness),
        &mut |_, _| ControlFlow::Continue(()),
    )
    .expect("iterates");
    let difference = (&pressure - &reference.pressure_pa)
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    eprintln!(
        "from the spike at the cap: {iterations} iterations, residual {residual:.1e}, {} cells loaded (reference {}), max |Δp| / H = {:.1e}",
        pressure.iter().filter(|&&p| p > 0.0).count(),
        reference.pressure_pa.iter().filter(|&&p| p > 0.0).count(),
        difference / hardness
    );
    assert!(residual < DEFAULT_TOLERANCE);
    assert!(pressure.iter().filter(|&&p| p > 0.0).count() > 1);
    assert!(difference < 1e-6 * hardness, "{difference}");
}

/// Issue 24, class 6: periodic and elastic, an approach at the mean separation closes the gap
/// everywhere. Just below it the solve converges with nearly full contact and a mean gap of
/// the mean separation less the approach; at it (and beyond) it is the full-contact error at
/// once, not thousands of diverging iterations.
#[test]
fn a_periodic_approach_that_closes_the_gap_is_full_contact() {
    let n = 16;
    let phase = 2.0 * std::f64::consts::PI / n as f64;
    let heights = Array2::from_shape_fn((n, n), |(j, i)| {
        1e-9 * ((phase * i as f64).cos() + (phase * j as f64).cos())
    });
    let top = heights.iter().fold(f64::NEG_INFINITY, |m, &v| m.max(v));
    let mean_separation = top - heights.mean().expect("mean");
    let problem = |m: f64| RoughContactProblem {
        heights_m: heights.view(),
        spacing_m: [SPIKE_SPACING; 2],
        e_star_pa: SPIKE_E_STAR,
        periodicity: Periodicity::Periodic,
        control: Control::Approach { m },
        hardness_pa: None,
        tolerance: DEFAULT_TOLERANCE,
        max_iterations: 2000,
        memory_limit_bytes: 1 << 30,
    };
    let below = solve(&problem(0.5 * mean_separation), &mut |_, _| {}).expect("converges");
    assert!(below.contact_fraction > 0.1 && below.contact_fraction < 1.0);
    // The mean gap is the mean separation less the approach (the mean displacement is zero).
    assert!(
        (below.mean_gap_m - 0.5 * mean_separation).abs() < 1e-6 * mean_separation,
        "{} against {}",
        below.mean_gap_m,
        0.5 * mean_separation
    );
    for factor in [1.0, 1.2] {
        let mut steps = 0;
        let error = solve(&problem(factor * mean_separation), &mut |_, _| steps += 1)
            .expect_err("full contact");
        assert!(
            matches!(error, RoughContactError::FullContact { .. }),
            "{error}"
        );
        assert_eq!(steps, 0, "refused before iterating");
    }
}

/// Issue 24, class 4: a periodic map more than 64 times longer than wide is refused before
/// anything is built (its kernel's images grow with the square of the longer side: 8 x 8192
/// cells took 44 s and 4.6 GB); at 64 it solves.
#[test]
fn a_periodic_map_far_longer_than_wide_is_refused() {
    let strip = |nx: usize| {
        Array2::from_shape_fn((4, nx), |(j, i)| {
            1e-9 * ((i as f64 * 0.7).sin() + (j as f64 * 1.3).cos())
        })
    };
    let problem = |heights: &Array2<f64>| {
        solve(
            &RoughContactProblem {
                heights_m: heights.view(),
                spacing_m: [SPIKE_SPACING; 2],
                e_star_pa: SPIKE_E_STAR,
                periodicity: Periodicity::Periodic,
                control: Control::MeanPressure { pa: 1e8 },
                hardness_pa: None,
                tolerance: DEFAULT_TOLERANCE,
                max_iterations: 2000,
                memory_limit_bytes: 1 << 30,
            },
            &mut |_, _| {},
        )
    };
    let error = problem(&strip(4 * 65)).expect_err("aspect 65");
    assert!(error.to_string().contains("at most 64"), "{error}");
    problem(&strip(4 * 64)).expect("aspect 64 solves");
}

/// Issue 50: a solve whose progress asks to stop (Ctrl-C in the Python package) ends at that
/// iteration with the `Interrupted` error, never a result; a progress that always goes on is
/// the plain solve, bit for bit. Elastic under a load and capped under a load (the search's
/// runs), both.
#[test]
fn a_solve_asked_to_stop_is_an_error_not_a_result() {
    let heights = spike_on_bump();
    for hardness_pa in [None, Some(4e9)] {
        let problem = RoughContactProblem {
            heights_m: heights.view(),
            spacing_m: [SPIKE_SPACING; 2],
            e_star_pa: SPIKE_E_STAR,
            periodicity: Periodicity::Periodic,
            control: Control::MeanPressure { pa: 2e8 },
            hardness_pa,
            tolerance: DEFAULT_TOLERANCE,
            max_iterations: 2000,
            memory_limit_bytes: 1 << 30,
        };
        let plain = solve(&problem, &mut |_, _| {}).expect("solves");
        assert!(plain.iterations > 3, "{} iterations", plain.iterations);
        let going_on = solve_interruptible(
            &problem,
            &Warm::default(),
            &mut OperatorCache::default(),
            &mut |_, _| ControlFlow::Continue(()),
        )
        .expect("solves");
        assert_eq!(going_on, plain);
        let mut asked = 0;
        let error = solve_interruptible(
            &problem,
            &Warm::default(),
            &mut OperatorCache::default(),
            &mut |iteration, _| {
                asked += 1;
                if iteration == 3 {
                    ControlFlow::Break(())
                } else {
                    ControlFlow::Continue(())
                }
            },
        )
        .expect_err("stopped");
        assert!(
            matches!(error, RoughContactError::Interrupted { iterations: 3, .. }),
            "{error}"
        );
        assert_eq!(asked, 3, "no iteration after the stop");
        assert!(
            error.to_string().contains("interrupted after 3 iterations"),
            "{error}"
        );
    }
}

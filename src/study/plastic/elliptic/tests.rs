//! Checks of the elastic-plastic elliptical contact against Hertz's ellipse, the elliptical
//! Hertz field's first yield and the ball (docs/plasticity.md states each tolerance with the
//! measured error).

use super::*;
use crate::contact::elliptic::RelativeCurvature;
use crate::contact::material::Material;
use crate::plasticity::loading::largest;
use crate::solution::point_numerical::PointTractions;
use crate::study::plastic::study_point;

const MODULUS: f64 = 210e9;
const POISSON: f64 = 0.3;
const YIELD: f64 = 1e9;

fn spec(steps: usize, unload_steps: usize, cells: usize, depth_cells: usize) -> PlasticitySpec {
    PlasticitySpec {
        yield_strength_pa: YIELD,
        hardening_modulus_pa: 0.0,
        unload: unload_steps > 0,
        steps,
        unload_steps: unload_steps.max(1),
        grid_cells: cells,
        depth_cells,
        extent_over_a: 1.5,
        depth_over_a: 1.5,
        tolerance: 1e-7,
        body1: Material {
            modulus_pa: MODULUS,
            poisson: POISSON,
        },
        counter_rigid: true,
    }
}

/// A rigid body of principal radii `radius_x_m`, `radius_y_m` on the steel flat at Hertz's
/// peak pressure `p0_over_y` Y.
fn ellipse(radius_x_m: f64, radius_y_m: f64, p0_over_y: f64) -> EllipticalContact {
    let e_star = MODULUS / (1.0 - POISSON * POISSON);
    let curvature = RelativeCurvature::from_radii(radius_x_m, radius_y_m).expect("curvature");
    let unit = EllipticalContact::from_curvatures(curvature, e_star, 1.0).expect("ellipse");
    let load = unit.load_for_peak_pressure(p0_over_y * YIELD);
    EllipticalContact::from_curvatures(curvature, e_star, load).expect("ellipse")
}

/// The largest von Mises stress over p0 of Hertz's elliptical pressure (semi-axes 1 and
/// `b_over_a`), on the axis (frictionless, its maximum is there by symmetry): the pressure
/// as means over 160 x 160 cells across the ellipse, its stress summed exactly over the
/// cells ([`PointTractions::stress_over_p0`]) and maximised over depth by a golden-section
/// search between 0.2 and 1.2 of the smaller semi-axis.
fn hertz_ellipse_axis_maximum(b_over_a: f64) -> f64 {
    let tractions =
        PointTractions::hertz_ellipse(160, 1.0, b_over_a, 0.0, POISSON).expect("tractions");
    let minor = b_over_a.min(1.0);
    let f = |z: f64| tractions.stress_over_p0(0.0, 0.0, z * minor).von_mises();
    let (mut lo, mut hi) = (0.2, 1.2);
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..50 {
        let (c, d) = (hi - ratio * (hi - lo), lo + ratio * (hi - lo));
        if f(c) > f(d) {
            hi = d;
        } else {
            lo = c;
        }
    }
    f(0.5 * (lo + hi))
}

#[test]
fn below_first_yield_the_ellipse_is_hertz_s() {
    // Radii 40 mm along x and 10 mm along y: a/b = 2.50 (Johnson 1985, §4.2).
    let hertz = ellipse(40e-3, 10e-3, 1.2);
    let (a, b) = (hertz.semi_axis_x_m, hertz.semi_axis_y_m);
    assert!(a / b > 2.45 && a / b < 2.55, "a/b = {}", a / b);
    let spec = spec(1, 1, 32, 12);
    let study = study_elliptical(&spec, &hertz, 0.0, &mut |_| {}).expect("solves");
    assert_eq!(study.loaded.max_plastic_strain, 0.0);
    assert_eq!(study.loaded.plastic_volume_m3, 0.0);
    let unloaded = study.unloaded.expect("unloaded");
    assert_eq!(unloaded.residual_depth_m, 0.0);
    assert_eq!(unloaded.residual_von_mises_max_pa, 0.0);
    // The grid's error at a/10.7 and b/10.7 per cell: the peak pressure and the approach to
    // 2 %, the area (whole cells) to 4 %.
    let loaded = &study.loaded;
    let p_error = loaded.max_pressure_pa / hertz.p0_pa - 1.0;
    let delta_error = loaded.approach_m / hertz.approach_m - 1.0;
    let area_error = loaded.contact_area_m2 / (std::f64::consts::PI * a * b) - 1.0;
    assert!(p_error.abs() < 0.02, "peak pressure {p_error:e}");
    assert!(delta_error.abs() < 0.02, "approach {delta_error:e}");
    assert!(area_error.abs() < 0.04, "area {area_error:e}");
    // The reported radius is the area's √(A/π), beside the circle √(ab) of the same area.
    assert_relative_eq_ratio(
        loaded.contact_radius_m,
        (loaded.contact_area_m2 / std::f64::consts::PI).sqrt(),
        1e-12,
    );
    assert_relative_eq_ratio(study.hertz.size_m(), (a * b).sqrt(), 1e-12);
    assert_relative_eq_ratio(study.hertz.p0_pa(), hertz.p0_pa, 1e-12);
}

fn assert_relative_eq_ratio(value: f64, reference: f64, tolerance: f64) {
    assert!(
        (value / reference - 1.0).abs() < tolerance,
        "{value} vs {reference}"
    );
}

#[test]
fn first_yield_is_where_the_elliptical_hertz_field_reaches_the_yield_strength() {
    // Radii 20 mm along x, 10 mm along y: b/a = 0.64.
    let reference = ellipse(20e-3, 10e-3, 1.0);
    let b_over_a = reference.semi_axis_y_m / reference.semi_axis_x_m;
    let ratio = hertz_ellipse_axis_maximum(b_over_a);
    // Between the ball's 0.620 and the line's 0.5575 (ν = 0.3; Johnson 1985, §6.2).
    assert!(ratio < 0.622 && ratio > 0.5575, "σvM max / p0 = {ratio}");
    // The grid: cells of a/20 and b/20, layers of b/20 from the surface (as the ball's check).
    let mut near = spec(1, 0, 48, 18);
    near.extent_over_a = 1.2;
    near.depth_over_a = 0.9;
    for (factor, plastic) in [(0.995, false), (1.005, true)] {
        let hertz = ellipse(20e-3, 10e-3, factor / ratio);
        let study = study_elliptical(&near, &hertz, 0.0, &mut |_| {}).expect("solves");
        let strain = largest(&study.loaded_snapshot().equivalent_plastic_strain).0;
        assert_eq!(
            strain > 0.0,
            plastic,
            "at {factor} of the first yield (p0 = {:.4} Y): {strain:e}",
            factor / ratio
        );
    }
}

#[test]
fn an_ellipse_with_equal_axes_is_the_ball() {
    // Radii 10 mm and 10.002 mm: a/b = 1 + 1e-4 or so.
    let hertz_ellipse = ellipse(10.002e-3, 10e-3, 2.5);
    let ratio = hertz_ellipse.semi_axis_x_m / hertz_ellipse.semi_axis_y_m;
    assert!(ratio > 1.0 && ratio < 1.001, "a/b = {ratio}");
    let e_star = MODULUS / (1.0 - POISSON * POISSON);
    let ball = PointContact::from_effective(hertz_ellipse.load_n, e_star, 10e-3);
    let spec = spec(2, 1, 24, 10);
    let elliptical = study_elliptical(&spec, &hertz_ellipse, 0.0, &mut |_| {}).expect("solves");
    let point = study_point(&spec, &ball, 0.0, &mut |_| {}).expect("solves");
    let (e, p) = (&elliptical.loaded, &point.loaded);
    assert!(
        p.max_plastic_strain > 1e-4,
        "plastic: {}",
        p.max_plastic_strain
    );
    for (what, x, y) in [
        ("peak pressure", e.max_pressure_pa, p.max_pressure_pa),
        ("approach", e.approach_m, p.approach_m),
        (
            "max plastic strain",
            e.max_plastic_strain,
            p.max_plastic_strain,
        ),
        ("plastic volume", e.plastic_volume_m3, p.plastic_volume_m3),
        ("von Mises max", e.von_mises_max_pa, p.von_mises_max_pa),
        (
            "dent",
            elliptical
                .unloaded
                .as_ref()
                .expect("unloaded")
                .residual_depth_m,
            point.unloaded.as_ref().expect("unloaded").residual_depth_m,
        ),
    ] {
        assert!((x / y - 1.0).abs() < 2e-3, "{what}: {x} vs {y}");
    }
}

//! Tests of the coated point study ([`super`]).

use super::*;
use crate::report::coated::CoatedReport;

/// A 12.7 mm steel ball on a coated steel flat (5 N), with `coating` lines in the coating
/// table and `extra` appended.
fn scene_text(coating: &str, extra: &str) -> String {
    format!(
        "format = 1\n[contact]\nkind = \"point\"\nload = \"5 N\"\nfriction = 0.1\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body1.coating]\n{coating}\n[contact.body2]\nradius = \"6.35 mm\"\nmaterial = \"steel\"\n{extra}"
    )
}

fn error_of(text: &str) -> String {
    match Scene::parse(text, "test", "test.toml") {
        Ok(_) => panic!("accepted: {text}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn bad_coatings_are_refused_by_key() {
    for (text, key) in [
        (
            scene_text("thickness = \"-2 um\"\nmaterial = \"boron_carbide\"", ""),
            "contact.body1.coating.thickness",
        ),
        (
            scene_text("thickness = \"0 um\"\nmaterial = \"boron_carbide\"", ""),
            "contact.body1.coating.thickness",
        ),
        (
            scene_text("material = \"boron_carbide\"", ""),
            "contact.body1.coating.thickness",
        ),
        (
            scene_text("thickness = \"2 um\"", ""),
            "contact.body1.coating.modulus",
        ),
        (
            scene_text(
                "thickness = \"2 um\"\nmaterial = \"boron_carbide\"\ncolour = 1",
                "",
            ),
            "colour",
        ),
        (
            scene_text(
                "thickness = \"2 um\"\nmaterial = \"boron_carbide\"",
                "[contact.body2.coating]\nthickness = \"1 um\"\nmaterial = \"steel\"\n",
            ),
            "contact.body2",
        ),
        (
            scene_text(
                "thickness = \"2 um\"\nmaterial = \"boron_carbide\"",
                "[thermal]\nspeed = \"1 m/s\"\n",
            ),
            "thermal",
        ),
    ] {
        let message = error_of(&text);
        assert!(message.contains(key), "{key}: {message}");
    }
    // A coating on a line contact is taken, with numerical.extent; on body 2 only refused.
    let line = scene_text(
        "thickness = \"2 um\"\nmaterial = \"boron_carbide\"",
        "[numerical]\nextent = 3\n",
    )
    .replace("kind = \"point\"", "kind = \"line\"")
    .replace("load = \"5 N\"", "load = \"5 kN/m\"");
    let scene = Scene::parse(&line, "test", "test.toml").expect("a coated line contact");
    assert_eq!(scene.numerical.extent_over_a, 3.0);
    let body2_only = "format = 1\n[contact]\nkind = \"point\"\nload = \"5 N\"\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"6.35 mm\"\nmaterial = \"steel\"\n[contact.body2.coating]\nthickness = \"1 um\"\nmaterial = \"boron_carbide\"\n";
    let message = error_of(body2_only);
    assert!(message.contains("contact.body2.coating"), "{message}");
    // A rigid counter-body is taken in a coated scene, and refused in an uncoated one.
    let rigid = scene_text("thickness = \"20 um\"\nmaterial = \"boron_carbide\"", "").replace(
        "radius = \"6.35 mm\"\nmaterial = \"steel\"",
        "radius = \"6.35 mm\"\nmaterial = \"rigid\"",
    );
    let scene = Scene::parse(&rigid, "test", "test.toml").expect("rigid counter-body");
    assert!(scene.contact.coating.is_some_and(|c| c.counter_rigid));
}

#[test]
fn a_grid_too_coarse_for_the_coating_names_the_cells_needed() {
    let text = scene_text(
        "thickness = \"0.5 um\"\nmaterial = \"boron_carbide\"",
        "[numerical]\ncells = 64\n",
    );
    let scene = Scene::parse(&text, "test", "test.toml").expect("valid");
    let message = solve(&scene).expect_err("too coarse").to_string();
    assert!(message.starts_with("numerical.cells"), "{message}");
    assert!(message.contains("at least 859"), "{message}");
}

#[test]
fn a_thick_coating_gives_the_coatings_hertz_contact_and_the_json_has_its_keys() {
    // h = 20 a: the coating's Hertz contact (p0 and a to the grid's resolution).
    let text = scene_text(
        "thickness = \"1 mm\"\nmaterial = \"boron_carbide\"",
        "[numerical]\ncells = 96\n",
    );
    let scene = Scene::parse(&text, "test", "test.toml").expect("valid");
    let study = solve(&scene).expect("solve");
    let (a, p0) = (study.hertz_semi_axes_m[0], study.hertz_p0_pa);
    let (ep, ea) = (
        study.solution.max_pressure_pa() / p0 - 1.0,
        study.contact_radius_m / a - 1.0,
    );
    eprintln!("measured: h = 20a, against the coating's Hertz contact: peak pressure {:+.2} %, radius {:+.2} %", 100.0 * ep, 100.0 * ea);
    assert!(ep.abs() < 0.01 && ea.abs() < 0.02, "{ep} {ea}");
    // The stress maximum is the homogeneous sliding sphere's (Hamilton, ν = 0.17, μ = 0.1),
    // searched on the plane y = 0 at steps of a/200.
    let mut hamilton: f64 = 0.0;
    for i in 0..=400 {
        for k in 0..=300 {
            let (x, z) = (-1.0 + i as f64 / 200.0, k as f64 / 200.0);
            let s = crate::solution::sphere_hertz::stress_over_p0(x, 0.0, z, 0.1, 0.17);
            hamilton = hamilton.max(s.von_mises());
        }
    }
    let von_mises = study.maxima.von_mises.value_pa / p0;
    eprintln!(
        "measured: h = 20a, von Mises maximum {von_mises:.4} p0 against Hamilton's {hamilton:.4} p0: {:+.2} %",
        100.0 * (von_mises / hamilton - 1.0)
    );
    assert!((von_mises / hamilton - 1.0).abs() < 0.02);
    // The surface's largest σxx, at the trailing edge (a kink between two cells, taken at the
    // edge): Hamilton's on the surface at steps of a/1000 (measured -0.64 %).
    let hamilton_surface = (0..=4000)
        .map(|i| {
            let x = -2.0 + i as f64 / 1000.0;
            crate::solution::sphere_hertz::stress_over_p0(x, 0.0, 0.0, 0.1, 0.17).xx
        })
        .fold(f64::NEG_INFINITY, f64::max);
    let surface = study.maxima.surface_tension;
    eprintln!(
        "measured: h = 20a, surface σxx maximum {:.4} p0 at x = {:.3} a against Hamilton's {hamilton_surface:.4} p0: {:+.2} %",
        surface.value_pa / p0,
        surface.x_m / a,
        100.0 * (surface.value_pa / p0 / hamilton_surface - 1.0)
    );
    assert!((surface.value_pa / p0 / hamilton_surface - 1.0).abs() < 0.03);
    assert!((surface.x_m / a + 1.0).abs() < 0.03, "{}", surface.x_m / a);
    let json = CoatedReport::new(&study).json_fields();
    for key in [
        "max_pressure_pa",
        "contact_radius_m",
        "contact_area_m2",
        "approach_m",
        "von_mises_max_pa",
        "von_mises_max_depth_m",
    ] {
        assert!(json[key].as_f64().is_some_and(f64::is_finite), "{key}");
    }
    let coating = CoatedReport::new(&study).json();
    for key in [
        "thickness_m",
        "von_mises_max_pa",
        "interface_shear_max_pa",
        "interface_normal_min_pa",
        "substrate_von_mises_max_pa",
    ] {
        assert!(coating[key].as_f64().is_some_and(f64::is_finite), "{key}");
    }
    assert_eq!(coating["thickness_m"].as_f64(), Some(1e-3));
    assert_eq!(json["coating"], coating);
}

/// A 20 mm steel roller on a coated steel flat, 100 kN/m, μ = 0.1.
fn line_scene(coating: &str, extra: &str) -> Scene {
    let text = format!(
        "format = 1\n[contact]\nkind = \"line\"\nload = \"100 kN/m\"\nfriction = 0.1\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body1.coating]\n{coating}\n[contact.body2]\nradius = \"10 mm\"\nmaterial = \"steel\"\n{extra}"
    );
    Scene::parse(&text, "test", "test.toml").expect("valid")
}

#[test]
fn a_thick_coating_on_a_line_contact_gives_the_coatings_hertz_and_mcewens_maximum() {
    // h = 220 b (B4C on steel): the coating's Hertz line contact and McEwen's largest von
    // Mises stress (ν = 0.17, μ = 0.1), the line JSON's keys. (A line load's stresses
    // fall as 1/r: at h = 22 b the steel under the B4C still raises the surface von Mises
    // stress by 0.96 %, at 220 b by 0.1 %.)
    let scene = line_scene(
        "thickness = \"20 mm\"\nmaterial = \"boron_carbide\"",
        "[numerical]\ncells = 400\n",
    );
    let study = solve(&scene).expect("solve");
    let (b, p0) = (study.hertz_semi_axes_m[0], study.hertz_p0_pa);
    let (ep, eb) = (
        study.solution.max_pressure_pa() / p0 - 1.0,
        study.semi_axes_m[0] / b - 1.0,
    );
    let mut mcewen: f64 = 0.0;
    for i in 0..=400 {
        for k in 0..=300 {
            let (x, z) = (-1.0 + i as f64 / 200.0, k as f64 / 200.0);
            let s = crate::solution::line_hertz::stress_over_p0(x, z, 0.1, 0.17);
            mcewen = mcewen.max(s.von_mises());
        }
    }
    let von_mises = study.maxima.von_mises.value_pa / p0;
    eprintln!(
        "measured: line, h = 220b: against the coating's Hertz, peak {:+.3} %, half-width {:+.3} %; von Mises maximum {von_mises:.4} p0 against McEwen's {mcewen:.4} p0: {:+.2} %",
        100.0 * ep,
        100.0 * eb,
        100.0 * (von_mises / mcewen - 1.0)
    );
    assert!(ep.abs() < 3e-3 && eb.abs() < 5e-3, "{ep} {eb}");
    assert!((von_mises / mcewen - 1.0).abs() < 0.005);
    // The surface's largest σxx: 2 μ p0 at the trailing edge (McEwen; a kink between two
    // strips, taken at the edge; measured -1.60 %: beyond the edge the friction's part rises
    // as a square root, which the edge's parabola rounds off).
    let surface = study.maxima.surface_tension;
    eprintln!(
        "measured: line, h = 220b, surface σxx maximum {:.4} p0 at x = {:.4} b against McEwen's 2 μ p0 = 0.2 p0 at -b: {:+.2} %",
        surface.value_pa / p0,
        surface.x_m / b,
        100.0 * (surface.value_pa / p0 / 0.2 - 1.0)
    );
    assert!((surface.value_pa / p0 / 0.2 - 1.0).abs() < 0.025);
    assert!((surface.x_m / b + 1.0).abs() < 0.01, "{}", surface.x_m / b);
    let json = CoatedReport::new(&study).json_fields();
    assert!(json["half_width_m"]
        .as_f64()
        .is_some_and(|w| (w / study.semi_axes_m[0] - 1.0).abs() < 1e-15));
    assert!(json["approach_m"].is_null());
    assert!(json.get("contact_area_m2").is_none() && json.get("contact_radius_m").is_none());
    for key in [
        "max_pressure_pa",
        "von_mises_max_pa",
        "von_mises_max_depth_m",
    ] {
        assert!(json[key].as_f64().is_some_and(f64::is_finite), "{key}");
    }
    assert_eq!(json["coating"]["thickness_m"].as_f64(), Some(20e-3));
}

#[test]
fn a_coated_line_grid_too_coarse_names_the_cells_needed() {
    let scene = line_scene(
        "thickness = \"0.5 um\"\nmaterial = \"boron_carbide\"",
        "[numerical]\ncells = 100\n",
    );
    let message = solve(&scene).expect_err("too coarse").to_string();
    assert!(message.starts_with("numerical.cells"), "{message}");
    assert!(message.contains("at least"), "{message}");
}

#[test]
fn a_thickness_sweep_is_validated_by_key() {
    let sweep = "[figure]\nlength_unit = \"um\"\n[sweep]\nparameter = \"coating_thickness\"\nfrom = 2\nto = 100\nsteps = 4\n";
    // Uncoated: the sweep needs a coating.
    let plain = "format = 1\n[contact]\nkind = \"line\"\nload = \"100 kN/m\"\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"10 mm\"\nmaterial = \"steel\"\n".to_string() + sweep;
    assert!(error_of(&plain).contains("sweep.parameter"));
    // Coated, another parameter: refused by key.
    let friction = scene_text(
        "thickness = \"10 um\"\nmaterial = \"boron_carbide\"",
        "[sweep]\nparameter = \"friction\"\nvalues = [0.0, 0.1]\n",
    );
    assert!(error_of(&friction).contains("sweep.parameter"));
    // A thinnest coating the grid cannot resolve names sweep.from and numerical.cells.
    let thin = scene_text(
        "thickness = \"10 um\"\nmaterial = \"boron_carbide\"",
        &sweep.replace("from = 2", "from = 0.5"),
    );
    let message = error_of(&thin);
    assert!(
        message.contains("sweep.from") && message.contains("numerical.cells to at least"),
        "{message}"
    );
    // Values with units are taken.
    let listed = scene_text(
        "thickness = \"10 um\"\nmaterial = \"boron_carbide\"",
        "[sweep]\nparameter = \"coating_thickness\"\nvalues = [\"5 um\", \"0.02 mm\"]\n",
    );
    let scene = Scene::parse(&listed, "test", "test.toml").expect("valid");
    let values = scene.sweep.map(|s| s.values).unwrap_or_default();
    assert_eq!(values.len(), 2);
    assert!((values[0] / 5e-6 - 1.0).abs() < 1e-12 && (values[1] / 2e-5 - 1.0).abs() < 1e-12);
}

#[test]
fn the_maximum_travels_from_the_substrate_into_a_thickening_hard_coating() {
    // The frictionless ball on B4C-coated steel (a = 53.7 µm), h = 4, 32 and 256 µm on 128
    // cells: the largest von Mises stress lies in the steel under the thin coating, on the
    // interface's coating side under the middle one and inside the thick coating.
    let text = scene_text(
        "thickness = \"10 um\"\nmaterial = \"boron_carbide\"",
        "[figure]\nlength_unit = \"um\"\n[sweep]\nparameter = \"coating_thickness\"\nfrom = 4\nto = 256\nsteps = 3\n[numerical]\ncells = 128\n",
    )
    .replace("friction = 0.1", "friction = 0.0");
    let scene = Scene::parse(&text, "test", "test.toml").expect("valid");
    let studies = sweep(&scene, &mut |_, _| {}).expect("sweep");
    let depth_over_h: Vec<f64> = studies
        .iter()
        .map(|s| s.maxima.von_mises.z_m / s.spec.thickness_m)
        .collect();
    eprintln!(
        "measured: thickness sweep 4, 32, 256 µm: depth of the maximum over h {depth_over_h:?}"
    );
    assert_eq!(studies.len(), 3);
    assert!(depth_over_h[0] > 1.0, "{depth_over_h:?}");
    assert!((depth_over_h[1] - 1.0).abs() < 1e-12, "{depth_over_h:?}");
    assert!(depth_over_h[2] < 1.0, "{depth_over_h:?}");
}

#[test]
fn a_coating_many_contacts_thick_is_sampled_at_the_contacts_depth() {
    // PEEK 100 mm on steel under a steel roller: h = 180 b. The largest von Mises stress is
    // the coating's own line contact's, McEwen's (ν = 0.38, μ = 0.1) at about 0.7 b below the
    // surface; depths spread evenly over h (3.75 b apart) missed it and reported the
    // surface's 0.30 p0 in place of 0.54 p0.
    let scene = line_scene(
        "thickness = \"100 mm\"\nmodulus = \"3.6 GPa\"\npoisson = 0.38",
        "[numerical]\ncells = 400\n",
    );
    let study = solve(&scene).expect("solve");
    let (b, p0) = (study.hertz_semi_axes_m[0], study.hertz_p0_pa);
    let (mut mcewen, mut depth): (f64, f64) = (0.0, 0.0);
    for i in 0..=400 {
        for k in 0..=300 {
            let (x, z) = (-1.0 + i as f64 / 200.0, k as f64 / 200.0);
            let vm = crate::solution::line_hertz::stress_over_p0(x, z, 0.1, 0.38).von_mises();
            if vm > mcewen {
                (mcewen, depth) = (vm, z);
            }
        }
    }
    let found = study.maxima.von_mises;
    eprintln!(
        "measured: line, PEEK h = 180b: von Mises maximum {:.4} p0 at z = {:.3} b against McEwen's {mcewen:.4} p0 at {depth:.3} b: {:+.2} %",
        found.value_pa / p0,
        found.z_m / b,
        100.0 * (found.value_pa / p0 / mcewen - 1.0)
    );
    assert!((found.value_pa / p0 / mcewen - 1.0).abs() < 0.01);
    assert!((found.z_m / b - depth).abs() < 0.1);
}

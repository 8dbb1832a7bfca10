use super::*;
use crate::scene::Scene;

/// A steel roller (R = 10 mm) on a flat of `substrate` under `layers` (TOML of
/// `[[contact.body1.layers]]` tables), 20 kN/m, `strips` strips over ±2 b.
fn line_scene(layers: &str, substrate: &str, strips: usize) -> String {
    format!(
        "format = 1\n[contact]\nkind = \"line\"\nload = \"20 kN/m\"\n[contact.body1]\nradius = \"flat\"\n{substrate}\n{layers}\n[contact.body2]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[numerical]\ncells = {strips}\nextent = 2\n"
    )
}

fn parse(text: &str) -> Scene {
    Scene::parse(text, "test", "test.toml").expect("a valid layered scene")
}

fn refusal(text: &str) -> String {
    match Scene::parse(text, "test", "test.toml") {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn two_layers_of_one_material_solve_as_one_coating() {
    let two = parse(&line_scene(
        "[[contact.body1.layers]]\nthickness = \"20 um\"\nmodulus = \"450 GPa\"\npoisson = 0.17\n[[contact.body1.layers]]\nthickness = \"30 um\"\nmodulus = \"450 GPa\"\npoisson = 0.17\n",
        "material = \"aluminium\"",
        400,
    ));
    let one = parse(&line_scene(
        "[contact.body1.coating]\nthickness = \"50 um\"\nmodulus = \"450 GPa\"\npoisson = 0.17\n",
        "material = \"aluminium\"",
        400,
    ));
    // The grid follows the top layer's Hertz contact (the same material) and both scenes'
    // cells fit 20 µm.
    let (a, b) = (
        super::super::coated::solve(&two).expect("solves"),
        super::super::coated::solve(&one).expect("solves"),
    );
    let peak = (a.solution.max_pressure_pa() / b.solution.max_pressure_pa() - 1.0).abs();
    let substrate =
        (a.maxima.substrate_von_mises.value_pa / b.maxima.substrate_von_mises.value_pa - 1.0).abs();
    let shear =
        (a.layers[1].interface_shear.value_pa / b.layers[0].interface_shear.value_pa - 1.0).abs();
    eprintln!("two B4C layers against one: peak {peak:.2e}, substrate σvM {substrate:.2e}, interface shear {shear:.2e}");
    // Not round-off: the kernel's split takes the top layer's thickness as its far term's
    // `c` (20 against 50 µm), so the sampled remainders differ (the waves themselves agree to
    // 4.4e-15, `crate::coating::stack_tests`).
    assert!(peak < 2e-5 && substrate < 2e-5 && shear < 2e-5);
    assert_eq!(a.layers.len(), 2);
    assert!((a.layers[0].thickness_m - 20e-6).abs() < 1e-18);
}

#[test]
fn equal_moduli_give_hertz_and_its_scaling_for_the_first_failure() {
    // Steel on steel under two "layers" of steel: the homogeneous Hertz line contact. Its
    // von Mises maximum, found here from McEwen's closed form (ν = 0.3, frictionless), over
    // the layer's yield strength is the utilisation; p0 grows as sqrt(W), so the first
    // failure is at W / U² (the hand calculation).
    let text = line_scene(
        "[[contact.body1.layers]]\nthickness = \"100 um\"\nmaterial = \"steel\"\nyield_strength = \"300 MPa\"\n[[contact.body1.layers]]\nthickness = \"400 um\"\nmaterial = \"steel\"\n",
        "material = \"steel\"\nyield_strength = \"1 GPa\"",
        400,
    );
    let scene = parse(&text);
    let study = super::super::coated::solve(&scene).expect("solves");
    let mut closed = 0.0_f64;
    for i in 0..=400 {
        let z = 0.4 + 0.6 * i as f64 / 400.0;
        closed =
            closed.max(crate::solution::line_hertz::stress_over_p0(0.0, z, 0.0, 0.3).von_mises());
    }
    let list = utilisation(&study);
    assert_eq!(list.len(), 2);
    assert_eq!(
        (list[0].place.as_str(), list[0].mode),
        ("layer 1", Mode::Yield)
    );
    assert_eq!(
        (list[1].place.as_str(), list[1].mode),
        ("substrate", Mode::Yield)
    );
    let expected = closed * study.hertz_p0_pa / 300e6;
    let error = list[0].value / expected - 1.0;
    let failure = first_failure(&scene, &study)
        .expect("solves")
        .expect("a failure");
    let load_error = failure.load_n / (study.load_n * list[0].value.powi(-2)) - 1.0;
    eprintln!(
        "steel layers: utilisation {:.4} against the closed form {expected:.4} ({error:+.2e}); first failure {:.1} N/m, {load_error:+.2e} from W/U², {} solves, check {:.5}",
        list[0].value, failure.load_n, failure.solves, failure.check
    );
    assert!(error.abs() < 3e-3, "{error}");
    assert!(load_error.abs() < 1e-3, "{load_error}");
    assert_eq!(
        (failure.place.as_str(), failure.mode),
        ("layer 1", Mode::Yield)
    );
}

#[test]
fn the_first_failure_of_a_stack_is_its_load_to_one_percent() {
    // DLC on Cr on steel, a soft substrate yield given low enough to compete.
    let text = line_scene(
        "[[contact.body1.layers]]\nthickness = \"20 um\"\nmodulus = \"150 GPa\"\npoisson = 0.2\ntensile_strength = \"400 MPa\"\n[[contact.body1.layers]]\nthickness = \"10 um\"\nmodulus = \"279 GPa\"\npoisson = 0.21\nyield_strength = \"350 MPa\"\nadhesion_strength = \"200 MPa\"\n",
        "material = \"steel\"\nyield_strength = \"400 MPa\"",
        300,
    );
    let scene = parse(&text);
    let study = super::super::coated::solve(&scene).expect("solves");
    let failure = first_failure(&scene, &study)
        .expect("solves")
        .expect("a failure");
    let again = scene.contact.with_load(failure.load_n).expect("a load");
    let mut at = scene.clone();
    at.contact = again;
    let resolved = super::super::coated::solve(&at).expect("solves");
    let list = utilisation(&resolved);
    let top = list.iter().map(|u| u.value).fold(f64::MIN, f64::max);
    eprintln!(
        "DLC/Cr/steel: first failure {} {} at {:.1} N/m ({} solves), the solve there gives {top:.5}; at the scene's load {:?}",
        failure.place,
        failure.mode.key(),
        failure.load_n,
        failure.solves,
        utilisation(&study).iter().map(|u| (u.place.clone(), u.value)).collect::<Vec<_>>()
    );
    assert!((top - 1.0).abs() < 1e-2, "{top}");
    // The JSON contract of issue 53.
    let mut reported = study.clone();
    reported.first_failure = Some(failure.clone());
    let json = crate::report::coated::CoatedReport::new(&reported).json_fields();
    assert!(json.get("coating").is_none());
    let layers = json["layers"].as_array().expect("layers");
    assert_eq!(layers.len(), 2);
    for key in [
        "thickness_m",
        "von_mises_max_pa",
        "max_tension_pa",
        "interface_shear_max_pa",
        "interface_normal_min_pa",
    ] {
        assert!(layers[1][key].is_f64(), "{key}");
    }
    assert!((layers[1]["thickness_m"].as_f64().unwrap_or(0.0) - 10e-6).abs() < 1e-18);
    assert!(json["substrate_von_mises_max_pa"].is_f64());
    let entries = json["utilisation"].as_array().expect("utilisation");
    let places: Vec<(&str, &str)> = entries
        .iter()
        .map(|e| {
            (
                e["where"].as_str().unwrap_or(""),
                e["mode"].as_str().unwrap_or(""),
            )
        })
        .collect();
    assert_eq!(
        places,
        [
            ("layer 1", "fracture"),
            ("layer 2", "yield"),
            ("interface 2", "delamination"),
            ("substrate", "yield")
        ]
    );
    assert!(entries
        .iter()
        .all(|e| e["value"].is_f64() && e["x_m"].is_f64() && e["z_m"].is_f64()));
    let first = &json["first_failure"];
    assert_eq!(first["where"], failure.place.as_str());
    assert_eq!(first["mode"], failure.mode.key());
    assert_eq!(first["load_n_per_m"].as_f64(), Some(failure.load_n));
    assert!(first.get("load_n").is_none());
}

#[test]
fn a_stack_is_refused_by_key_where_it_is_not_computed() {
    let layer = "[[contact.body1.layers]]\nthickness = \"20 um\"\nmaterial = \"steel\"\n";
    let both = refusal(&line_scene(
        &format!("{layer}[contact.body1.coating]\nthickness = \"5 um\"\nmaterial = \"steel\"\n"),
        "material = \"steel\"",
        400,
    ));
    assert!(
        both.contains("contact.body1.layers") && both.contains("contact.body1.coating"),
        "{both}"
    );
    let substrate_alone = refusal(&line_scene(
        "[contact.body1.coating]\nthickness = \"5 um\"\nmaterial = \"steel\"\n",
        "material = \"steel\"\nyield_strength = \"1 GPa\"",
        400,
    ));
    assert!(
        substrate_alone.contains("contact.body1.yield_strength"),
        "{substrate_alone}"
    );
    let thin = refusal(&line_scene(
        "[[contact.body1.layers]]\nthickness = \"0 um\"\nmaterial = \"steel\"\n",
        "material = \"steel\"",
        400,
    ));
    assert!(thin.contains("contact.body1.layers[1].thickness"), "{thin}");
    let strength = refusal(&line_scene(
        "[[contact.body1.layers]]\nthickness = \"20 um\"\nmaterial = \"steel\"\ntensile_strength = \"-3 MPa\"\n",
        "material = \"steel\"",
        400,
    ));
    assert!(
        strength.contains("contact.body1.layers[1].tensile_strength"),
        "{strength}"
    );
}

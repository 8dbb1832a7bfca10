//! Issue 38, "one answer everywhere", for the heating: the heating sheet, the heating report and
//! `hertz` / `contact` state the same maxima (one regression test per item).

use crate::cli::{repo, run, stderr};
use crate::contracts::{json, number};
use stressfield::figure::thermal::thermal_sheet;
use stressfield::render::chart::{Cell, Chart, Sheet};
use stressfield::render::Figure;
use stressfield::report::thermal::ThermalReport;
use stressfield::scene::Scene;
use stressfield::solution::Solution;
use stressfield::study::assess::StressMaxima;
use stressfield::study::gear_heating::gear_heating;
use stressfield::study::thermal::{study, ContactModel, ThermalStudy};
use stressfield::study::thermal_sections::{sections, ThermalSections};

/// A steel roller (body 1) under a steel cam, plane strain: the roller's surface passes the
/// contact at 2 m/s, the cam's at 5 m/s, so they slide at 3 m/s and friction on the roller acts
/// in −x (the cam the faster).
fn cam_on_roller(friction: f64, partition: &str) -> Scene {
    cam_on_roller_at(friction, partition, [2.0, 5.0])
}

/// The same with the surfaces' speeds `[V1, V2]` (m/s).
fn cam_on_roller_at(friction: f64, partition: &str, [v1, v2]: [f64; 2]) -> Scene {
    let text = format!(
        "format = 1\n[contact]\nkind = \"line\"\nload = \"300 kN/m\"\nfriction = {friction}\n\
         [contact.body1]\nradius = \"12 mm\"\nmaterial = \"steel\"\n[contact.body2]\n\
         radius = \"25 mm\"\nmaterial = \"steel\"\n[thermal]\n\
         body1_speed = \"{v1} m/s\"\nbody2_speed = \"{v2} m/s\"\npartition = \"{partition}\"\n"
    );
    Scene::parse(&text, "cam_on_roller", "cam_on_roller.toml").expect("valid scene")
}

fn panels(sheet: &Sheet) -> Vec<&Figure> {
    sheet
        .rows
        .iter()
        .flatten()
        .filter_map(|cell| match cell {
            Cell::Map(figure) => Some(figure),
            _ => None,
        })
        .collect()
}

fn panel<'a>(sheet: &'a Sheet, title: &str) -> &'a Figure {
    panels(sheet)
        .into_iter()
        .find(|f| f.title == title)
        .unwrap_or_else(|| panic!("no panel {title}"))
}

fn peclet_chart(sheet: &Sheet) -> &Chart {
    sheet
        .rows
        .iter()
        .flatten()
        .find_map(|cell| match cell {
            Cell::Chart(chart)
                if chart
                    .title
                    .starts_with("Maximum flash temperature of body 1") =>
            {
                Some(chart)
            }
            _ => None,
        })
        .expect("the Péclet chart")
}

fn sheet_of(name: &str, study: &ThermalStudy) -> (ThermalSections, Sheet) {
    let sections = sections(study, &mut |_, _| {}).expect("sections");
    let sheet = thermal_sheet(name, study, &sections, None);
    (sections, sheet)
}

/// Item 1: the sheet's total von Mises section passes through the report's maximum (its row
/// and depth), marks it with the report's value and place, and none of its samples exceeds it.
fn sheet_agrees_with_report(study: &ThermalStudy, sections: &ThermalSections, sheet: &Sheet) {
    let text = ThermalReport::new(study).text(study);
    let total = &study.total_von_mises;
    let figure = panel(sheet, "Contact + thermal stress: von Mises");
    let peak = figure.panels[0]
        .peak
        .expect("the total's maximum is marked");
    let printed = format!(
        "total {:.1} MPa at depth {:.2} µm, x = {:.2} µm",
        total.value_pa * 1e-6,
        total.depth_m * 1e6,
        total.x_m * 1e6
    );
    assert!(text.contains(&printed), "`{printed}` not in\n{text}");
    assert_eq!(
        format!("{:.1}", peak.value),
        format!("{:.1}", total.value_pa * 1e-6)
    );
    assert_eq!(
        format!("{:.2}", peak.z),
        format!("{:.2}", total.depth_m * 1e6)
    );
    assert_eq!(format!("{:.2}", peak.x), format!("{:.2}", total.x_m * 1e6));
    assert!(
        (sections.y_m - total.y_m).abs() < 1e-12,
        "the section's row"
    );
    assert!(
        sections
            .depths_m
            .iter()
            .any(|z| (z - total.depth_m).abs() <= 1e-12 * total.depth_m.max(1e-9)),
        "the maximum's depth among the section's"
    );
    let largest = sections
        .total_von_mises_pa
        .iter()
        .fold(f64::NEG_INFINITY, |m, &v| m.max(v));
    assert!(
        largest <= total.value_pa * (1.0 + 1e-6),
        "a sample of the sheet ({largest}) above the report's maximum ({})",
        total.value_pa
    );
    // The same for the maximum shear, and the contact alone's value in the subtitle.
    let shear = panel(sheet, "Contact + thermal stress: maximum shear (σ1 − σ3)/2");
    if let Some(peak) = shear.panels[0].peak {
        assert_eq!(
            format!("{:.1}", peak.value),
            format!("{:.1}", study.total_max_shear.value_pa * 1e-6)
        );
    }
    let subtitle = &figure.panels[0].subtitle;
    let contact = format!(
        "contact alone peaks at {:.1} MPa",
        study.contact_von_mises.value_pa * 1e-6
    );
    assert!(subtitle.contains(&contact), "{subtitle}");
}

#[test]
fn the_heating_sheet_passes_through_the_reports_maxima() {
    // The sliding sphere (3-D, Blok's partition): the sheet showed 942 MPa at 180.9 µm where
    // the report said 940.4 MPa at 160.8 µm.
    let scene = Scene::load(&repo("scenes/thermal_sliding_sphere.toml")).expect("scene");
    let studied = study(&scene, None, &mut |_| {}).expect("heating");
    let (sections, sheet) = sheet_of("sliding", &studied);
    sheet_agrees_with_report(&studied, &sections, &sheet);
    // The contact alone's marker is the report's (the closed form's, on y = 0).
    let contact = panel(&sheet, "Contact stress alone: von Mises").panels[0]
        .peak
        .expect("the contact alone's maximum is marked");
    let c = &studied.contact_von_mises;
    assert_eq!(
        [format!("{:.2}", contact.x), format!("{:.2}", contact.z)],
        [
            format!("{:.2}", c.x_m * 1e6),
            format!("{:.2}", c.depth_m * 1e6)
        ]
    );
    // The depth is refined, not one of the 16 searched.
    let a = studied.half_width_m;
    let coarse = stressfield::study::thermal::DEPTHS_OVER_A;
    let z = studied.total_von_mises.depth_m / a;
    assert!(coarse.iter().all(|d| (d - z).abs() > 1e-9), "{z}");
    // A line contact.
    let scene = cam_on_roller(0.1, "blok");
    let studied = study(&scene, None, &mut |_| {}).expect("heating");
    let (sections, sheet) = sheet_of("cam", &studied);
    sheet_agrees_with_report(&studied, &sections, &sheet);
}

#[test]
fn the_gears_sheet_and_report_put_the_contact_maximum_at_one_depth() {
    // The gear's contact σvM was at 20.97 µm on the sheet, 23.97 µm in the report.
    let scene = Scene::load(&repo("scenes/gear_pitch_point.toml")).expect("scene");
    let gears = gear_heating(&scene, &mut |_| {}).expect("gears");
    let studied = &gears.study;
    let sections = sections(studied, &mut |_, _| {}).expect("sections");
    let sheet = thermal_sheet("gears", studied, &sections, Some(&gears));
    sheet_agrees_with_report(studied, &sections, &sheet);
    let contact = panel(&sheet, "Contact stress alone: von Mises").panels[0]
        .peak
        .expect("the contact alone's maximum is marked");
    assert_eq!(
        format!("{:.2}", contact.z),
        format!("{:.2}", studied.contact_von_mises.depth_m * 1e6)
    );
    // Item 6: the pinion takes all the heat here? The Blok legend states the formula used.
    let chart = sheet
        .rows
        .iter()
        .flatten()
        .find_map(|cell| match cell {
            Cell::Chart(chart) if chart.title.starts_with("Flash temperature along") => Some(chart),
            _ => None,
        })
        .expect("the path chart");
    let blok = chart
        .series
        .iter()
        .find(|s| s.label.starts_with("Blok"))
        .expect("Blok's series");
    assert!(blok.label.contains("β1 √V1 + β2 √V2"), "{}", blok.label);
}

/// The closed form's maxima in Pa and m, as `hertz` computes them.
fn hertz_maxima(scene: &Scene, friction: f64) -> (StressMaxima, f64, f64) {
    let contact = &scene.contact;
    let solution = stressfield::study::closed_form_solution(contact, friction, contact.poisson)
        .expect("a closed form");
    (
        StressMaxima::of(&solution),
        contact.p0_pa(),
        contact.half_width_m(),
    )
}

#[test]
fn the_heating_blocks_contact_alone_is_the_closed_form() {
    // Item 2 and 3: a line contact's contact alone was 1.6 % (von Mises) and 4.3 % (Tresca, then
    // twice the shear) above `hertz`; at μ = 0.4 its maximum sat at x = −0.575a instead of
    // the trailing edge.
    // At μ = 0.4 slowly (V1 0.2, V2 0.25 m/s), so that the total's maximum stays on the
    // contact's edge peak.
    for (friction, speeds) in [(0.1, [2.0, 5.0]), (0.4, [0.2, 0.25])] {
        let scene = cam_on_roller_at(friction, "blok", speeds);
        let studied = study(&scene, None, &mut |_| {}).expect("heating");
        assert!(matches!(
            studied.contact_model,
            ContactModel::ClosedForm { .. }
        ));
        let (hertz, p0, a) = hertz_maxima(&scene, friction);
        let vm = hertz.von_mises.value_over_p0 * p0;
        let shear = hertz.max_shear.value_over_p0 * p0;
        let c = &studied.contact_von_mises;
        assert!(
            (c.value_pa / vm - 1.0).abs() < 1e-9,
            "{} vs {vm}",
            c.value_pa
        );
        assert!(
            (studied.contact_max_shear.value_pa / shear - 1.0).abs() < 1e-9,
            "{} vs {shear}",
            studied.contact_max_shear.value_pa
        );
        // Friction on the roller acts in −x (the cam the faster): the mirror image.
        assert!(
            (c.x_m / a + hertz.von_mises.x_over_a).abs() < 1e-6,
            "{}",
            c.x_m / a
        );
        assert!((c.depth_m / a - hertz.von_mises.z_over_a).abs() < 1e-6);
        if friction == 0.4 {
            // On the surface (hertz: x = 0.371a; here mirrored, the traction in −x), where
            // the a/20 DC-FFT grid's smoothing put it at depth; the total's maximum found
            // there too, between the cell centres (not half a cell away).
            assert!(
                c.depth_m == 0.0 && (c.x_m / a + 0.371).abs() < 1e-3,
                "{c:?}"
            );
            let t = &studied.total_von_mises;
            let cells = (t.x_m - studied.origin_m[0]) / studied.spacing_m[0];
            assert!(
                t.depth_m == 0.0 && (cells - cells.round()).abs() > 1e-3,
                "{t:?}"
            );
        }
        // The sections' contact stress is the closed form at their samples.
        let sections = sections(&studied, &mut |_, _| {}).expect("sections");
        let solution = Solution::LineHertz {
            friction: -friction,
            poisson: scene.contact.poisson,
        };
        for (k, &z) in sections.depths_m.iter().enumerate().step_by(5) {
            for column in (0..studied.shape[1]).step_by(7) {
                let x = studied.origin_m[0] + column as f64 * studied.spacing_m[0];
                let exact = solution.stress_over_p0(x / a, 0.0, z / a).von_mises() * p0;
                let drawn = sections.contact_von_mises_pa[[k, column]];
                assert!((drawn - exact).abs() <= 1e-9 * p0, "{drawn} vs {exact}");
            }
        }
    }
    // A sphere: the contact alone is `hertz`'s.
    let scene = Scene::load(&repo("scenes/thermal_sliding_sphere.toml")).expect("scene");
    let studied = study(&scene, None, &mut |_| {}).expect("heating");
    let (hertz, p0, _) = hertz_maxima(&scene, scene.contact.friction);
    assert!(
        (studied.contact_von_mises.value_pa / (hertz.von_mises.value_over_p0 * p0) - 1.0).abs()
            < 1e-9
    );
    assert!(
        (studied.contact_max_shear.value_pa / (hertz.max_shear.value_over_p0 * p0) - 1.0).abs()
            < 1e-9
    );
    // The thermal maximum has a place of its own, not under the hottest point.
    let text = ThermalReport::new(&studied).text(&studied);
    let thermal = format!(
        "thermal {:.1} MPa at depth {:.2} µm, x = {:.2} µm",
        studied.thermal_von_mises.value_pa * 1e-6,
        studied.thermal_von_mises.depth_m * 1e6,
        studied.thermal_von_mises.x_m * 1e6
    );
    assert!(text.contains(&thermal), "{text}");
}

#[test]
fn the_gears_hottest_point_has_the_closed_form_contact_stress() {
    // The gear's hottest point: 241.4 against 237.7 MPa.
    let scene = Scene::load(&repo("scenes/gear_pitch_point.toml")).expect("scene");
    let gears = gear_heating(&scene, &mut |_| {}).expect("gears");
    let point = &gears.points[gears.hottest];
    let studied = &gears.study;
    let solution = Solution::LineHertz {
        friction: studied.signed_friction,
        poisson: studied.spec.body1.material.poisson,
    };
    let exact = StressMaxima::of(&solution).von_mises.value_over_p0 * point.p0_pa;
    assert!(
        (studied.contact_von_mises.value_pa / exact - 1.0).abs() < 1e-9,
        "{} vs {exact}",
        studied.contact_von_mises.value_pa
    );
}

#[test]
fn tresca_is_half_the_principal_difference_in_the_heating_outputs() {
    // Item 3: one definition, (σ1 − σ3)/2, in the JSON keys, the text and the sheet.
    let dir = tempfile::tempdir().expect("temporary directory");
    let path = dir.path().join("cam.toml");
    std::fs::write(
        &path,
        "format = 1\n[contact]\nkind = \"line\"\nload = \"300 kN/m\"\nfriction = 0.1\n\
         [contact.body1]\nradius = \"12 mm\"\nmaterial = \"steel\"\n[contact.body2]\n\
         radius = \"25 mm\"\nmaterial = \"steel\"\n[thermal]\nspeed = \"3 m/s\"\n\
         body1_speed = \"2 m/s\"\nbody2_speed = \"5 m/s\"\npartition = \"blok\"\n",
    )
    .expect("write");
    let path = path.to_str().expect("utf-8");
    let output = run(&["thermal", path, "--json"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let raw = String::from_utf8_lossy(&output.stdout);
    assert!(!raw.contains("tresca"), "{raw}");
    let report = json(&output);
    let hertz = run(&["hertz", path]);
    let text = String::from_utf8_lossy(&hertz.stdout);
    // `hertz` prints the closed form's maximum shear; the heating block the same value.
    let shear = number(&report, "contact_max_shear_max_pa") * 1e-6;
    assert!(
        text.contains(&format!("= {shear:.1} MPa")),
        "{shear:.1} not in\n{text}"
    );
    assert!(
        text.contains("maximum shear (s1 - s3)/2 (Tresca) maxima"),
        "{text}"
    );
    let scene = cam_on_roller(0.1, "blok");
    let studied = study(&scene, None, &mut |_| {}).expect("heating");
    let (_, sheet) = sheet_of("cam", &studied);
    assert!(panels(&sheet)
        .iter()
        .all(|f| !f.title.contains("Tresca σ1 − σ3")));
    assert!(panels(&sheet)
        .iter()
        .any(|f| f.value_label == "(σ1 − σ3)/2 (MPa)"));
}

#[test]
fn the_peclet_charts_scene_point_is_the_scenes_temperature_with_all_heat_into_body_1() {
    // Item 4: body 1 at 2 m/s, sliding at 3 m/s: the point was scaled by V1/Vs onto a curve of
    // another flux. It is now the scene's own temperature with all the heat into body 1.
    let blok = study(&cam_on_roller(0.1, "blok"), None, &mut |_| {}).expect("heating");
    let all = study(&cam_on_roller(0.1, "body1"), None, &mut |_| {}).expect("heating");
    let (_, sheet) = sheet_of("cam", &blok);
    let chart = peclet_chart(&sheet);
    let point = chart
        .series
        .iter()
        .find(|s| s.label.starts_with("this scene"))
        .expect("the scene's point");
    let (pe, t) = point.points[0];
    assert_eq!(pe, blok.body1.peclet);
    let expected = all.body1.max_temperature_rise_k;
    assert!((t / expected - 1.0).abs() < 1e-9, "{t} vs {expected}");
    // A line contact's curve is computed over strips.
    assert!(
        chart.series[0].label.contains("strips"),
        "{}",
        chart.series[0].label
    );
    // And the curve passes through the point: the swept value at the scene's Pe, between
    // its neighbours on log axes, within 2 %.
    let sweep = &chart.series[0].points;
    let k = sweep.iter().position(|p| p.0 > pe).expect("bracketed");
    let (p0, p1) = (sweep[k - 1], sweep[k]);
    let f = (pe.ln() - p0.0.ln()) / (p1.0.ln() - p0.0.ln());
    let on_curve = (p0.1.ln() + f * (p1.1.ln() - p0.1.ln())).exp();
    assert!((on_curve / t - 1.0).abs() < 0.02, "{on_curve} vs {t}");
}

#[test]
fn a_stationary_source_is_said_on_the_peclet_chart() {
    // Item 4: a pin carrying the contact (Pe 0) got a moving-source curve, no point, no note.
    let text = "format = 1\n[contact]\nkind = \"point\"\nload = \"20 N\"\nfriction = 0.2\n\
                [contact.body1]\nradius = \"6.35 mm\"\nmaterial = \"steel\"\n[contact.body2]\n\
                radius = \"flat\"\nmaterial = \"steel\"\n[thermal]\nspeed = \"0.5 m/s\"\n\
                body1_speed = \"0 m/s\"\nbody2_speed = \"0.5 m/s\"\npartition = \"body1\"\n";
    let scene = Scene::parse(text, "pin", "pin.toml").expect("scene");
    let studied = study(&scene, None, &mut |_| {}).expect("heating");
    let (sections, sheet) = sheet_of("pin", &studied);
    let chart = peclet_chart(&sheet);
    let stationary = chart
        .series
        .iter()
        .find(|s| s.label.starts_with("stationary limit"))
        .expect("the stationary limit");
    let scene_k = studied.body1.max_temperature_rise_k;
    assert!(
        stationary.label.contains("this scene")
            && stationary.label.contains(&format!("{scene_k:.1} K")),
        "{}",
        stationary.label
    );
    assert!((sections.stationary_k.expect("3-D") / scene_k - 1.0).abs() < 1e-9);
}

#[test]
fn a_line_contacts_hottest_point_is_marked_at_y_0() {
    // Item 6: the map of identical rows marked its maximum on the bottom edge.
    let scene = cam_on_roller(0.1, "blok");
    let studied = study(&scene, None, &mut |_| {}).expect("heating");
    let (_, sheet) = sheet_of("cam", &studied);
    let surface = panel(
        &sheet,
        "Body 1's surface temperature rise (contact outlined)",
    );
    let peak = surface.panels[0].peak.expect("marked");
    assert_eq!(peak.z, 0.0);
    assert_eq!(peak.x, studied.body1.max_at_m[0] * 1e6);
    assert_eq!(peak.value, studied.body1.max_temperature_rise_k);
    // The Blok formula of a pinion taking all the heat is the one-body formula.
    let gears = std::fs::read_to_string(repo("scenes/gear_pitch_point.toml"))
        .expect("scene")
        .replace("partition = \"blok\"", "partition = \"body1\"");
    assert!(
        gears.contains("partition = \"body1\""),
        "the gear scene's partition"
    );
    let scene = Scene::parse(&gears, "gears", "gears.toml").expect("scene");
    let heating = gear_heating(&scene, &mut |_| {}).expect("gears");
    assert_eq!(
        stressfield::figure::thermal::blok_formula(heating.study.spec.partition),
        "Blok 1.11 μ w Vs / (√(2a) β1 √V1)"
    );
    // The ball on a disc's figure frames the contact (a = 0.085 mm), not ±2 mm.
    let disc = Scene::load(&repo("scenes/thermal_ball_on_disc.toml")).expect("scene");
    let a_mm = disc.contact.half_width_m() * 1e3;
    let x = disc.figure.x;
    assert!(x.1 - x.0 < 6.0 * a_mm, "{x:?} mm for a = {a_mm} mm");
}

#[test]
fn the_heating_report_echoes_the_properties_it_used() {
    // Item 7: an override of the conductivity is seen in the report.
    let dir = tempfile::tempdir().expect("temporary directory");
    let path = dir.path().join("roller.toml");
    std::fs::write(
        &path,
        "format = 1\n[contact]\nkind = \"line\"\nload = \"300 kN/m\"\nfriction = 0.1\n\
         [contact.body1]\nradius = \"12 mm\"\nmaterial = \"steel\"\n\
         conductivity = \"21.5 W/(m K)\"\ndiffusivity = \"4.5e-6 m^2/s\"\n\
         expansion = \"1.3e-5 /K\"\n[contact.body2]\n\
         radius = \"25 mm\"\nmaterial = \"steel\"\n[thermal]\nspeed = \"3 m/s\"\n\
         partition = \"body1\"\n",
    )
    .expect("write");
    let path = path.to_str().expect("utf-8");
    let output = run(&["thermal", path, "--json"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let report = json(&output);
    assert_eq!(number(&report, "body1_conductivity_w_per_m_k"), 21.5);
    assert_eq!(number(&report, "body1_diffusivity_m2_per_s"), 4.5e-6);
    assert_eq!(number(&report, "body1_expansion_per_k"), 1.3e-5);
    let output = run(&["thermal", path]);
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(
        text.contains("body 1 K = 21.5 W/(m K), kappa = 4.5e−6 m^2/s, alpha = 1.3e−5 1/K"),
        "{text}"
    );
}

#[test]
fn a_rough_heating_sheet_states_contacts_maximum_where_its_stresses_live() {
    // Item 5: the sheet said "contact alone peaks at 1455 MPa" where `contact` reported
    // 2313 MPa, and its sections reached 1.2 times half the map for stresses in the top few
    // µm. A coarser copy of the shipped rough ball (64 x 64 cells of 1 µm), heated at 2 m/s.
    let text = std::fs::read_to_string(repo("scenes/rough_ball_on_flat.toml"))
        .expect("scene")
        .replace("samples = 256", "samples = 64")
        .replace("spacing = \"0.5 um\"", "spacing = \"1 um\"")
        + "\n[thermal]\nspeed = \"2 m/s\"\npartition = \"blok\"\n";
    let scene = Scene::parse(&text, "rough", "rough.toml").expect("scene");
    let solution = stressfield::study::rough::solve(&scene, &mut |_, _| {}).expect("contact");
    let studied = study(&scene, Some(&solution), &mut |_| {}).expect("heating");
    let (maxima, search_depth) = stressfield::study::rough::subsurface_maxima(
        &solution,
        scene.contact.friction,
        studied.spec.body1.material.poisson,
    )
    .expect("maxima");
    let contact = maxima.von_mises.value_over_p0 * 1e6;
    assert!(
        (studied.contact_von_mises.value_pa / contact - 1.0).abs() < 1e-9,
        "{} vs {contact}",
        studied.contact_von_mises.value_pa
    );
    assert!(
        (studied.contact_max_shear.value_pa / (maxima.max_shear.value_over_p0 * 1e6) - 1.0).abs()
            < 1e-9
    );
    let (sections, sheet) = sheet_of("rough", &studied);
    let deepest = *sections.depths_m.last().expect("depths");
    assert!(
        deepest <= 2.0 * search_depth * (1.0 + 1e-9) + 1e-12,
        "{deepest} against the search depth {search_depth}"
    );
    let maxima_depth = [
        studied.total_von_mises.depth_m,
        studied.contact_von_mises.depth_m,
        studied.total_max_shear.depth_m,
        studied.contact_max_shear.depth_m,
    ]
    .iter()
    .fold(0.0f64, |d, &z| d.max(z));
    assert!(
        // (the last step may overshoot to keep the maximum's depth on a sample)
        deepest <= (4.0 * maxima_depth).max(16.0 * 1e-6) * (1.0 + 1.0 / 20.0),
        "{deepest} for maxima at most {maxima_depth} deep"
    );
    assert!(deepest >= studied.total_von_mises.depth_m);
    sheet_agrees_with_report(&studied, &sections, &sheet);
}

//! Recordings that agree with themselves and with the reports (issue 23): one step numbering in
//! titles, logs and the time panel; the depth of the report's maximum among a rough
//! recording's layers, with the report's value; colour ranges not set by a single cell.

use rerun::log::Chunk;
use stressfield::record;
use stressfield::scene::Scene;

use super::record::{record_in_memory, scene, Contents, FRICTION_SWEEP, ROUGH_SWEEP};

/// Per row at `path` on `timeline`, its time and the first text of `component` (a title row's
/// title, a log line).
fn first_texts(
    contents: &Contents,
    path: &str,
    timeline: &'static str,
    component: rerun::ComponentIdentifier,
) -> Vec<(i64, String)> {
    let name = rerun::TimelineName::from(timeline);
    let mut rows = Vec::new();
    for chunk in contents.chunks.get(path).into_iter().flatten() {
        let Some(times) = chunk.timelines().get(&name) else {
            continue;
        };
        let texts = chunk.iter_component::<rerun::components::Text>(component);
        for (&time, batch) in times.times_raw().iter().zip(texts) {
            if let Some(text) = batch.iter().next() {
                rows.push((time, text.as_str().to_string()));
            }
        }
    }
    rows.sort_by_key(|(time, _)| *time);
    rows
}

fn titles(contents: &Contents, path: &str, timeline: &'static str) -> Vec<(i64, String)> {
    first_texts(
        contents,
        path,
        timeline,
        rerun::Points2D::descriptor_labels().component,
    )
}

fn log_lines(contents: &Contents, timeline: &'static str) -> Vec<(i64, String)> {
    first_texts(
        contents,
        "/log",
        timeline,
        rerun::TextLog::descriptor_text().component,
    )
}

/// The number after `prefix` in `text`: `max σvM = 1574 MPa` -> 1574.
fn number_after(text: &str, prefix: &str) -> f64 {
    text.split_once(prefix)
        .and_then(|(_, rest)| rest.split([' ', ',', ':']).next())
        .and_then(|n| n.replace('−', "-").parse().ok())
        .unwrap_or_else(|| panic!("no number after {prefix:?} in {text:?}"))
}

#[test]
fn titles_logs_and_the_time_panel_count_steps_alike_and_name_the_swept_value() {
    let scene = scene(FRICTION_SWEEP);
    let sweep = scene.sweep.as_ref().expect("a sweep");
    let (_, contents) = record_in_memory(&scene);
    // The time panel: steps 1 to 6 on the timeline `friction`.
    let times: Vec<i64> = contents
        .scalars("/series/friction", "friction")
        .iter()
        .map(|(t, _)| *t)
        .collect();
    assert_eq!(times, (1..=6).collect::<Vec<i64>>());
    let expect = |time: i64| {
        format!(
            "step {time} of 6: {}",
            sweep.describe(time as usize - 1, &scene)
        )
    };
    let lines = log_lines(&contents, "friction");
    assert_eq!(lines.len(), 6, "{lines:?}");
    for (time, line) in &lines {
        assert_eq!(line, &expect(*time));
    }
    let titles = titles(&contents, "/sections/0/title", "friction");
    assert_eq!(titles.len(), 6, "{titles:?}");
    for (time, title) in &titles {
        assert!(title.starts_with(&expect(*time)), "{time}: {title}");
    }
    assert_no_backticks(&contents);
    // No wall-clock timeline beside the steps'.
    let log_time = rerun::TimelineName::from("log_time");
    assert!(contents
        .chunks
        .values()
        .flatten()
        .all(|chunk: &Chunk| !chunk.timelines().contains_key(&log_time)));
}

#[test]
fn a_rough_recording_has_a_layer_at_the_reports_maximum_with_its_value() {
    let scene = scene(ROUGH_SWEEP);
    let solution = stressfield::study::rough::solve(&scene, &mut |_, _| {}).expect("solved");
    let findings = stressfield::study::rough::findings(&scene, &solution).expect("findings");
    let maximum = findings.maxima.von_mises;
    let (_, contents) = record_in_memory(&scene);
    let titles = titles(&contents, "/depth/title", "depth");
    let layers = titles.len();
    assert!(layers > 20, "{titles:?}");
    // Layers numbered from 1, closer near the surface than deep.
    let depths: Vec<f64> = titles
        .iter()
        .map(|(_, t)| number_after(t, "z = "))
        .collect();
    assert_eq!(titles[0].0, 1);
    assert!(titles[0]
        .1
        .starts_with(&format!("layer 1 of {layers}: z = 0 µm")));
    assert!(depths[2] - depths[1] < 0.5 * (depths[layers - 1] - depths[layers - 2]));
    // The report's depth, exactly one of the layers, marked, and its largest σvM the report's.
    let at: Vec<&(i64, String)> = titles
        .iter()
        .filter(|(_, t)| t.ends_with(": the report's largest σvM"))
        .collect();
    assert_eq!(at.len(), 1, "{titles:?}");
    let (time, title) = at[0];
    let z = number_after(title, "z = ");
    assert!(
        (z - maximum.z_over_a).abs() <= 1e-3 * maximum.z_over_a,
        "{title} vs the report's {}",
        maximum.z_over_a
    );
    let labels = first_texts(
        &contents,
        "/depth/maximum/label",
        "depth",
        rerun::Points2D::descriptor_labels().component,
    );
    let (_, label) = labels
        .iter()
        .find(|(t, _)| t == time)
        .expect("a maximum at the layer");
    let shown = number_after(label, "max σvM = ");
    assert!(
        (shown - maximum.value_over_p0).abs() <= 1e-3 * maximum.value_over_p0,
        "{label} vs the report's {} MPa",
        maximum.value_over_p0
    );
    // No layer shows much more than the report, whose search is refined to an eighth of a
    // cell (here 0.125 µm: a layer 0.006 µm deeper shows 0.1 % more).
    for (_, label) in &labels {
        assert!(
            number_after(label, "max σvM = ") <= shown * 1.005,
            "{label}"
        );
    }
    assert_no_backticks(&contents);
    // The layers are at the scene's load, one of the sweep's, and say which.
    assert!(title.contains(", W = 0.2 N (step 2 of 3)"), "{title}");
    // The chart of the largest stresses against depth follows the layers.
    assert_eq!(contents.rows_on("/charts/depth_maxima", "depth"), layers);
    assert!(contents.view_names().iter().any(|v| v == "σvM, τ vs z"));
}

#[test]
fn a_rough_sweeps_colours_are_not_set_by_one_cell_and_a_capped_pressure_is_flagged() {
    let scene = Scene::load(std::path::Path::new("scenes/record_rough_load_sweep.toml"))
        .expect("the shipped scene");
    let (_, contents) = record_in_memory(&scene);
    let ticks: Vec<f64> = contents
        .labels("/contact/colorbar/labels")
        .iter()
        .filter_map(|t| t.replace('−', "-").parse().ok())
        .collect();
    let top_tick = ticks.iter().copied().fold(0.0, f64::max);
    let sweep_titles = titles(&contents, "/contact/title", record::timeline(&scene));
    let largest = contents
        .scalars("/series/max_pressure_mpa", "load")
        .iter()
        .map(|(_, p)| *p)
        .fold(0.0, f64::max);
    assert!(
        top_tick < 0.8 * largest,
        "colour bar to {top_tick} MPa, the largest pressure {largest} MPa"
    );
    // The steps whose maximum is beyond the colours say so; the maximum is still labelled.
    assert!(
        sweep_titles
            .iter()
            .any(|(_, t)| t.contains("in the top colour")),
        "{sweep_titles:?}"
    );
    let labels = contents.labels("/contact/maximum/label");
    assert!(labels
        .iter()
        .any(|l| (number_after(l, "max p = ") - largest).abs() < 1e-3 * largest));
    assert!(contents
        .text_documents()
        .iter()
        .any(|v| v.contains("its colours run to the 99.5 % quantile of all loads")));
    // With a hardness the pressure is capped, and the steps at the cap say so.
    let capped = scene_with_hardness("100 HV");
    let (_, contents) = record_in_memory(&capped);
    let capped_titles = titles(&contents, "/contact/title", "load");
    assert!(
        capped_titles
            .iter()
            .any(|(_, t)| t.contains("cells at the hardness ")),
        "{capped_titles:?}"
    );
}

/// The small rough sweep with a hardness.
fn scene_with_hardness(hardness: &str) -> Scene {
    scene(&ROUGH_SWEEP.replace(
        "periodic = true\n",
        &format!("periodic = true\nhardness = \"{hardness}\"\n"),
    ))
}

#[test]
fn a_rough_sweeps_single_load_views_say_which_load_they_show() {
    let off_sweep = scene(&ROUGH_SWEEP.replace("load = \"0.2 N\"", "load = \"0.3 N\""));
    let (_, contents) = record_in_memory(&off_sweep);
    let depth = titles(&contents, "/depth/title", "depth");
    assert!(
        depth
            .iter()
            .all(|(_, t)| t.contains(", W = 0.3 N (not one of the swept loads)")),
        "{depth:?}"
    );
    // The shipped sweep shows one of its loads.
    let shipped = Scene::load(std::path::Path::new("scenes/record_rough_load_sweep.toml"))
        .expect("the shipped scene");
    let sweep = shipped.sweep.as_ref().expect("a sweep");
    let load = stressfield::study::rough::problem(&shipped).map(|p| p.control);
    assert!(
        matches!(load, Some(stressfield::contact::rough::Control::Load { newtons })
            if sweep.values.contains(&newtons)),
        "{load:?}"
    );
}

/// Tab names and title rows are plain text: a backtick would be shown as one.
fn assert_no_backticks(contents: &Contents) {
    for name in contents.view_names() {
        assert!(!name.contains('`'), "view {name}");
    }
    for path in contents.chunks.keys().filter(|p| p.ends_with("/title")) {
        for title in contents.labels(path) {
            assert!(!title.contains('`'), "{path}: {title}");
        }
    }
}

/// A figure of panels in different planes (issue 23, item 13) records each in its own
/// coordinates: the views name each panel's plane, the maxima are labelled in its coordinates,
/// and only the depth sections chart the depth of their maximum.
#[test]
fn panels_in_different_planes_are_recorded_in_their_own_coordinates() {
    let scene = scene(
        r#"
format = 1
[contact]
kind = "point"
[figure]
quantity = "von_mises"
z = [0.0, 1.5]
resolution = 41
[[panel]]
[[panel]]
section = "yz"
at = 0.2
[[panel]]
section = "xy"
at = 0.48
[sweep]
parameter = "friction"
values = [0.0, 0.3]
"#,
    );
    let (summary, contents) = record_in_memory(&scene);
    assert_eq!(summary.panels, 3);
    let names = contents.view_names();
    for (k, plane) in ["xz", "yz", "xy"].into_iter().enumerate() {
        let name = format!("panel {}: σvM / p0 · {plane} section", k + 1);
        assert!(names.contains(&name), "{name}: {names:?}");
    }
    for (k, (across, down)) in [("x = ", "z = "), ("y = ", "z = "), ("x = ", "y = ")]
        .into_iter()
        .enumerate()
    {
        let labels = contents.labels(&format!("/sections/{k}/maximum/label"));
        assert_eq!(labels.len(), 2, "{labels:?}");
        for label in &labels {
            assert!(
                label.contains(across) && label.contains(down),
                "{k}: {label}"
            );
        }
    }
    for (k, depth) in [(0, true), (1, true), (2, false)] {
        let steps = usize::from(depth) * 2;
        let path = format!("/series/{k}/maximum_depth");
        assert_eq!(contents.scalars(&path, "friction").len(), steps, "{path}");
        // The native plot of the maximum's depth against μ, for depth sections only.
        let view = format!("depth vs μ, panel {}", k + 1);
        assert_eq!(contents.view_names().contains(&view), depth, "{view}");
    }
    let description = contents.text_documents().join("\n");
    assert!(
        description.contains("3 panel(s) of") && description.contains("xz, yz and xy sections"),
        "{description}"
    );
}

/// Issue 23, colour ranges: a sweep whose field grows by more than a decade takes each step's
/// own range (its colour bar logged with the step, its title saying so), and panels on the
/// figure's shared scale share one range, as in the PNG figure.
#[test]
fn a_sweep_spanning_decades_takes_each_steps_range_and_panels_share_one_scale() {
    // p0 grows as W^(1/3): 0.1 N to 1000 N is a factor 21.5 in MPa.
    let decades = "format = 1\n[contact]\nkind = \"point\"\nload = \"1 N\"\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"6.35 mm\"\nmaterial = \"steel\"\n[figure]\nquantity = \"von_mises\"\nlength_unit = \"mm\"\nstress_unit = \"MPa\"\nx = [-1.5, 1.5]\nz = [0.0, 1.5]\nresolution = 41\n[sweep]\nparameter = \"load\"\nvalues = [\"0.1 N\", \"10 N\", \"1000 N\"]\n";
    let (_, contents) = record_in_memory(&scene(decades));
    let bars = titles(&contents, "/sections/0/colorbar/labels", "load");
    assert_eq!(bars.len(), 3, "{bars:?}");
    let step_titles = titles(&contents, "/sections/0/title", "load");
    assert_eq!(step_titles.len(), 3, "{step_titles:?}");
    for (_, title) in &step_titles {
        assert!(title.contains("(this step's range)"), "{title}");
    }
    // Each step's top colour is above its own maximum and below twice it (3 % spare, two
    // digits rounded up), so the light load is not drawn dark.
    let maxima = contents.scalars("/series/0/maximum", "load");
    for ((_, title), (_, max)) in step_titles.iter().zip(&maxima) {
        let top = number_after(title, "colours 0 to ");
        assert!(top >= *max && top < 2.0 * max, "{title}: max {max}");
    }
    // A sweep within a decade keeps one range: the colour bar is static.
    let (_, contents) = record_in_memory(&scene(FRICTION_SWEEP));
    assert!(titles(&contents, "/sections/0/colorbar/labels", "friction").is_empty());
    // Two panels on the shared scale (sections at y = 0 and y = 0.6a): one colour range.
    let two = "format = 1\n[contact]\nkind = \"point\"\n[figure]\nquantity = \"von_mises\"\nresolution = 41\n[sweep]\nparameter = \"friction\"\nvalues = [0.0, 0.3]\n[[panel]]\n[[panel]]\nat = 0.6\n";
    let (_, contents) = record_in_memory(&scene(two));
    let bar = |k: usize| contents.labels(&format!("/sections/{k}/colorbar/labels"));
    assert_eq!(bar(0), bar(1));
}

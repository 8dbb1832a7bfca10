//! Tests of [`super`].

use super::*;

fn demo() -> Chart {
    let mut chart = Chart::new("Power spectrum", "q (rad/m)", "C (m⁴)");
    chart.x_scale = Scale::Log;
    chart.y_scale = Scale::Log;
    chart.series.push(Series {
        label: "measured".into(),
        points: (1..100)
            .map(|k| (k as f64 * 1e4, 1e-30 * (k as f64).powf(-3.6)))
            .collect(),
        style: Style::Markers,
        colour: PALETTE[0],
    });
    chart.series.push(Series {
        label: "fit".into(),
        points: vec![(1e4, 1e-30), (1e6, 1e-30 * 100f64.powf(-3.6))],
        style: Style::Dashed,
        colour: PALETTE[1],
    });
    chart.x_band = Some((5e4, 5e5));
    chart
}

#[test]
fn log_ticks_label_decades() {
    let (major, minor) = log_ticks(1e-3, 1e2);
    let labels: Vec<&str> = major.iter().map(|m| m.1.as_str()).collect();
    assert_eq!(labels, ["10⁻³", "10⁻²", "10⁻¹", "10⁰", "10¹", "10²"]);
    assert_eq!(minor.len(), 5 * 8);
    let (narrow, _) = log_ticks(3e-3, 2e-2);
    assert!(narrow.iter().any(|m| m.1 == "5·10⁻³"), "{narrow:?}");
}

#[test]
fn chart_draws_inside_its_image_with_white_margins() {
    let image = chart_png(&demo()).expect("renders");
    assert_eq!(image.dimensions(), (520, 380));
    let (w, h) = image.dimensions();
    for x in 0..w {
        assert_eq!(image.get_pixel(x, h - 1).0, [255, 255, 255]);
    }
    // Something of the first series' colour is drawn.
    assert!(image.pixels().any(|p| p.0 == PALETTE[0]));
    // Non-positive values on a log axis are dropped, not drawn at NaN.
    let mut bad = demo();
    bad.series[0].points.push((-1.0, 0.0));
    assert!(chart_png(&bad).is_ok());
}

#[test]
fn sheet_composes_maps_and_charts_and_svg_nests_cleanly() {
    let sheet = Sheet {
        title: "Demo".into(),
        notes: Vec::new(),
        rows: vec![
            vec![Cell::Chart(demo()), Cell::Chart(demo())],
            vec![Cell::Chart(demo())],
        ],
    };
    let image = sheet_png(&sheet).expect("png");
    assert_eq!(image.width(), GAP + 2 * (520 + GAP));
    let svg = sheet_svg(&sheet).expect("svg");
    assert_eq!(svg.matches("<svg").count(), 4);
    assert_eq!(svg.matches("</svg>").count(), 4);
    // No tag repeats an attribute.
    for tag in svg.split('<').filter(|t| t.starts_with("svg")) {
        let head = &tag[..tag.find('>').unwrap_or(tag.len())];
        let names: Vec<&str> = split_attributes(head)
            .iter()
            .filter_map(|a| a.split('=').next())
            .map(|_| "")
            .collect();
        let mut set = std::collections::HashSet::new();
        for part in split_attributes(head) {
            if let Some(name) = part.split('=').next().filter(|_| part.contains('=')) {
                assert!(set.insert(name.to_string()), "repeated {name} in {head}");
            }
        }
        drop(names);
    }
}

#[test]
#[ignore = "writes a demo image to look at"]
fn demo_image() {
    let sheet = Sheet {
        title: "Demo".into(),
        notes: Vec::new(),
        rows: vec![vec![Cell::Chart(demo())]],
    };
    sheet_png(&sheet)
        .expect("png")
        .save("/tmp/chart_demo.png")
        .expect("save");
}

//! Tests of [`super`].

use super::*;

#[test]
fn ticks_are_nice_and_inside() {
    let ticks = nice_ticks(0.0, 0.62, 5);
    assert_eq!(ticks.len(), 4);
    for (t, e) in ticks.iter().zip([0.0, 0.2, 0.4, 0.6]) {
        assert!((t - e).abs() < 1e-12, "{ticks:?}");
    }
    let ticks = nice_ticks(-0.3, 0.3, 7);
    assert_eq!(ticks.len(), 7);
    assert!((ticks[0] + 0.3).abs() < 1e-12 && (ticks[6] - 0.3).abs() < 1e-12);
    assert!(nice_ticks(0.0, 1250.0, 6).iter().all(|t| t % 250.0 == 0.0));
}

#[test]
fn short_numbers_keep_three_digits() {
    assert_eq!(short(0.55724), "0.557");
    assert_eq!(short(-0.25), "\u{2212}0.250");
    assert_eq!(short(1234.5), "1234");
    assert_eq!(short(0.0), "0");
    assert_eq!(short(2.5e-6), "2.50e\u{2212}6");
}

fn frame() -> Frame {
    Frame {
        u: (-1.0, 1.0),
        v: (0.0, 1.0),
        strip: 0.2,
        px: 400.0,
        bar: (1.05, 1.2),
        title_row: -0.6,
        legend_row: -0.4,
        bounds: [-1.1, 1.6, -0.8, 1.1],
    }
}

#[test]
fn labels_that_would_overlap_are_moved_apart() {
    let frame = frame();
    let wanted = [
        ((0.0, 0.5), "max σvM = 0.557 p0 at x = 0a, z = 0.700a"),
        ((0.05, 0.52), "min σvM = 0.001 p0 at x = 0.1a, z = 0.7a"),
        ((0.9, 0.1), "point 0"),
    ];
    let centres = place_labels(&frame, &wanted, &Avoid::default());
    assert_eq!(centres[0], (0.0, 0.5));
    // The second is moved a label height or more away; the third, far away, stays.
    assert!((centres[1].1 - 0.52).abs() >= LABEL_PX / frame.px - 1e-9);
    assert_eq!(centres[2], (0.9, 0.1));
    for i in 0..3 {
        for j in 0..i {
            let boxed = |k: usize| LabelBox {
                u: centres[k].0,
                v: centres[k].1,
                half_width: 0.5 * (wanted[k].1.chars().count() as f64 * CHAR_PX + 10.0) / frame.px,
                half_height: 0.5 * LABEL_PX / frame.px,
            };
            assert!(!boxed(i).overlaps(&boxed(j)), "{i} covers {j}");
        }
    }
}

#[test]
fn labels_never_cover_a_marked_point_and_stay_by_their_own() {
    // A moving load at x0 = 0 (issue 14): the labels of the two τxz lobes flank the axis,
    // where two material points sit one above the other. Pushed from below its dot, the
    // first point's label once landed on the second point's dot.
    let frame = frame();
    let h = LABEL_PX / frame.px;
    let (max_at, min_at) = ((-0.3, 0.5), (0.3, 0.5));
    let points = [(0.0, 0.5), (0.0, 0.58)];
    let below = |(u, v): (f64, f64)| (u, v + 0.9 * h);
    let wanted = [
        (
            below(max_at),
            "max τxz = 0.250 p0 at x = −0.860a, z = 0.500a",
        ),
        (
            below(min_at),
            "min τxz = −0.250 p0 at x = 0.860a, z = 0.500a",
        ),
        (below(points[0]), "point 0"),
        (below(points[1]), "point 1"),
    ];
    let dots = [max_at, min_at, points[0], points[1]];
    let avoid = Avoid {
        dots: &dots,
        ..Avoid::default()
    };
    let centres = place_labels(&frame, &wanted, &avoid);
    let boxed = |k: usize| LabelBox {
        u: centres[k].0,
        v: centres[k].1,
        half_width: 0.5 * (wanted[k].1.chars().count() as f64 * CHAR_PX + 10.0) / frame.px,
        half_height: 0.5 * h,
    };
    for k in 0..wanted.len() {
        for &(u, v) in &dots {
            let dot = LabelBox {
                u,
                v,
                half_width: DOT_PX / frame.px,
                half_height: DOT_PX / frame.px,
            };
            assert!(
                !boxed(k).overlaps(&dot),
                "label {k} covers the dot at ({u}, {v})"
            );
        }
        for j in 0..k {
            assert!(!boxed(k).overlaps(&boxed(j)), "{k} covers {j}");
        }
    }
    // Each point's label is nearer its own point than the other one.
    let distance = |(u, v): (f64, f64), (a, b): (f64, f64)| (u - a).hypot(v - b);
    for (j, own) in points.iter().enumerate() {
        let other = points[1 - j];
        assert!(
            distance(centres[2 + j], *own) < distance(centres[2 + j], other),
            "{centres:?}"
        );
    }
}

#[test]
fn labels_keep_off_rows_and_lines_where_there_is_room() {
    let frame = frame();
    let h = LABEL_PX / frame.px;
    let text = "max p = 2125 MPa at x = 100 µm, y = 107 µm";
    let half_width = 0.5 * (text.chars().count() as f64 * CHAR_PX + 10.0) / frame.px;
    let clear_of = |centre: (f64, f64), (u, v): (f64, f64)| {
        (centre.0 - u).abs() >= half_width || (centre.1 - v).abs() >= 0.5 * h
    };
    // A title row where the label is wanted.
    let rows = [(
        (0.0, 0.5),
        "step 1 of 10: W = 0.05 N: 4 spots, 0.543 % in contact",
    )];
    let avoid = Avoid {
        labels: &rows,
        ..Avoid::default()
    };
    let centre = place_labels(&frame, &[((0.0, 0.5), text)], &avoid)[0];
    assert!((centre.1 - 0.5).abs() >= h - 1e-12, "{centre:?}");
    // An outline through the wanted place: the label moves off it.
    let outline: Vec<(f64, f64)> = (0..=40)
        .map(|i| (-1.0 + 0.05 * f64::from(i), 0.5))
        .collect();
    let avoid = Avoid {
        lines: &outline,
        ..Avoid::default()
    };
    let centre = place_labels(&frame, &[((0.0, 0.5), text)], &avoid)[0];
    assert!(outline.iter().all(|&p| clear_of(centre, p)), "{centre:?}");
    // Lines everywhere: the label stays where it is wanted.
    let everywhere: Vec<(f64, f64)> = (0..=400)
        .flat_map(|i| {
            (0..=40).map(move |j| (-1.0 + 0.005 * f64::from(i), -0.8 + 0.05 * f64::from(j)))
        })
        .collect();
    let avoid = Avoid {
        lines: &everywhere,
        ..Avoid::default()
    };
    assert_eq!(
        place_labels(&frame, &[((0.0, 0.5), text)], &avoid)[0],
        (0.0, 0.5)
    );
}

#[test]
fn labels_near_a_side_stay_inside_the_map() {
    let frame = frame();
    let text = "max τxz = 0.113 p0 at x = −1.00a, z = 0.680a";
    let centres = place_labels(&frame, &[((frame.u.0, 0.5), text)], &Avoid::default());
    let half_width = 0.5 * (text.chars().count() as f64 * CHAR_PX + 10.0) / frame.px;
    assert!(
        (centres[0].0 - (frame.u.0 + half_width)).abs() < 1e-12,
        "{centres:?}"
    );
    let centres = place_labels(&frame, &[((frame.u.1, 0.5), text)], &Avoid::default());
    assert!(
        centres[0].0 + half_width <= frame.bar.0 + 1e-12,
        "{centres:?}"
    );
}

#[test]
fn tick_labels_share_their_decimals() {
    assert_eq!(
        tick_texts(&[0.0, 0.2, 0.4, 0.6, 0.8, 1.0]),
        ["0.0", "0.2", "0.4", "0.6", "0.8", "1.0"]
    );
    assert_eq!(
        tick_texts(&[-0.2, -0.1, 0.0, 0.1, 0.2]),
        ["\u{2212}0.2", "\u{2212}0.1", "0.0", "0.1", "0.2"]
    );
    assert_eq!(tick_texts(&[0.0, 500.0, 1000.0]), ["0", "500", "1000"]);
    assert_eq!(tick_texts(&[0.0, 0.05, 0.1]), ["0.00", "0.05", "0.10"]);
}

#[test]
fn captions_give_the_name_and_the_unit() {
    assert_eq!(name_and_unit("σvM / p0"), ("σvM".into(), " p0".into()));
    assert_eq!(name_and_unit("p (MPa)"), ("p".into(), " MPa".into()));
    assert_eq!(
        name_and_unit("height (µm)"),
        ("height".into(), " µm".into())
    );
    assert_eq!(name_and_unit("x/a"), ("x".into(), "a".into()));
    assert_eq!(name_and_unit("y (mm)"), ("y".into(), " mm".into()));
    assert_eq!(name_and_unit("spots"), ("spots".into(), String::new()));
}

fn map_figure(vertical_is_depth: bool) -> Figure {
    Figure {
        title: "map".into(),
        panels: vec![Panel {
            subtitle: String::new(),
            x: crate::field::Axis::new(0.0, 2.0, 3),
            z: crate::field::Axis::new(10.0, 30.0, 3),
            // Row k is at the vertical coordinate 10 + 10k.
            values: ndarray::Array2::from_shape_fn((3, 3), |(row, column)| {
                (10 * row + column) as f64
            }),
            traction: Vec::new(),
            half_width: 0.0,
            outlines: vec![vec![(0.0, 10.0), (1.0, 20.0)]],
            scale: None,
            peak: None,
            axes: None,
        }],
        value_label: "p (MPa)".into(),
        x_label: "x (µm)".into(),
        z_label: "y (µm)".into(),
        vertical_is_depth,
        traction_label: String::new(),
        colormap: ColorMap::Inferno,
        levels: crate::render::Levels::Count(0),
        mark: Mark::Max,
        panel_width_px: 400,
    }
}

#[test]
fn a_map_seen_from_above_is_drawn_with_y_up_and_labelled_in_its_own_coordinates() {
    let figure = map_figure(false);
    let shown = displayed(&figure, &figure.panels[0]);
    // The view's vertical axis points down: the largest y (row 2) is the top row, at −30.
    assert_eq!(shown.values[[0, 1]], 21.0);
    assert_eq!(shown.values[[2, 1]], 1.0);
    assert_eq!((shown.z.min, shown.z.max), (-30.0, -10.0));
    assert_eq!(shown.outlines[0], vec![(0.0, -10.0), (1.0, -20.0)]);
    // The maximum, found on the drawn map, is labelled where it is on the figure.
    let (largest, _) = extremes(&shown, Mark::Max);
    let e = largest.expect("a maximum");
    assert_eq!(e.value, 22.0);
    let notation = Notation::of(&figure, &figure.panels[0]);
    assert_eq!(notation.value(e.value), "22.0 MPa");
    assert_eq!(notation.position(e.u, e.v), "x = 2.00 µm, y = 30.0 µm");
    // A section in depth is drawn as it is.
    let depth = map_figure(true);
    let same = displayed(&depth, &depth.panels[0]);
    assert_eq!(same.values, depth.panels[0].values);
    assert_eq!(same.z, depth.panels[0].z);
}

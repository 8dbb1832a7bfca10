//! Tests of the figure renderer: layout, colour scales, marks, PNG and SVG.

use super::layout::PanelLayout;
use super::*;

/// A smooth bump centred at (`x0`, 0.8), the value 1 at its centre.
fn bump(x0: f64) -> impl Fn(f64, f64) -> f64 {
    move |x, z| (-((x - x0).powi(2) + (z - 0.8).powi(2)) / 0.5).exp()
}

fn panel(subtitle: &str, f: impl Fn(f64, f64) -> f64) -> Panel {
    let (x, z) = (Axis::new(-2.0, 2.0, 161), Axis::new(0.0, 1.6, 65));
    let values = Array2::from_shape_fn((z.count, x.count), |(iz, ix)| f(x.value(ix), z.value(iz)));
    let traction = (0..=200)
        .map(|i| {
            let x = -2.0 + 4.0 * i as f64 / 200.0;
            let p = (1.0 - x * x).max(0.0).sqrt();
            TractionSample { x, p, q: 0.2 * p }
        })
        .collect();
    Panel {
        subtitle: subtitle.to_string(),
        x,
        z,
        values,
        traction,
        half_width: 1.0,
        outlines: Vec::new(),
        scale: None,
        peak: None,
        axes: None,
    }
}

fn figure(levels: Levels, mark: Mark) -> Figure {
    Figure {
        title: "Test bumps τ1".to_string(),
        panels: vec![
            panel("left, μ = 0", bump(-0.5)),
            panel("right", |x, z| 0.5 * bump(0.5)(x, z)),
        ],
        value_label: "τ1 / p0".to_string(),
        x_label: "x/a".to_string(),
        z_label: "z/a".to_string(),
        vertical_is_depth: true,
        traction_label: "p, q / p0".to_string(),
        colormap: ColorMap::Viridis,
        levels,
        mark,
        panel_width_px: 300,
    }
}

fn expected_colour(map: ColorMap, t: f64) -> [u8; 3] {
    colormap::eval(map, t)
}

fn close(a: [u8; 3], b: [u8; 3], tolerance: u8) -> bool {
    a.iter().zip(b).all(|(x, y)| x.abs_diff(y) <= tolerance)
}

#[test]
fn png_has_the_layout_size_and_equal_aspect_maps() {
    let figure = figure(Levels::Count(6), Mark::Max);
    let image = render_png(&figure).expect("render");
    let plan = Plan::new(&figure).expect("plan");
    let layout = &plan.layout;
    assert_eq!(image.dimensions(), (layout.width, layout.height));
    for panel in &layout.panels {
        assert_eq!(panel.map.w, 300);
        // 4 wide, 1.6 deep: 120 px.
        assert_eq!(panel.map.h, 120);
    }
    // Side by side, same row, strip directly above its map.
    let (a, b) = (&layout.panels[0], &layout.panels[1]);
    assert_eq!(a.map.y, b.map.y);
    assert!(a.map.right() < b.map.x);
    assert!(a.strip.bottom() < a.map.y && a.strip.x == a.map.x && a.strip.w == a.map.w);
    assert!(b.map.right() < layout.colorbars[0].rect.x);
    assert!(layout.title_baseline < layout.subtitle_baseline);
    assert!(layout.subtitle_baseline < f64::from(a.strip.y));
}

#[test]
fn margins_stay_white() {
    assert_margins_white(&render_png(&figure(Levels::Count(6), Mark::Both)).expect("render"));
    assert_margins_white(&render_png(&compared(Mark::Both)).expect("render"));
}

fn assert_margins_white(image: &image::RgbImage) {
    let (w, h) = image.dimensions();
    let white = |x: u32, y: u32| image.get_pixel(x, y).0 == [255, 255, 255];
    for x in 0..w {
        assert!(
            white(x, 0) && white(x, h - 1),
            "ink at the top or bottom edge, x = {x}"
        );
    }
    for y in 0..h {
        assert!(
            white(0, y) && white(w - 1, y),
            "ink at the left or right edge, y = {y}"
        );
    }
}

#[test]
fn map_pixels_have_the_colour_of_their_value() {
    // No contours and no marks: the map shows the colour scale alone.
    let figure = figure(Levels::Values(Vec::new()), Mark::None);
    let image = render_png(&figure).expect("render");
    let plan = Plan::new(&figure).expect("plan");
    // The scale spans [0, 1]: the left bump peaks at 1.
    for (panel, layout) in figure.panels.iter().zip(&plan.layout.panels) {
        for (fx, fz) in [(0.5, 0.5), (0.3, 0.7), (0.8, 0.2), (0.1, 0.9)] {
            let px = layout.map.x + (fx * f64::from(layout.map.w)) as i32;
            let pz = layout.map.y + (fz * f64::from(layout.map.h)) as i32;
            let x = layout.data_x(f64::from(px) + 0.5);
            let z = layout.data_z(f64::from(pz) + 0.5);
            let value = (panel.values[[0, 0]] * 0.0) + {
                // The analytic field (the grid is fine enough for bilinear to agree).
                let left = bump(-0.5)(x, z);
                if std::ptr::eq(panel, &figure.panels[0]) {
                    left
                } else {
                    0.5 * bump(0.5)(x, z)
                }
            };
            let expected = expected_colour(ColorMap::Viridis, value);
            let got = image.get_pixel(px as u32, pz as u32).0;
            assert!(
                close(got, expected, 6),
                "({x:.2}, {z:.2}) = {value:.3}: {got:?} vs {expected:?}"
            );
        }
    }
}

#[test]
fn contour_lines_darken_the_map_on_their_level() {
    let figure = Figure {
        panels: vec![panel("", bump(0.0))],
        ..figure(Levels::Values(vec![0.5]), Mark::None)
    };
    let image = render_png(&figure).expect("render");
    let plan = Plan::new(&figure).expect("plan");
    let layout = &plan.layout.panels[0];
    // exp(-r^2 / 0.5) = 0.5 on the circle r = sqrt(0.5 ln 2) around (0, 0.8).
    let r = (0.5 * 2f64.ln()).sqrt();
    let mut dark = 0;
    for k in 0..16 {
        let angle = std::f64::consts::TAU * k as f64 / 16.0;
        let (x, z) = (r * angle.cos(), 0.8 + r * angle.sin());
        let (px, pz) = (layout.px(x).floor() as u32, layout.pz(z).floor() as u32);
        let plain = expected_colour(ColorMap::Viridis, 0.5);
        let got = image.get_pixel(px, pz).0;
        if got
            .iter()
            .zip(plain)
            .all(|(g, p)| u16::from(*g) + 30 < u16::from(p) || p < 40)
        {
            dark += 1;
        }
    }
    // A label may cover a stretch of the line.
    assert!(
        dark >= 12,
        "only {dark} of 16 points on the isoline are dark"
    );
}

#[test]
fn diverging_maps_show_compression_blue_and_zero_white() {
    let figure = Figure {
        panels: vec![panel("", |x, _| -x)],
        colormap: ColorMap::Diverging,
        ..figure(Levels::Values(Vec::new()), Mark::None)
    };
    let image = render_png(&figure).expect("render");
    let plan = Plan::new(&figure).expect("plan");
    let map = plan.layout.panels[0].map;
    let row = (map.y + map.h / 2) as u32;
    // x = 1.5: value -1.5 (compression) is blue; x = 0 white.
    let [r, g, b] = image.get_pixel((map.x + map.w * 7 / 8) as u32, row).0;
    assert!(b > 100 && b > r + 40 && b > g, "{:?}", [r, g, b]);
    let centre = image.get_pixel((map.x + map.w / 2) as u32, row).0;
    assert!(centre.iter().all(|c| *c > 235), "{centre:?}");
}

#[test]
fn svg_shows_the_same_figure() {
    let figure = figure(Levels::Count(6), Mark::Max);
    let svg = render_svg(&figure).expect("svg");
    let image = render_png(&figure).expect("png");
    assert!(svg.starts_with("<svg"));
    assert!(svg.contains(&format!(
        "width=\"{}\" height=\"{}\"",
        image.width(),
        image.height()
    )));
    for text in [
        "Test bumps τ1",
        "left, μ = 0",
        "x/a",
        "z/a",
        "τ1 / p0",
        "p, q / p0",
        "max 1.00 p0 at x = \u{2212}0.50a, z = 0.80a",
    ] {
        assert!(svg.contains(text), "no `{text}` in the SVG");
    }
    // Two heat maps and the colour bar, embedded once each.
    assert_eq!(svg.matches("<image").count(), 3);
    assert!(svg.len() < 2_000_000, "{} bytes", svg.len());
}

#[test]
fn rendering_is_deterministic_and_png_round_trips() {
    let figure = figure(Levels::Count(8), Mark::Both);
    let a = render_png(&figure).expect("render");
    let b = render_png(&figure).expect("render");
    assert!(a == b);
    let bytes = encode_png(&a).expect("encode");
    assert!(bytes.starts_with(b"\x89PNG"));
    let decoded = image::load_from_memory(&bytes).expect("decode").to_rgb8();
    assert!(decoded == a);
}

#[test]
fn bad_figures_are_errors() {
    let empty = Figure {
        panels: Vec::new(),
        ..figure(Levels::Count(5), Mark::Max)
    };
    assert!(matches!(render_png(&empty), Err(RenderError::NoPanels)));
    let mut wrong = figure(Levels::Count(5), Mark::Max);
    wrong.panels[1].values = Array2::zeros((3, 3));
    match render_svg(&wrong) {
        Err(RenderError::Draw(message)) => assert!(message.contains("panel 2"), "{message}"),
        other => panic!("expected an error, got {:?}", other.map(|s| s.len())),
    }
}

/// The difference of [`compared`]: small and signed, 0 at x = 0.
fn difference(x: f64, z: f64) -> f64 {
    0.01 * x * (1.0 + 0.2 * z)
}

/// The scale of the difference panel of [`compared`].
fn difference_scale() -> PanelScale {
    PanelScale {
        value_label: "Δτ1 / p0".to_string(),
        colormap: ColorMap::Diverging,
        levels: Levels::Count(4),
        range: None,
    }
}

/// "closed form" and "numerical" on the shared scale, then "their difference" on its own.
fn compared(mark: Mark) -> Figure {
    let exact = bump(-0.5);
    let numerical = move |x, z| exact(x, z) + difference(x, z);
    Figure {
        panels: vec![
            panel("closed form", bump(-0.5)),
            panel("numerical", numerical),
            Panel {
                scale: Some(difference_scale()),
                ..panel("numerical − closed form", difference)
            },
        ],
        ..figure(Levels::Count(6), mark)
    }
}

/// Whether the columns `x0..x1` are white over the rows `y0..y1`.
fn white_columns(image: &image::RgbImage, x0: i32, x1: i32, y0: i32, y1: i32) -> bool {
    (x0..x1).all(|x| (y0..y1).all(|y| image.get_pixel(x as u32, y as u32).0 == [255; 3]))
}

#[test]
fn a_clipped_colour_range_ends_its_bar_in_triangles_of_the_end_colours() {
    // The difference spans ±0.024 (0.01 x (1 + 0.2 z) at x = ±2, z = 1.6); colours to ±0.01.
    let mut figure = compared(Mark::None);
    figure.panels[2].scale = Some(PanelScale {
        range: Some((-0.01, 0.01)),
        ..difference_scale()
    });
    let plan = Plan::new(&figure).expect("plan");
    assert_eq!(plan.groups[0].beyond, [false, false]);
    assert_eq!(plan.groups[1].beyond, [true, true]);
    let image = render_png(&figure).expect("render");
    let bar = plan.layout.colorbars[1].rect;
    let centre = (bar.x + bar.w / 2) as u32;
    let (top, bottom) = (
        plan.groups[1].scale.rgb(0.01),
        plan.groups[1].scale.rgb(-0.01),
    );
    // Just outside the bar's ends, in the middle of the triangles.
    let above = image.get_pixel(centre, (bar.y - bar.w / 3) as u32).0;
    let below = image.get_pixel(centre, (bar.bottom() + bar.w / 3) as u32).0;
    assert_eq!((above, below), (top, bottom));
    // Unclipped: nothing drawn there.
    let unclipped = compared(Mark::None);
    let image = render_png(&unclipped).expect("render");
    let plan = Plan::new(&unclipped).expect("plan");
    let bar = plan.layout.colorbars[1].rect;
    let above = image
        .get_pixel((bar.x + bar.w / 2) as u32, (bar.y - bar.w / 3) as u32)
        .0;
    assert_eq!(above, [255; 3]);
}

#[test]
fn a_panel_with_its_own_scale_gets_its_own_group_and_colour_bar() {
    let figure = compared(Mark::Max);
    let plan = Plan::new(&figure).expect("plan");
    let ranges: Vec<_> = plan.groups.iter().map(|g| g.panels.clone()).collect();
    assert_eq!(ranges, vec![0..2, 2..3]);
    assert_eq!(plan.layout.colorbars.len(), 2);
    assert_eq!(plan.groups[0].value_label, "τ1 / p0");
    assert_eq!(plan.groups[1].value_label, "Δτ1 / p0");

    // Each group's scale spans its own values: the shared one both bumps (the numerical
    // one dips a little below 0 at the left), the difference one ±max |difference|.
    let shared = &plan.groups[0].scale;
    let over = |panels: &[Panel], f: fn(f64, f64) -> f64, start: f64| {
        panels
            .iter()
            .flat_map(|p| p.values.iter())
            .fold(start, |m, v| f(m, *v))
    };
    let shared_panels = &figure.panels[..2];
    assert_eq!(shared.lo, over(shared_panels, f64::min, f64::MAX));
    assert_eq!(shared.hi, over(shared_panels, f64::max, f64::MIN));
    assert!(shared.lo < 0.0 && shared.hi >= 1.0, "{shared:?}");
    let own = &plan.groups[1].scale;
    let largest = difference(2.0, 1.6);
    assert!((own.hi - largest).abs() < 1e-12, "{} vs {largest}", own.hi);
    assert_eq!(own.lo, -own.hi);

    // Contour levels per group, within the group's range.
    let levels = &plan.groups[0].levels;
    assert!(levels.len() >= 4 && levels.iter().all(|l| *l > shared.lo && *l < shared.hi));
    assert!(levels.iter().any(|l| *l > 0.5), "{levels:?}");
    let small = &plan.groups[1].levels;
    assert!(
        small.len() >= 2 && small.iter().all(|l| l.abs() < largest),
        "{small:?}"
    );

    // The difference bar is labelled in its own, small numbers.
    let ticks = &plan.layout.colorbars[1].ticks;
    assert!(ticks.values.contains(&0.0), "{ticks:?}");
    assert!(
        ticks.values.iter().all(|v| v.abs() <= own.hi + 1e-12),
        "{ticks:?}"
    );
}

#[test]
fn each_colour_bar_follows_its_group_and_clears_the_next_panel() {
    let figure = compared(Mark::Both);
    let image = render_png(&figure).expect("render");
    let plan = Plan::new(&figure).expect("plan");
    let layout = &plan.layout;
    assert_eq!(image.dimensions(), (layout.width, layout.height));
    let [a, b, c] = [0, 1, 2].map(|i| &layout.panels[i]);
    let [first, second] = [0, 1].map(|i| &layout.colorbars[i]);

    // Equal aspect, one row, the bars beside the maps of their group.
    for panel in [a, b, c] {
        assert_eq!((panel.map.w, panel.map.h), (300, 120));
        assert_eq!(panel.map.y, a.map.y);
    }
    for bar in [first, second] {
        assert_eq!((bar.rect.y, bar.rect.h), (a.map.y, a.map.h));
    }
    assert!(a.map.right() < b.map.x);
    assert!(b.map.right() < first.rect.x);
    assert!(first.right(layout.label_line) < f64::from(c.map.x));
    assert!(c.map.right() < second.rect.x);
    // A gap between panels of one group is narrower than the one after a bar.
    let within = b.map.x - a.map.right();
    let across = c.map.x - b.map.right();
    assert!(across > within + first.rect.w, "{within} vs {across}");

    // Between the first bar's caption and the next panel's axis numbers (strip and map),
    // nothing: white columns, at least a tick size of them; so no rotated axis label
    // either (only the first panel has one).
    let s = layout.sizes.tick;
    let (top, bottom) = (c.strip.y - 10, c.map.bottom() + 10);
    let numbers = c
        .z_ticks
        .labels
        .iter()
        .chain(&c.strip_ticks.labels)
        .map(|l| font::text_width(l, s).expect("width"))
        .fold(0.0, f64::max);
    let numbers_left = f64::from(c.map.x) - layout.tick_length - layout.tick_gap - numbers;
    let caption_right = first.right(layout.label_line);
    assert!(
        numbers_left - caption_right >= s,
        "{caption_right} .. {numbers_left}"
    );
    let band = (caption_right.ceil() as i32, numbers_left.floor() as i32 - 1);
    assert!(
        white_columns(&image, band.0, band.1, top, bottom),
        "{band:?}"
    );
    // The caption and the numbers are there, just outside the band.
    let ink_left = !white_columns(&image, first.rect.right(), band.0, top, bottom);
    let ink_right = !white_columns(&image, band.1, c.map.x - 1, top, bottom);
    assert!(ink_left && ink_right);

    // The bars show their maps: the shared one viridis (yellow on top), the other
    // diverging (red on top, white in the middle, blue at the bottom).
    let top_of = |bar: &layout::ColorbarLayout, j: i32| {
        image
            .get_pixel(
                (bar.rect.x + bar.rect.w / 2) as u32,
                (bar.rect.y + j) as u32,
            )
            .0
    };
    let yellow = top_of(first, 2);
    let t = 1.0 - 2.5 / f64::from(first.rect.h);
    assert!(
        close(yellow, colormap::eval(ColorMap::Viridis, t), 3),
        "{yellow:?}"
    );
    let [r, g, bl] = top_of(second, 2);
    assert!(r > 80 && r > g + 40 && r > bl + 40, "{:?}", [r, g, bl]);
    // (Just above the middle: the level 0 is marked across it.)
    let middle = top_of(second, second.rect.h / 2 - 3);
    assert!(middle.iter().all(|v| *v > 225), "{middle:?}");
}

#[test]
fn the_difference_map_has_the_colour_of_its_own_scale() {
    let figure = Figure {
        levels: Levels::Values(Vec::new()),
        panels: compared(Mark::None)
            .panels
            .into_iter()
            .map(|p| Panel {
                scale: p.scale.map(|s| PanelScale {
                    levels: Levels::Values(Vec::new()),
                    ..s
                }),
                ..p
            })
            .collect(),
        ..compared(Mark::None)
    };
    let image = render_png(&figure).expect("render");
    let plan = Plan::new(&figure).expect("plan");
    let layout = &plan.layout.panels[2];
    let largest = difference(2.0, 1.6);
    for (fx, fz) in [(0.1, 0.5), (0.3, 0.2), (0.7, 0.8), (0.95, 0.5)] {
        let px = layout.map.x + (fx * f64::from(layout.map.w)) as i32;
        let pz = layout.map.y + (fz * f64::from(layout.map.h)) as i32;
        let x = layout.data_x(f64::from(px) + 0.5);
        let z = layout.data_z(f64::from(pz) + 0.5);
        let t = 0.5 + 0.5 * difference(x, z) / largest;
        let expected = expected_colour(ColorMap::Diverging, t);
        let got = image.get_pixel(px as u32, pz as u32).0;
        assert!(
            close(got, expected, 6),
            "({x:.2}, {z:.2}): {got:?} vs {expected:?}"
        );
    }
}

#[test]
fn panels_group_by_their_resolved_scale() {
    let base = compared(Mark::Max);
    let groups = |panels: Vec<Panel>| -> Vec<std::ops::Range<usize>> {
        let figure = Figure {
            panels,
            ..base.clone()
        };
        let plan = Plan::new(&figure).expect("plan");
        assert_eq!(plan.layout.colorbars.len(), plan.groups.len());
        plan.groups.iter().map(|g| g.panels.clone()).collect()
    };
    let [a, b, d] = [0, 1, 2].map(|i| base.panels[i].clone());
    // All shared: one group, as before panels had scales.
    assert_eq!(groups(vec![a.clone(), b.clone()]), vec![0..2]);
    // A panel's own scale equal to the shared one is the shared one.
    let same = Panel {
        scale: Some(PanelScale {
            value_label: base.value_label.clone(),
            colormap: base.colormap,
            levels: base.levels.clone(),
            range: None,
        }),
        ..b.clone()
    };
    assert_eq!(groups(vec![a.clone(), same]), vec![0..2]);
    // Only neighbours group: the shared scale on both sides of a difference is two groups.
    assert_eq!(
        groups(vec![a.clone(), d.clone(), b.clone()]),
        vec![0..1, 1..2, 2..3]
    );
    assert_eq!(groups(vec![d.clone(), d, a, b]), vec![0..2, 2..4]);
}

#[test]
fn svg_shows_every_colour_bar() {
    let figure = compared(Mark::Max);
    let svg = render_svg(&figure).expect("svg");
    let image = render_png(&figure).expect("png");
    assert!(svg.contains(&format!(
        "width=\"{}\" height=\"{}\"",
        image.width(),
        image.height()
    )));
    for text in [
        "τ1 / p0",
        "Δτ1 / p0",
        "numerical − closed form",
        "closed form",
    ] {
        assert!(svg.contains(text), "no `{text}` in the SVG");
    }
    // Three heat maps and two colour bars.
    assert_eq!(svg.matches("<image").count(), 5);
}

#[test]
fn non_finite_values_do_not_break_the_figure() {
    let mut figure = figure(Levels::Count(5), Mark::Max);
    figure.panels[0].values[[10, 10]] = f64::NAN;
    figure.panels[1].values.fill(f64::NAN);
    let image = render_png(&figure).expect("render");
    assert!(image.width() > 0);
}

/// Panels in different planes (issue 23, item 13): a depth section, a plane parallel to the
/// surface (y up, no strip, taller) and another depth section, on one colour scale. Each
/// keeps its own axes: the plan view draws no strip and its own vertical caption, the section
/// after it its captions again, with room for them; the colour bar spans the tallest map and
/// each horizontal caption sits under its own map.
#[test]
fn panels_in_different_planes_keep_their_axes_on_one_scale() {
    let plan_view = Panel {
        z: Axis::new(-2.0, 2.0, 161),
        values: Array2::from_shape_fn((161, 161), |(iy, ix)| {
            0.8 * bump(0.0)(-2.0 + 0.025 * ix as f64, 0.8 - 2.0 + 0.025 * iy as f64)
        }),
        traction: Vec::new(),
        axes: Some(PanelAxes {
            x_label: "x/a".into(),
            z_label: "y/a".into(),
            vertical_is_depth: false,
        }),
        ..panel("plane z = 0.5a", bump(0.0))
    };
    let across = Panel {
        axes: Some(PanelAxes {
            x_label: "y/a".into(),
            z_label: "z/a".into(),
            vertical_is_depth: true,
        }),
        ..panel("yz plane", |x, z| 0.6 * bump(0.0)(x, z))
    };
    let base = figure(Levels::Count(6), Mark::Max);
    let uniform = Plan::new(&base).expect("plan").layout;
    let figure = Figure {
        panels: vec![base.panels[0].clone(), plan_view, across],
        ..base
    };
    assert_eq!(figure.colour_ranges(), vec![(0..3, (0.0, 1.0))]);
    let plan = Plan::new(&figure).expect("plan");
    let layout = &plan.layout;
    let [xz, xy, yz] = [0, 1, 2].map(|i| &layout.panels[i]);
    assert_eq!(
        [xz.strip_drawn, xy.strip_drawn, yz.strip_drawn],
        [true, false, true]
    );
    assert_eq!([xz.new_axes, xy.new_axes, yz.new_axes], [true, true, true]);
    assert!(xz.z_down && !xy.z_down && yz.z_down);
    // y upwards in the plan view: its top row is y = 2.
    assert!((xy.pz(2.0) - f64::from(xy.map.y)).abs() < 1e-9);
    // Room for the captions left of the plan view: wider apart than two sections.
    let gap = |a: &PanelLayout, b: &PanelLayout| b.map.x - a.map.right();
    let uniform_gap = gap(&uniform.panels[0], &uniform.panels[1]);
    assert!(
        gap(xz, xy) > uniform_gap + 10,
        "{} vs {uniform_gap}",
        gap(xz, xy)
    );
    // One colour bar, as tall as the tallest map (the square plan view).
    assert_eq!(layout.colorbars.len(), 1);
    assert_eq!(layout.colorbars[0].rect.h, xy.map.h);
    assert!(xy.map.h > xz.map.h);
    assert!(xz.x_label_baseline < xy.x_label_baseline);
    assert_eq!(xz.x_label_baseline, yz.x_label_baseline);
    // The marks are written in each panel's coordinates.
    let labels: Vec<&str> = plan
        .panels
        .iter()
        .flat_map(|p| &p.extremes)
        .map(|e| e.label.text.as_str())
        .collect();
    assert_eq!(labels.len(), 3, "{labels:?}");
    assert!(
        labels[0].contains("x = ") && labels[0].contains("z = "),
        "{labels:?}"
    );
    assert!(
        labels[1].contains("x = ") && labels[1].contains("y = "),
        "{labels:?}"
    );
    assert!(
        labels[2].contains("y = ") && labels[2].contains("z = "),
        "{labels:?}"
    );
    render_png(&figure).expect("renders");
    render_svg(&figure).expect("renders");
}

//! The `[volume]` of a scene in a 3-D view: nested iso-surfaces of the quantity (translucent
//! shells at a few fractions of its largest value, coloured on the figure's colour map) in the
//! half of the box behind the plane `y = 0`, so that the cut shows how they nest, closed by
//! caps where the box cuts them; the contact patch's front half on the surface shaded by the
//! pressure; the axes and the traction's direction (trailing edge at x = −a); the maximum the
//! report gives, labelled above the surface with a leader; and an initial camera that looks
//! at the patch from above, at an angle.
//!
//! z points down (into the body), in the figure's length unit.

use rerun::RecordingStream;

use super::isosurface::{isosurface, Mesh};
use super::layout::Eye;
use super::section::{position_text_3d, stress_text};
use super::RecordError;
use crate::render::colormap::ColorScale;
use crate::render::ColorMap;
use crate::scene::{ContactKind, Scene, VolumeSpec};
use crate::stress::QuantityKind;
use crate::study::volume::{half, Grid};

/// The iso-levels: from the scene's threshold to 90 % of `largest`, at most four; for a
/// signed quantity the same sizes on both sides of zero.
pub fn levels(spec: &VolumeSpec, largest: f64) -> Vec<f64> {
    let lowest = spec.threshold.clamp(0.05, 0.85);
    let count = 4;
    let sizes: Vec<f64> = (0..count)
        .map(|k| largest * (lowest + (0.9 - lowest) * k as f64 / (count - 1) as f64))
        .collect();
    match spec.quantity.kind() {
        QuantityKind::Signed => sizes
            .iter()
            .rev()
            .map(|s| -s)
            .chain(sizes.iter().copied())
            .collect(),
        _ => sizes,
    }
}

/// The colour scale of the shells.
pub fn scale(scene: &Scene, spec: &VolumeSpec, largest: f64) -> ColorScale {
    match spec.quantity.kind() {
        QuantityKind::Signed => ColorScale::for_range(ColorMap::Diverging, -largest, largest),
        _ => ColorScale::for_range(scene.figure.colormap, 0.0, largest),
    }
}

/// The camera: above the surface (z < 0), in front of the cut (y > 0, so that +x runs to the
/// right) and towards the trailing edge, looking at a point below the patch.
pub fn eye(spec: &VolumeSpec) -> Eye {
    let (width, depth) = (spec.x.1 - spec.x.0, spec.z.1 - spec.z.0);
    let size = width.max(spec.y.1 - spec.y.0).max(depth);
    let target = [
        0.5 * (spec.x.0 + spec.x.1),
        half(spec).1,
        spec.z.0 + 0.45 * depth,
    ];
    // About 25 degrees above the surface, a little towards the trailing edge, far enough
    // back that the box's near corner, where the axes start, and its ticked edges stay in
    // view.
    Eye {
        position: [
            (target[0] - 0.4 * size) as f32,
            (target[1] + 1.45 * size) as f32,
            (target[2] - 0.85 * size) as f32,
        ],
        target: target.map(|c| c as f32),
        up: [0.0, 0.0, -1.0],
    }
}

/// Logs what stays: the view's axes (z down), the outline of the box's top face and ticks
/// with their values along its near edges (x along the front of the surface, y along its left
/// side, z down the near corner).
pub fn log_static(
    stream: &RecordingStream,
    scene: &Scene,
    spec: &VolumeSpec,
) -> Result<(), RecordError> {
    stream.log_static("volume", &rerun::ViewCoordinates::RIGHT_HAND_Z_DOWN())?;
    let (x0, x1) = (spec.x.0 as f32, spec.x.1 as f32);
    let (y0, y1) = (spec.y.0 as f32, spec.y.1 as f32);
    let top = [
        [x0, y0, 0.0],
        [x1, y0, 0.0],
        [x1, y1, 0.0],
        [x0, y1, 0.0],
        [x0, y0, 0.0],
    ];
    stream.log_static(
        "volume/surface",
        &rerun::LineStrips3D::new([top])
            .with_colors([rerun::Color::from_rgb(150, 150, 150)])
            .with_radii([rerun::Radius::new_ui_points(0.75)]),
    )?;
    // The axes from the box's near corner (z down, into the body).
    let length = 0.2 * (x1 - x0).min(y1 - y0);
    let corner = [x0, y1, 0.0];
    stream.log_static(
        "volume/axes",
        &rerun::Arrows3D::from_vectors([
            [length, 0.0, 0.0],
            [0.0, length, 0.0],
            [0.0, 0.0, length],
        ])
        .with_origins([corner; 3])
        .with_colors([
            rerun::Color::from_rgb(230, 80, 80),
            rerun::Color::from_rgb(80, 200, 80),
            rerun::Color::from_rgb(90, 140, 255),
        ])
        .with_labels(["x", "y", "z (depth)"])
        .with_show_labels(true),
    )?;
    log_ticks(stream, scene, spec)
}

/// Ticks along the box's near edges, each labelled with its value and the length unit.
fn log_ticks(
    stream: &RecordingStream,
    scene: &Scene,
    spec: &VolumeSpec,
) -> Result<(), RecordError> {
    let suffix = scene.figure.length_unit.suffix();
    let tick = 0.02 * (spec.x.1 - spec.x.0).max(spec.y.1 - spec.y.0);
    let (x0, y0, y1) = (spec.x.0, spec.y.0, spec.y.1);
    let mut strips: Vec<[[f32; 3]; 2]> = Vec::new();
    let mut anchors: Vec<[f32; 3]> = Vec::new();
    let mut labels: Vec<String> = Vec::new();
    let point = |p: [f64; 3]| p.map(|c| c as f32);
    let text = |v: f64| format!("{}{suffix}", super::section::short(v));
    // x along the front edge (y = y1), ticks pointing out of the box.
    // No labels at the near corner, where the axes' own labels are (its ticks are the edges'
    // first values: x0, y1 and the surface).
    let away = |c: f64, corner: f64, span: f64| (c - corner).abs() > 1e-9 * span.abs().max(1.0);
    for x in super::section::nice_ticks(spec.x.0, spec.x.1, 5)
        .into_iter()
        .filter(|&x| away(x, x0, spec.x.1 - spec.x.0))
    {
        strips.push([point([x, y1, 0.0]), point([x, y1 + tick, 0.0])]);
        anchors.push(point([x, y1 + 3.0 * tick, 0.0]));
        labels.push(format!("x = {}", text(x)));
    }
    // y along the left edge (x = x0).
    for y in super::section::nice_ticks(y0, y1, 3)
        .into_iter()
        .filter(|&y| away(y, y1, y1 - y0))
    {
        strips.push([point([x0, y, 0.0]), point([x0 - tick, y, 0.0])]);
        anchors.push(point([x0 - 3.0 * tick, y, 0.0]));
        labels.push(format!("y = {}", text(y)));
    }
    // z down the near corner (x0, y1).
    for z in super::section::nice_ticks(spec.z.0, spec.z.1, 4)
        .into_iter()
        .filter(|&z| away(z, spec.z.0, spec.z.1 - spec.z.0))
    {
        strips.push([point([x0, y1, z]), point([x0 - tick, y1 + tick, z])]);
        anchors.push(point([x0 - 3.0 * tick, y1 + 3.0 * tick, z]));
        labels.push(format!("z = {}", text(z)));
    }
    // The box's near vertical edge, down which z is ticked.
    strips.push([point([x0, y1, spec.z.0]), point([x0, y1, spec.z.1])]);
    let grey = rerun::Color::from_rgb(170, 170, 170);
    stream.log_static(
        "volume/ticks",
        &rerun::LineStrips3D::new(strips)
            .with_colors([grey])
            .with_radii([rerun::Radius::new_ui_points(0.75)]),
    )?;
    stream.log_static(
        "volume/ticks/labels",
        &rerun::Points3D::new(anchors)
            .with_radii([rerun::Radius::new_ui_points(0.0)])
            .with_colors([rerun::Color::from_rgb(210, 210, 210)])
            .with_labels(labels)
            .with_show_labels(true),
    )?;
    Ok(())
}

/// The direction of the traction on the body, above the patch: `q = μp` in +x, the trailing
/// edge at x = −a (a scene without friction draws none).
fn log_traction_direction(
    stream: &RecordingStream,
    scene: &Scene,
    spec: &VolumeSpec,
) -> Result<(), RecordError> {
    if scene.contact.friction == 0.0 {
        stream.log("volume/traction", &rerun::Clear::flat())?;
        return Ok(());
    }
    let unit_over_a = scene.length_unit_over_a();
    let centre = scene.load_centre_over_a;
    let from = ((centre - 1.0) / unit_over_a) as f32;
    let length = (2.0 / unit_over_a) as f32;
    // In front of the patch (y > 0), a hair above the surface.
    let lift = (-0.01 * (spec.z.1 - spec.z.0)) as f32;
    let front = (1.3 * scene.contact.aspect / unit_over_a) as f32;
    stream.log(
        "volume/traction",
        &rerun::Arrows3D::from_vectors([[length, 0.0, 0.0]])
            .with_origins([[from, front, lift]])
            .with_colors([rerun::Color::from_rgb(255, 210, 60)])
            .with_labels([format!(
                "q = μp on the body, +x (μ = {}); trailing edge x = −a",
                crate::io::text::number(scene.contact.friction)
            )])
            .with_show_labels(true),
    )?;
    Ok(())
}

/// Logs the step's shells (one mesh per level), the contact patch and the maximum. Returns the
/// number of triangles.
pub fn log_step(
    stream: &RecordingStream,
    scene: &Scene,
    spec: &VolumeSpec,
    grid: &Grid,
    levels: &[f64],
    scale: &ColorScale,
) -> Result<usize, RecordError> {
    let mut triangles = 0;
    let closed = closed(spec, grid);
    for (m, &level) in levels.iter().enumerate() {
        // The region beyond a negative level is below it: the surface of the negated field.
        let mesh: Mesh = if level < 0.0 {
            isosurface(
                closed.values.mapv(|v| -v).view(),
                &closed.x,
                &closed.y,
                &closed.z,
                -level,
            )
        } else {
            isosurface(closed.values.view(), &closed.x, &closed.y, &closed.z, level)
        };
        let path = format!("volume/iso/{m}");
        if mesh.triangles.is_empty() {
            stream.log(path, &rerun::Clear::flat())?;
            continue;
        }
        triangles += mesh.triangles.len();
        // Outer shells more transparent than inner ones.
        let depth_in = (level.abs() / levels.iter().fold(0.0f64, |a, l| a.max(l.abs()))).min(1.0);
        let alpha = (255.0 * (0.5 + 0.5 * depth_in * depth_in)).round() as u8;
        let [r, g, b] = scale.rgb(level);
        stream.log(
            path,
            &rerun::Mesh3D::new(mesh.positions)
                .with_vertex_normals(mesh.normals)
                .with_triangle_indices(mesh.triangles)
                .with_albedo_factor(rerun::Rgba32::from_unmultiplied_rgba(r, g, b, alpha)),
        )?;
    }
    if matches!(
        scene.contact.kind,
        ContactKind::Point | ContactKind::Elliptical
    ) {
        let unit_over_a = scene.length_unit_over_a();
        let (aspect, centre) = (scene.contact.aspect, scene.load_centre_over_a);
        let outline: Vec<[f32; 3]> = (0..=256)
            .map(|i| {
                let angle = std::f64::consts::TAU * f64::from(i) / 256.0;
                [
                    ((centre + angle.cos()) / unit_over_a) as f32,
                    (aspect * angle.sin() / unit_over_a) as f32,
                    0.0,
                ]
            })
            .collect();
        stream.log(
            "volume/contact",
            &rerun::LineStrips3D::new([outline])
                .with_colors([rerun::Color::from_rgb(240, 240, 240)])
                .with_radii([rerun::Radius::new_ui_points(1.5)]),
        )?;
        stream.log("volume/contact/patch", &contact_patch(scene, spec))?;
        log_traction_direction(stream, scene, spec)?;
    }
    if let Some((value, at)) = crate::study::volume::maximum(scene, spec, grid) {
        let position = at.map(|c| c as f32);
        // The label above the surface, with a leader down to the point, so that it covers
        // no shell.
        let depth = (spec.z.1 - spec.z.0) as f32;
        let label_at = [position[0], position[1], -0.3 * depth];
        stream.log(
            "volume/maximum",
            &rerun::Points3D::new([position])
                .with_radii([rerun::Radius::new_ui_points(5.0)])
                .with_colors([rerun::Color::from_rgb(255, 255, 255)]),
        )?;
        stream.log(
            "volume/maximum/leader",
            &rerun::LineStrips3D::new([[label_at, position]])
                .with_colors([rerun::Color::from_rgb(255, 255, 255)])
                .with_radii([rerun::Radius::new_ui_points(0.75)]),
        )?;
        stream.log(
            "volume/maximum/label",
            &rerun::Points3D::new([label_at])
                .with_radii([rerun::Radius::new_ui_points(1.0)])
                .with_colors([rerun::Color::from_rgb(255, 255, 255)])
                .with_labels([format!(
                    "max {} = {} at {}",
                    spec.quantity.symbol(),
                    stress_text(scene, value),
                    position_text_3d(scene, position)
                )])
                .with_show_labels(true),
        )?;
    }
    Ok(triangles)
}

/// The grid with a layer of zeros a hair outside its bottom, its ends in x and its far side in
/// y (not at the surface, nor at the cut y = 0, where the shells show how they nest), so that
/// a shell the box cuts is closed by a cap on the box's face instead of left open.
fn closed(spec: &VolumeSpec, grid: &Grid) -> Grid {
    let cut = spec.y.0 < 0.0 && spec.y.1 > 0.0;
    let beyond = |axis: &[f64], first: bool, last: bool| {
        let hair = 1e-3
            * (axis[axis.len() - 1] - axis[0])
                .abs()
                .max(f64::MIN_POSITIVE);
        let mut out = Vec::with_capacity(axis.len() + 2);
        if first {
            out.push(axis[0] - hair);
        }
        out.extend_from_slice(axis);
        if last {
            out.push(axis[axis.len() - 1] + hair);
        }
        out
    };
    let x = beyond(&grid.x, true, true);
    let y = beyond(&grid.y, true, !cut);
    let z = beyond(&grid.z, false, true);
    let y_offset = 1;
    let mut values = ndarray::Array3::<f32>::zeros((z.len(), y.len(), x.len()));
    for ((k, j, i), &v) in grid.values.indexed_iter() {
        values[[k, j + y_offset, i + 1]] = v;
    }
    Grid { values, x, y, z }
}

/// The contact patch on the surface (its half y >= 0) as a mesh of rings, shaded by the Hertz pressure
/// `p/p0 = sqrt(1 - r²)` (white at the edge, dark red at the centre), in the figure's length
/// unit at the load's position, a hair above the surface so that the shells do not hide it.
fn contact_patch(scene: &Scene, spec: &VolumeSpec) -> rerun::Mesh3D {
    const RINGS: usize = 12;
    const SEGMENTS: usize = 96;
    let unit_over_a = scene.length_unit_over_a();
    let (aspect, centre) = (scene.contact.aspect, scene.load_centre_over_a);
    let lift = (-0.003 * (spec.z.1 - spec.z.0)) as f32;
    let shade = |r: f64| {
        let p = (1.0 - r * r).max(0.0).sqrt();
        let mix = |white: f64, dark: f64| (white + (dark - white) * p).round() as u8;
        rerun::Color::from_rgb(mix(255.0, 150.0), mix(255.0, 20.0), mix(255.0, 20.0))
    };
    let mut positions = vec![[(centre / unit_over_a) as f32, 0.0, lift]];
    let mut colors = vec![shade(0.0)];
    for ring in 1..=RINGS {
        let r = ring as f64 / RINGS as f64;
        for k in 0..SEGMENTS {
            // The half y >= 0 in front of the cut: the shells behind it stay uncovered.
            let angle = std::f64::consts::PI * (k as f64 / (SEGMENTS - 1) as f64);
            positions.push([
                ((centre + r * angle.cos()) / unit_over_a) as f32,
                (aspect * r * angle.sin() / unit_over_a) as f32,
                lift,
            ]);
            colors.push(shade(r));
        }
    }
    // Vertex of ring `ring` (1-based), segment `k`.
    let index = |ring: usize, k: usize| (1 + (ring - 1) * SEGMENTS + k % SEGMENTS) as u32;
    let mut triangles = Vec::new();
    for k in 0..SEGMENTS - 1 {
        triangles.push([0, index(1, k), index(1, k + 1)]);
    }
    for ring in 1..RINGS {
        for k in 0..SEGMENTS - 1 {
            let (a, b) = (index(ring, k), index(ring, k + 1));
            let (c, d) = (index(ring + 1, k), index(ring + 1, k + 1));
            triangles.push([a, c, d]);
            triangles.push([a, d, b]);
        }
    }
    // Half transparent: the maximum under the patch (and its dot) shows through.
    rerun::Mesh3D::new(positions)
        .with_triangle_indices(triangles)
        .with_vertex_colors(colors)
        .with_albedo_factor(rerun::Rgba32::from_unmultiplied_rgba(255, 255, 255, 120))
}

//! The `[volume]` of a scene in a 3-D view: nested iso-surfaces of the quantity (translucent
//! shells at a few fractions of its largest value, coloured on the figure's colour map) in the
//! half of the box behind the plane `y = 0`, so that the cut shows how they nest; the contact
//! patch on the surface shaded by the pressure; the maximum labelled; and an initial camera
//! that looks at the patch from above, at an angle.
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

/// The camera: above the surface (z < 0), in front of the cut (y < 0) and towards the trailing
/// edge, looking at a point below the patch.
pub fn eye(spec: &VolumeSpec) -> Eye {
    let (width, depth) = (spec.x.1 - spec.x.0, spec.z.1 - spec.z.0);
    let size = width.max(spec.y.1 - spec.y.0).max(depth);
    let target = [
        0.5 * (spec.x.0 + spec.x.1),
        half(spec).0,
        spec.z.0 + 0.3 * depth,
    ];
    // About 25 degrees above the surface, a little towards the trailing edge, as close as
    // shows the shells and the patch whole (the box's far corners may leave the view).
    Eye {
        position: [
            (target[0] - 0.3 * size) as f32,
            (target[1] - 0.95 * size) as f32,
            (target[2] - 0.5 * size) as f32,
        ],
        target: target.map(|c| c as f32),
        up: [0.0, 0.0, -1.0],
    }
}

/// Logs what stays: the view's axes (z down) and the outline of the box's top face.
pub fn log_static(stream: &RecordingStream, spec: &VolumeSpec) -> Result<(), RecordError> {
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
    for (m, &level) in levels.iter().enumerate() {
        // The region beyond a negative level is below it: the surface of the negated field.
        let mesh: Mesh = if level < 0.0 {
            isosurface(
                grid.values.mapv(|v| -v).view(),
                &grid.x,
                &grid.y,
                &grid.z,
                -level,
            )
        } else {
            isosurface(grid.values.view(), &grid.x, &grid.y, &grid.z, level)
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
    }
    let largest = grid
        .values
        .indexed_iter()
        .filter(|(_, v)| v.is_finite())
        .max_by(|a, b| a.1.total_cmp(b.1));
    if let Some(((k, j, i), &value)) = largest {
        let position = [grid.x[i] as f32, grid.y[j] as f32, grid.z[k] as f32];
        stream.log(
            "volume/maximum",
            &rerun::Points3D::new([position])
                .with_radii([rerun::Radius::new_ui_points(5.0)])
                .with_colors([rerun::Color::from_rgb(255, 255, 255)])
                .with_labels([format!(
                    "max {} = {} at {}",
                    spec.quantity.symbol(),
                    stress_text(scene, f64::from(value)),
                    position_text_3d(scene, position)
                )])
                .with_show_labels(true),
        )?;
    }
    Ok(triangles)
}

/// The contact patch on the surface as a mesh of rings, shaded by the Hertz pressure
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
            let angle = std::f64::consts::TAU * k as f64 / SEGMENTS as f64;
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
    for k in 0..SEGMENTS {
        triangles.push([0, index(1, k), index(1, k + 1)]);
    }
    for ring in 1..RINGS {
        for k in 0..SEGMENTS {
            let (a, b) = (index(ring, k), index(ring, k + 1));
            let (c, d) = (index(ring + 1, k), index(ring + 1, k + 1));
            triangles.push([a, c, d]);
            triangles.push([a, d, b]);
        }
    }
    rerun::Mesh3D::new(positions)
        .with_triangle_indices(triangles)
        .with_vertex_colors(colors)
}

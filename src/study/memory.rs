//! What drawing a scene's figure will need in memory, estimated from its grids before anything
//! is allocated: checked when a scene is validated and again before a figure is built.

use crate::scene::{ContactKind, Method, Scene};

/// Bytes each panel keeps per grid point until the figure is drawn (its values in display
/// units).
pub const KEPT_BYTES_PER_POINT: usize = 8;

/// Bytes per grid point while a panel is evaluated, on top of what the panels keep: the field,
/// its map, the copy in display units and the contour buffers. Measured: one von Mises panel of
/// 4000 x 1601 points peaked at 232 MB (36 bytes per point), three at 333 MB.
pub const WORKING_BYTES_PER_POINT: usize = 32;

/// Bytes per pixel of the image (the canvas, the returned image and the encoder's rows).
const BYTES_PER_PIXEL: usize = 8;

/// The memory a figure needs, in bytes, estimated before anything is allocated: every panel's
/// kept values, the working buffers of the largest panel (twice for a difference, which
/// evaluates two fields), and the image. Surface and rough scenes (sheets) are estimated by
/// their own solver and are not counted here.
pub fn figure_bytes(scene: &Scene) -> usize {
    if matches!(
        scene.contact.kind,
        ContactKind::Rough | ContactKind::Surface
    ) {
        return 0;
    }
    let mut kept = 0usize;
    let mut working = 0usize;
    for panel in &scene.panels {
        let points = super::plane(scene, panel).points();
        kept = kept.saturating_add(points.saturating_mul(KEPT_BYTES_PER_POINT));
        let factor = if panel.method == Method::Difference {
            2
        } else {
            1
        };
        working = working.max(points.saturating_mul(WORKING_BYTES_PER_POINT * factor));
    }
    // The image: each map at its width and equal-scale height, with room for the axes, the
    // traction strip, the titles and the colour bars.
    let spec = &scene.figure;
    let width = spec.width_px as usize;
    // The tallest map (each panel in its own plane).
    let aspect = scene
        .panels
        .iter()
        .map(|panel| {
            let (horizontal, vertical) = spec.ranges(panel.section);
            (vertical.1 - vertical.0) / (horizontal.1 - horizontal.0)
        })
        .fold(0.0, f64::max);
    let map_height = (width as f64 * aspect).clamp(8.0, 1e9) as usize;
    let image_width = scene.panels.len() * (width + 200) + 400;
    let image_height = map_height + map_height / 4 + 400;
    let image = image_width
        .saturating_mul(image_height)
        .saturating_mul(BYTES_PER_PIXEL);
    kept.saturating_add(working).saturating_add(image)
}

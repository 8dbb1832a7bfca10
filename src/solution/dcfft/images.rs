//! Periodic tractions: the window of images summed exactly, and the uniform state of the
//! mean traction (see the module doc of [`super`]).

use crate::solution::patch::{uniform_patch, PatchStresses, Rectangle};

/// Periodic tractions: the images of each cell summed exactly in each direction, on each side
/// (the window `|offset| <= (M + 1/2) L`; module doc).
pub const PERIODIC_IMAGES: usize = 2;

/// The weight of the offset of `s` cells along an axis of `n` cells in the symmetric window of
/// `images` periods on each side: 1 inside, 1/2 on its edge, 0 beyond.
pub(super) fn window_weight(s: usize, n: usize, images: usize) -> f64 {
    let (twice, limit) = (2 * s, (2 * images + 1) * n);
    match twice.cmp(&limit) {
        std::cmp::Ordering::Less => 1.0,
        std::cmp::Ordering::Equal => 0.5,
        std::cmp::Ordering::Greater => 0.0,
    }
}

/// The offsets `(s, weight)` of the periodic images of the offset `d` along an axis of period
/// `period`: the window of `images` periods on each side of the point (module doc).
pub(super) fn image_offsets(d: f64, period: f64, images: usize) -> Vec<(f64, f64)> {
    let centred = d - period * (d / period).round();
    let half = (images as f64 + 0.5) * period;
    let reach = images as i64 + 1;
    (-reach..=reach)
        .filter_map(|n| {
            let s = centred + n as f64 * period;
            let excess = (s.abs() - half) / period;
            if excess < -1e-9 {
                Some((s, 1.0))
            } else if excess <= 1e-9 {
                Some((s, 0.5))
            } else {
                None
            }
        })
        .collect()
}

/// The nearest periodic image of the offset `d` along an axis of period `period`, as
/// `(offset, weight)`: one in `(-period/2, period/2)`, or both `±period/2` with weight 1/2.
pub(super) fn centred_offsets(d: f64, period: f64) -> Vec<(f64, f64)> {
    let centred = d - period * (d / period).round();
    if ((centred.abs() - 0.5 * period) / period).abs() <= 1e-9 {
        vec![(-0.5 * period, 0.5), (0.5 * period, 0.5)]
    } else {
        vec![(centred, 1.0)]
    }
}

/// The images beyond the window, spread over the plane: minus the stress at offset `d` of
/// the window rectangle `|x| <= (M + 1/2) Lx`, `|y| <= (M + 1/2) Ly` loaded uniformly with
/// the cell's traction times `dx dy / (Lx Ly)` (module doc).
pub(super) fn far_images(
    d: [f64; 2],
    z: f64,
    cell: [f64; 2],
    periods: [f64; 2],
    images: usize,
    nu: f64,
) -> PatchStresses {
    let half = images as f64 + 0.5;
    let window = Rectangle {
        x1: -half * periods[0],
        x2: half * periods[0],
        y1: -half * periods[1],
        y2: half * periods[1],
    };
    let density = -cell[0] * cell[1] / (periods[0] * periods[1]);
    let s = uniform_patch(d[0], d[1], z, window, nu);
    PatchStresses {
        pressure: s.pressure.scaled(density),
        shear_x: s.shear_x.scaled(density),
        shear_y: s.shear_y.scaled(density),
    }
}

/// The uniform stress of uniform tractions `[p, qx, qy]` on the whole surface, component `c`
/// in the order of [`COMPONENTS`].
pub(super) fn uniform_stress(mean: [f64; 3], c: usize) -> f64 {
    let [p, qx, qy] = mean;
    [0.0, 0.0, -p, -qy, -qx, 0.0][c]
}

//! A rough contact on a coated body (`kind = "rough"` with `[contact.body1.coating]`): the
//! pressure solved on the surface's grid with the layered influence coefficients
//! ([`crate::contact::coated`], periodic or isolated), and the stresses under it in the
//! coating and in the substrate from the layered waves of the tractions
//! ([`crate::coating::stress::LayeredStress`]), with the maxima the `contact` report states.
//!
//! ## The depths searched
//! Full planes of the map (every cell centre) at: the surface and a quarter, a half and three
//! quarters of a cell below it (a lone loaded cell's stress peaks about a third of a cell deep,
//! [`crate::study::assess`]); `max(12, h/dz)` (at most 48) depths evenly through the coating
//! to the interface's coating side; the interface's substrate side; then below it the
//! homogeneous search's schedule measured from the interface ([`search_depths`]: quarters of a
//! cell, cells to five, then steps of a fifth of the depth reached) down to
//! `max(`[`super::rough::search_depth_m`]`, 2h)`. The best sampled depth of von Mises in the
//! coating, von Mises in the substrate and the Tresca shear is then refined by bisection
//! between its neighbours on the same side of the interface to `dz/16`, as the homogeneous
//! search does ([`crate::study::assess::grid_maxima_to_depth`]); places in `x` and `y` are
//! cell centres.
//!
//! The interface's shear traction `sqrt(σxz² + σyz²)` and normal stress `σzz` (continuous
//! across it) are taken on its plane at every cell centre.

use ndarray::Array2;
use rayon::prelude::*;

use super::assess::{search_depths, Extreme, StressMaxima, TRESCA_PER_VON_MISES};
use super::rough::{search_depth_m, REFERENCE_LENGTH_M, REFERENCE_PRESSURE_PA};
use crate::coating::stress::LayeredStress;
use crate::coating::Side;
use crate::contact::rough::RoughSolution;
use crate::operator::elastic::Periodicity;
use crate::operator::transform::TransformError;
use crate::scene::CoatingSpec;
use crate::stress::Stress;

/// A stress value (Pa) at a cell centre `(x, y)` (m, from the map's corner) and depth `z`
/// (m), on `side` of the interface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Place {
    pub value_pa: f64,
    pub x_m: f64,
    pub y_m: f64,
    pub z_m: f64,
    pub side: Side,
}

impl Place {
    const NONE: Place = Place {
        value_pa: f64::NEG_INFINITY,
        x_m: 0.0,
        y_m: 0.0,
        z_m: 0.0,
        side: Side::Coating,
    };

    /// The place as the report's [`Extreme`] (MPa and µm, the rough scenes' units).
    pub fn extreme(&self) -> Extreme {
        Extreme {
            value_over_p0: self.value_pa / REFERENCE_PRESSURE_PA,
            x_over_a: self.x_m / REFERENCE_LENGTH_M,
            y_over_a: self.y_m / REFERENCE_LENGTH_M,
            z_over_a: self.z_m / REFERENCE_LENGTH_M,
            mirrored_in_y: false,
        }
    }
}

/// The maxima under a coated rough contact (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoatingMaxima {
    pub thickness_m: f64,
    /// Von Mises in the coating (the interface's coating side included).
    pub coating_von_mises: Place,
    /// Von Mises in the substrate (the interface's substrate side included).
    pub substrate_von_mises: Place,
    /// The Tresca shear `(σ1 − σ3)/2` anywhere.
    pub tresca: Place,
    /// The interface's shear traction `sqrt(σxz² + σyz²)`.
    pub interface_shear: Place,
    /// The interface's most compressive `σzz` (a negative value).
    pub interface_normal_min: Place,
    /// Von Mises on the surface.
    pub surface_von_mises: Place,
    /// How deep the substrate was searched, m.
    pub search_depth_m: f64,
}

impl CoatingMaxima {
    /// The largest von Mises stress, in the coating or the substrate.
    pub fn von_mises(&self) -> Place {
        if self.coating_von_mises.value_pa >= self.substrate_von_mises.value_pa {
            self.coating_von_mises
        } else {
            self.substrate_von_mises
        }
    }

    /// The report's maxima (von Mises and Tresca anywhere, von Mises on the surface).
    pub fn stress_maxima(&self) -> StressMaxima {
        StressMaxima {
            von_mises: self.von_mises().extreme(),
            max_shear: self.tresca.extreme(),
            von_mises_surface: self.surface_von_mises.extreme(),
        }
    }

    /// The side of the interface the report's largest `quantity` (von Mises, or the Tresca
    /// shear) lies on.
    pub fn side_of(&self, tresca: bool) -> Side {
        if tresca {
            self.tresca.side
        } else {
            self.von_mises().side
        }
    }
}

/// The stress layers of the solved pressure and `q = friction p` (in +x) on the coated body
/// of `spec` (periodic when the contact is).
pub fn layered_stress(
    solution: &RoughSolution,
    spec: &CoatingSpec,
    friction: f64,
) -> Result<LayeredStress, TransformError> {
    let shear = solution.pressure_pa.mapv(|p| friction * p);
    LayeredStress::new(
        spec.layered(),
        solution.pressure_pa.view(),
        (friction != 0.0).then_some(shear.view()),
        solution.spacing_m,
        solution.periodicity == Periodicity::Periodic,
    )
}

/// The most depths sampled evenly through the coating (beyond the first cell's).
const MAX_COATING_DEPTHS: usize = 48;
/// The fewest.
const MIN_COATING_DEPTHS: usize = 12;

/// The depths sampled (module doc), in increasing order with their side; `dz` the smaller
/// cell side, `end` the deepest.
pub fn depths(h: f64, dz: f64, end: f64) -> Vec<(f64, Side)> {
    let mut coating: Vec<f64> = [0.0, 0.25, 0.5, 0.75]
        .iter()
        .map(|f| f * dz)
        .filter(|&z| z < h)
        .collect();
    let n = ((h / dz).ceil() as usize).clamp(MIN_COATING_DEPTHS, MAX_COATING_DEPTHS);
    coating.extend((1..n).map(|i| h * i as f64 / n as f64));
    coating.sort_by(f64::total_cmp);
    coating.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * h);
    let mut out: Vec<(f64, Side)> = coating.into_iter().map(|z| (z, Side::Coating)).collect();
    out.push((h, Side::Coating));
    out.push((h, Side::Substrate));
    if end > h {
        out.extend(
            search_depths(dz, end - h)
                .into_iter()
                .skip(1)
                .map(|z| (h + z, Side::Substrate)),
        );
    }
    out
}

/// One plane's maxima: von Mises and Tresca (value, row, column); on the interface's coating
/// side also its shear traction and most compressive `σzz`.
#[derive(Clone, Copy, Debug)]
struct PlaneMaxima {
    von_mises: (f64, usize, usize),
    tresca: (f64, usize, usize),
    interface_shear: (f64, usize, usize),
    interface_normal_min: (f64, usize, usize),
}

fn plane_maxima(
    layers: &LayeredStress,
    z: f64,
    side: Side,
    interface: bool,
) -> Result<PlaneMaxima, TransformError> {
    let field = layers.layer(z, side)?;
    let (_, ny, nx) = field.dim();
    let none = (f64::NEG_INFINITY, 0, 0);
    let mut best = PlaneMaxima {
        von_mises: none,
        tresca: none,
        interface_shear: none,
        interface_normal_min: (f64::INFINITY, 0, 0),
    };
    for row in 0..ny {
        for column in 0..nx {
            let s = stress_at(&field, row, column);
            let von_mises = s.von_mises();
            if von_mises > best.von_mises.0 {
                best.von_mises = (von_mises, row, column);
            }
            // The Tresca shear never exceeds σvM/√3 (`TRESCA_PER_VON_MISES`): skip the
            // principal stresses where that bound cannot win.
            if von_mises * TRESCA_PER_VON_MISES > best.tresca.0 {
                let tresca = s.max_shear();
                if tresca > best.tresca.0 {
                    best.tresca = (tresca, row, column);
                }
            }
            if interface {
                let shear = s.xz.hypot(s.yz);
                if shear > best.interface_shear.0 {
                    best.interface_shear = (shear, row, column);
                }
                if s.zz < best.interface_normal_min.0 {
                    best.interface_normal_min = (s.zz, row, column);
                }
            }
        }
    }
    Ok(best)
}

/// The stress at cell `[row, column]` of a layer `[component, y, x]`.
pub fn stress_at(field: &ndarray::Array3<f64>, row: usize, column: usize) -> Stress {
    Stress {
        xx: field[[0, row, column]],
        yy: field[[1, row, column]],
        zz: field[[2, row, column]],
        yz: field[[3, row, column]],
        xz: field[[4, row, column]],
        xy: field[[5, row, column]],
    }
}

/// The maxima under the solved coated rough contact (module doc).
pub fn maxima(
    solution: &RoughSolution,
    spec: &CoatingSpec,
    friction: f64,
) -> Result<CoatingMaxima, TransformError> {
    let layers = layered_stress(solution, spec, friction)?;
    let [dx, dy] = solution.spacing_m;
    let dz = dx.min(dy);
    let h = spec.thickness_m;
    let end = search_depth_m(solution).max(2.0 * h);
    let mut sampled: Vec<((f64, Side), PlaneMaxima)> = Vec::new();
    let evaluate = |points: &[(f64, Side)]| -> Result<Vec<_>, TransformError> {
        points
            .par_iter()
            .map(|&(z, side)| {
                let interface = z == h && side == Side::Coating;
                plane_maxima(&layers, z, side, interface).map(|m| ((z, side), m))
            })
            .collect()
    };
    let coarse = depths(h, dz, end);
    sampled.extend(evaluate(&coarse)?);
    // Bisection between the neighbours on the same side (module doc): von Mises in the
    // coating, in the substrate, and the Tresca shear on the side of its best depth.
    type Score = fn(&PlaneMaxima) -> f64;
    let von_mises: Score = |m| m.von_mises.0;
    let tresca: Score = |m| m.tresca.0;
    let tresca_side = sampled
        .iter()
        .max_by(|a, b| a.1.tresca.0.total_cmp(&b.1.tresca.0))
        .map_or(Side::Coating, |s| s.0 .1);
    let mut brackets: Vec<(Score, Side, [f64; 3])> = Vec::new();
    for (score, side) in [
        (von_mises, Side::Coating),
        (von_mises, Side::Substrate),
        (tresca, tresca_side),
    ] {
        let on_side: Vec<(f64, f64)> = sampled
            .iter()
            .filter(|s| s.0 .1 == side)
            .map(|s| (s.0 .0, score(&s.1)))
            .collect();
        let Some(best) = (0..on_side.len()).max_by(|&i, &j| on_side[i].1.total_cmp(&on_side[j].1))
        else {
            continue;
        };
        let above = on_side[best.saturating_sub(1)].0;
        let below = on_side[(best + 1).min(on_side.len() - 1)].0;
        brackets.push((score, side, [above, on_side[best].0, below]));
    }
    let tolerance = dz / 16.0;
    let value_at = |sampled: &[((f64, Side), PlaneMaxima)], z: f64, side: Side, score: Score| {
        sampled
            .iter()
            .find(|s| s.0 == (z, side))
            .map_or(f64::NEG_INFINITY, |s| score(&s.1))
    };
    while !brackets.is_empty() {
        let mut round: Vec<(f64, Side)> = Vec::new();
        for (_, side, [above, best, below]) in &brackets {
            for end in [*above, *below] {
                let z = 0.5 * (best + end);
                let point = (z, *side);
                if (best - end).abs() > tolerance
                    && !round.contains(&point)
                    && !sampled.iter().any(|s| s.0 == point)
                {
                    round.push(point);
                }
            }
        }
        sampled.extend(evaluate(&round)?);
        brackets = brackets
            .into_iter()
            .filter_map(|(score, side, [above, best, below])| {
                let (up, down) = (0.5 * (best + above), 0.5 * (best + below));
                let at = |z: f64| value_at(&sampled, z, side, score);
                let next = if best - above > tolerance && at(up) > at(best) && at(up) >= at(down) {
                    [above, up, best]
                } else if below - best > tolerance && at(down) > at(best) {
                    [best, down, below]
                } else {
                    [
                        if best - above > tolerance { up } else { above },
                        best,
                        if below - best > tolerance {
                            down
                        } else {
                            below
                        },
                    ]
                };
                (next[1] - next[0] > tolerance || next[2] - next[1] > tolerance)
                    .then_some((score, side, next))
            })
            .collect();
    }
    let place = |value: f64, row: usize, column: usize, z: f64, side: Side| Place {
        value_pa: value,
        x_m: (column as f64 + 0.5) * dx,
        y_m: (row as f64 + 0.5) * dy,
        z_m: z,
        side,
    };
    let mut out = CoatingMaxima {
        thickness_m: h,
        coating_von_mises: Place::NONE,
        substrate_von_mises: Place::NONE,
        tresca: Place::NONE,
        interface_shear: Place::NONE,
        interface_normal_min: Place {
            value_pa: f64::INFINITY,
            ..Place::NONE
        },
        surface_von_mises: Place::NONE,
        search_depth_m: end,
    };
    for &((z, side), m) in &sampled {
        let (v, row, column) = m.von_mises;
        let target = match side {
            Side::Coating => &mut out.coating_von_mises,
            Side::Substrate => &mut out.substrate_von_mises,
        };
        if v > target.value_pa {
            *target = place(v, row, column, z, side);
        }
        if z == 0.0 && v > out.surface_von_mises.value_pa {
            out.surface_von_mises = place(v, row, column, z, side);
        }
        let (t, row, column) = m.tresca;
        if t > out.tresca.value_pa {
            out.tresca = place(t, row, column, z, side);
        }
        if z == h && side == Side::Coating {
            let (s, row, column) = m.interface_shear;
            out.interface_shear = place(s, row, column, z, side);
            let (n, row, column) = m.interface_normal_min;
            out.interface_normal_min = place(n, row, column, z, side);
        }
    }
    Ok(out)
}

/// The scene's quantity on the row `row` of the map at the depths `z_m` (m), `[depth, x]` in
/// Pa; a depth on the interface takes `interface_side`, others the side they lie on.
pub fn row_section(
    layers: &LayeredStress,
    row: usize,
    z_m: &[f64],
    interface_side: Side,
    quantity: crate::stress::Quantity,
) -> Array2<f64> {
    let h = layers.layered().thickness_m;
    let rows: Vec<Array2<f64>> = z_m
        .par_iter()
        .map(|&z| layers.row(row, z, side_at(z, h, interface_side)))
        .collect();
    let nx = rows.first().map_or(0, |r| r.ncols());
    Array2::from_shape_fn((z_m.len(), nx), |(k, i)| {
        let r = &rows[k];
        quantity.of(&Stress {
            xx: r[[0, i]],
            yy: r[[1, i]],
            zz: r[[2, i]],
            yz: r[[3, i]],
            xz: r[[4, i]],
            xy: r[[5, i]],
        })
    })
}

/// The side of the interface a report's maximum `extreme` of `quantity` (von Mises or the
/// Tresca shear; MPa and µm) lies on: the side its depth lies on, and at the interface the
/// side whose value at its cell is the reported one (the in-plane stresses jump there).
pub fn reported_side(
    layers: &LayeredStress,
    extreme: &Extreme,
    quantity: crate::stress::Quantity,
    spacing_m: [f64; 2],
) -> Side {
    let h = layers.layered().thickness_m;
    let z = extreme.z_over_a * REFERENCE_LENGTH_M;
    if (z - h).abs() > 1e-9 * h {
        return side_at(z, h, Side::Coating);
    }
    let [nx, ny] = {
        let shape = layers.shape();
        [shape[1], shape[0]]
    };
    let cell = |u: f64, d: f64, n: usize| super::map_roll::cell_of(u, d / REFERENCE_LENGTH_M, n);
    let (row, column) = (
        cell(extreme.y_over_a, spacing_m[1], ny),
        cell(extreme.x_over_a, spacing_m[0], nx),
    );
    let target = extreme.value_over_p0 * REFERENCE_PRESSURE_PA;
    let miss = |side: Side| {
        let r = layers.row(row, h, side);
        let s = Stress {
            xx: r[[0, column]],
            yy: r[[1, column]],
            zz: r[[2, column]],
            yz: r[[3, column]],
            xz: r[[4, column]],
            xy: r[[5, column]],
        };
        (quantity.of(&s) - target).abs()
    };
    if miss(Side::Coating) <= miss(Side::Substrate) {
        Side::Coating
    } else {
        Side::Substrate
    }
}

/// The side of the interface a depth `z` lies on (`on_interface` within 1e-9 of `h`).
pub fn side_at(z: f64, h: f64, on_interface: Side) -> Side {
    if (z - h).abs() <= 1e-9 * h {
        on_interface
    } else if z < h {
        Side::Coating
    } else {
        Side::Substrate
    }
}

#[cfg(test)]
#[path = "coated_rough_tests.rs"]
mod tests;

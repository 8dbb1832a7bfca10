//! The maxima of a heated contact's stress ([`HeatedStress`]): the thermal, contact and total
//! von Mises stress and the contact and total maximum shear `(σ1 − σ3)/2`.
//!
//! ## The search
//! The maxima are searched over the cell centres of layers at coarse depths (a Hertz contact:
//! [`super::thermal::DEPTHS_OVER_A`] times `a`; a rough contact: the depths of `contact`'s
//! search, [`super::assess::grid_maxima_to_depth`]); each quantity's best layer is then
//! refined in depth by bisection of its bracket (the maximum over the layer's cells at each
//! depth), as the rough search does, down to
//! [`super::heated_stress::DEPTH_TOLERANCE_OVER_A`] of `a` or a sixteenth of a cell.
//!
//! A rough contact's coarse search computes the thermal layer at every coarse depth to
//! [`super::thermal::DENSE_CELLS`] cells, then at every other one (about 44 % apart in depth)
//! and at the last; the coarse depths between are searched with the thermal stress
//! interpolated as below (within 5e-3 of the layer's largest component, measured: the test
//! `interpolated_coarse_layers_match_the_computed_ones`), and are never reported as such.
//!
//! The bisection's layers take the thermal stress interpolated in depth, cell by cell and
//! component by component, by Lagrange's cubic through the four computed layers nearest (the
//! contact stress stays exact: the closed form, or its DC-FFT layer). Each computed thermal
//! layer is six influence-coefficient lattices twice the grid's size each way and their
//! transforms; the thermal stress varies smoothly in depth between the coarse layers, so the
//! interpolated one leads the bisection where the computed one did. Only the coarse layers
//! that an interpolation can need (within two depths of each quantity's best so far) are
//! kept. The depth each quantity settles on is then computed exactly: its thermal layer is
//! computed there, and the maximum reported is the exact one at that depth (or the best
//! computed coarse layer's, should that be larger).
//!
//! Where the contact stress is a closed form, the total's maxima are then located in x
//! between the cell centres by the compass search of [`super::compass`] (Hooke & Jeeves
//! 1961): the thermal stress between two centres is interpolated along the row by the
//! Catmull–Rom cubic (exact at the centres, [`HeatedStress::between`]), the contact stress
//! evaluated exactly, so that an edge peak of the contact stress (the trailing edge's tension
//! under high friction) is found where it is, not half a cell away. Depth and x are good to
//! the tolerance and to about 1e-9 of a cell, y to the cell row (a line contact: y = 0).
//!
//! ## References
//! - M. Abramowitz, I. A. Stegun, *Handbook of Mathematical Functions*, National Bureau of
//!   Standards (1964), §25.2 (Lagrange's interpolation formula, its error `O(h⁴)` for four
//!   points).
//! - R. Hooke, T. A. Jeeves, *J. ACM* 8 (1961) 212–229 (the compass search).

use std::collections::BTreeMap;
use std::ops::Range;

use ndarray::Array3;

use super::heated_stress::{
    measure, DepthBest, HeatedStress, StressLayer, CONTACT_MAX_SHEAR, CONTACT_VON_MISES,
    QUANTITIES, TOTAL_MAX_SHEAR, TOTAL_VON_MISES,
};
use super::thermal::{Maximum, ThermalStudyError};

/// The points of the interpolation in depth.
const STENCIL: usize = 4;

/// The weights of Lagrange's polynomial through `nodes` at `z`:
/// `w_i = Π_{j ≠ i} (z − z_j) / (z_i − z_j)` (Abramowitz & Stegun 1964, §25.2).
fn lagrange_weights(nodes: &[f64], z: f64) -> Vec<f64> {
    nodes
        .iter()
        .enumerate()
        .map(|(i, &zi)| {
            nodes
                .iter()
                .enumerate()
                .filter(|&(j, _)| j != i)
                .map(|(_, &zj)| (z - zj) / (zi - zj))
                .product()
        })
        .collect()
}

/// The coarse depths (indices) of the interpolation within the interval
/// `[coarse[interval], coarse[interval + 1]]`: the four around it, shifted inside at the ends.
fn stencil(points: usize, interval: usize) -> Range<usize> {
    let width = points.min(STENCIL);
    let start = interval.saturating_sub(1).min(points - width);
    start..start + width
}

/// The coarse depths that a bisection around coarse depth `best` can need: those of the
/// intervals either side of it.
fn needed(points: usize, best: usize) -> Range<usize> {
    let above = stencil(points, best.saturating_sub(1));
    let below = stencil(points, best.min(points.saturating_sub(2)));
    above.start.min(below.start)..above.end.max(below.end)
}

/// The computed coarse thermal layers kept for the interpolation, by their index among the
/// computed depths `depths` (increasing).
struct Kept {
    depths: Vec<f64>,
    layers: BTreeMap<usize, Array3<f32>>,
}

impl Kept {
    /// The thermal stress at `z`, interpolated between the computed layers (`None` when a
    /// layer it needs was not kept).
    fn at(&self, z: f64) -> Option<Array3<f64>> {
        let nodes = &self.depths;
        let interval = nodes
            .partition_point(|&d| d <= z)
            .saturating_sub(1)
            .min(nodes.len().saturating_sub(2));
        let range = stencil(nodes.len(), interval);
        let weights = lagrange_weights(&nodes[range.clone()], z);
        let mut out: Option<Array3<f64>> = None;
        for (index, w) in range.zip(weights) {
            let layer = self.layers.get(&index)?;
            match out.as_mut() {
                None => out = Some(layer.mapv(|v| w * f64::from(v))),
                Some(sum) => sum.zip_mut_with(layer, |s, &v| *s += w * f64::from(v)),
            }
        }
        out
    }
}

/// Whether coarse depth `index` of `points` has its thermal layer computed: the first
/// `dense`, then every other one, and the last; the others are interpolated in depth.
fn computed(index: usize, dense: usize, points: usize) -> bool {
    index < dense || (index - dense).is_multiple_of(2) || index + 1 == points
}

/// The coarse depth where quantity `k` is largest.
fn best_index(found: &[DepthBest], k: usize) -> usize {
    (0..found.len())
        .max_by(|&i, &j| found[i].1[k].0.total_cmp(&found[j].1[k].0))
        .unwrap_or(0)
}

impl HeatedStress {
    /// The maxima of the thermal, contact and total von Mises stress and of the contact and
    /// total maximum shear `(σ1 − σ3)/2`, searched at `coarse` depths (m, increasing from 0;
    /// the thermal layer computed at the first `dense` of them, then at every other one and
    /// the last, and interpolated between) and refined (see the module's docs) to
    /// `tolerance_m`; `progress(done)` after each coarse depth.
    pub(crate) fn maxima(
        &self,
        coarse: &[f64],
        dense: usize,
        tolerance_m: f64,
        progress: &mut dyn FnMut(usize),
    ) -> Result<[Maximum; QUANTITIES], ThermalStudyError> {
        // The contact's maxima come from the closed form when there is one, and a rough
        // contact's from `contact`'s own search ([`super::thermal::study`]): neither is refined
        // here.
        let contact_elsewhere = self.contact_elsewhere();
        let searched: Vec<usize> = (0..QUANTITIES)
            .filter(|&k| !(contact_elsewhere && (k == CONTACT_VON_MISES || k == CONTACT_MAX_SHEAR)))
            .collect();
        let points = coarse.len();
        let exact_coarse: Vec<f64> = (0..points)
            .filter(|&i| computed(i, dense, points))
            .map(|i| coarse[i])
            .collect();
        let computed_points = exact_coarse.len();
        let mut found: Vec<DepthBest> = Vec::new();
        let mut kept = Kept {
            depths: exact_coarse.clone(),
            layers: BTreeMap::new(),
        };
        // A coarse depth whose layer is interpolated waits until the computed layers its
        // cubic takes (two either side) are there.
        let mut pending: Vec<f64> = Vec::new();
        let mut done = 0;
        // A closed-form contact's layers (a Hertz grid, at most 262,144 cells) are computed
        // two depths at a time: each layer's transforms and sums are split over the threads
        // too, but too finely to keep both busy alone. Measured on the sliding sphere at
        // 9 m/s (580 x 437 cells): 415 MiB at the peak (312 MiB one at a time), within
        // `check`'s 403 MiB estimate.
        let mut next_layer: Option<StressLayer> = None;
        for (index, &z) in exact_coarse.iter().enumerate() {
            let layer = match next_layer.take() {
                Some(layer) => layer,
                None if self.closed_form() && index + 1 < computed_points => {
                    let (this, next) =
                        rayon::join(|| self.layer(z), || self.layer(exact_coarse[index + 1]));
                    next_layer = Some(next?);
                    this?
                }
                None => self.layer(z)?,
            };
            found.push((z, self.layer_best(&layer)));
            kept.layers.insert(index, layer.thermal.mapv(|v| v as f32));
            // Released before the interpolated depths take their own layers.
            drop(layer);
            done += 1;
            progress(done);
            if let Some(&next) = exact_coarse.get(index + 1) {
                pending.extend(coarse.iter().filter(|&&d| d > z && d < next));
            }
            let ready = |d: f64| {
                let below = exact_coarse.partition_point(|&e| e <= d);
                below < index || index + 1 == computed_points
            };
            let (now, later): (Vec<f64>, Vec<f64>) = pending.iter().partition(|&&d| ready(d));
            pending = later;
            for d in now {
                let thermal = match kept.at(d) {
                    Some(interpolated) => interpolated,
                    None => self.thermal_layer(d)?,
                };
                let layer = self.with_thermal(d, thermal)?;
                found.push((d, self.layer_best(&layer)));
                done += 1;
                progress(done);
            }
            // Keep the layers an interpolation around a best so far can need, and the last two,
            // `index - 1` and `index`: a later best `b > index` needs the computed layers from
            // `b - 2` on ([`needed`]); while depths wait for their interpolation, the last
            // three (the next one ready takes the stencil from `index - 2`). (A layer not kept
            // is computed exactly where needed, so this bounds memory, not correctness.)
            let wanted: Vec<Range<usize>> = searched
                .iter()
                .map(|&k| {
                    let best = found[best_index(&found, k)].0;
                    needed(computed_points, exact_coarse.partition_point(|&e| e < best))
                })
                .collect();
            kept.layers.retain(|&j, _| {
                let reach = if pending.is_empty() { 1 } else { 2 };
                j + reach >= index || wanted.iter().any(|r| r.contains(&j))
            });
        }
        found.sort_by(|a, b| a.0.total_cmp(&b.0));
        let coarse_found = found.len();
        let value = |found: &[DepthBest], z: f64, k: usize| {
            found
                .iter()
                .find(|(d, _)| *d == z)
                .map_or(f64::NEG_INFINITY, |(_, b)| b[k].0)
        };
        for &k in &searched {
            let best = best_index(&found[..coarse_found], k);
            let (mut above, mut middle, mut below) = (
                coarse[best.saturating_sub(1)],
                coarse[best],
                coarse[(best + 1).min(points - 1)],
            );
            while middle - above > tolerance_m || below - middle > tolerance_m {
                for z in [0.5 * (above + middle), 0.5 * (middle + below)] {
                    if value(&found, z, k) == f64::NEG_INFINITY {
                        let thermal = match kept.at(z) {
                            Some(interpolated) => interpolated,
                            None => self.thermal_layer(z)?,
                        };
                        let layer = self.with_thermal(z, thermal)?;
                        found.push((z, self.layer_best(&layer)));
                    }
                }
                let (up, down) = (0.5 * (above + middle), 0.5 * (middle + below));
                let (vu, vm, vd) = (
                    value(&found, up, k),
                    value(&found, middle, k),
                    value(&found, down, k),
                );
                (above, middle, below) = if vu > vm && vu >= vd {
                    (above, up, middle)
                } else if vd > vm {
                    (middle, down, below)
                } else {
                    (up, middle, down)
                };
            }
        }
        drop(kept);
        // Each quantity's depth, its value computed exactly there (the exact layers kept for
        // the search in x).
        let mut exact: Vec<StressLayer> = Vec::new();
        let mut maxima = [Maximum::NONE; QUANTITIES];
        for &k in &searched {
            let pick = |found: &[DepthBest]| {
                found
                    .iter()
                    .max_by(|a, b| a.1[k].0.total_cmp(&b.1[k].0))
                    .map(|(z, b)| (*z, b[k]))
                    .unwrap_or((0.0, (f64::NEG_INFINITY, 0, 0)))
            };
            let (mut z, mut b) = pick(&found);
            let is_coarse = exact_coarse.contains(&z);
            let needs_layer = self.closed_form() && (k == TOTAL_VON_MISES || k == TOTAL_MAX_SHEAR);
            if !is_coarse || needs_layer {
                if !exact.iter().any(|layer| layer.depth_m == z) {
                    exact.push(self.layer(z)?);
                }
                if !is_coarse {
                    let at_z = exact
                        .iter()
                        .find(|layer| layer.depth_m == z)
                        .map(|layer| self.layer_best(layer)[k]);
                    let exact_found: Vec<DepthBest> = found[..coarse_found]
                        .iter()
                        .filter(|(d, _)| exact_coarse.contains(d))
                        .copied()
                        .collect();
                    let (coarse_z, coarse_b) = pick(&exact_found);
                    match at_z {
                        Some(at_z) if at_z.0 >= coarse_b.0 => b = at_z,
                        _ => {
                            (z, b) = (coarse_z, coarse_b);
                            if needs_layer && !exact.iter().any(|layer| layer.depth_m == z) {
                                exact.push(self.layer(z)?);
                            }
                        }
                    }
                }
            }
            let (v, row, column) = b;
            maxima[k] = Maximum {
                value_pa: v,
                x_m: self.x_m(column),
                y_m: self.y_m(row),
                depth_m: z,
            };
        }
        if self.closed_form() {
            for k in [TOTAL_VON_MISES, TOTAL_MAX_SHEAR] {
                let depth = maxima[k].depth_m;
                if let Some(layer) = exact.iter().find(|layer| layer.depth_m == depth) {
                    maxima[k] = self.refine_in_x(k, maxima[k], layer);
                }
            }
        }
        Ok(maxima)
    }

    /// Quantity `k`'s maximum moved along its row, between the cell centres either side of
    /// it, to where the interpolated thermal plus the exact contact stress is largest (never
    /// lower than at the centre); `layer` is the exact layer at its depth.
    fn refine_in_x(&self, k: usize, at: Maximum, layer: &StressLayer) -> Maximum {
        let row = self.row_of(at.y_m);
        let dx = self.grid.spacing_m[0];
        let (lo, hi) = (self.x_m(0), self.x_m(self.grid.shape[1].saturating_sub(1)));
        let bounds = ((at.x_m - dx).max(lo), (at.x_m + dx).min(hi));
        // In units of a cell, so that the search's 1e-9 is of a cell.
        let value = |[s]: [f64; 1]| {
            let (thermal, contact) = self.between(layer, row, at.x_m + s * dx);
            measure(k, &thermal, &contact)
        };
        let ([s], best) = super::compass::compass_maximum(
            value,
            [0.0],
            at.value_pa,
            [0.5],
            [((bounds.0 - at.x_m) / dx, (bounds.1 - at.x_m) / dx)],
        );
        Maximum {
            value_pa: best,
            x_m: at.x_m + s * dx,
            ..at
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::thermal::kernel::CellGrid;
    use crate::thermal::stress::ThermalStressOperator;
    use ndarray::Array2;

    /// The thermal layers that the search interpolates (every other coarse depth beyond
    /// [`super::super::thermal::DENSE_CELLS`] cells) against the computed ones, under a flux of
    /// a few asperity spots on a rough contact's grid (cell Péclet number 0.01, as the rough
    /// ball of `benches/thermal.rs`): within 5e-3 of the layer's largest component (measured:
    /// 1.8e-3 at 7.2 cells, 3.2e-3 at 10.4, 4.5e-3 at 14.9 and 4.4e-3 at 21.5). The search
    /// reports no interpolated value: these layers only lead it to its brackets.
    #[test]
    fn interpolated_coarse_layers_match_the_computed_ones() {
        let (n, dz) = (48, 0.5e-6);
        let grid = CellGrid {
            shape: [n, n],
            spacing_m: [dz, dz],
        };
        let spots = [
            (20.0, 22.0, 1.0),
            (26.0, 25.0, 0.7),
            (23.0, 30.0, 0.4),
            (30.0, 18.0, 0.9),
        ];
        let flux = Array2::from_shape_fn((n, n), |(row, column)| {
            spots
                .iter()
                .map(|&(x, y, q)| {
                    let r2 = (column as f64 - x).powi(2) + (row as f64 - y).powi(2);
                    q * 1e9 * (-r2 / 2.0).exp()
                })
                .sum()
        });
        let thermal = |z: f64| {
            ThermalStressOperator::new(&grid, z, 2e4, 0.3, 1.0)
                .expect("operator")
                .apply(flux.view())
                .expect("layer")
        };
        let coarse = crate::study::assess::search_depths(dz, 30.0 * dz);
        let dense = super::super::thermal::dense_depths(&coarse, dz);
        let points = coarse.len();
        let depths: Vec<f64> = (0..points)
            .filter(|&i| computed(i, dense, points))
            .map(|i| coarse[i])
            .collect();
        let kept = Kept {
            layers: depths
                .iter()
                .enumerate()
                .map(|(i, &z)| (i, thermal(z).mapv(|v| v as f32)))
                .collect(),
            depths,
        };
        let mut errors = Vec::new();
        for (i, &z) in coarse.iter().enumerate() {
            if computed(i, dense, points) {
                continue;
            }
            let exact = thermal(z);
            let interpolated = kept.at(z).expect("kept");
            let largest = exact.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let error = (&interpolated - &exact)
                .iter()
                .fold(0.0f64, |m, v| m.max(v.abs()));
            errors.push((z / dz, error / largest));
        }
        eprintln!("{errors:?}");
        assert!(errors.len() >= 4, "{errors:?}");
        assert!(errors.iter().all(|&(_, e)| e < 5e-3), "{errors:?}");
    }

    #[test]
    fn lagrange_weights_reproduce_cubics_on_uneven_nodes() {
        let nodes = [0.0, 0.25, 0.7, 2.0];
        let cubic = |z: f64| 1.5 - 2.0 * z + 0.3 * z * z - 0.7 * z * z * z;
        for z in [0.1, 0.5, 1.3] {
            let w = lagrange_weights(&nodes, z);
            let value: f64 = nodes.iter().zip(&w).map(|(&n, &w)| w * cubic(n)).sum();
            assert!((value - cubic(z)).abs() < 1e-12, "{z}: {value}");
        }
    }

    #[test]
    fn the_stencil_lies_around_its_interval_and_inside_the_depths() {
        assert_eq!(stencil(10, 0), 0..4);
        assert_eq!(stencil(10, 4), 3..7);
        assert_eq!(stencil(10, 8), 6..10);
        assert_eq!(stencil(3, 1), 0..3);
        // Either side of the best: the intervals [best - 1, best] and [best, best + 1].
        assert_eq!(needed(10, 5), 3..8);
        assert_eq!(needed(10, 0), 0..4);
        assert_eq!(needed(10, 9), 6..10);
    }
}

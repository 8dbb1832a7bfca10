//! The parallel driver of DC-FFT depth layers ([`for_each_dcfft_layer`]).

use ndarray::{Array3, Axis as NdAxis};
use rayon::prelude::*;

use crate::solution::dcfft::{DcFft, DcFftError, COMPONENTS};

/// The working memory of the cell-based layers of all workers together above which the
/// layers of an isolated grid run one after another, each split over the threads (an
/// isolated 2048² grid with friction needs 0.67 GB per worker: the influence coefficients of
/// two loads, one component's row spectra and the layer, [`DcFft::worker_bytes`]).
const PARALLEL_LAYERS_BYTES: usize = 1 << 30;

/// Computes the DC-FFT layers of `fft` at `depths` and calls `take(index, z, layer)` for each
/// (in no particular order) with the layer `[component, y, x]`, in parallel: over the depths
/// when there are at least as many as threads, each worker holding one layer's working set;
/// otherwise, or where those working sets together would exceed [`PARALLEL_LAYERS_BYTES`]
/// (isolated grids, whose layers are all cell-based), layer after layer, each layer's
/// influence coefficients split over the threads ([`DcFft::influence_in_parallel`]) and then
/// its six components, which run in parallel. Either way a layer is the same to the last
/// bit.
pub fn for_each_dcfft_layer<F>(fft: &DcFft, depths: &[f64], take: F) -> Result<(), DcFftError>
where
    F: Fn(usize, f64, ndarray::ArrayView3<f64>) + Sync,
{
    let [ny, nx] = fft.shape();
    let threads = rayon::current_num_threads();
    let fits = fft.periodicity() == crate::operator::elastic::Periodicity::Periodic
        || fft.worker_bytes().saturating_mul(threads) <= PARALLEL_LAYERS_BYTES;
    if depths.len() >= threads && fits {
        return depths
            .par_iter()
            .enumerate()
            .map_init(
                || (fft.workspace(), Array3::zeros((6, ny, nx))),
                |(workspace, layer), (index, &z)| {
                    fft.layer_into(z, workspace, layer.view_mut())?;
                    take(index, z, layer.view());
                    Ok(())
                },
            )
            .collect();
    }
    let mut quadrant = Vec::new();
    let mut layer = Array3::zeros((6, ny, nx));
    let mut spectral = None;
    let mut workspaces = None;
    for (index, &z) in depths.iter().enumerate() {
        // A spectral layer (on this thread: a few milliseconds per 256² layer).
        if fft.is_spectral(z) {
            let workspace = spectral.get_or_insert_with(|| fft.workspace());
            fft.layer_into(z, workspace, layer.view_mut())?;
            take(index, z, layer.view());
            continue;
        }
        fft.influence_in_parallel(z, &mut quadrant, threads);
        // The six components over the threads, each worker with its component's working
        // memory kept from layer to layer (at 2048² with friction, 0.07 GB each; allocated
        // afresh for every layer, the 0.2 GB it then was cost more than the coefficients).
        let groups = workspaces.get_or_insert_with(|| {
            (0..threads.clamp(1, COMPONENTS.len()))
                .map(|_| fft.component_workspace())
                .collect::<Vec<_>>()
        });
        let count = groups.len();
        let mut outs: Vec<Vec<(usize, ndarray::ArrayViewMut2<f64>)>> =
            (0..count).map(|_| Vec::new()).collect();
        for (c, out) in layer.axis_iter_mut(NdAxis(0)).enumerate() {
            outs[c % count].push((c, out));
        }
        groups
            .par_iter_mut()
            .zip(outs)
            .try_for_each(|(workspace, outs)| {
                outs.into_iter()
                    .try_for_each(|(c, out)| fft.component_into(&quadrant, c, workspace, out))
            })?;
        take(index, z, layer.view());
    }
    Ok(())
}

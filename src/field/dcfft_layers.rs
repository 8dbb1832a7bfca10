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
/// its six components, which run in parallel. A periodic batch with fewer cell-based layers
/// than threads runs those layer after layer and its spectral layers over the depths. Either
/// way a layer is the same to the last bit.
pub fn for_each_dcfft_layer<F>(fft: &DcFft, depths: &[f64], take: F) -> Result<(), DcFftError>
where
    F: Fn(usize, f64, ndarray::ArrayView3<f64>) + Sync,
{
    let threads = rayon::current_num_threads();
    let periodic = fft.periodicity() == crate::operator::elastic::Periodicity::Periodic;
    let fits = periodic || fft.worker_bytes().saturating_mul(threads) <= PARALLEL_LAYERS_BYTES;
    let all: Vec<usize> = (0..depths.len()).collect();
    if depths.len() < threads || !fits {
        return one_by_one(fft, depths, &all, &take, threads);
    }
    // A periodic batch with fewer cell-based layers than threads among spectral ones (a
    // refinement round near the surface): a cell-based layer costs several spectral ones, so
    // it is split over the threads first and its spectral companions run over the depths
    // after, instead of one worker computing it alone while the others wait.
    let (cell_based, spectral): (Vec<usize>, Vec<usize>) =
        all.iter().partition(|&&i| !fft.is_spectral(depths[i]));
    if periodic && !cell_based.is_empty() && cell_based.len() < threads {
        one_by_one(fft, depths, &cell_based, &take, threads)?;
        return if spectral.len() >= threads {
            over_depths(fft, depths, &spectral, &take)
        } else {
            one_by_one(fft, depths, &spectral, &take, threads)
        };
    }
    over_depths(fft, depths, &all, &take)
}

/// The layers `depths[i]` for `i` in `indices` in parallel over the depths, each worker
/// holding one layer's working set.
fn over_depths<F>(
    fft: &DcFft,
    depths: &[f64],
    indices: &[usize],
    take: &F,
) -> Result<(), DcFftError>
where
    F: Fn(usize, f64, ndarray::ArrayView3<f64>) + Sync,
{
    let [ny, nx] = fft.shape();
    indices
        .par_iter()
        .map_init(
            || (fft.workspace(), Array3::zeros((6, ny, nx))),
            |(workspace, layer), &index| {
                let z = depths[index];
                fft.layer_into(z, workspace, layer.view_mut())?;
                take(index, z, layer.view());
                Ok(())
            },
        )
        .collect()
}

/// The layers `depths[i]` for `i` in `indices` one after another, a cell-based layer split
/// over the threads, a spectral one on this thread.
fn one_by_one<F>(
    fft: &DcFft,
    depths: &[f64],
    indices: &[usize],
    take: &F,
    threads: usize,
) -> Result<(), DcFftError>
where
    F: Fn(usize, f64, ndarray::ArrayView3<f64>) + Sync,
{
    let [ny, nx] = fft.shape();
    let mut quadrant = Vec::new();
    let mut layer = Array3::zeros((6, ny, nx));
    let mut spectral = None;
    let mut workspaces = None;
    for &index in indices {
        let z = depths[index];
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

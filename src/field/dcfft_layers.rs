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

/// The peak memory (bytes) of computing `depths` DC-FFT layers of an `[ny, nx]` grid with
/// `loads` traction arrays (1 to 3) on `threads` threads and keeping them all (the Python
/// package's `stress` returns them): a cell takes `48 depths` bytes for the layers kept (six
/// f64 components), `48 loads` for the tractions (their copy, and their zero-padded spectra
/// of `(2 ny)(nx + 1)` complex values, `32 loads`, plus a periodic grid's spectral layers',
/// `8 loads`), and for each worker running at once (as many as threads, at most one a
/// depth) `96 loads + 48`: the influence coefficients (`48 loads`), a component's row
/// spectra (at most `16 loads`), on a periodic square grid the turned coefficients of each
/// shear that is not a load (`24` a cell and `48 nx`, at most `32 loads` in all) and the
/// layer (`48`), which bounds [`DcFft::worker_bytes`]. Estimated before anything is
/// allocated, so that a call that cannot fit is refused instead of aborting the process
/// (issue 50: a 4096² grid at 50 depths asked for 40 GB).
pub fn kept_layers_bytes(shape: [usize; 2], loads: usize, depths: usize, threads: usize) -> usize {
    let cells = shape[0].saturating_mul(shape[1]);
    let workers = threads.clamp(1, depths.max(1));
    let per_cell = 48usize
        .saturating_mul(depths)
        .saturating_add(48 * loads)
        .saturating_add(workers.saturating_mul(96 * loads + 48));
    cells.saturating_mul(per_cell)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solution::dcfft::TractionGrid;
    use ndarray::Array2;

    /// The estimate bounds what a worker of the driver holds ([`DcFft::worker_bytes`]) for
    /// every combination of loads, isolated and periodic, square and not, plus the layers
    /// kept; and it does not overflow.
    #[test]
    fn the_kept_layers_estimate_bounds_the_workers() {
        let cell = |present: bool, shape: (usize, usize)| {
            present.then(|| Array2::from_shape_fn(shape, |(j, i)| (i + 2 * j) as f64))
        };
        for shape in [(16, 16), (12, 20)] {
            for mask in 1..8u8 {
                let (p, qx, qy) = (mask & 1 != 0, mask & 2 != 0, mask & 4 != 0);
                let loads = [p, qx, qy].iter().filter(|&&b| b).count();
                let grid = TractionGrid::new(
                    [0.0, 0.0],
                    [1.0, 1.0],
                    cell(p, shape),
                    cell(qx, shape),
                    cell(qy, shape),
                )
                .expect("grid");
                for fft in [
                    DcFft::new(&grid, 0.3).expect("isolated"),
                    DcFft::periodic(&grid, 0.3).expect("periodic"),
                ] {
                    let estimate = kept_layers_bytes([shape.0, shape.1], loads, 4, 2);
                    let layers = 4 * 48 * shape.0 * shape.1;
                    assert!(
                        estimate >= layers + 2 * fft.worker_bytes(),
                        "{shape:?}, loads {mask:03b}: {estimate} < {layers} + 2 x {}",
                        fft.worker_bytes()
                    );
                }
            }
        }
        assert_eq!(kept_layers_bytes([1 << 40, 1 << 40], 3, 50, 64), usize::MAX);
        // The call: 4096² at 50 depths, about 40 GB kept alone.
        assert!(kept_layers_bytes([4096, 4096], 1, 50, 2) > 40_000_000_000);
    }
}

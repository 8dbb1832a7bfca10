//! DC-FFT of gridded surface tractions (issue 4): the sliding Hertz point contact (p and
//! qx = 0.3 p) on 256 x 256 cells over [-2a, 2a]^2, all six stress components on 128 depth
//! layers, in parallel over the layers. Target: under 3 s on two cores. The same as one period
//! of periodic tractions (spectral layers, issue 22).
//! Also one layer on the calling thread, one xy section through the field layer (its six
//! components in parallel), the subsurface maxima search of a rough contact's report, and
//! direct summation against DC-FFT on a small grid (both on one
//! thread) for the ratio.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use ndarray::Array2;
use stressfield::field::{self, Axis, Plane, Section};
use stressfield::solution::dcfft::{DcFft, TractionGrid};
use stressfield::solution::Solution;
use stressfield::stress::Quantity;

/// Hertz tractions sampled at the cell centres of an n x n grid over [-2, 2]^2.
fn hertz_grid(n: usize) -> TractionGrid {
    let cell = 4.0 / n as f64;
    let pressure = Array2::from_shape_fn((n, n), |(j, i)| {
        let x = -2.0 + (i as f64 + 0.5) * cell;
        let y = -2.0 + (j as f64 + 0.5) * cell;
        (1.0 - x * x - y * y).max(0.0).sqrt()
    });
    let shear_x = pressure.mapv(|p| 0.3 * p);
    TractionGrid::new(
        [-2.0, -2.0],
        [cell, cell],
        Some(pressure),
        Some(shear_x),
        None,
    )
    .expect("valid grid")
}

fn dcfft(c: &mut Criterion) {
    let mut group = c.benchmark_group("dcfft");
    group.sample_size(10);
    let grid = hertz_grid(256);
    let fft = DcFft::new(&grid, 0.3).expect("planned");
    let depths: Vec<f64> = (0..128).map(|k| 2.0 * f64::from(k) / 127.0).collect();
    group.bench_with_input(
        BenchmarkId::new("parallel_layers", "256x256x128"),
        &depths,
        |b, depths| {
            b.iter(|| {
                field::for_each_dcfft_layer(&fft, depths, |_, _, layer| {
                    black_box(layer[[2, 128, 128]]);
                })
            })
        },
    );
    // The same tractions as one period (issue 22): layers from a cell down in Fourier space.
    let periodic = DcFft::periodic(&grid, 0.3).expect("planned");
    group.bench_with_input(
        BenchmarkId::new("periodic_layers", "256x256x128"),
        &depths,
        |b, depths| {
            b.iter(|| {
                field::for_each_dcfft_layer(&periodic, depths, |_, _, layer| {
                    black_box(layer[[2, 128, 128]]);
                })
            })
        },
    );
    let mut workspace = fft.workspace();
    let mut layer = ndarray::Array3::zeros((6, 256, 256));
    group.bench_function(BenchmarkId::new("sequential_layer", "256x256"), |b| {
        b.iter(|| fft.layer_into(black_box(0.5), &mut workspace, layer.view_mut()))
    });
    // The influence coefficients of one layer: on one thread, and in blocks of rows over the
    // rayon pool (as field::for_each_dcfft_layer does for fewer layers than threads).
    let mut quadrant = Vec::new();
    group.bench_function(BenchmarkId::new("influence_sequential", "256x256"), |b| {
        b.iter(|| fft.influence_into(black_box(0.5), &mut quadrant))
    });
    group.bench_function(BenchmarkId::new("influence_blocks", "256x256"), |b| {
        b.iter(|| {
            use rayon::prelude::*;
            let threads = rayon::current_num_threads();
            fft.influence_blocks(&mut quadrant, 4 * threads)
                .into_par_iter()
                .for_each(|block| fft.fill_influence(black_box(0.5), block));
        })
    });
    // One xy section through the field layer (the six components of one layer in parallel),
    // against the sequential layer above, all six components and von Mises.
    let solution = Solution::sphere_numerical(0.3, 0.3, 256, 2.0).expect("planned");
    let centres = Axis::new(-2.0 + 2.0 / 256.0, 2.0 - 2.0 / 256.0, 256);
    let section = Plane {
        section: Section::Xy { z: 0.5 },
        u: centres,
        v: centres,
    };
    let quantities = [
        Quantity::Sxx,
        Quantity::Syy,
        Quantity::Szz,
        Quantity::Syz,
        Quantity::Sxz,
        Quantity::Sxy,
        Quantity::VonMises,
    ];
    group.bench_function(BenchmarkId::new("field_xy_section", "256x256"), |b| {
        b.iter(|| field::evaluate(&solution, &section, &quantities, &|| {}).expect("fits"))
    });
    // The subsurface maxima search (σvM and Tresca over every cell of each layer, as the
    // rough contact report runs it) down to 1.5a: 47 layers (32 one cell apart, then each 8 %
    // deeper) and the fine ones around the best.
    let tractions = stressfield::solution::point_numerical::PointTractions::new(grid.clone(), 0.3)
        .expect("transformed");
    group.bench_function(BenchmarkId::new("grid_maxima_to_depth", "256x256"), |b| {
        b.iter(|| stressfield::study::assess::grid_maxima_to_depth(&tractions, black_box(1.5)))
    });
    // Direct summation against DC-FFT, one layer, one thread, small grid.
    let small = hertz_grid(32);
    let small_fft = DcFft::new(&small, 0.3).expect("planned");
    group.bench_function(BenchmarkId::new("direct_layer", "32x32"), |b| {
        b.iter(|| small.direct_layer(black_box(0.5), 0.3))
    });
    group.bench_function(BenchmarkId::new("sequential_layer", "32x32"), |b| {
        b.iter(|| small_fft.layer(black_box(0.5)))
    });
    group.finish();
}

criterion_group!(benches, dcfft);
criterion_main!(benches);

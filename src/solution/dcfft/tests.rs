//! Tests of [`super`].

use super::*;
use ndarray::Array2;

fn grid(shape: [usize; 2], loads: [bool; 3]) -> TractionGrid {
    grid_of_cells(shape, [0.1, 0.07], loads)
}

fn grid_of_cells(shape: [usize; 2], cell: [f64; 2], loads: [bool; 3]) -> TractionGrid {
    let [ny, nx] = shape;
    let field = |seed: f64| {
        Array2::from_shape_fn((ny, nx), |(j, i)| {
            let (x, y) = (i as f64 / nx as f64, j as f64 / ny as f64);
            (seed * x + 2.1 * y + seed * x * y).sin() + 0.3 * (7.0 * x * seed).cos()
        })
    };
    TractionGrid::new(
        [-0.4, 0.3],
        cell,
        loads[0].then(|| field(1.3)),
        loads[1].then(|| field(2.9)),
        loads[2].then(|| field(-1.7)),
    )
    .expect("valid grid")
}

fn assert_layers_agree(grid: &TractionGrid, depths: &[f64], nu: f64) {
    let fft = DcFft::new(grid, nu).expect("planned");
    for &z in depths {
        let direct = grid.direct_layer(z, nu);
        let difference = (&fft.layer(z).expect("transformed") - &direct)
            .iter()
            .fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(
            difference < 1e-9,
            "z = {z}: max |FFT - direct| = {difference:e}"
        );
        let shape = grid.shape();
        eprintln!("{shape:?}, z = {z}: max |FFT - direct| = {difference:.1e}");
    }
}

#[test]
fn fft_equals_direct_summation_on_small_grids() {
    // Tractions of order one; 16 x 12 and 20 x 20; the surface, tiny and larger depths.
    assert_layers_agree(
        &grid([12, 16], [true, true, true]),
        &[0.0, 1e-6, 0.03, 0.7],
        0.3,
    );
    assert_layers_agree(&grid([20, 20], [true, true, false]), &[0.0, 0.01, 2.0], 0.5);
    // The pressure and the shear along x transformed together (`Packed`), on an odd grid.
    assert_layers_agree(&grid([9, 14], [true, true, false]), &[0.0, 0.05, 0.6], 0.3);
    assert_layers_agree(&grid([7, 5], [false, false, true]), &[0.0, 0.2], 0.0);
    // Degenerate shapes: one cell, one row, one column.
    assert_layers_agree(&grid([1, 1], [true, true, true]), &[0.0, 0.5], 0.3);
    assert_layers_agree(&grid([1, 6], [true, false, false]), &[0.1], 0.3);
    assert_layers_agree(&grid([5, 1], [false, true, false]), &[0.1], 0.3);
}

#[test]
fn square_cells_turned_about_the_diagonal_equal_direct_summation() {
    // An isolated square grid of square cells evaluates the offsets a >= b only and turns
    // them about x = y for the others (`fill_turned_influence`); every combination of loads,
    // since the shears exchange under the turn.
    for loads in [
        [true, true, true],
        [true, true, false],
        [true, false, false],
        [false, true, false],
        [false, false, true],
        [false, true, true],
    ] {
        let grid = grid_of_cells([13, 13], [0.08, 0.08], loads);
        assert!(DcFft::new(&grid, 0.3)
            .expect("planned")
            .turns_about_diagonal());
        assert_layers_agree(&grid, &[0.0, 1e-6, 0.04, 0.9], 0.3);
    }
    assert_layers_agree(
        &grid_of_cells([1, 1], [0.5, 0.5], [true; 3]),
        &[0.0, 0.3],
        0.25,
    );
    // The turn needs both: a square grid of oblong cells, an oblong grid of square cells.
    for (shape, cell) in [([6, 6], [0.1, 0.07]), ([6, 7], [0.1, 0.1])] {
        let grid = grid_of_cells(shape, cell, [true; 3]);
        assert!(!DcFft::new(&grid, 0.3)
            .expect("planned")
            .turns_about_diagonal());
    }
}

/// The coefficients split over threads, band by band, are those of one thread to the last
/// bit: several bands of 64 rows and a short last one, parts of uneven length, the rows
/// below each band in chunks; turned grids with every pair of loads, and a grid that does not
/// turn (blocks of rows).
#[test]
fn coefficients_split_over_threads_equal_those_of_one_thread() {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(3)
        .build()
        .expect("a thread pool");
    let cases = [
        ([150, 150], [0.01, 0.01], [true, false, true]),
        ([150, 150], [0.01, 0.01], [true, true, false]),
        ([70, 70], [0.02, 0.02], [false, true, true]),
        ([40, 45], [0.02, 0.03], [true, false, true]),
    ];
    for (shape, cell, loads) in cases {
        let fft = DcFft::new(&grid_of_cells(shape, cell, loads), 0.3).expect("planned");
        for z in [0.0, 0.013, 0.4] {
            let mut one = Vec::new();
            fft.influence_into(z, &mut one);
            for threads in [2, 3, 5] {
                let mut split = Vec::new();
                pool.install(|| fft.influence_in_parallel(z, &mut split, threads));
                assert!(
                    one.iter()
                        .zip(&split)
                        .all(|(a, b)| a.to_bits() == b.to_bits()),
                    "{shape:?}, z = {z}, {threads} threads: not the same bits"
                );
            }
        }
    }
}

fn max_difference(a: &Array3<f64>, b: &Array3<f64>) -> f64 {
    (a - b).iter().fold(0.0f64, |m, v| m.max(v.abs()))
}

#[test]
fn periodic_fft_equals_periodic_direct_summation() {
    // Even and odd sizes (the window's edge falls on a cell for even ones), one row.
    for (shape, loads, nu) in [
        ([6, 8], [true, true, true], 0.3),
        ([5, 7], [true, true, false], 0.25),
        ([1, 6], [true, false, true], 0.3),
        ([4, 1], [false, true, false], 0.0),
    ] {
        let grid = grid(shape, loads);
        let fft = DcFft::periodic_by_cells(&grid, nu).expect("planned");
        for z in [0.0, 0.02, 0.3, 1.5] {
            let difference = max_difference(
                &fft.layer(z).expect("transformed"),
                &grid.periodic_direct_layer(z, nu),
            );
            assert!(difference < 1e-9, "{shape:?}, z = {z}: {difference:e}");
        }
    }
}

/// A periodic square grid of square cells sums the offsets `b <= a <= n/2` only, and turns
/// and mirrors them for the others (`fill_periodic_turned_influence`): its coefficients equal
/// those summed image by image at every offset (the blocks of `fill_influence`) to rounding,
/// with every combination of loads (the shears exchange under the turn, and one without the
/// other needs the other's sums), on even and odd grids, at the surface and within the first
/// cell; the same bits on one thread or several; and its layers equal direct summation.
#[test]
fn periodic_square_cells_turned_about_the_diagonal_equal_every_offset_summed() {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(3)
        .build()
        .expect("a thread pool");
    let mut worst = 0.0f64;
    for n in [8, 7] {
        for loads in [
            [true, false, false],
            [true, true, false],
            [true, false, true],
            [false, true, false],
            [false, false, true],
            [false, true, true],
            [true, true, true],
        ] {
            let grid = grid_of_cells([n, n], [0.1, 0.1], loads);
            let fft = DcFft::periodic(&grid, 0.3).expect("planned");
            assert!(fft.periodic_turns_about_diagonal());
            for z in [0.0, 0.025, 0.04375] {
                let mut turned = Vec::new();
                fft.influence_into(z, &mut turned);
                let mut summed = Vec::new();
                for block in fft.influence_blocks(&mut summed, 1) {
                    fft.fill_influence(z, block);
                }
                // The rows b <= n/2 are the coefficients (the others are their mirror).
                let rows = (n / 2 + 1) * n;
                for (t, s) in turned.chunks_exact(n * n).zip(summed.chunks_exact(n * n)) {
                    let largest = s[..rows].iter().fold(0.0f64, |m, v| m.max(v.abs()));
                    let difference = t[..rows]
                        .iter()
                        .zip(&s[..rows])
                        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
                    worst = worst.max(difference / largest);
                    assert!(
                        difference <= 1e-14 * largest,
                        "{n}², {loads:?}, z = {z}: {difference:e} of {largest:e}"
                    );
                }
                for threads in [2, 3] {
                    let mut split = Vec::new();
                    pool.install(|| fft.influence_in_parallel(z, &mut split, threads));
                    assert!(
                        turned
                            .iter()
                            .zip(&split)
                            .all(|(a, b)| a.to_bits() == b.to_bits()),
                        "{n}², {loads:?}, z = {z}, {threads} threads: not the same bits"
                    );
                }
            }
        }
    }
    eprintln!("periodic turned vs every offset summed: at most {worst:.1e} of the largest");
    let grid = grid_of_cells([6, 6], [0.1, 0.1], [true, true, false]);
    let fft = DcFft::periodic_by_cells(&grid, 0.3).expect("planned");
    for z in [0.0, 0.04] {
        let difference = max_difference(
            &fft.layer(z).expect("transformed"),
            &grid.periodic_direct_layer(z, 0.3),
        );
        assert!(difference < 1e-9, "6², z = {z}: {difference:e}");
    }
    // The turn needs both: a square grid of oblong cells, an oblong grid of square cells.
    for (shape, cell) in [([6, 6], [0.1, 0.07]), ([6, 7], [0.1, 0.1])] {
        let grid = grid_of_cells(shape, cell, [true; 3]);
        assert!(!DcFft::periodic(&grid, 0.3)
            .expect("planned")
            .periodic_turns_about_diagonal());
    }
}

#[test]
fn periodic_images_beyond_the_window_are_negligible() {
    // Zero-mean tractions carry no net force: with the far images spread over the plane,
    // the window of two periods each way is within 1e-3 of the largest traction of the
    // window of twelve (measured: 4.8e-4).
    let grid = grid([6, 8], [true, true, true]);
    let largest = grid
        .loads()
        .flat_map(|(_, a)| a.iter().map(|v| v.abs()))
        .fold(0.0, f64::max);
    let mut worst = 0.0f64;
    for (x, y) in [(0.05, 0.6), (-0.35, 0.33), (0.35, 0.0)] {
        for z in [0.0, 0.1, 0.4, 1.0] {
            let near = grid.periodic_stress_at(x, y, z, 0.3);
            let far = grid.periodic_stress_with_images(x, y, z, 0.3, 12);
            let difference = (0..6)
                .map(|c| (component(&near, c) - component(&far, c)).abs())
                .fold(0.0, f64::max);
            worst = worst.max(difference / largest);
        }
    }
    eprintln!(
        "periodic images: window 2 vs 12, largest difference {worst:.1e} of the largest traction"
    );
    assert!(worst < 1e-3, "{worst:e}");
}

#[test]
fn uniform_periodic_tractions_stress_the_body_uniformly() {
    let [ny, nx] = [5, 6];
    let uniform = |v: f64| Some(Array2::from_elem((ny, nx), v));
    let grid = TractionGrid::new(
        [0.3, -1.0],
        [0.2, 0.3],
        uniform(1.5),
        uniform(0.4),
        uniform(-0.2),
    )
    .expect("valid");
    let fft = DcFft::periodic(&grid, 0.3).expect("planned");
    for z in [0.0, 0.1, 3.0] {
        let layer = fft.layer(z).expect("transformed");
        for (c, expected) in [0.0, 0.0, -1.5, 0.2, -0.4, 0.0].into_iter().enumerate() {
            for value in layer.index_axis(Axis(0), c) {
                assert!(
                    (value - expected).abs() < 1e-12,
                    "c = {c}, z = {z}: {value}"
                );
            }
        }
    }
}

#[test]
fn a_sinusoidal_pressure_gives_the_closed_form() {
    // p = p̄ + p1 cos(kx), uniform in y: plane strain. Its stress, from the Airy function
    // (A + A kz) e^(-kz) cos kx with A = p1/k² (derived here): σxx = -p1 (1 - kz) e^(-kz) cos kx,
    // σzz = -p̄ - p1 (1 + kz) e^(-kz) cos kx, τxz = -p1 kz e^(-kz) sin kx,
    // σyy = ν (σxx + σzz) + (uniform part 0). The cells carry the cell means of the
    // pressure, whose fundamental has the amplitude p1 sinc²(k dx/2); the harmonics of the
    // steps fall as e^(-2π z/dx), about 3e-6 p1 at z = 2 dx. The images beyond the window
    // leave up to 5e-5 (measured; 1e-4 asked).
    let (nx, ny, dx, nu) = (32, 3, 1.0 / 32.0, 0.3);
    let k = 2.0 * std::f64::consts::PI;
    let (mean, p1) = (1.0, 0.6);
    let half = 0.5 * k * dx;
    let sinc = half.sin() / half;
    let pressure = Array2::from_shape_fn((ny, nx), |(_, i)| {
        let x = (i as f64 + 0.5) * dx;
        mean + p1 * k.recip() / dx * ((k * (x + 0.5 * dx)).sin() - (k * (x - 0.5 * dx)).sin())
    });
    let grid = TractionGrid::new([0.0, 0.0], [dx, 0.5], Some(pressure), None, None).expect("valid");
    let fft = DcFft::periodic(&grid, nu).expect("planned");
    let amplitude = p1 * sinc * sinc;
    for z in [2.0 * dx, 0.1, 0.3] {
        let layer = fft.layer(z).expect("transformed");
        let decay = (-k * z).exp();
        for i in 0..nx {
            let x = (i as f64 + 0.5) * dx;
            let (c, s) = ((k * x).cos(), (k * x).sin());
            let sxx = -amplitude * (1.0 - k * z) * decay * c;
            let szz = -mean - amplitude * (1.0 + k * z) * decay * c;
            let sxz = -amplitude * k * z * decay * s;
            let syy = nu * (sxx + szz + mean);
            for (component, expected) in [(0, sxx), (1, syy), (2, szz), (4, sxz)] {
                let got = layer[[component, 1, i]];
                assert!(
                    (got - expected).abs() < 1e-4,
                    "z = {z}, x = {x}, component {component}: {got} vs {expected}"
                );
            }
            for component in [3, 5] {
                assert!(layer[[component, 1, i]].abs() < 1e-12);
            }
        }
    }
}

#[test]
fn shape_mismatch_and_missing_tractions_are_reported() {
    let a = Array2::zeros((3, 4));
    let b = Array2::zeros((4, 3));
    assert_eq!(
        TractionGrid::new([0.0; 2], [1.0; 2], Some(a.clone()), None, Some(b)),
        Err(TractionGridError::ShapeMismatch {
            name: "shear_y",
            got: [4, 3],
            first: "pressure",
            expected: [3, 4],
        })
    );
    assert_eq!(
        TractionGrid::new([0.0; 2], [1.0; 2], None, None, None),
        Err(TractionGridError::NoTraction)
    );
    assert!(matches!(
        TractionGrid::new([0.0; 2], [0.0, 1.0], Some(a), None, None),
        Err(TractionGridError::CellSize { .. })
    ));
}

/// The largest |traction| of a grid.
fn largest_traction(grid: &TractionGrid) -> f64 {
    grid.loads()
        .flat_map(|(_, a)| a.iter().map(|v| v.abs()))
        .fold(0.0, f64::max)
}

#[test]
fn spectral_layers_equal_the_exact_periodic_sum() {
    // The spectral layers are exact for the periodic cells; the window of twelve images each
    // way is the independent reference (its own truncation measured at about 1e-5 of the
    // largest traction). Even and odd sizes (Nyquist wavenumbers), one row, all three loads,
    // from half a cell down.
    for (shape, loads, nu) in [
        ([6, 8], [true, true, true], 0.3),
        ([5, 7], [true, true, false], 0.25),
        ([1, 6], [true, false, true], 0.3),
    ] {
        let grid = grid(shape, loads);
        let largest = largest_traction(&grid);
        let fft = DcFft::periodic(&grid, nu).expect("planned");
        let cell = grid.cell()[0].min(grid.cell()[1]);
        let mut worst = 0.0f64;
        for z in [0.5 * cell, 0.7 * cell, cell, 1.5 * cell, 3.0 * cell, 0.9] {
            assert!(fft.is_spectral(z));
            let layer = fft.layer(z).expect("transformed");
            let [ny, nx] = shape;
            for (row, column) in [(0, 0), (ny / 2, nx - 1), (ny - 1, nx / 2)] {
                let (x, y) = grid.cell_centre(row, column);
                let far = grid.periodic_stress_with_images(x, y, z, nu, 12);
                for c in 0..6 {
                    let difference = (layer[[c, row, column]] - component(&far, c)).abs();
                    worst = worst.max(difference / largest);
                }
            }
        }
        eprintln!("{shape:?}: spectral vs 12 images, largest difference {worst:.1e}");
        assert!(worst < 1e-4, "{shape:?}: {worst:e}");
    }
}

#[test]
fn spectral_layers_agree_with_the_cell_based_layers() {
    // The cell-based periodic layers sum the images within two periods each way, which leaves
    // up to about 5e-4 of the largest traction (see the test of the images); the spectral
    // layers must agree with them to that, at every cell centre, and equal them in the mean.
    let grid = grid([12, 16], [true, true, true]);
    let largest = largest_traction(&grid);
    let nu = 0.3;
    let spectral = DcFft::periodic(&grid, nu).expect("planned");
    let cells = DcFft::periodic_by_cells(&grid, nu).expect("planned");
    let cell = grid.cell()[0].min(grid.cell()[1]);
    for z in [0.5 * cell, cell, 2.0 * cell, 0.5] {
        let (a, b) = (
            spectral.layer(z).expect("spectral"),
            cells.layer(z).expect("cells"),
        );
        let difference = max_difference(&a, &b) / largest;
        eprintln!("z = {z}: spectral vs cell-based periodic layers {difference:.1e}");
        assert!(difference < 1e-3, "z = {z}: {difference:e}");
        for c in 0..6 {
            let mean = |l: &Array3<f64>| l.index_axis(Axis(0), c).mean().unwrap_or(0.0);
            assert!(
                (mean(&a) - mean(&b)).abs() < 1e-3 * largest,
                "z = {z}, c = {c}"
            );
        }
    }
    // Shallower than half a cell: the cell-based layers themselves.
    assert!(!spectral.is_spectral(0.45 * cell));
    assert_eq!(
        spectral.layer(0.2 * cell).expect("cells"),
        cells.layer(0.2 * cell).expect("cells")
    );
}

#[test]
fn a_sinusoidal_shear_across_the_grid_gives_the_closed_form() {
    // qy = q1 cos(kx), uniform in y: an anti-plane wave (the shear across the wave
    // direction), σyz = -q1 e^(-kz) cos kx, σxy = -q1 e^(-kz) sin kx (u_y harmonic, derived in
    // the module doc of `spectral`), every other component zero. The cells carry the cell
    // means, q1 sinc(k dx/2) cos(k x_c); the steps' fundamental has the amplitude
    // q1 sinc²(k dx/2), and their harmonics at z >= 2 dx are below 3e-6 q1 (as for the
    // pressure wave).
    let (nx, ny, dx) = (32, 3, 1.0 / 32.0);
    let k = 2.0 * std::f64::consts::PI;
    let q1 = 0.8;
    let half = 0.5 * k * dx;
    let amplitude = q1 * (half.sin() / half).powi(2);
    let shear = Array2::from_shape_fn((ny, nx), |(_, i)| {
        let x = (i as f64 + 0.5) * dx;
        q1 / (k * dx) * ((k * (x + 0.5 * dx)).sin() - (k * (x - 0.5 * dx)).sin())
    });
    let grid = TractionGrid::new([0.0, 0.0], [dx, 0.5], None, None, Some(shear)).expect("valid");
    let fft = DcFft::periodic(&grid, 0.3).expect("planned");
    for z in [2.0 * dx, 0.1, 0.3] {
        let layer = fft.layer(z).expect("transformed");
        let decay = (-k * z).exp();
        for i in 0..nx {
            let x = (i as f64 + 0.5) * dx;
            let syz = -amplitude * decay * (k * x).cos();
            let sxy = -amplitude * decay * (k * x).sin();
            for (c, expected) in [(0, 0.0), (1, 0.0), (2, 0.0), (3, syz), (4, 0.0), (5, sxy)] {
                let got = layer[[c, 1, i]];
                assert!(
                    (got - expected).abs() < 1e-5,
                    "z = {z}, x = {x}, component {c}: {got} vs {expected}"
                );
            }
        }
    }
}

use ndarray::{Array2, Array3, Array4};

use super::*;
use crate::plasticity::column::{XX, XY, XZ, YY, YZ, ZZ};

const MU: f64 = 80e9;
const NU: f64 = 0.3;

fn grid(n: usize, nz: usize, h: f64, periodicity: Periodicity) -> VolumeGrid {
    VolumeGrid {
        shape: [n, n],
        spacing_m: [h, h],
        depth: DepthCells::uniform(nz, h).expect("depth"),
        periodicity,
    }
}

/// A dilatational eigenstrain `e` (each normal component) in the cells whose centres lie
/// within `radius` of `(x0, y0, c)` (cell indices).
fn ball(dims: [usize; 3], centre: [f64; 3], radius: f64, e: f64) -> (Array4<f64>, usize) {
    let [nz, ny, nx] = dims;
    let mut strain = Array4::zeros((nz, 6, ny, nx));
    let mut cells = 0;
    for l in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                let d = [
                    i as f64 + 0.5 - centre[0],
                    j as f64 + 0.5 - centre[1],
                    l as f64 + 0.5 - centre[2],
                ];
                if d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= radius * radius {
                    for c in [XX, YY, ZZ] {
                        strain[[l, c, j, i]] = e;
                    }
                    cells += 1;
                }
            }
        }
    }
    (strain, cells)
}

/// Mindlin & Cheng's spherical inclusion of dilatation `e`, volume `V`, centre depth `c`: by
/// reciprocity with Boussinesq's trace `-(1 + ν) z / (π R³)` (Johnson 1985, §3.2), harmonic
/// outside the ball, the surface moves by `u_z = -(1 + ν) e V c / (π (r² + c²)^(3/2))`
/// (into the body; the surface bulges out), and deep below the surface the inclusion is
/// under Eshelby's uniform pressure `σ = -4μ(1 + ν) e / (3(1 - ν))`.
#[test]
fn a_spherical_inclusion_lifts_the_surface_as_mindlin_and_cheng_s() {
    let (n, nz, h) = (48, 24, 1e-6);
    let vol = grid(n, nz, h, Periodicity::NonPeriodic);
    let e = 1e-3;
    let centre = [24.0, 24.0, 9.0];
    let (strain, cells) = ball(vol.dims(), centre, 4.6, e);
    let mut op = HalfSpace::new(vol, MU, NU);
    let mut stress = Array4::zeros((nz, 6, n, n));
    let mut surface = Array2::zeros((n, n));
    op.apply(strain.view(), None, stress.view_mut(), surface.view_mut())
        .expect("apply");
    let volume = cells as f64 * h * h * h;
    let c = centre[2] * h;
    let mut worst: f64 = 0.0;
    let peak = (1.0 + NU) * e * volume / (std::f64::consts::PI * c * c);
    for (j, i) in [(24, 24), (24, 30), (20, 33), (24, 40), (10, 12)] {
        let (x, y) = (
            (i as f64 + 0.5 - centre[0]) * h,
            (j as f64 + 0.5 - centre[1]) * h,
        );
        let r2 = x * x + y * y;
        let expected =
            -(1.0 + NU) * e * volume * c / (std::f64::consts::PI * (r2 + c * c).powf(1.5));
        let got = surface[[j, i]];
        worst = worst.max((got - expected).abs() / peak);
    }
    assert!(
        worst < 0.01,
        "surface displacement off by {worst:.2e} of its peak"
    );
    // Eshelby's uniform pressure inside, deep below the surface: the half-space's image
    // stresses the inclusion by about (a/c)³ of it (7 % in σzz at c = 2a), so the inclusion
    // is put at c = 3.5a, where they are 1.1 %. The staircase ball leaves shears inside that
    // fall with its radius in cells (7 % at 4.6 cells, 0.2 % at 9.2 cells, 0.6 % here).
    let (n, nz) = (64, 40);
    let deep = [32.0, 32.0, 24.0];
    let vol = grid(n, nz, h, Periodicity::NonPeriodic);
    let (strain, _) = ball(vol.dims(), deep, 6.9, e);
    let mut op = HalfSpace::new(vol, MU, NU);
    let mut stress = Array4::zeros((nz, 6, n, n));
    let mut surface = Array2::zeros((n, n));
    op.apply(strain.view(), None, stress.view_mut(), surface.view_mut())
        .expect("apply");
    let eshelby = -4.0 * MU * (1.0 + NU) * e / (3.0 * (1.0 - NU));
    for comp in [XX, YY, ZZ] {
        let value = stress[[24, comp, 32, 32]];
        assert!(
            (value / eshelby - 1.0).abs() < 0.02,
            "component {comp}: {value:e} vs {eshelby:e}"
        );
    }
    for comp in [XY, XZ, YZ] {
        let value = stress[[24, comp, 32, 32]];
        assert!(
            value.abs() < 0.01 * eshelby.abs(),
            "{comp}: {:e}",
            value / eshelby
        );
    }
}

/// A uniform eigenstrain in a layer, periodic: the constrained film, `σxx = σyy = -E e/(1 - ν)`
/// in the layer, nothing below it, the surface lifted by `2ν e h/(1 - ν)`.
#[test]
fn a_uniform_layer_is_the_constrained_film() {
    let (n, nz, h) = (8, 6, 1e-6);
    let vol = grid(n, nz, h, Periodicity::Periodic);
    let e = 2e-3;
    let mut strain = Array4::zeros((nz, 6, n, n));
    for l in 1..3 {
        for c in [XX, YY] {
            strain
                .index_axis_mut(Axis(0), l)
                .index_axis_mut(Axis(0), c)
                .fill(e);
        }
    }
    let mut op = HalfSpace::new(vol, MU, NU);
    let mut stress = Array4::zeros((nz, 6, n, n));
    let mut surface = Array2::zeros((n, n));
    op.apply(strain.view(), None, stress.view_mut(), surface.view_mut())
        .expect("apply");
    let young = 2.0 * MU * (1.0 + NU);
    for ((l, c, _, _), &value) in stress.indexed_iter() {
        let expected = if (1..3).contains(&l) && (c == XX || c == YY) {
            -young * e / (1.0 - NU)
        } else {
            0.0
        };
        assert!(
            (value - expected).abs() < 1e-9 * young * e,
            "({l}, {c}): {value:e}"
        );
    }
    let lift = -2.0 * NU * e * 2.0 * h / (1.0 - NU);
    for &u in surface.iter() {
        assert!((u / lift - 1.0).abs() < 1e-12);
    }
}

/// The contact's stress added in the transforms equals the DC-FFT layers of the same
/// tractions, isolated and periodic.
#[test]
fn the_contact_stress_in_the_transforms_equals_dcfft_layers() {
    for periodicity in [Periodicity::NonPeriodic, Periodicity::Periodic] {
        let (n, nz, h) = (12, 4, 2e-6);
        let vol = VolumeGrid {
            shape: [n, n + 2],
            spacing_m: [h, 1.3 * h],
            depth: DepthCells::new(vec![0.0, 0.4 * h, 1.3 * h, 2.0 * h, 5.0 * h]).expect("depth"),
            periodicity,
        };
        let pressure = Array2::from_shape_fn((n, n + 2), |(j, i)| {
            1e9 * (((3 * i + 5 * j) % 7) as f64 / 7.0 + 0.1)
        });
        let friction = 0.3;
        let mut op = HalfSpace::new(vol.clone(), MU, NU)
            .with_contact(NU, true)
            .expect("kernels");
        let strain = Array4::zeros((nz, 6, n, n + 2));
        let mut stress = Array4::zeros((nz, 6, n, n + 2));
        let mut surface = Array2::zeros((n, n + 2));
        op.apply(
            strain.view(),
            Some((pressure.view(), friction)),
            stress.view_mut(),
            surface.view_mut(),
        )
        .expect("apply");
        let tractions = TractionGrid::new(
            [0.0, 0.0],
            vol.spacing_m,
            Some(pressure.clone()),
            Some(pressure.mapv(|p| friction * p)),
            None,
        )
        .expect("grid");
        let fft = match periodicity {
            Periodicity::NonPeriodic => DcFft::new(&tractions, NU).expect("dcfft"),
            Periodicity::Periodic => DcFft::periodic(&tractions, NU).expect("dcfft"),
        };
        for l in 0..nz {
            let layer: Array3<f64> = fft.layer(vol.depth.centre_m(l)).expect("layer");
            for c in 0..6 {
                for j in 0..n {
                    for i in 0..n + 2 {
                        let (a, b) = (stress[[l, c, j, i]], layer[[c, j, i]]);
                        assert!(
                            (a - b).abs() < 1e-9 * 1e9,
                            "{periodicity:?} layer {l} c {c} ({j}, {i}): {a} vs {b}"
                        );
                    }
                }
            }
        }
    }
}

/// Eigenstrain and stress are tensors: turning the field a quarter turn about z turns the
/// stress with it (checks the rotation of each wave, every component).
#[test]
fn a_quarter_turn_turns_the_stress() {
    let (n, nz, h) = (16, 5, 1e-6);
    let vol = grid(n, nz, h, Periodicity::Periodic);
    let strain = Array4::from_shape_fn((nz, 6, n, n), |(l, c, j, i)| {
        let x = i as f64 - 6.0;
        let y = j as f64 - 9.0;
        let z = l as f64 - 2.0;
        1e-3 * (-(x * x + 0.5 * y * y + z * z) / 6.0).exp() * (1.0 + 0.2 * c as f64)
    });
    // (x, y) -> (y', x') = (x, -y)... a quarter turn: x' = -y, y' = x.
    let turn = |a: &Array4<f64>| {
        let mut out = Array4::zeros(a.raw_dim());
        for l in 0..nz {
            for j in 0..n {
                for i in 0..n {
                    // The point (i, j) goes to (i', j') = (n - j) % n, i).
                    let (ti, tj) = ((n - j) % n, i);
                    let v = |c: usize| a[[l, c, j, i]];
                    out[[l, XX, tj, ti]] = v(YY);
                    out[[l, YY, tj, ti]] = v(XX);
                    out[[l, ZZ, tj, ti]] = v(ZZ);
                    out[[l, XY, tj, ti]] = -v(XY);
                    out[[l, XZ, tj, ti]] = -v(YZ);
                    out[[l, YZ, tj, ti]] = v(XZ);
                }
            }
        }
        out
    };
    let mut op = HalfSpace::new(vol, MU, NU);
    let run = |op: &mut HalfSpace, strain: &Array4<f64>| {
        let mut stress = Array4::zeros((nz, 6, n, n));
        let mut surface = Array2::zeros((n, n));
        op.apply(strain.view(), None, stress.view_mut(), surface.view_mut())
            .expect("apply");
        stress
    };
    let direct = run(&mut op, &strain);
    let turned = run(&mut op, &turn(&strain));
    let expected = turn(&direct);
    let scale = direct.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for (a, b) in turned.iter().zip(&expected) {
        assert!((a - b).abs() < 1e-10 * scale, "{a} vs {b}");
    }
}

/// The images of an isolated grid (its layers padded to twice the grid) against a grid twice
/// as wide (padded to four times): a deviatoric zone (a Gaussian of 2 cells) in the middle of
/// 32 cells changes by the images by 2.0e-3 of the largest stress and 3.6e-3 of the largest
/// surface displacement (measured).
#[test]
fn the_images_of_an_isolated_grid_are_small() {
    let (nz, h) = (16, 1e-6);
    let zone = |n: usize| {
        let mut strain = Array4::zeros((nz, 6, n, n));
        let centre = n as f64 / 2.0;
        for l in 0..nz {
            for j in 0..n {
                for i in 0..n {
                    let (x, y, z) = (
                        i as f64 + 0.5 - centre,
                        j as f64 + 0.5 - centre,
                        l as f64 + 0.5 - 5.0,
                    );
                    let g = 1e-3 * (-(x * x + y * y + z * z) / 8.0).exp();
                    strain[[l, XX, j, i]] = 0.5 * g;
                    strain[[l, YY, j, i]] = 0.5 * g;
                    strain[[l, ZZ, j, i]] = -g;
                    strain[[l, XZ, j, i]] = 0.3 * g * x / 3.0;
                }
            }
        }
        strain
    };
    let run = |n: usize| {
        let mut op = HalfSpace::new(grid(n, nz, h, Periodicity::NonPeriodic), MU, NU);
        let mut stress = Array4::zeros((nz, 6, n, n));
        let mut surface = Array2::zeros((n, n));
        op.apply(zone(n).view(), None, stress.view_mut(), surface.view_mut())
            .expect("apply");
        (stress, surface)
    };
    let (small, small_surface) = run(32);
    let (wide, wide_surface) = run(64);
    let scale = wide.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let surface_scale = wide_surface.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let (mut stress_error, mut surface_error) = (0.0f64, 0.0f64);
    for l in 0..nz {
        for c in 0..6 {
            for j in 0..32 {
                for i in 0..32 {
                    let difference = small[[l, c, j, i]] - wide[[l, c, j + 16, i + 16]];
                    stress_error = stress_error.max(difference.abs() / scale);
                }
            }
        }
    }
    for j in 0..32 {
        for i in 0..32 {
            let difference = small_surface[[j, i]] - wide_surface[[j + 16, i + 16]];
            surface_error = surface_error.max(difference.abs() / surface_scale);
        }
    }
    eprintln!("images: stress {stress_error:.2e}, surface {surface_error:.2e} of their largest");
    assert!(
        stress_error < 3e-3,
        "stress changed by {stress_error:e} of its largest"
    );
    assert!(
        surface_error < 6e-3,
        "surface changed by {surface_error:e} of its largest"
    );
}

use super::*;

const MU: f64 = 80e9;
const NU: f64 = 0.3;

/// A reproducible complex number in [-1, 1]² from a seed.
fn pseudo(seed: usize) -> C64 {
    let a = ((seed as f64 * 12.9898).sin() * 43758.5453).fract();
    let b = ((seed as f64 * 78.233).sin() * 12345.6789).fract();
    C64::new(a, b)
}

fn random_strains(count: usize, seed: usize) -> Vec<[C64; 6]> {
    (0..count)
        .map(|j| std::array::from_fn(|c| pseudo(seed + 7 * j + c) * 1e-3))
        .collect()
}

fn rotate_in(strain: &[C64; 6], n: [f64; 2]) -> (C64, C64, C64, C64, C64, C64) {
    let (nx, ny) = (n[0], n[1]);
    let s = strain;
    let ss = s[XX] * (nx * nx) + s[XY] * (2.0 * nx * ny) + s[YY] * (ny * ny);
    let tt = s[XX] * (ny * ny) - s[XY] * (2.0 * nx * ny) + s[YY] * (nx * nx);
    let st = (s[YY] - s[XX]) * (nx * ny) + s[XY] * (nx * nx - ny * ny);
    let sz = s[XZ] * nx + s[YZ] * ny;
    let tz = s[YZ] * nx - s[XZ] * ny;
    (ss, tt, s[ZZ], st, sz, tz)
}

/// The surface displacement of a cell-wise uniform eigenstrain by reciprocity (Betti): the
/// displacement of the surface in direction `e` is the integral of `σ_e : ε*`, with `σ_e`
/// the stress of a unit surface force along `e` (Boussinesq's along z, Cerruti's along s and
/// t), written for one wave (Johnson 1985 §2.8 and the shear wave of
/// [`crate::solution::dcfft::spectral`]), each taken at `-k`.
fn reciprocal_surface(k: [f64; 2], cells: &DepthCells, strain: &[[C64; 6]]) -> [C64; 3] {
    let q = k[0].hypot(k[1]);
    let n = [k[0] / q, k[1] / q];
    let i = C64::new(0.0, 1.0);
    let (mut us, mut ut, mut uz) = (C64::default(), C64::default(), C64::default());
    for (j, s) in strain.iter().enumerate() {
        let (za, zb) = (cells.faces_m()[j], cells.faces_m()[j + 1]);
        // ∫ e^(-qz) dz and ∫ qz e^(-qz) dz over the cell.
        let i0 = ((-q * za).exp() - (-q * zb).exp()) / q;
        let i1 = ((1.0 + q * za) * (-q * za).exp() - (1.0 + q * zb) * (-q * zb).exp()) / q;
        let (ss, tt, zz, st, sz, tz) = rotate_in(s, n);
        uz += -ss * (i0 - i1) - tt * (2.0 * NU * i0) - zz * (i0 + i1) - sz * i * (2.0 * i1);
        us += -(ss * i) * (2.0 * i0 - i1)
            - tt * i * (2.0 * NU * i0)
            - zz * i * i1
            - sz * (2.0 * (i0 - i1));
        ut += -(st * i) * (2.0 * i0) - tz * (2.0 * i0);
    }
    [us * n[0] - ut * n[1], us * n[1] + ut * n[0], uz]
}

#[test]
fn surface_displacement_equals_reciprocity_with_boussinesq_and_cerruti() {
    let column = Column::new(MU, NU);
    let cells = DepthCells::new(vec![0.0, 0.3e-6, 1.0e-6, 1.2e-6, 2.5e-6, 4.0e-6]).expect("cells");
    let strain = random_strains(cells.count(), 3);
    let mut work = ColumnWork::default();
    for k in [
        [1e6, 0.0],
        [0.0, 2e6],
        [3e5, -4e5],
        [-2.5e6, 1.5e6],
        [4e4, 1e4],
    ] {
        let mut stress = vec![[ZERO; 6]; cells.count()];
        let mut surface = [ZERO; 3];
        column.apply(k, &cells, &strain, &mut stress, &mut surface, &mut work);
        let expected = reciprocal_surface(k, &cells, &strain);
        let scale = expected.iter().map(|v| v.norm()).fold(0.0, f64::max);
        for c in 0..3 {
            assert!(
                (surface[c] - expected[c]).norm() < 1e-11 * scale,
                "k = {k:?}, component {c}: {} vs {}",
                surface[c],
                expected[c]
            );
        }
    }
}

/// The stresses of each wave at the centres of cells split in three, with a source uniform
/// in each original cell.
fn split_in_three(cells: &DepthCells, strain: &[[C64; 6]]) -> (DepthCells, Vec<[C64; 6]>) {
    let mut faces = vec![0.0];
    let mut fine = Vec::new();
    for (j, s) in strain.iter().enumerate() {
        let (za, h) = (cells.faces_m()[j], cells.thickness_m(j));
        for part in 1..=3 {
            faces.push(za + h * part as f64 / 3.0);
            fine.push(*s);
        }
    }
    (DepthCells::new(faces).expect("faces"), fine)
}

#[test]
fn splitting_cells_changes_nothing_at_common_centres() {
    let column = Column::new(MU, NU);
    let cells = DepthCells::new(vec![0.0, 0.5e-6, 1.5e-6, 1.7e-6, 3.0e-6]).expect("cells");
    let strain = random_strains(cells.count(), 11);
    let (fine_cells, fine_strain) = split_in_three(&cells, &strain);
    let mut work = ColumnWork::default();
    for k in [[2e6, 1e6], [0.0, 5e5], [-7e6, 0.0]] {
        let mut coarse = vec![[ZERO; 6]; cells.count()];
        let mut fine = vec![[ZERO; 6]; fine_cells.count()];
        let (mut s1, mut s2) = ([ZERO; 3], [ZERO; 3]);
        column.apply(k, &cells, &strain, &mut coarse, &mut s1, &mut work);
        column.apply(k, &fine_cells, &fine_strain, &mut fine, &mut s2, &mut work);
        let scale = coarse
            .iter()
            .flatten()
            .map(|v| v.norm())
            .fold(0.0, f64::max);
        for j in 0..cells.count() {
            for c in 0..6 {
                let (a, b) = (coarse[j][c], fine[3 * j + 1][c]);
                assert!(
                    (a - b).norm() < 1e-11 * scale,
                    "k {k:?} cell {j} c {c}: {a} {b}"
                );
            }
        }
        for c in 0..3 {
            assert!((s1[c] - s2[c]).norm() < 1e-12 * s1[c].norm().max(1e-30));
        }
    }
}

/// Equilibrium `i k_a σ_aj + ∂σ_zj/∂z = 0`, plane strain across the wave (`ε_tt = 0`), and a
/// traction-free surface, checked by finite differences on thin cells of a smooth source.
#[test]
fn stresses_are_in_equilibrium_compatible_and_free_at_the_surface() {
    let column = Column::new(MU, NU);
    let h = 2e-9;
    let count = 1500;
    let cells = DepthCells::uniform(count, h).expect("cells");
    // A smooth source: a Gaussian bump in depth around 1 µm with its own complex amplitudes.
    let amplitudes: [C64; 6] = std::array::from_fn(|c| pseudo(40 + c) * 1e-3);
    let strain: Vec<[C64; 6]> = (0..count)
        .map(|j| {
            let z = cells.centre_m(j);
            let g = (-((z - 1.2e-6) / 0.4e-6).powi(2)).exp();
            amplitudes.map(|a| a * g)
        })
        .collect();
    let mut work = ColumnWork::default();
    let i = C64::new(0.0, 1.0);
    for k in [[2e6, 0.0], [1.5e6, -1e6]] {
        let mut stress = vec![[ZERO; 6]; count];
        let mut surface = [ZERO; 3];
        column.apply(k, &cells, &strain, &mut stress, &mut surface, &mut work);
        let scale = stress
            .iter()
            .flatten()
            .map(|v| v.norm())
            .fold(0.0, f64::max);
        // Equilibrium at interior centres (central differences).
        let mut worst: f64 = 0.0;
        for j in (10..count - 10).step_by(37) {
            let s = &stress[j];
            let d = |c: usize| (stress[j + 1][c] - stress[j - 1][c]) / (2.0 * h);
            let rows = [
                i * (s[XX] * k[0] + s[XY] * k[1]) + d(XZ),
                i * (s[XY] * k[0] + s[YY] * k[1]) + d(YZ),
                i * (s[XZ] * k[0] + s[YZ] * k[1]) + d(ZZ),
            ];
            for r in rows {
                worst = worst.max(r.norm() / (scale * k[0].hypot(k[1])));
            }
        }
        assert!(worst < 1e-4, "equilibrium residual {worst:e} for k = {k:?}");
        // Plane strain across the wave: the total strain along t vanishes.
        let q = k[0].hypot(k[1]);
        let t = [-k[1] / q, k[0] / q];
        let young = 2.0 * MU * (1.0 + NU);
        for j in (0..count).step_by(97) {
            let s = &stress[j];
            let e = &strain[j];
            let along = |m: &[C64; 6]| {
                m[XX] * (t[0] * t[0]) + m[YY] * (t[1] * t[1]) + m[XY] * (2.0 * t[0] * t[1])
            };
            let trace = s[XX] + s[YY] + s[ZZ];
            let elastic = (along(s) * (1.0 + NU) - trace * NU) / young;
            let total = elastic + along(e);
            assert!(total.norm() < 1e-10 * 1e-3, "ε_tt = {total} at cell {j}");
        }
        // Traction-free surface: the tractions at the first three centres extrapolate
        // (quadratically) to zero.
        for c in [ZZ, XZ, YZ] {
            let (a, b, d) = (stress[0][c], stress[1][c], stress[2][c]);
            let at_surface = (a * 15.0 - b * 10.0 + d * 3.0) / 8.0;
            assert!(
                at_surface.norm() < 1e-7 * scale,
                "component {c} at the surface: {at_surface}"
            );
        }
    }
}

/// Boussinesq's pressure wave from the surface correction alone: a full-space field with
/// `σ_zz(0) = μ` is cancelled by the half-space's response to the pressure `p = μ`,
/// `σzz = -p (1 + kz) e^(-kz)`, `σss = -p (1 - kz) e^(-kz)`, `σsz = i p kz e^(-kz)`
/// (Johnson 1985, §2.8).
#[test]
fn the_surface_correction_is_boussinesq_s_pressure_wave() {
    let column = Column::new(MU, NU);
    let full = [ZERO, ZERO, ZERO, C64::new(1.0, 0.0)];
    let mut c = apply(&column.correction, &full);
    for v in c.iter_mut() {
        *v = -*v;
    }
    // Tractions cancelled at the surface.
    assert!(
        (c[2]).norm() < 1e-14 && (c[3] + 1.0).norm() < 1e-14,
        "{c:?}"
    );
    let nc = apply(&column.n_plus, &c);
    for kz in [0.0f64, 0.3, 1.0, 2.5] {
        let decay = (-kz).exp();
        let z: Vec<C64> = (0..4).map(|r| (c[r] + nc[r] * kz) * decay).collect();
        let (l, m) = (column.l, column.m);
        let dw = (z[0] * l + z[3]) / m;
        let ss = dw * l - z[0] * m;
        // p = 1 in units of μ.
        assert!(
            (z[3] + (1.0 + kz) * decay).norm() < 1e-13,
            "σzz at kz = {kz}"
        );
        assert!((ss + (1.0 - kz) * decay).norm() < 1e-13, "σss at kz = {kz}");
        // σ_sz = i μ Zs: i kz e^(-kz).
        assert!((z[2] - kz * decay).norm() < 1e-13, "σsz at kz = {kz}");
        let tt = (dw - z[0]) * l;
        assert!((tt + 2.0 * NU * decay).norm() < 1e-13, "σtt at kz = {kz}");
    }
}

#[test]
fn projectors_are_complementary_and_nilpotent_parts_square_to_zero() {
    let column = Column::new(MU, 0.27);
    let id = identity();
    let sum = mat_add(&column.p_plus, &column.p_minus, 1.0);
    let square = mat_mul(&column.n_plus, &column.n_plus);
    for r in 0..4 {
        for c in 0..4 {
            assert!((sum[r][c] - id[r][c]).abs() < 1e-13);
            assert!(square[r][c].abs() < 1e-13);
            // N+ = v+ ℓ+ᵀ: rank one.
            let outer = column.v_plus[r] * column.l_plus[c];
            assert!((outer - column.n_plus[r][c]).abs() < 1e-13);
        }
    }
}

/// The mean of a layer (k = 0) is the laterally constrained layer: an equibiaxial eigenstrain
/// `e` stresses it by `σxx = σyy = -E e / (1 - ν)` (a thin film on a substrate) and lifts the
/// surface by `2ν e h / (1 - ν)`; a shear `ε*_xz` leaves no stress and shifts the surface by
/// `-2 ε*_xz h`.
#[test]
fn the_mean_is_the_constrained_layer() {
    let column = Column::new(MU, NU);
    let h = 1.5e-6;
    let cells = DepthCells::new(vec![0.0, h]).expect("cells");
    let e = 1e-3;
    let mut strain = [ZERO; 6];
    strain[XX] = C64::new(e, 0.0);
    strain[YY] = C64::new(e, 0.0);
    strain[XZ] = C64::new(0.5 * e, 0.0);
    let mut stress = vec![[ZERO; 6]];
    let mut surface = [ZERO; 3];
    column.apply(
        [0.0, 0.0],
        &cells,
        &[strain],
        &mut stress,
        &mut surface,
        &mut ColumnWork::default(),
    );
    let young = 2.0 * MU * (1.0 + NU);
    let biaxial = -young * e / (1.0 - NU);
    for c in [XX, YY] {
        assert!(
            (stress[0][c].re / biaxial - 1.0).abs() < 1e-13,
            "{c}: {}",
            stress[0][c]
        );
    }
    for c in [ZZ, YZ, XZ, XY] {
        assert!(stress[0][c].norm() < 1e-13 * young * e);
    }
    assert!((surface[2].re / (-2.0 * NU * e * h / (1.0 - NU)) - 1.0).abs() < 1e-13);
    assert!((surface[0].re / (-e * h) - 1.0).abs() < 1e-13);
}

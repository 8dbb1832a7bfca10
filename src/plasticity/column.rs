//! One wave of eigenstrain in an elastic half-space, along the depth: the residual stress at
//! the centres of the depth cells and the surface displacement, exactly for an eigenstrain
//! uniform in each cell, in `O(n)` for `n` cells.
//!
//! ## The problem of one wave
//! An eigenstrain `ε*(z) exp(i k·x)` (`k = |k| > 0`, `n = k / k`, `t = (-n_y, n_x)`; `s`
//! along `n`) in the half-space `z >= 0` with a traction-free surface. With the eigenstress
//! `σ* = C : ε* = λ tr(ε*) I + 2μ ε*`, the residual stress is `σ = C : ε(u) - σ*`, in
//! equilibrium (`div σ = 0`), with `σ·e_z = 0` at `z = 0` and `u -> 0` deep down. In the frame
//! `(s, t, z)` the problem splits (`∂s = i k`, `∂t = 0`) into a plane-strain problem in `(s, z)`
//! and an anti-plane one along `t`.
//!
//! Written for the state of the tractions on planes `z = const` and the displacements, the
//! equations are of first order and the eigenstrain enters only as a source term, uniform in
//! each cell (no jumps at the cell faces). Plane strain, with `u_s = i ũ`, `σ_sz = i τ̃` (so
//! that everything below is real for a real source) and the state
//! `Z = (k ũ, k u_z, τ̃ / μ, σ_zz / μ)`:
//!
//! ```text
//! dZ/dz = k (Â Z + f),   Â = | 0        -1  1   0   |
//!                            | l/m       0  0   1/m |
//!                            | 4(l+1)/m  0  0  -l/m |
//!                            | 0         0  1   0   |
//! f = (2 ε̃*_sz,  σ*_zz / (m μ),  (σ*_ss - (l/m) σ*_zz) / μ,  0),
//! ```
//!
//! with `l = λ/μ = 2ν/(1 - 2ν)`, `m = (λ + 2μ)/μ = 2(1 - ν)/(1 - 2ν)`, `ε*_sz = i ε̃*_sz`:
//! the first row is `σ_sz = μ(∂z u_s + ∂s u_z) - σ*_sz`, the second `σ_zz = λ tr ε + 2μ ∂z u_z
//! - σ*_zz`, the last two the equilibrium of `s` and `z`. The other stresses follow locally:
//! `∂z u_z = (l k ũ + σ_zz/μ + σ*_zz/μ)/m`, `σ_ss = λ ∂z u_z - (λ + 2μ) k ũ - σ*_ss`,
//! `σ_tt = λ (∂z u_z - k ũ) - σ*_tt`. Anti-plane, with `σ_st = i σ̃_st` and the state
//! `Z = (k u_t, σ_tz / μ)`: `Â = [[0, 1], [1, 0]]`, `f = (2 ε*_tz, -2 ε̃*_st)`, and
//! `σ̃_st = μ k u_t - σ̃*_st`. (Derived here from Hooke's law and equilibrium; the same
//! decomposition of a wave into a plane and an anti-plane problem as for the surface tractions
//! of [`crate::solution::dcfft::spectral`].)
//!
//! ## The solution
//! `Â` has the eigenvalues `-1` and `+1`, each twice in plane strain with one eigenvector
//! (a Jordan block: the solutions `e^(∓kz)` and `z e^(∓kz)` of Boussinesq's problem). With
//! the spectral projectors `P± = (Â ± 2I)(Â ∓ I)² / (±4)`, i.e.
//! `P+ = (Â + 2I)(Â - I)²/4`, `P- = (2I - Â)(Â + I)²/4` (partial fractions of
//! `1 = (x + 2)(x - 1)²/4 + (2 - x)(x + 1)²/4`), and the nilpotent parts `N± = (Â ± I) P±`,
//! the full space's Green function of `dZ/dz = kÂZ + δ` decaying both ways is
//!
//! ```text
//! G(ζ) =  e^(-kζ) (P+ + kζ N+)     ζ > 0 (the source above the point)
//! G(ζ) = -e^(+kζ) (P- + kζ N-)     ζ < 0 (the source below it),
//! ```
//!
//! (`G(0+) - G(0-) = P+ + P- = I`). A cell `[z_a, z_b]` of thickness `h` with a uniform source
//! `f` gives, at a distance `d` below its lower face, `e^(-kd)(I + kd N+) (P+ e0 + N+ e1) f`,
//! and at `d` above its upper face `-e^(-kd)(I - kd N-) (P- e0 - N- e1) f`, with
//! `e0 = 1 - e^(-x)`, `e1 = 1 - e^(-x)(1 + x)`, `x = kh` (the integrals of `e^(-ks)` and
//! `ks e^(-ks)` over the cell, times `k`). Since `N±² = 0`, the propagators
//! `e^(-kd)(I ± kd N∓)` compose additively in `d`, so one sweep downwards and one upwards
//! accumulate the cells above and below each centre: `O(n)` per wave. Each cell's own
//! contribution at its centre is that of its two halves.
//!
//! The half-space adds the homogeneous solution `e^(-kz)(I + kz N+) c` (decaying, `c` in the
//! range of `P+`) that cancels the traction of the full-space field at `z = 0`:
//! `c = -K Z_full(0)` with `K = D (T D)⁻¹ T`, `D` a basis of the range of `P+` and `T` the rows
//! of the tractions (Boussinesq's and Cerruti's problems for one wave).
//!
//! ## The mean (k = 0)
//! A layer uniform in x and y: the traction-free surface and equilibrium leave
//! `σ_zz = σ_xz = σ_yz = 0` at every depth, the lateral strains vanish, so
//! `ε_zz = σ*_zz / (λ + 2μ)`, `σ_xx = λ ε_zz - σ*_xx`, `σ_yy = λ ε_zz - σ*_yy`,
//! `σ_xy = -σ*_xy`, and the surface moves by `u_z(0) = -∫ ε_zz dz`,
//! `u_x(0) = -∫ 2 ε*_xz dz`, `u_y(0) = -∫ 2 ε*_yz dz` (the displacement vanishing deep down).
//!
//! ## Reference
//! L. Frérot, M. Bonnet, J.-F. Molinari, G. Anciaux, A Fourier-accelerated volume integral
//! method for elastoplastic contact, *Comput. Methods Appl. Mech. Engrg.* 351 (2019) 951–976
//! (the residual stress of a volume of eigenstrain per wave of a partial Fourier transform
//! in x and y, integrated along z; here derived in the first-order form above, cells uniform
//! in z, with the accumulation along z in `O(n)`).

use rustfft::num_complex::Complex;

/// A complex number of double precision.
pub type C64 = Complex<f64>;

/// The components of a symmetric tensor, in the order of
/// [`crate::solution::dcfft::COMPONENTS`]: xx, yy, zz, yz, xz, xy (tensor shears, not
/// engineering ones).
pub const XX: usize = 0;
pub const YY: usize = 1;
pub const ZZ: usize = 2;
pub const YZ: usize = 3;
pub const XZ: usize = 4;
pub const XY: usize = 5;

type Mat4 = [[f64; 4]; 4];
type Vec4 = [C64; 4];
type Vec2 = [C64; 2];

const ZERO: C64 = C64 { re: 0.0, im: 0.0 };

fn mat_mul(a: &Mat4, b: &Mat4) -> Mat4 {
    let mut out = [[0.0; 4]; 4];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, value) in row.iter_mut().enumerate() {
            *value = (0..4).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    out
}

fn mat_add(a: &Mat4, b: &Mat4, factor: f64) -> Mat4 {
    let mut out = *a;
    for (row, other) in out.iter_mut().zip(b) {
        for (value, o) in row.iter_mut().zip(other) {
            *value += factor * o;
        }
    }
    out
}

fn identity() -> Mat4 {
    let mut out = [[0.0; 4]; 4];
    for (i, row) in out.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    out
}

fn scaled(a: &Mat4, factor: f64) -> Mat4 {
    a.map(|row| row.map(|v| v * factor))
}

/// `m v` (the tests' check of the projectors and the surface correction).
#[cfg(test)]
fn apply(m: &Mat4, v: &Vec4) -> Vec4 {
    let mut out = [ZERO; 4];
    for (o, row) in out.iter_mut().zip(m) {
        *o = v[0] * row[0] + v[1] * row[1] + v[2] * row[2] + v[3] * row[3];
    }
    out
}

/// `1 - e^(-x)(1 + x)` from `e^(-x)`, by its series where it would cancel.
#[inline]
fn first_moment(x: f64, decay: f64) -> f64 {
    if x < 0.05 {
        // Σ_(n>=2) (-1)^n (n - 1) x^n / n!, to x^8 (the next term is below 1e-16 x² here).
        let mut term = x * x / 2.0;
        let mut sum = term;
        for n in 3..=8 {
            term *= -x / n as f64;
            sum += term * (n - 1) as f64;
        }
        sum
    } else {
        1.0 - decay * (1.0 + x)
    }
}

/// `1 - e^(-x)` from `e^(-x)` (by `expm1` where it would cancel).
#[inline]
fn zeroth_moment(x: f64, decay: f64) -> f64 {
    if x < 0.05 {
        -(-x).exp_m1()
    } else {
        1.0 - decay
    }
}

/// The cells along depth: faces `0 = z_0 < z_1 < ... < z_n` (m); cell `j` spans
/// `[z_j, z_(j+1)]` and is sampled at its centre.
#[derive(Clone, Debug, PartialEq)]
pub struct DepthCells {
    faces_m: Vec<f64>,
}

/// Why a set of depth cells cannot be used.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("depth cells need faces 0 = z0 < z1 < ... (finite), got {0}")]
pub struct DepthCellsError(pub String);

impl DepthCells {
    /// Cells between the given faces (the first must be 0, increasing, finite).
    pub fn new(faces_m: Vec<f64>) -> Result<Self, DepthCellsError> {
        let ordered = faces_m.windows(2).all(|w| w[1] > w[0]);
        if faces_m.len() < 2
            || faces_m[0] != 0.0
            || !ordered
            || !faces_m.iter().all(|z| z.is_finite())
        {
            return Err(DepthCellsError(format!("{faces_m:?}")));
        }
        Ok(Self { faces_m })
    }

    /// `count` cells of `thickness_m` each.
    pub fn uniform(count: usize, thickness_m: f64) -> Result<Self, DepthCellsError> {
        Self::new((0..=count).map(|j| j as f64 * thickness_m).collect())
    }

    /// `uniform` cells of `thickness_m` from the surface, then cells growing by the ratio
    /// `growth` each down to at least `depth_m` (a graded grid).
    pub fn graded(
        uniform: usize,
        thickness_m: f64,
        growth: f64,
        depth_m: f64,
    ) -> Result<Self, DepthCellsError> {
        let mut faces: Vec<f64> = (0..=uniform).map(|j| j as f64 * thickness_m).collect();
        let mut h = thickness_m;
        while faces.last().copied().unwrap_or(0.0) < depth_m && faces.len() < 100_000 {
            h *= growth.max(1.0);
            let last = faces.last().copied().unwrap_or(0.0);
            faces.push(last + h);
        }
        Self::new(faces)
    }

    pub fn count(&self) -> usize {
        self.faces_m.len() - 1
    }

    pub fn faces_m(&self) -> &[f64] {
        &self.faces_m
    }

    /// The depth of the centre of cell `j`, m.
    pub fn centre_m(&self, j: usize) -> f64 {
        0.5 * (self.faces_m[j] + self.faces_m[j + 1])
    }

    /// The thickness of cell `j`, m.
    pub fn thickness_m(&self, j: usize) -> f64 {
        self.faces_m[j + 1] - self.faces_m[j]
    }

    /// The depth of the bottom face, m.
    pub fn depth_m(&self) -> f64 {
        self.faces_m[self.faces_m.len() - 1]
    }

    pub fn centres_m(&self) -> Vec<f64> {
        (0..self.count()).map(|j| self.centre_m(j)).collect()
    }
}

/// The elastic half-space's constants of the one-wave problem (they depend on ν alone; the
/// stresses scale with the shear modulus).
#[derive(Clone, Debug)]
pub struct Column {
    shear_modulus_pa: f64,
    /// `λ/μ`.
    l: f64,
    /// `(λ + 2μ)/μ`.
    m: f64,
    p_plus: Mat4,
    /// The projector of the decaying waves (`1 - P+`): the sweeps use its rows per cell; the
    /// tests check it against `P+`.
    #[cfg_attr(not(test), allow(dead_code))]
    p_minus: Mat4,
    /// `N+ = A+ P+`, kept as its rank-one factors below; the tests check the product.
    #[cfg_attr(not(test), allow(dead_code))]
    n_plus: Mat4,
    /// `K = D (T D)⁻¹ T`: the surface correction `c = -K Z(0)`.
    correction: Mat4,
    /// `N± = v± ℓ±ᵀ` (each of rank one: one Jordan block of size two).
    v_plus: [f64; 4],
    l_plus: [f64; 4],
    v_minus: [f64; 4],
    l_minus: [f64; 4],
}

/// What a cell of a column contributes, in the frame of the wave.
#[derive(Clone, Debug)]
struct CellTerms {
    /// `P+ f`, `P- f`, `ℓ+·f`, `ℓ-·f` of the plane-strain source `f`.
    p_plus: Vec4,
    p_minus: Vec4,
    n_plus: C64,
    n_minus: C64,
    /// The anti-plane source.
    antiplane: Vec2,
    /// `σ*_ss, σ*_tt, σ*_zz, σ̃*_st` in units of μ.
    eigenstress: [C64; 4],
    /// `k h / 2` and `e^(-k h / 2)`.
    half_x: f64,
    half_decay: f64,
    /// The moments of the cell and of its half.
    e0: f64,
    e1: f64,
    e0_half: f64,
    e1_half: f64,
}

/// The working memory of [`Column::apply`] for one column of cells (one per thread).
#[derive(Clone, Debug, Default)]
pub struct ColumnWork {
    cells: Vec<CellTerms>,
    down: Vec<(Vec4, Vec2)>,
    state: Vec<(Vec4, Vec2)>,
}

/// The eigenstress `C : ε*` in units of μ, from tensor components (order [`XX`]...).
#[inline]
fn eigenstress_over_mu(strain: &[C64; 6], l: f64) -> [C64; 6] {
    let trace = (strain[XX] + strain[YY] + strain[ZZ]) * l;
    [
        trace + strain[XX] * 2.0,
        trace + strain[YY] * 2.0,
        trace + strain[ZZ] * 2.0,
        strain[YZ] * 2.0,
        strain[XZ] * 2.0,
        strain[XY] * 2.0,
    ]
}

impl Column {
    /// The constants of a half-space of shear modulus `shear_modulus_pa` and Poisson's ratio
    /// `poisson` (in (-1, 0.5): the incompressible limit has no finite `λ`).
    pub fn new(shear_modulus_pa: f64, poisson: f64) -> Self {
        let nu = poisson;
        let l = 2.0 * nu / (1.0 - 2.0 * nu);
        let m = 2.0 * (1.0 - nu) / (1.0 - 2.0 * nu);
        let a_hat: Mat4 = [
            [0.0, -1.0, 1.0, 0.0],
            [l / m, 0.0, 0.0, 1.0 / m],
            [4.0 * (l + 1.0) / m, 0.0, 0.0, -l / m],
            [0.0, 0.0, 1.0, 0.0],
        ];
        let id = identity();
        let a_minus = mat_add(&a_hat, &id, -1.0);
        let a_plus = mat_add(&a_hat, &id, 1.0);
        // P+ = (Â + 2I)(Â - I)² / 4, P- = (2I - Â)(Â + I)² / 4.
        let p_plus = scaled(
            &mat_mul(&mat_add(&a_hat, &id, 2.0), &mat_mul(&a_minus, &a_minus)),
            0.25,
        );
        let p_minus = scaled(
            &mat_mul(
                &mat_add(&scaled(&id, 2.0), &a_hat, -1.0),
                &mat_mul(&a_plus, &a_plus),
            ),
            0.25,
        );
        let n_plus = mat_mul(&a_plus, &p_plus);
        let n_minus = mat_mul(&a_minus, &p_minus);
        let correction = surface_correction(&p_plus);
        let (v_plus, l_plus) = rank_one(&n_plus);
        let (v_minus, l_minus) = rank_one(&n_minus);
        Self {
            v_plus,
            l_plus,
            v_minus,
            l_minus,
            shear_modulus_pa,
            l,
            m,
            p_plus,
            p_minus,
            n_plus,
            correction,
        }
    }

    pub fn shear_modulus_pa(&self) -> f64 {
        self.shear_modulus_pa
    }

    /// The residual stress (Pa) at the centres of `cells` and the surface displacement (m,
    /// `[u_x, u_y, u_z]`, `u_z` into the body) of the eigenstrain wave `strain[j]` of each
    /// cell (tensor components, order [`XX`]...) with wavevector `k` (rad/m; `[0, 0]` is the
    /// mean of a layer).
    ///
    /// # Panics
    /// If `strain` and `stress` do not have one entry per cell.
    pub fn apply(
        &self,
        k: [f64; 2],
        cells: &DepthCells,
        strain: &[[C64; 6]],
        stress: &mut [[C64; 6]],
        surface: &mut [C64; 3],
        work: &mut ColumnWork,
    ) {
        assert_eq!(stress.len(), cells.count(), "one stress per cell");
        self.solve(k, cells, strain, Some(stress), surface, work);
    }

    /// As [`Column::apply`], the surface displacement alone (the sweep upwards only).
    pub fn surface(
        &self,
        k: [f64; 2],
        cells: &DepthCells,
        strain: &[[C64; 6]],
        surface: &mut [C64; 3],
        work: &mut ColumnWork,
    ) {
        self.solve(k, cells, strain, None, surface, work);
    }

    fn solve(
        &self,
        k: [f64; 2],
        cells: &DepthCells,
        strain: &[[C64; 6]],
        stress: Option<&mut [[C64; 6]]>,
        surface: &mut [C64; 3],
        work: &mut ColumnWork,
    ) {
        let count = cells.count();
        assert_eq!(strain.len(), count, "one strain per cell");
        let magnitude = k[0].hypot(k[1]);
        if magnitude == 0.0 {
            self.mean(cells, strain, stress, surface);
            return;
        }
        let with_stress = stress.is_some();
        let (l, m) = (self.l, self.m);
        let mu = self.shear_modulus_pa;
        let n = [k[0] / magnitude, k[1] / magnitude];
        let (nx, ny) = (n[0], n[1]);
        let i = C64::new(0.0, 1.0);
        let minus_i = C64::new(0.0, -1.0);
        let (v_plus, l_plus) = (&self.v_plus, &self.l_plus);
        let (v_minus, l_minus) = (&self.v_minus, &self.l_minus);

        // The sources of each cell, in the frame of the wave, and their projections.
        work.cells.clear();
        for (j, cell_strain) in strain.iter().enumerate() {
            let s = eigenstress_over_mu(cell_strain, l);
            let ss = s[XX] * (nx * nx) + s[XY] * (2.0 * nx * ny) + s[YY] * (ny * ny);
            let tt = s[XX] * (ny * ny) - s[XY] * (2.0 * nx * ny) + s[YY] * (nx * nx);
            let st = (s[YY] - s[XX]) * (nx * ny) + s[XY] * (nx * nx - ny * ny);
            let sz = s[XZ] * nx + s[YZ] * ny;
            let tz = s[YZ] * nx - s[XZ] * ny;
            let zz = s[ZZ];
            // The real-phase forms of the odd components: σ*_sz = i σ̃*_sz, σ*_st = i σ̃*_st.
            let sz_tilde = sz * minus_i;
            let st_tilde = st * minus_i;
            let f = [sz_tilde, zz / m, ss - zz * (l / m)];
            // P+ f (the source has no fourth component), P- f = f - P+ f, N± f = v± (ℓ±·f).
            let mut p_plus = [ZERO; 4];
            for (r, row) in self.p_plus.iter().enumerate() {
                p_plus[r] = f[0] * row[0] + f[1] * row[1] + f[2] * row[2];
            }
            let p_minus = [
                f[0] - p_plus[0],
                f[1] - p_plus[1],
                f[2] - p_plus[2],
                -p_plus[3],
            ];
            let n_plus = f[0] * l_plus[0] + f[1] * l_plus[1] + f[2] * l_plus[2];
            let n_minus = f[0] * l_minus[0] + f[1] * l_minus[1] + f[2] * l_minus[2];
            let x = magnitude * cells.thickness_m(j);
            let half_decay = (-0.5 * x).exp();
            let full = half_decay * half_decay;
            work.cells.push(CellTerms {
                p_plus,
                p_minus,
                n_plus,
                n_minus,
                antiplane: [tz, -st_tilde],
                eigenstress: [ss, tt, zz, st_tilde],
                half_x: 0.5 * x,
                half_decay,
                e0: zeroth_moment(x, full),
                e1: first_moment(x, full),
                e0_half: zeroth_moment(0.5 * x, half_decay),
                e1_half: first_moment(0.5 * x, half_decay),
            });
        }

        // Down: the cells above each centre. `acc` is the field at the lower face of the
        // last cell added.
        work.down.clear();
        let mut acc = [ZERO; 4];
        let mut acc_a = [ZERO; 2];
        for (j, cell) in work.cells.iter().enumerate().filter(|_| with_stress) {
            let (half, decay) = (cell.half_x, cell.half_decay);
            if j > 0 {
                // From the lower face of cell j - 1 (the upper face of j) to the centre of j.
                down_by(&mut acc, v_plus, l_plus, half, decay);
                acc_a = [acc_a[0] * decay, acc_a[1] * decay];
            }
            work.down.push((acc, acc_a));
            // Then on to the lower face of j, adding cell j: (P+ e0 + N+ e1) f.
            down_by(&mut acc, v_plus, l_plus, half, decay);
            acc_a = [acc_a[0] * decay, acc_a[1] * decay];
            let nf = cell.n_plus * cell.e1;
            for r in 0..4 {
                acc[r] += cell.p_plus[r] * cell.e0 + nf * v_plus[r];
            }
            // Anti-plane: P+ = [[1, -1], [-1, 1]] / 2, no nilpotent part.
            let fa = &cell.antiplane;
            let half_diff = (fa[0] - fa[1]) * (0.5 * cell.e0);
            acc_a[0] += half_diff;
            acc_a[1] -= half_diff;
        }

        // Up: the cells below each centre, then the whole column at the surface.
        if with_stress {
            work.state.clear();
            work.state.resize(count, ([ZERO; 4], [ZERO; 2]));
        }
        let mut acc = [ZERO; 4];
        let mut acc_a = [ZERO; 2];
        for (j, cell) in work.cells.iter().enumerate().rev() {
            let (half, decay) = (cell.half_x, cell.half_decay);
            // `acc` is the field at the lower face of j from the cells below it: at the centre,
            up_by(&mut acc, v_minus, l_minus, half, decay);
            acc_a = [acc_a[0] * decay, acc_a[1] * decay];
            if with_stress {
                // plus the cells above and the cell's own halves,
                // (P+ - P-) f e0h + (N+ + N-) f e1h.
                let (down, down_a) = &work.down[j];
                let (a, b) = (cell.n_plus * cell.e1_half, cell.n_minus * cell.e1_half);
                let mut state = [ZERO; 4];
                for r in 0..4 {
                    state[r] = down[r]
                        + acc[r]
                        + (cell.p_plus[r] - cell.p_minus[r]) * cell.e0_half
                        + a * v_plus[r]
                        + b * v_minus[r];
                }
                // Anti-plane own: (P+ - P-) fa e0h = [[0, -1], [-1, 0]] fa e0h.
                let fa = &cell.antiplane;
                let state_a = [
                    down_a[0] + acc_a[0] - fa[1] * cell.e0_half,
                    down_a[1] + acc_a[1] - fa[0] * cell.e0_half,
                ];
                work.state[j] = (state, state_a);
            }
            // On to the upper face of j, adding cell j: -(P- e0 - N- e1) f.
            up_by(&mut acc, v_minus, l_minus, half, decay);
            acc_a = [acc_a[0] * decay, acc_a[1] * decay];
            let nf = cell.n_minus * cell.e1;
            for r in 0..4 {
                acc[r] += -cell.p_minus[r] * cell.e0 + nf * v_minus[r];
            }
            // Anti-plane: P- = [[1, 1], [1, 1]] / 2.
            let fa = &cell.antiplane;
            let half_sum = (fa[0] + fa[1]) * (0.5 * cell.e0);
            acc_a[0] -= half_sum;
            acc_a[1] -= half_sum;
        }
        // The full space's field at the surface is `acc`; the half-space cancels its
        // tractions with a decaying solution c = -K acc (K has columns 2 and 3 only).
        let mut c = [ZERO; 4];
        for (r, row) in self.correction.iter().enumerate() {
            c[r] = -(acc[2] * row[2] + acc[3] * row[3]);
        }
        let lc = c[0] * l_plus[0] + c[1] * l_plus[1] + c[2] * l_plus[2] + c[3] * l_plus[3];
        // Anti-plane: c = (Zt, -Zt).
        let c_a = [acc_a[1], -acc_a[1]];
        let surface_state = [acc[0] + c[0], acc[1] + c[1]];
        let surface_a = acc_a[0] + c_a[0];
        let u_s = surface_state[0] * i / magnitude;
        let u_t = surface_a / magnitude;
        surface[0] = u_s * nx - u_t * ny;
        surface[1] = u_s * ny + u_t * nx;
        surface[2] = surface_state[1] / magnitude;
        let Some(stress) = stress else { return };

        let mut decay_to_top = 1.0;
        for ((j, cell), out) in work.cells.iter().enumerate().zip(stress.iter_mut()) {
            let decay = cell.half_decay;
            let at_centre = decay_to_top * decay;
            decay_to_top = at_centre * decay;
            let kz = magnitude * cells.centre_m(j);
            let (mut state, state_a) = work.state[j];
            let nc = lc * kz;
            for r in 0..4 {
                state[r] += (c[r] + nc * v_plus[r]) * at_centre;
            }
            let state_a = [
                state_a[0] + c_a[0] * at_centre,
                state_a[1] + c_a[1] * at_centre,
            ];
            let [ss_star, tt_star, zz_star, st_star] = cell.eigenstress;
            let dw = (state[0] * l + state[3] + zz_star) / m;
            let ss = dw * l - state[0] * m - ss_star;
            let tt = (dw - state[0]) * l - tt_star;
            let zz = state[3];
            let sz = state[2] * i;
            let tz = state_a[1];
            let st = (state_a[0] - st_star) * i;
            out[XX] = (ss * (nx * nx) + tt * (ny * ny) - st * (2.0 * nx * ny)) * mu;
            out[YY] = (ss * (ny * ny) + tt * (nx * nx) + st * (2.0 * nx * ny)) * mu;
            out[ZZ] = zz * mu;
            out[YZ] = (sz * ny + tz * nx) * mu;
            out[XZ] = (sz * nx - tz * ny) * mu;
            out[XY] = ((ss - tt) * (nx * ny) + st * (nx * nx - ny * ny)) * mu;
        }
    }

    /// The mean of each layer (`k = 0`): the module doc's uniform layers.
    fn mean(
        &self,
        cells: &DepthCells,
        strain: &[[C64; 6]],
        mut stress: Option<&mut [[C64; 6]]>,
        surface: &mut [C64; 3],
    ) {
        let (l, m, mu) = (self.l, self.m, self.shear_modulus_pa);
        *surface = [ZERO; 3];
        for (j, cell_strain) in strain.iter().enumerate() {
            let s = eigenstress_over_mu(cell_strain, l);
            let ezz = s[ZZ] / m;
            let h = cells.thickness_m(j);
            surface[0] -= cell_strain[XZ] * (2.0 * h);
            surface[1] -= cell_strain[YZ] * (2.0 * h);
            surface[2] -= ezz * h;
            let Some(stress) = stress.as_deref_mut() else {
                continue;
            };
            stress[j] = [
                (ezz * l - s[XX]) * mu,
                (ezz * l - s[YY]) * mu,
                ZERO,
                ZERO,
                ZERO,
                -s[XY] * mu,
            ];
        }
    }
}

/// `v <- e^(-kd)(I + kd N+) v` with `kd = x`, `e^(-kd) = decay`, `N+ = v+ ℓ+ᵀ`.
#[inline(always)]
fn down_by(v: &mut Vec4, v_plus: &[f64; 4], l_plus: &[f64; 4], x: f64, decay: f64) {
    let dot = (v[0] * l_plus[0] + v[1] * l_plus[1] + v[2] * l_plus[2] + v[3] * l_plus[3]) * x;
    for r in 0..4 {
        v[r] = (v[r] + dot * v_plus[r]) * decay;
    }
}

/// `v <- e^(-kd)(I - kd N-) v`, `N- = v- ℓ-ᵀ`.
#[inline(always)]
fn up_by(v: &mut Vec4, v_minus: &[f64; 4], l_minus: &[f64; 4], x: f64, decay: f64) {
    let dot = (v[0] * l_minus[0] + v[1] * l_minus[1] + v[2] * l_minus[2] + v[3] * l_minus[3]) * x;
    for r in 0..4 {
        v[r] = (v[r] - dot * v_minus[r]) * decay;
    }
}

/// `N = v ℓᵀ` of a matrix of rank one.
fn rank_one(n: &Mat4) -> ([f64; 4], [f64; 4]) {
    let mut best = (0.0, 0, 0);
    for (r, row) in n.iter().enumerate() {
        for (c, value) in row.iter().enumerate() {
            if value.abs() > best.0 {
                best = (value.abs(), r, c);
            }
        }
    }
    let (_, r0, c0) = best;
    let l = n[r0];
    let v = std::array::from_fn(|r| n[r][c0] / n[r0][c0]);
    (v, l)
}

/// `K = D (T D)⁻¹ T` for the range of `p_plus` (module doc): the two columns of `P+` whose
/// tractions (rows 2 and 3) are best conditioned make `D`.
fn surface_correction(p_plus: &Mat4) -> Mat4 {
    let column = |c: usize| [p_plus[0][c], p_plus[1][c], p_plus[2][c], p_plus[3][c]];
    let mut best = (0.0, 0, 1);
    for a in 0..4 {
        for b in a + 1..4 {
            let (ca, cb) = (column(a), column(b));
            let det = ca[2] * cb[3] - ca[3] * cb[2];
            let scale = (ca[2].hypot(ca[3]) * cb[2].hypot(cb[3])).max(f64::MIN_POSITIVE);
            if (det / scale).abs() > best.0 {
                best = ((det / scale).abs(), a, b);
            }
        }
    }
    let (ca, cb) = (column(best.1), column(best.2));
    // (T D)⁻¹ for T D = [[ca2, cb2], [ca3, cb3]].
    let det = ca[2] * cb[3] - ca[3] * cb[2];
    let inverse = [[cb[3] / det, -cb[2] / det], [-ca[3] / det, ca[2] / det]];
    let mut k = [[0.0; 4]; 4];
    for (r, row) in k.iter_mut().enumerate() {
        // D (T D)⁻¹: row r = [ca[r], cb[r]] times the inverse; then T picks columns 2 and 3.
        let d0 = ca[r] * inverse[0][0] + cb[r] * inverse[1][0];
        let d1 = ca[r] * inverse[0][1] + cb[r] * inverse[1][1];
        row[2] = d0;
        row[3] = d1;
    }
    k
}

#[cfg(test)]
mod tests;

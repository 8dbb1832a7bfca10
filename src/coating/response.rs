//! The response of a layered half-space to one surface-traction wave: a layer `0 <= z <= h`
//! (modulus `E1`, Poisson `ν1`) perfectly bonded to a half-space `z >= h` (`E2`, `ν2`).
//!
//! ## The plane problem (pressure and the shear along the wave)
//! A wave `(p, q_s) e^(iks)` (`s` along the wave vector, `k > 0`) is a plane-strain problem in
//! the plane of `s` and `z`. With the Airy function `φ = k⁻² f(ζ) e^(iks)`, `ζ = kz`
//! (`σss = ∂²φ/∂z²`, `σzz = ∂²φ/∂s²`, `σsz = -∂²φ/∂s∂z`):
//!
//! ```text
//! σzz = -f,   σss = f'',   σsz = -i f',   σtt = ν (σss + σzz)
//! u_s = -(i / 2Gk) [(1 - ν) f'' + ν f],   u_z = (1 / 2Gk) [(1 - ν) f''' + (ν - 2) f']
//! ```
//!
//! (plane-strain Hooke's law, `u_s` from `ε_ss`, `u_z` from `2ε_sz = σsz / G`; derived here).
//! The biharmonic `f` is, in the layer and in the substrate (`η = ζ - kh`),
//!
//! ```text
//! f1 = (A + B ζ) e^(-ζ) + (C + D η) e^(η),      f2 = (A2 + B2 η) e^(-η)
//! ```
//!
//! the growing terms written from the interface so that nothing overflows however thick the
//! layer (the form of O'Sullivan & King 1988; Chen & Engel 1972 use the same six constants).
//! The surface conditions `σzz = -p`, `σsz = -q_s` give `f1(0) = p`, `f1'(0) = -i q_s`; the
//! interface continues `σzz`, `σsz` (so `f`, `f'`) and `u_s`, `u_z`:
//! `[(1 - ν) f'' + ν f] / G` and `[(1 - ν) f''' + (ν - 2) f'] / G`. The six real constants
//! depend on `k` only through `K = kh`; for `p = 1, q_s = 0` they give `F_p`, for
//! `f1(0) = 0, f1'(0) = 1` they give `F_q`, and `f = p F_p - i q_s F_q`.
//!
//! ## The anti-plane problem (the shear across the wave)
//! `q_t e^(iks)` (`t` across the wave) moves the body along `t` only:
//! `u_t = (q_t / G1 k) U(ζ) e^(iks)`, `U = a e^(-ζ) + c e^(η)` in the layer and
//! `U = b e^(-η)` below, with `σtz = G ∂u_t/∂z`, `σst = G ∂u_t/∂s`: `σtz(0) = -q_t`, and `u_t`,
//! `σtz` continuous at the interface.
//!
//! On equal materials `C = D = 0`, `F_p = (1 + ζ) e^(-ζ)`, `F_q = ζ e^(-ζ)`, `U = e^(-ζ)`: the
//! homogeneous half-space's waves (Johnson 1985, §2.8; [`crate::solution::dcfft::spectral`]),
//! and the surface compliance `u_z / p = 2 (1 - ν²) / (E k)`.
//!
//! ## References
//! - M. J. O'Sullivan, R. B. King, Sliding contact stress field due to a spherical indenter on
//!   a layered elastic half-space, *ASME J. Tribol.* 110 (1988) 235–240.
//! - W. T. Chen, P. A. Engel, Impact and contact stress analysis in multilayer media, *Int. J.
//!   Solids Struct.* 8 (1972) 1257–1281.
//! - K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §2.8.

use crate::contact::material::Material;

/// The constants of one wave's plane and anti-plane problems (module doc), for `K = kh`.
#[derive(Clone, Debug, PartialEq)]
pub struct WaveResponse {
    /// `kh`.
    pub k_h: f64,
    /// `[A, B, C, D, A2, B2]` of `F_p` (unit pressure).
    pub pressure: [f64; 6],
    /// `[A, B, C, D, A2, B2]` of `F_q` (`f(0) = 0`, `f'(0) = 1`).
    pub shear: [f64; 6],
    /// `[a, c, b]` of the anti-plane `U`.
    pub antiplane: [f64; 3],
    /// A stack's interlayers (empty for one coating), top first: `[A, B, C, D]` of `F_p`, the
    /// same of `F_q`, and `[a, c]` of `U`, each in the layer's own coordinates
    /// ([`Layered::stack_wave`]); `pressure`, `shear` and `antiplane` then hold the top
    /// layer's and the substrate's.
    pub interlayers: Vec<[f64; 10]>,
}

/// Which side of the interface a point at `z = h` belongs to (the in-plane stresses jump
/// there).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    Coating,
    Substrate,
}

/// `f, f', f'', f'''` of one basis function of the layer or the substrate.
type Derivatives = [f64; 4];

/// The layer's four basis functions at `ζ` (`η = ζ - K`): `[A, B, C, D]`.
fn layer_basis(zeta: f64, k_h: f64) -> [Derivatives; 4] {
    let decay = (-zeta).exp();
    let eta = zeta - k_h;
    let grow = eta.exp();
    [
        [decay, -decay, decay, -decay],
        [
            zeta * decay,
            (1.0 - zeta) * decay,
            (zeta - 2.0) * decay,
            (3.0 - zeta) * decay,
        ],
        [grow, grow, grow, grow],
        [
            eta * grow,
            (1.0 + eta) * grow,
            (2.0 + eta) * grow,
            (3.0 + eta) * grow,
        ],
    ]
}

/// The substrate's two basis functions at `η = ζ - K >= 0`: `[A2, B2]`.
fn substrate_basis(eta: f64) -> [Derivatives; 2] {
    let decay = (-eta).exp();
    [
        [decay, -decay, decay, -decay],
        [
            eta * decay,
            (1.0 - eta) * decay,
            (eta - 2.0) * decay,
            (3.0 - eta) * decay,
        ],
    ]
}

/// Solves `matrix x = rhs` (each column of `rhs` one right-hand side) by Gaussian elimination
/// with partial pivoting.
fn solve_linear<const N: usize, const M: usize>(
    mut matrix: [[f64; N]; N],
    mut rhs: [[f64; M]; N],
) -> [[f64; M]; N] {
    for column in 0..N {
        let pivot = (column..N)
            .max_by(|&a, &b| matrix[a][column].abs().total_cmp(&matrix[b][column].abs()))
            .unwrap_or(column);
        matrix.swap(column, pivot);
        rhs.swap(column, pivot);
        let (pivot_row, pivot_rhs) = (matrix[column], rhs[column]);
        for row in column + 1..N {
            let factor = matrix[row][column] / pivot_row[column];
            if factor != 0.0 {
                for (target, source) in matrix[row][column..].iter_mut().zip(&pivot_row[column..]) {
                    *target -= factor * source;
                }
                for (target, source) in rhs[row].iter_mut().zip(&pivot_rhs) {
                    *target -= factor * source;
                }
            }
        }
    }
    let mut x = [[0.0; M]; N];
    for row in (0..N).rev() {
        for k in 0..M {
            let mut sum = rhs[row][k];
            for j in row + 1..N {
                sum -= matrix[row][j] * x[j][k];
            }
            x[row][k] = sum / matrix[row][row];
        }
    }
    x
}

/// Solves `matrix x = rhs` (two right-hand sides) by Gaussian elimination with partial
/// pivoting, for the stack's system of any size.
fn solve_dense(mut matrix: Vec<Vec<f64>>, mut rhs: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    let n = matrix.len();
    for column in 0..n {
        let pivot = (column..n)
            .max_by(|&a, &b| matrix[a][column].abs().total_cmp(&matrix[b][column].abs()))
            .unwrap_or(column);
        matrix.swap(column, pivot);
        rhs.swap(column, pivot);
        let (pivot_row, pivot_rhs) = (matrix[column].clone(), rhs[column]);
        for row in column + 1..n {
            let factor = matrix[row][column] / pivot_row[column];
            if factor != 0.0 {
                for (target, source) in matrix[row][column..].iter_mut().zip(&pivot_row[column..]) {
                    *target -= factor * source;
                }
                for (target, source) in rhs[row].iter_mut().zip(&pivot_rhs) {
                    *target -= factor * source;
                }
            }
        }
    }
    let mut x = vec![[0.0; 2]; n];
    for row in (0..n).rev() {
        for k in 0..2 {
            let mut sum = rhs[row][k];
            for j in row + 1..n {
                sum -= matrix[row][j] * x[j][k];
            }
            x[row][k] = sum / matrix[row][row];
        }
    }
    x
}

/// A layer bonded to a substrate: the materials and the layer's thickness; `under`, the
/// layers between it and the substrate (top first; none for a single coating).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layered {
    /// The top layer's material.
    pub coating: Material,
    pub substrate: Material,
    /// The top layer's thickness (the scale of `K = kh`).
    pub thickness_m: f64,
    /// The layers under the top one, top first.
    pub under: Interlayers,
}

/// One layer of a stack: its material and thickness.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layer {
    pub material: Material,
    pub thickness_m: f64,
}

/// The most layers a stack holds (the top one and its interlayers).
pub const MAX_LAYERS: usize = 6;

/// The layers between the top one and the substrate, top first (at most
/// [`MAX_LAYERS`]` - 1`), held inline so that [`Layered`] stays `Copy`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interlayers {
    layers: [Layer; MAX_LAYERS - 1],
    count: usize,
}

impl Interlayers {
    /// No interlayer: a single coating.
    pub const NONE: Interlayers = Interlayers {
        layers: [Layer {
            material: Material {
                modulus_pa: 0.0,
                poisson: 0.0,
            },
            thickness_m: 0.0,
        }; MAX_LAYERS - 1],
        count: 0,
    };

    /// The given layers, top first; `None` when there are more than [`MAX_LAYERS`]` - 1`.
    pub fn of(layers: &[Layer]) -> Option<Interlayers> {
        (layers.len() < MAX_LAYERS).then(|| {
            let mut out = Self::NONE;
            out.layers[..layers.len()].copy_from_slice(layers);
            out.count = layers.len();
            out
        })
    }

    pub fn as_slice(&self) -> &[Layer] {
        &self.layers[..self.count]
    }

    pub fn is_empty(&self) -> bool {
        self.count == 0
    }
}

fn shear_modulus(material: &Material) -> f64 {
    material.modulus_pa / (2.0 * (1.0 + material.poisson))
}

/// `E / (1 - ν²)`, the plane-strain modulus.
pub fn plane_strain_modulus(material: &Material) -> f64 {
    material.modulus_pa / (1.0 - material.poisson * material.poisson)
}

impl Layered {
    /// The constants of the wave `K = kh` (module doc); a stack's by [`Self::stack_wave`].
    pub fn wave(&self, k_h: f64) -> WaveResponse {
        if !self.under.is_empty() {
            return self.stack_wave(k_h);
        }
        let (nu1, nu2) = (self.coating.poisson, self.substrate.poisson);
        // Interface displacement rows multiplied by G1: the substrate's terms by G1 / G2.
        let ratio = shear_modulus(&self.coating) / shear_modulus(&self.substrate);
        let surface = layer_basis(0.0, k_h);
        let top = layer_basis(k_h, k_h);
        let below = substrate_basis(0.0);
        let u_s = |d: &Derivatives, nu: f64| (1.0 - nu) * d[2] + nu * d[0];
        let u_z = |d: &Derivatives, nu: f64| (1.0 - nu) * d[3] + (nu - 2.0) * d[1];
        let mut matrix = [[0.0; 6]; 6];
        for j in 0..4 {
            matrix[0][j] = surface[j][0];
            matrix[1][j] = surface[j][1];
            matrix[2][j] = top[j][0];
            matrix[3][j] = top[j][1];
            matrix[4][j] = u_s(&top[j], nu1);
            matrix[5][j] = u_z(&top[j], nu1);
        }
        for j in 0..2 {
            matrix[2][4 + j] = -below[j][0];
            matrix[3][4 + j] = -below[j][1];
            matrix[4][4 + j] = -ratio * u_s(&below[j], nu2);
            matrix[5][4 + j] = -ratio * u_z(&below[j], nu2);
        }
        let mut rhs = [[0.0; 2]; 6];
        rhs[0][0] = 1.0;
        rhs[1][1] = 1.0;
        let x = solve_linear(matrix, rhs);
        let decay = (-k_h).exp();
        // Anti-plane: surface -a + c e^(-K) = -1; interface a e^(-K) + c - b = 0 and
        // -a e^(-K) + c + (G2/G1) b = 0.
        let anti = solve_linear(
            [
                [-1.0, decay, 0.0],
                [decay, 1.0, -1.0],
                [-decay, 1.0, 1.0 / ratio],
            ],
            [[-1.0], [0.0], [0.0]],
        );
        WaveResponse {
            k_h,
            pressure: std::array::from_fn(|i| x[i][0]),
            shear: std::array::from_fn(|i| x[i][1]),
            antiplane: [anti[0][0], anti[1][0], anti[2][0]],
            interlayers: Vec::new(),
        }
    }

    /// Every layer, top first: the top one and the interlayers.
    pub fn layers(&self) -> Vec<Layer> {
        let mut out = vec![Layer {
            material: self.coating,
            thickness_m: self.thickness_m,
        }];
        out.extend_from_slice(self.under.as_slice());
        out
    }

    /// The depths of the interfaces under each layer, m (the last: the stack's, over the
    /// substrate).
    pub fn interface_depths_m(&self) -> Vec<f64> {
        self.layers()
            .iter()
            .scan(0.0, |depth, layer| {
                *depth += layer.thickness_m;
                Some(*depth)
            })
            .collect()
    }

    /// The stack's thickness, m.
    pub fn total_thickness_m(&self) -> f64 {
        self.thickness_m
            + self
                .under
                .as_slice()
                .iter()
                .map(|l| l.thickness_m)
                .sum::<f64>()
    }

    /// The constants of the wave `K = kh` of a stack of `n` layers on the substrate, by the
    /// global matrix of the layers' constants: in each layer `f = (A + B ζ') e^(-ζ')
    /// + (C + D η') e^(η')`, `ζ'` measured from the layer's top and `η'` from its bottom
    /// (`ζ' - K_i`), so that every exponential is at most 1 however thick the layers; the two
    /// surface conditions and four continuity conditions (`f`, `f'`, `u_s`, `u_z`) at each of
    /// the `n` interfaces fix the `4n + 2` constants. This is the stable form of the transfer
    /// (propagator) matrix method of the layered half-space (Burmister 1945; Chen & Engel 1972
    /// for the multilayer, with the same per-layer Airy functions): the product of
    /// the layers' transfer matrices overflows as `e^(kh)`, the global matrix with the growing
    /// terms referred to each layer's bottom does not. The anti-plane `U = a e^(-ζ') + c e^(η')`
    /// takes `2n + 1` constants the same way. With one layer it is [`Self::wave`]'s system.
    ///
    /// ## References
    /// - D. M. Burmister, The general theory of stresses and displacements in layered systems
    ///   I, *J. Appl. Phys.* 16 (1945) 89–94.
    /// - W. T. Chen, P. A. Engel, Impact and contact stress analysis in multilayer media,
    ///   *Int. J. Solids Struct.* 8 (1972) 1257–1281.
    pub fn stack_wave(&self, k_h: f64) -> WaveResponse {
        let layers = self.layers();
        let n = layers.len();
        let g1 = shear_modulus(&self.coating);
        let big_k: Vec<f64> = layers
            .iter()
            .map(|l| k_h * (l.thickness_m / self.thickness_m))
            .collect();
        let u_s = |d: &Derivatives, nu: f64| (1.0 - nu) * d[2] + nu * d[0];
        let u_z = |d: &Derivatives, nu: f64| (1.0 - nu) * d[3] + (nu - 2.0) * d[1];
        let size = 4 * n + 2;
        let mut matrix = vec![vec![0.0; size]; size];
        let surface = layer_basis(0.0, big_k[0]);
        for j in 0..4 {
            matrix[0][j] = surface[j][0];
            matrix[1][j] = surface[j][1];
        }
        for i in 0..n {
            let row = 2 + 4 * i;
            let (nu, ratio) = (
                layers[i].material.poisson,
                g1 / shear_modulus(&layers[i].material),
            );
            let top = layer_basis(big_k[i], big_k[i]);
            for (j, basis) in top.iter().enumerate() {
                let column = 4 * i + j;
                matrix[row][column] = basis[0];
                matrix[row + 1][column] = basis[1];
                matrix[row + 2][column] = ratio * u_s(basis, nu);
                matrix[row + 3][column] = ratio * u_z(basis, nu);
            }
            let below: Vec<Derivatives> = if i + 1 < n {
                layer_basis(0.0, big_k[i + 1]).to_vec()
            } else {
                substrate_basis(0.0).to_vec()
            };
            let below_material = if i + 1 < n {
                &layers[i + 1].material
            } else {
                &self.substrate
            };
            let (nu_b, ratio_b) = (below_material.poisson, g1 / shear_modulus(below_material));
            for (j, basis) in below.iter().enumerate() {
                let column = 4 * (i + 1) + j;
                matrix[row][column] = -basis[0];
                matrix[row + 1][column] = -basis[1];
                matrix[row + 2][column] = -ratio_b * u_s(basis, nu_b);
                matrix[row + 3][column] = -ratio_b * u_z(basis, nu_b);
            }
        }
        let mut rhs = vec![[0.0; 2]; size];
        rhs[0][0] = 1.0;
        rhs[1][1] = 1.0;
        let x = solve_dense(matrix, rhs);
        // Anti-plane: surface -a0 + c0 e^(-K0) = -1; at interface i, U and (G/G1) U'
        // continuous.
        let anti_size = 2 * n + 1;
        let mut anti = vec![vec![0.0; anti_size]; anti_size];
        let mut anti_rhs = vec![[0.0; 2]; anti_size];
        anti[0][0] = -1.0;
        anti[0][1] = (-big_k[0]).exp();
        anti_rhs[0][0] = -1.0;
        for i in 0..n {
            let (row, decay) = (1 + 2 * i, (-big_k[i]).exp());
            let ratio = shear_modulus(&layers[i].material) / g1;
            anti[row][2 * i] = decay;
            anti[row][2 * i + 1] = 1.0;
            anti[row + 1][2 * i] = -ratio * decay;
            anti[row + 1][2 * i + 1] = ratio;
            if i + 1 < n {
                let below_decay = (-big_k[i + 1]).exp();
                let ratio_b = shear_modulus(&layers[i + 1].material) / g1;
                anti[row][2 * i + 2] = -1.0;
                anti[row][2 * i + 3] = -below_decay;
                anti[row + 1][2 * i + 2] = ratio_b;
                anti[row + 1][2 * i + 3] = -ratio_b * below_decay;
            } else {
                let ratio_b = shear_modulus(&self.substrate) / g1;
                anti[row][2 * n] = -1.0;
                anti[row + 1][2 * n] = ratio_b;
            }
        }
        let a = solve_dense(anti, anti_rhs);
        let plane = |load: usize| -> [f64; 6] {
            [
                x[0][load],
                x[1][load],
                x[2][load],
                x[3][load],
                x[4 * n][load],
                x[4 * n + 1][load],
            ]
        };
        WaveResponse {
            k_h,
            pressure: plane(0),
            shear: plane(1),
            antiplane: [a[0][0], a[1][0], a[2 * n][0]],
            interlayers: (1..n)
                .map(|i| {
                    let mut c = [0.0; 10];
                    for j in 0..4 {
                        c[j] = x[4 * i + j][0];
                        c[4 + j] = x[4 * i + j][1];
                    }
                    c[8] = a[2 * i][0];
                    c[9] = a[2 * i + 1][0];
                    c
                })
                .collect(),
        }
    }

    /// `k u_z(0) / p`, Pa⁻¹: the normal surface compliance of the wave `K = kh` times `k`
    /// (`2 / E1'` for a thick layer, `2 / E2'` for a thin one, `E' = E / (1 - ν²)`).
    pub fn normal_compliance_times_k(&self, k_h: f64) -> f64 {
        let wave = self.wave(k_h);
        let surface = layer_basis(0.0, k_h);
        let f3: f64 = (0..4).map(|j| wave.pressure[j] * surface[j][3]).sum();
        let f1: f64 = (0..4).map(|j| wave.pressure[j] * surface[j][1]).sum();
        let nu = self.coating.poisson;
        ((1.0 - nu) * f3 + (nu - 2.0) * f1) / (2.0 * shear_modulus(&self.coating))
    }

    /// The material at depth `z` on `side` of an interface.
    pub fn material_at(&self, z_m: f64, side: Side) -> Material {
        if self.under.is_empty() {
            return if z_m < self.thickness_m || (z_m == self.thickness_m && side == Side::Coating) {
                self.coating
            } else {
                self.substrate
            };
        }
        let layers = self.layers();
        match layer_index(&self.interface_depths_m(), z_m, side) {
            Some(i) => layers[i].material,
            None => self.substrate,
        }
    }

    /// The layer (0 the top) a depth on `side` of an interface lies in; `None` in the
    /// substrate.
    pub fn layer_at(&self, z_m: f64, side: Side) -> Option<usize> {
        layer_index(&self.interface_depths_m(), z_m, side)
    }
}

/// Which layer of the stack whose interfaces lie at `interfaces` (increasing) holds the depth
/// `z` on `side`: a depth within 1e-12 (relative) of an interface is on it, and `side` says
/// which of its neighbours it belongs to (`Coating`: the one above). `None` in the substrate.
fn layer_index(interfaces: &[f64], z: f64, side: Side) -> Option<usize> {
    interfaces.iter().position(|&depth| {
        let on = (z - depth).abs() <= 1e-12 * depth;
        z < depth && !on || on && side == Side::Coating
    })
}

/// One wave's fields at one depth, per unit traction: the plane problem's `f` and its
/// derivatives for unit pressure and unit shear, the anti-plane `U` and `U'`, and the
/// material's `ν` and `G / G1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaveAtDepth {
    /// `f, f', f'', f'''` of `F_p`.
    pub pressure: Derivatives,
    /// The same of `F_q`.
    pub shear: Derivatives,
    /// `U` and `U'` of the anti-plane problem.
    pub antiplane: [f64; 2],
    pub poisson: f64,
    /// The local shear modulus over the coating's.
    pub shear_ratio: f64,
}

impl WaveResponse {
    /// The fields at `ζ = kz` on `side` (module doc).
    pub fn at(&self, zeta: f64, side: Side, layered: &Layered) -> WaveAtDepth {
        if !self.interlayers.is_empty() {
            return self.stack_at(zeta, side, layered);
        }
        let in_coating = zeta < self.k_h || (zeta == self.k_h && side == Side::Coating);
        let combine = |coefficients: &[f64; 6]| -> Derivatives {
            let mut out = [0.0; 4];
            if in_coating {
                for (j, basis) in layer_basis(zeta, self.k_h).iter().enumerate() {
                    for (o, b) in out.iter_mut().zip(basis) {
                        *o += coefficients[j] * b;
                    }
                }
            } else {
                for (j, basis) in substrate_basis(zeta - self.k_h).iter().enumerate() {
                    for (o, b) in out.iter_mut().zip(basis) {
                        *o += coefficients[4 + j] * b;
                    }
                }
            }
            out
        };
        let [a, c, b] = self.antiplane;
        let g1 = shear_modulus(&layered.coating);
        let (antiplane, material) = if in_coating {
            let (d, g) = ((-zeta).exp(), (zeta - self.k_h).exp());
            ([a * d + c * g, -a * d + c * g], &layered.coating)
        } else {
            let d = (-(zeta - self.k_h)).exp();
            ([b * d, -b * d], &layered.substrate)
        };
        WaveAtDepth {
            pressure: combine(&self.pressure),
            shear: combine(&self.shear),
            antiplane,
            poisson: material.poisson,
            shear_ratio: shear_modulus(material) / g1,
        }
    }
}

impl WaveResponse {
    /// [`Self::at`] in a stack of several layers.
    fn stack_at(&self, zeta: f64, side: Side, layered: &Layered) -> WaveAtDepth {
        let scale = self.k_h / layered.thickness_m;
        let interfaces: Vec<f64> = layered
            .interface_depths_m()
            .iter()
            .map(|d| d * scale)
            .collect();
        let layers = layered.layers();
        let g1 = shear_modulus(&layered.coating);
        let index = layer_index(&interfaces, zeta, side);
        let mut pressure = [0.0; 4];
        let mut shear = [0.0; 4];
        let (antiplane, material) = match index {
            Some(i) => {
                let top = if i == 0 { 0.0 } else { interfaces[i - 1] };
                let thickness = interfaces[i] - top;
                let local = (zeta - top).clamp(0.0, thickness);
                let (cp, cq, a, c) = if i == 0 {
                    let p = &self.pressure;
                    let q = &self.shear;
                    (
                        [p[0], p[1], p[2], p[3]],
                        [q[0], q[1], q[2], q[3]],
                        self.antiplane[0],
                        self.antiplane[1],
                    )
                } else {
                    let k = &self.interlayers[i - 1];
                    (
                        [k[0], k[1], k[2], k[3]],
                        [k[4], k[5], k[6], k[7]],
                        k[8],
                        k[9],
                    )
                };
                for (j, basis) in layer_basis(local, thickness).iter().enumerate() {
                    for d in 0..4 {
                        pressure[d] += cp[j] * basis[d];
                        shear[d] += cq[j] * basis[d];
                    }
                }
                let (d, g) = ((-local).exp(), (local - thickness).exp());
                ([a * d + c * g, -a * d + c * g], layers[i].material)
            }
            None => {
                let eta = (zeta - interfaces[interfaces.len() - 1]).max(0.0);
                for (j, basis) in substrate_basis(eta).iter().enumerate() {
                    for d in 0..4 {
                        pressure[d] += self.pressure[4 + j] * basis[d];
                        shear[d] += self.shear[4 + j] * basis[d];
                    }
                }
                let d = (-eta).exp();
                let b = self.antiplane[2];
                ([b * d, -b * d], layered.substrate)
            }
        };
        WaveAtDepth {
            pressure,
            shear,
            antiplane,
            poisson: material.poisson,
            shear_ratio: shear_modulus(&material) / g1,
        }
    }
}

/// The stress spectra of one wave: for each component `[xx, yy, zz, yz, xz, xy]` the complex
/// factors `(re, im)` that multiply the transforms of `p`, `qx` and `qy`.
pub type WaveStress = [[[f64; 2]; 3]; 6];

impl WaveAtDepth {
    /// The stress of the wave along the unit vector `n = (nx, ny)` (module doc) as factors of
    /// the tractions' transforms `p̂`, `q̂x`, `q̂y`, rotated from `(n, t, z)` to `(x, y, z)`.
    pub fn stress(&self, n: [f64; 2]) -> WaveStress {
        let [nx, ny] = n;
        let (fp, fq) = (self.pressure, self.shear);
        // Complex (re, im) factors of p and q_s: f = p F_p - i q_s F_q.
        // σss = f'', σzz = -f, σsz = -i f', σtt = ν (σss + σzz).
        let ss = [[fp[2], 0.0], [0.0, -fq[2]]];
        let zz = [[-fp[0], 0.0], [0.0, fq[0]]];
        let sz = [[0.0, -fp[1]], [-fq[1], 0.0]];
        let nu = self.poisson;
        let tt = [
            [nu * (ss[0][0] + zz[0][0]), 0.0],
            [0.0, nu * (ss[1][1] + zz[1][1])],
        ];
        // Anti-plane, per unit q_t: σtz = G/G1 U', σst = i G/G1 U.
        let tz = [self.shear_ratio * self.antiplane[1], 0.0];
        let st = [0.0, self.shear_ratio * self.antiplane[0]];
        // q_s = nx qx + ny qy, q_t = -ny qx + nx qy.
        let mut out = [[[0.0; 2]; 3]; 6];
        // Plane parts: load 0 is p; q_s contributes to loads 1 and 2 with weights nx, ny.
        let plane = |component: [[f64; 2]; 2], out: &mut [[f64; 2]; 3], weight: f64| {
            for part in 0..2 {
                out[0][part] += weight * component[0][part];
                out[1][part] += weight * nx * component[1][part];
                out[2][part] += weight * ny * component[1][part];
            }
        };
        let anti = |component: [f64; 2], out: &mut [[f64; 2]; 3], weight: f64| {
            for part in 0..2 {
                out[1][part] += weight * -ny * component[part];
                out[2][part] += weight * nx * component[part];
            }
        };
        // xx = nx² ss + ny² tt - 2 nx ny st
        plane(ss, &mut out[0], nx * nx);
        plane(tt, &mut out[0], ny * ny);
        anti(st, &mut out[0], -2.0 * nx * ny);
        // yy = ny² ss + nx² tt + 2 nx ny st
        plane(ss, &mut out[1], ny * ny);
        plane(tt, &mut out[1], nx * nx);
        anti(st, &mut out[1], 2.0 * nx * ny);
        // zz
        plane(zz, &mut out[2], 1.0);
        // yz = ny sz + nx tz
        plane(sz, &mut out[3], ny);
        anti(tz, &mut out[3], nx);
        // xz = nx sz - ny tz
        plane(sz, &mut out[4], nx);
        anti(tz, &mut out[4], -ny);
        // xy = nx ny (ss - tt) + (nx² - ny²) st
        plane(ss, &mut out[5], nx * ny);
        plane(tt, &mut out[5], -nx * ny);
        anti(st, &mut out[5], nx * nx - ny * ny);
        out
    }

    /// `[2G1 k u_s / (-i), 2G1 k u_z]` per unit pressure and per unit `q_s` (`[load][component]`;
    /// the shear's `u_s` real and `u_z` imaginary after the `-i`), for the interface tests.
    pub fn plane_displacements(&self) -> [[f64; 2]; 2] {
        let nu = self.poisson;
        let scale = 1.0 / self.shear_ratio;
        let of = |d: &Derivatives| {
            [
                scale * ((1.0 - nu) * d[2] + nu * d[0]),
                scale * ((1.0 - nu) * d[3] + (nu - 2.0) * d[1]),
            ]
        };
        [of(&self.pressure), of(&self.shear)]
    }
}

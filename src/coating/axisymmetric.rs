//! An independent reference for the stresses in a coated body: an axisymmetric pressure on the
//! layered half-space, solved with Love's strain function in Hankel space. It shares nothing
//! with the plane waves of [`super::response`] and [`super::stress`] (no Airy function, no
//! wave constants, no grid, no transform), so it checks them: the tests here hold it to
//! Boussinesq's point load and Huber's Hertz field (equal moduli), to both thickness limits and
//! to the interface conditions; `super::tests` holds the coated study's maxima to it.
//!
//! ## The method (derived here)
//! Love's strain function `φ(r, z)` (Timoshenko & Goodier 1970, §139; `z` into the body):
//!
//! ```text
//! 2G u_r = -∂²φ/∂r∂z,                  2G u_z = 2(1 - ν) ∇²φ - ∂²φ/∂z²
//! σ_r = ∂/∂z (ν ∇²φ - ∂²φ/∂r²),        σ_θ = ∂/∂z (ν ∇²φ - (1/r) ∂φ/∂r)
//! σ_z = ∂/∂z ((2 - ν) ∇²φ - ∂²φ/∂z²),  τ_rz = ∂/∂r ((1 - ν) ∇²φ - ∂²φ/∂z²)
//! ```
//!
//! with `∇⁴φ = 0`. With `φ = ∫₀^∞ P̃(k) k⁻² ψ(kz) J0(kr) dk` (`P̃` the pressure's Hankel
//! transform, `p(r) = ∫₀^∞ P̃(k) J0(kr) k dk`) and `ζ = kz`, `(d²/dζ² - 1)² ψ = 0` and
//!
//! ```text
//! σ_z        = ∫ P̃ k [(1 - ν) ψ''' - (2 - ν) ψ'] J0(kr) dk
//! τ_rz       = ∫ P̃ k [ν ψ'' + (1 - ν) ψ] J1(kr) dk
//! σ_r + σ_θ  = ∫ P̃ k [2ν ψ''' + (1 - 2ν) ψ'] J0(kr) dk
//! σ_r - σ_θ  = ∫ P̃ k ψ' [J0(kr) - 2 J1(kr)/(kr)] dk = -∫ P̃ k ψ' J2(kr) dk
//! 2G u_r     = ∫ P̃ ψ' J1(kr) dk,     2G u_z = ∫ P̃ [(1 - 2ν) ψ'' - 2(1 - ν) ψ] J0(kr) dk
//! ```
//!
//! (from `∂J0(kr)/∂r = -k J1`, `∂²J0(kr)/∂r² = -k² J0 + k J1 / r`). In the coating
//! `ψ = (A + Bζ) e^(-ζ) + (C + Dη) e^(η)`, in the substrate `ψ = (E + Fη) e^(-η)`,
//! `η = ζ - kh` (the growing terms written from the interface, so that nothing overflows).
//! The surface is loaded, `(1 - ν1) ψ''' - (2 - ν1) ψ' = -1` and `ν1 ψ'' + (1 - ν1) ψ = 0` at
//! `ζ = 0`, and the interface continues the brackets of `σ_z`, `τ_rz`, `u_r`, `u_z` (the last
//! two divided by each material's `G`): six equations for six constants at each `k`. On one
//! material `A = -2ν`, `B = -1`, `C = D = 0` and the formulas give Boussinesq's field (for
//! `P̃ = P / 2π`) and the surface compliance `2(1 - ν²)/E`.
//!
//! The pressure is that of [`super::reference`], `p(r) = Σ c_n (1 - r²/a²)^(n - 1/2)`, whose
//! terms transform in closed form (Sonine's integral, Sneddon 1951):
//! `P̃_n(k) = a² 2^(n-1/2) Γ(n + 1/2) √(2/π) j_n(ka) / (ka)^n`.
//!
//! ## Quadrature
//! In `x = ka` over panels of unit width, 8 Gauss–Legendre points each, to `x = 3000`, and at
//! depth `z` only as far as `kz = 40` (beyond, every term is below `e^(-40)` of its size). In
//! the coating the Hertz term's field on a half-space of the coating, `c_1` times Huber's
//! closed form ([`crate::solution::sphere_hertz::stress_over_p0`] without friction), is added
//! in closed form and subtracted from the integrand, which then falls as `e^(-k(2h - z))` from
//! the layer's far side: otherwise the integrals on the surface near the contact's edge, where
//! `p` has a square-root edge, would converge only as `(ka)^(-1/2)` (0.02 `p0` at `ka` =
//! 3000). The higher terms vanish at the edge as `(1 - r²/a²)^(3/2)` or faster and are
//! integrated there to `ka = 300` (their tail at most 2e-4 of their size, `c_n` being a tenth
//! of `c_1` or less).
//!
//! ## References
//! - S. Timoshenko, J. N. Goodier, *Theory of Elasticity*, 3rd ed., McGraw-Hill (1970), §139
//!   (Love's strain function).
//! - I. N. Sneddon, *Fourier Transforms*, McGraw-Hill (1951) (Hankel transforms, Sonine's
//!   integral).
//! - K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §3.2 (Boussinesq's
//!   point load, eq. 3.21, the check), §3.4 (Huber's field of the Hertz pressure).

use std::f64::consts::PI;

use super::reference::{gamma_half, spherical_over_power, AxisymmetricContact};
use super::response::{Layered, Side};
use crate::contact::material::Material;
use crate::stress::Stress;

/// `ψ, ψ', ψ'', ψ'''` of one basis function.
type Derivatives = [f64; 4];

/// The coating's four basis functions at `ζ` (`η = ζ - K`): `[A, B, C, D]` (module doc).
fn coating_basis(zeta: f64, k_h: f64) -> [Derivatives; 4] {
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

/// The substrate's two basis functions at `η >= 0`: `[E, F]`.
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

fn shear_modulus(material: &Material) -> f64 {
    material.modulus_pa / (2.0 * (1.0 + material.poisson))
}

/// The brackets of the module doc for one `ψ`: `[σ_z, τ_rz, 2G u_r, 2G u_z]` (the last two
/// divided by `2G` by the caller).
fn brackets(d: &Derivatives, nu: f64) -> [f64; 4] {
    [
        (1.0 - nu) * d[3] - (2.0 - nu) * d[1],
        nu * d[2] + (1.0 - nu) * d[0],
        d[1],
        (1.0 - 2.0 * nu) * d[2] - 2.0 * (1.0 - nu) * d[0],
    ]
}

/// The six constants `[A, B, C, D, E, F]` at `K = kh` (module doc).
fn constants(layered: &Layered, k_h: f64) -> [f64; 6] {
    let (nu1, nu2) = (layered.coating.poisson, layered.substrate.poisson);
    let (g1, g2) = (
        shear_modulus(&layered.coating),
        shear_modulus(&layered.substrate),
    );
    let surface = coating_basis(0.0, k_h);
    let above = coating_basis(k_h, k_h);
    let below = substrate_basis(0.0);
    let mut matrix = vec![vec![0.0; 6]; 6];
    for j in 0..4 {
        let s = brackets(&surface[j], nu1);
        let a = brackets(&above[j], nu1);
        matrix[0][j] = s[0];
        matrix[1][j] = s[1];
        matrix[2][j] = a[0];
        matrix[3][j] = a[1];
        matrix[4][j] = a[2] / g1;
        matrix[5][j] = a[3] / g1;
    }
    for j in 0..2 {
        let b = brackets(&below[j], nu2);
        matrix[2][4 + j] = -b[0];
        matrix[3][4 + j] = -b[1];
        matrix[4][4 + j] = -b[2] / g2;
        matrix[5][4 + j] = -b[3] / g2;
    }
    // Scale the displacement rows to order one.
    for row in &mut matrix[4..] {
        for v in row.iter_mut() {
            *v *= g1;
        }
    }
    let x = super::reference::solve_dense(matrix, vec![-1.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    std::array::from_fn(|i| x[i])
}

/// One quadrature node in `k`.
#[derive(Clone, Copy, Debug)]
struct Node {
    k: f64,
    /// The weight `dk` times `k P̃(k)` of the whole pressure, Pa per m.
    loaded: f64,
    /// The same of the first (Hertz) term alone, `c_1 P̃_1(k)`.
    hertz: f64,
    constants: [f64; 6],
}

/// The stresses of an axisymmetric pressure on a coated half-space (module doc).
#[derive(Clone, Debug)]
pub struct AxisymmetricStress {
    layered: Layered,
    radius_m: f64,
    /// `c_1`, Pa: the Hertz term subtracted in the coating.
    hertz_pa: f64,
    nodes: Vec<Node>,
}

/// The largest `ka` integrated.
const X_MAX: usize = 3000;

/// The largest `ka` at which the terms `n >= 2` are integrated in the coating (where the Hertz
/// term's homogeneous part is subtracted): they fall as `(ka)^(-n-1)`, so their tail beyond is
/// at most `300^(-3/2)` (2e-4) of their size, on the surface at the contact's edge.
const HIGHER_TERMS_X: f64 = 300.0;

impl AxisymmetricStress {
    /// The field of `contact`'s pressure on `layered`.
    pub fn new(layered: Layered, contact: &AxisymmetricContact) -> Self {
        Self::of_pressure(layered, contact.radius_m, &contact.coefficients_pa)
    }

    /// The field of `p(r) = Σ c_n (1 - r²/a²)^(n - 1/2)` (`coefficients_pa` the `c_n`) on
    /// `layered`.
    pub fn of_pressure(layered: Layered, radius_m: f64, coefficients_pa: &[f64]) -> Self {
        let a = radius_m;
        let terms = coefficients_pa.len();
        let transforms: Vec<f64> = (1..=terms)
            .map(|n| {
                let mu = n as f64 - 0.5;
                a * a * 2f64.powf(mu) * gamma_half(n) * (2.0 / PI).sqrt()
            })
            .collect();
        let (points, weights) = crate::thermal::special::gauss_legendre(8);
        let mut nodes = Vec::with_capacity(8 * X_MAX);
        for panel in 0..X_MAX {
            for (t, w) in points.iter().zip(&weights) {
                let x = panel as f64 + 0.5 + 0.5 * t;
                let k = x / a;
                let dk = 0.5 * w / a;
                let bessel = spherical_over_power(x, terms);
                let each: Vec<f64> = (0..terms)
                    .map(|n| coefficients_pa[n] * transforms[n] * bessel[n])
                    .collect();
                nodes.push(Node {
                    k,
                    loaded: dk * k * each.iter().sum::<f64>(),
                    hertz: dk * k * each[0],
                    constants: constants(&layered, k * layered.thickness_m),
                });
            }
        }
        Self {
            layered,
            radius_m,
            hertz_pa: coefficients_pa.first().copied().unwrap_or(0.0),
            nodes,
        }
    }

    /// The field of a point load `load_n` at the origin (`P̃ = P / 2π`), for the Boussinesq
    /// check: integrated to `ka = 3000` with `a = length_m`, so valid where `kz = 40` comes
    /// first (`z >= length_m / 75`).
    pub fn point_load(layered: Layered, load_n: f64, length_m: f64) -> Self {
        let (points, weights) = crate::thermal::special::gauss_legendre(8);
        let mut nodes = Vec::with_capacity(8 * X_MAX);
        for panel in 0..X_MAX {
            for (t, w) in points.iter().zip(&weights) {
                let x = panel as f64 + 0.5 + 0.5 * t;
                let k = x / length_m;
                let dk = 0.5 * w / length_m;
                nodes.push(Node {
                    k,
                    loaded: dk * k * load_n / (2.0 * PI),
                    hertz: 0.0,
                    constants: constants(&layered, k * layered.thickness_m),
                });
            }
        }
        Self {
            layered,
            radius_m: length_m,
            hertz_pa: 0.0,
            nodes,
        }
    }

    /// The layered body.
    pub fn layered(&self) -> &Layered {
        &self.layered
    }

    /// The stress at radius `r_m`, depth `z_m` in the plane `θ = 0` (`xx = σ_r`,
    /// `yy = σ_θ`, `xz = τ_rz`); at `z = h` that of `side`.
    pub fn stress(&self, r_m: f64, z_m: f64, side: Side) -> Stress {
        self.stresses(&[r_m], z_m, side)[0]
    }

    /// The stresses at the radii `r_m`, all at depth `z_m` (see [`Self::stress`]).
    pub fn stresses(&self, r_m: &[f64], z_m: f64, side: Side) -> Vec<Stress> {
        self.stresses_with(r_m, z_m, side, &|_, _, x| bessel_pair(x))
    }

    /// [`Self::stresses`] with `bessel(node, radius, x)` giving `(J0(x), J1(x)/x)` at
    /// `x = k_node r_radius` (computed, or from a table).
    fn stresses_with(
        &self,
        r_m: &[f64],
        z_m: f64,
        side: Side,
        bessel: &dyn Fn(usize, usize, f64) -> (f64, f64),
    ) -> Vec<Stress> {
        let h = self.layered.thickness_m;
        let in_coating = z_m < h || (z_m == h && side == Side::Coating);
        let material = if in_coating {
            self.layered.coating
        } else {
            self.layered.substrate
        };
        let nu = material.poisson;
        let nu1 = self.layered.coating.poisson;
        // The Hertz term on a half-space of the coating (A = -2ν1, B = -1), subtracted in the
        // coating and added back in closed form.
        let homogeneous = [-2.0 * nu1, -1.0];
        // [σz, τrz, σr + σθ, ψ'] per radius: the Bessel factors J0, J1, J0, (J0 - 2J1/kr).
        let mut sums = vec![[0.0; 4]; r_m.len()];
        let a = self.radius_m;
        let subtracted = in_coating && self.hertz_pa != 0.0;
        let reach = if subtracted {
            // The Hertz term less its homogeneous part falls as e^(-k(2h - z)); the higher
            // terms as e^(-kz) and (ka)^(-2) (module doc).
            (40.0 / z_m)
                .min(HIGHER_TERMS_X / a)
                .max(40.0 / (2.0 * h - z_m))
        } else {
            40.0 / z_m
        };
        for (index, node) in self.nodes.iter().enumerate() {
            if node.k > reach {
                break;
            }
            let zeta = node.k * z_m;
            let k_h = node.k * h;
            let c = &node.constants;
            let mut psi = [0.0; 4];
            if in_coating {
                for (j, basis) in coating_basis(zeta, k_h).iter().enumerate() {
                    for (p, b) in psi.iter_mut().zip(basis) {
                        *p += c[j] * b;
                    }
                }
            } else {
                for (j, basis) in substrate_basis(zeta - k_h).iter().enumerate() {
                    for (p, b) in psi.iter_mut().zip(basis) {
                        *p += c[4 + j] * b;
                    }
                }
            }
            let values = |d: &Derivatives| {
                [
                    (1.0 - nu) * d[3] - (2.0 - nu) * d[1],
                    nu * d[2] + (1.0 - nu) * d[0],
                    2.0 * nu * d[3] + (1.0 - 2.0 * nu) * d[1],
                    d[1],
                ]
            };
            let mut kernel = values(&psi).map(|v| v * node.loaded);
            if in_coating && node.hertz != 0.0 {
                let mut flat = [0.0; 4];
                for (j, basis) in coating_basis(zeta, k_h).iter().take(2).enumerate() {
                    for (p, b) in flat.iter_mut().zip(basis) {
                        *p += homogeneous[j] * b;
                    }
                }
                let subtract = values(&flat);
                for (v, s) in kernel.iter_mut().zip(subtract) {
                    *v -= s * node.hertz;
                }
            }
            for (radius, (sum, &r)) in sums.iter_mut().zip(r_m).enumerate() {
                let x = node.k * r;
                let (j0, j1_over_x) = bessel(index, radius, x);
                sum[0] += kernel[0] * j0;
                sum[1] += kernel[1] * j1_over_x * x;
                sum[2] += kernel[2] * j0;
                sum[3] += kernel[3] * (j0 - 2.0 * j1_over_x);
            }
        }
        r_m.iter()
            .zip(&sums)
            .map(|(&r, s)| {
                let (sum, difference) = (s[2], s[3]);
                let mut stress = Stress {
                    xx: 0.5 * (sum + difference),
                    yy: 0.5 * (sum - difference),
                    zz: s[0],
                    yz: 0.0,
                    xz: s[1],
                    xy: 0.0,
                };
                if in_coating && self.hertz_pa != 0.0 {
                    let a = self.radius_m;
                    let huber = crate::solution::sphere_hertz::stress_over_p0(
                        r / a,
                        0.0,
                        z_m / a,
                        0.0,
                        nu1,
                    )
                    .scaled(self.hertz_pa);
                    stress = Stress {
                        xx: stress.xx + huber.xx,
                        yy: stress.yy + huber.yy,
                        zz: stress.zz + huber.zz,
                        yz: 0.0,
                        xz: stress.xz + huber.xz,
                        xy: 0.0,
                    };
                }
                stress
            })
            .collect()
    }
}

/// `(J0(x), J1(x)/x)` ([`super::reference::bessel_j0`], [`super::line_reference::bessel_over_power`]).
fn bessel_pair(x: f64) -> (f64, f64) {
    (
        super::reference::bessel_j0(x),
        super::line_reference::bessel_over_power(x, 1)[0],
    )
}

/// A largest value of the reference field and its place in the plane `θ = 0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peak {
    pub value_pa: f64,
    pub r_m: f64,
    pub z_m: f64,
}

/// The maxima the coated study reports ([`crate::study::coated::CoatedMaxima`]), of the
/// reference field: von Mises in the coating and in the substrate, the interface's shear
/// `|τrz|` and most compressive `σz`, the surface's largest `σr`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReferenceMaxima {
    pub coating_von_mises: Peak,
    pub substrate_von_mises: Peak,
    pub interface_shear: Peak,
    /// The most compressive `σz` (its value negative).
    pub interface_normal_min: Peak,
    pub surface_tension: Peak,
}

/// The golden-section search for the largest `f` on `[lo, hi]`: `(x, f(x))` (Kiefer 1953).
fn golden_maximum(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> (f64, f64) {
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    let (mut x1, mut x2) = (hi - ratio * (hi - lo), lo + ratio * (hi - lo));
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..24 {
        if f1 >= f2 {
            hi = x2;
            (x2, f2) = (x1, f1);
            x1 = hi - ratio * (hi - lo);
            f1 = f(x1);
        } else {
            lo = x1;
            (x1, f1) = (x2, f2);
            x2 = lo + ratio * (hi - lo);
            f2 = f(x2);
        }
    }
    if f1 >= f2 {
        (x1, f1)
    } else {
        (x2, f2)
    }
}

impl AxisymmetricStress {
    /// The maxima (see [`ReferenceMaxima`]) within `r <= reach_m` and `z <= deepest_m`: the
    /// largest of each on a grid of 25 radii and 7 depths in the coating and 17 in the
    /// substrate, then refined by golden sections over a grid step about it, in `r` and (for
    /// the von Mises stresses) in `z` in turn, twice.
    pub fn maxima(&self, reach_m: f64, deepest_m: f64) -> ReferenceMaxima {
        let h = self.layered.thickness_m;
        let (radii_count, coating_count, substrate_count) = (24, 6, 16);
        let radii: Vec<f64> = (0..=radii_count)
            .map(|i| reach_m * i as f64 / radii_count as f64)
            .collect();
        let dr = reach_m / radii_count as f64;
        let coating: Vec<f64> = (0..=coating_count)
            .map(|i| h * i as f64 / coating_count as f64)
            .collect();
        let substrate: Vec<f64> = (0..=substrate_count)
            .map(|i| h + (deepest_m - h) * i as f64 / substrate_count as f64)
            .collect();
        // The grid's Bessel functions, once for every depth: up to the farthest node any depth
        // reaches (the surface's).
        let reach = (HIGHER_TERMS_X / self.radius_m).max(40.0 / h);
        let nodes = self.nodes.iter().take_while(|n| n.k <= reach).count();
        let table: Vec<Vec<(f64, f64)>> = self.nodes[..nodes]
            .iter()
            .map(|n| radii.iter().map(|r| bessel_pair(n.k * r)).collect())
            .collect();
        let lookup = |node: usize, radius: usize, x: f64| {
            table
                .get(node)
                .map_or_else(|| bessel_pair(x), |row| row[radius])
        };
        let grid = |depths: &[f64], side: Side| -> Vec<(f64, Vec<Stress>)> {
            depths
                .iter()
                .map(|&z| (z, self.stresses_with(&radii, z, side, &lookup)))
                .collect()
        };
        let (upper, lower) = (
            grid(&coating, Side::Coating),
            grid(&substrate, Side::Substrate),
        );
        // The grid's best (value, r, z) of `quantity` over the rows `rows`.
        let best = |rows: &[(f64, Vec<Stress>)], quantity: &dyn Fn(&Stress) -> f64| {
            let mut out = (f64::NEG_INFINITY, 0.0, 0.0);
            for (z, row) in rows {
                for (r, s) in radii.iter().zip(row) {
                    let v = quantity(s);
                    if v > out.0 {
                        out = (v, *r, *z);
                    }
                }
            }
            out
        };
        // Refine (r, z) over a step each way, z kept within `depth_range`.
        let refine = |start: (f64, f64, f64),
                      side: Side,
                      depth_range: Option<(f64, f64, f64)>,
                      quantity: &dyn Fn(&Stress) -> f64| {
            let (mut value, mut r, mut z) = start;
            for _ in 0..2 {
                let (r_new, v) = golden_maximum(
                    |x| quantity(&self.stress(x, z, side)),
                    (r - dr).max(0.0),
                    (r + dr).min(reach_m),
                );
                if v > value {
                    (value, r) = (v, r_new);
                }
                if let Some((lo, hi, dz)) = depth_range {
                    let (z_new, v) = golden_maximum(
                        |t| quantity(&self.stress(r, t, side)),
                        (z - dz).max(lo),
                        (z + dz).min(hi),
                    );
                    if v > value {
                        (value, z) = (v, z_new);
                    }
                }
            }
            Peak {
                value_pa: value,
                r_m: r,
                z_m: z,
            }
        };
        let von_mises = |s: &Stress| s.von_mises();
        let shear = |s: &Stress| s.xz.abs();
        let compression = |s: &Stress| -s.zz;
        let tension = |s: &Stress| s.xx;
        let interface = std::slice::from_ref(&upper[coating_count]);
        let surface = std::slice::from_ref(&upper[0]);
        let mut normal = refine(
            best(interface, &compression),
            Side::Coating,
            None,
            &compression,
        );
        normal.value_pa = -normal.value_pa;
        ReferenceMaxima {
            coating_von_mises: refine(
                best(&upper, &von_mises),
                Side::Coating,
                Some((0.0, h, h / coating_count as f64)),
                &von_mises,
            ),
            substrate_von_mises: refine(
                best(&lower, &von_mises),
                Side::Substrate,
                Some((h, deepest_m, (deepest_m - h) / substrate_count as f64)),
                &von_mises,
            ),
            interface_shear: refine(best(interface, &shear), Side::Coating, None, &shear),
            interface_normal_min: normal,
            surface_tension: refine(best(surface, &tension), Side::Coating, None, &tension),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const STEEL: Material = Material {
        modulus_pa: 210e9,
        poisson: 0.3,
    };

    fn layered(coating: Material, substrate: Material, thickness_m: f64) -> Layered {
        Layered {
            coating,
            substrate,
            thickness_m,
            under: crate::coating::Interlayers::NONE,
        }
    }

    /// Johnson eq. 3.21: Boussinesq's point load `P` at depth `z`, radius `r`.
    fn boussinesq(load: f64, r: f64, z: f64, nu: f64) -> Stress {
        let rho = r.hypot(z);
        let p = load / (2.0 * PI);
        let first = if r == 0.0 {
            0.5 / (z * z)
        } else {
            (1.0 - z / rho) / (r * r)
        };
        Stress {
            xx: p * ((1.0 - 2.0 * nu) * first - 3.0 * z * r * r / rho.powi(5)),
            yy: -p * (1.0 - 2.0 * nu) * (first - z / rho.powi(3)),
            zz: -3.0 * p * z.powi(3) / rho.powi(5),
            yz: 0.0,
            xz: -3.0 * p * r * z * z / rho.powi(5),
            xy: 0.0,
        }
    }

    fn largest_difference(a: &Stress, b: &Stress) -> f64 {
        [
            a.xx - b.xx,
            a.yy - b.yy,
            a.zz - b.zz,
            a.yz - b.yz,
            a.xz - b.xz,
            a.xy - b.xy,
        ]
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()))
    }

    #[test]
    fn one_material_gives_boussinesqs_point_load() {
        // Equal moduli, a point load of 1 N: the Love integrals against Johnson 3.21 at depths
        // 0.2 to 2 (length 1 m), both sides of the "interface" at 0.5.
        let body = layered(STEEL, STEEL, 0.5);
        let field = AxisymmetricStress::point_load(body, 1.0, 1.0);
        let mut worst: f64 = 0.0;
        for z in [0.2, 0.5, 0.9, 2.0] {
            let radii = [0.0, 0.1, 0.4, 1.0, 2.5];
            for side in [Side::Coating, Side::Substrate] {
                for (r, got) in radii.iter().zip(field.stresses(&radii, z, side)) {
                    let want = boussinesq(1.0, *r, z, 0.3);
                    let scale = 1.0 / (2.0 * PI * (r * r + z * z));
                    worst = worst.max(largest_difference(&got, &want) / scale);
                }
            }
        }
        eprintln!(
            "measured: Love reference, one material, against Boussinesq: {worst:.1e} of P/(2π R²)"
        );
        assert!(worst < 1e-9, "{worst}");
    }

    /// The Love integrals alone (no Huber term added), for the checks of the method.
    fn without_closed_form(layered: Layered, a: f64, coefficients: &[f64]) -> AxisymmetricStress {
        let mut field = AxisymmetricStress::of_pressure(layered, a, coefficients);
        field.hertz_pa = 0.0;
        for node in &mut field.nodes {
            node.hertz = 0.0;
        }
        field
    }

    #[test]
    fn one_material_gives_hubers_hertz_field_and_the_thickness_limits_hold() {
        // The Hertz pressure (c = [p0]) by the Love integrals alone: on one material Huber's
        // field (Johnson §3.4); under a coating 1000 a thick the coating's; under one of a/10⁶
        // the substrate's (below it). Then the full reference (Huber term added in the coating)
        // on a B4C-like coating: σz, τrz continuous at the interface, σr jumps.
        let (a, p0) = (1e-4, 1e9);
        let hard = Material {
            modulus_pa: 450e9,
            poisson: 0.17,
        };
        let points = [(0.0, 0.2), (0.3, 0.48), (0.9, 0.3), (1.3, 1.0), (0.5, 2.0)];
        let mut worst = [0.0f64; 3];
        for (case, body) in [
            layered(STEEL, STEEL, 0.7 * a),
            layered(hard, STEEL, 1000.0 * a),
            layered(hard, STEEL, 1e-6 * a),
        ]
        .into_iter()
        .enumerate()
        {
            let field = without_closed_form(body, a, &[p0]);
            let nu = if case == 2 { 0.3 } else { body.coating.poisson };
            for &(r, z) in &points {
                let side = if case == 2 {
                    Side::Substrate
                } else {
                    Side::Coating
                };
                let got = field.stress(r * a, z * a, side);
                let want =
                    crate::solution::sphere_hertz::stress_over_p0(r, 0.0, z, 0.0, nu).scaled(p0);
                worst[case] = worst[case].max(largest_difference(&got, &want) / p0);
            }
        }
        eprintln!(
            "measured: Love reference, Hertz pressure: one material {:.1e} p0, h = 1000a against the coating's Huber {:.1e} p0, h = a/10⁶ against the substrate's {:.1e} p0",
            worst[0], worst[1], worst[2]
        );
        assert!(worst[0] < 1e-7, "{}", worst[0]);
        assert!(worst[1] < 1e-7, "{}", worst[1]);
        // The thin layer changes the substrate's field by O(h/a).
        assert!(worst[2] < 1e-5, "{}", worst[2]);
        // The interface of the full reference.
        let body = layered(hard, STEEL, 0.4 * a);
        let field = AxisymmetricStress::of_pressure(body, a, &[p0, 0.1 * p0]);
        let radii = [0.0, 0.4 * a, 0.9 * a, 1.5 * a];
        let above = field.stresses(&radii, 0.4 * a, Side::Coating);
        let below = field.stresses(&radii, 0.4 * a, Side::Substrate);
        let mut continuous: f64 = 0.0;
        let mut jump: f64 = 0.0;
        for (u, l) in above.iter().zip(&below) {
            continuous = continuous.max((u.zz - l.zz).abs()).max((u.xz - l.xz).abs());
            jump = jump.max((u.xx - l.xx).abs());
        }
        eprintln!(
            "measured: Love reference interface: σz, τrz continuous to {:.1e} p0, σr jumps by {:.2} p0",
            continuous / p0,
            jump / p0
        );
        assert!(continuous < 1e-7 * p0, "{continuous}");
        assert!(jump > 0.05 * p0, "{jump}");
    }

    #[test]
    fn the_surface_carries_the_pressure() {
        // σz = -p and τrz = 0 on the surface, inside and outside the contact, soft coating.
        let a = 1e-4;
        let soft = Material {
            modulus_pa: 105e9,
            poisson: 0.3,
        };
        let body = layered(soft, STEEL, 0.5 * a);
        let contact = AxisymmetricContact {
            radius_m: a,
            load_n: 0.0,
            approach_m: 0.0,
            coefficients_pa: vec![1e9, -1e8, 3e7],
            max_pressure_pa: 0.0,
            residual: 0.0,
        };
        let field = AxisymmetricStress::new(body, &contact);
        let radii: Vec<f64> = (0..12).map(|i| i as f64 * 0.13 * a).collect();
        let mut worst: f64 = 0.0;
        for (r, s) in radii.iter().zip(field.stresses(&radii, 0.0, Side::Coating)) {
            worst = worst
                .max((s.zz + contact.pressure_pa(*r)).abs())
                .max(s.xz.abs());
        }
        eprintln!(
            "measured: Love reference surface: σz = -p, τrz = 0 to {:.1e} p0",
            worst / 1e9
        );
        assert!(worst < 1e-5 * 1e9, "{worst}");
    }
}

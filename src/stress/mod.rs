//! The Cauchy stress tensor and the measures derived from it.
//!
//! Sign convention: tension positive, compression negative. Components are stored in whatever
//! unit the caller chose (pascals, or multiples of the peak pressure `p0` for normalised work);
//! every derived measure is linear or homogeneous of degree one, so the unit carries through.
//!
//! Uses nothing else of the crate.

mod quantity;

pub use quantity::{Quantity, QuantityKind};

/// A symmetric stress tensor, six independent components.
///
/// Axes: x along the surface (the sliding direction), y along the surface (the cylinder axis
/// for line contact), z into the body.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stress {
    pub xx: f64,
    pub yy: f64,
    pub zz: f64,
    pub yz: f64,
    pub xz: f64,
    pub xy: f64,
}

impl Stress {
    /// A plane-strain state from its in-plane components: `syy = nu (sxx + szz)`, and no
    /// out-of-plane shear (Johnson, *Contact Mechanics* (1985), §2.1).
    #[inline]
    pub fn plane_strain(xx: f64, zz: f64, xz: f64, nu: f64) -> Self {
        Self {
            xx,
            yy: nu * (xx + zz),
            zz,
            yz: 0.0,
            xz,
            xy: 0.0,
        }
    }

    /// Multiplies every component by `factor` (for example `p0` to go from `sigma/p0` to Pa).
    #[must_use]
    pub fn scaled(self, factor: f64) -> Self {
        Self {
            xx: self.xx * factor,
            yy: self.yy * factor,
            zz: self.zz * factor,
            yz: self.yz * factor,
            xz: self.xz * factor,
            xy: self.xy * factor,
        }
    }

    /// Whether every component is a finite number.
    pub fn is_finite(&self) -> bool {
        [self.xx, self.yy, self.zz, self.yz, self.xz, self.xy]
            .iter()
            .all(|v| v.is_finite())
    }

    /// The mean of several stresses (componentwise).
    #[must_use]
    pub fn mean(stresses: &[Stress]) -> Self {
        let sum = stresses.iter().fold(Stress::default(), |sum, s| sum + *s);
        sum.scaled(1.0 / stresses.len().max(1) as f64)
    }

    /// Hydrostatic (mean normal) stress `(sxx + syy + szz) / 3`.
    pub fn hydrostatic(&self) -> f64 {
        (self.xx + self.yy + self.zz) / 3.0
    }

    /// Von Mises equivalent stress
    /// `sqrt(((sxx-syy)^2 + (syy-szz)^2 + (szz-sxx)^2)/2 + 3 (syz^2 + sxz^2 + sxy^2))`.
    ///
    /// Computed from the components (no eigenvalues), so it is exact and cheap.
    pub fn von_mises(&self) -> f64 {
        let d_xy = self.xx - self.yy;
        let d_yz = self.yy - self.zz;
        let d_zx = self.zz - self.xx;
        let shear = self.yz * self.yz + self.xz * self.xz + self.xy * self.xy;
        (0.5 * (d_xy * d_xy + d_yz * d_yz + d_zx * d_zx) + 3.0 * shear).sqrt()
    }

    /// Principal shear stress in the xz plane, `sqrt(((sxx - szz)/2)^2 + sxz^2)`.
    ///
    /// This is Johnson's `tau_1` (Contact Mechanics, 1985, §4.2), the quantity of the classic
    /// line-contact contour figure; it ignores `syy`, unlike [`Stress::max_shear`].
    pub fn principal_shear_xz(&self) -> f64 {
        let half_diff = 0.5 * (self.xx - self.zz);
        (half_diff * half_diff + self.xz * self.xz).sqrt()
    }

    /// Maximum (Tresca) shear stress `(s1 - s3) / 2` over all planes.
    pub fn max_shear(&self) -> f64 {
        let [s1, _, s3] = self.principal();
        0.5 * (s1 - s3)
    }

    /// Principal stresses ordered `s1 >= s2 >= s3`.
    ///
    /// When the tensor is block diagonal in (x, z) | y, as in plane strain, the in-plane pair
    /// comes from the exact 2 x 2 formula; otherwise a cyclic Jacobi iteration is used, which is
    /// accurate to a few ulps of the largest component even for repeated eigenvalues.
    pub fn principal(&self) -> [f64; 3] {
        let mut values = if self.xy == 0.0 && self.yz == 0.0 {
            let centre = 0.5 * (self.xx + self.zz);
            let radius = self.principal_shear_xz();
            [centre + radius, self.yy, centre - radius]
        } else {
            self.jacobi_eigenvalues()
        };
        values.sort_by(|a, b| b.total_cmp(a));
        values
    }

    #[allow(clippy::needless_range_loop)] // rotations index rows and columns alike
    fn jacobi_eigenvalues(&self) -> [f64; 3] {
        let mut m = [
            [self.xx, self.xy, self.xz],
            [self.xy, self.yy, self.yz],
            [self.xz, self.yz, self.zz],
        ];
        // Cyclic Jacobi (Golub & Van Loan, *Matrix Computations*, the cyclic Jacobi method):
        // each rotation zeroes one off-diagonal entry; convergence is quadratic.
        for _sweep in 0..32 {
            let off = m[0][1].abs() + m[0][2].abs() + m[1][2].abs();
            let scale = m[0][0].abs() + m[1][1].abs() + m[2][2].abs() + off;
            if off <= f64::EPSILON * 1e-3 * scale || off == 0.0 {
                break;
            }
            for (p, q) in [(0usize, 1usize), (0, 2), (1, 2)] {
                if m[p][q] == 0.0 {
                    continue;
                }
                let theta = (m[q][q] - m[p][p]) / (2.0 * m[p][q]);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let t = if theta == 0.0 { 1.0 } else { t };
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                for k in 0..3 {
                    let mkp = m[k][p];
                    let mkq = m[k][q];
                    m[k][p] = c * mkp - s * mkq;
                    m[k][q] = s * mkp + c * mkq;
                }
                for k in 0..3 {
                    let mpk = m[p][k];
                    let mqk = m[q][k];
                    m[p][k] = c * mpk - s * mqk;
                    m[q][k] = s * mpk + c * mqk;
                }
            }
        }
        [m[0][0], m[1][1], m[2][2]]
    }
}

/// Component-wise sum, for superposing solutions.
impl std::ops::Add for Stress {
    type Output = Self;

    fn add(self, other: Self) -> Self {
        Self {
            xx: self.xx + other.xx,
            yy: self.yy + other.yy,
            zz: self.zz + other.zz,
            yz: self.yz + other.yz,
            xz: self.xz + other.xz,
            xy: self.xy + other.xy,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn general() -> Stress {
        Stress {
            xx: 3.0,
            yy: -1.0,
            zz: 2.0,
            yz: 0.5,
            xz: -1.5,
            xy: 0.75,
        }
    }

    #[test]
    fn principal_invariants_match_components() {
        let s = general();
        let [s1, s2, s3] = s.principal();
        assert!(s1 >= s2 && s2 >= s3);
        // I1, I2, I3 are invariant under rotation.
        let i1 = s.xx + s.yy + s.zz;
        let i2 = s.xx * s.yy + s.yy * s.zz + s.zz * s.xx - s.xy * s.xy - s.yz * s.yz - s.xz * s.xz;
        let i3 = s.xx * s.yy * s.zz + 2.0 * s.xy * s.yz * s.xz
            - s.xx * s.yz * s.yz
            - s.yy * s.xz * s.xz
            - s.zz * s.xy * s.xy;
        assert_relative_eq!(s1 + s2 + s3, i1, epsilon = 1e-12);
        assert_relative_eq!(s1 * s2 + s2 * s3 + s3 * s1, i2, epsilon = 1e-12);
        assert_relative_eq!(s1 * s2 * s3, i3, epsilon = 1e-12);
    }

    #[test]
    fn von_mises_equals_principal_form() {
        let s = general();
        let [s1, s2, s3] = s.principal();
        let from_principal =
            (0.5 * ((s1 - s2).powi(2) + (s2 - s3).powi(2) + (s3 - s1).powi(2))).sqrt();
        assert_relative_eq!(s.von_mises(), from_principal, epsilon = 1e-12);
    }

    #[test]
    fn plane_strain_fast_path_agrees_with_jacobi() {
        let s = Stress {
            xx: -0.4,
            yy: -0.21,
            zz: -0.9,
            yz: 0.0,
            xz: 0.17,
            xy: 0.0,
        };
        let fast = s.principal();
        let mut slow = s.jacobi_eigenvalues();
        slow.sort_by(|a, b| b.total_cmp(a));
        for (a, b) in fast.iter().zip(slow) {
            assert_relative_eq!(*a, b, epsilon = 1e-14);
        }
    }

    #[test]
    fn uniaxial_and_pure_shear_textbook_values() {
        let uniaxial = Stress {
            xx: 1.0,
            ..Stress::default()
        };
        assert_relative_eq!(uniaxial.von_mises(), 1.0, epsilon = 1e-15);
        assert_relative_eq!(uniaxial.max_shear(), 0.5, epsilon = 1e-15);
        assert_relative_eq!(uniaxial.hydrostatic(), 1.0 / 3.0, epsilon = 1e-15);
        let shear = Stress {
            xz: 1.0,
            ..Stress::default()
        };
        assert_relative_eq!(shear.von_mises(), 3f64.sqrt(), epsilon = 1e-15);
        assert_relative_eq!(shear.max_shear(), 1.0, epsilon = 1e-15);
        assert_relative_eq!(shear.principal_shear_xz(), 1.0, epsilon = 1e-15);
        let spherical = Stress {
            xx: -2.0,
            yy: -2.0,
            zz: -2.0,
            ..Stress::default()
        };
        assert_eq!(spherical.principal(), [-2.0, -2.0, -2.0]);
        assert_eq!(spherical.von_mises(), 0.0);
    }
}

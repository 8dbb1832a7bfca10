//! Exact stresses under a sliding Hertzian point contact (a sphere on an elastic half-space).

use crate::stress::Stress;

/// Stress (in units of `p0`) at `(x, y, z)` (in units of the contact radius `a`) in an elastic
/// half-space loaded by the Hertz pressure `p = p0 sqrt(1 - r^2/a^2)` and the full-sliding
/// traction `q = mu p`, which acts on the body's surface in +x.
///
/// Conventions: `z >= 0` points into the body; tension positive. On the surface inside the
/// contact `szz = -p`, `sxz = -q`, `syz = 0`; outside it the surface is traction-free.
///
/// ## The closed form
/// This is the closed form of Hamilton (1983), which for `mu = 0` is Huber's (1904). With
/// `r^2 = x^2 + y^2` and `a = 1`, Hamilton writes it with
///
/// ```text
/// A = r^2 + z^2 - 1,   S = sqrt(A^2 + 4 z^2),   M = sqrt((S + A)/2),   N = sqrt((S - A)/2),
/// phi = atan(1/M),     G = M^2 - N^2 + z M - N,  H = 2 M N + M + z N.
/// ```
///
/// These are the parts of two complex numbers: with `zeta = z + i`,
///
/// ```text
/// rho = M + i N = sqrt(r^2 + zeta^2),   u = rho + zeta,   S = |rho|^2,   G + i H = rho u,
/// phi = arg u.
/// ```
///
/// His explicit equations divide by `r^2`, `r^4` and `r^6` (removable on the axis, but they
/// lose all digits near it) and by `S` (zero on the contact edge), and far away their terms
/// cancel to a result that is smaller by `(a/R)^2`. So the same stresses are evaluated here in
/// a regrouped form without those divisions, derived afresh from Love's potentials (Johnson,
/// *Contact Mechanics*, 1985, §3.2). The pressure and the traction have the same shape, so one
/// axisymmetric potential serves both:
///
/// ```text
/// L(t, z) = ∫∫ p Omega dA,   Omega = z ln(R + z) - R,   t = r^2,
/// d_jk = (1/pi) ∂^j/∂t^j ∂^k/∂z^k L.
/// ```
///
/// Every Cartesian derivative of an axisymmetric function is a polynomial in `x, y` times
/// `t`-derivatives (`∂/∂x = 2x ∂/∂t`), so Love's formulas give, without any division by `r`
/// (`p0 = 1`; pressure and traction both have unit peak):
///
/// ```text
/// pressure:  sxx = -d11 + nu/2 d03 - z d12 + 2((nu-1) x^2 - nu y^2) d21 - 2 x^2 z d22
///            syy = -d11 + nu/2 d03 - z d12 + 2((nu-1) y^2 - nu x^2) d21 - 2 y^2 z d22
///            szz = d03/2 + 2z (d12 + t d22)
///            syz = -y z d13,   sxz = -x z d13,   sxy = 2 x y (2nu-1) d21 - 2 x y z d22
/// traction:  sxx = -4x (nu+4) d20 - 8x (x^2 + (1+nu) y^2) d30 - 6 x z d21 - 4 x^3 z d31
///            syy = -12 nu x d20 - 8 nu x^3 d30 - 2 x z d21 - 4 x y^2 z d31
///            szz = 8 x z d21 + 4 x z t d31
///            syz = -2 x y z d22
///            sxz = d03/2 + 8 z d20 + 4 z t d30 - 2 x^2 z d22
///            sxy = 4y (nu-2) d20 + 4y ((2nu-1) x^2 - y^2) d30 - 2 y z d21 - 4 x^2 y z d31
/// ```
///
/// (These follow from Love's displacements by Hooke's law together with `∇²L = 0`.) The
/// potential's derivatives have the closed forms, with `w = 1/u`,
///
/// ```text
/// d03 = 2 z phi - 2 N
/// d11 = -z phi/2 + Im[(4A - 5z^2 - 4 + 7iz + rho (z + 4i)) w] / 12
/// d12 = -phi/2   - Im[(rho + 2z) w] / 2
/// d13 =          - Im[(1 + i/rho) w]
/// d20 =  phi/16  + Im[(9A + 25z^2 - 9 + 52iz + rho (38z + 6i)) w^2] / 192
/// d21 =            Im[(2 rho + z + 4i) w^2] / 12
/// d22 =          - Im[(1 + 2i/rho) w^2] / 4
/// d30 =            Im[(3 rho + z + 9i) w^3] / 96
/// d31 =          - Im[(1 + 3i/rho) w^3] / 12
/// ```
///
/// derived as follows: the Newtonian potential of the Hertz pressure equals that of a line
/// load `(pi/2)(1 - s^2)` on the segment `z = -is`, `-1 <= s <= 1` (both are harmonic in
/// `z > 0` and vanish at infinity, and on `z = 0` both are `(pi^2/4)(2 - r^2)` inside the
/// contact and `(pi/2)((2 - r^2) asin(1/r) + sqrt(r^2 - 1))` outside), so
/// `d_jk = ∫_0^1 (1 - s^2) Re k_jk(t, z + is) ds` with `k_jk = ∂^j_t ∂^k_z Omega` at the complex
/// depth `z + is`; the integral is `Im` of an antiderivative at `s = 1`. Expanding real and
/// imaginary parts gives back Hamilton's terms, e.g. `-x z d13 = -z (x N/S - x z H/(G^2 + H^2))`
/// for the pressure's `sxz`. The tests compare this form with Hamilton's explicit equations
/// off the axis (they agree to 5e-14) and with quadrature of the Boussinesq and Cerruti
/// point-force solutions (to 1e-11; the test asks 1e-9).
///
/// Signs: Hamilton's explicit equations, in the form used here for comparison (that of the
/// ContactMechanics package's Hertz reference solutions, with his factor `3P/(2 pi a^3) = p0/a`
/// taken out), already follow this crate's convention: tension positive, `z` into the body,
/// traction in +x with `sxz = -q` on the surface. That was checked against the quadrature, not
/// against the printed paper, which was not available.
///
/// ## Singular points and cancellation
/// - Axis `r = 0`: nothing is divided by `r`; the formulas hold as they stand.
/// - Contact edge `r = 1, z = 0`: there `rho = 0`. Only `d13, d22, d31` contain `1/rho`, and
///   only multiplied by `z`; since `z = M N <= |rho|^2 / 2`, those products tend to zero, and
///   `1/rho` is taken as 0 at the edge itself. `phi = pi/2` on the surface inside (`M = 0`).
///   Near the edge the stresses vary like `sqrt(A)`, so `A = x^2 + y^2 - 1 + z^2` is formed
///   without first rounding `x^2 + y^2` (exact products and sums), and `rho = sqrt(A + 2iz)`
///   takes its smaller part from `M N = z`, not from a difference.
/// - Far field: for `r^2 + z^2 >= 36` the closed forms would lose `(R/a)^2` relative digits.
///   There the integrals over `s` above are evaluated directly with an 8-point Gauss–Jacobi
///   rule (weight `1 - s^2`); the integrands are analytic with singularities at
///   `s = ±r + iz`, so the rule's error is about `(2R)^-16`, and the nodes' contributions are
///   nearly equal, so their sum does not cancel. The kernels are those of point forces at
///   the complex depths, combined by the same formulas as above.
///
/// Accuracy, measured against 50-digit evaluation of the same closed forms: within `R < 6`
/// (axis, surface and the edge's neighbourhood included) the error is below 1e-15 `p0`, which
/// is at most about 1e-12 of the largest component at the point (near `R = 6`); beyond, about
/// 1e-14 of the largest component, checked up to `R = 1e6` and expected up to `R ~ 1e50`
/// (results stay finite up to about `1e75`). A component much smaller than the largest one at
/// the same point is accurate only relative to that largest one.
///
/// ## References
/// - G. M. Hamilton, Explicit equations for the stresses beneath a sliding spherical contact,
///   *Proc. Instn Mech. Engrs* 197C (1983) 53–59.
/// - M. T. Huber, Zur Theorie der Berührung fester elastischer Körper, *Ann. Phys.* 319 (1904)
///   153–163.
/// - K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §3.2 (Love's
///   potentials, Boussinesq and Cerruti) and §3.4 (Hertz pressure).
#[inline]
pub fn stress_over_p0(x: f64, y: f64, z: f64, mu: f64, nu: f64) -> Stress {
    let t = x * x + y * y;
    let d = if t + z * z < FAR_FIELD_RADIUS_SQ {
        PotentialDerivatives::closed_form(x, y, z)
    } else {
        PotentialDerivatives::far_field(t, z)
    };
    d.stress(x, y, z, t, mu, nu)
}

/// Surface tractions of the Hertz point contact: `(p/p0, q/p0)` at `(x/a, y/a)`, with
/// `p = sqrt(1 - r^2)` inside the contact and 0 outside.
///
/// `1 - r^2` is formed without rounding `r^2` first, exactly as in [`stress_over_p0`], so that
/// `szz = -p` and `sxz = -q` hold to the last digit on the surface, even next to the edge.
pub fn surface_traction_over_p0(x: f64, y: f64, mu: f64) -> (f64, f64) {
    let r2_minus_one = squares_minus_one(x, y);
    let p = if r2_minus_one < 0.0 {
        (-r2_minus_one).sqrt()
    } else {
        0.0
    };
    (p, mu * p)
}

/// Squared distance from the contact centre (in units of `a^2`) beyond which the far-field
/// quadrature replaces the closed forms.
const FAR_FIELD_RADIUS_SQ: f64 = 36.0;

/// Positive nodes and weights of the 8-point Gauss–Jacobi rule (alpha = beta = 1) on [-1, 1]:
/// `∫ (1 - s^2) f(s) ds ≈ Σ W_i f(s_i)`, exact for polynomials of degree 15. For an even `f`,
/// `∫_0^1 (1 - s^2) f ds = Σ_{s_i > 0} W_i f(s_i)`.
const GAUSS_JACOBI_NODES: [f64; 4] = [
    0.165_278_957_666_387_03,
    0.477_924_949_810_444_53,
    0.738_773_865_105_505,
    0.919_533_908_166_458_9,
];
const GAUSS_JACOBI_WEIGHTS: [f64; 4] = [
    0.318_592_313_687_328_43,
    0.225_336_554_969_857_94,
    0.102_147_702_360_358_21,
    0.020_590_095_649_121_964,
];

/// The derivatives `d_jk = (1/pi) ∂^j_t ∂^k_z L` of the potential `L = ∫∫ p Omega dA` that the
/// stresses need (see [`stress_over_p0`]); `tjzk` holds `d_jk`.
#[derive(Clone, Copy, Debug, Default)]
struct PotentialDerivatives {
    t0z3: f64,
    t1z1: f64,
    t1z2: f64,
    t1z3: f64,
    t2z0: f64,
    t2z1: f64,
    t2z2: f64,
    t3z0: f64,
    t3z1: f64,
}

impl PotentialDerivatives {
    /// The closed forms (see [`stress_over_p0`]); accurate for `r^2 + z^2` below a few tens.
    #[inline(always)]
    fn closed_form(x: f64, y: f64, z: f64) -> Self {
        let z2 = z * z;
        // Hamilton's A = r^2 + z^2 - 1, accurate even where it is small: near the contact edge
        // the stresses vary like sqrt(A), so rounding x^2 + y^2 first would cost digits.
        let a = squares_minus_one(x, y) + z2;
        // Hamilton's S = |rho|^2.
        let s = (a * a + 4.0 * z2).sqrt();
        // rho = M + iN = sqrt(A + 2iz): the larger part from the sum (no cancellation), the
        // smaller from M N = z.
        let large = (0.5 * (s + a.abs())).sqrt();
        let small = z / large.max(f64::MIN_POSITIVE);
        let (m, n) = if a >= 0.0 {
            (large, small)
        } else {
            (small, large)
        };
        let rho = Complex::new(m, n);
        let w = Complex::new(m + z, n + 1.0).recip(); // 1/u
        let w2 = w * w;
        let w3 = w2 * w;
        let phi = (1.0 / m).atan(); // arg u; pi/2 when M = 0

        // i/rho, taken as 0 on the contact edge where rho = 0 (it only appears times z).
        let inv_s = if s > 0.0 { 1.0 / s } else { 0.0 };
        let i_over_rho = Complex::new(n * inv_s, m * inv_s);

        let numerator_11 =
            Complex::new(4.0 * a - 5.0 * z2 - 4.0, 7.0 * z) + rho * Complex::new(z, 4.0);
        let numerator_20 =
            Complex::new(9.0 * a + 25.0 * z2 - 9.0, 52.0 * z) + rho * Complex::new(38.0 * z, 6.0);
        Self {
            t0z3: 2.0 * (z * phi - n),
            t1z1: -0.5 * z * phi + (numerator_11 * w).im / 12.0,
            t1z2: -0.5 * (phi + ((rho + Complex::new(2.0 * z, 0.0)) * w).im),
            t1z3: -((i_over_rho + Complex::ONE) * w).im,
            t2z0: phi / 16.0 + (numerator_20 * w2).im / 192.0,
            t2z1: ((rho * 2.0 + Complex::new(z, 4.0)) * w2).im / 12.0,
            t2z2: -0.25 * ((i_over_rho * 2.0 + Complex::ONE) * w2).im,
            t3z0: ((rho * 3.0 + Complex::new(z, 9.0)) * w3).im / 96.0,
            t3z1: -((i_over_rho * 3.0 + Complex::ONE) * w3).im / 12.0,
        }
    }

    /// The same derivatives as integrals over the line load, `∫_0^1 (1 - s^2) Re k(z + is) ds`,
    /// by Gauss–Jacobi quadrature; accurate for `r^2 + z^2 >= 36` (see [`stress_over_p0`]).
    #[inline(never)]
    fn far_field(t: f64, z: f64) -> Self {
        let mut sum = Self::default();
        for (&s, &weight) in GAUSS_JACOBI_NODES.iter().zip(&GAUSS_JACOBI_WEIGHTS) {
            let zeta = Complex::new(z, s);
            // rho = sqrt(t + zeta^2), whose real part t + z^2 - s^2 is positive here.
            let re = t + z * z - s * s;
            let im = 2.0 * z * s;
            let modulus = (re * re + im * im).sqrt(); // |rho|^2
            let m = (0.5 * (modulus + re)).sqrt();
            let n = 0.5 * im / m;
            let rho = Complex::new(m, n);
            let q = Complex::new(m, -n) * (1.0 / modulus); // 1/rho
            let w = (rho + zeta).recip(); // 1/u
            let q2 = q * q;
            let q3 = q2 * q;
            let q5 = q3 * q2;
            let w2 = w * w;
            let w3 = w2 * w;
            // k_jk = ∂^j_t ∂^k_z Omega at depth zeta, in terms of q = 1/rho and w = 1/u.
            let k03 = -(zeta * q3);
            let k11 = q * w * 0.5;
            let k12 = q3 * -0.5;
            let k13 = zeta * q5 * 1.5;
            let k20 = q * w2 * 0.25;
            let k21 = (q2 * w2 + q3 * w) * -0.25;
            let k22 = q5 * 0.75;
            let k30 = (q2 * w3 * 2.0 + q3 * w2) * -0.125;
            let k31 = (q3 * w3 * 2.0 + q2 * q2 * w2 * 3.0 + q5 * w * 3.0) * 0.125;
            sum.t0z3 += weight * k03.re;
            sum.t1z1 += weight * k11.re;
            sum.t1z2 += weight * k12.re;
            sum.t1z3 += weight * k13.re;
            sum.t2z0 += weight * k20.re;
            sum.t2z1 += weight * k21.re;
            sum.t2z2 += weight * k22.re;
            sum.t3z0 += weight * k30.re;
            sum.t3z1 += weight * k31.re;
        }
        sum
    }

    /// Love's stresses (see [`stress_over_p0`]) for the pressure plus `mu` times the traction.
    #[inline(always)]
    fn stress(&self, x: f64, y: f64, z: f64, t: f64, mu: f64, nu: f64) -> Stress {
        let d = self;
        let (x2, y2) = (x * x, y * y);
        let xz = x * z;

        // Normal pressure (Huber).
        let common = -d.t1z1 + 0.5 * nu * d.t0z3 - z * d.t1z2;
        let zd22 = z * d.t2z2;
        let pressure_xx = common + 2.0 * ((nu - 1.0) * x2 - nu * y2) * d.t2z1 - 2.0 * x2 * zd22;
        let pressure_yy = common + 2.0 * ((nu - 1.0) * y2 - nu * x2) * d.t2z1 - 2.0 * y2 * zd22;
        let pressure_zz = 0.5 * d.t0z3 + 2.0 * z * (d.t1z2 + t * d.t2z2);
        let pressure_yz = -y * z * d.t1z3;
        let pressure_xz = -xz * d.t1z3;
        let pressure_xy = 2.0 * x * y * ((2.0 * nu - 1.0) * d.t2z1 - zd22);

        // Tangential traction in +x (Hamilton's sliding part).
        let zd21 = z * d.t2z1;
        let zd31 = z * d.t3z1;
        let traction_xx = -x
            * (4.0 * (nu + 4.0) * d.t2z0
                + 8.0 * (x2 + (1.0 + nu) * y2) * d.t3z0
                + 6.0 * zd21
                + 4.0 * x2 * zd31);
        let traction_yy =
            -x * (12.0 * nu * d.t2z0 + 8.0 * nu * x2 * d.t3z0 + 2.0 * zd21 + 4.0 * y2 * zd31);
        let traction_zz = 4.0 * xz * (2.0 * d.t2z1 + t * d.t3z1);
        let traction_yz = -2.0 * x * y * zd22;
        let traction_xz = 0.5 * d.t0z3 + 4.0 * z * (2.0 * d.t2z0 + t * d.t3z0) - 2.0 * x2 * zd22;
        let traction_xy = y
            * (4.0 * (nu - 2.0) * d.t2z0 + 4.0 * ((2.0 * nu - 1.0) * x2 - y2) * d.t3z0
                - 2.0 * zd21
                - 4.0 * x2 * zd31);

        Stress {
            xx: pressure_xx + mu * traction_xx,
            yy: pressure_yy + mu * traction_yy,
            zz: pressure_zz + mu * traction_zz,
            yz: pressure_yz + mu * traction_yz,
            xz: pressure_xz + mu * traction_xz,
            xy: pressure_xy + mu * traction_xy,
        }
    }
}

/// `x^2 + y^2 - 1` to within a rounding of the result itself (not of 1): the squares are
/// split exactly (Dekker 1971) and summed without loss, so that near the circle `r = 1` the
/// difference keeps its digits. Plain arithmetic only (no `mul_add`, which is a slow library
/// call without hardware FMA). Valid for `|x|, |y| < 1e150`.
#[inline(always)]
fn squares_minus_one(x: f64, y: f64) -> f64 {
    let (xx, x_error) = exact_square(x);
    let (yy, y_error) = exact_square(y);
    // Two-sum (Knuth): xx + yy = sum + sum_error exactly.
    let sum = xx + yy;
    let y_part = sum - xx;
    let sum_error = (xx - (sum - y_part)) + (yy - y_part);
    // sum - 1 is exact where it matters (0.5 <= sum <= 2, Sterbenz).
    (sum - 1.0) + (sum_error + x_error + y_error)
}

/// `x^2` as `(rounded, error)` with `rounded + error = x^2` exactly (Dekker's product).
#[inline(always)]
fn exact_square(x: f64) -> (f64, f64) {
    const SPLIT: f64 = 134_217_729.0; // 2^27 + 1
    let square = x * x;
    let scaled = SPLIT * x;
    let high = scaled - (scaled - x);
    let low = x - high;
    (
        square,
        ((high * high - square) + 2.0 * high * low) + low * low,
    )
}

/// Just enough complex arithmetic for the closed forms (no allocation, all inlined).
#[derive(Clone, Copy, Debug)]
struct Complex {
    re: f64,
    im: f64,
}

impl Complex {
    const ONE: Self = Self::new(1.0, 0.0);

    #[inline(always)]
    const fn new(re: f64, im: f64) -> Self {
        Self { re, im }
    }

    #[inline(always)]
    fn recip(self) -> Self {
        let inv = 1.0 / (self.re * self.re + self.im * self.im);
        Self::new(self.re * inv, -self.im * inv)
    }
}

impl std::ops::Add for Complex {
    type Output = Self;

    #[inline(always)]
    fn add(self, other: Self) -> Self {
        Self::new(self.re + other.re, self.im + other.im)
    }
}

impl std::ops::Mul for Complex {
    type Output = Self;

    #[inline(always)]
    fn mul(self, other: Self) -> Self {
        Self::new(
            self.re * other.re - self.im * other.im,
            self.re * other.im + self.im * other.re,
        )
    }
}

impl std::ops::Mul<f64> for Complex {
    type Output = Self;

    #[inline(always)]
    fn mul(self, factor: f64) -> Self {
        Self::new(self.re * factor, self.im * factor)
    }
}

impl std::ops::Neg for Complex {
    type Output = Self;

    #[inline(always)]
    fn neg(self) -> Self {
        Self::new(-self.re, -self.im)
    }
}

#[cfg(test)]
mod tests;

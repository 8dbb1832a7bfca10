//! Influence coefficients of plane strain: the stresses under a uniform normal pressure and a
//! uniform tangential traction on a strip `s1 <= x <= s2` of the surface of a half-plane.

use std::f64::consts::PI;

/// In-plane stresses `(sxx, szz, sxz)` at `(x, z)` due to a uniform pressure `p = 1` pushing on
/// the strip `s1 <= x <= s2` (in +z, into the body), and due to a uniform tangential traction
/// `q = 1` acting on the body in +x over the same strip.
///
/// Obtained by integrating the Flamant point-force solutions (Johnson, *Contact Mechanics*,
/// 1985, §2.2) over the strip in closed form. With `X = x - s` and `r² = X² + z²`, a normal line
/// force gives `(sxx, szz, sxz) = -(2/π)(X² z, z³, X z²) / r⁴` and a tangential one
/// `-(2/π)(X³, X z², X² z) / r⁴`; the antiderivatives in X are
///
/// ```text
/// ∫ X² z / r⁴ = ½ atan(X/z) - z X / (2 r²)      ∫ z³ / r⁴ = ½ atan(X/z) + z X / (2 r²)
/// ∫ X z² / r⁴ = -z² / (2 r²)                    ∫ X³ / r⁴ = ½ ln r² + z² / (2 r²)
/// ```
///
/// and the strip's stress is `F(x - s1) - F(x - s2)`. `atan(X/z)` is evaluated as
/// `atan2(X, z)`, so the surface `z = 0` is included: there, under the strip, `szz = -p`,
/// `sxz = -q`, and the tangential `sxx` has the logarithmic singularity of the strip's edges
/// (returned as infinite exactly at an edge on the surface).
///
/// ## Reference
/// K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), ch. 2: §2.2 for the
/// Flamant solutions; the same chapter treats distributed loads on a strip.
#[inline]
pub fn uniform_strip(x: f64, z: f64, s1: f64, s2: f64) -> ([f64; 3], [f64; 3]) {
    let upper = antiderivatives(x - s1, z);
    let lower = antiderivatives(x - s2, z);
    let d: [f64; 4] = std::array::from_fn(|i| upper[i] - lower[i]);
    let f = STRIP_FACTOR;
    let normal = [f * d[0], f * d[1], f * d[2]];
    let tangential = [f * d[3], f * d[2], f * d[0]];
    (normal, tangential)
}

/// The factor `-2/π` of the Flamant solutions in [`uniform_strip`].
pub const STRIP_FACTOR: f64 = -2.0 / PI;

/// The antiderivatives of [`uniform_strip`] at `X = x - s` and depth `z`:
/// `(∫X²z/r⁴, ∫z³/r⁴, ∫Xz²/r⁴, ∫X³/r⁴)` in X (with `½ ln r² = ln r`). A strip's stress is
/// `STRIP_FACTOR` times their difference between its edges: for a normal load
/// `(sxx, szz, sxz)` from components `(0, 1, 2)`, for a tangential one from `(3, 2, 0)`.
#[inline]
pub fn antiderivatives(big_x: f64, z: f64) -> [f64; 4] {
    // r, not r², so that neither a tiny depth (z = 1e-200: z² underflows to zero, and the
    // edge's ln r would be -inf on both sides of a difference) nor a far point overflows.
    let r = big_x.hypot(z);
    let half_angle = 0.5 * big_x.atan2(z);
    let (cos, sin) = if r > 0.0 {
        (z / r, big_x / r)
    } else {
        (0.0, 0.0)
    };
    let zx = 0.5 * cos * sin;
    let zz = 0.5 * cos * cos;
    [half_angle - zx, half_angle + zx, -zz, r.ln() + zz]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn surface_under_the_strip_carries_the_load() {
        let (normal, tangential) = uniform_strip(0.3, 0.0, -0.5, 1.0);
        assert!((normal[1] + 1.0).abs() < 1e-15, "szz = -p: {normal:?}");
        assert!(normal[2].abs() < 1e-15);
        assert!(
            (tangential[2] + 1.0).abs() < 1e-15,
            "sxz = -q: {tangential:?}"
        );
        assert!(tangential[1].abs() < 1e-15);
        // Uniform pressure: sxx = -p on the surface under the strip (Johnson ch. 2).
        assert!((normal[0] + 1.0).abs() < 1e-15);
        // Outside the strip the surface is free.
        let (normal, tangential) = uniform_strip(2.0, 0.0, -0.5, 1.0);
        assert!(normal.iter().all(|v| v.abs() < 1e-15));
        assert!(tangential[1].abs() < 1e-15 && tangential[2].abs() < 1e-15);
    }

    #[test]
    fn a_vanishing_depth_is_the_surface_and_stays_finite() {
        // At a strip's edge (X = 0) just below the surface: z² underflows for z = 1e-200,
        // yet the stresses are those of the surface, with the finite logarithm of ln(z).
        for z in [1e-200, 5e-324] {
            let (normal, tangential) = uniform_strip(0.0, z, -0.5, 0.0);
            assert!(normal.iter().chain(&tangential).all(|v| v.is_finite()));
            // Half the strip's load at its edge (the mean of the two sides).
            assert!((normal[1] + 0.5).abs() < 1e-12, "{normal:?}");
            assert!((tangential[2] + 0.5).abs() < 1e-12, "{tangential:?}");
            // ∫X³/r⁴ from the near edge (X = 0: ln z + ½) to the far one (X = ½: ln ½).
            let expected = -2.0 / PI * (0.5f64.ln() - z.ln() - 0.5);
            assert!(
                (tangential[0] / expected - 1.0).abs() < 1e-12,
                "{tangential:?}"
            );
        }
    }

    #[test]
    fn far_away_a_strip_acts_as_a_line_force() {
        // Flamant with P = width: szz = -(2P/pi) z³/r⁴.
        let (x, z, width) = (300.0, 400.0, 0.5);
        let (normal, _) = uniform_strip(x, z, -0.25, 0.25);
        let r2: f64 = x * x + z * z;
        let flamant = -2.0 * width / PI * z.powi(3) / (r2 * r2);
        assert!(
            (normal[1] / flamant - 1.0).abs() < 1e-5,
            "{} vs {flamant}",
            normal[1]
        );
    }
}

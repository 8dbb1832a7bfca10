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
    let antiderivatives = |big_x: f64| {
        let r2 = big_x * big_x + z * z;
        let half_angle = 0.5 * big_x.atan2(z);
        let zx = if r2 > 0.0 {
            z * big_x / (2.0 * r2)
        } else {
            0.0
        };
        let zz = if r2 > 0.0 { z * z / (2.0 * r2) } else { 0.0 };
        // (∫X²z/r⁴, ∫z³/r⁴, ∫Xz²/r⁴, ∫X³/r⁴)
        [half_angle - zx, half_angle + zx, -zz, 0.5 * r2.ln() + zz]
    };
    let upper = antiderivatives(x - s1);
    let lower = antiderivatives(x - s2);
    let d: [f64; 4] = std::array::from_fn(|i| upper[i] - lower[i]);
    let f = -2.0 / PI;
    let normal = [f * d[0], f * d[1], f * d[2]];
    let tangential = [f * d[3], f * d[2], f * d[0]];
    (normal, tangential)
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

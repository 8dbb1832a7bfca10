//! Line contact by numerical integration: the Hertz tractions discretised into uniform strips
//! and the stress summed from the strips' exact influence coefficients ([`super::strip`]).
//!
//! This is an independent route to the closed form of [`super::line_hertz`] (a check of it,
//! and the model for tractions that have no closed form).

use super::strip;
use crate::stress::Stress;

/// Surface tractions discretised into `n` equal strips over `-a..a` (units of a and p0).
#[derive(Clone, Debug, PartialEq)]
pub struct StripTractions {
    /// `n + 1` strip edges.
    pub edges: Vec<f64>,
    /// Mean pressure on each strip.
    pub pressure: Vec<f64>,
    /// Mean tangential traction (on the body, +x) on each strip.
    pub shear: Vec<f64>,
}

impl StripTractions {
    /// The Hertz pressure `sqrt(1 - x²)` and `q = mu p`, each strip carrying the exact mean of
    /// the pressure over it, `(F(b) - F(a)) / (b - a)` with `F(x) = (x sqrt(1-x²) + asin x)/2`,
    /// so the total load `pi/2` is kept exactly.
    pub fn hertz(strips: usize, mu: f64) -> Self {
        let n = strips.max(1);
        let edges: Vec<f64> = (0..=n).map(|i| -1.0 + 2.0 * i as f64 / n as f64).collect();
        let antiderivative = |x: f64| 0.5 * (x * (1.0 - x * x).max(0.0).sqrt() + x.asin());
        let pressure: Vec<f64> = edges
            .windows(2)
            .map(|w| (antiderivative(w[1]) - antiderivative(w[0])) / (w[1] - w[0]))
            .collect();
        let shear = pressure.iter().map(|p| mu * p).collect();
        Self {
            edges,
            pressure,
            shear,
        }
    }

    /// Stress (units of p0) at `(x, z)` by direct summation over the strips (plane strain):
    /// exact for the discretised tractions, so on the surface exactly at a strip edge, where
    /// the traction jumps, the tangential load's `sxx` is logarithmically infinite (and
    /// `0 x inf`, NaN, where a strip carries none); see [`Self::finite_stress_over_p0`].
    pub fn stress_over_p0(&self, x: f64, z: f64, nu: f64) -> Stress {
        self.summed(x, z, nu)
    }

    /// [`Self::stress_over_p0`], made finite on the surface at the strip edges by the mean of
    /// the values at the centres of the two strips meeting there (half a strip either side):
    /// the value a user expects of the continuous tractions, to which it converges as the
    /// strips are refined. (For `szz` and `sxz`, constant on each strip's surface, that is the
    /// mean of the one-sided limits.) Everywhere else the exact value.
    pub fn finite_stress_over_p0(&self, x: f64, z: f64, nu: f64) -> Stress {
        let stress = self.summed(x, z, nu);
        if z > 0.0 || stress.is_finite() {
            return stress;
        }
        // The centres of the strips either side of the edge at x (the strips may differ in
        // width: the solved pressure of an EHL contact lies on a graded grid).
        let n = self.pressure.len();
        let k = self.edges.partition_point(|&e| e < x).min(n);
        let width = |i: usize| self.edges[i + 1] - self.edges[i];
        let left = if k > 0 { width(k - 1) } else { width(0) };
        let right = if k < n { width(k) } else { width(n - 1) };
        Stress::mean(&[
            self.summed(x - 0.5 * left, z, nu),
            self.summed(x + 0.5 * right, z, nu),
        ])
    }

    /// The strips' stresses summed by parts: strip `i` contributes
    /// `t_i (F(x − e_i) − F(x − e_{i+1}))` ([`strip::uniform_strip`]), so each edge's
    /// antiderivatives `F(x − e_k)` enter once, weighted by the jump of the tractions there,
    /// `t_k − t_{k−1}` (zero beyond the strips): one evaluation of the transcendental functions
    /// per edge instead of two.
    fn summed(&self, x: f64, z: f64, nu: f64) -> Stress {
        let n = self.pressure.len();
        let mut sum = [0.0; 3];
        let (mut p_before, mut q_before) = (0.0, 0.0);
        for (k, &edge) in self.edges.iter().enumerate() {
            let (p, q) = if k < n {
                (self.pressure[k], self.shear[k])
            } else {
                (0.0, 0.0)
            };
            let (dp, dq) = (p - p_before, q - q_before);
            (p_before, q_before) = (p, q);
            if dp == 0.0 && dq == 0.0 {
                continue;
            }
            let f = strip::antiderivatives(x - edge, z);
            sum[0] += dp * f[0] + dq * f[3];
            sum[1] += dp * f[1] + dq * f[2];
            sum[2] += dp * f[2] + dq * f[0];
        }
        let c = strip::STRIP_FACTOR;
        Stress::plane_strain(c * sum[0], c * sum[1], c * sum[2], nu)
    }

    /// The tractions `(p, q)` of the strip containing `x` (zero outside the strips).
    pub fn at(&self, x: f64) -> (f64, f64) {
        let n = self.pressure.len();
        let (first, last) = (self.edges[0], self.edges[n]);
        if !(x >= first && x < last) {
            return (0.0, 0.0);
        }
        let i = self
            .edges
            .partition_point(|&e| e <= x)
            .saturating_sub(1)
            .min(n - 1);
        (self.pressure[i], self.shear[i])
    }

    /// Total normal load per unit length (units of p0 a).
    pub fn load(&self) -> f64 {
        self.edges
            .windows(2)
            .zip(&self.pressure)
            .map(|(w, p)| (w[1] - w[0]) * p)
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solution::line_hertz;

    #[test]
    fn surface_values_at_strip_edges_are_the_mean_of_the_neighbouring_centres() {
        for mu in [0.0, 0.3] {
            let tractions = StripTractions::hertz(10, mu);
            // The contact edges (one side unloaded), interior edges, the centre x = 0.
            for k in [0, 3, 5, 10] {
                let x = tractions.edges[k];
                let at_edge = tractions.finite_stress_over_p0(x, 0.0, 0.3);
                assert!(at_edge.is_finite(), "mu {mu}, x {x}: {at_edge:?}");
                let left = tractions.stress_over_p0(x - 0.1, 0.0, 0.3);
                let right = tractions.stress_over_p0(x + 0.1, 0.0, 0.3);
                let mean = Stress::mean(&[left, right]);
                assert!(
                    (at_edge.xx - mean.xx).abs() < 1e-14,
                    "{at_edge:?} vs {mean:?}"
                );
                // szz = -p on the surface: the mean of the two strips' pressures.
                let (p_left, _) = tractions.at(x - 0.1);
                let (p_right, _) = tractions.at(x + 0.1);
                assert!((at_edge.zz + 0.5 * (p_left + p_right)).abs() < 1e-14);
            }
            // Just below the surface the exact sum is used, and it is close to the mean.
            let below = tractions.finite_stress_over_p0(0.0, 1e-3, 0.3);
            assert_eq!(below, tractions.stress_over_p0(0.0, 1e-3, 0.3));
            // The exact value of the discrete tractions at an edge where the traction jumps is
            // not finite; at the centre x = 0 the two strips carry the same tractions (the
            // discretised Hertz pressure is symmetric), no jump, and the value is finite.
            if mu > 0.0 {
                let jump = tractions.edges[3];
                assert!(!tractions.stress_over_p0(jump, 0.0, 0.3).is_finite());
                assert!(tractions.stress_over_p0(0.0, 0.0, 0.3).is_finite());
            }
        }
    }

    #[test]
    fn discretised_load_is_exact() {
        let tractions = StripTractions::hertz(37, 0.2);
        assert!((tractions.load() - std::f64::consts::FRAC_PI_2).abs() < 1e-14);
    }

    #[test]
    fn converges_to_the_closed_form_as_strips_are_refined() {
        // Maximum error over a set of interior points (z >= 0.1a) for n and 4n strips: the
        // piecewise-constant pressure converges at least like 1/n.
        let points: Vec<(f64, f64)> = (0..=20)
            .flat_map(|i| [0.1, 0.3, 0.786, 1.5].map(|z| (-2.0 + 0.2 * f64::from(i), z)))
            .collect();
        let error = |n: usize| {
            let tractions = StripTractions::hertz(n, 0.3);
            points
                .iter()
                .map(|&(x, z)| {
                    let a = tractions.stress_over_p0(x, z, 0.3);
                    let b = line_hertz::stress_over_p0(x, z, 0.3, 0.3);
                    [a.xx - b.xx, a.zz - b.zz, a.xz - b.xz]
                        .iter()
                        .fold(0.0f64, |m, d| m.max(d.abs()))
                })
                .fold(0.0f64, f64::max)
        };
        let (coarse, fine) = (error(50), error(200));
        assert!(fine < coarse / 3.0, "{coarse} -> {fine}");
        assert!(fine < 2e-3, "{fine}");
        assert!(error(2000) < 2e-4, "{}", error(2000));
    }
}

//! Where and how large the extreme stresses are, and what that means for yield.

use crate::solution::Solution;
use crate::stress::Quantity;

/// The largest value of a quantity and where it occurs (units of `p0` and `a`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Extreme {
    pub value_over_p0: f64,
    pub x_over_a: f64,
    pub z_over_a: f64,
}

/// Finds the maximum of `quantity` over `|x| <= 3a`, `0 <= z <= 3a` (where every Hertz
/// maximum lies), optionally restricted to the surface `z = 0`.
///
/// A coarse scan (step 0.025a) is followed by a compass search that halves its step down to
/// 1e-9 a, so locations are accurate to about 1e-8 a for smooth maxima.
pub fn maximum(solution: &Solution, quantity: Quantity, surface_only: bool) -> Extreme {
    let value = |x: f64, z: f64| quantity.of(&solution.stress_over_p0(x, 0.0, z));
    let step = 0.025;
    let (mut best_x, mut best_z, mut best) = (0.0, 0.0, f64::NEG_INFINITY);
    let nz = if surface_only { 1 } else { 121 };
    for iz in 0..nz {
        let z = step * iz as f64;
        for ix in 0..=240 {
            let x = -3.0 + step * ix as f64;
            let v = value(x, z);
            if v > best {
                (best_x, best_z, best) = (x, z, v);
            }
        }
    }
    let mut h = step;
    while h > 1e-9 {
        let mut improved = false;
        let moves: &[(f64, f64)] = if surface_only {
            &[(1.0, 0.0), (-1.0, 0.0)]
        } else {
            &[(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)]
        };
        for (dx, dz) in moves {
            let (x, z) = (best_x + dx * h, (best_z + dz * h).max(0.0));
            let v = value(x, z);
            if v > best {
                (best_x, best_z, best) = (x, z, v);
                improved = true;
            }
        }
        if !improved {
            h *= 0.5;
        }
    }
    Extreme {
        value_over_p0: best,
        x_over_a: best_x,
        z_over_a: best_z,
    }
}

/// The maxima that decide first yield under a contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StressMaxima {
    pub von_mises: Extreme,
    pub max_shear: Extreme,
    pub von_mises_surface: Extreme,
}

impl StressMaxima {
    pub fn of(solution: &Solution) -> Self {
        Self {
            von_mises: maximum(solution, Quantity::VonMises, false),
            max_shear: maximum(solution, Quantity::MaxShear, false),
            von_mises_surface: maximum(solution, Quantity::VonMises, true),
        }
    }

    /// Whether first yield (von Mises) starts at the surface: the surface maximum is within
    /// 1e-6 p0 of the overall maximum.
    pub fn yield_starts_at_surface(&self) -> bool {
        self.von_mises.value_over_p0 - self.von_mises_surface.value_over_p0 <= 1e-6
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn frictionless_line_contact_maxima() {
        let solution = Solution::LineHertz {
            friction: 0.0,
            poisson: 0.3,
        };
        // Johnson (1985) §4.2(b): tau_1 max 0.300 p0 at z = 0.786a on the axis.
        let tau1 = maximum(&solution, Quantity::Tau1, false);
        assert_relative_eq!(tau1.value_over_p0, 0.300, epsilon = 5e-4);
        assert_relative_eq!(tau1.z_over_a, 0.786, epsilon = 5e-4);
        assert!(tau1.x_over_a.abs() < 1e-6);
        let maxima = StressMaxima::of(&solution);
        assert!(!maxima.yield_starts_at_surface());
    }

    #[test]
    fn large_friction_moves_yield_to_the_surface() {
        // Johnson (1985) §7.2: for mu > ~0.3 first yield is at the surface.
        let solution = Solution::LineHertz {
            friction: 0.4,
            poisson: 0.3,
        };
        assert!(StressMaxima::of(&solution).yield_starts_at_surface());
        let solution = Solution::LineHertz {
            friction: 0.1,
            poisson: 0.3,
        };
        assert!(!StressMaxima::of(&solution).yield_starts_at_surface());
    }
}

//! Spur gear pair meshing at the pitch point, seen as two cylinders in line contact.

/// A pair of external involute spur gears.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpurGearPair {
    pub module_m: f64,
    pub teeth: [u32; 2],
    pub pressure_angle_rad: f64,
}

impl SpurGearPair {
    /// Pitch radius `r = m N / 2` of gear `i` (0 or 1).
    pub fn pitch_radius_m(&self, i: usize) -> f64 {
        self.module_m * f64::from(self.teeth[i]) / 2.0
    }

    /// Base radius `r_b = r cos(phi)`.
    pub fn base_radius_m(&self, i: usize) -> f64 {
        self.pitch_radius_m(i) * self.pressure_angle_rad.cos()
    }

    /// Radius of curvature of the involute flank at the pitch point, `rho = r sin(phi)`: the
    /// distance along the line of action from the base-circle tangency point to the pitch point
    /// (AP and BP in the seed notes' figure 56).
    ///
    /// ## Reference
    /// The involute's radius of curvature at a point is the length of its generating line from
    /// the base-circle tangency point; at the pitch point that is `r_b tan(phi) = r sin(phi)`.
    /// Seed lecture notes (Homework 3, Problem 1 and figure 56, after Wang 2002) set the
    /// problem; the teeth are then two cylinders in line contact (Hertz).
    pub fn curvature_radius_at_pitch_point_m(&self, i: usize) -> f64 {
        self.pitch_radius_m(i) * self.pressure_angle_rad.sin()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn seed_problem_one_radii() {
        // Seed notes, Problem 1: m = 5 mm, N = 20 and 40, phi = 20 deg.
        let pair = SpurGearPair {
            module_m: 5e-3,
            teeth: [20, 40],
            pressure_angle_rad: 20f64.to_radians(),
        };
        assert_relative_eq!(pair.pitch_radius_m(0), 0.050, max_relative = 1e-15);
        assert_relative_eq!(pair.pitch_radius_m(1), 0.100, max_relative = 1e-15);
        // 50 mm * sin 20 deg = 17.101 mm, 100 mm * sin 20 deg = 34.202 mm.
        assert_relative_eq!(
            pair.curvature_radius_at_pitch_point_m(0) * 1e3,
            17.101_007_166,
            max_relative = 1e-10
        );
        assert_relative_eq!(
            pair.curvature_radius_at_pitch_point_m(1) * 1e3,
            34.202_014_332,
            max_relative = 1e-10
        );
        // The two radii add up to the length of the line of action between tangency points.
        let c = pair.pitch_radius_m(0) + pair.pitch_radius_m(1);
        assert_relative_eq!(
            pair.curvature_radius_at_pitch_point_m(0) + pair.curvature_radius_at_pitch_point_m(1),
            c * 20f64.to_radians().sin(),
            max_relative = 1e-15
        );
    }
}

//! Spur gear pair: the teeth meshing at the pitch point seen as two cylinders in line contact,
//! and the kinematics along the path of contact (flank radii, rolling and sliding speeds, the
//! pairs of teeth sharing the load).
//!
//! Positions on the line of action are `s`, m from the pitch point, positive towards the
//! pinion's tip (the end of contact when the pinion drives): the pinion's flank radius grows
//! with `s`, the gear's shrinks.

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

    /// Tip (addendum) radius `r + m`: standard full-depth teeth, addendum one module (the
    /// ISO 53 basic rack).
    pub fn tip_radius_m(&self, i: usize) -> f64 {
        self.pitch_radius_m(i) + self.module_m
    }

    /// Base pitch `p_b = π m cos(φ)`: the distance between successive teeth along the line
    /// of action.
    pub fn base_pitch_m(&self) -> f64 {
        std::f64::consts::PI * self.module_m * self.pressure_angle_rad.cos()
    }

    /// The path of contact `[start, end]` (m from the pitch point): where the line of action
    /// meets the gear's tip circle (start, `s < 0`) and the pinion's (end), `s = ±(√(r_a² -
    /// r_b²) - r sin φ)`.
    ///
    /// ## Reference
    /// The tip circle meets the line of action at `√(r_a² - r_b²)` from the base circle's
    /// tangency point (right triangle of the base radius and the tip radius); e.g. Shigley's
    /// *Mechanical Engineering Design*, the contact ratio of spur gears. The test finds the
    /// intersections again as roots of a quadratic in plane coordinates.
    pub fn path_of_contact_m(&self) -> [f64; 2] {
        let along = |i: usize| {
            (self.tip_radius_m(i).powi(2) - self.base_radius_m(i).powi(2)).sqrt()
                - self.curvature_radius_at_pitch_point_m(i)
        };
        [-along(1), along(0)]
    }

    /// Transverse contact ratio: the path of contact over the base pitch, the mean number of
    /// pairs of teeth in contact.
    pub fn contact_ratio(&self) -> f64 {
        let [start, end] = self.path_of_contact_m();
        (end - start) / self.base_pitch_m()
    }

    /// Whether the path of contact starts beyond the pinion's base-circle tangency point (its
    /// flank radius would be negative there: interference, the tooth undercut).
    pub fn interferes(&self) -> bool {
        self.undercut().is_some()
    }

    /// The member (0 the pinion, 1 the gear) whose flank the other's tip reaches below its
    /// base circle, if any: the path of contact runs beyond that member's base-circle
    /// tangency point on the line of action (its flank radius `ρ` would be negative there),
    /// so the teeth interfere and a generated tooth is undercut. The pinion (the member with
    /// fewer teeth) meets it first.
    pub fn undercut(&self) -> Option<usize> {
        let [start, end] = self.path_of_contact_m();
        if start <= -self.curvature_radius_at_pitch_point_m(0) {
            Some(0)
        } else if end >= self.curvature_radius_at_pitch_point_m(1) {
            Some(1)
        } else {
            None
        }
    }

    /// The tooth thickness on the tip circle of member `i` (m), for standard teeth (tooth
    /// thickness `π m / 2` on the pitch circle, addendum one module, no profile shift):
    /// `s_a = 2 r_a (π / (2 N) + inv φ - inv φ_a)`, `inv x = tan x - x`, with
    /// `cos φ_a = r_b / r_a`. Zero or negative: the flanks meet below the tip circle, the
    /// tooth is pointed (no tip land).
    ///
    /// ## Reference
    /// The thickness of an involute tooth at radius `r` is `2 r (s / (2 R) + inv φ - inv φ_r)`
    /// for the thickness `s` at the pitch radius `R` (e.g. Shigley's *Mechanical Engineering
    /// Design*, and ISO 21771, the tooth thickness of involute gears); the test checks it
    /// against the flanks traced as involutes.
    pub fn tip_thickness_m(&self, i: usize) -> f64 {
        let involute = |x: f64| x.tan() - x;
        let tip = self.tip_radius_m(i);
        let tip_angle = (self.base_radius_m(i) / tip).acos();
        let n = f64::from(self.teeth[i]);
        2.0 * tip
            * (std::f64::consts::PI / (2.0 * n) + involute(self.pressure_angle_rad)
                - involute(tip_angle))
    }

    /// The flank radii of curvature `[ρ1, ρ2]` at `s`: `ρ1 = r1 sin φ + s`,
    /// `ρ2 = r2 sin φ - s` (each the distance from its base-circle tangency point).
    pub fn flank_radii_m(&self, s: f64) -> [f64; 2] {
        [
            self.curvature_radius_at_pitch_point_m(0) + s,
            self.curvature_radius_at_pitch_point_m(1) - s,
        ]
    }

    /// Pairs of teeth in contact when one pair is at `s`: the pairs a base pitch apart that
    /// lie on the path of contact.
    pub fn pairs_in_contact(&self, s: f64) -> usize {
        let [start, end] = self.path_of_contact_m();
        let pitch = self.base_pitch_m();
        let slack = 1e-12 * pitch;
        let behind = ((s - start + slack) / pitch).floor() as i64;
        let ahead = ((end - s + slack) / pitch).floor() as i64;
        (behind + ahead + 1).max(1) as usize
    }

    /// The speeds `[V1, V2]` at which the contact point at `s` moves over the pinion's and the
    /// gear's flank, `V_i = ω_i ρ_i`, for the pinion turning at `pinion_rad_per_s` (the gear at
    /// `ω2 = ω1 N1 / N2`). Their difference is the sliding speed `(ω1 + ω2) |s|`, zero at the
    /// pitch point.
    ///
    /// ## Reference
    /// The contact point moves along the line of action, normal to the flanks, so over each
    /// flank it moves at the flank's tangential speed, `ω` times the distance from the base
    /// tangency point (e.g. Niemann & Winter, *Maschinenelemente* II, the gear's sliding and
    /// rolling speeds). The test compares with the rigid-body velocities of both gears.
    pub fn flank_speeds_m_per_s(&self, s: f64, pinion_rad_per_s: f64) -> [f64; 2] {
        let [rho1, rho2] = self.flank_radii_m(s);
        let gear_rad_per_s = pinion_rad_per_s * f64::from(self.teeth[0]) / f64::from(self.teeth[1]);
        [pinion_rad_per_s * rho1, gear_rad_per_s * rho2]
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

    fn seed_pair() -> SpurGearPair {
        SpurGearPair {
            module_m: 5e-3,
            teeth: [20, 40],
            pressure_angle_rad: 20f64.to_radians(),
        }
    }

    /// Plane coordinates: the pinion's centre at the origin, the gear's at `(r1 + r2, 0)`, the
    /// pitch point at `(r1, 0)`, the line of action through it at `φ` to the common tangent
    /// (the y axis), `d = (sin φ, cos φ)`.
    fn plane(pair: &SpurGearPair) -> ([f64; 2], [f64; 2], [f64; 2]) {
        let phi = pair.pressure_angle_rad;
        (
            [pair.pitch_radius_m(0), 0.0],
            [phi.sin(), phi.cos()],
            [pair.pitch_radius_m(0) + pair.pitch_radius_m(1), 0.0],
        )
    }

    #[test]
    fn path_of_contact_is_where_the_tip_circles_cross_the_line_of_action() {
        for pair in [
            seed_pair(),
            SpurGearPair {
                module_m: 2e-3,
                teeth: [17, 83],
                pressure_angle_rad: 25f64.to_radians(),
            },
        ] {
            let (p0, d, o2) = plane(&pair);
            // |p0 + s d - centre|² = r_a²: s² + 2 s (p0 - c)·d + |p0 - c|² - r_a² = 0.
            let roots = |centre: [f64; 2], tip: f64| {
                let w = [p0[0] - centre[0], p0[1] - centre[1]];
                let b = w[0] * d[0] + w[1] * d[1];
                let c = w[0] * w[0] + w[1] * w[1] - tip * tip;
                let root = (b * b - c).sqrt();
                (-b - root, -b + root)
            };
            let (_, end) = roots([0.0, 0.0], pair.tip_radius_m(0));
            let (start, _) = roots(o2, pair.tip_radius_m(1));
            let [s0, s1] = pair.path_of_contact_m();
            assert_relative_eq!(s0, start, max_relative = 1e-12);
            assert_relative_eq!(s1, end, max_relative = 1e-12);
            assert!(!pair.interferes());
        }
        // The seed pair: between one and two pairs in contact.
        let pair = seed_pair();
        assert!((1.0..2.0).contains(&pair.contact_ratio()));
        // One pair around the pitch point, two near the ends.
        let [start, end] = pair.path_of_contact_m();
        assert_eq!(pair.pairs_in_contact(0.0), 1);
        assert_eq!(pair.pairs_in_contact(start + 1e-4), 2);
        assert_eq!(pair.pairs_in_contact(end - 1e-4), 2);
        assert_eq!(pair.pairs_in_contact(end - pair.base_pitch_m() - 1e-4), 2);
        assert_eq!(pair.pairs_in_contact(end - pair.base_pitch_m() + 1e-4), 1);
        assert_eq!(pair.pairs_in_contact(start + pair.base_pitch_m() - 1e-4), 1);
        assert_eq!(pair.pairs_in_contact(start + pair.base_pitch_m() + 1e-4), 2);
        // A 12-tooth pinion with a 20 deg rack-like mate is undercut.
        let small = SpurGearPair {
            module_m: 1e-3,
            teeth: [12, 200],
            pressure_angle_rad: 20f64.to_radians(),
        };
        assert!(small.interferes());
    }

    /// The tip thickness against the flanks traced as involutes: the polar angle of the
    /// involute point at roll angle `t`, `(r_b (cos t + t sin t), r_b (sin t - t cos t))`, at
    /// the pitch and the tip radius; and pointed teeth at a pressure angle near 90 deg.
    #[test]
    fn tip_thickness_follows_the_traced_involute() {
        for pair in [
            seed_pair(),
            SpurGearPair {
                module_m: 2e-3,
                teeth: [9, 31],
                pressure_angle_rad: 32f64.to_radians(),
            },
        ] {
            for i in 0..2 {
                let rb = pair.base_radius_m(i);
                let polar = |r: f64| {
                    let t = ((r / rb).powi(2) - 1.0).sqrt();
                    let (x, y) = (rb * (t.cos() + t * t.sin()), rb * (t.sin() - t * t.cos()));
                    y.atan2(x)
                };
                let n = f64::from(pair.teeth[i]);
                let tip = pair.tip_radius_m(i);
                let traced = 2.0
                    * tip
                    * (std::f64::consts::PI / (2.0 * n) + polar(pair.pitch_radius_m(i))
                        - polar(tip));
                assert_relative_eq!(pair.tip_thickness_m(i), traced, max_relative = 1e-9);
            }
        }
        // Standard 20 deg teeth keep a land of about 0.6 to 0.7 module.
        let seed = seed_pair();
        assert!(seed.tip_thickness_m(0) > 0.6 * seed.module_m);
        let steep = SpurGearPair {
            pressure_angle_rad: 89.9f64.to_radians(),
            ..seed
        };
        assert!(steep.tip_thickness_m(0) < 0.0);
        assert!(steep.tip_thickness_m(1) < 0.0);
    }

    #[test]
    fn flank_speeds_are_the_rigid_body_velocities() {
        let pair = seed_pair();
        let (p0, d, o2) = plane(&pair);
        let n = [d[1], -d[0]];
        let w1 = 157.08;
        let w2 = w1 * 20.0 / 40.0;
        let [start, end] = pair.path_of_contact_m();
        for k in 0..=10 {
            let s = start + (end - start) * f64::from(k) / 10.0;
            let p = [p0[0] + s * d[0], p0[1] + s * d[1]];
            // The pinion turns counter-clockwise, the gear clockwise.
            let v1 = [-w1 * p[1], w1 * p[0]];
            let v2 = [w2 * p[1], -w2 * (p[0] - o2[0])];
            let dot = |a: [f64; 2], b: [f64; 2]| a[0] * b[0] + a[1] * b[1];
            // The normal velocities agree (the teeth neither part nor penetrate) ...
            assert_relative_eq!(dot(v1, d), dot(v2, d), max_relative = 1e-12);
            // ... and the contact point moves along d, so the flanks' tangential velocities
            // are the speeds of the contact over them.
            let [speed1, speed2] = pair.flank_speeds_m_per_s(s, w1);
            assert_relative_eq!(
                dot(v1, n).abs(),
                speed1,
                epsilon = 1e-12,
                max_relative = 1e-12
            );
            assert_relative_eq!(
                dot(v2, n).abs(),
                speed2,
                epsilon = 1e-12,
                max_relative = 1e-12
            );
            assert_relative_eq!(
                (dot(v1, n) - dot(v2, n)).abs(),
                (w1 + w2) * s.abs(),
                epsilon = 1e-12
            );
        }
        let [v1, v2] = pair.flank_speeds_m_per_s(0.0, w1);
        assert_relative_eq!(v1, v2, max_relative = 1e-14);
    }
}

//! The density of a lubricant under pressure.

/// How the density changes with pressure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Compressibility {
    /// Dowson & Higginson (1966): `ρ/ρ0 = 1 + 0.6 p / (1 + 1.7 p)`, `p` in GPa; the density
    /// grows by at most 35 %.
    DowsonHigginson,
    /// A constant density.
    Incompressible,
}

impl Compressibility {
    /// `ρ/ρ0` and its derivative with respect to the pressure (1/Pa) at `pressure_pa`
    /// (negative pressures taken as zero).
    ///
    /// ## Reference
    /// D. Dowson & G. R. Higginson, *Elasto-Hydrodynamic Lubrication* (Pergamon, 1966); the
    /// same relation in Hamrock, Schmid & Jacobson, *Fundamentals of Fluid Film Lubrication*
    /// (2004), ch. 4.
    pub fn density_ratio(&self, pressure_pa: f64) -> (f64, f64) {
        match self {
            Compressibility::Incompressible => (1.0, 0.0),
            Compressibility::DowsonHigginson => {
                let p_gpa = pressure_pa.max(0.0) * 1e-9;
                let denominator = 1.0 + 1.7 * p_gpa;
                (
                    1.0 + 0.6 * p_gpa / denominator,
                    0.6e-9 / (denominator * denominator),
                )
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn dowson_higginson_by_hand() {
        let law = Compressibility::DowsonHigginson;
        // 1 GPa: 1 + 0.6 / 2.7 = 1.2222...
        assert_relative_eq!(
            law.density_ratio(1e9).0,
            1.0 + 0.6 / 2.7,
            max_relative = 1e-15
        );
        // The limit 1 + 0.6/1.7 = 1.353 at very high pressure.
        assert_relative_eq!(
            law.density_ratio(1e15).0,
            1.0 + 0.6 / 1.7,
            max_relative = 1e-5
        );
        let (_, slope) = law.density_ratio(5e8);
        let numeric = (law.density_ratio(5e8 + 1e3).0 - law.density_ratio(5e8 - 1e3).0) / 2e3;
        assert_relative_eq!(slope, numeric, max_relative = 1e-7);
        assert_eq!(law.density_ratio(-1e6).0, 1.0);
    }
}

//! The output of `stressfield probe`: the stress at each point as CSV (units of p0).

use std::io::Write;

use crate::solution::Solution;

/// Header of the probe output.
pub const HEADER: &str = "x,y,z,sxx,syy,szz,syz,sxz,sxy,s1,s2,s3,von_mises,max_shear";

/// Writes the header and one row per point ([`Solution::finite_stress_over_p0`]: on a strip
/// or cell edge at the surface of a numerical solution, the mean of the neighbouring centres),
/// every value in shortest round-trip form (17 significant digits at most, exact to the last
/// bit; exponent notation where it is shorter, see [`crate::io::text::number`]).
pub fn write_csv(
    out: &mut impl Write,
    solution: &Solution,
    points: &[[f64; 3]],
) -> std::io::Result<()> {
    writeln!(out, "{HEADER}")?;
    for &[x, y, z] in points {
        let s = solution.finite_stress_over_p0(x, y, z);
        let [s1, s2, s3] = s.principal();
        let values = [
            x,
            y,
            z,
            s.xx,
            s.yy,
            s.zz,
            s.yz,
            s.xz,
            s.xy,
            s1,
            s2,
            s3,
            s.von_mises(),
            s.max_shear(),
        ];
        let row: Vec<String> = values.iter().map(|v| crate::io::text::number(*v)).collect();
        writeln!(out, "{}", row.join(","))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_print_short_and_exact() {
        let solution = Solution::LineHertz {
            friction: 0.0,
            poisson: 0.3,
        };
        let mut out = Vec::new();
        write_csv(&mut out, &solution, &[[1e-5, 0.0, 1e8]]).expect("writes");
        let text = String::from_utf8(out).expect("utf-8");
        let row = text.lines().nth(1).expect("row");
        assert!(row.starts_with("1e-5,0,1e8,"), "{row}");
        for field in row.split(',') {
            assert!(field.len() <= 24, "{field}");
            let value: f64 = field.parse().expect("number");
            assert!(value.is_finite(), "{row}");
        }
    }
}

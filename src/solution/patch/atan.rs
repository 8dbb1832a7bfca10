//! The arc tangent of the corner terms `Tx`, `Ty` of [`super::uniform_patch`], in plain
//! arithmetic (no library call, no branch that the compiler cannot turn into a selection), so
//! that a loop over a row of corners runs on vector registers. The C library's `atan2` took a
//! quarter of the influence coefficients' time (perf, 256² layer).
//!
//! Method (the argument reduction of Sun's fdlibm `s_atan.c`, the polynomial our own):
//! with `r = |y| / x`, `atan r = atan c + atan((r - c) / (1 + c r))` for the nearest of
//! `c = 0, 1/2, 1, 3/2, ∞` (breaks at `r = 7/16, 11/16, 19/16, 39/16`), written with `y` and
//! `x` so that one division gives the reduced argument `t`, `|t| <= 7/16`, and the numerators
//! that cancel are exact (Sterbenz). Then `atan t = t + t³ g(t²)`, where `g` is the
//! Chebyshev interpolant of degree 11 of `(atan √s - √s) / s^{3/2}` on `0 <= s <= (7/16)²`,
//! computed with mpmath (`chebyfit`, 50 digits; its error 3.9e-18 is below the rounding of
//! the result) and evaluated by Estrin's scheme. `atan c` is added in two parts, its double and the rest. Measured against
//! mpmath over 3e5 arguments (uniform, across nine decades, and around every break): at most
//! 1.4 ulp, from the rounding of the division when `t` and the result lie on either side of
//! a power of two (the C library: 0.52 ulp). The tests bound it against `f64::atan2`.
//!
//! Reference: Sun Microsystems, fdlibm 5.3, `s_atan.c` (the reduction; 1993).

/// `atan(1/2)`, `π/4`, `atan(3/2)`, `π/2`: each as its double and the remainder.
const BASE: [(f64, f64); 4] = [
    (0.463_647_609_000_806_1, 2.269_877_745_296_168_7e-17),
    (std::f64::consts::FRAC_PI_4, 3.061_616_997_868_383e-17),
    (0.982_793_723_247_329, 1.390_331_103_123_099_8e-17),
    (std::f64::consts::FRAC_PI_2, 6.123_233_995_736_766e-17),
];

/// `g(s)`, the constant first.
const G: [f64; 12] = [
    -0.333_333_333_333_333_3,
    0.199_999_999_999_994_1,
    -0.142_857_142_855_668_06,
    0.111_111_110_966_450_38,
    -0.090_909_083_556_025_92,
    0.076_922_855_548_892_86,
    -0.066_662_419_233_599_64,
    0.058_769_464_567_550_61,
    -0.052_166_797_393_136_56,
    0.044_922_592_931_936_56,
    -0.033_128_134_256_069_586,
    0.014_773_184_616_983_806,
];

/// `atan2(y, x)` for `x >= 0` (or `+0`): in `[-π/2, π/2]`, with the sign of `y`; `0` (with
/// the sign of `y`) for `y = x = 0`, `±π/2` for `x = 0`. Not for `x < 0`.
#[inline(always)]
pub(crate) fn atan2_right(y: f64, x: f64) -> f64 {
    let ay = y.abs();
    let (num, den, base) = if ay <= 0.4375 * x {
        (ay, x, (0.0, 0.0))
    } else if ay <= 0.6875 * x {
        (2.0 * ay - x, 2.0 * x + ay, BASE[0])
    } else if ay <= 1.1875 * x {
        (ay - x, ay + x, BASE[1])
    } else if ay <= 2.4375 * x {
        (2.0 * ay - 3.0 * x, 2.0 * x + 3.0 * ay, BASE[2])
    } else {
        (-x, ay, BASE[3])
    };
    let t = if den == 0.0 { 0.0 } else { num / den };
    // g(s) by Estrin's scheme: a chain of four multiply-adds, not eleven as by Horner's.
    let s = t * t;
    let s2 = s * s;
    let s4 = s2 * s2;
    let s8 = s4 * s4;
    let pair = |k: usize| G[k] + G[k + 1] * s;
    let (q0, q1, q2) = (
        pair(0) + pair(2) * s2,
        pair(4) + pair(6) * s2,
        pair(8) + pair(10) * s2,
    );
    let g = (q0 + q1 * s4) + q2 * s8;
    (base.0 + (t + (t * s * g + base.1))).copysign(y)
}

/// `y[i] = atan2_right(y[i], x[i])` over a row.
pub(crate) fn atan2_right_in_place(y: &mut [f64], x: &[f64]) {
    for (y, x) in y.iter_mut().zip(x) {
        *y = atan2_right(*y, *x);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A reproducible sequence in `[0, 1)` (xorshift64*).
    fn uniform(state: &mut u64) -> f64 {
        *state ^= *state >> 12;
        *state ^= *state << 25;
        *state ^= *state >> 27;
        (state.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Units in the last place of `v`.
    fn ulp(v: f64) -> f64 {
        let v = v.abs();
        f64::from_bits(v.to_bits() + 1) - v
    }

    #[test]
    fn equals_the_library_atan2_within_two_ulps() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut worst = 0.0f64;
        let breaks = [0.4375, 0.6875, 1.1875, 2.4375, 1.0, 0.5, 1.5];
        for i in 0..400_000 {
            let (y, x) = match i % 3 {
                0 => (2.0 * uniform(&mut state) - 1.0, uniform(&mut state)),
                1 => {
                    let scale = 10f64.powf(-12.0 * uniform(&mut state));
                    let y = (2.0 * uniform(&mut state) - 1.0) * scale;
                    (
                        y,
                        uniform(&mut state) * 10f64.powf(-12.0 * uniform(&mut state)),
                    )
                }
                _ => {
                    let c = breaks[i % breaks.len()];
                    let x = 0.1 + uniform(&mut state);
                    let r = c * (1.0 + 1e-4 * (2.0 * uniform(&mut state) - 1.0));
                    (if i % 2 == 0 { r * x } else { -r * x }, x)
                }
            };
            let (ours, library) = (atan2_right(y, x), y.atan2(x));
            if library != 0.0 {
                worst = worst.max((ours - library).abs() / ulp(library));
            } else {
                assert_eq!(ours, 0.0, "atan2({y:e}, {x:e})");
            }
        }
        // At most 1.4 ulp from the exact value (mpmath), the library's 0.52.
        assert!(worst <= 2.0, "{worst} ulp");
        assert!(worst > 0.0, "not the library function itself");
    }

    #[test]
    fn zeros_and_the_axis_give_the_library_values() {
        for (y, x) in [(0.0, 0.0), (-0.0, 0.0), (1.0, 0.0), (-1.0, 0.0), (0.0, 1.0)] {
            let (ours, library) = (atan2_right(y, x), f64::atan2(y, x));
            assert_eq!(ours.to_bits(), library.to_bits(), "atan2({y}, {x})");
        }
        assert_eq!(atan2_right(5e-324, 1.0), 5e-324);
        assert_eq!(atan2_right(1.0, 5e-324), std::f64::consts::FRAC_PI_2);
        assert!(atan2_right(f64::NAN, 1.0).is_nan());
    }

    #[test]
    fn a_row_equals_one_value_at_a_time() {
        let mut state = 7u64;
        let y: Vec<f64> = (0..37).map(|_| 2.0 * uniform(&mut state) - 1.0).collect();
        let x: Vec<f64> = (0..37).map(|_| uniform(&mut state)).collect();
        let mut row = y.clone();
        atan2_right_in_place(&mut row, &x);
        for ((r, y), x) in row.iter().zip(&y).zip(&x) {
            assert_eq!(r.to_bits(), atan2_right(*y, *x).to_bits());
        }
    }
}

//! The colour scale shared by a group of panels (see `scales.rs`) and by its colour bar.

use colorous::Gradient;

use super::ColorMap;

/// Entries of the lookup table (more than any colour bar is tall).
const LUT_SIZE: usize = 1024;

/// Colour of values that are not finite.
pub(crate) const NAN_COLOR: [u8; 3] = [200, 200, 200];

/// Maps values in `[lo, hi]` to colours of a [`ColorMap`]; values outside are clamped.
#[derive(Clone, Debug)]
pub(crate) struct ColorScale {
    pub lo: f64,
    pub hi: f64,
    lut: Vec<[u8; 3]>,
}

impl ColorScale {
    /// The scale of a figure whose finite values span `[min, max]`: `[min(0, min), max]` for
    /// sequential maps, `[-M, M]` with `M = max |value|` for [`ColorMap::Diverging`].
    pub fn for_range(map: ColorMap, min: f64, max: f64) -> Self {
        let (mut lo, mut hi) = match map {
            ColorMap::Diverging => {
                let m = min.abs().max(max.abs());
                (-m, m)
            }
            _ => (min.min(0.0), max),
        };
        if !(lo.is_finite() && hi.is_finite()) {
            (lo, hi) = (0.0, 1.0);
        }
        if hi <= lo {
            // A constant field: any non-empty range shows it with one colour.
            let pad = if lo == 0.0 { 1.0 } else { lo.abs() };
            if map == ColorMap::Diverging {
                (lo, hi) = (-pad, pad);
            } else {
                hi = lo + pad;
            }
        }
        let lut = (0..LUT_SIZE)
            .map(|i| eval(map, i as f64 / (LUT_SIZE - 1) as f64))
            .collect();
        Self { lo, hi, lut }
    }

    /// Position of `value` along the scale, clamped to `0..=1`.
    pub fn fraction(&self, value: f64) -> f64 {
        ((value - self.lo) / (self.hi - self.lo)).clamp(0.0, 1.0)
    }

    /// The colour of `value`.
    pub fn rgb(&self, value: f64) -> [u8; 3] {
        if !value.is_finite() {
            return NAN_COLOR;
        }
        let index = (self.fraction(value) * (LUT_SIZE - 1) as f64).round() as usize;
        self.lut[index.min(LUT_SIZE - 1)]
    }
}

/// The colour of a colour map at `t` in `0..=1` (diverging: 0 is compression, blue).
pub(crate) fn eval(map: ColorMap, t: f64) -> [u8; 3] {
    let (gradient, t) = gradient(map, t.clamp(0.0, 1.0));
    gradient.eval_continuous(t).as_array()
}

fn gradient(map: ColorMap, t: f64) -> (Gradient, f64) {
    match map {
        ColorMap::Viridis => (colorous::VIRIDIS, t),
        ColorMap::Inferno => (colorous::INFERNO, t),
        ColorMap::Magma => (colorous::MAGMA, t),
        ColorMap::Plasma => (colorous::PLASMA, t),
        ColorMap::Cividis => (colorous::CIVIDIS, t),
        ColorMap::Turbo => (colorous::TURBO, t),
        // RdBu runs from red to blue: reversed, negative (compression) is blue.
        ColorMap::Diverging => (colorous::RED_BLUE, 1.0 - t),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sequential_scales_start_at_zero() {
        let scale = ColorScale::for_range(ColorMap::Viridis, 0.1, 0.3);
        assert_eq!((scale.lo, scale.hi), (0.0, 0.3));
        let scale = ColorScale::for_range(ColorMap::Viridis, -0.2, 0.3);
        assert_eq!((scale.lo, scale.hi), (-0.2, 0.3));
    }

    #[test]
    fn diverging_is_symmetric_blue_for_compression_white_at_zero() {
        let scale = ColorScale::for_range(ColorMap::Diverging, -1.2, 0.6);
        assert_eq!((scale.lo, scale.hi), (-1.2, 1.2));
        let [r, g, b] = scale.rgb(-1.2);
        assert!(b > r && b > g, "compression is blue: {:?}", [r, g, b]);
        let [r, g, b] = scale.rgb(1.2);
        assert!(r > b && r > g, "tension is red: {:?}", [r, g, b]);
        let [r, g, b] = scale.rgb(0.0);
        assert!(
            r > 235 && g > 235 && b > 235,
            "zero is white: {:?}",
            [r, g, b]
        );
    }

    #[test]
    fn constant_fields_get_a_usable_range() {
        let scale = ColorScale::for_range(ColorMap::Magma, 0.0, 0.0);
        assert!(scale.hi > scale.lo);
        let scale = ColorScale::for_range(ColorMap::Diverging, 0.0, 0.0);
        assert_eq!((scale.lo, scale.hi), (-1.0, 1.0));
    }

    #[test]
    fn the_lookup_table_follows_colorous() {
        let scale = ColorScale::for_range(ColorMap::Inferno, 0.0, 2.0);
        for v in [0.0, 0.37, 1.0, 1.81, 2.0] {
            let expected = colorous::INFERNO.eval_continuous(v / 2.0).as_array();
            let got = scale.rgb(v);
            for c in 0..3 {
                assert!(
                    got[c].abs_diff(expected[c]) <= 2,
                    "{v}: {got:?} vs {expected:?}"
                );
            }
        }
        assert_eq!(scale.rgb(f64::NAN), NAN_COLOR);
    }
}

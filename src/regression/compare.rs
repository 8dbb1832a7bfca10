//! Image comparison for regression tests: decoded pixels are compared with a per-channel
//! tolerance and a cap on the number of differing pixels, never PNG bytes (encoders and
//! anti-aliasing may legitimately change a few bits). No file I/O: the caller decodes and writes.

use std::fmt;

use image::{Rgb, RgbImage};

/// How different two images may be and still count as equal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tolerance {
    /// Largest accepted difference of one channel (0..=255) of a pixel.
    pub per_channel: u8,
    /// How many pixels may differ by more than `per_channel` in some channel.
    pub max_differing_pixels: usize,
}

impl Default for Tolerance {
    /// Two levels per channel and no differing pixel.
    fn default() -> Self {
        Self {
            per_channel: 2,
            max_differing_pixels: 0,
        }
    }
}

/// The outcome of [`compare`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Comparison {
    /// Width and height of the actual image.
    pub actual_size: (u32, u32),
    /// Width and height of the expected image.
    pub expected_size: (u32, u32),
    /// Pixels where some channel differs by more than the tolerance (0 when sizes differ).
    pub differing_pixels: usize,
    /// Largest difference of any channel of any pixel (0 when sizes differ).
    pub max_channel_difference: u8,
    /// Root mean square of the channel differences over the whole image, in levels of 255
    /// (see [`rms_difference`]; 0 when sizes differ).
    pub rms: f64,
    /// The tolerance the comparison was made with.
    pub tolerance: Tolerance,
}

impl Comparison {
    /// Whether both images have the same width and height.
    pub fn sizes_match(&self) -> bool {
        self.actual_size == self.expected_size
    }

    /// Sizes match and no more than `tolerance.max_differing_pixels` pixels differ.
    pub fn passed(&self) -> bool {
        self.sizes_match() && self.differing_pixels <= self.tolerance.max_differing_pixels
    }
}

impl fmt::Display for Comparison {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if !self.sizes_match() {
            let (aw, ah) = self.actual_size;
            let (ew, eh) = self.expected_size;
            return write!(f, "size {aw} x {ah} differs from the expected {ew} x {eh}");
        }
        write!(
            f,
            "{} pixel(s) differ by more than {} in some channel (at most {} allowed), largest \
             channel difference {}",
            self.differing_pixels,
            self.tolerance.per_channel,
            self.tolerance.max_differing_pixels,
            self.max_channel_difference
        )
    }
}

/// Compares `actual` with `expected` pixel by pixel.
pub fn compare(actual: &RgbImage, expected: &RgbImage, tolerance: Tolerance) -> Comparison {
    let mut comparison = Comparison {
        actual_size: actual.dimensions(),
        expected_size: expected.dimensions(),
        differing_pixels: 0,
        max_channel_difference: 0,
        rms: 0.0,
        tolerance,
    };
    if !comparison.sizes_match() {
        return comparison;
    }
    comparison.rms = rms_difference(actual, expected);
    for (a, e) in actual.pixels().zip(expected.pixels()) {
        let difference = channel_difference(a, e);
        comparison.max_channel_difference = comparison.max_channel_difference.max(difference);
        if difference > tolerance.per_channel {
            comparison.differing_pixels += 1;
        }
    }
    comparison
}

/// A picture of the differences: the expected image faded to light grey, with every pixel that
/// differs by more than `per_channel` in bright red. Sizes are taken from `expected`; pixels
/// outside `actual` count as differing.
pub fn diff_image(actual: &RgbImage, expected: &RgbImage, per_channel: u8) -> RgbImage {
    const RED: Rgb<u8> = Rgb([255, 0, 0]);
    RgbImage::from_fn(expected.width(), expected.height(), |x, y| {
        let e = expected.get_pixel(x, y);
        let differs = match actual.get_pixel_checked(x, y) {
            Some(a) => channel_difference(a, e) > per_channel,
            None => true,
        };
        if differs {
            RED
        } else {
            let [r, g, b] = e.0;
            let luma = (u32::from(r) * 299 + u32::from(g) * 587 + u32::from(b) * 114) / 1000;
            // Fade towards white so the red stands out: 192..=255.
            let faded = 192 + (luma * 63 / 255) as u8;
            Rgb([faded, faded, faded])
        }
    })
}

/// The root mean square difference of two images of the same size over all pixels and
/// channels, in levels of 255: `sqrt(Σ (a - e)² / (3 w h))`. This is matplotlib's measure for
/// its image comparison tests (`matplotlib.testing.compare.calculate_rms`), which pytest-mpl
/// uses with a default tolerance of 2.
///
/// # Panics
/// If the sizes differ (check [`Comparison::sizes_match`] first).
pub fn rms_difference(actual: &RgbImage, expected: &RgbImage) -> f64 {
    assert_eq!(actual.dimensions(), expected.dimensions(), "image sizes");
    let count = actual.as_raw().len();
    if count == 0 {
        return 0.0;
    }
    let sum: u64 = actual
        .as_raw()
        .iter()
        .zip(expected.as_raw())
        .map(|(a, e)| u64::from(a.abs_diff(*e)).pow(2))
        .sum();
    (sum as f64 / count as f64).sqrt()
}

fn channel_difference(a: &Rgb<u8>, b: &Rgb<u8>) -> u8 {
    a.0.iter()
        .zip(b.0.iter())
        .map(|(x, y)| x.abs_diff(*y))
        .max()
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gradient(width: u32, height: u32) -> RgbImage {
        RgbImage::from_fn(width, height, |x, y| {
            Rgb([(x * 10) as u8, (y * 10) as u8, 128])
        })
    }

    #[test]
    fn identical_images_pass() {
        let image = gradient(8, 6);
        let comparison = compare(
            &image,
            &image,
            Tolerance {
                per_channel: 0,
                max_differing_pixels: 0,
            },
        );
        assert!(comparison.passed());
        assert_eq!(comparison.differing_pixels, 0);
        assert_eq!(comparison.max_channel_difference, 0);
    }

    #[test]
    fn differences_within_the_channel_tolerance_pass() {
        let expected = gradient(8, 6);
        let mut actual = expected.clone();
        actual.get_pixel_mut(3, 2).0[1] += 2;
        let comparison = compare(
            &actual,
            &expected,
            Tolerance {
                per_channel: 2,
                max_differing_pixels: 0,
            },
        );
        assert!(comparison.passed());
        assert_eq!(comparison.max_channel_difference, 2);
        let strict = compare(
            &actual,
            &expected,
            Tolerance {
                per_channel: 1,
                max_differing_pixels: 0,
            },
        );
        assert!(!strict.passed());
        assert_eq!(strict.differing_pixels, 1);
    }

    #[test]
    fn the_pixel_cap_decides() {
        let expected = gradient(8, 6);
        let mut actual = expected.clone();
        for x in 0..3 {
            actual.put_pixel(x, 0, Rgb([255, 255, 255]));
        }
        let tolerance = |cap| Tolerance {
            per_channel: 4,
            max_differing_pixels: cap,
        };
        assert_eq!(
            compare(&actual, &expected, tolerance(3)).differing_pixels,
            3
        );
        assert!(compare(&actual, &expected, tolerance(3)).passed());
        assert!(!compare(&actual, &expected, tolerance(2)).passed());
        assert_eq!(
            compare(&actual, &expected, tolerance(2)).max_channel_difference,
            255
        );
    }

    #[test]
    fn different_sizes_fail_and_say_so() {
        let comparison = compare(
            &gradient(8, 6),
            &gradient(8, 7),
            Tolerance {
                per_channel: 255,
                max_differing_pixels: usize::MAX,
            },
        );
        assert!(!comparison.sizes_match());
        assert!(!comparison.passed());
        assert!(comparison.to_string().contains("8 x 6"), "{comparison}");
    }

    #[test]
    fn diff_image_marks_differing_pixels_red_and_fades_the_rest() {
        let expected = gradient(8, 6);
        let mut actual = expected.clone();
        actual.put_pixel(5, 4, Rgb([0, 0, 0]));
        let diff = diff_image(&actual, &expected, 2);
        assert_eq!(diff.dimensions(), expected.dimensions());
        assert_eq!(*diff.get_pixel(5, 4), Rgb([255, 0, 0]));
        for (x, y, pixel) in diff.enumerate_pixels() {
            if (x, y) != (5, 4) {
                let [r, g, b] = pixel.0;
                assert!(
                    r == g && g == b && r >= 192,
                    "pixel ({x}, {y}) is {:?}",
                    pixel.0
                );
            }
        }
    }

    #[test]
    fn rms_is_the_root_mean_square_of_channel_differences() {
        let expected = gradient(4, 5);
        let mut actual = expected.clone();
        // One channel of one pixel off by 60: sqrt(3600 / 60) = sqrt(60).
        actual.get_pixel_mut(1, 1).0[2] -= 60;
        assert!((rms_difference(&actual, &expected) - 60f64.sqrt()).abs() < 1e-12);
        let comparison = compare(&actual, &expected, Tolerance::default());
        assert!((comparison.rms - 60f64.sqrt()).abs() < 1e-12);
        assert_eq!(rms_difference(&expected, &expected), 0.0);
    }

    #[test]
    fn round_trip_through_png_bytes_compares_equal() {
        let image = gradient(5, 5);
        let mut bytes = Vec::new();
        image::DynamicImage::ImageRgb8(image.clone())
            .write_to(
                &mut std::io::Cursor::new(&mut bytes),
                image::ImageFormat::Png,
            )
            .expect("encode");
        let decoded = image::load_from_memory(&bytes).expect("decode").to_rgb8();
        assert!(compare(&decoded, &image, Tolerance::default()).passed());
    }
}

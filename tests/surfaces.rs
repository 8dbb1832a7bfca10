//! Surfaces: generated maps characterised by the statistics (the generator and the
//! statistics check each other), and the sample files shipped with the scenes.

use stressfield::surface::generate::{generate, Amplitude, Form, Generator, Spectrum};
use stressfield::surface::stats::{characterise, Options};

fn self_affine(n: usize, hurst: f64, seed: u64) -> Generator {
    Generator {
        shape: [n, n],
        spacing_m: [1e-6, 1e-6],
        spectrum: Spectrum::SelfAffine {
            hurst,
            rolloff_wavelength_m: n as f64 * 1e-6 / 4.0,
            cutoff_wavelength_m: 4e-6,
        },
        amplitude: Amplitude::RmsHeight(0.5e-6),
        form: Form::None,
        seed,
    }
}

#[test]
fn the_fitted_hurst_exponent_is_the_generated_one() {
    // 1024², the default band from 4 samples to a quarter of the map (the self-affine range
    // from the roll-off at a quarter to the cutoff at 4 samples); periodic, so no window.
    for (hurst, seed) in [(0.8, 1), (0.5, 2), (0.3, 3)] {
        let map = generate(&self_affine(1024, hurst, seed)).expect("surface");
        let options = Options {
            window: false,
            ..Options::default()
        };
        let c = characterise(&map, &options).expect("statistics");
        let fitted = c.spectra.hurst.expect("band holds rings");
        eprintln!(
            "H = {hurst}: fitted {fitted:.4}, Sq {:.4e}, Ssk {:+.3}, Sku {:.3}",
            c.height.sq, c.height.ssk, c.height.sku
        );
        assert!((fitted - hurst).abs() < 0.05, "H {hurst}: fitted {fitted}");
        // Rms height as generated (0.5 um), less what the mean plane takes of the longest
        // waves (a few percent with the roll-off at a quarter of the map).
        assert!(
            (c.height.sq / 0.5e-6 - 1.0).abs() < 0.05,
            "Sq {}",
            c.height.sq
        );
        // Gaussian heights: with the roll-off at a quarter of the map, one realisation holds
        // about (4 x 4) x a few independent patches per roll-off wavelength, so skewness and
        // kurtosis scatter by a few tenths; 0.3 and 0.6 are about three standard errors.
        assert!(c.height.ssk.abs() < 0.3, "Ssk {}", c.height.ssk);
        assert!((c.height.sku - 3.0).abs() < 0.6, "Sku {}", c.height.sku);
    }
}

//! Makes `scenes/surfaces/worn.asc`, the sample "worn surface" of the lecture notes' homework:
//! a self-affine surface (Hurst 0.8, roll-off 64 um, cutoff 4 um, rms height 0.4 um, seed 7) on
//! 128 x 128 samples 1 um apart, run in: every height above the level that 8 % of the surface
//! exceeds is brought down to a fifth of its excess (plateaus, as left by running-in wear; the
//! heights become negatively skewed), written as a Gwyddion-style ASCII matrix in um.
//!
//! `cargo run --release --example worn_surface` rewrites it identically (the generator is
//! seeded and portable).

use stressfield::surface::generate::{generate, Amplitude, Form, Generator, Spectrum};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let map = generate(&Generator {
        shape: [128, 128],
        spacing_m: [1e-6, 1e-6],
        spectrum: Spectrum::SelfAffine {
            hurst: 0.8,
            rolloff_wavelength_m: 64e-6,
            cutoff_wavelength_m: 4e-6,
        },
        amplitude: Amplitude::RmsHeight(0.4e-6),
        form: Form::None,
        seed: 7,
    })?;
    let mut heights: Vec<f64> = map.heights_m().iter().copied().collect();
    heights.sort_by(f64::total_cmp);
    let level = heights[(heights.len() as f64 * 0.92) as usize];
    let worn = map.heights_m().mapv(|h| {
        if h > level {
            level + 0.2 * (h - level)
        } else {
            h
        }
    });
    let mut text = String::from(
        "# Sample worn surface made by stressfield (cargo run --release --example worn_surface):\n\
         # a self-affine surface (Hurst 0.8, roll-off 64 um, cutoff 4 um, rms 0.4 um, ChaCha8 seed 7)\n\
         # run in: heights above the 92nd percentile cut to a fifth of their excess (plateaus).\n\
         # Channel: Height\n# Width: 128 um\n# Height: 128 um\n# Value units: um\n",
    );
    for row in worn.rows() {
        let line: Vec<String> = row.iter().map(|h| format!("{:.5}", h * 1e6)).collect();
        text.push_str(&line.join(" "));
        text.push('\n');
    }
    std::fs::write("scenes/surfaces/worn.asc", text)?;
    Ok(())
}

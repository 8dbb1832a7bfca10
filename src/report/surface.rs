//! The report of a characterised surface (`stressfield surface`, and `hertz` of a surface
//! scene): a readable table with units, or one JSON object in SI units.
//!
//! JSON keys (the output contract; lengths in m, Sdr a fraction): `Sa`, `Sq`, `Ssk`, `Sku`,
//! `Sp`, `Sv`, `Sz`, `Sdq`, `Sdr`, `Sal`, `Str`, `hurst`, `nayak_alpha`,
//! `summit_density_per_m2`, `summit_radius_m`, `summit_height_std_m`; and also `Ra`, `Rq`,
//! `Rsk`, `Rku`, `fractal_dimension`, `hurst_band_m`, `m0`, `m2`, `m4`, `summits`,
//! `summit_mean_height_m`, the same four from McCool's formulas (`mccool_...`), `levelling`,
//! `plane`, `rows`, `columns`, `spacing_m`, `str_is_upper_bound`, and, when E* (and a
//! hardness) are known, `e_star_pa`, `hardness_pa`, `plasticity_index`, and the homework's
//! highest asperity (`asperity_height_m`, `asperity_radius_m`, `asperity_p0_pa`,
//! `asperity_contact_radius_m`, `asperity_load_n`), and `greenwood_williamson`: the GW model of
//! the measured summits at separations of 3, 2, 1 and 0 summit height deviations above the
//! mean summit height (`separation_m`, `contacts_per_m2`, `area_fraction`, `pressure_pa`).
//! Unknown values, and values that mean nothing (a Hurst exponent outside (0, 1], Rsk and Rku
//! of rows flat to rounding, the Hertz asperity of a tip too flat for the map), are `null`;
//! `null_reasons` says why, one sentence each, as the text's `n/a:` lines do.

use std::f64::consts::PI;
use std::fmt::Write as _;

use serde::Serialize;

use crate::render::table::Row;
use crate::surface::gw::{plasticity_index, plasticity_reading, GreenwoodWilliamson, GwPoint};
use crate::surface::stats::Characterisation;

/// The Hertz sphere-on-flat contact of the highest asperity at an approach of a fifth of its
/// height (the lecture notes' homework): `a = sqrt(R δ)`, `P = (4/3) E* R^½ δ^(3/2)`,
/// `p0 = (2E*/π) sqrt(δ/R)` (Johnson 1985, §4.2).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct AsperityContact {
    pub height_m: f64,
    pub radius_m: f64,
    pub approach_m: f64,
    pub contact_radius_m: f64,
    pub load_n: f64,
    pub p0_pa: f64,
}

impl AsperityContact {
    pub fn new(height_m: f64, radius_m: f64, e_star_pa: f64) -> Self {
        let approach_m = height_m / 5.0;
        Self {
            height_m,
            radius_m,
            approach_m,
            contact_radius_m: (radius_m * approach_m).sqrt(),
            load_n: 4.0 / 3.0 * e_star_pa * radius_m.sqrt() * approach_m.powf(1.5),
            p0_pa: 2.0 * e_star_pa / PI * (approach_m / radius_m).sqrt(),
        }
    }
}

/// The JSON object (see the module doc for the keys).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[allow(non_snake_case)]
pub struct SurfaceReport {
    pub Sa: f64,
    pub Sq: f64,
    pub Ssk: f64,
    pub Sku: f64,
    pub Sp: f64,
    pub Sv: f64,
    pub Sz: f64,
    pub Sdq: f64,
    pub Sdr: f64,
    pub Sal: Option<f64>,
    pub Str: Option<f64>,
    pub str_is_upper_bound: bool,
    pub hurst: Option<f64>,
    pub fractal_dimension: Option<f64>,
    pub hurst_band_m: [f64; 2],
    pub nayak_alpha: f64,
    pub summit_density_per_m2: f64,
    pub summit_radius_m: f64,
    pub summit_height_std_m: f64,
    pub summit_mean_height_m: f64,
    pub summits: usize,
    pub mccool_summit_density_per_m2: f64,
    pub mccool_summit_radius_m: f64,
    pub mccool_summit_height_std_m: f64,
    pub mccool_summit_mean_height_m: f64,
    pub Ra: f64,
    pub Rq: f64,
    pub Rsk: Option<f64>,
    pub Rku: Option<f64>,
    pub m0: f64,
    pub m2: f64,
    pub m4: f64,
    pub levelling: String,
    /// The removed plane `z = c0 + c1 x + c2 y` (m, m/m, m/m).
    pub plane: [f64; 3],
    pub rows: usize,
    pub columns: usize,
    pub spacing_m: [f64; 2],
    pub e_star_pa: Option<f64>,
    pub hardness_pa: Option<f64>,
    pub plasticity_index: Option<f64>,
    pub asperity_height_m: f64,
    pub asperity_radius_m: Option<f64>,
    pub asperity_p0_pa: Option<f64>,
    pub asperity_contact_radius_m: Option<f64>,
    pub asperity_load_n: Option<f64>,
    pub greenwood_williamson: Option<Vec<GwPoint>>,
    /// Why values that could not be had are `null`, one sentence each.
    pub null_reasons: Vec<String>,
}

/// `value` with `decimals`, or `n/a` where it is not a number (a statistic that cannot be had).
fn or_na(value: f64, decimals: usize) -> String {
    if value.is_finite() {
        format!("{value:.decimals$}")
    } else {
        "n/a".to_string()
    }
}

/// How many summit height deviations above the mean summit height the GW rows are given at.
const GW_SEPARATIONS_IN_SIGMA: [f64; 4] = [3.0, 2.0, 1.0, 0.0];

impl SurfaceReport {
    pub fn new(c: &Characterisation, e_star_pa: Option<f64>, hardness_pa: Option<f64>) -> Self {
        let mut null_reasons = Vec::new();
        let mut asperity_radius_m = c.asperity.radius_x_m;
        let side_m = (c.spacing_m[0] * c.shape[1] as f64).min(c.spacing_m[1] * c.shape[0] as f64);
        let asperity = asperity_radius_m
            .zip(e_star_pa)
            .map(|(radius, e)| AsperityContact::new(c.asperity.height_m, radius, e))
            .filter(|contact| {
                let fits = contact.contact_radius_m <= 0.5 * side_m;
                if !fits {
                    null_reasons.push(format!(
                        "asperity: its Hertz contact radius ({} m, for a tip radius of {} m) exceeds half the map's shorter side ({} m): the tip is too flat for a sphere, and the radius, p0, contact radius and load mean nothing",
                        crate::io::text::approx(contact.contact_radius_m),
                        crate::io::text::approx(contact.radius_m),
                        crate::io::text::approx(0.5 * side_m)
                    ));
                    asperity_radius_m = None;
                }
                fits
            });
        if c.spectra.hurst.is_none() {
            let fitted = -c.spectra.fit_slope / 2.0 - 1.0;
            null_reasons.push(if fitted.is_finite() {
                format!("hurst, fractal_dimension: the spectrum's slope over the band gives H = {}, outside (0, 1] (D = {} outside [2, 3)): the surface is not self-affine there; give a band where it is (band in a scene, --band)", crate::io::text::approx(fitted), crate::io::text::approx(3.0 - fitted))
            } else {
                "hurst, fractal_dimension: the band holds fewer than three rings of the spectrum".to_string()
            });
        }
        if c.profile.flat_rows > 0 {
            null_reasons.push(format!(
                "Rsk, Rku: {} of {} rows are flat to rounding (rms residual at most 1e-10 of their heights): their skewness and kurtosis would be those of the noise",
                c.profile.flat_rows, c.shape[0]
            ));
        }
        // Without a summit the measured summit statistics are averages of nothing.
        let summit = |v: f64| if c.summits.count > 0 { v } else { f64::NAN };
        if c.summits.count == 0 {
            null_reasons.push("summit_radius_m, summit_height_std_m, summit_mean_height_m, plasticity_index: the map has no summit (no sample above its 8 neighbours), so there is nothing to average".to_string());
        }
        let (q0, q1) = c.spectra.band_q;
        let greenwood_williamson = e_star_pa
            .filter(|_| c.summits.count > 0 && c.summits.height_std_m > 0.0)
            .map(|e_star_pa| {
                let model = GreenwoodWilliamson {
                    density_per_m2: c.summits.density_per_m2,
                    radius_m: c.summits.radius_m,
                    height_std_m: c.summits.height_std_m,
                    mean_height_m: c.summits.mean_height_m,
                    e_star_pa,
                };
                GW_SEPARATIONS_IN_SIGMA
                    .iter()
                    .map(|k| model.at(model.mean_height_m + k * model.height_std_m))
                    .collect()
            });
        Self {
            Sa: c.height.sa,
            Sq: c.height.sq,
            Ssk: c.height.ssk,
            Sku: c.height.sku,
            Sp: c.height.sp,
            Sv: c.height.sv,
            Sz: c.height.sz,
            Sdq: c.sdq,
            Sdr: c.sdr,
            Sal: c.spatial.sal_m,
            Str: c.spatial.str_ratio,
            str_is_upper_bound: c.spatial.str_bounded,
            hurst: c.spectra.hurst,
            fractal_dimension: c.spectra.fractal_dimension,
            hurst_band_m: [2.0 * PI / q1, 2.0 * PI / q0],
            nayak_alpha: c.moments.nayak_alpha,
            summit_density_per_m2: c.summits.density_per_m2,
            summit_radius_m: summit(c.summits.radius_m),
            summit_height_std_m: summit(c.summits.height_std_m),
            summit_mean_height_m: summit(c.summits.mean_height_m),
            summits: c.summits.count,
            mccool_summit_density_per_m2: c.mccool.density_per_m2,
            mccool_summit_radius_m: c.mccool.radius_m,
            mccool_summit_height_std_m: c.mccool.height_std_m,
            mccool_summit_mean_height_m: c.mccool.mean_height_m,
            Ra: c.profile.ra,
            Rq: c.profile.rq,
            Rsk: c.profile.rsk,
            Rku: c.profile.rku,
            m0: c.moments.m0,
            m2: c.moments.m2,
            m4: c.moments.m4,
            levelling: c.options.form.describe().to_string(),
            plane: c.plane,
            rows: c.shape[0],
            columns: c.shape[1],
            spacing_m: c.spacing_m,
            e_star_pa,
            hardness_pa,
            plasticity_index: e_star_pa
                .zip(hardness_pa)
                .map(|(e, h)| plasticity_index(e, h, c.summits.height_std_m, c.summits.radius_m).0)
                .filter(|psi| psi.is_finite() && c.summits.count > 0),
            asperity_height_m: c.asperity.height_m,
            asperity_radius_m,
            asperity_p0_pa: asperity.map(|a| a.p0_pa),
            asperity_contact_radius_m: asperity.map(|a| a.contact_radius_m),
            asperity_load_n: asperity.map(|a| a.load_n),
            greenwood_williamson,
            null_reasons,
        }
    }

    pub fn json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// The main values as the rows of a sheet's table (lengths in µm).
    pub fn table_rows(&self) -> Vec<Row> {
        let um = |m: f64| m * 1e6;
        let value = |symbol: &str, value: String, meaning: &str| {
            Row::Value(symbol.into(), value, meaning.into())
        };
        let optional = |v: Option<f64>, f: &dyn Fn(f64) -> String| v.map_or("n/a".into(), f);
        let mut rows = vec![
            Row::Heading(format!("Height (ISO 25178-2), {}", self.levelling)),
            value(
                "Sa",
                format!("{:.4} µm", um(self.Sa)),
                "arithmetic mean height",
            ),
            value(
                "Sq",
                format!("{:.4} µm", um(self.Sq)),
                "root mean square height",
            ),
            value("Ssk", format!("{:.3}", self.Ssk), "skewness"),
            value("Sku", format!("{:.3}", self.Sku), "kurtosis"),
            value("Sp", format!("{:.4} µm", um(self.Sp)), "highest peak"),
            value("Sv", format!("{:.4} µm", um(self.Sv)), "deepest valley"),
            value("Sz", format!("{:.4} µm", um(self.Sz)), "maximum height"),
            Row::Heading("Hybrid and spatial".into()),
            value("Sdq", format!("{:.4}", self.Sdq), "rms gradient"),
            value(
                "Sdr",
                format!("{:.3} %", 100.0 * self.Sdr),
                "developed area ratio",
            ),
            value(
                "Sal",
                optional(self.Sal, &|v| format!("{:.2} µm", um(v))),
                "autocorrelation length (0.2)",
            ),
            value(
                "Str",
                optional(self.Str, &|v| {
                    format!("{}{v:.3}", if self.str_is_upper_bound { "≤ " } else { "" })
                }),
                "texture aspect ratio",
            ),
            Row::Heading(format!(
                "Spectrum (fit over {:.3}–{:.1} µm)",
                um(self.hurst_band_m[0]),
                um(self.hurst_band_m[1])
            )),
            value(
                "H",
                optional(self.hurst, &|v| format!("{v:.3}")),
                "Hurst exponent",
            ),
            value(
                "D",
                optional(self.fractal_dimension, &|v| format!("{v:.3}")),
                "fractal dimension 3 − H",
            ),
            value("α", format!("{:.2}", self.nayak_alpha), "Nayak's bandwidth"),
            Row::Heading("Summits: measured | McCool (spectral)".into()),
            value(
                "η",
                format!(
                    "{:.0} | {:.0} /mm²",
                    self.summit_density_per_m2 * 1e-6,
                    self.mccool_summit_density_per_m2 * 1e-6
                ),
                "summit density",
            ),
            value(
                "β",
                format!(
                    "{} | {:.1} µm",
                    or_na(um(self.summit_radius_m), 1),
                    um(self.mccool_summit_radius_m)
                ),
                "mean tip radius",
            ),
            value(
                "σs",
                format!(
                    "{} | {:.3} µm",
                    or_na(um(self.summit_height_std_m), 3),
                    um(self.mccool_summit_height_std_m)
                ),
                "summit height spread",
            ),
        ];
        if let Some(psi) = self.plasticity_index {
            rows.push(value(
                "ψ",
                format!("{psi:.2}"),
                &format!(
                    "plasticity index: {}",
                    plasticity_reading(psi)
                        .split(':')
                        .next()
                        .unwrap_or_default()
                ),
            ));
        }
        rows.push(Row::Heading(
            "Highest asperity, pressed on the counter-body (Hertz)".into(),
        ));
        rows.push(value(
            "h",
            format!("{:.4} µm", um(self.asperity_height_m)),
            "above the mean plane",
        ));
        rows.push(value(
            "R",
            optional(self.asperity_radius_m, &|v| format!("{:.1} µm", um(v))),
            "tip radius along x",
        ));
        if let (Some(p0), Some(a)) = (self.asperity_p0_pa, self.asperity_contact_radius_m) {
            rows.push(value(
                "p0",
                format!("{:.0} MPa", p0 * 1e-6),
                &format!("Hertz at δ = h/5, a = {:.2} µm", um(a)),
            ));
        }
        rows
    }

    /// The readable table with units.
    pub fn text(&self, c: &Characterisation, source: &str) -> String {
        let mut out = String::new();
        let _ = self.write_text(&mut out, c, source);
        out
    }

    fn write_text(&self, out: &mut String, c: &Characterisation, source: &str) -> std::fmt::Result {
        let um = |m: f64| m * 1e6;
        let optional =
            |v: Option<f64>, f: &dyn Fn(f64) -> String| v.map_or_else(|| "n/a".to_string(), f);
        writeln!(
            out,
            "surface {source}: {} x {} samples, spacing {:.4} x {:.4} µm ({:.1} x {:.1} µm)",
            self.columns,
            self.rows,
            um(self.spacing_m[0]),
            um(self.spacing_m[1]),
            um(self.spacing_m[0] * self.columns as f64),
            um(self.spacing_m[1] * self.rows as f64)
        )?;
        writeln!(
            out,
            "levelling: {} (plane z = {:.4e} m {:+.4e} x {:+.4e} y)",
            self.levelling, self.plane[0], self.plane[1], self.plane[2]
        )?;
        writeln!(out)?;
        writeln!(out, "height (ISO 25178-2)")?;
        writeln!(
            out,
            "  Sa  {:>12.5} µm     arithmetic mean height",
            um(self.Sa)
        )?;
        writeln!(
            out,
            "  Sq  {:>12.5} µm     root mean square height",
            um(self.Sq)
        )?;
        writeln!(out, "  Ssk {:>12.4}        skewness", self.Ssk)?;
        writeln!(out, "  Sku {:>12.4}        kurtosis", self.Sku)?;
        writeln!(out, "  Sp  {:>12.5} µm     highest peak", um(self.Sp))?;
        writeln!(out, "  Sv  {:>12.5} µm     deepest valley", um(self.Sv))?;
        writeln!(out, "  Sz  {:>12.5} µm     maximum height", um(self.Sz))?;
        writeln!(out, "hybrid")?;
        writeln!(
            out,
            "  Sdq {:>12.5}        root mean square gradient",
            self.Sdq
        )?;
        writeln!(
            out,
            "  Sdr {:>12.5} %      developed interfacial area ratio",
            100.0 * self.Sdr
        )?;
        writeln!(out, "spatial (autocorrelation threshold 0.2)")?;
        writeln!(
            out,
            "  Sal {:>12} µm     autocorrelation length",
            optional(self.Sal, &|v| format!("{:.4}", um(v)))
        )?;
        writeln!(
            out,
            "  Str {:>12}        texture aspect ratio{}",
            optional(self.Str, &|v| format!("{v:.4}")),
            if self.str_is_upper_bound {
                " (upper bound: the correlation stays above 0.2 within half the map in some direction)"
            } else {
                ""
            }
        )?;
        writeln!(
            out,
            "profile along x (ISO 4287, each row's mean line removed, mean of rows)"
        )?;
        writeln!(
            out,
            "  Ra {:.5} µm, Rq {:.5} µm, Rsk {}, Rku {}",
            um(self.Ra),
            um(self.Rq),
            optional(self.Rsk, &|v| format!("{v:.4}")),
            optional(self.Rku, &|v| format!("{v:.4}"))
        )?;
        writeln!(out, "spectrum")?;
        writeln!(
            out,
            "  Hurst exponent H {}   fractal dimension D = 3 - H {}   (fit over wavelengths {:.3} .. {:.3} µm)",
            optional(self.hurst, &|v| format!("{v:.4}")),
            optional(self.fractal_dimension, &|v| format!("{v:.4}")),
            um(self.hurst_band_m[0]),
            um(self.hurst_band_m[1])
        )?;
        writeln!(
            out,
            "  moments m0 {:.4e} m², m2 {:.4e}, m4 {:.4e} 1/m²; Nayak's alpha {:.3}",
            self.m0, self.m2, self.m4, self.nayak_alpha
        )?;
        writeln!(
            out,
            "summits (8 neighbours)           measured        McCool (spectral)"
        )?;
        writeln!(
            out,
            "  density (1/mm²)             {:>12.2}    {:>12.2}",
            self.summit_density_per_m2 * 1e-6,
            self.mccool_summit_density_per_m2 * 1e-6
        )?;
        writeln!(
            out,
            "  mean tip radius (µm)        {:>12}    {:>12.3}",
            or_na(um(self.summit_radius_m), 3),
            um(self.mccool_summit_radius_m)
        )?;
        writeln!(
            out,
            "  summit height std (µm)      {:>12}    {:>12.5}",
            or_na(um(self.summit_height_std_m), 5),
            um(self.mccool_summit_height_std_m)
        )?;
        writeln!(
            out,
            "  mean summit height (µm)     {:>12}    {:>12.5}",
            or_na(um(self.summit_mean_height_m), 5),
            um(self.mccool_summit_mean_height_m)
        )?;
        writeln!(out, "  ({} summits)", self.summits)?;
        if let Some(psi) = self.plasticity_index {
            writeln!(
                out,
                "plasticity index psi = (E*/H) sqrt(sigma_s/beta) = {psi:.3}: {}",
                plasticity_reading(psi)
            )?;
        }
        if let Some(points) = &self.greenwood_williamson {
            writeln!(
                out,
                "Greenwood-Williamson (measured summits, E* = {:.1} GPa)",
                self.e_star_pa.unwrap_or(f64::NAN) * 1e-9
            )?;
            writeln!(
                out,
                "  separation (µm)   contacts (1/mm²)   real area (%)   mean pressure (MPa)"
            )?;
            for (point, k) in points.iter().zip(GW_SEPARATIONS_IN_SIGMA) {
                writeln!(
                    out,
                    "  {:>8.4} (zs+{k:.0}σs) {:>12.3}   {:>13}   {:>19}",
                    um(point.separation_m),
                    point.contacts_per_m2 * 1e-6,
                    crate::io::text::approx(100.0 * point.area_fraction),
                    crate::io::text::approx(point.pressure_pa * 1e-6)
                )?;
            }
        }
        let [row, column] = c.asperity.at;
        writeln!(
            out,
            "highest asperity: row {row}, column {column}, {:.4} µm above the mean plane; tip radius {} µm along x, {} µm along y",
            um(self.asperity_height_m),
            optional(self.asperity_radius_m, &|v| format!("{:.3}", um(v))),
            optional(c.asperity.radius_y_m, &|v| format!("{:.3}", um(v)))
        )?;
        if let (Some(p0), Some(a), Some(load)) = (
            self.asperity_p0_pa,
            self.asperity_contact_radius_m,
            self.asperity_load_n,
        ) {
            writeln!(
                out,
                "  as a Hertz sphere on a flat at an approach of h/5 = {:.4} µm: p0 = {:.1} MPa, a = {:.4} µm, load {:.4e} N",
                um(self.asperity_height_m / 5.0),
                p0 * 1e-6,
                um(a),
                load
            )?;
        }
        for reason in &self.null_reasons {
            writeln!(out, "n/a: {reason}")?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn homework_hertz_numbers() {
        // Johnson §4.2: δ = a²/R, p0 = 3P/(2πa²).
        let contact = AsperityContact::new(1e-6, 20e-6, 115e9);
        assert!(
            (contact.contact_radius_m.powi(2) / 20e-6 / contact.approach_m - 1.0).abs() < 1e-12
        );
        let p0 = 3.0 * contact.load_n / (2.0 * PI * contact.contact_radius_m.powi(2));
        assert!((contact.p0_pa / p0 - 1.0).abs() < 1e-12);
    }
}

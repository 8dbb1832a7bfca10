//! The sheet of a surface scene: the topography (µm, the highest asperity marked), the profile
//! along x through the highest asperity with its finite-difference tip circle, the height
//! histogram against the Gaussian of the same Sq, the power spectra with the Hurst fit and its
//! band, the autocorrelation along x and y with the 0.2 threshold, and the
//! Greenwood–Williamson curves (see [`crate::surface::gw`]).

use std::f64::consts::PI;

use super::rough::{gw_model, map_axes_um, xy_map, SheetError};
use crate::render::chart::{Cell, Chart, Scale as ChartScale, Series, Sheet, Style, PALETTE};
use crate::render::table::Table;
use crate::render::{ColorMap, Mark};
use crate::report::surface::SurfaceReport;
use crate::scene::Scene;
use crate::study::map_roll::Roll;
use crate::surface::stats::{self, Characterisation};

/// The surface scene's sheet of its characterisation `c` (by
/// [`crate::study::surface::characterise`]).
pub fn surface_sheet(scene: &Scene, c: &Characterisation) -> Result<Sheet, SheetError> {
    let surface = scene.surface.as_ref().ok_or(SheetError::NoSurface)?;
    let (levelled, _) = stats::level(&surface.body1, c.options.form);
    // The highest asperity circled (a summit off the edges: its ring lies inside the map).
    let [row, column] = c.asperity.at;
    let (cx, cy) = (
        (column as f64 + 0.5) * c.spacing_m[0] * 1e6,
        (row as f64 + 0.5) * c.spacing_m[1] * 1e6,
    );
    let ring = 3.0 * c.spacing_m[0].max(c.spacing_m[1]) * 1e6;
    let circle = (0..=48)
        .map(|k| {
            let t = 2.0 * PI * k as f64 / 48.0;
            (cx + ring * t.cos(), cy + ring * t.sin())
        })
        .collect();
    let mut topography = xy_map(
        "Topography",
        &format!(
            "{}; {}; circle: highest asperity",
            surface.source,
            c.options.form.describe()
        ),
        map_axes_um(&surface.body1, Roll::NONE),
        levelled.mapv(|h| h * 1e6),
        "height (µm)",
        ColorMap::Viridis,
        vec![circle],
    );
    topography.mark = Mark::None;
    let um = 1e6;
    // Profile through the highest asperity, with the tip circle of radius R (drawn exactly,
    // in the exaggerated vertical scale of the chart).
    let mut profile = Chart::new(
        &format!(
            "Profile along x through the highest asperity (row {})",
            c.asperity.at[0]
        ),
        "x (µm)",
        "height (µm)",
    );
    profile.series.push(Series {
        label: "profile".into(),
        points: c
            .asperity
            .profile_x
            .iter()
            .map(|&(x, z)| (x * um, z * um))
            .collect(),
        style: Style::Line,
        colour: PALETTE[0],
    });
    if let Some(radius) = c.asperity.radius_x_m {
        let x0 = c.asperity.at[1] as f64 * c.spacing_m[0];
        let z0 = c.asperity.height_m - radius;
        let reach = (radius * 0.999).min(12.0 * c.spacing_m[0]);
        let circle = (0..=80)
            .map(|k| {
                let x = -reach + 2.0 * reach * k as f64 / 80.0;
                ((x0 + x) * um, (z0 + (radius * radius - x * x).sqrt()) * um)
            })
            .collect();
        profile.series.push(Series {
            label: format!("tip circle R = {:.1} µm", radius * um),
            points: circle,
            style: Style::Dashed,
            colour: PALETTE[1],
        });
    }
    let mut histogram = Chart::new(
        "Height distribution",
        "height (µm)",
        "probability density (1/µm)",
    );
    histogram.series.push(Series {
        label: "measured".into(),
        points: c.histogram.iter().map(|&(h, d)| (h * um, d / um)).collect(),
        style: Style::Bars,
        colour: PALETTE[0],
    });
    let sq = c.height.sq;
    histogram.series.push(Series {
        label: format!("Gaussian, Sq = {:.3} µm", sq * um),
        points: (0..=120)
            .map(|k| {
                let h = -4.0 * sq + 8.0 * sq * k as f64 / 120.0;
                (
                    h * um,
                    (-0.5 * (h / sq).powi(2)).exp() / (sq * (2.0 * PI).sqrt()) / um,
                )
            })
            .collect(),
        style: Style::Line,
        colour: PALETTE[1],
    });
    let mut psd = Chart::log_log(
        "Power spectral density",
        "wavenumber q (rad/µm)",
        "C (µm⁴), C1D (µm³)",
    );
    // Rings whose power is numerically zero (beyond a generated spectrum's cutoff: rounding
    // noise, 1e-12 of the largest or less) would stretch the log axis over 20 decades.
    let visible = |points: &[(f64, f64)]| {
        let largest = points.iter().map(|p| p.1).fold(0.0, f64::max);
        move |&&(_, v): &&(f64, f64)| v > 1e-12 * largest
    };
    psd.series.push(Series {
        label: "radially averaged 2-D".into(),
        points: c
            .spectra
            .radial
            .iter()
            .filter(visible(&c.spectra.radial))
            .map(|&(q, v)| (q / um, v * um.powi(4)))
            .collect(),
        style: Style::Markers,
        colour: PALETTE[0],
    });
    psd.series.push(Series {
        label: "1-D along x".into(),
        points: c
            .spectra
            .profile
            .iter()
            .filter(visible(&c.spectra.profile))
            .map(|&(q, v)| (q / um, v * um.powi(3)))
            .collect(),
        style: Style::Line,
        colour: PALETTE[2],
    });
    let (q0, q1) = c.spectra.band_q;
    if let Some(hurst) = c.spectra.hurst {
        let line = |q: f64| 10f64.powf(c.spectra.fit_intercept + c.spectra.fit_slope * q.log10());
        psd.series.push(Series {
            label: format!("fit C ∝ q^(−2(1+H)), H = {hurst:.3}"),
            points: vec![
                (q0 / um, line(q0) * um.powi(4)),
                (q1 / um, line(q1) * um.powi(4)),
            ],
            style: Style::Dashed,
            colour: PALETTE[1],
        });
    }
    // A slope that gives no Hurst exponent (outside (0, 1]: not self-affine over the band) is
    // drawn as what it is, with the caveat, rather than left unexplained.
    let fitted = -c.spectra.fit_slope / 2.0 - 1.0;
    if c.spectra.hurst.is_none() && fitted.is_finite() && q1 > q0 {
        let line = |q: f64| 10f64.powf(c.spectra.fit_intercept + c.spectra.fit_slope * q.log10());
        psd.series.push(Series {
            label: format!(
                "slope: H = {} outside (0, 1]: not self-affine",
                crate::io::text::approx((fitted * 1e3).round() / 1e3),
            ),
            points: vec![
                (q0 / um, line(q0) * um.powi(4)),
                (q1 / um, line(q1) * um.powi(4)),
            ],
            style: Style::Dashed,
            colour: PALETTE[3],
        });
    }
    psd.x_band = Some((q0 / um, q1 / um));
    let mut acf = Chart::new("Autocorrelation", "lag (µm)", "ACF");
    acf.series.push(Series {
        label: "along x".into(),
        points: c.acf_x.iter().map(|&(l, v)| (l * um, v)).collect(),
        style: Style::Line,
        colour: PALETTE[0],
    });
    acf.series.push(Series {
        label: "along y".into(),
        points: c.acf_y.iter().map(|&(l, v)| (l * um, v)).collect(),
        style: Style::Dashed,
        colour: PALETTE[2],
    });
    acf.hlines.push((
        0.2,
        format!(
            "0.2: Sal = {}",
            c.spatial
                .sal_m
                .map_or("n/a".into(), |s| format!("{:.2} µm", s * um))
        ),
    ));
    let rough = scene.contact.rough;
    let report = SurfaceReport::new(
        c,
        rough.and_then(|r| r.e_star_pa),
        rough.and_then(|r| r.hardness_pa),
    );
    let table = Table {
        title: "Parameters".into(),
        rows: report.table_rows(),
        width_px: 520,
        height_px: 560,
    };
    let mut rows = vec![
        vec![
            Cell::Map(topography),
            Cell::Chart(profile),
            Cell::Table(table),
        ],
        vec![Cell::Chart(histogram), Cell::Chart(psd), Cell::Chart(acf)],
    ];
    if let Some(e_star) = rough.and_then(|r| r.e_star_pa) {
        let gw = gw_model(c, e_star);
        let curves = gw.curves(60);
        let mut separation = Chart::new(
            "Greenwood–Williamson model",
            "separation d / σs",
            "A/A0, n/N, p/E*",
        );
        separation.y_scale = ChartScale::Log;
        let s = gw.height_std_m;
        let x = |d: f64| d / s;
        separation.series.push(Series {
            label: "real area A/A0".into(),
            points: curves
                .iter()
                .map(|p| (x(p.separation_m), p.area_fraction))
                .collect(),
            style: Style::Line,
            colour: PALETTE[0],
        });
        separation.series.push(Series {
            label: "contacts n/N".into(),
            points: curves
                .iter()
                .map(|p| (x(p.separation_m), p.contacts_per_m2 / gw.density_per_m2))
                .collect(),
            style: Style::Dashed,
            colour: PALETTE[2],
        });
        separation.series.push(Series {
            label: "load p/E*".into(),
            points: curves
                .iter()
                .map(|p| (x(p.separation_m), p.pressure_pa / e_star))
                .collect(),
            style: Style::Line,
            colour: PALETTE[1],
        });
        let mut area = Chart::log_log(
            "Real area against load (GW)",
            "mean pressure p / E*",
            "real area A/A0",
        );
        area.series.push(Series {
            label: "Greenwood–Williamson".into(),
            points: curves
                .iter()
                .map(|p| (p.pressure_pa / e_star, p.area_fraction))
                .collect(),
            style: Style::Line,
            colour: PALETTE[0],
        });
        let kappa = (8.0 / PI).sqrt();
        area.series.push(Series {
            label: format!("κ p/(E* h'rms), κ = {kappa:.2}"),
            points: curves
                .iter()
                .map(|p| {
                    (
                        p.pressure_pa / e_star,
                        kappa * p.pressure_pa / (e_star * c.sdq),
                    )
                })
                .filter(|p| p.1 < 1.0)
                .collect(),
            style: Style::Dashed,
            colour: PALETTE[1],
        });
        rows.push(vec![Cell::Chart(separation), Cell::Chart(area)]);
    }
    Ok(Sheet {
        notes: Vec::new(),
        title: scene
            .title
            .clone()
            .unwrap_or_else(|| format!("Rough surface: {}", surface.source)),
        rows,
    })
}

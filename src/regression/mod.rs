//! Regression runs: what `render --compare` found for each scene (image and field checks), the
//! one-line verdicts a CI log shows, and the self-contained HTML report (`--report DIR`).
//!
//! No file I/O here: the caller renders, reads the references, writes the report.
//! [`compare`] compares images, [`field_file`] saves and compares fields.

pub mod compare;
pub mod field_file;

use std::fmt::Write as _;

use base64::Engine as _;

use crate::regression::compare::{Comparison, Tolerance};

/// How two images are judged equal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ImageMeasure {
    /// Per-channel tolerance and a budget of differing pixels ([`Tolerance`]).
    Pixels(Tolerance),
    /// The root mean square channel difference (levels of 255) at most `max`, matplotlib's
    /// measure ([`crate::regression::compare::rms_difference`]).
    Rms { max: f64 },
}

impl ImageMeasure {
    /// The per-channel tolerance of the diff image: the measure's own, or (for RMS) 0, so the
    /// diff shows every changed pixel.
    pub fn diff_threshold(&self) -> u8 {
        match self {
            ImageMeasure::Pixels(tolerance) => tolerance.per_channel,
            ImageMeasure::Rms { .. } => 0,
        }
    }

    /// The tolerance in words, e.g. "RMS <= 2" or "channel diff <= 16, <= 0 pixels".
    pub fn describe(&self) -> String {
        match self {
            ImageMeasure::Pixels(t) => format!(
                "per-channel difference <= {}, at most {} differing pixel(s)",
                t.per_channel, t.max_differing_pixels
            ),
            ImageMeasure::Rms { max } => format!("RMS difference <= {max}"),
        }
    }
}

/// The image check of one scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImageCheck {
    pub comparison: Comparison,
    pub measure: ImageMeasure,
}

impl ImageCheck {
    pub fn passed(&self) -> bool {
        let c = &self.comparison;
        match self.measure {
            ImageMeasure::Pixels(_) => c.passed(),
            ImageMeasure::Rms { max } => c.sizes_match() && c.rms <= max,
        }
    }

    /// The measure found, e.g. "RMS 3.41 (limit 2)" or "132 pixels differ by > 16 (limit 0),
    /// RMS 0.84".
    pub fn summary(&self) -> String {
        let c = &self.comparison;
        if !c.sizes_match() {
            return c.to_string();
        }
        match self.measure {
            ImageMeasure::Pixels(t) => format!(
                "{} pixel(s) differ by more than {} (limit {}), largest channel difference {}, RMS {:.3}",
                c.differing_pixels, t.per_channel, t.max_differing_pixels, c.max_channel_difference, c.rms
            ),
            ImageMeasure::Rms { max } => format!(
                "RMS {:.3} (limit {max}), {} pixel(s) differ, largest channel difference {}",
                c.rms, c.differing_pixels, c.max_channel_difference
            ),
        }
    }
}

/// The largest difference between a panel's field and its reference.
#[derive(Clone, Debug, PartialEq)]
pub struct FieldDifference {
    /// Panel index (0 = left).
    pub panel: usize,
    /// Largest |actual - reference| over the grid, in the figure's stress unit.
    pub largest: f64,
    /// Where it is: horizontal and vertical coordinates in the figure's length unit.
    pub at: (f64, f64),
}

/// The field check of one scene: its panels against the saved reference fields.
#[derive(Clone, Debug, PartialEq)]
pub struct FieldCheck {
    /// Absolute tolerance in the figure's stress unit.
    pub tolerance: f64,
    /// The stress unit's label, e.g. "p0" or "MPa".
    pub unit: String,
    /// The labels of the horizontal and vertical coordinates with their unit, e.g. "x/a" and
    /// "z/a", or "x (mm)" and "z (mm)".
    pub axes: [String; 2],
    /// The panel with the largest difference (`None` when shapes or panel counts differ: see
    /// `mismatch`).
    pub largest: Option<FieldDifference>,
    /// Why the fields could not be compared value by value (different grid, panel count).
    pub mismatch: Option<String>,
}

impl FieldCheck {
    pub fn passed(&self) -> bool {
        self.mismatch.is_none()
            && self
                .largest
                .as_ref()
                .is_none_or(|d| d.largest <= self.tolerance)
    }

    /// e.g. "field: largest difference 2.1e-3 p0 in panel 1 at x/a = 0.52, z/a = 0.48 (limit
    /// 1e-3 p0)".
    pub fn summary(&self) -> String {
        if let Some(why) = &self.mismatch {
            return format!("field: {why}");
        }
        match &self.largest {
            // Nothing differs: no place to name.
            Some(d) if d.largest == 0.0 => format!(
                "field: largest difference 0 {} (limit {} {})",
                self.unit,
                short(self.tolerance),
                self.unit
            ),
            Some(d) => format!(
                "field: largest difference {} {} in panel {} at {} = {}, {} = {} (limit {} {})",
                short(d.largest),
                self.unit,
                d.panel,
                self.axes[0],
                short(d.at.0),
                self.axes[1],
                short(d.at.1),
                short(self.tolerance),
                self.unit
            ),
            None => "field: no values".to_string(),
        }
    }
}

/// A number in at most four significant digits, trailing zeros dropped, in exponent form when
/// that is shorter: 0.0025, 0.48, 1235, 1e-3, 9.999e-4, 3.2e9.
fn short(value: f64) -> String {
    if value == 0.0 || !value.is_finite() {
        return format!("{value}");
    }
    let trim = |digits: &str| -> String {
        if digits.contains('.') {
            digits
                .trim_end_matches('0')
                .trim_end_matches('.')
                .to_string()
        } else {
            digits.to_string()
        }
    };
    let scientific = format!("{value:.3e}");
    let exponent = match scientific.split_once('e') {
        Some((mantissa, power)) => format!("{}e{power}", trim(mantissa)),
        None => scientific,
    };
    let magnitude = value.abs().log10().floor();
    if (-4.0..6.0).contains(&magnitude) {
        let decimals = (3.0 - magnitude).max(0.0) as usize;
        let plain = trim(&format!("{value:.decimals$}"));
        if plain.len() <= exponent.len() {
            return plain;
        }
    }
    exponent
}

/// What happened to a scene in a comparison run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Image (and field, if compared) within tolerance.
    Passed,
    /// Outside tolerance, or the reference is missing or unreadable.
    Failed,
    /// Was outside tolerance or missing; `--update` rewrote the reference.
    Updated,
}

impl Status {
    fn key(self) -> &'static str {
        match self {
            Status::Passed => "pass",
            Status::Failed => "FAIL",
            Status::Updated => "updated",
        }
    }
}

/// One scene's result, with the images for the report (PNG bytes).
#[derive(Clone, Debug)]
pub struct SceneOutcome {
    pub name: String,
    pub status: Status,
    pub image: Option<ImageCheck>,
    pub field: Option<FieldCheck>,
    /// A problem that prevented the comparison (missing or unreadable reference).
    pub problem: Option<String>,
    /// Files the comparison wrote: the diff image, references rewritten by `--update`.
    pub written: Vec<String>,
    pub reference_png: Option<Vec<u8>>,
    pub actual_png: Vec<u8>,
    pub diff_png: Option<Vec<u8>>,
}

impl SceneOutcome {
    /// Whether image and field checks passed and nothing prevented them.
    pub fn checks_passed(&self) -> bool {
        self.problem.is_none()
            && self.image.as_ref().is_none_or(ImageCheck::passed)
            && self.field.as_ref().is_none_or(FieldCheck::passed)
    }

    /// The CI log line, e.g. `FAIL line_tau1: image: RMS 3.2 (limit 2); field: ...`.
    pub fn line(&self) -> String {
        let mut parts = Vec::new();
        if let Some(problem) = &self.problem {
            parts.push(problem.clone());
        }
        if let Some(image) = &self.image {
            parts.push(format!("image: {}", image.summary()));
        }
        if let Some(field) = &self.field {
            parts.push(field.summary());
        }
        parts.extend(self.written.iter().cloned());
        format!("{} {}: {}", self.status.key(), self.name, parts.join("; "))
    }
}

fn data_uri(png: &[u8]) -> String {
    format!(
        "data:image/png;base64,{}",
        base64::engine::general_purpose::STANDARD.encode(png)
    )
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The report: one self-contained HTML page (images embedded as data URIs), failures first,
/// then updated, then passed scenes (folded). The page is also well-formed XML (empty elements
/// closed, text escaped), so any XML parser reads it. `context` says what was compared with what, e.g.
/// "out/ against tests/golden/".
pub fn html_report(outcomes: &[SceneOutcome], context: &str, measure: &ImageMeasure) -> String {
    let count = |s: Status| outcomes.iter().filter(|o| o.status == s).count();
    let (failed, updated, passed) = (
        count(Status::Failed),
        count(Status::Updated),
        count(Status::Passed),
    );
    let mut html = String::new();
    let _ = write!(
        html,
        r#"<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8"/>
<title>stressfield regression report: {failed} failed of {total}</title>
<style>
body {{ font-family: system-ui, sans-serif; margin: 1.5em; color: #222; }}
h1 {{ font-size: 1.4em; margin-bottom: 0.2em; }}
.summary {{ font-size: 1.1em; margin: 0.5em 0 1.5em; }}
.scene {{ border: 1px solid #ccc; border-radius: 6px; margin: 0 0 1.5em; padding: 0.6em 1em; }}
.scene.fail {{ border-color: #c62828; border-width: 2px; }}
.badge {{ display: inline-block; padding: 0.1em 0.6em; border-radius: 4px; color: white; font-weight: bold; margin-right: 0.5em; }}
.fail .badge {{ background: #c62828; }} .pass .badge {{ background: #2e7d32; }} .updated .badge {{ background: #ef6c00; }}
.measure {{ font-family: ui-monospace, monospace; font-size: 0.9em; margin: 0.3em 0; }}
.images {{ display: flex; flex-wrap: wrap; gap: 1em; align-items: flex-start; }}
figure {{ margin: 0; max-width: 32%; min-width: 280px; }}
figure img {{ max-width: 100%; border: 1px solid #ddd; }}
figcaption {{ font-weight: bold; margin-bottom: 0.2em; }}
</style>
</head>
<body>
<h1>stressfield regression report</h1>
<div class="summary">{total} scene(s): <b>{failed} failed</b>, {updated} updated, {passed} passed. {context}. Image measure: {measure}.</div>
"#,
        total = outcomes.len(),
        context = escape(context),
        measure = escape(&measure.describe()),
    );
    for status in [Status::Failed, Status::Updated, Status::Passed] {
        for outcome in outcomes.iter().filter(|o| o.status == status) {
            scene_html(&mut html, outcome);
        }
    }
    html.push_str("</body>\n</html>\n");
    html
}

fn scene_html(html: &mut String, outcome: &SceneOutcome) {
    let class = match outcome.status {
        Status::Failed => "fail",
        Status::Updated => "updated",
        Status::Passed => "pass",
    };
    let _ = writeln!(
        html,
        r#"<section class="scene {class}" id="{id}">
<h2><span class="badge">{status}</span>{id}</h2>"#,
        id = escape(&outcome.name),
        status = outcome.status.key(),
    );
    if let Some(problem) = &outcome.problem {
        let _ = writeln!(html, r#"<div class="measure">{}</div>"#, escape(problem));
    }
    if let Some(image) = &outcome.image {
        let verdict = if image.passed() { "within" } else { "OUTSIDE" };
        let _ = writeln!(
            html,
            r#"<div class="measure">image ({verdict} tolerance): {}</div>"#,
            escape(&image.summary())
        );
    }
    if let Some(field) = &outcome.field {
        let verdict = if field.passed() { "within" } else { "OUTSIDE" };
        let summary = field.summary();
        let _ = writeln!(
            html,
            r#"<div class="measure">field ({verdict} tolerance): {}</div>"#,
            escape(summary.strip_prefix("field: ").unwrap_or(&summary))
        );
    }
    for written in &outcome.written {
        let _ = writeln!(html, r#"<div class="measure">{}</div>"#, escape(written));
    }
    let folded = outcome.status == Status::Passed;
    if folded {
        html.push_str("<details><summary>images</summary>\n");
    }
    html.push_str(r#"<div class="images">"#);
    // An updated scene's reference is the one it replaced.
    let (reference, actual) = match outcome.status {
        Status::Updated => ("previous reference", "actual (now the reference)"),
        Status::Passed | Status::Failed => ("reference", "actual"),
    };
    let images = [
        (reference, outcome.reference_png.as_deref()),
        (actual, Some(outcome.actual_png.as_slice())),
        ("difference", outcome.diff_png.as_deref()),
    ];
    for (caption, png) in images {
        let Some(png) = png else { continue };
        let _ = write!(
            html,
            r#"<figure><figcaption>{caption}</figcaption><img alt="{caption} of {name}" src="{uri}"/></figure>"#,
            name = escape(&outcome.name),
            uri = data_uri(png),
        );
    }
    html.push_str("</div>\n");
    if folded {
        html.push_str("</details>\n");
    }
    html.push_str("</section>\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    fn comparison(rms: f64, differing: usize) -> Comparison {
        Comparison {
            actual_size: (10, 10),
            expected_size: (10, 10),
            differing_pixels: differing,
            max_channel_difference: 40,
            rms,
            tolerance: Tolerance {
                per_channel: 16,
                max_differing_pixels: 0,
            },
        }
    }

    fn outcome(name: &str, status: Status, image: Option<ImageCheck>) -> SceneOutcome {
        SceneOutcome {
            name: name.into(),
            status,
            image,
            field: None,
            problem: None,
            written: Vec::new(),
            reference_png: Some(vec![1, 2, 3]),
            actual_png: vec![4, 5, 6],
            diff_png: None,
        }
    }

    #[test]
    fn the_measure_decides() {
        let pixels = ImageMeasure::Pixels(Tolerance {
            per_channel: 16,
            max_differing_pixels: 0,
        });
        let check = |measure, c| ImageCheck {
            comparison: c,
            measure,
        };
        assert!(!check(pixels, comparison(0.5, 3)).passed());
        assert!(check(pixels, comparison(5.0, 0)).passed());
        let rms = ImageMeasure::Rms { max: 2.0 };
        assert!(check(rms, comparison(1.9, 300)).passed());
        assert!(!check(rms, comparison(2.1, 0)).passed());
        assert!(check(rms, comparison(2.1, 0))
            .summary()
            .contains("RMS 2.100 (limit 2)"));
        let mut other_size = comparison(0.0, 0);
        other_size.expected_size = (10, 11);
        assert!(!check(rms, other_size).passed());
    }

    #[test]
    fn field_check_names_the_largest_difference_and_where() {
        let check = FieldCheck {
            tolerance: 1e-3,
            unit: "p0".into(),
            axes: ["x/a".into(), "z/a".into()],
            largest: Some(FieldDifference {
                panel: 1,
                largest: 2.5e-3,
                at: (0.5, 0.48),
            }),
            mismatch: None,
        };
        assert!(!check.passed());
        assert_eq!(
            check.summary(),
            "field: largest difference 0.0025 p0 in panel 1 at x/a = 0.5, z/a = 0.48 (limit 1e-3 p0)"
        );
        let within = FieldCheck {
            largest: Some(FieldDifference {
                panel: 0,
                largest: 1e-12,
                at: (0.0, 0.0),
            }),
            ..check.clone()
        };
        assert!(within.passed());
        assert!(
            within.summary().contains("1e-12 p0"),
            "{}",
            within.summary()
        );
        let mismatch = FieldCheck {
            mismatch: Some("2 panels, the reference has 3".into()),
            largest: None,
            ..check
        };
        assert!(!mismatch.passed());
    }

    #[test]
    fn report_lists_failures_first_and_embeds_the_images() {
        let rms = ImageMeasure::Rms { max: 2.0 };
        let failing = ImageCheck {
            comparison: comparison(3.0, 12),
            measure: rms,
        };
        let passing = ImageCheck {
            comparison: comparison(0.0, 0),
            measure: rms,
        };
        let outcomes = vec![
            outcome("alpha_pass", Status::Passed, Some(passing)),
            outcome("beta_<fail>", Status::Failed, Some(failing)),
        ];
        assert!(outcomes[0].checks_passed() && !outcomes[1].checks_passed());
        assert!(outcomes[1]
            .line()
            .starts_with("FAIL beta_<fail>: image: RMS 3.000"));
        let html = html_report(&outcomes, "out/ against tests/golden/", &rms);
        let fail_at = html
            .find("beta_&lt;fail&gt;")
            .expect("failure listed, escaped");
        let pass_at = html.find("alpha_pass").expect("pass listed");
        assert!(fail_at < pass_at, "failures come first");
        assert!(html.contains("<b>1 failed</b>"));
        // [1, 2, 3] and [4, 5, 6] in base64.
        assert!(html.contains("data:image/png;base64,AQID"));
        assert!(html.contains("data:image/png;base64,BAUG"));
        assert!(!html.contains("<fail>"), "names are escaped");
        // Balanced sections and a closed document.
        assert_eq!(
            html.matches("<section").count(),
            html.matches("</section>").count()
        );
        assert!(html.trim_end().ends_with("</html>"));
    }

    #[test]
    fn short_numbers() {
        assert_eq!(short(0.0025), "0.0025");
        assert_eq!(short(1e-12), "1e-12");
        assert_eq!(short(0.48), "0.48");
        assert_eq!(short(-1.0000000000000002), "-1");
        assert_eq!(short(1234.56), "1235");
        assert_eq!(short(3.2e9), "3.2e9");
        assert_eq!(short(1e-3), "1e-3");
        assert_eq!(short(0.00099987), "9.999e-4");
        assert_eq!(short(0.0), "0");
    }
}

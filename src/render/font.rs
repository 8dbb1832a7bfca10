//! The embedded font (DejaVu Sans, never a system font) and its metrics.
//!
//! Sizes are plotters font sizes: with the `ab_glyph` backend a size `s` is the pixel height
//! from descender to ascender, so one em is `s / 1.164` for DejaVu Sans.

use std::sync::OnceLock;

use plotters::style::{register_font, FontStyle};

use super::RenderError;

/// The family name the font is registered under.
pub(crate) const FAMILY: &str = "sans-serif";

/// Pixels per em for a plotters font size.
pub(crate) fn em(size: f64) -> f64 {
    let m = metrics();
    size * m.units_per_em / (m.ascender + m.descender)
}

/// Height of capitals and digits above the baseline.
pub(crate) fn cap_height(size: f64) -> f64 {
    let m = metrics();
    em(size) * m.cap_height / m.units_per_em
}

/// Height of the tallest glyphs above the baseline.
pub(crate) fn ascent(size: f64) -> f64 {
    let m = metrics();
    em(size) * m.ascender / m.units_per_em
}

/// Depth of descenders below the baseline.
pub(crate) fn descent(size: f64) -> f64 {
    let m = metrics();
    em(size) * m.descender / m.units_per_em
}

/// Horizontal metrics of one character at `size`: advance and left side bearing in pixels.
pub(crate) fn glyph_metrics(c: char, size: f64) -> (f64, f64) {
    let m = metrics();
    let scale = em(size) / m.units_per_em;
    match &m.face {
        Some(face) => {
            let glyph = face.glyph_index(c).unwrap_or(ttf_parser::GlyphId(0));
            let advance = face.glyph_hor_advance(glyph).map_or(0.0, f64::from);
            let lsb = face.glyph_hor_side_bearing(glyph).map_or(0.0, f64::from);
            (advance * scale, lsb * scale)
        }
        // DejaVu Sans's average advance, should the embedded font ever fail to parse.
        None => (0.55 * em(size), 0.0),
    }
}

/// What the layout needs from the font: vertical metrics (font units) and the parsed face for
/// per-glyph advances and side bearings (`ttf-parser`).
struct Metrics {
    units_per_em: f64,
    ascender: f64,
    /// Positive depth below the baseline.
    descender: f64,
    cap_height: f64,
    face: Option<ttf_parser::Face<'static>>,
}

/// DejaVu Sans's metrics, read once from the embedded font. The font is a fixed asset, so a
/// failure to read it is a build defect: the fallback values are DejaVu Sans's own.
fn metrics() -> &'static Metrics {
    static METRICS: OnceLock<Metrics> = OnceLock::new();
    METRICS.get_or_init(|| {
        let face = ttf_parser::Face::parse(dejavu::sans::regular(), 0).ok();
        match &face {
            Some(f) => {
                // DejaVu's OS/2 table is version 1, without a cap height: use the top of "H".
                let cap_height = f.capital_height().map(f64::from).or_else(|| {
                    let h = f.glyph_index('H')?;
                    f.glyph_bounding_box(h).map(|b| f64::from(b.y_max))
                });
                Metrics {
                    units_per_em: f64::from(f.units_per_em()),
                    ascender: f64::from(f.ascender()),
                    descender: -f64::from(f.descender()),
                    cap_height: cap_height.unwrap_or(1493.0),
                    face,
                }
            }
            None => Metrics {
                units_per_em: 2048.0,
                ascender: 1901.0,
                descender: 483.0,
                cap_height: 1493.0,
                face: None,
            },
        }
    })
}

/// Registers DejaVu Sans as "sans-serif" once per process.
pub(crate) fn ensure_registered() -> Result<(), RenderError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED
        .get_or_init(|| register_font(FAMILY, FontStyle::Normal, dejavu::sans::regular()).is_ok());
    if ok {
        Ok(())
    } else {
        Err(RenderError::Draw(
            "the embedded DejaVu Sans font could not be loaded".to_string(),
        ))
    }
}

/// Advance width in pixels of `text` set at `size` (sum of the advances, no kerning: the
/// painter places glyphs the same way).
pub(crate) fn text_width(text: &str, size: f64) -> Result<f64, RenderError> {
    Ok(text.chars().map(|c| glyph_metrics(c, size).0).sum())
}

/// `text` as set at `size`, cut to at most `max_width` pixels: unchanged when it fits,
/// otherwise the longest beginning that fits followed by an ellipsis.
pub(crate) fn fit(text: &str, size: f64, max_width: f64) -> Result<String, RenderError> {
    if text_width(text, size)? <= max_width {
        return Ok(text.to_string());
    }
    let ellipsis = text_width("…", size)?;
    // Widths of the beginnings, one character at a time, until the budget is spent.
    let mut width = ellipsis;
    let mut end = 0;
    for (index, c) in text.char_indices() {
        width += glyph_metrics(c, size).0;
        if width > max_width {
            break;
        }
        end = index + c.len_utf8();
    }
    Ok(format!("{}…", text[..end].trim_end()))
}

#[cfg(test)]
mod tests {
    use plotters::style::IntoFont;

    use super::*;

    #[test]
    fn metrics_are_read_from_the_font() {
        let m = metrics();
        assert_eq!(
            (m.units_per_em, m.ascender, m.descender, m.cap_height),
            (2048.0, 1901.0, 483.0, 1493.0)
        );
        let face = m.face.as_ref().expect("the embedded font parses");
        for c in ['A', 'τ', 'σ', 'μ', 'ν', '\u{2212}', '·'] {
            assert!(
                face.glyph_index(c).is_some_and(|g| g.0 != 0),
                "no glyph for {c}"
            );
        }
    }

    #[test]
    fn long_text_is_cut_to_its_width() {
        let short = "μ = 0.3,  ν = 0.3";
        assert_eq!(fit(short, 14.0, 500.0).expect("fits"), short);
        let long = "very long subtitle ".repeat(10_000);
        let cut = fit(&long, 14.0, 300.0).expect("cut");
        assert!(cut.ends_with('…'), "{cut}");
        let width = text_width(&cut, 14.0).expect("width");
        assert!(width <= 300.0 && width > 250.0, "{width}");
    }

    #[test]
    fn widths_agree_with_plotters() {
        ensure_registered().expect("font");
        for text in [
            "Principal shear stress τ1",
            "max 0.300 p0 at x = 0.000a, z = 0.785a",
            "\u{2212}1.5",
        ] {
            let ours = text_width(text, 20.0).expect("width");
            let (theirs, _) = (FAMILY, 20.0).into_font().box_size(text).expect("box");
            // plotters adds kerning and truncates; the advances alone agree within a pixel or two.
            assert!(
                (ours - f64::from(theirs)).abs() < 2.5,
                "{text}: {ours} vs {theirs}"
            );
        }
    }
}

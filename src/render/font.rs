//! The embedded font (DejaVu Sans, never a system font) and its metrics.
//!
//! Sizes are plotters font sizes: with the `ab_glyph` backend a size `s` is the pixel height
//! from descender to ascender, so one em is `s / 1.164` for DejaVu Sans.

use std::collections::HashMap;
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
    let glyph = m.glyphs.get(&c).copied().unwrap_or(0);
    let (advance, lsb) = m.horizontal(glyph);
    (advance * scale, lsb * scale)
}

/// What the layout needs from the font file: vertical metrics, advances, side bearings.
struct Metrics {
    units_per_em: f64,
    ascender: f64,
    /// Positive depth below the baseline.
    descender: f64,
    cap_height: f64,
    /// `(advance, left side bearing)` in font units, by glyph id (`hmtx`).
    h_metrics: Vec<(u16, i16)>,
    /// Side bearings of the glyphs after the last full `hmtx` entry.
    extra_lsb: Vec<i16>,
    /// Character to glyph id (`cmap`).
    glyphs: HashMap<char, u16>,
}

impl Metrics {
    fn horizontal(&self, glyph: u16) -> (f64, f64) {
        let g = usize::from(glyph);
        let last_advance = self.h_metrics.last().map_or(0, |m| m.0);
        match self.h_metrics.get(g) {
            Some(&(advance, lsb)) => (f64::from(advance), f64::from(lsb)),
            None => {
                let lsb = self
                    .extra_lsb
                    .get(g - self.h_metrics.len())
                    .copied()
                    .unwrap_or(0);
                (f64::from(last_advance), f64::from(lsb))
            }
        }
    }
}

/// DejaVu Sans's metrics, read once from the embedded font. The font is a fixed asset, so a
/// failure to read it is a build defect: the fallback values are DejaVu Sans's own.
fn metrics() -> &'static Metrics {
    static METRICS: OnceLock<Metrics> = OnceLock::new();
    METRICS.get_or_init(|| {
        truetype::read(dejavu::sans::regular()).unwrap_or(Metrics {
            units_per_em: 2048.0,
            ascender: 1901.0,
            descender: 483.0,
            cap_height: 1493.0,
            h_metrics: Vec::new(),
            extra_lsb: Vec::new(),
            glyphs: HashMap::new(),
        })
    })
}

/// A minimal reader of the TrueType tables the layout needs (`head`, `hhea`, `OS/2`, `hmtx`,
/// `cmap` formats 4 and 12).
mod truetype {
    use std::collections::HashMap;

    use super::Metrics;

    fn u16_at(data: &[u8], at: usize) -> Option<u16> {
        Some(u16::from_be_bytes([*data.get(at)?, *data.get(at + 1)?]))
    }

    fn i16_at(data: &[u8], at: usize) -> Option<i16> {
        u16_at(data, at).map(|v| v as i16)
    }

    fn u32_at(data: &[u8], at: usize) -> Option<u32> {
        Some(u32::from_be_bytes([
            *data.get(at)?,
            *data.get(at + 1)?,
            *data.get(at + 2)?,
            *data.get(at + 3)?,
        ]))
    }

    fn table<'a>(font: &'a [u8], tag: &[u8; 4]) -> Option<&'a [u8]> {
        let count = usize::from(u16_at(font, 4)?);
        (0..count).find_map(|i| {
            let record = 12 + 16 * i;
            if font.get(record..record + 4)? != tag {
                return None;
            }
            let offset = u32_at(font, record + 8)? as usize;
            let length = u32_at(font, record + 12)? as usize;
            font.get(offset..offset + length)
        })
    }

    pub(super) fn read(font: &[u8]) -> Option<Metrics> {
        let head = table(font, b"head")?;
        let hhea = table(font, b"hhea")?;
        let hmtx = table(font, b"hmtx")?;
        let maxp = table(font, b"maxp")?;
        let glyph_count = usize::from(u16_at(maxp, 4)?);
        let full = usize::from(u16_at(hhea, 34)?);
        let h_metrics = (0..full)
            .map(|g| Some((u16_at(hmtx, 4 * g)?, i16_at(hmtx, 4 * g + 2)?)))
            .collect::<Option<Vec<_>>>()?;
        let extra_lsb = (full..glyph_count)
            .map_while(|g| i16_at(hmtx, 4 * full + 2 * (g - full)))
            .collect();
        let glyphs = cmap(table(font, b"cmap")?)?;
        // Cap height: the top of "H" (OS/2 of DejaVu Sans is version 1, without sCapHeight).
        let cap_height = f64::from(glyph_y_max(font, head, *glyphs.get(&'H')?)?);
        Some(Metrics {
            units_per_em: f64::from(u16_at(head, 18)?),
            ascender: f64::from(i16_at(hhea, 4)?),
            descender: -f64::from(i16_at(hhea, 6)?),
            cap_height,
            h_metrics,
            extra_lsb,
            glyphs,
        })
    }

    /// The top of a glyph's outline (`yMax` of its `glyf` header), in font units.
    fn glyph_y_max(font: &[u8], head: &[u8], glyph: u16) -> Option<i16> {
        let loca = table(font, b"loca")?;
        let glyf = table(font, b"glyf")?;
        let g = usize::from(glyph);
        let offset = match i16_at(head, 50)? {
            0 => 2 * usize::from(u16_at(loca, 2 * g)?),
            _ => u32_at(loca, 4 * g)? as usize,
        };
        i16_at(glyf, offset + 8)
    }

    /// Unicode to glyph ids from the Windows Unicode subtable (format 12, else format 4).
    fn cmap(cmap: &[u8]) -> Option<HashMap<char, u16>> {
        let count = usize::from(u16_at(cmap, 2)?);
        let subtable = |platform: u16, encoding: u16| {
            (0..count).find_map(|i| {
                let record = 4 + 8 * i;
                let matches =
                    u16_at(cmap, record)? == platform && u16_at(cmap, record + 2)? == encoding;
                matches
                    .then(|| cmap.get(u32_at(cmap, record + 4)? as usize..))
                    .flatten()
            })
        };
        let mut glyphs = HashMap::new();
        if let Some(sub) = subtable(3, 10).filter(|s| u16_at(s, 0) == Some(12)) {
            let groups = u32_at(sub, 12)? as usize;
            for g in 0..groups {
                let at = 16 + 12 * g;
                let (start, end, first) =
                    (u32_at(sub, at)?, u32_at(sub, at + 4)?, u32_at(sub, at + 8)?);
                for code in start..=end.min(start + 0xFFFF) {
                    if let (Some(c), Ok(id)) =
                        (char::from_u32(code), u16::try_from(first + (code - start)))
                    {
                        glyphs.insert(c, id);
                    }
                }
            }
            return Some(glyphs);
        }
        let sub = subtable(3, 1).filter(|s| u16_at(s, 0) == Some(4))?;
        let segments = usize::from(u16_at(sub, 6)? / 2);
        let ends = 14;
        let starts = ends + 2 * segments + 2;
        let deltas = starts + 2 * segments;
        let range_offsets = deltas + 2 * segments;
        for s in 0..segments {
            let (start, end) = (u16_at(sub, starts + 2 * s)?, u16_at(sub, ends + 2 * s)?);
            let delta = u16_at(sub, deltas + 2 * s)?;
            let range_offset = usize::from(u16_at(sub, range_offsets + 2 * s)?);
            for code in start..=end {
                if code == 0xFFFF {
                    break;
                }
                let id = if range_offset == 0 {
                    code.wrapping_add(delta)
                } else {
                    let at = range_offsets + 2 * s + range_offset + 2 * usize::from(code - start);
                    match u16_at(sub, at)? {
                        0 => 0,
                        g => g.wrapping_add(delta),
                    }
                };
                if let Some(c) = char::from_u32(u32::from(code)) {
                    glyphs.insert(c, id);
                }
            }
        }
        Some(glyphs)
    }
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
        assert!(m.glyphs.len() > 3000, "{} characters", m.glyphs.len());
        for c in ['A', 'τ', 'σ', 'μ', 'ν', '\u{2212}', '·'] {
            assert!(
                m.glyphs.get(&c).is_some_and(|g| *g != 0),
                "no glyph for {c}"
            );
        }
    }

    #[test]
    fn widths_agree_with_plotters() {
        ensure_registered().expect("font");
        for text in [
            "Principal shear stress τ1",
            "max 0.300 at (0.00, 0.79)",
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

//! Finishing the SVG text that plotters wrote: the heat maps and the colour bars go in as
//! embedded PNG images under everything else, and text asks for DejaVu Sans first.
//!
//! plotters' SVG backend can only blit bitmaps pixel by pixel (one `<rect>` each) unless its
//! `image` feature pulls in a second `image` crate; an embedded PNG keeps the SVG small and the
//! map identical to the PNG output.

use super::layout::Rect;
use super::paint::draw_error;
use super::RenderError;

/// Inserts a white background and `images` right after the opening `<svg>` tag, so that they
/// lie under everything plotters drew, and names DejaVu Sans as the preferred font.
pub(crate) fn finish(
    svg: &str,
    images: &[(Rect, Vec<u8>)],
    size: (u32, u32),
) -> Result<String, RenderError> {
    let open = svg
        .find("<svg")
        .ok_or_else(|| draw_error("the SVG backend wrote no <svg> element"))?;
    let close = svg[open..]
        .find('>')
        .map(|i| open + i)
        .ok_or_else(|| draw_error("unterminated <svg> tag"))?;
    let (head, rest) = svg.split_at(close);
    let head = head.trim_end_matches('/');
    let mut out =
        String::with_capacity(svg.len() + images.iter().map(|(_, rgb)| rgb.len()).sum::<usize>());
    out.push_str(head);
    out.push_str(" xmlns:xlink=\"http://www.w3.org/1999/xlink\"");
    out.push_str(">\n");
    out.push_str(&format!(
        "<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"#FFFFFF\"/>\n",
        size.0, size.1
    ));
    for (rect, rgb) in images {
        if rect.w <= 0 || rect.h <= 0 {
            continue;
        }
        let image = image::RgbImage::from_raw(rect.w as u32, rect.h as u32, rgb.clone())
            .ok_or_else(|| draw_error("bitmap size does not match its rectangle"))?;
        let png = super::encode_png(&image)?;
        out.push_str(&format!(
            "<image x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" preserveAspectRatio=\"none\" \
             style=\"image-rendering:pixelated\" xlink:href=\"data:image/png;base64,{}\"/>\n",
            rect.x,
            rect.y,
            rect.w,
            rect.h,
            base64(&png)
        ));
    }
    out.push_str(rest[1..].trim_start_matches('\n'));
    Ok(out.replace(
        "font-family=\"sans-serif\"",
        "font-family=\"DejaVu Sans, sans-serif\"",
    ))
}

/// Standard base64 with padding (RFC 4648).
pub(crate) fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            *chunk.get(1).unwrap_or(&0),
            *chunk.get(2).unwrap_or(&0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(char::from(ALPHABET[(n >> (18 - 6 * k)) as usize & 63]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc_4648_vectors() {
        let cases = [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ];
        for (plain, encoded) in cases {
            assert_eq!(base64(plain.as_bytes()), encoded);
        }
    }

    #[test]
    fn images_go_right_after_the_svg_tag() {
        let svg = "<svg width=\"4\" height=\"2\" xmlns=\"http://www.w3.org/2000/svg\">\n<text font-family=\"sans-serif\">a</text>\n</svg>\n";
        let rect = Rect {
            x: 1,
            y: 0,
            w: 2,
            h: 1,
        };
        let out = finish(svg, &[(rect, vec![0; 6])], (4, 2)).expect("finish");
        let image = out.find("<image").expect("image");
        let text = out.find("<text").expect("text");
        assert!(
            out.find("<rect").expect("background") < image && image < text,
            "{out}"
        );
        assert!(out.contains("font-family=\"DejaVu Sans, sans-serif\""));
        assert!(out.contains("xmlns:xlink"));
        assert!(out.trim_end().ends_with("</svg>"));
    }
}

//! Text shown to people: numbers as short as they can be written exactly, and long echoes of
//! their own input cut to a readable length.

/// `value` in its shortest round-trip form (exact to the last bit), in plain decimals ("0.3",
/// "120", "-2.5", "0.0012", "20000") unless exponent notation is shorter by more than two
/// characters ("5e-324", "1.5e-7", "1e8", "1e308"), so ordinary numbers read as usual and no
/// number runs to dozens of digits (at most 24 characters). Infinities and NaN print as
/// `inf`, `-inf` and `NaN`.
pub fn number(value: f64) -> String {
    let plain = format!("{value}");
    if value == 0.0 || !value.is_finite() {
        return plain;
    }
    let exponent = format!("{value:e}");
    if plain.len() <= exponent.len() + 2 {
        plain
    } else {
        exponent
    }
}

/// `value` to four significant digits, in the form of [`number`]: a derived value in a message
/// ("3492000", "8.727e-304", "0.1234").
pub fn approx(value: f64) -> String {
    if !value.is_finite() {
        return number(value);
    }
    let rounded: f64 = format!("{value:.3e}").parse().unwrap_or(value);
    number(rounded)
}

/// `value` with `decimals` decimals ("0.1734", "40.0000") while that shows it, below 1e12;
/// otherwise in exponent notation with as many decimals ("1.0000e-12", "2.5000e15"), so a
/// tiny value never reads as zero and a huge one never runs to dozens of digits.
pub fn fixed(value: f64, decimals: usize) -> String {
    let magnitude = value.abs();
    let smallest = 10f64.powi(-(decimals as i32));
    if value == 0.0 || !value.is_finite() || (smallest..1e12).contains(&magnitude) {
        format!("{value:.decimals$}")
    } else {
        format!("{value:.decimals$e}")
    }
}

/// A limit or a round value for a message: plain below a million ("0.5", "1", "10000"),
/// exponent notation beyond ("1e6", "1e12") and below a thousandth ("1e-9").
pub fn compact(value: f64) -> String {
    let magnitude = value.abs();
    if value == 0.0 || !value.is_finite() || (1e-3..1e6).contains(&magnitude) {
        format!("{value}")
    } else {
        format!("{value:e}")
    }
}

/// `value` for a label in a figure or a recording: `digits` significant digits in plain
/// decimals for magnitudes from 1e-3 up to `below` (an integer part longer than `digits` is
/// kept whole), otherwise in exponent notation with `digits - 1` decimals; with `trim`,
/// trailing zeros and a bare point are dropped. Zero prints as `0`; a typographic minus.
pub fn significant(value: f64, digits: usize, below: f64, trim: bool) -> String {
    if value == 0.0 || !value.is_finite() {
        return if value.is_finite() {
            "0".into()
        } else {
            value.to_string()
        };
    }
    let trimmed = |text: &str| -> String {
        if trim && text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            text.to_string()
        }
    };
    let magnitude = value.abs();
    let text = if (1e-3..below).contains(&magnitude) {
        let decimals = (digits as i32 - 1 - magnitude.log10().floor() as i32).max(0) as usize;
        trimmed(&format!("{value:.decimals$}"))
    } else {
        let text = format!("{value:.precision$e}", precision = digits.saturating_sub(1));
        match text.split_once('e') {
            Some((mantissa, exponent)) => format!("{}e{exponent}", trimmed(mantissa)),
            None => text,
        }
    };
    text.replace('-', "\u{2212}")
}

/// At most `max_chars` characters of `text`; a longer text is cut and says how long it was,
/// e.g. `0,0,1aaaa… (10485760 characters)`.
pub fn cut(text: &str, max_chars: usize) -> String {
    let mut chars = text.char_indices();
    match chars.nth(max_chars) {
        None => text.to_string(),
        Some((end, _)) => format!("{}… ({} characters)", &text[..end], text.chars().count()),
    }
}

/// The lines of `text` without their endings: `\n`, `\r\n`, or a lone `\r` (old Mac files,
/// which would otherwise read as one line).
pub fn lines(text: &str) -> impl Iterator<Item = &str> {
    let mut rest = Some(text);
    std::iter::from_fn(move || {
        let current = rest?;
        match current.find(['\n', '\r']) {
            Some(at) => {
                let after = if current[at..].starts_with("\r\n") {
                    at + 2
                } else {
                    at + 1
                };
                rest = Some(&current[after..]);
                Some(&current[..at])
            }
            None => {
                rest = None;
                // As str::lines: no empty last line after a final ending.
                (!current.is_empty()).then_some(current)
            }
        }
    })
}

/// A size in bytes in the largest binary unit that keeps it whole or readable: "64 KiB",
/// "1 MiB", "2.5 GiB".
pub fn bytes(size: u64) -> String {
    const UNITS: [&str; 4] = ["bytes", "KiB", "MiB", "GiB"];
    let mut value = size as f64;
    let mut unit = 0;
    while value >= 1024.0 && unit + 1 < UNITS.len() {
        value /= 1024.0;
        unit += 1;
    }
    if unit == 0 || value.fract() == 0.0 {
        format!("{value:.0} {}", UNITS[unit])
    } else {
        format!("{value:.1} {}", UNITS[unit])
    }
}

/// An error and its causes for the user, each said once: `outer: cause: root cause`, leaving
/// out a cause whose text ends the message before it (an error that shows its source and also
/// chains it, such as `cannot read x: No such file or directory (os error 2)`). The command
/// line prints it after `error: `; the Python package raises it.
pub fn error_text(error: &anyhow::Error) -> String {
    let mut text = String::new();
    for cause in error.chain() {
        let line = cause.to_string();
        if text.is_empty() {
            text = line;
        } else if !text.ends_with(&line) {
            text.push_str(": ");
            text.push_str(&line);
        }
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_and_exact() {
        assert_eq!(number(0.3), "0.3");
        assert_eq!(number(-2.5), "-2.5");
        assert_eq!(number(0.0), "0");
        assert_eq!(number(120.0), "120");
        assert_eq!(number(0.0001), "0.0001");
        assert_eq!(number(5e-324), "5e-324");
        assert_eq!(number(1e308), "1e308");
        assert_eq!(number(-1.5e-7), "-1.5e-7");
        assert_eq!(number(1e16), "1e16");
        assert_eq!(number(1000.0), "1000");
        assert_eq!(number(20000.0), "20000");
        assert_eq!(number(1e8), "1e8");
        assert_eq!(number(123_456_789.0), "123456789");
        assert_eq!(number(0.00001), "1e-5");
        assert_eq!(number(f64::INFINITY), "inf");
        // Round trip, to the bit, on both sides of the switch.
        for v in [
            0.1 + 0.2,
            1.234_567_890_123_456_7e-5,
            9.999_999_999_999_998e15,
            5e-324,
        ] {
            assert_eq!(number(v).parse::<f64>().expect("parses"), v);
        }
        // Never longer than 24 characters, whatever the value.
        for v in [f64::MAX, f64::MIN_POSITIVE, -f64::MAX, 1.0 / 3.0] {
            assert!(number(v).len() <= 24, "{}", number(v));
        }
    }

    #[test]
    fn fixed_decimals_while_they_show_the_value() {
        assert_eq!(fixed(40.0, 4), "40.0000");
        assert_eq!(fixed(0.1734, 4), "0.1734");
        assert_eq!(fixed(0.0, 1), "0.0");
        assert_eq!(fixed(1e-12, 4), "1.0000e-12");
        assert_eq!(fixed(2.5e15, 1), "2.5e15");
        assert_eq!(fixed(-1e-5, 1), "-1.0e-5");
    }

    #[test]
    fn derived_values_keep_four_digits() {
        assert_eq!(approx(3_492_069.074_625_520_5), "3492000");
        assert_eq!(approx(8.726_646_259_971_649e-304), "8.727e-304");
        assert_eq!(approx(0.123_456), "0.1235");
        assert_eq!(approx(-2.0), "-2");
        assert_eq!(approx(f64::NAN), "NaN");
    }

    #[test]
    fn limits_read_at_a_glance() {
        assert_eq!(compact(1e12), "1e12");
        assert_eq!(compact(10000.0), "10000");
        assert_eq!(compact(1.0), "1");
        assert_eq!(compact(1e-9), "1e-9");
        assert_eq!(compact(0.01), "0.01");
    }

    #[test]
    fn long_echoes_are_cut() {
        assert_eq!(cut("short", 10), "short");
        assert_eq!(cut("exactly10!", 10), "exactly10!");
        let long = "x".repeat(1000);
        let shown = cut(&long, 20);
        assert!(shown.starts_with(&"x".repeat(20)), "{shown}");
        assert!(shown.ends_with("… (1000 characters)"), "{shown}");
        // Character boundaries, not bytes.
        assert_eq!(cut("µµµµ", 2), "µµ… (4 characters)");
    }

    #[test]
    fn lines_end_at_lf_crlf_or_a_lone_cr() {
        let split: Vec<&str> = lines("a\rb\r\nc\n\nd\r").collect();
        assert_eq!(split, ["a", "b", "c", "", "d"]);
        assert_eq!(lines("").count(), 0);
        assert_eq!(lines("x\n").collect::<Vec<_>>(), ["x"]);
    }

    #[test]
    fn sizes_read_in_binary_units() {
        assert_eq!(bytes(512), "512 bytes");
        assert_eq!(bytes(64 << 10), "64 KiB");
        assert_eq!(bytes(1 << 20), "1 MiB");
        assert_eq!(bytes(5 << 29), "2.5 GiB");
    }
}

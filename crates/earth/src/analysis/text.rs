//! The answer's text, written as bytes: JSON strings, numbers and region coordinates.
//!
//! A large answer is megabytes of these, written on every core; `core::fmt` (its padding
//! and float machinery) and a `String`'s per-character pushes cost as much as a stage of
//! the pipeline. Every writer here is checked against the text it replaces: strings
//! against `serde_json`, numbers against Rust's `{}`, coordinates against `{:.7}`.

/// A JSON number, or `null` for the unbounded ends of always-present areas.
pub(super) fn num(out: &mut Vec<u8>, x: f64) {
    if x.is_finite() {
        shortest(out, x);
    } else {
        out.extend_from_slice(b"null");
    }
}

/// Finite `x` exactly as Rust's `{}` writes it (`Display` for f64): the shortest decimal
/// digits that read back to `x` (the nearest such on a tie), never an exponent, no
/// fraction for an integer, `-0` for minus zero. The digits are zmij's (Schubfach: the
/// same shortest-and-nearest rule), laid out again: zmij writes an exponent outside a
/// middle range and `.0` after integers, `{}` does neither.
fn shortest(out: &mut Vec<u8>, x: f64) {
    let mut buf = zmij::Buffer::new();
    let s = buf.format_finite(x).as_bytes();
    let (negative, s) = match s.split_first() {
        Some((b'-', rest)) => (true, rest),
        _ => (false, s),
    };
    let (mantissa, exp) = match s.iter().position(|&b| b == b'e' || b == b'E') {
        Some(i) => (&s[..i], exponent(&s[i + 1..])),
        None => (s, 0),
    };
    // the value is 0.d₁d₂…dₙ × 10^point
    let mut digits = [0u8; 40];
    let mut n = 0usize;
    let mut before_point = None;
    for &b in mantissa {
        if b == b'.' {
            before_point = Some(n);
        } else if n < digits.len() {
            digits[n] = b;
            n += 1;
        }
    }
    let mut point = before_point.unwrap_or(n) as i32 + exp;
    let mut start = 0;
    while start < n && digits[start] == b'0' {
        start += 1;
        point -= 1;
    }
    let mut end = n;
    while end > start && digits[end - 1] == b'0' {
        end -= 1;
    }
    // an exact tie between two shortest digit strings: `{}` takes the one of larger
    // magnitude, zmij the even one
    if end > start && digits[end - 1] % 2 == 0 {
        let d = digits[start..end]
            .iter()
            .fold(0u64, |d, &b| d * 10 + u64::from(b - b'0'));
        if is_upper_midpoint(x, d, point - (end - start) as i32) {
            digits[end - 1] += 1;
        }
    }
    let d = &digits[start..end];
    if negative {
        out.push(b'-');
    }
    if d.is_empty() {
        out.push(b'0');
    } else if point <= 0 {
        out.extend_from_slice(b"0.");
        out.resize(out.len() + point.unsigned_abs() as usize, b'0');
        out.extend_from_slice(d);
    } else if point as usize >= d.len() {
        out.extend_from_slice(d);
        out.resize(out.len() + (point as usize - d.len()), b'0');
    } else {
        let (int, frac) = d.split_at(point as usize);
        out.extend_from_slice(int);
        out.push(b'.');
        out.extend_from_slice(frac);
    }
}

/// Whether |x| is exactly (d + ½)·10^q, halfway between the digit strings d and d + 1
/// (at most 17 digits, so 10·d + 5 fits in u64). With |x| = m·2^s (m odd) and
/// (d + ½)·10^q = (10·d + 5)·2^(q−1)·5^(q−1) (10·d + 5 odd), the two are equal exactly
/// when the powers of two agree and the odd parts do, which u128 decides.
fn is_upper_midpoint(x: f64, d: u64, q: i32) -> bool {
    let bits = x.to_bits();
    let (frac, exp) = (bits & ((1 << 52) - 1), ((bits >> 52) & 0x7ff) as i32);
    let (m, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1 << 52), exp - 1075)
    };
    if m == 0 {
        return false;
    }
    let (m, s) = (m >> m.trailing_zeros(), e + m.trailing_zeros() as i32);
    let (n, k) = (u128::from(d) * 10 + 5, q - 1);
    if s != k {
        return false;
    }
    // m = n·5^k for k ≥ 0, m·5^(−k) = n for k < 0; 5^55 > 2^127 bounds the loop
    let (mut small, big) = if k >= 0 {
        (n, u128::from(m))
    } else {
        (u128::from(m), n)
    };
    for _ in 0..k.unsigned_abs().min(56) {
        small *= 5;
        if small > big {
            return false;
        }
    }
    small == big
}

/// The decimal exponent after a mantissa's `e`: an optional sign, then digits.
fn exponent(s: &[u8]) -> i32 {
    let (sign, digits) = match s.split_first() {
        Some((b'-', rest)) => (-1, rest),
        Some((b'+', rest)) => (1, rest),
        _ => (1, s),
    };
    sign * digits
        .iter()
        .fold(0i32, |e, &b| e * 10 + i32::from(b.wrapping_sub(b'0')))
}

/// A JSON string literal with JSON's escapes (RFC 8259 §7) as `serde_json` writes them:
/// `"` and `\\` escaped, the control characters below U+0020 by their short escape or
/// `\u00xx`, all else as it is.
pub(super) fn string(out: &mut Vec<u8>, s: &str) {
    out.push(b'"');
    let bytes = s.as_bytes();
    let mut start = 0;
    for (i, &b) in bytes.iter().enumerate() {
        let esc: &[u8] = match b {
            b'"' => b"\\\"",
            b'\\' => b"\\\\",
            b'\n' => b"\\n",
            b'\r' => b"\\r",
            b'\t' => b"\\t",
            0x08 => b"\\b",
            0x0c => b"\\f",
            0..=0x1f => b"",
            _ => continue,
        };
        out.extend_from_slice(&bytes[start..i]);
        if esc.is_empty() {
            const HEX: &[u8; 16] = b"0123456789abcdef";
            out.extend_from_slice(b"\\u00");
            out.push(HEX[usize::from(b >> 4)]);
            out.push(HEX[usize::from(b & 15)]);
        } else {
            out.extend_from_slice(esc);
        }
        start = i + 1;
    }
    out.extend_from_slice(&bytes[start..]);
    out.push(b'"');
}

/// Region coordinates are written with this many decimals of a degree: 1e-7° ≈ 1.1 cm,
/// far below the stage tolerances, and a fixed-point writer is several times faster than
/// shortest round-trip formatting on the megabytes of a large answer.
pub(super) const REGION_DECIMALS: u32 = 7;

/// A coordinate in units of the last printed decimal.
pub(super) fn units(x: f64) -> i64 {
    (x * 10i64.pow(REGION_DECIMALS) as f64).round() as i64
}

/// A coordinate given in units of the last decimal, written with [`REGION_DECIMALS`]
/// decimals (what `{:.7}` writes of the degrees it stands for).
pub(super) fn coord_units(out: &mut Vec<u8>, v: i64) {
    // written from the right: the decimals, the point, the integer part, the sign
    let mut buf = [b'0'; 32];
    let mut k = buf.len();
    let mut a = v.unsigned_abs();
    for _ in 0..REGION_DECIMALS {
        k -= 1;
        buf[k] = b'0' + (a % 10) as u8;
        a /= 10;
    }
    k -= 1;
    buf[k] = b'.';
    loop {
        k -= 1;
        buf[k] = b'0' + (a % 10) as u8;
        a /= 10;
        if a == 0 {
            break;
        }
    }
    if v < 0 {
        k -= 1;
        buf[k] = b'-';
    }
    out.extend_from_slice(&buf[k..]);
}

/// A ring of positions in units of the last decimal, closed (its first position again
/// at the end), as a GeoJSON ring.
pub(super) fn ring_lonlat(out: &mut Vec<u8>, ring: &[[i64; 2]]) {
    out.push(b'[');
    for (k, p) in ring.iter().chain(ring.first()).enumerate() {
        if k > 0 {
            out.push(b',');
        }
        out.push(b'[');
        coord_units(out, p[0]);
        out.push(b',');
        coord_units(out, p[1]);
        out.push(b']');
    }
    out.push(b']');
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::Value;

    fn text(f: impl FnOnce(&mut Vec<u8>)) -> String {
        let mut v = Vec::new();
        f(&mut v);
        String::from_utf8(v).expect("the writers write UTF-8")
    }

    /// A small seeded generator (splitmix64), so that a failure names its seed.
    fn next(state: &mut u64) -> u64 {
        *state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = *state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Ids are written as serde_json writes them: every control character, quotes,
    /// backslashes, non-ASCII text.
    #[test]
    fn strings_are_escaped_as_serde_json_escapes_them() {
        let mut cases: Vec<String> = (0u8..0x20)
            .map(|b| format!("a{}b", char::from(b)))
            .collect();
        cases.extend(
            [
                "",
                "plain",
                "q\"uote",
                "back\\slash",
                "\u{7f}",
                "é – ü 飛",
                "\"\\\n",
            ]
            .map(String::from),
        );
        for c in &cases {
            assert_eq!(
                text(|o| string(o, c)),
                Value::from(c.as_str()).to_string(),
                "{c:?}"
            );
        }
    }

    #[test]
    fn coord_is_fixed_point_with_seven_decimals() {
        for &(x, want) in &[
            (0.0, "0.0000000"),
            (-0.0, "0.0000000"),
            (39.5, "39.5000000"),
            (-45.123456789, "-45.1234568"),
            (179.99999999, "180.0000000"),
            (-0.00000004, "0.0000000"),
            (-0.00000006, "-0.0000001"),
            (1.0000001, "1.0000001"),
        ] {
            assert_eq!(text(|o| coord_units(o, units(x))), want, "{x}");
        }
    }

    /// The coordinate writer agrees with `{:.7}` of the degrees it stands for, over every
    /// range of the Earth's coordinates (units of 1e-7° are exact in `{:.7}`'s rounding
    /// when the degrees are the units over 10⁷, as printed).
    #[test]
    fn coordinates_are_what_format_writes() {
        let mut state = 7u64;
        for k in 0..200_000u64 {
            let v = match k % 4 {
                0 => (next(&mut state) % 3_600_000_001) as i64 - 1_800_000_000,
                1 => (next(&mut state) % 20_001) as i64 - 10_000,
                2 => (next(&mut state) % 201) as i64 - 100,
                _ => [i64::MIN + 1, i64::MAX, -1, 0, 1, 10_000_000, -10_000_000]
                    [(k / 4 % 7) as usize],
            };
            let scale = 10i128.pow(REGION_DECIMALS);
            let a = i128::from(v).abs();
            let want = format!(
                "{}{}.{:07}",
                if v < 0 { "-" } else { "" },
                a / scale,
                a % scale
            );
            assert_eq!(text(|o| coord_units(o, v)), want, "{v}");
        }
    }

    /// Numbers are written exactly as `{}` writes them: on random bit patterns (every
    /// exponent, subnormals included), on times and windows of the answer's scale, on
    /// integers, on powers of ten and their neighbours, and on the extremes.
    #[test]
    fn numbers_are_what_display_writes() {
        let mut xs: Vec<f64> = vec![
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.1,
            0.3,
            1.5e16,
            1e21,
            1e22,
            1e-7,
            123456.0,
            f64::MAX,
            f64::MIN,
            f64::MIN_POSITIVE,
            f64::EPSILON,
            5e-324,
            -5e-324,
            // the largest subnormal
            f64::from_bits(0x000f_ffff_ffff_ffff),
        ];
        for e in -325..=308 {
            let p = format!("1e{e}").parse::<f64>().unwrap_or(0.0);
            xs.extend([
                p,
                f64::from_bits(p.to_bits() + 1),
                f64::from_bits(p.to_bits().saturating_sub(1)),
                -p,
            ]);
        }
        let mut state = 11u64;
        for k in 0..400_000u64 {
            let r = next(&mut state);
            let sign = if r & 1 == 0 { 1.0 } else { -1.0 };
            xs.push(match k % 4 {
                0 => f64::from_bits(r),
                1 => (r >> 11) as f64 / (1u64 << 53) as f64 * 48.0,
                2 => ((r >> 20) as f64).copysign(sign),
                // eighths near 2^52: 18 exact digits, of which the shortest keep 16 or
                // 17, so that many are exact ties between two shortest strings
                _ => ((r >> 12) as f64 / 8.0).copysign(sign),
            });
        }
        // the exact ties met, where zmij's own digits differ from `{}`'s (a fraction
        // written without exponent by both, so only the digits can differ)
        let ties = xs
            .iter()
            .filter(|x| x.fract() != 0.0 && x.abs() > 1e14 && x.abs() < 1e16)
            .filter(|&&x| zmij::Buffer::new().format_finite(x) != format!("{x}"))
            .count();
        assert!(ties > 1_000, "{ties} ties");
        let mut checked = 0;
        for &x in xs.iter().filter(|x| x.is_finite()) {
            assert_eq!(text(|o| num(o, x)), format!("{x}"), "{:#018x}", x.to_bits());
            checked += 1;
        }
        assert!(checked > 390_000, "{checked} numbers checked");
        assert_eq!(text(|o| num(o, f64::INFINITY)), "null");
        assert_eq!(text(|o| num(o, f64::NAN)), "null");
    }

    /// The check above can fail: a layout that keeps zmij's own text (its exponent, its
    /// `.0` after integers) differs from `{}` on such numbers, and so do zmij's digits on
    /// an exact tie (…841.25 is as near to …841.2 as to …841.3).
    #[test]
    fn canary_zmij_text_as_it_is_is_not_display() {
        let differs = [1.0f64, 1e21, 1e-7, -0.0, 123456.0]
            .iter()
            .filter(|&&x| zmij::Buffer::new().format_finite(x) != format!("{x}"))
            .count();
        assert_eq!(differs, 5);
        // -853633233828841.25, exactly
        let tie = f64::from_bits(0xc308_42ff_cd5d_df4a);
        assert_eq!(zmij::Buffer::new().format_finite(tie), "-853633233828841.2");
        assert_eq!(format!("{tie}"), "-853633233828841.3");
        assert!(is_upper_midpoint(tie, 8_536_332_338_288_412, -1));
        assert!(!is_upper_midpoint(
            f64::from_bits(tie.to_bits() - 1),
            8_536_332_338_288_412,
            -1
        ));
    }
}

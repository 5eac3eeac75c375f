//! Date-times of the moving-features formats (docs/moving-features.md, "Formats"):
//! RFC 3339 §5.6 `date-time` text to seconds since 1970-01-01T00:00:00Z and back.
//!
//! The time scale is POSIX time: the proleptic Gregorian calendar, every day 86,400 s,
//! no leap seconds (a second `60` is an error, not a 61st second). Years 0000 to 9999, the
//! four digits RFC 3339 writes.

use num_rational::BigRational;
use num_traits::ToPrimitive;

/// Seconds of a day.
const DAY_S: i64 = 86_400;

/// The first and last instants this module reads or writes: 0000-01-01T00:00:00Z and
/// 9999-12-31T23:59:59.999Z as epoch seconds (the range of four-digit years).
pub const FIRST_S: f64 = -62_167_219_200.0;
/// See [`FIRST_S`]; the end is exclusive: 10000-01-01T00:00:00Z.
pub const END_S: f64 = 253_402_300_800.0;

/// A date-time read from text.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Parsed {
    /// Seconds since 1970-01-01T00:00:00Z, the f64 nearest to the exact instant.
    pub t: f64,
    /// Whether the text gave a UTC offset (`Z` or `±hh:mm`). Without one (RFC 3339's
    /// `partial-time` alone, as MovingPandas writes `2021-10-07 13:00:25`) the instant is
    /// read as UTC, and the reader says so in a warning.
    pub has_offset: bool,
}

/// Days from 1970-01-01 to the proleptic Gregorian date `y-m-d` (m in 1..=12): the civil
/// day count by 400-year eras (each era 146,097 days, March-based years so that the leap
/// day is the last day of a year).
pub fn days_from_civil(y: i64, m: u32, d: u32) -> i64 {
    let y = if m <= 2 { y - 1 } else { y };
    let era = y.div_euclid(400);
    let yoe = y - era * 400; // 0..=399
    let mp = (i64::from(m) + 9) % 12; // March = 0
    let doy = (153 * mp + 2) / 5 + i64::from(d) - 1; // 0..=365
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy; // 0..=146096
    era * 146_097 + doe - 719_468
}

/// The proleptic Gregorian date of day `z` counted from 1970-01-01: the inverse of
/// [`days_from_civil`].
pub fn civil_from_days(z: i64) -> (i64, u32, u32) {
    let z = z + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d)
}

/// Whether `y` is a Gregorian leap year.
fn is_leap(y: i64) -> bool {
    (y % 4 == 0 && y % 100 != 0) || y % 400 == 0
}

/// The number of days of month `m` of year `y`.
fn month_days(y: i64, m: u32) -> u32 {
    match m {
        2 if is_leap(y) => 29,
        2 => 28,
        4 | 6 | 9 | 11 => 30,
        _ => 31,
    }
}

/// A fixed-width run of ASCII digits at `s[at..at + n]` as a number.
fn digits(s: &[u8], at: usize, n: usize) -> Option<u32> {
    let run = s.get(at..at + n)?;
    run.iter().try_fold(0u32, |acc, &b| {
        b.is_ascii_digit().then(|| acc * 10 + u32::from(b - b'0'))
    })
}

/// Reads an RFC 3339 §5.6 `date-time`: `full-date` then `T`, `t` or a space (the §5.6
/// note allows the space; pandas writes it) then `partial-time` with optional fraction
/// of any length, then `Z`, `z` or `±hh:mm`. Without an offset the text is read as UTC
/// and [`Parsed::has_offset`] is false: the caller decides whether that is allowed.
/// Errors say what is wrong in words.
pub fn parse(text: &str) -> Result<Parsed, String> {
    let s = text.as_bytes();
    let shape = "expected a date-time like 2021-10-07T13:00:25Z (RFC 3339)";
    let field = |at: usize, n: usize| digits(s, at, n).ok_or_else(|| shape.to_owned());
    let year = field(0, 4)?;
    if s.get(4) != Some(&b'-') || s.get(7) != Some(&b'-') {
        return Err(shape.to_owned());
    }
    let (month, day) = (field(5, 2)?, field(8, 2)?);
    if !matches!(s.get(10), Some(b'T' | b't' | b' ')) {
        return Err(shape.to_owned());
    }
    let (hour, minute) = (field(11, 2)?, field(14, 2)?);
    if s.get(13) != Some(&b':') || s.get(16) != Some(&b':') {
        return Err(shape.to_owned());
    }
    let second = field(17, 2)?;
    let y = i64::from(year);
    if !(1..=12).contains(&month) {
        return Err(format!("month {month:02} is not 01 to 12"));
    }
    if day == 0 || day > month_days(y, month) {
        return Err(format!("{year:04}-{month:02} has no day {day:02}"));
    }
    if hour > 23 || minute > 59 {
        return Err(format!("{hour:02}:{minute:02} is not a time of day"));
    }
    if second == 60 {
        return Err(String::from(
            "a leap second (:60) has no POSIX time; the formats count no leap seconds",
        ));
    }
    if second > 59 {
        return Err(format!("second {second:02} is not 00 to 59"));
    }
    let mut i = 19;
    let mut frac = "";
    if s.get(i) == Some(&b'.') {
        let n = s[i + 1..].iter().take_while(|b| b.is_ascii_digit()).count();
        if n == 0 {
            return Err(String::from("a digit must follow the decimal point"));
        }
        frac = &text[i + 1..i + 1 + n];
        i += 1 + n;
    }
    let (offset_s, has_offset) = match s.get(i) {
        None => (0, false),
        Some(b'Z' | b'z') => {
            i += 1;
            (0, true)
        }
        Some(&sign @ (b'+' | b'-')) => {
            let form = || String::from("a UTC offset is written ±hh:mm");
            if s.get(i + 3) != Some(&b':') {
                return Err(form());
            }
            let oh = digits(s, i + 1, 2).ok_or_else(form)?;
            let om = digits(s, i + 4, 2).ok_or_else(form)?;
            if oh > 23 || om > 59 {
                return Err(format!("offset {oh:02}:{om:02} is not ±00:00 to ±23:59"));
            }
            i += 6;
            let o = i64::from(oh * 3600 + om * 60);
            (if sign == b'-' { -o } else { o }, true)
        }
        Some(_) => return Err(String::from("expected Z, ±hh:mm or the end after the time")),
    };
    if i != s.len() {
        return Err(String::from("unexpected text after the date-time"));
    }
    let whole = days_from_civil(y, month, day) * DAY_S
        + i64::from(hour * 3600 + minute * 60 + second)
        - offset_s;
    // The nearest f64 to whole.frac: Rust's decimal reading rounds correctly, so the
    // instant is rounded once, not once per term.
    let t = if frac.is_empty() {
        whole as f64
    } else if whole >= 0 {
        format!("{whole}.{frac}")
            .parse::<f64>()
            .map_err(|_| String::from("not a number"))?
    } else {
        exact_sum(whole, frac)?
    };
    Ok(Parsed { t, has_offset })
}

/// The nearest f64 to `whole + 0.frac` for `whole < 0` (frac: k decimal digits), as
/// the decimal `-((|whole| − 1).(10^k − frac))` read once, correctly rounded.
fn exact_sum(whole: i64, frac: &str) -> Result<f64, String> {
    let k = frac.len();
    let f: num_bigint::BigUint = frac.parse().map_err(|_| String::from("digits"))?;
    let one = num_bigint::BigUint::from(10u8).pow(k as u32);
    if f == num_bigint::BigUint::from(0u8) {
        return Ok(whole as f64);
    }
    let rest = (one - f).to_string();
    let text = format!("-{}.{rest:0>k$}", whole.unsigned_abs() - 1);
    text.parse::<f64>()
        .map_err(|_| String::from("not a number"))
}

/// Reads an RFC 3339 date-time that must carry its UTC offset.
pub fn rfc3339(text: &str) -> Result<f64, String> {
    let p = parse(text)?;
    if p.has_offset {
        Ok(p.t)
    } else {
        Err(String::from(
            "a date-time needs its UTC offset (Z or ±hh:mm)",
        ))
    }
}

/// Checks epoch seconds given as a number: finite and within years 0000 to 9999. A value
/// too large for seconds is named as possibly milliseconds (MF-JSON's Unix timestamps).
pub fn epoch_seconds(x: f64) -> Result<f64, String> {
    if !x.is_finite() {
        return Err(format!("{x} is not a finite number of seconds"));
    }
    if (FIRST_S..END_S).contains(&x) {
        return Ok(x);
    }
    if (FIRST_S * 1000.0..END_S * 1000.0).contains(&x) {
        return Err(format!(
            "{x} s is beyond the year 9999; epoch times are read in seconds (milliseconds? divide by 1000)"
        ));
    }
    Err(format!("{x} s is outside the years 0000 to 9999"))
}

/// The nearest f64 to `ns`·10⁻⁹ seconds (nanoseconds since the epoch, as numpy's and
/// pandas' `datetime64[ns]` hold them): the instant rounded once, as [`parse`] rounds
/// the same instant written in RFC 3339 with its nanoseconds.
pub fn from_nanos(ns: i64) -> f64 {
    let (whole, frac) = (ns.div_euclid(1_000_000_000), ns.rem_euclid(1_000_000_000));
    if frac == 0 {
        return whole as f64;
    }
    let digits = format!("{frac:09}");
    let text = if whole >= 0 {
        format!("{whole}.{digits}").parse::<f64>().ok()
    } else {
        exact_sum(whole, &digits).ok()
    };
    // Both readings take digits only: they cannot fail; the two-rounding quotient is
    // the fallback all the same.
    text.unwrap_or(ns as f64 / 1e9)
}

/// Which way [`format()`] rounds to whole milliseconds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Round {
    /// Toward the past: the printed instant is ≤ the exact one.
    Floor,
    /// Toward the future: the printed instant is ≥ the exact one.
    Ceil,
    /// To the nearest millisecond (half away from zero): for display, and to write back
    /// a time that was read from whole milliseconds.
    Nearest,
}

/// Epoch seconds as RFC 3339 `YYYY-MM-DDTHH:MM:SS.sssZ`, rounded to whole milliseconds
/// as `round` says, exactly (the f64 is taken as the rational it is), so that an
/// enclosure [lo, hi] printed with `Floor` and `Ceil` still encloses. `None` outside years 0000 to 9999 or
/// for a value that is not finite.
pub fn format(t: f64, round: Round) -> Option<String> {
    if !t.is_finite() {
        return None;
    }
    let ms = BigRational::from_float(t)? * BigRational::from_integer(1000.into());
    let ms = match round {
        Round::Floor => ms.floor(),
        Round::Ceil => ms.ceil(),
        Round::Nearest => ms.round(),
    }
    .to_integer()
    .to_i64()?;
    let days = ms.div_euclid(DAY_S * 1000);
    let in_day = ms.rem_euclid(DAY_S * 1000);
    let (y, m, d) = civil_from_days(days);
    if !(0..=9999).contains(&y) {
        return None;
    }
    let (s, milli) = (in_day / 1000, in_day % 1000);
    Some(format!(
        "{y:04}-{m:02}-{d:02}T{:02}:{:02}:{:02}.{milli:03}Z",
        s / 3600,
        s / 60 % 60,
        s % 60
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn known_instants() {
        for (text, t) in [
            ("1970-01-01T00:00:00Z", 0.0),
            ("2021-10-07T13:00:25Z", 1_633_611_625.0),
            ("2021-10-07 13:00:25+00:00", 1_633_611_625.0),
            ("2021-10-07t15:00:25+02:00", 1_633_611_625.0),
            ("2021-10-07T08:30:25-04:30", 1_633_611_625.0),
            ("2000-02-29T00:00:00Z", 951_782_400.0),
            ("1969-12-31T23:59:59.5Z", -0.5),
            ("1900-01-01T00:00:00Z", -2_208_988_800.0),
            ("0000-01-01T00:00:00Z", FIRST_S),
            ("2038-01-19T03:14:08Z", 2_147_483_648.0),
            ("2021-10-07T13:00:25.125Z", 1_633_611_625.125),
        ] {
            assert_eq!(rfc3339(text), Ok(t), "{text}");
        }
        let p = parse("2021-10-07 13:00:25").expect("naive");
        assert_eq!((p.t, p.has_offset), (1_633_611_625.0, false));
        assert!(rfc3339("2021-10-07 13:00:25").is_err());
    }

    #[test]
    fn the_fraction_is_rounded_once() {
        // 1633611625.1 is not a binary fraction: the nearest f64 to the decimal.
        let t = rfc3339("2021-10-07T13:00:25.1Z").expect("time");
        assert_eq!(t, "1633611625.1".parse::<f64>().expect("f64"));
        let t = rfc3339("1969-12-31T23:59:58.9Z").expect("time");
        assert_eq!(t, "-1.1".parse::<f64>().expect("f64"));
    }

    #[test]
    fn bad_texts_say_why() {
        for (text, why) in [
            ("2021-10-07T13:00:60Z", "leap second"),
            ("2021-02-29T00:00:00Z", "no day 29"),
            ("2021-13-01T00:00:00Z", "month 13"),
            ("2021-10-07T24:00:00Z", "time of day"),
            ("2021-10-07T13:00:25.Z", "decimal point"),
            ("2021-10-07T13:00:25+0200", "±hh:mm"),
            ("2021-10-07T13:00:25+24:00", "offset"),
            ("2021-10-07T13:00:25Zx", "after the date-time"),
            ("2021-10-07", "expected a date-time"),
            ("2021/10/07T13:00:25Z", "expected a date-time"),
            ("", "expected a date-time"),
            ("２021-10-07T13:00:25Z", "expected a date-time"),
        ] {
            let e = parse(text).expect_err(text);
            assert!(e.contains(why), "{text}: {e}");
        }
    }

    #[test]
    fn civil_days_round_trip_over_four_centuries_and_more() {
        let mut day = days_from_civil(1600, 1, 1);
        for y in 1600..2401 {
            for m in 1..=12 {
                for d in 1..=month_days(y, m) {
                    assert_eq!(days_from_civil(y, m, d), day, "{y}-{m}-{d}");
                    assert_eq!(civil_from_days(day), (y, m, d));
                    day += 1;
                }
            }
        }
    }

    #[test]
    fn formatting_rounds_in_the_asked_direction() {
        assert_eq!(
            format(1_633_611_625.0, Round::Floor).as_deref(),
            Some("2021-10-07T13:00:25.000Z")
        );
        let t: f64 = "1633611625.1".parse().expect("f64"); // just below .1
        let lo = format(t, Round::Floor).expect("lo");
        let hi = format(t, Round::Ceil).expect("hi");
        let (tl, th) = (rfc3339(&lo).expect("lo"), rfc3339(&hi).expect("hi"));
        assert!(tl <= t && t <= th, "{lo} {t} {hi}");
        assert_eq!(
            format(-0.0005, Round::Floor).as_deref(),
            Some("1969-12-31T23:59:59.999Z")
        );
        assert_eq!(
            format(-0.0005, Round::Ceil).as_deref(),
            Some("1970-01-01T00:00:00.000Z")
        );
        assert_eq!(
            format(t, Round::Nearest).as_deref(),
            Some("2021-10-07T13:00:25.100Z")
        );
        assert_eq!(format(END_S, Round::Floor), None);
        assert_eq!(format(f64::NAN, Round::Floor), None);
    }

    #[test]
    fn epoch_numbers() {
        assert_eq!(epoch_seconds(1_633_611_625.0), Ok(1_633_611_625.0));
        assert!(epoch_seconds(1_633_611_625_000.0)
            .expect_err("ms")
            .contains("milliseconds"));
        assert!(epoch_seconds(f64::INFINITY).is_err());
    }

    #[test]
    fn nanoseconds_round_as_the_same_instant_written_out() {
        for (ns, text) in [
            (1_633_613_562_123_456_789, "2021-10-07T13:32:42.123456789Z"),
            (1_633_613_562_000_000_000, "2021-10-07T13:32:42Z"),
            (-1, "1969-12-31T23:59:59.999999999Z"),
            (-86_400_000_000_001, "1969-12-30T23:59:59.999999999Z"),
        ] {
            let p = parse(text).expect(text);
            assert_eq!(from_nanos(ns).to_bits(), p.t.to_bits(), "{text}");
        }
    }
}

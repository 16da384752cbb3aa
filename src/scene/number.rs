//! Exact numbers read from case files.
//!
//! A JSON number is the decimal it spells: `0.1` is one tenth, not the f64
//! nearest to it. A string such as `"1/3"` is an exact fraction. Neither ever
//! passes through a float.
//!
//! This module only reads and holds numbers. It does not round, snap or
//! compare geometry: those are decisions, and each rasterizer makes its own.

use std::cmp::Ordering;
use std::fmt;

use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

/// Longest digit string accepted in one number, and largest decimal exponent.
///
/// A case never needs more: coordinates are bounded by `limits::COORD_LIMIT`
/// and 1000 digits is far beyond any precision a rasterizer can use. The bound
/// keeps `1e999999999` from allocating a billion-digit integer.
pub const MAX_DIGITS: usize = 1000;

/// An exact rational number in lowest terms with a positive denominator.
///
/// The invariant is kept by [`RBig`], which reduces on construction.
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Number(RBig);

/// Why a piece of text is not an exact number.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NumberError {
    /// NaN or an infinity, spelled as a string.
    NonFinite(String),
    /// Not a decimal or a fraction.
    Malformed(String),
    /// More digits, or a larger exponent, than [`MAX_DIGITS`].
    TooLong(String),
    /// A fraction with a zero denominator.
    ZeroDenominator(String),
    /// A plus sign, or a sign anywhere but in front (`"+3"`, `"1/-2"`).
    Sign(String),
}

impl fmt::Display for NumberError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NumberError::NonFinite(s) => {
                write!(f, "{} is not finite; coordinates and values must be finite numbers", echo(s))
            }
            NumberError::Malformed(s) => write!(
                f,
                "{} is not an exact number; write a JSON number (12.5, -3e-2) or a fraction string (\"1/3\")",
                echo(s)
            ),
            NumberError::Sign(s) => write!(
                f,
                "{} is not an exact number: a sign may only be a minus in front (\"-1/2\", \"-0.5\"); a plus sign and a signed denominator are refused",
                echo(s)
            ),
            NumberError::TooLong(s) => write!(
                f,
                "{} has more than {MAX_DIGITS} digits or an exponent beyond ±{MAX_DIGITS}",
                abbreviate(s)
            ),
            NumberError::ZeroDenominator(s) => write!(f, "{} has a zero denominator", echo(s)),
        }
    }
}

/// Longest piece of input an error message repeats, in characters.
pub const ECHO_CHARS: usize = 80;

/// `s` as an error message repeats it: quoted, and cut to [`ECHO_CHARS`]
/// characters with "…" and its whole length when it is longer, so that a
/// 50 MB value never fills a message.
pub fn echo(s: &str) -> String {
    match s.char_indices().nth(ECHO_CHARS) {
        None => format!("{s:?}"),
        Some((cut, _)) => format!("{:?}… ({} characters)", &s[..cut], s.chars().count()),
    }
}

/// A number as an error message repeats it: its exact text, cut as
/// [`echo`] cuts (without quotes when whole).
pub fn echo_number(n: &Number) -> String {
    let text = n.to_string();
    if text.chars().count() <= ECHO_CHARS {
        text
    } else {
        echo(&text)
    }
}

fn abbreviate(s: &str) -> String {
    echo(s)
}

impl Number {
    pub const ZERO: Number = Number(RBig::ZERO);
    pub const ONE: Number = Number(RBig::ONE);

    /// Reads the text of a JSON number (`-12.5e3`) as the exact decimal it spells.
    pub fn from_decimal(text: &str) -> Result<Number, NumberError> {
        let malformed = || NumberError::Malformed(text.to_owned());
        let (negative, rest) = match text.strip_prefix('-') {
            Some(r) => (true, r),
            None => (false, text.strip_prefix('+').unwrap_or(text)),
        };
        let (mantissa, exponent) = match rest.find(['e', 'E']) {
            Some(i) => (&rest[..i], Some(&rest[i + 1..])),
            None => (rest, None),
        };
        let (int_part, frac_part) = match mantissa.find('.') {
            Some(i) => (&mantissa[..i], &mantissa[i + 1..]),
            None => (mantissa, ""),
        };
        let all_digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
        if int_part.is_empty() && frac_part.is_empty()
            || !all_digits(int_part)
            || !all_digits(frac_part)
        {
            return Err(malformed());
        }
        if int_part.len() + frac_part.len() > MAX_DIGITS {
            return Err(NumberError::TooLong(text.to_owned()));
        }
        let exponent: i64 = match exponent {
            None => 0,
            Some(e) => {
                let digits = e.strip_prefix(['+', '-']).unwrap_or(e);
                if digits.is_empty() || !all_digits(digits) {
                    return Err(malformed());
                }
                // Any exponent longer than 6 digits is beyond MAX_DIGITS anyway.
                if digits.trim_start_matches('0').len() > 6 {
                    return Err(NumberError::TooLong(text.to_owned()));
                }
                e.parse().map_err(|_| malformed())?
            }
        };
        let digits = format!("{int_part}{frac_part}");
        let mut numerator: IBig = digits.parse::<UBig>().map_err(|_| malformed())?.into();
        if numerator == IBig::ZERO {
            return Ok(Number::ZERO);
        }
        let scale = exponent - frac_part.len() as i64;
        if scale.unsigned_abs() > MAX_DIGITS as u64 {
            return Err(NumberError::TooLong(text.to_owned()));
        }
        if negative {
            numerator = -numerator;
        }
        let power = UBig::from(10u8).pow(scale.unsigned_abs() as usize);
        Ok(if scale >= 0 {
            Number(RBig::from_parts(numerator * IBig::from(power), UBig::ONE))
        } else {
            Number(RBig::from_parts(numerator, power))
        })
    }

    /// Reads a number given as a JSON string: a fraction `"p/q"` or a decimal.
    pub fn from_string(text: &str) -> Result<Number, NumberError> {
        let trimmed = text.trim();
        let lower = trimmed.to_ascii_lowercase();
        let bare = lower.trim_start_matches(['+', '-']);
        if matches!(bare, "nan" | "inf" | "infinity") {
            return Err(NumberError::NonFinite(text.to_owned()));
        }
        // SPEC §1.1: at most one sign, a minus, in front; a denominator is
        // a positive integer. (An exponent's sign is part of a decimal.)
        let (p, q) = trimmed.split_once('/').unwrap_or((trimmed, ""));
        let signed = |t: &str| t.trim_start().starts_with(['+', '-']);
        if trimmed.starts_with('+') || signed(q) || signed(p.strip_prefix('-').unwrap_or(p)) {
            return Err(NumberError::Sign(text.to_owned()));
        }
        match trimmed.split_once('/') {
            None => Number::from_decimal(trimmed),
            Some((p, q)) => {
                let p = Number::from_decimal(p.trim()).map_err(|_| malformed_fraction(text))?;
                let q = Number::from_decimal(q.trim()).map_err(|_| malformed_fraction(text))?;
                if !p.is_integer() || !q.is_integer() {
                    return Err(malformed_fraction(text));
                }
                if q.0 == RBig::ZERO {
                    return Err(NumberError::ZeroDenominator(text.to_owned()));
                }
                Ok(Number(p.0 / q.0))
            }
        }
    }

    /// Makes `numerator / denominator`.
    ///
    /// # Panics
    /// When `denominator` is zero.
    pub fn ratio(numerator: i64, denominator: i64) -> Number {
        assert!(denominator != 0, "Number::ratio with a zero denominator");
        Number(RBig::from_parts_signed(
            numerator.into(),
            denominator.into(),
        ))
    }

    pub fn from_rbig(value: RBig) -> Number {
        Number(value)
    }

    /// The nearest multiple of 2^-bits, ties to even: the snapping of
    /// SPEC.md §2 (D3D11.3 §3.2.4.1 rounds to nearest-even when it converts
    /// to 16.8 fixed point).
    pub fn snapped(&self, bits: u32) -> Number {
        let scaled = self.0.numerator() << bits as usize;
        let den = IBig::from(self.0.denominator().clone());
        // ⌊scaled / den⌋ for den > 0, and twice the remainder against den.
        let (q, r) = (&scaled / &den, &scaled % &den);
        let (q, r) = if r < IBig::ZERO {
            (q - IBig::ONE, r + &den)
        } else {
            (q, r)
        };
        let up = match (r * IBig::from(2u8)).cmp(&den) {
            std::cmp::Ordering::Greater => true,
            std::cmp::Ordering::Equal => (&q % IBig::from(2u8)) != IBig::ZERO,
            std::cmp::Ordering::Less => false,
        };
        let q = if up { q + IBig::ONE } else { q };
        Number(RBig::from_parts(q, UBig::ONE << bits as usize))
    }

    pub fn from_int(value: i64) -> Number {
        Number(RBig::from(value))
    }

    /// The numerator, in lowest terms; it carries the sign.
    pub fn numerator(&self) -> &IBig {
        self.0.numerator()
    }

    /// The denominator, in lowest terms; always positive.
    pub fn denominator(&self) -> &UBig {
        self.0.denominator()
    }

    pub fn as_rbig(&self) -> &RBig {
        &self.0
    }

    pub fn is_integer(&self) -> bool {
        self.0.denominator() == &UBig::ONE
    }

    pub fn is_zero(&self) -> bool {
        self.0 == RBig::ZERO
    }

    pub fn is_positive(&self) -> bool {
        self.0 > RBig::ZERO
    }

    pub fn abs(&self) -> Number {
        if self.0 < RBig::ZERO {
            Number(-self.0.clone())
        } else {
            self.clone()
        }
    }

    /// The nearest f64, for display and for adapters that take floats.
    /// Never used on a decision path.
    pub fn to_f64_lossy(&self) -> f64 {
        self.0.to_f64().value()
    }

    /// The number written as a short exact string: an integer, a terminating
    /// decimal, or `p/q`.
    pub fn to_exact_string(&self) -> String {
        let den = self.0.denominator();
        if den == &UBig::ONE {
            return self.0.numerator().to_string();
        }
        // A decimal terminates when the denominator is 2^a 5^b.
        let mut rest = den.clone();
        let (mut twos, mut fives) = (0usize, 0usize);
        while (&rest % 2u8) == 0u8 {
            rest /= 2u8;
            twos += 1;
        }
        while (&rest % 5u8) == 0u8 {
            rest /= 5u8;
            fives += 1;
        }
        if rest != UBig::ONE || twos.max(fives) > 40 {
            return format!("{}/{}", self.0.numerator(), den);
        }
        let places = twos.max(fives);
        let scaled =
            self.0.numerator() * IBig::from(UBig::from(10u8).pow(places)) / IBig::from(den.clone());
        let negative = scaled < IBig::ZERO;
        let digits = if negative {
            (-scaled).to_string()
        } else {
            scaled.to_string()
        };
        let digits = format!("{digits:0>width$}", width = places + 1);
        let (int, frac) = digits.split_at(digits.len() - places);
        format!("{}{int}.{frac}", if negative { "-" } else { "" })
    }
}

fn malformed_fraction(text: &str) -> NumberError {
    NumberError::Malformed(text.to_owned())
}

impl std::ops::Add for &Number {
    type Output = Number;
    fn add(self, other: &Number) -> Number {
        Number(&self.0 + &other.0)
    }
}

impl std::ops::Sub for &Number {
    type Output = Number;
    fn sub(self, other: &Number) -> Number {
        Number(&self.0 - &other.0)
    }
}

impl std::ops::Neg for Number {
    type Output = Number;
    fn neg(self) -> Number {
        Number(-self.0)
    }
}

impl PartialOrd for Number {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Number {
    fn cmp(&self, other: &Self) -> Ordering {
        self.0.cmp(&other.0)
    }
}

impl fmt::Display for Number {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_exact_string())
    }
}

impl fmt::Debug for Number {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Number({})", self.to_exact_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dec(s: &str) -> Number {
        Number::from_decimal(s).unwrap()
    }

    #[test]
    fn decimals_are_exact() {
        assert_eq!(dec("0.1"), Number::ratio(1, 10));
        assert_eq!(dec("-12.5"), Number::ratio(-25, 2));
        assert_eq!(dec("1e2"), Number::from_int(100));
        assert_eq!(dec("1.5E-1"), Number::ratio(3, 20));
        assert_eq!(dec("0e999999"), Number::ZERO);
        assert_ne!(
            dec("0.1").to_f64_lossy().to_string(),
            "0.1000000000000000055511151231257827"
        );
    }

    #[test]
    fn fractions_are_exact() {
        assert_eq!(Number::from_string("1/3").unwrap(), Number::ratio(1, 3));
        assert_eq!(Number::from_string(" -6/4 ").unwrap(), Number::ratio(-3, 2));
        assert_eq!(Number::from_string("2.5").unwrap(), Number::ratio(5, 2));
    }

    #[test]
    fn bad_numbers_are_refused() {
        assert!(matches!(
            Number::from_string("NaN"),
            Err(NumberError::NonFinite(_))
        ));
        assert!(matches!(
            Number::from_string("-Infinity"),
            Err(NumberError::NonFinite(_))
        ));
        assert!(matches!(
            Number::from_string("1/0"),
            Err(NumberError::ZeroDenominator(_))
        ));
        assert!(matches!(
            Number::from_string("1/2.5"),
            Err(NumberError::Malformed(_))
        ));
        for signed in ["+3", "1/-2", "-1/-2", "1/+2", "+1/2", "--1", "- -1"] {
            assert!(
                matches!(Number::from_string(signed), Err(NumberError::Sign(_))),
                "{signed}"
            );
        }
        assert_eq!(Number::from_string("-1/2"), Ok(Number::ratio(-1, 2)));
        assert_eq!(Number::from_string("-2.5e+1"), Ok(Number::from_int(-25)));
        assert!(matches!(
            Number::from_string("abc"),
            Err(NumberError::Malformed(_))
        ));
        assert!(matches!(
            Number::from_decimal("1e9999999"),
            Err(NumberError::TooLong(_))
        ));
        assert!(matches!(
            Number::from_decimal("1e-1001"),
            Err(NumberError::TooLong(_))
        ));
    }

    #[test]
    fn echoes_are_cut() {
        assert_eq!(echo("12"), "\"12\"");
        let long = "é".repeat(1000);
        let shown = echo(&long);
        assert!(shown.ends_with("… (1000 characters)"), "{shown}");
        assert_eq!(
            shown.chars().count(),
            ECHO_CHARS + 2 + "… (1000 characters)".chars().count()
        );
    }

    #[test]
    fn exact_strings_round_trip() {
        for s in ["0", "-3", "0.1", "-12.5", "1/3", "-7/6", "0.00390625"] {
            let n = Number::from_string(s).unwrap();
            assert_eq!(n.to_exact_string(), s);
        }
    }
}

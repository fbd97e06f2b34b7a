//! A number as a message shows it: a value the user gave, read back to them. Rust's `{}` writes
//! an `f64` in full positional notation, so `1e300` became 301 digits in an error message;
//! [`Shown`] writes magnitudes outside [1e-4, 1e9) in scientific notation instead, and any
//! other value exactly as `{}` (or `{:.N}`) would.

use std::fmt;

/// `v`, for an error message (precision honoured: `{:.4}` as for an `f64`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shown(pub f64);

impl fmt::Display for Shown {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        let plain = v == 0.0 || !v.is_finite() || (1e-4..1e9).contains(&v.abs());
        match (plain, f.precision()) {
            (true, Some(p)) => write!(f, "{v:.p$}"),
            (true, None) => write!(f, "{v}"),
            (false, Some(p)) => write!(f, "{v:.p$e}"),
            (false, None) => write!(f, "{v:e}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Shown;

    #[test]
    fn huge_and_tiny_values_are_short_and_the_rest_unchanged() {
        assert_eq!(Shown(1e300).to_string(), "1e300");
        assert_eq!(format!("{:.4}", Shown(-1e300)), "-1.0000e300");
        assert_eq!(Shown(2.5e-9).to_string(), "2.5e-9");
        assert_eq!(Shown(0.3).to_string(), "0.3");
        assert_eq!(format!("{:.4}", Shown(0.5)), "0.5000");
        assert_eq!(Shown(16.0).to_string(), "16");
        assert_eq!(Shown(0.0).to_string(), "0");
        assert_eq!(Shown(f64::NAN).to_string(), "NaN");
        assert_eq!(Shown(f64::NEG_INFINITY).to_string(), "-inf");
    }
}

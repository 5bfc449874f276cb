//! A command line's count (`--max-solver-work 1.2e9`, `--max-people
//! 100000`): a whole number, written out or in scientific notation, from 1
//! to a ceiling. `reach check --estimate` suggests bounds as `1.2e9`, and
//! the same text must work as the flag.

use std::ffi::OsStr;

use clap::builder::TypedValueParser;
use clap::error::ErrorKind;

/// Counts from 1 to `.0`.
#[derive(Clone, Copy, Debug)]
pub struct Count(pub u64);

impl TypedValueParser for Count {
    type Value = u64;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &OsStr,
    ) -> Result<u64, clap::Error> {
        let text = value.to_string_lossy();
        let name = arg
            .and_then(clap::Arg::get_long)
            .map_or_else(|| "the value".to_string(), |long| format!("--{long}"));
        let ceiling = self.0;
        let checked = whole(&text).filter(|n| (1..=ceiling).contains(n)).ok_or_else(|| {
            format!("`{text}` for {name} is not a whole number from 1 to {ceiling} (written as 250000000 or 2.5e8)")
        });
        checked.map_err(|why| {
            clap::Error::raw(ErrorKind::ValueValidation, format!("{why}\n")).with_cmd(cmd)
        })
    }
}

/// `text` as a whole number: digits (`250000000`), or a mantissa and a
/// power of ten whose product is whole (`2.5e8`, `3E6`, `.5e1`), with a
/// `+` before either if need be; none otherwise.
fn whole(text: &str) -> Option<u64> {
    let text = text.trim();
    let text = text.strip_prefix('+').unwrap_or(text);
    let (mantissa, exponent) = match text.split_once(['e', 'E']) {
        Some((mantissa, exponent)) => (mantissa, exponent.strip_prefix('+').unwrap_or(exponent)),
        None => (text, "0"),
    };
    let digits_only = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    let (units, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let written = !(units.is_empty() && fraction.is_empty());
    if !written || !digits_only(units) || !digits_only(fraction) || !digits_only(exponent) {
        return None;
    }
    let exponent: u32 = exponent.parse().ok()?;
    // The fraction's digits beyond the exponent must be zeros.
    let places = u32::try_from(fraction.len()).ok()?;
    let shift = exponent.checked_sub(places).map_or_else(
        || {
            fraction[exponent as usize..]
                .bytes()
                .all(|b| b == b'0')
                .then_some(0)
        },
        Some,
    )?;
    let kept = &fraction[..fraction.len().min(exponent as usize)];
    let joined: u64 = format!("{units}{kept}").parse().ok()?;
    joined.checked_mul(10u64.checked_pow(shift)?)
}

#[cfg(test)]
mod tests {
    use super::whole;

    #[test]
    fn counts_are_read_written_out_and_in_scientific_notation() {
        let table: [(&str, Option<u64>); 23] = [
            ("250000000", Some(250_000_000)),
            ("+2.5e8", Some(250_000_000)),
            ("100.0", Some(100)),
            (".5e1", Some(5)),
            ("1.e3", Some(1_000)),
            ("2e++8", None),
            ("++5", None),
            ("e", None),
            (".e3", None),
            ("1e4294967295", None),
            ("2.5e8", Some(250_000_000)),
            ("1.2e9", Some(1_200_000_000)),
            ("3E6", Some(3_000_000)),
            ("1e0", Some(1)),
            ("2e+3", Some(2_000)),
            ("1.50e2", Some(150)),
            ("1.25e1", None),
            ("1.5", None),
            ("e9", None),
            ("-1e3", None),
            ("1e-3", None),
            ("9e19", None),
            ("1.2.3e4", None),
        ];
        for (text, wanted) in table {
            assert_eq!(whole(text), wanted, "{text}");
        }
    }
}

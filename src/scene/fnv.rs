//! FNV-1a, the 64-bit hash of seeds and of the page's stamp: small, and
//! stable across Rust versions and machines (unlike std's hasher), so the
//! same scenario draws the same starts everywhere.

/// FNV-1a of `bytes`, its offset basis mixed with `seed` (0: plain FNV-1a).
pub fn fnv1a(seed: u64, bytes: impl IntoIterator<Item = u8>) -> u64 {
    bytes
        .into_iter()
        .fold(0xcbf2_9ce4_8422_2325 ^ seed, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn it_is_fnv_1a() {
        // The published 64-bit FNV-1a of "" and of "a".
        assert_eq!(fnv1a(0, []), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a(0, *b"a"), 0xaf63_dc4c_8601_ec8c);
    }
}

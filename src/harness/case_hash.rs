//! A case file's bytes hashed, for `report.json`'s `hash`: reports merged
//! by case id (`rastercheck merge`) compare it to refuse two different
//! files behind one id. FNV-1a over 64 bits (Fowler, Noll, Vo): not a
//! defence against a forger, which a report needs none of, but two edited
//! versions of one case collide with probability 2^-64.

/// FNV-1a's 64-bit offset basis and prime.
const OFFSET_BASIS: u64 = 0xcbf2_9ce4_8422_2325;
const PRIME: u64 = 0x0000_0100_0000_01b3;

/// `fnv1a64:` and the hash of `bytes` in 16 lowercase hex digits.
pub fn case_hash(bytes: &[u8]) -> String {
    let hash = bytes
        .iter()
        .fold(OFFSET_BASIS, |h, &b| (h ^ u64::from(b)).wrapping_mul(PRIME));
    format!("fnv1a64:{hash:016x}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn known_values() {
        // The published FNV-1a test vectors.
        assert_eq!(case_hash(b""), "fnv1a64:cbf29ce484222325");
        assert_eq!(case_hash(b"a"), "fnv1a64:af63dc4c8601ec8c");
        assert_eq!(case_hash(b"foobar"), "fnv1a64:85944171f73967e8");
    }
}

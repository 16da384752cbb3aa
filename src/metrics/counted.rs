//! A count said in words: the number and its noun phrase in the number the
//! count takes ("1 sample differs", "2 samples differ"), for the reasons,
//! console lines and findings that count things.

/// `n` and `one` when `n` is 1, else `n` and `many`: "1 fragment",
/// "0 fragments", "2 fragments". The phrases may carry their verb, so that
/// it agrees too ("hole is", "holes are").
pub fn counted(n: impl Into<u64>, one: &str, many: &str) -> String {
    let n = n.into();
    format!("{n} {}", if n == 1 { one } else { many })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_takes_the_singular_and_every_other_count_the_plural() {
        assert_eq!(
            counted(1u64, "line differs", "lines differ"),
            "1 line differs"
        );
        assert_eq!(
            counted(0u32, "line differs", "lines differ"),
            "0 lines differ"
        );
        assert_eq!(
            counted(2u8, "line differs", "lines differ"),
            "2 lines differ"
        );
    }
}

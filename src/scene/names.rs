//! The words a case file uses for a closed set of conventions: one macro,
//! so that each convention's words are written once.

/// The words a case file uses for a closed set of conventions, from one
/// list: `ALL` in the order given, `name`, and its inverse `from_name`.
macro_rules! case_names {
    ($ty:ident { $($variant:ident => $name:literal),+ $(,)? }) => {
        impl $ty {
            /// Every value, in the documented order.
            pub const ALL: [$ty; [$($name),+].len()] = [$($ty::$variant),+];

            /// Every value's word, in the same order (for error messages).
            pub const NAMES: [&'static str; [$($name),+].len()] = [$($name),+];

            /// The word a case file uses for this value.
            pub fn name(self) -> &'static str {
                match self {
                    $($ty::$variant => $name),+
                }
            }

            /// The value a case file's word names, if any.
            pub fn from_name(name: &str) -> Option<$ty> {
                $ty::ALL.into_iter().find(|v| v.name() == name)
            }
        }
    };
}

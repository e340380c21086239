//! Structs whose field list is written once and declared twice: a query's answer in the
//! core and its C mirror in `ffi` (`che_summary`, `chf_memory`, ...), with the same names,
//! docs and order, so that a field added to one is in the other. The core's module keeps
//! the list in a macro that hands it to [`fields_struct!`] with the head of the struct it
//! declares.

/// Declares `struct $name` with the fields given (all `pub`); with `from $core`, also the
/// conversion from the core's struct of the same fields (each converted with `as`: the C
/// side widens counts to 64 bits).
macro_rules! fields_struct {
    (
        $(#[$attr:meta])* $vis:vis struct $name:ident
        { $($(#[$doc:meta])* $field:ident: $ty:ty),* $(,)? }
    ) => {
        $(#[$attr])*
        $vis struct $name {
            $($(#[$doc])* pub $field: $ty,)*
        }
    };
    (
        $(#[$attr:meta])* $vis:vis struct $name:ident from $core:ty
        { $($(#[$doc:meta])* $field:ident: $ty:ty),* $(,)? }
    ) => {
        $crate::util::fields::fields_struct! {
            $(#[$attr])* $vis struct $name { $($(#[$doc])* $field: $ty),* }
        }
        impl From<&$core> for $name {
            #[allow(clippy::unnecessary_cast, reason = "some fields are already 64-bit")]
            fn from(x: &$core) -> Self {
                $name { $($field: x.$field as _),* }
            }
        }
    };
}
pub(crate) use fields_struct;

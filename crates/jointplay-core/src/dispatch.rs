//! The dispatch of an enum of kinds (body kinds, element kinds): `forward!`
//! implements a trait for the enum by forwarding each listed method to the
//! kind a variant holds, with one `match` over the kinds.

/// Implements each listed method `fn name(&self, arg: Type, ...) -> Ret;`
/// (attributes kept) as a `match` over the variants `[$kind ...]` of `Self`,
/// calling the same method of the value the variant holds.
macro_rules! forward {
    ($kinds:tt;) => {};
    ($kinds:tt; $(#[$attr:meta])* fn $name:ident(&self $(, $arg:ident: $ty:ty)*) $(-> $ret:ty)?; $($rest:tt)*) => {
        $(#[$attr])*
        fn $name(&self $(, $arg: $ty)*) $(-> $ret)? {
            $crate::dispatch::forward!(@match self, $kinds, $name($($arg),*))
        }
        $crate::dispatch::forward!($kinds; $($rest)*);
    };
    (@match $self:ident, [$($kind:ident)+], $name:ident $args:tt) => {
        match $self {
            $(Self::$kind(kind) => kind.$name $args,)+
        }
    };
}

pub(crate) use forward;

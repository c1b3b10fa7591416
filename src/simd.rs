//! Hot loops compiled twice, for baseline x86-64 (SSE2) and for AVX2, the
//! second chosen at run time where the CPU has it. Only the vectors' width
//! changes (no fused multiply-add is enabled), so both give the same bits.

/// Declares `fn NAME(ARGS) -> R { BODY }` whose body, with what it inlines,
/// is also compiled for AVX2 and runs so where the CPU has it.
macro_rules! avx2_where_there {
    ($(#[$meta:meta])* $vis:vis fn $name:ident($($arg:ident: $ty:ty),* $(,)?) $(-> $ret:ty)? $body:block) => {
        $(#[$meta])*
        $vis fn $name($($arg: $ty),*) $(-> $ret)? {
            #[inline(always)]
            fn lanes($($arg: $ty),*) $(-> $ret)? $body
            #[cfg(target_arch = "x86_64")]
            #[target_feature(enable = "avx2")]
            unsafe fn avx2($($arg: $ty),*) $(-> $ret)? {
                lanes($($arg),*)
            }
            #[cfg(target_arch = "x86_64")]
            if std::arch::is_x86_feature_detected!("avx2") {
                // SAFETY: the CPU has AVX2, checked just above.
                return unsafe { avx2($($arg),*) };
            }
            lanes($($arg),*)
        }
    };
}
pub(crate) use avx2_where_there;

#![no_main]
// The checks live in rastercheck::explore::fuzz::targets::exact_arithmetic.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    rastercheck::explore::fuzz::targets::exact_arithmetic(data);
});

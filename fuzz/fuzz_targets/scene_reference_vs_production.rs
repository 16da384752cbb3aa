#![no_main]
// The checks live in rastercheck::explore::fuzz::targets::scene_reference_vs_production.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    rastercheck::explore::fuzz::targets::scene_reference_vs_production(data);
});

#![no_main]
// The checks live in rastercheck::explore::fuzz::targets::protocol_response.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    rastercheck::explore::fuzz::targets::protocol_response(data);
});

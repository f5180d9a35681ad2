#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| qsic_fuzz::library::parse_expression(data));

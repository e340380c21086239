//! The Ply reader on arbitrary bytes; what it accepts must have ids in range and build.
#![no_main]

mod common;

use libfuzzer_sys::fuzz_target;
use topomesh::io::Format;

fuzz_target!(|data: &[u8]| common::check_parse(data, Format::Ply, "fuzz.ply"));

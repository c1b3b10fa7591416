//! Whether this build has ISA-L's igzip (src/io/deflate.rs): `cfg(isal)` when
//! the `isal` feature is on and vendor/isal-sys could build ISA-L; when its
//! build tools were missing, a warning, and ZIP output is libdeflate's alone.

use std::env;

fn main() {
    println!("cargo::rustc-check-cfg=cfg(isal)");
    if env::var_os("CARGO_FEATURE_ISAL").is_none() {
        return;
    }
    if env::var("DEP_ISAL_BUILT").as_deref() == Ok("1") {
        println!("cargo::rustc-cfg=isal");
        return;
    }
    let missing = env::var("DEP_ISAL_MISSING").unwrap_or_default();
    println!(
        "cargo::warning=ISA-L left out: {missing} not found on PATH. ZIP output is \
         libdeflate's alone (same pixels, different bytes from a build with ISA-L, \
         more CPU on grainy plates; README.md, set-up). For ISA-L: apt-get install nasm \
         autoconf automake libtool make, then cargo clean -p isal-sys"
    );
}

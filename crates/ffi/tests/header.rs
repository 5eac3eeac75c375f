//! The checked-in C header is the one cbindgen generates from src/lib.rs (extends the
//! C interface's build; no paper section). cbindgen runs as a library here, so the check
//! needs no installed tool and never skips: a stale header fails CI.
//! `UPDATE_HEADER=1 cargo test -p polyguard-ffi --test header` rewrites it.

use std::path::Path;

#[test]
fn the_checked_in_header_is_current() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(crate_dir.join("cbindgen.toml"))
        .expect("crates/ffi/cbindgen.toml reads");
    let mut generated = Vec::new();
    cbindgen::Builder::new()
        .with_crate(crate_dir)
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header")
        .write(&mut generated);
    let generated = String::from_utf8(generated).expect("the header is UTF-8");
    let path = crate_dir.join("include/polyguard.h");
    if std::env::var_os("UPDATE_HEADER").is_some() {
        std::fs::write(&path, &generated).expect("include/polyguard.h writes");
        return;
    }
    let checked_in = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        checked_in == generated,
        "crates/ffi/include/polyguard.h differs from what cbindgen generates from \
         src/lib.rs; run `UPDATE_HEADER=1 cargo test -p polyguard-ffi --test header` \
         and commit the header"
    );
}

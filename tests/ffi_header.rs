//! The committed C header `include/lamella.h` must be exactly what cbindgen generates from
//! `src/ffi/` with `cbindgen.toml` now. Run with `LAMELLA_UPDATE_HEADER=1` to rewrite it.

use std::path::Path;

#[test]
fn committed_header_matches_the_rust_source() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(root.join("cbindgen.toml")).expect("cbindgen.toml parses");
    let bindings = cbindgen::Builder::new()
        .with_config(config)
        .with_src(root.join("src/ffi/mod.rs"))
        .generate()
        .expect("cbindgen generates the header");
    let mut generated = Vec::new();
    bindings.write(&mut generated);
    let generated = String::from_utf8(generated).expect("the header is UTF-8");
    let header = root.join("include/lamella.h");
    if std::env::var_os("LAMELLA_UPDATE_HEADER").is_some_and(|v| v == "1") {
        std::fs::write(&header, &generated).expect("include/lamella.h is writable");
    }
    let committed = std::fs::read_to_string(&header).unwrap_or_default();
    assert!(
        committed == generated,
        "include/lamella.h is stale: run `LAMELLA_UPDATE_HEADER=1 cargo test --test ffi_header` and commit it"
    );
}

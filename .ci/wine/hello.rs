// Smoke test of the CI Wine prefix (.ci/windows builds it with plain rustc, no cargo, and runs
// it before the real build). A HashMap's RandomState takes its keys from ProcessPrng in
// bcryptprimitives.dll: without the shim in the prefix this exe does not even load.
use std::collections::HashMap;

fn main() {
    let mut m = HashMap::new();
    m.insert("wine", std::env::var("PLCSH_WINE").unwrap_or_default());
    println!("hello from Windows, PLCSH_WINE={}", m["wine"]);
}

//! Every `scripts/*.lua` runs with the real binary against the default simulator in stepped
//! time and must exit 0: the scripts assert their own outcomes.
//! A script whose expectation is made wrong must fail with exit status 1, naming the line.

mod common;
use common::*;
use std::path::{Path, PathBuf};

fn scripts() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scripts");
    let mut v: Vec<_> = std::fs::read_dir(&dir)
        .expect("scripts/")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "lua"))
        .collect();
    v.sort();
    v
}

fn run_script(path: &Path) -> std::process::Output {
    run(&["--time", "stepped", "run", path.to_str().unwrap()], "")
}

#[test]
fn every_script_runs_and_passes_its_checks() {
    let all = scripts();
    assert!(all.len() >= 10, "the example scripts are all there");
    let mut failed = Vec::new();
    for path in &all {
        let name = path.file_name().unwrap().to_str().unwrap();
        let o = run_script(path);
        if !o.status.success() {
            failed.push(format!("{name} ({:?}):\n{}\n{}", o.status, stdout(&o), String::from_utf8_lossy(&o.stderr)));
        }
    }
    assert!(failed.is_empty(), "{} script(s) failed:\n{}", failed.len(), failed.join("\n"));
}

/// The scripts' checks can fail: a copy of `name` with `from` replaced by `to` exits 1 and
/// reports the failed check at the line holding `at` (`from`'s line when `at` is empty).
fn fails_when_changed(name: &str, from: &str, to: &str, at: &str, expect: &str) {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("scripts").join(name);
    let code = std::fs::read_to_string(&src).unwrap();
    assert!(code.contains(from), "{name} no longer contains `{from}`");
    let at = if at.is_empty() { from } else { at };
    let line = code[..code.find(at).expect("`at` is in the script")].matches('\n').count() + 1;
    let dir = std::env::temp_dir().join(format!("plcsh-scripts-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, code.replacen(from, to, 1)).unwrap();
    // `require` finds lib/ through the project path, not the script's directory.
    let o = run_script(&p);
    let out = common::both(&o);
    assert_eq!(o.status.code(), Some(1), "{name} with `{to}` must fail:\n{out}");
    assert!(out.contains(&format!("{}:{line}:", p.display())), "{name}: the failing line {line} is named:\n{out}");
    assert!(out.contains(expect), "{name}: `{expect}` in:\n{out}");
}

#[test]
fn a_wrong_expectation_fails_the_script_with_exit_status_1() {
    fails_when_changed(
        "pto_single_segment.lua",
        "plcsh.assert_eq(plc.SMD212, 998,",
        "plcsh.assert_eq(plc.SMD212, 999,",
        "",
        "actual:   998",
    );
    fails_when_changed("pto_profile_ramp.lua", "plc.SMD212, pulses,", "plc.SMD212, pulses + 1,", "", "expected: 14201");
    fails_when_changed(
        "fx_blink.lua",
        "plcsh.assert_eq(fx.TN0, 30,",
        "plcsh.assert_eq(fx.TN0, 31,",
        "",
        "actual:   30",
    );
    fails_when_changed(
        "hsc_quadrature_multi_pv.lua",
        "{ number = 66, pv = 3, cv = 2110 }",
        "{ number = 66, pv = 3, cv = 2111 }",
        "plcsh.assert_eq(e.time_us,",
        "expected: 503500",
    );
    fails_when_changed(
        "rtc_from_host.lua",
        "\"2026-11-22T10:01:30\"",
        "\"2026-11-22T10:01:31\"",
        "",
        "actual:   \"2026-11-22T10:01:30\"",
    ); // One script, two families: the K2 readback checks what was read from the FX.
    fails_when_changed(
        "fx_recipe_to_k2.lua",
        "400 + 2 * (i - 1)",
        "402 + 2 * (i - 1)",
        "\"setpoints copied\"",
        "expected: {1200, 850, 40, -15, 300, 0, 7, 2500}",
    );
}

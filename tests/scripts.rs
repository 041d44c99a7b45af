//! Every `scripts/*.lua` runs with the real binary against the default simulator in stepped
//! time and must exit 0: the scripts assert their own outcomes (issue 7, "what it must show").

mod common;
use common::*;
use std::path::Path;

/// TEMPORARY: scripts that need commands from other branches (K2 pulse/counter/RTC/E2PROM
/// helpers, the servo drive). The integrator empties this list after the merge.
const NOT_RUNNABLE_UNTIL_MERGE: &[&str] = &[
    "pto_single_segment.lua",
    "pto_profile_ramp.lua",
    "hsc_quadrature_multi_pv.lua",
    "servo_move.lua",
    "eeprom_backup.lua",
    "rtc_from_host.lua",
    "k2_and_servo.lua",
];

fn scripts() -> Vec<std::path::PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scripts");
    let mut v: Vec<_> = std::fs::read_dir(&dir)
        .expect("scripts/")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "lua"))
        .collect();
    v.sort();
    v
}

#[test]
fn every_script_runs_and_passes_its_checks() {
    let all = scripts();
    assert!(all.len() >= 10, "the issue's example scripts are all there");
    let mut ran = 0;
    for path in &all {
        let name = path.file_name().unwrap().to_str().unwrap();
        if NOT_RUNNABLE_UNTIL_MERGE.contains(&name) {
            continue;
        }
        let o = run(&["--time", "stepped", "run", path.to_str().unwrap()], "");
        assert!(
            o.status.success(),
            "{name} failed ({:?}):\n{}\n{}",
            o.status,
            stdout(&o),
            String::from_utf8_lossy(&o.stderr)
        );
        ran += 1;
    }
    assert!(ran >= 3, "at least the scripts runnable on this branch ran");
}

#[test]
fn the_skip_list_names_only_existing_scripts() {
    let names: Vec<String> = scripts().iter().map(|p| p.file_name().unwrap().to_string_lossy().into_owned()).collect();
    for s in NOT_RUNNABLE_UNTIL_MERGE {
        assert!(names.iter().any(|n| n == s), "{s} is in the skip list but not in scripts/");
    }
}

//! `sim program` reports what the CPU recorded: a division by zero as a normal error with the
//! Err LED on while the CPU keeps running (K2 §2.2.1, K80S 5.3.4), and a STOP caused by the
//! program's STOP instruction (K80S 5.4.5).

mod common;
use common::*;

#[test]
fn sim_program_shows_normal_errors_and_a_program_stop() {
    let dir = std::env::temp_dir().join(format!("plcsh-status-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let il = dir.join("div.il");
    std::fs::write(&il, "LD %SM0.0\nDIV %VW0, %VW2\nLD %I0.0\nSTOP\n").unwrap();
    let script = format!(
        "sim program load {}\nsim step 10ms\nsim program\nset I0.0=1\nsim step 10ms\nsim program\n",
        il.display()
    );
    let o = run(&["--json", "--time", "stepped", "--device", "sim:K205-16DT"], &script);
    let l = json_lines(&o);
    assert!(l.iter().all(|x| x["ok"] == true), "{}", both(&o));
    let st = &l[2];
    assert_eq!(st["mode"], "RUN", "the CPU continues: {st}");
    assert_eq!(st["err_led"], true);
    assert_eq!(st["errors"][0]["code"], 5, "{st}");
    assert_eq!(st["errors"][0]["line"], 2);
    assert!(st["error_count"].as_u64().unwrap() >= 10, "{st}");
    assert_eq!(l[5]["mode"], "STOP", "{}", l[5]);
    let o = run(&["--time", "stepped", "--device", "sim:K205-16DT"], &script);
    let text = stdout(&o);
    assert!(text.contains("Err LED on") && text.contains("division by zero"), "{text}");
    assert!(text.contains("stopped by the program's STOP instruction"), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `sim snapshot save` / `restore` keep what `sim program` reports: the normal-error records
/// with the Err LED (K2 §2.2.1: the code is saved) and the program's STOP (K80S 5.4.5).
#[test]
fn a_snapshot_keeps_the_err_led_and_the_program_stop() {
    let dir = std::env::temp_dir().join(format!("plcsh-status-snap-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let il = dir.join("div.il");
    std::fs::write(&il, "LD %SM0.0\nDIV %VW0, %VW2\nLD %I0.0\nSTOP\n").unwrap();
    let script = format!(
        "sim program load {}\nsim step 10ms\nset I0.0=1\nsim step 10ms\nsim program\nsim snapshot save st\n\
         sim program load {}\nsim step 10ms\nsim snapshot restore st\nsim program\n",
        il.display(),
        il.display()
    );
    let o = plcsh()
        .env("PLCSH_SNAPSHOTS", &dir)
        .args(["--json", "--time", "stepped", "--device", "sim:K205-16DT"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .map(|c| output_with_input(c, script.as_bytes()))
        .unwrap();
    let l = json_lines(&o);
    assert!(l.iter().all(|x| x["ok"] == true), "{}", both(&o));
    let (before, after) = (&l[4], &l[9]);
    assert_eq!(before["mode"], "STOP", "{before}");
    for k in ["mode", "err_led", "errors", "error_count", "faults"] {
        assert_eq!(before[k], after[k], "{k} came back: {after}");
    }
    assert_eq!(after["err_led"], true);
    let text = stdout(&run(
        &["--time", "stepped", "--device", "sim:K205-16DT"],
        &format!("sim program load {}\nsim step 10ms\nset I0.0=1\nsim step 10ms\nsim program\n", il.display()),
    ));
    assert!(text.contains("stopped by the program's STOP instruction"), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// K2 §2.2.1's table through the shell: switch RUN + command RUN = RUN, every other pair
/// STOP, in either order of setting them.
#[test]
fn the_switch_and_command_table_through_the_shell() {
    let dir = std::env::temp_dir().join(format!("plcsh-status-switch-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let il = dir.join("n.il");
    std::fs::write(&il, "LD %SM0.0\nINC %VW0\n").unwrap();
    for (switch, command, want) in
        [("run", "run", "RUN"), ("run", "stop", "STOP"), ("stop", "run", "STOP"), ("stop", "stop", "STOP")]
    {
        for switch_first in [true, false] {
            let (a, b) = (format!("sim switch {switch}"), format!("sim cpu {command}"));
            let (first, second) = if switch_first { (a, b) } else { (b, a) };
            let script = format!("sim program load {}\n{first}\n{second}\nsim program\n", il.display());
            let o = run(&["--json", "--time", "stepped", "--device", "sim:K205-16DT"], &script);
            let l = json_lines(&o);
            let st = l.iter().rev().find(|x| x.get("mode").is_some()).unwrap_or_else(|| panic!("{}", both(&o)));
            assert_eq!(st["mode"], want, "switch {switch}, command {command} ({first}; {second}): {}", both(&o));
            // The refusal (a RUN command with the switch at STOP) says why.
            if switch == "stop" && command == "run" && switch_first {
                assert!(both(&o).to_ascii_lowercase().contains("switch"), "{}", both(&o));
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

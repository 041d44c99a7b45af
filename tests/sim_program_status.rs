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

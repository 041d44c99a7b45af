//! IL programs in the simulator from the outside: `sim serve --program` serves a K2 whose
//! CPU runs the program (read over Modbus TCP by another plcsh process), a load error is one
//! clear message naming file, line and column, and the shell's `sim program` commands.

mod common;
use common::*;

fn write_program(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("plcsh-program-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn a_served_k2_runs_its_program_between_modbus_requests() {
    let p = write_program("count.il", "LD %SM0.0\nINC %VW0\nLD %M0.0\n= %Q0.0\n");
    let served = serve(&["--tcp", "0", "--program", p.to_str().unwrap()]);
    assert!(served.ready["program"].as_str().unwrap().ends_with("count.il"));
    let url = format!("tcp://{}?model=K205-16DT", served.ready["tcp"].as_str().unwrap());
    let get = |line: &str| {
        let o = run(&["--json", "--device", &url, "-c", line], "");
        json_lines(&o).last().cloned().unwrap()
    };
    // The program scans between requests: the count moves on (waited for, however slowly a
    // loaded machine schedules the server).
    let a = get("get VW0")["values"][0]["value"].as_i64().unwrap();
    let start = std::time::Instant::now();
    let mut b = a;
    while b <= a {
        assert!(start.elapsed() < std::time::Duration::from_secs(20), "the program never scanned: {a} then {b}");
        std::thread::sleep(std::time::Duration::from_millis(20));
        b = get("get VW0")["values"][0]["value"].as_i64().unwrap();
    }
    // A coil written over Modbus is seen by the next scan: Q0.0 := M0.0.
    assert_eq!(get("get Q0.0")["values"][0]["value"], false);
    get("set M0.0=1");
    let start = std::time::Instant::now();
    while get("get Q0.0")["values"][0]["value"] != true {
        assert!(start.elapsed() < std::time::Duration::from_secs(20), "Q0.0 never followed M0.0");
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
}

#[test]
fn a_load_error_names_file_line_and_column() {
    let p = write_program("bad.il", "LD %SM0.0\nMOVE 1, %VW0\n  TONN T37, 10\n");
    let o = run(&["--json", "--time", "stepped", "-c", &format!("sim program load {}", p.display())], "");
    let l = json_lines(&o);
    let e = &l[0]["error"];
    assert!(e["message"].as_str().unwrap().contains("bad.il:3:3: unknown instruction TONN"), "{e}");
    assert!(e["hint"].as_str().unwrap().contains("did you mean TON"), "{e}");
    // The simulator is intact: nothing loaded, memory answers.
    let o = run(&["--json", "--time", "stepped", "-c", &format!("sim program load {}; get VW0", p.display())], "");
    assert!(stdout(&o).contains("unknown instruction"));
}

#[test]
fn sim_program_reports_mode_scans_and_faults() {
    let p = write_program("wd.il", "LD %SM0.0\nS %Q0.0, 1\nLD %M0.0\nJMPC L\nJMP E\nL: LD %SM0.0\nJMP L\nE:\n");
    let line = format!(
        "sim program load {}; sim scan 5; get Q0.0; set M0.0=1; sim step 5ms; get Q0.0; sim program",
        p.display()
    );
    let l = json_lines(&run(&["--json", "--time", "stepped", "-c", &line], ""));
    let st = l.last().unwrap();
    assert_eq!(st["mode"], "STOP", "{st}");
    assert_eq!(st["faults"][0]["kind"], "watchdog");
    assert_eq!(st["faults"][0]["code"], 1);
    let q: Vec<_> = l.iter().filter(|v| v["values"].is_array()).map(|v| v["values"][0]["value"].clone()).collect();
    assert_eq!(q, vec![serde_json::json!(true), serde_json::json!(false)], "Q0.0 on in RUN, off in STOP");
}

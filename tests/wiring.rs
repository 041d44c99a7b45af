//! Virtual wiring end to end with the real binary: the machine a K2 and a Kinco servo make
//! (PTO0 → drive in pulse-train mode through its gear → encoder output → HSC0 in A/B mode),
//! declared from the shell and from a bench file, in stepped time and asserted exactly; the
//! same bench served and driven by a second plcsh over Modbus TCP and the servo's pty.

mod common;
use common::*;
use serde_json::Value;

const PROFILE: &str =
    "profile 0 at VB3001 [(cycle=100us, count=1000), (cycle=50us, count=6000), (cycle=100us, count=1000)]";

fn bench_file() -> String {
    format!("{}/machines/pto_servo_encoder.toml", env!("CARGO_MANIFEST_DIR"))
}

/// The values of every `get` line, in order, as (operand, value).
fn gets(lines: &[Value]) -> Vec<Vec<(String, Value)>> {
    lines
        .iter()
        .filter(|l| l["cmd"] == "get")
        .map(|l| {
            l["values"]
                .as_array()
                .unwrap()
                .iter()
                .map(|v| (v["operand"].as_str().unwrap().to_string(), v["value"].clone()))
                .collect()
        })
        .collect()
}

fn vals(g: &[(String, Value)]) -> Vec<i64> {
    g.iter().map(|(_, v)| v.as_i64().unwrap_or_else(|| i64::from(v.as_bool().unwrap()))).collect()
}

/// The machine's numbers: 8000 pulses (1000 at 10 kHz, 6000 at 20 kHz, 1000 at 10 kHz =
/// 0.5 s); gear 4 → 32000 increments; 1250 lines at 10000 increments per revolution → 5000
/// counts per revolution → 16000 counts. PV 10000 counts = 20000 increments = 5000 pulses:
/// 100 ms of the first segment + 4000 pulses of the second (200 ms) → 300 ms after PLS.
fn check_machine(o: &std::process::Output) {
    assert!(o.status.success(), "{}\n{}", stdout(o), String::from_utf8_lossy(&o.stderr));
    let l = json_lines(o);
    let wait = l.iter().find(|l| l["cmd"] == "wait").expect("wait line");
    assert_eq!(wait["event"]["name"], "hsc0-cv=pv");
    assert_eq!(wait["event"]["time_us"], 300_000, "CV = PV exactly 300 ms after the start");
    let g = gets(&l);
    assert_eq!(vals(&g[0]), vec![20_000, 10_000, 1, 0], "at the event: position, CV, home switch, not yet there");
    assert_eq!(vals(&g[1]), vec![16_000, 8000, 32_000, 1], "after: counts, pulses, increments, target reached");
}

#[test]
fn the_wired_machine_in_stepped_time_from_shell_declarations() {
    let cmds = format!(
        "set servo:gear_factor=4; servo mode pulse; servo enable; \
         sim wire plc:Q0.0 -> servo:pulse; sim wire servo:encoder -> plc:I0.1,I0.0 lines=1250; \
         sim wire servo:target_reached -> plc:I0.5; sim wire servo:home@20000 -> plc:I0.4; \
         hsc 0 mode=9 rate=4x pv=10000; {PROFILE}; wait event hsc0-cv=pv timeout=2s; \
         get servo:position_actual plc:SMD38 plc:I0.4 plc:I0.5; sim step 1s; \
         get plc:SMD38 plc:SMD212 servo:position_actual plc:I0.5"
    );
    check_machine(&run(&["--json", "--time", "stepped", "-c", &cmds], ""));
}

#[test]
fn the_wired_machine_from_a_bench_file() {
    let cmds = format!(
        "hsc 0 mode=9 rate=4x pv=10000; {PROFILE}; wait event hsc0-cv=pv timeout=2s; \
         get servo:position_actual plc:SMD38 plc:I0.4 plc:I0.5; sim step 1s; \
         get plc:SMD38 plc:SMD212 servo:position_actual plc:I0.5"
    );
    let bench = bench_file();
    let o = run(&["--json", "--time", "stepped", "--bench", &bench, "-c", &cmds], "");
    check_machine(&o);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("2 device(s), 4 wire(s), 6 value(s)"), "{err}");
}

#[test]
fn wires_are_listed_replaced_and_removed() {
    let o = run(
        &[
            "--json",
            "-c",
            "sim wire plc:Q0.0 -> servo:pulse; sim wire servo:fault -> plc:I0.5; sim wire servo:enabled -> plc:I0.5; \
             sim wires; sim unwire plc:I0.5; sim wires; sim unwire all; sim wires",
        ],
        "",
    );
    assert!(o.status.success(), "{}", stdout(&o));
    let l = json_lines(&o);
    assert!(l[2]["message"].as_str().unwrap().contains("replaces servo:fault -> plc:I0.5"), "{}", l[2]);
    assert_eq!(l[3]["wires"].as_array().unwrap().len(), 2);
    assert_eq!(l[4]["removed"][0], "servo:enabled -> plc:I0.5");
    assert_eq!(l[5]["wires"].as_array().unwrap().len(), 1);
    assert_eq!(l[7]["wires"].as_array().unwrap().len(), 0);
}

/// What a command printed: its output and its errors (errors go to stderr).
fn said(o: &std::process::Output) -> String {
    format!("{}{}", stdout(o), String::from_utf8_lossy(&o.stderr))
}

#[test]
fn bad_wires_are_refused_with_what_works() {
    for (cmd, want) in [
        ("sim wire plc:Q0.0 servo:pulse", "FROM -> TO"),
        ("sim wire servo:encoder -> servo:pulse", "drive-to-drive"),
        ("sim wire servo:encoder -> plc:I0.0", "cannot be wired"),
        ("sim wire servo:brake -> plc:I0.0", "drive terminals: pulse, encoder"),
        ("sim wire plc:I9.0 -> servo:pulse", "I9.0"),
        ("sim wire nobody:Q0.0 -> servo:pulse", "no device named `nobody`"),
        ("sim wire servo:home@x -> plc:I0.4", "not a position"),
        ("sim unwire plc:I0.0", "nothing is wired"),
    ] {
        let o = run(&["-c", cmd], "");
        assert!(!o.status.success(), "{cmd} succeeded");
        let out = said(&o);
        assert!(out.contains(want), "{cmd}: {out}");
    }
    // A drive whose pulse input is A/B cannot follow pulse + direction.
    let o = run(&["-c", "set servo:pulse_mode=2; sim wire plc:Q0.0 -> servo:pulse"], "");
    assert!(!o.status.success());
    assert!(said(&o).contains("2508.03"), "{}", said(&o));
}

#[test]
fn loopback_with_a_delay_and_pulses_into_a_counter() {
    let o = run(
        &[
            "--json",
            "--time",
            "stepped",
            "-c",
            "sim wire plc:Q0.3 -> plc:I0.3 delay=2ms; sim wire plc:Q0.0 -> plc:I0.1; set Q0.3=1; sim step 1999us; \
             get I0.3; sim step 1us; get I0.3; hsc 0 mode=0 pv=500; pto 0 freq=1kHz count=1000; \
             wait event hsc0-cv=pv timeout=2s; sim step 1s; get SMD38",
        ],
        "",
    );
    assert!(o.status.success(), "{}", stdout(&o));
    let l = json_lines(&o);
    let g = gets(&l);
    assert_eq!(vals(&g[0]), vec![0], "not yet: the wire delays 2 ms");
    assert_eq!(vals(&g[1]), vec![1], "after 2 ms");
    let wait = l.iter().find(|l| l["cmd"] == "wait").unwrap();
    // PLS at 2 ms; each pulse rises at the start of its cycle (the PTO output is high in the
    // first half of each cycle): the 500th rises 499 cycles after the first, at 501 ms.
    assert_eq!(wait["event"]["time_us"], 501_000);
    assert_eq!(vals(&g[2]), vec![1000]);
}

#[test]
fn a_bench_with_a_real_device_or_a_bad_line_is_refused() {
    let dir = std::env::temp_dir().join(format!("plcsh-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let real = dir.join("real.toml");
    std::fs::write(&real, "[devices]\nservo = \"kinco:/dev/null?id=1\"\n").unwrap();
    let o = run(&["--bench", real.to_str().unwrap(), "-c", "sim wires"], "");
    assert!(!o.status.success());
    assert!(said(&o).contains("device servo = kinco:/dev/null?id=1 is not a simulator"), "{}", said(&o));
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "[devices]\nplc = \"sim:K205-16DT\"\nwires = 3\n").unwrap();
    let o = run(&["--bench", bad.to_str().unwrap(), "-c", "sim wires"], "");
    assert!(!o.status.success());
    assert!(said(&o).contains("bad.toml:3"), "{}", said(&o));
    // A bench's program runs in the simulated K2's scan engine.
    std::fs::write(dir.join("prog.il"), "LD %SM0.0\nST %Q0.1\n").unwrap();
    let prog = dir.join("prog.toml");
    std::fs::write(&prog, "[devices]\nplc = \"sim:K205-16DT\"\n[programs]\nplc = \"prog.il\"\n").unwrap();
    let o = run(&["--time", "stepped", "--bench", prog.to_str().unwrap(), "-c", "sim step 10ms; get Q0.1"], "");
    assert!(o.status.success(), "{}{}", stdout(&o), stderr(&o));
    assert!(stdout(&o).contains("Q0.1") && stdout(&o).contains("1"), "the program set Q0.1: {}", stdout(&o));
    // A program that does not load names its file and line.
    std::fs::write(dir.join("bad.il"), "LD %SM0.0\nSTT %Q0.1\n").unwrap();
    let badp = dir.join("badp.toml");
    std::fs::write(&badp, "[devices]\nplc = \"sim:K205-16DT\"\n[programs]\nplc = \"bad.il\"\n").unwrap();
    let o = run(&["--bench", badp.to_str().unwrap(), "-c", "sim wires"], "");
    assert!(!o.status.success());
    assert!(stderr(&o).contains("bad.il:2"), "{}", stderr(&o));
}

/// The bench served (K2 on Modbus TCP with the helper program, the drive on a pty, wired in
/// one process, wall-clock time) and driven by a second plcsh as a technician's would be.
#[test]
fn a_served_bench_is_driven_by_a_second_plcsh() {
    let link = std::env::temp_dir().join(format!("plcsh-wired-kinco-{}", std::process::id()));
    let bench = bench_file();
    let s =
        serve(&["--bench", &bench, "--tcp", "0", "--agent", "--servo-pty", link.to_str().unwrap(), "--servo-instant"]);
    assert_eq!(s.ready["bench"][0], "bench PTO axis with encoder feedback: 2 device(s), 4 wire(s), 6 value(s)");
    let plc = format!("plc=tcp://{}?model=K205-16DT&agent=VB3400", s.ready["tcp"].as_str().unwrap());
    let servo = format!("servo=kinco:{}?id=1", link.display());
    let client = |cmds: &str| run(&["--json", "-d", &plc, "-d", &servo, "-c", &format!("use plc; {cmds}")], "");
    let o = client("get servo:operating_mode servo:gear_factor; hsc 0 mode=9 rate=4x pv=10000");
    assert!(o.status.success(), "{}", stdout(&o));
    assert_eq!(vals(&gets(&json_lines(&o))[0]), vec![-4, 4], "the bench's initial values, read over the pty");
    let o = client(PROFILE);
    assert!(o.status.success(), "{}", stdout(&o));
    // Poll until PTO0 is idle again (SM66.7), as a client would; the train takes 0.5 s.
    let start = std::time::Instant::now();
    loop {
        let o = client("get SM66.7");
        if vals(&gets(&json_lines(&o))[0]) == vec![1] {
            break;
        }
        assert!(start.elapsed() < std::time::Duration::from_secs(20), "PTO0 never finished: {}", stdout(&o));
    }
    let o = client("get SMD212 SMD38 servo:position_actual I0.4 I0.5");
    assert!(o.status.success(), "{}", stdout(&o));
    let g = gets(&json_lines(&o));
    let v = vals(&g[0]);
    // The drive's encoder really came back: counts = increments × 5000 / 10000, exactly.
    assert_eq!(v, vec![8000, 16_000, 32_000, 1, 1], "pulses, counts, increments, home switch, target reached");
}

/// Human-readable errors go to stderr.
fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// `[[faults]]` in a bench: a drive fault armed at 20000 increments acts where the drive,
/// following PTO0's pulses through gear 4, crosses it (5000 pulses at 20 kHz: 0.25 s), and
/// is logged with that virtual time; the encoder counts stop there. A PLC fault entry takes
/// the SPEC of `sim fault` and acts on its schedule.
#[test]
fn bench_faults_and_a_drive_fault_at_a_position() {
    let dir = std::env::temp_dir().join(format!("plcsh-bench-faults-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("faulty.toml");
    let base = std::fs::read_to_string(bench_file()).unwrap();
    std::fs::write(
        &file,
        format!(
            "{base}\n[[faults]]\ndevice = \"servo\"\nspec = \"drive 16#7500 at=20000\"\n\n\
             [[faults]]\ndevice = \"plc\"\nspec = \"exception 4 on VW100 after=1s times=1\"\n"
        ),
    )
    .unwrap();
    let f = file.to_str().unwrap();
    let o = run(
        &["--time", "stepped", "--bench", f, "-c",
          "hsc 0 mode=9 rate=4x; pto 0 freq=20kHz count=8000; sim step 1s; get SMD38 servo:position_actual SMD212; servo sim events; sim faults"],
        "",
    );
    let out = said(&o);
    assert!(o.status.success(), "{out}");
    assert!(out.contains("plc:SMD38              10000"), "{out}");
    assert!(out.contains("servo:position_actual  20000"), "{out}");
    assert!(out.contains("plc:SMD212             8000"), "PTO0 sent every pulse: {out}");
    assert!(out.contains("0.250000s  drive id 1: fault 16#7500 at position 20000 inc"), "{out}");
    assert!(out.contains("fault 1: exception 04 (server device failure) on VB100..VB101 from 1.000000s"), "{out}");
    // The PLC fault acts once, at its time, and is logged as an event.
    let o = run(&["--time", "stepped", "--bench", f], "sim step 1s\nget VW100\nget VW100\nevents\n");
    let out = said(&o);
    assert!(out.contains("injected fault 1"), "{out}");
    assert!(out.contains("fault1"), "{out}");
    // A bad entry names the file and the entry.
    let bad = dir.join("bad-fault.toml");
    std::fs::write(&bad, format!("{base}\n[[faults]]\ndevice = \"servo\"\nspec = \"drive 16#7500 at=x\"\n")).unwrap();
    let o = run(&["--bench", bad.to_str().unwrap(), "-c", "sim wires"], "");
    assert!(!o.status.success());
    assert!(said(&o).contains("fault 1 `drive 16#7500 at=x`"), "{}", said(&o));
}

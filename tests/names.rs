//! A tag's name works wherever an operand does (docs/tags.md, "How names appear"): one table
//! over the command registry. Every form whose usage takes an operand (a placeholder
//! `OPERAND`, `RANGE`, `OBJ`, a terminal, or an operand example such as `I0.1`, `QB0=16#05`,
//! `VB3009`) has a row here with a line that gives it names instead; the rows are run in the
//! REPL (lines on standard input), one-shot (`-c`) and from Lua (`plcsh.exec`), and must
//! succeed and show what the row expects (Lua's own forms — `plc.NAME`, `plc["NAME"]`,
//! `plc:get` — are [`lua_reads_and_writes_by_name_and_loads_tags`]). A form added to the registry that takes operands
//! and has no row fails [`every_form_that_takes_an_operand_has_a_row`] until it is given one
//! — that is, until it takes names.

mod common;

use plcsh::shell::commands::forms;
use std::path::{Path, PathBuf};

/// The PLC's tags: every type the K2 has, a Cyrillic and a Chinese name.
const PLC_TAGS: &str = "name;address;type;comment
Tank2_Level;VD200;REAL;Tank 2 level
Conveyor_Run;M0.3;BOOL;conveyor motor
Мотор_1_Пуск;Q0.1;BOOL;пуск мотора
Start_Button;I0.1;BOOL;start push button
Encoder_B;I0.0;BOOL;
Motor_Out;Q0.0;BOOL;
Out_Byte;QB1;BYTE;
Speeds;VW100;WORD;speed table
Count_Pv;VD400;DINT;
Pto_Table;VB3001;BYTE;
Hsc_Table;VB3009;BYTE;
电机速度;VW300;INT;电机
Уровень_2;VW20;INT;уровень в баке 2
启动按钮;I0.2;BOOL;启动
";

/// The UMPK trainer's tags.
const UMPK_TAGS: &str = "name,address,comment\nKey_3,I3,a key\n";

/// The drive's tags (objects by name).
const SERVO_TAGS: &str = "name,address,comment\nAxis_Pos,position_actual,where the axis is\nAxis_Ctl,controlword,\n";

/// Every operand-taking form: (the form as `help` shows it, a line with names, a text the
/// result shows). The line runs on a session with a simulated K2 `plc` (current), the drive
/// `servo` and a UMPK `trainer`.
const ROWS: &[(&str, &str, &str)] = &[
    ("data save FILE OPERAND…", "data save named.toml Tank2_Level Conveyor_Run", "\"operand\":\"VD200/REAL\""),
    ("get OPERAND…", "get Tank2_Level Conveyor_Run Мотор_1_Пуск 电机速度 Speeds[2]", "\"name\":\"Tank2_Level\""),
    ("set OPERAND=VALUE[, OPERAND=VALUE…]", "set Tank2_Level=12.5, Conveyor_Run=1", "\"name\":\"Conveyor_Run\""),
    ("read RANGE…", "read Speeds[4] Out_Byte", "\"name\":\"Speeds\""),
    ("help [COMMAND [SUB]|OPERAND|all]", "help Tank2_Level", "\"comment\":\"Tank 2 level\""),
    ("watch OPERAND… [every=200ms] [count=N]", "watch Tank2_Level Мотор_1_Пуск count=2", "\"name\":\"Мотор_1_Пуск\""),
    ("trace OPERAND… every=10ms for=2s [to=FILE.csv]", "trace Tank2_Level Motor_Out every=10ms for=50ms", "\"operand\":\"Tank2_Level\""),
    (
        "plot [OPERAND…] [to=FILE.png|FILE.svg] [size=900x340] [width=60] [height=8]",
        "trace Tank2_Level Motor_Out every=10ms for=50ms; plot Tank2_Level",
        "Tank2_Level",
    ),
    ("sim input I0.1 freq=1kHz [dir=up|down]", "sim input Start_Button freq=1kHz", "I0.1"),
    ("sim input I0.1 off", "sim input Start_Button freq=1kHz; sim input Start_Button off", "stopped"),
    ("sim quad A B freq=1kHz [dir=up|down]", "sim quad Start_Button Encoder_B freq=1kHz", "I0.1"),
    ("sim retain RANGE…|none", "sim retain Speeds[4]", "VB100..VB107"),
    ("sim program stop-outputs QB0=16#05 …", "sim program stop-outputs Out_Byte=16#05", "QB1"),
    ("sim wire FROM -> TO[,TO…] [lines=N] [delay=D]", "sim wire plc:Motor_Out -> plc:Start_Button", "Q0.0"),
    ("sim unwire TERMINAL|all", "sim wire plc:Motor_Out -> plc:Start_Button; sim unwire plc:Motor_Out", "Q0.0"),
    (
        "hsc N mode=9 [rate=4x] [pv=[100,200,300]] [relative] [cyclic] [at VB3009] [cv=0] [dir=up|down] [reset=low] [start=low] [force]",
        "hsc 0 mode=0 pv=[100] at Hsc_Table",
        "\"ok\":true",
    ),
    (
        "profile N at VB3001 [(cycle=500us, count=1000), (freq=4kHz, count=4000), …] [force] [strict] [plan [to=FILE.png|FILE.svg] [size=900x340]]",
        "profile 0 at Pto_Table [(cycle=500us, count=1000)] plan",
        "\"planned_writes\":6",
    ),
    ("umpk monitor [OPERAND…] [count=N] [for=2s] [every=100ms] [quiet]", "umpk trainer monitor Key_3 count=1", "I3"),
    ("umpk sim input I3=1", "umpk trainer sim input Key_3=1", "I3"),
    ("umpk sim input I3 [off] [freq=2Hz]", "umpk trainer sim input Key_3 freq=2Hz", "I3"),
    ("umpk sim fault no-reply|stuck [I3=1] [for=D]", "umpk trainer sim fault stuck Key_3=1", "I3"),
    ("servo read OBJ…", "servo read Axis_Pos", "position_actual"),
    ("servo sim fault abort OBJ CODE", "servo sim fault abort Axis_Ctl 16#06090011", "6040.00"),
];

/// A placeholder of a form that stands for an operand.
fn operand_placeholder(word: &str) -> bool {
    let w = word.trim_matches(|c| matches!(c, '[' | ']' | '(' | ')' | ',' | '…'));
    if w.contains("FILE") {
        return false;
    }
    let head = w.split(['=', '|', ',']).next().unwrap_or(w).trim_end_matches('…');
    if ["OPERAND", "RANGE", "OBJ", "FROM", "TO", "TERMINAL", "A", "B"].contains(&head) {
        return true;
    }
    // An operand as an example: area letters, then a digit (`I0.1`, `QB0`, `VB3009`, `I3`).
    let letters = head.chars().take_while(|c| c.is_ascii_uppercase()).count();
    (1..=4).contains(&letters) && head[letters..].starts_with(|c: char| c.is_ascii_digit())
}

fn takes_operand(form: &str) -> bool {
    form.split_whitespace().skip(1).flat_map(|w| w.split('|')).any(operand_placeholder)
}

#[test]
fn every_form_that_takes_an_operand_has_a_row() {
    let mut want: Vec<String> = forms::all().map(|(_, f)| f.text).filter(|f| takes_operand(f)).collect();
    want.sort();
    let mut have: Vec<String> = ROWS.iter().map(|r| r.0.to_string()).collect();
    have.sort();
    assert_eq!(want, have, "the forms that take operands and the rows that give them names");
}

/// The tag files in a folder of test `name`'s own.
fn world(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-names-{}-{name}", std::process::id()));
    // Fresh: nothing a previous run left behind is read.
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    std::fs::write(d.join("plc.csv"), PLC_TAGS).unwrap();
    std::fs::write(d.join("umpk.csv"), UMPK_TAGS).unwrap();
    std::fs::write(d.join("servo.csv"), SERVO_TAGS).unwrap();
    d
}

fn plcsh(dir: &Path, json: bool) -> std::process::Command {
    let mut c = common::plcsh();
    c.current_dir(dir).args(["--time", "stepped", "--device", "trainer=sim-umpk:", "--device", "plc=sim:K205-16DT"]);
    c.args(["--tags", "plc.csv", "--tags", "servo=servo.csv", "--tags", "trainer=umpk.csv"]);
    if json {
        c.arg("--json");
    }
    c
}

/// Each row's line in the three routes. One-shot and REPL must show the row's text; Lua runs
/// the line through `plcsh.exec`, which raises if any command of it fails.
#[test]
fn every_row_works_with_names_in_the_repl_one_shot_and_lua() {
    let dir = world("rows");
    std::thread::scope(|s| {
        for chunk in ROWS.chunks(ROWS.len().div_ceil(3)) {
            let dir = &dir;
            s.spawn(move || {
                for (form, line, expect) in chunk {
                    // One-shot.
                    let o = plcsh(dir, true).args(["-c", line]).output().unwrap();
                    let out = common::stdout(&o);
                    let v = common::json_lines(&o);
                    assert!(o.status.success(), "{form}: `{line}` one-shot:\n{out}\n{}", common::stderr(&o));
                    assert!(v.iter().all(|j| j["ok"] != false), "{form}: `{line}`:\n{out}");
                    assert!(out.contains(expect), "{form}: `{line}` shows no `{expect}`:\n{out}");
                    // The REPL (lines on standard input).
                    let child = plcsh(dir, true)
                        .stdin(std::process::Stdio::piped())
                        .stdout(std::process::Stdio::piped())
                        .stderr(std::process::Stdio::piped())
                        .spawn()
                        .unwrap();
                    let o = common::output_with_input(child, format!("{line}\n").as_bytes());
                    let out = common::stdout(&o);
                    assert!(out.contains(expect), "{form}: `{line}` in the REPL shows no `{expect}`:\n{out}");
                    assert!(!out.contains("\"ok\":false"), "{form}: `{line}` in the REPL:\n{out}");
                    // Lua.
                    {
                        let code = format!("lua plcsh.exec([==[{line}]==]) print(\"done\")");
                        let o = plcsh(dir, false).args(["-c", &code]).output().unwrap();
                        let out = common::both(&o);
                        assert!(o.status.success() && out.contains("done"), "{form}: `{code}`:\n{out}");
                    }
                }
            });
        }
    });
}

/// The Lua forms of the issue: fields by name (`plc.Conveyor_Run`, `plc["Мотор_1_Пуск"]`),
/// `plc:get`, `plc:set`, and `plc:tags_load` on a device opened without tags.
#[test]
fn lua_reads_and_writes_by_name_and_loads_tags() {
    let dir = world("lua");
    let code = r#"
        assert(plc:tags_load("plc.csv") == 14)
        plc.Conveyor_Run = true
        plc["Мотор_1_Пуск"] = 1
        plc:set{Tank2_Level = 12.5}
        plc:set("电机速度", -3)
        local a, b = plc:get("Tank2_Level", "conveyor_run")
        print(a, b, plc["Мотор_1_Пуск"], plc.VD200, plc["电机速度"])
    "#;
    let script = dir.join("names.lua");
    std::fs::write(&script, code).unwrap();
    let o = common::plcsh().current_dir(&dir).args(["--time", "stepped", "run", "names.lua"]).output().unwrap();
    let out = common::both(&o);
    assert!(o.status.success(), "{out}");
    // VD200 read as a DWORD is the REAL's bits: the name picks the view.
    assert!(out.contains("12.5\ttrue\ttrue\t1095237632\t-3"), "{out}");
}

/// Output shows the name and the operand, JSON `name` beside `operand`; an unknown name gets
/// the nearest names; a bad tag file is refused at its line.
#[test]
fn output_shows_the_name_and_the_operand_and_a_misspelt_name_gets_the_nearest() {
    let dir = world("output");
    let o = plcsh(&dir, false).args(["-c", "set Tank2_Level=12.5; get Tank2_Level VW0"]).output().unwrap();
    let out = common::stdout(&o);
    assert!(out.contains("Tank2_Level (VD200/REAL)  12.5  Tank 2 level"), "{out}");
    assert!(out.lines().any(|l| l.starts_with("VW0 ") && l.trim_end().ends_with(" 0")), "{out}");
    let o = plcsh(&dir, true).args(["-c", "get Tank2_Levl"]).output().unwrap();
    let v = common::json_lines(&o);
    let hint = v[0]["error"]["hint"].as_str().unwrap_or("");
    assert!(hint.contains("did you mean Tank2_Level (VD200/REAL)"), "{}", v[0]);
    std::fs::write(dir.join("bad.csv"), "name,address,type\nA_1,VW0,INT\nB_1,VW99999,INT\nC_1,VB0,REAL\n").unwrap();
    let o = common::plcsh().current_dir(&dir).args(["--json", "--tags", "bad.csv", "-c", "get VW0"]).output().unwrap();
    let out = common::both(&o);
    assert!(!o.status.success(), "{out}");
    assert!(out.contains("bad.csv:3") && out.contains("bad.csv:4"), "{out}");
}

/// A profile's `tags = "…"` is read beside its devices.toml.
#[test]
fn a_profile_names_its_tag_file_beside_itself() {
    let dir = world("profile");
    let conf = dir.join("conf");
    std::fs::create_dir_all(&conf).unwrap();
    std::fs::write(conf.join("press.csv"), "name,address,type\nPress_Force,VW10,INT\n").unwrap();
    std::fs::write(conf.join("devices.toml"), "[devices.press1]\nurl = \"sim:K205-16DT\"\ntags = \"press.csv\"\n")
        .unwrap();
    let o = common::plcsh()
        .current_dir(&dir)
        .args([
            "--json",
            "--config",
            "conf/devices.toml",
            "--device",
            "press1",
            "-c",
            "set Press_Force=-5; get press1:Press_Force",
        ])
        .output()
        .unwrap();
    let v = common::json_lines(&o);
    let last = v.last().unwrap_or_else(|| panic!("{}", common::both(&o)));
    assert_eq!(last["values"][0]["name"], "Press_Force", "{last}");
    assert_eq!(last["values"][0]["operand"], "VW10/INT", "{last}");
    assert_eq!(last["values"][0]["value"], -5, "{last}");
}

/// A misspelt Cyrillic or Chinese name is searched among the names as typed: the K2 manual's
/// Cyrillic spelling (`ВW0` is `VW0`) is read only where it makes an operand, so `Уровен_2`
/// is not turned into a Latin-lettered word before "did you mean". In the REPL, one-shot and
/// Lua (through the shell and through the device handle).
#[test]
fn a_misspelt_cyrillic_or_chinese_name_gets_the_nearest_name_as_typed() {
    let dir = world("near");
    for (typed, near) in
        [("Уровен_2", "Уровень_2 (VW20/INT)"), ("уровнь_2", "Уровень_2"), ("电机速", "电机速度 (VW300/INT)")]
    {
        let line = format!("get {typed}");
        let o = plcsh(&dir, true).args(["-c", &line]).output().unwrap();
        let v = common::json_lines(&o);
        assert!(!o.status.success(), "{}", common::both(&o));
        let e = &v[0]["error"];
        assert!(e["message"].as_str().unwrap_or("").contains(&format!("`{typed}`")), "{typed}: {e}");
        assert!(e["hint"].as_str().unwrap_or("").contains(&format!("did you mean {near}")), "{typed}: {e}");
        let child = plcsh(&dir, false)
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let o = common::output_with_input(child, format!("{line}\n").as_bytes());
        let out = common::both(&o);
        assert!(out.contains(typed) && out.contains(&format!("did you mean {near}")), "REPL `{line}`:\n{out}");
        for code in [format!("lua plcsh.exec([==[{line}]==])"), format!("lua plc:get([==[{typed}]==])")] {
            let o = plcsh(&dir, false).args(["-c", &code]).output().unwrap();
            let out = common::both(&o);
            assert!(!o.status.success() && out.contains(&format!("did you mean {near}")), "`{code}`:\n{out}");
        }
    }
    // The manual's spelling still reads where it makes an operand, beside a name.
    let o = plcsh(&dir, true).args(["-c", "set ВW0=В#16#12; get ВW0 Уровень_2"]).output().unwrap();
    let v = common::json_lines(&o);
    assert!(o.status.success(), "{}", common::both(&o));
    let last = v.last().unwrap();
    assert_eq!(last["values"][0]["operand"], "VW0", "{last}");
    assert_eq!(last["values"][0]["value"], 18, "{last}");
    assert_eq!(last["values"][1]["name"], "Уровень_2", "{last}");
}

/// A refusal points at the column of what was typed, though the command ran with each name
/// written as its operand (`Start_Button` → `I0.1`, a shorter text) and the manual's Cyrillic
/// spelling read as Latin (`Х0` → `X0`, fewer bytes): per family, the K2 simulator's `sim`,
/// the UMPK's `umpk`, the drive's `servo`, and the FX's operands. The JSON column is a byte
/// offset in the line; the caret under the text line counts terminal columns (a Chinese
/// character is two).
#[test]
fn a_refusal_points_at_the_column_of_what_was_typed() {
    let dir = world("columns");
    std::fs::write(dir.join("fx.csv"), "name,address,comment\nFx_Start,X0,\nFx_Motor,Y0,\n").unwrap();
    let cases = [
        ("sim input Start_Button freq=1kQ", "freq=1kQ"),
        ("sim quad Start_Button Encoder_B freq=1kHz dir=zz", "dir=zz"),
        ("sim input 启动按钮 freq=1kQ", "freq=1kQ"),
        ("sim retain Speeds[2] VQ9", "VQ9"),
        ("umpk trainer monitor Key_3 I99", "I99"),
        ("servo read Axis_Pos nonsuch", "nonsuch"),
        ("servo sim fault abort Axis_Ctl 16#zz", "16#zz"),
        ("use fx; get Fx_Start Х0 Fx_Motor X99", "99"),
        ("use fx; watch Fx_Motor Х1 X78 count=1", "8"),
    ];
    for (line, at) in cases {
        let o =
            plcsh(&dir, true).args(["--device", "fx=sim-fx:FX3U", "--tags", "fx=fx.csv", "-c", line]).output().unwrap();
        let v = common::json_lines(&o);
        let e = &v.last().unwrap_or_else(|| panic!("{line}: {}", common::both(&o)))["error"];
        let col = e["column"].as_u64().unwrap_or_else(|| panic!("{line}: no column: {e}")) as usize;
        assert!(line.get(col..).is_some_and(|t| t.starts_with(at)), "{line}: column {col}, not at `{at}`: {e}");
    }
    // The caret, under the Chinese name's line.
    let line = "sim input 启动按钮 freq=1kQ";
    let o = plcsh(&dir, false).args(["-c", line]).output().unwrap();
    let out = common::both(&o);
    let caret = out.lines().find(|l| l.trim() == "^").unwrap_or_else(|| panic!("{out}"));
    assert_eq!(caret.find('^'), Some(2 + "sim input ".len() + 8 + 1), "{out}");
}

/// The keys of a bench file (`--bench`, a lab's `bench`) and of `lab.toml`, each with whether it
/// takes operands. A key added to either fails
/// [`every_bench_and_lab_key_that_takes_an_operand_takes_names`] until it is classified here —
/// and, when it takes operands, until the bench below gives it names.
const BENCH_KEYS: &[(&str, bool)] = &[
    ("name", false),
    ("current", false),
    ("devices", false),
    ("wires", true),
    ("init", true),
    ("programs", false),
    ("faults", true),
    ("tags", false),
];

/// `lab.toml`'s keys: none takes an operand (criteria are the grader's Lua, which takes names
/// like any script; a lab's names come from its bench's `[tags]`).
const LAB_KEYS: &[&str] = &[
    "title",
    "bench",
    "devices",
    "snapshot",
    "starter",
    "reference",
    "grader",
    "device",
    "budget",
    "points",
    "accepts",
    "shared",
    "language",
    "grants",
];

/// The keys a file accepts, as serde lists them refusing an unknown one.
fn keys_listed(out: &str) -> Vec<String> {
    let list = out.split("expected one of").nth(1).unwrap_or_else(|| panic!("no key list in: {out}"));
    let list = list.lines().next().unwrap_or("");
    let mut keys: Vec<String> = list.split(',').map(|k| k.trim().trim_matches('`').to_string()).collect();
    keys.sort();
    keys
}

/// A bench's wires, initial values and injected faults take the names of its `[tags]`; Lua's
/// `plcsh.wire` takes them too.
#[test]
fn every_bench_and_lab_key_that_takes_an_operand_takes_names() {
    let dir = world("bench");
    std::fs::write(dir.join("unknown.toml"), "zzz = 1\n[devices]\nplc = \"sim:K205-16DT\"\n").unwrap();
    let o = common::plcsh().current_dir(&dir).args(["--bench", "unknown.toml", "-c", "get VW0"]).output().unwrap();
    let mut want: Vec<String> = BENCH_KEYS.iter().map(|k| k.0.to_string()).collect();
    want.sort();
    assert_eq!(keys_listed(&common::both(&o)), want, "a bench key is not classified in BENCH_KEYS");
    std::fs::create_dir_all(dir.join("lab")).unwrap();
    std::fs::write(dir.join("lab/lab.toml"), "title = \"x\"\nzzz = 1\n").unwrap();
    let o = common::plcsh().current_dir(&dir).args(["lab", "check", "lab"]).output().unwrap();
    let mut want: Vec<String> = LAB_KEYS.iter().map(|k| k.to_string()).collect();
    want.sort();
    assert_eq!(keys_listed(&common::both(&o)), want, "a lab.toml key is not classified in LAB_KEYS");
    // Every operand-taking key, with names.
    let bench = "wires = [\"plc:Motor_Out -> plc:Start_Button\"]\n\
                 init = [\"plc:Уровень_2=7\", \"plc:电机速度=-3\"]\n\
                 [devices]\nplc = \"sim:K205-16DT\"\n[tags]\nplc = \"plc.csv\"\n\
                 [[faults]]\ndevice = \"plc\"\nspec = \"no-reply on Уровень_2 after=1h times=1\"\n";
    assert!(BENCH_KEYS.iter().filter(|k| k.1).all(|k| bench.contains(k.0)), "a row for every key that takes operands");
    std::fs::write(dir.join("named.toml"), bench).unwrap();
    let o = common::plcsh()
        .current_dir(&dir)
        .args(["--time", "stepped", "--bench", "named.toml", "-c"])
        .arg("sim wires; sim faults; get Уровень_2 电机速度; lua plcsh.wire('plc:Мотор_1_Пуск -> plc:I0.3')")
        .output()
        .unwrap();
    let out = common::both(&o);
    assert!(o.status.success(), "{out}");
    assert!(out.contains("plc:Q0.0 -> plc:I0.1"), "wires: {out}");
    assert!(out.contains("no-reply on VB20..VB21"), "faults: {out}");
    assert!(out.contains("Уровень_2 (VW20/INT)") && out.contains("电机速度 (VW300/INT)"), "init: {out}");
    assert!(out.lines().any(|l| l.starts_with("Уровень_2") && l.contains(" 7 ")), "init: {out}");
    assert!(out.contains("plc:Q0.1 -> plc:I0.3"), "plcsh.wire: {out}");
}

/// `data save` keeps each operand's tag name beside it; a set saved by name loads by name
/// (where the tags put the name now); `data diff` shows the names; a set written before
/// names (no `name` keys) still loads and compares.
#[test]
fn data_sets_keep_names_and_load_by_name() {
    let dir = world("data");
    let o = plcsh(&dir, false)
        .args(["-c", "set Tank2_Level=12.5, Уровень_2=5, VW0=9; data save s.toml Tank2_Level Уровень_2 VW0"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", common::both(&o));
    let text = std::fs::read_to_string(dir.join("s.toml")).unwrap();
    assert!(text.contains("operand = \"VW20/INT\", type = \"INT\", value = 5, name = \"Уровень_2\""), "{text}");
    assert!(
        text.contains("{ operand = \"VW0\", type = \"WORD\", value = 9 }"),
        "no name for an operand without a tag: {text}"
    );
    // The same names on other addresses: the set goes where the names are now.
    std::fs::write(dir.join("moved.csv"), "name;address;type\nTank2_Level;VD300;REAL\nУровень_2;VW22;INT\n").unwrap();
    let o = common::plcsh()
        .current_dir(&dir)
        .args([
            "--time",
            "stepped",
            "--json",
            "--tags",
            "moved.csv",
            "-c",
            "data load s.toml; get VD300/REAL VW22 VW20 VW0",
        ])
        .output()
        .unwrap();
    let v = common::json_lines(&o);
    let last = v.last().unwrap_or_else(|| panic!("{}", common::both(&o)));
    let values: Vec<&serde_json::Value> = last["values"].as_array().unwrap().iter().map(|x| &x["value"]).collect();
    assert_eq!(
        values,
        [&serde_json::json!(12.5), &serde_json::json!(5), &serde_json::json!(0), &serde_json::json!(9)],
        "{last}"
    );
    // `data diff` names what differs.
    let o = plcsh(&dir, false).args(["-c", "set Уровень_2=6; data diff s.toml"]).output().unwrap();
    let out = common::both(&o);
    assert!(out.contains("Уровень_2 (VW20/INT)"), "{out}");
    let o = plcsh(&dir, true).args(["-c", "set Уровень_2=6; data diff s.toml"]).output().unwrap();
    let last = common::json_lines(&o).pop().unwrap();
    assert_eq!(last["differences"][1]["name"], "Уровень_2", "{last}");
    assert!(last["differences"][2].get("name").is_none(), "{last}");
    // A file from before names: read as it was.
    let old = text.replace(", name = \"Tank2_Level\"", "").replace(", name = \"Уровень_2\"", "");
    std::fs::write(dir.join("old.toml"), old).unwrap();
    let o = plcsh(&dir, false).args(["-c", "data load old.toml; get VW20"]).output().unwrap();
    assert!(o.status.success() && common::stdout(&o).contains("5"), "{}", common::both(&o));
}

/// Series and records are labelled by name: a trace's CSV header, and a commissioning report's
/// curves and its log of writes (the guard logs operands; the report adds the name).
#[test]
fn traces_and_reports_label_by_name() {
    let dir = world("report");
    let o = plcsh(&dir, false)
        .args(["-c", "trace Tank2_Level Уровень_2 VW0 every=10ms for=30ms to=t.csv"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", common::both(&o));
    let csv = std::fs::read_to_string(dir.join("t.csv")).unwrap();
    let header = csv.lines().next().unwrap_or("");
    assert!(header.contains("Tank2_Level") && header.contains("Уровень_2") && header.contains("VW0"), "{header}");
    let script = r#"
        local commission = require("commission")
        local plc = plcsh.device("plc")
        local c = commission.new("names", { report = "r.html" })
        c:step("by name", function()
          plc["Уровень_2"] = 5
          c:trace { plc, "Tank2_Level", "Уровень_2", every = 10, ["for"] = 30, title = "t" }
        end)
        c:run()
    "#;
    std::fs::write(dir.join("r.lua"), script).unwrap();
    let o = plcsh(&dir, false).args(["run", "r.lua"]).output().unwrap();
    assert!(o.status.success(), "{}", common::both(&o));
    let r: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(dir.join("r.json")).unwrap()).unwrap();
    let series: Vec<&str> =
        r["traces"][0]["series"].as_array().unwrap().iter().filter_map(|s| s["name"].as_str()).collect();
    assert_eq!(series, ["Tank2_Level", "Уровень_2"], "{r}");
    let w = &r["writes"][0];
    assert_eq!((w["operand"].as_str(), w["name"].as_str()), (Some("VW20/INT"), Some("Уровень_2")), "{w}");
    let html = std::fs::read_to_string(dir.join("r.html")).unwrap();
    assert!(html.contains("Уровень_2 (<code>VW20/INT</code>)"), "the HTML writes table names the tag");
}

//! PLC data sets (docs/data-sets.md): `data save/diff/load` and the Lua methods. A random set
//! of typed K2 operands (bytes, words, INT/DINT/REAL views, bits, the E2PROM backup area of
//! k2.md §7 / manual §2.2.8) round-trips exactly through a file onto a second PLC, and the load
//! writes exactly the operands whose value differs; a load stops at the first refusal naming
//! the operand; a file from another family or model is refused before anything is sent; the
//! FX data registers and the UMPK's operands go the same way.

mod common;
use plcsh::dataset::DataSet;
use plcsh::shell::Shell;
use serde_json::Value;

#[path = "common/in_process.rs"]
mod in_process;
use in_process::{error, run};
use std::path::PathBuf;

/// The seeded generator the property tests share (`core::test_rng`).
#[path = "../src/core/test_rng.rs"]
#[allow(dead_code)]
mod test_rng;
use test_rng::Rng;

fn dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-data-{}-{tag}", std::process::id()));
    // Fresh: nothing a previous run left behind is read.
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn shell(devices: &[(&str, &str)]) -> Shell {
    in_process::shell_with(devices)
}

fn read_set(f: &str) -> DataSet {
    DataSet::parse(&std::fs::read_to_string(f).unwrap(), f).unwrap()
}

/// The values `get` reads for `ops` on the current device, as text.
fn values(sh: &mut Shell, ops: &str) -> Vec<String> {
    run(sh, &format!("get {ops}"))[0]["values"].as_array().unwrap().iter().map(|v| v["value"].to_string()).collect()
}

/// A random write of a K2 operand of a random type: (operand, value text).
fn random_write(rng: &mut Rng, at: u32) -> (String, String) {
    match rng.below(7) {
        0 => (format!("VB{at}"), rng.in_range(0, 255).to_string()),
        1 => (format!("VW{at}"), rng.in_range(0, 65_535).to_string()),
        2 => (format!("VW{at}/INT"), rng.in_range(-32_768, 32_767).to_string()),
        3 => (format!("VD{at}/DINT"), rng.in_range(i32::MIN as i64, i32::MAX as i64).to_string()),
        4 => {
            // A REAL from its bits: any sign and mantissa, an exponent from 2^-27 to 2^33 (the
            // literal parser refuses what does not fit an f32 as typed, so no extremes).
            let bits = (rng.below(2) as u32) << 31 | (rng.in_range(100, 160) as u32) << 23 | rng.below(1 << 23) as u32;
            (format!("VD{at}/REAL"), format!("{:?}", f32::from_bits(bits)))
        }
        5 => (format!("V{at}.{}", rng.below(8)), rng.below(2).to_string()),
        _ => (format!("M{}.{}", at % 32, rng.below(8)), rng.below(2).to_string()),
    }
}

#[test]
fn a_random_typed_set_round_trips_exactly_onto_another_plc_writing_only_what_differs() {
    let d = dir("roundtrip");
    for seed in 1..=8u64 {
        let mut rng = Rng(0x5DEE_CE66_D1CE_4E5B ^ seed);
        let mut sh = shell(&[("a", "sim:K205-16DT"), ("b", "sim:K205-16DT")]);
        // Operands 4 bytes apart (a DINT or REAL fits), plus some in the E2PROM area.
        let mut ops = Vec::new();
        let mut sets = Vec::new();
        for i in 0..24u32 {
            let at = if i < 18 { i * 4 } else { 3648 + (i - 18) * 4 };
            let (op, v) = random_write(&mut rng, at);
            if !ops.contains(&op) {
                sets.push(format!("a:{op}={v}"));
                ops.push(op);
            }
        }
        // Drive b differs in some of them: half of a's writes go to b too.
        let shared: Vec<String> =
            sets.iter().filter(|_| rng.below(2) == 0).map(|s| s.replacen("a:", "b:", 1)).collect();
        run(&mut sh, &format!("set {}", sets.join(", ")));
        if !shared.is_empty() {
            run(&mut sh, &format!("set {}", shared.join(", ")));
        }
        let (fa, fb) = (d.join(format!("a{seed}.toml")), d.join(format!("b{seed}.toml")));
        let (fa, fb) = (fa.to_str().unwrap(), fb.to_str().unwrap());
        let list = ops.join(" ");
        run(&mut sh, &format!("data a save {fa} {list} eeprom"));
        let set = read_set(fa);
        // What differs between b and the file: the diff says it, and the load writes exactly that.
        let l = run(&mut sh, &format!("data b diff {fa}"));
        let differ: Vec<String> = l[0]["differences"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x["operand"].as_str().unwrap().to_string())
            .collect();
        let l = run(&mut sh, &format!("data b load {fa}"));
        let written: Vec<String> =
            l[0]["written"].as_array().unwrap().iter().map(|x| x["operand"].as_str().unwrap().to_string()).collect();
        assert_eq!(written, differ, "seed {seed}: the load writes what the diff shows, in the file's order");
        assert_eq!(l[0]["unchanged"], set.set.values.len() - written.len(), "seed {seed}");
        run(&mut sh, &format!("data b save {fb} {list} eeprom"));
        let again = read_set(fb);
        assert_eq!(set.set.values, again.set.values, "seed {seed}: b now holds a's set");
        assert!(plcsh::dataset::diff(&set, &again).is_empty(), "seed {seed}");
        let l = run(&mut sh, &format!("data a diff {fa} {fb}; data b diff {fa}; data b load {fa}"));
        assert_eq!((&l[0]["count"], &l[1]["count"]), (&0.into(), &0.into()), "seed {seed}: {l:?}");
        assert_eq!(l[2]["written"], serde_json::json!([]), "seed {seed}: nothing left to write");
        // The typed values are what `get` reads on the first PLC.
        run(&mut sh, "use a");
        let got = values(&mut sh, &list);
        let file: Vec<String> =
            set.set.values[..ops.len()].iter().map(|e| serde_json::to_value(e.value).unwrap().to_string()).collect();
        assert_eq!(got, file, "seed {seed}");
    }
}

#[test]
fn a_load_stops_at_the_first_refusal_naming_it_and_writes_nothing_after() {
    let d = dir("refusal");
    let f = d.join("set.toml");
    let f = f.to_str().unwrap();
    let mut sh = shell(&[("plc", "sim:K205-16DT")]);
    std::fs::write(
        f,
        "[device]\nfamily = \"k2\"\nmodel = \"K205-16DT\"\nname = \"plc\"\nurl = \"sim:K205-16DT\"\n\
         saved = \"2026-12-07T23:10:00Z\"\nplcsh = \"0.1.0\"\n\n[set]\noperands = []\nvalues = [\n\
         { operand = \"VB10\", type = \"BYTE\", value = 1 },\n\
         { operand = \"SMB0\", type = \"BYTE\", value = 1 },\n\
         { operand = \"VB11\", type = \"BYTE\", value = 2 },\n]\n",
    )
    .unwrap();
    let e = error(&mut sh, &format!("data load {f}"));
    assert_eq!(e.code, "data-stopped", "{e}");
    assert_eq!(e.kind, plcsh::core::ErrorKind::Refused, "the device's refusal keeps its kind: {e}");
    assert_eq!(e.operand.as_deref(), Some("SMB0"), "{e}");
    assert!(e.message.contains("after one write") && e.message.contains("read-only"), "{e}");
    assert_eq!(values(&mut sh, "VB10 VB11"), ["1", "0"], "stopped there: VB11 was not written");
    // An operand the device does not have is refused before anything is written.
    std::fs::write(f, std::fs::read_to_string(f).unwrap().replace("SMB0", "VB99999")).unwrap();
    run(&mut sh, "set VB10=0");
    let e = error(&mut sh, &format!("data load {f}"));
    assert_eq!(e.code, "data-unknown-operand", "{e}");
    assert!(e.message.contains("VB99999"), "{e}");
    assert_eq!(values(&mut sh, "VB10"), ["0"]);
}

#[test]
fn a_file_from_another_family_or_model_is_refused_before_anything_is_sent() {
    let d = dir("other");
    let f = d.join("set.toml");
    let f = f.to_str().unwrap();
    let mut sh = shell(&[("plc", "sim:K205-16DT"), ("big", "sim:K209M-56DT"), ("fx", "sim-fx:FX2N")]);
    run(&mut sh, &format!("set VW0=5; data save {f} VW0; set VW0=0, big:VW0=1"));
    let e = error(&mut sh, &format!("data big load {f}"));
    assert_eq!(e.code, "data-other-device", "{e}");
    assert!(e.message.contains("K205-16DT") && e.message.contains("K209M-56DT"), "{e}");
    assert_eq!(error(&mut sh, &format!("data big diff {f}")).code, "data-other-device");
    let e = error(&mut sh, &format!("data fx load {f}"));
    assert_eq!(e.code, "data-other-device", "{e}");
    assert!(e.message.contains("fx FX2N"), "{e}");
    assert_eq!(values(&mut sh, "big:VW0 VW0"), ["1", "0"], "nothing was written");
    // Two files compare only within one family.
    let g = d.join("fx.toml");
    run(&mut sh, &format!("data fx save {} D0", g.display()));
    let e = error(&mut sh, &format!("data diff {f} {}", g.display()));
    assert_eq!(e.code, "data-families-differ", "{e}");
    // An operand that is not one is pointed at in the line as `get` points at it.
    let line = format!("data save {f} VW0 VQ3");
    let e = error(&mut sh, &line);
    let g = error(&mut sh, "get VW0 VQ3");
    assert_eq!(e.message, g.message);
    let at = |l: &str, e: &plcsh::core::Error| e.column.map(|c| c - l.find("VQ3").unwrap());
    assert_eq!(at(&line, &e), at("get VW0 VQ3", &g), "{e}");
    assert!(g.column.is_some());
    // A damaged or hand-broken file names the file and the entry.
    let bad = d.join("bad.toml");
    std::fs::write(&bad, std::fs::read_to_string(f).unwrap().replace("value = 5", "value = 70000")).unwrap();
    let e = error(&mut sh, &format!("data load {}", bad.display()));
    assert_eq!(e.code, "data-bad-value", "{e}");
    assert!(e.message.contains("70000") && e.message.contains("VW0"), "{e}");
    std::fs::write(&bad, "[device\n").unwrap();
    assert_eq!(error(&mut sh, &format!("data load {}", bad.display())).code, "data-bad-file");
    assert_eq!(values(&mut sh, "VW0"), ["0"]);
}

#[test]
fn eeprom_and_retained_name_the_k2_areas_that_survive_a_power_cut() {
    let d = dir("areas");
    let f = d.join("areas.toml");
    let f = f.to_str().unwrap();
    let mut sh = shell(&[("plc", "sim:K205-16DT"), ("fx", "sim-fx:FX2N")]);
    // No retained range yet: said so, with how to set one.
    let e = error(&mut sh, &format!("data save {f} retained"));
    assert_eq!(e.code, "data-retained-none", "{e}");
    run(&mut sh, "sim retain VB0..VB9 MB2[2] C0..C1");
    run(&mut sh, "set VB3=3, MB3=4, VB3902=9");
    let l = run(&mut sh, &format!("data save {f} retained eeprom"));
    let set = read_set(f);
    let names: Vec<&str> = set.set.values.iter().map(|e| e.operand.as_str()).collect();
    // manual §2.2.8: the backup area VB3648–VB3902 by default.
    let want: Vec<String> = (0..10)
        .map(|i| format!("VB{i}"))
        .chain(["MB2".into(), "MB3".into(), "C0".into(), "C1".into()])
        .chain((3648..=3902).map(|i| format!("VB{i}")))
        .collect();
    assert_eq!(names, want, "{l:?}");
    assert_eq!(set.set.operands, ["retained", "eeprom"]);
    assert_eq!(set.set.values.iter().find(|e| e.operand == "VB3902").unwrap().value, plcsh::dataset::FileValue::Int(9));
    // The extended area (`eeprom area 4095`).
    run(&mut sh, &format!("eeprom area 4095; data save {f} eeprom"));
    assert_eq!(read_set(f).set.values.last().unwrap().operand, "VB4095");
    // Other families have neither area by these names.
    let e = error(&mut sh, &format!("data fx save {f} eeprom"));
    assert_eq!((e.code, e.device.as_deref()), ("data-no-area", Some("fx")), "{e}");
    // An operand of another device is not this set's.
    let e = error(&mut sh, &format!("data save {f} fx:D0"));
    assert_eq!(e.code, "data-operand-elsewhere", "{e}");
}

#[test]
fn a_real_k2_has_its_e2prom_area_read_over_modbus_and_its_retained_ranges_named_by_hand() {
    let served = common::serve(&["--tcp", "127.0.0.1:0", "--state", "none"]);
    let url = format!("tcp://{}?model=K205-16DT", served.ready["tcp"].as_str().unwrap());
    let d = dir("wire");
    let f = d.join("wire.toml");
    let f = f.to_str().unwrap();
    let mut sh = shell(&[("plc", &url)]);
    let e = error(&mut sh, &format!("data save {f} retained"));
    assert_eq!(e.code, "data-retained-unknown", "{e}");
    assert!(e.message.contains("KincoBuilder"), "{e}");
    run(&mut sh, &format!("set VW3700=1234; data save {f} eeprom VD0/REAL; set VW3700=1, VD0/REAL=2.5"));
    let l = run(&mut sh, &format!("data diff {f}; data load {f}; data diff {f}"));
    assert_eq!(l[0]["count"], 3, "VB3700, VB3701 and VD0: {l:?}");
    assert_eq!(l[1]["written"].as_array().unwrap().len(), 3, "{l:?}");
    assert_eq!(l[2]["count"], 0, "{l:?}");
    assert_eq!(values(&mut sh, "VW3700 VD0/REAL"), ["1234", "0.0"]);
}

#[test]
fn fx_data_registers_and_umpk_operands_go_the_same_way() {
    let d = dir("families");
    let f = d.join("fx.toml");
    let f = f.to_str().unwrap();
    let mut sh = shell(&[("fx", "sim-fx:FX2N"), ("lab", "sim-umpk:UMPK16"), ("link", "sim-fx:FX2N?protocol=link")]);
    run(&mut sh, &format!("use fx; set D0=12, D7=-3, M5=1; data save {f} D0..D9 M5; set D7=0, M5=0"));
    let l = run(&mut sh, &format!("data diff {f}; data load {f}"));
    let differ: Vec<&str> =
        l[0]["differences"].as_array().unwrap().iter().map(|x| x["operand"].as_str().unwrap()).collect();
    assert_eq!(differ, ["D7", "M5"], "{l:?}");
    assert_eq!(l[1]["written"].as_array().unwrap().len(), 2, "{l:?}");
    assert_eq!(values(&mut sh, "D7 M5"), ["-3", "true"]);
    // The file names the model, not the way it was reached: it loads onto an FX2N on the
    // computer link too.
    let l = run(&mut sh, &format!("data link load {f}"));
    assert_eq!(l[0]["written"].as_array().unwrap().len(), 3, "D0, D7 and M5: {l:?}");
    assert_eq!(read_set(f).device.model, "FX2N");
    // The UMPK's terminal protocol reads operands and writes none (umpk.md §4): a set saves and
    // compares; a load with something to write is the device's refusal, naming the operand.
    let g = d.join("umpk.toml");
    let g = g.to_str().unwrap();
    run(&mut sh, &format!("use lab; data save {g} I0..I7 Q0..Q7"));
    let l = run(&mut sh, &format!("data diff {g}; data load {g}"));
    assert_eq!((&l[0]["count"], &l[1]["unchanged"]), (&0.into(), &16.into()), "{l:?}");
    let text = std::fs::read_to_string(g).unwrap();
    std::fs::write(
        g,
        text.replacen(
            "operand = \"Q0\", type = \"BOOL\", value = false",
            "operand = \"Q0\", type = \"BOOL\", value = true",
            1,
        ),
    )
    .unwrap();
    let e = error(&mut sh, &format!("data load {g}"));
    assert_eq!(e.code, "data-stopped", "{e}");
    assert_eq!(e.operand.as_deref(), Some("Q0"), "{e}");
}

#[test]
fn lua_saves_compares_and_loads_data_sets() {
    let d = dir("lua");
    let f = d.join("set.toml");
    let f = f.to_str().unwrap().replace('\\', "/");
    let script = format!(
        "local plc = plcsh.device('plc')\n\
         plc.VW10 = 7\n\
         local s = plc:data_save('{f}', 'VW10', 'VB12..VB13', 'eeprom')\n\
         assert(#s.values == 258, 'save ' .. #s.values)\n\
         plc.VW10 = 9\n\
         local d = plc:data_diff('{f}')\n\
         assert(d.count == 1 and d.differences[1].operand == 'VW10' and d.differences[1].left == 7, 'diff')\n\
         local l = plc:data_load('{f}')\n\
         assert(#l.written == 1 and l.written[1].old == 9 and l.unchanged == 257, 'load')\n\
         assert(plc.VW10 == 7 and plc:data_diff('{f}').count == 0, 'after')\n\
         print('lua ok')\n"
    );
    let p = d.join("s.lua");
    std::fs::write(&p, script).unwrap();
    let o = common::plcsh().args(["--time", "stepped", "run"]).arg(&p).output().unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success() && out.contains("lua ok"), "{out}\n{}", String::from_utf8_lossy(&o.stderr));
}

/// The wire traffic a recording holds (`plcsh --record`, `plcsh record show --json`) for a K2 on
/// Modbus TCP: a load sends a write for each operand whose value differs and none for the rest
/// (the E2PROM area included, whose writes wear it: k2.md §7), and a second load sends none.
#[test]
fn the_recorded_modbus_traffic_shows_a_load_writes_only_what_differs() {
    let served = common::serve(&["--tcp", "127.0.0.1:0", "--state", "none"]);
    let url = format!("plc=tcp://{}?model=K205-16DT", served.ready["tcp"].as_str().unwrap());
    let d = dir("recorded");
    let (set, rec) = (d.join("set.toml"), d.join("load.pcapng"));
    let line = format!(
        "set VW3700=1234, VW10=5; data save {set} eeprom VW10; set VB3701=0, VW10=6; get VW200; \
         data load {set}; get VW200; data load {set}",
        set = set.display()
    );
    let o = common::plcsh().args(["--record", rec.to_str().unwrap(), "-d", &url, "-c", &line]).output().unwrap();
    assert!(o.status.success(), "{}{}", common::stdout(&o), String::from_utf8_lossy(&o.stderr));
    drop(served);
    let o = common::plcsh().args(["--json", "record", "show", rec.to_str().unwrap()]).output().unwrap();
    let frames: Vec<Value> = common::json_lines(&o).into_iter().filter(|f| f["dir"] == "sent").collect();
    // Modbus writes: FC5, FC6, FC15, FC16.
    let writes = |fs: &[Value]| -> Vec<String> {
        fs.iter()
            .filter(|f| [5, 6, 15, 16].contains(&f["function"].as_u64().unwrap_or(0)))
            .map(|f| f["operands"].as_str().unwrap_or("?").to_string())
            .collect()
    };
    let marks: Vec<usize> =
        frames.iter().enumerate().filter(|(_, f)| f["operands"] == "VW200").map(|(i, _)| i).collect();
    assert_eq!(marks.len(), 2, "{marks:?}");
    let load = writes(&frames[marks[0] + 1..marks[1]]);
    assert_eq!(load.len(), 2, "one write for VB3701, one for VW10: {load:?}");
    assert!(load.iter().any(|w| w.contains("3700")) && load.iter().any(|w| w.contains("VW10")), "{load:?}");
    assert!(
        writes(&frames[marks[1] + 1..]).is_empty(),
        "the second load writes nothing: {:?}",
        writes(&frames[marks[1] + 1..])
    );
}

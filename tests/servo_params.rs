//! Drive parameter sets (docs/servo.md, "Parameter sets"): `servo params save/diff/load` and
//! the Lua methods on the in-process drive simulator. A random parameter set within each
//! object's range (the ranges the drive accepts: kinco-servo.md seed §1 and the public notes'
//! option codes, as `servo::sim::drive` enforces them) round-trips exactly through a file onto
//! a second drive; a load never writes a parameter whose value is already the file's (the
//! requests the simulated line received count it); a refusal stops the load naming the
//! parameter; a file from another drive type is refused.

mod common;
use plcsh::servo::objects::{self, ObjRef};
use plcsh::servo::params;
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
    let d = std::env::temp_dir().join(format!("plcsh-params-{}-{tag}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn shell() -> Shell {
    in_process::shell_with(&[("a", "sim-servo:?id=1"), ("b", "sim-servo:?id=1")])
}

/// Requests drive `name`'s simulated line has received so far.
fn received(sh: &mut Shell, name: &str) -> u64 {
    let i = sh.session.index(name).unwrap();
    let line = plcsh::servo::simulator(sh.session.entry(i).device.as_mut()).expect("simulated");
    let n = line.lock().unwrap().received;
    n
}

/// A value the drive accepts for parameter `o`: the option codes and modes the drive takes
/// (operating mode seed §3; 605A/605D option codes, 2508.03 pulse modes per the public notes;
/// 2508.02 gear divider not 0), a positive encoder resolution, otherwise any value of the type.
fn pick(o: &objects::Object, rng: &mut Rng) -> i64 {
    match o.name {
        "operating_mode" => rng.pick(&[1, 3, -3, 4, 6, -4]),
        "quickstop_option" => rng.in_range(0, 8),
        "halt_option" => rng.in_range(1, 4),
        "pulse_mode" => rng.pick(&[0, 1, 2, 10, 11, 12]),
        "gear_divider" => rng.in_range(1, 0xFFFF),
        "encoder_resolution" => rng.in_range(1, 1 << 24),
        _ => {
            let (lo, hi) = o.dtype.int_range();
            rng.in_range(lo, hi)
        }
    }
}

#[test]
fn a_random_parameter_set_round_trips_exactly_onto_another_drive() {
    let d = dir("roundtrip");
    for seed in 1..=6u64 {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15 ^ seed);
        let mut sh = shell();
        let mut want = Vec::new();
        {
            let i = sh.session.index("a").unwrap();
            let mut ops = plcsh::servo::ops(sh.session.entry(i).device.as_mut()).unwrap();
            for o in params::parameters() {
                let v = pick(o, &mut rng);
                plcsh::servo::ServoOps::write_raw(&mut ops, ObjRef::of(o), o.dtype.encode(&plcsh::core::Value::Int(v)))
                    .unwrap_or_else(|e| panic!("seed {seed}: {} = {v}: {e}", o.name));
                want.push((o.name, v));
            }
        }
        // Drive b holds another random set in about half of the parameters.
        {
            let i = sh.session.index("b").unwrap();
            let mut ops = plcsh::servo::ops(sh.session.entry(i).device.as_mut()).unwrap();
            for o in params::parameters() {
                if rng.below(2) == 0 {
                    continue;
                }
                let v = pick(o, &mut rng);
                plcsh::servo::ServoOps::write_raw(&mut ops, ObjRef::of(o), o.dtype.encode(&plcsh::core::Value::Int(v)))
                    .unwrap_or_else(|e| panic!("seed {seed}: b {} = {v}: {e}", o.name));
            }
        }
        let (fa, fb) = (d.join(format!("a{seed}.toml")), d.join(format!("b{seed}.toml")));
        let (fa, fb) = (fa.to_str().unwrap(), fb.to_str().unwrap());
        run(&mut sh, &format!("servo a params save {fa}"));
        // The load writes exactly what the diff shows (in the file's order), each once and read
        // back once: one request per parameter to compare, two per write on the simulated line.
        let l = run(&mut sh, &format!("servo b params diff {fa}"));
        let differ: Vec<String> =
            l[0]["differences"].as_array().unwrap().iter().map(|x| x["name"].as_str().unwrap().to_string()).collect();
        let before = received(&mut sh, "b");
        let l = run(&mut sh, &format!("servo b params load {fa}"));
        let written: Vec<String> =
            l[0]["written"].as_array().unwrap().iter().map(|x| x["name"].as_str().unwrap().to_string()).collect();
        assert_eq!(written, differ, "seed {seed}");
        let n = want.len() as u64;
        assert_eq!(received(&mut sh, "b") - before, n + 2 * written.len() as u64, "seed {seed}");
        run(&mut sh, &format!("servo b params save {fb}"));
        let a = params::ParamSet::parse(&std::fs::read_to_string(fa).unwrap(), fa).unwrap();
        let b = params::ParamSet::parse(&std::fs::read_to_string(fb).unwrap(), fb).unwrap();
        let got: Vec<(&str, i64)> =
            a.parameters.iter().map(|e| (objects::named(&e.name).name, e.value.unwrap())).collect();
        assert_eq!(got, want, "seed {seed}: the file holds what the drive holds");
        assert_eq!(a.parameters, b.parameters, "seed {seed}: drive b now holds drive a's set");
        assert!(params::diff(&a, &b).is_empty(), "seed {seed}");
        let l = run(&mut sh, &format!("servo a params diff {fa} {fb}; servo b params diff {fa}"));
        assert_eq!((&l[0]["count"], &l[1]["count"]), (&0.into(), &0.into()), "seed {seed}: {l:?}");
        let l = run(&mut sh, "servo a params diff --with b");
        assert_eq!(l[0]["count"], 0, "seed {seed}: the two drives hold one set: {l:?}");
    }
}

#[test]
fn two_open_drives_compare_parameter_by_parameter() {
    let mut sh = shell();
    sh.session.open("plc", "sim:K205-16DT").unwrap();
    run(&mut sh, "set b:profile_velocity=1234, b:gear_factor=7");
    let l = run(&mut sh, "servo a params diff --with b");
    assert_eq!((&l[0]["left"], &l[0]["right"], &l[0]["count"]), (&"a".into(), &"b".into(), &2.into()), "{l:?}");
    let diffs = l[0]["differences"].as_array().unwrap();
    assert_eq!((&diffs[0]["name"], &diffs[1]["name"]), (&"profile_velocity".into(), &"gear_factor".into()));
    assert_eq!(diffs[0]["right"]["shown"], "1234 DEC = 0.452 rpm", "with units: {l:?}");
    assert_eq!(error(&mut sh, "servo a params diff --with plc").code, "data-not-a-drive");
    assert_eq!(error(&mut sh, "servo a params diff --with nosuch").kind, plcsh::core::ErrorKind::Usage);
}

/// The wire traffic a recording holds (`plcsh --record`, `plcsh record show --json`): a save
/// sends no write, and a load sends exactly one write for each parameter that differs and
/// none for the others — the frames themselves, decoded by the recorder, not a count.
#[test]
fn the_recorded_wire_traffic_shows_a_load_writes_only_the_parameters_that_differ() {
    let d = dir("recorded");
    let (set, rec) = (d.join("set.toml"), d.join("load.pcapng"));
    let line = format!(
        "set b:profile_velocity=1234, b:gear_factor=7; servo a params save {set}; get b:statusword; \
         servo b params load {set}; get b:statusword; servo b params load {set}",
        set = set.display()
    );
    let o = common::plcsh()
        .args(["--time", "stepped", "--record", rec.to_str().unwrap()])
        .args(["-d", "a=sim-servo:?id=1", "-d", "b=sim-servo:?id=2", "-c", &line])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}{}", common::stdout(&o), String::from_utf8_lossy(&o.stderr));
    let o = common::plcsh().args(["--json", "record", "show", rec.to_str().unwrap()]).output().unwrap();
    let frames: Vec<Value> = common::json_lines(&o).into_iter().filter(|f| f["dir"] == "sent").collect();
    let is_write = |f: &Value| [0x23, 0x2B, 0x2F].contains(&f["function"].as_u64().unwrap_or(0));
    let objects = |fs: &[Value], unit: u64, write: bool| -> Vec<String> {
        fs.iter()
            .filter(|f| f["unit"] == unit && is_write(f) == write)
            .map(|f| f["operands"].as_str().unwrap_or("?").to_string())
            .collect()
    };
    // Drive 1 (a) was only read: by the save.
    assert!(objects(&frames, 1, true).is_empty(), "{:?}", objects(&frames, 1, true));
    let n = params::parameters().count();
    assert_eq!(objects(&frames, 1, false).len(), n);
    // Drive 2 (b): the two `set` writes, then between the statusword reads the load's
    // comparison reads, one write and one read-back per differing parameter, nothing else.
    let marks: Vec<usize> = frames
        .iter()
        .enumerate()
        .filter(|(_, f)| f["unit"] == 2 && f["operands"] == "statusword")
        .map(|(i, _)| i)
        .collect();
    assert_eq!(marks.len(), 2, "{marks:?}");
    assert_eq!(objects(&frames[..marks[0]], 2, true), ["profile_velocity", "gear_factor"]);
    let load = &frames[marks[0] + 1..marks[1]];
    assert_eq!(objects(load, 2, true), ["profile_velocity", "gear_factor"], "only what differs is written");
    let reads = objects(load, 2, false);
    assert_eq!(reads.len(), n + 2, "a read per parameter and a read-back per write: {reads:?}");
    // The second load finds nothing to write: reads only.
    let again = &frames[marks[1] + 1..];
    assert!(objects(again, 2, true).is_empty(), "{:?}", objects(again, 2, true));
    assert_eq!(objects(again, 2, false).len(), n);
}

#[test]
fn a_load_writes_only_what_differs_and_stores_only_when_asked() {
    let d = dir("writes");
    let f = d.join("set.toml");
    let f = f.to_str().unwrap();
    let mut sh = shell();
    let l = run(&mut sh, &format!("servo a params save {f}"));
    let n = l[0]["parameters"].as_array().unwrap().len() as u64;
    assert!(n >= 40, "{n}");
    // Nothing differs: one read per parameter on the line and not one write.
    let before = received(&mut sh, "a");
    let l = run(&mut sh, &format!("servo a params load {f}"));
    assert_eq!(received(&mut sh, "a") - before, n, "{l:?}");
    assert_eq!(l[0]["written"], serde_json::json!([]), "{l:?}");
    assert_eq!(l[0]["unchanged"], n);
    // Two differ: a read of each, then a write and a read-back for each of the two.
    run(&mut sh, "set a:profile_velocity=1234, a:gear_factor=7");
    let l = run(&mut sh, &format!("servo a params diff {f}"));
    assert_eq!(l[0]["count"], 2, "{l:?}");
    let diffs = l[0]["differences"].as_array().unwrap();
    assert_eq!(diffs[0]["name"], "profile_velocity");
    assert_eq!(diffs[0]["left"]["shown"], "273067 DEC = 100 rpm", "the units of a diff: {l:?}");
    let before = received(&mut sh, "a");
    let l = run(&mut sh, &format!("servo a params load {f}"));
    assert_eq!(received(&mut sh, "a") - before, n + 4, "{l:?}");
    let names: Vec<&str> = l[0]["written"].as_array().unwrap().iter().map(|w| w["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["profile_velocity", "gear_factor"]);
    assert_eq!(l[0]["written"][0]["old"], 1234);
    assert_eq!(l[0]["stored"], false);
    let saves = |sh: &mut Shell| {
        let i = sh.session.index("a").unwrap();
        let line = plcsh::servo::simulator(sh.session.entry(i).device.as_mut()).unwrap();
        let s = line.lock().unwrap().drive(1).unwrap().saves;
        s
    };
    assert_eq!(saves(&mut sh), 0, "no store without --store");
    let l = run(&mut sh, &format!("servo a params load {f} --store"));
    assert_eq!((saves(&mut sh), &l[0]["stored"]), (1, &true.into()), "{l:?}");
}

#[test]
fn a_refusal_stops_the_load_naming_the_parameter_and_a_refused_read_is_listed_not_guessed() {
    let d = dir("refusal");
    let f = d.join("set.toml");
    let f = f.to_str().unwrap();
    let mut sh = shell();
    run(&mut sh, &format!("servo a params save {f}; set b:gear_factor=9, b:pulse_filter=3"));
    run(&mut sh, "servo b sim fault abort gear_factor 16#06090030");
    let e = error(&mut sh, &format!("servo b params load {f}"));
    assert_eq!(e.kind, plcsh::core::ErrorKind::Refused, "{e}");
    assert_eq!(e.code, "servo-params-stopped", "{e}");
    assert!(e.message.contains("gear_factor (2508.01)") && e.message.contains("16#06090030"), "{e}");
    assert_eq!(e.operand.as_deref(), Some("gear_factor"));
    // Stopped there: the parameter after it was not written.
    let l = run(&mut sh, "get b:pulse_filter");
    assert_eq!(l[0]["values"][0]["value"], 3, "{l:?}");
    // A drive that refuses a read: the file says so, with the drive's answer, and no value.
    run(&mut sh, "servo b sim fault clear; servo b sim fault abort velocity_kp 16#06010000");
    let g = d.join("refused.toml");
    let g = g.to_str().unwrap();
    let l = run(&mut sh, &format!("servo b params save {g}"));
    assert!(l[0]["text"].as_str().unwrap_or_default().contains("1 refused") || l[0].to_string().contains("1 refused"));
    let set = params::ParamSet::parse(&std::fs::read_to_string(g).unwrap(), g).unwrap();
    let e = set.parameters.iter().find(|e| e.name == "velocity_kp").unwrap();
    assert_eq!((e.value, e.status.as_deref()), (None, Some("refused")), "{e:?}");
    assert!(e.note.as_deref().unwrap_or_default().contains("16#06010000"), "{e:?}");
    // The diff against a drive that answers shows the refusal, and a load skips it.
    let l = run(&mut sh, &format!("servo b sim fault clear; servo a params diff {g}; servo a params load {g}"));
    let diffs = l[1]["differences"].as_array().unwrap();
    assert!(diffs.iter().any(|x| x["name"] == "velocity_kp" && x["left"]["status"] == "refused"), "{l:?}");
    assert_eq!(l[2]["skipped"], serde_json::json!(["velocity_kp"]), "{l:?}");
}

#[test]
fn a_file_from_another_drive_type_or_dictionary_is_refused_before_any_write() {
    let d = dir("other");
    let f = d.join("set.toml");
    let f = f.to_str().unwrap();
    let mut sh = shell();
    run(&mut sh, &format!("servo a params save {f}; set b:gear_factor=9"));
    let text = std::fs::read_to_string(f).unwrap();
    let other = d.join("other.toml");
    std::fs::write(&other, text.replace("type = \"Kinco servo\"", "type = \"Delta ASDA-B2\"")).unwrap();
    let before = received(&mut sh, "b");
    let e = error(&mut sh, &format!("servo b params load {}", other.display()));
    assert_eq!(e.code, "servo-params-other-drive", "{e}");
    assert!(e.message.contains("Delta ASDA-B2") && e.message.contains("Kinco servo"), "{e}");
    let moved = d.join("moved.toml");
    std::fs::write(&moved, text.replace("object = \"2508.01\"", "object = \"2508.09\"")).unwrap();
    let e = error(&mut sh, &format!("servo b params load {}", moved.display()));
    assert_eq!(e.code, "servo-params-unknown-object", "{e}");
    assert!(e.message.contains("gear_factor") && e.message.contains("2508.09"), "{e}");
    let twice = d.join("twice.toml");
    let first = text.find("[[parameter]]").unwrap();
    let second = text[first + 1..].find("[[parameter]]").unwrap() + first + 1;
    std::fs::write(&twice, format!("{text}\n{}", &text[first..second])).unwrap();
    assert_eq!(error(&mut sh, &format!("servo b params load {}", twice.display())).code, "servo-params-duplicate");
    let bad = d.join("bad.toml");
    std::fs::write(&bad, "[drive\n").unwrap();
    assert_eq!(error(&mut sh, &format!("servo b params load {}", bad.display())).code, "servo-params-bad-file");
    assert_eq!(received(&mut sh, "b"), before, "nothing reached the drive");
    assert_eq!(run(&mut sh, "get b:gear_factor")[0]["values"][0]["value"], 9);
}

#[test]
fn lua_saves_compares_and_loads_parameter_sets() {
    let d = dir("lua");
    let f = d.join("set.toml");
    let f = f.to_str().unwrap().replace('\\', "/");
    let script = format!(
        "local s = plcsh.device('servo')\n\
         s:params_save('{f}')\n\
         s.profile_velocity = 99\n\
         local d = s:params_diff('{f}')\n\
         assert(d.count == 1 and d.differences[1].name == 'profile_velocity', 'diff')\n\
         local l = s:params_load('{f}', {{store = true}})\n\
         assert(#l.written == 1 and l.stored == true, 'load')\n\
         assert(s:params_diff('{f}').count == 0, 'after')\n\
         print('lua ok')\n"
    );
    let p = d.join("s.lua");
    std::fs::write(&p, script).unwrap();
    let o = common::plcsh().args(["--time", "stepped", "run"]).arg(&p).output().unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success() && out.contains("lua ok"), "{out}\n{}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn lua_compares_two_open_drives() {
    let d = dir("lua-with");
    let script = "local a = plcsh.device('a')\n\
                  local b = plcsh.device('b')\n\
                  b.gear_factor = 7\n\
                  local d = a:params_diff{with = 'b'}\n\
                  assert(d.count == 1 and d.differences[1].name == 'gear_factor', 'diff')\n\
                  assert(d.left == 'a' and d.right == 'b', 'labels')\n\
                  print('lua ok')\n";
    let p = d.join("w.lua");
    std::fs::write(&p, script).unwrap();
    let o = common::plcsh()
        .args(["--time", "stepped", "-d", "a=sim-servo:?id=1", "-d", "b=sim-servo:?id=2", "run"])
        .arg(&p)
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success() && out.contains("lua ok"), "{out}\n{}", String::from_utf8_lossy(&o.stderr));
}

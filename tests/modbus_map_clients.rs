//! The K2 Modbus map as a third-party master (pymodbus) addresses it, for every model in the
//! catalogue: each area's first and last address answers, one past the last is refused with
//! exception 02, and the last bit and word are the PLC operands the manual's table names —
//! checked through a program in the served PLC, not through plcsh's own driver.
//!
//! K2 manual §3.2.1 (register numbers, 0-based): I bit n = discrete input n; Q bit n = coil n;
//! M0.0…M1023.7 = coils / discrete inputs 320…8511; AIW2n = input register n; AQW2n =
//! holding register n; VW0…VW4094 = holding / input registers 100…2147 (K205). §3.2: one
//! request reads at most 1600 bits or 100 words and writes at most 800 bits or 100 words.
//! Area sizes per model: §2.1.2 (`shared/spec/k2.md` §1), written out here independently of
//! the catalogue in the code.
//!
//! Needs /usr/bin/python3 with pymodbus (Debian's python3-pymodbus, installed by .ci/run);
//! without it the test is skipped, except under CI where that is a failure.

#![cfg(unix)]

mod common;

use common::{pymodbus, serve};
use serde_json::{json, Value};
use std::io::{BufRead, BufReader, Write};
use std::process::{Child, ChildStdin, ChildStdout, Stdio};

/// (model, I bytes, Q bytes, M bytes, V bytes, AI bytes, AQ bytes): K2 manual §2.1.2.
const MODELS: &[(&str, u32, u32, u32, u32, u32, u32)] = &[
    ("K205-16DT", 2, 2, 1024, 4096, 0, 0),
    ("K205-16DR", 2, 2, 1024, 4096, 0, 0),
    ("K205EA-18DT", 1, 1, 1024, 4096, 2, 2),
    ("K205EX-22DT", 2, 2, 1024, 4096, 0, 0),
    ("K204ET-16DT", 1, 1, 1024, 4096, 2, 2),
    ("K209EA-50DX", 3, 3, 1024, 4096, 12, 4),
    ("K209M-56DT", 4, 3, 4096, 16384, 0, 0),
];

struct Probe {
    child: Child,
    tx: ChildStdin,
    rx: BufReader<ChildStdout>,
}

impl Probe {
    fn start(python: &str, addr: &str) -> Probe {
        let (host, port) = addr.rsplit_once(':').unwrap();
        let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/support/modbus_map_probe.py");
        let mut child = std::process::Command::new(python)
            .args([script, host, port])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("start the pymodbus probe");
        let tx = child.stdin.take().unwrap();
        let rx = BufReader::new(child.stdout.take().unwrap());
        Probe { child, tx, rx }
    }

    fn ask(&mut self, q: Value) -> Value {
        writeln!(self.tx, "{q}").unwrap();
        let mut line = String::new();
        self.rx.read_line(&mut line).unwrap();
        serde_json::from_str(&line).unwrap_or_else(|e| panic!("{q}: not JSON: {line:?}: {e}"))
    }

    /// The request is answered (and the answer's values, if any).
    fn ok(&mut self, model: &str, q: Value) -> Vec<Value> {
        let r = self.ask(q.clone());
        assert_eq!(r["result"], "ok", "{model}: {q} → {r}");
        r["values"].as_array().cloned().unwrap_or_default()
    }

    /// The request is refused with Modbus exception `code`.
    fn refused(&mut self, model: &str, q: Value, code: u64) {
        let r = self.ask(q.clone());
        assert_eq!((r["result"].as_str(), r["code"].as_u64()), (Some("exception"), Some(code)), "{model}: {q} → {r}");
    }
}

impl Drop for Probe {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

#[test]
fn every_areas_first_and_last_address_answers_as_the_manuals_table_for_every_model() {
    let Some(python) = pymodbus() else { return };
    let dir = std::env::temp_dir().join(format!("plcsh-modbus-map-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for &(model, ib, qb, mb, vb, aib, aqb) in MODELS {
        // The program shows the last M bit on Q0.0 and copies the last V word to VW0 and the
        // last AQ word (if any) to VW2, so the probe sees which operands its writes reached.
        let mut il = format!("LD %M{}.7\nST %Q0.0\nLD %SM0.0\nMOVE %VW{}, %VW0\n", mb - 1, vb - 2);
        if aqb > 0 {
            il += &format!("LD %SM0.0\nMOVE %AQW{}, %VW2\n", aqb - 2);
        }
        let file = dir.join(format!("{model}.il"));
        std::fs::write(&file, il).unwrap();
        let served = serve(&["--model", model, "--tcp", "127.0.0.1:0", "--program", file.to_str().unwrap()]);
        let addr = served.ready["tcp"].as_str().unwrap_or_else(|| panic!("{}", served.ready)).to_string();
        let mut p = Probe::start(python, &addr);
        let (q_last, i_last) = (qb * 8 - 1, ib * 8 - 1);
        let (m_first, m_last) = (320, 320 + mb * 8 - 1);
        let (v_first, v_last) = (100, 100 + vb / 2 - 1);
        // Coils: Q then M; the gap between them and the end are refused.
        for (op, last) in [("rc", q_last), ("rdi", i_last)] {
            p.ok(model, json!({"op": op, "a": 0, "n": 1}));
            p.ok(model, json!({"op": op, "a": last, "n": 1}));
            p.ok(model, json!({"op": op, "a": 0, "n": last + 1}));
            p.refused(model, json!({"op": op, "a": last + 1, "n": 1}), 2);
            p.refused(model, json!({"op": op, "a": last, "n": 2}), 2);
            p.refused(model, json!({"op": op, "a": m_first - 1, "n": 1}), 2);
            p.ok(model, json!({"op": op, "a": m_first, "n": 1}));
            p.ok(model, json!({"op": op, "a": m_last, "n": 1}));
            p.ok(model, json!({"op": op, "a": m_last + 1 - 1600, "n": 1600}));
            p.refused(model, json!({"op": op, "a": m_last + 1, "n": 1}), 2);
            p.refused(model, json!({"op": op, "a": m_first, "n": 1601}), 3);
        }
        // Registers: AQ / AI from 0, V from 100.
        for (op, words) in [("rhr", aqb / 2), ("rir", aib / 2)] {
            if words == 0 {
                p.refused(model, json!({"op": op, "a": 0, "n": 1}), 2);
            } else {
                p.ok(model, json!({"op": op, "a": 0, "n": words}));
                p.refused(model, json!({"op": op, "a": words, "n": 1}), 2);
                p.refused(model, json!({"op": op, "a": 0, "n": words + 1}), 2);
            }
            p.refused(model, json!({"op": op, "a": v_first - 1, "n": 1}), 2);
            p.ok(model, json!({"op": op, "a": v_first, "n": 100}));
            p.ok(model, json!({"op": op, "a": v_last, "n": 1}));
            p.ok(model, json!({"op": op, "a": v_last - 99, "n": 100}));
            p.refused(model, json!({"op": op, "a": v_last + 1, "n": 1}), 2);
            p.refused(model, json!({"op": op, "a": v_last, "n": 2}), 2);
            p.refused(model, json!({"op": op, "a": v_first, "n": 101}), 3);
        }
        // Writes: the last M bit, V word and AQ word reach the operands the table names.
        p.refused(model, json!({"op": "wc", "a": m_last + 1, "v": [true]}), 2);
        p.refused(model, json!({"op": "wc", "a": m_first, "v": vec![false; 801]}), 3);
        p.ok(model, json!({"op": "wc", "a": m_last + 1 - 800, "v": vec![false; 800]}));
        p.ok(model, json!({"op": "wc", "a": m_last, "v": [true]}));
        assert_eq!(p.ok(model, json!({"op": "rdi", "a": m_last, "n": 1})), [json!(true)], "{model}: coil = DI");
        p.ok(model, json!({"op": "until_c", "a": 0, "v": true}));
        p.refused(model, json!({"op": "wr", "a": v_last + 1, "v": [1]}), 2);
        p.refused(model, json!({"op": "wr", "a": v_first, "v": vec![0; 101]}), 3);
        p.ok(model, json!({"op": "wr", "a": v_last - 99, "v": vec![0; 100]}));
        p.ok(model, json!({"op": "wr", "a": v_last, "v": [0x1234]}));
        assert_eq!(p.ok(model, json!({"op": "rir", "a": v_last, "n": 1})), [json!(0x1234)], "{model}: HR = IR");
        p.ok(model, json!({"op": "until_hr", "a": v_first, "v": 0x1234}));
        if aqb > 0 {
            p.ok(model, json!({"op": "wr", "a": aqb / 2 - 1, "v": [0x0567]}));
            p.ok(model, json!({"op": "until_hr", "a": v_first + 1, "v": 0x0567}));
            p.refused(model, json!({"op": "wr", "a": aqb / 2, "v": [1]}), 2);
        }
        drop(p);
        drop(served);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

//! IL programs as users save them (docs/il.md "Loading"): UTF-8, UTF-16 with a byte-order
//! mark (little- and big-endian) and Windows-1251 (a Russian Windows' ANSI code page) load the
//! same through every loader — the K2's `sim program load` and `program=`, the FX's and the
//! UMPK's `program=` — UTF-16 without a mark loads by the NUL bytes of its ASCII text, broken
//! UTF-16 is refused naming the byte, and a refusal quoting the file escapes its control
//! characters.

mod common;
use common::*;

/// "Пуск" (start) in Windows-1251, written out byte by byte as a Russian Notepad saves it.
const START_1251: [u8; 4] = [0xCF, 0xF3, 0xF1, 0xEA];

fn files(name: &str, text: &str) -> Vec<(String, std::path::PathBuf)> {
    let dir = std::env::temp_dir().join(format!("plcsh-il-files-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let cp: Vec<u8> = text
        .replace("Пуск", "\u{1}")
        .bytes()
        .flat_map(|b| if b == 1 { START_1251.to_vec() } else { vec![b] })
        .collect();
    let le: Vec<u8> = [0xFF, 0xFE].into_iter().chain(text.encode_utf16().flat_map(|u| u.to_le_bytes())).collect();
    let be: Vec<u8> = [0xFE, 0xFF].into_iter().chain(text.encode_utf16().flat_map(|u| u.to_be_bytes())).collect();
    let mut out = Vec::new();
    for (enc, bytes) in [("utf8", text.as_bytes().to_vec()), ("cp1251", cp), ("utf16le", le), ("utf16be", be)] {
        let p = dir.join(format!("{enc}.il"));
        std::fs::write(&p, bytes).unwrap();
        out.push((enc.to_string(), p));
    }
    out
}

#[test]
fn a_k2_program_loads_in_every_encoding_a_windows_editor_saves() {
    let text = "// Пуск насоса\nLD %SM0.0 // Пуск\nINC %VW0\n";
    let mut reads = Vec::new();
    for (enc, p) in files("k2", text) {
        let script = format!("sim program load {}\nsim scan 3\nread VW0\n", p.display());
        let o = run(&["--json", "--time", "stepped", "--device", "sim:K205-16DT"], &script);
        let l = json_lines(&o);
        assert!(l.iter().all(|x| x["ok"] == true), "{enc}: {}", both(&o));
        assert!(l[0]["message"].as_str().unwrap_or("").contains("2 instructions loaded"), "{enc}: {}", l[0]);
        reads.push(l[2].to_string());
        // The device URL's program= takes the same path.
        let url = format!("sim:K205-16DT?program={}", p.display());
        let o = run(&["--json", "--time", "stepped", "--device", &url], "sim program\n");
        assert!(json_lines(&o)[0]["ok"] == true, "{enc} via program=: {}", both(&o));
    }
    assert!(reads.iter().all(|r| *r == reads[0] && r.contains('4')), "the same program ran: {reads:?}");
}

#[test]
fn fx_and_umpk_programs_load_through_the_same_decoder() {
    for (enc, p) in files("fx", "// Пуск\nLD X0\nOUT Y0\n") {
        let url = format!("fx=sim-fx:FX2N?program={}", p.display());
        let o = run(&["--json", "--time", "stepped", "--device", &url], "sim program\n");
        assert!(json_lines(&o)[0]["ok"] == true, "FX {enc}: {}", both(&o));
    }
    for (enc, p) in files("umpk", "// Пуск\nLD I0\nST Q0\n") {
        let url = format!("lab=sim-umpk:UMPK16?program={}", p.display());
        let o = run(&["--json", "--time", "stepped", "--device", &url], "sim program\n");
        assert!(json_lines(&o)[0]["ok"] == true, "UMPK {enc}: {}", both(&o));
    }
}

#[test]
fn broken_utf16_is_refused_naming_the_byte() {
    let dir = std::env::temp_dir().join(format!("plcsh-il-files-{}-broken", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("odd.il");
    std::fs::write(&p, [0xFF, 0xFE, b'L', 0, b'D']).unwrap();
    let o = run(&["--time", "stepped", "--device", "sim:K205-16DT"], &format!("sim program load {}\n", p.display()));
    let e = both(&o);
    assert!(e.contains("odd.il") && e.contains("byte 4"), "{e}");
}

#[test]
fn a_served_k2_runs_a_program_file_in_every_encoding() {
    // `sim serve --program FILE` decodes the file as `sim program load` does (docs/il.md
    // "Loading"); a Modbus client then sees what the program wrote (K2 §3.2.1: VW0 is
    // holding register 100). The first scan runs as the program loads, before readiness.
    let text = "// Пуск насоса\n(* Пуск *)\nLD %SM0.0 // Пуск\nMOVE 1234, %VW0\n";
    for (enc, p) in files("serve", text) {
        let served = serve(&["--tcp", "127.0.0.1:0", "--program", p.to_str().unwrap()]);
        let url = format!("tcp://{}?model=K205-16DT", served.ready["tcp"].as_str().unwrap());
        let o = run(&["--json", "--device", &url], "read VW0\n");
        let l = json_lines(&o);
        assert!(l[0]["ok"] == true && l[0].to_string().contains("1234"), "{enc}: {}", both(&o));
    }
}

/// `text` in UTF-16 without a byte-order mark, little- and big-endian, as files in `name`.
fn bomless(name: &str, text: &str) -> Vec<(&'static str, std::path::PathBuf)> {
    let dir = std::env::temp_dir().join(format!("plcsh-il-files-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let le: Vec<u8> = text.encode_utf16().flat_map(|u| u.to_le_bytes()).collect();
    let be: Vec<u8> = text.encode_utf16().flat_map(|u| u.to_be_bytes()).collect();
    [("utf16le-nobom", le), ("utf16be-nobom", be)]
        .into_iter()
        .map(|(enc, bytes)| {
            let p = dir.join(format!("{enc}.il"));
            std::fs::write(&p, bytes).unwrap();
            (enc, p)
        })
        .collect()
}

/// No character below U+0020 but the line ends, nor DEL.
fn no_control_characters(s: &str) -> bool {
    !s.chars().any(|c| c.is_control() && c != '\n')
}

#[test]
fn utf16_without_a_byte_order_mark_loads_in_every_loader() {
    // docs/il.md "Loading": the NUL bytes of ASCII text say UTF-16 and which byte order.
    for (enc, p) in bomless("k2-nobom", "(* Пуск *)\r\nLD %SM0.0 // Пуск\r\nINC %VW0\r\n") {
        let script = format!("sim program load {}\nsim scan 3\nread VW0\n", p.display());
        let o = run(&["--json", "--time", "stepped", "--device", "sim:K205-16DT"], &script);
        let l = json_lines(&o);
        assert!(l.iter().all(|x| x["ok"] == true), "K2 {enc}: {}", both(&o));
        assert!(l[0]["message"].as_str().unwrap_or("").contains("2 instructions loaded"), "K2 {enc}: {}", l[0]);
        assert!(l[2].to_string().contains('4'), "K2 {enc}: {}", l[2]);
    }
    for (enc, p) in bomless("fx-nobom", "// Пуск\r\nLD X0\r\nOUT Y0\r\n") {
        let url = format!("fx=sim-fx:FX2N?program={}", p.display());
        let o = run(&["--json", "--time", "stepped", "--device", &url], "sim program\n");
        assert!(json_lines(&o)[0]["ok"] == true, "FX {enc}: {}", both(&o));
    }
    for (enc, p) in bomless("umpk-nobom", "// Пуск\nLD I0\nST Q0\n") {
        let url = format!("lab=sim-umpk:UMPK16?program={}", p.display());
        let o = run(&["--json", "--time", "stepped", "--device", &url], "sim program\n");
        assert!(json_lines(&o)[0]["ok"] == true, "UMPK {enc}: {}", both(&o));
    }
}

#[test]
fn a_refusal_quoting_the_file_writes_its_control_characters_out() {
    // An escape sequence and a NUL inside an instruction: each loader names it, escaped,
    // and nothing it prints carries a control character (a terminal would obey it).
    let dir = std::env::temp_dir().join(format!("plcsh-il-files-{}-control", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let cases: [(&str, &str, &str); 3] = [
        ("k2", "sim:K205-16DT", "LD %SM0.0\nINC\u{1b}[2J\0 %VW0\n"),
        ("fx", "fx=sim-fx:FX2N", "LD X0\nOUT\u{1b}[2J\0 Y0\n"),
        ("umpk", "lab=sim-umpk:UMPK16", "LD I0\nST\u{1b}[2J\0 Q0\n"),
    ];
    for (name, dev, text) in cases {
        let p = dir.join(format!("{name}.il"));
        std::fs::write(&p, text).unwrap();
        let url = format!("{dev}?program={}", p.display());
        for json in [false, true] {
            let args: &[&str] = if json {
                &["--json", "--time", "stepped", "--device", &url]
            } else {
                &["--time", "stepped", "--device", &url]
            };
            let o = run(args, "sim program\n");
            let e = both(&o);
            assert!(!o.status.success(), "{name}: {e}");
            assert!(no_control_characters(&e), "{name} (json {json}): {e:?}");
            let escaped = if json { "\\\\u{1B}[2J\\\\0" } else { "\\u{1B}[2J\\0" };
            assert!(e.contains(&format!("{name}.il:2:1")) && e.contains(escaped), "{name} (json {json}): {e}");
        }
    }
}

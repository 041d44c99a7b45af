//! The guide's reference pages (docs/reference/*.md) say what the program does: their tables
//! are made from the program's own tables (`plcsh::cli::reference`), the exit statuses are the
//! ones the binary returns, the Modbus addresses are where a served simulated K2 answers (read
//! with a Modbus client written here, not plcsh's driver), and every environment variable the
//! source reads is listed. `PLCSH_BLESS=1 cargo test --test reference_docs` rewrites the tables.
//! Unix only: a few help texts name the system's own paths (the profile file's place), so the
//! pages show the Linux words.
#![cfg(unix)]

mod common;
use common::*;
use plcsh::cli::reference::{self, GENERATED};
use std::io::{Read, Write};
use std::path::Path;

fn docs() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/docs"))
}

/// The text between a generated table's markers on its page.
fn between(doc: &str, page: &str, name: &str) -> (usize, usize) {
    let (start, end) = (reference::start_marker(name), reference::end_marker(name));
    let a = doc.find(&start).unwrap_or_else(|| panic!("{page}: no marker {start:?}")) + start.len();
    let b = doc[a..].find(&end).unwrap_or_else(|| panic!("{page}: no marker {end:?}")) + a;
    (a, b)
}

#[test]
fn every_generated_table_is_the_programs() {
    let bless = std::env::var_os("PLCSH_BLESS").is_some();
    let mut stale = Vec::new();
    for g in GENERATED {
        let path = docs().join(g.page);
        let doc = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", g.page));
        let (a, b) = between(&doc, g.page, g.name);
        let table = (g.render)();
        if doc[a..b] != table {
            if bless {
                std::fs::write(&path, format!("{}{table}{}", &doc[..a], &doc[b..])).unwrap();
            } else {
                stale.push(format!("{}: {}", g.page, g.name));
            }
        }
    }
    assert!(
        stale.is_empty(),
        "stale tables (PLCSH_BLESS=1 cargo test --test reference_docs rewrites them):\n{}",
        stale.join("\n")
    );
}

#[test]
fn every_page_of_the_reference_is_in_the_summary() {
    let summary = std::fs::read_to_string(docs().join("SUMMARY.md")).unwrap();
    for e in std::fs::read_dir(docs().join("reference")).unwrap() {
        let name = e.unwrap().file_name().to_string_lossy().into_owned();
        assert!(summary.contains(&format!("(reference/{name})")), "docs/SUMMARY.md does not list reference/{name}");
    }
}

/// The flag table names every flag of every subcommand (clap's definition, walked here apart
/// from the renderer).
#[test]
fn the_flag_table_names_every_flag() {
    use clap::CommandFactory;
    let page = std::fs::read_to_string(docs().join("reference/command-line.md")).unwrap();
    fn walk(c: &clap::Command, page: &str, path: &str) {
        for a in c.get_arguments().filter(|a| !a.is_hide_set()) {
            if let Some(l) = a.get_long() {
                assert!(page.contains(&format!("`--{l}`")), "{path} --{l} is not on the page");
            }
        }
        for s in c.get_subcommands().filter(|s| !s.is_hide_set()) {
            let p = format!("{path} {}", s.get_name());
            assert!(page.contains(&format!("### `{p}`")) || s.get_arguments().next().is_none(), "{p}: no section");
            walk(s, page, &p);
        }
    }
    walk(&plcsh::cli::Cli::command(), &page, "plcsh");
}

/// The statuses the page lists are the ones the binary returns (the signal statuses are
/// tests/signals.rs's).
#[test]
fn the_documented_exit_statuses_are_returned() {
    use plcsh::core::exit;
    let page = std::fs::read_to_string(docs().join("reference/exit-status.md")).unwrap();
    let cases: &[(&[&str], i32)] = &[
        (&["-c", "get VW0"], exit::OK),
        (&["-c", "get AIW0"], exit::FAILED),
        (&["--read-only", "-c", "set VW0=1"], exit::FAILED),
        (&["--time", "sometimes", "-c", "get VW0"], exit::USAGE),
        (&["--config", "/nonexistent/plcsh-reference-test.toml", "-c", "get VW0"], exit::USAGE),
    ];
    for (args, want) in cases {
        let o = plcsh().args(*args).output().unwrap();
        assert_eq!(o.status.code(), Some(*want), "plcsh {args:?}: {}", both(&o));
        assert!(page.contains(&format!("| **{want}** |")), "status {want} is not on the page");
    }
}

/// Facts of the K2 manual's Modbus map (§3.2.1) on the page: VW2n is holding register 100 + n,
/// M byte b bit k is coil 320 + 8·b + k, and mbpoll counts from 1.
#[test]
fn the_address_page_agrees_with_the_manual() {
    let page = std::fs::read_to_string(docs().join("reference/modbus-addresses.md")).unwrap();
    for row in [
        "| `VW0` | holding registers | 03 | 100 | `mbpoll -t 4 -r 101 -c 1` |",
        "| `VW100` | holding registers | 03 | 150 | `mbpoll -t 4 -r 151 -c 1` |",
        "| `VD100` | holding registers | 03 | 150…151 | `mbpoll -t 4 -r 151 -c 2` |",
        "| `M10.3` | coils | 01 | 403 | `mbpoll -t 0 -r 404 -c 1` |",
        "| `Q0.0` | coils | 01 | 0 | `mbpoll -t 0 -r 1 -c 1` |",
        "| `AIW2` | input registers | 04 | 1 | `mbpoll -t 3 -r 2 -c 1` |",
    ] {
        assert!(page.contains(row), "the page lacks {row}");
    }
}

/// One Modbus TCP request by hand: function code, 0-based address, count; the reply's data.
fn modbus(addr: &str, fc: u8, start: u16, count: u16) -> Vec<u8> {
    let mut s = std::net::TcpStream::connect(addr).unwrap();
    s.set_read_timeout(Some(std::time::Duration::from_secs(5))).unwrap();
    let mut req = vec![0, 7, 0, 0, 0, 6, 1, fc];
    req.extend(start.to_be_bytes());
    req.extend(count.to_be_bytes());
    s.write_all(&req).unwrap();
    let mut head = [0u8; 9];
    s.read_exact(&mut head).unwrap();
    assert_eq!(head[7], fc, "exception {} for FC {fc} at {start}", head[8]);
    let mut data = vec![0u8; head[8] as usize];
    s.read_exact(&mut data).unwrap();
    data
}

/// The page's addresses, asked of a served simulated K2 by a client that is not plcsh's: what
/// plcsh wrote to each operand is at the address (and mbpoll's `-r` minus one) the page gives.
#[test]
fn the_pages_addresses_are_where_a_served_k2_answers() {
    let served = serve(&["--tcp", "0", "--model", reference::EXAMPLE_MODEL, "--state", "none"]);
    let at = served.ready["tcp"].as_str().unwrap().to_string();
    let url = format!("tcp://{at}?model={}", reference::EXAMPLE_MODEL);
    let o = plcsh()
        .args(["-d", &url, "-c", "set VW0=4660, VW2=22136, VW100=16#0A0B, Q1.2=1, M10.3=1, AQW0=1234"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", both(&o));
    let page = std::fs::read_to_string(docs().join("reference/modbus-addresses.md")).unwrap();
    // `| `OP` | table | FC | ADDRESS | `mbpoll -t T -r R -c N` |`
    let row = |op: &str| -> (u8, u16, u16) {
        let line = page.lines().find(|l| l.starts_with(&format!("| `{op}` |"))).unwrap_or_else(|| panic!("{op}"));
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        let fc: u8 = cells[3].parse().unwrap();
        let address: u16 = cells[4].split('…').next().unwrap().parse().unwrap();
        let r: u16 = cells[5].split("-r ").nth(1).unwrap().split(' ').next().unwrap().parse().unwrap();
        assert_eq!(r, address + 1, "{op}: mbpoll's -r is the protocol address + 1");
        (fc, address, r)
    };
    let word = |op: &str| {
        let (fc, a, _) = row(op);
        let d = modbus(&at, fc, a, 1);
        u16::from_be_bytes([d[0], d[1]])
    };
    let bit = |op: &str| {
        let (fc, a, _) = row(op);
        modbus(&at, fc, a, 1)[0] & 1
    };
    assert_eq!(word("VW0"), 4660);
    assert_eq!(word("VW2"), 22136);
    assert_eq!(word("VW100"), 0x0A0B);
    assert_eq!(word("VB101") & 0xFF, 0x0B, "VB101 is the low byte of VW100's register");
    assert_eq!(word("AQW0"), 1234);
    assert_eq!((bit("Q1.2"), bit("M10.3"), bit("Q0.0"), bit("M0.0")), (1, 1, 0, 0));
    // Input registers carry V too: VW0 by FC 04 at the same address.
    assert_eq!(u16::from_be_bytes(modbus(&at, 4, row("VW0").1, 1)[..2].try_into().unwrap()), 4660);
}

/// Every `PLCSH_…` environment variable the program reads is in the page's table, and every
/// variable in the table is read somewhere (the test's own and the benchmarks' apart).
#[test]
fn every_environment_variable_read_is_listed() {
    fn walk(dir: &Path, found: &mut std::collections::BTreeSet<String>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(&p, found);
            } else if p.extension().is_some_and(|x| x == "rs") {
                let text = std::fs::read_to_string(&p).unwrap();
                for (k, _) in text.match_indices("\"PLCSH_") {
                    let name: String =
                        text[k + 1..].chars().take_while(|c| c.is_ascii_uppercase() || *c == '_').collect();
                    if text[k + 1 + name.len()..].starts_with('"') {
                        found.insert(name);
                    }
                }
            }
        }
    }
    let mut found = std::collections::BTreeSet::new();
    walk(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/src")), &mut found);
    found.retain(|n| n != "PLCSH_BLESS" && !n.starts_with("PLCSH_BENCH_"));
    let listed: Vec<&str> = reference::ENVIRONMENT.iter().map(|(v, _, _)| *v).collect();
    for n in &found {
        assert!(listed.contains(&n.as_str()), "{n} is read by the program but not in reference::ENVIRONMENT");
    }
    for v in listed.iter().filter(|v| v.starts_with("PLCSH_")) {
        assert!(found.contains(*v), "{v} is listed but the program does not read it");
    }
}

/// The messages the catalogue explains are the ones the program prints: each message's fixed
/// words are on the page and in the source (a reworded message shows up here, and the page
/// is reworded with it).
#[test]
fn the_message_catalogue_quotes_the_program() {
    let page = std::fs::read_to_string(docs().join("reference/errors.md")).unwrap();
    let mut source = String::new();
    fn walk(dir: &Path, out: &mut String) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push_str(&std::fs::read_to_string(&p).unwrap());
            }
        }
    }
    walk(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/src")), &mut source);
    // Messages in the catalogue are the program's too (English, the reference language).
    for file in plcsh::core::msg::CATALOGUE_FILES {
        let path = format!("{}/lib/locales/en/{file}.ftl", env!("CARGO_MANIFEST_DIR"));
        source.push_str(&std::fs::read_to_string(path).unwrap());
    }
    for words in [
        "is in use by",
        "is not in the K2 Modbus map",
        "no plcsh helper answers in",
        "is installed but its heartbeat did not move in",
        "mailbox busy: ",
        "races to other clients",
        "did not acknowledge",
        "the helper in the PLC is version 1",
        "the helper in the PLC is version 2",
        "after PLS",
        "(Modbus exception",
        "a reply with an invalid CRC arrived",
        "the device did not answer: no reply from unit",
        "cannot connect to",
        "cannot open the serial port",
        "the session is read-only (--read-only)",
        "allow list",
        "is out of range for",
    ] {
        assert!(page.contains(words), "docs/reference/errors.md does not explain `{words}`");
        assert!(source.contains(words), "no message of the program says `{words}` any more: update the catalogue");
    }
}

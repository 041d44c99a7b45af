//! Replays the fuzz corpus (`fuzz/corpus/TARGET/`) and every input that ever crashed or hung
//! a target (`fuzz/regressions/TARGET/`) through the same entry points the cargo-fuzz targets
//! use (`plcsh::fuzzing`), on stable: none may panic, and each must finish quickly (the
//! parsers run in time linear in their input; a regression to exponential time shows here as
//! a slow input long before it hangs a user's keystroke). The test profile has overflow
//! checks, so an input whose arithmetic overflows panics here as it does under `cargo fuzz -a`;
//! the reproductions of reported overflows also run with the refusal each must get.

use plcsh::fuzzing::TARGETS;
use std::path::Path;
use std::time::{Duration, Instant};

/// Generous for a debug build on a loaded machine; the exponential cases took seconds to hours.
const SLOW: Duration = Duration::from_secs(2);

fn inputs(dir: &Path) -> Vec<std::path::PathBuf> {
    let mut v: Vec<_> = std::fs::read_dir(dir)
        .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.is_file()).collect())
        .unwrap_or_default();
    v.sort();
    v
}

#[test]
fn every_corpus_and_regression_input_passes_its_target() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz");
    let mut seen = 0;
    for (name, run) in TARGETS {
        let corpus = inputs(&root.join("corpus").join(name));
        assert!(!corpus.is_empty(), "fuzz/corpus/{name}/ has no seed inputs");
        assert!(
            root.join("fuzz_targets").join(format!("{name}.rs")).exists(),
            "fuzz/fuzz_targets/{name}.rs is missing"
        );
        for path in corpus.iter().chain(&inputs(&root.join("regressions").join(name))) {
            let data = std::fs::read(path).unwrap();
            let start = Instant::now();
            let r = std::panic::catch_unwind(|| run(&data));
            assert!(r.is_ok(), "{} panicked", path.display());
            assert!(start.elapsed() < SLOW, "{} took {:?}", path.display(), start.elapsed());
            seen += 1;
        }
    }
    // Every target directory names a target (a renamed target leaves no orphan corpus).
    for sub in ["corpus", "regressions"] {
        for d in std::fs::read_dir(root.join(sub)).unwrap() {
            let n = d.unwrap().file_name().to_string_lossy().into_owned();
            assert!(TARGETS.iter().any(|(t, _)| *t == n), "fuzz/{sub}/{n} is not a target");
        }
    }
    assert!(seen > TARGETS.len());
}

/// The reported overflows' reproductions, with the refusal each must get: the helper refuses a mailbox
/// request it cannot serve and keeps scanning; a number too large to hold is refused naming
/// the limit, never wrapped. `cargo test --release --test fuzz_corpus` shows a release
/// build (no overflow checks) refusing them the same way.
#[test]
fn the_overflow_reproductions_are_refused_naming_the_limit() {
    use plcsh::core::Clock;
    use plcsh::k2::agent::protocol::ResultCode;
    use plcsh::k2::sim::agent_probe::AgentProbe;
    use plcsh::output::Style;
    use plcsh::session::Session;
    use plcsh::shell::Shell;

    // The mailbox: `set k2:VW3502=40000, k2:VW3504=1, k2:VW3500=1; set k2:VW3496=1`, and
    // start 100 with length 16#AAAA (acked done after copying one byte).
    let mut probe = AgentProbe::new();
    assert_eq!(probe.request(1, [40000, 1, 0], &[0; 64]), Ok(ResultCode::BadRange));
    assert_eq!(probe.request(2, [100, 0xAAAA, 0], &[0; 64]), Ok(ResultCode::BadRange));
    assert_eq!(probe.request(2, [66, 1, 0], &[0; 64]), Ok(ResultCode::Ok), "still serving");

    let mut session = Session::new(Clock::stepped());
    session.open("plc", "sim:K205-16DT").unwrap();
    let mut sh = Shell::new(session, Style { json: true, color: false });
    let mut refusal = |line: &str| -> String {
        let r = sh.exec(line);
        let e = r.into_iter().find_map(|r| r.err()).unwrap_or_else(|| panic!("`{line}` was accepted"));
        e.1.message.clone()
    };
    // The cycle × frequency product wrapped ("0 Hz is above Q0.0's limit") or panicked.
    for line in ["pwm 0 cycle=368934881474192us width=250us", "pwm 0 cycle=122222h width=2"] {
        let m = refusal(line);
        assert!(m.contains("up to 65 535 µs, or whole milliseconds up to 65 535 ms"), "{line}: {m}");
    }
    // The operand range iterator and group arithmetic overflowed.
    for line in ["get VD4294967292[2]", "get K8M536870912.0[2]", "get AIW4294967295"] {
        let m = refusal(line);
        assert!(m.contains("addresses go up to 65535"), "{line}: {m}");
    }

    // A device URL's timeout in ms × 1000 wrapped to 384 µs.
    for url in ["sim-servo:?id=1&timeout=18446744073709552", "tcp://127.0.0.1:9?timeout=18446744073709552"] {
        let e = Session::new(Clock::stepped()).open("d", url).map(|_| ()).unwrap_err();
        assert!(e.message.contains("longer than a day (86400000 ms)"), "{url}: {e}");
    }
}

//! Replays the fuzz corpus (`fuzz/corpus/TARGET/`) and every input that ever crashed or hung
//! a target (`fuzz/regressions/TARGET/`) through the same entry points the cargo-fuzz targets
//! use (`plcsh::fuzzing`), on stable: none may panic, and each must finish quickly (the
//! parsers run in time linear in their input; a regression to exponential time shows here as
//! a slow input long before it hangs a user's keystroke).

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

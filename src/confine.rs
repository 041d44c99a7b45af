//! The rules of a sandboxed run (`plcsh run --sandbox`, every submission and grader that
//! `plcsh lab` runs), held by the session so that every path obeys them: the session refuses
//! to open a real device here ([`crate::session::Session::open`] asks [`Confinement::check_url`]
//! before any transport is touched), shell commands that read or write files ask
//! [`Confinement::check_read`] / [`Confinement::check_write`], and snapshots are files under
//! the write directory, never named snapshots in the user's data directory. The Lua side
//! (`script::sandbox`) removes the parts of Lua that reach outside plcsh and routes Lua's own
//! file functions through the same checks.
//!
//! The write rule itself ([`WriteRule`], [`check_write`]) is here too: the shell's commands
//! that write files (`trend … to=`, `eeprom dump`, …) hold one, unrestricted outside a sandbox.

use crate::core::msg::Msg;
use crate::core::url::DeviceUrl;
use crate::core::{Error, Result};
use crate::msg;
use std::path::{Path, PathBuf};

/// Device URL schemes a sandboxed run may open: the in-process simulators.
pub const SIMULATED: &[&str] = &["sim", "sim-servo", "sim-umpk", "sim-fx"];

/// What a sandboxed run may touch.
#[derive(Clone, Debug, Default)]
pub struct Confinement {
    /// Folders whose files may be read (the lab folder, the submission's folder, the write directory).
    pub read: Vec<PathBuf>,
    /// The one folder files may be written in (none: no file is written).
    pub write: Option<PathBuf>,
    /// What the read rule covers, in words, for messages that must not show the folders'
    /// paths (a graded submission is not told where the lab lives).
    pub view: Option<String>,
    /// `Some(grants)` while a graded submission runs: the machine is the lab's, and of what
    /// changes the bench rather than drives it ([`bench_action`]) only the actions its
    /// `lab.toml` grants by name are allowed.
    pub machine: Option<Vec<String>>,
}

/// The actions that change the bench rather than drive it, by the name a lab grants them
/// with (`grants = ["sim faults"]` in `lab.toml`): a program on the real machine could do
/// none of them. Every `sim` sub-command but `sim time`, `sim step` (waiting is what a
/// program does) and `sim snapshot save`, the simulators' own controls (`servo sim`, `umpk sim`), opening and
/// closing devices (`connect`, `close`, `plcsh.connect`), setting the PLC's clock from the
/// host (`rtc sync`) and the user's folders (`paths`).
#[allow(clippy::type_complexity)] // one row: the name a lab grants, what the action does
pub const BENCH_ACTIONS: &[(&str, fn() -> Msg)] = &[
    ("sim clock", || msg!("tbl-bench-sim-clock")),
    ("sim input", || msg!("tbl-bench-sim-input")),
    ("sim quad", || msg!("tbl-bench-sim-quad")),
    ("sim inputs", || msg!("tbl-bench-sim-inputs")),
    ("sim retain", || msg!("tbl-bench-sim-retain")),
    ("sim program", || msg!("tbl-bench-sim-program")),
    ("sim cpu", || msg!("tbl-bench-sim-cpu")),
    ("sim stop", || msg!("tbl-bench-sim-stop")),
    ("sim pause", || msg!("tbl-bench-sim-pause")),
    ("sim switch", || msg!("tbl-bench-sim-switch")),
    ("sim scan", || msg!("tbl-bench-sim-scan")),
    ("sim break", || msg!("tbl-bench-sim-break")),
    ("sim stepi", || msg!("tbl-bench-sim-stepi")),
    ("sim stepn", || msg!("tbl-bench-sim-stepn")),
    ("sim wire", || msg!("tbl-bench-sim-wire")),
    ("sim wires", || msg!("tbl-bench-sim-wires")),
    ("sim unwire", || msg!("tbl-bench-sim-unwire")),
    ("sim snapshot", || msg!("tbl-bench-sim-snapshot")),
    ("sim snapshots", || msg!("tbl-bench-sim-snapshots")),
    ("sim fault", || msg!("tbl-bench-sim-fault")),
    ("sim faults", || msg!("tbl-bench-sim-faults")),
    ("servo sim", || msg!("tbl-bench-servo-sim")),
    ("umpk sim", || msg!("tbl-bench-umpk-sim")),
    ("connect", || msg!("tbl-bench-connect")),
    ("close", || msg!("tbl-bench-close")),
    ("rtc sync", || msg!("tbl-bench-rtc-sync")),
    ("paths", || msg!("tbl-bench-paths")),
];

/// The bench action a command is (its [`BENCH_ACTIONS`] name), or `None` when it drives the
/// devices. `cmd` is the command's registry name, `args` its words after a leading device
/// word (`rtc press sync` → `sync`).
pub fn bench_action(cmd: &str, args: &str) -> Option<String> {
    let mut words = args.split_whitespace().map(str::to_ascii_lowercase);
    let first = words.next();
    match cmd {
        "sim" => match first.as_deref().unwrap_or("time") {
            "time" | "step" => None,
            // Saving the state changes nothing (the file rules hold); restoring it does.
            "snapshot" if words.next().as_deref() == Some("save") => None,
            sub => Some(format!("sim {sub}")),
        },
        // The device word may come first: `servo axis1 sim fault`.
        "servo" | "umpk" => {
            let second = words.next();
            (first.as_deref() == Some("sim") || second.as_deref() == Some("sim")).then(|| format!("{cmd} sim"))
        }
        "connect" | "close" | "paths" => Some(cmd.to_string()),
        "rtc" => (first.as_deref() == Some("sync")).then(|| "rtc sync".to_string()),
        _ => None,
    }
}

fn canon(p: &Path) -> PathBuf {
    crate::core::fspath::canonical(p).unwrap_or_else(|_| p.to_path_buf())
}

/// `path` with `..` and symbolic links resolved as far as the file system allows (a file that
/// does not exist yet resolves through its folder).
fn resolve(path: &Path) -> Option<PathBuf> {
    if let Ok(p) = crate::core::fspath::canonical(path) {
        return Some(p);
    }
    let name = path.file_name()?;
    let parent = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    Some(crate::core::fspath::canonical(parent).ok()?.join(name))
}

/// The rule: `None` writes anywhere; `Some(None)` nowhere; `Some(Some(dir))` only under `dir`.
pub type WriteRule = Option<Option<PathBuf>>;

/// Checks that `path` may be written under `rule` (after resolving `..` and symbolic links in
/// its directory).
pub fn check_write(rule: &WriteRule, path: &str) -> Result<()> {
    let Some(dir) = rule else { return Ok(()) };
    let Some(dir) = dir else {
        return Err(
            Error::unsupported(msg!("tbl-confine-no-write", path = path)).hint(msg!("tbl-confine-no-write-hint"))
        );
    };
    let dir = crate::core::fspath::canonical(dir).unwrap_or_else(|_| dir.clone());
    let p = Path::new(path);
    let parent = p.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let resolved = crate::core::fspath::canonical(parent).ok().map(|d| d.join(p.file_name().unwrap_or_default()));
    match resolved {
        Some(r) if r.starts_with(&dir) && p.file_name().is_some() => Ok(()),
        _ => Err(Error::unsupported(msg!("tbl-confine-write-outside", path = path, dir = dir.display().to_string()))
            .hint(msg!("tbl-confine-write-outside-hint"))),
    }
}

impl Confinement {
    pub fn new(read: Vec<PathBuf>, write: Option<PathBuf>) -> Confinement {
        let write = write.map(|w| canon(&w));
        let mut read: Vec<PathBuf> = read.iter().map(|r| canon(r)).collect();
        read.extend(write.clone());
        Confinement { read, write, view: None, machine: None }
    }

    /// Refuses bench action `what` ([`BENCH_ACTIONS`]) while the machine is the lab's, unless
    /// the lab grants it.
    pub fn check_bench(&self, what: &str) -> Result<()> {
        match &self.machine {
            Some(grants) if !grants.iter().any(|g| g == what) => {
                let why = BENCH_ACTIONS
                    .iter()
                    .find(|(n, _)| *n == what)
                    .map_or_else(|| msg!("tbl-bench-other"), |(_, w)| w());
                Err(Error::unsupported(msg!("tbl-bench-refused", what = what, why = why.text))
                    .hint(msg!("tbl-bench-refused-hint", what = what)))
            }
            _ => Ok(()),
        }
    }

    /// Refuses every device URL but the in-process simulators, and a simulator's file
    /// parameters outside the run's folders. Called where the session opens devices.
    pub fn check_url(&self, url: &str) -> Result<()> {
        let u = DeviceUrl::parse(url)?;
        let scheme = u.scheme.to_ascii_lowercase();
        if !SIMULATED.contains(&scheme.as_str()) {
            return Err(Error::unsupported(msg!("tbl-confine-real-device", url = url))
                .hint(msg!("tbl-confine-real-device-hint")));
        }
        if let Some(p) = u.param("program") {
            self.check_read(p)?;
        }
        if let Some(s) = u.param("state") {
            self.check_write(s)?;
        }
        Ok(())
    }

    /// Refuses reading `path` outside the run's folders.
    pub fn check_read(&self, path: &str) -> Result<()> {
        match resolve(Path::new(path)) {
            Some(r) if self.read.iter().any(|d| r.starts_with(d)) => Ok(()),
            _ => Err(Error::unsupported(msg!("tbl-confine-read-outside", path = path))
                .hint(msg!("tbl-confine-read-outside-hint", folders = self.folders()))),
        }
    }

    /// Refuses writing `path` outside the write directory.
    pub fn check_write(&self, path: &str) -> Result<()> {
        check_write(&Some(self.write.clone()), path)
    }

    /// The file of snapshot `name` for saving (`save`) or restoring: a path under the run's
    /// folders; a bare name (the user's data directory) is refused.
    pub fn snapshot_file(&self, name: &str, save: bool) -> Result<PathBuf> {
        if !(name.contains('/') || name.ends_with(".json")) {
            return Err(Error::unsupported(msg!("tbl-confine-named-snapshot", name = name))
                .hint(msg!("tbl-confine-named-snapshot-hint")));
        }
        if save {
            self.check_write(name)?;
        } else {
            self.check_read(name)?;
        }
        Ok(PathBuf::from(name))
    }

    fn folders(&self) -> String {
        if let Some(v) = &self.view {
            return v.clone();
        }
        if self.read.is_empty() {
            return msg!("tbl-confine-no-folder").text;
        }
        self.read.iter().map(|p| p.display().to_string()).collect::<Vec<_>>().join(", ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every bench action's description is in every language, and every `tbl-bench-…` id of
    /// the catalogue but the refusal's own belongs to an action.
    #[test]
    fn every_bench_action_has_its_text_in_every_language() {
        use crate::core::msg::Lang;
        let used: Vec<&str> = BENCH_ACTIONS.iter().map(|(_, w)| w().id).collect();
        for lang in Lang::ALL {
            let ids = crate::core::msg::ids(*lang);
            for id in &used {
                assert!(ids.iter().any(|i| i == id), "{id} has no text in {}", lang.tag());
            }
        }
        let own = ["tbl-bench-refused", "tbl-bench-refused-hint", "tbl-bench-other"];
        for id in crate::core::msg::ids(Lang::En) {
            if id.starts_with("tbl-bench-") {
                assert!(used.contains(&id.as_str()) || own.contains(&id.as_str()), "{id} belongs to no action");
            }
        }
    }

    #[test]
    fn real_devices_are_refused_and_simulators_allowed() {
        let c = Confinement::new(vec![std::env::temp_dir()], None);
        for url in [
            "tcp://127.0.0.1:502",
            "rtu:/dev/ttyUSB0",
            "rtu+tcp://10.0.0.1:4001",
            "kinco:/dev/ttyUSB0?id=1",
            "kinco+rfc2217://h:1",
            "umpk:/dev/ttyS0",
            "umpk+tcp://h:1",
            "fx:/dev/ttyS0",
            "fxlink:COM3",
        ] {
            let e = c.check_url(url).unwrap_err();
            assert!(e.to_string().contains("sandboxed run"), "{url}: {e}");
        }
        for url in ["sim:K205-16DT", "sim-servo:?id=1", "sim-umpk:UMPK16", "sim-fx:FX2N"] {
            c.check_url(url).unwrap();
        }
        assert!(c.check_url("sim-umpk:UMPK16?state=/etc/flash.json").is_err());
        assert!(c.check_url("sim:K205-16DT?program=/etc/passwd").is_err());
    }

    #[test]
    fn bench_actions_are_refused_unless_granted_and_driving_is_not_one() {
        for (cmd, args, want) in [
            ("sim", "unwire all", Some("sim unwire")),
            ("sim", "", None),
            ("sim", "step 10ms", None),
            ("sim", "snapshot save w/s.json", None),
            ("sim", "snapshot restore w/s.json", Some("sim snapshot")),
            ("sim", "clock real", Some("sim clock")),
            ("servo", "axis1 sim fault", Some("servo sim")),
            ("servo", "enable", None),
            ("umpk", "sim reference lab1", Some("umpk sim")),
            ("rtc", "sync", Some("rtc sync")),
            ("rtc", "set 2026-01-01T00:00:00", None),
            ("close", "servo", Some("close")),
            ("get", "VW0", None),
        ] {
            assert_eq!(bench_action(cmd, args).as_deref(), want, "{cmd} {args}");
        }
        // Every action named is one a lab can grant.
        for (cmd, args) in [("sim", "wire a -> b"), ("servo", "sim x"), ("connect", "x sim:"), ("paths", "")] {
            let a = bench_action(cmd, args).unwrap();
            assert!(BENCH_ACTIONS.iter().any(|(n, _)| *n == a), "{a}");
        }
        let mut c = Confinement::new(vec![], None);
        c.check_bench("sim unwire").unwrap();
        c.machine = Some(vec!["sim faults".into()]);
        c.check_bench("sim faults").unwrap();
        let e = c.check_bench("sim unwire").unwrap_err();
        assert!(e.message.contains("not available to a graded submission"), "{e}");
    }

    #[test]
    fn reads_stay_in_the_folders_and_named_snapshots_are_refused() {
        let d = std::env::temp_dir().join(format!("plcsh-confine-{}", std::process::id()));
        std::fs::create_dir_all(d.join("out")).unwrap();
        std::fs::write(d.join("a.txt"), "x").unwrap();
        let c = Confinement::new(vec![d.clone()], Some(d.join("out")));
        c.check_read(d.join("a.txt").to_str().unwrap()).unwrap();
        assert!(c.check_read("/etc/passwd").is_err());
        assert!(c.check_read(d.join("../x").to_str().unwrap()).is_err());
        assert!(c.snapshot_file("lab1", true).is_err());
        assert!(c.snapshot_file(d.join("grade.json").to_str().unwrap(), true).is_err());
        c.snapshot_file(d.join("out/s.json").to_str().unwrap(), true).unwrap();
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn writes_stay_under_the_directory() {
        let dir = std::env::temp_dir().join(format!("plcsh-confine-writes-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        assert!(check_write(&None, "/etc/x").is_ok());
        assert!(check_write(&Some(None), "x.csv").is_err());
        let rule = Some(Some(dir.clone()));
        assert!(check_write(&rule, dir.join("a.csv").to_str().unwrap()).is_ok());
        assert!(check_write(&rule, dir.join("../a.csv").to_str().unwrap()).is_err());
        assert!(check_write(&rule, "/etc/passwd").is_err());
        let _ = std::fs::remove_dir_all(&dir);
    }
}

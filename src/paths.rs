//! Where plcsh keeps its files, in one place: the profile file, the user's Lua modules, the
//! simulated K2's state, the REPL history, named snapshots, a served UMPK's flash, and
//! recordings. Every module that reads or writes one of them asks here, and `plcsh paths`
//! (or `paths` in the shell) prints this table with the file in effect for this run.
//!
//! The user's directories come from `directories` (`~/.config/plcsh` and
//! `~/.local/share/plcsh` on Linux, `~/Library/Application Support/plcsh` on macOS);
//! environment variables and flags override single files. On Windows the split is the usual
//! one: the configuration (profiles, the user's Lua modules) roams with the user in
//! `%APPDATA%\plcsh\config`, while what belongs to this PC — the simulator's state, history,
//! snapshots, UMPK flash images — stays in `%LOCALAPPDATA%\plcsh\data`, so a lab PC with
//! roaming profiles does not carry them to every log-on.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

fn dirs() -> Option<directories::ProjectDirs> {
    directories::ProjectDirs::from("", "", "plcsh")
}

fn env_path(key: &str) -> Option<PathBuf> {
    std::env::var_os(key).filter(|p| !p.is_empty()).map(PathBuf::from)
}

/// The profile file: `PLCSH_CONFIG`, else `devices.toml` in the user's config directory
/// (`--config FILE` overrides both).
pub fn config_file() -> Option<PathBuf> {
    env_path("PLCSH_CONFIG").or_else(|| dirs().map(|d| d.config_dir().join("devices.toml")))
}

/// The user's Lua modules (`lib/` in the config directory).
pub fn user_lib() -> Option<PathBuf> {
    dirs().map(|d| d.config_dir().join("lib"))
}

/// The directories `require` searches before the modules built into the binary, most specific
/// first (only those that exist): `PLCSH_LIB`, the user's [`user_lib`], the project's `lib/`
/// ([`project_lib`]). The Lua searcher (`script::paths`) walks them; `paths` shows them.
pub fn lib_dirs() -> Vec<PathBuf> {
    let mut dirs: Vec<PathBuf> = Vec::new();
    if let Some(v) = std::env::var_os("PLCSH_LIB") {
        dirs.extend(std::env::split_paths(&v).filter(|p| !p.as_os_str().is_empty()));
    }
    dirs.extend(user_lib());
    if let Some(found) = project_lib() {
        dirs.push(found);
    }
    dirs.retain(|d| d.is_dir());
    dirs.dedup();
    dirs
}

/// The project's `lib/` on disk next to the executable, when there is one.
pub fn project_lib() -> Option<PathBuf> {
    let exe = std::env::current_exe().ok()?;
    [2usize, 1, 0]
        .iter()
        .filter_map(|up| {
            let mut p = exe.parent();
            for _ in 0..*up {
                p = p.and_then(Path::parent);
            }
            p.map(|p| p.join("lib"))
        })
        .find(|p| p.join("commission.lua").is_file())
}

/// The simulated K2's state file (backup area, retained ranges, clock) by default.
pub fn k2_state() -> Option<PathBuf> {
    dirs().map(|d| d.data_local_dir().join("state.json"))
}

/// The REPL history.
pub fn history() -> Option<PathBuf> {
    dirs().map(|d| d.data_local_dir().join("history.txt"))
}

/// The directory named snapshots live in: `PLCSH_SNAPSHOTS`, else the data directory's.
pub fn snapshots() -> Option<PathBuf> {
    env_path("PLCSH_SNAPSHOTS").or_else(|| dirs().map(|d| d.data_local_dir().join("snapshots")))
}

/// The file of snapshot `name` (a path when it has a path separator of this system — `/`, and
/// `\` on Windows — or a drive letter, or ends in `.json`).
pub fn snapshot_file(name: &str) -> crate::core::Result<PathBuf> {
    // A drive (`C:x`) is a path prefix on Windows only; elsewhere Path says there is none.
    let drive = Path::new(name).components().any(|c| matches!(c, std::path::Component::Prefix(_)));
    if name.chars().any(std::path::is_separator) || drive || name.ends_with(".json") {
        return Ok(PathBuf::from(name));
    }
    if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || "_-.".contains(c)) {
        return Err(crate::core::Error::usage(crate::msg!("snapshot-not-name", name = name))
            .hint(crate::msg!("snapshot-not-name-hint")));
    }
    let d = snapshots().ok_or_else(|| {
        crate::core::Error::io(crate::msg!("snapshot-no-data-dir")).hint(crate::msg!("snapshot-no-data-dir-hint"))
    })?;

    Ok(d.join(format!("{name}.json")))
}

/// The directory a served UMPK keeps its flash in (one file per model and link) unless
/// `--umpk-state FILE` names one.
pub fn umpk_flash() -> Option<PathBuf> {
    dirs().map(|d| d.data_local_dir().join("umpk"))
}

/// The files in effect for this run, as the command line set them (`--config`, `--state`):
/// set once at start-up, read by `paths`.
#[derive(Clone, Debug, Default)]
pub struct InEffect {
    pub config: Option<PathBuf>,
    /// `None`: the state file is off (`--state none`).
    pub state: Option<PathBuf>,
    pub record: Option<PathBuf>,
}

static IN_EFFECT: OnceLock<InEffect> = OnceLock::new();

/// Records the files the command line chose (the first call wins).
pub fn set_in_effect(e: InEffect) {
    let _ = IN_EFFECT.set(e);
}

/// One row of `paths`: a name (the JSON key), the path, and what sets it.
pub struct Place {
    pub name: &'static str,
    pub path: String,
    pub set_by: &'static str,
}

fn shown(p: Option<PathBuf>) -> String {
    p.map(|p| p.display().to_string()).unwrap_or_else(|| "-".into())
}

/// Every file plcsh uses, with the one in effect for this run.
pub fn places() -> Vec<Place> {
    let e = IN_EFFECT.get().cloned().unwrap_or_else(|| InEffect {
        config: config_file(),
        state: env_path("PLCSH_STATE").or_else(k2_state),
        record: None,
    });
    let lib: Vec<String> = lib_dirs().iter().map(|d| d.display().to_string()).collect();
    let lib = if lib.is_empty() { "built in".to_string() } else { format!("{}, then built in", lib.join(", ")) };
    vec![
        Place { name: "config", path: shown(e.config), set_by: "--config, PLCSH_CONFIG" },
        Place { name: "lib", path: lib, set_by: "PLCSH_LIB" },
        Place { name: "user_lib", path: shown(user_lib()), set_by: "(your modules)" },
        Place {
            name: "state",
            path: e.state.map(|p| p.display().to_string()).unwrap_or_else(|| "none".into()),
            set_by: "--state, PLCSH_STATE",
        },
        Place { name: "history", path: shown(history()), set_by: "" },
        Place { name: "snapshots", path: shown(snapshots()), set_by: "PLCSH_SNAPSHOTS" },
        Place { name: "umpk_flash", path: shown(umpk_flash()), set_by: "sim serve --umpk-state" },
        Place {
            name: "recordings",
            path: e.record.map(|p| p.display().to_string()).unwrap_or_else(|| "none (--record FILE)".into()),
            set_by: "--record",
        },
    ]
}

//! What a simulated K2 keeps when it is switched off (manual §2.2.8–2.2.10; k2.md §7):
//! the E2PROM backup area (VB3648–VB3902 by default, up to VB4095 by configuration), the
//! battery-retained ranges the user configured, the real-time clock, and the E2PROM's
//! per-byte write counts (the manual: about 1 000 000 writes).
//!
//! Everything lives in one JSON state file — `~/.local/share/plcsh/state.json` by default,
//! or `--state FILE` — holding one entry per model, restored when the simulator starts.
//!
//! Durability (what a real K2 keeps through a power cut, the simulator keeps through
//! `kill -9`): a store that touches the backup area or a retained range rewrites the file
//! before it is acknowledged — through [`crate::core::durable`]: written and fsync'd without
//! a name where the system allows, named `.NAME.tmp`, renamed over the file, and the
//! directory fsync'd — so a crash at any moment leaves the old or the new file, never half
//! of one, and every acknowledged store is in it. Chosen over a write-through journal for simplicity: the file stays one readable
//! JSON document; the cost is measured in BENCHMARKS.md ("Durable retained writes").
//! Stores elsewhere cost nothing extra.
//!
//! One process per state file: the simulator holds an advisory lock (`flock`) on
//! `.NAME.lock` beside the file while it uses it, with its process id inside, so a second
//! plcsh on the same file is refused naming the first instead of silently overwriting its
//! state. The lock dies with its process (also on `kill -9`); the lock file itself stays,
//! empty of meaning, and a stale `.NAME.tmp` from a crash is removed by the next owner.
//!
//! Write counting (stated assumption): every store that touches a backup byte counts as
//! one E2PROM write of that byte, even when the value does not change — the manual does
//! not say whether the firmware compares before writing, and counting every store errs on
//! the side of warning early. Crossing 10 000, 100 000, 500 000 and 1 000 000 writes on a
//! byte raises an `eeprom-wear` event.

use crate::core::durable::{self, sibling};
use crate::core::{Error, Result};
use crate::k2::catalog::{EEPROM_ENDURANCE, EEPROM_FIRST, EEPROM_LAST_DEFAULT, EEPROM_LAST_MAX};
use crate::k2::operand::Area;
use crate::msg;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// Write counts at which a wear event is raised.
pub const WEAR_MARKS: [u64; 4] = [10_000, 100_000, 500_000, EEPROM_ENDURANCE];

/// A battery-retained byte range (V or M).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Retain {
    pub area: Area,
    pub first: u32,
    pub len: u32,
}

/// The backup configuration and E2PROM bookkeeping of one simulator.
#[derive(Clone, Debug)]
pub struct Backup {
    /// Last V byte of the E2PROM backup area (VB3902 … VB4095).
    pub last: u32,
    /// Writes per byte VB3648…VB4095, over the simulated PLC's life.
    pub writes: Vec<u64>,
    /// Writes per byte in this session (for the wear projection).
    pub session: Vec<u64>,
    pub retain: Vec<Retain>,
    /// The state file, when the simulator persists.
    pub path: Option<PathBuf>,
    /// The lock held on the state file while this simulator uses it.
    pub lock: Option<std::sync::Arc<std::fs::File>>,
    /// Virtual time this session's counting started.
    pub since: Duration,
}

impl Default for Backup {
    fn default() -> Backup {
        let n = (EEPROM_LAST_MAX - EEPROM_FIRST + 1) as usize;
        Backup {
            last: EEPROM_LAST_DEFAULT,
            writes: vec![0; n],
            session: vec![0; n],
            retain: Vec::new(),
            path: None,
            lock: None,
            since: Duration::ZERO,
        }
    }
}

impl Backup {
    /// Sets the end of the backup area (3902 default, at most 4095, §2.2.8).
    pub fn set_last(&mut self, last: u32) -> Result<()> {
        if !(EEPROM_LAST_DEFAULT..=EEPROM_LAST_MAX).contains(&last) {
            return Err(Error::usage(msg!(
                "k2-backup-end",
                default = EEPROM_LAST_DEFAULT,
                max = EEPROM_LAST_MAX,
                last = last
            ))
            .hint(msg!("k2-backup-end-hint")));
        }
        self.last = last;
        Ok(())
    }

    /// Counts a store to V bytes `first..first+len`; returns the wear marks crossed as
    /// (byte, writes).
    pub fn count(&mut self, first: u32, len: u32) -> Vec<(u32, u64)> {
        let mut crossed = Vec::new();
        let lo = first.max(EEPROM_FIRST);
        let hi = (first + len).min(self.last + 1);
        for b in lo..hi {
            let i = (b - EEPROM_FIRST) as usize;
            self.writes[i] += 1;
            self.session[i] += 1;
            if WEAR_MARKS.contains(&self.writes[i]) {
                crossed.push((b, self.writes[i]));
            }
        }
        crossed
    }

    /// The most-written byte: (byte, lifetime writes, session writes).
    pub fn hottest(&self) -> Option<(u32, u64, u64)> {
        let (i, w) = self.writes.iter().enumerate().max_by_key(|(_, w)| **w)?;
        (*w > 0).then(|| (EEPROM_FIRST + i as u32, *w, self.session[i]))
    }
}

/// A saved retained range.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct RetainSaved {
    pub area: String,
    pub first: u32,
    pub data: String,
}

/// A saved clock: its reading and the host's Unix time when it was saved.
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
pub struct RtcSaved {
    pub civil_secs: i64,
    pub host_unix: i64,
}

/// What one model keeps.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct ModelState {
    pub backup_last: u32,
    /// The backup area VB3648…VB(backup_last), hex.
    pub backup: String,
    pub eeprom_writes: Vec<u64>,
    #[serde(default)]
    pub retain: Vec<RetainSaved>,
    pub rtc: Option<RtcSaved>,
}

#[derive(Debug, Default, Serialize, Deserialize)]
struct StateFile {
    version: u32,
    models: BTreeMap<String, ModelState>,
}

/// The default state file (`~/.local/share/plcsh/state.json` on Linux).
pub fn default_path() -> Option<PathBuf> {
    crate::paths::k2_state()
}

pub fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

pub fn unhex(s: &str) -> Option<Vec<u8>> {
    if !s.len().is_multiple_of(2) {
        return None;
    }
    (0..s.len()).step_by(2).map(|i| u8::from_str_radix(s.get(i..i + 2)?, 16).ok()).collect()
}

fn read_file(path: &Path) -> Result<StateFile> {
    match std::fs::read_to_string(path) {
        Ok(text) => serde_json::from_str(&text).map_err(|e| {
            Error::io(msg!("k2-state-invalid", file = path.display().to_string()))
                .cause(e)
                .hint(msg!("k2-state-invalid-hint"))
        }),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(StateFile { version: 1, ..Default::default() }),
        Err(e) => Err(Error::io(msg!("k2-state-unreadable", file = path.display().to_string())).cause(e)),
    }
}

/// The saved state of `model`, if the file has one.
pub fn load(path: &Path, model: &str) -> Result<Option<ModelState>> {
    Ok(read_file(path)?.models.remove(model))
}

/// Stores `model`'s state in the file, keeping other models' entries; atomic.
pub fn save(path: &Path, model: &str, state: ModelState) -> Result<()> {
    let mut file = read_file(path).unwrap_or_default();
    file.version = 1;
    file.models.insert(model.to_string(), state);
    let text = serde_json::to_string_pretty(&file).map_err(|e| Error::io(msg!("k2-state-cannot-encode")).cause(e))?;
    // Nothing changed (a read-only session): leave the file alone — no write, no fsync.
    if std::fs::read(path).is_ok_and(|old| old == text.as_bytes()) {
        return Ok(());
    }
    durable::write_atomic(path, text.as_bytes())
}

/// Takes the state file's lock (module doc) or says who holds it; removes a temporary
/// file a crashed owner left.
pub fn lock(path: &Path) -> Result<std::sync::Arc<std::fs::File>> {
    use std::io::{Read, Seek, Write};
    let (dir, lock) = sibling(path, "lock");
    std::fs::create_dir_all(&dir)
        .map_err(|e| Error::io(msg!("file-cannot-create", path = dir.display().to_string())).cause(e))?;
    let mut f = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .create(true)
        .truncate(false)
        .open(&lock)
        .map_err(|e| Error::io(msg!("file-cannot-open", path = lock.display().to_string())).cause(e))?;
    // An advisory lock on Unix (flock), a mandatory one on Windows (LockFileEx): either way
    // one plcsh per state file. Released when the file closes, also on kill -9.
    if f.try_lock().is_err() {
        let mut holder = String::new();
        let _ = f.read_to_string(&mut holder);
        let holder = holder.trim();
        let file = path.display().to_string();
        let m = if holder.is_empty() {
            msg!("k2-state-in-use", file = file)
        } else {
            msg!("k2-state-in-use-by", file = file, pid = holder)
        };
        return Err(Error::usage(m).hint(msg!("k2-state-in-use-hint")));
    }
    let _ = f.set_len(0);
    let _ = f.rewind();
    let _ = write!(f, "{}", std::process::id());
    durable::remove_stale(path);
    Ok(std::sync::Arc::new(f))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_only_the_configured_area_and_marks_wear() {
        let mut b = Backup::default();
        assert!(b.count(3640, 8).is_empty());
        assert_eq!(b.writes[0], 0, "VB3640…VB3647 is outside");
        b.count(3646, 4);
        assert_eq!(&b.writes[..2], &[1, 1]);
        b.count(4000, 2);
        assert_eq!(b.writes[(4000 - EEPROM_FIRST) as usize], 0, "past VB3902 by default");
        b.set_last(4095).unwrap();
        b.count(4000, 2);
        assert_eq!(b.writes[(4000 - EEPROM_FIRST) as usize], 1);
        assert!(b.set_last(5000).is_err());
        let mut crossed = Vec::new();
        for _ in 0..10_000 {
            crossed.extend(b.count(3700, 1));
        }
        assert_eq!(crossed, vec![(3700, 10_000)]);
        assert_eq!(b.hottest().unwrap().0, 3700);
    }

    #[test]
    fn hex_round_trip_and_atomic_save() {
        assert_eq!(unhex(&hex(&[0, 0xAB, 255])).unwrap(), vec![0, 0xAB, 255]);
        assert!(unhex("abc").is_none());
        let dir = std::env::temp_dir().join(format!("plcsh-state-test-{}", std::process::id()));
        let path = dir.join("s.json");
        let st = ModelState { backup_last: 3902, backup: "2a".into(), ..Default::default() };
        save(&path, "K205-16DT", st).unwrap();
        save(&path, "K209M-56DT", ModelState::default()).unwrap();
        assert_eq!(load(&path, "K205-16DT").unwrap().unwrap().backup, "2a", "other models are kept");
        assert!(load(&path, "K204ET-16DT").unwrap().is_none());
        let leftovers =
            std::fs::read_dir(&dir).unwrap().filter(|e| e.as_ref().unwrap().file_name() != "s.json").count();
        assert_eq!(leftovers, 0, "no temporary file left behind");
        let held = lock(&path).unwrap();
        let e = lock(&path).unwrap_err();
        assert!(e.message.contains(&format!("in use by process {}", std::process::id())), "{}", e.message);
        drop(held);
        let again = lock(&path).expect("free again once the holder is gone");
        drop(again);
        let _ = std::fs::remove_file(dir.join(".s.json.lock"));
        std::fs::write(&path, "{not json").unwrap();
        assert!(load(&path, "K205-16DT").is_err());
        let _ = std::fs::remove_dir_all(&dir);
    }
}

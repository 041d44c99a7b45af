//! `lab.toml`: what a teaching lab is made of — its devices (a bench file or a `[devices]`
//! table), a start snapshot, the starter files handed to students, the reference solution,
//! the grader script, the limits of one graded run and the points of each criterion. Parsed
//! once, checked whole (every file named exists, inside the lab folder), with messages that
//! name the key and what to write.

use crate::core::{Error, Result};
use crate::msg;
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// The file name of a lab's description, in the lab folder.
pub const FILE: &str = "lab.toml";

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Raw {
    title: String,
    bench: Option<String>,
    #[serde(default)]
    devices: BTreeMap<String, String>,
    snapshot: Option<String>,
    #[serde(default)]
    starter: Vec<String>,
    reference: String,
    grader: String,
    /// The device an IL submission is loaded into.
    device: Option<String>,
    #[serde(default)]
    budget: RawBudget,
    #[serde(default)]
    points: BTreeMap<String, f64>,
    /// The submission kinds the lab grades (default: the reference's).
    accepts: Option<Vec<String>>,
    /// Lua modules in the lab folder a submission may `require` (a fresh copy each).
    #[serde(default)]
    shared: Vec<String>,
    /// The language of the lab's messages and verdicts (`en`, `ru`, `zh-CN`), whatever the
    /// grader's locale.
    language: Option<String>,
    /// Bench actions a submission may take ([`crate::confine::BENCH_ACTIONS`]).
    #[serde(default)]
    grants: Vec<String>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct RawBudget {
    sim_time: Option<String>,
    instructions: Option<u64>,
    memory: Option<String>,
    wall: Option<String>,
    submission: Option<String>,
    write: Option<String>,
}

/// One graded run's limits ([`crate::core::budget`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Limits {
    pub sim_time: Duration,
    pub instructions: u64,
    pub memory: usize,
    pub wall: Duration,
    /// The most a submission may be, in bytes (a folder: all its files together).
    pub submission: u64,
    /// The most a submission may leave in its write directory, in bytes.
    pub write: u64,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits {
            sim_time: Duration::from_secs(600),
            instructions: 50_000_000,
            memory: 256 << 20,
            wall: Duration::from_secs(60),
            // A whole class's programs are kilobytes; a megabyte is room for any honest one.
            submission: 1 << 20,
            // A worker per core on a laptop: 8 × 64 MiB at most on its disk at once.
            write: 64 << 20,
        }
    }
}

/// A lab, checked.
#[derive(Clone, Debug)]
pub struct Lab {
    /// The lab folder (absolute).
    pub dir: PathBuf,
    pub title: String,
    pub bench: Option<PathBuf>,
    pub devices: Vec<(String, String)>,
    pub snapshot: Option<PathBuf>,
    pub starter: Vec<PathBuf>,
    pub reference: PathBuf,
    pub grader: PathBuf,
    pub device: String,
    pub limits: Limits,
    pub points: BTreeMap<String, f64>,
    /// The submission kinds graded ([`KINDS`]).
    pub accepts: Vec<String>,
    /// The shared modules: (module name, file, the file's name in the lab folder).
    pub shared: Vec<(String, PathBuf, String)>,
    /// The bench actions a submission may take (`grants` in `lab.toml`).
    pub grants: Vec<String>,
}

/// The submission kinds, as `accepts` names them, and how verdicts name them.
pub const KINDS: &[(&str, &str)] =
    &[("lua", "Lua (.lua)"), ("k2-il", "K2 IL (.il)"), ("umpk-il", "UMPK IL (.il)"), ("fx-il", "FX IL (.il)")];

/// The IL kind of a device URL's family (`sim:` is a K2).
pub fn il_kind(url: &str) -> &'static str {
    let scheme = url.split(':').next().unwrap_or_default().to_ascii_lowercase();
    match scheme.as_str() {
        "sim-umpk" | "umpk" => "umpk-il",
        "sim-fx" | "fx" | "fxlink" => "fx-il",
        _ => "k2-il",
    }
}

/// How a verdict names the kinds in `accepts`: `K2 IL (.il)`, `Lua (.lua) or K2 IL (.il)`.
pub fn describe_kinds(accepts: &[String]) -> String {
    let names: Vec<&str> = accepts.iter().filter_map(|k| KINDS.iter().find(|(n, _)| n == k).map(|(_, d)| *d)).collect();
    names.join(" or ")
}

impl Lab {
    /// The kind of submission `file` is in this lab (`lua`, or the IL of the lab's device).
    pub fn kind_of(&self, file: &Path) -> Option<String> {
        match file.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
            Some("lua") => Some("lua".into()),
            Some("il") => Some(self.il_kind()),
            _ => None,
        }
    }

    /// The IL kind of the device an IL submission is loaded into.
    pub fn il_kind(&self) -> String {
        let url = match &self.bench {
            Some(b) => crate::wiring::bench::Bench::load(b).ok().and_then(|b| b.devices.get(&self.device).cloned()),
            None => self.devices.iter().find(|(n, _)| n == &self.device).map(|(_, u)| u.clone()),
        };
        il_kind(url.as_deref().unwrap_or("sim:")).to_string()
    }
}

fn duration(key: &str, text: &str) -> Result<Duration> {
    let us = crate::core::literal::parse_duration_us(text.trim()).map_err(|e| {
        let msg = msg!("lab-budget-not-time", file = FILE, key = key, text = text);
        match spelled_out(text) {
            Some((n, short, secs)) => Error::usage(msg).hint(if short == "s" {
                msg!("lab-hint-write-time", time = format!("{}{short}", number(n)))
            } else {
                msg!(
                    "lab-hint-write-time-or",
                    time = format!("{}{short}", number(n)),
                    seconds = format!("{}s", number(secs))
                )
            }),
            None => Error::usage(msg!(
                "lab-budget-not-time-why",
                file = FILE,
                key = key,
                text = text,
                error = e.to_string()
            ))
            .hint(msg!("lab-hint-time-example")),
        }
    })?;
    if us <= 0 {
        return Err(Error::usage(msg!("lab-budget-not-positive", file = FILE, key = key, text = text)));
    }
    Ok(Duration::from_micros(us as u64))
}

/// A time written out in words (`10 minutes`, `90 sec`, `2 часа`): the number, the unit as
/// plcsh writes it, and the time in seconds — what the message tells the user to write.
fn spelled_out(text: &str) -> Option<(f64, &'static str, f64)> {
    let t = text.trim();
    let split = t.find(|c: char| !(c.is_ascii_digit() || c == '.' || c == '_'))?;
    let n: f64 = t[..split].replace('_', "").parse().ok()?;
    let word = t[split..].trim().trim_end_matches('.').to_lowercase();
    let (short, factor) = match word.as_str() {
        "h" | "hr" | "hrs" | "hour" | "hours" | "ч" | "час" | "часа" | "часов" => ("h", 3600.0),
        "m" | "min" | "mins" | "minute" | "minutes" | "мин" | "минута" | "минуты" | "минут" => {
            ("min", 60.0)
        }
        "s" | "sec" | "secs" | "second" | "seconds" | "с" | "сек" | "секунда" | "секунды" | "секунд" => {
            ("s", 1.0)
        }
        "ms" | "msec" | "millisecond" | "milliseconds" | "мс" => ("ms", 0.001),
        _ => return None,
    };
    Some((n, short, n * factor))
}

/// A number as a person writes it: `10`, `2.5`.
fn number(x: f64) -> String {
    let s = format!("{x:.3}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

fn bytes(text: &str) -> Result<usize> {
    bytes_of("memory", text)
}

fn bytes_of(key: &str, text: &str) -> Result<usize> {
    let t = text.trim();
    let (num, mult) = [("GiB", 1usize << 30), ("MiB", 1 << 20), ("KiB", 1 << 10), ("B", 1)]
        .iter()
        .find_map(|(u, m)| t.strip_suffix(u).map(|n| (n.trim(), *m)))
        .unwrap_or((t, 1));
    match num.parse::<usize>() {
        Ok(n) if n > 0 => Ok(n.saturating_mul(mult)),
        _ => Err(Error::usage(msg!("lab-budget-not-size", file = FILE, key = key, text = text)).hint(
            match size_in_words(t) {
                Some(w) => msg!("lab-hint-write-size", size = w),
                None => msg!("lab-hint-size-example"),
            },
        )),
    }
}

/// A size written another way (`256 MB`, `1g`, `512 мегабайт`), as plcsh writes it (`256MiB`).
fn size_in_words(t: &str) -> Option<String> {
    let split = t.find(|c: char| !c.is_ascii_digit())?;
    let n: u64 = t[..split].parse().ok().filter(|n| *n > 0)?;
    let unit = match t[split..].trim().to_lowercase().as_str() {
        "k" | "kb" | "kib" | "kbytes" | "kilobyte" | "kilobytes" | "кб" | "килобайт" => "KiB",
        "m" | "mb" | "mib" | "meg" | "megs" | "megabyte" | "megabytes" | "мб" | "мегабайт" | "мегабайта" => {
            "MiB"
        }
        "g" | "gb" | "gib" | "gigabyte" | "gigabytes" | "гб" | "гигабайт" | "гигабайта" => "GiB",
        "b" | "byte" | "bytes" | "байт" => "B",
        _ => return None,
    };
    Some(format!("{n}{unit}"))
}

impl Lab {
    /// Reads `LAB/lab.toml` (`path` may name the folder or the file).
    pub fn load(path: &Path) -> Result<Lab> {
        let file = if path.is_dir() { path.join(FILE) } else { path.to_path_buf() };
        let text = std::fs::read_to_string(&file).map_err(|e| {
            Error::io(msg!("lab-cannot-read-file", file = file.display().to_string()))
                .cause(e)
                .hint(msg!("lab-hint-lab-folder"))
        })?;
        let dir = file.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
        let dir = crate::core::fspath::canonical(dir)
            .map_err(|e| Error::io(msg!("lab-cannot-open", dir = dir.display().to_string())).cause(e))?;
        Lab::parse(&text, &dir)
    }

    /// Parses the text of a `lab.toml` whose folder is `dir`.
    pub fn parse(text: &str, dir: &Path) -> Result<Lab> {
        let raw: Raw =
            toml::from_str(text).map_err(|e| Error::usage(format!("{}: {}", dir.join(FILE).display(), e.message())))?;
        if let Some(tag) = &raw.language {
            let lang = crate::core::msg::Lang::from_tag(tag)
                .ok_or_else(|| Error::usage(format!("{FILE}: {}", crate::msg!("lang-unknown", lang = tag.as_str()))))?;
            crate::core::msg::set_language(lang);
        }
        let file = |key: &str, name: &str| -> Result<PathBuf> {
            let p = dir.join(name);
            let real = crate::core::fspath::canonical(&p).map_err(|e| {
                Error::usage(msg!(
                    "lab-no-such-file",
                    file = FILE,
                    key = key,
                    name = name,
                    dir = dir.display().to_string()
                ))
                .cause(e)
            })?;
            if !real.starts_with(dir) {
                return Err(Error::usage(msg!("lab-file-outside", file = FILE, key = key, name = name))
                    .hint(msg!("lab-hint-files-inside")));
            }
            Ok(real)
        };
        if raw.bench.is_some() != raw.devices.is_empty() {
            return Err(Error::usage(msg!("lab-devices-one-way", file = FILE)).hint(msg!("lab-hint-devices-example")));
        }
        let devices: Vec<(String, String)> = raw.devices.into_iter().collect();
        let rules = crate::confine::Confinement::new(vec![dir.to_path_buf()], None);
        for (name, url) in &devices {
            rules.check_url(url).map_err(|e| Error::usage(format!("{FILE}: [devices] {name}: {}", e.message)))?;
        }
        let b = raw.budget;
        let d = Limits::default();
        let limits = Limits {
            sim_time: b.sim_time.as_deref().map(|t| duration("sim_time", t)).transpose()?.unwrap_or(d.sim_time),
            instructions: match b.instructions {
                Some(0) => return Err(Error::usage(msg!("lab-budget-instructions-zero", file = FILE))),
                Some(n) => n,
                None => d.instructions,
            },
            memory: b.memory.as_deref().map(bytes).transpose()?.unwrap_or(d.memory),
            wall: b.wall.as_deref().map(|t| duration("wall", t)).transpose()?.unwrap_or(d.wall),
            submission: match b.submission.as_deref() {
                Some(t) => bytes_of("submission", t)? as u64,
                None => d.submission,
            },
            write: match b.write.as_deref() {
                Some(t) => bytes_of("write", t)? as u64,
                None => d.write,
            },
        };
        for g in &raw.grants {
            if !crate::confine::BENCH_ACTIONS.iter().any(|(n, _)| n == g) {
                let names: Vec<&str> = crate::confine::BENCH_ACTIONS.iter().map(|(n, _)| *n).collect();
                let near = names.iter().map(|n| (crate::core::text::edit_distance(g, n), *n)).min();
                let hint = match near {
                    Some((d, n)) if d <= 2 => msg!("lab-hint-did-you-mean-grant", near = n, grants = names.join(", ")),
                    _ => msg!("lab-hint-grants", grants = names.join(", ")),
                };
                return Err(Error::usage(msg!("lab-not-a-grant", file = FILE, grant = g.as_str())).hint(hint));
            }
        }
        for (k, v) in &raw.points {
            if !v.is_finite() || *v < 0.0 {
                return Err(Error::usage(msg!(
                    "lab-points-negative",
                    file = FILE,
                    key = k.as_str(),
                    value = v.to_string()
                )));
            }
        }
        let bench = raw.bench.as_deref().map(|b| file("bench", b)).transpose()?;
        if let Some(want) = &raw.device {
            // The device an IL submission is loaded into is one of the lab's.
            let names: Vec<String> = match &bench {
                Some(b) => crate::wiring::bench::Bench::load(b)?.devices.into_keys().collect(),
                None => devices.iter().map(|(n, _)| n.clone()).collect(),
            };
            if !names.contains(want) {
                let near = names.iter().map(|n| (crate::core::text::edit_distance(want, n), n)).min();
                let hint = match near {
                    Some((d, n)) if d <= 2 => {
                        msg!("lab-hint-did-you-mean-device", near = n, devices = names.join(", "))
                    }
                    _ => msg!("lab-hint-devices", devices = names.join(", ")),
                };
                return Err(Error::usage(msg!("lab-not-a-device", file = FILE, device = want.as_str())).hint(hint));
            }
        }
        for k in raw.accepts.iter().flatten() {
            if !KINDS.iter().any(|(n, _)| n == k) {
                let names: Vec<&str> = KINDS.iter().map(|(n, _)| *n).collect();
                return Err(Error::usage(msg!("lab-not-a-kind", file = FILE, kind = k.as_str()))
                    .hint(msg!("lab-hint-kinds", kinds = names.join(", "))));
            }
        }
        let mut shared = Vec::new();
        for name in &raw.shared {
            let real = file("shared", name)?;
            let module = name.strip_suffix(".lua").filter(|m| !m.is_empty()).ok_or_else(|| {
                Error::usage(msg!("lab-shared-not-lua", file = FILE, name = name.as_str()))
                    .hint(msg!("lab-hint-shared-example"))
            })?;
            shared.push((module.replace(['/', '\\'], "."), real, name.clone()));
        }
        let mut lab = Lab {
            dir: dir.to_path_buf(),
            title: raw.title,
            bench,
            devices,
            snapshot: raw.snapshot.as_deref().map(|s| file("snapshot", s)).transpose()?,
            starter: raw.starter.iter().map(|s| file("starter", s)).collect::<Result<_>>()?,
            reference: file("reference", &raw.reference)?,
            grader: file("grader", &raw.grader)?,
            device: raw.device.unwrap_or_else(|| "plc".into()),
            limits,
            points: raw.points,
            accepts: raw.accepts.clone().unwrap_or_default(),
            shared,
            grants: raw.grants.clone(),
        };
        if raw.accepts.is_none() {
            let kind = lab.kind_of(&lab.reference).unwrap_or_else(|| "lua".into());
            lab.accepts = vec![kind];
        }
        Ok(lab)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lab_dir(files: &[(&str, &str)]) -> PathBuf {
        use std::sync::atomic::{AtomicU32, Ordering};
        static N: AtomicU32 = AtomicU32::new(0);
        let d = std::env::temp_dir().join(format!(
            "plcsh-labcfg-{}-{}",
            std::process::id(),
            N.fetch_add(1, Ordering::Relaxed)
        ));
        std::fs::create_dir_all(&d).unwrap();
        for (n, t) in files {
            std::fs::write(d.join(n), t).unwrap();
        }
        crate::core::fspath::canonical(&d).unwrap()
    }

    #[test]
    fn a_lab_parses_with_its_limits() {
        let d = lab_dir(&[("ref.il", ""), ("g.lua", "")]);
        let lab = Lab::parse(
            "title = \"t\"\nreference = \"ref.il\"\ngrader = \"g.lua\"\n[devices]\nplc = \"sim:K205-16DT\"\n[budget]\nsim_time = \"2min\"\nmemory = \"64MiB\"\n[points]\nstarts = 2\n",
            &d,
        )
        .unwrap();
        assert_eq!(lab.limits.sim_time, Duration::from_secs(120));
        assert_eq!(lab.limits.memory, 64 << 20);
        assert_eq!(lab.limits.instructions, 50_000_000);
        assert_eq!(lab.points["starts"], 2.0);
        // By default a lab accepts its reference's kind: here the IL of its K2.
        assert_eq!(lab.accepts, ["k2-il"]);
        assert_eq!(describe_kinds(&lab.accepts), "K2 IL (.il)");
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn accepts_and_shared_modules_are_read() {
        let d = lab_dir(&[("ref.il", ""), ("g.lua", ""), ("helpers.lua", "return {}")]);
        let lab = Lab::parse(
            "title = \"t\"\nreference = \"ref.il\"\ngrader = \"g.lua\"\naccepts = [\"lua\", \"umpk-il\"]\nshared = [\"helpers.lua\"]\ndevice = \"u\"\n[devices]\nu = \"sim-umpk:UMPK16\"\n",
            &d,
        )
        .unwrap();
        assert_eq!(lab.accepts, ["lua", "umpk-il"]);
        assert_eq!(lab.kind_of(Path::new("x.il")).as_deref(), Some("umpk-il"));
        assert_eq!(lab.shared[0].0, "helpers");
        assert_eq!(describe_kinds(&lab.accepts), "Lua (.lua) or UMPK IL (.il)");
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn bad_labs_are_refused_with_the_key() {
        let d = lab_dir(&[("ref.il", ""), ("g.lua", "")]);
        let base = "title = \"t\"\nreference = \"ref.il\"\ngrader = \"g.lua\"\n";
        let cases = [
            (format!("{base}[devices]\nplc = \"tcp://10.0.0.1:502\"\n"), "real device"),
            (base.to_string(), "one of the two"),
            (format!("{base}snapshot = \"../x.json\"\n[devices]\nplc = \"sim:K205-16DT\"\n"), "snapshot"),
            (format!("{base}[devices]\nplc = \"sim:K205-16DT\"\n[budget]\nsim_time = \"soon\"\n"), "sim_time"),
            (format!("{base}[devices]\nplc = \"sim:K205-16DT\"\n[budget]\nmemory = \"lots\"\n"), "memory"),
            (format!("{base}colour = 1\n[devices]\nplc = \"sim:K205-16DT\"\n"), "colour"),
            (format!("{base}accepts = [\"python\"]\n[devices]\nplc = \"sim:K205-16DT\"\n"), "not a submission kind"),
            (
                format!("{base}shared = [\"ref.il\"]\n[devices]\nplc = \"sim:K205-16DT\"\n"),
                "a shared module is a .lua file",
            ),
            (format!("{base}shared = [\"../x.lua\"]\n[devices]\nplc = \"sim:K205-16DT\"\n"), "shared"),
            (
                format!("{base}grants = [\"sim faultz\"]\n[devices]\nplc = \"sim:K205-16DT\"\n"),
                "grants = [\"sim faultz\"]: not an action a lab grants",
            ),
            (format!("{base}[devices]\nplc = \"sim:K205-16DT\"\n[budget]\nwrite = \"lots\"\n"), "write = \"lots\""),
            (
                format!("{base}device = \"plc2\"\n[devices]\nplc = \"sim:K205-16DT\"\n"),
                "device = \"plc2\" is not a device of the lab",
            ),
        ];
        for (text, want) in cases {
            let e = Lab::parse(&text, &d).unwrap_err().to_string();
            assert!(e.contains(want), "{want}: {e}");
        }
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_misnamed_device_gets_the_nearest_name() {
        let d = lab_dir(&[("ref.il", ""), ("g.lua", "")]);
        let text = "title = \"t\"\nreference = \"ref.il\"\ngrader = \"g.lua\"\ndevice = \"plc2\"\n[devices]\nplc = \"sim:K205-16DT\"\nservo = \"sim-servo:?id=1\"\n";
        let e = Lab::parse(text, &d).unwrap_err();
        assert!(e.hint.as_deref().unwrap_or_default().contains("did you mean device = \"plc\"?"), "{e}");
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_time_in_words_is_quoted_with_what_to_write() {
        for (text, want) in [
            ("10 minutes", "write \"10min\" or \"600s\""),
            ("90 seconds", "write \"90s\""),
            ("2 hours", "write \"2h\" or \"7200s\""),
            ("10 минут", "write \"10min\" or \"600s\""),
        ] {
            let e = duration("sim_time", text).unwrap_err();
            assert!(e.message.contains(&format!("sim_time = \"{text}\"")), "{text}: {e}");
            assert!(e.hint.as_deref().unwrap_or_default().contains(want), "{text}: {:?}", e.hint);
            assert!(!e.to_string().contains("mutes"), "{e}");
        }
        for (text, want) in [("256 MB", "write \"256MiB\""), ("1g", "write \"1GiB\""), ("64 мб", "write \"64MiB\"")] {
            let e = bytes(text).unwrap_err();
            assert!(e.message.contains(&format!("memory = \"{text}\"")), "{text}: {e}");
            assert!(e.hint.as_deref().unwrap_or_default().contains(want), "{text}: {:?}", e.hint);
        }
        let e = duration("wall", "soon").unwrap_err();
        assert!(e.message.contains("wall = \"soon\""), "{e}");
        assert_eq!(duration("sim_time", "10min").unwrap(), Duration::from_secs(600));
        assert_eq!(duration("sim_time", "1h30m").unwrap(), Duration::from_secs(5400));
    }
}

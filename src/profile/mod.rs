//! Device profiles: the devices a technician works with, named once in a TOML file in the
//! user's config directory (`~/.config/plcsh/devices.toml` on Linux; `PLCSH_CONFIG` or
//! `--config FILE` override it), so `connect press1` or `--device press1` replaces a URL.
//!
//! ```toml
//! [devices.press1]
//! url = "rtu:/dev/ttyUSB0?baud=115200&unit=3"
//! model = "K209EA-50DX"          # any other key becomes a URL parameter
//! read_only = true               # refuse every write
//! allow = ["VW100..VW120", "M0.0"]   # or: refuse writes outside these operands ("clock": rtc set)
//! [devices.press1.options]        # passed to Device::set_option after opening
//! word_order = "low-first"       # checked against the family when the file is loaded
//! ```
//!
//! Profiles belong to the session layer: the write rules (`read_only`, `allow`) become a
//! [`Guard`] on the open device, and the session checks it before anything reaches the device,
//! for every front end. A bad file is reported with file:line (toml's spans) and never stops
//! the shell: a broken profile is skipped, the others and the defaults still work.
//!
//! The same file names fleets (`[fleets.NAME]`, [`fleet`]): sets of these devices worked on as
//! one; their definitions are read here, the runner that works on them is `crate::fleet`.

pub mod fleet;
pub mod tags;

use crate::core::url::DeviceUrl;
use crate::core::{Error, ErrorKind, Operand, OperandSpace, Result};
use crate::msg;
use serde::Deserialize;
use std::collections::{BTreeMap, HashSet};
use std::fmt;
use std::path::{Path, PathBuf};
use toml::Spanned;

/// One named device profile.
#[derive(Clone, Debug, PartialEq)]
pub struct Profile {
    pub name: String,
    /// The URL with the profile's extra keys appended as parameters.
    pub url: String,
    /// Options for `Device::set_option`, from `[devices.NAME.options]`.
    pub options: Vec<(String, String)>,
    pub read_only: bool,
    /// Write allow-list (operand expressions), when present.
    pub allow: Option<Vec<String>>,
    /// Where the profile is defined (`file:line`).
    pub origin: String,
    /// The device's tag file (`tags = "press1.csv"`, relative to the profile file's folder):
    /// its names work wherever an operand does (`crate::names`).
    pub tags: Option<PathBuf>,
}

/// A problem in the profile file, at a line.
#[derive(Clone, Debug, PartialEq)]
pub struct Problem {
    pub file: String,
    pub line: usize,
    pub message: String,
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.file, self.line, self.message)
    }
}

/// The profiles loaded from one file, and what was wrong in it.
#[derive(Clone, Debug, Default)]
pub struct Profiles {
    list: Vec<Profile>,
    pub problems: Vec<Problem>,
    /// The fleets (`[fleets.NAME]`, [`fleet`]).
    pub fleets: Vec<fleet::Fleet>,
    /// The file they came from (also when it does not exist yet).
    pub file: Option<PathBuf>,
}

/// The profile file's path: `PLCSH_CONFIG`, else the user's config directory.
pub fn default_path() -> Option<PathBuf> {
    crate::paths::config_file()
}

#[derive(Deserialize)]
struct RawFile {
    #[serde(default)]
    devices: BTreeMap<String, Spanned<BTreeMap<String, Spanned<toml::Value>>>>,
    #[serde(default)]
    fleets: BTreeMap<String, Spanned<BTreeMap<String, Spanned<toml::Value>>>>,
}

fn line_of(text: &str, offset: usize) -> usize {
    text[..offset.min(text.len())].bytes().filter(|b| *b == b'\n').count() + 1
}

fn scalar(v: &toml::Value) -> Option<String> {
    match v {
        toml::Value::String(s) => Some(s.clone()),
        toml::Value::Integer(i) => Some(i.to_string()),
        toml::Value::Float(f) => Some(f.to_string()),
        toml::Value::Boolean(b) => Some(b.to_string()),
        _ => None,
    }
}

fn valid_name(n: &str) -> bool {
    !n.is_empty() && n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
}

impl Profiles {
    /// Reads the profile file; a missing file is no profiles and no problem.
    pub fn load(path: &Path) -> Profiles {
        match std::fs::read_to_string(path) {
            Ok(text) => Profiles::parse(&text, path),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                Profiles { file: Some(path.to_path_buf()), ..Default::default() }
            }
            Err(e) => Profiles {
                problems: vec![Problem {
                    file: path.display().to_string(),
                    line: 0,
                    message: msg!("profile-cannot-read", error = e.to_string()).into(),
                }],
                file: Some(path.to_path_buf()),
                ..Default::default()
            },
        }
    }

    /// Parses profile text; `path` is used in messages only.
    pub fn parse(text: &str, path: &Path) -> Profiles {
        let file = path.display().to_string();
        let mut out = Profiles { file: Some(path.to_path_buf()), ..Default::default() };
        let raw: RawFile = match toml::from_str(text) {
            Ok(r) => r,
            Err(e) => {
                let line = e.span().map(|s| line_of(text, s.start)).unwrap_or(0);
                out.problems.push(Problem {
                    file,
                    line,
                    message: msg!("profile-file-not-loaded", error = e.message().trim_end()).into(),
                });
                return out;
            }
        };
        for (name, section) in raw.devices {
            let origin_line = line_of(text, section.span().start);
            let problem = |at: usize, m: String| Problem { file: file.clone(), line: line_of(text, at), message: m };
            match profile(&name, section.get_ref(), &format!("{file}:{origin_line}"), None) {
                Ok(p) => out.list.push(p),
                Err((at, m)) => {
                    let at = at.unwrap_or(section.span().start);
                    out.problems.push(problem(at, msg!("profile-skipped", name = name.as_str(), reason = m).into()));
                }
            }
        }
        for (name, section) in raw.fleets {
            let origin = format!("{file}:{}", line_of(text, section.span().start));
            let make = |member: &str, url: &str| profile(member, section.get_ref(), &origin, Some(url));
            let parsed = if valid_name(&name) {
                fleet::parse(&name, section.get_ref(), &origin, &make)
            } else {
                Err((None, msg!("fleet-name-letters").into()))
            };
            match parsed {
                Ok(f) => out.fleets.push(f),
                Err((at, m)) => out.problems.push(Problem {
                    file: file.clone(),
                    line: line_of(text, at.unwrap_or(section.span().start)),
                    message: msg!("fleet-skipped", name = name.as_str(), reason = m).into(),
                }),
            }
        }
        out
    }

    /// Checks every profile against the device it names, at load (not only at `connect`):
    /// the URL scheme, the model and the allow items. Each profile is checked on its offline
    /// twin — the simulator of its family and model ([`offline_twin`]), so nothing is sent
    /// to a real device at start-up. A profile that fails is skipped with its file:line.
    pub fn validate(&mut self, clock: &crate::core::Clock) {
        let mut kept = Vec::new();
        for p in std::mem::take(&mut self.list) {
            match check(&p, clock) {
                Ok(()) => kept.push(p),
                Err(e) => {
                    let (file, line) = p.origin.rsplit_once(':').unwrap_or((&p.origin, "0"));
                    let what = format!("profile `{}` ({}): ", p.name, p.origin);
                    let mut message = format!(
                        "profile `{}` skipped: {}",
                        p.name,
                        e.message.strip_prefix(&what).unwrap_or(&e.message)
                    );
                    if let Some(h) = &e.hint {
                        message.push_str(&format!(" ({h})"));
                    }
                    self.problems.push(Problem { file: file.to_string(), line: line.parse().unwrap_or(0), message });
                }
            }
        }
        self.list = kept;
        // A URL fleet's members differ only in their address: the first stands for them all.
        let mut fleets = Vec::new();
        for f in std::mem::take(&mut self.fleets) {
            let first = f.members.first().and_then(|m| match &m.source {
                fleet::Source::Made(p) => Some(p),
                fleet::Source::Profile(_) => None,
            });
            match first.map_or(Ok(()), |p| check(p, clock)) {
                Ok(()) => fleets.push(f),
                Err(e) => {
                    let (file, line) = f.origin.rsplit_once(':').unwrap_or((&f.origin, "0"));
                    let mut message = format!("fleet `{}` skipped: {}", f.name, e.message);
                    if let Some(h) = &e.hint {
                        message.push_str(&format!(" ({h})"));
                    }
                    self.problems.push(Problem { file: file.to_string(), line: line.parse().unwrap_or(0), message });
                }
            }
        }
        self.fleets = fleets;
        self.problems.sort_by_key(|p| p.line);
    }

    pub fn list(&self) -> &[Profile] {
        &self.list
    }

    pub fn get(&self, name: &str) -> Option<&Profile> {
        self.list.iter().find(|p| p.name == name)
    }

    /// The fleet named `name`, or an error naming the fleets there are.
    pub fn fleet(&self, name: &str) -> Result<&fleet::Fleet> {
        self.fleets.iter().find(|f| f.name == name).ok_or_else(|| fleet::unknown(self, name))
    }

    /// "no profile named x" with the known names and the file, for errors.
    pub fn unknown(&self, name: &str) -> Error {
        let names: Vec<&str> = self.list.iter().map(|p| p.name.as_str()).collect();
        let file = self.file.as_ref().map(|f| f.display().to_string()).unwrap_or_else(|| "devices.toml".into());
        Error::usage(msg!("profile-unknown", name = name)).hint(if names.is_empty() {
            msg!("profile-unknown-define-hint", section = format!("[devices.{name}]"), file = file)
        } else {
            msg!("profile-unknown-list-hint", file = file, list = names.join(", "))
        })
    }
}

type Bad = (Option<usize>, String);

/// One profile from its keys; `url` (a fleet member's expanded address) replaces the `url` key.
fn profile(
    name: &str,
    keys: &BTreeMap<String, Spanned<toml::Value>>,
    origin: &str,
    url: Option<&str>,
) -> std::result::Result<Profile, Bad> {
    if !valid_name(name) {
        return Err((None, msg!("profile-name-letters").into()));
    }
    let at = |v: &Spanned<toml::Value>| Some(v.span().start);
    let url = match (url, keys.get("url")) {
        (Some(u), _) => u.to_string(),
        (None, Some(v)) => match v.get_ref() {
            toml::Value::String(s) => s.clone(),
            _ => return Err((at(v), msg!("profile-url-not-string").into())),
        },
        (None, None) => {
            return Err((None, msg!("profile-url-missing", example = "url = \"tcp://192.168.1.10:502?unit=1\"").into()))
        }
    };
    let parsed = DeviceUrl::parse(&url).map_err(|e| (keys.get("url").and_then(at), e.message.clone()))?;
    let mut p = Profile {
        name: name.to_string(),
        url: url.clone(),
        options: Vec::new(),
        read_only: false,
        allow: None,
        origin: origin.to_string(),
        tags: None,
    };
    let mut extra = Vec::new();
    for (k, v) in keys {
        match k.as_str() {
            "url" | "devices" => {}
            "read_only" => match v.get_ref() {
                toml::Value::Boolean(b) => p.read_only = *b,
                _ => return Err((at(v), msg!("profile-read-only-bool").into())),
            },
            "allow" => {
                let items = match v.get_ref() {
                    toml::Value::Array(a) => {
                        a.iter().map(|i| i.as_str().map(str::to_string)).collect::<Option<Vec<_>>>()
                    }
                    _ => None,
                };
                match items {
                    Some(items) => p.allow = Some(items),
                    None => {
                        return Err((
                            at(v),
                            msg!("profile-allow-list", example = "[\"VW100..VW120\", \"M0.0\"]").into(),
                        ))
                    }
                }
            }
            "tags" => match v.get_ref() {
                toml::Value::String(f) => {
                    // Relative to the folder of the file that names it, as a person reads it there.
                    let file = origin.rsplit_once(':').map_or(origin, |(f, _)| f);
                    let dir = Path::new(file).parent().unwrap_or(Path::new(""));
                    p.tags = Some(dir.join(f));
                }
                _ => return Err((at(v), crate::msg!("names-profile-tags-not-text").into())),
            },
            "options" => match v.get_ref() {
                toml::Value::Table(t) => {
                    for (ok, ov) in t {
                        let s = scalar(ov)
                            .ok_or_else(|| (at(v), msg!("profile-option-scalar", key = ok.as_str()).into()))?;
                        p.options.push((ok.clone(), s));
                    }
                }
                _ => return Err((at(v), msg!("profile-options-table").into())),
            },
            _ => {
                let s =
                    scalar(v.get_ref()).ok_or_else(|| (at(v), msg!("profile-key-scalar", key = k.as_str()).into()))?;
                if parsed.param(k).is_none() {
                    extra.push(format!("{k}={s}"));
                }
            }
        }
    }
    if !extra.is_empty() {
        let sep = if url.contains('?') { '&' } else { '?' };
        p.url = format!("{url}{sep}{}", extra.join("&"));
    }
    Ok(p)
}

/// The simulator that stands for a profile's device when it is checked at load: the same
/// family and model, without touching the wire. `None` for a scheme no family knows. A new
/// family adds its schemes here beside its line in `schemes::open_url`.
pub fn offline_twin(u: &DeviceUrl) -> Option<String> {
    let k2_model = || u.param("model").unwrap_or(crate::k2::catalog::DEFAULT_MODEL).to_string();
    match u.base_scheme() {
        "sim" => Some(format!("sim:{}", u.param("model").unwrap_or(&u.target))),
        "tcp" | "rtu" => Some(format!("sim:{}", k2_model())),
        "kinco" | "sim-servo" => Some("sim-servo:?id=1".to_string()),
        "fx" | "fxlink" => Some(format!("sim-fx:{}", u.param("model").unwrap_or("FX2N"))),
        "sim-fx" => {
            Some(format!("sim-fx:{}", u.param("model").unwrap_or(if u.target.is_empty() { "FX2N" } else { &u.target })))
        }
        "umpk" => Some(u.param("model").map_or("sim-umpk:".to_string(), |m| format!("sim-umpk:?model={m}"))),
        "sim-umpk" => Some(match u.param("model") {
            Some(m) => format!("sim-umpk:?model={m}"),
            None => format!("sim-umpk:{}", u.target),
        }),
        _ => None,
    }
}

/// The URL parameters the family of `u` takes (the lists its `open` functions check), so a
/// misspelt key in a profile is found at load. Beside [`offline_twin`] for the same reason.
pub fn url_params(u: &DeviceUrl) -> Option<Vec<&'static str>> {
    use crate::{fx::driver as fx, k2::driver as k2, servo::driver as servo, umpk::driver as umpk};
    // `control=PATH` (a served simulator's control channel) goes to the session.
    let wire = |lists: &[&[&'static str]]| lists.iter().flat_map(|l| l.iter().copied()).chain(["control"]).collect();
    Some(match (u.base_scheme(), u.scheme.as_str()) {
        ("sim", _) => crate::schemes::K2_SIM_PARAMS.to_vec(),
        (_, "rtu" | "rtu+rfc2217") => wire(&[k2::PARAMS, k2::LINE_PARAMS]),
        ("tcp" | "rtu", _) => wire(&[k2::PARAMS]),
        ("kinco", _) => servo::SERIAL_PARAMS.to_vec(),
        ("sim-servo", _) => servo::SIM_PARAMS.to_vec(),
        ("fx", _) => wire(&[fx::PORT_PARAMS]),
        ("fxlink", _) => wire(&[fx::LINK_PARAMS]),
        ("sim-fx", _) => fx::SIM_PARAMS.to_vec(),
        ("umpk", _) => wire(&[umpk::SERIAL_PARAMS]),
        ("sim-umpk", _) => umpk::SIM_PARAMS.to_vec(),
        _ => return None,
    })
}

/// One profile against its offline twin: scheme, URL parameters, model, options, allow items.
fn check(p: &Profile, clock: &crate::core::Clock) -> Result<()> {
    let u = DeviceUrl::parse(&p.url)?;
    let Some(twin) = offline_twin(&u) else {
        return Err(Error::usage(msg!("profile-unknown-scheme", scheme = u.scheme.as_str(), url = p.url.as_str())).hint(
            msg!(
                "profile-known-schemes-hint",
                list = "sim:MODEL, tcp://HOST:PORT, rtu:/dev/PORT, rtu+tcp://HOST:PORT, kinco:/dev/PORT, sim-servo:, fx:/dev/PORT, fxlink:/dev/PORT, sim-fx:FX2N, umpk:/dev/PORT, sim-umpk:UMPK16"
            ),
        ));
    };
    if let Some(known) = url_params(&u) {
        u.expect_params(&known)?;
    }
    let mut device = crate::schemes::open_url(&twin, clock)?;
    for (k, v) in &p.options {
        check_option(&u, device.as_mut(), k, v).map_err(|mut e| {
            e.message = format!("[options] {k} = \"{v}\": {}", e.message);
            e
        })?;
    }
    Guard::build(p, device.operands())?;
    Ok(())
}

/// One `[options]` entry against the family that will receive it. The twin is the same
/// driver as the real device for every family but the K2, whose wire driver has options of
/// its own (checked without a connection); a simulator's file options (`state`, `program`)
/// are left for `connect`, so loading the file touches no other file.
fn check_option(u: &DeviceUrl, twin: &mut dyn crate::core::Device, key: &str, value: &str) -> Result<()> {
    match (u.base_scheme(), key) {
        ("tcp" | "rtu", _) => crate::k2::driver::check_option(key, value),
        ("sim", "state" | "program") => Ok(()),
        _ => twin.set_option(key, value),
    }
}

/// The write rules of a profile, bound to an open device's operand space.
#[derive(Clone, Debug)]
pub struct Guard {
    profile: String,
    origin: String,
    read_only: bool,
    /// Allowed operand names (views stripped: `VW0/INT` is `VW0`) and the list as written.
    allow: Option<(HashSet<String>, Vec<String>)>,
}

/// An operand's name without a type view (`VD100/REAL` → `VD100`): views share the bytes.
fn bare(name: &str) -> &str {
    name.split('/').next().unwrap_or(name)
}

impl Guard {
    /// The guard for `p` on a device with operand space `space`; `None` when the profile has
    /// no write rules. An allow item that is not an operand of the device is an error.
    pub fn build(p: &Profile, space: &dyn OperandSpace) -> Result<Option<Guard>> {
        if !p.read_only && p.allow.is_none() {
            return Ok(None);
        }
        let allow = match &p.allow {
            None => None,
            Some(items) => {
                let mut set = HashSet::new();
                for item in items {
                    // `clock`: the real-time clock (`rtc set|sync`), which is no operand.
                    if item.trim() == crate::core::device::CLOCK {
                        set.insert(crate::core::device::CLOCK.to_string());
                        continue;
                    }
                    let ops = space.parse(item).map_err(|e| {
                        Error::usage(msg!(
                            "profile-allow-item",
                            name = p.name.as_str(),
                            origin = p.origin.as_str(),
                            item = item.as_str(),
                            reason = e.message.as_str()
                        ))
                        .hint(msg!("profile-allow-item-hint"))
                    })?;
                    set.extend(ops.iter().map(|o| bare(&space.name(o)).to_string()));
                }
                Some((set, items.clone()))
            }
        };
        Ok(Some(Guard { profile: p.name.clone(), origin: p.origin.clone(), read_only: p.read_only, allow }))
    }

    /// Refuses a write the profile does not allow, naming the profile and the rule.
    pub fn check(&self, space: &dyn OperandSpace, op: &Operand) -> Result<()> {
        self.check_name(&space.name(op), None)
    }

    /// Refuses a change of the operand named `name` (a canonical name such as `VW100`,
    /// `Q0.0`, `controlword`, or `clock`) that the profile does not allow; `what` names
    /// the instruction or action when the change is not a plain write (`PLS 0`).
    pub fn check_name(&self, name: &str, what: Option<&str>) -> Result<()> {
        // `what` is `none` for a plain write (the messages' selector).
        let what = what.unwrap_or("none");
        if self.read_only {
            // A refusal by the write rules, as docs/json.md lists it: kind `refused`.
            return Err(Error::new(
                ErrorKind::Refused,
                msg!(
                    "profile-read-only-refused",
                    what = what,
                    name = name,
                    profile = self.profile.as_str(),
                    origin = self.origin.as_str()
                ),
            )
            .operand(name.to_string())
            .hint(msg!("profile-read-only-refused-hint")));
        }
        if let Some((set, items)) = &self.allow {
            if !set.contains(bare(name)) {
                return Err(Error::new(
                    ErrorKind::Refused,
                    msg!(
                        "profile-allow-refused",
                        what = what,
                        name = name,
                        profile = self.profile.as_str(),
                        list = items.join(", "),
                        origin = self.origin.as_str()
                    ),
                )
                .operand(name.to_string())
                .hint(msg!("profile-allow-refused-hint")));
            }
        }
        Ok(())
    }

    /// True for a profile with `read_only = true`.
    pub fn read_only(&self) -> bool {
        self.read_only
    }

    /// True when the profile lists the operands that may be written (`allow`).
    pub fn has_allow(&self) -> bool {
        self.allow.is_some()
    }

    /// A short description for `devices` (`read only`, `allow VW100..VW120, M0.0`).
    pub fn summary(&self) -> String {
        match (&self.allow, self.read_only) {
            (_, true) => msg!("profile-summary-read-only").into(),
            (Some((_, items)), false) => msg!("profile-summary-allow", list = items.join(", ")).into(),

            (None, false) => String::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::k2::{catalog, space::K2Space};

    fn parse(text: &str) -> Profiles {
        Profiles::parse(text, Path::new("/home/u/.config/plcsh/devices.toml"))
    }

    const GOOD: &str = r#"
[devices.press1]
url = "rtu:/dev/ttyUSB0?baud=115200&unit=3"
model = "K209EA-50DX"
allow = ["VW100..VW104", "M0.0"]

[devices.axis1]
url = "kinco:/dev/ttyUSB1?id=1"
encoder = 65536
read_only = true
[devices.axis1.options]
word_order = "low-first"
"#;

    #[test]
    fn profiles_with_extra_keys_rules_and_options() {
        let p = parse(GOOD);
        assert!(p.problems.is_empty(), "{:?}", p.problems);
        let press = p.get("press1").unwrap();
        assert_eq!(press.url, "rtu:/dev/ttyUSB0?baud=115200&unit=3&model=K209EA-50DX");
        assert_eq!(press.allow.as_deref(), Some(&["VW100..VW104".to_string(), "M0.0".to_string()][..]));
        assert!(!press.read_only);
        assert_eq!(press.origin, "/home/u/.config/plcsh/devices.toml:2");
        let axis = p.get("axis1").unwrap();
        assert_eq!(axis.url, "kinco:/dev/ttyUSB1?id=1&encoder=65536");
        assert!(axis.read_only);
        assert_eq!(axis.options, vec![("word_order".to_string(), "low-first".to_string())]);
        let names: Vec<&str> = p.list().iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, vec!["axis1", "press1"]);
    }

    #[test]
    fn a_url_parameter_wins_over_the_same_extra_key() {
        let p = parse("[devices.a]\nurl = \"sim:K205-16DT?model=K209M-56DT\"\nmodel = \"K205-16DT\"\n");
        assert_eq!(p.get("a").unwrap().url, "sim:K205-16DT?model=K209M-56DT");
    }

    #[test]
    fn a_syntax_error_is_reported_with_its_line_and_loads_nothing() {
        let p = parse("[devices.a]\nurl = \"sim:\"\n\n[devices.b]\nurl = sim:K205\n");
        assert!(p.list().is_empty());
        assert_eq!(p.problems.len(), 1);
        let shown = p.problems[0].to_string();
        assert!(shown.starts_with("/home/u/.config/plcsh/devices.toml:5: "), "{shown}");
    }

    #[test]
    fn a_bad_profile_is_skipped_with_its_line_and_the_others_load() {
        let text = "[devices.ok]\nurl = \"sim:K205-16DT\"\n\n[devices.nourl]\nmodel = \"x\"\n\n[devices.badro]\nurl = \"sim:\"\nread_only = \"yes\"\n\n[devices.badallow]\nurl = \"sim:\"\nallow = \"VW0\"\n\n[devices.\"bad name\"]\nurl = \"sim:\"\n";
        let p = parse(text);
        let names: Vec<&str> = p.list().iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, vec!["ok"]);
        let lines: Vec<(usize, bool)> = p.problems.iter().map(|pr| (pr.line, pr.message.contains("skipped"))).collect();
        // BTreeMap order: "bad name", badallow, badro, nourl.
        assert_eq!(lines, vec![(15, true), (13, true), (9, true), (4, true)], "{:?}", p.problems);
        assert!(p.problems[3].message.contains("`url` is missing"));
        assert!(p.problems[2].message.contains("read_only"));
    }

    /// Every scheme the session opens has its parameter list and an offline twin here.
    #[test]
    fn every_scheme_has_its_parameters_and_a_twin() {
        for (scheme, ..) in crate::schemes::SCHEMES {
            let u = DeviceUrl::parse(&format!("{scheme}x")).unwrap();
            assert!(url_params(&u).is_some() && offline_twin(&u).is_some(), "{scheme}");
        }
    }

    #[test]
    fn missing_file_is_no_profiles_and_no_problem() {
        let p = Profiles::load(Path::new("/nonexistent/plcsh/devices.toml"));
        assert!(p.list().is_empty() && p.problems.is_empty());
        assert!(p.unknown("press1").hint.clone().unwrap().contains("[devices.press1]"));
    }

    #[test]
    fn guard_enforces_read_only_and_the_allow_list() {
        let space = K2Space::new(catalog::find("K205-16DT").unwrap());
        let p = parse(GOOD);
        let g = Guard::build(p.get("press1").unwrap(), &space).unwrap().unwrap();
        let op = |t: &str| space.parse(t).unwrap()[0];
        assert!(g.check(&space, &op("VW102")).is_ok());
        assert!(g.check(&space, &op("VW102/INT")).is_ok(), "a view of an allowed operand");
        assert!(g.check(&space, &op("M0.0")).is_ok());
        let e = g.check(&space, &op("VW106")).unwrap_err();
        assert!(e.message.contains("press1") && e.message.contains("allow list"), "{}", e.message);
        assert_eq!(e.operand.as_deref(), Some("VW106"));
        assert_eq!(e.kind, ErrorKind::Refused, "a refusal, as docs/json.md lists it");
        assert!(g.check(&space, &op("VB100")).is_err(), "a different size is not listed");
        let mut ro = p.get("axis1").unwrap().clone();
        ro.url = "sim:".into();
        let g = Guard::build(&ro, &space).unwrap().unwrap();
        let e = g.check(&space, &op("VW0")).unwrap_err();
        assert!(e.message.contains("read_only") && e.kind == ErrorKind::Refused, "{e}");
        let mut bad = p.get("press1").unwrap().clone();
        bad.allow = Some(vec!["VX1".into()]);
        assert!(Guard::build(&bad, &space).unwrap_err().message.contains("allow item `VX1`"));
        let mut none = bad.clone();
        none.allow = None;
        assert!(Guard::build(&none, &space).unwrap().is_none());
    }
}

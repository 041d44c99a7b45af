//! The session: the open devices and their names, the shared virtual clock, and the
//! interrupt flag. It is the one API the REPL, Lua and one-shot commands call; front ends
//! never touch transports or simulators directly.
//!
//! Device URLs are opened through one list, [`crate::schemes::open_url`]: a new family adds
//! its schemes there.

pub use crate::schemes::{open_url, url_family, K2_SIM_PARAMS, SCHEMES};

use crate::core::url::DeviceUrl;
use crate::core::{Clock, Device, Error, Operand, Result, Value};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// One value read or written, as reported to users and scripts (rendered by [`crate::output`]).
pub use crate::output::Reading;

/// An open device with its name.
pub struct Entry {
    pub name: String,
    pub url: String,
    pub device: Box<dyn Device>,
    /// Write rules from the device's profile (`read_only`, `allow`), for `devices`; the
    /// device itself sits in a [`crate::guard::Guarded`] that enforces them.
    pub guard: Option<crate::profile::Guard>,
    /// A served simulator's control channel (`control=PATH` in the URL), where `sim fault …`
    /// and the other simulator controls go ([`crate::core::link::control`]).
    pub control: Option<std::path::PathBuf>,
    /// The device's tag names ([`crate::names`]), resolved on its operand grammar; empty
    /// when it has no tag file.
    pub names: Arc<crate::names::Names>,
    /// A tag file not resolved yet (the device was not connected when it was given): resolved
    /// when the device is made ready.
    pub tags: Option<Arc<crate::tags::TagTable>>,
}

/// How `set` items arrive: operand text and value text, with their columns in the line.
#[derive(Clone, Debug)]
pub struct SetItem {
    pub operand: String,
    pub value: String,
    pub column: usize,
    pub value_column: usize,
}

/// A resolved operand: which device, which operands.
#[derive(Clone, Debug)]
pub struct Target {
    pub device: usize,
    pub ops: Vec<Operand>,
}

pub struct Session {
    devices: Vec<Entry>,
    current: usize,
    pub clock: Clock,
    pub interrupt: Arc<AtomicBool>,
    /// Device profiles (`connect press1`), from the profile file.
    pub profiles: crate::profile::Profiles,
    /// The session-wide read-only switch (`--read-only`), shared by every device's guard.
    read_only: Arc<AtomicBool>,
    /// A sandboxed run's rules ([`crate::confine`]): checked here, where devices are opened.
    pub confine: Option<Arc<crate::confine::Confinement>>,
    /// A graded run's limits ([`crate::core::budget`]): waits stop at its simulated-time limit.
    pub budget: Option<Arc<crate::core::budget::Budget>>,
    /// The log of every write made to a device while a report is recorded
    /// ([`crate::guard::WriteLog`]); every device's guard writes to it.
    pub write_log: Arc<crate::guard::WriteLog>,
}

/// The `control=PATH` of a wire URL: a served simulator's control channel. The drive line
/// (`kinco:`) takes it itself; for the other families the session keeps it.
fn control_param(url: &str) -> Option<std::path::PathBuf> {
    let u = DeviceUrl::parse(url).ok()?;
    matches!(u.base_scheme(), "tcp" | "rtu" | "fx" | "fxlink" | "umpk").then(|| u.param("control").map(Into::into))?
}

impl Session {
    /// An empty session with the given clock.
    pub fn new(clock: Clock) -> Session {
        let clock_for_log = clock.clone();
        Session {
            devices: Vec::new(),
            current: 0,
            clock,
            interrupt: Arc::new(AtomicBool::new(false)),
            profiles: Default::default(),
            read_only: Arc::new(AtomicBool::new(false)),
            confine: None,
            budget: None,
            write_log: Arc::new(crate::guard::WriteLog::new(clock_for_log)),
        }
    }

    /// True when a device on a wire (not a simulator) is open: its time is the machine's.
    pub fn has_wire_device(&self) -> bool {
        self.devices.iter().any(|e| !e.device.info().simulated)
    }

    /// Waits `d` for a script or command. In stepped time with only simulators open, the
    /// virtual clock jumps; with a device on a wire open, the wait is real (a timeout on a
    /// real machine must not expire in no time) and the virtual clock then moves by the same
    /// amount, so simulators stay in step. False when interrupted (Ctrl-C).
    pub fn sleep(&self, d: std::time::Duration) -> bool {
        // A graded run's wait ends at its simulated-time limit (and the run with it).
        let d = match &self.budget {
            Some(b) => match b.cap_wait(&self.clock, d) {
                Some(d) => d,
                None => {
                    self.interrupt.store(true, Ordering::Relaxed);
                    return false;
                }
            },
            None => d,
        };
        if self.clock.is_stepped() && self.has_wire_device() {
            let ok = Clock::sleep_real(d, &self.interrupt);
            self.clock.step(d);
            return ok;
        }
        self.clock.sleep(d, &self.interrupt)
    }

    /// A jump of the stepped clock by `d` (`sim step`, `wait`) within a graded run's
    /// simulated-time limit: past it, the clock stops at the limit and the run ends.
    pub fn budget_step(&self, d: std::time::Duration) -> Result<std::time::Duration> {
        let Some(b) = &self.budget else { return Ok(d) };
        match b.cap_wait(&self.clock, d) {
            Some(d) => Ok(d),
            None => {
                self.interrupt.store(true, Ordering::Relaxed);
                Err(Error::new(crate::core::ErrorKind::Interrupted, b.exceeded().unwrap_or_default()))
            }
        }
    }

    /// Refuses reading `path` when a sandbox's rules forbid it (commands that load files).
    pub fn check_read(&self, path: &str) -> Result<()> {
        self.confine.as_ref().map_or(Ok(()), |c| c.check_read(path))
    }

    /// The file of snapshot `name` ([`crate::paths::snapshot_file`]), under a sandbox's rules when
    /// there are some: a path under its folders, never a named snapshot in the data directory.
    pub fn snapshot_file(&self, name: &str, save: bool) -> Result<std::path::PathBuf> {
        match &self.confine {
            Some(c) => c.snapshot_file(name, save),
            None => crate::paths::snapshot_file(name),
        }
    }

    /// Turns the session-wide read-only switch on or off: every device refuses every
    /// change (writes, instructions, servo commands) while it is on.
    pub fn set_read_only(&self, on: bool) {
        self.read_only.store(on, Ordering::Relaxed);
    }

    /// Refuses bench action `what` in a graded submission ([`crate::confine::Confinement::check_bench`]).
    pub fn check_bench(&self, what: &str) -> Result<()> {
        self.confine.as_ref().map_or(Ok(()), |c| c.check_bench(what))
    }

    pub fn read_only(&self) -> bool {
        self.read_only.load(Ordering::Relaxed)
    }

    /// Opens `url` under `name` (replacing a device of that name) and makes it current if
    /// it is the first. A `url` without a scheme is a profile name (`crate::profile`).
    pub fn open(&mut self, name: &str, url: &str) -> Result<()> {
        if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-') {
            // ASCII only: a device name is typed before operands (`press1:VW0`), where Cyrillic
            // look-alikes are read as the Latin letters the manual means (core::text).
            return Err(Error::usage(crate::msg!("session-bad-device-name", name = name))
                .hint(crate::msg!("session-hint-device-name")));
        }
        if let Some(c) = &self.confine {
            // A profile brings the user's options (state files, …): a sandboxed run opens
            // devices by URL only, and only simulators.
            if !url.contains(':') {
                let real = self.profiles.get(url).is_some_and(|p| c.check_url(&p.url).is_err());
                return Err(crate::core::Error::unsupported(if real {
                    crate::msg!("session-sandbox-real-profile", url = url)
                } else {
                    crate::msg!("session-sandbox-not-url", url = url)
                })
                .hint("e.g. plcsh.connect(\"sim:K205-16DT\")")
                .device(name));
            }
            c.check_url(url).map_err(|e| e.device(name))?;
            c.check_bench("connect").map_err(|e| e.device(name))?;
        }
        if !url.contains(':') {
            return self.open_profile_named(name, url);
        }
        crate::core::trace::name_device(url, name);
        let device = open_url(url, &self.clock).map_err(|e| e.device(name))?;
        self.add(name, url, device);
        Ok(())
    }

    /// Opens `url` under `name` as [`open`](Self::open) does, with `key=value` set at the
    /// device's first use instead of now (`crate::pending`): the simulated PLC's state file,
    /// so a plcsh that never uses that PLC never takes its state file.
    pub fn open_with_option_on_first_use(&mut self, name: &str, url: &str, key: &str, value: &str) -> Result<()> {
        self.open(name, url)?;
        let i = self.index(name)?;
        let mut e = self.devices.remove(i);
        e.device = Box::new(crate::pending::Pending::option_on_first_use(e.device, key, value));
        self.devices.insert(i, e);
        Ok(())
    }

    /// Opens `url` under `name`; when its link cannot be made now (a PLC not powered yet, an
    /// adapter not plugged in), the device still joins the session, not connected, and every
    /// later command tries again (`crate::pending`). Returns that link error, for a note.
    /// Anything else (a bad URL, a profile's error) fails as [`open`](Self::open) does.
    pub fn open_or_later(&mut self, name: &str, url: &str) -> Result<Option<Error>> {
        let e = match self.open(name, url) {
            Ok(()) => return Ok(None),
            Err(e) if e.kind == crate::core::ErrorKind::Link && url.contains(':') => e,
            Err(e) => return Err(e),
        };
        let (u, clock, read_only) = (url.to_string(), self.clock.clone(), self.read_only.clone());
        let (log, logged_as) = (self.write_log.clone(), name.to_string());
        let open: crate::pending::Opener = Box::new(move || {
            let device = open_url(&u, &clock)?;
            let guarded = crate::guard::Guarded::new(device, None, read_only.clone()).logging(log.clone(), &logged_as);
            Ok(Box::new(guarded) as Box<dyn Device>)
        });
        let device = Box::new(crate::pending::Pending::unopened(url, open, e.clone()));
        let entry = Entry {
            name: name.to_string(),
            url: url.to_string(),
            device,
            guard: None,
            control: control_param(url),
            names: crate::names::none(),
            tags: None,
        };
        match self.devices.iter().position(|d| d.name == name) {
            Some(i) => self.devices[i] = entry,
            None => self.devices.push(entry),
        }
        Ok(Some(e))
    }

    /// The write log as it stands: every device's guard first reads back the values of its
    /// last family operation ([`crate::guard::WriteLog`]; an empty read reaches its guard, and
    /// only devices with such an operation are asked, so no deferred device is made ready).
    pub fn write_log_entries(&mut self) -> (Vec<crate::guard::Written>, u64) {
        let waiting = self.write_log.waiting();
        for e in self.devices.iter_mut().filter(|e| waiting.contains(&e.name)) {
            let _ = e.device.read(&[]);
        }
        self.write_log.entries()
    }

    /// Makes device `i` ready for a command ([`Device::ready`]): the reason it is not (its
    /// state file held by another plcsh, its link still down) comes back named by device.
    pub fn ready(&mut self, i: usize) -> Result<()> {
        let e = &mut self.devices[i];
        e.device.ready().map_err(|err| err.device(&e.name))?;
        if let Some(tags) = e.tags.clone() {
            // A tag file given before the device was connected: resolved now, and reported on
            // every command until it resolves (a name must not mean nothing silently).
            let table = crate::tags::TagTable::clone(&tags);
            e.names =
                Arc::new(crate::names::Names::resolve(table, e.device.operands()).map_err(|err| err.device(&e.name))?);
            e.tags = None;
        }
        Ok(())
    }

    /// Gives device `i` the tags of `tags` (`tags = "…"` in a profile, `--tags`,
    /// `plc:tags_load`): resolved on its operand grammar now, or when it is connected if it
    /// is not yet. Returns how many names the device has.
    pub fn attach_tags(&mut self, i: usize, tags: crate::tags::TagTable) -> Result<usize> {
        let e = &mut self.devices[i];
        let waiting = tags.iter().next().is_some_and(|t| {
            e.device.operands().parse(&t.address).is_err_and(|x| x.kind == crate::core::ErrorKind::Link)
        });
        if waiting {
            let n = tags.len();
            e.tags = Some(Arc::new(tags));
            return Ok(n);
        }
        let names = crate::names::Names::resolve(tags, e.device.operands()).map_err(|err| err.device(&e.name))?;
        let n = names.len();
        e.names = Arc::new(names);
        e.tags = None;
        Ok(n)
    }

    /// Loads tag file `path` ([`crate::names::load`]) for device `i`, under a sandbox's rules.
    pub fn load_tags(&mut self, i: usize, path: &std::path::Path) -> Result<usize> {
        self.check_read(&path.to_string_lossy())?;
        let tags = crate::names::load(path).map_err(|e| e.device(&self.devices[i].name))?;
        self.attach_tags(i, tags)
    }

    /// The names of device `i`.
    pub fn names(&self, i: usize) -> &crate::names::Names {
        &self.devices[i].names
    }

    /// The tag that is exactly operand `op` of device `i`, if it has one.
    pub fn tag_of(&self, i: usize, op: &Operand) -> Option<&crate::names::Named> {
        self.devices[i].names.of(op)
    }

    /// How an operand is labelled in series (trace, plot, watch, recordings): its tag's name
    /// when it has one, else its canonical text.
    pub fn label_of(&self, i: usize, op: &Operand) -> String {
        match self.tag_of(i, op) {
            Some(n) => n.name.clone(),
            None => self.name_of(i, op),
        }
    }

    /// Parses an operand expression (a name, a range or count form from names, or an
    /// operand) on device `i`'s grammar: the one place names become operands. Errors carry
    /// a column within `body`; an unknown word gets the nearest names beside the grammar's
    /// own suggestions.
    pub fn parse_on(&self, i: usize, body: &str) -> Result<Vec<Operand>> {
        let e = &self.devices[i];
        let space = e.device.operands();
        match e.names.expand(body) {
            Some(crate::names::Expanded::One(op)) => return Ok(vec![op]),
            Some(crate::names::Expanded::Text(t)) => {
                let lead = body.len() - body.trim_start().len();
                return space.parse(&t).map_err(|err| {
                    let mut err = err;
                    err.column = Some(lead);
                    err
                });
            }
            None => {}
        }
        space.parse(body).map_err(|err| {
            let near = e.names.near(body);
            if near.is_empty() {
                return err;
            }
            // A word nearer a name than an operand: said as an unknown name, the grammar's own
            // reading kept as the cause.
            let word = body.trim();
            let list: Vec<String> = near.iter().map(|n| format!("{} ({})", n.name, n.operand)).collect();
            let mut hint: String = crate::msg!("names-hint-did-you-mean", names = list.join(", ")).into();
            if let Some(h) = &err.hint {
                hint = format!("{hint}; {h}");
            }
            let msg = crate::msg!("names-unknown", word = word, file = e.names.file.as_str());
            Error::new(crate::core::ErrorKind::Operand, msg)
                .cause(&err.message)
                .hint(hint)
                .column(body.len() - body.trim_start().len())
        })
    }

    /// Makes ready the device each operand expression names (`press:VW0`, else the current one).
    fn ready_for(&mut self, texts: &[&str]) -> Result<()> {
        let mut done: Vec<usize> = Vec::new();
        for t in texts {
            let t = t.trim();
            let i = match t.find(':').map(|c| self.index(&t[..c])) {
                Some(Ok(i)) => i,
                Some(Err(_)) => continue, // resolve names the unknown device
                None => match self.current_index() {
                    Ok(i) => i,
                    Err(_) => continue,
                },
            };
            if !done.contains(&i) {
                self.ready(i)?;
                done.push(i);
            }
        }
        Ok(())
    }

    /// Opens profile `profile` under device name `name`: its URL, then its options, then its
    /// write rules as the entry's [`crate::profile::Guard`]. Called by [`Self::open`] for a URL
    /// without a scheme.
    fn open_profile_named(&mut self, name: &str, profile: &str) -> Result<()> {
        let p = self.profiles.get(profile).cloned().ok_or_else(|| self.profiles.unknown(profile).device(name))?;
        self.open_profile(name, &p)
    }

    /// Opens profile `p` under device name `name` (also a fleet member's own profile): its
    /// URL, its options, its write rules as the entry's guard.
    pub fn open_profile(&mut self, name: &str, p: &crate::profile::Profile) -> Result<()> {
        let from = crate::msg!("session-from-profile", profile = p.name.as_str(), origin = p.origin.to_string()).text;
        crate::core::trace::name_device(&p.url, name);
        let mut device = open_url(&p.url, &self.clock).map_err(|e| e.device(name).cause(&from))?;
        for (k, v) in &p.options {
            device.set_option(k, v).map_err(|e| e.device(name).cause(&from))?;
        }
        let guard = crate::profile::Guard::build(p, device.operands()).map_err(|e| e.device(name))?;
        self.add_guarded(name, &p.url, device, guard);
        if let Some(tags) = &p.tags {
            let i = self.index(name)?;
            self.load_tags(i, tags).map_err(|e| e.cause(&from))?;
        }
        Ok(())
    }

    /// Adds an already-open device (behind the session's write guard).
    pub fn add(&mut self, name: &str, url: &str, device: Box<dyn Device>) {
        self.add_guarded(name, url, device, None);
    }

    /// Adds an already-open device with a profile's write rules. Every device is wrapped
    /// in a [`crate::guard::Guarded`], so the session-wide read-only switch holds for it
    /// too, whether or not it has rules of its own.
    pub fn add_guarded(
        &mut self,
        name: &str,
        url: &str,
        device: Box<dyn Device>,
        rules: Option<crate::profile::Guard>,
    ) {
        let device = Box::new(
            crate::guard::Guarded::new(device, rules.clone(), self.read_only.clone())
                .logging(self.write_log.clone(), name),
        );
        let control = control_param(url);
        let entry = Entry {
            name: name.to_string(),
            url: url.to_string(),
            device,
            guard: rules,
            control,
            names: crate::names::none(),
            tags: None,
        };
        match self.devices.iter().position(|e| e.name == name) {
            Some(i) => self.devices[i] = entry,
            None => self.devices.push(entry),
        }
    }

    pub fn close(&mut self, name: &str) -> Result<()> {
        if let Some(c) = &self.confine {
            c.check_bench("close").map_err(|e| e.device(name))?;
        }
        let i = self.index(name)?;
        self.devices.remove(i);
        if self.current >= self.devices.len() {
            self.current = 0;
        } else if self.current > i {
            self.current -= 1;
        }
        Ok(())
    }

    pub fn entries(&self) -> &[Entry] {
        &self.devices
    }

    pub fn index(&self, name: &str) -> Result<usize> {
        self.devices.iter().position(|e| e.name == name).ok_or_else(|| {
            let names: Vec<&str> = self.devices.iter().map(|e| e.name.as_str()).collect();
            Error::usage(crate::msg!("session-no-device-named", name = name)).hint(if names.is_empty() {
                crate::msg!("session-hint-none-open")
            } else {
                crate::msg!("session-hint-open-devices", names = names.join(", "))
            })
        })
    }

    pub fn use_device(&mut self, name: &str) -> Result<()> {
        self.current = self.index(name)?;
        Ok(())
    }

    /// Makes device `i` the current one (an index from [`index`](Self::index)).
    pub fn use_index(&mut self, i: usize) {
        if i < self.devices.len() {
            self.current = i;
        }
    }

    pub fn current_name(&self) -> Option<&str> {
        self.devices.get(self.current).map(|e| e.name.as_str())
    }

    pub fn entry(&mut self, i: usize) -> &mut Entry {
        &mut self.devices[i]
    }

    pub fn device(&mut self, name: &str) -> Result<&mut Box<dyn Device>> {
        let i = self.index(name)?;
        Ok(&mut self.devices[i].device)
    }

    /// The current device's index, or an error when none is open.
    pub fn current_index(&self) -> Result<usize> {
        if self.devices.is_empty() {
            Err(Error::usage(crate::msg!("session-none-open")).hint(crate::msg!("session-hint-add-device")))
        } else {
            Ok(self.current)
        }
    }

    /// Splits `dev:OPERAND` and parses the operand with that device's grammar.
    pub fn resolve(&self, text: &str) -> Result<Target> {
        let lead = text.len() - text.trim_start().len();
        let t = text.trim();
        let (device, body, offset) = match t.find(':') {
            Some(c) => (self.index(&t[..c]).map_err(|e| e.column(lead))?, &t[c + 1..], lead + c + 1),
            None => (self.current_index()?, t, lead),
        };
        let ops = self.parse_on(device, body).map_err(|e| e.shift(offset).device(&self.devices[device].name))?;
        Ok(Target { device, ops })
    }

    /// Refuses a write the device's rules do not allow (before anything is sent).
    pub fn check_write(&self, device: usize, op: &Operand) -> Result<()> {
        let e = &self.devices[device];
        e.device.permits(&[crate::core::device::Change::Write(*op)]).map_err(|err| err.device(&e.name))
    }

    /// Is device `i` a simulator?
    pub fn simulated(&self, i: usize) -> bool {
        self.devices[i].device.info().simulated
    }

    pub fn name_of(&self, device: usize, op: &Operand) -> String {
        self.devices[device].device.operands().name(op)
    }

    /// Reads operand expressions (each may be a range) from any devices.
    pub fn get(&mut self, texts: &[&str]) -> Result<Vec<(usize, Reading)>> {
        self.ready_for(texts)?;
        let targets: Vec<Target> = texts.iter().map(|t| self.resolve(t)).collect::<Result<_>>()?;
        let mut out = Vec::new();
        // Batch consecutive operands of one device so drivers can coalesce.
        let mut i = 0;
        while i < targets.len() {
            let dev = targets[i].device;
            let mut ops: Vec<Operand> = Vec::new();
            while i < targets.len() && targets[i].device == dev {
                ops.extend_from_slice(&targets[i].ops);
                i += 1;
            }
            let entry = &mut self.devices[dev];
            let values = entry.device.read(&ops).map_err(|e| e.device(&entry.name))?;
            for (op, v) in ops.iter().zip(values) {
                out.push((dev, reading(entry, op, v)));
            }
        }
        Ok(out)
    }

    /// Validates every item first (operand, value, bounds); writes nothing if any is bad.
    /// Then writes in the order given.
    pub fn set(&mut self, items: &[SetItem]) -> Result<Vec<(usize, Reading)>> {
        let texts: Vec<&str> = items.iter().map(|it| it.operand.as_str()).collect();
        self.ready_for(&texts)?;
        let mut plan: Vec<(usize, Operand, Value)> = Vec::new();
        for it in items {
            let target = self.resolve(&it.operand).map_err(|e| e.shift(it.column))?;
            let entry = &self.devices[target.device];
            let space = entry.device.operands();
            for op in &target.ops {
                let v = space.value(op, &it.value).map_err(|e| {
                    let col = it.value_column + e.column.unwrap_or(0);
                    let mut e = e.operand(space.name(op)).device(&entry.name);
                    e.column = Some(col);
                    e
                })?;
                self.check_write(target.device, op).map_err(|e| e.column(it.column))?;
                plan.push((target.device, *op, v));
            }
        }
        let mut out = Vec::new();
        let mut i = 0;
        while i < plan.len() {
            let dev = plan[i].0;
            let mut batch = Vec::new();
            while i < plan.len() && plan[i].0 == dev {
                batch.push((plan[i].1, plan[i].2));
                i += 1;
            }
            let entry = &mut self.devices[dev];
            entry.device.write(&batch).map_err(|e| e.device(&entry.name))?;
            for (op, v) in batch {
                out.push((dev, reading(entry, &op, v)));
            }
        }
        Ok(out)
    }

    /// Writes numeric values (from Lua or a typed helper) to one device, in order, after
    /// checking every value against its operand; writes nothing if any is bad.
    pub fn write_values(&mut self, device: usize, items: &[(Operand, Value)]) -> Result<()> {
        for (op, _) in items {
            self.check_write(device, op)?;
        }
        let entry = &mut self.devices[device];
        let space = entry.device.operands();
        let mut checked = Vec::with_capacity(items.len());
        for (op, v) in items {
            let v = space.check(op, *v).map_err(|e| e.operand(space.name(op)).device(&entry.name))?;
            checked.push((*op, v));
        }
        entry.device.write(&checked).map_err(|e| e.device(&entry.name))
    }

    /// Reads parsed operands from one device.
    pub fn read_values(&mut self, device: usize, ops: &[Operand]) -> Result<Vec<Value>> {
        let entry = &mut self.devices[device];
        entry.device.read(ops).map_err(|e| e.device(&entry.name))
    }

    /// Raises the interrupt flag (Ctrl-C); waits and scripts check it.
    pub fn interrupt(&self) {
        self.interrupt.store(true, Ordering::Relaxed);
        Clock::wake_sleepers();
    }

    pub fn clear_interrupt(&self) {
        self.interrupt.store(false, Ordering::Relaxed);
    }

    pub fn interrupted(&self) -> bool {
        self.interrupt.load(Ordering::Relaxed)
    }
}

/// A reading of `op` on `entry`, with its tag's name and comment when it has one.
pub fn reading(entry: &Entry, op: &Operand, value: Value) -> Reading {
    let tag = entry.names.of(op);
    Reading {
        operand: entry.device.operands().name(op),
        value,
        dtype: op.dtype,
        device: None,
        name: tag.map(|t| t.name.clone()),
        comment: tag.map(|t| t.comment.clone()).filter(|c| !c.is_empty()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::ErrorKind;

    #[test]
    fn every_listed_scheme_is_one_open_url_knows() {
        let clock = Clock::stepped();
        for (prefix, _, family, simulated) in SCHEMES {
            let url = format!("{prefix}./no-such-port?model=nothing");
            assert_eq!(url_family(&url), Some((*family, *simulated)), "{url}");
            if let Err(e) = open_url(&url, &clock) {
                assert!(!e.message.contains("unknown device scheme"), "{url}: {e}");
            }
        }
        assert_eq!(url_family("rtu+tcp://127.0.0.1:502"), Some(("k2", false)));
        assert_eq!(url_family("press1"), None, "a profile name");
        assert!(open_url("nope:x", &clock).is_err_and(|e| e.message.contains("unknown device scheme")));
    }

    fn session() -> Session {
        let mut s = Session::new(Clock::stepped());
        s.open("plc", "sim:K205-16DT").unwrap();
        s
    }

    fn item(op: &str, v: &str) -> SetItem {
        SetItem { operand: op.into(), value: v.into(), column: 0, value_column: 0 }
    }

    #[test]
    fn a_confined_session_opens_simulators_only_whichever_way_a_device_is_named() {
        let mut s = Session::new(Clock::stepped());
        s.profiles = crate::profile::Profiles::parse(
            "[devices.press1]\nurl = \"tcp://192.0.2.1:502\"\n[devices.bench]\nurl = \"sim:K205-16DT\"\n",
            std::path::Path::new("devices.toml"),
        );
        s.confine = Some(Arc::new(crate::confine::Confinement::new(vec![std::env::temp_dir()], None)));
        for (name, url) in
            [("a", "tcp://192.0.2.1:502"), ("b", "press1"), ("c", "kinco+rfc2217://h:1"), ("d", "nosuch")]
        {
            let e = s.open(name, url).unwrap_err();
            assert!(e.to_string().contains("sandboxed run"), "{url}: {e}");
            assert!(s.index(name).is_err(), "{url} was not opened");
        }
        // Profiles bring the user's options (state files): refused even for a simulator.
        assert!(s.open("bench", "bench").unwrap_err().to_string().contains("by URL only"));
        s.open("sim", "sim:K205-16DT").unwrap();
    }

    #[test]
    fn set_then_get_in_order() {
        let mut s = session();
        s.set(&[item("SMB67", "16#85"), item("SMW68", "500"), item("SMD72", "1000")]).unwrap();
        let r = s.get(&["SMB67", "SMW68", "SMD72"]).unwrap();
        let v: Vec<i64> = r.iter().map(|(_, r)| r.value.as_i64()).collect();
        assert_eq!(v, vec![133, 500, 1000]);
    }

    #[test]
    fn a_bad_item_writes_nothing() {
        let mut s = session();
        let e = s.set(&[item("VW0", "1"), item("VB2", "300"), item("VW4", "2")]).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Value);
        assert_eq!(e.operand.as_deref(), Some("VB2"));
        let r = s.get(&["VW0", "VW4"]).unwrap();
        assert!(r.iter().all(|(_, r)| r.value == Value::Int(0)));
    }

    #[test]
    fn numeric_writes_are_checked() {
        let mut s = session();
        let t = s.resolve("VB0").unwrap();
        assert!(s.write_values(t.device, &[(t.ops[0], Value::Int(256))]).is_err());
        s.write_values(t.device, &[(t.ops[0], Value::Int(255))]).unwrap();
        assert_eq!(s.read_values(t.device, &t.ops).unwrap(), vec![Value::Int(255)]);
    }

    #[test]
    fn every_listed_scheme_is_known_to_open_url() {
        for (scheme, ..) in SCHEMES {
            if let Err(e) = open_url(&format!("{scheme}x"), &Clock::stepped()) {
                assert!(!e.message.contains("unknown device scheme"), "{scheme}: {}", e.message);
            }
        }
    }

    #[test]
    fn device_prefix_addresses_another_device() {
        let mut s = session();
        s.open("other", "sim:K209M-56DT").unwrap();
        s.set(&[item("other:VW16000", "9")]).unwrap();
        assert_eq!(s.get(&["other:VW16000"]).unwrap()[0].1.value, Value::Int(9));
        assert!(s.get(&["VW16000"]).is_err(), "the current device is the K205");
        let e = s.get(&["nope:VW0"]).unwrap_err();
        assert!(e.hint.clone().unwrap().contains("plc"));
    }
}

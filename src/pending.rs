//! Devices that are not ready at the moment the session opens them, and become ready on
//! first use: the simulated PLC's state file, taken only when a command uses that PLC, and
//! a real device whose link could not be made yet (a cabinet powered after the shell opened).
//!
//! Why a wrapper: the state file's lock is "one plcsh per state file" (`k2::sim::state`), and
//! most of what plcsh does — `ports`, `models`, `help`, `agent il`, a fleet or a publisher,
//! a second shell that only talks to a drive — never touches the default simulated PLC. Taking
//! the lock when the session opens would make one open shell lock out every other plcsh on
//! the machine. Likewise a REPL or a piped batch opened before the PLC is powered should stay
//! open and connect at the next command, as the link's hint says. Both are the same shape: a
//! step deferred to the first use of the device, retried on every use until it succeeds.
//!
//! The session puts [`Pending`] around the guarded device (`Pending(Guarded(device))`), and a
//! device opened late is guarded like one opened at once (the session's opener wraps it), so
//! every call goes through both and no path can use the simulator before its state is loaded:
//! a call fails with the reason (the state file's holder, the link error) and changes nothing,
//! the capability hook ([`Device::family`]) included, so a family's accessor (`k2::ops` …)
//! answers `None`. Front ends call [`Device::ready`] (through `Session::ready`) before a
//! command, so the user sees the reason, not a missing capability.

use crate::core::device::Change;
use crate::core::operand::{Candidate, Operand, OperandSpace};
use crate::core::{Device, DeviceInfo, Error, ErrorKind, Result, Value};
use crate::msg;

/// A device with a step deferred to its first use.
pub struct Pending {
    state: State,
}

enum State {
    /// Open, with an option still to set before first use (`state`: the simulator's state file).
    Opened { device: Box<dyn Device>, option: Option<(String, String)> },
    /// Not open yet: the link failed when the session opened it; every use tries again.
    Unopened(Unopened),
}

/// Opens the device (guarded as the session guards every device).
pub type Opener = Box<dyn FnMut() -> Result<Box<dyn Device>> + Send>;

struct Unopened {
    open: Opener,
    info: DeviceInfo,
    space: NotConnected,
}

/// The operand space of a device that is not connected yet: every name is refused with the
/// reason, since the device's grammar (its model) is known only once it answers.
struct NotConnected {
    family: &'static str,
    reason: Error,
}

/// How `devices` and the prompt tell a device that is not connected yet: the end of its link.
pub const NOT_CONNECTED: &str = " (not connected)";

/// The model a device not connected yet shows when its URL names none.
pub const UNKNOWN_MODEL: &str = "not connected";

/// Is this device one that has not connected yet?
pub fn is_not_connected(info: &DeviceInfo) -> bool {
    info.link.ends_with(NOT_CONNECTED)
}

impl Pending {
    /// `device`, with `key=value` set on first use (e.g. the simulator's `state` file).
    pub fn option_on_first_use(device: Box<dyn Device>, key: &str, value: &str) -> Pending {
        Pending { state: State::Opened { device, option: Some((key.to_string(), value.to_string())) } }
    }

    /// A device at `url` that could not be opened (`error`); each use tries again with `open`.
    pub fn unopened(url: &str, open: Opener, error: Error) -> Pending {
        let family = family_of(url);
        let model = crate::core::url::DeviceUrl::parse(url)
            .ok()
            .and_then(|u| u.param("model").map(str::to_string))
            .unwrap_or_else(|| UNKNOWN_MODEL.to_string());
        let info = DeviceInfo { family, model, link: format!("{url}{NOT_CONNECTED}"), simulated: false };
        let space = NotConnected { family, reason: error };
        Pending { state: State::Unopened(Unopened { open, info, space }) }
    }

    /// True once nothing is deferred any more.
    pub fn is_ready(&self) -> bool {
        matches!(self.state, State::Opened { option: None, .. })
    }

    /// Drops a deferred option without setting it (the shell chose to run without it).
    pub fn forget_option(&mut self) {
        if let State::Opened { option, .. } = &mut self.state {
            *option = None;
        }
    }

    fn make_ready(&mut self) -> Result<&mut Box<dyn Device>> {
        if let State::Unopened(u) = &mut self.state {
            match (u.open)() {
                Ok(device) => self.state = State::Opened { device, option: None },
                Err(e) => {
                    u.space.reason = e.clone();
                    return Err(not_connected(e));
                }
            }
        }
        let State::Opened { device, option } = &mut self.state else { unreachable!("opened above") };
        if let Some((key, value)) = option.as_ref() {
            device.set_option(key, value)?;
            *option = None;
        }
        Ok(device)
    }

    /// Whether the device answers the capability hook at all, asked without making it ready.
    /// A device not open yet may answer anything once it is. (A lookup for another family
    /// than the device's — `servo status` looking for a drive among the open devices — is
    /// answered by `core::device::lookup` from the device's family name before the hook is
    /// asked, so it does not take the simulated PLC's state file either.)
    fn answers(&mut self, ask: impl FnOnce(&mut Box<dyn Device>) -> bool) -> bool {
        match &mut self.state {
            State::Opened { device, .. } => ask(device),
            State::Unopened(_) => true,
        }
    }
}

/// The family a URL's scheme names, for `devices` before the device answers.
fn family_of(url: &str) -> &'static str {
    crate::schemes::url_family(url).map_or("unknown", |(family, _)| family)
}

/// A link error said again for a device that stays in the session, not connected.
fn not_connected(e: Error) -> Error {
    let mut e = e;
    if e.kind == ErrorKind::Link && !e.message.contains("not connected") {
        e.message = format!("{} (not connected)", e.message);
    }
    e
}

impl OperandSpace for NotConnected {
    fn family(&self) -> &'static str {
        self.family
    }
    fn parse(&self, text: &str) -> Result<Vec<Operand>> {
        Err(Error::link(msg!("pending-not-connected", operand = text.trim()))
            .cause(self.reason.message.clone())
            .hint(msg!("pending-not-connected-hint")))
    }
    fn name(&self, op: &Operand) -> String {
        format!("{op:?}")
    }
    fn describe(&self, _op: &Operand) -> Option<String> {
        None
    }
    fn help(&self, text: &str) -> Result<String> {
        self.parse(text).map(|_| String::new())
    }
    fn complete(&self, _prefix: &str) -> Vec<Candidate> {
        Vec::new()
    }
}

impl Device for Pending {
    fn info(&self) -> &DeviceInfo {
        match &self.state {
            State::Opened { device, .. } => device.info(),
            State::Unopened(u) => &u.info,
        }
    }
    fn operands(&self) -> &dyn OperandSpace {
        match &self.state {
            State::Opened { device, .. } => device.operands(),
            State::Unopened(u) => &u.space,
        }
    }
    fn ready(&mut self) -> Result<()> {
        self.make_ready().map(|_| ())
    }
    fn read(&mut self, ops: &[Operand]) -> Result<Vec<Value>> {
        self.make_ready()?.read(ops)
    }
    fn read_into(&mut self, ops: &[Operand], out: &mut Vec<Value>) -> Result<()> {
        self.make_ready()?.read_into(ops, out)
    }
    fn write(&mut self, items: &[(Operand, Value)]) -> Result<()> {
        self.make_ready()?.write(items)
    }
    fn requests(&self) -> u64 {
        match &self.state {
            State::Opened { device, .. } => device.requests(),
            State::Unopened(_) => 0,
        }
    }
    fn family(&mut self, changes: &[Change]) -> Result<Option<&mut dyn std::any::Any>> {
        if !self.answers(|d| d.family(&[]).ok().flatten().is_some()) {
            return Ok(None);
        }
        self.make_ready()?.family(changes)
    }
    fn permits(&self, changes: &[Change]) -> Result<()> {
        match &self.state {
            State::Opened { device, .. } => device.permits(changes),
            State::Unopened(_) => Ok(()),
        }
    }
    fn set_option(&mut self, key: &str, value: &str) -> Result<()> {
        // Setting the deferred option by hand (`--state`-like options from a profile or a
        // command) replaces the deferred one.
        if let State::Opened { device, option } = &mut self.state {
            if option.as_ref().is_some_and(|(k, _)| k == key) {
                device.set_option(key, value)?;
                *option = None;
                return Ok(());
            }
        }
        self.make_ready()?.set_option(key, value)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Clock;

    #[test]
    fn a_state_file_is_taken_at_first_use_and_not_before() {
        let dir = std::env::temp_dir().join(format!("plcsh-pending-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let state = dir.join("state.json");
        let clock = Clock::stepped();
        let sim = crate::schemes::open_url("sim:K205-16DT", &clock).unwrap();
        let mut first = Pending::option_on_first_use(sim, "state", &state.to_string_lossy());
        assert!(!first.is_ready());
        // Not used yet: another holder can take the state file.
        let other = crate::schemes::open_url("sim:K205-16DT", &clock).unwrap();
        let mut other = Pending::option_on_first_use(other, "state", &state.to_string_lossy());
        other.ready().expect("the first holder");
        let e = first.ready().unwrap_err();
        assert!(e.message.contains("in use"), "{}", e.message);
        let op = first.operands().parse("VW0").unwrap();
        assert!(first.read(&op).is_err(), "no use before the state is loaded");
        assert!(crate::k2::ops(&mut first).is_none());
        drop(other);
        first.ready().expect("free again: the next use takes it");
        assert!(first.is_ready());
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn looking_for_another_family_leaves_the_state_file_alone() {
        let dir = std::env::temp_dir().join(format!("plcsh-pending-family-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let state = dir.join("state.json");
        let clock = Clock::stepped();
        let sim = crate::schemes::open_url("sim:K205-16DT", &clock).unwrap();
        let mut plc = Pending::option_on_first_use(sim, "state", &state.to_string_lossy());
        assert!(crate::servo::ops(&mut plc).is_none());
        assert!(crate::core::device::lookup(&mut plc, "umpk", &[]).unwrap().is_none());
        assert!(!plc.is_ready(), "a lookup for a drive or a UMPK does not take the PLC's state file");
        assert!(!state.exists());
        assert!(crate::k2::ops(&mut plc).is_some(), "the PLC's own family makes it ready");
        assert!(plc.is_ready());
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_device_not_there_yet_is_tried_again_on_each_use() {
        let clock = Clock::stepped();
        let url = "tcp://127.0.0.1:1?model=K205-16DT";
        let e = crate::schemes::open_url(url, &clock).err().expect("nothing listens on port 1");
        let c = clock.clone();
        let mut d = Pending::unopened(url, Box::new(move || crate::schemes::open_url(url, &c)), e);
        assert_eq!(d.info().family, "k2");
        assert_eq!(d.info().model, "K205-16DT");
        assert!(is_not_connected(d.info()));
        let e = d.operands().parse("VW0").unwrap_err();
        assert_eq!(e.kind, ErrorKind::Link);
        assert!(d.ready().is_err());
        assert!(d.ready().is_err(), "still not there: still an error, not a panic");
        // Now something listens there (a listener bound to port 0 stands in for the PLC).
        let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
        let url = format!("tcp://{}?model=K205-16DT", l.local_addr().unwrap());
        let e = crate::schemes::open_url("tcp://127.0.0.1:1", &clock).err().unwrap();
        let (u, c) = (url.clone(), clock.clone());
        let mut d = Pending::unopened(&url, Box::new(move || crate::schemes::open_url(&u, &c)), e);
        d.ready().expect("the listener accepts the connection");
        assert!(d.is_ready());
        assert!(!is_not_connected(d.info()), "{}", d.info().link);
        assert!(d.operands().parse("VW0").is_ok());
    }
}

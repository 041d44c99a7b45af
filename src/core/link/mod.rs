//! The transport layer, family-neutral: every byte that reaches a device or leaves a served
//! simulator goes through here, apart from the codecs that give it meaning.
//!
//! - [`transport`]: the byte stream every transport offers; [`settings`]: a serial line's
//!   character format;
//! - [`line`]: the byte line of the serial families (servo, UMPK, FX) and the registry that
//!   shares one line among the devices on it;
//! - [`serial`]: what carries a serial line — a port on this computer (a tty, a COM port),
//!   a device server's raw TCP port ([`tcp`]) or its RFC 2217 port ([`rfc2217`]) — and the
//!   list of ports present (`plcsh ports`);
//! - [`port`]: deadline ports under the K2's Modbus client;
//! - [`tcp`]: TCP as a line, client and served; [`pipe`]: an in-process line for tests;
//! - [`traced`]: async streams that report their frames;
//! - [`control`]: the control channel beside a served simulator (faults, inputs, events);
//! - [`pty`], [`async_pty`]: pseudo-terminals simulators are served on (Unix; on Windows
//!   they refuse and name the TCP option).
//!
//! Platform code lives in two folders only, [`unix`] and `windows`, which offer the same
//! items; this file picks one. No device family contains a `cfg` for the operating system.

pub mod control;
pub mod line;
pub mod pipe;
pub mod port;
pub mod rfc2217;
pub mod serial;
pub mod served;
pub mod settings;
pub mod tcp;
pub mod traced;
pub mod transport;

#[cfg(unix)]
pub mod unix;
#[cfg(unix)]
use unix as sys;
#[cfg(windows)]
pub mod windows;
#[cfg(windows)]
use windows as sys;

pub use sys::{async_pty, local_connect, port_gone, pty, LocalListener, LocalStream};

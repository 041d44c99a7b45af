//! Serial lines, whatever carries them: a port on this computer (`/dev/ttyUSB0`, `COM3`,
//! `COM10`, `/dev/cu.usbserial-…`), a serial device server's raw TCP port (`…+tcp://HOST:PORT`:
//! Moxa NPort "TCP server" mode, USR, ser2net `raw`, ESP-Link) or its RFC 2217 port
//! (`…+rfc2217://HOST:PORT`: the same, with the baud rate and framing set from here).
//!
//! Every serial family (`rtu`, `kinco`, `umpk`, `fx`, `fxlink`) takes its line from
//! [`Carrier::from_url`] and [`open`], so a new carrier reaches them all at once. The
//! character format is [`LineSettings`]; its frame times are what line-aware timeouts are
//! computed from.

use super::transport::Transport;
use crate::core::url::DeviceUrl;
use crate::core::{Error, Result};
use std::io::{self, Read, Write};
use std::time::Duration;

pub use super::settings::{LineSettings, Parity};

/// The `serialport` builder for a port with these settings.
pub fn builder(path: &str, s: LineSettings) -> serialport::SerialPortBuilder {
    serialport::new(path, s.baud)
        .data_bits(if s.data_bits == 7 { serialport::DataBits::Seven } else { serialport::DataBits::Eight })
        .parity(match s.parity {
            Parity::None => serialport::Parity::None,
            Parity::Even => serialport::Parity::Even,
            Parity::Odd => serialport::Parity::Odd,
        })
        .stop_bits(if s.stop_bits == 2 { serialport::StopBits::Two } else { serialport::StopBits::One })
        .flow_control(serialport::FlowControl::None)
        .timeout(Duration::from_millis(100))
}

/// What carries a serial line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Carrier {
    /// A port on this computer.
    Port(String),
    /// A serial device server's raw TCP port (`HOST:PORT`): bytes in, bytes out.
    Tcp(String),
    /// A serial device server speaking RFC 2217 (`HOST:PORT`).
    Rfc2217(String),
}

impl Carrier {
    /// The carrier a device URL names: `FAMILY:PORT`, `FAMILY+tcp://HOST:PORT` or
    /// `FAMILY+rfc2217://HOST:PORT`. `example` is a port URL for the hint.
    pub fn from_url(u: &DeviceUrl, example: &str) -> Result<Carrier> {
        let carrier = u.scheme.split_once('+').map(|(_, c)| c);
        let target = u.target.trim();
        if target.is_empty() {
            return Err(Error::usage(format!("{} names no serial port", u.text))
                .hint(format!("e.g. {example} (`plcsh ports` lists this computer's serial ports)")));
        }
        match carrier {
            None => Ok(Carrier::Port(target.to_string())),
            Some("tcp") => Ok(Carrier::Tcp(super::tcp::with_port(target, u)?)),
            Some("rfc2217") => Ok(Carrier::Rfc2217(super::tcp::with_port(target, u)?)),
            Some(other) => Err(Error::usage(format!("`+{other}` in {} is not a way to reach a serial line", u.text))
                .hint("use +tcp://HOST:PORT (a device server's raw TCP port) or +rfc2217://HOST:PORT")),
        }
    }

    /// The name a line is shared under (one line per port or server).
    pub fn key(&self) -> String {
        match self {
            Carrier::Port(p) => p.clone(),
            Carrier::Tcp(a) => format!("tcp://{a}"),
            Carrier::Rfc2217(a) => format!("rfc2217://{a}"),
        }
    }

    /// True for a line through the network: the device server adds its own delay.
    pub fn networked(&self) -> bool {
        !matches!(self, Carrier::Port(_))
    }
}

/// Opens the line. A port is opened exclusively; a device server is connected to within
/// the connect timeout, and an RFC 2217 server is told `settings`.
pub fn open(c: &Carrier, settings: LineSettings) -> Result<Box<dyn Transport>> {
    match c {
        Carrier::Port(path) => open_port(path, settings).map(|p| Box::new(p) as Box<dyn Transport>),
        Carrier::Tcp(addr) => Ok(Box::new(super::tcp::TcpLine::connect(addr, super::tcp::CONNECT_TIMEOUT)?)),
        Carrier::Rfc2217(addr) => {
            Ok(Box::new(super::rfc2217::Rfc2217::connect(addr, settings, super::tcp::CONNECT_TIMEOUT)?))
        }
    }
}

/// What to check when a port cannot be opened.
pub fn open_hint() -> String {
    format!(
        "`plcsh ports` lists this computer's serial ports and their USB adapters; check the name ({}), that no other program (KincoBuilder, a terminal program) holds the port{}",
        super::sys::PORT_EXAMPLES,
        super::sys::PERMISSION_HINT
    )
}

/// Opens a port on this computer (exclusively: a second program cannot open it meanwhile).
pub fn open_port(path: &str, settings: LineSettings) -> Result<SerialPort> {
    builder(path, settings)
        .open_native()
        .map(SerialPort)
        .map_err(|e| Error::link(format!("cannot open the serial port {path}")).cause(e).hint(open_hint()))
}

/// A serial port on this computer (a tty or a COM port).
pub struct SerialPort(pub super::sys::NativePort);

impl Drop for SerialPort {
    /// Gives the port back the way the system expects (see `sys::release_port`).
    fn drop(&mut self) {
        super::sys::release_port(&mut self.0);
    }
}

fn timed_out(e: &io::Error) -> bool {
    matches!(e.kind(), io::ErrorKind::TimedOut | io::ErrorKind::WouldBlock)
}

impl Transport for SerialPort {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.0.write_all(bytes)?;
        self.0.flush()
    }
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        use serialport::SerialPort as _;
        // A zero timeout means "what is there now"; COM ports take at least 1 ms.
        self.0.set_timeout(timeout.max(Duration::from_millis(1))).map_err(io::Error::from)?;
        match self.0.read(buf) {
            Err(e) if timed_out(&e) => Ok(0),
            r => r,
        }
    }
    fn discard_input(&mut self) -> io::Result<()> {
        use serialport::SerialPort as _;
        self.0.clear(serialport::ClearBuffer::Input).map_err(io::Error::from)
    }
}

/// One serial port present on this computer, as `plcsh ports` lists it.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct PortInfo {
    /// What to put in a device URL (`COM3`, `/dev/ttyUSB0`).
    pub name: String,
    /// `usb`, `pci`, `bluetooth` or `other`.
    pub kind: &'static str,
    /// `VID:PID` of a USB adapter, hexadecimal.
    pub usb_id: Option<String>,
    pub manufacturer: Option<String>,
    pub product: Option<String>,
    pub serial_number: Option<String>,
}

/// The serial ports the operating system reports, sorted by name (COM2 before COM10).
pub fn ports() -> Result<Vec<PortInfo>> {
    let found = serialport::available_ports()
        .map_err(|e| Error::io("cannot list the serial ports").cause(e).hint(super::sys::PORT_LIST_HINT))?;
    let mut list: Vec<PortInfo> = found
        .into_iter()
        .filter(|p| super::sys::listed_port(&p.port_name))
        .map(|p| {
            let mut info = PortInfo {
                name: p.port_name,
                kind: "other",
                usb_id: None,
                manufacturer: None,
                product: None,
                serial_number: None,
            };
            match p.port_type {
                serialport::SerialPortType::UsbPort(u) => {
                    info.kind = "usb";
                    info.usb_id = Some(format!("{:04x}:{:04x}", u.vid, u.pid));
                    info.manufacturer = u.manufacturer;
                    info.product = u.product;
                    info.serial_number = u.serial_number;
                }
                serialport::SerialPortType::PciPort => info.kind = "pci",
                serialport::SerialPortType::BluetoothPort => info.kind = "bluetooth",
                serialport::SerialPortType::Unknown => {}
            }
            info
        })
        .collect();
    list.sort_by_key(|p| natural_key(&p.name));
    list.dedup_by(|a, b| a.name == b.name);
    Ok(list)
}

/// `COM10` sorts after `COM9`: the text before the trailing number, then the number.
fn natural_key(name: &str) -> (String, u64) {
    let digits = name.len() - name.trim_end_matches(|c: char| c.is_ascii_digit()).len();
    let (head, tail) = name.split_at(name.len() - digits);
    (head.to_ascii_lowercase(), tail.parse().unwrap_or(0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_times_follow_the_character_format() {
        let s = LineSettings::n81(9600);
        assert_eq!(s.char_bits(), 10);
        assert_eq!(s.time_of(96), Duration::from_millis(100));
        let fx = LineSettings { baud: 4800, data_bits: 7, parity: Parity::Even, stop_bits: 1 };
        assert_eq!(fx.char_bits(), 10);
        assert_eq!(fx.to_string(), "4800 7E1");
        let rtu = LineSettings { baud: 19200, data_bits: 8, parity: Parity::Even, stop_bits: 1 };
        assert_eq!(rtu.char_bits(), 11);
        assert_eq!(rtu.time_of(usize::MAX), Duration::from_micros(u64::MAX.div_ceil(19200)), "saturates, never wraps");
    }

    #[test]
    fn carriers_from_urls() {
        let c = |t: &str| Carrier::from_url(&DeviceUrl::parse(t).unwrap(), "kinco:COM4?id=1");
        assert_eq!(c("kinco:COM10?id=1").unwrap(), Carrier::Port("COM10".into()));
        assert_eq!(c("kinco:/dev/ttyUSB0").unwrap(), Carrier::Port("/dev/ttyUSB0".into()));
        assert_eq!(c("kinco+tcp://10.0.0.5:4001?id=2").unwrap(), Carrier::Tcp("10.0.0.5:4001".into()));
        assert_eq!(c("fx+rfc2217://moxa:4001").unwrap(), Carrier::Rfc2217("moxa:4001".into()));
        assert_eq!(c("umpk+RFC2217://[::1]:7000").unwrap(), Carrier::Rfc2217("[::1]:7000".into()));
        let e = c("kinco:?id=1").unwrap_err();
        assert!(e.hint.as_deref().unwrap().contains("plcsh ports"));
        assert!(c("kinco+udp://h:1").unwrap_err().message.contains("+udp"));
        assert!(c("kinco+tcp://host").is_err(), "a device server needs a port");
        assert!(c("kinco+tcp://host:99999").is_err());
    }

    #[test]
    fn port_names_sort_naturally() {
        let mut v = ["COM10", "COM2", "COM1", "/dev/ttyUSB10", "/dev/ttyUSB9"];
        v.sort_by_key(|n| natural_key(n));
        assert_eq!(v, ["/dev/ttyUSB9", "/dev/ttyUSB10", "COM1", "COM2", "COM10"]);
    }
}

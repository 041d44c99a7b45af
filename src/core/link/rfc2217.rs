//! RFC 2217 (Telnet Com Port Control Option): a serial line on a device server that this
//! side configures — baud rate, data bits, parity and stop bits are sent to the server
//! (`kinco+rfc2217://HOST:PORT?baud=38400`), which sets its port accordingly. Moxa NPort
//! ("RFC2217 mode"), ser2net (`telnet(rfc2217)`) and pyserial's server speak it.
//!
//! The stream is Telnet: a data byte 0xFF travels doubled (IAC IAC), and commands (IAC
//! WILL/WONT/DO/DONT option, IAC SB … IAC SE sub-negotiations) are interleaved with the data.
//! [`Decoder`] separates them in one pass over the bytes (linear, never panics: it reads
//! what any server sends), and [`Rfc2217`] answers option requests, sends the settings after
//! the server agrees to COM-PORT-OPTION (RFC 2217 §2, §3: SET-BAUDRATE 1, SET-DATASIZE 2,
//! SET-PARITY 3, SET-STOPSIZE 4, SET-CONTROL 5, PURGE-DATA 12; the server answers each with
//! the code + 100), and waits for the server to confirm them before the first frame.

use super::settings::{LineSettings, Parity};
use super::transport::Transport;
use crate::core::{Error, Result};
use crate::msg;
use std::io::{self, Read, Write};
use std::net::TcpStream;
use std::time::{Duration, Instant};

/// Telnet bytes (RFC 854) and options (RFC 856, 858, 2217).
pub mod telnet {
    pub const IAC: u8 = 255;
    pub const DONT: u8 = 254;
    pub const DO: u8 = 253;
    pub const WONT: u8 = 252;
    pub const WILL: u8 = 251;
    pub const SB: u8 = 250;
    pub const SE: u8 = 240;
    pub const BINARY: u8 = 0;
    pub const ECHO: u8 = 1;
    pub const SGA: u8 = 3;
    pub const COM_PORT: u8 = 44;
    /// Client-to-server sub-negotiation codes (the server answers with code + 100).
    pub const SET_BAUDRATE: u8 = 1;
    pub const SET_DATASIZE: u8 = 2;
    pub const SET_PARITY: u8 = 3;
    pub const SET_STOPSIZE: u8 = 4;
    pub const SET_CONTROL: u8 = 5;
    pub const PURGE_DATA: u8 = 12;
    pub const SERVER_OFFSET: u8 = 100;
}
use telnet::*;

/// The longest sub-negotiation kept (longer ones are cut: no option needs more).
const MAX_SB: usize = 64;

/// What the decoder found in the stream besides data.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Event {
    /// IAC WILL/WONT/DO/DONT option.
    Option { verb: u8, option: u8 },
    /// IAC SB option payload… IAC SE (payload unescaped, cut at [`MAX_SB`]).
    Sub { option: u8, payload: Vec<u8> },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum State {
    Data,
    Iac,
    Verb(u8),
    SubOption,
    Sub,
    SubIac,
}

/// Splits a Telnet byte stream into data and [`Event`]s, across reads.
#[derive(Clone, Debug)]
pub struct Decoder {
    state: State,
    sub_option: u8,
    sub: Vec<u8>,
}

impl Default for Decoder {
    fn default() -> Decoder {
        Decoder { state: State::Data, sub_option: 0, sub: Vec::new() }
    }
}

impl Decoder {
    /// Feeds `input`: data bytes are appended to `data`, commands to `events`.
    pub fn feed(&mut self, input: &[u8], data: &mut Vec<u8>, events: &mut Vec<Event>) {
        for &b in input {
            self.state = match (self.state, b) {
                (State::Data, IAC) => State::Iac,
                (State::Data, _) => {
                    data.push(b);
                    State::Data
                }
                (State::Iac, IAC) => {
                    data.push(IAC);
                    State::Data
                }
                (State::Iac, WILL | WONT | DO | DONT) => State::Verb(b),
                (State::Iac, SB) => State::SubOption,
                (State::Iac, _) => State::Data, // NOP, GA, BRK …: nothing to do on a data line
                (State::Verb(verb), option) => {
                    events.push(Event::Option { verb, option });
                    State::Data
                }
                (State::SubOption, option) => {
                    self.sub_option = option;
                    self.sub.clear();
                    State::Sub
                }
                (State::Sub, IAC) => State::SubIac,
                (State::Sub, _) => {
                    if self.sub.len() < MAX_SB {
                        self.sub.push(b);
                    }
                    State::Sub
                }
                (State::SubIac, IAC) => {
                    if self.sub.len() < MAX_SB {
                        self.sub.push(IAC);
                    }
                    State::Sub
                }
                (State::SubIac, SE) => {
                    events.push(Event::Sub { option: self.sub_option, payload: std::mem::take(&mut self.sub) });
                    State::Data
                }
                (State::SubIac, _) => State::Sub, // a malformed sub-negotiation: keep looking for IAC SE
            };
        }
    }
}

/// `bytes` with every 0xFF doubled, as data travels in Telnet.
pub fn escape(bytes: &[u8], out: &mut Vec<u8>) {
    for &b in bytes {
        out.push(b);
        if b == IAC {
            out.push(IAC);
        }
    }
}

/// IAC SB COM-PORT-OPTION `code` `value`… IAC SE (the value escaped).
fn com_port(code: u8, value: &[u8]) -> Vec<u8> {
    let mut v = vec![IAC, SB, COM_PORT, code];
    escape(value, &mut v);
    v.extend([IAC, SE]);
    v
}

/// The settings as the four sub-negotiations that set them, plus "no flow control".
pub fn settings_requests(s: LineSettings) -> Vec<Vec<u8>> {
    let parity = match s.parity {
        Parity::None => 1,
        Parity::Odd => 2,
        Parity::Even => 3,
    };
    vec![
        com_port(SET_BAUDRATE, &s.baud.to_be_bytes()),
        com_port(SET_DATASIZE, &[s.data_bits]),
        com_port(SET_PARITY, &[parity]),
        com_port(SET_STOPSIZE, &[s.stop_bits]),
        com_port(SET_CONTROL, &[1]),
    ]
}

/// A serial line on an RFC 2217 server.
pub struct Rfc2217 {
    stream: TcpStream,
    addr: String,
    decoder: Decoder,
    /// Data decoded but not yet handed to the caller.
    pending: Vec<u8>,
    events: Vec<Event>,
    raw: Vec<u8>,
}

impl Rfc2217 {
    /// Connects, negotiates COM-PORT-OPTION and sets the line, all within `timeout`.
    pub fn connect(addr: &str, settings: LineSettings, timeout: Duration) -> Result<Rfc2217> {
        let stream = super::tcp::connect(addr, timeout, super::tcp::server_hint)?;
        let mut l = Rfc2217 {
            stream,
            addr: addr.to_string(),
            decoder: Decoder::default(),
            pending: Vec::new(),
            events: Vec::new(),
            raw: vec![0; 512],
        };
        l.negotiate(settings, Instant::now() + timeout)?;
        Ok(l)
    }

    /// `what`: `confirm`, `agree`, `closed` (with `reason`), `refused`, `baud` (with `got`, `want`).
    fn refused(&self, what: &str, reason: String, got_want: (u32, u32)) -> Error {
        let (got, want) = got_want;
        Error::link(msg!("link-rfc2217", addr = &self.addr, what = what, reason = reason, got = got, want = want))
            .hint(msg!("link-hint-rfc2217"))
    }

    fn negotiate(&mut self, settings: LineSettings, deadline: Instant) -> Result<()> {
        let mut hello = vec![IAC, WILL, COM_PORT, IAC, WILL, BINARY, IAC, DO, BINARY, IAC, WILL, SGA, IAC, DO, SGA];
        self.write_raw(&hello)?;
        hello.clear();
        // The settings go out once the server agrees to the option (RFC 2217 §2).
        let mut agreed = false;
        let mut confirmed = [false; 5];
        let requests = settings_requests(settings);
        while !(agreed && confirmed.iter().all(|c| *c)) {
            let left = deadline.saturating_duration_since(Instant::now());
            if left.is_zero() {
                return Err(self.refused(if agreed { "confirm" } else { "agree" }, String::new(), (0, 0)));
            }
            self.read_more(left).map_err(|e| self.refused("closed", e.to_string(), (0, 0)))?;
            for ev in std::mem::take(&mut self.events) {
                match ev {
                    Event::Option { verb: DO, option: COM_PORT } if !agreed => {
                        agreed = true;
                        for r in &requests {
                            self.write_raw(r)?;
                        }
                    }
                    Event::Option { verb: DONT, option: COM_PORT } => {
                        return Err(self.refused("refused", String::new(), (0, 0)))
                    }
                    Event::Option { verb, option } => self.answer_option(verb, option)?,
                    Event::Sub { option: COM_PORT, payload } => {
                        if let Some((&code, value)) = payload.split_first() {
                            let i = code.wrapping_sub(SERVER_OFFSET + 1) as usize;
                            if i < confirmed.len() {
                                confirmed[i] = true;
                                if code == SERVER_OFFSET + SET_BAUDRATE {
                                    let got = value.get(..4).map(|b| u32::from_be_bytes([b[0], b[1], b[2], b[3]]));
                                    if got.is_some_and(|b| b != settings.baud) {
                                        return Err(self.refused(
                                            "baud",
                                            String::new(),
                                            (got.unwrap_or(0), settings.baud),
                                        ));
                                    }
                                }
                            }
                        }
                    }
                    Event::Sub { .. } => {}
                }
            }
        }
        Ok(())
    }

    /// Answers an option request the way a data line wants it: binary and suppress-go-ahead
    /// on, COM-PORT-OPTION on, everything else (echo included) off.
    fn answer_option(&mut self, verb: u8, option: u8) -> io::Result<()> {
        let answer = match (verb, option) {
            (DO, BINARY | SGA | COM_PORT) | (WILL, BINARY | SGA) => return Ok(()), // as asked
            (DO, _) => WONT,
            (WILL, _) => DONT,
            _ => return Ok(()), // WONT/DONT need no answer
        };
        self.write_raw(&[IAC, answer, option])
    }

    fn write_raw(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.stream.write_all(bytes)
    }

    /// Reads once (within `timeout`) and decodes what came.
    fn read_more(&mut self, timeout: Duration) -> io::Result<()> {
        self.stream.set_read_timeout(Some(timeout.max(Duration::from_micros(1))))?;
        match self.stream.read(&mut self.raw) {
            Ok(0) => Err(io::Error::new(io::ErrorKind::UnexpectedEof, msg!("link-connection-closed").text)),
            Ok(n) => {
                self.decoder.feed(&self.raw[..n], &mut self.pending, &mut self.events);
                Ok(())
            }
            Err(e) if matches!(e.kind(), io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut) => Ok(()),
            Err(e) if e.kind() == io::ErrorKind::Interrupted => Ok(()),
            Err(e) => Err(e),
        }
    }
}

impl Transport for Rfc2217 {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        let mut out = Vec::with_capacity(bytes.len() + 4);
        escape(bytes, &mut out);
        self.write_raw(&out)
    }

    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        let deadline = Instant::now() + timeout;
        loop {
            for ev in std::mem::take(&mut self.events) {
                if let Event::Option { verb, option } = ev {
                    self.answer_option(verb, option)?;
                }
            }
            if !self.pending.is_empty() {
                let n = buf.len().min(self.pending.len());
                buf[..n].copy_from_slice(&self.pending[..n]);
                self.pending.drain(..n);
                return Ok(n);
            }
            let left = deadline.saturating_duration_since(Instant::now());
            if left.is_zero() && !timeout.is_zero() {
                return Ok(0);
            }
            self.read_more(left)?;
            if timeout.is_zero() && self.pending.is_empty() {
                return Ok(0);
            }
        }
    }

    /// Drops what this side holds and asks the server to purge its receive buffer.
    fn discard_input(&mut self) -> io::Result<()> {
        self.write_raw(&com_port(PURGE_DATA, &[1]))?;
        self.pending.clear();
        let mut scratch = [0u8; 256];
        while self.recv(&mut scratch, Duration::ZERO)? > 0 {}
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn decode(input: &[u8]) -> (Vec<u8>, Vec<Event>) {
        let (mut d, mut data, mut ev) = (Decoder::default(), Vec::new(), Vec::new());
        d.feed(input, &mut data, &mut ev);
        (data, ev)
    }

    #[test]
    fn data_and_commands_are_separated_across_reads() {
        // RFC 854: IAC IAC is a data 0xFF; RFC 2217 §3: the server's SET-BAUDRATE answer is 101.
        let stream = [1, IAC, IAC, 2, IAC, DO, COM_PORT, 3, IAC, SB, COM_PORT, 101, 0, 0, 0x96, 0, IAC, SE, 4];
        let (data, ev) = decode(&stream);
        assert_eq!(data, [1, 0xFF, 2, 3, 4]);
        assert_eq!(
            ev,
            [
                Event::Option { verb: DO, option: COM_PORT },
                Event::Sub { option: COM_PORT, payload: vec![101, 0, 0, 0x96, 0] }
            ]
        );
        // The same bytes one at a time give the same result.
        let (mut d, mut data1, mut ev1) = (Decoder::default(), Vec::new(), Vec::new());
        for b in stream {
            d.feed(&[b], &mut data1, &mut ev1);
        }
        assert_eq!((data1, ev1), (data, ev));
    }

    #[test]
    fn settings_go_out_as_rfc2217_asks() {
        let s = LineSettings { baud: 38400, data_bits: 7, parity: Parity::Even, stop_bits: 2 };
        let r = settings_requests(s);
        assert_eq!(r[0], [IAC, SB, COM_PORT, 1, 0, 0, 0x96, 0, IAC, SE]);
        assert_eq!(r[1], [IAC, SB, COM_PORT, 2, 7, IAC, SE]);
        assert_eq!(r[2], [IAC, SB, COM_PORT, 3, 3, IAC, SE], "EVEN is 3");
        assert_eq!(r[3], [IAC, SB, COM_PORT, 4, 2, IAC, SE]);
        // A baud rate with a 0xFF byte is escaped inside the sub-negotiation.
        let odd = settings_requests(LineSettings::n81(0x0001_C2FF));
        assert_eq!(odd[0], [IAC, SB, COM_PORT, 1, 0, 1, 0xC2, IAC, IAC, IAC, SE]);
    }

    #[test]
    fn hostile_streams_are_decoded_without_panic() {
        let long_sub: Vec<u8> = [IAC, SB, COM_PORT].into_iter().chain(std::iter::repeat_n(7, 10_000)).collect();
        let (data, ev) = decode(&long_sub);
        assert!(data.is_empty() && ev.is_empty());
        let (data, _) = decode(&[IAC, SB, COM_PORT, IAC, 9, IAC, SE, 5]);
        assert_eq!(data, [5]);
        let (data, ev) = decode(&[IAC, 241, IAC]);
        assert!(data.is_empty() && ev.is_empty());
    }
}

//! `sim serve --rfc2217`: the served serial lines' TCP ports speak RFC 2217 (Telnet
//! COM-PORT-OPTION) instead of raw TCP, as a Moxa NPort in "RFC2217 mode" or ser2net's
//! `telnet(rfc2217)` does. So `rtu+rfc2217://`, `kinco+rfc2217://` (and pyserial's
//! `rfc2217://`, or a virtual COM port driver that redirects to RFC 2217) reach plcsh's own
//! simulators, and a program that sets the baud rate and format of its line gets the answers
//! it waits for.
//!
//! Shape: each family is served on a raw TCP port on loopback as usual, and a front — this
//! file — listens where the user asked. Per client it connects to the raw port and relays:
//! from the client, [`Server::feed`] separates data from Telnet commands (the decoder is the
//! client's, `core::link::rfc2217::Decoder`: one pass, never panics) and answers them; to the
//! client, data bytes 0xFF are doubled (IAC IAC). The line settings are kept per connection
//! and confirmed as RFC 2217 §3 asks (the server answers each SET-… with code + 100 and the
//! value in effect; a value 0 is a question); SET-CONTROL, PURGE-DATA, the state masks and
//! FLOWCONTROL-SUSPEND/RESUME are answered the same way, and a client's NOTIFY-LINESTATE /
//! NOTIFY-MODEMSTATE (which only a server should send) gets the current state. A simulated
//! device has no baud rate of its own: any setting is accepted.

use crate::core::link::rfc2217::telnet::*;
use crate::core::link::rfc2217::{escape, Decoder, Event};
use std::net::SocketAddr;
use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::{TcpListener, TcpStream};

/// RFC 2217 codes beyond the four settings, SET-CONTROL and PURGE-DATA (client to server).
const SIGNATURE: u8 = 0;
const NOTIFY_LINESTATE: u8 = 6;
const NOTIFY_MODEMSTATE: u8 = 7;
const FLOWCONTROL_SUSPEND: u8 = 8;
const FLOWCONTROL_RESUME: u8 = 9;
const SET_LINESTATE_MASK: u8 = 10;
const SET_MODEMSTATE_MASK: u8 = 11;

/// The line as a modem sees it: clear to send, data set ready, carrier detect (RFC 2217 §3,
/// NOTIFY-MODEMSTATE bits 4, 5, 7), and a transmitter that is empty (NOTIFY-LINESTATE bits 5, 6).
const MODEM_STATE: u8 = 0x10 | 0x20 | 0x80;
const LINE_STATE: u8 = 0x20 | 0x40;

/// The options this side agrees to, either way: binary data, no go-aheads, COM-PORT-OPTION.
fn accepted(option: u8) -> bool {
    matches!(option, BINARY | SGA | COM_PORT)
}

/// One connection's Telnet side: what was agreed, the line settings the client set, and the
/// decoder that carries partial commands across reads.
#[derive(Clone, Debug)]
pub struct Server {
    decoder: Decoder,
    events: Vec<Event>,
    /// Options this side does (WILL sent) and the client does (DO sent), and those refused
    /// once (a refusal is not repeated, so two sides cannot loop).
    we: [bool; 256],
    they: [bool; 256],
    refused: [bool; 256],
    pub baud: u32,
    pub data_bits: u8,
    /// RFC 2217 parity code: 1 none, 2 odd, 3 even, 4 mark, 5 space.
    pub parity: u8,
    /// RFC 2217 stop size code: 1 one, 2 two, 3 one and a half.
    pub stop: u8,
    /// SET-CONTROL states: outbound flow control (1 none), break (6 off), DTR (8 on), RTS
    /// (11 on), inbound flow control (14 none).
    flow_out: u8,
    brk: u8,
    dtr: u8,
    rts: u8,
    flow_in: u8,
    linestate_mask: u8,
    modemstate_mask: u8,
}

impl Default for Server {
    fn default() -> Server {
        Server {
            decoder: Decoder::default(),
            events: Vec::new(),
            we: [false; 256],
            they: [false; 256],
            refused: [false; 256],
            baud: 9600,
            data_bits: 8,
            parity: 1,
            stop: 1,
            flow_out: 1,
            brk: 6,
            dtr: 8,
            rts: 11,
            flow_in: 14,
            linestate_mask: 0,
            modemstate_mask: 0,
        }
    }
}

/// IAC SB COM-PORT-OPTION `code` `value`… IAC SE, the value escaped.
fn sub(code: u8, value: &[u8], out: &mut Vec<u8>) {
    out.extend([IAC, SB, COM_PORT, code]);
    escape(value, out);
    out.extend([IAC, SE]);
}

impl Server {
    /// Feeds bytes from the client: the data bytes (unescaped) go to `data`, for the device;
    /// the answers to its commands go to `reply`, for the client. Linear in `input`; any
    /// input is taken without panic.
    pub fn feed(&mut self, input: &[u8], data: &mut Vec<u8>, reply: &mut Vec<u8>) {
        self.decoder.feed(input, data, &mut self.events);
        for ev in std::mem::take(&mut self.events) {
            match ev {
                Event::Option { verb, option } => self.option(verb, option, reply),
                Event::Sub { option: COM_PORT, payload } => {
                    if let Some((&code, value)) = payload.split_first() {
                        self.com_port(code, value, reply);
                    }
                }
                Event::Sub { .. } => {}
            }
        }
    }

    /// RFC 854/1143, kept simple: agree once to what a data line wants, refuse the rest once,
    /// answer a withdrawal once.
    fn option(&mut self, verb: u8, option: u8, reply: &mut Vec<u8>) {
        let o = usize::from(option);
        let answer = match verb {
            WILL if accepted(option) && !self.they[o] => {
                self.they[o] = true;
                DO
            }
            DO if accepted(option) && !self.we[o] => {
                self.we[o] = true;
                WILL
            }
            WILL if !accepted(option) && !self.refused[o] => {
                self.refused[o] = true;
                DONT
            }
            DO if !accepted(option) && !self.refused[o] => {
                self.refused[o] = true;
                WONT
            }
            WONT if self.they[o] => {
                self.they[o] = false;
                DONT
            }
            DONT if self.we[o] => {
                self.we[o] = false;
                WONT
            }
            _ => return,
        };
        reply.extend([IAC, answer, option]);
    }

    /// A COM-PORT-OPTION command from the client (RFC 2217 §3), answered with code + 100.
    fn com_port(&mut self, code: u8, value: &[u8], reply: &mut Vec<u8>) {
        let first = value.first().copied();
        let answer = code.wrapping_add(SERVER_OFFSET);
        match code {
            SIGNATURE if value.is_empty() => {
                sub(answer, concat!("plcsh ", env!("CARGO_PKG_VERSION"), " sim serve").as_bytes(), reply)
            }
            SET_BAUDRATE => {
                if let Some(b) = value.get(..4) {
                    let baud = u32::from_be_bytes([b[0], b[1], b[2], b[3]]);
                    if baud != 0 {
                        self.baud = baud;
                    }
                }
                sub(answer, &self.baud.to_be_bytes(), reply);
            }
            SET_DATASIZE => {
                if let Some(v @ 5..=8) = first {
                    self.data_bits = v;
                }
                sub(answer, &[self.data_bits], reply);
            }
            SET_PARITY => {
                if let Some(v @ 1..=5) = first {
                    self.parity = v;
                }
                sub(answer, &[self.parity], reply);
            }
            SET_STOPSIZE => {
                if let Some(v @ 1..=3) = first {
                    self.stop = v;
                }
                sub(answer, &[self.stop], reply);
            }
            SET_CONTROL => {
                let state = match first {
                    None | Some(0) => self.flow_out,
                    Some(v @ 1..=3) | Some(v @ 17..=19) => {
                        self.flow_out = v;
                        v
                    }
                    Some(4) => self.brk,
                    Some(v @ 5..=6) => {
                        self.brk = v;
                        v
                    }
                    Some(7) => self.dtr,
                    Some(v @ 8..=9) => {
                        self.dtr = v;
                        v
                    }
                    Some(10) => self.rts,
                    Some(v @ 11..=12) => {
                        self.rts = v;
                        v
                    }
                    Some(13) => self.flow_in,
                    Some(v @ 14..=16) => {
                        self.flow_in = v;
                        v
                    }
                    Some(_) => self.flow_out, // not a SET-CONTROL value: the state in effect
                };
                sub(answer, &[state], reply);
            }
            NOTIFY_LINESTATE => sub(answer, &[LINE_STATE], reply),
            NOTIFY_MODEMSTATE => sub(answer, &[MODEM_STATE], reply),
            FLOWCONTROL_SUSPEND | FLOWCONTROL_RESUME => sub(answer, &[], reply),
            SET_LINESTATE_MASK => {
                self.linestate_mask = first.unwrap_or(self.linestate_mask);
                sub(answer, &[self.linestate_mask], reply);
            }
            SET_MODEMSTATE_MASK => {
                self.modemstate_mask = first.unwrap_or(self.modemstate_mask);
                sub(answer, &[self.modemstate_mask], reply);
            }
            // Nothing is buffered on this side: a purge of either direction is done at once.
            PURGE_DATA => sub(answer, &[first.unwrap_or(3)], reply),
            _ => {} // a client's signature, a server's code sent back: nothing to answer
        }
    }
}

/// Listens on `listen` and relays each client to the raw line at `inner` (see the module's
/// doc); returns the bound listener's address with the task that serves it.
pub async fn front(
    listen: SocketAddr,
    inner: SocketAddr,
) -> crate::core::Result<(SocketAddr, impl std::future::Future<Output = std::io::Result<()>>)> {
    let l = TcpListener::bind(listen).await.map_err(|e| {
        crate::core::Error::io(crate::msg!("cli-serve-cannot-listen", addr = listen.to_string()))
            .cause(e)
            .hint(crate::msg!("cli-hint-serve-port"))
    })?;
    let addr = l.local_addr()?;
    Ok((addr, async move {
        loop {
            let (client, _) = l.accept().await?;
            tokio::spawn(relay(client, inner));
        }
    }))
}

/// One client: Telnet on its side, the raw line on the other, until either closes.
async fn relay(client: TcpStream, inner: SocketAddr) {
    let Ok(line) = TcpStream::connect(inner).await else { return };
    let _ = client.set_nodelay(true);
    let _ = line.set_nodelay(true);
    let (mut cr, mut cw) = client.into_split();
    let (mut lr, mut lw) = line.into_split();
    let mut server = Server::default();
    let (mut from_client, mut from_line) = (vec![0u8; 4096], vec![0u8; 4096]);
    let (mut data, mut reply) = (Vec::new(), Vec::new());
    loop {
        tokio::select! {
            n = cr.read(&mut from_client) => {
                let Ok(n @ 1..) = n else { break };
                data.clear();
                reply.clear();
                server.feed(&from_client[..n], &mut data, &mut reply);
                if !reply.is_empty() && cw.write_all(&reply).await.is_err() {
                    break;
                }
                if !data.is_empty() && lw.write_all(&data).await.is_err() {
                    break;
                }
            }
            n = lr.read(&mut from_line) => {
                let Ok(n @ 1..) = n else { break };
                reply.clear();
                escape(&from_line[..n], &mut reply);
                if cw.write_all(&reply).await.is_err() {
                    break;
                }
            }
        }
    }
}

/// With `--rfc2217`: the arguments with each serial option's TCP port moved to a free
/// loopback port, and where each front listens, by its readiness line field (`rtu_tcp`, …).
/// Without it: nothing to change.
#[allow(clippy::type_complexity)]
pub fn behind_fronts(
    args: &super::ServeArgs,
) -> crate::core::Result<(Option<super::ServeArgs>, Vec<(&'static str, SocketAddr)>)> {
    if !args.rfc2217 {
        return Ok((None, Vec::new()));
    }
    let mut inner = args.clone();
    let mut fronts = Vec::new();
    for (field, option) in [
        ("rtu_tcp", &mut inner.rtu_tcp),
        ("servo_tcp", &mut inner.servo_tcp),
        ("fx_tcp", &mut inner.fx_tcp),
        ("fx_link_tcp", &mut inner.fx_link_tcp),
        ("umpk_tcp", &mut inner.umpk_tcp),
    ] {
        if let Some(a) = option.take() {
            fronts.push((field, super::listen_addr(&a)?));
            *option = Some("127.0.0.1:0".to_string());
        }
    }
    if fronts.is_empty() {
        return Err(crate::core::Error::usage(crate::msg!("cli-serve-rfc2217-needs-tcp"))
            .hint(crate::msg!("cli-hint-serve-rfc2217")));
    }
    Ok((Some(inner), fronts))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn feed(s: &mut Server, input: &[u8]) -> (Vec<u8>, Vec<u8>) {
        let (mut data, mut reply) = (Vec::new(), Vec::new());
        s.feed(input, &mut data, &mut reply);
        (data, reply)
    }

    /// RFC 2217 §2: the client's WILL COM-PORT-OPTION gets DO; binary and SGA are agreed
    /// both ways; echo is refused, once.
    #[test]
    fn options_are_agreed_once_and_refused_once() {
        let mut s = Server::default();
        let (_, r) = feed(&mut s, &[IAC, WILL, COM_PORT, IAC, WILL, BINARY, IAC, DO, BINARY, IAC, DO, ECHO]);
        assert_eq!(r, [IAC, DO, COM_PORT, IAC, DO, BINARY, IAC, WILL, BINARY, IAC, WONT, ECHO]);
        let (_, r) = feed(&mut s, &[IAC, WILL, COM_PORT, IAC, DO, ECHO]);
        assert!(r.is_empty(), "agreed and refused options are not answered again: {r:?}");
        let (_, r) = feed(&mut s, &[IAC, WONT, COM_PORT]);
        assert_eq!(r, [IAC, DONT, COM_PORT]);
    }

    /// RFC 2217 §3: each setting is answered with code + 100 and the value in effect; a value
    /// 0 (or one out of range) asks for the value in effect.
    #[test]
    fn settings_are_confirmed_with_the_value_in_effect() {
        let mut s = Server::default();
        let baud = 19200u32.to_be_bytes();
        let mut req = vec![IAC, SB, COM_PORT, SET_BAUDRATE];
        req.extend(baud);
        req.extend([IAC, SE, IAC, SB, COM_PORT, SET_PARITY, 3, IAC, SE]);
        req.extend([IAC, SB, COM_PORT, SET_DATASIZE, 9, IAC, SE]);
        let (data, r) = feed(&mut s, &req);
        assert!(data.is_empty());
        let mut want = vec![IAC, SB, COM_PORT, 101];
        want.extend(baud);
        want.extend([IAC, SE, IAC, SB, COM_PORT, 103, 3, IAC, SE, IAC, SB, COM_PORT, 102, 8, IAC, SE]);
        assert_eq!(r, want);
        assert_eq!((s.baud, s.parity, s.data_bits), (19200, 3, 8));
        // A query: the value in effect, unchanged.
        let (_, r) = feed(&mut s, &[IAC, SB, COM_PORT, SET_BAUDRATE, 0, 0, 0, 0, IAC, SE]);
        assert_eq!(r[4..8], baud);
    }

    /// Data crosses unescaped one way and escaped the other; a 0xFF in a setting's value is
    /// escaped in the answer (RFC 854: IAC IAC).
    #[test]
    fn data_and_values_are_escaped() {
        let mut s = Server::default();
        let (data, r) = feed(&mut s, &[1, IAC, IAC, 2]);
        assert_eq!((data, r), (vec![1, 0xFF, 2], vec![]));
        let baud = 0x0001_C2FFu32.to_be_bytes();
        let (_, r) = feed(&mut s, &[IAC, SB, COM_PORT, SET_BAUDRATE, baud[0], baud[1], baud[2], IAC, IAC, IAC, SE]);
        assert_eq!(r, [IAC, SB, COM_PORT, 101, 0, 1, 0xC2, IAC, IAC, IAC, SE]);
        assert_eq!(s.baud, 0x0001_C2FF);
    }

    /// What only a server should send, and codes nobody defined, are taken without harm.
    #[test]
    fn notifications_and_unknown_codes_are_tolerated() {
        let mut s = Server::default();
        let (_, r) = feed(&mut s, &[IAC, SB, COM_PORT, NOTIFY_MODEMSTATE, IAC, SE]);
        assert_eq!(r, [IAC, SB, COM_PORT, 107, MODEM_STATE, IAC, SE]);
        let (_, r) = feed(&mut s, &[IAC, SB, COM_PORT, 99, 1, IAC, SE, IAC, SB, COM_PORT, IAC, SE]);
        assert!(r.is_empty());
        let (_, r) = feed(&mut s, &[IAC, SB, COM_PORT, SET_CONTROL, 8, IAC, SE]);
        assert_eq!(r, [IAC, SB, COM_PORT, 105, 8, IAC, SE]);
    }
}

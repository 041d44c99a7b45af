//! The served K2's network and serial loops: Modbus TCP, RTU over TCP and RTU on a byte
//! stream (a pty), built so a misbehaving client cannot knock the server over.
//!
//! - Every framed request is decoded by one decoder ([`rtu_frame::decode_pdu`]), so a
//!   malformed one gets the same exception on every transport: 01 for a function the K2
//!   does not implement, 02 for an address outside its areas, 03 for a bad length, byte
//!   count, quantity or value. (tokio-modbus's server skeleton, used before, closed a TCP
//!   connection on an FC 05 with an illegal coil value, dropped unknown functions on RTU
//!   over TCP silently, and panicked in its decoder on an FC 15 whose quantity needs more
//!   bytes than it carries — tokio-modbus 0.17 `codec/mod.rs`, `WriteMultipleCoils`
//!   unpacking; we validate before any of that runs.)
//! - A connection limit ([`Limits::max_connections`]): connections beyond it are accepted
//!   and closed at once, so a client learns at once instead of hanging in the backlog.
//! - An idle timeout: a connection that sends nothing for [`Limits::idle`] is closed.
//! - Running out of file descriptors (EMFILE) or any other accept error never ends the
//!   server: it says so once, waits a moment and accepts again.
//! - Modbus TCP unit id 0xFF is "this device" (libmodbus's default for TCP, where the unit
//!   id addresses nothing), unless [`Limits::unit_ff`] is off.
//! - RTU: silence-based framing (`rtu_frame`'s module doc): when the line is quiet for
//!   [`SILENCE`], whatever could not be taken as a request is dropped, so a bad CRC or a
//!   truncated frame costs that request only.
//!
//! Each connection and each transport runs as its own task, and framing work is linear in
//! the bytes received, so noise on one transport cannot hold up another.

use super::fault::FaultKind;
use super::modbus_server::K2Service;
use super::rtu_frame::{self, Frame};
use crate::core::link::async_pty::AsyncPty;
use std::future::Future;
use std::io;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::Duration;
use tokio::io::{AsyncRead, AsyncReadExt, AsyncWrite, AsyncWriteExt};
use tokio::net::{TcpListener, TcpStream};

/// How long a serial line must be quiet for the bytes received to count as ended
/// (3.5 character times at 9600 baud are 4 ms; a pty has no baud rate, and a client writes
/// a frame in one piece, so a margin for a loaded host).
pub const SILENCE: Duration = Duration::from_millis(15);

/// Longest Modbus TCP frame: the 7-byte MBAP header and a PDU of at most 253 bytes.
const MBAP_MAX: usize = 260;

/// How long a reply may wait for a client that does not read before it is dropped.
pub const WRITE_STALL: Duration = Duration::from_secs(2);

/// What a served transport tolerates.
#[derive(Clone, Copy, Debug)]
pub struct Limits {
    /// Connections served at once; further ones are closed on accept.
    pub max_connections: usize,
    /// A connection silent this long is closed.
    pub idle: Duration,
    /// Answer Modbus TCP requests for unit id 0xFF as this device.
    pub unit_ff: bool,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits { max_connections: 64, idle: Duration::from_secs(300), unit_ff: true }
    }
}

/// Appends the reply PDU to a decoded frame to `out`; false when there is none (another
/// unit, a broadcast, an injected no-reply). With it, the injected fault that acted on it
/// (`k2::sim::fault`) for the transport to finish: a `drop` closes the connection, a
/// `bad-crc` corrupts an RTU reply's CRC.
fn answer(service: &K2Service, unit: u8, frame: &Frame, out: &mut Vec<u8>) -> (bool, Option<FaultKind>) {
    match frame {
        Frame::Request { request, .. } => service.handle_into(unit, request, out),
        Frame::Refuse { function, exception, .. } if unit == service.unit() => {
            out.extend_from_slice(&[function | 0x80, u8::from(*exception)]);
            (true, None)
        }
        Frame::Refuse { .. } => (false, None),
    }
}

/// Accepts connections on `listener` and serves each with `conn` (TCP or RTU framing)
/// within the limits, until the future is dropped.
async fn accept_loop(listener: TcpListener, service: K2Service, limits: Limits, rtu: bool) -> io::Result<()> {
    let active = Arc::new(AtomicUsize::new(0));
    let mut warned = false;
    loop {
        let stream = match listener.accept().await {
            Ok((s, _)) => {
                warned = false;
                s
            }
            Err(e) => {
                // EMFILE, ENFILE, ENOBUFS, ECONNABORTED …: the server stays up.
                if !warned {
                    eprintln!("plcsh sim serve: {}", crate::msg!("k2-serve-accept-retry", error = e.to_string()));
                    warned = true;
                }
                tokio::time::sleep(Duration::from_millis(50)).await;
                continue;
            }
        };
        if active.load(Ordering::SeqCst) >= limits.max_connections {
            drop(stream); // closed at once: the client sees the refusal
            continue;
        }
        let _ = stream.set_nodelay(true);
        active.fetch_add(1, Ordering::SeqCst);
        let (service, active) = (service.clone(), active.clone());
        tokio::spawn(async move {
            let _ = if rtu {
                rtu_stream(stream, service, Some(limits.idle)).await
            } else {
                tcp_conn(stream, service, limits).await
            };
            active.fetch_sub(1, Ordering::SeqCst);
        });
    }
}

/// Serves Modbus TCP on `listener` until the future is dropped.
pub async fn serve_tcp(listener: TcpListener, service: K2Service, limits: Limits) -> io::Result<()> {
    accept_loop(listener, service, limits, false).await
}

/// Serves Modbus RTU frames over TCP (what serial-to-Ethernet gateways in transparent
/// mode carry) on `listener` until the future is dropped.
pub async fn serve_rtu_over_tcp(listener: TcpListener, service: K2Service, limits: Limits) -> io::Result<()> {
    accept_loop(listener, service, limits, true).await
}

/// Serves Modbus RTU on a pseudo-terminal until the future is dropped (framing in
/// [`super::rtu_frame`]).
pub async fn serve_rtu(pty: &AsyncPty, service: K2Service) -> io::Result<()> {
    let s = pty.stream().map_err(|e| io::Error::other(e.to_string()))?;
    serve_rtu_stream(s, service).await
}

/// Serves Modbus RTU frames on any byte stream (a pty, an in-memory pipe in tests) until the
/// stream ends.
pub async fn serve_rtu_stream<S>(s: S, service: K2Service) -> io::Result<()>
where
    S: AsyncRead + AsyncWrite + Unpin,
{
    rtu_stream(s, service, None).await
}

/// One Modbus TCP connection: MBAP header (transaction, protocol 0, length, unit), PDU.
/// Received bytes and the reply are kept in buffers the connection reuses; a request that
/// arrives in one piece is one read.
async fn tcp_conn(mut s: TcpStream, service: K2Service, limits: Limits) -> io::Result<()> {
    let mut rx: Vec<u8> = Vec::with_capacity(2 * MBAP_MAX);
    let mut out: Vec<u8> = Vec::with_capacity(MBAP_MAX);
    // The idle timer is armed once and moved on only when it fires early (a request came
    // meanwhile), so a request costs a clock read, not a timer in the runtime's wheel.
    let mut heard = tokio::time::Instant::now();
    let idle = tokio::time::sleep_until(heard + limits.idle);
    tokio::pin!(idle);
    loop {
        // Frame what has arrived: a whole request, or read more.
        let total = match rx.get(..7) {
            Some(head) => {
                let len = u16::from_be_bytes([head[4], head[5]]) as usize;
                // A length the PDU cannot have, or another protocol: the stream cannot be framed.
                if head[2..4] != [0, 0] || !(2..=254).contains(&len) {
                    return Ok(());
                }
                Some(6 + len).filter(|t| rx.len() >= *t)
            }
            None => None,
        };
        let Some(total) = total else {
            rx.reserve(MBAP_MAX);
            tokio::select! {
                r = s.read_buf(&mut rx) => {
                    if r? == 0 {
                        return Ok(()); // closed
                    }
                    heard = tokio::time::Instant::now();
                }
                () = &mut idle => {
                    if heard.elapsed() >= limits.idle {
                        return Ok(()); // idle: close
                    }
                    idle.as_mut().reset(heard + limits.idle);
                }
            }
            continue;
        };
        let unit = rx[6];
        let as_unit = if unit == 0xFF && limits.unit_ff { service.unit() } else { unit };
        let frame = rtu_frame::decode_pdu(as_unit, &rx[7..total]);
        out.clear();
        out.extend_from_slice(&rx[..7]); // the length is set below
        let (replied, fault) = answer(&service, as_unit, &frame, &mut out);
        rx.drain(..total);
        if fault == Some(FaultKind::Drop) {
            return Ok(()); // the client sees the connection closed instead of a reply
        }
        if replied {
            let len = (out.len() - 6) as u16;
            out[4..6].copy_from_slice(&len.to_be_bytes());
            // A client that stops reading is closed once a reply has waited too long.
            if !write_stalling(&mut s, &out).await? {
                return Ok(());
            }
        }
    }
}

/// Writes `out`, giving up after [`WRITE_STALL`]: `Ok(false)` when it stalled. The write is
/// tried once before a timer is set, so the usual reply (the socket takes it at once) costs
/// no timer.
async fn write_stalling<S: AsyncWrite + Unpin>(s: &mut S, out: &[u8]) -> io::Result<bool> {
    let mut write = std::pin::pin!(s.write_all(out));
    if let std::task::Poll::Ready(r) = std::future::poll_fn(|cx| std::task::Poll::Ready(write.as_mut().poll(cx))).await
    {
        return r.map(|()| true);
    }
    match tokio::time::timeout(WRITE_STALL, write).await {
        Ok(r) => r.map(|()| true),
        Err(_) => Ok(false),
    }
}

/// Serves RTU frames on a byte stream (RTU over TCP, a pty) with silence-based framing;
/// ends when the stream ends or stays silent for `idle` (never, for `None`).
pub async fn rtu_stream<S>(mut s: S, service: K2Service, idle: Option<Duration>) -> io::Result<()>
where
    S: AsyncRead + AsyncWrite + Unpin,
{
    let mut rx = rtu_frame::Receiver::default();
    let mut chunk = [0u8; 512];
    let mut out: Vec<u8> = Vec::with_capacity(rtu_frame::MAX_FRAME);
    loop {
        // Quiet line with bytes pending (or being discarded): the frame has ended.
        let wait = if rx.pending() { Some(SILENCE) } else { idle };
        let read = match wait {
            Some(w) => tokio::time::timeout(w, s.read(&mut chunk)).await,
            None => Ok(s.read(&mut chunk).await),
        };
        let frames = match read {
            Err(_) if !rx.pending() => return Ok(()),
            Err(_) => rx.silence(),
            Ok(Ok(0)) => {
                return Err(io::Error::new(io::ErrorKind::UnexpectedEof, crate::msg!("k2-serve-stream-closed").text))
            }

            Ok(Ok(n)) => rx.bytes(&chunk[..n]),
            Ok(Err(e)) => return Err(e),
        };
        for f in frames {
            let unit = match &f {
                Frame::Request { unit, .. } | Frame::Refuse { unit, .. } => *unit,
            };
            out.clear();
            out.push(unit);
            let (replied, fault) = answer(&service, unit, &f, &mut out);
            if fault == Some(FaultKind::Drop) && idle.is_some() {
                return Ok(()); // RTU over TCP: the connection closes instead of a reply
            }
            if replied {
                let crc = rtu_frame::crc16(&out);
                out.extend_from_slice(&crc.to_le_bytes());
                if fault == Some(FaultKind::BadCrc) {
                    if let Some(last) = out.last_mut() {
                        *last ^= 0xFF;
                    }
                }
                // A client that stops reading fills the line; its replies are dropped after
                // a while rather than holding this transport (or spinning on it).
                let _ = write_stalling(&mut s, &out).await;
            }
        }
    }
}

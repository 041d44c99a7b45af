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
use std::io;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::Duration;
use tokio::io::{AsyncRead, AsyncReadExt, AsyncWrite, AsyncWriteExt};
use tokio::net::{TcpListener, TcpStream};
use tokio_modbus::ExceptionCode;

/// How long a serial line must be quiet for the bytes received to count as ended
/// (3.5 character times at 9600 baud are 4 ms; a pty has no baud rate, and a client writes
/// a frame in one piece, so a margin for a loaded host).
pub const SILENCE: Duration = Duration::from_millis(15);

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

/// The reply to a decoded frame, or `None` (another unit, a broadcast, an injected
/// no-reply), with the injected fault that acted on it (`k2::sim::fault`) for the transport
/// to finish: a `drop` closes the connection, a `bad-crc` corrupts an RTU reply's CRC.
fn answer(service: &K2Service, unit: u8, frame: Frame) -> (Option<Vec<u8>>, Option<FaultKind>) {
    match frame {
        Frame::Request { request, .. } => {
            let function = request.function_code().value();
            let served = service.handle_with_faults(unit, &request);
            (served.reply.map(|r| rtu_frame::encode_pdu(function, &r)), served.fault)
        }
        Frame::Refuse { function, exception, .. } if unit == service.unit() => {
            (Some(rtu_frame::encode_pdu(function, &Err::<tokio_modbus::Response, ExceptionCode>(exception))), None)
        }
        Frame::Refuse { .. } => (None, None),
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
                    eprintln!("plcsh sim serve: cannot accept a connection now ({e}); retrying");
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

/// Serves Modbus TCP on `listener`.
pub async fn serve_tcp(listener: TcpListener, service: K2Service, limits: Limits) -> io::Result<()> {
    accept_loop(listener, service, limits, false).await
}

/// Serves Modbus RTU frames over TCP (a transparent serial gateway) on `listener`.
pub async fn serve_rtu_over_tcp(listener: TcpListener, service: K2Service, limits: Limits) -> io::Result<()> {
    accept_loop(listener, service, limits, true).await
}

/// One Modbus TCP connection: MBAP header (transaction, protocol 0, length, unit), PDU.
async fn tcp_conn(mut s: TcpStream, service: K2Service, limits: Limits) -> io::Result<()> {
    loop {
        let mut head = [0u8; 7];
        match tokio::time::timeout(limits.idle, s.read_exact(&mut head)).await {
            Err(_) => return Ok(()), // idle: close
            Ok(r) => {
                r?;
            }
        }
        let len = u16::from_be_bytes([head[4], head[5]]) as usize;
        // A length the PDU cannot have, or another protocol: the stream cannot be framed.
        if head[2..4] != [0, 0] || !(2..=254).contains(&len) {
            return Ok(());
        }
        let mut pdu = vec![0u8; len - 1];
        match tokio::time::timeout(limits.idle, s.read_exact(&mut pdu)).await {
            Err(_) => return Ok(()),
            Ok(r) => {
                r?;
            }
        }
        let unit = head[6];
        let as_unit = if unit == 0xFF && limits.unit_ff { service.unit() } else { unit };
        let (reply, fault) = answer(&service, as_unit, rtu_frame::decode_pdu(as_unit, &pdu));
        if fault == Some(FaultKind::Drop) {
            return Ok(()); // the client sees the connection closed instead of a reply
        }
        if let Some(reply) = reply {
            let mut out = Vec::with_capacity(7 + reply.len());
            out.extend_from_slice(&head[..4]);
            out.extend_from_slice(&(reply.len() as u16 + 1).to_be_bytes());
            out.push(unit);
            out.extend(reply);
            // A client that stops reading is closed once a reply has waited too long.
            match tokio::time::timeout(WRITE_STALL, s.write_all(&out)).await {
                Ok(r) => r?,
                Err(_) => return Ok(()),
            }
        }
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
            Ok(Ok(0)) => return Err(io::Error::new(io::ErrorKind::UnexpectedEof, "the stream closed")),
            Ok(Ok(n)) => rx.bytes(&chunk[..n]),
            Ok(Err(e)) => return Err(e),
        };
        for f in frames {
            let unit = match &f {
                Frame::Request { unit, .. } | Frame::Refuse { unit, .. } => *unit,
            };
            let (reply, fault) = answer(&service, unit, f);
            if fault == Some(FaultKind::Drop) && idle.is_some() {
                return Ok(()); // RTU over TCP: the connection closes instead of a reply
            }
            if let Some(pdu) = reply {
                let mut out = vec![unit];
                out.extend(pdu);
                out.extend(rtu_frame::crc16(&out).to_le_bytes());
                if fault == Some(FaultKind::BadCrc) {
                    if let Some(last) = out.last_mut() {
                        *last ^= 0xFF;
                    }
                }
                // A client that stops reading fills the line; its replies are dropped after
                // a while rather than holding this transport (or spinning on it).
                let _ = tokio::time::timeout(WRITE_STALL, s.write_all(&out)).await;
            }
        }
    }
}

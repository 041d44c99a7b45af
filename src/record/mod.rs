//! Bus recording (`--record FILE`), the timeline (`plcsh record show`) and replay
//! (`plcsh replay`): what crossed every device link of a session, kept so a problem seen at
//! the machine can be looked at, and replayed, at a desk.
//!
//! Recording hooks [`crate::core::trace`]: every driver already reports each frame there
//! (the K2 wire driver through its [`crate::core::link::traced::Traced`] stream, the servo
//! driver frame by frame), so every device link is covered without a front end's help. The
//! file is pcapng (written with the `pcap-file` crate), the encapsulation is in [`packet`]
//! and documented in docs/recording.md. In-process simulators (`sim:`, the K2 behind no
//! wire) have no frames to record; serve them (`plcsh sim serve`) and connect over Modbus
//! to record their traffic. The servo simulator (`sim-servo:`) runs the real driver over an
//! in-memory line, so its frames are recorded.
//!
//! Each link is one pcapng interface: `if_name` the device name(s), `if_description`
//! `PROTOCOL; LINK` (e.g. `modbus-tcp; tcp://127.0.0.1:502?unit=1&model=K205-16DT`). Each
//! packet carries the wall time as its timestamp (nanoseconds), the direction in
//! `epb_flags` (inbound = from the device) and the session's virtual time in a comment
//! `plcsh vt_us=N`.

pub mod container;
pub mod decode;
pub mod file;
pub mod framing;
pub mod helper;
pub mod layers;
pub mod packet;
pub mod reassembly;
pub mod replay;
pub mod show;

use crate::core::trace::{self, Dir, Proto};
use crate::core::{Clock, Error, Result};
use packet::Segment;
use pcap_file::pcapng::blocks::enhanced_packet::{EnhancedPacketBlock, EnhancedPacketOption};
use pcap_file::pcapng::blocks::interface_description::{InterfaceDescriptionBlock, InterfaceDescriptionOption};
use pcap_file::pcapng::PcapNgWriter;
use pcap_file::DataLink;
use std::borrow::Cow;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

/// The EPB comment prefix that carries virtual time.
pub const VT_PREFIX: &str = "plcsh vt_us=";

/// How often buffered packets reach the file at the latest (and at every connection close).
const FLUSH_EVERY: Duration = Duration::from_millis(200);

struct Tcp {
    port: u16,
    /// Next sequence numbers of plcsh's and the device's side.
    cseq: u32,
    sseq: u32,
}

struct LinkState {
    if_id: u32,
    proto: Proto,
    connections: u32,
    tcp: Option<Tcp>,
    /// Bytes of a frame not yet complete, per direction (0 = sent, 1 = received).
    pending: [Vec<u8>; 2],
}

struct Inner {
    w: PcapNgWriter<BufWriter<File>>,
    /// Links in the order first seen (a handful: a linear search beats hashing the URLs).
    links: Vec<(String, LinkState)>,
    /// Device URL → device name, from the session.
    names: Vec<(String, String)>,
    last_flush: Instant,
    /// Wall time is `wall0` plus the monotonic time since `instant0`: one clock read per frame.
    wall0: Duration,
    instant0: Instant,
    /// The current frame's monotonic time.
    now: Instant,
    /// Reused buffers: the packet being written, its comment.
    packet: Vec<u8>,
    comment: String,
    /// Packets written since the last flush.
    dirty: bool,
    /// [`FileRecorder::finish`] ran.
    finished: bool,
    /// The first write error (recording stops writing then; [`FileRecorder::finish`] reports it).
    error: Option<String>,
}

/// Writes a session's frames to a pcapng file.
pub struct FileRecorder {
    path: String,
    clock: Clock,
    inner: Mutex<Inner>,
}

/// Does the device opened from `url` talk over `link` (a driver's link name)?
fn url_on_link(url: &str, link: &str) -> bool {
    if url == link {
        return true;
    }
    let (scheme, rest) = url.split_once(':').unwrap_or(("", url));
    let target = rest.split('?').next().unwrap_or("").trim_start_matches("//");
    link == target || (target.is_empty() && link == scheme) || link == format!("{scheme}:{target}")
}

impl FileRecorder {
    /// Creates (truncates) `path` and writes the pcapng section header.
    pub fn create(path: &Path, clock: Clock) -> Result<FileRecorder> {
        let f = File::create(path).map_err(|e| {
            Error::io(crate::msg!("record-cannot-create", file = path.display().to_string()))
                .cause(e)
                .hint(crate::msg!("record-hint-writable"))
        })?;
        let w = PcapNgWriter::new(BufWriter::with_capacity(64 * 1024, f))
            .map_err(|e| Error::io(crate::msg!("record-cannot-write", file = path.display().to_string())).cause(e))?;
        Ok(FileRecorder {
            path: path.display().to_string(),
            clock,
            inner: Mutex::new(Inner {
                w,
                links: Vec::new(),
                names: Vec::new(),
                last_flush: Instant::now(),
                wall0: SystemTime::now().duration_since(UNIX_EPOCH).unwrap_or_default(),
                instant0: Instant::now(),
                now: Instant::now(),
                packet: Vec::with_capacity(512),
                comment: String::with_capacity(32),
                dirty: false,
                finished: false,
                error: None,
            }),
        })
    }

    /// Starts recording every frame of this process to `path`. A background thread writes
    /// buffered packets out every 200 ms, so an idle session's last frames reach the file
    /// even if the process is then killed.
    pub fn start(path: &Path, clock: Clock) -> Result<Arc<FileRecorder>> {
        let r = Arc::new(FileRecorder::create(path, clock)?);
        trace::set_recorder(Some(r.clone()));
        let weak = Arc::downgrade(&r);
        let _ = std::thread::Builder::new().name("plcsh-record-flush".into()).spawn(move || loop {
            std::thread::sleep(FLUSH_EVERY);
            let Some(r) = weak.upgrade() else { return };
            let mut i = r.lock();
            if i.finished {
                return;
            }
            if i.dirty {
                i.now = Instant::now();
                i.flush();
            }
        });
        Ok(r)
    }

    /// Names the device opened from `url` (so the capture says `plc`, not the URL).
    pub fn name_device(&self, url: &str, name: &str) {
        let mut i = self.lock();
        i.names.retain(|(u, n)| !(u == url && n == name));
        i.names.push((url.to_string(), name.to_string()));
    }

    /// Stops recording and writes everything out; reports the first write error.
    pub fn finish(&self) -> Result<()> {
        trace::set_recorder(None);
        let mut i = self.lock();
        i.now = Instant::now();
        let links: Vec<String> = i.links.iter().map(|(k, _)| k.clone()).collect();
        for l in links {
            i.flush_pending(&l, 0, self.vt());
            i.flush_pending(&l, 1, self.vt());
        }
        if let Err(e) = i.w.get_mut().flush() {
            i.error.get_or_insert(e.to_string());
        }
        i.finished = true;
        match &i.error {
            Some(e) => {
                Err(Error::io(crate::msg!("record-incomplete", file = self.path.as_str(), error = e.to_string())))
            }
            None => Ok(()),
        }
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Inner> {
        self.inner.lock().unwrap_or_else(|p| p.into_inner())
    }

    fn vt(&self) -> Duration {
        self.clock.now()
    }
}

impl Inner {
    fn get(&mut self, link: &str) -> Option<&mut LinkState> {
        self.links.iter_mut().find(|(k, _)| k == link).map(|(_, l)| l)
    }

    /// Writes the packet in `self.packet`.
    fn write(&mut self, if_id: u32, dir: Option<Dir>, vt: Duration) {
        if self.error.is_some() {
            return;
        }
        let wall = self.wall0 + self.now.saturating_duration_since(self.instant0);
        self.comment.clear();
        use std::fmt::Write as _;
        let _ = write!(self.comment, "{VT_PREFIX}{}", vt.as_micros());
        let mut options = Vec::with_capacity(2);
        options.push(EnhancedPacketOption::Comment(Cow::Borrowed(self.comment.as_str())));
        if let Some(d) = dir {
            // epb_flags bits 0-1: 01 inbound, 10 outbound.
            options.push(EnhancedPacketOption::Flags(if d == Dir::Received { 1 } else { 2 }));
        }
        let epb = EnhancedPacketBlock {
            interface_id: if_id,
            timestamp: wall,
            original_len: self.packet.len() as u32,
            data: Cow::Borrowed(&self.packet),
            options,
        };
        if let Err(e) = self.w.write_pcapng_block(epb) {
            self.error = Some(e.to_string());
        }
        self.dirty = true;
        if self.now.saturating_duration_since(self.last_flush) >= FLUSH_EVERY {
            self.flush();
        }
    }

    fn flush(&mut self) {
        self.last_flush = self.now;
        self.dirty = false;
        if let Err(e) = self.w.get_mut().flush() {
            self.error.get_or_insert(e.to_string());
        }
    }

    /// The link's state, declaring its interface on first sight.
    fn link(&mut self, link: &str, proto: Proto) -> &mut LinkState {
        if let Some(i) = self.links.iter().position(|(k, _)| k == link) {
            return &mut self.links[i].1;
        }
        {
            let if_id = self.links.len() as u32;
            let names: Vec<&str> =
                self.names.iter().filter(|(u, _)| url_on_link(u, link)).map(|(_, n)| n.as_str()).collect();
            let name = if names.is_empty() { link.to_string() } else { names.join(",") };
            let linktype = DataLink::from(packet::linktype(proto));
            let idb = InterfaceDescriptionBlock {
                linktype,
                snaplen: 0xFFFF,
                options: vec![
                    InterfaceDescriptionOption::IfName(Cow::Owned(name)),
                    InterfaceDescriptionOption::IfDescription(Cow::Owned(format!(
                        "{}; {link}",
                        packet::proto_name(proto)
                    ))),
                    // pcap-file writes timestamps in nanoseconds.
                    InterfaceDescriptionOption::IfTsResol(9),
                ],
            };
            if let Err(e) = self.w.write_pcapng_block(idb) {
                self.error.get_or_insert(e.to_string());
            }
            self.links.push((
                link.to_string(),
                LinkState { if_id, proto, connections: 0, tcp: None, pending: [Vec::new(), Vec::new()] },
            ));
        }
        &mut self.links.last_mut().expect("just pushed").1
    }

    /// A TCP segment on a Modbus TCP link, numbers advanced.
    fn segment(&mut self, link: &str, dir: Dir, flags: u8, payload: &[u8], vt: Duration) {
        let l = self.link(link, Proto::ModbusTcp);
        let if_id = l.if_id;
        if l.tcp.is_none() {
            l.connections += 1;
            l.tcp = Some(Tcp { port: 49152 + ((if_id * 97 + l.connections) % 16000) as u16, cseq: 1000, sseq: 5000 });
        }
        let t = l.tcp.as_mut().expect("set above");
        let (src, dst, sport, dport) = match dir {
            Dir::Sent => (packet::CLIENT_IP, packet::server_ip(if_id), t.port, packet::MODBUS_PORT),
            Dir::Received => (packet::server_ip(if_id), packet::CLIENT_IP, packet::MODBUS_PORT, t.port),
        };
        let (seq, ack) = match dir {
            Dir::Sent => (t.cseq, t.sseq),
            Dir::Received => (t.sseq, t.cseq),
        };
        let advance = payload.len() as u32 + u32::from(flags & (packet::TCP_SYN | packet::TCP_FIN) != 0);
        match dir {
            Dir::Sent => t.cseq = t.cseq.wrapping_add(advance),
            Dir::Received => t.sseq = t.sseq.wrapping_add(advance),
        }
        let ack = if flags & packet::TCP_ACK != 0 { ack } else { 0 };
        let s = Segment { src, dst, sport, dport, seq, ack, flags };
        packet::tcp_packet_into(&mut self.packet, &s, payload);
        self.write(if_id, Some(dir), vt);
    }

    /// Writes one frame in its link's encapsulation.
    fn emit(&mut self, link: &str, proto: Proto, dir: Dir, frame: &[u8], vt: Duration) {
        if proto == Proto::ModbusTcp {
            if self.get(link).is_none_or(|l| l.tcp.is_none()) {
                self.handshake(link, vt);
            }
            self.segment(link, dir, packet::TCP_PSH | packet::TCP_ACK, frame, vt);
        } else {
            let if_id = self.link(link, proto).if_id;
            packet::user_packet_into(&mut self.packet, dir, proto, frame);
            self.write(if_id, Some(dir), vt);
        }
    }

    fn handshake(&mut self, link: &str, vt: Duration) {
        self.segment(link, Dir::Sent, packet::TCP_SYN, &[], vt);
        self.segment(link, Dir::Received, packet::TCP_SYN | packet::TCP_ACK, &[], vt);
        self.segment(link, Dir::Sent, packet::TCP_ACK, &[], vt);
    }

    /// Writes out whatever is pending in one direction as one frame.
    fn flush_pending(&mut self, link: &str, side: usize, vt: Duration) {
        let Some(l) = self.get(link) else { return };
        if l.pending[side].is_empty() {
            return;
        }
        let proto = l.proto;
        let bytes = std::mem::take(&mut l.pending[side]);
        let dir = if side == 0 { Dir::Sent } else { Dir::Received };
        self.emit(link, proto, dir, &bytes, vt);
    }

    fn frame(&mut self, link: &str, proto: Proto, dir: Dir, bytes: &[u8], vt: Duration) {
        let side = usize::from(dir == Dir::Received);
        if dir == Dir::Sent {
            // A new request: what came back before it is complete, whatever its shape.
            self.flush_pending(link, 1, vt);
        }
        let l = self.link(link, proto);
        if l.pending[side].is_empty() && framing::frame_end(proto, dir == Dir::Sent, bytes) == Some(bytes.len()) {
            // The usual case: one whole frame.
            self.emit(link, proto, dir, bytes, vt);
            return;
        }
        let l = self.link(link, proto);
        l.pending[side].extend_from_slice(bytes);
        while let Some(l) = self.get(link) {
            let Some(end) = framing::frame_end(proto, dir == Dir::Sent, &l.pending[side]) else { break };
            if end == 0 {
                break;
            }
            let frame: Vec<u8> = l.pending[side].drain(..end).collect();
            self.emit(link, proto, dir, &frame, vt);
        }
    }
}

impl trace::Recorder for FileRecorder {
    fn opened(&self, link: &str, proto: Proto, _peer: &str) {
        let vt = self.vt();
        let mut i = self.lock();
        i.now = Instant::now();
        let l = i.link(link, proto);
        if proto == Proto::ModbusTcp && l.tcp.is_none() {
            i.handshake(link, vt);
        }
    }

    fn frame(&self, link: &str, proto: Proto, dir: Dir, bytes: &[u8]) {
        let vt = self.vt();
        let mut i = self.lock();
        i.now = Instant::now();
        i.frame(link, proto, dir, bytes, vt);
    }

    fn closed(&self, link: &str) {
        let vt = self.vt();
        let mut i = self.lock();
        i.now = Instant::now();
        i.flush_pending(link, 0, vt);
        i.flush_pending(link, 1, vt);
        let is_tcp = i.get(link).is_some_and(|l| l.tcp.is_some());
        if is_tcp {
            let fin = packet::TCP_FIN | packet::TCP_ACK;
            i.segment(link, Dir::Sent, fin, &[], vt);
            i.segment(link, Dir::Received, fin, &[], vt);
            i.segment(link, Dir::Sent, packet::TCP_ACK, &[], vt);
            if let Some(l) = i.get(link) {
                l.tcp = None;
            }
        }
        i.flush();
    }

    fn named(&self, url: &str, name: &str) {
        self.name_device(url, name);
    }
}

/// The recorder of this process, while one runs (`--record`).
fn current() -> &'static Mutex<Option<Arc<FileRecorder>>> {
    static C: std::sync::OnceLock<Mutex<Option<Arc<FileRecorder>>>> = std::sync::OnceLock::new();
    C.get_or_init(|| Mutex::new(None))
}

/// Starts recording to `path` (`--record FILE`).
pub fn start(path: &Path, clock: Clock) -> Result<()> {
    let r = FileRecorder::start(path, clock)?;
    *current().lock().unwrap_or_else(|p| p.into_inner()) = Some(r);
    Ok(())
}

/// Stops the recording started with [`start`], writing everything out.
pub fn stop() -> Result<()> {
    let r = current().lock().unwrap_or_else(|p| p.into_inner()).take();
    r.map_or(Ok(()), |r| r.finish())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn device_urls_match_their_links() {
        assert!(url_on_link("tcp://127.0.0.1:502?unit=1", "tcp://127.0.0.1:502?unit=1"));
        assert!(url_on_link("sim-servo:?id=1", "sim-servo"));
        assert!(url_on_link("sim-servo:axes?id=2", "sim-servo:axes"));
        assert!(url_on_link("kinco:/dev/ttyUSB0?id=1", "/dev/ttyUSB0"));
        assert!(!url_on_link("kinco:/dev/ttyUSB1?id=1", "/dev/ttyUSB0"));
    }
}

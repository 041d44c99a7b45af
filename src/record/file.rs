//! Reading a recording back: the frames of every link in file order, with direction, wall
//! time and virtual time, the encapsulation taken off. The file may be plcsh's own
//! (docs/recording.md) or a capture another tool took on the wire (tshark, tcpdump,
//! Wireshark; pcapng or classic pcap): [`super::container`] reads the blocks (and skips
//! damage, naming its offset), [`super::layers`] takes each packet apart down to TCP, and
//! [`super::reassembly`] puts each direction of each connection back in order and cuts it
//! into Modbus frames.
//!
//! In a capture plcsh did not write, every server endpoint (address and port) is one link.
//! Which side is the server: port 502 if one side has it, else the side the connection's
//! first SYN went to, else an endpoint already known as a server, else the side the first
//! payload went to (the first request). The link is Modbus TCP unless its first request is
//! no MBAP frame but a whole RTU frame with a valid CRC (an RTU-over-TCP gateway).

use super::container::{self, Capture};
use super::layers::{self, Layers};
use super::packet::{self, parse_user};
use super::reassembly::Stream;
use crate::core::trace::{Dir, Proto};
use crate::core::{Error, Result};
use std::collections::HashMap;
use std::net::{IpAddr, SocketAddr};
use std::path::Path;
use std::time::Duration;

/// One recorded link (a pcapng interface, or a server endpoint in a foreign capture).
#[derive(Clone, Debug, PartialEq)]
pub struct LinkInfo {
    /// Device name(s) (`plc`, `ax1,ax2`), or the link when no device was named.
    pub name: String,
    pub proto: Proto,
    /// The driver's link: for K2 devices the URL they were opened with.
    pub link: String,
}

/// One recorded frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// Index into [`Recording::links`].
    pub link: usize,
    pub dir: Dir,
    /// Wall time since the Unix epoch.
    pub wall: Duration,
    /// The session's virtual time, when recorded.
    pub vt: Option<Duration>,
    /// The frame as on the wire (an MBAP frame for Modbus TCP, an RTU frame, a servo frame).
    pub bytes: Vec<u8>,
}

#[derive(Clone, Debug, Default, PartialEq)]
pub struct Recording {
    pub links: Vec<LinkInfo>,
    pub frames: Vec<Frame>,
    /// Why reading stopped before the end (a file cut short by a killed process): the
    /// frames before that point are kept.
    pub truncated: Option<String>,
    /// Damaged regions skipped in the middle of the file, each with its byte offsets: the
    /// frames before and after them are kept.
    pub damaged: Vec<String>,
    /// What else a reader should know (bytes a capture missed).
    pub notes: Vec<String>,
}

/// Reads a recording.
pub fn read(path: &Path) -> Result<Recording> {
    let bytes = std::fs::read(path).map_err(|e| {
        Error::io(crate::msg!("record-cannot-read", file = path.display().to_string()))
            .cause(e)
            .hint(crate::msg!("record-hint-give-file"))
    })?;
    parse(&bytes).map_err(|m| {
        Error::usage(crate::msg!("record-not-readable", file = path.display().to_string(), error = m))
            .hint(crate::msg!("record-hint-capture"))
    })
}

/// What one interface carries.
enum Kind {
    /// plcsh's own link (or a USER link): one link, the index.
    Link(usize),
    /// Foreign IP traffic: links per server endpoint.
    Ip,
    /// A link type plcsh does not read.
    Unreadable,
}

/// A connection in a foreign capture: the client side, the link, each direction's stream.
struct Conn {
    link: usize,
    client: SocketAddr,
    streams: [Stream; 2],
}

struct Reader {
    rec: Recording,
    /// Server endpoints seen, with their links (a handful: searched linearly).
    servers: HashMap<SocketAddr, usize>,
    conns: Vec<(SocketAddr, SocketAddr, Conn)>,
    /// Each connection's index in `conns`, by its two ends (the smaller first).
    by_ends: HashMap<(SocketAddr, SocketAddr), usize>,
    /// Packets the capture's snap length cut short.
    cut: usize,
}

/// Parses a capture's bytes (pcapng or pcap).
pub fn parse(bytes: &[u8]) -> std::result::Result<Recording, String> {
    let cap = container::parse(bytes)?;
    let mut r = Reader {
        rec: Recording::default(),
        servers: HashMap::new(),
        conns: Vec::new(),
        by_ends: HashMap::new(),
        cut: 0,
    };
    r.rec.truncated = cap.truncated.clone();
    r.rec.damaged = cap.damaged.clone();
    let kinds: Vec<Kind> = cap.interfaces.iter().map(|i| r.interface(i)).collect();
    for (n, p) in cap.packets.iter().enumerate() {
        let vt = p
            .comments
            .iter()
            .find_map(|c| c.strip_prefix(super::VT_PREFIX).and_then(|n| n.parse::<u64>().ok()))
            .map(Duration::from_micros);
        let flags_dir = match p.flags.map(|f| f & 3) {
            Some(1) => Some(Dir::Received),
            Some(2) => Some(Dir::Sent),
            _ => None,
        };
        let iface = &cap.interfaces[p.iface];
        let lt = iface.linktype;
        match kinds[p.iface] {
            Kind::Unreadable => {
                return Err(unreadable(&cap, n, p.iface));
            }
            Kind::Link(link) if packet::is_user(lt) => {
                let Some((dir, proto, frame)) = parse_user(p.data) else { continue };
                let l = &mut r.rec.links[link];
                if l.proto == Proto::Unknown {
                    // No description: the header's protocol byte, else the link type's.
                    l.proto = if proto == Proto::Unknown { packet::proto_of_linktype(lt) } else { proto };
                }
                r.rec.frames.push(Frame { link, dir, wall: p.ts, vt, bytes: frame.to_vec() });
            }
            ref k => {
                let own = if let Kind::Link(l) = k { Some(*l) } else { None };
                if let Some(Layers::Tcp(t)) = layers::tcp(lt, p.data) {
                    r.cut += usize::from(t.cut);
                    r.segment(&t, own, flags_dir, p.ts, vt);
                }
            }
        }
    }
    r.finish();
    if r.cut > 0 {
        r.rec.notes.push(crate::msg!("record-snap-length", count = r.cut).text);
    }
    if r.rec.frames.is_empty() && !cap.packets.is_empty() && kinds.iter().any(|k| matches!(k, Kind::Ip)) {
        return Err(crate::msg!("record-no-tcp", count = cap.packets.len()).text);
    }
    Ok(r.rec)
}

/// The refusal for a packet on an interface whose link type plcsh does not read.
fn unreadable(cap: &Capture<'_>, n: usize, iface: usize) -> String {
    let i = &cap.interfaces[iface];
    let known: Vec<&str> = layers::IP_LINKTYPES.iter().map(|(_, n)| *n).collect();
    format!(
        "packet {} (block at offset {}) is on interface {iface} (described at offset {}) with link type {}, \
         which plcsh does not read; it reads {}, and USER0…USER15 as plcsh writes them",
        n + 1,
        cap.packets[n].offset,
        i.offset,
        i.linktype,
        known.join(", ")
    )
}

impl Reader {
    fn interface(&mut self, i: &container::Interface) -> Kind {
        let (proto, link) = match i.description.split_once("; ") {
            Some((p, l)) if packet::proto_of_name(p) != Proto::Unknown || p == "raw" => {
                (Some(packet::proto_of_name(p)), l.to_string())
            }
            _ => (None, i.description.clone()),
        };
        let ip = layers::IP_LINKTYPES.iter().any(|(t, _)| *t == i.linktype);
        if packet::is_user(i.linktype) || (ip && proto.is_some()) {
            // Without a description the first packet's header says (see `parse`).
            let proto = if ip { Proto::ModbusTcp } else { proto.unwrap_or(Proto::Unknown) };
            let name = if i.name.is_empty() { format!("if{}", self.rec.links.len()) } else { i.name.clone() };
            self.rec.links.push(LinkInfo { name, proto, link });
            return Kind::Link(self.rec.links.len() - 1);
        }
        if ip {
            Kind::Ip
        } else {
            Kind::Unreadable
        }
    }

    /// The link of a foreign server endpoint, made on first sight.
    fn server_link(&mut self, server: SocketAddr, first: &[u8]) -> usize {
        if let Some(l) = self.servers.get(&server) {
            return *l;
        }
        let mbap = first.len() >= 7 && first[2..4] == [0, 0];
        let rtu = first.len() >= 4 && {
            let n = first.len();
            crate::k2::sim::rtu_frame::crc16(&first[..n - 2]) == u16::from_le_bytes([first[n - 2], first[n - 1]])
        };
        let proto = if !mbap && rtu { Proto::RtuOverTcp } else { Proto::ModbusTcp };
        let host = match server.ip() {
            IpAddr::V6(a) => format!("[{a}]"),
            a => a.to_string(),
        };
        let name = format!("{host}:{}", server.port());
        let scheme = if proto == Proto::RtuOverTcp { "rtu-tcp" } else { "tcp" };
        self.rec.links.push(LinkInfo { link: format!("{scheme}://{name}"), name, proto });
        self.servers.insert(server, self.rec.links.len() - 1);
        self.rec.links.len() - 1
    }

    fn segment(
        &mut self,
        t: &layers::Tcp<'_>,
        own: Option<usize>,
        flags_dir: Option<Dir>,
        wall: Duration,
        vt: Option<Duration>,
    ) {
        let src = SocketAddr::new(t.src, t.sport);
        let dst = SocketAddr::new(t.dst, t.dport);
        // The connection, either way round.
        let ends = if src < dst { (src, dst) } else { (dst, src) };
        let found = self.by_ends.get(&ends).copied();
        let syn = t.flags & layers::TCP_SYN != 0;
        let ci = match found {
            Some(ci) if !(syn && t.flags & layers::TCP_ACK == 0) => ci,
            _ => {
                // A new connection (or the same ports reused by a new SYN).
                if t.payload.is_empty() && !syn {
                    return;
                }
                let known = |s: &SocketAddr| self.servers.contains_key(s);
                let to_server = match flags_dir {
                    Some(d) => d == Dir::Sent,
                    None if t.dport == packet::MODBUS_PORT && t.sport != packet::MODBUS_PORT => true,
                    None if t.sport == packet::MODBUS_PORT && t.dport != packet::MODBUS_PORT => false,
                    None if syn => t.flags & layers::TCP_ACK == 0,
                    None if known(&dst) => true,
                    None if known(&src) => false,
                    None => true,
                };
                let (client, server) = if to_server { (src, dst) } else { (dst, src) };
                let link = match own {
                    Some(l) => l,
                    None => self.server_link(server, if to_server { t.payload } else { &[] }),
                };
                let conn = Conn { link, client, streams: [Stream::default(), Stream::default()] };
                match found {
                    Some(ci) => {
                        self.close(ci, wall, vt);
                        self.conns[ci] = (client, server, conn);
                        ci
                    }
                    None => {
                        self.conns.push((client, server, conn));
                        self.by_ends.insert(ends, self.conns.len() - 1);
                        self.conns.len() - 1
                    }
                }
            }
        };
        let (client, link) = (self.conns[ci].2.client, self.conns[ci].2.link);
        let dir = if src == client { Dir::Sent } else { Dir::Received };
        let side = usize::from(dir == Dir::Received);
        let proto = self.rec.links[link].proto;
        if syn {
            self.conns[ci].2.streams[side].syn(t.seq);
        }
        let mut out = Vec::new();
        let conn = &mut self.conns[ci].2;
        conn.streams[side].push(t.seq, t.payload, proto, dir == Dir::Sent, &mut out);
        if dir == Dir::Sent && !out.is_empty() {
            // A new request: what came back before it is complete, whatever its shape.
            let mut replies = Vec::new();
            conn.streams[1].flush(&mut replies);
            self.emit(link, Dir::Received, replies, wall, vt);
        }
        self.emit(link, dir, out, wall, vt);
        if t.flags & (layers::TCP_FIN | layers::TCP_RST) != 0 {
            let mut rest = Vec::new();
            self.conns[ci].2.streams[side].finish(proto, dir == Dir::Sent, &mut rest);
            self.emit(link, dir, rest, wall, vt);
        }
    }

    fn emit(&mut self, link: usize, dir: Dir, frames: Vec<Vec<u8>>, wall: Duration, vt: Option<Duration>) {
        for bytes in frames {
            self.rec.frames.push(Frame { link, dir, wall, vt, bytes });
        }
    }

    /// Flushes a connection's streams (at its end, or the end of the capture).
    fn close(&mut self, ci: usize, wall: Duration, vt: Option<Duration>) {
        let link = self.conns[ci].2.link;
        let proto = self.rec.links[link].proto;
        for (side, dir) in [(0, Dir::Sent), (1, Dir::Received)] {
            let mut out = Vec::new();
            let s = &mut self.conns[ci].2.streams[side];
            s.finish(proto, dir == Dir::Sent, &mut out);
            let lost = std::mem::take(&mut s.lost);
            if lost > 0 {
                let (c, sv) = (self.conns[ci].0, self.conns[ci].1);
                let (from, to) = if side == 0 { (c, sv) } else { (sv, c) };
                self.rec.notes.push(
                    crate::msg!("record-bytes-missing", lost = lost, from = from.to_string(), to = to.to_string()).text,
                );
            }
            self.emit(link, dir, out, wall, vt);
        }
    }

    fn finish(&mut self) {
        let (wall, vt) = self.rec.frames.last().map_or((Duration::ZERO, None), |f| (f.wall, f.vt));
        for ci in 0..self.conns.len() {
            self.close(ci, wall, vt);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::trace::Recorder;
    use crate::core::Clock;

    #[test]
    fn a_file_cut_short_keeps_the_frames_before_the_cut() {
        let path = std::env::temp_dir().join(format!("plcsh-cut-{}.pcapng", std::process::id()));
        let r = super::super::FileRecorder::create(&path, Clock::stepped()).unwrap();
        r.name_device("rtu:/dev/x", "plc");
        for k in 0..3u8 {
            r.frame("/dev/x", Proto::ModbusRtu, Dir::Sent, &[1, 3, 0, k, 0, 1, 0, 0]);
        }
        r.finish().unwrap();
        let bytes = std::fs::read(&path).unwrap();
        let whole = parse(&bytes).unwrap();
        assert_eq!((whole.frames.len(), whole.truncated.clone()), (3, None));
        assert_eq!(whole.links[0].name, "plc");
        assert_eq!(whole.links[0].proto, Proto::ModbusRtu);
        let cut = parse(&bytes[..bytes.len() - 10]).unwrap();
        assert_eq!(cut.frames.len(), 2);
        assert!(cut.truncated.is_some());
        assert_eq!(cut.frames[1].bytes, vec![1, 3, 0, 1, 0, 1, 0, 0]);
        let _ = std::fs::remove_file(&path);
    }
}

//! Reading a recording back: the frames of every link in file order, with direction, wall
//! time and virtual time, the encapsulation ([`super::packet`]) taken off. TCP packets
//! without payload (handshakes, FINs) are skipped. Files from other tools are read too as
//! far as they use the same encapsulations (their timestamps are then taken as nanoseconds,
//! which is what `pcap-file` reads).

use super::packet::{self, parse_tcp, parse_user};
use crate::core::trace::{Dir, Proto};
use crate::core::{Error, Result};
use pcap_file::pcapng::blocks::enhanced_packet::EnhancedPacketOption;
use pcap_file::pcapng::blocks::interface_description::InterfaceDescriptionOption;
use pcap_file::pcapng::{Block, PcapNgReader};
use pcap_file::DataLink;
use std::path::Path;
use std::time::Duration;

/// One recorded link (a pcapng interface).
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
}

/// Reads a recording.
pub fn read(path: &Path) -> Result<Recording> {
    let bytes = std::fs::read(path).map_err(|e| {
        Error::io(format!("cannot read the recording {}", path.display()))
            .cause(e)
            .hint("give the file written by --record FILE")
    })?;
    parse(&bytes).map_err(|m| {
        Error::usage(format!("{} is not a readable pcapng recording: {m}", path.display()))
            .hint("recordings are written by plcsh --record FILE (pcapng)")
    })
}

/// Parses pcapng bytes.
pub fn parse(bytes: &[u8]) -> std::result::Result<Recording, String> {
    let mut r = PcapNgReader::new(bytes).map_err(|e| e.to_string())?;
    let mut rec = Recording::default();
    // Interface ids restart with every section; map them to links.
    let mut ifaces: Vec<(usize, DataLink)> = Vec::new();
    while let Some(block) = r.next_block() {
        let block = match block {
            Ok(b) => b,
            Err(e) => {
                rec.truncated = Some(e.to_string());
                break;
            }
        };
        match block {
            Block::SectionHeader(_) => ifaces.clear(),
            Block::InterfaceDescription(idb) => {
                let mut name = String::new();
                let mut desc = String::new();
                for o in &idb.options {
                    match o {
                        InterfaceDescriptionOption::IfName(n) => name = n.to_string(),
                        InterfaceDescriptionOption::IfDescription(d) => desc = d.to_string(),
                        _ => {}
                    }
                }
                let (proto, link) = match desc.split_once("; ") {
                    Some((p, l)) => (packet::proto_of_name(p), l.to_string()),
                    None => (Proto::Unknown, desc.clone()),
                };
                let proto = if idb.linktype == DataLink::ETHERNET { Proto::ModbusTcp } else { proto };
                if name.is_empty() {
                    name = format!("if{}", rec.links.len());
                }
                ifaces.push((rec.links.len(), idb.linktype));
                rec.links.push(LinkInfo { name, proto, link });
            }
            Block::EnhancedPacket(epb) => {
                let Some(&(link, linktype)) = ifaces.get(epb.interface_id as usize) else {
                    return Err(format!("a packet names interface {} that was not described", epb.interface_id));
                };
                let mut vt = None;
                let mut flags_dir = None;
                for o in &epb.options {
                    match o {
                        EnhancedPacketOption::Comment(c) => {
                            vt = c
                                .strip_prefix(super::VT_PREFIX)
                                .and_then(|n| n.parse::<u64>().ok())
                                .map(Duration::from_micros)
                        }
                        EnhancedPacketOption::Flags(f) => {
                            flags_dir = match f & 3 {
                                1 => Some(Dir::Received),
                                2 => Some(Dir::Sent),
                                _ => None,
                            }
                        }
                        _ => {}
                    }
                }
                let data: &[u8] = &epb.data;
                let (dir, bytes) = if linktype == DataLink::ETHERNET {
                    let Some((seg, payload)) = parse_tcp(data) else { continue };
                    if payload.is_empty() {
                        continue;
                    }
                    let dir =
                        flags_dir.unwrap_or(if seg.dport == packet::MODBUS_PORT { Dir::Sent } else { Dir::Received });
                    (dir, payload.to_vec())
                } else {
                    let Some((dir, _proto, frame)) = parse_user(data) else { continue };
                    (dir, frame.to_vec())
                };
                rec.frames.push(Frame { link, dir, wall: epb.timestamp, vt, bytes });
            }
            _ => {}
        }
    }
    Ok(rec)
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

//! Packet encapsulation for recordings (docs/recording.md), pure: frames in, capture bytes
//! out, and back.
//!
//! - Modbus TCP frames become Ethernet II / IPv4 / TCP packets to port 502, so Wireshark and
//!   tshark decode them as Modbus/TCP without configuration. Addresses are synthetic
//!   (plcsh 10.0.0.1, the device 10.0.1.N, N = the link's interface number + 1; the real
//!   address is in the interface description); sequence and acknowledgement numbers follow
//!   the bytes sent, with a handshake when a connection opens and FINs when it closes, and
//!   the IPv4 and TCP checksums are correct.
//! - Every other link is recorded under a LINKTYPE_USERn of its own ([`PROTO_LINKTYPES`]:
//!   USER0 Modbus RTU, USER1 RTU over TCP, USER2 Kinco servo RS232, USER3 UMPK, USER4 FX
//!   programming port, USER5 FX computer link, USER15 undeclared), so Wireshark hands each to
//!   its own dissector (lib/wireshark/), with a 4-byte header before the frame bytes:
//!   `[direction, protocol, 0, 0]`, direction 0 = sent by plcsh, 1 = received; the protocol
//!   codes of [`proto_code`].

use crate::core::trace::{Dir, Proto};

/// LINKTYPE_USER0.
pub const LINKTYPE_USER0: u32 = 147;
/// The USER link type each protocol is written with (docs/recording.md).
/// Wireshark tells them apart by link type: each gets its own dissector (lib/wireshark/).
pub const PROTO_LINKTYPES: &[(Proto, u32)] = &[
    (Proto::ModbusRtu, LINKTYPE_USER0),
    (Proto::RtuOverTcp, LINKTYPE_USER0 + 1),
    (Proto::KincoServo, LINKTYPE_USER0 + 2),
    (Proto::Umpk, LINKTYPE_USER0 + 3),
    (Proto::FxPort, LINKTYPE_USER0 + 4),
    (Proto::FxLink, LINKTYPE_USER0 + 5),
    (Proto::Unknown, LINKTYPE_USER0 + 15),
];

/// The link type frames of `p` are written with: Ethernet for Modbus TCP, else its USER type.
pub fn linktype(p: Proto) -> u32 {
    if p == Proto::ModbusTcp {
        return 1;
    }
    PROTO_LINKTYPES.iter().find(|(q, _)| *q == p).map_or(LINKTYPE_USER0 + 15, |(_, t)| *t)
}

/// Length of the USER per-packet header.
pub const USER_HEADER: usize = 4;
/// The Modbus/TCP port every synthetic device listens on.
pub const MODBUS_PORT: u16 = 502;

pub const TCP_FIN: u8 = 0x01;
pub const TCP_SYN: u8 = 0x02;
pub const TCP_PSH: u8 = 0x08;
pub const TCP_ACK: u8 = 0x10;

/// plcsh's side of every synthetic connection.
pub const CLIENT_IP: [u8; 4] = [10, 0, 0, 1];

/// The device's synthetic address for interface `if_id`.
pub fn server_ip(if_id: u32) -> [u8; 4] {
    let n = if_id + 1;
    [10, 0, 1 + (n / 250) as u8, (n % 250) as u8]
}

pub fn proto_code(p: Proto) -> u8 {
    match p {
        Proto::Unknown => 0,
        Proto::ModbusRtu => 1,
        Proto::RtuOverTcp => 2,
        Proto::KincoServo => 3,
        Proto::ModbusTcp => 4,
        Proto::Umpk => 5,
        Proto::FxPort => 6,
        Proto::FxLink => 7,
    }
}

pub fn proto_of_code(c: u8) -> Proto {
    match c {
        1 => Proto::ModbusRtu,
        2 => Proto::RtuOverTcp,
        3 => Proto::KincoServo,
        4 => Proto::ModbusTcp,
        5 => Proto::Umpk,
        6 => Proto::FxPort,
        7 => Proto::FxLink,
        _ => Proto::Unknown,
    }
}

/// The name of a protocol in interface descriptions and `record show --json`.
pub fn proto_name(p: Proto) -> &'static str {
    match p {
        Proto::Unknown => "raw",
        Proto::ModbusTcp => "modbus-tcp",
        Proto::ModbusRtu => "modbus-rtu",
        Proto::RtuOverTcp => "modbus-rtu-over-tcp",
        Proto::KincoServo => "kinco-servo",
        Proto::Umpk => "umpk",
        Proto::FxPort => "fx-port",
        Proto::FxLink => "fx-link",
    }
}

pub fn proto_of_name(s: &str) -> Proto {
    [
        Proto::ModbusTcp,
        Proto::ModbusRtu,
        Proto::RtuOverTcp,
        Proto::KincoServo,
        Proto::Umpk,
        Proto::FxPort,
        Proto::FxLink,
    ]
    .into_iter()
    .find(|p| proto_name(*p) == s)
    .unwrap_or(Proto::Unknown)
}

/// A USER packet: the header, then the frame.
pub fn user_packet(dir: Dir, proto: Proto, frame: &[u8]) -> Vec<u8> {
    let mut p = Vec::with_capacity(USER_HEADER + frame.len());
    user_packet_into(&mut p, dir, proto, frame);
    p
}

/// [`user_packet`] into a reused buffer.
pub fn user_packet_into(p: &mut Vec<u8>, dir: Dir, proto: Proto, frame: &[u8]) {
    p.clear();
    p.extend_from_slice(&[u8::from(dir == Dir::Received), proto_code(proto), 0, 0]);
    p.extend_from_slice(frame);
}

/// Is `linktype` one of LINKTYPE_USER0…USER15 (147…162)?
pub fn is_user(linktype: u32) -> bool {
    (LINKTYPE_USER0..LINKTYPE_USER0 + 16).contains(&linktype)
}

/// The protocol a USER link type stands for (docs/recording.md); USER0 also held every
/// protocol in older recordings, told apart by the header's protocol byte.
pub fn proto_of_linktype(linktype: u32) -> Proto {
    PROTO_LINKTYPES.iter().find(|(_, t)| *t == linktype).map_or(Proto::Unknown, |(p, _)| *p)
}

/// Splits a USER0 packet; `None` when it is too short to hold the header.
pub fn parse_user(packet: &[u8]) -> Option<(Dir, Proto, &[u8])> {
    if packet.len() < USER_HEADER {
        return None;
    }
    let dir = if packet[0] == 0 { Dir::Sent } else { Dir::Received };
    Some((dir, proto_of_code(packet[1]), &packet[USER_HEADER..]))
}

/// One TCP segment's addressing and numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Segment {
    pub src: [u8; 4],
    pub dst: [u8; 4],
    pub sport: u16,
    pub dport: u16,
    pub seq: u32,
    pub ack: u32,
    pub flags: u8,
}

fn sum16(data: &[u8], mut acc: u32) -> u32 {
    for c in data.chunks(2) {
        acc += u32::from(u16::from_be_bytes([c[0], *c.get(1).unwrap_or(&0)]));
    }
    acc
}

fn fold(mut acc: u32) -> u16 {
    while acc > 0xFFFF {
        acc = (acc & 0xFFFF) + (acc >> 16);
    }
    !(acc as u16)
}

/// An Ethernet II / IPv4 / TCP packet carrying `payload`, checksums filled in.
pub fn tcp_packet(s: &Segment, payload: &[u8]) -> Vec<u8> {
    let mut p = Vec::with_capacity(54 + payload.len());
    tcp_packet_into(&mut p, s, payload);
    p
}

/// [`tcp_packet`] into a reused buffer.
pub fn tcp_packet_into(p: &mut Vec<u8>, s: &Segment, payload: &[u8]) {
    let mac = |ip: [u8; 4]| [0x02, 0x00, ip[0], ip[1], ip[2], ip[3]];
    p.clear();
    p.extend_from_slice(&mac(s.dst));
    p.extend_from_slice(&mac(s.src));
    p.extend_from_slice(&[0x08, 0x00]);
    // IPv4 header, 20 bytes, DF set, TTL 64, protocol 6.
    let total = (20 + 20 + payload.len()) as u16;
    let mut ip = [0u8; 20];
    ip[0] = 0x45;
    ip[2..4].copy_from_slice(&total.to_be_bytes());
    ip[6] = 0x40;
    ip[8] = 64;
    ip[9] = 6;
    ip[12..16].copy_from_slice(&s.src);
    ip[16..20].copy_from_slice(&s.dst);
    let c = fold(sum16(&ip, 0));
    ip[10..12].copy_from_slice(&c.to_be_bytes());
    p.extend_from_slice(&ip);
    // TCP header, 20 bytes, window 65535.
    let mut tcp = [0u8; 20];
    tcp[0..2].copy_from_slice(&s.sport.to_be_bytes());
    tcp[2..4].copy_from_slice(&s.dport.to_be_bytes());
    tcp[4..8].copy_from_slice(&s.seq.to_be_bytes());
    tcp[8..12].copy_from_slice(&s.ack.to_be_bytes());
    tcp[12] = 5 << 4;
    tcp[13] = s.flags;
    tcp[14..16].copy_from_slice(&0xFFFFu16.to_be_bytes());
    let mut pseudo = [0u8; 12];
    pseudo[0..4].copy_from_slice(&s.src);
    pseudo[4..8].copy_from_slice(&s.dst);
    pseudo[9] = 6;
    pseudo[10..12].copy_from_slice(&((20 + payload.len()) as u16).to_be_bytes());
    let mut acc = sum16(&pseudo, 0);
    acc = sum16(&tcp, acc);
    // An odd last byte is summed as if padded with a zero (RFC 793), as `sum16` does.
    acc = sum16(payload, acc);
    tcp[16..18].copy_from_slice(&fold(acc).to_be_bytes());
    p.extend_from_slice(&tcp);
    p.extend_from_slice(payload);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tcp_packets_round_trip_with_valid_checksums() {
        let s = Segment {
            src: CLIENT_IP,
            dst: server_ip(0),
            sport: 49153,
            dport: 502,
            seq: 1001,
            ack: 5001,
            flags: TCP_PSH | TCP_ACK,
        };
        let payload = [0, 1, 0, 0, 0, 6, 1, 3, 0, 100, 0, 2];
        let p = tcp_packet(&s, &payload);
        assert_eq!(p.len(), 14 + 20 + 20 + payload.len());
        // A header with its checksum in place sums to zero (RFC 1071).
        assert_eq!(fold(sum16(&p[14..34], 0)), 0, "IPv4 header checksum");
        let mut pseudo = Vec::new();
        pseudo.extend_from_slice(&p[26..34]);
        pseudo.extend_from_slice(&[0, 6, 0, (20 + payload.len()) as u8]);
        assert_eq!(fold(sum16(&p[34..], sum16(&pseudo, 0))), 0, "TCP checksum");
        let Some(crate::record::layers::Layers::Tcp(t)) = crate::record::layers::tcp(1, &p) else { panic!() };
        assert_eq!((t.sport, t.dport, t.seq, t.flags), (s.sport, s.dport, s.seq, s.flags));
        assert_eq!(t.payload, payload);
    }

    #[test]
    fn hostile_packets_are_refused_not_panicked_on() {
        for n in 0..80 {
            let junk: Vec<u8> = (0..n).map(|i| (i * 37 + 11) as u8).collect();
            let _ = parse_user(&junk);
        }
        let u = user_packet(Dir::Received, Proto::KincoServo, &[1, 2]);
        assert_eq!(parse_user(&u), Some((Dir::Received, Proto::KincoServo, &[1u8, 2][..])));
    }
}

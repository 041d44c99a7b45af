//! Taking a captured packet apart down to its TCP segment, for captures any tool wrote:
//! the link layers tshark and tcpdump write (Ethernet II with VLAN tags, Linux cooked
//! SLL/SLL2 from `-i any` and `-i lo`, BSD loopback NULL/LOOP, raw IP), then IPv4 or IPv6
//! (with extension headers), then TCP. Link types: <https://www.tcpdump.org/linktypes.html>.
//! Pure; every length is checked against the bytes there, nothing panics.

use std::net::IpAddr;

pub const LINKTYPE_NULL: u32 = 0;
pub const LINKTYPE_ETHERNET: u32 = 1;
pub const LINKTYPE_RAW: u32 = 101;
pub const LINKTYPE_LOOP: u32 = 108;
pub const LINKTYPE_LINUX_SLL: u32 = 113;
pub const LINKTYPE_IPV4: u32 = 228;
pub const LINKTYPE_IPV6: u32 = 229;
pub const LINKTYPE_LINUX_SLL2: u32 = 276;

/// The link types [`tcp`] reads, named for messages.
pub const IP_LINKTYPES: &[(u32, &str)] = &[
    (LINKTYPE_NULL, "BSD loopback (NULL)"),
    (LINKTYPE_ETHERNET, "Ethernet"),
    (LINKTYPE_RAW, "raw IP"),
    (LINKTYPE_LOOP, "OpenBSD loopback (LOOP)"),
    (LINKTYPE_LINUX_SLL, "Linux cooked (SLL)"),
    (LINKTYPE_IPV4, "raw IPv4"),
    (LINKTYPE_IPV6, "raw IPv6"),
    (LINKTYPE_LINUX_SLL2, "Linux cooked v2 (SLL2)"),
];

pub const TCP_FIN: u8 = 0x01;
pub const TCP_SYN: u8 = 0x02;
pub const TCP_RST: u8 = 0x04;
pub const TCP_ACK: u8 = 0x10;

/// A TCP segment, addresses included.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tcp<'a> {
    pub src: IpAddr,
    pub dst: IpAddr,
    pub sport: u16,
    pub dport: u16,
    pub seq: u32,
    pub flags: u8,
    pub payload: &'a [u8],
    /// The capture kept less than the IP packet held (its snap length): `payload` is the
    /// part kept.
    pub cut: bool,
}

/// What a packet holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layers<'a> {
    Tcp(Tcp<'a>),
    /// Not TCP over IP (ARP, UDP, ICMP, an IP fragment, a packet cut by the snap length).
    Other,
}

fn be16(b: &[u8], at: usize) -> Option<u16> {
    Some(u16::from_be_bytes([*b.get(at)?, *b.get(at + 1)?]))
}

/// `None` when the link type is not one plcsh reads.
pub fn tcp(linktype: u32, p: &[u8]) -> Option<Layers<'_>> {
    let ip = match linktype {
        LINKTYPE_ETHERNET => ethernet(p),
        // A 4-byte address family (host order for NULL, network order for LOOP): the IP
        // version nibble after it says the same and is never ambiguous.
        LINKTYPE_NULL | LINKTYPE_LOOP => p.get(4..),
        LINKTYPE_RAW | LINKTYPE_IPV4 | LINKTYPE_IPV6 => Some(p),
        LINKTYPE_LINUX_SLL => match be16(p, 14) {
            Some(0x0800 | 0x86DD) => p.get(16..),
            _ => None,
        },
        LINKTYPE_LINUX_SLL2 => match be16(p, 0) {
            Some(0x0800 | 0x86DD) => p.get(20..),
            _ => None,
        },
        _ => return None,
    };
    Some(ip.and_then(ip_tcp).map_or(Layers::Other, Layers::Tcp))
}

/// The IP packet in an Ethernet II frame (past up to two VLAN tags).
fn ethernet(p: &[u8]) -> Option<&[u8]> {
    let mut at = 12;
    for _ in 0..3 {
        match be16(p, at)? {
            0x8100 | 0x88A8 => at += 4,
            0x0800 | 0x86DD => return p.get(at + 2..),
            _ => return None,
        }
    }
    None
}

fn ip_tcp(ip: &[u8]) -> Option<Tcp<'_>> {
    let (src, dst, seg, cut) = match ip.first()? >> 4 {
        4 => {
            let ihl = usize::from(ip[0] & 0x0F) * 4;
            let total = usize::from(be16(ip, 2)?);
            // Total length 0: segmentation offload, the packet runs to the capture's end.
            let end = if total == 0 { ip.len() } else { total };
            let frag = be16(ip, 6)?;
            if ihl < 20 || *ip.get(9)? != 6 || frag & 0x3FFF != 0 || end < ihl {
                return None;
            }
            let (end, cut) = if ip.len() < end { (ip.len(), true) } else { (end, false) };
            let a = |at: usize| -> Option<IpAddr> {
                let o: [u8; 4] = ip.get(at..at + 4)?.try_into().ok()?;
                Some(IpAddr::from(o))
            };
            (a(12)?, a(16)?, ip.get(ihl..end)?, cut)
        }
        6 => {
            if ip.len() < 40 {
                return None;
            }
            let plen = usize::from(be16(ip, 4)?);
            let end = 40usize.checked_add(plen)?;
            let (end, cut) = if ip.len() < end { (ip.len(), true) } else { (end, false) };
            let a = |at: usize| -> Option<IpAddr> {
                let o: [u8; 16] = ip.get(at..at + 16)?.try_into().ok()?;
                Some(IpAddr::from(o))
            };
            let (mut next, mut at) = (*ip.get(6)?, 40);
            // Extension headers: hop-by-hop, routing, destination options, authentication.
            for _ in 0..8 {
                match next {
                    0 | 43 | 60 => {
                        let len = (usize::from(*ip.get(at + 1)?) + 1) * 8;
                        next = *ip.get(at)?;
                        at += len;
                    }
                    51 => {
                        let len = (usize::from(*ip.get(at + 1)?) + 2) * 4;
                        next = *ip.get(at)?;
                        at += len;
                    }
                    _ => break,
                }
            }
            if next != 6 || at > end {
                return None;
            }
            (a(8)?, a(24)?, ip.get(at..end)?, cut)
        }
        _ => return None,
    };
    let off = usize::from(*seg.get(12)? >> 4) * 4;
    if off < 20 || seg.len() < off {
        return None;
    }
    Some(Tcp {
        src,
        dst,
        sport: be16(seg, 0)?,
        dport: be16(seg, 2)?,
        seq: u32::from_be_bytes(seg.get(4..8)?.try_into().ok()?),
        flags: seg[13],
        payload: &seg[off..],
        cut,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An IPv4/TCP packet from 127.0.0.1:40000 to 127.0.0.1:5020 carrying `payload`.
    fn ipv4(payload: &[u8]) -> Vec<u8> {
        let mut p = vec![0x45, 0, 0, 0, 0, 0, 0x40, 0, 64, 6, 0, 0, 127, 0, 0, 1, 127, 0, 0, 1];
        let total = (40 + payload.len()) as u16;
        p[2..4].copy_from_slice(&total.to_be_bytes());
        p.extend_from_slice(&[0x9C, 0x40, 0x13, 0x9C, 0, 0, 0, 7, 0, 0, 0, 0, 0x50, 0x18, 0xFF, 0xFF, 0, 0, 0, 0]);
        p.extend_from_slice(payload);
        p
    }

    #[test]
    fn every_link_type_reaches_the_same_segment() {
        let ip = ipv4(b"abc");
        let mut eth = vec![0; 12];
        eth.extend_from_slice(&[0x81, 0x00, 0, 1, 0x08, 0x00]);
        eth.extend_from_slice(&ip);
        let mut sll = vec![0, 0, 3, 4, 0, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0x08, 0x00];
        sll.extend_from_slice(&ip);
        let mut sll2 = vec![0x08, 0x00, 0, 0, 0, 0, 0, 1, 3, 4, 0, 6, 0, 0, 0, 0, 0, 0, 0, 0];
        sll2.extend_from_slice(&ip);
        let mut null = vec![2, 0, 0, 0];
        null.extend_from_slice(&ip);
        for (lt, p) in [(1, &eth), (113, &sll), (276, &sll2), (0, &null), (108, &null), (101, &ip), (228, &ip)] {
            let Some(Layers::Tcp(t)) = tcp(lt, p) else { panic!("link type {lt}") };
            assert_eq!((t.sport, t.dport, t.seq, t.payload), (40000, 5020, 7, &b"abc"[..]), "link type {lt}");
        }
        assert_eq!(tcp(105, &ip), None, "802.11 is not read");
        // Cut by a snap length: the part kept, marked.
        let Some(Layers::Tcp(t)) = tcp(101, &ip[..ip.len() - 1]) else { panic!() };
        assert_eq!((t.payload, t.cut), (&b"ab"[..], true));
    }

    #[test]
    fn ipv6_with_an_extension_header() {
        let v4 = ipv4(b"xy");
        let tcp_part = &v4[20..];
        let mut p = vec![0x60, 0, 0, 0, 0, 0, 0, 64];
        p[4..6].copy_from_slice(&((8 + tcp_part.len()) as u16).to_be_bytes());
        p[6] = 0; // hop-by-hop first
        p.extend_from_slice(&[0; 15]);
        p.push(1);
        p.extend_from_slice(&[0; 15]);
        p.push(1);
        p.extend_from_slice(&[6, 0, 1, 4, 0, 0, 0, 0]);
        p.extend_from_slice(tcp_part);
        let Some(Layers::Tcp(t)) = tcp(LINKTYPE_IPV6, &p) else { panic!() };
        assert_eq!((t.src, t.payload), ("::1".parse().unwrap(), &b"xy"[..]));
    }

    #[test]
    fn hostile_packets_do_not_panic() {
        let ip = ipv4(b"hello");
        for lt in [0, 1, 101, 108, 113, 228, 229, 276] {
            for n in 0..ip.len() {
                let _ = tcp(lt, &ip[..n]);
                let mut m = ip.clone();
                m[n] = 0xFF;
                let _ = tcp(lt, &m);
            }
        }
    }
}

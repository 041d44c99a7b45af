//! Honest link diagnoses, against independent responders: test code that plays a device on a
//! pseudo-terminal of its own, framing the requests with its own reading of the protocol (not
//! plcsh's codecs, not its simulators) and answering as a misbehaving device would — with a
//! damaged checksum, or too late. What the user is told must name what arrived, never blame
//! silence, the unit id or an object for it.
// Unix only: real pseudo-terminals (Windows has none).
#![cfg(unix)]

mod common;
use common::pty_responder::{self, Act};
use plcsh::core::{Clock, ErrorKind};
use plcsh::session::Session;
use std::io::{Read, Write};
use std::time::{Duration, Instant};

/// One request as the responder framed it, with the time its last byte arrived.
#[derive(Clone, Debug)]
struct Req {
    at: Instant,
    bytes: Vec<u8>,
}

type Responder = pty_responder::Responder<Req>;

/// Starts a responder on a new pty. `frame` says how long the request at the front of the
/// buffer is (`None`: not all of it yet); `answer(request, k)` what to do for the k-th.
fn responder(
    frame: fn(&[u8]) -> Option<usize>,
    mut answer: impl FnMut(&[u8], usize) -> Vec<Act> + Send + 'static,
) -> Responder {
    pty_responder::start(
        move |buf: &mut Vec<u8>, at| {
            let len = frame(buf)?;
            Some(Some(Req { at, bytes: buf.drain(..len).collect() }))
        },
        move |req: &Req, k| answer(&req.bytes, k),
    )
}

// ---------------------------------------------------------------------------------------------
// Modbus RTU, as Modbus over serial line V1.02 §2.5.1 and the application protocol V1.1b3 §6
// describe it: unit id, function code, data, CRC-16 (polynomial A001h reflected, initial FFFFh,
// low byte first; §6.2.2 of the serial-line specification).

fn crc(bytes: &[u8]) -> [u8; 2] {
    let mut c: u16 = 0xFFFF;
    for b in bytes {
        c ^= *b as u16;
        for _ in 0..8 {
            c = if c & 1 != 0 { (c >> 1) ^ 0xA001 } else { c >> 1 };
        }
    }
    c.to_le_bytes()
}

fn with_crc(mut f: Vec<u8>) -> Vec<u8> {
    let c = crc(&f);
    f.extend(c);
    f
}

/// A request a master sends: FC 1–6 are 8 bytes; FC 15/16 carry a byte count at offset 6.
fn rtu_request_len(b: &[u8]) -> Option<usize> {
    let len = match *b.get(1)? {
        0x0F | 0x10 => 9 + *b.get(6)? as usize,
        _ => 8,
    };
    (b.len() >= len).then_some(len)
}

/// The reply to a read of holding registers (FC 03): each register holds its address.
fn read_reply(req: &[u8]) -> Vec<u8> {
    let start = u16::from_be_bytes([req[2], req[3]]);
    let n = u16::from_be_bytes([req[4], req[5]]);
    let mut f = vec![req[0], 3, (2 * n) as u8];
    for a in start..start + n {
        f.extend(a.to_be_bytes());
    }
    with_crc(f)
}

#[test]
fn an_rtu_reply_with_a_corrupted_crc_is_reported_as_such_not_as_silence() {
    // Every reply is right but for its CRC, whose low byte is flipped.
    let r = responder(rtu_request_len, |req, _| {
        let mut reply = read_reply(req);
        let last = reply.len() - 2;
        reply[last] ^= 0xFF;
        vec![Act::Send(reply)]
    });
    let mut s = Session::new(Clock::following());
    let url = format!("rtu:{}?baud=115200&model=K205-16DT&retries=0&timeout=300ms", r.path.display());
    s.open("press", &url).unwrap();
    let e = s.get(&["VW10"]).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link, "{e}");
    let text = e.to_string();
    assert!(text.starts_with("press: "), "names the device: {text}");
    assert!(!text.contains("did not answer"), "something did answer: {text}");
    assert!(text.contains("invalid CRC"), "{text}");
    // What arrived, in hex, as the responder sent it.
    let req = &r.seen()[0].bytes;
    let mut sent = read_reply(req);
    let last = sent.len() - 2;
    sent[last] ^= 0xFF;
    let hex: Vec<String> = sent.iter().map(|b| format!("{b:02X}")).collect();
    assert!(text.contains(&hex.join(" ")), "shows the bytes {hex:?}: {text}");
    let good = crc(&sent[..last]);
    let good = format!("need {:02X} {:02X}", good[0], good[1]);
    assert!(text.contains(&good), "names the CRC the bytes need ({good}): {text}");
    assert!(e.hint.as_deref().is_some_and(|h| h.contains("baud=") && h.contains("wiring")), "{text}");
}

#[test]
fn rtu_noise_without_a_frame_is_shown_and_silence_is_still_silence() {
    // Request 0: three stray bytes; request 1: nothing at all.
    let r = responder(rtu_request_len, |_, k| if k == 0 { vec![Act::Send(vec![0x00, 0xFF, 0x7E])] } else { vec![] });
    let mut s = Session::new(Clock::following());
    let url = format!("rtu:{}?baud=115200&model=K205-16DT&retries=0&timeout=300ms", r.path.display());
    s.open("plc", &url).unwrap();
    let text = s.get(&["VW10"]).unwrap_err().to_string();
    assert!(text.contains("3 byte(s) arrived but no valid reply frame") && text.contains("00 FF 7E"), "{text}");
    assert!(!text.contains("did not answer"), "{text}");
    let text = s.get(&["VW10"]).unwrap_err().to_string();
    assert!(text.contains("did not answer"), "{text}");
}

// ---------------------------------------------------------------------------------------------
// The Kinco servo protocol as the FD5P manual's RS232 chapter describes it (§2): 10 bytes — id,
// function (40 read; 4F/4B/43 read replies with 1/2/4 bytes), index low byte first, sub-index,
// 4 data bytes low byte first, and a check byte that makes the sum of all 10 bytes 0 (mod 256).

fn servo_request_len(b: &[u8]) -> Option<usize> {
    (b.len() >= 10).then_some(10)
}

/// What the responder's drive holds: the statusword (6041.00) and the actual position (6063.00).
fn servo_value(index: u16) -> u32 {
    match index {
        0x6041 => 0x0237,
        0x6063 => 123_456,
        _ => 0,
    }
}

/// The reply to a read: 43 with four data bytes, as the manual's examples show.
fn servo_reply(req: &[u8]) -> Vec<u8> {
    let index = u16::from_le_bytes([req[2], req[3]]);
    let mut f = vec![req[0], 0x43, req[2], req[3], req[4]];
    f.extend(servo_value(index).to_le_bytes());
    let sum = f.iter().fold(0u8, |s, b| s.wrapping_add(*b));
    f.push(sum.wrapping_neg());
    f
}

fn servo_session(r: &Responder) -> Session {
    let mut s = Session::new(Clock::following());
    s.open("axis", &format!("kinco:{}?id=1&timeout=200ms", r.path.display())).unwrap();
    s
}

fn value(s: &mut Session, op: &str) -> plcsh::core::Result<i64> {
    Ok(s.get(&[op])?[0].1.value.as_i64())
}

#[test]
fn a_servo_reply_later_than_the_timeout_is_dropped_and_named_late() {
    // The first request is answered 300 ms after it arrived (timeout 200 ms, so the reply comes
    // in the middle of the quiet awaited after the silence); the rest at once.
    let r = responder(servo_request_len, |req, k| {
        let mut acts = Vec::new();
        if k == 0 {
            acts.push(Act::Sleep(Duration::from_millis(300)));
        }
        acts.push(Act::Send(servo_reply(req)));
        acts
    });
    let mut s = servo_session(&r);
    let e = value(&mut s, "statusword").unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link, "{e}");
    let text = e.to_string();
    assert!(text.contains("likely cause: late replies") && text.contains("timeout="), "{text}");
    assert!(!text.contains("wrong id") && !text.contains("does not exist"), "{text}");
    // The next request gets its own answer, sent after the late reply was over.
    assert_eq!(value(&mut s, "position_actual").unwrap(), 123_456);
    let (seen, ends) = (r.seen(), r.ends());
    assert_eq!(seen.len(), 2, "no probe after a late reply: {seen:?}");
    assert!(seen[1].at >= ends[0], "the next request waited for the line to be quiet");
}

#[test]
fn a_stale_servo_reply_is_skipped_and_never_blames_the_object() {
    // The first request (the statusword) is answered 500 ms late with a 200 ms timeout: later
    // than the quiet awaited after it, so the late frame arrives while the next request (the
    // actual position, 6063.00) waits. It must be skipped, not taken as a reply to 6063.00,
    // and 6063.00 must not be reported as missing on the drive.
    let r = responder(servo_request_len, |req, k| {
        let mut acts = Vec::new();
        if k == 0 {
            acts.push(Act::Sleep(Duration::from_millis(500)));
        }
        acts.push(Act::Send(servo_reply(req)));
        acts
    });
    let mut s = servo_session(&r);
    assert_eq!(value(&mut s, "statusword").unwrap_err().kind, ErrorKind::Link);
    match value(&mut s, "position_actual") {
        Ok(v) => assert_eq!(v, 123_456, "its own answer"),
        Err(e) => {
            let text = e.to_string();
            assert!(!text.contains("does not exist"), "a stale frame blamed on the object: {text}");
            assert!(text.contains("late replies"), "{text}");
        }
    }
    // Whatever the timing, the line is in step afterwards.
    assert_eq!(value(&mut s, "position_actual").unwrap(), 123_456);
    assert_eq!(value(&mut s, "statusword").unwrap(), 0x0237);
}

#[test]
fn rtu_over_tcp_a_corrupted_crc_points_at_the_gateway_settings() {
    // A transparent gateway played by the test: one connection, each 8-byte request answered
    // with a reply whose CRC's high byte is flipped.
    let listener = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let addr = listener.local_addr().unwrap();
    std::thread::spawn(move || {
        let Ok((mut s, _)) = listener.accept() else { return };
        let mut req = [0u8; 8];
        while s.read_exact(&mut req).is_ok() {
            let mut reply = read_reply(&req);
            let last = reply.len() - 1;
            reply[last] ^= 0xFF;
            let _ = s.write_all(&reply);
        }
    });
    let mut s = Session::new(Clock::following());
    s.open("gw", &format!("rtu+tcp://{addr}?model=K205-16DT&retries=0&timeout=300ms")).unwrap();
    let e = s.get(&["VW10"]).unwrap_err();
    let text = e.to_string();
    assert_eq!(e.kind, ErrorKind::Link, "{text}");
    assert!(text.starts_with("gw: ") && text.contains("invalid CRC") && !text.contains("did not answer"), "{text}");
    assert!(e.hint.as_deref().is_some_and(|h| h.contains("gateway's serial settings")), "{text}");
}

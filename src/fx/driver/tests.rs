//! The FX driver on the in-process simulator and on scripted lines: both protocols' reads
//! and writes, coalescing, retries, noise, silence and timeouts.

use super::*;
use crate::core::link::line as lines;
use crate::core::url::DeviceUrl;
use crate::core::Clock;
use crate::fx::link::{Reply, Settings};
use crate::fx::memory::Memory;
use crate::fx::port::{self, ACK, ENQ, NAK};
use crate::fx::sim::{LinkServer, PortServer, Server, SimLink};
use std::io;
use std::sync::{Arc, Mutex};

fn sim(url: &str) -> Box<dyn Device> {
    open_sim(&DeviceUrl::parse(url).unwrap(), &Clock::stepped()).unwrap_or_else(|e| panic!("{url}: {e}"))
}

fn ops(d: &dyn Device, names: &[&str]) -> Vec<Operand> {
    names.iter().flat_map(|n| d.operands().parse(n).unwrap()).collect()
}

fn set(d: &mut dyn Device, name: &str, v: i64) {
    let o = ops(d, &[name])[0];
    let v = d.operands().check(&o, Value::Int(v)).unwrap();
    d.write(&[(o, v)]).unwrap();
}

fn get(d: &mut dyn Device, name: &str) -> i64 {
    let o = ops(d, &[name]);
    d.read(&o).unwrap()[0].as_i64()
}

#[test]
fn port_and_link_read_and_write_every_kind() {
    for url in ["sim-fx:FX2N", "sim-fx:FX2N?protocol=link", "sim-fx:FX3U"] {
        let mut d = sim(url);
        let d = d.as_mut();
        set(d, "D100", -5);
        assert_eq!(get(d, "D100"), -5, "{url}");
        assert_eq!(get(d, "D100/WORD"), 65531);
        set(d, "D10/DINT", 100_000);
        assert_eq!(get(d, "D10/WORD"), 100_000 & 0xFFFF, "low word first");
        assert_eq!(get(d, "D11"), 1);
        assert_eq!(get(d, "D10/DINT"), 100_000);
        set(d, "D20/REAL", 0);
        set(d, "Y10", 1);
        assert_eq!(get(d, "Y10"), 1);
        assert_eq!(get(d, "K2Y10"), 1);
        set(d, "K4M0/WORD", 0xA5F0);
        assert_eq!(get(d, "M4"), 1);
        assert_eq!(get(d, "M0"), 0);
        assert_eq!(get(d, "K4M0/WORD"), 0xA5F0);
        assert_eq!(get(d, "K1M4"), 0xF, "K1 is 4 bits");
        assert_eq!(get(d, "K3M0"), 0x5F0, "M12–M15 are on, but a K3 group's high bits are zero");
        assert_eq!(get(d, "K4M0"), 0xA5F0 - 0x10000, "a full K4 group is a signed 16-bit value");
        assert_eq!(get(d, "K4M0/DINT"), 0xA5F0, "K4 in a 32-bit operation: high 16 bits zero");
        assert_eq!(get(d, "K8M0"), 0xA5F0, "K8 in 32 bits: M16–M31 are off");
        set(d, "K4M0", -1);
        assert_eq!(get(d, "K4M0/WORD"), 0xFFFF);
        set(d, "K4M0/DINT", 0xA5F0);
        assert_eq!(get(d, "K8M0"), 0xA5F0, "a 32-bit write to K4 writes 16 bits");
        set(d, "K2M3", 0xFF);
        assert_eq!(get(d, "K4M0/WORD"), 0xA5F0 | 0x7F8, "an unaligned group writes exactly its bits");
        set(d, "CN200", -7);
        assert_eq!(get(d, "CN200"), -7);
        set(d, "TN3", 42);
        assert_eq!(get(d, "TN3"), 42);
        assert_eq!(get(d, "M8000"), 1, "RUN");
        assert_eq!(get(d, "D8000"), 200);
        let tc = ops(d, &["TS0"])[0];
        d.write(&[(tc, Value::Bool(true))]).unwrap();
        assert_eq!(get(d, "TS0"), 1);
    }
}

#[test]
fn coils_are_read_only_and_nothing_is_sent() {
    let mut d = sim("sim-fx:FX2N");
    let o = ops(d.as_ref(), &["TC0"])[0];
    let before = d.requests();
    let e = d.write(&[(o, Value::Bool(true))]).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Unsupported);
    assert_eq!(d.requests(), before);
}

#[test]
fn port_reads_coalesce_within_64_bytes() {
    let mut d = sim("sim-fx:FX2N");
    // D0..D40: 41 words = 82 bytes → 2 frames; plus M0 (another region) → 3.
    let o = ops(d.as_ref(), &["D0..D40", "M0", "D100"]);
    let before = d.requests();
    d.read(&o).unwrap();
    assert_eq!(d.requests() - before, 4, "D0–D31, D32–D40, D100, M0");
    let o = ops(d.as_ref(), &["D0", "D31", "D5", "D16"]);
    let before = d.requests();
    d.read(&o).unwrap();
    assert_eq!(d.requests() - before, 1, "64 bytes in one frame, out of order");
}

#[test]
fn an_fx1s_counter_gap_is_not_read_across() {
    let mut d = sim("sim-fx:FX1S");
    let o = ops(d.as_ref(), &["CS0", "CS31", "CS235", "CS255"]);
    let before = d.requests();
    assert_eq!(d.read(&o).unwrap().len(), 4, "C32–C234 do not exist: no NAK");
    assert_eq!(d.requests() - before, 2);
    let mut l = sim("sim-fx:FX1S?protocol=link");
    let o = ops(l.as_ref(), &["CS0", "CS31", "CS235", "CS255"]);
    assert_eq!(l.read(&o).unwrap().len(), 4);
    assert_eq!(l.requests(), 2);
}

#[test]
fn link_reads_and_writes_coalesce() {
    let mut d = sim("sim-fx:FX2N?protocol=link");
    let o = ops(d.as_ref(), &["D0..D63", "D64", "X0..X7", "K4M0", "M16"]);
    let before = d.requests();
    d.read(&o).unwrap();
    assert_eq!(d.requests() - before, 4, "WR D0–D63, WR D64, BR X0–X7, BR M0–M16");
    // Scattered single words go in one WT frame.
    let w: Vec<(Operand, Value)> =
        ops(d.as_ref(), &["D1", "D50", "D7"]).into_iter().zip([1, 2, 3].map(Value::Int)).collect();
    let before = d.requests();
    d.write(&w).unwrap();
    assert_eq!(d.requests() - before, 1);
    assert_eq!(get(d.as_mut(), "D50"), 2);
}

#[test]
fn decimal_xy_link_frames_reach_the_same_devices() {
    let mut l = sim("sim-fx:FX2N?protocol=link&xy=decimal&share=unit-test-xy");
    let mut p = sim("sim-fx:FX2N?share=unit-test-xy");
    set(l.as_mut(), "Y22", 1); // sent as BW Y0018
    assert_eq!(get(p.as_mut(), "Y22"), 1);
    assert_eq!(get(l.as_mut(), "K2Y20"), 4);
    assert!(open_sim(&DeviceUrl::parse("sim-fx:FX2N?protocol=link&xy=hex").unwrap(), &Clock::stepped()).is_err());
}

#[test]
fn both_ports_share_one_plc() {
    let mut a = sim("sim-fx:FX1N?share=unit-test-a");
    let mut b = sim("sim-fx:FX1N?protocol=link&share=unit-test-a");
    set(a.as_mut(), "D5", 77);
    assert_eq!(get(b.as_mut(), "D5"), 77);
    set(b.as_mut(), "D1000", 9); // written over the link, read on the port
    assert_eq!(get(a.as_mut(), "D1000"), 9);
    assert!(
        open_sim(&DeviceUrl::parse("sim-fx:FX2N?share=unit-test-a").unwrap(), &Clock::stepped()).is_err(),
        "model differs"
    );
}

/// A transport in front of the in-process simulator that spoils the replies to the first
/// `bad` data frames: a wrong sum-check digit, or NAK instead of the answer.
struct Faulty {
    inner: SimLink,
    rx: std::collections::VecDeque<u8>,
    bad: u32,
    nak: bool,
    frames: u32,
}
impl Transport for Faulty {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.inner.send(bytes)?;
        let mut buf = [0u8; 512];
        let n = self.inner.recv(&mut buf, Duration::ZERO)?;
        let mut reply = buf[..n].to_vec();
        if bytes != [ENQ] {
            self.frames += 1;
            if self.bad > 0 {
                self.bad -= 1;
                if self.nak {
                    reply = vec![NAK];
                } else {
                    let last = reply.len() - 1;
                    reply[last] = if reply[last] == b'0' { b'1' } else { b'0' };
                }
            }
        }
        self.rx.extend(reply);
        Ok(())
    }
    fn recv(&mut self, buf: &mut [u8], _t: Duration) -> io::Result<usize> {
        let n = buf.len().min(self.rx.len());
        for (slot, b) in buf.iter_mut().zip(self.rx.drain(..n)) {
            *slot = b;
        }
        Ok(n)
    }
}

fn faulty(bad: u32, nak: bool, link: bool) -> (Driver, Arc<Mutex<Memory>>) {
    let model = Model::find("FX2N").unwrap();
    let plc = sim_plc(model, None, &Clock::stepped()).unwrap();
    let s = Settings::default();
    let h = Header { station: 0, pc: 0xFF, wait: 0 };
    let server: Box<dyn Server> = if link { Box::new(LinkServer::new(0, s)) } else { Box::new(PortServer::default()) };
    let t = Faulty { inner: SimLink::new(plc.clone(), server), rx: Default::default(), bad, nak, frames: 0 };
    let line = lines::private("faulty", Box::new(t));
    let info = DeviceInfo { family: "fx", model: "test".into(), link: "faulty".into(), simulated: true };
    let d = if link { Driver::link(line, model, h, s, info) } else { Driver::port(line, model, info) };
    (d, plc)
}

#[test]
fn bad_sums_and_naks_are_retried_three_times_then_reported() {
    for link in [false, true] {
        // Three spoiled replies: the fourth attempt succeeds.
        let (mut d, plc) = faulty(3, false, link);
        plc.lock().unwrap().set_word(Area::D, 5, 1234).unwrap();
        assert_eq!(get(&mut d, "D5"), 1234, "link={link}");
        assert_eq!((d.requests(), d.resent), (4, 3));
        // Four: reported as a link error naming the bad sum.
        let (mut d, _) = faulty(4, false, link);
        let o = ops(&d, &["D5"]);
        let e = d.read(&o).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Link, "{e}");
        assert!(e.message.contains("sum check") && e.message.contains("4 attempts"), "{e}");
        assert_eq!(d.requests(), 4);
        // The link recovers afterwards.
        assert_eq!(get(&mut d, "D5"), 0);
    }
    // NAK four times on the programming port: the PLC refuses.
    let (mut d, _) = faulty(4, true, false);
    let o = ops(&d, &["M500"]);
    let e = d.write(&[(o[0], Value::Bool(true))]).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Refused, "{e}");
    assert!(e.message.contains("NAK") && e.message.contains("forcing M500 ON"), "{e}");
    let (mut d, plc) = faulty(2, true, false);
    let o = ops(&d, &["M500"]);
    d.write(&[(o[0], Value::Bool(true))]).unwrap();
    assert_eq!(plc.lock().unwrap().bit(Area::M, 500), Some(true));
}

#[test]
fn link_nak_codes_are_reported_in_words() {
    // The device table says D7999 exists on an FX2N; a simulated FX1S lacks D300, but the
    // space refuses it before sending — so build a link driver whose model is larger than
    // the simulated PLC to see the PLC's own NAK.
    let big = Model::find("FX2N").unwrap();
    let plc = sim_plc(Model::find("FX1S").unwrap(), None, &Clock::stepped()).unwrap();
    let s = Settings::default();
    let line = lines::private("mismatch", Box::new(SimLink::new(plc, Box::new(LinkServer::new(0, s)))));
    let info = DeviceInfo { family: "fx", model: "test".into(), link: "x".into(), simulated: true };
    let mut d = Driver::link(line, big, Header { station: 0, pc: 0xFF, wait: 0 }, s, info);
    let e = d.read(&ops(&d, &["D300"])).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Refused);
    assert!(e.message.contains("NAK 06H") && e.message.contains("device number"), "{e}");
    assert_eq!(d.requests(), 1, "an area error is not retried");
}

#[test]
fn silence_is_reported_with_what_to_check() {
    // A link request for station 3 on a line where only station 0 answers.
    let model = Model::find("FX2N").unwrap();
    let plc = sim_plc(model, None, &Clock::stepped()).unwrap();
    let s = Settings::default();
    let line = lines::private("one-station", Box::new(SimLink::new(plc, Box::new(LinkServer::new(0, s)))));
    let info = DeviceInfo { family: "fx", model: "test".into(), link: "x".into(), simulated: true };
    let mut d = Driver::link(line, model, Header { station: 3, pc: 0xFF, wait: 0 }, s, info.clone());
    let e = d.read(&ops(&d, &["D0"])).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link);
    assert!(e.message.contains("no reply to WR"), "{e}");
    assert!(e.hint.as_deref().unwrap().contains("station 3"), "{e:?}");
    assert_eq!(d.requests(), 1, "silence is not retried");
    // A programming port that answers nothing: the ENQ probe goes unanswered, the frame
    // goes without it, and the silence is reported naming both; the next request probes again.
    let (mut p, sent) = scripted(None, vec![]);
    let e = p.read(&ops(&p, &["D0"])).unwrap_err();
    assert!(e.message.contains("no reply to a read of 2 bytes at 1000H"), "{e}");
    assert!(e.message.contains("it answered no ENQ either"), "{e}");
    assert!(e.hint.as_deref().unwrap().contains("7E1"), "{e:?}");
    assert_eq!(p.requests(), 1);
    p.read(&ops(&p, &["D0"])).unwrap_err();
    let sent = sent.lock().unwrap().clone();
    assert_eq!(sent.iter().map(|f| f[0]).collect::<Vec<_>>(), vec![ENQ, port::STX, ENQ, port::STX], "{sent:?}");
}

/// A timeout the user set is quoted as given in the no-reply message, to the
/// microsecond (never `timeout=` with the value lost, never `0 ms`).
#[test]
fn a_no_reply_message_keeps_the_timeout_the_user_gave() {
    let model = Model::find("FX2N").unwrap();
    let plc = sim_plc(model, None, &Clock::stepped()).unwrap();
    let s = Settings::default();
    let line = lines::private("one-station", Box::new(SimLink::new(plc, Box::new(LinkServer::new(0, s)))));
    let info = DeviceInfo { family: "fx", model: "test".into(), link: "x".into(), simulated: true };
    let mut d = Driver::link(line, model, Header { station: 3, pc: 0xFF, wait: 0 }, s, info);
    for (given, shown) in
        [("40ms", "40 ms (timeout=40ms)"), ("2.5", "2.5 ms (timeout=2.5)"), ("0.03s", "30 ms (timeout=0.03s)")]
    {
        d.set_option("timeout", given).unwrap();
        let e = d.read(&ops(&d, &["D0"])).unwrap_err();
        assert!(e.message.contains(&format!("within {shown}")), "{given}: {e}");
    }
    // `auto` goes back to the timeout computed from the line, with its parts.
    d.set_option("timeout", "auto").unwrap();
    let e = d.read(&ops(&d, &["D0"])).unwrap_err();
    assert!(e.message.contains("characters at 9600") && !e.message.contains("timeout="), "{e}");
}

// Public drivers (node-fxplc `FXPLCClient._sendCommand`, KrystianD/fxplc `_send_command`)
// send their frames without ENQ, and clones answer them: a PLC that leaves the ENQ probe
// unanswered is talked to without ENQ from then on.
#[test]
fn enq_is_probed_once_and_skipped_when_unanswered() {
    let read = port::encode_read_reply(&[0x34, 0x12]);
    let (mut d, sent) = scripted(None, vec![vec![], read.clone(), read.clone(), read.clone()]);
    assert_eq!(get(&mut d, "D123"), 0x1234);
    assert_eq!(get(&mut d, "D123"), 0x1234);
    assert_eq!(get(&mut d, "D123"), 0x1234);
    let firsts: Vec<u8> = sent.lock().unwrap().iter().map(|f| f[0]).collect();
    assert_eq!(firsts, vec![ENQ, port::STX, port::STX, port::STX], "one probe, then frames alone");
    // A PLC that answers ENQ keeps getting it after a failure (here a bad sum check).
    let mut bad = read.clone();
    bad[7] ^= 1;
    let (mut d, sent) = scripted(None, vec![vec![ACK], bad, vec![ACK], read.clone()]);
    assert_eq!(get(&mut d, "D123"), 0x1234);
    let firsts: Vec<u8> = sent.lock().unwrap().iter().map(|f| f[0]).collect();
    assert_eq!(firsts, vec![ENQ, port::STX, ENQ, port::STX]);
}

/// A line that answers each frame sent with the next scripted bytes (nothing once the
/// script runs out), keeping what was sent.
struct Scripted {
    replies: std::collections::VecDeque<Vec<u8>>,
    rx: std::collections::VecDeque<u8>,
    sent: Arc<Mutex<Vec<Vec<u8>>>>,
}
impl Transport for Scripted {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.sent.lock().unwrap().push(bytes.to_vec());
        self.rx.extend(self.replies.pop_front().unwrap_or_default());
        Ok(())
    }
    fn recv(&mut self, buf: &mut [u8], _t: Duration) -> io::Result<usize> {
        let n = buf.len().min(self.rx.len());
        for (slot, b) in buf.iter_mut().zip(self.rx.drain(..n)) {
            *slot = b;
        }
        Ok(n)
    }
}

/// A driver (computer link for `station`, or the programming port) on a scripted line.
fn scripted(station: Option<u8>, replies: Vec<Vec<u8>>) -> (Driver, Arc<Mutex<Vec<Vec<u8>>>>) {
    let sent = Arc::new(Mutex::new(Vec::new()));
    let t = Scripted { replies: replies.into(), rx: Default::default(), sent: sent.clone() };
    let line = lines::private("scripted", Box::new(t));
    let model = Model::find("FX2N").unwrap();
    let info = DeviceInfo { family: "fx", model: "test".into(), link: "scripted".into(), simulated: true };
    let d = match station {
        Some(st) => Driver::link(line, model, Header { station: st, pc: 0xFF, wait: 0 }, Settings::default(), info),
        None => Driver::port(line, model, info),
    };
    (d, sent)
}

fn reply(station: u8, r: Reply) -> Vec<u8> {
    fxlink::encode_reply(Header { station, pc: 0xFF, wait: 0 }, &r, Settings::default())
}

// Seed 004, "FX系列PLC专用协议通信指令格式详解": the reply repeats the station number, data
// comes in STX … ETX, a write is acknowledged with ACK, an error is NAK and a code
// ("若发送码有误，则有以下回应"). A reply carries no device address: a reply from another
// station, or of the wrong kind or length, is never taken for this request's.
#[test]
fn link_replies_must_fit_the_request() {
    let data = |st, v: &str| reply(st, Reply::Data(v.as_bytes().to_vec()));
    // Station 3's data (9999 = 270FH) to station 5's read of D100: resent, and D100's own value used.
    let (mut d, sent) = scripted(Some(5), vec![data(3, "270F"), data(5, "0064")]);
    assert_eq!(get(&mut d, "D100"), 100);
    assert_eq!((sent.lock().unwrap().len(), d.resent), (2, 1));
    // Two words where one was asked for (the reply to another request), then ACK: never a value.
    let (mut d, _) = scripted(Some(5), vec![data(5, "00640065"), reply(5, Reply::Ack), data(5, "0064")]);
    assert_eq!(get(&mut d, "D100"), 100, "the third reply fits");
    let (mut d, _) = scripted(Some(5), vec![data(5, "00640065"); 4]);
    let e = d.read(&ops(&d, &["D100"])).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link, "{e}");
    assert!(e.message.contains("another request") && e.message.contains("4 attempts"), "{e}");
    // A write answered by a data frame, by another station's ACK: not done, and said so.
    let o = ops(&d, &["D100"])[0];
    for wrong in [data(5, "0064"), reply(3, Reply::Ack)] {
        let (mut d, sent) = scripted(Some(5), vec![wrong.clone(); 4]);
        let e = d.write(&[(o, Value::Int(1))]).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Link, "{e}");
        assert!(e.message.contains("WW of 1 value(s) at D0100") && e.message.contains("4 attempts"), "{e}");
        assert_eq!(sent.lock().unwrap().len(), 4);
    }
    // ... and ACK from the addressed station after one of them: done.
    let (mut d, _) = scripted(Some(5), vec![data(5, "0064"), reply(5, Reply::Ack)]);
    d.write(&[(o, Value::Int(1))]).unwrap();
    // NAK 06 to a write: refused at once, never success.
    let (mut d, sent) = scripted(Some(5), vec![reply(5, Reply::Nak(6))]);
    let e = d.write(&[(o, Value::Int(1))]).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Refused, "{e}");
    assert!(e.message.contains("station 5 answered NAK 06H to WW"), "{e}");
    assert_eq!(sent.lock().unwrap().len(), 1, "a resend cannot cure an area error");
    // Another station's NAK is not this station's refusal.
    let (mut d, _) = scripted(Some(5), vec![reply(3, Reply::Nak(6)), reply(5, Reply::Ack)]);
    d.write(&[(o, Value::Int(1))]).unwrap();
}

// Seed 004: the PLC answers ENQ with ACK when ready and NAK on error ("通过ENQ、ACK和NAK上位机
// 协调与PLC的通信应答"). A burst of 00H — what a serial port delivers for characters with
// parity errors — is neither; it is set aside, and reported as noise when nothing else comes.
#[test]
fn noise_is_set_aside_and_never_called_a_nak() {
    let burst = vec![0u8; 31];
    let with = |mut a: Vec<u8>, b: &[u8]| {
        a.extend_from_slice(b);
        a
    };
    // Noise in front of the ACK and of the data: the exchange succeeds at once.
    let read = port::encode_read_reply(&[0x34, 0x12]);
    let (mut d, sent) = scripted(None, vec![with(burst.clone(), &[ACK]), with(burst.clone(), &read)]);
    assert_eq!(get(&mut d, "D123"), 0x1234);
    assert_eq!(sent.lock().unwrap().len(), 2, "ENQ and one read");
    // Nothing but noise to every ENQ: noise, not NAK.
    let (mut d, sent) = scripted(None, vec![burst.clone(); 4]);
    let e = d.read(&ops(&d, &["D123"])).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link, "{e}");
    assert!(e.message.contains("noise") && e.message.contains("31 × 00H"), "{e}");
    assert!(!e.message.contains("NAK"), "{e}");
    assert_eq!(sent.lock().unwrap().as_slice(), vec![vec![ENQ]; 4].as_slice());
    // Real NAKs are still NAKs.
    let (mut d, _) = scripted(None, vec![vec![NAK]; 4]);
    let e = d.read(&ops(&d, &["D123"])).unwrap_err();
    assert!(e.message.contains("answered ENQ with NAK 4 times"), "{e}");
    // Bytes with the parity bit and a stray tail in front of a link reply: set aside.
    let mut noisy = vec![0x80, 0xFF, b'3', b'B'];
    noisy.extend(reply(0, Reply::Data(b"0007".to_vec())));
    let (mut d, _) = scripted(Some(0), vec![noisy]);
    assert_eq!(get(&mut d, "D5"), 7);
    assert_eq!(d.resent, 0);
    // Only noise on the link, four times: reported as noise.
    let (mut d, _) = scripted(Some(0), vec![vec![0x00, 0x80, 0x00]; 4]);
    let e = d.read(&ops(&d, &["D5"])).unwrap_err();
    assert!(e.message.contains("noise on the line") && !e.message.contains("NAK"), "{e}");
    // A mix is listed attempt by attempt.
    let (mut d, _) = scripted(Some(0), vec![vec![0x00], vec![0x00], reply(0, Reply::Nak(2)), vec![0x00]]);
    let e = d.read(&ops(&d, &["D5"])).unwrap_err();
    assert!(e.message.contains("4 attempts: noise ×3, NAK 02H ×1"), "{e}");
}

#[test]
fn timeouts_follow_the_line_the_frames_and_the_wait() {
    let model = Model::find("FX2N").unwrap();
    let info = DeviceInfo { family: "fx", model: "test".into(), link: "x".into(), simulated: true };
    let link = |baud: u32, wait: u8, networked: bool| {
        let line = lines::private(
            "t",
            Box::new(SimLink::new(sim_plc(model, None, &Clock::stepped()).unwrap(), Box::new(PortServer::default()))),
        );
        let serial = LineSettings { baud, data_bits: 7, parity: Parity::Even, stop_bits: 1 };
        Driver::link(line, model, Header { station: 0, pc: 0xFF, wait }, Settings::default(), info.clone())
            .on_line(serial, networked)
    };
    // A WR of 64 words: a 17-character request, a 264-character reply (seed 004's frame:
    // STX, station, PC number, 4 hex per word, ETX, sum).
    let wr64 = (17, fxlink::data_reply_chars(256, Settings::default()));
    assert_eq!(wr64.1, 264);
    // 281 characters of 10 bits at 4800 baud: 585.4 ms on the wire, then the turnaround.
    let t4800 = link(4800, 0, false).timeout_for(wr64.0, wr64.1);
    assert_eq!(t4800, Duration::from_micros(585_417) + TURNAROUND);
    assert!(t4800 > Duration::from_millis(550), "a 64-word WR at 4800 baud fits");
    let t9600 = link(9600, 0, false).timeout_for(wr64.0, wr64.1);
    let t19200 = link(19200, 0, false).timeout_for(wr64.0, wr64.1);
    assert!(t4800 > t9600 && t9600 > t19200, "{t4800:?} {t9600:?} {t19200:?}");
    // 2810 bits: 292 709 µs at 9600 baud, 146 355 µs at 19200 (each rounded up).
    assert_eq!(t9600 - t19200, Duration::from_micros(292_709 - 146_355), "the wire time halves");
    // A smaller frame, the wait digit (×10 ms) and a device server each change it.
    assert!(link(9600, 0, false).timeout_for(17, 12) < t9600);
    assert_eq!(
        link(9600, 5, false).timeout_for(17, 12) - link(9600, 0, false).timeout_for(17, 12),
        Duration::from_millis(50)
    );
    assert_eq!(link(9600, 0, true).timeout_for(17, 12) - link(9600, 0, false).timeout_for(17, 12), NETWORK_ALLOWANCE);
    // The URL's timeout= replaces it; `auto` brings the computed one back.
    let mut d = link(4800, 0, false);
    d.set_option("timeout", "200ms").unwrap();
    assert_eq!(d.timeout_for(wr64.0, wr64.1), Duration::from_millis(200));
    assert!(d.timeout_text(17, 12).contains("timeout="));
    d.set_option("timeout", "auto").unwrap();
    assert_eq!(d.timeout_for(wr64.0, wr64.1), t4800);
    assert!(d.timeout_text(wr64.0, wr64.1).starts_with("835 ms (281 characters at 4800 7E1: 585 ms on the wire"));
    // Resends wait at least the frame time.
    assert!(d.resend_gap(wr64.0, wr64.1) >= Duration::from_millis(550));
}

/// A line that never falls quiet: a character every millisecond.
struct Chatter(Arc<std::sync::atomic::AtomicUsize>);
impl Transport for Chatter {
    fn send(&mut self, _: &[u8]) -> io::Result<()> {
        self.0.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
        Ok(())
    }
    fn recv(&mut self, buf: &mut [u8], t: Duration) -> io::Result<usize> {
        std::thread::sleep(t.min(Duration::from_millis(1)));
        buf[0] = b'7';
        Ok(1)
    }
}

#[test]
fn a_line_that_never_falls_quiet_gets_no_frame() {
    let sent = Arc::new(std::sync::atomic::AtomicUsize::new(0));
    let model = Model::find("FX2N").unwrap();
    let info = DeviceInfo { family: "fx", model: "test".into(), link: "x".into(), simulated: true };
    let line = lines::private("chatter", Box::new(Chatter(sent.clone())));
    let mut d = Driver::link(line, model, Header { station: 0, pc: 0xFF, wait: 0 }, Settings::default(), info)
        .on_line(LineSettings { baud: 19200, data_bits: 7, parity: Parity::Even, stop_bits: 1 }, false);
    let e = d.read(&ops(&d, &["D0"])).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link);
    assert!(e.message.contains("did not go quiet before WR of 1 point(s) from D0000"), "{e}");
    assert!(e.hint.as_deref().unwrap().contains("only master"), "{e:?}");
    assert_eq!(sent.load(std::sync::atomic::Ordering::SeqCst), 0, "nothing is sent into a busy line");
}

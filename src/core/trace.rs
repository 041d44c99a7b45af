//! Frame tracing for `-v`/`-vv` and recording for `--record`: every driver reports each
//! frame it sends and receives here, and the front end decides where it goes (stderr in the
//! shell, a buffer in tests, a pcapng file through [`crate::record`]). Off by default; when
//! off, a report costs one atomic load.
//!
//! Two independent outlets: the display sink ([`set_sink`]) sees frames as they cross; the
//! recorder ([`set_recorder`]) also learns each link's protocol and when a connection opens
//! and closes, which it needs to write standard captures, and the name each device is opened
//! under ([`name_device`]: the session tells it here, so it need not know the recorder).

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, OnceLock};
use std::time::{Duration, Instant};

/// Direction of a frame, seen from plcsh.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dir {
    Sent,
    Received,
}

/// The protocol a link carries, so a recording can encapsulate and decode its frames.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Proto {
    /// Not declared by the driver: recorded as raw bytes.
    Unknown,
    /// Modbus TCP (MBAP header + PDU).
    ModbusTcp,
    /// Modbus RTU on a serial line (unit, PDU, CRC).
    ModbusRtu,
    /// Modbus RTU frames carried over a TCP connection (a transparent gateway).
    RtuOverTcp,
    /// The Kinco servo drives' 10-byte RS232 frames.
    KincoServo,
    /// The UMPK teaching PLC's terminal protocol (`?NNCC` commands, `#…` replies).
    Umpk,
    /// The FX programming-port protocol (ENQ, `STX cmd addr count … ETX sum`).
    FxPort,
    /// The FX dedicated computer-link protocol (`ENQ station pc cmd wait …`).
    FxLink,
}

/// Receives every frame with its link's protocol, and connection boundaries.
pub trait Recorder: Send + Sync {
    /// A connection on `link` opened (`peer`: where it goes, e.g. `127.0.0.1:502`).
    fn opened(&self, link: &str, proto: Proto, peer: &str);
    /// A frame (or, for stream transports, a piece of one) crossed `link`.
    fn frame(&self, link: &str, proto: Proto, dir: Dir, bytes: &[u8]);
    /// The connection on `link` closed.
    fn closed(&self, link: &str);
    /// The device opened from `url` is called `name` (so a capture says `plc`, not the URL).
    fn named(&self, _url: &str, _name: &str) {}
}

/// Where traced frames go.
pub trait FrameSink: Send + Sync {
    /// `link` names the device or port; `since_last` is the time since the previous frame.
    fn frame(&self, link: &str, dir: Dir, bytes: &[u8], since_last: Duration);
}

static ENABLED: AtomicBool = AtomicBool::new(false);
static RECORDING: AtomicBool = AtomicBool::new(false);

fn recorder() -> &'static Mutex<Option<Arc<dyn Recorder>>> {
    static R: OnceLock<Mutex<Option<Arc<dyn Recorder>>>> = OnceLock::new();
    R.get_or_init(|| Mutex::new(None))
}

/// Sends every frame and connection event to `rec` from now on (`None` stops recording).
pub fn set_recorder(rec: Option<Arc<dyn Recorder>>) {
    let mut r = recorder().lock().unwrap_or_else(|p| p.into_inner());
    RECORDING.store(rec.is_some(), Ordering::Relaxed);
    *r = rec;
}

fn with_recorder(f: impl FnOnce(&dyn Recorder)) {
    if !RECORDING.load(Ordering::Relaxed) {
        return;
    }
    let r = recorder().lock().unwrap_or_else(|p| p.into_inner()).clone();
    if let Some(r) = r {
        f(r.as_ref());
    }
}

/// Reports that a connection on `link` opened.
pub fn opened(link: &str, proto: Proto, peer: &str) {
    with_recorder(|r| r.opened(link, proto, peer));
}

/// Reports that the connection on `link` closed.
pub fn closed(link: &str) {
    with_recorder(|r| r.closed(link));
}

/// Tells the running recording (if any) the name of the device opened from `url`.
pub fn name_device(url: &str, name: &str) {
    with_recorder(|r| r.named(url, name));
}

struct State {
    sink: Arc<dyn FrameSink>,
    last: Option<Instant>,
}

fn state() -> &'static Mutex<Option<State>> {
    static S: OnceLock<Mutex<Option<State>>> = OnceLock::new();
    S.get_or_init(|| Mutex::new(None))
}

/// Sends frames to `sink` from now on (`None` turns tracing off).
pub fn set_sink(sink: Option<Arc<dyn FrameSink>>) {
    let mut s = state().lock().unwrap_or_else(|p| p.into_inner());
    ENABLED.store(sink.is_some(), Ordering::Relaxed);
    *s = sink.map(|sink| State { sink, last: None });
}

pub fn enabled() -> bool {
    ENABLED.load(Ordering::Relaxed)
}

/// Reports one frame of an undeclared protocol.
pub fn frame(link: &str, dir: Dir, bytes: &[u8]) {
    frame_proto(link, Proto::Unknown, dir, bytes)
}

/// Reports one frame (drivers call this for every frame on the wire).
pub fn frame_proto(link: &str, proto: Proto, dir: Dir, bytes: &[u8]) {
    with_recorder(|r| r.frame(link, proto, dir, bytes));
    if !enabled() {
        return;
    }
    let mut s = state().lock().unwrap_or_else(|p| p.into_inner());
    if let Some(st) = s.as_mut() {
        let now = Instant::now();
        let since = st.last.map(|l| now - l).unwrap_or_default();
        st.last = Some(now);
        st.sink.frame(link, dir, bytes, since);
    }
}

/// Formats bytes as `01 2B 40 60`.
pub fn hex_bytes(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02X}")).collect::<Vec<_>>().join(" ")
}

/// Prints frames to stderr: `plc → 01 03 00 64 00 02 C5 D4  (+0.412 ms)`.
pub struct StderrSink;

impl FrameSink for StderrSink {
    fn frame(&self, link: &str, dir: Dir, bytes: &[u8], since_last: Duration) {
        let arrow = if dir == Dir::Sent { "→" } else { "←" };
        eprintln!("{link} {arrow} {}  (+{:.3} ms)", hex_bytes(bytes), since_last.as_secs_f64() * 1e3);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Collect(Mutex<Vec<(Dir, Vec<u8>)>>);
    impl FrameSink for Collect {
        fn frame(&self, link: &str, dir: Dir, bytes: &[u8], _since: Duration) {
            // Only this test's link: drivers in tests running in parallel report frames too.
            if link == "x" {
                self.0.lock().unwrap().push((dir, bytes.to_vec()));
            }
        }
    }

    #[test]
    fn frames_reach_the_sink_only_while_enabled() {
        let c = Arc::new(Collect(Mutex::new(Vec::new())));
        frame("x", Dir::Sent, &[1]);
        set_sink(Some(c.clone()));
        frame("x", Dir::Sent, &[1, 2]);
        frame("x", Dir::Received, &[3]);
        set_sink(None);
        frame("x", Dir::Sent, &[4]);
        let got = c.0.lock().unwrap().clone();
        assert_eq!(got, vec![(Dir::Sent, vec![1, 2]), (Dir::Received, vec![3])]);
        assert_eq!(hex_bytes(&[0x01, 0x2B]), "01 2B");
    }
}

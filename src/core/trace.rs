//! Frame tracing for `-v`/`-vv`: every driver reports each frame it sends and receives here,
//! and the front end decides where it goes (stderr in the shell, a buffer in tests). Off by
//! default; when off, a report costs one atomic load.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, OnceLock};
use std::time::{Duration, Instant};

/// Direction of a frame, seen from plcsh.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dir {
    Sent,
    Received,
}

/// Where traced frames go.
pub trait FrameSink: Send + Sync {
    /// `link` names the device or port; `since_last` is the time since the previous frame.
    fn frame(&self, link: &str, dir: Dir, bytes: &[u8], since_last: Duration);
}

static ENABLED: AtomicBool = AtomicBool::new(false);

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

/// Reports one frame (drivers call this for every frame on the wire).
pub fn frame(link: &str, dir: Dir, bytes: &[u8]) {
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

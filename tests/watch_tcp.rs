//! `watch` and `trace` against the simulator served over TCP, through `plcsh sim serve --tcp 127.0.0.1:0`.
//! The achieved rates are printed (a benchmark figure), not asserted.

mod common;
use common::*;
use std::process::Stdio;

/// Finds a `127.0.0.1:PORT` string anywhere in the readiness JSON.
fn address(v: &serde_json::Value) -> Option<String> {
    match v {
        serde_json::Value::String(s) if s.starts_with("127.0.0.1:") => Some(s.clone()),
        serde_json::Value::String(s) => s.find("127.0.0.1:").map(|i| s[i..].trim_end_matches('/').to_string()),
        serde_json::Value::Object(m) => m.values().find_map(address),
        serde_json::Value::Array(a) => a.iter().find_map(address),
        _ => None,
    }
}

fn serve_tcp() -> (Served, String) {
    let served = serve(&["--tcp", "127.0.0.1:0"]);
    let addr = address(&served.ready).unwrap_or_else(|| panic!("no 127.0.0.1:PORT in {}", served.ready));
    (served, addr)
}

#[test]
fn watch_and_trace_over_tcp_report_the_achieved_rate() {
    let (_server, addr) = serve_tcp();
    let url = format!("tcp://{addr}");
    let o = plcsh()
        .args(["--device", &url, "--json", "-v", "-c", "watch VW0 VD4 M0.0 every=20ms count=50"])
        .stdin(Stdio::null())
        .output()
        .unwrap();
    let l = json_lines(&o);
    let samples: Vec<&serde_json::Value> = l.iter().filter(|v| v.get("sample").is_some()).collect();
    assert_eq!(samples.len(), 50, "{}", stdout(&o));
    assert_eq!(samples[49]["t_us"].as_u64().map(|t| t >= 980_000), Some(true), "sample 50 is due at 980 ms");
    let err = String::from_utf8_lossy(&o.stderr);
    let report = err.lines().find(|l| l.starts_with("watch: ")).expect("the --verbose rate report");
    println!("{report}");
    assert!(report.contains("asked 50.0 Hz"));
    let o = plcsh()
        .args(["--device", &url, "-v", "-c", "trace VW0 VD4 every=10ms for=1s"])
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stdout(&o));
    let err = String::from_utf8_lossy(&o.stderr);
    let report = err.lines().find(|l| l.starts_with("trace: ")).expect("the --verbose rate report");
    println!("{report}");
    assert!(report.starts_with("trace: 101 samples"), "{report}");
}

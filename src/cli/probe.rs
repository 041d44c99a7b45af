//! `plcsh probe URL` (what a K2 answers before the helper is in it, read-only) and
//! `plcsh agent check URL` (the helper's self-test): both open a K2 on a wire by URL or
//! profile name, run the library's check ([`crate::k2::probe`], [`crate::k2::agent::check`])
//! and print a table, `--json`, or (probe) a Markdown report to attach when plcsh and a PLC
//! disagree. Exit status 0 only when every verdict or step passed.

use crate::core::url::DeviceUrl;
use crate::core::{Device, Error, Result};
use crate::k2::agent::check;
use crate::k2::driver::K2Wire;
use crate::k2::probe;
use crate::output::{self, Style};
use crate::shell::Shell;
use std::io::Write;
use std::path::PathBuf;

#[derive(clap::Args, Debug)]
pub struct ProbeArgs {
    /// The PLC: tcp://HOST:PORT, rtu:PORT?baud=…, rtu+tcp://HOST:PORT, or a profile name.
    #[arg(value_name = "URL")]
    pub url: String,
    /// Also write the findings as a Markdown report to FILE.
    #[arg(long, value_name = "FILE")]
    pub report: Option<PathBuf>,
    /// Reads timed for the response time (p50, p99).
    #[arg(long, value_name = "N", default_value_t = 100, value_parser = clap::value_parser!(u32).range(1..=10_000))]
    pub reads: u32,
    /// On a serial line that does not answer, try the common settings (9600…115200 baud, no,
    /// even or odd parity) and say which one answered.
    #[arg(long = "scan-serial")]
    pub scan_serial: bool,
}

#[derive(clap::Args, Debug)]
pub struct CheckArgs {
    /// The PLC: tcp://HOST:PORT?agent=VB3400, rtu:PORT?…, or a profile name (agent=VB3400 when the URL has none).
    #[arg(value_name = "URL")]
    pub url: String,
}

/// The device URL `target` names: itself, or a profile's URL and options. `writes`: the
/// command writes (`agent check`), so a read-only session (`--read-only`) or a profile that
/// limits writes (`read_only`, `allow`) refuses it before anything is opened.
fn resolve(shell: &Shell, target: &str, writes: bool) -> Result<(DeviceUrl, Vec<(String, String)>)> {
    let refuse = |why: crate::core::msg::Msg| {
        Error::new(crate::core::ErrorKind::Refused, why).hint(crate::msg!("cli-hint-agent-check-writes"))
    };
    if writes && shell.session.read_only() {
        return Err(refuse(crate::msg!("cli-agent-check-read-only")));
    }
    let (text, options) = if target.contains(':') {
        (target.to_string(), Vec::new())
    } else {
        let p = shell.session.profiles.get(target).ok_or_else(|| shell.session.profiles.unknown(target))?;
        if writes && (p.read_only || p.allow.is_some()) {
            return Err(refuse(crate::msg!("cli-agent-check-profile", profile = target, origin = p.origin.as_str())));
        }
        (p.url.clone(), p.options.clone())
    };
    let url = DeviceUrl::parse(&text)?.without("control");
    match url.base_scheme() {
        "tcp" | "rtu" => Ok((url, options)),
        "sim" => Err(Error::usage(crate::msg!("cli-probe-in-process", url = text.as_str()))
            .hint(crate::msg!("cli-hint-probe-in-process"))),
        s => {
            Err(Error::usage(crate::msg!("cli-probe-not-on-wire", scheme = s)).hint(crate::msg!("cli-hint-probe-urls")))
        }
    }
}

fn open(url: &DeviceUrl, options: &[(String, String)]) -> Result<K2Wire> {
    let mut dev = K2Wire::open(url)?;
    for (k, v) in options {
        dev.set_option(k, v)?;
    }
    Ok(dev)
}

fn fail(out: &mut dyn Write, style: Style, cmd: &str, e: &Error) -> i32 {
    let _ = output::report_error(out, style, cmd, e, None);
    if e.kind == crate::core::ErrorKind::Usage {
        2
    } else {
        1
    }
}

/// Serial settings a scan tries after the URL's own, most common first.
const SCAN_BAUDS: &[u32] = &[9600, 19200, 38400, 57600, 115200];
const SCAN_PARITIES: &[&str] = &["none", "even", "odd"];

/// The URL with `key=value` set (replacing the URL's own).
fn with_param(url: &DeviceUrl, key: &str, value: &str) -> Result<DeviceUrl> {
    let base = url.clone().without(key);
    let sep = if base.text.contains('?') { '&' } else { '?' };
    DeviceUrl::parse(&format!("{}{sep}{key}={value}", base.text))
}

pub fn probe(args: &ProbeArgs, shell: &Shell, style: Style, out: &mut dyn Write) -> i32 {
    let (url, options) = match resolve(shell, &args.url, false) {
        Ok(x) => x,
        Err(e) => return fail(out, style, "probe", &e),
    };
    let mut dev = match open(&url, &options) {
        Ok(d) => d,
        Err(e) => return fail(out, style, "probe", &e),
    };
    let mut tried = vec![];
    let hint = dev.link_hint();
    let mut result = probe::run(&mut dev, args.reads, &hint);
    let mut line = dev.serial_line();
    let silent =
        |p: &probe::Probe| p.areas.iter().all(|a| matches!(a.extent, probe::Extent::NoReply { last: None, .. }));
    if silent(&result) && args.scan_serial && dev.serial_line().is_some() {
        tried.push(dev.serial_line().unwrap_or_default());
        drop(dev);
        'scan: for baud in SCAN_BAUDS {
            for parity in SCAN_PARITIES {
                let candidate = with_param(&url, "baud", &baud.to_string())
                    .and_then(|u| with_param(&u, "parity", parity))
                    .and_then(|u| with_param(&u, "retries", "0"))
                    .and_then(|u| with_param(&u, "timeout", "300ms"));
                let Ok(candidate) = candidate else { continue };
                let Ok(mut d) = open(&candidate, &options) else { continue };
                let settings = d.serial_line().unwrap_or_default();
                if tried.contains(&settings) {
                    continue;
                }
                tried.push(settings);
                let hint = d.link_hint();
                if !matches!(
                    probe::Reader::read(&mut d, crate::k2::modbus_map::Table::HoldingRegisters, 100),
                    probe::Answer::Failed { .. }
                ) {
                    result = probe::run(&mut d, args.reads, &hint);
                    line = d.serial_line();
                    break 'scan;
                }
            }
        }
    }
    let serial = if silent(&result) { None } else { line };
    let version = env!("CARGO_PKG_VERSION");
    if let Some(path) = &args.report {
        if let Err(e) = std::fs::write(path, probe::markdown(&result, &args.url, serial.as_deref(), version)) {
            let e = Error::io(crate::msg!("cli-probe-cannot-write-report", file = path.display().to_string())).cause(e);
            return fail(out, style, "probe", &e);
        }
    }
    let w = if style.json {
        let mut j = serde_json::to_value(&result).unwrap_or_default();
        j["ok"] = true.into();
        j["cmd"] = "probe".into();
        j["passed"] = result.ok().into();
        j["url"] = args.url.clone().into();
        j["serial"] = serial.clone().into();
        j["serial_tried"] = tried.clone().into();
        writeln!(out, "{j}")
    } else {
        writeln!(out, "{}", text(&result, &args.url, serial.as_deref(), &tried))
    };
    if w.is_err() {
        return 1;
    }
    i32::from(!result.ok())
}

/// Terminal columns of a cell (a Chinese character takes two).
fn columns(cell: Option<&String>) -> usize {
    cell.map_or(0, |c| unicode_width::UnicodeWidthStr::width(c.as_str()))
}

fn text(p: &probe::Probe, url: &str, serial: Option<&str>, tried: &[String]) -> String {
    let mut rows = vec![crate::output::headings(crate::msg!("probe-columns"))];
    rows.extend(probe::rows(p));
    let widths: Vec<usize> =
        (0..probe::HEADERS.len()).map(|c| rows.iter().map(|r| columns(r.get(c))).max().unwrap_or(0)).collect();
    let mut s = crate::msg!("probe-head", url = url, requests = p.requests).text + "\n";
    if let Some(line) = serial {
        s.push_str(&crate::msg!("probe-serial-answered", settings = line));
        s.push('\n');
    }
    if !tried.is_empty() && serial.is_none() {
        s.push_str(&crate::msg!("probe-serial-tried", settings = tried.join("; ")));
        s.push('\n');
    }
    for r in &rows {
        // Padded to display columns: a Chinese heading takes two a character.
        let cells: Vec<String> = r
            .iter()
            .zip(&widths)
            .map(|(c, w)| format!("{c}{}", " ".repeat(w.saturating_sub(columns(Some(c))))))
            .collect();
        s.push_str(cells.join("  ").trim_end());
        s.push('\n');
    }
    s.push_str(&if p.models.is_empty() {
        crate::msg!("probe-models-none")
    } else {
        crate::msg!("probe-models", models = p.models.join(", "))
    });
    s.push('\n');
    for v in &p.verdicts {
        s.push_str(&crate::msg!("probe-verdict", ok = if v.ok { "ok" } else { "failed" }, what = v.what.as_str()));
        s.push('\n');
        if let Some(t) = &v.todo {
            s.push_str("  ");
            s.push_str(&crate::msg!("probe-what-to-do", todo = t.as_str()));
            s.push('\n');
        }
    }
    s.trim_end().to_string()
}

pub fn check(args: &CheckArgs, shell: &Shell, style: Style, out: &mut dyn Write) -> i32 {
    let (url, options) = match resolve(shell, &args.url, true) {
        Ok(x) => x,
        Err(e) => return fail(out, style, "agent check", &e),
    };
    let mut dev = match open(&url, &options) {
        Ok(d) => d,
        Err(e) => return fail(out, style, "agent check", &e),
    };
    let report = dev.agent_check();
    let w = if style.json {
        let mut j = serde_json::to_value(&report).unwrap_or_default();
        j["ok"] = true.into();
        j["cmd"] = "agent check".into();
        j["passed"] = report.passed().into();
        j["url"] = args.url.clone().into();
        writeln!(out, "{j}")
    } else {
        write!(out, "{}", check::text(&report))
    };
    if w.is_err() {
        return 1;
    }
    i32::from(!report.passed())
}

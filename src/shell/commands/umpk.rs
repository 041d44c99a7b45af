//! `umpk …`: the UMPK8/UMPK16 terminal commands (manual §4.1), the real-time monitor,
//! Intel HEX programming (§4.2) and the simulator's inputs, through [`crate::umpk::ops`]: the
//! [`crate::umpk::driver::Driver`] (the serial driver and the in-process simulator alike).
//!
//! Which controller: `umpk [DEVICE] SUBCOMMAND …` — a first word naming an open device picks
//! it; otherwise the current device if it is a UMPK, otherwise the only UMPK open.
//!
//! `umpk monitor [OPERAND…] [count=N] [for=DURATION] [every=DURATION]` shows the monitor
//! stream like `watch` (a live table on a terminal, lines on a pipe, JSON lines with
//! `--json`); sample times are cycles × 10 ms, since every packet is one cycle (§4.1.11). The
//! samples become the last trace, so `plot` draws them.

use super::k2cmd::{check_options, opt, value_err};
use super::watch::{Mode, Render};
use super::CommandSpec;
use crate::core::literal::parse_option_duration_us;
use crate::core::{DataType, Error, Result, Value};
use crate::output::Outcome;
use crate::session::Reading;
use crate::shell::lex::{self, Word};
use crate::shell::sample::{Recording, Sample};
use crate::shell::{Args, Shell};
use crate::umpk::codec::{error_code_text, letter_text, Reply, INFO_LEN};
use crate::umpk::driver::Driver;
use crate::umpk::hex;
use crate::umpk::sim::{describe_status, logic::CYCLE_MS};
use crate::umpk::space::UmpkOperand;
use std::io::Write;
use std::time::Duration;

pub const UMPK: CommandSpec = CommandSpec {
    name: "umpk",
    aliases: &[],
    usage: "umpk [DEVICE] info|program-info|errors [clear]|timing|reset|echo on|off|monitor [OPERAND…] [count=N] [for=2s] [every=100ms] [quiet]|program FILE.hex [info=\"…\"] [run]|send TEXT|sim input I3=1|sim input I3 [off] [freq=2Hz]|sim inputs|sim flash-fail PAGE|off|sim fault no-reply|stuck [I3=1] [for=D]|sim fault clear|sim faults|sim events|sim reference [NAME]",
    summary: || crate::msg!("summary-umpk"),
    subcommands: &["info", "program-info", "errors", "timing", "reset", "echo", "monitor", "program", "send", "sim"],
    run: umpk,
};

fn is_umpk(sh: &mut Shell, i: usize) -> bool {
    // By family, so a UMPK not connected yet is still found (and tried) by name.
    sh.session.entries()[i].device.info().family == "umpk"
}

fn pick<'a>(sh: &mut Shell, words: &'a [Word<'a>]) -> Result<(usize, &'a [Word<'a>])> {
    if let Some(&(col, first)) = words.first() {
        if !UMPK.subcommands.contains(&first) {
            if let Ok(i) = sh.session.index(first) {
                if !is_umpk(sh, i) {
                    return Err(Error::usage(crate::msg!("shell-umpk-not-umpk", name = first)).column(col));
                }
                return Ok((i, &words[1..]));
            }
        }
    }
    if let Ok(i) = sh.session.current_index() {
        if is_umpk(sh, i) {
            return Ok((i, words));
        }
    }
    let all: Vec<usize> = (0..sh.session.entries().len()).filter(|&i| is_umpk(sh, i)).collect();
    match all.as_slice() {
        [i] => Ok((*i, words)),
        [] => Err(Error::usage(crate::msg!("shell-umpk-none-open"))
            .hint(crate::msg!("shell-hint-umpk-open", port = crate::core::platform::words::port!()))),
        _ => Err(Error::usage(crate::msg!("shell-umpk-several"))),
    }
}

/// The UMPK behind device `dev` for a command that only reads it (or drives the simulator's
/// own inputs, which a simulator control is, as on the K2).
fn driver(sh: &mut Shell, dev: usize) -> &mut Driver {
    changing(sh, dev, "").expect("reads are always permitted")
}

/// The UMPK behind device `dev` for a command that changes the controller (`what`: reset,
/// echo, program, errors clear, send): the write guard checks it first and refuses the whole
/// command, naming the rule ([`crate::umpk::ops`]). An allow list names it as `umpk:WHAT`.
fn changing<'a>(sh: &'a mut Shell, dev: usize, what: &str) -> Result<&'a mut Driver> {
    let change =
        crate::core::device::Change::Action { what: format!("umpk {what}"), touches: vec![format!("umpk:{what}")] };
    let changes: &[crate::core::device::Change] = if what.is_empty() { &[] } else { std::slice::from_ref(&change) };
    let ops = crate::umpk::ops(sh.session.entry(dev).device.as_mut(), changes)?;
    Ok(ops.expect("picked a UMPK"))
}

fn umpk(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let words = lex::words_in(&args)?;
    let (dev, rest) = pick(sh, &words)?;
    sh.session.ready(dev)?;
    let Some(&(col, sub)) = rest.first() else {
        return Err(Error::usage(crate::msg!("shell-umpk-needs-subcommand")).hint(UMPK.usage).column(args.offset));
    };
    let rest = &rest[1..];
    let name = sh.session.entries()[dev].name.clone();
    let r = match sub {
        "info" => info(driver(sh, dev)),
        "program-info" => {
            let t = driver(sh, dev).program_info()?;
            let text = String::from_utf8_lossy(&t).into_owned();
            let shown = if text.trim().is_empty() {
                crate::msg!("shell-umpk-program-info-none")
            } else {
                crate::msg!("shell-umpk-program-info", info = text.as_str())
            };
            Ok(Outcome::new("umpk").text(shown.text).with("program_info", text))
        }
        "errors" if rest.first().is_some_and(|w| w.1 == "clear") => errors(changing(sh, dev, "errors-clear")?, rest),
        "errors" => errors(driver(sh, dev), rest),
        "timing" => {
            let t = driver(sh, dev).timing()?;
            Ok(Outcome::new("umpk")
                .text(
                    crate::msg!(
                        "shell-umpk-timing",
                        total = format!("{:.1}", t.total_us()),
                        firmware = format!("{:.1}", t.firmware_us()),
                        program = format!("{:.1}", t.program_us()),
                        hhkk = format!("{:04X}", t.firmware),
                        llmm = format!("{:04X}", t.total)
                    )
                    .text,
                )
                .with("firmware_counts", t.firmware)
                .with("total_counts", t.total)
                .with("program_us", t.program_us())
                .with("firmware_us", t.firmware_us())
                .with("total_us", t.total_us()))
        }
        "reset" => {
            changing(sh, dev, "reset")?.reset()?;
            Ok(Outcome::new("umpk").text(crate::msg!("shell-umpk-reset").text))
        }
        "echo" => {
            let on = match rest.first().map(|w| w.1) {
                Some("on") => true,
                Some("off") => false,
                _ => return Err(Error::usage("umpk echo on|off").column(col)),
            };
            changing(sh, dev, "echo")?.set_echo(on)?;
            Ok(Outcome::new("umpk").text(format!("echo {}", if on { "on" } else { "off" })).with("echo", on))
        }
        "monitor" => monitor(sh, dev, rest),
        "program" => program(sh, dev, rest, col),
        "send" => send(changing(sh, dev, "send")?, rest, col),
        "sim" => sim(sh, dev, rest, col),
        other => Err(Error::usage(crate::msg!("shell-umpk-unknown", sub = other)).column(col).hint(UMPK.usage)),
    };
    r.map(|mut o| {
        o.device = Some(name.clone());
        o
    })
    .map_err(|e| e.device(name))
}

/// True when the current device is a UMPK (`sim input I3=1` then means its input).
pub fn current_is_umpk(sh: &mut Shell) -> bool {
    sh.session.current_index().is_ok_and(|i| is_umpk(sh, i))
}

/// `sim input I3=1 | I3 freq=2Hz | I3 off` on the current UMPK: the same as `umpk sim input …`.
pub fn sim_input(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let words = lex::words_in(&args)?;
    let dev = sh.session.current_index()?;
    let name = sh.session.entries()[dev].name.clone();
    let col = words.first().map_or(args.offset, |w| w.0);
    let mut o = sim(sh, dev, &words, col).map_err(|e| e.device(&name))?;
    o.device = Some(name);
    Ok(o)
}

/// `sim program load FILE.il [tags=FILE.csv]` / `sim program` on the current UMPK: an IL lab program run by
/// the simulator on the scan engine ([`crate::umpk::sim::program`]).
pub fn sim_program(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let words = lex::words_in(&args)?;
    let dev = sh.session.current_index()?;
    let name = sh.session.entries()[dev].name.clone();
    let col = words.first().map_or(args.offset, |w| w.0);
    let s = driver(sh, dev)
        .simulator()
        .ok_or_else(|| Error::unsupported(crate::msg!("shell-umpk-real-program")).device(&name).column(col))?;
    let mut u = s.lock().unwrap_or_else(|p| p.into_inner());
    let now = u.clock.now();
    u.advance(now);
    let msg = match words.get(1).map(|w| (w.0, w.1)) {
        None | Some((_, "status")) => None,
        Some((_, "load")) => {
            let (args, tag_file) = super::simprogram::tags_option(args)?;
            let (c, path) = lex::one_path(&args, 2, "sim program load")?.ok_or_else(|| {
                Error::usage(crate::msg!(
                    "shell-sim-load-needs-file",
                    example = "sim program load scripts/umpk_lab1.il"
                ))
                .column(col)
            })?;
            sh.session.check_read(&path).map_err(|e| e.device(&name).column(c))?;
            let text = crate::core::encoding::read_source(&path).map_err(|e| {
                Error::io(crate::msg!("shell-cannot-read-because", file = path.as_str(), reason = e.to_string()))
                    .device(&name)
                    .column(c)
            })?;
            let tags = match &tag_file {
                Some((tc, t)) => {
                    sh.session.check_read(t).map_err(|e| e.device(&name).column(*tc))?;
                    let space = crate::umpk::space::UmpkSpace { model: u.model };
                    Some(
                        crate::profile::tags::load(std::path::Path::new(t), None, &space)
                            .map_err(|p| p.into_error().device(&name).column(*tc))?,
                    )
                }
                None => None,
            };
            let r = crate::umpk::sim::program::IlRunner::load_with_tags(&text, &path, u.model, tags.as_ref())
                .map_err(|e| e.device(&name))?;
            let n = r.instructions();
            u.load_logic(Box::new(r));
            Some(crate::msg!("shell-umpk-il-loaded", file = path.as_str(), instructions = n, cycle = CYCLE_MS).text)
        }
        Some((c, other)) => {
            return Err(Error::usage(crate::msg!("shell-umpk-sim-program-unknown", sub = other))
                .hint(crate::msg!("shell-hint-umpk-sim-program"))
                .device(&name)
                .column(c))
        }
    };
    let kind = u.program_kind();
    let mode = u.mode().name();
    let text = crate::msg!("shell-umpk-program-mode", program = kind.as_str(), mode = mode).text;
    let mut o = Outcome::new("sim")
        .text(msg.map_or(text.clone(), |m| format!("{m}\n{text}")))
        .with("program", kind)
        .with("mode", mode)
        .with("timing_counts", u.timing().total);
    o.device = Some(name);
    Ok(o)
}

fn info(d: &mut Driver) -> Result<Outcome> {
    let i = d.controller_info()?;
    let st = d.layout.decode(i.status);
    let mode = if st.programming {
        "Programming"
    } else if st.work {
        "Work"
    } else {
        "Wait"
    };
    let bits = describe_status(&st);
    let model = d.model().name;
    let echo = d.echo.unwrap_or(true);
    // The fields' names, in the order of the rows (`|` between them in the catalogue).
    let fields = crate::output::headings(crate::msg!("shell-umpk-info-fields"));
    let field = |k: usize| fields.get(k).cloned().unwrap_or_default();
    let flags = if bits.is_empty() { crate::msg!("shell-umpk-no-flag").text } else { bits.join(", ") };
    let mut rows = vec![
        vec![field(0), format!("{model} (MM={:02X})", i.model)],
        vec![field(1), format!("{} (VV={:02X})", i.version, i.version.0)],
        vec![field(2), format!("{} / {}", i.inputs, i.outputs)],
        vec![field(3), crate::msg!("shell-umpk-mode", mode = mode).text],
        vec![field(4), format!("{:02X}: {flags}", i.status)],
        vec![field(5), format!("{:02X}", i.microcode)],
        vec![field(6), if echo { "on" } else { "off" }.into()],
    ];
    let sim = d.simulator();
    if let Some(s) = &sim {
        rows.push(vec![field(7), s.lock().unwrap_or_else(|p| p.into_inner()).program_kind()]);
    }
    Ok(Outcome::new("umpk")
        .table(&crate::output::headings(crate::msg!("shell-umpk-info-columns")), rows)
        .with("model", model)
        .with("model_code", i.model)
        .with("firmware", i.version.to_string())
        .with("inputs", i.inputs)
        .with("outputs", i.outputs)
        .with("mode", mode)
        .with("status", i.status)
        .with("status_bits", st)
        .with("microcode", i.microcode)
        .with("echo", echo))
}

fn errors(d: &mut Driver, rest: &[Word]) -> Result<Outcome> {
    if rest.first().is_some_and(|w| w.1 == "clear") {
        d.clear_errors()?;
        return Ok(Outcome::new("umpk").text(crate::msg!("shell-umpk-errors-cleared").text));
    }
    let e = d.errors()?;
    let codes: Vec<u8> = e.iter().copied().filter(|&c| c != 0).collect();
    let rows: Vec<Vec<String>> =
        e.iter().enumerate().map(|(k, &c)| vec![(k + 1).to_string(), c.to_string(), error_code_text(c)]).collect();
    let o = Outcome::new("umpk").with("errors", e.to_vec()).with("codes", &codes);
    Ok(if codes.is_empty() {
        o.text(crate::msg!("shell-umpk-errors-empty").text)
    } else {
        o.table(&crate::output::headings(crate::msg!("shell-umpk-errors-columns")), rows)
    })
}

fn send(d: &mut Driver, rest: &[Word], col: usize) -> Result<Outcome> {
    let Some(&(_, text)) = rest.first() else {
        return Err(Error::usage(crate::msg!("shell-umpk-send-needs")).column(col));
    };
    let text = lex::unquote(text);
    let x = d.send_raw(&text)?;
    let (shown, meaning) = match &x.reply {
        Reply::Ok => ("R".to_string(), "ok".to_string()),
        Reply::Letter(l) => ((*l as char).to_string(), letter_text(*l).to_string()),
        Reply::Packet(p) => {
            (format!("#{}", p.iter().map(|b| format!("{b:02X}")).collect::<String>()), "a packet".into())
        }
        Reply::Text(t) => (format!("#{}", String::from_utf8_lossy(t)), "program info".into()),
    };
    Ok(Outcome::new("umpk")
        .text(format!("{text} → {shown} ({meaning}; echo {})", if x.echoed { "on" } else { "off" }))
        .with("reply", shown)
        .with("meaning", meaning)
        .with("echoed", x.echoed))
}

/// `umpk sim …` / `sim input …`: the control language of [`crate::umpk::sim::control`], applied
/// to an in-process simulator or sent to a served one's control channel (`control=PATH`);
/// `reference NAME` loads one of the simulator's reference programs.
fn sim(sh: &mut Shell, dev: usize, rest: &[Word], col: usize) -> Result<Outcome> {
    let line = rest.iter().map(|w| w.1).collect::<Vec<_>>().join(" ");
    if rest.first().map(|w| w.1) != Some("reference") {
        let control = sh.session.entries()[dev].control.clone();
        let (text, data) = match (driver(sh, dev).simulator(), control) {
            (Some(s), _) => {
                let mut u = s.lock().unwrap_or_else(|p| p.into_inner());
                crate::umpk::sim::control::answer(&mut u, &line).map_err(|e| e.column(col))?
            }
            (None, Some(path)) => crate::core::link::control::send(&path, &line).map_err(|e| e.column(col))?,
            (None, None) => return Err(Error::unsupported(crate::msg!("shell-umpk-sim-needs-simulator")).column(col)),
        };
        let mut o = Outcome::new("umpk").text(text);
        if let serde_json::Value::Object(m) = data {
            for (k, v) in m {
                if !matches!(k.as_str(), "ok" | "text" | "time_us") {
                    o = o.with(&k, v);
                }
            }
        }
        return Ok(o);
    }
    let d = driver(sh, dev);
    let s =
        d.simulator().ok_or_else(|| Error::unsupported(crate::msg!("shell-umpk-reference-in-process")).column(col))?;
    let mut u = s.lock().unwrap_or_else(|p| p.into_inner());
    let (pos, _) = lex::options(rest.get(1..).unwrap_or(&[]));
    match rest.first().map(|w| w.1) {
        Some("reference") => {
            use crate::umpk::sim::reference;
            let Some(&(c, name)) = pos.first() else {
                let list: Vec<String> =
                    reference::REFERENCES.iter().map(|r| format!("{}: {}", r.name, r.description)).collect();
                return Ok(Outcome::new("umpk").text(list.join("\n")).with("references", reference::names()));
            };
            let r = reference::find(name).ok_or_else(|| {
                value_err(c, crate::msg!("shell-umpk-no-reference", name = name))
                    .hint(crate::msg!("shell-hint-umpk-references", names = reference::names()))
            })?;
            let runner = (r.build)(&mut u.logic);
            u.load_logic(runner);
            Ok(Outcome::new("umpk")
                .text(
                    crate::msg!(
                        "shell-umpk-reference-loaded",
                        name = r.name,
                        description = r.description,
                        mode = u.mode().name()
                    )
                    .text,
                )
                .with("program", r.name)
                .with("mode", u.mode().name()))
        }
        _ => unreachable!("only reference reaches here"),
    }
}

fn program(sh: &mut Shell, dev: usize, rest: &[Word], col: usize) -> Result<Outcome> {
    let (pos, opts) = lex::options(rest);
    check_options(&opts, &["info"], UMPK.usage)?;
    let Some(&(fc, file)) = pos.first() else {
        return Err(Error::usage(crate::msg!("shell-umpk-program-needs-file")).column(col).hint(UMPK.usage));
    };
    let run = match pos.get(1) {
        None => false,
        Some((_, "run")) => true,
        Some(&(c, w)) => return Err(Error::usage(crate::msg!("shell-umpk-program-extra", extra = w)).column(c)),
    };
    let info = match opt(&opts, "info") {
        None => None,
        Some((c, v)) => {
            let v = lex::unquote(v);
            if v.is_empty() || v.len() > INFO_LEN || !v.bytes().all(|b| (0x20..0x7F).contains(&b)) {
                return Err(value_err(c, crate::msg!("shell-umpk-info-text", info = &*v)));
            }
            Some(v.as_bytes().to_vec())
        }
    };
    // The file, as text: `umpk program "Лаб 1/прошивка.hex"` (docs/commands.md, "Quoting").
    let file = lex::unquote(file);
    let file = file.as_ref();
    sh.session.check_read(file).map_err(|e| e.column(fc))?;
    let text = std::fs::read_to_string(file)
        .map_err(|e| Error::io(crate::msg!("shell-cannot-read", file = file)).cause(e).column(fc))?;
    let d = driver(sh, dev);
    let memory = d.model().program_bytes;
    let prog = hex::parse_file(&text, memory).map_err(|m| {
        Error::new(crate::core::ErrorKind::Value, format!("{file}: {m}")).hint(crate::msg!(
            "shell-hint-umpk-hex",
            model = d.model().name,
            last = format!("{:04X}", memory - 1)
        ))
    })?;
    let show = crate::core::platform::escapes(crate::core::platform::Stream::Stderr) && !sh.style.json;
    let mut progress = |k: usize, n: usize| {
        if show {
            let bar = crate::shell::progress::bar(k as f64 / n as f64, 20);
            eprint!("\r\x1b[2K{}", crate::msg!("shell-umpk-programming", bar = bar, record = k, records = n));
            let _ = std::io::stderr().flush();
        }
    };
    let d = changing(sh, dev, "program")?;
    let r = d.program(&prog, info.as_deref(), &mut progress);
    if show {
        eprint!("\r\x1b[2K");
    }
    let r = r?;
    if run {
        d.reset()?;
    }
    let next = if run { crate::msg!("shell-umpk-programmed-run") } else { crate::msg!("shell-umpk-programmed-stays") };
    // The simulator keeps a binary but cannot run it: said here, not discovered from dead outputs.
    let simulated = d.simulator().is_some();
    let note = if simulated {
        format!("\n{}", crate::msg!("label-note", note = crate::umpk::sim::binary_not_executed().text))
    } else {
        String::new()
    };
    let mut out = Outcome::new("umpk")
        .text(
            crate::msg!(
                "shell-umpk-programmed",
                bytes = r.bytes,
                pages = r.pages,
                records = r.records,
                info = r.info.as_str(),
                named = if r.info.is_empty() { "no" } else { "yes" },
                stopped = if r.was_running { "yes" } else { "no" },
                next = next.text
            )
            .text
                + &note,
        )
        .with("bytes", r.bytes)
        .with("pages", r.pages)
        .with("records", r.records)
        .with("info", &r.info)
        .with("run", run)
        .with("was_running", r.was_running);
    if simulated {
        out = out.with("executed", false).with("note", crate::umpk::sim::binary_not_executed().text);
    }
    Ok(out)
}

fn monitor(sh: &mut Shell, dev: usize, rest: &[Word]) -> Result<Outcome> {
    let (mut pos, opts) = lex::options(rest);
    check_options(&opts, &["count", "for", "every"], UMPK.usage)?;
    let quiet = pos.iter().any(|w| w.1 == "quiet");
    pos.retain(|w| w.1 != "quiet");
    let dur = |key: &str| -> Result<Option<Duration>> {
        opt(&opts, key)
            .map(|(c, v)| {
                parse_option_duration_us(v)
                    .map(|us| Duration::from_micros(us.max(0) as u64))
                    .map_err(|m| value_err(c, m))
            })
            .transpose()
    };
    let mut count: Option<u64> = opt(&opts, "count")
        .map(|(c, v)| v.parse().map_err(|_| value_err(c, crate::msg!("shell-count-not-number", value = v))))
        .transpose()?;
    let span = dur("for")?;
    if quiet && count.is_none() && span.is_none() {
        // Nothing is shown while it runs (Lua): one sample unless told otherwise.
        count = Some(1);
    }
    let mode = if sh.style.json {
        Mode::Json
    } else if crate::core::platform::escapes(crate::core::platform::Stream::Stdout) && !quiet {
        Mode::Live { color: sh.style.color }
    } else {
        Mode::Lines
    };
    let every_cycles = match dur("every")? {
        Some(d) => (d.as_millis() as u64 / CYCLE_MS).max(1),
        None if matches!(mode, Mode::Live { .. }) => 10,
        None => 1,
    };
    let model = driver(sh, dev).model();
    let texts: Vec<String> = if pos.is_empty() {
        vec![format!("I0..I{}", model.inputs - 1), format!("Q0..Q{}", model.outputs - 1)]
    } else {
        pos.iter().map(|w| w.1.to_string()).collect()
    };
    let mut ops = Vec::new();
    {
        let space = sh.session.entry(dev).device.operands();
        for (k, t) in texts.iter().enumerate() {
            let col = pos.get(k).map_or(0, |w| w.0);
            ops.extend(space.parse(t).map_err(|e| e.shift(col))?);
        }
    }
    let parsed: Vec<UmpkOperand> = ops.iter().map(UmpkOperand::from_core).collect();
    let labels: Vec<String> = parsed.iter().map(UmpkOperand::name).collect();
    let every = Duration::from_millis(every_cycles * CYCLE_MS);
    let mut render = Render::new(mode, labels.clone(), every);
    let mut rec = Recording::new(labels.clone(), every);
    let interrupt = sh.session.interrupt.clone();
    let d = driver(sh, dev);
    d.monitor_start()?;
    let (mut packets, mut shown) = (0u64, 0u64);
    let mut out = std::io::stdout();
    let result: Result<()> = (|| loop {
        if interrupt.load(std::sync::atomic::Ordering::Relaxed) {
            return Ok(());
        }
        let Some(m) = d.monitor_next(d.timeout)? else {
            return Err(Error::link(crate::msg!("shell-umpk-monitor-stopped")));
        };
        let t = Duration::from_millis(packets * CYCLE_MS);
        if span.is_some_and(|s| t > s) {
            return Ok(());
        }
        packets += 1;
        if (packets - 1) % every_cycles != 0 {
            continue;
        }
        let readings = parsed
            .iter()
            .map(|o| {
                let on = match o.area().letter {
                    'I' => m.inputs >> o.index & 1 != 0,
                    'Q' => m.outputs >> o.index & 1 != 0,
                    'T' => m.timers >> o.index & 1 != 0,
                    'C' => m.counters >> o.index & 1 != 0,
                    _ => m.markers >> o.index & 1 != 0,
                };
                Reading::plain(o.name(), Value::Bool(on), DataType::Bool)
            })
            .collect();
        let s = Sample { index: shown, t, readings };
        if !quiet {
            render
                .sample(&s, &mut out)
                .map_err(|e| Error::io(crate::msg!("shell-umpk-monitor-cannot-write", reason = e.to_string())))?;
        }
        rec.push(&s);
        shown += 1;
        if count.is_some_and(|c| shown >= c) {
            return Ok(());
        }
    })();
    let stop = d.monitor_stop();
    result?;
    stop?;
    let columns: serde_json::Map<String, serde_json::Value> = rec
        .labels
        .iter()
        .zip(&rec.columns)
        .map(|(l, c)| (l.clone(), serde_json::json!(c.iter().map(|v| *v as u8).collect::<Vec<_>>())))
        .collect();
    let t_ms: Vec<u64> = rec.t.iter().map(|t| (t * 1000.0).round() as u64).collect();
    sh.last_trace = Some(rec);
    let o = Outcome::new("umpk")
        .with("packets", packets)
        .with("samples", shown)
        .with("span_ms", packets * CYCLE_MS)
        .with("t_ms", t_ms)
        .with("columns", columns);
    Ok(if quiet {
        o.text(crate::msg!("shell-umpk-monitor-samples", samples = shown, packets = packets).text)
    } else {
        o.quiet()
    })
}

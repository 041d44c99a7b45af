//! Entry points for the fuzz targets in `fuzz/`: one function per parser or decoder that
//! takes outside input, each taking arbitrary bytes. The rule they check is the project's:
//! outside input never panics and is handled in time linear in its length. The cargo-fuzz
//! targets (`fuzz/fuzz_targets/*.rs`, nightly) call these; `tests/fuzz_corpus.rs` (stable,
//! `cargo test`) replays every corpus input and every input that ever crashed through the
//! same functions, so a fixed bug stays fixed.
//!
//! A new parser adds one function here and one row in [`TARGETS`] (and a one-line target
//! file in `fuzz/fuzz_targets/`, plus seed inputs in `fuzz/corpus/NAME/`).

use crate::core::url::DeviceUrl;
use crate::core::{Clock, DataType, OperandSpace};
use crate::k2::catalog::MODELS;
use crate::k2::space::K2Space;
use crate::k2::Event;
use std::path::Path;

/// A target's entry point.
pub type Target = fn(&[u8]);

/// Every target: name (the directory under `fuzz/corpus/` and `fuzz/regressions/`, and the
/// cargo-fuzz target) and entry point.
pub static TARGETS: &[(&str, Target)] = &[
    ("operand", operand),
    ("literal", literal),
    ("lexer", lexer),
    ("url", url),
    ("profile", profile),
    ("completion", completion),
    ("servo_frame", servo_frame),
    ("servo_units", servo_units),
    ("servo_params", servo_params),
    ("data_set", data_set),
    ("pulse", pulse),
    ("modbus_rtu", modbus_rtu),
    ("modbus_tcp", modbus_tcp),
    ("modbus_client", modbus_client),
    ("agent_mailbox", agent_mailbox),
    ("agent_base", agent_base),
    ("il", il),
    ("il_encoding", il_encoding),
    ("fx_port", fx_port),
    ("control", control),
    ("fx_link", fx_link),
    ("fx_operand", fx_operand),
    ("fx_il", fx_il),
    ("umpk_reply", umpk_reply),
    ("umpk_hex", umpk_hex),
    ("pcapng", pcapng),
    ("rfc2217", rfc2217),
    ("rfc2217_server", rfc2217_server),
    ("mqtt_command", mqtt_command),
    ("bench", bench),
    ("lab_toml", lab_toml),
    ("umpk_snapshot", umpk_snapshot),
    ("tags", tags),
];

fn text(data: &[u8]) -> String {
    String::from_utf8_lossy(data).into_owned()
}

/// The K2 operand grammar, bound to every model (bounds, hints' "last valid" operand).
pub fn operand(data: &[u8]) {
    let t = text(data);
    let _ = crate::k2::operand::parse_expr(&t);
    for m in MODELS {
        let space = K2Space::new(m);
        if let Ok(ops) = space.parse(&t) {
            for op in ops.iter().take(64) {
                let _ = space.name(op);
                let _ = space.describe(op);
            }
        }
        let _ = space.complete(&t);
    }
}

/// IEC literals and durations, fitted into every type.
pub fn literal(data: &[u8]) {
    let t = text(data);
    if let Ok(lit) = crate::core::literal::parse_literal(&t) {
        for d in DataType::ALL {
            let _ = lit.fit(d, d.bits());
        }
    }
    let _ = crate::core::literal::parse_duration_us(&t);
    let _ = crate::k2::helpers::parse_freq_hz(&t);
}

/// The command-line lexer: commands, words, options, quoted text, the manual's spelling read
/// in operand words only; and any text [`quote`](crate::shell::lex::quote)d is one word that
/// reads back as itself.
pub fn lexer(data: &[u8]) {
    use crate::shell::lex;
    let t = text(data);
    if let Ok(parts) = lex::split_commands(&t) {
        for (_, p) in parts {
            if let Ok(w) = lex::words(p) {
                let _ = lex::options(&w);
                w.iter().for_each(|(_, word)| drop(lex::unquote(word)));
            }
            for cmd in ["sim", "trace", "umpk", "get"] {
                let _ = crate::shell::fold_operands(cmd, p);
            }
        }
    }
    let q = lex::quote(&t);
    let w = lex::words(&q).unwrap_or_default();
    assert!(w.len() == 1 && lex::unquote(w[0].1) == t, "quote({t:?}) gave {q}, read back as {w:?}");
}

/// Device URLs, and the numbers the drivers read from them (`baud=`, `unit=`, `id=`,
/// `retries=`, `timeout=`).
pub fn url(data: &[u8]) {
    if let Ok(u) = DeviceUrl::parse(&text(data)) {
        let _ = u.param_num::<u32>("baud");
        let _ = u.param_num::<u32>("retries");
        let _ = u.param_num::<u8>("unit");
        let _ = u.param_num::<u8>("id");
        if let Some(t) = u.param("timeout") {
            let _ = crate::core::literal::parse_timeout(t);
        }
        let _ = u.expect_params(&["unit", "model"]);
    }
}

/// The device profile file, and the write rules built from it.
pub fn profile(data: &[u8]) {
    let p = crate::profile::Profiles::parse(&text(data), Path::new("fuzz/devices.toml"));
    let space = K2Space::new(&MODELS[0]);
    for prof in p.list() {
        let _ = crate::profile::Guard::build(prof, &space);
    }
}

/// What arrives from outside for fleets and MQTT: a write command from the broker
/// (`publish --accept-writes`), a broker URL and a fleet's URL range.
pub fn mqtt_command(data: &[u8]) {
    let _ = crate::publish::writes::parse(data);
    let t = text(data);
    let _ = crate::publish::parse_broker(&t);
    let _ = crate::fleet::expand(&t);
}

/// Completion and the inline hint (run on every keystroke), at every cursor position.
pub fn completion(data: &[u8]) {
    use crate::shell::complete::{complete, hint, DeviceView, View};
    let t = text(data);
    let k205 = K2Space::new(&MODELS[0]);
    let servo = crate::servo::objects::ServoSpace::new(Default::default());
    let files = |_: &str| Vec::new();
    let view = View {
        devices: vec![
            DeviceView { name: "plc", family: "k2", model: MODELS[0].name, space: &k205, names: None },
            DeviceView { name: "servo", family: "servo", model: "FD", space: &servo, names: None },
        ],
        current: Some(0),
        profiles: Vec::new(),
        files: &files,
    };
    let ends: Vec<usize> = t.char_indices().map(|(i, _)| i).chain([t.len()]).collect();
    // Every 8th position keeps a long input linear overall (each call is linear itself).
    for &pos in ends.iter().step_by(8.max(ends.len() / 64)) {
        let _ = complete(&t, pos, &view);
        let _ = hint(&t, pos, &view);
    }
}

/// The servo's 10-byte frames as a stream, and replies checked against requests.
pub fn servo_frame(data: &[u8]) {
    use crate::servo::frame::{decode_reply, Decoded, FrameBuffer, Size};
    let mut buf = FrameBuffer::new();
    buf.push(data);
    let mut frames = Vec::new();
    loop {
        match buf.next_frame() {
            Decoded::NeedMore => break,
            Decoded::Frame(f) => frames.push(f),
            Decoded::Bad(..) => {}
        }
    }
    for pair in frames.windows(2) {
        for size in [Size::B1, Size::B2, Size::B4] {
            let _ = decode_reply(&pair[0], &pair[1].to_bytes(), size);
        }
    }
}

/// A drive parameter set file (`servo params load FILE`): parsed, checked, compared with
/// itself.
pub fn servo_params(data: &[u8]) {
    use crate::servo::params::{self, ParamSet};
    if let Ok(set) = ParamSet::parse(&text(data), "fuzz.toml") {
        assert!(params::diff(&set, &set).is_empty(), "a set differs from itself");
        let _ = set.to_toml();
    }
}

/// A PLC data set file (`data load FILE`, `data diff FILE`): parsed, checked, compared with
/// itself, written and read again to the same values.
pub fn data_set(data: &[u8]) {
    use crate::dataset::{self, DataSet};
    if let Ok(set) = DataSet::parse(&text(data), "fuzz.toml") {
        assert!(dataset::diff(&set, &set).is_empty(), "a set differs from itself");
        let again = DataSet::parse(&set.to_toml(), "again.toml").expect("a set's own text reads back");
        assert!(dataset::diff(&set, &again).is_empty(), "a set written and read back differs");
        assert_eq!(set.device, again.device);
    }
}

/// Servo object names and values with units (`300rpm`, `100rps/s`, `2.5rev`).
pub fn servo_units(data: &[u8]) {
    use crate::servo::objects::{self, ObjRef, ServoSpace};
    use crate::servo::units::{self, Resolution, Unit};
    let t = text(data);
    let _ = units::parse_resolution(&t);
    let _ = objects::parse(&t);
    let r = data.first().map(|b| 1u32 << (b % 32)).unwrap_or(10_000);
    for unit in [Unit::None, Unit::Bits, Unit::Increments, Unit::Speed, Unit::Accel, Unit::Mode] {
        let _ = units::parse_engineering(&t, unit, r);
    }
    let space = ServoSpace::new(Resolution::new(r));
    let _ = space.parse(&t);
    for name in ["target_position", "profile_velocity", "profile_acceleration", "controlword"] {
        let _ = space.parse_value(&ObjRef::of(objects::named(name)), &t);
    }
}

/// The options of the pulse helpers `pto`, `pwm` and `profile` (`cycle=1ms width=250us`,
/// `freq=2kHz count=1000`, `at=VB3001 [(cycle=500us, count=10)]`), read as the commands
/// read them and planned for every model with pulse outputs.
pub fn pulse(data: &[u8]) {
    crate::shell::commands::pulse::fuzz_options(&text(data));
}

/// A fresh simulated K2 behind a Modbus service (unit 1).
fn service() -> crate::k2::sim::modbus_server::K2Service {
    let sim = crate::k2::sim::open("K205-16DT", Clock::stepped()).expect("the default model");
    crate::k2::sim::modbus_server::K2Service::new(std::sync::Arc::new(std::sync::Mutex::new(sim)), 1)
}

/// Modbus RTU framing on a serial line, in the chunks the bytes arrive in, and the
/// requests served.
pub fn modbus_rtu(data: &[u8]) {
    use crate::k2::sim::rtu_frame::{self, Frame};
    let svc = service();
    // The server's receiver, with the line falling silent after every fourth chunk.
    let mut rx = rtu_frame::Receiver::default();
    let mut frames = Vec::new();
    for (i, chunk) in data.chunks(37).enumerate() {
        frames.extend(rx.bytes(chunk));
        if i % 4 == 3 {
            frames.extend(rx.silence());
        }
    }
    frames.extend(rx.silence());
    for f in frames {
        if let Frame::Request { unit, request } = f {
            if let Some(r) = svc.handle(unit, &request) {
                let _ = rtu_frame::encode(unit, request.function_code().value(), &r);
            }
        }
    }
}

/// Modbus TCP (MBAP header + PDU) as the server frames it, and the requests served.
pub fn modbus_tcp(data: &[u8]) {
    use crate::k2::sim::rtu_frame::{self, Frame};
    let svc = service();
    let mut rest = data;
    while rest.len() >= 7 {
        let len = u16::from_be_bytes([rest[4], rest[5]]) as usize;
        if !(2..=254).contains(&len) || rest.len() < 6 + len {
            break;
        }
        let (unit, pdu) = (rest[6], &rest[7..6 + len]);
        if let Frame::Request { request, .. } = rtu_frame::decode_pdu(unit, pdu) {
            if let Some(r) = svc.handle(unit, &request) {
                let _ = rtu_frame::encode_pdu(request.function_code().value(), &r);
            }
        }
        rest = &rest[6 + len..];
    }
}

/// Modbus replies as the K2 driver's client reads them (TCP and RTU framing, every request
/// kind, bytes arriving in several chunk sizes).
pub fn modbus_client(data: &[u8]) {
    crate::k2::driver::fuzz_replies(data);
}

/// The PLC-side helper's mailbox: the input, in frames of the mailbox's size, written over
/// the mailbox as a client may (any byte of it), each frame followed by two scans of
/// `lib/k2_agent.il` in the simulator's scan engine, stepped scan by scan. Every scan is
/// checked ([`crate::k2::sim::agent_probe`]): the CPU stays in RUN, the heartbeat moves, a
/// waiting request gets [`crate::k2::agent::protocol::Command::decode`]'s verdict, and no
/// memory outside the mailbox and the request's SM bytes changes; a broken promise panics.
pub fn agent_mailbox(data: &[u8]) {
    use crate::core::Device;
    use crate::k2::agent::protocol;
    let mut probe = crate::k2::sim::agent_probe::AgentProbe::new();
    for frame in data.chunks(protocol::SIZE as usize).take(16) {
        if let Err(e) = probe.write_and_scan(frame).and_then(|_| probe.checked_scan()) {
            panic!("the helper broke the protocol: {e}");
        }
    }
    let _ = probe.status();
    let _: Vec<Event> = crate::k2::K2Ops::events(&mut probe.sim, true).unwrap_or_default();
    let _ = probe.sim.read(&[]);
}

/// The helper's mailbox address (`--agent VB3400`, `agent il`).
pub fn agent_base(data: &[u8]) {
    let _ = crate::k2::agent::protocol::parse_base(&text(data));
}

/// IL program text, compiled (parse + compile) for a simulated K2 and for a UMPK8.
pub fn il(data: &[u8]) {
    let t = text(data);
    let sim = crate::k2::sim::open("K205-16DT", Clock::stepped()).expect("the default model");
    let _ = sim.compile(&t, "fuzz.il");
    let _ = crate::umpk::sim::program::IlRunner::load(&t, "fuzz.il", &crate::umpk::model::MODELS[0]);
}

/// IL files as saved (core::encoding): UTF-8, UTF-16 with or without a byte-order mark, Windows-1251;
/// what decodes is compiled as a K2 program.
pub fn il_encoding(data: &[u8]) {
    if let Ok((t, _)) = crate::core::encoding::decode(data) {
        let sim = crate::k2::sim::open("K205-16DT", Clock::stepped()).expect("the default model");
        let _ = sim.compile(&t, "fuzz.il");
    }
}

/// FX programming port: the simulator's request side for the smallest model and the FX3U
/// (classic and E-command tables; bytes in 23-byte chunks, with a gap after every fourth) and
/// the driver's reply decoder.
pub fn fx_port(data: &[u8]) {
    use crate::fx::sim::{PortServer, Server};
    for model in ["FX1S", "FX3U"] {
        let model = crate::fx::model::Model::find(model).expect("a known model");
        let plc = std::sync::Mutex::new(crate::fx::memory::Memory::new(model));
        let mut server = PortServer::default();
        for (i, chunk) in data.chunks(23).enumerate() {
            let _ = server.feed(chunk, &plc);
            if i % 4 == 3 {
                server.gap();
            }
        }
    }
    let _ = crate::fx::port::decode_request(data);
    let count = data.first().map_or(0, |b| *b as usize);
    let _ = crate::fx::port::decode_read_reply(data, count);
}

/// FX computer link under every settings combination: the simulator's request side, and
/// the driver's reply framing and decoding with the values read out of data replies.
pub fn fx_link(data: &[u8]) {
    use crate::fx::link::{decode_reply, parse_values, reply_len, Header, Reply, Settings};
    use crate::fx::sim::{LinkServer, Server};
    let plc = std::sync::Mutex::new(crate::fx::memory::Memory::new(&crate::fx::model::MODELS[0]));
    for bits in 0..4u8 {
        let s = Settings { sum: bits & 1 != 0, format4: bits & 2 != 0, decimal_xy: bits == 3 };
        let mut server = LinkServer::new(0, s);
        for (i, chunk) in data.chunks(29).enumerate() {
            let _ = server.feed(chunk, &plc);
            if i % 4 == 3 {
                server.gap();
            }
        }
        let h = Header { station: 0, pc: 0xFF, wait: 0 };
        let mut rest = data;
        while let Some(n) = reply_len(rest, s) {
            if let Ok(Reply::Data(d)) = decode_reply(&rest[..n], h, s) {
                let _ = parse_values(&d, 4);
                let _ = parse_values(&d, 8);
            }
            rest = &rest[n..];
        }
    }
}

/// FX operand names, on every model over both protocols.
pub fn fx_operand(data: &[u8]) {
    use crate::fx::space::{FxSpace, Proto};
    let t = text(data);
    for m in crate::fx::model::MODELS {
        for proto in [Proto::Port, Proto::Link] {
            let _ = FxSpace::new(m, proto).parse_fx(&t);
        }
    }
}

/// FX instruction lists: translated and compiled for each model; a program that loads runs
/// a few scans on a simulated PLC (stepped clock moved 1 s between them).
pub fn fx_il(data: &[u8]) {
    let t = text(data);
    for m in crate::fx::model::MODELS {
        if let Ok(p) = crate::fx::program::Loaded::load(&t, "fuzz.il", m) {
            let clock = Clock::stepped();
            let mut plc = crate::fx::memory::Memory::with_clock(m, clock.clone());
            plc.load_program(p);
            for _ in 0..3 {
                clock.step(std::time::Duration::from_millis(2));
                plc.advance();
            }
        }
    }
}

/// UMPK: the simulator's command reader (every byte received, replies taken), the driver's
/// reply reader for every command's shape, with and without echo, and the form check of
/// what `umpk send` is given (each line).
pub fn umpk_reply(data: &[u8]) {
    use crate::umpk::codec::{check_form, parse_exchange, Command, Monitor};
    for line in data.split(|b| *b == b'\n') {
        let _ = check_form(line);
    }
    let mut sim = crate::umpk::sim::Umpk::new(&crate::umpk::model::MODELS[0], Clock::stepped());
    for chunk in data.chunks(17) {
        sim.receive(chunk);
        let _ = sim.take_all();
    }
    for c in Command::ALL {
        let sent = c.encode();
        for crlf in [None, Some(true), Some(false)] {
            let _ = parse_exchange(data, &sent, c.shape(), crlf);
        }
    }
    let _ = Monitor::decode(data);
}

/// UMPK Intel HEX program files: single records and whole-file validation.
pub fn umpk_hex(data: &[u8]) {
    use crate::umpk::hex::{pages, parse_file, Record};
    for line in data.split(|b| *b == b'\n') {
        let _ = Record::parse(line.strip_suffix(b"\r").unwrap_or(line));
    }
    for m in crate::umpk::model::MODELS {
        if let Ok(p) = parse_file(&text(data), m.program_bytes) {
            let _ = pages(&p);
        }
    }
}

/// A capture as `plcsh record show` reads it (pcapng or pcap, plcsh's own or another tool's,
/// damaged or not): parsed, reassembled, then every frame decoded.
pub fn pcapng(data: &[u8]) {
    if let Ok(rec) = crate::record::file::parse(data) {
        let _ = crate::record::decode::all(&rec.links, &rec.frames);
    }
}

/// A device server's Telnet stream (RFC 854/2217): fed whole and in two pieces, the decoder
/// must give the same data and events, and never more data bytes than came in.
pub fn rfc2217(data: &[u8]) {
    use crate::core::link::rfc2217::Decoder;
    let (mut whole, mut d1, mut e1) = (Decoder::default(), Vec::new(), Vec::new());
    whole.feed(data, &mut d1, &mut e1);
    assert!(d1.len() <= data.len());
    let cut = data.first().map_or(0, |b| usize::from(*b) % (data.len() + 1));
    let (mut parts, mut d2, mut e2) = (Decoder::default(), Vec::new(), Vec::new());
    parts.feed(&data[..cut], &mut d2, &mut e2);
    parts.feed(&data[cut..], &mut d2, &mut e2);
    assert_eq!((d1, e1), (d2, e2), "the same stream cut in two decodes the same");
}

/// The RFC 2217 server side (`sim serve --rfc2217`): any stream from a client, whole or cut
/// in two, gives the same data and the same answers, and both stay linear in its length (an
/// answer is at most a few bytes per command, and a command takes at least three bytes).
pub fn rfc2217_server(data: &[u8]) {
    use crate::cli::serve::rfc2217::Server;
    let (mut whole, mut d1, mut r1) = (Server::default(), Vec::new(), Vec::new());
    whole.feed(data, &mut d1, &mut r1);
    assert!(d1.len() <= data.len());
    assert!(r1.len() <= 8 * data.len(), "{} answer bytes for {} input bytes", r1.len(), data.len());
    let cut = data.first().map_or(0, |b| usize::from(*b) % (data.len() + 1));
    let (mut parts, mut d2, mut r2) = (Server::default(), Vec::new(), Vec::new());
    parts.feed(&data[..cut], &mut d2, &mut r2);
    parts.feed(&data[cut..], &mut d2, &mut r2);
    assert_eq!((d1, r1), (d2, r2), "the same stream cut in two is answered the same");
}

/// The bench file (parse only: no device is opened).
pub fn bench(data: &[u8]) {
    let _ = crate::wiring::bench::Bench::parse(&text(data), Path::new("fuzz/bench.toml"));
}

/// Control channels of served simulators: each line (at most the channel's line length) to
/// the K2's, the drive line's, the UMPK's and the FX PLC's control language, on in-process
/// simulators whose stepped clock moves between lines.
pub fn control(data: &[u8]) {
    let clock = Clock::stepped();
    let mut k2 = crate::k2::sim::K2Sim::new(&MODELS[0], clock.clone());
    let mut umpk = crate::umpk::sim::Umpk::new(&crate::umpk::model::MODELS[0], clock.clone());
    let mut fx = crate::fx::memory::Memory::with_clock(&crate::fx::model::MODELS[0], clock.clone());
    let mut servo = crate::servo::sim::SimLine::new(&[1], clock.clone());
    for line in data.split(|b| *b == b'\n').take(64) {
        let line = text(&line[..line.len().min(crate::core::link::control::MAX_LINE)]);
        let _ = crate::k2::sim::control::answer(&mut k2, &line, true);
        let _ = crate::umpk::sim::control::answer(&mut umpk, &line);
        let _ = crate::fx::control::answer(&mut fx, &line);
        let _ = crate::servo::sim::control::answer_line(&mut servo, &line);
        clock.step(std::time::Duration::from_millis(7));
    }
}

/// A lab's `lab.toml` (parse and check; the files it names are looked up in a folder that
/// does not exist, so nothing is read).
pub fn lab_toml(data: &[u8]) {
    let _ = crate::lab::config::Lab::parse(&text(data), Path::new("fuzz/no-such-lab"));
}

/// A snapshot's `umpk` section (a snapshot file is outside input): decoded, then restored onto
/// a simulated UMPK16, which must refuse or take it without panicking.
pub fn umpk_snapshot(data: &[u8]) {
    let Ok(state) = serde_json::from_slice::<crate::umpk::sim::snapshot::UmpkState>(data) else { return };
    let clock = Clock::stepped();
    let mut u = crate::umpk::sim::Umpk::new(&crate::umpk::model::MODELS[1], clock.clone());
    if u.restore_snapshot(&state).is_ok() {
        clock.step(std::time::Duration::from_millis(50));
        u.advance(clock.now());
        let _ = u.snapshot_state();
    }
}

/// A tag file (CSV, TOML or IEC declarations, in any encoding): read in every format and by
/// detection, checked against every family, written back as CSV and IEC and read again; and
/// the bytes as an IL program with `VAR_GLOBAL` symbols, loaded by the simulated K2.
pub fn tags(data: &[u8]) {
    use crate::tags::{export, TagFormat, TagTable};
    let space = K2Space::new(&MODELS[0]);
    for f in [None, Some(TagFormat::Csv), Some(TagFormat::Toml), Some(TagFormat::Iec)] {
        let Ok(t) = TagTable::parse(data, "fuzz.tags", f) else { continue };
        let _ = t.suggest("Conveyor_Run");
        if let Ok(t) = crate::profile::tags::check(t, &space) {
            let csv = export::to_csv(&t);
            let back = TagTable::parse_text(&csv, "fuzz.csv", Some(TagFormat::Csv));
            assert!(back.is_ok_and(|b| b.len() == t.len()), "the CSV export reads back");
            if let Ok(iec) = export::to_iec(&t, &space) {
                let back = TagTable::parse_text(&iec, "fuzz.st", Some(TagFormat::Iec));
                assert!(back.is_ok_and(|b| b.len() == t.len()), "the IEC export reads back");
            }
        }
    }
    let sim = crate::k2::sim::K2Sim::new(&MODELS[0], Clock::stepped());
    let _ = sim.compile(&text(data), "fuzz.il");
}

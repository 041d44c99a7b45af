//! Every example is a test: the fenced examples of README.md and docs/*.md, run against the
//! simulator as a reader would type them, comparing the output a page shows. The convention is
//! docs/examples.md: `sh` lines that start with `plcsh`, `text` blocks that show a session
//! (`$ plcsh …` or a `NAME(sim)>` prompt), `lua` snippets and `toml` files are examples; an HTML
//! comment before a block marks one that needs hardware (`<!-- example: hardware -->`: run against
//! a simulator of the same family) or cannot run here (`<!-- example: skip (REASON) -->`).
#![cfg(unix)]

mod common;
use common::*;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// One fenced block: where it is, its info string, its text and the marker before it.
struct Block {
    at: String,
    info: String,
    text: String,
    marker: Option<String>,
}

/// A block being read: its first line, info string, lines so far and marker.
type OpenBlock<'a> = (usize, String, Vec<&'a str>, Option<String>);

fn blocks(path: &Path, name: &str) -> Vec<Block> {
    let doc = std::fs::read_to_string(path).unwrap();
    let mut out: Vec<Block> = Vec::new();
    let mut open: Option<OpenBlock> = None;
    let mut last_comment: Option<String> = None;
    for (i, line) in doc.lines().enumerate() {
        if let Some((start, info, body, marker)) = open.as_mut() {
            if line.starts_with("```") {
                out.push(Block {
                    at: format!("{name}:{}", *start + 1),
                    info: info.clone(),
                    text: body.join("\n"),
                    marker: marker.take(),
                });
                open = None;
            } else {
                body.push(line);
            }
            continue;
        }
        if let Some(info) = line.strip_prefix("```") {
            open = Some((i, info.trim().to_string(), Vec::new(), last_comment.take()));
        } else if let Some(c) = line.trim().strip_prefix("<!-- example:") {
            last_comment = Some(c.trim_end_matches("-->").trim().to_string());
        } else if !line.trim().is_empty() {
            last_comment = None;
        }
    }
    out
}

/// Every page: the README, CHANGELOG.md, docs/*.md and docs/reference/*.md.
fn pages() -> Vec<(PathBuf, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut v = vec![
        (root.join("README.md"), "README.md".to_string()),
        (root.join("CHANGELOG.md"), "CHANGELOG.md".to_string()),
    ];
    for dir in ["docs", "docs/reference"] {
        let mut docs: Vec<_> = std::fs::read_dir(root.join(dir))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "md"))
            .collect();
        docs.sort();
        for p in docs {
            let n = format!("{dir}/{}", p.file_name().unwrap().to_string_lossy());
            v.push((p, n));
        }
    }
    v
}

/// A working directory for the examples: the project's scripts, lib, machines and docs are
/// there as in a checkout, and whatever an example writes stays out of the repository.
fn workdir() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("plcsh-doc-examples-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for d in ["scripts", "lib", "machines", "docs", "completions", "assets"] {
        if root.join(d).exists() {
            std::os::unix::fs::symlink(root.join(d), dir.join(d)).unwrap();
        }
    }
    dir
}

/// The URL scheme of a device argument (`NAME=URL` or `URL`), if it is a URL.
fn scheme(dev: &str) -> Option<&str> {
    let url = dev.split_once('=').filter(|(n, _)| !n.contains(':')).map_or(dev, |(_, u)| u);
    let s = url.split_once(':')?.0;
    (!s.is_empty() && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '+')).then_some(s)
}

/// A hardware URL's simulator of the same family (`None` for a simulator URL).
fn same_family(url: &str) -> Option<String> {
    let s = scheme(url)?;
    let param = |k: &str| url.split(['?', '&']).find_map(|p| p.strip_prefix(&format!("{k}=")).map(str::to_string));
    let family = s.split('+').next().unwrap();
    let name = url.split_once('=').filter(|(n, _)| !n.contains(':')).map(|(n, _)| format!("{n}="));
    let sim = match family {
        "tcp" | "rtu" => format!("sim:{}", param("model").unwrap_or_else(|| "K205-16DT".into())),
        "kinco" => format!("sim-servo:?id={}", param("id").unwrap_or_else(|| "1".into())),
        "fx" | "fxlink" => "sim-fx:FX2N".to_string(),
        "umpk" => format!("sim-umpk:{}", param("model").unwrap_or_else(|| "UMPK8".into())),
        _ => return None,
    };
    Some(format!("{}{sim}", name.unwrap_or_default()))
}

/// Shell words as the pages quote them: single and double quotes, spaces.
fn words(line: &str) -> Vec<String> {
    let (mut out, mut cur, mut quote, mut any) = (Vec::new(), String::new(), None, false);
    for c in line.chars() {
        match (quote, c) {
            (None, '\'' | '"') => (quote, any) = (Some(c), true),
            (Some(q), _) if c == q => quote = None,
            (None, ' ') => {
                if any || !cur.is_empty() {
                    out.push(std::mem::take(&mut cur));
                }
                any = false;
            }
            (None, '#') if cur.is_empty() && !any => break,
            _ => cur.push(c),
        }
    }
    if any || !cur.is_empty() {
        out.push(cur);
    }
    out
}

/// Quotes a word for `sh -c`.
fn quote(w: &str) -> String {
    format!("'{}'", w.replace('\'', "'\\''"))
}

/// A served simulated K2 standing in for a K2 on the wire: the same model, unit id and helper
/// mailbox as the URL asks for, on Modbus TCP, RTU over TCP and RTU on a pty.
fn served_k2(dir: &Path, url: &str) -> Option<(Served, String)> {
    let (name, url) = match url.split_once('=').filter(|(n, _)| !n.contains(':')) {
        Some((n, u)) => (format!("{n}="), u),
        None => (String::new(), url),
    };
    let (scheme, rest) = url.split_once(':')?;
    if !matches!(scheme, "tcp" | "rtu" | "rtu+tcp") {
        return None;
    }
    let query = rest.split_once('?').map_or("", |(_, q)| q);
    let param = |k: &str| query.split('&').find_map(|p| p.strip_prefix(&format!("{k}=")));
    let default_model = if scheme == "tcp" { "K204ET-16DT" } else { "K205-16DT" };
    static SERVED: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let link = dir.join(format!("k2-{}", SERVED.fetch_add(1, std::sync::atomic::Ordering::Relaxed)));
    let link_s = link.display().to_string();
    let model = param("model").unwrap_or(default_model).to_string();
    let mut args = vec!["--tcp", "0", "--rtu-tcp", "0", "--rtu-pty", &link_s, "--model", &model];
    if let Some(u) = param("unit") {
        args.extend(["--unit", u]);
    }
    if let Some(a) = param("agent") {
        args.extend(["--agent", a]);
    }
    let s = serve(&args);
    let q = if query.is_empty() { String::new() } else { format!("?{query}") };
    let to = match scheme {
        "tcp" => format!("tcp://{}{q}", s.ready["tcp"].as_str()?),
        "rtu+tcp" => format!("rtu+tcp://{}{q}", s.ready["rtu_tcp"].as_str()?),
        _ => format!("rtu:{link_s}{q}"),
    };
    Some((s, format!("{name}{to}")))
}

/// A `plcsh …` line with its hardware devices replaced by simulators of the same family
/// (`hardware` blocks): a K2 on the wire by a served simulated K2 on the same transport, other
/// families by their in-process simulators. `Err` names a hardware device in an unmarked block.
fn rewrite(
    dir: &Path,
    line: &str,
    hardware: bool,
    served: &dyn Fn(&str) -> bool,
) -> Result<(String, Vec<Served>), String> {
    let mut w = words(line);
    let mut servers = Vec::new();
    for i in 1..w.len() {
        // A device after -d, or the PLC `probe URL` and `agent check URL` take as their argument.
        let positional = w[i - 1] == "probe" || (i >= 2 && w[i - 2] == "agent" && w[i - 1] == "check");
        if matches!(w[i - 1].as_str(), "-d" | "--device") || positional {
            if let Some(sim) = same_family(&w[i]).filter(|_| !served(&w[i])) {
                if !hardware {
                    return Err(format!("needs hardware ({}): mark the block", w[i]));
                }
                w[i] = match served_k2(dir, &w[i]) {
                    Some((s, url)) => {
                        servers.push(s);
                        url
                    }
                    None => sim,
                };
            }
        }
    }
    Ok((w.iter().map(|s| quote(s)).collect::<Vec<_>>().join(" "), servers))
}

/// Runs a shell line in `dir` with `plcsh` on PATH and the test's private HOME.
fn sh(dir: &Path, line: &str, stdin: &str) -> std::process::Output {
    let bindir = Path::new(bin()).parent().unwrap();
    let path = format!("{}:{}", bindir.display(), std::env::var("PATH").unwrap_or_default());
    let home = dir.join("home");
    let child = Command::new("sh")
        .arg("-c")
        .arg(line)
        .current_dir(dir)
        .env("PATH", path)
        .env("HOME", &home)
        .env("XDG_DATA_HOME", home.join("data"))
        .env("XDG_CONFIG_HOME", home.join("config"))
        .env("PLCSH_STATE", "none")
        // English unless an example says --lang: the pages show English output.
        .env("PLCSH_LANG", "en")
        .env_remove("PLCSH_CONFIG")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    output_with_input(child, stdin.as_bytes())
}

/// Whitespace-insensitive: runs of spaces are one space.
/// A leading wall-clock time column (`0.005166  plc → …`, as `record show` prints) is volatile:
/// it is compared as `T`.
fn norm(s: &str) -> String {
    let mut w: Vec<&str> = s.split_whitespace().collect();
    if let Some(first) = w.first() {
        let timestamp = first.split_once('.').is_some_and(|(a, b)| {
            !a.is_empty()
                && a.bytes().all(|c| c.is_ascii_digit())
                && b.len() == 6
                && b.bytes().all(|c| c.is_ascii_digit())
        });
        if timestamp && w.len() > 1 {
            w[0] = "T";
        }
    }
    w.join(" ")
}

/// Whether every shown line appears in what plcsh printed, in order within its stream (results on
/// stdout, errors on stderr, as a terminal interleaves them); `…` in a shown line stands for anything.
fn shows(shown: &[&str], o: &std::process::Output) -> Result<(), String> {
    let streams: [Vec<String>; 2] = [stdout(o).lines().map(norm).collect(), stderr(o).lines().map(norm).collect()];
    let mut at = [0, 0];
    for s in shown {
        let s = norm(s);
        if s.is_empty() || s == "…" {
            continue;
        }
        let parts: Vec<&str> = s.split('…').collect();
        let fits = |g: &String| {
            let mut pos = 0;
            parts.iter().all(|p| match g[pos..].find(p) {
                Some(k) => {
                    pos += k + p.len();
                    true
                }
                None => false,
            })
        };
        let found = (0..2).find_map(|k| streams[k][at[k]..].iter().position(fits).map(|i| (k, i)));
        match found {
            Some((k, i)) => at[k] += i + 1,
            None => return Err(format!("shown line not in the output: {s:?}")),
        }
    }
    Ok(())
}

/// Is this line a REPL prompt (`plc(sim)> get VW0`)? Returns the command typed.
fn prompt(line: &str) -> Option<&str> {
    let (head, cmd) = line.split_once("> ")?;
    let name = head.split('(').next().unwrap();
    (!name.is_empty() && name.chars().all(|c| c.is_alphanumeric() || c == '_' || c == '-') && !head.contains(' ')
        || head.contains("(sim") && !head.starts_with(' '))
    .then_some(cmd)
}

#[derive(Default)]
struct Tally {
    run: usize,
    skipped: usize,
    failures: Vec<String>,
}

impl Tally {
    fn check(&mut self, at: &str, what: &str, r: Result<(), String>) {
        self.run += 1;
        if let Err(e) = r {
            self.failures.push(format!("{at}: {what}\n    {e}"));
        }
    }
}

fn ok_or_err(o: &std::process::Output, expect_ok: bool) -> Result<(), String> {
    if o.status.success() == expect_ok {
        Ok(())
    } else {
        Err(format!("exit {:?}: {}", o.status.code(), both(o)))
    }
}

/// A `plcsh sim serve` line, started with its ports on 0 and its links and files in `dir`, kept
/// running for the rest of its block: its readiness line is the example's outcome, and what it
/// bound replaces what the page shows (`127.0.0.1:5020`, `/tmp/k2`) in the block's later lines.
fn serve_line(dir: &Path, line: &str, subs: &mut Vec<(String, String)>) -> Result<std::process::Child, String> {
    let mut w = words(line);
    w.retain(|x| x != "&" && !(x.starts_with('[') && x.ends_with(']')));
    let mut ports = Vec::new();
    for i in 1..w.len() {
        let flag = w[i - 1].clone();
        if flag.ends_with("-tcp") || flag == "--tcp" {
            let port = w[i].rsplit(':').next().unwrap().to_string();
            ports.push((flag.trim_start_matches("--").replace('-', "_"), port));
            w[i] = "0".into();
        } else if flag.ends_with("-pty") || flag.ends_with("-control") || (flag == "--state" && w[i] != "none") {
            let new = dir.join(Path::new(&w[i]).file_name().unwrap()).display().to_string();
            subs.push((w[i].clone(), new.clone()));
            w[i] = new;
        }
    }
    let args: Vec<&str> = w[3..].iter().map(String::as_str).collect();
    let mut child = plcsh()
        .current_dir(dir)
        .args(["sim", "serve"])
        .args(&args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| e.to_string())?;
    let mut first = String::new();
    use std::io::BufRead;
    let _ = std::io::BufReader::new(child.stdout.take().unwrap()).read_line(&mut first);
    match serde_json::from_str::<serde_json::Value>(&first) {
        Ok(v) if v["ready"] == true || v["ok"] == true => {
            for (key, port) in ports {
                if let Some(addr) = v[&key].as_str() {
                    for host in ["127.0.0.1", "localhost"] {
                        subs.push((format!("{host}:{port}"), addr.to_string()));
                        subs.push((format!("{host}:PORT"), addr.to_string()));
                    }
                    subs.push((addr.to_string(), addr.to_string()));
                }
            }
            Ok(child)
        }
        _ => {
            plcsh::core::platform::terminate_child(&child);
            let out = child.wait_with_output().map_err(|e| e.to_string())?;
            Err(format!("no readiness line: {first:?} {}", String::from_utf8_lossy(&out.stderr)))
        }
    }
}

/// A failing example (`fails` blocks) fails cleanly: exit status 1 and an `error[…]` message.
fn fails_cleanly(o: &std::process::Output) -> Result<(), String> {
    if o.status.code() == Some(1) && both(o).contains("error[") {
        Ok(())
    } else {
        Err(format!("expected a clean error (exit 1, error[…]): exit {:?}: {}", o.status.code(), both(o)))
    }
}

/// The lines of an `sh` block: a command whose single quote spans lines is one line, and the
/// lines under a command that are not commands themselves are its shown output.
fn sh_commands(text: &str) -> Vec<(String, Vec<String>)> {
    const OTHER: [&str; 11] =
        ["tshark", "mbpoll", "picocom", "socat", "cargo", "rustup", "mkdir", "cp", ".", "sudo", "npm"];
    let mut out: Vec<(String, Vec<String>)> = Vec::new();
    let mut pending = String::new();
    let mut in_output = false;
    for line in text.replace("\\\n", " ").lines() {
        if !pending.is_empty() {
            pending.push(' ');
            pending.push_str(line.trim());
            if pending.matches('\'').count().is_multiple_of(2) {
                out.push((std::mem::take(&mut pending), Vec::new()));
            }
            continue;
        }
        let l = line.trim();
        let first = l.split_whitespace().next().unwrap_or("");
        if l.starts_with("plcsh ") || l.starts_with("printf ") {
            in_output = !l.starts_with("plcsh sim serve");
            if !l.matches('\'').count().is_multiple_of(2) {
                pending = l.to_string();
            } else {
                out.push((l.to_string(), Vec::new()));
            }
        } else if l.is_empty() || l.starts_with('#') || OTHER.contains(&first) {
            in_output = false;
        } else if in_output {
            if let Some(last) = out.last_mut() {
                last.1.push(l.to_string());
            }
        }
    }
    out
}

/// An `sh` block: its `plcsh` lines run in order (servers kept for the block), and the output a
/// command shows under it must appear in what it printed.
fn run_sh_block(dir: &Path, b: &Block, marker: &str, t: &mut Tally) {
    let hardware = marker.starts_with("hardware");
    let mut subs: Vec<(String, String)> = Vec::new();
    let mut servers = Vec::new();
    for (line, shown) in sh_commands(&b.text) {
        let mut l = line;
        let is_plcsh = l.starts_with("plcsh ") || (l.starts_with("printf ") && l.contains("| plcsh"));
        if !is_plcsh {
            continue;
        }
        if l.starts_with("plcsh sim serve") {
            match serve_line(dir, &l, &mut subs) {
                Ok(child) => {
                    servers.push(child);
                    t.check(&b.at, &l, Ok(()))
                }
                Err(e) => t.check(&b.at, &l, Err(e)),
            }
            continue;
        }
        for (from, to) in &subs {
            l = l.replace(from, to);
        }
        let served = |u: &str| subs.iter().any(|(_, to)| u.contains(to.as_str()));
        let shown: Vec<&str> = shown.iter().map(String::as_str).collect();
        let expect = |o: &std::process::Output| {
            let status = if marker == "fails" { fails_cleanly(o) } else { ok_or_err(o, true) };
            status.and_then(|_| shows(&shown, o).map_err(|e| format!("{e}\n--- output:\n{}", both(o))))
        };
        if l.starts_with("printf ") {
            let o = sh(dir, &l, "");
            t.check(&b.at, &l, expect(&o));
            continue;
        }
        let (cmd, redirect) = match l.split_once(" > ") {
            Some((c, r)) => (c.to_string(), format!(" > {}", quote(words(r)[0].as_str()))),
            None => (l.clone(), String::new()),
        };
        match rewrite(dir, &cmd, hardware, &served) {
            Err(e) => t.check(&b.at, &l, Err(e)),
            Ok((cmd, _servers)) => {
                let o = sh(dir, &format!("{cmd}{redirect}"), "");
                t.check(&b.at, &l, expect(&o));
            }
        }
    }
    for s in servers {
        plcsh::core::platform::terminate_child(&s);
        let _ = s.wait_with_output();
    }
}

/// A `text` block showing a session: `$ plcsh …` lines (one-shot, or starting a REPL whose
/// prompt lines follow) and the output shown under each.
fn run_session_block(dir: &Path, b: &Block, hardware: bool, t: &mut Tally) {
    let lines: Vec<&str> = b.text.lines().collect();
    let mut i = 0;
    while i < lines.len() {
        let Some(cmd) = lines[i].strip_prefix("$ ") else {
            i += 1;
            continue;
        };
        let at = format!("{} ({})", b.at, cmd);
        i += 1;
        let (mut typed, mut shown) = (Vec::new(), Vec::new());
        while i < lines.len() && !lines[i].starts_with("$ ") {
            // `.. ` continues an unfinished Lua chunk: typed, as a prompt line is.
            match prompt(lines[i]).or_else(|| lines[i].strip_prefix("..")) {
                Some(c) => typed.push(c.split(" # ").next().unwrap().trim_end()),
                None if !lines[i].starts_with("  ") || !lines[i].trim_start().starts_with('^') => shown.push(lines[i]),
                None => {}
            }
            i += 1;
        }
        let cmd = cmd.split(" # ").next().unwrap().trim();
        let (cmd, _servers) = match rewrite(dir, cmd, hardware, &|_| false) {
            Ok(c) => c,
            Err(e) => {
                t.check(&at, "", Err(e));
                continue;
            }
        };
        // On a simulator of the same family a real device's lines say `(sim)`.
        let shown: Vec<String> =
            shown.iter().map(|l| if hardware { l.replace("(real)", "(sim)") } else { l.to_string() }).collect();
        let shown: Vec<&str> = shown.iter().map(String::as_str).collect();
        let stdin = typed.iter().map(|c| format!("{c}\n")).collect::<String>();
        let o = sh(dir, &cmd, &stdin);
        // A shown error is the example's point; the session then exits 1 as plcsh does.
        let shown_error = shown.iter().any(|l| l.starts_with("error["));
        let mut r = shows(&shown, &o);
        if r.is_ok() && !shown_error && !o.status.success() {
            r = ok_or_err(&o, true);
        }
        t.check(&at, "session", r.map_err(|e| format!("{e}\n--- output:\n{}", both(&o))));
    }
}

fn run_lua_block(dir: &Path, b: &Block, n: usize, t: &mut Tally) {
    let file = dir.join(format!("example{n}.lua"));
    std::fs::write(&file, &b.text).unwrap();
    let o = sh(dir, &format!("plcsh --state none --time stepped run {}", quote(&file.display().to_string())), "");
    t.check(&b.at, "lua", ok_or_err(&o, true));
}

/// A `toml` block: a profile file, a tag file, a bench file or a lab's `lab.toml` (checked with the files
/// of `plcsh lab new` around it). `<!-- example: file NAME [after FILE] -->` writes it as NAME
/// (after the project's FILE) for the examples that follow to open.
fn run_toml_block(dir: &Path, b: &Block, marker: &str, n: usize, t: &mut Tally) {
    let mut file = dir.join(format!("example{n}.toml"));
    let mut text = b.text.clone();
    if let Some(spec) = marker.strip_prefix("file ") {
        let w: Vec<&str> = spec.split_whitespace().collect();
        file = dir.join(w[0]);
        if let (Some(&"after"), Some(base)) = (w.get(1), w.get(2)) {
            let root = Path::new(env!("CARGO_MANIFEST_DIR"));
            text = format!("{}\n{text}\n", std::fs::read_to_string(root.join(base)).unwrap());
        }
    }
    std::fs::write(&file, &text).unwrap();
    let f = quote(&file.display().to_string());
    let r = if b.text.contains("grader =") {
        // A lab: the example lab's files with this lab.toml; its reference gets every point.
        let lab = dir.join(format!("lab-example{n}"));
        let q = quote(&lab.display().to_string());
        let o = sh(dir, &format!("plcsh lab new {q} && cp {f} {q}/lab.toml && plcsh lab check {q}"), "");
        ok_or_err(&o, true)
    } else if b.text.contains("[devices.") {
        // A profile file: loaded with no problem reported.
        let o = sh(dir, &format!("plcsh --state none --config {f} devices --json"), "");
        ok_or_err(&o, true).and_then(|_| {
            let out = both(&o);
            if out.contains("problem") && out.contains(&*file.display().to_string()) {
                Err(format!("the file has a problem: {out}"))
            } else {
                Ok(())
            }
        })
    } else if b.text.contains("[tags]") {
        // A tag file (docs/tags.md): it checks without a problem.
        let o = sh(dir, &format!("plcsh tags check {f}"), "");
        ok_or_err(&o, true)
    } else {
        // A bench file: the machine it describes opens.
        let o = sh(dir, &format!("plcsh --state none --time stepped --bench {f} -c devices"), "");
        ok_or_err(&o, true)
    };
    t.check(&b.at, "toml", r);
}

#[test]
fn every_example_in_the_readme_and_docs_runs() {
    let dir = workdir();
    let mut t = Tally::default();
    let mut n = 0;
    for (path, name) in pages() {
        for b in blocks(&path, &name) {
            n += 1;
            let marker = b.marker.clone().unwrap_or_default();
            if marker.starts_with("skip") {
                assert!(marker.contains('('), "{}: a skipped example says why: `skip (REASON)`", b.at);
                t.skipped += 1;
                continue;
            }
            let hardware = marker.starts_with("hardware");
            match b.info.as_str() {
                "sh" => run_sh_block(&dir, &b, &marker, &mut t),
                "text" | "" if b.text.lines().any(|l| l.starts_with("$ plcsh")) => {
                    run_session_block(&dir, &b, hardware, &mut t)
                }
                "text" if b.text.lines().any(|l| prompt(l).is_some()) => {
                    t.check(&b.at, "a session without its `$ plcsh …` line", Err("start it with `$ plcsh …`".into()))
                }
                "lua" => run_lua_block(&dir, &b, n, &mut t),
                "toml" => run_toml_block(&dir, &b, &marker, n, &mut t),
                _ => {}
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    println!("doc examples: {} run, {} skipped (marked), {} failed", t.run, t.skipped, t.failures.len());
    assert!(t.failures.is_empty(), "{} of {} examples failed:\n{}", t.failures.len(), t.run, t.failures.join("\n"));
    assert!(t.run >= 60, "only {} examples ran", t.run);
}

/// A heading's anchor, as GitHub and mdBook make it: lower case, spaces to `-`, punctuation dropped.
fn anchor(heading: &str) -> String {
    let h = heading.trim_start_matches('#').trim().to_lowercase();
    h.chars()
        .filter(|c| c.is_alphanumeric() || matches!(c, '-' | '_' | ' '))
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// The anchors of a page's headings (outside fenced blocks).
fn anchors(path: &Path) -> Vec<String> {
    let mut fence = false;
    let mut out = Vec::new();
    for l in std::fs::read_to_string(path).unwrap_or_default().lines() {
        if l.starts_with("```") {
            fence = !fence;
        } else if !fence && l.starts_with('#') && l.trim_start_matches('#').starts_with(' ') {
            out.push(anchor(l));
        }
    }
    out
}

/// No link leaves the repository: every Markdown link of the README and docs/ names a file of
/// the checkout, and an anchor into a page names one of its headings.
#[test]
fn every_link_stays_in_the_repository() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).canonicalize().unwrap();
    let mut bad = Vec::new();
    let mut count = 0;
    for (path, name) in pages() {
        let doc = std::fs::read_to_string(&path).unwrap();
        for (k, _) in doc.match_indices("](") {
            let rest = &doc[k + 2..];
            let Some(end) = rest.find(')') else { continue };
            let target = &rest[..end];
            if target.contains(' ') {
                continue;
            }
            count += 1;
            let (file, frag) = target.split_once('#').unwrap_or((target, ""));
            let full = if file.is_empty() { path.clone() } else { path.parent().unwrap().join(file) };
            let into_page = (!frag.is_empty() && file.ends_with(".md")) || file.is_empty();
            if into_page && !anchors(&full).iter().any(|a| a == frag) {
                bad.push(format!("{name}: {target} (no such heading)"));
            }
            match full.canonicalize() {
                Ok(p) if p.starts_with(&root) && !target.contains("://") => {}
                _ => bad.push(format!("{name}: {target}")),
            }
        }
    }
    println!("doc links: {count} checked");
    assert!(bad.is_empty(), "links that leave the repository or name no file:\n{}", bad.join("\n"));
    assert!(count >= 30, "only {count} links");
}

//! The interactive loop (rustyline) and the non-interactive one (commands from a pipe,
//! no prompt or echo). History persists in the user's data directory.

use super::helper::ShellHelper;
use super::Shell;
use crate::session::Session;
use rustyline::error::ReadlineError;
use std::io::{BufRead, Write};
use std::path::PathBuf;

/// Where the REPL keeps its history (`~/.local/share/plcsh/history.txt` on Linux).
pub fn history_path() -> Option<PathBuf> {
    crate::paths::history()
}

/// Runs the interactive REPL until `quit` or end of input. Returns the exit status.
pub fn interactive(shell: &mut Shell) -> i32 {
    let config = rustyline::Config::builder().completion_type(rustyline::CompletionType::List).build();
    let mut ed: rustyline::Editor<ShellHelper, rustyline::history::DefaultHistory> =
        match rustyline::Editor::with_config(config) {
            Ok(e) => e,
            Err(e) => {
                eprintln!("{}", crate::msg!("repl-no-line-editor", error = e.to_string()));
                return 1;
            }
        };
    ed.set_helper(Some(ShellHelper::new(shell.style.color)));
    let history = history_path();
    if let Some(h) = &history {
        let _ = ed.load_history(h);
    }
    let mut out = std::io::stdout();
    let _ = writeln!(out, "{}", banner(&device_list(shell)));
    loop {
        let prompt = prompt(&shell.session);
        // Lend the session to the completer while the line is read (see helper.rs).
        let placeholder = Session::new(shell.session.clock.clone());
        if let Some(h) = ed.helper_mut() {
            h.prompt_width = prompt.chars().count();
            h.session = Some(std::mem::replace(&mut shell.session, placeholder));
        }
        crate::signals::set_idle(true);
        let read = ed.readline(&prompt);
        crate::signals::set_idle(false);
        if let Some(s) = ed.helper_mut().and_then(|h| h.session.take()) {
            shell.session = s;
        }
        match read {
            Ok(text) => {
                // New input after a Ctrl-C that was handled: the next stop counts again.
                shell.session.clear_interrupt();
                crate::signals::handled();
                // A pasted block arrives as one input with bracketed paste (the terminal marks
                // it), or as keystrokes read ahead without it (kept by rustyline's buffer):
                // either way every line runs in order, as if typed one after another.
                let mut lines: std::collections::VecDeque<String> = text.split('\n').map(str::to_string).collect();
                while let Some(mut line) = lines.pop_front() {
                    if line.trim().is_empty() {
                        continue;
                    }
                    // An unfinished Lua chunk continues on the next line.
                    while shell.needs_more(&line) {
                        let more = match lines.pop_front() {
                            Some(l) => l,
                            None => match ed.readline(".. ") {
                                Ok(more) => more,
                                Err(_) => break,
                            },
                        };
                        line.push('\n');
                        line.push_str(&more);
                    }
                    if text.contains('\n') {
                        // Each pasted line is echoed before its output, as a typed one would be.
                        let _ = writeln!(out, "{prompt}{line}");
                    }
                    let _ = ed.add_history_entry(line.as_str());
                    shell.run_line(&line, &mut out);
                    if shell.quit {
                        break;
                    }
                    if shell.session.interrupted() {
                        if !crate::signals::is_ctrl_c() && crate::signals::exit_status().is_some() {
                            // SIGTERM or SIGHUP: the session ends (its status is the signal's).
                            shell.quit = true;
                            break;
                        }
                        // Ctrl-C: back to the prompt; the rest of a pasted block and what was
                        // typed ahead are dropped, not run.
                        crate::core::platform::discard_typed_ahead();
                        shell.session.clear_interrupt();
                        crate::signals::handled();
                        break;
                    }
                }
                if shell.quit {
                    break;
                }
            }
            Err(ReadlineError::Interrupted) => continue,
            Err(ReadlineError::Eof) => break,
            Err(e) => {
                eprintln!("{}", crate::msg!("repl-input-error", error = e.to_string()));
                break;
            }
        }
    }
    if let Some(h) = &history {
        if let Some(dir) = h.parent() {
            let _ = std::fs::create_dir_all(dir);
        }
        // Appended under the file's lock, never rewritten from this session's copy: two shells
        // open at once both keep their lines (the later one does not drop the earlier's).
        let _ = ed.append_history(h);
    }
    0
}

/// The REPL's first lines: the version and how to get help, then the open devices, wrapped
/// between words to 80 columns.
pub fn banner(devices: &str) -> String {
    let mut lines = vec![crate::msg!("repl-banner", version = env!("CARGO_PKG_VERSION")).text];
    let wrapped = crate::core::text::wrap(&crate::msg!("repl-devices", devices = devices), 77);
    lines.extend(wrapped.into_iter().enumerate().map(|(i, l)| if i == 0 { l } else { format!("  {l}") }));
    lines.join("\n")
}

fn device_list(shell: &Shell) -> String {
    shell
        .session
        .entries()
        .iter()
        .map(|e| {
            let (name, model) = (e.name.as_str(), e.device.info().model.as_str());
            if e.device.info().simulated {
                crate::msg!("repl-device-simulated", name = name, model = model).text
            } else {
                format!("{name} ({model} {})", e.url)
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// Runs commands from a reader, one line at a time, no prompt. Returns 0 when every
/// command succeeded, 1 otherwise.
pub fn batch(shell: &mut Shell, input: &mut dyn BufRead, out: &mut dyn Write) -> i32 {
    let mut ok = true;
    let mut line = String::new();
    loop {
        line.clear();
        crate::signals::set_idle(true);
        let read = input.read_line(&mut line);
        crate::signals::set_idle(false);
        match read {
            Ok(0) => break,
            Ok(_) => {}
            Err(e) => {
                eprintln!("{}", crate::msg!("repl-input-error", error = e.to_string()));
                return 1;
            }
        }
        let mut l = line.trim_end_matches(['\n', '\r']).to_string();
        if l.trim().is_empty() || l.trim_start().starts_with('#') {
            continue;
        }
        // An unfinished Lua chunk continues on the next line.
        while shell.needs_more(&l) {
            let mut more = String::new();
            if input.read_line(&mut more).unwrap_or(0) == 0 {
                break;
            }
            l.push('\n');
            l.push_str(more.trim_end_matches(['\n', '\r']));
        }
        ok &= shell.run_line(&l, out);
        if shell.quit {
            break;
        }
        if shell.session.interrupted() {
            // A stop ends the session: the rest of the input is not run.
            return crate::signals::exit_status().unwrap_or(130);
        }
    }
    i32::from(!ok)
}

/// The prompt: the current device's name, `(sim)` when it is simulated (`plc(sim)>`
/// against `press1>`), and `read-only` while the session-wide switch is on.
pub fn prompt(s: &Session) -> String {
    let mut marks: Vec<String> = Vec::new();
    let name = match s.current_index() {
        Ok(i) => {
            let e = &s.entries()[i];
            if e.device.info().simulated {
                marks.push("sim".into());
            }
            if crate::pending::is_not_connected(e.device.info()) {
                marks.push(crate::msg!("shell-prompt-not-connected").text);
            }
            e.name.clone()
        }
        Err(_) => "plcsh".to_string(),
    };
    if s.read_only() {
        marks.push("read-only".into());
    }
    if marks.is_empty() {
        format!("{name}> ")
    } else {
        format!("{name}({})> ", marks.join(", "))
    }
}

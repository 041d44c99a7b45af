//! `use`, `devices`, `connect`, `close`: naming and switching devices in the session.

use super::CommandSpec;
use crate::core::{Error, Result};
use crate::output::Outcome;
use crate::shell::{lex, Args, Shell};

pub const USE: CommandSpec = CommandSpec {
    name: "use",
    aliases: &[],
    usage: "use DEVICE",
    summary: || crate::msg!("summary-use"),
    subcommands: &[],
    run: use_cmd,
};

pub const DEVICES: CommandSpec = CommandSpec {
    name: "devices",
    aliases: &[],
    usage: "devices",
    summary: || crate::msg!("summary-devices"),
    subcommands: &[],
    run: devices,
};

pub const CONNECT: CommandSpec = CommandSpec {
    name: "connect",
    aliases: &["open"],
    usage: "connect NAME URL | connect PROFILE   e.g. connect press sim:K209EA-50DX, connect press1",
    summary: || crate::msg!("summary-connect"),
    subcommands: &[],
    run: connect,
};

pub const CLOSE: CommandSpec = CommandSpec {
    name: "close",
    aliases: &[],
    usage: "close NAME",
    summary: || crate::msg!("summary-close"),
    subcommands: &[],
    run: close,
};

/// The one name a command takes, its quotes removed by the shell's one quoting rule
/// ([`lex::unquote`]): `use 'k2'` names `k2`.
fn one_word(args: &Args, usage: &str) -> Result<String> {
    let w = lex::words(args.text)?;
    match w.as_slice() {
        [(_, name)] => Ok(lex::unquote(name).into_owned()),
        _ => Err(Error::usage(format!("usage: {usage}")).column(args.offset)),
    }
}

fn use_cmd(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let name = one_word(&args, USE.usage)?;
    sh.session.use_device(&name).map_err(|e| e.column(args.offset))?;
    let mut o = Outcome::new("use");
    o.device = Some(name);
    Ok(o.quiet())
}

fn devices(sh: &mut Shell, args: Args) -> Result<Outcome> {
    super::no_arguments("devices", args)?;
    let (rows, o) = super::profiles::devices_and_profiles(&sh.session);
    Ok(o.table(&["name", "family", "model", "url", "writes"], rows))
}

fn connect(sh: &mut Shell, args: Args) -> Result<Outcome> {
    // Quoted words are their text (a port path with a space: `connect k2 'rtu:/dev/my port'`).
    let w = lex::unquoted_words(args.text)?;
    let (name, url) = match w.as_slice() {
        [profile] => (profile, profile),
        [name, url] => (name, url),
        _ => return Err(Error::usage(format!("usage: {}", CONNECT.usage)).column(args.offset)),
    };
    sh.session.open(name, url)?;
    let mut o = Outcome::new("connect");
    o.device = Some(name.to_string());
    Ok(o.quiet())
}

fn close(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let name = one_word(&args, CLOSE.usage)?;
    sh.session.close(&name)?;
    Ok(Outcome::new("close").quiet())
}

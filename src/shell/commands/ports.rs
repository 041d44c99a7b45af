//! `ports`: the serial ports this computer has, with what the operating system knows of each
//! USB adapter (VID:PID, maker, product, serial number) — how a technician finds "which COM
//! is my USB-RS485 adapter" without Device Manager. The list is `core::link::serial::ports`.

use super::CommandSpec;
use crate::core::link::serial;
use crate::core::Result;
use crate::output::Outcome;
use crate::shell::{Args, Shell};

pub const PORTS: CommandSpec = CommandSpec {
    name: "ports",
    aliases: &[],
    usage: "ports",
    summary: || crate::msg!("summary-ports"),
    subcommands: &[],
    run: ports,
};

fn ports(_sh: &mut Shell, args: Args) -> Result<Outcome> {
    if !args.text.trim().is_empty() {
        return Err(crate::core::Error::usage(crate::msg!("shell-ports-no-arguments", extra = args.text.trim()))
            .hint("ports")
            .column(args.offset));
    }
    outcome()
}

/// The list, as a table and as `ports` in JSON.
pub fn outcome() -> Result<Outcome> {
    let list = serial::ports()?;
    let dash = |v: &Option<String>| v.clone().unwrap_or_else(|| "-".into());
    let rows: Vec<Vec<String>> = list
        .iter()
        .map(|p| {
            let adapter = [&p.manufacturer, &p.product].iter().filter_map(|v| v.as_deref()).collect::<Vec<_>>();
            vec![
                p.name.clone(),
                p.kind.to_string(),
                dash(&p.usb_id),
                if adapter.is_empty() { "-".into() } else { adapter.join(" ") },
                dash(&p.serial_number),
            ]
        })
        .collect();
    let mut o = Outcome::new("ports").with("ports", &list);
    if list.is_empty() {
        o = o.text(crate::msg!("shell-no-ports").text);
    } else {
        o = o.table(&crate::output::headings(crate::msg!("shell-ports-columns")), rows);
    }
    Ok(o)
}

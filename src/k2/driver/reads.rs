//! The wire driver's side of `plcsh probe` and `plcsh agent check`: one-unit reads that keep a
//! Modbus exception apart from a link failure ([`crate::k2::probe::Reader`]), and the helper
//! self-test over the device's mailbox ([`crate::k2::agent::check`]). Nothing here writes but
//! the check's mailbox commands.

use super::{Failure, K2Wire, Link, Op};
use crate::k2::agent::check;
use crate::k2::agent::client::AgentClient;
use crate::k2::agent::protocol as p;
use crate::k2::modbus_map::Table;
use crate::k2::probe::{Answer, Reader};
use crate::msg;
use std::time::Instant;

impl Reader for K2Wire {
    fn read(&mut self, table: Table, addr: u16) -> Answer {
        let start = Instant::now();
        match self.exchange(Op::Read(table.read_fc(), addr, 1)) {
            Ok(_) => {
                let data = self.ctx.as_ref().map(|c| c.data()).unwrap_or(&[]);
                let want = if table.is_bits() { 2 } else { 3 };
                if data.len() < want {
                    return Answer::Failed {
                        message: msg!("k2-reply-read-short", table = table.name(), addr = addr).into(),

                        hint: self.link.hint().to_string(),
                    };
                }
                Answer::Data(start.elapsed())
            }
            Err(Failure::Exception(c)) => Answer::Exception(u8::from(c)),
            Err(Failure::Link(e)) => Answer::Failed {
                hint: e.hint.clone().unwrap_or_else(|| self.link.hint().to_string()),
                message: e.message.clone(),
            },
        }
    }
}

impl K2Wire {
    /// What to check when the PLC does not answer on this link.
    pub fn link_hint(&self) -> String {
        self.link.hint()
    }

    /// The serial line's settings and the unit id, for a serial link (`None` on TCP).
    pub fn serial_line(&self) -> Option<String> {
        match &self.link {
            Link::Rtu { line, .. } | Link::RtuRfc2217 { line, .. } => {
                Some(format!("{line}, unit {}", self.settings.unit))
            }
            _ => None,
        }
    }

    /// Runs `plcsh agent check` on the helper at the device's `agent=VB…` (VB3400 without one).
    pub fn agent_check(&mut self) -> check::Report {
        let mut client = self.agent.take().unwrap_or_else(|| {
            let mut c = AgentClient::new(p::DEFAULT_BASE);
            c.timeout = self.settings.timeout.max(std::time::Duration::from_secs(1));
            c
        });
        let model = self.space.model;
        let r = check::run_wall(&mut client, &mut super::sm::VWords(self), model);
        self.agent = Some(client);
        r
    }
}

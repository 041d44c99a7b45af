//! The exit statuses of `plcsh`, in one table: what the command line returns and what a
//! shell script, CI job or `systemd` unit can rely on. The binary's entry point and the
//! stop signals return these constants, and the guide's reference page (docs/reference/exit-status.md)
//! is made from [`STATUSES`], so the page and the program cannot disagree.

use super::msg::{Lang, Msg};
use super::platform::code;
use super::ErrorKind;
use crate::msg;

/// Every command (or the script) succeeded.
pub const OK: i32 = 0;
/// A command, a script, a device in a fleet or a criterion failed (the message says which).
pub const FAILED: i32 = 1;
/// The command line is wrong: an unknown flag or subcommand, a missing value, a file named
/// on the command line that does not exist.
pub const USAGE: i32 = 2;
/// `plcsh publish`: the MQTT broker refused the credentials (no retry mends that).
pub const BROKER_AUTH: i32 = 3;
/// `plcsh publish`: the broker's TLS certificate did not verify, or no broker answered at the
/// start.
pub const BROKER_UNREACHABLE: i32 = 4;
/// SIGHUP (a dropped SSH session; on Windows, the console window closed).
pub const HANGUP: i32 = 128 + code::HUP;
/// Ctrl-C (SIGINT) stopped the work; the abort handlers ran.
pub const INTERRUPTED: i32 = 128 + code::INT;
/// SIGTERM (`timeout`, `systemctl stop`, CI; on Windows, Ctrl-Break).
pub const TERMINATED: i32 = 128 + code::TERM;

/// One exit status: its number, a short name and when `plcsh` returns it.
#[derive(Clone, Copy, Debug)]
pub struct Status {
    pub code: i32,
    /// Its short name and when it happens, from the catalogue (`engine.ftl`, ids `exit-…`);
    /// the reference page formats them in English.
    pub name: fn(Lang) -> Msg,
    pub when: fn(Lang) -> Msg,
}

/// The exit statuses, in order. A Lua script's `os.exit(N)` returns N (after its abort
/// handlers ran), which is not a status of plcsh's own and so not listed.
pub static STATUSES: &[Status] = &[
    Status { code: OK, name: |l| msg!(lang: l, "exit-ok-name"), when: |l| msg!(lang: l, "exit-ok-when") },
    Status { code: FAILED, name: |l| msg!(lang: l, "exit-failed-name"), when: |l| msg!(lang: l, "exit-failed-when") },
    Status { code: USAGE, name: |l| msg!(lang: l, "exit-usage-name"), when: |l| msg!(lang: l, "exit-usage-when") },
    Status {
        code: BROKER_AUTH,
        name: |l| msg!(lang: l, "exit-broker-refused-name"),
        when: |l| msg!(lang: l, "exit-broker-refused-when"),
    },
    Status {
        code: BROKER_UNREACHABLE,
        name: |l| msg!(lang: l, "exit-broker-unreachable-name"),
        when: |l| msg!(lang: l, "exit-broker-unreachable-when"),
    },
    Status { code: HANGUP, name: |l| msg!(lang: l, "exit-hangup-name"), when: |l| msg!(lang: l, "exit-hangup-when") },
    Status {
        code: INTERRUPTED,
        name: |l| msg!(lang: l, "exit-interrupted-name"),
        when: |l| msg!(lang: l, "exit-interrupted-when"),
    },
    Status {
        code: TERMINATED,
        name: |l| msg!(lang: l, "exit-terminated-name"),
        when: |l| msg!(lang: l, "exit-terminated-when"),
    },
];

/// The status a failed command line ends with: [`USAGE`] for a usage error, else [`FAILED`].
pub fn for_error(kind: ErrorKind) -> i32 {
    if kind == ErrorKind::Usage {
        USAGE
    } else {
        FAILED
    }
}

/// The status a stop signal asks for (128 + its number, as shells report it).
pub fn for_signal(sig: i32) -> i32 {
    128 + sig
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_has_each_status_once_in_order() {
        let codes: Vec<i32> = STATUSES.iter().map(|s| s.code).collect();
        assert_eq!(codes, [OK, FAILED, USAGE, BROKER_AUTH, BROKER_UNREACHABLE, HANGUP, INTERRUPTED, TERMINATED]);
        assert!(codes.windows(2).all(|w| w[0] < w[1]));
    }

    #[test]
    fn signal_statuses_are_128_plus_the_signal_as_shells_report_them() {
        assert_eq!((HANGUP, INTERRUPTED, TERMINATED), (129, 130, 143));
        assert_eq!(for_signal(code::TERM), TERMINATED);
        assert_eq!(for_error(ErrorKind::Usage), USAGE);
        assert_eq!(for_error(ErrorKind::Link), FAILED);
    }
}

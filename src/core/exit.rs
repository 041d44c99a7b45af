//! The exit statuses of `plcsh`, in one table: what the command line returns and what a
//! shell script, CI job or `systemd` unit can rely on. The binary's entry point and the
//! stop signals return these constants, and the guide's reference page (docs/reference/exit-status.md)
//! is made from [`STATUSES`], so the page and the program cannot disagree.

use super::platform::code;
use super::ErrorKind;

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
    pub name: &'static str,
    pub when: &'static str,
}

/// The exit statuses, in order. A Lua script's `os.exit(N)` returns N (after its abort
/// handlers ran), which is not a status of plcsh's own and so not listed.
pub static STATUSES: &[Status] = &[
    Status {
        code: OK,
        name: "ok",
        when: "every command succeeded; a script finished; every device of a fleet answered; \
               `sim serve` stopped by SIGTERM, SIGHUP or Ctrl-C; `publish` stopped by Ctrl-C, \
               SIGTERM or SIGHUP after every reading was delivered",
    },
    Status {
        code: FAILED,
        name: "failed",
        when: "a command, a script or a check failed (the `error[KIND]` message says which); one \
               device of a fleet failed; a lab criterion failed; a damaged recording was shown in part",
    },
    Status {
        code: USAGE,
        name: "usage",
        when: "the command line is wrong: unknown flag or subcommand, missing or bad value, a file \
               named with --config that does not exist, an unreadable recording",
    },
    Status {
        code: BROKER_AUTH,
        name: "broker refused",
        when: "`publish`: the MQTT broker refused the credentials (username, password or its ACL)",
    },
    Status {
        code: BROKER_UNREACHABLE,
        name: "broker unreachable",
        when: "`publish`: the broker's TLS certificate did not verify, or no broker answered within \
               10 s of the start",
    },
    Status {
        code: HANGUP,
        name: "SIGHUP",
        when: "the terminal went away (a dropped SSH session; Windows: the console window closed); \
               the running command stopped and the abort handlers ran",
    },
    Status {
        code: INTERRUPTED,
        name: "Ctrl-C",
        when: "Ctrl-C stopped a one-shot, a script or a fleet run; the abort handlers ran (in the \
               interactive shell Ctrl-C returns to the prompt instead)",
    },
    Status {
        code: TERMINATED,
        name: "SIGTERM",
        when: "SIGTERM (`timeout`, `systemctl stop`, CI; Windows: Ctrl-Break) stopped the work; the \
               abort handlers ran",
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

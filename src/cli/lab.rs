//! `plcsh lab new NAME`, `plcsh lab check LAB`, `plcsh lab grade LAB SUBMISSIONS… [--jobs N]
//! [--junit FILE]`: thin calls into [`crate::lab`]. A lab builds its own simulators from its
//! `lab.toml` (never the user's state file, profiles or `--device`s), so this runs before the
//! session is built. Exit status: `check` 1 when the reference does not get every point;
//! `grade` 0 when every submission was graded (whatever the grades), 1 on a grader error.

use crate::output::{self, Style};
use clap::Subcommand;
use std::io::Write;
use std::path::PathBuf;

#[derive(Subcommand, Debug)]
pub enum LabCmd {
    /// Write a working example lab (K2 + drive with wiring, IL starter, Lua grader) into NAME.
    New {
        /// The new lab's folder.
        name: PathBuf,
    },
    /// Check a lab: its lab.toml, files and start state, and the grader on the reference solution.
    Check {
        /// The lab folder (or its lab.toml).
        lab: PathBuf,
    },
    /// Grade submissions (files or folders of .lua / .il files), each in a fresh sandboxed worker.
    Grade {
        /// The lab folder (or its lab.toml).
        lab: PathBuf,
        /// Submission files or folders.
        #[arg(required = true)]
        submissions: Vec<PathBuf>,
        /// Worker processes at a time (default: one per core).
        #[arg(long, value_name = "N")]
        jobs: Option<usize>,
        /// Also write the results as JUnit XML to FILE.
        #[arg(long, value_name = "FILE")]
        junit: Option<PathBuf>,
        /// Show what each submission printed (stdout and stderr, the first 64 KiB of each);
        /// `--json` always carries them as `stdout` and `stderr`.
        #[arg(long)]
        show_output: bool,
    },
    /// Grade one submission and write its report as JSON to REPORT (what `lab grade` runs per
    /// submission; what the submission prints goes to stdout, never into the report).
    #[command(hide = true)]
    Worker {
        lab: PathBuf,
        submission: String,
        #[arg(long, value_name = "REPORT")]
        report: PathBuf,
        /// The submission's write directory, made private by the parent (which removes it).
        #[arg(long, value_name = "DIR")]
        write_dir: Option<PathBuf>,
    },
}

pub fn run(cmd: &LabCmd, style: Style, out: &mut dyn Write) -> i32 {
    let fail = |out: &mut dyn Write, name: &str, e: &crate::core::Error| {
        let _ = output::report_error(out, style, name, e, None);
        if e.kind == crate::core::ErrorKind::Usage {
            2
        } else {
            1
        }
    };
    match cmd {
        LabCmd::New { name } => match crate::lab::new_lab(name) {
            Ok(o) => i32::from(output::write_outcome(out, style, &o).is_err()),
            Err(e) => fail(out, "lab", &e),
        },
        LabCmd::Check { lab } => match crate::lab::check(lab) {
            Ok((o, head, ok)) => {
                if style.json {
                    let mut v = o.to_json();
                    v["ok"] = ok.into();
                    if !ok {
                        v["error"] = serde_json::json!({"kind": "state", "code": "lab-check-failed", "message": head});
                    }
                    let _ = writeln!(out, "{v}");
                } else {
                    let _ = writeln!(out, "{head}");
                    let _ = output::write_outcome(out, style, &o);
                    // Criteria a program passes without doing the task, named for the teacher.
                    let warnings = o.data.get("warnings").and_then(|w| w.as_array()).cloned().unwrap_or_default();
                    for w in warnings.iter().filter_map(|w| w.as_str()) {
                        let _ = writeln!(out, "{}", crate::msg!("label-warning", warning = w));
                    }
                }
                i32::from(!ok)
            }
            Err(e) => fail(out, "lab", &e),
        },
        LabCmd::Grade { lab, submissions, jobs, junit, show_output } => {
            let jobs = jobs.unwrap_or_else(crate::lab::runner::default_jobs);
            let (l, reports) = match crate::lab::grade(lab, submissions, jobs) {
                Ok(x) => x,
                Err(e) => return fail(out, "lab", &e),
            };
            if crate::signals::exit_status().is_some() {
                // Stopped: the workers were ended; no summary of a partial run is printed as
                // if it were the class's grades.
                // (The status is the signal's: cli::run.)
                let done = reports.iter().filter(|r| r.code.as_deref() != Some("lab-not-graded")).count();
                let e = crate::core::Error::new(
                    crate::core::ErrorKind::Interrupted,
                    crate::msg!("lab-grade-stopped", cause = crate::signals::cause().to_string(), done = done),
                )
                .hint(crate::msg!("lab-hint-grade-again"));
                let _ = output::report_error(out, style, "lab", &e, None);
                return 1;
            }
            if let Some(path) = junit {
                if let Err(e) = std::fs::write(path, crate::lab::report::junit(&l, &reports)) {
                    return fail(
                        out,
                        "lab",
                        &crate::core::Error::io(crate::msg!("lab-cannot-write", file = path.display().to_string()))
                            .cause(e),
                    );
                }
            }
            if style.json {
                for r in &reports {
                    let _ = writeln!(out, "{}", crate::lab::report_json(r));
                }
            }
            let (head, o) = crate::lab::summary(&l, &reports);
            if !style.json {
                let _ = writeln!(out, "{head}");
            }
            let _ = output::write_outcome(out, style, &o);
            if !style.json {
                // Why each criterion failed: expected, got, and when.
                for line in crate::lab::report::why_lines(&reports) {
                    let _ = writeln!(out, "{line}");
                }
                if *show_output {
                    for r in &reports {
                        for (what, text) in [("stdout", &r.stdout), ("stderr", &r.stderr)] {
                            if let Some(t) = text {
                                let _ = writeln!(out, "{} ({what}):", crate::lab::report::cell(&r.student));
                                for line in t.lines() {
                                    let _ = writeln!(out, "  {}", visible(line));
                                }
                            }
                        }
                    }
                }
            }
            i32::from(reports.iter().any(|r| r.code.as_deref() == Some("lab-grader-error")))
        }
        LabCmd::Worker { lab, submission, report, write_dir } => {
            crate::lab::runner::worker(lab, submission, report, write_dir.as_deref())
        }
    }
}

/// A line of a submission's output with its control characters made visible (`\u{1b}`), so
/// it cannot move the cursor or clear the teacher's terminal.
fn visible(line: &str) -> String {
    line.chars()
        .map(|c| if c.is_control() && c != '\t' { c.escape_default().to_string() } else { c.to_string() })
        .collect()
}

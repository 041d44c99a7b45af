//! `plcsh tags FILE`, `plcsh tags check FILE` and `plcsh tags export FILE --to csv|iec`: a
//! tag table listed, checked and written back — thin calls into [`crate::tags`]. No device is
//! opened; the family the addresses are read in is the one `--model` names (any family's
//! model; the simulated K2's by default), and names are checked against every family's
//! operands, so a table does not start to read two ways when it moves to another device.

use crate::core::{exit, Error};
use crate::output::{self, Outcome, Style};
use crate::profile::tags::{load as load_checked, space_for};
use crate::tags::{export, TagFormat, TagProblems};
use clap::{Args, Subcommand, ValueEnum};
use std::io::Write;
use std::path::PathBuf;

#[derive(Args, Debug)]
#[command(args_conflicts_with_subcommands = true)]
pub struct TagsArgs {
    #[command(subcommand)]
    pub cmd: Option<TagsCmd>,
    /// The tag file to list (CSV, TOML `[tags]`, or IEC `VAR_GLOBAL` declarations).
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,
    #[command(flatten)]
    pub opts: TagsOpts,
}

#[derive(Args, Debug, Default)]
pub struct TagsOpts {
    /// The model whose operands the addresses are (K2, FX or UMPK; default: the simulated K2's).
    #[arg(long, value_name = "MODEL")]
    pub model: Option<String>,
    /// Read the file as this format instead of telling it by its name and text.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub format: Option<FormatArg>,
}

#[derive(Subcommand, Debug)]
pub enum TagsCmd {
    /// Check a tag file: one line per problem with file:line:column; exit status 1 when there is any.
    Check {
        #[arg(value_name = "FILE")]
        file: PathBuf,
        #[command(flatten)]
        opts: TagsOpts,
    },
    /// Write a tag file in another form (CSV or IEC VAR_GLOBAL) to standard output or --output.
    Export {
        #[arg(value_name = "FILE")]
        file: PathBuf,
        /// The form to write.
        #[arg(long, value_enum)]
        to: FormatOut,
        /// Write here instead of standard output (replaced whole, atomically).
        #[arg(long, short = 'o', value_name = "FILE")]
        output: Option<PathBuf>,
        #[command(flatten)]
        opts: TagsOpts,
    },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum FormatArg {
    Csv,
    Toml,
    Iec,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum FormatOut {
    Csv,
    Iec,
}

impl FormatArg {
    fn format(self) -> TagFormat {
        match self {
            FormatArg::Csv => TagFormat::Csv,
            FormatArg::Toml => TagFormat::Toml,
            FormatArg::Iec => TagFormat::Iec,
        }
    }
}

fn problems_json(p: &TagProblems) -> serde_json::Value {
    serde_json::Value::Array(
        p.0.iter()
            .map(|p| {
                serde_json::json!({"file": p.origin, "line": p.line, "column": p.column, "code": p.message.id, "message": p.message.text})
            })
            .collect(),
    )
}

/// Reports a file's problems: one line each (text, on standard output for `check`, which is
/// what it was asked for; on standard error otherwise) or one JSON object with `problems`.
fn report(out: &mut dyn Write, style: Style, cmd: &str, p: &TagProblems, to_stdout: bool) -> i32 {
    if style.json {
        let v =
            serde_json::json!({"ok": false, "cmd": cmd, "problems": problems_json(p), "error": p.clone().into_error()});
        let _ = writeln!(out, "{v}");
    } else if to_stdout {
        // The problems are the answer; the summary is the error a script's log shows.
        let _ = writeln!(out, "{p}");
        let file = p.0.first().map_or("", |x| x.origin.as_str());
        let e = Error::new(
            crate::core::ErrorKind::Syntax,
            crate::msg!("tags-check-failed", file = file, count = p.0.len() as i64),
        );
        let _ = output::report_error(out, style, cmd, &e, None);
    } else {
        let _ = out.flush();
        eprintln!("{p}");
    }
    exit::FAILED
}

pub fn run(args: &TagsArgs, style: Style, out: &mut dyn Write) -> i32 {
    let fail = |out: &mut dyn Write, cmd: &str, e: &Error| {
        let _ = output::report_error(out, style, cmd, e, None);
        exit::for_error(e.kind)
    };
    let (cmd, file, opts) = match (&args.cmd, &args.file) {
        (Some(TagsCmd::Check { file, opts }), _) => ("tags", file, opts),
        (Some(TagsCmd::Export { file, opts, .. }), _) => ("tags", file, opts),
        (None, Some(file)) => ("tags", file, &args.opts),
        (None, None) => {
            return fail(out, "tags", &Error::usage(crate::msg!("tags-usage")));
        }
    };
    let space = match space_for(opts.model.as_deref()) {
        Ok(s) => s,
        Err(e) => return fail(out, cmd, &e),
    };
    let table = match load_checked(file, opts.format.map(FormatArg::format), space.as_ref()) {
        Ok(t) => t,
        // `check` prints what it was asked to find on standard output.
        Err(p) => return report(out, style, cmd, &p, matches!(args.cmd, Some(TagsCmd::Check { .. }))),
    };
    let warnings: Vec<String> = table.warnings().iter().map(|w| w.to_string()).collect();
    match &args.cmd {
        // `check` reports overlaps as problems: they are what it is asked to find.
        Some(TagsCmd::Check { .. }) if !warnings.is_empty() => {
            report(out, style, cmd, &TagProblems(table.warnings().to_vec()), true)
        }
        Some(TagsCmd::Check { .. }) => {
            let o = Outcome::new(cmd)
                .text(crate::msg!("tags-check-ok", file = table.origin(), count = table.len() as i64).text)
                .with("file", table.origin())
                .with("count", table.len())
                .with("problems", Vec::<()>::new());
            i32::from(output::write_outcome(out, style, &o).is_err())
        }
        Some(TagsCmd::Export { to, output: path, .. }) => {
            let text = match to {
                FormatOut::Csv => export::to_csv(&table),
                FormatOut::Iec => match export::to_iec(&table, space.as_ref()) {
                    Ok(t) => t,
                    Err(e) => return fail(out, cmd, &e),
                },
            };
            for w in &warnings {
                eprintln!("{}", crate::msg!("tags-warning", warning = w.as_str()));
            }
            match path {
                Some(p) => match crate::core::durable::write_atomic(p, text.as_bytes()) {
                    Ok(()) => exit::OK,
                    Err(e) => fail(out, cmd, &e),
                },
                None => i32::from(out.write_all(text.as_bytes()).is_err()),
            }
        }
        None => {
            let mut rows = Vec::with_capacity(table.len());
            let mut json = Vec::with_capacity(table.len());
            for t in table.iter() {
                // Checked above: every address resolves.
                let op = t.resolve(space.as_ref()).ok();
                let ty = op.map(|o| o.dtype.name()).unwrap_or_else(|| t.dtype.name());
                let operand = op.map(|o| space.name(&o)).unwrap_or_else(|| t.address.clone());
                rows.push(vec![t.name.clone(), operand.clone(), ty.to_string(), t.comment.clone()]);
                json.push(serde_json::json!({
                    "name": t.name, "address": t.address, "operand": operand, "type": ty,
                    "comment": t.comment, "line": t.line,
                }));
            }
            let mut o = Outcome::new(cmd)
                .table(&["name", "address", "type", "comment"], rows)
                .with("file", table.origin())
                .with("format", table.format().map(|f| f.name()))
                .with("tags", json)
                .with("warnings", &warnings);
            o.notes = warnings;
            i32::from(output::write_outcome(out, style, &o).is_err())
        }
    }
}

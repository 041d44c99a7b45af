//! `plcsh tags FILE`, `plcsh tags check FILE` and `plcsh tags export FILE --to csv|iec`: a
//! tag table listed, checked and written back — thin calls into [`crate::tags`]. No device is
//! opened; the family the addresses are read in is the one `--model` names (any family's
//! model; the simulated K2's by default), and names are checked against every family's
//! operands, so a table does not start to read two ways when it moves to another device.

use crate::core::{exit, Error, OperandSpace};
use crate::output::{self, Outcome, Style};
use crate::tags::{export, TagFormat, TagProblems, TagTable};
use clap::{Args, Subcommand, ValueEnum};
use std::io::Write;
use std::path::{Path, PathBuf};

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

/// The operand space of a model of any family (`K209M`, `FX2N`, `UMPK16`).
pub fn space_for(model: Option<&str>) -> crate::core::Result<Box<dyn OperandSpace>> {
    let name = model.unwrap_or(crate::k2::catalog::DEFAULT_MODEL);
    if let Some(m) = crate::k2::catalog::find(name) {
        return Ok(Box::new(crate::k2::space::K2Space::new(m)));
    }
    if let Some(m) = crate::fx::model::Model::find(name) {
        return Ok(Box::new(crate::fx::space::FxSpace::new(m, crate::fx::space::Proto::Port)));
    }
    if let Some(m) = name.to_ascii_uppercase().starts_with("UMPK").then(|| crate::umpk::model::find(name)).flatten() {
        return Ok(Box::new(crate::umpk::space::UmpkSpace { model: m }));
    }
    Err(Error::usage(crate::msg!("tags-unknown-model", model = name)))
}

/// One space of every family, the largest model of each: the operands a name must not read as.
pub fn every_family() -> Vec<Box<dyn OperandSpace>> {
    let k2 = crate::k2::catalog::MODELS.last().expect("the K2 catalogue has models");
    let fx = crate::fx::model::MODELS.last().expect("the FX catalogue has models");
    let umpk = crate::umpk::model::MODELS.last().expect("the UMPK catalogue has models");
    vec![
        Box::new(crate::k2::space::K2Space::new(k2)),
        Box::new(crate::fx::space::FxSpace::new(fx, crate::fx::space::Proto::Port)),
        Box::new(crate::umpk::space::UmpkSpace { model: umpk }),
    ]
}

/// Reads and checks a tag file for `space`'s family: the table, or every problem.
pub fn load_checked(path: &Path, format: Option<TagFormat>, space: &dyn OperandSpace) -> Result<TagTable, TagProblems> {
    let bytes = std::fs::read(path).map_err(|e| {
        let origin = path.display().to_string();
        TagProblems(vec![crate::tags::TagProblem {
            origin: origin.clone(),
            line: 0,
            column: 0,
            message: crate::msg!("tags-cannot-read", file = origin.as_str(), reason = e.to_string()),
        }])
    })?;
    let table = TagTable::parse(&bytes, &path.display().to_string(), format)?;
    let others = every_family();
    let mut spaces: Vec<&dyn OperandSpace> = vec![space];
    spaces.extend(others.iter().map(|b| b.as_ref()));
    table.checked(&spaces)
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
        let v = serde_json::json!({"ok": false, "cmd": cmd, "problems": problems_json(p), "error": p.clone().into_error()});
        let _ = writeln!(out, "{v}");
    } else if to_stdout {
        let _ = writeln!(out, "{p}");
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
        (Some(TagsCmd::Check { file, opts }), _) => ("tags check", file, opts),
        (Some(TagsCmd::Export { file, opts, .. }), _) => ("tags export", file, opts),
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
        Err(p) => return report(out, style, cmd, &p, cmd == "tags check"),
    };
    match &args.cmd {
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
            let o = Outcome::new(cmd)
                .table(&["name", "address", "type", "comment"], rows)
                .with("file", table.origin())
                .with("format", table.format().map(|f| f.name()))
                .with("tags", json);
            i32::from(output::write_outcome(out, style, &o).is_err())
        }
    }
}

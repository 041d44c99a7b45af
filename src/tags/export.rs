//! Writing a tag table back: the CSV and IEC forms `plcsh tags export` makes, each read back
//! by its parser to the same tags (tests/tags.rs round-trips them).
//!
//! CSV: a header row `name,address,type,comment` and one row per tag, a field quoted (RFC
//! 4180) when it holds a comma, a quote, a line break or leading or trailing spaces. IEC:
//! one `VAR_GLOBAL` block, `name AT %address : TYPE; (* comment *)`, a bit address in IEC's
//! form with `X` (`%MX0.3`); a tag without a declared type gets its address's type from the
//! family, which IEC requires. A comment's line breaks become spaces and a `*)` in it `* )`,
//! so it stays one comment.

use super::{TagTable, TagType};
use crate::core::OperandSpace;

/// `field` as a CSV field.
fn csv_field(field: &str) -> String {
    let needs = field.contains([',', '"', '\n', '\r']) || field.trim() != field;
    if needs {
        format!("\"{}\"", field.replace('"', "\"\""))
    } else {
        field.to_string()
    }
}

/// The table as CSV (UTF-8, `\n` line ends).
pub fn to_csv(table: &TagTable) -> String {
    let mut out = String::from("name,address,type,comment\n");
    for t in table.iter() {
        let row = [csv_field(&t.name), csv_field(&t.address), t.dtype.name().to_string(), csv_field(&t.comment)];
        out.push_str(&row.join(","));
        out.push('\n');
    }
    out
}

/// An address in IEC's direct form: `%` and, for a bit (`M0.3`), the size letter `X`.
fn iec_address(address: &str) -> String {
    let letters = address.bytes().take_while(|b| b.is_ascii_alphabetic()).count();
    let rest = &address[letters..];
    let bit = rest.split_once('.').is_some_and(|(n, b)| {
        !n.is_empty() && !b.is_empty() && n.bytes().all(|c| c.is_ascii_digit()) && b.bytes().all(|c| c.is_ascii_digit())
    });
    if bit && letters > 0 {
        format!("%{}X{rest}", &address[..letters])
    } else {
        format!("%{address}")
    }
}

/// The table as one `VAR_GLOBAL` block; `space` gives the type of a tag that declares none
/// (its address's own type). Refused naming the tag when its address is not an operand of
/// the family.
pub fn to_iec(table: &TagTable, space: &dyn OperandSpace) -> crate::core::Result<String> {
    let mut out = String::from("VAR_GLOBAL\n");
    for t in table.iter() {
        let ty = match t.dtype {
            TagType::Of(ty) => ty,
            TagType::Natural => t.resolve(space)?.dtype,
        };
        out.push_str(&format!("    {} AT {} : {};", t.name, iec_address(&t.address), ty.name()));
        if !t.comment.is_empty() {
            let c = t.comment.replace(['\r', '\n'], " ").replace("*)", "* )").replace("(*", "( *");
            out.push_str(&format!(" (* {c} *)"));
        }
        out.push('\n');
    }
    out.push_str("END_VAR\n");
    Ok(out)
}

//! `models [MODEL]`: the K2 model catalogue (`k2::catalog`), in the shell and as `plcsh models`.
//! The list fits an 80-column terminal (one short row a model); `models MODEL` shows one model
//! in full, with the manual's disagreements and the choice made for each.

use super::CommandSpec;
use crate::core::Result;
use crate::k2::catalog::{self, Model};
use crate::output::Outcome;
use crate::shell::{Args, Shell};

pub const MODELS: CommandSpec = CommandSpec {
    name: "models",
    aliases: &[],
    usage: "models [MODEL]   e.g. models K209EA",
    summary: || crate::msg!("summary-models"),
    subcommands: &[],
    run: models,
};

fn models(_sh: &mut Shell, args: Args) -> Result<Outcome> {
    let name = args.text.trim();
    outcome((!name.is_empty()).then_some(name)).map_err(|e| e.column(args.offset))
}

/// The catalogue (`None`) or one model.
pub fn outcome(model: Option<&str>) -> Result<Outcome> {
    let Some(name) = model else {
        let rows: Vec<[String; 6]> = catalog::MODELS
            .iter()
            .map(|m| {
                [
                    m.name.to_string(),
                    format!("{}/{}/{}", m.di, m.dout, m.dio),
                    format!("{}/{}", m.ai, m.ao),
                    m.hsc.len().to_string(),
                    if m.pto.is_empty() {
                        "none (relay)".into()
                    } else {
                        m.pto.iter().map(|p| p.output).collect::<Vec<_>>().join(" ")
                    },
                    if m.discrepancies.is_empty() { String::new() } else { m.discrepancies.len().to_string() },
                ]
            })
            .collect();
        let mut head: [String; 6] = Default::default();
        for (h, t) in head.iter_mut().zip(crate::output::headings(crate::msg!("shell-models-columns"))) {
            *h = t;
        }
        // Aligned by display width: a Chinese heading takes two columns a character.
        let width = crate::shell::term::width;
        let mut w = [0usize; 6];
        for r in std::iter::once(&head).chain(&rows) {
            for (i, c) in r.iter().enumerate() {
                w[i] = w[i].max(width(c));
            }
        }
        let line = |r: &[String; 6]| {
            let cells: Vec<String> =
                r.iter().enumerate().map(|(i, c)| format!("{c}{}", " ".repeat(w[i] - width(c)))).collect();
            cells.join("  ").trim_end().to_string()
        };
        let mut text: Vec<String> = std::iter::once(&head).chain(&rows).map(line).collect();
        text.push(crate::msg!("shell-models-footer").text);
        return Ok(Outcome::new("models").text(text.join("\n")).with("models", catalog::MODELS));
    };
    let m = catalog::lookup(name)?;
    Ok(Outcome::new("models").text(detail(m)).with("models", [m]))
}

/// One model in full, wrapped to 80 columns.
fn detail(m: &Model) -> String {
    let mut lines = vec![
        format!("{} ({})", m.name, m.cpu),
        format!("  I/O         DI {} / DO {} / DIO {}, AI {} / AO {}", m.di, m.dout, m.dio, m.ai, m.ao),
        format!(
            "  areas       I{} Q{} M{} V{} AI{} AQ{} bytes",
            m.i_bytes, m.q_bytes, m.m_bytes, m.v_bytes, m.ai_bytes, m.aq_bytes
        ),
    ];
    for h in m.hsc {
        lines.push(format!(
            "  HSC{}        {} kHz single-phase, {} kHz A/B",
            h.channel,
            h.max_hz_single / 1000,
            h.max_hz_ab / 1000
        ));
    }
    if m.pto.is_empty() {
        lines.push(format!("  pulses      {}", crate::msg!("shell-models-no-pulses")));
    }
    for p in m.pto {
        let up_to = crate::msg!("shell-models-pto", output = p.output, khz = p.max_hz / 1000);
        lines.push(format!("  PTO{}        {up_to}", p.channel));
    }
    for d in m.discrepancies {
        let note = format!("{}: chose {}; {}", d.what, d.chosen, d.other);
        for (i, l) in crate::core::text::wrap(&note, 64).into_iter().enumerate() {
            lines.push(format!("  {:<12}{l}", if i == 0 { "manual" } else { "" }));
        }
    }
    lines.join("\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_catalogue_and_one_model_fit_80_columns() {
        let list = outcome(None).unwrap();
        let text = list.message.clone().unwrap();
        assert!(text.lines().all(|l| l.chars().count() <= 80), "{text}");
        for m in catalog::MODELS {
            let d = detail(m);
            assert!(d.lines().all(|l| l.chars().count() <= 80), "{d}");
        }
        assert!(detail(catalog::find("K209EA").unwrap()).contains("chose 10 kHz"));
        assert!(outcome(Some("K999")).unwrap_err().to_string().contains("unknown K2 model"));
    }
}

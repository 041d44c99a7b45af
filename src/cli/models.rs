//! `plcsh models`: the K2 model catalogue, with the manual's disagreements made visible.

use crate::k2::catalog;
use crate::output::Outcome;

/// The catalogue as a table and JSON.
pub fn outcome() -> Outcome {
    let rows = catalog::MODELS
        .iter()
        .map(|m| {
            let pto: Vec<String> = m.pto.iter().map(|p| format!("{} {}k", p.output, p.max_hz / 1000)).collect();
            let hsc: Vec<String> = m
                .hsc
                .iter()
                .map(|h| format!("HSC{} {}k/{}k", h.channel, h.max_hz_single / 1000, h.max_hz_ab / 1000))
                .collect();
            vec![
                m.name.to_string(),
                format!("{}/{}/{}", m.di, m.dout, m.dio),
                format!("{}/{}", m.ai, m.ao),
                format!(
                    "I{} Q{} M{} V{} AI{} AQ{}",
                    m.i_bytes, m.q_bytes, m.m_bytes, m.v_bytes, m.ai_bytes, m.aq_bytes
                ),
                if hsc.is_empty() { "-".into() } else { hsc.join(", ") },
                if pto.is_empty() { "none (relay outputs)".into() } else { pto.join(", ") },
                m.discrepancies
                    .iter()
                    .map(|d| format!("{}: chose {}; {}", d.what, d.chosen, d.other))
                    .collect::<Vec<_>>()
                    .join("; "),
            ]
        })
        .collect();
    Outcome::new("models")
        .table(
            &["model", "DI/DO/DIO", "AI/AO", "area bytes", "HSC (1-phase/AB)", "pulse outputs", "manual disagreements"],
            rows,
        )
        .with("models", catalog::MODELS)
}

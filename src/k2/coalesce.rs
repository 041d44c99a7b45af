//! The coalescing planner: turns a batch of operand spans (from [`super::modbus_map`]) into
//! the fewest, cheapest Modbus requests the K2's limits allow. Coalescing is where a
//! fieldbus tool wins or loses: `get VW0..VW198` is one request, not a hundred.
//!
//! Reads: spans are grouped by region (one function code per table, and a request never
//! leaves the PLC area it started in, so it never runs past an area bound or into the
//! unmapped gap between Q and M). Within a region an exact dynamic programme picks the
//! partition with the least cost, where a request costs a fixed overhead (header, checksum,
//! turnaround, round trip) and each unit read costs its bytes; so a small gap is read
//! through, a large one is skipped when that is cheaper, and no request exceeds 1600 bits
//! or 100 registers (manual §3.2.1). Among partitions of equal cost the one with fewer
//! requests wins.
//!
//! Writes keep the caller's order (a handshake flag written after its data must arrive
//! after it): consecutive items that touch adjacent or overlapping addresses of one region
//! share a request, up to 800 bits or 100 registers; anything else starts a new request.
//!
//! Pure: no I/O.

use super::modbus_map::{Span, Table};

/// What a request costs on a link, for deciding when to read through a gap.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Costs {
    /// Fixed cost of one request, in bytes of payload it is worth.
    pub request_bytes: u32,
}

impl Costs {
    /// Modbus TCP: the round trip dominates; reading through any gap within the limits
    /// beats a second request.
    pub const TCP: Costs = Costs { request_bytes: 1000 };
    /// Modbus RTU: a request costs its 8-byte frame, the reply's 5 bytes of header and
    /// checksum, two 3.5-character silences and the PLC's turnaround (about 10 characters):
    /// about 30 characters, i.e. 15 registers or 240 bits of gap.
    pub const RTU: Costs = Costs { request_bytes: 30 };
}

/// Cost of `units` of a table, in eighths of a byte (a bit costs one, a register 16).
fn unit_cost(table: Table) -> u64 {
    if table.is_bits() {
        1
    } else {
        16
    }
}

/// Plans the reads of `spans` (any order, duplicates allowed). Every span lies wholly
/// inside one returned request; requests are sorted by region and address.
pub fn plan_reads(spans: &[Span], costs: Costs) -> Vec<Span> {
    let mut sorted: Vec<Span> = spans.to_vec();
    sorted.sort_unstable();
    sorted.dedup();
    let mut out = Vec::new();
    let mut i = 0;
    while i < sorted.len() {
        let region = sorted[i].region;
        let mut j = i;
        while j < sorted.len() && sorted[j].region == region {
            j += 1;
        }
        plan_region(&sorted[i..j], costs, &mut out);
        i = j;
    }
    out
}

/// The dynamic programme over one region's spans (sorted by start).
fn plan_region(s: &[Span], costs: Costs, out: &mut Vec<Span>) {
    let table = s[0].table();
    let limit = table.read_limit() as u32;
    let overhead = costs.request_bytes as u64 * 8;
    let per_unit = unit_cost(table);
    let n = s.len();
    // Fast path (the common `get VW0..VW198`): everything fits one request and the gaps
    // cost less than a request. Any split into k ≥ 2 requests saves at most the gaps and
    // pays k − 1 more overheads, so one request is optimal.
    let lo = s[0].start as u32;
    let mut hi = lo;
    let mut gaps = 0u64;
    for sp in s {
        gaps += (sp.start as u32).saturating_sub(hi) as u64;
        hi = hi.max(sp.end());
    }
    if hi - lo <= limit && gaps * per_unit <= overhead {
        out.push(Span { region: s[0].region, start: lo as u16, count: (hi - lo) as u16 });
        return;
    }
    // best[j] = (cost, requests, first span of the last request) covering s[..j].
    let mut best: Vec<(u64, u32, usize)> = vec![(0, 0, 0); n + 1];
    for j in 1..=n {
        let mut hi = 0u32;
        let mut choice = (u64::MAX, u32::MAX, 0usize);
        for i in (0..j).rev() {
            hi = hi.max(s[i].end());
            let lo = s[i].start as u32;
            if hi - lo > limit {
                break; // the window only grows as i moves left
            }
            let (c, r, _) = best[i];
            let cand = (c + overhead + (hi - lo) as u64 * per_unit, r + 1, i);
            if (cand.0, cand.1) < (choice.0, choice.1) {
                choice = cand;
            }
        }
        best[j] = choice;
    }
    let mut requests = Vec::new();
    let mut j = n;
    while j > 0 {
        let i = best[j].2;
        let lo = s[i].start;
        let hi = s[i..j].iter().map(Span::end).max().unwrap_or(lo as u32);
        requests.push(Span { region: s[i].region, start: lo, count: (hi - lo as u32) as u16 });
        j = i;
    }
    requests.reverse();
    out.extend(requests);
}

/// The request holding `span` and the span's offset in it.
pub fn find(requests: &[Span], span: &Span) -> Option<(usize, usize)> {
    requests
        .iter()
        .position(|r| r.region == span.region && r.start <= span.start && span.end() <= r.end())
        .map(|k| (k, (span.start - requests[k].start) as usize))
}

/// One write request: a contiguous range and the items (indices into the caller's list,
/// in order) it carries.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WriteRun {
    pub span: Span,
    pub items: Vec<usize>,
}

/// Plans writes in the caller's order: an item joins the request before it when it is in
/// the same region, touches or overlaps it, and the union stays within the write limit.
pub fn plan_writes(spans: &[Span]) -> Vec<WriteRun> {
    let mut runs: Vec<WriteRun> = Vec::new();
    for (k, s) in spans.iter().enumerate() {
        if let Some(last) = runs.last_mut() {
            let r = last.span;
            let lo = r.start.min(s.start) as u32;
            let hi = r.end().max(s.end());
            let touches = s.start as u32 <= r.end() && r.start as u32 <= s.end();
            let limit = s.table().write_limit().unwrap_or(0) as u32;
            if r.region == s.region && touches && hi - lo <= limit {
                last.span = Span { region: r.region, start: lo as u16, count: (hi - lo) as u16 };
                last.items.push(k);
                continue;
            }
        }
        runs.push(WriteRun { span: *s, items: vec![k] });
    }
    runs
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::k2::catalog;
    use crate::k2::modbus_map::{locate_read, locate_write};
    use crate::k2::operand::{parse_expr, parse_one};
    use crate::k2::space::K2Space;

    fn space() -> K2Space {
        K2Space::new(catalog::find("K205-16DT").unwrap())
    }

    fn spans(texts: &[&str]) -> Vec<Span> {
        let s = space();
        texts.iter().flat_map(|t| parse_expr(t).unwrap()).map(|o| locate_read(&s, &o).unwrap()).collect()
    }

    fn spans_of(words: impl Iterator<Item = u32>) -> Vec<Span> {
        let s = space();
        words.map(|b| locate_read(&s, &parse_one(&format!("VW{b}")).unwrap()).unwrap()).collect()
    }

    #[test]
    fn fifty_words_over_vw0_to_vw400_take_the_three_requests_the_limit_forces() {
        // 49 words VW0, VW8 … VW384 (registers 100, 104 … 292) and VW400 (register 300):
        // they span 201 registers. A read is at most 100 registers (§3.2.1), and no window of
        // 100 registers covers both register 200 and register 300, so 3 requests are forced:
        // 100…199, 200…292, 300.
        let words: Vec<u32> = (0..49).map(|k| k * 8).chain([400]).collect();
        assert_eq!(words.len(), 50);
        let plan = plan_reads(&spans_of(words.into_iter()), Costs::TCP);
        assert_eq!(plan.len(), 3, "{plan:?}");
        assert!(plan.iter().all(|r| r.count <= 100));
        // Every word is inside a request.
        for s in spans_of((0..49).map(|k| k * 8).chain([400])) {
            assert!(find(&plan, &s).is_some(), "{s:?}");
        }
        // Fifty words VW0, VW8 … VW392 span 197 registers: two requests.
        assert_eq!(plan_reads(&spans_of((0..50).map(|k| k * 8)), Costs::TCP).len(), 2);
    }

    #[test]
    fn splits_at_the_limits() {
        let plan = plan_reads(&spans(&["VW0..VW498"]), Costs::TCP);
        assert_eq!(plan.iter().map(|r| r.count).collect::<Vec<_>>(), vec![100, 100, 50]);
        let bits = plan_reads(&spans(&["M0.0..M249.7"]), Costs::TCP);
        assert_eq!(bits.iter().map(|r| r.count).collect::<Vec<_>>(), vec![1600, 400]);
    }

    #[test]
    fn one_function_code_per_table_and_never_across_areas() {
        let plan = plan_reads(&spans(&["Q0.0", "M0.0", "I0.0", "VW0"]), Costs::TCP);
        assert_eq!(plan.len(), 4);
        let tables: Vec<Table> = plan.iter().map(|r| r.table()).collect();
        assert!(tables.contains(&Table::DiscreteInputs) && tables.contains(&Table::HoldingRegisters));
        // Requests stay inside V's last register.
        let end = plan_reads(&spans(&["VW4000", "VW4094", "VB4095"]), Costs::TCP);
        assert_eq!(end.len(), 1);
        assert_eq!(end[0].end(), 2148);
    }

    #[test]
    fn gaps_are_read_through_when_cheaper() {
        // Near-adjacent words merge.
        let plan = plan_reads(&spans(&["VW0", "VW4", "VB9", "VW2"]), Costs::TCP);
        assert_eq!(plan, vec![Span { region: plan[0].region, start: 100, count: 5 }]);
        // A 89-register gap: one request over TCP, two over RTU where the gap costs more
        // than a request.
        assert_eq!(plan_reads(&spans(&["VW0", "VW180"]), Costs::TCP).len(), 1);
        assert_eq!(plan_reads(&spans(&["VW0", "VW180"]), Costs::RTU).len(), 2);
        // A 10-register gap is still read through over RTU.
        assert_eq!(plan_reads(&spans(&["VW0", "VW22"]), Costs::RTU).len(), 1);
        // Duplicates and overlaps cost nothing extra.
        assert_eq!(plan_reads(&spans(&["VD0", "VW0", "VW0", "VB3"]), Costs::RTU).len(), 1);
    }

    #[test]
    fn writes_keep_their_order_and_merge_only_neighbours() {
        let s = space();
        let w = |t: &str| locate_write(&s, &parse_one(t).unwrap()).unwrap();
        let runs = plan_writes(&[w("VW0"), w("VW2"), w("VW10"), w("VB1")]);
        assert_eq!(runs.len(), 3);
        assert_eq!(runs[0].items, vec![0, 1]);
        assert_eq!((runs[0].span.start, runs[0].span.count), (100, 2));
        assert_eq!(runs[2].items, vec![3], "VB1 comes after VW10, so it is not folded into the first run");
        let many: Vec<Span> = parse_expr("VW0..VW298").unwrap().iter().map(|o| locate_write(&s, o).unwrap()).collect();
        assert_eq!(plan_writes(&many).iter().map(|r| r.span.count).collect::<Vec<_>>(), vec![100, 50]);
        let coils: Vec<Span> =
            parse_expr("M0.0..M119.7").unwrap().iter().map(|o| locate_write(&s, o).unwrap()).collect();
        assert_eq!(plan_writes(&coils).iter().map(|r| r.span.count).collect::<Vec<_>>(), vec![800, 160]);
        assert_eq!(plan_writes(&[w("Q0.0"), w("M0.0")]).len(), 2);
    }
}

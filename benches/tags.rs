//! Tag lookup benchmark: looking up a name in a table of 10 000 tags against parsing an
//! operand (docs/tags.md; the target is that a name costs no more than an operand). Cases, in
//! rounds that alternate so the machine's load falls on all of them alike; the best round of
//! each is printed, with its ratio to the operand parse. Prints figures; asserts nothing.
//! Run: cargo bench --bench tags (or build it with `cargo build --bench tags` and run the
//! binary in target/debug/deps/ for a debug figure).

use plcsh::core::OperandSpace;
use plcsh::k2::catalog;
use plcsh::k2::space::K2Space;
use plcsh::tags::TagTable;
use std::hint::black_box;
use std::time::Instant;

const TAGS: usize = 10_000;
const N: usize = 200_000;

fn main() {
    let space = K2Space::new(catalog::find("K209M-56DT").unwrap());
    let mut csv = String::from("name,address,type,comment\n");
    for i in 0..TAGS {
        let name = if i % 2 == 0 { format!("Conveyor_{i}_Run") } else { format!("Мотор_{i}_Пуск") };
        csv.push_str(&format!("{name},VW{},INT,tag {i}\n", (i % 2000) * 2));
    }
    let table = TagTable::parse(csv.as_bytes(), "bench.csv", None).unwrap();
    let bound = plcsh::names::Names::resolve(table.clone(), &space).unwrap();
    let names: Vec<String> = table.iter().map(|t| t.name.clone()).collect();
    let upper: Vec<String> = names.iter().map(|n| n.to_uppercase()).collect();
    let operands: Vec<String> = table.iter().map(|t| t.address.clone()).collect();
    type Case<'a> = (&'a str, Box<dyn Fn(usize) -> usize + 'a>);
    let cases: Vec<Case> = vec![
        (
            "operand parse  K2Space::parse(\"VW1234\")",
            Box::new(|i| space.parse(&operands[i % TAGS]).map_or(0, |v| v.len())),
        ),
        (
            "name lookup    table.get(\"Conveyor_42_Run\")",
            Box::new(|i| table.get(&names[i % TAGS]).map_or(0, |t| t.line)),
        ),
        (
            "name lookup, other case  table.get(\"CONVEYOR_42_RUN\")",
            Box::new(|i| table.get(&upper[i % TAGS]).map_or(0, |t| t.line)),
        ),
        (
            "name → operand  table.get(n).resolve(space)",
            Box::new(|i| {
                table.get(&names[i % TAGS]).and_then(|t| t.resolve(&space).ok()).map_or(0, |o| o.bits as usize)
            }),
        ),
        (
            "name → operand, bound names  Names::get(n)",
            Box::new(|i| bound.get(&names[i % TAGS]).map_or(0, |n| n.op.bits as usize)),
        ),
    ];
    let mut best = vec![f64::MAX; cases.len()];
    for _round in 0..7 {
        for (k, (_, f)) in cases.iter().enumerate() {
            let t = Instant::now();
            let mut acc = 0usize;
            for i in 0..N {
                acc = acc.wrapping_add(f(black_box(i)));
            }
            black_box(acc);
            best[k] = best[k].min(t.elapsed().as_secs_f64() * 1e9 / N as f64);
        }
    }
    println!("{TAGS} tags, {N} operations per case, best of 7 rounds:");
    for (k, (name, _)) in cases.iter().enumerate() {
        println!("{name:<58} {:>8.1} ns  ({:.2}× the operand parse)", best[k], best[k] / best[0]);
    }
}

//! Lua benchmark: register writes and reads per second from Lua against the
//! in-process simulator (target ≥ 1 000 000 writes/s), and the wall time of a script that
//! waits 10 simulated minutes in stepped time (target < 1 s). Prints figures; asserts nothing.
//! Run: cargo bench --bench lua

use plcsh::core::Clock;
use plcsh::output::Style;
use plcsh::script::Engine;
use plcsh::session::Session;
use plcsh::shell::Shell;
use std::time::Instant;

fn shell() -> (Shell, Engine) {
    let mut s = Session::new(Clock::stepped());
    s.open("plc", "sim:K205-16DT").unwrap();
    let sh = Shell::new(s, Style::default());
    let e = Engine::new(sh.session.interrupt.clone(), Box::new(std::io::sink())).unwrap();
    (sh, e)
}

/// Runs `code` (which performs `n` operations) and returns operations per second.
fn rate(sh: &mut Shell, e: &Engine, n: u64, code: &str) -> f64 {
    let t = Instant::now();
    e.run_chunk(sh, code).map_err(|f| f.human()).unwrap();
    n as f64 / t.elapsed().as_secs_f64()
}

fn main() {
    let (mut sh, e) = shell();
    let n = 3_000_000u64;
    let cases = [
        ("field write  plc.VW100 = i", format!("local plc = plc for i = 1, {n} do plc.VW100 = i & 0xFFFF end")),
        ("field write  plc.SMB67 = i (SM byte)", format!("local plc = plc for i = 1, {n} do plc.SMB67 = i & 0xFF end")),
        (
            "field write  plc['M0.3'] = bool",
            format!("local plc = plc for i = 1, {n} do plc['M0.3'] = (i & 1) == 1 end"),
        ),
        ("field read   v = plc.VW100", format!("local plc, s = plc, 0 for i = 1, {n} do s = s + plc.VW100 end")),
        (
            "plc:get(VW0, VW2)  calls (2 values each)",
            format!("local plc = plc for i = 1, {n} // 2 do local a, b = plc:get('VW0', 'VW2') end"),
        ),
    ];
    println!("Lua register access against the in-process simulator ({n} operations each):");
    for (name, code) in &cases {
        // Warm-up, then the best of three.
        rate(&mut sh, &e, n / 10, &code.replace(&n.to_string(), &(n / 10).to_string()));
        let ops = if name.contains("get") { n / 2 } else { n };
        let best = (0..3).map(|_| rate(&mut sh, &e, ops, code)).fold(0.0, f64::max);
        println!("  {name:<40} {:>12.0} /s", best);
    }
    let batch = 200_000u64;
    let r = rate(
        &mut sh,
        &e,
        batch * 3,
        &format!("local plc = plc for i = 1, {batch} do plc:set{{SMB67 = 0x85, SMW68 = 500, SMD72 = i}} end"),
    );
    println!("  {:<40} {:>12.0} registers/s", "plc:set{SMB67=…, SMW68=…, SMD72=…}", r);
    let r = rate(&mut sh, &e, 100_000, "for i = 1, 100000 do plcsh.exec('set VW0=1') end");
    println!("  {:<40} {:>12.0} commands/s", "plcsh.exec('set VW0=1')", r);

    // Ten simulated minutes, in process and through the real binary.
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/scripts/wait_ten_minutes.lua");
    let (mut sh, e) = shell();
    let t = Instant::now();
    e.run_file(&mut sh, std::path::Path::new(script), &[]).map_err(|f| f.human()).unwrap();
    println!("\nscripts/wait_ten_minutes.lua (11 simulated minutes, polling every 250 ms):");
    println!("  in process: {:.2} ms wall", t.elapsed().as_secs_f64() * 1000.0);
    let mut walls: Vec<f64> = (0..7)
        .map(|_| {
            let t = Instant::now();
            let o = std::process::Command::new(env!("CARGO_BIN_EXE_plcsh"))
                .args(["--time", "stepped", "run", script])
                .output()
                .unwrap();
            assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stdout));
            t.elapsed().as_secs_f64() * 1000.0
        })
        .collect();
    walls.sort_by(|a, b| a.partial_cmp(b).unwrap());
    println!("  plcsh --time stepped run (process start to exit): median {:.1} ms, max {:.1} ms", walls[3], walls[6]);
}

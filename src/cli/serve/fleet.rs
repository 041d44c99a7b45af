//! `plcsh sim serve --fleet N --tcp ADDR`: N simulated K2s in one process, each with its own
//! memory and its own Modbus TCP port, so a fleet (docs/fleets.md) and its tests run without
//! hardware. Every member is built by the same code as the single served K2
//! ([`super::make_k2`]: model, unit, helper program, faults, user program) and served by
//! the same server; they share the process's virtual clock. Up to [`THREADS`] members, each is
//! served on a thread of its own (with its own small runtime), so one member that is slow to
//! answer (a `late` fault, a long request) holds no other, as separate PLCs would not. A
//! larger fleet (up to 10 000) shares [`THREADS`] threads, member k on thread k mod
//! [`THREADS`]: a runtime costs two descriptors and a thread, so 5 000 members each with
//! their own would need 20 000 descriptors before the first client; there a `late` fault
//! also delays the members of its thread. With port 0 each member binds a free port of its
//! own; with port P the members take P, P+1, … (a fleet's `url` range then names them). The
//! readiness line lists the bound addresses in order under `fleet`, and `tcp` is the first
//! of them.

use super::{bind, limits, make_k2, ServeArgs};
use crate::cli::Cli;
use crate::core::{Clock, Error, Result};
use crate::k2::sim::modbus_net;
use crate::k2::sim::modbus_server::K2Service;
use serde_json::{json, Map, Value as Json};
use std::sync::{Arc, Mutex};
use tokio::task::JoinSet;

/// The most threads a served fleet uses (a member each up to this many members).
pub(super) const THREADS: usize = 256;

/// Binds and spawns the N members; adds `fleet` (addresses), `tcp` and the members' shared
/// fields to `ready`.
pub(super) async fn serve(
    cli: &Cli,
    args: &ServeArgs,
    n: u16,
    clock: &Clock,
    tasks: &mut JoinSet<std::io::Result<()>>,
    ready: &mut Map<String, Json>,
) -> Result<()> {
    if cli.state.as_ref().is_some_and(|p| p.as_os_str() != "none") {
        return Err(Error::usage(crate::msg!("cli-serve-fleet-state")).hint(crate::msg!("cli-hint-serve-fleet-state")));
    }
    if cli.bench.is_some() {
        return Err(Error::usage(crate::msg!("cli-serve-fleet-bench")));
    }
    let tcp = args.tcp.as_deref().unwrap_or("0");
    let first = super::listen_addr(tcp)?;
    let limits = limits(args)?;
    let mut addrs = Vec::new();
    let mut groups: Vec<Vec<(std::net::TcpListener, K2Service)>> =
        (0..usize::from(n).min(THREADS)).map(|_| Vec::new()).collect();
    for k in 0..n {
        let port = if first.port() == 0 {
            0
        } else {
            first
                .port()
                .checked_add(k)
                .ok_or_else(|| Error::usage(crate::msg!("cli-serve-fleet-ports", tcp = tcp, count = n)))?
        };
        let mut fields = Map::new();
        let sim = make_k2(cli, args, clock, &mut fields, None)?;
        if k == 0 {
            ready.extend(fields);
        }
        let l = bind(&std::net::SocketAddr::new(first.ip(), port).to_string()).await?;
        addrs.push(l.local_addr()?.to_string());
        let l = l.into_std()?;
        let service = K2Service::new(Arc::new(Mutex::new(sim)), args.unit);
        let slots = groups.len();
        groups[usize::from(k) % slots].push((l, service));
    }
    for (t, group) in groups.into_iter().enumerate() {
        let (done_tx, done) = tokio::sync::oneshot::channel::<std::io::Result<()>>();
        std::thread::Builder::new().name(format!("fleet-k2-{t}")).spawn(move || {
            let served = tokio::runtime::Builder::new_current_thread().enable_all().build().and_then(|rt| {
                rt.block_on(async move {
                    let mut members = JoinSet::new();
                    for (l, service) in group {
                        let l = tokio::net::TcpListener::from_std(l)?;
                        members.spawn(modbus_net::serve_tcp(l, service, limits));
                    }
                    // The first member to end (an error) ends the thread's part.
                    match members.join_next().await {
                        Some(r) => r.unwrap_or_else(|e| Err(std::io::Error::other(e.to_string()))),
                        None => Ok(()),
                    }
                })
            });
            let _ = done_tx.send(served);
        })?;
        // A member's end (an error, or its thread gone) ends the server, as for one K2.
        tasks.spawn(async move {
            done.await
                .unwrap_or_else(|_| Err(std::io::Error::other(crate::msg!("cli-serve-fleet-member-stopped").text)))
        });
    }
    ready.insert("tcp".into(), json!(addrs[0]));
    ready.insert("fleet".into(), json!(addrs));
    Ok(())
}

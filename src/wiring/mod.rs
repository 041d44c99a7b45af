//! Virtual wiring in a session: `sim wire` / `sim unwire` / `sim wires` ([`setup`]) and wired
//! benches ([`bench`]) open the simulated devices a wire joins and hand the wire to its host.
//!
//! The signal model itself (terminals, roles, wires, the peer interface, what a wire carries
//! between pieces) is family-neutral and lives in the core, [`crate::core::wiring`], so the
//! families that speak it (the K2 as host, the drives as peers) need not name this layer; it
//! is re-exported here for the modules that open devices.

pub mod bench;
pub mod setup;

pub use crate::core::wiring::*;

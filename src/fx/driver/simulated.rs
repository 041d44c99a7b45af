//! The in-process FX simulator as a device (`sim-fx:MODEL`): the same [`Driver`] talks to a
//! simulated PLC ([`crate::fx::sim`]) over an in-process line instead of a serial port, so
//! the simulator exercises the real driver code. Devices opened with one `share=NAME` use one
//! simulated PLC, as the programming port and the computer link of one PLC do.

use super::computer_link::{link_header, link_settings};
use super::{finish, model_of, Driver, SIM_PARAMS};
use crate::core::link::line as lines;
use crate::core::url::DeviceUrl;
use crate::core::{Clock, Device, DeviceInfo, Error, Result};
use crate::fx::memory::Memory;
use crate::fx::model::Model;
use crate::fx::sim::{LinkServer, Plc, PortServer, Server, SimLink};
use crate::msg;
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock, Weak};

fn shared_plcs() -> &'static Mutex<HashMap<String, Weak<Mutex<Memory>>>> {
    static R: OnceLock<Mutex<HashMap<String, Weak<Mutex<Memory>>>>> = OnceLock::new();
    R.get_or_init(|| Mutex::new(HashMap::new()))
}

/// A simulated PLC's memory on `clock`, shared under `share` when given.
pub fn sim_plc(model: &'static Model, share: Option<&str>, clock: &Clock) -> Result<Plc> {
    let fresh = || Arc::new(Mutex::new(Memory::with_clock(model, clock.clone())));
    let Some(name) = share else { return Ok(fresh()) };
    let mut reg = shared_plcs().lock().unwrap_or_else(|p| p.into_inner());
    reg.retain(|_, w| w.strong_count() > 0);
    if let Some(p) = reg.get(name).and_then(Weak::upgrade) {
        let m = p.lock().unwrap_or_else(|e| e.into_inner()).model.name;
        if m != model.name {
            return Err(Error::usage(msg!("fx-sim-other-model", name = name, model = m, want = model.name)));
        }
        return Ok(p);
    }
    let p = fresh();
    reg.insert(name.to_string(), Arc::downgrade(&p));
    Ok(p)
}

/// Opens `sim-fx:MODEL?protocol=port|link&station=0&sum=1&format=1&share=NAME&program=FILE.il`
/// on the session's clock; `program` loads an FX list into the PLC ([`crate::fx::program`]).
pub fn open_sim(u: &DeviceUrl, clock: &Clock) -> Result<Box<dyn Device>> {
    u.expect_params(SIM_PARAMS)?;
    let model = model_of(u, Some(if u.target.is_empty() { "FX2N" } else { &u.target }))?;
    let plc = sim_plc(model, u.param("share"), clock)?;
    if let Some(p) = u.param("program") {
        let text = crate::core::encoding::read_source(p)
            .map_err(|e| Error::io(msg!("fx-cannot-read-program", url = &u.text, file = p, reason = e.to_string())))?;
        let loaded = crate::fx::program::Loaded::load(&text, p, model)?;
        plc.lock().unwrap_or_else(|e| e.into_inner()).load_program(loaded);
    }
    let sim = plc.clone();
    let link = match u.param("protocol") {
        None | Some("port") => false,
        Some("link") => true,
        Some(p) => return Err(Error::usage(msg!("fx-protocol-param", value = p, url = &u.text))),
    };
    let info = |what: &str| DeviceInfo {
        family: "fx",
        model: format!("simulated {} ({what})", model.name),
        link: u.text.clone(),
        simulated: true,
    };
    let d = if link {
        let header = link_header(u)?;
        let settings = link_settings(u)?;
        let server: Box<dyn Server> = Box::new(LinkServer::new(header.station, settings));
        let line = lines::private(&u.text, Box::new(SimLink::new(plc, server)));
        Driver::link(line, model, header, settings, info("computer link"))
    } else {
        let line = lines::private(&u.text, Box::new(SimLink::new(plc, Box::new(PortServer::default()))));
        Driver::port(line, model, info("programming port"))
    };
    let mut d = d;
    d.sim = Some(sim);
    finish(d, u)
}
